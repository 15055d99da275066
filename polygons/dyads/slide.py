"""A prescribed slide (a second input): the collar C is moved along the link PQ at a stated
sliding velocity ṡ and acceleration s̈ while the link moves as the driver makes it ("the block
moves out along the rod at 1.5 m/s, slowing at 0.8 m/s², while the rod turns at 5 rad/s").

Position: C = P + s e, e = PQ/|PQ|; the link's point C1 under C is at the same place.  The
collar is on the rod only for 0 ≤ s ≤ |PQ|: beyond Q, or behind P, it has left the rod, and
the scene is refused (a sweep stops there: the collar's limit of travel).
Velocity: v_C = v_C1 + ṡ e, v_C1 = v_P + ω × PC1 (the image of C1 on the link).
Acceleration: a_C = a_C1 + s̈ e + 2 ω × ṡ e, a_C1 = a_P + α × PC1 − ω² PC1: every term is
known, so the polygon closes with no intersection (the Coriolis 2ωṡ drawn from both inputs).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..steps import Builder, Component, Kind, Op
from .base import size_of
from . import image
from .primitives import Constructed, AlongLink, Prescribed


@dataclass(frozen=True)
class SlideDyad(Constructed):
    """``point`` moved along ``link`` (ends ``p`` → ``q``); ``coincident`` is the link's point
    under it."""
    point: str
    link: str
    p: str
    q: str
    coincident: str
    two_closures = False

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.coincident, self.point)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p, self.q)

    @cached_property
    def construction(self) -> AlongLink:
        """Its position, stated once: C = P + s PQ/|PQ|, C1 = C.
        ``locate`` and ``source`` are this primitive's (:mod:`polygons.dyads.primitives`)."""
        return AlongLink(self.coincident, self.p, self.q, Prescribed(self.point),
                         also=(self.point,))

    def why_not(self, scene, pos) -> str:
        d = np.asarray(pos[self.q], dtype=float) - np.asarray(pos[self.p], dtype=float)
        n = float(np.hypot(d[0], d[1]))
        s = float(scene.prescribed[self.point].position)
        C, L, P, Q = self.point, self.link, self.p, self.q
        if not n > 1e-12 * size_of(scene):
            return (f"{P} and {Q} coincide, so the direction of {L} along which {C} slides "
                    f"is undefined")
        if s > n:
            return (f"the collar {C} at {_mm(s)} along {L} is beyond the end {Q} of the rod "
                    f"{L} ({_mm(n)}): it has left the rod")
        if s < 0:
            return (f"the collar {C} at {_mm(s)} along {L} is behind {P}, off the rod {L} "
                    f"(its position is measured from {P} towards {Q}, 0 to {_mm(n)})")
        return (f"the collar {C} at {_mm(s)} along {L} is at the end of the rod {L} "
                f"({_mm(n)}): its travel stops there")

    def toggle_reason(self, scene, pos) -> str:
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        C, C1, L, P, Q = self.point, self.coincident, self.link, self.p, self.q
        V = b.names.of
        c, c1 = V(C), V(C1)
        image.emit_image(b, C1, L, P, Q)
        if b.velocity:
            b.add(Kind.VECTOR, Op.SLIDE_DRIVE, (C, P, Q), f"{c1}{c}", c1, c, "sliding",
                  f"(v_{C})_{C1}", f"(v_{C})_{C1} = ṡ along {P}{Q} (given)",
                  f"From {c1} draw the given sliding velocity of {C} along {L}: {c1}{c}, "
                  f"parallel to {P}{Q}; {b.names.pole}{c} is the velocity of {C}.",
                  component=Component.GIVEN)
            return
        c2 = b.fresh(C)
        b.add(Kind.VECTOR, Op.SLIDE_DRIVE, (C, P, Q), f"{c1}{c2}", c1, c2, "sliding",
              f"(a_{C})_{C1}", f"(a_{C})_{C1} = s̈ along {P}{Q} (given)",
              f"From {c1} draw the given sliding acceleration of {C} along {L}, parallel to "
              f"{P}{Q}; call its end {c2}.", component=Component.GIVEN)
        b.add(Kind.VECTOR, Op.CORIOLIS, (C,), f"{c2}{c}", c2, c, "coriolis",
              "a_cor", f"a_cor = 2 ω_{L} × (v_{C})_{C1}",
              f"From {c2} draw the Coriolis acceleration 2ωṡ, perpendicular to {L} (ṡ turned "
              f"through 90° in the sense of ω_{L}); it ends at {c}: {b.names.pole}{c} is the "
              f"acceleration of {C}.", component=Component.CORIOLIS, link=L)


def _mm(x: float) -> str:
    return f"{1e3 * x:.6g} mm"


def matches(scene, placed):
    """Every prescribed slide whose link's ends are placed."""
    for sl in scene.prescribed.values():
        if sl.point not in placed and sl.p in placed and sl.q in placed:
            yield SlideDyad(sl.point, sl.link, sl.p, sl.q, sl.coincident)
