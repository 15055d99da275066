"""Cams stated by their profile, as books state them: base circle, nose radius, lift and the
flank radius (a circular-arc cam) or straight flanks tangent to both circles (a tangent cam),
with a knife-edge, roller or flat-faced follower that translates (its line of stroke through
the cam's centre or offset from it) or oscillates (an arm pivoted at a fixed point).

    [driver]
    crank = "OK"                 # O: the cam's centre; K: the centre of curvature of the
    angle = "30 deg"             #   part in contact (found here); angle: the nose's axis,
    omega = "10 rad/s"           #   O → nose centre, CCW from +x
    sense = "CCW"
    [cam_profiles.R]             # R: the follower's point (the roller's centre, the knife's
    base_radius = "25 mm"        #   edge; a translating flat face: the equivalent yoke's point
    nose_radius = "8 mm"         #   on the stroke at K's level, ρ short of the face; an
                                 #   oscillating follower's arm is QR, Q its pivot)
    lift = "20 mm"               # or faces_angle = "90 deg" (a tangent cam)
    flank_radius = "60 mm"       # or kind = "tangent" (straight flanks)
    follower = "roller"          # "knife", "roller" (with roller = "10 mm") or "flat"
    roller = "10 mm"
    stroke = "90 deg"            # translating: the line of stroke's direction …
    offset = "0 mm"              #   … and its distance from O (+: left of the stroke)
    # pivot = "Q", arm = "80 mm", side = "left"   an oscillating follower instead of stroke

Geometry (the cam's own frame, x along the nose axis): the nose centre Q at d = r₁ + L − r₂; a
circular-arc flank of radius R has its centre P on the far side of the axis, |OP| = R − r₁,
|QP| = R − r₂; a tangent cam's flank is the common tangent x·N = r₁ of the two circles, N at
β = acos((r₁ − r₂)/d) from the axis.  At the cam angle the follower's point is found on each
part's offset curve (the part's radius + the roller's): where the line of stroke (translating)
or the arm's circle about its pivot (oscillating, on the stated side) meets it; the part in
contact is the one whose span of outward normals holds the contact normal (a flat face: the
part whose normal is the face's).  The scene is then rewritten to the equivalent linkage of
that instant:

* a circular part (nose, arc flank, base circle while the follower moves on it — it dwells,
  refused in words) → the crank O → K (K the part's centre) and [cams.R] (the link K R =
  ρ + roller on the guide, or with the arm QR; a flat face: the Scotch yoke, or the slotted
  arm of [cams] arm);
* a straight flank with an oscillating knife or roller → R a pin in a slot of the cam (∥ the
  flank, offset r₁ + roller from O) at the end of the arm QR;
* a straight flank with a translating knife or roller → R a pin in that slot of the cam and a
  block on the fixed line of stroke: the tangent mechanism (:mod:`polygons.dyads.slot_slider`);
  :func:`straight_flank_motion` is its closed form s = (r₁ + r − b·N)/(e·N) and derivatives,
  kept as the tests' oracle.

:func:`contact` is the geometry alone (the tests, the diagram, the drawing); :func:`rewrite`
turns a scene's ``[cam_profiles]`` into ``[links]``, ``[sliders]``, ``[slots]``, ``[cams]``
and the driver's angle before :func:`polygons.contacts.rewrite` reads them.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .cam_events import nose_axis_of
from .errors import SceneError, show
from .units import parse_quantity

from .cam_profile_table import (AXIS_KEY, FOLLOWERS, KEYS, KINDS, SIDES, TABLE,  # noqa: F401
                                TABLES)
_LINK = re.compile(r"^([A-Z][a-z0-9_']*)([A-Z][a-z0-9_']*)$")


def _u(a: float) -> tuple[float, float]:
    return (math.cos(a), math.sin(a))


def _dot(p, q) -> float:
    return p[0] * q[0] + p[1] * q[1]


def _cross(p, q) -> float:
    return p[0] * q[1] - p[1] * q[0]


def _wrap(x: float) -> float:
    return math.atan2(math.sin(x), math.cos(x))


def _rot(p, a):
    c, s = math.cos(a), math.sin(a)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


@dataclass(frozen=True)
class Profile:
    """A cam profile in its own frame (x along the nose axis), SI."""

    base: float          # r₁
    nose: float          # r₂
    lift: float          # L
    flank: float | None  # R (None: a tangent cam)

    @property
    def d(self) -> float:
        """OQ, the nose centre's distance from O."""
        return self.base + self.lift - self.nose

    def flank_centre(self, side: int) -> tuple[float, float]:
        """P, the centre of the flank on the side ``side`` (+1: the +y side of the axis) —
        on the far side: |OP| = R − r₁, |QP| = R − r₂."""
        R, r1, r2, d = self.flank, self.base, self.nose, self.d
        u = (d * d - (R - r2) ** 2 + (R - r1) ** 2) / (2 * d)
        v = math.sqrt(max((R - r1) ** 2 - u * u, 0.0))
        return (u, -side * v)

    def spans(self) -> tuple[float, float]:
        """(φ_n, φ_b): the outward normals of the nose run over |φ| ≤ φ_n from the axis,
        those of the flanks over φ_n < |φ| ≤ φ_b, the base circle's beyond (a tangent cam:
        φ_n = φ_b = β, its flank's normal)."""
        if self.flank is None:     # tangent: the common tangent's normal
            beta = math.acos((self.base - self.nose) / self.d)
            return beta, beta
        P = self.flank_centre(+1)
        phi_n = math.atan2(-P[1], self.d - P[0])      # the direction P → Q
        phi_b = math.atan2(-P[1], -P[0])              # the direction P → O
        return phi_n, phi_b

    def parts(self, axis: float = 0.0) -> tuple["Part", ...]:
        """Every part of the profile with the nose axis at ``axis`` (O at the origin)."""
        phi_n, phi_b = self.spans()
        out = [Part("nose", 0, _rot((self.d, 0.0), axis), self.nose, axis, -phi_n, phi_n)]
        for side in (+1, -1):
            lo, hi = sorted((side * phi_n, side * phi_b))
            if self.flank is not None:
                out.append(Part("flank", side, _rot(self.flank_centre(side), axis), self.flank,
                                axis, lo, hi))
            else:
                out.append(Part("straight flank", side, (0.0, 0.0), math.inf, axis, lo, hi))
        out.append(Part("base circle", 0, (0.0, 0.0), self.base, axis, phi_b, 2 * math.pi
                        - phi_b))
        return tuple(out)

    def outline(self, axis: float = 0.0, n: int = 360) -> list[tuple[float, float]]:
        """The profile's points (about ``n``), counter-clockwise, O at the origin."""
        pts = []
        for k in range(n):
            phi = 2 * math.pi * k / n
            pts.append(self.support_point(axis + phi, axis))
        return pts

    def support_point(self, direction: float, axis: float) -> tuple[float, float]:
        """The profile's point whose outward normal is ``direction`` (a straight flank: its
        end on the nose's side when the direction is its normal)."""
        for part in self.parts(axis):
            if part.holds(direction) and part.radius < math.inf:
                e = _u(direction)
                return (part.centre[0] + part.radius * e[0],
                        part.centre[1] + part.radius * e[1])
        raise AssertionError("no part holds the direction")  # pragma: no cover


@dataclass(frozen=True)
class Part:
    """One part of the profile: a circular arc (``centre``, ``radius``) or a straight flank
    (radius ∞, normal at ``lo`` = ``hi`` from the axis); its outward normals run from ``lo``
    to ``hi`` (radians from the nose axis ``axis``, CCW)."""

    name: str
    side: int
    centre: tuple[float, float]
    radius: float
    axis: float
    lo: float
    hi: float

    def holds(self, direction: float, tol: float = 1e-12) -> bool:
        rel = (direction - self.axis - self.lo) % (2 * math.pi)
        return rel <= (self.hi - self.lo) + tol or rel >= 2 * math.pi - tol


@dataclass(frozen=True)
class Follower:
    """The follower: ``kind`` knife, roller or flat; translating along ``stroke`` (angle) with
    its line ``offset`` to the left of O, or oscillating about ``pivot`` (relative to O) on an
    arm of ``arm`` on ``side`` (+1 left); ``face_offset`` an oscillating flat face's."""

    kind: str
    roller: float = 0.0
    stroke: float | None = None
    offset: float = 0.0
    pivot: tuple[float, float] | None = None
    arm: float = 0.0
    side: int = 1
    face_offset: float = 0.0

    @property
    def oscillating(self) -> bool:
        return self.pivot is not None

    @property
    def foot(self) -> tuple[float, float]:
        """b: the foot of O on the line of stroke."""
        e = _u(self.stroke)
        return (-self.offset * e[1], self.offset * e[0])


@dataclass(frozen=True)
class Contact:
    """The part in contact (``part``: 'nose', 'flank', 'straight flank', 'base circle'), its
    ``side`` (+1: the flank after the nose in the cam's CCW order), centre (O at the origin,
    the fixed frame) and radius, the outward ``normal`` at the contact (angle), the follower's
    point ``point`` (the roller's centre, the knife's edge, a flat face's point of contact) and
    ``s``: a translating follower's displacement from the foot of O along the stroke (the
    roller's centre, the face), an oscillating one's arm angle ψ (pivot → R; a flat face:
    the arm's direction)."""

    part: str
    side: int
    centre: tuple[float, float]
    radius: float
    normal: float
    point: tuple[float, float]
    s: float


def _circle_meets(p, r, c, rho):
    """The two points of the circles (p, r) and (c, rho), or ()."""
    w = (c[0] - p[0], c[1] - p[1])
    dd = math.hypot(*w)
    if dd == 0:
        return ()
    a = (r * r - rho * rho + dd * dd) / (2 * dd)
    h2 = r * r - a * a
    if h2 < 0:
        return ()
    h = math.sqrt(h2)
    ex, ey = w[0] / dd, w[1] / dd
    m = (p[0] + a * ex, p[1] + a * ey)
    return ((m[0] - h * ey, m[1] + h * ex), (m[0] + h * ey, m[1] - h * ex))


def _line_circle(N, p, q, r):
    """The points x of the line x·N = p on the circle (q, r)."""
    t = (-N[1], N[0])
    dist = p - _dot(q, N)
    h2 = r * r - dist * dist
    if h2 < 0:
        return ()
    foot = (q[0] + dist * N[0], q[1] + dist * N[1])
    h = math.sqrt(h2)
    return ((foot[0] + h * t[0], foot[1] + h * t[1]), (foot[0] - h * t[0], foot[1] - h * t[1]))


def _on_straight(profile: Profile, part: Part, x, rr) -> bool:
    """Whether the roller centre ``x`` (its contact x − rr N) lies on the flank segment."""
    N = _u(part.axis + part.lo)
    T = (-N[1], N[0])
    q = (x[0] - rr * N[0], x[1] - rr * N[1])
    a = _dot((profile.base * N[0], profile.base * N[1]), T)
    nose = _rot((profile.d, 0.0), part.axis)
    b = _dot((nose[0] + profile.nose * N[0], nose[1] + profile.nose * N[1]), T)
    lo, hi = sorted((a, b))
    return lo - 1e-12 <= _dot(q, T) <= hi + 1e-12


def contact(profile: Profile, f: Follower, axis: float) -> Contact:
    """The part in contact with the nose axis at ``axis`` (the module docstring)."""
    cands = []
    rr = f.roller if f.kind == "roller" else 0.0
    for part in profile.parts(axis):
        straight = part.radius == math.inf
        if f.kind == "flat" and not f.oscillating:
            normal = f.stroke
            if straight or not part.holds(normal):
                continue
            e = _u(normal)
            pt = (part.centre[0] + part.radius * e[0], part.centre[1] + part.radius * e[1])
            return Contact(part.name, part.side, part.centre, part.radius, normal, pt,
                           _dot(part.centre, e) + part.radius)
        if f.kind == "flat":          # oscillating flat face: (c − Q)·n_l = f + side ρ
            if straight:
                continue
            w = (part.centre[0] - f.pivot[0], part.centre[1] - f.pivot[1])
            k = f.face_offset + f.side * part.radius
            if abs(k) > math.hypot(*w):
                continue
            for sgn in (1, -1):
                psi = math.atan2(w[1], w[0]) - math.pi / 2 + sgn * math.acos(k / math.hypot(*w))
                nl = _u(psi + math.pi / 2)
                pt = (part.centre[0] - f.side * part.radius * nl[0],
                      part.centre[1] - f.side * part.radius * nl[1])
                normal = math.atan2(-f.side * nl[1], -f.side * nl[0])
                along = _dot((pt[0] - f.pivot[0], pt[1] - f.pivot[1]), _u(psi))
                if 0 < along <= f.arm and part.holds(normal):       # on the face
                    cands.append((math.hypot(*pt), Contact(part.name, part.side, part.centre,
                                                          part.radius, normal, pt,
                                                          _wrap(psi))))
            continue
        # a knife or a roller: its point on the part's offset curve
        if f.oscillating:
            if straight:
                N = _u(axis + part.lo)
                pts = _line_circle(N, profile.base + rr, f.pivot, f.arm)
            else:
                pts = _circle_meets(f.pivot, f.arm, part.centre, part.radius + rr)
            pts = [x for x in pts
                   if f.side * _cross((-f.pivot[0], -f.pivot[1]),
                                      (x[0] - f.pivot[0], x[1] - f.pivot[1])) > 0]
        else:
            e, b = _u(f.stroke), f.foot
            if straight:
                N = _u(axis + part.lo)
                if _dot(e, N) <= 1e-12:
                    continue
                s = (profile.base + rr - _dot(b, N)) / _dot(e, N)
            else:
                w = (part.centre[0] - b[0], part.centre[1] - b[1])
                ce = _dot(w, e)
                disc = ce * ce - _dot(w, w) + (part.radius + rr) ** 2
                if disc < 0:
                    continue
                s = ce + math.sqrt(disc)
            pts = [(b[0] + s * e[0], b[1] + s * e[1])]
        for x in pts:
            if straight:
                if not _on_straight(profile, part, x, rr):
                    continue
                normal = axis + part.lo
            else:
                normal = math.atan2(x[1] - part.centre[1], x[0] - part.centre[0])
                if not part.holds(normal):
                    continue
            if f.oscillating:
                s = _wrap(math.atan2(x[1] - f.pivot[1], x[0] - f.pivot[0]))
            else:
                s = _dot((x[0] - f.foot[0], x[1] - f.foot[1]), _u(f.stroke))
            cands.append((math.hypot(*x), Contact(part.name, part.side, part.centre,
                                                  part.radius, normal, x, s)))
    if not cands:
        raise SceneError("no part of the cam's profile meets the follower (check the "
                         "follower's place: the arm too short or too long for the cam, a flat "
                         "face shorter than the reach of its contact)")
    return max(cands, key=lambda c: c[0])[1]


def straight_flank_motion(profile: Profile, f: Follower, axis: float, omega: float,
                          alpha: float = 0.0) -> tuple[float, float, float]:
    """(s, v, a) of a translating knife or roller on a straight flank, the closed form:
    X = b + s e on x·N = r₁ + r, N turning with the cam (dN/dθ = T = N turned 90°):
    s = (r₁ + r − b·N)/(e·N), s′ = −(X·T)/(e·N), s″ = −(g′ (e·N) − g (e·T))/(e·N)² with
    g = X·T, g′ = s′ (e·T) − (r₁ + r); v = ω s′, a = ω² s″ + α s′."""
    rr = f.roller if f.kind == "roller" else 0.0
    got = contact(profile, f, axis)
    if got.part != "straight flank":
        raise ValueError("the follower is not on a straight flank")
    N = _u(got.normal)
    T = (-N[1], N[0])
    e, b = _u(f.stroke), f.foot
    p = profile.base + rr
    h = _dot(e, N)
    s = (p - _dot(b, N)) / h
    X = (b[0] + s * e[0], b[1] + s * e[1])
    g = _dot(X, T)
    s1 = -g / h
    g1 = s1 * _dot(e, T) - p
    s2 = -(g1 * h - g * _dot(e, T)) / (h * h)
    return s, omega * s1, omega * omega * s2 + alpha * s1


def _q(value, dim, file, where) -> float:
    return parse_quantity(value, dim, file=file, where=where)


def profile_of(table: dict, file: str, where: str) -> Profile:
    """The profile a [cam_profiles] entry states, checked (one line naming the key)."""
    for key in table:
        if key not in KEYS and key != AXIS_KEY:
            raise SceneError(f"unknown key {show(key)} (keys: {', '.join(KEYS)})", file=file,
                             where=f"{where}.{key}")
    for key in ("base_radius", "nose_radius"):
        if key not in table:
            raise SceneError(f"missing key {key!r}", file=file, where=where)
    r1, r2 = (_q(table[k], "length", file, f"{where}.{k}")
              for k in ("base_radius", "nose_radius"))
    kind = table.get("kind", "circular arc")
    if kind not in KINDS:
        raise SceneError(f"kind must be one of {', '.join(KINDS)}, got {show(kind)}",
                         file=file, where=f"{where}.kind")
    if not (r1 > 0 and r2 > 0):
        raise SceneError("base_radius and nose_radius must be positive", file=file,
                         where=where)
    if not r2 < r1:
        raise SceneError("the nose must be smaller than the base circle (nose_radius < "
                         "base_radius)", file=file, where=f"{where}.nose_radius")
    if "faces_angle" in table:
        if kind != "tangent" or "lift" in table:
            raise SceneError("faces_angle states a tangent cam's lift: with kind = "
                             "\"tangent\" and no lift", file=file, where=f"{where}.faces_angle")
        faces = _q(table["faces_angle"], "angle", file, f"{where}.faces_angle")
        if not 0 < faces < math.pi:
            raise SceneError("faces_angle must be between 0 and 180 deg", file=file,
                             where=f"{where}.faces_angle")
        beta = (math.pi - faces) / 2
        lift = (r1 - r2) / math.cos(beta) + r2 - r1
    elif "lift" in table:
        lift = _q(table["lift"], "length", file, f"{where}.lift")
    else:
        raise SceneError("missing key 'lift' (or faces_angle for a tangent cam)", file=file,
                         where=where)
    if not lift > 0:
        raise SceneError("lift must be positive", file=file, where=f"{where}.lift")
    flank = None
    action = (_q(table["angle_of_action"], "angle", file, f"{where}.angle_of_action")
              if "angle_of_action" in table else None)
    if kind == "circular arc" and "flank_radius" not in table and action is not None:
        flank = flank_for_action(r1, r2, lift, action, file, f"{where}.angle_of_action")
        return Profile(r1, r2, lift, flank)
    if kind == "circular arc":
        if "flank_radius" not in table:
            raise SceneError("a circular-arc cam needs flank_radius or angle_of_action (or "
                             "kind = \"tangent\")", file=file, where=where)
        flank = _q(table["flank_radius"], "length", file, f"{where}.flank_radius")
        p = Profile(r1, r2, lift, flank)
        u = (p.d ** 2 - (flank - r2) ** 2 + (flank - r1) ** 2) / (2 * p.d)
        if not (flank > r1 and (flank - r1) ** 2 > u * u):
            raise SceneError(f"a flank of radius {show(table['flank_radius'])} cannot touch "
                             f"both the base circle and the nose: it must be larger", file=file,
                             where=f"{where}.flank_radius")
    elif "flank_radius" in table:
        raise SceneError("a tangent cam's flanks are straight: leave flank_radius out",
                         file=file, where=f"{where}.flank_radius")
    prof = Profile(r1, r2, lift, flank)
    if action is not None and abs(2 * prof.spans()[1] - action) > math.radians(0.05):
        raise SceneError(f"angle_of_action {show(table['angle_of_action'])} does not fit the "
                         f"profile, whose angle of action is "
                         f"{math.degrees(2 * prof.spans()[1]):.6g} deg", file=file,
                         where=f"{where}.angle_of_action")
    return prof


def flank_for_action(r1: float, r2: float, lift: float, action: float, file, where) -> float:
    """The flank radius R of the circular-arc cam whose angle of action is ``action``: 2 φ_b
    falls from 360° (the smallest flank that touches both circles) to the tangent cam's 2 β as
    R grows; bisection on log R."""
    tangent = 2 * Profile(r1, r2, lift, None).spans()[1]
    if not tangent < action < 2 * math.pi:
        raise SceneError(f"a circular-arc cam with this base circle, nose and lift has an angle "
                         f"of action between {math.degrees(tangent):.6g} deg (straight flanks) "
                         f"and 360 deg", file=file, where=where)
    d = r1 + lift - r2

    def phi_b(R):
        u = (d * d - (R - r2) ** 2 + (R - r1) ** 2) / (2 * d)
        if (R - r1) ** 2 <= u * u:
            return math.pi
        return Profile(r1, r2, lift, R).spans()[1]
    lo, hi = math.log(r1), math.log(1e9 * r1)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if 2 * phi_b(math.exp(mid)) > action:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-15:
            break
    return math.exp(0.5 * (lo + hi))


def follower_of(table: dict, ground: dict, o, file: str, where: str) -> Follower:
    """The follower a [cam_profiles] entry states (``o`` the cam centre's coordinates), checked."""
    kind = table.get("follower", "roller")
    if kind not in FOLLOWERS:
        raise SceneError(f"follower must be one of {', '.join(FOLLOWERS)}, got "
                         f"{show(kind)}", file=file, where=f"{where}.follower")
    roller = 0.0
    if kind == "roller":
        if "roller" not in table:
            raise SceneError("a roller follower needs roller = \"<radius>\"", file=file,
                             where=where)
        roller = _q(table["roller"], "length", file, f"{where}.roller")
        if not roller > 0:
            raise SceneError("roller must be positive", file=file, where=f"{where}.roller")
    elif "roller" in table:
        raise SceneError(f"roller is for a roller follower, not a {kind} one", file=file,
                         where=f"{where}.roller")
    if "pivot" in table:
        if "stroke" in table or "offset" in table:
            raise SceneError("an oscillating follower (pivot) has no line of stroke: leave "
                             "stroke and offset out", file=file, where=f"{where}.pivot")
        piv = table["pivot"]
        if not isinstance(piv, str) or piv not in ground or not isinstance(ground[piv], list):
            raise SceneError(f"pivot must be a point of [ground] given as [x, y], got "
                             f"{show(piv)}", file=file, where=f"{where}.pivot")
        q = [_q(x, "length", file, f"ground.{piv}") for x in ground[piv]]
        if "arm" not in table:
            raise SceneError("an oscillating follower needs arm = \"<length>\" (pivot to the "
                             "roller's centre or the knife's edge)", file=file, where=where)
        arm = _q(table["arm"], "length", file, f"{where}.arm")
        side = table.get("side")
        if side not in SIDES:
            raise SceneError(f"side must be 'left' or 'right', got {show(side)}", file=file,
                             where=f"{where}.side")
        if not arm > 0:
            raise SceneError("arm must be positive", file=file, where=f"{where}.arm")
        if "face_offset" in table and kind != "flat":
            raise SceneError("face_offset is for a flat face", file=file,
                             where=f"{where}.face_offset")
        fo = _q(table.get("face_offset", "0 mm"), "length", file, f"{where}.face_offset")
        return Follower(kind, roller, pivot=(q[0] - o[0], q[1] - o[1]), arm=arm,
                        side=1 if side == "left" else -1, face_offset=fo)
    for key in ("arm", "side", "face_offset"):
        if key in table:
            raise SceneError(f"{key} is for an oscillating follower (with pivot)", file=file,
                             where=f"{where}.{key}")
    if "stroke" not in table:
        raise SceneError("missing key 'stroke' (a translating follower's line of stroke) or "
                         "'pivot' (an oscillating follower's)", file=file, where=where)
    stroke = _q(table["stroke"], "angle", file, f"{where}.stroke")
    off = _q(table.get("offset", "0 mm"), "length", file, f"{where}.offset")
    return Follower(kind, roller, stroke=stroke, offset=off)


def _fresh(base: str, data: dict) -> str:
    used = set()
    for t in ("ground", "points", "links", "sliders", "slots"):
        if isinstance(data.get(t), dict):
            used |= set(data[t])
    for suffix in ("1", "2", "3", "'", "''"):
        if base + suffix not in used:
            return base + suffix
    return base + "_c"      # pragma: no cover


def stated(data: dict, file: str):
    """(label, table, profile, follower, O's label, O's coordinates, the crank, K) of a
    scene's [cam_profiles], checked."""
    raw = data.get(TABLE)
    if not isinstance(raw, dict) or len(raw) != 1:
        raise SceneError("[cam_profiles] holds one cam (its follower's label)", file=file,
                         where=TABLE)
    (label, table), = raw.items()
    where = f"{TABLE}.{label}"
    if not isinstance(table, dict):
        raise SceneError("expected a table", file=file, where=where)
    if AXIS_KEY in table:
        raise SceneError(f"unknown key {AXIS_KEY!r}", file=file, where=where)
    prof = profile_of(table, file, where)
    drv = data.get("driver")
    if not (isinstance(drv, dict) and isinstance(drv.get("crank"), str)
            and (isinstance(drv.get("angle"), str) or "when" in table)):
        raise SceneError("a cam by its profile is driven as a crank: [driver] crank = \"OK\" "
                         "(O the cam's centre, K the centre of curvature found) and angle = the "
                         "nose axis's direction", file=file, where="driver")
    m = _LINK.match(drv["crank"])
    if m is None:
        raise SceneError(f"{show(drv['crank'])} is not a link name (two labels: 'OK')",
                         file=file, where="driver.crank")
    centre_o, k = m.groups()
    ground = data.get("ground", {})
    if not (isinstance(ground, dict) and centre_o in ground):
        raise SceneError(f"the cam's centre {centre_o} must be in [ground]", file=file,
                         where="driver.crank")
    if not isinstance(ground[centre_o], list):
        raise SceneError(f"give the cam's centre {centre_o} as [x, y]", file=file,
                         where=f"ground.{centre_o}")
    o = [_q(x, "length", file, f"ground.{centre_o}") for x in ground[centre_o]]
    fol = follower_of(table, ground, o, file, where)
    return label, table, prof, fol, centre_o, o, drv["crank"], k


def _loads_on_the_cam(data: dict, crank: str, k: str, file: str) -> None:
    """The force tables on a cam by its profile, checked: the crank O → K is the equivalent
    linkage's (K the part's centre of curvature, found at each angle), not the cam — its
    mass only at O with an inertia of its own (not a rod's of OK), and nothing at K."""
    masses = data.get("masses")
    spec = masses.get(crank) if isinstance(masses, dict) else None
    if isinstance(spec, dict):
        c = spec.get("centre", "0.5")
        try:
            at_o = float(c) == 0.0
        except (TypeError, ValueError):
            at_o = isinstance(c, str) and _q(c, "length", file, f"masses.{crank}.centre") == 0
        own = "radius_of_gyration" in spec or spec.get("inertia", "rod") != "rod"
        if not (at_o and own) or "centre_left" in spec:
            raise SceneError(f"[masses.{crank}] on a cam stated by its profile: {crank} is the "
                             f"equivalent linkage's crank (O to the centre of curvature {k} "
                             f"found at each angle), not the cam: give the cam's mass at its "
                             f"centre (centre = \"0 mm\") with its own inertia "
                             f"(radius_of_gyration, inertia = \"disc\" or a value)",
                             file=file, where=f"masses.{crank}")
    for tab in ("masses", "forces", "springs"):
        for name, entry in (data.get(tab) or {}).items() if isinstance(data.get(tab),
                                                                        dict) else ():
            if isinstance(entry, dict) and k in (entry.get("at"), entry.get("a"),
                                                 entry.get("b")):
                raise SceneError(f"{k} is the centre of curvature of the part in contact, "
                                 f"found at each cam angle, no point of the cam's own: nothing "
                                 f"can act at it", file=file, where=f"{tab}.{name}")


def rewrite(data: dict, file: str) -> dict:
    """``data`` with its [cam_profiles.R] replaced by its equivalent linkage at the driver's
    angle (see the module docstring)."""
    if data.get(TABLE) is None:
        return data
    label, table, prof, fol, centre_o, o, crank, k = stated(data, file)
    where = f"{TABLE}.{label}"
    _loads_on_the_cam(data, crank, k, file)
    drv = data["driver"]
    axis = nose_axis_of(table, drv, lambda ax: contact(prof, fol, ax).part, file, where)
    try:
        got = contact(prof, fol, axis)
    except SceneError as exc:
        raise SceneError(str(exc.args[0]) if exc.args else str(exc), file=file,
                         where=where) from None
    if got.part == "base circle":
        raise SceneError(f"at this cam angle the follower {label} dwells on the base circle: it "
                         f"is at rest (v = 0, a = 0) and there is no equivalent linkage",
                         file=file, where=where)
    straight = got.part == "straight flank"
    out = dict(data)
    out[TABLE] = {label: {**table, AXIS_KEY: f"{axis!r} rad"}}     # kept for the drawing
    links = dict(data.get("links", {}))
    pt = (o[0] + got.point[0], o[1] + got.point[1])
    near = {"near": [f"{pt[0]!r} m", f"{pt[1]!r} m"]}
    arm = None
    if fol.oscillating:
        arm = table["pivot"] + label
        if arm in links:
            raise SceneError(f"the follower's arm {arm} is built from pivot and arm: leave it "
                             f"out of [links]", file=file, where=f"links.{arm}")
        links[arm] = f"{fol.arm!r} m"
    if straight:       # a pin in a slot of the cam ∥ the flank, r₁ + roller from O
        t = _rot(_u(got.normal), -math.pi / 2)       # N is the slot's left normal …
        sense = 1.0 if _dot(got.point, t) >= 0 else -1.0    # … K on the roller's side
        t = (sense * t[0], sense * t[1])
        links[crank] = f"{prof.d!r} m"
        out["driver"] = {**drv, "angle": f"{math.degrees(math.atan2(t[1], t[0]))!r} deg"}
        rr = fol.roller if fol.kind == "roller" else 0.0
        out["slots"] = {**data.get("slots", {}),
                        label: {"lever": crank, "coincident": _fresh(label, data),
                                "offset": f"{sense * (prof.base + rr)!r} m"}}
        if not fol.oscillating:      # the pin also on the fixed guide: the tangent mechanism
            b = (o[0] + fol.foot[0], o[1] + fol.foot[1])
            out["sliders"] = {**data.get("sliders", {}),
                              label: {"through": [f"{b[0]!r} m", f"{b[1]!r} m"],
                                      "direction": f"{math.degrees(fol.stroke)!r} deg"}}
        out["links"] = links
        out["assembly"] = {**data.get("assembly", {}), label: near}
        return out
    c = got.centre
    links[crank] = f"{math.hypot(*c)!r} m"
    out["links"] = links
    out["driver"] = {**drv, "angle": f"{math.degrees(math.atan2(c[1], c[0]))!r} deg"}
    cam = {"centre": k, "radius": f"{got.radius!r} m"}
    if fol.kind == "flat" and fol.oscillating:
        cam |= {"follower": "flat", "arm": arm, "side": "left" if fol.side > 0 else "right",
                "face_offset": f"{fol.face_offset!r} m"}
    elif fol.kind == "flat":
        b = (o[0] + fol.foot[0], o[1] + fol.foot[1])
        out["sliders"] = {**data.get("sliders", {}),
                          label: {"through": [f"{b[0]!r} m", f"{b[1]!r} m"],
                                  "direction": f"{math.degrees(fol.stroke)!r} deg"}}
        cam |= {"follower": "flat", "face": f"{math.degrees(fol.stroke) + 90.0!r} deg"}
    else:
        cam |= {"roller": f"{fol.roller!r} m"}
        if not fol.oscillating:
            b = (o[0] + fol.foot[0], o[1] + fol.foot[1])
            out["sliders"] = {**data.get("sliders", {}),
                              label: {"through": [f"{b[0]!r} m", f"{b[1]!r} m"],
                                      "direction": f"{math.degrees(fol.stroke)!r} deg"}}
        out["assembly"] = {**data.get("assembly", {}), label: near}
    out["cams"] = {**data.get("cams", {}), label: cam}
    return out


__all__ = ["Profile", "Part", "Follower", "Contact", "contact", "profile_of", "follower_of",
           "stated", "straight_flank_motion", "rewrite", "pose", "to_dict", "report_lines",
           "TABLES", "AXIS_KEY"]


def pose(scene):
    """(profile, follower, nose axis angle, O's coordinates, the follower's label, contact) of
    a solved scene's cam stated by its profile (None without one): the drawing's."""
    raw = scene.extra.get(TABLE)
    if not raw:
        return None
    (label, table), = raw.items()
    m = _LINK.match(scene.driver.link)
    o = scene.ground[m.group(1)]
    ground = {g: [f"{p[0]!r} m", f"{p[1]!r} m"] for g, p in scene.ground.items()}
    clean = {k: v for k, v in table.items() if k != AXIS_KEY}
    prof = profile_of(clean, scene.file, f"{TABLE}.{label}")
    fol = follower_of(clean, ground, o, scene.file, f"{TABLE}.{label}")
    axis = _q(table[AXIS_KEY], "angle", scene.file, f"{TABLE}.{label}")
    return prof, fol, axis, o, label, contact(prof, fol, axis)


def to_dict(scene) -> dict | None:
    """The cam's profile as found and the part in contact (SI, angles in degrees): the JSON's
    ``cam_profile``; None without one."""
    got = pose(scene)
    if got is None:
        return None
    prof, fol, axis, o, label, c = got
    phi_n, phi_b = prof.spans()
    out = {"follower_point": label,
           "kind": "circular arc" if prof.flank is not None else "tangent",
           "base_radius": prof.base, "nose_radius": prof.nose, "lift": prof.lift,
           "flank_radius": prof.flank, "nose_centre_distance": prof.d,
           "angle_of_action_deg": math.degrees(2 * phi_b),
           "nose_span_deg": math.degrees(2 * phi_n),
           "nose_axis_deg": math.degrees(axis),
           "follower": fol.kind, "motion": "oscillating" if fol.oscillating else "translating",
           "part_in_contact": c.part,
           "contact_normal_deg": math.degrees(c.normal) % 360.0,
           "follower_position": [o[0] + c.point[0], o[1] + c.point[1]]}
    if fol.oscillating:
        out["arm_angle_deg"] = math.degrees(c.s)
    else:
        rr = fol.roller if fol.kind == "roller" else 0.0
        dwell = math.sqrt(max((prof.base + rr) ** 2 - fol.offset ** 2, 0.0)) \
            if fol.kind != "flat" else prof.base
        out["displacement"] = c.s
        out["lift_from_dwell"] = c.s - dwell
    return out


def report_lines(scene) -> list[str]:
    """The cam's profile and its contact, in words (``polygons solve``)."""
    d = to_dict(scene)
    if d is None:
        return []
    mm = lambda x: f"{x * 1e3:.6g} mm"        # noqa: E731
    head = (f"cam by its profile ({d['kind']}): base circle {mm(d['base_radius'])}, nose "
            f"{mm(d['nose_radius'])}, lift {mm(d['lift'])}"
            + (f", flanks {mm(d['flank_radius'])}" if d["flank_radius"] else "")
            + f", angle of action {d['angle_of_action_deg']:.6g}°")
    lines = [head, f"  nose axis at {d['nose_axis_deg']:.6g}°: the {d['part_in_contact']} "
                   f"touches the {d['motion']} {d['follower']} follower "
                   f"{d['follower_point']} (contact normal at "
                   f"{d['contact_normal_deg']:.6g}°)"]
    if d["motion"] == "oscillating":
        lines.append(f"  the arm's angle: {d['arm_angle_deg']:.6g}°")
    else:
        lines.append(f"  the follower's displacement along the stroke: "
                     f"{mm(d['displacement'])} ({mm(d['lift_from_dwell'])} above its dwell)")
        if d["follower"] == "flat":     # R is the equivalent yoke's point, not the face's
            got = pose(scene)[-1]
            lines.append(f"  (the point {d['follower_point']} of the table is the equivalent "
                         f"yoke's, on the stroke at the level of K: {mm(got.radius)} short of "
                         f"the face; the face's displacement is the line above)")
    return lines
