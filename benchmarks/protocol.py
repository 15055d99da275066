"""One timing protocol for every package (used by benchmarks/run.py).

The rules, the same for polygons, pylinkage and the numpy closed form:

* the same geometry: the four-bar of S001-WE6, at the same K crank angles;
* warm: every callable is called once, untimed, before its timings (imports, numba and our
  code generation happen there);
* one timer, ``time.perf_counter_ns``, read once before and once after a loop of K calls
  (one per angle); the time per call is the best of ``repeat`` such loops divided by K; the
  loops of all methods are interleaved so that each sees the same machine load;
* nothing else is in the timed region: no ``gc.collect()`` (the collector stays enabled, as in
  a user's program), no result checking, no argument building;
* "pre-built" times the solve of a model built beforehand (our compiled program or staged
  scene, pylinkage's Linkage); "build + solve" times building it from the parsed geometry
  and solving once, inside the region;
* the cold start is the whole process a user's shell starts: the ``polygons`` console script
  installed beside this interpreter (``<venv>/bin/polygons``: site with its ``.pth`` files,
  the editable install's finder among them), the code under test first on ``PYTHONPATH``,
  bytecode caching on; the commands interleaved, one untimed round first (it warms the OS
  caches and writes the bytecode); the median over N rounds of the wall time and of the
  child's CPU time (user + system, ``RUSAGE_CHILDREN``), which a loaded machine inflates
  less than the wall time.
"""
from __future__ import annotations

import math
import os
import statistics
from pathlib import Path
import subprocess
import sys
import time

import numpy as np


def per_call(fns: dict, args, repeat: int) -> dict:
    """Seconds per call of each ``fns[name](arg)`` over ``args``: warm, interleaved, best of
    ``repeat`` loops, perf_counter_ns around the loop only."""
    for fn in fns.values():
        fn(args[0])
    best = {k: math.inf for k in fns}
    clock = time.perf_counter_ns
    for _ in range(repeat):
        for name, fn in fns.items():
            t0 = clock()
            for a in args:
                fn(a)
            t1 = clock()
            best[name] = min(best[name], (t1 - t0) / len(args))
    return {k: v * 1e-9 for k, v in best.items()}


def write_readme_section(marker: str, md: str) -> None:
    """The README's text between ``<!-- MARKER:begin -->`` and ``<!-- MARKER:end -->``
    replaced by ``md`` (the figures a benchmark's ``--readme`` regenerates)."""
    readme = Path(__file__).resolve().parent.parent / "README.md"
    text = readme.read_text(encoding="utf-8")
    head, rest = text.split(f"<!-- {marker}:begin -->\n", 1)
    _, tail = rest.split(f"<!-- {marker}:end -->", 1)
    readme.write_text(f"{head}<!-- {marker}:begin -->\n{md}\n<!-- {marker}:end -->{tail}",
                      encoding="utf-8")


def scenes_at(probe):
    """The scene restated at each angle of the sweep ``probe`` (its closures pinned 'near'
    the followed ones: :meth:`polygons.sweep.Sweep.scene_at`)."""
    return [probe.scene_at(i) for i in range(probe.n)]


def single_position(root, path, avail, quick, others, cf, jit_rows=True):
    """Rows (method, seconds per call, what is timed) for one position of the four-bar."""
    from polygons.compiled import compile_scene
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    from polygons.sweep import sweep

    scene = load_scene(root / path)
    p = cf.params("four-bar", scene)
    K = 16 if quick else 64
    th0 = p["theta0"]
    thetas = [float(t) for t in th0 + 2 * np.pi * np.arange(K) / K]
    probe = sweep(scene, inputs=thetas)
    scenes = scenes_at(probe)
    prog = compile_scene(scene)
    idx = list(range(K))
    fns = {
        "compiled": lambda i: prog.solve(thetas[i]),
        "compiled+steps": lambda i: prog.solve(thetas[i]).steps,
        "compiled build": lambda i: compile_scene(scenes[i]).solve(),
        "staged": lambda i: solve(scenes[i]),
        "staged+steps": lambda i: solve(scenes[i]).steps,
        "load+staged": lambda i: solve(load_scene(root / path)),
        "closed form": lambda i: cf.four_bar(p, np.array([thetas[i]])),
    }
    notes = {
        "compiled": ("polygons compiled, pre-built",
                     "compile_scene once outside; timed: the float function filling every "
                     "step's vectors, points, directions, ω/α values and angles into its flat "
                     "record (the terms' magnitudes, Step records and text built lazily)"),
        "compiled+steps": ("polygons compiled + Step records",
                           "as above, and the Step records (numbers and terms) materialised"),
        "compiled build": ("polygons compiled, build + solve",
                           "timed: compile_scene (plan, staged assembly for the closures, "
                           "cached code) + solve, from a parsed Scene"),
        "staged": ("polygons staged (shapely), pre-built scene",
                   "timed: solve(scene): assembly, the step program with every intersection "
                   "as shapely finds it (GEOS's arithmetic in floats), the Solution (its Step "
                   "records and text built on first "
                   "access; the plan kept with the scene)"),
        "staged+steps": ("polygons staged + Step records",
                         "timed: solve(scene) as above and its .steps: every Step record "
                         "with its numbers and terms (its formula is written when shown)"),
        "load+staged": ("polygons load_scene + staged",
                        "timed: TOML parse + solve (the scene's own angle)"),
        "closed form": ("numpy closed form, one position",
                        "benchmarks/closed_form.py on a 1-element array"),
    }
    from polygons import jit
    if jit_rows and jit.available():
        jprog = compile_scene(scene, jit=True)
        fns["numba"] = lambda i: jprog.solve(thetas[i])
        notes["numba"] = ("polygons compiled by numba, pre-built",
                          "compile_scene(jit=True) once outside; timed: the same record "
                          "filled by the generated code compiled by numba (a float64 array)")
    pl = None
    if avail.get("pylinkage") is None:
        start = {lab: (float(np.ravel(v[0])[0]), float(np.ravel(v[1])[0]))
                 for lab, v in probe.pos.items()}
        pl = others.PyLinkage(p, start)
        fns["pylinkage"] = lambda i: pl.single_fast(thetas[i])
        fns["pylinkage py"] = lambda i: pl.single_python(thetas[i])
        fns["pylinkage build"] = lambda i: others.PyLinkage(p, start).single_python(thetas[i])
        notes["pylinkage"] = ("pylinkage, pre-built (numba path)",
                              "Linkage built outside; timed: step_fast_with_kinematics(1)")
        notes["pylinkage py"] = ("pylinkage, pre-built (Python path)",
                                 "Linkage built outside; timed: step_with_derivatives(1)")
        notes["pylinkage build"] = ("pylinkage, build + solve",
                                    "timed: Linkage built from the same geometry + "
                                    "step_with_derivatives(1)")
    t = per_call(fns, idx, 5 if quick else 30)
    rows = [dict(key=k, method=notes[k][0], time=t[k], timed=notes[k][1]) for k in fns]
    return rows


def batch_vs_closed_form(root, path, quick, cf, n=10_000):
    """(ours s, closed form s, max relative error of ω_BC against it) for n random four-bars
    solved at once."""
    from polygons.batch import solve_many
    from polygons.scene import load_scene

    scene = load_scene(root / path)
    p = cf.params("four-bar", scene)
    rng = np.random.default_rng(1)
    L = {k: scene.links[k].length for k in ("AB", "BC", "CD")}
    ab = L["AB"] * rng.uniform(0.9, 1.1, n)
    bc = L["BC"] * rng.uniform(0.95, 1.05, n)
    cd = L["CD"] * rng.uniform(0.95, 1.05, n)
    th = rng.uniform(0.0, 2 * math.pi, n)
    pp = dict(p, r=ab, b=bc, c=cd)
    fns = {"ours": lambda _: solve_many(scene, AB=ab, BC=bc, CD=cd, theta=th),
           "closed": lambda _: cf.four_bar(pp, th)}
    with np.errstate(invalid="ignore"):
        t = per_call(fns, [0], 5 if quick else 30)
        b = solve_many(scene, AB=ab, BC=bc, CD=cd, theta=th)
        ref = cf.four_bar(dict(pp), th.astype(np.longdouble))
    w = np.asarray(ref[f"{p['coupler']}.omega"], dtype=float)
    ok = b.ok & np.isfinite(w)
    err = float(np.max(np.abs(b.omega(p["coupler"])[ok] - w[ok])) / np.max(np.abs(w[ok])))
    return t["ours"], t["closed"], err, int(b.ok.sum())


_FRESH = """
import math, sys, time
import numpy as np
sys.path[:0] = [{here!r}, {root!r}]
import closed_form as cf
from polygons.batch import solve_many
from polygons.scene import load_scene
scene = load_scene({path!r})
p = cf.params("four-bar", scene)
rng = np.random.default_rng(1)
n = 10_000
L = {{k: scene.links[k].length for k in ("AB", "BC", "CD")}}
ab = L["AB"] * rng.uniform(0.9, 1.1, n)
bc = L["BC"] * rng.uniform(0.95, 1.05, n)
cd = L["CD"] * rng.uniform(0.95, 1.05, n)
th = rng.uniform(0.0, 2 * math.pi, n)
pp = dict(p, r=ab, b=bc, c=cd)
with np.errstate(invalid="ignore"):
    t0 = time.perf_counter_ns(); cf.four_bar(pp, th); t1 = time.perf_counter_ns()
    solve_many(scene, AB=ab, BC=bc, CD=cd, theta=th); t2 = time.perf_counter_ns()
print((t2 - t1) * 1e-9, (t1 - t0) * 1e-9)
"""


def batch_fresh(root, path, runs: int = 5) -> tuple[float, float]:
    """(ours s, closed form s): the first call of each in a fresh process (the scene loaded
    and the 10⁴ random four-bars drawn before the timer; ours includes generating and
    compiling its code for arrays, the closed form its first numpy calls), median of
    ``runs`` processes."""
    here = str(Path(__file__).resolve().parent)
    code = _FRESH.format(here=here, root=str(root), path=str(root / path))
    ours, closed = [], []
    for _ in range(runs):
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                             check=True, cwd=root).stdout.split()
        ours.append(float(out[0]))
        closed.append(float(out[1]))
    return statistics.median(ours), statistics.median(closed)


def cli_sweep(root, case: str, steps: int, runs: int) -> float:
    """Median wall time (s) of ``polygons sweep CASE --steps N --no-plot`` as a whole process
    (bytecode caching on, as :func:`cold`), the CSV written to a temporary folder."""
    import tempfile
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(runs):
            t0 = time.perf_counter_ns()
            subprocess.run([sys.executable, "-m", "polygons", "sweep", case, "--steps",
                            str(steps), "--no-plot", "--progress", "off", "--out", tmp],
                           cwd=root, capture_output=True, check=True, env=env)
            times.append((time.perf_counter_ns() - t0) * 1e-9)
    return statistics.median(times)


def polygons_command(root) -> tuple[list[str], dict]:
    """The command a user runs and its environment: the console script installed beside this
    interpreter (``pip install -e .`` writes ``<venv>/bin/polygons``; ``python -m polygons``
    when there is none), with ``root`` first on ``PYTHONPATH`` so that the script imports the
    code under test (an editable install maps ``polygons`` to the tree it was made from), and
    ``PYTHONDONTWRITEBYTECODE`` removed (with it set every module is compiled from source at
    every start, ~60 ms more)."""
    script = Path(sys.executable).parent / ("polygons.exe" if os.name == "nt" else "polygons")
    cmd = [str(script)] if script.is_file() else [sys.executable, "-m", "polygons"]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPATH"] = os.pathsep.join([str(root)] + [p for p in env.get("PYTHONPATH", "")
                                                        .split(os.pathsep) if p])
    return cmd, env


def cold_times(root, commands: dict, runs: int) -> dict:
    """For each ``commands[name]`` (argv after ``polygons``), run as a whole process by
    :func:`polygons_command`: ``{"wall": s, "cpu": s, "command": text}``, the medians over
    ``runs`` rounds (the commands interleaved in each round, one untimed round first).  The
    CPU time is the child's user + system time (``RUSAGE_CHILDREN`` before and after)."""
    import resource
    cmd, env = polygons_command(root)
    wall = {k: [] for k in commands}
    cpu = {k: [] for k in commands}
    clock = time.perf_counter_ns
    for i in range(runs + 1):
        for name, argv in commands.items():
            r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = clock()
            subprocess.run(cmd + list(argv), cwd=root, capture_output=True, check=False,
                           env=env)
            t1 = clock()
            r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            if i:                                 # the first round warms the OS caches
                wall[name].append((t1 - t0) * 1e-9)
                cpu[name].append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
    shown = " ".join(Path(c).name if j == 0 else c for j, c in enumerate(cmd))
    return {k: {"wall": statistics.median(wall[k]), "cpu": statistics.median(cpu[k]),
                "command": f"{shown} {' '.join(commands[k])}"} for k in commands}


def cold(root, argv, runs: int) -> float:
    """Median wall time (s) of ``polygons ARGV`` as a whole process (:func:`cold_times`)."""
    return cold_times(root, {"cold": argv}, runs)["cold"]["wall"]
