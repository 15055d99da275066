"""Adversary campaign: `polygons check --measured` with a minus sign on a magnitude.

Defect found on main: `check cases/s001-we6.toml --measured v_C=-15` printed "ok v_C measured
15.00 m/s" — the student's minus sign (or a sign slip: a_C, at_, cor_ …) vanished without a
word. A point's velocity or acceleration, a component or a Coriolis term is read as a length
off the polygon: it is still graded on its size, and the report now says the sign was dropped.
"""
from conftest import CASES
from polygons.cli import main

WE6 = CASES / "s001-we6.toml"


def test_a_sign_on_a_magnitude_is_named(capsys):
    rc = main(["check", str(WE6), "--measured", "v_C=-15", "a_C=25016"])
    out = capsys.readouterr().out
    assert rc == 0 and "ok   v_C" in out
    assert "a magnitude has no sign: -15.00 was graded as 15.00" in out
    assert out.count("a magnitude has no sign") == 1        # a_C was written unsigned
