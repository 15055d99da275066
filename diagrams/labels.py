"""Label placement without overlaps, tested geometrically (paper mm, y up; no svgwrite).

Every label is a box.  A label may not cross a vector (a segment thickened by the arrowhead's
half-width), another label or another vertex; crossing a construction line is allowed but
costs.  Candidates are tried around the anchor at growing distances; the cheapest free one
wins.  :func:`box_hits_segment` is also what the tests use to check the finished drawings.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from .text import ASCENT, DESCENT, width

Pt = tuple[float, float]

#: clear space (mm) kept between two labels, so they never touch
LABEL_GAP = 0.35
#: clear space (mm) kept between two labels side by side on one line (their middles within half
#: a height), so that they never read as one ("(a_P2)ⁿ_O2 (a_P4)ᵗ_O4"): close to a word space
LABEL_GAP_X = 1.6


@dataclass(frozen=True)
class Box:
    x0: float
    y0: float
    x1: float
    y1: float

    def grown(self, d: float) -> "Box":
        return Box(self.x0 - d, self.y0 - d, self.x1 + d, self.y1 + d)

    def overlaps(self, other: "Box") -> bool:
        return (self.x0 < other.x1 and other.x0 < self.x1 and self.y0 < other.y1
                and other.y0 < self.y1)

    def contains(self, p: Pt) -> bool:
        return self.x0 <= p[0] <= self.x1 and self.y0 <= p[1] <= self.y1

    def union(self, other: "Box") -> "Box":
        return Box(min(self.x0, other.x0), min(self.y0, other.y0), max(self.x1, other.x1),
                   max(self.y1, other.y1))

    @property
    def centre(self) -> Pt:
        return ((self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2)


def bounds(points) -> Box:
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return Box(min(xs), min(ys), max(xs), max(ys))


def text_box(x: float, baseline: float, text: str, size: float, anchor: str = "start") -> Box:
    """The box a text occupies given its insertion point, as the SVG places it."""
    w = width(text, size)
    x0 = {"start": x, "middle": x - w / 2, "end": x - w}[anchor]
    return Box(x0, baseline - DESCENT * size, x0 + w, baseline + ASCENT * size)


def clip(p0: Pt, p1: Pt, box: Box) -> tuple[Pt, Pt] | None:
    """Liang–Barsky: the part of segment p0→p1 inside ``box`` (None if none)."""
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, p0[0] - box.x0), (dx, box.x1 - p0[0]),
                 (-dy, p0[1] - box.y0), (dy, box.y1 - p0[1])):
        if p == 0:
            if q < 0:
                return None
            continue
        r = q / p
        if p < 0:
            if r > t1:
                return None
            t0 = max(t0, r)
        else:
            if r < t0:
                return None
            t1 = min(t1, r)
    return ((p0[0] + t0 * dx, p0[1] + t0 * dy), (p0[0] + t1 * dx, p0[1] + t1 * dy))


def _meets(p0: Pt, p1: Pt, x0: float, y0: float, x1: float, y1: float) -> bool:
    """``clip(p0, p1, Box(x0, y0, x1, y1)) is not None``, the same arithmetic without the
    boxes and points (the label placer asks it ~10⁵ times on a large drawing)."""
    ax, ay = p0
    dx, dy = p1[0] - ax, p1[1] - ay
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
        if p == 0:
            if q < 0:
                return False
            continue
        r = q / p
        if p < 0:
            if r > t1:
                return False
            if r > t0:
                t0 = r
        else:
            if r < t0:
                return False
            if r < t1:
                t1 = r
    return True


def clip_line(anchor: Pt, direction: Pt, box: Box) -> tuple[Pt, Pt] | None:
    """The chord of the infinite line through ``anchor`` along ``direction`` in ``box``."""
    big = 4 * (abs(box.x1 - box.x0) + abs(box.y1 - box.y0) + abs(anchor[0]) + abs(anchor[1]))
    n = math.hypot(*direction)
    ux, uy = direction[0] / n, direction[1] / n
    return clip((anchor[0] - big * ux, anchor[1] - big * uy),
                (anchor[0] + big * ux, anchor[1] + big * uy), box)


def box_hits_segment(box: Box, p0: Pt, p1: Pt, clearance: float = 0.0) -> bool:
    """True if the segment, thickened by ``clearance`` on each side, meets ``box``."""
    if clearance <= 0:
        return _meets(p0, p1, box.x0, box.y0, box.x1, box.y1)
    # Minkowski sum of box and a disc ≈ the box grown by the clearance with cut corners;
    # the grown box is conservative (a little larger) which is what a label wants
    return _meets(p0, p1, box.x0 - clearance, box.y0 - clearance, box.x1 + clearance,
                  box.y1 + clearance)


def first_clear(keys, box_of, placed, segs, clearance: float = 0.3):
    """The first place of ``keys`` whose name box (``box_of(key)``) overlaps no box of
    ``placed`` and keeps ``clearance`` off every segment of ``segs``; failing that, the first
    clear of the placed names only; failing both, the last.  Returns ``(key, box)``."""
    keys = list(keys)
    for clear in (True, False):
        for key in keys:
            bx = box_of(key)
            if not any(bx.overlaps(o) for o in placed) and not (clear and any(
                    box_hits_segment(bx, a, b, clearance) for a, b in segs)):
                return key, bx
    return key, bx


def point_segment_distance(p: Pt, a: Pt, b: Pt) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def box_point_distance(b: Box, p: Pt) -> float:
    """The distance (mm) from point ``p`` to the box ``b`` (0 inside it)."""
    return math.hypot(max(b.x0 - p[0], 0.0, p[0] - b.x1), max(b.y0 - p[1], 0.0, p[1] - b.y1))


def box_segment_distance(box: Box, a: Pt, b: Pt) -> float:
    if _meets(a, b, box.x0, box.y0, box.x1, box.y1):
        return 0.0
    corners = [(box.x0, box.y0), (box.x1, box.y0), (box.x1, box.y1), (box.x0, box.y1)]
    d = min(point_segment_distance(c, a, b) for c in corners)
    for i in range(4):
        c0, c1 = corners[i], corners[(i + 1) % 4]
        d = min(d, point_segment_distance(a, c0, c1), point_segment_distance(b, c0, c1))
    return d


@dataclass
class Placer:
    """Obstacles of one drawing; :meth:`place` adds each placed label as a new obstacle."""

    hard_segments: list[tuple[Pt, Pt, float]] = field(default_factory=list)  # a, b, clearance
    soft_segments: list[tuple[Pt, Pt]] = field(default_factory=list)
    boxes: list[Box] = field(default_factory=list)
    frame: Box | None = None     # labels prefer to stay inside (cost otherwise)
    soft_cost: float = 4.0       # cost of crossing a soft line (≈ 4 steps further out)
    _grid: tuple | None = field(default=None, repr=False, compare=False)

    def hard(self, a: Pt, b: Pt, clearance: float = 0.8) -> None:
        self.hard_segments.append((a, b, clearance))

    def rim(self, c: Pt, r: float, clearance: float = 0.3, n: int = 48) -> None:
        """A circle (a wheel's rim) as ``n`` hard chords: no label is set across it."""
        pts = [(c[0] + r * math.cos(2 * math.pi * i / n), c[1] + r * math.sin(2 * math.pi * i / n))
               for i in range(n + 1)]
        for p, q in zip(pts, pts[1:]):
            self.hard(p, q, clearance)

    def soft(self, a: Pt, b: Pt) -> None:
        self.soft_segments.append((a, b))

    def block(self, box: Box) -> None:
        self.boxes.append(box)

    def free(self, box: Box, near=None) -> bool:
        """No label, vertex or vector in the way (``near``: the obstacles near ``box``, from
        :meth:`_near`, else looked up)."""
        boxes, hard, _ = near or self._near(box)
        x0, y0, x1, y1 = box.x0, box.y0, box.x1, box.y1
        gx0, gy0, gx1, gy1 = x0 - LABEL_GAP, y0 - LABEL_GAP, x1 + LABEL_GAP, y1 + LABEL_GAP
        wx0, wx1, half = x0 - LABEL_GAP_X, x1 + LABEL_GAP_X, (y1 - y0) / 2
        for b in boxes:                   # (box.grown(LABEL_GAP).overlaps(b))
            if gx0 < b.x1 and b.x0 < gx1 and gy0 < b.y1 and b.y0 < gy1:
                return False
            # on one line (their middles within half a height): a word space apart
            if (wx0 < b.x1 and b.x0 < wx1
                    and abs((b.y0 + b.y1) - (y0 + y1)) < min(half, (b.y1 - b.y0) / 2) * 2):
                return False
        for a, b, c in hard:              # (box_hits_segment(box, a, b, c))
            if c <= 0:
                if _meets(a, b, x0, y0, x1, y1):
                    return False
            elif _meets(a, b, x0 - c, y0 - c, x1 + c, y1 + c):
                return False
        return True

    def cost(self, box: Box, near=None) -> float:
        c = 0.0
        _, hard, soft = near or self._near(box)
        x0, y0, x1, y1 = box.x0 - 0.8, box.y0 - 0.8, box.x1 + 0.8, box.y1 + 0.8
        for a, b in soft:                 # (box_hits_segment(box, a, b, 0.8))
            if _meets(a, b, x0, y0, x1, y1):
                c += self.soft_cost
        if self.frame is not None and not (self.frame.contains((box.x0, box.y0))
                                           and self.frame.contains((box.x1, box.y1))):
            c += 1.5
        # stay clear of vectors where possible (a vector farther than 1.5 mm beyond its
        # clearance adds nothing, so only the near ones are measured)
        near = min((box_segment_distance(box, a, b) - cl for a, b, cl in hard), default=5.0)
        c += max(0.0, 1.5 - near) * 0.8
        return c

    def near_boxes(self, box: Box) -> list[Box]:
        """The placed labels that may come within :data:`LABEL_GAP` of ``box`` (every one that
        does, perhaps a few more; in no particular order)."""
        return self._near(box)[0]

    def _near(self, box: Box):
        """(boxes, hard segments, soft segments) that can matter to a label in ``box``: all of
        them on a small drawing; on a large one those indexed in the grid cells ``box`` covers
        (:class:`_Grid`; every obstacle within its reach of the box is among them, each once,
        and every use -- any, min, a count -- is order-free, so the answers are the same)."""
        lists = (self.boxes, self.hard_segments, self.soft_segments)
        if len(lists[0]) + len(lists[1]) + len(lists[2]) < _GRID_FROM:
            return lists
        if self._grid is None:
            self._grid = (_Grid(_box_reach), _Grid(_hard_reach), _Grid(_soft_reach))
        x0, y0, x1, y1 = box.x0, box.y0, box.x1, box.y1
        if not math.isfinite(x0 + x1 + y0 + y1):
            return lists
        span = (math.floor(x0 / _CELL), math.floor(y0 / _CELL), math.floor(x1 / _CELL),
                math.floor(y1 / _CELL))
        gb, gh, gs = self._grid
        return (gb.near(lists[0], box, span), gh.near(lists[1], box, span),
                gs.near(lists[2], box, span))

    def place(self, text: str, at: Pt, size: float, *, prefer: float | None = None,
              distances=(0.9, 1.6, 2.6, 4.0, 6.0, 8.5, 12.0), directions: int = 24,
              along: float | None = None, extra_cost=None) -> tuple[float, float, str, Box]:
        """Place ``text`` near point ``at``: returns (x, baseline, anchor, box).

        ``prefer`` is the preferred direction (radians); ``along`` (radians) restricts the
        candidates to the two sides of a line through ``at`` in that direction;
        ``extra_cost(0, box)`` adds to a place's cost (:meth:`place_any`).
        """
        if along is not None:
            dirs = [along + math.pi / 2, along - math.pi / 2]
        else:
            dirs = [2 * math.pi * k / directions for k in range(directions)]
        return self.place_any(text, size, [(at, dirs)], prefer=prefer, distances=distances,
                              extra_cost=extra_cost)

    def place_any(self, text: str, size: float, anchors, *, prefer: float | None = None,
                  distances=(0.9, 1.6, 2.6, 4.0, 6.0, 8.5, 12.0), extra_cost=None,
                  required: bool = True) -> tuple[float, float, str, Box] | None:
        """Like :meth:`place` over several (point, directions) anchors; the cheapest wins.

        With ``required`` False, None when no candidate is free (nothing is placed)."""
        w = width(text, size)
        h = (ASCENT + DESCENT) * size
        best = None
        for rank, d in enumerate(distances):
            for ai, (at, dirs) in enumerate(anchors):
                for th in dirs:
                    ux, uy = math.cos(th), math.sin(th)
                    # centre so that the box side nearest `at` is d away along (ux, uy)
                    half = min(abs(w / 2 / ux) if abs(ux) > 1e-12 else math.inf,
                               abs(h / 2 / uy) if abs(uy) > 1e-12 else math.inf)
                    cx, cy = at[0] + (d + half) * ux, at[1] + (d + half) * uy
                    box = Box(round(cx - w / 2, 3), round(cy - h / 2, 3),
                              round(cx + w / 2, 3), round(cy + h / 2, 3))
                    near = self._near(box)
                    if not self.free(box, near):
                        continue
                    c = self.cost(box, near) + rank * 0.9
                    if prefer is not None:
                        diff = abs((th - prefer + math.pi) % (2 * math.pi) - math.pi)
                        c += diff / math.pi * 1.2
                    if extra_cost is not None:
                        c += extra_cost(ai, box)
                    if best is None or c < best[0] - 1e-9:
                        best = (c, box)
            if best is not None and best[0] < (rank + 1) * 0.9:
                break
        if best is None and not required:
            return None
        if best is None and distances[-1] < 30.0:   # nothing free near: look further out
            far = tuple(round(distances[-1] * f, 3) for f in (1.4, 2.0, 3.0))
            return self.place_any(text, size, anchors, prefer=prefer, distances=far,
                                  extra_cost=extra_cost, required=required)
        if best is None:   # nothing free anywhere: park it beside the first anchor, far out
            at = anchors[0][0]
            best = (math.inf, Box(at[0] + 14, at[1] + 2, at[0] + 14 + w, at[1] + 2 + h))
        box = best[1]
        self.block(box)
        baseline = box.y0 + DESCENT * size
        return (box.x0, baseline, "start", box)


# ---------------------------------------------------------------- the obstacles' grid
#: from this many obstacles a Placer looks them up in a grid instead of testing every one
#: (each label tries ~170 boxes: testing all N obstacles made placing N labels cost N²)
_GRID_FROM = 48
#: the grid's cell (mm)
_CELL = 6.0
#: a segment needing more samples than this is tested against every box instead
_MAX_SAMPLES = 400


def _box_reach(b: Box):
    """A placed box: its cells, grown by the gap two labels keep (``free``)."""
    return b.grown(max(LABEL_GAP, LABEL_GAP_X) + 0.01), None


def _hard_reach(seg):
    """A vector: blocks a box within its clearance (``free``) and costs within 1.5 mm more
    (``cost``)."""
    a, b, cl = seg
    return (a, b), max(cl, 0.0) + 1.5 + 0.01


def _soft_reach(seg):
    """A construction line: costs within 0.8 mm (``cost``)."""
    a, b = seg
    return (a, b), 0.8 + 0.01


class _Grid:
    """Obstacles by the square cells (:data:`_CELL` mm) of their reach, kept in step with the
    Placer's list: items appended are added, items popped from the end removed, a list
    replaced is indexed afresh."""

    def __init__(self, reach):
        self.reach = reach
        self.source = None                   # the list indexed
        self.items: list = []                # its items, as indexed
        self.keys: list = []                 # each item's cells (None: tested always)
        self.cells: dict = {}
        self.always: set = set()
        self.memo: dict = {}                 # a cell range -> its items (until a change)

    def _sync(self, lst) -> None:
        if lst is not self.source:
            self.source, self.items, self.keys, self.cells = lst, [], [], {}
            self.always = set()
            self.memo = {}
        n = len(self.items)
        if n == len(lst) and (not n or lst[n - 1] is self.items[n - 1]):
            return                           # unchanged (the common case)
        self.memo = {}
        while n > len(lst) or (n and lst[n - 1] is not self.items[n - 1]):
            n -= 1                           # popped (or changed): drop it from the cells
            keys = self.keys.pop()
            self.items.pop()
            if keys is None:
                self.always.discard(n)
            else:
                for k in keys:
                    self.cells[k].discard(n)
        for i in range(n, len(lst)):
            keys = self._cells_of(lst[i])
            self.items.append(lst[i])
            self.keys.append(keys)
            if keys is None:
                self.always.add(i)
            else:
                for k in keys:
                    self.cells.setdefault(k, set()).add(i)

    def _cells_of(self, item):
        shape, margin = self.reach(item)
        if isinstance(shape, Box):
            return _cover(shape.x0, shape.y0, shape.x1, shape.y1)   # None: huge
        (ax, ay), (bx, by) = shape
        length = math.hypot(bx - ax, by - ay)
        if not math.isfinite(length):
            return None
        n = int(length / (_CELL / 2)) + 1    # samples at most half a cell apart
        if n > _MAX_SAMPLES:
            return None
        m = margin + _CELL / 4               # every point of the segment within a
        keys = set()                         # quarter cell of a sample
        for j in range(n + 1):
            t = j / n
            x, y = ax + t * (bx - ax), ay + t * (by - ay)
            keys.update(_cover(x - m, y - m, x + m, y + m) or ())
        return keys

    def near(self, lst, box: Box, span) -> list:
        """The items of ``lst`` filed under the cells ``span`` (the floor of ``box``'s
        corners over :data:`_CELL`: :meth:`Placer._near`) covers."""
        n = len(self.items)
        if (lst is not self.source or n != len(lst)
                or (n and lst[n - 1] is not self.items[n - 1])):
            self._sync(lst)
        got = self.memo.get(span)
        if got is None:
            i0, j0, i1, j1 = span                  # (the cells _cover(box) lists)
            if (i1 - i0 + 1) * (j1 - j0 + 1) > _MAX_SAMPLES:
                return lst
            found = set(self.always)
            get = self.cells.get
            for i in range(i0, i1 + 1):
                for j in range(j0, j1 + 1):
                    more = get((i, j))
                    if more:
                        found.update(more)
            got = self.memo[span] = [lst[i] for i in found]   # each once; every use is
        return got                                             # order-free


def _cover(x0, y0, x1, y1):
    if not math.isfinite(x0 + x1 + y0 + y1):
        return None
    i0, i1 = math.floor(x0 / _CELL), math.floor(x1 / _CELL)
    j0, j1 = math.floor(y0 / _CELL), math.floor(y1 / _CELL)
    if (i1 - i0 + 1) * (j1 - j0 + 1) > _MAX_SAMPLES:
        return None                                # huge: tested always / against all
    return [(i, j) for i in range(i0, i1 + 1) for j in range(j0, j1 + 1)]


class StrokeCells:
    """Drawn strokes ``(stroke, (a, b))`` by the square cells (``cell`` mm) their segments
    pass near: each segment sampled at most half a cell apart, every sample's cells within a
    quarter cell (so every point of the segment lies in a cell it is filed under; a long
    diagonal construction line is filed under the cells along it, not its bounding box)."""

    def __init__(self, drawn, cell: float = 8.0):
        self.cell, self.cells, self.long, self.all = cell, {}, [], list(drawn)
        q = cell / 4 + 0.01
        for idx, (st, g) in enumerate(self.all):
            (ax, ay), (bx, by) = g
            length = math.hypot(bx - ax, by - ay)
            n = int(length / (cell / 2)) + 1 if math.isfinite(length) else 10 ** 9
            if n > 400:                   # a very long line: tested always
                self.long.append(idx)
                continue
            keys = set()
            for j in range(n + 1):
                x, y = ax + j / n * (bx - ax), ay + j / n * (by - ay)
                for i in range(math.floor((x - q) / cell), math.floor((x + q) / cell) + 1):
                    for k in range(math.floor((y - q) / cell), math.floor((y + q) / cell) + 1):
                        keys.add((i, k))
            for key in keys:
                self.cells.setdefault(key, []).append(idx)

    def near(self, box, reach: float):
        """Every stroke within ``reach`` of ``box`` (and perhaps a few more), each once, in
        no particular order (:func:`diagrams.polygon._owner_cost` asks whether any is near)."""
        c = self.cell
        i0, i1 = int(math.floor((box.x0 - reach) / c)), int(math.floor((box.x1 + reach) / c))
        j0, j1 = int(math.floor((box.y0 - reach) / c)), int(math.floor((box.y1 + reach) / c))
        if (i1 - i0 + 1) * (j1 - j0 + 1) > len(self.all):
            return self.all                  # a reach wider than the grid pays: every stroke
        found = set(self.long)
        cells = self.cells
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                more = cells.get((i, j))
                if more:
                    found.update(more)
        return [self.all[k] for k in sorted(found)]


def largest_gap_direction(at: Pt, others: list[Pt]) -> float | None:
    """The bisector of the widest angular gap between directions from ``at`` to ``others``."""
    angs = sorted(math.atan2(o[1] - at[1], o[0] - at[0]) for o in others
                  if math.hypot(o[0] - at[0], o[1] - at[1]) > 1e-6)
    if not angs:
        return None
    if len(angs) == 1:
        return angs[0] + math.pi
    gaps = [(angs[(i + 1) % len(angs)] - angs[i]) % (2 * math.pi) or 2 * math.pi
            for i in range(len(angs))]
    i = max(range(len(gaps)), key=lambda k: (gaps[k], -k))
    return angs[i] + gaps[i] / 2


def leader(box, to, gap_to: float = 0.3):
    """A thin line from a label's box (0.5 mm off it) to the point ``to`` it names, ending
    ``gap_to`` mm short of it, or None when the label sits right by it (within 1.5 mm)."""
    cx = min(max(to[0], box.x0), box.x1)
    cy = min(max(to[1], box.y0), box.y1)
    d = math.hypot(to[0] - cx, to[1] - cy)
    if d < 1.5:
        return None
    u = ((to[0] - cx) / d, (to[1] - cy) / d)
    return ((round(cx + 0.5 * u[0], 3), round(cy + 0.5 * u[1], 3)),
            (round(to[0] - gap_to * u[0], 3), round(to[1] - gap_to * u[1], 3)))
