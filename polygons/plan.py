"""Plan: order the mechanism into a driver plus dyads, then into construction steps.

``scene → plan → evaluate → render``.  :func:`make_plan` finds, from the scene's topology
alone, the order in which a draughtsman places the points (the driver first, then any point
tied by two links to placed points (RRR), by a link and a fixed guide (RRP), a slotted lever
whose pin is placed (RPR), or rigidly attached to a placed link).  :func:`construction` turns
that order into the velocity and acceleration construction steps, as frozen :class:`Step`
records with no numbers in them; :mod:`polygons.evaluate` fills the numbers in, the diagrams
draw them.  Only the dyads needed for the requested points are planned (``targets``).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable

from .errors import UnknownLabelError, UnsupportedError, suggest
from .scene import BodyPoint, Crank, Scene, SliderDrive


# ---------------------------------------------------------------- dyads (placement order)
@dataclass(frozen=True)
class CrankDyad:
    """The input crank: ``tip`` turns about fixed ``pivot`` at the given ω, α."""
    link: str
    pivot: str
    tip: str

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.tip,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pivot,)


@dataclass(frozen=True)
class SliderDriveDyad:
    """The input slider: ``point`` moves along its fixed guide at a given speed."""
    point: str

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.point,)

    @property
    def needs(self) -> tuple[str, ...]:
        return ()


@dataclass(frozen=True)
class RRR:
    """Point ``x`` joined by link ``link_p`` to placed ``p`` and by ``link_q`` to placed ``q``."""
    p: str
    x: str
    q: str
    link_p: str
    link_q: str

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p, self.q)


@dataclass(frozen=True)
class RRP:
    """Point ``x`` joined by ``link`` to placed ``p`` and sliding on a fixed straight guide."""
    p: str
    x: str
    link: str

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p,)


@dataclass(frozen=True)
class RPR:
    """Placed pin ``pin`` slides in the slot of ``lever`` turning about fixed ``pivot``;
    places the lever's point ``coincident`` under the pin and its far end ``far``."""
    pin: str
    lever: str
    pivot: str
    coincident: str
    far: str | None

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.coincident,) + ((self.far,) if self.far else ())

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pin, self.pivot)


@dataclass(frozen=True)
class Image:
    """Point ``x`` rigid with link ``link`` whose ends ``p`` and ``q`` are placed."""
    x: str
    link: str
    p: str
    q: str

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p, self.q)


@dataclass(frozen=True)
class RPP:
    """Scotch yoke: placed pin ``pin`` slides in the straight slot of the yoke ``x``, which
    translates on its fixed guide; places ``x``, the yoke's point on the guide under the slot
    line through the pin."""
    pin: str
    x: str

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pin,)


Dyad = CrankDyad | SliderDriveDyad | RRR | RRP | RPR | Image | RPP


@dataclass(frozen=True)
class Plan:
    scene: Scene
    dyads: tuple[Dyad, ...]
    targets: tuple[str, ...]


def make_plan(scene: Scene, targets: Iterable[str] | None = None) -> Plan:
    """Order the scene into dyads; keep only those the ``targets`` (labels) depend on."""
    placed: set[str] = set(scene.ground)
    dyads: list[Dyad] = []
    drv = scene.driver
    if isinstance(drv, Crank):
        dyads.append(CrankDyad(drv.link, drv.pivot, drv.tip))
        placed.add(drv.tip)
    else:
        dyads.append(SliderDriveDyad(drv.point))
        placed.add(drv.point)

    labels = [lab for lab in scene.labels if lab not in placed]
    links = list(scene.links.values())
    while True:
        progress = False
        for slot in scene.slots.values():
            if slot.coincident not in placed and slot.pin in placed:
                d = RPR(slot.pin, slot.lever, slot.pivot, slot.coincident, slot.far)
                dyads.append(d)
                placed.update(d.placed)
                progress = True
        for x in labels:
            if x in placed:
                continue
            dyad = _dyad_for(scene, x, placed, links)
            if dyad is not None:
                dyads.append(dyad)
                placed.update(dyad.placed)
                progress = True
        if all(lab in placed for lab in labels) or not progress:
            break

    missing = [lab for lab in labels if lab not in placed]
    if missing:
        x = missing[0]
        joined = [l.name for l in links if x in (l.a, l.b)]
        raise UnsupportedError(
            f"cannot place point {x}: it is joined by {', '.join(joined) or 'no link'}; a point "
            f"is placed by two links to placed points, a link plus a slider guide "
            f"([sliders.{x}]), a slot, or [points.{x}] on a placed link", file=scene.file,
            where=x)

    if targets is None:
        return Plan(scene, tuple(dyads), tuple(scene.labels))
    targets = tuple(targets)
    for t in targets:
        if t not in scene.labels:
            raise UnknownLabelError(f"unknown point {t!r}: {suggest(t, scene.labels)}",
                                    file=scene.file)
    return Plan(scene, _prune(dyads, targets, scene), targets)


def _dyad_for(scene: Scene, x: str, placed: set[str], links) -> Dyad | None:
    guide = scene.sliders.get(x)
    if guide is not None and guide.pin is not None:   # a Scotch yoke
        return RPP(guide.pin, x) if guide.pin in placed else None
    if x in scene.points:
        bp: BodyPoint = scene.points[x]
        link = scene.links.get(bp.link)
        if link is not None:
            p, q = link.a, link.b
        else:  # a point on a slotted lever
            slot = next(s for s in scene.slots.values() if s.lever == bp.link)
            p, q = slot.pivot, slot.coincident
        if p in placed and q in placed:
            return Image(x, bp.link, p, q)
        return None
    joints = [(l.b if l.a == x else l.a, l.name) for l in links
              if x in (l.a, l.b) and l.length is not None]
    known = [(other, name) for other, name in joints if other in placed]
    if x in scene.sliders and known:
        return RRP(known[0][0], x, known[0][1])
    if len(known) >= 2:
        (p, lp), (q, lq) = known[0], known[1]
        return RRR(p, x, q, lp, lq)
    # a point of a link whose two other ends are placed is handled as a rigid image only when
    # declared in [points]; links are binary, so nothing else to do here
    return None


def _prune(dyads: list[Dyad], targets: tuple[str, ...], scene: Scene) -> tuple[Dyad, ...]:
    producer = {}
    for d in dyads:
        for lab in d.placed:
            producer[lab] = d
    needed: list[Dyad] = []
    stack = [t for t in targets if t in producer]
    seen: set[str] = set()
    while stack:
        lab = stack.pop()
        if lab in seen:
            continue
        seen.add(lab)
        d = producer[lab]
        if d not in needed:
            needed.append(d)
        deps = list(d.needs)
        if isinstance(d, (RRR, RRP)) and scene.assembly.get(d.x) is not None:
            deps += list(scene.assembly[d.x].ref)
        stack.extend(dep for dep in deps if dep in producer)
    return tuple(d for d in dyads if d in needed)


# ---------------------------------------------------------------- construction steps
@dataclass(frozen=True)
class Step:
    """One stroke of the construction, as a tutorial figure adds it.

    Planned with ``op``/``args`` and words only; :func:`polygons.evaluate.evaluate` returns a
    copy with the numbers (``vector``, ``point``, ``direction``, ``value``, ``angle_deg``,
    ``substituted``) filled in.  The diagrams draw these records and never recompute them.
    """

    diagram: str            # 'velocity' | 'acceleration'
    number: int             # 1, 2, ... within its diagram (Fig. a, b, c ...)
    kind: str               # 'vector' | 'line' | 'intersection' | 'measure' | 'image'
    op: str                 # evaluator operation
    args: tuple[str, ...]   # space labels / link names the operation uses
    draws: str              # what appears on paper: 'oa', 'c line', 'b', 'ω_BC'
    start: str | None       # polygon vertex the vector starts at / the line passes through
    end: str | None         # polygon vertex this step creates
    theorem: str            # 'relative_velocity', 'centripetal', 'coriolis', ...
    quantity: str           # '(v_A)_O', '(a_C)_B^t', 'ω_BC'
    formula: str            # symbolic formula
    reason: str             # the sentence a tutorial would write
    lines: tuple[int, ...] = ()          # for an intersection: the step numbers of its lines
    # -- filled by evaluate ---------------------------------------------------------------
    at: tuple[float, float] | None = None         # start vertex / line anchor, polygon coords
    vector: tuple[float, float] | None = None     # for vectors and images: end - start
    point: tuple[float, float] | None = None      # vertex created
    direction: tuple[float, float] | None = None  # for lines: unit direction
    value: float | None = None                    # for measures (SI, signed)
    unit: str = ""
    angle_deg: float | None = None                # for intersections: angle between the lines
    substituted: str = ""                         # formula with the numbers put in


@dataclass
class _Builder:
    scene: Scene
    diagram: str
    steps: list[Step] = field(default_factory=list)

    def add(self, kind, op, args, draws, start, end, theorem, quantity, formula, reason,
            lines=()) -> int:
        n = len(self.steps) + 1
        self.steps.append(Step(self.diagram, n, kind, op, tuple(args), draws, start, end,
                               theorem, quantity, formula, reason, tuple(lines)))
        return n


class Vertices:
    """Polygon vertex names: lower-case space labels; every fixed point is the pole."""

    def __init__(self, scene: Scene):
        self.scene = scene
        drv = scene.driver
        first = drv.pivot if isinstance(drv, Crank) else next(iter(scene.ground))
        self.pole = first.lower()
        self.taken = {lab.lower() for lab in scene.labels} | {self.pole}

    def of(self, label: str) -> str:
        return self.pole if label in self.scene.ground else label.lower()

    def fresh(self, label: str, diagram_taken: set[str]) -> str:
        base = label.lower()
        sep = "_" if base[-1].isdigit() else ""
        k = 1
        while True:
            name = f"{base}{sep}{k}"
            if name not in self.taken and name not in diagram_taken:
                diagram_taken.add(name)
                return name
            k += 1


def construction(plan: Plan) -> tuple[Step, ...]:
    """The velocity steps then the acceleration steps for ``plan``'s dyads, in order."""
    scene = plan.scene
    names = Vertices(scene)
    steps: list[Step] = []
    for diagram in scene.solve:
        b = _Builder(scene, diagram)
        taken: set[str] = set()
        for dyad in plan.dyads:
            _emit(b, dyad, names, taken)
        steps.extend(b.steps)
    return tuple(steps)


def _vq(diagram: str) -> str:
    return "v" if diagram == "velocity" else "a"


def _emit(b: _Builder, dyad: Dyad, names: Vertices, taken: set[str]) -> None:
    scene = b.scene
    V = names.of
    vel = b.diagram == "velocity"
    pole = names.pole
    ground_alias = " = ".join([pole] + [g.lower() for g in scene.ground if g.lower() != pole])

    if isinstance(dyad, CrankDyad):
        P, X, L = dyad.pivot, dyad.tip, dyad.link
        p, x = V(P), V(X)
        if vel:
            b.add("vector", "crank_velocity", (L, P, X), f"{p}{x}", p, x, "relative_velocity",
                  f"(v_{X})_{P}", f"(v_{X})_{P} = ω_{L} × {P}{X}",
                  f"Draw {p}{x} = ω × {P}{X} perpendicular to {P}{X}, in the sense of rotation "
                  f"of the crank, starting at the pole {ground_alias} (fixed points have no "
                  f"velocity).")
        else:
            drv = scene.driver
            has_t = isinstance(drv, Crank) and drv.alpha != 0.0
            x1 = names.fresh(X, taken) if has_t else x
            b.add("vector", "centripetal", (L, P, X), f"{p}{x1}", p, x1, "centripetal",
                  f"(a_{X})_{P}^n", f"(a_{X})_{P}^n = ω_{L}² × {P}{X}",
                  f"Draw the centripetal acceleration of {X} about {P}, ω² × {P}{X}, from {p} "
                  f"parallel to {X}{P}, pointing from {X} towards {P}."
                  + ("" if has_t else f" The crank has no angular acceleration, so this "
                                      f"ends at {x}."))
            if has_t:
                b.add("vector", "crank_tangential", (L, P, X), f"{x1}{x}", x1, x, "tangential",
                      f"(a_{X})_{P}^t", f"(a_{X})_{P}^t = α_{L} × {P}{X}",
                      f"Add the tangential acceleration α × {P}{X} from {x1}, perpendicular to "
                      f"{P}{X} in the sense of α; it ends at {x}.")
        return

    if isinstance(dyad, SliderDriveDyad):
        X = dyad.point
        x = V(X)
        q = _vq(b.diagram)
        b.add("vector", "slider_drive", (X,), f"{pole}{x}", pole, x, "input",
              f"{q}_{X}", f"{q}_{X} (given, along the guide)",
              f"Draw the given {'velocity' if vel else 'acceleration'} of the slider {X} from "
              f"the pole along its guide.")
        return

    if isinstance(dyad, (RRR, RRP)):
        P, X = dyad.p, dyad.x
        LP = dyad.link_p if isinstance(dyad, RRR) else dyad.link
        p, x = V(P), V(X)
        if vel:
            n1 = b.add("line", "line_perp", (P, X), f"line ⟂ {P}{X}", p, None,
                       "relative_velocity", f"(v_{X})_{P}", f"(v_{X})_{P} ⟂ {P}{X}",
                       f"Through {p} draw a line perpendicular to {P}{X}: the velocity of {X} "
                       f"relative to {P}, of unknown length.")
            if isinstance(dyad, RRR):
                Q, LQ = dyad.q, dyad.link_q
                q_ = V(Q)
                n2 = b.add("line", "line_perp", (Q, X), f"line ⟂ {Q}{X}", q_, None,
                           "relative_velocity", f"(v_{X})_{Q}", f"(v_{X})_{Q} ⟂ {Q}{X}",
                           f"Through {q_} draw a line perpendicular to {Q}{X}: the velocity of "
                           f"{X} relative to {Q}, of unknown length.")
            else:
                n2 = b.add("line", "line_guide", (X,), "slider line", pole, None,
                           "slider_line", f"v_{X}", f"v_{X} ∥ guide of {X}",
                           f"Through {pole} draw a line along the guide of {X}: the slider "
                           f"can only move along it.")
            b.add("intersection", "intersect", (), x, None, x, "intersection", f"v_{X}",
                  f"{x} = intersection of the two lines",
                  f"The two lines meet at {x}: {pole}{x} is the velocity of {X}.", (n1, n2))
            b.add("measure", "omega", (LP, P, X), f"ω_{LP}", None, None, "angular_velocity",
                  f"ω_{LP}", f"ω_{LP} = {p}{x} / {P}{X}",
                  f"The angular velocity of {LP} is the relative velocity divided by its length.")
            if isinstance(dyad, RRR):
                b.add("measure", "omega", (dyad.link_q, dyad.q, X), f"ω_{dyad.link_q}", None, None,
                      "angular_velocity", f"ω_{dyad.link_q}",
                      f"ω_{dyad.link_q} = {V(dyad.q)}{x} / {dyad.q}{X}",
                      f"The angular velocity of {dyad.link_q} is its relative velocity divided "
                      f"by its length.")
            else:
                b.add("measure", "slider_velocity", (X,), f"v_{X}", None, None, "slider",
                      f"v_{X} along guide", f"v_{X} = {pole}{x}",
                      f"The slider velocity is {pole}{x}, signed along the guide direction.")
            return
        # acceleration
        x1 = names.fresh(X, taken)
        b.add("vector", "centripetal", (LP, P, X), f"{p}{x1}", p, x1, "centripetal",
              f"(a_{X})_{P}^n", f"(a_{X})_{P}^n = ω_{LP}² × {P}{X} = v²/{P}{X}",
              f"From {p} draw the centripetal acceleration of {X} relative to {P}, parallel to "
              f"{P}{X} and pointing from {X} towards {P}; call its end {x1}.")
        n1 = b.add("line", "line_perp", (P, X), f"{x.upper() if False else x} line", x1, None,
                   "tangential", f"(a_{X})_{P}^t", f"(a_{X})_{P}^t = α_{LP} × {P}{X} ⟂ {P}{X}",
                   f"Through {x1} draw a line perpendicular to {P}{X} for the tangential "
                   f"acceleration of unknown length: the {x} line.")
        if isinstance(dyad, RRR):
            Q, LQ = dyad.q, dyad.link_q
            q_ = V(Q)
            x2 = names.fresh(X, taken)
            b.add("vector", "centripetal", (LQ, Q, X), f"{q_}{x2}", q_, x2, "centripetal",
                  f"(a_{X})_{Q}^n", f"(a_{X})_{Q}^n = ω_{LQ}² × {Q}{X} = v²/{Q}{X}",
                  f"From {q_} draw the centripetal acceleration of {X} relative to {Q}, "
                  f"pointing from {X} towards {Q}; call its end {x2}.")
            n2 = b.add("line", "line_perp", (Q, X), f"line ⟂ {Q}{X}", x2, None, "tangential",
                       f"(a_{X})_{Q}^t", f"(a_{X})_{Q}^t = α_{LQ} × {Q}{X} ⟂ {Q}{X}",
                       f"Through {x2} draw a line perpendicular to {Q}{X} for the tangential "
                       f"acceleration of {X} relative to {Q}, of unknown length.")
        else:
            n2 = b.add("line", "line_guide", (X,), "slider line", pole, None, "slider_line",
                       f"a_{X}", f"a_{X} ∥ guide of {X}",
                       f"Through {pole} draw a line along the guide of {X}: the slider's "
                       f"acceleration lies along it.")
        b.add("intersection", "intersect", (), x, None, x, "intersection", f"a_{X}",
              f"{x} = intersection of the two lines",
              f"The lines meet at {x}: {pole}{x} is the acceleration of {X}.", (n1, n2))
        b.add("measure", "alpha", (LP, P, X), f"α_{LP}", None, None, "angular_acceleration",
              f"α_{LP}", f"α_{LP} = {x1}{x} / {P}{X}",
              f"The angular acceleration of {LP} is its tangential acceleration {x1}{x} "
              f"divided by {P}{X}.")
        if isinstance(dyad, RRR):
            b.add("measure", "alpha", (dyad.link_q, dyad.q, X), f"α_{dyad.link_q}", None,
                  None, "angular_acceleration", f"α_{dyad.link_q}",
                  f"α_{dyad.link_q} = {x2}{x} / {dyad.q}{X}",
                  f"The angular acceleration of {dyad.link_q} is {x2}{x} divided by "
                  f"{dyad.q}{X}.")
        else:
            b.add("measure", "slider_acceleration", (X,), f"a_{X}", None, None, "slider",
                  f"a_{X} along guide", f"a_{X} = {pole}{x}",
                  f"The slider acceleration is {pole}{x}, signed along the guide direction.")
        return

    if isinstance(dyad, RPR):
        A, B, A1, lev = dyad.pin, dyad.pivot, dyad.coincident, dyad.lever
        a, b_, a1 = V(A), V(B), V(A1)
        if vel:
            n1 = b.add("line", "line_perp", (B, A1), f"line ⟂ {B}{A1}", b_, None,
                       "relative_velocity", f"v_{A1}", f"v_{A1} = ω_{lev} × {B}{A1} ⟂ {B}{A}",
                       f"Through {b_} draw a line perpendicular to the lever {B}{A}: the "
                       f"velocity of {A1}, the point of the lever under the pin.")
            n2 = b.add("line", "line_along", (B, A1), f"slot line ∥ {B}{A}", a, None,
                       "sliding", f"(v_{A})_{A1}", f"(v_{A})_{A1} ∥ {B}{A}",
                       f"Through {a} draw a line parallel to the slot {B}{A}: the velocity of "
                       f"{A} sliding relative to {A1}.")
            b.add("intersection", "intersect", (), a1, None, a1, "intersection", f"v_{A1}",
                  f"{a1} = intersection of the two lines",
                  f"They meet at {a1}: {b_}{a1} is the velocity of {A1} and {a1}{a} the "
                  f"sliding velocity.", (n1, n2))
            b.add("measure", "omega", (lev, B, A1), f"ω_{lev}", None, None, "angular_velocity",
                  f"ω_{lev}", f"ω_{lev} = {b_}{a1} / {B}{A}",
                  f"The lever turns at the velocity of {A1} divided by {B}{A}.")
            b.add("measure", "slide_velocity", (A,), f"v_slide", None, None, "sliding",
                  f"(v_{A})_{A1}", f"(v_{A})_{A1} = {a1}{a}",
                  f"The sliding velocity of {A} along the slot is {a1}{a} (positive away "
                  f"from {B}).")
        else:
            k1 = names.fresh(A1, taken)
            b.add("vector", "centripetal", (lev, B, A1), f"{b_}{k1}", b_, k1, "centripetal",
                  f"(a_{A1})^n", f"(a_{A1})^n = ω_{lev}² × {B}{A}",
                  f"From {b_} draw the centripetal acceleration of {A1} about {B}, ω² × {B}{A}, "
                  f"pointing towards {B}; call its end {k1}.")
            n1 = b.add("line", "line_perp", (B, A1), f"{a1} line", k1, None, "tangential",
                       f"(a_{A1})^t", f"(a_{A1})^t = α_{lev} × {B}{A} ⟂ {B}{A}",
                       f"Through {k1} draw a line perpendicular to {B}{A} for the tangential "
                       f"acceleration of {A1}, of unknown length.")
            n2 = b.add("line", "coriolis_offset_line", (A,), "Coriolis offset line", a, None,
                       "coriolis", "2ω×v", f"2 ω_{lev} v = 2 × ω_{lev} × (v_{A})_{A1}",
                       f"The Coriolis acceleration 2ωv is known (ω × v turns v through 90° "
                       f"in the sense of ω). Step back from {a} by it and through that point "
                       f"draw a line parallel to the slot: the sliding acceleration lies on "
                       f"it.")
            b.add("intersection", "intersect", (), a1, None, a1, "intersection", f"a_{A1}",
                  f"{a1} = intersection of the two lines",
                  f"The lines meet at {a1}: {b_}{a1} is the acceleration of {A1}.", (n1, n2))
            k2 = names.fresh(A, taken)
            b.add("vector", "coriolis", (A,), f"{a1}{k2}", a1, k2, "coriolis",
                  f"a_cor", f"a_cor = 2 ω_{lev} × (v_{A})_{A1}",
                  f"From {a1} the Coriolis acceleration 2ωv, perpendicular to the slot, to "
                  f"{k2}.")
            b.add("vector", "join", (A,), f"{k2}{a}", k2, a, "sliding", f"(a_{A})_{A1}^slide",
                  f"(a_{A})_{A1} = {k2}{a} ∥ {B}{A}",
                  f"{k2}{a}, along the slot, is the sliding acceleration of {A} relative to the "
                  f"lever.")
            b.add("measure", "alpha", (lev, B, A1), f"α_{lev}", None, None,
                  "angular_acceleration", f"α_{lev}", f"α_{lev} = {k1}{a1} / {B}{A}",
                  f"The lever's angular acceleration is its tangential acceleration {k1}{a1} "
                  f"divided by {B}{A}.")
            b.add("measure", "slide_acceleration", (A,), "a_slide", None, None, "sliding",
                  f"(a_{A})_{A1}", f"(a_{A})_{A1} = {k2}{a}",
                  f"The sliding acceleration of {A} is {k2}{a} (positive away from {B}).")
        if dyad.far:
            _emit_image(b, names, dyad.far, lev, B, A1)
        return

    if isinstance(dyad, Image):
        _emit_image(b, names, dyad.x, dyad.link, dyad.p, dyad.q)
        return

    if isinstance(dyad, RPP):
        A, Y = dyad.pin, dyad.x
        a, y = V(A), V(Y)
        q = _vq(b.diagram)
        what = "velocity" if vel else "acceleration"
        n1 = b.add("line", "line_guide", (Y,), "slider line", pole, None, "slider_line",
                   f"{q}_{Y}", f"{q}_{Y} ∥ guide of {Y}",
                   f"Through {pole} draw a line along the guide of the yoke {Y}: the yoke only "
                   f"translates along it.")
        n2 = b.add("line", "line_slot", (Y,), "slot line", a, None, "sliding",
                   f"({q}_{A})_{Y}", f"({q}_{A})_{Y} ∥ slot of {Y}",
                   f"Through {a} draw a line parallel to the yoke's slot: {A} slides along it "
                   f"relative to the yoke, which does not turn (so there is no Coriolis "
                   f"term).")
        b.add("intersection", "intersect", (), y, None, y, "intersection", f"{q}_{Y}",
              f"{y} = intersection of the two lines",
              f"They meet at {y}: {pole}{y} is the {what} of the yoke and {y}{a} that of {A} "
              f"sliding in the slot.", (n1, n2))
        if vel:
            b.add("measure", "slider_velocity", (Y,), f"v_{Y}", None, None, "slider",
                  f"v_{Y} along guide", f"v_{Y} = {pole}{y}",
                  f"The yoke's velocity is {pole}{y}, signed along its guide.")
        else:
            b.add("measure", "slider_acceleration", (Y,), f"a_{Y}", None, None, "slider",
                  f"a_{Y} along guide", f"a_{Y} = {pole}{y}",
                  f"The yoke's acceleration is {pole}{y}, signed along its guide.")
        return
    raise AssertionError(dyad)


def _emit_image(b: _Builder, names: Vertices, X: str, link: str, P: str, Q: str) -> None:
    V = names.of
    p, q, x = V(P), V(Q), V(X)
    what = "velocity" if b.diagram == "velocity" else "acceleration"
    formula = (f"{x} = {p} + ω_{link} × {P}{X}" if b.diagram == "velocity"
               else f"{x} = {p} + α_{link} × {P}{X} − ω_{link}² {P}{X}")
    b.add("image", "image", (link, P, Q, X), f"{p}{x}", p, x, "image", f"{_vq(b.diagram)}_{X}",
          formula,
          f"{X} is a point of the rigid link {link}: {p}{q}{x} is the {what} image of "
          f"{P}{Q}{X} (similar to it, turned), so {x} follows from {p} and {q}.")
