"""A wheel rolling without slipping on a MOVING straight surface, and a cylinder between two
moving plates (polygons.contacts, [rolling] with ``on`` / ``opposite``): the plates' motion from
independent slider-crank closed forms (tests/analytic_klein.py), the wheel's from the books'
formulas v_W = (v₁ + v₂)/2, ω = (v₁ − v₂)/2r, and the no-slip condition checked on the rigid
wheel itself (its points at the contacts move, tangentially, with the plates)."""
import math
import random
from pathlib import Path

import numpy as np
import pytest

from analytic_klein import slider_crank
from polygons.contacts import higher, report_lines
from polygons.errors import PolygonsError
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_scene as _parse, parse_toml

CASE = Path(__file__).resolve().parents[1] / "cases" / "rolling-cylinder-between-plates.toml"


def parse(text):
    return _parse(parse_toml(text, "x.toml"), file="x.toml")


def _near(a, b, tol=1e-9):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert np.max(np.abs(a - b)) <= tol * max(1.0, float(np.max(np.abs(b)))), (a, b)


def _k(w, d):
    return np.array([-w * d[1], w * d[0]])


def _plates(r, theta, omega, ls, es, lt, et, sides=(1.0, 1.0), alpha=0.0):
    return (slider_crank(r, ls, theta, omega, es, sides[0], alpha),
            slider_crank(r, lt, theta, omega, et, sides[1], alpha))


def _scene(r, theta, omega, ls, es, lt, et, rad, x_w, y_c, sides=("right", "right"),
           opposite=True, link=""):
    rolling = f"""
[rolling.W]
radius = "{rad * 1000!r} mm"
through = ["{x_w * 1000!r} mm", "{y_c * 1000!r} mm"]
direction = "0 deg"
on = "S"
""" + ('opposite = "T"\n' if opposite else "")
    return f"""
title = "t"
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "{r * 1000!r} mm"
AS = "{ls * 1000!r} mm"
AT = "{lt * 1000!r} mm"
{link}
[driver]
crank = "OA"
angle = "{math.degrees(theta)!r} deg"
omega = "{abs(omega)!r} rad/s"
sense = "{'CCW' if omega > 0 else 'CW'}"
[sliders.S]
through = ["0 mm", "{es * 1000!r} mm"]
direction = "0 deg"
[sliders.T]
through = ["0 mm", "{et * 1000!r} mm"]
direction = "0 deg"
{rolling}
[assembly]
S = "S {sides[0]} of A"
T = "T {sides[1]} of A"
"""


def _check_between(sol, S, T, rad, W):
    """Every number of the cylinder against the plates' closed forms and the rigid wheel."""
    (q,) = sol.scene.equivalents
    h = higher(sol, q)
    v1, v2, a1, a2 = S["v_B"], T["v_B"], S["a_B"], T["a_B"]
    _near(h["surface_velocity"], [v1, v2])
    _near(h["surface_acceleration"], [a1, a2])
    _near(h["centre"], W, 1e-15)
    _near(h["centre_velocity"], ((v1 + v2) / 2, 0.0))
    _near(h["centre_acceleration"], ((a1 + a2) / 2, 0.0))
    w, al = (v1 - v2) / (2 * rad), (a1 - a2) / (2 * rad)
    assert abs(h["omega"] - w) <= 1e-9 * max(1.0, abs(w))
    assert abs(h["alpha"] - al) <= 1e-9 * max(1.0, abs(al))
    # the rigid wheel: at each contact its point moves with the plate (no slip), and its
    # acceleration there is the plate's along the surface plus r·ω² towards the centre
    vW, aW, Wp = np.array(h["centre_velocity"]), np.array(h["centre_acceleration"]), np.array(W)
    for C, v, a, key in ((h["contacts"][0], v1, a1, "contact_acceleration"),
                         (h["contacts"][1], v2, a2, "opposite_contact_acceleration")):
        d = np.array(C) - Wp
        assert abs(np.linalg.norm(d) - rad) < 1e-15
        _near(vW + _k(h["omega"], d), (v, 0.0))
        acc = aW + _k(h["alpha"], d) - h["omega"] ** 2 * d
        _near(acc, h[key])
        _near(h[key], (a, -w * w * d[1]))
    # the instant centre: on the line of the contacts, where the wheel's velocity vanishes
    I = np.array(h["instant_centre"])
    assert abs(I[0] - W[0]) < 1e-12
    _near(vW + _k(h["omega"], I - Wp), (0.0, 0.0))
    return h


def test_cylinder_between_plates_case():
    sol = solve(load_scene(CASE))
    S, T = _plates(0.06, math.radians(15), 10.0, 0.25, -0.1, 0.22, 0.1)
    h = _check_between(sol, S, T, 0.04, (0.48, 0.0))
    # the plates move in opposite directions: the instant centre lies inside the cylinder
    assert S["v_B"] < 0 < T["v_B"] and abs(h["instant_centre"][1]) < 0.04
    # the case's stated answers (the plates' |v|, |a|) are the plates' closed forms
    r = 0.04
    exact = {"v(S)": S["v_B"], "a(S)": S["a_B"], "v(T)": T["v_B"], "a(T)": T["a_B"],
             # the cylinder itself, from the two no-slip conditions (signed, CCW +)
             "omega(W)": (S["v_B"] - T["v_B"]) / (2 * r), "v(W)": (S["v_B"] + T["v_B"]) / 2,
             "a(W)": (S["a_B"] + T["a_B"]) / 2, "alpha(W)": (S["a_B"] - T["a_B"]) / (2 * r)}
    assert sorted(a.quantity for a in sol.scene.answers) == sorted(exact)
    for ans in sol.scene.answers:
        assert abs(abs(exact[ans.quantity]) - ans.exact) < 1e-12 * max(1, ans.exact), ans
        # and the solver's own value of each asked quantity (signed where the table is)
        ours = quantity(sol, ans.quantity)
        want = exact[ans.quantity] if ans.quantity.startswith(("omega", "alpha")) \
            else abs(exact[ans.quantity])
        assert abs(ours - want) < 1e-9 * abs(want), (ans.quantity, ours, want)
    assert quantity(sol, "omega(W)") < 0          # the lower plate runs left: CW
    text = "\n".join(report_lines(sol))
    assert "v_W = (v₁ + v₂)/2 = " in text and "instant centre of the wheel" in text


def test_random_cylinders_between_plates():
    rng = random.Random(5)
    for _ in range(25):
        r = rng.uniform(0.02, 0.1)
        ls, lt = r * rng.uniform(3, 6), r * rng.uniform(3, 6)
        es, et = -rng.uniform(0, 1.5) * r, rng.uniform(0, 1.5) * r
        theta, omega = rng.uniform(-math.pi, math.pi), rng.choice((-1, 1)) * rng.uniform(2, 50)
        rad, xw = rng.uniform(0.01, 0.1), rng.uniform(-0.3, 0.3)
        yc = rng.uniform(-0.2, 0.2)
        sides = (rng.choice(("right", "left")), rng.choice(("right", "left")))
        sol = solve(parse(_scene(r, theta, omega, ls, es, lt, et, rad, xw, yc, sides)))
        S, T = _plates(r, theta, omega, ls, es, lt, et,
                       tuple(1.0 if s == "right" else -1.0 for s in sides))
        _check_between(sol, S, T, rad, (xw, yc + rad))


def test_wheel_on_one_moving_plate_driven_by_a_link():
    """A wheel pinned to the end of a link from the crank (W on the line ∥ the plate, the
    equivalent slider) rolling on the plate of S: ω = (v_S − v_W)/r, α = (a_S − a_W)/r, the
    instant centre on the normal through W at v_W/ω."""
    rng = random.Random(11)
    for _ in range(15):
        r = rng.uniform(0.02, 0.08)
        ls, lw = r * rng.uniform(3, 6), r * rng.uniform(3, 6)
        es, rad = -rng.uniform(0.5, 1.5) * r, rng.uniform(0.01, 0.05)
        yc = rng.uniform(-0.5, 0.5) * r
        ew = yc + rad
        theta, omega = rng.uniform(-math.pi, math.pi), rng.choice((-1, 1)) * rng.uniform(2, 50)
        text = _scene(r, theta, omega, ls, es, lw, 9.0, rad, 0.0, yc, opposite=False)
        text = text.replace(f'AT = "{lw * 1000!r} mm"', f'AW = "{lw * 1000!r} mm"')
        text = text.replace('[sliders.T]\nthrough = ["0 mm", "9000.0 mm"]\ndirection = "0 deg"\n',
                            "").replace('T = "T right of A"', 'W = "W right of A"')
        sol = solve(parse(text))
        S = slider_crank(r, ls, theta, omega, es)
        Wx = slider_crank(r, lw, theta, omega, ew)
        (q,) = sol.scene.equivalents
        h = higher(sol, q)
        _near(sol.points["W"].velocity, (Wx["v_B"], 0.0))
        w, al = (S["v_B"] - Wx["v_B"]) / rad, (S["a_B"] - Wx["a_B"]) / rad
        assert abs(h["omega"] - w) <= 1e-9 * max(1.0, abs(w))
        assert abs(h["alpha"] - al) <= 1e-9 * max(1.0, abs(al))
        W = np.array(sol.points["W"].position)
        C = np.array(h["contacts"][0])
        _near(np.array(h["centre_velocity"]) + _k(h["omega"], C - W), (S["v_B"], 0.0))
        I = np.array(h["instant_centre"])
        _near(np.array(h["centre_velocity"]) + _k(h["omega"], I - W), (0.0, 0.0))


BASE = _scene(0.05, 0.3, 10.0, 0.2, -0.08, 0.2, 0.08, 0.03, 0.2, -0.03)


@pytest.mark.parametrize("edit,words", [
    (('on = "S"', 'on = "Q"'), "must name a [sliders] point"),
    (('opposite = "T"', 'opposite = "S"'), "two different plates"),
    (('[sliders.T]\nthrough = ["0 mm", "80.0 mm"]\ndirection = "0 deg"',
      '[sliders.T]\nthrough = ["0 mm", "80.0 mm"]\ndirection = "30 deg"'), "along the surface"),
    (('AT = "200.0 mm"', 'AT = "200.0 mm"\nSW = "100 mm"'), "placed by them"),
    (('on = "S"', 'on = "W"'), "must name a [sliders] point"),
])
def test_refusals_in_one_line(edit, words):
    assert edit[0] in BASE, edit[0]
    with pytest.raises(PolygonsError) as exc:
        solve(parse(BASE.replace(*edit)))
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_centres_and_drawings(tmp_path):
    """`polygons centres` numbers the wheel after the links: its centre relative to each
    plate is the contact, relative to the frame on the line of the contacts, and
    v_W = ω · I₁ⱼW; the space diagram draws the plates and the wheel, rolling-W.svg the
    velocity distribution through I, with no label on another."""
    from polygons.centres import instant_centres
    from polygons.cli.centres import centre_lines
    from polygons.contacts import wheel_centres
    import diagrams
    from diagrams import rolling as dr
    from diagrams.labels import text_box
    from diagrams.model import Text
    sol = solve(load_scene(CASE))
    cs = instant_centres(sol, None)
    (row,) = wheel_centres(sol, cs)
    assert row["number"] == len(cs.bodies) + 1
    h = higher(sol, sol.scene.equivalents[0])
    assert [r["point"] for r in row["relative"]] == h["contacts"]
    assert {r["body"] for r in row["relative"]} == {"S", "T"}
    # Kennedy: I(1, wheel), I(wheel, S) = C₁ and I(1, S) (at infinity ⟂ the guide) collinear
    assert abs(row["absolute"][0] - h["contacts"][0][0]) < 1e-12
    d = math.dist(row["absolute"], row["centre"])
    assert abs(abs(row["omega"]) * d - row["speed"]) < 1e-12
    text = "\n".join(centre_lines(sol, cs))
    assert "I₄₇ (wheel W / the plate of S) = the contact point (480, -40) mm" in text
    paths = diagrams.write(sol, tmp_path, stages=False)
    names = {p.name for p in paths}
    assert "rolling-W.svg" in names and "space.svg" in names
    space = (tmp_path / "space.svg").read_text()
    for cls in ("wheel", "plate-S", "plate-T", "instant-centre"):
        assert cls in space, cls
    fig = (tmp_path / "rolling-W.svg").read_text()
    for cls in ("velocity-distribution", "line-of-contacts", "instant-centre"):
        assert cls in fig, cls
    d = dr.drawing(sol, sol.scene.equivalents[0])
    boxes = [text_box(t.x, t.baseline, t.text, t.size, t.anchor)
             for t in d.items() if isinstance(t, Text) and t.role == "point"]
    assert len(boxes) == 4          # C1, C2, W, I
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not a.overlaps(b)


def test_fixed_wheel_keeps_its_contact_as_centre():
    from polygons.centres import instant_centres
    from polygons.contacts import wheel_centres
    sol = solve(load_scene(CASE.parent / "rolling-wheel-driven.toml"))
    (row,) = wheel_centres(sol, instant_centres(sol, None))
    assert row["absolute"] == higher(sol, sol.scene.equivalents[0])["contacts"][0]


def test_wheel_quantities_are_checked_and_examined(tmp_path, capsys):
    """ω(W) of a wheel is graded by `check` (its drawn length ω r) and asked by `exam`."""
    from polygons.cli import main
    assert main(["check", str(CASE), "--measured", "omega(W)=-6.8", "v(W)=0.186"]) == 0
    assert "2 of 2 within tolerance" in capsys.readouterr().out
    assert main(["check", str(CASE), "--measured", "omega(W)=-9"]) != 0
    assert main(["exam", str(CASE), "--variants", "1", "--out", str(tmp_path / "x")]) == 0
    assert "ω_W" in capsys.readouterr().out


STATED = CASE.parent / "rolling-plates-stated.toml"


def _stated(vA, aA, vC, aC, r, opposite="C"):
    return parse(f"""
[ground]
O = ["0 mm", "-300 mm"]
[sliders.A]
through = ["0 mm", "0 mm"]
direction = "0 deg"
[driver]
slider = "A"
position = "0 mm"
velocity = "{vA!r} m/s"
acceleration = "{aA!r} m/s^2"
[rolling.B]
radius = "{r!r} m"
through = ["0 mm", "0 mm"]
direction = "0 deg"
on = "A"
opposite = "{opposite}"
opposite_velocity = "{vC!r} m/s"
opposite_acceleration = "{aC!r} m/s^2"
""")


def test_plates_moved_at_stated_rates_as_books_state_them():
    """The lower plate the input slider (a lone block), the upper one moved at its stated
    rate: v_B = (v_A + v_C)/2, ω = (v_A − v_C)/2r (CCW +), the same with accelerations."""
    sol = solve(load_scene(STATED))
    vA, aA, vC, aC, r = 4.0, 2.0, -2.0, 0.0, 0.125
    w, al, vB, aB = (vA - vC) / (2 * r), (aA - aC) / (2 * r), (vA + vC) / 2, (aA + aC) / 2
    exact = {"omega(B)": w, "v(B)": abs(vB), "alpha(B)": al, "a(B)": abs(aB),
             # the rim: T on top moves with the upper plate; R level with B, in front of it
             "v(T)": abs(vC), "v(R)": math.hypot(vB, w * r),
             "a(R)": math.hypot(aB - w * w * r, al * r)}
    for ans in sol.scene.answers:
        assert abs(abs(exact[ans.quantity]) - ans.exact) < 1e-12 * ans.exact, ans
        assert abs(quantity(sol, ans.quantity) - exact[ans.quantity]) < 1e-12 * ans.exact
    rng = random.Random(11)
    for _ in range(20):
        vA, aA, vC, aC = (rng.uniform(-5, 5) for _ in range(4))
        r = rng.uniform(0.01, 1.0)
        sol = solve(_stated(vA, aA, vC, aC, r))
        h = higher(sol, sol.scene.equivalents[0])
        w, al = (vA - vC) / (2 * r), (aA - aC) / (2 * r)
        assert abs(quantity(sol, "omega(B)") - w) < 1e-9 * max(1, abs(w))
        assert abs(quantity(sol, "alpha(B)") - al) < 1e-9 * max(1, abs(al))
        # the wheel's points at the two contacts move with their plates (no slip)
        vB = np.array(h["centre_velocity"])
        _near(vB + _k(w, np.array([0.0, -r])), (vA, 0.0))
        _near(vB + _k(w, np.array([0.0, r])), (vC, 0.0))


def test_plank_on_rollers_the_plank_a_lone_input_block():
    """A plank (the input block P) on a roller on the fixed floor: v_W = v_P/2, ω = −v_P/2r."""
    sol = solve(parse("""
[ground]
O = ["0 m", "0 m"]
[sliders.P]
through = ["0 m", "0.1 m"]
direction = "0 deg"
[driver]
slider = "P"
position = "0 m"
velocity = "2 m/s"
acceleration = "0.5 m/s^2"
[rolling.W]
radius = "50 mm"
through = ["0 m", "0 m"]
direction = "0 deg"
opposite = "P"
"""))
    assert abs(quantity(sol, "v(W)") - 1.0) < 1e-12
    assert abs(quantity(sol, "omega(W)") - (-20.0)) < 1e-12
    assert abs(quantity(sol, "alpha(W)") - (-5.0)) < 1e-12


@pytest.mark.parametrize("opposite,words", [
    ("A", "a label of its own"),           # the input block: it is not moved at a stated rate
    ("B", "a label of its own"),           # the cylinder itself
])
def test_stated_plate_refusals(opposite, words):
    with pytest.raises(PolygonsError, match=words):
        _stated(4.0, 0.0, -2.0, 0.0, 0.1, opposite=opposite)


def test_stated_plate_acceleration_alone_is_refused():
    text = STATED.read_text().replace('opposite_velocity = "-2 m/s"\n', "")
    with pytest.raises(PolygonsError, match="needs opposite_velocity"):
        parse(text)


def test_rim_points_of_a_wheel_on_the_ground():
    """[rolling.W] rim: the contact point is at rest with r·ω² towards W, the top moves at
    2 v_W, any point P at v_W + ω k × WP (the wheel of rolling-wheel-driven, on the floor)."""
    text = (CASE.parent / "rolling-wheel-driven.toml").read_text().replace(
        'direction = "0 deg"\n\n[assembly]',
        'direction = "0 deg"\nrim = { K = "270 deg", T = "90 deg", '
        'S = { angle = "30 deg", distance = "20 mm" } }\n\n[assembly]')
    assert "rim =" in text
    sol = solve(parse(text))
    W, vW, aW = (np.array(getattr(sol.points["W"], k)) for k in
                 ("position", "velocity", "acceleration"))
    w, al = quantity(sol, "omega(W)"), quantity(sol, "alpha(W)")
    assert quantity(sol, "v(K)") < 1e-12 * np.hypot(*vW)
    assert abs(quantity(sol, "a(K)") - 0.05 * w * w) < 1e-9 * 0.05 * w * w
    assert abs(quantity(sol, "dir_a(K)") - math.pi / 2) < 1e-9       # up, towards W
    assert abs(quantity(sol, "v(T)") - 2 * np.hypot(*vW)) < 1e-9 * np.hypot(*vW)
    d = 0.02 * np.array([math.cos(math.pi / 6), math.sin(math.pi / 6)])
    vS = vW + _k(w, d)
    aS = aW + _k(al, d) - w * w * d
    assert abs(quantity(sol, "v(S)") - np.hypot(*vS)) < 1e-9 * np.hypot(*vS)
    assert abs(quantity(sol, "a(S)") - np.hypot(*aS)) < 1e-9 * np.hypot(*aS)
    assert abs(quantity(sol, "dist(S,W)") - 0.02) < 1e-12
    assert any(line.lstrip().startswith("S (20 mm from W") for line in report_lines(sol))


@pytest.mark.parametrize("rim,words", [
    ('rim = { A = "90 deg" }', "already a point"),
    ('rim = { W = "90 deg" }', "already a point"),
    ('rim = { T = { angle = "90 deg", distance = "-1 mm" } }', "distance must be"),
    ('rim = { T = { distance = "1 mm" } }', "off the rim is"),
    ('rim = "T"', "rim must be a table"),
])
def test_rim_refusals(rim, words):
    text = (CASE.parent / "rolling-wheel-driven.toml").read_text().replace(
        'direction = "0 deg"\n\n[assembly]', f'direction = "0 deg"\n{rim}\n\n[assembly]')
    with pytest.raises(PolygonsError, match=words):
        parse(text)


@pytest.mark.parametrize("edit,words", [
    (('opposite = "C"', 'opposite = "<script>"'), "name it with a label"),
    (('radius = "125 mm"', 'radius = "1e-300 mm"'), "too short beside the mechanism"),
])
def test_stated_plate_and_radius_bounds(edit, words):
    with pytest.raises(PolygonsError, match=words):
        parse(STATED.read_text().replace(*edit))


def test_the_wheels_asked_results_are_marked_in_the_legend():
    """ω_W, α_W and a wheel's named points are not vertices of the polygons: the finished
    diagram's legend lists them with their rule, marked '← asked' when asked."""
    from diagrams import polygon
    sol = solve(load_scene(CASE.parent / "rolling-wheel-driven.toml"))
    rows = [t for t, _ in polygon.legend(polygon.layout(sol, "velocity"), sol)]
    w = next(t for t in rows if t.startswith("ω_W"))
    assert "7.793 rad/s CCW" in w and "no slip" in w and w.endswith("← asked")
    sol = solve(load_scene(STATED))
    rows = [t for t, _ in polygon.legend(polygon.layout(sol, "acceleration"), sol)]
    aR = next(t for t in rows if t.startswith("a_R"))
    assert "71.01" in aR and "− ω² BR" in aR and aR.endswith("← asked")
    assert any(t.startswith("a_B") and "mean of its plates" in t for t in rows)
    assert any(t.startswith("α_B") and "8 rad/s² CCW" in t for t in rows)


RIM_PIN = CASE.parent / "rolling-wheel-rim-pin.toml"


def _rim_pin(omega, alpha, phi, rho, L, xc, r=0.1):
    return parse(f"""
[ground]
O = ["0 mm", "0 mm"]
[links]
BC = "{L!r} m"
[driver]
wheel = "W"
omega = "{abs(omega)!r} rad/s {'CCW' if omega > 0 else 'CW'}"
alpha = "{abs(alpha)!r} rad/s^2 {'CCW' if alpha > 0 else 'CW'}"
[rolling.W]
radius = "{r!r} m"
through = ["0 mm", "0 mm"]
direction = "0 deg"
rim = {{ B = {{ angle = "{math.degrees(phi)!r} deg", distance = "{rho!r} m" }} }}
[sliders.C]
through = ["{xc!r} m", "0 m"]
direction = "90 deg"
[assembly]
C = "C above B"
""")


def test_a_driven_wheel_moves_a_rod_from_a_pin_on_it():
    """[driver] wheel: the collar's and the rod's motion equal the loop closed by hand
    (tests/analytic_contacts.py wheel_rim_rod_collar), on the case and on random wheels; the
    pin B is the image of the rigid wheel about W; a sweep follows the wheel as it rolls."""
    from analytic_contacts import wheel_rim_rod_collar
    from polygons.sweep import sweep
    sol = solve(load_scene(RIM_PIN))
    ex = wheel_rim_rod_collar(0.1, -4.0, -6.0, math.radians(150), 0.08, 0.3, 0.15)
    exact = {"vs(C)": ex["v_C"], "as(C)": ex["a_C"], "omega(BC)": ex["omega_BC"],
             "alpha(BC)": ex["alpha_BC"], "omega(W)": -4.0}
    for ans in sol.scene.answers:
        want = exact[ans.quantity]
        assert abs(quantity(sol, ans.quantity) - want) < 1e-9 * abs(want), ans.quantity
        assert abs(ans.exact - (abs(want) if ans.mode == "abs" else want)) < 1e-12 * abs(want)
    _near(sol.points["B"].velocity, ex["v_B"])
    _near(sol.points["B"].acceleration, ex["a_B"])
    rng = random.Random(13)
    done = 0
    while done < 20:
        omega, alpha = rng.uniform(-20, 20), rng.uniform(-50, 50)
        phi, rho = rng.uniform(-math.pi, math.pi), rng.uniform(0.02, 0.1)
        L, xc = rng.uniform(0.25, 0.5), rng.uniform(0.05, 0.2)
        ex = wheel_rim_rod_collar(0.1, omega, alpha, phi, rho, L, xc)
        if abs(ex["C"][1] - ex["B"][1]) < 0.3 * L:       # near the rod's toggle: skip
            continue
        sol = solve(_rim_pin(omega, alpha, phi, rho, L, xc))
        _near(sol.points["C"].position, ex["C"], 1e-12)
        assert abs(quantity(sol, "vs(C)") - ex["v_C"]) <= 1e-9 * max(1.0, abs(ex["v_C"]))
        assert abs(quantity(sol, "as(C)") - ex["a_C"]) <= 1e-9 * max(1.0, abs(ex["a_C"]))
        done += 1
    # the sweep rolls the wheel: at s the pin has turned by −s/r about W, and the sweep's
    # values at the scene's own position are the staged solve's
    scene = load_scene(RIM_PIN)
    sw = sweep(scene, inputs=[0.0, 0.01])
    s0 = solve(scene)
    assert abs(sw.pos["B"][0][0] - s0.points["B"].position[0]) < 1e-12
    ex = wheel_rim_rod_collar(0.1, -4.0, -6.0, math.radians(150) - 0.01 / 0.1, 0.08, 0.3,
                              0.15 - 0.01)              # the wheel 10 mm further on
    assert abs(sw.pos["C"][1][1] - ex["C"][1]) < 1e-12


@pytest.mark.parametrize("edit,words", [
    (('wheel = "W"', 'wheel = "Q"'), "must name a \\[rolling\\] wheel"),
    (('wheel = "W"', 'wheel = 7'), "wheel must be the label of a \\[rolling\\] wheel"),
    (('omega = "4 rad/s CW"', 'omega = "4 rad/s"'), "sense in words"),
    (('alpha = "6 rad/s^2 CW"', 'alpha = "6 rad/s^2 CW"\nspeed = "1 m/s"'), "a wheel driver takes"),
])
def test_wheel_driver_refusals(edit, words):
    with pytest.raises(PolygonsError, match=words):
        parse(RIM_PIN.read_text().replace(*edit))


def test_centres_of_a_driven_wheel_turn_it_about_its_contact():
    """The driven wheel is body 2: I₁₂ is its contact with the floor (not a guide's point at
    infinity), so the rod's ω by the centres is the polygon's."""
    from polygons.centres import instant_centres
    sol = solve(load_scene(RIM_PIN))
    cs = instant_centres(sol)
    c12 = next(c for c in cs.centres if (c.i, c.j) == (1, 2))
    _near(c12.point, (0.0, 0.0), 1e-12)
    w = {o.number: o.omega for o in cs.omegas}
    assert abs(w[2] - (-4.0)) < 1e-12 and abs(w[3] - sol.links["BC"].omega) < 1e-9


def test_the_key_states_a_driven_wheel_as_the_book_does():
    """The handout's data table names the wheel, its input ω and α and its pin (not the
    equivalent slider the solver moves)."""
    from diagrams.handout import handout
    text = handout(solve(load_scene(RIM_PIN)))
    assert "input wheel W</th><td>ω = 4 rad/s CW, α = 6 rad/s² CW" in text
    assert "pin B</th><td>on the wheel W, 80 mm from its centre at 150°" in text
    assert "input slider W" not in text
