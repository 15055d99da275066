"""The figures of a handout: every diagram of a solution as SVG, the stage figures cropped
to their drawing and sized for the two-column narration, with a scale bar readable once reduced.

Used by :mod:`diagrams.handout`, the gallery's thumbnails and the interactive page.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from polygons.evaluate import Solution
from polygons.plan import Step

DRAWABLE = ("vector", "image", "line", "intersection")
#: width (mm) of a stage figure: the narration runs in two columns, two or three stages a page
STAGE_WIDTH = 86.0
#: the scale bar's numbers on a reduced stage figure are printed at least this high (mm)
PRINTED_SCALE_TEXT = 2.3
#: ... but never drawn larger than this (mm), so a much-reduced figure's bar stays a bar
MAX_SCALE_TEXT = 4.5
#: labels of the stage figures are set this much larger than on the full-size drawings
STAGE_TEXT_SCALE = 1.5
#: tallest printed stage figure (mm)
STAGE_HEIGHT = 52.0


@dataclass
class Figures:
    """The diagrams of one solution: SVG bytes and the drawing records, by name
    ('space', 'velocity', 'velocity-1', ...)."""
    svg: dict = field(default_factory=dict)
    drawing: dict = field(default_factory=dict)
    error: str = ""


def figures(sol: Solution, scales=None, paper: str | None = None) -> Figures:
    """Every diagram of ``sol`` with its stages, through the public API of :mod:`diagrams`."""
    import diagrams
    from .svg import to_svg
    out = Figures()
    for d in diagrams.drawings(sol, scales, paper, True):
        out.drawing[d.name] = d
        if d.stage is None:
            out.svg[d.name] = to_svg(d)
    # the stage figures print reduced: their labels are set larger (placed anew, clear of
    # each other as on every drawing) and their scale bar readable
    for d in diagrams.drawings(sol, scales, paper, True, STAGE_TEXT_SCALE):
        if d.stage is not None:
            t = trimmed(d, ("heading", "caption", "key", "legend"))
            t = trimmed(readable_scale_bar(t, stage_width(t.width, t.height) / t.width),
                        ("heading", "caption", "key", "legend"))
            out.svg[d.name] = to_svg(t)
    return out


def readable_scale_bar(d, reduction: float):
    """``d`` with its scale bar redrawn so its numbers print at least
    :data:`PRINTED_SCALE_TEXT` mm high once the figure is reduced by ``reduction``."""
    from dataclasses import replace

    from .layout import SCALE_SIZE, scale_bar
    from .model import Segment
    lay = d.meta.get("layout")
    if lay is None or reduction >= 1.0:
        return d
    size = min(max(SCALE_SIZE, PRINTED_SCALE_TEXT / reduction), MAX_SCALE_TEXT)
    groups = []
    for g in d.groups:
        if g.ident != "scale-bar":
            groups.append(g)
            continue
        line = next(it for it in g.items if isinstance(it, Segment))
        x0, y0 = line.a
        # no longer than the drawing above it, so the bar does not widen the figure
        drawn = [b for other in d.groups if other.ident != "scale-bar"
                 for b in _extent(other.items)]
        room = (max(drawn) - x0) if drawn else line.b[0] - line.a[0]
        bar, _, _ = scale_bar(lay.scale, max(20.0, min(line.b[0] - line.a[0], room)) + 0.01,
                              size=size, statement=False)
        groups.append(bar.moved(x0, y0 - (size - SCALE_SIZE) * 1.2))   # clear of the drawing
    return replace(d, groups=tuple(groups))


def _extent(items) -> list[float]:
    """x coordinates (mm) reached by ``items`` (recursively): their right-hand extent."""
    from .labels import text_box
    from .model import Arrow, Circle, Polyline, Segment, Text
    xs: list[float] = []
    for it in items:
        if isinstance(it, Segment):
            xs += [it.a[0], it.b[0]]
        elif isinstance(it, Polyline):
            xs += [p[0] for p in it.points]
        elif isinstance(it, Circle):
            xs.append(it.centre[0] + it.r)
        elif isinstance(it, Arrow):
            xs += [it.drawn[0][0], it.drawn[1][0]]
        elif isinstance(it, Text):
            xs.append(text_box(it.x, it.baseline, it.text, it.size, it.anchor).x1)
        elif hasattr(it, "items"):
            xs += _extent(it.items)
    return xs


def stage_width(natural: float, height: float | None = None) -> float:
    """Printed width (mm) of a stage figure ``natural`` × ``height`` mm: one of the two
    columns, and no taller than :data:`STAGE_HEIGHT` so three rows of stages fit a page."""
    w = min(natural, STAGE_WIDTH)
    if height:
        w = min(w, STAGE_HEIGHT * natural / height)
    return w


def trimmed(d, drop: tuple[str, ...] = ("heading", "caption"), margin: float = 3.0):
    """A copy of drawing ``d`` without the groups named in ``drop`` (their ident or class),
    cropped to what is left: the stage figures inside the narration need neither their own
    title nor their caption, since the handout's text says both."""
    from dataclasses import replace

    from .labels import text_box
    from .model import Arrow, Circle, Polyline, Segment, Text

    groups = tuple(g for g in d.groups if g.ident not in drop
                   and not set(g.cls.split()) & set(drop))
    xs: list[float] = []
    ys: list[float] = []

    def walk(items):
        for it in items:
            if hasattr(it, "items") and not isinstance(it, (Segment, Polyline, Circle, Arrow,
                                                            Text)):
                walk(it.items)
            elif isinstance(it, Segment):
                xs.extend((it.a[0], it.b[0]))
                ys.extend((it.a[1], it.b[1]))
            elif isinstance(it, Polyline):
                xs.extend(p[0] for p in it.points)
                ys.extend(p[1] for p in it.points)
            elif isinstance(it, Circle):
                xs.extend((it.centre[0] - it.r, it.centre[0] + it.r))
                ys.extend((it.centre[1] - it.r, it.centre[1] + it.r))
            elif isinstance(it, Arrow):
                pts = [*it.drawn, *((p[0] + it.shift[0], p[1] + it.shift[1]) for p in it.head)]
                xs.extend(p[0] for p in pts)
                ys.extend(p[1] for p in pts)
            elif isinstance(it, Text):
                b = text_box(it.x, it.baseline, it.text, it.size, it.anchor)
                xs.extend((b.x0, b.x1))
                ys.extend((b.y0, b.y1))
    walk(groups)
    if not xs:
        return d
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    dx, dy = margin - x0, margin - y0
    return replace(d, width=round(x1 - x0 + 2 * margin, 1),
                   height=round(y1 - y0 + 2 * margin, 1),
                   groups=tuple(g.moved(dx, dy) for g in groups))


def stage_of(sol: Solution, step: Step) -> int | None:
    """Stage number (1, 2 ...) of a drawn step in its diagram's stage figures, else None."""
    if step.kind not in DRAWABLE:
        return None
    k = 0
    for s in sol.steps:
        if s.diagram == step.diagram and s.kind in DRAWABLE:
            k += 1
            if s.number == step.number:
                return k
    return None


# ---------------------------------------------------------------- words
