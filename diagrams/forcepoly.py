"""The drawing board's force methods drawn: the force polygon of each Assur group, stage by
stage, and Zhukovsky's lever (:mod:`polygons.forces.graphical`,
:mod:`polygons.forces.zhukovsky`).  Same page, scale bar, key and writer as the velocity and
acceleration polygons; every vector's kind has its look (:data:`diagrams.components.LOOKS`,
the ``force-…`` kinds).  Nothing is recomputed: every vector is a record of the construction.

Files (``polygons forces CASE --svg DIR``): ``group-<state>-<n>.svg`` (the finished polygon
of group n) and ``group-<state>-<n>-<k>.svg`` (its stages); ``joint-<state>-<n>-<corner>.svg``
(and stages) for the joints of a triad's plate that is a triangle of links;
``zhukovsky-<state>.svg`` and
``zhukovsky-<state>-<k>.svg``.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from polygons.errors import PolygonsError, UnsupportedError
from polygons.forces import effort as effort_mod
from polygons.forces import graphical, zhukovsky
from polygons.forces import words as force_words

from .components import LOOKS
from . import scale as scales
from .inset import MIN_VECTOR_MM
from .labels import bounds, first_clear, text_box

KIND_LOOK = {"load": "force-load", "force": "force-load", "weight": "force-load",
             "spring": "force-load", "torque": "force-load", "friction": "force-load",
             "couple": "force-load", "inertia": "force-inertia", "transmitted": "force-passed",
             "effort": "force-effort"}


from .fbd import _dir, _fmt, _slug  # noqa: E402,F401 (one of each, the free-body diagrams')


def _text(x, y, text, size, anchor):
    """A label anchored at its start (an end-anchored typeset label is moved left by its
    width: sub- and superscript runs keep their places in every renderer)."""
    from .model import Text
    from .notation import width
    if anchor == "end":
        x -= width(text, size)
    elif anchor == "middle":
        x -= width(text, size) / 2
    return Text(x, y, text, size, anchor="start", role="label")


def _beside(arrows, tail, tip, n) -> tuple[float, float]:
    """The move (mm) that draws the vector tail → tip beside the drawn ones it would lie on
    (collinear and overlapping): 2.2 mm along ``n``, further for each one already there."""
    u = np.subtract(tip, tail) / math.dist(tail, tip)
    ends = sorted(float(np.subtract(p, tail) @ u) for p in (tail, tip))
    k = 0
    for ar in arrows:
        d2 = np.subtract(ar.tip, ar.tail)
        w = np.subtract(ar.tail, tail)
        if abs(u[0] * d2[1] - u[1] * d2[0]) > 0.03 * max(1e-9, float(np.hypot(*d2))):
            continue                                  # not within ~2° of it
        far = max(abs(u[0] * w[1] - u[1] * w[0]),
                  abs(u[0] * (w[1] + d2[1]) - u[1] * (w[0] + d2[0])))
        if far > 1.0:
            continue                                  # more than 1 mm off its line
        s = sorted(float(np.subtract(p, tail) @ u) for p in (ar.tail, ar.tip))
        if min(ends[1], s[1]) - max(ends[0], s[0]) > 0.1 and ar.shift == (0.0, 0.0) or \
                min(ends[1], s[1]) - max(ends[0], s[0]) > 0.1 and k == 0:
            k += 1
    return (float(2.2 * k * n[0]), float(2.2 * k * n[1])) if k else (0.0, 0.0)


def _known_item(k, stage):
    return (k.name, k.force, KIND_LOOK.get(k.kind, "force-load"), stage,
            f"{k.name}: {_fmt(float(np.hypot(*k.force)))} N ∠{_dir(k.force):.1f}°"
            + (f" (h = {k.offset * 1e3:.3g} mm)" if k.kind == "inertia" else ""))


def _moments_item(t, stage):
    return (t.name, t.force, "force-moments", stage,
            f"{t.name}: {graphical.found_words(t)} (by moments)")


def _closing_item(f, stage):
    look = "force-effort" if f.how == "effort" else "force-closing"
    return (f.name, f.force, look, stage, f"{f.name}: {_fmt(abs(f.value))} N ∠"
            f"{_dir(f.force) if f.value else _dir(f.direction):.1f}°")


def _closing_stage(g) -> int:
    """The stage at which the polygon closes: 3 for a group of two bodies (dyads, triads)."""
    return 3 if g.kind in graphical.DYAD_KINDS or g.kind == "triad" else 2


def _triad_vectors(g: graphical.Group):
    """The class-III group's polygon, ordered so that each binary link's part (its known
    forces, its normal component, its along-link component) runs on: the corner's force on
    the plate is then the diagonal across it.  Stage 1: the first link's part, the plate's
    known forces, the third link's known forces and normal component; Stage 2: its component
    along the link by moments about the Assur point S, then the second link's part; Stage 3:
    the two closing sides (along the first and second links); Stage 4: the diagonals."""
    ts, along_k = g.normals[:3], g.normals[3]
    close_j, close_i = g.closing
    legs = {t.body for t in ts}

    def part(link, stage):
        items = [_known_item(k, stage) for k in g.knowns if k.body == link and k.force.any()]
        return items + [_moments_item(t, stage) for t in ts if t.body == link]
    seq = part(close_i.body, 1)
    end_i = len(seq)
    seq += [_known_item(k, 1) for k in g.knowns if k.body not in legs and k.force.any()]
    start_k = len(seq)
    seq += part(along_k.body, 1) + [_moments_item(along_k, 2)]
    end_k = len(seq)
    start_j = len(seq)
    seq += part(close_j.body, 2)
    seq += [_closing_item(close_j, 3), _closing_item(close_i, 3)]
    n = len(seq)
    lines = [(n - 2, close_j.direction, 3), (n, close_i.direction, 3)]
    name = {ts[q].body: g.reactions[q].name for q in range(3)}
    diag = [(n - 1, end_i, name[close_i.body]), (start_k, end_k, name[along_k.body]),
            (start_j, n - 1, name[close_j.body])]
    return seq, lines, diag


def _vectors(g: graphical.Group):
    """(name, force, look, stage, words) head to tail, and the construction lines
    (point, direction, stage) and diagonals (from-vertex index, to-vertex index, name)."""
    if g.kind == "triad":
        return _triad_vectors(g)
    seq = []
    lines = []
    diag = []
    first = g.bodies[0]
    for k in g.knowns:
        if k.force.any():
            stage = 1 if k.body == first or g.kind in ("crank", "slider driver", "joint") \
                else 2
            seq.append(_known_item(k, stage))
    # the normal components go after their link's knowns: K1, t1, K2, t2
    for t in g.normals:
        stage = 1 if t.body == first or g.kind == "joint" else 2
        idx = sum(1 for s in seq if s[3] <= stage)
        seq.insert(idx, _moments_item(t, stage))
    close = [f for f in g.closing if f.how != "effort" or g.kind == "slider driver"]
    cstage = _closing_stage(g)
    start_closing = len(seq)
    for f in close:
        seq.append(_closing_item(f, cstage))
    if len(close) == 2:
        lines.append((start_closing, close[0].direction, cstage))
        lines.append((len(seq), close[1].direction, cstage))
    if g.kind in graphical.DYAD_KINDS:
        s1 = sum(1 for s in seq if s[3] == 1)          # the vertex after the first link
        diag.append((start_closing + 1, s1, g.reactions[0].name))
    return seq, lines, diag


def group_drawings(an, st):
    """(stem, Drawing) of each group's force polygon and its stages at ``st``."""
    try:
        fp = graphical.construct(an, st)
    except UnsupportedError:
        return []
    return _drawings(fp.groups, fp, st, an.model)


def joint_drawings(an, st):
    """(stem, Drawing) of the polygon of each joint of a class-III group's plate that is a
    triangle of links (the forces on the pin), and its stages: ``joint-<state>-<n>-<corner>``."""
    try:
        fp = graphical.construct(an, st)
    except UnsupportedError:
        return []
    return _drawings(fp.joints, fp, st, an.model)


def _drawings(groups, fp, st, model):
    from .labels import bounds, box_hits_segment, text_box
    from .layout import FORCE_LEGEND_MM, arrow_head, compose
    from .model import Arrow, Circle, Group, Segment, Text
    from .scale import Scale, round_up

    out = []
    for g in groups:
        seq, lines, diag = _vectors(g)
        if not seq:
            continue
        big = max(float(np.hypot(*s[1])) for s in seq)
        if big == 0.0:
            continue
        small = min(float(np.hypot(*s[1])) for s in seq if float(np.hypot(*s[1])) > 0)
        fscale = Scale("force", scales.force_scale(big, small), "N", 1.0)
        k = fscale.mm_per_si
        # a force too short to draw at this scale: said in the legend, not drawn
        ghosts = {i for i, s in enumerate(seq)
                  if 0 < float(np.hypot(*s[1])) * k < MIN_VECTOR_MM}
        verts = [np.zeros(2)]
        for s in seq:
            verts.append(verts[-1] + s[1] * k)
        centre = sum(verts, np.zeros(2)) / len(verts)
        nst = max(s[3] for s in seq) + (1 if diag else 0)
        for stage in list(range(1, nst + 1)) + [None]:
            if stage is not None and not (diag and stage == nst) and not any(
                    s[3] == stage and float(np.hypot(*s[1])) > 0 and i not in ghosts
                    for i, s in enumerate(seq)):
                continue           # nothing to draw at this stage (massless, or too small)
            arrows, labels, extra = [], [], []
            placed = []
            lo = np.min(np.array(verts), axis=0) - 8.0
            hi = np.max(np.array(verts), axis=0) + 8.0
            for vi, d, lst in lines:
                if stage is not None and lst != stage:
                    continue
                p = verts[vi]
                reach = [t for i in range(2) if abs(d[i]) > 1e-12
                         for t in ((lo[i] - p[i]) / d[i], (hi[i] - p[i]) / d[i])]
                tmin = max(min(reach[j], reach[j + 1]) for j in range(0, len(reach), 2))
                tmax = min(max(reach[j], reach[j + 1]) for j in range(0, len(reach), 2))
                a, b = p + tmin * d, p + tmax * d
                extra.append(Segment(tuple(map(float, a)), tuple(map(float, b)),
                                     "construction", cls="closing-line"))
            for i, (name, f, look, sst, _) in enumerate(seq):
                if stage is not None and sst > stage:
                    continue
                tail, tip = tuple(map(float, verts[i])), tuple(map(float, verts[i + 1]))
                if math.dist(tail, tip) < 1e-6 or i in ghosts:
                    continue
                new = stage is not None and sst == stage
                head, shaft = arrow_head(tail, tip)
                u = (np.array(tip) - np.array(tail)) / math.dist(tail, tip)
                n = np.array([-u[1], u[0]])
                mid = (np.array(tail) + np.array(tip)) / 2
                if n @ (mid - centre) < 0:
                    n = -n
                shift = _beside(arrows, tail, tip, n)
                arrows.append(Arrow(tail, tip, f"c-{look}" + ("-new" if new else ""), head,
                                    shaft, name=name, role="known",
                                    faded=stage is not None and not new, shift=shift,
                                    title=f"{name} = {_fmt(float(np.hypot(*f)))} N"))
                mid = mid + np.array(shift)
                if shift != (0.0, 0.0):
                    n = np.array(shift) / float(np.hypot(*shift))
                elif any(_beside([Arrow(tuple(map(float, verts[j])),
                                        tuple(map(float, verts[j + 1])), "", (), (0, 0))],
                                 tail, tip, n) != (0.0, 0.0)
                         for j in range(len(seq)) if j != i
                         and float(np.hypot(*seq[j][1])) > 0):
                    n = -n                      # a collinear partner is drawn on that side
                segs = [(tuple(map(float, verts[j])), tuple(map(float, verts[j + 1])))
                        for j in range(len(seq)) if stage is None or seq[j][3] <= stage]
                segs += [(e.a, e.b) for e in extra]
                for off, side in ((2.5, 1), (5.0, 1), (2.5, -1), (8.0, 1), (5.0, -1),
                                  (11.0, 1), (8.0, -1), (14.0, 1), (11.0, -1), (17.0, 1),
                                  (14.0, -1), (20.0, 1)):
                    at = mid + side * off * n
                    anchor = "start" if side * n[0] >= 0 else "end"
                    bx = text_box(float(at[0]), float(at[1]) - 1.0, name, 2.8, anchor)
                    if not any(bx.overlaps(o) for o in placed) and not any(
                            box_hits_segment(bx, a, b, 0.3) for a, b in segs):
                        break
                else:
                    # crowded (short vectors close together): clear of the other names at
                    # least, further out if need be
                    for off, side in ((2.5, 1), (2.5, -1), (5.0, 1), (5.0, -1), (8.0, 1),
                                      (8.0, -1), (11.0, 1), (11.0, -1), (14.0, 1),
                                      (14.0, -1), (17.0, 1), (17.0, -1), (20.0, 1),
                                      (20.0, -1), (24.0, 1), (24.0, -1), (28.0, 1)):
                        at = mid + side * off * n
                        anchor = "start" if side * n[0] >= 0 else "end"
                        bx = text_box(float(at[0]), float(at[1]) - 1.0, name, 2.8, anchor)
                        if not any(bx.overlaps(o) for o in placed):
                            break
                    else:
                        at = mid + 2.5 * n
                        anchor = "start" if n[0] >= 0 else "end"
                        bx = text_box(float(at[0]), float(at[1]) - 1.0, name, 2.8, anchor)
                placed.append(bx)
                labels.append(_text(float(at[0]), float(at[1]) - 1.0, name, 2.8, anchor))
            if diag and (stage is None or stage == nst):
                for a_i, b_i, name in diag:
                    tail, tip = tuple(map(float, verts[a_i])), tuple(map(float, verts[b_i]))
                    if math.dist(tail, tip) > 1e-6:
                        head, shaft = arrow_head(tail, tip)
                        u = np.subtract(tip, tail) / math.dist(tail, tip)
                        n = np.array([-u[1], u[0]])
                        if n @ (np.add(tail, tip) / 2 - centre) < 0:
                            n = -n
                        # on a drawn side (a two-force link): drawn beside it, moved 2.2 mm
                        shift = _beside(arrows, tail, tip, -n)
                        arrows.append(Arrow(tail, tip, "c-force-reaction"
                                            + ("-new" if stage else ""), head, shaft,
                                            name=name, role="result", title=name,
                                            shift=shift))
                        mid = (np.array(tail) + np.array(tip)) / 2 + np.array(shift)
                        m2 = -1.0 if shift != (0.0, 0.0) else 1.0
                        # clear of the other names and of every drawn vector (WE8's 'R_P on
                        # slider P' was set across the gas force), else of the names at least
                        drawn = [(tuple(np.add(ar.tail, ar.shift)),
                                  tuple(np.add(ar.tip, ar.shift))) for ar in arrows]
                        drawn += [(e.a, e.b) for e in extra]
                        def box_of(q, mid=mid, n=n, m2=m2, name=name):
                            at = mid + q[1] * m2 * q[0] * n
                            return text_box(float(at[0]), float(at[1]) - 1.0, name, 2.8,
                                            "start" if q[1] * m2 * n[0] >= 0 else "end")
                        (off, sd), bx = first_clear(
                            ((3.0, 1), (6.0, 1), (9.0, 1), (12.0, 1), (3.0, -1), (6.0, -1),
                             (9.0, -1), (15.0, 1), (12.0, -1), (18.0, 1), (15.0, -1),
                             (21.0, 1)), box_of, placed, drawn)
                        at = mid + sd * m2 * off * n
                        anchor = "start" if sd * m2 * n[0] >= 0 else "end"
                        placed.append(bx)
                        labels.append(_text(float(at[0]), float(at[1]) - 1.0, name, 2.8,
                                            anchor))
            start = Circle((0.0, 0.0), 0.8, "pole", cls="start")
            pts = [tuple(map(float, v)) for v in verts]
            box = bounds(pts)
            for t in labels:
                box = box.union(text_box(t.x, t.baseline, t.text, t.size, t.anchor))
            # the forces too short for the polygon's scale, drawn again head to tail in a
            # detail below it at a round magnification (each ≥ 3 mm there), its vertex ringed
            drawn_in_detail = {}
            reach = bounds([p for e in extra for p in (e.a, e.b)] + pts)
            for item in _details(seq, ghosts, stage, verts, k, box.union(reach), placed,
                                 fscale):
                if isinstance(item, tuple):              # (index, magnification)
                    drawn_in_detail[item[0]] = item[1]
                elif isinstance(item, Arrow):
                    arrows.append(item)
                elif isinstance(item, Text):
                    labels.append(item)
                    box = box.union(text_box(item.x, item.baseline, item.text, item.size,
                                             item.anchor))
                else:
                    extra.append(item)
            for ar in arrows:
                box = box.union(bounds([ar.tail, ar.tip]))
            box = box.grown(6.0)
            looks = list(dict.fromkeys([s[2] for s in seq if (stage is None or s[3] <= stage)
                                        and float(np.hypot(*s[1])) > 0]
                                       + (["force-reaction"] if diag and (stage is None or
                                                                          stage == nst)
                                          else [])))
            key = [(f"c-{lk}", LOOKS[lk].name, True) for lk in looks]
            if lines and (stage is None or stage == _closing_stage(g)):
                key.append(("construction", "line of known direction", False))
            legend = [(s[4], "normal") for i, s in enumerate(seq)
                      if (stage is None or s[3] <= stage) and i not in ghosts]
            legend += [(f"{seq[i][4]} (detail ×{_fmt(drawn_in_detail[i])})", "normal")
                       for i in sorted(ghosts) if (stage is None or seq[i][3] <= stage)
                       and i in drawn_in_detail]
            legend += [(f"{seq[i][0]} ≈ 0 ({float(np.hypot(*seq[i][1])) * k:.2f} mm at this "
                        f"scale: {_fmt(float(np.hypot(*seq[i][1])))} N, not drawn)", "normal")
                       for i in sorted(ghosts) if (stage is None or seq[i][3] <= stage)
                       and i not in drawn_in_detail]
            legend += [(m, "normal") for m in g.moments]
            if g.kind == "crank":
                legend.append((f"input torque T = "
                               f"{force_words.effort_words(model, fp.effort, st.sol, 5)}",
                               "bold"))
            if g.kind == "slider driver":
                legend.append((f"input force "
                               f"{force_words.effort_words(model, fp.effort, st.sol, 5)}",
                               "bold"))
            for f in g.reactions:
                if f.how == "reaction" and (stage is None or stage == nst):
                    legend.append((f"{f.name}: {_fmt(f.value)} N ∠{_dir(f.direction):.1f}°",
                                   "bold"))
            if stage is None and any(f.how == "joint" for f in g.reactions):
                legend.append(("the plate's links, joint by joint (joint-… drawings):",
                               "normal"))
                legend += [(f"{f.name}: {_fmt(f.value)} N ∠{_dir(f.direction):.1f}°", "normal")
                           for f in g.reactions if f.how == "joint"]
            if g.kind == "joint":
                corner = g.normals[0].at
                stem = f"joint-{_slug(st.name)}-{g.index}-{_slug(corner)}"
                title = f"Force polygon, joint {corner} (group {g.index})"
            else:
                stem = f"group-{_slug(st.name)}-{g.index}"
                title = f"Force polygon, group {g.index}"
            stem += f"-{stage}" if stage else ""
            cap = _stage_caption(g, stage, nst)
            out.append((stem, compose(
                name=stem, kind="force", stage=stage,
                title=title + (f" — Stage {stage}" if stage else ""),
                subtitle=f"{g.title.split(': ', 1)[1]}; {st.name}",
                desc=f"Force polygon of {g.title}",
                content=[Group("polygon", "force-polygon", g.title,
                               tuple([start] + extra + arrows)),
                         Group("labels", "labels", "names", tuple(labels))],
                content_box=box, legend=legend, scale=fscale, caption=[cap],
                legend_width=FORCE_LEGEND_MM,
                scale_statement=fscale.statement, meta={}, key=key)))
    return out


#: a detail's magnifications (round, as a draughtsman picks them)
DETAIL_FACTORS = (2, 2.5, 4, 5, 10, 20, 25, 50, 100)
#: the gap (mm) between the polygon and its details, and between two details
DETAIL_GAP = 8.0


def _ghost_runs(ghosts, seq, stage) -> list[list[int]]:
    """The forces too short to draw (``ghosts``) shown at ``stage``, in runs of consecutive
    ones (head to tail in the polygon: one detail each)."""
    shown = sorted(i for i in ghosts if stage is None or seq[i][3] <= stage)
    runs: list[list[int]] = []
    for i in shown:
        if runs and runs[-1][-1] == i - 1:
            runs[-1].append(i)
        else:
            runs.append([i])
    return runs


def _details(seq, ghosts, stage, verts, k, box, placed, fscale):
    """The details of a force polygon: each run of forces too short for its scale drawn
    again, head to tail, magnified ×m (the least of :data:`DETAIL_FACTORS` that draws each
    :data:`MIN_VECTOR_MM` long, else the largest: those still shorter stay said in the
    legend), in a row below the polygon; the run's vertex on the polygon ringed (and
    numbered when there are two or more); the caption states the factor and the detail's
    scale.  Yields (index, m) for each force drawn, then Arrow, Text and Circle items."""
    from .model import Circle
    runs = _ghost_runs(ghosts, seq, stage)
    x = box.x0
    top = box.y0 - DETAIL_GAP
    for r_i, run in enumerate(runs):
        lens = [float(np.hypot(*seq[i][1])) * k for i in run]
        need = MIN_VECTOR_MM / min(lens)
        m = next((f for f in DETAIL_FACTORS if f >= need), DETAIL_FACTORS[-1])
        run = [i for i, ln in zip(run, lens) if ln * m >= MIN_VECTOR_MM - 1e-9]
        if not run:
            continue
        tag = f"({r_i + 1})" if len(runs) > 1 else ""
        # set once to measure it, then where its left edge is x (a name set to the left of
        # its arrow included)
        _, first = _one_detail(seq, run, m, k, (x, top), tag, stage, list(placed))
        items, dbox = _one_detail(seq, run, m, k, (2 * x - first.x0, top), tag, stage,
                                  placed)
        ring_at = tuple(map(float, verts[run[0]]))
        yield Circle(ring_at, 2.5, "inset", cls="inset-ring force-detail-ring")
        if tag:                            # the ring's number, clear of the other names
            for dx, dy, anchor in ((3.0, 2.0, "start"), (3.0, -4.5, "start"),
                                   (-3.0, 2.0, "end"), (-3.0, -4.5, "end"),
                                   (0.0, 4.0, "middle"), (0.0, -6.5, "middle"),
                                   (6.0, 5.0, "start"), (-6.0, 5.0, "end"),
                                   (6.0, -8.0, "start"), (-6.0, -8.0, "end")):
                bx = text_box(ring_at[0] + dx, ring_at[1] + dy, tag, 2.8, anchor)
                if not any(bx.overlaps(o) for o in placed):
                    break
            placed.append(bx)
            yield _text(ring_at[0] + dx, ring_at[1] + dy, tag, 2.8, anchor)
        for i in run:
            yield (i, m)
        yield from items
        x = dbox.x1 + DETAIL_GAP


def _one_detail(seq, run, m, k, at, tag, stage, placed):
    """One detail's items (arrows, names, caption) with its left end near ``at[0]`` and its
    top at ``at[1]``, and its box; the boxes of its texts are added to ``placed``."""
    from .layout import arrow_head
    from .model import Arrow, Text
    chain = [np.zeros(2)]
    for i in run:
        chain.append(chain[-1] + seq[i][1] * k * m)
    lo = np.min(np.array(chain), axis=0)
    hi = np.max(np.array(chain), axis=0)
    off = np.array([at[0] - lo[0] + 2.0, at[1] - hi[1] - 4.0])
    pts = [tuple(map(float, q + off)) for q in chain]
    segs = list(zip(pts, pts[1:]))
    centre = np.mean(np.array(pts), axis=0)
    items = []
    dbox = bounds(pts)
    for j, i in enumerate(run):
        name, f, look, sst, _ = seq[i]
        new = stage is not None and sst == stage
        tail, tip = pts[j], pts[j + 1]
        head, shaft = arrow_head(tail, tip)
        items.append(Arrow(tail, tip, f"c-{look}" + ("-new" if new else ""), head, shaft,
                           name=name, role="known", faded=stage is not None and not new,
                           title=f"{name} = {_fmt(float(np.hypot(*f)))} N "
                                 f"(detail ×{_fmt(m)})"))
        u = np.subtract(tip, tail) / math.dist(tail, tip)
        n = np.array([-u[1], u[0]])
        mid = (np.array(tail) + np.array(tip)) / 2
        if n @ (mid - centre) < 0:
            n = -n
        def box_of(q, mid=mid, n=n, name=name):
            p = mid + q[1] * q[0] * n
            return text_box(float(p[0]), float(p[1]) - 1.0, name, 2.8,
                            "start" if q[1] * n[0] >= 0 else "end")
        (off_mm, side), bx = first_clear(
            ((2.5, 1), (5.0, 1), (2.5, -1), (8.0, 1), (5.0, -1), (11.0, 1), (8.0, -1),
             (14.0, 1), (11.0, -1)), box_of, placed, segs)
        p = mid + side * off_mm * n
        anchor = "start" if side * n[0] >= 0 else "end"
        placed.append(bx)
        dbox = dbox.union(bx)
        items.append(_text(float(p[0]), float(p[1]) - 1.0, name, 2.8, anchor))
    cap = (f"detail{' ' + tag if tag else ''} ×{_fmt(m)}: 1 cm = {_fmt(10.0 / (k * m))} N "
           f"(the ringed vertex)")
    cy = dbox.y0 - 4.0
    bx = text_box(dbox.x0, cy, cap, 2.6, "start")
    placed.append(bx)
    items.append(Text(dbox.x0, cy, cap, 2.6, anchor="start", role="inset",
                      cls="inset-caption"))
    return items, dbox.union(bx)


def _stage_caption(g, stage, nst) -> str:
    if g.kind in ("RRR", "RRP"):
        a = g.bodies[0]
        b = g.bodies[1] if g.kind == "RRR" else f"slider {g.bodies[1]}"
        words = {1: f"The known forces on {a}, then the normal component at its outer pin "
                    f"from moments about the middle pin.",
                 2: f"The known forces on {b}" + (", then its normal component by moments."
                                                  if g.kind == "RRR" else "."),
                 3: "Lines of known direction (along the links, or the guide normal) through "
                    "the last point and the start: where they meet closes the polygon.",
                 4: "The pin force between the two bodies is the diagonal."}
    elif g.kind == "RRP, moving guide":
        words = {1: f"The known forces on {g.bodies[0]}, then the normal component at its "
                    f"outer pin from moments about the pin in the slot.",
                 3: "Lines of known direction (along the link, and normal to the slot) through "
                    "the last point and the start: where they meet closes the polygon.",
                 4: "The light block passes the slot's force to the pin: the diagonal."}
    elif g.kind == "RPR":
        words = {1: f"The known forces on the slotted lever {g.bodies[0]}, then the slot's "
                    f"force (normal to the slot, through the block) from moments about the "
                    f"lever's pivot.",
                 2: "The polygon closes on the pivot's force; the light block passes the "
                    "slot's force back to the pin."}
    elif g.kind == "RPP":
        words = {1: f"The known forces on the yoke {g.bodies[0]}.",
                 2: "Lines of known direction (normal to the slot, normal to the guide) "
                    "through the last point and the start: where they meet closes the "
                    "polygon; the guide couple from moments."}
    elif g.kind == "triad":
        words = {1: "Each binary link's known forces and its normal component, by moments "
                    "about its corner on the plate; the plate's known forces.",
                 2: "The third link's component along itself by moments of the whole group "
                    "about the Assur point S (where the other two links' lines meet), then "
                    "the second link's part.",
                 3: "Lines along the other two links through the last point and the start: "
                    "where they meet closes the polygon.",
                 4: "Each corner's force on the plate is a diagonal: across its link's part."}
    elif g.kind == "joint":
        words = {1: "The forces on the pin known: the binary link's (found with the group), "
                    "each plate link's normal component (by moments about its other end) "
                    "and, for a plate link already met at another joint, its component along "
                    "itself (from its balance along itself).",
                 2: "Lines along the plate links not yet met, through the last point and the "
                    "start: where they meet closes the joint's polygon (the last joint only "
                    "checks that it closes)."}
    else:
        words = {1: "The known forces on the driver, including those passed on.",
                 2: "The polygon closes on the bearing (guide) force; the input effort "
                    "follows from moments."}
    if stage is None:
        return ("" if g.kind == "joint" else
                "Groups from the one furthest from the driver; each inertia force acts "
                "offset by h = I_G α / (m a_G). ") + " ".join(words[i] for i in sorted(words))
    return words.get(stage, "")


def lever_drawings(an, st):
    """(stem, Drawing) of Zhukovsky's lever at ``st`` and its stages."""
    from .labels import bounds, text_box
    from .layout import FORCE_LEGEND_MM, arrow_head, compose
    from .model import Arrow, Circle, Group, Segment
    from .scale import Scale, round_up

    try:
        lv = zhukovsky.construct(an, st)
    except UnsupportedError:
        return []
    model = an.model
    imgs = lv.images
    ext = max([float(np.hypot(*p)) for p in imgs.values()] + [1e-9])
    vscale = Scale("velocity", round_up(ext * 10.0 / 70.0), "m/s", 1.0)
    kv = vscale.mm_per_si
    allf = lv.applied + lv.effort_forces
    fbig = max([float(np.hypot(*a.force)) for a in allf] + [1e-9])
    # an effort nil next to the loads (torque-driven: the applied torques balance) is not drawn
    nil = all(float(np.hypot(*a.force)) <= 1e-9 * fbig for a in lv.effort_forces)
    out = []
    for stage in (1, 2, 3, None):
        items, arrows, labels, placed = [], [], [], []

        lines = []                         # the lever's sides and rays: no name on them

        def label(x, y, text, size=2.8, anchor="start"):
            """A name near (x, y) clear of the other names, the force arrows and the
            lever's sides and rays; else clear of the names at least."""
            segs = [(tuple(np.add(ar.tail, ar.shift)), tuple(np.add(ar.tip, ar.shift)))
                    for ar in arrows] + lines
            moves = [(0.0, (j + 1) // 2 * 3.2 * (1 if j % 2 else -1)) for j in range(9)]
            moves += [(dx, dy) for dx in (-6.0, 6.0, -12.0, 12.0)
                      for dy in (0.0, -3.2, 3.2, -6.4, 6.4)]
            moves += [(0.0, (j + 1) // 2 * 3.2 * (1 if j % 2 else -1)) for j in range(9, 30)]
            (dx, dy), bx = first_clear(
                moves, lambda q: text_box(x + q[0], y + q[1], text, size, anchor), placed, segs)
            placed.append(bx)
            labels.append(_text(x + dx, y + dy, text, size, anchor))

        faded1 = stage is not None and stage > 1
        for name, body in model.bodies.items():
            if body.b is None:
                continue
            a, b = imgs.get(body.a), imgs.get(body.b)
            if a is None or b is None:
                continue
            items.append(Segment(tuple(map(float, a * kv)), tuple(map(float, b * kv)),
                                 "c-force-lever" + ("" if faded1 else "-new"), faded=faded1,
                                 cls="lever"))
            lines.append((tuple(map(float, a * kv)), tuple(map(float, b * kv))))
        show = [] if stage == 1 else (lv.applied if stage == 2 else allf)
        show = [a for a in show if a.kind != "effort" or not nil]
        drawn = [a for a in show if float(np.hypot(*a.lever)) * kv > 0.05
                 and float(np.hypot(*a.force)) > 0.0]
        tips = []
        for a in drawn:                      # arrows first, then the names clear of them
            mag = float(np.hypot(*a.force))
            tail = tuple(map(float, a.lever * kv))
            ln = _arrow_length(mag, fbig)
            tip = (tail[0] + a.force[0] / mag * ln, tail[1] + a.force[1] / mag * ln)
            look = KIND_LOOK.get(a.kind, "force-load")
            new = stage is not None and (stage == 2 and a.kind != "effort"
                                         or stage == 3 and a.kind == "effort")
            head, shaft = arrow_head(tail, tip)
            # two forces along one line at one image (the toggle press's Stone and −m a_G
            # at d): the later drawn beside, moved 2.2 mm square to it
            u = np.subtract(tip, tail) / math.dist(tail, tip)
            shift = _beside(arrows, tail, tip, np.array([-u[1], u[0]]))
            arrows.append(Arrow(tail, tip, f"c-{look}" + ("-new" if new else ""), head, shaft,
                                name=a.name, role="known", title=f"{a.name} {_fmt(mag)} N",
                                faded=stage is not None and not new, shift=shift))
            tips.append((a.name, tuple(np.add(tail, shift)), tuple(np.add(tip, shift))))
        images = []
        for lab, p in imgs.items():
            q = tuple(map(float, p * kv))
            if lab in model.scene.ground:
                continue
            items.append(Segment((0.0, 0.0), q, "c-force-lever", faded=True, cls="ray"))
            lines.append(((0.0, 0.0), q))
            items.append(Circle(q, 0.5, "vertex", cls="image"))
            images.append((lab, q))
        items.append(Circle((0.0, 0.0), 0.9, "pole", cls="pole"))
        label(1.2, -3.5, "o (pivot)", 3.0)
        for lab, q in images:
            label(q[0] + 1.2, q[1] + 1.2, lab.lower(), 3.0)
        for name, tail, tip in tips:
            u = np.subtract(tip, tail) / math.dist(tail, tip)
            label(tip[0] + 1.5 * u[0], tip[1] + 1.5 * u[1] - 1.0, name, 2.6,
                  "start" if u[0] >= -0.2 else "end")
        pts = [(0.0, 0.0)] + [tuple(map(float, p * kv)) for p in imgs.values()]
        pts += [tuple(np.add(q, ar.shift)) for ar in arrows for q in (ar.tail, ar.tip)]
        box = bounds(pts)
        for o in placed:
            box = box.union(o)
        box = box.grown(6.0)
        unit = effort_mod.unit(model)
        legend = [(f"{a.name}: {_fmt(float(np.hypot(*a.force)))} N, moment about o "
                   + (force_words.lever_moment_words(a.moment, 4) if a in drawn
                      else "0 (applied at o)"), "normal") for a in (show or [])]
        if stage in (3, None):
            legend.append((f"effort {effort_mod.short(model)} = "
                           + (f"0 {unit} (the loads balance)" if nil else
                              force_words.effort_words(model, lv.effort, st.sol, 6)), "bold"))
        looks = ["force-lever"] + list(dict.fromkeys(KIND_LOOK.get(a.kind, "force-load")
                                                     for a in show))
        key = [(f"c-{lk}", LOOKS[lk].name, lk != "force-lever") for lk in looks]
        words = {1: "The velocity polygon turned 90° CCW about its pole o: a rigid lever "
                    "pivoted at o; each point's image carries the forces at that point.",
                 2: "Each force (inertia forces offset by h) applied at its image, parallel "
                    "to itself; couples as force pairs at the images of the link's ends.",
                 3: "The effort's moment about o balances the rest: Σ moments = 0."}
        cap = words[stage] if stage else " ".join(words.values()) + (
            " Drawn for a unit input rate (the input is at rest)." if lv.unit_rate else "")
        stem = f"zhukovsky-{_slug(st.name)}" + (f"-{stage}" if stage else "")
        out.append((stem, compose(
            name=stem, kind="zhukovsky", stage=stage,
            title="Zhukovsky's lever" + (f" — Stage {stage}" if stage else ""),
            subtitle=f"{model.scene.title} ({st.name})",
            desc="Zhukovsky's lever: the velocity polygon turned 90°",
            content=[Group("lever", "lever", "the turned velocity polygon", tuple(items)),
                     Group("forces", "forces", "forces at their images", tuple(arrows)),
                     Group("labels", "labels", "names", tuple(labels))],
            content_box=box, legend=legend, scale=vscale, legend_width=FORCE_LEGEND_MM,
            caption=[cap + f" Lever to the velocity scale; force arrows "
                     f"not to scale: 6 mm + 12 mm × √(F/F_max), F_max = {fbig:.4g} N (the "
                     f"moments come from their points and directions; values in the legend)."],
            scale_statement=vscale.statement, meta={}, key=key)))
    return out


def _arrow_length(mag: float, big: float) -> float:
    """A force arrow's length on the lever (mm): every force visible, longer for larger ones
    (the lever's moments come from points and directions, not from arrow lengths)."""
    return 6.0 + 12.0 * math.sqrt(mag / big)


def write(an, outdir) -> list[Path]:
    """Write every group's force polygon (and stages) and Zhukovsky's lever to ``outdir``."""
    from .svg import to_svg
    outdir = Path(outdir)
    if outdir.exists() and not outdir.is_dir():
        raise PolygonsError(f"{outdir} exists and is not a folder", where=str(outdir))
    outdir.mkdir(parents=True, exist_ok=True)
    paths = []
    for st in an.states:
        for stem, d in group_drawings(an, st) + joint_drawings(an, st) + lever_drawings(an, st):
            p = outdir / f"{stem}.svg"
            p.write_bytes(to_svg(d))
            paths.append(p)
    return paths
