"""RRP: point X joined by a link to placed P and sliding on a fixed straight guide (the
slider-crank's piston).

Position: X on the guide with |PX| = L (two closures).  Velocity: v_X = v_P + ω × PX, and
v_X ∥ guide: the line ⟂ PX through p meets the slider line through the pole at x.
Acceleration: a_X = a_P − ω² PX + α × PX ∥ guide.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..steps import Builder
from . import pinned
from .primitives import Constructed, CircleLine, FixedLine, Length


@dataclass(frozen=True)
class RRP(Constructed):
    """Point ``x`` joined by ``link`` to placed ``p`` and sliding on a fixed straight guide."""
    p: str
    x: str
    link: str
    two_closures = True

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "RRP"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.link, self.x)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p,)

    @property
    def default_ref(self) -> tuple[str, ...]:
        return (self.p,)

    @cached_property
    def construction(self) -> CircleLine:
        """Its position, stated once: X on the guide with |PX| = L (closure σ).  ``locate`` and ``source`` are
        this primitive's (:mod:`polygons.dyads.primitives`)."""
        return CircleLine(self.x, self.p, Length(self.link), FixedLine(self.x))

    def why_not(self, scene, pos) -> str:
        from ..theorems import cross
        g = scene.sliders[self.x]
        L = scene.links[self.link].length
        w = np.array(g.through) - pos[self.p]
        e = np.array(g.direction)
        dist = abs(cross(e, -w))
        if dist > L:
            return (f"the links cannot close at this input: {self.link} = {1e3 * L:.6g} mm "
                    f"cannot reach the guide of {self.x}, which is {1e3 * dist:.6g} mm from "
                    f"{self.p}")
        return (f"{self.link} is perpendicular to the guide of {self.x} (it reaches the guide "
                f"no further)")

    def toggle_reason(self, scene, pos) -> str:
        return (f"{self.link} is perpendicular to the guide of {self.x} (it reaches the guide "
                f"no further)")

    def emit(self, b: Builder) -> None:
        pinned.emit_two_lines(b, self.p, self.x, self.link, other=None)


def match(scene, x, placed, known):
    """A link of known length from x to a placed point, and x on a fixed guide."""
    g = scene.sliders.get(x)
    if g is None or g.pin is not None or not known:
        return None
    return RRP(known[0][0], x, known[0][1])


def claims(scene, x) -> bool:
    """Whether the scene declares ``x`` as this kind's point."""
    return x in scene.sliders
