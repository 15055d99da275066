"""The generated scene reference: every example it prints is TOML that the format accepts."""
import re
import tomllib
from pathlib import Path

import pytest

from polygons.reference import REFERENCE, _key_schema, collect, example_line, markdown

ROOT = Path(__file__).resolve().parents[1]


def _valid(value, schema) -> bool:
    """``value`` against the subset of JSON Schema the reference writes."""
    if "const" in schema and value != schema["const"]:
        return False
    if "anyOf" in schema and not any(_valid(value, s) for s in schema["anyOf"]):
        return False
    kind = schema.get("type")
    types = {"string": str, "array": list, "object": dict, "boolean": bool}
    if kind in types and not isinstance(value, types[kind]):
        return False
    if kind in ("number", "integer") and (isinstance(value, bool) or not isinstance(
            value, int if kind == "integer" else (int, float))):
        return False
    if isinstance(value, str) and "pattern" in schema \
            and not re.search(schema["pattern"], value):
        return False
    if isinstance(value, list):
        if not schema.get("minItems", 0) <= len(value) <= schema.get("maxItems", len(value)):
            return False
        if "items" in schema and not all(_valid(v, schema["items"]) for v in value):
            return False
    if isinstance(value, dict):
        props = schema.get("properties", {})
        if any(r not in value for r in schema.get("required", ())):
            return False
        if schema.get("additionalProperties") is False and set(value) - set(props):
            return False
        if not all(_valid(v, props[k]) for k, v in value.items() if k in props):
            return False
    return True


def test_the_validator_can_fail():
    schema = _key_schema(next(k for _, t in collect() for k in t.keys
                              if k.type == "quantity" and k.dimension == "length"))
    assert _valid("300 mm", schema)
    assert not _valid("300", schema) and not _valid(300, schema) and not _valid("C", schema)


KEYS = [(t.name or "top", k) for _, t in collect() for k in t.keys if k.example]


@pytest.mark.parametrize("table,key", KEYS, ids=[f"{t}.{k.name}" for t, k in KEYS])
def test_every_example_is_toml_the_format_accepts(table, key):
    line = example_line(key)
    value = tomllib.loads(line)           # raises if not TOML
    (name, v), = value.items()
    assert _valid(v, _key_schema(key)), f"[{table}] {line} does not fit {key.type}"


def test_the_printed_reference_examples_parse():
    """Each example as printed in docs/scene-reference.md (the generated text), copied out of
    its table, parses as TOML."""
    text = markdown(collect())
    assert text == (ROOT / REFERENCE).read_text(encoding="utf-8")
    rows = [ln for ln in text.splitlines() if ln.startswith("| `")]
    examples = []
    for row in rows:
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", row)[1:-1]]
        if cells[4]:
            examples.append(cells[4].strip("`").replace("\\|", "|"))
    assert len(examples) == len(KEYS)
    for ex in examples:
        tomllib.loads(ex)
