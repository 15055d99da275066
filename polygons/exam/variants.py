"""Seeded variants of a scene for an exam, each well posed, with its answers and the
tolerance a careful drawing deserves.

A variant takes one value from each range of the scene's ``[exam]`` (the combinations are
drawn without repetition with ``random.Random(seed)``: the same seed gives the same variants
on every machine) and is solved as an ordinary scene.  It is kept only if

* it assembles (the closure the scene's words choose exists),
* its assembly is at least ``closure_margin`` from the other closure and from a toggle (the
  smallest angle of the position construction, :func:`polygons.sweep.evaluate`'s margin),
* within ``pose_margin`` of its pose (a turn of the driving crank or rod) it still closes, no
  moving link or slider comes to rest (a dead centre) and no asked signed answer changes
  sign (a change point),
* every intersection of its velocity and acceleration constructions is at least
  ``min_angle`` (30° by default: a 0.25° protractor error then stays near 1 % in ω),
* at its round drawing scale (1, 2, 2.5 or 5 × 10ⁿ per cm, the polygon within 120 mm) the
  line every asked answer is read from is at least ``min_vector`` (8 mm) — a zero answer
  included: nothing asked is rounding noise,
* every asked answer is at least ``min_ratio`` (5) times its full tolerance, and more than
  ``partial_factor`` times: the partial band never reaches zero, so the sign of a signed
  answer is meaningful, and
* its answers, as printed, differ from every variant kept before (duplicates by value);

otherwise the next combination is drawn, at most ``attempts`` times per variant.  Rejections
are counted by reason.  Before any variant is drawn, a fixed probe of the ranges finds asked
answers that are the same in every variant (``v(P2)`` of a crank whose length and speed do not
vary, ``at(P2,O2)`` = 0 of a steady crank) or equal in size to another asked answer
(``v(P2,P4)`` and ``vs(P2)``): they need no drawing or ask the same thing, and are dropped
with the reason (:attr:`ExamSet.dropped`).

Each asked quantity's tolerance is what ``polygons check`` allows: the 95th percentile of its
error in the drawing-board emulation (:func:`polygons.tolerances.emulated_tolerances`), else
the scene's stated drawing tolerance, and never less than a 0.5 mm ruler reading at the
variant's scale.
"""
from __future__ import annotations

import copy
import dataclasses
import math
import random
from dataclasses import dataclass
from typing import Mapping

from .. import notation
from ..errors import PolygonsError, SceneError
from ..evaluate import Solution, solve
from ..exam_table import ExamSpec, spec as exam_spec
from ..quantities import dimension_of_quantity, drawn_on_polygon, quantity
from ..units import round_up
from ..scene import Scene, load_scene, parse_quantity_expr, parse_scene, parse_toml, \
    read_scene_text

#: most variants one run makes (documented in README; checked before any work)
MAX_VARIANTS = 500
#: the polygon's largest extent on paper at the round scale (mm)
POLYGON_MM = 120.0
UNIT = {"velocity": "m/s", "acceleration": "m/s²", "angular_velocity": "rad/s",
        "angular_acceleration": "rad/s²"}
#: the default range when a scene has no [exam] table: the crank angle round the turn
DEFAULT_ANGLES = "0..350 deg step 10"
#: asked functions answered with their sign (one convention, stated in every question)
SIGNED = ("omega", "alpha", "vs", "as")
#: draws of the fixed probe that finds answers constant across variants or duplicated
PROBE_DRAWS = 12
#: the cost model of one draw (s): a solve, its checks and, when kept, the emulation —
#: measured on this project's 2-core machine (Fig 7: ~3 ms; a 100-link chain: ~45 ms)
DRAW_S_BASE, DRAW_S_PER_POINT = 2e-3, 2.2e-4
#: the default worst-case work budget of one `exam` run (seconds; --budget raises it)
BUDGET_S = 600.0


@dataclass(frozen=True)
class Asked:
    """One asked quantity of one variant."""
    expr: str               # 'omega(BC)'
    fn: str                 # its function, typed at load: 'omega'
    words: str              # 'angular velocity of BC'
    symbol: str             # 'ω_BC'
    unit: str               # SI unit shown ('rad/s')
    value: float            # SI, signed for ω, α, vs, as
    tolerance: float        # absolute, SI: Moodle's rule |x − answer| ≤ tolerance
    source: str             # 'emulated' | 'stated' | 'reading'
    sense: str | None       # 'CW' / 'CCW' for ω and α (shown in the key), else None

    @property
    def signed(self) -> bool:
        """ω, α (+ counter-clockwise) and a sliding value (+ along its slot's stated way) are
        answered with their sign; a point's velocity or acceleration by its magnitude."""
        return self.fn in SIGNED

    @property
    def answer(self) -> float:
        """What the student writes: the signed value, or the magnitude (:attr:`signed`)."""
        return self.value if self.signed else abs(self.value)


@dataclass(frozen=True)
class Variant:
    number: int                             # 1, 2, ...
    values: tuple[tuple[str, str], ...]     # (name in [exam], value as written)
    scene: Scene
    solution: Solution
    asked: tuple[Asked, ...]
    scales: Mapping[str, float]             # diagram -> SI per cm (round)
    min_angle_deg: float
    closure_deg: float
    #: everything a student needs, in words: (what, value) rows (:func:`data_rows`)
    data: tuple[tuple[str, str], ...] = ()


@dataclass(frozen=True)
class ExamSet:
    scene: Scene
    spec: ExamSpec
    seed: int
    variants: tuple[Variant, ...]
    rejected: Mapping[str, int]             # reason -> count
    drawn: int                              # every variant drawn, kept or not
    default_ranges: bool                    # the scene had no [exam]: the angle was varied
    dropped: tuple[tuple[str, str], ...] = ()   # (asked expr, why it is not asked)
    combinations: int = 0                   # how many distinct variants the ranges give


# ---------------------------------------------------------------- words
_SYMBOL = {"v": "v", "a": "a", "an": "aⁿ", "at": "aᵗ", "omega": "ω", "alpha": "α",
           "cor": "a_cor", "vs": "v_slide", "as": "a_slide"}


def _args(expr: str) -> tuple[str, tuple[str, ...]]:
    """(function, labels) of a quantity, read by the scene's one grammar (typed, cached)."""
    return parse_quantity_expr(expr)


def _positive(sol: Solution | None, label: str) -> str:
    """Which way a sliding value counts positive, from the slide's record."""
    sr = sol.slides.get(label) if sol is not None else None
    if sr is None or sr.along != "guide":
        lever = sr.along if sr is not None else "its lever"
        return f"along the slot of {lever}, + away from its pivot"
    angle = round(math.degrees(math.atan2(sr.direction[1], sr.direction[0])), 6)
    return f"along its guide, + towards {angle:g}° from +x"


def words(expr: str, sol: Solution | None = None) -> str:
    fn, args = _args(expr)
    a0 = args[0] if args else ""
    rel = f" relative to {args[1]}" if len(args) > 1 else ""
    if fn in ("vs", "as"):
        what = "velocity" if fn == "vs" else "acceleration"
        return f"sliding {what} of {a0} ({_positive(sol, a0)})"
    return {"v": f"velocity of {a0}{rel}", "a": f"acceleration of {a0}{rel}",
            "an": f"centripetal acceleration of {a0}{rel}",
            "at": f"tangential acceleration of {a0}{rel}",
            "omega": f"angular velocity of link {a0}",
            "alpha": f"angular acceleration of link {a0}",
            "cor": f"Coriolis acceleration of {a0}",
            }[fn]


def symbol(expr: str) -> str:
    """The asked quantity's symbol in the notation table's spelling (docs/notation.md), as
    the drawings and the handout name it: v_P2, (v_P2)_P4, (a_P4)ⁿ_O4, ω_O4P4 — never the
    labels run together (v_P2P4)."""
    fn, args = _args(expr)
    if fn in ("v", "a") and len(args) == 2:
        return notation.quantity(f"({fn}_{args[0]})_{args[1]}")
    if fn in ("an", "at") and len(args) == 2:
        return notation.quantity(f"(a_{args[0]})_{args[1]}^{fn[1]}")
    return f"{_SYMBOL[fn]}_{''.join(args)}"


# ---------------------------------------------------------------- the data in words
def _g(x: float) -> str:
    """A value as a student reads it: at most six significant figures, no e-notation."""
    if abs(x) < 1e-9 or not math.isfinite(x):     # below 1e-9 of the unit: rounding noise
        return "0"
    text = f"{x:.{max(0, 5 - math.floor(math.log10(abs(x))))}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def _mm(x: float) -> str:
    return f"{_g(x * 1000.0)} mm"


def _deg(a: float) -> str:
    return f"{_g(math.degrees(a) % 360.0)}°"


def data_rows(scene: Scene) -> tuple[tuple[str, str], ...]:
    """Every datum of the variant in words — fixed points, lengths, guides, slots, points on
    links, the closure chosen and the driver — so that a question can be answered without
    its picture (x to the right, y up; angles counter-clockwise from +x)."""
    rows: list[tuple[str, str]] = []
    model = scene.model                 # the joint tables as read once (polygons.model)
    for label, (x, y) in scene.ground.items():
        rows.append((f"fixed point {label}", f"at x = {_mm(x)}, y = {_mm(y)}"))
    for link in model.links():
        if link.length is not None:
            rows.append((f"link {link.name}", f"{link.a}{link.b} = {_mm(link.length)}"))
    yoke_pins = {s.carrier: s for s in model.yoke_slots()}
    for label, g in model.guide.items():
        words_ = (f"slides on a straight fixed guide through x = {_mm(g.line.through[0])}, "
                  f"y = {_mm(g.line.through[1])} at {_deg(g.line.angle)} from +x")
        pin = yoke_pins.get(label)
        if pin is not None and pin.line.angle is not None:
            words_ += f"; {pin.at} slides in its straight slot at {_deg(pin.line.angle)} from +x"
        rows.append((f"slider {label}", words_))
    for pin, slot in model.slot.items():
        where = f"the slot of link {slot.carrier}, which turns about {slot.line.origin}"
        if slot.line.offset:
            where += f" (the slot line {_mm(abs(slot.line.offset))} to the " \
                     f"{'left' if slot.line.offset > 0 else 'right'} of the lever's line)"
        rows.append((f"pin {pin}", f"slides in {where}; {slot.coincident} is the point of "
                                   f"the lever under {pin}"))
    for label, bp in model.points.items():
        link = model.link(bp.link)
        ends = (link.a, link.b) if link is not None else ("its first end", "its second end")
        along = (_mm(bp.along) if bp.along is not None
                 else f"{_g(bp.fraction or 0.0)} of the way")
        rows.append((f"point {label}", f"on link {bp.link}: {along} from {ends[0]} towards "
                                       f"{ends[1]}" + (f", {_mm(abs(bp.left))} to the "
                                       f"{'left' if bp.left > 0 else 'right'} of "
                                       f"{ends[0]}→{ends[1]}" if bp.left else "")))
    for label, br in scene.assembly.items():
        rows.append((f"assembly of {label}", br.text))
    drv = scene.driver
    if hasattr(drv, "pivot"):
        rows.append((f"crank {drv.link}", f"at {_deg(drv.angle)} from +x"))
        rows.append((f"angular velocity of {drv.link}",
                     f"{_g(abs(drv.omega))} rad/s {'CCW' if drv.omega >= 0 else 'CW'}"))
        alpha = getattr(drv, "alpha", 0.0) or 0.0
        rows.append((f"angular acceleration of {drv.link}",
                     f"{_g(abs(alpha))} rad/s² {'CCW' if alpha > 0 else 'CW' if alpha else ''}"
                     .rstrip()))
    else:
        g = model.guide.get(drv.point)
        way = (f"+ towards {_deg(g.line.angle)} from +x" if g is not None
               else "+ along its guide")
        if drv.rod_rate is not None:
            rod, w, al = drv.rod_rate
            rows.append((f"driving slider {drv.point}", f"at {_mm(drv.position)} along its "
                                                        f"guide ({way}) from its through point"))
            rows.append((f"angular velocity of {rod}",
                         f"{_g(abs(w))} rad/s {'CCW' if w >= 0 else 'CW'}"))
            rows.append((f"angular acceleration of {rod}",
                         f"{_g(abs(al))} rad/s² {'CCW' if al > 0 else 'CW' if al else ''}"
                         .rstrip()))
        else:
            rows.append((f"driving slider {drv.point}",
                         f"at {_mm(drv.position)} along its guide ({way}) from its through "
                         f"point; velocity {_g(drv.velocity)} m/s, acceleration "
                         f"{_g(drv.acceleration)} m/s² (signed the same way)"))
    # the student gets no scene file: every other pair in words too
    crossing: dict[str, list] = {}
    for sl in model.crossings():                # two pairs per pin, one per lever
        crossing.setdefault(sl.at, []).append(sl)
    for pin, (s1, s2) in crossing.items():
        (l1, l2), (c1, c2) = (s1.carrier, s2.carrier), (s1.coincident, s2.coincident)
        rows.append((f"pin {pin}", f"slides in the slots of links {l1} and {l2} at once (each "
                                   f"slot along its link, {_ends(model, l1)} and {_ends(model, l2)}"
                                   f"); {c1} and {c2} are the points of {l1} and {l2} under "
                                   f"{pin}"))
    for point, sl in model.prescribed.items():
        rows.append((f"collar {point}", f"slides along link {sl.link}: at {_mm(sl.position)} "
                                        f"from {sl.p} towards {sl.q}, sliding velocity "
                                        f"{_g(sl.velocity)} m/s and acceleration "
                                        f"{_g(sl.acceleration)} m/s² (signed from {sl.p} "
                                        f"towards {sl.q}); {sl.coincident} is the point of "
                                        f"{sl.link} under {point}"))
    for q in scene.equivalents:
        text = q.words
        if q.opposite_motion is not None:
            text += (f"; the plate of {q.opposite} moves at {_g(q.opposite_motion[0])} m/s, "
                     f"accelerating at {_g(q.opposite_motion[1])} m/s² (signed along "
                     f"{_deg(q.face)})")
        rows.append((f"contact at {q.at}", text))
    return tuple(rows)


def _ends(model, lever: str) -> str:
    link = model.link(lever)
    return f"from {link.a} through {link.b}" if link is not None else lever


# ---------------------------------------------------------------- scales
def round_scales(sol: Solution) -> dict[str, float]:
    """diagram -> SI per cm: a round scale that fits the polygon within :data:`POLYGON_MM`."""
    out = {}
    for d, verts in sol.vertices.items():
        xs = [p[0] for p in verts.values()]
        ys = [p[1] for p in verts.values()]
        extent = max(max(xs) - min(xs), max(ys) - min(ys))
        out[d] = round_up(extent / (POLYGON_MM / 10.0)) if extent > 0 else 1.0
    return out


class _Scale:
    """What :func:`polygons.tolerances.tolerance_for` reads of a scale."""

    def __init__(self, per_cm: float):
        self.mm_per_si = 10.0 / per_cm


# ---------------------------------------------------------------- one variant
def convention(a_fn: str, expr: str, sol: Solution | None = None) -> str:
    """The sign convention of one answer, in words (every question states its own)."""
    if a_fn in ("omega", "alpha"):
        return ("Give it signed: positive counter-clockwise (CCW), negative clockwise (CW), "
                "with x to the right and y up.")
    if a_fn in ("vs", "as"):
        along, _, way = _positive(sol, _args(expr)[1][0]).partition(", + ")
        return f"Give it signed {along}: positive {way}, negative the other way."
    return "Give its magnitude (a positive number)."


def pose_check(scene: Scene, sp: ExamSpec, asked: tuple[str, ...]) -> tuple[float, str | None]:
    """(the assembly's smallest angle in degrees, why the pose is refused or None).

    The assembly angle is the smallest angle of the position construction at the pose
    (asin of :func:`polygons.sweep.evaluate`'s margin: 0 at a toggle or where the two closures
    meet).  Over the window ± ``pose_margin`` (a turn of the driving crank, or of the slider's
    longest link about it), sampled at five poses, the mechanism must still close, every
    moving link's ω and every slide's velocity keep one sign (no dead centre: nothing comes
    to rest) and so must every asked signed answer (no change point)."""
    import numpy as np
    from ..sweep import compile_plan, evaluate
    from ..position import driver_input
    prog = compile_plan(scene)
    x0 = float(driver_input(scene))
    turn = math.radians(sp.pose_margin_deg)
    if not hasattr(scene.driver, "pivot"):
        turn *= max((ln.length or 0.0 for ln in scene.model.links()), default=0.0)
    with np.errstate(all="ignore"):         # the pose first: positions only (cheap)
        m0 = float(evaluate(prog, np.array([x0]), rates=False)["margin"][0])
    closure = 0.0 if not math.isfinite(m0) or m0 < 0 else math.degrees(math.asin(min(m0, 1.0)))
    if closure < sp.closure_margin_deg:
        return closure, (f"within {sp.closure_margin_deg:g}° of the other closure or a toggle")
    if turn == 0:
        return closure, None
    xs = x0 + turn * np.array([0.0, -1.0, -0.5, 0.5, 1.0])
    with np.errstate(all="ignore"):
        out = evaluate(prog, xs, rates=True)
    m = np.asarray(out["margin"], dtype=float)
    margin_words = f"{sp.pose_margin_deg:g}°"
    if not (np.all(np.isfinite(m)) and np.all(m > 0)):
        return closure, f"within {margin_words} of a pose where it does not close"

    def one_sign(series) -> bool:
        v = np.broadcast_to(np.asarray(series, dtype=float), xs.shape)
        if not np.all(np.isfinite(v)):
            return False
        big = float(np.max(np.abs(v)))
        if big <= 1e-12:                        # at rest throughout (a fixed body)
            return True
        return bool(np.all(v > 0) or np.all(v < 0))
    for name, w in out["omega"].items():
        if not one_sign(w):
            return closure, f"within {margin_words} of a dead centre (a link at rest)"
    for name, sv in out["slide_v"].items():
        if not one_sign(sv):
            return closure, f"within {margin_words} of a dead centre (a slider at rest)"
    table = {"omega": "omega", "alpha": "alpha", "vs": "slide_v", "as": "slide_a"}
    for expr in asked:
        fn, args = _args(expr)
        series = out.get(table.get(fn, ""), {}).get(args[0]) if fn in table else None
        if series is not None and not one_sign(series):
            return closure, f"within {margin_words} of a change point (an asked answer " \
                            f"changing sign)"
    return closure, None


def closure_angle_deg(scene: Scene) -> float:
    """The smallest angle of the assembly construction at the scene's input, degrees (90
    when nothing closes by two circles or lines)."""
    import numpy as np
    from ..sweep import compile_plan, evaluate
    drv = scene.driver
    x = getattr(drv, "angle", None)
    if x is None:
        x = getattr(drv, "position", 0.0)
    prog = compile_plan(scene)
    with np.errstate(all="ignore"):
        m = float(evaluate(prog, np.atleast_1d(float(x)), rates=False)["margin"][0])
    if not math.isfinite(m) or m < 0:
        return 0.0
    return math.degrees(math.asin(min(m, 1.0)))


def answers(sol: Solution, asked: tuple[str, ...], scales: Mapping[str, float]
            ) -> tuple[Asked, ...]:
    from ..tolerances import emulated_tolerances, stated_tolerance, tolerance_for
    emulated = emulated_tolerances(sol)
    stated = stated_tolerance(sol)
    sc = {d: _Scale(v) for d, v in scales.items()}
    out = []
    for expr in asked:
        value = quantity(sol, expr)
        pct, source = (emulated[expr], "emulated") if expr in emulated else (stated, "stated")
        tol = tolerance_for(sol, expr, value, pct, sc)
        if tol > pct * abs(value) * (1 + 1e-9):
            source = "reading"
        fn = _args(expr)[0]
        sense = None
        if fn in ("omega", "alpha") and value != 0:
            sense = "CCW" if value > 0 else "CW"
        out.append(Asked(expr, fn, words(expr, sol), symbol(expr),
                         UNIT[dimension_of_quantity(expr)], value, tol, source, sense))
    return tuple(out)


def _set(data: dict, key: str, text: str, base: Scene) -> None:
    table, _, name = key.partition(".")
    data.setdefault(table, {})
    if table == "driver" and name in ("omega", "alpha", "rod_omega", "rod_alpha"):
        # the sense stays the scene's: written out in words, any sense in the text dropped
        if name.startswith("rod_"):
            rate = base.driver.rod_rate[1 if name == "rod_omega" else 2]
        else:
            rate = (base.driver.omega if name == "omega"
                    else getattr(base.driver, "alpha", 0.0)) or 0.0
        sense_key = {"omega": "sense", "alpha": "alpha_sense", "rod_omega": "rod_sense",
                     "rod_alpha": "rod_alpha_sense"}[name]
        data["driver"][sense_key] = "CW" if rate < 0 else "CCW"
    data[table][name] = text
    if table == "driver" and name == "angle":
        # a variant's cam angle replaces the book's event ([cam_profiles] when = "leaves the
        # straight flank"), which is the scene's way of stating its one angle
        for prof in (data.get("cam_profiles") or {}).values():
            if isinstance(prof, dict):
                prof.pop("when", None)


def _rejects(sol: Solution, sp: ExamSpec, scales, asked) -> str | None:
    ang = sol.min_intersection_angle_deg
    if ang is not None and ang < sp.min_angle_deg:
        return f"a construction angle under {sp.min_angle_deg:g}°"
    for expr in asked:
        value = quantity(sol, expr)
        diagram, si = drawn_on_polygon(sol, expr, value)
        # a zero answer draws no line at all: it is rejected like a short one (no noise)
        per_cm = scales.get(diagram)
        if per_cm is None or si * 10.0 / per_cm < sp.min_vector_mm:
            return f"an asked answer's line under {sp.min_vector_mm:g} mm at the round scale"
    return None


def one_line(text: str) -> str:
    """Every run of white space (a line break included) as one space."""
    return " ".join(str(text).split())


# ---------------------------------------------------------------- the set
def combinations(sp: ExamSpec) -> int:
    return math.prod(len(r.values) for r in sp.ranges) if sp.ranges else 1


def _pick(sp: ExamSpec, index: int) -> tuple[str, ...]:
    """The combination ``index`` (0 .. combinations − 1) of the ranges' values."""
    out = []
    for r in reversed(sp.ranges):
        index, k = divmod(index, len(r.values))
        out.append(r.values[k])
    return tuple(reversed(out))


def _order(sp: ExamSpec, rng: random.Random, limit: int):
    """Combination indices in a seeded order, none twice, at most ``limit``."""
    total = combinations(sp)
    if total <= 100_000:
        order = list(range(total))
        rng.shuffle(order)
        yield from order[:limit]
        return
    seen: set[int] = set()
    while len(seen) < min(limit, total):
        k = rng.randrange(total)
        if k not in seen:
            seen.add(k)
            yield k


def estimate_seconds(scene: Scene, draws: int) -> float:
    """The worst-case time of ``draws`` draws of ``scene`` by the cost model above."""
    size = len(scene.labels) + len(scene.model.links())
    return draws * (DRAW_S_BASE + DRAW_S_PER_POINT * size)


def _duration(s: float) -> str:
    if s < 120:
        return f"{s:.0f} s"
    if s < 7200:
        return f"{s / 60:.0f} min"
    return f"{s / 3600:.1f} h"


def make_exam(path: str, n: int, seed: int, budget_s: float = BUDGET_S) -> ExamSet:
    """``n`` variants of the scene at ``path`` (``1 ≤ n ≤`` :data:`MAX_VARIANTS`); refused
    before any draw when the worst case (``n`` × attempts draws, at most every combination)
    is estimated above ``budget_s`` seconds."""
    if not 1 <= n <= MAX_VARIANTS:
        raise SceneError(f"--variants must be from 1 to {MAX_VARIANTS}, got {n}", file=path)
    base = load_scene(path)
    data = parse_toml(read_scene_text(path), str(path))
    sp = exam_spec(base, parse_quantity_expr)
    default = sp is None
    if default:                 # no [exam]: the crank angle round the turn, the [[answers]]
        if not hasattr(base.driver, "pivot"):
            raise SceneError("add an [exam] table saying what varies (this scene's driver is "
                             "not a crank, so the crank angle cannot be varied by default: a "
                             "slider's position or velocity, its rod's rod_angle or rod_omega, "
                             "or a link's length)",
                             file=path, where="exam")
        probe = copy.deepcopy(data)
        probe["exam"] = {"angle": DEFAULT_ANGLES}
        sp = exam_spec(parse_scene(probe, file=str(path)), parse_quantity_expr)
    placed_by_rod = isinstance(data.get("driver"), dict) and "rod" in data["driver"]
    for rg in sp.ranges:        # a slider placed by position, or by its rod's angle
        if rg.key in ("driver.position", "driver.rod_angle") and \
                (rg.key == "driver.rod_angle") != placed_by_rod:
            how = "its rod (vary rod_angle)" if placed_by_rod else "position (vary position)"
            raise SceneError(f"{rg.name} varies how the slider driver is placed; this scene "
                             f"places it by {how}", file=path, where=f"exam.{rg.name}")
    if isinstance(data.get("drawn"), dict) and data["drawn"] and sp.ranges:
        raise SceneError("the scene states its pose by [drawn] positions (one instant as drawn: "
                         "they choose its closures and may give lengths), which a variant's "
                         "other numbers move away from: for an exam state the lengths and "
                         "the crank angle, and each closure in words ([assembly], e.g. C = \"C "
                         "above AD\"), in place of [drawn]", file=path, where="drawn")
    if not sp.ask:
        raise SceneError("nothing to ask: give [exam] ask = [\"omega(BC)\", ...] (the scene's "
                         "[[answers]] name no velocity or acceleration)", file=path,
                         where="exam.ask")
    if not sp.ranges and n > 1:
        raise SceneError("the [exam] table varies nothing: add a range such as "
                         "angle = \"20..70 deg step 5\" (or ask for one variant)", file=path,
                         where="exam")
    total = combinations(sp)
    if total < n:
        sizes = " × ".join(f"{r.name} {len(r.values)}" for r in sp.ranges)
        raise SceneError(f"the [exam] ranges give only {total:,} distinct variants ({sizes}); "
                         f"{n} asked: widen a range or add one", file=path, where="exam")
    draws = min(total, n * sp.attempts)
    worst = estimate_seconds(base, draws)
    if worst > budget_s:
        raise SceneError(f"this exam may draw up to {draws:,} variants of a scene of "
                         f"{len(base.links)} links (about {_duration(worst)} in the worst case, "
                         f"~{estimate_seconds(base, 1) * 1000:.0f} ms a draw), above the "
                         f"budget of {_duration(budget_s)}: lower [exam] attempts or "
                         f"--variants, or raise --budget (minutes)", file=path, where="exam")
    base_sol = solve(base)
    for i, expr in enumerate(sp.ask):          # every asked quantity exists in this mechanism
        try:
            quantity(base_sol, expr)
        except PolygonsError as exc:
            raise SceneError(f"cannot ask {expr!r}: {exc.reason}", file=path,
                             where=f"exam.ask[{i}]") from None
    del base_sol
    ask, dropped = _plan_asked(data, base, sp, path)
    if not ask:
        why = "; ".join(f"{symbol(e)} {w}" for e, w in dropped)
        raise SceneError(f"nothing left to ask: {why}; vary what they depend on or ask "
                         f"other quantities", file=path, where="exam.ask")
    sp = dataclasses.replace(sp, ask=ask)
    rng = random.Random(seed)
    order = _order(sp, rng, draws)
    seen: set[tuple[str, ...]] = set()
    rejected: dict[str, int] = {}
    variants: list[Variant] = []
    drawn = 0
    for k in range(1, n + 1):
        for _ in range(sp.attempts):
            index = next(order, None)
            if index is None:
                raise SceneError(_short(variants, n, total, drawn, rejected, sp, exhausted=True),
                                 file=path, where="exam")
            drawn += 1
            pick = _pick(sp, index)
            reason, variant = _try(data, base, sp, pick, k, path, seen)
            if variant is not None:
                variants.append(variant)
                break
            rejected[reason] = rejected.get(reason, 0) + 1
        else:
            raise SceneError(_short(variants, n, total, drawn, rejected, sp, exhausted=False),
                             file=path, where="exam")
    return ExamSet(base, sp, seed, tuple(variants), dict(sorted(rejected.items())), drawn,
                   default, tuple(dropped), total)


def _short(variants, n, total, drawn, rejected, sp, exhausted: bool) -> str:
    """Why fewer than ``n`` variants: how many the ranges can give, and what limits them."""
    why = "; ".join(f"{c} {r}" for r, c in sorted(rejected.items(), key=lambda x: -x[1]))
    top = max(rejected.items(), key=lambda x: x[1])[0] if rejected else "none"
    kept = len(variants)
    ranges = "the [exam] ranges give" if sp.ranges else "the scene alone gives"
    are = "is" if kept == 1 else "are"
    if exhausted:
        can = f"{ranges} {total:,} combinations and only {kept} {are} well posed"
    else:
        est = round(total * kept / drawn) if drawn else 0
        can = (f"only {kept} of {n} variants found well posed in {drawn:,} draws (about "
               f"{est:,} of the {total:,} combinations would be)")
    return (f"{can}; {n} asked (rejected: {why}); the limiting criterion: {top} — widen the "
            f"[exam] ranges, relax that criterion"
            + ("" if exhausted else " or raise attempts"))


def _plan_asked(data, base: Scene, sp: ExamSpec, path) -> tuple[tuple[str, ...], list]:
    """The asked quantities, less those that are the same in every variant or equal in size
    to one asked before it, found on a fixed probe of :data:`PROBE_DRAWS` combinations
    (``random.Random(0)``: the same for every seed)."""
    if not sp.ranges or combinations(sp) < 2:
        return sp.ask, []
    values: list[list[float]] = []
    rng = random.Random(0)
    from ..memo import forget, recording
    for index in _order(sp, rng, min(combinations(sp), 4 * PROBE_DRAWS)):
        d = _variant_data(data, base, sp, _pick(sp, index), 0)
        try:
            with recording() as made:
                sol = solve(parse_scene(d, file=f"{path} (probe)"))
                values.append([quantity(sol, e) for e in sp.ask])
        except (PolygonsError, Warning, ArithmeticError):
            continue
        finally:
            forget(made)
        if len(values) >= PROBE_DRAWS:
            break
    if len(values) < 2:
        return sp.ask, []
    cols = list(zip(*values))

    def same(xs, ys) -> bool:
        return all(math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-12 * max(1.0, abs(x)))
                   for x, y in zip(xs, ys))
    keep, dropped = [], []
    for i, expr in enumerate(sp.ask):
        col = cols[i]
        if same(col, [col[0]] * len(col)):
            what = "0" if abs(col[0]) < 1e-12 else "the same"
            dropped.append((expr, f"is {what} in every variant: it needs no drawing"))
            continue
        twin = next((e for j, e in enumerate(sp.ask[:i]) if e in keep
                     and dimension_of_quantity(e) == dimension_of_quantity(expr)
                     and same([abs(x) for x in cols[j]], [abs(x) for x in col])), None)
        if twin is not None:
            dropped.append((expr, f"is as large as {symbol(twin)} in every variant: it asks "
                                  f"the same thing"))
            continue
        keep.append(expr)
    return tuple(keep), dropped


def _variant_data(data, base, sp: ExamSpec, pick, k) -> dict:
    d = copy.deepcopy(data)
    d.pop("exam", None)
    for r, text in zip(sp.ranges, pick):
        _set(d, r.key, text, base)
    # the title and the statement may quote values the variant changes: neither is kept
    d["title"] = one_line(f"{sp.title} — variant {k}")
    src = d.get("source", {}) if isinstance(d.get("source"), dict) else {}
    d["source"] = {key: src[key] for key in ("drawing_tolerance", "mechanism") if key in src}
    return d


def _try(data, base, sp: ExamSpec, pick, k, path, seen):
    """(reason, None) for a rejected draw — nothing of it is kept: the memos its scene and
    solution made are dropped (:func:`polygons.memo.forget`) — or ("", the variant)."""
    from ..memo import forget, recording
    with recording() as made:
        reason, variant = _draw(data, base, sp, pick, k, path, seen)
    if variant is None:
        forget(made)
    return reason, variant


def _draw(data, base, sp: ExamSpec, pick, k, path, seen):
    d = _variant_data(data, base, sp, pick, k)
    try:
        scene = parse_scene(d, file=f"{path} (variant {k})")
        sol = solve(scene)
        closure, why = pose_check(scene, sp, sp.ask)
        if why:
            return why, None
        sol.steps                       # the construction, drawn
    except (PolygonsError, Warning, ArithmeticError):   # (a command runs with every warning
        return "does not assemble or cannot be constructed", None      # an error)
    scales = round_scales(sol)
    why = _rejects(sol, sp, scales, sp.ask)
    if why:
        return why, None
    try:
        asked = answers(sol, sp.ask, scales)
    except (PolygonsError, Warning, ArithmeticError):
        return "its answers cannot be read or emulated", None
    if any(abs(a.value) < sp.min_ratio * a.tolerance for a in asked):
        return f"an asked answer under {sp.min_ratio:g}× its tolerance", None
    key = tuple(_num_key(a.answer) for a in asked)
    if key in seen:
        return "the same answers as a variant kept before", None
    seen.add(key)
    values = tuple((r.name, text) for r, text in zip(sp.ranges, pick))
    return "", Variant(k, values, scene, sol, asked, scales,
                       sol.min_intersection_angle_deg or 90.0, closure, data_rows(scene))


def _num_key(x: float) -> str:
    """An answer as the quiz prints it (six significant figures)."""
    return f"{x:.5e}"


__all__ = ["Asked", "Variant", "ExamSet", "make_exam", "round_scales", "closure_angle_deg",
           "pose_check", "convention", "words", "symbol", "one_line", "estimate_seconds",
           "MAX_VARIANTS", "SIGNED", "BUDGET_S"]
