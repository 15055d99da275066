"""The SVG writer: the only module that imports svgwrite.

Turns a :class:`~diagrams.model.Drawing` (mm, y up) into SVG bytes: the page is sized in mm
with a viewBox in mm, so the file prints to scale (1 cm on paper is 1 cm of the drawing).
Output is deterministic (no generated ids, coordinates rounded to 0.001 mm, attributes in a
fixed order).  svgwrite validates every element and attribute against SVG 1.1 full when
:data:`VALIDATE` is set (the tests set it); drawings are written without it, as the
validation was ~80 % of the time of a large drawing (the output is the same).

Each vector's component kind has one look (:data:`diagrams.components.LOOKS`): a colour and a
width/dash pattern, so the meaning survives greyscale printing — styles named ``c-<kind>``
(``c-<kind>-new`` for the stage that draws it, heavier; earlier stages keep their colour at
40 % opacity).  The Coriolis vector is heavy with an open (hollow) head; construction lines of
unknown length are thin and dashed.  The mechanism's own styles (links, pivots, guides, the
input arcs) are in :data:`STYLES` below.  Text is typeset by :mod:`diagrams.notation`
(``tspan`` sub- and superscripts).
"""
from __future__ import annotations

import svgwrite

from .components import LOOKS, new_width
from .model import Arrow, Circle, Drawing, Group, Polyline, Segment, Text
from .notation import mark_labels, plain, svg_runs
from .text import FONT_FAMILY

#: validate every element and attribute (svgwrite's debug mode); tests/test_diagrams.py sets it
VALIDATE = False

INK = "#000000"
FADED = "#8c8c8c"
#: earlier stages keep their component colours, lighter
FADED_OPACITY = 0.4

#: style name -> stroke width, dash array, extra attributes
STYLES = {
    "vector": (0.45, None),
    "vector-new": (0.75, None),
    "result": (0.45, "0.5 0.9"),
    "result-new": (0.7, "0.6 1.0"),
    "coriolis": (0.9, None),
    "coriolis-new": (1.1, None),
    "construction": (0.25, "3 1.5"),
    "construction-new": (0.45, "3 1.5"),
    "offset": (0.25, "0.4 0.8"),
    "leader": (0.15, None),
    "inset": (0.2, None),
    "image-side": (0.25, "4 1 0.8 1"),
    "scalebar": (0.3, None),
    "link": (0.8, None),
    "link-thin": (0.35, None),
    "equivalent": (0.7, "2.4 1.2"),
    "slot": (0.3, None),
    "hatch": (0.2, None),
    "ground": (0.35, None),
    "centre": (0.2, "5 1 1 1"),
    "guide-path": (0.2, "5 1 1 1"),
    "input": (0.35, None),
    "input-alpha": (0.35, "1.2 0.8"),
    "frame": (0.2, None),
    "pole": (0.35, None),
    "vertex": (0.2, None),
    "pin": (0.35, None),
    "block": (0.45, None),
    "plate": (0.35, None),
}
#: fills for closed shapes (None: no fill)
FILLS = {"pole": "#ffffff", "vertex": "ink", "pin": "#ffffff", "block": "#ffffff",
         "plate": "#e6e6e6", "ground": "#ffffff"}


def _n(v: float) -> float:
    r = round(float(v), 3)
    return 0.0 if r == 0 else r


def _stroke_attrs(style: str, faded: bool) -> dict:
    if style.startswith("c-"):          # a component's look (diagrams.components)
        kind = style[2:].removesuffix("-new")
        look = LOOKS[kind]
        w = new_width(look) if style.endswith("-new") else look.width
        attrs = {"stroke": look.colour, "stroke_width": w, "stroke_linecap": "butt",
                 "stroke_linejoin": "round", "fill": "none"}
        if look.dash:
            attrs["stroke_dasharray"] = look.dash
        if faded:
            attrs["stroke_opacity"] = FADED_OPACITY
        return attrs
    w, dash = STYLES[style]
    ink = FADED if faded else INK
    attrs = {"stroke": ink, "stroke_width": w, "stroke_linecap": "butt",
             "stroke_linejoin": "round"}
    if dash:
        attrs["stroke_dasharray"] = dash
    fill = FILLS.get(style)
    attrs["fill"] = "none" if fill is None else (ink if fill == "ink" else fill)
    return attrs


class _Writer:
    def __init__(self, d: Drawing):
        self.d = d
        #: the scene's labels, typeset where the text names them (O2 → O₂; notation)
        self.labels = d.meta.get("labels", ())
        self.H = d.height
        self.dwg = svgwrite.Drawing(size=(f"{d.width}mm", f"{d.height}mm"),
                                    viewBox=f"0 0 {d.width} {d.height}", profile="full",
                                    debug=VALIDATE)

    def p(self, pt):
        return (_n(pt[0]), _n(self.H - pt[1]))

    def item(self, it):
        dwg = self.dwg
        if isinstance(it, Group):
            g = dwg.g(id=it.ident, class_=it.cls)
            if it.title:
                g.set_desc(title=plain(it.title))
            for sub in it.items:
                g.add(self.item(sub))
            return g
        if isinstance(it, Segment):
            kw = _stroke_attrs(it.style, it.faded)
            kw.pop("fill")
            if it.cls:
                kw["class_"] = it.cls
            return dwg.line(self.p(it.a), self.p(it.b), **kw)
        if isinstance(it, Polyline):
            kw = _stroke_attrs(it.style, it.faded)
            if it.cls:
                kw["class_"] = it.cls
            if "filled" in it.cls.split():     # an arrowhead drawn as a polygon (insets)
                kw["fill"] = kw["stroke"]
                kw.pop("stroke_dasharray", None)
                if "stroke_opacity" in kw:
                    kw["fill_opacity"] = kw["stroke_opacity"]
            elif "open" in it.cls.split():
                kw["fill"] = "#ffffff"
                kw.pop("stroke_dasharray", None)
            pts = [self.p(q) for q in it.points]
            return dwg.polygon(pts, **kw) if it.closed else dwg.polyline(pts, **kw)
        if isinstance(it, Circle):
            kw = _stroke_attrs(it.style, it.faded)
            if it.cls:
                kw["class_"] = it.cls
            if it.ident:
                kw["id"] = it.ident
            return dwg.circle(self.p(it.centre), _n(it.r), **kw)
        if isinstance(it, Arrow):
            if it.shift != (0.0, 0.0):    # drawn beside a collinear vector (diagrams.crowd)
                g = dwg.g(class_="arrow shifted",
                          transform=f"translate({_n(it.shift[0])},{_n(-it.shift[1])})")
            else:      # the head of an arc (an input ω, a couple): no vector's length
                g = dwg.g(class_="arrow arc-head" if it.role == "arc" else "arrow")
            kw = _stroke_attrs(it.style, it.faded)
            kw.pop("fill")
            g.add(dwg.line(self.p(it.tail), self.p(it.shaft_end), class_="shaft", **kw))
            if it.head:
                if it.style.startswith("c-"):
                    look = LOOKS[it.style[2:].removesuffix("-new")]
                    ink, open_head = look.colour, look.open_head
                else:
                    ink = FADED if it.faded else INK
                    open_head = it.role == "coriolis" or it.style == "input-alpha"
                hk = {}
                if it.faded and it.style.startswith("c-"):
                    hk = {"fill_opacity": FADED_OPACITY, "stroke_opacity": FADED_OPACITY}
                g.add(dwg.polygon([self.p(q) for q in it.head], class_="head",
                                  fill="#ffffff" if open_head else ink, stroke=ink,
                                  stroke_width=0.3 if open_head else 0.1,
                                  stroke_linejoin="miter", **hk))
            return g
        if isinstance(it, Text):
            kw = {"font_size": _n(it.size), "font_family": FONT_FAMILY,
                  "fill": it.ink or (FADED if it.faded else INK)}
            if it.ink and it.faded:
                kw["fill_opacity"] = FADED_OPACITY
            if it.anchor != "start":
                kw["text_anchor"] = it.anchor
            if it.weight != "normal":
                kw["font_weight"] = it.weight
            cls = " ".join(c for c in (it.role, it.cls) if c)
            if cls:
                kw["class_"] = cls
            if it.ident:
                kw["id"] = it.ident
            parts = svg_runs(mark_labels(it.text, self.labels), it.size)
            if len(parts) == 1 and parts[0][3] is None:
                return dwg.text(parts[0][0], insert=(_n(it.x), _n(self.H - it.baseline)), **kw)
            t = dwg.text("", insert=(_n(it.x), _n(self.H - it.baseline)), **kw)
            for s, dx, dy, size in parts:      # textbook sub/superscripts (diagrams.notation)
                tkw = {}
                if dx:
                    tkw["dx"] = [_n(dx)]
                if dy:
                    tkw["dy"] = [_n(dy)]
                if size is not None:
                    tkw["font_size"] = _n(size)
                t.add(dwg.tspan(s, **tkw))
            return t
        raise TypeError(it)  # pragma: no cover

    def write(self) -> bytes:
        d, dwg = self.d, self.dwg
        dwg.set_desc(title=plain(mark_labels(d.title, self.labels)),
                     desc=plain(mark_labels(d.desc, self.labels)))
        dwg.add(dwg.rect((0, 0), (d.width, d.height), id="background", fill="#ffffff"))
        for g in d.groups:
            dwg.add(self.item(g))
        return ('<?xml version="1.0" encoding="utf-8"?>\n' + dwg.tostring() + "\n").encode()


def to_svg(d: Drawing) -> bytes:
    """The SVG document of ``d`` as UTF-8 bytes (deterministic)."""
    return _Writer(d).write()
