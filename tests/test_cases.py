"""Every shipped scene file is a textbook case: it must reproduce the reference's exact answers
to 1e-9 relative, the tutorial's printed answers within the drawing tolerance stated in the file,
and must NOT reproduce the printed values the reference identifies as slips."""
import math
from pathlib import Path

import numpy as np
import pytest

import analytic

from conftest import (REFERENCE, ROOT, SHARED_REFERENCE, case_files, reference_cases,
                      shared_reference_cases)
from polygons.evaluate import solve
from polygons.forces import has_forces
from polygons.report import check_answers
from polygons.scene import load_scene

EXACT_REL = 1e-9
FILES = case_files()
IDS = [f.stem for f in FILES]


@pytest.fixture(scope="module")
def solved():
    cache = {}

    def get(path):
        if path not in cache:
            cache[path] = solve(load_scene(path))
        return cache[path]
    return get


def test_there_are_cases():
    assert len(FILES) >= 1


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_case_reproduces_exact_answers(path, solved):
    sol = solved(path)
    checks = [c for c in check_answers(sol) if c.answer.exact is not None]
    assert checks, f"{path.name} has no exact answers to test"
    for c in checks:
        exact = c.answer.exact
        tol = EXACT_REL * abs(exact) if exact != 0 else 1e-12
        assert abs(c.compared - exact) <= tol, (
            f"{c.answer.quantity} = {c.compared!r} {c.answer.unit}, exact {exact!r}")


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_case_matches_tutorial_within_drawing_tolerance(path, solved):
    sol = solved(path)
    for c in check_answers(sol):
        a = c.answer
        if a.tutorial is None:
            continue
        if a.slip:
            assert not c.within, (f"{a.quantity}: we reproduce the tutorial's slip "
                                  f"{a.tutorial} (ours {c.compared})")
        else:
            assert c.within, (f"{a.quantity}: tutorial {a.tutorial}, ours {c.compared:.6g} "
                              f"({c.diff_pct:+.2f} %, tolerance ±{a.tolerance * 100:g} %)")


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_case_senses_agree_with_tutorial(path, solved):
    sol = solved(path)
    for c in check_answers(sol):
        a = c.answer
        if a.sense in ("CW", "CCW") and not a.slip:
            assert (c.ours > 0) == (a.sense == "CCW"), f"{a.quantity}: tutorial says {a.sense}"


#: the cases outside the reference, and the test that recomputes their `exact` values from an
#: independent closed form (tests/analytic.py or one written out in the test), not from the solver
OWN_EXACT_CHECK = {
    "bj-engine-imperial": ("test_units.py", "test_imperial_case_exact_answers_are_the_closed_form"),
    "efficiency-four-bar": ("test_cases.py", "test_exact_values_outside_the_reference_are_closed_forms"),
    **{name: ("test_conditions.py",
              "test_question_cases_exact_values_are_the_closed_form_and_ours")
       for name in ("question-engine-conditions", "question-offset-quick-return")},
    "cam-profile-tangent-roller": ("test_cam_profiles.py",
                                   "test_the_new_cases_exact_answers_are_the_closed_forms"),
    "cam-profile-arc-flat-oscillating": ("test_cam_profiles.py",
                                         "test_the_new_cases_exact_answers_are_the_closed_forms"),
    "bar-on-cylinder-rod-angle": ("test_contacts.py",
                                  "test_the_bar_on_a_cylinder_placed_by_its_angle"),
    "cam-profile-tangent-flank": ("test_cam_profiles.py",
                                  "test_the_tangent_flank_case_is_the_books_closed_form"),
    "cam-profile-circular-arc": ("test_cam_profiles.py",
                                 "test_case_exact_answers_are_the_closed_form"),
    "ratio-four-bar": ("test_conditions.py",
                       "test_ratio_case_exact_answers_are_the_closed_form_and_kennedy"),
    "khurmi-ex7.2": ("test_centres.py", "test_khurmi_exact_answers_are_the_closed_form_and_ours"),
    "new-crossing-slots": ("test_crossing.py",
                           "test_the_case_exact_answers_come_from_the_loop_solution"),
    "new-slot-slider": ("test_slot_slider.py",
                        "test_the_case_is_its_closed_form_and_its_answers_are_the_oracles"),
    "new-screw-slotted-arm": ("test_book_forms.py",
                              "test_the_screw_case_exact_answers_are_the_closed_form"),
    **{name: ("test_triad.py", "test_the_case_exact_answers_come_from_the_oracle")
       for name in ("triad-eight-bar", "triad-plate-point", "triad-ternary-coupler",
                    "triad-plate-distances")},
    "triad-slider-corner": ("test_triad_slider.py",
                            "test_the_case_exact_answers_come_from_the_oracle"),
    "new-block-on-moving-link": ("test_book_forms.py",
                                 "test_a_block_pinned_to_one_moving_link_sliding_on_another"),
    "new-engine-rod-angle": ("test_book_forms.py",
                             "test_the_engine_placed_by_its_rod_angle_matches_the_closed_form"),
    "centres-double-slider": ("test_centres.py",
                              "test_double_slider_centre_of_the_bar_where_the_normals_meet"),
    **{name: ("test_klein.py", "test_cases_against_the_loop_closure")
       for name in ("klein-inline-engine", "klein-offset-engine")},
    **{name: ("test_graphical.py", "test_the_force_cases_kinematic_answers_are_their_sources")
       for name in ("forces-toggle-press", "forces-actuator-four-bar",
                    "forces-engine-piston-effort", "forces-whitworth", "forces-scotch-yoke",
                    "forces-oscillating-cylinder", "forces-triad", "forces-triad-truss")},
    "book-hibbeler-wheel-incline": ("test_adversary_cases.py",
                                    "test_the_book_cases_exact_answers_come_from_their_loop_closure"),
    "cam-roller-follower": ("test_contacts.py", "test_roller_follower_is_the_slider_crank"),
    "cam-flat-follower": ("test_contacts.py", "test_flat_follower_is_the_scotch_yoke"),
    "book-ladder-bar-omega": ("test_book_forms.py",
                              "test_the_ladder_case_exact_answers_are_the_closed_form"),
    "rolling-wheel-forces": ("test_contact_forces.py",
                             "test_shipped_rolling_case_is_the_wheel_s_equations"),
    "cam-roller-forces": ("test_contact_forces.py",
                          "test_shipped_case_equals_the_follower_equation_of_motion"),
    "curved-slot-pin": ("test_contacts.py", "test_curved_slot_case_and_random_instances"),
    "rolling-wheel-driven": ("test_contacts.py",
                             "test_rolling_wheel_is_the_offset_slider_crank_and_turns_at_v_over_r"),
    "cam-oscillating-flat-follower": ("test_contacts.py",
                                      "test_oscillating_flat_follower_is_the_tangency_condition"),
    "rolling-wheel-rim-pin": ("test_contacts_moving.py",
                              "test_a_driven_wheel_moves_a_rod_from_a_pin_on_it"),
    "rolling-plates-stated": ("test_contacts_moving.py",
                              "test_plates_moved_at_stated_rates_as_books_state_them"),
    "rolling-cylinder-between-plates": ("test_contacts_moving.py",
                                        "test_cylinder_between_plates_case"),
    "bar-on-half-cylinder": ("test_contacts.py",
                             "test_bar_on_a_half_cylinder_driven_by_a_crank"),
    "khurmi-flywheel-steam-engine": ("test_cases.py",
                                     "test_exact_values_outside_the_reference_are_closed_forms"),
    "rest-slider-crank": ("test_cases.py", "test_exact_values_outside_the_reference_are_closed_forms"),
    "scotch-yoke": ("test_cases.py", "test_exact_values_outside_the_reference_are_closed_forms"),
    **{name: ("test_new_dyads.py", "test_case_exact_answers_are_the_analytic_values")
       for name in ("new-collar-on-rotating-rod", "new-elliptic-trammel", "new-engine-from-idc",
                    "new-offset-slot", "new-oscillating-cylinder", "new-rotary-engine",
                    "new-shaper-ram", "new-slot-on-moving-lever", "new-stephenson-six-bar",
                    "new-toggle-press", "new-watt-six-bar", "new-whitworth")},
}
REF = reference_cases()
IN_REFERENCE = [f for f in FILES if load_scene(f).source.get("id") in REF]


def test_every_case_has_an_independent_source_for_its_exact_values():
    """Each case's `exact` values are the reference's (tests below) or recomputed from a closed
    form by the named test, which exists and reads that case."""
    here = Path(__file__).resolve().parent
    for path in FILES:
        if path in IN_REFERENCE:
            assert path.stem not in OWN_EXACT_CHECK, f"{path.name} is in the reference"
            continue
        assert path.stem in OWN_EXACT_CHECK, (
            f"{path.name}: no reference record, so a test must recompute its exact values from "
            f"an independent closed form: name it in OWN_EXACT_CHECK (tests/test_cases.py)")
        test_file, test_name = OWN_EXACT_CHECK[path.stem]
        text = (here / test_file).read_text(encoding="utf-8")
        assert f"def {test_name}(" in text, f"{test_file}::{test_name} not found"
        assert path.stem in text, f"{test_file} never reads {path.name}"
    assert set(OWN_EXACT_CHECK) <= {f.stem for f in FILES}


def test_every_reference_case_has_a_case_file():
    """Each kinematic record of the reference is a scene of cases/ (the two torque-driven Ex 3.16
    and 3.17 included: their kinematic answers are in their scenes too)."""
    ours = {load_scene(f).source.get("id") for f in IN_REFERENCE}
    assert set(REF) <= ours, sorted(set(REF) - ours)


def _reference_value(answer, case):
    """The reference's exact value for ``answer`` in the case file's unit and mode."""
    value = case["exact_answers"][answer.ref]
    if isinstance(value, list):     # a point [x, y] in m, stored to 9 decimals
        axis = answer.quantity[:2]
        assert axis in ("x(", "y("), (answer.quantity, answer.ref)
        value = value[0 if axis == "x(" else 1]
    if answer.unit == "mm" and not answer.ref.endswith("_mm"):
        value *= 1e3
    return abs(value) if answer.mode == "abs" else value


@pytest.mark.parametrize("path", IN_REFERENCE, ids=[f.stem for f in IN_REFERENCE])
def test_case_exact_values_are_the_reference_values(path):
    """The `exact` numbers in the scene files are copied from the reference, not from us; the
    tutorial's printed values are the reference's too."""
    scene = load_scene(path)
    case = REF[scene.source["id"]]
    checked = 0
    for a in scene.answers:
        if a.ref is None or a.exact is None:
            continue
        if isinstance(case["exact_answers"][a.ref], list):
            # points: the reference rounds them to 1e-9 m
            tol = 1e-6 if a.unit == "mm" else 1e-9
            assert a.exact == pytest.approx(_reference_value(a, case), rel=0, abs=tol), a.quantity
        else:
            assert a.exact == pytest.approx(_reference_value(a, case), rel=1e-12, abs=1e-15), a.ref
        checked += 1
        if a.tutorial is not None and a.ref in case["tutorial_answers"]:
            printed = case["tutorial_answers"][a.ref]
            if printed["unit"] == a.unit:
                assert a.tutorial == printed["value"], (a.quantity, a.ref)
    # the torque-driven Ex 3.16 and 3.17 have their reference values in their force answers
    # (tests/test_forces.py); every other case has some in its kinematic answers
    assert checked or has_forces(scene), f"{path.name}: no exact value is the reference's"


@pytest.mark.parametrize("path", IN_REFERENCE, ids=[f.stem for f in IN_REFERENCE])
def test_case_slips_are_those_of_the_reference(path):
    scene = load_scene(path)
    case = REF[scene.source["id"]]
    slips_ref = {k for k, v in case["tutorial_answers"].items() if v["slip"]}
    slips_ref |= {v["exact_key"] for v in case["tutorial_answers"].values() if v["slip"]}
    slips_ours = {a.ref for a in scene.answers if a.slip}
    assert slips_ours <= slips_ref, f"{path.name}: slips not in the reference: {slips_ours - slips_ref}"


FACTS = ("geometry", "inputs", "exact_answers", "tutorial_answers", "slips", "compute")


def test_project_reference_is_the_shared_reference():
    """Where the steering side's reference is beside the repository, every one of its cases is in
    the project's copy with the same facts (refresh tests/reference/ when this fails).  Without
    it the copy stands alone: this cross-check then has nothing to compare and passes."""
    shared = shared_reference_cases()
    if shared is None:
        pytest.skip(f"by design: no shared reference beside the repository ({SHARED_REFERENCE}); "
                    f"the project's copy {REFERENCE.relative_to(ROOT)} stands alone")
    for cid, case in shared.items():
        assert cid in REF, f"{cid} is in {SHARED_REFERENCE} but not in {REFERENCE}"
        for key in FACTS:
            assert REF[cid].get(key) == case.get(key), f"{cid}: {key} differs from the shared reference"


def _closed_forms():
    """The four cases outside the reference that no other test recomputes, by tests/analytic.py
    (loop closure differentiated by hand), in the case files' units: {stem: {quantity: value}}."""
    norm = lambda v: float(np.hypot(*v))                        # noqa: E731
    rest = analytic.slider_crank((0, 0), 0.1, 0.4, math.radians(45), 0.0, 200.0, (0, 0), 0.0, +1)
    fb = analytic.four_bar((0, 0), (0.45, 0), 0.1, 0.4, 0.35, math.radians(90), 12.0, 0.0, +1)
    w = -120 * 2 * math.pi / 60                                 # 120 rev/min CW
    engine = analytic.slider_crank((0, 0), 0.2, 0.6, math.radians(135), w, 0.0, (0, 0), 0.0, -1)
    r, th, om = 0.05, math.radians(30), 10.0                    # Scotch yoke: x = R sin(ωt)
    return {
        "rest-slider-crank": {"v(B)": norm(rest["vB"]), "a(A)": norm(rest["aA"]),
                              "a(B)": norm(rest["aB"]), "alpha(AB)": rest["alpha_AB"]},
        "efficiency-four-bar": {"omega(CD)": fb["omega_CD"], "omega(BC)": fb["omega_BC"],
                                "v(C)": norm(fb["vC"])},
        "khurmi-flywheel-steam-engine": {"vs(P)": engine["vB"][0], "as(P)": engine["aB"][0],
                                         "x(P)": engine["B"][0] * 1e3},
        "scotch-yoke": {"y(Y)": r * math.sin(th) * 1e3, "vs(Y)": om * r * math.cos(th),
                        "as(Y)": -om * om * r * math.sin(th)},
    }


def test_exact_values_outside_the_reference_are_closed_forms():
    """rest-slider-crank, efficiency-four-bar, khurmi-flywheel-steam-engine, scotch-yoke: every
    `exact` of their [[answers]] is the closed form's (not the solver's), to 1e-12."""
    for stem, closed in _closed_forms().items():
        scene = load_scene(ROOT / "cases" / f"{stem}.toml")
        assert {a.quantity for a in scene.answers} == set(closed), stem
        for a in scene.answers:
            value = closed[a.quantity]
            value = value if a.mode == "signed" else abs(value)
            assert a.exact == pytest.approx(value, rel=1e-12, abs=1e-15), (stem, a.quantity)
