"""The drawing board, emulated: what a careful student should expect from the construction.

The student draws the space diagram at a scale that fits the mechanism in 150 mm of paper, then
the velocity and acceleration polygons each at a scale that makes their largest vector about
100 mm long, exactly as :mod:`polygons.plan` lays the construction out: known vectors first
(ω·r ⟂ the crank, the centripetal ω²·r ∥ the link, the Coriolis 2ωv), then lines of unknown
length (⟂ a link, along a guide, along a slot) intersected.  Every stroke carries the
instruments' precision:

* pencil: every point marked or every length set off is within ±0.25 mm (uniform) on paper;
* protractor / set square: every direction drawn is within ±0.25° (uniform);
* rule: every length read off is within ±0.25 mm.

Lengths and speeds that the question *gives* are used exactly in the arithmetic (ω²·AB from
the stated AB); what is *measured* (a relative velocity, to compute a centripetal term) comes
off the paper with its error.  The Monte Carlo runs ``trials`` independent drawings at each of
``positions`` crank angles, vectorised over both, and reports the relative error of every
answer a tutorial asks for: |v| and |a| of the moving points, ω and α of the links.
"""
from __future__ import annotations

import math

import numpy as np

from .errors import UnsupportedError
from .sweep import Program, compile_plan, run

PENCIL_MM = 0.25
PROTRACTOR_DEG = 0.25
SPACE_MM = 150.0      # the mechanism's extent on paper
POLYGON_MM = 100.0    # the longest vector of each polygon on paper


class Paper:
    """Noise of the instruments, on arrays shaped (trials, positions)."""

    def __init__(self, rng: np.random.Generator, shape):
        self.rng = rng
        self.shape = shape

    def u(self, half):
        return self.rng.uniform(-half, half, self.shape)

    def mark(self, p, scale):            # a point marked with the pencil
        return (p[0] + self.u(PENCIL_MM) * scale, p[1] + self.u(PENCIL_MM) * scale)

    def length(self, value, scale):      # a length set off or read with the rule
        return value + self.u(PENCIL_MM) * scale

    def direction(self, angle):          # a direction drawn with protractor / set square
        return angle + self.u(math.radians(PROTRACTOR_DEG))


def _ang(v):
    return np.arctan2(v[1], v[0])


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _polar(length, angle):
    return (length * np.cos(angle), length * np.sin(angle))


def _norm(v):
    return np.hypot(v[0], v[1])


def _meet(p, a1, q, a2):
    """Intersection of the line through p at angle a1 with the line through q at angle a2."""
    d1 = (np.cos(a1), np.sin(a1))
    d2 = (np.cos(a2), np.sin(a2))
    den = d1[0] * d2[1] - d1[1] * d2[0]
    w = _sub(q, p)
    t = (w[0] * d2[1] - w[1] * d2[0]) / den
    return (p[0] + t * d1[0], p[1] + t * d1[1])


def _circles(p, r1, q, r2, sigma):
    d = _sub(q, p)
    d2 = d[0] ** 2 + d[1] ** 2
    af = 0.5 + 0.5 * (r1 * r1 - r2 * r2) / d2
    hf = sigma * np.sqrt(np.maximum(r1 * r1 / d2 - af * af, 0.0))
    return (p[0] + af * d[0] - hf * d[1], p[1] + af * d[1] + hf * d[0])


def emulate(scene, thetas, trials: int = 200, seed: int = 1) -> dict:
    """Relative errors of a careful student's answers at crank angles ``thetas``.

    Returns ``{"per_quantity": {name: errors (trials, positions)}, "exact": {...},
    "scales": {...}}``; every error is |drawn − exact| / |exact|."""
    prog: Program = compile_plan(scene)
    exact = run(prog, np.asarray(thetas, dtype=float))
    rng = np.random.default_rng(seed)
    K = len(thetas)
    shape = (trials, K)
    paper = Paper(rng, shape)
    th = np.broadcast_to(np.asarray(thetas, dtype=float), shape)

    # scales (metres, m/s, m/s² per mm of paper), chosen per position like a student would
    pts = [lab for lab in exact["pos"] if not isinstance(exact["pos"][lab], tuple)]
    xs = np.concatenate([exact["pos"][p][0] for p in pts] + [np.array([g[0] for g in prog.ground.values()])])
    ys = np.concatenate([exact["pos"][p][1] for p in pts] + [np.array([g[1] for g in prog.ground.values()])])
    ks = max(xs.max() - xs.min(), ys.max() - ys.min()) / SPACE_MM
    vmax = np.max([np.hypot(*exact["vel"][p]) for p in pts], axis=0)
    amax = np.max([np.hypot(*exact["acc"][p]) for p in pts], axis=0)
    kv = vmax / POLYGON_MM
    ka = amax / POLYGON_MM

    # ---- the space diagram, drawn
    S: dict = {}
    for lab, g in prog.ground.items():
        S[lab] = paper.mark((np.full(shape, g[0]), np.full(shape, g[1])), ks)
    V: dict = {lab: (np.zeros(shape), np.zeros(shape)) for lab in prog.ground}   # polygon
    A: dict = {lab: (np.zeros(shape), np.zeros(shape)) for lab in prog.ground}
    W: dict = {}
    AL: dict = {}
    w_in = prog.rate
    for op in prog.ops:
        k, X, data = op.kind, op.label, op.data
        if k == "crank":
            pivot, r, link = data
            ang = paper.direction(th)
            S[X] = paper.mark(_add(S[pivot], _polar(paper.length(r, ks), ang)), ks)
        elif k == "rrr":
            p, q, r1, r2, sigma, lp, lq = data
            S[X] = paper.mark(_circles(S[p], paper.length(r1, ks), S[q], paper.length(r2, ks),
                                       sigma), ks)
        elif k == "rrp":
            p, L, g, e, sigma, link = data
            gp = paper.mark((np.full(shape, g[0]), np.full(shape, g[1])), ks)
            ga = paper.direction(np.full(shape, math.atan2(e[1], e[0])))
            # circle (p, L) ∩ guide line
            ex, ey = np.cos(ga), np.sin(ga)
            w = _sub(gp, S[p])
            bq = ex * w[0] + ey * w[1]
            Ld = paper.length(L, ks)
            root = np.sqrt(np.maximum(bq * bq - (w[0] ** 2 + w[1] ** 2 - Ld * Ld), 0.0))
            t = -bq + sigma * root
            S[X] = paper.mark((gp[0] + t * ex, gp[1] + t * ey), ks)
            S[X + "#guide"] = ga
        elif k == "rpr":
            pin, pivot, far, far_len, lever = data
            S[X] = S[pin]
            if far is not None:
                a = paper.direction(_ang(_sub(S[pin], S[pivot])))
                S[far] = paper.mark(_add(S[pivot], _polar(paper.length(far_len, ks), a)), ks)
        else:
            raise UnsupportedError(f"the drawing-board emulation does not draw {k} dyads yet")

    def link_dir(a, b):          # the direction of a drawn link, transferred with a set square
        return paper.direction(_ang(_sub(S[b], S[a])))

    # ---- the velocity polygon (paper mm × kv = m/s)
    for op in prog.ops:
        k, X, data = op.kind, op.label, op.data
        if k == "crank":
            pivot, r, link = data
            d = link_dir(pivot, X) + math.copysign(math.pi / 2, w_in)
            V[X] = paper.mark(_polar(paper.length(abs(w_in) * r, kv), d), kv)
            W[link] = np.full(shape, w_in)
        elif k == "rrr":
            p, q, r1, r2, sigma, lp, lq = data
            x = _meet(V[p], link_dir(p, X) + math.pi / 2, V[q], link_dir(q, X) + math.pi / 2)
            V[X] = paper.mark(x, kv)
            for other, link, L in ((p, lp, r1), (q, lq, r2)):
                rel = _sub(V[X], V[other])
                mag = paper.length(_norm(rel), kv)            # read off with the rule
                sense = np.sign(_cross(_sub(S[X], S[other]), rel))
                W[link] = sense * mag / L
        elif k == "rrp":
            p, L, g, e, sigma, link = data
            x = _meet(V[p], link_dir(p, X) + math.pi / 2, (np.zeros(shape), np.zeros(shape)),
                      S[X + "#guide"])
            V[X] = paper.mark(x, kv)
            rel = _sub(V[X], V[p])
            W[link] = np.sign(_cross(_sub(S[X], S[p]), rel)) * paper.length(_norm(rel), kv) / L
        elif k == "rpr":
            pin, pivot, far, far_len, lever = data
            lev = link_dir(pivot, pin)
            a1 = _meet((np.zeros(shape), np.zeros(shape)), lev + math.pi / 2, V[pin],
                       paper.direction(_ang(_sub(S[pin], S[pivot]))))
            V[X] = paper.mark(a1, kv)
            rho = _norm(_sub(S[pin], S[pivot]))
            rho_read = paper.length(rho, ks)
            W[lever] = (np.sign(_cross(_sub(S[pin], S[pivot]), V[X])) *
                        paper.length(_norm(V[X]), kv) / rho_read)
            slide = _sub(V[pin], V[X])
            S[pin + "#vs"] = (np.sign(slide[0] * np.cos(lev) + slide[1] * np.sin(lev)) *
                             paper.length(_norm(slide), kv))
            S[pin + "#rho"] = rho_read
            if far is not None:
                V[far] = paper.mark(_polar(paper.length(abs(W[lever]) * far_len, kv),
                                           lev + math.copysign(math.pi / 2, 1.0) *
                                           np.sign(W[lever])), kv)

    # ---- the acceleration polygon (paper mm × ka = m/s²)
    for op in prog.ops:
        k, X, data = op.kind, op.label, op.data
        if k == "crank":
            pivot, r, link = data
            d = link_dir(X, pivot)                              # towards the pivot
            A[X] = paper.mark(_polar(paper.length(w_in * w_in * r, ka), d), ka)
            AL[link] = np.full(shape, prog.rate2)
        elif k in ("rrr", "rrp"):
            if k == "rrr":
                p, q, r1, r2, sigma, lp, lq = data
                pairs = ((p, lp, r1), (q, lq, r2))
            else:
                p, L, g, e, sigma, link = data
                pairs = ((p, link, L),)
            ends = []
            for other, link, L in pairs:
                c = _add(A[other], _polar(paper.length(W[link] ** 2 * L, ka),
                                          link_dir(X, other)))      # centripetal, towards
                ends.append((c, link_dir(other, X) + math.pi / 2, other, link, L))
            if k == "rrr":
                x = _meet(ends[0][0], ends[0][1], ends[1][0], ends[1][1])
            else:
                x = _meet(ends[0][0], ends[0][1], (np.zeros(shape), np.zeros(shape)),
                          S[X + "#guide"])
            A[X] = paper.mark(x, ka)
            for c, _, other, link, L in ends:
                tang = _sub(A[X], c)
                AL[link] = (np.sign(_cross(_sub(S[X], S[other]), tang)) *
                            paper.length(_norm(tang), ka) / L)
        elif k == "rpr":
            pin, pivot, far, far_len, lever = data
            lev = link_dir(pivot, pin)
            rho = S[pin + "#rho"]
            k1 = _polar(paper.length(W[lever] ** 2 * rho, ka), lev + math.pi)   # towards B
            k1 = paper.mark(k1, ka)
            cor_mag = 2.0 * np.abs(W[lever] * S[pin + "#vs"])
            cor_dir = lev + math.pi / 2 * np.sign(W[lever] * S[pin + "#vs"])
            # step back from a by the Coriolis vector, then a line along the slot
            back = _sub(A[pin], _polar(paper.length(cor_mag, ka), paper.direction(cor_dir)))
            a1 = _meet(k1, lev + math.pi / 2, back, paper.direction(lev))
            A[X] = paper.mark(a1, ka)
            tang = _sub(A[X], k1)
            AL[lever] = (np.sign(_cross(_polar(1.0, lev), tang)) *
                         paper.length(_norm(tang), ka) / rho)
            if far is not None:
                wl, al = W[lever], AL[lever]
                A[far] = paper.mark(_add(_polar(paper.length(wl * wl * far_len, ka), lev + math.pi),
                                         _polar(paper.length(np.abs(al) * far_len, ka),
                                                lev + math.pi / 2 * np.sign(al))), ka)

    errors = {}
    for lab in V:
        if lab in prog.ground:
            continue
        ve = np.hypot(*exact["vel"][lab])
        ae = np.hypot(*exact["acc"][lab])
        errors[f"|v_{lab}|"] = (np.abs(paper.length(_norm(V[lab]), kv) - ve) / ve, ve)
        errors[f"|a_{lab}|"] = (np.abs(paper.length(_norm(A[lab]), ka) - ae) / ae, ae)
    for name in W:
        if name in exact["omega"] and np.ndim(exact["omega"][name]) and name not in (
                d.link for d in prog.plan.dyads if hasattr(d, "pivot") and hasattr(d, "tip")):
            we = exact["omega"][name]
            ae = exact["alpha"][name]
            errors[f"ω_{name}"] = (np.abs(W[name] - we) / np.abs(we), np.abs(we))
            if name in AL:
                errors[f"α_{name}"] = (np.abs(AL[name] - ae) / np.abs(ae), np.abs(ae))
    return {"errors": errors, "scales": {"space_m_per_mm": ks,
                                         "velocity_m_s_per_mm": kv.tolist(),
                                         "acceleration_m_s2_per_mm": ka.tolist()},
            "angle_deg": np.degrees(np.arcsin(np.clip(exact["margin"], 0, 1)))}


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


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
