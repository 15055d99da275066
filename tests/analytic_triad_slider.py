"""An independent solution of a class-III group with a block on a guide at a corner (two links
and a block), for the tests: Newton on the corners' six equations, then the rates by a linear
solve of the equations differentiated once and twice; every closure by a dense scan of the
four-bar's coupler curve against the guide.  numpy only; no import of ``polygons``.

Unknowns z = (B, C, X).  Equations, with A, D the links' outer points and the guide through G
of unit normal n: |B − A|² = a², |C − D|² = d², n·(X − G) = 0, and the plate's three sides
|B − C|² = l_BC², |C − X|² = l_CX², |B − X|² = l_BX².  Differentiated: (P − Q)·(v_P − v_Q) = 0,
(P − Q)·(a_P − a_Q) + |v_P − v_Q|² = 0, n·v_X = 0, n·a_X = 0 (the guide fixed).
"""
from __future__ import annotations

import math

import numpy as np

import analytic_triad as at

#: the distance equations (i, j) into [B, C, X, A, D]; row 2 is the guide's
_PAIRS = [(0, 3), (1, 4), None, (0, 1), (1, 2), (0, 2)]


def _jac(pts, n):
    J = np.zeros((6, 6))
    for r, pr in enumerate(_PAIRS):
        if pr is None:
            J[r, 4:6] = n
            continue
        i, j = pr
        d = pts[i] - pts[j]
        J[r, 2 * i:2 * i + 2] += 2 * d
        if j < 3:
            J[r, 2 * j:2 * j + 2] -= 2 * d
    return J


def solve_position(A, D, G, n, lengths, guess, tol=1e-15, iters=100):
    """Newton from ``guess`` (B, C, X): lengths = (a, d, l_BC, l_CX, l_BX)."""
    z = np.array(guess, dtype=float).reshape(6)
    out = [np.array(A, float), np.array(D, float)]
    a, d, lbc, lcx, lbx = lengths
    L = [a, d, None, lbc, lcx, lbx]
    n, G = np.asarray(n, float), np.asarray(G, float)
    for _ in range(iters):
        pts = [z[0:2], z[2:4], z[4:6]] + out
        F = np.array([n @ (pts[2] - G) if pr is None else
                      (pts[pr[0]] - pts[pr[1]]) @ (pts[pr[0]] - pts[pr[1]]) - L[r] ** 2
                      for r, pr in enumerate(_PAIRS)])
        step = np.linalg.solve(_jac(pts, n), -F)
        z = z + step
        if np.max(np.abs(step)) < tol * max(1.0, np.max(np.abs(z))):
            break
    return z[0:2].copy(), z[2:4].copy(), z[4:6].copy()


def rates(B, C, X, A, D, n, vA, vD, aA, aD):
    """(vB, vC, vX), (aB, aC, aX) from the differentiated equations."""
    pts = [np.asarray(p, float) for p in (B, C, X, A, D)]
    n = np.asarray(n, float)
    J = _jac(pts, n)
    vo = [np.asarray(v, float) for v in (vA, vD)]
    ao = [np.asarray(a, float) for a in (aA, aD)]
    rhs = np.zeros(6)
    for r, pr in enumerate(_PAIRS):
        if pr is not None and pr[1] >= 3:
            rhs[r] = 2 * (pts[pr[0]] - pts[pr[1]]) @ vo[pr[1] - 3]
    v = np.linalg.solve(J, rhs)
    vel = [v[0:2], v[2:4], v[4:6]] + vo
    rhs = np.zeros(6)
    for r, pr in enumerate(_PAIRS):
        if pr is None:
            continue
        i, j = pr
        dv = vel[i] - vel[j]
        rhs[r] = -2 * (dv @ dv)
        if j >= 3:
            rhs[r] += 2 * (pts[i] - pts[j]) @ ao[j - 3]
    acc = np.linalg.solve(J, rhs)
    return (v[0:2], v[2:4], v[4:6]), (acc[0:2], acc[2:4], acc[4:6])


def _g(A, a, D, d, G, n, L, xi, eta, psi, sigma):
    B, C, X, h2 = at.coupler(A, a, D, d, L, xi, eta, psi, sigma)
    return float(np.dot(n, X - np.asarray(G))) if h2 >= 0 else math.nan


def scan_closures(A, a, D, d, G, n, L, xi, eta, samples=4096):
    """Every closure (B, C, X) by a scan of the angle ψ of AB at ``samples`` points on both
    assemblies σ of the four-bar A B C D: each change of sign of n·(X − G) bisected, each local
    extremum that keeps its sign searched (golden section) for a dip through zero, the two
    assemblies joined where they fold."""
    roots = []
    psis = np.linspace(0.0, 2 * math.pi, samples + 1)
    for sigma in (1.0, -1.0):
        f = (lambda p, s=sigma: _g(A, a, D, d, G, n, L, xi, eta, p, s))
        g = np.array([f(p) for p in psis])
        for k in range(samples):
            if np.isfinite(g[k]) and np.isfinite(g[k + 1]) and (g[k] > 0) != (g[k + 1] > 0):
                roots.append((at._bisect(f, psis[k], psis[k + 1]), sigma))
        for k in range(1, samples):
            w = g[k - 1:k + 2]
            if not np.all(np.isfinite(w)) or len({bool(v > 0) for v in w}) != 1:
                continue
            sign = 1.0 if w[1] > 0 else -1.0
            if sign * w[1] <= sign * w[0] and sign * w[1] <= sign * w[2]:
                x = at._golden(f, psis[k - 1], psis[k + 1], sign)
                if (f(x) > 0) != (w[1] > 0):
                    roots.append((at._bisect(f, psis[k - 1], x), sigma))
                    roots.append((at._bisect(f, x, psis[k + 1]), sigma))
        ok = np.isfinite(g)
        for k in range(samples):
            if ok[k] != ok[k + 1]:
                i, j = (k, k + 1) if ok[k] else (k + 1, k)
                lo, hi = psis[i], psis[j]
                for _ in range(100):
                    mid = 0.5 * (lo + hi)
                    if at.coupler(A, a, D, d, L, xi, eta, mid, 1.0)[3] >= 0:
                        lo = mid
                    else:
                        hi = mid
                gf = f(lo)
                if np.isfinite(gf) and (gf > 0) != (g[i] > 0):
                    roots.append((at._bisect(f, psis[i], lo), sigma))
    out = []
    for psi, sigma in roots:
        B, C, X, _ = at.coupler(A, a, D, d, L, xi, eta, psi, sigma)
        if abs(float(np.dot(n, X - np.asarray(G)))) > 1e-9:
            continue
        if all(max(np.max(np.abs(B - o[0])), np.max(np.abs(X - o[2]))) > 1e-9 for o in out):
            out.append((B, C, X))
    return out


def random_group(rng, close: bool = False, samples: int = 181):
    """(A, a, D, d, G, n, L, ξ, η): a random group; with ``close`` the guide is within δ
    (1e-9 … 1e-5 m) of an extremum of n·X along the coupler curve (two closures a hair
    apart)."""
    while True:
        A = rng.uniform(-0.1, 0.1, 2)
        D = rng.uniform(0.2, 0.4, 2) * [1, rng.choice([-1, 1])]
        a, d, L = rng.uniform(0.08, 0.3, 3)
        xi, eta = rng.uniform(-0.1, 0.2), rng.uniform(-0.15, 0.15)
        th = rng.uniform(0, math.pi)
        n = np.array([-math.sin(th), math.cos(th)])
        if not close:
            return A, a, D, d, n * rng.uniform(-0.2, 0.4), n, L, xi, eta
        sig = rng.choice([1.0, -1.0])
        psis = np.linspace(0, 2 * math.pi, samples)
        h = np.array([float(n @ X) if h2 >= 0 else np.nan for _, _, X, h2 in
                      (at.coupler(A, a, D, d, L, xi, eta, p, sig) for p in psis)])
        ks = [k for k in range(1, samples - 1) if np.all(np.isfinite(h[k - 1:k + 2]))
              and (h[k] - h[k - 1]) * (h[k + 1] - h[k]) < 0]
        if not ks:
            continue
        k = int(rng.choice(ks))
        sign = 1.0 if h[k] < h[k - 1] else -1.0

        def f(p):
            return float(n @ at.coupler(A, a, D, d, L, xi, eta, p, sig)[2])
        off = f(at._golden(f, psis[k - 1], psis[k + 1], sign)) + sign * 10 ** rng.uniform(-9, -5)
        return A, a, D, d, n * off, n, L, xi, eta
