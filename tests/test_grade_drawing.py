"""`polygons check --drawing`: a drawn polygon graded vector by vector.

Drawings made from the true construction (its vertices at a round scale, every vertex marked
with the emulated pencil's error, ±0.25 mm) pass; the typical mistakes — the Coriolis
component reversed, a line drawn ∥ a link instead of ⟂, the polygon drawn at another scale
than the one stated, a missing vector — are each caught and named, with the step to recheck.
"""
import json
import math
import random
from pathlib import Path

import pytest

from polygons.cli import main
from polygons.cli.check import emulated_tolerances, stated_tolerance
from polygons.drawing_format import (DrawingError, StudentDrawing, parse_json, parse_svg,
                                     read_drawing)
from polygons.evaluate import solve
from polygons.grade_drawing import expected_vectors, grade
from polygons.scene import load_scene

CASES = Path(__file__).resolve().parents[1] / "cases"
WE3 = CASES / "s001-we3.toml"
FIG7 = CASES / "s003-fig7.toml"


@pytest.fixture(scope="module")
def sols():
    out = {}
    for path in (WE3, FIG7):
        sol = solve(load_scene(path))
        out[path.name] = (sol, emulated_tolerances(sol), stated_tolerance(sol))
    return out


def _scale(sol, diagram):
    """SI per mm that draws the polygon's farthest vertex 100 mm from the pole."""
    return max(math.hypot(*p) for p in sol.vertices[diagram].values()) / 100.0


def _drawing(sol, diagram, verts, k, seed=None, vectors=None):
    rng = random.Random(seed)
    noise = (lambda: rng.uniform(-0.25, 0.25)) if seed is not None else (lambda: 0.0)
    P = {n: (p[0] / k + 40 + noise(), p[1] / k - 20 + noise()) for n, p in verts.items()}
    vectors = vectors or tuple((e.start, e.end) for e in expected_vectors(sol, diagram))
    return StudentDrawing(diagram, k, f"1 mm = {k:.6g}", P, tuple(vectors), "<test>")


def _meet(p, d, q, e):
    den = d[0] * e[1] - d[1] * e[0]
    t = ((q[0] - p[0]) * e[1] - (q[1] - p[1]) * e[0]) / den
    return (p[0] + t * d[0], p[1] + t * d[1])


def _step(sol, diagram, number):
    return next(s for s in sol.steps if s.diagram == diagram and s.number == number)


@pytest.mark.parametrize("case", [WE3.name, FIG7.name])
@pytest.mark.parametrize("diagram", ["velocity", "acceleration"])
def test_true_construction_with_pencil_noise_passes(sols, case, diagram):
    sol, em, st = sols[case]
    k = _scale(sol, diagram)
    for seed in range(25):
        g = grade(sol, _drawing(sol, diagram, sol.vertices[diagram], k, seed), em, st)
        assert g.ok, (seed, [(m.name, m.problem) for m in g.marks if m.mark < 1])
        assert g.score == g.out_of == len(expected_vectors(sol, diagram))
        assert g.closures and all(c.ok for c in g.closures)


def test_expected_vectors_follow_the_steps(sols):
    sol = sols[WE3.name][0]
    vel = [(e.start, e.end, e.rule) for e in expected_vectors(sol, "velocity")]
    assert vel == [("a", "b", "⟂ AB"), ("b", "c", "⟂ BC"), ("a", "c", "⟂ DC")]
    acc = {(e.start, e.end): e.rule for e in expected_vectors(sol, "acceleration")}
    assert acc[("b", "c1")] == "∥ BC, towards B" and acc[("c1", "c")] == "⟂ BC"
    sol7 = sols[FIG7.name][0]
    cor = [e for e in expected_vectors(sol7, "acceleration") if e.coriolis]
    assert len(cor) == 1 and cor[0].vector == pytest.approx(
        tuple(-x for x in _step(sol7, "acceleration", 4).vector))   # 2ωv, drawn p4 → p2_1


def test_parallel_instead_of_perpendicular_is_named(sols):
    sol, em, st = sols[WE3.name]
    V = dict(sol.vertices["velocity"])
    line_bc, line_dc = _step(sol, "velocity", 2), _step(sol, "velocity", 3)
    d = line_bc.direction
    wrong = (-d[1], d[0])                       # ∥ BC instead of ⟂ BC
    V["c"] = _meet(V["b"], wrong, V["a"], line_dc.direction)
    g = grade(sol, _drawing(sol, "velocity", V, _scale(sol, "velocity"), 3), em, st)
    bad = {m.name: m for m in g.marks if m.mark < 1}
    assert "bc" in bad and bad["bc"].problem == "drawn ∥ BC instead of ⟂ BC"
    assert bad["bc"].hint.startswith("bc must be ⟂ BC (velocity step 2")
    assert not g.ok


def test_reversed_coriolis_is_named(sols):
    sol, em, st = sols[FIG7.name]
    A = dict(sol.vertices["acceleration"])
    cor = (A["p2_1"][0] - A["p4"][0], A["p2_1"][1] - A["p4"][1])     # 2ωv as drawn
    tangential, slot = _step(sol, "acceleration", 3), _step(sol, "acceleration", 4)
    # the student sets 2ωv off the wrong way: p2_1 = p4 − 2ωv, then p2_1 → p2 ∥ the slot
    A["p4"] = _meet(A["p4_1"], tangential.direction,
                    (A["p2"][0] + cor[0], A["p2"][1] + cor[1]), slot.direction)
    A["p2_1"] = (A["p4"][0] - cor[0], A["p4"][1] - cor[1])
    g = grade(sol, _drawing(sol, "acceleration", A, _scale(sol, "acceleration"), 5), em, st)
    bad = {m.name: m for m in g.marks if m.mark < 1}
    assert bad["p4p2_1"].problem.startswith("the Coriolis component is reversed: drawn towards")
    assert bad["p4p2_1"].shown == "p₄p₂′" and bad["p4p2_1"].mark == 0.5
    assert "2ω × v" in bad["p4p2_1"].hint and "acceleration step 6" in bad["p4p2_1"].hint
    assert "o2p2" not in bad and "o2p4_1" not in bad            # the rest stays right


def test_the_stated_scale_is_the_scale(sols):
    """A polygon drawn at twice the stated scale: the stated scale is taken as the scale, so
    the given vector ab is named a wrong value (with the slip that doubles it) and costs its
    half mark; the lines, graded through the student's own vertices, keep theirs."""
    sol, em, st = sols[WE3.name]
    k = _scale(sol, "velocity")
    drawing = _drawing(sol, "velocity", sol.vertices["velocity"], k / 2, 1)  # drawn twice big
    stated = StudentDrawing("velocity", k, drawing.scale_text.replace(
        f"{k / 2:.6g}", f"{k:.6g}"), drawing.vertices, drawing.vectors, "<test>")
    g = grade(sol, stated, em, st)
    marks = {m.name: m for m in g.marks}
    assert g.score == 2.5 and marks["ab"].mark == 0.5 and not g.ok
    assert "the value is wrong, not the scale" in marks["ab"].problem
    assert "diameter" in marks["ab"].problem and "2×" in marks["ab"].problem
    assert marks["bc"].mark == marks["ac"].mark == 1


def test_a_value_shown_equal_to_its_limit_is_inside_it():
    from polygons.grade_drawing import within
    assert within(0.94, 0.86, 1)            # "0.9° (± 0.9°)": inside
    assert within(-0.94, 0.86, 1)
    assert not within(0.96, 0.86, 1)        # "1.0° (± 0.9°)": outside
    assert within(1.049, 1.0, 1) and not within(1.051, 1.0, 1)


def test_a_line_drawn_the_other_way_is_the_same_line(sols):
    """ac ⟂ DC with c set on the far side of a (the arrow a→c reversed along its line): the
    line is right, its sense is not graded (it is not a known vector); no "off by 178.7°"."""
    sol, em, st = sols[WE3.name]
    V = dict(sol.vertices["velocity"])
    k = _scale(sol, "velocity")
    g0 = grade(sol, _drawing(sol, "velocity", V, k, 4), em, st)
    V["c"] = (-V["c"][0] * 0.5, -V["c"][1] * 0.5)       # along ⟂ DC, behind a
    g = grade(sol, _drawing(sol, "velocity", V, k, 4), em, st)
    ac = {m.name: m for m in g.marks}["ac"]
    assert ac.mark == 1 and ac.problem == "" and abs(ac.angle_err_deg) < 2
    assert {m.name: m for m in g0.marks}["ac"].mark == 1


def test_missing_and_reversed_arrows(sols):
    sol, em, st = sols[WE3.name]
    k = _scale(sol, "velocity")
    g = grade(sol, _drawing(sol, "velocity", sol.vertices["velocity"], k, 2,
                            vectors=(("a", "b"), ("c", "b"))), em, st)
    marks = {m.name: m for m in g.marks}
    assert marks["ab"].mark == 1 and marks["cb"].mark == 1     # a line: either arrow
    assert marks["ac"].problem == "missing" and "⟂ DC" in marks["ac"].hint
    g = grade(sol, _drawing(sol, "velocity", sol.vertices["velocity"], k, 2,
                            vectors=(("b", "a"), ("b", "c"), ("a", "c"))), em, st)
    assert {m.name: m.mark for m in g.marks}["ab"] == 0        # the given vector has a sense


SVG = """<svg xmlns="http://www.w3.org/2000/svg" data-polygons-drawing="velocity"
 data-scale="{scale}" viewBox="0 0 300 300">
{body}</svg>"""


def test_json_and_svg_files_through_the_command(sols, tmp_path, capsys):
    sol = sols[WE3.name][0]
    k = 0.5                                      # 1 mm = 0.5 m/s
    V = sol.vertices["velocity"]
    js = {"diagram": "velocity", "scale": "1 mm = 0.5 m/s",
          "vertices": {("o" if n == "a" else n): [p[0] / k + 150, p[1] / k + 150]
                       for n, p in V.items()},
          "vectors": [["o", "b"], ["b", "c"], ["o", "c"]]}
    path = tmp_path / "we3.json"
    path.write_text(json.dumps(js), encoding="utf-8")
    assert main(["check", str(WE3), "--drawing", str(path)]) == 0
    out = capsys.readouterr().out
    assert "3 of 3 vectors — all right" in out
    body = "".join(f'<circle data-vertex="{n}" cx="{x}" cy="{300 - y}" r="0.8"/>\n'
                   for n, (x, y) in js["vertices"].items())
    body += "".join(f'<line data-from="{a}" data-to="{b}"/>\n' for a, b in js["vectors"])
    svg = tmp_path / "we3.svg"
    svg.write_text(SVG.format(scale="1 cm = 5 m/s", body=body), encoding="utf-8")
    d_svg, d_json = read_drawing(str(svg)), read_drawing(str(path))
    assert d_svg.scale == pytest.approx(d_json.scale)
    for n in d_json.vertices:        # y down in SVG: the same shape, mirrored back
        dx = d_svg.vertices[n][0] - d_json.vertices[n][0]
        dy = d_svg.vertices[n][1] + 300 - d_json.vertices[n][1]
        assert abs(dx) < 1e-9 and abs(dy) < 1e-9
    assert main(["check", str(WE3), "--drawing", str(svg), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["all_ok"] and report["score"] == 3
    # a wrong drawing: exit 3 and the hint names the step
    js["vertices"]["c"][0] += 8
    path.write_text(json.dumps(js), encoding="utf-8")
    assert main(["check", str(WE3), "--drawing", str(path)]) == 3
    assert "hint:" in capsys.readouterr().out


@pytest.mark.parametrize("text,words", [
    ("{", "not valid JSON"),
    ('{"diagram": "force", "scale": 1, "vertices": {}, "vectors": []}', "diagram must be"),
    ('{"diagram": "velocity", "scale": "fast", "vertices": {}, "vectors": []}', "scale"),
    ('{"diagram": "velocity", "scale": -1, "vertices": {}, "vectors": []}', "positive"),
    ('{"diagram": "velocity", "scale": 1, "vertices": {"a": [1e300, 0]}, "vectors": []}',
     "coordinate"),
    ('{"diagram": "velocity", "scale": 1, "vertices": {"a": [0, 0]}, "vectors": [["a", "z"]]}',
     "not among"),
    ('{"diagram": "velocity", "scale": 1, "vertices": {"<b>": [0, 0]}, "vectors": []}',
     "vertex name"),
    ('<?xml version="1.0"?><!DOCTYPE x [<!ENTITY a "aaaa">]><svg/>', "DOCTYPE"),
    ('<svg xmlns="http://www.w3.org/2000/svg"/>', "not a polygons drawing"),
])
def test_bad_drawing_files_are_one_line_errors(tmp_path, capsys, text, words):
    path = tmp_path / "bad.json"
    path.write_text(text, encoding="utf-8")
    assert main(["check", str(WE3), "--drawing", str(path)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err and "polygons: error:" in err


def test_too_many_vertices_is_refused():
    data = {"diagram": "velocity", "scale": 1,
            "vertices": {f"v{i}": [0, 0] for i in range(201)}, "vectors": []}
    with pytest.raises(DrawingError, match="at most 200"):
        parse_json(json.dumps(data))
    with pytest.raises(DrawingError):
        parse_svg('<svg data-polygons-drawing="velocity" data-scale="1">'
                  + "".join(f'<circle data-vertex="v{i}" cx="0" cy="0"/>' for i in range(202))
                  + "</svg>")


# ---------------------------------------------------------------- the corpus of typical errors
from drawing_corpus import CORPUS, DRAWINGS, case_of, check, solved   # noqa: E402


@pytest.mark.parametrize("name", sorted(CORPUS))
def test_corpus_of_typical_errors(name):
    """Each typical slip (tests/data/drawings/corpus.toml) gets its marks and its feedback: one
    slip costs its own mark only, later steps graded on the student's own vertices."""
    from polygons.cli._drawing import grade_json
    sol, em, st = solved(case_of(name))
    g = grade(sol, read_drawing(str(DRAWINGS / CORPUS[name]["file"])), em, st)
    check(name, grade_json(g))


def test_corpus_is_large_and_varied():
    assert len(CORPUS) >= 20
    files = [c["file"] for c in CORPUS.values()]
    assert any(f.endswith(".svg") for f in files) and any(f.endswith(".json") for f in files)
    assert {p.name for p in DRAWINGS.glob("*.json")} | {p.name for p in DRAWINGS.glob("*.svg")} \
        == set(files)


def test_mangled_drawings_grade_without_error():
    """Random slips of every kind at once: always a grade, marks 0, ½ or 1, no error."""
    from drawing_corpus import mangled
    for name, d in mangled(150):
        sol, em, st = solved(case_of(name))
        g = grade(sol, d, em, st)
        assert all(m.mark in (0.0, 0.5, 1.0) for m in g.marks) and 0 <= g.score <= g.out_of


def _replay():
    import importlib.util
    spec = importlib.util.spec_from_file_location("make_corpus", DRAWINGS / "make_corpus.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.replay


@pytest.mark.parametrize("diagram", ["velocity", "acceleration"])
def test_an_image_vertex_is_carried_forward(diagram):
    """A coupler point found by its image (bce similar to BCE): with the crank's vector drawn
    0.955× (ω = N/10), b and c move and e with them; e is graded on the student's own b and c,
    so the slip costs the crank's vector only."""
    sol, em, st = solved(CASES / "forces-actuator-four-bar.toml")
    steps = [s for s in sol.steps if s.diagram == diagram]
    assert any(s.kind == "image" for s in steps)
    first = next(s for s in steps if s.kind == "vector")
    k = _scale(sol, diagram)
    mods = {first.number: {"scale": 3 / math.pi}}
    if diagram == "acceleration":       # every known acceleration vector scales with ω²
        mods = {s.number: {"scale": (3 / math.pi) ** 2} for s in steps if s.kind == "vector"}
    P = _replay()(sol, diagram, mods)
    g = grade(sol, _drawing(sol, diagram, P, k), em, st)
    images = [m for m in g.marks if next(s for s in steps if s.number == m.step).kind == "image"]
    assert images and all(m.mark == 1 and m.problem == "" for m in images)
    assert g.score == g.out_of - 0.5, [(m.name, m.mark, m.problem) for m in g.marks]
    truth = grade(sol, _drawing(sol, diagram, sol.vertices[diagram], k, 7), em, st)
    assert truth.ok
