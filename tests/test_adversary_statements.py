"""Statement forms books print that the trust campaign (helper 'adversary') found refused:
an angle in degrees and minutes (42°18'), an angular acceleration stated against the rotation
('retarding at 5 rad/s²'), and a rolling wheel driven by its centre's velocity and acceleration
(Hibbeler: 'its centre moves at 2 m/s to the right').  Each is checked against the form the
tool already took (the same numbers) and, for the wheel, v_W = −ω r, a_W = −α r."""
import json
import math
import re
from pathlib import Path

import pytest

import polygons
from polygons.errors import PolygonsError

FOUR_BAR = """
[ground]
A = ["0 mm", "0 mm"]
D = { from = "A", distance = "150 mm", angle = "0 deg" }
[links]
AB = "40 mm"
BC = "150 mm"
CD = "80 mm"
[driver]
crank = "AB"
angle = "ANGLE"
omega = "120 rpm CW"
ALPHA
[assembly]
C = "C above AD"
"""


def _four_bar(angle="60 deg", alpha='alpha = "20 rad/s^2 CCW"'):
    return polygons.solve(FOUR_BAR.replace("ANGLE", angle).replace("ALPHA", alpha))


def _crank_angle(res):
    x, y = res.points["B"].position
    return math.degrees(math.atan2(y, x))


@pytest.mark.parametrize("text, degrees", [("42°18'", 42.3), ("42° 18′ 30″", 42 + 18 / 60 + 30 / 3600),
                                           ("42 deg 18 min", 42.3), ("-5°30'", -5.5)])
def test_an_angle_in_degrees_and_minutes_is_read_as_books_print_it(text, degrees):
    assert _crank_angle(_four_bar(text)) == pytest.approx(degrees, abs=1e-12)
    # and everywhere an angle is read: "from" a line, a pivot placed from another
    res = _four_bar(f"{text} CW from AD")
    assert _crank_angle(res) == pytest.approx(-degrees, abs=1e-12)


def test_minutes_of_arc_at_or_above_sixty_are_refused_in_one_line():
    with pytest.raises(PolygonsError, match="minutes and seconds of arc are below 60"):
        _four_bar("42°60'")


def test_the_schema_accepts_degrees_and_minutes_and_alpha_against_the_rotation():
    schema = json.loads((Path(polygons.__file__).parent / "scene.schema.json").read_text())
    drv = schema["properties"]["driver"]["properties"]
    alpha = drv["alpha"]["pattern"]
    for ok in ("5 rad/s^2 retarding", "5 rad/s^2 decelerating", "5 rad/s^2 CW", "5 rad/s^2"):
        assert re.search(alpha, ok), ok
    assert not re.search(alpha, "5 rad/s^2 sideways")
    guide = next(iter(schema["properties"]["sliders"]["patternProperties"].values()))
    direction = guide["properties"]["direction"]["pattern"]
    for ok in ("30°15'", "30 deg 15 min", "30 deg", "-5°30'"):
        assert re.search(direction, ok), ok
    assert not re.search(direction, "30°75")


@pytest.mark.parametrize("word, sense", [("retarding", "CCW"), ("decelerating", "CCW"),
                                         ("accelerating", "CW")])
def test_alpha_against_the_rotation_takes_its_sense_from_omega(word, sense):
    said = _four_bar(alpha=f'alpha = "5 rad/s^2 {word}"')     # ω is CW
    plain = _four_bar(alpha=f'alpha = "5 rad/s^2 {sense}"')
    assert said.links["AB"].alpha == plain.links["AB"].alpha == (5.0 if sense == "CCW" else -5.0)
    assert said.points["C"].acceleration == plain.points["C"].acceleration


def test_alpha_against_the_rotation_is_refused_with_a_sense_or_at_rest():
    with pytest.raises(PolygonsError, match="leave out alpha_sense"):
        _four_bar(alpha='alpha = "5 rad/s^2 retarding"\nalpha_sense = "CW"')
    with pytest.raises(PolygonsError, match="at rest"):
        polygons.solve(FOUR_BAR.replace("ANGLE", "60 deg").replace('omega = "120 rpm CW"',
                                                                   'omega = "0 rpm"')
                       .replace("ALPHA", 'alpha = "5 rad/s^2 retarding"'))


WHEEL = """
[ground]
O = ["0 mm", "0 mm"]
[links]
AB = "1000 mm"
[driver]
wheel = "W"
RATES
[rolling.W]
radius = "300 mm"
through = ["0 mm", "0 mm"]
direction = "20 deg"
rim = { A = "60 deg" }
[sliders.B]
through = ["0 mm", "200 mm"]
direction = "0 deg"
[assembly]
B = "B right of O"
"""


def test_a_wheel_driven_by_its_centres_velocity_is_the_wheel_driven_by_omega():
    """Hibbeler's form: the centre's velocity and acceleration along the surface; the same
    motion as ω = −v / r, α = −a / r (the wheel on the left of the surface's direction)."""
    by_centre = polygons.solve(WHEEL.replace(
        "RATES", 'velocity = "1.8 m/s"\nacceleration = "-0.9 m/s^2"'))
    by_omega = polygons.solve(WHEEL.replace(
        "RATES", 'omega = "6 rad/s CW"\nalpha = "3 rad/s^2 CCW"'))
    e = (math.cos(math.radians(20)), math.sin(math.radians(20)))
    vw = by_centre.points["W"].velocity
    assert vw[0] * e[0] + vw[1] * e[1] == pytest.approx(1.8, rel=1e-12)
    for p in ("W", "A", "B"):
        for got, want in ((by_centre.points[p].velocity, by_omega.points[p].velocity),
                          (by_centre.points[p].acceleration, by_omega.points[p].acceleration)):
            assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_a_wheel_given_omega_and_its_centres_velocity_is_refused_naming_both():
    with pytest.raises(PolygonsError, match="not both: drop omega"):
        polygons.solve(WHEEL.replace("RATES", 'velocity = "1.8 m/s"\nomega = "6 rad/s CW"'))
    with pytest.raises(PolygonsError, match="not both"):
        polygons.solve(WHEEL.replace("RATES", 'acceleration = "1 m/s^2"\nomega = "6 rad/s CW"'))


ENGINE_QUESTION = """
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "150 mm"
AP = "600 mm"
[driver]
crank = "OA"
angle = "30 deg from idc"
omega = "300 rpm CW"
[sliders.P]
from = "O"
offset = "-50 mm"
direction = "0 deg"
[assembly]
P = "P right of O"
[[questions]]
find = "angle"
quantity = "x(P)"
condition = "dead centres"
unit = "deg"
samples = 24
"""


def test_a_root_crank_angle_is_also_given_as_the_scene_states_its_angle():
    """The scene says '30 deg from idc': `ask` gives each root crank angle CCW from +x and, as
    the book would read it, from idc in the crank's sense — the dead centres of an offset engine
    (crank and rod in line, |OP| = l ± r) are 0° and 180° + the offset's two angles from idc."""
    from polygons.conditions import answer_all, report_lines, to_dict
    scene = polygons.load(ENGINE_QUESTION)
    findings = answer_all(scene)
    roots = to_dict(findings)[0]["roots"]
    r, l, e = 0.15, 0.6, -0.05
    idc = math.atan2(e, math.sqrt((l + r) ** 2 - e ** 2))
    odc = math.atan2(e, math.sqrt((l - r) ** 2 - e ** 2)) + math.pi
    want = sorted((math.degrees(idc - x) % 360.0) for x in (idc, odc))   # turned CW from idc
    got = sorted(x["as_stated"]["input"] % 360.0 for x in roots)
    assert got[1] == pytest.approx(want[1], abs=1e-7)
    assert min(got[0], 360 - got[0]) == pytest.approx(0.0, abs=1e-7)
    assert all(x["as_stated"]["from"] == "idc" for x in roots)
    assert "deg from idc" in "\n".join(report_lines(findings))


@pytest.mark.parametrize("omega, sense, turn", [
    ('"120 rpm anti clockwise"', None, 1), ('"120 rpm counter clockwise"', None, 1),
    ('"120 rpm c.w."', None, -1), ('"120 rpm"', "anti clockwise", 1), ('"120 rpm"', "ACW", 1),
    ('"120 rpm"', "Anticlockwise", 1), ('"120 rpm"', "counterclockwise", 1),
    ('"120 rpm"', "Clockwise", -1)])
def test_the_senses_books_print_are_read_alike_after_a_rate_and_as_the_sense_key(omega, sense,
                                                                                turn):
    """'anti clockwise' after a rate was read as 'clockwise' with 'rpm anti' an unknown unit;
    the sense key took 'anticlockwise' but not 'Anticlockwise' or 'counterclockwise'."""
    drive = f"omega = {omega}" + (f'\nsense = "{sense}"' if sense else "")
    res = polygons.solve(FOUR_BAR.replace("ANGLE", "60 deg").replace(
        'omega = "120 rpm CW"', drive).replace("ALPHA", ""))
    assert res.links["AB"].omega == pytest.approx(turn * 4 * math.pi, rel=1e-15)


def test_a_questions_angle_and_length_values_are_printed_as_the_table_prints_them():
    """Khurmi & Gupta's crank and slotted lever (fixed centres 240 mm, crank 120 mm, slotted bar
    450 mm): the bar's greatest inclination to the vertical is 30° (printed in rad before) and
    the stroke of its end 2 · 450 sin 30° = 450 mm, its ends at ±225 mm (printed in m)."""
    from polygons.conditions import answer_all, report_lines
    scene = polygons.load("""
[ground]
O = ["0 mm", "0 mm"]
C = { from = "O", distance = "240 mm", angle = "-90 deg" }
[links]
OA = "120 mm"
CD = "450 mm"
[driver]
crank = "OA"
angle = "60 deg"
omega = "30 rpm CW"
[slots.A]
lever = "CD"
coincident = "A1"
[[questions]]
find = "angle"
quantity = "angle(D,C,O)"
condition = "max"
unit = "deg"
samples = 24
[[questions]]
find = "angle"
quantity = "x(D)"
condition = "stroke"
unit = "mm"
samples = 24
""")
    text = "\n".join(report_lines(answer_all(scene)))
    assert text.count("angle(D,C,O) = 30 deg") == 2
    assert "stroke = 450 mm" in text and "x(D) = 225 mm" in text and "x(D) = -225 mm" in text


@pytest.mark.parametrize("text, dimension, si", [
    ("50 kN-m", "torque", 5e4), ("50 kN·m", "torque", 5e4), ("0.5 kg-m²", "inertia", 0.5),
    ("0.5 kg·m^2", "inertia", 0.5), ("72 km/hr", "velocity", 20.0), ("72 kmph", "velocity", 20.0),
    ("30 m/min", "velocity", 0.5), ("1.2 metres", "length", 1.2), ("300 millimetres", "length", 0.3),
    ("10 kgf", "force", 98.0665), ("35 N/cm^2", "pressure", 3.5e5)])
def test_the_unit_spellings_books_print(text, dimension, si):
    """Khurmi & Gupta print kN-m and kg-m², Indian books km/hr and kmph, shaper problems a
    cutting speed in m/min, older books kgf and N/cm²: each was 'unknown unit'."""
    from polygons.units import parse_quantity
    assert parse_quantity(text, dimension) == pytest.approx(si, rel=1e-15)


def test_a_questions_range_may_be_stated_as_the_scene_states_its_crank_angle():
    """'between the inner and the outer dead centre' — range = ["0 deg from idc", "180 deg from
    idc"] (the crank turning CW: the interval reversed in +x terms); the roots against the
    offset engine's closed form x = r cos θ + √(l² − (e − r sin θ)²), v = ẋ, by bisection."""
    from polygons.conditions import answer_all, to_dict
    text = ENGINE_QUESTION.split("[[questions]]")[0] + """
[[questions]]
find = "angle"
quantity = "vs(P)"
condition = "value"
value = "-3 m/s"
range = ["0 deg from idc", "180 deg from idc"]
unit = "deg"
samples = 36
"""
    roots = to_dict(answer_all(polygons.load(text)))[0]["roots"]
    r, l, e, w = 0.15, 0.6, -0.05, -10 * math.pi
    idc = math.atan2(e, math.sqrt((l + r) ** 2 - e ** 2))

    def v(psi):              # ψ past idc, turned CW
        th = idc - math.radians(psi)
        s = e - r * math.sin(th)
        return w * (-r * math.sin(th) + s * r * math.cos(th) / math.sqrt(l * l - s * s)) + 3.0
    want = []
    for k in range(180):
        lo, hi = float(k), k + 1.0
        if (v(lo) > 0) != (v(hi) > 0):
            for _ in range(100):
                mid = (lo + hi) / 2
                lo, hi = (mid, hi) if (v(mid) > 0) == (v(lo) > 0) else (lo, mid)
            want.append(lo)
    got = sorted(x["as_stated"]["input"] for x in roots)
    assert got == pytest.approx(want, abs=1e-7) and len(want) == 2
    with pytest.raises(PolygonsError, match="from odc too"):
        polygons.load(text.replace('"180 deg from idc"]', '"180 deg from odc"]'))


TRAMMEL = """
[ground]
O = ["0 mm", "0 mm"]
[links]
AB = "400 mm"
[sliders.A]
through = ["0 mm", "0 mm"]
direction = "DIR"
[sliders.B]
through = ["0 mm", "0 mm"]
direction = "90 deg"
[driver]
slider = "A"
position = "POS"
velocity = "V"
acceleration = "ACC"
[assembly]
B = "B above O"
"""


@pytest.mark.parametrize("direction, pos, words, signed", [
    ("0 deg", "200 mm", ("2 m/s to the left", "5 m/s^2 to the right"), ("-2 m/s", "5 m/s^2")),
    ("180 deg", "-200 mm", ("2 m/s to the left", "5 m/s^2 Right"), ("2 m/s", "-5 m/s^2"))])
def test_a_slider_drivers_rates_in_words_as_hibbeler_gives_them(direction, pos, words, signed):
    """'block A moves to the left at 2 m/s, slowing at 5 m/s²': the magnitude and the direction
    in words are the signed value along the guide (either way the guide's direction is
    written); a guide along neither axis refuses the words in one line."""
    def solve(v, a):
        return polygons.solve(TRAMMEL.replace("DIR", direction).replace("POS", pos)
                              .replace('"V"', f'"{v}"').replace('"ACC"', f'"{a}"'))
    by_words, by_sign = solve(*words), solve(*signed)
    for p in ("A", "B"):
        assert by_words.points[p].velocity == by_sign.points[p].velocity
        assert by_words.points[p].acceleration == by_sign.points[p].acceleration
    assert by_words.points["A"].velocity[0] == pytest.approx(-2.0, rel=1e-15)
    with pytest.raises(PolygonsError, match="runs at 30°"):
        polygons.solve(TRAMMEL.replace("DIR", "30 deg").replace("POS", "200 mm")
                       .replace('"V"', '"2 m/s up"').replace('"ACC"', '"0 m/s^2"'))


def _segments_cross(p, q, r, s):
    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    return side(p, q, r) * side(p, q, s) < 0 and side(r, s, p) * side(r, s, q) < 0


@pytest.mark.parametrize("angle", ["60 deg", "135 deg", "240 deg", "300 deg"])
def test_a_four_bars_open_and_crossed_circuits_as_norton_names_them(angle):
    """'C open' / 'C crossed' (Norton, Uicker, Myszka): the closure whose links do not cross /
    do (AB with CD, or BC with the frame DA), here against the circle–circle closures."""
    def solve(words):
        return polygons.solve(FOUR_BAR.replace("ANGLE", angle).replace("ALPHA", "")
                              .replace('C = "C above AD"', f'C = "{words}"'))
    a, d = (0.0, 0.0), (0.15, 0.0)
    for words, crossed in (("open", False), ("C crossed", True), ("C open circuit", False)):
        res = solve(words)
        b, c = res.points["B"].position, res.points["C"].position
        assert (_segments_cross(a, b, c, d) or _segments_cross(b, c, d, a)) == crossed
    # the other words give the other closure
    assert solve("open").points["C"].position != solve("crossed").points["C"].position


def test_open_and_crossed_are_refused_where_they_do_not_choose_or_name_no_four_bar():
    with pytest.raises(PolygonsError, match="both of the closures"):      # B on AD: both open
        polygons.solve(FOUR_BAR.replace("ANGLE", "0 deg").replace("ALPHA", "")
                       .replace('C = "C above AD"', 'C = "C open"'))
    with pytest.raises(PolygonsError, match="names a four-bar's circuit"):
        polygons.load(ENGINE_QUESTION.split("[[questions]]")[0]
                      .replace('"30 deg from idc"', '"30 deg"')
                      .replace('P = "P right of O"', 'P = "P open"'))
