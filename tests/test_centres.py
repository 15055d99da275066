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

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import analytic
from conftest import ROOT, case_files
from polygons.errors import UnsupportedError
from scenes import crank_driver, slider_crank_case
from polygons.errors import ParallelLinesError
from polygons.centres import instant_centres
from polygons.errors import SceneError
from polygons.evaluate import solve
from polygons.pins import least_velocity, report_lines, rubbing_velocities
from polygons.scene import load_scene, parse_scene

REL = 1e-9
FILES = case_files()
IDS = [f.stem for f in FILES]


@pytest.fixture(scope="module")
def solved():
    cache = {}

    def get(path):
        if path not in cache:
            sol = solve(load_scene(path))
            try:
                cache[path] = (sol, instant_centres(sol))
            except UnsupportedError as exc:
                cache[path] = exc
        if isinstance(cache[path], UnsupportedError):
            assert path.stem in REFUSED, f"{path.name}: {cache[path]}"
            pytest.skip(f"{path.name}: refused by design: {cache[path]}")
        return cache[path]
    return get


def _scale(sol):
    return max([math.hypot(*p.velocity) for p in sol.points.values()] + [1e-300])


#: shipped cases whose topology the centres do not model (two inputs, offset or guided slots):
#: refused with a one-line reason, never answered wrongly
REFUSED = {"new-collar-on-rotating-rod", "new-offset-slot", "new-oscillating-cylinder",
           "new-rotary-engine", "new-slot-on-moving-lever",
           "new-elliptic-trammel", "bar-on-half-cylinder"}


def test_every_shipped_case_is_handled():
    """Four-bars, slider-cranks, slotted levers and the Scotch yoke: no case is skipped; the
    others are refused with a reason."""
    kinds = set()
    for path in FILES:
        sol = solve(load_scene(path))
        if path.stem in REFUSED:
            with pytest.raises(UnsupportedError):
                instant_centres(sol)
            continue
        cs = instant_centres(sol)
        n = len(cs.bodies)
        assert len(cs.centres) == n * (n - 1) // 2
        kinds.add(n)
    assert kinds >= {2, 3, 4, 6}          # up to the six-bars (Watt, Stephenson, Whitworth)


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
        if b.kind == "slider":
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
    assert i14.point is None and i14.how == "slider (at infinity ⟂ guide)"
    assert abs(i14.direction[0]) < 1e-15 and abs(i14.direction[1]) == 1.0
    i13 = _meet(A, (B[0] - A[0], B[1] - A[1]), C, (0.0, 1.0))
    i24 = _meet(A, (0.0, 1.0), B, (C[0] - B[0], C[1] - B[1]))
    assert cs.centre(1, 3).point == pytest.approx(i13, abs=1e-15)
    assert cs.centre(2, 4).point == pytest.approx(i24, abs=1e-15)
    # piston speed = ω2 × I12I24 (the textbook result) against the polygon
    v = abs(sol.scene.driver.omega) * math.dist(A, i24)
    assert v == pytest.approx(math.hypot(*sol.points["C"].velocity), rel=1e-12)


def test_slotted_lever_centre_on_the_common_normal():
    """Figure 7: I23 lies on O2O4 and on the normal to the slot at P2."""
    sol = solve(load_scene(ROOT / "cases/s003-fig7.toml"))
    cs = instant_centres(sol)
    P = sol.placement.points
    e = (P["P2"][0] - P["O4"][0], P["P2"][1] - P["O4"][1])
    i23 = _meet(P["O4"], (P["O2"][0] - P["O4"][0], P["O2"][1] - P["O4"][1]),
                P["P2"], (-e[1], e[0]))
    c = cs.centre(2, 3)
    assert c.point == pytest.approx(i23, abs=1e-15)
    assert c.how == "Kennedy: 23 on 21–13 and the common normal at P2"
    assert not c.primary and c.order == 1


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
    return subprocess.run([sys.executable, "-m", "polygons", *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT)


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
    for c in cs.centres:
        assert f">{c.label}" in svg, c.label
    assert "I14 → ∞" in svg                      # the slider's centre, by a direction arrow
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
    except ParallelLinesError:
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
