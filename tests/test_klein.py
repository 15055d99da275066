"""Klein's and Ritterhaus's constructions (polygons.classic.klein, diagrams.klein): the
numbers read off the figure equal the closed-form loop solution (tests/analytic_klein.py) to
1e-9 and the polygons' to 1e-9; the refusals are one line; the drawings carry every stage."""
import json
import math
import random
import subprocess
import sys
from pathlib import Path

import pytest

from analytic_klein import slider_crank
from polygons.classic import klein
from polygons.errors import PolygonsError
from polygons.evaluate import solve
from polygons.scene import load_scene, parse_scene as _parse, parse_toml


def parse_scene(text, file):
    return _parse(parse_toml(text, file), file=file)

ROOT = Path(__file__).resolve().parents[1]
CASES = {"klein-inline-engine": (0.2, 0.7, math.radians(-30), -120.0, 0.0),
         "klein-offset-engine": (0.06, 0.24, math.radians(40), 150.0, 0.02)}


def _scene(r, L, theta, omega, e, side="right", extra=""):
    return f"""
title = "t"
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "{r * 1000!r} mm"
AB = "{L * 1000!r} mm"
[driver]
crank = "OA"
angle = "{math.degrees(theta)!r} deg"
omega = "{abs(omega)!r} rad/s"
sense = "{'CCW' if omega > 0 else 'CW'}"
[sliders.B]
through = ["0 mm", "{e * 1000!r} mm"]
direction = "0 deg"
[assembly]
B = "B {side} of A"
{extra}"""


def _close(fig, exact):
    for mine, key in ((fig.v_piston, "v_B"), (fig.a_piston, "a_B"),
                      (fig.omega_rod, "omega_rod"), (fig.alpha_rod, "alpha_rod")):
        ref = exact[key]
        assert abs(mine - ref) <= 1e-9 * max(abs(ref), 1.0), (key, mine, ref)


@pytest.mark.parametrize("case", sorted(CASES))
def test_cases_against_the_loop_closure(case):
    sol = solve(load_scene(ROOT / "cases" / f"{case}.toml"))
    fig = klein.figure(sol, "klein")
    _close(fig, slider_crank(*CASES[case]))
    assert fig.difference < 1e-9
    assert fig.inline == (CASES[case][4] == 0.0)


def test_random_engines_both_methods():
    rng = random.Random(23)
    for _ in range(40):
        r = rng.uniform(0.02, 0.2)
        L = r * rng.uniform(2.5, 6.0)
        e = 0.0 if rng.random() < 0.5 else rng.uniform(-0.5, 0.5) * r
        theta = rng.uniform(-math.pi, math.pi)
        if abs(math.sin(theta)) < 0.05:          # Ritterhaus's K is undefined at a dead centre
            theta += 0.3
        omega = rng.choice((-1, 1)) * rng.uniform(5, 300)
        sol = solve(parse_scene(_scene(r, L, theta, omega, e), "rand.toml"))
        exact = slider_crank(r, L, theta, omega, e)
        _close(klein.figure(sol, "klein"), exact)
        if e == 0.0:
            _close(klein.figure(sol, "ritterhaus"), exact)
            _close(klein.figure(sol, "bennett"), exact)
            # Bennett's Q is Klein's Q too (AQ = AM²/AB from AL = OA²/AB)
            q3 = klein.figure(sol, "bennett").points["Q"]
            assert math.dist(klein.figure(sol, "klein").points["Q"], q3) < 1e-12 * L * 100
            # Ritterhaus's Q is Klein's Q (the similar triangles)
            q1 = klein.figure(sol, "klein").points["Q"]
            q2 = klein.figure(sol, "ritterhaus").points["Q"]
            assert math.dist(q1, q2) < 1e-12 * L * 100


def test_klein_circles_cut_on_the_chord_through_q():
    sol = solve(load_scene(ROOT / "cases" / "klein-offset-engine.toml"))
    f = klein.figure(sol)
    (c1, r1), (c2, r2) = f.klein_circle, f.rod_circle
    for p in ("K", "L"):
        assert abs(math.dist(f.points[p], c1) - r1) < 1e-12
        assert abs(math.dist(f.points[p], c2) - r2) < 1e-12
    A, B, Q, N = (f.points[k] for k in "ABQN")
    assert abs((N[0] - Q[0]) * (B[0] - A[0]) + (N[1] - Q[1]) * (B[1] - A[1])) < 1e-15


@pytest.mark.parametrize("text,method,words", [
    (_scene(0.05, 0.2, 0.5, 10.0, 0.01), "ritterhaus", "in-line engine"),
    (_scene(0.05, 0.2, 0.5, 10.0, 0.0).replace(
        'sense = "CCW"', 'sense = "CCW"\nalpha = "3 rad/s^2"\nalpha_sense = "CCW"'), "klein",
     "turning uniformly"),
    (_scene(0.05, 0.2, 0.5, 0.0, 0.0).replace('sense = "CW"', ''), "klein", "at rest"),
    (_scene(0.05, 0.2, 0.0, 10.0, 0.0), "ritterhaus", "parallel"),
    (_scene(0.05, 0.2, 0.5, 10.0, -0.01), "bennett", "in-line engine"),
    (_scene(0.05, 0.2, 0.5, 10.0, 0.0).replace(
        'sense = "CCW"', 'sense = "CCW"\nalpha = "3 rad/s^2"\nalpha_sense = "CW"'), "bennett",
     "turning uniformly"),
])
def test_refusals(text, method, words):
    sol = solve(parse_scene(text, "x.toml"))
    with pytest.raises(PolygonsError) as exc:
        klein.figure(sol, method)
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_bennett_on_the_inline_case_and_at_the_dead_centres():
    """Bennett's construction on the shipped in-line engine equals the loop closure; its L₁ is
    the foot of the perpendicular from O on the rod at right angles (A₁L₁ = r²/l), AL = A₁L₁,
    K lies on the line of stroke, and at a dead centre (where Ritterhaus's K is undefined)
    Bennett's still closes."""
    sol = solve(load_scene(ROOT / "cases" / "klein-inline-engine.toml"))
    f = klein.figure(sol, "bennett")
    _close(f, slider_crank(*CASES["klein-inline-engine"]))
    p = f.points
    r, L = math.dist(p["O"], p["A"]), math.dist(p["A"], p["B"])
    assert abs(math.dist(p["A1"], p["L1"]) - r * r / L) < 1e-12
    assert abs(math.dist(p["A"], p["L"]) - r * r / L) < 1e-12
    assert abs(p["K"][1]) < 1e-12 and abs(p["N"][1]) < 1e-12      # on the line of stroke
    assert f.names["A1"] == "C1" and f.names["B1"] == "P1" and f.names["L1"] == "L1"
    text = "\n".join(klein.report_lines(f))
    assert "Bennett's construction" in text and "C1L1 = 57.1429 mm" in text
    for theta in (0.0, math.pi):
        sol = solve(parse_scene(_scene(0.05, 0.2, theta, 40.0, 0.0), "dc.toml"))
        _close(klein.figure(sol, "bennett"), slider_crank(0.05, 0.2, theta, 40.0))


def test_bennett_drawn_stage_by_stage(tmp_path):
    from polygons.cli import main
    case = str(ROOT / "cases" / "klein-inline-engine.toml")
    assert main(["solve", case, "--klein", "bennett", "--svg", str(tmp_path)]) == 0
    names = sorted(p.name for p in tmp_path.glob("bennett*.svg"))
    assert names == ["bennett-1.svg", "bennett-2.svg", "bennett-3.svg", "bennett-4.svg",
                     "bennett.svg"]
    svg = (tmp_path / "bennett.svg").read_text()
    for cls in ("crank-right-angle", "rod-right-angle", "perpendicular-OL1",
                "perpendicular-LK", "perpendicular-KQ", "an-BA", "at-BA", "a-B"):
        assert cls in svg, cls
    assert "perpendicular-LK" not in (tmp_path / "bennett-2.svg").read_text()
    s = parse_scene(_scene(0.05, 0.2, 0.5, 10.0, 0.0, extra='[diagram]\nklein = "bennett"\n'),
                    "x.toml")
    assert s.options.diagram.klein == "bennett"


def test_not_a_slider_crank_is_refused_in_one_line():
    from conftest import cli
    r = cli("solve", ROOT / "cases" / "s001-we3.toml", "--klein")
    assert r.returncode == 1
    assert r.stderr.count("\n") == 1 and "slider-crank" in r.stderr


def test_option_checked_at_load():
    with pytest.raises(PolygonsError, match="klein must be"):
        parse_scene(_scene(0.05, 0.2, 0.5, 10.0, 0.0, extra='[diagram]\nklein = "bennet"\n'),
                    "x.toml")
    s = parse_scene(_scene(0.05, 0.2, 0.5, 10.0, 0.0, extra='[diagram]\nklein = true\n'),
                    "x.toml")
    assert s.options.diagram.klein == "klein"


def test_cli_json_and_drawings(tmp_path):
    from polygons.cli import main
    case = str(ROOT / "cases" / "klein-offset-engine.toml")
    out = tmp_path / "k.json"
    assert main(["solve", case, "--json", "-o", str(out), "--svg", str(tmp_path / "d")]) == 0
    data = json.loads(out.read_text())["klein"]
    assert data["method"] == "klein" and not data["inline"]
    assert data["max_relative_difference"] < 1e-9
    names = sorted(p.name for p in (tmp_path / "d").glob("klein*.svg"))
    assert names == ["klein-1.svg", "klein-2.svg", "klein-3.svg", "klein-4.svg", "klein.svg"]
    svg = (tmp_path / "d" / "klein.svg").read_text()
    for cls in ("klein-circle", "rod-circle", "chord", "an-BA", "at-BA", "a-B"):
        assert f'class="{cls}' in svg or f"{cls}" in svg


def test_labels_do_not_overlap():
    import diagrams.klein as dk
    from diagrams.labels import text_box
    from diagrams.model import Text
    for case in CASES:
        sol = solve(load_scene(ROOT / "cases" / f"{case}.toml"))
        for method in ("klein", "ritterhaus", "bennett") if "inline" in case else ("klein",):
            d = dk.drawing(sol, klein.figure(sol, method))
            boxes = [text_box(t.x, t.baseline, t.text, t.size, t.anchor)
                     for t in d.items() if isinstance(t, Text) and t.role == "point"]
            for i, a in enumerate(boxes):
                for b in boxes[i + 1:]:
                    assert not a.overlaps(b)


def test_handout_carries_the_construction_and_the_equivalent_linkage(tmp_path):
    from polygons.cli.handout import build
    html = build(str(ROOT / "cases" / "klein-offset-engine.toml"))
    assert 'id="klein"' in html and "Klein circle" in html
    assert html.index('id="klein"') < html.index("</body>")
    html = build(str(ROOT / "cases" / "curved-slot-pin.toml"))
    assert 'id="equivalent"' in html and "equivalent link KP" in html
    assert 'id="klein"' not in build(str(ROOT / "cases" / "s001-we3.toml"))
