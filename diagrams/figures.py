"""The figures of a handout: every diagram of a solution as SVG, the stage figures cropped
to their drawing and sized for the two-column narration, with a scale bar readable once reduced.

Used by :mod:`diagrams.handout`, the gallery's thumbnails and the interactive page.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from polygons.evaluate import Solution
from polygons.plan import Step

from .scale import round_down  # noqa: F401 (figures.round_down: the rule's one home is scale)

DRAWABLE = ("vector", "image", "line", "intersection")
#: width (mm) of a stage figure: the narration runs in two columns, two or three stages a page
STAGE_WIDTH = 56.0
#: every label of a stage figure prints at least this high (mm) once the figure is reduced
#: to its column: the labels are set larger on the reduced figures (and placed anew)
PRINTED_LABEL = 2.5
#: the scale bar's numbers on a reduced stage figure are printed at least this high (mm)
PRINTED_SCALE_TEXT = 2.5
#: ... but never drawn larger than this (mm), so a much-reduced figure's bar stays a bar
MAX_SCALE_TEXT = 18.0
#: labels of the stage figures are set at least this much larger than on the full-size drawings
STAGE_TEXT_SCALE = 1.5
#: tallest printed stage figure (mm)
STAGE_HEIGHT = 44.0
#: a diagram whose stage figures, drawn whole at the finished diagram's scale, print
#: reduced below this (the median: a triad's polygon, its insets far apart, ×0.13) is
#: staged in details: each stage's own vectors at their own stated scale
#: (:func:`detail`)
DETAIL_BELOW = 0.2
#: the printable area (mm) of the handout's A4 portrait page, and the height a finished
#: diagram's heading and note take on it: a finished diagram is printed at its stated scale,
#: so it must fit this (else it is drawn at the round scale that does, and says so)
PAGE = (180.0, 262.0)
PLATE_ROOM = 26.0
#: margin (mm) of a finished diagram as the handout prints it (:func:`plate`): its heading
#: left out (the page's heading names it) and cropped to its drawing, key and legend
PLATE_MARGIN = 3.0
#: a finished diagram is not redrawn at a coarser scale to fit the page once what it draws
#: to scale would be smaller than this (mm, its larger side): smaller, a polygon can no
#: longer be measured nor laid over a drawing; it keeps its first scale, printed reduced
MIN_DRAWN_MM = 30.0


def plate(d):
    """Finished drawing ``d`` as the handout prints it: without its heading, cropped."""
    return trimmed(d, ("heading",), PLATE_MARGIN)


@dataclass
class Figures:
    """The diagrams of one solution: SVG bytes and the drawing records, by name
    ('space', 'velocity', 'velocity-1', ...); ``rescaled`` names the finished diagrams drawn
    at another round scale than asked or chosen for the landscape sheet, so that they print
    on the handout's page at their stated scale: name → (scale first chosen, scale drawn)."""
    svg: dict = field(default_factory=dict)
    drawing: dict = field(default_factory=dict)
    error: str = ""
    rescaled: dict = field(default_factory=dict)


def figures(sol: Solution, scales=None, paper: str | None = None) -> Figures:
    """Every diagram of ``sol`` with its stages, through the public API of :mod:`diagrams`.

    The finished diagrams fit the handout's portrait page at their stated scale (key and
    legend moved below the drawing when beside it they are too wide; else the next round
    scale that fits, recorded in ``rescaled``, while the drawing stays :data:`MIN_DRAWN_MM`
    across: else it keeps its scale and is printed reduced); the stage figures are cropped to their
    drawing, with labels set so that they print :data:`PRINTED_LABEL` mm high or more."""
    import diagrams
    from .layout import MARGIN, restack
    from .svg import to_svg
    out = Figures()
    finals = []
    for d in diagrams.drawings(sol, scales, paper, False):
        first = d.scale_statement
        d = _fitted(sol, restack(d, PAGE[0] + 2 * (MARGIN - PLATE_MARGIN)), paper)
        finals.append(d)
        out.drawing[d.name] = d
        out.svg[d.name] = to_svg(d)
        if d.scale_statement != first:
            out.rescaled[d.name] = (first, d.scale_statement)
    for d in finals:
        lay = d.meta.get("layout")
        # stage k redraws k steps: stage figures only for a polygon of at most
        # diagrams.MAX_STAGED_STEPS steps, as `polygons draw` (a large mechanism's handout
        # shows the finished diagrams and the steps in words)
        if lay is not None and len(lay.con.steps) <= diagrams.MAX_STAGED_STEPS:
            for st in _stages(sol, d.name, lay.scale, paper, lay):
                out.drawing[st.name] = st
                out.svg[st.name] = to_svg(st)
    return out


def _fitted(sol: Solution, d, paper):
    """Finished drawing ``d`` (restacked) at the first round scale, its own or a coarser one,
    at which it fits the page; ``d`` itself when none does while the drawing stays
    :data:`MIN_DRAWN_MM` across (:func:`_readable`) or its key or legend alone is too tall
    (:func:`_never_fits`): printed reduced then, not redrawn until its polygon is a dot."""
    from .layout import MARGIN, restack
    width = PAGE[0] + 2 * (MARGIN - PLATE_MARGIN)
    start = d
    for k in range(12):                        # the next round scales, up to 10⁴ ×
        fit = _fitting_scale(d, jump=k >= 2)
        if fit is None:
            return d
        fit = None if _never_fits(d) else _readable(d, fit)
        if fit is None:
            return start
        d = restack(_redrawn(sol, d, fit, paper), width)
    return d if _fitting_scale(d) is None else start


def _drawn_mm(d):
    """(the larger side (mm) of what drawing ``d`` draws to scale -- a polygon's
    construction, the mechanism's points --, its scale), or None for another drawing."""
    from .labels import bounds
    from .polygon import FRAME_MARGIN
    from .scale import parse
    lay = d.meta.get("layout")
    if lay is not None:
        f = lay.frame
        return max(f.x1 - f.x0, f.y1 - f.y0) - 2 * FRAME_MARGIN, lay.scale
    pos = d.meta.get("positions")
    if d.kind != "space" or not pos:
        return None
    scale = d.meta.get("scale") or parse(d.scale_statement, "length")
    b = bounds(list(pos.values()))
    return max(b.x1 - b.x0, b.y1 - b.y0) * scale.mm_per_si, scale


def _readable(d, scale):
    """``scale`` if drawing ``d`` drawn at it stays :data:`MIN_DRAWN_MM` across, else the
    coarsest round scale between its own and ``scale`` at which it does, None if none is
    coarser than its own."""
    from .scale import make
    got = _drawn_mm(d)
    if got is None:
        return scale
    mm, own = got
    if mm * own.per_cm / scale.per_cm >= MIN_DRAWN_MM - 1e-9:
        return scale
    limit = round_down(own.per_cm * mm / MIN_DRAWN_MM)
    if not limit > own.per_cm * (1 + 1e-9):
        return None
    return make(scale.quantity, limit, forced=True)


def _never_fits(d) -> bool:
    """True when the key or the legend of drawing ``d`` is by itself taller than the page
    leaves a finished diagram (a large mechanism's list of vectors): their rows do not
    shrink with the drawing, so no round scale makes it fit.  The diagram then keeps its
    scale and is printed reduced (:func:`diagrams.handout._plate` says so) instead of being
    redrawn at ever larger scales until its polygon is a dot.  (A legend's rows only grow
    with the scale: a zero polygon adds one.)"""
    from .layout import extent
    room = PAGE[1] - PLATE_ROOM + 1e-9
    for g in d.groups:
        if g.ident in ("key", "legend"):
            b = extent(g.items)
            if b is not None and b.y1 - b.y0 > room:
                return True
    # what does not shrink with the scale (heading, key, legend, the labels beyond the
    # polygon's frame) is taller than the page leaves once the polygon is MIN_DRAWN_MM high
    lay = d.meta.get("layout")
    if lay is not None:
        frame = lay.frame.y1 - lay.frame.y0
        return d.height - frame + MIN_DRAWN_MM > room
    return False


def _fitting_scale(d, jump: bool = False):
    """None if drawing ``d`` fits the page at its scale, else the next round scale (a larger
    value per cm): only the drawing itself shrinks with it, not its text.  ``jump`` (after
    two steps that did not fit: a drawing far too big, a large mechanism): the round scale
    at least as much larger as the drawing is too big, so it fits in a step or two."""
    from .scale import QUANTITY_OF, make, parse, round_up
    t = plate(d)
    if t.width <= PAGE[0] + 1e-9 and t.height <= PAGE[1] - PLATE_ROOM + 1e-9:
        return None
    lay = d.meta.get("layout")
    scale = lay.scale if lay is not None else d.meta.get("scale") or parse(
        d.scale_statement, QUANTITY_OF.get(d.kind, "length"))
    factor = 1.01
    if jump:
        factor = max(factor, t.width / PAGE[0], t.height / (PAGE[1] - PLATE_ROOM))
    return make(scale.quantity, round_up(scale.per_cm * factor), forced=True)


def _redrawn(sol: Solution, d, scale, paper):
    """Finished drawing ``d`` drawn anew at ``scale``."""
    from dataclasses import replace

    from . import polygon, space
    if d.kind == "space":
        new = space.drawing(sol, scale, paper)
        return replace(new, meta={**new.meta, "scale": scale})
    return polygon.drawing(sol, polygon.layout(sol, d.kind, scale, paper))


def _stages(sol: Solution, diagram: str, scale, paper, final=None):
    """The stage figures of ``diagram`` at ``scale``, cropped, labels readable in print.

    The labels' enlargement is estimated from the finished layout ``final`` (labels at their
    own size: the figure's reduction barely depends on them), with a tenth to spare, and
    checked on the figure drawn: one label placement per diagram, rarely two."""
    from dataclasses import replace

    from . import polygon
    from .strokes import construction
    drop = ("heading", "caption", "key", "legend")

    def reduction(lay):
        last = trimmed(polygon.drawing(sol, lay, len(lay.con.steps)), drop)
        return stage_width(last.width, last.height) / last.width

    def staged(lay):
        """The stage figures and the smallest printed height of their labels (mm)."""
        out, least = [], math.inf
        for cell in cells(sol, diagram):
            stage = cell_stage(sol, cell)
            if stage is None:
                continue
            new = {s.number for s in cell if s.kind == "line"}
            if details:
                part = detail(con, stage, new, lay)
                t = polygon.drawing(sol, part, stage)
                t = replace(t, meta={**t.meta, "detail": part.scale.statement})
                t = trimmed(_as_new(t, new), drop)
            else:
                t = trimmed(_as_new(polygon.drawing(sol, lay, stage), new), drop)
            k = stage_width(t.width, t.height) / t.width
            for _ in range(3):      # the larger bar may enlarge the figure, reducing it more
                # (a hundredth to spare for the printed width's rounding)
                r = trimmed(readable_scale_bar(t, k * 0.99), drop)
                k2 = stage_width(r.width, r.height) / r.width
                if k2 >= k * 0.99:
                    break
                k = k2
            r = uncrowded(r)
            out.append(r)
            least = min([least] + [x.size * min(k2, 1.0) for x in _texts(r.groups)
                                   if x.role in LABEL_ROLES])
        return out, least

    smallest = min(polygon.LABEL_SIZE, polygon.LINE_LABEL_SIZE, polygon.VECTOR_LABEL_SIZE)
    first = STAGE_TEXT_SCALE
    if final is not None:
        first = max(first, round(1.1 * PRINTED_LABEL / (smallest * min(reduction(final), 1.0)),
                                 2))
    con = None

    def drawn(ts):
        """The stage figures with labels set ``ts`` larger, enlarged until they print
        PRINTED_LABEL high: checked on the figures drawn, since a stage may be reduced more
        than the last one and a crowded label set smaller (a hundredth to spare for the
        printed width's rounding).  A detail (``details``) gets ``ts`` itself for its
        layout, made per stage."""
        for _ in range(3):
            lay = ts if details else polygon.layout(sol, diagram, scale, paper, ts)
            out, printed = staged(lay)
            if printed >= 1.01 * PRINTED_LABEL:
                break
            ts = round(ts * PRINTED_LABEL / printed * 1.03, 2)
        return out

    details = False
    out = drawn(first)
    shrink = sorted(stage_width(d.width, d.height) / d.width for d in out)
    if shrink and shrink[len(shrink) // 2] < DETAIL_BELOW:
        # drawn whole, the stages print too small to read (a triad's polygon, its labels
        # set larger and its insets far apart): each is drawn as a detail of its own
        # vectors at its own stated scale
        details, con = True, construction(sol, diagram)
        out = drawn(STAGE_TEXT_SCALE)
    return out


#: the drawing area (mm, before a handout's reduction) of a stage detail (:func:`detail`)
DETAIL_MM = (76.0, 30.0)
#: a stage detail enlarges its step at most this much over the stage drawn whole
DETAIL_ZOOM = 50.0
#: an earlier vector shorter than this (mm) is left out of a stage detail's context
DETAIL_CONTEXT_MM = 6.0


def _stroke_points(st) -> list:
    """The SI points stroke ``st`` is drawn through (a line: its anchor)."""
    return [st.a] if st.kind == "line" else [st.a, st.b]


def detail(con, stage: int, also=(), text_scale: float = 1.0,
           size: tuple[float, float] = DETAIL_MM):
    """Stage ``stage`` of ``con`` cropped to its own strokes at its own round scale: the
    scale k (SI per cm) is the finest at which the stage's new strokes (those of its step and
    of the steps ``also`` -- the lines its intersection uses) fit ``size``,
    k = roundup(max(w·10/W, h·10/H)); the window of ``size`` centred on them (on the whole
    stage when that fits too) keeps the earlier strokes and vertices lying in it, drawn
    faded as in any stage figure.  Used where the stage drawn whole at the finished
    diagram's scale is too crowded to read once reduced to a handout's column (a triad)."""
    from dataclasses import replace

    from .labels import Box, bounds
    from .polygon import LABEL_SIZE, layout_of
    from .scale import QUANTITY_OF, make, round_up
    from .text import ASCENT, DESCENT
    upto = con.steps[stage - 1].number
    own = {upto, *also}
    # (an intersection's resultant from the pole, dotted, is drawn when it lies in the
    # window: the detail is the lines and the vertex they fix)
    new = [p for st in con.strokes if st.step in own and st.role != "result"
           for p in _stroke_points(st)]
    so_far = ([p for st in con.strokes if st.step <= upto for p in _stroke_points(st)]
              + [v for n, v in con.vertices.items() if con.born.get(n, 0) <= upto])
    W, H = size

    def per_cm(b: Box) -> float:
        return max((b.x1 - b.x0) * 10.0 / W, (b.y1 - b.y0) * 10.0 / H)
    whole = bounds(so_far)
    k_all = round_up(per_cm(whole)) or 1.0
    nb = bounds(new or so_far)
    k = max(round_up(per_cm(nb)), round_up(k_all / DETAIL_ZOOM)) or k_all
    centre = (whole if k >= k_all else nb).centre
    half = (W * k / 20.0, H * k / 20.0)
    win = Box(centre[0] - half[0], centre[1] - half[1], centre[0] + half[0],
              centre[1] + half[1])
    inside = win.grown(1e-9 * k)
    mm = 10.0 / k
    # the context: an earlier stroke lying in the window and, an arrow, drawn
    # DETAIL_CONTEXT_MM long at least; an earlier vertex not crowding one already kept (the
    # step's own first): no inset for the context, whose vectors the figures before drew
    mine = {st for st in con.strokes if st.step in own and st.role != "result"}
    strokes = tuple(st for st in con.strokes if st.step <= upto and (
        st in mine or all(inside.contains(p) for p in _stroke_points(st)) and (
            st.kind != "arrow" or math.dist(st.a, st.b) * mm >= DETAIL_CONTEXT_MM)))
    ends = {n for st in strokes if st in mine for n in (st.frm, st.to) if n}
    near = (ASCENT + DESCENT) * LABEL_SIZE * text_scale
    vertices = {n: v for n, v in con.vertices.items() if n in ends}
    for st in strokes:
        for n in (st.frm, st.to):
            if not n or n in vertices:
                continue
            v = con.vertices[n]
            if all(math.dist(v, u) * mm >= near for u in vertices.values()):
                vertices[n] = v
    strokes = tuple(st for st in strokes if st in mine
                    or all(n in vertices for n in (st.frm, st.to) if n))
    part = replace(con, strokes=strokes, vertices=vertices)
    return layout_of(part, make(QUANTITY_OF.get(con.diagram, con.diagram), k), win,
                     text_scale)


#: which of two overlapping labels of a stage figure is kept (higher first): the stage's own
#: (not faded) before the earlier ones; among those the new vector's name, its vertex, its
#: construction line; among the earlier ones the vertices, the lines, then the vectors
_KEEP = {(False, "component"): 6, (False, "vertex"): 5, (False, "line"): 4,
         (True, "vertex"): 3, (True, "line"): 2, (True, "component"): 1}


def uncrowded(d):
    """Stage figure ``d`` without the labels that would print on another one: its labels are
    set larger than the finished drawing's so that they print legibly once the figure is
    reduced to its column, and where the polygon is crowded (a triad's near-coincident
    vertices) they no longer all find room.  The thumbnail keeps the stage's new labels and
    drops the earlier ones that collide (an earlier vector's name first, then a line's, then
    a vertex's), measured as the layout audit measures the SVG (:mod:`diagrams.audit`):
    the finished drawing beside it names everything."""
    import xml.etree.ElementTree as ET
    from dataclasses import replace

    from .audit import NS, OVERLAP_MM, _text_box
    from .model import Group, Text
    from .svg import to_svg
    count, what = [0], {}

    def tag(it):
        if isinstance(it, Group):
            return replace(it, items=tuple(tag(i) for i in it.items))
        if isinstance(it, Text):
            count[0] += 1
            what[count[0]] = (it.faded, it.role)
            return replace(it, ident=f"uncrowded-{count[0]}")
        return it
    tagged = replace(d, groups=tuple(tag(g) for g in d.groups))
    texts = []                    # (priority, index, boxes)
    for t in ET.fromstring(to_svg(tagged)).iter(f"{NS}text"):
        ident = t.get("id") or ""
        if not ident.startswith("uncrowded-"):
            continue
        _, _, boxes = _text_box(t)
        i = int(ident.split("-")[1])
        pri = _KEEP.get(what[i], 9)         # a bar's, an inset's text: always kept
        texts.append((pri, i, boxes))
    texts.sort(key=lambda r: (-r[0], r[1]))
    kept, drop = [], set()
    for pri, i, boxes in texts:
        if pri < 9 and any(min(a[2], b[2]) - max(a[0], b[0]) > OVERLAP_MM
                           and min(a[3], b[3]) - max(a[1], b[1]) > OVERLAP_MM
                           for a in boxes for b in kept):
            drop.add(i)
            continue
        kept += boxes
    if not drop:
        return d
    count[0] = 0

    def keep(items):
        out = []
        for it in items:
            if isinstance(it, Group):
                out.append(replace(it, items=keep(it.items)))
                continue
            if isinstance(it, Text):
                count[0] += 1
                if count[0] in drop:
                    continue
            out.append(it)
        return tuple(out)
    return replace(d, groups=keep(d.groups), meta={**d.meta, "dropped": len(drop)})


#: the roles of a stage figure's labels that must print :data:`PRINTED_LABEL` mm high
LABEL_ROLES = ("vertex", "line", "component")


def _texts(items):
    """The Text items among ``items`` (recursively)."""
    from .model import Text
    for it in items:
        if isinstance(it, Text):
            yield it
        elif hasattr(it, "items"):
            yield from _texts(it.items)


def _as_new(d, steps: set[int]):
    """``d`` with the construction lines of ``steps`` drawn as the new step (heavier), not
    faded: the lines a figure's intersection uses are drawn with it."""
    from dataclasses import replace

    from .model import Group
    if not steps:
        return d
    marks = {f"step-{n}" for n in steps}

    def fix(it):
        if isinstance(it, Group):
            return replace(it, items=tuple(fix(i) for i in it.items))
        cls = set(getattr(it, "cls", "").split())
        if not cls & marks:
            return it
        if "construction-line" in cls:
            style = it.style if it.style.endswith("-new") else it.style + "-new"
            return replace(it, faded=False, style=style)
        if "line-label" in cls:
            return replace(it, faded=False)
        return it
    return replace(d, groups=tuple(fix(g) for g in d.groups))


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

    from .layout import extent

    groups = tuple(g for g in d.groups if g.ident not in drop
                   and not set(g.cls.split()) & set(drop))
    box = extent(groups)                 # (the drawing's own extent: diagrams.layout)
    if box is None:
        return d
    x0, x1, y0, y1 = box.x0, box.x1, box.y0, box.y1
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


def cells(sol: Solution, diagram: str) -> list[list[Step]]:
    """The steps of ``diagram`` grouped as the handout shows them, one figure a group: a
    construction line is drawn in the figure of the step that uses it (the intersection
    where it meets another), each vector, image or intersection closes a group; steps that
    draw nothing go with the next figure (the last ones, after every figure, form a group
    of their own)."""
    out: list[list[Step]] = []
    cur: list[Step] = []
    for s in sol.steps:
        if s.diagram != diagram:
            continue
        cur.append(s)
        if s.kind in DRAWABLE and s.kind != "line":
            out.append(cur)
            cur = []
    if cur:
        out.append(cur)
    return out


def cell_stage(sol: Solution, cell: list[Step]) -> int | None:
    """The stage figure of a group of steps (that of its last drawn step), else None."""
    last = cell[-1]
    return stage_of(sol, last) if last.kind in DRAWABLE and last.kind != "line" else None


# ---------------------------------------------------------------- words
