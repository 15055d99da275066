"""Free-body diagrams and force polygons of every moving body, in the style of the polygons'
SVGs (:mod:`diagrams`: same line styles, page, scale bar and writer).

For each state and body: ``fbd-<state>-<body>.svg``, the body to a length scale with every
force on it as an arrow of fixed length drawn from its point (labelled with its value and
direction), the inertia force −m a_G at each centre of mass dotted, couples as arcs; and
``forces-<state>-<body>.svg``, the force polygon to a round force scale: the same forces head
to tail, which close because the body is in (d'Alembert) equilibrium.  Every number comes from
the :class:`~polygons.forces.Analysis`; nothing is recomputed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from polygons.forces import Analysis, State, contact_force, position as _pos
from polygons.errors import PolygonsError, UnknownLabelError


@dataclass(frozen=True)
class Vector:
    name: str          # 'R_O', 'Gas', 'W_OA', '−m a_G (OA)'
    at: np.ndarray     # SI position of the point of application
    force: np.ndarray  # N
    kind: str          # 'contact' | 'load' | 'weight' | 'inertia' | 'input'


@dataclass(frozen=True)
class Couple:
    name: str
    at: np.ndarray
    value: float       # N m, CCW positive


def body_forces(an: Analysis, st: State, body: str) -> tuple[list[Vector], list[Couple]]:
    """Every force and couple on ``body`` at ``st`` (reactions, loads, weights, inertia)."""
    model = an.model
    b = model.bodies[body]
    sol, ne = st.sol, st.ne
    vecs: list[Vector] = []
    couples: list[Couple] = []
    seen = {s.coincident for s in model.slots
            if s.lever == body and s.coincident is not None}   # reported under the pin
    for lab in b.labels + tuple(s.pin for s in model.slots if s.lever == body):
        if lab in seen:
            continue
        try:
            f = contact_force(model, ne, lab, body)
        except UnknownLabelError:
            continue
        seen.add(lab)
        vecs.append(Vector(f"R_{lab}", _pos(sol, lab), f, "contact"))
    if body in ne.rolling:          # a rolling wheel: the surface's normal and friction
        v, n, _ = ne.guide[body]
        f, e, at = ne.rolling[body]
        vecs.append(Vector(f"N_{body} (surface)", np.asarray(at), v * n, "contact"))
        vecs.append(Vector(f"F_{body} (friction)", np.asarray(at), f * np.asarray(e),
                           "contact"))
    elif body in ne.guide:
        v, n, c = ne.guide[body]
        vecs.append(Vector(f"N_{body} (guide)", _pos(sol, body), v * n, "contact"))
        if c:
            couples.append(Couple(f"guide couple on {body}", _pos(sol, body), c))
    for ld in ne.loads:
        if ld.body != body:
            continue
        if ld.force.any() and ld.pos is not None:
            name = f"W_{ld.item}" if ld.kind == "gravity" else ld.source
            vecs.append(Vector(name, ld.pos, ld.force, "weight" if ld.kind == "gravity"
                               else "load"))
        if ld.couple:
            at = _pos(sol, ld.at) if ld.at else _pos(sol, b.a)
            couples.append(Couple(ld.source, at, ld.couple))
    drv = model.scene.driver
    if body == model.driver_body and ne.effort is not None:
        if b.kind == "block":
            e = np.array(model.scene.model.guide[body].line.direction)
            vecs.append(Vector("input force", _pos(sol, body), ne.effort * e, "input"))
        else:
            couples.append(Couple("input torque", _pos(sol, drv.pivot), ne.effort))
    for i in st.inertia:
        if i.body != body:
            continue
        if i.ma.any():
            vecs.append(Vector(f"−m a_G ({i.item})", i.centre, -i.ma, "inertia"))
        if i.i_alpha:
            couples.append(Couple(f"−I_G α ({i.item})", i.centre, -i.i_alpha))
    return vecs, couples


def _slug(text: str) -> str:
    return "".join(ch if ch.isalnum() else "-" for ch in text).strip("-").lower()


def _fmt(x: float) -> str:
    return f"{x:.4g}"


def _gap_words(gap: float, drawn) -> str:
    """The polygon's closing gap in words: 'gap 0 N' below 10⁻⁹ of its largest force (the
    arithmetic's rounding: it printed 'gap 7.3e-15 N'), else 'gap 0.12 N'."""
    big = max((float(np.hypot(*v.force)) for v in drawn), default=0.0)
    if gap <= 1e-9 * max(big, 1e-300):
        return "gap 0 N"
    return f"gap {_fmt(gap)} N"


def _dir(v) -> float:
    """A force's direction, degrees CCW from +x in [0, 360), printed with one decimal: a
    direction a hair under 360° is 0 (never '∠360.0°')."""
    d = math.degrees(math.atan2(v[1], v[0])) % 360.0
    return 0.0 if d >= 359.95 else d


def drawings(an: Analysis):
    """(file stem, Drawing) for every state and body that carries a force."""
    from .labels import bounds, text_box
    from .layout import FORCE_LEGEND_MM, arrow_head, compose
    from .model import Arrow, Circle, Group, Polyline, Segment
    from .scale import Scale, round_up

    out = []
    model = an.model
    for st in an.states:
        for name, body in model.bodies.items():
            vecs, couples = body_forces(an, st, name)
            if not any(float(np.hypot(*v.force)) > 0 for v in vecs) and not couples:
                continue
            pts = {lab: _pos(st.sol, lab) for lab in body.labels}
            pts.update({f"G:{i.item}": i.centre for i in st.inertia if i.body == name})
            allp = list(pts.values()) + [v.at for v in vecs]
            roll = st.ne.rolling.get(name)      # a wheel: its radius, centre to contact
            rr = None if roll is None else float(np.hypot(*(np.asarray(roll[2])
                                                             - pts[body.a])))
            if rr is not None:                  # the rim, all round its centre
                allp += [pts[body.a] + rr * np.array(d) for d in ((1, 0), (-1, 0), (0, 1),
                                                                  (0, -1))]
            bb = bounds([tuple(p) for p in allp])
            # a slider block is a point: its free body at the scale of a tenth of the
            # mechanism (not of nothing), the block drawn as its symbol
            spread = bounds([tuple(p.position) for p in st.sol.points.values()])
            ext = max(bb.x1 - bb.x0, bb.y1 - bb.y0,
                      0.1 * max(spread.x1 - spread.x0, spread.y1 - spread.y0), 1e-9)
            lscale = Scale("length", round_up(ext * 10.0 / 90.0), "mm", 1e-3)
            k = lscale.mm_per_si

            def P(p):
                return (round((p[0] - bb.x0) * k, 3), round((p[1] - bb.y0) * k, 3))

            items = []
            rim = []
            if rr is not None:              # a wheel: its rim to scale, the contact on it
                c = P(pts[body.a])
                rad = rr * k
                rim = [(c[0] + rad * math.cos(t * math.pi / 24),
                        c[1] + rad * math.sin(t * math.pi / 24)) for t in range(49)]
                items.append(Polyline(tuple(rim), "link", cls=f"body wheel {name}"))
            elif body.kind == "block":
                c = P(pts[body.a])
                e = np.array(model.scene.model.guide[body.a].line.direction)
                n = np.array([-e[1], e[0]])
                corners = [np.array(c) + sx * 6 * e + sy * 4 * n
                           for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
                items.append(Polyline(tuple(tuple(map(float, q)) for q in corners), "block",
                                      closed=True, cls=f"body {name}"))
            else:
                a, bq = P(pts[body.a]), P(pts[body.b])
                items.append(Segment(a, bq, "link", cls=f"body {name}"))
                for lab, p in pts.items():
                    if lab not in (body.a, body.b):
                        items.append(Segment(a, P(p), "link-thin", cls=f"body {name}"))
            # geometry first (body, arrows, arcs), then every label by the placer, clear of
            # all of them and of each other (diagrams.labels)
            arrows, labels, leaders, texts = [], [], [], []
            L = 16.0
            segments = [(it.a, it.b) for it in items if isinstance(it, Segment)]
            for lab, p in pts.items():
                q = P(p)
                if lab.startswith("G:"):
                    items.append(Circle(q, 0.7, "vertex", cls="centre-of-mass"))
                    texts.append((f"G_{lab[2:]}", q, 2.6, "vertex", "normal", None))
                else:
                    items.append(Circle(q, 1.1, "pin", cls="point"))
                    texts.append((lab, q, 3.2, "vertex", "bold", None))
            for v in vecs:
                mag = float(np.hypot(*v.force))
                if mag == 0.0:
                    continue
                u = v.force / mag
                tail = P(v.at)
                tip = (tail[0] + L * u[0], tail[1] + L * u[1])
                text = f"{v.name} {_fmt(mag)} N ∠{_dir(v.force):.1f}°"
                side = _along_member(tail, tip, segments)
                if side is not None:
                    # beside a two-force member: the arrow parallel to the rod, off it
                    tail = (tail[0] + BESIDE * side[0], tail[1] + BESIDE * side[1])
                    tip = (tip[0] + BESIDE * side[0], tip[1] + BESIDE * side[1])
                mid = ((tail[0] + tip[0]) / 2, (tail[1] + tip[1]) / 2)
                texts.append((text, mid, 2.5, "label", "normal", (tail, tip)))
                head, shaft = arrow_head(tail, tip)
                style = "result" if v.kind == "inertia" else "vector"
                arrows.append(Arrow(tail, tip, style, head, shaft, name=v.name,
                                    role="known", title=f"{v.name} = {_fmt(mag)} N"))
            arcs = list(zip(rim, rim[1:]))       # labels kept off a wheel's rim too
            for cpl in couples:
                c = P(cpl.at)
                r = 6.0
                sgn = 1.0 if cpl.value > 0 else -1.0
                angs = [math.radians(200) + sgn * math.radians(t) for t in range(0, 241, 20)]
                arc = tuple((c[0] + r * math.cos(t), c[1] + r * math.sin(t)) for t in angs)
                items.append(Polyline(arc[:-1], "vector", cls="couple"))
                arcs += list(zip(arc, arc[1:]))
                head, shaft = arrow_head(arc[-2], arc[-1], length=2.2, half=0.8)
                arrows.append(Arrow(arc[-2], arc[-1], "vector", head, shaft, name=cpl.name,
                                    role="arc", title=f"{cpl.name} {_fmt(abs(cpl.value))} N m"))
                texts.append((f"{cpl.name} {_fmt(abs(cpl.value))} N m "
                              f"{'CCW' if cpl.value > 0 else 'CW'}", c, 2.5, "label", "normal",
                              "arc"))
            placed = _place_labels(texts, segments, arrows, arcs, labels, leaders)
            content = [Group("body", "body", f"{name}", tuple(items)),
                       Group("forces", "forces", "forces on the body", tuple(arrows)),
                       Group("labels", "labels", "values", tuple(labels))]
            if leaders:
                content.append(Group("leaders", "leaders", "leaders from the values to the "
                                     "forces they name", tuple(leaders)))
            xs = [q for it in items + arrows + leaders for q in _pts(it)]
            box = bounds(xs)
            for o in placed:
                box = box.union(o)
            box = box.grown(6.0)
            legend = [("solid: forces on the body", "normal"),
                      ("dotted: inertia force −m a_G", "normal"),
                      ("arcs: couples", "normal"),
                      ("arrows drawn 16 mm long;", "normal"),
                      ("lengths in the force polygon", "normal")]
            stem = f"fbd-{_slug(st.name)}-{_slug(name)}"
            out.append((stem, compose(
                name=stem, kind="free-body", stage=None,
                title=f"Free body: {name} ({st.name})",
                subtitle="forces on the body from its pins, guides, slots and loads",
                desc=f"Free-body diagram of {name}", content=content, content_box=box,
                legend=legend, scale=lscale,
                caption=[f"{model.scene.title}. Body drawn to scale; each arrow starts at "
                         f"the point the force acts on. The force polygon "
                         f"(forces-{_slug(st.name)}-{_slug(name)}.svg) draws them to "
                         f"scale."],
                scale_statement=lscale.statement, meta={})))

            # force polygon
            drawn = [v for v in vecs if float(np.hypot(*v.force)) > 0]
            if not drawn:
                continue
            big = max(float(np.hypot(*v.force)) for v in drawn)
            small = min(float(np.hypot(*v.force)) for v in drawn)
            from .inset import MIN_VECTOR_MM
            from .scale import force_scale
            fscale = Scale("force", force_scale(big, small), "N", 1.0)
            kf = fscale.mm_per_si
            cur = np.zeros(2)
            parr, plab, said = [], [], []
            for v in drawn:
                tail = (float(cur[0] * kf), float(cur[1] * kf))
                cur = cur + v.force
                tip = (float(cur[0] * kf), float(cur[1] * kf))
                mm = math.dist(tail, tip)
                if mm < MIN_VECTOR_MM:           # too short to draw: said in the legend
                    said.append((f"{v.name} ≈ 0 ({mm:.2f} mm at this scale: "
                                 f"{_fmt(float(np.hypot(*v.force)))} N, not drawn)", "normal"))
                    continue
                head, shaft = arrow_head(tail, tip)
                style = "result" if v.kind == "inertia" else "vector"
                parr.append(Arrow(tail, tip, style, head, shaft, name=v.name, role="known",
                                  title=f"{v.name} = {_fmt(float(np.hypot(*v.force)))} N"))
            gap = float(np.hypot(*cur))
            pleaders: list = []
            _place_labels([(a.name, None, 2.8, "label", "normal", (a.tail, a.tip))
                           for a in parr], [], parr, [], plab, pleaders)
            start = Circle((0.0, 0.0), 0.8, "pole", cls="start")
            pts2 = [(0.0, 0.0)] + [q for a in parr for q in (a.tail, a.tip)]
            box2 = bounds(pts2 + [q for it in pleaders for q in (it.a, it.b)])
            for t in plab:
                box2 = box2.union(text_box(t.x, t.baseline, t.text, t.size, t.anchor))
            box2 = box2.grown(6.0)
            stem2 = f"forces-{_slug(st.name)}-{_slug(name)}"
            couple_words = "; ".join(f"{c.name} {_fmt(abs(c.value))} N m "
                                     f"{'CCW' if c.value > 0 else 'CW'}" for c in couples)
            out.append((stem2, compose(
                name=stem2, kind="force", stage=None,
                title=f"Force polygon: {name} ({st.name})",
                subtitle="the forces on the body head to tail, inertia force included",
                desc=f"Force polygon of {name}",
                content=[Group("polygon", "force-polygon", f"forces on {name}",
                               tuple([start] + parr)),
                         Group("labels", "labels", "names", tuple(plab)),
                         Group("leaders", "leaders", "leaders from the names to the forces",
                               tuple(pleaders))],
                content_box=box2,
                legend=[(f"{v.name}: {_fmt(float(np.hypot(*v.force)))} N ∠"
                         f"{_dir(v.force):.2f}°", "normal") for v in drawn] + said,
                scale=fscale, legend_width=FORCE_LEGEND_MM,
                caption=[f"The polygon closes ({_gap_words(gap, drawn)}): the body is in "
                         f"equilibrium "
                         f"with its inertia force (d'Alembert)."
                         + (f" Couples (not in the polygon): {couple_words}."
                            if couples else "")],
                scale_statement=fscale.statement, meta={"gap_N": gap})))
    return out


#: a force along a member is drawn this far beside it (mm of paper)
BESIDE = 3.0


def _place_labels(texts, segments, arrows, arcs, labels: list, leaders: list) -> list:
    """Place every label of a free-body diagram with :class:`diagrams.labels.Placer`: point
    labels by their points, a force's value beside its arrow (nearer it than any other, else
    further out with a leader), a couple's value outside its arc.  Appends the ``Text`` items
    to ``labels`` and the leader ``Segment`` items to ``leaders``; returns the boxes."""
    from .labels import Placer, box_segment_distance
    from .model import Segment, Text
    placer = Placer()
    for a, b in segments:
        placer.hard(a, b, 0.6)
    for ar in arrows:
        placer.hard(ar.tail, ar.tip, 0.8)
    for a, b in arcs:
        placer.hard(a, b, 0.4)
    boxes = []
    for text, at, size, role, weight, own in texts:       # points first: they are fixed
        if own is not None:
            continue
        placer.block(_dot(at))
    for text, at, size, role, weight, own in texts:
        if own is None:
            x, base, _, box = placer.place(text, at, size, prefer=math.radians(45),
                                           distances=(0.9, 1.6, 2.6, 4.0, 6.0))
        elif own == "arc":
            x, base, _, box = placer.place(text, at, size, prefer=math.radians(-90),
                                           distances=(7.0, 8.5, 10.0, 12.0, 15.0))
        else:
            tail, tip = own
            others = [(ar.tail, ar.tip) for ar in arrows if (ar.tail, ar.tip) != own]

            def mine(_ai, box, own=own, others=others):
                d = box_segment_distance(box, *own)
                near = min((box_segment_distance(box, a, b) for a, b in others),
                           default=math.inf)
                return 6.0 if near < d + 2.5 else 0.0
            ang = math.atan2(tip[1] - tail[1], tip[0] - tail[0])
            anchors = [((tail[0] + f * (tip[0] - tail[0]), tail[1] + f * (tip[1] - tail[1])),
                        [ang + math.pi / 2, ang - math.pi / 2]) for f in (0.5, 0.7, 0.3, 0.9)]
            got = placer.place_any(text, size, anchors, distances=(0.8, 1.6, 2.6, 4.0),
                                   extra_cost=mine, required=False)
            if got is not None and mine(0, got[3]) > 0:
                placer.boxes.remove(got[3])
                got = None
            if got is None:
                mid = ((tail[0] + tip[0]) / 2, (tail[1] + tip[1]) / 2)
                got = placer.place(text, mid, size, distances=(5.0, 7.0, 9.0, 12.0, 16.0))
                lead = _lead(got[3], mid)
                if lead is not None:
                    leaders.append(Segment(lead[0], lead[1], "hatch", cls="leader"))
                    placer.hard(lead[0], lead[1], 0.3)
            x, base, _, box = got
        labels.append(Text(x, base, text, size, role="vertex" if role == "vertex" else "label",
                           weight=weight))
        boxes.append(box)
    return boxes


def _dot(p):
    from .labels import Box
    return Box(p[0] - 1.2, p[1] - 1.2, p[0] + 1.2, p[1] + 1.2)


def _lead(box, to):
    """A leader from 0.5 mm off a label's box to 0.5 mm short of ``to`` (None when beside
    it): :func:`labels.leader`."""
    from .labels import leader
    return leader(box, to, 0.5)


def _along_member(tail, tip, segments) -> tuple[float, float] | None:
    """The unit normal (paper) to step a force arrow off the member it would lie on — a force at
    a pin of a two-force member acts along the member — or None when the arrow is clear of it.
    The side is the one away from the point labels (set up and to the right of their points),
    the same for both ends."""
    for a, b in segments:
        d = np.subtract(b, a, dtype=float)
        length = float(np.hypot(*d))
        if length < 1e-9:
            continue
        e = d / length
        n = np.array([-e[1], e[0]])
        arrow = np.subtract(tip, tail, dtype=float)
        slant = abs(float(arrow @ n)) / max(float(np.hypot(*arrow)), 1e-9)   # |sin| to it
        off = abs(float(np.subtract(tail, a) @ n))
        along = [float(np.subtract(p, a) @ e) for p in (tail, tip)]
        if off < 0.6 and slant < 0.1 and min(along) > -1.0 and max(along) < length + 1.0:
            if n[0] + n[1] > 0:
                n = -n
            return float(n[0]), float(n[1])
    return None


def _pts(it):
    from .model import Arrow, Circle, Polyline, Segment, Text
    if isinstance(it, Segment):
        return [it.a, it.b]
    if isinstance(it, Polyline):
        return list(it.points)
    if isinstance(it, Circle):
        return [it.centre]
    if isinstance(it, Arrow):
        return [it.tail, it.tip]
    if isinstance(it, Text):
        return [(it.x, it.baseline)]
    return []


def write(an: Analysis, outdir) -> list[Path]:
    """Write every free-body diagram and force polygon as ``outdir/<name>.svg``."""
    from .svg import to_svg
    outdir = Path(outdir)
    if outdir.exists() and not outdir.is_dir():
        raise PolygonsError(f"{outdir} exists and is not a folder", where=str(outdir))
    outdir.mkdir(parents=True, exist_ok=True)
    paths = []
    for stem, d in drawings(an):
        p = outdir / f"{stem}.svg"
        p.write_bytes(to_svg(d))
        paths.append(p)
    return paths
