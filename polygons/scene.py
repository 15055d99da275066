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
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import Any, Mapping

from . import topology
from .errors import (BranchError, PolygonsError, SceneError, SceneSyntaxError,
                     UnknownLabelError, show, suggest)
from .loadtables import READS as LOAD_READS
from .model import build as build_model
from .reader import LABEL as _LABEL, Reader, answer_fields, record, refuse_control_characters
from .reader import MAX_SCENE_BYTES, read_scene_text  # noqa: F401  (the file is read there)
from .records import (Answer, BodyPoint, Branch, Crank, Guide, Link, Quantity,  # noqa: F401
                      SliderDrive, Slot, Vec)
from .options import Options, parse_options
from .senses import alpha_words
from .units import parse_along
# TABLES: this loader's declared tables, collected as polygons.scene.TABLES by the reference
from .scene_tables import (ANSWER_KEYS, KEYS, RELATIONS, TABLES, TOP_KEYS,  # noqa: F401
                           EXTREMES as _EXTREMES, CONTACT_TABLES, book_words, circuit_refs)
from .quantity_grammar import (QUANTITY_FUNCTIONS, parse_quantity_expr,  # noqa: F401
                               _parse_answers, unit_dimension)

_LABEL_TOKEN = re.compile(r"[A-Z][a-z0-9_']*")

#: option tables, read and checked at load by :mod:`polygons.options` (``Scene.options``)
OPTION_KEYS = ("sweep", "diagram", "handout", "centres")
#: tables read by extension modules (forces, loads, pins); stored raw in ``Scene.extra`` and
#: validated by the module that uses them (it must raise SceneError subclasses itself)
EXTENSION_KEYS = ("masses", "forces", "torques", "springs", "gravity", "dynamics",
                  "force_answers", "flywheel", "efficiency", "pins", "least_velocity",
                  "pin_answers", "exam", "questions", "cam_profiles")
DIAGRAMS = ("velocity", "acceleration")
#: the text keys of [source] (where the case comes from; shown in reports and handouts)
SOURCE_TEXT = ("id", "seed", "example", "category", "statement", "conventions", "notes",
               "backsolved", "slips", "mechanism")


# ---------------------------------------------------------------- the scene
# (the records of its tables: polygons.records)
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
    options: Options = Options()
    loads: Any = None           # polygons.loads.Loads: the force tables, parsed and checked
    #: the mechanism model (polygons.model.Mechanism): bodies and pairs, read once at load
    model: Any = None
    #: pins in two moving slots at once ([crossing]; polygons.records.Crossing)
    crossing: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))
    #: second inputs: prescribed slides along a link (:mod:`polygons.topology`)
    prescribed: Mapping[str, topology.Slide] = field(
        default_factory=lambda: MappingProxyType({}))
    #: cams and curved slots replaced by their equivalent links (:mod:`polygons.contacts`)
    equivalents: tuple = ()

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
        for cr in self.crossing.values():
            seen[cr.pin] = None
            for c in cr.coincident:
                seen[c] = None
        return tuple(seen)

    def link_between(self, p: str, q: str) -> Link | None:
        for link in self.links.values():
            if {link.a, link.b} == {p, q}:
                return link
        return None


# ---------------------------------------------------------------- loading
#: a slider driver whose rate the book states as its rod's ω and α
ROD_RATE = ("rod_omega", "rod_sense", "rod_alpha", "rod_alpha_sense")


def split_link_name(name: str, *, file: str | None = None, where: str | None = None
                    ) -> tuple[str, str]:
    """'BC' -> ('B', 'C'); 'O2P2' -> ('O2', 'P2').  A label is a capital letter followed by
    lower-case letters, digits, '_' or a prime.  (A name read well is remembered.)"""
    ends = _LINK_ENDS.get(name) if name.__class__ is str else None
    if ends is not None:
        return ends
    tokens = _LABEL_TOKEN.findall(name)
    if "".join(tokens) != name or len(tokens) != 2:
        raise SceneError(f"link name {show(name)} must be its two end labels, e.g. 'BC' or 'O2P2' "
                         f"(a label is a capital letter followed by lower-case letters or "
                         f"digits)", file=file, where=where)
    if tokens[0] == tokens[1]:
        raise SceneError(f"link {show(name)} joins {tokens[0]} to itself", file=file, where=where)
    if len(_LINK_ENDS) >= 4096:         # a long run's many names: start afresh
        _LINK_ENDS.clear()
    ends = _LINK_ENDS[name] = tokens[0], tokens[1]
    return ends


_LINK_ENDS: dict[str, tuple[str, str]] = {}


_Reader = Reader     # the name the loader's helpers use


def parse_toml(text: str, file: str) -> dict:
    """The TOML ``text`` as a dict: read by rtoml (compiled, ~13× faster than tomllib on a case
    file); anything rtoml refuses is read again by ``tomllib``, whose words every failure
    gives, as a :class:`SceneSyntaxError` (rtoml's messages name no key; and where the two
    disagree, tomllib accepts it).  Without rtoml installed, tomllib reads everything."""
    fast = _rtoml()
    if fast is not None:
        try:
            data = fast.loads(text)
        except Exception:         # noqa: BLE001 - any refusal is tomllib's to explain
            pass
        else:
            refuse_control_characters(text, data, file)
            return data
    import tomllib                    # only where rtoml refuses (or is missing): a quicker start
    try:
        data = tomllib.loads(text)
        refuse_control_characters(text, data, file)
        return data
    except tomllib.TOMLDecodeError as exc:
        raise SceneSyntaxError(f"not valid TOML: {' '.join(str(exc).split())[:200]}",
                               file=file) from None
    except RecursionError:
        raise SceneSyntaxError("not a scene: arrays or tables are nested too deeply",
                               file=file) from None
    except ValueError as exc:         # e.g. an integer of more than 4300 digits
        raise SceneSyntaxError(f"not valid TOML: {' '.join(str(exc).split())[:120]}",
                               file=file) from None


def _rtoml():
    """The rtoml module, imported on first use (None without it)."""
    global _FAST
    if _FAST is False:
        try:
            import rtoml
        except ImportError:       # an optional speed-up: tomllib reads the same files
            rtoml = None
        _FAST = rtoml
    return _FAST


_FAST: Any = False          # not yet imported


def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file; every problem raises a :class:`SceneError`."""
    file = str(path)
    return parse_scene(parse_toml(read_scene_text(path), file), file=file)


#: the largest mechanism served (links; fixed, drawn, body points or sliders each), checked
#: before any work: every command on a 201-link scene takes ~10 s, growing about linearly
#: (benchmarks/large.py; README "Large mechanisms")
MAX_LINKS = 250
MAX_POINTS = 250


def parse_scene(data: dict, *, file: str = "<scene>",
                extra_keys: tuple[str, ...] = EXTENSION_KEYS) -> Scene:
    """Build a :class:`Scene` from parsed TOML ``data`` (see module docstring)."""
    if isinstance(data, dict) and "ground" not in data and _lone_wheel(data):
        data = {**data, "ground": _surface_point(data)}
    if isinstance(data, dict) and "cam_profiles" in data:     # a cam by its profile
        from . import cam_profiles              # imported only here: a quicker start
        data = cam_profiles.rewrite(data, file)
    equivalents = ()
    if isinstance(data, dict) and any(name in data for name in CONTACT_TABLES):
        from . import contacts                  # imported only here: a quicker start
        data, equivalents = contacts.rewrite(data, file)
    r = _Reader(file)
    r.table(data, "", TOP_KEYS + ("crossing",) + OPTION_KEYS + extra_keys,
            required=("ground", "driver"))
    for table, most in (("links", MAX_LINKS), ("ground", MAX_POINTS), ("drawn", MAX_POINTS),
                        ("points", MAX_POINTS), ("sliders", MAX_POINTS)):
        if isinstance(data.get(table), dict) and len(data[table]) > most:
            raise SceneError(f"{len(data[table]):,} {table}: at most {most} are served (every "
                             f"command's cost is measured up to this size)", file=file,
                             where=table)
    options = parse_options(data, file)
    title = r.string(data["title"], "title") if "title" in data else path_stem(file)
    source = data.get("source", {})
    r.table(source, "source", KEYS["source"])
    for key in SOURCE_TEXT:
        if key in source and not isinstance(source[key], str):
            r.string(source[key], f"source.{key}")      # refused, naming the key
    if not isinstance(source.get("synthetic", False), bool):
        raise SceneError("synthetic must be true or false", file=file, where="source.synthetic")

    # ground
    ground_raw = r.named(data["ground"], "ground")
    ground = {}
    for name, value in ground_raw.items():
        where = f"ground.{name}"
        ground[r.label(name, where)] = (topology.ground_from(value, r, where, ground)
                                        if isinstance(value, dict) else r.vec(value, where))
    if not ground:
        raise SceneError("at least one fixed pivot is needed", file=file, where="ground")

    # the space diagram as drawn: coordinates of moving points at this instant
    drawn_raw = r.named(data.get("drawn", {}), "drawn")
    drawn = {r.label(k, f"drawn.{k}"): r.vec(v, f"drawn.{k}") for k, v in drawn_raw.items()}
    placed = {**drawn, **ground}

    # links
    links_raw = r.named(data.get("links", {}), "links")
    links: dict[str, Link] = {}
    for name, value in links_raw.items():
        a, b = split_link_name(name, file=file, where=f"links.{name}")
        if value == "drawn":
            missing = [p for p in (a, b) if p not in placed]
            if missing:
                raise SceneError(f"length 'drawn' needs the positions of {a} and {b}; "
                                 f"{' and '.join(missing)} not in [ground] or [drawn]",
                                 file=file, where=f"links.{name}")
            length = math.dist(placed[a], placed[b])
            if not length > 0:
                raise SceneError(f"length 'drawn' is zero: {a} and {b} are drawn at the same "
                                 f"place", file=file, where=f"links.{name}")
            links[name] = Link(name, a, b, length)
            continue
        length = r.quantity(value, "length", f"links.{name}")
        if not link_length_ok(length):
            raise SceneError(link_length_problem(length, show(value)), file=file,
                             where=f"links.{name}")
        links[name] = record(Link, name=name, a=a, b=b, length=length)

    # slots
    slots: dict[str, Slot] = {}
    for pin, spec in r.named(data.get("slots", {}), "slots").items():
        where = f"slots.{pin}"
        r.label(pin, where)
        r.table(spec, where, KEYS["slots"], required=("lever",))
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
        slots[pin] = Slot(pin, lever, pivot, coincident, far, far_length, offset,
                          topology.slot_length(spec, r, where))

    # extra body points
    points: dict[str, BodyPoint] = {}
    for label, spec in r.named(data.get("points", {}), "points").items():
        where = f"points.{label}"
        r.label(label, where)
        r.table(spec, where, KEYS["points"], required=("on",))
        on = r.string(spec["on"], where + ".on")
        split_link_name(on, file=file, where=where + ".on")
        side = topology.plate_side(split_link_name(on), links, points)
        if side is not None and on not in links \
                and not any(s.lever == on for s in slots.values()):
            points[label] = BodyPoint(label, side[0], *topology.on_side(spec, r, where, side))
            continue
        if on not in links and not any(s.lever == on for s in slots.values()):
            raise UnknownLabelError(f"link {show(on)} is not defined: "
                                    f"{suggest(on, list(links) + [s.lever for s in slots.values()])}",
                                    file=file, where=where + ".on")
        along, fraction, left = topology.point_on_link(
            spec, r, where, links[on].length if on in links else None)
        points[label] = BodyPoint(label, on, along, fraction, left)

    known = set(ground)
    for link in links.values():
        known |= {link.a, link.b}
    for slot in slots.values():
        known |= {slot.pivot, slot.coincident}
    known |= set(points)

    def need_label(label: str, where: str) -> str:
        if label not in known:
            raise UnknownLabelError(f"unknown point {show(label)}: {suggest(label, known)}",
                                    file=file, where=where)
        return label

    slider_labels = set(data.get("sliders", {})) if isinstance(data.get("sliders"), dict) \
        else set()
    for slot in slots.values():
        if slot.pin not in known and slot.pin not in slider_labels:
            raise SceneError(f"the pin {slot.pin} sliding in the slot of {slot.lever} is on no "
                             f"link: make it the end of a link (a crank, a rocker) or a point "
                             f"of one in [points]", file=file, where=f"slots.{slot.pin}")

    # sliders
    sliders: dict[str, Guide] = {}
    for label, spec in r.named(data.get("sliders", {}), "sliders").items():
        where = f"sliders.{label}"
        r.table(spec, where, KEYS["sliders"], required=("direction",))
        through = topology.guide_through(spec, r, where, ground)
        if through is None:
            r.table(spec, where, tuple(spec), required=("through",))
            through = r.vec(spec["through"], where + ".through")
        angle = r.quantity(spec["direction"], "angle", where + ".direction", reduce=True)
        if "pin" in spec or "slot" in spec:
            # a Scotch yoke: this slider carries a straight slot in which a placed pin slides
            if "pin" not in spec or "slot" not in spec:
                raise SceneError("a slider carrying a slot (Scotch yoke) needs both pin = "
                                 "\"P\" (the pin sliding in the slot) and slot = \"0 deg\" "
                                 "(the slot's direction)", file=file, where=where)
            r.label(label, where)
            pin = need_label(r.label(spec["pin"], where + ".pin"), where + ".pin")
            slot_angle = r.quantity(spec["slot"], "angle", where + ".slot", reduce=True)
            if abs(math.sin(slot_angle - angle)) < 1e-9:
                raise SceneError("the slot is parallel to the yoke's guide, so the pin does "
                                 "not fix the yoke; give the slot another direction",
                                 file=file, where=where + ".slot")
            known.add(label)
            sliders[label] = Guide(through, angle, pin, slot_angle)
        else:
            drv_raw = data.get("driver")
            if label in slots or (isinstance(drv_raw, dict) and drv_raw.get("slider") == label
                                  and label not in known):
                # the pin of a slot driven along a fixed guide (a collar on a screw moving a
                # slotted arm), or a lone block driven along its guide (a plate under a
                # rolling cylinder: [rolling] on / opposite)
                known.add(r.label(label, where))
            else:
                need_label(r.label(label, where), where)
            sliders[label] = Guide(through, angle)

    # crossing slots: a pin in the slots of two moving levers
    crossing = {}
    for pin, spec in r.named(data.get("crossing", {}), "crossing").items():
        if pin in slots or pin in sliders or pin in crossing:
            raise SceneError(f"{pin} already slides in a slot or on a guide; a pin in two "
                             f"slots is stated once, in [crossing.{pin}]", file=file,
                             where=f"crossing.{pin}")
        cr = topology.parse_crossing(pin, spec, r, links, known | set(sliders))
        crossing[pin] = cr
        known |= {pin, *cr.coincident}

    # driver
    drv = data["driver"]
    r.table(drv, "driver", KEYS["driver"])
    if "wheel" in drv:              # (contacts.rewrite turns a stated wheel into its input)
        raise SceneError(f"wheel = {show(drv['wheel'])} needs its [rolling] table: "
                         f"[rolling.W] radius, through, direction", file=file,
                         where="driver.wheel")
    drv = topology.lever_as_crank(drv, r, data.get("slots", {}), data.get("links", {}))
    prescribed = {}
    if "slide" in drv:
        sl = topology.parse_slide(drv["slide"], r, links, split_link_name,
                                  labels=known | set(sliders))
        prescribed[sl.point] = sl
        known |= {sl.point, sl.coincident}
        drv = {k: v for k, v in drv.items() if k != "slide"}
    if ("crank" in drv) == ("slider" in drv):
        raise SceneError("the driver is either a crank (crank = \"OA\") or a slider "
                         "(slider = \"C\"): give exactly one", file=file, where="driver")
    driver: Crank | SliderDrive
    rod = None                  # a slider driver placed by its rod: topology.rod_of's
    if "crank" in drv:
        r.table(drv, "driver", ("crank", "angle", "omega", "speed", "sense", "alpha",
                                "alpha_sense"), required=("crank",))
        name = r.string(drv["crank"], "driver.crank")
        pivot, tip = split_link_name(name, file=file, where="driver.crank")
        if name not in links and f"{tip}{pivot}" in links:
            name = f"{tip}{pivot}"      # written the other way round in [links]
        elif name not in links:
            raise UnknownLabelError(f"crank {show(name)} is not a link in [links]: "
                                    f"{suggest(name, links)}", file=file, where="driver.crank")
        if pivot not in ground:
            raise SceneError(f"the crank turns about its first label {pivot}, which must be a "
                             f"fixed pivot in [ground] ({', '.join(ground)}); write the crank "
                             f"with its pivot first", file=file, where="driver.crank")
        omega, turn = topology.crank_rate(drv, r, links[name].length)
        if turn is not None:
            omega *= turn
        elif omega != 0.0:   # a crank at rest has no sense of rotation
            raise SceneError("missing key 'sense' (required: crank, omega, sense — or the sense "
                             "in omega, '300 rad/s CW'; only a crank at rest, omega = 0, may "
                             "leave it out)", file=file, where="driver")
        alpha = 0.0
        if "alpha" in drv:
            drv = alpha_words(drv, omega, file)
            alpha, turn = topology.rate_with_sense(drv, "alpha", "alpha_sense",
                                                  "angular_acceleration", r)
            if alpha != 0.0:
                if turn is None:
                    raise SceneError("alpha needs alpha_sense = 'CW' or 'CCW' (the sense of the "
                                     "angular acceleration, not of the rotation), or the sense "
                                     "in alpha, '80 rad/s^2 CCW'", file=file,
                                     where="driver.alpha_sense")
                alpha *= turn
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
        driver = record(Crank, link=name, pivot=pivot, tip=tip, angle=angle, omega=omega,
                        alpha=alpha, stated=topology.stated_from(drv.get("angle"), angle,
                                                                 omega, r))
    else:
        r.table(drv, "driver", ("slider", "position", "velocity", "acceleration", "rod",
                                "rod_angle") + ROD_RATE, required=("slider",))
        point = need_label(r.label(drv["slider"], "driver.slider"), "driver.slider")
        if ("velocity" in drv) == ("rod_omega" in drv):
            raise SceneError("give the slider driver's velocity (velocity = \"2 m/s\"), or its "
                             "rod's angular velocity (rod_omega = \"2 rad/s CW\", with rod and "
                             "rod_angle): exactly one", file=file, where="driver")
        if any(k in drv for k in ROD_RATE) and not ("rod_omega" in drv and "rod" in drv):
            raise SceneError("rod_sense, rod_alpha and rod_alpha_sense go with rod_omega, rod "
                             "and rod_angle", file=file, where="driver")
        if "rod_omega" in drv and "acceleration" in drv:
            raise SceneError("with rod_omega, give the rod's rod_alpha (the slider's "
                             "acceleration follows from it), not acceleration", file=file,
                             where="driver.acceleration")
        if point not in sliders:
            raise SceneError(f"slider driver {point} needs a guide: add [sliders.{point}]",
                             file=file, where="driver.slider")
        if ("position" in drv) == ("rod" in drv or "rod_angle" in drv):
            raise SceneError("place the slider driver by its position (position = \"150 mm\") "
                             "or by the angle of its rod (rod = \"BA\", rod_angle = "
                             "\"30 deg\"): give exactly one", file=file, where="driver")
        rod = (topology.rod_of(drv, r, point, links, split_link_name) if "position" not in drv
               else None)                       # (name, link, far end, far end − slider)
        position = (r.quantity(drv["position"], "length", "driver.position")
                    if rod is None else topology.slider_by_rod(
                        rod, r, point, sliders, links, ground, data.get("assembly", {}),
                        slots))
        if "rod_omega" in drv:          # the book gives the rod's ω and α
            v, a, stated, meet = topology.slider_rate_by_rod(drv, rod, r, point, position,
                                                             sliders, links, ground)
            driver = SliderDrive(point, position, v, a, rod_rate=stated, rod_angle_deg=meet)
        else:
            e = sliders[point].direction        # '2 m/s to the left' along the guide
            driver = SliderDrive(point, position,
                                 parse_along(drv["velocity"], "velocity", e, file=file,
                                             where="driver.velocity"),
                                 parse_along(drv.get("acceleration", "0 m/s^2"), "acceleration",
                                             e, file=file, where="driver.acceleration"))

    # assembly
    assembly: dict[str, Branch] = {}
    for label, spec in r.named(data.get("assembly", {}), "assembly").items():
        where = f"assembly.{label}"
        need_label(r.label(label, where), where)
        said = " ".join(spec.split()) if isinstance(spec, str) else ""
        circuit = circuit_refs(label, said[len(label) + 1:] if said.startswith(label + " ")
                               else said, links, ground)           # 'C open', 'C crossed'
        if circuit and circuit[1] is None:
            raise BranchError(f"'{said}' names a four-bar's circuit: {label} must join a fixed "
                              f"pivot D and the end B of a link AB turning about another fixed "
                              f"pivot A; say '{label} above ...' or near = [x, y]", file=file,
                              where=where)
        assembly[label] = record(Branch, label=label, text=spec, relation=circuit[0],
                                 ref=circuit[1], near=None) if circuit else \
            _parse_branch(label, spec, r, need_label, where)

    if isinstance(driver, SliderDrive) and rod is not None:
        # the rod's stated angle says where its other end is: that closure, unless stated
        name, _, other, (rx, ry) = rod
        g = sliders[driver.point]
        if other not in assembly and other not in ground:
            assembly[other] = Branch(other, f"{other} where {name} at its stated angle puts it",
                                     "near", near=(g.through[0] + driver.position
                                                   * math.cos(g.angle) + rx,
                                                   g.through[1] + driver.position
                                                   * math.sin(g.angle) + ry))
        elif other in assembly:         # the words must agree with the angle (position.py)
            driver = replace(driver, rod_end=(name, other, math.atan2(ry, rx),
                                              driver.position))

    for label in drawn:
        need_label(label, f"drawn.{label}")

    # solve
    solve = data.get("solve", list(DIAGRAMS))
    if (not isinstance(solve, list) or not solve
            or any(s not in DIAGRAMS for s in solve)):
        raise SceneError(f"solve must be a list drawn from {list(DIAGRAMS)}, got {show(solve)}",
                         file=file, where="solve")
    if "acceleration" in solve and "velocity" not in solve:
        raise SceneError("the acceleration polygon needs the velocity polygon: "
                         "solve = ['velocity', 'acceleration']", file=file, where="solve")

    default_tol = drawing_tolerance(source, r)
    answers_raw = data.get("answers", [])
    if not isinstance(answers_raw, list):
        raise SceneError("answers must be an array of tables: [[answers]]", file=file,
                         where="answers")
    answers = _parse_answers(answers_raw, r, default_tol)

    check_proportions(file, ground, drawn, links, sliders, points, assembly, driver,
                      contacts=_contact_radii(equivalents))

    # the joint tables read once into bodies and pairs: every method reads this model
    model = build_model(ground=ground, links=links, sliders=sliders, slots=slots,
                        points=points, prescribed=prescribed, driver=driver,
                        crossing=crossing,
                        along_lever=lambda slot: bool(slot.offset) or topology.guided_pin_in(
                            links, driver, slot),
                        wheel_pins={q.at: tuple(p for p, _, _ in q.rim)
                                    for q in equivalents if q.kind == "rolling" and q.driven})
    # (every field of Scene, set at once; loads set below, before the scene is handed out)
    scene = record(Scene, file=file, title=title, source=MappingProxyType(dict(source)),
                   ground=MappingProxyType(ground), links=MappingProxyType(links),
                   driver=driver, sliders=MappingProxyType(sliders),
                   slots=MappingProxyType(slots), points=MappingProxyType(points),
                   assembly=MappingProxyType(assembly), answers=answers,
                   solve=DIAGRAMS if "solve" not in data else tuple(
                       [s for s in DIAGRAMS if s in solve]),
                   drawn=MappingProxyType(drawn),
                   extra=MappingProxyType({k: data[k] for k in extra_keys if k in data}),
                   options=options, loads=None, prescribed=MappingProxyType(prescribed),
                   model=model, crossing=MappingProxyType(crossing), equivalents=equivalents)
    # the force tables ([masses], [forces], ...), parsed and checked now (polygons.loads)
    # (read off the scene without them, then a new record with them: never set afterwards)
    # (polygons.loads, the tables' readers, imported only for a scene that has one of them)
    if any(k in scene.extra for k in LOAD_READS):
        from .loads import parse as parse_loads
        loads = parse_loads(scene, lambda spec, where, **kw: answer_fields(
            spec, r, where, default_tol, **kw))
    else:
        from .loadbodies import without_tables
        loads = without_tables(scene)
    scene = record(Scene, **{**vars(scene), "loads": loads})
    # (the tables' modules imported only for a scene that has them: a quicker start)
    if "exam" in scene.extra:
        from .exam_table import spec as exam_spec
        exam_spec(scene, parse_quantity_expr)      # [exam], checked now (polygons.exam_table)
    if "questions" in scene.extra:
        from .question_table import check as check_questions
        check_questions(scene, parse_quantity_expr, default_tol)   # [[questions]]
    return scene


def _contact_radii(equivalents) -> dict:
    """table.label.radius -> radius of each equivalent link's contact (for the proportions)."""
    if not equivalents:
        return {}
    from .contacts import TABLE_OF
    return {f"{TABLE_OF[q.kind]}.{q.at}.radius": q.radius for q in equivalents}


def _lone_wheel(data) -> bool:
    """A wheel rolling on a fixed surface and driving itself ([driver] wheel): the surface is
    its frame, so the book states no fixed pivot (a lone wheel, its centre O)."""
    drv, rolling = data.get("driver"), data.get("rolling")
    return (isinstance(drv, dict) and isinstance(drv.get("wheel"), str)
            and isinstance(rolling, dict) and isinstance(rolling.get(drv["wheel"]), dict)
            and "through" in rolling[drv["wheel"]])


def _surface_point(data) -> dict:
    """The frame of a lone wheel: its surface's ``through`` point, labelled G (the ground; G1,
    G2 ... where the scene uses G), a fixed point of the surface (velocity and acceleration
    zero — not the wheel's point in contact, whose acceleration is r ω²)."""
    used = set(re.findall(r"[A-Z][a-z0-9_']*", repr(data)))
    label = next(x for x in ("G", *(f"G{k}" for k in range(1, 100))) if x not in used)
    return {label: data["rolling"][data["driver"]["wheel"]]["through"]}


#: the smallest link length or offset accepted, as a fraction of the mechanism's size, and the
#: farthest a coordinate may lie from the origin, as a multiple of it: within these the
#: constructions' tolerances (relative to the size) separate a point from a line
MIN_RELATIVE = 1e-6
#: the shortest link accepted (m)
MIN_LENGTH = 1e-9


def link_length_ok(length):
    """Whether a link length (m; a number or an array of them) is one the constructions
    compute with: at least :data:`MIN_LENGTH` — the one rule for a scene file's [links] and
    the rows of :func:`polygons.solve_many`."""
    return length >= MIN_LENGTH


def link_length_problem(length: float, shown: str) -> str:
    """Why ``length`` (shown to the user as ``shown``) is not a link length."""
    if not length > 0:
        return f"length must be positive, got {shown}"
    return (f"{shown} is too small to compute with: a link must be at least {MIN_LENGTH:g} m "
            f"long")
MAX_RELATIVE = 1e6
#: the farthest a point of [points] may lie from its link's first label, as a multiple of the
#: mechanism's size: farther, the mechanism shrinks to nothing in every drawing
MAX_POINT_RELATIVE = 1e4


def check_proportions(file, ground, drawn, links, sliders, points, assembly, driver,
                      contacts: dict[str, float] | None = None) -> None:
    """Lengths and coordinates within a stated range relative to the mechanism's size.

    size = the longest link, or the largest distance between two fixed or drawn points (or a
    slider driver's position).  Every link length and point offset must be zero or at least
    ``MIN_RELATIVE`` × size; every coordinate at most ``MAX_RELATIVE`` × size from the origin.
    (Checked in that order; the key of a refused value is named only then.)
    """
    places = [*ground.values(), *drawn.values()]
    size = max([link.length for link in links.values()]
               + [math.dist(p, q) for p in places for q in places]
               + [abs(driver.position) if isinstance(driver, SliderDrive) else 0.0])
    if not size > 0:        # a lone block (a plate under a rolling cylinder): its guide's
        size = max([math.dist(p, g.through) for p in places for g in sliders.values()]
                   + list((contacts or {}).values()))     # offset, or a wheel's radius
    if not size > 0:
        raise SceneError("the mechanism has no size: every link length and distance between "
                         "pivots is zero", file=file, where="links")
    shortest = MIN_RELATIVE * size
    for name, link in links.items():
        if abs(link.length) < shortest:
            _too_short(file, f"links.{name}", link.length, size)
    for key, radius in (contacts or {}).items():      # a wheel's, a cam's, a slot's radius
        if radius < shortest:
            _too_short(file, key, radius, size)
    for key in ("along", "left"):
        for label, point in points.items():
            value = getattr(point, key)
            if value and abs(value) < shortest:
                _too_short(file, f"points.{label}.{key}", value, size)
    for label, point in points.items():
        link = links.get(point.link)
        reach = math.hypot((point.along or 0.0) + (point.fraction or 0.0) * (
            link.length if link is not None and link.length else size), point.left or 0.0)
        if reach > MAX_POINT_RELATIVE * size:
            raise SceneError(f"the point lies {reach:.4g} m from {point.link}'s first label, too "
                             f"far for a mechanism of size {size:.4g} m: a point of [points] "
                             f"must be within {MAX_POINT_RELATIVE:g} × the size",
                             file=file, where=f"points.{label}")
    farthest = MAX_RELATIVE * size
    for table, suffix, values in (
            ("ground", "", ground.items()), ("drawn", "", drawn.items()),
            ("sliders", ".through", ((k, g.through) for k, g in sliders.items())),
            ("assembly", ".near", ((k, b.near) for k, b in assembly.items() if b.near))):
        for key, (x, y) in values:
            if abs(x) > farthest or abs(y) > farthest:
                where = f"{table}.{key}{suffix}"
                raise SceneError(f"({x:.4g}, {y:.4g}) m lies too far from the origin for a "
                                 f"mechanism of size {size:.4g} m: coordinates must be within "
                                 f"{MAX_RELATIVE:g} × the size", file=file, where=where)


def _too_short(file, where, value, size):
    raise SceneError(f"{value:.4g} m is too short beside the mechanism's size "
                     f"{size:.4g} m: lengths must be at least {MIN_RELATIVE:g} of the "
                     f"size (or zero for an offset)", file=file, where=where)


def path_stem(file: str) -> str:
    return Path(file).stem


_RELATIONS = RELATIONS

def _parse_branch(label, spec, r: _Reader, need_label, where) -> Branch:
    if isinstance(spec, dict):
        r.table(spec, where, ("near",), required=("near",))
        near = r.vec(spec["near"], where + ".near")      # stated as the book would: in mm
        # a coordinate below 1e-9 of the other is rounding noise (a point computed on a
        # vertical line: x = 6e-18 m), written 0 as the book would
        big = max(abs(v) for v in near)
        mm = ", ".join(f"{(v if abs(v) > 1e-9 * big else 0.0) * 1000:.6g}".replace("-", "−")
                       for v in near)
        return Branch(label, f"{label} near ({mm}) mm", "near", near=near)
    text = r.string(spec, where)
    words = " ".join(text.split())
    # '{label} {rel} REF' or '{rel} REF' (a label starts upper-case, a relation lower-case)
    head = label + " "
    rest = words[len(head):] if words.startswith(head) else words
    if rest in _EXTREMES:                       # 'D uppermost': of its group's corners
        return record(Branch, label=label, text=text, relation=_EXTREMES[rest], ref=(),
                      near=None)
    rest = book_words(rest)                     # the book's other phrasings
    for rel in _RELATIONS:
        if rest.startswith(rel) and rest[len(rel):len(rel) + 1] == " ":
            ref = rest[len(rel) + 1:]
            if _LABEL.match(ref):
                return record(Branch, label=label, text=text, relation=rel,
                              ref=(need_label(ref, where),), near=None)
            tokens = _LABEL_TOKEN.findall(ref)
            if len(tokens) == 2 and tokens[0] + tokens[1] == ref:
                return record(Branch, label=label, text=text, relation=rel,
                              ref=(need_label(tokens[0], where), need_label(tokens[1], where)),
                              near=None)
            raise BranchError(f"cannot read the reference {show(ref)} in {show(text)}: give a point "
                              f"('{label} above B') or a line of two points ('{label} above AD')",
                              file=r.file, where=where)
    raise BranchError(f"cannot read {show(text)}: write '{label} above AD', '{label} below AD', "
                      f"'{label} left of B', '{label} right of B' or near = [x, y]",
                      file=r.file, where=where)


def drawing_tolerance(source, r: _Reader) -> float:
    """The case's stated drawing tolerance (``[source] drawing_tolerance``), default 3 %."""
    if "drawing_tolerance" in source:
        return r.quantity(source["drawing_tolerance"], "fraction", "source.drawing_tolerance")
    return 0.03


__all__ = ["Scene", "Link", "Guide", "Crank", "SliderDrive", "Slot", "BodyPoint", "Branch",
           "Answer", "load_scene", "parse_scene", "split_link_name", "PolygonsError"]
