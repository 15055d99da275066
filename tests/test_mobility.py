"""Mobility before solving (Grübler–Kutzbach) and redundant links: a scene that does not move
with its stated inputs is refused in the textbook's words, naming the links; tested through the
real entry point (one line on stderr, exit 1)."""
import tomllib

import pytest

from conftest import case_files, cli
from polygons.errors import PolygonsError
from polygons.mobility import MobilityError, check_redundant_lengths, mobility
from polygons.plan import make_plan
from polygons.scene import load_scene, parse_scene
from scenes import four_bar_text

FOUR_BAR = four_bar_text('angle = "60 deg"\nomega = "10 rad/s"\nsense = "CW"', "{extra}")

REDUNDANT_QS = FOUR_BAR.format(extra='''QS = "50 mm"
[points.Q]
on = "BC"
fraction = 0.5
[points.S]
on = "CD"
fraction = 0.5''')

TRUSS = """
[ground]
A = ["0 mm", "0 mm"]
C = ["100 mm", "0 mm"]
[links]
AB = "60 mm"
BC = "70 mm"
[driver]
crank = "AB"
angle = "60 deg"
omega = "139 rad/s"
sense = "CCW"
"""

FIVE_BAR = """
[ground]
A = ["0 mm", "0 mm"]
E = ["200 mm", "0 mm"]
[links]
AB = "60 mm"
BC = "120 mm"
CD = "120 mm"
DE = "60 mm"
[driver]
crank = "AB"
angle = "60 deg"
omega = "10 rad/s"
sense = "CW"
"""


def scene(text):
    return parse_scene(tomllib.loads(text), file="t.toml")


def run_cli(tmp_path, text):
    f = tmp_path / "scene.toml"
    f.write_text(text)
    return cli("solve", f)           # the entry point function, in this process


@pytest.mark.parametrize("path", case_files(), ids=lambda p: p.stem)
def test_every_shipped_case_has_one_degree_of_freedom_per_input(path):
    scene = load_scene(path)
    m = mobility(scene)
    # a prescribed slide (a collar driven along a link) is a second input and a body of its own
    assert m.dof == len(m.inputs) == 1 + len(scene.prescribed)


def test_a_collar_on_a_rotating_rod_has_two_degrees_of_freedom():
    # frame, rod OA, collar C: n = 3; pin O and the collar's slide on OA: j = 2 → F = 6 − 4 = 2
    m = mobility(load_scene(case_files()[0].parent / "new-collar-on-rotating-rod.toml"))
    assert (len(m.bodies) + 1, m.revolutes, m.prismatics, m.dof) == (3, 1, 1, 2)
    assert m.inputs == ("OA", "collar C")


def test_hand_count_of_a_slider_crank():
    # frame, crank, rod, slider: n = 4; pins O, A, B and the slide: j = 4 → F = 9 − 8 = 1
    m = mobility(load_scene(case_files()[0].parent / "s001-we4.toml"))
    assert (len(m.bodies) + 1, m.revolutes, m.prismatics, m.dof) == (4, 3, 1, 1)


def test_a_redundant_link_across_a_four_bar_is_refused_naming_it(tmp_path):
    with pytest.raises(MobilityError) as e:
        make_plan(scene(REDUNDANT_QS))
    assert e.value.dof == 0 and e.value.links == ("QS",)
    r = run_cli(tmp_path, REDUNDANT_QS)
    assert r.returncode == 1 and r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("polygons: error: ")
    assert "QS is redundant" in lines[0] and "locked structure" in lines[0]
    assert "F = 3(5 − 1) − 2 × 6 = 0" in lines[0]


def test_a_locked_structure_is_not_solved(tmp_path):
    r = run_cli(tmp_path, TRUSS)
    assert r.returncode == 1 and "locked structure" in r.stderr and "AB, BC" in r.stderr
    assert "rad/s" not in r.stdout


def test_too_few_inputs_says_how_many_more(tmp_path):
    with pytest.raises(MobilityError) as e:
        make_plan(scene(FIVE_BAR))
    assert e.value.dof == 2
    assert "needs 1 more input" in str(e.value)


def test_an_over_constrained_scene_is_refused():
    text = REDUNDANT_QS.replace('QS = "50 mm"', 'QS = "50 mm"\nBD = "100 mm"')
    with pytest.raises(MobilityError) as e:
        make_plan(scene(text))
    assert e.value.dof == -1 and "over-constrained" in str(e.value)


def test_a_redundant_link_must_have_its_stated_length():
    sc = scene(FOUR_BAR.format(extra=""))
    plan = make_plan(sc)
    # a plan without the dyad of C: BC and CD join points placed by other means
    from dataclasses import replace
    from polygons.position import assemble
    pts = dict(assemble(plan).points)
    partial = replace(plan, dyads=tuple(d for d in plan.dyads if "C" not in d.placed))
    check_redundant_lengths(sc, partial, pts)             # both fit exactly
    pts["C"] = (0.2, 0.177)
    with pytest.raises(MobilityError, match=r"link BC is 136 mm in \[links\]"):
        check_redundant_lengths(sc, partial, pts)
    assert isinstance(MobilityError("x"), PolygonsError)
