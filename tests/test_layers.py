"""The design's layers, checked on the import graph read from the source (tests/imports.py):

    base → scene → plan → interpreters → forces → render → commands

each module imports only its own layer or lower ones (lazy imports inside functions included);
the solver core never imports ``diagrams``; one module each imports shapely, svgwrite and
matplotlib; no import cycle; no module over 800 lines.
"""
import pytest

from imports import graph, imports, module_files, nodes

LAYERS = ("base", "scene", "plan", "interpreters", "forces", "render", "commands")

#: module (or package prefix) → layer; the longest matching prefix wins
WHERE = {
    "polygons.errors": "base", "polygons.units": "base", "polygons.schema": "base",
    "polygons.theorems": "base", "polygons.steps": "base", "polygons.memo": "base", "polygons.notation": "base",
    "polygons.program": "base", "polygons.calculus": "base",
    "polygons.scene": "scene", "polygons.quantity_grammar": "scene", "polygons.records": "scene", "polygons.loads": "scene", "polygons.quantities": "interpreters",
    "polygons.options": "scene", "polygons.contacts": "scene", "polygons.wheels": "scene", "polygons.higher": "scene", "polygons.pins": "scene", "polygons.topology": "scene", "polygons.senses": "scene",
    "polygons.exam_table": "scene", "polygons.drawing_format": "scene",
    "polygons.question_table": "scene", "polygons.cam_profiles": "scene", "polygons.cam_events": "scene", "polygons.cam_profile_table": "scene",
    "polygons.cam_diagram": "interpreters", "polygons.conditions": "forces",
    "polygons.grade_drawing": "interpreters", "polygons.exam": "commands",
    "polygons.scene_tables": "scene", "polygons.loadmodel": "scene", "polygons.loadbodies": "scene",
    "polygons.reader": "scene",
    "polygons.loadeffort": "scene", "polygons.loadtables": "scene", "polygons.loadrun": "scene",
    # the mechanism model: the joint tables read once into bodies and pairs, the last step of
    # loading a scene (polygons.scene builds it; every layer above reads it)
    "polygons.model": "scene",
    "polygons.reference": "commands", "polygons.__main__": "commands",
    "polygons.notation_doc": "commands",
    "polygons.plan": "plan", "polygons.dyads": "plan", "polygons.mobility": "plan",
    "polygons.geometry": "interpreters", "polygons.geos_crossing": "interpreters",
    "polygons.narrate": "interpreters", "polygons.position": "interpreters",
    "polygons.evaluate": "interpreters", "polygons.sweep": "interpreters",
    "polygons.harmonic": "interpreters",
    "polygons.sweep_store": "interpreters", "polygons.sweep_follow": "interpreters",
    "polygons.sweep_range": "interpreters", "polygons.sweep_extremes": "interpreters",
    "polygons.drawing_board": "interpreters", "polygons.compiled": "interpreters",
    "polygons.codegen": "interpreters", "polygons.codegen_lean": "interpreters",
    "polygons.jit": "interpreters",
    "polygons.fused": "interpreters",
    "polygons.batch": "interpreters", "polygons.centres": "interpreters",
    "polygons.centres_links": "interpreters", "polygons.centres_velocity": "interpreters",
    "polygons.classic": "interpreters",
    "polygons.kennedy": "interpreters",
    "polygons.streams": "interpreters",
    "polygons.forces": "forces",
    "polygons.report": "render", "polygons.csv_text": "render",
    "polygons.csv_jit": "render", "polygons.csv_format": "render", "diagrams": "render",
    "polygons.cli": "commands", "polygons.api": "commands", "polygons": "commands",
}


# the exam's variants and their keys: a library below the commands (polygons.cli.exam), so
# that an import of a command from it is a back arrow; the grading tolerances it shares with
# `polygons check`, below both
WHERE.update({"polygons.exam": "render", "polygons.tolerances": "interpreters"})


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


#: the modules (the import graph's keys); the graph itself is read on first use, once per test
#: process (tests/imports.py), not at collection in every worker
MODULES = sorted(module_files())


def test_every_module_has_a_layer():
    assert [m for m in MODULES if layer_of(m) is None] == []


@pytest.mark.parametrize("mod", MODULES)
def test_imports_go_downward_only(mod):
    mine = LAYERS.index(layer_of(mod))
    GRAPH = graph()
    up = sorted(n for n in GRAPH[mod] if n in GRAPH and n != "polygons"
                and LAYERS.index(layer_of(n)) > mine)
    assert up == [], f"{mod} ({layer_of(mod)}) imports higher layers: {up}"


def test_only_the_entry_points_import_the_command_line():
    """polygons.cli is the top: a library module (the exam's variants, once) reaching up into
    a command for a helper is a back arrow.  polygons.api sits beside it (commands) and reads
    the forces' JSON of `polygons forces --json` from it."""
    GRAPH = graph()
    users = sorted(m for m in MODULES if not m.startswith("polygons.cli")
                   and any(n == "polygons.cli" or n.startswith("polygons.cli.")
                           for n in GRAPH[m]))
    assert users == ["polygons.__main__", "polygons.api"]


def test_the_solver_core_never_imports_diagrams():
    GRAPH = graph()
    bad = {m: sorted(n for n in GRAPH[m] if n.split(".")[0] == "diagrams")
           for m in MODULES if m.startswith("polygons") and not m.startswith("polygons.cli")
           and m not in ("polygons.api",)}
    assert {m: v for m, v in bad.items() if v} == {}


@pytest.mark.parametrize("lib,owner", [("shapely", "polygons.geometry"),
                                       ("svgwrite", "diagrams.svg"),
                                       ("matplotlib", "diagrams.plots")])
def test_one_module_imports_each_heavy_library(lib, owner):
    GRAPH = graph()
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


# ---------------------------------------------------------------- groups own their methods
def _group_kinds() -> set[str]:
    from polygons import dyads
    return {n for n in dyads.__all__ if isinstance(getattr(dyads, n), type)}


def test_no_isinstance_on_a_group_kind_outside_the_groups():
    """What differs by kind is the group's own (a method, or a name it gives a table):
    nobody outside polygons/dyads/ asks a group what class it is."""
    import ast
    kinds = _group_kinds()
    found = []
    for mod, path in module_files().items():
        if mod.startswith("polygons.dyads"):
            continue
        for node in nodes(path):
            if (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "isinstance"
                    and len(node.args) == 2):
                names = {getattr(n, "id", None) or getattr(n, "attr", None)
                         for n in ast.walk(node.args[1])}
                if names & kinds:
                    found.append(f"{mod}:{node.lineno}")
    assert found == []


def test_each_group_names_a_force_polygon_the_construction_has():
    """A group kind's ``force_polygon`` is a key of forces.graphical.POLYGONS (or None: no
    body of its own); a kind without one is refused by construction."""
    from polygons import dyads
    from polygons.forces.graphical import POLYGONS
    named = {n: getattr(getattr(dyads, n), "force_polygon", "—") for n in _group_kinds()}
    assert {n: k for n, k in named.items() if k not in POLYGONS and k not in (None, "—")} == {}
    assert set(POLYGONS) == {k for k in named.values() if k not in (None, "—")}


# ---------------------------------------------------------------- one reader of the joint tables
#: the scene's joint tables ([links], [sliders], [slots], [points], [crossing], [driver.slide])
JOINT_TABLES = {"links", "sliders", "slots", "points", "crossing", "prescribed"}
#: who still reads them outside the groups and the model, and why: the planner's topology
#: (the groups' own helpers), mobility (a redundant link's stated length, varied by a batch)
#: and the batch (it writes varied tables); the exam's data table and the sweep's range of a
#: slider driver read the model (issue 34's goal: at most four)
TABLE_READERS = {"polygons.topology", "polygons.mobility", "polygons.batch"}
MAX_TABLE_READERS = 3


def _joint_table_readers() -> set[str]:
    import ast
    out = set()
    for mod, path in module_files().items():
        if mod.startswith("polygons.dyads") or mod == "polygons.model":
            continue
        for node in nodes(path):
            if isinstance(node, ast.Attribute) and node.attr in JOINT_TABLES:
                v = node.value
                if getattr(v, "id", None) == "scene" or getattr(v, "attr", None) == "scene":
                    out.add(mod)
    return out


def test_only_the_model_and_the_groups_read_the_joint_tables():
    """Everything else reads the mechanism model (polygons.model): at most four modules
    outside polygons/dyads/ read scene.links, scene.sliders, scene.slots... directly."""
    readers = _joint_table_readers()
    assert readers <= TABLE_READERS and len(readers) <= MAX_TABLE_READERS, sorted(readers)
