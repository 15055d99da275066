"""A pin on the rim of a driven wheel rolling without slipping on a fixed straight surface
([driver] wheel = "W", [rolling.W] rim = { B = "150 deg" }, B the end of a link).

The wheel turns at ω = −(v_W · e)/r, α = −(a_W · e)/r (its contact at rest; e along the
surface; W, the input, moves on the equivalent guide ∥ the surface), so its point B is the
image of the rigid wheel about W:

    Position: B = W + ρ (cos φ, sin φ), φ = φ₀ − s/r as the wheel rolls a distance s from
    where the scene states it (the input's position 0: contacts.rewrite).
    Velocity: v_B = v_W + ω × WB.   Acceleration: a_B = a_W + α × WB − ω² WB.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from .primitives import Constructed, RimPoint, WheelRim


def _wheel(scene, pin):
    """(the rolling entry, its angle φ₀, distance ρ) of the driven wheel carrying ``pin``."""
    for q in scene.equivalents:
        if q.kind == "rolling" and q.driven:
            for label, angle, dist in q.rim:
                if label == pin:
                    return q, angle, dist
    return None


@dataclass(frozen=True)
class WheelPin(Constructed):
    """Point ``x`` on the rim of the driven wheel centred at ``w``."""
    x: str
    w: str
    two_closures = False

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.w,)

    @cached_property
    def construction(self) -> RimPoint:
        """Its position, stated once: X = W + ρ (cos φ, sin φ), φ = φ₀ − s/r.
        ``locate`` and ``source`` are this primitive's (:mod:`polygons.dyads.primitives`)."""
        return RimPoint(self.x, self.w, WheelRim(self.x))

    def why_not(self, scene, pos) -> str:
        return ""

    def toggle_reason(self, scene, pos) -> str:
        return ""

    def emit(self, b: Builder) -> None:
        W, X = self.w, self.x
        w, x = b.names.of(W), b.names.of(X)
        if not any(st.op in (Op.ROLL_OMEGA, Op.ROLL_ALPHA) and st.args[0] == W
                   for st in b.steps):            # the wheel's rate, once a diagram
            sym, op = ("ω", Op.ROLL_OMEGA) if b.velocity else ("α", Op.ROLL_ALPHA)
            b.add(Kind.MEASURE, op, (W, W), f"{sym}_{W}", None, None,
                  "angular_velocity" if b.velocity else "angular_acceleration",
                  f"{sym}_{W}", f"{sym}_{W} = {b.names.pole}{w} / r",
                  f"The wheel {W} rolls without slipping on the fixed surface: its contact is "
                  f"at rest, so it turns at the {b.what} of its centre divided by its radius "
                  f"(clockwise when the centre moves along the surface's direction).",
                  component=Component.RELATIVE if b.velocity else Component.TANGENTIAL,
                  link=W, reads=f"{b.names.pole}{w}")
        formula = (f"{x} = {w} + ω_{W} × {W}{X}" if b.velocity
                   else f"{x} = {w} + α_{W} × {W}{X} − ω_{W}² {W}{X}")
        b.add(Kind.IMAGE, Op.IMAGE, (W, W, W, X), f"{w}{x}", w, x, "image", f"{b.q}_{X}",
              formula,
              f"{X} is a point of the wheel {W}: {w}{x} = ({'ω' if b.velocity else 'α'} of the "
              f"wheel) × {W}{X}" + ("" if b.velocity else f" − ω² {W}{X}") + ", from w.",
              component=Component.IMAGE, link=W)


def claims(scene, x) -> bool:
    """A rim point of a driven wheel."""
    return _wheel(scene, x) is not None


def match(scene, x, placed, known):
    found = _wheel(scene, x)
    if found is None or found[0].at not in placed:
        return None
    return WheelPin(x, found[0].at)
