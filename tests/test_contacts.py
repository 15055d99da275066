"""Cams and curved slots by their equivalent linkage (polygons.contacts): the follower's and
the pin's velocity and acceleration equal independent closed forms (tests/analytic_contacts.py,
tests/analytic_klein.py) to 1e-9; refusals in words; the space diagram draws the equivalent
link dashed and labelled."""
import math
import random
from pathlib import Path

import numpy as np
import pytest

from analytic_contacts import flat_follower, four_bar
from analytic_klein import slider_crank
from polygons.errors import PolygonsError, UnsupportedError
from polygons.evaluate import solve
from polygons.scene import load_scene, parse_scene as _parse, parse_toml

ROOT = Path(__file__).resolve().parents[1] / "cases"


def parse(text):
    return _parse(parse_toml(text, "x.toml"), file="x.toml")


def _near(a, b, tol=1e-9):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert np.max(np.abs(a - b)) <= tol * max(1.0, float(np.max(np.abs(b)))), (a, b)


def test_roller_follower_is_the_slider_crank():
    sol = solve(load_scene(ROOT / "cam-roller-follower.toml"))
    ex = slider_crank(0.025, 0.05, math.radians(60 - 90), 20.0)
    _near(sol.points["R"].velocity, (0.0, ex["v_B"]))
    _near(sol.points["R"].acceleration, (0.0, ex["a_B"]))
    (q,) = sol.scene.equivalents
    assert (q.kind, q.link, q.length) == ("cam", "CR", pytest.approx(0.05, abs=1e-15))


def test_flat_follower_is_the_scotch_yoke():
    sol = solve(load_scene(ROOT / "cam-flat-follower.toml"))
    ex = flat_follower(0.02, math.radians(30), 10.0, 0.05)
    _near(sol.points["F"].velocity, (0.0, ex["v"]))
    _near(sol.points["F"].acceleration, (0.0, ex["a"]))
    assert sol.scene.equivalents[0].kind == "flat-faced cam"


def _slot_scene(r, theta, omega, K, b, c, near):
    return f"""
[ground]
O = ["0 mm", "0 mm"]
K = ["{K[0] * 1000!r} mm", "{K[1] * 1000!r} mm"]
[links]
OA = "{r * 1000!r} mm"
AP = "{b * 1000!r} mm"
[driver]
crank = "OA"
angle = "{math.degrees(theta)!r} deg"
omega = "{abs(omega)!r} rad/s"
sense = "{'CCW' if omega > 0 else 'CW'}"
[curved_slots.P]
centre = "K"
radius = "{c * 1000!r} mm"
[assembly]
P = {{ near = ["{near[0] * 1000!r} mm", "{near[1] * 1000!r} mm"] }}
"""


def test_curved_slot_case_and_random_instances():
    sol = solve(load_scene(ROOT / "curved-slot-pin.toml"))
    ex = four_bar((0, 0), 0.03, math.radians(45), 15.0, (0.09, -0.02), 0.08, 0.07)
    _near(sol.points["P"].position, ex["P"])
    _near(sol.points["P"].velocity, ex["vP"])
    _near(sol.points["P"].acceleration, ex["aP"])
    rng = random.Random(4)
    done = 0
    while done < 15:
        r, b, c = rng.uniform(0.02, 0.05), rng.uniform(0.08, 0.12), rng.uniform(0.06, 0.1)
        K = (rng.uniform(0.08, 0.12), rng.uniform(-0.04, 0.04))
        theta, omega = rng.uniform(-math.pi, math.pi), rng.choice((-1, 1)) * rng.uniform(1, 50)
        try:
            ex = four_bar((0, 0), r, theta, omega, K, b, c, rng.choice((-1, 1)))
        except ValueError:
            continue           # this instance does not assemble
        if not np.all(np.isfinite(ex["aP"])):
            continue
        A = (r * math.cos(theta), r * math.sin(theta))
        # the closure nearest the exact P (the other is at least the chord away)
        sol = solve(parse(_slot_scene(r, theta, omega, K, b, c, [float(x) for x in ex["P"]])))
        P = sol.points["P"].position
        if math.dist(P, ex["P"]) > 1e-6:
            continue
        _near(sol.points["P"].velocity, ex["vP"], 1e-8)
        _near(sol.points["P"].acceleration, ex["aP"], 1e-8)
        assert abs(math.dist(P, K) - c) < 1e-12 and abs(math.dist(P, A) - b) < 1e-12
        done += 1


BASE = (ROOT / "cam-roller-follower.toml").read_text()


@pytest.mark.parametrize("edit,words", [
    (('radius = "40 mm"\n', ''), "centre of curvature and radius of curvature"),
    (('roller = "10 mm"\n', ''), "roller's radius"),
    (('roller = "10 mm"\n', 'roller = "10 mm"\nface = "0 deg"\n'), "flat-faced"),
    (('roller = "10 mm"\n', 'roller = "50 mm"\nconcave = true\n'), "concave"),
    (('roller = "10 mm"\n', 'roller = "10 mm"\nshape = "spline"\n'), "unknown key"),
    (('centre = "C"\n', 'centre = "R"\n'), "must differ"),
])
def test_refusals_in_words(edit, words):
    with pytest.raises(PolygonsError) as exc:
        parse(BASE.replace(*edit))
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_forces_refused_naming_the_method():
    with pytest.raises(UnsupportedError, match="polygons forces does not handle a cam contact"):
        parse(BASE + '\n[masses.OC]\nmass = "1 kg"\n')


def test_a_flat_follower_needs_its_guide():
    text = (ROOT / "cam-flat-follower.toml").read_text().replace("[sliders.F]", "[sliders.G]")
    with pytest.raises(PolygonsError, match=r"\[sliders.F\]"):
        parse(text)


def test_space_diagram_draws_the_equivalent_link():
    from diagrams.model import Text
    from diagrams.space import drawing
    from diagrams.svg import to_svg
    d = drawing(solve(load_scene(ROOT / "curved-slot-pin.toml")))
    assert any(isinstance(t, Text) and t.text == "equivalent link KP" for t in d.items())
    svg = to_svg(d).decode()
    assert "equivalent" in svg and "contact-arc" in svg
