"""The fused sweep kernel (polygons/fused.py): one function for the whole chain, its rates by the
lean Cartesian solve — compiled by numba, or its loops run over numpy slices — gives the arrays
program's results (the staged construction run on arrays) to 1e-12 of each quantity's scale:
positions, rates, ω, α, slides, margin, and NaN where the followed closure cannot be made; a
construction it does not make keeps the arrays program.  Each topology costs one numba
compile (~0.5–1 s): two here."""
from pathlib import Path

import numpy as np
import pytest

from polygons import jit
from polygons import sweep as sweep_mod
from polygons.fused import Unsupported, fused_of, generate
from polygons.scene import load_scene
from polygons.sweep import arrays_program, compile_plan, sweep
from test_compiled import _four_bar
from test_jit import _same_sweep

ROOT = Path(__file__).resolve().parent.parent
needs_numba = pytest.mark.skipif(not jit.available(), reason="numba is not installed")


@needs_numba
@pytest.mark.parametrize("case, primitives", [
    # (circle-circle: the four-bar below; rotation and circle-line: tests/test_jit.py's
    # slider-crank, whose numba sweep is this kernel)
    ("new-elliptic-trammel", "a translation driver, a circle and a fixed line, a rigid image"),
])
def test_the_fused_kernel_is_the_staged_construction_on_arrays(case, primitives, monkeypatch):
    scene = load_scene(str(ROOT / "cases" / f"{case}.toml"))
    prog = compile_plan(scene)
    assert fused_of(prog, arrays_program(prog)[0].index) is not None, primitives
    x0 = prog.input0
    xs = x0 + (np.linspace(-0.5, 0.5, 601) if prog.input_kind == "crank"
               else np.linspace(-0.05, 0.05, 601) * prog.scale)
    fused_numpy, fused_numba = sweep(scene, inputs=xs), sweep(scene, inputs=xs, jit=True)
    monkeypatch.setattr(sweep_mod, "FUSED_NUMPY", False)
    staged = sweep(scene, inputs=xs)
    _same_sweep(staged, fused_numba)
    _same_sweep(staged, fused_numpy)


@needs_numba
def test_where_the_four_bar_cannot_close_all_give_nan_and_the_same_margin(monkeypatch):
    scene = _four_bar(0.5, 0.2, 0.3, 0.25, 0.5, 10.0, 3.0)   # closes over part of a turn only
    xs = np.linspace(0.0, 2 * np.pi, 1001)
    b, c = sweep(scene, inputs=xs), sweep(scene, inputs=xs, jit=True)
    monkeypatch.setattr(sweep_mod, "FUSED_NUMPY", False)
    a = sweep(scene, inputs=xs)
    assert np.isnan(a.pos["C"][0]).any() and not np.isnan(a.pos["C"][0]).all()
    for fused in (b, c):
        _same_sweep(a, fused)
        assert np.array_equal(np.isnan(a.omega["BC"]), np.isnan(fused.omega["BC"]))


def test_a_construction_it_does_not_make_is_named_and_left_to_the_arrays_program():
    prog = compile_plan(load_scene(str(ROOT / "cases" / "s003-fig7.toml")))
    with pytest.raises(Unsupported, match="PinInSlot"):
        generate(prog, arrays_program(prog)[0].index)
    assert fused_of(prog, arrays_program(prog)[0].index) is None


def test_without_numba_the_numpy_loops_serve(monkeypatch):
    monkeypatch.setattr(jit, "available", lambda: False)
    prog = compile_plan(_four_bar(0.5, 0.1, 0.4, 0.3, 1.0, 10.0, 0.0))
    assert fused_of(prog, arrays_program(prog)[0].index) is None
    assert fused_of(prog, arrays_program(prog)[0].index, arrays=True) is not None
    assert sweep_mod.run(prog, np.array([0.1, 0.2]), jit=True)["omega"]["BC"].shape == (2,)
