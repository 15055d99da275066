"""Quantities with units, as a textbook writes them: ``"50 mm"``, ``"2000 rev/min"``.

Everything inside polygons is SI (m, s, rad, kg, N).  A scene value must carry its unit; a bare
number is a :class:`~polygons.errors.UnitError` (nothing is guessed).  We keep a small table
instead of depending on a units library: scenes need about eighty spellings of fifteen dimensions,
parsing them is ten lines, and it keeps `import polygons` fast (see README, "Dependencies").
"""
from __future__ import annotations

import functools
import math
import re

from .errors import UnitError, show

#: dimension name -> the SI unit written in reports
SI_UNIT = {
    "length": "m",
    "angle": "rad",
    "angular_velocity": "rad/s",
    "angular_acceleration": "rad/s^2",
    "velocity": "m/s",
    "acceleration": "m/s^2",
    "mass": "kg",
    "force": "N",
    "torque": "N m",
    "pressure": "Pa",
    "inertia": "kg m^2",
    "stiffness": "N/m",
    "torsional_stiffness": "N m/rad",
    "time": "s",
    "energy": "J",
    "power": "W",
    "angular_momentum": "kg m^2/s",
    "fraction": "",
}

_TAU = 2.0 * math.pi
# exact definitions (NIST SP 811): the international inch and pound, standard gravity
_IN = 0.0254
_FT = 0.3048
_LB = 0.45359237
_G0 = 9.80665
_LBF = _LB * _G0
_SLUG = _LBF / _FT

#: unit spelling -> (dimension, factor to SI); every factor is checked against pint in
#: tests/test_units.py
UNITS: dict[str, tuple[str, float]] = {
    "m": ("length", 1.0), "mm": ("length", 1e-3), "cm": ("length", 1e-2),
    "km": ("length", 1e3), "um": ("length", 1e-6), "µm": ("length", 1e-6),
    "in": ("length", _IN), "ft": ("length", _FT),
    "deg": ("angle", math.pi / 180.0), "°": ("angle", math.pi / 180.0),
    "rad": ("angle", 1.0), "rev": ("angle", _TAU),
    "rad/s": ("angular_velocity", 1.0), "rev/min": ("angular_velocity", _TAU / 60.0),
    "rpm": ("angular_velocity", _TAU / 60.0), "rev/s": ("angular_velocity", _TAU),
    "deg/s": ("angular_velocity", math.pi / 180.0),
    "rad/s^2": ("angular_acceleration", 1.0), "rad/s²": ("angular_acceleration", 1.0),
    "rev/min/s": ("angular_acceleration", _TAU / 60.0),
    "deg/s^2": ("angular_acceleration", math.pi / 180.0),
    "deg/s²": ("angular_acceleration", math.pi / 180.0),
    "rev/s^2": ("angular_acceleration", _TAU), "rev/s²": ("angular_acceleration", _TAU),
    "m/s": ("velocity", 1.0), "mm/s": ("velocity", 1e-3), "km/h": ("velocity", 1 / 3.6),
    "ft/s": ("velocity", _FT), "in/s": ("velocity", _IN), "ft/min": ("velocity", _FT / 60.0),
    "mph": ("velocity", 1609.344 / 3600.0),
    "m/min": ("velocity", 1 / 60.0), "mm/min": ("velocity", 1e-3 / 60.0),
    "m/s^2": ("acceleration", 1.0), "m/s²": ("acceleration", 1.0),
    "mm/s^2": ("acceleration", 1e-3), "mm/s²": ("acceleration", 1e-3),
    "ft/s^2": ("acceleration", _FT), "ft/s²": ("acceleration", _FT),
    "in/s^2": ("acceleration", _IN), "in/s²": ("acceleration", _IN),
    "kg": ("mass", 1.0), "g": ("mass", 1e-3), "t": ("mass", 1e3),
    "lb": ("mass", _LB), "slug": ("mass", _SLUG),
    "N": ("force", 1.0), "kN": ("force", 1e3), "MN": ("force", 1e6), "lbf": ("force", _LBF),
    "kgf": ("force", _G0),
    "N m": ("torque", 1.0), "Nm": ("torque", 1.0), "N*m": ("torque", 1.0),
    "N·m": ("torque", 1.0), "kN m": ("torque", 1e3), "N mm": ("torque", 1e-3),
    "lbf ft": ("torque", _LBF * _FT), "lbf in": ("torque", _LBF * _IN),
    "Pa": ("pressure", 1.0), "kPa": ("pressure", 1e3), "MPa": ("pressure", 1e6),
    "bar": ("pressure", 1e5), "psi": ("pressure", _LBF / _IN ** 2),
    "N/mm^2": ("pressure", 1e6), "N/mm²": ("pressure", 1e6),
    "kN/m^2": ("pressure", 1e3), "kN/m²": ("pressure", 1e3),
    "N/m^2": ("pressure", 1.0), "N/m²": ("pressure", 1.0),
    "N/cm^2": ("pressure", 1e4), "N/cm²": ("pressure", 1e4),
    "kg m^2": ("inertia", 1.0), "kg m²": ("inertia", 1.0), "kg mm^2": ("inertia", 1e-6),
    "kg mm²": ("inertia", 1e-6), "lb ft^2": ("inertia", _LB * _FT ** 2),
    "lb ft²": ("inertia", _LB * _FT ** 2), "lb in^2": ("inertia", _LB * _IN ** 2),
    "lb in²": ("inertia", _LB * _IN ** 2), "slug ft^2": ("inertia", _SLUG * _FT ** 2),
    "slug ft²": ("inertia", _SLUG * _FT ** 2),
    "N/m": ("stiffness", 1.0), "N/mm": ("stiffness", 1e3), "kN/m": ("stiffness", 1e3),
    "lbf/in": ("stiffness", _LBF / _IN), "lbf/ft": ("stiffness", _LBF / _FT),
    "N m/rad": ("torsional_stiffness", 1.0), "Nm/rad": ("torsional_stiffness", 1.0),
    "lbf ft/rad": ("torsional_stiffness", _LBF * _FT),
    "lbf in/rad": ("torsional_stiffness", _LBF * _IN),
    "s": ("time", 1.0), "ms": ("time", 1e-3), "min": ("time", 60.0),
    "J": ("energy", 1.0), "kJ": ("energy", 1e3), "W": ("power", 1.0), "kW": ("power", 1e3),
    "kg m^2/s": ("angular_momentum", 1.0), "kg m²/s": ("angular_momentum", 1.0),
    "%": ("fraction", 0.01),
}

#: other spellings a textbook prints -> the spelling of :data:`UNITS` they mean (read as it;
#: error messages list the canonical spellings only)
SPELLINGS: dict[str, str] = {
    "r.p.m.": "rpm", "r.p.m": "rpm", "RPM": "rpm", "R.P.M.": "rpm", "r/min": "rpm",
    "rev/minute": "rpm", "revolutions per minute": "rpm",
    "rps": "rev/s", "r.p.s.": "rev/s", "r/s": "rev/s",
    "rad/sec": "rad/s", "rad/sec^2": "rad/s^2", "rad/sec²": "rad/s^2", "rad/s/s": "rad/s^2",
    "degree": "deg", "degrees": "deg", "deg.": "deg",
    "inch": "in", "inches": "in", "in.": "in", "foot": "ft", "feet": "ft", "ft.": "ft",
    "m/sec": "m/s", "mm/sec": "mm/s", "ft/sec": "ft/s", "in/sec": "in/s",
    "m/sec^2": "m/s^2", "m/sec²": "m/s^2", "mm/sec^2": "mm/s^2", "mm/sec²": "mm/s^2",
    "ft/sec^2": "ft/s^2", "ft/sec²": "ft/s^2", "in/sec^2": "in/s^2", "in/sec²": "in/s^2",
    "m/s/s": "m/s^2", "N-m": "N m", "N.m": "N m", "Nmm": "N mm", "N-mm": "N mm",
    "kN-m": "kN m", "kN·m": "kN m", "kN.m": "kN m", "kNm": "kN m", "N·mm": "N mm",
    "kg-m^2": "kg m^2", "kg-m²": "kg m^2", "kg·m^2": "kg m^2", "kg·m²": "kg m^2",
    "kg.m^2": "kg m^2", "kg.m²": "kg m^2",
    "km/hr": "km/h", "kmph": "km/h", "km/hour": "km/h",
    "metre": "m", "metres": "m", "meter": "m", "meters": "m", "millimetre": "mm",
    "millimetres": "mm", "millimeter": "mm", "millimeters": "mm", "mm.": "mm",
    "m/minute": "m/min",
}

#: (smallest non-zero, largest) magnitude accepted, in SI, per dimension: inside this range
#: every product the constructions form (ω²·r, 2ωv, m·a, squared distances) stays finite and
#: far from underflow.  A value outside is refused at load with the range in the message.
LIMITS: dict[str, tuple[float, float]] = {
    "length": (0.0, 1e6),                   # up to 1000 km (a link: at least 1 nm, see scene)
    "angle": (0.0, 1e6 * math.pi / 180),    # beyond ±1e6 deg precision would be lost
    "angular_velocity": (0.0, 1e6),
    "angular_acceleration": (0.0, 1e12),
    "velocity": (0.0, 1e6),
    "acceleration": (0.0, 1e12),
    "mass": (1e-9, 1e9),                     # a µg: a subnormal mass would make inertia 0
    "force": (0.0, 1e12),
    "torque": (0.0, 1e12),
    "pressure": (0.0, 1e12),
    "inertia": (1e-18, 1e9),                 # α = T / I must stay finite
    "stiffness": (0.0, 1e12),
    "torsional_stiffness": (0.0, 1e12),
    "time": (0.0, 1e9),
    "fraction": (0.0, 1e6),
    "energy": (0.0, 1e15),
    "power": (0.0, 1e15),
    "angular_momentum": (0.0, 1e15),
}

#: unit systems for reports (``polygons solve --units``): dimension -> unit written
SYSTEMS: dict[str, dict[str, str]] = {
    "mm": {"length": "mm", "velocity": "m/s", "acceleration": "m/s²",
           "angular_velocity": "rad/s", "angular_acceleration": "rad/s²"},
    "si": {"length": "m", "velocity": "m/s", "acceleration": "m/s²",
           "angular_velocity": "rad/s", "angular_acceleration": "rad/s²"},
    "imperial": {"length": "in", "velocity": "ft/s", "acceleration": "ft/s²",
                 "angular_velocity": "rad/s", "angular_acceleration": "rad/s²"},
}

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
#: the period of an orientation, in each angle unit (reduced exactly with math.fmod)
_TURN = {"deg": 360.0, "°": 360.0, "rad": _TAU, "rev": 1.0}
#: an angle in degrees, minutes (and seconds) as books print it: 42°18', 42° 18′ 30″, 42 deg 18 min
_DMS = re.compile(r"^\s*([-+]?)(\d+(?:\.\d*)?)\s*(?:°|deg)\s*(\d+(?:\.\d*)?)\s*(?:'|′|min)"
                  r"\s*(?:(\d+(?:\.\d*)?)\s*(?:\"|″|''|sec|s))?\s*$")


def article(word: str) -> str:
    """'a length', 'an angle', 'an angular velocity'."""
    return ("an " if word[:1].lower() in "aeiou" else "a ") + word


def units_of(dimension: str) -> list[str]:
    """The unit spellings accepted for ``dimension``."""
    return list(_units_of(dimension))


@functools.cache
def _units_of(dimension: str) -> tuple[str, ...]:
    return tuple(u for u, (d, _) in UNITS.items() if d == dimension)


@functools.cache
def _accepted(dimension: str) -> str:
    """The first few spellings, for an error message: "'mm', 'cm', 'm' ..."."""
    return ", ".join(repr(u) for u in _units_of(dimension)[:6])


def check_range(result: float, dimension: str, value, *, file=None, where=None) -> float:
    """Refuse a non-finite value, or one outside :data:`LIMITS` (zero is always allowed)."""
    if not math.isfinite(result):
        raise UnitError(f"{show(value)} is not a finite number", file=file, where=where)
    low, high = LIMITS.get(dimension, (0.0, math.inf))
    if (result != 0.0 and abs(result) < low) or abs(result) > high:
        _out_of_range(result, dimension, value, low, high, file, where)
    return result + 0.0        # -0.0 -> 0.0


def _out_of_range(result, dimension, value, low, high, file, where):
    words = dimension.replace("_", " ")
    si = SI_UNIT.get(dimension, "")
    if abs(result) > high:
        shown = f"{high * 180 / math.pi:g} deg" if dimension == "angle" else f"{high:g} {si}"
        raise UnitError(f"{show(value)} is out of range: {article(words)} must not exceed "
                        f"{shown.rstrip()} in magnitude", file=file, where=where)
    if result != 0.0 and abs(result) < low:
        raise UnitError(f"{show(value)} is too small to compute with: {article(words)} must be "
                        f"0 or at least {low:g} {si}".rstrip() + " in magnitude",
                        file=file, where=where)


def parse_quantity(value, dimension: str, *, file: str | None = None,
                   where: str | None = None, reduce: bool = False) -> float:
    """Convert ``"50 mm"`` to SI (0.05) after checking it is a ``dimension``.

    A bare number is accepted only for the dimensionless ``fraction``.  The magnitude must be
    zero or within :data:`LIMITS`.  ``reduce`` (orientations only) reduces an angle to one
    turn exactly, in its stated unit, before converting (``"370 deg"`` -> 10°).

    The value of an accepted text is a pure function of (text, dimension, reduce): it is
    remembered (up to :data:`_MEMO_SIZE` texts); a refused one is checked again every time,
    so each refusal names its own file and key.
    """
    if value.__class__ is str:
        key = (value, dimension, reduce)
        hit = _PARSED.get(key)
        if hit is None:
            hit = _parse_quantity(value, dimension, file, where, reduce)
            if len(_PARSED) >= _MEMO_SIZE:      # a long run's many texts: start afresh
                _PARSED.clear()
            _PARSED[key] = hit
        return hit
    return _parse_quantity(value, dimension, file, where, reduce)


#: texts remembered by :func:`parse_quantity` (a scene holds tens; a sweep of files, more)
_MEMO_SIZE = 4096
_PARSED: dict[tuple[str, str, bool], float] = {}


def _parse_quantity(value, dimension: str, file, where, reduce) -> float:
    words = dimension.replace("_", " ")
    accepted = _accepted(dimension)
    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        raise UnitError(f"expected a quantity such as '{_example(dimension)}', got "
                        f"{show(value)}", file=file, where=where)
    if isinstance(value, (int, float)):
        if dimension == "fraction":
            return check_range(float(value), dimension, value, file=file, where=where)
        if isinstance(value, float) and not math.isfinite(value):
            raise UnitError(f"{show(value)} is not a finite number", file=file, where=where)
        raise UnitError(f"missing unit: {show(value)} needs {article(words)} unit, "
                        f"e.g. '{value} {units_of(dimension)[0]}' (accepted: {accepted})",
                        file=file, where=where)
    dms = _DMS.match(value) if dimension == "angle" else None
    if dms:             # 42°18'30" = 42 + 18/60 + 30/3600 deg (minutes, seconds below 60)
        sign, d, m, sec = dms.groups()
        if float(m) >= 60 or float(sec or 0) >= 60:
            raise UnitError(f"{show(value)}: minutes and seconds of arc are below 60",
                            file=file, where=where)
        deg = float(d) + float(m) / 60 + float(sec or 0) / 3600
        value = f"{'-' if sign == '-' else ''}{deg!r} deg"
    match = _NUMBER.match(value)
    if not match:
        raise UnitError(f"cannot read {show(value)} as a number with a unit "
                        f"(write e.g. '{_example(dimension)}')", file=file, where=where)
    number, unit = float(match.group(1)), " ".join(match.group(2).split())
    unit = SPELLINGS.get(unit, unit)
    if not unit:
        if dimension == "fraction":
            return check_range(number, dimension, value, file=file, where=where)
        raise UnitError(f"missing unit in {show(value)}: {article(words)} "
                        f"needs one of {accepted}", file=file, where=where)
    if unit not in UNITS:
        raise UnitError(f"unknown unit {show(unit)} in {show(value)} (accepted for "
                        f"{words}: {accepted})", file=file, where=where)
    got, factor = UNITS[unit]
    if got != dimension:
        raise UnitError(f"{show(value)} is {article(got.replace('_', ' '))}, but "
                        f"{article(words)} is needed here (accepted: {accepted})",
                        file=file, where=where)
    if not math.isfinite(number):
        raise UnitError(f"{show(value)} is not a finite number", file=file, where=where)
    if dimension == "angle":
        check_range(number * factor, dimension, value, file=file, where=where)
        if reduce:
            number = math.fmod(number, _TURN[unit])       # exact
    return check_range(number * factor, dimension, value, file=file, where=where)


#: a motion's direction in words, as books give it ('2 m/s to the left'): the axis it names
_TOWARDS = {"to the right": (1.0, 0.0), "right": (1.0, 0.0), "to the left": (-1.0, 0.0),
            "left": (-1.0, 0.0), "upwards": (0.0, 1.0), "upward": (0.0, 1.0), "up": (0.0, 1.0),
            "downwards": (0.0, -1.0), "downward": (0.0, -1.0), "down": (0.0, -1.0)}
_TOWARDS_RE = re.compile(r"^(.*?)\s+(" + "|".join(sorted(map(re.escape, _TOWARDS), key=len,
                                                            reverse=True)) + r")\s*$",
                         re.IGNORECASE)


def parse_along(value, dimension: str, direction: tuple[float, float], *, file=None,
                where=None) -> float:
    """A velocity or acceleration signed along a guide's ``direction`` (unit vector): "2 m/s"
    as signed, or its magnitude and a direction in words as books give it, "2 m/s to the
    left" (right, up, down: +x, −x, +y, −y), which the guide must lie along."""
    m = _TOWARDS_RE.match(value) if isinstance(value, str) else None
    if not m:
        return parse_quantity(value, dimension, file=file, where=where)
    size = parse_quantity(m.group(1), dimension, file=file, where=where)
    if size < 0:
        raise UnitError(f"{show(value)}: a magnitude with its direction in words, or a signed "
                        f"value without them", file=file, where=where)
    ax = _TOWARDS[m.group(2).lower()]
    along = direction[0] * ax[0] + direction[1] * ax[1]
    if abs(abs(along) - 1.0) > 1e-9:
        raise UnitError(f"{show(value)}: its line (guide, surface) runs at "
                        f"{math.degrees(math.atan2(direction[1], direction[0])):.6g}°, not "
                        f"{'horizontally' if ax[1] == 0 else 'vertically'}: give the value "
                        f"signed along its direction", file=file, where=where)
    return size if along > 0 else -size


def to_unit(value_si: float, unit: str) -> float:
    """Express an SI value in ``unit`` (``to_unit(0.05, 'mm') == 50``)."""
    return value_si / UNITS[unit][1]


def dimension_of(unit: str) -> str:
    if unit not in UNITS:
        raise UnitError(f"unknown unit {show(unit)}")
    return UNITS[unit][0]


def _example(dimension: str) -> str:
    return {"length": "50 mm", "angle": "30 deg", "angular_velocity": "2000 rev/min",
            "angular_acceleration": "0 rad/s^2", "velocity": "7 m/s",
            "acceleration": "1505 m/s^2", "mass": "0.5 kg", "force": "20 N"}.get(
                dimension, f"1 {units_of(dimension)[0] if units_of(dimension) else ''}")


#: the round values of a drawing scale (1, 2, 2.5, 5 × 10ⁿ)
ROUND = (1.0, 2.0, 2.5, 5.0)


def round_up(x: float) -> float:
    """The smallest round scale value (1, 2, 2.5, 5 × 10ⁿ) ≥ ``x`` (1 for a value that is
    not positive and finite)."""
    if not (x > 0 and math.isfinite(x)):
        return 1.0
    n = math.floor(math.log10(x))
    for k in (n - 1, n, n + 1):
        for m in ROUND:
            v = float(f"{m}e{k}")
            if v >= x * (1 - 1e-12):
                return v
    raise AssertionError(x)  # pragma: no cover


def cos_sin(phi: float) -> tuple[float, float]:
    """(cos φ, sin φ), exact at the multiples of 90° a book states ('D is 200 mm from A at
    90°': x = 0, not 1.2e-17 m, which printed as noise in an exam's data)."""
    k = phi / (math.pi / 2)
    if abs(k) < 1e6 and k == round(k):
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(round(k)) % 4]
    return math.cos(phi), math.sin(phi)


