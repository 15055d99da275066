"""Crossing slots: a pin P slides in the straight slots of two moving levers at once (lever 1
AQ turning about A, lever 2 BR about B, each placed first by the rest of the mechanism).

Position: P is where the two slot lines cross, P = A + t e₁ with
t = ((B − A) × e₂) / (e₁ × e₂), e₁ = AQ/|AQ|, e₂ = BR/|BR|; the levers' points under the pin,
P1 and P2, coincide with it.  The margin is |e₁ × e₂|, the sine of the angle between the
slots (parallel slots: the pin is not fixed).

Velocity: v_P = v_P1 + (v_P)_P1 = v_P2 + (v_P)_P2, the sliding velocities along the slots:
the line ∥ slot 1 through p1 meets the line ∥ slot 2 through p2 at p (p1, p2 the images of the
levers' points under the pin).

Acceleration: a_P = a_P1 + 2 ω₁ × (v_P)_P1 + (a_P)_P1 = a_P2 + 2 ω₂ × (v_P)_P2 + (a_P)_P2:
from p1′ the Coriolis 2ω₁v₁ to k1 and a line ∥ slot 1 through it; from p2′ the Coriolis
2ω₂v₂ to k2 and a line ∥ slot 2; they meet at p′.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..steps import Builder, Component, Kind, Op
from . import image


@dataclass(frozen=True)
class Crossing:
    """Pin ``x`` in the slots of ``lever1`` (``a1`` → ``q1``) and ``lever2`` (``a2`` →
    ``q2``); ``under1``, ``under2`` the levers' points under the pin."""
    x: str
    lever1: str
    a1: str
    q1: str
    under1: str
    lever2: str
    a2: str
    q2: str
    under2: str
    two_closures = False

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x, self.under1, self.under2)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.a1, self.q1, self.a2, self.q2)

    def locate(self, scene, pos, sigma, x):
        """P = A + t e₁, t = ((B − A) × e₂) / (e₁ × e₂); margin |e₁ × e₂| (−1 where the
        slots are parallel, P NaN there)."""
        a, b = pos[self.a1], pos[self.a2]
        d1, d2 = pos[self.q1] - a, pos[self.q2] - b
        e1 = d1 / np.hypot(d1[0], d1[1])
        e2 = d2 / np.hypot(d2[0], d2[1])
        den = e1[0] * e2[1] - e1[1] * e2[0]
        ok = np.abs(den) > 1e-12
        w = b - a
        t = (w[0] * e2[1] - w[1] * e2[0]) / np.where(ok, den, np.nan)
        X = a + t * e1
        margin = np.where(ok, np.abs(den), -1.0)
        return {self.x: X, self.under1: X.copy(), self.under2: X.copy()}, margin

    def source(self, g) -> None:
        """:meth:`locate` as straight-line code (floats or arrays), the same formula."""
        (ax, ay), (qx, qy) = g.pos(self.a1), g.pos(self.q1)
        (bx, by), (rx, ry) = g.pos(self.a2), g.pos(self.q2)
        d1x, d1y = g.let(f"{qx} - {ax}"), g.let(f"{qy} - {ay}")
        d2x, d2y = g.let(f"{rx} - {bx}"), g.let(f"{ry} - {by}")
        n1, n2 = g.let(f"hypot_p({d1x}, {d1y})"), g.let(f"hypot_p({d2x}, {d2y})")
        e1x, e1y = g.let(f"{d1x} / {n1}"), g.let(f"{d1y} / {n1}")
        e2x, e2y = g.let(f"{d2x} / {n2}"), g.let(f"{d2y} / {n2}")
        den = g.let(f"{e1x} * {e2y} - {e1y} * {e2x}")
        if g.arrays:
            safe = g.let(f"where(abs({den}) > 1e-12, {den}, nan)")
            g.margin(g.let(f"where(abs({den}) > 1e-12, abs({den}), -1.0)"))
        else:
            safe = g.let(f"({den} if abs({den}) > 1e-12 else nan)")
            g.margin(g.let(f"(abs({den}) if abs({den}) > 1e-12 else -1.0)"))
        wx, wy = g.let(f"{bx} - {ax}"), g.let(f"{by} - {ay}")
        t = g.let(f"({wx} * {e2y} - {wy} * {e2x}) / {safe}")
        x, y = g.let(f"{ax} + {t} * {e1x}"), g.let(f"{ay} + {t} * {e1y}")
        for lab in self.placed:
            g.place(lab, x, y)

    def why_not(self, scene, pos) -> str:
        return (f"the slots of {self.lever1} and {self.lever2} are parallel at this instant, "
                f"so they do not fix the pin {self.x}")

    def toggle_reason(self, scene, pos) -> str:
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        X = self.x
        V = b.names.of
        x = V(X)
        C = Component
        slots = ((self.lever1, self.a1, self.q1, self.under1),
                 (self.lever2, self.a2, self.q2, self.under2))
        lines, ks = [], []
        for lev, A, Q, U in slots:
            image.emit_image(b, U, lev, A, Q)
            u = V(U)
            if b.velocity:
                lines.append(b.add(
                    Kind.LINE, Op.LINE_SLIDE, (X, U), f"slot line ∥ {A}{Q}", u, None,
                    "sliding", f"(v_{X})_{U}", f"(v_{X})_{U} ∥ {A}{Q}",
                    f"Through {u} draw a line parallel to the slot of {lev}: the velocity of "
                    f"{X} sliding relative to {U}, of unknown length.",
                    component=C.SLIDING, relative=(X, U)))
                continue
            k = b.fresh(U, dash=True)
            ks.append(k)
            b.add(Kind.VECTOR, Op.CORIOLIS, (X, U), f"{u}{k}", u, k, "coriolis", "a_cor",
                  f"a_cor = 2 ω_{lev} × (v_{X})_{U}",
                  f"From {u} draw the Coriolis acceleration 2ω_{lev}v, the sliding velocity "
                  f"in the slot of {lev} turned through 90° in the sense of ω_{lev}; call "
                  f"its end {k}.", component=C.CORIOLIS, link=lev)
            lines.append(b.add(
                Kind.LINE, Op.LINE_SLIDE, (X, U), f"slot line ∥ {A}{Q}", k, None, "sliding",
                f"(a_{X})_{U}^slide", f"(a_{X})_{U} ∥ {A}{Q}",
                f"Through {k} draw a line parallel to the slot of {lev}: the sliding "
                f"acceleration of {X} relative to {U} lies on it.",
                component=C.SLIDING, relative=(X, U)))
        what = "velocity" if b.velocity else "acceleration"
        b.add(Kind.INTERSECTION, Op.INTERSECT, (), x, None, x, "intersection",
              f"{b.q}_{X}", f"{x} = intersection of the two slot lines",
              f"The lines meet at {x}: {b.names.pole}{x} is the {what} of {X}.",
              tuple(lines), component=C.RESULTANT)
        for i, (lev, A, Q, U) in enumerate(slots):
            u = V(U)
            if b.velocity:
                b.add(Kind.MEASURE, Op.SLIDE_VELOCITY, (X, U), "v_slide", None, None,
                      "sliding", f"(v_{X})_{U}", f"(v_{X})_{U} = {u}{x}",
                      f"The sliding velocity of {X} in the slot of {lev} is {u}{x} "
                      f"(positive from {A} towards {Q}).", component=C.SLIDING)
                continue
            k = ks[i]
            b.add(Kind.MEASURE, Op.SLIDE_ACCELERATION, (X, U), "a_slide", None, None,
                  "sliding", f"(a_{X})_{U}", f"(a_{X})_{U} = {k}{x}",
                  f"The sliding acceleration of {X} in the slot of {lev} is {k}{x} "
                  f"(positive from {A} towards {Q}).", component=C.SLIDING)


def claims(scene, x) -> bool:
    """A pin declared in [crossing]."""
    return x in getattr(scene, "crossing", {})


def match(scene, x, placed, known):
    """Both slotted levers placed (their ends)."""
    cr = scene.crossing[x]
    ends = [(scene.links[lev].a, scene.links[lev].b) for lev in cr.levers]
    if not all(p in placed for e in ends for p in e):
        return None
    (a1, q1), (a2, q2) = ends
    return Crossing(x, cr.levers[0], a1, q1, cr.coincident[0], cr.levers[1], a2, q2,
                    cr.coincident[1])
