"""Streamed sweeps (polygons.sweep.stream, polygons/cli/_stream.py): the same CSV as the
in-memory sweep, byte for byte, and the same maxima, computed chunk by chunk."""
import numpy as np
import pytest

from conftest import CASES
from polygons.cli import main
from polygons.cli import sweep as cli_sweep
from polygons.scene import load_scene
from polygons.streams import Extremes, plan_stream, stream
from polygons.sweep import sweep


@pytest.mark.parametrize("case", ["s001-we6.toml", "s001-we3.toml", "s003-fig7.toml",
                                  "scotch-yoke.toml", "new-collar-on-rotating-rod.toml",
                                  "new-offset-slot.toml", "new-oscillating-cylinder.toml",
                                  "new-rotary-engine.toml", "new-slot-on-moving-lever.toml"])
def test_streamed_chunks_are_the_in_memory_sweep(case):
    scene = load_scene(CASES / case)
    n = 1000
    st = plan_stream(scene, n)
    assert st.code is not None          # compiled for arrays
    sw = sweep(scene, n)
    assert np.array_equal(st.inputs(0, n), sw.inputs)
    got = 0
    for s, xs, res in stream(st, chunk=300):         # chunks not aligned with anything
        e = s + len(xs)
        got += len(xs)
        for lab, xy in res["vel"].items():
            if xy is not None:
                np.testing.assert_array_equal(np.broadcast_to(xy[0], xs.shape),
                                              sw.velocity(lab)[s:e, 0])
        for name, w in res["alpha"].items():
            np.testing.assert_array_equal(np.broadcast_to(w, xs.shape), sw.alpha[name][s:e])
    assert got == n


def test_extremes_on_the_stream_are_the_maxima_of_the_whole_sweep():
    scene = load_scene(CASES / "s001-we6.toml")
    n = 5000
    st = plan_stream(scene, n)
    ext = Extremes()
    for _, xs, res in stream(st, chunk=777):
        ext.add_chunk(xs, res)
    sw = sweep(scene, n)
    V = sw.velocity("C")
    vm = np.hypot(V[:, 0], V[:, 1])
    i = int(np.argmax(vm))
    assert ext.max["v:C"][0] == pytest.approx(vm[i], rel=1e-15)
    assert ext.max["v:C"][1] == sw.inputs[i]
    j = int(np.argmax(np.abs(sw.alpha["BC"])))
    assert ext.max["alpha:BC"] == (abs(sw.alpha["BC"][j]), sw.inputs[j])
    assert ext.min_angle[0] == pytest.approx(float(np.nanmin(sw.angle_deg)), rel=1e-12)
    assert ext.n == n and ext.bad == 0


@pytest.mark.parametrize("case", ["s001-we6.toml", "s001-we3.toml", "s001-we1.toml"])
def test_streamed_command_writes_the_same_csv_and_maxima(case, tmp_path, monkeypatch, capsys):
    args = ["sweep", str(CASES / case), "--steps", "3000", "--no-plot"]
    assert main(args + ["--out", str(tmp_path / "mem")]) == 0
    whole = capsys.readouterr().out
    monkeypatch.setattr(cli_sweep, "STREAM_FROM", 100)
    assert main(args + ["--out", str(tmp_path / "stream")]) == 0
    streamed = capsys.readouterr().out
    name = case.replace(".toml", "-sweep.csv")
    assert (tmp_path / "stream" / name).read_bytes() == (tmp_path / "mem" / name).read_bytes()
    assert "streamed" in streamed
    # every link's maxima line is the same text (same maxima, same input where they occur)
    links = [ln for ln in whole.splitlines() if ln.startswith("link ")]
    assert links and links == [ln for ln in streamed.splitlines() if ln.startswith("link ")]
