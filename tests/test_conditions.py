"""Conditions as questions ([[questions]], polygons/conditions.py): the roots the construction
finds against closed forms of the slider-crank whose roots are found here by bisection."""
import math

import pytest

from conftest import ROOT
from polygons import conditions
from polygons.conditions import brent
from polygons.scene import load_scene

ENGINE = ROOT / "cases" / "question-engine-conditions.toml"
OFFSET = ROOT / "cases" / "question-offset-quick-return.toml"


def bisect(g, a, b, iters=200):
    ga = g(a)
    for _ in range(iters):
        m = 0.5 * (a + b)
        gm = g(m)
        if gm == 0 or b - a < 1e-15:
            return m
        if (gm > 0) == (ga > 0):
            a, ga = m, gm
        else:
            b = m
    return 0.5 * (a + b)


# the slider-crank: O at the origin, the line of stroke y = e, P left of the crank pin
def x_p(t, r, l, e=0.0):
    return r * math.cos(t) - math.sqrt(l * l - (e - r * math.sin(t)) ** 2)


def dx(t, r, l):                  # in-line: dx/dθ
    s = math.sqrt(l * l - (r * math.sin(t)) ** 2)
    return -r * math.sin(t) + r * r * math.sin(t) * math.cos(t) / s


def ddx(t, r, l):                 # in-line: d²x/dθ²
    s = math.sqrt(l * l - (r * math.sin(t)) ** 2)
    sc = math.sin(t) * math.cos(t)
    return -r * math.cos(t) + r * r * math.cos(2 * t) / s + r ** 4 * sc * sc / s ** 3


def _engine_closed_form():
    r, l, m, F = 0.04, 0.14, 0.5, 2000.0
    w = 3000 * 2 * math.pi / 60
    t1 = bisect(lambda t: ddx(t, r, l), math.radians(60), math.radians(120))
    t2 = 2 * math.pi - t1
    vmax = w * abs(dx(t1, r, l))
    # gudgeon pin: Rx = F − m ω² x''(θ) at θ = 135°, zero at ω² = F / (m x'')
    w0 = math.sqrt(F / (m * ddx(math.radians(135), r, l)))
    return {0: ([math.degrees(t1), math.degrees(t2)], [vmax, vmax]),
            1: ([math.degrees(t1), math.degrees(t2)], None),
            2: ([2 * r * 1e3], None), 3: ([0.0, 180.0], None),
            4: ([w0 * 60 / (2 * math.pi)], None)}


def _offset_closed_form():
    r, l, e = 0.04, 0.14, 0.02
    far, near = math.sqrt((l + r) ** 2 - e * e), math.sqrt((l - r) ** 2 - e * e)
    t_far = math.atan2(e, -far)                 # crank along O → P
    t_near = math.atan2(e, -near) + math.pi     # crank folded back on the rod
    dead = sorted(math.degrees(t) % 360.0 for t in (t_far, t_near))
    turn = (t_far - t_near) % (2 * math.pi)     # crank CW from the near to the far dead centre
    ratio = max(turn, 2 * math.pi - turn) / min(turn, 2 * math.pi - turn)
    g = lambda t: x_p(t, r, l, e) + 0.15        # noqa: E731
    t_lo = bisect(g, t_near - 2 * math.pi, t_far)          # on each stroke once
    t_hi = bisect(g, t_far, t_near)
    roots = sorted(math.degrees(t) % 360.0 for t in (t_lo, t_hi))
    return {0: ([(far - near) * 1e3], None), 1: (dead, None), 2: ([ratio], None),
            3: (roots, None)}


@pytest.mark.parametrize("path,closed", [(ENGINE, _engine_closed_form),
                                         (OFFSET, _offset_closed_form)],
                         ids=["question-engine-conditions", "question-offset-quick-return"])
def test_question_cases_exact_values_are_the_closed_form_and_ours(path, closed):
    """Each question's `exact` (and `value_exact`) is the closed form's (to 1e-12), and the
    construction's roots, polished by Brent's method, agree with it to 1e-9."""
    scene = load_scene(path)
    want = closed()
    (answer,) = scene.answers            # the instant's answer, from the same closed form
    instant = {ENGINE: 3000 * math.pi / 30 * abs(dx(math.radians(135), 0.04, 0.14)),
               OFFSET: x_p(math.radians(60), 0.04, 0.14, 0.02) * 1e3}[path]
    assert answer.exact == pytest.approx(instant, rel=1e-12)
    if path == ENGINE:      # "the piston effort": F_P = F − m ω² x''(θ) along the stroke
        (fp,) = scene.loads.answers
        w = 3000 * math.pi / 30
        assert fp.exact == pytest.approx(2000 - 0.5 * w * w * ddx(math.radians(135), 0.04,
                                                                  0.14), rel=1e-12)
        from polygons.forces import analyse, force_quantity
        assert force_quantity(analyse(scene), "Fp(P)") == pytest.approx(fp.exact, rel=1e-9)
    qs = conditions.scene_questions(scene)
    assert len(qs) == len(want)
    for q in qs:
        roots, values = want[q.index]
        assert q.exact == pytest.approx(roots, rel=1e-12, abs=1e-10), q.desc
        if values is not None:
            assert q.value_exact == pytest.approx(values, rel=1e-12), q.desc
        f = conditions.answer(scene, q)
        c = conditions.check(f)
        assert c.exact_ok, (q.desc, f.reported(), q.exact, c.worst_rel)
        assert c.value_ok in (None, True), (q.desc, f.values())


def test_brent_finds_a_root_to_full_precision():
    x = brent(lambda x: math.cos(x) - x, 0.0, 1.0)
    assert abs(math.cos(x) - x) < 1e-15
    with pytest.raises(ValueError):
        brent(lambda x: x * x + 1, -1.0, 1.0)


def test_the_table_knows_the_kinematic_functions_of_the_scene():
    from polygons.question_table import KINEMATIC
    from polygons.scene import QUANTITY_FUNCTIONS
    assert KINEMATIC == QUANTITY_FUNCTIONS


def _with(path, **question):
    import tomllib
    from polygons.scene import parse_scene
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data["questions"] = [question]
    return parse_scene(data, file=str(path))


def test_a_condition_that_never_holds_is_said_in_words():
    """'where is the piston 300 mm from O' (beyond its reach: |OP| ≤ l + r = 180 mm)."""
    scene = _with(OFFSET, find="angle", quantity="x(P)", condition="value", value="-300 mm",
                  unit="deg", samples=24)
    (f,) = conditions.answer_all(scene)
    assert f.roots == () and "never equals -0.3 over the whole turn" in f.words
    scene = _with(ENGINE, find="angle", quantity="v(P)", condition="zero", unit="deg",
                  samples=24)
    (f,) = conditions.answer_all(scene)
    assert f.roots == () and "a magnitude" in f.words


def test_the_least_speed_over_a_range_and_its_end():
    """min of v(P) between 30° and 90°: the piston slows towards the dead centre at 0°, so the
    least speed in the range is at its 30° end (v = ω |x'(30°)|)."""
    scene = _with(ENGINE, find="angle", quantity="v(P)", condition="min",
                  range=["30 deg", "90 deg"], unit="deg", samples=16)
    (f,) = conditions.answer_all(scene)
    (root,) = f.roots
    assert root.kind == "min" and math.degrees(root.input) == pytest.approx(30.0, abs=1e-12)
    w = 3000 * math.pi / 30
    assert root.value == pytest.approx(w * abs(dx(math.radians(30), 0.04, 0.14)), rel=1e-9)


@pytest.mark.parametrize("question,words", [
    ({"find": "when", "quantity": "v(P)", "condition": "max", "unit": "deg"}, "find must be"),
    ({"find": "angle", "quantity": "v(P)", "condition": "biggest", "unit": "deg"},
     "condition must be"),
    ({"find": "omega", "quantity": "v(P)", "condition": "max", "unit": "rad/s"},
     "needs range"),
    ({"find": "angle", "quantity": "v(P)", "condition": "value", "unit": "deg"},
     "needs value"),
    ({"find": "angle", "quantity": "v(P)", "condition": "max", "unit": "deg",
      "samples": 10 ** 9}, "samples must be"),
    ({"find": "angle", "quantity": "v(P)", "condition": "max", "unit": "mm"},
     "not a unit of angle"),
    ({"find": "angle", "quantity": "q(P)", "condition": "max", "unit": "deg"}, None),
    ({"find": "position", "quantity": "v(P)", "condition": "max", "unit": "mm",
      "range": ["0 mm", "1 mm"]}, "needs a slider driver"),
])
def test_a_bad_question_is_refused_at_load_in_one_line(question, words):
    from polygons.errors import SceneError
    if words is None:           # an unknown function: refused when answered, naming it
        scene = _with(OFFSET, **question)
        with pytest.raises(SceneError, match="no force tables"):
            conditions.answer_all(scene)
        return
    with pytest.raises(SceneError, match=words):
        _with(OFFSET, **question)


def test_ask_command_answers_and_narrates_the_construction_at_a_root(tmp_path):
    import json
    from polygons.cli import main
    out = tmp_path / "a.txt"
    assert main(["ask", str(OFFSET), "--show", "4:2", "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "time ratio = 1.059" in text and "exact: 80.9058 ✓" in text
    assert "The construction at root 2 of question 4" in text and "-150.0000" in text
    assert main(["ask", str(OFFSET), "--json", "-o", str(tmp_path / "a.json")]) == 0
    data = json.loads((tmp_path / "a.json").read_text(encoding="utf-8"))
    assert [q["exact_ok"] for q in data["questions"]] == [True] * 4
    assert main(["ask", str(OFFSET), "--show", "9"]) == 1
    assert main(["ask", str(ROOT / "cases" / "s001-we1.toml")]) == 1


# ------------------------------------------------------------------ ratios as answers
RATIO = ROOT / "cases" / "ratio-four-bar.toml"


def test_ratio_case_exact_answers_are_the_closed_form_and_kennedy():
    """v_C / v_B and ω_CD / ω_AB from the closed-form four-bar; ω_CD / ω_AB also by Kennedy's
    theorem: I24 on AD produced where BC meets it, ω4 / ω2 = A I24 / D I24 (signed)."""
    import analytic
    import numpy as np
    from polygons.evaluate import solve
    from polygons.report import check_answers
    fb = analytic.four_bar((0, 0), (0.45, 0), 0.1, 0.4, 0.35, math.radians(90), 12.0, 0.0, +1)
    B, C = np.array(fb["B"]), np.array(fb["C"])
    x_i = B[0] - B[1] * (C[0] - B[0]) / (C[1] - B[1])          # BC produced meets y = 0
    kennedy = (x_i - 0.0) / (x_i - 0.45)
    want = {"v(C) / v(B)": float(np.hypot(*fb["vC"]) / np.hypot(*fb["vB"])),
            "omega(CD) / omega(AB)": fb["omega_CD"] / 12.0,
            "omega(AB) / omega(CD)": 12.0 / fb["omega_CD"]}
    assert want["omega(CD) / omega(AB)"] == pytest.approx(kennedy, rel=1e-12)
    # "the distance of I13 from C": I13 where AB (x = 0) meets DC produced, in mm
    D = np.array([0.45, 0.0])
    i13 = D + (0.0 - D[0]) / (C[0] - D[0]) * (C - D)
    want["dist(I13,C)"] = float(np.hypot(*(C - i13))) * 1e3
    assert want["dist(I13,C)"] / 1e3 * abs(fb["omega_BC"]) == pytest.approx(
        float(np.hypot(*fb["vC"])), rel=1e-12)               # v_C = ω_BC · I13C
    scene = load_scene(RATIO)
    assert {a.quantity: a.exact for a in scene.answers} == pytest.approx(want, rel=1e-12)
    for c in check_answers(solve(scene)):
        assert c.compared == pytest.approx(c.answer.exact, rel=1e-9), c.answer.quantity


def test_an_unknown_or_infinite_instant_centre_is_refused_in_words():
    """'the distance of I19 from C' in a four-bar (links 1 … 4); a slider's I14 at infinity."""
    from polygons.errors import PolygonsError
    from polygons.evaluate import solve
    from polygons.quantities import quantity
    with pytest.raises(PolygonsError, match="numbered 1 … 4"):
        quantity(solve(load_scene(RATIO)), "dist(I19,C)")
    with pytest.raises(PolygonsError, match="at infinity"):
        quantity(solve(load_scene(OFFSET)), "dist(I14,O)")


def test_a_ratio_of_two_kinds_is_refused_at_load_and_a_force_ratio_works():
    import tomllib
    from polygons.errors import SceneError
    from polygons.forces import analyse, force_quantity
    from polygons.scene import parse_scene
    data = tomllib.loads(RATIO.read_text(encoding="utf-8"))
    data["answers"][0]["quantity"] = "v(C) / omega(AB)"
    with pytest.raises(SceneError, match="a ratio of a velocity to an angular velocity"):
        parse_scene(data, file="r.toml")
    an = analyse(load_scene(ROOT / "cases" / "efficiency-four-bar.toml"))
    # the input torque by Newton–Euler over that by virtual work: one
    assert force_quantity(an, "Tin / Tin_vw") == pytest.approx(1.0, rel=1e-9)
    assert force_quantity(an, "Tin / Tin") == 1.0


def test_a_ratio_is_graded_like_any_other_answer(capsys):
    from polygons.cli import main
    assert main(["check", str(RATIO), "--measured", "v(C)/v(B)=0.85"]) == 0
    assert main(["check", str(RATIO), "--measured", "v(C)/v(B)=0.95"]) == 3


def test_a_question_on_a_cam_is_refused_in_words():
    """A cam stated by its centre of curvature ([cams]) is that instant's linkage only (a cam
    stated by its profile is answered: test_cam_profiles)."""
    import tomllib
    from polygons.errors import SceneError
    from polygons.scene import parse_scene
    path = ROOT / "cases" / "cam-roller-follower.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data["questions"] = [{"find": "angle", "quantity": "vs(R)", "condition": "max",
                          "unit": "deg"}]
    with pytest.raises(SceneError, match="at this instant only"):
        conditions.answer_all(parse_scene(data, file=str(path)))


def test_a_crossing_says_the_value_asked_not_its_rounding_noise():
    """The piston's acceleration changes sign where its speed is greatest: the root's value
    is 0 (the residual left by Brent's method, ~1e-12 m/s², is the construction's rounding,
    not a number to print), and the gudgeon pin's load reverses at 0 N."""
    from polygons.conditions import answer_all, report_lines
    scene = load_scene(str(ROOT / "cases" / "question-engine-conditions.toml"))
    found = answer_all(scene)
    crossings = [r for f in found for r in f.roots if r.kind == "crossing"]
    assert crossings and all(r.value == 0.0 for r in crossings)
    assert not any("e-1" in line for line in report_lines(found))
