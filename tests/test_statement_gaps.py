"""The statement gaps of issue 32, each tested as the book words it."""
import json
import math
import tomllib

import pytest

from conftest import ROOT
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_scene

KLEIN = ROOT / "cases" / "klein-inline-engine.toml"


def _scene(path, **tables):
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data.update(tables)
    return parse_scene(data, file=str(path))


def test_klein_on_is_an_answer_without_asking_for_klein(tmp_path):
    """"Find ON by Klein's construction, and hence the piston's acceleration": ON is read off
    the space diagram (a_P = ω²·NO) whenever an answer names N, and `solve` reports the
    construction without --klein."""
    scene = _scene(KLEIN, answers=[{"quantity": "dist(O,N)", "unit": "mm"},
                                   {"quantity": "dist(O,M)", "unit": "mm"}])
    sol = solve(scene)
    w = abs(scene.driver.omega)
    assert quantity(sol, "dist(O,N)") == pytest.approx(quantity(sol, "a(P)") / w ** 2,
                                                       rel=1e-9)
    assert quantity(sol, "dist(O,M)") == pytest.approx(quantity(sol, "v(P)") / w, rel=1e-9)
    with pytest.raises(Exception, match="point of a construction"):
        quantity(sol, "v(N)")
    path = tmp_path / "k.toml"
    text = KLEIN.read_text(encoding="utf-8") + '\n[[answers]]\nquantity = "dist(O,N)"\nunit = "mm"\n'
    path.write_text(text, encoding="utf-8")
    from polygons.cli import main
    out = tmp_path / "out.txt"
    assert main(["solve", str(path), "--no-steps", "-o", str(out)]) == 0
    assert "Klein's construction" in out.read_text(encoding="utf-8")


def test_centres_json_names_links_by_a_stable_key(tmp_path):
    """A truss on the coupler is one link of the circle diagram whose report name grows
    ('BC (with 4 links fixed to it)'); its JSON key stays 'BC', every centre carries the two
    keys."""
    from polygons.centres import instant_centres
    from polygons.cli.centres import to_json
    pts = {"A": (0.0, 0.0), "D": (0.1, 0.0), "B": (0.02, 0.05), "C": (0.115, 0.06),
           "T1": (0.07, 0.1), "T2": (0.09, 0.14)}
    links = {a + b: f"{math.dist(pts[a], pts[b])!r} m"
             for a, b in (("A", "B"), ("B", "C"), ("D", "C"), ("B", "T1"), ("C", "T1"),
                          ("C", "T2"), ("T1", "T2"))}
    near = {x: {"near": [f"{pts[x][0]!r} m", f"{pts[x][1]!r} m"]} for x in ("C", "T1", "T2")}
    sol = solve(parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": ["0.1 m", "0 m"]},
        "links": links, "assembly": near,
        "driver": {"crank": "AB", "angle": f"{math.degrees(math.atan2(0.05, 0.02))!r} deg",
                   "omega": "10 rad/s", "sense": "CCW"}}))
    data = json.loads(json.dumps(to_json(sol, instant_centres(sol))))
    assert [x["key"] for x in data["links"]] == ["frame", "AB", "BC", "DC"]
    assert data["links"][2]["fixed"] == ["BT1", "CT1", "CT2", "T1T2"]
    i13 = next(c for c in data["centres"] if c["label"] == "I13")
    assert i13["keys"] == ["frame", "BC"]
    assert {o["key"] for o in data["omegas"]} == {"frame", "AB", "BC", "DC"}


def test_piston_effort_and_turning_moment_are_named_without_a_flywheel(tmp_path):
    """"Find the piston effort and the turning moment on the crank shaft" (no flywheel, no
    efficiency): F_P = F_gas − m a_P along the line of stroke, T = F_P · (OC sin(θ+β)/cos β)
    in the sense of rotation, both printed by `polygons forces`."""
    from polygons.cli import main
    from polygons.forces import analyse, force_quantity
    path = ROOT / "cases" / "question-engine-conditions.toml"
    scene = load_scene(path)
    an = analyse(scene)
    sol = solve(scene)
    fp = 2000.0 - 0.5 * quantity(sol, "as(P)")
    assert force_quantity(an, "Fp(P)") == pytest.approx(fp, rel=1e-12)
    r, l, th = 0.04, 0.14, math.radians(135)        # the crank pin above, P to the left
    beta = math.asin(r * math.sin(th) / l)
    # the rod's thrust F_P / cos β, its moment about O: F_P r sin(θ + β) / cos β
    torque = fp * r * math.sin(math.pi - th + beta) / math.cos(beta)
    assert force_quantity(an, "Tturn") == pytest.approx(torque, rel=1e-9)
    out = tmp_path / "f.txt"
    assert main(["forces", str(path), "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    # a signed moment written once, its size with its sense in words (torque > 0 here)
    assert f"turning moment T on the crank: {torque:.8g} N m in the sense of rotation" in text
    assert f"piston effort F_P at P" in text and f"{fp:.8g} N" in text


def test_a_vertical_engine_is_placed_from_inner_dead_centre():
    """"A vertical engine ... when the crank has turned 25° from the inner dead centre": the
    cylinder above O, the line of stroke vertical; idc is the crank pointing at the cylinder
    (90°), 25° past it in the crank's sense (CW) is 65° from +x."""
    data = {"ground": {"O": ["0 mm", "0 mm"]}, "links": {"OC": "100 mm", "PC": "400 mm"},
            "driver": {"crank": "OC", "angle": "25 deg from idc", "omega": "10 rad/s",
                       "sense": "CW"},
            "sliders": {"P": {"through": ["0 mm", "0 mm"], "direction": "90 deg"}},
            "assembly": {"P": "P above O"}}
    sol = solve(parse_scene(data, file="vertical.toml"))
    assert math.degrees(sol.scene.driver.angle) == pytest.approx(65.0, abs=1e-12)
    c = math.radians(65.0)
    y = 0.1 * math.sin(c) + math.sqrt(0.4 ** 2 - (0.1 * math.cos(c)) ** 2)
    assert sol.points["P"].position[1] == pytest.approx(y, rel=1e-12)


LONE_WHEEL = """
title = "A wheel rolling on a level road"
[driver]
wheel = "O"
omega = "10 rad/s CW"
alpha = "4 rad/s^2 CCW"
[rolling.O]
radius = "500 mm"
through = ["0 m", "0 m"]
direction = "0 deg"
rim = { A = "90 deg", B = "0 deg", P = "-90 deg" }
[[answers]]
quantity = "v(A)"
unit = "m/s"
"""


def test_a_lone_wheel_needs_no_ground_point_and_its_centre_is_the_books_o(tmp_path):
    """"A wheel of 0.5 m radius, centre O, rolls without slipping on a level road at 10 rad/s
    clockwise, slowing at 4 rad/s².  Find the velocity and acceleration of the point A at the
    top, of B level with O and of the point P in contact with the road."  No [ground]: the
    road is the frame.  v_O = rω, a_O = rα along the road; v_A = 2rω; P: v = 0, a = rω² up;
    the rim points and O are points of the JSON like any other."""
    path = tmp_path / "wheel.toml"
    path.write_text(LONE_WHEEL, encoding="utf-8")
    sol = solve(load_scene(path))
    r, w, al = 0.5, -10.0, 4.0
    vo, ao = -w * r, -al * r                     # rolling to the right, slowing
    assert quantity(sol, "vs(O)") == pytest.approx(vo, rel=1e-12)
    assert quantity(sol, "as(O)") == pytest.approx(ao, rel=1e-12)
    assert quantity(sol, "v(A)") == pytest.approx(2 * r * abs(w), rel=1e-12)
    assert quantity(sol, "v(B)") == pytest.approx(math.sqrt(2) * r * abs(w), rel=1e-12)
    assert quantity(sol, "v(P)") == pytest.approx(0.0, abs=1e-12)
    assert quantity(sol, "a(P)") == pytest.approx(r * w * w, rel=1e-12)
    assert math.degrees(quantity(sol, "dir_a(P)")) == pytest.approx(90.0, abs=1e-9)
    assert quantity(sol, "omega(O)") == pytest.approx(w, rel=1e-12)
    from polygons.cli import main
    out = tmp_path / "w.json"
    assert main(["solve", str(path), "--json", "-o", str(out)]) == 0
    points = json.loads(out.read_text(encoding="utf-8"))["points"]
    assert {"O", "A", "B", "P"} <= set(points)
    assert points["A"]["speed"] == pytest.approx(2 * r * abs(w), rel=1e-12)
    assert points["P"]["acceleration_magnitude"] == pytest.approx(r * w * w, rel=1e-12)
    # the frame's one point is the road's `through` point, G, at rest
    assert points["G"]["speed"] == 0.0 and points["G"]["position"] == [0.0, 0.0]
