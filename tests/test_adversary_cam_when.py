"""Adversary campaign: a cam's instant stated by its event, the cam turning clockwise with the
sense written after its rate.

Defect found on main: cases/cam-profile-tangent-flank.toml (`when = "leaves the straight
flank"`, on the rise by default) with `omega = "180 rpm CW"` — the documented way to give the
sense with the rate — read the cam as turning CCW: it answered the return (the nose axis at
29.74°, v_R = −1.042 m/s, the follower falling) where `sense = "CW"` gives the rise (150.26°,
v_R = +1.042 m/s). The sense is now read as the driver reads it.
"""
import math
import tomllib

import pytest
import rtoml

import polygons

from conftest import CASES

DATA = tomllib.loads((CASES / "cam-profile-tangent-flank.toml").read_text())
for _key in ("answers", "questions", "exam"):
    DATA.pop(_key, None)


def _solve(**driver):
    d = tomllib.loads(rtoml.dumps(DATA))
    d["driver"].pop("sense", None)
    d["driver"].update(driver)
    scene = polygons.load(rtoml.dumps(d))
    return math.degrees(scene.driver.angle) % 360.0, polygons.solve(scene).points["R"]


@pytest.mark.parametrize("driver", [{"omega": "180 rpm", "sense": "CW"},
                                    {"omega": "180 rpm CW"}, {"omega": "180 rpm clockwise"}])
def test_clockwise_rise(driver):
    angle, r = _solve(**driver)
    assert angle == pytest.approx(150.2551187, abs=1e-6)
    assert r.velocity[1] == pytest.approx(1.0420807, rel=1e-6)       # rising


@pytest.mark.parametrize("driver", [{"omega": "180 rpm", "sense": "CCW"},
                                    {"omega": "180 rpm anticlockwise"}])
def test_anticlockwise_rise(driver):
    angle, r = _solve(**driver)
    assert angle == pytest.approx(29.7448813, abs=1e-6)
    assert r.velocity[1] == pytest.approx(1.0420807, rel=1e-6)
