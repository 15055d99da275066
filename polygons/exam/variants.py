"""Seeded variants of a scene for an exam, each well conditioned, with its answers and the
tolerance a careful drawing deserves.

A variant takes one value from each range of the scene's ``[exam]`` (drawn with
``random.Random(seed)``: the same seed gives the same variants on every machine) and is
solved as an ordinary scene.  It is kept only if

* it assembles (the closure the scene's words choose exists),
* its assembly is at least ``closure_margin`` from the other closure and from a toggle (the
  smallest angle of the position construction, :func:`polygons.sweep.evaluate`'s margin),
* every intersection of its velocity and acceleration constructions is at least
  ``min_angle`` (30° by default: a 0.25° protractor error then stays near 1 % in ω),
* at its round drawing scale (1, 2, 2.5 or 5 × 10ⁿ per cm, the polygon within 120 mm) no
  asked vector is shorter than ``min_vector`` (8 mm), and
* it differs from every variant kept before;

otherwise it is drawn again, at most ``attempts`` times per variant.  Rejections are counted
by reason.

Each asked quantity's tolerance is what ``polygons check`` allows: the 95th percentile of its
error in the drawing-board emulation (:func:`polygons.tolerances.emulated_tolerances`), else
the scene's stated drawing tolerance, and never less than a 0.5 mm ruler reading at the
variant's scale.
"""
from __future__ import annotations

import copy
import math
import random
from dataclasses import dataclass
from typing import Mapping

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
    sense: str | None       # 'CW' / 'CCW' for ω and α (asked separately), else None

    @property
    def answer(self) -> float:
        """What the student writes: a magnitude (the sense of ω, α is a separate choice)."""
        return abs(self.value) if self.fn not in ("vs", "as") else self.value


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


@dataclass(frozen=True)
class ExamSet:
    scene: Scene
    spec: ExamSpec
    seed: int
    variants: tuple[Variant, ...]
    rejected: Mapping[str, int]             # reason -> count
    drawn: int                              # every variant drawn, kept or not
    default_ranges: bool                    # the scene had no [exam]: the angle was varied


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
    fn, args = _args(expr)
    return f"{_SYMBOL[fn]}_{''.join(args)}"


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


def _rejects(sol: Solution, sp: ExamSpec, scales, asked) -> str | None:
    ang = sol.min_intersection_angle_deg
    if ang is not None and ang < sp.min_angle_deg:
        return f"a construction angle under {sp.min_angle_deg:g}°"
    for expr in asked:
        value = quantity(sol, expr)
        diagram, si = drawn_on_polygon(sol, expr, value)
        if diagram not in scales or si <= 1e-9 * _largest(sol, diagram):
            continue            # a zero answer (at(B,A) of a steady crank) draws no vector
        if si * 10.0 / scales[diagram] < sp.min_vector_mm:
            return f"an asked vector under {sp.min_vector_mm:g} mm at the round scale"
    return None


def _largest(sol: Solution, diagram: str) -> float:
    return max((math.hypot(*p) for p in sol.vertices[diagram].values()), default=0.0)


# ---------------------------------------------------------------- the set
def make_exam(path: str, n: int, seed: int) -> ExamSet:
    """``n`` variants of the scene at ``path`` (``1 ≤ n ≤`` :data:`MAX_VARIANTS`)."""
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
    if not sp.ask:
        raise SceneError("nothing to ask: give [exam] ask = [\"omega(BC)\", ...] (the scene's "
                         "[[answers]] name no velocity or acceleration)", file=path,
                         where="exam.ask")
    if not sp.ranges and n > 1:
        raise SceneError("the [exam] table varies nothing: add a range such as "
                         "angle = \"20..70 deg step 5\" (or ask for one variant)", file=path,
                         where="exam")
    base_sol = solve(base)
    for i, expr in enumerate(sp.ask):          # every asked quantity exists in this mechanism
        try:
            quantity(base_sol, expr)
        except PolygonsError as exc:
            raise SceneError(f"cannot ask {expr!r}: {exc.reason}", file=path,
                             where=f"exam.ask[{i}]") from None
    rng = random.Random(seed)
    seen: set[tuple[str, ...]] = set()
    rejected: dict[str, int] = {}
    variants: list[Variant] = []
    drawn = 0
    for k in range(1, n + 1):
        for _ in range(sp.attempts):
            drawn += 1
            pick = tuple(rng.choice(r.values) for r in sp.ranges)
            reason, variant = _try(data, base, sp, pick, k, path, seen)
            if variant is not None:
                seen.add(pick)
                variants.append(variant)
                break
            rejected[reason] = rejected.get(reason, 0) + 1
        else:
            why = "; ".join(f"{c} {r}" for r, c in sorted(rejected.items()))
            raise SceneError(f"only {len(variants)} of {n} variants found well conditioned in "
                             f"{sp.attempts} draws for variant {k} (rejected: {why}); widen "
                             f"the [exam] ranges, lower min_angle or raise attempts",
                             file=path, where="exam")
    return ExamSet(base, sp, seed, tuple(variants), dict(sorted(rejected.items())), drawn,
                   default)


def _try(data, base, sp: ExamSpec, pick, k, path, seen):
    if pick in seen:
        return "a duplicate of a variant kept before", None
    d = copy.deepcopy(data)
    d.pop("exam", None)
    for r, text in zip(sp.ranges, pick):
        _set(d, r.key, text, base)
    # the title and the statement may quote values the variant changes: neither is kept
    d["title"] = f"{sp.title} — variant {k}"
    src = d.get("source", {}) if isinstance(d.get("source"), dict) else {}
    d["source"] = {key: src[key] for key in ("drawing_tolerance", "mechanism") if key in src}
    try:
        scene = parse_scene(d, file=f"{path} (variant {k})")
        sol = solve(scene)
        sol.steps                       # the construction, drawn
        closure = closure_angle_deg(scene)
    except (PolygonsError, Warning):    # (a command runs with every warning an error)
        return "does not assemble or cannot be constructed", None
    if closure < sp.closure_margin_deg:
        return f"within {sp.closure_margin_deg:g}° of the other closure or a toggle", None
    scales = round_scales(sol)
    why = _rejects(sol, sp, scales, sp.ask)
    if why:
        return why, None
    try:
        asked = answers(sol, sp.ask, scales)
    except (PolygonsError, Warning):
        return "its answers cannot be read or emulated", None
    values = tuple((r.name, text) for r, text in zip(sp.ranges, pick))
    return "", Variant(k, values, scene, sol, asked, scales,
                       sol.min_intersection_angle_deg or 90.0, closure)


__all__ = ["Asked", "Variant", "ExamSet", "make_exam", "round_scales", "closure_angle_deg",
           "words", "symbol", "MAX_VARIANTS"]
