"""Construction lines and their intersection: the only module that imports shapely.

A drawing-board construction ends every dyad by intersecting two lines of unknown length (the
c line with the slider line, the two tangential lines of a four-bar, the Coriolis offset line
with the lever's tangential line).  :func:`intersect` does that with shapely geometry and
reports the angle between the two lines, which is the conditioning of the result: at 90° a
pencil error moves the intersection by the same amount, at 1° by 57 times as much, at 0° (a
toggle or change point) there is no intersection and we raise :class:`ParallelLinesError`.

Both lines are drawn as segments (:func:`drawn_segments`) and intersected by shapely
(:func:`meet_drawn`; :func:`intersect`, for Klein's and Kennedy's constructions).  The staged
solver's :func:`meet` gives the same doubles without building geometries: GEOS's own
arithmetic written out in floats (:mod:`polygons.geos_crossing`), shapely asked only where
GEOS would take another branch.  shapely is imported on first use, so a solve that never
needs it never loads it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import ConstructionError, ParallelLinesError
from .geos_crossing import crossing

#: below this angle two construction lines are treated as parallel (the position is a toggle);
#: an exact toggle computed in floating point leaves ~sqrt(eps) ≈ 1e-6° of angle, hence 1e-5°
PARALLEL_DEG = 1e-5
#: below this angle the construction (and the number) is flagged as ill-conditioned
WARN_DEG = 1.0


@dataclass(frozen=True)
class Line:
    """An infinite construction line: through ``point`` along unit ``direction``."""

    point: tuple[float, float]
    direction: tuple[float, float]
    name: str = ""


@dataclass(frozen=True)
class Intersection:
    point: tuple[float, float]
    angle_deg: float  # acute angle between the two lines, 0..90


def line(point, direction, name: str = "") -> Line:
    """A :class:`Line` through ``point`` along ``direction`` (normalised here)."""
    dx, dy = float(direction[0]), float(direction[1])
    n = math.hypot(dx, dy)
    if n == 0.0 or not math.isfinite(n):
        raise ParallelLinesError(f"construction line {name or '?'} has no direction "
                                 f"(its defining vector is zero)")
    return Line((float(point[0]), float(point[1])), (dx / n, dy / n), name)


def angle_between(l1: Line, l2: Line) -> float:
    """Acute angle in degrees between two lines (0 = parallel, 90 = perpendicular)."""
    cross = abs(l1.direction[0] * l2.direction[1] - l1.direction[1] * l2.direction[0])
    dot = abs(l1.direction[0] * l2.direction[0] + l1.direction[1] * l2.direction[1])
    return math.degrees(math.atan2(cross, dot))


def intersect(l1: Line, l2: Line, *, step: str | None = None) -> Intersection:
    """Intersection point of two construction lines, as shapely computes it
    (:func:`meet_drawn`).

    Raises :class:`ParallelLinesError` below ``PARALLEL_DEG``."""
    angle = angle_between(l1, l2)
    if angle < PARALLEL_DEG:
        raise ParallelLinesError(
            f"the {l1.name or 'first line'} and the {l2.name or 'second line'} are parallel "
            f"(angle {angle:.2g}°): the mechanism is at a toggle or change point and this "
            f"point of the polygon is undefined", step=step)
    if l1.point == l2.point:
        # both lines through one point (an instant at rest: every relative velocity is zero,
        # so the lines of unknown length all start at the pole): they meet there, exactly
        return Intersection(l1.point, angle)
    x, y = meet_drawn(*l1.point, *l1.direction, *l2.point, *l2.direction)
    if x != x:
        raise ConstructionError(
            f"shapely found no single intersection of the {l1.name or 'first line'} and the "
            f"{l2.name or 'second line'}", step=step)
    return Intersection((x, y), angle)


def meet(px, py, ux, uy, qx, qy, vx, vy) -> tuple[float, float]:
    """X = P + t u = Q + s v: the intersection of two construction lines, as shapely finds it
    where they are drawn (NaN, NaN where it finds no single point on both lines) — the same
    doubles as :func:`meet_drawn`, from GEOS's arithmetic written out in floats
    (:func:`polygons.geos_crossing.crossing`); shapely itself where GEOS would branch
    otherwise.  The lines must not be parallel (the caller has checked their angle); P = Q is
    returned as it is (an instant at rest)."""
    if px == qx and py == qy:
        return px, py
    ends, h = drawn_segments(px, py, ux, uy, qx, qy, vx, vy)
    hit = crossing(*ends)
    if hit is None:
        return _shapely_meet(ends, px, py, ux, uy, qx, qy, vx, vy, h)
    return _on_both(hit[0], hit[1], px, py, ux, uy, qx, qy, vx, vy, h)


def meet_drawn(px, py, ux, uy, qx, qy, vx, vy) -> tuple[float, float]:
    """:func:`meet` with the two segments made shapely geometries and intersected by shapely
    (the drawing's own intersection, which :func:`meet` reproduces bit for bit)."""
    if px == qx and py == qy:
        return px, py
    ends, h = drawn_segments(px, py, ux, uy, qx, qy, vx, vy)
    return _shapely_meet(ends, px, py, ux, uy, qx, qy, vx, vy, h)


def drawn_segments(px, py, ux, uy, qx, qy, vx, vy) -> tuple[list, float]:
    """The two construction lines drawn as segments, ([x1, y1, x2, y2, x3, y3, x4, y4], h):
    each from before its anchor to past the crossing.

    With t = ((Q − P) × v) / (u × v) and s = ((Q − P) × u) / (u × v) (the 2×2 solve) the first
    runs from min(0, t) − h to max(0, t) + h along u, the second likewise along v, with
    h = max(|t|, |s|, |P|∞, |Q|∞) / 2: they always cross, are never shorter than the rounding
    of their coordinates, and their end points carry no more rounding than the anchors and the
    crossing do."""
    den = ux * vy - uy * vx
    wx, wy = qx - px, qy - py
    t = (wx * vy - wy * vx) / den
    s = (wx * uy - wy * ux) / den
    h = 0.5 * max(abs(t), abs(s), abs(px), abs(py), abs(qx), abs(qy))
    a0, a1 = min(0.0, t) - h, max(0.0, t) + h
    b0, b1 = min(0.0, s) - h, max(0.0, s) + h
    ends = [px + a0 * ux, py + a0 * uy, px + a1 * ux, py + a1 * uy,
            qx + b0 * vx, qy + b0 * vy, qx + b1 * vx, qy + b1 * vy]
    # components below 1e-200 zeroed: GEOS mishandles subnormal coordinates (a vertical segment
    # at x = -5e-314 met a horizontal one at its end point), and nothing a scene can state is
    # that small (a 1 µm link at 1e-3 rad/s moves at 1e-9 m/s)
    return [0.0 if -1e-200 < c < 1e-200 else c for c in ends], h


def _shapely_meet(ends, px, py, ux, uy, qx, qy, vx, vy, h) -> tuple[float, float]:
    """The drawn segments ``ends`` intersected by shapely, checked on both lines."""
    import numpy as np
    import shapely
    s1, s2 = shapely.linestrings(np.array(ends).reshape(2, 2, 2))
    hit = shapely.intersection(s1, s2)
    xy = shapely.get_coordinates(hit)
    if len(xy) != 1 or shapely.get_type_id(hit) != 0:     # 0: a Point
        return math.nan, math.nan
    x, y = xy[0].tolist()
    return _on_both(x, y, px, py, ux, uy, qx, qy, vx, vy, h)


def _on_both(x, y, px, py, ux, uy, qx, qy, vx, vy, h) -> tuple[float, float]:
    """(x, y) if it lies on both lines (to the rounding of the drawn segments), else NaN."""
    scale = max(abs(px), abs(py), abs(qx), abs(qy), abs(x), abs(y), 2.0 * h)
    off = max(abs(ux * (y - py) - uy * (x - px)), abs(vx * (y - qy) - vy * (x - qx)))
    if not off <= 1e-9 * scale:
        return math.nan, math.nan
    return x, y
