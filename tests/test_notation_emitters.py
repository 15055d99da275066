"""One notation across every emitter, for every group kind (issue 33): the drawings, the
narration (``polygons solve``), the handout, the grader's rows and hints (``polygons check``)
and the exam's symbols name each vertex, vector and quantity alike.

Each kind is taken from the case the notation table (docs/notation.md) shows it with
(``notation_doc._kinds``).  The names are read from the typed records — the steps' ``end``,
``quantity`` and ``reason``, the grader's rules, the drawings' Text items, the exam's
``symbol`` — and looked up in what the others print; nothing is parsed back out of text.
"""
import pytest

import diagrams
from diagrams.model import Text
from diagrams.notation import plain
from polygons import notation_doc
from polygons.exam.variants import symbol
from polygons.grade_drawing import rules
from polygons.notation import quantity as table_quantity, vertex
from polygons.report import table

KINDS = {k: (path, sol) for k, path, _, sol in notation_doc._kinds()}
#: the handout (the costliest emitter, ~0.3 s a case) on the kinds with numbered and dashed
#: vertices and vectors named from a fixed centre: c₁/c₂ and dc₂ (RRR), the Coriolis foot a′
#: and a₁′ (RPR), p′ and o₂p₁ (Guided)
HANDOUT_KINDS = ("RRR", "RPR", "Guided")


def _made(sol):
    """The steps that make a vertex (vectors, images, intersections)."""
    return [st for st in sol.steps if st.kind in ("vector", "image", "intersection") and st.end]


def test_every_group_kind_is_checked():
    assert {"CrankDyad", "RRR", "RRP", "RPR", "Guided", "Crossing", "Image", "Triad",
            "TriadSlider", "SlideDyad", "SliderDriveDyad", "SlotSlider", "WheelPin",
            "RPP"} <= set(KINDS)


@pytest.fixture(scope="module")
def emitted():
    """Per kind: the drawings' texts (Unicode), the narration, the grader's rules."""
    out = {}
    for kind, (path, sol) in KINDS.items():
        texts = {plain(t.text) for d in diagrams.drawings(sol, None, None, False)
                 for t in d.items() if isinstance(t, Text)}
        # the narration: the construction's lines of the solve table (its answers' rows
        # quote the case file's own words)
        rest = set(table(sol, steps=False).splitlines())
        narration = "\n".join(x for x in table(sol).splitlines() if x not in rest)
        out[kind] = (sol, texts, narration,
                     {dg: rules(sol, dg) for dg in sol.scene.solve})
    return out


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_a_vertex_is_spelled_one_way_everywhere(kind, emitted):
    """Every vertex a step makes is printed as notation.vertex spells it (p₄′, c₁) by the
    drawing, the narration and the grader; its source form ('p2_1', 'c1') is printed by
    none of them."""
    sol, texts, narration, rs = emitted[kind]
    hints = " ".join(e["where"] + " " + e["rule"] for r in rs.values() for e in r["expected"])
    for st in _made(sol):
        name, shown = st.end, vertex(st.end)
        assert any(shown == t or shown in t.split(" = ") for t in texts), (kind, name)
        if name != shown:                      # a numbered or dashed vertex
            for where, text in (("narration", narration), ("grader", hints)):
                assert f" {name} " not in f" {text} ".replace(".", " ").replace(",", " "), \
                    (kind, where, name)
        if name in st.reason:                  # the sentence names it: so does the narration
            assert shown in narration, (kind, st.number, name)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_the_grader_names_each_vector_as_the_legend_does(kind, emitted):
    """The grader's row for each vector (its ``shown`` name: dc₂ about the fixed D where the
    pole is a = d) is the name the drawing's legend gives it."""
    sol, texts, _, rs = emitted[kind]
    for r in rs.values():
        for e in r["expected"]:
            shown = e["shown"]
            assert any(t.startswith(f"{shown} = ") or t.startswith(f"{shown} ≈ 0")
                       for t in texts), (kind, shown)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_no_construction_line_is_named_after_a_vertex(kind):
    """A construction line is named by what it is (line ⟂ BC, slot line ∥ O4Q), never 'c
    line' after the vertex it leads to."""
    _, sol = KINDS[kind]
    vertices = {st.end for st in _made(sol)} | {sol.pole}
    for st in sol.steps:
        if st.kind == "line":
            assert not any(st.draws == f"{v} line" for v in vertices), (kind, st.draws)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_the_exam_spells_an_asked_quantity_as_the_steps_do(kind):
    """An exam question's symbol for a quantity a step gives is that step's quantity in the
    table's spelling ((v_P2)_P4, (a_P4)ⁿ_O4, ω_O4P4), never the labels run together."""
    _, sol = KINDS[kind]
    spelled = {table_quantity(st.quantity) for st in sol.steps}
    asked = [a.q for a in sol.scene.answers if a.q is not None and len(a.q.args) == 2
             and a.q.fn in ("v", "a", "an", "at")]
    given = {st.quantity for st in sol.steps}
    for q in asked:
        x, y = q.args
        src = {"v": f"(v_{x})_{y}", "a": f"(a_{x})_{y}", "an": f"(a_{x})_{y}^n",
               "at": f"(a_{x})_{y}^t"}[q.fn]
        if src in given:                      # a step gives it: the exam spells it as it
            assert symbol(str(q)) == table_quantity(src) in spelled, (kind, str(q))
    for q in asked:                           # never the two labels run together
        assert f"_{q.args[0]}{q.args[1]}" not in symbol(str(q)), (kind, str(q))


@pytest.mark.parametrize("kind", HANDOUT_KINDS)
def test_the_handout_prints_the_narrations_vertices(kind, emitted):
    """The handout's step sentences name each numbered or dashed vertex as printed (a₁′ set
    as a<sub>1</sub>′), never in source form."""
    from diagrams.handout import handout
    sol = emitted[kind][0]
    html = handout(sol)
    for st in _made(sol):
        if vertex(st.end) != st.end:
            assert f" {st.end} " not in html and f" {st.end}." not in html, (kind, st.end)
            assert f"<sub>{st.end[1:].split('_')[0]}</sub>" in html or "′" in html
