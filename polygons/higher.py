"""A higher pair's own numbers, read off its solved equivalent linkage (split from
:mod:`polygons.contacts`, which states the contact and rewrites it): each named for what it is
in :data:`OUTPUTS` — a sliding velocity is always the relative velocity of the two bodies'
material points at the contact; the speed of the contact point over each body is a field of
its own.  docs/contact-outputs.md is generated from :data:`OUTPUTS`."""
from __future__ import annotations

import math
import re

from .errors import SceneError
from .reader import LABEL
from .units import parse_quantity
from .wheels import rolling

#: Every output of a higher pair (``higher_pair`` in ``solve --json``, :func:`higher`), by the
#: kind of contact: (field, meaning).  SI units; vectors [x, y]; rates CCW positive.  Generated
#: into docs/contact-outputs.md (``python -m polygons.reference``); tests/test_contact_outputs.py
#: holds :func:`higher` to it (no field unnamed here); tests/domain.py checks each by finite
#: differences of positions on random mechanisms.
OUTPUTS: dict[str, tuple[tuple[str, str], ...]] = {
    "bearing": (
        ("contact", "the contact point T, m: the foot of the perpendicular from the circle's "
                    "centre K to the bar (a geometric point: it moves over both bodies)"),
        ("omega", "the bar's angular velocity, rad/s"),
        ("alpha", "the bar's angular acceleration, rad/s²"),
        ("bar_direction", "the unit vector u along the bar, from its first label to its "
                          "second: the sign of the three rates below"),
        ("sliding_velocity", "the sliding velocity at the contact: the velocity of the bar's "
                             "material point at T relative to the (fixed) cylinder's, along u, "
                             "m/s. It is v_A·u for any point A of the bar (the bar's points "
                             "all share their component along it)"),
        ("bar_point_velocity", "the velocity of the bar's material point at T, m/s "
                               "(sliding_velocity·u: no component along the normal, the bar "
                               "does not cut into the cylinder)"),
        ("bar_point_acceleration", "the acceleration of the bar's material point at T, m/s² "
                                   "(a_A + α k × AT − ω² AT)"),
        ("contact_velocity_along_bar", "the rate at which the contact point T moves along the "
                                       "bar, relative to the bar, along u, m/s (the equivalent "
                                       "slot's sliding velocity of K: d(AT)/dt)"),
        ("contact_velocity_along_circle", "the rate at which T moves over the cylinder (its "
                                          "velocity in the frame, the cylinder being fixed), "
                                          "along u, m/s: ±R·ω. Always contact_velocity_along_"
                                          "circle = sliding_velocity + contact_velocity_along_"
                                          "bar"),
        ("instant_centre", "the bar's instant centre, m: where the normal to the path of its "
                           "first label meets the normal at the contact (absent when ω = 0)"),
    ),
    "curved slot": (
        ("slot_body", "the body carrying the slot: 'frame' or a link's name (the body of the "
                      "centre of curvature K other than the equivalent link)"),
        ("tangent", "the unit tangent to the slot at the pin P, k × KP/|KP| (CCW about K): "
                    "the sign of sliding_velocity"),
        ("sliding_velocity", "the sliding velocity of the pin in the slot: v_P − v_(slot's "
                             "point at P) along the tangent, m/s"),
        ("relative_omega", "the equivalent link KP's angular velocity relative to the slot's "
                           "body, rad/s: sliding_velocity / radius"),
    ),
    "cam": (
        ("contact", "the contact point on the profile, m: C + radius·CR/|CR| (C the centre of "
                    "curvature, R the roller's centre)"),
        ("cam_body", "the body carrying the profile: 'frame' or a link's name"),
        ("tangent", "the unit tangent to the profile at the contact, k × CR/|CR|: the sign of "
                    "the next two"),
        ("follower_velocity_relative", "the velocity of the roller's centre R relative to the "
                                       "cam (v_R − v_(cam's point at R)), along the tangent, "
                                       "m/s"),
        ("contact_velocity_along_profile", "the rate at which the contact point moves over "
                                           "the profile, relative to the cam, along the "
                                           "tangent, m/s (radius/|CR| of the last)"),
    ),
    "rolling": (
        ("centre", "the wheel's centre W, m"),
        ("centre_velocity", "v_W, m/s"),
        ("omega", "the wheel's angular velocity, rad/s (no slip at each contact)"),
        ("contacts", "the contact points, m: with the first surface, then with the second "
                     "plate"),
        ("surface_velocity", "each surface's velocity along `direction`, m/s"),
        ("instant_centre", "the wheel's instant centre (the contact with a fixed surface), m; "
                           "absent when the wheel translates"),
        ("alpha", "the wheel's angular acceleration, rad/s²"),
        ("centre_acceleration", "a_W, m/s²"),
        ("surface_acceleration", "each surface's acceleration along `direction`, m/s²"),
        ("contact_acceleration", "the acceleration of the wheel's material point at the first "
                                 "contact, m/s² (the surface's plus r·ω² towards W)"),
        ("opposite_contact_acceleration", "the same at the second plate's contact, m/s²"),
    ),
}
OUTPUTS["flat-faced cam"] = ()      # the follower's own point, slide and (arm) ω, α only


def _carrier(sol, label: str, exclude: str | None):
    """The body carrying the profile or slot whose centre of curvature is ``label`` (other
    than the equivalent link ``exclude``), with its (ω, α): ('frame', 0, 0) for a [ground]
    point; None when no solved body carries it."""
    if label in sol.scene.ground:
        return "frame", 0.0, 0.0
    model = sol.scene.model
    for name in model.carried_by(label, exclude=(exclude,) if exclude else ()):
        if name == "frame":
            return "frame", 0.0, 0.0
        link = sol.links.get(name)
        if link is not None and link.omega is not None:
            return name, link.omega, link.alpha
        if model.body(name).kind == "block":        # translates on its fixed guide
            return name, 0.0, 0.0
    return None


def _unit(a, b):
    d = math.dist(a, b)
    return ((b[0] - a[0]) / d, (b[1] - a[1]) / d)


def higher(sol, q: Equivalent) -> dict | None:
    """The higher pair's own numbers read off the solved equivalent linkage, each named for
    what it is (:data:`OUTPUTS`): a rolling wheel's ω, α, instant centre and contacts
    (:func:`rolling`); a bar on a fixed circle (:func:`bearing`); a pin in a curved slot and a
    roller on a cam arc (:func:`on_arc`).  None where the motion is not solved."""
    if q.kind == "rolling":
        return rolling(sol, q)
    if q.kind == "bearing":
        return bearing(sol, q)
    if q.kind in ("curved slot", "cam"):
        return on_arc(sol, q)
    return None


def bearing(sol, q: Equivalent) -> dict | None:
    """A bar AQ bearing on a fixed circle (centre K, radius R): the contact T is the foot of
    the perpendicular from K, T = A + t u with t = AK·u, u along the bar.

        sliding velocity   v_s = v_A·u           (the bar's point at T over the fixed cylinder:
                                                  v_T,bar = v_A + ω k × AT, normal part 0)
        T along the bar    ṫ  = −v_A·u + ω AK·n  (n = k × u; relative to the bar)
        T over the circle  v_s + ṫ = ω AK·n = ±R ω

    (the contact point's speed along the bar, R·csc²θ·ω in a book's angle, is not the
    sliding velocity: they differ by the speed of the contact over the cylinder)."""
    pts = sol.points
    link = sol.links.get(q.link)
    if link is None or link.omega is None:
        return None
    A, B, K = pts[link.a].position, pts[link.b].position, pts[q.at].position
    u = _unit(A, B)
    n = (-u[1], u[0])
    AK = (K[0] - A[0], K[1] - A[1])
    t = AK[0] * u[0] + AK[1] * u[1]
    T = (A[0] + t * u[0], A[1] + t * u[1])
    w = link.omega
    vA = pts[link.a].velocity
    out = {"contact": T, "omega": w, "alpha": link.alpha, "bar_direction": u}
    slide = vA[0] * u[0] + vA[1] * u[1]
    along_circle = w * (AK[0] * n[0] + AK[1] * n[1])
    out["sliding_velocity"] = slide
    out["bar_point_velocity"] = (vA[0] - w * t * u[1], vA[1] + w * t * u[0])
    aA = pts[link.a].acceleration
    if aA is not None and link.alpha is not None:
        al = link.alpha
        out["bar_point_acceleration"] = (aA[0] - al * t * u[1] - w * w * t * u[0],
                                         aA[1] + al * t * u[0] - w * w * t * u[1])
    out["contact_velocity_along_bar"] = along_circle - slide
    out["contact_velocity_along_circle"] = along_circle
    if w != 0.0:
        out["instant_centre"] = (A[0] - vA[1] / w, A[1] + vA[0] / w)
    return out


def on_arc(sol, q: Equivalent) -> dict | None:
    """A pin P in a circular slot, or a roller's centre R on a cam arc, about the centre of
    curvature C carried by a body turning at ω_b: relative to that body P moves on the circle
    about C, so its relative velocity is along the tangent t = k × CP/|CP|,

        v_rel = (v_P − v_C − ω_b k × CP)·t = |CP|·(ω_CP − ω_b);

    for the pin that is the sliding velocity in the slot; for the roller it is its centre's
    (the roller turns on its pin: its sliding at the contact is not fixed by the linkage), and
    the contact point runs over the profile at v_rel·radius/|CP|."""
    pts = sol.points
    P, C = pts.get(q.at), pts.get(q.centre)
    link = sol.links.get(q.link)
    body = _carrier(sol, q.centre, q.link)
    if P is None or C is None or link is None or link.omega is None or body is None:
        return None
    r = math.dist(C.position, P.position)
    e = _unit(C.position, P.position)
    tangent = (-e[1], e[0])
    rel = r * (link.omega - body[1])
    if q.kind == "curved slot":
        return {"slot_body": body[0], "tangent": tangent, "sliding_velocity": rel,
                "relative_omega": rel / r}
    contact = (C.position[0] + q.radius * e[0], C.position[1] + q.radius * e[1])
    return {"contact": contact, "cam_body": body[0], "tangent": tangent,
            "follower_velocity_relative": rel,
            "contact_velocity_along_profile": rel * q.radius / r}


def _bearing_lines(q, h, mm) -> list[str]:
    """A bar on a fixed circle in words: the sliding velocity (the bar's point at the contact
    over the cylinder) and, named apart, the contact point's own speeds along each body."""
    out = [f"    contact with the bar at {mm(h['contact'])}: the bar slides over the cylinder "
           f"at {abs(h['sliding_velocity']):.6g} m/s (sliding velocity: its point at the "
           f"contact, v_{q.link[0]}·u along the bar)",
           f"    the contact point moves along the bar at "
           f"{abs(h['contact_velocity_along_bar']):.6g} m/s (relative to the bar) and round the "
           f"cylinder at {abs(h['contact_velocity_along_circle']):.6g} m/s (R·ω)"]
    if "instant_centre" in h:
        out.append(f"    instant centre of {q.link}: {mm(h['instant_centre'])} "
                   f"(on the normal to the bar at the contact, through {q.at})")
    return out


def _q(value, dim, file, where) -> float:
    return parse_quantity(value, dim, file=file, where=where)


LINK_NAME = re.compile(r"^[A-Z][a-z0-9_']*[A-Z][a-z0-9_']*$")


def _bar_to_contact(bar, label, radius, side, data, file, where) -> float:
    """A bearing bar stated without a length: its far end is its point touching the circle at
    this instant, |PT| from its first label P — P a fixed pivot (|PT|² = |PK|² − R²) or the
    slider driver at a stated position (as a fixed pivot) or placed by this bar's angle (T
    the foot of K on the bar's line through the slider: |PT| = (K − P)·u, P where the line at
    the stated angle is tangent to the circle).
    Otherwise the bar's length is asked for (its first label is a moving pin)."""
    ground, drv = data.get("ground", {}), data.get("driver")
    if not (isinstance(ground[label], list) and len(ground[label]) == 2):
        raise SceneError(f"give the circle's centre {label} as [x, y]", file=file,
                         where=f"ground.{label}")
    kx, ky = (_q(v, "length", file, f"ground.{label}") for v in ground[label])
    splits = [(bar[:i], bar[i:]) for i in range(1, len(bar))
              if LABEL.match(bar[:i]) and LABEL.match(bar[i:])]
    for p, q in splits:
        if p in ground and isinstance(ground[p], list):
            px, py = (_q(v, "length", file, f"ground.{p}") for v in ground[p])
            d2 = (kx - px) ** 2 + (ky - py) ** 2 - radius ** 2
            if d2 <= 0:
                raise SceneError(f"the bar's pivot {p} is inside the circle about {label}",
                                 file=file, where=where)
            return math.sqrt(d2)
        sliders = data.get("sliders", {})
        if isinstance(drv, dict) and drv.get("slider") == p and isinstance(
                drv.get("position"), str) and isinstance(sliders, dict) \
                and isinstance(sliders.get(p), dict) and "through" in sliders[p]:
            g = sliders[p]                        # the slider driver at a stated position
            tx, ty = (_q(v, "length", file, f"sliders.{p}.through") for v in g["through"])
            e = _q(g.get("direction", "0 deg"), "angle", file, f"sliders.{p}.direction")
            s = _q(drv["position"], "length", file, "driver.position")
            d2 = (kx - tx - s * math.cos(e)) ** 2 + (ky - ty - s * math.sin(e)) ** 2 \
                - radius ** 2
            if d2 <= 0:
                raise SceneError(f"the slider {p} is inside the circle about {label}",
                                 file=file, where=where)
            return math.sqrt(d2)
        if isinstance(drv, dict) and drv.get("slider") == p and drv.get("rod") in (bar, q + p) \
                and isinstance(drv.get("rod_angle"), str) and isinstance(sliders, dict) \
                and isinstance(sliders.get(p), dict) and "through" in sliders[p]:
            from .topology import _turn_of
            text, turn = _turn_of(drv["rod_angle"])
            phi = turn * _q(text, "angle", file, "driver.rod_angle")
            if drv["rod"] != bar:
                phi += math.pi                    # the angle stated far end → slider
            ux, uy = math.cos(phi), math.sin(phi)
            g = sliders[p]
            tx, ty = (_q(v, "length", file, f"sliders.{p}.through") for v in g["through"])
            e = _q(g.get("direction", "0 deg"), "angle", file, f"sliders.{p}.direction")
            nx, ny = -uy, ux
            den = math.cos(e) * nx + math.sin(e) * ny
            if abs(den) < 1e-12:
                raise SceneError(f"the bar {bar} is parallel to the guide of {p}: its angle "
                                 f"does not place the slider", file, "driver.rod")
            off = radius if side == "left" else -radius
            s = ((kx - tx) * nx + (ky - ty) * ny - off) / den
            bx, by = tx + s * math.cos(e), ty + s * math.sin(e)
            t = (kx - bx) * ux + (ky - by) * uy
            if t <= 0:
                raise SceneError(f"the circle about {label} is behind the bar's end {p}",
                                 file=file, where=where)
            return t
    raise SceneError(f"give the bar's length in [links] ({bar} = \"...\"): unstated, its far "
                     f"end is its point at the contact, found only when its first label is a "
                     f"fixed pivot or the slider driver (at a position or placed by this "
                     f"bar's angle)", file=file,
                     where=f"{where}.bar")



__all__ = ["OUTPUTS", "higher", "bearing", "on_arc"]
