"""Kennedy's theorem on the circle diagram: lines of centres, their intersections (points at
infinity included) and the closure that finds the unknown centres of a set of links.

A centre is finite (``point``) or at infinity (``direction``: every line through it is
parallel to it).  The line through two centres is

* the line through two distinct finite centres;
* the line through a finite centre in the direction of one at infinity;
* **the line at infinity** through two centres at infinity in different directions.

Two lines of centres meet at a finite point, or at infinity in their common direction when
they are parallel; a finite line meets the line at infinity at the point at infinity in its own
direction (the plain double slider: I13, the bar's centre at (60, 80) mm, is where two finite
lines meet, each through a pin in the direction of a block's centre at infinity; I24 is where
the line at infinity I12–I14 meets the finite line I23–I34: at infinity along AB).

The closure takes a *window* of link numbers and, for each unknown pair of it, every line of
centres the window offers (I_ik–I_kj for each k of the window with both known), keeps the first
two distinct ones (the best-conditioned pair when those two cross at under
:data:`WELL_DEG`), and repeats until nothing more is found.  Its cost is the window's size
cubed; a large mechanism is solved in small windows (:mod:`polygons.centres`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from . import geometry
from .errors import ParallelLinesError

Vec = tuple[float, float]

#: two centres (or two lines of centres) closer than this fraction of the mechanism's size
#: are the same
SAME = 1e-9
#: two lines of centres crossing at less than this are replaced by a better pair if one exists
WELL_DEG = 2.0


def pair_name(i: int, j: int) -> str:
    """'13', or '1,13' when a number has two digits."""
    return f"{i}{j}" if i < 10 and j < 10 else f"{i},{j}"


@dataclass(frozen=True)
class Line:
    """A line of centres: through ``point`` along unit ``direction``, or the line at infinity
    (``point`` None)."""

    point: Vec | None
    direction: Vec | None
    name: str

    @property
    def at_infinity(self) -> bool:
        return self.point is None


def canonical(d) -> Vec:
    """A direction at infinity has no sense: pick the one with x > 0 (or y > 0)."""
    x, y = float(d[0]), float(d[1])
    n = math.hypot(x, y)
    x, y = x / n, y / n
    if x < 0 or (x == 0 and y < 0):
        x, y = -x, -y
    return (x + 0.0, y + 0.0)


def _parallel(d1: Vec, d2: Vec) -> bool:
    s = abs(d1[0] * d2[1] - d1[1] * d2[0])
    return math.degrees(math.asin(min(1.0, s))) < geometry.PARALLEL_DEG


def line_through(c1, c2, name: str, size: float) -> Line | None:
    """The line of centres through centres ``c1`` and ``c2`` (each with ``point`` or
    ``direction``); None when it is undefined (the two centres are one point)."""
    p1, p2 = c1.point, c2.point
    if p1 is not None and p2 is not None:
        d = (p2[0] - p1[0], p2[1] - p1[1])
        n = math.hypot(*d)
        if n <= SAME * size:
            return None
        return Line(p1, (d[0] / n, d[1] / n), name)
    if (p1 is None and c1.direction is None) or (p2 is None and c2.direction is None):
        return None                     # a centre that is everywhere (no relative motion)
    if p1 is not None:
        return Line(p1, c2.direction, name)
    if p2 is not None:
        return Line(p2, c1.direction, name)
    if c1.direction is None or c2.direction is None or _parallel(c1.direction, c2.direction):
        return None                     # one point at infinity: no line
    return Line(None, None, name)       # the line at infinity


def same_line(l1: Line, l2: Line, size: float) -> bool:
    if l1.at_infinity or l2.at_infinity:
        return l1.at_infinity and l2.at_infinity
    if not _parallel(l1.direction, l2.direction):
        return False
    dx, dy = l2.point[0] - l1.point[0], l2.point[1] - l1.point[1]
    return abs(l1.direction[0] * dy - l1.direction[1] * dx) <= SAME * max(size, 1e-300)


def angle_of(l1: Line, l2: Line) -> float:
    """The angle (degrees, 0–90) the two lines cross at; 90 for a finite line and the line at
    infinity (their meeting is exact: the finite line's own direction)."""
    if l1.at_infinity or l2.at_infinity:
        return 90.0
    s = abs(l1.direction[0] * l2.direction[1] - l1.direction[1] * l2.direction[0])
    return math.degrees(math.asin(min(1.0, s)))


def meet(l1: Line, l2: Line, step: str) -> tuple[Vec | None, Vec | None, float]:
    """(point, direction at infinity, angle) where two distinct lines of centres meet."""
    if l1.at_infinity:
        return None, canonical(l2.direction), 90.0
    if l2.at_infinity:
        return None, canonical(l1.direction), 90.0
    try:
        hit = geometry.intersect(geometry.line(l1.point, l1.direction, l1.name),
                                 geometry.line(l2.point, l2.direction, l2.name), step=step)
    except ParallelLinesError:          # two parallel lines meet at infinity
        return None, canonical(l1.direction), 0.0
    return (float(hit.point[0]), float(hit.point[1])), None, float(hit.angle_deg)


@dataclass(frozen=True)
class Found:
    """A centre found by Kennedy: where, the two lines (each as the labels of the two centres
    it joins) and in words."""

    point: Vec | None
    direction: Vec | None
    lines: tuple[tuple[str, str], tuple[str, str]]
    via: tuple[int, int]                # the third links k of the two triangles
    angle_deg: float


def kennedy(i: int, j: int, window, known, size: float) -> Found | None:
    """I_ij from the lines of centres I_ik–I_kj, k in ``window`` (``known``: (a, b) with
    a < b → the centre record), or None if fewer than two distinct lines are known."""
    lines: list[tuple[Line, int, tuple[str, str]]] = []
    for k in window:
        if k == i or k == j:
            continue
        a = known.get((i, k) if i < k else (k, i))
        if a is None:
            continue
        b = known.get((k, j) if k < j else (j, k))
        if b is None:
            continue
        ln = line_through(a, b, f"line I{pair_name(i, k)}–I{pair_name(k, j)}", size)
        if ln is None or any(same_line(ln, m, size) for m, _, _ in lines):
            continue
        lines.append((ln, k, (a.label, b.label)))
        if len(lines) == 2 and angle_of(lines[0][0], lines[1][0]) >= WELL_DEG:
            break
    if len(lines) < 2:
        return None
    best = (0, 1)
    if angle_of(lines[0][0], lines[1][0]) < WELL_DEG:
        score = -1.0
        for a in range(len(lines)):
            for b in range(a + 1, len(lines)):
                s = angle_of(lines[a][0], lines[b][0])
                if s > score + 1e-12:
                    score, best = s, (a, b)
    (l1, k1, n1), (l2, k2, n2) = lines[best[0]], lines[best[1]]
    point, direction, angle = meet(l1, l2, f"centre I{pair_name(i, j)}")
    return Found(point, direction, (n1, n2), (k1, k2), angle)


__all__ = ["SAME", "WELL_DEG", "Line", "Found", "pair_name", "canonical", "line_through",
           "same_line", "angle_of", "meet", "kennedy"]
