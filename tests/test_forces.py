"""Forces: the five force cases against the reference, virtual work against Newton–Euler on every
case, energy against RK4 integration, closed forms, and bad force input through the CLI."""
import json
import math
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from conftest import CASES, case_files, cli, reference_cases
from polygons.errors import BranchError, AssemblyError, PolygonsError
from polygons.forces import (analyse, check_force_answers, force_quantity, has_forces,
                             load_model, newton_euler)
from polygons.scene import load_scene, parse_scene

EXACT_REL = 1e-9
FORCE_CASES = [f for f in case_files() if has_forces(load_scene(f))]
IDS = [f.stem for f in FORCE_CASES]
EXE = Path(sys.executable).with_name("polygons")


@pytest.fixture(scope="module")
def analysed():
    cache = {}

    def get(path):
        if path not in cache:
            cache[path] = analyse(load_scene(path))
        return cache[path]
    return get


def test_the_five_force_cases_are_there():
    names = {f.name for f in FORCE_CASES}
    assert {"s001-we8.toml", "s001-sae5-q1.toml", "s000-d225-2003-q3.toml",
            "s002-ex3.16.toml", "s002-ex3.17.toml"} <= names


# ---------------------------------------------------------------- reference answers
@pytest.mark.parametrize("path", FORCE_CASES, ids=IDS)
def test_force_answers_reproduce_the_exact_values(path, analysed):
    checks = [c for c in check_force_answers(analysed(path)) if c.answer.exact is not None]
    assert checks, f"{path.name} has no exact force answers"
    for c in checks:
        exact = c.answer.exact
        tol = EXACT_REL * abs(exact) if exact != 0 else 1e-12
        assert abs(c.compared - exact) <= tol, (
            f"{c.answer.quantity} [{c.answer.state}] = {c.compared!r}, exact {exact!r}")


@pytest.mark.parametrize("path", FORCE_CASES, ids=IDS)
def test_force_answers_match_the_tutorial_and_do_not_reproduce_its_slips(path, analysed):
    for c in check_force_answers(analysed(path)):
        a = c.answer
        if a.tutorial is None:
            continue
        if a.slip:
            assert not c.within, f"{a.quantity}: we reproduce the tutorial's slip {a.tutorial}"
        else:
            assert c.within, (f"{a.quantity}: tutorial {a.tutorial}, ours {c.compared:.6g} "
                              f"(tolerance ±{a.tolerance * 100:g} %)")


REF = reference_cases()
IN_REFERENCE = [p for p in FORCE_CASES if load_scene(p).source["id"] in REF]


def test_force_cases_outside_the_reference_are_checked_by_closed_forms():
    """The force cases without a reference record have their exact values recomputed below."""
    outside = {p.name for p in FORCE_CASES} - {p.name for p in IN_REFERENCE}
    # (the forces-* cases: their efforts by closed forms in tests/test_graphical.py; the cam's
    # in tests/test_contact_forces.py)
    assert outside == {"khurmi-flywheel-steam-engine.toml", "efficiency-four-bar.toml",
                       "cam-roller-forces.toml", "rolling-wheel-forces.toml",
                       "forces-toggle-press.toml", "forces-actuator-four-bar.toml",
                       "forces-engine-piston-effort.toml", "forces-whitworth.toml",
                       "forces-scotch-yoke.toml", "forces-oscillating-cylinder.toml",
                       "forces-triad.toml", "forces-triad-truss.toml",
                       # its piston effort by the closed form in tests/test_conditions.py
                       "question-engine-conditions.toml",
                       # the lever's torque by a power balance in tests/test_slot_slider.py
                       "new-slot-slider.toml"}


@pytest.mark.parametrize("path", IN_REFERENCE, ids=[p.stem for p in IN_REFERENCE])
def test_force_exact_values_are_the_reference_values_and_slips_its_slips(path):
    case = REF[load_scene(path).source["id"]]
    model = load_model(load_scene(path))
    slips_ref = {v["exact_key"] for v in case["tutorial_answers"].values() if v["slip"]}
    for a in model.answers:
        if a.slip:
            assert a.ref in slips_ref, f"{a.ref} is not a slip in the reference"
        if a.ref is None or a.exact is None:
            continue
        value = case["exact_answers"][a.ref]
        expected = abs(value) if a.mode == "abs" else value
        assert a.exact == pytest.approx(expected, rel=1e-12, abs=1e-15), a.ref
        if a.tutorial is not None and a.ref in case["tutorial_answers"]:
            assert a.tutorial == case["tutorial_answers"][a.ref]["value"], a.ref


def test_we8_slips_are_all_asserted():
    model = load_model(load_scene(CASES / "s001-we8.toml"))
    slipped = {a.ref for a in model.answers if a.slip}
    assert {"F_inertia", "F_net", "F_rod", "T_crank"} <= slipped


def test_ex316_part_c_slips_are_asserted():
    model = load_model(load_scene(CASES / "s002-ex3.16.toml"))
    assert {a.ref for a in model.answers if a.slip} == {"S_B", "M_B"}


# ---------------------------------------------------------------- virtual work vs Newton–Euler
@pytest.mark.parametrize("path", FORCE_CASES, ids=IDS)
def test_virtual_work_agrees_with_newton_euler(path, analysed):
    an = analysed(path)
    for st_ in an.states:
        scale = max([abs(t.value) for t in st_.breakdown] + [1.0])
        if an.model.mode == "kinetostatic":
            assert st_.vw_effort == pytest.approx(st_.ne.effort, rel=1e-10, abs=1e-12 * scale)
        else:   # the applied torques are in the loads: no extra input may be needed
            assert abs(st_.vw_effort) <= 1e-12 * scale, (st_.name, st_.vw_effort)
        assert st_.ne.residual <= 1e-9 * scale


@pytest.mark.parametrize("path", [p for p in FORCE_CASES if "3.1" in p.name],
                         ids=lambda p: p.stem)
def test_torque_driven_states_are_consistent_kinetostatically(path, analysed):
    """At the solved α, a kinetostatic solve needs no extra input and gives the same pins."""
    an = analysed(path)
    for st_ in an.states:
        ne = newton_euler(an.model, st_.sol, st_.vsol, lds=st_.ne.loads)
        scale = max(float(np.abs(st_.ne.values).max()), 1.0)
        assert abs(ne.effort) <= 1e-10 * scale
        for key, f in st_.ne.pin.items():
            assert np.allclose(ne.pin[key], f, atol=1e-10 * scale), key


# ---------------------------------------------------------------- released motion
def test_ex316_energy_and_integration_agree(analysed):
    an = analysed(CASES / "s002-ex3.16.toml")
    (check,) = an.dynamics["checks"]
    assert check["relative_difference"] < 1e-8
    assert check["omega_energy"] == pytest.approx(-3.450670895867166, rel=1e-12)
    assert check["rk4_steps"] >= 50


def _scene(text: str, file="t.toml"):
    return parse_scene(tomllib.loads(text), file=file)


PENDULUM = """
title = "uniform rod released horizontal"
[ground]
O = ["0 m", "0 m"]
[links]
OA = "1.5 m"
[driver]
crank = "OA"
angle = "0 deg"
omega = "0 rad/s"
sense = "CW"
[masses.OA]
mass = "2 kg"
[gravity]
g = "9.81 m/s^2"
[dynamics]
mode = "release"
after = ["90 deg", "150 deg"]
steps = 80
"""


def test_pendulum_closed_forms():
    """Uniform rod from horizontal: α0 = 3g/2L, reaction mg/4 up, ω² = 3g sin θ / L."""
    an = analyse(_scene(PENDULUM))
    g, L, m = 9.81, 1.5, 2.0
    assert force_quantity(an, "alpha(OA)", "release", -1) == pytest.approx(1.5 * g / L,
                                                                           rel=1e-12)
    assert force_quantity(an, "Ry(O,OA)", "release") == pytest.approx(m * g / 4, rel=1e-12)
    for deg in (90, 150):
        w = force_quantity(an, "omega(OA)", f"{deg} deg", -1)
        assert w == pytest.approx(math.sqrt(3 * g * math.sin(math.radians(deg)) / L),
                                  rel=1e-12)
    for c in an.dynamics["checks"]:
        assert c["relative_difference"] < 1e-7


def test_release_that_cannot_reach_the_angle_says_so():
    text = PENDULUM.replace('after = ["90 deg", "150 deg"]', 'after = ["200 deg"]')
    with pytest.raises(PolygonsError, match="energy runs out|turns back"):
        analyse(_scene(text))


# ---------------------------------------------------------------- what-ifs from the reference
def _s000(extra: str):
    data = tomllib.loads((CASES / "s000-d225-2003-q3.toml").read_text() + extra)
    return data


def test_s000_with_the_weights_the_tutorial_ignored():
    an = analyse(parse_scene(_s000('\n[gravity]\ng = "9.81 m/s^2"\n'), file="g.toml"))
    assert force_quantity(an, "Tin") == pytest.approx(-6.193, abs=5e-4)


def test_s000_with_the_20_N_downwards():
    data = _s000("")
    data["forces"]["Load"]["force"] = ["0 N", "-20 N"]
    an = analyse(parse_scene(data, file="down.toml"))
    assert force_quantity(an, "Tin") == pytest.approx(-6.864, abs=5e-4)


# ---------------------------------------------------------------- random mechanisms
FOURBAR = """
title = "random four-bar"
[ground]
A = ["0 m", "0 m"]
D = ["{d} m", "0 m"]
[links]
AB = "{a} m"
BC = "{b} m"
CD = "{c} m"
[driver]
crank = "AB"
angle = "{th} deg"
omega = "{w} rad/s"
sense = "CCW"
alpha = "{al} rad/s^2"
alpha_sense = "CW"
[assembly]
C = "C above AD"
[points.E]
on = "BC"
along = "{e} m"
left = "0.05 m"
[masses.AB]
mass = "{m1} kg"
[masses.BC]
mass = "{m2} kg"
[masses.CD]
mass = "{m3} kg"
inertia = "0.01 kg m^2"
centre = 0.3
[masses.Pt]
at = "E"
mass = "0.2 kg"
[gravity]
g = "9.81 m/s^2"
direction = "{gd} deg"
[forces.P]
at = "E"
magnitude = "{f} N"
direction = "{fd} deg"
[torques.Out]
on = "CD"
torque = "3 N m"
sense = "CW"
[springs.K]
stiffness = "200 N/m"
between = ["C", "D"]
on = ["CD", ""]
free_length = "0.2 m"
[springs.Kt]
stiffness = "5 N m/rad"
at = "C"
twist = "10 deg"
[torques.Fb]
at = "B"
friction = "0.3 N m"
"""


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(d=st.floats(0.3, 0.6), a=st.floats(0.08, 0.15), b=st.floats(0.3, 0.6),
       c=st.floats(0.25, 0.5), th=st.floats(0, 359), w=st.floats(1, 50),
       al=st.floats(0, 200), e=st.floats(0.05, 0.3), m1=st.floats(0.1, 2),
       m2=st.floats(0.1, 2), m3=st.floats(0.1, 2), gd=st.floats(0, 359),
       f=st.floats(0, 100), fd=st.floats(0, 359))
def test_random_four_bars_virtual_work_equals_newton_euler(**p):
    scene = _scene(FOURBAR.format(**p))
    try:
        an = analyse(scene)
    except (AssemblyError, BranchError):   # cannot close, or both closures below AD
        assume(False)
    except PolygonsError as exc:
        assume("parallel" not in str(exc) and "singular" not in str(exc))
        raise
    st_ = an.states[0]
    scale = max([abs(t.value) for t in st_.breakdown] + [1.0])
    assert st_.vw_effort == pytest.approx(st_.ne.effort, rel=1e-8, abs=1e-9 * scale)


def test_torque_driven_round_trip_on_a_four_bar():
    """Kinetostatic at a given α → T_in; torque-driven with T_in applied → the same α."""
    p = dict(d=0.45, a=0.1, b=0.4, c=0.35, th=40, w=12, al=30, e=0.2, m1=1, m2=0.7, m3=1.1,
             gd=270, f=20, fd=30)
    an = analyse(_scene(FOURBAR.format(**p)))
    tin = an.states[0].ne.effort
    text = FOURBAR.format(**p).replace('alpha = "30 rad/s^2"\nalpha_sense = "CW"\n', "")
    text += (f'\n[torques.In]\non = "AB"\ntorque = "{abs(tin)!r} N m"\n'
             f'sense = "{"CCW" if tin > 0 else "CW"}"\n[dynamics]\nmode = "torque-driven"\n')
    an2 = analyse(_scene(text))
    assert an2.states[0].ne.alpha == pytest.approx(-30.0, rel=1e-9)
    for key, f in an.states[0].ne.pin.items():
        assert np.allclose(an2.states[0].ne.pin[key], f, rtol=1e-8, atol=1e-8)


SLIDER_DRIVEN = """
title = "slider-driven slider-crank"
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "50 mm"
AB = "200 mm"
[driver]
slider = "B"
position = "220 mm"
velocity = "3 m/s"
acceleration = "40 m/s^2"
[sliders.B]
through = ["0 mm", "0 mm"]
direction = "0 deg"
[assembly]
A = "A above OB"
[masses.OA]
mass = "0.3 kg"
[masses.AB]
mass = "0.5 kg"
[masses.B]
mass = "0.4 kg"
[gravity]
g = "9.81 m/s^2"
[torques.Load]
on = "OA"
torque = "2 N m"
sense = "CW"
"""


def test_slider_driver_input_force_by_both_methods():
    an = analyse(_scene(SLIDER_DRIVEN))
    st_ = an.states[0]
    assert st_.vw_effort == pytest.approx(st_.ne.effort, rel=1e-10)


YOKE = (CASES / "scotch-yoke.toml")


@pytest.mark.skipif(not YOKE.exists(), reason="no Scotch yoke case")
def test_scotch_yoke_forces():
    """Yoke of mass m on a vertical guide: input torque = m a_y v_y / ω (no other load)."""
    data = tomllib.loads(YOKE.read_text())
    data["masses"] = {"Y": {"mass": "2 kg"}}
    an = analyse(parse_scene(data, file="yoke.toml"))
    st_ = an.states[0]
    sr = st_.sol.slides["Y"]
    w = st_.sol.links["OP"].omega
    assert st_.ne.effort == pytest.approx(2.0 * sr.acceleration * sr.velocity / w, rel=1e-10)
    assert st_.vw_effort == pytest.approx(st_.ne.effort, rel=1e-10)


# ---------------------------------------------------------------- CLI
def run(*args):
    """``polygons ARGS`` in this process (conftest.cli: the entry point function)."""
    return cli(*args)


def run_process(*args):
    """``polygons ARGS`` as a separate process (the console script)."""
    cmd = [str(EXE)] if EXE.exists() else [sys.executable, "-m", "polygons"]
    return subprocess.run(cmd + [str(a) for a in args], capture_output=True, text=True,
                          timeout=120)


def test_cli_forces_table_states_units_and_senses():
    out = run("forces", CASES / "s001-we8.toml")
    assert out.returncode == 0, out.stderr
    assert "input torque on OC: 157.75996 N m CCW" in out.stdout
    assert "turning moment on OC: 157.75996 N m CW" in out.stdout
    assert "SLIP in the tutorial" in out.stdout


def test_cli_forces_json_and_determinism():
    # two processes (each its own hash seed): the same bytes
    a = run_process("forces", CASES / "s002-ex3.17.toml", "--json")
    b = run_process("forces", CASES / "s002-ex3.17.toml", "--json")
    assert a.returncode == 0, a.stderr
    assert a.stdout == b.stdout
    data = json.loads(a.stdout)
    st_ = data["states"][0]
    assert st_["alpha_in"] == pytest.approx(3.7808823529411772, rel=1e-12)
    pins = {(p["pin"], p["on"]): p["force"] for p in st_["pins"]}
    assert pins[("O", "OA")] == pytest.approx([-2.7555555555555555, 29.535147058823533])


def test_cli_solve_appends_forces_when_the_scene_has_masses():
    out = run("solve", CASES / "s000-d225-2003-q3.toml", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["forces"]["states"][0]["input"]["newton_euler"] == pytest.approx(
        -6.029423097089744, rel=1e-12)
    out = run("solve", CASES / "s000-d225-2003-q3.toml")
    assert "input torque on OA: 6.0294231 N m CW" in out.stdout
    out = run("solve", CASES / "s003-fig7.toml", "--json")
    assert "forces" not in json.loads(out.stdout)


def test_cli_release_case_reports_energy_and_rk4():
    out = run("forces", CASES / "s002-ex3.16.toml")
    assert out.returncode == 0, out.stderr
    assert "energy vs RK4" in out.stdout and "after 30 deg" in out.stdout


BASE = (CASES / "s001-we8.toml").read_text()


@pytest.mark.parametrize("change,expected", [
    (('mass = "0.5 kg"', 'mass = "-0.5 kg"'), r"\[masses.P.mass\].*must not be negative"),
    (('mass = "0.5 kg"', 'mass = 0.5'), r"\[masses.P.mass\].*missing unit"),
    (('at = "P"\npressure', 'at = "Q"\npressure'), r"\[forces.Gas.at\].*unknown point 'Q'"),
    (('bore = "80 mm"', 'bor = "80 mm"'), r"\[forces.Gas.bor\].*unknown key 'bor'.*did you mean 'bore'"),
    (('pressure = "1.2 MPa"', 'pressure = "1.2 N"'), r"\[forces.Gas.pressure\].*pressure"),
    (('[masses.P]', '[masses.PX]'), r"\[masses.PX\].*unknown link or slider 'PX'"),
])
def test_bad_force_input_gives_one_readable_line(tmp_path, change, expected):
    old, new = change
    assert old in BASE
    path = tmp_path / "bad.toml"
    path.write_text(BASE.replace(old, new, 1))
    for cmd in (("forces", "solve") if "negative" in expected else ("forces",)):
        out = run(cmd, path)
        assert out.returncode != 0
        assert "Traceback" not in out.stderr
        lines = out.stderr.strip().splitlines()
        assert len(lines) == 1, out.stderr
        assert "bad.toml" in lines[0]
        assert re.search(expected, lines[0]), lines[0]


def test_friction_with_a_sense_is_refused():
    text = (CASES / "s002-ex3.16.toml").read_text().replace(
        'friction = "0.1 N m"', 'friction = "0.1 N m"\nsense = "CW"')
    with pytest.raises(PolygonsError, match=r"\[torques.Friction.sense\].*does not apply"):
        analyse(_scene(text, "f.toml"))


def test_forces_on_a_scene_without_masses_is_an_error():
    out = run("forces", CASES / "s003-fig7.toml")
    assert out.returncode != 0 and "nothing for a force analysis" in out.stderr
    assert "Traceback" not in out.stderr


# ---------------------------------------------------------------- free-body diagrams
@pytest.mark.parametrize("name", ["s002-ex3.17.toml", "s001-we8.toml", "s000-d225-2003-q3.toml"])
def test_force_polygons_close_and_svgs_are_deterministic(name, analysed):
    from diagrams.svg import to_svg
    from diagrams.fbd import drawings
    an = analysed(CASES / name)
    first = drawings(an)
    assert any(stem.startswith("fbd-") for stem, _ in first)
    for stem, d in first:
        if stem.startswith("forces-"):
            scale = max(abs(float(v)) for v in an.states[0].ne.values) + 1.0
            assert d.meta["gap_N"] <= 1e-9 * scale, stem
    second = drawings(an)
    assert [to_svg(d) for _, d in first] == [to_svg(d) for _, d in second]


def test_cli_forces_svg_writes_valid_files(tmp_path):
    import cairosvg
    out = run("forces", CASES / "s002-ex3.16.toml", "--svg", tmp_path / "fbd")
    assert out.returncode == 0, out.stderr
    files = sorted((tmp_path / "fbd").glob("*.svg"))
    assert {f.name for f in files} >= {"fbd-release-oa.svg", "forces-after-30-deg-oa.svg"}
    for f in files:
        assert cairosvg.svg2png(url=str(f))[:4] == b"\x89PNG"


# ---------------------------------------------------------------- machine: cylinder, flywheel, efficiency
def _engine_exact(N, D, stroke, l, m, beta_deg, p1, p2, d, sense=-1, g_along=0.0):
    """In-line slider-crank, piston on the -x side, x = r cos b - sqrt(l² - r² sin² b), massless
    crank and rod, reciprocating mass m, double-acting cylinder (rod d on the crank side):
    F_L = p1 A - p2 (A - a); F = F_L - m a_P along +x; T = F v_P/|ω| (power balance);
    rod thrust Q = F / cos φ; bearing thrust F_B = Q e_PC·e_OC."""
    r, w = stroke / 2, sense * 2 * math.pi * N / 60
    A1, a = math.pi / 4 * D ** 2, math.pi / 4 * d ** 2
    FL = p1 * A1 - p2 * (A1 - a)
    b = math.radians(beta_deg)
    s, c = math.sin(b), math.cos(b)
    L = math.sqrt(l * l - r * r * s * s)
    x = r * c - L
    d1 = -r * s + r * r * s * c / L
    d2 = -r * c + r * r * (c * c - s * s) / L + r ** 4 * s * s * c * c / L ** 3
    v, acc = d1 * w, d2 * w * w
    F = FL - m * acc + m * g_along
    pc = np.array([r * c - x, r * s])
    Q = F / (abs(pc[0]) / np.hypot(*pc))
    FB = Q * float(pc @ np.array([c, s])) / float(np.hypot(*pc))
    return dict(w=w, FL=FL, x=x, v=v, a=acc, T=F * v / abs(w), FB=FB, Q=Q)


def test_khurmi_flywheel_case_against_the_closed_form():
    """Khurmi's steam engine: the file's exact values are the closed form's (not the solver's),
    the solver reproduces them, and the book's printed T, F_B, α are within 0.2 %."""
    path = CASES / "khurmi-flywheel-steam-engine.toml"
    e = _engine_exact(120, 0.25, 0.4, 0.6, 60, 135, 550e3, 70e3, 0.05)
    I, TR = 60 * 0.6 ** 2, 20e3 / abs(e["w"])
    alpha = (e["T"] - TR) / I
    model = load_model(load_scene(path))
    exact = {a.quantity: a.exact for a in model.answers}
    assert exact["F(Steam)"] == pytest.approx(e["FL"], rel=1e-12)
    assert exact["Tturn"] == pytest.approx(e["T"], rel=1e-12)
    assert exact["Rr(C,OC)"] == pytest.approx(abs(e["FB"]), rel=1e-12)
    assert exact["TR"] == pytest.approx(TR, rel=1e-12)
    assert exact["Ifw"] == pytest.approx(I, rel=1e-12)
    assert exact["alpha_fw"] == pytest.approx(alpha, rel=1e-12)
    scene = load_scene(path)
    kin = {a.quantity: a.exact for a in scene.answers}
    assert kin["vs(P)"] == pytest.approx(e["v"], rel=1e-12)
    assert kin["as(P)"] == pytest.approx(e["a"], rel=1e-12)
    an = analyse(scene)
    assert force_quantity(an, "Tturn") == pytest.approx(e["T"], rel=1e-9)
    assert force_quantity(an, "alpha_fw") == pytest.approx(alpha, rel=1e-9)
    # the book's printed answers (two-term piston acceleration): hand-checked, within 0.2 %
    for expr, printed in (("Tturn", 3929.0), ("Rr(C,OC)", -11980.0), ("alpha_fw", 108.2)):
        assert force_quantity(an, expr) == pytest.approx(printed, rel=2e-3), expr


def test_double_acting_cylinder_annulus_area(write_scene):
    """F = p1 π D²/4 − p2 π (D² − d²)/4; with the rod on the front side the areas swap."""
    base = (CASES / "khurmi-flywheel-steam-engine.toml").read_text()
    D, d, p1, p2 = 0.25, 0.05, 550e3, 70e3
    an = analyse(load_scene(write_scene(base)))
    assert force_quantity(an, "F(Steam)") == pytest.approx(
        p1 * math.pi * D * D / 4 - p2 * math.pi * (D * D - d * d) / 4, rel=1e-12)
    front = base.replace('rod = "50 mm"', 'rod = "50 mm"\nrod_side = "front"')
    an = analyse(load_scene(write_scene(front, "front.toml")))
    assert force_quantity(an, "F(Steam)") == pytest.approx(
        p1 * math.pi * (D * D - d * d) / 4 - p2 * math.pi * D * D / 4, rel=1e-12)
    bad = base.replace('rod = "50 mm"', 'rod = "300 mm"')
    with pytest.raises(PolygonsError, match=r"\[forces.Steam.rod\].*thinner than the bore"):
        load_scene(write_scene(bad, "bad.toml"))


def test_flywheel_from_resisting_torque_and_given_inertia(write_scene):
    """α = (T − T_R)/I with T_R and I given directly (hand-checked with the closed-form T)."""
    base = (CASES / "khurmi-flywheel-steam-engine.toml").read_text()
    text = base.replace('mass = "60 kg"\nradius_of_gyration = "600 mm"\npower = "20 kW"',
                        'inertia = "10 kg m^2"\nresisting_torque = "4000 N m"')
    assert text != base
    an = analyse(load_scene(write_scene(text)))
    e = _engine_exact(120, 0.25, 0.4, 0.6, 60, 135, 550e3, 70e3, 0.05)
    assert force_quantity(an, "alpha_fw") == pytest.approx((e["T"] - 4000.0) / 10.0, rel=1e-9)
    assert force_quantity(an, "alpha_fw") < 0          # slowing down: T < T_R
    for change, expected in (
            (('inertia = "10 kg m^2"', 'inertia = "10 kg m^2"\nmass = "3 kg"'), r"\[flywheel\]"),
            (('resisting_torque = "4000 N m"', ''), r"\[flywheel\].*power"),
            (('inertia = "10 kg m^2"', 'inertia = "10 kg"'), r"\[flywheel.inertia\]")):
        bad = text.replace(*change)
        with pytest.raises(PolygonsError, match=expected):
            load_scene(write_scene(bad, "bad.toml"))


def _four_bar_case():
    from analytic import four_bar
    return four_bar((0, 0), (0.45, 0), 0.1, 0.4, 0.35, math.radians(90), 12.0, 0.0, 1)


def test_efficiency_case_against_the_closed_form():
    """VR = ω_AB/ω_CD from the closed-form four-bar; MA = η VR; T_out = η T_in VR;
    T_in for a load T_L on CD: T_L ω_CD/ω_AB, and T_in/η with the losses."""
    path = CASES / "efficiency-four-bar.toml"
    r = _four_bar_case()
    vr, eta = 12.0 / r["omega_CD"], 0.8
    expected = {"VR(CD)": vr, "MA(CD)": eta * vr, "Tout_eta(CD)": eta * 20.0 * vr,
                "Tin": 30.0 / vr, "Tin_eta": 30.0 / vr / eta}
    model = load_model(load_scene(path))
    exact = {a.quantity: a.exact for a in model.answers}
    an = analyse(load_scene(path))
    for q, value in expected.items():
        assert exact[q] == pytest.approx(value, rel=1e-12), q
        assert force_quantity(an, q) == pytest.approx(value, rel=1e-9), q


def test_efficiency_when_the_load_drives_back(write_scene):
    """When the mechanism drives the input (T_in·ω < 0) the losses reduce the torque: T_in·η."""
    text = (CASES / "efficiency-four-bar.toml").read_text().replace(
        'torque = "30 N m"\nsense = "CW"', 'torque = "30 N m"\nsense = "CCW"')
    an = analyse(load_scene(write_scene(text)))
    vr = 12.0 / _four_bar_case()["omega_CD"]
    assert force_quantity(an, "Tin") == pytest.approx(-30.0 / vr, rel=1e-9)
    assert force_quantity(an, "Tin_eta") == pytest.approx(-30.0 / vr * 0.8, rel=1e-9)
    with pytest.raises(PolygonsError, match=r"\[efficiency.eta\].*fraction"):
        load_scene(write_scene(text.replace('eta = "80 %"', 'eta = "120 %"'), "bad.toml"))


def test_json_pin_components_and_identifier_keys(tmp_path):
    """Khurmi's engine: on the crank at C, tangential × r = T and radial = F_B (closed form);
    along the rod = −Q (compression); every key an identifier with its words beside it."""
    path = CASES / "khurmi-flywheel-steam-engine.toml"
    out_file = tmp_path / "forces.json"
    out = run("forces", path, "--json", "-o", out_file)
    assert out.returncode == 0 and out.stdout == "", out.stderr
    data = json.loads(out_file.read_text())
    st_ = data["states"][0]
    e = _engine_exact(120, 0.25, 0.4, 0.6, 60, 135, 550e3, 70e3, 0.05)
    pins = {p["key"]: p for p in st_["pins"]}
    comps = {c["key"]: c["value"] for c in pins["pin_C_on_OC"]["components"]}
    assert comps["crank_tangential"] * 0.2 == pytest.approx(e["T"], rel=1e-9)
    assert comps["crank_radial"] == pytest.approx(e["FB"], rel=1e-9)
    rod = {c["key"]: c["value"] for c in pins["pin_C_on_PC"]["components"]}
    assert rod["PC_along"] == pytest.approx(-e["Q"], rel=1e-9)   # pushes C away from P
    machine = {m["key"]: m["value"] for m in st_["machine"]}
    assert machine["flywheel_alpha"] == pytest.approx((e["T"] - 20e3 / abs(e["w"])) / 21.6,
                                                      rel=1e-9)
    keyed = [p for p in st_["pins"]] + st_["input"]["breakdown"] + st_["unknowns"]
    keyed += [c for p in st_["pins"] for c in p["components"]] + st_["machine"]
    for item in keyed:
        assert item["key"].isidentifier(), item["key"]
    for item in st_["input"]["breakdown"] + st_["unknowns"] + st_["machine"]:
        assert item["words"] and item["words"] != item["key"]
    assert {t["key"] for t in st_["input"]["breakdown"]} == {"force_Steam", "inertia_force_P"}


def test_solve_out_writes_the_same_as_stdout(tmp_path):
    case = CASES / "s001-we8.toml"
    for extra in ((), ("--json",)):
        shown = run("solve", case, *extra)
        written = tmp_path / "solve.out"
        quiet = run("solve", case, *extra, "--out", written)
        assert quiet.returncode == 0 and quiet.stdout == "", quiet.stderr
        assert written.read_text() == shown.stdout
    bad = run("forces", case, "-o", tmp_path)
    assert bad.returncode != 0 and "is a folder" in bad.stderr
    assert len(bad.stderr.strip().splitlines()) == 1


def test_fbd_forces_on_a_two_force_member_are_drawn_beside_it(analysed):
    """WE8's massless rod PC: the pin forces act along it; their arrows are drawn parallel to
    the rod but off it (≥ 2 mm), and each value sits clear of the rod (by its arrow, or on a
    leader)."""
    from diagrams.fbd import drawings
    from diagrams.labels import text_box
    from diagrams.model import Arrow, Segment, Text
    an = analysed(CASES / "s001-we8.toml")
    d = dict(drawings(an))["fbd-instant-pc"]
    (rod,) = [s for s in d.items("body") if isinstance(s, Segment) and s.style == "link"]
    a, b = np.array(rod.a), np.array(rod.b)
    e = (b - a) / np.hypot(*(b - a))
    n = np.array([-e[1], e[0]])
    arrows = [x for x in d.items("forces") if isinstance(x, Arrow)]
    assert len(arrows) == 2
    for arr in arrows:
        off = [abs(float((np.array(p) - a) @ n)) for p in (arr.tail, arr.tip)]
        assert min(off) >= 2.0, off                       # beside the rod, not on it
        assert abs(float((np.array(arr.tip) - arr.tail) @ n)) < 5e-3   # parallel (0.001 mm grid)
    leaders = [x for x in d.items("leaders") if isinstance(x, Segment)]
    assert len(leaders) <= 2          # a value set by its own arrow needs no leader
    for t in (x for x in d.items("labels") if isinstance(x, Text)):
        box = text_box(t.x, t.baseline, t.text, t.size, t.anchor)
        corners = [(box.x0, box.y0), (box.x0, box.y1), (box.x1, box.y0), (box.x1, box.y1)]
        sides = {np.sign(float((np.array(c) - a) @ n)) for c in corners}
        along = [float((np.array(c) - a) @ e) for c in corners]
        clear = len(sides) == 1 or max(along) < 0 or min(along) > np.hypot(*(b - a))
        assert clear, t.text                              # the value does not sit on the rod


VERTICAL_ENGINE = """
title = "Khurmi: vertical double-acting steam engine, 200 rev/min, 125 deg from TDC"
[ground]
O = ["0 mm", "0 mm"]
[links]
OC = "225 mm"
PC = "1.2 m"
[driver]
crank = "OC"
angle = "-35 deg"
omega = "200 rev/min"
sense = "CW"
[sliders.P]
through = ["0 mm", "0 mm"]
direction = "90 deg"
[assembly]
P = "P above O"
[masses.P]
mass = "225 kg"
[gravity]
g = "9.81 m/s^2"
[forces.Steam]
at = "P"
pressure = "30 kPa"
back_pressure = "1.5 kPa"
bore = "300 mm"
rod = "50 mm"
direction = "-90 deg"
"""


def test_vertical_double_acting_engine_turning_moment():
    """Khurmi & Gupta's vertical double-acting steam engine (bore 300 mm, stroke 450 mm, rod
    1.2 m, 225 kg, 200 rev/min, 125° from top dead centre, 30 kN/m² above and 1.5 kN/m² below
    the piston, rod 50 mm): the turning moment equals the closed form (the horizontal engine
    turned by −90°: the weight acts along the stroke towards the crank), and the book's
    two-term-formula answer, T = 3020 N m, is within 1 %."""
    e = _engine_exact(200, 0.3, 0.45, 1.2, 225, 55, 30e3, 1.5e3, 0.05, g_along=9.81)
    an = analyse(_scene(VERTICAL_ENGINE))
    assert force_quantity(an, "F(Steam)") == pytest.approx(e["FL"], rel=1e-12)
    assert force_quantity(an, "Tturn") == pytest.approx(e["T"], rel=1e-9)   # sense of rotation
    assert force_quantity(an, "Tturn") == pytest.approx(3020.0, rel=1e-2)
    assert force_quantity(an, "Tturn") == pytest.approx(-force_quantity(an, "Tout"), rel=1e-12)


def test_loads_schema_declares_every_key_it_reads():
    """polygons.loads reads exactly the keys its TABLES declare (force answers: the shared
    answer keys plus 'positive' and 'state')."""
    from polygons.loads import TABLES
    from polygons.scene import ANSWER_KEYS, EXTENSION_KEYS
    names = {t.name for t in TABLES}
    assert names == {"masses", "gravity", "forces", "torques", "springs", "dynamics",
                     "flywheel", "efficiency", "force_answers"}
    assert names <= set(EXTENSION_KEYS)
    fa = next(t for t in TABLES if t.name == "force_answers")
    assert {k.name for k in fa.keys} == set(ANSWER_KEYS) | {"positive", "state"}
    for t in TABLES:
        assert len({k.name for k in t.keys}) == len(t.keys) and all(k.doc for k in t.keys)


def test_force_modules_import_downward_only():
    """polygons.loads / loadmodel (scene layer) import only errors, schema, units and the
    mechanism model (its bodies and pairs, read instead of the joint tables); the
    forces package never imports diagrams or the commands, and has no import cycle."""
    import ast
    root = Path(__file__).resolve().parents[1] / "polygons"

    def imported(path):
        out = set()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module is None:
                out.update("." * node.level + a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                out.add(("." * node.level) + node.module)
            elif isinstance(node, ast.Import):
                out.update(a.name for a in node.names)
        return out
    for name in ("loads.py", "loadmodel.py", "loadtables.py", "loadrun.py", "loadbodies.py"):
        inner = {m for m in imported(root / name) if m.startswith(".")}
        assert inner <= {".errors", ".schema", ".units", ".loadmodel", ".reader", ".model",
                         ".loadeffort", ".loadtables", ".loadrun", ".loadbodies"}, \
            (name, inner)
    graph = {}
    for path in sorted((root / "forces").glob("*.py")):
        mods = imported(path)
        assert not any("diagrams" in m or "cli" in m for m in mods), path.name
        graph[path.stem] = {m[1:] for m in mods if m.startswith(".") and not m.startswith("..")}
    graph.pop("__init__")
    done: set = set()

    def visit(node, trail):
        assert node not in trail, " -> ".join(trail + [node])
        if node in done:
            return
        for nxt in graph.get(node, ()):
            visit(nxt, trail + [node])
        done.add(node)
    for node in graph:
        visit(node, [])


def test_the_turning_moment_numbers_do_not_depend_on_the_samples():
    """ΔE, the mean, the torque's extremes and E at the crossings of T = T_m are found to the
    precision of the construction (Brent's crossings, Gauss–Kronrod areas, golden-section
    extremes: polygons/forces/cycle.py), so 24 and 48 samples give the same numbers to
    1e-9 — where trapezoids of the samples are off in the third figure (the Scotch yoke:
    ΔE 40.2818 J; the old 360-sample trapezoids of the toggle press said 214.542 J for
    214.581 J)."""
    from polygons.forces.cycle import turning_moment
    scene = load_scene(str(CASES / "forces-scotch-yoke.toml"))
    model = load_model(scene)
    a, b = turning_moment(model, scene, 12), turning_moment(model, scene, 16)
    assert a.fluctuation == pytest.approx(b.fluctuation, rel=1e-9)
    assert a.mean == pytest.approx(b.mean, abs=1e-9 * a.fluctuation)
    assert a.max_torque[0] == pytest.approx(b.max_torque[0], rel=1e-9)
    assert a.min_torque[0] == pytest.approx(b.min_torque[0], rel=1e-9)
    assert math.remainder(a.at_max - b.at_max, 2 * math.pi) == pytest.approx(0, abs=1e-7)
    assert [e for _, e in a.crossings] == pytest.approx([e for _, e in b.crossings], rel=1e-9)
    sampled = float(np.max(b.energy) - np.min(b.energy))       # trapezoids of the samples
    assert abs(sampled - b.fluctuation) > 1e-3 * b.fluctuation
    assert max(b.torque) < b.max_torque[0]


def test_gravity_straight_down_has_no_sideways_noise():
    """[gravity] direction = "-90 deg" (the default) is (0, −g) exactly, not (6e-16, −9.81):
    polygons.units.cos_sin, as the exam's data and the topology's placements use it."""
    scene = load_scene(str(CASES / "forces-toggle-press.toml"))
    model = load_model(scene)
    assert model.parsed.gravity == (0.0, -9.81)
