"""The drawing board, emulated: what a careful student should expect from the construction.

The student draws the space diagram at a scale that fits the mechanism in 150 mm of paper, then
the velocity and acceleration polygons each at a scale that makes their largest vector about
100 mm long, running the very step program the staged solver runs (the interpreter kernel of
:mod:`polygons.interpret` with a noisy backend, so every dyad kind is covered): known vectors
first (ω·r ⟂ the crank, the centripetal ω²·r ∥ the link, the Coriolis 2ωv), then lines of
unknown length (⟂ a link, along a guide, along a slot) intersected.  Every stroke carries the
instruments' precision:

* pencil: every point marked or every length set off is within ±0.25 mm (uniform) on paper;
* protractor / set square: every direction drawn is within ±0.25° (uniform);
* rule: every length read off is within ±0.25 mm.

What is *measured* (a relative velocity, to compute ω and then a centripetal term) comes off
the paper with its error.  The Monte Carlo runs ``trials`` independent drawings at each of
``positions`` crank angles, vectorised over both, and reports the relative error of every
answer a tutorial asks for: |v| and |a| of the moving points, ω and α of the links.
"""
from __future__ import annotations

import math

import numpy as np

from .interpret import Backend, Kernel
from .scene import Crank
from .steps import Diagram, Vertices
from .sweep import Program, compile_plan, place, run
from .theorems import norm

PENCIL_MM = 0.25
PROTRACTOR_DEG = 0.25
SPACE_MM = 150.0      # the mechanism's extent on paper
POLYGON_MM = 100.0    # the longest vector of each polygon on paper


class Paper(Backend):
    """The interpreter backend of a drawing board: every stroke of the step program is drawn
    with the instruments' noise, on arrays of N = trials × positions drawings at once.

    ``scales``: diagram → metres (m/s, m/s²) per mm of paper, per drawing (N,)."""

    def __init__(self, rng: np.random.Generator, n: int, scales):
        self.rng = rng
        self.n = n
        self.scales = scales

    def u(self, half):
        return self.rng.uniform(-half, half, self.n)

    def vector(self, diagram, vec):      # set off with rule and protractor
        length = norm(vec) + self.u(PENCIL_MM) * self.scales[diagram]
        angle = np.arctan2(vec[1], vec[0]) + self.u(math.radians(PROTRACTOR_DEG))
        return np.array([length * np.cos(angle), length * np.sin(angle)])

    def direction(self, diagram, d):     # a direction drawn with protractor / set square
        angle = np.arctan2(d[1], d[0]) + self.u(math.radians(PROTRACTOR_DEG))
        return np.array([np.cos(angle), np.sin(angle)])

    def mark(self, diagram, p):          # a point marked with the pencil
        k = self.scales[diagram]
        return p + np.array([self.u(PENCIL_MM) * k, self.u(PENCIL_MM) * k])

    def read(self, value, diagram):      # a length read off with the rule
        return value + self.u(PENCIL_MM) * self.scales[diagram]


def emulate(scene, thetas, trials: int = 200, seed: int = 1) -> dict:
    """Relative errors of a careful student's answers at crank angles ``thetas``.

    The scene's step program (the same steps the staged solver and the sweep run) is executed
    on paper: every point of the space diagram marked with the pencil, every known vector set
    off and every line drawn with the instruments' errors, every vertex where lines meet
    marked, every answer read off with the rule.  Returns ``{"errors": {name: (errors
    (trials, positions), exact (positions,))}, "scales": {...}, "angle_deg": ...}``; every
    error is |drawn − exact| / |exact|."""
    prog: Program = compile_plan(scene)
    xs = np.asarray(thetas, dtype=float)
    exact = run(prog, xs)
    K = len(xs)
    N = trials * K
    rng = np.random.default_rng(seed)
    th = np.tile(xs, trials)

    # scales (metres, m/s, m/s² per mm of paper), chosen per position like a student would
    pts = [lab for lab in exact["pos"] if not isinstance(exact["pos"][lab], tuple)]
    gx = np.array([g[0] for g in prog.ground.values()])
    gy = np.array([g[1] for g in prog.ground.values()])
    allx = np.concatenate([exact["pos"][p][0] for p in pts] + [gx])
    ally = np.concatenate([exact["pos"][p][1] for p in pts] + [gy])
    ks = max(allx.max() - allx.min(), ally.max() - ally.min()) / SPACE_MM
    vmax = np.max([np.hypot(*exact["vel"][p]) for p in pts], axis=0)
    amax = np.max([np.hypot(*exact["acc"][p]) for p in pts], axis=0)
    kv, ka = vmax / POLYGON_MM, amax / POLYGON_MM
    paper = Paper(rng, N, {"space": ks, Diagram.VELOCITY: np.tile(kv, trials),
                           Diagram.ACCELERATION: np.tile(ka, trials)})

    # the space diagram, drawn: every point marked with the pencil
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        pos, _ = place(prog, th)
        drawn = {}
        for lab, p in pos.items():
            p = np.broadcast_to(p, (2, N))
            drawn[lab] = p + np.array([paper.u(PENCIL_MM) * ks, paper.u(PENCIL_MM) * ks])
        omega, alpha = {}, {}
        drv = scene.driver
        if isinstance(drv, Crank):
            omega[drv.link], alpha[drv.link] = prog.rate, prog.rate2
        k = Kernel(scene, drawn, Vertices(scene), paper, omega, alpha, arrays=True)
        for step in prog.steps:
            k.run(step)

    def grid(a):
        return np.asarray(a).reshape(trials, K)

    errors = {}
    given = {drv.link} if isinstance(drv, Crank) else set()
    with np.errstate(invalid="ignore", divide="ignore"):   # an exact zero: no relative error
        _errors(errors, exact, k, paper, pts, prog, given, grid)
    return {"errors": errors, "scales": {"space_m_per_mm": ks,
                                         "velocity_m_s_per_mm": kv.tolist(),
                                         "acceleration_m_s2_per_mm": ka.tolist()},
            "angle_deg": np.degrees(np.arcsin(np.clip(exact["margin"], 0, 1)))}


def _errors(errors, exact, k, paper, pts, prog, given, grid) -> None:
    """|drawn − exact| / |exact| of every point's |v|, |a| and every link's ω, α (NaN where the
    exact value is zero; :func:`summary` leaves those out)."""
    for lab in pts:
        if lab in prog.ground:
            continue
        ve = np.hypot(*exact["vel"][lab])
        ae = np.hypot(*exact["acc"][lab])
        vd = paper.read(norm(k.of(Diagram.VELOCITY, lab)), Diagram.VELOCITY)
        ad = paper.read(norm(k.of(Diagram.ACCELERATION, lab)), Diagram.ACCELERATION)
        errors[f"|v_{lab}|"] = (np.abs(grid(vd) - ve) / ve, ve)
        errors[f"|a_{lab}|"] = (np.abs(grid(ad) - ae) / ae, ae)
    for name, w in k.omega.items():
        if name in given or name not in exact["omega"] or not np.ndim(exact["omega"][name]):
            continue
        we, ae = exact["omega"][name], exact["alpha"][name]
        errors[f"ω_{name}"] = (np.abs(grid(w) - we) / np.abs(we), np.abs(we))
        if name in k.alpha:
            errors[f"α_{name}"] = (np.abs(grid(k.alpha[name]) - ae) / np.abs(ae), np.abs(ae))



def summary(result, min_angle_deg: float = 1.0, floor: float = 1e-3) -> dict:
    """Median and 95th percentile of each answer's relative error over trials and positions,
    leaving out positions within ``min_angle_deg`` of a toggle and answers whose exact value
    is below ``floor`` of its largest (a relative error of a near-zero answer means little)."""
    keep = result["angle_deg"] > min_angle_deg
    out = {}
    for name, (err, ex) in result["errors"].items():
        ok = keep & (ex > floor * np.max(ex))
        e = err[:, ok]
        e = e[np.isfinite(e)]
        if e.size:
            out[name] = {"median": float(np.median(e)), "p95": float(np.percentile(e, 95))}
    return out
