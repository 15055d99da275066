"""The printed side of `polygons exam`: the teacher's key and the students' worksheets.

* :func:`key_html`: one A4 document, a page per variant: its data, every asked answer with
  its sense and the tolerance the quiz uses (full and partial credit), and the finished
  space, velocity and acceleration diagrams at the variant's round scales.
* :func:`worksheet_html`: the handout's worksheet (:func:`diagrams.handout.handout` with
  ``worksheet=True``) of one variant, its drawing areas at the variant's round scale, with
  the student's name (escaped) when given.
* :func:`space_svg`: the space diagram the quiz questions embed.
* :func:`pdf_stable`: a Chromium PDF with its dates and document ID made constant, so the
  same seed gives the same bytes.

Every piece of text from the scene or the class list is escaped (:func:`diagrams.html.esc`).
"""
from __future__ import annotations

import hashlib
import math
import re

from .html import esc
from .scale import make

CSS = """
@page { size: A4 portrait; margin: 12mm 14mm; }
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 10pt; color: #111; }
h1 { font-size: 15pt; margin: 0 0 2mm 0; }
h2 { font-size: 12.5pt; margin: 0 0 2mm 0; }
section.variant + section.variant { page-break-before: always; }
section.variant { page-break-before: always; }
section.variant.first { page-break-before: auto; }
table { border-collapse: collapse; margin: 2mm 0 3mm 0; }
td, th { border: 0.2mm solid #999; padding: 0.8mm 2mm; text-align: left; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
.figs { display: flex; flex-wrap: wrap; gap: 3mm; align-items: flex-start; }
.figs svg { max-width: 182mm; height: auto; }
.sub { color: #444; }
"""
STUDENT_CSS = ("p.student { font-size: 13pt; border: 0.3mm solid #333; padding: 2mm 3mm; "
               "margin: 0 0 3mm 0; }")
SOURCE = {"emulated": "emulated", "stated": "stated", "reading": "reading"}
LEGEND = ("Tolerance from: <em>emulated</em> — the 95th percentile of a careful drawing's error "
          "in the drawing-board emulation (pencil and rule ±0.25 mm, protractor ±0.25°); "
          "<em>stated</em> — the case's drawing tolerance; <em>reading</em> — a 0.5 mm ruler "
          "reading at the variant's scale.")


def forced_scales(variant) -> dict:
    """The variant's round polygon scales as :class:`diagrams.scale.Scale` (forced)."""
    return {d: make(d, per_cm, forced=True) for d, per_cm in variant.scales.items()}


def finished(variant):
    """The variant's finished drawings (space, velocity, acceleration; no stages) at its
    round scales, as the :class:`diagrams.figures.Figures` the handout reads."""
    import diagrams
    from .figures import Figures
    from .svg import to_svg
    figs = Figures()
    for d in diagrams.drawings(variant.solution, forced_scales(variant), None, False):
        figs.drawing[d.name] = d
        figs.svg[d.name] = to_svg(d)
    return figs


def space_svg(variant, figs=None) -> bytes:
    return (figs or finished(variant)).svg["space"]


def _num(x: float) -> str:
    """Six significant figures, no e-notation: the rule of ``polygons.exam.lms.number`` (the
    quiz's numbers; render may not import commands, and tests/test_exam.py holds them equal)."""
    if x == 0 or not math.isfinite(x):
        return "0"
    decimals = max(0, 5 - math.floor(math.log10(abs(x))))
    text = f"{x:.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def key_html(exam, figs: dict | None = None) -> str:
    """The teacher's key: every variant's answers and finished diagrams (``figs``: variant
    number → :func:`finished`, made here when not given)."""
    figs = figs or {}
    scene = exam.scene
    parts = ["<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n",
             f"<title>Exam key — {esc(scene.title)}</title>\n<style>{CSS}</style>\n</head>\n"
             "<body>\n",
             f"<h1>Exam key: {esc(scene.title)}</h1>\n",
             f"<p class=\"sub\">{len(exam.variants)} variants, seed {exam.seed}; "
             f"{exam.drawn} drawn, {exam.drawn - len(exam.variants)} rejected"
             + "".join(f"; {c} {esc(r)}" for r, c in exam.rejected.items()) + ".</p>\n",
             f"<p class=\"sub\">Every variant: construction angles ≥ "
             f"{exam.spec.min_angle_deg:g}°, assembly ≥ {exam.spec.closure_margin_deg:g}° "
             f"from the other closure, no dead centre or change of sign of an asked answer "
             f"within {exam.spec.pose_margin_deg:g}° of the pose, the line of every asked "
             f"answer ≥ {exam.spec.min_vector_mm:g} mm at the stated scale and every answer ≥ "
             f"{exam.spec.min_ratio:g}× its tolerance. Full credit within the tolerance, "
             f"{exam.spec.partial * 100:g} % within {exam.spec.partial_factor:g}× it (not in "
             f"the Canvas QTI: Canvas makes every band fully correct). ω and α are answered "
             f"signed (+ counter-clockwise), a sliding value signed along its slot, a point's "
             f"velocity or acceleration by its magnitude.</p>\n",
             f"<p class=\"sub\">{LEGEND}</p>\n"]
    for expr, why in getattr(exam, "dropped", ()):
        parts.append(f"<p class=\"sub\">Not asked: {esc(expr)} {esc(why)}.</p>\n")
    for v in exam.variants:
        first = " first" if v is exam.variants[0] else ""
        parts.append(f"<section class=\"variant{first}\">\n<h2>Variant {v.number}</h2>\n")
        parts.append("<p>" + "; ".join(f"{esc(n)} = {esc(t)}" for n, t in v.values)
                     + f" &nbsp;·&nbsp; smallest construction angle {v.min_angle_deg:.1f}°, "
                       f"assembly {v.closure_deg:.1f}°</p>\n")
        if getattr(v, "data", ()):
            parts.append("<table>" + "".join(
                f"<tr><td>{esc(what)}</td><td>{esc(value)}</td></tr>" for what, value in v.data)
                + "</table>\n")
        parts.append("<table><tr><th>quantity</th><th></th><th>answer</th><th>sense</th>"
                     "<th>± full</th><th>± partial</th><th>tolerance from</th></tr>\n")
        for a in v.asked:
            parts.append(
                f"<tr><td>{esc(a.symbol)}</td><td>{esc(a.words)}</td>"
                f"<td class=\"n\">{_num(a.answer)} {esc(a.unit)}</td>"
                f"<td>{esc(a.sense or '')}</td><td class=\"n\">{_num(a.tolerance)}</td>"
                f"<td class=\"n\">{_num(a.tolerance * exam.spec.partial_factor)}</td>"
                f"<td>{esc(SOURCE[a.source])}</td></tr>\n")
        parts.append("</table>\n<div class=\"figs\">\n")
        f = figs.get(v.number) or finished(v)
        for name in f.svg:
            svg = f.svg[name].decode("utf-8")
            svg = re.sub(r"^<\?xml[^>]*>\s*", "", svg)
            parts.append(svg + "\n")
        parts.append("</div>\n</section>\n")
    parts.append("</body>\n</html>\n")
    return "".join(parts)


def worksheet_html(variant, student: str | None = None, figs=None) -> str:
    """The handout's worksheet for one variant, at its round scales, with a name line
    (the worksheet draws no stage figure: :func:`finished` is all it needs)."""
    from .handout import handout
    text = handout(variant.solution, worksheet=True, figs=figs or finished(variant),
                   source_name=f"variant-{variant.number:02d}.toml")
    who = (f"Name: {esc(student)} &nbsp;·&nbsp; " if student else "Name: ____________ · ")
    banner = f"<p class=\"student\">{who}variant {variant.number}</p>\n"
    m = re.search(r"<body[^>]*>\n", text)
    if m is None:       # pragma: no cover - the handout always writes its body tag
        return text
    style = f"<style>{STUDENT_CSS}</style>\n"
    return text[:m.end()] + style + banner + text[m.end():]


def safe_name(text: str, limit: int = 40) -> str:
    """A file-name part: ASCII letters, digits, '-' and '_' only (spaces become '-')."""
    import unicodedata
    flat = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")
    flat = re.sub(r"[^A-Za-z0-9_-]+", "-", flat).strip("-_")
    return flat[:limit].strip("-_") or "student"


_DATE = re.compile(rb"/(CreationDate|ModDate) \(D:[^)]*\)")
_ID = re.compile(rb"/ID \[<([0-9A-Fa-f]+)> ?<([0-9A-Fa-f]+)>\]")


def pdf_stable(data: bytes) -> bytes:
    """The PDF with its dates and file ID replaced by constants of the same length (the
    cross-reference offsets stay right): byte-identical output for identical content."""
    def date(m):
        # D:YYYYMMDDHHmmSS and any time zone: every digit fixed, the length kept
        text = m.group(0)
        head = b"/" + m.group(1) + b" (D:"
        body = text[len(head):-1]
        fixed = b"19800101000000"[:len(body)]
        rest = bytes(b"0"[0] if c in b"0123456789" else c for c in body[len(fixed):])
        return head + fixed + rest + b")"
    data = _DATE.sub(date, data)
    digest = hashlib.sha256(_ID.sub(b"", data)).hexdigest().upper().encode("ascii")

    def ident(m):
        a, b = (digest * 4)[:len(m.group(1))], (digest * 4)[:len(m.group(2))]
        sep = m.group(0)[len(b"/ID [<") + len(m.group(1)) + 1:-len(m.group(2)) - 3]
        return b"/ID [<" + a + b">" + sep + b"<" + b + b">]"
    return _ID.sub(ident, data)


__all__ = ["key_html", "worksheet_html", "space_svg", "pdf_stable", "safe_name",
           "forced_scales"]
