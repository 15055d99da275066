"""Property tests: the polygons agree with independent closed-form loop solutions
(tests/analytic.py, complex-number loop closure differentiated by hand) on random
slider-cranks, four-bars and slotted levers, wherever the construction is well conditioned."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import analytic
from scenes import crank_driver, m, rad, slider_crank_case
from polygons.errors import AssemblyError, ParallelLinesError
from polygons.evaluate import solve
from polygons.scene import parse_scene

TOL = 1e-9
MIN_ANGLE = 1.0   # degrees: "well-conditioned"

lengths = st.floats(0.01, 1.0)
angles = st.floats(0.0, 2 * math.pi)
omegas = st.floats(0.5, 500.0) | st.floats(-500.0, -0.5)
alphas = st.floats(-1e4, 1e4)
settings_ = settings(max_examples=150, deadline=None,
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


@settings(max_examples=60, deadline=None)
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
    except (AssemblyError, ParallelLinesError, Exception) as exc:  # noqa: BLE001
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
