"""RRP on a moving guide: the pin X on a link of known length from a placed point P slides in
the slot of a lever placed first — driven (the inverted slider-crank driven by its guide: the
oscillating-cylinder engine, the rotary engine — the cylinder turns at a given ω and the
piston's crank-pin is on a driven crank) or placed by its own links (a guide carried by a
moving link).

Position: X on the circle |PX| = L and on the slot line B + d n + t e (e along the lever
B → Q, n = perp(e), d the slot's offset): two closures.  The slot is open-ended: the pin of
an oscillating cylinder is at the end of its piston rod, beyond the cylinder's end, so a
lever's length does not bound it; a stated ``[slots.X] length`` is refused, not yet modelled
here.  The lever's point X1 under the pin is at the same place.  Velocity: v_X = v_X1 + ṡ e = v_P + ω × PX: from p, x1 (the lever's image)
is known; the line ∥ the slot through x1 meets the line ⟂ PX through p at x.  Acceleration:
a_X = a_X1 + s̈ e + 2 ω_lever × ṡ e = a_P − ω² PX + α × PX: x1, then the Coriolis 2ωṡ from it
and a line ∥ the slot through its end; the centripetal ω² PX from p and a line ⟂ PX through
its end; the lines meet at x.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from ..topology import guided_pin
from . import image
from .primitives import Constructed, CircleLine, Guarded, Length, LeverLine, SlotUnstated


@dataclass(frozen=True)
class Guided(Constructed):
    """Pin ``x`` joined by ``link`` to placed ``p``, sliding in the slot of the placed lever
    ``lever`` (pivot ``pivot``, far end ``far``); also places the lever point ``coincident``."""
    p: str
    x: str
    link: str
    lever: str
    pivot: str
    far: str
    coincident: str
    two_closures = True

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "RRP, moving guide"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.link,)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x, self.coincident)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p, self.pivot, self.far)

    @property
    def default_ref(self) -> tuple[str, ...]:
        return (self.p, self.pivot)

    @cached_property
    def construction(self) -> Guarded:
        """Its position, stated once: X on the circle |PX| = L and the lever's slot (closure σ), X1 = X; a stated slot length refused.
        ``locate`` and ``source`` are this primitive's (:mod:`polygons.dyads.primitives`)."""
        return Guarded(CircleLine(self.x, self.p, Length(self.link),
                                  LeverLine(self.x, self.pivot, self.far),
                                  also=(self.coincident,)),
                       SlotUnstated(self.x))

    def why_not(self, scene, pos) -> str:
        from ..theorems import cross
        length = scene.slots[self.x].length
        if length is not None:
            return (f"[slots.{self.x}] length = {1e3 * length:.6g} mm is not checked for a pin "
                    f"found in the slot of a lever placed first (of its two closures the "
                    f"assembly would have to test the one chosen): remove it, the slot of "
                    f"{self.lever} is then open-ended (a cylinder's piston rod reaches beyond "
                    f"its end)")
        through, e = self.construction.inner.line.at(scene, pos)
        L = scene.links[self.link].length
        dist = abs(float(cross(e, pos[self.p] - through)))
        if dist > L:
            return (f"the links cannot close at this input: {self.link} = {1e3 * L:.6g} mm "
                    f"cannot reach the slot of {self.lever}, which is {1e3 * dist:.6g} mm "
                    f"from {self.p}")
        return self.toggle_reason(scene, pos)

    def toggle_reason(self, scene, pos) -> str:
        return (f"{self.link} is perpendicular to the slot of {self.lever} (it reaches the "
                f"slot no further)")

    def emit(self, b: Builder) -> None:
        P, X, L, lev, X1 = self.p, self.x, self.link, self.lever, self.coincident
        B, Q = self.pivot, self.far
        V = b.names.of
        p, x, x1 = V(P), V(X), V(X1)
        C = Component
        image.emit_image(b, X1, lev, B, Q)
        if b.velocity:
            n1 = b.add(Kind.LINE, Op.LINE_SLIDE, (X,), f"slot line ∥ {B}{Q}", x1, None,
                       "sliding", f"(v_{X})_{X1}", f"(v_{X})_{X1} ∥ {B}{Q}",
                       f"Through {x1} draw a line parallel to the slot of {lev}: the velocity "
                       f"of {X} sliding relative to {X1}.", component=C.SLIDING)
            n2 = b.add(Kind.LINE, Op.LINE_PERP, (P, X), f"line ⟂ {P}{X}", p, None,
                       "relative_velocity", f"(v_{X})_{P}", f"(v_{X})_{P} ⟂ {P}{X}",
                       f"Through {p} draw a line perpendicular to {P}{X}: the velocity of {X} "
                       f"relative to {P}, of unknown length.", component=C.RELATIVE,
                       link=L)
            b.add(Kind.INTERSECTION, Op.INTERSECT, (), x, None, x, "intersection", f"v_{X}",
                  f"{x} = intersection of the two lines",
                  f"The lines meet at {x}: {b.names.pole}{x} is the velocity of {X} and "
                  f"{x1}{x} its sliding velocity in the slot.", (n1, n2),
                  component=C.RESULTANT)
            b.add(Kind.MEASURE, Op.OMEGA, (L, P, X), f"ω_{L}", None, None,
                  "angular_velocity", f"ω_{L}", f"ω_{L} = {p}{x} / {P}{X}",
                  f"The angular velocity of {L} is its relative velocity divided by its "
                  f"length.", component=C.RELATIVE, link=L)
            b.add(Kind.MEASURE, Op.SLIDE_VELOCITY, (X,), "v_slide", None, None, "sliding",
                  f"(v_{X})_{X1}", f"(v_{X})_{X1} = {x1}{x}",
                  f"The sliding velocity of {X} in the slot is {x1}{x} (positive from {B} "
                  f"towards {Q}).", component=C.SLIDING)
            return
        k1 = b.fresh(X, dash=True)
        b.add(Kind.VECTOR, Op.CORIOLIS, (X,), f"{x1}{k1}", x1, k1, "coriolis", "a_cor",
              f"a_cor = 2 ω_{lev} × (v_{X})_{X1}",
              f"From {x1} draw the Coriolis acceleration 2ωv, the sliding velocity turned "
              f"through 90° in the sense of ω_{lev}; call its end {k1}.",
              component=C.CORIOLIS, link=lev)
        n1 = b.add(Kind.LINE, Op.LINE_SLIDE, (X,), f"slot line ∥ {B}{Q}", k1, None, "sliding",
                   f"(a_{X})_{X1}^slide", f"(a_{X})_{X1} ∥ {B}{Q}",
                   f"Through {k1} draw a line parallel to the slot: the sliding acceleration "
                   f"of {X} lies on it.", component=C.SLIDING)
        x2 = b.fresh(X)
        pn = b.names.named(P)              # o₂p₁ about O2 where the pole is o₄ = o₂
        b.add(Kind.VECTOR, Op.CENTRIPETAL, (L, P, X), f"{pn}{x2}", p, x2, "centripetal",
              f"(a_{X})_{P}^n", f"(a_{X})_{P}^n = ω_{L}² × {P}{X} = v²/{P}{X}",
              f"From {pn} draw the centripetal acceleration of {X} relative to {P}, pointing "
              f"from {X} towards {P}; call its end {x2}.", component=C.CENTRIPETAL, link=L)
        n2 = b.add(Kind.LINE, Op.LINE_PERP, (P, X), f"line ⟂ {P}{X}", x2, None, "tangential",
                   f"(a_{X})_{P}^t", f"(a_{X})_{P}^t = α_{L} × {P}{X} ⟂ {P}{X}",
                   f"Through {x2} draw a line perpendicular to {P}{X} for the tangential "
                   f"acceleration, of unknown length.", component=C.TANGENTIAL, link=L)
        b.add(Kind.INTERSECTION, Op.INTERSECT, (), x, None, x, "intersection", f"a_{X}",
              f"{x} = intersection of the two lines",
              f"The lines meet at {x}: {b.names.pole}{x} is the acceleration of {X}.",
              (n1, n2), component=C.RESULTANT)
        b.add(Kind.MEASURE, Op.ALPHA, (L, P, X), f"α_{L}", None, None, "angular_acceleration",
              f"α_{L}", f"α_{L} = {x2}{x} / {P}{X}",
              f"The angular acceleration of {L} is its tangential acceleration {x2}{x} "
              f"divided by {P}{X}.", component=C.TANGENTIAL, link=L)
        b.add(Kind.MEASURE, Op.SLIDE_ACCELERATION, (X,), "a_slide", None, None, "sliding",
              f"(a_{X})_{X1}", f"(a_{X})_{X1} = {k1}{x}",
              f"The sliding acceleration of {X} is {k1}{x} (positive from {B} towards {Q}).",
              component=C.SLIDING)


def claims(scene, x) -> bool:
    """A pin on one link, in the slot of a lever placed before it (driven or by its links)."""
    slot = scene.slots.get(x)
    return slot is not None and guided_pin(scene, slot)


def match(scene, x, placed, known):
    """The pin's link to a placed point, and the lever placed (pivot and far end)."""
    slot = scene.slots[x]
    if not known or slot.far is None or slot.pivot not in placed or slot.far not in placed:
        return None
    p, link = known[0]
    return Guided(p, x, link, slot.lever, slot.pivot, slot.far, slot.coincident)
