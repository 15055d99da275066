"""Drawings a lecturer hands out unchanged (issue 21, items 1, 3, 6, 8, 9), read back from the
written SVGs where the point is what a reader sees:

* every asked quantity of the scene (components, Coriolis, sliding, the ram's v_R, ω/α) is
  marked on its diagram — a vector group of the component the answer names, classed
  ``asked``, and a legend row ``← asked``;
* every drawn vector is in its component's look and has a key entry (no thin grey vector);
* every vector or line label is nearer its own stroke than any other, or led to it;
* one notation: space labels O₂ (scene labels only), p₄′ in the text table and hints, no
  double negative, no duplicated legend row, the legend in the scale's unit;
* free-body diagrams typeset R_B, W_AB and set no label on another, an arrow or an arc;
* the sweep summary rounded as the table, the scene's own input marked, the asked points
  plotted.
"""
import math
import re
import xml.etree.ElementTree as ET

import pytest

import diagrams
from conftest import CASES
from diagrams import polygon
from diagrams.labels import box_hits_segment, box_segment_distance, text_box
from diagrams.model import Arrow, Polyline, Segment, Text
from diagrams.components import LOOKS
from diagrams.notation import mark_labels, plain
from diagrams.svg import to_svg
from polygons.evaluate import solve
from polygons.scene import load_scene

SVG = "{http://www.w3.org/2000/svg}"
MARKED = ["new-rotary-engine", "new-oscillating-cylinder", "new-slot-on-moving-lever",
          "s003-fig7", "new-whitworth", "s001-sae4-q3", "s001-we1"]
_cache = {}


def finals(name):
    if name not in _cache:
        sol = solve(load_scene(CASES / f"{name}.toml"))
        ds = diagrams.drawings(sol, stages=False)
        _cache[name] = (sol, {d.kind: d for d in ds},
                        {d.kind: ET.fromstring(to_svg(d)) for d in ds})
    return _cache[name]


def _groups(root):
    return [g.get("class", "").split() for g in root.iter(SVG + "g")]


def _texts(root):
    return ["".join(t.itertext()) for t in root.iter(SVG + "text")]


#: the component an answer's function names, on which diagram
WHICH = {"v": ("velocity", None), "a": ("acceleration", None),
         "an": ("acceleration", "centripetal"), "at": ("acceleration", "tangential"),
         "cor": ("acceleration", "coriolis"), "vs": ("velocity", "sliding"),
         "as": ("acceleration", "sliding"), "omega": ("velocity", None),
         "alpha": ("acceleration", None)}


@pytest.mark.parametrize("name", MARKED)
def test_every_asked_quantity_is_marked_on_its_drawing(name):
    """Read from the SVG: for each answer, a vector of the component it names (sliding for
    vs/as on a slot, the absolute vector for a slider on a fixed guide) classed 'asked', and
    as many '← asked' legend rows as the diagram has asked quantities."""
    sol, ds, roots = finals(name)
    for ans in sol.scene.answers:
        fn, args = ans.q.fn, ans.q.args
        if fn not in WHICH or WHICH[fn][0] not in roots:
            continue
        diagram, comp = WHICH[fn]
        if ans.exact == 0.0 and fn in ("an", "at"):    # no vector: said so
            assert any("= 0: no vector to draw" in t and "← asked" in t
                       for t in _texts(roots[diagram])), (name, ans.quantity)
            continue
        asked = [c for c in _groups(roots[diagram]) if "vector" in c and "asked" in c]
        if fn in ("vs", "as") and args[0] in sol.scene.model.guide:
            comp = None                       # along a fixed guide: the absolute vector
        if comp is not None:
            assert any(comp in c for c in asked), (name, ans.quantity, asked)
        elif fn in ("v", "a", "vs", "as"):
            pole = sol.pole
            frm = pole if len(args) == 1 or fn in ("vs", "as") else sol.vertex_of(args[1])
            x = sol.vertex_of(args[0])
            ghosts = ds[diagram].meta["layout"].ghosts
            if (frm, x) in ghosts or (x, frm) in ghosts:   # too short for any inset: said
                assert any("not drawn" in t and "← asked" in t and t.startswith(
                    (f"{frm}{x} ", f"{x}{frm} ")) for t in _texts(roots[diagram])), (
                    name, ans.quantity)
                continue
            assert any({f"from-{frm}", f"to-{x}"} <= set(c) or {f"from-{x}", f"to-{frm}"}
                       <= set(c) for c in asked), (name, ans.quantity)
        elif args[0] == getattr(sol.scene.driver, "link", None):   # the input's own rate:
            assert any("given" in c for c in asked), (name, ans.quantity)  # its vector
        else:                                 # ω, α: their measure row is marked
            sym = "ω" if fn == "omega" else "α"
            assert any(t.startswith(sym) and "← asked" in t and args[0] in t
                       for t in _texts(roots[diagram])), (name, ans.quantity)


def test_fig7_acceleration_marks_its_five():
    """Fig 7's acceleration diagram: α, Coriolis, the centripetal and tangential parts, the
    sliding acceleration — each drawn vector classed 'asked' (it marked none before)."""
    _, _, roots = finals("s003-fig7")
    asked = [c for c in _groups(roots["acceleration"]) if "vector" in c and "asked" in c]
    kinds = {k for c in asked for k in ("centripetal", "tangential", "coriolis", "sliding")
             if k in c}
    assert kinds == {"centripetal", "tangential", "coriolis", "sliding"}
    assert sum("← asked" in t for t in _texts(roots["acceleration"])) >= 5


@pytest.mark.parametrize("name", MARKED)
def test_every_vector_is_in_its_components_look_with_a_key_entry(name):
    """No vector drawn as a construction line (thin grey, no key): the inverted slider-crank's
    p₁p, p₂p, p₄p and op are sliding, tangential, relative — each in the key."""
    _, ds, roots = finals(name)
    for kind, d in ds.items():
        if kind == "space":
            continue
        drawn = {a.style[2:].removesuffix("-new") for a in d.items() if isinstance(a, Arrow)}
        assert "construction" not in drawn, (name, kind)
        keys = {t.text for t in d.items("key") if isinstance(t, Text)}
        assert {LOOKS[k].name for k in drawn} <= keys, (name, kind)


@pytest.mark.parametrize("name", ["new-rotary-engine", "new-oscillating-cylinder",
                                  "new-slot-on-moving-lever", "s003-fig7"])
def test_each_label_sits_by_its_own_stroke_or_is_led_to_it(name):
    """Every vector name and line name is nearer its own stroke (by OWNER_MARGIN) than any
    other drawn line or vector, or has a leader ending on its own stroke."""
    sol, ds, _ = finals(name)
    for kind in ("velocity", "acceleration"):
        lay = ds[kind].meta["layout"]
        geo = [(st, polygon._drawn(lay, st, g) if st.kind != "line" else g)
               for st, g in polygon._geometry(lay) if g is not None
               and st.kind in ("line", "arrow", "offset")]
        led = {(step, fv) for step, fv, _ in lay.leaders}
        ends = {(step, fv): lead[1] for step, fv, lead in lay.leaders}
        for st, g in geo:
            if st.kind == "line":
                lab = lay.line_labels.get(st.step)
            else:
                lab = lay.vector_labels.get((st.step, st.frm, st.to))
            if lab is None:
                continue
            box = lab[3]
            key = (st.step, (st.frm, st.to))
            if key in led:
                # the leader ends on its own vector
                from diagrams.labels import point_segment_distance
                assert point_segment_distance(ends[key], *g) < 0.5, (name, kind, st.label)
                continue
            mine = box_segment_distance(box, *g)
            others = min((box_segment_distance(box, *h) for s2, h in geo
                          if s2 is not st and not polygon.on_line(h, g)), default=math.inf)
            assert others >= mine + polygon.OWNER_MARGIN - 1e-6, (name, kind, st.label)


def test_rotary_engine_slot_line_label_is_beside_the_slot_line():
    """The issue's case: 'slot line ∥ OQ' sat beside the line ⊥ CP."""
    _, ds, _ = finals("new-rotary-engine")
    lay = ds["acceleration"].meta["layout"]
    geo = {st.step: g for st, g in polygon._geometry(lay) if st.kind == "line"}
    slot = next(st for st in lay.con.strokes if st.kind == "line" and "slot" in st.label)
    other = next(st for st in lay.con.strokes if st.kind == "line" and "slot" not in st.label)
    box = lay.line_labels[slot.step][3]
    assert box_segment_distance(box, *geo[slot.step]) < box_segment_distance(box,
                                                                             *geo[other.step])


# ---------------------------------------------------------------- one notation
def test_space_labels_are_subscripted_and_only_the_scenes_labels():
    """O2 is typeset O₂ (a tspan subscript) on the space diagram; the title's question number
    Q3 of 'SAE4 Q3' is not a label there and stays as written."""
    _, _, roots = finals("s003-fig7")
    subs = [t for t in roots["space"].iter(SVG + "tspan") if t.text == "2"
            and t.get("font-size")]
    assert subs
    labels = ("O2", "P2", "O4", "P4", "A", "B")
    assert plain(mark_labels("crank O2P2 drives O4P4", labels)) == "crank O₂P₂ drives O₄P₄"
    assert plain(mark_labels("SAE4 Q3, paper A4, ω_O4P4", labels)) == "SAE4 Q3, paper A4, ω_O4P4"


def test_the_table_and_hints_write_vertices_as_printed_with_no_double_negative(capsys):
    from polygons.cli import main
    main(["solve", str(CASES / "s003-fig7.toml")])
    out = capsys.readouterr().out
    assert "p₄′" in out and "p4_1" not in out and "p2_1" not in out
    assert not re.search(r"-\d[\d.]*\s*\S+\s*\((towards|along|away)", out)
    main(["check", str(CASES / "s003-fig7.toml"), "--measured", "alpha_O4P4=3"])
    out = capsys.readouterr().out
    assert "hint:" in out and "p₄′p₄" in out and "p4_1" not in out


@pytest.mark.parametrize("name", MARKED)
def test_legend_has_no_duplicated_vector_and_speaks_the_scales_unit(name):
    _, ds, _ = finals(name)
    for kind in ("velocity", "acceleration"):
        rows = [t.text for t in ds[kind].items("legend") if isinstance(t, Text)]
        for r in rows:
            r = r.replace("\u2060", "")
            m = re.search(r"\((\S+)\)\s+\(= (\S+)\)", r)
            assert not (m and m.group(1) == m.group(2)), r
        unit = ds[kind].meta["layout"].scale.unit.replace("^2", "²")
        other = {"m/s": "mm/s", "mm/s": "m/s", "m/s²": "mm/s²", "mm/s²": "m/s²"}[unit]
        assert not any(re.search(rf"\d {re.escape(other)}(\s|$)", r) for r in rows), (name, kind)


def test_whitworth_legend_in_mm_per_s_like_its_scale():
    _, ds, _ = finals("new-whitworth")
    rows = [t.text for t in ds["velocity"].items("legend") if isinstance(t, Text)]
    assert ds["velocity"].meta["layout"].scale.unit == "mm/s"
    slide = next(r for r in rows if r.startswith("v_slide"))
    assert " mm/s " in slide and " m/s " not in slide


def test_lever_components_name_their_pivot():
    """(a_P4)ⁿ and (a_P4)ᵗ of Fig 7's slotted lever are (a_P4)ⁿ_O4, (a_P4)ᵗ_O4."""
    sol, _, _ = finals("s003-fig7")
    qs = {s.quantity for s in sol.steps if s.diagram == "acceleration"}
    assert {"(a_P4)_O4^n", "(a_P4)_O4^t"} <= qs


def test_a_stacked_superscript_does_not_run_into_what_follows():
    """'(a_P)_O2^t ← asked': the text after a stacked pair starts after the subscript."""
    from diagrams.notation import svg_runs
    from diagrams.metrics import plain_width
    runs = svg_runs("(a_P)_O2^t x", 3.0)
    sup = next(i for i, r in enumerate(runs) if r[0] == "t")
    sub_w, sup_w = plain_width("O2", 2.1), plain_width("t", 2.1)
    assert runs[sup + 1][1] == pytest.approx(sub_w - sup_w, abs=1e-3)


# ---------------------------------------------------------------- free-body diagrams
@pytest.mark.parametrize("case", ["s002-ex3.17", "s002-ex3.16"])
def test_free_body_labels_are_typeset_and_overlap_nothing(case):
    from diagrams.fbd import drawings as fbd_drawings
    from polygons.forces import analyse
    an = analyse(load_scene(CASES / f"{case}.toml"))
    pages = fbd_drawings(an)
    assert pages
    for stem, d in pages:
        labels = [(t.text, text_box(t.x, t.baseline, t.text, t.size, t.anchor))
                  for t in d.items() if isinstance(t, Text) and t.role in ("label", "vertex")]
        for i, (ta, a) in enumerate(labels):
            for tb, b in labels[i + 1:]:
                assert not a.overlaps(b), (stem, ta, tb)
        strokes = []
        for it in d.items():
            if isinstance(it, Arrow):
                strokes.append((it.name, it.tail, it.tip))
            elif isinstance(it, Polyline) and "couple" in it.cls:
                strokes += [("arc", p, q) for p, q in zip(it.points, it.points[1:])]
            elif isinstance(it, Segment) and it.style == "link":
                strokes.append(("body", it.a, it.b))
        for t, b in labels:
            for what, p, q in strokes:
                assert not box_hits_segment(b, p, q, 0.2), (stem, t, what)
        root = ET.fromstring(to_svg(d))
        for t in root.iter(SVG + "text"):
            if (t.text or "").startswith(("R_", "W_", "−I_G", "G_")):
                raise AssertionError(f"{stem}: {t.text!r} not typeset")
    ex = [d for stem, d in pages if stem.startswith("fbd-")][0]
    root = ET.fromstring(to_svg(ex))
    assert any(t.text in ("R", "W") and len(list(t)) for t in root.iter(SVG + "text")) or any(
        (s.text or "").strip() and s.get("font-size") for s in root.iter(SVG + "tspan"))


# ---------------------------------------------------------------- sweeps
def test_sweep_summary_rounds_marks_the_scene_and_plots_the_asked_points(tmp_path, capsys,
                                                                        monkeypatch):
    from polygons.cli import main
    from polygons.cli import sweep as cli_sweep
    from polygons.steps import number
    seen = {}
    real = cli_sweep.plot

    def spy(sw, points, links, shm, unit, stem, formats):
        seen["points"] = list(points)
        return []
    monkeypatch.setattr(cli_sweep, "plot", spy)
    assert main(["sweep", str(CASES / "s003-fig7.toml"), "--steps", "36", "--out",
                 str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert seen["points"] == ["P2", "P4"]            # asked: cor(P2), v(P4) ...
    for m in re.finditer(r"max \|[va]\| = ([\d.e+-]+)", out):
        assert m.group(1) == number(float(m.group(1)))   # already as the table rounds
        assert len(m.group(1).replace(".", "").lstrip("0")) <= 6
    monkeypatch.setattr(cli_sweep, "plot", real)
    # the dots: one marker point per curve, at the scene's crank angle, on the curve's value
    import diagrams.plots as plots
    got = {}

    def capture(title, xlabel, panels, stem, formats, markers, *a, **k):
        got["panels"], got["markers"] = panels, markers
        return []
    monkeypatch.setattr(plots, "plot_panels", capture)
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    from polygons.sweep import sweep
    sw = sweep(sol.scene, 36)
    cli_sweep.plot(sw, ["P2"], ["O4P4"], {}, "mm", tmp_path / "x", ["png"])
    theta = math.degrees(sol.scene.driver.angle) % 360.0
    assert any(m.x == pytest.approx(theta) and "scene" in m.label for m in got["markers"])
    for panel in got["panels"]:
        curves = [ln for ln in panel.lines if ln.marker is None]
        dots = [ln for ln in panel.lines if ln.marker == "o"]
        assert len(dots) == len(curves) and all(d.x == [pytest.approx(theta)] for d in dots)
    om = next(p for p in got["panels"] if p.ylabel.startswith("ω"))
    dot = next(ln for ln in om.lines if ln.marker == "o")
    assert dot.y[0] == pytest.approx(sol.links["O4P4"].omega, rel=1e-9)
