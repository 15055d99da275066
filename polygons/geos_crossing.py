"""Where two drawn segments cross, computed as shapely (GEOS) computes it, in plain floats.

shapely intersects two line segments that cross at one interior point with GEOS's
``LineIntersector``: the orientation of each segment's ends about the other (a floating-point
filter, exact where decisive), then ``CGAlgorithmsDD::intersection`` — the homogeneous
coordinates of the two lines in double-double arithmetic (``math::DD``: Dekker's splitting,
no fused multiply-add) —

    p = (p1y − p2y, p2x − p1x, p1x p2y − p2x p1y),   q likewise,
    X = (py qw − qy pw) / (px qy − qx py),   Y = (qx pw − px qw) / (px qy − qx py),

kept where it lies in both segments' envelopes.  :func:`crossing` is that arithmetic written
out operation by operation over Python floats (IEEE doubles rounded to nearest, as GEOS's are
on every platform shapely ships for), so it returns the very doubles shapely returns — not the
correctly rounded crossing, which differs from GEOS's in about one case in two thousand by an
ulp — in a quarter of the time, without building geometries.  Where GEOS would take another
branch (an end on the other line, an undecided orientation, a point outside the envelopes, a
division by zero) it returns None and the caller asks shapely itself
(:func:`polygons.geometry.meet`).  ``tests/test_geometry.py`` holds it to shapely bit for bit.

The body of :func:`crossing` is :func:`source`'s output (the GEOS operations with the exact
identities x − 0 = x, x + (−0) = x folded and single-use temporaries inlined), pasted here so
that importing this module compiles nothing; the test regenerates it and compares.
"""
from __future__ import annotations

SPLIT = 134217729.0          # 2^27 + 1: Dekker's splitting constant (GEOS math::DD::SPLIT)
#: GEOS's orientation filter (CGAlgorithmsDD::orientationIndexFilter, Ozaki et al.)
_ORIENT_ERR = 3.3306690621773724e-16


def proper(ax, ay, bx, by, cx, cy, dx, dy) -> bool:
    """Whether GEOS finds segments AB and CD crossing at one interior point (its
    ``computeIntersect`` takes the proper branch): each segment's ends strictly on either side
    of the other's line, every orientation decided by GEOS's floating-point filter (False
    where the filter cannot decide: GEOS then works in double-double, and so does shapely)."""
    c = _orientation(ax, ay, bx, by, cx, cy)
    d = _orientation(ax, ay, bx, by, dx, dy)
    if c == 0 or d == 0 or c == d:
        return False
    a = _orientation(cx, cy, dx, dy, ax, ay)
    b = _orientation(cx, cy, dx, dy, bx, by)
    return a != 0 and b != 0 and a != b


def _orientation(p1x, p1y, p2x, p2y, qx, qy) -> int:
    """Which side of P1 → P2 the point Q is on (1 left, −1 right) where GEOS's filter
    (``CGAlgorithmsDD::orientationIndexFilter``) decides it; 0 on the line or undecided."""
    left = (p1x - qx) * (p2y - qy)
    right = (p1y - qy) * (p2x - qx)
    det = left - right
    if abs(det) >= abs(left + right) * _ORIENT_ERR:
        return 1 if det > 0.0 else -1 if det < 0.0 else 0
    return 0


def crossing(ax, ay, bx, by, cx, cy, dx, dy):
    """GEOS's crossing of the segments AB and CD (see the module docstring), or None where
    GEOS would not take this branch."""
    if not proper(ax, ay, bx, by, cx, cy, dx, dy):
        return None
    try:
        x, y = _dd_intersection(ax, ay, bx, by, cx, cy, dx, dy)
    except ZeroDivisionError:           # GEOS: a null point, then the nearest end point
        return None
    if not (min(ax, bx) <= x <= max(ax, bx) and min(ay, by) <= y <= max(ay, by)
            and min(cx, dx) <= x <= max(cx, dx) and min(cy, dy) <= y <= max(cy, dy)):
        return None                     # (also NaN, and ±inf: GEOS's nearest end point)
    return x, y


# ---------------------------------------------------------------- the generator
def source() -> str:
    """The text of :func:`_dd_intersection`: GEOS's ``CGAlgorithmsDD::intersection`` with
    ``math::DD``'s ``selfAdd``, ``selfMultiply`` and ``selfDivide`` written out, the exact
    identities folded, the temporaries used once inlined."""
    import re
    defs: dict[str, str] = {}
    order: list[str] = []
    zero, nzero = "0.0", "-0.0"

    def op(a, o, b):
        if a in (zero, nzero) and b in (zero, nzero):
            return repr(eval(f"({a}) {o} ({b})"))       # both known: the constant
        if (o == "-" and b == zero) or (o == "+" and b == nzero):
            return a                                     # x − 0 = x, x + (−0) = x, exactly
        if o == "+" and a == nzero:
            return b
        t = f"t{len(order) + 1}"
        defs[t] = f"{a} {o} {b}"
        order.append(t)
        return t

    def neg(a):
        if a in (zero, nzero):
            return nzero if a == zero else zero
        return op("-1.0", "*", a)                        # GEOS: -1 * d.hi

    def add(a, b):                                       # DD::selfAdd(yhi, ylo)
        (hi, lo), (yhi, ylo) = a, b
        S, T = op(hi, "+", yhi), op(lo, "+", ylo)
        e, f = op(S, "-", hi), op(T, "-", lo)
        s, t = op(S, "-", e), op(T, "-", f)
        s = op(op(yhi, "-", e), "+", op(hi, "-", s))
        t = op(op(ylo, "-", f), "+", op(lo, "-", t))
        e = op(s, "+", T)
        H = op(S, "+", e)
        h = op(e, "+", op(S, "-", H))
        e = op(t, "+", h)
        zh = op(H, "+", e)
        return zh, op(e, "+", op(H, "-", zh))

    def sub(a, b):                                       # DD::selfSubtract
        return add(a, (neg(b[0]), neg(b[1])))

    def mul(a, b):                                       # DD::selfMultiply(yhi, ylo)
        (hi, lo), (yhi, ylo) = a, b
        C = op("SPLIT", "*", hi)
        hx = op(C, "-", hi)
        c = op("SPLIT", "*", yhi)
        hx = op(C, "-", hx)
        tx = op(hi, "-", hx)
        hy = op(c, "-", yhi)
        C = op(hi, "*", yhi)
        hy = op(c, "-", hy)
        ty = op(yhi, "-", hy)
        c = op(op(op(op(op(hx, "*", hy), "-", C), "+", op(hx, "*", ty)), "+", op(tx, "*", hy)),
               "+", op(tx, "*", ty))
        c = op(c, "+", op(op(hi, "*", ylo), "+", op(lo, "*", yhi)))
        zh = op(C, "+", c)
        return zh, op(c, "+", op(C, "-", zh))

    def div(a, b):                                       # DD::selfDivide(yhi, ylo)
        (hi, lo), (yhi, ylo) = a, b
        C = op(hi, "/", yhi)
        c = op("SPLIT", "*", C)
        hc = op(c, "-", C)
        u = op("SPLIT", "*", yhi)
        hc = op(c, "-", hc)
        tc = op(C, "-", hc)
        hy = op(u, "-", yhi)
        U = op(C, "*", yhi)
        hy = op(u, "-", hy)
        ty = op(yhi, "-", hy)
        u = op(op(op(op(op(hc, "*", hy), "-", U), "+", op(hc, "*", ty)), "+", op(tc, "*", hy)),
               "+", op(tc, "*", ty))
        c = op(op(op(op(op(hi, "-", U), "-", u), "+", lo), "-", op(C, "*", ylo)), "/", yhi)
        u = op(C, "+", c)
        return u, op(op(C, "-", u), "+", c)

    p1x, p1y, p2x, p2y, q1x, q1y, q2x, q2y = ((v, zero) for v in
                                                "ax ay bx by cx cy dx dy".split())
    px, py = sub(p1y, p2y), sub(p2x, p1x)
    pw = sub(mul(p1x, p2y), mul(p2x, p1y))
    qx, qy = sub(q1y, q2y), sub(q2x, q1x)
    qw = sub(mul(q1x, q2y), mul(q2x, q1y))
    x = sub(mul(py, qw), mul(qy, pw))
    y = sub(mul(qx, pw), mul(px, qw))
    w = sub(mul(px, qy), mul(qx, py))
    xw, yw = div(x, w), div(y, w)
    X, Y = op(xw[0], "+", xw[1]), op(yw[0], "+", yw[1])      # DD::doubleValue: hi + lo
    name = re.compile(r"\bt\d+\b")
    uses = dict.fromkeys(order, 0)
    for t in order:
        for u in name.findall(defs[t]):
            uses[u] += 1
    for u in name.findall(f"{X} {Y}"):
        uses[u] += 1

    def expand(text):
        return name.sub(lambda m: f"({expand(defs[m[0]])})" if uses[m[0]] == 1 else m[0], text)

    body = [f"    {t} = {expand(defs[t])}" for t in order if uses[t] > 1]
    return "\n".join(["def _dd_intersection(ax, ay, bx, by, cx, cy, dx, dy):",
                      '    """Generated by polygons.geos_crossing.source(): do not edit."""',
                      *body, f"    return {expand(X)}, {expand(Y)}", ""])


# ---------------------------------------------------------------- generated (source())
def _dd_intersection(ax, ay, bx, by, cx, cy, dx, dy):
    """Generated by polygons.geos_crossing.source(): do not edit."""
    t1 = -1.0 * by
    t2 = ay + t1
    t3 = t2 - ay
    t8 = ((t1 - t3) + (ay - (t2 - t3))) + 0.0
    t9 = t2 + t8
    t12 = 0.0 + (t8 + (t2 - t9))
    t13 = t9 + t12
    t15 = t12 + (t9 - t13)
    t16 = -1.0 * ax
    t17 = bx + t16
    t18 = t17 - bx
    t23 = ((t16 - t18) + (bx - (t17 - t18))) + 0.0
    t24 = t17 + t23
    t27 = 0.0 + (t23 + (t17 - t24))
    t28 = t24 + t27
    t30 = t27 + (t24 - t28)
    t31 = SPLIT * ax
    t33 = SPLIT * by
    t34 = t31 - (t31 - ax)
    t35 = ax - t34
    t37 = ax * by
    t38 = t33 - (t33 - by)
    t39 = by - t38
    t51 = (((((t34 * t38) - t37) + (t34 * t39)) + (t35 * t38)) + (t35 * t39)) + ((ax * 0.0) + (0.0 * by))
    t52 = t37 + t51
    t54 = t51 + (t37 - t52)
    t55 = SPLIT * bx
    t57 = SPLIT * ay
    t58 = t55 - (t55 - bx)
    t59 = bx - t58
    t61 = bx * ay
    t62 = t57 - (t57 - ay)
    t63 = ay - t62
    t75 = (((((t58 * t62) - t61) + (t58 * t63)) + (t59 * t62)) + (t59 * t63)) + ((bx * 0.0) + (0.0 * ay))
    t76 = t61 + t75
    t79 = -1.0 * t76
    t80 = -1.0 * (t75 + (t61 - t76))
    t81 = t52 + t79
    t82 = t54 + t80
    t83 = t81 - t52
    t84 = t82 - t54
    t93 = ((t79 - t83) + (t52 - (t81 - t83))) + t82
    t94 = t81 + t93
    t97 = ((t80 - t84) + (t54 - (t82 - t84))) + (t93 + (t81 - t94))
    t98 = t94 + t97
    t100 = t97 + (t94 - t98)
    t101 = -1.0 * dy
    t102 = cy + t101
    t103 = t102 - cy
    t108 = ((t101 - t103) + (cy - (t102 - t103))) + 0.0
    t109 = t102 + t108
    t112 = 0.0 + (t108 + (t102 - t109))
    t113 = t109 + t112
    t115 = t112 + (t109 - t113)
    t116 = -1.0 * cx
    t117 = dx + t116
    t118 = t117 - dx
    t123 = ((t116 - t118) + (dx - (t117 - t118))) + 0.0
    t124 = t117 + t123
    t127 = 0.0 + (t123 + (t117 - t124))
    t128 = t124 + t127
    t130 = t127 + (t124 - t128)
    t131 = SPLIT * cx
    t133 = SPLIT * dy
    t134 = t131 - (t131 - cx)
    t135 = cx - t134
    t137 = cx * dy
    t138 = t133 - (t133 - dy)
    t139 = dy - t138
    t151 = (((((t134 * t138) - t137) + (t134 * t139)) + (t135 * t138)) + (t135 * t139)) + ((cx * 0.0) + (0.0 * dy))
    t152 = t137 + t151
    t154 = t151 + (t137 - t152)
    t155 = SPLIT * dx
    t157 = SPLIT * cy
    t158 = t155 - (t155 - dx)
    t159 = dx - t158
    t161 = dx * cy
    t162 = t157 - (t157 - cy)
    t163 = cy - t162
    t175 = (((((t158 * t162) - t161) + (t158 * t163)) + (t159 * t162)) + (t159 * t163)) + ((dx * 0.0) + (0.0 * cy))
    t176 = t161 + t175
    t179 = -1.0 * t176
    t180 = -1.0 * (t175 + (t161 - t176))
    t181 = t152 + t179
    t182 = t154 + t180
    t183 = t181 - t152
    t184 = t182 - t154
    t193 = ((t179 - t183) + (t152 - (t181 - t183))) + t182
    t194 = t181 + t193
    t197 = ((t180 - t184) + (t154 - (t182 - t184))) + (t193 + (t181 - t194))
    t198 = t194 + t197
    t200 = t197 + (t194 - t198)
    t201 = SPLIT * t28
    t203 = SPLIT * t198
    t204 = t201 - (t201 - t28)
    t205 = t28 - t204
    t207 = t28 * t198
    t208 = t203 - (t203 - t198)
    t209 = t198 - t208
    t221 = (((((t204 * t208) - t207) + (t204 * t209)) + (t205 * t208)) + (t205 * t209)) + ((t28 * t200) + (t30 * t198))
    t222 = t207 + t221
    t224 = t221 + (t207 - t222)
    t225 = SPLIT * t128
    t227 = SPLIT * t98
    t228 = t225 - (t225 - t128)
    t229 = t128 - t228
    t231 = t128 * t98
    t232 = t227 - (t227 - t98)
    t233 = t98 - t232
    t245 = (((((t228 * t232) - t231) + (t228 * t233)) + (t229 * t232)) + (t229 * t233)) + ((t128 * t100) + (t130 * t98))
    t246 = t231 + t245
    t249 = -1.0 * t246
    t250 = -1.0 * (t245 + (t231 - t246))
    t251 = t222 + t249
    t252 = t224 + t250
    t253 = t251 - t222
    t254 = t252 - t224
    t263 = ((t249 - t253) + (t222 - (t251 - t253))) + t252
    t264 = t251 + t263
    t267 = ((t250 - t254) + (t224 - (t252 - t254))) + (t263 + (t251 - t264))
    t268 = t264 + t267
    t271 = SPLIT * t113
    t273 = SPLIT * t98
    t274 = t271 - (t271 - t113)
    t275 = t113 - t274
    t277 = t113 * t98
    t278 = t273 - (t273 - t98)
    t279 = t98 - t278
    t291 = (((((t274 * t278) - t277) + (t274 * t279)) + (t275 * t278)) + (t275 * t279)) + ((t113 * t100) + (t115 * t98))
    t292 = t277 + t291
    t294 = t291 + (t277 - t292)
    t295 = SPLIT * t13
    t297 = SPLIT * t198
    t298 = t295 - (t295 - t13)
    t299 = t13 - t298
    t301 = t13 * t198
    t302 = t297 - (t297 - t198)
    t303 = t198 - t302
    t315 = (((((t298 * t302) - t301) + (t298 * t303)) + (t299 * t302)) + (t299 * t303)) + ((t13 * t200) + (t15 * t198))
    t316 = t301 + t315
    t319 = -1.0 * t316
    t320 = -1.0 * (t315 + (t301 - t316))
    t321 = t292 + t319
    t322 = t294 + t320
    t323 = t321 - t292
    t324 = t322 - t294
    t333 = ((t319 - t323) + (t292 - (t321 - t323))) + t322
    t334 = t321 + t333
    t337 = ((t320 - t324) + (t294 - (t322 - t324))) + (t333 + (t321 - t334))
    t338 = t334 + t337
    t341 = SPLIT * t13
    t343 = SPLIT * t128
    t344 = t341 - (t341 - t13)
    t345 = t13 - t344
    t347 = t13 * t128
    t348 = t343 - (t343 - t128)
    t349 = t128 - t348
    t361 = (((((t344 * t348) - t347) + (t344 * t349)) + (t345 * t348)) + (t345 * t349)) + ((t13 * t130) + (t15 * t128))
    t362 = t347 + t361
    t364 = t361 + (t347 - t362)
    t365 = SPLIT * t113
    t367 = SPLIT * t28
    t368 = t365 - (t365 - t113)
    t369 = t113 - t368
    t371 = t113 * t28
    t372 = t367 - (t367 - t28)
    t373 = t28 - t372
    t385 = (((((t368 * t372) - t371) + (t368 * t373)) + (t369 * t372)) + (t369 * t373)) + ((t113 * t30) + (t115 * t28))
    t386 = t371 + t385
    t389 = -1.0 * t386
    t390 = -1.0 * (t385 + (t371 - t386))
    t391 = t362 + t389
    t392 = t364 + t390
    t393 = t391 - t362
    t394 = t392 - t364
    t403 = ((t389 - t393) + (t362 - (t391 - t393))) + t392
    t404 = t391 + t403
    t407 = ((t390 - t394) + (t364 - (t392 - t394))) + (t403 + (t391 - t404))
    t408 = t404 + t407
    t410 = t407 + (t404 - t408)
    t411 = t268 / t408
    t412 = SPLIT * t411
    t414 = SPLIT * t408
    t415 = t412 - (t412 - t411)
    t416 = t411 - t415
    t418 = t411 * t408
    t419 = t414 - (t414 - t408)
    t420 = t408 - t419
    t434 = ((((t268 - t418) - (((((t415 * t419) - t418) + (t415 * t420)) + (t416 * t419)) + (t416 * t420))) + (t267 + (t264 - t268))) - (t411 * t410)) / t408
    t435 = t411 + t434
    t438 = t338 / t408
    t439 = SPLIT * t438
    t441 = SPLIT * t408
    t442 = t439 - (t439 - t438)
    t443 = t438 - t442
    t445 = t438 * t408
    t446 = t441 - (t441 - t408)
    t447 = t408 - t446
    t461 = ((((t338 - t445) - (((((t442 * t446) - t445) + (t442 * t447)) + (t443 * t446)) + (t443 * t447))) + (t337 + (t334 - t338))) - (t438 * t410)) / t408
    t462 = t438 + t461
    return (t435 + ((t411 - t435) + t434)), (t462 + ((t438 - t462) + t461))
