"""Crowded polygons: collinear vectors drawn side by side, tight clusters of vertices enlarged.

Paper mm, y up; no svgwrite, no kinematics.  Two things a textbook figure does by hand:

* **Collinear vectors.**  When two vectors of one polygon lie on one line and overlap (D225's
  oa₁ on oc, SAE4-Q3's ab on ad), the longer keeps its place and the shorter (of equal ones,
  the later) is drawn beside it, moved square to the line by :data:`OFFSET` mm to the side away
  from the polygon's middle (a third one the other side, then further out), with a thin leader
  tick from each of its vertices to its moved ends.  The vector keeps its length and
  direction; only where it is drawn changes (:func:`shifts`).  :func:`collinear_overlap`
  measures the overlap; the tests use it on the written SVGs.
* **Tight clusters.**  Vertices nearer each other than a label's height (but not coincident)
  cannot carry readable labels: :func:`clusters` finds them, and the polygon drawing circles
  each and draws it again enlarged ``k`` × in a free corner, labelled 'detail ×k'.
"""
from __future__ import annotations

import math

Pt = tuple[float, float]
Seg = tuple[Pt, Pt]

#: sideways distance (mm) between two collinear vectors drawn side by side: clears both
#: arrowheads (half-width 1 mm each) with a little white between
OFFSET = 2.2
#: two segments whose ends lie within this (mm) of one line lie on one line
COLLINEAR_MM = 0.6
#: the largest overlap allowed, as a fraction of the shorter segment's length
OVERLAP_FRACTION = 0.1
#: leader ticks run this far (mm) past the moved arrow's end, and start this far off the dot
TICK_PAST = 0.6
TICK_GAP = 0.8


def collinear_overlap(a: Seg, b: Seg, tol: float = COLLINEAR_MM) -> float:
    """The overlap of segments ``a`` and ``b`` lying on one line, as a fraction of the shorter's
    length: 0 when either is shorter than 0.05 mm or they do not lie on one line (the shorter's
    ends more than ``tol`` from the longer's line)."""
    La, Lb = math.dist(*a), math.dist(*b)
    if min(La, Lb) < 0.05:
        return 0.0
    (p0, p1), (q0, q1) = (a, b) if La >= Lb else (b, a)
    L = max(La, Lb)
    ux, uy = (p1[0] - p0[0]) / L, (p1[1] - p0[1]) / L
    if any(abs((q[0] - p0[0]) * uy - (q[1] - p0[1]) * ux) > tol for q in (q0, q1)):
        return 0.0
    s0 = (q0[0] - p0[0]) * ux + (q0[1] - p0[1]) * uy
    s1 = (q1[0] - p0[0]) * ux + (q1[1] - p0[1]) * uy
    ov = min(L, max(s0, s1)) - max(0.0, min(s0, s1))
    return max(0.0, ov) / min(La, Lb)


def _normal(a: Pt, b: Pt) -> Pt:
    """The unit normal of the line a-b, the same for both senses of the line."""
    L = math.dist(a, b)
    ux, uy = (b[0] - a[0]) / L, (b[1] - a[1]) / L
    if ux < -1e-9 or (abs(ux) <= 1e-9 and uy < 0):
        ux, uy = -ux, -uy
    return (-uy, ux)


def _moved(s: Seg, d: Pt) -> Seg:
    return ((s[0][0] + d[0], s[0][1] + d[1]), (s[1][0] + d[0], s[1][1] + d[1]))


def shifts(vectors, middle: Pt) -> dict:
    """{key: (dx, dy)} for the vectors to draw beside a collinear, overlapping other.

    ``vectors`` is a list of (key, tail, tip) in paper mm, in drawing order.  Longest first (of
    equal lengths, the earlier first), each keeps its place unless it overlaps one already
    placed by more than :data:`OVERLAP_FRACTION`; then it moves square to its line by
    1, 2, … × :data:`OFFSET`, first to the side away from ``middle`` (the polygon's middle),
    until it overlaps none.  Shifts are rounded to 0.001 mm (deterministic output).
    """
    order = sorted(range(len(vectors)),
                   key=lambda i: (-round(math.dist(vectors[i][1], vectors[i][2]), 3), i))
    placed = _Placed()
    out = {}
    for i in order:
        key, a, b = vectors[i]
        seg = (a, b)
        if math.dist(a, b) < 0.05:
            continue
        if placed.clear(seg):
            placed.append(seg)
            continue
        n = _normal(a, b)
        mid = ((a[0] + b[0]) / 2 - middle[0], (a[1] + b[1]) / 2 - middle[1])
        outer = 1.0 if mid[0] * n[0] + mid[1] * n[1] >= 0 else -1.0
        for level in range(1, 6):
            found = None
            for sgn in (outer, -outer):
                d = (round(sgn * level * OFFSET * n[0], 3) + 0.0,
                     round(sgn * level * OFFSET * n[1], 3) + 0.0)
                cand = _moved(seg, d)
                if placed.clear(cand):
                    found = (d, cand)
                    break
            if found:
                out[key] = found[0]
                placed.append(found[1])
                break
    return out


class _Placed:
    """The vectors placed so far, by the square cells (:data:`_CELL` mm) within
    :data:`COLLINEAR_MM` of them: two segments that overlap on one line come that near each
    other (the shorter's overlapping part lies within it of the longer), so a new vector is
    tested against the placed ones filed under its own cells only -- the same answer as
    testing every one, without testing N² pairs on a large polygon."""

    def __init__(self):
        self.segs: list[Seg] = []
        self.cells: dict = {}
        self.always: list[int] = []

    @staticmethod
    def _keys(s: Seg, margin: float):
        (ax, ay), (bx, by) = s
        n = int(math.dist(s[0], s[1]) / (_CELL / 2)) + 1     # samples half a cell apart
        if not n <= 2000:
            return None
        m = margin + _CELL / 4
        keys = set()
        for j in range(n + 1):
            x, y = ax + j / n * (bx - ax), ay + j / n * (by - ay)
            for i in range(math.floor((x - m) / _CELL), math.floor((x + m) / _CELL) + 1):
                for k in range(math.floor((y - m) / _CELL), math.floor((y + m) / _CELL) + 1):
                    keys.add((i, k))
        return keys

    def append(self, s: Seg) -> None:
        idx = len(self.segs)
        self.segs.append(s)
        keys = self._keys(s, COLLINEAR_MM + 0.01)
        if keys is None:
            self.always.append(idx)
            return
        for k in keys:
            self.cells.setdefault(k, []).append(idx)

    def clear(self, s: Seg) -> bool:
        """True when ``s`` overlaps no placed vector by more than :data:`OVERLAP_FRACTION`."""
        keys = self._keys(s, 0.0)
        if keys is None:
            near = range(len(self.segs))
        else:
            near = set(self.always)
            for k in keys:
                near.update(self.cells.get(k, ()))
        return all(collinear_overlap(s, self.segs[i]) <= OVERLAP_FRACTION for i in near)


#: the cell (mm) of :class:`_Placed`
_CELL = 8.0


def leader_ticks(tail: Pt, tip: Pt, shift: Pt) -> list[Seg]:
    """The two thin ticks from a moved vector's vertices to its drawn ends (a little past)."""
    d = math.hypot(*shift)
    if d == 0:
        return []
    u = (shift[0] / d, shift[1] / d)
    out = []
    for p in (tail, tip):
        out.append(((round(p[0] + TICK_GAP * u[0], 3), round(p[1] + TICK_GAP * u[1], 3)),
                    (round(p[0] + (d + TICK_PAST) * u[0], 3),
                     round(p[1] + (d + TICK_PAST) * u[1], 3))))
    return out


# ---------------------------------------------------------------- tight clusters of vertices
def clusters(points: dict, near: float, same: float = 0.6) -> list[list[str]]:
    """Groups of vertices (names, sorted) each of which lies within ``near`` mm of another of
    its group, when at least two of the group are not drawn at one place (further apart than
    ``same``): the clusters whose labels would crowd.  Sorted, so deterministic."""
    names = sorted(points)
    parent = {n: n for n in names}

    def find(n):
        while parent[n] != n:
            n = parent[n]
        return n
    for i, n in enumerate(names):
        for m in names[i + 1:]:
            if math.dist(points[n], points[m]) < near:
                parent[find(m)] = find(n)
    groups: dict[str, list[str]] = {}
    for n in names:
        groups.setdefault(find(n), []).append(n)
    out = []
    for g in groups.values():
        if len(g) < 2:
            continue
        spread = max(math.dist(points[a], points[b]) for a in g for b in g)
        if spread > same:
            out.append(g)
    return sorted(out)


def clip_to_circle(a: Pt, b: Pt, c: Pt, r: float) -> Seg | None:
    """The part of segment a-b inside the circle (centre ``c``, radius ``r``), or None."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    fx, fy = a[0] - c[0], a[1] - c[1]
    A = dx * dx + dy * dy
    if A == 0:
        return None
    B = 2 * (fx * dx + fy * dy)
    C = fx * fx + fy * fy - r * r
    disc = B * B - 4 * A * C
    if disc <= 0:
        return None
    s = math.sqrt(disc)
    t0, t1 = max(0.0, (-B - s) / (2 * A)), min(1.0, (-B + s) / (2 * A))
    if t1 - t0 <= 1e-9:
        return None
    return ((a[0] + t0 * dx, a[1] + t0 * dy), (a[0] + t1 * dx, a[1] + t1 * dy))


def mapped(p: Pt, c: Pt, k: float, C: Pt) -> Pt:
    """Point ``p`` of the drawing as the inset shows it: about ``c`` enlarged ``k`` ×, at ``C``."""
    return (round(C[0] + k * (p[0] - c[0]), 3), round(C[1] + k * (p[1] - c[1]), 3))
