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
    length = "300 mm"                 # the slot ends 300 mm from B (unstated: open-ended)

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

from .errors import SceneError, UnknownLabelError, show, suggest
from .schema import Key, Table
from .senses import sense_in
from .units import cos_sin


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
    Table("crossing", "[crossing.P]: a pin P sliding in the straight slots of two moving "
          "levers at once (crossing slots): each lever is a link in [links] placed by the rest "
          "of the mechanism, its slot running along the link from its first label through its "
          "second (open-ended); P is where the two slots cross.", (
              Key("levers", "array", "the two slotted levers (links in [links])",
                  '["O2Q", "O4R"]', required=True),
              Key("coincident", "array", "each lever's point under P (default: P followed "
                  "by the lever's first label's digits, or P1 and P2)", '["P2", "P4"]'),
          ), many=True),
)


_FROM = re.compile(r"^\s*(.*?)\s+from\s+(.+?)\s*$", re.IGNORECASE)
_DEAD_WORDS = {"idc": "idc", "inner dead centre": "idc", "inner dead center": "idc",
               "tdc": "idc", "odc": "odc", "outer dead centre": "odc",
               "outer dead center": "odc", "bdc": "odc"}
_LINE = re.compile(r"[A-Z][a-z0-9_']*[A-Z][a-z0-9_']*\Z")     # \Z: no "AB\n"
#: the axes an angle may be measured from (the direction of each, CCW from +x)
_AXES = {"+x": 0.0, "x": 0.0, "-x": math.pi, "+y": math.pi / 2, "y": math.pi / 2,
         "-y": -math.pi / 2}
def crank_rate(drv, r, length) -> tuple[float, int | None]:
    """|ω| of a crank and its sense: ``omega``, or the crank pin's ``speed`` as books give it
    (v = ω r, so ω = v / |OA|)."""
    if ("omega" in drv) == ("speed" in drv):
        raise SceneError("give the crank's omega ('300 rad/s') or its pin's speed ('5 m/s'): "
                         "exactly one", file=r.file, where="driver")
    if "omega" in drv:
        return rate_with_sense(drv, "omega", "sense", "angular_velocity", r)
    v, turn = rate_with_sense(drv, "speed", "sense", "velocity", r)
    if not length:
        raise SceneError("speed needs the crank's length in [links] (ω = speed / length)",
                         file=r.file, where="driver.speed")
    return v / length, turn


def rate_with_sense(drv, key: str, sense_key: str, dimension: str, r) -> tuple[float, int | None]:
    """|ω| (or |α|) and its sense (+1 CCW, −1 CW, None when not stated): from ``sense_key`` or
    written after the value as books do ('300 rad/s CW', '120 rpm clockwise'); both may be
    given only if they agree."""
    text, written = sense_in(drv[key])
    value = r.quantity(text, dimension, f"driver.{key}")
    if value < 0:           # a magnitude: its sense is stated in words, never by a sign
        raise SceneError(f"{key} = {show(drv[key])} is negative: give its magnitude and its "
                         f"sense in words ('{key} = \"{show(text.strip().lstrip('-'))[1:-1]}\"' "
                         f"with {sense_key} = \"CW\" or \"CCW\")", file=r.file,
                         where=f"driver.{key}")
    if sense_key not in drv:
        return value, written
    turn = r.sense(drv[sense_key], f"driver.{sense_key}")
    if written is not None and written != turn:
        raise SceneError(f"{key} = {drv[key]!r} says {'CW' if written < 0 else 'CCW'} but "
                         f"{sense_key} = {drv[sense_key]!r}: give the sense once",
                         file=r.file, where=f"driver.{sense_key}")
    return value, turn


def ground_from(spec, r, where, ground) -> tuple[float, float]:
    """A fixed pivot placed from another, as books do ('D is 300 mm from A at 30°'):
    ``{ from = "A", distance = "300 mm", angle = "30 deg" }`` (CCW from +x, or '30 deg CW')."""
    r.table(spec, where, ("from", "distance", "angle"), required=("from", "distance", "angle"))
    frm = r.label(spec["from"], where + ".from")
    if frm not in ground:
        raise SceneError(f"{frm} must be a fixed pivot given before this one in [ground] "
                         f"({', '.join(ground) or 'none yet'})", file=r.file,
                         where=where + ".from")
    d = r.quantity(spec["distance"], "length", where + ".distance")
    text, turn = _turn_of(spec["angle"]) if isinstance(spec["angle"], str) else (
        spec["angle"], 1.0)
    phi = turn * r.quantity(text, "angle", where + ".angle")
    x0, y0 = ground[frm]
    c, s = cos_sin(phi)
    return (x0 + d * c, y0 + d * s)


def plate_corner(spec, r, where, length) -> tuple[float, float]:
    """(along, left) of a plate's corner X given by its distances from the link's ends,
    d₁ = |first label X|, d₂ = |second label X|: along = (L² + d₁² − d₂²) / 2L,
    left = ±√(d₁² − along²), on the stated side."""
    if any(k in spec for k in ("along", "fraction", "left", "distance", "angle")):
        raise SceneError("give the corner either by distances (and side) or by along/left "
                         "or distance/angle, not both", file=r.file, where=where)
    if length is None:
        raise SceneError(f"distances need the link {spec.get('on')}'s length in [links]",
                         file=r.file, where=where + ".distances")
    ds = spec["distances"]
    if not isinstance(ds, list) or len(ds) != 2:
        raise SceneError("distances = [from the first label, from the second], e.g. "
                         "[\"100 mm\", \"120 mm\"]", file=r.file, where=where + ".distances")
    d1, d2 = (r.quantity(v, "length", where + ".distances") for v in ds)
    side = spec.get("side")
    if side not in ("left", "right"):
        raise SceneError("side must be 'left' or 'right' (of the link's first → second label)",
                         file=r.file, where=where + ".side")
    L = length
    along = (L * L + d1 * d1 - d2 * d2) / (2.0 * L)
    h2 = d1 * d1 - along * along
    if not h2 > 1e-18 * L * L:
        raise SceneError(f"no triangle has the sides {1e3 * L:.6g}, {1e3 * d1:.6g} and "
                         f"{1e3 * d2:.6g} mm (each must be shorter than the other two "
                         f"together)", file=r.file, where=where + ".distances")
    return along, math.sqrt(h2) * (1.0 if side == "left" else -1.0)


def point_on_link(spec, r, where, length=None) -> tuple[float | None, float | None, float]:
    """(along, fraction, left) of ``[points.X]``: given as they are, or in polar form from
    the link's first label, ``distance`` and ``angle`` (CCW from first → second label, or
    '30 deg CW'): along = d cos φ, left = d sin φ; or a plate's corner by its two distances
    (:func:`plate_corner`, ``length`` the link's)."""
    if "distances" in spec or "side" in spec:
        if "distances" not in spec:
            raise SceneError("side goes with distances = [..., ...]", file=r.file, where=where)
        along, left = plate_corner(spec, r, where, length)
        return along, None, left
    polar = ("distance" in spec) or ("angle" in spec)
    if polar:
        if not ("distance" in spec and "angle" in spec) or any(
                k in spec for k in ("along", "fraction", "left")):
            raise SceneError("give the point either by distance and angle (polar, from the "
                             "link's first label) or by along/fraction and left",
                             file=r.file, where=where)
        d = r.quantity(spec["distance"], "length", where + ".distance")
        text, turn = _turn_of(spec["angle"]) if isinstance(spec["angle"], str) else (
            spec["angle"], 1.0)
        phi = turn * r.quantity(text, "angle", where + ".angle")
        along, left = d * math.cos(phi), d * math.sin(phi)
        # a right angle's cosine is 6e-17, not 0: rounding, not a length (90 deg CW)
        return (0.0 if abs(along) <= 1e-12 * abs(d) else along), None, \
            (0.0 if abs(left) <= 1e-12 * abs(d) else left)
    if ("along" in spec) == ("fraction" in spec):
        raise SceneError("give exactly one of 'along' (a length from the link's first "
                         "label) or 'fraction' (of the link length, e.g. 0.5 for the "
                         "mid-point), or distance and angle", file=r.file, where=where)
    along = r.quantity(spec["along"], "length", where + ".along") if "along" in spec else None
    fraction = (r.quantity(spec["fraction"], "fraction", where + ".fraction")
                if "fraction" in spec else None)
    left = r.quantity(spec.get("left", "0 m"), "length", where + ".left")
    return along, fraction, left


def _turn_of(text: str) -> tuple[str, float]:
    """'30 deg CW' → ('30 deg', −1); '30 deg' → ('30 deg', +1): the sense an angle is
    measured in, CCW unless the text ends in a clockwise word."""
    head, turn = sense_in(text)
    return head.strip(), 1.0 if turn is None else float(turn)


def stated_from(value, angle: float, omega: float, r):
    """'θ from REF' → (REF, its angle = angle − turn θ, turn); None for a plain angle."""
    m = _FROM.match(value) if isinstance(value, str) else None
    if not m:
        return None
    amount, turn = _turn_of(m.group(1))
    ref = " ".join(m.group(2).split())
    if ref.lower() in _DEAD_WORDS:      # measured in the crank's sense of rotation
        turn = 1.0 if omega >= 0 else -1.0
    return ref, angle - turn * r.quantity(amount, "angle", "driver.angle", reduce=True), turn


def default_coincident(point: str) -> str:
    """The conventional name of the point under ``point``: C → C1, P2 → P2'."""
    return f"{point}'" if point[-1].isdigit() else f"{point}1"


def parse_slide(spec, r, links, split_link_name, labels=()) -> Slide:
    """``[driver.slide]`` → :class:`Slide` (``r`` is the scene reader, ``labels`` the point
    labels already in use)."""
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
    taken = {lab for link in links.values() for lab in (link.a, link.b)} | set(labels)
    for lab, key in ((point, "point"), (coincident, "coincident")):
        if lab in taken:
            raise SceneError(f"{lab} is already a point of the mechanism; the sliding point "
                             f"and the point under it need labels of their own", file=r.file,
                             where=f"{where}.{key}")
    if coincident == point:
        raise SceneError("the point under the collar needs a label of its own",
                         file=r.file, where=where + ".coincident")
    return Slide(point, along, p, q, coincident,
                 r.quantity(spec["position"], "length", where + ".position"),
                 r.quantity(spec["velocity"], "velocity", where + ".velocity"),
                 r.quantity(spec.get("acceleration", "0 m/s^2"), "acceleration",
                            where + ".acceleration"))


def parse_crossing(pin, spec, r, links, taken) -> "Crossing":
    """``[crossing.P]`` → :class:`polygons.records.Crossing` (``taken``: the labels already
    in use, which the points under the pin must not reuse)."""
    from .records import Crossing
    where = f"crossing.{pin}"
    r.label(pin, where)
    r.table(spec, where, ("levers", "coincident"), required=("levers",))
    levers = spec["levers"]
    if not isinstance(levers, list) or len(levers) != 2:
        raise SceneError("levers must name the two slotted levers, e.g. levers = [\"O2Q\", "
                         "\"O4R\"]", file=r.file, where=where + ".levers")
    levers = tuple(r.string(v, f"{where}.levers") for v in levers)
    for lev in levers:
        if lev not in links or links[lev].length is None:
            raise UnknownLabelError(f"the slotted lever {show_text(lev)} must be a link with a "
                                    f"length in [links]: {suggest(lev, links)}", file=r.file,
                                    where=where + ".levers")
        if pin in (links[lev].a, links[lev].b):
            raise SceneError(f"{pin} slides in the slot of {lev}, so it cannot be an end of "
                             f"{lev}", file=r.file, where=where + ".levers")
    if levers[0] == levers[1]:
        raise SceneError("the two slots must be cut in two different levers", file=r.file,
                         where=where + ".levers")
    default = [pin + (links[lev].a[1:] or str(i + 1)) for i, lev in enumerate(levers)]
    if len(set(default)) < 2:
        default = [f"{pin}1", f"{pin}2"]
    coincident = spec.get("coincident", default)
    if not isinstance(coincident, list) or len(coincident) != 2:
        raise SceneError("coincident must name each lever's point under the pin, e.g. "
                         "coincident = [\"P2\", \"P4\"]", file=r.file,
                         where=where + ".coincident")
    coincident = tuple(r.label(c, where + ".coincident") for c in coincident)
    if len(set(coincident) | {pin}) < 3 or set(coincident) & set(taken):
        raise SceneError(f"the points under {pin} need labels of their own, different from "
                         f"{pin} and from every other point", file=r.file,
                         where=where + ".coincident")
    return Crossing(pin, levers, coincident)


def show_text(x) -> str:
    return repr(x)[:60]


def slider_by_rod(rod, r, point, sliders, links, ground, assembly, slots=None) -> float:
    """The position of a slider driver placed by the angle of its rod, as books state it ("the
    connecting rod AB makes 30° with the line of stroke"): ``rod`` (a link at the slider,
    its angle measured first label → second label) at ``rod_angle`` (CCW from +x, or
    '30 deg CW').  The rod's other end R is on a fixed guide (R = S + L u must lie on it:
    one position) or joined to a fixed pivot D (|S + L u − D| = l: two positions, the
    scene's [assembly] word for the slider or near = [...] chooses).  ``rod`` is
    :func:`rod_of`'s."""
    where = "driver.rod"
    name, link, other, (ux, uy) = rod

    g = sliders[point]
    (tx, ty), (ex, ey) = g.through, (math.cos(g.angle), math.sin(g.angle))

    def cross(ax, ay, bx, by):
        return ax * by - ay * bx
    if other in sliders and sliders[other].pin is None:          # R on a fixed guide
        g2 = sliders[other]
        fx, fy = math.cos(g2.angle), math.sin(g2.angle)
        den = cross(ex, ey, fx, fy)
        if abs(den) < 1e-12:
            raise SceneError(f"the guides of {point} and {other} are parallel: the rod's angle "
                             f"does not place the slider", file=r.file, where=where)
        return cross(g2.through[0] - tx - ux, g2.through[1] - ty - uy, fx, fy) / den
    bears = [sl for sl in (slots or {}).values()
             if sl.lever in (link.name, link.b + link.a) and sl.pin in ground]
    if bears:       # the rod leans on a fixed circle ([bearing]): the pin K in its offset slot
        sl = bears[0]          # (K − P)·n = offset, P the lever's pivot, n ⟂ its direction
        L = math.hypot(ux, uy)
        lx, ly = ux / L, uy / L                       # slider → far end
        if sl.pivot != point:                         # the lever runs far end → slider
            lx, ly = -lx, -ly
        nx, ny = -ly, lx
        den = ex * nx + ey * ny
        if abs(den) < 1e-12:
            raise SceneError(f"the rod {name} is parallel to the guide of {point}: its angle "
                             f"does not place the slider", file=r.file, where=where)
        # the lever's pivot P = S (the slider) or S + L u (its far end)
        px, py = (tx, ty) if sl.pivot == point else (tx + ux, ty + uy)
        kx, ky = ground[sl.pin]
        return ((kx - px) * nx + (ky - py) * ny - sl.offset) / den
    pivots = _pivots(other, link, links, ground)
    if len(pivots) != 1:
        raise SceneError(f"the rod's angle places the slider {point} when the rod's other end "
                         f"{other} slides on a fixed guide or is joined by one link to a fixed "
                         f"pivot, or the rod bears on a fixed circle ([bearing]); give "
                         f"position = \"...\" instead", file=r.file, where=where)
    l2, D = pivots[0]
    wx, wy = tx + ux - ground[D][0], ty + uy - ground[D][1]
    b = ex * wx + ey * wy
    c = wx * wx + wy * wy - l2.length ** 2
    disc = b * b - c
    if disc < 0:
        raise SceneError(f"no position of {point} on its guide puts {name} at this angle: "
                         f"{other} cannot reach {l2.name}'s circle", file=r.file, where=where)
    roots = sorted({-b - math.sqrt(disc), -b + math.sqrt(disc)})
    if len(roots) == 1:
        return roots[0]
    spec = assembly.get(point)
    if isinstance(spec, dict) and "near" in spec:
        nx, ny = (r.quantity(v, "length", f"assembly.{point}.near") for v in spec["near"])
        return min(roots, key=lambda s: math.hypot(tx + s * ex - nx, ty + s * ey - ny))
    s1, s2 = roots
    raise SceneError(f"two positions of {point} put {name} at this angle, "
                     f"({1e3 * (tx + s1 * ex):.4g}, {1e3 * (ty + s1 * ey):.4g}) mm and "
                     f"({1e3 * (tx + s2 * ex):.4g}, {1e3 * (ty + s2 * ey):.4g}) mm; say which: "
                     f"[assembly] {point} = {{ near = [x, y] }}", file=r.file,
                     where=f"assembly.{point}")


def _pivots(other, rod, links, ground) -> list:
    """(link, fixed pivot) of each link with a length joining the rod's far end ``other`` to
    a fixed point."""
    return [(l2, l2.b if l2.a == other else l2.a) for l2 in links.values()
            if other in (l2.a, l2.b) and l2 is not rod and l2.length is not None
            and (l2.b if l2.a == other else l2.a) in ground]


def rod_of(drv, r, point, links, split):
    """(name, link, other end R, R − S) of a slider driver's rod at its stated angle."""
    where = "driver.rod"
    if "rod" not in drv or "rod_angle" not in drv:
        raise SceneError("give both rod = \"BA\" and rod_angle = \"30 deg\"", file=r.file,
                         where="driver")
    name = r.string(drv["rod"], where)
    p, q = split(name, file=r.file, where=where)
    link = links.get(name) or links.get(q + p)
    if link is None or link.length is None or point not in (p, q):
        raise SceneError(f"rod {name!r} must be a link with a length in [links] with the "
                         f"slider {point} at one end", file=r.file, where=where)
    text, turn = _turn_of(drv["rod_angle"]) if isinstance(drv["rod_angle"], str) else (
        drv["rod_angle"], 1.0)
    phi = turn * r.quantity(text, "angle", "driver.rod_angle")
    sign = 1.0 if p == point else -1.0          # R − S = sign L u(φ)
    return (name, link, q if p == point else p,
            (sign * link.length * math.cos(phi), sign * link.length * math.sin(phi)))


def slider_rate_by_rod(drv, rod, r, point, position, sliders, links, ground
                       ) -> tuple[float, float, tuple[str, float, float], float]:
    """The slider driver's (velocity, acceleration) along its guide when the book gives the
    angular velocity and acceleration of its rod ('the bar AB turns at 2 rad/s CW'), and
    (rod, ω, α) as stated.  With r = R − S, e the slider's guide:

        v_R − s e = ω k × r,   a_R − s̈ e = α k × r − ω² r,

    R on a fixed guide f (v_R = t f, a_R = ť f) or turning about a fixed pivot D
    (v_R = ω₂ k × d, a_R = α₂ k × d − ω₂² d, d = R − D): two linear equations each time,
    singular only where the rod's ω does not fix the slider's speed (the rod momentarily
    does not turn whatever the slider does: an engine's crank at right angles to the stroke)."""
    name, link, other, (rx, ry) = rod         # (rod_of's)
    w, turn = rate_with_sense(drv, "rod_omega", "rod_sense", "angular_velocity", r)
    if turn is None and w != 0.0:
        raise SceneError("rod_omega needs its sense: rod_sense = \"CW\" or \"CCW\" (or in "
                         "the value, '2 rad/s CW')", file=r.file, where="driver.rod_sense")
    w *= turn or 1.0
    a = 0.0
    if "rod_alpha" in drv:
        a, turn = rate_with_sense(drv, "rod_alpha", "rod_alpha_sense",
                                  "angular_acceleration", r)
        if turn is None and a != 0.0:
            raise SceneError("rod_alpha needs rod_alpha_sense = \"CW\" or \"CCW\" (the sense "
                             "of the angular acceleration)", file=r.file,
                             where="driver.rod_alpha_sense")
        a *= turn or 1.0
    g = sliders[point]
    e = (math.cos(g.angle), math.sin(g.angle))
    kr = (-ry, rx)                                      # k × r
    S = (g.through[0] + position * e[0], g.through[1] + position * e[1])
    R = (S[0] + rx, S[1] + ry)
    if other in sliders and sliders[other].pin is None:          # R on a fixed guide
        f = (math.cos(sliders[other].angle), math.sin(sliders[other].angle))
        col, extra = f, (0.0, 0.0)
    else:
        D = _pivots(other, link, links, ground)[0][1]     # (one: slider_by_rod checked)
        d = (R[0] - ground[D][0], R[1] - ground[D][1])
        col, extra = (-d[1], d[0]), d
    det = -col[0] * e[1] + col[1] * e[0]                # det [col, −e]
    size = math.hypot(*col) * math.hypot(rx, ry)
    if abs(det) <= 1e-6 * size:         # (its angle is extreme there: a double root)
        raise SceneError(f"at this angle the rod {name}'s ω does not fix the slider {point}'s "
                         f"speed (the rod does not turn at this instant, whatever the slider's "
                         f"speed): give the slider's velocity instead", file=r.file,
                         where="driver.rod_omega")

    def solve(bx, by):          # [col, −e] (x, s) = b  →  s
        return (col[0] * by - col[1] * bx) / det
    v = solve(w * kr[0], w * kr[1])
    x = (w * kr[0] + v * e[0]) / col[0] if abs(col[0]) > abs(col[1]) else \
        (w * kr[1] + v * e[1]) / col[1]                 # t, or ω₂ about D
    # accelerations: the pivot's centripetal term −ω₂² d moves to the right-hand side
    acc = solve(a * kr[0] - w * w * rx + extra[0] * x * x,
                a * kr[1] - w * w * ry + extra[1] * x * x)
    meet = math.degrees(math.asin(min(1.0, abs(det) / math.hypot(*col))))   # col ∧ e
    return v, acc, (name, w, a), meet


def lever_as_crank(drv: dict, r, slots_raw, links_raw) -> dict:
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
    if not any(isinstance(v, str) and k == lever for k, v in links_raw.items()):
        raise SceneError(f"a driven lever needs its length in [links] ({lever} = \"...\"): its "
                         f"far end is placed along it, and the pin is found in its slot",
                         file=r.file, where="driver.lever")
    out = {k: v for k, v in drv.items() if k != "lever"}
    out["crank"] = lever
    return out


def crank_angle(value, r, *, pivot, tip, sense, ground, links, sliders, assembly) -> float:
    """The crank angle (rad, CCW from +x) stated as a book states it:

    * ``"30 deg"``: CCW from +x;
    * ``"30 deg from idc"`` / ``"from odc"``: a slider-crank, θ past inner / outer dead centre
      in the crank's sense of rotation;
    * ``"30 deg from AD"``: CCW from the ray A → D between two fixed points (the line of
      centres of a four-bar);
    * ``"30 deg from +y"`` (or +x, -x, -y): from an axis;
    * ``"30 deg CW from AD"`` / ``"45 deg clockwise from +y"``: measured clockwise (``CCW``,
      the default, also said).
    """
    where = "driver.angle"
    m = _FROM.match(value) if isinstance(value, str) else None
    if not m:
        return r.quantity(value, "angle", where, reduce=True)
    amount, turn = _turn_of(m.group(1))
    theta = r.quantity(amount, "angle", where, reduce=True)
    ref = " ".join(m.group(2).split())
    dead = _DEAD_WORDS.get(ref.lower())
    if dead is None:
        if ref.lower() in _AXES:
            return _AXES[ref.lower()] + turn * theta
        if not _LINE.match(ref):
            raise SceneError(f"cannot read {value!r}: write '30 deg', '30 deg from idc', "
                             f"'30 deg from odc', '30 deg from AD' (two fixed points) or "
                             f"'30 deg CW from +y'", file=r.file, where=where)
        a, b = re.findall(r"[A-Z][a-z0-9_']*", ref)
        missing = [lab for lab in (a, b) if lab not in ground]
        if missing:
            raise SceneError(f"'{ref}' in {value!r} must join two fixed points; "
                             f"{', '.join(missing)} not in [ground] ({', '.join(ground)})",
                             file=r.file, where=where)
        (ax, ay), (bx, by) = ground[a], ground[b]
        return math.atan2(by - ay, bx - ax) + turn * theta
    if amount != m.group(1).strip():
        raise SceneError(f"{value!r}: an angle from a dead centre is measured in the crank's "
                         f"sense of rotation ([driver] sense); drop the CW/CCW",
                         file=r.file, where=where)
    rods = [(l.b if l.a == tip else l.a, l) for l in links.values()
            if tip in (l.a, l.b) and pivot not in (l.a, l.b)]
    rods = [(x, l) for x, l in rods if x in sliders and sliders[x].pin is None]
    if len(rods) != 1:
        raise SceneError(f"'{dead}' is a slider-crank's dead centre: the crank pin {tip} must "
                         f"be joined by one connecting rod to one slider on a fixed guide",
                         file=r.file, where=where)
    x, rod = rods[0]
    crank_len = next(l.length for l in links.values() if {l.a, l.b} == {pivot, tip})
    guide = sliders[x]
    return dead_centre_angle(theta, dead, sense, pivot=ground[pivot], r_crank=crank_len,
                             rod=rod.length, guide=(guide.through, guide.direction),
                             side=_piston_side(x, assembly, ground, guide, r), file=r.file)


def _piston_side(x, assembly, ground, guide, r) -> float:
    """+1 when the slider ``x`` is on the +direction side of its guide's foot point, −1
    otherwise, read from the scene's [assembly] words for x ("B right of O", near = ...)."""
    spec = assembly.get(x) if isinstance(assembly, dict) else None
    e = guide.direction
    how = (f"say which side the slider is on in [assembly], e.g. {x} = \"{x} right of O\" "
           f"(a fixed point) or {x} = {{ near = [...] }}")
    if isinstance(spec, dict) and "near" in spec:
        nx, ny = r.vec(spec["near"], f"assembly.{x}.near")
        return 1.0 if (nx - guide.through[0]) * e[0] + (ny - guide.through[1]) * e[1] >= 0 \
            else -1.0
    if isinstance(spec, str):
        words = " ".join(spec.split())
        for rel, (cx, cy) in (("right of", (1, 0)), ("left of", (-1, 0)), ("above", (0, 1)),
                              ("below", (0, -1))):
            for pre in (f"{x} {rel} ", f"{rel} "):
                if words.startswith(pre) and words[len(pre):] in ground:
                    along = cx * e[0] + cy * e[1]
                    if abs(along) < 1e-9:
                        break
                    return 1.0 if along > 0 else -1.0
    raise SceneError(f"a crank angle from a dead centre needs the side of the slider {x}: "
                     f"{how}", file=r.file, where="driver.angle")


def guide_through(spec, r, where, ground) -> tuple[float, float] | None:
    """A slider guide stated by its distance from a pivot: ``from = "O"``, ``offset = "20 mm"``
    (perpendicular distance, positive to the left of the guide direction) → a point on it;
    None when the guide gives ``through`` instead."""
    if "from" not in spec and "offset" not in spec:
        return None
    if "through" in spec or "from" not in spec or "offset" not in spec:
        raise SceneError("give the guide either through = [x, y] or from = \"O\" with "
                         "offset = \"20 mm\" (its distance from that fixed point, positive "
                         "to the left of the direction)", file=r.file, where=where)
    frm = r.label(spec["from"], where + ".from")
    if frm not in ground:
        raise SceneError(f"from = {frm!r} must be a fixed point in [ground] "
                         f"({', '.join(ground)})", file=r.file, where=where + ".from")
    d = r.quantity(spec["offset"], "length", where + ".offset")
    a = r.quantity(spec["direction"], "angle", where + ".direction")
    ox, oy = ground[frm]
    c, s = cos_sin(a)
    return (ox - d * s, oy + d * c)


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
    along = (ox - gx) * e[0] + (oy - gy) * e[1]
    fx, fy = gx + along * e[0], gy + along * e[1]
    h = math.hypot(ox - fx, oy - fy)
    d = rod + r_crank if which == "idc" else rod - r_crank
    if d <= h:
        raise SceneError(f"no {which.upper()}: crank and rod in line ({1e3 * d:.6g} mm) "
                         f"cannot reach the guide {1e3 * h:.6g} mm from the pivot", file=file,
                         where="driver.angle")
    t = side * math.sqrt(d * d - h * h)
    base = math.atan2(fy + t * e[1] - oy, fx + t * e[0] - ox)
    if which == "odc":
        base += math.pi
    return base + sense * theta


def slot_length(spec, r, where) -> float | None:
    """``[slots.P] length = "300 mm"``: how far the slot runs along the lever from its pivot
    (from the foot of the pivot on an offset slot); None when not stated (the slot open-ended:
    only a stated length bounds it).  The pin beyond it has left the slot."""
    if "length" not in spec:
        return None
    length = r.quantity(spec["length"], "length", where + ".length")
    if not length > 0:
        raise SceneError(f"the slot's length must be positive, got {spec['length']!r}",
                         file=r.file, where=where + ".length")
    return length


def lever_driven(scene, slot) -> bool:
    """Whether the slotted lever of ``slot`` is the driver (a crank carrying a slot)."""
    return getattr(scene.driver, "link", None) == slot.lever


def guided_pin(scene, slot) -> bool:
    """Whether the pin of ``slot`` is found in the slot of a lever placed first (the lever
    driven, or placed by its own links): the lever has a far end and the pin hangs from
    exactly one link of known length that is not the driving crank."""
    return guided_pin_in(scene.links, scene.driver, slot)


def guided_pin_in(links, driver, slot) -> bool:
    """:func:`guided_pin` from the parsed [links] and driver (before the scene is built)."""
    if slot.far is None:
        return False
    joints = [l for l in links.values()
              if slot.pin in (l.a, l.b) and l.length is not None and l.name != slot.lever]
    return len(joints) == 1 and joints[0].name != getattr(driver, "link", None)


def slot_along_lever(scene, slot) -> bool:
    """Whether the slot's direction is the lever's pivot → far end (an offset slot, or a lever
    placed before its pin, which may lie on either side of the pivot) rather than pivot → pin
    (a pin placed first, the lever following it)."""
    return bool(slot.offset) or guided_pin(scene, slot)


def why_unplaced(scene, x: str, placed) -> str:
    """Why point ``x`` cannot be placed by any dyad, in the scene's words ('' when there is
    nothing more specific to say than the planner's general sentence)."""
    joints = [(l.b if l.a == x else l.a, l.name) for l in scene.links.values()
              if x in (l.a, l.b) and l.length is not None]
    known = [o for o, _ in joints if o in placed]
    lever_of = next((s for s in scene.slots.values() if x in (s.far, s.coincident)
                     and s.pin not in placed and s.pin != x), None)
    if lever_of is not None and len(known) < 2:
        inner = why_unplaced(scene, lever_of.pin, placed)
        return (f"{x} is on the slotted lever {lever_of.lever}, which turns with its pin "
                f"{lever_of.pin}, and {lever_of.pin} is not placed" + (f": {inner}" if inner
                                                                         else ""))
    slot = scene.slots.get(x)
    if slot is not None:
        if slot.pivot not in placed:
            return (f"the pin {x} slides in the slot of lever {slot.lever}, whose pivot "
                    f"{slot.pivot} is not placed either")
        if slot.far is None:
            return (f"the pin {x} slides in the slot of lever {slot.lever}, which has no length "
                    f"in [links]: such a lever follows a pin placed by its own links (a crank, "
                    f"two links); to find the pin in the slot of a lever placed first, give "
                    f"{slot.lever} a length")
        if len(joints) != 1:
            return (f"the pin {x} slides in the slot of lever {slot.lever} and is joined by "
                    f"{len(joints)} links ({', '.join(n for _, n in joints) or 'none'}): a pin "
                    f"found in a slot hangs from exactly one link")
        return (f"the pin {x} slides in the slot of lever {slot.lever}, which is not placed: a "
                f"guide carried by a moving link is placed first by its own links (or driven, "
                f"[driver] lever = \"{slot.lever}\"), then the pin is found in it")
    others = [o for o, _ in joints if o not in placed]
    if len(joints) >= 3 and len(known) < 2:
        return (f"{x} is joined by {', '.join(n for _, n in joints)}, and fewer than two of "
                f"their other ends are placed: unless a link or guide is missing, the links "
                f"around {x} form a closed group (a class-III Assur group, a triad) that no "
                f"single dyad places; a triad is solved when its plate's three corners each "
                f"have one link to a placed point, or one corner is a block on a fixed guide "
                f"([sliders]) with no link of its own and the other two one link each")
    if len(joints) == 1 and x not in scene.sliders and x not in scene.points:
        return (f"{x} hangs from one link ({joints[0][1]}) only: it needs a second link, a "
                f"guide ([sliders.{x}]), a slot ([slots.{x}]) or [points.{x}] on a link")
    blocks = sorted({o for o in others if o in scene.sliders}
                    | {bp.label for bp in scene.points.values() if bp.label in scene.sliders
                       and bp.link in {n for _, n in joints}})
    if len(joints) == 2 and others and blocks:
        return (f"{x} is joined by {joints[0][1]} and {joints[1][1]}, but "
                f"{' and '.join(others)} {'is' if len(others) == 1 else 'are'} not placed "
                f"before it: with the block{'s' if len(blocks) > 1 else ''} on a guide at "
                f"{', '.join(blocks)} the links around {x} may form a closed group (a "
                f"class-III Assur group); one is solved when one corner of its plate is a "
                f"block on a fixed guide and each other corner has one link to a placed point "
                f"(blocks at two corners are not supported)")
    if len(joints) == 2 and others:
        return (f"{x} is joined by {joints[0][1]} and {joints[1][1]}, but "
                f"{' and '.join(others)} {'is' if len(others) == 1 else 'are'} not placed "
                f"before it")
    return ""


def plate_side(ends, links, points):
    """(link, P, Q) where the two labels ``ends`` are both points of one link's plate (its
    ends and its [points] read so far), P and Q in the link's frame (its first label at the
    origin, the second on +x); else None."""
    for name, link in links.items():
        if link.length is None:
            continue
        frame = {link.a: (0.0, 0.0), link.b: (link.length, 0.0)}
        for bp in points.values():
            if bp.link == name:
                along = bp.along if bp.along is not None else bp.fraction * link.length
                frame[bp.label] = (along, bp.left)
        if all(e in frame for e in ends) and math.dist(*(frame[e] for e in ends)) > 0:
            return name, frame[ends[0]], frame[ends[1]]
    return None


def on_side(spec, r, where, side) -> tuple[float, None, float]:
    """(along, None, left) on the plate's link of a point stated on a side of the plate that
    is no link (``side`` from :func:`plate_side`: CX of the plate BC carrying X)."""
    _, P, Q = side
    n = math.dist(P, Q)
    a, f, lft = point_on_link(spec, r, where, n)
    ux, uy = (Q[0] - P[0]) / n, (Q[1] - P[1]) / n
    s = a if a is not None else f * n
    return P[0] + s * ux - lft * uy, None, P[1] + s * uy + lft * ux
