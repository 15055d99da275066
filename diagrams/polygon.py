"""Velocity and acceleration polygons, final and stage by stage, from the step records.

Nothing here computes kinematics: every vertex, vector and construction line is read from the
evaluated :class:`~polygons.plan.Step` records (``at``, ``vector``, ``point``, ``direction``)
and ``Solution.vertices``.  What this module decides is how each record looks on paper:

* a 'vector' or 'image' step is an arrow ``at → point`` (the Coriolis vector drawn heavy with
  an open head, an image vector with the thin side that closes its image triangle);
* a 'line' step is a dashed construction line of unknown length through ``at`` along
  ``direction``, labelled with what the step draws ('c line', 'slider line', 'Coriolis offset
  line'); the Coriolis offset line also shows its offset from the pin's vertex, dotted;
* an 'intersection' step fixes a vertex: the parts of its two lines up to the vertex become
  arrows (anchor → vertex; for the slot line, vertex → anchor: the pin's velocity relative to
  the lever point) and the absolute vector pole → vertex is added, dotted, if not yet drawn;
* 'measure' steps draw nothing; their values go to the legend.

Every vector is drawn in the look of its component kind (:func:`diagrams.components.component_of`)
and named at its midpoint; the asked quantities of the scene (``[[answers]]``) are drawn too
(absolute ones from the pole), so every diagram closes to the question.  Stage k of a diagram
shows every drawable step up to the k-th, the k-th heavier, the earlier ones lighter, with
the step's sentence in the drawings' notation as the caption.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from polygons.evaluate import Solution
from polygons.narrate import substitute
from polygons.plan import Step
from polygons.steps import tail_name

from . import crowd, inset, scale as scales
from .labels import (Box, Placer, StrokeCells, bounds, box_hits_segment, box_segment_distance,
                     clip_line, largest_gap_direction, leader)
from .layout import arrow_head, compose
from .components import LOOKS, ORDER
from .model import Arrow, Circle, Drawing, Group, Polyline, Segment, Text
from .notation import mark_drawing, vector
from .polywords import along_words, measure_text, prose  # noqa: F401 (the polygon's words)
from .strokes import Construction, Stroke, construction
from .text import ASCENT, DESCENT, display, number, token

Pt = tuple[float, float]

LABEL_SIZE = 3.5
LINE_LABEL_SIZE = 2.7
VECTOR_LABEL_SIZE = 2.6
FRAME_MARGIN = 10.0     # construction lines run this far (mm) beyond the polygon
QUANTITY = {"velocity": "velocity", "acceleration": "acceleration"}

# ---------------------------------------------------------------- layout of the final drawing
@dataclass(frozen=True)
class Layout:
    """The final polygon on paper (content coordinates, mm): shared by all its stages."""
    con: Construction
    scale: scales.Scale
    origin: Pt                       # SI point drawn at content (0, 0)
    frame: Box
    vertex_labels: tuple             # (names tuple, x, baseline, box)
    line_labels: dict                # step number -> (text, x, baseline, box)
    vector_labels: dict              # (step, frm, to) -> (text, x, baseline, box)
    text_scale: float = 1.0          # labels × this (a figure printed reduced: larger labels)
    shifts: dict = field(default_factory=dict)   # (step, frm, to) -> (dx, dy) mm: drawn beside
    insets: tuple = ()               # diagrams.inset.Inset: tight clusters drawn enlarged
    leaders: tuple = ()              # (step, (frm, to), (a, b)): a vector's name led to it
    ghosts: frozenset = frozenset()  # (frm, to) of the vectors too short for any inset

    def size(self, base: float) -> float:
        return round(base * self.text_scale, 3)

    def P(self, v: Pt) -> Pt:
        k = self.scale.mm_per_si
        return (round((v[0] - self.origin[0]) * k, 3), round((v[1] - self.origin[1]) * k, 3))


def _extent_points(con: Construction) -> list[Pt]:
    pts = list(con.vertices.values())
    for st in con.strokes:
        if st.kind in ("line", "offset"):
            pts.append(st.a)
        if st.kind == "offset":
            pts.append(st.b)
    return pts


def scale_of(sol: Solution, diagram: str, scale: scales.Scale | None = None,
             paper: str | None = None):
    """(scale, construction, its extent box): the scale :func:`layout` draws ``diagram`` to
    (``scale`` checked, else the round scale chosen for ``paper``), without placing a label
    (``polygons check`` grades against it)."""
    con = construction(sol, diagram)
    bb = bounds(_extent_points(con))
    extent = (bb.x1 - bb.x0, bb.y1 - bb.y0)
    lengths = [math.hypot(s.b[0] - s.a[0], s.b[1] - s.a[1]) for s in con.strokes
               if s.kind == "arrow"]
    if scale is None:
        scale = scales.choose(QUANTITY[diagram], extent, lengths, paper)
    scales.check_size(scale, extent, diagram)
    return scale, con, bb


def layout(sol: Solution, diagram: str, scale: scales.Scale | None = None,
           paper: str | None = None, text_scale: float = 1.0) -> Layout:
    scale, con, bb = scale_of(sol, diagram, scale, paper)
    return layout_of(con, scale, bb, text_scale)


def layout_of(con: Construction, scale: scales.Scale, bb: Box,
              text_scale: float = 1.0) -> Layout:
    """The layout of construction ``con`` at ``scale``, its SI extent ``bb`` drawn inside
    the frame (a stage's detail: :func:`detail`, the finished polygon: :func:`layout`)."""
    extent = (bb.x1 - bb.x0, bb.y1 - bb.y0)
    k = scale.mm_per_si
    w, h = extent[0] * k, extent[1] * k
    frame = Box(-FRAME_MARGIN, -FRAME_MARGIN, w + FRAME_MARGIN, h + FRAME_MARGIN)
    lay = Layout(con, scale, (bb.x0, bb.y0), frame, (), {}, {}, text_scale)
    lay = replace(lay, ghosts=_ghosts(lay))
    vecs = [((st.step, st.frm, st.to), g[0], g[1]) for st, g in _geometry(lay)
            if st.kind == "arrow"]
    lay = replace(lay, shifts=crowd.shifts(vecs, frame.centre))
    return _place_insets(_place_labels(lay))


def _paper_segments(lay: Layout) -> list:
    """Every stroke of the finished drawing where it is drawn (mm)."""
    segs = []
    for st, g in _geometry(lay):
        if g is None:
            continue
        segs.append(_drawn(lay, st, g))
        if st.kind == "arrow":
            segs += crowd.leader_ticks(g[0], g[1], _shift(lay, st))
        elif st.kind == "offset":
            segs += _right_angle(lay.con, st, g)
    return segs


def _paper_points(lay: Layout) -> dict:
    return {n: lay.P(v) for n, v in sorted(lay.con.vertices.items())}


def _crowded(lay: Layout) -> float:
    """Vertices nearer each other than this (mm: a vertex label's height) crowd."""
    return (ASCENT + DESCENT) * lay.size(LABEL_SIZE)


def _place_insets(lay: Layout) -> Layout:
    """Tight clusters of vertices (nearer than a vertex label is tall) drawn again enlarged."""
    con = lay.con
    pts = _paper_points(lay)
    near = _crowded(lay)
    boxes = ([v[3] for v in lay.vertex_labels] + [v[3] for v in lay.line_labels.values()]
             + [v[3] for v in lay.vector_labels.values()])
    vectors = [(st.frm, st.to) for st, _ in _geometry(lay) if st.kind == "arrow"]
    found = inset.plan(pts, _paper_segments(lay), boxes, lay.frame, _inset_size(lay), near,
                       lambda n: con.pole_label if n == con.pole else n, vectors,
                       # a figure printed reduced (labels set larger: a handout's stage
                       # thumbnail) has no caption: at its size it took a fifth of the
                       # figure, 2.6 mm it printed 0.5 mm high; the finished plate has it
                       inset.CAPTION_SIZE if lay.text_scale <= 1.0 else 0.0,
                       # a stage figure printed reduced in a handout's column (labels set
                       # larger): its inset no larger than usual -- the rule is the
                       # finished drawing's (NOT DONE: thumbnails' insets may show a
                       # vector under 3 mm, as before)
                       inset.MAX_RADIUS_FOR_VECTORS if lay.text_scale <= 1.0
                       else inset.MAX_RADIUS)
    return replace(lay, insets=tuple(found))


def _inset_size(lay: Layout) -> float:
    return round(lay.size(LABEL_SIZE) * 0.85, 3)

def _shift(lay: Layout, st: Stroke) -> tuple[float, float]:
    return lay.shifts.get((st.step, st.frm, st.to), (0.0, 0.0)) if st.kind == "arrow" \
        else (0.0, 0.0)


def _drawn(lay: Layout, st: Stroke, g):
    """Where stroke ``st`` (paper geometry ``g``) is drawn: moved beside a collinear vector."""
    d = _shift(lay, st)
    if d == (0.0, 0.0) or g is None:
        return g
    return ((g[0][0] + d[0], g[0][1] + d[1]), (g[1][0] + d[0], g[1][1] + d[1]))


def _geometry(lay: Layout, every: bool = False):
    """Paper geometry of every drawn stroke: arrows (tail, tip), line chords, offsets, sides;
    an arrow shorter than :data:`diagrams.inset.ZERO_MM` is not drawn (no inset can show it:
    the legend says '≈ 0'), ``every`` includes it."""
    out = []
    for st in lay.con.strokes:
        if not every and _ghost(lay, st):
            continue
        if st.kind == "line":
            a = lay.P(st.a)
            chord = clip_line(a, st.b, lay.frame)
            out.append((st, chord))
        else:
            out.append((st, (lay.P(st.a), lay.P(st.b))))
    return out


def _ghost(lay: Layout, st: Stroke) -> bool:
    """True for a vector too short to draw at the drawing's scale (:func:`_ghosts`)."""
    return st.kind == "arrow" and (st.frm, st.to) in lay.ghosts


def _ghosts(lay: Layout) -> frozenset:
    """(frm, to) of every vector no inset can draw :data:`inset.MIN_VECTOR_MM` long: shorter
    than :data:`inset.ZERO_MM`, or than the rule at the largest enlargement its cluster's
    ring allows (:func:`inset.largest_factor`), or with its ends drawn as one point (nearer
    than 0.6 mm: no ring).  They are not drawn; the legend gives each
    as '≈ 0 (x mm at this scale)'."""
    pts = _paper_points(lay)
    out = set()
    rings = inset.rings(pts, _crowded(lay))
    for st in lay.con.strokes:
        if st.kind != "arrow":
            continue
        L = math.dist(lay.P(st.a), lay.P(st.b))
        if L < inset.ZERO_MM:
            out.add((st.frm, st.to))
            continue
        if L >= inset.MIN_VECTOR_MM:
            continue
        ring = next((r for names, _, r in rings if st.frm in names and st.to in names), None)
        # (no ring: its ends are drawn as one point, one label 'b₁ = s₁')
        if ring is None or L * inset.largest_factor(ring) < inset.MIN_VECTOR_MM:
            out.add((st.frm, st.to))
    return frozenset(out)


def _place_labels(lay: Layout) -> Layout:
    con = lay.con
    placer = Placer(frame=lay.frame)
    geo = _geometry(lay)
    for _, c, r in inset.rings(_paper_points(lay), _crowded(lay)):   # labels keep off rings
        for a, b in inset.chords(c, r):
            placer.hard(a, b, 0.3)
    for st, g in geo:
        if g is None:
            continue
        if st.kind == "arrow":
            dg = _drawn(lay, st, g)
            placer.hard(dg[0], dg[1], 1.0)
            for a, b in crowd.leader_ticks(g[0], g[1], _shift(lay, st)):
                placer.hard(a, b, 0.3)
        elif st.kind == "line":
            placer.soft(g[0], g[1])
        else:
            placer.hard(g[0], g[1], 0.6)
            if st.kind == "offset":
                for a, b in _right_angle(lay.con, st, g):
                    placer.hard(a, b, 0.3)
    # vertices: group those drawn at the same place
    order = sorted(con.vertices, key=lambda n: (con.born.get(n, 99), n))
    groups: list[list[str]] = []
    for n in order:
        p = lay.P(con.vertices[n])
        for gr in groups:
            q = lay.P(con.vertices[gr[0]])
            if math.hypot(p[0] - q[0], p[1] - q[1]) < 0.6:
                gr.append(n)
                break
        else:
            groups.append([n])
    for gr in groups:
        p = lay.P(con.vertices[gr[0]])
        placer.block(Box(p[0] - 0.8, p[1] - 0.8, p[0] + 0.8, p[1] + 0.8))
    vlabels = []
    for gr in groups:
        at = lay.P(con.vertices[gr[0]])
        others = []
        for st, g in geo:
            if g is None:
                continue
            if st.kind == "line":
                if _dist_to_line(at, g) < 0.3:
                    others += [g[0], g[1]]
            elif _near(g[0], at):
                others.append(g[1])
            elif _near(g[1], at):
                others.append(g[0])
        prefer = largest_gap_direction(at, others)
        text = _vertex_text(con, gr, None)
        placer.boxes = [b for b in placer.boxes
                        if not (b.x1 - b.x0 < 1.7 and b.contains(at))]   # own dot
        x, base, _, box = placer.place(text, at, lay.size(LABEL_SIZE), prefer=prefer)
        vlabels.append((tuple(gr), x, base, box))
        placer.block(Box(at[0] - 0.8, at[1] - 0.8, at[0] + 0.8, at[1] + 0.8))
    # every drawn stroke, so a label can be set nearer its own than any other (a reader
    # tells which line or vector it names)
    drawn = [(st, g if st.kind == "line" else _drawn(lay, st, g)) for st, g in geo
             if g is not None and st.kind in ("line", "arrow", "offset")]
    llabels = {}
    leaders = []
    for st, g in geo:
        if st.kind != "line" or g is None:
            continue
        (x0, y0), (x1, y1) = g
        ang = math.atan2(y1 - y0, x1 - x0)
        anchors = []
        for f in (0.96, 0.04, 0.88, 0.12, 0.75, 0.25):
            pt = (x0 + f * (x1 - x0), y0 + f * (y1 - y0))
            anchors.append((pt, [ang + math.pi / 2, ang - math.pi / 2]))
        text = display(st.label)
        placer.hard(g[0], g[1], 0.7)            # not across its own line
        owner = _owner_cost(st, g, drawn)
        x, base, _, box = placer.place_any(text, lay.size(LINE_LABEL_SIZE), anchors,
                                           distances=(0.3, 0.8, 1.8, 3.3, 5.3, 8.0),
                                           extra_cost=owner)
        placer.hard_segments.pop()
        if owner(0, box) > 0:          # as near another line: further out, led to its own
            placer.boxes.remove(box)
            far = placer.place_any(
                text, lay.size(LINE_LABEL_SIZE), anchors, distances=(4.0, 6.0, 8.5, 12.0),
                required=False, extra_cost=lambda _ai, b, st=st, g=g: _crossings(
                    _leader_to(b, g), st, drawn) * 3.0 + _through(_leader_to(b, g), placer))
            lead = None if far is None else _leader_to(far[3], g)
            if far is None or (lead is not None and _through(lead, placer, far[3])):
                if far is not None:
                    placer.boxes.remove(far[3])
                placer.block(box)
            else:
                x, base, _, box = far
                if lead is not None:
                    leaders.append((st.step, (st.frm, st.to), lead))
                    placer.hard(lead[0], lead[1], 0.3)
        llabels[st.step] = (text, x, base, box)
    vec_labels = {}
    asked = asked_vectors(con)
    # the component named at each vector's midpoint, asked ones first, then longest first; a
    # name with no free place nearer its own vector than any other goes where there is
    # room, with a leader to the vector; a vector too short to carry its name (and not
    # asked) is named in the side panel only
    arrows = [(st, _drawn(lay, st, g)) for st, g in geo
              if st.kind in ("arrow", "offset") and st.label]
    arrows.sort(key=lambda sg: ((sg[0].frm, sg[0].to) not in asked,
                                -math.hypot(sg[1][1][0] - sg[1][0][0],
                                            sg[1][1][1] - sg[1][0][1]), sg[0].step))
    for st, g in arrows:
        L = math.hypot(g[1][0] - g[0][0], g[1][1] - g[0][1])
        want = (st.frm, st.to) in asked and st.kind == "arrow"
        if L < 4.0 and not want:
            continue
        ang = math.atan2(g[1][1] - g[0][1], g[1][0] - g[0][0])
        anchors = []
        for f in (0.5, 0.4, 0.6, 0.3, 0.7):
            pt = (g[0][0] + f * (g[1][0] - g[0][0]), g[0][1] + f * (g[1][1] - g[0][1]))
            anchors.append((pt, [ang + math.pi / 2, ang - math.pi / 2]))
        owner = _owner_cost(st, g, drawn)
        placed = placer.place_any(st.label, lay.size(VECTOR_LABEL_SIZE), anchors,
                                  distances=(0.5, 1.1, 2.0, 3.2), required=False,
                                  extra_cost=owner)
        near = None
        if placed is not None and owner(0, placed[3]) > 0:
            placer.boxes.remove(placed[3])        # beside another vector: lead it instead
            near, placed = placed, None
        if placed is None:
            mid = ((g[0][0] + g[1][0]) / 2, (g[0][1] + g[1][1]) / 2)
            placed = placer.place_any(
                st.label, lay.size(VECTOR_LABEL_SIZE),
                [(mid, [2 * math.pi * k / 24 for k in range(24)])],
                distances=(4.0, 6.0, 8.5, 12.0, 16.0), required=False,
                extra_cost=lambda _ai, box, mid=mid, st=st: _crossings(
                    _leader(box, mid), st, drawn) * 3.0 + _through(_leader(box, mid), placer))
            lead = None if placed is None else _leader(placed[3], mid)
            if lead is not None and _through(lead, placer, placed[3]):
                placer.boxes.remove(placed[3])    # no clear way to it: the near place
                placed, lead = None, None
            if placed is None and near is not None:
                placer.block(near[3])
                placed = near
            elif placed is None and want:
                placed = placer.place(st.label, mid, lay.size(VECTOR_LABEL_SIZE))
            if lead is not None:
                leaders.append((st.step, (st.frm, st.to), lead))
                placer.hard(lead[0], lead[1], 0.3)
        if placed is not None:
            x, base, _, box = placed
            vec_labels[(st.step, st.frm, st.to)] = (st.label, x, base, box)
    return replace(lay, vertex_labels=tuple(vlabels), line_labels=llabels,
                   vector_labels=vec_labels, leaders=tuple(leaders))


#: a label this much (mm) nearer another stroke than its own would read as the other's
OWNER_MARGIN = 2.5


def on_line(g, seg, tol: float = 0.3) -> bool:
    """True when segment ``g`` lies on the line of ``seg`` (a vector on its own construction
    line, p₁p on the slot line): a label by one is by the other."""
    return _dist_to_line(g[0], seg) < tol and _dist_to_line(g[1], seg) < tol


def _owner_cost(own: Stroke, seg, drawn):
    """extra_cost for a label of stroke ``own`` (paper segment ``seg``): dear when another
    drawn line or vector is about as near the label's box as its own.  The other strokes are
    looked up by the cells of a coarse grid (:class:`diagrams.labels.StrokeCells`, made once
    per drawing), so a label costs what the strokes near it cost, not every stroke."""
    index = _strokes_of(drawn)

    def cost(_ai, box) -> float:
        mine = box_segment_distance(box, seg[0], seg[1])
        reach = mine + OWNER_MARGIN
        for st, (a, b) in index.near(box, reach):
            if st is own or on_line((a, b), seg):
                continue
            if box_segment_distance(box, a, b) < reach:
                return 6.0
        return 0.0
    return cost


_STROKE_INDEX: dict = {}


def _strokes_of(drawn) -> StrokeCells:
    """The grid of ``drawn`` (one list per drawing), made on its first label."""
    hit = _STROKE_INDEX.get(id(drawn))
    if hit is None or hit[0] is not drawn:
        _STROKE_INDEX.clear()              # one drawing at a time
        hit = _STROKE_INDEX[id(drawn)] = (drawn, StrokeCells(drawn))
    return hit[1]


def _crossings(lead, own: Stroke, drawn) -> int:
    """How many drawn strokes other than ``own`` the leader ``lead`` crosses (those filed
    under the cells of its box: a stroke crossing it has a point in that box)."""
    if lead is None:
        return 0
    (ax, ay), (bx, by) = lead
    box = Box(min(ax, bx), min(ay, by), max(ax, bx), max(ay, by))
    return sum(1 for st, g in _strokes_of(drawn).near(box, 0.0)
               if st is not own and _cross(lead, g))


def _through(lead, placer: Placer, skip: Box | None = None) -> float:
    """Dear (100) when the leader ``lead`` passes through a label already placed (other than
    ``skip``: the label's own, when testing its leader); the labels near it looked up."""
    if lead is None:
        return 0.0
    (ax, ay), (bx, by) = lead
    near = placer.near_boxes(Box(min(ax, bx) - 0.35, min(ay, by) - 0.35, max(ax, bx) + 0.35,
                                 max(ay, by) + 0.35))
    return 100.0 if any(box_hits_segment(b, lead[0], lead[1], 0.35) for b in near
                        if b is not skip and b.x1 - b.x0 > 1.7) else 0.0   # (a dot it may pass)


def _cross(p, q) -> bool:
    (a, b), (c, d) = p, q

    def side(o, e, f):
        return (e[0] - o[0]) * (f[1] - o[1]) - (e[1] - o[1]) * (f[0] - o[0])
    return (side(a, b, c) * side(a, b, d) < 0) and (side(c, d, a) * side(c, d, b) < 0)


def _leader_to(box: Box, seg):
    """A leader from a label's box to the nearest point of the segment ``seg``."""
    (x0, y0), (x1, y1) = seg
    c = box.centre
    L2 = (x1 - x0) ** 2 + (y1 - y0) ** 2
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((c[0] - x0) * (x1 - x0)
                                               + (c[1] - y0) * (y1 - y0)) / L2))
    return _leader(box, (x0 + t * (x1 - x0), y0 + t * (y1 - y0)))


def _leader(box: Box, to: Pt):
    """A thin line from a label's box to the point it names (:func:`labels.leader`)."""
    return leader(box, to, 0.3)


def _right_angle(con: Construction, st: Stroke, g, size: float = 1.6):
    """The two short strokes of the right-angle mark where the Coriolis offset (paper
    segment ``g``, anchor first) meets its construction line."""
    line = next((ln for ln in con.strokes if ln.kind == "line" and ln.step == st.step), None)
    (ax, ay), (bx, by) = g
    L = math.hypot(bx - ax, by - ay)
    if line is None or L < 3 * size:
        return []
    u = ((bx - ax) / L, (by - ay) / L)
    w = line.b
    n = math.hypot(*w)
    w = (w[0] / n, w[1] / n)
    p1 = (ax + u[0] * size, ay + u[1] * size)
    p2 = (p1[0] + w[0] * size, p1[1] + w[1] * size)
    p3 = (ax + w[0] * size, ay + w[1] * size)
    return [(p1, p2), (p2, p3)]


def _near(p: Pt, q: Pt, tol: float = 0.05) -> bool:
    return abs(p[0] - q[0]) < tol and abs(p[1] - q[1]) < tol


def _dist_to_line(p: Pt, chord) -> float:
    (x0, y0), (x1, y1) = chord
    L = math.hypot(x1 - x0, y1 - y0)
    if L == 0:
        return math.inf
    return abs((x1 - x0) * (y0 - p[1]) - (x0 - p[0]) * (y1 - y0)) / L


def _vertex_text(con: Construction, names, upto: int | None) -> str:
    shown = [n for n in names if upto is None or con.born.get(n, 0) <= upto]
    return " = ".join(con.pole_label if n == con.pole else n for n in shown)


# ---------------------------------------------------------------- drawing a stage
ARROW_STYLE = {"known": "vector", "resolved": "vector", "join": "vector", "image": "vector",
               "result": "result", "coriolis": "coriolis"}


def _stage_number(con: Construction, stage: int | None) -> int | None:
    """Step number shown last in ``stage`` (1-based index into the drawable steps)."""
    return None if stage is None else con.steps[stage - 1].number


#: the look of a stroke that only places a line (the Coriolis vector stepped back): a light
#: construction copy of its component, drawn once heavy as the polygon's side
AUX = {"coriolis": "coriolis-aux"}


def _style(component: str, new: bool) -> str:
    return f"c-{component}" + ("-new" if new else "")


def stroke_items(lay: Layout, stage: int | None):
    """The drawn items of the polygon up to ``stage`` (None: the finished polygon)."""
    con = lay.con
    upto = _stage_number(con, stage)
    lines_g, vec_g, pts_g, lab_g = [], [], [], []
    shown = []          # (a, b, style, head?, open head?, faded) for the insets
    asked = asked_vectors(con)
    for st, g in _geometry(lay):
        if upto is not None and st.step > upto:
            continue
        faded = upto is not None and st.step < upto
        new = upto is not None and st.step == upto
        if st.kind == "line":
            if g is None:
                continue
            lines_g.append(Segment(g[0], g[1], _style("construction", new), faded,
                                   cls=f"construction-line step-{st.step}"))
            shown.append((g[0], g[1], _style("construction", new), False, False, faded))
            text, x, base, _ = lay.line_labels[st.step]
            lab_g.append(Text(x, base, text, lay.size(LINE_LABEL_SIZE), role="line", faded=faded,
                              cls=f"line-label step-{st.step}"))
            for step, fv, (a, b) in lay.leaders:
                if step == st.step and fv == (st.frm, st.to):
                    lines_g.append(Segment(a, b, "leader", faded,
                                           cls=f"label-leader step-{st.step}"))
        elif st.kind == "side":
            lines_g.append(Segment(g[0], g[1], _style("image", False), faded,
                                   cls=f"image-side step-{st.step}"))
            shown.append((g[0], g[1], _style("image", False), False, False, faded))
        else:
            look = LOOKS[st.component]
            head, shaft_end = arrow_head(g[0], g[1], open_head=look.open_head)
            if st.kind == "arrow":
                shift = _shift(lay, st)
                vec_g.append(Arrow(g[0], g[1], _style(st.component, new), head, shaft_end,
                                   vector(st.frm, st.to), st.frm, st.to, st.role,
                                   st.title, faded, new, shift))
                for a, b in crowd.leader_ticks(g[0], g[1], shift):   # beside a collinear one
                    lines_g.append(Segment(a, b, "leader", faded,
                                           cls=f"leader step-{st.step}"))
                    shown.append((a, b, "leader", False, False, faded))
                dg = _drawn(lay, st, g)
                shown.append((dg[0], dg[1], _style(st.component, new), True, look.open_head,
                              faded))
            else:     # the Coriolis offset: not a polygon side, a light arrowed step back
                aux = _style(AUX[st.component], False)
                head, shaft_end = arrow_head(g[0], g[1], open_head=True)
                lines_g.append(Segment(g[0], shaft_end, aux, faded,
                                       cls=f"offset step-{st.step}"))
                shown.append((g[0], g[1], aux, True, True, faded))
                if head:
                    lines_g.append(Polyline(head, aux, closed=True,
                                            faded=faded, cls=f"offset-head open step-{st.step}"))
                for a, b in _right_angle(con, st, g):
                    lines_g.append(Segment(a, b, aux, faded,
                                           cls=f"right-angle step-{st.step}"))
        if st.kind in ("arrow", "offset"):
            lab = lay.vector_labels.get((st.step, st.frm, st.to))
            if lab is not None:
                text, x, base, _ = lab
                mark = st.kind == "arrow" and (st.frm, st.to) in asked
                lab_g.append(Text(x, base, text, lay.size(VECTOR_LABEL_SIZE), role="component",
                                  faded=faded, cls=f"component-label {st.component}"
                                  + (" asked" if mark else ""),
                                  ink=LOOKS[st.component].colour))
            for step, fv, (a, b) in lay.leaders:
                if step == st.step and fv == (st.frm, st.to):
                    lines_g.append(Segment(a, b, "leader", faded,
                                           cls=f"label-leader step-{st.step}"))
    for names, x, base, box in lay.vertex_labels:
        text = _vertex_text(con, names, upto)
        if not text:
            continue
        visible = [n for n in names if upto is None or con.born.get(n, 0) <= upto]
        newest = max(con.born.get(n, 0) for n in visible)
        faded = upto is not None and newest < upto
        for n in visible:
            pole = n == con.pole
            pts_g.append(Circle(lay.P(con.vertices[n]), 0.9 if pole else 0.55,   # its own
                                "pole" if pole else "vertex",                       # place
                                faded, cls="vertex", ident=f"{con.diagram}-vertex-{token(n)}"))
        lab_g.append(Text(x, base, text, lay.size(LABEL_SIZE), role="vertex", faded=faded,
                          cls="vertex-label", weight="bold" if not faded else "normal"))
    groups = []
    for i, ins in enumerate(lay.insets):
        visible = [n for n in con.vertices if upto is None or con.born.get(n, 0) <= upto]
        old = {n for n in visible if upto is not None and con.born.get(n, 0) < upto}
        if sum(n in visible for n in ins.names) < 2:
            continue
        pts = {n: lay.P(v) for n, v in con.vertices.items()}
        groups.append(Group(f"{con.diagram}-inset-{i + 1}", "inset",
                            f"Detail ×{ins.k}: the vertices {', '.join(ins.names)} enlarged",
                            tuple(inset.items(ins, shown, pts, visible, con.pole, old)
                                  + inset.labels(ins, visible, _inset_size(lay), old))))
    return [Group(f"{con.diagram}-construction", "construction", "Construction lines",
                  tuple(lines_g)),
            Group(f"{con.diagram}-vectors", "vectors", "Vectors",
                  tuple(Group(f"{con.diagram}-vec-{i}-{token(a.name)}",
                              f"vector {a.role} {a.style.split('-')[1]} from-{token(a.frm)} "
                              f"to-{token(a.to)}" + (" asked" if (a.frm, a.to) in asked
                                                     else ""),
                              f"{a.title} — {number(lay.scale.si(_len(a)) / lay.scale.factor)}"
                              f" {display(lay.scale.unit)} at {lay.scale.statement}",
                              (a,)) for i, a in enumerate(vec_g))),
            Group(f"{con.diagram}-vertices", "vertices", "Polygon vertices", tuple(pts_g)),
            Group(f"{con.diagram}-labels", "labels", "Labels", tuple(lab_g))] + groups


def key(lay: Layout, stage: int | None = None) -> list[str]:
    """The component kinds drawn (up to ``stage``), in the legend's order."""
    upto = _stage_number(lay.con, stage)
    seen = {("construction" if st.kind == "line" else
             AUX[st.component] if st.kind == "offset" else st.component)
            for st in lay.con.strokes if upto is None or st.step <= upto}
    return [c for c in ORDER if c in seen]


def _len(a: Arrow) -> float:
    return math.hypot(a.tip[0] - a.tail[0], a.tip[1] - a.tail[1])


def _content_box(lay: Layout) -> Box:
    box = lay.frame
    for _, _, _, b in lay.vertex_labels:
        box = box.union(b)
    for _, _, _, b in lay.line_labels.values():
        box = box.union(b)
    for _, _, _, b in lay.vector_labels.values():
        box = box.union(b)
    for ins in lay.insets:
        box = box.union(ins.box)
    return box.grown(1.0)


def asked_vectors(con: Construction) -> set[tuple[str, str]]:
    """(frm, to) of every drawn vector that shows an asked quantity, both ways round."""
    out = set()
    for a in con.asked:
        if a.vector is not None:
            out |= {a.vector, a.vector[::-1]}
    return out


#: a legend longer than this (a large mechanism's hundreds of vectors) lists the asked
#: quantities only and says how many more there are
MAX_LEGEND_LINES = 40


def legend(lay: Layout, sol: Solution | None = None) -> list[tuple[str, str]]:
    """Vector lengths read off the drawing (mm ÷ scale) and the step's measured values;
    the asked quantities (the scene's ``[[answers]]``) are marked 'asked'.  Beyond
    :data:`MAX_LEGEND_LINES` lines only the asked ones are listed, with a count of the rest."""
    sc = lay.scale
    out = [(f"Scaled from the drawing ({sc.statement}):", "bold")]
    pts = [lay.P(v) for v in lay.con.vertices.values()]
    if all(math.dist(p, pts[0]) < 0.6 for p in pts):     # nothing to enlarge: say so
        out.append((f"Every vertex lies at the pole {lay.con.pole_label}: every "
                    f"{lay.con.diagram} of this diagram is zero.", "normal"))
    seen = set()
    asked = asked_vectors(lay.con)
    asked_m = {a.measure for a in lay.con.asked if a.measure is not None}
    vectors: list[tuple[str, str]] = []
    for st, g in _geometry(lay, every=True):
        if st.kind != "arrow":
            continue
        if (st.frm, st.to) in seen:
            continue
        seen.add((st.frm, st.to))
        mm = math.hypot(g[1][0] - g[0][0], g[1][1] - g[0][1])
        val = sc.si(mm) / sc.factor
        what = "Coriolis 2ωv" if st.component == "coriolis" else st.label
        mark = "\u2003← asked" if (st.frm, st.to) in asked else ""
        name = vector(_about(lay.con, st), st.to)
        if _ghost(lay, st):        # too short for any inset: said, not drawn
            if mm < 0.005:
                text = f"{name} = 0 (a point: not drawn)"
            else:
                text = (f"{name} ≈ 0 ({mm:.2f} mm at this scale: "
                        f"{number(val, 3)} {display(sc.unit)}, not drawn)")
            vectors.append((f"{text}  {what}{mark}", "bold" if mark else "normal"))
            continue
        vectors.append((f"{name} = {number(val, 4)} {display(sc.unit)}  "
                        f"({mm:.1f} mm)  {what}{mark}", "bold" if mark else "normal"))
    for a in lay.con.asked:
        if a.zero:
            vectors.append((f"{a.zero} = 0: no vector to draw\u2003← asked", "bold"))
    measures = [(prose(sol, lay.con, measure_text(m, sol, lay.con, sc))
                 + ("\u2003← asked" if m.number in asked_m else ""),
                 "bold" if m.number in asked_m else "normal") for m in lay.con.measures]
    if len(vectors) + len(measures) > MAX_LEGEND_LINES:   # a large mechanism: the asked only
        left = sum(style != "bold" for _, style in vectors + measures)
        vectors = [v for v in vectors if v[1] == "bold"]
        measures = [m for m in measures if m[1] == "bold"]
        vectors.append((f"… and {left} more (every value is in the solve table)", "normal"))
    out += vectors
    if sol is not None and sol.scene.equivalents:        # a rolling wheel's ω, α, points
        from .rolling import legend_rows
        measures += legend_rows(sol, lay.con.diagram)
    if measures:
        out.append(("", "normal"))
        out.append(("From the construction:", "bold"))
        out += measures
    return out


def _about(con: Construction, st: Stroke) -> str:
    """The tail's name of a vector as the book writes it (:func:`polygons.steps.tail_name`:
    from the pole, the fixed pivot its intersection names — dc about D where the pole is
    a = d — or a centripetal vector's fixed centre, dc₂), else the vertex."""
    if st.frm != con.pole:
        return st.frm
    step = next((s for s in con.steps if s.number == st.step), None)
    if step is None:
        return st.frm
    return tail_name(step, st.frm, con.pole, set(con.pole_label.split(" = ")),
                     step if step.kind == "intersection" else None)


def _stage_notes(sol: Solution, lay: Layout, s: Step) -> list[str]:
    """What a stage adds beyond its step's sentence: the way the Coriolis offset steps, the
    asked vectors it closes the diagram with."""
    con = lay.con
    notes = []
    sc = lay.scale
    for st, g in _geometry(lay, every=True):
        if st.step != s.number:
            continue
        if st.kind == "offset":
            back = math.atan2(g[0][1] - g[1][1], g[0][0] - g[1][0])
            mm = math.hypot(g[1][0] - g[0][0], g[1][1] - g[0][1])
            notes.append(f"The step back from {st.to} runs {along_words(back)}, against 2ωv "
                         f"({number(sc.si(mm) / sc.factor)} {display(sc.unit)}, {mm:.1f} mm "
                         f"drawn, square to the slot line: the right-angle mark).")
        elif st.kind == "arrow" and st.title.endswith("(asked)"):
            mm = math.hypot(g[1][0] - g[0][0], g[1][1] - g[0][1])
            notes.append(f"Join {vector(st.frm, st.to)}: it is {st.label} = "
                         f"{number(sc.si(mm) / sc.factor)} {display(sc.unit)}, "
                         f"{along_words(math.atan2(g[1][1] - g[0][1], g[1][0] - g[0][0]))} "
                         f"(asked).")
    return [prose(sol, con, n) for n in notes]


def drawing(sol: Solution, lay: Layout, stage: int | None = None) -> Drawing:
    con = lay.con
    what = "Velocity" if con.diagram == "velocity" else "Acceleration"
    sid = sol.scene.source.get("id", "")
    subtitle = f"{sid}: {sol.scene.title}" if sid else sol.scene.title
    n = len(con.steps)
    if stage is None:
        name = con.diagram
        title = f"{what} diagram (pole {con.pole_label})"
        caption = []
        legend_lines = legend(lay, sol)
        desc = (f"{what} polygon of {sol.scene.title}, drawn to scale {lay.scale.statement}. "
                + " ".join(f"{i}. {prose(sol, con, s.reason)}"
                           for i, s in enumerate(con.steps, 1)))
    else:
        s = con.steps[stage - 1]
        name = f"{con.diagram}-{stage}"
        title = f"{what} diagram, stage {stage} of {n}"
        caption = [f"Stage {stage}. {prose(sol, con, s.reason)}"]
        formula = substitute(s, sol.scene)
        if formula:
            caption.append(prose(sol, con, formula))
        caption += _stage_notes(sol, lay, s)
        legend_lines = []
        desc = f"Stage {stage} of {n} of the {what.lower()} polygon: {prose(sol, con, s.reason)}"
    content = stroke_items(lay, stage)
    page = compose(name=name, kind=con.diagram, stage=stage, title=title, subtitle=subtitle,
                   desc=desc, content=content, content_box=_content_box(lay),
                   legend=legend_lines, scale=lay.scale, caption=caption,
                   scale_statement=lay.scale.statement,
                   meta={"layout": lay},
                   key=[(f"c-{c}", LOOKS[c].name, c != "construction") for c in key(lay, stage)])
    return mark_drawing(page, sol.points)       # O4P2 → O₄P₂: the scene's labels typeset
