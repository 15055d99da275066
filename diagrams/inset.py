"""Enlarged insets of tight vertex clusters ('detail ×k'), as a textbook draws them.

Paper mm, y up; no svgwrite, no kinematics.  When vertices of a polygon lie nearer each other
than a vertex label is tall (:func:`diagrams.crowd.clusters`), the drawing rings the cluster
with a thin circle and draws everything inside that circle again, ``k`` × larger, inside a
circle of its own in a free corner of the drawing (else beside it), joined to the ring by a
thin line and captioned 'detail ×k'.  The inset's vertices carry their own labels, placed so
they touch nothing; its strokes keep their component looks, arrowheads at their usual size.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .crowd import clip_to_circle, clusters, mapped
from .labels import Box, Placer, box_hits_segment, leader, text_box
from .layout import arrow_head
from .model import Circle, Polyline, Segment, Text
from .scale import RULE_MM

Pt = tuple[float, float]

#: the enlargements offered (a round number, as a draughtsman picks)
FACTORS = (2, 3, 4, 5, 6, 8, 10, 15, 20)
#: the inset's radius is at most this (mm) ...
MAX_RADIUS = 26.0
#: ... unless a larger one is what shows its shortest vector :data:`MIN_VECTOR_MM` long
MAX_RADIUS_FOR_VECTORS = 30.0
CAPTION_SIZE = 2.6
#: the layout rule: no vector drawn shorter than this (mm), on the drawing or in its inset
#: (diagrams.audit measures it on the SVG)
MIN_VECTOR_MM = RULE_MM
#: a vector shorter than this (mm) at the drawing's scale is not drawn at all: no inset can
#: show it :data:`MIN_VECTOR_MM` long; the legend gives it as '≈ 0 (x mm at this scale)'
ZERO_MM = MIN_VECTOR_MM / FACTORS[-1]
RING_MARGIN = 1.6       # mm of ring around the cluster's outermost vertex


@dataclass(frozen=True)
class Inset:
    names: tuple[str, ...]     # the cluster's vertices
    c: Pt                      # ring centre on the drawing
    r: float                   # ring radius (mm)
    k: int                     # enlargement
    C: Pt                      # inset centre
    R: float                   # inset radius (= k r)
    labels: tuple              # (names tuple, text, x, baseline, box, leader) in the inset;
    #                            leader: a thin line to the vertex of a label set away from it
    caption: tuple             # (text, x, baseline, box)
    join: tuple | None = None  # the line from the ring to the inset, when it crosses nothing
    caption_size: float = CAPTION_SIZE

    @property
    def box(self) -> Box:
        """The inset's circle, its caption and its labels (a label set outside the circle
        is part of what the key and the legend must keep clear of)."""
        b = Box(self.C[0] - self.R, self.C[1] - self.R, self.C[0] + self.R, self.C[1] + self.R)
        b = b.union(self.caption[3])
        for lab in self.labels:
            b = b.union(lab[4])
        return b

    def show(self, p: Pt) -> Pt:
        return mapped(p, self.c, self.k, self.C)


def _factor(points: list[Pt], near: float, vectors=()) -> int:
    """The least round enlargement that sets the cluster's nearest two vertices 1.6 label
    heights apart and draws each of its ``vectors`` (lengths, mm) :data:`MIN_VECTOR_MM`
    long or longer."""
    d = min((math.dist(p, q) for i, p in enumerate(points) for q in points[i + 1:]
             if math.dist(p, q) >= 0.6), default=near)
    for k in FACTORS:
        if d * k >= 1.6 * near and all(L * k >= MIN_VECTOR_MM for L in vectors):
            return k
    return FACTORS[-1]


def largest_factor(r: float) -> int:
    """The largest enlargement a ring of radius ``r`` (mm) may have: its inset no wider than
    :data:`MAX_RADIUS_FOR_VECTORS`."""
    return max([k for k in FACTORS if k * r <= MAX_RADIUS_FOR_VECTORS] or [FACTORS[0]])


def _vector_factor(vectors) -> int:
    """The least round enlargement that draws every one of ``vectors`` (mm) at least
    :data:`MIN_VECTOR_MM` long."""
    return next((k for k in FACTORS if all(L * k >= MIN_VECTOR_MM for L in vectors)),
                FACTORS[-1])


def _free(box: Box, segments, boxes) -> bool:
    return (not any(box.overlaps(b) for b in boxes)
            and not any(box_hits_segment(box, a, b, 0.5) for a, b in segments))


def rings(points: dict, near: float) -> list[tuple[tuple[str, ...], Pt, float]]:
    """(names, centre, radius) of the ring around each cluster of vertices nearer each other
    than ``near`` mm (known before any label is placed: labels keep off the rings)."""
    out = []
    for names in clusters(points, near):
        pts = [points[n] for n in names]
        cx = (min(p[0] for p in pts) + max(p[0] for p in pts)) / 2
        cy = (min(p[1] for p in pts) + max(p[1] for p in pts)) / 2
        c = (round(cx, 3), round(cy, 3))
        out.append((tuple(names), c, round(max(math.dist(c, p) for p in pts) + RING_MARGIN, 3)))
    return out


def chords(c: Pt, r: float, n: int = 32) -> list[tuple[Pt, Pt]]:
    """A circle as ``n`` chords (label placement and the tests treat it as segments)."""
    pts = [(c[0] + r * math.cos(2 * math.pi * i / n), c[1] + r * math.sin(2 * math.pi * i / n))
           for i in range(n)]
    return [(pts[i], pts[(i + 1) % n]) for i in range(n)]


def plan(points: dict, segments: list, boxes: list, frame: Box, label_size: float,
         near: float, names_of=lambda n: n, vectors=(), caption_size: float = CAPTION_SIZE,
         max_radius: float = MAX_RADIUS_FOR_VECTORS) -> list[Inset]:
    """The insets of a drawing: ``points`` {vertex: paper point}; ``segments`` every drawn
    stroke (a, b) and ``boxes`` every label box (mm) an inset must keep clear of; ``frame``
    the drawing's frame; ``near`` the distance under which vertices crowd; ``names_of`` the
    label of a vertex (the pole's aliases); ``vectors`` the (tail, tip) vertex names of the
    drawn vectors: one inside a ring is drawn :data:`MIN_VECTOR_MM` long in its inset, the
    inset's radius allowed up to ``max_radius`` for it."""
    out: list[Inset] = []
    taken = list(boxes)
    for names, c, r in rings(points, near):
        pts = [points[n] for n in names]
        inside = set(names)
        lens = [math.dist(points[a], points[b]) for a, b in vectors
                if a in inside and b in inside and a in points and b in points]
        lens = [L for L in lens if L >= ZERO_MM - 1e-9]
        k = _factor(pts, near, lens)
        need = _vector_factor(lens)
        while k > FACTORS[0] and k * r > MAX_RADIUS and (
                k > need or k * r > max_radius):
            k = FACTORS[FACTORS.index(k) - 1]
        R = round(k * r, 3)
        cap_h = (caption_size + 1.0) if caption_size > 0 else 0.0
        corners = [(frame.x1 - R - 1.0, frame.y1 - R - 1.0), (frame.x0 + R + 1.0, frame.y1 - R - 1.0),
                   (frame.x1 - R - 1.0, frame.y0 + R + cap_h + 1.0),
                   (frame.x0 + R + 1.0, frame.y0 + R + cap_h + 1.0)]
        C = None
        for q in corners:
            b = Box(q[0] - R, q[1] - R - cap_h, q[0] + R, q[1] + R).grown(1.0)
            ring = Box(c[0] - r, c[1] - r, c[0] + r, c[1] + r)
            if (_free(b, segments, taken) and not b.overlaps(ring)
                    and not any(b.contains(p) for p in points.values())):
                C = q
                break
        if C is None:       # no corner free: beside everything drawn, below earlier insets
            right = max([frame.x1] + [b.x1 for b in boxes]
                        + [p[0] for seg in segments for p in seg])
            beside = [i for i in out if i.C[0] - i.R > right]
            top = min([frame.y1] + [i.box.y0 - 3.0 for i in beside])
            C = (right + 4.0 + R, top - R)
        C = (round(C[0], 3), round(C[1], 3))
        ins = Inset(tuple(names), c, r, k, C, R, (), ("", 0.0, 0.0, Box(*C, *C)),
                    caption_size=caption_size)
        ins = _labels(ins, points, segments, taken, label_size, names_of)
        d = math.dist(c, C)
        if d > r + R + 2.0:
            u = ((C[0] - c[0]) / d, (C[1] - c[1]) / d)
            join = ((round(c[0] + u[0] * (r + 0.5), 3), round(c[1] + u[1] * (r + 0.5), 3)),
                    (round(C[0] - u[0] * R, 3), round(C[1] - u[1] * R, 3)))
            if not any(_crosses(join, s) for s in segments) and not any(
                    box_hits_segment(b, *join, 0.3) for b in taken + [x[4] for x in ins.labels]):
                ins = replace(ins, join=join)
        out.append(ins)
        taken.append(ins.box.grown(1.0))
        taken += [lab[4] for lab in ins.labels]
    return out


def _labels(ins: Inset, points: dict, segments, boxes, size: float, names_of) -> Inset:
    """Place the inset's vertex labels clear of its (enlarged) strokes and of everything on
    the drawing, and its caption."""
    C, R = ins.C, ins.R
    placer = Placer(frame=Box(C[0] - R, C[1] - R, C[0] + R, C[1] + R))
    for a, b in segments + chords(C, R):
        placer.hard(a, b, 0.5)
    for b in boxes:
        placer.block(b)
    for a, b in segments:
        seg = clip_to_circle(ins.show(a), ins.show(b), C, R)
        if seg is not None:
            placer.hard(seg[0], seg[1], 0.6)
    inside = _inside(ins, points)
    groups: list[list[str]] = []
    for n in inside:
        p = ins.show(points[n])
        for g in groups:
            if math.dist(ins.show(points[g[0]]), p) < 0.6:
                g.append(n)
                break
        else:
            groups.append([n])
    for g in groups:
        p = ins.show(points[g[0]])
        placer.block(Box(p[0] - 0.8, p[1] - 0.8, p[0] + 0.8, p[1] + 0.8))
    # the caption first: no vertex label on it (none on a figure printed reduced: size 0)
    text = f"detail ×{ins.k}" if ins.caption_size > 0 else ""
    cs = ins.caption_size
    tb = text_box(C[0], C[1] - R - 1.0 - cs * 0.76, text, cs, "middle")
    caption = (text, C[0], C[1] - R - 1.0 - cs * 0.76, tb)
    placer.block(tb)
    labels = []
    for g in groups:
        at = ins.show(points[g[0]])
        text = " = ".join(names_of(n) for n in g)
        x, base, _, box = placer.place(text, at, size)
        labels.append((tuple(g), text, x, base, box, leader(box, at, 0.9)))
    # a leader crossing another label or the caption is left out (the label stays nearest
    # its vertex of every free place)
    boxes_all = [lab[4] for lab in labels] + [tb]
    labels = [lab if lab[5] is None or not any(
        box_hits_segment(b, *lab[5], 0.3) for b in boxes_all if b is not lab[4])
        else lab[:5] + (None,) for lab in labels]
    return replace(ins, labels=tuple(labels), caption=caption)


def _crosses(s, t) -> bool:
    """True if segments s and t cross (or touch)."""
    def orient(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    (a, b), (c, d) = s, t
    d1, d2, d3, d4 = orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d)
    if ((d1 > 0) != (d2 > 0)) and ((d3 > 0) != (d4 > 0)):
        return True
    from .labels import point_segment_distance
    return min(point_segment_distance(a, c, d), point_segment_distance(b, c, d),
               point_segment_distance(c, a, b), point_segment_distance(d, a, b)) < 0.3


def _inside(ins: Inset, points: dict) -> list[str]:
    """The vertices the inset shows: those inside its ring."""
    return [n for n in sorted(points) if math.dist(points[n], ins.c) <= ins.r]


def items(ins: Inset, strokes, points: dict, visible, pole: str, old=()):
    """The drawn items of one inset.  ``strokes``: (a, b, style, head, open_head, faded) of
    every stroke shown on the drawing (arrows with ``head`` True); ``visible``: the vertices
    shown; ``pole``: the pole's name (drawn as an open circle); ``old``: the vertices drawn
    in earlier stages (lighter)."""
    C, R = ins.C, ins.R
    out = [Circle(ins.c, ins.r, "inset", cls="inset-ring"),
           Circle(C, R, "inset", cls="inset-frame")]
    if ins.join is not None:       # the thin line joining the ring to its inset
        out.append(Segment(*ins.join, "inset", cls="inset-join"))
    for a, b, style, head, open_head, faded in strokes:
        ta, tb = ins.show(a), ins.show(b)
        seg = clip_to_circle(ta, tb, C, R)
        if seg is None:
            continue
        tip_in = head and math.dist(tb, C) <= R
        if tip_in:
            h, shaft = arrow_head(seg[0], tb, open_head=open_head)
            if h:
                out.append(Segment(_r(seg[0]), _r(shaft), style, faded, cls="inset-vector"))
                out.append(Polyline(tuple(_r(p) for p in h), style, closed=True, faded=faded,
                                    cls="inset-head" + (" open" if open_head else " filled")))
                continue
        out.append(Segment(_r(seg[0]), _r(seg[1]), style, faded, cls="inset-vector"))
    shown = set(visible)
    for names, _, x, base, _, _ in ins.labels:
        vis = [n for n in names if n in shown]
        if not vis:
            continue
        for n in vis:             # each at its own place (a group lies within 0.6 mm)
            out.append(Circle(_r(ins.show(points[n])), 0.9 if n == pole else 0.55,
                              "pole" if n == pole else "vertex", n in old, cls="inset-vertex"))
    return out


def labels(ins: Inset, visible, size: float, old=()):
    """The inset's vertex labels (of the visible vertices; lighter when all of a label's
    vertices are ``old``, drawn in earlier stages) and its caption."""
    shown = set(visible)
    out = []
    for names, text, x, base, _, lead in ins.labels:
        if all(n in shown for n in names):
            faded = all(n in old for n in names)
            out.append(Text(x, base, text, size, role="vertex", cls="inset-label",
                            weight="normal" if faded else "bold", faded=faded))
            if lead is not None:
                out.append(Segment(lead[0], lead[1], "leader", faded, cls="inset-leader"))
    text, x, base, _ = ins.caption
    if text:
        out.append(Text(x, base, text, ins.caption_size, "middle", role="inset",
                        cls="inset-caption"))
    return out


def _r(p: Pt) -> Pt:
    return (round(p[0], 3), round(p[1], 3))
