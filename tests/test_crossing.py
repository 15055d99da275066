"""Crossing slots: a pin in the slots of two moving levers (polygons/dyads/crossing.py),
against the independent loop solution tests/analytic_more.py crossing_slots."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import analytic_more as am
from polygons.errors import PolygonsError, SceneError
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_scene

CASE = Path(__file__).resolve().parents[1] / "cases" / "new-crossing-slots.toml"
REL = 1e-9


def reference(ad=0.1, r=0.04, ab=0.053, bo=0.08, theta=60.0, w=10.0, al=-20.0,
              near=0.06 + 0.07j):
    O2, O4 = am.fixed(0, 0), am.fixed(ad, 0)
    A = am.crank(O2, r, math.radians(theta), w, al)
    B, _, (w4, a4) = am.rrr(A, ab, O4, bo, near)
    P, s1, s2 = am.crossing_slots(O2, A, O4, B)
    return {"v(P)": abs(P[1]), "a(P)": abs(P[2]), "vs(P,P2)": s1[1], "vs(P,P4)": s2[1],
            "as(P,P2)": s1[2], "as(P,P4)": s2[2], "cor(P,P2)": abs(2 * w * s1[1]),
            "cor(P,P4)": abs(2 * w4 * s2[1]), "omega(O4B)": w4, "alpha(O4B)": a4,
            "x(P)": P[0].real, "y(P)": P[0].imag}


def scene_text(ad=0.1, r=0.04, ab=0.053, bo=0.08, theta=60.0, w=10.0, al=-20.0):
    return f"""
[ground]
O2 = ["0 mm", "0 mm"]
O4 = ["{ad * 1e3!r} mm", "0 mm"]
[links]
O2A = "{r * 1e3!r} mm"
AB = "{ab * 1e3!r} mm"
O4B = "{bo * 1e3!r} mm"
[driver]
crank = "O2A"
angle = "{theta!r} deg"
omega = "{abs(w)!r} rad/s {'CCW' if w >= 0 else 'CW'}"
alpha = "{abs(al)!r} rad/s^2 {'CCW' if al >= 0 else 'CW'}"
[assembly]
B = "B above O2O4"
[crossing.P]
levers = ["O2A", "O4B"]
coincident = ["P2", "P4"]
"""


def test_the_case_solves_to_the_independent_loop_solution():
    sol = solve(load_scene(CASE))
    for q, value in reference().items():
        assert quantity(sol, q) == pytest.approx(value, rel=REL, abs=1e-12), q


def test_the_case_exact_answers_come_from_the_loop_solution():
    ref = reference()
    scene = load_scene(CASE)
    assert len(scene.answers) >= 8
    for a in scene.answers:
        value = ref[a.quantity] if a.mode == "signed" else abs(ref[a.quantity])
        assert a.exact == pytest.approx(value, rel=1e-12), a.quantity


def test_finite_differences_of_the_pin_position():
    def pos(th):
        O2, O4 = am.fixed(0, 0), am.fixed(0.1, 0)
        A = am.crank(O2, 0.04, th, 10.0, -20.0)
        B, _, _ = am.rrr(A, 0.053, O4, 0.08, 0.06 + 0.07j)
        return am.crossing_slots(O2, A, O4, B)[0][0]
    v, a = am.fd_check(pos, math.radians(60), 10.0, -20.0)
    sol = solve(load_scene(CASE))
    assert np.allclose(sol.points["P"].velocity, am.vec(v), rtol=1e-6, atol=1e-8)
    assert np.allclose(sol.points["P"].acceleration, am.vec(a), rtol=1e-5, atol=1e-6)


def test_both_slides_and_both_coriolis_components_are_reported():
    sol = solve(load_scene(CASE))
    assert set(sol.slides) == {"P in O2A", "P in O4B"}
    ref = reference()
    s = sol.slides["P in O4B"]
    assert s.along == "O4B" and s.velocity == pytest.approx(ref["vs(P,P4)"], rel=REL)
    assert math.hypot(*s.coriolis) == pytest.approx(ref["cor(P,P4)"], rel=REL)


def test_the_model_holds_two_blocks_pinned_together_at_the_pin():
    m = load_scene(CASE).model
    blocks = [b for b in m.bodies if b.kind == "cross-block"]
    assert [b.name for b in blocks] == ["block P in O2A", "block P in O4B"]
    assert [(s.carrier, s.coincident) for s in m.crossings()] == [("O2A", "P2"), ("O4B", "P4")]
    assert ("P", ("block P in O2A", "block P in O4B")) in [(t.label, t.bodies)
                                                            for t in m.turning]


@settings(max_examples=25, deadline=None)
@given(theta=st.floats(20, 160), w=st.floats(-30, 30), al=st.floats(-100, 100),
       bo=st.floats(0.07, 0.09))
def test_random_instants_against_the_loop_solution(theta, w, al, bo):
    try:
        ref = reference(theta=theta, w=w, al=al, bo=bo)
    except ValueError:          # the four-bar does not close, or the slots are parallel
        return
    text = scene_text(theta=theta, w=w, al=al, bo=bo)
    try:
        sol = solve(parse_scene(tomllib.loads(text), file="t.toml"))
    except PolygonsError:       # the solver refuses near a toggle; the oracle may not
        return
    if sol.min_intersection_angle_deg < 5:
        return
    for q in ("v(P)", "a(P)", "vs(P,P2)", "vs(P,P4)", "as(P,P2)", "as(P,P4)", "x(P)"):
        scale = max(1.0, abs(ref["a(P)"])) if q.startswith("a") else 1.0
        assert quantity(sol, q) == pytest.approx(ref[q], rel=1e-8, abs=1e-10 * scale), q


def test_the_sweep_and_the_compiled_program_agree_with_the_staged_solve():
    from polygons.compiled import compile_scene
    from polygons.sweep import sweep
    scene = load_scene(CASE)
    sol = solve(scene)
    sw = sweep(scene, inputs=np.array([math.radians(60.0)]))
    assert np.allclose(sw.vel["P"][0][0], sol.points["P"].velocity[0], rtol=1e-12)
    assert np.allclose(sw.acc["P"][1][0], sol.points["P"].acceleration[1], rtol=1e-12)
    prog = compile_scene(scene)
    assert prog is not None


@pytest.mark.parametrize("change,words", [
    ('levers = ["O2A", "O4B"]', None),
    ('levers = ["O2A"]', "levers must name the two slotted levers"),
    ('levers = ["O2A", "O2A"]', "two different levers"),
    ('levers = ["O2A", "XY"]', "must be a link with a length"),
    ('levers = ["O2A", "AB"]\ncoincident = ["P2", "P3"]', None),
    ('levers = ["O2A", "O4B"]\ncoincident = ["P2", "A"]', "labels of their own"),
])
def test_bad_crossing_tables_are_refused_in_words(change, words):
    text = scene_text().replace('levers = ["O2A", "O4B"]\ncoincident = ["P2", "P4"]', change)
    if words is None:
        parse_scene(tomllib.loads(text), file="t.toml")
        return
    with pytest.raises(SceneError) as e:
        parse_scene(tomllib.loads(text), file="t.toml")
    assert words in str(e.value)


def test_parallel_slots_are_refused_in_words():
    # the crank along O2O4 at 0° and the rocker also along +x: the slots are parallel
    text = scene_text(theta=0.0, ad=0.1, r=0.04, ab=0.14, bo=0.08).replace(
        'B = "B above O2O4"', 'B = "B above O2O4"')
    with pytest.raises(PolygonsError) as e:
        solve(parse_scene(tomllib.loads(text), file="t.toml"))
    assert "parallel" in str(e.value) or "cannot" in str(e.value)


def test_forces_refuse_a_pin_in_two_slots_naming_both():
    text = scene_text() + '\n[masses.O4B]\nmass = "1 kg"\n'
    scene = parse_scene(tomllib.loads(text), file="t.toml")   # loads: its masses unused yet
    from polygons.forces.analysis import analyse
    with pytest.raises(PolygonsError) as e:
        analyse(scene)
    assert "polygons forces does not handle a pin sliding in the slots of two moving" in str(
        e.value)


def test_the_guard_names_the_command_the_user_ran(tmp_path, capsys):
    """A crossing-slots scene with a mass: centres, sweep and check take it (the masses are
    for the forces); solve and forces, which analyse the forces, refuse it in their own
    names (the guard once named `polygons forces` whatever the command)."""
    from polygons.cli import main
    path = tmp_path / "cx.toml"
    path.write_text(CASE.read_text(encoding="utf-8") + '\n[masses.AB]\nmass = "2 kg"\n',
                    encoding="utf-8")
    words = "does not handle a pin sliding in the slots of two moving levers"
    for cmd, extra in (("solve", ()), ("forces", ()), ("check", ("--measured", "Tin=1"))):
        assert main([cmd, str(path), *extra]) == 1
        err = capsys.readouterr().err
        assert f"polygons {cmd} {words}" in err and err.count("\n") == 1, err
    assert main(["centres", str(path), "-o", str(tmp_path / "c")]) == 0
    assert main(["check", str(path), "--measured", "v_P=1.0733"]) == 0
    assert main(["sweep", str(path), "--steps", "12", "-o", str(tmp_path / "s")]) == 0
    assert "does not handle" not in capsys.readouterr().err
