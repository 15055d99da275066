"""The shortcuts load_scene takes are exact: each is compared with the long way round.

* polygons.loads.parse: a scene without force tables skips reading them (the defaults);
* polygons.options.parse_options: a scene without option tables shares the default options;
* the frozen records built at once (Scene, Answer) carry every field their class declares;
* polygons.units.parse_quantity remembers accepted texts, never refusals.
"""
from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from polygons import loads as loads_mod
from polygons.errors import UnitError
from polygons.options import DEFAULT, parse_options
from polygons.reader import Reader
from polygons.scene import Answer, Scene, answer_fields, drawing_tolerance, load_scene
from polygons.units import _parse_quantity, parse_quantity

CASES = sorted((Path(__file__).parent.parent / "cases").glob("*.toml"))


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_loads_shortcut_matches_reading_every_table(path):
    scene = load_scene(path)
    r = Reader(scene.file)
    long_way = loads_mod.parse(scene, lambda spec, where, **kw: answer_fields(
        spec, r, where, drawing_tolerance(scene.source, r), **kw), shortcut=False)
    if not any(k in scene.extra for k in loads_mod.READS):
        assert not scene.loads.active
    assert scene.loads == long_way


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_records_carry_every_field(path):
    scene = load_scene(path)
    names = {f.name for f in dataclasses.fields(Scene)}
    assert set(vars(scene)) == names
    answer_names = {f.name for f in dataclasses.fields(Answer)}
    for a in scene.answers:
        assert set(vars(a)) == answer_names
        # the same record the dataclass's own __init__ builds
        assert a == Answer(**{n: getattr(a, n) for n in answer_names})
        with pytest.raises(dataclasses.FrozenInstanceError):
            a.unit = "mm"
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.title = "x"
    # the same record the dataclass's own __init__ builds
    assert scene == Scene(**{n: getattr(scene, n) for n in names})


@pytest.mark.parametrize("text, dim, reduce", [
    ("50 mm", "length", False), ("370 deg", "angle", True), ("370 deg", "angle", False),
    ("2000 rev/min", "angular_velocity", False), ("3 %", "fraction", False),
    ("1e-3 km", "length", False)])
def test_remembered_quantity_is_the_one_computed(text, dim, reduce):
    fresh = _parse_quantity(text, dim, None, None, reduce)
    assert parse_quantity(text, dim, reduce=reduce) == fresh      # first call: computed
    assert parse_quantity(text, dim, reduce=reduce) == fresh      # then remembered
    assert parse_quantity(text, dim, reduce=reduce) is parse_quantity(text, dim, reduce=reduce)


def test_refusals_are_not_remembered():
    for where in ("links.AB", "links.BC"):
        with pytest.raises(UnitError) as exc:
            parse_quantity("50 kg", "length", file="f.toml", where=where)
        assert exc.value.where == where
    # a text accepted for one dimension is still refused for another
    assert parse_quantity("50 mm", "length") == pytest.approx(0.05)
    with pytest.raises(UnitError):
        parse_quantity("50 mm", "angle")
    for _ in range(2):          # out of range, asked twice: refused twice
        with pytest.raises(UnitError, match="out of range"):
            parse_quantity("2e6 deg", "angle", reduce=True)


def test_default_options_are_those_read_from_empty_tables():
    assert parse_options({}, "f.toml") is DEFAULT
    long_way = parse_options({"sweep": {}, "diagram": {}, "handout": {}}, "f.toml")
    assert long_way is not DEFAULT and long_way == DEFAULT


def test_memo_starts_afresh_when_full():
    from polygons import units
    for i in range(units._MEMO_SIZE + 10):
        parse_quantity(f"{i} mm", "length")
    assert 0 < len(units._PARSED) <= units._MEMO_SIZE
    assert parse_quantity("12345 mm", "length") is parse_quantity("12345 mm", "length")


def _built_as_init_builds(rec):
    """``rec`` carries every field of its class and equals the record __init__ builds."""
    names = {f.name for f in dataclasses.fields(rec)}
    assert set(vars(rec)) == names, type(rec).__name__
    assert rec == type(rec)(**{n: getattr(rec, n) for n in names})
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(rec, next(iter(names)), None)


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_every_record_set_at_once_is_whole(path):
    """Links, the driver, the assembly's branches, the loads and their bodies and joints."""
    scene = load_scene(path)
    for rec in (*scene.links.values(), scene.driver, *scene.assembly.values(), scene.loads,
                *scene.loads.bodies.values(), *scene.loads.joints):
        _built_as_init_builds(rec)
