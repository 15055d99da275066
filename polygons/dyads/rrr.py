"""RRR: point X joined by two links to two placed points P and Q (the four-bar's coupler pin).

Position: X on both circles |PX| = r₁, |QX| = r₂ (two closures, named in the scene's words).
Velocity: v_X = v_P + ω_p × PX = v_Q + ω_q × QX: lines ⟂ PX through p and ⟂ QX through q meet
at x.  Acceleration: a_X = a_P − ω_p² PX + α_p × PX = a_Q − ω_q² QX + α_q × QX: the two
centripetal vectors are known, the two tangential lines meet at x.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder
from . import pinned
from .primitives import Constructed, CircleCircle, Length


@dataclass(frozen=True)
class RRR(Constructed):
    """Point ``x`` joined by link ``link_p`` to placed ``p`` and by ``link_q`` to placed ``q``."""
    p: str
    x: str
    q: str
    link_p: str
    link_q: str
    two_closures = True

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "RRR"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.link_p, self.link_q)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p, self.q)

    @property
    def default_ref(self) -> tuple[str, ...]:
        return (self.p, self.q)

    @cached_property
    def construction(self) -> CircleCircle:
        """Its position, stated once: X on both circles |PX| = r₁, |QX| = r₂ (closure σ).  ``locate`` and ``source`` are
        this primitive's (:mod:`polygons.dyads.primitives`)."""
        return CircleCircle(self.x, self.p, Length(self.link_p), self.q, Length(self.link_q))

    def why_not(self, scene, pos) -> str:
        import math
        r1 = scene.links[self.link_p].length
        r2 = scene.links[self.link_q].length
        d = pos[self.q] - pos[self.p]
        dist = math.hypot(float(d[0]), float(d[1]))
        if dist == 0.0:
            return (f"{self.p} and {self.q} coincide, so {self.x} is not fixed by "
                    f"{self.link_p} and {self.link_q}")
        if dist > r1 + r2:
            why = (f"{self.link_p} + {self.link_q} = {1e3 * (r1 + r2):.6g} mm is shorter than "
                   f"{self.p}{self.q} = {1e3 * dist:.6g} mm")
        elif dist < abs(r1 - r2):
            why = (f"|{self.link_p} − {self.link_q}| = {1e3 * abs(r1 - r2):.6g} mm is longer "
                   f"than {self.p}{self.q} = {1e3 * dist:.6g} mm")
        else:
            return self.toggle_reason(scene, pos)
        return (f"the links cannot close at this input: {why}, so {self.x} cannot be placed")

    def toggle_reason(self, scene, pos) -> str:
        import math
        r1 = scene.links[self.link_p].length
        r2 = scene.links[self.link_q].length
        d = pos[self.q] - pos[self.p]
        dist = math.hypot(float(d[0]), float(d[1]))
        how = ("stretched out" if abs(dist - (r1 + r2)) < abs(dist - abs(r1 - r2))
               else "folded back")
        return (f"{self.link_p} and {self.link_q} are in line ({self.p}, {self.x}, {self.q} "
                f"collinear, {how})")

    def emit(self, b: Builder) -> None:
        pinned.emit_two_lines(b, self.p, self.x, self.link_p, other=(self.q, self.link_q))


def match(scene, x, placed, known):
    """Two links of known length from x to placed points (and x on no guide)."""
    if x in scene.sliders or len(known) < 2:
        return None
    (p, lp), (q, lq) = known[0], known[1]
    return RRR(p, x, q, lp, lq)


def claims(scene, x) -> bool:
    """Whether the scene declares ``x`` as this kind's point."""
    return True
