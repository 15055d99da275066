"""The staged solve's rows alone, quickly: ``python benchmarks/staged.py [--repeat N]``.

The same protocol as ``benchmarks/run.py`` (:func:`protocol.single_position`: the S001-WE6
four-bar at 64 crank angles, warm, interleaved, best of ``--repeat`` loops) with only the
rows the staged solve is judged by and its references.  On a shared machine an absolute time
means little, so each row is also given as a ratio to two references timed in the same run
(the compiled float function, pure Python, and pylinkage's Python path, both pre-built) and as
the figure that ratio gives on the quiet machine, where the references took
:data:`QUIET` (README, ``benchmarks/run.py --readme``)."""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

import closed_form as cf  # noqa: E402
import protocol  # noqa: E402

FOUR_BAR = "cases/s001-we6.toml"
#: the references' times on the quiet machine (README's benchmark table, load 0.8–1.0)
QUIET = {"compiled": 3.1e-6, "pylinkage py": 20.8e-6}
ROWS = ("staged", "staged+steps", "load+staged")
GOALS = {"staged+steps": 80e-6, "load+staged": 300e-6}


def measure(repeat: int, cpu: bool = False) -> dict:
    """Seconds per call of the staged rows and the references (one interleaved run; ``cpu``:
    this process's CPU time instead of the wall clock, which a loaded machine inflates)."""
    from polygons.compiled import compile_scene
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    from polygons.sweep import sweep

    scene = load_scene(ROOT / FOUR_BAR)
    p = cf.params("four-bar", scene)
    K = 64
    thetas = [float(t) for t in p["theta0"] + 2 * np.pi * np.arange(K) / K]
    probe = sweep(scene, inputs=thetas)
    scenes = protocol.scenes_at(probe)
    prog = compile_scene(scene)
    fns = {
        "compiled": lambda i: prog.solve(thetas[i]),
        "staged": lambda i: solve(scenes[i]),
        "staged+steps": lambda i: solve(scenes[i]).steps,
        "load+staged": lambda i: solve(load_scene(ROOT / FOUR_BAR)),
    }
    try:
        import others
        if others.available().get("pylinkage") is None:
            start = {lab: (float(np.ravel(v[0])[0]), float(np.ravel(v[1])[0]))
                     for lab, v in probe.pos.items()}
            pl = others.PyLinkage(p, start)
            fns["pylinkage py"] = lambda i: pl.single_python(thetas[i])
    except ImportError:
        pass
    if cpu:
        clock, protocol.time.perf_counter_ns = protocol.time.perf_counter_ns, time.process_time_ns
        try:
            return protocol.per_call(fns, list(range(K)), repeat)
        finally:
            protocol.time.perf_counter_ns = clock
    return protocol.per_call(fns, list(range(K)), repeat)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=30, help="loops per row (best taken)")
    ap.add_argument("--cpu", action="store_true",
                    help="time by this process's CPU time (a shared machine's load inflates the "
                         "wall clock of long loops more than of short ones)")
    args = ap.parse_args(argv)
    load = os.getloadavg()[0]
    t = measure(args.repeat, args.cpu)
    refs = [r for r in QUIET if r in t]
    print(f"load average {load:.1f} → {os.getloadavg()[0]:.1f}; references: "
          + ", ".join(f"{r} {t[r] * 1e6:.1f} µs (quiet {QUIET[r] * 1e6:.1f})" for r in refs))
    for row in ROWS:
        est = [t[row] / t[r] * QUIET[r] for r in refs]
        goal = GOALS.get(row)
        mark = "" if goal is None else (f"  goal ≤ {goal * 1e6:.0f} µs: "
                                        f"{'met' if max(est) <= goal else 'NOT met'}")
        print(f"  {row:13s} {t[row] * 1e6:7.1f} µs here; "
              + ", ".join(f"{t[row] / t[r]:.2f}× {r}" for r in refs)
              + "; quiet ≈ " + " / ".join(f"{e * 1e6:.1f}" for e in est) + " µs" + mark)
    return 0


if __name__ == "__main__":
    sys.exit(main())
