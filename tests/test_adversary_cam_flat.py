"""Khurmi & Gupta's symmetrical circular cam with a flat-faced follower (minimum radius 30 mm,
lift 20 mm, angle of lift 75°, nose radius 5 mm, 600 r.p.m.), stated as the book states it and
checked against the book's own closed forms: the flank radius from the angle of lift, the
follower's acceleration ω²(R − r₁)cos θ on the flank and −ω² d cos ψ on the nose at the
beginning of the lift, where the flank meets the nose (from either side) and at the apex.  And
the point R of a translating flat face: the equivalent yoke's point at K's level, ρ short of the
face (the campaign found the module's docstring calling it the face's point)."""
import json
import math

import pytest

import polygons

R1, L, R2, PHI = 0.030, 0.020, 0.005, math.radians(75)
W = 600 * 2 * math.pi / 60
D = R1 + L - R2
RF = (R1 ** 2 + D ** 2 - 2 * R1 * D * math.cos(PHI) - R2 ** 2) / (
    2 * (R1 - R2 - D * math.cos(PHI)))

CAM = """
[ground]
O = ["0 mm", "0 mm"]
[driver]
crank = "OK"
ANGLE
omega = "600 rpm CW"
[cam_profiles.R]
base_radius = "30 mm"
nose_radius = "5 mm"
lift = "20 mm"
angle_of_action = "150 deg"
follower = "flat"
stroke = "90 deg"
WHEN
"""


def _solve(angle=None, when=None):
    text = CAM.replace("ANGLE", f'angle = "{angle}"' if angle else "").replace(
        "WHEN", f'when = "{when}"' if when else "")
    return json.loads(polygons.solve(text).to_json())


def _flank_to_nose():
    """(θ_j, ψ): the cam's turn from the start of the lift to the flank–nose junction, and the
    nose axis's angle from the stroke there (θ_j + ψ = φ)."""
    p = (-(RF - R1) * math.cos(PHI), -(RF - R1) * math.sin(PHI))     # the flank's centre
    psi = math.atan2(-p[1], D - p[0])                                 # the normal P → Q
    return PHI - psi, psi


def test_the_flank_radius_is_the_books():
    d = _solve(angle="90 deg")
    assert d["cam_profile"]["flank_radius"] == pytest.approx(RF, rel=1e-12)


@pytest.mark.parametrize("when, want", [
    ("leaves the base circle", lambda: W * W * (RF - R1)),
    ("leaves the flank", lambda: W * W * (RF - R1) * math.cos(_flank_to_nose()[0])),
    ("reaches the nose", lambda: -W * W * D * math.cos(_flank_to_nose()[1])),
])
def test_the_followers_acceleration_at_the_books_instants(when, want):
    a = _solve(when=when)["points"]["R"]["acceleration"][1]       # up the stroke
    assert a == pytest.approx(want(), rel=1e-9)


def test_at_the_apex_and_the_point_r_is_the_yokes_rho_short_of_the_face():
    d = _solve(angle="90 deg")
    assert d["points"]["R"]["acceleration"][1] == pytest.approx(-W * W * D, rel=1e-12)
    assert d["cam_profile"]["displacement"] == pytest.approx(R1 + L, rel=1e-12)
    assert d["points"]["R"]["position"][1] == pytest.approx(D, rel=1e-12)   # K's level
    text = polygons.solve(CAM.replace("ANGLE", 'angle = "90 deg"').replace("WHEN", "")).table()
    assert "5 mm short of the face" in text


@pytest.mark.parametrize("case", ["cam-profile-circular-arc", "rolling-wheel-rim-pin",
                                  "forces-toggle-press"])
def test_the_api_reports_are_the_commands_reports(case, capsys):
    """README: `res.table()` is the text of `polygons solve`, `res.to_json()` its `--json`.  The
    campaign found the API leaving out what the command adds — a contact's equivalent linkage,
    a cam's profile and the part in contact (`cam_profile`), the forces' table."""
    from pathlib import Path
    from polygons.cli import run_command
    path = str(Path(__file__).resolve().parent.parent / "cases" / f"{case}.toml")
    res = polygons.solve(path)
    assert run_command(["solve", path, "--json"]) == 0
    assert json.loads(capsys.readouterr().out) == json.loads(res.to_json())
    assert run_command(["solve", path]) == 0
    assert capsys.readouterr().out.strip() == res.table().strip()
