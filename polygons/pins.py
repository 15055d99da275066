"""Pin sizes, rubbing velocities and the point of least velocity on a link.

    [pins.B]                 # the pin at B has a diameter: its rubbing velocity is reported
    diameter = "60 mm"
    [least_velocity]         # the point of these links that moves slowest, and its speed
    links = ["BC"]           # (or, at the top of the file: least_velocity = "BC")
    [[pin_answers]]          # printed / exact answers for these (like [[answers]])
    quantity = "rub(B)"      # or "least(BC)" (its speed), "least_at(BC)" (distance from B)
    unit = "m/s"

Rubbing velocity at a pin of radius r joining links 1 and 2: v_r = |ω₁ − ω₂| · r, which is
(ω₁ + ω₂) · r in magnitudes when the two links turn in opposite senses; at a fixed pivot the
frame does not turn, v_r = |ω| · r; a slider block does not turn either.  A pin sliding in
a slot carries a block that turns with the slotted lever (or translates with a Scotch yoke).

Least velocity on link PQ: the foot g of the perpendicular from the pole o to the link's
velocity image pq; the point G divides PQ as g divides pq (PG/PQ = pg/pq), and v_G = og.
If the foot falls beyond p or q, the slowest point of the link itself is that end.

This module parses its tables (``TABLES``) from ``Scene.extra`` and reads a solved
:class:`~polygons.evaluate.Solution` duck-typed; it imports nothing from the solver.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from .errors import SceneError, UnknownLabelError, suggest
from .scene import Scene, _Reader, answer_fields, drawing_tolerance
from .schema import Key, Table
from .scene_tables import ANSWER_FIELDS

Vec = tuple[float, float]

TABLES: tuple[Table, ...] = (
    Table("pins", "Pin sizes: the rubbing velocity at each pin with a diameter is reported.",
          (Key("diameter", "quantity", "diameter of the pin (its radius is used: v = Δω·r)",
               example='"60 mm"', dimension="length", required=True),), many=True),
    Table("least_velocity", "Links on which to find the point of least velocity.",
          (Key("links", "array", "link names, e.g. [\"BC\"]", example='["BC"]',
               required=True),)),
    Table("pin_answers", "Printed and exact answers for rubbing and least velocities "
                         "(fields as [[answers]]; quantity rub(B), least(BC) or "
                         "least_at(BC)).",
          ANSWER_FIELDS, array=True),
)


@dataclass(frozen=True)
class PinSpec:
    diameters: Mapping[str, float]        # pin label -> diameter (m)
    least: tuple[str, ...]                 # link names
    answers: tuple                         # scene.Answer-like dicts as PinAnswer


@dataclass(frozen=True)
class PinAnswer:
    quantity: str
    unit: str
    tutorial: float | None
    exact: float | None
    mode: str
    sense: str | None
    tolerance: float
    slip: bool
    ref: str | None
    desc: str
    note: str


@dataclass(frozen=True)
class Rubbing:
    """Rubbing velocity at pin ``pin`` between ``links`` (names; 'frame' or 'slider C')."""

    pin: str
    diameter: float
    links: tuple[str, str]
    omegas: tuple[float, float]           # signed, CCW positive
    opposite: bool                        # the two turn in opposite senses
    relative: float                       # |ω₁ − ω₂|
    velocity: float                       # |ω₁ − ω₂| · d/2


@dataclass(frozen=True)
class LeastVelocity:
    """The slowest point G of link ``link`` (ends ``a``, ``b``): ``fraction`` = AG/AB along
    the line AB (of the foot of the perpendicular), ``on_link`` False when that foot lies
    beyond an end and the slowest point of the link itself is that end (``point`` is then the
    end)."""

    link: str
    a: str
    b: str
    fraction: float | None                # None when the link translates (all points alike)
    along: float | None                   # AG in m along AB (signed)
    point: Vec                            # G in the space diagram (m)
    velocity: Vec                         # v_G (m/s)
    speed: float
    image: Vec                            # g on the velocity diagram
    on_link: bool


def spec(scene: Scene) -> PinSpec:
    """The scene's [pins], [least_velocity] and [[pin_answers]], checked."""
    r = _Reader(scene.file)
    extra = scene.extra
    diameters: dict[str, float] = {}
    raw = extra.get("pins", {})
    r.named(raw, "pins")
    for label, tab in raw.items():
        where = f"pins.{label}"
        r.label(label, where)
        if label not in scene.labels:
            raise UnknownLabelError(f"unknown point {label!r}: {suggest(label, scene.labels)}",
                                    file=scene.file, where=where)
        r.table(tab, where, ("diameter",), required=("diameter",))
        d = r.quantity(tab["diameter"], "length", where + ".diameter")
        if not d > 0:
            raise SceneError("a pin diameter must be positive", file=scene.file,
                             where=where + ".diameter")
        diameters[label] = d
    least: tuple[str, ...] = ()
    if "least_velocity" in extra:
        raw_least = extra["least_velocity"]
        if isinstance(raw_least, (str, list)):    # least_velocity = "BC" at the top level
            links = raw_least
        else:
            links = r.table(raw_least, "least_velocity", ("links",),
                            required=("links",))["links"]
        if isinstance(links, str):
            links = [links]
        if not isinstance(links, list) or not all(isinstance(x, str) for x in links):
            raise SceneError(f"links must be a list of link names, e.g. [\"BC\"], got "
                             f"{links!r}", file=scene.file, where="least_velocity.links")
        names = _link_names(scene)
        for name in links:
            if name not in names:
                raise UnknownLabelError(f"unknown link {name!r}: {suggest(name, names)}",
                                        file=scene.file, where="least_velocity.links")
        least = tuple(links)
    answers = []
    raw_ans = extra.get("pin_answers", [])
    if not isinstance(raw_ans, list):
        raise SceneError("write these answers as [[pin_answers]] tables", file=scene.file,
                         where="pin_answers")
    tol = drawing_tolerance(scene.source, r)
    for i, a in enumerate(raw_ans):
        where = f"pin_answers[{i}]"
        fields = answer_fields(a, r, where, tol)
        fn, arg = _parse_quantity(fields["quantity"], scene.file, where)
        if fn == "rub" and arg not in diameters:
            raise SceneError(f"rub({arg}) needs [pins.{arg}] diameter", file=scene.file,
                             where=where + ".quantity")
        if fn != "rub" and arg not in least:
            raise SceneError(f"{fn}({arg}) needs {arg} in [least_velocity] links",
                             file=scene.file, where=where + ".quantity")
        answers.append(PinAnswer(**fields))
    return PinSpec(MappingProxyType(diameters), least, tuple(answers))


def _link_names(scene: Scene) -> list[str]:
    return [b.name for b in scene.model.bodies if b.kind in ("link", "lever")]


def _parse_quantity(q: str, file, where) -> tuple[str, str]:
    q = q.replace(" ", "")
    for fn in ("rub", "least_at", "least"):
        if q.startswith(fn + "(") and q.endswith(")"):
            return fn, q[len(fn) + 1:-1]
    raise SceneError(f"quantity must be rub(PIN), least(LINK) or least_at(LINK), got {q!r}",
                     file=file, where=where + ".quantity")


# ---------------------------------------------------------------- results
def _turning(solution) -> dict[str, tuple[float, tuple[str, ...]]]:
    """Every body at a pin, read off the mechanism model: name -> (ω, labels).  The frame
    and slider blocks do not turn; the block on a pin in a lever's slot turns with the lever,
    in a yoke's slot it translates."""
    scene, model = solution.scene, solution.scene.model
    out: dict[str, tuple[float, tuple[str, ...]]] = {"frame": (0.0, tuple(scene.ground))}
    for b in model.moving:
        if b.kind in ("link", "lever"):
            lr = solution.links.get(b.name)
            if lr is not None and lr.omega is not None:
                out[b.name] = (lr.omega, b.labels)
        elif b.kind == "block":
            out[f"slider {b.name}"] = (0.0, (b.name,))
        elif b.kind == "pin-block":
            carrier = model.slide_of(b.name).carrier
            if model.body(carrier).kind == "yoke":
                out[f"block at {b.a}"] = (0.0, (b.a,))
            else:
                lr = solution.links.get(carrier)
                if lr is not None and lr.omega is not None:
                    out[f"block at {b.a}"] = (lr.omega, (b.a,))
    return out


def rubbing_velocities(solution) -> tuple[Rubbing, ...]:
    """The rubbing velocity at every pin with a diameter, per pair of links meeting there."""
    sp = spec(solution.scene)
    bodies = _turning(solution)
    out = []
    for pin, d in sp.diameters.items():
        at = [(name, w) for name, (w, labels) in bodies.items() if pin in labels]
        if len(at) < 2:
            raise SceneError(f"no two links meet at {pin}, so it is not a pin",
                             file=solution.scene.file, where=f"pins.{pin}")
        for x in range(len(at)):
            for y in range(x + 1, len(at)):
                (n1, w1), (n2, w2) = at[x], at[y]
                rel = abs(w1 - w2)
                out.append(Rubbing(pin, d, (n1, n2), (w1, w2), w1 * w2 < 0, rel,
                                   rel * d / 2))
    return tuple(out)


def least_velocity(solution, link: str) -> LeastVelocity:
    """G on ``link``: the foot of the perpendicular from the pole o to the image ab,
    t = −(oa · ab) / |ab|², G = A + t·AB, v_G = oa + t·ab."""
    lr = solution.links.get(link)
    if lr is None or "velocity" not in solution.vertices:
        raise SceneError(f"link {link!r} has no velocity image in this solution",
                         file=solution.scene.file, where="least_velocity")
    a, b = lr.a, lr.b
    pa, pb = solution.points[a].position, solution.points[b].position
    va, vb = solution.points[a].velocity, solution.points[b].velocity
    ab = (vb[0] - va[0], vb[1] - va[1])
    n2 = ab[0] ** 2 + ab[1] ** 2
    scale = max(math.hypot(*va), math.hypot(*vb), 1e-300)
    if math.sqrt(n2) <= 1e-12 * scale:       # the link translates: every point alike
        return LeastVelocity(link, a, b, None, None, tuple(pa), tuple(va), math.hypot(*va),
                             tuple(va), True)
    t = -(va[0] * ab[0] + va[1] * ab[1]) / n2
    on = 0.0 <= t <= 1.0
    tt = min(1.0, max(0.0, t))
    g = (va[0] + tt * ab[0], va[1] + tt * ab[1])
    p = (pa[0] + tt * (pb[0] - pa[0]), pa[1] + tt * (pb[1] - pa[1]))
    return LeastVelocity(link, a, b, t, t * math.dist(pa, pb), p, g, math.hypot(*g), g, on)


def answer_value(solution, quantity: str) -> float:
    """rub(B) (m/s; the largest pair at B), least(BC) (m/s), least_at(BC) (m from B's end)."""
    fn, arg = _parse_quantity(quantity, solution.scene.file, "pin_answers")
    if fn == "rub":
        return max(r.velocity for r in rubbing_velocities(solution) if r.pin == arg)
    lv = least_velocity(solution, arg)
    if fn == "least":
        return lv.speed
    return lv.along if lv.along is not None else 0.0


def check_answers(solution) -> list[tuple[PinAnswer, float]]:
    """(answer, ours in its unit) for every [[pin_answers]] entry."""
    from .units import UNITS
    out = []
    for a in spec(solution.scene).answers:
        v = answer_value(solution, a.quantity)
        out.append((a, v if a.unit in ("-", "1") else v / UNITS[a.unit][1]))
    return out


def has_pins(scene: Scene) -> bool:
    return any(k in scene.extra for k in ("pins", "least_velocity"))


def report_lines(solution) -> list[str]:
    """The rubbing and least-velocity section of a report (empty without those tables)."""
    if not has_pins(solution.scene):
        return []
    lines = []
    rubs = rubbing_velocities(solution)
    if rubs:
        lines.append("rubbing velocities (v = |ω₁ − ω₂| · r):")
        for r in rubs:
            w1, w2 = r.omegas
            how = (f"(ω₁ + ω₂)·r = ({_g(abs(w1))} + {_g(abs(w2))}) × {_g(r.diameter / 2)}"
                   if r.opposite else
                   f"|ω₁ − ω₂|·r = {_g(r.relative)} × {_g(r.diameter / 2)}")
            lines.append(f"  pin {r.pin} (⌀ {_g(r.diameter * 1000)} mm) between "
                         f"{r.links[0]} and {r.links[1]}: {how} = {_g(r.velocity)} m/s")
    for link in spec(solution.scene).least:
        lv = least_velocity(solution, link)
        if lv.fraction is None:
            lines.append(f"least velocity on {link}: the link translates, every point at "
                         f"{_g(lv.speed)} m/s")
            continue
        where = (f"{lv.a}G = {_g(lv.along * 1000)} mm from {lv.a} "
                 f"({_g(lv.fraction)} of {lv.a}{lv.b})")
        if not lv.on_link:
            end = lv.a if lv.fraction < 0 else lv.b
            where += f", beyond the link: its slowest point is the end {end}"
        lines.append(f"least velocity on {link}: G with {where}; v_G = og = "
                     f"{_g(lv.speed)} m/s")
    checks = check_answers(solution)
    if checks:
        lines.append(f"  {'answer':<30} {'unit':<6} {'ours':>10} {'printed':>10} "
                     f"{'exact':>10}")
        for a, v in checks:
            lines.append(f"  {a.desc[:30]:<30} {a.unit:<6} {_g(v):>10} "
                         f"{_g(a.tutorial) if a.tutorial is not None else '-':>10} "
                         f"{_g(a.exact) if a.exact is not None else '-':>10}")
    return lines


def to_dict(solution) -> dict:
    """The same as JSON-ready data."""
    if not has_pins(solution.scene):
        return {}
    return {
        "rubbing": [{"pin": r.pin, "diameter": r.diameter, "links": list(r.links),
                     "omegas": list(r.omegas), "opposite": r.opposite,
                     "velocity": r.velocity} for r in rubbing_velocities(solution)],
        "least_velocity": {
            link: {"a": lv.a, "b": lv.b, "fraction": lv.fraction, "along": lv.along,
                   "point": list(lv.point), "velocity": list(lv.velocity),
                   "speed": lv.speed, "on_link": lv.on_link}
            for link in spec(solution.scene).least
            for lv in [least_velocity(solution, link)]},
    }


def _g(x: float) -> str:
    return f"{(x if x != 0 else 0.0):.5g}"      # no '-0'
