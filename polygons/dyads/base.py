"""What every dyad module provides, and the vectorised geometry they share.

A dyad is a frozen record naming the points it places (``placed``) and the points it needs
placed first (``needs``).  Its module is the only place that knows its geometry:

* ``match`` (a module function): whether the dyad can be placed now, given the placed labels;
* ``locate(scene, pos, sigma, x)``: where its points go, written with numpy broadcasting so the
  same code places one position (arrays of shape (2,)) or a whole sweep ((2, N)).  A
  two-closure dyad takes ``sigma`` = +1 or −1 for its closure; ``x`` is the input of a driver.
  It returns ``(points, margin)``: ``margin`` is the conditioning of the closure (negative
  where the dyad cannot close, positions NaN there);
* ``why_not(scene, pos)``: the sentence a textbook says when it cannot close or degenerates;
* ``emit(b)``: the velocity or acceleration steps it adds to the construction
  (:class:`polygons.steps.Builder`).

The planner orders dyads; the interpreters execute their steps; neither knows their insides.
"""
from __future__ import annotations

import math

import numpy as np

from ..memo import memo_of
from .triad_math import triad_cols, triad_scalar
from .triad_slider_math import triad_slider_cols, triad_slider_scalar

#: a closure discriminant within this fraction of the squared size is a double closure
CLOSE_TOL = 1e-12


def circle_circle(p, r1, q, r2, sigma):
    """The point X with |PX| = r1, |QX| = r2, left of P→Q for sigma = +1 (right for −1).

    X = P + a u + σ h perp(u),  a = (r1² − r2² + d²) / 2d,  h = √(r1² − a²),  u = PQ/d.
    Returns (X, margin) with margin = σ-free sine of the angle PX, QX (h d / r1 r2), negative
    (−√|h²| d / r1 r2) where the circles do not meet (X is NaN there).  One position (P, Q of
    shape (2,), plain-float radii) takes :func:`circle_circle_scalar`, the same formula.
    """
    if np.ndim(p) == 1 and np.ndim(q) == 1 and _floats(r1, r2, sigma):
        x, y, m = circle_circle_scalar(float(p[0]), float(p[1]), r1, float(q[0]), float(q[1]),
                                       r2, sigma)
        return np.array([x, y]), m
    x, y, margin = _circle_circle_xy(p[0], p[1], r1, q[0], q[1], r2, sigma)
    return np.array([x, y]), margin


def _circle_circle_xy(px, py, r1, qx, qy, r2, sigma):
    """:func:`circle_circle` over arrays, coordinate by coordinate (no (2, N) copies):
    X = P + a u + σ h perp(u), perp(u) = (−u_y, u_x)."""
    dx, dy = qx - px, qy - py
    dist = np.hypot(dx, dy)
    a = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist)
    h2 = r1 * r1 - a * a
    tol = CLOSE_TOL * np.maximum(np.maximum(r1, r2), dist) ** 2
    ok = h2 >= -tol
    h = np.sqrt(np.where(ok, np.maximum(h2, 0.0), np.nan))
    ux, uy = dx / dist, dy / dist
    sh = sigma * h
    x = px + a * ux + sh * -uy
    y = py + a * uy + sh * ux
    margin = np.where(ok, h * dist, -np.sqrt(np.abs(h2)) * dist) / (r1 * r2)
    return x, y, margin


def circle_line(p, length, through, e, sigma):
    """The point X on the line ``through`` + t e with |PX| = length, (X − P)·e of sign σ.

    t = −b + σ √(b² − c),  b = e·(g − p),  c = |g − p|² − L².  Returns (X, margin) with
    margin = |PX·e| / L (negative where the line is out of reach; X NaN there).  One position
    (plain floats, a fixed or placed guide of shape (2,)) takes :func:`circle_line_scalar`.
    """
    if (np.ndim(p) == 1 and np.ndim(through) == 1 and np.ndim(e) == 1
            and _floats(length, sigma)):
        x, y, m = circle_line_scalar(float(p[0]), float(p[1]), length, float(through[0]),
                                     float(through[1]), float(e[0]), float(e[1]), sigma)
        return np.array([x, y]), m
    g = np.asarray(through, dtype=float)
    if g.ndim == 1:         # a fixed guide; a moving one (a lever's slot) is (2, N) already
        g = g.reshape((2,) + (1,) * (np.ndim(p) - 1))
    e = np.asarray(e, dtype=float)
    if e.ndim == 1:
        e = e.reshape((2,) + (1,) * (np.ndim(p) - 1))
    w = g - p
    bq = e[0] * w[0] + e[1] * w[1]
    c = w[0] * w[0] + w[1] * w[1] - length * length
    disc = bq * bq - c
    ok = disc >= -CLOSE_TOL * length * length
    root = np.sqrt(np.where(ok, np.maximum(disc, 0.0), np.nan))
    x = g + (-bq + sigma * root) * e
    margin = np.where(ok, root, -np.sqrt(np.abs(disc))) / length
    return x, margin


_hypot, _sqrt, _nan = math.hypot, math.sqrt, math.nan


def _floats(*xs) -> bool:
    return all(type(x) is float for x in xs)


def circle_circle_scalar(px, py, r1, qx, qy, r2, sigma):
    """:func:`circle_circle` over plain floats (the compiled evaluator's fast path): the same
    formula, term for term.  Returns (x, y, margin); x, y NaN where the circles do not meet."""
    dx = qx - px
    dy = qy - py
    dist = _hypot(dx, dy)
    if dist == 0.0:
        return _nan, _nan, _nan
    a = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist)
    h2 = r1 * r1 - a * a
    big = r1 if r1 > r2 else r2
    big = big if big > dist else dist
    if not h2 >= -(CLOSE_TOL * (big * big)):
        return _nan, _nan, -_sqrt(abs(h2)) * dist / (r1 * r2)
    h = _sqrt(h2) if h2 > 0.0 else 0.0
    ux = dx / dist
    uy = dy / dist
    sh = sigma * h
    return px + a * ux + sh * -uy, py + a * uy + sh * ux, h * dist / (r1 * r2)


def circle_line_scalar(px, py, length, gx, gy, ex, ey, sigma):
    """:func:`circle_line` over plain floats (the compiled evaluator's fast path): the same
    formula, term for term.  Returns (x, y, margin); x, y NaN where the line is out of reach."""
    wx = gx - px
    wy = gy - py
    bq = ex * wx + ey * wy
    c = wx * wx + wy * wy - length * length
    disc = bq * bq - c
    if not disc >= -CLOSE_TOL * length * length:
        return _nan, _nan, -_sqrt(abs(disc)) / length
    root = _sqrt(disc) if disc > 0.0 else 0.0
    t = -bq + sigma * root
    return gx + t * ex, gy + t * ey, root / length


def circle_circle_cols(px, py, r1, qx, qy, r2, sigma):
    """:func:`circle_circle_scalar`'s signature over arrays (the compiled program run on N
    positions): :func:`circle_circle` itself, on its coordinates."""
    shape = np.broadcast_shapes(*(np.shape(v) for v in (px, py, qx, qy, r1, r2)))
    x, y, m = _circle_circle_xy(px, py, r1, qx, qy, r2, sigma)
    return np.broadcast_to(x, shape), np.broadcast_to(y, shape), np.broadcast_to(m, shape)


def circle_line_cols(px, py, length, gx, gy, ex, ey, sigma):
    """:func:`circle_line_scalar`'s signature over arrays: :func:`circle_line` itself (the
    guide fixed, or moving: a lever's slot, its point and direction (N,) arrays too)."""
    shape = np.broadcast_shapes(*(np.shape(v) for v in (px, py, length, gx, gy, ex, ey)))
    # coordinate by coordinate, as circle_line (no (2, N) copies of the operands)
    wx, wy = gx - px, gy - py
    bq = ex * wx + ey * wy
    disc = bq * bq - (wx * wx + wy * wy - length * length)
    ok = disc >= -CLOSE_TOL * length * length
    root = np.sqrt(np.where(ok, np.maximum(disc, 0.0), np.nan))
    t = -bq + sigma * root
    m = np.where(ok, root, -np.sqrt(np.abs(disc))) / length
    return (np.broadcast_to(gx + t * ex, shape), np.broadcast_to(gy + t * ey, shape),
            np.broadcast_to(m, shape))


def end_margin_scalar(m0, t, lo, hi, tol):
    """The margin ``m0`` of a point at ``t`` along a rod or slot that runs from ``lo`` to
    ``hi`` (``hi`` NaN: open-ended): min(m0, (t − lo + tol)/tol, (hi + tol − t)/tol), held
    in [−1, 1].  It is 1 from ``lo`` to ``hi`` inclusive, falls to 0 within ``tol`` beyond an
    end (where a sweep's limit of travel is found, this dyad the smallest margin there) and is
    negative further out, where the point has left the rod or slot."""
    m = m0
    a = (t - lo + tol) / tol
    if a < m:
        m = a
    if hi == hi:
        b = (hi + tol - t) / tol
        if b < m:
            m = b
    return -1.0 if m < -1.0 else m


def end_margin_cols(m0, t, lo, hi, tol):
    """:func:`end_margin_scalar` over arrays (numpy; ``hi`` NaN where open-ended)."""
    a = (t - lo + tol) / tol
    b = np.where(np.isnan(hi), np.inf, (hi + tol - t) / tol)
    return np.maximum(np.fmin(np.fmin(m0, a), b), -1.0)     # (fmin: a NaN t keeps m0)


#: the array form of each scalar fast path (for the compiled program run on arrays)
ARRAY_TWIN = {circle_circle_scalar: circle_circle_cols, circle_line_scalar: circle_line_cols,
              end_margin_scalar: end_margin_cols, triad_scalar: triad_cols,
              triad_slider_scalar: triad_slider_cols}


def as_col(v, like):
    """A constant plane vector shaped to broadcast against ``like`` ((2,) or (2, N))."""
    return np.asarray(v, dtype=float).reshape((2,) + (1,) * (np.ndim(like) - 1))


def size_of(scene) -> float:
    """The mechanism's size: its longest link or ground coordinate (for relative tolerances;
    over every row when a batch gives the lengths or coordinates as arrays).  Kept with the
    scene (a frozen record) after the first call."""
    memo = memo_of(scene)
    if "_size" in memo:
        return memo["_size"]

    def big(x) -> float:
        return abs(x) if isinstance(x, float) else float(np.max(np.abs(x)))
    lengths = [big(l.length) for l in scene.links.values() if l.length is not None]
    coords = [big(c) for v in scene.ground.values() for c in v]
    size = memo["_size"] = max(lengths + coords + [1e-300])
    return size
