"""Quantities with units, as a textbook writes them: ``"50 mm"``, ``"2000 rev/min"``.

Everything inside polygons is SI (m, s, rad, kg, N).  A scene value must carry its unit; a bare
number is a :class:`~polygons.errors.UnitError` (nothing is guessed).  We keep a small table
instead of depending on a units library: scenes need about twenty units of a dozen dimensions,
parsing them is ten lines, and it keeps `import polygons` fast (see README, "Dependencies").
"""
from __future__ import annotations

import math
import re

from .errors import UnitError

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

#: unit spelling -> (dimension, factor to SI)
UNITS: dict[str, tuple[str, float]] = {
    "m": ("length", 1.0), "mm": ("length", 1e-3), "cm": ("length", 1e-2),
    "km": ("length", 1e3), "um": ("length", 1e-6), "µm": ("length", 1e-6),
    "deg": ("angle", math.pi / 180.0), "°": ("angle", math.pi / 180.0),
    "rad": ("angle", 1.0),
    "rad/s": ("angular_velocity", 1.0), "rev/min": ("angular_velocity", _TAU / 60.0),
    "rpm": ("angular_velocity", _TAU / 60.0), "rev/s": ("angular_velocity", _TAU),
    "deg/s": ("angular_velocity", math.pi / 180.0),
    "rad/s^2": ("angular_acceleration", 1.0), "rad/s²": ("angular_acceleration", 1.0),
    "rev/min/s": ("angular_acceleration", _TAU / 60.0),
    "m/s": ("velocity", 1.0), "mm/s": ("velocity", 1e-3), "km/h": ("velocity", 1 / 3.6),
    "m/s^2": ("acceleration", 1.0), "m/s²": ("acceleration", 1.0),
    "mm/s^2": ("acceleration", 1e-3), "mm/s²": ("acceleration", 1e-3),
    "kg": ("mass", 1.0), "g": ("mass", 1e-3),
    "N": ("force", 1.0), "kN": ("force", 1e3),
    "N m": ("torque", 1.0), "Nm": ("torque", 1.0), "N*m": ("torque", 1.0),
    "N·m": ("torque", 1.0), "kN m": ("torque", 1e3),
    "Pa": ("pressure", 1.0), "kPa": ("pressure", 1e3), "MPa": ("pressure", 1e6),
    "bar": ("pressure", 1e5),
    "kg m^2": ("inertia", 1.0), "kg m²": ("inertia", 1.0), "kg mm^2": ("inertia", 1e-6),
    "N/m": ("stiffness", 1.0), "N/mm": ("stiffness", 1e3),
    "N m/rad": ("torsional_stiffness", 1.0), "Nm/rad": ("torsional_stiffness", 1.0),
    "s": ("time", 1.0), "ms": ("time", 1e-3),
    "J": ("energy", 1.0), "kJ": ("energy", 1e3), "W": ("power", 1.0), "kW": ("power", 1e3),
    "kg m^2/s": ("angular_momentum", 1.0), "kg m²/s": ("angular_momentum", 1.0),
    "%": ("fraction", 0.01),
}

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def units_of(dimension: str) -> list[str]:
    """The unit spellings accepted for ``dimension``."""
    return [u for u, (d, _) in UNITS.items() if d == dimension]


def parse_quantity(value, dimension: str, *, file: str | None = None,
                   where: str | None = None) -> float:
    """Convert ``"50 mm"`` to SI (0.05) after checking it is a ``dimension``.

    A bare number is accepted only for the dimensionless ``fraction``.
    """
    accepted = ", ".join(repr(u) for u in units_of(dimension)[:6])
    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        raise UnitError(f"expected a quantity such as '{_example(dimension)}', got {value!r}",
                        file=file, where=where)
    if isinstance(value, (int, float)):
        if dimension == "fraction":
            return float(value)
        raise UnitError(f"missing unit: {value!r} needs a {dimension.replace('_', ' ')} unit, "
                        f"e.g. '{value} {units_of(dimension)[0]}' (accepted: {accepted})",
                        file=file, where=where)
    match = _NUMBER.match(value)
    if not match:
        raise UnitError(f"cannot read {value!r} as a number with a unit "
                        f"(write e.g. '{_example(dimension)}')", file=file, where=where)
    number, unit = float(match.group(1)), " ".join(match.group(2).split())
    if not unit:
        if dimension == "fraction":
            return number
        raise UnitError(f"missing unit in {value!r}: a {dimension.replace('_', ' ')} "
                        f"needs one of {accepted}", file=file, where=where)
    if unit not in UNITS:
        raise UnitError(f"unknown unit {unit!r} in {value!r} (accepted for "
                        f"{dimension.replace('_', ' ')}: {accepted})", file=file, where=where)
    got, factor = UNITS[unit]
    if got != dimension:
        raise UnitError(f"{value!r} is a {got.replace('_', ' ')}, but a "
                        f"{dimension.replace('_', ' ')} is needed here (accepted: {accepted})",
                        file=file, where=where)
    result = number * factor
    if not math.isfinite(result):
        raise UnitError(f"{value!r} is not a finite number", file=file, where=where)
    return result


def to_unit(value_si: float, unit: str) -> float:
    """Express an SI value in ``unit`` (``to_unit(0.05, 'mm') == 50``)."""
    return value_si / UNITS[unit][1]


def dimension_of(unit: str) -> str:
    if unit not in UNITS:
        raise UnitError(f"unknown unit {unit!r}")
    return UNITS[unit][0]


def _example(dimension: str) -> str:
    return {"length": "50 mm", "angle": "30 deg", "angular_velocity": "2000 rev/min",
            "angular_acceleration": "0 rad/s^2", "velocity": "7 m/s",
            "acceleration": "1505 m/s^2", "mass": "0.5 kg", "force": "20 N"}.get(
                dimension, f"1 {units_of(dimension)[0] if units_of(dimension) else ''}")
