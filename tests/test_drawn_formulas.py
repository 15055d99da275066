"""Drawings that agree with their numbers (issue 28, item 4): every "= xy / XY" a drawing
prints beside a rate is the length of the polygon's vector xy over the space diagram's XY,
to rounding — over every shipped case.  An angular velocity is its relative velocity over the
length; an angular acceleration its *tangential* part (from the end of the centripetal vector)
over the length, never the whole relative acceleration.  The printed caption and the number
come from one Step record (diagrams.polygon.measure_text)."""
import math

import pytest

from conftest import case_files
from diagrams.polygon import measure_text
from diagrams.text import display
from polygons.evaluate import solve
from polygons.scene import load_scene

CASES = case_files()


def _split(word, names):
    """``word`` as two names of ``names`` run together ('x1x' → ('x1', 'x')), else None."""
    hits = [(word[:i], word[i:]) for i in range(1, len(word))
            if word[:i] in names and word[i:] in names]
    return hits[0] if len(hits) == 1 else None


def _formulas(sol):
    """(step, vector (v1, v2), space pair (P, Q) or None) of every measure step whose formula
    reads '… = v1v2 / PQ' or '… = v1v2'."""
    for s in sol.steps:
        if s.kind != "measure" or "=" not in s.formula or s.value is None:
            continue
        rhs = s.formula.split("=", 1)[1].strip()
        parts = [p.strip() for p in rhs.split("/")]
        vertices = sol.vertices.get(s.diagram, {})
        vec = _split(parts[0], vertices)
        if vec is None:
            continue
        pair = _split(parts[1], sol.points) if len(parts) == 2 else None
        if len(parts) == 2 and pair is None:
            continue                        # '/ r': a wheel's radius (checked by its tests)
        yield s, vec, pair


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_each_printed_ratio_is_the_lengths_it_names(path):
    sol = solve(load_scene(path))
    seen = 0
    for s, (v1, v2), pair in _formulas(sol):
        vx = sol.vertices[s.diagram]
        length = math.dist(vx[v1], vx[v2])
        size = max(math.hypot(*p) for p in vx.values())     # the polygon's rounding scale
        if pair is not None:
            span = math.dist(sol.points[pair[0]].position, sol.points[pair[1]].position)
            length, size = length / span, size / span
        assert abs(abs(s.value) - length) <= 1e-9 * max(abs(s.value), length, size), (
            f"{path.stem} {s.diagram} step {s.number}: {s.formula} prints {s.value!r} but the "
            f"lengths it names give {length!r}")
        # the drawing's caption is that record's own formula
        assert display(s.formula.split("=", 1)[1].strip()) in measure_text(s)
        seen += 1
    if any(st.kind == "measure" for st in sol.steps):
        assert seen or all("=" not in st.formula for st in sol.steps if st.kind == "measure")


def test_a_triad_s_alpha_is_read_from_its_tangential_part():
    """The issue's triad: α_CD printed with "(= oc / DC)" while oc / DC was another number.
    Each α of a triad names the tangential vector (c₁c, b₁b, x₁x, x₂x); s₁s and s₂s are named
    as the sums of two tangential terms they are."""
    sol = solve(load_scene(CASES[0].parent / "triad-ternary-coupler.toml"))
    acc = {s.draws: s for s in sol.steps if s.diagram == "acceleration"}
    assert acc["α_CD"].formula == "α_CD = c1c / DC"
    assert acc["α_AB"].formula == "α_AB = b1b / AB"
    # the plate's rate by its link's one symbol (legend, narration, table, grader alike),
    # its words naming the plate by its corners
    assert acc["α_BC"].formula == "α_BC = x1x / SX"
    assert acc["α_BC"].quantity == "α_BC" and "the plate BCX (link BC)" in acc["α_BC"].reason
    names = {s.quantity for s in sol.steps if s.diagram == "acceleration" and s.kind == "line"}
    assert "(a_B)_A^t + (a_S)_B^t" in names and "(a_C)_D^t + (a_S)_C^t" in names
    vx = sol.vertices["acceleration"]
    oc = math.dist(vx["o"], vx["c"]) / 0.2          # what the old caption said it was
    assert abs(oc - abs(acc["α_CD"].value)) > 1e-7 * oc
