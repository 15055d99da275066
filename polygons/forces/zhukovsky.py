"""Zhukovsky's (Joukowski's) lever: the velocity polygon turned 90° (CCW) about its pole and
taken as a rigid lever pivoted there.  Each force, inertia force included, is applied at the
image of its point of application (the image of the point in the velocity polygon, turned),
parallel to itself; a couple C on a link AB is applied as the pair ±C/AB normal to AB at the
images a and b; the balancing effort (the driver's torque as a pair on the crank, a force at
a slider's image, an actuator's pair at the images of its ends) follows from the moments about
the pole.

The moment of a force F applied at the turned image r = k × v of its point is
r × F = −F · v: the lever's moment equation is the power balance, so the effort equals the
virtual-work effort (:mod:`polygons.forces.virtual_work`); the tests hold them to 1e-9.  The
inertia force −m a_G acts through the point offset from G by h = I_G α / (m a_G), so it carries
the inertia couple too.  At rest (input rate 0) the polygon of a unit input rate is used.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import effort as effort_mod
from .model import cross, image, perp, position, wheel
from .states import Analysis, State


@dataclass(frozen=True)
class Applied:
    """A force on the lever: ``force`` (N) at the space point ``at`` (m) of ``body``, applied
    at ``lever`` = the turned image of ``at`` (m/s); ``moment`` about the pole (N m/s)."""
    name: str
    kind: str            # 'load' | 'weight' | 'inertia' | 'couple' | 'effort' | 'spring' ...
    body: str
    force: np.ndarray
    at: np.ndarray
    lever: np.ndarray
    moment: float
    label: str = ""      # the space label of the point, when it has one


@dataclass(frozen=True)
class Lever:
    state: str
    unit_rate: bool                    # drawn on the polygon of a unit input rate (at rest)
    images: dict                       # space label -> turned image (m/s)
    applied: tuple[Applied, ...]       # the known forces (loads, inertia, couples as pairs)
    effort_forces: tuple[Applied, ...]  # the effort found, as applied on the lever
    effort: float                      # N m or N (the driver's, or [dynamics] effort)
    moment_sum: float                  # Σ moments of the known forces about the pole
    unit_moment: float                 # moment of the unit effort about the pole


def _turn(v) -> np.ndarray:
    return perp(np.asarray(v, dtype=float))       # 90° CCW


def construct(an: Analysis, st: State) -> Lever:
    """Zhukovsky's lever at the state ``st``."""
    model = an.model
    drv = st.sol.scene.driver
    rate = (drv.omega if hasattr(drv, "omega") else drv.velocity)
    vs = st.vsol if rate == 0.0 else st.sol        # the polygon the lever is drawn on
    images = {lab: _turn(p.velocity) for lab, p in vs.points.items() if p.velocity is not None}

    def lev(body, r):
        return _turn(image(vs, model.bodies[body], r, "velocity"))

    def label_at(body, r):
        for lab in model.bodies[body].labels:
            if float(np.hypot(*(position(st.sol, lab) - r))) < 1e-12:
                return lab
        return ""

    def force(name, kind, body, f, r) -> Applied:
        q = lev(body, r)
        return Applied(name, kind, body, np.asarray(f, float), np.asarray(r, float), q,
                       cross(q, f), label_at(body, r))

    def pair(name, kind, body, c) -> list[Applied]:
        """A couple ``c`` on ``body`` as ±c/AB normal to AB at A and B (none on a block that
        translates; a rolling wheel's at its centre and the top of its rim)."""
        b = model.bodies[body]
        q = wheel(st.sol, b)
        if c == 0.0 or (q is None and (b.kind == "block" or b.b is None)):
            return []
        pa = position(st.sol, b.a)
        pb = (pa + q.radius * perp(np.array((math.cos(q.face), math.sin(q.face))))
              if q is not None else position(st.sol, b.b))
        d = pb - pa
        ln = float(np.hypot(*d))
        f = c / ln * perp(d / ln)                 # (B − A) × f = c
        return [force(f"{name} at {b.a}", kind, body, -f, pa),
                force(f"{name} at {b.b if q is None else 'the rim'}", kind, body, f, pb)]

    applied: list[Applied] = []
    for ld in st.ne.loads:
        kind = {"gravity": "weight"}.get(ld.kind, ld.kind)
        name = f"W_{ld.item}" if ld.kind == "gravity" else ld.source
        if ld.force.any() and ld.pos is not None:
            applied.append(force(name, kind, ld.body, ld.force, ld.pos))
        if ld.couple:
            applied += pair(name, "couple", ld.body, ld.couple)
    for it in st.inertia:
        f = -it.ma
        free = next(m for m in model.masses if m.name == it.item).free
        c = 0.0 if free else -it.i_alpha
        n2 = float(f @ f)
        if n2 > 0:
            applied.append(force(f"−m a_G ({it.item})", "inertia", it.body, f,
                                 it.centre - c * perp(f) / n2))
        elif c:
            applied += pair(f"−I_G α ({it.item})", "inertia", it.body, c)
    unit = []
    for t in effort_mod.terms(model, st.sol):
        if t.couple:
            unit += pair("effort", "effort", t.body, t.couple)
        if t.pos is not None:
            unit.append(force("effort", "effort", t.body, t.direction, t.pos))
    msum = sum((a.moment for a in applied), 0.0)
    munit = sum((a.moment for a in unit), 0.0)
    if abs(munit) < 1e-12 * max(1.0, max((abs(a.moment) for a in applied), default=1.0)):
        from ..errors import UnsupportedError
        raise UnsupportedError(f"Zhukovsky's lever: the {effort_mod.words(model)} has no "
                               f"moment about the pole (its point does not move along it): it "
                               f"cannot balance the loads", file=model.scene.file)
    e = -msum / munit
    found = tuple(Applied(a.name.replace("effort", effort_mod.short(model)), "effort", a.body,
                          a.force * e, a.at, a.lever, a.moment * e, a.label) for a in unit)
    return Lever(st.name, rate == 0.0, images, tuple(applied), found, e, msum, munit)


__all__ = ["Applied", "Lever", "construct"]
