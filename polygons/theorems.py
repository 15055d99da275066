"""The vector theorems a velocity or acceleration polygon is built from.

Each function states its formula first, then maps the symbols to parameters (as sympy's
``Point.v2pt_theory`` does).  Vectors are plane vectors ``(x, y)``; an angular velocity or
acceleration is the signed scalar ``ω`` of ``ω k`` (CCW positive), so ``ω × r = ω · perp(r)``
with ``perp(x, y) = (-y, x)``.
"""
from __future__ import annotations

import numpy as np


def perp(r) -> np.ndarray:
    """k × r: ``r`` turned 90° counter-clockwise."""
    r = np.asarray(r, dtype=float)
    return np.array([-r[1], r[0]])


def dot(a, b):
    """a · b for plane vectors, or column-wise for (2, N) arrays of them."""
    if np.ndim(a) == 1 and np.ndim(b) == 1:
        return float(np.asarray(a, dtype=float) @ np.asarray(b, dtype=float))
    return a[0] * b[0] + a[1] * b[1]


def norm(a):
    """|a| for a plane vector, or column-wise for a (2, N) array of them (there as
    √(x² + y²): four times faster than ``hypot`` on arrays, equal to within an ulp for any
    vector a mechanism has)."""
    if np.ndim(a) > 1:
        x, y = a[0], a[1]
        return np.sqrt(x * x + y * y)
    return float(np.hypot(a[0], a[1]))


def cross(a, b):
    """z-component of a × b (column-wise for (2, N) arrays of vectors)."""
    c = a[0] * b[1] - a[1] * b[0]
    return float(c) if np.ndim(c) == 0 else c


def relative_velocity(omega: float, r) -> np.ndarray:
    """(v_B)_A = ω × AB.

    The velocity of B relative to A, two points of one rigid link turning at ``omega``;
    ``r`` is the vector AB (from A to B).  Its length is ω·AB and it is perpendicular to AB.
    """
    return omega * perp(r)


def centripetal(omega: float, r) -> np.ndarray:
    """(a_B)_A^n = −ω² AB  (magnitude ω²·AB = v²/AB, directed from B towards A).

    ``r`` is AB (from the centre A to the point B), ``omega`` the link's angular velocity.
    In the polygon it is the vector a → b1.
    """
    return -(omega * omega) * np.asarray(r, dtype=float)


def tangential(alpha: float, r) -> np.ndarray:
    """(a_B)_A^t = α × AB  (magnitude α·AB, perpendicular to AB).

    ``alpha`` is the link's angular acceleration, ``r`` the vector AB.  In the polygon it is
    b1 → b; when α is unknown only its direction is known: the "c line".
    """
    return alpha * perp(r)


def coriolis(omega: float, v_slide) -> np.ndarray:
    """a_cor = 2 ω × v  (magnitude 2ωv, v turned 90° in the sense of ω).

    ``omega`` is the angular velocity of the link carrying the slot, ``v_slide`` the velocity
    of the sliding point relative to that link (along the slot).
    """
    return 2.0 * omega * perp(v_slide)


def angular_velocity(r, v_rel) -> float:
    """ω = (AB × (v_B)_A) / AB²: the angular velocity a relative velocity implies.

    ``r`` is AB, ``v_rel`` the measured velocity of B relative to A (the vector ab).
    """
    r = np.asarray(r, dtype=float)
    return cross(r, v_rel) / dot(r, r)


def angular_acceleration(r, a_rel) -> float:
    """α = (AB × (a_B)_A) / AB²: tangential component of ab divided by AB, signed.

    ``r`` is AB, ``a_rel`` the acceleration of B relative to A (the vector ab); the centripetal
    part is parallel to AB and drops out of the cross product.
    """
    r = np.asarray(r, dtype=float)
    return cross(r, a_rel) / dot(r, r)
