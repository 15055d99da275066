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

from .evaluate import Solution
# what a careful drawing achieves lives with the drawing grader (the page carries it too)
from .grade_drawing import DEFAULT_TOLERANCE, emulated_tolerances, stated_tolerance
from .quantities import drawn_on_polygon

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


__all__ = ["DEFAULT_TOLERANCE", "READING_MM", "tolerance_for", "emulated_tolerances",
           "stated_tolerance"]
