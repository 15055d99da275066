"""The notation table (docs/notation.md) is generated from the groups' steps and is current;
every name the steps give a vertex follows its rules, and the drawings and the narration print
the same names."""
import re

import pytest

import diagrams
from conftest import ROOT, case_files
from diagrams.model import Text
from polygons import notation_doc
from polygons.evaluate import solve
from polygons.notation import VERTEX, vertex
from polygons.scene import load_scene


def test_the_notation_table_is_current():
    assert (ROOT / notation_doc.NOTATION).read_text(encoding="utf-8") == notation_doc.markdown()


def test_the_table_covers_every_group_kind_of_the_shipped_cases():
    text = notation_doc.markdown()
    for kind in ("RRR", "RRP", "RPR", "Guided", "Triad", "CrankDyad"):
        assert f"## {kind}\n" in text


def _labels_of(scene):
    return {lab.lower() for lab in scene.labels}


@pytest.mark.parametrize("path", case_files(), ids=lambda p: p.stem)
def test_every_vertex_a_step_makes_follows_the_rules(path):
    """A new vertex is a point's own (its label in lower case), or an end of a known component
    numbered after it (c1; p4_1 for a label ending in a digit), or a Coriolis foot dashed
    (p_1, p2_1): never a name that reads as another point's vertex."""
    scene = load_scene(path)
    sol = solve(scene)
    # a point's own vertex: its label's, or a construction point's the books letter (the
    # Assur point S of a triad: s)
    own = _labels_of(scene) | {st.end for st in sol.steps
                               if st.end and re.fullmatch("[a-z]", st.end)}
    for st in sol.steps:
        if st.kind not in ("vector", "image", "intersection") or not st.end:
            continue
        name = st.end
        if name in own or name == sol.pole:
            continue
        m = re.fullmatch(VERTEX, name)
        assert m is not None, f"{path.stem}: vertex {name!r} of step {st.number}"
        base = m["vl"] + (m["vd"] or "")
        if m["vq"] or m["vp"]:           # dashed: after its own point's vertex
            assert base in own, f"{path.stem}: {name!r} dashes no point's vertex"
        else:                            # numbered: a letter label's vertex and a number
            assert any(name == lab + d for lab in own if not lab[-1].isdigit()
                       for d in m["vd"]), f"{path.stem}: {name!r}"
        if st.op == "coriolis":          # the Coriolis foot is dashed, as the books draw it
            assert m["vq"] or m["vp"], f"{path.stem}: Coriolis foot {name!r} not dashed"


@pytest.mark.parametrize("case", ["s003-fig7", "forces-oscillating-cylinder", "s001-we3"])
def test_drawings_and_narration_print_the_tables_names(case):
    """Each vertex a step makes is printed by the drawing's labels and the narration alike as
    notation.vertex spells it (p′ for the oscillating cylinder's Coriolis foot, p₂′ in Fig 7)."""
    scene = load_scene(ROOT / "cases" / f"{case}.toml")
    sol = solve(scene)
    printed = {vertex(st.end) for st in sol.steps
               if st.kind in ("vector", "image", "intersection") and st.end}
    texts = set()
    for d in diagrams.drawings(sol, None, None, False):
        texts |= {t.text for t in d.items() if isinstance(t, Text)}
    from diagrams.notation import plain
    drawn = {plain(t) for t in texts}
    words = " ".join(st.reason for st in sol.steps)
    for name in printed:
        assert any(name in t.split(" = ") or name == t for t in drawn), (case, name)
    coriolis = [st for st in sol.steps if st.op == "coriolis"]
    for st in coriolis:
        assert "′" in vertex(st.end) or "″" in vertex(st.end)
        assert st.end in words or vertex(st.end) in words
