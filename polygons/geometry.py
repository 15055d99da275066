"""Construction lines and their intersection: the only module that imports shapely.

A drawing-board construction ends every dyad by intersecting two lines of unknown length (the
c line with the slider line, the two tangential lines of a four-bar, the Coriolis offset line
with the lever's tangential line).  :func:`intersect` does that with shapely geometry and
reports the angle between the two lines, which is the conditioning of the result: at 90° a
pencil error moves the intersection by the same amount, at 1° by 57 times as much, at 0° (a
toggle or change point) there is no intersection and we raise :class:`ParallelLinesError`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from .errors import ConstructionError, ParallelLinesError

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
    d = np.asarray(direction, dtype=float)
    n = math.hypot(d[0], d[1])
    if n == 0.0 or not math.isfinite(n):
        raise ParallelLinesError(f"construction line {name or '?'} has no direction "
                                 f"(its defining vector is zero)")
    return Line((float(point[0]), float(point[1])), (float(d[0] / n), float(d[1] / n)), name)


def angle_between(l1: Line, l2: Line) -> float:
    """Acute angle in degrees between two lines (0 = parallel, 90 = perpendicular)."""
    cross = abs(l1.direction[0] * l2.direction[1] - l1.direction[1] * l2.direction[0])
    dot = abs(l1.direction[0] * l2.direction[0] + l1.direction[1] * l2.direction[1])
    return math.degrees(math.atan2(cross, dot))


def intersect(l1: Line, l2: Line, *, step: str | None = None) -> Intersection:
    """Intersection point of two construction lines, as shapely computes it.

    Each line is drawn as a segment long enough to contain the intersection: with anchors a
    distance ``d`` apart and an angle ``θ`` between the lines the intersection lies within
    ``d / sin θ`` of either anchor, so segments of half-length ``2 d / sin θ`` (plus the scale
    of the anchors) always cross.  Raises :class:`ParallelLinesError` below ``PARALLEL_DEG``.
    """
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
    p, q, u, v = (_flush(np.array(x)) for x in (l1.point, l2.point, l1.direction,
                                                 l2.direction))
    scale = max(float(np.hypot(*p)), float(np.hypot(*q)), float(np.hypot(*(p - q))), 1e-300)
    half = 2.0 * scale / math.sin(math.radians(angle)) + scale
    s1 = shapely.LineString(_flush(np.array([p - half * u, p + half * u])))
    s2 = shapely.LineString(_flush(np.array([q - half * v, q + half * v])))
    hit = shapely.intersection(s1, s2)
    if hit.is_empty or hit.geom_type != "Point":
        raise ParallelLinesError(
            f"the {l1.name or 'first line'} and the {l2.name or 'second line'} do not meet "
            f"in a single point (got {hit.geom_type})", step=step)
    x = np.array([hit.x, hit.y])
    # the point must lie on both lines (to rounding of the segments' length)
    off = max(abs(float(u[0] * (x - p)[1] - u[1] * (x - p)[0])),
              abs(float(v[0] * (x - q)[1] - v[1] * (x - q)[0])))
    if not off <= 1e-9 * half:
        raise ConstructionError(
            f"the intersection of the {l1.name or 'first line'} and the "
            f"{l2.name or 'second line'} came back {off:.3g} off the lines", step=step)
    return Intersection((float(x[0]), float(x[1])), angle)


def _flush(a: np.ndarray) -> np.ndarray:
    """Zero the components below 1e-200 in magnitude: GEOS mishandles subnormal coordinates
    (a vertical segment at x = -5e-314 met a horizontal one at its end point), and nothing a
    scene can state is that small (a 1 µm link at 1e-3 rad/s moves at 1e-9 m/s)."""
    return np.where(np.abs(a) < 1e-200, 0.0, a)
