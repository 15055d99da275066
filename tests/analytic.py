"""Independent closed-form kinematics of three planar mechanisms.

This module is the *analytic oracle* for the graphical solver in
``polygons``.  It deliberately depends on nothing but numpy: no shapely, no
import of ``polygons``.

Method (the same for every mechanism)
-------------------------------------
Every link is a complex number ``l * exp(i*phi)`` (x = real part, y =
imaginary part).  The mechanism closes a vector loop::

    sum_k  l_k exp(i phi_k)  =  0                          (position)

1. *Position*: the loop is solved in closed form (circle/circle or
   circle/line intersection), the assembly branch picked as documented.
2. *Velocity*: differentiate the loop once in time.  With
   ``d/dt exp(i phi) = i phi_dot exp(i phi)`` the result is LINEAR in the two
   unknown rates; split it into real and imaginary parts and solve the
   2x2 real system exactly (Cramer's rule, :func:`_solve2`).
3. *Acceleration*: differentiate again.  The matrix is the same as for the
   velocities; the known terms (input alpha, all centripetal ``-l w^2`` and
   Coriolis ``2 i l_dot w`` terms) go to the right-hand side.

No finite differences are used in the closed forms.  A separate, cruder
numerical check is provided by :func:`central_difference` and the
``*_fd`` helpers, which differentiate only the *position* solution.

Conventions
-----------
SI units; x right, y up; every angle in radians CCW from +x; omega / alpha
are signed scalars, CCW positive.  Points and vectors are returned as numpy
arrays of shape (2,), scalars as Python floats.  ``perp(v)`` means ``v``
rotated by +90 deg, i.e. ``(-v_y, v_x)`` (multiplication by ``i``).

``ValueError`` is raised when a mechanism cannot be assembled in the given
position (or is exactly at a singular/toggle position where the rates are
undefined).
"""

from __future__ import annotations

import cmath
import math
from typing import Callable

import numpy as np

__all__ = [
    "slider_crank",
    "four_bar",
    "slotted_lever",
    "central_difference",
    "slider_crank_fd",
    "four_bar_fd",
    "slotted_lever_fd",
]

# relative size below which a 2x2 determinant is treated as singular
_SINGULAR_TOL = 1e-12


# ----------------------------------------------------------------------------
# small complex-number helpers
# ----------------------------------------------------------------------------
def _pt(p, name: str) -> complex:
    """Array-like of shape (2,) -> complex number x + i y."""
    a = np.asarray(p, dtype=float).reshape(-1)
    if a.shape != (2,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be a finite 2-vector, got {p!r}")
    return complex(a[0], a[1])


def _vec(z: complex) -> np.ndarray:
    """Complex number -> numpy array [x, y]."""
    return np.array([z.real, z.imag], dtype=float)


def _cross(a: complex, b: complex) -> float:
    """z-component of the planar cross product a x b."""
    return a.real * b.imag - a.imag * b.real


def _positive(value, name: str) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{name} must be a positive finite length, got {value!r}")
    return v


def _finite(value, name: str) -> float:
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return v


def _branch(value) -> int:
    if value not in (1, -1):
        raise ValueError(f"branch must be +1 or -1, got {value!r}")
    return int(value)


def _solve2(c1: complex, c2: complex, rhs: complex, what: str) -> tuple[float, float]:
    """Solve ``x*c1 + y*c2 = rhs`` for REAL x, y (c1, c2, rhs complex).

    This is the 2x2 real system [Re c1  Re c2; Im c1  Im c2] [x; y] = [Re rhs;
    Im rhs], solved by Cramer's rule with determinant cross(c1, c2).
    """
    det = _cross(c1, c2)
    scale = abs(c1) * abs(c2)
    if scale == 0.0 or abs(det) <= _SINGULAR_TOL * scale:
        raise ValueError(
            f"{what}: singular loop equation (toggle / dead-centre position), "
            "the rates are not defined"
        )
    x = _cross(rhs, c2) / det
    y = _cross(c1, rhs) / det
    return x, y


# ----------------------------------------------------------------------------
# position solutions (shared by the closed forms and the *_fd helpers)
# ----------------------------------------------------------------------------
def _slider_crank_position(O, r, L, theta, line_point, line_dir, branch):
    o = _pt(O, "O")
    p0 = _pt(line_point, "line_point")
    r = _positive(r, "r")
    L = _positive(L, "L")
    theta = _finite(theta, "theta")
    psi = _finite(line_dir, "line_dir")
    branch = _branch(branch)

    e2 = complex(math.cos(theta), math.sin(theta))
    u = complex(math.cos(psi), math.sin(psi))
    a = o + r * e2
    d = a - p0
    along = d.real * u.real + d.imag * u.imag  # d . u
    off = _cross(u, d)  # signed distance of A from the line
    disc = L * L - off * off
    if disc < 0.0:
        raise ValueError(
            f"slider_crank cannot assemble: crank pin is {abs(off):.6g} from the "
            f"slider line but the rod is only {L:.6g} long"
        )
    s = along + branch * math.sqrt(disc)
    b = p0 + s * u
    phi = math.atan2((b - a).imag, (b - a).real)
    return o, p0, u, e2, a, b, s, phi, r, L, theta


def _circle_circle(c1: complex, r1: float, c2: complex, r2: float, what: str):
    """Both intersections of circle(c1, r1) and circle(c2, r2)."""
    dz = c2 - c1
    d = abs(dz)
    if d == 0.0:
        raise ValueError(f"{what} cannot assemble: coincident circle centres")
    if d > r1 + r2 or d < abs(r1 - r2):
        raise ValueError(
            f"{what} cannot assemble: distance {d:.6g} outside "
            f"[{abs(r1 - r2):.6g}, {r1 + r2:.6g}]"
        )
    a = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    ez = dz / d
    base = c1 + a * ez
    return base + h * 1j * ez, base - h * 1j * ez


def _four_bar_position(A, D, AB, BC, CD, theta, branch):
    a = _pt(A, "A")
    d = _pt(D, "D")
    AB = _positive(AB, "AB")
    BC = _positive(BC, "BC")
    CD = _positive(CD, "CD")
    theta = _finite(theta, "theta")
    branch = _branch(branch)

    e2 = complex(math.cos(theta), math.sin(theta))
    b = a + AB * e2
    ground = d - a
    if abs(ground) == 0.0:
        raise ValueError("four_bar: A and D coincide, the branch side is undefined")
    c_plus, c_minus = _circle_circle(b, BC, d, CD, "four_bar")
    ok = [c for c in (c_plus, c_minus) if branch * _cross(ground, c - a) > 0.0]
    if len(ok) == 2 and c_plus != c_minus:
        raise ValueError(
            "four_bar: both assembly modes lie on the same side of the line A->D, "
            "so branch=%+d does not identify one of them" % branch
        )
    if not ok:
        raise ValueError(
            "four_bar cannot assemble with C on the %s of A->D (branch=%+d)"
            % ("left" if branch > 0 else "right", branch)
        )
    c = ok[0]
    th3 = math.atan2((c - b).imag, (c - b).real)
    th4 = math.atan2((c - d).imag, (c - d).real)
    return a, d, b, c, e2, th3, th4, AB, BC, CD, theta


def _slotted_lever_position(O, r, theta, B):
    o = _pt(O, "O")
    bz = _pt(B, "B")
    r = _positive(r, "r")
    theta = _finite(theta, "theta")
    e2 = complex(math.cos(theta), math.sin(theta))
    a = o + r * e2
    s = abs(a - bz)
    if s == 0.0:
        raise ValueError(
            "slotted_lever cannot assemble: the crank pin is on the lever pivot B, "
            "the slot direction is undefined"
        )
    phi = math.atan2((a - bz).imag, (a - bz).real)
    return o, bz, e2, a, s, phi, r, theta


# ----------------------------------------------------------------------------
# closed forms
# ----------------------------------------------------------------------------
def slider_crank(O, r, L, theta, omega, alpha, line_point, line_dir, branch):
    """Slider-crank (RRRP) with the slider on an arbitrary fixed line.

    Loop equation (complex numbers, u = exp(i*psi))::

        O + r e^{i theta} + L e^{i phi} = P0 + s u

        d/dt :  i r w e^{i theta} + i L w3 e^{i phi} = s' u
        d2/dt2: (i a - w^2) r e^{i theta} + (i a3 - w3^2) L e^{i phi} = s'' u

    Unknowns (phi, s) from the circle/line intersection, then (w3, s') and
    (a3, s'') from the two linear 2x2 systems, which share the matrix
    [i L e^{i phi}, -u].

    Symbols -> parameters: O = ``O`` (crank pivot), r = ``r`` (crank O->A),
    theta = ``theta``, w = ``omega``, a = ``alpha`` (crank); L = ``L`` (rod
    A->B), phi = rod angle, w3 = ``omega_AB``, a3 = ``alpha_AB``; P0 =
    ``line_point``, psi = ``line_dir`` (direction angle of the slider line),
    s = ``s`` (signed position of B along u measured from P0).
    ``branch`` = +1 takes the root with larger s (B further along +u),
    -1 the root with smaller s.

    Returns a dict with keys ``A, B, vA, vB, aA, aB`` (arrays), ``omega_AB,
    alpha_AB, s, s_dot, s_ddot`` (floats) and the extra ``phi_AB`` (rod angle
    of A->B, radians).  Raises ValueError if the rod cannot reach the line or
    at a toggle position (rod perpendicular to the line).
    """
    omega = _finite(omega, "omega")
    alpha = _finite(alpha, "alpha")
    o, p0, u, e2, a, b, s, phi, r, L, theta = _slider_crank_position(
        O, r, L, theta, line_point, line_dir, branch
    )
    e3 = complex(math.cos(phi), math.sin(phi))
    col_w3 = 1j * L * e3
    col_s = -u

    vA = 1j * r * omega * e2
    w3, s_dot = _solve2(col_w3, col_s, -vA, "slider_crank velocity")

    aA = (1j * alpha - omega * omega) * r * e2
    rhs = -(aA - w3 * w3 * L * e3)
    a3, s_ddot = _solve2(col_w3, col_s, rhs, "slider_crank acceleration")

    return {
        "A": _vec(a),
        "B": _vec(b),
        "vA": _vec(vA),
        "vB": _vec(s_dot * u),
        "aA": _vec(aA),
        "aB": _vec(s_ddot * u),
        "omega_AB": float(w3),
        "alpha_AB": float(a3),
        "s": float(s),
        "s_dot": float(s_dot),
        "s_ddot": float(s_ddot),
        "phi_AB": float(phi),
    }


def four_bar(A, D, AB, BC, CD, theta, omega, alpha, branch):
    """Four-bar linkage A-B-C-D (RRRR) with fixed pivots A and D.

    Loop equation (complex numbers)::

        A + AB e^{i theta} + BC e^{i th3} = D + CD e^{i th4}

        d/dt :  i AB w e^{i theta} + i BC w3 e^{i th3} = i CD w4 e^{i th4}
        d2/dt2: (i a - w^2) AB e^{i theta} + (i a3 - w3^2) BC e^{i th3}
                    = (i a4 - w4^2) CD e^{i th4}

    Positions: B = A + AB e^{i theta}; C = intersection of circle(B, BC) and
    circle(D, CD).  Rates: (w3, w4) and then (a3, a4) from two linear 2x2
    systems sharing the matrix [i BC e^{i th3}, -i CD e^{i th4}].

    Symbols -> parameters: A = ``A``, D = ``D`` (fixed pivots); AB, BC, CD =
    ``AB`` (crank A->B), ``BC`` (coupler B->C), ``CD`` (rocker D->C);
    theta = ``theta``, w = ``omega``, a = ``alpha`` (crank); th3, w3, a3 =
    coupler angle of B->C, ``omega_BC``, ``alpha_BC``; th4, w4, a4 = rocker
    angle of D->C, ``omega_CD``, ``alpha_CD``.
    ``branch`` = +1: C on the LEFT of the directed line A->D
    (cross(D-A, C-A) > 0); -1: on the right.  If both assembly modes lie on
    the same side of A->D the branch is ambiguous and ValueError is raised
    (never a silent choice).

    Returns a dict with keys ``B, C, vB, vC, aB, aC`` (arrays), ``omega_BC,
    alpha_BC, omega_CD, alpha_CD`` (floats) and the extras ``phi_BC,
    phi_CD`` (angles of B->C and D->C, radians).  Raises ValueError if the
    loop cannot close or at a toggle position (coupler parallel to rocker).
    """
    omega = _finite(omega, "omega")
    alpha = _finite(alpha, "alpha")
    a, d, b, c, e2, th3, th4, AB, BC, CD, theta = _four_bar_position(
        A, D, AB, BC, CD, theta, branch
    )
    e3 = complex(math.cos(th3), math.sin(th3))
    e4 = complex(math.cos(th4), math.sin(th4))
    col3 = 1j * BC * e3
    col4 = -1j * CD * e4

    vB = 1j * AB * omega * e2
    w3, w4 = _solve2(col3, col4, -vB, "four_bar velocity")

    aB = (1j * alpha - omega * omega) * AB * e2
    rhs = -aB + w3 * w3 * BC * e3 - w4 * w4 * CD * e4
    a3, a4 = _solve2(col3, col4, rhs, "four_bar acceleration")

    vC = 1j * CD * w4 * e4
    aC = (1j * a4 - w4 * w4) * CD * e4
    return {
        "B": _vec(b),
        "C": _vec(c),
        "vB": _vec(vB),
        "vC": _vec(vC),
        "aB": _vec(aB),
        "aC": _vec(aC),
        "omega_BC": float(w3),
        "alpha_BC": float(a3),
        "omega_CD": float(w4),
        "alpha_CD": float(a4),
        "phi_BC": float(th3),
        "phi_CD": float(th4),
    }


def slotted_lever(O, r, theta, omega, alpha, B):
    """Crank + slotted lever (RPR inversion, quick-return / Whitworth core).

    Loop equation (complex numbers)::

        O + r e^{i theta} = B + s e^{i phi}

        d/dt :  i r w e^{i theta} = s' e^{i phi} + i s w4 e^{i phi}
        d2/dt2: (i a - w^2) r e^{i theta}
                  = (s'' - s w4^2) e^{i phi} + (s a4 + 2 s' w4) i e^{i phi}

    The last term ``2 s' w4 i e^{i phi}`` is the Coriolis acceleration.
    Positions: A = O + r e^{i theta}, s = |A - B|, phi = arg(A - B).  Rates:
    (s', w4) and then (s'', a4) from two linear 2x2 systems sharing the
    matrix [e^{i phi}, i s e^{i phi}] (determinant s, never singular once
    assembled).

    Symbols -> parameters: O = ``O`` (crank pivot), r = ``r`` (crank O->A),
    theta = ``theta``, w = ``omega``, a = ``alpha`` (crank); B = ``B`` (fixed
    lever pivot; the slot passes through B); phi = ``phi`` (lever angle of
    B->A), w4 = ``omega_lever``, a4 = ``alpha_lever``; s = ``s`` = |BA|,
    s' = ``s_dot``, s'' = ``s_ddot`` (sliding velocity / acceleration of the
    pin along the slot, positive away from B).

    Returns a dict with keys ``A, vA, aA`` (arrays; pin A = crank point),
    ``phi, omega_lever, alpha_lever, s, s_dot, s_ddot`` (floats),
    ``coriolis`` (array: 2 w4 s' perp(unit(B->A)), i.e. 2 omega x v_rel),
    ``vA1, aA1`` (arrays: velocity/acceleration of the lever point A1
    coincident with A: vA1 = w4 s perp(e), aA1 = (a4 perp(e) - w4^2 e) s).
    Identities: vA = vA1 + s' e;  aA = aA1 + s'' e + coriolis.
    Raises ValueError if the pin sits on the pivot B (s = 0).
    """
    omega = _finite(omega, "omega")
    alpha = _finite(alpha, "alpha")
    o, bz, e2, a, s, phi, r, theta = _slotted_lever_position(O, r, theta, B)
    e = complex(math.cos(phi), math.sin(phi))
    col_s = e
    col_w = 1j * s * e

    vA = 1j * r * omega * e2
    s_dot, w4 = _solve2(col_s, col_w, vA, "slotted_lever velocity")

    aA = (1j * alpha - omega * omega) * r * e2
    cor = 2.0 * w4 * s_dot * 1j * e
    rhs = aA + s * w4 * w4 * e - cor
    s_ddot, a4 = _solve2(col_s, col_w, rhs, "slotted_lever acceleration")

    vA1 = 1j * s * w4 * e
    aA1 = (1j * a4 - w4 * w4) * s * e
    return {
        "A": _vec(a),
        "vA": _vec(vA),
        "aA": _vec(aA),
        "phi": float(phi),
        "omega_lever": float(w4),
        "alpha_lever": float(a4),
        "s": float(s),
        "s_dot": float(s_dot),
        "s_ddot": float(s_ddot),
        "coriolis": _vec(cor),
        "vA1": _vec(vA1),
        "aA1": _vec(aA1),
    }


# ----------------------------------------------------------------------------
# numerical (finite-difference) cross-check
# ----------------------------------------------------------------------------
def _wrap(x):
    """Wrap angles (array or scalar) to (-pi, pi]."""
    return np.mod(np.asarray(x, dtype=float) + np.pi, 2.0 * np.pi) - np.pi


def central_difference(
    f: Callable[[float], object],
    theta: float,
    omega: float,
    h: float = 1e-3,
    alpha: float = 0.0,
    angle: bool = False,
) -> dict:
    """Time derivatives of any position function x(theta) by central differences.

    ``f(theta)`` returns a scalar or array (a point, a slider position, a link
    angle...).  With the crank driven at ``omega`` and ``alpha`` the chain rule
    gives::

        x_dot  = x'(theta) * omega
        x_ddot = x''(theta) * omega**2 + x'(theta) * alpha

    x' and x'' are estimated with the fourth-order five-point central
    stencils (step ``h`` in radians of crank angle)::

        x'  ~ (-x(+2h) + 8 x(+h) - 8 x(-h) + x(-2h)) / (12 h)
        x'' ~ (-x(+2h) + 16 x(+h) - 30 x(0) + 16 x(-h) - x(-2h)) / (12 h^2)

    Truncation error is O(h^4), round-off O(eps/h^2); h = 1e-3 gives about
    1e-9..1e-10 relative agreement on smooth, well-conditioned positions.
    With ``angle=True`` the samples are treated as angles and unwrapped
    relative to x(theta) (use this for link angles).

    Returns ``{"x", "dx_dtheta", "d2x_dtheta2", "v", "a"}`` (floats or arrays).
    """
    theta = float(theta)
    h = float(h)
    if not (h > 0.0):
        raise ValueError("h must be positive")
    x0 = np.asarray(f(theta), dtype=float)
    samples = {}
    for k in (-2, -1, 1, 2):
        xk = np.asarray(f(theta + k * h), dtype=float)
        samples[k] = x0 + _wrap(xk - x0) if angle else xk
    d1 = (-samples[2] + 8.0 * samples[1] - 8.0 * samples[-1] + samples[-2]) / (12.0 * h)
    d2 = (
        -samples[2] + 16.0 * samples[1] - 30.0 * x0 + 16.0 * samples[-1] - samples[-2]
    ) / (12.0 * h * h)

    def out(x):
        return float(x) if np.ndim(x) == 0 else np.asarray(x, dtype=float)

    return {
        "x": out(x0),
        "dx_dtheta": out(d1),
        "d2x_dtheta2": out(d2),
        "v": out(d1 * omega),
        "a": out(d2 * omega * omega + d1 * alpha),
    }


def slider_crank_fd(O, r, L, theta, omega, alpha, line_point, line_dir, branch, h=1e-3):
    """Finite-difference version of :func:`slider_crank` (same keys).

    Only the closed-form POSITION solution is used; every rate comes from
    :func:`central_difference`.  Crude check, not an oracle.
    """
    def pos(t):
        return _slider_crank_position(O, r, L, t, line_point, line_dir, branch)

    o, p0, u, e2, a, b, s, phi, *_ = pos(theta)
    A = central_difference(lambda t: _vec(pos(t)[4]), theta, omega, h, alpha)
    Bd = central_difference(lambda t: _vec(pos(t)[5]), theta, omega, h, alpha)
    S = central_difference(lambda t: pos(t)[6], theta, omega, h, alpha)
    P = central_difference(lambda t: pos(t)[7], theta, omega, h, alpha, angle=True)
    return {
        "A": _vec(a), "B": _vec(b),
        "vA": A["v"], "vB": Bd["v"], "aA": A["a"], "aB": Bd["a"],
        "omega_AB": P["v"], "alpha_AB": P["a"],
        "s": float(s), "s_dot": S["v"], "s_ddot": S["a"],
        "phi_AB": float(phi),
    }


def four_bar_fd(A, D, AB, BC, CD, theta, omega, alpha, branch, h=1e-3):
    """Finite-difference version of :func:`four_bar` (same keys).

    Only the closed-form POSITION solution is used; every rate comes from
    :func:`central_difference`.  Crude check, not an oracle.
    """
    def pos(t):
        return _four_bar_position(A, D, AB, BC, CD, t, branch)

    a, d, b, c, e2, th3, th4, *_ = pos(theta)
    Bd = central_difference(lambda t: _vec(pos(t)[2]), theta, omega, h, alpha)
    Cd = central_difference(lambda t: _vec(pos(t)[3]), theta, omega, h, alpha)
    T3 = central_difference(lambda t: pos(t)[5], theta, omega, h, alpha, angle=True)
    T4 = central_difference(lambda t: pos(t)[6], theta, omega, h, alpha, angle=True)
    return {
        "B": _vec(b), "C": _vec(c),
        "vB": Bd["v"], "vC": Cd["v"], "aB": Bd["a"], "aC": Cd["a"],
        "omega_BC": T3["v"], "alpha_BC": T3["a"],
        "omega_CD": T4["v"], "alpha_CD": T4["a"],
        "phi_BC": float(th3), "phi_CD": float(th4),
    }


def slotted_lever_fd(O, r, theta, omega, alpha, B, h=1e-3):
    """Finite-difference version of :func:`slotted_lever` (same keys).

    Only the closed-form POSITION solution is used for A, s and phi; the
    Coriolis term and the lever-point quantities vA1, aA1 are then rebuilt
    from the differentiated s and phi with their textbook definitions.
    Crude check, not an oracle.
    """
    def pos(t):
        return _slotted_lever_position(O, r, t, B)

    o, bz, e2, a, s, phi, *_ = pos(theta)
    Ad = central_difference(lambda t: _vec(pos(t)[3]), theta, omega, h, alpha)
    S = central_difference(lambda t: pos(t)[4], theta, omega, h, alpha)
    P = central_difference(lambda t: pos(t)[5], theta, omega, h, alpha, angle=True)
    w4, a4, s_dot = P["v"], P["a"], S["v"]
    e = complex(math.cos(phi), math.sin(phi))
    return {
        "A": _vec(a), "vA": Ad["v"], "aA": Ad["a"],
        "phi": float(phi), "omega_lever": w4, "alpha_lever": a4,
        "s": float(s), "s_dot": s_dot, "s_ddot": S["a"],
        "coriolis": _vec(2.0 * w4 * s_dot * 1j * e),
        "vA1": _vec(1j * s * w4 * e),
        "aA1": _vec((1j * a4 - w4 * w4) * s * e),
    }


# ----------------------------------------------------------------------------
# rigid points and the Scotch yoke (closed forms by hand)
# ----------------------------------------------------------------------------
def coupler_point(B, vB, aB, phi, w, a, along, left):
    """A point P rigid with a link through B at angle ``phi`` (turning at w, a)::

        P = B + (along + i left) e^{i phi}
        v_P = v_B + i w (along + i left) e^{i phi}
        a_P = a_B + (i a - w^2) (along + i left) e^{i phi}

    Symbols -> parameters: B, v_B, a_B = ``B``, ``vB``, ``aB`` (2-vectors); phi = ``phi``
    (the link's angle, e.g. ``phi_BC`` of :func:`four_bar`), w, a = ``w``, ``a`` (its
    ``omega_BC``, ``alpha_BC``); (along, left) = the point's coordinates along the link from B
    and to its left.
    """
    rho = complex(_finite(along, "along"), _finite(left, "left")) * cmath.exp(1j * phi)
    b, vb, ab = (complex(x[0], x[1]) for x in (B, vB, aB))
    return {"P": _vec(b + rho), "vP": _vec(vb + 1j * w * rho),
            "aP": _vec(ab + (1j * a - w * w) * rho)}


def scotch_yoke(O, r, theta, omega, alpha, G, guide_dir, slot_dir):
    """Scotch yoke: crank pin P = O + r e^{i theta} slides in the yoke's slot (direction f);
    the yoke translates on its guide through G (direction e).  Its point on the guide::

        Y = G + t e,  t = ((P − G) × f) / (e × f)
        ṫ = (v_P × f) / (e × f),  ẗ = (a_P × f) / (e × f)

    with v_P = i w r e^{i theta}, a_P = (i a − w²) r e^{i theta}.  Symbols -> parameters:
    O, r, theta, w, a = ``O``, ``r``, ``theta``, ``omega``, ``alpha``; G = ``G``; e, f = unit
    vectors at ``guide_dir`` and ``slot_dir`` (radians).
    """
    o = _pt(O, "O")
    g = _pt(G, "G")
    p = o + r * cmath.exp(1j * theta)
    vp = 1j * omega * r * cmath.exp(1j * theta)
    ap = (1j * alpha - omega * omega) * r * cmath.exp(1j * theta)
    e, f = cmath.exp(1j * guide_dir), cmath.exp(1j * slot_dir)
    den = _cross(e, f)
    t = _cross(p - g, f) / den
    t_dot = _cross(vp, f) / den
    t_ddot = _cross(ap, f) / den
    return {"P": _vec(p), "Y": _vec(g + t * e), "t": t, "t_dot": t_dot, "t_ddot": t_ddot,
            "vY": _vec(t_dot * e), "aY": _vec(t_ddot * e)}
