"""Labelled SVG diagrams: construction order, scale, labels, scaled lengths, valid output.

Everything is checked on the drawings themselves: the model's geometry (labels against
vectors), the written SVG parsed back (vertices, arrows, the stated scale), and one case
rendered to PNG by cairosvg, a real renderer.
"""
import io
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

import diagrams
from conftest import CASES, case_files
from diagrams import crowd, inset, measure, polygon, scale
from diagrams.labels import box_hits_segment, text_box
from diagrams.model import Arrow, Circle, Polyline, Segment, Text
from diagrams.components import LOOKS
from diagrams.notation import JOIN, MARK
from diagrams.svg import to_svg
from polygons.cli import main
from polygons.errors import PolygonsError, SceneError, UnknownKeyError
from polygons.evaluate import solve
from polygons.scene import load_scene, parse_scene

FILES = case_files()
IDS = [f.stem for f in FILES]
SVG = "{http://www.w3.org/2000/svg}"
ROOT = Path(__file__).resolve().parents[1]

_cache = {}


def solved(path):
    if path not in _cache:
        sol = solve(load_scene(path))
        _cache[path] = (sol, diagrams.drawings(sol))
    return _cache[path]


_svg = {}
_readings = {}


def svg_of(d) -> str:
    """``to_svg(d)`` of a drawing of :func:`solved`, written once per test process (several
    tests read the same SVG back; the drawings it caches live as long, so ids stay theirs)."""
    hit = _svg.get(id(d))
    if hit is None or hit[0] is not d:
        hit = _svg[id(d)] = (d, to_svg(d))
    return hit[1]


def readings(path) -> dict:
    """``measure.readings_of`` of a case's drawings (:func:`solved`), once per test process
    (read only: measure.compare reads them)."""
    if path not in _readings:
        _readings[path] = measure.readings_of(solved(path)[1])
    return _readings[path]


def finals(drawings):
    return {d.kind: d for d in drawings if d.stage is None}


def drawable_steps(sol, diagram):
    return [s for s in sol.steps if s.diagram == diagram
            and s.kind in ("vector", "image", "line", "intersection")]


# ---------------------------------------------------------------- what is produced
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_every_case_has_the_three_diagrams_and_every_stage(path):
    sol, ds = solved(path)
    names = [d.name for d in ds]
    assert names[0] == "space"
    for diagram in sol.scene.solve:
        n = len(drawable_steps(sol, diagram))
        assert n >= 1
        assert diagram in names
        assert [x for x in names if x.startswith(diagram + "-")] == \
            [f"{diagram}-{k}" for k in range(1, n + 1)]


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_every_svg_parses_with_title_desc_and_mm_page(path):
    sol, ds = solved(path)
    for d in ds:
        data = svg_of(d)
        root = ET.fromstring(data)
        assert root.tag == SVG + "svg"
        assert root.get("width").endswith("mm") and root.get("height").endswith("mm")
        vb = [float(x) for x in root.get("viewBox").split()]
        assert vb[2] == pytest.approx(float(root.get("width")[:-2]))
        title, desc = root.find(SVG + "title"), root.find(SVG + "desc")
        assert title is not None and title.text.strip()
        assert desc is not None and desc.text.strip()
        texts = [t.text for t in root.iter(SVG + "text")]
        assert any("Scale 1 cm = " in (t or "") for t in texts)   # text as text
        for g in root.iter(SVG + "g"):
            if (g.get("class") or "").startswith("vector"):
                assert g.find(SVG + "title") is not None     # every vector says what it is


# ---------------------------------------------------------------- construction order
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_stage_k_adds_exactly_step_k(path):
    sol, ds = solved(path)
    by_name = {d.name: d for d in ds}
    for diagram in sol.scene.solve:
        steps = drawable_steps(sol, diagram)
        prev_vectors = set()
        for k, step in enumerate(steps, 1):
            d = by_name[f"{diagram}-{k}"]
            arrows = [a for a in d.items() if isinstance(a, Arrow)]
            vectors = {(a.frm, a.to) for a in arrows}
            new = {(a.frm, a.to) for a in arrows if a.new}
            assert prev_vectors <= vectors
            assert vectors - prev_vectors == new
            lay = by_name[diagram].meta["layout"]
            if step.kind in ("vector", "image") and (step.start, step.end) not in lay.ghosts:
                assert (step.start, step.end) in new   # (a vector too short for any inset
                #                                        is said in the legend, not drawn)
            if step.kind == "line":
                assert not new
                assert any(isinstance(s, Segment) and f"step-{step.number}" in s.cls
                           and s.style == "c-construction-new" for s in d.items())
            if step.kind == "intersection":
                assert new or any(step.end in g for g in lay.ghosts)   # (its vectors: ≈ 0)
                assert all(to == step.end or frm == step.end for frm, to in new)
            caption = " ".join(t.text for t in d.items("caption")).replace(JOIN, "").replace(MARK, "")
            # stages are numbered, never lettered: 'Fig. b' would read as vertex b
            assert caption.startswith(f"Stage {k}. ")
            words = step.reason.replace("⟂", "⊥").split()
            assert " ".join(words[:3]) in caption
            prev_vectors = vectors


def test_fig7_stages_follow_the_tutorial_with_coriolis_and_offset_line():
    sol, ds = solved(CASES / "s003-fig7.toml")
    by = {d.name: d for d in ds}
    caps = [" ".join(t.text for t in by[f"acceleration-{k}"].items("caption"))
            for k in range(1, 8)]
    assert "centripetal acceleration of P2" in caps[0]
    assert "centripetal acceleration of P4" in caps[1]
    assert "Coriolis" in caps[3] and "parallel to the slot" in caps[3]
    assert "Coriolis" in caps[5]
    final = by["acceleration"]
    labels = [t.text for t in final.items() if isinstance(t, Text)]
    assert "Coriolis offset line" in labels and "2ωv" in labels and "line ⊥ O4P4" in labels
    cor = [a for a in final.items() if isinstance(a, Arrow) and a.role == "coriolis"]
    assert len(cor) == 1 and (cor[0].frm, cor[0].to) == ("p4", "p2_1")
    assert cor[0].style == "c-coriolis"


def test_we4_has_the_line_perpendicular_to_bc_and_slider_line_as_the_tutorial_draws():
    """The tutorial's "c line" is named for what it is (one notation: "line ⊥ BC")."""
    sol, ds = solved(CASES / "s001-we4.toml")
    acc = finals(ds)["acceleration"]
    labels = {t.text for t in acc.items() if isinstance(t, Text)}
    assert {"line ⊥ BC", "slider line", "a", "b", "c1", "c"} <= labels
    assert not any(t.endswith(" line") and t.split()[0] in ("b", "c", "p4", "r") for t in labels)
    vecs = {(a.frm, a.to): a.role for a in acc.items() if isinstance(a, Arrow)}
    assert vecs[("a", "b")] == "known" and vecs[("b", "c1")] == "known"
    assert vecs[("c1", "c")] == "resolved" and vecs[("a", "c")] == "resolved"


# ---------------------------------------------------------------- arrows are the step vectors
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_arrows_join_their_vertices_in_the_sense_of_the_step_vectors(path):
    sol, ds = solved(path)
    for kind, d in finals(ds).items():
        if kind == "space":
            continue
        r = measure.read_svg(svg_of(d))
        drawn = {(v.frm, v.to): v for v in r.vectors}
        for v in r.vectors:          # tail at `frm`, tip at `to`
            if v.mm < 0.05:          # shorter than a vertex mark: its ends share one mark
                continue
            for end, name in ((v.tail, v.frm), (v.tip, v.to)):
                assert math.dist(end, r.vertices[name]) < 0.01, (kind, v)
        for s in sol.steps:
            if s.diagram != kind or s.kind not in ("vector", "image"):
                continue
            if (s.start, s.end) in d.meta["layout"].ghosts:   # too short for any inset:
                assert (s.start, s.end) not in drawn          # said in the legend instead
                continue
            v = drawn[(s.start, s.end)]
            mag = math.hypot(*s.vector)
            if mag == 0 or v.mm < 0.05:
                continue
            ang_step = math.atan2(s.vector[1], s.vector[0])
            ang_drawn = math.atan2(v.tip[1] - v.tail[1], v.tip[0] - v.tail[0])
            diff = abs((ang_step - ang_drawn + math.pi) % (2 * math.pi) - math.pi)
            assert math.degrees(diff) < 0.1 + math.degrees(0.002 / max(v.mm, 1e-9)), s.draws
            assert r.si(v.mm) == pytest.approx(mag, rel=1e-3, abs=r.si(0.002))


# ---------------------------------------------------------------- labels do not overlap
LABEL_ROLES = ("vertex", "line", "component", "point", "input", "inset")


def _label_boxes(d):
    """(text, box) of every label of the drawing, boxes from the typeset widths."""
    out = []
    for t in d.items():
        if isinstance(t, Text) and t.role in LABEL_ROLES:
            out.append((t.text, text_box(t.x, t.baseline, t.text, t.size, t.anchor)))
    return out


def _strokes(d):
    """(what, a, b, clearance) of every drawn stroke a label must keep clear of: vectors,
    links, the input arcs and arrows, the Coriolis offset and its right-angle mark."""
    out = []
    for it in d.items():
        if isinstance(it, Arrow):
            out.append((f"vector {it.name}" if it.role != "input" else "input arrow",
                        *it.drawn, 0.5 if it.role != "input" else 0.2))
        elif isinstance(it, Segment) and (it.style == "link" or "offset" in it.cls
                                          or "right-angle" in it.cls or "leader" in it.cls
                                          or "inset" in it.cls):
            out.append((it.cls or it.style, it.a, it.b, 0.3))
        elif isinstance(it, Circle) and it.cls in ("inset-ring", "inset-frame"):
            out += [(it.cls, p, q, 0.2) for p, q in inset.chords(it.centre, it.r)]
        elif isinstance(it, Polyline) and it.style.startswith("input"):
            out += [("input arc", p, q, 0.2) for p, q in zip(it.points, it.points[1:])]
        elif isinstance(it, Polyline) and it.style == "ground":
            pts = it.points + it.points[:1]
            out += [("fixed-pivot symbol", p, q, 0.2) for p, q in zip(pts, pts[1:])]
        elif isinstance(it, Segment) and it.style in ("ground", "hatch"):
            out.append(("fixed-pivot hatching", it.a, it.b, 0.1))
    return out


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_labels_overlap_neither_vectors_arcs_nor_each_other(path):
    """Every shipped case, every space/velocity/acceleration drawing and stage: no label box
    overlaps another label, and none touches a vector, link, input arc or offset."""
    sol, ds = solved(path)
    _assert_no_overlap(ds)


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_handout_stage_labels_set_larger_overlap_nothing_either(path):
    """The handout's stage figures (printed reduced) set their labels 1.5× larger: placed
    anew, they keep the same clearances."""
    from diagrams.figures import STAGE_TEXT_SCALE
    sol, _ = solved(path)
    ds = [d for d in diagrams.drawings(sol, stages=True, text_scale=STAGE_TEXT_SCALE)
          if d.kind != "space"]
    sizes = {t.size for d in ds for t in d.items() if isinstance(t, Text) and t.role == "vertex"
             and "inset" not in t.cls}
    assert sizes == {round(polygon.LABEL_SIZE * STAGE_TEXT_SCALE, 3)}
    _assert_no_overlap(ds)


def _assert_no_overlap(ds):
    for d in ds:
        boxes = _label_boxes(d)
        for i, (ta, a) in enumerate(boxes):
            for tb, b in boxes[i + 1:]:
                assert not a.grown(0.2).overlaps(b), f"{d.name}: labels {ta!r} and {tb!r} touch"
        strokes = _strokes(d)
        for t, b in boxes:
            for what, p, q, clearance in strokes:
                assert not box_hits_segment(b, p, q, clearance), \
                    f"{d.name}: label {t!r} touches {what}"


# ---------------------------------------------------------------- collinear vectors
def _collinear_overlaps(segments, tol=0.6, fraction=0.1):
    """Pairs of (name, (a, b)) segments (mm) on one line (the shorter's ends within ``tol`` of
    the longer's line) overlapping over more than ``fraction`` of the shorter's length."""
    out = []
    for i, (na, sa) in enumerate(segments):
        for nb, sb in segments[i + 1:]:
            (p0, p1), (q0, q1) = sorted((sa, sb), key=lambda s: -math.dist(*s))
            L, short = math.dist(p0, p1), math.dist(q0, q1)
            if short < 0.05:
                continue
            u = ((p1[0] - p0[0]) / L, (p1[1] - p0[1]) / L)
            off = [abs((q[0] - p0[0]) * u[1] - (q[1] - p0[1]) * u[0]) for q in (q0, q1)]
            along = sorted((q[0] - p0[0]) * u[0] + (q[1] - p0[1]) * u[1] for q in (q0, q1))
            common = min(L, along[1]) - max(0.0, along[0])
            if max(off) <= tol and common > fraction * short:
                out.append((na, nb, round(common / short, 2)))
    return out


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_no_two_vectors_overlap_on_one_line(path):
    """Read back from the written SVG (the arrows' translations included), no two vectors of a
    polygon (finished or any stage) lie on one line over more than a tenth of the shorter: the
    shorter is drawn beside the other, joined to its vertices by two thin leader ticks."""
    sol, ds = solved(path)
    for d in ds:
        if d.kind == "space":
            continue
        r = measure.read_svg(svg_of(d))
        segs = [(f"{v.frm}{v.to}", v.drawn) for v in r.vectors]
        assert not _collinear_overlaps(segs), (d.name, _collinear_overlaps(segs))
        ticks = [it for it in d.items() if isinstance(it, Segment) and it.cls.startswith("leader")]
        moved = [a for a in d.items() if isinstance(a, Arrow) and a.shift != (0.0, 0.0)]
        assert len(ticks) == 2 * len(moved), d.name
        for a in moved:    # moved square to itself by a whole number of offsets
            n = math.hypot(*a.shift)
            along = (a.shift[0] * (a.tip[0] - a.tail[0]) + a.shift[1] * (a.tip[1] - a.tail[1]))
            assert abs(along) < 0.01 * _len_mm(a) + 1e-3, (d.name, a.name)
            assert n / crowd.OFFSET == pytest.approx(round(n / crowd.OFFSET), abs=1e-3)


def _len_mm(a):
    return math.dist(a.tail, a.tip)


@pytest.mark.parametrize("case, pairs", [
    ("s000-d225-2003-q3", {"velocity": ("oa1", "oc"), "acceleration": ("oa1", "oc")}),
    ("s001-sae4-q3", {"velocity": ("ab", "ad")})])
def test_the_collinear_check_bites_where_the_books_vectors_lie_on_one_line(case, pairs):
    """Where the vectors lie (vertex to vertex, as before they were moved), D225's oa₁ lies on
    oc and SAE4-Q3's ab on ad: the check finds them, so it can fail; drawn, they do not."""
    sol, ds = solved(CASES / f"{case}.toml")
    for kind, (x, y) in pairs.items():
        r = measure.read_svg(to_svg(finals(ds)[kind]))
        raw = _collinear_overlaps([(f"{v.frm}{v.to}", (v.tail, v.tip)) for v in r.vectors])
        assert any({a, b} == {x, y} for a, b, _ in raw), (kind, raw)
        assert not _collinear_overlaps([(f"{v.frm}{v.to}", v.drawn) for v in r.vectors])
        moved = {f"{v.frm}{v.to}" for v in r.vectors if v.shift != (0.0, 0.0)}
        assert x in moved and y not in moved     # the shorter one moves


def test_a_flat_image_draws_no_side_over_its_vectors():
    """SAE4-Q3's D lies on AB produced and D225's C on BA₁: their images are flat, so no image
    side is drawn on top of the vectors; a proper image triangle keeps its side."""
    for case in ("s001-sae4-q3", "s000-d225-2003-q3"):
        sol, ds = solved(CASES / f"{case}.toml")
        for kind in ("velocity", "acceleration"):
            assert not [s for s in finals(ds)[kind].items() if isinstance(s, Segment)
                        and "image-side" in s.cls], (case, kind)
    sides = [s for path in FILES for d in finals(solved(path)[1]).values() for s in d.items()
             if isinstance(s, Segment) and "image-side" in s.cls]
    assert len(sides) >= 4


# ---------------------------------------------------------------- tight clusters: insets
def _vertex_height(lay):
    from diagrams.text import ASCENT, DESCENT
    return (ASCENT + DESCENT) * lay.size(polygon.LABEL_SIZE)


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_vertices_closer_than_a_label_are_drawn_again_enlarged(path):
    """Every two vertices of a finished polygon drawn nearer each other than a vertex label
    is tall (but not at one place) lie in a ringed cluster drawn again k × in an inset,
    where they stand at least a label's height apart, each at c + k (p − c)."""
    from diagrams.crowd import clusters
    sol, ds = solved(path)
    for kind, d in finals(ds).items():
        if kind == "space":
            continue
        lay = d.meta["layout"]
        h = _vertex_height(lay)
        pts = measure.read_svg(svg_of(d)).vertices      # as written, page coordinates
        off = d.meta["content_offset"]
        names = sorted(pts)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                dist = math.dist(pts[a], pts[b])
                if not 0.6 <= dist < h:
                    continue
                ins = next((x for x in lay.insets if a in x.names and b in x.names), None)
                assert ins is not None, (d.name, a, b, dist)
                assert ins.k * dist >= h, (d.name, a, b)
        assert len(lay.insets) == len(clusters({n: lay.P(v) for n, v in
                                                lay.con.vertices.items()}, h))
        for ins in lay.insets:
            dots = [c for c in d.items("inset") if isinstance(c, Circle)
                    and c.cls == "inset-vertex"]
            for n in ins.names:
                p = pts[n]
                want = (ins.C[0] + off[0] + ins.k * (p[0] - ins.c[0] - off[0]),
                        ins.C[1] + off[1] + ins.k * (p[1] - ins.c[1] - off[1]))
                assert any(math.dist(c.centre, want) < 0.01 for c in dots), (d.name, n)
            caption = [t.text for t in d.items("inset") if isinstance(t, Text)
                       and t.role == "inset"]
            assert caption == [f"detail ×{ins.k}"]


def test_the_watt_six_bars_cluster_e_f_f1_gets_an_inset_and_output_stays_deterministic(
        tmp_path):
    """Watt II's a-diagram puts e, f₁ and f within 2.6 mm (f₁f is 0.8 mm): ringed and drawn
    ×8 beside the polygon; the SVGs are byte-identical run to run."""
    sol, ds = solved(CASES / "new-watt-six-bar.toml")
    lay = finals(ds)["acceleration"].meta["layout"]
    assert [(i.names, i.k) for i in lay.insets] == [(("e", "f", "f1"), 8)]
    assert not finals(ds)["velocity"].meta["layout"].insets
    path = CASES / "new-watt-six-bar.toml"
    a = diagrams.write(solve(load_scene(path)), tmp_path / "a")
    b = diagrams.write(solve(load_scene(path)), tmp_path / "b")
    for p, q in zip(a, b):
        assert p.read_bytes() == q.read_bytes(), p.name
    assert b"detail \xc3\x978" in (tmp_path / "a" / "acceleration.svg").read_bytes()


def test_a_polygon_collapsed_to_the_pole_says_so():
    """Starting from rest every velocity is zero: no cluster to enlarge, a note instead."""
    sol, ds = solved(CASES / "rest-slider-crank.toml")
    d = finals(ds)["velocity"]
    assert not d.meta["layout"].insets
    assert any("Every vertex lies at the pole" in t.text for t in d.items("legend"))
    assert not any("Every vertex lies at the pole" in t.text
                   for t in finals(ds)["acceleration"].items("legend"))


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_legend_caption_and_drawing_do_not_overlap(path):
    sol, ds = solved(path)
    for d in ds:
        regions = {}
        for g in d.groups:
            boxes = [text_box(t.x, t.baseline, t.text, t.size, t.anchor)
                     for t in g.items if isinstance(t, Text)]
            if boxes and g.cls in ("legend", "caption", "heading"):
                bx = boxes[0]
                for b in boxes[1:]:
                    bx = bx.union(b)
                regions[g.cls] = bx
        drawn = [(it.tail, it.tip) if isinstance(it, Arrow) else (it.a, it.b)
                 for it in d.items() if isinstance(it, Arrow)
                 or (isinstance(it, Segment) and it.style != "scalebar")]
        for name, region in regions.items():
            assert 0 <= region.x0 and region.x1 <= d.width + 0.5, (d.name, name)
            for a, b in drawn:
                assert not box_hits_segment(region, a, b), (d.name, name)


# ---------------------------------------------------------------- scale
def test_round_scales():
    assert scale.round_up(0.0137) == 0.02
    assert scale.round_up(2.1) == 2.5
    assert scale.round_up(2.5) == 2.5
    assert scale.round_up(7) == 10
    assert scale.parse("1 cm = 2 m/s", "velocity").statement == "1 cm = 2 m/s"
    assert scale.parse("500 m/s^2", "acceleration").statement == "1 cm = 500 m/s²"
    assert scale.parse("2 cm = 1 m/s", "velocity").per_cm == pytest.approx(0.5)
    assert scale.parse("20 mm", "length").statement == "1 cm = 20 mm"
    assert scale.make("velocity", 0.05).statement == "1 cm = 50 mm/s"


@pytest.mark.parametrize("bad", ["2", "2 m", "-1 m/s", "0 m/s", "1 cm = x", "fast"])
def test_bad_scales_are_polygons_errors(bad):
    with pytest.raises(scale.ScaleError) as exc:
        scale.parse(bad, "velocity")
    assert isinstance(exc.value, PolygonsError)


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_scales_are_round_and_polygons_fit_the_paper(path):
    sol, ds = solved(path)
    for kind, d in finals(ds).items():
        m = re.fullmatch(r"1 cm = ([0-9.]+) (\S+)", d.scale_statement)
        value = float(m.group(1))
        mant = value / 10 ** math.floor(math.log10(value))
        assert any(math.isclose(mant, r) for r in scale.ROUND), d.scale_statement
        if kind == "space":
            continue
        lay = d.meta["layout"]
        f = lay.frame
        w, h = f.x1 - f.x0 - 2 * polygon.FRAME_MARGIN, f.y1 - f.y0 - 2 * polygon.FRAME_MARGIN
        a4 = scale.PAPER["A4"]
        assert (w <= a4[0] + 1e-6 and h <= a4[1] + 1e-6) or \
               (w <= a4[1] + 1e-6 and h <= a4[0] + 1e-6), (kind, w, h)
        # not needlessly small (unless everything is at rest: a polygon of one point)
        assert max(w, h) > 0.3 * a4[1] or max(w, h) == 0, (kind, w, h)


def test_a_forced_scale_is_used_and_stated():
    sol, _ = solved(CASES / "s003-fig7.toml")
    forced = {"velocity": scale.parse("0.05 m/s", "velocity")}
    ds = diagrams.drawings(sol, forced, stages=False)
    vel = finals(ds)["velocity"]
    assert vel.scale_statement == "1 cm = 50 mm/s"
    r = measure.read_svg(to_svg(vel))
    v = next(v for v in r.vectors if (v.frm, v.to) == ("o2", "p2"))
    assert v.mm == pytest.approx(1.0471975511965979 / 0.05 * 10, abs=0.01)


def test_scene_diagram_table_forces_scale_and_rejects_typos():
    text = (CASES / "s001-we4.toml").read_text()
    data = __import__("tomllib").loads(text)
    data["diagram"] = {"acceleration_scale": "1 cm = 250 m/s^2", "paper": "A4"}
    sol = solve(parse_scene(data, file="we4.toml"))
    acc = finals(diagrams.drawings(sol, stages=False))["acceleration"]
    assert acc.scale_statement == "1 cm = 250 m/s²"
    # [diagram] is checked when the scene is loaded (polygons.options), not when drawn
    data["diagram"] = {"acceleration_scal": "250 m/s^2"}
    with pytest.raises(UnknownKeyError, match="acceleration_scale"):
        parse_scene(data, file="we4.toml")
    data["diagram"] = {"velocity_scale": "250 m/s^2"}
    with pytest.raises(SceneError, match=r"diagram\.velocity_scale"):
        parse_scene(data, file="we4.toml")


# ---------------------------------------------------------------- scaled lengths
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_scaled_lengths_agree_with_the_tutorial_within_drawing_tolerance(path):
    sol, ds = solved(path)
    rows = measure.compare(sol, readings(path))
    for row in rows:
        if row.scaled is None or row.tutorial is None:
            continue
        if row.slip:
            assert not row.within, f"{row.quantity}: the drawing reproduces the slip"
        else:
            assert row.within, (f"{row.quantity}: scaled {row.scaled:.5g}, tutorial "
                                f"{row.tutorial} ({row.diff_pct:+.2f} %, ±{row.tolerance:.0%}"
                                f" + ruler {row.resolution:.3g})")


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_scaled_lengths_are_the_exact_values_to_a_ruler_division(path):
    sol, ds = solved(path)
    for row in measure.compare(sol, readings(path)):
        if row.scaled is None or row.exact is None:
            continue
        assert abs(row.scaled - row.exact) <= row.resolution + 1e-6 * abs(row.exact) + 1e-12, \
            (row.quantity, row.scaled, row.exact)
    # without the ruler's rounding the drawing gives the exact numbers to 0.01 %
    for row in measure.compare(sol, readings(path), ruler=None):
        if row.scaled is None or row.exact is None or row.exact == 0:
            continue
        if not row.quantity.startswith(("dir_", "angle")):
            assert row.scaled == pytest.approx(row.exact, rel=2e-4, abs=1e-9), row.quantity


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_senses_read_off_the_drawings_agree_with_the_tutorial(path):
    sol, ds = solved(path)
    rows = [r for r in measure.compare(sol, readings(path))
            if r.signed is not None and r.sense in ("CW", "CCW") and not r.slip
            and r.quantity.startswith(("omega", "alpha"))]
    for r in rows:
        assert (r.signed > 0) == (r.sense == "CCW"), (r.quantity, r.signed, r.sense)


def test_fig7_scaled_values():
    sol, ds = solved(CASES / "s003-fig7.toml")
    got = {(r.quantity, r.tutorial): r.scaled
           for r in measure.compare(sol, readings(CASES / "s003-fig7.toml"))}
    assert got[("v(P2)", 1.048)] == pytest.approx(1.045, abs=0.006)
    assert got[("cor(P2)", 1.96)] == pytest.approx(1.96, abs=0.015)
    assert got[("omega(O4P4)", 1.216)] == pytest.approx(1.216, rel=0.01)
    assert got[("alpha(O4P4)", 4.12)] == pytest.approx(4.12, rel=0.015)


# ---------------------------------------------------------------- determinism and rendering
def test_output_is_deterministic(tmp_path):
    path = CASES / "s003-fig7.toml"
    a = diagrams.write(solve(load_scene(path)), tmp_path / "a")
    b = diagrams.write(solve(load_scene(path)), tmp_path / "b")
    assert [p.name for p in a] == [p.name for p in b]
    for p, q in zip(a, b):
        assert p.read_bytes() == q.read_bytes(), p.name


def test_cairosvg_renders_the_fig7_diagrams_with_the_arrows_where_the_svg_says():
    cairosvg = pytest.importorskip("cairosvg")
    from PIL import Image
    sol, ds = solved(CASES / "s003-fig7.toml")
    for kind, d in finals(ds).items():
        data = to_svg(d)
        dpi = 254                       # 10 px per mm
        png = cairosvg.svg2png(bytestring=data, dpi=dpi)
        img = Image.open(io.BytesIO(png)).convert("L")
        assert img.size == (round(d.width * 10), round(d.height * 10))
        assert img.getextrema() == (0, 255)
        if kind == "space":
            continue
        r = measure.read_svg(data)
        look = {(a.frm, a.to): LOOKS[a.style[2:].removesuffix("-new")]
                for a in d.items() if isinstance(a, Arrow)}
        for v in r.vectors:
            if v.mm < 6:
                continue
            dark = 0      # points on the shaft, away from the vertices and arrowheads
            tail, tip = v.drawn          # where the ink is (moved beside a collinear one)
            for k in range(10):
                t = 0.3 + 0.03 * k
                x = tail[0] + t * (tip[0] - tail[0])
                y = tail[1] + t * (tip[1] - tail[1])
                px, py = x * 10, (d.height - y) * 10
                window = [img.getpixel((round(px) + i, round(py) + j))
                          for i in (-1, 0, 1) for j in (-1, 0, 1)]
                dark += min(window) < 170      # every component colour is darker in grey
            solid = look[(v.frm, v.to)].dash is None
            assert dark >= (10 if solid else 3), (kind, v)   # solid, or dashed/dotted


def test_styles_carry_meaning_without_colour():
    """One look per component kind, told apart in greyscale by width and dash pattern alone."""
    velocity = ("given", "relative", "sliding", "image", "resultant", "construction")
    acceleration = ("given", "centripetal", "tangential", "sliding", "coriolis", "image",
                    "resultant", "construction")
    for kinds in (velocity, acceleration):      # the kinds one diagram can show together
        assert len({(LOOKS[k].width, LOOKS[k].dash) for k in kinds}) == len(kinds)
    sol, ds = solved(CASES / "s003-fig7.toml")
    root = ET.fromstring(to_svg(finals(ds)["acceleration"]))
    def widths(kind):
        out = []
        for g in root.iter(SVG + "g"):
            cls = (g.get("class") or "").split()
            if cls[:1] == ["vector"] and kind in cls:
                line = next(g.iter(SVG + "line"))
                out.append((float(line.get("stroke-width")), line.get("stroke-dasharray")))
        return out
    assert widths("coriolis") and all(w > 0.8 and dash is None for w, dash in widths("coriolis"))
    assert widths("centripetal") and all(w < 0.6 and dash is None
                                         for w, dash in widths("centripetal"))
    assert widths("tangential") and all(dash for _, dash in widths("tangential"))
    assert all(dash for _, dash in widths("resultant"))       # the absolute vector is dotted
    heads = [g for g in root.iter(SVG + "g") if "coriolis" in (g.get("class") or "").split()]
    assert heads[0].find(f".//{SVG}polygon").get("fill") == "#ffffff"   # open head
    dashed = [l for l in root.iter(SVG + "line") if "construction-line" in (l.get("class") or "")]
    assert dashed and all(l.get("stroke-dasharray") for l in dashed)


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_every_drawing_has_a_key_of_what_it_draws(path):
    sol, ds = solved(path)
    for d in ds:
        keys = {t.text for t in d.items("key") if isinstance(t, Text)}
        assert "Key:" in keys, d.name
        if d.kind == "space":
            continue
        drawn = {a.style[2:].removesuffix("-new") for a in d.items() if isinstance(a, Arrow)}
        for kind in drawn:
            assert LOOKS[kind].name in keys, (d.name, kind)


def test_sae4_q3_closes_to_the_asked_od_and_a_d():
    """SAE4 Q3 asks v_D and a_D: od and the acceleration od are drawn from the pole, named
    and printed (exact 2.666 m/s and 440.3 m/s² from the closed-form check below)."""
    sol, ds = solved(CASES / "s001-sae4-q3.toml")
    f = finals(ds)
    import numpy as np
    vd, ad = (np.hypot(*sol.points["D"].velocity), np.hypot(*sol.points["D"].acceleration))
    # independent: D on AB produced, v_D = v_A + ω_AB × AD (loop closure of the rigid link)
    a, b, dpt = (np.array(sol.points[k].position) for k in "ABD")
    va, vb = np.array(sol.points["A"].velocity), np.array(sol.points["B"].velocity)
    t = np.linalg.norm(dpt - a) / np.linalg.norm(b - a)
    assert vd == pytest.approx(np.linalg.norm(va + t * (vb - va)), rel=1e-9)
    assert round(vd, 3) == 2.666 and round(ad, 1) == 440.3
    for kind, value, name in (("velocity", vd, "v_D"), ("acceleration", ad, "a_D")):
        d = f[kind]
        od = [x for x in d.items() if isinstance(x, Arrow) and (x.frm, x.to) == ("o", "d")]
        assert len(od) == 1, kind
        labels = {t.text for t in d.items() if isinstance(t, Text)}
        assert name in labels, kind
        legend = [t.text for t in d.items("legend") if isinstance(t, Text)]
        row = next(r for r in legend if r.startswith(f"o{JOIN}d ="))
        assert f"= {value:.4g}" in row and "asked" in row, row
        ad_row = next(r for r in legend if r.startswith(f"a{JOIN}d ="))
        assert name not in ad_row.split()[-1:]       # ad is D relative to A, not v_D


# ---------------------------------------------------------------- architecture
def test_svgwrite_is_imported_by_one_module_and_diagrams_do_not_redo_kinematics():
    importers = []
    for p in list((ROOT / "diagrams").glob("*.py")) + list((ROOT / "polygons").glob("*.py")):
        src = p.read_text()
        if re.search(r"^\s*(import svgwrite|from svgwrite)", src, re.M):
            importers.append(p.relative_to(ROOT).as_posix())
        if p.parent.name == "diagrams" and p.name != "plots.py":
            assert "theorems" not in src, p.name
    assert importers == ["diagrams/svg.py"]


# ---------------------------------------------------------------- command line
def test_cli_draw_writes_every_file_and_measures(tmp_path, capsys):
    out = tmp_path / "fig7"
    assert main(["draw", str(CASES / "s003-fig7.toml"), "-o", str(out)]) == 0
    names = sorted(p.name for p in out.iterdir())
    assert "space.svg" in names and "velocity.svg" in names and "acceleration.svg" in names
    assert "velocity-4.svg" in names and "acceleration-7.svg" in names
    capsys.readouterr()
    assert main(["draw", str(CASES / "s003-fig7.toml"), "-o", str(out), "--measure"]) == 0
    text = capsys.readouterr().out
    assert "velocity diagram: Scale 1 cm = " in text
    assert "within drawing tolerance" in text and "OUTSIDE" not in text


def test_cli_solve_svg_keeps_stdout_json(tmp_path, capsys):
    out = tmp_path / "we4"
    assert main(["solve", str(CASES / "s001-we4.toml"), "--json", "--svg", str(out),
                 "--no-stages"]) == 0
    import json
    json.loads(capsys.readouterr().out)
    assert sorted(p.name for p in out.iterdir()) == ["acceleration.svg", "space.svg",
                                                     "velocity.svg"]


@pytest.mark.parametrize("args, words", [
    (["--scale", "velocity=2"], "missing unit"),
    (["--scale", "speed=2 m/s"], "unknown diagram 'speed'"),
    (["--scale", "velocity"], "KIND=VALUE"),
    (["--scale", "velocity=1e-9 m/s"], "would be"),
])
def test_cli_bad_scale_is_one_line(tmp_path, capsys, args, words):
    code = main(["draw", str(CASES / "s003-fig7.toml"), "-o", str(tmp_path / "x")] + args)
    err = capsys.readouterr().err
    assert code == 1
    assert err.startswith("polygons: error: ") and err.count("\n") == 1 and words in err


def test_cli_output_folder_that_is_a_file(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("x")
    assert main(["draw", str(CASES / "s003-fig7.toml"), "-o", str(f)]) == 1
    assert "not a folder" in capsys.readouterr().err


@pytest.mark.parametrize("case,cw", [("s001-we6.toml", True), ("s001-sae4-q3.toml", False)])
def test_sweep_plot_axis_runs_in_the_cranks_sense_of_rotation(case, cw, monkeypatch, tmp_path):
    """A CW crank's angle decreases with time: its plot's x axis is reversed (and says so)."""
    import diagrams.plots as plots
    from polygons.cli.sweep import plot
    from polygons.sweep import sweep
    seen = {}

    def fake(title, xlabel, panels, stem, formats, markers, xlim, xticks, reverse_x=False):
        seen.update(xlabel=xlabel, reverse_x=reverse_x)
        return []
    monkeypatch.setattr(plots, "plot_panels", fake)
    scene = load_scene(CASES / case)
    assert (scene.driver.omega < 0) == cw            # the scene's own sense, read directly
    plot(sweep(scene, 12), [], [], {}, "mm", tmp_path / "x", ("png",))
    assert seen["reverse_x"] is cw
    assert ("axis reversed" in seen["xlabel"]) is cw


# ---------------------------------------------------------------- notation
def test_notation_typesets_textbook_labels():
    from diagrams import notation as n
    assert n.runs("p2_1") == [("p", "base"), ("2", "sub"), ("′", "base")]
    assert n.runs("a1") == [("a", "base"), ("1", "sub")]
    assert n.runs("(a_B)_A^n") == [("(a", "base"), ("B", "sub"), (")", "base"), ("A", "sub"),
                                   ("n", "sup")]
    assert n.runs("omega_BC") == [("ω", "base"), ("BC", "sub")]
    assert n.runs("(a_P4)^t")[-1] == ("t", "sup")
    assert n.plain(n.vector("b1", "b")) == "b₁b" and n.plain("p4_1") == "p₄′"
    assert n.html("(a_B)_A^n") == '(a<sub>B</sub>)<span class="subsup"><sub>A</sub><sup>n</sup></span>'
    # prose and units are left alone
    assert n.runs("1 cm = 20 m/s²") == [("1 cm = 20 m/s²", "base")]
    assert n.join_vectors("(= b1b / AB)", ["b", "b1", "a"]) == f"(= b1{JOIN}b / AB)"
    assert n.name_bare_omegas("ω² × CB = 2² × 0.1", {"CB": "BC"}) == "ω_BC² × CB = 2² × 0.1"
    # a stacked superscript adds only what is wider than its subscript
    assert n.width("(a_B)_A^n", 3.0) < n.width("(a_B)_A", 3.0) + n.width("n", 3.0 * n.SMALL)


def test_fig7_svg_typesets_vertex_labels_with_tspans():
    sol, ds = solved(CASES / "s003-fig7.toml")
    root = ET.fromstring(to_svg(finals(ds)["acceleration"]))
    labels = ["".join(t.itertext()) for t in root.iter(SVG + "text")
              if "vertex-label" in (t.get("class") or "")]
    assert "p2′" in labels and "p4′" in labels            # p₂′: 2 in a subscript tspan
    subs = [s for t in root.iter(SVG + "text") for s in t.iter(SVG + "tspan")
            if s.get("font-size") and float(s.get("font-size")) < float(t.get("font-size"))]
    assert subs and not any("_" in "".join(t.itertext()) for t in root.iter(SVG + "text")
                            if "vertex-label" in (t.get("class") or ""))


def test_a_wheel_rolling_on_the_ground_is_drawn_as_a_wheel_not_its_equivalent_slider():
    """The wheel's centre is a pin (no block in a hatched guide inside the wheel), the ground
    under it is hatched, and the links list says the wheel rolls (not 'W slides on a guide')."""
    sol = solve(load_scene(CASES / "rolling-wheel-driven.toml"))
    d = diagrams.drawings(sol, None, None, False)[0]
    classes = [it.cls for it in d.items() if hasattr(it, "cls")]
    assert not any(c.startswith("guide") for c in classes)
    hatch = [it for it in d.items() if isinstance(it, Segment) and it.style == "hatch"]
    assert len(hatch) >= 20            # the fixed ground's hatching (the crank's pivot has ~6)
    texts = [t.text for t in d.items("legend") if isinstance(t, Text)]
    assert any("wheel W" in t and "rolls without slipping" in t for t in texts)
    assert not any("W slides on a guide" in t for t in texts)


def test_the_coriolis_vector_is_drawn_once_and_its_stepped_back_copy_light():
    """Fig 7: one heavy 2ωv vector (p4 → p2′); the copy stepped back from p2 to place the offset
    line is a light construction stroke in the Coriolis colour, with its own key entry."""
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    acc = next(d for d in diagrams.drawings(sol, None, None, False) if d.name == "acceleration")
    heavy = [a for a in acc.items("vectors") if isinstance(a, Arrow) and "coriolis" in a.style]
    assert len(heavy) == 1
    light = [s for s in acc.items() if isinstance(s, Segment) and "offset" in s.cls.split()]
    assert light and all(s.style == "c-coriolis-aux" for s in light)
    assert LOOKS["coriolis-aux"].width < LOOKS["coriolis"].width / 2
    keys = [t.text for t in acc.items("key") if isinstance(t, Text)]
    assert any("stepped back" in t for t in keys)


def test_the_links_list_gives_the_fixed_link_as_the_title_does():
    """WE3's title gives AD 1 m: the space diagram lists AD = 1000 mm (fixed link) with AB, BC,
    DC; a link already named between two pivots is not listed twice."""
    sol = solve(load_scene(CASES / "s001-we3.toml"))
    d = diagrams.drawings(sol, None, None, False)[0]
    texts = [t.text for t in d.items("legend") if isinstance(t, Text)]
    assert "AD = 1000 mm (fixed link)" in texts
    assert sum("(fixed link)" in t for t in texts) == 1
