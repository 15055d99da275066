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
        lay = polygon.layout(sol, "velocity")
        return lay.vertex_labels, lay.line_labels, lay.vector_labels
    fast = placed()
    assert used                                  # the grid was used
    monkeypatch.setattr(labels, "_GRID_FROM", 10 ** 9)
    assert placed() == fast


def test_svg_written_without_validation_is_what_validation_passes(monkeypatch):
    """svgwrite's validation is off when drawing (diagrams.svg.VALIDATE): the same bytes."""
    import diagrams
    from diagrams import svg
    sol = solve(load_scene(ROOT / "cases" / "s003-fig7.toml"))
    ds = diagrams.drawings(sol, stages=False)
    quick = [svg.to_svg(d) for d in ds]
    monkeypatch.setattr(svg, "VALIDATE", True)
    assert [svg.to_svg(d) for d in ds] == quick
