"""Independent closed-form kinematics of the dyads added for issue 10, and of the six-bars,
quick returns and presses built from them.

Same method and conventions as :mod:`analytic` (numpy only, no import of ``polygons``): every
link is a complex number l e^{iφ}; each group closes a vector loop, solved for position in
closed form (the closure picked as the one nearest a stated point), differentiated once for
the velocities (a 2×2 real system, Cramer's rule) and again for the accelerations (the same
matrix, the centripetal and Coriolis terms on the right).  A motion is a triple
``(z, v, a)`` of complex numbers: position, velocity, acceleration.  Nothing here draws a
polygon, and a separate check differentiates positions numerically (:func:`fd_check`).
"""
from __future__ import annotations

import cmath
import math

import numpy as np

from analytic import _cross, _solve2


def vec(z: complex) -> np.ndarray:
    return np.array([z.real, z.imag])


def fixed(x, y=None) -> tuple[complex, complex, complex]:
    z = complex(x, y) if y is not None else complex(*x)
    return z, 0j, 0j


def crank(O, r, theta, omega, alpha):
    """Tip of a crank about the motion O: z = O + r e^{iθ}."""
    zo, vo, ao = O
    u = cmath.exp(1j * theta)
    return (zo + r * u, vo + 1j * omega * r * u,
            ao + (1j * alpha - omega * omega) * r * u)


def rates(P, Q):
    """(ω, α) of the rigid line P→Q: ż_QP = iω z_QP, z̈_QP = (iα − ω²) z_QP."""
    d = Q[0] - P[0]
    w = ((Q[1] - P[1]) / d).imag
    al = ((Q[2] - P[2]) / d + w * w).imag
    return w, al


def image(P, Q, along, left=0.0):
    """A point rigid with the line P→Q: X = P + (along + i·left) (Q − P)/|Q − P|."""
    d = Q[0] - P[0]
    w, al = rates(P, Q)
    r = (along + 1j * left) * d / abs(d)
    return P[0] + r, P[1] + 1j * w * r, P[2] + (1j * al - w * w) * r


def _pick(c1, c2, near):
    return c1 if abs(c1 - near) <= abs(c2 - near) else c2


def rrr(P, l1, Q, l2, near):
    """X with |PX| = l1, |QX| = l2 (P, Q moving): X = P + l1 e^{iθ1} = Q + l2 e^{iθ2}.
    Returns (X motion, (ω1, α1), (ω2, α2))."""
    d = Q[0] - P[0]
    dist = abs(d)
    a = (l1 * l1 - l2 * l2 + dist * dist) / (2 * dist)
    h2 = l1 * l1 - a * a
    if h2 <= 0:
        raise ValueError("rrr cannot close")
    u = d / dist
    c = [P[0] + a * u + s * math.sqrt(h2) * 1j * u for s in (1, -1)]
    x = _pick(c[0], c[1], near)
    e1, e2 = (x - P[0]) / l1, (x - Q[0]) / l2
    # i l1 e1 ω1 − i l2 e2 ω2 = vQ − vP
    w1, w2 = _solve2(1j * l1 * e1, -1j * l2 * e2, Q[1] - P[1], "rrr velocity")
    rhs = Q[2] - P[2] + l1 * w1 * w1 * e1 - l2 * w2 * w2 * e2
    a1, a2 = _solve2(1j * l1 * e1, -1j * l2 * e2, rhs, "rrr acceleration")
    v = P[1] + 1j * w1 * l1 * e1
    acc = P[2] + (1j * a1 - w1 * w1) * l1 * e1
    return (x, v, acc), (w1, a1), (w2, a2)


def rrp(P, L, G, phi, near):
    """X with |PX| = L on the fixed line G + s e^{iφ}: X = P + L e^{iθ} = G + s e^{iφ}.
    Returns (X motion, (ω, α) of PX, (s, ṡ, s̈))."""
    e = cmath.exp(1j * phi)
    w0 = G - P[0]
    b = (w0 * e.conjugate()).real
    c = abs(w0) ** 2 - L * L
    disc = b * b - c
    if disc <= 0:
        raise ValueError("rrp cannot close")
    cands = [(-b + s * math.sqrt(disc)) for s in (1, -1)]
    s0 = min(cands, key=lambda s: abs(G + s * e - near))
    x = G + s0 * e
    u = (x - P[0]) / L
    # i L u ω − e ṡ = −vP
    w, sd = _solve2(1j * L * u, -e, -P[1], "rrp velocity")
    al, sdd = _solve2(1j * L * u, -e, -P[2] + L * w * w * u, "rrp acceleration")
    return (x, sd * e, sdd * e), (w, al), (s0, sd, sdd)


def slot(A, B, d=0.0):
    """Pin A (moving) in the slot of a lever pivoted at B (moving), the slot parallel to the
    lever at offset d (left positive): A − B = (t + i d) e^{iφ}, t > 0.
    Returns dict with φ, ω, α of the lever, t, ṫ, ẗ (sliding, positive along e^{iφ}), the
    Coriolis vector 2 i ω ṫ e^{iφ} and the motion of A1 (the lever point under the pin)."""
    r = A[0] - B[0]
    t = math.sqrt(abs(r) ** 2 - d * d)
    phi = cmath.phase(r) - math.atan2(d, t)
    e = cmath.exp(1j * phi)
    k = (t + 1j * d) * e            # = A − B
    # e ṫ + i k ω = vA − vB
    td, w = _solve2(e, 1j * k, A[1] - B[1], "slot velocity")
    cor = 2j * w * td * e
    # e ẗ + i k α = aA − aB − 2iωṫ e + ω² k
    tdd, al = _solve2(e, 1j * k, A[2] - B[2] - cor + w * w * k, "slot acceleration")
    a1 = (A[0], B[1] + 1j * w * k, B[2] + (1j * al - w * w) * k)
    return dict(phi=phi, omega=w, alpha=al, t=t, t_dot=td, t_ddot=tdd, coriolis=cor, A1=a1,
                e=e)


def lever_point(B, phi, w, al, length):
    """The point of a lever at distance ``length`` along e^{iφ} from its pivot B."""
    return crank(B, length, phi, w, al)


def guided(P, L, B, phi, w, al, d, near):
    """The pin X on |PX| = L sliding in the slot of a lever about B at angle φ (rates ω, α),
    slot offset d: X = P + L e^{iθ} = B + (t + i d) e^{iφ}.
    Returns (X motion, (ω, α) of PX, (t, ṫ, ẗ), Coriolis vector, X1 motion)."""
    e = cmath.exp(1j * phi)
    g = B[0] + 1j * d * e
    w0 = g - P[0]
    b = (w0 * e.conjugate()).real
    c = abs(w0) ** 2 - L * L
    disc = b * b - c
    if disc <= 0:
        raise ValueError("guided cannot close")
    ts = [(-b + s * math.sqrt(disc)) for s in (1, -1)]
    t = min(ts, key=lambda t: abs(g + t * e - near))
    x = g + t * e
    u = (x - P[0]) / L
    k = (t + 1j * d) * e
    # X = B + k:  vX = vB + ṫ e + i ω k = vP + i L u θ̇
    #   i L u θ̇ − e ṫ = vB − vP + i ω k
    th_d, td = _solve2(1j * L * u, -e, B[1] - P[1] + 1j * w * k, "guided velocity")
    cor = 2j * w * td * e
    rhs = B[2] - P[2] + cor + (1j * al - w * w) * k + L * th_d * th_d * u
    th_dd, tdd = _solve2(1j * L * u, -e, rhs, "guided acceleration")
    X = (x, P[1] + 1j * th_d * L * u, P[2] + (1j * th_dd - th_d * th_d) * L * u)
    X1 = (x, B[1] + 1j * w * k, B[2] + (1j * al - w * w) * k)
    return X, (th_d, th_dd), (t, td, tdd), cor, X1


def collar(O, theta, w, al, s, sd, sdd):
    """A collar at s along a rod turning about O: z = O + s e^{iθ};
    ż = (ṡ + i s ω) e^{iθ};  z̈ = (s̈ − s ω² + i (s α + 2 ṡ ω)) e^{iθ}."""
    e = cmath.exp(1j * theta)
    return (O[0] + s * e, O[1] + (sd + 1j * s * w) * e,
            O[2] + (sdd - s * w * w + 1j * (s * al + 2 * sd * w)) * e)


def trammel(L, s, sd, sdd, near_up=True):
    """Elliptic trammel: A = (s, 0) on the x axis, B = (0, y) on the y axis, |AB| = L:
    y = ±√(L² − s²), ẏ = −s ṡ / y, ÿ = −(ṡ² + s s̈ + ẏ²) / y (from y² = L² − s²)."""
    y = math.sqrt(L * L - s * s) * (1 if near_up else -1)
    yd = -s * sd / y
    ydd = -(sd * sd + s * sdd + yd * yd) / y
    return complex(0, y), complex(0, yd), complex(0, ydd)


def fd_check(position, x0, rate, rate2, h=1e-4):
    """Velocity and acceleration of ``position(x)`` (complex) by central differences, for an
    input x(t) with ẋ = rate, ẍ = rate2: v = z' ẋ, a = z'' ẋ² + z' ẍ."""
    zp, z0, zm = position(x0 + h), position(x0), position(x0 - h)
    d1 = (zp - zm) / (2 * h)
    d2 = (zp - 2 * z0 + zm) / (h * h)
    return d1 * rate, d2 * rate * rate + d1 * rate2


def crossing_slots(A, Q, B, R):
    """A pin P in the slots of two turning levers: P = A + t1 u1 = B + t2 u2, u1 = (Q − A)/|Q −
    A| turning at (ω1, α1), u2 likewise.  Differentiating the loop once,
    ṫ1 u1 − ṫ2 u2 = Ḃ − Ȧ + i(t2 ω2 u2 − t1 ω1 u1); twice,
    ẗ1 u1 − ẗ2 u2 = B̈ − Ä + 2i(ṫ2 ω2 u2 − ṫ1 ω1 u1) + (iα2 − ω2²) t2 u2 − (iα1 − ω1²) t1 u1.
    Returns (P motion, (t1, ṫ1, ẗ1), (t2, ṫ2, ẗ2)): t along each slot from its pivot."""
    u1 = (Q[0] - A[0]) / abs(Q[0] - A[0])
    u2 = (R[0] - B[0]) / abs(R[0] - B[0])
    w1, al1 = rates(A, Q)
    w2, al2 = rates(B, R)
    t1, t2 = _solve2(u1, -u2, B[0] - A[0], "crossing position")
    td1, td2 = _solve2(u1, -u2, B[1] - A[1] + 1j * (t2 * w2 * u2 - t1 * w1 * u1),
                       "crossing velocity")
    rhs = (B[2] - A[2] + 2j * (td2 * w2 * u2 - td1 * w1 * u1)
           + (1j * al2 - w2 * w2) * t2 * u2 - (1j * al1 - w1 * w1) * t1 * u1)
    tdd1, tdd2 = _solve2(u1, -u2, rhs, "crossing acceleration")
    z = A[0] + t1 * u1
    v = A[1] + td1 * u1 + 1j * w1 * t1 * u1
    a = A[2] + tdd1 * u1 + 2j * w1 * td1 * u1 + (1j * al1 - w1 * w1) * t1 * u1
    return (z, v, a), (t1, td1, tdd1), (t2, td2, tdd2)


__all__ = ["vec", "fixed", "crank", "rates", "image", "rrr", "rrp", "slot", "lever_point",
           "guided", "collar", "trammel", "fd_check", "_cross", "crossing_slots"]

