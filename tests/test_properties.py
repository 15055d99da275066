"""Property tests: the polygons agree with independent closed-form loop solutions
(tests/analytic.py, complex-number loop closure differentiated by hand) on random
slider-cranks, four-bars and slotted levers, wherever the construction is well conditioned."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import analytic
from conftest import examples
from scenes import crank_driver, m, rad, slider_crank_case
from polygons.errors import AssemblyError, BranchError, ParallelLinesError
from polygons.evaluate import solve
from polygons.scene import parse_scene

TOL = 1e-9
MIN_ANGLE = 1.0   # degrees: "well-conditioned"

lengths = st.floats(0.01, 1.0)
angles = st.floats(0.0, 2 * math.pi)
omegas = st.floats(0.5, 500.0) | st.floats(-500.0, -0.5)
alphas = st.floats(-1e4, 1e4)
# full depth 150 examples (60 for the finite differences): POLYGONS_DEEP=1 and CI run it, an
# everyday run a quarter (tests/conftest.py: examples)
settings_ = settings(max_examples=examples(150), deadline=None,
                     suppress_health_check=[HealthCheck.filter_too_much])


def close(ours, ref, scale):
    return float(np.hypot(*(np.asarray(ours) - np.asarray(ref)))) <= TOL * scale


@settings_
@given(r=lengths, ratio=st.floats(1.2, 6.0), theta=angles, omega=omegas, alpha=alphas,
       line_dir=angles, offset=st.floats(-0.8, 0.8), branch=st.sampled_from([1, -1]))
def test_slider_crank_matches_closed_form(r, ratio, theta, omega, alpha, line_dir, offset, branch):
    scene, ref = slider_crank_case(r, ratio, theta, omega, alpha, line_dir, offset, branch)
    L = r * ratio
    sol = solve(scene)
    assume(sol.min_intersection_angle_deg > MIN_ANGLE)
    vs, as_ = abs(omega) * r, (omega ** 2 + abs(alpha)) * r
    assert close(sol.points["B"].position, ref["B"], L)
    assert close(sol.points["B"].velocity, ref["vB"], vs)
    assert close(sol.points["B"].acceleration, ref["aB"], as_)
    assert abs(sol.links["AB"].omega - ref["omega_AB"]) <= TOL * vs / L
    assert abs(sol.links["AB"].alpha - ref["alpha_AB"]) <= TOL * as_ / L
    assert abs(sol.slides["B"].velocity - ref["s_dot"]) <= TOL * vs


@settings_
@given(ad=st.floats(0.2, 1.0), ab=lengths, bc=lengths, cd=lengths, theta=angles,
       omega=omegas, alpha=alphas)
def test_four_bar_matches_closed_form(ad, ab, bc, cd, theta, omega, alpha):
    try:
        ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, +1)
    except ValueError:
        assume(False)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"]},
        "links": {"AB": m(ab), "BC": m(bc), "CD": m(cd)},
        "driver": crank_driver("AB", theta, omega, alpha),
        "assembly": {"C": "C above AD"},
    })
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    except BranchError as e:
        # 'C above AD' names no closure when the other one lies on AD (a rhombus folded
        # onto A): refused in words, naming both, never a guess
        other = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, -1)["C"]
        assert abs(other[1]) <= 1e-9 * ad, e
        assert "C above AD" in str(e) and "both" in str(e)
        assume(False)
    assume(sol.min_intersection_angle_deg > MIN_ANGLE)
    vs, as_ = abs(omega) * ab, (omega ** 2 + abs(alpha)) * ab
    assert close(sol.points["C"].position, ref["C"], ad)
    assert close(sol.points["C"].velocity, ref["vC"], vs)
    assert close(sol.points["C"].acceleration, ref["aC"], as_)
    for link, key in (("BC", "BC"), ("CD", "CD")):
        assert abs(sol.links[link].omega - ref[f"omega_{key}"]) <= TOL * vs / min(bc, cd)
        assert abs(sol.links[link].alpha - ref[f"alpha_{key}"]) <= TOL * as_ / min(bc, cd) * 10


@settings_
@given(r=lengths, dist=st.floats(0.05, 2.0), theta=angles, omega=omegas, alpha=alphas,
       lever=st.floats(0.5, 3.0))
def test_slotted_lever_matches_closed_form(r, dist, theta, omega, alpha, lever):
    B = (0.0, -dist)
    try:
        ref = analytic.slotted_lever((0, 0), r, theta, omega, alpha, B)
    except ValueError:
        assume(False)
    assume(ref["s"] > 1e-3 * r)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"], "B": ["0 m", m(-dist)]},
        "links": {"OA": m(r), "BC": m(lever * (dist + r))},
        "driver": crank_driver("OA", theta, omega, alpha),
        "slots": {"A": {"lever": "BC", "coincident": "A1"}},
    })
    sol = solve(scene)
    vs, as_ = abs(omega) * r, (omega ** 2 + abs(alpha)) * r
    lev = sol.links["BC"]
    assert abs(lev.omega - ref["omega_lever"]) <= TOL * vs / ref["s"]
    assert abs(lev.alpha - ref["alpha_lever"]) <= TOL * (as_ + vs * vs / ref["s"]) / ref["s"]
    assert abs(sol.slides["A"].velocity - ref["s_dot"]) <= TOL * vs
    assert abs(sol.slides["A"].acceleration - ref["s_ddot"]) <= TOL * (as_ + vs * vs / ref["s"])
    assert close(sol.slides["A"].coriolis, ref["coriolis"], as_ + vs * vs / ref["s"])
    assert close(sol.points["A1"].velocity, ref["vA1"], vs)
    assert close(sol.points["A1"].acceleration, ref["aA1"], as_ + vs * vs / ref["s"])


@settings(max_examples=examples(60), deadline=None)
@given(ad=st.floats(0.2, 1.0), ab=lengths, bc=lengths, cd=lengths, theta=angles,
       omega=omegas)
def test_four_bar_velocity_matches_finite_differences_of_positions(ad, ab, bc, cd, theta, omega):
    """Independent of the closed form: differentiate our own position analysis numerically."""
    def scene_at(t):
        return parse_scene({
            "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"]},
            "links": {"AB": m(ab), "BC": m(bc), "CD": m(cd)},
            "driver": crank_driver("AB", t, omega, 0.0),
            "assembly": {"C": "C above AD"},
        })
    h = 1e-5
    try:
        sol = solve(scene_at(theta))
        cp = np.array(solve(scene_at(theta + h), targets=["C"]).points["C"].position)
        cm = np.array(solve(scene_at(theta - h), targets=["C"]).points["C"].position)
    except (AssemblyError, ParallelLinesError, Exception):  # noqa: BLE001
        assume(False)
    assume(sol.min_intersection_angle_deg > 5.0)
    v_fd = (cp - cm) / (2 * h) * omega
    scale = abs(omega) * ab
    assert float(np.hypot(*(np.array(sol.points["C"].velocity) - v_fd))) <= 1e-5 * scale


@pytest.mark.parametrize("theta", [0.3, 1.9, 4.0])
def test_slider_driver_recovers_the_crank_motion(theta):
    """Drive a slider-crank from its piston with the closed form's s, ṡ, s̈ (crank at constant
    ω = 7 rad/s): the polygons must give back ω = 7 and α = 0 for the crank."""
    r, L, omega = 0.05, 0.17, 7.0
    ref = analytic.slider_crank((0, 0), r, L, theta, omega, 0.0, (0, 0), 0.0, +1)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]},
        "links": {"OA": m(r), "AB": m(L)},
        "sliders": {"B": {"through": ["0 m", "0 m"], "direction": "0 deg"}},
        "driver": {"slider": "B", "position": m(ref["s"]),
                   "velocity": f"{float(ref['s_dot'])!r} m/s",
                   "acceleration": f"{float(ref['s_ddot'])!r} m/s^2"},
        "assembly": {"A": {"near": [m(ref["A"][0]), m(ref["A"][1])]}},
    })
    sol = solve(scene)
    assert sol.links["OA"].omega == pytest.approx(omega, rel=1e-9)
    assert abs(sol.links["OA"].alpha) <= 1e-9 * omega ** 2
    assert sol.links["AB"].omega == pytest.approx(ref["omega_AB"], rel=1e-9)


@settings_
@given(ad=st.floats(0.2, 1.0), ab=lengths, bc=lengths, cd=lengths, theta=angles,
       omega=omegas, alpha=alphas,
       along=st.floats(-1.0, 2.0).filter(lambda v: v == 0 or abs(v) > 1e-5),
       left=st.floats(-1.0, 1.0).filter(lambda v: v == 0 or abs(v) > 1e-5))
def test_coupler_point_image_matches_closed_form(ad, ab, bc, cd, theta, omega, alpha, along,
                                                 left):
    """Image dyad: a point rigid with the coupler ([points.P] on BC), against the loop
    closure's ω₃, α₃ carried to the point by hand (analytic.coupler_point)."""
    try:
        ref4 = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, +1)
    except ValueError:
        assume(False)
    ref = analytic.coupler_point(ref4["B"], ref4["vB"], ref4["aB"], ref4["phi_BC"],
                                 ref4["omega_BC"], ref4["alpha_BC"], along * bc, left * bc)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"]},
        "links": {"AB": m(ab), "BC": m(bc), "CD": m(cd)},
        "points": {"P": {"on": "BC", "along": m(along * bc), "left": m(left * bc)}},
        "driver": crank_driver("AB", theta, omega, alpha),
        "assembly": {"C": "C above AD"},
    })
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > MIN_ANGLE)
    bp = bc * math.hypot(along, left)
    w3, a3 = abs(ref4["omega_BC"]), abs(ref4["alpha_BC"])
    vscale = np.hypot(*ref4["vB"]) + abs(ref4["omega_CD"]) * cd + w3 * bp   # the terms' sizes
    ascale = (np.hypot(*ref4["aB"]) + (abs(ref4["alpha_CD"]) + ref4["omega_CD"] ** 2) * cd
              + (a3 + w3 * w3) * bp)
    assert close(sol.points["P"].position, ref["P"], ad + bc + bp)
    assert close(sol.points["P"].velocity, ref["vP"], vscale)
    assert close(sol.points["P"].acceleration, ref["aP"], ascale)


@settings_
@given(r=lengths, theta=angles, omega=omegas, alpha=alphas, guide=angles,
       slot=st.floats(0.2, math.pi - 0.2), gx=st.floats(-1, 1), gy=st.floats(-1, 1))
def test_scotch_yoke_matches_closed_form(r, theta, omega, alpha, guide, slot, gx, gy):
    """RPP dyad (Scotch yoke) on a guide at any angle, its slot at any angle to it."""
    slot_dir = guide + slot
    ref = analytic.scotch_yoke((0, 0), r, theta, omega, alpha, (gx, gy), guide, slot_dir)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]},
        "links": {"OP": m(r)},
        "driver": crank_driver("OP", theta, omega, alpha),
        "sliders": {"Y": {"through": [m(gx), m(gy)], "direction": rad(guide), "pin": "P",
                          "slot": rad(slot_dir)}},
    })
    sol = solve(scene)
    vs, as_ = abs(omega) * r / math.sin(slot), (omega ** 2 + abs(alpha)) * r / math.sin(slot)
    assert close(sol.points["Y"].position, ref["Y"], 2 + r / math.sin(slot))
    assert close(sol.points["Y"].velocity, ref["vY"], vs)
    assert close(sol.points["Y"].acceleration, ref["aY"], as_)
    assert abs(sol.slides["Y"].velocity - ref["t_dot"]) <= TOL * vs
