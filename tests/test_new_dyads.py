"""The dyad kinds of issue 10 — a prescribed slide (second input), a pin in the slot of a
driven lever (inverted slider-crank driven by its guide), an offset slot, a slot on a lever
with a moving pivot — and the six-bars, quick returns and presses built on ternary links:
every case against the independent loop-closure check (tests/analytic_more.py), the sweep
against the staged solver, and random instances of every new kind (hypothesis)."""
import math

import numpy as np
import pytest

from polygons.mobility import MobilityError
from polygons.errors import BranchError
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import analytic
import analytic_more as am
from conftest import CASES
from scenes import crank_driver, m
from polygons.errors import AssemblyError, ParallelLinesError, SceneError
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_scene
from polygons.sweep import sweep

REL = 1e-9
DEG = math.radians


# ---------------------------------------------------------------- the cases' references
def _pt(z):
    return z[0]


def ref_collar():
    C = am.collar(am.fixed(0, 0), DEG(30), 5.0, 0.0, 0.4, 1.5, -0.8)
    C1 = am.crank(am.fixed(0, 0), 0.4, DEG(30), 5.0, 0.0)
    return {"v(C)": abs(C[1]), "a(C)": abs(C[2]), "v(C1)": abs(C1[1]), "a(C1)": abs(C1[2]),
            "cor(C)": 2 * 5.0 * 1.5, "v(C,C1)": 1.5, "x(C)": C[0].real, "y(C)": C[0].imag}


def _guided_refs(P0, L, B, phi, w, al, d, near, link, pin):
    X, (wt, at), (t, td, tdd), cor, X1 = am.guided(P0, L, B, phi, w, al, d, near)
    return {f"omega({link})": wt, f"alpha({link})": at, f"vs({pin})": td, f"as({pin})": tdd,
            f"cor({pin})": abs(cor), f"v({pin})": abs(X[1]), f"a({pin})": abs(X[2]),
            f"x({pin})": X[0].real, f"y({pin})": X[0].imag}


def ref_oscillating():
    return _guided_refs(am.fixed(0, 0), 0.1, am.fixed(0.3, 0), DEG(170), -2.0, 5.0, 0.0,
                        0.093 + 0.036j, "O2P", "P")


def ref_rotary():
    w = 1200 * 2 * math.pi / 60
    return _guided_refs(am.fixed(0.05, 0), 0.2, am.fixed(0, 0), DEG(60), w, 0.0, 0.0,
                        0.11 + 0.19j, "CP", "P")


def _slot_refs(A, B, d, lever, pin, far, length):
    r = am.slot(A, B, d)
    Q = am.lever_point(B, r["phi"], r["omega"], r["alpha"], length)
    return r, Q, {f"omega({lever})": r["omega"], f"alpha({lever})": r["alpha"],
                  f"vs({pin})": r["t_dot"], f"as({pin})": r["t_ddot"],
                  f"cor({pin})": abs(r["coriolis"]), f"v({far})": abs(Q[1]),
                  f"a({far})": abs(Q[2])}


def ref_offset():
    A = am.crank(am.fixed(0, 0), 0.1, DEG(30), 10.0, 0.0)
    return _slot_refs(A, am.fixed(0, -0.2), 0.02, "BQ", "A", "Q", 0.5)[2]


def _quick_return(r, theta, w, C, arm, rod, guide_y, near_R, lever="CD", far="D"):
    A = am.crank(am.fixed(0, 0), r, theta, w, 0.0)
    s, D, out = _slot_refs(A, C, 0.0, lever, "A", far, arm)
    R, (wr, ar), (sR, vR, aR) = am.rrp(D, rod, complex(0, guide_y), 0.0, near_R)
    out.update({"vs(R)": vR, "as(R)": aR, "omega(DR)": wr, "alpha(DR)": ar})
    return out


def ref_whitworth():
    return _quick_return(0.15, DEG(60), -math.pi, am.fixed(0, -0.1), 0.125, 0.5, -0.1,
                         -0.45 - 0.1j)


def ref_shaper():
    return _quick_return(0.1, DEG(120), 10.0, am.fixed(0, -0.3), 0.5, 0.15, 0.25,
                         -0.2 + 0.25j)


def ref_watt():
    B = am.crank(am.fixed(0, 0), 0.06, DEG(75), 20.0, -50.0)
    C, (wbc, abc), (wdc, adc) = am.rrr(B, 0.18, am.fixed(0.2, 0), 0.12, 0.18 + 0.12j)
    E = am.image(am.fixed(0.2, 0), C, 0.08, -0.06)
    F, (wef, aef), (wgf, agf) = am.rrr(E, 0.2, am.fixed(0.42, 0.04), 0.11, 0.44 + 0.15j)
    return {"omega(DC)": wdc, "alpha(DC)": adc, "omega(EF)": wef, "alpha(EF)": aef,
            "omega(GF)": wgf, "alpha(GF)": agf, "v(E)": abs(E[1]), "a(E)": abs(E[2]),
            "v(F)": abs(F[1]), "a(F)": abs(F[2])}


def ref_stephenson():
    B = am.crank(am.fixed(0, 0), 0.08, DEG(60), -15.0, 0.0)
    C, (wbc, abc), (wdc, adc) = am.rrr(B, 0.22, am.fixed(0.25, 0), 0.15, 0.245 + 0.15j)
    E = am.image(B, C, 0.11, 0.07)
    F, (wef, aef), (wgf, agf) = am.rrr(E, 0.16, am.fixed(0.15, 0.3), 0.12, 0.2585 + 0.249j)
    return {"omega(BC)": wbc, "alpha(BC)": abc, "omega(GF)": wgf, "alpha(GF)": agf,
            "omega(EF)": wef, "alpha(EF)": aef, "v(E)": abs(E[1]), "a(E)": abs(E[2]),
            "v(F)": abs(F[1]), "a(F)": abs(F[2])}


def ref_toggle():
    w = 200 * 2 * math.pi / 60
    A = am.crank(am.fixed(0, 0), 0.08, DEG(45), w, 0.0)
    B, (wab, aab), (wcb, acb) = am.rrr(A, 0.32, am.fixed(0.3, 0.25), 0.2, 0.38 + 0.07j)
    D, (wbd, abd), (s, vD, aD) = am.rrp(B, 0.22, complex(0.3, 0), DEG(90), 0.3 - 0.14j)
    return {"omega(AB)": wab, "omega(CB)": wcb, "alpha(CB)": acb, "omega(BD)": wbd,
            "alpha(BD)": abd, "vs(D)": vD, "as(D)": aD}


def ref_trammel():
    L, s, sd, sdd = 0.4, 0.2, 2.0, -5.0
    Bz = am.trammel(L, s, sd, sdd)
    A = (complex(s, 0), complex(sd, 0), complex(sdd, 0))
    C = am.image(A, Bz, 0.15)
    w, al = am.rates(A, Bz)
    return {"vs(B)": Bz[1].imag, "as(B)": Bz[2].imag, "omega(AB)": w, "alpha(AB)": al,
            "v(C)": abs(C[1]), "a(C)": abs(C[2])}


MOVING_ANGLE = 90.0


def ref_moving_lever():
    A = am.crank(am.fixed(0, 0), 0.1, DEG(MOVING_ANGLE), -10.0, 0.0)
    O4 = am.fixed(0.1, -0.2)
    Q, _, _ = am.rrr(A, 0.3, O4, 0.3, 1e3 - 0.2j)              # Q right of O4
    w, al = am.rates(O4, Q)
    phi = math.atan2((Q[0] - O4[0]).imag, (Q[0] - O4[0]).real)
    out = _guided_refs(am.fixed(0.3, 0), 0.15, O4, phi, w, al, 0.0, 0.3 + 1e3j,  # P above O2
                       "O2P", "P")
    out.update({"omega(O4Q)": w, "alpha(O4Q)": al})
    return out


def ref_engine_from_idc():
    """In-line engine, cylinder on +x: IDC is the crank along +x; 60° clockwise from it is
    θ = −60°; the loop closure of tests/analytic.py with B on the +x side (branch +1)."""
    w = -450 * 2 * math.pi / 60
    ref = analytic.slider_crank((0, 0), 0.15, 0.6, -DEG(60), w, 0.0, (0, 0), 0.0, +1)
    return {"vs(P)": ref["s_dot"], "as(P)": ref["s_ddot"], "omega(CP)": ref["omega_AB"],
            "alpha(CP)": ref["alpha_AB"], "v(C)": 0.15 * abs(w)}


REFS = {
    "new-engine-from-idc": ref_engine_from_idc,
    "new-slot-on-moving-lever": ref_moving_lever,
    "new-collar-on-rotating-rod": ref_collar,
    "new-oscillating-cylinder": ref_oscillating,
    "new-rotary-engine": ref_rotary,
    "new-offset-slot": ref_offset,
    "new-whitworth": ref_whitworth,
    "new-shaper-ram": ref_shaper,
    "new-watt-six-bar": ref_watt,
    "new-stephenson-six-bar": ref_stephenson,
    "new-toggle-press": ref_toggle,
    "new-elliptic-trammel": ref_trammel,
}
UNITS = {"mm": 1e-3}


def _si(answer) -> float:
    return answer.exact * UNITS.get(answer.unit, 1.0)


@pytest.mark.parametrize("case", sorted(REFS))
def test_case_solves_to_the_analytic_check(case):
    """Every reference value of the independent check agrees with the solver to 1e-9."""
    sol = solve(load_scene(CASES / f"{case}.toml"))
    ref = REFS[case]()
    for q, value in ref.items():
        ours = quantity(sol, q)
        assert ours == pytest.approx(value, rel=REL, abs=1e-12), (q, ours, value)


@pytest.mark.parametrize("case", sorted(REFS))
def test_case_exact_answers_are_the_analytic_values(case):
    """The `exact` numbers in the case file come from the analytic check, not the solver."""
    scene = load_scene(CASES / f"{case}.toml")
    ref = REFS[case]()
    checked = 0
    for a in scene.answers:
        if a.exact is None:
            continue
        value = ref[a.quantity]
        value = value if a.mode == "signed" else abs(value)
        assert _si(a) == pytest.approx(value, rel=1e-12, abs=1e-15), a.quantity
        checked += 1
    assert checked >= 3


def test_collar_sweep_holds_the_slide_as_stated():
    """Swept over the rod's angle, the collar stays 400 mm out and its sliding rates are the
    stated ones; |a_C| does not depend on the angle (uniform ω)."""
    scene = load_scene(CASES / "new-collar-on-rotating-rod.toml")
    sw = sweep(scene, 72)
    C = sw.position("C")
    assert np.allclose(np.hypot(C[:, 0], C[:, 1]), 0.4, rtol=0, atol=1e-15)
    assert np.all(sw.slide_v["C"] == 1.5) and np.all(sw.slide_a["C"] == -0.8)
    acc = np.hypot(*sw.acceleration("C").T)
    assert np.allclose(acc, ref_collar()["a(C)"], rtol=1e-13)


def test_rotary_engine_turns_fully_and_matches_finite_differences():
    """The cylinder block turns round once; P's velocity and acceleration are the finite
    differences of its position over the block's angle."""
    scene = load_scene(CASES / "new-rotary-engine.toml")
    sw = sweep(scene, 36)
    assert sw.full_cycle
    w = 1200 * 2 * math.pi / 60

    def pos(phi):
        return am.guided(am.fixed(0.05, 0), 0.2, am.fixed(0, 0), phi, w, 0.0, 0.0,
                         0.2 * np.exp(1j * phi))[0][0]
    for i in range(0, 36, 5):
        phi = sw.inputs[i]
        v, a = am.fd_check(pos, phi, w, 0.0, h=1e-5)
        assert abs(complex(*sw.velocity("P")[i]) - v) <= 1e-6 * abs(v)
        assert abs(complex(*sw.acceleration("P")[i]) - a) <= 1e-4 * abs(a)


# ---------------------------------------------------------------- scene keys refused
def _base():
    return {"ground": {"O": ["0 m", "0 m"]}, "links": {"OA": "0.6 m"},
            "driver": {**crank_driver("OA", 0.5, 5.0, 0.0),
                       "slide": {"point": "C", "along": "OA", "position": "0.3 m",
                                 "velocity": "1.5 m/s"}}}


@pytest.mark.parametrize("change, words", [
    (lambda d: d["driver"]["slide"].update(along="AO"), "written OA"),
    (lambda d: d["driver"]["slide"].update(along="OB"), "not defined"),
    (lambda d: d["driver"]["slide"].update(point="A"), "must not be an end"),
    (lambda d: d["driver"]["slide"].update(speed="1 m/s"), "unknown key"),
    (lambda d: d["driver"]["slide"].update(velocity="1 m"), ""),
    (lambda d: d["driver"].update(lever="OA"), "exactly one"),
])
def test_bad_slide_keys_are_refused_at_load(change, words):
    data = _base()
    change(data)
    with pytest.raises(SceneError) as exc:
        parse_scene(data)
    assert words in str(exc.value)


def test_lever_driver_needs_a_slot_and_offset_needs_a_length():
    with pytest.raises(SceneError, match="carries no slot"):
        parse_scene({"ground": {"O": ["0 m", "0 m"]}, "links": {"OQ": "1 m"},
                     "driver": {"lever": "OQ", "angle": "0 deg", "omega": "1 rad/s",
                                "sense": "CW"}})
    with pytest.raises(SceneError, match="offset slot needs the lever's length"):
        parse_scene({"ground": {"O": ["0 m", "0 m"], "B": ["0 m", "-1 m"]},
                     "links": {"OA": "0.1 m"}, "driver": crank_driver("OA", 0.3, 1.0, 0.0),
                     "slots": {"A": {"lever": "BQ", "offset": "10 mm"}}})


def test_offset_slot_that_cannot_reach_the_pin_is_an_assembly_error():
    scene = parse_scene({"ground": {"O": ["0 m", "0 m"], "B": ["0 m", "-0.15 m"]},
                         "links": {"OA": "0.1 m", "BQ": "0.5 m"},
                         "driver": crank_driver("OA", -math.pi / 2, 1.0, 0.0),
                         "slots": {"A": {"lever": "BQ", "coincident": "A1",
                                         "offset": "60 mm"}}})
    with pytest.raises(AssemblyError, match="within the slot's offset"):
        solve(scene)


# ---------------------------------------------------------------- property tests
TOL = 1e-9
lengths = st.floats(0.02, 1.0)


def nz(lo, hi):
    """Floats in [lo, hi] that are zero or at least 1e-5 (the loader refuses lengths below
    1e-6 of the mechanism's size)."""
    return st.floats(lo, hi).filter(lambda v: v == 0 or abs(v) > 1e-5)
angles = st.floats(0.0, 2 * math.pi)
omegas = st.floats(0.5, 200.0) | st.floats(-200.0, -0.5)
alphas = st.floats(-1e3, 1e3)
def offsets(big):
    """0, or an offset of at least 1 mm either way (a 1e-120 m offset is a toggle of the
    geometry check, not of the mechanism)."""
    return st.just(0.0) | st.floats(1e-3, big) | st.floats(-big, -1e-3)


prop = settings(max_examples=100, deadline=None,
                suppress_health_check=[HealthCheck.filter_too_much])


def _close(ours, ref, scale):
    return abs(complex(*ours) - ref) <= TOL * scale


@prop
@given(length=lengths, frac=st.floats(0.05, 0.95), theta=angles, omega=omegas, alpha=alphas,
       sd=st.floats(-5, 5), sdd=st.floats(-50, 50))
def test_prescribed_slide_matches_closed_form(length, frac, theta, omega, alpha, sd, sdd):
    s = frac * length
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]}, "links": {"OA": m(length)},
        "driver": {**crank_driver("OA", theta, omega, alpha),
                   "slide": {"point": "C", "along": "OA", "position": m(s),
                             "velocity": f"{sd!r} m/s", "acceleration": f"{sdd!r} m/s^2"}}})
    sol = solve(scene)
    C = am.collar(am.fixed(0, 0), theta, omega, alpha, s, sd, sdd)
    vs = abs(omega) * length + abs(sd)
    as_ = (omega ** 2 + abs(alpha)) * length + abs(sdd) + 2 * abs(omega * sd)
    assert _close(sol.points["C"].position, C[0], length)
    assert _close(sol.points["C"].velocity, C[1], vs)
    assert _close(sol.points["C"].acceleration, C[2], as_)
    assert abs(sol.slides["C"].acceleration - sdd) <= TOL * as_


@prop
@given(ad=st.floats(0.3, 1.0), ab=st.floats(0.1, 0.5), bc=lengths, cd=lengths, theta=angles,
       omega=omegas, alpha=alphas, frac=st.floats(0.1, 0.9), sd=st.floats(-3, 3),
       sdd=st.floats(-30, 30))
def test_prescribed_slide_on_a_coupler_matches_closed_form(ad, ab, bc, cd, theta, omega,
                                                           alpha, frac, sd, sdd):
    """The collar slides along the coupler BC of a four-bar (ω and α of BC not given)."""
    try:
        ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, +1)
    except ValueError:
        assume(False)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"]},
        "links": {"AB": m(ab), "BC": m(bc), "CD": m(cd)},
        "driver": {**crank_driver("AB", theta, omega, alpha),
                   "slide": {"point": "K", "along": "BC", "position": m(frac * bc),
                             "velocity": f"{sd!r} m/s", "acceleration": f"{sdd!r} m/s^2"}},
        "assembly": {"C": "C above AD"}})
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > 1.0)
    B = (complex(*ref["B"]), complex(*ref["vB"]), complex(*ref["aB"]))
    w, al = ref["omega_BC"], ref["alpha_BC"]
    th = math.atan2(ref["C"][1] - ref["B"][1], ref["C"][0] - ref["B"][0])
    K = am.collar(B, th, w, al, frac * bc, sd, sdd)
    vs = abs(omega) * ab + abs(sd) + abs(w) * bc
    as_ = (omega ** 2 + abs(alpha)) * ab + abs(sdd) + abs(al) * bc + w * w * bc + abs(w * sd)
    assert _close(sol.points["K"].velocity, K[1], vs)
    assert _close(sol.points["K"].acceleration, K[2], as_ * 10)


@prop
@given(dist=st.floats(0.05, 1.0), r=lengths, phi=angles, omega=omegas, alpha=alphas,
       d=offsets(0.3), lever=st.floats(0.5, 2.0), sign=st.sampled_from([1, -1]))
def test_pin_in_a_driven_lever_matches_closed_form(dist, r, phi, omega, alpha, d, lever,
                                                   sign):
    """Inverted slider-crank driven by its guide, the slot through the pivot or offset."""
    e = complex(math.cos(phi), math.sin(phi))
    g = 1j * d * e
    w0 = g - complex(dist, 0)
    b = (w0 * e.conjugate()).real
    disc = b * b - (abs(w0) ** 2 - r * r)
    assume(disc > 1e-6 * r * r)
    t = -b + sign * math.sqrt(disc)
    assume(abs(t) > 1e-3 * r)          # not the pin on the lever's pivot
    near = g + t * e
    X, (wt, at), (t, td, tdd), cor, X1 = am.guided(am.fixed(dist, 0), r, am.fixed(0, 0), phi,
                                                  omega, alpha, d, near)
    L = lever * (dist + r + abs(d))
    slots = {"lever": "OQ", "coincident": "P4"}
    if d:
        slots["offset"] = m(d)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"], "O2": [m(dist), "0 m"]},
        "links": {"O2P": m(r), "OQ": m(L)},
        "driver": {**crank_driver("OQ", phi, omega, alpha)},
        "slots": {"P": slots},
        "assembly": {"P": {"near": [m(near.real), m(near.imag)]}}})
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > 1.0)
    vs = abs(omega) * L
    as_ = (omega ** 2 + abs(alpha)) * L
    scale_a = as_ + vs * vs / r + abs(omega) * vs
    assert _close(sol.points["P"].position, X[0], L)
    assert _close(sol.points["P"].velocity, X[1], vs)
    assert _close(sol.points["P"].acceleration, X[2], scale_a * 10)
    assert abs(sol.slides["P"].velocity - td) <= TOL * vs
    assert abs(sol.slides["P"].acceleration - tdd) <= TOL * scale_a * 10


@prop
@given(dist=st.floats(0.05, 1.0), r=lengths, theta=angles, omega=omegas, alpha=alphas,
       d=offsets(0.3), lever=st.floats(0.5, 3.0))
def test_offset_slot_matches_closed_form(dist, r, theta, omega, alpha, d, lever):
    A = am.crank(am.fixed(0, 0), r, theta, omega, alpha)
    Bz = complex(0, -dist)
    assume(abs(A[0] - Bz) ** 2 - d * d > 1e-4 * r * r)
    ref = am.slot(A, am.fixed(0, -dist), d)
    L = lever * (dist + r)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"], "B": ["0 m", m(-dist)]},
        "links": {"OA": m(r), "BQ": m(L)},
        "driver": crank_driver("OA", theta, omega, alpha),
        "slots": {"A": {"lever": "BQ", "coincident": "A1", "offset": m(d)}}})
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > 1.0)
    vs, as_ = abs(omega) * r, (omega ** 2 + abs(alpha)) * r
    t = ref["t"]
    scale_a = as_ + vs * vs / t
    assert abs(sol.links["BQ"].omega - ref["omega"]) <= TOL * vs / t * 10
    assert abs(sol.links["BQ"].alpha - ref["alpha"]) <= TOL * scale_a / t * 10
    assert abs(sol.slides["A"].velocity - ref["t_dot"]) <= TOL * vs * 10
    assert abs(sol.slides["A"].acceleration - ref["t_ddot"]) <= TOL * scale_a * 10
    assert _close(sol.slides["A"].coriolis, ref["coriolis"], scale_a * 10)


@prop
@given(ad=st.floats(0.3, 1.0), ab=st.floats(0.1, 0.5), bc=lengths, cd=lengths, theta=angles,
       omega=omegas, alpha=alphas, rho=st.floats(0.2, 2.0), d=offsets(0.05),
       lever=st.floats(0.5, 3.0))
def test_slot_on_a_lever_with_a_moving_pivot_matches_closed_form(ad, ab, bc, cd, theta,
                                                                 omega, alpha, rho, d, lever):
    """The lever's pivot is the coupler pin C of a four-bar; the pin E is a point of the
    crank AB produced (ρ AB from A)."""
    try:
        ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, +1)
    except ValueError:
        assume(False)
    C = (complex(*ref["C"]), complex(*ref["vC"]), complex(*ref["aC"]))
    E = am.crank(am.fixed(0, 0), rho * ab, theta, omega, alpha)
    assume(abs(E[0] - C[0]) ** 2 - d * d > 1e-3 * ab * ab)
    sl = am.slot(E, C, d)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"]},
        "links": {"AB": m(ab), "BC": m(bc), "CD": m(cd), "CQ": m(lever * (ab + bc))},
        "points": {"E": {"on": "AB", "along": m(rho * ab)}},
        "driver": crank_driver("AB", theta, omega, alpha),
        "slots": {"E": {"lever": "CQ", "coincident": "E1", "offset": m(d)}},
        "assembly": {"C": "C above AD"}})
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > 2.0)
    t = sl["t"]
    vs = abs(omega) * ab * (1 + rho) + abs(complex(*ref["vC"]))
    as_ = (omega ** 2 + abs(alpha)) * ab * (1 + rho) + abs(complex(*ref["aC"]))
    scale_a = as_ + vs * vs / t
    assert abs(sol.links["CQ"].omega - sl["omega"]) <= 1e-8 * vs / t
    assert abs(sol.links["CQ"].alpha - sl["alpha"]) <= 1e-8 * scale_a / t
    assert abs(sol.slides["E"].velocity - sl["t_dot"]) <= 1e-8 * vs
    assert abs(sol.slides["E"].acceleration - sl["t_ddot"]) <= 1e-8 * scale_a


@prop
@given(L=lengths, frac=nz(-0.95, 0.95), sd=st.floats(0.01, 5) | st.floats(-5, -0.01),
       sdd=st.floats(-50, 50),
       c=nz(-0.5, 1.5))
def test_elliptic_trammel_matches_closed_form(L, frac, sd, sdd, c):
    s = frac * L
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]}, "links": {"AB": m(L)},
        "points": {"C": {"on": "AB", "along": m(c * L)}},
        "sliders": {"A": {"through": ["0 m", "0 m"], "direction": "0 deg"},
                    "B": {"through": ["0 m", "0 m"], "direction": "90 deg"}},
        "driver": {"slider": "A", "position": m(s), "velocity": f"{sd!r} m/s",
                   "acceleration": f"{sdd!r} m/s^2"},
        "assembly": {"B": "B above O"}})
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > 1.0)
    Bz = am.trammel(L, s, sd, sdd)
    A = (complex(s, 0), complex(sd, 0), complex(sdd, 0))
    C = am.image(A, Bz, c * L)
    y = abs(Bz[0])
    vs = abs(sd) * (1 + L / y)
    as_ = (abs(sdd) + sd * sd / y) * (1 + L / y) ** 3
    assert _close(sol.points["B"].velocity, Bz[1], vs)
    assert _close(sol.points["B"].acceleration, Bz[2], as_)
    assert _close(sol.points["C"].acceleration, C[2], as_ * (1 + abs(c)))


# ---------------------------------------------------------------- angle words, guide offset
def _engine(angle, side="B right of O", guide=None, omega=("10 rad/s", "CW"), r=0.05, L=0.2):
    guide = guide or {"through": ["0 m", "0 m"], "direction": "0 deg"}
    return parse_scene({"ground": {"O": ["0 m", "0 m"], "D": ["0.3 m", "0.1 m"]},
                        "links": {"OA": m(r), "AB": m(L)},
                        "driver": {"crank": "OA", "angle": angle, "omega": omega[0],
                                   "sense": omega[1]},
                        "sliders": {"B": guide}, "assembly": {"B": side}})


@prop
@given(theta=st.floats(0.0, 179.0), r=st.floats(0.01, 0.2), ratio=st.floats(1.5, 6.0),
       cw=st.booleans(), right=st.booleans(), outer=st.booleans())
def test_crank_angle_from_a_dead_centre_gives_the_piston_displacement(theta, r, ratio, cw,
                                                                     right, outer):
    """In-line engine: the piston's distance from the crank shaft after the crank has turned θ
    from a dead centre, whichever way it turns and whichever side the cylinder is on."""
    L = r * ratio
    scene = _engine(f"{theta!r} deg from {'odc' if outer else 'idc'}",
                    "B right of O" if right else "B left of O",
                    omega=("10 rad/s", "CW" if cw else "CCW"), r=r, L=L)
    sol = solve(scene)
    B = sol.points["B"].position
    th = math.radians(theta)
    # |OB| = ± r cos θ + √(L² − r² sin² θ): from IDC the crank starts pointing at the piston
    # (|OB| = L + r), from ODC away from it (|OB| = L − r)
    dist = (-1 if outer else 1) * r * math.cos(th) + math.sqrt(L * L - (r * math.sin(th)) ** 2)
    assert abs(B[0]) == pytest.approx(dist, rel=1e-12, abs=1e-15)
    assert (B[0] > 0) == right
    # the crank has turned θ from the dead centre in its own sense of rotation
    dead = 0.0 if right != outer else math.pi
    turned = (scene.driver.angle - dead) * (-1 if cw else 1)
    assert math.remainder(turned - th, 2 * math.pi) == pytest.approx(0.0, abs=1e-12)


def test_angle_from_the_line_of_centres_and_guide_from_a_pivot():
    s = _engine("30 deg from OD")
    assert s.driver.angle == pytest.approx(math.atan2(0.1, 0.3) + math.radians(30), rel=1e-15)
    g = _engine("30 deg", guide={"from": "O", "offset": "20 mm", "direction": "30 deg"})
    assert g.sliders["B"].through == pytest.approx((-0.02 * 0.5, 0.02 * math.sqrt(3) / 2))
    # the same engine stated with through = the point 20 mm left of O solves identically
    t = _engine("30 deg", guide={"through": [m(-0.01), m(0.02 * math.sqrt(3) / 2)],
                                 "direction": "30 deg"})
    assert solve(g).points["B"].acceleration == pytest.approx(
        solve(t).points["B"].acceleration, rel=1e-12)


@pytest.mark.parametrize("words, degrees", [
    ("30 deg CW from OD", math.degrees(math.atan2(0.1, 0.3)) - 30.0),
    ("30 deg ccw from OD", math.degrees(math.atan2(0.1, 0.3)) + 30.0),
    ("45 deg from +y", 135.0), ("45 deg clockwise from +y", 45.0),
    ("10 deg CW from -x", 170.0), ("20 deg from -y", -70.0), ("0.5 rad from +x", 28.64788975654116),
])
def test_angles_as_a_book_words_them(words, degrees):
    """'θ CW from AD', 'θ from +y', ...: the crank angle CCW from +x they mean, hand-checked."""
    got = math.degrees(_engine(words).driver.angle)
    assert math.remainder(got - degrees, 360.0) == pytest.approx(0.0, abs=1e-12)


def test_a_coupler_point_in_polar_form_is_the_triangle_of_two_distances():
    """'BE = 70 mm and angle CBE = θ' ([points.E] distance/angle, an image point) against the
    same point stated by BE = 70 mm and CE = 80 mm (two links: an RRR dyad): the same point,
    velocity and acceleration, θ from the cosine rule."""
    base = {"ground": {"A": ["0 mm", "0 mm"], "D": ["100 mm", "0 mm"]},
            "links": {"AB": "40 mm", "BC": "120 mm", "CD": "80 mm"},
            "driver": {"crank": "AB", "angle": "60 deg", "omega": "10 rad/s CCW",
                       "alpha": "30 rad/s^2 CW"},
            "assembly": {"C": "C above AD"}}
    theta = math.degrees(math.acos((70**2 + 120**2 - 80**2) / (2 * 70 * 120)))
    polar = solve(parse_scene(base | {"points": {"E": {"on": "BC", "distance": "70 mm",
                                                       "angle": f"{theta!r} deg"}}}))
    links = dict(base["links"], BE="70 mm", CE="80 mm")
    tri = solve(parse_scene(base | {"links": links,
                                    "assembly": base["assembly"] | {"E": "E above BC"}}))
    for get in ("position", "velocity", "acceleration"):
        a, b = getattr(polar.points["E"], get), getattr(tri.points["E"], get)
        assert math.dist(a, b) <= 1e-12 * max(1.0, math.hypot(*b)), get
    cw = parse_scene(base | {"points": {"E": {"on": "BC", "distance": "70 mm",
                                              "angle": f"{theta!r} deg CW"}}}).points["E"]
    assert cw.left == pytest.approx(-polar.scene.points["E"].left, rel=1e-15)
    with pytest.raises(SceneError, match="distance and angle"):
        parse_scene(base | {"points": {"E": {"on": "BC", "distance": "70 mm", "left": "1 mm"}}})


def test_rates_with_their_sense_written_after_them():
    """'10 rad/s CW' as books write it is omega = 10 rad/s with sense = CW; alpha likewise;
    both ways at once must agree."""
    def crank(**kw):
        return parse_scene({"ground": {"O": ["0 m", "0 m"]}, "links": {"OA": "0.05 m",
                            "AB": "0.2 m"}, "driver": {"crank": "OA", "angle": "30 deg", **kw},
                            "sliders": {"B": {"through": ["0 m", "0 m"], "direction": "0 deg"}},
                            "assembly": {"B": "B right of O"}}).driver
    d = crank(omega="120 rpm clockwise", alpha="20 rad/s^2 CCW")
    assert d.omega == pytest.approx(-4 * math.pi, rel=1e-15) and d.alpha == 20.0
    assert crank(omega="10 rad/s CW", sense="cw").omega == -10.0
    with pytest.raises(SceneError, match="give the sense once"):
        crank(omega="10 rad/s CW", sense="CCW")
    with pytest.raises(SceneError, match="missing key 'sense'"):
        crank(omega="10 rad/s")
    # the crank pin's speed as books give it: v = ω r, OA = 50 mm
    assert crank(speed="5 m/s CW").omega == pytest.approx(-100.0, rel=1e-15)
    assert crank(speed="300 mm/s", sense="CCW").omega == pytest.approx(6.0, rel=1e-15)
    with pytest.raises(SceneError, match="exactly one"):
        crank(speed="5 m/s CW", omega="100 rad/s")
    with pytest.raises(SceneError, match="exactly one"):
        crank(sense="CW")


@pytest.mark.parametrize("angle, side, guide, words", [
    ("30 deg from idc", "B above O", None, "needs the side of the slider"),
    ("30 deg CW from idc", "B right of O", None, "crank's sense of rotation"),
    ("30 deg from XY", "B right of O", None, "must join two fixed points"),
    ("30 deg from the moon", "B right of O", None, "cannot read"),
    ("30 deg", "B right of O", {"from": "O", "direction": "0 deg"}, "offset"),
    ("30 deg", "B right of O", {"from": "A", "offset": "1 mm", "direction": "0 deg"},
     "must be a fixed point"),
])
def test_bad_angle_words_and_guides_are_refused(angle, side, guide, words):
    with pytest.raises(SceneError, match=words):
        _engine(angle, side, guide)


def test_dead_centre_needs_a_slider_crank():
    with pytest.raises(SceneError, match="dead centre"):
        parse_scene({"ground": {"A": ["0 m", "0 m"], "D": ["1 m", "0 m"]},
                     "links": {"AB": "0.3 m", "BC": "1 m", "CD": "0.8 m"},
                     "driver": {"crank": "AB", "angle": "10 deg from idc", "omega": "1 rad/s",
                                "sense": "CW"}, "assembly": {"C": "C above AD"}})


@prop
@given(ad=st.floats(0.3, 1.0), ab=st.floats(0.1, 0.5), bc=lengths, cd=lengths, theta=angles,
       omega=omegas, alpha=alphas, px=nz(-1.0, 1.0), py=nz(-1.0, 1.0),
       r=lengths, sign=st.sampled_from([1, -1]), d=offsets(0.05))
def test_pin_in_the_slot_of_a_four_bar_rocker_matches_closed_form(ad, ab, bc, cd, theta, omega,
                                                                  alpha, px, py, r, sign, d):
    """The rocker DC of a four-bar carries a slot (through D or offset); the pin P of a
    second rocker O2P slides in it."""
    try:
        ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, +1)
    except ValueError:
        assume(False)
    D = am.fixed(ad, 0)
    C = (complex(*ref["C"]), complex(*ref["vC"]), complex(*ref["aC"]))
    w, al = am.rates(D, C)
    phi = math.atan2((C[0] - D[0]).imag, (C[0] - D[0]).real)
    e = complex(math.cos(phi), math.sin(phi))
    g = D[0] + 1j * d * e
    w0 = g - complex(px, py)
    b = (w0 * e.conjugate()).real
    disc = b * b - (abs(w0) ** 2 - r * r)
    assume(disc > 1e-4 * r * r)
    near = g + (-b + sign * math.sqrt(disc)) * e
    X, (wt, at), (t, td, tdd), cor, X1 = am.guided(am.fixed(px, py), r, D, phi, w, al, d, near)
    slot = {"lever": "DC", "coincident": "P4"}
    if d:
        slot["offset"] = m(d)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"], "O2": [m(px), m(py)]},
        "links": {"AB": m(ab), "BC": m(bc), "DC": m(cd), "O2P": m(r)},
        "driver": crank_driver("AB", theta, omega, alpha),
        "slots": {"P": slot},
        "assembly": {"C": "C above AD", "P": {"near": [m(near.real), m(near.imag)]}}})
    try:
        sol = solve(scene)
    except ParallelLinesError:
        assume(False)
    assume(sol.min_intersection_angle_deg > 2.0)
    vs = abs(omega) * ab + abs(w) * (cd + 2.0)
    as_ = (omega ** 2 + abs(alpha)) * ab + (abs(al) + w * w) * (cd + 2.0) + vs * vs / r
    assert abs(sol.links["O2P"].omega - wt) <= 1e-8 * vs / r
    assert abs(sol.links["O2P"].alpha - at) <= 1e-8 * as_ / r
    assert abs(sol.slides["P"].velocity - td) <= 1e-8 * vs
    assert abs(sol.slides["P"].acceleration - tdd) <= 1e-8 * as_


# ---------------------------------------------------------------- unsupported topologies


def _crank_scene(**extra):
    data = {"ground": {"O": ["0 m", "0 m"], "D": ["0.3 m", "0 m"], "E": ["0.15 m", "0.3 m"]},
            "links": {"OA": "0.1 m"}, "driver": crank_driver("OA", 1.0, 10.0, 0.0)}
    for k, v in extra.items():
        data[k] = {**data.get(k, {}), **v}
    return parse_scene(data)


def test_a_triad_is_solved_as_a_class_iii_group_once_its_closure_is_chosen():
    # the group closes in several ways: refused, listing them, until [assembly] chooses one
    scene = _crank_scene(links={"AB": "0.2 m", "BC": "0.15 m", "CD": "0.2 m", "BX": "0.1 m",
                                "XE": "0.1 m", "CX": "0.12 m"})
    with pytest.raises(BranchError, match="class-III group BCX has 4 closures"):
        solve(scene)
    chosen = _crank_scene(links={"AB": "0.2 m", "BC": "0.15 m", "CD": "0.2 m", "BX": "0.1 m",
                                 "XE": "0.1 m", "CX": "0.12 m"},
                          assembly={"X": {"near": ["0.21 m", "0.22 m"]}})
    assert solve(chosen).points["X"].position == pytest.approx((0.21068, 0.22052), abs=1e-5)


def test_a_point_on_one_link_is_named():
    # two degrees of freedom and one input: said first, with the point that cannot be placed
    with pytest.raises(MobilityError, match=r"needs 1 more input.*hangs from one link \(AB\) "
                                            r"only"):
        solve(_crank_scene(links={"AB": "0.2 m"}))


def test_a_slot_on_an_unplaced_lever_says_what_places_a_guide_on_a_moving_link():
    scene = _crank_scene(links={"DQ": "0.3 m", "EP": "0.15 m"},
                         slots={"P": {"lever": "DQ", "coincident": "P4"}})
    with pytest.raises(MobilityError) as exc:
        solve(scene)
    assert "needs 1 more input" in str(exc.value)
    assert "guide carried by a moving link is placed first by its own links" in str(exc.value)
    assert "lever = \"DQ\"" in str(exc.value)


def test_a_slot_pin_on_no_link_is_named_not_guessed():
    with pytest.raises(SceneError, match="the pin C sliding in the slot of DQ is on no link"):
        _crank_scene(slots={"C": {"lever": "DQ"}})


def test_slide_labels_must_be_new():
    data = _base()
    data["ground"]["K"] = ["1 m", "0 m"]
    data["driver"]["slide"]["point"] = "K"
    with pytest.raises(SceneError, match="already a point"):
        parse_scene(data)


def test_a_driven_lever_needs_its_length():
    with pytest.raises(SceneError, match="driven lever needs its length"):
        parse_scene({"ground": {"O": ["0 m", "0 m"], "C": ["0.05 m", "0 m"]},
                     "links": {"CP": "0.2 m"},
                     "driver": {"lever": "OQ", "angle": "0 deg", "omega": "1 rad/s",
                                "sense": "CW"},
                     "slots": {"P": {"lever": "OQ"}}})


def test_trammel_driven_by_a_crank_to_its_mid_point():
    """OC = CA = CB: A on the x axis and B = C + (C − A) on the y axis; v_A = −2 ω r sin θ."""
    r, th, w = 0.2, DEG(60), 10.0
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]}, "links": {"OC": m(r), "CA": m(r)},
        "points": {"B": {"on": "CA", "along": m(-r)}},
        "sliders": {"A": {"through": ["0 m", "0 m"], "direction": "0 deg"}},
        "driver": crank_driver("OC", th, w, 0.0), "assembly": {"A": "A right of O"}})
    sol = solve(scene)
    assert sol.slides["A"].velocity == pytest.approx(-2 * w * r * math.sin(th), rel=1e-12)
    assert sol.points["B"].position[0] == pytest.approx(0.0, abs=1e-15)
    assert sol.points["B"].velocity == pytest.approx((0.0, 2 * w * r * math.cos(th)),
                                                     abs=1e-12)


# ---------------------------------------------------------------- the ends of rods and slots
def _cli(*args):
    """``polygons ARGS`` in this process (conftest.cli: the entry point function)."""
    from conftest import cli
    return cli(*args)


def _edited(tmp_path, case, old, new, name="edited.toml"):
    text = (CASES / case).read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    path = tmp_path / name
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


@pytest.mark.parametrize("position, words", [
    ("700 mm", "the collar C at 700 mm along OA is beyond the end A of the rod OA (600 mm)"),
    ("-50 mm", "the collar C at -50 mm along OA is behind O, off the rod OA"),
])
def test_collar_off_its_rod_is_refused_through_the_cli(tmp_path, position, words):
    path = _edited(tmp_path, "new-collar-on-rotating-rod.toml", 'position = "400 mm"',
                   f'position = "{position}"')
    out = _cli("solve", path)
    assert out.returncode != 0 and out.stdout == ""
    lines = out.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"polygons: error: {path} [C1]")
    assert words in lines[0]
    with pytest.raises(AssemblyError, match="the collar C at"):
        solve(load_scene(path))         # (the compiled rows: the batch test below)


def test_collar_at_the_end_of_its_rod_solves_to_the_closed_form(tmp_path):
    """s = OA exactly: the collar at A is still on the rod (the closed form of the collar)."""
    path = _edited(tmp_path, "new-collar-on-rotating-rod.toml", 'position = "400 mm"',
                   'position = "600 mm"')
    sol = solve(load_scene(path))
    C = am.collar(am.fixed(0, 0), DEG(30), 5.0, 0.0, 0.6, 1.5, -0.8)
    assert quantity(sol, "v(C)") == pytest.approx(abs(C[1]), rel=1e-12)
    assert quantity(sol, "a(C)") == pytest.approx(abs(C[2]), rel=1e-12)


@pytest.mark.parametrize("engine", ["compiled", "located"])
def test_collar_travel_stops_where_the_position_is_the_rod_length(engine):
    """Rods from 350 to 450 mm under the collar 400 mm out: every rod shorter than 400 mm is
    refused in the collar's words, every other one solves (the rod's end is the limit)."""
    from polygons.batch import solve_many
    scene = load_scene(CASES / "new-collar-on-rotating-rod.toml")
    OA = np.linspace(0.35, 0.45, 41)          # 0.4 is row 20, exactly
    b = solve_many(scene, {"OA": OA}, engine=engine)
    assert OA[20] == 0.4
    assert list(b.ok) == list(OA >= 0.4)
    errs = b.errors
    assert [e.row for e in errs] == list(range(20))
    assert all("the collar C at 400 mm along OA is beyond the end A of the rod OA" in e.reason
               for e in errs)
    assert "(350 mm)" in errs[0].reason


def _fig7_slot(tmp_path, length):
    return _edited(tmp_path, "s003-fig7.toml", 'lever = "O4P4"     #',
                   f'length = "{length}"\nlever = "O4P4"     #', f"slot{length}.toml")


def test_pin_beyond_the_stated_end_of_its_slot_is_refused_through_the_cli(tmp_path):
    """Fig. 7: the pin is 550.58 mm from O4; a 500 mm slot cannot hold it."""
    path = _fig7_slot(tmp_path, "500 mm")
    out = _cli("solve", path)
    assert out.returncode != 0 and out.stdout == ""
    lines = out.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"polygons: error: {path} [O4P4]")
    assert ("the pin P2 at 550.58 mm from the pivot O4 is beyond the end of the slot in lever "
            "O4P4 (500 mm long)") in lines[0]
    assert _cli("solve", _fig7_slot(tmp_path, "551 mm")).returncode == 0


def test_sweep_stops_where_the_pin_reaches_the_end_of_its_slot(tmp_path):
    """O2O4 = 450 mm, O2P2 = 200 mm: |O4P2|² = 0.2² + 0.45² + 2·0.2·0.45 sin θ, which is 0.6²
    at sin θ = (0.36 − 0.2425)/0.18: the sweep's limits of travel, named by the slot's end."""
    scene = load_scene(_fig7_slot(tmp_path, "600 mm"))
    sw = sweep(scene, 90)
    s = (0.36 - 0.04 - 0.2025) / 0.18
    want = sorted([math.asin(s), math.pi - math.asin(s) - 2 * math.pi])
    assert not sw.full_cycle
    ends = [l for l in sw.limits if l.kind == "limit"]
    assert [l.input for l in ends] == pytest.approx(want, abs=1e-9)
    for l in ends:
        assert "reaches the end of the slot in lever O4P4, 600 mm from the pivot O4" in l.reason
    P = sw.position("P2")
    d = np.hypot(P[:, 0], P[:, 1])
    assert d.max() <= 0.6 and d.max() > 0.59    # inside the slot, up to its end
    # just beyond a limit the staged solve refuses in the slot's words
    beyond = parse_scene({**_raw(scene.file), "driver": {
        **_raw(scene.file)["driver"], "angle": f"{math.degrees(want[1]) + 0.01} deg"}})
    with pytest.raises(AssemblyError, match="beyond the end of the slot in lever O4P4") as st:
        solve(beyond)
    from polygons.compiled import compile_scene     # and the compiled evaluator the same
    with pytest.raises(AssemblyError) as co:
        compile_scene(scene).solve(want[1] + math.radians(0.01))
    assert str(co.value) == str(st.value).replace(str(beyond.file), str(scene.file))


def _raw(path):
    import tomllib
    with open(path, "rb") as f:
        return tomllib.load(f)


def test_a_lever_length_does_not_bound_its_slot():
    """The Whitworth lever arm CD (125 mm) is shorter than the pin's reach (241.8 mm): the
    slot runs on, the case solves (its answers are checked above)."""
    sol = solve(load_scene(CASES / "new-whitworth.toml"))
    assert quantity(sol, "dist(C,A)") > 0.125 + 0.1


def test_oscillating_cylinder_solves_with_the_pin_beyond_the_cylinder(tmp_path):
    """The crank pin is at the end of the piston rod: with the cylinder O4Q only 150 mm long
    (the pin 210 mm from O4) the answers are the closed form's, as with the 500 mm one."""
    path = _edited(tmp_path, "new-oscillating-cylinder.toml", 'O4Q = "500 mm"',
                   'O4Q = "150 mm"')
    sol = solve(load_scene(path))
    assert quantity(sol, "dist(O4,P)") > 0.15 + 0.05
    for q, value in ref_oscillating().items():
        assert quantity(sol, q) == pytest.approx(value, rel=REL, abs=1e-12), q
    short = sweep(load_scene(path), 36)
    long_ = sweep(load_scene(CASES / "new-oscillating-cylinder.toml"), 36)
    assert [l.input for l in short.limits] == pytest.approx([l.input for l in long_.limits],
                                                           abs=1e-12)
    assert all("end of the slot" not in l.reason for l in short.limits)


def test_a_stated_slot_length_on_a_guided_pin_is_refused(tmp_path):
    path = _edited(tmp_path, "new-oscillating-cylinder.toml", 'coincident = "P4"',
                   'coincident = "P4"\nlength = "400 mm"')
    out = _cli("solve", path)
    assert out.returncode != 0 and len(out.stderr.splitlines()) == 1
    assert "[slots.P] length = 400 mm is not checked" in out.stderr


def test_a_slot_length_must_be_positive(tmp_path):
    with pytest.raises(SceneError, match="slot's length must be positive"):
        load_scene(_fig7_slot(tmp_path, "0 mm"))


@prop
@given(dist=st.floats(0.05, 1.0), r=lengths, theta=angles, d=st.sampled_from([0.0, 0.02, -0.03]),
       frac=st.floats(0.3, 1.7))
def test_slot_length_refuses_exactly_beyond_its_end(dist, r, theta, d, frac):
    """A slot stated L long holds the pin iff its coordinate along the slot, t = √(|BA|² − d²)
    (am.slot), is at most L: the staged solve and the compiled evaluator refuse together,
    in the slot's words, everywhere else they solve."""
    from polygons.compiled import compile_scene
    A = am.crank(am.fixed(0, 0), r, theta, 1.0, 0.0)
    assume(abs(A[0] - complex(0, -dist)) ** 2 - d * d > 1e-4 * r * r)
    t = am.slot(A, am.fixed(0, -dist), d)["t"]
    L = frac * t
    assume(abs(L - t) > 1e-6 * t)
    data = {"ground": {"O": ["0 m", "0 m"], "B": ["0 m", m(-dist)]},
            "links": {"OA": m(r), "BQ": m(3 * (dist + r))},
            "driver": crank_driver("OA", theta, 1.0, 0.0),
            "slots": {"A": {"lever": "BQ", "coincident": "A1", "offset": m(d),
                            "length": m(L)}}}
    scene = parse_scene(data)
    if L >= t:
        try:
            solve(scene)
        except ParallelLinesError:
            return
        compile_scene(scene).solve()
        return
    with pytest.raises(AssemblyError, match="beyond the end of the slot in lever BQ") as st_:
        solve(scene)
    ok = parse_scene({**data, "slots": {"A": {**data["slots"]["A"], "length": m(2 * t)}}})
    prog = compile_scene(ok)
    from dataclasses import replace
    params = tuple(p if isinstance(g, tuple) else float(g(scene))
                   for p, g in zip(prog.params, prog.code.getters))
    with pytest.raises(AssemblyError) as co:
        replace(prog, scene=scene, params=params).solve()
    assert str(co.value) == str(st_.value)
