"""Adversary campaign: an exam variant's data in words (the student gets no scene file).

Defects found on main (each test failed before its fix):
- crossing slots, a collar's prescribed slide and every contact (cam, curved slot, bar on a
  circle, rolling) were written as "also: … (see the scene file)": a GIFT question of
  new-crossing-slots asked v_P with nothing saying P is in the slots of O2A and O4B, and the
  collar's position, velocity and acceleration were not given at all;
- rounding noise in words: "fixed point D: at x = 0.0000000000000122465 mm" for a pivot
  placed "200 mm from A at 90°", and "R near (6.17629e−15, 100.866) mm" for a cam profile's
  follower.
"""
from __future__ import annotations

import math

import pytest

import polygons
from polygons.exam.variants import data_rows
from polygons.scene import load_scene

from conftest import CASES


def _rows(case: str) -> dict:
    return dict(data_rows(load_scene(CASES / f"{case}.toml")))


def test_no_datum_left_to_the_scene_file():
    for case in ("new-crossing-slots", "new-collar-on-rotating-rod", "cam-roller-follower",
                 "curved-slot-pin", "bar-on-half-cylinder", "rolling-plates-stated"):
        rows = _rows(case)
        assert not any("scene file" in v for v in rows.values()), (case, rows)


def test_crossing_slots_in_words():
    rows = _rows("new-crossing-slots")
    assert "from O2 through A and from O4 through B" in rows["pin P"]
    assert "P2 and P4" in rows["pin P"]


def test_collar_slide_in_words():
    row = _rows("new-collar-on-rotating-rod")["collar C"]
    assert "at 400 mm from O towards A" in row
    assert "sliding velocity 1.5 m/s" in row and "acceleration -0.8 m/s²" in row


def test_contacts_in_words():
    assert "radius 40 mm" in _rows("cam-roller-follower")["contact at R"]
    stated = _rows("rolling-plates-stated")["contact at B"]
    assert "moves at -2 m/s" in stated          # the stated plate's motion is a datum


def test_pivot_at_a_right_angle_is_exact():
    scene = polygons.load("""
[ground]
A = ["0 mm", "0 mm"]
D = { from = "A", distance = "200 mm", angle = "90 deg" }
E = { from = "A", distance = "100 mm", angle = "180 deg" }
[links]
AB = "60 mm"
BC = "180 mm"
CD = "150 mm"
[driver]
crank = "AB"
angle = "30 deg"
omega = "10 rad/s"
sense = "CCW"
[assembly]
C = "C right of AD"
""")
    assert scene.ground["D"] == (0.0, 0.2) and scene.ground["E"] == (-0.1, 0.0)
    rows = dict(data_rows(scene))
    assert rows["fixed point D"] == "at x = 0 mm, y = 200 mm"
    assert math.isclose(scene.ground["D"][1], 0.2)


def test_no_noise_in_a_cam_followers_closure():
    rows = _rows("cam-profile-tangent-flank")
    assert rows["assembly of R"] == "R near (0, 96.7471) mm"


def test_a_cam_stated_by_its_event_varies_its_angle():
    """cam-profile-tangent-flank states its instant as `when = "leaves the straight flank"`:
    every variant of `polygons exam` set the angle too and was refused ("give the driver's
    angle or the cam's when, not both"), so the exam said the ranges gave 0 well-posed
    variants. The variant's angle now replaces the event."""
    import copy
    import tomllib

    from polygons.exam.variants import _set
    from polygons.scene import parse_scene

    path = CASES / "cam-profile-tangent-flank.toml"
    data = tomllib.loads(path.read_text())
    base = load_scene(path)
    d = copy.deepcopy(data)
    _set(d, "driver.angle", "100 deg", base)
    scene = parse_scene(d, file="variant")
    assert "when" not in d["cam_profiles"]["R"]
    assert "when" in data["cam_profiles"]["R"]            # the scene's own data untouched
    assert math.degrees(scene.driver.angle) % 360 == pytest.approx(100.0)


def test_an_exam_of_a_scene_drawn_at_one_instant_is_refused_in_words(tmp_path, capsys):
    """[drawn] positions choose a scene's closures at one instant; varying the crank angle
    moved the mechanism away from them and 35 of 36 variants failed to assemble, the message
    blaming the [exam] ranges.  Now: one line naming [drawn] and what to state instead."""
    from polygons.cli import main
    text = (CASES / "s001-we6.toml").read_text().replace(
        '[assembly]\nC = "C below AD"\n', '[drawn]\nC = ["149.25 mm", "-151.07 mm"]\n')
    path = tmp_path / "drawn.toml"
    path.write_text(text)
    assert polygons.solve(str(path)) is not None          # the scene itself solves
    assert main(["exam", str(path), "--variants", "3", "--out", str(tmp_path / "x"),
                 "--html"]) == 1
    err = capsys.readouterr().err
    assert "[drawn]" in err and "[assembly]" in err and err.count("\n") == 1
