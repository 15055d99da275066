"""Image: a point rigid with a link whose two ends are placed (a coupler point, a ternary
link's third pin, "BD is a continuation of AB").

Position: X = P + along·u + left·perp(u), u = PQ/|PQ|.  Velocity: v_X = v_P + ω × PX (the
velocity image pqx is similar to PQX).  Acceleration: a_X = a_P + α × PX − ω² PX.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from .primitives import Constructed, RigidImage


@dataclass(frozen=True)
class Image(Constructed):
    """Point ``x`` rigid with link ``link`` whose ends ``p`` and ``q`` are placed."""
    x: str
    link: str
    p: str
    q: str
    two_closures = False

    #: its force polygon: none of its own (a point on a link placed before: the loads
    #: there act on that link, in its group)
    force_polygon = None

    def force_bodies(self) -> tuple[str, ...]:
        """No body: its point rides on a link another group closes."""
        return ()

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x,)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.p, self.q)

    @cached_property
    def construction(self) -> RigidImage:
        """Its position, stated once: X = P + a u + l perp(u), rigid with the link PQ.  ``locate`` and ``source`` are
        this primitive's (:mod:`polygons.dyads.primitives`)."""
        return RigidImage(self.x, self.p, self.q)

    def why_not(self, scene, pos) -> str:
        return (f"link {self.link} has zero length at this instant, so {self.x} cannot be "
                f"placed on it")

    def toggle_reason(self, scene, pos) -> str:
        return self.why_not(scene, pos)

    def emit(self, b: Builder) -> None:
        emit_image(b, self.x, self.link, self.p, self.q)


def emit_image(b: Builder, X: str, link: str, P: str, Q: str) -> None:
    V = b.names.of
    p, q, x = V(P), V(Q), V(X)
    formula = (f"{x} = {p} + ω_{link} × {P}{X}" if b.velocity
               else f"{x} = {p} + α_{link} × {P}{X} − ω_{link}² {P}{X}")
    b.add(Kind.IMAGE, Op.IMAGE, (link, P, Q, X), f"{p}{x}", p, x, "image", f"{b.q}_{X}",
          formula,
          f"{X} is a point of the rigid link {link}: {p}{q}{x} is the {b.what} image of "
          f"{P}{Q}{X} (similar to it, turned), so {x} follows from {p} and {q}.",
          component=Component.IMAGE, link=link)


def match(scene, x, placed, known):
    """A point declared in [points] on a link (or slotted lever) whose ends are placed."""
    if x not in scene.points:
        return None
    bp = scene.points[x]
    link = scene.links.get(bp.link)
    if link is not None:
        p, q = link.a, link.b
    else:  # a point on a slotted lever
        slot = next(s for s in scene.slots.values() if s.lever == bp.link)
        p, q = slot.pivot, slot.coincident
    return Image(x, bp.link, p, q) if p in placed and q in placed else None


def claims(scene, x) -> bool:
    """Whether the scene declares ``x`` as this kind's point."""
    return x in scene.points
