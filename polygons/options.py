"""Scene options: the optional ``[sweep]``, ``[diagram]`` and ``[handout]`` tables.

They say how a scene is swept, drawn and printed, not what the mechanism is; they are read
and checked when the scene is loaded (so a typo in ``[sweep]`` fails on ``polygons solve``
too, naming the key) and kept as frozen values on ``Scene.options``.  The commands override
them with their own flags (``--steps``, ``--scale`` ...).

    [sweep]
    points = ["B"]      # displacement, velocity, acceleration against the input
    links = ["AB"]      # ω and α against the input
    steps = 720         # positions over the cycle
    shm = true          # overlay the simple-harmonic curve
    unit = "mm"         # display unit of length

    [diagram]
    velocity_scale = "1 cm = 2 m/s"     # or "2 m/s": SI value drawn as 1 cm
    acceleration_scale = "500 m/s^2"
    space_scale = "20 mm"
    paper = "A4"                        # A5 or A4
    stages = false                      # only the finished diagrams
    klein = true                        # also Klein's construction (or "ritterhaus", "bennett")

    [handout]
    force_polygons = true               # the force polygons per Assur group in the handout
    zhukovsky = true                    # and Zhukovsky's lever
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from .errors import PolygonsError, SceneError, UnknownKeyError, show, suggest
from .schema import Key, Table
from .units import parse_quantity

#: largest number of sweep positions accepted from a scene (memory: ~1 kB per position)
MAX_STEPS = 10_000_000
#: the diagram kinds and the quantity each one's scale measures
SCALE_QUANTITY = {"space": "length", "velocity": "velocity", "acceleration": "acceleration"}
PAPERS = ("A5", "A4")
#: the slider-crank constructions [diagram] klein names (polygons.classic.klein.METHODS)
KLEIN_METHODS = ("klein", "ritterhaus", "bennett")

TABLES: tuple[Table, ...] = (
    Table("sweep", "How `polygons sweep` solves and plots a full input revolution (its flags "
                   "override these).", (
        Key("points", "array", "point labels whose displacement, velocity and acceleration "
                               "are plotted against the input (a list, or one comma-separated "
                               "string); default: the sliders, else the last point placed",
            example='["B", "C"]'),
        Key("links", "array", "link names whose ω and α are plotted; default: every link but "
                              "the crank", example='["BC"]'),
        Key("steps", "integer", f"positions over the cycle, 2 .. {MAX_STEPS:,}", example="720",
            default=360),
        Key("shm", "bool", "overlay the simple-harmonic curve on each slider (the crank pin "
                           "projected on its guide)", example="true", default=False),
        Key("unit", "string", "display unit of length in the summary and plots: 'mm' or 'm'; "
                              "default: mm when every link is shorter than 1 m",
            example='"mm"'),
    )),
    Table("diagram", "How `polygons draw` / `solve --svg` / `handout` draw the diagrams (the "
                     "--scale and --paper flags override these).", (
        Key("space_scale", "scale", "length drawn as 1 cm of paper in the space diagram: "
                                    "'20 mm' or '1 cm = 20 mm'", example='"1 cm = 20 mm"',
            dimension="length"),
        Key("velocity_scale", "scale", "velocity drawn as 1 cm in the velocity polygon",
            example='"1 cm = 2 m/s"', dimension="velocity"),
        Key("acceleration_scale", "scale", "acceleration drawn as 1 cm in the acceleration "
                                           "polygon", example='"500 m/s^2"',
            dimension="acceleration"),
        Key("paper", "string", "paper the drawings fit: 'A5' or 'A4'; default: A5, or A4 when "
                               "a vector would be too short to read on A5", example='"A4"'),
        Key("stages", "bool", "also write the construction stage by stage "
                              "(velocity-1.svg ...)", example="false", default=True),
        Key("klein", "bool-or-string", "a slider-crank's classic construction, printed by "
                                         "`solve` and drawn by `draw` (klein.svg): true or 'klein' (Klein's, in-line "
                               "or offset), 'ritterhaus' or 'bennett' (in-line only); a crank "
                               "turning "
                               "uniformly", example="true"),
    )),
    Table("centres", "How `polygons centres` numbers the links of the circle diagram (by "
                     "default 1 the frame, 2 the driver, then in the order the construction "
                     "places them).", (
        Key("numbers", "table", "the number of each link named (2 and up; 1 is the frame): "
                                "a link's name, or a block's as the centres table names it "
                                "('slider C', 'block P2', 'collar C', 'yoke Y'); the links "
                                "not named take the numbers left, in the default order",
            example='{ O2P2 = 2, "block P2" = 3, O4P4 = 4 }'),
    )),
    Table("handout", "What `polygons handout` adds to the answer key (a scene with force "
                     "tables); any other key is refused, naming it.", (
        Key("force_polygons", "bool", "a section with the force polygons per Assur group: "
                                      "each group's finished polygon, the construction in "
                                      "words and its reactions and input effort (the "
                                      "numbers `polygons forces` prints); refused in one "
                                      "line when the construction does not handle the "
                                      "mechanism", example="true", default=False),
        Key("zhukovsky", "bool", "a section with Zhukovsky's lever: the finished lever, its "
                                 "forces and moments about the pole and the balancing "
                                 "effort (equal to the virtual work's)", example="true",
            default=False),
        Key("turning_moment", "bool", "a section with the turning-moment diagram over a "
                                      "uniform turn of the crank (360 angles): its plot, "
                                      "maximum, minimum and mean torque and the maximum "
                                      "fluctuation of energy (as `polygons forces --cycle`)",
            example="true", default=False),
    )),
)

_KEYS = {t.name: tuple(k.name for k in t.keys) for t in TABLES}


@dataclass(frozen=True)
class SweepOptions:
    """``[sweep]``: None where the scene does not say (the command's default applies)."""

    points: tuple[str, ...] | None = None
    links: tuple[str, ...] | None = None
    steps: int | None = None
    shm: bool | None = None
    unit: str | None = None


@dataclass(frozen=True)
class DiagramOptions:
    """``[diagram]``: ``scales`` maps a diagram kind to its forced scale, SI units per cm."""

    scales: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))
    paper: str | None = None
    stages: bool | None = None
    klein: str | None = None       # 'klein' | 'ritterhaus' | 'bennett' | None


@dataclass(frozen=True)
class CentresOptions:
    """``[centres]``: ``numbers`` maps a link's name to its number in the circle diagram
    (checked against the mechanism's links by :mod:`polygons.centres`)."""

    numbers: Mapping[str, int] = field(default_factory=lambda: MappingProxyType({}))


@dataclass(frozen=True)
class HandoutOptions:
    """``[handout]``: the force methods the answer key adds (:mod:`diagrams.handout_forces`)."""

    force_polygons: bool = False
    zhukovsky: bool = False
    turning_moment: bool = False


@dataclass(frozen=True)
class Options:
    sweep: SweepOptions = SweepOptions()
    diagram: DiagramOptions = DiagramOptions()
    centres: CentresOptions = CentresOptions()
    handout: HandoutOptions = HandoutOptions()


#: the options of a scene without [sweep], [diagram] or [handout]
DEFAULT = Options()


def labels(value, *, file: str | None, where: str) -> tuple[str, ...]:
    """A list of labels, or one comma-separated string of them."""
    if isinstance(value, str):
        value = [v.strip() for v in value.split(",") if v.strip()]
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise SceneError(f"expected a list of labels, e.g. [\"B\", \"C\"], got {show(value)}",
                         file=file, where=where)
    return tuple(value)


def scale_per_cm(text, quantity: str, *, file: str | None = None, where: str | None = None,
                 error=SceneError) -> float:
    """A drawing scale '2 m/s', '1 cm = 2 m/s' or '20 mm' -> SI units per cm of paper."""
    if not isinstance(text, str):
        raise error(f"a scale is text such as '1 cm = 2 m/s', got {show(text)}", file=file,
                    where=where)
    s = " ".join(text.split())
    lhs = None
    if "=" in s:
        lhs, s = (part.strip() for part in s.split("=", 1))
    per = 0.01
    if lhs is not None:
        try:
            per = parse_quantity(lhs, "length")
        except PolygonsError:
            raise error(f"cannot read the paper length {show(lhs)} in the scale {show(text)}; "
                        f"write '1 cm = 2 m/s'", file=file, where=where) from None
        if per <= 0:
            raise error(f"the paper length in {show(text)} must be positive", file=file,
                        where=where)
    try:
        value = parse_quantity(s, quantity)
    except PolygonsError as exc:
        raise error(f"bad {quantity} scale {show(text)}: {exc.reason}", file=file,
                    where=where) from None
    if not (value > 0 and math.isfinite(value)):
        raise error(f"a scale must be positive, got {show(text)}", file=file, where=where)
    return value * 0.01 / per


def _table(data, name: str, file: str) -> dict:
    table = data.get(name, {})
    if not isinstance(table, dict):
        raise SceneError(f"[{name}] must be a table, got {type(table).__name__}", file=file,
                         where=name)
    for key in table:
        if key not in _KEYS[name]:
            hint = suggest(key, _KEYS[name]) if _KEYS[name] else f"[{name}] accepts no key yet"
            raise UnknownKeyError(f"unknown key {show(key)}: {hint}", file=file,
                                  where=f"{name}.{key}")
    return table


def _bool(table, key, name, file):
    value = table.get(key)
    if value is not None and not isinstance(value, bool):
        raise SceneError(f"{key} must be true or false, got {show(value)}", file=file,
                         where=f"{name}.{key}")
    return value


def parse_options(data: Mapping, file: str) -> Options:
    """Check and read ``[sweep]``, ``[diagram]`` and ``[handout]`` of parsed TOML ``data``."""
    if not any(t in data for t in ("sweep", "diagram", "handout", "centres")):
        return DEFAULT      # what reading the empty tables gives (frozen: shared)
    sw = _table(data, "sweep", file)
    steps = sw.get("steps")
    if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int)
                              or not 2 <= steps <= MAX_STEPS):
        raise SceneError(f"steps must be a whole number from 2 to {MAX_STEPS:,}, got "
                         f"{show(steps)}", file=file, where="sweep.steps")
    unit = sw.get("unit")
    if unit is not None and unit not in ("mm", "m"):
        raise SceneError(f"unit must be 'mm' or 'm', got {show(unit)}", file=file,
                         where="sweep.unit")
    sweep = SweepOptions(
        points=labels(sw["points"], file=file, where="sweep.points") if "points" in sw else None,
        links=labels(sw["links"], file=file, where="sweep.links") if "links" in sw else None,
        steps=steps, shm=_bool(sw, "shm", "sweep", file), unit=unit)

    dg = _table(data, "diagram", file)
    scales = {}
    for kind, quantity in SCALE_QUANTITY.items():
        key = f"{kind}_scale"
        if key in dg:
            scales[kind] = scale_per_cm(dg[key], quantity, file=file, where=f"diagram.{key}")
    paper = dg.get("paper")
    if paper is not None and paper not in PAPERS:
        raise SceneError(f"paper must be one of {', '.join(PAPERS)}, got {show(paper)}",
                         file=file, where="diagram.paper")
    klein = dg.get("klein")
    if klein is True:
        klein = "klein"
    elif klein is False:
        klein = None
    elif klein is not None and klein not in KLEIN_METHODS:
        raise SceneError(f"klein must be true, false, 'klein', 'ritterhaus' or 'bennett', got "
                         f"{show(klein)}", file=file, where="diagram.klein")
    diagram = DiagramOptions(MappingProxyType(scales), paper,
                             _bool(dg, "stages", "diagram", file), klein)
    ho = _table(data, "handout", file)
    handout = HandoutOptions(bool(_bool(ho, "force_polygons", "handout", file)),
                             bool(_bool(ho, "zhukovsky", "handout", file)),
                             bool(_bool(ho, "turning_moment", "handout", file)))
    return Options(sweep, diagram, _centres(_table(data, "centres", file), file), handout)


#: the largest number a link may be given in [centres] numbers
MAX_NUMBER = 10_000


def _centres(table, file: str) -> CentresOptions:
    numbers = table.get("numbers", {})
    where = "centres.numbers"
    if not isinstance(numbers, dict):
        raise SceneError(f"numbers must be a table of link = number, e.g. "
                         f"{{ O2P2 = 2, O4P4 = 4 }}, got {show(numbers)}", file=file,
                         where=where)
    for name, n in numbers.items():
        if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= MAX_NUMBER:
            raise SceneError(f"the number of {show(name)} must be a whole number from 2 to "
                             f"{MAX_NUMBER:,} (1 is the frame), got {show(n)}", file=file,
                             where=f"{where}.{name}")
    seen: dict[int, str] = {}
    for name, n in numbers.items():
        if n in seen:
            raise SceneError(f"{show(seen[n])} and {show(name)} both have the number {n}",
                             file=file, where=where)
        seen[n] = name
    return CentresOptions(MappingProxyType(dict(numbers)))


__all__ = ["TABLES", "Options", "SweepOptions", "DiagramOptions", "CentresOptions",
           "HandoutOptions", "parse_options",
           "scale_per_cm", "labels", "MAX_STEPS"]
