"""The layout rule measured on the SVG (diagrams.audit): no vector under 3 mm unless its inset
draws it 3 mm or longer, no label on another, no text printed under 2 mm.

A representative subset runs here (the triads' near-zero components, a Coriolis case, a
velocity image, a rolling wheel, Klein); ``python benchmarks/layout_audit.py`` runs every
shipped case × every kind (~1 min); POLYGONS_AUDIT_ALL=1 runs it here too.
"""
import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "cases"
sys.path.insert(0, str(ROOT / "benchmarks"))

SUBSET = ["s003-fig7", "s001-we3", "rolling-wheel-driven",
          "klein-inline-engine", "centres-double-slider"]
#: finished drawings only (a stage is a prefix of its finished drawing, at its layout)
FINISHED_ONLY: set = set()
#: the kinds held to the rule (force polygons and free bodies: NOT DONE yet, see the report
#: of benchmarks/layout_audit.py)
HELD = ("space", "velocity", "acceleration", "stages", "klein", "rolling")


def _svg(items) -> bytes:
    return ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">'
            + "".join(items) + "</svg>").encode()


def test_audit_measures_a_short_vector_its_inset_and_overlapping_labels():
    from diagrams.audit import measure, verdict
    arrow = ('<g class="arrow"><line class="shaft" x1="10" y1="10" x2="11" y2="10"/>'
             '<polygon class="head" points="12,10 11,9 11,11"/></g>')
    m = measure(_svg([arrow]), "t")
    assert m.vectors[0][1] == pytest.approx(2.0) and m.vectors[0][2] is None
    assert any("drawn 2.00 mm" in b for b in verdict(m))
    inset = ('<g class="inset"><circle class="inset-ring" cx="11" cy="10" r="2"/>'
             '<circle class="inset-frame" cx="60" cy="60" r="10"/></g>')
    m = measure(_svg([arrow, inset]), "t")
    assert m.vectors[0][2] == pytest.approx(10.0) and not verdict(m)   # ×5 in its inset
    texts = ['<text font-size="3" x="10" y="50">line</text>',
             '<text font-size="3" x="12" y="50.5">b</text>']
    m = measure(_svg(texts), "t")
    assert len(m.overlaps) == 1
    far = ['<text font-size="3" x="10" y="50">line</text>',
           '<text font-size="3" x="40" y="50">b</text>']
    assert not measure(_svg(far), "t").overlaps
    assert "prints 1.50 mm" in verdict(measure(_svg(far), "t", reduction=0.5))[0]
    arc = '<g class="arrow arc-head"><line x1="0" y1="0" x2="0" y2="0"/></g>'
    assert not measure(_svg([arc]), "t").vectors          # an input ω's head: no vector


@pytest.mark.parametrize("stem", SUBSET if not os.environ.get("POLYGONS_AUDIT_ALL")
                         else [p.stem for p in sorted(CASES.glob("*.toml"))])
def test_every_drawing_of_a_case_keeps_the_layout_rule(stem):
    from diagrams.audit import measure, verdict
    from layout_audit import drawings_of
    breaches, kinds = [], set()
    for kind, name, svg, red in drawings_of(CASES / f"{stem}.toml", handout=False,
                                              forces=False, stages=stem not in FINISHED_ONLY):
        if kind not in HELD:
            continue
        kinds.add(kind)
        breaches += verdict(measure(svg, f"{stem}/{name}", red))
    assert kinds and not breaches, breaches[:10]


def test_a_vector_too_short_for_any_inset_is_said_not_drawn():
    """The ternary coupler's c₁s₂ (0.03 mm at 1 cm = 2 m/s²) is no arrow; its legend row says
    '≈ 0 (0.03 mm at this scale ...)'; oc₁ (0.38 mm) is in an inset at ×8 or more; every
    finished drawing of the triad keeps the rule (its stages: the benchmark)."""
    import diagrams
    from diagrams import polygon
    from diagrams.audit import measure, verdict
    from diagrams.model import Arrow
    from diagrams.svg import to_svg
    from polygons.api import solve
    sol = solve(str(CASES / "triad-ternary-coupler.toml")).solution
    ds = diagrams.drawings(sol, stages=False)
    for d in ds:
        assert not verdict(measure(to_svg(d), d.name)), d.name
    d = next(d for d in ds if d.name == "acceleration")
    lay = d.meta["layout"]
    assert ("c1", "s2") in lay.ghosts and ("o", "c1") not in lay.ghosts
    drawn = {(a.frm, a.to) for a in d.items() if isinstance(a, Arrow)}
    assert ("c1", "s2") not in drawn and ("o", "c1") in drawn
    rows = [r for r, _ in polygon.legend(lay, sol)]
    assert any(r.startswith("c1\u2060s2 ≈ 0 (0.03 mm at this scale") for r in rows), rows
    ins = [i for i in lay.insets if "c1" in i.names]
    assert ins and ins[0].k >= 8


def test_a_triads_handout_stage_thumbnails_keep_the_layout_rule(monkeypatch):
    """The handout's stage thumbnails print 56 mm wide with labels set larger so they print
    2.5 mm high.  Drawn whole, the triad's acceleration polygon (its insets far apart)
    printed at ×0.13: each stage is a detail of its own vectors at its own stated scale
    (diagrams.figures.detail), printed at ×0.2 or more, most at ×0.35 or more (an own
    vector far shorter than its step's lines keeps an inset); measured after the column's
    reduction, none breaks the layout rule, and each draws its step's new vertex."""
    import diagrams
    from diagrams import figures
    from diagrams.audit import measure, verdict
    from diagrams.svg import to_svg
    from polygons.api import solve
    sol = solve(str(CASES / "forces-triad.toml")).solution
    d = next(d for d in diagrams.drawings(sol, None, None, False) if d.name == "acceleration")
    lay = d.meta["layout"]
    stages = figures._stages(sol, "acceleration", lay.scale, None, lay)
    breaches = []
    for s in stages:
        k = figures.stage_width(s.width, s.height) / s.width
        breaches += verdict(measure(to_svg(s), f"forces-triad/handout:{s.name}", k))
    assert len(stages) >= 10 and not breaches, breaches[:10]
    assert all(s.meta.get("detail") for s in stages)
    shrink = [figures.stage_width(s.width, s.height) / s.width for s in stages]
    assert min(shrink) >= 0.2 and sorted(shrink)[len(shrink) // 2] >= 0.35, shrink
    from diagrams.text import token
    for s in stages:
        step = lay.con.steps[int(s.name.rsplit("-", 1)[1]) - 1]
        if step.end and lay.con.born.get(step.end) == step.number:
            mine = f"acceleration-vertex-{token(step.end)}"
            assert any(getattr(c, "ident", "") == mine and not c.faded
                       for c in s.items()), (s.name, mine)


def test_force_legend_rows_are_wrapped_to_the_figures_width():
    """A force drawing's legend row longer than FORCE_LEGEND_MM is wrapped (its further lines
    indented), measured by the typeset width of each text the SVG holds: the oscillating
    cylinder's group 2 has '−m a_G (O2P) ≈ 0 (1.13 mm at this scale: 2.824 N, not drawn)',
    ~90 mm unwrapped.  A polygon that closes to rounding says 'gap 0 N', not 'gap 7.3e-15 N'."""
    from diagrams import fbd, forcepoly
    from diagrams.audit import measure
    from diagrams.layout import FORCE_LEGEND_MM, LEGEND_INDENT
    from diagrams.svg import to_svg
    from polygons.forces import analyse
    from polygons.scene import load_scene
    an = analyse(load_scene(str(CASES / "forces-oscillating-cylinder.toml")))
    st = an.states[0]
    drawn = dict(forcepoly.group_drawings(an, st) + forcepoly.lever_drawings(an, st))
    drawn |= dict(fbd.drawings(an))
    rows = 0
    for name, d in drawn.items():
        legend = [t for t in d.items("legend") if getattr(t, "text", "")]
        m = measure(to_svg(d), name)
        for text, _, boxes in m.texts:
            if any(t.text == text for t in legend):
                w = max(b[2] for b in boxes) - min(b[0] for b in boxes)
                assert w <= FORCE_LEGEND_MM + 0.5, (name, text, w)
        rows += sum(1 for t in legend if t.x > min(u.x for u in legend) + LEGEND_INDENT / 2)
        if name.startswith("forces-"):
            assert "gap 0 N" in " ".join(t.text for t in d.items("caption")), name
    assert rows >= 2


def test_crossing_slots_sliding_results_are_named_apart():
    """A pin in crossing slots has two sliding velocities and accelerations: each legend row
    names its quantity ('a_slide = (a_P)_P2 = …'), not two bare 'a_slide' rows."""
    from diagrams.polywords import measure_text
    from diagrams.strokes import construction
    from polygons.api import solve
    sol = solve(str(CASES / "new-crossing-slots.toml")).solution
    for diagram, sym in (("velocity", "v"), ("acceleration", "a")):
        con = construction(sol, diagram)
        rows = [r for r in (measure_text(m, sol, con) for m in con.measures)
                if "slide" in r]
        assert len(rows) == 2, rows
        assert any(f"({sym}_P)_P2" in r for r in rows) and any(f"({sym}_P)_P4" in r
                                                                for r in rows), rows
