"""Force results in words, written by one formatter (polygons/forces/words.py): a signed force
or moment once, its size with its sense ('3.79649 N m CW', 'T − 157.76 N m = 0'), never a
signed number with a sense after it ('−3.79649 N m (CCW)'), inside a sum ('T + (−157.76 N m)
= 0'), nor a direction of 360°.  Checked on the formatter and on what `polygons forces`,
the handout's lever table and `polygons check` print for the toggle press (issue 33)."""
import numpy as np
import pytest

from conftest import ROOT
from polygons.forces import words


def test_a_moment_is_its_size_with_its_sense():
    assert words.moment_words(-3.79649) == "3.79649 N m CW"
    assert words.moment_words(157.76) == "157.76 N m CCW"
    assert words.moment_words(-1e-15) == "0 N m"
    assert words.balance_words(-157.76, 157.76) == "T − 157.76 N m = 0, T = 157.76 N m CCW"
    assert words.balance_words(12.5, -12.5) == "T + 12.5 N m = 0, T = 12.5 N m CW"
    assert words.table_moment(-4.62687) == "4.62687 CW" and words.table_moment(-0.0) == "0"
    assert words.lever_moment_words(-4637.6) == "4637.6 N m/s CW"


def test_the_turning_moment_says_which_way_it_turns():
    # a crank turning CW (w < 0): a moment in its sense is CW, against it CCW
    assert words.rotation_words(6.65, -15.0) == "6.65 N m in the sense of rotation (CW)"
    assert words.rotation_words(-221.43, 20.9) == "221.43 N m against the rotation (CW)"


def test_a_direction_under_360_degrees_is_0():
    assert words.angle((1.0, -1e-15)) == "0"
    assert words.angle((0.0, -1.0)) == "270"
    assert words.sense_words((1.0, -1e-9)).endswith("(∠0.0°)")
    f = type("F", (), {"value": -27.4611, "force": np.array([-25.77, 9.49])})()
    assert words.found_words(f) == "27.4611 N, to the left (∠159.8°)"


@pytest.fixture(scope="module")
def toggle():
    from polygons.forces import analyse
    from polygons.scene import load_scene
    return analyse(load_scene(ROOT / "cases" / "forces-toggle-press.toml"))


def test_the_forces_text_writes_each_sign_once(toggle):
    from polygons.cli.forces import forces_table
    text = forces_table(toggle)
    for bad in ("+ (-", "+ (−", "N m (CCW)", "N m (CW)", "towards 360", "∠360", " -0 ",
                " -0\n"):
        assert bad not in text, bad
    assert "turning moment T on the crank: 221.42891 N m against the rotation (CW)" in text
    assert "guide: on D 1848.96 N normal to the guide, towards 0°" in text
    assert "moments about O: T − 221.429 N m = 0, T = 221.429 N m CCW" in text
    assert "4.62687 CW" in text and "Σ moments of the known forces about o: 4637.6 N m/s CCW" \
        in text


def test_the_handout_lever_table_writes_senses(toggle):
    from diagrams.handout_forces import _lever
    html = _lever(toggle)
    assert "4.62687 CW" in html and "−4.62687" not in html and "-4.62687" not in html
    assert "input torque on OA: 221.42891 N m CCW" in html


def test_check_grades_a_signed_torque_by_its_sense():
    from polygons.cli import main
    import io
    import contextlib
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(["check", str(ROOT / "cases" / "forces-toggle-press.toml"),
                     "--measured", "Tin=-221.43"])
    text = out.getvalue()
    assert code == 3
    assert "measured 221.4 N m CW, expected 221.4 N m CCW" in text
    assert "the sense is wrong: Tin is 221.4 N m CCW" in text
    assert "a magnitude has no sign" not in text
