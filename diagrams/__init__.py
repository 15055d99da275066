"""Labelled SVG diagrams in construction order: space, velocity and acceleration diagrams.

    from diagrams import write
    write(solution, "out/fig7")        # space.svg, velocity.svg, velocity-1.svg ...

Modules: :mod:`diagrams.polygon` (polygons and their stages, from the step records),
:mod:`diagrams.space` (the mechanism), :mod:`diagrams.scale` (round drawing scales),
:mod:`diagrams.labels` (overlap-free labels), :mod:`diagrams.layout` (the page),
:mod:`diagrams.measure` (lengths read back off the SVGs), :mod:`diagrams.svg` (the only
svgwrite importer), :mod:`diagrams.notation` (textbook labels), :mod:`diagrams.components`
(one look per component kind), :mod:`diagrams.figures` / :mod:`diagrams.handout` (handouts)
and :mod:`diagrams.page` (the interactive construction page).  Nothing here recomputes kinematics: the drawings take their geometry
from ``Solution.steps`` / ``Solution.vertices`` / ``Solution.placement``.
"""
from __future__ import annotations

from pathlib import Path
from typing import Mapping

from .scale import DiagramError, Scale, ScaleError

__all__ = ["drawings", "write", "DiagramError", "ScaleError", "Scale", "options",
           "MAX_STAGED_STEPS"]

#: stage by stage drawings are made for a polygon of at most this many steps; a longer one is
#: drawn finished only (stage k redraws k steps, so n stages hold n²/2 strokes: a 101-link
#: truss's 150 stages were 11,000 strokes and most of ``draw``'s time)
MAX_STAGED_STEPS = 40


def options(sol, scales: Mapping[str, Scale] | None = None, paper: str | None = None,
            stages: bool | None = None) -> dict:
    """Scene ``[diagram]`` options overridden by the caller's (the command line's)."""
    from .scale import options_from_scene
    opts = options_from_scene(sol.scene)
    merged = dict(opts.get("scales", {}))
    merged.update(scales or {})
    return {"scales": merged, "paper": paper or opts.get("paper"),
            "stages": opts.get("stages", True) if stages is None else stages}


def drawings(sol, scales: Mapping[str, Scale] | None = None, paper: str | None = None,
             stages: bool | None = None, text_scale: float = 1.0, klein: str | None = None):
    """Every drawing of a solution, in order: space, then each polygon and its stages (for a
    polygon of at most :data:`MAX_STAGED_STEPS` steps), then (``klein`` or the scene's
    ``[diagram] klein``) Klein's construction and its stages.

    ``text_scale`` enlarges the polygons' labels (for figures printed reduced)."""
    from . import polygon, space
    opts = options(sol, scales, paper, stages)
    sc, paper = opts["scales"], opts["paper"]
    out = [space.drawing(sol, sc.get("space"), paper)]
    for diagram in sol.scene.solve:
        if diagram not in sol.vertices:
            continue
        lay = polygon.layout(sol, diagram, sc.get(diagram), paper, text_scale)
        out.append(polygon.drawing(sol, lay))
        if opts["stages"] and len(lay.con.steps) <= MAX_STAGED_STEPS:
            for k in range(1, len(lay.con.steps) + 1):
                out.append(polygon.drawing(sol, lay, k))
    from . import rolling       # a wheel on a moving surface: its own figure
    out += rolling.drawings(sol, None, paper)
    method = klein or sol.scene.options.diagram.klein
    if method:
        from polygons.classic.klein import figure
        from . import klein as klein_drawing
        out += klein_drawing.drawings(sol, figure(sol, method), sc.get("space"), paper,
                                      opts["stages"])
    return out


def write(sol, outdir, scales: Mapping[str, Scale] | None = None, paper: str | None = None,
          stages: bool | None = None, klein: str | None = None) -> list[Path]:
    """Write every drawing of ``sol`` as ``outdir/<name>.svg``; return the paths."""
    from .svg import to_svg
    outdir = Path(outdir)
    if outdir.exists() and not outdir.is_dir():
        raise DiagramError(f"{outdir} exists and is not a folder", where=str(outdir))
    outdir.mkdir(parents=True, exist_ok=True)
    paths = []
    for d in drawings(sol, scales, paper, stages, klein=klein):
        path = outdir / f"{d.name}.svg"
        path.write_bytes(to_svg(d))
        paths.append(path)
    return paths
