"""Scene layer for the mechanisms beyond the slider-crank and four-bar (issue 10): the keys
that state a second input, a lever drive, an offset slot and a crank angle from a dead centre.

    [driver]
    crank = "OA"                      # the rod turns at ω, α ...
    omega = "5 rad/s"
    [driver.slide]                    # ... and the collar C is moved along it (a second input)
    point = "C"
    along = "OA"                      # the link it slides on; position measured from O
    position = "300 mm"
    velocity = "1.5 m/s"              # ṡ, positive from O towards A
    acceleration = "-0.8 m/s^2"       # s̈ ("slowing at 0.8 m/s²" while moving out)
    coincident = "C1"                 # the rod's point under the collar (default C1)

    [driver]
    lever = "O4Q"                     # the slotted lever (cylinder) drives: a crank whose
                                      # link carries a slot (needs [slots.P] lever = "O4Q")
    [slots.P]
    lever = "BQ"
    offset = "20 mm"                  # the slot runs parallel to BQ, 20 mm to its left

    [driver]
    angle = "30 deg from idc"         # a slider-crank's crank angle from inner / outer dead
                                      # centre, in the crank's sense of rotation

Parsed here and called from :mod:`polygons.scene` (a few lines there); the records live here
so the loader stays small.  This module imports nothing from the rest of the package except
the schema and the errors.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .errors import SceneError, UnknownLabelError, suggest
from .schema import Key, Table


@dataclass(frozen=True)
class Slide:
    """A prescribed slide (a second input): ``point`` is moved along link ``link`` (ends
    ``p`` → ``q``) at distance ``position`` from ``p``, with sliding velocity ``velocity`` and
    acceleration ``acceleration`` signed from ``p`` towards ``q``; ``coincident`` is the
    link's point under it."""

    point: str
    link: str
    p: str
    q: str
    coincident: str
    position: float
    velocity: float
    acceleration: float


TABLES: tuple[Table, ...] = (
    Table("driver.slide", "A second input: a point (collar, block) moved along a link at a "
          "prescribed sliding velocity and acceleration while the link moves as the driver "
          "makes it.", (
              Key("point", "label", "the sliding point", "C", required=True),
              Key("along", "link", "the link it slides on (position measured from its first "
                  "label)", "OA", required=True),
              Key("position", "quantity", "distance from the link's first label", "300 mm",
                  dimension="length", required=True),
              Key("velocity", "quantity", "sliding velocity", "1.5 m/s",
                  dimension="velocity", required=True,
                  sign="positive from the link's first label towards its second"),
              Key("acceleration", "quantity", "sliding acceleration", "-0.8 m/s^2",
                  dimension="acceleration", default="0 m/s^2",
                  sign="positive from the link's first label towards its second"),
              Key("coincident", "label", "the link's point under the sliding point", "C1"),
          )),
    Table("driver", "Keys of the input added for the inverted slider-crank and dead-centre "
          "angles (the rest of [driver] is read by polygons.scene).", (
              Key("lever", "link", "a slotted lever driven like a crank (the oscillating "
                  "cylinder, the rotary engine): needs a length in [links] and [slots.PIN] "
                  "lever = this lever", "O4Q"),
              Key("angle", "string", "crank angle; also 'θ from idc' / 'θ from odc' for a "
                  "slider-crank (inner / outer dead centre, θ in the crank's sense of "
                  "rotation)", "30 deg from idc"),
          )),
    Table("slots", "Key added to [slots.PIN] for a slot that does not pass through the "
          "lever's pivot.", (
              Key("offset", "quantity", "perpendicular distance of the slot line from the "
                  "lever's line (needs the lever's length in [links])", "20 mm",
                  dimension="length", default="0 mm", sign="positive to the left of the "
                  "lever's pivot → far end"),
          ), many=True),
)


_DEAD = re.compile(r"^\s*(.*?)\s+from\s+(idc|odc|inner dead cent(?:re|er)|"
                   r"outer dead cent(?:re|er))\s*$", re.IGNORECASE)


def default_coincident(point: str) -> str:
    """The conventional name of the point under ``point``: C → C1, P2 → P2'."""
    return f"{point}'" if point[-1].isdigit() else f"{point}1"


def parse_slide(spec, r, links, split_link_name) -> Slide:
    """``[driver.slide]`` → :class:`Slide` (``r`` is the scene reader)."""
    where = "driver.slide"
    r.table(spec, where, ("point", "along", "position", "velocity", "acceleration",
                          "coincident"), required=("point", "along", "position", "velocity"))
    point = r.label(spec["point"], where + ".point")
    along = r.string(spec["along"], where + ".along")
    p, q = split_link_name(along, file=r.file, where=where + ".along")
    if along not in links:
        if f"{q}{p}" in links:
            raise SceneError(f"link {along!r} is written {q}{p} in [links]; the slide's "
                             f"position is measured from the first label, so write along = "
                             f"\"{q}{p}\" with the position from {q}, or name the link {along} "
                             f"in [links]", file=r.file, where=where + ".along")
        raise UnknownLabelError(f"link {along!r} is not defined: {suggest(along, links)}",
                                file=r.file, where=where + ".along")
    if point in (p, q):
        raise SceneError(f"the sliding point {point} must not be an end of {along}",
                         file=r.file, where=where + ".point")
    coincident = r.label(spec.get("coincident", default_coincident(point)),
                         where + ".coincident")
    taken = {lab for link in links.values() for lab in (link.a, link.b)}
    for lab, key in ((point, "point"), (coincident, "coincident")):
        if lab in taken:
            raise SceneError(f"{lab} is already an end of a link; the sliding point and the "
                             f"point under it need labels of their own", file=r.file,
                             where=f"{where}.{key}")
    if coincident == point:
        raise SceneError("the point under the collar needs a label of its own",
                         file=r.file, where=where + ".coincident")
    return Slide(point, along, p, q, coincident,
                 r.quantity(spec["position"], "length", where + ".position"),
                 r.quantity(spec["velocity"], "velocity", where + ".velocity"),
                 r.quantity(spec.get("acceleration", "0 m/s^2"), "acceleration",
                            where + ".acceleration"))


def lever_as_crank(drv: dict, r, slots_raw) -> dict:
    """``[driver] lever = "O4Q"`` is a crank whose link carries a slot: return the driver table
    with ``crank`` in its place (after checking a slot is carried by that lever)."""
    if "lever" not in drv:
        return drv
    if "crank" in drv or "slider" in drv:
        raise SceneError("the driver is a crank, a slider or a lever: give exactly one",
                         file=r.file, where="driver")
    lever = r.string(drv["lever"], "driver.lever")
    levers = [s.get("lever") for s in slots_raw.values() if isinstance(s, dict)]
    if lever not in levers:
        raise SceneError(f"lever {lever!r} carries no slot: add [slots.PIN] lever = "
                         f"\"{lever}\" (or drive it as crank = \"{lever}\")", file=r.file,
                         where="driver.lever")
    out = {k: v for k, v in drv.items() if k != "lever"}
    out["crank"] = lever
    return out


def split_dead_centre(value):
    """'30 deg from idc' → ('30 deg', 'idc'); anything else → (value, None)."""
    if not isinstance(value, str):
        return value, None
    m = _DEAD.match(value)
    if not m:
        return value, None
    word = m.group(2).lower()
    return m.group(1), ("idc" if word.startswith("i") else "odc")


def dead_centre_angle(theta: float, which: str, sense: int, *, pivot, r_crank, rod, guide,
                      side, file) -> float:
    """The crank angle (CCW from +x) ``theta`` past inner ('idc') or outer ('odc') dead centre,
    turned in the crank's ``sense`` (+1 CCW, −1 CW).

    At the dead centres crank and rod are in line: the crank pin A lies on the line O→B with
    |OB| = L + r (inner: the crank points at the piston) or L − r (outer: away from it).
    B is on the guide through G along e:  B = F + t e,  F the foot of O on the guide,
    t = ±√(d² − h²), h = |OF|; ``side`` (+1 / −1) is the side of F the piston is on.
    """
    (gx, gy), e = guide
    ox, oy = pivot
    w = (ox - gx, oy - gy)
    along = w[0] * e[0] + w[1] * e[1]
    fx, fy = gx + along * e[0], gy + along * e[1]
    h = math.hypot(ox - fx, oy - fy)
    d = rod + r_crank if which == "idc" else rod - r_crank
    if d <= h:
        raise SceneError(f"no {which.upper()}: the crank and rod ({1e3 * d:.6g} mm in line) "
                         f"cannot reach the guide {1e3 * h:.6g} mm from the pivot", file=file,
                         where="driver.angle")
    t = side * math.sqrt(d * d - h * h)
    bx, by = fx + t * e[0] - ox, fy + t * e[1] - oy
    base = math.atan2(by, bx)
    if which == "odc":
        base += math.pi
    return base + sense * theta


def lever_driven(scene, slot) -> bool:
    """Whether the slotted lever of ``slot`` is the driver (a crank carrying a slot)."""
    return getattr(scene.driver, "link", None) == slot.lever


def slot_along_lever(scene, slot) -> bool:
    """Whether the slot's direction is the lever's pivot → far end (an offset slot, or a driven
    lever whose pin may lie on either side of the pivot) rather than pivot → pin."""
    return bool(slot.offset) or lever_driven(scene, slot)
