"""RPR: a placed pin A slides in the straight slot of a lever turning about pivot B (the
crank and slotted lever, the quick return).

Position: the lever's point A1 under the pin coincides with A; the lever's far end lies along
BA at its stated length.  The slot is open-ended unless ``[slots.A] length`` states how far it
runs from B (a lever's length is not its slot's: in the Whitworth motion the arm CD is shorter
than the pin's reach): the pin further out than that has left the slot, and is refused (a
sweep's limit of travel).  Velocity: v_A = v_A1 + (v_A)_A1 with v_A1 = ω × BA1 ⟂ BA and the
sliding velocity ∥ BA: the line ⟂ BA through b meets the line ∥ BA through a at a1.
Acceleration: a_A = a_A1 + (a_A)_A1 + 2 ω × (v_A)_A1: the centripetal ω² BA known, the
tangential line through its end, the sliding line ∥ BA stepped back from a by the Coriolis
2ωv; they meet at a1.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..steps import Builder, Component, Kind, Op
from .base import size_of
from . import image
from .primitives import Constructed, PinInSlot


@dataclass(frozen=True)
class RPR(Constructed):
    """Placed pin ``pin`` slides in the slot of ``lever`` turning about ``pivot``;
    places the lever's point ``coincident`` under the pin and its far end ``far``; ``offset``
    when the slot runs parallel to the lever, off its pivot."""
    pin: str
    lever: str
    pivot: str
    coincident: str
    far: str | None
    offset: bool = False
    two_closures = False

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "RPR"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.lever,)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.coincident,) + ((self.far,) if self.far else ())

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pin, self.pivot)

    @cached_property
    def construction(self) -> PinInSlot:
        """Its position, stated once: the lever's point A1 = A, its far end along the slot at
        its stated length.  ``locate`` and ``source`` are this primitive's
        (:mod:`polygons.dyads.primitives`)."""
        return PinInSlot(self.coincident, self.pin, self.pivot, self.far)

    def why_not(self, scene, pos) -> str:
        slot = scene.slots[self.pin]
        off = slot.offset
        d = np.asarray(pos[self.pin], dtype=float) - np.asarray(pos[self.pivot], dtype=float)
        s = float(np.hypot(d[0], d[1]))
        t = math.sqrt(max(s * s - off * off, 0.0))
        if slot.length is not None and t > slot.length and s > abs(off):
            where = f"{t * 1e3:.6g} mm along the slot" if off else f"{t * 1e3:.6g} mm"
            return (f"the pin {self.pin} at {where} from the pivot {self.pivot} is beyond the "
                    f"end of the slot in lever {self.lever} ({slot.length * 1e3:.6g} mm long): "
                    f"it has left the slot")
        if off:
            return (f"the pin {self.pin} is within the slot's offset {1e3 * abs(off):.6g} mm "
                    f"of the pivot {self.pivot}: the slot of lever {self.lever} cannot pass "
                    f"through it")
        return (f"the pin {self.pin} is on the pivot {self.pivot} of lever {self.lever}: the "
                f"slot direction is undefined")

    def toggle_reason(self, scene, pos) -> str:
        slot = scene.slots[self.pin]
        if slot.length is not None:
            d = np.asarray(pos[self.pin], dtype=float) - np.asarray(pos[self.pivot], dtype=float)
            t = math.sqrt(max(float(d @ d) - slot.offset ** 2, 0.0))
            if abs(t - slot.length) <= 1e-9 * size_of(scene):
                return (f"the pin {self.pin} reaches the end of the slot in lever {self.lever}, "
                        f"{slot.length * 1e3:.6g} mm from the pivot {self.pivot}: its travel "
                        f"in the slot stops there")
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        A, B, A1, lev = self.pin, self.pivot, self.coincident, self.lever
        V = b.names.of
        a, b_, a1 = V(A), V(B), V(A1)
        C = Component
        if b.velocity:
            n1 = b.add(Kind.LINE, Op.LINE_PERP, (B, A1), f"line ⟂ {B}{A1}", b_, None,
                       "relative_velocity", f"v_{A1}", f"v_{A1} = ω_{lev} × {B}{A1} ⟂ {B}{A1}",
                       f"Through {b_} draw a line perpendicular to the lever {B}{A1}: the "
                       f"velocity of {A1}, the point of the lever under the pin.",
                       component=C.RELATIVE, link=lev, relative=(A1, B))
            if self.offset:     # the slot runs parallel to the lever, off B
                F = self.far
                n2 = b.add(Kind.LINE, Op.LINE_SLIDE, (A,), f"slot line ∥ {B}{F}", a, None,
                           "sliding", f"(v_{A})_{A1}", f"(v_{A})_{A1} ∥ {B}{F}",
                           f"Through {a} draw a line parallel to the slot (parallel to "
                           f"{B}{F}, offset from {B}): the velocity of {A} sliding relative "
                           f"to {A1}.", component=C.SLIDING, relative=(A, A1))
            else:
                n2 = b.add(Kind.LINE, Op.LINE_ALONG, (B, A1), f"slot line ∥ {B}{A1}", a, None,
                           "sliding", f"(v_{A})_{A1}", f"(v_{A})_{A1} ∥ {B}{A1}",
                           f"Through {a} draw a line parallel to the slot {B}{A1}: the "
                           f"velocity of {A} sliding relative to {A1}.",
                           component=C.SLIDING, relative=(A, A1))
            b.add(Kind.INTERSECTION, Op.INTERSECT, (), a1, None, a1, "intersection",
                  f"v_{A1}", f"{a1} = intersection of the two lines",
                  f"They meet at {a1}: {b_}{a1} is the velocity of {A1} and {a1}{a} the "
                  f"sliding velocity.", (n1, n2), component=C.RESULTANT)
            b.add(Kind.MEASURE, Op.OMEGA, (lev, B, A1), f"ω_{lev}", None, None,
                  "angular_velocity", f"ω_{lev}", f"ω_{lev} = {b_}{a1} / {B}{A1}",
                  f"The lever turns at the velocity of {A1} divided by {B}{A1}.",
                  component=C.RELATIVE, link=lev, reads=f"{b_}{a1}")
            b.add(Kind.MEASURE, Op.SLIDE_VELOCITY, (A,), "v_slide", None, None, "sliding",
                  f"(v_{A})_{A1}", f"(v_{A})_{A1} = {a1}{a}",
                  f"The sliding velocity of {A} along the slot is {a1}{a} (positive away "
                  f"from {B}).", component=C.SLIDING)
        else:
            k1 = b.fresh(A1)
            bn = b.names.named(B)          # o₄p₄′ about O4 where the pole is o₂ = o₄
            b.add(Kind.VECTOR, Op.CENTRIPETAL, (lev, B, A1), f"{bn}{k1}", b_, k1,
                  "centripetal", f"(a_{A1})_{B}^n", f"(a_{A1})_{B}^n = ω_{lev}² × {B}{A1}",
                  f"From {bn} draw the centripetal acceleration of {A1} about {B}, ω² × "
                  f"{B}{A1}, pointing towards {B}; call its end {k1}.",
                  component=C.CENTRIPETAL, link=lev)
            n1 = b.add(Kind.LINE, Op.LINE_PERP, (B, A1), f"line ⟂ {B}{A1}", k1, None,
                       "tangential",
                       f"(a_{A1})_{B}^t", f"(a_{A1})_{B}^t = α_{lev} × {B}{A1} ⟂ {B}{A1}",
                       f"Through {k1} draw a line perpendicular to {B}{A1} for the tangential "
                       f"acceleration of {A1}, of unknown length.", component=C.TANGENTIAL,
                       link=lev, relative=(A1, B))
            n2 = b.add(Kind.LINE, Op.CORIOLIS_OFFSET_LINE, (A,), "Coriolis offset line", a,
                       None, "coriolis", "2ω×v", f"2 ω_{lev} v = 2 × ω_{lev} × (v_{A})_{A1}",
                       f"The Coriolis acceleration 2ωv is known (ω × v turns v through 90° "
                       f"in the sense of ω). Step back from {a} by it and through that point "
                       f"draw a line parallel to the slot: the sliding acceleration lies on "
                       f"it.", component=C.CORIOLIS, link=lev, relative=(A, A1))
            b.add(Kind.INTERSECTION, Op.INTERSECT, (), a1, None, a1, "intersection",
                  f"a_{A1}", f"{a1} = intersection of the two lines",
                  f"The lines meet at {a1}: {b_}{a1} is the acceleration of {A1}.", (n1, n2),
                  component=C.RESULTANT)
            k2 = b.fresh(A, dash=True)
            b.add(Kind.VECTOR, Op.CORIOLIS, (A,), f"{a1}{k2}", a1, k2, "coriolis",
                  "a_cor", f"a_cor = 2 ω_{lev} × (v_{A})_{A1}",
                  f"From {a1} the Coriolis acceleration 2ωv, perpendicular to the slot, to "
                  f"{k2}.", component=C.CORIOLIS, link=lev)
            b.add(Kind.VECTOR, Op.JOIN, (A,), f"{k2}{a}", k2, a, "sliding",
                  f"(a_{A})_{A1}^slide", f"(a_{A})_{A1} = {k2}{a} ∥ {B}{A1}",
                  f"{k2}{a}, along the slot, is the sliding acceleration of {A} relative to "
                  f"the lever.", component=C.SLIDING)
            b.add(Kind.MEASURE, Op.ALPHA, (lev, B, A1), f"α_{lev}", None, None,
                  "angular_acceleration", f"α_{lev}", f"α_{lev} = {k1}{a1} / {B}{A1}",
                  f"The lever's angular acceleration is its tangential acceleration "
                  f"{k1}{a1} divided by {B}{A1}.", component=C.TANGENTIAL, link=lev,
                  reads=f"{k1}{a1}")
            b.add(Kind.MEASURE, Op.SLIDE_ACCELERATION, (A,), "a_slide", None, None, "sliding",
                  f"(a_{A})_{A1}", f"(a_{A})_{A1} = {k2}{a}",
                  f"The sliding acceleration of {A} is {k2}{a} (positive away from {B}).",
                  component=C.SLIDING)
        if self.far:
            image.emit_image(b, self.far, lev, B, A1)


def matches(scene, placed):
    """Every slot whose pin is placed and whose lever point is not yet."""
    for slot in scene.slots.values():
        if slot.coincident not in placed and slot.pin in placed and slot.pivot in placed:
            yield RPR(slot.pin, slot.lever, slot.pivot, slot.coincident, slot.far,
                      bool(slot.offset))
