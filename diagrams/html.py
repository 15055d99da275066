"""Small HTML helpers for the handouts: escaping, textbook symbols, numbers, inline SVG.

No svgwrite here: figures come from :mod:`diagrams.svg` as bytes and are inlined as text; the
worksheet's empty drawing area (:func:`grid_svg`) is written as plain SVG text.
"""
from __future__ import annotations

import html
import math
import re

from .text import FONT_FAMILY


def esc(text) -> str:
    return html.escape(str(text), quote=True)


def plain_text(text: str) -> str:
    """Spelling for print: '⟂' (missing from many fonts) as '⊥', '^2' as '²'."""
    return (text.replace("⟂", "⊥").replace("rad/s^2", "rad/s²").replace("m/s^2", "m/s²")
            .replace("^2", "²"))




def sym(text: str) -> str:
    """Escaped HTML with textbook subscripts: '(a_C)_B^n' → (a<sub>C</sub>)<sub>B</sub><sup>n</sup>,
    vertex 'p2_1' → p<sub>2</sub>′ (one notation with the SVGs: :mod:`diagrams.notation`)."""
    from .notation import html as typeset
    return typeset(plain_text(text))


def num(x: float | None, digits: int = 4) -> str:
    """``x`` to ``digits`` significant figures, plainly written for drawing-board sizes."""
    if x is None:
        return "–"
    if x == 0:
        return "0"
    mag = abs(x)
    if 1e-4 <= mag < 1e9:
        decimals = max(0, digits - 1 - int(math.floor(math.log10(mag))))
        s = f"{round(x, decimals):.{decimals}f}"
        return s.replace("-", "−")
    return f"{x:.{digits}g}".replace("-", "−")


def unit(u: str) -> str:
    return esc(plain_text(u))


_ID = re.compile(r'\bid="([^"]+)"')
_REF = re.compile(r'(url\(#|href="#)([^")]+)')


def inline_svg(svg: bytes | str, prefix: str, css_class: str = "",
               width_mm: float | None = None, label: str = "") -> str:
    """An SVG document as an element to put inside HTML.

    The XML declaration goes; every ``id`` (and the references to it) gets ``prefix`` so many
    figures can share one page; ``width_mm`` sets the printed width (height follows the
    viewBox); ``label`` becomes the accessible name.
    """
    text = svg.decode("utf-8") if isinstance(svg, bytes) else svg
    text = re.sub(r"^\s*<\?xml[^>]*\?>\s*", "", text)
    text = re.sub(r"<!DOCTYPE[^>]*>\s*", "", text)
    text = _ID.sub(lambda m: f'id="{prefix}-{m.group(1)}"', text)
    text = _REF.sub(lambda m: f"{m.group(1)}{prefix}-{m.group(2)}", text)
    m = re.search(r"<svg\b[^>]*>", text)
    if not m:
        raise ValueError("not an SVG document")
    tag = m.group(0)
    vb = re.search(r'viewBox="([^"]+)"', tag)
    attrs = tag[len("<svg"):-1]
    attrs = re.sub(r'\s(width|height)="[^"]*"', "", attrs)
    if vb and width_mm is not None:
        _, _, w, h = (float(v) for v in vb.group(1).split())
        attrs += f' width="{width_mm:.1f}mm" height="{width_mm * h / w:.1f}mm"'
    elif vb:
        _, _, w, h = (float(v) for v in vb.group(1).split())
        attrs += f' width="{w:g}mm" height="{h:g}mm"'
    if css_class:
        attrs += f' class="{esc(css_class)}"'
    if label:
        attrs += f' role="img" aria-label="{esc(label)}"'
    return text[:m.start()] + "<svg" + attrs + ">" + text[m.end():]


def svg_size(svg: bytes | str) -> tuple[float, float]:
    """(width, height) in mm from the viewBox (the diagrams draw 1 user unit = 1 mm)."""
    text = svg.decode("utf-8") if isinstance(svg, bytes) else svg
    vb = re.search(r'viewBox="([^"]+)"', text)
    _, _, w, h = (float(v) for v in vb.group(1).split())
    return w, h


def grid_svg(width_mm: float, height_mm: float, scale_statement: str, per_cm_display: float,
             unit_text: str, ident: str, title: str, pole: tuple[float, float] | None = None,
             pole_label: str = "") -> str:
    """An empty drawing area of ``width_mm`` × ``height_mm`` at true size: a 5 mm grid with
    the centimetres heavier, a scale bar in whole centimetres and the scale statement, and
    (optionally) a small ring where the key's drawing puts the pole."""
    bar_h, pad = 14.0, 4.0
    W, H = width_mm + 2 * pad, height_mm + bar_h
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" class="drawing-area" id="{esc(ident)}" '
           f'viewBox="{-pad:g} 0 {W:g} {H:g}" width="{W:g}mm" height="{H:g}mm" role="img" '
           f'aria-label="{esc(title)}">',
           f"<title>{esc(title)}</title>",
           f'<rect x="0" y="0" width="{width_mm:g}" height="{height_mm:g}" fill="#ffffff" '
           f'stroke="#000000" stroke-width="0.3"/>']
    minor, major = [], []
    x = 5.0
    while x < width_mm - 1e-9:
        (major if abs(x / 10 - round(x / 10)) < 1e-9 else minor).append(
            f"M{x:g} 0V{height_mm:g}")
        x += 5.0
    y = 5.0
    while y < height_mm - 1e-9:
        (major if abs(y / 10 - round(y / 10)) < 1e-9 else minor).append(
            f"M0 {y:g}H{width_mm:g}")
        y += 5.0
    out.append(f'<path d="{" ".join(minor)}" stroke="#d9d9d9" stroke-width="0.15" '
               f'fill="none"/>')
    out.append(f'<path d="{" ".join(major)}" stroke="#b3b3b3" stroke-width="0.25" '
               f'fill="none"/>')
    if pole is not None:
        px, py = pole
        out.append(f'<circle cx="{px:.1f}" cy="{py:.1f}" r="1.2" fill="none" stroke="#000000" '
                   f'stroke-width="0.3"/>')
        if pole_label:
            # beside the ring, on whichever side and above or below it the whole note fits
            # inside the area (it is clipped at the area's edge otherwise)
            from .text import width as text_width
            w = text_width(pole_label, 3.0)
            right = px + 2.2 + w <= width_mm - 1.0 or px - 2.2 - w < 1.0
            x, anchor = (px + 2.2, "start") if right else (px - 2.2, "end")
            y = py + 4.2 if py + 4.2 <= height_mm - 1.0 else py - 2.2
            out.append(f'<text x="{x:.1f}" y="{y:.1f}" font-size="3" text-anchor="{anchor}" '
                       f'font-family="{FONT_FAMILY}" fill="#000000">{esc(pole_label)}</text>')
    # scale bar: whole centimetres under the area
    n = int(max(2, min(10, math.floor((width_mm - 60.0) / 10.0))))
    y0 = height_mm + 5.0
    parts = [f"M0 {y0:g}H{10 * n:g}"] + [f"M{10 * i:g} {y0:g}v-1.5" for i in range(n + 1)]
    out.append(f'<path d="{" ".join(parts)}" stroke="#000000" stroke-width="0.3" '
               f'fill="none"/>')
    step = 1
    while step < n and len(_plain(per_cm_display * n)) * 1.7 + 2.0 > 10.0 * step:
        step += 1
    for i in range(0, n + 1, step):
        out.append(f'<text x="{10 * i:g}" y="{y0 + 4.0:g}" font-size="2.6" '
                   f'text-anchor="middle" font-family="{FONT_FAMILY}">'
                   f'{esc(_plain(per_cm_display * i))}</text>')
    out.append(f'<text x="{10 * n + 7:g}" y="{y0 + 1.0:g}" font-size="3" '
               f'font-family="{FONT_FAMILY}">{esc(unit_text)}</text>')
    out.append(f'<text x="{10 * n + 7:g}" y="{y0 + 6.0:g}" font-size="3.2" font-weight="bold" '
               f'font-family="{FONT_FAMILY}">Scale {esc(scale_statement)}</text>')
    out.append("</svg>")
    return "".join(out)


def _plain(x: float) -> str:
    s = f"{x:.10f}".rstrip("0").rstrip(".")
    return s if s not in ("", "-0") else "0"
