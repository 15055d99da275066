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

from polygons.centres import FULL_BODIES, Centres, instant_centres, pair_name, sub

from . import scale as scales
from .labels import Box, Placer, bounds, box_hits_segment, width
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


def _ident(c) -> str:
    return c.label.replace(",", "-")


def label_of(c) -> str:
    """I₁₃ (textbook subscripts), I₁,₁₃ past link 9."""
    return "I" + sub(pair_name(c.i, c.j))


def drawing(sol, centres: Centres | None = None, paper: str | None = None):
    """The :class:`~diagrams.model.Drawing` of the centres of ``sol``."""
    cs = centres if centres is not None else instant_centres(sol)
    big = not cs.complete or len(cs.bodies) > FULL_BODIES
    pos = {k: tuple(v) for k, v in sol.placement.points.items()}
    bb = bounds(list(pos.values()))
    size = max(bb.x1 - bb.x0, bb.y1 - bb.y0, 1e-9)
    mid = ((bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2)
    # a large mechanism: the centre I1j of each link (the one its velocities use) and the
    # primary centres at the pins (the pins themselves, not labelled again)
    shown = [c for c in cs.centres if not big or c.i == 1 or c.primary]
    near = [c for c in shown if c.point is not None and math.dist(c.point, mid) <= FAR * size]
    allb = bounds(list(pos.values()) + [c.point for c in near])
    extent = (allb.x1 - allb.x0, allb.y1 - allb.y0)
    sc = scales.choose("length", extent, [], paper or "A4", pad_mm=PAD_MM)
    content, box, sc, placer = space_layout(sol, sc, paper)
    k = sc.mm_per_si

    def P(p) -> Pt:
        return ((p[0] - bb.x0) * k, (p[1] - bb.y0) * k)

    lines, dots, arrows, labels, leaders = [], [], [], [], []
    nearset = {(c.i, c.j) for c in near}
    by_label = {c.label: c for c in cs.centres}
    # the lines of centres Kennedy intersected, each through the centres it joins (soft
    # obstacles for the labels)
    for c in ([] if big else cs.centres):
        if c.primary or c.point is None or (c.i, c.j) not in nearset:
            continue
        for pair in c.lines:
            pts = [c.point] + [by_label[lab].point for lab in pair
                               if lab in by_label and (by_label[lab].i, by_label[lab].j)
                               in nearset]
            if len(pts) >= 2:
                a, b = _extreme(pts)
                if math.dist(P(a), P(b)) < 0.5:
                    continue
                lines.append(Segment(_r(P(a)), _r(P(b)), "construction",
                                     cls=f"line-of-centres {_ident(c)}"))
                placer.soft(P(a), P(b))
    # finite centres: one dot per place, the centres there in one label with a leader
    groups: dict[tuple[float, float], list] = {}
    for c in near:
        q = _r(P(c.point))
        key = (round(q[0] / 0.05) * 0.05, round(q[1] / 0.05) * 0.05)
        groups.setdefault(key, []).append((c, q))
    for key in sorted(groups, key=lambda g: (groups[g][0][0].i, groups[g][0][0].j)):
        members = groups[key]
        q = members[0][1]
        for c, _ in members:
            dots.append(Circle(q, 0.9, "vertex", cls=f"centre {_ident(c)}", ident=_ident(c)))
        placer.block(Box(q[0] - 1.0, q[1] - 1.0, q[0] + 1.0, q[1] + 1.0))
    unlabelled = 0
    for key in sorted(groups, key=lambda g: (groups[g][0][0].i, groups[g][0][0].j)):
        members = groups[key]
        if big and all(c.i != 1 or c.primary for c, _ in members):
            continue                      # a pin: drawn as the pin
        q = members[0][1]
        text = " = ".join(label_of(c) for c, _ in members
                          if not big or (c.i == 1 and not c.primary))
        got = _place(placer, text, NOTE + 0.4, q,
                     (1.8, 3.0, 5.0, 8.0, 12.0) if big else (1.8, 2.6, 3.6, 5.0, 7.0, 9.5, 13.0),
                     leader=True, directions=12 if big else 24, required=not big)
        if got is None:                   # no room (a crowded large drawing): dot only
            unlabelled += 1
            continue
        x, base, _, tb = got
        labels.append(Text(x, base, text, NOTE + 0.4, role="centre", cls="centre-label"))
        lead = _leader(q, tb)
        if lead is not None:
            leaders.append(Segment(_r(lead[0]), _r(lead[1]), "leader", cls="centre-leader"))
            placer.hard(lead[0], lead[1], 0.2)
    for c in shown:
        if (c.i, c.j) in nearset or (c.point is None and c.direction is None):
            continue
        # at infinity (a direction) or too far off: an arrow from the nearest drawn point
        if c.point is None:
            d = c.direction
            start = _start_of(c, cs, pos, mid)
            text = f"{label_of(c)} → ∞"
        else:
            start = _toward(c, by_label, nearset, mid)
            d = (c.point[0] - start[0], c.point[1] - start[1])
            n = math.hypot(*d)
            d = (d[0] / n, d[1] / n)
            text = f"{label_of(c)} (off the page)"
        s0 = P(start)
        # no sense at infinity: the side clear of the drawing, starting past what is there
        ways = [(d, (-d[0], -d[1])) if c.point is None else (d,)][0]
        here = _local(placer, s0, 36.0)
        cost, d, off = min(((_arrow_cost(here, s0, u, off) + 0.25 * off, u, off)
                            for off in (1.6, 4.5, 7.5, 10.5, 13.5) for u in ways),
                           key=lambda t: t[0])
        s = (s0[0] + off * d[0], s0[1] + off * d[1])
        tip = (s[0] + 14.0 * d[0], s[1] + 14.0 * d[1])
        head, shaft = arrow_head(s, tip, 2.6, 0.9)
        arrows.append(Arrow(_r(s), _r(tip), "construction", tuple(_r(h) for h in head),
                            _r(shaft), name=_ident(c), role="infinity", title=text))
        placer.hard(s, tip, 0.6)
        x, base, _, tb = _place(placer, text, NOTE, tip, (0.8, 1.5, 2.5, 4.0, 6.0))
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
                               f"least v = {number(lv.speed)} m/s (⟂ from {label_of(c)})")

    # the circle diagram, to the right of everything drawn so far
    from .labels import text_box
    # no line of centres through a label: each is cut where it crosses one (the space
    # diagram's labels, the centres' labels)
    texts = [text_box(it.x, it.baseline, it.text, it.size).grown(0.5)
             for g in content for it in g.items if isinstance(it, Text)]
    texts += [text_box(it.x, it.baseline, it.text, it.size).grown(0.5) for it in labels]
    lines = [piece for seg in lines for piece in _cut(seg, texts)]
    for g in content:
        for it in g.items:
            if isinstance(it, Text):
                box = box.union(text_box(it.x, it.baseline, it.text, it.size))
    for it in lines + dots + leaders:
        if isinstance(it, Segment):
            box = box.union(bounds([it.a, it.b]))
        elif isinstance(it, Circle):
            box = box.union(bounds([it.centre]))
    for it in labels:
        box = box.union(text_box(it.x, it.baseline, it.text, it.size))
    for a in arrows:
        box = box.union(bounds([a.tail, a.tip]))
    circle: tuple = ()
    if not big:
        cx, cy = box.x1 + 12.0 + CIRCLE_R, (box.y0 + box.y1) / 2
        circle = _circle_diagram(cs, (cx, cy))
        box = box.union(Box(cx - CIRCLE_R - 8, cy - CIRCLE_R - 8, cx + CIRCLE_R + 8,
                            cy + CIRCLE_R + 8))
    content = content + [
        Group("centres-lines", "lines-of-centres", "Lines of centres (Kennedy)", tuple(lines)),
        Group("centres-points", "centres", "Instant centres", tuple(dots + arrows)),
        Group("centres-leaders", "leaders", "Leaders to the centre labels", tuple(leaders)),
        Group("centres-labels", "labels", "Centre labels", tuple(labels))]
    if circle:
        content.append(Group("circle-diagram", "circle-diagram",
                             "Circle diagram: solid chords known from joints, dashed found by "
                             "Kennedy", circle))
    legend = _legend(cs, size, big, least_notes)
    scene = sol.scene
    sid = scene.source.get("id", "")
    desc = ("Instant centres: " + cs.note + ". " +
            "; ".join(f"{c.label}: {c.how}" for c in shown[:60]) + ".")
    if big:
        caption = [f"{len(cs.bodies)} links: drawn are the centre I1j of every link (the one "
                   f"its velocities use) and the primary centres at the pins (the pins "
                   f"themselves, not labelled again); the lines of centres, the circle diagram "
                   f"and the other centres are left out (polygons centres --json lists the "
                   f"{len(cs.centres)} found)."
                   + (f" {unlabelled} centre{'s' if unlabelled > 1 else ''} too crowded to "
                      f"label {'are' if unlabelled > 1 else 'is'} drawn as a dot only."
                      if unlabelled else "")]
    elif any(c.by_field for c in cs.centres) and len(scene.model.inputs) == 1:
        caption = ["Kennedy's theorem leaves some centres open here (no two distinct lines of "
                   "centres meet there: a group of three links on a plate, or a toggle); those "
                   "marked 'from the velocity field' in the legend are read off the polygon's "
                   "velocities, the others come from the pairs and Kennedy's theorem. Solid "
                   "chords of the circle diagram: centres at the pairs; dashed: found."]
    elif any(c.by_field for c in cs.centres):
        caption = ["Two inputs are given at this instant: each link's centre I1j is read off "
                   "its velocity field (the polygon's velocities), the others from the pairs "
                   "and Kennedy's theorem. Solid chords of the circle diagram: centres at the "
                   "pairs; dashed: found."]
    else:
        caption = ["Solid chords of the circle diagram: centres at the joints; dashed: found "
                   "by Kennedy's theorem (three links, three centres on one line)."]
    key = [("link", "link (rigid body)", False)]
    if lines:
        key.append(("construction", "line of centres (Kennedy)", False))
    if arrows:
        key.append(("construction", "towards a centre at infinity or off the page", True))
    if leaders:
        key.append(("leader", "leader from a centre to its label", False))
    return compose(name="centres", kind="space", stage=None, title="Instantaneous centres",
                   subtitle=f"{sid}: {scene.title}" if sid else scene.title, desc=desc,
                   content=content, content_box=box.grown(1.0), legend=legend, scale=sc,
                   caption=caption, scale_statement=sc.statement, meta={}, key=key)


def _cut(seg: Segment, boxes) -> list[Segment]:
    """``seg`` without its parts inside any of ``boxes`` (Liang–Barsky on each box)."""
    (ax, ay), (bx, by) = seg.a, seg.b
    dx, dy = bx - ax, by - ay
    gone: list[tuple[float, float]] = []
    for b in boxes:
        t0, t1 = 0.0, 1.0
        for p, q in ((-dx, ax - b.x0), (dx, b.x1 - ax), (-dy, ay - b.y0), (dy, b.y1 - ay)):
            if p == 0:
                if q < 0:
                    t0, t1 = 1.0, 0.0
                    break
                continue
            t = q / p
            if p < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
        if t0 < t1:
            gone.append((t0, t1))
    if not gone:
        return [seg]
    out, t = [], 0.0
    for g0, g1 in sorted(gone) + [(1.0, 1.0)]:
        if g0 > t and math.hypot(dx, dy) * (g0 - t) > 0.8:
            out.append(Segment(_r((ax + t * dx, ay + t * dy)), _r((ax + g0 * dx, ay + g0 * dy)),
                               seg.style, cls=seg.cls))
        t = max(t, g1)
    return out


def _leader_cost(placer, q: Pt, box: Box) -> float:
    """A label whose leader would cross another label or a line costs more (so the leader
    runs clear of the ω/α arcs, the links and the other labels where it can)."""
    lead = _leader(q, box)
    if lead is None:
        return 0.0
    a, b = lead
    c = 6.0 if any(box_hits_segment(o, a, b, 0.0) for o in placer.boxes) else 0.0
    if any(_cross(a, b, p0, p1) for p0, p1, _ in placer.hard_segments):
        c += 1.2
    if any(_cross(a, b, p0, p1) for p0, p1 in placer.soft_segments):
        c += 0.3
    return c + 0.15 * math.dist(a, b)


def _place(placer: Placer, text: str, size: float, at: Pt, distances, leader=False,
           directions: int = 24, required: bool = True):
    """``placer.place`` around ``at`` (``directions`` of them), with a leader's cost when ``leader``,
    tried first among the obstacles within reach of its candidates only (the same choice, at
    a cost that does not grow with the drawing), then, if none is free there, in the whole
    drawing (only when ``required``: else None); the label's box is added to ``placer``."""
    dirs = [(at, [2 * math.pi * i / directions for i in range(directions)])]
    reach = max(distances) + width(text, size) + 2.0 * size + 3.0
    tries = [(_local(placer, at, reach), False)] + ([(placer, True)] if required else [])
    for here, must in tries:
        cost = (lambda _, b, here=here: _leader_cost(here, at, b)) if leader else None
        got = here.place_any(text, size, dirs, distances=distances, extra_cost=cost,
                             required=must)
        if got is not None:
            if here is not placer:
                placer.block(got[3])
            return got
    return None


def _local(placer: Placer, at: Pt, reach: float) -> Placer:
    """A placer holding only ``placer``'s obstacles within ``reach`` (mm) of ``at``."""
    x0, y0, x1, y1 = at[0] - reach, at[1] - reach, at[0] + reach, at[1] + reach

    def near(a, b) -> bool:
        return not (max(a[0], b[0]) < x0 or min(a[0], b[0]) > x1
                    or max(a[1], b[1]) < y0 or min(a[1], b[1]) > y1)

    return Placer([h for h in placer.hard_segments if near(h[0], h[1])],
                  [h for h in placer.soft_segments if near(h[0], h[1])],
                  [b for b in placer.boxes if near((b.x0, b.y0), (b.x1, b.y1))],
                  placer.frame, placer.soft_cost)


def _arrow_cost(placer, s: Pt, d: Pt, off: float) -> float:
    """How much an arrow from ``off`` past ``s`` along ``d`` would cover: labels, then
    lines."""
    a = (s[0] + off * d[0], s[1] + off * d[1])
    b = (a[0] + 16.0 * d[0], a[1] + 16.0 * d[1])
    c = 6.0 * sum(box_hits_segment(o, a, b, 0.5) for o in placer.boxes
                  if not (o.x0 <= s[0] <= o.x1 and o.y0 <= s[1] <= o.y1))
    c += sum(_cross(a, b, p0, p1) or _near(p0, p1, a, b) for p0, p1, _ in placer.hard_segments)
    return c


def _near(p0: Pt, p1: Pt, a: Pt, b: Pt) -> bool:
    """Whether segment p0p1 runs along ab (within 1 mm of its middle)."""
    m = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    n2 = dx * dx + dy * dy
    if n2 == 0:
        return math.dist(m, p0) < 1.0
    t = max(0.0, min(1.0, ((m[0] - p0[0]) * dx + (m[1] - p0[1]) * dy) / n2))
    return math.dist(m, (p0[0] + t * dx, p0[1] + t * dy)) < 1.0


def _cross(a: Pt, b: Pt, c: Pt, d: Pt) -> bool:
    """Whether segments ab and cd cross (touching ends do not count)."""
    def side(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    s1, s2 = side(a, b, c), side(a, b, d)
    s3, s4 = side(c, d, a), side(c, d, b)
    return s1 * s2 < 0 and s3 * s4 < 0


def _leader(q: Pt, box: Box) -> tuple[Pt, Pt] | None:
    """A leader from the dot at ``q`` to the nearest point of the label's box, when the label
    stands off the dot."""
    x = min(max(q[0], box.x0), box.x1)
    y = min(max(q[1], box.y0), box.y1)
    d = math.dist(q, (x, y))
    if d < 1.6:
        return None
    u = ((x - q[0]) / d, (y - q[1]) / d)
    return (q[0] + 1.1 * u[0], q[1] + 1.1 * u[1]), (x - 0.3 * u[0], y - 0.3 * u[1])


def _legend(cs: Centres, size: float, big: bool, least_notes) -> list[tuple[str, str]]:
    if big:
        legend = [("Links:", "bold")]
        row: list[str] = []
        for b in cs.bodies:
            row.append(f"{b.number} {b.name}")
            if len(row) == 8:
                legend.append((", ".join(row), "normal"))
                row = []
        if row:
            legend.append((", ".join(row), "normal"))
        return legend
    legend = [("Links:", "bold")] + [(f"{b.number}  {b.name}", "normal") for b in cs.bodies]
    legend += [("", "normal"), ("Centres:", "bold")]
    for c in cs.centres:
        if c.point is not None:
            where = f"({_mm(c.point[0], size)}, {_mm(c.point[1], size)}) mm"
        elif c.direction is not None:
            ang = round(math.degrees(math.atan2(c.direction[1], c.direction[0])), 6) + 0.0
            where = f"∞ along {number(ang, 4)}°"
        else:
            where = "any point"
        how = c.how if len(c.how) <= 70 else c.how.split(" (")[0]
        legend.append((f"{label_of(c)} {where}: {how}", "normal"))
    legend += [("", "normal"), ("ω by the centres:", "bold")]
    for o in cs.omegas[1:]:
        legend.append((f"ω{sub(o.number)} ({o.name}) = {number(abs(o.omega))} rad/s "
                       f"{'' if o.omega == 0 else ('CCW' if o.omega > 0 else 'CW')}", "normal"))
    if least_notes:
        legend += [("", "normal"), ("Least velocity:", "bold")]
        legend += [(t, "normal") for t in least_notes]
    return legend


def _mm(x: float, size: float) -> str:
    """A coordinate in mm, rounding noise (below 1e-9 of the mechanism's size) shown as 0."""
    return number(0.0 if abs(x) < 1e-9 * size else x * 1000)


def _extreme(pts) -> tuple[Pt, Pt]:
    best = (pts[0], pts[1])
    for a in pts:
        for b in pts:
            if math.dist(a, b) > math.dist(*best):
                best = (a, b)
    return best


def _toward(c, by_label, nearset, mid) -> Pt:
    """Where the arrow to a far centre starts: the drawn centre on one of its lines of
    centres nearest to it (the arrow then runs along that line), else the mechanism's middle."""
    best = None
    for pair in c.lines:
        for lab in pair:
            o = by_label.get(lab)
            if o is not None and o.point is not None and (o.i, o.j) in nearset:
                dist = math.dist(o.point, c.point)
                if best is None or dist < best[0]:
                    best = (dist, o.point)
    return best[1] if best is not None else mid


def _start_of(c, cs: Centres, pos, mid) -> Pt:
    """Where a centre-at-infinity arrow starts: a point the two links share, else the point of
    the block among them (it slides there), else a point of the higher-numbered link."""
    bi, bj = cs.body(c.i), cs.body(c.j)
    shared = [x for x in bj.labels if x in bi.labels and x in pos]
    if shared:
        return pos[shared[0]]
    for b in (bj, bi):
        if (b.kind.endswith("block") or b.kind in ("collar", "yoke")) and b.labels[0] in pos:
            return pos[b.labels[0]]
    for lab in bj.labels:
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
                             cls=f"chord {'known' if c.primary else 'found'} {_ident(c)}"))
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
