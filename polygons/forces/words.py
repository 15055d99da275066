"""The one formatter of force results in words: a signed component is written once, as its
size with its sense in words — '157.76 N m CW', '27.46 N, to the left (∠159.7°)', '5804.4 N
towards 0° (along the guide)', '105.69 N pulling (tension)' — never as a signed number with
a sense after it ('−3.79649 N m (CCW)') nor inside a sum ('T + (−157.76 N m) = 0').

Used by the ``forces`` and ``solve`` text, the handout's force sections, the force drawings
and Zhukovsky's lever (text, handout table, drawing legend).
"""
from __future__ import annotations

import math

#: the eight direction words of a force, by 45° sectors from +x
DIRECTIONS = ("to the right", "up and to the right", "up", "up and to the left",
              "to the left", "down and to the left", "down", "down and to the right")


def _degrees(v, spec: str) -> tuple[float, str]:
    """A direction's angle CCW from +x in [0, 360) and its text in the format ``spec``; a
    direction a rounding short of +x (−1e-14 rad, printed '360') is 0."""
    deg = math.degrees(math.atan2(float(v[1]), float(v[0]))) % 360.0
    text = format(deg, spec)
    return (0.0, format(0.0, spec)) if float(text) >= 360.0 else (deg, text)


def angle(v, digits: int = 6) -> str:
    """A direction's angle CCW from +x in [0, 360) as printed ('0', never '360' for
    −1e-14 rad): ``digits`` significant figures."""
    return _degrees(v, f".{digits}g")[1]


def sense(m: float) -> str:
    """'CCW' for a positive moment, 'CW' for a negative one, '' for zero."""
    return "" if m == 0.0 else ("CCW" if m > 0 else "CW")


def moment_words(m: float, unit: str = "N m", digits: int = 6) -> str:
    """A moment as a book writes it: its magnitude and its sense ('157.76 N m CW'); a
    rounding residue (|m| < 1e-12) is '0 N m' (never '-0')."""
    if abs(m) < 1e-12:
        return f"0 {unit}"
    return f"{abs(m):.{digits}g} {unit} {sense(m)}"


def sense_words(force) -> str:
    """The sense of a force in words, with its angle: 'down and to the left (∠213.4°)'."""
    deg, shown = _degrees(force, ".1f")
    return f"{DIRECTIONS[int(((deg + 22.5) % 360.0) // 45.0)]} (∠{shown}°)"


def found_words(f) -> str:
    """A force found by moments: its magnitude and its sense in words ('27.46 N, down and to
    the left (∠213.4°)'), not the signed value along the normal chosen."""
    if abs(f.value) < 1e-12:
        return "0 N"
    return f"{abs(f.value):.6g} N, {sense_words(f.force)}"


def balance_words(known: float, effort: float) -> str:
    """The input torque's moment equation written as a book would: 'T − 157.76 N m = 0,
    T = 157.76 N m CCW' (``known``: the known forces' moment about the pivot, CCW +)."""
    sign = "−" if known < 0 else "+"
    return f"T {sign} {abs(known):.6g} N m = 0, T = {moment_words(effort)}"


def rotation_words(t: float, w: float, digits: int = 8) -> str:
    """A moment counted in the sense of rotation (a crank turning at ``w``): its size, with
    'in the sense of rotation' or 'against it' and its sense ('221.43 N m against the
    rotation (CW)'), not a signed number."""
    if abs(t) < 1e-12:
        return "0 N m"
    way = "in the sense of rotation" if t > 0 else "against the rotation"
    turning = math.copysign(1.0, w if w else 1.0) * t
    return f"{abs(t):.{digits}g} N m {way} ({sense(turning)})"


def effort_words(model, e: float, sol=None, digits: int = 8) -> str:
    """The balancing effort in words: a torque with its sense ('221.43 N m CCW'); an
    actuator's force pushing or pulling; a force at a slider with the way it points along
    the guide ('5804.419 N towards 0° (along the guide)', needs the solution ``sol``, else
    '… N along the guide, + towards …°'); 0 without a sense."""
    from . import effort
    if effort.is_torque(model):
        return moment_words(e, digits=digits)
    spec = model.parsed.effort
    if abs(e) < 1e-300:
        return "0 N"
    if spec is not None and spec.kind == "actuator":
        return f"{abs(e):.{digits}g} N {'pushing (compression)' if e > 0 else 'pulling (tension)'}"
    if sol is None:
        return f"{abs(e):.{digits}g} N along the guide ({'+' if e > 0 else '−'})"
    d = effort.terms(model, sol)[0].direction * (1.0 if e > 0 else -1.0)
    return f"{abs(e):.{digits}g} N towards {angle(d)}° (along the guide)"


def lever_moment_words(m: float, digits: int = 6) -> str:
    """A moment on Zhukovsky's lever (a force in N at a turned image in m/s: N m/s) with its
    sense: '4.62687 N m/s CW'; 0 as '0'."""
    if abs(m) < 1e-9 * max(1.0, abs(m)) or abs(m) < 1e-12:
        return "0"
    return f"{abs(m):.{digits}g} N m/s {sense(m)}"


def lever_sum_words(model, lv) -> str:
    """Zhukovsky's lever's balance in words: 'Σ moments of the known forces about o: 4637.6
    N m/s CCW; a unit effort (1 N m CCW) gives 20.944 N m/s CW' — each moment once, with
    its sense (``lv``: :class:`polygons.forces.zhukovsky.Lever`)."""
    from . import effort
    spec = model.parsed.effort
    one = ("1 N m CCW" if effort.unit(model) == "N m" else "1 N pushing"
           if spec is not None and spec.kind == "actuator" else "1 N along the guide")
    return (f"Σ moments of the known forces about o: {lever_moment_words(lv.moment_sum)}; "
            f"a unit effort ({one}) gives {lever_moment_words(lv.unit_moment)}")


def table_moment(m: float, digits: int = 6) -> str:
    """A moment in a table whose heading gives the unit: '4.62687 CW', '0' (never '-0')."""
    if abs(m) < 1e-12:
        return "0"
    return f"{abs(m):.{digits}g} {sense(m)}"


__all__ = ["angle", "sense", "moment_words", "sense_words", "found_words", "balance_words",
           "rotation_words", "effort_words", "lever_moment_words", "lever_sum_words",
           "table_moment",
           "DIRECTIONS"]
