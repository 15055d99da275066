"""Checks of tests/analytic.py (the independent closed-form oracle).

1. Against the exact answers of the project's reference, tests/reference/cases.json (a copy
   of the steering side's reference, produced by a separate reference implementation: see
   tests/reference/README.md): every kinematic case, 1e-9 relative.
2. Against central finite differences of the position solution for random
   geometries (~1e-6 relative), plus the relative-velocity/acceleration
   identities that a velocity/acceleration polygon must satisfy.
3. Non-assemblable / singular / ambiguous input raises ValueError.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import analytic as an  # noqa: E402

from conftest import CASES as CASES_DIR, REFERENCE as CASES_JSON  # noqa: E402
from conftest import case_files, reference_cases  # noqa: E402
from polygons.scene import load_scene  # noqa: E402

CASES = reference_cases()

REL = 1e-9  # relative tolerance against cases.json
ATOL_POINT = 1e-9  # cases.json stores points rounded to 9 decimals
# the cases the brief requires to be covered
REQUIRED = [
    "S003-Fig7",
    "S000-D225-2003-Q3",
    "S001-WE4",
    "S001-WE2",
    "S001-SAE1-Q3",
    "S001-WE6",
    "S001-WE7",
    "S001-SAE4-Q2",
]

deg = math.radians


def _norm(v) -> float:
    return float(np.hypot(*np.asarray(v, dtype=float)))


def _perp(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    return np.array([-v[1], v[0]])


def _angle_between_deg(u, v) -> float:
    u = np.asarray(u, float)
    v = np.asarray(v, float)
    return math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), float(u @ v)))


# ---------------------------------------------------------------------------
# per-mechanism mapping of cases.json keys -> analytic.py results
# Each builder returns {key: (actual, atol)}; the expected value is
# case["exact_answers"][key].  Signed values are compared signed; keys that
# cases.json stores as magnitudes are compared with magnitudes.
# ---------------------------------------------------------------------------
def _sc(case):
    g, i = case["geometry"], case["inputs"]
    res = an.slider_crank(
        g["O"], g["r"], g["L"], deg(g.get("theta_deg", 0.0)), i["omega"],
        i.get("alpha", 0.0), g["line_point"], deg(g["line_dir_deg"]), g["branch"],
    )
    return res, g, i


def _rod_angle_to_line_deg(res, g) -> float:
    rod = res["B"] - res["A"]
    u = np.array([math.cos(deg(g["line_dir_deg"])), math.sin(deg(g["line_dir_deg"]))])
    return math.degrees(math.asin(min(1.0, abs(u[0] * rod[1] - u[1] * rod[0]) / _norm(rod))))


def comp_sc(case):
    res, g, _ = _sc(case)
    L = g["L"]
    return {
        "v_piston": (res["s_dot"], 0.0),
        "a_piston": (res["s_ddot"], 0.0),
        "omega_rod": (res["omega_AB"], 0.0),
        "alpha_rod": (res["alpha_AB"], 0.0),
        "v_rod_rel": (abs(res["omega_AB"]) * L, 0.0),
        "a_rod_centripetal": (res["omega_AB"] ** 2 * L, 0.0),
        "a_rod_tangential": (abs(res["alpha_AB"]) * L, 0.0),
        "v_crankpin": (_norm(res["vA"]), 0.0),
        "a_crankpin": (_norm(res["aA"]), 0.0),
        "A": (res["A"], ATOL_POINT),
        "P": (res["B"], ATOL_POINT),
        "rod_angle_to_line_deg": (_rod_angle_to_line_deg(res, g), 0.0),
    }


def comp_we1(case):
    g, i = case["geometry"], case["inputs"]

    def a_mm(r, theta):
        res = an.slider_crank(g["O"], r, g["L"], theta, i["omega"], 0.0,
                              g["line_point"], deg(g["line_dir_deg"]), g["branch"])
        return abs(res["s_ddot"]) * 1000.0, res

    a0, res0 = a_mm(g["r"], 0.0)
    a0_r10, _ = a_mm(0.010, 0.0)
    # the maximum really is at theta = 0 (scan one revolution)
    scan = max(a_mm(g["r"], t)[0] for t in np.linspace(0, 2 * np.pi, 721))
    assert scan <= a0 * (1 + 1e-12)
    return {
        "a_max_mm_s2": (a0, 0.0),
        "a_theta0_closed_form_mm_s2": (a0, 0.0),
        "a_max_r10_mm_s2": (a0_r10, 0.0),
        "OP_at_theta0_mm": (_norm(res0["B"] - np.asarray(g["O"], float)) * 1000.0, 0.0),
    }


def comp_we8(case):
    res, g, i = _sc(case)
    L = g["L"]
    O = np.asarray(g["O"], float)
    rod = res["B"] - res["A"]
    arm = abs(rod[0] * (O - res["A"])[1] - rod[1] * (O - res["A"])[0]) / L
    phi = _rod_angle_to_line_deg(res, g)
    # piston dynamics (line along +x, gas force along +x): only as a
    # derived check of the kinematics (virtual power T w = F v)
    F_gas = i["p_gas"] * math.pi * i["bore"] ** 2 / 4.0
    F_net = F_gas - i["m_piston"] * res["s_ddot"]
    return {
        "v_crankpin": (_norm(res["vA"]), 0.0),
        "v_piston": (res["s_dot"], 0.0),
        "v_rod_rel": (abs(res["omega_AB"]) * L, 0.0),
        "rod_angle_deg": (phi, 0.0),
        "arm_mm": (arm * 1000.0, 0.0),
        "a_crankpin": (_norm(res["aA"]), 0.0),
        "a_rod_centripetal": (res["omega_AB"] ** 2 * L, 0.0),
        "a_piston": (res["s_ddot"], 0.0),
        "F_inertia": (i["m_piston"] * abs(res["s_ddot"]), 0.0),
        "F_net": (F_net, 0.0),
        "F_rod": (F_net / math.cos(math.radians(phi)), 0.0),
        "T_crank": (F_net * res["s_dot"] / i["omega"], 0.0),
    }


def comp_fb(case):
    g, i = case["geometry"], case["inputs"]
    alpha = i.get("alpha_AB", 0.0)
    res = an.four_bar(g["A"], g["D"], g["AB"], g["BC"], g["CD"], deg(g["theta_AB_deg"]),
                      i["omega_AB"], alpha, g["branch"])
    return {
        "v_B": (_norm(res["vB"]), 0.0),
        "v_C": (_norm(res["vC"]), 0.0),
        "v_CB": (abs(res["omega_BC"]) * g["BC"], 0.0),
        "omega_BC": (res["omega_BC"], 0.0),
        "omega_CD": (res["omega_CD"], 0.0),
        "alpha_BC": (res["alpha_BC"], 0.0),
        "alpha_CD": (res["alpha_CD"], 0.0),
        "a_B": (_norm(res["aB"]), 0.0),
        "a_C": (_norm(res["aC"]), 0.0),
        "a_C_tangential_CD": (abs(res["alpha_CD"]) * g["CD"], 0.0),
        "a_C_centripetal_CD": (res["omega_CD"] ** 2 * g["CD"], 0.0),
        "a_CB_centripetal": (res["omega_BC"] ** 2 * g["BC"], 0.0),
        "a_B_centripetal": (i["omega_AB"] ** 2 * g["AB"], 0.0),
        "a_B_tangential": (abs(alpha) * g["AB"], 1e-12),
        "C": (res["C"], ATOL_POINT),
        "B": (res["B"], ATOL_POINT),
    }


def comp_we5(case):
    # rocking lever: wheel crank C->B, coupler B->A, lever O->A  ==  four_bar
    g, i = case["geometry"], case["inputs"]
    res = an.four_bar(g["C_wheel"], g["O_lever"], g["CB"], g["BA"], g["OA"],
                      deg(g["theta_CB_deg"]), i["omega_wheel"], 0.0, g["branch"])
    aA = res["aC"]
    return {
        "omega_AB": (res["omega_BC"], 0.0),
        "v_A": (_norm(res["vC"]), 0.0),
        "v_AB": (abs(res["omega_BC"]) * g["BA"], 0.0),
        "omega_OA": (res["omega_CD"], 0.0),
        "a_BC_centripetal": (i["omega_wheel"] ** 2 * g["CB"], 0.0),
        "a_AB_centripetal": (res["omega_BC"] ** 2 * g["BA"], 0.0),
        "a_OA_centripetal": (res["omega_CD"] ** 2 * g["OA"], 0.0),
        "a_OA_tangential": (abs(res["alpha_CD"]) * g["OA"], 0.0),
        "a_A": (_norm(aA), 0.0),
        "a_A_direction_deg": (math.degrees(math.atan2(aA[1], aA[0])), 0.0),
        "alpha_AB": (res["alpha_BC"], 0.0),
        "alpha_OA": (res["alpha_CD"], 0.0),
        "A": (res["C"], ATOL_POINT),
        "B": (res["B"], ATOL_POINT),
    }


def comp_sae4q3(case):
    # four-bar O-A-B-C (crank OA, coupler AB, rocker C->B) + coupler point D
    # on AB produced.  cases.json gives the pivots rounded to 9 decimals (its
    # own v_BA = 1.500000003 shows it); we use the same rounded pivots, so the
    # case still agrees to 1e-9.
    g, i = case["geometry"], case["inputs"]
    w, al = i["omega_OA"], i["alpha_OA"]
    A = np.asarray(g["A"], float)
    theta = math.atan2(A[1] - g["O"][1], A[0] - g["O"][0])
    res = an.four_bar(g["O"], g["C_pivot"], g["OA"], g["AB"], g["BC"], theta, w, al, +1)
    Apt = np.asarray(g["O"], float) + g["OA"] * np.array([math.cos(theta), math.sin(theta)])
    vA = w * _perp(Apt - g["O"])
    aA = al * _perp(Apt - g["O"]) - w * w * (Apt - g["O"])
    # four_bar's "B" is the crank pin (case point A), its "C" is case point B
    assert np.allclose(res["B"], Apt, rtol=0, atol=1e-15)
    e = (res["C"] - Apt) / _norm(res["C"] - Apt)
    rD = g["AD"] * e
    vD = vA + res["omega_BC"] * _perp(rD)
    aD = aA + res["alpha_BC"] * _perp(rD) - res["omega_BC"] ** 2 * rD
    return {
        "v_A": (_norm(vA), 0.0),
        "v_B": (_norm(res["vC"]), 0.0),
        "v_D": (_norm(vD), 0.0),
        "v_BA": (abs(res["omega_BC"]) * g["AB"], 0.0),
        "a_A": (_norm(aA), 0.0),
        "a_B": (_norm(res["aC"]), 0.0),
        "a_D": (_norm(aD), 0.0),
        "omega_AB": (res["omega_BC"], 0.0),
        "omega_BC": (res["omega_CD"], 0.0),
        "alpha_AB": (res["alpha_BC"], 0.0),
        "alpha_BC": (res["alpha_CD"], 0.0),
    }


def comp_s000(case):
    # disc crank O (pin A, R = 40 mm) + slotted lever pivoted at B
    g, i = case["geometry"], case["inputs"]
    w = i["omega_disc"]
    res = an.slotted_lever(g["O_disc"], g["R"], deg(g["crank_angle_deg"]), w,
                           i["alpha_disc"], g["B_pivot"])
    A, O, B = res["A"], np.asarray(g["O_disc"], float), np.asarray(g["B_pivot"], float)
    e = (A - B) / res["s"]
    n = _perp(e)
    J_B = i["m_lever"] * g["BC"] ** 2 / 3.0 + i["m_C"] * g["BC"] ** 2
    return {
        "lever_angle_from_BO_deg": (_angle_between_deg(A - B, O - B), 0.0),
        "BA_mm": (res["s"] * 1000.0, 0.0),
        "angle_OA_BA_deg": (_angle_between_deg(A - O, A - B), 0.0),
        "v_A_tangential_to_BA": (_norm(res["vA1"]), 0.0),
        "v_A_radial_along_BA": (abs(res["s_dot"]), 0.0),
        "omega_BC": (res["omega_lever"], 0.0),
        "dalpha_dtheta": (res["omega_lever"] / w, 0.0),
        "omega_BC_analytic": (res["omega_lever"], 0.0),
        "coriolis": (_norm(res["coriolis"]), 0.0),
        "a_A_normal_to_BA": (abs(float(res["aA"] @ n)), 0.0),
        "a_tangential_BA": (abs(res["alpha_lever"]) * res["s"], 0.0),
        "alpha_BC": (res["alpha_lever"], 0.0),
        "a_slide": (res["s_ddot"], 0.0),
        "J_B": (J_B, 0.0),
        "T_inertia_lever": (J_B * res["alpha_lever"], 0.0),
    }


def comp_s003(case):
    # crank O2 -> P (l2) + slotted link 4 pivoted at O4
    g, i = case["geometry"], case["inputs"]
    w = i["omega2"]
    res = an.slotted_lever(g["O2"], g["l2"], deg(g["crank_angle_deg"]), w, 0.0, g["O4"])
    P, O2, O4 = res["A"], np.asarray(g["O2"], float), np.asarray(g["O4"], float)
    # the slot direction stated in the case
    assert math.isclose(math.degrees(res["phi"]), g["slot_angle_deg"], rel_tol=1e-12)
    assert np.allclose(P, g["P"], rtol=0, atol=ATOL_POINT)
    e = (P - O4) / res["s"]
    aP2P4 = res["aA"] - res["aA1"]  # relative accel = s'' e + coriolis
    return {
        "beta_deg": (_angle_between_deg(P - O2, P - O4), 0.0),
        "O4P": (res["s"], 0.0),
        "omega2": (w, 0.0),
        "v_P2": (_norm(res["vA"]), 0.0),
        "v_P4": (_norm(res["vA1"]), 0.0),
        "omega4": (res["omega_lever"], 0.0),
        "v_P2P4": (abs(res["s_dot"]), 0.0),
        "v_P2P4_signed_outward": (res["s_dot"], 0.0),
        "a_P2_n": (w * w * g["l2"], 0.0),
        "a_P2_t": (_norm(res["aA"]) - w * w * g["l2"], 1e-12),
        "a_P4_n": (res["omega_lever"] ** 2 * res["s"], 0.0),
        "a_P4_t": (abs(res["alpha_lever"]) * res["s"], 0.0),
        "a_P2P4_n": (abs(float((aP2P4 - res["coriolis"]) @ _perp(e))), 1e-12),
        "a_P2P4_t": (abs(res["s_ddot"]), 0.0),
        "a_P2P4_t_signed_outward": (res["s_ddot"], 0.0),
        "coriolis": (_norm(res["coriolis"]), 0.0),
        "alpha4": (res["alpha_lever"], 0.0),
    }


BUILDERS = {
    "comp_sc": comp_sc,
    "comp_we1": comp_we1,
    "comp_we8": comp_we8,
    "comp_fb": comp_fb,
    "comp_we5": comp_we5,
    "comp_sae4q3": comp_sae4q3,
    "comp_s000": comp_s000,
    "comp_s003": comp_s003,
}
KIN_CASES = sorted(cid for cid, c in CASES.items() if c["compute"] in BUILDERS)


def reference_comparisons(case_id):
    """[(key, actual, expected, atol)] for one case (also used for reporting)."""
    case = CASES[case_id]
    built = BUILDERS[case["compute"]](case)
    exact = case["exact_answers"]
    missing = sorted(set(built) - set(exact))
    assert not missing, f"{case_id}: keys not in cases.json: {missing}"
    return [(k, built[k][0], exact[k], built[k][1]) for k in sorted(built)]


def rel_error(actual, expected, atol=0.0) -> float:
    """max |actual - expected| / |expected| (vectors: per component, scaled by
    the vector norm); errors below atol count as zero."""
    a = np.atleast_1d(np.asarray(actual, dtype=float))
    e = np.atleast_1d(np.asarray(expected, dtype=float))
    assert a.shape == e.shape
    err = float(np.max(np.abs(a - e)))
    if err <= atol:
        return 0.0
    scale = float(np.linalg.norm(e))
    return err / scale if scale > 0 else math.inf


# ---------------------------------------------------------------------------
# 1. reference cases
# ---------------------------------------------------------------------------
def test_required_cases_present_and_covered():
    for cid in REQUIRED:
        assert cid in CASES, f"{cid} missing from {CASES_JSON}"
        assert cid in KIN_CASES, f"{cid} not checked"


@pytest.mark.parametrize("case_id", KIN_CASES)
def test_reference_case(case_id):
    tol = REL
    bad = []
    for key, actual, expected, atol in reference_comparisons(case_id):
        err = rel_error(actual, expected, atol)
        if not err <= tol:
            bad.append(f"{key}: analytic {actual!r} vs exact {expected!r} (rel {err:.3g})")
    assert not bad, f"{case_id}:\n  " + "\n  ".join(bad)


def test_brief_numbers_slotted_levers():
    """The headline values quoted in the brief, independent of cases.json keys."""
    g = CASES["S003-Fig7"]["geometry"]
    r = an.slotted_lever(g["O2"], g["l2"], deg(g["crank_angle_deg"]), 5.235987755982989, 0.0, g["O4"])
    assert math.isclose(r["omega_lever"], 1.2145955942749975, rel_tol=REL)
    assert math.isclose(abs(r["alpha_lever"]), 4.108215643870321, rel_tol=REL)
    assert math.isclose(_norm(r["coriolis"]), 1.9576025310605703, rel_tol=REL)

    r = an.slotted_lever([0.0, 0.07], 0.04, deg(150.0), 100.0, 0.0, [0.0, 0.0])
    assert math.isclose(r["omega_lever"], 32.258064516129025, rel_tol=REL)  # = 100 * 1.875/5.8125
    assert math.isclose(r["omega_lever"], 100 * 1.875 / 5.8125, rel_tol=1e-12)
    assert math.isclose(r["alpha_lever"], -925.2023044245827, rel_tol=REL)
    assert math.isclose(_norm(r["coriolis"]), 162.22414376611925, rel_tol=REL)
    # Coriolis = 2 * omega_lever x (s_dot * e), e = unit(B->A)
    e = r["A"] / r["s"]
    assert np.allclose(r["coriolis"], 2 * r["omega_lever"] * r["s_dot"] * _perp(e), rtol=1e-14, atol=0)


def test_we7_affine_in_alpha():
    """alpha_CD is affine in the input alpha with slope omega_CD/omega_AB (WE7 note)."""
    g = CASES["S001-WE6"]["geometry"]
    args = (g["A"], g["D"], g["AB"], g["BC"], g["CD"], deg(g["theta_AB_deg"]), -480.0)
    r0 = an.four_bar(*args, 0.0, g["branch"])
    r1 = an.four_bar(*args, 80000.0, g["branch"])
    slope = r0["omega_CD"] / -480.0
    assert math.isclose(r1["alpha_CD"] - r0["alpha_CD"], 80000.0 * slope, rel_tol=1e-9)


# ---------------------------------------------------------------------------
# 1b. the case files' exact values that have no reference key (derived quantities:
#     a lever's end, a coupler point, a signed twin of a reference magnitude), recomputed
#     here from tests/analytic.py on the case's geometry -- not from the solver
# ---------------------------------------------------------------------------
RPM = 2 * math.pi / 60


def _mag(value, mode):
    return value if mode == "signed" else abs(value)


def _derived_s000():
    g, i = CASES["S000-D225-2003-Q3"]["geometry"], CASES["S000-D225-2003-Q3"]["inputs"]
    r = an.slotted_lever(g["O_disc"], g["R"], deg(g["crank_angle_deg"]), i["omega_disc"],
                         i["alpha_disc"], g["B_pivot"])
    w4, a4, e = r["omega_lever"], r["alpha_lever"], (r["A"] - g["B_pivot"]) / r["s"]
    C = np.asarray(g["B_pivot"]) + g["BC"] * e
    return {"v(A)": _norm(r["vA"]), "a(A)": _norm(r["aA"]), "vs(A)": r["s_dot"],
            "a(A1)": _norm(r["aA1"]), "an(A1,B)": w4 ** 2 * r["s"],
            "x(A)": r["A"][0] * 1e3, "y(A)": r["A"][1] * 1e3,
            "v(C)": abs(w4) * g["BC"], "a(C)": g["BC"] * math.hypot(a4, w4 ** 2),
            "x(C)": C[0] * 1e3, "y(C)": C[1] * 1e3}


def _derived_four_bar(D, CD, theta, omega, branch):
    r = an.four_bar((0, 0), D, 0.1, 0.2, CD, deg(theta), omega, 0.0, branch)
    return {"omega(DC)": r["omega_CD"], "v(C)": _norm(r["vC"]), "alpha(BC)": r["alpha_BC"],
            "alpha(DC)": r["alpha_CD"], "at(C,D)": abs(r["alpha_CD"]) * CD,
            "an(C,D)": r["omega_CD"] ** 2 * CD, "a(C)": _norm(r["aC"])}


def _derived_sae4q3():
    # the case file's pivot C is exact (15 sqrt 3 - 90 mm); the reference rounds it to 1e-9 m
    theta, w, al = deg(60.0), 100.0, 10000.0
    r = an.four_bar((0, 0), (0.135, 0.015 * math.sqrt(3) - 0.09), 0.03, 0.12, 0.09, theta, w,
                    al, +1)
    A, e = r["B"], (r["C"] - r["B"]) / 0.12
    rD = 0.168 * e
    vA = w * _perp(A)
    D = A + rD
    vD = vA + r["omega_BC"] * _perp(rD)
    return {"v(B,A)": abs(r["omega_BC"]) * 0.12, "v(D)": _norm(vD), "omega(AB)": r["omega_BC"],
            "alpha(AB)": r["alpha_BC"], "x(D)": D[0] * 1e3, "y(D)": D[1] * 1e3}


def _derived_we1(r):
    g, i = CASES["S001-WE1"]["geometry"], CASES["S001-WE1"]["inputs"]
    res = an.slider_crank(g["O"], r, g["L"], 0.0, i["omega"], 0.0, g["line_point"],
                          deg(g["line_dir_deg"]), g["branch"])
    return {"as(B)": res["s_ddot"] * 1e3, "v(B)": _norm(res["vB"]) * 1e3,
            "dist(O,B)": _norm(res["B"] - np.asarray(g["O"], float)) * 1e3}


def _derived_we5():
    g, i = CASES["S001-WE5"]["geometry"], CASES["S001-WE5"]["inputs"]
    r = an.four_bar(g["C_wheel"], g["O_lever"], g["CB"], g["BA"], g["OA"],
                    deg(g["theta_CB_deg"]), i["omega_wheel"], 0.0, g["branch"])
    return {"v(B)": _norm(r["vB"]), "at(A,B)": abs(r["alpha_BC"]) * g["BA"]}


def _derived_we8():
    res, g, _ = _sc(CASES["S001-WE8"])
    return {"omega(PC)": res["omega_AB"], "alpha(PC)": res["alpha_AB"],
            "at(P,C)": abs(res["alpha_AB"]) * g["L"], "x(C)": res["A"][0] * 1e3,
            "y(C)": res["A"][1] * 1e3, "x(P)": res["B"][0] * 1e3}


def _derived_ex316():
    g = CASES["S002-Ex3.16"]["geometry"]
    return {"x(A)": g["L"], "dist(O,S)": g["spring_at"], "v(A)": 0.0}   # released from rest


def _derived_ex317():
    g, i = CASES["S002-Ex3.17"]["geometry"], CASES["S002-Ex3.17"]["inputs"]
    return {"v(A)": i["omega1"] * _norm(np.subtract(g["A"], g["O"]))}


DERIVED = {
    "s000-d225-2003-q3": _derived_s000,
    # D = C - DC (cos 60, sin 60) etc. as the case files state them exactly
    "s001-sae2-q1": lambda: _derived_four_bar((0.25, 0.05 * math.sqrt(3) + 0.06), 0.06, 60.0,
                                              500 * RPM, -1),
    "s001-sae2-q2": lambda: _derived_four_bar((0.1775, 0.1 - 0.0225 * math.sqrt(3)), 0.045, 90.0,
                                              -60 * RPM, +1),
    "s001-sae4-q3": _derived_sae4q3,
    "s001-we1": lambda: _derived_we1(CASES["S001-WE1"]["geometry"]["r"]),
    "s001-we1-r10": lambda: _derived_we1(0.010),
    "s001-we5": _derived_we5,
    "s001-we8": _derived_we8,
    "s002-ex3.16": _derived_ex316,
    "s002-ex3.17": _derived_ex317,
}


@pytest.mark.parametrize("stem", sorted(DERIVED))
def test_case_exact_values_without_a_reference_key_are_the_closed_form(stem):
    scene = load_scene(CASES_DIR / f"{stem}.toml")
    closed = DERIVED[stem]()
    own = [a for a in scene.answers if a.ref is None and a.exact is not None]
    assert own
    for a in own:
        assert a.quantity in closed, f"{stem}: {a.quantity} is not recomputed here"
        expected = _mag(closed[a.quantity], a.mode)
        assert a.exact == pytest.approx(expected, rel=REL, abs=1e-12), (stem, a.quantity)


def test_every_exact_value_of_a_reference_case_has_a_source():
    """Each `exact` of a case with a reference record is the reference's (test_cases.py) or
    recomputed above."""
    for path in case_files():
        scene = load_scene(path)
        if scene.source.get("id") not in CASES:
            continue
        own = [a.quantity for a in scene.answers if a.ref is None and a.exact is not None]
        assert not own or path.stem in DERIVED, f"{path.name}: {own} have no independent source"


# ---------------------------------------------------------------------------
# 2. finite differences + polygon identities on random geometries
# ---------------------------------------------------------------------------
FD_REL = 1e-6


def _close(actual, expected, scale, rel=FD_REL):
    err = float(np.max(np.abs(np.atleast_1d(actual) - np.atleast_1d(expected))))
    assert err <= rel * scale, f"{actual!r} vs {expected!r} (err {err:.3g}, scale {scale:.3g})"


def _rand_slider_cranks(n, seed=1):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        O = rng.uniform(-1, 1, 2)
        r = rng.uniform(0.05, 1.0)
        L = rng.uniform(1.2, 4.0) * r
        args = dict(O=O, r=r, L=L, theta=rng.uniform(0, 2 * np.pi),
                    omega=rng.uniform(-50, 50), alpha=rng.uniform(-500, 500),
                    line_point=O + rng.uniform(-0.3, 0.3, 2) * r,
                    line_dir=rng.uniform(-np.pi, np.pi), branch=int(rng.choice([-1, 1])))
        try:
            res = an.slider_crank(**args)
            an.slider_crank_fd(**args)
        except ValueError:
            continue
        rod = res["B"] - res["A"]
        u = np.array([math.cos(args["line_dir"]), math.sin(args["line_dir"])])
        if abs(float(rod @ u)) / L < 0.2:  # too close to a toggle
            continue
        out.append((args, res))
    return out


def _rand_four_bars(n, seed=2):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        A = rng.uniform(-1, 1, 2)
        D = A + rng.uniform(0.5, 2.0) * np.array([math.cos(t := rng.uniform(0, 2 * np.pi)), math.sin(t)])
        args = dict(A=A, D=D, AB=rng.uniform(0.1, 1.5), BC=rng.uniform(0.3, 2.5),
                    CD=rng.uniform(0.3, 2.0), theta=rng.uniform(0, 2 * np.pi),
                    omega=rng.uniform(-50, 50), alpha=rng.uniform(-500, 500),
                    branch=int(rng.choice([-1, 1])))
        try:
            res = an.four_bar(**args)
            an.four_bar_fd(**args)
        except ValueError:
            continue
        if abs(math.sin(res["phi_CD"] - res["phi_BC"])) < 0.25:  # poor transmission
            continue
        out.append((args, res))
    return out


def _rand_slotted_levers(n, seed=3):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        O = rng.uniform(-1, 1, 2)
        r = rng.uniform(0.05, 1.0)
        B = O + rng.uniform(0.3, 3.0) * r * np.array([math.cos(t := rng.uniform(0, 2 * np.pi)), math.sin(t)])
        args = dict(O=O, r=r, theta=rng.uniform(0, 2 * np.pi),
                    omega=rng.uniform(-50, 50), alpha=rng.uniform(-500, 500), B=B)
        res = an.slotted_lever(**args)
        if res["s"] < 0.2 * r:  # pin too close to the pivot
            continue
        out.append((args, res))
    return out


@pytest.mark.parametrize("args,res", _rand_slider_cranks(12))
def test_slider_crank_vs_fd_and_polygon(args, res):
    fd = an.slider_crank_fd(**args)
    r, L, w, al = args["r"], args["L"], args["omega"], args["alpha"]
    V, Acc = r * abs(w), r * (w * w + abs(al))
    for k in ("A", "B", "s"):
        _close(res[k], fd[k], r, 1e-14)
    for k in ("vA", "vB", "s_dot"):
        _close(res[k], fd[k], V)
    for k in ("aA", "aB", "s_ddot"):
        _close(res[k], fd[k], Acc)
    _close(res["omega_AB"], fd["omega_AB"], V / L)
    _close(res["alpha_AB"], fd["alpha_AB"], Acc / L)
    # the velocity / acceleration polygon: vB = vA + w3 x AB, aB = aA + a3 x AB - w3^2 AB
    rAB = res["B"] - res["A"]
    _close(res["vB"], res["vA"] + res["omega_AB"] * _perp(rAB), V, 1e-12)
    _close(res["aB"], res["aA"] + res["alpha_AB"] * _perp(rAB) - res["omega_AB"] ** 2 * rAB, Acc, 1e-12)
    assert math.isclose(_norm(rAB), L, rel_tol=1e-12)
    # B on the line, vB and aB along it
    u = np.array([math.cos(args["line_dir"]), math.sin(args["line_dir"])])
    _close(res["B"], np.asarray(args["line_point"]) + res["s"] * u, r, 1e-12)
    _close(res["vB"], res["s_dot"] * u, V, 1e-14)
    _close(res["aB"], res["s_ddot"] * u, Acc, 1e-14)


@pytest.mark.parametrize("args,res", _rand_four_bars(12))
def test_four_bar_vs_fd_and_polygon(args, res):
    fd = an.four_bar_fd(**args)
    AB, w, al = args["AB"], args["omega"], args["alpha"]
    V, Acc = AB * abs(w), AB * (w * w + abs(al))
    for k in ("B", "C"):
        _close(res[k], fd[k], AB, 1e-14)
    for k in ("vB", "vC"):
        _close(res[k], fd[k], V)
    for k in ("aB", "aC"):
        _close(res[k], fd[k], Acc)
    for k, link in (("BC", "BC"), ("CD", "CD")):
        _close(res["omega_" + k], fd["omega_" + k], V / args[link])
        _close(res["alpha_" + k], fd["alpha_" + k], Acc / args[link])
    rBC = res["C"] - res["B"]
    rDC = res["C"] - np.asarray(args["D"])
    _close(res["vC"], res["vB"] + res["omega_BC"] * _perp(rBC), V, 1e-12)
    _close(res["vC"], res["omega_CD"] * _perp(rDC), V, 1e-12)
    _close(res["aC"], res["aB"] + res["alpha_BC"] * _perp(rBC) - res["omega_BC"] ** 2 * rBC, Acc, 1e-12)
    _close(res["aC"], res["alpha_CD"] * _perp(rDC) - res["omega_CD"] ** 2 * rDC, Acc, 1e-12)
    ad = np.asarray(args["D"]) - args["A"]
    ac = res["C"] - args["A"]
    side = float(ad[0] * ac[1] - ad[1] * ac[0])
    assert np.sign(side) == args["branch"]


@pytest.mark.parametrize("args,res", _rand_slotted_levers(12))
def test_slotted_lever_vs_fd_and_polygon(args, res):
    fd = an.slotted_lever_fd(**args)
    r, w, al = args["r"], args["omega"], args["alpha"]
    V, Acc = r * abs(w), r * (w * w + abs(al))
    s = res["s"]
    _close(res["A"], fd["A"], r, 1e-14)
    for k in ("vA", "vA1", "s_dot"):
        _close(res[k], fd[k], V)
    for k in ("aA", "aA1", "s_ddot", "coriolis"):
        _close(res[k], fd[k], Acc)
    _close(res["omega_lever"], fd["omega_lever"], V / s)
    _close(res["alpha_lever"], fd["alpha_lever"], Acc / s)
    # polygon identities: vA = vA1 + s' e ; aA = aA1 + s'' e + 2 w4 s' perp(e)
    e = np.array([math.cos(res["phi"]), math.sin(res["phi"])])
    _close(res["A"], np.asarray(args["B"]) + s * e, r, 1e-12)
    _close(res["vA"], res["vA1"] + res["s_dot"] * e, V, 1e-12)
    _close(res["coriolis"], 2 * res["omega_lever"] * res["s_dot"] * _perp(e), Acc, 1e-14)
    _close(res["aA"], res["aA1"] + res["s_ddot"] * e + res["coriolis"], Acc, 1e-12)


def test_central_difference_on_known_function():
    f = lambda t: np.array([math.cos(t), math.sin(2 * t)])  # noqa: E731
    t, w, al = 0.7, 3.0, -5.0
    d = an.central_difference(f, t, w, 1e-3, alpha=al)
    v = np.array([-math.sin(t), 2 * math.cos(2 * t)]) * w
    a = np.array([-math.cos(t), -4 * math.sin(2 * t)]) * w * w + np.array([-math.sin(t), 2 * math.cos(2 * t)]) * al
    assert np.allclose(d["v"], v, rtol=0, atol=1e-9)
    assert np.allclose(d["a"], a, rtol=0, atol=1e-6)
    # angle mode unwraps across +-pi
    g = an.central_difference(lambda t: math.atan2(math.sin(t), math.cos(t)), math.pi, 2.0, 1e-3, angle=True)
    assert math.isclose(g["v"], 2.0, rel_tol=1e-9) and abs(g["a"]) < 1e-6


# ---------------------------------------------------------------------------
# 3. invalid geometry
# ---------------------------------------------------------------------------
def test_slider_crank_cannot_assemble():
    # crank pin 1.0 off the line, rod only 0.5 long
    with pytest.raises(ValueError, match="cannot assemble"):
        an.slider_crank([0, 0], 1.0, 0.5, math.pi / 2, 1.0, 0.0, [0, 0], 0.0, 1)


def test_slider_crank_toggle_is_singular():
    # rod exactly perpendicular to the slider line: rates undefined
    with pytest.raises(ValueError, match="singular"):
        an.slider_crank([0, 0], 1.0, 1.0, math.pi / 2, 1.0, 0.0, [0, 0], 0.0, 1)


def test_four_bar_cannot_assemble():
    # |BD| = 3 > BC + CD = 1.5
    with pytest.raises(ValueError, match="cannot assemble"):
        an.four_bar([0, 0], [2, 0], 1.0, 0.5, 1.0, math.pi, 1.0, 0.0, 1)


def test_four_bar_branch_ambiguous_or_missing():
    # both intersections of circle(B,1.2) and circle(D,1.5) lie above A->D
    args = ([0, 0], [1, 0], 2.0, 1.2, 1.5, math.pi / 2, 1.0, 0.0)
    with pytest.raises(ValueError, match="same side"):
        an.four_bar(*args, 1)
    with pytest.raises(ValueError, match="cannot assemble"):
        an.four_bar(*args, -1)


def test_slotted_lever_pin_on_pivot():
    with pytest.raises(ValueError, match="cannot assemble"):
        an.slotted_lever([0, 0], 1.0, 0.0, 1.0, 0.0, [1.0, 0.0])


@pytest.mark.parametrize("bad", [
    lambda: an.slider_crank([0, 0], -1.0, 2.0, 0.0, 1.0, 0.0, [0, 0], 0.0, 1),
    lambda: an.slider_crank([0, 0], 1.0, 2.0, 0.0, 1.0, 0.0, [0, 0], 0.0, 0),
    lambda: an.four_bar([0, 0], [0, 0], 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1),
    lambda: an.four_bar([0, 0, 0], [1, 0], 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1),
    lambda: an.slotted_lever([0, 0], 0.0, 0.0, 1.0, 0.0, [1, 0]),
])
def test_bad_parameters(bad):
    with pytest.raises(ValueError):
        bad()
