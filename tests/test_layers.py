"""The design's layers, checked on the import graph read from the source (tests/imports.py):

    base → scene → plan → interpreters → forces → render → commands

each module imports only its own layer or lower ones (lazy imports inside functions included);
the solver core never imports ``diagrams``; one module each imports shapely, svgwrite and
matplotlib; no import cycle; no module over 800 lines.
"""
import pytest

from imports import imports, module_files

LAYERS = ("base", "scene", "plan", "interpreters", "forces", "render", "commands")

#: module (or package prefix) → layer; the longest matching prefix wins
WHERE = {
    "polygons.errors": "base", "polygons.units": "base", "polygons.schema": "base",
    "polygons.theorems": "base", "polygons.steps": "base", "polygons.memo": "base", "polygons.notation": "base",
    "polygons.scene": "scene", "polygons.records": "scene", "polygons.loads": "scene", "polygons.quantities": "interpreters",
    "polygons.options": "scene", "polygons.contacts": "scene", "polygons.wheels": "scene", "polygons.pins": "scene", "polygons.topology": "scene",
    "polygons.exam_table": "scene", "polygons.drawing_format": "scene",
    "polygons.grade_drawing": "interpreters", "polygons.exam": "commands",
    "polygons.scene_tables": "scene", "polygons.loadmodel": "scene", "polygons.reader": "scene",
    "polygons.loadeffort": "scene",
    # the mechanism model: the joint tables read once into bodies and pairs, the last step of
    # loading a scene (polygons.scene builds it; every layer above reads it)
    "polygons.model": "scene",
    "polygons.reference": "commands", "polygons.__main__": "commands",
    "polygons.notation_doc": "commands",
    "polygons.plan": "plan", "polygons.dyads": "plan", "polygons.mobility": "plan",
    "polygons.geometry": "interpreters",
    "polygons.narrate": "interpreters", "polygons.position": "interpreters",
    "polygons.evaluate": "interpreters", "polygons.sweep": "interpreters",
    "polygons.sweep_store": "interpreters",
    "polygons.drawing_board": "interpreters", "polygons.compiled": "interpreters",
    "polygons.codegen": "interpreters", "polygons.jit": "interpreters",
    "polygons.batch": "interpreters", "polygons.centres": "interpreters",
    "polygons.classic": "interpreters",
    "polygons.kennedy": "interpreters",
    "polygons.streams": "interpreters",
    "polygons.forces": "forces",
    "polygons.report": "render", "polygons.csv_text": "render", "diagrams": "render",
    "polygons.cli": "commands", "polygons.api": "commands", "polygons": "commands",
}


#: entries that stand for the package module itself, not for everything below it
PACKAGES_ONLY = ("polygons",)


def layer_of(mod: str) -> str | None:
    best = None
    for prefix in WHERE:
        if prefix in PACKAGES_ONLY and mod != prefix:
            continue
        if (mod == prefix or mod.startswith(prefix + ".")) and (best is None
                                                                 or len(prefix) > len(best)):
            best = prefix
    return WHERE[best] if best else None


GRAPH = imports()
MODULES = sorted(GRAPH)


def test_every_module_has_a_layer():
    assert [m for m in MODULES if layer_of(m) is None] == []


@pytest.mark.parametrize("mod", MODULES)
def test_imports_go_downward_only(mod):
    mine = LAYERS.index(layer_of(mod))
    up = sorted(n for n in GRAPH[mod] if n in GRAPH and n != "polygons"
                and LAYERS.index(layer_of(n)) > mine)
    assert up == [], f"{mod} ({layer_of(mod)}) imports higher layers: {up}"


def test_the_solver_core_never_imports_diagrams():
    bad = {m: sorted(n for n in GRAPH[m] if n.split(".")[0] == "diagrams")
           for m in MODULES if m.startswith("polygons") and not m.startswith("polygons.cli")
           and m not in ("polygons.api",)}
    assert {m: v for m, v in bad.items() if v} == {}


@pytest.mark.parametrize("lib,owner", [("shapely", "polygons.geometry"),
                                       ("svgwrite", "diagrams.svg"),
                                       ("matplotlib", "diagrams.plots")])
def test_one_module_imports_each_heavy_library(lib, owner):
    users = sorted(m for m in MODULES if any(n.split(".")[0] == lib for n in GRAPH[m]))
    assert users == [owner]


def test_no_import_cycle():
    top = imports()          # lazy imports inside functions included
    state: dict[str, int] = {}
    path: list[str] = []

    def visit(m):
        state[m] = 1
        path.append(m)
        for n in sorted(top[m]):
            if n not in top or n == m:
                continue
            if state.get(n) == 1:
                raise AssertionError("import cycle: " + " → ".join(path[path.index(n):] + [n]))
            if n not in state:
                visit(n)
        path.pop()
        state[m] = 2

    for m in MODULES:
        if m not in state:
            visit(m)


@pytest.mark.parametrize("mod,path", sorted(module_files().items()))
def test_no_module_over_800_lines(mod, path):
    n = len(path.read_text(encoding="utf-8").splitlines())
    assert n <= 800, f"{mod}: {n} lines"
