"""Closed-form numpy baselines written for the benchmark (independent of polygons' dyads).

The textbook loop-closure solutions in *angle* form, vectorised over the crank angle θ:

* four-bar: Freudenstein's half-angle solution for the rocker and coupler angles (Norton,
  *Design of Machinery*, eqs. 4.10 and 4.13), ω from the differentiated loop (6.18), α from
  the second derivative (7.12);
* slider-crank with the guide at any angle and offset: the rod angle from
  ``sin φ = −(y_A)/L`` in the guide's frame, then ω, α, ṡ, s̈ from the differentiated loop;
* slotted lever (crank + lever through a fixed pivot, Coriolis): lever angle ``atan2`` of
  the pin, ω, α, ṡ, s̈ from the differentiated loop ``B + s e^{iφ} = O + r e^{iθ}``.

Every function takes the mechanism's parameters (read once from the scene by
:func:`params`) and an array of crank angles, works in any float dtype (``np.longdouble``
gives the benchmark's high-precision reference), and returns the same named outputs as
:func:`outputs_of_sweep` reads from a polygons sweep.
"""
from __future__ import annotations

import math

import numpy as np

from polygons.position import assemble
from polygons.plan import make_plan


def params(kind: str, scene) -> dict:
    """Everything a closed form needs, read once from the scene (SI)."""
    drv = scene.driver
    P = assemble(make_plan(scene)).points
    p = {"kind": kind, "omega": drv.omega, "alpha": drv.alpha, "theta0": drv.angle,
         "pivot": scene.ground[drv.pivot], "r": scene.links[drv.link].length,
         "tip": drv.tip}
    if kind == "four-bar":
        (name_c,) = [l for l in scene.labels if l not in scene.ground and l != drv.tip]
        links = {frozenset((l.a, l.b)): l for l in scene.links.values()}
        (D,) = [g for g in scene.ground if g != drv.pivot]
        p.update(C=name_c, D=scene.ground[D], b=links[frozenset((drv.tip, name_c))].length,
                 c=links[frozenset((D, name_c))].length,
                 coupler=links[frozenset((drv.tip, name_c))].name,
                 rocker=links[frozenset((D, name_c))].name)
        # the open / crossed solution: the one that gives the scene's C at its own angle
        best = None
        for sign in (1.0, -1.0):
            out = four_bar(dict(p, sign=sign), np.array([drv.angle]))
            d = math.hypot(out[f"{name_c}.x"][0] - P[name_c][0], out[f"{name_c}.y"][0] - P[name_c][1])
            if best is None or d < best[0]:
                best = (d, sign)
        p["sign"] = best[1]
    elif kind == "slider-crank":
        (B,) = [s for s in scene.sliders]
        g = scene.sliders[B]
        link = [l for l in scene.links.values() if B in (l.a, l.b)][0]
        p.update(B=B, L=link.length, through=g.through, psi=g.angle, rod=link.name)
        ex, ey = g.direction
        A = P[drv.tip]
        p["sign"] = 1.0 if (P[B][0] - A[0]) * ex + (P[B][1] - A[1]) * ey > 0 else -1.0
    elif kind == "slotted-lever":
        (pin,) = list(scene.slots)
        slot = scene.slots[pin]
        p.update(pin=pin, B=scene.ground[slot.pivot], lever=slot.lever, A1=slot.coincident)
    else:
        raise ValueError(kind)
    return p


def four_bar(p: dict, theta) -> dict:
    th = np.asarray(theta)
    dt = th.dtype if th.dtype.kind == "f" else np.float64
    one = dt.type(1)
    ax_, ay_ = (dt.type(v) for v in p["pivot"])
    dx_, dy_ = (dt.type(v) for v in p["D"])
    a, b, c = dt.type(p["r"]), dt.type(p["b"]), dt.type(p["c"])
    w2, al2 = dt.type(p["omega"]), dt.type(p["alpha"])
    gx, gy = dx_ - ax_, dy_ - ay_
    d = np.hypot(gx, gy)
    th1 = np.arctan2(gy, gx)
    t2 = th - th1
    K1, K2, K3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    K4, K5 = d / b, (c * c - d * d - a * a - b * b) / (2 * a * b)
    c2, s2 = np.cos(t2), np.sin(t2)
    A = c2 - K1 - K2 * c2 + K3
    B = -2 * s2
    C = K1 - (K2 + one) * c2 + K3
    D = c2 - K1 + K4 * c2 + K5
    E = -2 * s2
    F = K1 + (K4 - one) * c2 + K5
    sg = dt.type(p.get("sign", -1.0))
    t4 = 2 * np.arctan2(-B + sg * np.sqrt(B * B - 4 * A * C), 2 * A)
    t3 = 2 * np.arctan2(-E + sg * np.sqrt(E * E - 4 * D * F), 2 * D)
    w3 = a * w2 * np.sin(t4 - t2) / (b * np.sin(t3 - t4))
    w4 = a * w2 * np.sin(t2 - t3) / (c * np.sin(t4 - t3))
    s3, c3, s4, c4 = np.sin(t3), np.cos(t3), np.sin(t4), np.cos(t4)
    AA, BB = c * s4, b * s3
    CC = a * al2 * s2 + a * w2 * w2 * c2 + b * w3 * w3 * c3 - c * w4 * w4 * c4
    DD, EE = c * c4, b * c3
    FF = a * al2 * c2 - a * w2 * w2 * s2 - b * w3 * w3 * s3 + c * w4 * w4 * s4
    den = AA * EE - BB * DD
    al3 = (CC * DD - AA * FF) / den
    al4 = (CC * EE - BB * FF) / den
    # back to the global frame
    T2, T4 = t2 + th1, t4 + th1
    e2x, e2y = np.cos(T2), np.sin(T2)
    e4x, e4y = np.cos(T4), np.sin(T4)
    tip, name_c = p["tip"], p["C"]
    w22 = w2 * w2
    w42 = w4 * w4
    return {
        f"{tip}.x": ax_ + a * e2x, f"{tip}.y": ay_ + a * e2y,
        f"{tip}.vx": -a * w2 * e2y, f"{tip}.vy": a * w2 * e2x,
        f"{tip}.ax": a * (-al2 * e2y - w22 * e2x), f"{tip}.ay": a * (al2 * e2x - w22 * e2y),
        f"{name_c}.x": dx_ + c * e4x, f"{name_c}.y": dy_ + c * e4y,
        f"{name_c}.vx": -c * w4 * e4y, f"{name_c}.vy": c * w4 * e4x,
        f"{name_c}.ax": c * (-al4 * e4y - w42 * e4x), f"{name_c}.ay": c * (al4 * e4x - w42 * e4y),
        f"{p['coupler']}.omega": w3, f"{p['rocker']}.omega": w4,
        f"{p['coupler']}.alpha": al3, f"{p['rocker']}.alpha": al4,
    }


def slider_crank(p: dict, theta) -> dict:
    th = np.asarray(theta)
    dt = th.dtype if th.dtype.kind == "f" else np.float64
    r, L = dt.type(p["r"]), dt.type(p["L"])
    w, al = dt.type(p["omega"]), dt.type(p["alpha"])
    psi = dt.type(p["psi"])
    ex, ey = np.cos(psi), np.sin(psi)
    gx, gy = (dt.type(v) for v in p["through"])
    ox, oy = (dt.type(v) for v in p["pivot"])
    # the crank pivot in the guide's frame (u along the guide, n across it)
    ou = (ox - gx) * ex + (oy - gy) * ey
    on = -(ox - gx) * ey + (oy - gy) * ex
    t = th - psi
    ct, st = np.cos(t), np.sin(t)
    an = on + r * st                       # the crank pin across the guide
    sphi = -an / L
    cphi = dt.type(p["sign"]) * np.sqrt(1 - sphi * sphi)
    s = ou + r * ct + L * cphi
    w3 = -r * w * ct / (L * cphi)
    sd = -r * w * st - L * w3 * sphi
    al3 = (r * w * w * st - r * al * ct + L * w3 * w3 * sphi) / (L * cphi)
    sdd = -r * w * w * ct - r * al * st - L * al3 * sphi - L * w3 * w3 * cphi
    th_ = th
    e2x, e2y = np.cos(th_), np.sin(th_)
    tip, B = p["tip"], p["B"]
    return {
        f"{tip}.x": ox + r * e2x, f"{tip}.y": oy + r * e2y,
        f"{tip}.vx": -r * w * e2y, f"{tip}.vy": r * w * e2x,
        f"{tip}.ax": r * (-al * e2y - w * w * e2x), f"{tip}.ay": r * (al * e2x - w * w * e2y),
        f"{B}.x": gx + s * ex, f"{B}.y": gy + s * ey,
        f"{B}.vx": sd * ex, f"{B}.vy": sd * ey, f"{B}.ax": sdd * ex, f"{B}.ay": sdd * ey,
        f"{p['rod']}.omega": w3, f"{p['rod']}.alpha": al3,
        f"{B}.v_s": sd, f"{B}.a_s": sdd,
    }


def slotted_lever(p: dict, theta) -> dict:
    th = np.asarray(theta)
    dt = th.dtype if th.dtype.kind == "f" else np.float64
    r = dt.type(p["r"])
    w, al = dt.type(p["omega"]), dt.type(p["alpha"])
    ox, oy = (dt.type(v) for v in p["pivot"])
    bx, by = (dt.type(v) for v in p["B"])
    c2, s2 = np.cos(th), np.sin(th)
    Ax, Ay = ox + r * c2, oy + r * s2
    phi = np.arctan2(Ay - by, Ax - bx)
    s = np.hypot(Ax - bx, Ay - by)
    d = th - phi
    cd, sd_ = np.cos(d), np.sin(d)
    w4 = r * w * cd / s
    sdot = -r * w * sd_
    al4 = (r * al * cd - r * w * w * sd_ - 2 * w4 * sdot) / s
    sddot = -r * al * sd_ - r * w * w * cd + w4 * w4 * s
    ex, ey = np.cos(phi), np.sin(phi)
    tip, A1, lev = p["tip"], p["A1"], p["lever"]
    return {
        f"{tip}.x": Ax, f"{tip}.y": Ay,
        f"{tip}.vx": -r * w * s2, f"{tip}.vy": r * w * c2,
        f"{tip}.ax": r * (-al * s2 - w * w * c2), f"{tip}.ay": r * (al * c2 - w * w * s2),
        f"{A1}.vx": -w4 * s * ey, f"{A1}.vy": w4 * s * ex,
        f"{A1}.ax": s * (-al4 * ey - w4 * w4 * ex), f"{A1}.ay": s * (al4 * ex - w4 * w4 * ey),
        f"{lev}.omega": w4, f"{lev}.alpha": al4,
        f"{tip}.v_s": sdot, f"{tip}.a_s": sddot,
    }


def four_bar_lean(p: dict, theta) -> dict:
    """The four-bar in *Cartesian* form, as lean as numpy allows (the baseline a user would
    write by hand for speed): B on the crank circle, C where the circles about B (BC) and D
    (CD) cross, ω and α of BC and DC from the velocity and acceleration loops dotted with the
    other link (``ω₃ = −(v_B·r₄)/(r₃×r₄)``, ``ω₄ = −(v_B·r₃)/(r₃×r₄)``, the same with
    ``q = a_B − ω₃² r₃ + ω₄² r₄`` for α).  The closure ``p["lean_sigma"]`` (the side of B→D
    that C is on) is taken from :func:`four_bar` at the scene's angle by :func:`lean`."""
    th = np.asarray(theta)
    ax, ay = p["pivot"]
    dx, dy = p["D"]
    a, b, c, w2, al2, sg = p["r"], p["b"], p["c"], p["omega"], p["alpha"], p["lean_sigma"]
    ex, ey = np.cos(th), np.sin(th)
    bx, by = ax + a * ex, ay + a * ey
    ux, uy = dx - bx, dy - by
    d2 = ux * ux + uy * uy
    d = np.sqrt(d2)
    m = (b * b - c * c + d2) / (2.0 * d)
    h = sg * np.sqrt(b * b - m * m) / d
    m /= d
    cx, cy = bx + m * ux - h * uy, by + m * uy + h * ux
    r3x, r3y, r4x, r4y = cx - bx, cy - by, cx - dx, cy - dy
    vbx, vby = -w2 * a * ey, w2 * a * ex
    k = 1.0 / (r3x * r4y - r3y * r4x)
    w3 = -(vbx * r4x + vby * r4y) * k
    w4 = -(vbx * r3x + vby * r3y) * k
    abx = -al2 * a * ey - w2 * w2 * a * ex
    aby = al2 * a * ex - w2 * w2 * a * ey
    qx = abx - w3 * w3 * r3x + w4 * w4 * r4x
    qy = aby - w3 * w3 * r3y + w4 * w4 * r4y
    al3 = -(qx * r4x + qy * r4y) * k
    al4 = -(qx * r3x + qy * r3y) * k
    tip, name_c = p["tip"], p["C"]
    return {
        f"{tip}.x": bx, f"{tip}.y": by, f"{tip}.vx": vbx, f"{tip}.vy": vby,
        f"{tip}.ax": abx, f"{tip}.ay": aby,
        f"{name_c}.x": cx, f"{name_c}.y": cy, f"{name_c}.vx": -w4 * r4y,
        f"{name_c}.vy": w4 * r4x, f"{name_c}.ax": -al4 * r4y - w4 * w4 * r4x,
        f"{name_c}.ay": al4 * r4x - w4 * w4 * r4y,
        f"{p['coupler']}.omega": w3, f"{p['rocker']}.omega": w4,
        f"{p['coupler']}.alpha": al3, f"{p['rocker']}.alpha": al4,
    }


def lean(p: dict) -> dict:
    """``p`` with the closure :func:`four_bar_lean` needs: the side of B→D that C lies on at
    the scene's crank angle, by :func:`four_bar` (the half-angle form)."""
    t = np.array([p["theta0"]])
    ref = four_bar(p, t)
    ax, ay = p["pivot"]
    dx, dy = p["D"]
    bx, by = ax + p["r"] * math.cos(t[0]), ay + p["r"] * math.sin(t[0])
    cx, cy = float(ref[f"{p['C']}.x"][0]), float(ref[f"{p['C']}.y"][0])
    side = (dx - bx) * (cy - by) - (dy - by) * (cx - bx)
    return dict(p, lean_sigma=1.0 if side > 0 else -1.0)


SOLVERS = {"four-bar": four_bar, "slider-crank": slider_crank, "slotted-lever": slotted_lever}


def solve(p: dict, theta) -> dict:
    return SOLVERS[p["kind"]](p, theta)


def outputs_of_sweep(sw, keys) -> dict:
    """The same named outputs read off a polygons :class:`~polygons.sweep.Sweep`."""
    out = {}
    for key in keys:
        lab, q = key.split(".")
        if q in ("x", "y"):
            v = sw.pos[lab]
            out[key] = v[0 if q == "x" else 1]
        elif q in ("vx", "vy"):
            out[key] = sw.vel[lab][0 if q == "vx" else 1]
        elif q in ("ax", "ay"):
            out[key] = sw.acc[lab][0 if q == "ax" else 1]
        elif q == "omega":
            out[key] = sw.omega[lab]
        elif q == "alpha":
            out[key] = sw.alpha[lab]
        elif q == "v_s":
            out[key] = sw.slide_v[lab]
        elif q == "a_s":
            out[key] = sw.slide_a[lab]
    return out
