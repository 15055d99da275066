"""The typed primitives a group's position is constructed from, each stated once.

A group declares its construction (``construction``: one primitive over typed operands) and
:class:`Constructed` makes both of its position methods from it:

* ``locate(scene, pos, sigma, x)`` — numpy, the staged solve and the sweeps (one position
  of shape (2,) or a whole sweep (2, N));
* ``source(g)`` — the generated program (:mod:`polygons.codegen`), the same formula over the
  program's typed names.

The operands say where each number comes from: a placed point (a label), a link's stated
length (:class:`Length`), a fixed guide (:class:`FixedLine`), the driver's input.  The
primitives:

* :class:`CircleCircle` — |PX| = r₁, |QX| = r₂, closure σ (RRR);
* :class:`CircleLine` — |PX| = r, X on a fixed line, closure σ (RRP);
* :class:`Rotation` — X = P + r (cos θ, sin θ), θ the input (the crank);
* :class:`Translation` — X = G + s e, s the input (the slider driver);
* :class:`LineLine` — X = G + t e on a fixed line where the line through A along f meets it,
  t = ((A − G) × f) / (e × f) (the Scotch yoke);
* :class:`RigidImage` — X = P + a u + l perp(u), u = PQ/|PQ|, a = along + fraction |PQ| (a
  point rigid with a link).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..theorems import perp
from .base import as_col, circle_circle, circle_circle_scalar, circle_line, circle_line_scalar


# ---------------------------------------------------------------- operands
@dataclass(frozen=True)
class Length:
    """The stated length of the link ``link`` ([links])."""
    link: str

    def value(self, scene):
        return scene.links[self.link].length

    def param(self, g):
        return g.param(lambda s: s.links[self.link].length)


@dataclass(frozen=True)
class FixedLine:
    """The fixed guide of the slider ``label`` ([sliders]): through G along the unit e; its
    ``slot`` (a yoke's slot direction f) when asked."""
    label: str

    def through(self, scene):
        return scene.sliders[self.label].through

    def direction(self, scene):
        return scene.sliders[self.label].direction

    def slot(self, scene):
        return scene.sliders[self.label].slot_direction

    def params(self, g, attr: str) -> tuple:
        """The (x, y) parameters of ``attr`` ('through', 'direction', 'slot_direction')."""
        return tuple(g.param(lambda s, i=i: getattr(s.sliders[self.label], attr)[i])
                     for i in (0, 1))


# ---------------------------------------------------------------- primitives
@dataclass(frozen=True)
class CircleCircle:
    """X with |PX| = r₁ and |QX| = r₂, left of P→Q for σ = +1 (right for −1):
    X = P + a u + σ h perp(u), a = (r₁² − r₂² + d²)/2d, h = √(r₁² − a²)
    (:func:`~polygons.dyads.base.circle_circle`)."""
    x: str
    p: str
    r1: Length
    q: str
    r2: Length

    def locate(self, scene, pos, sigma, x):
        X, margin = circle_circle(pos[self.p], self.r1.value(scene), pos[self.q],
                                  self.r2.value(scene), sigma)
        return {self.x: X}, margin

    def source(self, g) -> None:
        r1, r2 = self.r1.param(g), self.r2.param(g)
        x, y, m = g.call(circle_circle_scalar, *g.pos(self.p), r1, *g.pos(self.q), r2,
                         g.sigma(self.x), n=3)
        g.margin(m)
        g.place(self.x, x, y)


@dataclass(frozen=True)
class CircleLine:
    """X on the fixed line G + t e with |PX| = r, (X − P)·e of sign σ:
    t = −b + σ √(b² − c), b = e·(G − P), c = |G − P|² − r²
    (:func:`~polygons.dyads.base.circle_line`)."""
    x: str
    p: str
    r: Length
    line: FixedLine

    def locate(self, scene, pos, sigma, x):
        X, margin = circle_line(pos[self.p], self.r.value(scene), self.line.through(scene),
                                self.line.direction(scene), sigma)
        return {self.x: X}, margin

    def source(self, g) -> None:
        L = self.r.param(g)
        gx, gy = self.line.params(g, "through")
        ex, ey = self.line.params(g, "direction")
        x, y, m = g.call(circle_line_scalar, *g.pos(self.p), L, gx, gy, ex, ey,
                         g.sigma(self.x), n=3)
        g.margin(m)
        g.place(self.x, x, y)


@dataclass(frozen=True)
class Rotation:
    """X = P + r (cos θ, sin θ), θ the driver's input (a crank about its fixed pivot)."""
    x: str
    p: str
    r: Length

    def locate(self, scene, pos, sigma, x):
        r = self.r.value(scene)
        p = pos[self.p]
        if np.ndim(x) == 0:
            tip = p + r * np.array([math.cos(x), math.sin(x)])
        else:
            tip = p + r * np.array([np.cos(x), np.sin(x)])
        return {self.x: tip}, None

    def source(self, g) -> None:
        r = self.r.param(g)
        px, py = g.pos(self.p)
        c, s_ = g.let("cos({})", g.x), g.let("sin({})", g.x)
        g.place(self.x, g.let("{} + {} * {}", px, r, c), g.let("{} + {} * {}", py, r, s_))


@dataclass(frozen=True)
class Translation:
    """X = G + s e, s the driver's input (a slider driven along its fixed guide)."""
    x: str
    line: FixedLine

    def locate(self, scene, pos, sigma, x):
        through = np.array(self.line.through(scene))
        e = np.array(self.line.direction(scene))
        if np.ndim(x) == 0:
            return {self.x: through + x * e}, None
        return {self.x: as_col(through, x[None]) + x * as_col(e, x[None])}, None

    def source(self, g) -> None:
        tx, ty = self.line.params(g, "through")
        ex, ey = self.line.params(g, "direction")
        g.place(self.x, g.let("{} + {} * {}", tx, g.x, ex), g.let("{} + {} * {}", ty, g.x, ey))


@dataclass(frozen=True)
class LineLine:
    """X = G + t e on the fixed line where the line through the placed A along the yoke's
    slot f meets it: t = ((A − G) × f) / (e × f); the margin |e × f| (0: parallel)."""
    x: str
    a: str
    line: FixedLine

    def locate(self, scene, pos, sigma, x):
        a = pos[self.a]
        e, f = np.array(self.line.direction(scene)), np.array(self.line.slot(scene))
        through = as_col(self.line.through(scene), a)
        den = e[0] * f[1] - e[1] * f[0]
        w = a - through
        t = (w[0] * f[1] - w[1] * f[0]) / den
        return {self.x: through + t * as_col(e, a)}, abs(den) + 0.0 * t

    def source(self, g) -> None:
        ex, ey = self.line.params(g, "direction")
        fx, fy = self.line.params(g, "slot_direction")
        tx, ty = self.line.params(g, "through")
        ax, ay = g.pos(self.a)
        den = g.let("{} * {} - {} * {}", ex, fy, ey, fx)
        g.margin(g.let("abs({})", den))
        wx, wy = g.let("{} - {}", ax, tx), g.let("{} - {}", ay, ty)
        t = g.let("({} * {} - {} * {}) / {}", wx, fy, wy, fx, den)
        g.place(self.x, g.let("{} + {} * {}", tx, t, ex), g.let("{} + {} * {}", ty, t, ey))


@dataclass(frozen=True)
class RigidImage:
    """X rigid with the link PQ ([points.X]): X = P + a u + l perp(u), u = PQ/|PQ|,
    a = along (or fraction · |PQ|), l its offset to the left; the margin +1 (−1 where
    |PQ| = 0)."""
    x: str
    p: str
    q: str

    def locate(self, scene, pos, sigma, x):
        bp = scene.points[self.x]
        d = pos[self.q] - pos[self.p]
        n = np.hypot(d[0], d[1])
        u = d / n
        along = bp.along if bp.along is not None else bp.fraction * n
        return {self.x: pos[self.p] + along * u + bp.left * perp(u)}, np.where(n > 0, 1.0, -1.0)

    def source(self, g) -> None:
        along = g.param(lambda s: s.points[self.x].along or 0.0)
        frac = g.param(lambda s: s.points[self.x].fraction
                       if s.points[self.x].along is None else 0.0)
        left = g.param(lambda s: s.points[self.x].left)
        (px, py), (qx, qy) = g.pos(self.p), g.pos(self.q)
        dx, dy = g.let("{} - {}", qx, px), g.let("{} - {}", qy, py)
        n = g.let("hypot({}, {})", dx, dy)
        g.margin(g.let("where({} > 0, 1.0, -1.0)", n))
        ux, uy = g.let("{} / {}", dx, n), g.let("{} / {}", dy, n)
        a = g.let("{} + {} * {}", along, frac, n)
        g.place(self.x, g.let("{} + {} * {} + {} * -{}", px, a, ux, left, uy),
                g.let("{} + {} * {} + {} * {}", py, a, uy, left, ux))


#: every primitive (a group's ``construction`` is one of these)
PRIMITIVES = (CircleCircle, CircleLine, Rotation, Translation, LineLine, RigidImage)


class Constructed:
    """A group whose position is its ``construction`` (a primitive): ``locate`` and
    ``source`` are that primitive's, stated once."""

    def locate(self, scene, pos, sigma, x):
        return self.construction.locate(scene, pos, sigma, x)

    def source(self, g) -> None:
        """:meth:`locate`'s formula in the generated program (:mod:`polygons.codegen`): the
        same primitive, emitted through ``g``."""
        self.construction.source(g)


__all__ = ["Length", "FixedLine", "CircleCircle", "CircleLine", "Rotation", "Translation",
           "LineLine", "RigidImage", "PRIMITIVES", "Constructed"]
