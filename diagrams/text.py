"""Text on the drawings: display spelling, width estimates and wrapping (no svgwrite here).

Label placement needs the size of a text before it is drawn.  The widths below are the
advance widths of DejaVu Sans (em units) — the font the SVGs ask for first — so the boxes the
placer tests are the boxes a renderer draws, to within a few per cent for other sans fonts.
"""
from __future__ import annotations

from .notation import width as _typeset_width

#: font stack asked for by the SVGs (the widths above are DejaVu Sans)
FONT_FAMILY = "DejaVu Sans, Verdana, Arial, Helvetica, sans-serif"

#: text height above the baseline and depth below it, as fractions of the font size
ASCENT = 0.76
DESCENT = 0.24


def display(text: str) -> str:
    """The spelling drawn on paper: '⟂' (missing from common fonts) as '⊥', '^2' as '²'."""
    return (text.replace("⟂", "⊥").replace("^2", "²").replace("^3", "³")
            .replace("rad/s2", "rad/s²"))


def width(text: str, size: float) -> float:
    """Advance width of ``text`` typeset (:mod:`diagrams.notation`) at ``size`` (mm)."""
    return _typeset_width(text, size)


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
