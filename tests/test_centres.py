"""Instant centres (Kennedy), velocities by the centres, rubbing and least velocities.

The centres use only the positions, the topology and the driver's input; the velocity polygon
(``Solution.points[...].velocity``, ``Solution.links[...].omega``) is an independent method, so
agreement to 1e-9 relative is a real cross-check.  Closed forms (line intersections written out
here with plain trigonometry) check the centres themselves and the textbook case.
"""
import json
import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import analytic
from conftest import ROOT, case_files
from polygons.errors import BranchError, UnsupportedError
from scenes import crank_driver, slider_crank_case
from polygons.errors import ParallelLinesError
from polygons.centres import instant_centres
from polygons.errors import SceneError
from polygons.evaluate import solve
from polygons.pins import least_velocity, report_lines, rubbing_velocities
from polygons.scene import load_scene, parse_scene

REL = 1e-12
FILES = case_files()
IDS = [f.stem for f in FILES]


@pytest.fixture(scope="module")
def solved():
    cache = {}

    def get(path):
        if path not in cache:
            sol = solve(load_scene(path))
            cache[path] = (sol, instant_centres(sol))
        return cache[path]
    return get


def _scale(sol):
    return max([math.hypot(*p.velocity) for p in sol.points.values()] + [1e-300])


def test_every_shipped_case_is_handled():
    """Every kind of body and pair of the shipped cases: four-bars, slider-cranks, slotted
    levers, offset slots, slots on moving levers, oscillating cylinders, the Scotch yoke, the
    double slider and the collar of a prescribed slide (two inputs): all n(n − 1)/2 centres."""
    kinds, sizes = set(), set()
    for path in FILES:
        sol = solve(load_scene(path))
        cs = instant_centres(sol)
        n = len(cs.bodies)
        assert len(cs.centres) == n * (n - 1) // 2 and cs.complete, path.name
        kinds |= {b.kind for b in cs.bodies}
        sizes.add(n)
    assert sizes >= {2, 3, 4, 6}          # up to the six-bars (Watt, Stephenson, Whitworth)
    from polygons.model import BODY_KINDS
    assert kinds == set(BODY_KINDS)          # every kind of body the model builds


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_velocities_by_centres_agree_with_the_polygon(path, solved):
    sol, cs = solved(path)
    vs = _scale(sol)
    assert set(cs.velocities) == set(sol.points)
    for label, pv in cs.velocities.items():
        v = sol.points[label].velocity
        assert math.dist(pv.velocity, v) <= REL * vs, (label, pv.velocity, v)
    ws = max([abs(lr.omega) for lr in sol.links.values()] + [1e-300])
    for name, lr in sol.links.items():
        assert abs(cs.omega(name) - lr.omega) <= REL * ws, name
    # a slider block translates: ω = 0 and its velocity is the slider's
    for b in cs.bodies:
        if b.kind == "block":
            o = next(o for o in cs.omegas if o.number == b.number)
            assert o.omega == 0.0
            label = b.name.split()[1]
            assert math.dist(o.velocity, sol.points[label].velocity) <= REL * vs


def _collinear(c1, c2, c3, size):
    """Kennedy: the three centres of three links on one line (directions at infinity too)."""
    fin = [c.point for c in (c1, c2, c3) if c.point is not None]
    inf = [c.direction for c in (c1, c2, c3) if c.point is None]
    if len(fin) == 3:
        (ax, ay), (bx, by), (cx, cy) = fin
        area = abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
        span = max(math.dist(fin[0], fin[1]), math.dist(fin[0], fin[2]),
                   math.dist(fin[1], fin[2]), size)
        return area <= 1e-9 * span * span
    if len(fin) == 2 and len(inf) == 1:
        d = (fin[1][0] - fin[0][0], fin[1][1] - fin[0][1])
        n = math.hypot(*d)
        return n <= 1e-9 * size or abs(d[0] * inf[0][1] - d[1] * inf[0][0]) <= 1e-9 * n
    return True          # two or three at infinity: the line at infinity


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_kennedy_three_centres_on_a_line(path, solved):
    sol, cs = solved(path)
    n = len(cs.bodies)
    for i in range(1, n + 1):
        for j in range(i + 1, n + 1):
            for k in range(j + 1, n + 1):
                assert _collinear(cs.centre(i, j), cs.centre(j, k), cs.centre(i, k), cs.size), \
                    (i, j, k)


def _meet(p, u, q, v):
    """Intersection of p + s u and q + t v (Cramer)."""
    det = u[0] * (-v[1]) - u[1] * (-v[0])
    s = ((q[0] - p[0]) * (-v[1]) - (q[1] - p[1]) * (-v[0])) / det
    return (p[0] + s * u[0], p[1] + s * u[1])


def test_four_bar_centres_by_hand():
    """I13 = AB × DC and I24 = AD × BC for worked example 6 (A, B, C, D from the polygon-free
    placement), written out independently of polygons.centres."""
    sol = solve(load_scene(ROOT / "cases/s001-we6.toml"))
    cs = instant_centres(sol)
    P = sol.placement.points
    A, B, C, D = (P[k] for k in "ABCD")
    sub = lambda a, b: (b[0] - a[0], b[1] - a[1])  # noqa: E731
    i13 = _meet(A, sub(A, B), D, sub(D, C))
    i24 = _meet(A, sub(A, D), B, sub(B, C))
    assert [b.name for b in cs.bodies] == ["frame", "AB", "BC", "CD"]
    assert cs.centre(1, 3).point == pytest.approx(i13, rel=1e-12, abs=1e-12)
    assert cs.centre(2, 4).point == pytest.approx(i24, rel=1e-12, abs=1e-12)
    assert cs.centre(1, 3).how == "Kennedy: 13 on 12–23 and 14–43"
    assert cs.centre(1, 2).how.startswith("pin") and cs.centre(1, 2).primary
    # ω4 = ω2 · I12I24 / I14I24 (the textbook ratio), signs from the sides of I24
    w2 = sol.scene.driver.omega
    ratio = (i24[0] - A[0]) / (i24[0] - D[0])        # I24 on the line AD (the x axis)
    assert cs.omega("CD") == pytest.approx(w2 * ratio, rel=1e-12)


def test_slider_crank_centres_by_hand():
    """Worked example 4: I14 at infinity ⟂ the guide; I13 on the crank line produced and on
    the normal to the guide at C; I24 on the normal to the guide at A and on the rod line."""
    sol = solve(load_scene(ROOT / "cases/s001-we4.toml"))
    cs = instant_centres(sol)
    P = sol.placement.points
    A, B, C = P["A"], P["B"], P["C"]
    i14 = cs.centre(1, 4)
    assert i14.point is None and i14.how == "slider C on its guide: at infinity ⟂ the guide"
    assert abs(i14.direction[0]) < 1e-15 and abs(i14.direction[1]) == 1.0
    i13 = _meet(A, (B[0] - A[0], B[1] - A[1]), C, (0.0, 1.0))
    i24 = _meet(A, (0.0, 1.0), B, (C[0] - B[0], C[1] - B[1]))
    assert cs.centre(1, 3).point == pytest.approx(i13, abs=1e-15)
    assert cs.centre(2, 4).point == pytest.approx(i24, abs=1e-15)
    # piston speed = ω2 × I12I24 (the textbook result) against the polygon
    v = abs(sol.scene.driver.omega) * math.dist(A, i24)
    assert v == pytest.approx(math.hypot(*sol.points["C"].velocity), rel=1e-12)


def test_slotted_lever_centre_on_the_common_normal():
    """Figure 7, numbered as the tutorial: 2 the crank, 3 the block on P2, 4 the slotted link.
    I34 is at infinity ⟂ the slot, so I24 lies on O2O4 and on the normal to the slot at P2
    (the line through I23 = P2 and I34); I13 on the crank line and the normal through O4."""
    sol = solve(load_scene(ROOT / "cases/s003-fig7.toml"))
    cs = instant_centres(sol)
    assert [b.name for b in cs.bodies] == ["frame", "O2P2", "block P2", "O4P4"]
    P = sol.placement.points
    e = (P["P2"][0] - P["O4"][0], P["P2"][1] - P["O4"][1])
    i24 = _meet(P["O4"], (P["O2"][0] - P["O4"][0], P["O2"][1] - P["O4"][1]),
                P["P2"], (-e[1], e[0]))
    c = cs.centre(2, 4)
    assert c.point == pytest.approx(i24, abs=1e-15)
    assert c.how == "Kennedy: 24 on 21–14 and 23–34"
    assert not c.primary and c.lines == (("I12", "I14"), ("I23", "I34"))
    i34 = cs.centre(3, 4)
    assert i34.primary and i34.point is None
    assert abs(i34.direction[0] * e[0] + i34.direction[1] * e[1]) < 1e-15 * math.hypot(*e)
    i13 = _meet(P["O2"], (P["P2"][0] - P["O2"][0], P["P2"][1] - P["O2"][1]),
                P["O4"], (-e[1], e[0]))
    assert cs.centre(1, 3).point == pytest.approx(i13, abs=1e-15)
    assert cs.omega("block P2") == cs.omega("O4P4") == pytest.approx(
        sol.links["O4P4"].omega, rel=1e-12)


SLIDER_DRIVEN = {
    "ground": {"A": ["0 mm", "0 mm"]},
    "links": {"AB": "60 mm", "BC": "150 mm"},
    "driver": {"slider": "C", "position": "180 mm", "velocity": "2 m/s"},
    "sliders": {"C": {"through": ["0 mm", "0 mm"], "direction": "0 deg"}},
    "assembly": {"B": "B above AC"},
}


def test_slider_driven_mechanism():
    """Driver = the slider (link 2 translates): ω of crank and rod from the centres."""
    sol = solve(parse_scene(SLIDER_DRIVEN))
    cs = instant_centres(sol)
    assert cs.bodies[1].name == "slider C"
    vs = _scale(sol)
    for label, pv in cs.velocities.items():
        assert math.dist(pv.velocity, sol.points[label].velocity) <= REL * vs
    for name, lr in sol.links.items():
        assert cs.omega(name) == pytest.approx(lr.omega, rel=REL)


def test_parallelogram_centres_at_infinity():
    """A parallelogram four-bar: AB ∥ DC puts I13 at infinity (the coupler translates, ω3 = 0)
    and BC ∥ AD puts I24 at infinity (ω4 = ω2)."""
    scene = parse_scene({
        "ground": {"A": ["0 mm", "0 mm"], "D": ["100 mm", "0 mm"]},
        "links": {"AB": "40 mm", "BC": "100 mm", "DC": "40 mm"},
        "driver": {"crank": "AB", "angle": "60 deg", "omega": "10 rad/s", "sense": "CCW"},
        "assembly": {"C": "C above AD"},
    })
    sol = solve(scene)
    cs = instant_centres(sol)
    assert cs.centre(1, 3).point is None and cs.centre(2, 4).point is None
    assert "parallel" in cs.centre(1, 3).how
    assert cs.omega("BC") == 0.0
    assert cs.omega("DC") == pytest.approx(10.0, rel=1e-12)
    for label, pv in cs.velocities.items():
        assert math.dist(pv.velocity, sol.points[label].velocity) <= REL * _scale(sol)


# ---------------------------------------------------------------- least velocity
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_least_velocity_is_the_point_nearest_the_instant_centre(path, solved):
    """Polygon: the foot of the perpendicular from o to the image ab.  Centres: the point of
    the link line nearest I_1j, moving at |ω|·distance.  Two methods, one point."""
    sol, cs = solved(path)
    vs = _scale(sol)
    for name, lr in sol.links.items():
        c = cs.centre(1, cs.body(name).number)
        if c.point is None or lr.omega == 0:
            continue
        lv = least_velocity(sol, name)
        A, B = sol.points[lr.a].position, sol.points[lr.b].position
        u = ((B[0] - A[0]) / math.dist(A, B), (B[1] - A[1]) / math.dist(A, B))
        s = (c.point[0] - A[0]) * u[0] + (c.point[1] - A[1]) * u[1]
        dist = abs((c.point[0] - A[0]) * u[1] - (c.point[1] - A[1]) * u[0])
        assert lv.along == pytest.approx(s, rel=1e-9, abs=1e-9 * cs.size), name
        if lv.on_link:
            assert lv.speed == pytest.approx(abs(lr.omega) * dist, rel=1e-9, abs=1e-9 * vs)


# ---------------------------------------------------------------- the textbook case
def _khurmi_closed_form():
    """Khurmi Ex 7.2 by hand: crank 0.5 m at 135°, 180 rpm CW; rod 2 m; piston on the line of
    stroke through O (to the left); pins of 50, 60 and 30 mm; E 1.5 m from P."""
    r, l, w = 0.5, 2.0, -180 * 2 * math.pi / 60
    th = math.radians(135)
    B = (r * math.cos(th), r * math.sin(th))
    phi = math.asin(B[1] / l)                      # rod angle below the line of stroke
    Px = B[0] - l * math.cos(phi)
    vB = (-w * B[1], w * B[0])
    d = (Px - B[0], -B[1])
    w3 = -vB[1] / d[0]                             # v_P has no y-component
    vP = vB[0] - w3 * d[1]
    E = (B[0] + 0.25 * d[0], B[1] + 0.25 * d[1])
    vE = math.hypot(vB[0] - w3 * (E[1] - B[1]), vB[1] + w3 * (E[0] - B[0]))
    I13 = (Px, Px * math.tan(th))                  # crank line produced × normal at P
    u = (d[0] / l, d[1] / l)
    BG = (I13[0] - B[0]) * u[0] + (I13[1] - B[1]) * u[1]
    vG = abs(w3) * abs((I13[0] - B[0]) * u[1] - (I13[1] - B[1]) * u[0])
    return {"v(P)": abs(vP), "omega(BP)": w3, "v(E)": vE,
            "rub(O)": abs(w) * 0.025, "rub(B)": abs(w - w3) * 0.030, "rub(P)": abs(w3) * 0.015,
            "least(BP)": vG, "least_at(BP)": BG}


def test_khurmi_exact_answers_are_the_closed_form_and_ours():
    from polygons.pins import check_answers as pin_checks
    from polygons.report import check_answers
    path = ROOT / "cases/khurmi-ex7.2.toml"
    sol = solve(load_scene(path))
    exact = _khurmi_closed_form()
    checks = [(c.answer, c.compared) for c in check_answers(sol)] + pin_checks(sol)
    assert {a.quantity for a, _ in checks} == set(exact)
    for a, ours in checks:
        value = exact[a.quantity]
        assert a.exact == pytest.approx(abs(value) if a.mode == "abs" else value, rel=1e-12)
        assert ours == pytest.approx(a.exact, rel=1e-9), a.quantity
        if a.tutorial is not None:                 # the book, within its drawing tolerance
            assert abs(ours - a.tutorial) <= a.tolerance * max(abs(ours), abs(a.tutorial)), \
                a.quantity
    rubs = {r.pin: r for r in rubbing_velocities(sol)}
    assert rubs["B"].opposite and not rubs["P"].opposite      # crank CW, rod CCW
    assert rubs["O"].links == ("frame", "OB")
    assert rubs["P"].links == ("BP", "slider P")


def test_rubbing_formula_same_and_opposite_senses():
    """Same senses: (ω₁ − ω₂)·r; opposite: (ω₁ + ω₂)·r in magnitudes."""
    scene = parse_scene({**SLIDER_DRIVEN, "pins": {"B": {"diameter": "20 mm"}}},
                        file="t.toml")
    sol = solve(scene)
    (r,) = rubbing_velocities(sol)
    w1, w2 = sol.links["AB"].omega, sol.links["BC"].omega
    expect = (abs(w1) + abs(w2) if w1 * w2 < 0 else abs(abs(w1) - abs(w2))) * 0.010
    assert r.velocity == pytest.approx(expect, rel=1e-12)


@pytest.mark.parametrize("tables, where", [
    ({"pins": {"Q": {"diameter": "20 mm"}}}, "[pins.Q]"),
    ({"pins": {"B": {"diameter": "-2 mm"}}}, "[pins.B.diameter]"),
    ({"pins": {"B": {"diam": "2 mm"}}}, "[pins.B.diam]"),
    ({"pins": {"B": {"diameter": "2"}}}, "[pins.B.diameter]"),
    ({"least_velocity": {"links": ["XY"]}}, "[least_velocity.links]"),
    ({"pin_answers": [{"quantity": "rub(B)", "unit": "m/s"}]}, "[pin_answers[0].quantity]"),
])
def test_bad_pin_tables_are_one_line_errors(tables, where):
    from polygons.pins import spec
    scene = parse_scene({**SLIDER_DRIVEN, **tables}, file="t.toml")
    with pytest.raises(SceneError) as err:
        spec(scene)
    assert where in str(err.value) and "\n" not in str(err.value)


@pytest.mark.parametrize("form", ["BC", ["BC"], {"links": ["BC"]}, {"links": "BC"}])
def test_least_velocity_key_forms(form):
    from polygons.pins import spec
    scene = parse_scene({**SLIDER_DRIVEN, "least_velocity": form}, file="t.toml")
    assert spec(scene).least == ("BC",)


def test_report_lines_only_with_the_tables():
    assert report_lines(solve(parse_scene(SLIDER_DRIVEN))) == []
    lines = report_lines(solve(load_scene(ROOT / "cases/khurmi-ex7.2.toml")))
    assert any(ln.startswith("least velocity on BP") for ln in lines)
    assert sum(ln.startswith("  pin ") for ln in lines) == 3


# ---------------------------------------------------------------- command and drawing
def _run(*args):
    """``polygons ARGS`` in this process (conftest.cli: the entry point function)."""
    from conftest import cli
    return cli(*args, cwd=ROOT)


def test_centres_command_table_json_and_svg(tmp_path):
    out = _run("centres", "cases/khurmi-ex7.2.toml", "-o", tmp_path)
    assert out.returncode == 0, out.stderr
    assert "I13" in out.stdout and "Kennedy: 13 on 12–23 and 14–43" in out.stdout
    assert "rubbing velocities" in out.stdout and "least velocity on BP" in out.stdout
    svg1 = (tmp_path / "centres.svg").read_bytes()
    js = _run("centres", "cases/khurmi-ex7.2.toml", "--json")
    data = json.loads(js.stdout)
    assert [c["label"] for c in data["centres"]] == ["I12", "I13", "I14", "I23", "I24", "I34"]
    assert data["centres"][2]["point"] is None and data["centres"][2]["direction"] == [0.0, 1.0]
    assert data["pins"]["least_velocity"]["BP"]["speed"] == pytest.approx(7.737465102290866)
    again = _run("centres", "cases/khurmi-ex7.2.toml", "-o", tmp_path / "b")
    assert again.returncode == 0 and again.stdout.replace("/b/", "/") == out.stdout
    assert (tmp_path / "b" / "centres.svg").read_bytes() == svg1       # deterministic


def test_centres_command_errors_are_one_line(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text((ROOT / "cases/s001-we4.toml").read_text() + '\n[pins.Z]\ndiameter = "5 mm"\n')
    for args in (("centres", bad), ("centres", "cases/s001-we4.toml", "--points", "Q")):
        out = _run(*args)
        assert out.returncode == 1 and out.stderr.startswith("polygons: error: ")
        assert out.stderr.count("\n") == 1 and "Traceback" not in out.stderr


def test_centres_drawing_marks_every_centre_and_the_circle_diagram():
    from diagrams.centres import centres_figure
    sol = solve(load_scene(ROOT / "cases/khurmi-ex7.2.toml"))
    cs = instant_centres(sol)
    svg = centres_figure(sol)
    assert svg.startswith("<?xml")
    from diagrams.centres import label_of
    for c in cs.centres:
        assert label_of(c) in svg, c.label
    assert "I₁₄ → ∞" in svg                      # the slider's centre, by a direction arrow
    known = sum(c.primary for c in cs.centres)
    assert svg.count("chord known") == known == 4
    assert svg.count("chord found") == len(cs.centres) - known == 2
    assert svg == centres_figure(sol)
    assert 'class="least-point BP"' in svg and "least v = 7.737 m/s" in svg


def test_six_link_mechanism_fifteen_centres():
    """A six-link mechanism with three links at one pin (crank OA, AB, lever CB, rod BD,
    slider D; the layout of Khurmi's Fig. 7.9): 15 centres, three of them at the pin B, the
    rest by Kennedy in textbook order, velocities equal to the polygon's."""
    sol = solve(parse_scene({
        "ground": {"O": ["0 mm", "0 mm"], "C": ["0 mm", "65 mm"]},
        "links": {"OA": "28 mm", "AB": "44 mm", "CB": "49 mm", "BD": "46 mm"},
        "driver": {"crank": "OA", "angle": "165 deg", "omega": "600 rev/min", "sense": "CW"},
        "sliders": {"D": {"through": ["0 mm", "54 mm"], "direction": "0 deg"}},
        "assembly": {"B": "B left of C", "D": "D right of B"},
    }))
    cs = instant_centres(sol)
    assert len(cs.centres) == 15
    at_b = [c.label for c in cs.centres if c.how == "pin B"]
    assert at_b == ["I34", "I35", "I45"]
    found = sorted((c for c in cs.centres if not c.primary), key=lambda c: c.order)
    assert [c.order for c in found] == list(range(1, len(found) + 1))
    assert all(len(c.lines) == 2 and c.how.startswith("Kennedy: ") for c in found)
    for label, pv in cs.velocities.items():
        assert math.dist(pv.velocity, sol.points[label].velocity) <= REL * _scale(sol)
    for name, lr in sol.links.items():
        assert cs.omega(name) == pytest.approx(lr.omega, rel=REL)
    n = len(cs.bodies)
    for i in range(1, n + 1):
        for j in range(i + 1, n + 1):
            for k in range(j + 1, n + 1):
                assert _collinear(cs.centre(i, j), cs.centre(j, k), cs.centre(i, k), cs.size)


def test_rubbing_at_a_slot_pin_uses_the_block_turning_with_the_lever():
    """Figure 7: the block on P2 turns with the slotted lever, so v_r = |ω2 − ω4|·r."""
    import tomllib
    data = tomllib.loads((ROOT / "cases/s003-fig7.toml").read_text(encoding="utf-8"))
    data["pins"] = {"P2": {"diameter": "20 mm"}}
    sol = solve(parse_scene(data, file="fig7-pins.toml"))
    (r,) = rubbing_velocities(sol)
    assert r.links == ("O2P2", "block at P2")
    w2, w4 = sol.scene.driver.omega, sol.links["O4P4"].omega
    assert r.velocity == pytest.approx(abs(w2 - w4) * 0.010, rel=1e-12)


# ---------------------------------------------------------------- random mechanisms
_hyp = settings(max_examples=120, deadline=None,
                suppress_health_check=[HealthCheck.filter_too_much])
_omegas = st.floats(0.5, 500.0) | st.floats(-500.0, -0.5)


def _well_conditioned(sol, cs):
    angles = [c.angle_deg for c in cs.centres if not c.primary]
    return sol.min_intersection_angle_deg > 1.0 and min(angles, default=90.0) > 1.0


@_hyp
@given(r=st.floats(0.01, 1.0), ratio=st.floats(1.2, 6.0), theta=st.floats(0, 2 * math.pi),
       omega=_omegas, line_dir=st.floats(0, 2 * math.pi), offset=st.floats(-0.8, 0.8),
       branch=st.sampled_from([1, -1]))
def test_random_slider_cranks_centres_match_the_closed_form(r, ratio, theta, omega, line_dir,
                                                           offset, branch):
    """Velocities by the centres against tests/analytic.py's loop solution (no polygon)."""
    scene, ref = slider_crank_case(r, ratio, theta, omega, 0.0, line_dir, offset, branch)
    sol = solve(scene)
    cs = instant_centres(sol)
    assume(_well_conditioned(sol, cs))
    assert math.dist(cs.velocities["B"].velocity, ref["vB"]) <= REL * abs(omega) * r
    assert abs(cs.omega("AB") - ref["omega_AB"]) <= REL * abs(omega) / ratio


@_hyp
@given(ad=st.floats(0.2, 1.0), ab=st.floats(0.01, 1.0), bc=st.floats(0.01, 1.0),
       cd=st.floats(0.01, 1.0), theta=st.floats(0, 2 * math.pi), omega=_omegas)
def test_random_four_bars_centres_match_the_closed_form(ad, ab, bc, cd, theta, omega):
    try:
        ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, 0.0, +1)
    except ValueError:
        assume(False)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [f"{ad!r} m", "0 m"]},
        "links": {"AB": f"{ab!r} m", "BC": f"{bc!r} m", "CD": f"{cd!r} m"},
        "driver": crank_driver("AB", theta, omega, 0.0),
        "assembly": {"C": "C above AD"},
    })
    try:
        sol = solve(scene)
    except (ParallelLinesError, BranchError):   # a closure on AD itself: the words cannot say
        assume(False)
    try:
        cs = instant_centres(sol)
    except UnsupportedError:      # lines of centres that do not meet: only at a toggle
        assume(not sol.min_intersection_angle_deg > 1.0)
        raise
    assume(_well_conditioned(sol, cs))
    vs = abs(omega) * ab
    assert math.dist(cs.velocities["C"].velocity, ref["vC"]) <= REL * vs
    for link in ("BC", "CD"):
        assert abs(cs.omega(link) - ref[f"omega_{link}"]) <= REL * vs / min(bc, cd)


# ---------------------------------------------------------------- every mechanism (issue 22)
def _double_slider_closed_form(L=0.1, a=0.06, va=1.0):
    """A on the x axis at a (moving at va), B on the y axis at b = √(L² − a²): ḃ from
    a ȧ + b ḃ = 0, ω of AB = (b ȧ − a ḃ)/L², the centre of AB where the normals to the guides
    at A and B meet: (a, b)."""
    b = math.sqrt(L * L - a * a)
    vb = -a * va / b
    w = (b * va - a * vb) / (L * L)
    ab = -(va * va + vb * vb) / b
    return {"I13": (a, b), "vB": vb, "omega": w, "vC": abs(w) * L / 2, "aB": ab, "b": b}


def test_double_slider_centre_of_the_bar_where_the_normals_meet():
    """The plain double slider (A on a horizontal guide, B on a vertical one, AB = 100 mm, A at
    60 mm, A driven): I13 = (60, 80) mm; the two blocks' centres with the frame at infinity ⟂
    their guides; I24 where the line at infinity (I12–I14) meets the finite line I23–I34: at
    infinity along AB.  The case's answers are the closed form's."""
    from polygons.report import check_answers
    path = ROOT / "cases/centres-double-slider.toml"
    sol = solve(load_scene(path))
    cs = instant_centres(sol)
    ref = _double_slider_closed_form()
    assert [b.name for b in cs.bodies] == ["frame", "slider A", "AB", "slider B"]
    assert cs.centre(1, 3).point == pytest.approx(ref["I13"], abs=1e-15)
    assert cs.centre(1, 2).direction == pytest.approx((0.0, 1.0), abs=1e-15)
    assert cs.centre(1, 4).direction == pytest.approx((1.0, 0.0), abs=1e-15)
    i24 = cs.centre(2, 4)
    assert i24.point is None and "line at infinity" in i24.how
    assert i24.direction == pytest.approx((0.6, -0.8), abs=1e-15)     # along AB, no sense
    assert cs.omega("AB") == pytest.approx(ref["omega"], rel=1e-12)
    assert cs.velocities["B"].velocity == pytest.approx((0.0, ref["vB"]), abs=1e-15)
    assert cs.velocities["C"].speed == pytest.approx(ref["vC"], rel=1e-12)
    assert cs.velocities["C"].how.startswith("v_C = ω₃ · I₁₃C = 12.5 × 0.05 = 0.625")
    exact = {"vs(B)": ref["vB"], "omega(AB)": ref["omega"], "v(C)": ref["vC"],
             "as(B)": ref["aB"], "dist(O,B)": ref["b"]}
    checks = check_answers(sol)
    assert {c.answer.quantity for c in checks} == set(exact)
    for c in checks:
        assert c.answer.exact == pytest.approx(exact[c.answer.quantity], rel=1e-12)
        assert c.ours == pytest.approx(c.answer.exact, rel=1e-12)


def test_two_inputs_centres_from_the_velocity_field():
    """The collar on a rotating rod (the collar's slide given: two inputs): the collar's
    centre I13 is its point of zero velocity, C + k × v_C / ω, said so; v_C = ω₃ · I₁₃C."""
    sol = solve(load_scene(ROOT / "cases/new-collar-on-rotating-rod.toml"))
    cs = instant_centres(sol)
    assert [b.kind for b in cs.bodies] == ["frame", "link", "collar"]
    c13 = cs.centre(1, 3)
    assert c13.by_field and "velocity field" in c13.how and "two inputs" in cs.note
    th, w, r, s = math.radians(30), 5.0, 0.4, 1.5          # closed form: C = r e, v = s e + ω r n
    e, n = (math.cos(th), math.sin(th)), (-math.sin(th), math.cos(th))
    v = (s * e[0] + w * r * n[0], s * e[1] + w * r * n[1])
    C = (r * e[0], r * e[1])
    assert c13.point == pytest.approx((C[0] - v[1] / w, C[1] + v[0] / w), abs=1e-15)
    d23 = cs.centre(2, 3).direction                      # at infinity ⟂ the rod
    assert cs.centre(2, 3).primary and abs(d23[0] * e[0] + d23[1] * e[1]) < 1e-15
    assert cs.velocities["C"].speed == pytest.approx(2.5, rel=1e-12)
    assert cs.velocities["C"].how == "v_C = ω₃ · I₁₃C = 5 × 0.5 = 2.5 m/s"


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_every_case_through_the_command(path, capsys):
    """`polygons centres CASE` exits 0 for every shipped case and prints, for every point,
    the body whose centre is used, the distance and v = ω × distance."""
    from polygons.cli import main
    assert main(["centres", str(path)]) == 0
    out = capsys.readouterr().out
    sol = solve(load_scene(path))
    for label in sol.points:
        assert f"  v_{label} = " in out, label


def test_units_and_numbers_in_the_table(tmp_path, capsys):
    """--units converts the table's lengths and speeds; [centres] numbers renumbers."""
    from polygons.cli import main
    assert main(["centres", "cases/centres-double-slider.toml", "--units", "imperial"]) == 0
    out = capsys.readouterr().out
    assert f"v_B = ω₃ · I₁₃B = 12.5 rad/s × {0.06 / 0.0254:.5g} in = {0.75 / 0.3048:.5g} ft/s" \
        in out
    scene = tmp_path / "f7.toml"
    scene.write_text((ROOT / "cases/s003-fig7.toml").read_text(encoding="utf-8")
                     + '\n[centres]\nnumbers = { O2P2 = 2, O4P4 = 3 }\n', encoding="utf-8")
    cs = instant_centres(solve(load_scene(scene)))
    assert [b.name for b in cs.bodies] == ["frame", "O2P2", "O4P4", "block P2"]


@pytest.mark.parametrize("numbers, where", [
    ('{ O2P3 = 2 }', "centres.numbers.O2P3"),
    ('{ O2P2 = 1 }', "centres.numbers.O2P2"),
    ('{ O2P2 = 9 }', "centres.numbers.O2P2"),
    ('{ O2P2 = 2, O4P4 = 2 }', "centres.numbers"),
    ('"2"', "centres.numbers"),
])
def test_bad_numbers_are_one_line_errors(tmp_path, numbers, where):
    scene = tmp_path / "f7.toml"
    scene.write_text((ROOT / "cases/s003-fig7.toml").read_text(encoding="utf-8")
                     + f'\n[centres]\nnumbers = {numbers}\n', encoding="utf-8")
    with pytest.raises(SceneError) as err:
        instant_centres(solve(load_scene(scene)))
    assert f"[{where}]" in str(err.value) and "\n" not in str(err.value)


def chain_scene(m: int) -> dict:
    """A four-bar A B C D and ``m`` RRR dyads, dyad k joining X_k to the previous moving pin
    and to a new ground pivot G_k: a chain of four-bar loops of 3 + 2m links."""
    d, h = 0.1, 0.08
    pts = {"A": (0.0, 0.0), "D": (d, 0.0), "B": (0.02, 0.05), "C": (d + 0.015, 0.06)}
    ground = {"A": ["0 m", "0 m"], "D": [f"{d!r} m", "0 m"]}
    links, asm = {}, {"C": {"near": [f"{pts['C'][0]!r} m", f"{pts['C'][1]!r} m"]}}

    def length(a, b):
        return f"{math.dist(pts[a], pts[b])!r} m"

    links.update(AB=length("A", "B"), BC=length("B", "C"), DC=length("D", "C"))
    prev = "C"
    for k in range(1, m + 1):
        g, x = f"G{k}", f"X{k}"
        pts[g] = ((k + 1) * d + 0.01 * math.sin(k), 0.005 * math.cos(3 * k))
        pts[x] = (pts[g][0] + 0.012 + 0.006 * math.sin(2 * k), h + 0.01 * math.cos(k))
        ground[g] = [f"{pts[g][0]!r} m", f"{pts[g][1]!r} m"]
        links[f"{prev}{x}"], links[f"{g}{x}"] = length(prev, x), length(g, x)
        asm[x] = {"near": [f"{pts[x][0]!r} m", f"{pts[x][1]!r} m"]}
        prev = x
    return {"ground": ground, "links": links, "assembly": asm,
            "driver": {"crank": "AB", "angle": f"{math.degrees(math.atan2(0.05, 0.02))!r} deg",
                       "omega": "10 rad/s", "sense": "CCW"}}


def test_large_mechanism_centres_the_velocities_need_in_linear_time():
    """41 links (a chain of 19 four-bar loops): only the centres the velocities need and the
    primary ones, found in windows along the construction (not all 861); the velocities the
    polygon's; the count grows linearly: 7 a loop (its two links' primaries and the centres
    the window finds), 7m + 6 in all."""
    import time
    from polygons.centres import FULL_BODIES
    sizes = {}
    for m in (9, 19):
        sol = solve(parse_scene(chain_scene(m)))
        t = time.perf_counter()
        cs = instant_centres(sol)
        sizes[m] = (len(cs.centres), time.perf_counter() - t)
        n = len(cs.bodies)
        assert n == 4 + 2 * m > FULL_BODIES and not cs.complete
        assert "the velocities need" in cs.note
        vs = _scale(sol)
        for label, pv in cs.velocities.items():
            assert math.dist(pv.velocity, sol.points[label].velocity) <= 1e-12 * vs, label
        assert all((1, j) in {(c.i, c.j) for c in cs.centres} for j in range(2, n + 1))
    assert sizes[9][0] == 7 * 9 + 6 and sizes[19][0] == 7 * 19 + 6
    assert sizes[19][1] < 1.0


def test_a_truss_on_a_four_bar_is_one_link_of_the_circle_diagram():
    """Triangles of links built on the coupler BC (each new point pinned to the two before)
    are rigid with it: one link of the circle diagram, every point's velocity ω₃ · I₁₃X, the
    polygon's."""
    pts = {"A": (0.0, 0.0), "D": (0.1, 0.0), "B": (0.02, 0.05), "C": (0.115, 0.06),
           "T1": (0.07, 0.1), "T2": (0.09, 0.14)}
    links = {a + b: f"{math.dist(pts[a], pts[b])!r} m"
             for a, b in (("A", "B"), ("B", "C"), ("D", "C"), ("B", "T1"), ("C", "T1"),
                          ("C", "T2"), ("T1", "T2"))}
    near = {x: {"near": [f"{pts[x][0]!r} m", f"{pts[x][1]!r} m"]} for x in ("C", "T1", "T2")}
    sol = solve(parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": ["0.1 m", "0 m"]},
        "links": links, "assembly": near,
        "driver": {"crank": "AB", "angle": f"{math.degrees(math.atan2(0.05, 0.02))!r} deg",
                   "omega": "10 rad/s", "sense": "CCW"}}))
    cs = instant_centres(sol)
    assert [b.name for b in cs.bodies] == ["frame", "AB", "BC (with 4 links fixed to it)",
                                           "DC"]
    assert cs.bodies[2].fixed == ("BT1", "CT1", "CT2", "T1T2") and cs.complete
    for name in ("BT1", "CT2", "T1T2"):
        assert cs.omega(name) == pytest.approx(sol.links[name].omega, rel=1e-12)
    assert cs.velocities["T2"].how.startswith("v_T2 = ω₃ · I₁₃T2 = ")
    for label, pv in cs.velocities.items():
        assert math.dist(pv.velocity, sol.points[label].velocity) <= 1e-12 * _scale(sol)


@pytest.mark.parametrize("stem", ["s003-fig7", "new-watt-six-bar", "centres-double-slider",
                                  "new-rotary-engine"])
def test_centre_labels_sit_on_no_other_label(stem):
    """Each centre's label (I₁₃, textbook subscripts) is on no other text of the drawing —
    the space diagram's labels and the ω/α notes included — and no line of centres runs
    through a label."""
    from diagrams.centres import drawing, label_of
    from diagrams.labels import box_hits_segment, text_box
    from diagrams.model import Segment, Text
    sol = solve(load_scene(ROOT / f"cases/{stem}.toml"))
    cs = instant_centres(sol)
    d = drawing(sol, cs)
    texts = [t for t in d.items() if isinstance(t, Text)]
    mine = [t for t in texts if t.cls == "centre-label"]
    assert {label_of(c) for c in cs.centres} <= {p.split(" ")[0] for t in mine
                                                 for p in t.text.split(" = ")}
    boxes = [(t, text_box(t.x, t.baseline, t.text, t.size, t.anchor)) for t in texts]
    for t in mine:
        b = text_box(t.x, t.baseline, t.text, t.size, t.anchor)
        for o, ob in boxes:
            assert o is t or not b.overlaps(ob), (t.text, o.text)
    for seg in d.items("lines-of-centres"):
        if isinstance(seg, Segment):
            for o, ob in boxes:
                assert not box_hits_segment(ob, seg.a, seg.b, 0.0), (seg.cls, o.text)


def test_a_large_mechanism_draws_each_links_centre_and_says_so():
    """18 links: I1j of each link drawn (I₁,₁₀ ... past link 9), no line of centres, no circle
    diagram, the caption saying what is drawn; SVG ids without commas."""
    from diagrams.centres import svg
    sol = solve(parse_scene(chain_scene(7)))
    cs = instant_centres(sol)
    text = svg(sol, cs)
    assert "I₁,₁₇" in text and "chord" not in text and 'id="I1,' not in text
    assert "drawn are the centre I1j of every link" in text


def test_a_triad_plate_of_three_links_has_its_pins_and_kennedy_finds_every_centre():
    """A class-III group whose plate is the triangle BC, CX, BX: the pins B, C, X join the
    plate (one link of the circle diagram) to AB, CD, XE, so Kennedy's theorem gives every
    centre (it used to say 'leaves 6 open': X was no pin of the plate); the plate's centre
    I14 is its point of zero velocity; the triad's auxiliary point S is a point of the plate."""
    sol = solve(load_scene(ROOT / "cases/triad-ternary-coupler.toml"))
    cs = instant_centres(sol)
    assert "all 15 centres, from the pairs and Kennedy's theorem" in cs.note
    assert cs.centre(4, 6).how == "pin X"
    B, vB = np.array(sol.points["B"].position), np.array(sol.points["B"].velocity)
    w = sol.links["BC"].omega
    assert np.allclose(cs.centre(1, 4).point, B - np.array([vB[1], -vB[0]]) / w, atol=1e-9)
    assert cs.centre(2, 4).how.startswith("Kennedy: ") and not cs.centre(2, 4).by_field
    sol8 = solve(load_scene(ROOT / "cases/triad-eight-bar.toml"))
    cs8 = instant_centres(sol8)
    s = next(x for x in sol8.points if x.startswith("S"))
    assert cs8.velocities[s].number == cs8.body("BC").number
