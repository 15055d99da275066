"""Numbers from functions, to the precision of the construction: a zero by Brent's method and
a definite integral by adaptive Gauss–Kronrod quadrature — each point of them one full
construction (a staged solve, a force analysis), so as few as the precision needs.

    brent:     x with g(x) = 0 in [a, b], g(a)·g(b) ≤ 0 (Brent 1973, ch. 4, "zero")
    integral:  ∫ₐᵇ f(x) dx ≈ Σ wᵢ f(xᵢ) (the 15-point Kronrod rule, the 7-point Gauss rule
               inside it its error estimate; halved where they differ)
"""
from __future__ import annotations

import math
from typing import Callable

#: the double's unit roundoff step
_EPS = 2.220446049250313e-16


def brent(g: Callable[[float], float], a: float, b: float, ga: float | None = None,
          gb: float | None = None, xtol: float = 0.0, maxiter: int = 200) -> float:
    """A zero of ``g`` in [a, b] where g(a)·g(b) ≤ 0, by Brent's method (inverse quadratic
    interpolation, secant and bisection; Brent 1973, ch. 4, "zero"): the bracket shrinks to
    4 ε |x| + xtol."""
    fa = g(a) if ga is None else ga
    fb = g(b) if gb is None else gb
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if fa * fb > 0.0:
        raise ValueError("brent: no sign change in the bracket")
    c, fc = a, fa
    d = e = b - a
    eps = _EPS
    for _ in range(maxiter):
        if fb * fc > 0.0:
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2.0 * eps * abs(b) + 0.5 * xtol
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0.0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p, q = 2.0 * m * s, 1.0 - s
            else:
                qq, r = fa / fc, fb / fc
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0))
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0.0:
                q = -q
            else:
                p = -p
            if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else math.copysign(tol, m)
        fb = g(b)
    return b


#: the 15-point Kronrod nodes on [−1, 1] (the positive half; the Gauss nodes are the odd
#: ones) and weights, and the 7-point Gauss weights (Piessens et al., QUADPACK, qk15)
_XK = (0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
       0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
       0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
       0.207784955007898467600689403773245, 0.000000000000000000000000000000000)
_WK = (0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
       0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
       0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
       0.204432940075298892414161999234649, 0.209482141084727828012999174891714)
_WG = (0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
       0.381830050505118944950369775488975, 0.417959183673469387755102040816327)


def _kronrod(f, a: float, b: float) -> tuple[float, float]:
    """(the 15-point Kronrod sum, |Kronrod − Gauss|) on [a, b]."""
    c, h = 0.5 * (a + b), 0.5 * (b - a)
    fc = f(c)
    k, g = _WK[7] * fc, _WG[3] * fc
    for j in range(7):
        y = f(c - h * _XK[j]) + f(c + h * _XK[j])
        k += _WK[j] * y
        if j % 2 == 1:
            g += _WG[j // 2] * y
    return k * h, abs((k - g) * h)


def _break(f, lo: float, hi: float) -> float:
    """Where ``f`` jumps or turns a corner in [lo, hi] (a force that acts only one way, a
    torque F·v/ω as v passes zero): the half that departs more from the straight line
    through its ends kept (its midpoint against the mean of its ends), to the last bit — two
    evaluations a halving."""
    flo, fhi = f(lo), f(hi)
    mid = 0.5 * (lo + hi)
    fm = f(mid)
    while True:
        q1, q2 = 0.5 * (lo + mid), 0.5 * (mid + hi)
        if not (lo < q1 < mid < q2 < hi):
            return mid
        f1, f2 = f(q1), f(q2)
        if abs(f1 - 0.5 * (flo + fm)) >= abs(f2 - 0.5 * (fm + fhi)):
            hi, fhi, mid, fm = mid, fm, q1, f1
        else:
            lo, flo, mid, fm = mid, fm, q2, f2


def integral(f: Callable[[float], float], a: float, b: float, rel: float = 1e-12,
             most: int = 200) -> tuple[float, float]:
    """(∫ₐᵇ f dx, its error estimate) by adaptive Gauss–Kronrod (15 points a piece): the
    piece with the largest estimate halved until the estimates sum below ``rel`` of the
    integral of |f| (or ``most`` pieces: the estimate then says how far it is).  A piece
    whose estimate does not fall on halving (by ≥ 64× — a smooth piece's falls ~30 000×)
    holds a jump or a corner of ``f``: it is found by bisection (:func:`_break`) and the two
    sides integrated apart."""
    if a == b:
        return 0.0, 0.0
    pieces = [(a, b, *_kronrod(f, a, b))]
    scale = abs(pieces[0][2])
    while len(pieces) < most:
        err = sum(p[3] for p in pieces)
        scale = max(scale, sum(abs(p[2]) for p in pieces))
        if err <= rel * scale or err == 0.0:
            break
        i = max(range(len(pieces)), key=lambda j: pieces[j][3])
        lo, hi, _, e0 = pieces.pop(i)
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            pieces.append((lo, hi, 0.0, 0.0))       # a piece of no width left
            continue
        kids = [(lo, mid, *_kronrod(f, lo, mid)), (mid, hi, *_kronrod(f, mid, hi))]
        worst = max(kids, key=lambda p: p[3])
        if worst[3] > e0 / 64.0 and worst[1] - worst[0] < 0.01 * (b - a):
            x = _break(f, worst[0], worst[1])       # a jump or corner: either side apart
            kids.remove(worst)
            kids += [(worst[0], x, *_kronrod(f, worst[0], x)),
                     (x, worst[1], *_kronrod(f, x, worst[1]))]
        pieces += kids
    return sum(p[2] for p in pieces), sum(p[3] for p in pieces)


__all__ = ["brent", "integral"]
