"""Scene files: a mechanism stated as a textbook states it, in TOML with units.

    title = "Worked example 4"
    [ground]                  # fixed pivots (space labels, upper case)
    A = ["0 mm", "0 mm"]
    [links]                   # binary links named by their two end labels
    AB = "50 mm"
    BC = "170 mm"
    [driver]                  # the input: a crank turning about its first label ...
    crank = "AB"
    angle = "60 deg"          # CCW from +x
    omega = "300 rad/s"
    sense = "CW"              # CW or CCW
    alpha = "0 rad/s^2"       # optional, with alpha_sense
    [sliders.C]               # ... C slides on a fixed straight guide
    through = ["0 mm", "0 mm"]
    direction = "0 deg"
    [assembly]                # which of the two closures, in words
    C = "right of A"

Also ``[drawn] B = ["135 mm", "26 mm"]`` (the space diagram as drawn: picks the closure
nearest to it, gives lengths written ``AB = "drawn"`` and the crank angle when ``angle`` is
omitted, and is checked against the assembly), ``[slots.PIN] lever = "BC"`` (a pin sliding in the slot of a lever pivoted at B, the
quick-return / slotted-lever case), ``[points.D] on = "AB", along = "168 mm"`` (extra points of
a rigid link: coupler points, "BD is a continuation of AB", mid-points with ``fraction``), a
slider as the driver (``[driver] slider = "C"``), and ``[[answers]]`` (the tutorial's printed
answers and the exact ones, used by the tests and the reports).

:func:`load_scene` turns a file into a frozen :class:`Scene` (all SI) or raises a
:class:`~polygons.errors.SceneError` subclass naming the file, the key and the reason.
"""
from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any, Mapping

from . import topology
from .errors import (BranchError, PolygonsError, SceneError, SceneSyntaxError,
                     UnknownKeyError, UnknownLabelError, UnitError, suggest)
from .units import UNITS, dimension_of, parse_quantity

Vec = tuple[float, float]

_LABEL_TOKEN = re.compile(r"[A-Z][a-z0-9_']*")
_LABEL = re.compile(r"^[A-Z][a-z0-9_']*$")

TOP_KEYS = ("title", "source", "ground", "links", "driver", "sliders", "slots", "points",
            "assembly", "answers", "solve", "drawn")
#: tables read by extension modules (forces, sweeps, diagrams); stored raw in ``Scene.extra``
#: and validated by the module that uses them (it must raise SceneError subclasses itself)
EXTENSION_KEYS = ("masses", "forces", "torques", "springs", "gravity", "dynamics", "sweep",
                  "diagram", "handout", "force_answers")
DIAGRAMS = ("velocity", "acceleration")


# ---------------------------------------------------------------- value objects
@dataclass(frozen=True)
class Link:
    """A rigid binary link between pins ``a`` and ``b`` (``length`` None for a slotted lever)."""

    name: str
    a: str
    b: str
    length: float | None


@dataclass(frozen=True)
class Guide:
    """A fixed straight slider guide through ``through`` at ``angle`` (rad, CCW from +x).

    A slider may carry a straight slot (a Scotch yoke): ``pin`` slides in it, and the slot
    keeps the fixed direction ``slot_angle`` because the slider only translates.  The
    slider's label is then the point of the yoke on its guide, under the slot line."""

    through: Vec
    angle: float
    pin: str | None = None
    slot_angle: float | None = None

    @property
    def direction(self) -> Vec:
        return (math.cos(self.angle), math.sin(self.angle))

    @property
    def slot_direction(self) -> Vec | None:
        if self.slot_angle is None:
            return None
        return (math.cos(self.slot_angle), math.sin(self.slot_angle))


@dataclass(frozen=True)
class Crank:
    """Driver: link ``link`` turning about fixed ``pivot``; ``tip`` is its other end."""

    link: str
    pivot: str
    tip: str
    angle: float
    omega: float   # signed, CCW positive
    alpha: float   # signed, CCW positive


@dataclass(frozen=True)
class SliderDrive:
    """Driver: point ``point`` pushed along its guide; ``position`` measured from the guide's
    ``through`` point along its direction, ``velocity``/``acceleration`` signed the same way."""

    point: str
    position: float
    velocity: float
    acceleration: float


@dataclass(frozen=True)
class Slot:
    """Pin ``pin`` slides in the straight slot of ``lever``, which turns about fixed ``pivot``;
    the slot runs through the pivot along the lever.  ``coincident`` is the point of the lever
    under the pin at this instant (P4 under P2, A1 under A); ``far`` is the lever's other
    labelled end when it has a stated length (C of lever BC), else None."""

    pin: str
    lever: str
    pivot: str
    coincident: str
    far: str | None
    far_length: float | None
    offset: float = 0.0     # the slot line's distance left of the lever's line (topology)


@dataclass(frozen=True)
class BodyPoint:
    """Point ``label`` rigidly attached to link ``link`` (ends P, Q): at distance ``along`` from
    P towards Q plus ``left`` perpendicular (to the left of P→Q)."""

    label: str
    link: str
    along: float | None
    fraction: float | None
    left: float


@dataclass(frozen=True)
class Branch:
    """Assembly choice for ``label``: ``relation`` ('above', 'below', 'left of', 'right of',
    'near') a reference (a point label, a line of two labels, or coordinates for 'near')."""

    label: str
    text: str
    relation: str
    ref: tuple[str, ...] = ()
    near: Vec | None = None


@dataclass(frozen=True)
class Answer:
    """One printed (tutorial) answer and/or exact reference value for a result quantity."""

    quantity: str
    unit: str
    tutorial: float | None      # in `unit`
    exact: float | None         # in `unit`
    mode: str                   # 'abs' compares magnitudes, 'signed' compares signed values
    sense: str | None           # the tutorial's direction word (CW/CCW/...), if any
    tolerance: float            # relative drawing tolerance for the tutorial value
    slip: bool                  # the reference found a slip: we must NOT reproduce it
    ref: str | None             # key in the reference cases.json
    desc: str
    note: str


@dataclass(frozen=True)
class Scene:
    file: str
    title: str
    source: Mapping[str, Any]
    ground: Mapping[str, Vec]
    links: Mapping[str, Link]
    driver: Crank | SliderDrive
    sliders: Mapping[str, Guide]
    slots: Mapping[str, Slot]
    points: Mapping[str, BodyPoint]
    assembly: Mapping[str, Branch]
    answers: tuple[Answer, ...]
    solve: tuple[str, ...] = DIAGRAMS
    drawn: Mapping[str, Vec] = field(default_factory=lambda: MappingProxyType({}))
    extra: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))
    #: second inputs: prescribed slides along a link (:mod:`polygons.topology`)
    prescribed: Mapping[str, topology.Slide] = field(
        default_factory=lambda: MappingProxyType({}))

    @property
    def labels(self) -> tuple[str, ...]:
        """Every point label of the space diagram, in order of first mention."""
        seen: dict[str, None] = {}
        for g in self.ground:
            seen[g] = None
        for link in self.links.values():
            seen[link.a] = None
            seen[link.b] = None
        for slot in self.slots.values():
            seen[slot.pivot] = None
            seen[slot.coincident] = None
        for p in self.points:
            seen[p] = None
        for lab, g in self.sliders.items():
            if g.pin is not None:       # a Scotch yoke's point on its guide
                seen[lab] = None
        for sl in self.prescribed.values():
            seen[sl.coincident] = None
            seen[sl.point] = None
        return tuple(seen)

    def link_between(self, p: str, q: str) -> Link | None:
        for link in self.links.values():
            if {link.a, link.b} == {p, q}:
                return link
        return None


# ---------------------------------------------------------------- loading
def split_link_name(name: str, *, file: str | None = None, where: str | None = None
                    ) -> tuple[str, str]:
    """'BC' -> ('B', 'C'); 'O2P2' -> ('O2', 'P2').  A label is a capital letter followed by
    lower-case letters, digits, '_' or a prime."""
    tokens = _LABEL_TOKEN.findall(name)
    if "".join(tokens) != name or len(tokens) != 2:
        raise SceneError(f"link name {name!r} must be its two end labels, e.g. 'BC' or 'O2P2' "
                         f"(a label is a capital letter followed by lower-case letters or "
                         f"digits)", file=file, where=where)
    if tokens[0] == tokens[1]:
        raise SceneError(f"link {name!r} joins {tokens[0]} to itself", file=file, where=where)
    return tokens[0], tokens[1]


class _Reader:
    """Reads one scene table with location-aware errors."""

    def __init__(self, file: str):
        self.file = file

    def table(self, data, where: str, allowed: tuple[str, ...], required: tuple[str, ...] = ()
              ) -> dict:
        if not isinstance(data, dict):
            raise SceneError(f"expected a table, got {type(data).__name__}", file=self.file,
                             where=where)
        for key in data:
            if key not in allowed:
                raise UnknownKeyError(f"unknown key {key!r}: {suggest(key, allowed)}",
                                      file=self.file, where=f"{where}.{key}" if where else key)
        for key in required:
            if key not in data:
                raise SceneError(f"missing key {key!r} (required: {', '.join(required)})",
                                 file=self.file, where=where)
        return data

    def quantity(self, value, dimension: str, where: str) -> float:
        return parse_quantity(value, dimension, file=self.file, where=where)

    def vec(self, value, where: str) -> Vec:
        if not isinstance(value, list) or len(value) != 2:
            raise SceneError(f"expected coordinates [x, y] with units, e.g. ['0 mm', '70 mm'], "
                             f"got {value!r}", file=self.file, where=where)
        return (self.quantity(value[0], "length", where + "[0]"),
                self.quantity(value[1], "length", where + "[1]"))

    def label(self, value, where: str) -> str:
        if not isinstance(value, str) or not _LABEL.match(value):
            raise SceneError(f"{value!r} is not a point label (a capital letter followed by "
                             f"lower-case letters or digits, e.g. 'C' or 'O2')", file=self.file,
                             where=where)
        return value

    def sense(self, value, where: str) -> int:
        if value in ("CCW", "ccw", "anticlockwise", "anti-clockwise", "counter-clockwise"):
            return 1
        if value in ("CW", "cw", "clockwise"):
            return -1
        raise SceneError(f"sense must be 'CW' or 'CCW', got {value!r}", file=self.file,
                         where=where)

    def string(self, value, where: str) -> str:
        if not isinstance(value, str):
            raise SceneError(f"expected text, got {value!r}", file=self.file, where=where)
        return value


def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file; every problem raises a :class:`SceneError`."""
    path = Path(path)
    file = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SceneError("no such scene file", file=file) from None
    except OSError as exc:
        raise SceneError(f"cannot read the scene file ({exc.strerror})", file=file) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneSyntaxError(f"not valid TOML: {exc}", file=file) from None
    return parse_scene(data, file=file)


def parse_scene(data: dict, *, file: str = "<scene>",
                extra_keys: tuple[str, ...] = EXTENSION_KEYS) -> Scene:
    """Build a :class:`Scene` from parsed TOML ``data`` (see module docstring)."""
    r = _Reader(file)
    r.table(data, "", TOP_KEYS + extra_keys, required=("ground", "links", "driver"))
    title = r.string(data.get("title", path_stem(file)), "title")
    source = data.get("source", {})
    r.table(source, "source", ("id", "seed", "example", "category", "synthetic", "statement",
                               "conventions", "drawing_tolerance", "notes", "backsolved",
                               "slips", "mechanism"))

    # ground
    ground_raw = r.table(data["ground"], "ground", tuple(data["ground"]))
    ground = {}
    for name, value in ground_raw.items():
        ground[r.label(name, f"ground.{name}")] = r.vec(value, f"ground.{name}")
    if not ground:
        raise SceneError("at least one fixed pivot is needed", file=file, where="ground")

    # the space diagram as drawn: coordinates of moving points at this instant
    drawn_raw = r.table(data.get("drawn", {}), "drawn", tuple(data.get("drawn", {})))
    drawn = {r.label(k, f"drawn.{k}"): r.vec(v, f"drawn.{k}") for k, v in drawn_raw.items()}
    placed = {**drawn, **ground}

    # links
    links_raw = r.table(data["links"], "links", tuple(data["links"]))
    links: dict[str, Link] = {}
    for name, value in links_raw.items():
        a, b = split_link_name(name, file=file, where=f"links.{name}")
        if value == "drawn":
            missing = [p for p in (a, b) if p not in placed]
            if missing:
                raise SceneError(f"length 'drawn' needs the positions of {a} and {b}; "
                                 f"{' and '.join(missing)} not in [ground] or [drawn]",
                                 file=file, where=f"links.{name}")
            links[name] = Link(name, a, b, math.dist(placed[a], placed[b]))
            continue
        length = r.quantity(value, "length", f"links.{name}")
        if length <= 0:
            raise SceneError(f"length must be positive, got {value!r}", file=file,
                             where=f"links.{name}")
        links[name] = Link(name, a, b, length)

    # slots
    slots: dict[str, Slot] = {}
    for pin, spec in r.table(data.get("slots", {}), "slots", tuple(data.get("slots", {}))).items():
        where = f"slots.{pin}"
        r.label(pin, where)
        r.table(spec, where, ("lever", "coincident", "offset"), required=("lever",))
        lever = r.string(spec["lever"], where + ".lever")
        pivot, other = split_link_name(lever, file=file, where=where + ".lever")
        if pivot not in ground and not any(pivot in (l.a, l.b) for l in links.values()):
            raise SceneError(f"the lever {lever}'s first label {pivot} is its pivot: a fixed "
                             f"pivot (in [ground]: {', '.join(ground)}) or a pin of a link",
                             file=file, where=where + ".lever")
        if lever in links:
            if "coincident" not in spec:
                raise SceneError(f"lever {lever} has a length, so name the point of the lever "
                                 f"under {pin}: coincident = \"{pin}1\"", file=file, where=where)
            coincident = r.label(spec["coincident"], where + ".coincident")
            far, far_length = other, links[lever].length
        else:
            coincident = r.label(spec.get("coincident", other), where + ".coincident")
            if coincident != other:
                raise SceneError(f"lever {lever} has no length in [links], so its second label "
                                 f"{other} is the point under the pin; coincident must be "
                                 f"{other!r}", file=file, where=where + ".coincident")
            far, far_length = None, None
        offset = r.quantity(spec.get("offset", "0 m"), "length", where + ".offset")
        if offset and far is None:
            raise SceneError(f"an offset slot needs the lever's length: give {lever} in "
                             f"[links] and coincident = \"{pin}1\"", file=file,
                             where=where + ".offset")
        slots[pin] = Slot(pin, lever, pivot, coincident, far, far_length, offset)

    # extra body points
    points: dict[str, BodyPoint] = {}
    for label, spec in r.table(data.get("points", {}), "points",
                               tuple(data.get("points", {}))).items():
        where = f"points.{label}"
        r.label(label, where)
        r.table(spec, where, ("on", "along", "fraction", "left"), required=("on",))
        on = r.string(spec["on"], where + ".on")
        split_link_name(on, file=file, where=where + ".on")
        if on not in links and not any(s.lever == on for s in slots.values()):
            raise UnknownLabelError(f"link {on!r} is not defined: "
                                    f"{suggest(on, list(links) + [s.lever for s in slots.values()])}",
                                    file=file, where=where + ".on")
        if ("along" in spec) == ("fraction" in spec):
            raise SceneError("give exactly one of 'along' (a length from the link's first "
                             "label) or 'fraction' (of the link length, e.g. 0.5 for the "
                             "mid-point)", file=file, where=where)
        along = r.quantity(spec["along"], "length", where + ".along") if "along" in spec else None
        fraction = (r.quantity(spec["fraction"], "fraction", where + ".fraction")
                    if "fraction" in spec else None)
        left = r.quantity(spec.get("left", "0 m"), "length", where + ".left")
        points[label] = BodyPoint(label, on, along, fraction, left)

    known = set(ground)
    for link in links.values():
        known |= {link.a, link.b}
    for slot in slots.values():
        known |= {slot.pivot, slot.coincident}
    known |= set(points)

    def need_label(label: str, where: str) -> str:
        if label not in known:
            raise UnknownLabelError(f"unknown point {label!r}: {suggest(label, known)}",
                                    file=file, where=where)
        return label

    for slot in slots.values():
        if slot.pin not in known:
            raise SceneError(f"the pin {slot.pin} sliding in the slot of {slot.lever} is on no "
                             f"link: make it the end of a link (a crank, a rocker) or a point "
                             f"of one in [points]", file=file, where=f"slots.{slot.pin}")

    # sliders
    sliders: dict[str, Guide] = {}
    for label, spec in r.table(data.get("sliders", {}), "sliders",
                               tuple(data.get("sliders", {}))).items():
        where = f"sliders.{label}"
        r.table(spec, where, ("through", "direction", "pin", "slot", "from", "offset"),
                required=("direction",))
        through = topology.guide_through(spec, r, where, ground)
        if through is None:
            r.table(spec, where, tuple(spec), required=("through",))
            through = r.vec(spec["through"], where + ".through")
        angle = r.quantity(spec["direction"], "angle", where + ".direction")
        if "pin" in spec or "slot" in spec:
            # a Scotch yoke: this slider carries a straight slot in which a placed pin slides
            if "pin" not in spec or "slot" not in spec:
                raise SceneError("a slider carrying a slot (Scotch yoke) needs both pin = "
                                 "\"P\" (the pin sliding in the slot) and slot = \"0 deg\" "
                                 "(the slot's direction)", file=file, where=where)
            r.label(label, where)
            pin = need_label(r.label(spec["pin"], where + ".pin"), where + ".pin")
            slot_angle = r.quantity(spec["slot"], "angle", where + ".slot")
            if abs(math.sin(slot_angle - angle)) < 1e-9:
                raise SceneError("the slot is parallel to the yoke's guide, so the pin does "
                                 "not fix the yoke; give the slot another direction",
                                 file=file, where=where + ".slot")
            known.add(label)
            sliders[label] = Guide(through, angle, pin, slot_angle)
        else:
            need_label(r.label(label, where), where)
            sliders[label] = Guide(through, angle)

    # driver
    drv = r.table(data["driver"], "driver", tuple(data["driver"]))
    drv = topology.lever_as_crank(drv, r, data.get("slots", {}), data["links"])
    prescribed = {}
    if "slide" in drv:
        sl = topology.parse_slide(drv["slide"], r, links, split_link_name,
                                  labels=known | set(sliders))
        prescribed[sl.point] = sl
        known |= {sl.point, sl.coincident}
        drv = {k: v for k, v in drv.items() if k != "slide"}
    r.table(drv, "driver", ("crank", "slider", "angle", "omega", "sense", "alpha",
                            "alpha_sense", "position", "velocity", "acceleration", "lever",
                            "slide"))
    if ("crank" in drv) == ("slider" in drv):
        raise SceneError("the driver is either a crank (crank = \"OA\") or a slider "
                         "(slider = \"C\"): give exactly one", file=file, where="driver")
    driver: Crank | SliderDrive
    if "crank" in drv:
        r.table(drv, "driver", ("crank", "angle", "omega", "sense", "alpha", "alpha_sense"),
                required=("crank", "omega", "sense"))
        name = r.string(drv["crank"], "driver.crank")
        pivot, tip = split_link_name(name, file=file, where="driver.crank")
        if name not in links and f"{tip}{pivot}" in links:
            name = f"{tip}{pivot}"      # written the other way round in [links]
        elif name not in links:
            raise UnknownLabelError(f"crank {name!r} is not a link in [links]: "
                                    f"{suggest(name, links)}", file=file, where="driver.crank")
        if pivot not in ground:
            raise SceneError(f"the crank turns about its first label {pivot}, which must be a "
                             f"fixed pivot in [ground] ({', '.join(ground)}); write the crank "
                             f"with its pivot first", file=file, where="driver.crank")
        omega = abs(r.quantity(drv["omega"], "angular_velocity", "driver.omega"))
        omega *= r.sense(drv["sense"], "driver.sense")
        alpha = 0.0
        if "alpha" in drv:
            alpha = abs(r.quantity(drv["alpha"], "angular_acceleration", "driver.alpha"))
            if alpha != 0.0:
                if "alpha_sense" not in drv:
                    raise SceneError("alpha needs alpha_sense = 'CW' or 'CCW' (the sense of the "
                                     "angular acceleration, not of the rotation)", file=file,
                                     where="driver.alpha_sense")
                alpha *= r.sense(drv["alpha_sense"], "driver.alpha_sense")
        if "angle" in drv:
            angle = topology.crank_angle(drv["angle"], r, pivot=pivot, tip=tip,
                                         sense=1 if omega >= 0 else -1, ground=ground,
                                         links=links, sliders=sliders,
                                         assembly=data.get("assembly", {}))
        elif tip in drawn:
            angle = math.atan2(drawn[tip][1] - ground[pivot][1], drawn[tip][0] - ground[pivot][0])
        else:
            raise SceneError(f"give the crank angle (angle = \"30 deg\") or the drawn position "
                             f"of {tip} in [drawn]", file=file, where="driver.angle")
        driver = Crank(name, pivot, tip, angle, omega, alpha)
    else:
        r.table(drv, "driver", ("slider", "position", "velocity", "acceleration"),
                required=("slider", "position", "velocity"))
        point = need_label(r.label(drv["slider"], "driver.slider"), "driver.slider")
        if point not in sliders:
            raise SceneError(f"slider driver {point} needs a guide: add [sliders.{point}]",
                             file=file, where="driver.slider")
        driver = SliderDrive(point, r.quantity(drv["position"], "length", "driver.position"),
                             r.quantity(drv["velocity"], "velocity", "driver.velocity"),
                             r.quantity(drv.get("acceleration", "0 m/s^2"), "acceleration",
                                        "driver.acceleration"))

    # assembly
    assembly: dict[str, Branch] = {}
    for label, spec in r.table(data.get("assembly", {}), "assembly",
                               tuple(data.get("assembly", {}))).items():
        where = f"assembly.{label}"
        need_label(r.label(label, where), where)
        assembly[label] = _parse_branch(label, spec, r, need_label, where)

    for label in drawn:
        need_label(label, f"drawn.{label}")

    # solve
    solve = data.get("solve", list(DIAGRAMS))
    if (not isinstance(solve, list) or not solve
            or any(s not in DIAGRAMS for s in solve)):
        raise SceneError(f"solve must be a list drawn from {list(DIAGRAMS)}, got {solve!r}",
                         file=file, where="solve")
    if "acceleration" in solve and "velocity" not in solve:
        raise SceneError("the acceleration polygon needs the velocity polygon: "
                         "solve = ['velocity', 'acceleration']", file=file, where="solve")

    default_tol = drawing_tolerance(source, r)
    answers = tuple(_parse_answer(i, a, r, default_tol) for i, a in
                    enumerate(data.get("answers", [])))

    return Scene(file=file, title=title, source=MappingProxyType(dict(source)),
                 ground=MappingProxyType(ground), links=MappingProxyType(links),
                 driver=driver, sliders=MappingProxyType(sliders),
                 slots=MappingProxyType(slots), points=MappingProxyType(points),
                 assembly=MappingProxyType(assembly), answers=answers,
                 solve=tuple(s for s in DIAGRAMS if s in solve),
                 drawn=MappingProxyType(drawn),
                 extra=MappingProxyType({k: data[k] for k in extra_keys if k in data}),
                 prescribed=MappingProxyType(prescribed))


def path_stem(file: str) -> str:
    return Path(file).stem


_RELATIONS = ("above", "below", "left of", "right of")


def _parse_branch(label, spec, r: _Reader, need_label, where) -> Branch:
    if isinstance(spec, dict):
        r.table(spec, where, ("near",), required=("near",))
        return Branch(label, f"{label} near {spec['near']}", "near",
                      near=r.vec(spec["near"], where + ".near"))
    text = r.string(spec, where)
    words = " ".join(text.split())
    for rel in _RELATIONS:
        prefix = f"{label} {rel} "
        if words.startswith(prefix) or words.startswith(f"{rel} "):
            ref = words[len(prefix):] if words.startswith(prefix) else words[len(rel) + 1:]
            if _LABEL.match(ref):
                return Branch(label, text, rel, (need_label(ref, where),))
            tokens = _LABEL_TOKEN.findall(ref)
            if "".join(tokens) == ref and len(tokens) == 2:
                return Branch(label, text, rel, tuple(need_label(t, where) for t in tokens))
            raise BranchError(f"cannot read the reference {ref!r} in {text!r}: give a point "
                              f"('{label} above B') or a line of two points ('{label} above AD')",
                              file=r.file, where=where)
    raise BranchError(f"cannot read {text!r}: write '{label} above AD', '{label} below AD', "
                      f"'{label} left of B', '{label} right of B' or near = [x, y]",
                      file=r.file, where=where)


def drawing_tolerance(source, r: _Reader) -> float:
    """The case's stated drawing tolerance (``[source] drawing_tolerance``), default 3 %."""
    if "drawing_tolerance" in source:
        return r.quantity(source["drawing_tolerance"], "fraction", "source.drawing_tolerance")
    return 0.03


ANSWER_KEYS = ("quantity", "unit", "tutorial", "exact", "mode", "sense", "tolerance", "slip",
               "ref", "desc", "note")


def answer_fields(spec, r: _Reader, where: str, default_tol: float, *,
                  extra_keys: tuple[str, ...] = (), extra_units=()) -> dict:
    """The fields every answer table shares (``[[answers]]``, ``[[force_answers]]``), checked:
    unknown keys, units, plain numbers for tutorial/exact, mode, tolerance, slip."""
    r.table(spec, where, ANSWER_KEYS + extra_keys, required=("quantity", "unit"))
    unit = r.string(spec["unit"], where + ".unit")
    if unit not in UNITS and unit not in ("-", "1") and unit not in extra_units:
        raise UnitError(f"unknown unit {unit!r}", file=r.file, where=where + ".unit")

    def number(key):
        if key not in spec:
            return None
        value = spec[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise SceneError(f"{key} must be a plain number in {unit!r}, got {value!r}",
                             file=r.file, where=f"{where}.{key}")
        return float(value)

    mode = spec.get("mode", "abs")
    if mode not in ("abs", "signed"):
        raise SceneError(f"mode must be 'abs' or 'signed', got {mode!r}", file=r.file,
                         where=where + ".mode")
    tol = default_tol
    if "tolerance" in spec:
        tol = r.quantity(spec["tolerance"], "fraction", where + ".tolerance")
    slip = spec.get("slip", False)
    if not isinstance(slip, bool):
        raise SceneError("slip must be true or false", file=r.file, where=where + ".slip")
    quantity = r.string(spec["quantity"], where + ".quantity")
    return dict(quantity=quantity, unit=unit, tutorial=number("tutorial"),
                exact=number("exact"), mode=mode, sense=spec.get("sense"), tolerance=tol,
                slip=slip, ref=spec.get("ref"), desc=spec.get("desc", quantity),
                note=spec.get("note", ""))


def _parse_answer(i: int, spec, r: _Reader, default_tol: float) -> Answer:
    return Answer(**answer_fields(spec, r, f"answers[{i}]", default_tol))


def unit_dimension(unit: str) -> str:
    if unit in ("-", "1"):
        return "fraction"
    return dimension_of(unit)


__all__ = ["Scene", "Link", "Guide", "Crank", "SliderDrive", "Slot", "BodyPoint", "Branch",
           "Answer", "load_scene", "parse_scene", "split_link_name", "PolygonsError"]
