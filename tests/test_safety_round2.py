"""Regression tests for issue 30's adversarial findings (round 2): internal errors A, C, D, F,
H, I, J, K, L, M, N, the --cycle work budget (P), ``--students`` of the wrong kind and
``solve --points`` on a case with answers — each by the kind of problem, not the instance:
every quantity of an unsolved polygon, every table of the wrong type, every shipped case in
one process in two orders.

The scenes the findings came with are in tests/data/ (nothing beside the clone is read).
In process and cheap (a few seconds in all).
"""
from __future__ import annotations

import math
import os
import re
from pathlib import Path

import numpy as np
import pytest

import polygons
from conftest import CASES, ROOT
from polygons.errors import PolygonsError
from test_safety import FOUR_BAR, refused, run

DATA = ROOT / "tests" / "data"


def ok(code, out, err) -> str:
    assert code == 0 and err == "", (code, err)
    return out


# ---------------------------------------------------------------- A: an unsolved polygon
def test_every_acceleration_quantity_of_a_velocity_only_scene_is_refused_by_its_kind(tmp_path):
    """Not only a(C): as(P), an, at, alpha, cor, dir_a — whatever the name, one line."""
    from polygons.quantities import FUNCTIONS
    base = (DATA / "velocity-only-slider-accel-answer.toml").read_text(encoding="utf-8")
    base = base.split("[[answers]]")[0]
    args = {"v": "P", "a": "P", "an": "P,C", "at": "P,C", "omega": "CP", "alpha": "CP",
            "vs": "P", "as": "P", "cor": "P", "dist": "P,C", "x": "P", "y": "P", "dir_v": "P",
            "dir_a": "P", "angle": "P,C,O", "arm": "O,P,C"}
    assert set(args) == set(FUNCTIONS), "a new quantity function: add it here"
    for fn, a in args.items():
        expr = f"{fn}({a})"
        path = tmp_path / f"{fn}.toml"
        path.write_text(base + f'[[answers]]\nquantity = "{expr}"\nunit = "-"\nexact = 1.0\n',
                        encoding="utf-8")
        code, out, err = run("solve", path, "--no-steps")
        if fn == "cor":       # a fixed guide has no Coriolis term, solved or not: refused too
            refused(code, out, err)
        elif fn in ("a", "at", "alpha", "as", "dir_a"):      # read off the acceleration polygon
            refused(code, out, err, "acceleration polygon", "answers[0]")
        else:                 # an: ω²·r needs only the velocity polygon; the rest, positions
            assert code == 0, (expr, err)


# ---------------------------------------------------------------- C: no recursion on user text
def test_a_label_word_of_thousands_of_capitals_is_split_without_recursion():
    from diagrams.notation import MARK, mark_labels
    word = "A" * 5000 + "O2"
    assert mark_labels(word, ["A", "O2"]) == "A" * 5000 + f"O{MARK}2"
    assert mark_labels("O2P2 SAE4 Q3", ["O2", "P2", "Q"]) == f"O{MARK}2P{MARK}2 SAE4 Q3"


def test_a_student_text_of_thousands_of_labels_is_split_without_recursion():
    from polygons.cli.check import _split_labels

    class Sol:
        points = {"C": 0, "B": 0, "P2": 0, "P": 0}
    assert len(_split_labels(Sol, "CB" * 5000)) == 10000
    assert _split_labels(Sol, "P2_P") == ["P2", "P"] and _split_labels(Sol, "PX") is None


def test_a_title_word_of_label_capitals_is_drawn(tmp_path):
    ok(*run("draw", DATA / "long-label-word-title.toml", "-o", tmp_path / "d", "--no-stages"))


# ---------------------------------------------------------------- D: every table's type
def _tables():
    from polygons.reference import collect
    return sorted({t.name for _, t in collect() if t.name})


@pytest.mark.parametrize("value", ["0", "1.5", "true", '"x"', "[1]"])
def test_every_section_of_the_wrong_type_is_refused_like_the_others(scene, value):
    """Every declared table given a number, a bool, a text or a list: refused in one line
    (solve reads the force tables too), never an internal error."""
    body = FOUR_BAR.split("\n", 1)[1]
    for name in _tables():
        text = re.sub(rf"^\[{name}\]\n(?:[^\[\n].*\n)*", "", body, flags=re.M)
        path = scene(f"{name} = {value}\n" + text)
        code, out, err = run("solve", path, "--no-steps")
        assert code in (0, 1) and "internal error" not in err, (name, value, err)
        if code == 1:
            refused(code, out, err)


@pytest.fixture
def scene(tmp_path):
    def write(text: str, name: str = "s.toml") -> Path:
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path
    return write


# ---------------------------------------------------------------- F: centres at rest
def test_the_centres_of_a_triad_at_rest_are_those_of_its_pose():
    """A centre is where the velocity ratios put it: at rest the same as at any rate."""
    text = (DATA / "triad-at-rest.toml").read_text(encoding="utf-8")
    rest = polygons.solve(text).centres()
    moving = polygons.solve(text.replace('omega = "0 rad/s CCW"', 'omega = "3 rad/s CCW"')
                            ).centres()
    a = {(c.i, c.j): c.point for c in rest.centres}
    b = {(c.i, c.j): c.point for c in moving.centres}
    assert a.keys() == b.keys() and len(a) == 15
    for k in a:
        assert (a[k] is None) == (b[k] is None), k
        if a[k] is not None:
            assert math.dist(a[k], b[k]) <= 1e-9 * 0.3, k
    assert all(o.omega == 0.0 for o in rest.omegas)


def test_centres_of_a_triad_at_rest_on_the_command_line():
    out = ok(*run("centres", DATA / "triad-at-rest.toml"))
    assert "I14" in out and "0 rad/s" in out


# ---------------------------------------------------------------- H: a toggle everywhere
def test_a_sweep_whose_every_position_is_a_toggle_is_refused(tmp_path):
    refused(*run("sweep", DATA / "toggle-everywhere.toml", "--steps", 36, "-o", tmp_path),
            "every probed position", "toggle")


def test_the_sweep_summary_takes_no_maximum_of_nothing():
    from polygons.cli.sweep import _peak
    assert "no position" in _peak(None, lambda sw: np.full(5, np.nan), 1.0, "m/s")


# ---------------------------------------------------------------- I, item 5: solve --points
@pytest.mark.parametrize("case, points", [
    (DATA / "wheel-between-plates.toml", "S"), (DATA / "wheel-between-plates.toml", "T"),
    (CASES / "rolling-plates-stated.toml", "O"), (CASES / "klein-offset-engine.toml", "O"),
    (CASES / "klein-inline-engine.toml", "O")])
def test_solve_points_also_solves_what_the_answers_read(case, points):
    out = ok(*run("solve", case, "--points", points, "--no-steps"))
    full = ok(*run("solve", case, "--no-steps"))
    answers = lambda t: [ln for ln in t.splitlines() if "exact" in ln or "✓" in ln]  # noqa
    assert answers(out) == answers(full)


def test_an_answer_reading_a_point_the_targets_left_out_says_so():
    res = polygons.solve(DATA / "wheel-between-plates.toml", targets=["S"])
    with pytest.raises(PolygonsError, match="does not place"):
        res.table()


# ---------------------------------------------------------------- J, K: --fluctuation
def test_a_plain_fluctuation_is_the_fraction_itself():
    case = CASES / "forces-toggle-press.toml"
    a = ok(*run("forces", case, "--cycle", 36, "--fluctuation", "0.02"))
    b = ok(*run("forces", case, "--cycle", 36, "--fluctuation", "2 %"))
    assert a == b and "I = ΔE / (ω² C_s) = " in a


@pytest.mark.parametrize("cs", ["5e-324", "1e-310", "1e-7", "1", "2", "-0.02", "0"])
@pytest.mark.parametrize("json", [(), ("--json",)])
def test_a_fluctuation_outside_its_range_is_refused(cs, json):
    refused(*run("forces", CASES / "forces-toggle-press.toml", "--cycle", 36,
                 "--fluctuation", cs, *json), "[--fluctuation]")


# ---------------------------------------------------------------- L: caches keyed by identity
def _points(res):
    return tuple(sorted((k, p.position, p.velocity, p.acceleration)
                        for k, p in res.solution.points.items()))


def _one(path, targets):
    try:
        scene = polygons.load(path)
        return _points(polygons.solve(scene, targets=[scene.labels[0]] if targets else None))
    except PolygonsError as exc:
        return f"refused: {exc}"


def test_every_shipped_case_in_one_process_in_two_orders_as_alone():
    """Each case's answer the same after any other case (forwards and backwards) as with
    every code cache empty: no state leaks from one scene into the next."""
    from polygons import compiled
    files = sorted(CASES.glob("*.toml"))
    alone = {}
    for f in files:
        for t in (False, True):
            compiled._CACHE.clear()
            alone[(f, t)] = _one(f, t)
    for order in (files, files[::-1]):
        compiled._CACHE.clear()
        for f in order:
            for t in ((True, False) if order is files else (False, True)):
                assert _one(f, t) == alone[(f, t)], (f.name, t)


# ---------------------------------------------------------------- M: one rule for a link
@pytest.mark.parametrize("bad", [5e-324, 1e-12, 1e-300, 0.0, -0.05])
def test_solve_many_refuses_a_link_length_a_scene_refuses(bad):
    scene = polygons.load(FOUR_BAR)
    b = polygons.solve_many(scene, AB=[0.1, bad])      # the row refused, as a scene file is
    assert list(b.ok) == [True, False] and [e.where for e in b.errors] == ["AB"]
    assert re.search("positive|too small", b.errors[0].reason)
    assert np.isnan(b.omega("BC")[1])
    with pytest.raises(PolygonsError, match="links.AB"):
        polygons.load(FOUR_BAR.replace('AB = "100 mm"', f'AB = "{bad} m"'))


# ---------------------------------------------------------------- N: --vary decimals
@pytest.mark.parametrize("spec, first, last", [
    ("theta=0.5..1deg:3", math.radians(0.5), math.radians(1.0)),
    ("AB=40.5..60mm:3", 0.0405, 0.06), ("omega=1.5..2rad/s:3", 1.5, 2.0),
    ("AB=40..60.5mm:3", 0.04, 0.0605), ("AB=.05..0.06 m:2", 0.05, 0.06)])
def test_a_vary_range_takes_decimal_ends(spec, first, last):
    from polygons.cli._vary import parse_vary
    name, values = parse_vary(spec, polygons.load(FOUR_BAR))
    assert len(values) == int(spec.rsplit(":", 1)[1])
    assert values[0] == pytest.approx(first, rel=1e-12)
    assert values[-1] == pytest.approx(last, rel=1e-12)


# ---------------------------------------------------------------- P: the --cycle budget
def test_a_turning_moment_diagram_above_the_budget_is_refused_before_work():
    line = refused(*run("forces", DATA / "truss-100-links-masses.toml", "--cycle", 3600),
                   "[--cycle]", "--long", "budget")
    most = int(re.search(r"--cycle (\d+) or less", line).group(1))
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import CYCLE_BUDGET, MAX_CYCLE, cycle_work
    model = load_model(polygons.load(DATA / "truss-100-links-masses.toml"))
    assert cycle_work(model, most) <= CYCLE_BUDGET < cycle_work(model, most + 1)
    four_bar = load_model(polygons.load(CASES / "forces-toggle-press.toml"))
    assert cycle_work(four_bar, MAX_CYCLE) <= CYCLE_BUDGET      # small scenes: the whole range


# ---------------------------------------------------------------- item 5: --students
def test_a_class_list_that_is_a_fifo_or_a_folder_says_what_it_is(tmp_path):
    fifo = tmp_path / "class.csv"
    os.mkfifo(fifo)
    folder = tmp_path / "folder"
    folder.mkdir()
    for path, words in ((fifo, "FIFO"), (folder, "directory"), (tmp_path / "no.csv", "no such")):
        refused(*run("exam", CASES / "efficiency-four-bar.toml", "--variants", 2,
                     "--students", path, "--out", tmp_path / "out"), words)
