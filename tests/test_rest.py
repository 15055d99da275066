"""Instants at rest (ω = 0, with or without α): the velocity polygon collapses to the pole, the
acceleration polygon holds tangential (and given) components only, and the lines through the
pole are met there, not refused as a toggle.  Exact values from tests/analytic.py."""
import math

import numpy as np
import pytest

import analytic as an
from conftest import CASES
from polygons.narrate import substitute
from polygons.evaluate import solve
from polygons.scene import load_scene
import tomllib

from polygons.scene import parse_scene
from scenes import four_bar_text


def scene_from_text(text):
    return parse_scene(tomllib.loads(text))

REL = 1e-9


def test_the_shipped_rest_case_agrees_with_the_loop_closure():
    sol = solve(load_scene(CASES / "rest-slider-crank.toml"))
    ref = an.slider_crank((0, 0), 0.1, 0.4, math.radians(45), 0.0, 200.0, (0, 0), 0.0, +1)
    for label in ("A", "B"):
        assert sol.points[label].velocity == (0.0, 0.0)
    np.testing.assert_allclose(sol.points["B"].acceleration, ref["aB"], rtol=REL, atol=1e-12)
    np.testing.assert_allclose(sol.points["A"].acceleration, ref["aA"], rtol=REL, atol=1e-12)
    assert sol.links["AB"].alpha == pytest.approx(ref["alpha_AB"], rel=REL)
    assert any("at rest" in w for w in sol.warnings)
    # every centripetal component is zero: each centripetal step's vector vanishes
    cen = [s for s in sol.steps if s.op == "centripetal"]
    assert cen and all(s.vector == (0.0, 0.0) for s in cen)


FOURBAR = four_bar_text('angle = "{angle} deg"\nomega = "0 rad/s"\nalpha = "{alpha} rad/s^2"\n'
                        'alpha_sense = "CW"', side="below")


@pytest.mark.parametrize("angle,alpha", [(300, 200), (30, 1), (123.4, 5e3)])
def test_a_four_bar_at_rest_matches_the_loop_closure(angle, alpha):
    sol = solve(scene_from_text(FOURBAR.format(angle=angle, alpha=alpha)))
    C = np.array(sol.points["C"].position)
    branch = 1 if 0.2 * C[1] > 0 else -1          # cross(D − A, C − A) with A at O
    ref = an.four_bar((0, 0), (0.2, 0), 0.08, 0.136, 0.16, math.radians(angle), 0.0, -alpha,
                      branch)
    assert sol.points["C"].velocity == (0.0, 0.0)
    np.testing.assert_allclose(sol.points["C"].acceleration, ref["aC"], rtol=REL)
    assert sol.links["BC"].alpha == pytest.approx(ref["alpha_BC"], rel=REL)
    assert sol.links["CD"].alpha == pytest.approx(ref["alpha_CD"], rel=REL)
    assert sol.links["BC"].omega == 0.0 and sol.links["CD"].omega == 0.0


def test_a_slotted_lever_at_rest_has_no_coriolis_and_exact_alpha():
    text = """
[ground]
O4 = ["0 m", "0 m"]
O2 = ["0 m", "0.45 m"]
[links]
O2P2 = "0.20 m"
[driver]
crank = "O2P2"
angle = "19.7 deg"
omega = "0 rad/s"
alpha = "10 rad/s^2"
alpha_sense = "CCW"
[slots.P2]
lever = "O4P4"
"""
    sol = solve(scene_from_text(text))
    ref = an.slotted_lever((0, 0.45), 0.2, math.radians(19.7), 0.0, 10.0, (0, 0))
    assert sol.slides["P2"].coriolis == (0.0, 0.0) or np.allclose(sol.slides["P2"].coriolis, 0)
    assert sol.links["O4P4"].alpha == pytest.approx(ref["alpha_lever"], rel=REL)
    assert sol.links["O4P4"].omega == 0.0


def test_a_translating_coupler_prints_zero_not_rounding_noise():
    """A parallelogram's coupler translates: its ω and α are zero; the construction leaves
    ~1e-15, which the table prints as 0 with no sense (the JSON keeps the computed number)."""
    from polygons.report import table
    from polygons.scene import parse_scene
    scene = parse_scene({"ground": {"A": ["0 mm", "0 mm"], "D": ["100 mm", "0 mm"]},
                         "links": {"AB": "40 mm", "BC": "100 mm", "CD": "40 mm"},
                         "driver": {"crank": "AB", "angle": "60 deg", "speed": "0.4 m/s CW"},
                         "assembly": {"C": "C above AD"}})
    sol = solve(scene)
    assert abs(sol.links["BC"].omega) < 1e-13
    row = next(line for line in table(sol).splitlines() if line.startswith("BC "))
    assert row.split()[2:] == ["0", "0"], row
    row = next(line for line in table(sol).splitlines() if line.startswith("AB "))
    assert row.split()[2:4] == ["10", "CW"], row


def test_the_worked_steps_print_zero_too():
    """The same rule in the construction's worked lines: ω_BC = 0 / 0.1 = 0 rad/s, no sense,
    no 1e-15 (the staged steps and the compiled ones alike)."""
    from polygons.compiled import compile_scene
    from polygons.scene import parse_scene
    scene = parse_scene({"ground": {"A": ["0 mm", "0 mm"], "D": ["100 mm", "0 mm"]},
                         "links": {"AB": "40 mm", "BC": "100 mm", "CD": "40 mm"},
                         "driver": {"crank": "AB", "angle": "60 deg", "omega": "10 rad/s CW"},
                         "assembly": {"C": "C above AD"}})
    for steps in (solve(scene).steps, compile_scene(scene).solve().steps):
        w = next(s for s in steps if s.op == "omega" and s.args[0] == "BC")
        text = substitute(w, scene)
        assert w.value == 0.0 and text.endswith("= 0 rad/s"), text
        cd = next(s for s in steps if s.op == "omega" and s.args[0] == "CD")
        assert cd.value == pytest.approx(-10.0, rel=1e-12)
