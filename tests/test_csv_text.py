"""The sweep's output: the CSV writer (polygons/csv_text.py) gives np.savetxt's '%.17g' bytes
on every kind of float64, the .npz holds every column exactly, and a sweep estimated above the
budget is refused before any work, naming the estimate and --large (issue 30 E, issue 31)."""
import importlib.util
import io
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import CASES
from polygons import csv_text
from polygons.cli import main
from polygons.cli import sweep as cli_sweep

DATA = Path(__file__).parent / "data"


def _savetxt(values) -> bytes:
    buf = io.BytesIO()
    np.savetxt(buf, np.asarray(values, float)[:, None], fmt="%.17g")
    return buf.getvalue()


def _awkward(n: int, seed: int = 0) -> np.ndarray:
    """Values across the whole float64 range: random bits, decimals, halves, powers of ten
    and their neighbours, zeros, subnormals, inf and NaN."""
    rng = np.random.default_rng(seed)
    bits = rng.integers(-2 ** 63, 2 ** 63 - 1, n).view(np.float64)
    p10 = 10.0 ** np.arange(-320, 309)
    return np.concatenate([
        bits, np.round(rng.uniform(-1e3, 1e3, n), 3), rng.standard_normal(n),
        rng.integers(-10 ** 6, 10 ** 6, n) / 8.0,                  # exact halves: ties to even
        rng.integers(-2 ** 53, 2 ** 53, n // 4) / 4.0,
        p10, -p10, np.nextafter(p10, 0), np.nextafter(p10, np.inf),
        [0.0, -0.0, np.inf, -np.inf, np.nan, 5e-324, -5e-324, 2.2250738585072014e-308,
         1.7976931348623157e308, 1e16, 1e17, 9007199254740993.0, 0.1, 1 / 3]])


def test_the_writer_in_python_gives_savetxt_bytes():
    """The formatter numba compiles, run as plain Python (the logic, with or without numba)."""
    x = _awkward(300)
    hi, lo, sc = csv_text._powers()
    out = np.empty(x.size * 25, np.uint8)
    dig = np.empty(17, np.int64)
    used = 0
    for v in x:
        used = csv_text._put(float(v), hi, lo, sc, out, used, dig)
        out[used] = 10
        used += 1
    assert out[:used].tobytes() == _savetxt(x)


@pytest.mark.skipif(importlib.util.find_spec("numba") is None, reason="numba not installed")
def test_the_compiled_writer_gives_savetxt_bytes_and_reads_back_exactly():
    x = _awkward(10_000, seed=1)
    got = csv_text.csv_rows([x], x.size, compiled=True)
    assert got == _savetxt(x)
    back = np.array([float(s) for s in got.split()])
    assert np.array_equal(back, x, equal_nan=True)
    # several columns and scalar columns: the commas and newlines of np.savetxt
    cols = [x[:5000], 0.0, -x[5000:10000], 1.5]
    buf = io.BytesIO()
    np.savetxt(buf, np.column_stack([np.broadcast_to(c, (5000,)) for c in cols]),
               delimiter=",", fmt="%.17g")
    assert csv_text.csv_rows(cols, 5000, compiled=True) == buf.getvalue()


def test_npz_holds_every_column_exactly_and_the_same_bytes_twice(tmp_path):
    x = _awkward(100, seed=2)
    cols = [x, -x, 0.0]
    for name in ("a.npz", "b.npz"):
        csv_text.write_npz(tmp_path / name, [("P.x", "m"), ("P.y", "m"), ("z", "1")], cols,
                           x.size)
    assert (tmp_path / "a.npz").read_bytes() == (tmp_path / "b.npz").read_bytes()
    with np.load(tmp_path / "a.npz") as d:
        assert list(d["columns"]) == ["P.x", "P.y", "z"] and list(d["units"]) == ["m", "m", "1"]
        assert np.array_equal(d["data"][:, 0], x, equal_nan=True)
        assert np.array_equal(d["data"][:, 1], -x, equal_nan=True)
        assert not d["data"][:, 2].any()


@pytest.mark.parametrize("stream", [False, True])
def test_sweep_npz_has_every_point_and_link(stream, tmp_path, monkeypatch, capsys):
    if stream:
        monkeypatch.setattr(cli_sweep, "STREAM_FROM", 100)
    args = ["sweep", str(CASES / "s001-we6.toml"), "--steps", "500", "--no-plot"]
    assert main(args + ["--out", str(tmp_path / "csv")]) == 0
    assert main(args + ["--npz", "--out", str(tmp_path / "npz")]) == 0
    capsys.readouterr()
    head = (tmp_path / "csv" / "s001-we6-sweep.csv").read_text().splitlines()
    rows = np.loadtxt(head[1:], delimiter=",")
    with np.load(tmp_path / "npz" / "s001-we6-sweep.npz") as d:
        names = [f"{c} [{u}]" for c, u in zip(d["columns"], d["units"])]
        data = d["data"]
    assert data.shape[0] == 500
    for j, col in enumerate(head[0].split(",")):          # the CSV's columns, exactly
        assert np.array_equal(data[:, names.index(col)], rows[:, j], equal_nan=True)
    assert len(names) > len(head[0].split(","))           # and more: every point and link


def test_a_sweep_above_the_budget_is_refused_before_any_work(tmp_path, capsys):
    """The documented maximum (10^7 steps) in an eight-bar with a triad: ~7.8 GB of CSV."""
    out = tmp_path / "out"
    assert main(["sweep", str(DATA / "triad-eight-bar-max-steps.toml"), "--no-plot",
                 "--out", str(out)]) != 0
    err = capsys.readouterr().err
    assert "would write about" in err and "GB of CSV" in err and "--large" in err
    assert "10,000,000 rows × 37 columns" in err
    assert not out.exists()                               # refused before any work


def test_the_estimate_names_npz_size():
    from polygons.scene import load_scene
    sc = load_scene(CASES / "s001-we6.toml")
    opt = dict(points=None, links=None, steps=1_000_000, npz=False)
    _, size_csv, secs, m = cli_sweep.estimate(sc, opt)
    _, size_npz, _, m_all = cli_sweep.estimate(sc, dict(opt, npz=True))
    assert size_csv == 1_000_000 * m * cli_sweep.VALUE_BYTES["csv"]
    assert size_npz == 1_000_000 * m_all * 8 and m_all > m
    assert 0 < secs < 3600
