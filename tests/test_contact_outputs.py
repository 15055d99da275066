"""Contacts say what they report (issue 28, item 3): every output of a higher pair is named in
polygons.higher.OUTPUTS (docs/contact-outputs.md is generated from it) and is what its name
says.  Finite-difference checks of each on random mechanisms: tests/test_domain.py (bearing,
curved_slot, cam, rolling kinds; tests/domain.py ``_contact``)."""
import math
from pathlib import Path

import pytest

from conftest import CASES
from polygons.contacts import to_list
from polygons.evaluate import solve
from polygons.higher import OUTPUTS, higher
from polygons.scene import load_scene

FLOOR = Path(__file__).resolve().parent / "data" / "bar-on-half-cylinder-floor.toml"
CONTACT_CASES = ["bar-on-half-cylinder", "curved-slot-pin", "cam-roller-follower",
                 "cam-flat-follower", "cam-oscillating-flat-follower", "rolling-wheel-driven",
                 "rolling-cylinder-between-plates", "rolling-plates-stated",
                 "rolling-wheel-rim-pin"]


def test_the_bar_s_sliding_velocity_is_its_point_over_the_cylinder():
    """The book's bar on a half-cylinder, A pushed along the floor at 0.5 m/s (tests/data):
    by hand, φ = 36.87° (u = (0.8, 0.6)), ω = 1 rad/s CCW, α = 3 rad/s² CCW, the contact
    T = (240, 180) mm, 300 mm from A.  The bar's point at T moves at v_A + ω k × AT =
    (0.32, 0.24) m/s = 0.4 u: it slides over the cylinder at 0.4 m/s (v_A·u).  The contact
    point itself runs round the cylinder at R·ω = 0.1 m/s back along u, so along the bar (relative
    to it) at −0.1 − 0.4 = −0.5 m/s: the number reported as the sliding velocity before."""
    sol = solve(load_scene(FLOOR))
    h = higher(sol, sol.scene.equivalents[0])
    ok = lambda a, b: abs(a - b) <= 1e-12    # noqa: E731
    assert ok(h["sliding_velocity"], 0.4)
    assert all(ok(a, b) for a, b in zip(h["bar_point_velocity"], (0.32, 0.24)))
    assert ok(h["contact_velocity_along_circle"], -0.1)
    assert ok(h["contact_velocity_along_bar"], -0.5)
    # a = α k × AT − ω² AT = 3·0.3·(−0.6, 0.8) − 0.3·(0.8, 0.6)
    assert all(ok(a, b) for a, b in zip(h["bar_point_acceleration"], (-0.78, 0.54)))
    assert all(ok(a, b) for a, b in zip(h["contact"], (0.24, 0.18)))


def test_the_report_names_the_sliding_velocity_and_the_contact_speeds_apart():
    from polygons.contacts import report_lines
    text = "\n".join(report_lines(solve(load_scene(FLOOR))))
    assert "slides over the cylinder at 0.4 m/s (sliding velocity" in text
    assert "moves along the bar at 0.5 m/s (relative to the bar)" in text
    assert "round the cylinder at 0.1 m/s" in text


@pytest.mark.parametrize("name", CONTACT_CASES)
def test_every_output_is_named_and_documented(name):
    """No field of a higher pair that OUTPUTS (and so the generated docs) does not name."""
    sol = solve(load_scene(CASES / f"{name}.toml"))
    for q, row in zip(sol.scene.equivalents, to_list(sol)):
        named = {f for f, _ in OUTPUTS[q.kind]}
        h = higher(sol, q) or {}
        assert set(h) <= named, (q.kind, set(h) - named)
        assert set(row.get("higher_pair", {})) <= named
    doc = (CASES.parent / "docs" / "contact-outputs.md").read_text(encoding="utf-8")
    for kind, fields in OUTPUTS.items():
        for f, _ in fields:
            assert f"`{f}`" in doc


def test_a_curved_slot_s_sliding_velocity_is_the_pin_over_the_slot():
    """A slot cut in the frame: the pin's sliding velocity is its own speed, along the
    tangent."""
    sol = solve(load_scene(CASES / "curved-slot-pin.toml"))
    h = higher(sol, sol.scene.equivalents[0])
    v = sol.points["P"].velocity
    assert h["slot_body"] == "frame"
    assert abs(h["sliding_velocity"] - (v[0] * h["tangent"][0] + v[1] * h["tangent"][1])) \
        <= 1e-12 * math.hypot(*v)
    assert abs(abs(h["sliding_velocity"]) - math.hypot(*v)) <= 1e-9 * math.hypot(*v)
