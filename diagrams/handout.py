"""Teaching handouts: one self-contained, printable HTML document per case.

    from diagrams.handout import handout
    html = handout(solution)                   # the answer key
    html = handout(solution, worksheet=True)   # the student's version

The handout reads, in order: the problem statement and its data; the space diagram; the
velocity construction narrated step by step (the tutorial's sentence, the stage figure and the
formula with its numbers); the same for the acceleration diagram, with the centripetal,
tangential and Coriolis components explained where they first occur; the results with units
and senses; and the comparison with the tutorial's printed answers, with the slips the
reference found in plain words.

The worksheet is the same document without a single result: the narration keeps its
sentences and symbolic formulas, the polygon figures are replaced by empty drawing areas at
the scale the key is drawn to (true size when printed), and the answers become blanks to fill
in, with the ``polygons check`` command that grades them.

Every figure is inline SVG from :mod:`diagrams` (``diagrams.drawings`` / ``diagrams.svg``);
the document loads nothing from the network and runs no script.
"""
from __future__ import annotations

import math
import re

from polygons.evaluate import Solution
from polygons.narrate import worked
from polygons.plan import Step
from polygons.report import check_answers, sense

from .figures import Figures, cell_stage, cells, figures, stage_of, stage_width
from .html import esc, grid_svg, inline_svg, num, plain_text, svg_size, sym, unit
# the problem section (PAIRED_DATA, _data_rows: read by the tests from here)
from .handout_problem import PAIRED_DATA, _data_rows  # noqa: F401
from .handout_problem import _paragraphs, problem as _problem, redact_answers
from .handout_style import CSS, EXPLAIN, SUBSUP_CSS  # noqa: F401 (SUBSUP_CSS: public)
from .notation import join_vectors, link_names, name_bare_omegas, slot_names

DRAWABLE = ("vector", "image", "line", "intersection")
#: printable area (mm) of an A4 page with the margins of the stylesheet below (every page
#: portrait: one orientation throughout)
PORTRAIT = (180.0, 262.0)
#: empty drawing areas of the worksheet (mm, inside their 4 mm side margins and above their
#: 14 mm scale bar): A5 when the key's drawing fits it, else as large as a page allows
AREAS = {"A5": (150.0, 100.0), "portrait": (172.0, 222.0)}

#: a stage figure printed this narrow (mm) or narrower sits beside its steps' text
NARROW_STAGE = 30.0

UNIT_OF = {"velocity": "m/s", "acceleration": "m/s²"}
WHAT = {"velocity": "velocity", "acceleration": "acceleration"}


def quantity_words(expr: str) -> str:
    """'v(C,B)' → 'velocity of C relative to B' (for the worksheet's blanks)."""
    fn, _, rest = expr.replace(" ", "").partition("(")
    args = [a for a in rest.rstrip(")").split(",") if a]
    a0 = args[0] if args else ""
    rel = f" relative to {args[1]}" if len(args) > 1 else ""
    return {
        "v": f"velocity of {a0}{rel}",
        "a": f"acceleration of {a0}{rel}",
        "an": f"centripetal acceleration of {a0}{rel}",
        "at": f"tangential acceleration of {a0}{rel}",
        "omega": f"angular velocity of {a0} and its sense",
        "alpha": f"angular acceleration of {a0} and its sense",
        "cor": f"Coriolis acceleration of {a0}",
        "vs": f"sliding velocity of {a0}",
        "as": f"sliding acceleration of {a0}",
    }.get(fn, "")


def textbook_name(expr: str) -> str:
    """'v(C,B)' → 'v_CB', the name ``polygons check --measured`` takes."""
    fn, _, rest = expr.replace(" ", "").partition("(")
    args = [a for a in rest.rstrip(")").split(",") if a]
    return f"{fn}_{''.join(args)}"


def formula_with_numbers(step: Step, scene) -> str:
    """The step's worked line (symbol = theorem = numbers), as one line of text (not escaped):
    made by :func:`polygons.narrate.worked` from the step's terms (powers of ten printed)."""
    return plain_text(worked(step, scene, printed=True))


# ---------------------------------------------------------------- the document
class _Doc:
    def __init__(self):
        self.parts: list[str] = []
        self.explained: set[str] = set()
        self.section = 0

    def sec(self) -> int:
        self.section += 1
        return self.section

    def add(self, *html: str):
        self.parts.extend(html)

    def text(self) -> str:
        return "".join(self.parts)


def handout(sol: Solution, *, worksheet: bool = False, figs: Figures | None = None,
            source_name: str | None = None, centres: bool = False) -> str:
    """The handout (answer key) or, with ``worksheet``, the student's version, as HTML;
    ``centres`` adds the check by the instantaneous centres to the key."""
    scene = sol.scene
    figs = figures(sol) if figs is None else figs
    src = scene.source
    sid = src.get("id", "")
    file = source_name or scene.file
    doc = _Doc()
    kind = "Worksheet" if worksheet else "Handout"
    title = f"{sid}: {scene.title}" if sid else scene.title
    doc.add("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n",
            "<meta name=\"generator\" content=\"polygons\">\n",
            f"<meta name=\"polygons-kind\" content=\"{kind.lower()}\">\n",
            f"<title>{esc(kind)} — {esc(title)}</title>\n<style>{CSS}</style>\n</head>\n",
            f"<body class=\"{kind.lower()}\">\n")
    _header(doc, sol, worksheet, kind)
    _problem(doc, sol, worksheet)
    _space(doc, sol, figs, worksheet)
    drawn = [d for d in scene.solve if d in sol.vertices]
    # a worksheet whose last drawing area takes a whole page has its answer table before
    # it, under that diagram's steps: after it, the table alone would make a last page
    early = bool(worksheet and drawn and _area_size(figs, drawn[-1]) == "portrait")
    for diagram in drawn:
        _construction(doc, sol, figs, diagram, worksheet,
                      (lambda: _blanks(doc, sol, file)) if early and diagram == drawn[-1]
                      else None)
    if worksheet:
        if not early:
            _blanks(doc, sol, file)
    else:
        _results(doc, sol)
        if centres:
            _centres(doc, sol)
        _comparison(doc, sol)
        _about(doc, sol)
    _footer(doc, sol, worksheet, file)
    doc.add("</body>\n</html>\n")
    return doc.text()


def _header(doc: _Doc, sol: Solution, worksheet: bool, kind: str) -> None:
    scene, src = sol.scene, sol.scene.source
    doc.add("<header>\n")
    badges = [f'<span class="badge">{esc(kind.upper())}</span>']
    if src.get("id"):
        badges.append(f'<span class="badge">{esc(src["id"])}</span>')
    if src.get("synthetic"):
        badges.append('<span class="badge">SYNTHETIC GEOMETRY</span>')
    doc.add(f"<div>{''.join(badges)}</div>\n", f"<h1>{esc(scene.title)}</h1>\n")
    bits = [src.get("example"), src.get("mechanism")]
    line = " · ".join(esc(b) for b in bits if b)
    if line:
        doc.add(f'<p class="sub">{line}</p>\n')
    if src.get("synthetic"):
        doc.add('<p class="note"><strong>Note.</strong> The tutorial\'s figure for this example '
                'is missing; the geometry below is a stand-in that the reference proposes, so '
                'the numbers are those of the stand-in.</p>\n')
    if worksheet:
        doc.add('<p class="note">Draw each diagram in the empty area provided, at the scale '
                'stated under it (print at 100 %: the grid squares are 5 mm). Measure your '
                'answers off your drawings and write them in the table at the end.</p>\n')
    doc.add("</header>\n")


def _plate(doc: _Doc, figs: Figures, name: str, heading: str, label: str,
           intro: str = "", ident: str | None = None, level: str = "h3") -> None:
    """A finished diagram printed at its stated scale (full size: a key laid over a student's
    drawing matches it), below its heading and ``intro`` HTML; :func:`figures` has chosen a
    scale at which it fits the portrait page (stated here when it is not the first choice).
    Only a drawing that no round scale makes fit is reduced, and then says so."""
    d = figs.drawing.get(name)
    if d is None or name not in figs.svg:
        return
    from .figures import plate
    from .svg import to_svg
    svg = to_svg(plate(d))       # the page's heading names it
    w, h = svg_size(svg)
    if w <= PORTRAIT[0] + 0.05 and h <= PORTRAIT[1] + 0.05:
        width, reduced = w, None
    else:
        k = min(PORTRAIT[0] / w, PORTRAIT[1] / h)
        width, reduced = w * k, k
    head = f"<{level}>{esc(heading) if level == 'h2' else sym(heading)}</{level}>\n"
    # the drawing (with its heading unless that opens a section) floats: when it does not
    # fit what is left of the page, it goes to the next page and the text after it fills
    # this one, instead of leaving the rest of the page empty
    doc.add(f'<section class="plate portrait" id="{esc(ident or "plate-" + name)}">\n'
            + (head + intro if level == "h2" else intro)
            + '<div class="sheet">' + ("" if level == "h2" else head))
    doc.add(f'<figure class="diagram full">{inline_svg(svg, name, "figure", width, label)}'
            f"</figure>\n")
    scale_txt = figs.drawing[name].scale_statement if name in figs.drawing else ""
    if reduced is None:
        msg = (f"Full size ({scale_txt}): printed at 100 %, it can be laid over a drawing "
               f"made at that scale."
               if scale_txt else "Full size.")
        if name in figs.rescaled:
            msg += (f" (Drawn at {scale_txt} rather than {figs.rescaled[name][0]} so that it "
                    f"fits an A4 page at its scale.)")
    else:
        msg = (f"Reduced to {math.floor(reduced * 100)} % to fit the page: measure with its "
               f"scale bar, not with the stated scale.")
    doc.add(f'<p class="figure-note">{esc(msg)}</p>\n</div>\n</section>\n')


def _space(doc: _Doc, sol: Solution, figs: Figures, worksheet: bool) -> None:
    d = figs.drawing.get("space")
    sc = d.scale_statement if d is not None else ""
    intro = ("<p>The mechanism frozen at the instant asked about, drawn to scale"
             + (f" ({esc(sc)})" if sc else "") + ". Every direction in the velocity and "
             "acceleration diagrams is taken from it: a relative velocity is at right angles "
             "to the link, a centripetal acceleration parallel to it.</p>\n")
    if worksheet:
        intro = intro.replace("</p>\n", " If the tutorial asks you to, draw it yourself "
                              "first from the data and check it against this one.</p>\n")
    _plate(doc, figs, "space", f"{doc.sec()}. The space diagram", "Space diagram of the "
           "mechanism", intro, ident="space", level="h2")


def _explain(doc: _Doc, key: str) -> None:
    if key in doc.explained or key not in EXPLAIN:
        return
    doc.explained.add(key)
    head, body = EXPLAIN[key]
    doc.add(f'<aside class="explain" data-explains="{esc(key)}"><h4>{esc(head)}</h4>'
            f"<p>{esc(body)}</p></aside>\n")


def _explains_for(step: Step) -> list[str]:
    keys = []
    if step.op == "crank_velocity" or step.op == "line_perp" and step.diagram == "velocity":
        keys.append("relative_velocity")
    if step.op == "line_guide":
        keys.append("slider_line")
    if step.op == "line_along":
        keys.append("sliding")
    if step.theorem in ("centripetal", "tangential", "coriolis", "image"):
        keys.append(step.theorem)
    if step.op == "crank_tangential":
        keys.append("tangential")
    return keys


def _construction(doc: _Doc, sol: Solution, figs: Figures, diagram: str,
                  worksheet: bool, before_area=None) -> None:
    scene = sol.scene
    n_sec = doc.sec()
    what = WHAT[diagram]
    final = figs.drawing.get(diagram)
    lay = final.meta.get("layout") if final is not None else None
    scale = lay.scale if lay is not None else None
    doc.add(f'<section id="{diagram}" class="construction">\n'
            f"<h2>{n_sec}. The {what} diagram</h2>\n")
    pole_alias = " = ".join([sol.pole] + [g.lower() for g in scene.ground
                                          if g.lower() != sol.pole])
    P, Q = _example_pair(sol)
    intro = (f"Lower-case letters are the points of the {what} diagram: the vector from "
             f"<em>{sym(sol.vertex_of(P))}</em> to <em>{sym(sol.vertex_of(Q))}</em> is the "
             f"{what} of {sym(Q)} relative to {sym(P)}. The pole "
             f"<em>{sym(pole_alias)}</em> stands for every fixed point, which has no "
             f"{what}. Every component has one colour and line style (the key on each "
             f"drawing), readable in greyscale too.")
    if scale is not None:
        intro += f" Scale <strong>{esc(scale.statement)}</strong>."
    doc.add(f"<p>{intro}</p>\n")
    if not worksheet:
        doc.add(f'<p class="figure-note">The figures below show the drawing so far, the '
                f"new steps drawn heavier and the earlier ones lighter (construction lines "
                f"with the point where they meet), reduced, with the scale bar they are drawn "
                f"to: measure on the finished {what} diagram that follows them, printed full "
                f"size.</p>\n")
    links = link_names(scene)
    vertices = sorted(sol.printed_names(diagram))

    def words(text: str) -> str:
        """The drawings' notation: ω_AB for a bare ω of link AB, b₁b for a vector name."""
        return join_vectors(name_bare_omegas(slot_names(text, scene), links), vertices)

    doc.add(f'<ol class="steps{"" if worksheet else " staged"}" id="{diagram}-steps">\n')
    if worksheet:
        for step in sol.steps:
            if step.diagram != diagram:
                continue
            for key in _explains_for(step):
                _explain(doc, key)
            doc.add(f'<li class="step" id="{diagram}-step-{step.number}" '
                    f'data-step="{step.number}">\n<p class="say"><span class="num">'
                    f"{step.number}.</span>{sym(words(step.reason))}</p>\n")
            if step.kind != "intersection":
                doc.add(f'<p class="formula symbolic">{sym(words(step.formula))}</p>\n')
            doc.add("</li>\n")
    else:
        for cell in cells(sol, diagram):
            for step in cell:
                for key in _explains_for(step):
                    _explain(doc, key)
            k = cell_stage(sol, cell)
            name = f"{diagram}-{k}" if k is not None else None
            nums = [s.number for s in cell]
            last = k is not None and k == stage_of(sol, [s for s in sol.steps
                                                       if s.diagram == diagram
                                                       and s.kind in DRAWABLE][-1])
            fig, narrow = "", False
            if last:
                fig = (f'<p class="figure-note">This completes the {what} diagram: the '
                       f"finished diagram is printed full size.</p>\n")
            elif name and name in figs.svg:
                svg = figs.svg[name]
                w, h = svg_size(svg)
                width = stage_width(w, h)
                narrow = width <= NARROW_STAGE
                drawn = [s.number for s in cell if s.kind in DRAWABLE]
                steps = (f"step {drawn[0]}" if len(drawn) == 1 else
                         f"steps {', '.join(map(str, drawn[:-1]))} and {drawn[-1]}")
                part = figs.drawing[name].meta.get("detail") if name in figs.drawing \
                    else None
                # a detail (a crowded polygon's stage cropped to its own vectors) says so
                # and states its own scale
                about = (f": a detail at {sym(part)}" if part else "")
                fig = (f'<figure class="diagram stage{" narrow" if narrow else ""}">'
                       f"{inline_svg(svg, name, 'figure', width, f'{what} diagram, {steps}')}"
                       f"<figcaption>The {what} diagram after {steps}{about}"
                       f"</figcaption></figure>\n")
            doc.add(f'<li class="step" id="{diagram}-step-{nums[0]}" data-step="'
                    f'{" ".join(map(str, nums))}">\n')
            if narrow:           # beside the text, which it would otherwise follow
                doc.add(fig)
            for step in cell:
                anchor = (f' id="{diagram}-step-{step.number}"' if step.number != nums[0]
                          else "")
                doc.add(f'<p class="say"{anchor}><span class="num">{step.number}.</span>'
                        f"{sym(words(step.reason))}</p>\n")
                f = formula_with_numbers(step, sol.scene)
                if f:
                    doc.add(f'<p class="formula answer">{_meet_kept(sym(words(f)))}</p>\n')
            if not narrow:
                doc.add(fig)
            doc.add("</li>\n")
    doc.add("</ol>\n")
    if sol.min_intersection_angle_deg is not None and not worksheet:
        angles = [s.angle_deg for s in sol.steps if s.diagram == diagram and s.angle_deg]
        if angles:
            doc.add(f'<p class="note">The construction lines of this diagram cross at '
                    f"{num(min(angles), 3)}° or more"
                    + (" — a clean intersection." if min(angles) >= 20 else
                       " — a shallow crossing: draw carefully, small errors in direction move "
                       "the point a long way.") + "</p>\n")
    doc.add("</section>\n")
    if worksheet:
        if before_area is not None:
            before_area()
        _area(doc, sol, figs, diagram)
    else:
        title = figs.drawing[diagram].title if diagram in figs.drawing else what
        _plate(doc, figs, diagram, f"The finished {title[:1].lower()}{title[1:]}",
               f"Finished {what} diagram")


def _example_pair(sol: Solution) -> tuple[str, str]:
    """Two labels of one link, both moving if possible (B, C of BC), for the intro."""
    from polygons.evaluate import link_ends
    ground = set(sol.scene.ground)
    pairs = [link_ends(sol.scene, n) for n in sol.links]
    for a, b in pairs:
        if a not in ground and b not in ground:
            return a, b
    return pairs[0] if pairs else ("A", "B")


def _area_size(figs: Figures, diagram: str) -> str | None:
    """The drawing area a worksheet gives ``diagram``: 'A5' when the key's drawing (its
    frame) fits one, else a whole 'portrait' page (None: no finished drawing)."""
    final = figs.drawing.get(diagram)
    lay = final.meta.get("layout") if final is not None else None
    if lay is None:
        return None
    fw, fh = lay.frame.x1 - lay.frame.x0, lay.frame.y1 - lay.frame.y0
    aw, ah = AREAS["A5"]
    return "A5" if fw <= aw and fh <= ah else "portrait"


def _area(doc: _Doc, sol: Solution, figs: Figures, diagram: str) -> None:
    """The worksheet's empty drawing area for ``diagram``: true size, at the key's scale.

    The area is A5 when the key's drawing (its frame: the polygon and its construction lines)
    fits, else a whole landscape or portrait page; its size depends on the page, not on the
    answer.  If the key's drawing is larger than any A4 page, the next round scale that fits
    is used and the note says so.  A ring marks where the key's pole falls with its drawing
    centred in the area, so the student's diagram stays on the paper.
    """
    from .scale import make, round_up
    final = figs.drawing.get(diagram)
    lay = final.meta.get("layout") if final is not None else None
    if lay is None:
        return
    scale = lay.scale
    frame = lay.frame
    fw, fh = frame.x1 - frame.x0, frame.y1 - frame.y0
    k = 1.0
    name = _area_size(figs, diagram)
    aw, ah = AREAS[name]
    if not (fw <= aw and fh <= ah):
        name = "portrait"
        aw, ah = AREAS[name]
        scale = make(scale.quantity, round_up(scale.per_cm * max(fw / aw, fh / ah)))
        k = lay.scale.per_cm / scale.per_cm
    px, py = lay.P(lay.con.vertices[sol.pole])
    cx, cy = (frame.x0 + frame.x1) / 2, (frame.y0 + frame.y1) / 2
    pole = (aw / 2 + k * (px - cx), ah / 2 - k * (py - cy))
    what = WHAT[diagram]
    svg = grid_svg(aw, ah, scale.statement, scale.per_cm_display, plain_text(scale.unit),
                   f"area-{diagram}", f"Empty drawing area for the {what} diagram, "
                   f"scale {scale.statement}", pole, f"pole {sol.pole}: start here")
    cls = "plate portrait"
    note = (f"True size at 100 % print scale: {scale.statement}; grid squares 5 mm. The ring "
            f"marks a pole position that leaves room for the whole diagram.")
    if k != 1.0:
        note += (f" (The answer key is drawn at {lay.scale.statement}, which needs a sheet "
                 f"larger than A4.)")
    elif diagram in figs.rescaled:
        note += (f" ({scale.statement} rather than {figs.rescaled[diagram][0]}, at which the "
                 f"diagram would not fit an A4 page.)")
    doc.add(f'<section class="{cls}" id="plate-area-{diagram}">\n'
            f"<h3>Draw the {what} diagram here</h3>\n"
            f'<figure class="area">{svg}</figure>\n'
            f'<p class="figure-note">{esc(note)}</p>\n</section>\n')


def _and(words: list[str]) -> str:
    """'O', 'O and Q', 'O, Q and D'."""
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def _results(doc: _Doc, sol: Solution) -> None:
    scene = sol.scene
    doc.add(f'<section id="results">\n<h2>{doc.sec()}. Results</h2>\n')
    # the fixed points in words, not as rows of zeros (their positions are in the data)
    fixed = [lab for lab in sol.points if lab in scene.ground]
    still = (f" {_and(fixed)} {'is' if len(fixed) == 1 else 'are'} fixed: no velocity, no "
             f"acceleration." if fixed else "")
    doc.add('<p class="note">Read off the constructions above (exact to the precision of the '
            "arithmetic; a drawing gives them to about 1–2 %). Directions are angles CCW from "
            f"+x; senses of rotation CW/CCW.{esc(still)}</p>\n")
    doc.add('<table class="answer" id="results-points">\n<thead><tr><th>point</th>'
            '<th class="n">x mm</th><th class="n">y mm</th><th class="n">velocity m/s</th>'
            '<th class="n">direction</th><th class="n">acceleration m/s²</th>'
            '<th class="n">direction</th></tr></thead>\n<tbody>\n')
    for lab, pr in sol.points.items():
        if lab in fixed:
            continue
        cells = [f"<td>{esc(lab)}</td>", f'<td class="n">{num(pr.position[0] * 1000)}</td>',
                 f'<td class="n">{num(pr.position[1] * 1000)}</td>']
        for vec in (pr.velocity, pr.acceleration):
            if vec is None:
                cells += ['<td class="n"></td>', '<td class="n"></td>']
                continue
            m = math.hypot(*vec)
            d = math.degrees(math.atan2(vec[1], vec[0])) % 360.0 if m else None
            cells += [f'<td class="n">{num(m)}</td>',
                      f'<td class="n">{(num(d, 4) + "°") if d is not None else "–"}</td>']
        doc.add("<tr>" + "".join(cells) + "</tr>\n")
    doc.add("</tbody>\n</table>\n")
    doc.add('<table class="answer" id="results-links">\n<thead><tr><th>link</th>'
            '<th class="n">length mm</th><th class="n">ω rad/s</th><th>sense</th>'
            '<th class="n">α rad/s²</th><th>sense</th></tr></thead>\n<tbody>\n')
    for name, lr in sol.links.items():
        w = lr.omega
        a = lr.alpha
        doc.add(f"<tr><td>{esc(name)}</td><td class=\"n\">{num(lr.length * 1000)}</td>"
                f"<td class=\"n\">{num(abs(w)) if w is not None else ''}</td>"
                f"<td>{sense(w) if w is not None else ''}</td>"
                f"<td class=\"n\">{num(abs(a)) if a is not None else ''}</td>"
                f"<td>{sense(a) if a is not None else ''}</td></tr>\n")
    doc.add("</tbody>\n</table>\n")
    if sol.slides:
        doc.add('<table class="answer" id="results-slides">\n<thead><tr><th>sliding</th>'
                '<th>along</th><th class="n">velocity m/s</th>'
                '<th class="n">acceleration m/s²</th><th class="n">Coriolis 2ωv m/s²</th>'
                "</tr></thead>\n<tbody>\n")
        for lab, sr in sol.slides.items():
            along = "its guide" if sr.along == "guide" else f"the slot of {sr.along}"
            d = num(math.degrees(math.atan2(sr.direction[1], sr.direction[0])) % 360.0)
            cor = num(math.hypot(*sr.coriolis)) if sr.coriolis is not None else "–"
            doc.add(f"<tr><td>{esc(lab)}</td><td>{esc(along)} (+ towards {d}°)</td>"
                    f"<td class=\"n\">{num(sr.velocity)}</td>"
                    f"<td class=\"n\">{num(sr.acceleration)}</td>"
                    f"<td class=\"n\">{cor}</td></tr>\n")
        doc.add("</tbody>\n</table>\n")
    for w in sol.warnings:
        doc.add(f'<p class="note"><strong>Warning:</strong> {esc(w)}</p>\n')
    doc.add("</section>\n")


def _centres(doc: _Doc, sol: Solution) -> None:
    """The same velocities by the instantaneous centres (Kennedy's theorem), as a check."""
    from polygons.centres import instant_centres
    from polygons.errors import PolygonsError
    from .centres import centres_figure
    try:
        cs, svg = instant_centres(sol), centres_figure(sol)
    except PolygonsError as exc:
        doc.add(f'<section id="centres">\n<h2>{doc.sec()}. Instantaneous centres</h2>\n'
                f"<p>Not drawn for this mechanism: {esc(exc.reason)}.</p>\n</section>\n")
        return
    w, h = svg_size(svg)
    vel = "; ".join(sym(pv.how) for lab, pv in cs.velocities.items()
                    if lab not in sol.scene.ground)
    doc.add(f'<section id="centres">\n<h2>{doc.sec()}. Instantaneous '
            f"centres</h2>\n<p>The same velocities found another way: {esc(cs.note)}; then v "
            f"= ω × the radius from the link's centre relative to the frame (Kennedy: any "
            f"three links' centres lie on one line). They agree with the polygon.</p>\n"
            f"<figure class=\"diagram centres\">"
            f"{inline_svg(svg, 'centres', 'figure', min(w, 0.7 * PORTRAIT[0]), 'Instant centres')}"
            f"</figure>\n<p>Velocities by the centres: {vel}.</p>\n</section>\n")


def _comparison(doc: _Doc, sol: Solution) -> None:
    src = sol.scene.source
    checks = [c for c in check_answers(sol) if c.answer.tutorial is not None]
    doc.add(f'<section id="comparison">\n<h2>{doc.sec()}. Comparison with the tutorial\'s '
            f"answers</h2>\n")
    if not checks:
        doc.add("<p>The tutorial prints no numerical answer for this example.</p>\n")
    else:
        doc.add('<p class="note">Difference = (tutorial − polygons) / polygons. A drawing '
                "is expected to agree within the stated drawing tolerance.</p>\n")
        doc.add('<table class="answer wide" id="comparison-table">\n<thead><tr><th>quantity</th>'
                '<th>unit</th><th class="n">polygons</th><th class="n">tutorial</th>'
                '<th class="n">difference</th><th>verdict</th></tr></thead>\n<tbody>\n')
        for c in checks:
            a = c.answer
            ours = num(c.compared, 5)
            if a.sense and a.mode == "abs":
                ours_sense = sense(c.ours) if a.q.fn in ("omega", "alpha") else ""
                ours += f" {ours_sense}" if ours_sense else ""
            tut = f"{a.tutorial:g}" + (f" {esc(a.sense)}" if a.sense else "")
            if c.diff_pct is None:
                diff = "–"
            elif abs(c.diff_pct) < 0.005:
                diff = "0.00 %"
            else:
                diff = f"{c.diff_pct:+.2f} %".replace("-", "−")
            if a.slip:
                note = re.sub(r"(?i)^\s*slip\s*[:,-]\s*", "", a.note or "")
                verdict = "<strong>slip in the tutorial</strong>" + (
                    f": {sym(note)}" if note else "")
            elif c.within:
                verdict = f"within ±{a.tolerance * 100:g} %"
                if a.note:
                    verdict += f" ({sym(a.note)})"
            else:
                verdict = f"<strong>outside ±{a.tolerance * 100:g} %</strong>" + (
                    f": {sym(a.note)}" if a.note else "")
            doc.add(f"<tr><td class=\"q\">{sym(a.desc)}</td><td>{unit(a.unit)}</td>"
                    f'<td class="n">{ours}</td><td class="n">{tut}</td>'
                    f'<td class="n">{diff}</td><td>{verdict}</td></tr>\n')
        doc.add("</tbody>\n</table>\n")
    slips = src.get("slips", "")
    if slips:
        doc.add("<h3>Slips in the printed working</h3>\n<div class=\"slip\">\n")
        for para in _paragraphs(slips):
            doc.add(f"<p>{esc(plain_text(para))}</p>\n")
        doc.add("</div>\n<p class=\"note\">polygons does not reproduce these slips: its "
                "numbers come from the construction with the data as stated.</p>\n")
    doc.add("</section>\n")


def _about(doc: _Doc, sol: Solution) -> None:
    src = sol.scene.source
    parts = [("Where this example comes from", " · ".join(
        str(x) for x in (src.get("example"), src.get("category")) if x)),
        ("Conventions", src.get("conventions", "")),
        ("What was reconstructed", src.get("backsolved", "")),
        ("Notes", src.get("notes", ""))]
    parts = [(h, t.strip()) for h, t in parts if t and t.strip()]
    if not parts:
        return
    doc.add(f'<section id="about" class="about">\n<h2>{doc.sec()}. About this case</h2>\n')
    for head, text in parts:
        doc.add(f"<h3>{esc(head)}</h3>\n")
        for para in _paragraphs(text):
            doc.add(f"<p>{esc(plain_text(para))}</p>\n")
    doc.add("</section>\n")


def worksheet_questions(sol: Solution) -> list[str]:
    """The quantities the tutorial asks for (those with a printed answer), gradeable by
    ``polygons check``, in order, without repeats."""
    seen: list[str] = []
    for a in sol.scene.answers:
        if a.tutorial is None or a.quantity in seen:
            continue
        fn = a.q.fn
        if fn in ("v", "a", "an", "at", "omega", "alpha", "cor", "vs", "as"):
            seen.append(a.quantity)
    return seen


def _blanks(doc: _Doc, sol: Solution, file: str) -> None:
    qs = worksheet_questions(sol)
    doc.add(f'<section id="your-answers">\n<h2>{doc.sec()}. Your answers</h2>\n')
    if not qs:
        doc.add("<p>Write down the velocities and accelerations your diagrams give.</p>\n")
    else:
        doc.add("<p>Measure these off your diagrams (with their senses of rotation where "
                "asked):</p>\n<table id=\"blanks\">\n<thead><tr><th>name</th><th>what</th>"
                "<th>unit</th><th>your value</th></tr></thead>\n<tbody>\n")
        for q in qs:
            dim = q.split("(")[0]
            u = {"v": "m/s", "vs": "m/s", "omega": "rad/s", "alpha": "rad/s²"}.get(dim, "m/s²")
            doc.add(f"<tr><td><code>{esc(textbook_name(q))}</code></td>"
                    f"<td>{esc(quantity_words(q))}</td><td>{esc(u)}</td>"
                    f'<td class="blank"></td></tr>\n')
        doc.add("</tbody>\n</table>\n")
        example = " ".join(f"{textbook_name(q)}=…" for q in qs[:3])
        doc.add(f'<p class="note screen-only">Check your values: <code>polygons check {esc(file)} '
                f"--measured {esc(example)}</code> (numbers in the units above, or write the "
                f"unit: <code>{esc(textbook_name(qs[0]))}='…'</code> with e.g. "
                f"<code>mm/s</code>; add CW or CCW after an ω or α).</p>\n")
    doc.add("</section>\n")


def _footer(doc: _Doc, sol: Solution, worksheet: bool, file: str) -> None:
    try:
        from importlib.metadata import version
        v = version("polygons")
    except Exception:   # pragma: no cover - not installed
        v = ""
    cmd = f"polygons handout {file}" + (" --worksheet" if worksheet else "")
    tag = '<footer class="screen-only">' if worksheet else "<footer>"
    doc.add(f"{tag}Generated by polygons {esc(v)} from <code>{esc(file)}</code> "
            f"(regenerate: <code>{esc(cmd)} -o FILE.html</code>)."
            + ("" if worksheet else " The answer key's worksheet: add --worksheet.")
            + "</footer>\n")


__all__ = ["handout", "figures", "Figures", "redact_answers", "worksheet_questions",
           "textbook_name", "formula_with_numbers", "stage_of"]


_MEET = re.compile(r" \((lines meet at [^()]*?°)\)$")


def _meet_kept(html: str) -> str:
    """A worked line's closing '(lines meet at 90°)' kept in one piece and on the line of
    the value it qualifies (a no-break space before it, the words set unbroken): never a
    line of its own, opening a column (issue 33)."""
    return _MEET.sub(lambda m: f'\u00a0<span class="meet">({m.group(1)})</span>', html)
