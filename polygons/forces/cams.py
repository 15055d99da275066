"""The contact force of a cam (roller or flat-faced follower) or of a pin in a curved slot,
read off the forces of the equivalent linkage; and the friction and normal force on a wheel
rolling on a fixed surface (its slider's guide force is the normal, and in place of a guide
couple Newton–Euler finds the friction at the contact that makes it turn: I_G α = r × F).

F_contact = the force in the equivalent link CR (roller, curved slot) or the slot's normal
force on the follower (flat face).  A frictionless contact pushes along the common normal,
which passes through the profile's centre of curvature C and the follower's point (the
roller's centre R, the pin P, the foot of the perpendicular from C on a flat face): the line
of the equivalent link CR, a massless two-force member, or the normal of the follower's slot
through C.  So the linkage that gives the instant's velocities and accelerations gives the
contact force too, exactly (books: "the force between cam and follower acts along the common
normal").  A cam can only push: a pull means the follower leaves the cam at this instant.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .model import ForceModel, position
from .newton_euler import NEResult


@dataclass(frozen=True)
class CamContact:
    """One contact at one state: ``force`` (N) on the ``follower`` from the ``cam`` at
    ``contact`` (m; None when the face's side is not stated); ``push`` its component along the
    normal from the cam's material to the follower (N; negative: the cam would have to pull,
    contact is lost; None for a slot, which has two walls, and a translating flat face);
    ``pressure_angle`` (rad) between the normal and the follower point's velocity (None when it
    is at rest)."""

    label: str
    kind: str
    cam: str
    follower: str
    force: tuple[float, float]
    contact: tuple[float, float] | None
    push: float | None
    pressure_angle: float | None
    via: str                 # how the linkage carries it, in words

    @property
    def magnitude(self) -> float:
        return float(math.hypot(*self.force))

    @property
    def lost(self) -> bool:
        return self.push is not None and self.push < 0.0


def _others(model: ForceModel, label: str, exclude: str) -> tuple[str, ...]:
    return tuple(b for b in model.members.get(label, ()) if b != exclude)


def _pressure_angle(v, normal: np.ndarray) -> float | None:
    """The angle between the contact normal and the velocity ``v`` of the follower's point."""
    if v is None or math.hypot(*v) == 0.0:
        return None
    c = abs(float(np.dot(normal, v))) / math.hypot(*v)
    return math.acos(min(1.0, c))


def cam_contacts(model: ForceModel, ne: NEResult, sol) -> tuple[CamContact, ...]:
    """Every cam / curved-slot contact of the scene at the state ``sol`` solved by ``ne``."""
    out = []
    for q in model.scene.equivalents:
        if q.kind in ("cam", "curved slot"):
            C, P = position(sol, q.centre), position(sol, q.at)
            f = -np.asarray(ne.pin[(q.at, q.link)])     # on what is pinned at P, from CR
            r = P - C
            u = r / float(np.hypot(*r))
            concave = q.kind == "cam" and q.length < q.radius
            cam = " and ".join(_others(model, q.centre, q.link)) or "the frame"
            follower = " and ".join(_others(model, q.at, q.link)) or "the frame"
            if q.kind == "cam":
                push = float(np.dot(f, -u if concave else u))
                contact = C + q.radius * u
                via = f"the force in the equivalent link {q.link}"
            else:                       # a slot has two walls: either sense is possible
                push, contact = None, P
                via = f"the force in the equivalent link {q.link} (normal to the slot)"
            out.append(CamContact(q.at, q.kind, cam, follower, (float(f[0]), float(f[1])),
                                  (float(contact[0]), float(contact[1])), push,
                                  _pressure_angle(sol.points[q.at].velocity, u), via))
        elif q.kind == "flat-faced cam":
            s = next(x for x in model.slots if x.pin == q.centre)
            value, n = ne.slot[q.centre]
            f = value * np.asarray(n)                  # on the follower (the slotted body)
            C = position(sol, q.centre)
            follower = s.lever
            if q.arm is not None:   # the cam on the arm's left (face +1) or right (−1)
                a, b = model.bodies[q.arm].a, model.bodies[q.arm].b
                d = position(sol, b) - position(sol, a)
                left = np.array([-d[1], d[0]]) / float(np.hypot(*d))
                away = -q.face * left               # from the cam towards the face
                push = float(np.dot(f, away))
                contact = C + q.radius * away
                contact_t = (float(contact[0]), float(contact[1]))
                w = sol.links[q.arm].omega or 0.0       # the arm's point at the contact
                rq = contact - position(sol, a)
                v = (-w * rq[1], w * rq[0])
            else:                   # a translating face: which side the follower lies is
                push, contact_t = None, None        # not stated
                away, v = np.asarray(n), sol.points[q.at].velocity
            out.append(CamContact(q.at, q.kind, s.carrier, follower,
                                  (float(f[0]), float(f[1])), contact_t, push,
                                  _pressure_angle(v, away),
                                  f"the normal force of the slot of {follower} on the pin "
                                  f"{q.centre}"))
    return tuple(out)


def words(c: CamContact) -> str:
    """The contact in a line: who pushes whom, how hard, along which normal."""
    d = math.degrees(math.atan2(c.force[1], c.force[0])) % 360.0
    what = {"cam": "the cam", "curved slot": "the curved slot",
            "flat-faced cam": "the cam"}[c.kind]
    line = (f"contact at {c.label}: {what} ({c.cam}) on {c.follower}: {c.magnitude:.6g} N "
            f"towards {d:.6g}° along the common normal ({c.via})")
    if c.pressure_angle is not None:
        line += f"; pressure angle {math.degrees(c.pressure_angle):.4g}°"
    if c.lost:
        line += (f" — the cam would have to pull ({c.push:.6g} N): the follower leaves the "
                 f"cam at this instant (a stronger spring or a smaller speed keeps contact)")
    return line


def mu_needed(label: str, ne: NEResult) -> float | None:
    """The least coefficient of friction that keeps the wheel ``label`` rolling without
    slipping: |F| / N (None when the surface does not press on it)."""
    f = ne.rolling[label][0]
    n = ne.guide[label][0]
    return abs(f) / n if n > 0 else None


def rolling_words(label: str, ne: NEResult) -> str:
    """A wheel's contact with its fixed surface in a line: the normal force, the friction
    that makes it roll (F = the force along the surface at the contact), the μ it needs."""
    f, e, at = ne.rolling[label]
    n = ne.guide[label][0]
    d = math.degrees(math.atan2(e[1] * f, e[0] * f)) % 360.0 if f else 0.0
    line = (f"rolling: the surface on the wheel {label}: normal {n:.6g} N, friction "
            f"{abs(f):.6g} N along the surface towards {d:.6g}° at the contact "
            f"({at[0] * 1e3:.6g}, {at[1] * 1e3:.6g}) mm")
    mu = mu_needed(label, ne)
    if mu is None:
        return line + " — the surface would have to pull: the wheel leaves it at this instant"
    return line + f"; it rolls without slipping while μ ≥ {mu:.4g}"
