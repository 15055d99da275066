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
