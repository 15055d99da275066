"""The input slider: a point moving along its fixed guide at a given speed and acceleration.

Position: X = G + s e.  Velocity: v_X = ṡ e.  Acceleration: a_X = s̈ e (given).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from .primitives import Constructed, FixedLine, Translation


@dataclass(frozen=True)
class SliderDriveDyad(Constructed):
    """The input slider ``point`` on its fixed guide."""
    point: str
    two_closures = False

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "slider driver"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.point,)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.point,)

    @property
    def needs(self) -> tuple[str, ...]:
        return ()

    @cached_property
    def construction(self) -> Translation:
        """Its position, stated once: X = G + s e along its guide.  ``locate`` and ``source`` are
        this primitive's (:mod:`polygons.dyads.primitives`)."""
        return Translation(self.point, FixedLine(self.point))

    def why_not(self, scene, pos) -> str:
        return ""

    def toggle_reason(self, scene, pos) -> str:
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        X = self.point
        x, pole, q = b.names.of(X), b.names.pole, b.q
        wheel = getattr(b.scene.model.named.get(X), "kind", None) == "wheel"
        rod = getattr(b.scene.driver, "rod_rate", None)
        say = (f"Draw the {b.what} of the wheel's centre {X} from the pole along the surface: "
               f"rolling without slipping (its contact at rest) it is "
               f"{'ω' if b.velocity else 'α'} × r." if wheel else
               f"Draw the {b.what} of the slider {X} from the pole along its guide: it follows "
               f"from the rod {rod[0]}'s given " + ("ω (the relative velocity of its ends is "
                                                    "ω × the rod, ⟂ to it)." if b.velocity else
                                                    "ω and α (the relative acceleration of its "
                                                    "ends is α × the rod ⟂ to it, and ω² × the "
                                                    "rod along it).") if rod else
               f"Draw the given {b.what} of the slider {X} from the pole along its guide.")
        b.add(Kind.VECTOR, Op.SLIDER_DRIVE, (X,), f"{pole}{x}", pole, x, "input",
              f"{q}_{X}", f"{q}_{X} (given, along the guide)", say,
              component=Component.GIVEN)


def driver(scene):
    from ..scene import SliderDrive
    drv = scene.driver
    return SliderDriveDyad(drv.point) if isinstance(drv, SliderDrive) else None
