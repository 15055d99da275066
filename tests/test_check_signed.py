"""`polygons check --measured`: a signed answer (a slider's velocity along its guide) is graded
with its sign when the student writes one, and the report says plainly when only the
magnitude was graded (issue 29: "expected −6.928 m/s … ok" for a measured +6.928)."""
import json

import pytest

from conftest import CASES
from polygons.cli import main

LADDER = CASES / "book-ladder-bar-omega.toml"


def _run(capsys, *values, as_json=False):
    rc = main(["check", str(LADDER), "--measured", *values] + (["--json"] if as_json else []))
    return rc, capsys.readouterr().out


def test_a_written_sign_is_graded(capsys):
    from polygons.evaluate import solve
    from polygons.quantities import quantity
    from polygons.scene import load_scene
    expected = quantity(solve(load_scene(LADDER)), "vs(B)")
    assert expected < 0                      # the slider moves against its guide's direction
    wrong = f"+{abs(expected):.3f}"
    rc, out = _run(capsys, f"vs_B={wrong}")
    assert rc == 3 and "OFF  vs_B" in out and f"measured +{abs(expected):.3f}" in out
    assert "the sense is wrong" in out and "along the guide's direction" in out
    for right in (f"-{abs(expected):.3f}", f"\u2212{abs(expected):.3f}"):
        rc, out = _run(capsys, f"vs_B={right}")
        assert rc == 0 and "ok   vs_B" in out and "magnitude only" not in out
    rc, out = _run(capsys, f"vs_B={wrong}", as_json=True)
    g = json.loads(out)["grades"][0]
    assert g["graded"] == "signed" and g["sense_ok"] is False and not g["ok"]


def test_no_sign_grades_the_magnitude_and_says_so(capsys):
    rc, out = _run(capsys, "vs_B=6.928")
    assert rc == 0 and "(magnitude)" in out
    assert "magnitude only: no sign was written, so its sense is not graded" in out
    rc, out = _run(capsys, "vs_B=6.928", as_json=True)
    assert json.loads(out)["grades"][0]["graded"] == "magnitude"


@pytest.mark.parametrize("value,graded", [("omega_AB=1CW", "magnitude and sense"),
                                          ("omega_AB=1", "magnitude")])
def test_json_says_what_was_graded(capsys, value, graded):
    rc, out = _run(capsys, value, as_json=True)
    assert json.loads(out)["grades"][0]["graded"] == graded


def test_an_angular_velocity_without_a_sense_says_so(capsys):
    rc, out = _run(capsys, "omega_AB=1")
    assert "magnitude only: no sense was written" in out
    rc, out = _run(capsys, "omega_AB=1CW")
    assert "magnitude only" not in out
