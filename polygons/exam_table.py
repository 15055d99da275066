"""The scene's ``[exam]`` table: what `polygons exam` varies, what it asks, how well
conditioned every variant must be.  Read and checked when the scene is loaded (a typo fails
every command, naming the key); kept raw in ``Scene.extra`` and read again, cheaply, by
:func:`spec` when a command needs it.

    [exam]
    AB = "40..60 mm step 5"          # a link's length: LOW..HIGH UNIT step STEP
    angle = "20..70 deg step 5"      # the crank's angle, ω and α (a crank driver)
    omega = "10..30 rad/s step 2"
    title = "Four-bar linkage"      # each variant's heading (+ its number)
    ask = ["omega(BC)", "a(C)"]      # default: the scene's [[answers]] that can be drawn
    min_angle = "30 deg"             # smallest construction intersection angle
    closure_margin = "15 deg"        # smallest angle of the assembly (distance to the other
                                     # closure and to a toggle)
    min_vector = "8 mm"              # shortest asked vector on paper at the round scale
    attempts = 200                   # draws per variant before giving up

Every value a range gives is written back into the scene as the text ``"45 mm"`` (exact decimal
arithmetic), so a variant is an ordinary scene.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation

from .errors import SceneError, show
from .reader import Reader
from .schema import Key, Table
from .units import parse_quantity

#: most values one range may give, and most draws per variant (`attempts`)
MAX_RANGE_VALUES = 10_000
MAX_ATTEMPTS = 10_000
#: the driver's keys a range may vary, and the dimension of each
DRIVER_KEYS = {"angle": "angle", "omega": "angular_velocity", "alpha": "angular_acceleration"}
#: ... and a slider driver's (the rod's ω and α where the scene gives the rate that way)
SLIDER_KEYS = {"position": "length", "velocity": "velocity", "acceleration": "acceleration",
               "rod_angle": "angle", "rod_omega": "angular_velocity",
               "rod_alpha": "angular_acceleration"}
#: quantity functions an exam may ask (a number read off the polygons)
ASKABLE = ("v", "a", "an", "at", "omega", "alpha", "vs", "as", "cor")
DEFAULTS = {"min_angle": "30 deg", "closure_margin": "15 deg", "min_vector": "8 mm",
            "min_ratio": 5, "pose_margin": "5 deg", "attempts": 200, "partial": "50 %",
            "partial_factor": 3}
#: keys whose range is a magnitude (the sense stays the scene's)
MAGNITUDES = ("omega", "alpha", "rod_omega", "rod_alpha")

_RANGE = re.compile(r"^\s*([-+]?\d+(?:\.\d+)?)\s*\.\.\s*([-+]?\d+(?:\.\d+)?)\s*(.*?)\s+"
                    r"step\s+(\d+(?:\.\d+)?)\s*$")

TABLES: tuple[Table, ...] = (
    Table("exam", "What `polygons exam` varies from variant to variant (ranges), which answers "
                  "it asks and how well conditioned each variant must be.", (
        Key("<LINK>", "string", "a range of the link's length: 'LOW..HIGH UNIT step STEP' "
                                "(every value LOW, LOW+STEP, ... up to HIGH; at most "
                                f"{MAX_RANGE_VALUES:,})", example='"40..60 mm step 5"'),
        Key("angle", "string", "a range of the crank angle (as [driver] angle, CCW from +x)",
            example='"20..70 deg step 5"'),
        Key("omega", "string", "a range of the crank's ω (its sense stays the scene's)",
            example='"10..30 rad/s step 2"'),
        Key("alpha", "string", "a range of the crank's α (its sense stays the scene's)",
            example='"0..100 rad/s^2 step 10"'),
        Key("position", "string", "a slider driver's position along its guide (one placed by "
                                  "position)", example='"80..160 mm step 10"'),
        Key("velocity", "string", "a slider driver's velocity along its guide (signed)",
            example='"1..3 m/s step 0.5"'),
        Key("acceleration", "string", "a slider driver's acceleration along its guide (signed)",
            example='"-5..5 m/s^2 step 1"'),
        Key("rod_angle", "string", "the angle of a slider driver's rod (one placed by rod and "
                                   "rod_angle)", example='"120..160 deg step 5"'),
        Key("rod_omega", "string", "the rod's ω of a slider driven by rod_omega (its sense "
                                   "stays the scene's)", example='"1..4 rad/s step 0.5"'),
        Key("rod_alpha", "string", "the rod's α of a slider driven by rod_omega (its sense "
                                   "stays the scene's)", example='"0..5 rad/s^2 step 1"'),
        Key("title", "string", "the heading of every variant (its number is added): the "
                               "scene's title and problem statement may quote values a "
                               "variant changes, so neither is carried over",
            example='"Quick-return mechanism"', default="Exam"),
        Key("ask", "array", "the quantities asked, in textbook notation (v, a, an, at, omega, "
                            "alpha, vs, as, cor); default: the scene's [[answers]] of those "
                            "kinds", example='["omega(BC)", "a(C)"]'),
        Key("min_angle", "quantity", "smallest intersection angle of the velocity and "
                                     "acceleration constructions a variant may have",
            example='"30 deg"', dimension="angle", default=DEFAULTS["min_angle"]),
        Key("closure_margin", "quantity", "smallest angle of the assembly construction (how "
                                          "far the variant is from the other closure and "
                                          "from a toggle)", example='"15 deg"',
            dimension="angle", default=DEFAULTS["closure_margin"]),
        Key("min_vector", "quantity", "shortest asked vector on paper at the variant's round "
                                      "drawing scale", example='"8 mm"', dimension="length",
            default=DEFAULTS["min_vector"]),
        Key("min_ratio", "number", "smallest ratio of every asked answer to its full tolerance "
                                   "(2 .. 100, and more than partial_factor: the partial band "
                                   "never reaches zero, so no answer is rounding noise and "
                                   "every sign is meaningful; default 5, or partial_factor "
                                   "+ 1 when that is more)", example="5",
            default=DEFAULTS["min_ratio"]),
        Key("pose_margin", "quantity", "how far the pose must be from a dead centre (a moving "
                                       "link or slider at rest) and from a change point (an "
                                       "asked signed answer changing sign), as a turn of the "
                                       "driving crank or rod (a slider placed by position: "
                                       "that arc of its longest link)", example='"5 deg"',
            dimension="angle", default=DEFAULTS["pose_margin"]),
        Key("attempts", "integer", f"draws per variant before giving up, 1 .. {MAX_ATTEMPTS:,}",
            example="200", default=DEFAULTS["attempts"]),
        Key("partial", "quantity", "credit of the second, wider answer of each numerical "
                                   "question", example='"50 %"', dimension="fraction",
            default=DEFAULTS["partial"]),
        Key("partial_factor", "number", "the wider answer's tolerance, as a multiple of the "
                                        "drawing tolerance (1 .. 20)", example="3",
            default=DEFAULTS["partial_factor"]),
    )),
)

_FIXED = tuple(k.name for k in TABLES[0].keys if not k.name.startswith("<")
               and k.name not in DRIVER_KEYS and k.name not in SLIDER_KEYS)


@dataclass(frozen=True)
class Range:
    """One varied value: the scene key it replaces and every value it may take, as text."""
    key: str                  # 'links.AB', 'driver.angle'
    name: str                 # as written in [exam]: 'AB', 'angle'
    dimension: str
    values: tuple[str, ...]   # '40 mm', '45 mm', ...


@dataclass(frozen=True)
class ExamSpec:
    ranges: tuple[Range, ...]
    ask: tuple[str, ...]
    title: str
    min_angle_deg: float
    closure_margin_deg: float
    min_vector_mm: float
    attempts: int
    min_ratio: float
    pose_margin_deg: float
    partial: float
    partial_factor: float


def _range(text, name: str, dimension: str, r: Reader, where: str) -> Range:
    m = _RANGE.match(text) if isinstance(text, str) else None
    if not m:
        raise SceneError(f"write a range as 'LOW..HIGH UNIT step STEP', e.g. "
                         f"'40..60 mm step 5', got {show(text)}", file=r.file, where=where)
    try:
        lo, hi, step = Decimal(m.group(1)), Decimal(m.group(2)), Decimal(m.group(4))
    except InvalidOperation:  # pragma: no cover - the pattern admits only decimals
        raise SceneError(f"cannot read the range {show(text)}", file=r.file, where=where)
    unit = m.group(3)
    for part in (m.group(1), m.group(2)):      # the unit is right for this key, the ends finite
        r.quantity(f"{part} {unit}", dimension, where)
    if step <= 0 or hi < lo:
        raise SceneError(f"a range runs from LOW up to HIGH by a positive step, got "
                         f"{show(text)}", file=r.file, where=where)
    count = int((hi - lo) / step) + 1
    if count > MAX_RANGE_VALUES:
        raise SceneError(f"{show(text)} gives {count:,} values; at most "
                         f"{MAX_RANGE_VALUES:,}", file=r.file, where=where)
    values = tuple(f"{(lo + k * step).normalize():f} {unit}" for k in range(count))
    return Range(where.replace("exam.", ""), name, dimension, values)


def _magnitude(rg: Range, name: str, text, scene, where: str) -> None:
    """ω and α ranges are magnitudes: the sense is the scene's [driver] sense."""
    if name in MAGNITUDES and rg.values[0].lstrip().startswith("-"):
        raise SceneError(f"{name} = {show(text)} gives negative values: a range of {name} is "
                         f"a magnitude (the sense stays the scene's [driver] sense); write it "
                         f"from 0 up, e.g. \"10..30 rad/s step 2\"", file=scene.file,
                         where=where)


def spec(scene, parse_expr=None) -> ExamSpec | None:
    """The scene's ``[exam]``, checked against the scene (None when it has none).
    ``parse_expr`` checks an asked quantity's grammar (the loader passes its own)."""
    raw = scene.extra.get("exam")
    if raw is None:
        return None
    r = Reader(scene.file)
    r.named(raw, "exam")
    ranges = []
    for name, value in raw.items():
        where = f"exam.{name}"
        if name in _FIXED:
            continue
        if name in DRIVER_KEYS:
            if getattr(scene.driver, "omega", None) is None or not hasattr(scene.driver,
                                                                             "pivot"):
                raise SceneError(f"{name} varies a crank driver's {name}; this scene's driver "
                                 f"is not a crank", file=scene.file, where=where)
            rg = _range(value, name, DRIVER_KEYS[name], r, where)
            _magnitude(rg, name, value, scene, where)
            ranges.append(Range(f"driver.{name}", name, rg.dimension, rg.values))
        elif name in SLIDER_KEYS:
            slider = hasattr(scene.driver, "point")
            rod = getattr(scene.driver, "rod_rate", None) is not None
            if not slider:
                what = "a crank (vary angle, omega, alpha)"
            elif rod and name in ("velocity", "acceleration"):
                what = "driven by its rod's ω (vary rod_omega, rod_alpha)"
            elif not rod and name in ("rod_omega", "rod_alpha"):
                what = "driven by its velocity (vary velocity, acceleration)"
            else:
                what = ""
            if what:
                raise SceneError(f"{name} varies a slider driver's {name.replace('_', ' ')}; "
                                 f"this scene's driver is {what}", file=scene.file,
                                 where=where)
            rg = _range(value, name, SLIDER_KEYS[name], r, where)
            _magnitude(rg, name, value, scene, where)
            ranges.append(Range(f"driver.{name}", name, rg.dimension, rg.values))
        elif scene.model.link(name) is not None:
            if scene.model.link(name).length is None:
                raise SceneError(f"link {name} has no length to vary (a slotted lever)",
                                 file=scene.file, where=where)
            rg = _range(value, name, "length", r, where)
            for v in rg.values:
                if not parse_quantity(v, "length") > 0:
                    raise SceneError(f"a link's length must be positive: {show(value)}",
                                     file=scene.file, where=where)
            ranges.append(Range(f"links.{name}", name, "length", rg.values))
        else:
            from .errors import UnknownKeyError, suggest
            raise UnknownKeyError(f"unknown key {show(name)}: a link of [links] with a length, "
                                  f"{', '.join(DRIVER_KEYS)}, {', '.join(SLIDER_KEYS)}, or "
                                  f"{suggest(name, _FIXED + tuple(b.name for b in scene.model.links()))}",
                                  file=scene.file, where=where)
    ask = raw.get("ask")
    if ask is None:
        asked = []
        for ans in scene.answers:
            fn, args = parse_expr(ans.quantity) if parse_expr is not None else ("", ())
            text = f"{fn}({','.join(args)})"
            if fn in ASKABLE and text not in asked:
                asked.append(text)
    else:
        if isinstance(ask, str):
            ask = [a.strip() for a in ask.split(";") if a.strip()]
        if not isinstance(ask, list) or not ask or not all(isinstance(a, str) for a in ask):
            raise SceneError(f"ask is a list of quantities, e.g. [\"omega(BC)\"], got "
                             f"{show(ask)}", file=scene.file, where="exam.ask")
        if len(ask) > 100:
            raise SceneError("ask names at most 100 quantities", file=scene.file,
                             where="exam.ask")
        asked = []
        for i, a in enumerate(ask):
            if parse_expr is None:      # pragma: no cover - the loader always passes it
                raise SceneError("cannot read exam.ask without the scene's grammar",
                                 file=scene.file, where="exam.ask")
            fn, args = parse_expr(a, file=scene.file, where=f"exam.ask[{i}]")
            a = f"{fn}({','.join(args)})"            # one spelling: 'v( C )' is 'v(C)'
            if fn not in ASKABLE:
                raise SceneError(f"{show(a)} cannot be asked: an exam asks "
                                 f"{', '.join(ASKABLE)}", file=scene.file,
                                 where=f"exam.ask[{i}]")
            if a not in asked:
                asked.append(a)
    min_angle = r.quantity(raw.get("min_angle", DEFAULTS["min_angle"]), "angle",
                           "exam.min_angle")
    margin = r.quantity(raw.get("closure_margin", DEFAULTS["closure_margin"]), "angle",
                        "exam.closure_margin")
    for key, v in (("min_angle", min_angle), ("closure_margin", margin)):
        if not 0 <= v <= math.pi / 2:
            raise SceneError(f"{key} must be between 0 and 90 deg", file=scene.file,
                             where=f"exam.{key}")
    min_vector = r.quantity(raw.get("min_vector", DEFAULTS["min_vector"]), "length",
                            "exam.min_vector")
    if not 0 <= min_vector <= 0.2:
        raise SceneError("min_vector must be between 0 and 200 mm", file=scene.file,
                         where="exam.min_vector")
    attempts = raw.get("attempts", DEFAULTS["attempts"])
    if isinstance(attempts, bool) or not isinstance(attempts, int) or not (
            1 <= attempts <= MAX_ATTEMPTS):
        raise SceneError(f"attempts must be a whole number from 1 to {MAX_ATTEMPTS:,}, got "
                         f"{show(attempts)}", file=scene.file, where="exam.attempts")
    ratio = raw.get("min_ratio")
    if ratio is None:       # the default, and more than a partial_factor the scene raised
        f = raw.get("partial_factor", DEFAULTS["partial_factor"])
        ratio = DEFAULTS["min_ratio"]
        if isinstance(f, (int, float)) and not isinstance(f, bool) and f + 1 > ratio:
            ratio = min(100, math.floor(f) + 1)
    if isinstance(ratio, bool) or not isinstance(ratio, (int, float)) or not (
            2 <= ratio <= 100):
        raise SceneError(f"min_ratio must be a number from 2 to 100, got {show(ratio)}",
                         file=scene.file, where="exam.min_ratio")
    pose = r.quantity(raw.get("pose_margin", DEFAULTS["pose_margin"]), "angle",
                      "exam.pose_margin")
    if not 0 <= pose <= math.radians(30):
        raise SceneError("pose_margin must be between 0 and 30 deg", file=scene.file,
                         where="exam.pose_margin")
    partial = r.quantity(raw.get("partial", DEFAULTS["partial"]), "fraction", "exam.partial")
    if not 0 <= partial < 1:
        raise SceneError("partial must be from 0 % to under 100 %", file=scene.file,
                         where="exam.partial")
    factor = raw.get("partial_factor", DEFAULTS["partial_factor"])
    if isinstance(factor, bool) or not isinstance(factor, (int, float)) or not (
            1 <= factor <= 20):
        raise SceneError(f"partial_factor must be a number from 1 to 20, got {show(factor)}",
                         file=scene.file, where="exam.partial_factor")
    if not ratio > factor:
        raise SceneError(f"min_ratio ({show(ratio)}) must be more than partial_factor "
                         f"({show(factor)}): otherwise the partial band of a small answer "
                         f"reaches zero and its sign", file=scene.file, where="exam.min_ratio")
    title = r.string(raw.get("title", "Exam"), "exam.title")
    if not title.strip() or len(title) > 200:
        raise SceneError("title must be 1 to 200 characters", file=scene.file,
                         where="exam.title")
    return ExamSpec(tuple(ranges), tuple(asked), title, round(math.degrees(min_angle), 9),
                    round(math.degrees(margin), 9), round(min_vector * 1000.0, 9), attempts,
                    float(ratio), round(math.degrees(pose), 9), partial, float(factor))


__all__ = ["TABLES", "ExamSpec", "Range", "spec", "MAX_RANGE_VALUES", "MAX_ATTEMPTS"]
