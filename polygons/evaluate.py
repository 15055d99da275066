"""Evaluate the planned construction: put the numbers into every step.

Each step is executed with the theorem it names (:mod:`polygons.theorems`) and, for the
intersections, with shapely (:mod:`polygons.geometry`).  Every number in a
:class:`Solution` is read off the evaluated polygon vertices; nothing is computed twice.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import Iterable, Mapping

import numpy as np

from . import geometry
from .errors import ConstructionError, PolygonsError
from .plan import Plan, Step, Vertices, construction, make_plan
from .position import Placement, assemble
from .scene import Crank, Scene
from .theorems import (angular_acceleration, angular_velocity, centripetal, coriolis, cross,
                       perp, relative_velocity, tangential)

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
    """scene → plan → position → evaluated construction → :class:`Solution`."""
    plan = make_plan(scene, targets)
    placement = assemble(plan)
    return evaluate(plan, placement, construction(plan))


def link_ends(scene: Scene, name: str) -> tuple[str, str]:
    if name in scene.links:
        return scene.links[name].a, scene.links[name].b
    for slot in scene.slots.values():
        if slot.lever == name:
            return slot.pivot, slot.coincident
    raise KeyError(name)


class _State:
    def __init__(self, plan: Plan, placement: Placement):
        self.scene = plan.scene
        self.pos = {k: np.array(v) for k, v in placement.points.items()}
        self.names = Vertices(self.scene)
        self.vx = {"velocity": {self.names.pole: np.zeros(2)},
                   "acceleration": {self.names.pole: np.zeros(2)}}
        self.omega: dict[str, float] = {}
        self.alpha: dict[str, float] = {}
        self.lines: dict[tuple[str, int], geometry.Line] = {}
        self.slide_v: dict[str, float] = {}
        self.slide_a: dict[str, float] = {}
        self.cor: dict[str, np.ndarray] = {}
        drv = self.scene.driver
        if isinstance(drv, Crank):
            self.omega[drv.link] = drv.omega
            self.alpha[drv.link] = drv.alpha

    def r(self, p: str, x: str) -> np.ndarray:
        return self.pos[x] - self.pos[p]

    def vertex(self, diagram: str, name: str) -> np.ndarray:
        return self.vx[diagram][name]

    def of(self, diagram: str, label: str) -> np.ndarray:
        return self.vx[diagram][self.names.of(label)]


def _unit_of(r: np.ndarray) -> np.ndarray:
    return r / float(np.hypot(*r))


def _f(x: float) -> str:
    """Five significant figures written out in full, trailing zeros dropped, as a tutorial
    would (156105, 0.80587, 0.05)."""
    x = float(x)
    if x == 0.0 or not 1e-4 <= abs(x) < 1e9:
        return f"{x:.5g}"
    decimals = max(0, 4 - math.floor(math.log10(abs(x))))
    text = f"{x:.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def evaluate(plan: Plan, placement: Placement, steps: tuple[Step, ...]) -> Solution:
    st = _State(plan, placement)
    scene = st.scene
    done: list[Step] = []
    for step in steps:
        try:
            done.append(_run(st, step))
        except PolygonsError as exc:
            raise exc.located(file=scene.file,
                              step=f"{step.diagram} {step.number} ({step.draws})") from None
    return _collect(plan, placement, st, tuple(done))


def _run(st: _State, s: Step) -> Step:
    scene, d = st.scene, s.diagram
    vel = d == "velocity"
    vx = st.vx[d]
    start = vx[s.start] if s.start is not None else None
    op, args = s.op, s.args

    def vector(vec, substituted, unit):
        end = start + vec
        vx[s.end] = end
        return replace(s, at=_t(start), vector=_t(vec), point=_t(end),
                       substituted=substituted, unit=unit)

    def new_line(direction, anchor, name):
        ln = geometry.line(anchor, direction, name)
        st.lines[(d, s.number)] = ln
        return replace(s, at=_t(ln.point), direction=ln.direction)

    if op == "crank_velocity":
        L, P, X = args
        w = st.omega[L]
        r = st.r(P, X)
        vec = relative_velocity(w, r)
        return vector(vec, f"(v_{X})_{P} = ω × {P}{X} = {_f(abs(w))} × {_f(_n(r))} = "
                           f"{_f(_n(vec))} m/s", "m/s")
    if op == "slider_drive":
        (X,) = args
        e = np.array(scene.sliders[X].direction)
        val = scene.driver.velocity if vel else scene.driver.acceleration
        return vector(val * e, f"{_f(val)} {'m/s' if vel else 'm/s²'} along the guide",
                      "m/s" if vel else "m/s^2")
    if op == "centripetal":
        L, P, X = args
        w = st.omega[L]
        r = st.r(P, X)
        vec = centripetal(w, r)
        return vector(vec, f"ω² × {P}{X} = {_f(abs(w))}² × {_f(_n(r))} = {_f(_n(vec))} m/s²",
                      "m/s^2")
    if op == "crank_tangential":
        L, P, X = args
        al = st.alpha[L]
        r = st.r(P, X)
        vec = tangential(al, r)
        return vector(vec, f"α × {P}{X} = {_f(abs(al))} × {_f(_n(r))} = {_f(_n(vec))} m/s²",
                      "m/s^2")
    if op == "line_perp":
        P, X = args
        return new_line(perp(st.r(P, X)), start, s.draws)
    if op == "line_along":
        P, X = args
        return new_line(st.r(P, X), start, s.draws)
    if op == "line_guide":
        (X,) = args
        return new_line(np.array(scene.sliders[X].direction), start, s.draws)
    if op == "line_slot":       # the slot of a translating yoke: a fixed direction
        (X,) = args
        return new_line(np.array(scene.sliders[X].slot_direction), start, s.draws)
    if op == "coriolis_offset_line":
        (A,) = args
        slot = scene.slots[A]
        e = _unit_of(st.r(slot.pivot, A))
        w = st.omega[slot.lever]
        a_cor = coriolis(w, st.slide_v[A] * e)
        st.cor[A] = a_cor
        out = new_line(e, st.of(d, A) - a_cor, s.draws)
        return replace(out, vector=_t(-a_cor), substituted=(
            f"2ωv = 2 × {_f(abs(w))} × {_f(abs(st.slide_v[A]))} = {_f(_n(a_cor))} m/s²"),
            unit="m/s^2")
    if op == "coriolis":
        (A,) = args
        a_cor = st.cor[A]
        return vector(a_cor, f"2ωv = {_f(_n(a_cor))} m/s²", "m/s^2")
    if op == "join":
        vec = vx[s.end] - start
        return replace(s, at=_t(start), vector=_t(vec), point=_t(vx[s.end]),
                       substituted=f"{s.start}{s.end} = {_f(_n(vec))} m/s²", unit="m/s^2")
    if op == "intersect":
        l1, l2 = (st.lines[(d, n)] for n in s.lines)
        hit = geometry.intersect(l1, l2, step=f"{d} {s.number} ({s.draws})")
        p = np.array(hit.point)
        vx[s.end] = p
        unit = "m/s" if vel else "m/s^2"
        return replace(s, point=hit.point, angle_deg=hit.angle_deg, unit=unit,
                       substituted=f"{st.names.pole}{s.end} = {_f(_n(p))} {unit.replace('^2', '²')}"
                                   f" (lines meet at {hit.angle_deg:.3g}°)")
    if op == "omega":
        L, P, Q = args
        r = st.r(P, Q)
        rel = st.of(d, Q) - st.of(d, P)
        w = angular_velocity(r, rel)
        st.omega[L] = w
        return replace(s, value=w, unit="rad/s", substituted=(
            f"ω_{L} = {_f(_n(rel))} / {_f(_n(r))} = {_f(abs(w))} rad/s {_sense(w)}"))
    if op == "alpha":
        L, P, X = args
        r = st.r(P, X)
        rel = st.of(d, X) - st.of(d, P)
        al = angular_acceleration(r, rel)
        st.alpha[L] = al
        at = abs(cross(_unit_of(r), rel))
        return replace(s, value=al, unit="rad/s^2", substituted=(
            f"α_{L} = {_f(at)} / {_f(_n(r))} = {_f(abs(al))} rad/s² {_sense(al)}"))
    if op in ("slider_velocity", "slider_acceleration"):
        (X,) = args
        e = np.array(scene.sliders[X].direction)
        val = float(st.of(d, X) @ e)
        unit = "m/s" if vel else "m/s^2"
        return replace(s, value=val, unit=unit,
                       substituted=f"{_f(val)} {unit} along the guide ({_f(math.degrees(scene.sliders[X].angle))}°)")
    if op in ("slide_velocity", "slide_acceleration"):
        (A,) = args
        slot = scene.slots[A]
        e = _unit_of(st.r(slot.pivot, A))
        if vel:
            val = float((st.of(d, A) - st.of(d, slot.coincident)) @ e)
            st.slide_v[A] = val
            unit = "m/s"
        else:
            val = float((st.of(d, A) - st.of(d, slot.coincident) - st.cor[A]) @ e)
            st.slide_a[A] = val
            unit = "m/s^2"
        return replace(s, value=val, unit=unit, substituted=(
            f"{_f(val)} {unit} ({'away from' if val >= 0 else 'towards'} {slot.pivot})"))
    if op == "image":
        L, P, Q, X = args
        if L not in st.omega:
            st.omega[L] = angular_velocity(st.r(P, Q), st.of("velocity", Q) - st.of("velocity", P))
        r = st.r(P, X)
        if vel:
            vec = relative_velocity(st.omega[L], r)
        else:
            if L not in st.alpha:
                st.alpha[L] = angular_acceleration(st.r(P, Q), st.of(d, Q) - st.of(d, P))
            vec = tangential(st.alpha[L], r) + centripetal(st.omega[L], r)
        unit = "m/s" if vel else "m/s^2"
        return vector(vec, f"{s.start}{s.end} = {_f(_n(vec))} {unit}", unit)
    raise ConstructionError(f"unknown construction operation {op!r}")


def _n(v) -> float:
    return float(np.hypot(v[0], v[1]))


def _t(v) -> Vec:
    return (float(v[0]), float(v[1]))


def _sense(w: float) -> str:
    if w == 0.0:
        return ""
    return "CCW" if w > 0 else "CW"


def _collect(plan: Plan, placement: Placement, st: _State, steps: tuple[Step, ...]) -> Solution:
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
            e = _unit_of(st.r(slot.pivot, pin))
            slides[pin] = SlideResult(pin, slot.lever, _t(e), st.slide_v.get(pin),
                                      st.slide_a.get(pin),
                                      _t(st.cor[pin]) if pin in st.cor else None)
    angles = [s.angle_deg for s in steps if s.angle_deg is not None]
    warnings = []
    for s in steps:
        if s.angle_deg is not None and s.angle_deg < geometry.WARN_DEG:
            warnings.append(f"{s.diagram} step {s.number}: the lines meeting at {s.end} cross at "
                            f"only {s.angle_deg:.3g}° — close to a toggle; the drawing and this "
                            f"number are unreliable")
    vertices = {d: MappingProxyType({k: _t(v) for k, v in st.vx[d].items()}) for d in solved}
    return Solution(scene, plan, placement, steps, st.names.pole, MappingProxyType(vertices),
                    MappingProxyType(points), MappingProxyType(links),
                    MappingProxyType(slides), min(angles) if angles else None,
                    tuple(warnings))
