"""Evaluate the planned construction: put the numbers into every step.

The staged solver: the mechanism is assembled dyad by dyad (:mod:`polygons.position`), then
the construction's steps run as the program :mod:`polygons.codegen` writes from them (each
op's theorem, :mod:`polygons.theorems`, over the placed points), with every intersection of
two construction lines drawn and found as shapely finds it (:func:`polygons.geometry.meet`:
GEOS's arithmetic written out in floats, the same doubles).  Every number in a
:class:`Solution` is read off that record; nothing is computed twice.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from types import MappingProxyType
from typing import Iterable, Mapping

from . import geometry
from .compiled import compile_staged, min_angle, steps_from_record
from .plan import Plan, construction, make_plan
from .position import Placement, assemble
from .scene import Scene
from .steps import Step, pole_of
from .memo import memo_of

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


class Solution:
    """One solved instant: the staged construction's numbers (``record``, a flat tuple of
    floats laid out by its program) with every report read off them on first access: the
    evaluated :class:`Step` records with their substituted text, the polygon vertices, each
    point's velocity and acceleration, each link's ω and α, each slide."""

    def __init__(self, scene: Scene, plan: Plan, placement: Placement, staged, record: tuple):
        d = self.__dict__
        d.update(scene=scene, plan=plan, placement=placement, _staged=staged, record=record,
                 pole=pole_of(scene))

    def __setattr__(self, name, value):
        raise AttributeError(f"a Solution is frozen: cannot set {name!r}")

    def vertex_of(self, label: str) -> str:
        return self.pole if label in self.scene.ground else label.lower()

    def printed_names(self, diagram: str) -> set[str]:
        """The names a diagram's words give its vertices: its vertex names and the pole's
        other names, every fixed point's letter (dc₂ about D where the pole is a = d, o₄p₄′
        about O4 where it is o₂ = o₄)."""
        return set(self.vertices.get(diagram, ())) | {g.lower() for g in self.scene.ground}

    def _at(self, key):
        i = self._staged.code.index.get(key)
        return None if i is None else (self.record[i[0]], self.record[i[1]])

    def _one(self, key):
        i = self._staged.code.index.get(key)
        return None if i is None else self.record[i]

    @cached_property
    def steps(self) -> tuple[Step, ...]:
        return steps_from_record(self.scene, self._staged.steps, self._staged.code.layout,
                                 self.record)

    @cached_property
    def min_intersection_angle_deg(self) -> float | None:
        return min_angle(self._staged.code.layout, self.record)

    @cached_property
    def vertices(self) -> Mapping[str, Mapping[str, Vec]]:
        """diagram → vertex → polygon coordinates."""
        out = {}
        for key, ij in self._staged.code.index.items():
            if key[0] == "vx":
                out.setdefault(key[1], {})[key[2]] = (self.record[ij[0]], self.record[ij[1]])
        return MappingProxyType({d: MappingProxyType(out[d]) for d in self.scene.solve})

    def _vel(self, diagram: str, label: str):
        if diagram not in self.scene.solve:
            return None
        return self.vertices[diagram][self.vertex_of(label)]

    @cached_property
    def points(self) -> Mapping[str, PointResult]:
        return MappingProxyType({label: PointResult(p, self._vel("velocity", label),
                                                    self._vel("acceleration", label))
                                 for label, p in self.placement.points.items()})

    @cached_property
    def links(self) -> Mapping[str, LinkResult]:
        scene, pos, solved = self.scene, self.placement.points, self.scene.solve
        links = {}
        for body in scene.model.bodies:
            if body.kind not in ("link", "lever"):
                continue
            name, a, b = body.name, body.a, body.b
            if a not in pos or b not in pos:
                continue
            r = (pos[b][0] - pos[a][0], pos[b][1] - pos[a][1])
            omega, alpha = self._one(("omega", name)), self._one(("alpha", name))
            if omega is None and "velocity" in solved:
                omega = _rate(r, self._vel("velocity", a), self._vel("velocity", b))
            if alpha is None and "acceleration" in solved:
                alpha = _rate(r, self._vel("acceleration", a), self._vel("acceleration", b))
            links[name] = LinkResult(name, a, b, math.hypot(*r), omega, alpha)
        return MappingProxyType(links)

    @cached_property
    def slides(self) -> Mapping[str, SlideResult]:
        model, solved = self.scene.model, self.scene.solve
        slides = {}
        for guide in model.sliding:
            label = guide.at
            if guide.carrier == "frame" and label in self.placement.points:
                e = guide.line.at(self.placement.points)[1]
                v, a = self._vel("velocity", label), self._vel("acceleration", label)
                slides[label] = SlideResult(
                    label, "guide", e,
                    v[0] * e[0] + v[1] * e[1] if "velocity" in solved else None,
                    a[0] * e[0] + a[1] * e[1] if "acceleration" in solved else None, None)
        along = {s.at: s.carrier for s in model.slots() + model.collars()}
        for s in model.crossings():       # a pin in two slots: one slide per slot
            key = f"{s.at} in {s.carrier}"
            e = self._at(("slot_e", key))
            if e is not None:
                slides[key] = SlideResult(s.at, s.carrier, e, self._one(("slide_v", key)),
                                          self._one(("slide_a", key)),
                                          self._at(("coriolis", key)))
        for pin, link in along.items():
            e = self._at(("slot_e", pin))
            if e is not None:
                slides[pin] = SlideResult(pin, link, e, self._one(("slide_v", pin)),
                                          self._one(("slide_a", pin)),
                                          self._at(("coriolis", pin)))
        return MappingProxyType(slides)

    @cached_property
    def warnings(self) -> tuple[str, ...]:
        warnings = []
        for o, s in zip(self._staged.code.layout, self._staged.steps):
            angle = None if o.angle is None else self.record[o.angle]
            if angle is not None and angle < geometry.WARN_DEG:
                warnings.append(f"{s.diagram} step {s.number}: the lines meeting at {s.end} "
                                f"cross at only {angle:.3g}° — close to a toggle; the drawing "
                                f"and this number are unreliable")
        meet = getattr(self.scene.driver, "rod_angle_deg", None)
        if meet is not None and meet < geometry.WARN_DEG:
            warnings.append(f"the slider's speed from the rod's ω: the two directions that give "
                            f"it meet at only {meet:.3g}° — the rod barely turns whatever the "
                            f"slider's speed; this input is unreliable")
        if "velocity" in self.scene.solve and all(
                c == 0.0 for v in self.vertices["velocity"].values() for c in v):
            warnings.append("the mechanism is at rest at this instant: every velocity is zero, "
                            "so the velocity polygon collapses to the pole and the acceleration "
                            "polygon has tangential (and given) components only")
        return tuple(warnings)


def _rate(r, va, vb) -> float:
    """ω (or α) = (r × (v_B − v_A)) / r²: a link's rate from its ends' polygon vertices."""
    rel = (vb[0] - va[0], vb[1] - va[1])
    return (r[0] * rel[1] - r[1] * rel[0]) / (r[0] * r[0] + r[1] * r[1])


def solve(scene: Scene, targets: Iterable[str] | None = None) -> Solution:
    """scene → plan → position → the staged construction → :class:`Solution`.

    The plan, its steps and their compiled program depend on the scene's topology only, so
    they are made once per scene (and ``targets``) and kept with it; each solve assembles the
    mechanism (the dyad modules' statements) and runs the program, whose intersections are
    drawn and found as shapely finds them (:func:`polygons.geometry.meet`)."""
    targets = tuple(targets) if targets is not None else None
    plan, steps, staged = planned(scene, targets)
    placement = assemble(plan)
    if staged.groups:
        plan, notes = assur_pairs(plan, placement.points)
        if notes:   # a triad's S at infinity: its construction through another pair of links
            plan, steps, staged = planned(scene, targets, plan)
            placement = Placement(placement.points, placement.branches + notes,
                                  placement.sigmas)
    record = staged.record(placement)
    # the positions reported are the program's (the same dyad formulas over floats, on the
    # closures the assembly chose), so every number of a Solution comes from one record
    placement = Placement(staged.placed(record), placement.branches, placement.sigmas)
    return Solution(scene, plan, placement, staged, record)


def planned(scene: Scene, targets: tuple[str, ...] | None = None, plan: Plan | None = None):
    """(plan, construction steps, staged program) of ``scene``, made on first use and kept
    with the scene (``plan``: this plan of it instead of the scene's own, :func:`assur_pairs`)."""
    cache = memo_of(scene).setdefault("planned", {})   # a memo beside the frozen record
    key = targets if plan is None else (targets, plan.dyads)
    hit = cache.get(key)
    if hit is None:
        plan = plan or make_plan(scene, targets)
        steps = construction(plan)
        hit = cache[key] = (plan, steps, compile_staged(scene, plan, steps, geometry.meet))
    return hit


def assur_pairs(plan: Plan, points) -> tuple[Plan, tuple]:
    """``plan`` with each class-III group's auxiliary point S taken on the pair of its links
    that meet at the instant ``points`` where its own pair is parallel (S at infinity: a
    point of the construction, not a singularity of the group), and the notes saying so as
    (label, words)."""
    from dataclasses import replace
    dyads, notes = [], []
    for d in plan.dyads:
        if getattr(d, "many_closures", False):
            d, note = d.for_instant(points)
            if note:
                notes.append((d.s, note))
        dyads.append(d)
    return (replace(plan, dyads=tuple(dyads)) if notes else plan), tuple(notes)


def link_ends(scene: Scene, name: str) -> tuple[str, str]:
    """A link's or slotted lever's axis (its ends; a lever's pivot and the point under the
    pin), read off the mechanism model."""
    body = scene.model.body(name)
    if body.kind not in ("link", "lever"):
        raise KeyError(name)
    return body.a, body.b
