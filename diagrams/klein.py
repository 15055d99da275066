"""Klein's (or Ritterhaus's, Bennett's) construction drawn on the space diagram, stage by stage.

The figure comes from :func:`polygons.classic.klein.figure` (nothing is computed here but
where things go): the crank circle, the crank, the rod and the line of stroke (stage 1); the
perpendicular through O and the rod produced to M, the velocity triangle O A M (stage 2); the
Klein circle on A with radius AM and the circle on AB as diameter cutting at K, L — or
Ritterhaus's parallels M K and K Q, or Bennett's crank at right angles O A₁ with its rod
A₁ B₁, the foot L₁, the point L and the perpendiculars L K, K Q (stage 3); the chord through Q to N on the line through O
parallel to the stroke and the acceleration quadrilateral O A Q N (stage 4).  The sides of the
triangle and of the quadrilateral take the polygons' component looks (given, relative,
centripetal, tangential, resultant) with the key; the legend gives each side's length and the
number it stands for (× ω or × ω²).
"""
from __future__ import annotations

import math

from polygons.classic.klein import TITLES, Figure

from . import scale as scales
from .labels import Box, Placer, bounds
from .layout import compose
from .model import Circle, Drawing, Group, Polyline, Segment, Text
from .text import number

Pt = tuple[float, float]
LABEL_SIZE = 3.6
PIN_R = 1.1
PAD_MM = 24.0
#: the area (mm) Klein's construction is fitted to when no paper is asked for: an A4
#: landscape page's width, its key and legend below it
KLEIN_AREA = (265.0, 170.0)
KLEIN_PAGE_WIDTH = 285.0
#: the stages and their titles
STAGES = ("the crank, the rod and the line of stroke",
          "velocity: the triangle {O} {A} {M} (turned 90°, × ω)",
          "the circles (Klein) / the parallels (Ritterhaus) / the perpendiculars (Bennett)",
          "acceleration: the quadrilateral {O} {A} {Q} {N} (turned 180°, × ω²)")


def stage_title(f: Figure, stage: int) -> str:
    """The stage's title in the scene's letters."""
    text = STAGES[stage - 1]
    if stage == 3:
        text = {"klein": "the Klein circle and the circle on the rod",
                "ritterhaus": "the parallel through {M} and the perpendicular through {K}",
                "bennett": "{A}{L} = {A1}{L1}, the perpendiculars {L}{K} and {K}{Q}"}[f.method]
    return text.format(**{k: v for k, v in f.names.items() if k != "inline"})


def _extent(f: Figure) -> list[Pt]:
    pts = list(f.points.values())
    O, r = f.points["O"], math.dist(f.points["O"], f.points["A"])
    pts += [(O[0] - r, O[1] - r), (O[0] + r, O[1] + r)]
    if f.method == "klein":
        for (c, R) in (f.klein_circle, f.rod_circle):
            pts += [(c[0] - R, c[1] - R), (c[0] + R, c[1] + R)]
    return pts


def drawing(sol, f: Figure, stage: int | None = None, scale: scales.Scale | None = None,
            paper: str | None = None) -> Drawing:
    """The construction up to ``stage`` (1..4; None: finished)."""
    last = len(STAGES) if stage is None else stage
    ext = bounds(_extent(f))
    # its own scale, on A4 unless asked otherwise: the circle on the rod sets the figure's
    # size, and at the space diagram's A5 scale the crank was 12 mm, M A Q K L N on top of
    # each other
    if scale is None and paper is None:
        w, h = ext.x1 - ext.x0, ext.y1 - ext.y0
        scale = scales.make("length", scales.round_up(max(
            w * 10.0 / (KLEIN_AREA[0] - PAD_MM), h * 10.0 / (KLEIN_AREA[1] - PAD_MM))))
    sc = scale or scales.choose("length", (ext.x1 - ext.x0, ext.y1 - ext.y0),
                                paper=paper, pad_mm=PAD_MM)
    k = sc.mm_per_si

    def P(role_or_pt) -> Pt:
        p = f.points[role_or_pt] if isinstance(role_or_pt, str) else role_or_pt
        return (p[0] * k, p[1] * k)

    nm = f.names
    placer = Placer()
    groups: list[Group] = []

    def style(kind: str, at: int) -> str:
        return f"c-{kind}-new" if at == last and stage is not None else f"c-{kind}"

    # stage 1: the mechanism
    O, A, B = P("O"), P("A"), P("B")
    r = math.dist(O, A)
    e = f.stroke
    span = max(ext.x1 - ext.x0, ext.y1 - ext.y0) * k * 0.6 + 10
    sp = P(f.stroke_point)
    t0 = (O[0] - sp[0]) * e[0] + (O[1] - sp[1]) * e[1]
    tb = (B[0] - sp[0]) * e[0] + (B[1] - sp[1]) * e[1]
    lo, hi = min(t0, tb) - span * 0.4, max(t0, tb) + span * 0.4
    s1, s2 = ((sp[0] + lo * e[0], sp[1] + lo * e[1]), (sp[0] + hi * e[0], sp[1] + hi * e[1]))
    n = (-e[1], e[0])
    bw, bh = 6.0, 4.0
    block = tuple((B[0] + sx * bw / 2 * e[0] + sy * bh / 2 * n[0],
                   B[1] + sx * bw / 2 * e[1] + sy * bh / 2 * n[1])
                  for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1)))
    mech = [Circle(O, r, "construction", cls="crank-circle"),
            Segment(s1, s2, "guide-path", cls="stroke"),
            Segment(O, A, "link", cls="crank"), Segment(A, B, "link", cls="rod"),
            Polyline(block, "block", closed=True, cls="piston"),
            Circle(O, PIN_R * 1.3, "pin", cls="pivot"), Circle(A, PIN_R, "pin"),
            Circle(B, PIN_R, "pin")]
    for a, b in ((O, A), (A, B), (s1, s2)):
        placer.hard(a, b)
    for c, rr in ((O, PIN_R * 1.3 + 0.4), (A, PIN_R + 0.4)):
        placer.block(Box(c[0] - rr, c[1] - rr, c[0] + rr, c[1] + rr))
    placer.block(bounds(block).grown(0.4))
    groups.append(Group("mechanism", "mechanism", "The crank, the rod and the line of stroke",
                        tuple(mech)))
    labels = ["O", "A", "B"]
    legend: list[tuple[str, str]] = [
        (f"crank {f.crank}: ω = {number(abs(f.omega))} rad/s "
         f"{'CCW' if f.omega > 0 else 'CW'}, uniform", "normal"),
        ("in-line engine" if f.inline else
         f"offset engine: O is {number(abs(f.offset) * 1000)} mm from the stroke", "normal")]
    key: list[tuple[str, str, bool]] = [("link", "crank, rod", False),
                                        ("guide-path", "line of stroke", False),
                                        ("construction", "construction line or circle", False)]
    M = P("M")
    if last >= 2:
        # the perpendicular through O and the rod produced to M
        ext_end = M
        items = [Segment(O, M, "construction", cls="perpendicular"),
                 Segment(A, ext_end, "construction", cls="rod-produced"),
                 Segment(O, A, style("given", 2), cls="oa"),
                 Segment(A, M, style("relative", 2), cls="ab"),
                 Segment(O, M, style("resultant", 2), cls="ob")]
        for a, b in ((O, M), (A, M)):
            placer.hard(a, b)
        # the perpendicular through O runs on past M to the crank circle: keep labels off it
        placer.soft((O[0] - n[0] * r, O[1] - n[1] * r), (O[0] + n[0] * r, O[1] + n[1] * r))
        groups.append(Group("velocity", "velocity", "Velocity triangle O A M (turned 90°)",
                            tuple(items)))
        labels.append("M")
        w = abs(f.omega)
        dOM, dAM = math.dist(f.points["O"], f.points["M"]), math.dist(f.points["A"],
                                                                      f.points["M"])
        legend += [("", "normal"), ("Velocity (each length × ω):", "bold"),
                   (f"{nm['O']}{nm['A']} → v_{nm['A']} = {number(w * math.dist(f.points['O'], f.points['A']))} m/s",
                    "normal"),
                   (f"{nm['A']}{nm['M']} = {number(dAM * 1000)} mm → (v_{nm['B']})_{nm['A']} = "
                    f"{number(w * dAM)} m/s", "normal"),
                   (f"{nm['O']}{nm['M']} = {number(dOM * 1000)} mm → v_{nm['B']} = "
                    f"{number(w * dOM)} m/s", "normal")]
        key += [("c-given", "crank pin (given)", False), ("c-relative", "relative", False)]
    if last >= 3:
        items = []
        if f.method == "klein":
            (c1, R1), (c2, R2) = f.klein_circle, f.rod_circle
            items += [Circle(P(c1), R1 * k, "construction-new" if last == 3 and stage else
                             "construction", cls="klein-circle"),
                      Circle(P(c2), R2 * k, "construction-new" if last == 3 and stage else
                             "construction", cls="rod-circle")]
            labels += [x for x in ("K", "L") if x in f.points]
        elif f.method == "bennett":
            A1, B1, L1, Lp, K, Q = (P(x) for x in ("A1", "B1", "L1", "L", "K", "Q"))
            items += [Segment(O, A1, "construction", cls="crank-right-angle"),
                      Segment(A1, B1, "construction", cls="rod-right-angle"),
                      Segment(O, L1, "construction", cls="perpendicular-OL1"),
                      Segment(Lp, K, "construction", cls="perpendicular-LK"),
                      Segment(K, Q, "construction", cls="perpendicular-KQ")]
            for a, b in ((O, A1), (A1, B1), (O, L1), (Lp, K), (K, Q)):
                placer.hard(a, b)
            labels += ["A1", "B1", "L1", "L", "K", "Q"]
        else:
            K, Q = P("K"), P("Q")
            items += [Segment(M, K, "construction", cls="parallel-MK"),
                      Segment(O, K, "construction", cls="crank-produced"),
                      Segment(K, Q, "construction", cls="parallel-KQ")]
            for a, b in ((M, K), (K, Q), (O, K)):
                placer.hard(a, b)
            labels += ["K", "Q"]
        groups.append(Group("circles", "construction", STAGES[2], tuple(items)))
    if last >= 4:
        Q, N = P("Q"), P("N")
        items = []
        if "K" in f.points and f.method == "klein":
            Kp, Lp = P("K"), P("L")
            items.append(Segment(Kp, Lp, "construction", cls="chord"))
            # the chord produced to N
            end = min((Kp, Lp), key=lambda p: math.dist(p, N))
            items.append(Segment(end, N, "construction", cls="chord-produced"))
            placer.hard(Kp, Lp)
            placer.hard(end, N)
        else:
            items.append(Segment(Q, N, "construction", cls="perpendicular-QN"))
        if not f.inline:     # the line through O parallel to the stroke
            items.append(Segment(O, N, "construction", cls="parallel-ON"))
        # a_A lies on the crank (and on oa): drawn 0.8 mm beside it
        u = (A[0] - O[0], A[1] - O[1])
        lu = math.hypot(*u) or 1.0
        sh = (-u[1] / lu * 0.8, u[0] / lu * 0.8)
        items += [Segment((O[0] + sh[0], O[1] + sh[1]), (A[0] + sh[0], A[1] + sh[1]),
                          style("centripetal", 4), cls="a-A"),
                  Segment(A, Q, style("centripetal", 4), cls="an-BA"),
                  Segment(Q, N, style("tangential", 4), cls="at-BA"),
                  Segment(N, O, style("resultant", 4), cls="a-B")]
        for a, b in ((A, Q), (Q, N), (N, O)):
            placer.hard(a, b)
        groups.append(Group("acceleration", "acceleration",
                            "Acceleration quadrilateral O A Q N (turned 180°)", tuple(items)))
        labels += ["Q", "N"]
        w2 = f.omega ** 2
        d = {kk: math.dist(f.points[kk[0]], f.points[kk[1]]) for kk in ("OA", "AQ", "QN", "NO")}
        legend += [("", "normal"), ("Acceleration (each length × ω²):", "bold"),
                   (f"{nm['O']}{nm['A']} → a_{nm['A']} = {number(w2 * d['OA'])} m/s²", "normal"),
                   (f"{nm['A']}{nm['Q']} = {number(d['AQ'] * 1000)} mm → (a_{nm['B']})_{nm['A']}^n"
                    f" = {number(w2 * d['AQ'])} m/s²", "normal"),
                   (f"{nm['Q']}{nm['N']} = {number(d['QN'] * 1000)} mm → (a_{nm['B']})_{nm['A']}^t"
                    f" = {number(w2 * d['QN'])} m/s²", "normal"),
                   (f"{nm['N']}{nm['O']} = {number(d['NO'] * 1000)} mm → a_{nm['B']} = "
                    f"{number(w2 * d['NO'])} m/s²", "normal"),
                   (f"α_{f.rod} = ω²·{nm['Q']}{nm['N']}/{nm['A']}{nm['B']} = "
                    f"{number(abs(f.alpha_rod))} rad/s²", "normal")]
        key += [("c-centripetal", "centripetal", False), ("c-tangential", "tangential", False)]
    if last >= 2:
        key.append(("c-resultant", "piston (resultant)", False))
    # the point labels, placed clear of the lines
    texts = []
    for role in dict.fromkeys(labels):
        at = P(role)
        x, y, anchor, _ = placer.place(nm[role], at, LABEL_SIZE)
        texts.append(Text(x, y, nm[role], LABEL_SIZE, anchor=anchor, role="point"))
        if role not in ("O", "A", "B"):
            texts.append(Circle(at, 0.5, "vertex"))
    groups.append(Group("labels", "labels", "Point labels", tuple(texts)))
    allpts = [P(r) for r in labels] + [s1, s2, (O[0] - r, O[1] - r), (O[0] + r, O[1] + r)]
    if last >= 3 and f.method == "klein":
        for c, R in (f.klein_circle, f.rod_circle):
            cc = P(c)
            allpts += [(cc[0] - R * k, cc[1] - R * k), (cc[0] + R * k, cc[1] + R * k)]
    box = bounds(allpts).grown(8.0)
    title = TITLES[f.method] + ("" if stage is None else
                                f" — stage {stage}: {stage_title(f, stage)}")
    scene = sol.scene
    sid = scene.source.get("id", "") if hasattr(scene.source, "get") else ""
    subtitle = f"{sid}: {scene.title}" if sid else scene.title
    name = f.method if stage is None else f"{f.method}-{stage}"
    o, a_, b_, m_, q_, n_ = (nm[x] for x in ("O", "A", "B", "M", "Q", "N"))
    caption = [] if stage is not None else [
        f"The velocity triangle {o} {a_} {m_} is the velocity polygon turned 90° (each length "
        f"× ω); the quadrilateral {o} {a_} {q_} {n_} is the acceleration polygon turned 180° "
        f"(each length × ω²): a_{b_} = ω²·{n_}{o}, read off the space diagram."]
    from .layout import restack
    return restack(compose(name=name, kind="space", stage=stage, title=title, subtitle=subtitle,
                   desc=f"{TITLES[f.method]} for {scene.title}, space scale {sc.statement}.",
                   content=groups, content_box=Box(box.x0, box.y0, box.x1, box.y1),
                   legend=legend, scale=sc, caption=caption, scale_statement=sc.statement,
                   key=key, meta={"figure": f.method,
                                           "labels": tuple(sorted(set(scene.labels) | {
                                               v for kk, v in nm.items() if kk != "inline"}))}),
                   KLEIN_PAGE_WIDTH)


def drawings(sol, f: Figure, scale=None, paper=None, stages: bool = True) -> list[Drawing]:
    """The finished construction, then (``stages``) each stage."""
    out = [drawing(sol, f, None, scale, paper)]
    if stages:
        out += [drawing(sol, f, s, scale, paper) for s in range(1, len(STAGES) + 1)]
    return out
