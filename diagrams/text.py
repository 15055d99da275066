"""Text on the drawings: display spelling, width estimates and wrapping (no svgwrite here).

Label placement needs the size of a text before it is drawn.  The widths below are the
advance widths of DejaVu Sans (em units) — the font the SVGs ask for first — so the boxes the
placer tests are the boxes a renderer draws, to within a few per cent for other sans fonts.
"""
from __future__ import annotations

import json

_WIDTHS: dict[str, float] = json.loads(
    '{" ": 0.318, "!": 0.401, "\\"": 0.46, "#": 0.838, "$": 0.636, "%": 0.95, "&": 0.78, '
    '"\'": 0.275, "(": 0.39, ")": 0.39, "*": 0.5, "+": 0.838, ",": 0.318, "-": 0.361, '
    '".": 0.318, "/": 0.337, "0": 0.636, "1": 0.636, "2": 0.636, "3": 0.636, "4": 0.636, '
    '"5": 0.636, "6": 0.636, "7": 0.636, "8": 0.636, "9": 0.636, ":": 0.337, ";": 0.337, '
    '"<": 0.838, "=": 0.838, ">": 0.838, "?": 0.531, "@": 1.0, "A": 0.684, "B": 0.686, '
    '"C": 0.698, "D": 0.77, "E": 0.632, "F": 0.575, "G": 0.775, "H": 0.752, "I": 0.295, '
    '"J": 0.295, "K": 0.656, "L": 0.557, "M": 0.863, "N": 0.748, "O": 0.787, "P": 0.603, '
    '"Q": 0.787, "R": 0.695, "S": 0.635, "T": 0.611, "U": 0.732, "V": 0.684, "W": 0.989, '
    '"X": 0.685, "Y": 0.611, "Z": 0.685, "[": 0.39, "\\\\": 0.337, "]": 0.39, "^": 0.838, '
    '"_": 0.5, "`": 0.5, "a": 0.613, "b": 0.635, "c": 0.55, "d": 0.635, "e": 0.615, '
    '"f": 0.352, "g": 0.635, "h": 0.634, "i": 0.278, "j": 0.278, "k": 0.579, "l": 0.278, '
    '"m": 0.974, "n": 0.634, "o": 0.612, "p": 0.635, "q": 0.635, "r": 0.411, "s": 0.521, '
    '"t": 0.392, "u": 0.634, "v": 0.592, "w": 0.818, "x": 0.592, "y": 0.592, "z": 0.525, '
    '"{": 0.636, "|": 0.337, "}": 0.636, "~": 0.838, "ω": 0.837, "α": 0.659, "θ": 0.612, '
    '"²": 0.401, "³": 0.401, "∥": 0.5, "⊥": 0.871, "×": 0.838, "·": 0.318, "−": 0.838, '
    '"→": 0.838, "°": 0.5, "₁": 0.401, "₂": 0.401, "₃": 0.401, "≈": 0.838, "±": 0.838, '
    '"µ": 0.636, "—": 1.0, "–": 0.5, "′": 0.227, "″": 0.401, "‴": 0.575, "\u2060": 0.0, "Δ": 0.684, "Σ": 0.632, "√": 0.637}')
_DEFAULT_WIDTH = 0.7

#: font stack asked for by the SVGs (the widths above are DejaVu Sans)
FONT_FAMILY = "DejaVu Sans, Verdana, Arial, Helvetica, sans-serif"

#: text height above the baseline and depth below it, as fractions of the font size
ASCENT = 0.76
DESCENT = 0.24


def display(text: str) -> str:
    """The spelling drawn on paper: '⟂' (missing from common fonts) as '⊥', '^2' as '²'."""
    return (text.replace("⟂", "⊥").replace("^2", "²").replace("^3", "³")
            .replace("rad/s2", "rad/s²"))


def plain_width(text: str, size: float) -> float:
    """Advance width of ``text`` set as it is (no sub/superscripts) at ``size`` (mm)."""
    return size * sum(_WIDTHS.get(ch, _DEFAULT_WIDTH) for ch in text)


def width(text: str, size: float) -> float:
    """Advance width of ``text`` typeset (:mod:`diagrams.notation`) at ``size`` (mm)."""
    from .notation import width as typeset_width
    return typeset_width(text, size)


def wrap(text: str, max_width: float, size: float) -> list[str]:
    """Greedy word wrap of ``text`` to lines no wider than ``max_width`` mm."""
    lines: list[str] = []
    for para in text.split("\n"):
        words = para.split()
        line = ""
        for w in words:
            trial = f"{line} {w}" if line else w
            if line and width(trial, size) > max_width:
                lines.append(line)
                line = w
            else:
                line = trial
        lines.append(line)
    return lines


def number(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant figures, without exponent for drawing-board sizes."""
    if x == 0 or not (1e-4 <= abs(x) < 1e9):
        return f"{x:.{digits}g}"
    from math import floor, log10
    decimals = max(0, digits - 1 - int(floor(log10(abs(x)))))
    s = f"{round(x, decimals):.{decimals}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return s


def plain(x: float) -> str:
    """A round scale value written plainly: 2.5, 0.05, 2500."""
    s = f"{x:.10f}".rstrip("0").rstrip(".")
    return s if s not in ("", "-0") else "0"


def token(name: str) -> str:
    """A label or vertex name as an XML name token ('p4_1' stays, "B'" → 'B-u27-')."""
    return "".join(ch if (ch.isascii() and (ch.isalnum() or ch in "_.")) else
                   f"-u{ord(ch):x}-" for ch in name)


def untoken(tok: str) -> str:
    import re
    return re.sub(r"-u([0-9a-f]+)-", lambda m: chr(int(m.group(1), 16)), tok)
