"""The scene's ``[[questions]]``: a book's question that fixes an input by a condition, or asks
for an extreme over the cycle, as data.  Read and checked when the scene is loaded (a typo fails
every command, naming the key); kept raw in ``Scene.extra`` and read into frozen
:class:`Question` records by :func:`questions` (cheap) when :mod:`polygons.conditions` answers
them.

    [[questions]]                      # "the crank angle at which the piston's speed is greatest"
    find = "angle"                     # the input sought: the crank's angle (or "omega",
                                       # the crank's speed; "position", a slider driver's)
    quantity = "v(P)"                  # any answer quantity ([[answers]] or [[force_answers]])
    condition = "max"                  # max | min | stationary | zero | value (with value) |
                                       # stroke | dead centres | time ratio
    range = ["0 deg", "180 deg"]       # where to look (default: a full turn of the crank)
    unit = "deg"                       # the unit the found input is reported in
    value_unit = "m/s"                 # the unit of the quantity there
    exact = [73.9]                     # every root in the range, in `unit`, in increasing order
    value_exact = [12.8]               # the quantity at each, in `value_unit`

Conditions: ``zero`` — the quantity changes sign (every crossing in the range); ``value`` — it
equals ``value``; ``max`` / ``min`` — its greatest / least value in the range (every place it
takes it); ``stationary`` — every place it stops rising or falling.  Over the cycle (``find =
"angle"``, a full turn): ``stroke`` — the quantity's greatest minus its least value;
``dead centres`` — the crank angles of the two; ``time ratio`` — the crank's turn from one to the
other against the rest of the turn (the quick return's time ratio, larger over smaller).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .errors import SceneError, show
from .reader import Reader
from .schema import Key, Table
from .units import UNITS, dimension_of, parse_quantity

FINDS = {"angle": "angle", "omega": "angular_velocity", "position": "length"}
CONDITIONS = ("zero", "value", "max", "min", "stationary", "stroke", "dead centres",
              "time ratio")
#: conditions over the whole cycle (the range is a full turn of the crank)
CYCLE = ("stroke", "dead centres", "time ratio")
#: the most sample points of one question's bracketing pass (each is a full construction)
MAX_SAMPLES = 20_000
MIN_SAMPLES = 8
MAX_QUESTIONS = 50
DEFAULT_SAMPLES = 360

TABLES: tuple[Table, ...] = (
    Table("questions", "[[questions]]: the value of one input (the crank angle in a range, the "
                       "crank's speed, a slider driver's position) at which a condition holds "
                       "— a quantity equal to a value, at its extreme, changing sign — or the "
                       "extremes over the cycle (stroke, dead centres, quick-return time "
                       "ratio).  Every root in the range is found (bracketed on a sweep of "
                       "`samples` instants, then polished to full precision by Brent's method "
                       "on the construction) and answered by `polygons ask`.", (
        Key("find", "string", "the input sought: 'angle' (the crank's, CCW from +x; each root "
                              "also as the scene states its angle: '283.5 deg from idc'), 'omega' "
                              "(the crank's speed, its sense the scene's) or 'position' (a "
                              "slider driver's)", example='"angle"', required=True),
        Key("quantity", "string", "the quantity the condition is on: any [[answers]] or "
                                  "[[force_answers]] quantity (v(P), vs(P), a(C), Rx(P,PC) ...)",
            example='"vs(P)"', required=True),
        Key("condition", "string", "zero | value | max | min | stationary | stroke | "
                                   "dead centres | time ratio", example='"zero"',
            required=True),
        Key("value", "string", "with condition = 'value': the value the quantity must equal, "
                               "with its unit", example='"5 m/s"'),
        Key("range", "array", "[low, high] of the input, with units (a crank angle also as "
                               "the scene states it: '180 deg from idc'; default: a full turn "
                              "for an angle; required for omega and position)",
            example='["0 deg", "180 deg"]'),
        Key("samples", "integer", f"instants of the bracketing sweep ({MIN_SAMPLES} to "
                                  f"{MAX_SAMPLES:,}); a root closer to another than the "
                                  f"spacing may be missed", example="360",
            default=DEFAULT_SAMPLES),
        Key("unit", "string", "the unit the found input (or a stroke, or '-' for the time "
                              "ratio) is reported and compared in", example='"deg"',
            required=True),
        Key("value_unit", "string", "the unit of the quantity's value at each root "
                                    "(default: SI)", example='"m/s"'),
        Key("exact", "numbers", "every root in the range, in `unit`, increasing (a stroke or "
                              "time ratio: one number), from an independent closed form",
            example="[73.9]"),
        Key("tutorial", "numbers", "the book's printed roots, in `unit`", example="[74]"),
        Key("value_exact", "numbers", "the quantity's exact value at each root, in "
                                    "`value_unit`", example="[12.8]"),
        Key("tolerance", "quantity", "drawing tolerance of the book's values", example='"2 %"',
            dimension="fraction"),
        Key("desc", "string", "the question in words", example='"the angle of greatest '
                                                               'piston speed"'),
    ), array=True),
)
KEYS = tuple(k.name for k in TABLES[0].keys)
#: the kinematic quantity functions (polygons.scene.QUANTITY_FUNCTIONS; the rest are the force
#: analysis's, checked by polygons.conditions before it solves)
KINEMATIC = ("v", "a", "an", "at", "omega", "alpha", "vs", "as", "cor", "dist", "x", "y",
             "dir_v", "dir_a", "angle", "arm")


_FROM_WORD = re.compile(r"\s+from\s+", re.IGNORECASE)


def _range_end(text, dim, scene, r, where) -> float:
    """An end of a crank angle's range: '30 deg' (CCW from +x), or as the scene states its
    angle, '180 deg from idc' (the same reference, measured the same way: Crank.stated)."""
    parts = _FROM_WORD.split(text, maxsplit=1) if isinstance(text, str) else []
    if len(parts) != 2:
        return r.quantity(text, dim, where)
    stated = getattr(scene.driver, "stated", None)
    ref = " ".join(parts[1].split())
    if stated is None or ref.lower() != stated[0].lower():
        raise SceneError(f"range {show(text)}: an angle from {ref} is read as the scene states "
                         f"its crank angle, which must then be from {ref} too "
                         f"(angle = \"30 deg from {ref}\"); or write the range CCW from +x",
                         file=r.file, where=where)
    return stated[1] + stated[2] * r.quantity(parts[0], dim, where)


@dataclass(frozen=True)
class Question:
    """One ``[[questions]]`` entry, SI inside (``range``, ``value``); ``exact`` / ``tutorial`` /
    ``value_exact`` in the entry's units."""

    index: int
    find: str
    quantity: str
    condition: str
    value: float | None
    range: tuple[float, float] | None
    samples: int
    unit: str
    value_unit: str | None
    exact: tuple[float, ...] | None
    tutorial: tuple[float, ...] | None
    value_exact: tuple[float, ...] | None
    tolerance: float
    desc: str

    @property
    def where(self) -> str:
        return f"questions[{self.index}]"


def _numbers(r: Reader, value, where) -> tuple[float, ...]:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = [value]
    if not isinstance(value, list) or len(value) > 1000 or not all(
            isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)
            for x in value):
        raise SceneError(f"expected an array of finite numbers, got {show(value)}",
                         file=r.file, where=where)
    return tuple(float(x) for x in value)


def _unit(r: Reader, value, where, dimension: str | None = None) -> str:
    unit = r.string(value, where)
    if unit in ("-", "1"):
        got = "fraction"
    elif unit in UNITS:
        got = dimension_of(unit)
    else:
        raise SceneError(f"unknown unit {show(unit)}", file=r.file, where=where)
    if dimension is not None and got != dimension:
        raise SceneError(f"{show(unit)} is not a unit of {dimension.replace('_', ' ')}",
                         file=r.file, where=where)
    return unit


def questions(scene, parse, tolerance: float) -> tuple[Question, ...]:
    """The scene's ``[[questions]]`` as records, each checked (one line naming the key);
    ``parse`` reads a kinematic quantity's grammar (``polygons.scene.parse_quantity_expr``,
    handed in: the scene imports this module), ``tolerance`` is the scene's drawing
    tolerance."""
    raw = scene.extra.get("questions", [])
    r = Reader(scene.file)
    if not isinstance(raw, list) or not all(isinstance(q, dict) for q in raw):
        raise SceneError("write questions as [[questions]] tables", file=r.file,
                         where="questions")
    if len(raw) > MAX_QUESTIONS:
        raise SceneError(f"{len(raw)} questions: at most {MAX_QUESTIONS} are served",
                         file=r.file, where="questions")
    out = []
    for i, spec in enumerate(raw):
        where = f"questions[{i}]"
        r.table(spec, where, KEYS, required=("find", "quantity", "condition", "unit"))
        find = r.string(spec["find"], where + ".find")
        if find not in FINDS:
            raise SceneError(f"find must be one of {', '.join(FINDS)}, got {show(find)}",
                             file=r.file, where=where + ".find")
        crank = hasattr(scene.driver, "angle")
        if (find == "position") == crank:
            raise SceneError(f"find = {find!r} needs a {'slider' if crank else 'crank'} driver; "
                             f"this scene's driver is a {'crank' if crank else 'slider'}",
                             file=r.file, where=where + ".find")
        quantity = r.string(spec["quantity"], where + ".quantity")
        fn = quantity.split("(", 1)[0].strip()
        if fn in KINEMATIC:                   # a kinematic quantity: its grammar now
            parse(quantity, file=r.file, where=where + ".quantity")
        condition = r.string(spec["condition"], where + ".condition")
        if condition not in CONDITIONS:
            raise SceneError(f"condition must be one of {', '.join(CONDITIONS)}, got "
                             f"{show(condition)}", file=r.file, where=where + ".condition")
        if condition in CYCLE and find != "angle":
            raise SceneError(f"{condition!r} is over the crank's cycle: find = 'angle'",
                             file=r.file, where=where + ".condition")
        value = None
        if condition == "value":
            if "value" not in spec:
                raise SceneError("condition = 'value' needs value = \"<number> <unit>\"",
                                 file=r.file, where=where)
            text = r.string(spec["value"], where + ".value")
            unit = text.strip().split(" ", 1)[-1] if " " in text.strip() else ""
            dim = "fraction" if unit in ("", "-") else (dimension_of(unit) if unit in UNITS
                                                         else None)
            if dim is None:
                raise SceneError(f"value {show(text)}: unknown unit {show(unit)}",
                                 file=r.file, where=where + ".value")
            value = parse_quantity(text, dim, file=r.file, where=where + ".value") \
                if dim != "fraction" else float(text.split()[0])
        elif "value" in spec:
            raise SceneError(f"value is for condition = 'value', not {condition!r}",
                             file=r.file, where=where + ".value")
        dim = FINDS[find]
        rng = None
        if "range" in spec:
            lohi = spec["range"]
            if not isinstance(lohi, list) or len(lohi) != 2:
                raise SceneError(f"range must be [low, high] with units, got {show(lohi)}",
                                 file=r.file, where=where + ".range")
            rng = tuple(_range_end(x, dim, scene, r, f"{where}.range[{j}]") if find == "angle"
                        else r.quantity(x, dim, f"{where}.range[{j}]")
                        for j, x in enumerate(lohi))
            if find == "angle" and any(_FROM_WORD.search(str(x)) for x in lohi):
                rng = tuple(sorted(rng))       # measured CW from the reference: reversed
            if not rng[1] > rng[0]:
                raise SceneError(f"range: high must exceed low, got {show(lohi)}", file=r.file,
                                 where=where + ".range")
            if find == "angle" and rng[1] - rng[0] > 2 * math.pi * (1 + 1e-12):
                raise SceneError("range: at most one turn (360 deg)", file=r.file,
                                 where=where + ".range")
            if condition in CYCLE and abs(rng[1] - rng[0] - 2 * math.pi) > 1e-9:
                raise SceneError(f"{condition!r} is over a full turn: leave range out",
                                 file=r.file, where=where + ".range")
            if find == "omega" and rng[0] < 0:
                raise SceneError("range: the crank's speed is a magnitude (≥ 0); its sense is "
                                 "the scene's", file=r.file, where=where + ".range")
        elif find != "angle":
            raise SceneError(f"find = {find!r} needs range = [low, high]", file=r.file,
                             where=where)
        samples = spec.get("samples", DEFAULT_SAMPLES)
        if (isinstance(samples, bool) or not isinstance(samples, int)
                or not MIN_SAMPLES <= samples <= MAX_SAMPLES):
            raise SceneError(f"samples must be an integer from {MIN_SAMPLES} to "
                             f"{MAX_SAMPLES:,}, got {show(samples)}", file=r.file,
                             where=where + ".samples")
        want = ("fraction" if condition == "time ratio" else None if condition == "stroke"
                else dim)
        unit = _unit(r, spec["unit"], where + ".unit", want)
        value_unit = (_unit(r, spec["value_unit"], where + ".value_unit")
                      if "value_unit" in spec else None)
        nums = {k: _numbers(r, spec[k], f"{where}.{k}") if k in spec else None
                for k in ("exact", "tutorial", "value_exact")}
        tol = r.quantity(spec["tolerance"], "fraction", where + ".tolerance") \
            if "tolerance" in spec else tolerance
        desc = r.string(spec.get("desc", f"{condition} of {quantity}"), where + ".desc")
        out.append(Question(i, find, quantity, condition, value, rng, samples, unit,
                            value_unit, nums["exact"], nums["tutorial"], nums["value_exact"],
                            tol, desc))
    return tuple(out)


def check(scene, parse, tolerance: float) -> None:
    """Checked at load: every ``[[questions]]`` entry readable (:func:`questions`)."""
    if "questions" in scene.extra:
        questions(scene, parse, tolerance)
