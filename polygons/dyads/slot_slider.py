"""A slider on a fixed guide driven by a slotted lever through its pin (the tangent
mechanism; the slot may be offset from the lever's pivot line): the block X slides on its
fixed guide ([sliders.X]) and its pin X slides in the straight slot of the lever BQ
([slots.X] lever = "BQ", coincident = "X1"), the lever placed first — driven
([driver] crank = "BQ") or placed by its own links.

Position: X is where the guide G + s e crosses the slot B + δ n + u f (f = BQ/|BQ|,
n = perp(f), δ the slot's offset to the left of B → Q):

    s = ((B + δ n − G) × f) / (e × f),   X = G + s e,

one closure; the margin |e × f| (the slot parallel to the guide: the pin at infinity, refused).  The
lever's point X1 under the pin is at X.  Velocity: v_X = v_X1 + (v_X)_X1, v_X ∥ the guide and
the sliding velocity ∥ the slot: the lever's image x1, then the line ∥ the slot through x1
meets the line along the guide through the pole at x.  Acceleration: a_X = a_X1 + (a_X)_X1 +
2 ω × (v_X)_X1: the image x1, the Coriolis 2ωv from it, a line ∥ the slot through its end; the
line along the guide through the pole meets it at x.

Its position is one primitive (:class:`SlotCrossesGuide`), written once as its ``source``:
its ``locate`` is that statement evaluated (:mod:`polygons.dyads.numeric`).  A stated slot
length is not modelled here (refused in words).  The graphical force polygons have no
construction of this group's (it names none: refused naming it); every other method reads
the model's bodies and pairs (a block on the guide, the pin's block in the slot).

The module registers itself (``ROLE``, ``BEFORE``: :mod:`polygons.dyads`): the planner asks
it about the lever's point X1 under the pin (the block's X is no label of the space
diagram's own), before the kinds that would claim any point (RRR).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..steps import Builder, Component, Kind, Op
from . import image
from .numeric import Stated
from .primitives import FixedLine, Guarded, LeverLine, SlotUnstated, _check

#: how the planner finds it: a point kind (``claims``/``match``), asked before rrr (which
#: claims every point)
ROLE = "point"
BEFORE = ("rrr",)


@dataclass(frozen=True)
class SlotCrossesGuide(Stated):
    """X where the fixed guide G + s e of ``x`` crosses the slot of the lever ``slot``
    (B + δ n + u f): s = ((B + δ n − G) × f) / (e × f); the margin |e × f| (−1, X NaN,
    where they are parallel within 1e-12: X at infinity); ``also``: labels placed at X
    too."""
    x: str
    guide: FixedLine
    slot: LeverLine
    also: tuple[str, ...] = ()

    def source(self, g, check=True):
        (gx, gy), (ex, ey) = self.guide.emit(g)
        (bx, by), (fx, fy) = self.slot.emit(g)
        den = g.let("{} * {} - {} * {}", ex, fy, ey, fx)
        if g.arrays:
            safe = g.let("where(abs({}) > 1e-12, {}, nan)", den, den)
            m = _check(g, g.let("where(abs({}) > 1e-12, abs({}), -1.0)", den, den), check)
        else:
            safe = g.let("({} if abs({}) > 1e-12 else nan)", den, den)
            m = _check(g, g.let("(abs({}) if abs({}) > 1e-12 else -1.0)", den, den), check)
        s = g.let("(({} - {}) * {} - ({} - {}) * {}) / {}", bx, gx, fy, by, gy, fx, safe)
        x, y = g.let("{} + {} * {}", gx, s, ex), g.let("{} + {} * {}", gy, s, ey)
        for label in (self.x,) + self.also:
            g.place(label, x, y)
        return m


@dataclass(frozen=True)
class SlotSlider:
    """The block ``x`` on its fixed guide, its pin in the slot of the placed lever ``lever``
    (pivot ``pivot``, far end ``far``); also places the lever's point ``coincident`` under
    the pin."""
    x: str
    lever: str
    pivot: str
    far: str
    coincident: str
    offset: bool = False        # the slot offset from the lever's line: signed along B → Q
    two_closures = False
    #: the kind in words, for a method that refuses it (no ``force_polygon``: the graphical
    #: force polygons have no construction of this group's)
    words = ("a slider on a fixed guide driven through its pin by the slot of a turning lever "
             "(the tangent mechanism)")

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.x, self.coincident)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.pivot, self.far)

    @cached_property
    def construction(self) -> Guarded:
        """Its position, stated once: X where the guide crosses the lever's slot, X1 = X; a
        stated slot length refused."""
        return Guarded(SlotCrossesGuide(self.x, FixedLine(self.x),
                                        LeverLine(self.x, self.pivot, self.far),
                                        also=(self.coincident,)),
                       SlotUnstated(self.x))

    def locate(self, scene, pos, sigma, x):
        return self.construction.locate(scene, pos, sigma, x)

    def source(self, g) -> None:
        self.construction.source(g)

    def why_not(self, scene, pos) -> str:
        length = scene.slots[self.x].length
        if length is not None:
            return (f"[slots.{self.x}] length = {1e3 * length:.6g} mm is not checked for a "
                    f"slider driven by the slot of a lever (the tangent mechanism): remove it, "
                    f"the slot of {self.lever} is then open-ended")
        return self.toggle_reason(scene, pos)

    def toggle_reason(self, scene, pos) -> str:
        return (f"the slot of {self.lever} is parallel to the guide of {self.x}: the pin "
                f"{self.x} is not fixed by them (it runs off to infinity)")

    def emit(self, b: Builder) -> None:
        X, X1, lev, B, Q = self.x, self.coincident, self.lever, self.pivot, self.far
        V = b.names.of
        x, x1, pole = V(X), V(X1), b.names.pole
        C = Component
        image.emit_image(b, X1, lev, B, Q)
        if b.velocity:
            start, what = x1, f"(v_{X})_{X1}"
        else:
            start = b.fresh(X, dash=True)
            b.add(Kind.VECTOR, Op.CORIOLIS, (X,), f"{x1}{start}", x1, start, "coriolis",
                  "a_cor", f"a_cor = 2 ω_{lev} × (v_{X})_{X1}",
                  f"From {x1} draw the Coriolis acceleration 2ωv, the sliding velocity turned "
                  f"through 90° in the sense of ω_{lev}; call its end {start}.",
                  component=C.CORIOLIS, link=lev)
            what = f"(a_{X})_{X1}^slide"
        n1 = b.add(Kind.LINE, Op.LINE_SLIDE, (X,), f"slot line ∥ {B}{Q}", start, None,
                   "sliding", what, f"{what} ∥ the slot of {lev}",
                   f"Through {start} draw a line parallel to the slot of {lev}: the "
                   f"{b.what} of {X} sliding relative to {X1} lies on it.",
                   component=C.SLIDING)
        n2 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", pole, None, "slider_line",
                   f"{b.q}_{X}", f"{b.q}_{X} ∥ guide of {X}",
                   f"Through {pole} draw a line along the guide of {X}: the block can only "
                   f"move along it.", component=C.RESULTANT)
        b.add(Kind.INTERSECTION, Op.INTERSECT, (), x, None, x, "intersection", f"{b.q}_{X}",
              f"{x} = intersection of the two lines",
              f"The lines meet at {x}: {pole}{x} is the {b.what} of the block {X} and "
              f"{start}{x} its sliding {b.what} in the slot.", (n1, n2),
              component=C.RESULTANT)
        op = Op.SLIDER_VELOCITY if b.velocity else Op.SLIDER_ACCELERATION
        b.add(Kind.MEASURE, op, (X,), f"{b.q}_{X}", None, None, "slider",
              f"{b.q}_{X} along guide", f"{b.q}_{X} = {pole}{x}",
              f"The block's {b.what} is {pole}{x}, along its guide.",
              component=C.RESULTANT)
        op = Op.SLIDE_VELOCITY if b.velocity else Op.SLIDE_ACCELERATION
        b.add(Kind.MEASURE, op, (X,), "v_slide" if b.velocity else "a_slide", None, None,
              "sliding", f"({b.q}_{X})_{X1}", f"({b.q}_{X})_{X1} = {start}{x}",
              f"The sliding {b.what} of {X} in the slot is {start}{x} (positive "
              f"{f'from {B} towards {Q}' if self.offset else f'away from {B}'}).",
              component=C.SLIDING)


def _slot_under(scene, x):
    """The slot whose lever's point under the pin is ``x``, when the pin is a block on a
    fixed guide that hangs from no link and is not the driver, in a lever with a length:
    the slot, or None.  (The planner asks about ``x``: the block's label is no point of the
    space diagram's own, only its guide's and the slot's.)"""
    slot = next((s for s in scene.slots.values() if s.coincident == x), None)
    if slot is None or slot.far is None or slot.pin in scene.points:
        return None
    g = scene.sliders.get(slot.pin)
    if g is None or g.pin is not None or getattr(scene.driver, "point", None) == slot.pin:
        return None
    if any(slot.pin in (l.a, l.b) for l in scene.links.values()):
        return None
    return slot


def claims(scene, x) -> bool:
    """The lever's point under the pin of a block on a fixed guide (the pin on no link), in
    the slot of a lever with a length."""
    return _slot_under(scene, x) is not None


def match(scene, x, placed, known):
    """The lever placed (its pivot and far end)."""
    slot = _slot_under(scene, x)
    if slot is None or slot.pivot not in placed or slot.far not in placed:
        return None
    return SlotSlider(slot.pin, slot.lever, slot.pivot, slot.far, x, bool(slot.offset))
