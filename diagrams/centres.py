"""The instant-centre drawing: the space diagram with every centre I_ij, the lines of centres
Kennedy's theorem intersected, and the circle diagram.

Centres come from :func:`polygons.centres.instant_centres` (nothing is recomputed here).  A
finite centre is a small filled dot labelled I13; a centre at infinity is an arrow along its
direction labelled 'I14 → ∞'; a centre too far off to draw to the mechanism's scale is an arrow
pointing at it, its coordinates in the legend.  The circle diagram numbers the links as points
on a circle; a chord is solid for a centre known from a joint, dashed for one found by Kennedy.
"""
from __future__ import annotations

import math

from polygons.centres import Centres, instant_centres, pair_name

from . import scale as scales
from .labels import Box, bounds
from .layout import arrow_head, compose
from .model import Arrow, Circle, Group, Segment, Text
from .space import LABEL_SIZE, PAD_MM, space_layout
from .text import number

Pt = tuple[float, float]
NOTE = 2.8
#: centres further than this many mechanism sizes from it are not drawn to scale
FAR = 2.5
CIRCLE_R = 16.0


def _r(p: Pt) -> Pt:
    return (round(p[0], 3), round(p[1], 3))


def drawing(sol, centres: Centres | None = None, paper: str | None = None):
    """The :class:`~diagrams.model.Drawing` of the centres of ``sol``."""
    cs = centres if centres is not None else instant_centres(sol)
    pos = {k: tuple(v) for k, v in sol.placement.points.items()}
    bb = bounds(list(pos.values()))
    size = max(bb.x1 - bb.x0, bb.y1 - bb.y0, 1e-9)
    mid = ((bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2)
    near = [c for c in cs.centres if c.point is not None
            and math.dist(c.point, mid) <= FAR * size]
    allb = bounds(list(pos.values()) + [c.point for c in near])
    extent = (allb.x1 - allb.x0, allb.y1 - allb.y0)
    sc = scales.choose("length", extent, [], paper or "A4", pad_mm=PAD_MM)
    content, box, sc, placer = space_layout(sol, sc, paper)
    k = sc.mm_per_si

    def P(p) -> Pt:
        return ((p[0] - bb.x0) * k, (p[1] - bb.y0) * k)

    lines, dots, arrows, labels = [], [], [], []
    nearset = {(c.i, c.j) for c in near}
    by = {(c.i, c.j): c for c in cs.centres}
    # the lines of centres used by Kennedy, each drawn through the centres it joins
    for c in cs.centres:
        if c.primary or c.point is None or (c.i, c.j) not in nearset:
            continue
        for pair in c.lines:
            pts = [c.point]
            for lab in pair:
                if lab.startswith("normal at "):
                    pts.append(pos[lab[len("normal at "):]])
                elif lab.startswith("I"):
                    i, j = _pair(lab, by)
                    o = by[(i, j)]
                    if o.point is not None and (i, j) in nearset:
                        pts.append(o.point)
            if len(pts) >= 2:
                a, b = _extreme(pts)
                lines.append(Segment(_r(P(a)), _r(P(b)), "construction",
                                     cls=f"line-of-centres {c.label}"))
    for c in cs.centres:
        if c.point is not None and (c.i, c.j) in nearset:
            q = P(c.point)
            dots.append(Circle(_r(q), 0.9, "vertex", cls=f"centre {c.label}", ident=c.label))
            x, base, _, _ = placer.place(c.label, q, NOTE + 0.4,
                                         distances=(1.0, 1.8, 2.8, 4.0, 6.0, 9.0))
            labels.append(Text(x, base, c.label, NOTE + 0.4, role="centre", cls="centre-label"))
            continue
        # at infinity (a direction) or too far off: an arrow from the nearest drawn point
        if c.point is None:
            d = c.direction
            start = _start_of(c, cs, pos, mid)
            text = f"{c.label} → ∞"
        else:
            start = _toward(c, by, nearset, mid)
            d = (c.point[0] - start[0], c.point[1] - start[1])
            n = math.hypot(*d)
            d = (d[0] / n, d[1] / n)
            text = f"{c.label} (off the page)"
        s = P(start)
        tip = (s[0] + 14.0 * d[0], s[1] + 14.0 * d[1])
        head, shaft = arrow_head(s, tip, 2.6, 0.9)
        arrows.append(Arrow(_r(s), _r(tip), "construction", tuple(_r(h) for h in head),
                            _r(shaft), name=c.label, role="infinity", title=text))
        placer.hard(s, tip, 0.6)
        x, base, _, _ = placer.place(text, tip, NOTE, distances=(0.8, 1.5, 2.5, 4.0, 6.0))
        labels.append(Text(x, base, text, NOTE, role="centre", cls="centre-label"))

    # the point of least velocity on each link asked for ([least_velocity]): the foot of the
    # perpendicular from the link's centre I_1j, the same point as og ⟂ ab on the polygon
    from polygons.pins import has_pins, least_velocity, spec
    least_notes: list[str] = []
    if has_pins(sol.scene):
        for link in spec(sol.scene).least:
            lv = least_velocity(sol, link)
            c = cs.centre(1, cs.body(link).number)
            if lv.fraction is None or c.point is None or (c.i, c.j) not in nearset:
                continue
            g = P(lv.point)
            lines.append(Segment(_r(P(c.point)), _r(g), "offset", cls=f"least {link}"))
            dots.append(Circle(_r(g), 0.8, "pin", cls=f"least-point {link}"))
            x, base, _, _ = placer.place("G", g, LABEL_SIZE - 0.6,
                                         distances=(1.0, 2.0, 3.5, 5.0, 8.0))
            labels.append(Text(x, base, "G", LABEL_SIZE - 0.6, role="centre",
                               weight="bold", cls="least-label"))
            least_notes.append(f"G on {link}: {lv.a}G = {number(lv.along * 1000)} mm, "
                               f"least v = {number(lv.speed)} m/s (⟂ from {c.label})")

    # the circle diagram, to the right of everything drawn so far
    for g in content:
        for it in g.items:
            if isinstance(it, Text):
                from .labels import text_box
                box = box.union(text_box(it.x, it.baseline, it.text, it.size))
    for it in lines + dots + labels:
        if isinstance(it, Segment):
            box = box.union(bounds([it.a, it.b]))
        elif isinstance(it, Circle):
            box = box.union(bounds([it.centre]))
    for a in arrows:
        box = box.union(bounds([a.tail, a.tip]))
    cx, cy = box.x1 + 12.0 + CIRCLE_R, (box.y0 + box.y1) / 2
    circle = _circle_diagram(cs, (cx, cy))
    box = box.union(Box(cx - CIRCLE_R - 8, cy - CIRCLE_R - 8, cx + CIRCLE_R + 8,
                        cy + CIRCLE_R + 8))
    content = content + [
        Group("centres-lines", "lines-of-centres", "Lines of centres (Kennedy)", tuple(lines)),
        Group("centres-points", "centres", "Instant centres", tuple(dots + arrows)),
        Group("centres-labels", "labels", "Centre labels", tuple(labels)),
        Group("circle-diagram", "circle-diagram",
              "Circle diagram: solid chords known from joints, dashed found by Kennedy",
              circle)]
    legend = [("Links:", "bold")] + [(f"{b.number}  {b.name}", "normal") for b in cs.bodies]
    legend += [("", "normal"), ("Centres:", "bold")]
    for c in cs.centres:
        where = (f"({_mm(c.point[0], size)}, {_mm(c.point[1], size)}) mm"
                 if c.point is not None else
                 f"∞ along {number(round(math.degrees(math.atan2(c.direction[1], c.direction[0])), 6) + 0.0, 4)}°")
        legend.append((f"{c.label} {where}: {c.how}", "normal"))
    legend += [("", "normal"), ("ω by the centres:", "bold")]
    for o in cs.omegas[1:]:
        legend.append((f"ω{o.number} ({o.name}) = {number(abs(o.omega))} rad/s "
                       f"{'' if o.omega == 0 else ('CCW' if o.omega > 0 else 'CW')}", "normal"))
    if least_notes:
        legend += [("", "normal"), ("Least velocity:", "bold")]
        legend += [(t, "normal") for t in least_notes]
    scene = sol.scene
    sid = scene.source.get("id", "")
    desc = ("Instant centres by Kennedy's theorem: " +
            "; ".join(f"{c.label}: {c.how}" for c in cs.centres) + ".")
    return compose(name="centres", kind="space", stage=None, title="Instantaneous centres",
                   subtitle=f"{sid}: {scene.title}" if sid else scene.title, desc=desc,
                   content=content, content_box=box.grown(1.0), legend=legend, scale=sc,
                   caption=["Solid chords of the circle diagram: centres at the joints; "
                            "dashed: found by Kennedy's theorem (three links, three centres "
                            "on one line)."],
                   scale_statement=sc.statement, meta={})


def _mm(x: float, size: float) -> str:
    """A coordinate in mm, rounding noise (below 1e-9 of the mechanism's size) shown as 0."""
    return number(0.0 if abs(x) < 1e-9 * size else x * 1000)


def _pair(label: str, by) -> tuple[int, int]:
    for (i, j) in by:
        if "I" + pair_name(i, j) == label:
            return (i, j)
    raise KeyError(label)


def _extreme(pts) -> tuple[Pt, Pt]:
    best = (pts[0], pts[1])
    for a in pts:
        for b in pts:
            if math.dist(a, b) > math.dist(*best):
                best = (a, b)
    return best


def _toward(c, by, nearset, mid) -> Pt:
    """Where the arrow to a far centre starts: the drawn centre on one of its lines of
    centres nearest to it (the arrow then runs along that line), else the mechanism's middle."""
    best = None
    for pair in c.lines:
        for lab in pair:
            if not lab.startswith("I"):
                continue
            o = by[_pair(lab, by)]
            if o.point is not None and (o.i, o.j) in nearset:
                dist = math.dist(o.point, c.point)
                if best is None or dist < best[0]:
                    best = (dist, o.point)
    return best[1] if best is not None else mid


def _start_of(c, cs: Centres, pos, mid) -> Pt:
    """Where a centre-at-infinity arrow starts: a point of the higher-numbered link."""
    body = cs.body(c.j)
    for lab in body.labels:
        if lab in pos:
            return pos[lab]
    return mid


def _circle_diagram(cs: Centres, centre: Pt) -> tuple:
    n = len(cs.bodies)
    at = {}
    items = [Circle(_r(centre), CIRCLE_R, "centre", cls="circle")]
    for b in cs.bodies:
        th = math.pi / 2 - 2 * math.pi * (b.number - 1) / n
        at[b.number] = (centre[0] + CIRCLE_R * math.cos(th), centre[1] + CIRCLE_R * math.sin(th))
    for c in cs.centres:
        style = "link-thin" if c.primary else "construction"
        items.append(Segment(_r(at[c.i]), _r(at[c.j]), style,
                             cls=f"chord {'known' if c.primary else 'found'} {c.label}"))
    for b in cs.bodies:
        p = at[b.number]
        items.append(Circle(_r(p), 1.0, "vertex", cls="link-point"))
        th = math.atan2(p[1] - centre[1], p[0] - centre[0])
        q = (p[0] + 4.0 * math.cos(th), p[1] + 4.0 * math.sin(th) - 1.3)
        items.append(Text(round(q[0], 3), round(q[1], 3), str(b.number), LABEL_SIZE, "middle",
                          role="link-number", weight="bold"))
    return tuple(items)


def svg(sol, centres: Centres | None = None, paper: str | None = None) -> str:
    """The drawing as SVG text."""
    from .svg import to_svg
    return to_svg(drawing(sol, centres, paper)).decode()


def centres_figure(solution) -> str:
    """The instant-centre figure of a solved scene as SVG text (for the handout's stage)."""
    return svg(solution)
