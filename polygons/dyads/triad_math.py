"""Every closure of a class-III group (a triad), found numerically: the geometry of
:mod:`polygons.dyads.triad`, in plain floats (one position) and over arrays (a sweep, each
position following the closure of the one before: continuation).

The group: a rigid plate with corners B, C, X (in the plate's own frame B = (0, 0),
C = (L, 0), X = (ξ, η)), each corner joined by a binary link to a placed point: |AB| = a,
|DC| = d, |EX| = e.  With φ the direction of B→C, C − B = L u(φ) and X − B = R(φ)(ξ, η); B
lies on the circle about A (radius a) and, for C to reach D, on the circle about D − (C − B)
(radius d): B = circle_circle(A, a, D − L u(φ), d, σ), σ = ±1.  What is left is one equation
in φ,

    g(φ, σ) = |B(φ, σ) + R(φ)(ξ, η) − E| − e = 0,

whose real roots are the closures (up to six; with a triangle of three links for the plate,
its mirror image η → −η too).  φ is scanned at 2048 points on each branch σ, every change of
sign is refined to the last bit (regula falsi, Illinois), and the branches are joined where they fold
(B's two circles touch), so no root between samples is lost except a double one (two
closures that meet: a toggle).  Each closure is checked against the three lengths.
"""
from __future__ import annotations

import math

import numpy as np

_N = 2048
_TWO_PI = 2.0 * math.pi


def _b_of(phi, ax, ay, a, dx, dy, d, L, sigma):
    """B on the circle about A and on the circle about D − L u(φ); (bx, by, ok)."""
    qx = dx - L * np.cos(phi)
    qy = dy - L * np.sin(phi)
    wx, wy = qx - ax, qy - ay
    dist = np.hypot(wx, wy)
    with np.errstate(all="ignore"):
        m = (a * a - d * d + dist * dist) / (2.0 * dist)
        h2 = a * a - m * m
        ok = (h2 >= 0.0) & (dist > 0.0)
        h = np.sqrt(np.where(ok, h2, 0.0))
        ux, uy = wx / dist, wy / dist
    return ax + m * ux - sigma * h * uy, ay + m * uy + sigma * h * ux, ok, h2


def _g(phi, sigma, p):
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = p
    bx, by, ok, h2 = _b_of(phi, ax, ay, a, dx, dy, d, L, sigma)
    c, s = np.cos(phi), np.sin(phi)
    xx = bx + xi * c - eta * s
    xy = by + xi * s + eta * c
    return np.hypot(xx - ex, xy - ey) - e, ok, h2


def _root(f, lo, hi, flo, fhi, n=80):
    """The root of f in the bracket [lo, hi] (f changes sign there) by the Illinois form of
    regula falsi: the bracket is kept, so it cannot leave it; to the last bit or 1e-15 rad."""
    side, last = 0, math.nan
    for _ in range(n):
        den = fhi - flo
        x = (lo * fhi - hi * flo) / den if den != 0.0 else 0.5 * (lo + hi)
        if not (min(lo, hi) <= x <= max(lo, hi)):
            x = 0.5 * (lo + hi)
        if abs(x - last) <= 4e-16 * max(1.0, abs(x)):
            return x                    # no longer moving: converged to the last bits
        last = x
        fx = f(x)
        if fx == 0.0 or abs(hi - lo) <= 1e-15:
            return x
        if (fx > 0) == (fhi > 0):
            hi, fhi = x, fx
            if side == -1:
                flo *= 0.5
            side = -1
        else:
            lo, flo = x, fx
            if side == 1:
                fhi *= 0.5
            side = 1
    return 0.5 * (lo + hi)


def _fold_h2(p):
    """h² of B's two circles as a function of φ (zero where they touch: the fold)."""
    ax, ay, a, dx, dy, d, _, _, _, L = p[:10]

    def h2(phi):
        dist = math.hypot(dx - L * math.cos(phi) - ax, dy - L * math.sin(phi) - ay)
        m = (a * a - d * d + dist * dist) / (2.0 * dist) if dist else math.inf
        return a * a - m * m
    return h2


def _g1(phi, sigma, p):
    """:func:`_g` at one φ, in plain floats (the root finder's inner loop)."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = p
    c, s = math.cos(phi), math.sin(phi)
    wx, wy = dx - L * c - ax, dy - L * s - ay
    dist = math.hypot(wx, wy)
    if dist == 0.0:
        return math.nan
    m = (a * a - d * d + dist * dist) / (2.0 * dist)
    h = math.sqrt(max(a * a - m * m, 0.0))
    ux, uy = wx / dist, wy / dist
    bx, by = ax + m * ux - sigma * h * uy, ay + m * uy + sigma * h * ux
    return math.hypot(bx + xi * c - eta * s - ex, by + xi * s + eta * c - ey) - e


def closures(p) -> list[tuple[float, float, float]]:
    """Every closure (φ, σ, η) of the group with parameters ``p`` = (ax, ay, a, dx, dy, d, ex,
    ey, e, L, ξ, η, mirror): roots of g(φ, σ) on both branches (and, with ``mirror``, of the
    mirrored plate)."""
    *q, mirror = p
    out = []
    for eta in ((q[11], -q[11]) if mirror and q[11] != 0.0 else (q[11],)):
        qq = tuple(q[:11]) + (eta,)
        phis = np.linspace(0.0, _TWO_PI, _N + 1)
        vals = {s: _g(phis, s, qq) for s in (1.0, -1.0)}
        for s in (1.0, -1.0):
            g, ok, _ = vals[s]
            pos = g > 0
            for k in np.nonzero(ok[:-1] & ok[1:] & (pos[:-1] != pos[1:]))[0]:
                f = (lambda ph, s=s: _g1(ph, s, qq))
                out.append((_root(f, float(phis[k]), float(phis[k + 1]), float(g[k]),
                                  float(g[k + 1])), s, eta))
        # the fold: where B's circles touch, branch +1 turns into branch −1
        gp, okp, _ = vals[1.0]
        gm, _, _ = vals[-1.0]
        for k in np.nonzero(okp[:-1] != okp[1:])[0]:
            i, j = (k, k + 1) if okp[k] else (k + 1, k)       # i valid, j not
            h2 = _fold_h2(qq)
            fold = _root(h2, float(phis[i]), float(phis[j]), h2(float(phis[i])),
                         h2(float(phis[j])))
            gf = float(_g(fold, 1.0, qq)[0])
            for s, gs in ((1.0, gp[i]), (-1.0, gm[i])):
                if (gs > 0) != (gf > 0):
                    f = (lambda ph, s=s: _g1(ph, s, qq))
                    out.append((_root(f, float(phis[i]), fold, float(gs), gf), s, eta))
    return out


def corners(phi, sigma, eta, p):
    """(B, C, X) of the closure (φ, σ, η)."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, _ = p[:12]
    bx, by, _, _ = _b_of(phi, ax, ay, a, dx, dy, d, L, sigma)
    c, s = math.cos(phi), math.sin(phi)
    bx, by = float(bx), float(by)
    return ((bx, by), (bx + L * c, by + L * s),
            (bx + xi * c - eta * s, by + xi * s + eta * c))


def _distinct(points, size):
    """The closures' corners without repeats (a root found from two sides)."""
    out = []
    for pts in points:
        if all(max(math.dist(pts[i], q[i]) for i in range(3)) > 1e-9 * size for q in out):
            out.append(pts)
    return out


def all_corners(p, size) -> list[tuple]:
    """The corners (B, C, X) of every closure, each checked against the three lengths."""
    ax, ay, a, dx, dy, d, ex, ey, e = p[:9]
    good = []
    for phi, s, eta in closures(p):
        B, C, X = corners(phi, s, eta, p)
        err = max(abs(math.dist(B, (ax, ay)) - a), abs(math.dist(C, (dx, dy)) - d),
                  abs(math.dist(X, (ex, ey)) - e))
        if err <= 1e-9 * size:
            good.append((B, C, X))
    return _distinct(good, size)


def _pick(cands, rb, rx):
    """The closure nearest the reference corners B, X, its distance, and the distance from
    it to the nearest other closure."""
    dist = [max(math.dist(c[0], rb), math.dist(c[2], rx)) for c in cands]
    i = int(np.argmin(dist))
    others = [max(math.dist(c[0], cands[i][0]), math.dist(c[2], cands[i][2]))
              for j, c in enumerate(cands) if j != i]
    return cands[i], dist[i], (min(others) if others else math.inf)


_NAN7 = (math.nan,) * 6 + (-1.0,)


def _newton(q, pose, size, iters=30):
    """The closure of the group ``q`` = (ax, ay, a, dx, dy, d, ex, ey, e, L, ξ, η) near the
    plate pose (bx, by, φ), by Newton on |B − A|² = a², |C − D|² = d², |X − E|² = e²; returns
    (pose, margin) with margin = |det J| / (|J₁| |J₂| |J₃|) (φ scaled by the size: 0 where
    two closures meet), or (None, −1) where it does not converge."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = q
    bx, by, phi = pose
    for _ in range(iters):
        c, s = math.cos(phi), math.sin(phi)
        cx, cy = bx + L * c - dx, by + L * s - dy          # C − D
        xx = bx + xi * c - eta * s - ex                     # X − E
        xy = by + xi * s + eta * c - ey
        ux, uy = bx - ax, by - ay                           # B − A
        f1 = ux * ux + uy * uy - a * a
        f2 = cx * cx + cy * cy - d * d
        f3 = xx * xx + xy * xy - e * e
        j23 = (cx * -L * s + cy * L * c) / size             # (C − D)·∂C/∂φ, φ scaled
        j33 = (xx * (-xi * s - eta * c) + xy * (xi * c - eta * s)) / size
        # J = 2 [[ux, uy, 0], [cx, cy, j23], [xx, xy, j33]]
        det = ux * (cy * j33 - j23 * xy) - uy * (cx * j33 - j23 * xx)
        if det == 0.0 or not math.isfinite(det):
            return None, -1.0
        # Cramer's rule for J (Δbx, Δby, Δφ·size)ᵀ = −F/2
        r1, r2, r3 = -0.5 * f1, -0.5 * f2, -0.5 * f3
        d1 = r1 * (cy * j33 - j23 * xy) - uy * (r2 * j33 - j23 * r3)
        d2 = ux * (r2 * j33 - j23 * r3) - r1 * (cx * j33 - j23 * xx)
        d3 = ux * (cy * r3 - r2 * xy) - uy * (cx * r3 - r2 * xx) + r1 * (cx * xy - cy * xx)
        step_b, step_p = d1 / det, d2 / det
        bx, by, phi = bx + step_b, by + step_p, phi + d3 / det / size
        if max(abs(step_b), abs(step_p), abs(d3 / det)) <= 1e-15 * size:
            break
    else:
        return None, -1.0
    norms = (math.hypot(ux, uy) * math.sqrt(cx * cx + cy * cy + j23 * j23)
             * math.sqrt(xx * xx + xy * xy + j33 * j33))
    margin = abs(det) / norms if norms > 0 else 0.0
    return (bx, by, phi), margin


def _pose_of(B, C):
    return (B[0], B[1], math.atan2(C[1] - B[1], C[0] - B[0]))


def _corners_of(q, pose, mirror_eta):
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, _ = q
    bx, by, phi = pose
    c, s = math.cos(phi), math.sin(phi)
    return ((bx, by), (bx + L * c, by + L * s),
            (bx + xi * c - mirror_eta * s, by + xi * s + mirror_eta * c))


def _follow(q, mirror, ref_b, ref_x, size, pose=None, fallback=True):
    """The closure nearest the reference corners: Newton from ``pose`` (the neighbour's) or,
    without one or when it fails or jumps, the nearest of every closure.  Returns
    (corners, pose, η, margin) or None."""
    if pose is not None:
        for eta in ((q[11], -q[11]) if mirror else (q[11],)):
            qq = q[:11] + (eta,)
            new, m = _newton(qq, pose[:3], size)
            if new is not None:
                B, C, X = _corners_of(qq, new, eta)
                if (eta == pose[3] and max(math.dist(B, ref_b), math.dist(X, ref_x))
                        <= 0.25 * size):
                    return (B, C, X), new + (eta,), m
        if not fallback:
            return None
    cands = all_corners(q + (mirror,), size)
    if not cands:
        return None
    (B, C, X), dist, other = _pick(cands, ref_b, ref_x)
    if pose is not None and dist > 0.25 * size:
        return None                         # the followed closure is gone
    eta = q[11]
    if mirror and abs(math.dist(B, X) - math.hypot(q[10], q[11])) > 1e-9 * size:
        eta = -q[11]
    new = _pose_of(B, C)
    _, m = _newton(q[:11] + (eta,), new, size)
    return (B, C, X), new + (eta,), m


def _ref_poses(q, mirror, ref_b, ref_x):
    """Plate poses (bx, by, φ, η) that put B at ``ref_b`` and X towards ``ref_x``."""
    xi, eta = q[10], q[11]
    out = []
    for e in ((eta, -eta) if mirror and eta else (eta,)):
        phi = (math.atan2(ref_x[1] - ref_b[1], ref_x[0] - ref_b[0]) - math.atan2(e, xi))
        out.append((ref_b[0], ref_b[1], phi, e))
    return out


def _from_reference(q, mirror, ref_b, ref_x, size):
    """Newton from the reference's own pose (the fast path: at the reference's input it is
    the closure itself); else the nearest of every closure."""
    for pose in _ref_poses(q, mirror, ref_b, ref_x):
        res = _follow(q, mirror, ref_b, ref_x, size, pose, fallback=False)
        if res is not None:
            return res
    return _follow(q, mirror, ref_b, ref_x, size)


def triad_scalar(ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta, mirror, rbx, rby, rxx, rxy,
                 size):
    """The closure nearest the reference corners (rb, rx): (bx, by, cx, cy, xx, xy, margin),
    margin the conditioning of the closure (:func:`_newton`: 0 where two closures meet; −1
    and NaN where the group cannot close)."""
    q = (ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta)
    if not all(math.isfinite(v) for v in q + (rbx, rby, rxx, rxy)):
        return _NAN7
    res = _from_reference(q, mirror, (rbx, rby), (rxx, rxy), size)
    if res is None:
        return _NAN7
    (B, C, X), _, m = res
    return (*B, *C, *X, m)


def triad_cols(ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta, mirror, rbx, rby, rxx, rxy,
               size):
    """:func:`triad_scalar` over N positions, by continuation: the position whose closure
    is nearest the reference first, then outwards, each by Newton from its neighbour's
    closure.  Where the followed closure is lost (it met another and both vanished) the
    positions beyond are NaN and the margin −1: the limit of travel."""
    arrs = [np.asarray(v, dtype=float) for v in (ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta)]
    shape = np.broadcast_shapes(*(v.shape for v in arrs))
    n = int(np.prod(shape)) if shape else 1
    cols = [np.broadcast_to(v, shape).reshape(n).tolist() for v in arrs]
    out = np.full((7, n), np.nan)
    out[6] = -1.0
    qs = [tuple(c[k] for c in cols) for k in range(n)]
    ref_b, ref_x = (rbx, rby), (rxx, rxy)
    start, best, first = None, math.inf, None
    for k in range(0, n, max(1, n // 8)):    # the probed position nearest the reference
        if not all(math.isfinite(v) for v in qs[k]):
            continue
        res = _from_reference(qs[k], mirror, ref_b, ref_x, size)
        if res is None:
            continue
        dist = max(math.dist(res[0][0], ref_b), math.dist(res[0][2], ref_x))
        if dist < best:
            start, best, first = k, dist, res
        if dist <= 1e-9 * size:
            break
    if start is not None:
        done = np.zeros(n, dtype=bool)
        # a crank's positions run round the turn: the last is the first's neighbour then
        wrap = n > 2 and _adjacent(qs, 0, n - 1)
        back = list(range(start, -1, -1)) + (list(range(n - 1, start, -1)) if wrap else [])
        for rng in (range(start, n), back):
            res = first
            for k in rng:
                if k != start:
                    if done[k] or not all(math.isfinite(v) for v in qs[k]):
                        break
                    (B, _, X), pose, _ = res
                    res = _follow(qs[k], mirror, B, X, size, pose)
                    if res is None:
                        break
                (B, C, X), _, m = res
                out[:, k] = (*B, *C, *X, m)
                done[k] = True
    return tuple(o.reshape(shape) if shape else o[0] for o in out)


def _adjacent(qs, i, j) -> bool:
    """Whether positions i and j are as close as neighbouring positions are (the outer
    points' moves, against twice the largest step between neighbours)."""
    def gap(u, v):
        return max(abs(qs[u][k] - qs[v][k]) for k in (0, 1, 3, 4, 6, 7))
    steps = [gap(k, k + 1) for k in range(len(qs) - 1)]
    finite = [s for s in steps if math.isfinite(s)]
    return bool(finite) and gap(i, j) <= 2.0 * max(finite)
