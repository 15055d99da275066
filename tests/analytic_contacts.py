"""Independent closed forms for the equivalent-linkage cases (numpy only, no polygons import).

* :func:`four_bar` — a crank O2A at θ turning at ω (uniform), a coupler AP = b, P at c from a
  fixed centre K (the pin in a circular slot of the frame: the equivalent link KP); the
  closure chosen by ``sign`` (which side of A→K P lies on); velocity and acceleration of P by
  the two 2×2 linear solves of the differentiated loop.
* :func:`flat_follower` — an eccentric circle cam (centre at e from the shaft, at θ) under a
  translating flat face perpendicular to the follower's guide through the shaft: the follower
  moves as s = e·sin(θ − γ) + ρ along the guide direction γ + 90°.
* :func:`oscillating_flat_follower` — the same cam under a flat face along an arm pivoted at
  Q: the face stays tangent, cos φ·dy − sin φ·dx = d (d the cam centre's signed distance to
  the left of the arm line), differentiated implicitly twice by hand.
"""
import math

import numpy as np


def _k(v):
    return np.array([-v[1], v[0]])


def four_bar(O2, r, theta, omega, K, b, c, sign=1.0):
    O2, K = np.asarray(O2, float), np.asarray(K, float)
    A = O2 + r * np.array([math.cos(theta), math.sin(theta)])
    d = np.linalg.norm(K - A)
    x = (b * b - c * c + d * d) / (2 * d)
    h = math.sqrt(b * b - x * x)
    u = (K - A) / d
    P = A + x * u + sign * h * _k(u)
    vA = omega * _k(A - O2)
    # vA + w3 k×(P−A) = w4 k×(P−K)
    M = np.column_stack([_k(P - A), -_k(P - K)])
    w3, w4 = np.linalg.solve(M, -vA)
    vP = w4 * _k(P - K)
    aA = -omega ** 2 * (A - O2)
    rhs = -aA + w3 ** 2 * (P - A) - w4 ** 2 * (P - K)
    a3, a4 = np.linalg.solve(M, rhs)
    aP = -w4 ** 2 * (P - K) + a4 * _k(P - K)
    return {"P": P, "vP": vP, "aP": aP, "omega_AP": w3, "omega_KP": w4, "alpha_AP": a3,
            "alpha_KP": a4}


def flat_follower(e, theta, omega, rho, guide=math.pi / 2):
    """s, v, a of the follower along ``guide`` (the face ⟂ the guide), uniform ω."""
    phi = theta - (guide - math.pi / 2)
    return {"s": e * math.sin(phi) + rho, "v": e * omega * math.cos(phi),
            "a": -e * omega ** 2 * math.sin(phi)}


def oscillating_flat_follower(O, e, theta, omega, Q, rho, side, phi_near, offset=0.0):
    """An eccentric circle cam (centre C at e from the shaft O, at θ, uniform ω) under a flat
    face along an arm pivoted at Q (the face ``offset`` to the left of the arm line; the cam
    on ``side`` +1 left / −1 right): the arm angle φ, its ω and α.

    G(φ, θ) = cos φ·dy − sin φ·dx − d = 0,   dx, dy = C − Q,   d = offset + side·ρ;
    φ' = −G_θ/G_φ,  φ'' = −(G_θθ + 2 G_θφ φ' + G_φφ φ'²)/G_φ  (the closure nearest phi_near)."""
    dx = O[0] + e * math.cos(theta) - Q[0]
    dy = O[1] + e * math.sin(theta) - Q[1]
    d = offset + side * rho
    beta, r = math.atan2(dy, dx), math.hypot(dx, dy)
    roots = (beta - math.asin(d / r), beta - math.pi + math.asin(d / r))
    phi = min(roots, key=lambda p: abs(math.remainder(p - phi_near, 2 * math.pi)))
    dx1, dy1 = -e * math.sin(theta), e * math.cos(theta)
    dx2, dy2 = -e * math.cos(theta), -e * math.sin(theta)
    c, s = math.cos(phi), math.sin(phi)
    g_p = -s * dy - c * dx
    g_t = c * dy1 - s * dx1
    g_tt = c * dy2 - s * dx2
    g_tp = -s * dy1 - c * dx1
    g_pp = -c * dy + s * dx
    p1 = -g_t / g_p
    p2 = -(g_tt + 2 * g_tp * p1 + g_pp * p1 * p1) / g_p
    return {"phi": phi, "omega": p1 * omega, "alpha": p2 * omega * omega}


def wheel_rim_rod_collar(r, omega, alpha, phi, rho, L, xc, sign=1.0):
    """A wheel of radius r rolling on the floor y = 0 (centre W = (0, r) now), turning at ω,
    α (CCW +); a pin B at ρ, φ from W; a rod BC = L to a collar C on the vertical line x = xc
    (above B when ``sign`` > 0).  v_W = −ω r, a_W = −α r along x; v_B = v_W + ω k × WB,
    a_B = a_W + α k × WB − ω² WB; C from (C − B)·(C − B) = L², differentiated twice:
    (C − B)·(v_C − v_B) = 0, (C − B)·(a_C − a_B) + |v_C − v_B|² = 0."""
    W = np.array([0.0, r])
    d = rho * np.array([math.cos(phi), math.sin(phi)])
    B = W + d
    vB = np.array([-omega * r, 0.0]) + omega * _k(d)
    aB = np.array([-alpha * r, 0.0]) + alpha * _k(d) - omega ** 2 * d
    dx = xc - B[0]
    C = np.array([xc, B[1] + sign * math.sqrt(L * L - dx * dx)])
    u = C - B
    vC = (u @ vB) / u[1]                   # u·((0, vC) − vB) = 0
    rel = np.array([0.0, vC]) - vB
    aC = (u @ aB - rel @ rel) / u[1]
    w_rod = (u[0] * rel[1] - u[1] * rel[0]) / (u @ u)
    arel = np.array([0.0, aC]) - aB
    a_rod = (u[0] * arel[1] - u[1] * arel[0]) / (u @ u)
    return {"B": B, "C": C, "v_B": vB, "a_B": aB, "v_C": vC, "a_C": aC, "omega_BC": w_rod,
            "alpha_BC": a_rod}
