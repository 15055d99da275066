"""Evaluate the planned construction: put the numbers into every step.

Each step is executed with the theorem it names (:mod:`polygons.theorems`) and, for the
intersections, with shapely (:mod:`polygons.geometry`).  Every number in a
:class:`Solution` is read off the evaluated polygon vertices; nothing is computed twice.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Iterable, Mapping

import numpy as np

from . import geometry
from .errors import PolygonsError
from .interpret import Backend, Kernel, terms_of
from .narrate import substitute
from .plan import Plan, construction, make_plan
from .position import Placement, assemble
from .scene import Crank, Scene
from .steps import Step, Vertices
from .theorems import angular_acceleration, angular_velocity

Vec = tuple[float, float]


@dataclass(frozen=True)
class PointResult:
    position: Vec
    velocity: Vec | None
    acceleration: Vec | None


@dataclass(frozen=True)
class LinkResult:
    name: str
    a: str
    b: str
    length: float          # at this instant (a slotted lever: pivot to pin)
    omega: float | None    # CCW positive
    alpha: float | None


@dataclass(frozen=True)
class SlideResult:
    """A point sliding on a guide (fixed line) or in a slot (rotating lever)."""
    label: str
    along: str             # 'guide' or the lever name
    direction: Vec         # unit vector along which velocity/acceleration are signed
    velocity: float | None
    acceleration: float | None
    coriolis: Vec | None   # slots only


@dataclass(frozen=True)
class Solution:
    scene: Scene
    plan: Plan
    placement: Placement
    steps: tuple[Step, ...]
    pole: str
    vertices: Mapping[str, Mapping[str, Vec]]   # diagram -> vertex -> polygon coordinates
    points: Mapping[str, PointResult]
    links: Mapping[str, LinkResult]
    slides: Mapping[str, SlideResult]
    min_intersection_angle_deg: float | None
    warnings: tuple[str, ...]

    def vertex_of(self, label: str) -> str:
        return self.pole if label in self.scene.ground else label.lower()


def solve(scene: Scene, targets: Iterable[str] | None = None) -> Solution:
    """scene → plan → position → evaluated construction → :class:`Solution`.

    The plan and its steps depend on the scene's topology only, so they are made once per
    scene (and ``targets``) and kept with it."""
    plan, steps = planned(scene, tuple(targets) if targets is not None else None)
    placement = assemble(plan)
    return evaluate(plan, placement, steps)


def planned(scene: Scene, targets: tuple[str, ...] | None = None):
    """(plan, construction steps) of ``scene``, made on first use and kept with the scene."""
    cache = scene.__dict__.setdefault("_planned", {})   # a memo beside the frozen fields
    hit = cache.get(targets)
    if hit is None:
        plan = make_plan(scene, targets)
        hit = cache[targets] = (plan, construction(plan))
    return hit


def link_ends(scene: Scene, name: str) -> tuple[str, str]:
    if name in scene.links:
        return scene.links[name].a, scene.links[name].b
    for slot in scene.slots.values():
        if slot.lever == name:
            return slot.pivot, slot.coincident
    raise KeyError(name)


class Exact(Backend):
    """The staged solver's backend: construction lines as :class:`geometry.Line` and their
    intersections by shapely on paper-sized segments (:func:`geometry.intersect`)."""

    def line(self, anchor, direction, name):
        ln = geometry.line(anchor, direction, name)
        return np.array(ln.point), np.array(ln.direction), ln

    def intersect(self, l1, l2, s: Step):
        hit = geometry.intersect(l1[2], l2[2], step=f"{s.diagram} {s.number} ({s.draws})")
        return np.array(hit.point), math.sin(math.radians(hit.angle_deg)), hit.angle_deg


def start_kernel(plan: Plan, placement: Placement, backend: Backend) -> Kernel:
    """A kernel at the placed position, with the driver's ω and α known."""
    scene = plan.scene
    pos = {k: np.array(v) for k, v in placement.points.items()}
    omega, alpha = {}, {}
    drv = scene.driver
    if isinstance(drv, Crank):
        omega[drv.link] = drv.omega
        alpha[drv.link] = drv.alpha
    return Kernel(scene, pos, Vertices(scene), backend, omega, alpha)


def evaluate(plan: Plan, placement: Placement, steps: tuple[Step, ...]) -> Solution:
    """Run ``steps`` with the exact backend and put the numbers into every step."""
    k = start_kernel(plan, placement, Exact())
    scene = plan.scene
    done: list[Step] = []
    for step in steps:
        try:
            at, vec, point, direction, value, unit, angle, terms = k.run(step)
        except PolygonsError as exc:
            raise exc.located(file=scene.file,
                              step=f"{step.diagram} {step.number} ({step.draws})") from None
        done.append(_filled(step, scene, at=_t(at) if at is not None else None,
                            vector=_t(vec) if vec is not None else None,
                            point=_t(point) if point is not None else None,
                            direction=_t(direction) if direction is not None else None,
                            value=float(value) if value is not None else None, unit=unit,
                            angle_deg=angle, terms=terms_of(terms)))
    return _collect(plan, placement, k, tuple(done))


def _filled(step: Step, scene: Scene, **numbers) -> Step:
    """A copy of the planned ``step`` with its numbers and its substituted text: the frozen
    record is built once, field by field (``dataclasses.replace`` re-runs ``__init__`` and
    was a third of a solve)."""
    new = object.__new__(Step)
    new.__dict__.update(step.__dict__)
    new.__dict__.update(numbers)
    new.__dict__["substituted"] = substitute(new, scene)
    return new


def _n(v) -> float:
    return float(np.hypot(v[0], v[1]))


def _t(v) -> Vec:
    return (float(v[0]), float(v[1]))


def _unit_of(r: np.ndarray) -> np.ndarray:
    return r / float(np.hypot(*r))


def _collect(plan: Plan, placement: Placement, st: Kernel, steps: tuple[Step, ...]) -> Solution:
    scene = st.scene
    solved = scene.solve
    points = {}
    for label, p in placement.points.items():
        v = st.of("velocity", label) if "velocity" in solved else None
        a = st.of("acceleration", label) if "acceleration" in solved else None
        points[label] = PointResult(p, _t(v) if v is not None else None,
                                    _t(a) if a is not None else None)
    links = {}
    names = list(scene.links) + [s.lever for s in scene.slots.values()]
    for name in names:
        a, b = link_ends(scene, name)
        if a not in st.pos or b not in st.pos:
            continue
        omega = st.omega.get(name)
        alpha = st.alpha.get(name)
        r = st.r(a, b)
        if omega is None and "velocity" in solved:
            omega = angular_velocity(r, st.of("velocity", b) - st.of("velocity", a))
        if alpha is None and "acceleration" in solved:
            alpha = angular_acceleration(r, st.of("acceleration", b) - st.of("acceleration", a))
        links[name] = LinkResult(name, a, b, _n(r), omega, alpha)
    slides = {}
    for label, g in scene.sliders.items():
        if label in st.pos:
            e = np.array(g.direction)
            slides[label] = SlideResult(
                label, "guide", g.direction,
                float(st.of("velocity", label) @ e) if "velocity" in solved else None,
                float(st.of("acceleration", label) @ e) if "acceleration" in solved else None,
                None)
    for pin, slot in scene.slots.items():
        if slot.coincident in st.pos:
            e = st._slot_e(pin)[0]
            slides[pin] = SlideResult(pin, slot.lever, _t(e), st.slide_v.get(pin),
                                      st.slide_a.get(pin),
                                      _t(st.cor[pin]) if pin in st.cor else None)
    for pin, sl in scene.prescribed.items():     # second inputs: slides along a link
        if pin in st.pos:
            slides[pin] = SlideResult(pin, sl.link, _t(_unit_of(st.r(sl.p, sl.q))),
                                      st.slide_v.get(pin), st.slide_a.get(pin),
                                      _t(st.cor[pin]) if pin in st.cor else None)
    angles = [s.angle_deg for s in steps if s.angle_deg is not None]
    warnings = []
    for s in steps:
        if s.angle_deg is not None and s.angle_deg < geometry.WARN_DEG:
            warnings.append(f"{s.diagram} step {s.number}: the lines meeting at {s.end} cross at "
                            f"only {s.angle_deg:.3g}° — close to a toggle; the drawing and this "
                            f"number are unreliable")
    if "velocity" in solved and all(v == 0.0 for vec in st.vx["velocity"].values()
                                    for v in np.ravel(vec)):
        warnings.append("the mechanism is at rest at this instant: every velocity is zero, so "
                        "the velocity polygon collapses to the pole and the acceleration "
                        "polygon has tangential (and given) components only")
    vertices = {d: MappingProxyType({k: _t(v) for k, v in st.vx[d].items()}) for d in solved}
    return Solution(scene, plan, placement, steps, st.names.pole, MappingProxyType(vertices),
                    MappingProxyType(points), MappingProxyType(links),
                    MappingProxyType(slides), min(angles) if angles else None,
                    tuple(warnings))
