"""The data of the interactive page (:mod:`diagrams.page`): frames, polygon strokes, drawing mode.

Everything the page's script draws is computed here, in SI, and sent as one JSON blob:

* the **frames**: the crank (or slider) positions of the cycle, the first one *exactly* the
  scene's own input (so the slider starts where the static drawings are), ordered in the crank's
  sense of rotation; the points' positions and velocities come from :func:`polygons.sweep.sweep`
  at those inputs;
* the **polygon strokes** of each diagram: which arrows the finished static drawing draws
  (:func:`diagrams.polygon.construction`: the same component kinds, so the live acceleration
  polygon shows its centripetal, tangential, sliding and Coriolis parts) and every polygon
  vertex at every frame, read from the compiled construction (:mod:`polygons.compiled`) run at
  that frame's input — the same program, on the same closures, as the static drawings;
* one **box per polygon over the whole cycle**, so the live polygons keep one scale;
* the **drawing mode** of each diagram: the vertices to place in construction order, the
  construction's vectors, the static drawing's stated scale and a paper size, and the
  grading rules of ``polygons check --drawing`` (:func:`polygons.grade_drawing.rules`: the
  vectors to draw with their tolerances and slips) that the page's ``grade.js`` applies;
* the **inset rule**'s constants (:func:`inset_rule`, from :mod:`diagrams.inset`), which the
  page's ``inset.js`` applies to the live polygons at every frame.

Nothing here computes kinematics of its own.
"""
from __future__ import annotations

import math
import re

import numpy as np

from .components import LOOKS, ORDER

#: positions in the slider (frames of the cycle)
FRAMES = 180
#: a frame larger than this × the cycle's median size does not set the live panels' scale
OFF_SCALE = 6.0
#: margin (mm) of the drawing mode's paper around the static polygon's extent
PAPER_MARGIN = 15.0
#: smallest drawing-mode paper (mm)
PAPER_MIN = (120.0, 90.0)

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _r(x: float):
    """Six significant figures: a deterministic, compact JSON number (None if not finite)."""
    x = float(x)
    if not math.isfinite(x):
        return None
    return float(f"{x:.6g}") + 0.0        # + 0.0: no '-0.0' in the data


def point_name(label: str) -> str:
    """A space label typeset as the drawings do: O2 → O₂, P4 → P₄ (digits after a letter)."""
    return re.sub(r"(?<=[A-Za-z])(\d+)", lambda m: m.group(1).translate(_SUB), label)


def vertex_name(vertex: str) -> str:
    """A polygon vertex typeset: p2_1 → p₂′ (:func:`diagrams.notation.plain`)."""
    from .notation import plain
    return plain(vertex)


# ---------------------------------------------------------------- the mechanism's lines
def edges(scene) -> list[tuple[str, str, str]]:
    """(end, end, link name) of every line the mechanism panel draws.

    A slotted lever is its pivot to its *own* point under the pin (P4 under P2, not the pin P2
    of the other link) and on to its far end when it has one."""
    from polygons.evaluate import link_ends
    model = scene.model                    # the slot runs on to the lever's point under the pin
    out = [(ln.a, ln.b, ln.name) for ln in model.links()]
    for slot in model.slots() + model.crossings():
        out.append((slot.line.origin, slot.coincident, slot.carrier))
        if slot.far:
            out.append((slot.coincident, slot.far, slot.carrier))
    for lab, bp in model.points.items():
        try:
            a, b = link_ends(scene, bp.link)
        except KeyError:
            continue
        out.append((a, lab, bp.link))
        out.append((b, lab, bp.link))
    seen, uniq = set(), []
    for a, b, n in out:
        if (a, b) not in seen and (b, a) not in seen and a != b:
            seen.add((a, b))
            uniq.append((a, b, n))
    return uniq


# ---------------------------------------------------------------- the frames
def inputs(scene, n: int) -> tuple[np.ndarray, int, bool]:
    """The frames' inputs (θ in rad or s in m) in the crank's sense of rotation, the index of
    the scene's own input among them, and whether they go round a full cycle.

    A crank that turns fully: n equal steps starting *at* the scene's angle; otherwise n
    points strictly inside the reachable range with the scene's own input put among them."""
    from polygons.position import driver_input
    from polygons.scene import Crank
    from polygons.sweep import compile_plan, find_range
    own = float(driver_input(scene))
    drv = scene.driver
    crank = isinstance(drv, Crank)
    backwards = crank and drv.omega < 0
    full, (lo, hi), _, _ = find_range(compile_plan(scene))
    if crank and full:
        sign = -1.0 if backwards else 1.0
        return own + sign * 2.0 * math.pi * np.arange(n) / n, 0, True
    xs = lo + (hi - lo) * (np.arange(n) + 0.5) / n
    xs = np.sort(np.append(xs[np.abs(xs - own) > 1e-12 * max(1.0, abs(own))], own))
    if backwards:
        xs = xs[::-1]
    return xs, int(np.flatnonzero(xs == own)[0]), False


def _vertices_of(sol, diagrams) -> dict | None:
    """Every polygon vertex of each diagram of a compiled solution (the construction at one
    frame's input), or None where the construction failed (a toggle, no closure)."""
    if sol is None:
        return None
    steps = sol.steps
    out = {d: {} for d in diagrams}
    for s in steps:
        if s.diagram in out and s.end is not None and s.point is not None:
            out[s.diagram][s.end] = s.point
    return out


def _tag(sol, step, line=None) -> str | None:
    """The link a polygon arrow belongs to (hovering that link highlights it): the step's
    link, else the link whose ends are the step's (X, Y) pair."""
    from polygons.evaluate import link_ends
    for s in (line, step):
        if s is None:
            continue
        if s.link:
            return s.link
        if s.relative:
            for name in [b.name for b in sol.scene.model.bodies if b.kind in ("link", "lever")]:
                try:
                    if set(link_ends(sol.scene, name)) == set(s.relative):
                        return name
                except KeyError:
                    continue
    return None


def strokes(sol, con) -> list[dict]:
    """The arrows (and image sides) of a finished static polygon: ends by vertex name, the
    component kind, the role and the link each belongs to."""
    steps = {s.number: s for s in sol.steps if s.diagram == con.diagram}
    out, seen = [], set()
    for st in con.strokes:
        if st.kind not in ("arrow", "side") or not st.frm or not st.to:
            continue
        key = (st.kind, st.frm, st.to)
        if key in seen:
            continue
        seen.add(key)
        step = steps.get(st.step)
        line = None
        if st.role == "resolved" and step is not None:
            line = next((steps[n] for n in step.lines
                         if steps[n].start in (st.frm, st.to)), None)
        out.append({"f": st.frm, "t": st.to, "c": st.component, "k": st.kind,
                    "role": st.role,
                    "link": None if st.role == "result" else _tag(sol, step, line)})
    return out


def on_scale(frames_pts, factor: float) -> list[bool]:
    """Which frames set the scale: those whose largest distance from the origin is at most
    ``factor`` × the median of it over the cycle.  Near a toggle a polygon (or a point at the
    meeting of two almost parallel slots) runs off to infinity; one such frame would shrink
    every other frame to a dot.  Frames that cannot be solved do not count either."""
    size = []
    for pts in frames_pts:
        good = [math.hypot(*p) for p in pts if p is not None and None not in p]
        size.append(max(good) if good else None)
    known = sorted(x for x in size if x is not None)
    if not known:
        return [True] * len(size)
    med = known[len(known) // 2]
    return [x is not None and (med <= 0 or x <= factor * med) for x in size]


def _mech_off(sw, labels, n: int) -> list[int]:
    """The frames left out of the mechanism panel's scale (see :func:`on_scale`): distances
    from the points' centroid over the cycle."""
    P = {lab: sw.position(lab) for lab in labels}
    if not P:
        return []
    allp = np.concatenate(list(P.values()))
    c = np.nanmean(allp, axis=0) if np.isfinite(allp).any() else np.zeros(2)
    frames_pts = [[None if not np.isfinite(P[lab][i]).all() else
                   (float(P[lab][i][0] - c[0]), float(P[lab][i][1] - c[1])) for lab in labels]
                  for i in range(n)]
    on = on_scale(frames_pts, OFF_SCALE)
    return [i for i in range(n) if not on[i]]


def _nice(x: float) -> float:
    """A round bar length (1, 2, 2.5, 5 × 10ⁿ) not above ``x``."""
    if not (x > 0 and math.isfinite(x)):
        return 1.0
    k = math.floor(math.log10(x))
    for m in (5.0, 2.5, 2.0, 1.0):
        v = m * 10.0 ** k
        if v <= x * (1 + 1e-12):
            return float(f"{v:.6g}")
    return float(f"{10.0 ** k:.6g}")


def key(kinds) -> list[dict]:
    """The key of the component kinds drawn, in the static drawings' order and looks."""
    return [{"kind": k, "name": LOOKS[k].name, "colour": LOOKS[k].colour,
             "width": LOOKS[k].width, "dash": LOOKS[k].dash, "open": LOOKS[k].open_head}
            for k in ORDER if k in kinds]


def frames(sol, figs=(), n: int = FRAMES) -> dict:
    """The page's data (SI, rounded to six significant figures), see the module docstring."""
    from polygons.compiled import compile_scene
    from polygons.scene import Crank
    from polygons.sweep import sweep
    from .polygon import construction
    if not isinstance(n, int) or not 2 <= n <= 3600:
        raise ValueError(f"the page takes 2 to 3600 frames, got {n!r}")
    scene = sol.scene
    xs, start, full = inputs(scene, n)
    sw = sweep(scene, inputs=xs)
    N = len(xs)
    drv = scene.driver
    crank = isinstance(drv, Crank)

    def arr(d, lab):
        a = np.asarray(d[lab] if d[lab] is not None else (0.0, 0.0), dtype=float)
        if a.shape == (2,):                    # a fixed point: one position for every frame
            a = np.broadcast_to(a, (N, 2))
        elif a.shape == (2, N):                # (xs, ys)
            a = a.T
        return [[_r(a[i, 0]), _r(a[i, 1])] for i in range(N)]

    labels = [lab for lab in scene.labels if lab in sw.pos]
    diagrams = [d for d in scene.solve if d in sol.vertices]
    prog = compile_scene(scene)
    per_frame = [_vertices_of(sol_k, diagrams) for sol_k in prog.solve_along(xs, start)]
    layouts = {f.kind: f.meta.get("layout") for f in figs
               if f.stage is None and f.kind in diagrams and f.meta.get("layout") is not None}
    polys, drawing = {}, {}
    from polygons.grade_drawing import emulated_tolerances, rules, stated_tolerance
    emulated, stated = emulated_tolerances(sol), stated_tolerance(sol)
    for d in diagrams:
        con = layouts[d].con if d in layouts else construction(sol, d)
        names = [con.pole] + sorted((v for v in con.born if v != con.pole),
                                    key=lambda v: (con.born[v], v))
        names += sorted(v for v in con.vertices if v not in names)
        own = dict(sol.vertices[d])
        ok = [st for st in strokes(sol, con) if st["f"] in own and st["t"] in own]
        vx = {v: [] for v in names}
        for fr in per_frame:
            for v in names:
                p = None if fr is None else (fr[d].get(v) if v != con.pole else (0.0, 0.0))
                vx[v].append(None if p is None else [_r(p[0]), _r(p[1])])
        on = on_scale([[vx[v][i] for v in names] for i in range(N)], OFF_SCALE)
        pts = np.array([vx[v][i] for v in names for i in range(N) if on[i]
                        and vx[v][i] is not None and None not in vx[v][i]] or [[0.0, 0.0]],
                       dtype=float)
        box = [float(pts[:, 0].min()), float(pts[:, 1].min()),
               float(pts[:, 0].max()), float(pts[:, 1].max())]
        span = max(box[2] - box[0], box[3] - box[1])
        polys[d] = {"vx": vx, "strokes": ok, "box": [_r(b) for b in box],
                    "off": [i for i in range(N) if not on[i]],
                    "bar": _nice(span / 4.0) if span > 1e-12 else None,
                    "unit": "m/s" if d == "velocity" else "m/s²",
                    "pole": con.pole, "pole_label": vertex_name(con.pole_label),
                    "names": {v: vertex_name(v) for v in names},
                    "key": key({st["c"] for st in ok})}
        drawing[d] = drawing_mode(sol, con, layouts.get(d), names)
        # the grading rules of `polygons check --drawing`, for the page's grade.js
        drawing[d]["rules"] = rules(sol, d, emulated, stated)
    if crank:
        shown = [_r(math.degrees(x) % 360.0) for x in xs]
    else:
        shown = [_r(x * 1000.0) for x in xs]
    return {
        "kind": sw.input_kind,
        "inputs": shown,
        "unit": "°" if crank else "mm",
        "sense": ("CW" if drv.omega < 0 else "CCW") if crank else "",
        "start": start,
        "full": bool(full),
        "labels": labels,
        "names": {lab: point_name(lab) for lab in labels},
        "ground": [g for g in scene.ground if g in sw.pos],
        "pos": {lab: arr(sw.pos, lab) for lab in labels},
        "vel": {lab: arr(sw.vel, lab) for lab in labels if lab in sw.vel},
        "edges": [list(e) for e in edges(scene) if e[0] in sw.pos and e[1] in sw.pos],
        "mech_off": _mech_off(sw, labels, N),
        "colours": {k: LOOKS[k].colour for k in ("given", "relative", "resultant")},
        "polys": polys,
        "drawing": drawing,
        "inset": inset_rule(),
    }


def inset_rule() -> dict:
    """The constants of the static drawings' inset rule (:mod:`diagrams.inset`), for the
    live panel's port of it (``assets/inset.js``): the round enlargements, the rule's
    shortest vector, the length under which a vector is not drawn, the ring's margin, the
    inset's largest radii (mm) and the distance under which vertices are drawn as one."""
    import inspect
    from . import crowd, inset
    same = inspect.signature(crowd.clusters).parameters["same"].default
    return {"factors": list(inset.FACTORS), "min_mm": inset.MIN_VECTOR_MM,
            "zero_mm": inset.ZERO_MM, "ring_margin": inset.RING_MARGIN,
            "max_radius": inset.MAX_RADIUS, "max_radius_vectors": inset.MAX_RADIUS_FOR_VECTORS,
            "same": same}


# ---------------------------------------------------------------- the drawing mode
def drawing_mode(sol, con, lay, names) -> dict:
    """What the student draws for one diagram: the vertices in construction order (the pole
    first), the construction's vectors (arrows between its vertices, in order), the stated
    scale of the static drawing and a paper (mm) with the cursor's start where the static
    drawing puts the pole."""
    from . import scale as scales
    if lay is not None:
        sc = lay.scale
    else:
        ext = np.array([p for p in con.vertices.values()], dtype=float)
        extent = tuple(ext.max(axis=0) - ext.min(axis=0)) if len(ext) else (1.0, 1.0)
        sc = scales.choose(scales.QUANTITY_OF[con.diagram], extent)
    k = sc.mm_per_si
    pts = np.array(list(con.vertices.values()), dtype=float)
    x0, y0 = pts.min(axis=0)
    x1, y1 = pts.max(axis=0)
    w, h = (x1 - x0) * k, (y1 - y0) * k
    W = max(PAPER_MIN[0], math.ceil((w + 2 * PAPER_MARGIN) / 10.0) * 10.0)
    H = max(PAPER_MIN[1], math.ceil((h + 2 * PAPER_MARGIN) / 10.0) * 10.0)
    pole = ((W - w) / 2 - x0 * k, (H - h) / 2 - y0 * k)
    vectors = []
    for st in con.strokes:
        if st.kind == "arrow" and st.frm and st.to and [st.frm, st.to] not in vectors:
            vectors.append([st.frm, st.to])
    unit = sc.unit.replace("²", "^2")
    per_mm = sc.per_cm_display / 10.0
    from polygons.options import scale_per_cm
    text = f"1 mm = {float(f'{per_mm:.6g}'):g} {unit}"
    return {"scale": text, "si_per_mm": scale_per_cm(text, con.diagram) / 10.0,
            "statement": sc.statement, "paper": [W, H],
            "cursor": [float(round(pole[0])), float(round(pole[1]))],
            "vertices": names,
            "labels": {v: vertex_name(con.pole_label if v == con.pole else v) for v in names},
            "vectors": vectors}
