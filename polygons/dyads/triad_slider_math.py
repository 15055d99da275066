"""Every closure of a class-III group whose third corner is a block on a fixed guide (two links
and a block: :mod:`polygons.dyads.triad_slider`), found algebraically as
:mod:`polygons.dyads.triad_math` finds the three-link triad's: the same plate, one circle
constraint replaced by a line.

The plate: corners P₁, P₂, P₃ (in its own frame P₁ = (0, 0), P₂ = (L, 0), P₃ = (ξ, η)); P₁
joined by a link to A (|AP₁| = a), P₂ to D (|DP₂| = d), P₃ a pin in a block sliding on the
fixed guide through G along e (normal n = perp e).  With φ the direction of P₁→P₂ and B = P₁
(A at the origin) the loop equations are

    |B|² = a²,   |B + L u(φ) − D|² = d²,   n·(B + R(φ)(ξ, η) − G) = 0.

The second less the first, and the third, are *linear* in B (coefficients linear in cos φ,
sin φ): B = (N_x, N_y) / Δ by Cramer's rule and the first becomes
q(φ) = N_x² + N_y² − a² Δ² = 0, a quartic form in (cos φ, sin φ).  With φ = φ₀ + 2 atan t,
(1 + t²)⁴ q is a polynomial of degree 8 in t with the factor 1 + t² (the coupler curve of the
four-bar A P₁ P₂ D traced by P₃ is a tricircular sextic: a line meets it in at most 6 points),
so what is left has degree ≤ 6 and every closure among its real roots.  Those are isolated by
:func:`polygons.dyads.triad_math.real_roots` (the roots of the derivatives cut the line into
monotone pieces: two closures however close are both found), each polished by Newton on the
three loop equations (stopped at the rounding floor of the group's own conditioning) and
checked against the two lengths and the guide.  With a triangle of three links for the plate
its mirror image η → −η is a group too.

Continuation through a sweep (:func:`triad_slider_cols`) is the three-link triad's: Newton
from the neighbour's closure, checked against every closure where ill-conditioned, never
jumping farther than four times the last step's motion.
"""
from __future__ import annotations

import math

import numpy as np

from .triad_math import _EPS, ClosureFamily, choose_phi0, eliminated, first_corner

_NAN7 = (math.nan,) * 6 + (-1.0,)


def _unpack(q):
    ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta = q
    n = math.hypot(ex, ey)
    return ax, ay, a, dx, dy, d, gx, gy, ex / n, ey / n, L, xi, eta


def _poly(q, phi0):
    """The coefficients (low → high, in t) of (1 + t²)³ q(φ₀ + 2 atan t) / s⁴ (s the group's
    size), of degree ≤ 6 (degree 8 where the factor 1 + t² does not divide out to rounding)."""
    ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta = _unpack(q)
    dx, dy, gx, gy = dx - ax, dy - ay, gx - ax, gy - ay
    # the guide's point nearest A (the size must not depend on where along it G was given)
    along = gx * ex + gy * ey
    gx, gy = gx - along * ex, gy - along * ey
    s = max(a, d, L, math.hypot(dx, dy), math.hypot(gx, gy), math.hypot(xi, eta))
    if not s > 0.0:
        return None
    a, d, L, xi, eta, dx, dy, gx, gy = (v / s for v in (a, d, L, xi, eta, dx, dy, gx, gy))
    nx, ny = -ey, ex
    lin, m11, m12, r1 = first_corner(phi0, a, d, L, dx, dy)
    # n·B = n·G − n·R(φ)(ξ, η) = n·G − cos φ (n_x ξ + n_y η) − sin φ (n_y ξ − n_x η)
    m21, m22 = lin(nx, 0.0, 0.0), lin(ny, 0.0, 0.0)
    r2 = lin(nx * gx + ny * gy, -(nx * xi + ny * eta), -(ny * xi - nx * eta))
    full, q6, rem = eliminated(a, m11, m12, r1, m21, m22, r2)
    big = float(np.max(np.abs(full))) if len(full) else 0.0
    if float(np.max(np.abs(rem), initial=0.0)) <= 1e-10 * max(big, 1e-300):
        return q6
    return full


def _phi0(q):
    return choose_phi0(q, _poly)


def corners_of(q, pose):
    """(P₁, P₂, P₃) at the plate pose (bx, by, φ)."""
    L, xi, eta = q[10], q[11], q[12]
    bx, by, phi = pose
    c, s = math.cos(phi), math.sin(phi)
    return ((bx, by), (bx + L * c, by + L * s),
            (bx + xi * c - eta * s, by + xi * s + eta * c))


def _residual(q, pose) -> float:
    """The largest error of the two lengths and of P₃'s distance from the guide."""
    ax, ay, a, dx, dy, d, gx, gy, ex, ey = _unpack(q)[:10]
    B, C, X = corners_of(q, pose)
    return max(abs(math.dist(B, (ax, ay)) - a), abs(math.dist(C, (dx, dy)) - d),
               abs((X[0] - gx) * -ey + (X[1] - gy) * ex))


def _b_candidates(phi, q):
    """B at the plate angle φ: by Cramer's rule, and where its determinant vanishes B's two
    points on the circle about A and the line the guide makes of it."""
    ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta = _unpack(q)
    nx, ny = -ey, ex
    c, s = math.cos(phi), math.sin(phi)
    m11, m12 = 2 * (L * c - dx + ax), 2 * (L * s - dy + ay)
    r1 = -((L * c - dx + ax) ** 2 + (L * s - dy + ay) ** 2 - d * d + a * a)
    px, py = xi * c - eta * s, xi * s + eta * c
    r2 = nx * (gx - ax - px) + ny * (gy - ay - py)         # n·B′ = r2 (B′ = B − A)
    out = []
    det = m11 * ny - m12 * nx
    if det != 0.0 and math.isfinite(det):
        out.append((ax + (r1 * ny - m12 * r2) / det, ay + (m11 * r2 - r1 * nx) / det))
    h2 = a * a - r2 * r2                                    # B′ = r2 n ± h e on |B′| = a
    if h2 >= 0.0:
        h = math.sqrt(h2)
        for sg in (1.0, -1.0):
            out.append((ax + r2 * nx + sg * h * ex, ay + r2 * ny + sg * h * ey))
    return out


def _jacobian(q, pose, size):
    """The loop equations F (|B − A|² − a², |C − D|² − d², n·(X − G)·size) and their
    Jacobian rows in (bx, by, φ·size), halved for the first two."""
    ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta = _unpack(q)
    nx, ny = -ey, ex
    bx, by, phi = pose
    c, s = math.cos(phi), math.sin(phi)
    cx, cy = bx + L * c - dx, by + L * s - dy              # C − D
    ux, uy = bx - ax, by - ay                               # B − A
    px, py = xi * c - eta * s, xi * s + eta * c             # X − B
    f1 = ux * ux + uy * uy - a * a
    f2 = cx * cx + cy * cy - d * d
    f3 = (nx * (bx + px - gx) + ny * (by + py - gy)) * size
    j23 = (cx * -L * s + cy * L * c) / size
    # rows: [ux, uy, 0], [cx, cy, j23], [nx·size/2, ny·size/2, (n·∂X/∂φ)/2]
    h = 0.5 * size
    j3 = (h * nx, h * ny, 0.5 * (nx * -py + ny * px))
    return (f1, f2, f3), ((ux, uy, 0.0), (cx, cy, j23), j3)


def _det3(r0, r1, r2):
    return (r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0])
            + r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]))


def _margin(rows) -> float:
    det = _det3(*rows)
    norms = math.prod(math.sqrt(sum(v * v for v in r)) for r in rows)
    return abs(det) / norms if norms > 0 else 0.0


def _newton(q, pose, size, iters=30):
    """The closure near the plate pose (bx, by, φ), by Newton on the three loop equations;
    returns (pose, margin) with margin = |det J| / (|J₁| |J₂| |J₃|) (0 where two closures
    meet), or (None, −1) where it does not converge."""
    bx, by, phi = pose
    floor = 1e3 * _EPS * size * size
    prev = math.inf
    res = math.inf
    for _ in range(iters):
        (f1, f2, f3), rows = _jacobian(q, (bx, by, phi), size)
        det = _det3(*rows)
        if det == 0.0 or not math.isfinite(det):
            return None, -1.0
        rhs = (-0.5 * f1, -0.5 * f2, -0.5 * f3)
        st = []
        for k in range(3):          # Cramer's rule, column k replaced by the right side
            cols = [list(r) for r in rows]
            for i in range(3):
                cols[i][k] = rhs[i]
            st.append(_det3(*cols) / det)
        bx, by, phi = bx + st[0], by + st[1], phi + st[2] / size
        step = max(abs(v) for v in st)
        res = max(abs(f1), abs(f2), abs(f3))
        if step <= 4.0 * _EPS * size or (res <= floor and step >= 0.5 * prev):
            break
        prev = step
    else:
        if not res <= floor:
            return None, -1.0
    _, rows = _jacobian(q, (bx, by, phi), size)
    return (bx, by, phi), _margin(rows)


def margin_at(q, pose, size) -> float:
    """The conditioning of the closure at the plate pose (0 where two closures meet)."""
    return _margin(_jacobian(q, pose, size)[1])


def closures(p, size=None) -> list[tuple[float, float, float, float]]:
    """Every closure (bx, by, φ, η) of the group with parameters ``p`` = (ax, ay, a, dx, dy, d,
    gx, gy, ex, ey, L, ξ, η, mirror): the real roots of the polynomial eliminated from P₁ and
    of the one eliminated from P₂ (the first cannot tell apart two closures of nearly one φ
    where DP₂ is normal to the guide, the second where AP₁ is), and, with ``mirror``, the
    mirrored plate's; each polished by Newton, checked against the loop equations, once."""
    *q, mirror = p
    q = tuple(float(v) for v in q)
    if not all(math.isfinite(v) for v in q) or math.hypot(q[8], q[9]) == 0.0:
        return []
    size = size or max(abs(v) for v in q) or 1.0
    out, seen = [], []
    ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi = q[:12]
    for eta in ((q[12], -q[12]) if mirror and q[12] != 0.0 else (q[12],)):
        qq = q[:12] + (eta,)
        qc = (dx, dy, d, ax, ay, a, gx, gy, ex, ey, L, L - xi, -eta)
        poses = FAMILY.closures_from(qq, size) + [
            (cx + L * math.cos(ph), cy + L * math.sin(ph), ph - math.pi)
            for cx, cy, ph in FAMILY.closures_from(qc, size)]
        for pose in poses:
            pts = corners_of(qq, pose)
            if _residual(qq, pose) <= 1e-9 * size and all(
                    max(math.dist(pts[i], o[i]) for i in range(3)) > 1e-9 * size for o in seen):
                seen.append(pts)
                out.append(pose + (eta,))
    return out


def _listed(q, mirror, size):
    """Every closure as (corners, pose (bx, by, φ, η)), without repeats."""
    out = []
    for pose in closures(q + (mirror,), size):
        pts = corners_of(q[:12] + (pose[3],), pose[:3])
        if all(max(math.dist(pts[i], o[0][i]) for i in range(3)) > 1e-9 * size for o in out):
            out.append((pts, pose))
    return out


def all_corners(p, size) -> list[tuple]:
    """The corners (P₁, P₂, P₃) of every closure, without repeats."""
    q = tuple(float(v) for v in p[:13])
    return [c for c, _ in _listed(q, p[13], size)]


_SIN_1DEG = math.sin(math.radians(1.0))


def construction_sine(q, B, C, X) -> float:
    """The sine of the smallest angle of the group's construction (one definition for a solve
    and a sweep): the two lines that meet at S — AP₁ and DP₂ produced, unless they are parallel
    within 1°, then the pair of the three (with the normal to the guide at P₃) that meets best
    (:meth:`polygons.dyads.triad_slider.TriadSlider.for_instant`) — then the line from S to the
    third corner against that corner's own line (its link, or the guide's normal).  Zero only
    where the three lines are concurrent (two closures meet)."""
    ax, ay, _, dx, dy, _, _, _, ex, ey = _unpack(q)[:10]
    n = (-ey, ex)
    lines = (((ax, ay), (B[0] - ax, B[1] - ay)), ((dx, dy), (C[0] - dx, C[1] - dy)), (X, n))
    corner = (B, C, X)

    def sin(a, b):
        m = math.hypot(*a) * math.hypot(*b)
        return abs(a[0] * b[1] - a[1] * b[0]) / m if m > 0 else 0.0
    pairs = ((0, 1, 2), (0, 2, 1), (1, 2, 0))
    s = [sin(lines[i][1], lines[j][1]) for i, j, _ in pairs]
    v = 0 if s[0] >= _SIN_1DEG else max(range(3), key=s.__getitem__)
    i, j, k = pairs[v]
    (oi, ui), (oj, uj) = lines[i], lines[j]
    cr = ui[0] * uj[1] - ui[1] * uj[0]
    if cr == 0.0:
        return 0.0
    t = ((oj[0] - oi[0]) * uj[1] - (oj[1] - oi[1]) * uj[0]) / cr
    S = (oi[0] + t * ui[0], oi[1] + t * ui[1])
    P = corner[k]
    return min(s[v], sin((P[0] - S[0], P[1] - S[1]), lines[k][1]))


def _ref_poses(q, mirror, ref_b, ref_x):
    """Plate poses (bx, by, φ, η) that put P₁ at ``ref_b`` and P₃ towards ``ref_x``."""
    xi, eta = q[11], q[12]
    out = []
    for e in ((eta, -eta) if mirror and eta else (eta,)):
        phi = math.atan2(ref_x[1] - ref_b[1], ref_x[0] - ref_b[0]) - math.atan2(e, xi)
        out.append((ref_b[0], ref_b[1], phi, e))
    return out


#: following the closure: as the three-link triad's (:class:`triad_math.ClosureFamily`)
FAMILY = ClosureFamily(12, _newton, corners_of, _listed, margin_at, _phi0, _b_candidates,
                       _residual)
_follow = FAMILY.follow


def _from_reference(q, mirror, ref_b, ref_x, size):
    return FAMILY.from_reference(q, mirror, ref_b, ref_x, size,
                                 _ref_poses(q, mirror, ref_b, ref_x))


def triad_slider_scalar(ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta, mirror, rbx, rby,
                        rxx, rxy, size):
    """The closure nearest the reference corners (P₁ at rb, P₃ at rx): (p1x, p1y, p2x, p2y,
    p3x, p3y, margin), margin the smallest construction sine (0 where two closures meet; −1
    and NaN where the group cannot close)."""
    q = (ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta)
    if not all(math.isfinite(v) for v in q + (rbx, rby, rxx, rxy)) or math.hypot(ex, ey) == 0:
        return _NAN7
    res = _from_reference(q, mirror, (rbx, rby), (rxx, rxy), size)
    if res is None:
        return _NAN7
    (B, C, X), _, m = res
    return (*B, *C, *X, construction_sine(q, B, C, X) if m > 0 else m)


def triad_slider_cols(ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi, eta, mirror, rbx, rby,
                      rxx, rxy, size):
    """:func:`triad_slider_scalar` over N positions, by continuation (as
    :func:`polygons.dyads.triad_math.triad_cols`): the position whose closure is nearest the
    reference first, then outwards, each by Newton from its neighbour's closure; where the
    followed closure is lost the positions beyond are NaN and the margin −1."""
    from .triad_math import follow_closure
    arrs = [np.asarray(v, dtype=float) for v in (ax, ay, a, dx, dy, d, gx, gy, ex, ey, L, xi,
                                                 eta)]

    def misfit(P):
        """How far the reference corner P₁ is from its link's circle at each position."""
        return np.abs(np.hypot(rbx - P[0], rby - P[1]) - P[2])

    return follow_closure(arrs, misfit, _from_reference, _follow, construction_sine, mirror,
                          (rbx, rby), (rxx, rxy), size)
