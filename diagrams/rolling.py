"""A wheel rolling on a moving surface, or a cylinder between two moving plates, drawn.

Two pieces (the numbers come from :func:`polygons.contacts.rolling`; nothing is computed here
but where things go):

* :func:`space_items` — on the space diagram: each moving plate as a grey strip along its
  surface, joined to its block by a bar (the plate and the block are one body), the wheel, its
  contact points and its instant centre I;
* :func:`drawing` — the books' figure for the wheel (``rolling-W.svg``): the wheel between its
  surfaces with the velocity of its points along the line of the contacts drawn to a velocity
  scale (v₁ at the lower contact, v₂ at the upper — or the linkage's v_W — the straight line
  through their tips crossing the line of the contacts at I, v_W = (v₁ + v₂)/2 at the centre),
  and the legend with ω, α, a_W and the contact points' r·ω².
"""
from __future__ import annotations

import math

from polygons.contacts import rolling, wheel_point
from polygons.steps import Op

from . import scale as scales
from .labels import Box, Placer, bounds
from .layout import arrow_head, compose
from .model import Arrow, Circle, Drawing, Group, Polyline, Segment, Text
from .text import number

Pt = tuple[float, float]
#: the plates' strips on paper (mm)
STRIP_MM = 1.6
LABEL_SIZE = 3.6


def _nice(x: float) -> float:
    """The round number (1, 2, 2.5, 5 × 10ⁿ) at or above ``x``."""
    p = 10.0 ** math.floor(math.log10(x))
    return next(m * p for m in (1, 2, 2.5, 5, 10) if m * p >= x * (1 - 1e-12))


def moving(scene) -> list:
    """The scene's rolling contacts on a moving surface (or between two plates)."""
    return [q for q in scene.equivalents if q.kind == "rolling" and (q.on or q.opposite)]


def _plate_span(sol, q, name, sign) -> tuple[Pt, Pt, Pt, Pt] | None:
    """(the block's position, its foot on the plate's surface, the strip's two ends) in SI."""
    h = rolling(sol, q)
    if h is None:
        return None
    e = (math.cos(q.face), math.sin(q.face))
    n = (-e[1], e[0])
    W, r = h["centre"], q.radius
    C = (W[0] + sign * r * n[0], W[1] + sign * r * n[1])
    B = sol.placement.points.get(name, C)     # a plate moved at a stated rate: no block
    t = (B[0] - C[0]) * e[0] + (B[1] - C[1]) * e[1]
    foot = (C[0] + t * e[0], C[1] + t * e[1])
    lo, hi = min(t, -1.4 * r), max(t, 1.4 * r)
    return B, foot, (C[0] + lo * e[0], C[1] + lo * e[1]), (C[0] + hi * e[0], C[1] + hi * e[1])


def extent(sol) -> list[Pt]:
    """SI points the space diagram must hold for the moving wheels (wheel and plates)."""
    out = []
    for q in moving(sol.scene):
        h = rolling(sol, q)
        if h is None:
            continue
        W, r = h["centre"], q.radius
        out += [(W[0] - r, W[1] - r), (W[0] + r, W[1] + r)]
        for name, sign in ((q.on, -1), (q.opposite, 1)):
            if name:
                span = _plate_span(sol, q, name, sign)
                if span:
                    out += [span[2], span[3]]
    return out


def space_items(sol, q, to_paper, k, placer):
    """(background items, body items, notes) for one moving-surface wheel on the space
    diagram; ``to_paper`` maps SI to the drawing's mm."""
    h = rolling(sol, q)
    if h is None:
        return [], [], []
    e = (math.cos(q.face), math.sin(q.face))
    back, body, notes = [], [], []
    W = to_paper(h["centre"])
    rad = q.radius * k
    body.append(Circle(W, round(rad, 3), "link-thin", cls="wheel"))
    body.append(Circle(W, 0.9, "pin", cls="wheel-centre"))
    placer.rim(W, rad)                   # no note or label across the wheel's rim
    for name, sign in ((q.on, -1), (q.opposite, 1)):
        if name is None:          # the fixed surface
            C = to_paper(h["contacts"][0])
            s1, s2 = (C[0] - e[0] * rad * 1.3, C[1] - e[1] * rad * 1.3), \
                (C[0] + e[0] * rad * 1.3, C[1] + e[1] * rad * 1.3)
            back.append(Segment(s1, s2, "ground", cls="rolling-surface"))
            placer.hard(s1, s2, 1.0)
            continue
        B, foot, a, b = (to_paper(p) for p in _plate_span(sol, q, name, sign))
        # the strip lies on the far side of the surface from the wheel
        off = (-e[1] * sign * STRIP_MM, e[0] * sign * STRIP_MM)
        strip = (a, b, (b[0] + off[0], b[1] + off[1]), (a[0] + off[0], a[1] + off[1]))
        body.append(Polyline(tuple((round(x, 3), round(y, 3)) for x, y in strip), "plate",
                             closed=True, cls=f"plate plate-{name}"))
        if name in sol.placement.points:        # the bar joining the plate to its block
            body.append(Segment(B, (foot[0] + off[0], foot[1] + off[1]), "link",
                                cls=f"plate-bar plate-{name}"))
            placer.hard(B, foot, 1.0)
        placer.hard(a, b, 1.0)
        notes.append((f"plate of {name}", ((a[0] + b[0]) / 2 + off[0] * 2,
                                           (a[1] + b[1]) / 2 + off[1] * 2)))
    for C in h["contacts"]:
        body.append(Circle(to_paper(C), 0.6, "vertex", cls="contact"))
    placer.block(Box(W[0] - rad, W[1] - rad, W[0] + rad, W[1] + rad))
    notes.append((f"{'cylinder' if q.opposite else 'wheel'} {q.at}", (W[0] + rad * 0.7,
                                                                      W[1] + rad * 0.7)))
    if "instant_centre" in h:
        I = to_paper(h["instant_centre"])
        body.append(Circle(I, 0.8, "vertex", cls="instant-centre"))
        notes.append((f"I: instant centre of {q.at}", I))
    b_, n_ = rim_items(sol, q, to_paper)
    return back, body + b_, notes + n_


def rim_items(sol, q, to_paper) -> tuple[list, list]:
    """The wheel's named points ([rolling.W] rim) as dots with their labels."""
    body, notes = [], []
    for label, _angle, _dist in q.rim:
        if label in sol.points:        # a pin of a driven wheel: drawn with the links
            continue
        got = wheel_point(sol, q, label)
        if got is None:
            continue
        P = to_paper(got[0])
        body.append(Circle(P, 0.6, "vertex", cls="rim-point"))
        notes.append((label, P))
    return body, notes


def drawing(sol, q, scale: scales.Scale | None = None, paper: str | None = None) -> Drawing:
    """The wheel's own figure: its velocity along the line of the contacts (the books'
    straight-line distribution through I) and its numbers."""
    h = rolling(sol, q)
    e = (math.cos(q.face), math.sin(q.face))
    n = (-e[1], e[0])
    r = q.radius
    W = h["centre"]
    vs = list(h["surface_velocity"])
    vw = h["centre_velocity"][0] * e[0] + h["centre_velocity"][1] * e[1]
    # the points of the line of contacts whose velocity is drawn: the contacts and W
    pts = [(h["contacts"][0], vs[0], "C1")]
    if q.opposite:
        pts.append((h["contacts"][1], vs[1], "C2"))
    pts.append((W, vw, q.at))
    vmax = max(abs(v) for _, v, _ in pts) or 1.0
    # the velocity arrows are drawn at 3 r for the largest, on a round velocity scale
    sc = scales.choose("length", (6 * r, 4 * r), paper=paper, pad_mm=30.0) \
        if scale is None else scale
    k = sc.mm_per_si
    vk = 1.0 / _nice(vmax / (3 * r * k))     # mm of paper per m/s (a round m/s per mm)

    def P(p):
        return ((p[0] - W[0]) * k, (p[1] - W[1]) * k)

    placer = Placer()
    items, vec, lab = [], [], []
    c = P(W)
    rad = r * k
    items.append(Circle(c, round(rad, 3), "link-thin", cls="wheel"))
    items.append(Circle(c, 0.9, "pin", cls="wheel-centre"))
    placer.block(Box(c[0] - 1.5, c[1] - 1.5, c[0] + 1.5, c[1] + 1.5))
    reach = [v * vk for _, v, _ in pts]
    lo_e, hi_e = min(reach + [-1.5 * rad]) - 4.0, max(reach + [1.5 * rad]) + 4.0
    for sign, name in ((-1, q.on), (1, q.opposite)):
        if sign == 1 and not q.opposite:
            continue
        C = (c[0] + sign * rad * n[0], c[1] + sign * rad * n[1])
        a = (C[0] + e[0] * lo_e, C[1] + e[1] * lo_e)
        b = (C[0] + e[0] * hi_e, C[1] + e[1] * hi_e)
        off = (n[0] * sign * STRIP_MM, n[1] * sign * STRIP_MM)
        style = "plate" if name else "ground"
        items.append(Polyline((a, b, (b[0] + off[0], b[1] + off[1]),
                               (a[0] + off[0], a[1] + off[1])), style, closed=True,
                              cls="plate" if name else "rolling-surface"))
        placer.hard(a, b, 1.0)
    # the line of the contacts and the velocity arrows along the surface
    ends = [P(p) for p, _, _ in pts]
    tips = []
    for (p, v, name), at in zip(pts, ends):
        tip = (at[0] + v * vk * e[0], at[1] + v * vk * e[1])
        tips.append(tip)
        if abs(v) * vk > 0.5:
            head, base = arrow_head(at, tip)
            vec.append(Arrow(at, tip, "c-resultant", head, base, name=f"v_{name}"))
            placer.hard(at, tip, 0.6)
    I = P(h["instant_centre"]) if "instant_centre" in h else None
    lo = min([-rad * 1.2] + ([((I[0] - c[0]) * n[0] + (I[1] - c[1]) * n[1])] if I else []))
    hi = max([rad * 1.2] + ([((I[0] - c[0]) * n[0] + (I[1] - c[1]) * n[1])] if I else []))
    items.append(Segment((c[0] + lo * n[0], c[1] + lo * n[1]), (c[0] + hi * n[0],
                                                                 c[1] + hi * n[1]),
                         "construction", cls="line-of-contacts"))
    placer.soft((c[0] + lo * n[0], c[1] + lo * n[1]), (c[0] + hi * n[0], c[1] + hi * n[1]))
    if I is not None:
        # the straight line through the tips of the contacts' arrows meets the line of the
        # contacts at I (the velocities are proportional to the distance from I)
        line = tips + [I]
        p0, p1 = max(((a, b) for a in line for b in line), key=lambda ab: math.dist(*ab))
        items.append(Segment(p0, p1, "construction", cls="velocity-distribution"))
        placer.soft(p0, p1)
        items.append(Circle(I, 0.8, "vertex", cls="instant-centre"))
        lab.append(("I", I))
    names = [("C1" if q.opposite or q.on else "C", ends[0])]
    if q.opposite:
        names.append(("C2", ends[1]))
    names.append((q.at, c))
    texts = []
    for text, at in names + lab:
        if text in ("C1", "C2", "C", "I"):
            items.append(Circle(at, 0.5, "vertex"))
        x, y, anchor, _ = placer.place(text, at, LABEL_SIZE)
        texts.append(Text(x, y, text, LABEL_SIZE, anchor=anchor, role="point"))
    # the legend
    W_ = q.at

    def sense(x):
        return "CCW" if x > 0 else ("CW" if x < 0 else "")
    legend = [(f"{'cylinder' if q.opposite else 'wheel'} {W_}: r = {number(r * 1000)} mm; "
               f"+ along the surface at {number(math.degrees(q.face))}°", "normal"),
              ("", "normal"), ("Velocity (no slip at each contact):", "bold"),
              (f"v₁ = {number(vs[0])} m/s ({q.on or 'fixed surface'})", "normal")]
    if q.opposite:
        legend += [(f"v₂ = {number(vs[1])} m/s ({q.opposite})", "normal"),
                   (f"v_{W_} = (v₁ + v₂)/2 = {number(vw)} m/s", "normal"),
                   (f"ω = (v₁ − v₂)/2r = {number(abs(h['omega']))} rad/s "
                    f"{sense(h['omega'])}", "normal")]
    else:
        legend += [(f"v_{W_} = {number(vw)} m/s (the linkage)", "normal"),
                   (f"ω = (v₁ − v_{W_})/r = {number(abs(h['omega']))} rad/s "
                    f"{sense(h['omega'])}", "normal")]
    if I is not None:
        legend.append((f"I{W_} = v_{W_}/ω = {number(math.dist(h['instant_centre'], W) * 1000)} "
                       f"mm", "normal"))
    if "alpha" in h:
        a = h["surface_acceleration"]
        aw = h["centre_acceleration"][0] * e[0] + h["centre_acceleration"][1] * e[1]
        legend += [("", "normal"), ("Acceleration:", "bold"),
                   (f"a₁ = {number(a[0])} m/s²" + (f", a₂ = {number(a[1])} m/s²"
                                                   if q.opposite else ""), "normal"),
                   (f"a_{W_} = {number(aw)} m/s²" + (" = (a₁ + a₂)/2" if q.opposite else ""),
                    "normal"),
                   (f"α = {number(abs(h['alpha']))} rad/s² {sense(h['alpha'])}", "normal"),
                   (f"contact points: the plate's a + r·ω² = "
                    f"{number(r * h['omega'] ** 2)} m/s² towards {W_}", "normal")]
    key = [("link-thin", "wheel", False), ("plate", "moving plate", False),
           ("construction", "line of contacts; velocity distribution", False),
           ("c-resultant", "velocity along the surface", False)]
    allpts = tips + ends + [(c[0] + lo_e * e[0] - rad * n[0], c[1] + lo_e * e[1] - rad * n[1]),
                            (c[0] + hi_e * e[0] + rad * n[0], c[1] + hi_e * e[1] + rad * n[1])]
    if I is not None:
        allpts.append(I)
    box = bounds(allpts).grown(8.0)
    scene = sol.scene
    sid = scene.source.get("id", "") if hasattr(scene.source, "get") else ""
    title = (f"Cylinder {W_} between two moving plates" if q.opposite else
             f"Wheel {W_} rolling on a moving plate")
    caption = [f"Each arrow is the velocity along the surface of the wheel's point there "
               f"(1 mm = {number(1 / vk)} m/s); they end on a straight line through the "
               f"instant centre I, which lies on the line of the contacts."]
    return compose(name=f"rolling-{W_}", kind="space", stage=None, title=title,
                   subtitle=f"{sid}: {scene.title}" if sid else scene.title,
                   desc=f"{title}, space scale {sc.statement}.",
                   content=[Group("wheel", "mechanism", "The wheel and the plates",
                                  tuple(items)),
                            Group("velocity", "velocity", "Velocities along the surface",
                                  tuple(vec)),
                            Group("labels", "labels", "Point labels", tuple(texts))],
                   content_box=Box(box.x0, box.y0, box.x1, box.y1), legend=legend, scale=sc,
                   caption=caption, scale_statement=sc.statement, key=key,
                   meta={"figure": "rolling", "labels": tuple(sorted(set(scene.labels)
                                                                    | {"C1", "C2"}))})


def drawings(sol, scale=None, paper=None) -> list[Drawing]:
    """One figure per wheel on a moving surface (none when the scene has none or the
    solution stops before velocity)."""
    return [drawing(sol, q, scale, paper) for q in moving(sol.scene)
            if rolling(sol, q) is not None]


def legend_rows(sol, diagram: str) -> list[tuple[str, str]]:
    """Rows for a finished diagram's legend: each rolling wheel's ω (velocity) or α
    (acceleration) from its no-slip condition(s), and the speed or acceleration of its named
    points and of a cylinder's centre between plates (not vertices of the polygon), each
    marked '← asked' when the scene's [[answers]] ask it."""
    from polygons.quantities import quantity
    from polygons.steps import sense
    asked = {(a.q.fn, a.q.args[0]) for a in sol.scene.answers if len(a.q.args) == 1}
    vel = diagram == "velocity"
    rows = []
    for q in sol.scene.equivalents:
        if q.kind != "rolling" or rolling(sol, q) is None:
            continue
        fn = "omega" if vel else "alpha"
        if any(st.op in (Op.ROLL_OMEGA, Op.ROLL_ALPHA) and st.args[0] == q.at
               for st in sol.steps):          # a driven wheel: its rate is a measure step
            continue
        try:
            w = quantity(sol, f"{fn}({q.at})")
        except Exception:                     # noqa: BLE001 - not solved (velocity only)
            continue
        sym, unit = ("ω", "rad/s") if vel else ("α", "rad/s²")
        how = "the no-slip conditions" if q.opposite else "no slip at the contact"
        mark = (fn, q.at) in asked
        rows.append((f"{sym}_{q.at} = {number(abs(w), 4)} {unit} {sense(w)} (wheel {q.at}, "
                     f"{how})" + ("\u2003← asked" if mark else ""), "bold" if mark else "normal"))
        points = [p for p, _, _ in q.rim if p not in sol.points] + (
            [q.at] if q.at not in sol.points else [])
        f, u = ("v", "m/s") if vel else ("a", "m/s²")
        for p in points:
            mark = (f, p) in asked
            how = (f"the centre of the cylinder {q.at}: the mean of its plates'" if p == q.at
                   else f"a point of wheel {q.at}: {f}_{q.at} + {sym} × {q.at}{p}"
                   + ("" if vel else f" − ω² {q.at}{p}"))
            rows.append((f"{f}_{p} = {number(quantity(sol, f'{f}({p})'), 4)} {u} ({how})"
                         + ("\u2003← asked" if mark else ""), "bold" if mark else "normal"))
    return rows
