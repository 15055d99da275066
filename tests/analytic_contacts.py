"""Independent closed forms for the equivalent-linkage cases (numpy only, no polygons import).

* :func:`four_bar` — a crank O2A at θ turning at ω (uniform), a coupler AP = b, P at c from a
  fixed centre K (the pin in a circular slot of the frame: the equivalent link KP); the
  closure chosen by ``sign`` (which side of A→K P lies on); velocity and acceleration of P by
  the two 2×2 linear solves of the differentiated loop.
* :func:`flat_follower` — an eccentric circle cam (centre at e from the shaft, at θ) under a
  translating flat face perpendicular to the follower's guide through the shaft: the follower
  moves as s = e·sin(θ − γ) + ρ along the guide direction γ + 90°.
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
