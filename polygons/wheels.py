"""A wheel rolling without slipping, read off the solved linkage (split from
:mod:`polygons.contacts`, which states the contact and rewrites it): the no-slip conditions on a
fixed or moving surface or between two plates (:func:`rolling`), the wheel's named points
(:func:`wheel_point`), its instant centres (:func:`wheel_centres`) and its lines in words."""
from __future__ import annotations

import math


def wheel_point(sol, q, label: str):
    """A wheel's named point P (``q.rim``): (position, velocity, acceleration) in SI; the
    wheel is a rigid body turning at ω, α about its centre W —

        v_P = v_W + ω k × WP,      a_P = a_W + α k × WP − ω² WP.

    The centre itself (``q.at``, between two plates not a point of the polygons) is given too.
    None when ``label`` is not one of this wheel's points or the motion is not solved."""
    h = rolling(sol, q)
    if h is None:
        return None
    W = h["centre"]
    if label == q.at:
        d = (0.0, 0.0)
    else:
        spec = next((r for r in q.rim if r[0] == label), None)
        if spec is None:
            return None
        d = (spec[2] * math.cos(spec[1]), spec[2] * math.sin(spec[1]))
    w, vW = h["omega"], h["centre_velocity"]
    pos = (W[0] + d[0], W[1] + d[1])
    vel = (vW[0] - w * d[1], vW[1] + w * d[0])
    acc = None
    if "alpha" in h:
        al, aW = h["alpha"], h["centre_acceleration"]
        acc = (aW[0] - al * d[1] - w * w * d[0], aW[1] + al * d[0] - w * w * d[1])
    return pos, vel, acc


def _along(sol, name, e, which, q=None):
    """The velocity or acceleration of the block ``name`` along ``e`` (0 for the frame; the
    stated motion of a plate moved at a given rate, ``q.opposite_motion``)."""
    if name is None:
        return 0.0
    if q is not None and q.opposite_motion is not None and name == q.opposite:
        return q.opposite_motion[0 if which == "velocity" else 1]
    v = getattr(sol.points[name], which)
    return v[0] * e[0] + v[1] * e[1]


def rolling(sol, q) -> dict | None:
    """A wheel rolling without slipping on a fixed or moving surface (and, with
    ``q.opposite``, under a second plate), from the no-slip condition at each contact:

    the wheel's point at the contact C₁ = W − r·n moves with the surface, v_W + ω r e = v₁ e,
    so ω = (v₁ − v_W)/r along e; with a second plate at C₂ = W + r·n, v_W − ω r e = v₂ e
    gives v_W = (v₁ + v₂)/2, ω = (v₁ − v₂)/2r; the same for α with the accelerations (the
    contact points' ω²r towards W cancel in a_W).  The instant centre is W + (v_W/ω)·n."""
    e = (math.cos(q.face), math.sin(q.face))
    n = (-e[1], e[0])
    r = q.radius
    blocks = [name for name in (q.on, q.opposite) if name is not None
              and not (q.opposite_motion is not None and name == q.opposite)]
    if any(name not in sol.points or sol.points[name].velocity is None for name in blocks):
        return None             # a plate the plan left out (solve --points) or not solved
        return None
    v1 = _along(sol, q.on, e, "velocity")
    if q.opposite is None:
        p = sol.points.get(q.at)
        if p is None or p.velocity is None:
            return None
        W = p.position
        vw = p.velocity[0] * e[0] + p.velocity[1] * e[1]
        w = (v1 - vw) / r
    else:
        W = (q.surface[0] + r * n[0], q.surface[1] + r * n[1])
        v2 = _along(sol, q.opposite, e, "velocity", q)
        vw, w = (v1 + v2) / 2, (v1 - v2) / (2 * r)
    C1 = (W[0] - r * n[0], W[1] - r * n[1])
    out = {"centre": W, "centre_velocity": (vw * e[0], vw * e[1]), "omega": w,
           "contacts": [C1], "surface_velocity": [v1]}
    if q.opposite is not None:
        out["contacts"].append((W[0] + r * n[0], W[1] + r * n[1]))
        out["surface_velocity"].append(v2)
    if q.on is None and q.opposite is None:
        out["instant_centre"] = C1            # the contact with the fixed surface
    elif w != 0.0:
        out["instant_centre"] = (W[0] + vw / w * n[0], W[1] + vw / w * n[1])
    accel = all(sol.points[name].acceleration is not None for name in blocks)
    if q.opposite is None:
        accel = accel and sol.points[q.at].acceleration is not None
    if not accel:
        return out
    a1 = _along(sol, q.on, e, "acceleration")
    if q.opposite is None:
        aw = sol.points[q.at].acceleration[0] * e[0] + sol.points[q.at].acceleration[1] * e[1]
        al = (a1 - aw) / r
    else:
        a2 = _along(sol, q.opposite, e, "acceleration", q)
        aw, al = (a1 + a2) / 2, (a1 - a2) / (2 * r)
    c = r * w * w
    out.update({"alpha": al, "centre_acceleration": (aw * e[0], aw * e[1]),
                "surface_acceleration": [a1] + ([a2] if q.opposite is not None else []),
                # the wheel's point at each contact: the surface's a plus ω²r towards W
                "contact_acceleration": (a1 * e[0] + c * n[0], a1 * e[1] + c * n[1])})
    if q.opposite is not None:
        out["opposite_contact_acceleration"] = (a2 * e[0] - c * n[0], a2 * e[1] - c * n[1])
    return out


def _rim_lines(sol, q, mm) -> list[str]:
    """The wheel's named points: v_P = v_W + ω k × WP, a_P = a_W + α k × WP − ω² WP."""
    out = []
    for label, angle, dist in q.rim:
        got = wheel_point(sol, q, label)
        if got is None:
            continue
        pos, vel, acc = got
        snap = lambda v, ref: tuple(0.0 if abs(c) <= 1e-12 * ref else c for c in v)  # noqa: E731
        pos = snap(pos, max(map(abs, pos)) or 1.0)
        vel = snap(vel, math.hypot(*vel))
        acc = snap(acc, math.hypot(*acc)) if acc is not None else None
        where = ("on the rim" if dist == q.radius else f"{dist * 1000:.6g} mm from {q.at}")
        text = (f"    {label} ({where} at {math.degrees(angle):.6g}°, {mm(pos)}): |v| = "
                f"{math.hypot(*vel):.6g} m/s at {math.degrees(math.atan2(vel[1], vel[0])) % 360:.6g}°")
        if acc is not None:
            text += (f", |a| = {math.hypot(*acc):.6g} m/s² at "
                     f"{math.degrees(math.atan2(acc[1], acc[0])) % 360:.6g}°")
        out.append(text + f"  (v = v_{q.at} + ω × {q.at}{label})")
    return out


def _moving_lines(q, h, mm, sense) -> list[str]:
    """A wheel on a moving surface (or between two plates) in words, signed along the
    surface's direction."""
    W, r = q.at, q.radius
    v = h["surface_velocity"]
    names = [q.on or "the frame"] + ([q.opposite] if q.opposite else [])
    out = [f"    along the surface (+ at {math.degrees(q.face):.6g}°): v₁ = {v[0]:.6g} m/s "
           f"({names[0]})" + (f", v₂ = {v[1]:.6g} m/s ({names[1]})" if q.opposite else "")]
    vw = h["centre_velocity"][0] * math.cos(q.face) + h["centre_velocity"][1] * math.sin(q.face)
    if q.opposite:
        out.append(f"    v_{W} = (v₁ + v₂)/2 = {vw:.6g} m/s at {mm(h['centre'])}; ω = (v₁ − v₂)/2r "
                   f"= {abs(h['omega']):.6g} rad/s {sense(h['omega'])}")
    else:
        out.append(f"    v_{W} = {vw:.6g} m/s; ω = (v₁ − v_{W})/r = {abs(h['omega']):.6g} rad/s "
                   f"{sense(h['omega'])}")
    if "alpha" in h:
        a = h["surface_acceleration"]
        aw = (h["centre_acceleration"][0] * math.cos(q.face)
              + h["centre_acceleration"][1] * math.sin(q.face))
        what = "(a₁ + a₂)/2" if q.opposite else "from the linkage"
        out.append(f"    a₁ = {a[0]:.6g} m/s²" + (f", a₂ = {a[1]:.6g} m/s²" if q.opposite else "")
                   + f"; a_{W} = {what} = {aw:.6g} m/s²; α = {abs(h['alpha']):.6g} rad/s² "
                     f"{sense(h['alpha'])}; each contact point of the wheel accelerates as its "
                     f"plate plus r·ω² = {r * h['omega'] ** 2:.6g} m/s² towards {W}")
    if "instant_centre" in h:
        d = math.dist(h["instant_centre"], h["centre"])
        out.append(f"    instant centre of the wheel: {mm(h['instant_centre'])}, on the line of "
                   f"the contact points {d * 1000:.6g} mm from {W} (v_{W}/ω)")
    else:
        out.append("    the wheel translates (ω = 0): no instant centre at a finite distance")
    return out


def wheel_centres(sol, cs) -> list[dict]:
    """The instant centres of each rolling wheel, numbered after the linkage's links in
    ``cs`` (:func:`polygons.centres.instant_centres`): the wheel is not a link of the
    equivalent linkage, so its centres come from the no-slip conditions — relative to each
    surface its centre is the contact point; relative to the frame it lies on the line of the
    contact points (Kennedy: with the contact and the plate's centre at infinity ⟂ its guide)
    at v_W/ω from W."""
    out = []
    n = len(cs.bodies)
    blocks = {b.labels[0]: b.number for b in cs.bodies if b.kind == "block"}
    for q in getattr(sol.scene, "equivalents", ()):
        if q.kind != "rolling" or q.driven:     # a driven wheel is a body of the linkage
            continue
        h = rolling(sol, q)
        if h is None:
            continue
        n += 1
        wheel = n
        rel = [(blocks.get(q.on, 1) if q.on else 1, q.on or "frame", h["contacts"][0])]
        if q.opposite and q.opposite_motion is not None:
            n += 1                  # a plate moved at a stated rate: a body of its own
            rel.append((n, q.opposite, h["contacts"][1]))
        elif q.opposite:
            rel.append((blocks.get(q.opposite, 1), q.opposite, h["contacts"][1]))
        out.append({"wheel": q.at, "number": wheel, "absolute": h.get("instant_centre"),
                    "omega": h["omega"], "speed": math.hypot(*h["centre_velocity"]),
                    "centre": h["centre"],
                    "relative": [{"number": i, "body": name, "point": p} for i, name, p in rel]})
    return out


__all__ = ["rolling", "wheel_point", "wheel_centres"]
