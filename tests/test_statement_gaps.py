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
