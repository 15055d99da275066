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
  point rigid with a link);
* :class:`LinesMeet` — where the lines A₁ → Q₁ and A₂ → Q₂ meet (a pin in two moving slots);
* :class:`AlongLink` — X = P + s PQ/|PQ|, s prescribed (a collar driven along a link);
* :class:`RimPoint` — X = W + ρ (cos φ, sin φ), φ = φ₀ − s/r (a pin on a rolling wheel);
* :class:`PinInSlot` — a slotted lever's point under its placed pin, and its far end along
  the slot (RPR; a slot offset from the pivot too);
* :class:`Guarded` — a primitive refused where a stated condition fails (a case not
  modelled, which the group's ``why_not`` names);
* :class:`TriadClosure` — the corners of a class-III group's plate (:class:`PlateShape`),
  each on a link to a placed point, the closure nearest a reference
  (:mod:`~polygons.dyads.triad_math`);
* :class:`AssurPoint` — where two links' lines produced meet (NaN where parallel);
* :class:`Then` — primitives in order (the triad: its closure, then S).

Every primitive is written once, as ``source``: its ``locate`` is that statement evaluated
(:class:`~polygons.dyads.numeric.Stated`; written down as one Python function per primitive
the first time, :class:`~polygons.dyads.numeric.Traced`), the same formulas term for term as
the generated program.  The fused kernel (:mod:`polygons.fused`) reads the primitives' typed
operands, not these statements.

A line operand is fixed (:class:`FixedLine`) or a lever's slot (:class:`LeverLine`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..theorems import perp
from .base import (as_col, circle_circle, circle_circle_scalar, circle_line, circle_line_scalar,
                   end_margin_cols, end_margin_scalar, size_of)
from .numeric import Numeric, Stated
from .triad_math import all_corners, triad_scalar
from .triad_slider_math import all_corners as all_slider_corners, triad_slider_scalar


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

    def at(self, scene, pos):
        """(G, e) for numpy."""
        return self.through(scene), self.direction(scene)

    def emit(self, g):
        """((Gx, Gy), (ex, ey)) in the generated program."""
        return self.params(g, "through"), self.params(g, "direction")


@dataclass(frozen=True)
class LeverLine:
    """The slot of a lever turning about ``pivot`` towards ``far``, ``offset`` left of the
    line pivot → far ([slots.PIN] offset, of the pin ``pin``): G = B + δ perp(e),
    e = BQ/|BQ|."""
    pin: str
    pivot: str
    far: str

    def at(self, scene, pos):
        d = pos[self.far] - pos[self.pivot]
        e = d / np.hypot(d[0], d[1])
        return pos[self.pivot] + scene.slots[self.pin].offset * perp(e), e

    def emit(self, g):
        (bx, by), (qx, qy) = g.pos(self.pivot), g.pos(self.far)
        dx, dy = g.let("{} - {}", qx, bx), g.let("{} - {}", qy, by)
        n = g.let("hypot_p({}, {})", dx, dy)
        ex, ey = g.let("{} / {}", dx, n), g.let("{} / {}", dy, n)
        off = g.param(lambda s: s.slots[self.pin].offset)
        tx, ty = g.let("{} + {} * -{}", bx, off, ey), g.let("{} + {} * {}", by, off, ex)
        return (tx, ty), (ex, ey)


@dataclass(frozen=True)
class SlotUnstated:
    """The flag of a slot whose length is not stated ([slots.PIN] length): a stated one is
    not modelled for this construction (refused by its ``why_not``)."""
    pin: str

    def value(self, scene) -> bool:
        return scene.slots[self.pin].length is None

    def param(self, g):
        return g.param(lambda s: 1.0 if s.slots[self.pin].length is None else -1.0)


@dataclass(frozen=True)
class Prescribed:
    """The prescribed slide of ``point`` along its link ([driver.slide] position)."""
    point: str

    def value(self, scene):
        return scene.prescribed[self.point].position

    def param(self, g):
        return g.param(lambda s: s.prescribed[self.point].position)


@dataclass(frozen=True)
class WheelRim:
    """The rim pin ``pin`` of the driven rolling wheel: (the wheel's radius r, the pin's angle
    φ₀ at input 0 and its distance ρ from the centre)."""
    pin: str

    def value(self, scene):
        for q in scene.equivalents:
            if q.kind == "rolling" and q.driven:
                for label, angle, dist in q.rim:
                    if label == self.pin:
                        return q.radius, angle, dist
        return None


# ---------------------------------------------------------------- primitives
# Each states ``source(g, check)``: its formula, returning its margin's name (None: always
# placed), the margin checked where it is made unless ``check`` is False (a wrapper checks it
# then); ``locate(scene, pos, sigma, x) -> (points, margin)`` is that statement evaluated
# (:class:`~polygons.dyads.numeric.Stated`).
def _check(g, m, check: bool):
    """The margin ``m`` checked by the program here (over arrays: kept), when asked."""
    if check:
        g.margin(m)
    return m


@dataclass(frozen=True)
class CircleCircle(Stated):
    """X with |PX| = r₁ and |QX| = r₂, left of P→Q for σ = +1 (right for −1):
    X = P + a u + σ h perp(u), a = (r₁² − r₂² + d²)/2d, h = √(r₁² − a²)
    (:func:`~polygons.dyads.base.circle_circle`)."""
    x: str
    p: str
    r1: Length
    q: str
    r2: Length

    def source(self, g, check=True):
        r1, r2 = self.r1.param(g), self.r2.param(g)
        x, y, m = g.call(circle_circle_scalar, *g.pos(self.p), r1, *g.pos(self.q), r2,
                         g.sigma(self.x), n=3)
        _check(g, m, check)
        g.place(self.x, x, y)
        return m


@dataclass(frozen=True)
class CircleLine(Stated):
    """X on the line G + t e (fixed, or a lever's slot) with |PX| = r, (X − P)·e of sign σ:
    t = −b + σ √(b² − c), b = e·(G − P), c = |G − P|² − r²
    (:func:`~polygons.dyads.base.circle_line`); ``also``: labels placed at X too (the
    carrier's point under it)."""
    x: str
    p: str
    r: Length
    line: "FixedLine | LeverLine"
    also: tuple[str, ...] = ()

    def source(self, g, check=True):
        if isinstance(self.line, LeverLine):     # the line first, as it is drawn
            (gx, gy), (ex, ey) = self.line.emit(g)
            L = self.r.param(g)
        else:
            L = self.r.param(g)
            (gx, gy), (ex, ey) = self.line.emit(g)
        x, y, m = g.call(circle_line_scalar, *g.pos(self.p), L, gx, gy, ex, ey,
                         g.sigma(self.x), n=3)
        _check(g, m, check)
        for label in (self.x,) + self.also:
            g.place(label, x, y)
        return m


@dataclass(frozen=True)
class Rotation(Stated):
    """X = P + r (cos θ, sin θ), θ the driver's input (a crank about its fixed pivot)."""
    x: str
    p: str
    r: Length

    def source(self, g, check=True):
        r = self.r.param(g)
        px, py = g.pos(self.p)
        c, s_ = g.let("cos({})", g.x), g.let("sin({})", g.x)
        g.place(self.x, g.let("{} + {} * {}", px, r, c), g.let("{} + {} * {}", py, r, s_))
        return None


@dataclass(frozen=True)
class Translation(Stated):
    """X = G + s e, s the driver's input (a slider driven along its fixed guide)."""
    x: str
    line: FixedLine

    def source(self, g, check=True):
        tx, ty = self.line.params(g, "through")
        ex, ey = self.line.params(g, "direction")
        g.place(self.x, g.let("{} + {} * {}", tx, g.x, ex), g.let("{} + {} * {}", ty, g.x, ey))
        return None


@dataclass(frozen=True)
class LineLine(Stated):
    """X = G + t e on the fixed line where the line through the placed A along the yoke's
    slot f meets it: t = ((A − G) × f) / (e × f); the margin |e × f| (0: parallel)."""
    x: str
    a: str
    line: FixedLine

    def source(self, g, check=True):
        ex, ey = self.line.params(g, "direction")
        fx, fy = self.line.params(g, "slot_direction")
        tx, ty = self.line.params(g, "through")
        ax, ay = g.pos(self.a)
        den = g.let("{} * {} - {} * {}", ex, fy, ey, fx)
        m = _check(g, g.let("abs({})", den), check)
        wx, wy = g.let("{} - {}", ax, tx), g.let("{} - {}", ay, ty)
        t = g.let("({} * {} - {} * {}) / {}", wx, fy, wy, fx, den)
        g.place(self.x, g.let("{} + {} * {}", tx, t, ex), g.let("{} + {} * {}", ty, t, ey))
        return m


@dataclass(frozen=True)
class RigidImage(Stated):
    """X rigid with the link PQ ([points.X]): X = P + a u + l perp(u), u = PQ/|PQ|,
    a = along (or fraction · |PQ|), l its offset to the left; the margin +1 (−1 where
    |PQ| = 0)."""
    x: str
    p: str
    q: str

    def offsets(self, scene) -> tuple[float, float, float]:
        """(along, fraction, left) of [points.X]: ``along`` stated (fraction 0), or the
        fraction of |PQ| (along 0)."""
        bp = scene.points[self.x]
        if bp.along is not None:
            return bp.along, 0.0, bp.left
        return 0.0, bp.fraction, bp.left

    def source(self, g, check=True):
        along = g.param(lambda s: s.points[self.x].along or 0.0)
        frac = g.param(lambda s: s.points[self.x].fraction
                       if s.points[self.x].along is None else 0.0)
        left = g.param(lambda s: s.points[self.x].left)
        (px, py), (qx, qy) = g.pos(self.p), g.pos(self.q)
        dx, dy = g.let("{} - {}", qx, px), g.let("{} - {}", qy, py)
        n = g.let("hypot({}, {})", dx, dy)
        m = _check(g, g.let("where({} > 0, 1.0, -1.0)", n), check)
        ux, uy = g.let("{} / {}", dx, n), g.let("{} / {}", dy, n)
        a = g.let("{} + {} * {}", along, frac, n)
        g.place(self.x, g.let("{} + {} * {} + {} * -{}", px, a, ux, left, uy),
                g.let("{} + {} * {} + {} * {}", py, a, uy, left, ux))
        return m


@dataclass(frozen=True)
class LinesMeet(Stated):
    """X where the line A₁ → Q₁ meets the line A₂ → Q₂ (two moving slots):
    X = A₁ + t e₁, t = ((A₂ − A₁) × e₂) / (e₁ × e₂); the margin |e₁ × e₂| (−1 where the
    lines are parallel, X NaN there); ``also``: labels placed at X too."""
    x: str
    a1: str
    q1: str
    a2: str
    q2: str
    also: tuple[str, ...] = ()

    def source(self, g, check=True):
        (ax, ay), (qx, qy) = g.pos(self.a1), g.pos(self.q1)
        (bx, by), (rx, ry) = g.pos(self.a2), g.pos(self.q2)
        d1x, d1y = g.let("{} - {}", qx, ax), g.let("{} - {}", qy, ay)
        d2x, d2y = g.let("{} - {}", rx, bx), g.let("{} - {}", ry, by)
        n1, n2 = g.let("hypot_p({}, {})", d1x, d1y), g.let("hypot_p({}, {})", d2x, d2y)
        e1x, e1y = g.let("{} / {}", d1x, n1), g.let("{} / {}", d1y, n1)
        e2x, e2y = g.let("{} / {}", d2x, n2), g.let("{} / {}", d2y, n2)
        den = g.let("{} * {} - {} * {}", e1x, e2y, e1y, e2x)
        if g.arrays:
            safe = g.let("where(abs({}) > 1e-12, {}, nan)", den, den)
            m = _check(g, g.let("where(abs({}) > 1e-12, abs({}), -1.0)", den, den), check)
        else:
            safe = g.let("({} if abs({}) > 1e-12 else nan)", den, den)
            m = _check(g, g.let("(abs({}) if abs({}) > 1e-12 else -1.0)", den, den), check)
        wx, wy = g.let("{} - {}", bx, ax), g.let("{} - {}", by, ay)
        t = g.let("({} * {} - {} * {}) / {}", wx, e2y, wy, e2x, safe)
        x, y = g.let("{} + {} * {}", ax, t, e1x), g.let("{} + {} * {}", ay, t, e1y)
        for lab in (self.x,) + self.also:
            g.place(lab, x, y)
        return m


@dataclass(frozen=True)
class AlongLink(Stated):
    """X = P + s PQ/|PQ|, s a prescribed slide (a collar driven along the link PQ); the
    margin: |PQ| beyond 1e-12 of the mechanism's size and 0 ≤ s ≤ |PQ|
    (:func:`~polygons.dyads.base.end_margin_scalar`, within that tolerance); ``also``:
    labels placed at X too."""
    x: str
    p: str
    q: str
    s: Prescribed
    also: tuple[str, ...] = ()

    def source(self, g, check=True):
        (px, py), (qx, qy) = g.pos(self.p), g.pos(self.q)
        s_ = self.s.param(g)
        tiny = g.param(lambda s: 1e-12 * size_of(s))
        dx, dy = g.let("{} - {}", qx, px), g.let("{} - {}", qy, py)
        n = g.let("hypot_p({}, {})", dx, dy)
        m0 = g.let("where({} > {}, 1.0, -1.0)", n, tiny)
        m = _check(g, g.call(end_margin_scalar, m0, s_, "0.0", n, tiny)[0], check)
        cx = g.let("{} + {} * {} / {}", px, s_, dx, n)
        cy = g.let("{} + {} * {} / {}", py, s_, dy, n)
        for lab in (self.x,) + self.also:
            g.place(lab, cx, cy)
        return m


@dataclass(frozen=True)
class RimPoint(Stated):
    """X on the rim of the driven rolling wheel centred at W: X = W + ρ (cos φ, sin φ),
    φ = φ₀ − s/r, s the input (the wheel's centre along its surface: rolling turns it by
    −s/r; the rim angles stated at input 0)."""
    x: str
    w: str
    rim: WheelRim

    def source(self, g, check=True):
        phi0 = g.param(lambda s: self.rim.value(s)[1])
        rho = g.param(lambda s: self.rim.value(s)[2])
        r = g.param(lambda s: self.rim.value(s)[0])
        wx, wy = g.pos(self.w)
        phi = g.let("{} - {} / {}", phi0, g.x, r)
        g.place(self.x, g.let("{} + {} * cos({})", wx, rho, phi),
                g.let("{} + {} * sin({})", wy, rho, phi))
        return None


@dataclass(frozen=True)
class PinInSlot(Stated):
    """The lever turning about B whose slot the placed pin A slides in ([slots.A]): the
    lever's point X under the pin is A; its far end F at the lever's stated length l along
    the slot — e = BA/|BA| (F = B + l e), or, for a slot offset δ from the pivot,
    BA = t e + δ perp(e), t = √(|BA|² − δ²), e = (t BA − δ perp(BA)) / |BA|²; the margin
    |BA| (or t/|BA|) beyond 1e-12 of the size and the pin within the slot's stated length
    (:func:`~polygons.dyads.base.end_margin_scalar`)."""
    x: str
    pin: str
    pivot: str
    far: str | None

    def variant(self, scene) -> tuple:
        """A slot offset from the pivot is another statement (:meth:`_source_offset`)."""
        return (bool(scene.slots[self.pin].offset),)

    def source(self, g, check=True):
        (ax, ay), (bx, by) = g.pos(self.pin), g.pos(self.pivot)
        if g.scene.slots[self.pin].offset:      # (the cache key tells offset slots apart)
            return self._source_offset(g, ax, ay, bx, by, check)
        tiny = g.param(lambda s: 1e-12 * size_of(s))
        dx, dy = g.let("{} - {}", ax, bx), g.let("{} - {}", ay, by)
        n = g.let("hypot({}, {})", dx, dy)
        m0 = g.let("where({} > {}, 1.0, 0.0)", n, tiny)
        hi = g.param(lambda s: _slot_end(s.slots[self.pin]))
        m = _check(g, g.call(end_margin_scalar, m0, n, "0.0", hi, tiny)[0], check)
        g.place(self.x, ax, ay)
        if self.far:
            fl = g.param(lambda s: s.slots[self.pin].far_length)
            g.place(self.far, g.let("{} + {} * {} / {}", bx, fl, dx, n),
                    g.let("{} + {} * {} / {}", by, fl, dy, n))
        return m

    def _source_offset(self, g, ax, ay, bx, by, check):
        off = g.param(lambda s: s.slots[self.pin].offset)
        fl = g.param(lambda s: s.slots[self.pin].far_length)
        tiny2 = g.param(lambda s: 1e-12 * size_of(s) ** 2)
        dx, dy = g.let("{} - {}", ax, bx), g.let("{} - {}", ay, by)
        n = g.let("hypot_p({}, {})", dx, dy)
        t2 = g.let("{} * {} - {} * {}", n, n, off, off)
        t = g.let("sqrt(where({} > 0, {}, nan))", t2, t2)
        # over floats the test comes first (no division by a zero |BA|); over arrays the
        # margin is kept, NaN-free, as locate's
        m0 = g.let(g.e("where({} > {}, {} / {}, -1.0)", t2, tiny2, t, n) if g.arrays else
                   g.e("({} / {} if {} > {} else -1.0)", t, n, t2, tiny2))
        hi = g.param(lambda s: _slot_end(s.slots[self.pin]))
        tiny = g.param(lambda s: 1e-12 * size_of(s))
        m = _check(g, g.call(end_margin_scalar, m0, t, "0.0", hi, tiny)[0], check)
        g.place(self.x, ax, ay)
        n2 = g.let("{} * {}", n, n)
        ex = g.let("({} * {} - {} * -{}) / {}", t, dx, off, dy, n2)
        ey = g.let("({} * {} - {} * {}) / {}", t, dy, off, dx, n2)
        g.place(self.far, g.let("{} + {} * {}", bx, fl, ex), g.let("{} + {} * {}", by, fl, ey))
        return m


def _slot_end(slot) -> float:
    """The slot's stated length (NaN: open-ended)."""
    return math.nan if slot.length is None else slot.length


@dataclass(frozen=True)
class Guarded(Stated):
    """``inner`` refused (margin −1) where ``ok`` does not hold: a case the construction does
    not model, which the group's ``why_not`` names."""
    inner: "CircleLine"
    ok: SlotUnstated

    @property
    def x(self) -> str:
        return self.inner.x

    def variant(self, scene) -> tuple:
        return self.inner.variant(scene)

    def source(self, g, check=True):
        m = self.inner.source(g, check=False)
        ok = self.ok.param(g)
        return _check(g, g.let("where({} > 0.0, {}, -1.0)", ok, m), check)


# ---------------------------------------------------------------- the class-III group
@dataclass(frozen=True)
class PlateShape:
    """A triad's plate in its own frame, B = (0, 0): C = (L, 0), X = (ξ, η) — a link BC
    carrying the point X ([points.X]: ξ = along or fraction · L, η = left), or a triangle of
    links BC, BX, CX (ξ = (L² + |BX|² − |CX|²)/2L, η = √(|BX|² − ξ²), its mirror image a
    closure too: ``mirror``)."""
    x: str
    links: tuple[str, ...]        # (the plate link) or (BC, BX, CX)

    @property
    def mirror(self) -> bool:
        return len(self.links) == 3

    def value(self, scene) -> tuple:
        """(L, ξ, η)."""
        if not self.mirror:
            L = scene.links[self.links[0]].length
            bp = scene.points[self.x]
            along = bp.along if bp.along is not None else bp.fraction * L
            return L, along, bp.left
        lbc, lbx, lcx = (scene.links[n].length for n in self.links)
        xi = (lbc * lbc + lbx * lbx - lcx * lcx) / (2.0 * lbc)
        return lbc, xi, np.sqrt(np.maximum(lbx * lbx - xi * xi, 0.0))   # (batch: arrays)

    def params(self, g) -> tuple:
        return tuple(g.param(lambda s, i=i: self.value(s)[i]) for i in range(3))


class _ClosureOfThree(Stated):
    """A class-III group's closure as one stated step (its subclasses say the numbers,
    :meth:`operands`, and the two functions of their algebra): the corners placed from the
    closure nearest the reference kept under ``keys``, the margin its conditioning."""
    #: (operands…, references…, size) → (6 coordinates, margin); its array twin by name
    scalar = None
    #: (operands, size) → every closure's corners
    listing = None

    @property
    def x(self) -> str:
        return self.corners[0]

    def every(self, scene, pos) -> list[dict]:
        """Every closure at the positions ``pos`` (one position): {B, C, X} each."""
        g = Numeric(scene, pos, None, 0.0, False)
        p = tuple(float(v) for v in self.operands(g))
        return [dict(zip(self.corners, map(np.array, c)))
                for c in type(self).listing(p, size_of(scene))]

    def source(self, g, check=True):
        refs = [g.sigma(k) for k in self.keys]
        size = g.param(lambda s: size_of(s))
        *xy, m = g.call(type(self).scalar, *self.operands(g), *refs, size, n=7)
        _check(g, m, check)
        for k, label in enumerate(self.corners):
            g.place(label, xy[2 * k], xy[2 * k + 1])
        return m


@dataclass(frozen=True)
class TriadClosure(_ClosureOfThree):
    """The corners B, C, X of a rigid plate (:class:`PlateShape`) each on a link of stated
    length to a placed point: |AB| = a, |DC| = d, |EX| = e — the closure nearest the
    reference corners kept under ``keys`` (B's and X's coordinates), by
    :func:`~polygons.dyads.triad_math.triad_scalar` (the real roots of a polynomial of
    degree ≤ 6, polished by Newton; over a sweep its array twin follows the closure by
    continuation); the margin the construction's conditioning (−1: it cannot close)."""
    corners: tuple[str, str, str]              # B, C, X
    outer: tuple[str, str, str]                # A, D, E
    lengths: tuple[Length, Length, Length]     # AB, DC, EX
    plate: PlateShape
    keys: tuple[str, str, str, str]            # where the reference corners are kept
    scalar = staticmethod(triad_scalar)
    listing = staticmethod(all_corners)

    def operands(self, g) -> tuple:
        """(ax, ay, a, dx, dy, d, ex, ey, e, L, ξ, η, mirror): the group's numbers, in the
        order :mod:`~polygons.dyads.triad_math` takes them."""
        out = []
        for o, ln in zip(self.outer, self.lengths):
            out += [*g.pos(o), ln.param(g)]
        return (*out, *self.plate.params(g), "1.0" if self.plate.mirror else "0.0")


@dataclass(frozen=True)
class AssurPoint(Stated):
    """S where the lines O₁P₁ and O₂P₂ produced meet (Assur's auxiliary point of a triad):
    S = O₁ + t u, u = P₁ − O₁, w = P₂ − O₂, t = ((O₂ − O₁) × w) / (u × w); with ``normal``
    (a block's fixed guide) the second line is the normal to that guide at P₂ instead:
    w = (−e_y, e_x), O₂ = P₂.  NaN where they are parallel (S at infinity: a point of the
    construction, not a failure of the group — no margin)."""
    x: str
    o1: str
    p1: str
    o2: str
    p2: str
    normal: FixedLine | None = None

    def source(self, g, check=True):
        (ax, ay), (bx, by) = g.pos(self.o1), g.pos(self.p1)
        ux, uy = g.let("{} - {}", bx, ax), g.let("{} - {}", by, ay)
        if self.normal is None:
            (dx, dy), (cx, cy) = g.pos(self.o2), g.pos(self.p2)
            wx, wy = g.let("{} - {}", cx, dx), g.let("{} - {}", cy, dy)
        else:           # the normal to the guide at P₂: through P₂ along (−e_y, e_x)
            (dx, dy), (ex, ey) = g.pos(self.p2), self.normal.params(g, "direction")
            wx, wy = g.let("-{}", ey), g.let("{} + 0.0", ex)
        den = g.let("{} * {} - {} * {}", ux, wy, uy, wx)
        safe = g.let(g.e("where({} != 0.0, {}, nan)", den, den) if g.arrays else
                     g.e("({} if {} != 0.0 else nan)", den, den))
        t = g.let("(({} - {}) * {} - ({} - {}) * {}) / {}", dx, ax, wy, dy, ay, wx, safe)
        g.place(self.x, g.let("{} + {} * {}", ax, t, ux), g.let("{} + {} * {}", ay, t, uy))
        return None


@dataclass(frozen=True)
class CornerFrame:
    """The plate of a triad with a block in its corners' frame, B = (0, 0): C = (L, 0),
    X = (ξ, η) — from a link carrying a point ([points]: along or fraction · length, left)
    or a triangle of three links (ξ = (|BC|² + |BX|² − |CX|²)/2|BC|, η = √(|BX|² − ξ²)),
    whichever corners the plate's own link joins; ``mirror``: the triangle's image η → −η
    is a closure too."""
    b: str
    c: str
    x: str
    links: tuple[str, ...]        # (the plate link) or (BC, BX, CX) as the scene lists them

    @property
    def mirror(self) -> bool:
        return len(self.links) == 3

    def value(self, scene) -> tuple:
        """(L, ξ, η) (arrays in a batch)."""
        if not self.mirror:
            lk = scene.links[self.links[0]]
            bp = scene.points[({self.b, self.c, self.x} - {lk.a, lk.b}).pop()]
            along = bp.along if bp.along is not None else bp.fraction * lk.length
            own = {lk.a: (0.0, 0.0), lk.b: (lk.length, 0.0), bp.label: (along, bp.left)}
        else:
            lbc, lbx, lcx = (scene.links[n].length for n in self.links)
            first = scene.links[self.links[0]]
            third = ({self.b, self.c, self.x} - {first.a, first.b}).pop()
            xi = (lbc * lbc + lbx * lbx - lcx * lcx) / (2.0 * lbc)
            own = {first.a: (0.0, 0.0), first.b: (lbc, 0.0),
                   third: (xi, np.sqrt(np.maximum(lbx * lbx - xi * xi, 0.0)))}
        (bx, by), (cx, cy), (xx, xy) = (own[k] for k in (self.b, self.c, self.x))
        ux, uy = np.subtract(cx, bx), np.subtract(cy, by)
        L = np.hypot(ux, uy)
        ux, uy = ux / L, uy / L
        wx, wy = np.subtract(xx, bx), np.subtract(xy, by)
        return L, wx * ux + wy * uy, wy * ux - wx * uy

    def params(self, g) -> tuple:
        return tuple(g.param(lambda s, i=i: self.value(s)[i]) for i in range(3))


@dataclass(frozen=True)
class TriadSliderClosure(_ClosureOfThree):
    """The corners B, C of a rigid plate (:class:`CornerFrame`) each on a link of stated
    length to a placed point (|AB| = a, |DC| = d) and its corner X on a fixed guide
    (:class:`FixedLine`): the closure nearest the reference corners kept under ``keys``, by
    :func:`~polygons.dyads.triad_slider_math.triad_slider_scalar` (the real roots of a
    polynomial of degree ≤ 6, polished by Newton; over a sweep its array twin follows the
    closure by continuation); the margin the construction's conditioning."""
    corners: tuple[str, str, str]              # B, C, X
    outer: tuple[str, str]                     # A, D
    lengths: tuple[Length, Length]             # AB, DC
    guide: FixedLine
    plate: CornerFrame
    keys: tuple[str, str, str, str]            # where the reference corners are kept
    scalar = staticmethod(triad_slider_scalar)
    listing = staticmethod(all_slider_corners)

    def operands(self, g) -> tuple:
        """(ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, ξ, η, mirror): the group's numbers, in
        the order :mod:`~polygons.dyads.triad_slider_math` takes them."""
        out = []
        for o, ln in zip(self.outer, self.lengths):
            out += [*g.pos(o), ln.param(g)]
        through, direction = self.guide.emit(g)
        return (*out, *through, *direction, *self.plate.params(g),
                "1.0" if self.plate.mirror else "0.0")


@dataclass(frozen=True)
class Then(Stated):
    """``steps`` in order, each placing its points from those before; the margin the first
    step's (the ones after it place construction points that cannot fail)."""
    steps: tuple

    @property
    def x(self) -> str:
        return self.steps[0].x

    def variant(self, scene) -> tuple:
        return tuple(s.variant(scene) for s in self.steps)

    def source(self, g, check=True):
        margins = [s.source(g, check) for s in self.steps]
        return margins[0]


#: every primitive (a group's ``construction`` is one of these)
PRIMITIVES = (CircleCircle, CircleLine, Rotation, Translation, LineLine, RigidImage,
              LinesMeet, AlongLink, RimPoint, PinInSlot, Guarded, TriadClosure, TriadSliderClosure,
              AssurPoint, Then)


class Constructed:
    """A group whose position is its ``construction`` (a primitive): ``locate`` and
    ``source`` are that primitive's, stated once."""

    def locate(self, scene, pos, sigma, x):
        return self.construction.locate(scene, pos, sigma, x)

    def source(self, g) -> None:
        """:meth:`locate`'s formula in the generated program (:mod:`polygons.codegen`): the
        same primitive, emitted through ``g``, its margin checked (or kept, over arrays)."""
        self.construction.source(g)


__all__ = ["Length", "FixedLine", "LeverLine", "SlotUnstated", "Prescribed", "WheelRim",
           "CircleCircle", "CircleLine", "Rotation", "Translation", "LineLine", "RigidImage",
           "LinesMeet", "AlongLink", "RimPoint", "PinInSlot", "Guarded", "PlateShape",
           "TriadClosure", "CornerFrame", "TriadSliderClosure", "AssurPoint", "Then", "PRIMITIVES",
           "Constructed"]
