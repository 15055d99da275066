"""The input crank: its tip turns about a fixed pivot at the given ω and α.

Position: X = P + r (cos θ, sin θ).  Velocity: (v_X)_P = ω × PX.  Acceleration:
(a_X)_P = −ω² PX (+ α × PX when the crank accelerates).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from .primitives import Constructed, Length, Rotation


@dataclass(frozen=True)
class CrankDyad(Constructed):
    """The input crank ``link``: ``tip`` turns about fixed ``pivot``; ``tangential`` when the
    crank has an angular acceleration (its tangential component is drawn)."""
    link: str
    pivot: str
    tip: str
    tangential: bool = False
    two_closures = False

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "crank"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.link,)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.tip,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pivot,)

    @cached_property
    def construction(self) -> Rotation:
        """Its position, stated once: the tip X = P + r (cos θ, sin θ).  ``locate`` and ``source`` are
        this primitive's (:mod:`polygons.dyads.primitives`)."""
        return Rotation(self.tip, self.pivot, Length(self.link))

    def why_not(self, scene, pos) -> str:
        return ""

    def toggle_reason(self, scene, pos) -> str:
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        P, X, L = self.pivot, self.tip, self.link
        p, x = b.names.of(P), b.names.of(X)
        # the driver named for what it is: a driven link that carries a slot (the oscillating
        # cylinder O4Q) is no crank
        slotted = any(sl.lever == L for sl in getattr(b.scene, "slots", {}).values())
        what = f"the driving link {L}" if slotted else "the crank"
        if b.velocity:
            b.add(Kind.VECTOR, Op.CRANK_VELOCITY, (L, P, X), f"{p}{x}", p, x,
                  "relative_velocity", f"(v_{X})_{P}", f"(v_{X})_{P} = ω_{L} × {P}{X}",
                  f"Draw {p}{x} = ω × {P}{X} perpendicular to {P}{X}, in the sense of rotation "
                  f"of {what}, starting at the pole {b.names.alias()} (fixed points have "
                  f"no velocity).", component=Component.GIVEN, link=L)
            return
        has_t = self.tangential
        x1 = b.fresh(X) if has_t else x
        b.add(Kind.VECTOR, Op.CENTRIPETAL, (L, P, X), f"{p}{x1}", p, x1, "centripetal",
              f"(a_{X})_{P}^n", f"(a_{X})_{P}^n = ω_{L}² × {P}{X}",
              f"Draw the centripetal acceleration of {X} about {P}, ω² × {P}{X}, from {p} "
              f"parallel to {X}{P}, pointing from {X} towards {P}."
              + ("" if has_t else f" {what[0].upper()}{what[1:]} has no angular "
                                  f"acceleration, so this ends at {x}."),
              component=Component.CENTRIPETAL, link=L)
        if has_t:
            b.add(Kind.VECTOR, Op.CRANK_TANGENTIAL, (L, P, X), f"{x1}{x}", x1, x,
                  "tangential", f"(a_{X})_{P}^t", f"(a_{X})_{P}^t = α_{L} × {P}{X}",
                  f"Add the tangential acceleration α × {P}{X} from {x1}, perpendicular to "
                  f"{P}{X} in the sense of α; it ends at {x}.", component=Component.TANGENTIAL,
                  link=L)


def scene_alpha(scene) -> float:
    return getattr(scene.driver, "alpha", 0.0)


def driver(scene):
    """The crank dyad when the scene is driven by a crank, else None."""
    from ..scene import Crank
    drv = scene.driver
    if not isinstance(drv, Crank):
        return None
    return CrankDyad(drv.link, drv.pivot, drv.tip, scene_alpha(scene) != 0.0)
