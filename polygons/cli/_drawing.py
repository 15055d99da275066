"""``polygons check SCENE --drawing FILE``: the report of a graded drawn polygon.

The grading is :func:`polygons.grade_drawing.grade`; the file format is
:mod:`polygons.drawing_format`.  Exit status 0 when every vector and closure is right, 3 when
something is off (like ``--measured``), 1 on an unreadable file.
"""
from __future__ import annotations

import math

from ..notation import vertex

from ..errors import SceneError


def grade_file(sol, path: str, emulated: dict, stated: float):
    from ..drawing_format import read_drawing
    from ..grade_drawing import grade
    drawing = read_drawing(path)
    if drawing.diagram not in sol.vertices:
        raise SceneError(f"the drawing is a {drawing.diagram} polygon, which this scene does "
                         f"not construct (solve = {list(sol.scene.solve)})", file=path,
                         where="diagram")
    return grade(sol, drawing, emulated, stated)


def report(sol, g, path: str) -> str:
    what = "Velocity" if g.diagram == "velocity" else "Acceleration"
    lines = [f"{sol.scene.title}", f"  drawing: {path}",
             f"  {what} polygon at {g.scale_text}: {g.score:g} of {g.out_of} vectors"
             + (" — all right" if g.ok else ""),
             "  (tolerances: length from the drawing-board emulation's 95th percentile of "
             "each quantity, never under 1.0 mm of paper; direction from the instruments: "
             "protractor ±0.25°, pencil ±0.25 mm; a line is graded by its direction through "
             "your own vertices, its length is your own; a value shown equal to its "
             "tolerance is within it)", ""]
    for m in g.marks:
        verdict = "ok " if m.mark == 1 else ("1/2" if m.mark == 0.5 else "OFF")
        detail = ""
        if m.drawn and m.angle_err_deg is not None:
            detail = f"  direction {m.angle_err_deg:+.1f}° (± {m.direction_tol_deg:.1f}°)"
            if m.length_err_pct is not None:
                detail += f", length {m.length_err_pct:+.1f} % (± {m.length_tol_pct:.1f} %)"
        lines.append(f"  {verdict}  {m.shown:<8} {'line ' if m.line else ''}{m.rule}{detail}")
        if m.problem:
            lines.append(f"       {m.problem}")
        if m.note:
            lines.append(f"       {m.note}")
        if m.hint and m.mark < 1:
            lines.append(f"       hint: {m.hint}")
    names = {v: vertex(v) for v in sol.vertices[g.diagram]}
    for c in g.closures:
        lines.append(f"  {'ok ' if c.ok else 'OFF'}  closure at {names.get(c.vertex, c.vertex)}"
                     f": {c.off_mm:.2f} mm from where its lines meet (± {c.tol_mm:.2f} mm)")
        if c.hint:
            lines.append(f"       hint: {c.hint}")
    if g.extras:
        lines.append(f"  also drawn: {', '.join(m.shown for m in g.extras)} (joining your own "
                     f"vertices: not graded on its own)")
    if g.unknown:
        lines.append(f"  not graded: vertices {', '.join(g.unknown)} are not in the "
                     f"construction (its vertices: "
                     f"{', '.join(vertex(v) for v in sorted(sol.vertices[g.diagram]))}, "
                     f"written {', '.join(sorted(sol.vertices[g.diagram]))} in a file; the "
                     f"pole may also be called o)")
    return "\n".join(lines) + "\n"


def _f(x):
    """A number JSON can carry (an infinite or undefined one is null)."""
    return x if x is None or math.isfinite(x) else None


def mark_json(m) -> dict:
    return {"vector": m.name, "shown": m.shown, "rule": m.rule, "step": m.step,
            "line": m.line, "drawn": m.drawn, "mark": m.mark,
            "direction_ok": m.direction_ok, "sense_ok": m.sense_ok, "length_ok": m.length_ok,
            "angle_error_deg": _f(m.angle_err_deg), "length_error_pct": _f(m.length_err_pct),
            "direction_tolerance_deg": _f(m.direction_tol_deg),
            "length_tolerance_pct": _f(m.length_tol_pct), "problem": m.problem,
            "hint": m.hint, "note": m.note}


def grade_json(g) -> dict:
    """The grade as plain data (what the page's grade.js returns, field for field)."""
    return {"diagram": g.diagram, "scale": g.scale_text, "score": g.score,
            "out_of": g.out_of, "all_ok": g.ok, "vectors": [mark_json(m) for m in g.marks],
            "extras": [mark_json(m) for m in g.extras],
            "closures": [{"vertex": c.vertex, "off_mm": _f(c.off_mm),
                          "tolerance_mm": _f(c.tol_mm), "ok": c.ok, "hint": c.hint}
                         for c in g.closures],
            "carried_ratio": _f(g.scale_ratio), "unknown_vertices": list(g.unknown)}


def to_json(sol, g, path: str) -> dict:
    return {"case": {"file": sol.scene.file, "title": sol.scene.title}, "drawing": path,
            **grade_json(g)}
