"""Every closure of a class-III group (a triad), found algebraically: the geometry of
:mod:`polygons.dyads.triad`, in plain floats (one position) and over arrays (a sweep, each
position following the closure of the one before: continuation).

The group: a rigid plate with corners B, C, X (in the plate's own frame B = (0, 0),
C = (L, 0), X = (ξ, η)), each corner joined by a binary link to a placed point: |AB| = a,
|DC| = d, |EX| = e.  With φ the direction of B→C, C − B = L u(φ), X − B = R(φ)(ξ, η), and
(A at the origin) the loop equations are

    |B|² = a²,   |B + L u − D|² = d²,   |B + R(φ)(ξ, η) − E|² = e².

The second and third less the first are *linear* in B (coefficients linear in cos φ,
sin φ): B = (N_x, N_y) / Δ by Cramer's rule, and the first becomes

    q(φ) = N_x² + N_y² − a² Δ² = 0,

a quartic form in (cos φ, sin φ).  With the tangent of the half angle, φ = φ₀ + 2 atan t,
(1 + t²)⁴ q is a polynomial of degree 8 in t that has the factor 1 + t² (the circular
points: the isotropic solutions of the 3-RPR platform's forward problem, Gosselin, Sefrioui
and Richard 1994; Wampler 1999): what is left, of degree ≤ 6, has every real closure among its
real roots.  Its real roots are isolated by the roots of its derivatives (between two
consecutive real critical points it is monotone: at most one root, found by a bracketing
method to the last bit; a critical point where it is zero within its rounding is a double
root: two closures that meet), so two closures however close are both found.  φ₀ keeps the
closure φ = φ₀ + π away from t = ∞.  Each root is polished by Newton on the three loop
equations (stopping at the rounding floor of the group's own conditioning, not at an absolute
step) and checked against the three lengths.  With a triangle of three links for the plate,
its mirror image η → −η is a group too.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

_TWO_PI = 2.0 * math.pi
_EPS = 2.220446049250313e-16


def _quartic(p, phi0):
    """The coefficients (low → high, in t) of (1 + t²)³ q(φ₀ + 2 atan t) / s⁴ (s the group's
    size: the coefficients are of order one), of degree ≤ 6: see the module docstring."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = p
    dx, dy, ex, ey = dx - ax, dy - ay, ex - ax, ey - ay
    s = max(a, d, e, L, math.hypot(dx, dy), math.hypot(ex, ey), math.hypot(xi, eta))
    if not s > 0.0:
        return None
    a, d, e, L, xi, eta, dx, dy, ex, ey = (v / s for v in (a, d, e, L, xi, eta, dx, dy,
                                                         ex, ey))
    lin, m11, m12, r1 = first_corner(phi0, a, d, L, dx, dy)
    m21, m22 = lin(-2 * ex, 2 * xi, -2 * eta), lin(-2 * ey, 2 * eta, 2 * xi)
    r2 = lin(-(xi * xi + eta * eta + ex * ex + ey * ey - e * e + a * a),
             2 * (ex * xi + ey * eta), 2 * (ey * xi - ex * eta))
    return eliminated(a, m11, m12, r1, m21, m22, r2)[1]


def first_corner(phi0, a, d, L, dx, dy):
    """(lin, m₁₁, m₁₂, r₁): ``lin(k0, kc, ks)`` the coefficients in t of (k0 + kc cos φ +
    ks sin φ)(1 + t²), φ = φ₀ + 2 atan t; and B's first linear equation relative to A,
    2 B′·(L u(φ) − D′) = −(|L u − D′|² − d² + a²) (|DC| = d with C = B + L u), as such."""
    c0, s0 = math.cos(phi0), math.sin(phi0)

    def lin(k0, kc, ks):
        kc, ks = kc * c0 + ks * s0, ks * c0 - kc * s0
        return np.array([k0 + kc, 2.0 * ks, k0 - kc])
    m11, m12 = lin(-2 * dx, 2 * L, 0.0), lin(-2 * dy, 0.0, 2 * L)
    r1 = lin(-(L * L + dx * dx + dy * dy - d * d + a * a), 2 * L * dx, 2 * L * dy)
    return lin, m11, m12, r1


def eliminated(a, m11, m12, r1, m21, m22, r2):
    """B eliminated from its two linear equations M B′ = r by Cramer's rule and put into
    |B′| = a: (q = (r₁m₂₂ − m₁₂r₂)² + (m₁₁r₂ − r₁m₂₁)² − a² det², q / (1 + t²), remainder)."""
    from numpy.polynomial import polynomial as _PP   # low → high order (imported here:
    mul, sub = _PP.polymul, _PP.polysub              # a triad only; a quicker start)
    dl = sub(mul(m11, m22), mul(m12, m21))
    nx = sub(mul(r1, m22), mul(m12, r2))
    ny = sub(mul(m11, r2), mul(r1, m21))
    q = sub(_PP.polyadd(mul(nx, nx), mul(ny, ny)), a * a * mul(dl, dl))
    q6, rem = _PP.polydiv(q, np.array([1.0, 0.0, 1.0]))
    return q, q6, rem


def _val(c, t):
    """c(t) by Horner, and a bound on its rounding error."""
    v, w, at = 0.0, 0.0, abs(t)
    for k in range(len(c) - 1, -1, -1):
        v = v * t + c[k]
        w = w * at + abs(c[k])
    return v, 4.0 * len(c) * _EPS * w


def _bracket(c, lo, hi, flo, fhi):
    """The root of c in [lo, hi] where it changes sign, to the last bit: the Illinois form
    of regula falsi, with a bisection wherever two of its steps have not halved the bracket
    (so a far end with a huge value cannot stall it)."""
    side, slow = 0, 0
    for _ in range(400):
        width = hi - lo
        if width <= 2.0 * _EPS * max(abs(lo), abs(hi)):
            break
        x = (lo * fhi - hi * flo) / (fhi - flo) if fhi != flo else 0.5 * (lo + hi)
        if slow >= 2 or not lo < x < hi:
            x, slow = 0.5 * (lo + hi), 0
            if not lo < x < hi:
                break
        fx = _val(c, x)[0]
        if fx == 0.0:
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
        slow = slow + 1 if hi - lo > 0.5 * width else 0
    return lo if abs(flo) < abs(fhi) else hi


def real_roots(c) -> list[float]:
    """Every real root of the polynomial c (low → high), each once: the real line cut at
    the real roots of c′ (found the same way) into pieces where c is monotone, a root in each
    piece where c changes sign, and a critical point where c is zero within its rounding
    (a double root)."""
    c = [float(v) for v in c]
    big = max((abs(v) for v in c), default=0.0)
    while len(c) > 1 and abs(c[-1]) <= 1e-14 * big:     # leading rounding noise
        c.pop()
    n = len(c) - 1
    if n < 1 or big == 0.0:
        return []
    if n == 1:
        return [-c[0] / c[1]]
    bound = 1.0 + max(abs(v) for v in c[:-1]) / abs(c[-1])      # Cauchy's bound
    crit = [x for x in real_roots([k * c[k] for k in range(1, n + 1)]) if -bound < x < bound]
    pts = [-bound] + sorted(crit) + [bound]
    vals = [_val(c, x) for x in pts]
    out = []
    for i, x in enumerate(pts):
        if 0 < i < len(pts) - 1 and abs(vals[i][0]) <= vals[i][1]:
            out.append(x)                        # a double root (at rounding level)
    for (lo, (flo, elo)), (hi, (fhi, ehi)) in zip(zip(pts, vals), zip(pts[1:], vals[1:])):
        if abs(flo) <= elo or abs(fhi) <= ehi:
            continue
        if (flo > 0) != (fhi > 0):
            out.append(_bracket(c, lo, hi, flo, fhi))
    return sorted(out)


def choose_phi0(p, poly):
    """φ₀ and the polynomial ``poly(p, φ₀)`` of a class-III group's closures: φ₀ chosen so
    that φ₀ + π is no closure (the leading coefficient of the degree-6 polynomial is not
    small), from a few trial values; None where the polynomial cannot be formed."""
    best = None
    for phi0 in (0.0, 1.0, 2.0, 3.0, 4.0, 5.0):
        c = poly(p, phi0)
        if c is None:
            return None
        lead = abs(c[-1]) / max(float(np.max(np.abs(c))), 1e-300) if len(c) >= 7 else 0.0
        if best is None or lead > best[0]:
            best = (lead, phi0, c)
        if lead >= 1e-3:
            break
    return best[1], best[2]


def _phi0(p):
    return choose_phi0(p, _quartic)


def _b_candidates(phi, p):
    """B at the plate angle φ: by Cramer's rule, and B's two points on the circles about A
    and about D − L u(φ) (where Cramer's determinant vanishes)."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = p
    c, s = math.cos(phi), math.sin(phi)
    out = []
    m11, m12 = 2 * (L * c - dx + ax), 2 * (L * s - dy + ay)
    px, py = xi * c - eta * s, xi * s + eta * c
    m21, m22 = 2 * (px - ex + ax), 2 * (py - ey + ay)
    # relative to A: 2 B'·(Lu − D') = −(|Lu − D'|² − d² + a²), likewise for X
    r1 = -((L * c - dx + ax) ** 2 + (L * s - dy + ay) ** 2 - d * d + a * a)
    r2 = -((px - ex + ax) ** 2 + (py - ey + ay) ** 2 - e * e + a * a)
    det = m11 * m22 - m12 * m21
    if det != 0.0 and math.isfinite(det):
        out.append((ax + (r1 * m22 - m12 * r2) / det, ay + (m11 * r2 - r1 * m21) / det))
    for sigma in (1.0, -1.0):
        bx, by, ok, _ = _b_of(phi, ax, ay, a, dx, dy, d, L, sigma)
        out.append((float(bx), float(by)))
    return out


def _residual(q, pose) -> float:
    """The largest error of the three lengths at the plate pose (bx, by, φ)."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = q
    B, C, X = _corners_of(q, pose, eta)
    return max(abs(math.dist(B, (ax, ay)) - a), abs(math.dist(C, (dx, dy)) - d),
               abs(math.dist(X, (ex, ey)) - e))


def _routes(q):
    """The group restated from each corner in turn (B, then C, then X first): (its
    parameters, a function taking its closure (bx′, by′, φ′) back to the plate pose (bx, by,
    φ)).  Eliminated from B the polynomial cannot tell apart two closures whose plate angles
    nearly agree where DC ∥ EX (Cramer's determinant of B vanishes there: the plate translates
    along a line at one φ), from C where AB ∥ EX, from X where AB ∥ DC; the union of the three
    misses a closure only where all three links are parallel."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = q
    yield q, (lambda pose: pose)
    # from C: C at the origin, B at (L, 0), X at (L − ξ, −η); φ′ = φ + π
    def from_c(pose):
        cx, cy, ph = pose
        return (cx + L * math.cos(ph), cy + L * math.sin(ph), ph - math.pi)
    yield (dx, dy, d, ax, ay, a, ex, ey, e, L, L - xi, -eta), from_c
    # from X: X at the origin, B at (|XB|, 0), C where the plate puts it
    lxb = math.hypot(xi, eta)
    if lxb > 0.0:
        ux, uy = -xi / lxb, -eta / lxb            # X→B in the plate frame
        wx, wy = L - xi, -eta                      # X→C
        xi3, eta3 = wx * ux + wy * uy, wy * ux - wx * uy
        beta = math.atan2(uy, ux)                  # the direction of X→B in the plate frame

        def from_x(pose):
            xx, xy, ph = pose                      # ph: the direction of X→B
            bx, by = xx + lxb * math.cos(ph), xy + lxb * math.sin(ph)
            return (bx, by, ph - beta)
        # B on the circle (A, a) second, C on (D, d) third, in the frame X→B
        yield (ex, ey, e, ax, ay, a, dx, dy, d, lxb, xi3, eta3), from_x


def closures(p, size=None) -> list[tuple[float, float, float, float]]:
    """Every closure (bx, by, φ, η) of the group with parameters ``p`` = (ax, ay, a, dx, dy, d,
    ex, ey, e, L, ξ, η, mirror): each real root of the polynomial eliminated from each corner
    in turn (:func:`_routes`; and, with ``mirror``, of the mirrored plate's), polished by
    Newton and checked against the three lengths; each closure once."""
    *q, mirror = p
    q = tuple(float(v) for v in q)
    if not all(math.isfinite(v) for v in q):
        return []
    size = size or max(abs(v) for v in q) or 1.0
    out, seen = [], []
    for eta in ((q[11], -q[11]) if mirror and q[11] != 0.0 else (q[11],)):
        qq = q[:11] + (eta,)
        for rq, back in _routes(qq):
            for pose in TRIAD.closures_from(rq, size):
                pose = back(pose)
                pts = _corners_of(qq, pose, eta)
                if _residual(qq, pose) <= 1e-9 * size and all(
                        max(math.dist(pts[i], o[i]) for i in range(3)) > 1e-9 * size
                        for o in seen):
                    seen.append(pts)
                    out.append(pose + (eta,))
    return out


def _b_of(phi, ax, ay, a, dx, dy, d, L, sigma):
    """B on the circle about A and on the circle about D − L u(φ); (bx, by, ok, h²)."""
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


def _distinct(points, size):
    """The closures' corners without repeats (a root found twice)."""
    out = []
    for pts in points:
        if all(max(math.dist(pts[i], q[i]) for i in range(3)) > 1e-9 * size for q in out):
            out.append(pts)
    return out


def all_corners(p, size) -> list[tuple]:
    """The corners (B, C, X) of every closure (:func:`closures`), without repeats."""
    q = tuple(float(v) for v in p[:12])
    return _distinct([_corners_of(q, pose[:3], pose[3]) for pose in closures(p, size)], size)


def separation(cands) -> float:
    """The least distance between two closures (the largest of their corners' distances);
    inf with fewer than two."""
    best = math.inf
    for i, c in enumerate(cands):
        for o in cands[i + 1:]:
            best = min(best, max(math.dist(c[k], o[k]) for k in range(3)))
    return best


_NAN7 = (math.nan,) * 6 + (-1.0,)


def _newton(q, pose, size, iters=30):
    """The closure of the group ``q`` = (ax, ay, a, dx, dy, d, ex, ey, e, L, ξ, η) near the
    plate pose (bx, by, φ), by Newton on |B − A|² = a², |C − D|² = d², |X − E|² = e²; returns
    (pose, margin) with margin = |det J| / (|J₁| |J₂| |J₃|) (φ scaled by the size: 0 where
    two closures meet), or (None, −1) where it does not converge."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = q
    bx, by, phi = pose
    floor = 1e3 * _EPS * size * size        # F (lengths squared) at rounding level
    prev = math.inf
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
        step = max(abs(step_b), abs(step_p), abs(d3 / det))
        res = max(abs(f1), abs(f2), abs(f3))
        # converged: the step at the last bits, or no longer shrinking with the equations
        # already met to rounding (the floor of this group's conditioning, not an absolute)
        if step <= 4.0 * _EPS * size or (res <= floor and step >= 0.5 * prev):
            break
        prev = step
    else:
        if not res <= floor:
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


#: below this conditioning margin another closure may lie near the one Newton found: the
#: followed closure is then checked against every closure (it must be the nearest)
_SURE = 0.05


def _listed(q, mirror, size):
    """Every closure as (corners (B, C, X), pose (bx, by, φ, η)), without repeats."""
    out = []
    for pose in closures(q + (mirror,), size):
        pts = _corners_of(q, pose[:3], pose[3])
        if all(max(math.dist(pts[i], o[0][i]) for i in range(3)) > 1e-9 * size for o in out):
            out.append((pts, pose))
    return out


@dataclass(frozen=True)
class ClosureFamily:
    """What following a class-III group's closure needs of its own geometry: ``n`` numbers
    of the group before the plate's mirror η, ``newton(qq, (bx, by, φ), size)`` → (pose,
    margin), ``corners(qq, (bx, by, φ))`` → (P₁, P₂, P₃) with qq = q[:n] + (η,),
    ``listed(q, mirror, size)`` → every closure as (corners, pose), ``margin(qq, pose, size)``."""
    n: int
    newton: Callable
    corners: Callable
    listed: Callable
    margin: Callable
    #: ``phi0(qq)`` → (φ₀, the polynomial) or None; ``b_candidates(φ, qq)`` → the corner
    #: P₁ there; ``residual(qq, pose)`` → the loop equations' largest error
    phi0: Callable
    b_candidates: Callable
    residual: Callable

    def closures_from(self, qq, size) -> list[tuple[float, float, float]]:
        """Every closure (bx, by, φ) of ``qq`` by the polynomial eliminated from its first
        corner: each real root, each candidate P₁ there polished by Newton (where Cramer's
        determinant nearly vanishes two closures share nearly one φ and differ in P₁),
        checked against the loop equations."""
        got = self.phi0(qq)
        if got is None:
            return []
        phi0, c = got
        out = []
        for t in real_roots(c):
            phi = phi0 + 2.0 * math.atan(t)
            for bx, by in self.b_candidates(phi, qq):
                if not (math.isfinite(bx) and math.isfinite(by)):
                    continue
                pose = (bx, by, phi)
                new, _ = self.newton(qq, pose, size)
                if new is not None and self.residual(qq, new) <= self.residual(qq, pose):
                    pose = new
                if self.residual(qq, pose) <= 1e-9 * size:
                    out.append(pose)
        return out

    def follow(self, q, mirror, ref_b, ref_x, size, pose=None, fallback=True, reach=None):
        """The closure nearest the reference corners: Newton from ``pose`` (the
        neighbour's), checked against every closure where it is ill-conditioned
        (:data:`_SURE`: it must be the nearest); without a pose, or where Newton fails, the
        nearest of every closure.  With a pose, a closure farther than ``reach`` (default a
        quarter of the size) from the reference is not its continuation: None (the followed
        closure is gone).  Returns (corners, pose, margin) or None."""
        reach = 0.25 * size if reach is None else reach
        if pose is not None:
            qq = q[:self.n] + (pose[3],)
            new, m = self.newton(qq, pose[:3], size)
            if new is not None:
                B, C, X = self.corners(qq, new)
                if max(math.dist(B, ref_b), math.dist(X, ref_x)) <= reach and m >= _SURE:
                    return (B, C, X), new + (pose[3],), m
            if not fallback:
                return None
        cands = self.listed(q, mirror, size)
        if not cands:
            return None
        dist = [max(math.dist(c[0][0], ref_b), math.dist(c[0][2], ref_x)) for c in cands]
        i = int(np.argmin(dist))
        if pose is not None and dist[i] > reach:
            return None                         # the followed closure is gone
        (B, C, X), new = cands[i]
        return (B, C, X), new, self.margin(q[:self.n] + (new[3],), new[:3], size)

    def from_reference(self, q, mirror, ref_b, ref_x, size, ref_poses):
        """The closure at the reference corners: Newton from each pose ``ref_poses`` gives
        (no fallback), else the nearest of every closure."""
        for pose in ref_poses:
            res = self.follow(q, mirror, ref_b, ref_x, size, pose, fallback=False)
            if res is not None:
                return res
        return self.follow(q, mirror, ref_b, ref_x, size)


_SIN_1DEG = math.sin(math.radians(1.0))
_PAIRS = ((0, 1, 2), (0, 2, 1), (1, 2, 0))


def construction_sine(q, B, C, X) -> float:
    """The sine of the smallest angle of the group's construction (the conditioning a solve
    and a sweep report, one definition): the two links' lines that meet at S, then the line
    S–P₃ against the third link, for the pair the construction takes (AB, DC unless they are
    parallel within 1°, then the pair that meets best: :meth:`Triad.for_instant`).  Zero only
    where the three links' lines are concurrent (two closures meet)."""
    ax, ay, _, dx, dy, _, ex, ey = q[:8]
    P = (B, C, X)
    u = ((B[0] - ax, B[1] - ay), (C[0] - dx, C[1] - dy), (X[0] - ex, X[1] - ey))
    O = ((ax, ay), (dx, dy), (ex, ey))

    def sin(a, b):
        n = math.hypot(*a) * math.hypot(*b)
        return abs(a[0] * b[1] - a[1] * b[0]) / n if n > 0 else 0.0
    s = [sin(u[i], u[j]) for i, j, _ in _PAIRS]
    v = 0 if s[0] >= _SIN_1DEG else max(range(3), key=s.__getitem__)
    i, j, k = _PAIRS[v]
    cr = u[i][0] * u[j][1] - u[i][1] * u[j][0]
    if cr == 0.0:
        return 0.0
    t = ((O[j][0] - O[i][0]) * u[j][1] - (O[j][1] - O[i][1]) * u[j][0]) / cr
    S = (O[i][0] + t * u[i][0], O[i][1] + t * u[i][1])
    return min(s[v], sin((P[k][0] - S[0], P[k][1] - S[1]), u[k]))


def margin_at(q, pose, size) -> float:
    """The conditioning of the closure at the plate pose: |det J| / (|J₁| |J₂| |J₃|) of the
    loop equations (φ scaled by the size; 0 where two closures meet)."""
    ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta = q
    bx, by, phi = pose
    c, s = math.cos(phi), math.sin(phi)
    cx, cy = bx + L * c - dx, by + L * s - dy
    xx, xy = bx + xi * c - eta * s - ex, by + xi * s + eta * c - ey
    ux, uy = bx - ax, by - ay
    j23 = (cx * -L * s + cy * L * c) / size
    j33 = (xx * (-xi * s - eta * c) + xy * (xi * c - eta * s)) / size
    det = ux * (cy * j33 - j23 * xy) - uy * (cx * j33 - j23 * xx)
    norms = (math.hypot(ux, uy) * math.sqrt(cx * cx + cy * cy + j23 * j23)
             * math.sqrt(xx * xx + xy * xy + j33 * j33))
    return abs(det) / norms if norms > 0 else 0.0


def _ref_poses(q, mirror, ref_b, ref_x):
    """Plate poses (bx, by, φ, η) that put B at ``ref_b`` and X towards ``ref_x``."""
    xi, eta = q[10], q[11]
    out = []
    for e in ((eta, -eta) if mirror and eta else (eta,)):
        phi = (math.atan2(ref_x[1] - ref_b[1], ref_x[0] - ref_b[0]) - math.atan2(e, xi))
        out.append((ref_b[0], ref_b[1], phi, e))
    return out


TRIAD = ClosureFamily(11, _newton, lambda qq, pose: _corners_of(qq, pose, qq[11]), _listed,
                      margin_at, _phi0, _b_candidates, _residual)
_follow = TRIAD.follow


def _from_reference(q, mirror, ref_b, ref_x, size):
    """Newton from the reference's own pose (the fast path: at the reference's input it is
    the closure itself); else the nearest of every closure."""
    return TRIAD.from_reference(q, mirror, ref_b, ref_x, size,
                                _ref_poses(q, mirror, ref_b, ref_x))


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
    return (*B, *C, *X, construction_sine(q, B, C, X) if m > 0 else m)


def triad_cols(ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta, mirror, rbx, rby, rxx, rxy,
               size):
    """:func:`triad_scalar` over N positions, by continuation: the position whose closure
    is nearest the reference first (where the reference corners meet the lengths: the input
    the reference was taken at), then outwards, each by Newton from its neighbour's closure,
    checked against every closure where ill-conditioned, and never jumping farther than four
    times the last step's motion.  Where the followed closure is lost (it met another and both vanished) the
    positions beyond are NaN and the margin −1: the limit of travel."""
    arrs = [np.asarray(v, dtype=float) for v in (ax, ay, a, dx, dy, d, ex, ey, e, L, xi, eta)]

    def misfit(P):
        """How far the reference corners are from closing the group at each position."""
        return (np.abs(np.hypot(rbx - P[0], rby - P[1]) - P[2])
                + np.abs(np.hypot(rxx - P[6], rxy - P[7]) - P[8]))

    return follow_closure(arrs, misfit, _from_reference, _follow, construction_sine, mirror,
                          (rbx, rby), (rxx, rxy), size)


def follow_closure(arrs, misfit, from_reference, follow, sine, mirror, ref_b, ref_x, size):
    """A class-III group's closure over N positions by continuation (:func:`triad_cols`, and
    the triad with a block's): ``arrs`` the group's data columns, ``misfit(P)`` how far the
    reference corners are from closing it at each position, ``from_reference``/``follow``
    the group's Newton starts, ``sine`` its smallest construction sine.  Returns the seven
    columns (B, C, X, margin), NaN and margin −1 beyond the followed closure's end."""
    shape = np.broadcast_shapes(*(v.shape for v in arrs))
    n = int(np.prod(shape)) if shape else 1
    cols = [np.broadcast_to(v, shape).reshape(n).tolist() for v in arrs]
    out = np.full((7, n), np.nan)
    out[6] = -1.0
    qs = [tuple(c[k] for c in cols) for k in range(n)]
    start, best, first = None, math.inf, None
    # first the position where the reference closes the group best (the reference is a
    # closure at one of the inputs: the scene's own, or the one a sweep was anchored at),
    # then probes through the rest
    with np.errstate(all="ignore"):
        r = misfit(np.array(cols))
    order = ([int(np.nanargmin(r))] if np.isfinite(r).any() else []) \
        + list(range(0, n, max(1, n // 8)))
    for k in order:
        if not all(math.isfinite(v) for v in qs[k]):
            continue
        res = from_reference(qs[k], mirror, ref_b, ref_x, size)
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
            res, moved = first, None
            for k in rng:
                if k != start:
                    if done[k] or not all(math.isfinite(v) for v in qs[k]):
                        break
                    (B, _, X), pose, _ = res
                    reach = 0.25 * size if moved is None else max(4.0 * moved, 1e-3 * size)
                    new = follow(qs[k], mirror, B, X, size, pose, reach=reach)
                    if new is None:
                        break
                    moved = max(math.dist(new[0][0], B), math.dist(new[0][2], X))
                    res = new
                (B, C, X), _, m = res
                out[:, k] = (*B, *C, *X,
                             sine(qs[k], B, C, X) if m > 0 else m)
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
