"""`polygons exam`: seeded, well-conditioned variants of one scene and their export.

:mod:`polygons.exam.variants` draws the variants (the scene's ``[exam]`` ranges, checked by
:mod:`polygons.exam_table`), solves each one and keeps those whose construction is well
conditioned; :mod:`polygons.exam.lms` writes them as Moodle XML, GIFT and a QTI 1.2 package.
The printed key and worksheets are drawn by :mod:`diagrams.exam_sheets` (the command joins the
two: this package never imports ``diagrams``).
"""
from .variants import Asked, ExamSet, Variant, make_exam, MAX_VARIANTS

__all__ = ["Asked", "ExamSet", "Variant", "make_exam", "MAX_VARIANTS"]
