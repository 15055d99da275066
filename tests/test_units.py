"""Units against pint, the imperial textbook case, ``solve --units``, and the scene-file
reference / JSON Schema held to the loader's own tables."""
from __future__ import annotations

import json
import math
import re
import tomllib

import numpy as np
import pytest

import analytic
from conftest import CASES, ROOT, case_files

from polygons import reference as schema
from polygons.errors import UnitError
from polygons.evaluate import solve
from polygons.report import check_answers, table
from polygons.scene import load_scene, parse_scene
from polygons.units import LIMITS, SI_UNIT, SPELLINGS, SYSTEMS, UNITS, parse_quantity

pint = pytest.importorskip("pint")
UREG = pint.UnitRegistry()

#: our spelling -> pint's, where they differ
PINT_NAME = {"°": "degree", "µm": "micrometer", "um": "micrometer", "rev": "revolution",
             "rpm": "revolution/minute", "%": "percent", "in": "inch", "t": "metric_ton",
             "mph": "mile/hour", "Nm": "N*m", "deg": "degree"}
PINT_SI = {"length": "m", "angle": "radian", "angular_velocity": "radian/s",
           "angular_acceleration": "radian/s**2", "velocity": "m/s", "acceleration": "m/s**2",
           "mass": "kg", "force": "N", "torque": "N*m", "pressure": "Pa",
           "inertia": "kg*m**2", "stiffness": "N/m", "torsional_stiffness": "N*m/radian",
           "time": "s", "fraction": "dimensionless", "energy": "J", "power": "W",
           "angular_momentum": "kg*m**2/s"}


def pint_expr(unit: str) -> str:
    if unit in PINT_NAME:
        return PINT_NAME[unit]
    text = unit.replace("²", "^2").replace("·", " ").replace("*", " ").replace("^", "**")
    tokens = re.split(r"(\s+|/|\*\*\d)", text)
    out = []
    for tok in tokens:
        out.append(PINT_NAME.get(tok, tok) if tok not in ("in", "rev") else
                   {"in": "inch", "rev": "revolution"}[tok])
    return re.sub(r"\s+", "*", "".join(out).strip())


@pytest.mark.parametrize("unit", sorted(UNITS), ids=lambda u: u.replace("/", "_per_"))
def test_every_unit_factor_agrees_with_pint(unit):
    dimension, factor = UNITS[unit]
    expected = UREG.Quantity(1.0, pint_expr(unit)).to(PINT_SI[dimension]).magnitude
    assert factor == pytest.approx(expected, rel=1e-12), (unit, pint_expr(unit))


@pytest.mark.parametrize("spelling", sorted(SPELLINGS))
def test_every_textbook_spelling_means_a_unit_of_the_table(spelling):
    """'120 r.p.m.', '2 rad/sec', '30 degrees', '5 inches': read as the canonical spelling
    they name, whose factor the pint test above checks."""
    unit = SPELLINGS[spelling]
    assert unit in UNITS and spelling not in UNITS
    dimension, factor = UNITS[unit]
    assert parse_quantity(f"3 {spelling}", dimension) == pytest.approx(3 * factor, rel=1e-15)


@pytest.mark.parametrize("unit", ["in", "ft", "ft/s", "ft/s^2", "ft/s²", "lbf", "lb", "slug",
                                  "psi", "bar", "N/mm^2", "kN/m^2", "deg/s", "rev/s"])
def test_the_issue_units_are_accepted(unit):
    assert unit in UNITS
    assert parse_quantity(f"2 {unit}", UNITS[unit][0]) == pytest.approx(2 * UNITS[unit][1])


def test_every_dimension_has_limits_and_an_si_unit():
    dims = {d for d, _ in UNITS.values()}
    assert dims <= set(LIMITS) and dims <= set(SI_UNIT)


def test_report_systems_use_known_units():
    for system in SYSTEMS.values():
        for dim, unit in system.items():
            assert UNITS[unit][0] == dim


# ------------------------------------------------------------------ the imperial case
IMPERIAL = CASES / "bj-engine-imperial.toml"
IN, FT = 0.0254, 0.3048


def test_imperial_case_exact_answers_are_the_closed_form():
    """Every `exact` of the imperial case recomputed from tests/analytic.py (not the solver)."""
    w = -2000 * 2 * math.pi / 60
    ref = analytic.slider_crank((0, 0), 3 * IN, 8 * IN, math.radians(40), w, 0.0, (0, 0), 0.0,
                                +1)
    closed = {"omega(BD)": ref["omega_AB"], "v(D)": abs(ref["s_dot"]) / FT,
              "v(B)": float(np.hypot(*ref["vA"])) / FT, "alpha(BD)": ref["alpha_AB"],
              "a(D)": abs(ref["s_ddot"]) / FT}
    scene = load_scene(IMPERIAL)
    assert {a.quantity for a in scene.answers} == set(closed)
    for a in scene.answers:
        assert a.exact == pytest.approx(closed[a.quantity], rel=1e-12), a.quantity


def test_imperial_case_solves_to_the_exact_and_printed_answers():
    sol = solve(load_scene(IMPERIAL))
    checks = check_answers(sol)
    assert len(checks) == 5
    for c in checks:
        assert c.exact_rel is not None and c.exact_rel < 1e-9, c.answer.quantity
        assert c.within, (c.answer.quantity, c.compared, c.answer.tutorial)


def test_solve_units_imperial_table():
    sol = solve(load_scene(IMPERIAL))
    text = table(sol, steps=False, units="imperial")
    row = next(l for l in text.splitlines() if l.startswith("D "))
    assert "x in" in text and "|v| ft/s" in text and "|a| ft/s²" in text
    x, y, v = (float(t) for t in row.split()[1:4])
    assert x == pytest.approx(10.0622, abs=1e-4) and v == pytest.approx(43.6184, abs=1e-4)
    si = table(sol, steps=False, units="si")
    row = next(l for l in si.splitlines() if l.startswith("D "))
    assert float(row.split()[1]) == pytest.approx(10.0622 * IN, abs=1e-4)
    assert float(row.split()[3]) == pytest.approx(43.6184 * FT, rel=1e-5)


def test_solve_units_flag_through_the_cli(capsys):
    from polygons.cli import main
    assert main(["solve", str(IMPERIAL), "--units", "imperial", "--no-steps"]) == 0
    out = capsys.readouterr().out
    assert "ft/s" in out and "43.6184" in out


# ------------------------------------------------------------------ reference and schema
def test_generated_reference_and_schema_are_up_to_date():
    """docs/scene-reference.md and polygons/scene.schema.json are what the tables generate
    (run `python -m polygons.reference` after changing a table)."""
    for rel, text in schema.generated().items():
        path = ROOT / rel
        assert path.exists(), f"{rel} missing: run python -m polygons.reference"
        assert path.read_text(encoding="utf-8") == text, f"{rel} is stale: run python -m " \
                                                         f"polygons.reference"


def _documented() -> dict[str, set[str]]:
    out: dict[str, set[str]] = {}
    for _, t in schema.collect():
        out.setdefault(t.name, set()).update(k.name for k in t.keys)
    return out


def _keys_in(data: dict) -> set[tuple[str, str]]:
    """(table, key) for every key a scene uses; entries of label/link tables as '<...>'."""
    docs = _documented()
    used = set()
    for top, value in data.items():
        if top not in docs or not top:
            used.add(("", top))          # a top-level key, or a table nobody declares
            continue
        names = docs[top]
        items = value if isinstance(value, list) else [value]
        for item in items:
            for key, sub in item.items():
                if any(n.startswith("<") for n in names):
                    used.add((top, next(n for n in names if n.startswith("<"))))
                elif isinstance(sub, dict) and key not in names:     # [sliders.C] ...
                    used |= {(top, k) for k in sub}
                else:
                    used.add((top, key))
    return used


@pytest.mark.parametrize("path", case_files(), ids=lambda p: p.stem)
def test_every_key_of_every_case_is_in_the_reference(path):
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    docs = _documented()
    reference = (ROOT / schema.REFERENCE).read_text(encoding="utf-8")
    from polygons.scene import EXTENSION_KEYS
    for table_name, key in _keys_in(data):
        if table_name == "" and key in EXTENSION_KEYS and key not in docs:
            continue          # a force table whose module does not declare TABLES yet
        assert key in docs.get(table_name, set()) or (table_name == "" and key in docs), \
            (table_name, key)
        assert f"`{key}`" in reference or f"[{key}" in reference, (table_name, key)


def _refuses(data: dict, where: str):
    with pytest.raises(Exception) as info:
        parse_scene(data, file="t.toml")
    assert where in str(info.value), str(info.value)


def test_the_loader_accepts_exactly_the_declared_keys():
    """A key added to a table is refused ('unknown key'); each declared key is accepted."""
    base = tomllib.loads((CASES / "s003-fig7.toml").read_text(encoding="utf-8"))
    for _, t in schema.collect():
        if not t.name or t.name not in {"source", "driver", "sliders", "slots", "points",
                                        "answers", "sweep", "diagram", "handout"}:
            continue
        data = json.loads(json.dumps(base))
        bogus = {"zz_not_a_key": 1}
        if t.array:
            data[t.name] = [dict(bogus)]
        elif t.many:
            data[t.name] = {"Q": dict(bogus)}
        else:
            data[t.name] = dict(data.get(t.name, {})) | bogus
        with pytest.raises(Exception, match="zz_not_a_key"):
            parse_scene(data, file="t.toml")
    from polygons.scene_tables import KEYS
    from polygons.options import TABLES as OPTION_TABLES
    declared = {t.name: {k.name for k in t.keys} for _, t in schema.collect()}
    for name, keys in KEYS.items():
        assert set(keys) == declared[name]
    assert {t.name for t in OPTION_TABLES} <= set(declared)


def _validate(instance, sch, path="$"):
    """A small JSON Schema validator: the keywords polygons/scene.schema.json uses."""
    if "anyOf" in sch:
        errors = []
        for option in sch["anyOf"]:
            try:
                _validate(instance, option, path)
                break
            except AssertionError as exc:
                errors.append(str(exc))
        else:
            raise AssertionError(f"{path}: no alternative matches: {errors}")
    if "const" in sch:
        assert instance == sch["const"], path
    kind = sch.get("type")
    types = {"object": dict, "array": list, "string": str, "boolean": bool, "integer": int,
             "number": (int, float)}
    if kind:
        assert isinstance(instance, types[kind]) and not (
            kind in ("integer", "number") and isinstance(instance, bool)), (path, kind)
    if kind == "string" and "pattern" in sch:
        assert re.search(sch["pattern"], instance), (path, instance, sch["pattern"])
    if kind == "array":
        assert len(instance) >= sch.get("minItems", 0), path
        assert len(instance) <= sch.get("maxItems", 10 ** 9), path
        for i, item in enumerate(instance):
            if "items" in sch:
                _validate(item, sch["items"], f"{path}[{i}]")
    if kind == "object":
        for req in sch.get("required", ()):
            assert req in instance, f"{path}: missing {req}"
        for key, value in instance.items():
            if key in sch.get("properties", {}):
                _validate(value, sch["properties"][key], f"{path}.{key}")
                continue
            pats = [p for p in sch.get("patternProperties", {}) if re.search(p, key)]
            if pats:
                _validate(value, sch["patternProperties"][pats[0]], f"{path}.{key}")
                continue
            assert sch.get("additionalProperties", True) is not False, f"{path}: extra {key}"


@pytest.mark.parametrize("path", case_files(), ids=lambda p: p.stem)
def test_every_case_validates_against_the_json_schema(path):
    sch = json.loads((ROOT / schema.JSON_SCHEMA).read_text(encoding="utf-8"))
    _validate(tomllib.loads(path.read_text(encoding="utf-8")), sch)


def test_the_json_schema_rejects_typos_and_missing_units():
    sch = json.loads((ROOT / schema.JSON_SCHEMA).read_text(encoding="utf-8"))
    base = tomllib.loads((CASES / "s001-we4.toml").read_text(encoding="utf-8"))
    for bad in ({"driver": base["driver"] | {"omgea": "1 rad/s"}},
                {"links": base["links"] | {"AB": "50"}},
                {"ground": {"A": ["0 mm"]}}):
        with pytest.raises(AssertionError):
            _validate(base | bad, sch)


def test_the_json_schema_accepts_what_the_loader_accepts_of_book_wording():
    """Spellings books print and a sense written after a rate: the loader and the schema
    agree (a scene the loader reads validates)."""
    sch = json.loads((ROOT / schema.JSON_SCHEMA).read_text(encoding="utf-8"))
    base = tomllib.loads((CASES / "s001-we4.toml").read_text(encoding="utf-8"))
    drv = {k: v for k, v in base["driver"].items() if k != "sense"}
    data = base | {"driver": drv | {"omega": "2865 r.p.m. clockwise"},
                   "links": base["links"] | {"AB": "5 cm"}}
    _validate(data, sch)
    assert parse_scene(data, file="x").driver.omega == pytest.approx(-2865 * 2 * math.pi / 60)


def test_the_json_schema_ships_with_the_package():
    import importlib.resources
    text = importlib.resources.files("polygons").joinpath("scene.schema.json").read_text(
        encoding="utf-8")
    assert json.loads(text)["title"] == "polygons scene file"
    assert "scene.schema.json" in (ROOT / "pyproject.toml").read_text(encoding="utf-8")


def test_ci_runs_exactly_the_readme_test_command_in_a_fresh_venv():
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").strip().splitlines()[-1]
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert ci.startswith("rm -rf .venv && python3 -m venv .venv")
    assert f"    {ci}\n" in readme


def test_unit_errors_name_the_key(tmp_path):
    text = (CASES / "bj-engine-imperial.toml").read_text(encoding="utf-8")
    p = tmp_path / "x.toml"
    p.write_text(text.replace('BD = "8 in"', 'BD = "8 furlong"'), encoding="utf-8")
    with pytest.raises(UnitError, match=r"\[links\.BD\].*unknown unit 'furlong'"):
        load_scene(p)
