"""Plan: order the mechanism into a driver plus dyads, then into construction steps.

``scene → plan → interpreters → render``.  :func:`make_plan` finds, from the scene's topology
alone, the order in which a draughtsman places the points: the driver first, then, pass by
pass, every dyad whose points can be placed from those already placed.  Which dyads exist and
when each can be placed is the business of :mod:`polygons.dyads` (one module per kind); this
module only orders them.  :func:`construction` asks each dyad, in order, for its velocity and
acceleration steps (typed :class:`~polygons.steps.Step` records with no numbers in them); an
interpreter fills the numbers in.  Only the dyads needed for the requested points are planned
(``targets``).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterable

from . import dyads as kinds
from .errors import UnknownLabelError, UnsupportedError, suggest
from .mobility import MobilityError, check_mobility, used_links
from .scene import Scene
from .topology import why_unplaced
from .steps import Builder, Diagram, Step, Vertices, pole_of  # noqa: F401  (re-exported)

if TYPE_CHECKING:           # (the union imports every kind: the planner imports those it asks)
    from .dyads import Dyad


@dataclass(frozen=True)
class Plan:
    scene: Scene
    dyads: tuple[Dyad, ...]
    targets: tuple[str, ...]


def make_plan(scene: Scene, targets: Iterable[str] | None = None) -> Plan:
    """Order the scene into dyads; keep only those the ``targets`` (labels) depend on.

    The scene's mobility is checked first (:func:`polygons.mobility.check_mobility`): a
    locked, over-constrained or under-driven scene is refused before any dyad is ordered."""
    dyads = _order(scene)
    links = {b.name for b in scene.model.links()}
    check_mobility(scene, redundant=tuple(sorted(links - used_links(dyads))))
    if targets is None:
        return Plan(scene, tuple(dyads), tuple(scene.labels))
    targets = tuple(targets)
    for t in targets:
        if t not in scene.labels:
            raise UnknownLabelError(f"unknown point {t!r}: {suggest(t, scene.labels)}",
                                    file=scene.file)
    return Plan(scene, _prune(dyads, targets, scene), targets)


def _order(scene: Scene) -> list[Dyad]:
    """The driver, then pass by pass every dyad that can be placed."""
    placed: set[str] = set(scene.ground)
    dyads: list[Dyad] = []
    for module in kinds.kinds("driver"):     # each imported when first asked
        d = module.driver(scene)
        if d is not None:
            dyads.append(d)
            placed.update(d.placed)
            break

    labels = [lab for lab in scene.labels if lab not in placed]
    links = scene.model.links()               # (a, b and whether it has a length: the model's)
    at: dict[str, list] = {}                  # each point's links, in the scene's order
    for ln in links:
        for end in dict.fromkeys((ln.a, ln.b)):
            at.setdefault(end, []).append(ln)
    while True:
        progress = False
        for module in kinds.kinds("slot"):
            for d in module.matches(scene, placed):
                dyads.append(d)
                placed.update(d.placed)
                progress = True
        for x in labels:
            if x in placed:
                continue
            d = _point_dyad(scene, x, placed, at.get(x, ()))
            if d is not None:
                dyads.append(d)
                placed.update(d.placed)
                progress = True
        if not progress:        # no dyad fits: a group of a higher class (a triad) may
            for module in kinds.kinds("group"):
                for d in module.matches(scene, placed):
                    dyads.append(d)
                    placed.update(d.placed)
                    progress = True
        if all(lab in placed for lab in labels) or not progress:
            break

    missing = [lab for lab in labels if lab not in placed]
    if missing:
        x = missing[0]
        joined = [l.name for l in links if x in (l.a, l.b)]
        why = why_unplaced(scene, x, placed)
        try:                       # an under-driven scene is said so first, with the reason
            check_mobility(scene)
        except MobilityError as exc:
            if why:
                raise MobilityError(f"{exc.reason}; cannot place point {x}: {why}",
                                    dof=exc.dof, links=exc.links, file=scene.file,
                                    where=exc.where) from None
            raise
        if why:
            raise UnsupportedError(f"cannot place point {x}: {why}", file=scene.file, where=x)
        raise UnsupportedError(
            f"cannot place point {x}: it is joined by {', '.join(joined) or 'no link'}; a point "
            f"is placed by two links to placed points, a link plus a slider guide "
            f"([sliders.{x}]), a slot, or [points.{x}] on a placed link", file=scene.file,
            where=x)
    return dyads


def _point_dyad(scene: Scene, x: str, placed: set[str], links) -> Dyad | None:
    """The dyad placing ``x`` now, asked of the first kind that claims ``x`` (``links``: those
    at ``x``, or more)."""
    joints = [(l.b if l.a == x else l.a, l.name) for l in links
              if x in (l.a, l.b) and l.length is not None]
    known = [(other, name) for other, name in joints if other in placed]
    for module in kinds.kinds("point"):
        if module.claims(scene, x):
            return module.match(scene, x, placed, known)
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
        if d.two_closures and scene.assembly.get(d.placed[0]) is not None:
            deps += list(scene.assembly[d.placed[0]].ref)
        stack.extend(dep for dep in deps if dep in producer)
    return tuple(d for d in dyads if d in needed)


def construction(plan: Plan, diagrams: Iterable[str] | None = None) -> tuple[Step, ...]:
    """The velocity steps then the acceleration steps for ``plan``'s dyads, in order (the
    scene's ``solve`` diagrams unless ``diagrams`` is given).

    A dyad's steps depend on its record (labels, and the flags its module puts there) and on
    the vertex names (the scene's labels and fixed points), never on a number: they are made
    once per such topology and shared."""
    scene = plan.scene
    diagrams = tuple(scene.solve if diagrams is None else diagrams)
    key = (plan.dyads, diagrams, tuple(scene.ground), tuple(scene.labels), pole_of(scene))
    hit = _STEPS.get(key)
    if hit is None:
        if len(_STEPS) >= 256:          # a bound, not a policy: topologies are few
            _STEPS.clear()
        hit = _STEPS[key] = _construct(plan, diagrams)
    return hit


_STEPS: dict = {}


def _construct(plan: Plan, diagrams: tuple[str, ...]) -> tuple[Step, ...]:
    scene = plan.scene
    names = Vertices(scene)
    steps: list[Step] = []
    for diagram in diagrams:
        b = Builder(scene, Diagram(diagram), names)
        for dyad in plan.dyads:
            dyad.emit(b)
        steps.extend(b.steps)
    return tuple(steps)
