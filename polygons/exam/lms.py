"""An exam's questions for learning systems: Moodle XML, GIFT and a QTI 1.2 package.

Per variant and per asked quantity one **numerical** question.  Every question carries the
variant's data in words (a table: fixed points, lengths, slots, the driver), states what is
asked and its one sign convention (ω, α signed, + counter-clockwise; a sliding value signed
along its slot; a point's velocity or acceleration as a magnitude); a picture, where there
is one, is marked not to scale (a screen shows it at no known scale).  Full credit within the
drawing tolerance and ``partial`` credit within ``partial_factor`` × it (Moodle's numerical
``get_matching_answer`` grades by the first answer whose |response − answer| ≤ tolerance).
Moodle XML is written the way ``question/format/xml/format.php`` imports it
(``<question type="numerical">``, ``<questiontext format="html">`` with the space diagram as
``<file name=... encoding="base64">`` referred to as ``@@PLUGINFILE@@/name``, ``<answer
fraction=...><text/><tolerance/>``, ``<units><unit><multiplier/><unit_name/>``); each variant's
questions go in a category of their own so a quiz can draw one variant per student.  GIFT
cannot carry a file: the data in words make it self-contained; each item is one line.  The
QTI package (``imsmanifest.xml`` + one assessment with Canvas's ``numerical_question``
metadata) carries the diagrams as files and only the full-credit band (Canvas makes every
respcondition a fully correct answer: :func:`_qti_numerical`).

Every piece of text from the scene is escaped where it lands: HTML inside XML (ElementTree
escapes the XML, :func:`html.escape` the HTML), GIFT's ``~ = # { } :`` and backslash in
names and stems; a GIFT category has no escape at all (:func:`_cat`).  Output is
deterministic: the same variants give the same bytes (fixed zip timestamps).
"""
from __future__ import annotations

import base64
import html
import io
import math
import xml.etree.ElementTree as ET
import zipfile
from typing import Mapping

from .variants import Asked, ExamSet, Variant, convention, data_rows, one_line

#: units as a learner types them (Moodle compares the unit text)
ASCII_UNIT = {"m/s": "m/s", "m/s²": "m/s^2", "rad/s": "rad/s", "rad/s²": "rad/s^2"}
ZIP_TIME = (1980, 1, 1, 0, 0, 0)
#: the picture's caption: a screen shows it at no known size (its scale bar grows with it)
NOT_TO_SCALE = ("Space diagram not to scale on screen: measure against its scale bar, which "
                "is resized with it, or take every dimension from the data table.")


def number(x: float) -> str:
    """Six significant figures, never in e-notation (every importer reads it)."""
    if x == 0 or not math.isfinite(x):
        return "0"
    decimals = max(0, 5 - math.floor(math.log10(abs(x))))
    text = f"{x:.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def partial_tolerance(exam: ExamSet, a: Asked) -> float:
    return a.tolerance * exam.spec.partial_factor


def qname(v: Variant, a: Asked, what: str = "") -> str:
    return f"V{v.number:02d} {what}{a.symbol}"


def image_name(v: Variant) -> str:
    return f"variant-{v.number:02d}-space.svg"


# ---------------------------------------------------------------- the question's words
def data_html(v: Variant) -> str:
    """The variant's data as an HTML table (every value from the scene, escaped): all a
    student needs, whatever the picture shows."""
    rows = "".join(f"<tr><td>{html.escape(what)}</td><td>{html.escape(value)}</td></tr>"
                   for what, value in (v.data or data_rows(v.scene)))
    return ("<table><caption>Data (x to the right, y up; angles counter-clockwise from "
            "+x)</caption>" + rows + "</table>")


def stem_html(exam: ExamSet, v: Variant, a: Asked, image: bool) -> str:
    """One question: title, picture (marked not to scale: the data table is the data),
    the data in words, what is asked and its sign convention.  One line: GIFT items end at
    a blank line."""
    title = html.escape(one_line(v.scene.title))
    head = (f"<p><strong>{title}</strong></p>"
            + (f'<p><img src="@@PLUGINFILE@@/{html.escape(image_name(v))}" '
               f'alt="space diagram of variant {v.number}"><br>'
               f"<em>{NOT_TO_SCALE}</em></p>" if image else "")
            + data_html(v))
    return head + (f"<p>Draw the construction and find the {html.escape(a.words)}, "
                   f"{html.escape(a.symbol)}, in {html.escape(ASCII_UNIT[a.unit])}. "
                   f"{html.escape(convention(a.fn, a.expr, v.solution))}</p>")


# ---------------------------------------------------------------- Moodle XML
def _text(parent, tag: str, text: str, fmt: str | None = None):
    el = ET.SubElement(parent, tag, {"format": fmt} if fmt else {})
    ET.SubElement(el, "text").text = text
    return el


def _value(parent, tag: str, text: str):
    ET.SubElement(parent, tag).text = text


def moodle_xml(exam: ExamSet, images: Mapping[int, bytes] | None = None) -> bytes:
    """The whole exam as Moodle XML (``images``: variant number → space diagram SVG)."""
    images = images or {}
    root = ET.Element("quiz")
    title = exam.scene.title
    for v in exam.variants:
        cat = ET.SubElement(root, "question", {"type": "category"})
        _text(cat, "category", f"$course$/top/polygons exam/{_cat(title)}/variant "
                               f"{v.number:02d}")
        _text(cat, "info", "", "html")
        for a in v.asked:
            q = ET.SubElement(root, "question", {"type": "numerical"})
            _text(q, "name", qname(v, a))
            qt = _text(q, "questiontext", stem_html(exam, v, a, v.number in images), "html")
            if v.number in images:
                f = ET.SubElement(qt, "file", {"name": image_name(v), "path": "/",
                                               "encoding": "base64"})
                f.text = base64.b64encode(images[v.number]).decode("ascii")
            _text(q, "generalfeedback", html.escape(
                f"{a.symbol} = {number(a.answer)} {ASCII_UNIT[a.unit]} ± "
                f"{number(a.tolerance)} (a careful drawing's tolerance)"), "html")
            _value(q, "defaultgrade", "1.0000000")
            _value(q, "penalty", "0.3333333")
            _value(q, "hidden", "0")
            _value(q, "idnumber", f"polygons-v{v.number:02d}-{a.expr}")
            for fraction, tol, words in (
                    ("100", a.tolerance, "Within a careful drawing's tolerance."),
                    (number(exam.spec.partial * 100), partial_tolerance(exam, a),
                     "Close: within about three times a careful drawing's tolerance.")):
                ans = ET.SubElement(q, "answer", {"fraction": fraction,
                                                  "format": "moodle_auto_format"})
                ET.SubElement(ans, "text").text = number(a.answer)
                _text(ans, "feedback", html.escape(words), "html")
                _value(ans, "tolerance", number(tol))
            _value(q, "unitgradingtype", "0")
            _value(q, "unitpenalty", "0.1000000")
            _value(q, "showunits", "0")
            _value(q, "unitsleft", "0")
            units = ET.SubElement(q, "units")
            unit = ET.SubElement(units, "unit")
            _value(unit, "multiplier", "1")
            _value(unit, "unit_name", ASCII_UNIT[a.unit])
    ET.indent(root, space="  ")
    return ET.tostring(root, encoding="UTF-8", xml_declaration=True) + b"\n"


def _cat(title: str) -> str:
    """A category path segment: one line ('/' would nest categories).  Moodle's GIFT
    importer runs ``escapedchar_pre`` over the ``$CATEGORY`` line and never
    ``escapedchar_post`` (question/format/gift/format.php, ``readquestion``), so an escape
    there would arrive as '&&058;': the segment needs none — the category line is read whole
    before any ``::``, ``{`` or ``~`` is looked for, so those survive as they are, and a
    backslash (the only start of an escape) becomes '-'."""
    return one_line(title).replace("/", "-").replace("\\", "-")


# ---------------------------------------------------------------- GIFT
GIFT_SPECIAL = "\\~=#{}:"


def gift_escape(text: str) -> str:
    return "".join("\\" + c if c in GIFT_SPECIAL else c for c in text)


def gift(exam: ExamSet) -> str:
    """One GIFT item per question, each on one line (Moodle splits items at blank lines):
    ``::name::[html]stem{#=answer:tolerance =%50%answer:3×tolerance}``, each variant after
    its ``$CATEGORY`` line."""
    out = [f"// polygons exam: {_comment(exam.scene.title)} (seed {exam.seed}); GIFT "
           f"carries no picture: the data are given in words", ""]
    for v in exam.variants:
        out += [f"$CATEGORY: $course$/top/polygons exam/{_cat(exam.scene.title)}"
                f"/variant {v.number:02d}", ""]
        for a in v.asked:
            stem = gift_escape(one_line(stem_html(exam, v, a, False)))
            p = number(exam.spec.partial * 100)
            out.append(f"::{gift_escape(one_line(qname(v, a)))}::[html]{stem}"
                       f"{{#={number(a.answer)}:{number(a.tolerance)} "
                       f"=%{p}%{number(a.answer)}:{number(partial_tolerance(exam, a))}}}")
            out.append("")
    return "\n".join(out)


def _comment(text: str) -> str:
    return " ".join(text.split())


# ---------------------------------------------------------------- QTI 1.2 (Canvas)
def _meta(item, fields: dict) -> None:
    md = ET.SubElement(ET.SubElement(item, "itemmetadata"), "qtimetadata")
    for k, val in fields.items():
        f = ET.SubElement(md, "qtimetadatafield")
        ET.SubElement(f, "fieldlabel").text = k
        ET.SubElement(f, "fieldentry").text = val


def _mat(parent, html_text: str) -> None:
    m = ET.SubElement(parent, "material")
    ET.SubElement(m, "mattext", {"texttype": "text/html"}).text = html_text


def _qti_image(stem: str, v: Variant) -> str:
    """Canvas's reference to a file of the package (``$IMS-CC-FILEBASE$``, URL-escaped)."""
    return stem.replace(f"@@PLUGINFILE@@/{image_name(v)}",
                        f"%24IMS-CC-FILEBASE%24/images/{image_name(v)}")


def qti_assessment(exam: ExamSet, images: Mapping[int, bytes]) -> bytes:
    root = ET.Element("questestinterop", {
        "xmlns": "http://www.imsglobal.org/xsd/ims_qtiasiv1p2",
        "xmlns:xsi": "http://www.w3.org/2001/XMLSchema-instance",
        "xsi:schemaLocation": "http://www.imsglobal.org/xsd/ims_qtiasiv1p2 "
                              "http://www.imsglobal.org/xsd/ims_qtiasiv1p2p1.xsd"})
    asm = ET.SubElement(root, "assessment", {"ident": "polygons-exam",
                                             "title": exam.scene.title})
    section = ET.SubElement(asm, "section", {"ident": "root_section"})
    for v in exam.variants:
        for a in v.asked:
            _qti_numerical(section, exam, v, a, v.number in images)
    ET.indent(root, space="  ")
    return ET.tostring(root, encoding="UTF-8", xml_declaration=True) + b"\n"


def _qti_numerical(section, exam, v, a, image: bool) -> None:
    """One numerical item with ONE respcondition, full credit within the tolerance.  Canvas's
    importer (gems/plugins/qti_exporter/lib/qti/numeric_interaction.rb,
    ``get_canvas_answers``) turns every respcondition into an answer of ``:weight=>100``:
    a partial band would become a second fully correct answer, so it is left out (Canvas's
    numerical questions have no partial credit; the README says so)."""
    item = ET.SubElement(section, "item", {"ident": f"v{v.number:02d}-{_ident(a.expr)}",
                                           "title": qname(v, a)})
    _meta(item, {"question_type": "numerical_question", "points_possible": "1.0"})
    pres = ET.SubElement(item, "presentation")
    _mat(pres, _qti_image(stem_html(exam, v, a, image), v))
    rs = ET.SubElement(pres, "response_str", {"ident": "response1", "rcardinality": "Single"})
    ET.SubElement(ET.SubElement(rs, "render_fib", {"fibtype": "Decimal"}), "response_label",
                  {"ident": "answer1"})
    proc = ET.SubElement(item, "resprocessing")
    ET.SubElement(ET.SubElement(proc, "outcomes"), "decvar", {
        "maxvalue": "100", "minvalue": "0", "varname": "SCORE", "vartype": "Decimal"})
    for score, tol in (("100", a.tolerance),):
        cond = ET.SubElement(proc, "respcondition", {"continue": "No"})
        var = ET.SubElement(ET.SubElement(cond, "conditionvar"), "or")
        ET.SubElement(var, "varequal", {"respident": "response1"}).text = number(a.answer)
        both = ET.SubElement(var, "and")
        ET.SubElement(both, "vargte", {"respident": "response1"}).text = number(a.answer - tol)
        ET.SubElement(both, "varlte", {"respident": "response1"}).text = number(a.answer + tol)
        ET.SubElement(cond, "setvar", {"action": "Set", "varname": "SCORE"}).text = score


def _ident(expr: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in expr).strip("_")


def qti_manifest(exam: ExamSet, images: Mapping[int, bytes]) -> bytes:
    ns = "http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1"
    root = ET.Element("manifest", {"identifier": "polygons-exam-manifest", "xmlns": ns})
    meta = ET.SubElement(root, "metadata")
    ET.SubElement(meta, "schema").text = "IMS Content"
    ET.SubElement(meta, "schemaversion").text = "1.1.3"
    ET.SubElement(root, "organizations")
    res = ET.SubElement(root, "resources")
    r = ET.SubElement(res, "resource", {"identifier": "polygons-exam",
                                        "type": "imsqti_xmlv1p2", "href": "quiz.xml"})
    ET.SubElement(r, "file", {"href": "quiz.xml"})
    for n in sorted(images):
        ET.SubElement(r, "dependency", {"identifierref": f"image-{n:02d}"})
    for n in sorted(images):
        img = ET.SubElement(res, "resource", {"identifier": f"image-{n:02d}",
                                              "type": "webcontent",
                                              "href": f"images/variant-{n:02d}-space.svg"})
        ET.SubElement(img, "file", {"href": f"images/variant-{n:02d}-space.svg"})
    ET.indent(root, space="  ")
    return ET.tostring(root, encoding="UTF-8", xml_declaration=True) + b"\n"


def qti_zip(exam: ExamSet, images: Mapping[int, bytes] | None = None) -> bytes:
    images = images or {}
    files = [("imsmanifest.xml", qti_manifest(exam, images)),
             ("quiz.xml", qti_assessment(exam, images))]
    files += [(f"images/variant-{n:02d}-space.svg", images[n]) for n in sorted(images)]
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files:
            info = zipfile.ZipInfo(name, ZIP_TIME)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            z.writestr(info, data)
    return buf.getvalue()


__all__ = ["moodle_xml", "gift", "qti_zip", "qti_assessment", "qti_manifest", "number",
           "gift_escape", "partial_tolerance"]
