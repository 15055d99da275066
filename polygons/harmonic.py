"""The simple-harmonic comparison of a slider's sweep: the crank pin projected on the slider's
line of stroke (a Scotch yoke with the same crank)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import PolygonsError
from .scene import Crank


@dataclass(frozen=True)
class Harmonic:
    """The simple-harmonic curve a slider would follow if it were driven by the crank pin's
    projection on its line of stroke (a Scotch yoke with the same crank): ``travel``,
    ``velocity``, ``acceleration`` arrays (N,), signed along the slider's guide; ``offset`` is
    the constant added to the projection so both strokes have the same centre (the harmonic
    *motion* has no preferred origin)."""

    point: str
    pin: str
    travel: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    offset: float


def harmonic(sw, point: str) -> Harmonic:
    """The SHM curve for slider ``point``: the crank pin projected on ``point``'s guide."""
    scene = sw.scene
    drv = scene.driver
    if not isinstance(drv, Crank):
        raise PolygonsError("the simple-harmonic comparison needs a crank driver",
                            file=scene.file)
    if point not in scene.model.guide or point not in sw.travel:
        raise PolygonsError(f"the simple-harmonic comparison is for a slider; {point} has no "
                            f"guide", file=scene.file, where=point)
    ex, ey = scene.model.guide[point].line.direction
    px, py = scene.ground[drv.pivot]
    (ax, ay), (vx, vy), (aax, aay) = sw.pos[drv.tip], sw.vel[drv.tip], sw.acc[drv.tip]
    proj = (ax - px) * ex + (ay - py) * ey
    tr = sw.travel[point]
    offset = float(0.5 * (np.nanmax(tr) + np.nanmin(tr)) - 0.5 * (np.nanmax(proj) + np.nanmin(proj)))
    return Harmonic(point, drv.tip, proj + offset, vx * ex + vy * ey, aax * ex + aay * ey,
                    offset)
