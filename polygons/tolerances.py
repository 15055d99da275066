"""How close a careful drawing comes: the tolerance a measured value is graded against.

A value read off a drawing is expected within the larger of

* what a careful drawing achieves: the 95th percentile of that quantity's error in the
  drawing-board emulation (:func:`emulated_tolerances`), else the case's stated drawing
  tolerance (:func:`stated_tolerance`, ``[source] drawing_tolerance``, default 2 %);
* a ruler reading of ±0.5 mm (:data:`READING_MM`) on the line of the polygon the value is read
  from, at the scale it is drawn to (:func:`tolerance_for`): a short vector cannot be read
  to 2 %.

Shared by ``polygons check`` (:mod:`polygons.cli.check`) and the exam's answer keys
(:mod:`polygons.exam.variants`), below both.
"""
from __future__ import annotations

import math

from .errors import UnsupportedError
from .evaluate import Solution
from .quantities import drawn_on_polygon
from .units import parse_quantity

#: the drawing tolerance of a case that states none (a fraction)
DEFAULT_TOLERANCE = 0.02
#: a ruler reading, mm of paper
READING_MM = 0.5


def tolerance_for(sol: Solution, expr: str, expected: float, pct: float,
                  scales: dict) -> float:
    """tol = max(pct |expected|, 0.5 mm of paper at the diagram's scale, as a share of the
    drawn length of ``expr``'s vector); ``scales``: diagram name → its scale."""
    tol = pct * abs(expected)
    diagram, drawn = drawn_on_polygon(sol, expr, expected)
    sc = scales.get(diagram)
    if sc is not None:
        reading = READING_MM / sc.mm_per_si          # SI value of 0.5 mm of paper
        if drawn > 0:
            tol = max(tol, reading * abs(expected) / drawn)
        else:
            tol = max(tol, reading)
    return tol


def emulated_tolerances(sol: Solution, trials: int = 400) -> dict[str, float]:
    """{expression: relative tolerance}: the 95th percentile of a careful drawing's error from
    the drawing-board emulation (:mod:`polygons.drawing_board`: pencil and rule ±0.25 mm,
    protractor ±0.25°), at this case's crank angle; {} when the emulation does not cover the
    case (a slider driver, or a dyad it does not draw).  Fixed seed, so the grading is reproducible."""
    from . import drawing_board
    from .scene import Crank
    drv = sol.scene.driver
    if not isinstance(drv, Crank):
        return {}
    try:
        result = drawing_board.summary(drawing_board.emulate(sol.scene, [drv.angle],
                                                             trials=trials, seed=1))
    except UnsupportedError:  # a dyad the emulation does not draw: the stated ± % applies
        return {}
    out = {}
    for q, stats in result.items():        # keyed by the typed quantity (scene.Quantity)
        p95 = float(stats["p95"])
        if math.isfinite(p95) and p95 > 0:
            out[str(q)] = p95
    return out


def stated_tolerance(sol: Solution) -> float:
    """The case's ``[source] drawing_tolerance`` as a fraction (:data:`DEFAULT_TOLERANCE`
    when it states none)."""
    text = sol.scene.source.get("drawing_tolerance")
    if text is None:
        return DEFAULT_TOLERANCE
    return parse_quantity(text, "fraction")


__all__ = ["DEFAULT_TOLERANCE", "READING_MM", "tolerance_for", "emulated_tolerances",
           "stated_tolerance"]
