"""RPP: the Scotch yoke — a placed pin slides in the straight slot of a yoke that translates
on a fixed guide (no rotation, so no Coriolis term).

Position: the yoke's point Y on the guide under the slot line through the pin:
Y = G + t e, t = ((A − G) × f) / (e × f).  Velocity and acceleration: the line along the
guide through the pole meets the line along the slot through a (or a's acceleration) at y.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from .primitives import Constructed, FixedLine, LineLine


@dataclass(frozen=True)
class RPP(Constructed):
    """Scotch yoke: placed pin ``pin`` slides in the slot of the yoke ``x`` on its guide."""
    pin: str
    x: str
    two_closures = False

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "RPP"

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (self.x,)

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pin,)

    @cached_property
    def construction(self) -> LineLine:
        """Its position, stated once: the yoke's point on its guide under the slot line through the pin.  ``locate`` and ``source`` are
        this primitive's (:mod:`polygons.dyads.primitives`)."""
        return LineLine(self.x, self.pin, FixedLine(self.x))

    def why_not(self, scene, pos) -> str:
        return f"the slot of the yoke {self.x} is parallel to its guide"

    def toggle_reason(self, scene, pos) -> str:
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        A, Y = self.pin, self.x
        V = b.names.of
        a, y, pole, q = V(A), V(Y), b.names.pole, b.q
        C = Component
        n1 = b.add(Kind.LINE, Op.LINE_GUIDE, (Y,), "slider line", pole, None, "slider_line",
                   f"{q}_{Y}", f"{q}_{Y} ∥ guide of {Y}",
                   f"Through {pole} draw a line along the guide of the yoke {Y}: the yoke "
                   f"only translates along it.", component=C.RESULTANT)
        n2 = b.add(Kind.LINE, Op.LINE_SLOT, (Y,), "slot line", a, None, "sliding",
                   f"({q}_{A})_{Y}", f"({q}_{A})_{Y} ∥ slot of {Y}",
                   f"Through {a} draw a line parallel to the yoke's slot: {A} slides along "
                   f"it relative to the yoke, which does not turn (so there is no Coriolis "
                   f"term).", component=C.SLIDING, relative=(A, Y))
        b.add(Kind.INTERSECTION, Op.INTERSECT, (), y, None, y, "intersection", f"{q}_{Y}",
              f"{y} = intersection of the two lines",
              f"They meet at {y}: {pole}{y} is the {b.what} of the yoke and {y}{a} that of "
              f"{A} sliding in the slot.", (n1, n2), component=C.RESULTANT)
        if b.velocity:
            b.add(Kind.MEASURE, Op.SLIDER_VELOCITY, (Y,), f"v_{Y}", None, None, "slider",
                  f"v_{Y} along guide", f"v_{Y} = {pole}{y}",
                  f"The yoke's velocity is {pole}{y}, along its guide.",
                  component=C.RESULTANT)
        else:
            b.add(Kind.MEASURE, Op.SLIDER_ACCELERATION, (Y,), f"a_{Y}", None, None, "slider",
                  f"a_{Y} along guide", f"a_{Y} = {pole}{y}",
                  f"The yoke's acceleration is {pole}{y}, along its guide.",
                  component=C.RESULTANT)


def match(scene, x, placed, known):
    """x is a yoke (a slider with a slot) whose pin is placed."""
    g = scene.sliders.get(x)
    if g is None or g.pin is None:
        return None
    return RPP(g.pin, x) if g.pin in placed else None


def claims(scene, x) -> bool:
    """Whether the scene declares ``x`` as this kind's point."""
    return x in scene.sliders and scene.sliders[x].pin is not None
