"""Large generated mechanisms (benchmarks/large.py): a 61-link truss and a chain of RRR dyads
solve and close their loops; past the documented size the scene is refused before any work."""
from __future__ import annotations

import importlib.util
import math

import pytest

from conftest import ROOT
from polygons.errors import SceneError
from polygons.evaluate import solve
from polygons.scene import MAX_LINKS, load_scene

_spec = importlib.util.spec_from_file_location("large", ROOT / "benchmarks" / "large.py")
large = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(large)


def _closes(sol, scene):
    """Every link keeps its length; the velocity and acceleration loop equations of every
    link hold: (v_b − v_a)·(b − a) = 0, (a_b − a_a)·(b − a) + |v_b − v_a|² = 0."""
    pts = sol.points
    vmax = max(math.hypot(*p.velocity) for p in pts.values())
    amax = max(math.hypot(*p.acceleration) for p in pts.values())
    for name, link in scene.links.items():
        a, b = pts[link.a], pts[link.b]
        d = (b.position[0] - a.position[0], b.position[1] - a.position[1])
        dv = (b.velocity[0] - a.velocity[0], b.velocity[1] - a.velocity[1])
        da = (b.acceleration[0] - a.acceleration[0], b.acceleration[1] - a.acceleration[1])
        assert math.hypot(*d) == pytest.approx(link.length, rel=1e-12), name
        assert abs(dv[0] * d[0] + dv[1] * d[1]) <= 1e-11 * vmax * link.length, name
        assert abs(da[0] * d[0] + da[1] * d[1] + dv[0] ** 2 + dv[1] ** 2) \
            <= 1e-10 * amax * link.length, name


@pytest.mark.parametrize("kind, size", [("truss", 29), ("chain", 12)])
def test_generated_scene_solves_and_closes(write_scene, kind, size):
    text = large.scene_text(kind, size, loads=True)
    scene = load_scene(write_scene(text))
    assert len(scene.links) == large.links_of(kind, size) == (61 if kind == "truss" else 25)
    sol = solve(scene)
    _closes(sol, scene)
    # the positions are the generator's own (circle intersections, independent of polygons)
    for label, (x, y) in large.positions(kind, size).items():
        p = sol.points[label].position
        assert math.hypot(p[0] - x * 1e-3, p[1] - y * 1e-3) < 1e-9, label


def test_a_truss_moves_rigidly_with_its_coupler(write_scene):
    sol = solve(load_scene(write_scene(large.scene_text("truss", 29))))
    w = sol.links["BC"].omega
    assert all(sol.links[n].omega == pytest.approx(w, rel=1e-9)
               for n in sol.scene.links if n.startswith("T") or "T" in n[1:])


def test_larger_than_served_is_refused_before_work(write_scene):
    size = large.size_for_links("chain", MAX_LINKS + 1)
    path = write_scene(large.scene_text("chain", size))
    with pytest.raises(SceneError, match=f"at most {MAX_LINKS}"):
        load_scene(path)
    assert large.fit_exponent([10, 20, 40], [1.0, 2.0, 4.0]) == pytest.approx(1.0)


def test_the_label_grid_places_every_label_where_testing_every_obstacle_does(
        write_scene, monkeypatch):
    """diagrams.labels looks obstacles up in a grid from _GRID_FROM of them: the same labels,
    to the bit, as testing every obstacle for every candidate."""
    from diagrams import labels, polygon
    sol = solve(load_scene(write_scene(large.scene_text("truss", 4))))
    used, grid = [], labels._Grid
    monkeypatch.setattr(labels, "_Grid", type("Spy", (grid,), {
        "near": lambda self, lst, box, span: used.append(1) or grid.near(self, lst, box, span)}))

    def placed():
        lays = [polygon.layout(sol, d) for d in ("velocity", "acceleration")]
        return [(lay.vertex_labels, lay.line_labels, lay.vector_labels, lay.leaders,
                 lay.insets) for lay in lays]
    fast = placed()
    assert used                                  # the grid was used
    assert any(lay[3] for lay in fast)           # leaders tested (crossings, labels passed)
    # every obstacle tested, every stroke for a label's owner and a leader's crossings
    monkeypatch.setattr(labels, "_GRID_FROM", 10 ** 9)
    monkeypatch.setattr(labels.StrokeCells, "near", lambda self, box, reach: self.all)
    assert placed() == fast


def test_collinear_vectors_found_near_are_those_found_testing_every_pair(monkeypatch):
    """diagrams.crowd.shifts tests a vector against the placed ones filed under its cells:
    the same shifts as testing every placed vector, on fans and overlapping runs of vectors."""
    import random

    from diagrams import crowd
    rnd = random.Random(7)
    vecs = []
    for i in range(150):
        x, y = rnd.uniform(0, 80), rnd.uniform(0, 60)
        ang = rnd.choice([0.0, 0.5, 1.2, math.pi / 2]) + rnd.choice([0.0, 0.0, 0.004])
        L = rnd.choice([3.0, 10.0, 25.0, 60.0])
        if i % 3 == 0 and vecs:                  # on the line of an earlier one
            _, (x, y), (bx, by) = vecs[rnd.randrange(len(vecs))]
            ang = math.atan2(by - y, bx - x)
        vecs.append((i, (x, y), (x + L * math.cos(ang), y + L * math.sin(ang))))
    fast = crowd.shifts(vecs, (40.0, 30.0))
    assert len(fast) > 10
    monkeypatch.setattr(crowd._Placed, "_keys", staticmethod(lambda s, margin: None))
    assert crowd.shifts(vecs, (40.0, 30.0)) == fast


def _figures_counted(monkeypatch, sol):
    """diagrams.figures.figures(sol), how many polygons it laid out and spaces it drew, and
    the scale each diagram was first drawn to."""
    from diagrams import figures, polygon, space
    calls = {"layout": 0, "space": 0}
    first: dict = {}
    lay, draw = polygon.layout, space.drawing

    def laid(sol, diagram, *a, **k):
        calls["layout"] += 1
        out = lay(sol, diagram, *a, **k)
        first.setdefault(diagram, out.scale.statement)
        return out

    def drawn(*a, **k):
        calls["space"] += 1
        out = draw(*a, **k)
        first.setdefault("space", out.scale_statement)
        return out
    monkeypatch.setattr(polygon, "layout", laid)
    monkeypatch.setattr(space, "drawing", drawn)
    return figures.figures(sol), calls, first


def test_a_legend_taller_than_the_page_is_not_redrawn_at_ever_larger_scales(
        write_scene, monkeypatch):
    """41-link truss: the finished diagrams are laid out three times at most in all,
    and keep their first scale (it took 24 layouts, the polygons redrawn at up to 10⁴ × their
    scale, while the legend listed every vector: now it lists the asked ones beyond
    diagrams.polygon.MAX_LEGEND_LINES); its polygons have more than
    diagrams.MAX_STAGED_STEPS steps: no stage figures."""
    sol = solve(load_scene(write_scene(large.scene_text("truss", 19, loads=True))))
    figs, calls, first = _figures_counted(monkeypatch, sol)
    assert calls["space"] == 1 and calls["layout"] <= 3
    assert figs.rescaled == {} and sorted(figs.svg) == ["acceleration", "space", "velocity"]
    assert {n: d.scale_statement for n, d in figs.drawing.items()} == first


def test_a_diagram_is_not_rescaled_to_fit_until_it_is_a_dot(write_scene, monkeypatch):
    """21-link truss: the velocity polygon's labels and legend do not fit the page at any
    scale that leaves the polygon diagrams.figures.MIN_DRAWN_MM across (it was redrawn 12
    times, down to 1 cm = 200 m/s, 2000 × smaller): it keeps its first scale, and the
    handout prints it reduced, saying so."""
    from diagrams import figures
    from diagrams.handout import handout
    sol = solve(load_scene(write_scene(large.scene_text("truss", 9, loads=True))))
    figs, calls, first = _figures_counted(monkeypatch, sol)
    assert calls["layout"] <= 8                  # (3 of them for the stage figures)
    assert figs.drawing["velocity"].scale_statement == first["velocity"] == "1 cm = 0.1 m/s"
    for name in ("space", "velocity", "acceleration"):
        d = figs.drawing[name]
        if name in figs.rescaled:
            assert figures._drawn_mm(d)[0] >= figures.MIN_DRAWN_MM
        else:
            assert d.scale_statement == first[name]
    assert "Reduced to" in handout(sol, figs=figs)
    assert [figures.round_down(x) for x in (2.83, 10.0, 0.3, 0.0999, 7e-5)] == \
        [2.5, 10.0, 0.25, 0.05, 5e-5]


def test_check_grades_at_the_scale_the_diagrams_are_drawn_to():
    """polygons check reads the diagrams' scale without placing their labels."""
    from diagrams import polygon
    for case in ("s001-we1", "new-watt-six-bar", "s000-d225-2003-q3"):
        sol = solve(load_scene(ROOT / "cases" / f"{case}.toml"))
        for d in sol.scene.solve:
            assert polygon.scale_of(sol, d)[0] == polygon.layout(sol, d).scale


def test_svg_written_without_validation_is_what_validation_passes(monkeypatch):
    """svgwrite's validation is off when drawing (diagrams.svg.VALIDATE): the same bytes."""
    import diagrams
    from diagrams import svg
    sol = solve(load_scene(ROOT / "cases" / "s003-fig7.toml"))
    ds = diagrams.drawings(sol, stages=False)
    quick = [svg.to_svg(d) for d in ds]
    monkeypatch.setattr(svg, "VALIDATE", True)
    assert [svg.to_svg(d) for d in ds] == quick


def test_a_large_mechanism_legend_lists_the_asked_and_counts_the_rest(write_scene):
    """Beyond diagrams.polygon.MAX_LEGEND_LINES lines (a 41-link truss: ~80 vectors) a
    finished diagram's legend lists only the asked quantities and says how many it leaves
    out; every shipped case's legend is shorter and lists every vector."""
    from diagrams import polygon
    text = large.scene_text("truss", 19, loads=True) + \
        '\n[[answers]]\nquantity = "v(C)"\nunit = "m/s"\n'
    sol = solve(load_scene(write_scene(text)))
    lines = polygon.legend(polygon.layout(sol, "velocity"), sol)
    assert len(lines) <= polygon.MAX_LEGEND_LINES
    assert any("← asked" in t for t, _ in lines)
    more = [t for t, _ in lines if t.startswith("… and ")]
    assert len(more) == 1 and int(more[0].split()[2]) > polygon.MAX_LEGEND_LINES
    fig7 = solve(load_scene(ROOT / "cases" / "s003-fig7.toml"))
    assert not any(t.startswith("… and ") for t, _ in
                   polygon.legend(polygon.layout(fig7, "acceleration"), fig7))
