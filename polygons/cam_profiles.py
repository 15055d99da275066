"""Cams stated by their profile, as books state them: base circle, nose radius, lift and the
flank radius (a circular-arc cam) or straight flanks (a tangent cam), a translating follower
(knife-edge, roller or flat-faced) whose line of stroke passes through the cam's centre.

    [driver]
    crank = "OK"                 # O: the cam's centre; K: the centre of curvature of the
    angle = "30 deg"             #   part in contact (found here); angle: the nose's axis,
    omega = "10 rad/s"           #   O → nose centre, CCW from +x
    sense = "CCW"
    [cam_profiles.R]             # R: the follower's point (the roller's centre, the knife's
    base_radius = "25 mm"        #   edge, the flat face's point on the line of stroke)
    nose_radius = "8 mm"
    lift = "20 mm"
    flank_radius = "60 mm"       # or kind = "tangent" (straight flanks)
    follower = "roller"          # "knife", "roller" (with roller = "10 mm") or "flat"
    roller = "10 mm"
    stroke = "90 deg"            # the line of stroke, from O towards the follower

Geometry (the cam's own frame, x along the nose axis): the nose centre Q at d = r₁ + L − r₂; a
circular-arc flank of radius R has its centre P on the far side of the axis, |OP| = R − r₁,
|QP| = R − r₂ (tangent to the base circle where the ray P→O meets it, to the nose where P→Q
meets it); a tangent cam's flank is the common tangent of the two circles.  At the stated cam
angle the part in contact is the one whose span of outward normals holds the contact normal —
the stroke's direction for a flat face; the direction from the part's centre to the roller's
centre, on the ray of the stroke, for a knife or a roller — and the scene is rewritten to its
equivalent linkage: the crank O → K (K the part's centre, rigid with the cam) and a [cams.R]
entry (radius of the part; a flat face's R is then the yoke's point under K, the face
the part's radius beyond it along the stroke: v and a are the follower's, its displacement is
y(R) + ρ).  On the base circle the follower dwells (at rest: refused in those
words, there is no linkage); a tangent cam's straight flank is not served yet (refused).

:func:`contact` is the geometry alone (used by the tests and the report); :func:`rewrite`
turns a scene's ``[cam_profiles]`` into ``[links]``, ``[sliders]``, ``[cams]`` and the
driver's angle before :func:`polygons.contacts.rewrite` reads them.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .errors import SceneError, show
from .schema import Key, Table
from .units import parse_quantity

TABLE = "cam_profiles"
FOLLOWERS = ("knife", "roller", "flat")
KINDS = ("circular arc", "tangent")

TABLES: tuple[Table, ...] = (
    Table(TABLE, "[cam_profiles.R]: a cam stated by its profile (base circle, nose, flanks) with "
                 "a translating follower whose line of stroke passes through the cam's centre "
                 "(R: the follower's point); the part in contact at the driver's angle (the "
                 "nose's axis) is found and the equivalent linkage built: the driver's crank "
                 "O → K (K: the part's centre of curvature, rigid with the cam) and a [cams.R] "
                 "entry.  The follower dwelling on the base circle and a tangent cam's "
                 "straight flank are refused in words.", (
        Key("base_radius", "quantity", "the base circle's radius r₁", example='"25 mm"',
            dimension="length", required=True),
        Key("nose_radius", "quantity", "the nose's radius r₂", example='"8 mm"',
            dimension="length", required=True),
        Key("lift", "quantity", "the follower's lift L (nose centre at r₁ + L − r₂ from O)",
            example='"20 mm"', dimension="length", required=True),
        Key("kind", "string", "'circular arc' (with flank_radius) or 'tangent'",
            example='"circular arc"', default="circular arc"),
        Key("flank_radius", "quantity", "a circular-arc cam's flank radius R",
            example='"60 mm"', dimension="length"),
        Key("angle_of_action", "quantity", "the cam's turn while the follower moves (rise "
                                           "and return, 2 φ_b): with a circular-arc cam and "
                                           "no flank_radius, the flank radius is found from "
                                           "it; otherwise checked against the profile (to "
                                           "0.05°)", example='"150 deg"', dimension="angle"),
        Key("follower", "string", "'knife', 'roller' or 'flat' (translating)",
            example='"roller"', default="roller"),
        Key("roller", "quantity", "the roller's radius", example='"10 mm"',
            dimension="length"),
        Key("stroke", "quantity", "the line of stroke's direction from the cam's centre "
                                  "towards the follower, CCW from +x", example='"90 deg"',
            dimension="angle", required=True),
    ), many=True),
)
KEYS = tuple(k.name for k in TABLES[0].keys)
_LINK = re.compile(r"^([A-Z][a-z0-9_']*)([A-Z][a-z0-9_']*)$")


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
        those of the flanks over φ_n < |φ| ≤ φ_b, the base circle's beyond."""
        if self.flank is None:     # tangent: the common tangent's normal
            beta = math.acos((self.base - self.nose) / self.d)
            return beta, beta
        P = self.flank_centre(+1)
        phi_n = math.atan2(-P[1], self.d - P[0])      # the direction P → Q
        phi_b = math.atan2(-P[1], -P[0])              # the direction P → O
        return phi_n, phi_b

    def parts(self, side: int):
        """(name, centre, radius) of the parts on the side of the contact."""
        out = [("nose", (self.d, 0.0), self.nose)]
        if self.flank is not None:
            out.append(("flank", self.flank_centre(side), self.flank))
        out.append(("base circle", (0.0, 0.0), self.base))
        return out


@dataclass(frozen=True)
class Contact:
    """The part in contact: ``part`` ('nose', 'flank', 'base circle', 'tangent flank'),
    ``side`` (+1: the flank after the nose in the cam's CCW order), its centre (cam frame)
    and radius, and the follower's displacement ``s`` from O along the stroke."""

    part: str
    side: int
    centre: tuple[float, float]
    radius: float
    s: float


def _wrap(x: float) -> float:
    return math.atan2(math.sin(x), math.cos(x))


def contact(profile: Profile, follower: str, roller: float, phi: float) -> Contact:
    """The part in contact when the line of stroke is at ``phi`` from the nose axis (the
    stroke's angle minus the axis's): a flat face touches where the outward normal is the
    stroke; a knife or a roller where the ray of the stroke meets the part's offset arc with
    its normal in the part's span."""
    phi = _wrap(phi)
    side = 1 if phi >= 0 else -1
    phi_n, phi_b = profile.spans()
    e = (math.cos(phi), math.sin(phi))
    rr = roller if follower == "roller" else 0.0
    for name, c, rho in profile.parts(side):
        if follower == "flat":
            normal = abs(phi)
        else:
            ce = c[0] * e[0] + c[1] * e[1]
            disc = ce * ce - (c[0] ** 2 + c[1] ** 2) + (rho + rr) ** 2
            if disc < 0:
                continue
            s = ce + math.sqrt(disc)
            normal = abs(math.atan2(s * e[1] - c[1], s * e[0] - c[0]))
        lo, hi = {"nose": (0.0, phi_n), "flank": (phi_n, phi_b),
                  "base circle": (phi_b, math.pi)}[name]
        if lo - 1e-12 <= normal <= hi + 1e-12:
            if follower == "flat":
                s = c[0] * e[0] + c[1] * e[1] + rho
            return Contact(name, side, c, rho, s)
    if profile.flank is None:
        return Contact("tangent flank", side, (math.nan, math.nan), math.inf, math.nan)
    raise SceneError("no part of the cam's profile meets the follower (the profile is not "
                     "convex: check the radii)")  # pragma: no cover


def _q(value, dim, file, where) -> float:
    return parse_quantity(value, dim, file=file, where=where)


def profile_of(table: dict, file: str, where: str) -> Profile:
    """The profile a [cam_profiles] entry states, checked (one line naming the key)."""
    for key in table:
        if key not in KEYS:
            raise SceneError(f"unknown key {show(key)} (keys: {', '.join(KEYS)})", file=file,
                             where=f"{where}.{key}")
    for key in ("base_radius", "nose_radius", "lift", "stroke"):
        if key not in table:
            raise SceneError(f"missing key {key!r}", file=file, where=where)
    r1, r2, lift = (_q(table[k], "length", file, f"{where}.{k}")
                    for k in ("base_radius", "nose_radius", "lift"))
    kind = table.get("kind", "circular arc")
    if kind not in KINDS:
        raise SceneError(f"kind must be one of {', '.join(KINDS)}, got {show(kind)}",
                         file=file, where=f"{where}.kind")
    if not (r1 > 0 and r2 > 0 and lift > 0):
        raise SceneError("base_radius, nose_radius and lift must be positive", file=file,
                         where=where)
    if not r2 < r1:
        raise SceneError("the nose must be smaller than the base circle (nose_radius < "
                         "base_radius)", file=file, where=f"{where}.nose_radius")
    if not r1 + lift - r2 > 0:
        raise SceneError("the nose centre must lie beyond O (base_radius + lift > "
                         "nose_radius)", file=file, where=f"{where}.lift")
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


def rewrite(data: dict, file: str) -> dict:
    """``data`` with each [cam_profiles.R] replaced by its equivalent linkage at the driver's
    angle (see the module docstring)."""
    raw = data.get(TABLE)
    if raw is None:
        return data
    if not isinstance(raw, dict) or len(raw) != 1:
        raise SceneError("[cam_profiles] holds one cam (its follower's label)", file=file,
                         where=TABLE)
    (label, table), = raw.items()
    where = f"{TABLE}.{label}"
    if not isinstance(table, dict):
        raise SceneError("expected a table", file=file, where=where)
    prof = profile_of(table, file, where)
    drv = data.get("driver")
    if not (isinstance(drv, dict) and isinstance(drv.get("crank"), str)
            and isinstance(drv.get("angle"), str)):
        raise SceneError("a cam by its profile is driven as a crank: [driver] crank = \"OK\" "
                         "(O the cam's centre, K the centre of curvature found) and angle = the "
                         "nose axis's direction", file=file, where="driver")
    m = _LINK.match(drv["crank"])
    if m is None:
        raise SceneError(f"{show(drv['crank'])} is not a link name (two labels: 'OK')",
                         file=file, where="driver.crank")
    centre_o, k = m.groups()
    follower = table.get("follower", "roller")
    if follower not in FOLLOWERS:
        raise SceneError(f"follower must be one of {', '.join(FOLLOWERS)}, got "
                         f"{show(follower)}", file=file, where=f"{where}.follower")
    roller = 0.0
    if follower == "roller":
        if "roller" not in table:
            raise SceneError("a roller follower needs roller = \"<radius>\"", file=file,
                             where=where)
        roller = _q(table["roller"], "length", file, f"{where}.roller")
    elif "roller" in table:
        raise SceneError(f"roller is for a roller follower, not a {follower} one", file=file,
                         where=f"{where}.roller")
    axis = _q(drv["angle"], "angle", file, "driver.angle")
    stroke = _q(table["stroke"], "angle", file, f"{where}.stroke")
    got = contact(prof, follower, roller, stroke - axis)
    if got.part == "base circle":
        raise SceneError(f"at this cam angle the follower {label} dwells on the base circle: it "
                         f"is at rest (v = 0, a = 0) and there is no equivalent linkage",
                         file=file, where=where)
    if got.part == "tangent flank":
        raise SceneError("the follower is on a straight flank of the tangent cam: its "
                         "equivalent (a slot on the cam) is not served yet; the nose is",
                         file=file, where=where)
    ground = data.get("ground", {})
    if not (isinstance(ground, dict) and centre_o in ground):
        raise SceneError(f"the cam's centre {centre_o} must be in [ground]", file=file,
                         where="driver.crank")
    o = [_q(x, "length", file, f"ground.{centre_o}") for x in ground[centre_o]] \
        if isinstance(ground[centre_o], list) else None
    if o is None:
        raise SceneError(f"give the cam's centre {centre_o} as [x, y]", file=file,
                         where=f"ground.{centre_o}")
    c = got.centre
    out = dict(data)            # the table stays: kept raw in Scene.extra for diagram()
    out["links"] = {**data.get("links", {}),
                    drv["crank"]: f"{math.hypot(*c)!r} m"}
    out["driver"] = {**drv, "angle": f"{math.degrees(axis + math.atan2(c[1], c[0]))!r} deg"}
    guide = {"through": [f"{o[0]!r} m", f"{o[1]!r} m"],
             "direction": f"{math.degrees(stroke)!r} deg"}
    out["sliders"] = {**data.get("sliders", {}), label: guide}
    cam = {"centre": k, "radius": f"{got.radius!r} m"}
    if follower == "flat":
        cam |= {"follower": "flat", "face": f"{math.degrees(stroke) + 90.0!r} deg"}
    else:
        cam |= {"roller": f"{roller!r} m"}
    out["cams"] = {**data.get("cams", {}), label: cam}
    if follower != "flat":      # the roller's centre: the far end of the equivalent rod
        far = (o[0] + got.s * math.cos(stroke), o[1] + got.s * math.sin(stroke))
        out["assembly"] = {**data.get("assembly", {}),
                           label: {"near": [f"{far[0]!r} m", f"{far[1]!r} m"]}}
    return out


__all__ = ["Profile", "Contact", "contact", "profile_of", "rewrite", "TABLES"]
