"""Higher pairs stated as the books state them, replaced at load by their equivalent linkage.

At one instant a curved contact moves like a link joining the two centres of curvature (the
classic *equivalent linkage*): its velocity and acceleration polygons are the equivalent
mechanism's.  Two forms (scene layer; the rewrite happens on the parsed TOML before the
scene is read, so every method sees ordinary links, sliders and yokes):

    [curved_slots.P]        # the pin P in a circular-arc slot
    centre = "K"            # the slot's centre of curvature: a [ground] point (a slot in the
    radius = "150 mm"       #   frame) or a point of the link carrying it; the arc's radius
                            # → the equivalent link KP = radius

    [cams.R]                # a roller follower: R the roller's centre
    centre = "C"            # the cam profile's centre of curvature at the contact (a point of
    radius = "40 mm"        #   the cam: the end of the crank OC, or [points] on it), and the
    roller = "10 mm"        #   profile's radius of curvature there; the roller's radius
                            # → the equivalent link CR = radius + roller (radius − roller
                            #   when the roller bears on a concave arc: concave = true)

    [cams.F]                # a translating flat-faced follower ([sliders.F] its guide)
    follower = "flat"
    centre = "C"
    radius = "40 mm"
    face = "0 deg"          # the face's direction (fixed: the follower only translates)
                            # → a Scotch yoke: C slides in a slot ∥ the face, carried by F

A wheel rolling on a straight surface ([rolling]) keeps the equivalent slider when the surface
is fixed or carried by a plate that translates along itself (``on``); a cylinder between two
such plates (``opposite``) has no lower-pair equivalent — its centre's place along the plates
is the mean of theirs — and is solved from the no-slip condition at each contact
(:func:`rolling`), outside the linkage.

Refused in words where the curvature is not given (no ``centre`` / ``radius``), and for the
force analysis (the equivalent link carries the contact force along the common normal only at
the instant; forces are not modelled for contacts yet).  :data:`Equivalent` records what was
replaced; ``Scene.equivalents`` holds them, the reports name the equivalent link and the
space diagram draws it dashed, labelled as such.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import SceneError, UnsupportedError, show
from .reader import LABEL
from .schema import Key, Table
from .scene_tables import CONTACT_TABLES
from .units import parse_quantity
from .higher import (OUTPUTS, LINK_NAME, _bar_to_contact, _bearing_lines,  # noqa: F401
                     bearing, higher, on_arc)
from .wheels import _moving_lines, _rim_lines, rolling, wheel_centres, wheel_point

TABLES: tuple[Table, ...] = (
    Table("curved_slots", "A pin in a circular-arc slot, replaced at the instant by the "
                          "equivalent link from the slot's centre of curvature to the pin.", (
        Key("centre", "label", "the slot's centre of curvature: a [ground] point (a slot in "
                               "the frame) or a point of the link that carries the slot",
            example='"K"', required=True),
        Key("radius", "quantity", "the arc's radius (the pin's centre line)", example='"150 mm"',
            dimension="length", required=True),
    ), many=True),
    Table("cams", "A cam and its follower at the contact, replaced at the instant by the "
                  "equivalent linkage through the profile's centre of curvature.", (
        Key("centre", "label", "the cam profile's centre of curvature at the contact (a point "
                               "of the cam: its crank's end or a [points] entry on it)",
            example='"C"', required=True),
        Key("radius", "quantity", "the profile's radius of curvature at the contact",
            example='"40 mm"', dimension="length", required=True),
        Key("follower", "string", "'roller' (the table's label is the roller's centre) or "
                                  "'flat' (a translating flat face; the label is the "
                                  "follower's point on its guide, [sliders.LABEL])",
            example='"roller"', default="roller"),
        Key("roller", "quantity", "the roller's radius (roller follower)", example='"10 mm"',
            dimension="length"),
        Key("concave", "bool", "the roller bears on a concave arc of the profile (the "
                               "equivalent link is radius − roller)", example="false",
            default=False),
        Key("face", "quantity", "the flat face's direction, CCW from +x (flat follower)",
            example='"0 deg"', dimension="angle"),
        Key("arm", "link", "an oscillating flat-faced follower: the arm (a [links] entry, "
                           "pivot label first, the pivot in [ground]) whose face runs along "
                           "it; instead of face and [sliders.LABEL] (the label is then the "
                           "arm's far end)", example='"QF"'),
        Key("side", "string", "with arm: the side of the face, looking along the arm from "
                              "its pivot, on which the cam lies: 'left' or 'right'",
            example='"right"'),
        Key("face_offset", "quantity", "with arm: the face's distance from the line through "
                                       "the arm's ends, positive to the left",
            example='"0 mm"', dimension="length", default="0 mm"),
    ), many=True),
    Table("rolling", "A wheel (disc, cylinder) rolling without slipping on a straight "
                     "surface, fixed or carried by a plate translating along it (`on`), or "
                     "between two such plates (`opposite`); the table's label is the wheel's "
                     "centre. On one surface its centre moves on the line ∥ the surface at "
                     "the radius (the equivalent slider); on a fixed surface its instant "
                     "centre is the contact point and ω = −v/r.", (
        Key("radius", "quantity", "the wheel's radius", example='"50 mm"', dimension="length",
            required=True),
        Key("through", "point", "a point of the surface", example='["0 mm", "-30 mm"]',
            dimension="length", required=True),
        Key("direction", "quantity", "the surface's direction, CCW from +x; the wheel is on "
                                     "its left", example='"0 deg"', dimension="angle",
            required=True),
        Key("on", "label", "the surface moves: it is carried by the block (plate, rack) of "
                           "this [sliders] point, translating on a fixed guide ∥ the "
                           "surface; ω = (v_surface − v_W)/r along the direction (omitted: "
                           "the frame)", example='"S"'),
        Key("opposite", "label", "a cylinder between two plates: a second plate, the block "
                                 "of this [sliders] point (guide ∥ the surface), touches the "
                                 "wheel 2r from the first surface. The wheel is then placed "
                                 "by the two plates (no link may join its centre): 'through' "
                                 "is its contact with the first surface, v_W = (v₁ + v₂)/2, "
                                 "ω = (v₁ − v₂)/2r", example='"T"'),
        Key("rim", "table", "points of the wheel asked about, as books name them ('the "
                            "point A at the top of the wheel'): label = its angle about the "
                            "centre, CCW from +x, on the rim; or label = { angle = ..., "
                            "distance = ... } off the rim (a hub, a spoke). v(A), a(A), "
                            "dir_v(A) ... of these labels are then results",
            example='{ A = "90 deg", B = { angle = "0 deg", distance = "30 mm" } }'),
        Key("opposite_velocity", "quantity", "the second plate moved at a stated velocity, "
                                             "as books give it ('the upper plate moves at "
                                             "2 m/s to the left'): signed along `direction`; "
                                             "`opposite` is then only the plate's name (not "
                                             "a [sliders] block)", example='"-2 m/s"',
            dimension="velocity"),
        Key("opposite_acceleration", "quantity", "with opposite_velocity: the second plate's "
                                                 "acceleration, signed along `direction`",
            example='"0 m/s^2"', dimension="acceleration", default="0 m/s^2"),
    ), many=True),
    Table("bearing", "A bar bearing on a fixed circle (a bar leaning on a half-cylinder): "
                     "the bar stays tangent, the contact slides along it. The table's label "
                     "is the circle's centre (a [ground] point); the equivalent: that centre "
                     "slides in a slot ∥ the bar at the radius from it.", (
        Key("bar", "link", "the bar (a [links] entry) from its first label; its length may "
                           "be left out when its first label is the slider driver (placed by "
                           "this bar's angle or at a position) or a fixed pivot: its far end "
                           "is then its point touching the circle at this instant",
            example='"AQ"', required=True),
        Key("radius", "quantity", "the circle's radius", example='"100 mm"',
            dimension="length", required=True),
        Key("side", "string", "the side of the bar, looking from its first label to its "
                              "second, on which the circle lies: 'left' or 'right'",
            example='"right"', required=True),
    ), many=True),
)

#: the scene tables this module rewrites
NAMES = CONTACT_TABLES
#: the table each kind of :class:`Equivalent` is stated in
TABLE_OF = {"curved slot": "curved_slots", "cam": "cams", "flat-faced cam": "cams",
            "rolling": "rolling", "bearing": "bearing"}
#: the force tables a scene with contacts cannot carry yet
FORCE_TABLES = ("masses", "forces", "torques", "springs", "gravity", "dynamics",
                "force_answers", "flywheel", "efficiency")




@dataclass(frozen=True)
class Equivalent:
    """One contact replaced by its equivalent: ``kind`` 'curved slot' | 'cam' (roller) |
    'flat-faced cam'; ``at`` the pin / roller centre / follower; ``centre`` the centre of
    curvature; ``link`` the equivalent link's name (None for the flat face: a yoke);
    ``length`` the equivalent link's length (m); ``radius``/``roller`` as stated."""

    kind: str
    at: str
    centre: str
    link: str | None
    length: float | None
    radius: float
    roller: float | None = None
    face: float | None = None       # a flat face's / rolling surface's angle; bearing: side
    surface: tuple | None = None    # a point of a rolling surface
    on: str | None = None           # rolling: the slider carrying the surface (None: frame)
    opposite: str | None = None     # rolling: the slider carrying a second plate
    #: rolling: the second plate's stated (velocity, acceleration) along ``face`` when it is
    #: not a block of the linkage (books: "the upper plate moves at 2 m/s")
    opposite_motion: tuple[float, float] | None = None
    #: rolling: the wheel's named points, (label, angle CCW from +x about the centre, distance)
    rim: tuple[tuple[str, float, float], ...] = ()
    #: rolling: the wheel is the input ([driver] wheel = label): its rim points may carry pins
    driven: bool = False
    #: an oscillating flat-faced follower's arm (its face along it; ``face`` then ±1: the
    #: cam's side, left / right)
    arm: str | None = None

    @property
    def words(self) -> str:
        if self.kind == "rolling" and self.opposite:
            first = f"the plate of {self.on}" if self.on else "the fixed surface"
            return (f"the cylinder {self.at} (radius {self.radius * 1000:.6g} mm) rolls "
                    f"without slipping between {first} and the plate of {self.opposite} "
                    f"(at {math.degrees(self.face):.6g}°): the two no-slip conditions give "
                    f"v_{self.at} = (v₁ + v₂)/2 and ω = (v₁ − v₂)/2r along the plates; its "
                    f"instant centre lies on the line of the contact points")
        if self.kind == "rolling" and self.on:
            return (f"the wheel {self.at} (radius {self.radius * 1000:.6g} mm) rolls without "
                    f"slipping on the plate of {self.on} (surface at "
                    f"{math.degrees(self.face):.6g}°, translating along itself): its centre "
                    f"moves on the line ∥ the surface {self.radius * 1000:.6g} mm from it "
                    f"(the equivalent slider), ω = (v_{self.on} − v_{self.at})/r; its instant "
                    f"centre relative to the plate is the contact point")
        if self.kind == "rolling":
            return (f"the wheel {self.at} (radius {self.radius * 1000:.6g} mm) rolls without "
                    f"slipping on the fixed surface at {math.degrees(self.face):.6g}°: its "
                    f"centre moves on the line ∥ the surface {self.radius * 1000:.6g} mm from "
                    f"it (the equivalent slider), its instant centre is the contact point")
        if self.kind == "bearing":
            return (f"the bar {self.link} bears on the fixed circle about {self.at} (radius "
                    f"{self.radius * 1000:.6g} mm): {self.at} slides in the equivalent slot ∥ "
                    f"the bar, {self.radius * 1000:.6g} mm from it")
        if self.kind == "curved slot":
            return (f"the pin {self.at} in the circular slot (centre of curvature {self.centre}, "
                    f"radius {self.radius * 1000:.6g} mm) moves at this instant as the "
                    f"equivalent link {self.link} = {self.length * 1000:.6g} mm")
        if self.kind == "cam":
            return (f"the roller {self.at} (radius {self.roller * 1000:.6g} mm) on the cam arc "
                    f"(centre of curvature {self.centre}, radius {self.radius * 1000:.6g} mm) "
                    f"moves at this instant as the equivalent link {self.link} = "
                    f"{self.length * 1000:.6g} mm")
        if self.arm is not None:
            return (f"the flat face of the arm {self.arm} on the cam arc (centre of curvature "
                    f"{self.centre}, radius {self.radius * 1000:.6g} mm) moves at this instant "
                    f"as the crank and slotted lever: {self.centre} slides in a slot of "
                    f"{self.arm} ∥ the face, {self.radius * 1000:.6g} mm from it")
        return (f"the flat face of {self.at} (at {math.degrees(self.face):.6g}°) on the cam arc "
                f"(centre of curvature {self.centre}, radius {self.radius * 1000:.6g} mm) moves "
                f"at this instant as a Scotch yoke: {self.centre} slides in a slot ∥ the face "
                f"carried by {self.at}")


def _q(value, dim, file, where):
    try:
        return parse_quantity(value, dim)
    except SceneError as exc:
        raise exc.located(file=file, where=where) from None
    except Exception:   # noqa: BLE001 - any unreadable value: one line naming the key
        raise SceneError(f"cannot read {value!r} as a {dim}", file=file, where=where) from None


def _label(value, file, where) -> str:
    """A point label (a capital letter, then lower-case letters or digits), else refused in
    one short line (the user's text shown cut)."""
    if not isinstance(value, str) or not LABEL.match(value):
        raise SceneError(f"{show(value)} is not a point label (a capital letter followed by "
                         f"lower-case letters or digits, e.g. 'C' or 'O2')", file=file,
                         where=where)
    return value


def _entry(table, name, label, file):
    _label(label, file, name)
    where = f"{name}.{label}"
    if not isinstance(table, dict):
        raise SceneError(f"[{where}] must be a table", file=file, where=where)
    keys = {k.name for t in TABLES if t.name == name for k in t.keys}
    for k in table:
        if k not in keys:
            raise SceneError(f"unknown key {k!r}: one of {', '.join(sorted(keys))}",
                             file=file, where=f"{where}.{k}")
    if "centre" not in table or "radius" not in table:
        what = "the slot's centre of curvature and radius" if name == "curved_slots" else \
            "the profile's centre of curvature and radius of curvature at the contact"
        raise SceneError(f"the equivalent linkage needs {what} (centre = ..., radius = ...): "
                         f"without the curvature at the contact the instant's accelerations "
                         f"are not defined by this construction", file=file, where=where)
    centre = _label(table["centre"], file, f"{where}.centre")
    radius = _q(table["radius"], "length", file, f"{where}.radius")
    if not (radius > 0 and math.isfinite(radius)):
        raise SceneError("radius must be positive", file=file, where=f"{where}.radius")
    return where, centre, radius


def rewrite(data: dict, file: str) -> tuple[dict, tuple[Equivalent, ...]]:
    """``data`` with [curved_slots] and [cams] replaced by their equivalent links and yokes."""
    if not any(name in data for name in NAMES):
        return data, ()
    data = dict(data)
    raw = {name: data.pop(name, {}) for name in NAMES}
    force = [t for t in FORCE_TABLES if t in data]
    links = dict(data.get("links", {})) if isinstance(data.get("links", {}), dict) else None
    if links is None:
        raise SceneError("[links] must be a table", file=file, where="links")
    sliders = dict(data.get("sliders", {})) if isinstance(data.get("sliders", {}), dict) \
        else data.get("sliders")
    out: list[Equivalent] = []
    slots = dict(data.get("slots", {})) if isinstance(data.get("slots", {}), dict) else None
    drv = data.get("driver")
    if isinstance(drv, dict) and "wheel" in drv and not isinstance(drv["wheel"], str):
        raise SceneError(f"wheel must be the label of a [rolling] wheel, got "
                         f"{show(drv['wheel'])}", file=file, where="driver.wheel")
    wheel = _driven(data)
    if wheel is not None and not (isinstance(raw["rolling"], dict) and wheel in raw["rolling"]):
        raise SceneError(f"wheel = {show(wheel)} must name a [rolling] wheel", file=file,
                         where="driver.wheel")
    for name in ("rolling", "bearing"):
        if not isinstance(raw[name], dict):
            raise SceneError(f"[{name}] must be a table of labels", file=file, where=name)
        for label, table in raw[name].items():
            out.append(_higher(name, label, table, file, sliders, slots, links, data))
    if _driven(data) is not None:
        data["driver"] = _wheel_driver(data["driver"], out, file)
    if slots:
        data["slots"] = slots
    for name in ("curved_slots", "cams"):
        if not isinstance(raw[name], dict):
            raise SceneError(f"[{name}] must be a table of labels", file=file, where=name)
        for label, table in raw[name].items():
            where, centre, radius = _entry(table, name, label, file)
            if centre == label:
                raise SceneError("the centre of curvature must differ from the contact's point",
                                 file=file, where=f"{where}.centre")
            follower = table.get("follower", "roller") if name == "cams" else None
            if follower not in (None, "roller", "flat"):
                raise SceneError(f"follower must be 'roller' or 'flat', got {follower!r}",
                                 file=file, where=f"{where}.follower")
            if follower == "flat" and "arm" in table:
                out.append(_flat_arm(table, label, centre, radius, links, slots, data, file,
                                     where))
                continue
            if any(k in table for k in ("side", "face_offset")):
                raise SceneError("side and face_offset are for an oscillating flat-faced "
                                 "follower (arm = \"QF\")", file=file, where=where)
            if "arm" in table:
                raise SceneError("arm is for a flat-faced follower (follower = \"flat\")",
                                 file=file, where=f"{where}.arm")
            if follower == "flat":
                if "face" not in table:
                    raise SceneError("a flat-faced follower needs face = \"<angle>\" (the "
                                     "face's direction)", file=file, where=f"{where}.face")
                if "roller" in table or table.get("concave"):
                    raise SceneError("roller and concave are for a roller follower",
                                     file=file, where=where)
                face = _q(table["face"], "angle", file, f"{where}.face")
                g = sliders.get(label) if isinstance(sliders, dict) else None
                if not isinstance(g, dict):
                    raise SceneError(f"a flat-faced follower {label} slides on a fixed guide: "
                                     f"state it as [sliders.{label}] (through, direction)",
                                     file=file, where=where)
                if "pin" in g or "slot" in g:
                    raise SceneError(f"[sliders.{label}] already carries a slot", file=file,
                                     where=f"sliders.{label}")
                g = dict(g)
                g["pin"] = centre
                g["slot"] = f"{math.degrees(face)!r} deg"
                sliders[label] = g
                out.append(Equivalent("flat-faced cam", label, centre, None, None, radius,
                                      face=face))
                continue
            length = radius
            roller = None
            if name == "cams":
                if "face" in table:
                    raise SceneError("face is for a flat-faced follower (follower = \"flat\")",
                                     file=file, where=f"{where}.face")
                if "roller" not in table:
                    raise SceneError("a roller follower needs roller = \"<radius>\" (the "
                                     "roller's radius)", file=file, where=f"{where}.roller")
                roller = _q(table["roller"], "length", file, f"{where}.roller")
                concave = table.get("concave", False)
                if not isinstance(concave, bool):
                    raise SceneError("concave must be true or false", file=file,
                                     where=f"{where}.concave")
                if not (roller >= 0 and math.isfinite(roller)):
                    raise SceneError("roller must be zero or positive", file=file,
                                     where=f"{where}.roller")
                length = radius - roller if concave else radius + roller
                if not length > 0:
                    raise SceneError("a roller on a concave arc must be smaller than the arc "
                                     "(radius − roller > 0)", file=file, where=where)
            link = centre + label
            if link in links or label + centre in links:
                raise SceneError(f"the equivalent link {link} is already in [links]",
                                 file=file, where=where)
            links[link] = f"{length!r} m"
            out.append(Equivalent("curved slot" if name == "curved_slots" else "cam", label,
                                  centre, link, length, radius, roller))
    data["links"] = links
    if slots:
        data["slots"] = slots
    if isinstance(sliders, dict) and sliders:
        data["sliders"] = sliders
    for q in out if force else ():
        if q.kind == "bearing" or (q.kind == "rolling" and (q.on or q.opposite or q.driven)):
            what = ("a bar bearing on a circle" if q.kind == "bearing" else
                    "a wheel driving the linkage" if q.driven else
                    "a wheel rolling on a moving plate or between plates")
            raise UnsupportedError(f"polygons forces does not handle a rolling contact "
                                   f"([{force[0]}] with {what}, {q.at}): only a wheel rolling "
                                   f"on a fixed surface, its friction at the contact found",
                                   file=file, where=force[0])
    return data, tuple(out)


def _flat_arm(table, label, centre, radius, links, slots, data, file, where) -> "Equivalent":
    """[cams.F] follower = "flat", arm = "QF": a flat face along an arm pivoted at Q.  The cam's
    centre of curvature C stays at the radius from the face, so at the instant C moves as a
    pin in a slot of the arm ∥ the face, offset by face_offset ± radius (the cam's side): the
    equivalent is the crank and slotted lever (RPR with an offset slot)."""
    if "face" in table:
        raise SceneError("an arm's face runs along the arm: give arm or face, not both",
                         file=file, where=f"{where}.face")
    if "roller" in table or table.get("concave"):
        raise SceneError("roller and concave are for a roller follower", file=file, where=where)
    arm = table["arm"]
    if not isinstance(arm, str) or arm not in links:
        raise SceneError(f"arm must be a link of [links] (the follower's arm, pivot first), got "
                         f"{arm!r}", file=file, where=f"{where}.arm")
    ends = [(arm[:i], arm[i:]) for i in range(1, len(arm))]
    ground = data.get("ground", {}) if isinstance(data.get("ground"), dict) else {}
    ends = [(a, b) for a, b in ends if a in ground and b == label]
    if not ends:
        raise SceneError(f"the arm {arm} must run from a fixed pivot in [ground] to the "
                         f"follower's label {label}", file=file, where=f"{where}.arm")
    side = table.get("side")
    if side not in ("left", "right"):
        raise SceneError(f"side must be 'left' or 'right' (where the cam lies, looking along "
                         f"the arm from its pivot), got {side!r}", file=file,
                         where=f"{where}.side")
    if slots is None or centre in slots:
        raise SceneError(f"{centre} is already a pin in [slots]", file=file, where=where)
    e = _q(table.get("face_offset", "0 mm"), "length", file, f"{where}.face_offset")
    off = e + (radius if side == "left" else -radius)
    coincident = _fresh(centre, data)
    slots[centre] = {"lever": arm, "coincident": coincident, "offset": f"{off!r} m"}
    return Equivalent("flat-faced cam", label, centre, None, None, radius, arm=arm,
                      face=1.0 if side == "left" else -1.0)


def _check_keys(table, name, label, file):
    _label(label, file, name)
    where = f"{name}.{label}"
    if not isinstance(table, dict):
        raise SceneError(f"[{where}] must be a table", file=file, where=where)
    keys = {k.name: k for t in TABLES if t.name == name for k in t.keys}
    for k in table:
        if k not in keys:
            raise SceneError(f"unknown key {k!r}: one of {', '.join(sorted(keys))}",
                             file=file, where=f"{where}.{k}")
    for k, key in keys.items():
        if key.required and k not in table:
            raise SceneError(f"missing key {k!r} ({key.doc})", file=file, where=where)
    return where


def _higher(name, label, table, file, sliders, slots, links, data) -> Equivalent:
    """[rolling.W] → a slider W on the line ∥ the surface; [bearing.K] → K in an offset slot
    of the bar."""
    where = _check_keys(table, name, label, file)
    radius = _q(table["radius"], "length", file, f"{where}.radius")
    if not (radius > 0 and math.isfinite(radius)):
        raise SceneError("radius must be positive", file=file, where=f"{where}.radius")
    if name == "rolling":
        if not isinstance(sliders, dict) or label in sliders:
            raise SceneError(f"the wheel's centre {label} is also in [sliders]: the rolling "
                             f"contact places it", file=file, where=where)
        pt = table["through"]
        if not (isinstance(pt, list) and len(pt) == 2):
            raise SceneError("through must be [x, y] with units", file=file,
                             where=f"{where}.through")
        x, y = (_q(v, "length", file, f"{where}.through") for v in pt)
        ang = _q(table["direction"], "angle", file, f"{where}.direction")
        nx, ny = -math.sin(ang), math.cos(ang)
        motion = None
        if "opposite_velocity" in table:
            name_ = table.get("opposite")
            if not (isinstance(name_, str) and LABEL.match(name_)):
                raise SceneError("opposite_velocity moves the second plate: name it with a "
                                 "label, opposite = \"T\" (a capital letter, then letters or "
                                 "digits)", file=file, where=f"{where}.opposite")
            motion = (_q(table["opposite_velocity"], "velocity", file,
                         f"{where}.opposite_velocity"),
                      _q(table.get("opposite_acceleration", "0 m/s^2"), "acceleration", file,
                         f"{where}.opposite_acceleration"))
        elif "opposite_acceleration" in table:
            raise SceneError("opposite_acceleration needs opposite_velocity (the second "
                             "plate's stated motion)", file=file,
                             where=f"{where}.opposite_acceleration")
        plates = {k: (table["opposite"] if k == "opposite" and motion is not None
                      else _plate(table, k, label, ang, sliders, file, where))
                  for k in ("on", "opposite")}
        if motion is not None and (plates["opposite"] == label
                                   or (isinstance(sliders, dict) and plates["opposite"] in sliders)):
            raise SceneError(f"opposite = {plates['opposite']!r} with opposite_velocity names "
                             f"a plate moved at a stated rate: a label of its own, not the "
                             f"wheel's or a [sliders] block's", file=file,
                             where=f"{where}.opposite")
        if plates["on"] is not None and plates["on"] == plates["opposite"]:
            raise SceneError("on and opposite must be two different plates", file=file,
                             where=f"{where}.opposite")
        if plates["opposite"] is None:
            sliders[label] = {"through": [f"{x + radius * nx!r} m", f"{y + radius * ny!r} m"],
                              "direction": f"{math.degrees(ang)!r} deg"}
        else:
            joined = [k for k in links if isinstance(k, str) and label in _ends(k)]
            pts = data.get("points", {})
            if joined or (isinstance(pts, dict) and label in pts):
                what = f"the link {joined[0]}" if joined else "[points]"
                raise SceneError(f"the cylinder {label} between two plates is placed by them "
                                 f"(no slip at both contacts); it cannot also be in {what}",
                                 file=file, where=where)
        return Equivalent("rolling", label, label, None, None, radius,
                          face=ang, surface=(x, y), on=plates["on"],
                          opposite=plates["opposite"], opposite_motion=motion,
                          rim=_rim(table.get("rim", {}), label, radius, data, sliders, file,
                                   where, driven=_driven(data) == label),
                          driven=_driven(data) == label)
    bar, side = table["bar"], table["side"]
    if side not in ("left", "right"):
        raise SceneError(f"side must be 'left' or 'right', got {side!r}", file=file,
                         where=f"{where}.side")
    ground = data.get("ground", {})
    if not isinstance(ground, dict) or label not in ground:
        raise SceneError(f"the circle's centre {label} must be a [ground] point (a fixed "
                         f"circle)", file=file, where=where)
    if isinstance(bar, str) and bar not in links and LINK_NAME.match(bar):
        links[bar] = f"{_bar_to_contact(bar, label, radius, side, data, file, where)!r} m"
    if not isinstance(bar, str) or bar not in links:
        raise SceneError(f"bar must be a link of [links], got {bar!r}", file=file,
                         where=f"{where}.bar")
    if slots is None or label in slots:
        raise SceneError(f"{label} is already in [slots]", file=file, where=where)
    coincident = _fresh(label, data)
    off = radius if side == "left" else -radius
    slots[label] = {"lever": bar, "coincident": coincident, "offset": f"{off!r} m"}
    return Equivalent("bearing", label, label, bar, None, radius, roller=None,
                      face=1.0 if side == "left" else -1.0, surface=None)


def wheel_of(scene, label):
    """The [rolling] entry whose wheel (centre) is ``label``, or None."""
    return next((q for q in getattr(scene, "equivalents", ())
                 if q.kind == "rolling" and q.at == label), None)


def _fresh(base: str, data) -> str:
    """A label ``base`` + digits that the scene does not use (the point under a pin)."""
    n = 1
    while f"{base}{n}" in str(data):
        n += 1
    return f"{base}{n}"


def _driven(data) -> str | None:
    """The label of the wheel the scene drives ([driver] wheel = "W"), else None."""
    drv = data.get("driver")
    return drv.get("wheel") if isinstance(drv, dict) and isinstance(drv.get("wheel"), str) \
        else None


def _wheel_driver(drv: dict, eqs, file) -> dict:
    """[driver] wheel = "W", omega, sense (alpha, alpha_sense): the wheel rolling on a fixed
    surface turns at ω, α; its centre is then the input slider on the equivalent guide,
    v_W = ω k × (W − C) = −ω r along the surface, a_W = −α r (C the contact).  Or, as books
    state it ('its centre moves at 2 m/s to the right, accelerating at 4 m/s²'), the centre's
    ``velocity`` and ``acceleration`` along the surface's direction: ω = −v / r, α = −a / r."""
    label = drv["wheel"]
    q = next((e for e in eqs if e.kind == "rolling" and e.at == label), None)
    if q is None:
        raise SceneError(f"wheel = {show(label)} must name a [rolling] wheel", file=file,
                         where="driver.wheel")
    if q.on is not None or q.opposite is not None:
        raise SceneError(f"the driven wheel {label} rolls on a fixed surface here: on and "
                         f"opposite (moving plates) are not handled with a wheel driver",
                         file=file, where="driver.wheel")
    extra = set(drv) - {"wheel", "omega", "sense", "alpha", "alpha_sense", "velocity",
                        "acceleration"}
    if extra:
        raise SceneError(f"a wheel driver takes wheel, omega, sense, alpha, alpha_sense (or its "
                         f"centre's velocity and acceleration); not "
                         f"{', '.join(sorted(map(show, extra)))}", file=file, where="driver")
    if "velocity" in drv or "acceleration" in drv:
        mixed = sorted({"omega", "sense", "alpha", "alpha_sense"} & set(drv))
        if mixed or "velocity" not in drv:
            raise SceneError("give the wheel's omega (sense, alpha) or its centre's velocity "
                             "(and acceleration) along the surface, not both"
                             + (f": drop {', '.join(mixed)}" if mixed else ""),
                             file=file, where="driver")
        from .units import parse_along    # '2 m/s to the right' along the surface
        e = (math.cos(q.face), math.sin(q.face))
        v = parse_along(drv["velocity"], "velocity", e, file=file, where="driver.velocity")
        a = parse_along(drv.get("acceleration", "0 m/s^2"), "acceleration", e, file=file,
                        where="driver.acceleration")
        return {"slider": label, "position": "0 m", "velocity": f"{v!r} m/s",
                "acceleration": f"{a!r} m/s^2"}
    from .senses import alpha_words, sense_in, turn_word

    def rate(key, sense_key, dim):
        if key not in drv:
            return 0.0
        text, turn = sense_in(drv[key])
        value = _q(text, dim, file, f"driver.{key}")
        if sense_key in drv:
            said = turn_word(drv[sense_key])
            if said is None or (turn is not None and turn != said):
                raise SceneError(f"{sense_key} must be 'CW' or 'CCW' (once)", file=file,
                                 where=f"driver.{sense_key}")
            turn = said
        if value < 0 or (turn is None and value != 0):
            raise SceneError(f"give {key}'s magnitude and its sense in words ('4 rad/s CW')",
                             file=file, where=f"driver.{key}")
        return value * int(turn or 0)
    w = rate("omega", "sense", "angular_velocity")
    drv = alpha_words(drv, w, file)      # 'retarding': against ω
    al = rate("alpha", "alpha_sense", "angular_acceleration")
    r = q.radius
    return {"slider": label, "position": "0 m", "velocity": f"{-w * r!r} m/s",
            "acceleration": f"{-al * r!r} m/s^2"}


def _rim(raw, wheel, radius, data, sliders, file, where, driven=False) -> tuple:
    """[rolling.W] rim = { A = "90 deg", B = { angle = "0 deg", distance = "30 mm" } }: the
    wheel's named points (angle CCW from +x about the centre; on the rim unless a distance
    is given), checked: labels of their own."""
    if not isinstance(raw, dict):
        raise SceneError('rim must be a table: rim = { A = "90 deg" }', file=file,
                         where=f"{where}.rim")
    used = set()
    for table in ("ground", "drawn", "points", "slots", "crossing"):
        t = data.get(table)
        if isinstance(t, dict):
            used |= set(t)
    used |= set(sliders) if isinstance(sliders, dict) else set()
    if not driven:      # a driven wheel's rim points may be the ends of links (its pins)
        for name in data.get("links", {}) if isinstance(data.get("links", {}), dict) else ():
            if isinstance(name, str):
                used |= set(_ends(name))
    out = []
    for label, spec in raw.items():
        at = f"{where}.rim.{label}"
        if not (isinstance(label, str) and LABEL.match(label)):
            raise SceneError(f"a rim point's label must be a capital letter with lower-case "
                             f"letters or digits, got {show(label)}", file=file,
                             where=f"{where}.rim")
        if label == wheel or label in used:
            raise SceneError(f"{label} is already a point of the mechanism: a wheel's point "
                             f"needs a label of its own", file=file, where=at)
        if isinstance(spec, dict):
            extra = set(spec) - {"angle", "distance"}
            if extra or "angle" not in spec:
                raise SceneError("a wheel point off the rim is { angle = \"30 deg\", "
                                 "distance = \"20 mm\" }", file=file, where=at)
            angle = _q(spec["angle"], "angle", file, f"{at}.angle")
            dist = _q(spec.get("distance", f"{radius!r} m"), "length", file, f"{at}.distance")
            if not (0 <= dist <= 1e3 * radius and math.isfinite(dist)):
                raise SceneError("distance must be zero or positive, at most 1000 radii",
                                 file=file, where=f"{at}.distance")
        else:
            angle, dist = _q(spec, "angle", file, at), radius
        out.append((label, angle, dist))
    return tuple(out)


def _ends(link: str) -> tuple[str, ...]:
    """The labels a link's name may join (AW → A, W; O2A → O2, A): every split point."""
    return tuple(link[:i] for i in range(1, len(link))) + \
        tuple(link[i:] for i in range(1, len(link)))


def _plate(table, key, label, ang, sliders, file, where):
    """The [sliders] point carrying a moving surface (``on``/``opposite``), checked: a block
    on a fixed straight guide parallel to the surface."""
    name = table.get(key)
    if name is None:
        return None
    if not isinstance(name, str) or not isinstance(sliders, dict) or name not in sliders:
        raise SceneError(f"{key} must name a [sliders] point (the block carrying the plate), "
                         f"got {name!r}", file=file, where=f"{where}.{key}")
    if name == label:
        raise SceneError(f"{key} must be the plate's block, not the wheel's centre", file=file,
                         where=f"{where}.{key}")
    g = sliders[name]
    if not isinstance(g, dict) or "pin" in g or "slot" in g or "direction" not in g:
        raise SceneError(f"the plate {name} must be a block on a fixed straight guide "
                         f"([sliders.{name}] through, direction)", file=file,
                         where=f"{where}.{key}")
    d = _q(g["direction"], "angle", file, f"sliders.{name}.direction")
    if abs(math.sin(d - ang)) > 1e-9:
        raise SceneError(f"the plate {name} must slide along the surface (its guide at "
                         f"{math.degrees(d):.6g}°, the surface at {math.degrees(ang):.6g}°): a "
                         f"plate moving across the surface would not keep touching the wheel",
                         file=file, where=f"{where}.{key}")
    return name


def report_lines(sol) -> list[str]:
    """The equivalences and the follower's (pin's) velocity and acceleration."""
    eqs = getattr(sol.scene, "equivalents", ())
    if not eqs:
        return []
    cam = any(q.kind in ("cam", "curved slot", "flat-faced cam") for q in eqs)
    lines = ["Equivalent linkage at this instant (valid here only: for velocity, "
             + ("acceleration and the frictionless contact's force along the common normal):"
                if cam else "acceleration):")]
    for q in eqs:
        lines.append(f"  {q.words}")
        p = sol.points.get(q.at)
        if p is not None and p.velocity is not None:
            v = math.hypot(*p.velocity)
            text = f"    {q.at}: |v| = {v:.6g} m/s"
            if p.acceleration is not None:
                text += f", |a| = {math.hypot(*p.acceleration):.6g} m/s²"
            lines.append(text)
        h = higher(sol, q)
        if h is None:
            continue
        mm = lambda p: f"({p[0] * 1000:.6g}, {p[1] * 1000:.6g}) mm"   # noqa: E731
        def sense(x):
            return "CCW" if x > 0 else ("CW" if x < 0 else "")
        if q.kind == "rolling" and (q.on or q.opposite):
            lines += _moving_lines(q, h, mm, sense)
        elif q.kind == "rolling":
            lines.append(f"    wheel {q.at}: ω = v/r = {abs(h['omega']):.6g} rad/s "
                         f"{sense(h['omega'])}" + (f", α = a/r = {abs(h['alpha']):.6g} rad/s² "
                                                    f"{sense(h['alpha'])}" if 'alpha' in h
                                                    else ""))
            lines.append(f"    instant centre of the wheel: the contact point "
                         f"{mm(h['instant_centre'])}" + (
                             f"; the wheel's point there accelerates at r·ω² = "
                             f"{math.hypot(*h['contact_acceleration']):.6g} m/s² towards "
                             f"{q.at}" if "contact_acceleration" in h else ""))
        elif q.kind == "bearing":
            lines += _bearing_lines(q, h, mm)
        elif q.kind == "curved slot":
            lines.append(f"    the pin {q.at} slides in the slot (cut in {h['slot_body']}) at "
                         f"{abs(h['sliding_velocity']):.6g} m/s relative to it "
                         f"({q.link}·(ω_{q.link} − ω of the slot's body))")
        elif q.kind == "cam":
            lines.append(f"    contact with the profile at {mm(h['contact'])}; the roller's "
                         f"centre moves relative to the cam ({h['cam_body']}) at "
                         f"{abs(h['follower_velocity_relative']):.6g} m/s, the contact point "
                         f"over the profile at {abs(h['contact_velocity_along_profile']):.6g} m/s")
        lines += _rim_lines(sol, q, mm)
    return lines


def to_list(sol) -> list[dict]:
    out = []
    for q in getattr(sol.scene, "equivalents", ()):
        d = {"kind": q.kind, "at": q.at, "centre": q.centre, "link": q.link,
             "length_m": q.length, "radius_m": q.radius, "roller_m": q.roller,
             "face_rad": q.face, "on": q.on, "opposite": q.opposite}
        if q.rim:
            d["rim"] = []
            for label, angle, dist in q.rim:
                got = wheel_point(sol, q, label)
                d["rim"].append({"label": label, "angle_rad": angle, "distance_m": dist,
                                 **({"position": list(got[0]), "velocity": list(got[1]),
                                     "acceleration": list(got[2]) if got[2] else None}
                                    if got else {})})
        if q.opposite_motion is not None:
            d["opposite_motion"] = {"velocity": q.opposite_motion[0],
                                    "acceleration": q.opposite_motion[1]}
        h = higher(sol, q)
        if h:
            d["higher_pair"] = {k: (list(v) if isinstance(v, tuple) else v)
                                for k, v in h.items()}
        out.append(d)
    return out


__all__ = ["TABLES", "Equivalent", "rewrite", "report_lines", "to_list", "rolling",
           "wheel_centres", "wheel_point", "wheel_of"]
