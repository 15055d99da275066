"""Write the corpus of typical student errors (tests/data/drawings/*.json, *.svg).

Each drawing is what a student who made one slip draws: the construction replayed step by step
on the student's own vertices (``replay``), with the slip put into one step — a known vector
scaled (rpm slip, radius for diameter, ω·r for ω²·r, ωv for 2ωv), reversed or turned 90°, a
line turned 90° (∥ for ⟂), the Coriolis offset on the wrong side — and every later step built
on what the student had drawn.  Coordinates are rounded to 0.1 mm, as read off paper.  The
expected marks and feedback of each drawing are in corpus.toml, written by hand from the
grading rules (polygons/grade_drawing.py); this script only makes the drawings:

    PYTHONPATH=. python tests/data/drawings/make_corpus.py
"""
import json
import math
from pathlib import Path

from polygons.evaluate import solve
from polygons.grade_drawing import expected_vectors
from polygons.scene import load_scene
from polygons.steps import Kind

HERE = Path(__file__).resolve().parent
CASES = HERE.parents[2] / "cases"
#: case, diagram -> (SI per mm, the stated scale, pole on paper)
SETUP = {("s001-we3", "velocity"): (0.5, "1 mm = 0.5 m/s", (130, 80)),
         ("s001-we3", "acceleration"): (25.0, "1 cm = 250 m/s^2", (20, 130)),
         ("s003-fig7", "velocity"): (0.01, "1 mm = 0.01 m/s", (90, 20)),
         ("s003-fig7", "acceleration"): (0.05, "1 mm = 0.05 m/s^2", (120, 60))}


def _rot(v, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return (v[0] * c - v[1] * s, v[0] * s + v[1] * c)


def _meet(p, d, q, e):
    den = d[0] * e[1] - d[1] * e[0]
    t = ((q[0] - p[0]) * e[1] - (q[1] - p[1]) * e[0]) / den
    return (p[0] + t * d[0], p[1] + t * d[1])


def replay(sol, diagram, mods):
    """The construction redone on the student's own vertices; ``mods`` {step: {scale, turn,
    shift}} puts a slip into a step (shift: the offset of an offset line, scaled)."""
    V = sol.vertices[diagram]
    pole = sol.vertex_of(next(iter(sol.scene.ground)))
    P = {pole: (0.0, 0.0)}
    lines = {}
    for s in (s for s in sol.steps if s.diagram == diagram):
        m = mods.get(s.number, {})
        if s.kind == Kind.IMAGE and s.end not in P and len(s.args) >= 4:
            # the student's own triangle: start + z·(base − start), z the link's ratio
            q = sol.vertex_of(s.args[2])
            t = (V[s.end][0] - V[s.start][0], V[s.end][1] - V[s.start][1])
            b = (V[q][0] - V[s.start][0], V[q][1] - V[s.start][1])
            n2 = b[0] ** 2 + b[1] ** 2
            z = ((t[0] * b[0] + t[1] * b[1]) / n2, (t[1] * b[0] - t[0] * b[1]) / n2)
            o = (P[q][0] - P[s.start][0], P[q][1] - P[s.start][1])
            P[s.end] = (P[s.start][0] + z[0] * o[0] - z[1] * o[1],
                        P[s.start][1] + z[0] * o[1] + z[1] * o[0])
        elif s.kind == Kind.VECTOR and s.start and s.end and s.end not in P:
            v = (V[s.end][0] - V[s.start][0], V[s.end][1] - V[s.start][1])
            v = _rot(v, m.get("turn", 0.0))
            r = m.get("scale", 1.0)
            P[s.end] = (P[s.start][0] + r * v[0], P[s.start][1] + r * v[1])
        elif s.kind == Kind.LINE and s.direction is not None and s.at is not None:
            shift = (s.at[0] - V[s.start][0], s.at[1] - V[s.start][1])
            r = m.get("shift", 1.0)
            anchor = (P[s.start][0] + r * shift[0], P[s.start][1] + r * shift[1])
            lines[s.number] = (anchor, _rot(s.direction, m.get("turn", 0.0)))
        elif s.kind == Kind.INTERSECTION and len(s.lines) == 2:
            (p, d), (q, e) = lines[s.lines[0]], lines[s.lines[1]]
            P[s.end] = _meet(p, d, q, e)
    return P


def drawing(case, diagram, mods=None, drop=(), flip=(), rename=None, scale_drawn=None,
            extra=()):
    sol = solve(load_scene(CASES / f"{case}.toml"))
    k, stated, (x0, y0) = SETUP[(case, diagram)]
    P = replay(sol, diagram, mods or {})
    kd = scale_drawn or k
    rename = rename or {}
    verts = {rename.get(n, n): [round(x0 + p[0] / kd, 1), round(y0 + p[1] / kd, 1)]
             for n, p in P.items()}
    vectors = []
    for e in expected_vectors(sol, diagram):
        if e.start + e.end in drop or e.start not in P or e.end not in P:
            continue
        a, b = (e.end, e.start) if e.start + e.end in flip else (e.start, e.end)
        vectors.append([rename.get(a, a), rename.get(b, b)])
    vectors += [list(x) for x in extra]
    return {"diagram": diagram, "scale": stated, "vertices": verts, "vectors": vectors}


def svg(d):
    H = 200
    body = "".join(f'  <circle data-vertex="{n}" cx="{x}" cy="{round(H - y, 1)}" r="0.8"/>\n'
                   for n, (x, y) in d["vertices"].items())
    body += "".join(f'  <line data-from="{a}" data-to="{b}"/>\n' for a, b in d["vectors"])
    return (f'<svg xmlns="http://www.w3.org/2000/svg" data-polygons-drawing="{d["diagram"]}"'
            f' data-scale="{d["scale"]}" viewBox="0 0 250 {H}">\n{body}</svg>\n')


W, F = "s001-we3", "s003-fig7"
RPM = 3 / math.pi                       # ω = N/10 for 2πN/60: 100 for 104.7 rad/s
CORPUS = {
    # WE3, velocity: ab (ω·AB ⟂ AB, given), line bc ⟂ BC, line ac ⟂ DC
    "we3-v-right": (W, "velocity", {}),
    "we3-v-rpm-slip": (W, "velocity", {"mods": {1: {"scale": RPM}}}),
    "we3-v-diameter": (W, "velocity", {"mods": {1: {"scale": 2.0}}}),
    "we3-v-ab-parallel": (W, "velocity", {"mods": {1: {"turn": 90.0}}}),
    "we3-v-ab-reversed": (W, "velocity", {"mods": {1: {"turn": 180.0}}}),
    "we3-v-bc-parallel": (W, "velocity", {"mods": {2: {"turn": 90.0}}}),
    "we3-v-ac-arrow-reversed": (W, "velocity", {"flip": ("ac",)}),
    "we3-v-ac-missing": (W, "velocity", {"drop": ("ac",)}),
    "we3-v-mislabelled": (W, "velocity", {"rename": {"c": "c1"}}),
    "we3-v-scale-1.5": (W, "velocity", {"mods": {1: {"scale": 1.5}}}),
    # WE3, acceleration: ab, bc1 centripetal; line c1c ⟂ BC; ac2 centripetal; line c2c ⟂ DC
    "we3-a-right": (W, "acceleration", {}),
    "we3-a-bc1-reversed": (W, "acceleration", {"mods": {2: {"turn": 180.0}}}),
    "we3-a-omega-not-squared": (W, "acceleration", {"mods": {1: {"scale": 1 / 52.35987755982988}}}),
    "we3-a-rpm-slip": (W, "acceleration", {"mods": {1: {"scale": RPM ** 2}, 2: {"scale": RPM ** 2},
                                                    4: {"scale": RPM ** 2}}}),
    "we3-a-wrong-scale": (W, "acceleration", {"scale_drawn": 20.0}),
    "we3-a-c1c-parallel": (W, "acceleration", {"mods": {3: {"turn": 90.0}}}),
    "we3-a-c2-missing": (W, "acceleration", {"drop": ("ac2", "c2c"), "extra": (("a", "c"),)}),
    # Fig 7, velocity: o2p2 (given), line o2p4 ⟂ O4P4, line p2p4 ∥ the slot
    "fig7-v-right": (F, "velocity", {}),
    "fig7-v-slot-turned": (F, "velocity", {"mods": {3: {"turn": 25.0}}}),
    "fig7-v-half-radius": (F, "velocity", {"mods": {1: {"scale": 0.5}}}),
    "fig7-v-arrow-p4p2": (F, "velocity", {"flip": ("p2p4",)}),
    # Fig 7, acceleration: o2p2, o2p4_1 centripetal; line p4_1p4 ⟂; Coriolis p4p2_1; p2_1p2 ∥
    "fig7-a-right": (F, "acceleration", {}),
    "fig7-a-coriolis-reversed": (F, "acceleration", {"mods": {4: {"shift": -1.0},
                                                              6: {"turn": 180.0}}}),
    "fig7-a-coriolis-half": (F, "acceleration", {"mods": {4: {"shift": 0.5},
                                                          6: {"scale": 0.5}}}),
    "fig7-a-coriolis-missing": (F, "acceleration", {"mods": {4: {"shift": 0.0}, 6: {"scale": 0.0}},
                                                    "drop": ("p4p2_1", "p2_1p2"),
                                                    "extra": (("p4", "p2"),)}),
    "fig7-a-centripetal-reversed": (F, "acceleration", {"mods": {2: {"turn": 180.0}}}),
}
#: also written as the interactive page's SVG
AS_SVG = ("we3-v-rpm-slip", "fig7-a-coriolis-reversed", "we3-a-c1c-parallel")


def main():
    for name, (case, diagram, kw) in CORPUS.items():
        d = drawing(case, diagram, **kw)
        if name == "fig7-a-coriolis-missing":
            del d["vertices"]["p2_1"]
        if name in AS_SVG:
            (HERE / f"{name}.svg").write_text(svg(d), encoding="utf-8")
        else:
            (HERE / f"{name}.json").write_text(json.dumps(d, indent=1) + "\n",
                                               encoding="utf-8")


if __name__ == "__main__":
    main()
