"""Speed against error, in one run: ``python benchmarks/run.py``.

For four seed mechanisms -- a four-bar (S001-WE6), an in-line slider-crank (S001-WE4), an offset
slider-crank (S001-WE2) and a slotted-lever quick return (S003-Fig7) -- this measures, on the
same crank angles:

  (a) the staged constructor, one position at a time with every step recorded: warm (scene
      loaded), cold (TOML load + solve) and the first solve of a fresh process;
  (b) the vectorised sweep (polygons.sweep) for N = 1e5 and 1e6 positions;
  (c) a closed-form numpy baseline (benchmarks/closed_form.py, textbook angle form);
  (d) central finite differences of the vectorised positions on the same grid;
  (e) the drawing board: the construction with a pencil (±0.25 mm) and protractor (±0.25°)
      at a sensible scale, Monte Carlo (polygons/drawing_board.py);
  (f) pylinkage (numba fast path for sweeps; its fastest single-position solve with
      derivatives) and (g) mechanism (fsolve per position), when installed
      (pip install -e .[bench]); each is skipped with the reason when it is not.

Every error is measured against the closed forms evaluated in extended precision
(np.longdouble), at the positions whose smallest construction angle is above 1°, as the largest
deviation of each output over the positions divided by that output's largest magnitude (a
point's vectors by their largest length).  Timings are the best of several repetitions,
interleaved so that every method sees the same machine load.

Prints a table and the targets (met or not), writes benchmarks/results/bench.json and
benchmarks/results/speed-vs-error.{png,svg}.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT))

import closed_form as cf  # noqa: E402
from polygons import drawing_board as drawing  # noqa: E402
import others  # noqa: E402
import protocol  # noqa: E402
from polygons.evaluate import solve  # noqa: E402
from polygons.scene import Branch, load_scene  # noqa: E402
from polygons.sweep import compile_plan, evaluate, sweep  # noqa: E402

#: the cold starts' median CPU time (s), by command (filled by main, shown beside the wall)
COLD_CPU: dict = {}
MECHANISMS = [
    ("four-bar", "four-bar", "cases/s001-we6.toml"),
    ("slider-crank (in-line)", "slider-crank", "cases/s001-we4.toml"),
    ("slider-crank (offset)", "slider-crank", "cases/s001-we2.toml"),
    ("quick return (slotted lever)", "slotted-lever", "cases/s003-fig7.toml"),
]
STUDENT_MIN_PER_POSITION = 15.0     # assumed, not measured: one careful construction by hand
MIN_ANGLE = 1.0


# ---------------------------------------------------------------- errors
def rel_error(out: dict, ref: dict, mask=None):
    """(max relative error, worst output) over the outputs both dicts have."""
    worst, name = 0.0, ""
    groups = {}
    for key in ref:
        if key not in out:
            continue
        lab, q = key.split(".")
        if q in ("x", "y", "vx", "vy", "ax", "ay"):
            groups.setdefault((lab, q[:-1] or "p"), []).append(key)
        else:
            groups.setdefault((lab, q), []).append(key)
    for (lab, q), keys in groups.items():
        r = [np.asarray(ref[k], dtype=np.longdouble) for k in keys]
        o = [np.asarray(out[k], dtype=np.longdouble) for k in keys]
        if mask is not None:
            r = [v[mask] for v in r]
            o = [v[mask] for v in o]
        if q == "p":
            scale = max(float(np.max(np.sqrt(sum(v * v for v in r)))), 1e-300)
            scale = max(scale, 1.0 * float(np.max([np.max(np.abs(v)) for v in r])))
        else:
            scale = float(np.max(np.sqrt(sum(v * v for v in r))))
        if scale == 0.0:
            continue
        dev = float(np.max(np.sqrt(sum((a - b) ** 2 for a, b in zip(o, r)))))
        e = dev / scale
        if not math.isfinite(e):
            e = math.inf
        if e > worst:
            worst, name = e, f"{lab}.{q}"
    return worst, name


def best_of(fns: dict, repeat: int) -> dict:
    """Interleaved repetitions; the best time of each function (seconds), by the protocol of
    benchmarks/protocol.py: perf_counter_ns around the call only, no gc.collect()."""
    best = {k: math.inf for k in fns}
    for _ in range(repeat):
        for k, fn in fns.items():
            t = time.perf_counter_ns()
            fn()
            best[k] = min(best[k], (time.perf_counter_ns() - t) * 1e-9)
    return best


# ---------------------------------------------------------------- finite differences
def finite_differences(prog, p, xs, keys):
    """Positions on the uniform periodic grid ``xs``, differentiated by central differences
    (h = the grid step): v = ω dP/dθ, a = ω² d²P/dθ² (constant ω, as in these scenes)."""
    res = evaluate(prog, xs, rates=False)
    h = xs[1] - xs[0]
    w = p["omega"]
    out = {}

    def d1(f):
        return (np.roll(f, -1) - np.roll(f, 1)) * (w / (2 * h))

    def d2(f):
        return (np.roll(f, -1) - 2 * f + np.roll(f, 1)) * (w * w / (h * h))

    pos = res["pos"]
    for key in keys:
        lab, q = key.split(".")
        if q in ("vx", "vy", "ax", "ay") and lab in pos and lab != p.get("A1"):
            f = pos[lab][0 if q[1] == "x" else 1]
            out[key] = d1(f) if q[0] == "v" else d2(f)
        elif q in ("x", "y") and lab in pos:
            out[key] = pos[lab][0 if q == "x" else 1]
    for name, a, b in prog.links:
        if f"{name}.omega" in keys and a in pos and b in pos:
            ax_, ay_ = (np.broadcast_to(v, xs.shape) for v in pos[a])
            bx_, by_ = (np.broadcast_to(v, xs.shape) for v in pos[b])
            phi = np.unwrap(np.arctan2(by_ - ay_, bx_ - ax_))
            out[f"{name}.omega"] = d1(phi)
            out[f"{name}.alpha"] = d2(phi)
    for key in keys:
        lab, q = key.split(".")
        if q in ("v_s", "a_s"):
            if lab in res["travel"]:
                s = res["travel"][lab]
            else:                                   # a pin in a slot: distance from the pivot
                (ax_, ay_), (bx_, by_) = pos[lab], p["B"]
                s = np.hypot(ax_ - bx_, ay_ - by_)
            out[key] = d1(s) if q == "v_s" else d2(s)
    return out


# ---------------------------------------------------------------- one mechanism
def bench_mechanism(title, kind, path, sizes, avail, quick, log):
    scene = load_scene(ROOT / path)
    p = cf.params(kind, scene)
    prog = compile_plan(scene)
    th0 = p["theta0"]
    first = sweep(scene, inputs=[th0])
    start = {lab: (float(np.ravel(v[0])[0]), float(np.ravel(v[1])[0]))
             for lab, v in first.pos.items()}
    rows = []
    keys = list(cf.solve(p, np.array([th0])).keys())

    # positions checked for error: every sweep is compared on a subsample of 2048 angles
    def sub(n):
        step = max(1, n // 2048)
        return np.arange(0, n, step)

    # ---- (a) staged constructor, one position at a time
    K = 16 if quick else 64
    thetas = th0 + 2 * np.pi * np.arange(K) / K
    probe = sweep(scene, inputs=thetas)
    scenes = []
    for i, t in enumerate(thetas):
        drv = replace(scene.driver, angle=float(t))
        asm = {lab: Branch(lab, "near", "near", near=(float(probe.pos[lab][0][i]),
                                                         float(probe.pos[lab][1][i])))
               for lab in probe.branches}
        scenes.append(replace(scene, driver=drv, assembly=asm))
    sols = [solve(s) for s in scenes]
    staged = {k: np.array([_read(sol, k, p) for sol in sols]) for k in keys}
    ref_a = cf.solve(p, thetas.astype(np.longdouble))
    mask_a = probe.angle_deg > MIN_ANGLE
    err_a, worst_a = rel_error(staged, ref_a, mask_a)
    reps = 3 if quick else 8
    t_warm = best_of({"warm": lambda: [solve(s) for s in scenes]}, reps)["warm"] / K
    t_cold = best_of({"cold": lambda: solve(load_scene(ROOT / path))}, 5 if quick else 30)["cold"]
    code = (f"import time; t = time.perf_counter(); from polygons import load_scene, solve; "
            f"solve(load_scene({str(ROOT / path)!r})); print(time.perf_counter() - t)")
    t0 = time.perf_counter()
    inproc = float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                  check=True, cwd=ROOT).stdout)
    t_fresh = time.perf_counter() - t0
    n_steps = len(sols[0].steps)
    rows.append(dict(method="staged constructor, warm", n=1, time=t_warm, error=err_a,
                     worst=worst_a, note=f"scene loaded; all {n_steps} steps recorded"))
    rows.append(dict(method="staged constructor, cold", n=1, time=t_cold, error=err_a,
                     worst=worst_a, note="load_scene (TOML) + solve"))
    rows.append(dict(method="staged, fresh process", n=1, time=t_fresh, error=err_a,
                     worst=worst_a, note=f"interpreter + imports + load + solve "
                                         f"({inproc * 1e3:.0f} ms of it in Python)"))
    log(f"  staged: warm {t_warm * 1e6:.0f} µs, cold {t_cold * 1e6:.0f} µs, "
        f"error {err_a:.2g}")

    # ---- pylinkage single position (with derivatives): its fastest of two paths
    pl = None
    if avail.get("pylinkage") is None:
        pl = others.PyLinkage(p, start)
        pl.single_python(thetas[1])
        pl.single_fast(thetas[1])
        t = best_of({"py": lambda: [pl.single_python(x) for x in thetas],
                     "fast": lambda: [pl.single_fast(x) for x in thetas]}, reps)
        single = [pl.single_python(x) for x in thetas]
        so = pl.outputs(*(np.array([s[j] for s in single], dtype=float) for j in range(3)))
        err_pls = rel_error(so, ref_a, mask_a)
        t_py, t_fast = t["py"] / K, t["fast"] / K
        rows.append(dict(method="pylinkage, single position", n=1, time=min(t_py, t_fast),
                         error=err_pls[0], worst=err_pls[1],
                         note=f"fastest of step_with_derivatives ({t_py * 1e6:.0f} µs) and "
                              f"step_fast_with_kinematics ({t_fast * 1e6:.0f} µs)"))

    # ---- (b) (c) (d) (f) sweeps on the same grid
    for n in sizes:
        xs = th0 + 2 * np.pi * np.arange(n) / n
        idx = sub(n)
        ref = cf.solve(p, xs[idx].astype(np.longdouble))
        mask = probe_mask(scene, xs[idx])
        fns = {"sweep": lambda: sweep(scene, inputs=xs),
               "closed": lambda: cf.solve(p, xs),
               "fd": lambda: finite_differences(prog, p, xs, keys)}
        if JIT:
            sweep(scene, inputs=xs[:16], jit=True)              # numba compiles, untimed
            fns["sweep numba"] = lambda: sweep(scene, inputs=xs, jit=True)
        if kind == "four-bar":
            lean_p = cf.lean(p)
            fns["lean"] = lambda: cf.four_bar_lean(lean_p, xs)
        if pl is not None:
            pl.sweep_fast(xs[0], 16, 2 * np.pi / n)             # compile outside the timing
            fns["pylinkage"] = lambda: pl.sweep_fast(xs[0], n, 2 * np.pi / n)
        t = best_of(fns, 3 if quick else (7 if n <= 100_000 else 4))
        sw = sweep(scene, inputs=xs)
        ours = {k: v[idx] for k, v in cf.outputs_of_sweep(sw, keys).items()}
        e_sw = rel_error(ours, ref, mask)
        cfo = {k: np.asarray(v)[idx] for k, v in cf.solve(p, xs).items()}
        e_cf = rel_error(cfo, ref, mask)
        fdo = {k: np.asarray(v)[idx] for k, v in finite_differences(prog, p, xs, keys).items()}
        e_fd = rel_error(fdo, ref, mask)
        tag = f"N = {n:.0e}".replace("e+0", "e")
        rows.append(dict(method=f"vectorised sweep, {tag}", n=n, time=t["sweep"], error=e_sw[0],
                         worst=e_sw[1], note="polygons.sweep: v, a, ω, α, slides, conditioning"))
        rows.append(dict(method=f"closed form (numpy), {tag}", n=n, time=t["closed"],
                         error=e_cf[0], worst=e_cf[1], note="benchmarks/closed_form.py"))
        if "sweep numba" in t:
            swj = sweep(scene, inputs=xs, jit=True)
            e_j = rel_error({k: v[idx] for k, v in cf.outputs_of_sweep(swj, keys).items()},
                            ref, mask)
            rows.append(dict(method=f"vectorised sweep (numba), {tag}", n=n,
                             time=t["sweep numba"], error=e_j[0], worst=e_j[1],
                             note="polygons.sweep(jit=True): the same code compiled by numba"))
            del swj
        if "lean" in t:
            lo = {k: np.asarray(v)[idx] for k, v in cf.four_bar_lean(lean_p, xs).items()}
            e_l = rel_error(lo, ref, mask)
            rows.append(dict(method=f"lean closed form (numpy), {tag}", n=n, time=t["lean"],
                             error=e_l[0], worst=e_l[1],
                             note="closed_form.four_bar_lean: Cartesian, a few numpy lines"))
        rows.append(dict(method=f"finite differences, {tag}", n=n, time=t["fd"], error=e_fd[0],
                         worst=e_fd[1], note="central, h = 2π/N, of the vectorised positions"))
        if pl is not None:
            pos, vel, acc = pl.sweep_fast(xs[0], n, 2 * np.pi / n)
            plo = {k: np.asarray(v)[idx] for k, v in pl.outputs(pos, vel, acc).items()}
            e_pl = rel_error(plo, ref, mask)
            rows.append(dict(method=f"pylinkage numba, {tag}", n=n, time=t["pylinkage"],
                             error=e_pl[0], worst=e_pl[1],
                             note="step_fast_with_kinematics (crank stepped by 2π/N)"))
        log(f"  N={n}: sweep {n / t['sweep'] / 1e6:.1f} M/s"
            + (f", numba {n / t['sweep numba'] / 1e6:.1f} M/s" if "sweep numba" in t else "")
            + (f", lean {n / t['lean'] / 1e6:.1f} M/s" if "lean" in t else "")
            + f", closed {n / t['closed'] / 1e6:.1f}"
            f" M/s, fd {n / t['fd'] / 1e6:.1f} M/s"
            + (f", pylinkage {n / t['pylinkage'] / 1e6:.2f} M/s" if pl is not None else ""))
        del sw, ours, cfo, fdo

    # ---- (g) mechanism: fsolve at every position
    if avail.get("mechanism") is None:
        M = 20 if quick else 100
        xs = th0 + 2 * np.pi * np.arange(M) / M
        mp = others.MechanismPkg(p, start)
        t0 = time.perf_counter()
        mech = mp.run(xs)
        tm = (time.perf_counter() - t0) / M
        ref = cf.solve(p, xs.astype(np.longdouble))
        e = rel_error(mp.outputs(mech), ref, probe_mask(scene, xs))
        rows.append(dict(method="mechanism (fsolve)", n=M, time=tm * M, error=e[0],
                         worst=e[1], note=f"Mechanism.iterate over {M} positions"))

    # ---- (e) the drawing board
    D = 36
    xs = th0 + 2 * np.pi * np.arange(D) / D
    trials = 100 if quick else 1000
    t0 = time.perf_counter()
    res = drawing.emulate(scene, xs, trials=trials, seed=7)
    t_em = time.perf_counter() - t0
    summ = {q.display: v for q, v in drawing.summary(res, MIN_ANGLE).items()}
    worst_med = max(summ.items(), key=lambda kv: kv[1]["median"])
    worst_p95 = max(summ.items(), key=lambda kv: kv[1]["p95"])
    rows.append(dict(method="drawing board (student)", n=1,
                     time=STUDENT_MIN_PER_POSITION * 60.0, error=worst_med[1]["median"],
                     worst=worst_med[0],
                     note=(f"pencil ±{drawing.PENCIL_MM} mm, protractor ±{drawing.PROTRACTOR_DEG}°;"
                           f" median of the worst answer; 95 % of answers within "
                           f"{worst_p95[1]['p95'] * 100:.1f} % ({worst_p95[0]}); time assumed "
                           f"{STUDENT_MIN_PER_POSITION:g} min/position"),
                     drawing=summ, emulation_s=t_em, trials=trials, positions=D))
    return {"title": title, "kind": kind, "scene": path, "rows": rows,
            "min_angle_deg": float(np.nanmin(probe.angle_deg))}


def probe_mask(scene, xs):
    return sweep(scene, inputs=xs).angle_deg > MIN_ANGLE


def _read(sol, key, p):
    lab, q = key.split(".")
    if q in ("x", "y"):
        return sol.points[lab].position[0 if q == "x" else 1]
    if q in ("vx", "vy"):
        return sol.points[lab].velocity[0 if q == "vx" else 1]
    if q in ("ax", "ay"):
        return sol.points[lab].acceleration[0 if q == "ax" else 1]
    if q == "omega":
        return sol.links[lab].omega
    if q == "alpha":
        return sol.links[lab].alpha
    if q == "v_s":
        return sol.slides[lab].velocity
    if q == "a_s":
        return sol.slides[lab].acceleration
    raise KeyError(key)


# ---------------------------------------------------------------- report
def fmt_time(s):
    if s >= 60:
        return f"{s / 60:.0f} min"
    if s >= 1:
        return f"{s:.2f} s"
    if s >= 1e-3:
        return f"{s * 1e3:.2f} ms"
    if s >= 1e-6:
        return f"{s * 1e6:.1f} µs"
    return f"{s * 1e9:.1f} ns"


def table(results) -> str:
    lines = []
    head = f"{'mechanism':<29} {'method':<31} {'positions/s':>12} {'time/position':>14} " \
           f"{'max rel. error':>15}  worst output / note"
    lines.append(head)
    lines.append("-" * len(head))
    for mech in results:
        for i, r in enumerate(mech["rows"]):
            per = r["time"] / r["n"]
            rate = 1.0 / per
            err = "—" if r["error"] is None else (f"{r['error']:.1e}" if r["error"] < 1e-3
                                                  else f"{r['error'] * 100:.2f} %")
            lines.append(f"{mech['title'] if i == 0 else '':<29} {r['method']:<31} "
                         f"{rate:>12.3g} {fmt_time(per):>14} {err:>15}  "
                         f"{(r['worst'] + '; ') if r['worst'] else ''}{r['note']}")
        lines.append("")
    return "\n".join(lines)


def targets(results, sizes):
    out = []
    for mech in results:
        rows = {r["method"]: r for r in mech["rows"]}
        for n in sizes:
            tag = f"N = {n:.0e}".replace("e+0", "e")
            s = rows[f"vectorised sweep, {tag}"]
            c = rows[f"closed form (numpy), {tag}"]
            ratio = (s["n"] / s["time"]) / (c["n"] / c["time"])
            out.append(dict(target=f"sweep ≥ 1.0× closed-form throughput ({mech['title']}, {tag})",
                            value=ratio, goal=1.0, met=ratio >= 1.0))
            sj = rows.get(f"vectorised sweep (numba), {tag}")
            for base, words, goal in (
                    (rows.get(f"lean closed form (numpy), {tag}"),
                     "1× the lean Cartesian closed form", 1.0),
                    (rows.get(f"pylinkage numba, {tag}"), "2× pylinkage's fastest path", 2.0)):
                for name, r in (("numpy", s), ("numba", sj)):
                    if base is not None and r is not None:
                        ratio = base["time"] / r["time"]
                        out.append(dict(target=f"sweep ({name}) ≥ {words} ({mech['title']}, "
                                               f"{tag})", value=ratio, goal=goal,
                                        met=ratio >= goal))
        ours = [r for r in mech["rows"] if r["method"].startswith(("staged constructor, warm",
                                                                    "vectorised sweep"))]
        assert any(r["method"].startswith("vectorised sweep (numba)") for r in ours) == JIT
        worst = max(r["error"] for r in ours)
        out.append(dict(target=f"error ≤ 1e-12 relative where the smallest angle > 1° "
                               f"({mech['title']}: staged and sweep)", value=worst,
                        goal=1e-12, met=worst <= 1e-12))
    return out


FOUR_BAR = "cases/s001-we6.toml"
#: numba installed: the compiled program and the sweep are also run by it (polygons/jit.py)
JIT = __import__("polygons.jit", fromlist=["available"]).available()


def protocol_table(single, ours_b, closed_b, err_b, ok_b, cold, runs, fresh=None) -> str:
    lines = ["one protocol (benchmarks/protocol.py): four-bar S001-WE6, the same angles, warm, "
             "perf_counter_ns, best loop, no gc.collect",
             f"{'method':<44} {'time/call':>11}  timed region"]
    for r in single:
        lines.append(f"{r['method']:<44} {fmt_time(r['time']):>11}  {r['timed']}")
    lines.append(f"{'batch: 10^4 random four-bars, solve_many':<44} {fmt_time(ours_b):>11}  "
                 f"one call, every row's v, a, ω, α and conditioning ({ok_b} rows closed; "
                 f"ω rel. error vs closed form {err_b:.1e})")
    lines.append(f"{'batch: the same, numpy closed form':<44} {fmt_time(closed_b):>11}  "
                 f"benchmarks/closed_form.py vectorised over the geometry")
    if fresh is not None:
        lines.append(f"{'batch, fresh process: solve_many':<44} {fmt_time(fresh[0]):>11}  "
                     f"first call in a new process (its code for arrays generated then), "
                     f"median of {fresh[2]} processes")
        lines.append(f"{'batch, fresh process: closed form':<44} {fmt_time(fresh[1]):>11}  "
                     f"first call in the same processes")
    for k, v in cold.items():
        lines.append(f"{'cold: polygons ' + k:<44} {fmt_time(v):>11}  whole process (the venv's "
                     f"console script), median of {runs}"
                     + (" (cases/s003-fig7.toml)" if k == "solve" else "")
                     + (f"; CPU {fmt_time(COLD_CPU[k])}" if k in COLD_CPU else ""))
    return "\n".join(lines) + "\n"


def protocol_targets(single, ours_b, closed_b, cold, fresh=None):
    t = {r["key"]: r["time"] for r in single}
    out = []
    pl = min([t[k] for k in ("pylinkage", "pylinkage py") if k in t], default=None)
    if pl is not None:
        for key, name in (("compiled", "Python"), ("numba", "numba")):
            if key in t:
                ratio = pl / t[key]
                out.append(dict(target=f"compiled single solve ({name}) with its flat record ≥ "
                                       f"5× faster than pylinkage pre-built (four-bar)",
                                value=ratio, goal=5.0, met=ratio >= 5.0))
    out.append(dict(target="staged shapely solve ≤ 100 µs (µs)", value=t["staged"] * 1e6,
                    goal=100.0, met=t["staged"] <= 100e-6))
    out.append(dict(target="staged solve WITH its Step records ≤ 100 µs (µs)",
                    value=t["staged+steps"] * 1e6, goal=100.0,
                    met=t["staged+steps"] <= 100e-6))
    out.append(dict(target="load_scene + staged solve ≤ 300 µs (µs)",
                    value=t["load+staged"] * 1e6, goal=300.0, met=t["load+staged"] <= 300e-6))
    ratio = closed_b / ours_b
    out.append(dict(target="batch of 10^4 random four-bars ≥ 1× the vectorised closed form "
                           "(warm)", value=ratio, goal=1.0, met=ratio >= 1.0))
    if fresh is not None:
        ratio = fresh[1] / fresh[0]
        out.append(dict(target="batch of 10^4 random four-bars ≥ 1× the vectorised closed "
                               "form (fresh process, first call)", value=ratio, goal=1.0,
                        met=ratio >= 1.0))
    out.append(dict(target="polygons --help cold ≤ 80 ms (ms)", value=cold["--help"] * 1e3,
                    goal=80.0, met=cold["--help"] <= 0.080))
    out.append(dict(target="polygons solve cases/s003-fig7.toml cold ≤ 200 ms (ms)",
                    value=cold["solve"] * 1e3, goal=200.0, met=cold["solve"] <= 0.200))
    return out


# ---------------------------------------------------------------- issue 31's table
#: the case and size of the command-line sweep row (a four-bar, 19 columns of CSV)
CLI_CASE, CLI_STEPS = "cases/s001-we6.toml", 1_000_000


def issue31_rows(chain_rows, single, cold, cli_s, acc=()) -> list:
    """Every row of issue 31's table: (figure, the issue's figure, this run, goal, met), the
    met column None where this run did not measure the row (it says why)."""
    t = {r["key"]: r["time"] for r in single}
    by_n = {r["n"]: r for r in chain_rows}
    rows = []
    ns = [n for n in (1, 4, 8, 16, 32) if n in by_n]
    if ns:
        vals = [by_n[n]["sweep_jit_ratio"] for n in ns]
        rows.append(("numba sweep vs pylinkage, N = " + "/".join(map(str, ns)),
                     "5.1× / 2.7× / 1.8× / 1.11× / 1.03×",
                     " / ".join(f"{v:.2f}×" for v in vals), "≥ 4× at every N ≤ 32",
                     all(v >= 4.0 for v in vals)))
        vals = [by_n[n]["sweep_ratio"] for n in ns]
        rows.append(("numpy sweep vs pylinkage, N = " + "/".join(map(str, ns)), "0.47× (N = 32)",
                     " / ".join(f"{v:.2f}×" for v in vals), "≥ 1× at every N ≤ 32",
                     all(v >= 1.0 for v in vals)))
        cn = [n for n in (8, 32) if n in by_n]
        vals = [by_n[n]["lean_ratio"] for n in cn]
        full = [by_n[n]["single_ratio"] for n in cn]
        rows.append(("compiled pure Python vs pylinkage, N = " + " / ".join(map(str, cn))
                     + " (answers only: p, v, a, as pylinkage; full record in brackets)",
                     "1.86× / 1.45×", " / ".join(f"{v:.2f}× ({f:.2f}×)" for v, f in
                                                 zip(vals, full)), "≥ 3×",
                     all(v >= 3.0 for v in vals) if vals else None))
    else:
        for fig, now, goal in (("numba sweep vs pylinkage", "5.1× … 1.03×", "≥ 4×"),
                               ("numpy sweep vs pylinkage, N = 32", "0.47×", "≥ 1×"),
                               ("compiled pure Python vs pylinkage, N = 8 / 32",
                                "1.86× / 1.45×", "≥ 3×")):
            rows.append((fig, now, "not measured (needs pylinkage and numba)", goal, None))
    rows.append(("staged solve with Step records (WE6)", "128 µs",
                 f"{t['staged+steps'] * 1e6:.0f} µs", "≤ 80 µs", t["staged+steps"] <= 80e-6))
    rows.append((f"CLI `sweep {CLI_CASE} --steps {CLI_STEPS}` (no plots)", "23 s",
                 f"{cli_s:.1f} s", "≤ 3 s", cli_s <= 3.0))
    rows.append(("cold `polygons solve cases/s003-fig7.toml`", "304 ms",
                 f"{cold['solve'] * 1e3:.0f} ms", "≤ 200 ms", cold["solve"] <= 0.200))
    if acc:
        import accuracy
        worst = max(max(v for k, v in r["errors"].items() if k != "lean (numpy)")
                    / (r["errors"]["lean (numpy)"] + 1e-15) for r in acc)
        rows.append(("accuracy: sweeps and compiled within 2× of the lean solver at γ = "
                     + ", ".join(f"{r['gamma']:g}°" for r in acc) + " (benchmarks/accuracy.py)",
                     "—", f"worst {worst:.2f}× the lean solver's error", "≤ 2×",
                     all(all(accuracy.goal_met(r).values()) for r in acc)))
    else:
        rows.append(("accuracy: sweep and compiled within 2× of the lean solver at γ = 1°, "
                     "0.1°, 0.01°", "—", "not measured by this run", "≤ 2×", None))
    return rows


def _met(m) -> str:
    return "not measured" if m is None else ("met" if m else "not met")


# ---------------------------------------------------------------- README section
def _cell(r) -> str:
    err = "—" if r["error"] is None else (f"{r['error']:.1e}" if r["error"] < 1e-3
                                          else f"**{r['error'] * 100:.0f} %**"
                                          if r["method"] != "drawing board (student)"
                                          else f"{r['error'] * 100:.2f} %")
    if r["method"] == "drawing board (student)":
        return err
    per = r["time"] / r["n"]
    speed = fmt_time(per) if r["n"] == 1 else f"{r['n'] / r['time'] / 1e6:.3g} M/s"
    return f"{speed} · {err}"


def markdown(results, single, batch, fresh, cold, runs, chain_rows, goals, info,
             issue31=(), acc=()) -> str:
    """The README's benchmark figures, every one from this run (``--readme``)."""
    out = [f"Measured in one run (`python benchmarks/run.py --readme`, {info['date']}, "
           f"pylinkage {info.get('pylinkage_version', '—')}, numba "
           f"{info.get('numba_version', '—')}, mechanism {info.get('mechanism_version', '—')}) "
           f"on this project's machine: {info['cpus']} cores, load average "
           f"{info['load_start']:.1f} at the start and {info['load_end']:.1f} at the end "
           f"(shared with other jobs: absolute times are inflated, the ratios are from the "
           f"same run, interleaved).", "",
           "| method (rate or time per position · max rel. error) | "
           + " | ".join(m["title"] for m in results) + " |",
           "|---|" + "---|" * len(results)]
    methods = []
    for m in results:
        for r in m["rows"]:
            if r["method"] not in methods:
                methods.append(r["method"])
    for meth in methods:
        cells = []
        for m in results:
            r = next((r for r in m["rows"] if r["method"] == meth), None)
            cells.append("—" if r is None else _cell(r))
        out.append(f"| {meth} | " + " | ".join(cells) + " |")
    out += ["", "**One protocol, one position of the four-bar (S001-WE6), the batch and cold "
            "starts** (each row says what its timed region holds):", "",
            "| method | time per call | timed region |", "|---|---|---|"]
    for r in single:
        out.append(f"| {r['method']} | {fmt_time(r['time'])} | {r['timed']} |")
    ours_b, closed_b, err_b, ok_b = batch
    out.append(f"| batch: 10⁴ random four-bars, `polygons.solve_many`, warm | "
               f"{fmt_time(ours_b)} | one call: every row's positions, v, a, ω, α, "
               f"conditioning and row errors ({ok_b} rows close; ω within {err_b:.1e} of the "
               f"closed form) |")
    out.append(f"| batch: the same 10⁴, numpy closed form, warm | {fmt_time(closed_b)} | "
               f"one call |")
    out.append(f"| batch, fresh process: `solve_many` | {fmt_time(fresh[0])} | its first "
               f"call in a new process (code for arrays generated then), median of {fresh[2]} |")
    out.append(f"| batch, fresh process: closed form | {fmt_time(fresh[1])} | its first call "
               f"in the same processes |")
    for k, v in cold.items():
        out.append(f"| cold `polygons {k}{' cases/s003-fig7.toml' if k == 'solve' else ''}` | "
                   f"{fmt_time(v)} | whole process (the venv's console script), median of "
                   f"{runs}" + (f"; CPU (user + sys) {fmt_time(COLD_CPU[k])}" if k in COLD_CPU
                                else "") + " |")
    if chain_rows:
        import chains
        out += ["", "**Against pylinkage as the chain grows** (chains of N RRR dyads, "
                "`benchmarks/chains.py`, run by this command; pylinkage pre-built, its faster "
                "path for one position and its numba loop for sweeps of "
                f"{chain_rows[0]['positions']:,} positions; numba compile = our two kernels' "
                "one-off compile time, untimed in the rows):", "", chains.table(chain_rows)]
    if issue31:
        out += ["", "**Issue 31's table, this run** (the issue's figure, this run's, the goal):",
                "", "| figure | issue | this run | goal | |", "|---|---|---|---|---|"]
        for fig, now, val, goal, met in issue31:
            out.append(f"| {fig} | {now} | {val} | {goal} | {_met(met)} |")
    if acc:
        import accuracy
        out += ["", "**Accuracy near a toggle** (`benchmarks/accuracy.py`: a four-bar whose "
                "construction angle at C is γ; the largest error of v_C and a_C relative to "
                "their largest size, against the lean closed form in long double from the same "
                "float64 inputs; ✔: within 2× of the lean closed form's float64 error):", "",
                accuracy.table(acc)]
    out += ["", "![Speed against error: positions per second against the largest relative "
            "error, per method and mechanism](docs/figures/speed-vs-error.png)"]
    out += ["", "Goals (ratios from this run):", ""]
    for g in goals:
        val = f"{g['value']:.3g}" if g["goal"] != 1e-12 else f"{g['value']:.2g}"
        out.append(f"* {g['target']}: {val} — **{'met' if g['met'] else 'not met'}**")
    return "\n".join(out)


def write_readme(md: str) -> None:
    protocol.write_readme_section("bench", md)


def chain_targets(rows) -> list:
    out = []
    for r in rows:
        for key, name, goal in (("single_ratio", "compiled (Python)", 5.0),
                                ("numba_ratio", "compiled (numba)", 5.0),
                                ("sweep_ratio", "sweep (numpy)", 2.0),
                                ("sweep_jit_ratio", "sweep (numba)", 2.0)):
            out.append(dict(target=f"chain N = {r['n']}: {name} ≥ {goal:g}× pylinkage",
                            value=r[key], goal=goal, met=r[key] >= goal))
    return out


def plot(results, stem):
    from diagrams.plots import Line, plot_xy

    series = {}
    for mech in results:
        for r in mech["rows"]:
            if r["error"] is None or r["method"] in ("staged constructor, cold",
                                                     "staged, fresh process"):
                continue
            method = r["method"]
            series.setdefault(method, ([], []))
            series[method][0].append(r["n"] / r["time"])
            series[method][1].append(max(r["error"], 1e-17))
    colors = {"vectorised sweep (numba)": "tab:cyan", "lean": "tab:olive",
              "vectorised": "tab:blue", "staged": "tab:green", "closed": "tab:orange",
              "finite": "tab:purple", "pylinkage": "tab:red", "mechanism": "tab:brown",
              "drawing": "black"}
    lines = []
    for method, (x, y) in series.items():
        c = next((v for k, v in colors.items() if method.startswith(k)), None)
        marker = "s" if "1e6" in method else ("^" if "single" in method or "warm" in method
                                               else "o")
        lines.append(Line(method, x, y, "none", c, 1.0, marker))
    return plot_xy("Speed against error: one point per mechanism (errors floored at 1e-17)",
                   "positions per second (drawing board: assumed 15 min per position)",
                   "max relative error (angle > 1°; drawing board: median)", lines, stem,
                   logx=True, logy=True, annotate=False, width=10.0, height=5.5,
                   legend_outside=True)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="smaller sizes and fewer repetitions")
    ap.add_argument("--sizes", help="comma-separated sweep sizes (default 100000,1000000; "
                                    "--quick: 20000,100000)")
    ap.add_argument("--no-others", action="store_true", help="skip pylinkage and mechanism")
    ap.add_argument("--out", default=str(HERE / "results"), help="output directory")
    ap.add_argument("--chains", default="1,2,4,8,16,32",
                    help="chain sizes N against pylinkage (benchmarks/chains.py; '' skips)")
    ap.add_argument("--chain-positions", type=int, default=1_000_000,
                    help="positions of each chain's sweep (issue 31's table: 10^6)")
    ap.add_argument("--no-large", action="store_true",
                    help="with --readme: leave README's large-mechanism table "
                         "(benchmarks/large.py --readme) as it is")
    ap.add_argument("--no-jit", action="store_true",
                    help="leave out the numba rows (polygons/jit.py) even where numba is installed")
    ap.add_argument("--readme", action="store_true",
                    help="write the figures into README.md between <!-- bench:begin --> and "
                         "<!-- bench:end --> (every number from this run)")
    args = ap.parse_args(argv)
    global JIT
    JIT = JIT and not args.no_jit
    load_start = os.getloadavg()[0]
    sizes = ([int(s) for s in args.sizes.split(",")] if args.sizes else
             ([20_000, 100_000] if args.quick else [100_000, 1_000_000]))
    avail = ({"pylinkage": "skipped (--no-others)", "mechanism": "skipped (--no-others)"}
             if args.no_others else others.available())
    log = lambda s: print(s, file=sys.stderr, flush=True)  # noqa: E731
    for name, why in avail.items():
        if why:
            log(f"{name}: {why}")
    results = []
    for title, kind, path in MECHANISMS:
        log(f"{title} ({path})")
        results.append(bench_mechanism(title, kind, path, sizes, avail, args.quick, log))
    goals = targets(results, sizes)
    log("one protocol: single position, batch, cold start (four-bar S001-WE6)")
    single = protocol.single_position(ROOT, FOUR_BAR, avail, args.quick, others, cf, JIT)
    ours_b, closed_b, err_b, ok_b = protocol.batch_vs_closed_form(ROOT, FOUR_BAR, args.quick, cf)
    fresh_runs = 1 if args.quick else 5
    fresh = protocol.batch_fresh(ROOT, FOUR_BAR, fresh_runs) + (fresh_runs,)
    chain_rows = []
    if args.chains and avail.get("pylinkage") is None and JIT:
        import chains
        for n in (int(c) for c in args.chains.split(",")):
            log(f"chain of {n} dyads")
            r = chains.measure(n, args.chain_positions, args.quick)
            r["positions"] = args.chain_positions
            chain_rows.append(r)
    elif args.chains:
        log("chains: not measured (needs pylinkage and numba: pip install -e .[bench])")
    runs = 3 if args.quick else 10
    cold_runs = protocol.cold_times(ROOT, {"--help": ["--help"],
                                           "solve": ["solve", "cases/s003-fig7.toml"]}, runs)
    cold = {k: v["wall"] for k, v in cold_runs.items()}
    COLD_CPU.update({k: v["cpu"] for k, v in cold_runs.items()})
    log(f"command-line sweep: {CLI_CASE} --steps {CLI_STEPS:,}")
    cli_s = protocol.cli_sweep(ROOT, CLI_CASE, CLI_STEPS, 1 if args.quick else 3)
    goals += protocol_targets(single, ours_b, closed_b, cold, fresh)
    goals += chain_targets(chain_rows)
    log("accuracy near a toggle: benchmarks/accuracy.py")
    import accuracy
    acc = [accuracy.measure(g) for g in accuracy.GAMMAS] if JIT else []
    issue31 = issue31_rows(chain_rows, single, cold, cli_s, acc)
    print(table(results))
    print(protocol_table(single, ours_b, closed_b, err_b, ok_b, cold, runs, fresh))
    if chain_rows:
        import chains
        print(chains.table(chain_rows))
    print("targets (ratios measured in this run):")
    for g in goals:
        val = f"{g['value']:.3g}" if g["goal"] != 1e-12 else f"{g['value']:.2g}"
        print(f"  [{'met' if g['met'] else 'NOT met'}] {g['target']}: {val}")
    for name, why in avail.items():
        if why:
            print(f"  {name}: not compared — {why}")
    print("issue 31's table (the issue's figure → this run; goal):")
    for fig, now, val, goal, met in issue31:
        print(f"  [{_met(met)}] {fig}: {now} → {val}; goal {goal}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    info = {"python": sys.version.split()[0], "numpy": np.__version__,
            "machine": platform.machine(), "processor": platform.processor(),
            "cpus": __import__("os").cpu_count(), "sizes": sizes, "quick": args.quick,
            "others": {k: (v or "compared") for k, v in avail.items()}}
    info.update(date=time.strftime("%Y-%m-%d", time.gmtime()), load_start=load_start,
                load_end=os.getloadavg()[0])
    print(f"load average: {load_start:.1f} at the start, {info['load_end']:.1f} at the end "
          f"({info['cpus']} cores)")
    for name in ("pylinkage", "mechanism", "shapely", "numba"):
        try:
            from importlib.metadata import version
            info[f"{name}_version"] = version(name)
        except Exception:
            pass
    (out / "bench.json").write_text(json.dumps({
        "info": info, "results": results, "targets": goals,
        "protocol": {"single": single, "batch": {"n": 10_000, "ours_s": ours_b,
                                                 "closed_form_s": closed_b,
                                                 "omega_rel_error": err_b, "solved": ok_b},
                     "batch_fresh": {"ours_s": fresh[0], "closed_form_s": fresh[1]},
                     "cold_s": cold, "cold_cpu_s": dict(COLD_CPU), "rules": protocol.__doc__},
        "chains": chain_rows}, indent=1, default=float))
    info["cli_sweep_s"] = cli_s
    written = plot(results, out / "speed-vs-error")
    if args.readme:
        write_readme(markdown(results, single, (ours_b, closed_b, err_b, ok_b), fresh, cold,
                              runs, chain_rows, goals, info, issue31, acc))
        # the figure the README shows is committed (benchmarks/results/ is not)
        written += plot(results, ROOT / "docs" / "figures" / "speed-vs-error")
        print("README.md: the benchmark section rewritten from this run")
        if not args.no_large:
            import large
            log("large mechanisms: benchmarks/large.py --readme")
            large.main(["--readme"])
    print(f"written: {out / 'bench.json'}, " + ", ".join(str(w) for w in written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
