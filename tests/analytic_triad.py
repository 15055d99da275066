"""An independent solution of a class-III group (a triad), for the tests: Newton on the six
distance equations of the corners B, C, X, then the rates by a linear solve of the loop
equations differentiated once and twice.  numpy only; no import of ``polygons``.

Unknowns z = (B, C, X) (six coordinates).  Equations, with A, D, E the outer points:
|B − A|² = a², |C − D|² = d², |X − E|² = e², and the plate's three sides |B − C|² = l_BC²,
|C − X|² = l_CX², |B − X|² = l_BX² — each of the form |P − Q|² = l².  Differentiating
(P − Q)·(P − Q) = l² gives (P − Q)·(v_P − v_Q) = 0 and
(P − Q)·(a_P − a_Q) + |v_P − v_Q|² = 0: a 6 × 6 linear system each time (the same matrix
J, the Jacobian of the equations).
"""
from __future__ import annotations

import math

import numpy as np


def _pairs(outer):
    """(i, j) index pairs into the point list [B, C, X, A, D, E] for the six equations."""
    return [(0, 3), (1, 4), (2, 5), (0, 1), (1, 2), (0, 2)]


def _jac(pts):
    J = np.zeros((6, 6))
    for r, (i, j) in enumerate(_pairs(None)):
        d = pts[i] - pts[j]
        if i < 3:
            J[r, 2 * i:2 * i + 2] += d
        if j < 3:
            J[r, 2 * j:2 * j + 2] -= d
    return J


def solve_position(A, D, E, lengths, guess, tol=1e-15, iters=100):
    """Newton from ``guess`` (B, C, X): lengths = (a, d, e, l_BC, l_CX, l_BX)."""
    z = np.array(guess, dtype=float).reshape(6)
    out = [np.array(A, float), np.array(D, float), np.array(E, float)]
    L = np.array(lengths, dtype=float)
    for _ in range(iters):
        pts = [z[0:2], z[2:4], z[4:6]] + out
        F = np.array([(pts[i] - pts[j]) @ (pts[i] - pts[j]) for i, j in _pairs(None)]) - L * L
        step = np.linalg.solve(2.0 * _jac(pts), -F)
        z = z + step
        if np.max(np.abs(step)) < tol * max(1.0, np.max(np.abs(z))):
            break
    return z[0:2].copy(), z[2:4].copy(), z[4:6].copy()


def rates(B, C, X, A, D, E, vA, vD, vE, aA, aD, aE):
    """(vB, vC, vX), (aB, aC, aX) from the differentiated distance equations."""
    pts = [np.asarray(p, float) for p in (B, C, X, A, D, E)]
    J = _jac(pts)
    vo = [np.asarray(v, float) for v in (vA, vD, vE)]
    ao = [np.asarray(a, float) for a in (aA, aD, aE)]
    rhs = np.zeros(6)
    for r, (i, j) in enumerate(_pairs(None)):
        if j >= 3:
            rhs[r] = (pts[i] - pts[j]) @ vo[j - 3]
    v = np.linalg.solve(J, rhs)
    vel = [v[0:2], v[2:4], v[4:6]] + vo
    rhs = np.zeros(6)
    for r, (i, j) in enumerate(_pairs(None)):
        dv = vel[i] - vel[j]
        rhs[r] = -(dv @ dv)
        if j >= 3:
            rhs[r] += (pts[i] - pts[j]) @ ao[j - 3]
    a = np.linalg.solve(J, rhs)
    return (v[0:2], v[2:4], v[4:6]), (a[0:2], a[2:4], a[4:6])


def omega(P, Q, vP, vQ):
    """ω of the line P→Q: ((Q − P) × (v_Q − v_P)) / |Q − P|²."""
    r, dv = np.asarray(Q) - np.asarray(P), np.asarray(vQ) - np.asarray(vP)
    return float((r[0] * dv[1] - r[1] * dv[0]) / (r @ r))


# ---------------------------------------------------------------- every closure, by a scan
def _circle_circle(P, r, Q, s, sigma):
    """The point on the circles (P, r) and (Q, s) on side σ of P→Q, and h² (< 0: none)."""
    w = np.subtract(Q, P)
    dist = np.hypot(*w)
    m = (r * r - s * s + dist * dist) / (2.0 * dist)
    h2 = r * r - m * m
    h = np.sqrt(max(h2, 0.0))
    u = w / dist
    return np.array(P) + m * u + sigma * h * np.array([-u[1], u[0]]), h2


def coupler(A, a, D, d, L, xi, eta, psi, sigma):
    """The four-bar A–B–C–D with the plate on BC: B = A + a u(ψ), C on the circles (B, L)
    and (D, d) on side σ, X = B + R(BC)(ξ, η); (B, C, X, h²)."""
    B = np.array(A) + a * np.array([math.cos(psi), math.sin(psi)])
    C, h2 = _circle_circle(B, L, D, d, sigma)
    ux, uy = (C - B) / L
    X = B + np.array([xi * ux - eta * uy, xi * uy + eta * ux])
    return B, C, X, h2


def _g(A, a, D, d, E, e, L, xi, eta, psi, sigma):
    B, C, X, h2 = coupler(A, a, D, d, L, xi, eta, psi, sigma)
    return (math.hypot(*(X - np.array(E))) - e) if h2 >= 0 else math.nan


def _bisect(f, lo, hi):
    flo = f(lo)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _golden(f, lo, hi, sign):
    """The extremum of f on [lo, hi]: its minimum (sign = +1) or maximum (−1)."""
    g = (math.sqrt(5) - 1) / 2
    c, d = hi - g * (hi - lo), lo + g * (hi - lo)
    fc, fd = sign * f(c), sign * f(d)
    for _ in range(100):
        if fc < fd:
            hi, d, fd = d, c, fc
            c = hi - g * (hi - lo)
            fc = sign * f(c)
        else:
            lo, c, fc = c, d, fd
            d = lo + g * (hi - lo)
            fd = sign * f(d)
    return 0.5 * (lo + hi)


def scan_closures(A, a, D, d, E, e, L, xi, eta, n=4096):
    """Every closure (B, C, X) of the group by a scan of the angle ψ of AB (the four-bar
    ABCD's coupler point X meeting the circle (E, e)) at ``n`` points on both assemblies σ:
    each change of sign bisected; each local extremum of g that does not change sign at the
    samples searched (golden section) for a dip through zero (two close closures); the two
    assemblies joined where they fold (C's circles touch)."""
    roots = []
    psis = np.linspace(0.0, 2 * math.pi, n + 1)
    for sigma in (1.0, -1.0):
        f = (lambda p, s=sigma: _g(A, a, D, d, E, e, L, xi, eta, p, s))
        g = np.array([f(p) for p in psis])
        for k in range(n):
            if np.isfinite(g[k]) and np.isfinite(g[k + 1]) and (g[k] > 0) != (g[k + 1] > 0):
                roots.append((_bisect(f, psis[k], psis[k + 1]), sigma))
        for k in range(1, n):
            w = g[k - 1:k + 2]
            if not np.all(np.isfinite(w)) or len({bool(v > 0) for v in w}) != 1:
                continue
            sign = 1.0 if w[1] > 0 else -1.0
            if sign * w[1] <= sign * w[0] and sign * w[1] <= sign * w[2]:
                x = _golden(f, psis[k - 1], psis[k + 1], sign)
                if (f(x) > 0) != (w[1] > 0):
                    roots.append((_bisect(f, psis[k - 1], x), sigma))
                    roots.append((_bisect(f, x, psis[k + 1]), sigma))
        # the fold: the last valid sample before the circles stop meeting
        ok = np.isfinite(g)
        for k in range(n):
            if ok[k] != ok[k + 1]:
                i, j = (k, k + 1) if ok[k] else (k + 1, k)

                def h2(p):
                    return coupler(A, a, D, d, L, xi, eta, p, 1.0)[3]
                lo, hi = psis[i], psis[j]
                for _ in range(100):
                    mid = 0.5 * (lo + hi)
                    if h2(mid) >= 0:
                        lo = mid
                    else:
                        hi = mid
                gf = f(lo)
                if np.isfinite(gf) and (gf > 0) != (g[i] > 0):
                    roots.append((_bisect(f, psis[i], lo), sigma))
    out = []
    for psi, sigma in roots:
        B, C, X, _ = coupler(A, a, D, d, L, xi, eta, psi, sigma)
        if abs(math.hypot(*(X - np.array(E))) - e) > 1e-9:
            continue
        if all(max(np.max(np.abs(B - o[0])), np.max(np.abs(X - o[2]))) > 1e-9 for o in out):
            out.append((B, C, X))
    return out


def close_group(rng, samples: int = 361):
    """(A, a, D, d, E, e, L, ξ, η): a random group whose X-link length e is within δ
    (1e-9 … 1e-5 m) of an extremum of |X − E| along the four-bar ABCD's coupler curve (found
    on ``samples`` coupler angles, then by golden section): two closures a hair apart."""
    while True:
        A = rng.uniform(-0.1, 0.1, 2)
        D = rng.uniform(0.2, 0.4, 2) * [1, rng.choice([-1, 1])]
        E = rng.uniform(-0.2, 0.4, 2)
        a, d, L = rng.uniform(0.08, 0.3, 3)
        xi, eta = rng.uniform(-0.1, 0.2), rng.uniform(-0.15, 0.15)
        sig = rng.choice([1.0, -1.0])
        psis = np.linspace(0, 2 * math.pi, samples)
        r = np.array([math.hypot(*(X - E)) if h2 >= 0 else np.nan for _, _, X, h2 in
                      (coupler(A, a, D, d, L, xi, eta, p, sig) for p in psis)])
        ks = [k for k in range(1, samples - 1) if np.all(np.isfinite(r[k - 1:k + 2]))
              and (r[k] - r[k - 1]) * (r[k + 1] - r[k]) < 0]
        if not ks:
            continue
        k = int(rng.choice(ks))
        sign = 1.0 if r[k] < r[k - 1] else -1.0

        def f(p):
            return math.hypot(*(coupler(A, a, D, d, L, xi, eta, p, sig)[2] - E))
        e = f(_golden(f, psis[k - 1], psis[k + 1], sign)) + sign * 10 ** rng.uniform(-9, -5)
        return A, a, D, d, E, e, L, xi, eta
