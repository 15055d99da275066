"""A prescribed slide (a second input): the collar C is moved along the link PQ at a stated
sliding velocity ṡ and acceleration s̈ while the link moves as the driver makes it ("the block
moves out along the rod at 1.5 m/s, slowing at 0.8 m/s², while the rod turns at 5 rad/s").

Position: C = P + s e, e = PQ/|PQ|; the link's point C1 under C is at the same place.
Velocity: v_C = v_C1 + ṡ e, v_C1 = v_P + ω × PC1 (the image of C1 on the link).
Acceleration: a_C = a_C1 + s̈ e + 2 ω × ṡ e, a_C1 = a_P + α × PC1 − ω² PC1: every term is
known, so the polygon closes with no intersection (the Coriolis 2ωṡ drawn from both inputs).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..steps import Builder, Component, Kind, Op
from .base import size_of
from . import image


@dataclass(frozen=True)
class SlideDyad:
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

    def locate(self, scene, pos, sigma, x):
        s = scene.prescribed[self.point].position
        d = pos[self.q] - pos[self.p]
        n = np.hypot(d[0], d[1])
        c = pos[self.p] + s * d / n
        return {self.coincident: c, self.point: c.copy()}, np.where(
            n > 1e-12 * size_of(scene), 1.0, -1.0)

    def source(self, g) -> None:
        """:meth:`locate` as straight-line float code for the compiled evaluator
        (:mod:`polygons.compiled`): the same formula, emitted through ``g``.

        C = P + s PQ/|PQ| (the margin: |PQ| beyond 1e-12 of the mechanism's size), C1 = C."""
        (px, py), (qx, qy) = g.pos(self.p), g.pos(self.q)
        s_ = g.param(lambda s: s.prescribed[self.point].position)
        tiny = g.param(lambda s: 1e-12 * size_of(s))
        dx, dy = g.let(f"{qx} - {px}"), g.let(f"{qy} - {py}")
        n = g.let(f"hypot_p({dx}, {dy})")
        g.margin(g.let(f"where({n} > {tiny}, 1.0, -1.0)"))
        cx, cy = g.let(f"{px} + {s_} * {dx} / {n}"), g.let(f"{py} + {s_} * {dy} / {n}")
        g.place(self.coincident, cx, cy)
        g.place(self.point, cx, cy)

    def why_not(self, scene, pos) -> str:
        return (f"{self.p} and {self.q} coincide, so the direction of {self.link} along which "
                f"{self.point} slides is undefined")

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


def matches(scene, placed):
    """Every prescribed slide whose link's ends are placed."""
    for sl in scene.prescribed.values():
        if sl.point not in placed and sl.p in placed and sl.q in placed:
            yield SlideDyad(sl.point, sl.link, sl.p, sl.q, sl.coincident)
