"""The class-III group's position stated once (polygons/dyads/triad.py: ``construction``, a
TriadClosure then an AssurPoint): the staged solve, the compiled program, the numpy sweep
(the generated program over arrays) and the group's ``locate`` (that statement evaluated,
polygons/dyads/numeric.py) place every point of every triad case within 1e-12 of the
mechanism's size, at the scene's input and at ten inputs about it."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from polygons.compiled import compile_scene
from polygons.evaluate import solve
from polygons.scene import load_scene
from polygons.sweep import compile_plan, place, sweep

ROOT = Path(__file__).resolve().parents[1] / "cases"
TRIADS = sorted(ROOT.glob("triad-*.toml")) + sorted(ROOT.glob("forces-triad*.toml"))


def _col(a, i):
    a = np.asarray(a, dtype=float).reshape(2, -1)
    return a[:, i if a.shape[1] > 1 else 0]


@pytest.mark.parametrize("path", TRIADS, ids=[p.stem for p in TRIADS])
def test_every_interpreter_places_the_triad_alike(path):
    scene = load_scene(path)
    staged = solve(scene)
    prog = compile_scene(scene)
    xs = prog.x0 + np.linspace(-0.05, 0.05, 11)          # xs[5] is the scene's input
    sw = sweep(scene, inputs=xs)                          # the generated program over arrays
    located, _ = place(compile_plan(scene), xs)           # each group's locate over arrays
    size = max(float(np.max(np.abs(p.position))) for p in staged.points.values())
    worst = 0.0
    for i, x in enumerate(xs):
        one = prog.solve(float(x))                        # the compiled program, floats
        for lab, p in staged.points.items():
            ref = np.array(one.position(lab))
            got = [_col(sw.pos[lab], i), _col(located[lab], i)]
            if i == 5:
                got.append(np.array(p.position))
            worst = max([worst] + [float(np.max(np.abs(g - ref))) for g in got])
    assert worst <= 1e-12 * size


def test_a_batch_of_varied_plates_is_placed_alike_by_both_engines():
    """The batch's 'located' engine (each group's locate over the rows' varied lengths: the
    statement run over arrays, triad_cols) and its compiled one give the same corners."""
    from polygons.batch import solve_many
    scene = load_scene(ROOT / "triad-ternary-coupler.toml")
    v = {"BX": scene.links["BX"].length * np.array([0.99, 1.0, 1.01])}
    a, b = solve_many(scene, v, engine="compiled"), solve_many(scene, v, engine="located")
    assert a.ok.all() and b.ok.all()
    for lab in ("B", "C", "X"):
        assert np.max(np.abs(np.asarray(a.position(lab)) - np.asarray(b.position(lab)))) <= 1e-12
