"""Accuracy near a toggle: ``python benchmarks/accuracy.py`` (issue 31, item 2).

A four-bar (AB 0.1 m, BC 0.4 m, CD 0.3 m, ω 10 rad/s, α 50 rad/s²) whose ground AD is chosen
so that the construction angle at C (between CB and CD) is γ at θ₀ = 1 rad, for γ = 1°, 0.1°,
0.01°; 101 crank angles about θ₀ that keep BD within a tenth of its distance from the
toggle (γ stays about the same).  Each path's largest
error of C's velocity and acceleration, relative to the largest |v_C| and |a_C|, against the
lean Cartesian closed form (``closed_form.four_bar_lean``) evaluated in ``np.longdouble`` from
the same float64 inputs (the reference); the goal (issue 31): the sweeps and the compiled
program within 2× of the lean closed form's own float64 error (+1e-15, the floor of a
well-conditioned solve).

Paths: the lean closed form in float64 (numpy), the numpy sweep (the staged construction on
arrays: unit directions, then intersections), the numba sweep (``jit=True``: the fused kernel
of ``polygons/fused.py``, the 2×2 Cartesian solve), the compiled program one position at a
time (``compile_scene(...).solve(θ)``: the staged construction over floats), and its
answers-only program (``compile_scene(..., outputs=(...))``: the lines as given, the 2×2 solve).
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))

import closed_form as cf  # noqa: E402

GAMMAS = (1.0, 0.1, 0.01)
A, B, C, THETA0, OMEGA, ALPHA = 0.1, 0.4, 0.3, 1.0, 10.0, 50.0


def scene_at(gamma_deg: float):
    """The four-bar whose construction angle at C is ``gamma_deg`` at θ₀ (C folded back
    towards B: |BD|² = b² + c² − 2bc cos γ = a² + d² − 2ad cos θ₀, solved for d)."""
    from polygons.scene import parse_scene
    g = math.radians(gamma_deg)
    bd2 = B * B + C * C - 2 * B * C * math.cos(g)
    d = A * math.cos(THETA0) + math.sqrt(A * A * math.cos(THETA0) ** 2 - A * A + bd2)
    # the closure: C left of B→D (σ = +1), its point near there
    bx, by = A * math.cos(THETA0), A * math.sin(THETA0)
    ux, uy = d - bx, -by
    L = math.hypot(ux, uy)
    m = (B * B - C * C + L * L) / (2 * L)
    h = math.sqrt(max(B * B - m * m, 0.0))
    cx, cy = bx + (m * ux - h * uy) / L, by + (m * uy + h * ux) / L
    return parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [f"{d!r} m", "0 m"]},
        "links": {"AB": f"{A!r} m", "BC": f"{B!r} m", "CD": f"{C!r} m"},
        "driver": {"crank": "AB", "angle": f"{THETA0!r} rad", "omega": f"{OMEGA!r} rad/s",
                   "sense": "CCW", "alpha": f"{ALPHA!r} rad/s^2", "alpha_sense": "CCW"},
        "assembly": {"C": {"near": [f"{cx!r} m", f"{cy!r} m"]}},
    })


def _err(got: dict, ref: dict) -> float:
    """The largest error of C's velocity and acceleration relative to the largest |v|, |a|."""
    worst = 0.0
    for q in ("v", "a"):
        rx, ry = (np.asarray(ref[f"C.{q}{c}"], dtype=np.longdouble) for c in "xy")
        gx, gy = (np.asarray(got[f"C.{q}{c}"], dtype=np.longdouble) for c in "xy")
        scale = float(np.max(np.hypot(rx, ry)))
        worst = max(worst, float(np.max(np.hypot(gx - rx, gy - ry))) / scale)
    return worst


def measure(gamma_deg: float) -> dict:
    from polygons.compiled import compile_scene
    from polygons.sweep import sweep
    scene = scene_at(gamma_deg)
    p = cf.lean(cf.params("four-bar", scene))
    # crank angles that move BD by at most a tenth of its distance from the toggle |b − c|
    d = p["D"][0]
    bd = math.sqrt(A * A + d * d - 2 * A * d * math.cos(THETA0))
    reach = 0.1 * (bd - abs(B - C)) / (A * d * math.sin(THETA0) / bd)
    xs = THETA0 + reach * np.linspace(-1.0, 1.0, 101)
    pl = {k: (np.longdouble(v) if isinstance(v, float) else v) for k, v in p.items()}
    pl["pivot"] = tuple(np.longdouble(v) for v in p["pivot"])
    pl["D"] = tuple(np.longdouble(v) for v in p["D"])
    ref = cf.four_bar_lean(pl, xs.astype(np.longdouble))
    out = {"lean (numpy)": _err(cf.four_bar_lean(p, xs), ref)}
    for name, jit in (("sweep (numpy)", False), ("sweep (numba, fused)", True)):
        sw = sweep(scene, inputs=xs, jit=jit)
        out[name] = _err({"C.vx": sw.vel["C"][0], "C.vy": sw.vel["C"][1],
                          "C.ax": sw.acc["C"][0], "C.ay": sw.acc["C"][1]}, ref)
    prog = compile_scene(scene)
    sols = [prog.solve(float(x)) for x in xs]
    out["compiled (Python)"] = _err(
        {f"C.{q}{c}": [getattr(s, {"v": "velocity", "a": "acceleration"}[q])("C")[i]
                       for s in sols] for q in "va" for i, c in enumerate("xy")}, ref)
    lean = compile_scene(scene, outputs=("pos", "velocity", "acceleration"))
    sols = [lean.solve(float(x)) for x in xs]
    out["compiled answers only (Python)"] = _err(
        {f"C.{q}{c}": [getattr(s, {"v": "velocity", "a": "acceleration"}[q])("C")[i]
                       for s in sols] for q in "va" for i, c in enumerate("xy")}, ref)
    angle = float(np.min(sweep(scene, inputs=xs).angle_deg))
    return {"gamma": gamma_deg, "angle": angle, "errors": out}


def goal_met(r: dict) -> dict:
    """Each path against the goal: within 2× of the lean closed form (+1e-15)."""
    lean = r["errors"]["lean (numpy)"]
    return {k: v <= 2.0 * lean + 1e-15 for k, v in r["errors"].items() if k != "lean (numpy)"}


def table(rows) -> str:
    names = list(rows[0]["errors"])
    out = ["| γ at C | smallest angle swept | " + " | ".join(names) + " |",
           "|---|---|" + "---|" * len(names)]
    for r in rows:
        met = goal_met(r)
        cells = [f"{r['errors'][k]:.1e}" + ("" if k not in met else
                                            (" ✔" if met[k] else " ✘ (> 2× lean)"))
                 for k in names]
        out.append(f"| {r['gamma']:g}° | {r['angle']:.3g}° | " + " | ".join(cells) + " |")
    return "\n".join(out)


def main() -> int:
    rows = [measure(g) for g in GAMMAS]
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
