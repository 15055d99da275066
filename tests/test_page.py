"""The interactive page's data (diagrams.pagedata) and HTML (diagrams.page), without a browser.

The live polygons are the static construction at every frame: each arrow's ends are the
static drawing's vertices at the scene's own position, and at every frame the vertices of the
points are the sweep's velocities and accelerations (two interpreters of the construction:
the compiled float program and the vectorised sweep).  The slider starts exactly at the
scene's input; one box (one scale) holds each polygon over the whole cycle; a slotted lever is
drawn to its own point; user text is escaped.  (tests/test_browser.py drives the page.)
"""
import json
import math
import re

import numpy as np
import pytest

from conftest import CASES, case_files

import diagrams
from diagrams.page import fill, ordered, page, script_json
from diagrams.pagedata import frames, inputs
from polygons.evaluate import solve
from polygons.options import scale_per_cm
from polygons.scene import Crank, load_scene
from polygons.sweep import sweep
from diagrams.polygon import construction

N = 48


#: every case but a cam stated by its profile, which has no page (no sweep follows its
#: changing linkage: refused in one line, tests/test_cam_profiles.py)
@pytest.mark.parametrize("path", [f for f in case_files()
                                  if "[cam_profiles." not in f.read_text(encoding="utf-8")],
                         ids=lambda p: p.stem)
def test_live_polygons_are_the_construction_at_every_frame(path):
    scene = load_scene(path)
    sol = solve(scene)
    D = frames(sol, (), N)
    drv = scene.driver
    # the slider starts exactly at the scene's own input
    if isinstance(drv, Crank):
        assert D["inputs"][D["start"]] == pytest.approx(math.degrees(drv.angle) % 360, abs=1e-3)
    else:
        assert D["inputs"][D["start"]] == pytest.approx(drv.position * 1000, rel=1e-5)
    xs, start, _ = inputs(scene, N)
    assert start == D["start"] and len(xs) == len(D["inputs"])
    sw = sweep(scene, inputs=xs)           # the vectorised interpreter, independently
    for d, P in D["polys"].items():
        own = sol.vertices[d]
        size = max(math.hypot(*v) for v in own.values()) or 1.0
        assert P["strokes"], d
        static = {(st.frm, st.to) for st in construction(sol, d).strokes if st.kind == "arrow"}
        assert {(s["f"], s["t"]) for s in P["strokes"] if s["k"] == "arrow"} == static
        for s in P["strokes"]:           # at the scene's position: the static drawing's ends
            for v in (s["f"], s["t"]):
                assert math.dist(P["vx"][v][D["start"]], own[v]) <= 1e-5 * size, (d, v)
        rates = sw.vel if d == "velocity" else sw.acc
        x0, y0, x1, y1 = P["box"]
        for lab in scene.labels:
            v = sol.vertex_of(lab)
            if lab in scene.ground or v not in P["vx"] or rates.get(lab) is None:
                continue
            ref = np.asarray(rates[lab], dtype=float).T
            got = np.array(P["vx"][v], dtype=float)
            assert np.allclose(got, ref, rtol=1e-4, atol=1e-5 * size), (d, lab)
        # one box over the cycle (one scale) holds every frame but those near a toggle, where
        # the polygon is over 6 × its median size; the scene's own position is never one
        off = set(P["off"])
        assert D["start"] not in off and len(off) < len(D["inputs"]) // 4
        size = [max(math.hypot(*p) for p in (P["vx"][v][i] for v in P["vx"]))
                for i in range(len(D["inputs"]))]
        med = sorted(size)[len(size) // 2]
        assert all((size[i] > 6 * med) == (i in off) for i in range(len(size)))
        pts = np.array([ps[i] for ps in P["vx"].values() for i in range(len(ps))
                        if i not in off], dtype=float)
        tol = 1e-5 * max(x1 - x0, y1 - y0)
        assert (pts[:, 0] >= x0 - tol).all() and (pts[:, 0] <= x1 + tol).all()
        assert (pts[:, 1] >= y0 - tol).all() and (pts[:, 1] <= y1 + tol).all()
        assert {k["kind"] for k in P["key"]} == {s["c"] for s in P["strokes"]}
    for pin, slot in scene.slots.items():   # a lever is drawn to its own point, not the pin
        levers = [e for e in D["edges"] if e[2] == slot.lever]
        assert levers and all(pin not in e[:2] for e in levers)


def test_fig7_acceleration_in_components_and_lever_hover():
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    D = frames(sol, (), N)
    kinds = {s["c"] for s in D["polys"]["acceleration"]["strokes"]}
    assert {"centripetal", "tangential", "coriolis", "sliding"} <= kinds
    lever = {(s["f"], s["t"]) for d in ("velocity", "acceleration")
             for s in D["polys"][d]["strokes"] if s["link"] == "O4P4"}
    crank = {(s["f"], s["t"]) for d in ("velocity", "acceleration")
             for s in D["polys"][d]["strokes"] if s["link"] == "O2P2"}
    assert ("o2", "p4") in lever and ("o2", "p4_1") in lever and ("p4_1", "p4") in lever
    assert ("o2", "p2") not in lever and ("o2", "p2") in crank
    assert ["O4", "P4", "O4P4"] in D["edges"]
    assert D["polys"]["acceleration"]["pole_label"] == "o₂ = o₄"
    assert D["polys"]["acceleration"]["names"]["p4_1"] == "p₄′"


def test_stages_are_shown_in_construction_order():
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    names = [d.name for d in ordered(diagrams.drawings(sol))]
    assert names == (["space"] + [f"velocity-{k}" for k in range(1, 5)] + ["velocity"]
                     + [f"acceleration-{k}" for k in range(1, 8)] + ["acceleration"])


def test_drawing_mode_data_states_the_static_scale():
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    figs = diagrams.drawings(sol)
    D = frames(sol, figs, N)
    for f in figs:
        if f.stage is None and f.kind in D["drawing"]:
            g = D["drawing"][f.kind]
            lay = f.meta["layout"]
            assert scale_per_cm(g["scale"], f.kind) == pytest.approx(lay.scale.per_cm)
            assert g["statement"] == f.scale_statement
            assert set(g["vertices"]) == set(sol.vertices[f.kind]) and g["vertices"][0] == "o2"
            # the cursor starts where the whole polygon fits on the paper
            k = lay.scale.mm_per_si
            for x, y in sol.vertices[f.kind].values():
                px, py = g["cursor"][0] + x * k, g["cursor"][1] + y * k
                assert 0 <= px <= g["paper"][0] and 0 <= py <= g["paper"][1]
    assert D["drawing"]["acceleration"]["vectors"][:2] == [["o2", "p2"], ["o2", "p4_1"]]


def test_user_text_is_escaped_and_filled_in_one_pass(write_scene):
    text = (CASES / "s001-we1.toml").read_text(encoding="utf-8")
    hostile = 'A </script><script>alert(1)</script> & {CSS} {JS} <!-- "q"'
    text = re.sub(r'(?m)^title = .*$', lambda m: f"title = {json.dumps(hostile)}", text, count=1)
    path = write_scene(text)
    sol = solve(load_scene(path))
    html = page(sol, n=12)
    assert "<script>alert(1)" not in html and "<!-- \"q\"" not in html
    assert html.count("<script") == 2 and html.count("</script>") == 2
    assert "&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; {CSS} {JS}" in html
    blob = re.search(r'<script type="application/json" id="frames">(.*?)</script>', html,
                     re.S).group(1)
    assert "<" not in blob and json.loads(blob)["title"].endswith(hostile)
    assert fill("{A}{B}", {"A": "{B}", "B": "x"}) == "{B}x"
    assert json.loads(script_json({"t": "</script>"})) == {"t": "</script>"}


def test_velocity_only_scene(write_scene, tmp_path):
    """A scene that solves the velocity diagram only: the page has one live polygon and one
    polygon to draw."""
    text = (CASES / "s001-we1.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^(title = .*)$", r'\1\nsolve = ["velocity"]', text, count=1)
    sol = solve(load_scene(write_scene(text)))
    html = page(sol, n=12)
    data = json.loads(re.search(r'id="frames">(.*?)</script>', html, re.S).group(1))
    assert list(data["polys"]) == ["velocity"] and data["diagrams"] == ["velocity"]
    select = re.search(r'<select id="draw-diagram">(.*?)</select>', html, re.S).group(1)
    assert select.count("<option ") == 1
