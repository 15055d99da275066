"""The optional numba backend (polygons/jit.py): the same generated code compiled to machine
code gives the staged solve's steps and the numpy sweep's arrays to 1e-12 of each quantity's
scale, fails as the Python program does, and is skipped cleanly where numba is missing.

numba compiles every topology anew (~1–2 s each), so by default three topologies are checked
(a four-bar, an offset slider-crank, a slotted-lever quick return); ``POLYGONS_JIT_ALL=1``
checks every shipped case (minutes)."""
import math
import os
from pathlib import Path

import numpy as np
import pytest

from polygons import jit
from polygons.compiled import compile_scene
from polygons.errors import AssemblyError, ParallelLinesError
from polygons.evaluate import solve
from polygons.scene import load_scene
from polygons.sweep import sweep
from test_compiled import _four_bar, assert_same_steps

ROOT = Path(__file__).resolve().parent.parent
REL = 1e-12
ALL = os.environ.get("POLYGONS_JIT_ALL") == "1"
CASES = (sorted((ROOT / "cases").glob("*.toml")) if ALL else
         [ROOT / "cases" / f"{c}.toml" for c in ("s001-we2", "s003-fig7")])

needs_numba = pytest.mark.skipif(not jit.available(), reason="numba is not installed")


def test_without_numba_the_python_program_is_kept(monkeypatch):
    monkeypatch.setattr(jit, "available", lambda: False)
    monkeypatch.setattr(jit, "_MADE", {})   # (a kernel an earlier test in this worker made)
    scene = _four_bar(0.5, 0.1, 0.4, 0.3, 1.0, 10.0, 0.0)
    prog = compile_scene(scene, jit=True)
    assert prog.fn is prog.code.fn and isinstance(prog.params, tuple)
    assert sweep(scene, inputs=[0.1, 0.2], jit=True).omega["BC"].shape == (2,)


def _same_sweep(a, b):
    for key in ("pos", "vel", "acc", "coriolis"):
        for lab, xy in getattr(a, key).items():
            if xy is None:
                assert getattr(b, key)[lab] is None
                continue
            x, y = np.asarray(xy, dtype=float), np.asarray(getattr(b, key)[lab], dtype=float)
            scale = max(float(np.nanmax(np.abs(v))) for v in getattr(a, key).values()
                        if v is not None)
            assert np.array_equal(np.isnan(x), np.isnan(y)), (key, lab)
            assert float(np.nanmax(np.abs(x - y), initial=0.0)) <= REL * scale, (key, lab)
    for key in ("omega", "alpha", "slide_v", "slide_a", "travel"):
        for lab, v in getattr(a, key).items():
            w = getattr(b, key)[lab]
            scale = max(1.0, float(np.nanmax(np.abs(v), initial=0.0)))
            assert float(np.nanmax(np.abs(np.asarray(v) - np.asarray(w)), initial=0.0)) \
                <= REL * scale, (key, lab)
    assert np.allclose(a.margin, b.margin, rtol=0, atol=1e-12, equal_nan=True)


@needs_numba
def test_a_four_bar_by_numba_is_the_staged_construction_and_fails_alike():
    prog = compile_scene(_four_bar(0.5, 0.1, 0.4, 0.3, 1.0, 10.0, 50.0), jit=True)
    assert prog.fn is not prog.code.fn
    for theta in (0.3, 2.0, 4.0):
        staged = solve(_four_bar(0.5, 0.1, 0.4, 0.3, theta, 10.0, 50.0))
        sol = prog.solve(theta)
        assert_same_steps(staged.steps, sol.steps)
        assert type(sol.omega("BC")) is float
    wide = compile_scene(_four_bar(0.5, 0.2, 0.3, 0.25, 0.5, 10.0, 0.0), jit=True)
    with pytest.raises(AssemblyError, match="cannot close"):
        wide.solve(math.pi)
    toggle = compile_scene(_four_bar(0.5, 0.2, 0.1, 0.2, 0.0, 10.0, 0.0), jit=True)
    with pytest.raises(ParallelLinesError) as err:
        toggle.solve()
    with pytest.raises(ParallelLinesError) as py:
        compile_scene(toggle.scene).solve()
    assert err.value.step == py.value.step


@needs_numba
@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_numba_matches_the_staged_solve_and_the_numpy_sweep(path):
    scene = load_scene(str(path))
    prog = compile_scene(scene, jit=True)
    if prog.fn is prog.code.fn:
        pytest.skip(f"{path.name}: numba does not compile this construction (Python kept)")
    sol = prog.solve()
    assert_same_steps(solve(scene).steps, sol.steps, scene)
    xs = prog.x0 + np.linspace(-0.5, 0.5, 181)
    _same_sweep(sweep(scene, inputs=xs), sweep(scene, inputs=xs, jit=True))
