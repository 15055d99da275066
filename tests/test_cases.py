"""Every shipped scene file is a textbook case: it must reproduce the reference's exact answers
to 1e-9 relative, the tutorial's printed answers within the drawing tolerance stated in the file,
and must NOT reproduce the printed values the reference identifies as slips."""
import json

import pytest

from conftest import REFERENCE, case_files
from polygons.evaluate import solve
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


#: cases outside the reference whose exact answers a test recomputes from tests/analytic.py
OWN_EXACT_CHECK = {"BJ-SP15.3-15.8": "tests/test_units.py"}


def reference_case(scene, path):
    """The reference record of ``scene`` (skips when the reference or the record is absent)."""
    if not REFERENCE.exists():
        pytest.skip(f"reference {REFERENCE} not present")
    ref = {c["id"]: c for c in json.loads(REFERENCE.read_text())["cases"]}
    if scene.source.get("id") not in ref and scene.source.get("synthetic"):
        pytest.skip(f"{path.name}: a synthetic scene with no reference record")
    if scene.source.get("id") in OWN_EXACT_CHECK:
        pytest.skip(f"{path.name}: not in the reference; its exact values are recomputed by "
                    f"{OWN_EXACT_CHECK[scene.source['id']]}")
    if scene.source.get("id") not in ref and ("seed" not in scene.source
                                              or scene.source.get("category") == "textbook"):
        pytest.skip(f"{path.name}: a textbook case outside the seeds (its exact values are "
                    f"checked against closed forms in its own tests)")
    return ref[scene.source["id"]]


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_case_exact_values_are_the_reference_values(path):
    """The `exact` numbers in the scene files are copied from the reference, not from us."""
    scene = load_scene(path)
    case = reference_case(scene, path)
    for a in scene.answers:
        if a.ref is None or a.exact is None:
            continue
        value = case["exact_answers"][a.ref]
        if isinstance(value, list):
            continue
        if a.unit == "mm" and not a.ref.endswith("_mm"):
            value *= 1e3
        expected = abs(value) if a.mode == "abs" else value
        assert a.exact == pytest.approx(expected, rel=1e-12, abs=1e-15), a.ref


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_case_slips_are_those_of_the_reference(path):
    scene = load_scene(path)
    case = reference_case(scene, path)
    slips_ref = {k for k, v in case["tutorial_answers"].items() if v["slip"]}
    slips_ref |= {v["exact_key"] for v in case["tutorial_answers"].values() if v["slip"]}
    slips_ours = {a.ref for a in scene.answers if a.slip}
    assert slips_ours <= slips_ref, f"{path.name}: slips not in the reference: {slips_ours - slips_ref}"
