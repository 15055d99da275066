"""The handout's problem section: the statement as printed (its paragraphs; the answers left
out of a worksheet) and the data table, every datum read off the scene and its mechanism
model (:mod:`polygons.model`), long tables two data a row.  Written into the document
(``doc.add``, ``doc.sec``) by :func:`diagrams.handout.handout`.
"""
from __future__ import annotations

import math
import re

from polygons.contacts import wheel_of
from polygons.evaluate import Solution
from polygons.report import sense
from polygons.scene import Crank

from .handout_forces import load_rows
from .html import esc, plain_text


def _paragraphs(text: str) -> list[str]:
    """A statement written with hard line breaks → its paragraphs / list items."""
    out: list[str] = []
    marker = re.compile(r"^(\s*[-•]\s|\s*\d+\.\s|\s*\([ivx]+\)\s|\s*\([a-z]\)\s|\s*\(Ans|"
                        r"\s*\(Answer)")
    for line in text.strip().splitlines():
        if not line.strip():
            out.append("")
            continue
        if out and out[-1] and not marker.match(line):
            out[-1] += " " + line.strip()
        else:
            out.append(line.strip())
    return [p for p in out if p]


_ANSWER_UNITS = r"(?:m/s\^?2|m/s²|m/s|rad/s\^?2|rad/s²|rad/s|N\b|kN\b|N ?m\b|W\b)"
_PAREN = re.compile(r"\(([^()]*)\)")


def redact_answers(text: str) -> str:
    """The statement without the printed answers: '(Ans. 76 rad/s clockwise.)', '(Answer 34
    m/s ...)' and parentheses quoting results in m/s, rad/s, N ... become '(answer on the
    key)'.  Given data in words ('(alpha is 21.052 deg at this position)') stays."""
    def repl(m):
        inner = m.group(1).strip()
        if re.match(r"(?i)ans(wer)?s?\b", inner) or re.search(
                r"\d\s*" + _ANSWER_UNITS, inner):
            return "(answer on the key)"
        return m.group(0)
    return _PAREN.sub(repl, text)


def _g(x: float) -> str:
    """A given datum as written: up to 6 significant figures, no trailing zeros."""
    if x == 0:
        return "0"
    return f"{x:.6g}".replace("-", "−")


def _fmt_len(si: float) -> str:
    return f"{_g(si * 1000.0)} mm"


#: a data table longer than this many rows sets two short data side by side in a row
#: (link OA | 100 mm | link AF | 300 mm), as books print a long list of lengths
PAIRED_DATA = 8
#: a datum of at most this many characters is short
SHORT_DATUM = 28


def _data_rows(rows: list[tuple[str, str]]) -> list[list[tuple[str, str]]]:
    """The data table's rows: one datum a row, or, for a table of more than
    :data:`PAIRED_DATA` data, two consecutive short data (:data:`SHORT_DATUM`) a row, in
    the order given (read across, then down); a long datum has its row to itself."""
    if len(rows) <= PAIRED_DATA:
        return [[r] for r in rows]
    def short(r):
        return len(r[0]) + len(r[1]) <= SHORT_DATUM
    out: list[list[tuple[str, str]]] = []
    for r in rows:
        if short(r) and out and len(out[-1]) == 1 and short(out[-1][0]):
            out[-1].append(r)
        else:
            out.append([r])
    return out


def data(sol: Solution) -> list[tuple[str, str]]:
    """The data table's rows (name, value), every datum read off the scene's model."""
    scene = sol.scene
    drv = scene.driver
    rows: list[tuple[str, str]] = []
    for lab, p in scene.ground.items():
        rows.append((f"fixed point {lab}", f"({_g(p[0] * 1000)}, {_g(p[1] * 1000)}) mm"))
    for ln in scene.model.links():
        if ln.length is not None:
            rows.append((f"link {ln.name}", _fmt_len(ln.length)))
    model = scene.model
    for pin, slot in model.slot.items():
        lever, pivot = slot.carrier, slot.line.origin
        txt = (f"{pin} slides in the slot of the lever {lever}, which turns about "
               f"{pivot}; {slot.coincident} is the point of the lever under {pin}")
        far_length = model.body(lever).length
        if slot.far and far_length:
            txt += f"; {pivot}{slot.far} = {_fmt_len(far_length)}"
        rows.append((f"slot {lever}", txt))
    for lab, g in model.guide.items():
        through, angle = g.line.through, g.line.angle
        txt = (f"slides on a fixed guide through ({_g(through[0] * 1000)}, "
               f"{_g(through[1] * 1000)}) mm at {_g(math.degrees(angle))}°")
        for yoke in model.yoke_slots():
            if yoke.carrier == lab:
                txt += (f"; it carries a slot at {_g(math.degrees(yoke.line.angle))}° in "
                        f"which {yoke.at} slides")
        if model.body(lab).kind == "wheel":           # a driven rolling wheel
            r = wheel_of(scene, lab).radius
            txt = (f"a wheel of radius {_fmt_len(r)} rolling without slipping on the fixed "
                   f"surface at {_g(math.degrees(angle))}°; its centre at "
                   f"({_g(through[0] * 1000)}, {_g(through[1] * 1000)}) mm")
            rows.append((f"wheel {lab}", txt))
            rows += [(f"pin {p}", f"on the wheel {lab}, {_fmt_len(d)} from its centre at "
                                  f"{_g(math.degrees(a))}°")
                     for p, a, d in wheel_of(scene, lab).rim]
            continue
        rows.append((f"slider {lab}", txt))
    for lab, bp in scene.model.points.items():
        if bp.along is not None:
            where = f"{_fmt_len(bp.along)} along {bp.link}"
        else:
            where = f"at {_g(bp.fraction)} of {bp.link}"
        if bp.left:
            where += f", {_fmt_len(bp.left)} to the left"
        rows.append((f"point {lab}", f"rigid with {bp.link}: {where}"))
    if isinstance(drv, Crank):
        # a driven link carrying a slot (the oscillating cylinder O4Q) is no crank
        what = ("driving link" if any(sl.lever == drv.link
                                      for sl in getattr(scene, "slots", {}).values())
                else "crank")
        rows.append((f"input {what} {drv.link}",
                     f"turns about {drv.pivot}; at this instant {drv.link} is at "
                     f"{_g(math.degrees(drv.angle))}° (CCW from the +x axis)"))
        rpm = abs(drv.omega) * 60.0 / (2 * math.pi)
        rows.append((f"ω of the {what}", f"{_g(abs(drv.omega))} rad/s {sense(drv.omega)} "
                                         f"(= {_g(rpm)} rev/min)"))
        rows.append((f"α of the {what}", "0 (constant speed)" if drv.alpha == 0 else
                     f"{_g(abs(drv.alpha))} rad/s² {sense(drv.alpha)}"))
    elif model.body(drv.point).kind == "wheel":
        r = wheel_of(scene, drv.point).radius
        rows.append((f"input wheel {drv.point}",
                     f"ω = {_g(abs(drv.velocity / r))} rad/s {sense(-drv.velocity)}, α = "
                     f"{_g(abs(drv.acceleration / r))} rad/s² {sense(-drv.acceleration)}"))
    elif drv.rod_rate is not None:        # the book gives the rod's ω and α
        rod, w, al = drv.rod_rate
        pts = sol.placement.points
        a, b = (drv.point, rod.replace(drv.point, "", 1)) if rod.startswith(drv.point) else \
            (rod.replace(drv.point, "", 1), drv.point)
        at = (f"at {_g(math.degrees(math.atan2(pts[b][1] - pts[a][1], pts[b][0] - pts[a][0])))}"
              f"° ({a} → {b}, CCW from +x); " if a in pts and b in pts else "")
        rows.append((f"input rod {rod}", f"{at}ω = {_g(abs(w))} rad/s {sense(w)}, α = "
                                         f"{_g(abs(al))} rad/s² {sense(al)}".rstrip()))
    else:
        rows.append((f"input slider {drv.point}",
                     f"v = {_g(drv.velocity)} m/s, a = {_g(drv.acceleration)} m/s² along its "
                     f"guide"))
    for lab, br in scene.assembly.items():
        rows.append((f"assembly of {lab}", br.text))
    rows += load_rows(scene.loads, _g)
    return rows


def problem(doc, sol: Solution, worksheet: bool, beside=None) -> None:
    """The problem section: its statement (the printed answers left out of a worksheet,
    :func:`redact_answers`) and its data table, every datum read off the scene's model.

    ``beside`` (a function of ``doc``) sets the data in a column with what it writes (the
    space diagram's heading and words, then its figure: :func:`diagrams.handout._space`)
    beside them, one datum a row."""
    scene = sol.scene
    doc.add(f'<section id="problem">\n<h2>{doc.sec()}. The problem</h2>\n')
    statement = scene.source.get("statement", "")
    if statement:
        if worksheet:
            statement = redact_answers(statement)
        doc.add('<div class="statement">\n')
        for para in _paragraphs(statement):
            doc.add(f"<p>{esc(plain_text(para))}</p>\n")
        doc.add("</div>\n")
    if beside is not None:
        doc.add('<div class="beside">\n<div class="beside-text">\n')
    doc.add("<h3>Data</h3>\n<table class=\"data\">\n<tbody>\n")
    rows = data(sol)
    paired = beside is None and len(rows) > PAIRED_DATA
    for pair in (_data_rows(rows) if beside is None else [[r] for r in rows]):
        cells = "".join(f"<th scope=\"row\">{esc(a)}</th><td>{esc(plain_text(b))}</td>"
                        for a, b in pair)
        if len(pair) == 1 and paired:      # across the table
            cells = cells.replace("<td>", '<td colspan="3">')
        doc.add(f"<tr>{cells}</tr>\n")
    doc.add("</tbody>\n</table>\n")
    doc.add('<p class="note">Coordinates: x to the right, y up; angles counter-clockwise (CCW) '
            'from +x; CW = clockwise.</p>\n')
    if beside is not None:
        beside(doc)
        doc.add("</div>\n")
    doc.add("</section>\n")
