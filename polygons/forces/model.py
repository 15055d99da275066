"""The force model at one instant: the scene's parsed loads (:mod:`polygons.loads`) read against a
kinematic :class:`~polygons.evaluate.Solution`.

Accelerations of centres of mass are read off the acceleration polygon as images of their link
(similar figures), velocities likewise; nothing is differentiated again here.  Every external
load at a state is a :class:`Load` (:func:`loads`); every mass item's m a_G and I_G α an
:class:`Inertia` (:func:`inertias`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..errors import ConstructionError, SceneError
from ..evaluate import Solution
from ..loadmodel import (AppliedForce, AppliedTorque, Body, Friction, ForceAnswer, Joint, Loads,
                     MassItem, SlotContact, Spring)
from ..scene import Scene
from ..theorems import centripetal, cross, perp, relative_velocity, tangential

__all__ = ["ForceModel", "Load", "Inertia", "has_forces", "position", "image",
           "body_omega", "body_alpha", "body_angle", "unit_r", "centre", "loads",
           "spring_state", "spring_refs", "friction_sense", "inertias", "cross", "perp"]


def has_forces(scene: Scene) -> bool:
    """True when the scene has any force table (masses, forces, torques, springs)."""
    return scene.loads is not None and scene.loads.active


@dataclass(frozen=True)
class ForceModel:
    """The scene, its parsed loads and the springs' references at the scene's instant."""
    scene: Scene
    parsed: Loads
    ref: Mapping = field(default_factory=lambda: MappingProxyType({}))

    # the parsed tables, by their names
    @property
    def bodies(self) -> Mapping[str, Body]:
        return self.parsed.bodies

    @property
    def members(self) -> Mapping[str, tuple[str, ...]]:
        return self.parsed.members

    @property
    def joints(self) -> tuple[Joint, ...]:
        return self.parsed.joints

    @property
    def slots(self) -> tuple[SlotContact, ...]:
        return self.parsed.slots

    @property
    def guides(self) -> tuple[str, ...]:
        return self.parsed.guides

    @property
    def masses(self) -> tuple[MassItem, ...]:
        return self.parsed.masses

    @property
    def forces(self) -> tuple[AppliedForce, ...]:
        return self.parsed.forces

    @property
    def torques(self) -> tuple[AppliedTorque, ...]:
        return self.parsed.torques

    @property
    def frictions(self) -> tuple[Friction, ...]:
        return self.parsed.frictions

    @property
    def springs(self) -> tuple[Spring, ...]:
        return self.parsed.springs

    @property
    def gravity(self) -> np.ndarray:
        return np.array(self.parsed.gravity)

    @property
    def mode(self) -> str:
        return self.parsed.mode

    @property
    def after(self) -> tuple[float, ...]:
        return self.parsed.after

    @property
    def steps(self) -> int:
        return self.parsed.steps

    @property
    def answers(self) -> tuple[ForceAnswer, ...]:
        return self.parsed.answers

    @property
    def driver_body(self) -> str:
        return self.parsed.driver_body

    def items_of(self, body: str) -> list[MassItem]:
        return self.parsed.items_of(body)


# ---------------------------------------------------------------- reading the polygons
def position(sol: Solution, label: str) -> np.ndarray:
    return np.array(sol.points[label].position)


def _kin(sol: Solution, label: str, kind: str) -> np.ndarray:
    v = getattr(sol.points[label], kind)
    return np.zeros(2) if v is None else np.array(v)


def wheel(sol: Solution, body: Body):
    """The [rolling] wheel that ``body`` is (a block at its centre rolling on a fixed surface),
    or None."""
    if body.kind != "block":
        return None
    return next((q for q in getattr(sol.scene, "equivalents", ()) if q.kind == "rolling"
                 and q.at == body.a and q.on is None and q.opposite is None), None)


def _wheel_rates(sol: Solution, body: Body) -> tuple[float, float] | None:
    """(ω, α) of a rolling wheel from the no-slip condition (:func:`polygons.wheels.rolling`)."""
    q = wheel(sol, body)
    if q is None:
        return None
    from ..wheels import rolling
    h = rolling(sol, q) or {}
    return float(h.get("omega") or 0.0), float(h.get("alpha") or 0.0)


def image(sol: Solution, body: Body, r: np.ndarray, kind: str) -> np.ndarray:
    """Velocity or acceleration of the point at ``r`` of ``body``, from its first labelled point
    A by the theorems of the polygons: v = v_A + ω × AR, a = a_A + α × AR − ω² AR (the image
    of the body in the polygon is similar to the body).  A slider block translates; a rolling
    wheel (a block at its centre) turns at the ω and α of rolling."""
    rates = _wheel_rates(sol, body) if body.kind == "block" else None
    if body.kind == "block" and rates is None:
        return _kin(sol, body.a, kind)
    ar = np.asarray(r, dtype=float) - position(sol, body.a)
    w, al = rates if rates is not None else (sol.links[body.name].omega or 0.0,
                                              sol.links[body.name].alpha or 0.0)
    if kind == "velocity":
        return _kin(sol, body.a, kind) + relative_velocity(w, ar)
    return _kin(sol, body.a, kind) + tangential(al, ar) + centripetal(w, ar)


def body_omega(sol: Solution, body: Body) -> float:
    if body.kind == "block":
        rates = _wheel_rates(sol, body)
        return 0.0 if rates is None else rates[0]
    return float(sol.links[body.name].omega or 0.0)


def body_alpha(sol: Solution, body: Body) -> float:
    if body.kind == "block":
        rates = _wheel_rates(sol, body)
        return 0.0 if rates is None else rates[1]
    return float(sol.links[body.name].alpha or 0.0)


def body_angle(sol: Solution, body: Body) -> float:
    if body.kind == "block":
        return 0.0
    d = position(sol, body.b) - position(sol, body.a)
    return math.atan2(d[1], d[0])


def unit_r(sol: Solution, body: Body) -> np.ndarray:
    """Unit vector along ``body`` (its first label towards its second; a block: its guide)."""
    if body.kind == "block":
        return np.array(sol.scene.model.guide[body.a].line.direction)
    d = position(sol, body.b) - position(sol, body.a)
    return d / float(np.hypot(*d))


def centre(model: ForceModel, sol: Solution, item: MassItem) -> np.ndarray:
    if item.kind in ("point", "block"):
        return position(sol, item.at)
    body = model.bodies[item.body]
    u = unit_r(sol, body)
    return position(sol, body.a) + item.along * u + item.left * perp(u)


# ---------------------------------------------------------------- loads
@dataclass(frozen=True)
class Load:
    """A force ``force`` at ``pos`` (label ``at``) and/or a couple on ``body``; ``source`` names
    the table entry it comes from; ``item`` marks the weight of a mass item."""
    source: str
    kind: str              # 'force' | 'torque' | 'gravity' | 'spring' | 'friction' | 'input'
    body: str
    at: str | None
    pos: np.ndarray | None
    force: np.ndarray
    couple: float
    item: str | None = None


def spring_refs(model: ForceModel, base: Solution) -> dict:
    """The springs' references at the scene's instant (``base``): a linear spring's free
    length, a directional spring's anchor, a torsional spring's unstressed relative angle."""
    ref = {}
    for s in model.springs:
        if s.kind == "linear":
            (l1, _), (l2, _) = s.ends
            length = float(np.hypot(*(position(base, l2) - position(base, l1))))
            ref[s.name] = s.free_length if s.free_length is not None \
                else length - s.extension
            if ref[s.name] < 0:
                raise SceneError(f"the free length comes out negative "
                                 f"({ref[s.name]:.6g} m)", file=model.scene.file,
                                 where=f"springs.{s.name}")
        elif s.kind == "directional":
            ref[s.name] = position(base, s.at)
        else:
            ref[s.name] = rel_angle(model, base, s.first, s.second) - s.twist
    return ref


def rel_angle(model, sol, first, second) -> float:
    a = body_angle(sol, model.bodies[first])
    b = body_angle(sol, model.bodies[second]) if second else 0.0
    return a - b


def wrap(x: float) -> float:
    """An angle brought into [−π, π)."""
    return (x + math.pi) % (2.0 * math.pi) - math.pi


def spring_state(model: ForceModel, sol: Solution, s: Spring) -> dict:
    """Extension (or twist), force (or torque) and potential energy of a spring at ``sol``:
    F = k·x, T = −k_t·φ, V = ½ k x²."""
    if s.kind == "linear":
        (l1, _), (l2, _) = s.ends
        p1, p2 = position(sol, l1), position(sol, l2)
        d = p2 - p1
        length = float(np.hypot(*d))
        if not length > 1e-12 * float(np.max(np.abs(np.concatenate([p1, p2])))):
            raise ConstructionError(f"the ends {l1} and {l2} of the spring coincide: the line "
                                    f"of its force is undefined", file=model.scene.file,
                                    where=f"springs.{s.name}")
        ext = length - model.ref[s.name]
        return {"extension": ext, "tension": s.stiffness * ext, "length": length,
                "energy": 0.5 * s.stiffness * ext * ext, "unit": d / length}
    if s.kind == "directional":
        e = np.array(s.direction)
        ext = s.extension - float((position(sol, s.at) - model.ref[s.name]) @ e)
        return {"extension": ext, "tension": s.stiffness * ext,
                "energy": 0.5 * s.stiffness * ext * ext, "unit": e}
    twist = wrap(rel_angle(model, sol, s.first, s.second) - model.ref[s.name])
    return {"twist": twist, "torque": -s.stiffness * twist,
            "energy": 0.5 * s.stiffness * twist * twist}


def loads(model: ForceModel, sol: Solution, vsol: Solution,
          motion: int | None = None) -> list[Load]:
    """Every external load at the state ``sol``.  ``vsol`` (velocities per unit input rate) and
    ``motion`` (+1/−1, the sense of the input's motion) fix a friction's sense when the pin does
    not turn at this instant (released from rest)."""
    out: list[Load] = []
    g = model.gravity
    if g.any():
        for it in model.masses:
            out.append(Load(f"weight of {it.name}", "gravity", it.body, it.at,
                            centre(model, sol, it), it.mass * g, 0.0, it.name))
    for f in model.forces:
        v = sol.points[f.at].velocity if f.resisting else None
        if v is not None and float(np.dot(v, f.force)) >= 0.0 and any(v):
            continue        # a resisting force does not act while its point moves with it
        out.append(Load(f.name, "force", f.body, f.at, position(sol, f.at), np.array(f.force),
                        0.0))
    for t in model.torques:
        out.append(Load(t.name, "torque", t.body, t.at, None, np.zeros(2), t.torque))
    for s in model.springs:
        st = spring_state(model, sol, s)
        if s.kind == "linear":
            (l1, b1), (l2, b2) = s.ends
            f = st["tension"] * st["unit"]          # pulls l1 towards l2
            if b1:
                out.append(Load(s.name, "spring", b1, l1, position(sol, l1), f, 0.0))
            if b2:
                out.append(Load(s.name, "spring", b2, l2, position(sol, l2), -f, 0.0))
        elif s.kind == "directional":
            out.append(Load(s.name, "spring", s.body, s.at, position(sol, s.at),
                            st["tension"] * st["unit"], 0.0))
        else:
            out.append(Load(s.name, "spring", s.first, s.at, None, np.zeros(2), st["torque"]))
            if s.second:
                out.append(Load(s.name, "spring", s.second, s.at, None, np.zeros(2),
                                -st["torque"]))
    for fr in model.frictions:
        sense = friction_sense(model, sol, vsol, fr, motion)
        t = -fr.torque * sense
        out.append(Load(fr.name, "friction", fr.first, fr.at, None, np.zeros(2), t))
        if fr.second:
            out.append(Load(fr.name, "friction", fr.second, fr.at, None, np.zeros(2), -t))
    return out


def friction_sense(model, sol, vsol, fr: Friction, motion) -> int:
    """Sense (+1 CCW / −1 CW / 0) of the relative rotation of ``fr.first`` against
    ``fr.second`` at its pin; at rest, the sense it is about to turn in (``motion``)."""
    b1 = model.bodies[fr.first]
    b2 = model.bodies[fr.second] if fr.second else None
    w = body_omega(sol, b1) - (body_omega(sol, b2) if b2 else 0.0)
    scale = max(1.0, abs(body_omega(sol, b1)))
    if abs(w) > 1e-12 * scale:
        return 1 if w > 0 else -1
    if motion:
        ws = body_omega(vsol, b1) - (body_omega(vsol, b2) if b2 else 0.0)
        if abs(ws) > 1e-12:
            return int(math.copysign(1, ws * motion))
    return 0


# ---------------------------------------------------------------- inertia
@dataclass(frozen=True)
class Inertia:
    """A mass item's inertia at one state: m a_G and I_G α (the inertia force is −m a_G)."""
    item: str
    body: str
    mass: float
    inertia: float
    centre: np.ndarray
    v: np.ndarray
    a: np.ndarray
    alpha: float            # of its body (0 for a free disc)
    omega: float

    @property
    def ma(self) -> np.ndarray:
        return self.mass * self.a

    @property
    def i_alpha(self) -> float:
        return self.inertia * self.alpha


def inertias(model: ForceModel, sol: Solution) -> list[Inertia]:
    out = []
    for it in model.masses:
        body = model.bodies[it.body]
        g = centre(model, sol, it)
        w = 0.0 if it.free else body_omega(sol, body)
        al = 0.0 if it.free else body_alpha(sol, body)
        out.append(Inertia(it.name, it.body, it.mass, it.inertia, g,
                           image(sol, body, g, "velocity"), image(sol, body, g, "acceleration"),
                           al, w))
    return out
