"""Speed against pylinkage as the mechanism grows: ``python benchmarks/chains.py``.

Chains of N RRR dyads (``benchmarks/large.py``: ``chain(N)``, N = 1 is the four-bar; each
further dyad a four-bar stage on the point before and a fixed pivot), the same geometry built
in pylinkage (its ``RRRDyad`` on the crank and on each dyad before).  By the one protocol of
``benchmarks/protocol.py`` (warm, interleaved, best of several loops, nothing else timed):

* one position: our compiled programs pre-built (``prog.solve(θ)``) against pylinkage's
  pre-built Linkage (the faster of its numba ``step_fast_with_kinematics(1)`` and Python
  ``step_with_derivatives(1)``).  What each computes: pylinkage the positions, velocities and
  accelerations of every joint (no ω, α, no conditioning); our *answers-only* program
  (``compile_scene(scene, outputs=("pos", "velocity", "acceleration"))``) the same numbers,
  like with like; our *full-record* program (``compile_scene(scene)``) every step's vectors,
  points, unit directions, ω, α, construction angles and magnitudes of the step records and
  the drawing (much more: the row kept to show what the records cost);
* a sweep of ``--positions`` crank angles: ``polygons.sweep.sweep(scene, inputs=...)``
  against pylinkage's numba ``step_fast_with_kinematics(n)``.

Both of ours are timed twice: as Python / numpy and compiled by numba (``jit=True``,
:mod:`polygons.jit`; the kernels' one-off compile time is reported, untimed in the rows;
``--no-numba`` leaves the numba rows out, for quick runs).  The sweeps compute, for both
tools, every point's position, velocity and acceleration at each input (ours also ω, α of
every link and the conditioning margin).
Prints one row per N with the ratios and whether the goals hold (issue 31: answers-only
compiled Python ≥ 3×, numpy sweep ≥ 1×; issue 20: numba compiled ≥ 5×, numba sweep ≥ 2×).  ``python benchmarks/run.py`` runs it too (``--chains``), and its ``--readme``
writes the table into the README.  Needs ``pip install -e .[bench]`` (pylinkage, numba).
"""
from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))

import large  # noqa: E402
import protocol  # noqa: E402


class ChainLinkage:
    """pylinkage's model of ``large.scene_text('chain', n)`` (lengths in metres)."""

    def __init__(self, n: int, omega: float, theta0: float):
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import RRRDyad
        from pylinkage.simulation import Linkage

        pos = {k: (x * 1e-3, y * 1e-3) for k, (x, y) in large.positions("chain", n).items()}
        self.pivot, self.r = pos["A"], large.AB * 1e-3
        a = Ground(*pos["A"], name="A")
        d = Ground(*pos["D"], name="D")
        self.crank = Crank(anchor=a, radius=self.r, angular_velocity=0.0,
                           initial_angle=theta0, name="B")
        prev = RRRDyad(self.crank.output, d, distance1=large.BC * 1e-3,
                       distance2=large.CD * 1e-3, x=pos["C"][0], y=pos["C"][1], name="C")
        comps = [a, d, self.crank, prev]
        for k in range(2, n + 1):
            o = Ground(*pos[f"O{k}"], name=f"O{k}")
            prev = RRRDyad(prev, o, distance1=large.COUPLER * 1e-3,
                           distance2=large.ROCKER * 1e-3, x=pos[f"P{k}"][0],
                           y=pos[f"P{k}"][1], name=f"P{k}")
            comps += [o, prev]
        self.linkage = Linkage(comps, name=f"chain-{n}")
        self.linkage.set_input_velocity(self.crank, omega=omega, alpha=0.0)

    def _prepare(self, dtheta: float) -> None:
        if self.crank.angular_velocity != dtheta or self.linkage._solver_data is None:
            self.crank.angular_velocity = dtheta
            self.linkage.compile()

    def _place(self, theta: float) -> None:
        self.crank.x = self.pivot[0] + self.r * math.cos(theta)
        self.crank.y = self.pivot[1] + self.r * math.sin(theta)

    def single_fast(self, theta: float):
        self._prepare(0.0)
        self._place(theta)
        return self.linkage.step_fast_with_kinematics(iterations=1)

    def single_python(self, theta: float):
        self._prepare(0.0)
        self._place(theta)
        return next(self.linkage.step_with_derivatives(iterations=1))

    def sweep_fast(self, theta_start: float, n: int, dtheta: float):
        self._prepare(dtheta)
        self._place(theta_start - dtheta)
        return self.linkage.step_fast_with_kinematics(iterations=n)


#: what our answers-only program computes in the timed single call: pylinkage's outputs
LEAN = ("pos", "velocity", "acceleration")


def measure(n: int, positions: int, quick: bool, numba: bool = True) -> dict:
    from polygons.compiled import compile_scene
    from polygons.scene import load_scene
    from polygons.sweep import sweep

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"chain-{n}.toml"
        path.write_text(large.scene_text("chain", n))
        scene = load_scene(path)
    theta0 = math.radians(large.THETA)
    K = 16 if quick else 64
    # angles near the scene's, where the assembly stated is the one followed
    thetas = [theta0 + 0.2 * k / K for k in range(K)]
    prog = compile_scene(scene)
    lean = compile_scene(scene, outputs=LEAN)
    t0 = time.perf_counter()
    jprog = compile_scene(scene, jit=True) if numba else prog
    jit_compile = time.perf_counter() - t0
    if numba and jprog.fn is prog.fn:
        raise SystemExit("numba is not importable: pip install -e .[bench] (or --no-numba)")
    pl = ChainLinkage(n, 10.0, theta0)
    # the same answer first: C and the chain's last point at one angle
    got = prog.solve(thetas[3])
    pos, _, _ = pl.single_fast(thetas[3])
    last = "C" if n == 1 else f"P{n}"
    ref = np.asarray(pos)[0, -1]
    ours = np.asarray(got.position(last), dtype=float)
    agree = float(np.max(np.abs(ours - ref)))
    lg = lean.solve(thetas[3])
    lean_agree = max(max(abs(a - b) for a, b in zip(getattr(lg, f)(last), getattr(got, f)(last)))
                     / max(1.0, *map(abs, getattr(got, f)(last)))
                     for f in ("position", "velocity", "acceleration"))
    jgot = jprog.solve(thetas[3]).record
    jit_agree = max(abs(a - b) / (1.0 + abs(a)) for a, b in zip(got.record, jgot))
    reps = 5 if quick else 20
    idx = list(range(K))
    singles = {"compiled": lambda i: prog.solve(thetas[i]),
               "lean": lambda i: lean.solve(thetas[i]),
               "numba": lambda i: jprog.solve(thetas[i]),
               "pl fast": lambda i: pl.single_fast(thetas[i]),
               "pl py": lambda i: pl.single_python(thetas[i])}
    if not numba:
        del singles["numba"]
    t1 = protocol.per_call(singles, idx, 3 * reps)
    t1.setdefault("numba", math.nan)
    xs = theta0 + 2 * np.pi * np.arange(positions) / positions
    dth = 2 * np.pi / positions
    t0 = time.perf_counter()
    if numba:
        sweep(scene, inputs=xs[:8], jit=True)          # compiles the sweep kernel (untimed)
    jit_compile += time.perf_counter() - t0
    sweeps = {"sweep": lambda _: sweep(scene, inputs=xs),
              "sweep numba": lambda _: sweep(scene, inputs=xs, jit=True),
              "pl sweep": lambda _: pl.sweep_fast(float(xs[0]), positions, dth)}
    if not numba:
        del sweeps["sweep numba"]
    t2 = protocol.per_call(sweeps, [0], 3 if quick else 7)
    t2.setdefault("sweep numba", math.nan)
    best_pl = min(t1["pl fast"], t1["pl py"])
    return dict(n=n, links=large.links_of("chain", n), compiled=t1["compiled"], pl=best_pl,
                lean=t1["lean"], lean_ratio=best_pl / t1["lean"], lean_agree=lean_agree,
                numba=t1["numba"], single_ratio=best_pl / t1["compiled"],
                numba_ratio=best_pl / t1["numba"], sweep=positions / t2["sweep"],
                sweep_jit=positions / t2["sweep numba"],
                pl_sweep=positions / t2["pl sweep"], sweep_ratio=t2["pl sweep"] / t2["sweep"],
                sweep_jit_ratio=t2["pl sweep"] / t2["sweep numba"], agree=agree,
                jit_agree=jit_agree, jit_compile=jit_compile)


def _met(ratio, goal):
    if ratio != ratio:
        return "not run"
    return f"{ratio:.2f}× {'met' if ratio >= goal else '**not met**'}"


def table(rows) -> str:
    """The chains table: one row per N, Python and numba paths against pylinkage."""
    out = ["| N dyads | links | pylinkage, pre-built (p, v, a) | answers only, Python (p, v, a) "
           "| ratio (goal ≥ 3×) | full record, Python (every step) | ratio | "
           "compiled (numba, full record) | ratio (goal ≥ 5×) | pylinkage sweep | "
           "sweep (numpy) | ratio (goal ≥ 1×) | sweep (numba) | ratio (goal ≥ 2×) | "
           "numba compile |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        numba = "not run" if r["numba"] != r["numba"] else f"{r['numba'] * 1e6:.2f} µs"
        sj = ("not run" if r["sweep_jit"] != r["sweep_jit"]
              else f"{r['sweep_jit'] / 1e6:.3g} M/s")
        out.append(f"| {r['n']} | {r['links']} | {r['pl'] * 1e6:.1f} µs | "
                   f"{r['lean'] * 1e6:.1f} µs | {_met(r['lean_ratio'], 3)} | "
                   f"{r['compiled'] * 1e6:.1f} µs | {r['single_ratio']:.2f}× | "
                   f"{numba} | {_met(r['numba_ratio'], 5)} | "
                   f"{r['pl_sweep'] / 1e6:.3g} M/s | {r['sweep'] / 1e6:.3g} M/s | "
                   f"{_met(r['sweep_ratio'], 1)} | {sj} | "
                   f"{_met(r['sweep_jit_ratio'], 2)} | {r['jit_compile']:.1f} s |")
    return "\n".join(out)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sizes", "--n", default="1,2,4,8,16,32",
                    help="chain lengths N, comma-separated (default 1,2,4,8,16,32)")
    ap.add_argument("--positions", type=int, default=100_000,
                    help="positions of each sweep (default 10^5)")
    ap.add_argument("--quick", action="store_true", help="fewer loops")
    ap.add_argument("--no-numba", action="store_true",
                    help="leave the numba rows out (no compile: quick iterations)")
    args = ap.parse_args(argv)
    try:
        import pylinkage  # noqa: F401
    except ImportError as exc:
        print(f"pylinkage not importable ({exc}); pip install -e .[bench]")
        return 1
    rows = []
    for n in (int(s) for s in args.sizes.split(",")):
        r = measure(n, args.positions, args.quick, numba=not args.no_numba)
        rows.append(r)
        print(f"N = {n}: answers only {r['lean'] * 1e6:.1f} µs ({r['lean_ratio']:.2f}×, equal "
              f"to the full record to {r['lean_agree']:.1e}), full record "
              f"{r['compiled'] * 1e6:.1f} µs, numba {r['numba'] * 1e6:.2f} µs, "
              f"pylinkage {r['pl'] * 1e6:.1f} µs ({r['single_ratio']:.2f}×, "
              f"{r['numba_ratio']:.2f}×); sweep {r['sweep'] / 1e6:.3g} M/s, numba "
              f"{r['sweep_jit'] / 1e6:.3g} M/s, pylinkage {r['pl_sweep'] / 1e6:.3g} M/s "
              f"({r['sweep_ratio']:.2f}×, {r['sweep_jit_ratio']:.2f}×); pylinkage agrees to "
              f"{r['agree']:.1e} m, numba to {r['jit_agree']:.1e} (relative)", flush=True)
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
