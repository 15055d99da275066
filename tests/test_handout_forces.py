"""``[handout] force_polygons`` / ``zhukovsky``: the force methods in the answer key.

The sections are checked against Newton–Euler's solution and the virtual work (independent of
the graphical constructions), the keys' refusals and where the sections land."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from polygons.errors import PolygonsError, UnknownKeyError
from polygons.forces import analyse
from polygons.scene import load_scene

CASES = Path(__file__).resolve().parent.parent / "cases"
ASKED = ("forces-toggle-press", "s001-we8")


def _g6(x: float) -> str:
    return f"{x:.6g}".replace("-", "−")


def _with(tmp_path, stem: str, table: str) -> Path:
    p = tmp_path / f"{stem}.toml"
    p.write_text((CASES / f"{stem}.toml").read_text(encoding="utf-8").split("\n[handout]")[0]
                 + "\n" + table + "\n", encoding="utf-8")
    return p


BOTH = "[handout]\nforce_polygons = true\nzhukovsky = true"


@pytest.fixture(scope="module")
def keys(tmp_path_factory):
    """Each case's answer key with both sections (the shipped files ask for one each)."""
    from polygons.cli.handout import build
    tmp = tmp_path_factory.mktemp("keys")
    return {stem: build(str(_with(tmp, stem, BOTH))) for stem in ASKED}


def test_shipped_cases_ask_for_the_methods():
    asked = {stem: load_scene(CASES / f"{stem}.toml").options.handout for stem in ASKED}
    assert asked["s001-we8"].force_polygons and asked["forces-toggle-press"].zhukovsky


@pytest.mark.parametrize("stem", ASKED)
def test_sections_carry_newton_euler_and_virtual_work_numbers(stem, keys):
    page = keys[stem]
    an = analyse(load_scene(CASES / f"{stem}.toml"))
    st = an.states[0]
    i, j = page.index('<section id="force-polygons"'), page.index('<section id="zhukovsky"')
    polys, lever = page[i:j], page[j:page.index("</section>", j)]
    assert i < page.index("<footer")                       # before the footer, after results
    # the input torque: Newton–Euler's and the virtual work's, to the 8 figures printed
    for e in (st.ne.effort, st.vw_effort):
        sense = "CCW" if e > 0 else "CW"
        assert f"{abs(e):.8g} N m {sense}" in polys and f"{abs(e):.8g} N m {sense}" in lever
    # every pin reaction in the table is Newton–Euler's (magnitude, to 6 figures)
    table = polys[polys.index('id="force-polygon-reactions-'):]
    rows = re.findall(r"<tr><td>([^<]*)</td><td>([^<]*)</td>", table)
    assert len(rows) >= len(st.ne.pin)
    for (lab, body), f in st.ne.pin.items():
        assert (lab, body) in rows
        assert _g6(float(np.hypot(*f))) in table, (lab, body)
    # one finished figure per group with a polygon, and the lever
    assert polys.count("<svg") >= 2 and lever.count("<svg") == 1
    assert "Group 1" in polys or "group 1" in polys and "closes on" in polys
    assert 'F<span class="subsup"><sub>' in polys or "R<sub>" in polys      # typeset names


def test_not_asked_no_section_and_worksheet_never():
    from polygons.cli.handout import build
    page = build(str(CASES / "efficiency-four-bar.toml"))
    assert 'id="force-polygons"' not in page and 'id="zhukovsky"' not in page
    ws = build(str(CASES / "s001-we8.toml"), worksheet=True)
    assert 'id="force-polygons"' not in ws and 'id="zhukovsky"' not in ws


@pytest.mark.parametrize("table, words", [
    ("[handout]\nforce_polygon = true", "unknown key 'force_polygon'"),
    ("[handout]\nzhukovsky = 1", "zhukovsky must be true or false"),
])
def test_bad_keys_refused(tmp_path, table, words):
    with pytest.raises(PolygonsError) as e:
        load_scene(_with(tmp_path, "s001-we8", table))
    assert words in str(e.value) and "\n" not in str(e.value)
    if "unknown" in words:
        assert isinstance(e.value, UnknownKeyError)


@pytest.mark.parametrize("stem, table, words", [
    ("forces-actuator-four-bar", "[handout]\nforce_polygons = true",
     "force_polygons = true: the force-polygon construction finds the driver's effort"),
    ("s001-we4", "[handout]\nzhukovsky = true",
     "zhukovsky = true asks for a force method, but the scene has no [masses]"),
])
def test_method_refused_in_one_line(tmp_path, stem, table, words):
    from polygons.cli.handout import build
    with pytest.raises(PolygonsError) as e:
        build(str(_with(tmp_path, stem, table)))
    assert words in str(e.value) and "\n" not in str(e.value)
    assert "[handout." in str(e.value)


def test_every_state_has_its_sections_with_unique_ids(tmp_path):
    """A release case (two states): each state's groups, table and lever, ids never repeated."""
    from polygons.cli.handout import build
    page = build(str(_with(tmp_path, "s002-ex3.16", BOTH)))
    an = analyse(load_scene(CASES / "s002-ex3.16.toml"))
    assert len(an.states) == 2
    for st in an.states:
        assert f"<h3>{st.name}</h3>" in page
    ids = re.findall(r'\bid="([^"]+)"', re.sub(r"<svg\b.*?</svg>", "", page, flags=re.S))
    assert len(ids) == len(set(ids))
    assert page.count('id="force-polygon-reactions-') == page.count('id="zhukovsky-moments-') == 2
