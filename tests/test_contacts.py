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
FLOOR = Path(__file__).resolve().parent / "data" / "bar-on-half-cylinder-floor.toml"


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


def test_forces_of_a_rolling_contact_refused_naming_the_method():
    """(a cam's forces and a wheel rolling on a fixed surface are analysed:
    tests/test_contact_forces.py)"""
    text = (ROOT / "rolling-cylinder-between-plates.toml").read_text().split("[[answers]]")[0]
    with pytest.raises(UnsupportedError,
                       match="polygons forces does not handle a rolling contact"):
        parse(text + '\n[gravity]\ng = "9.81 m/s^2"\n')


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


def test_rolling_wheel_is_the_offset_slider_crank_and_turns_at_v_over_r():
    from polygons.contacts import higher
    sol = solve(load_scene(ROOT / "rolling-wheel-driven.toml"))
    ex = slider_crank(0.04, 0.15, math.radians(50), 12.0, e=0.02)
    _near(sol.points["W"].velocity, (ex["v_B"], 0.0))
    _near(sol.points["W"].acceleration, (ex["a_B"], 0.0))
    h = higher(sol, sol.scene.equivalents[0])
    assert abs(h["omega"] - (-ex["v_B"] / 0.05)) < 1e-9 * abs(h["omega"])
    assert abs(h["alpha"] - (-ex["a_B"] / 0.05)) < 1e-9 * abs(h["alpha"])
    # asked as the books ask it: the wheel's ω and α by its label, and the case's exact values
    from polygons.quantities import quantity
    assert abs(quantity(sol, "omega(W)") - (-ex["v_B"] / 0.05)) < 1e-9 * abs(h["omega"])
    assert abs(quantity(sol, "alpha(W)") - (-ex["a_B"] / 0.05)) < 1e-9 * abs(h["alpha"])
    exact = {a.quantity: a.exact for a in sol.scene.answers}
    assert abs(exact["omega(W)"] - abs(ex["v_B"]) / 0.05) < 1e-12 * exact["omega(W)"]
    assert abs(exact["alpha(W)"] - abs(ex["a_B"]) / 0.05) < 1e-12 * exact["alpha(W)"]
    # the contact is the wheel's instant centre: every wheel point's velocity is ω k × (p − I)
    I, W = h["instant_centre"], sol.points["W"].position
    _near(I, (ex["x_B"], -0.03), 1e-12)
    _near((-h["omega"] * (W[1] - I[1]), h["omega"] * (W[0] - I[0])), sol.points["W"].velocity)


def _bar(x, R, d, v):
    """φ, φ̇, φ̈ of a bar from A = (x, 0) tangent to the circle (d, R) of radius R, A moving at
    the steady v: (d − x) sin φ − R cos φ = R, differentiated by hand."""
    # tangent line from A: φ = atan2(R, d − x) · 2 (the circle touches the floor)
    phi = 2 * math.atan2(R, d - x)
    s, c = math.sin(phi), math.cos(phi)
    D = (d - x) * c + R * s
    w = v * s / D
    Nd = v * c * w
    Dd = -v * c - (d - x) * s * w + R * c * w
    return phi, w, (Nd * D - v * s * Dd) / (D * D)


def test_bar_on_a_half_cylinder():
    from polygons.contacts import higher
    sol = solve(load_scene(FLOOR))
    phi, w, a = _bar(0.0, 0.1, 0.3, 0.5)
    link = sol.links["AQ"]
    assert abs(link.omega - w) < 1e-9 and abs(link.alpha - a) < 1e-9
    Q = sol.points["Q"].position
    assert abs(math.atan2(Q[1], Q[0]) - phi) < 1e-12
    h = higher(sol, sol.scene.equivalents[0])
    T, I, K = h["contact"], h["instant_centre"], (0.3, 0.1)
    assert abs(math.dist(T, K) - 0.1) < 1e-12
    # Kennedy: I on the vertical through A and on the normal KT
    assert abs(I[0]) < 1e-12
    assert abs((I[0] - K[0]) * (T[1] - K[1]) - (I[1] - K[1]) * (T[0] - K[0])) < 1e-12
    rng = random.Random(9)
    for _ in range(10):
        x, v = rng.uniform(-0.2, 0.1), rng.uniform(-1, 1)
        text = FLOOR.read_text().replace(
            'position = "0 mm"', f'position = "{x * 1000!r} mm"').replace(
            'velocity = "0.5 m/s"', f'velocity = "{v!r} m/s"').split("[[answers]]")[0]
        sol = solve(parse(text))
        phi, w, a = _bar(x, 0.1, 0.3, v)
        assert abs(sol.links["AQ"].omega - w) < 1e-9 * max(1, abs(w))
        assert abs(sol.links["AQ"].alpha - a) < 1e-9 * max(1, abs(a))


@pytest.mark.parametrize("table,words", [
    ('[bearing.K]\nbar = "AQ"\nradius = "100 mm"\n', "missing key 'side'"),
    ('[bearing.K]\nbar = "XQ"\nradius = "100 mm"\nside = "left"\n', "give the bar's length in [links]"),
    ('[bearing.Z]\nbar = "AQ"\nradius = "100 mm"\nside = "left"\n', "[ground] point"),
])
def test_bearing_refusals(table, words):
    text = FLOOR.read_text().split("[bearing.K]")[0] + table
    with pytest.raises(PolygonsError) as exc:
        parse(text)
    assert words in str(exc.value)


def _bar_general(A, vA, aA, K, R):
    """φ, φ̇, φ̈ of a bar from A tangent to the circle (K, R) on its right:
    (K − A) × u = R, u = (cos φ, sin φ), differentiated by hand."""
    dx, dy = K[0] - A[0], K[1] - A[1]
    phi = math.atan2(dy, dx) + math.asin(R / math.hypot(dx, dy))
    s, c = math.sin(phi), math.cos(phi)
    D = dx * c + dy * s
    N = vA[0] * s - vA[1] * c
    w = N / D
    Nd = aA[0] * s + vA[0] * c * w - aA[1] * c + vA[1] * s * w
    Dd = -vA[0] * c - vA[1] * s + w * (-dx * s + dy * c)
    return phi, w, (Nd * D - N * Dd) / (D * D)


def test_bar_on_a_half_cylinder_driven_by_a_crank():
    sol = solve(load_scene(ROOT / "bar-on-half-cylinder.toml"))
    th, r, om, O = math.radians(30), 0.04, 10.0, (-0.1, 0.06)
    A = (O[0] + r * math.cos(th), O[1] + r * math.sin(th))
    vA = (-om * r * math.sin(th), om * r * math.cos(th))
    aA = (-om * om * r * math.cos(th), -om * om * r * math.sin(th))
    phi, w, a = _bar_general(A, vA, aA, (0.3, 0.1), 0.1)
    link = sol.links["AQ"]
    assert abs(link.omega - w) < 1e-9 and abs(link.alpha - a) < 1e-9
    Q = sol.points["Q"].position
    assert abs(math.atan2(Q[1] - A[1], Q[0] - A[0]) - phi) < 1e-12


def test_the_bar_s_instant_centre_is_kennedy_s():
    """The instant centre read off the bearing (normal at the contact × normal to A's path)
    is the one polygons centres finds by Kennedy's theorem on the equivalent linkage."""
    from polygons.centres import instant_centres
    from polygons.contacts import higher
    sol = solve(load_scene(ROOT / "bar-on-half-cylinder.toml"))
    h = higher(sol, sol.scene.equivalents[0])
    cs = instant_centres(sol)
    bar = next(b.number for b in cs.bodies if b.name == "AQ")
    frame = next(b.number for b in cs.bodies if b.name == "frame")
    _near(cs.centre(frame, bar).point, h["instant_centre"], 1e-12)


def _osc_flat(theta, omega, Q, rho, side, offset=0.0, e=0.02, arm=0.15):
    return f"""
[ground]
O = ["0 mm", "0 mm"]
Q = ["{Q[0] * 1e3!r} mm", "{Q[1] * 1e3!r} mm"]
[links]
OC = "{e * 1e3!r} mm"
QF = "{arm * 1e3!r} mm"
[driver]
crank = "OC"
angle = "{math.degrees(theta)!r} deg"
omega = "{abs(omega)!r} rad/s"
sense = "{'CCW' if omega > 0 else 'CW'}"
[cams.F]
follower = "flat"
centre = "C"
radius = "{rho * 1e3!r} mm"
arm = "QF"
side = "{'left' if side > 0 else 'right'}"
face_offset = "{offset * 1e3!r} mm"
"""


def test_oscillating_flat_follower_is_the_tangency_condition():
    """[cams.F] arm = "QF": the arm's ω and α equal the tangency condition differentiated by
    hand (tests/analytic_contacts.py), on the case and on random cams, faces and offsets."""
    from analytic_contacts import oscillating_flat_follower
    from polygons.scene import parse_scene, parse_toml
    sol = solve(load_scene(ROOT / "cam-oscillating-flat-follower.toml"))
    C = (0.02 * math.cos(math.radians(30)), 0.02 * math.sin(math.radians(30)))
    ex = oscillating_flat_follower((0, 0), 0.02, math.radians(30), 10.0, (0.1, 0.08), 0.05, -1,
                                   math.atan2(C[1] - 0.08, C[0] - 0.1))
    assert abs(sol.links["QF"].omega - ex["omega"]) < 1e-9 * abs(ex["omega"])
    assert abs(sol.links["QF"].alpha - ex["alpha"]) < 1e-9 * abs(ex["alpha"])
    for ans in sol.scene.answers:
        want = ex["omega"] if ans.quantity.startswith("omega") else ex["alpha"]
        assert abs(ans.exact - abs(want)) < 1e-12 * abs(want)
    rng = np.random.default_rng(3)
    done = 0
    while done < 25:
        theta, omega = rng.uniform(-math.pi, math.pi), rng.choice((-1, 1)) * rng.uniform(1, 40)
        Q = tuple(float(v) for v in rng.uniform(-0.15, 0.15, 2))
        rho, side = float(rng.uniform(0.02, 0.06)), int(rng.choice((-1, 1)))
        offset = float(rng.uniform(-0.01, 0.01))
        theta, omega = float(theta), float(omega)
        C = 0.02 * np.array([math.cos(theta), math.sin(theta)])
        d = offset + side * rho
        if np.hypot(*(C - np.array(Q))) < abs(d) * 1.3 + 0.01:
            continue                    # no tangent through Q's arm here, or near the toggle
        # the face touches the cam ahead of the pivot (the slot runs from Q towards F)
        near_phi = math.atan2(C[1] - Q[1], C[0] - Q[0])
        ex = oscillating_flat_follower((0, 0), 0.02, theta, omega, Q, rho, side, near_phi,
                                       offset)
        F = tuple(float(q + 0.15 * t) for q, t in zip(Q, (math.cos(ex["phi"]),
                                                          math.sin(ex["phi"]))))
        sol = solve(parse_scene(parse_toml(_osc_flat(theta, omega, Q, rho, side, offset),
                                           "x.toml"), file="x.toml"))
        Fs = sol.points["F"].position
        assert math.dist(Fs, F) < 1e-12, (Fs, F)
        link = sol.links["QF"]
        assert abs(link.omega - ex["omega"]) <= 1e-9 * max(1.0, abs(ex["omega"]))
        assert abs(link.alpha - ex["alpha"]) <= 1e-9 * max(1.0, abs(ex["alpha"]))
        done += 1


@pytest.mark.parametrize("edit,words", [
    (('arm = "QF"', 'arm = "QX"'), "arm must be a link"),
    (('side = "right"', 'side = "under"'), "side must be 'left' or 'right'"),
    (('arm = "QF"', 'arm = "QF"\nface = "0 deg"'), "give arm or face"),
    (('arm = "QF"', 'arm = "QF"\nroller = "5 mm"'), "roller and concave are for a roller"),
    (('arm = "QF"\nside = "right"', 'side = "right"\nface = "0 deg"'), "side and face_offset"),
])
def test_oscillating_flat_follower_refusals(edit, words):
    from polygons.errors import PolygonsError
    from polygons.scene import parse_scene, parse_toml
    text = (ROOT / "cam-oscillating-flat-follower.toml").read_text().replace(*edit)
    with pytest.raises(PolygonsError, match=words):
        parse_scene(parse_toml(text, "x.toml"), file="x.toml")


def test_words_about_a_point_with_one_position_must_hold():
    """[assembly] words on a point placed without a choice are checked, not passed over."""
    from polygons.scene import parse_scene, parse_toml
    text = (ROOT / "cam-oscillating-flat-follower.toml").read_text()
    ok = parse_scene(parse_toml(text + '\n[assembly]\nF = "F below OQ"\n', "x.toml"),
                     file="x.toml")
    assert solve(ok).points["F"].position[1] < 0
    bad = parse_scene(parse_toml(text + '\n[assembly]\nF = "F above OQ"\n', "x.toml"),
                      file="x.toml")
    with pytest.raises(PolygonsError, match="one position here.*not 'F above OQ'"):
        solve(bad)


def test_the_bar_on_a_cylinder_placed_by_its_angle():
    """"... its lower end B slides along the floor at 1 m/s ... when it makes 30° with the
    floor": the slider driver placed by its rod's angle while the rod bears on a circle (B
    where the line at 30° is tangent: (K − B)·n = −R), the bar's length left out (Q is its
    point at the contact) — against _bar_general; and the floor fixture without AQ's length
    gives what it gives with it."""
    from polygons.scene import load_scene
    case = Path(__file__).resolve().parent.parent / "cases" / "bar-on-cylinder-rod-angle.toml"
    scene = load_scene(case)
    sol = solve(scene)
    phi = math.radians(30)
    K, R = (0.3, 0.1), 0.1
    s = (K[0] * -math.sin(phi) + K[1] * math.cos(phi) + R) / -math.sin(phi)
    _, w, a = _bar_general((s, 0.0), (1.0, 0.0), (0.0, 0.0), K, R)
    want = {"omega(BQ)": w, "alpha(BQ)": a, "x(B)": s * 1e3}
    for ans in scene.answers:
        assert ans.exact == pytest.approx(abs(want[ans.quantity]), rel=1e-12) or \
            ans.exact == pytest.approx(want[ans.quantity], rel=1e-12)
    assert sol.points["B"].position[0] == pytest.approx(s, rel=1e-12)
    assert sol.links["BQ"].omega == pytest.approx(w, rel=1e-12)
    assert sol.links["BQ"].alpha == pytest.approx(a, rel=1e-9)
    Q = sol.points["Q"].position          # the bar's point touching the cylinder
    assert math.hypot(Q[0] - K[0], Q[1] - K[1]) == pytest.approx(R, rel=1e-12)
    with_length = solve(parse(FLOOR.read_text()))
    without = solve(parse(FLOOR.read_text().replace('AQ = "600 mm"', "")))
    assert without.links["AQ"].omega == pytest.approx(with_length.links["AQ"].omega, rel=1e-12)
    assert without.links["AQ"].alpha == pytest.approx(with_length.links["AQ"].alpha, rel=1e-12)
