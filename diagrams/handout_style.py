"""The handout's stylesheet and the explanations it prints where a kind of step first occurs
(:mod:`diagrams.handout`)."""
from __future__ import annotations

from .notation import HTML_CSS as NOTATION_CSS

EXPLAIN = {
    "relative_velocity": (
        "Relative velocity",
        "Two points of one rigid link keep their distance, so the only way one can move "
        "relative to the other is by turning about it: the relative velocity is ω × length, "
        "at right angles to the line joining them. A fixed point has no velocity, so every "
        "fixed point is the pole."),
    "slider_line": (
        "A slider on a guide",
        "A slider can only move along its guide, so its velocity (and its acceleration) lie "
        "along the guide: the line through the pole parallel to the guide."),
    "sliding": (
        "A pin in a slot",
        "Where a pin slides in the slot of a turning lever, its velocity is the velocity of "
        "the point of the lever under it (at right angles to the lever) plus the sliding "
        "velocity along the slot."),
    "centripetal": (
        "Centripetal acceleration",
        "A point turning about another point of the same link at angular velocity ω, at "
        "radius r, accelerates towards it by ω²r = v²/r, where v is their relative velocity "
        "from the velocity diagram. It is always known once the velocity diagram is drawn, "
        "so it is drawn first: parallel to the link, pointing towards the centre it turns "
        "about."),
    "tangential": (
        "Tangential acceleration",
        "If the link's angular velocity is changing (angular acceleration α), the point "
        "also accelerates by αr at right angles to the link. Its size is not known until "
        "the diagram closes, so only its line is drawn; where two such lines cross fixes "
        "the point, and the length of the tangential vector divided by r gives α."),
    "coriolis": (
        "Coriolis acceleration",
        "When a point slides along a link that is itself turning, its acceleration relative "
        "to the coincident point of the link has, besides the sliding acceleration along "
        "the slot, a component 2ωv at right angles to the slot (ω the link's angular "
        "velocity, v the sliding velocity from the velocity diagram). Its sense is that of "
        "v turned through 90° in the sense of ω. It is known, so it is drawn as a known "
        "vector, and the unknown sliding acceleration lies along the slot from its end."),
    "image": (
        "Velocity and acceleration images",
        "The points of one rigid link make, on the velocity or the acceleration diagram, a "
        "figure similar to the link itself (turned, and scaled by the diagram): once two "
        "points of the link are on the diagram, any third point follows by copying the "
        "shape."),
}


#: a stacked pair ((a_P2)ⁿ_O2): the superscript over the subscript, both right after the
#: parenthesis.  A column flex box whose first item (the superscript, moved first by
#: ``order``) gives the box its baseline, raised to a superscript's height, so the subscript
#: falls below the text's baseline (this overrides the notation's shared rule, which put the
#: superscript at the subscript's height and the subscript below it in Chromium's print).
SUBSUP_CSS = (".subsup{display:inline-flex;flex-direction:column;vertical-align:0.55em;"
              "line-height:1;font-size:0.7em;margin-left:0.05em}"
              ".subsup sub,.subsup sup{display:block;font-size:1em;vertical-align:baseline;"
              "line-height:1}.subsup sup{order:-1}")
CSS = """
@page { size: A4 portrait; margin: 10mm 14mm 10mm 14mm; }
html { background: #ffffff; }
body { font-family: "DejaVu Serif", Georgia, "Times New Roman", serif; font-size: 9.5pt;
       line-height: 1.32; color: #000; margin: 0 auto; max-width: 182mm; padding: 6mm 0; }
h1, h2, h3, .figure-note, table, .formula, .explain h4, .badge, footer, .data dt {
       font-family: "DejaVu Sans", Verdana, Arial, sans-serif; }
h1 { font-size: 17pt; line-height: 1.2; margin: 0 0 2mm 0; }
h2 { font-size: 13pt; margin: 3.5mm 0 1.5mm 0; border-bottom: 0.4mm solid #000;
     break-after: avoid; page-break-after: avoid; }
h3 { font-size: 11pt; margin: 4mm 0 1.5mm 0; break-after: avoid; page-break-after: avoid; }
p { margin: 1mm 0 1.4mm 0; }
.sub { font-size: 9.5pt; color: #333; margin: 0 0 3mm 0; }
.badge { display: inline-block; border: 0.3mm solid #000; padding: 0 1.5mm; font-size: 8.5pt;
         font-weight: bold; margin-right: 1.5mm; }
.statement { border-left: 1mm solid #999; padding: 0.5mm 0 0.5mm 3mm; margin: 2mm 0; }
.statement p { margin: 0.8mm 0; }
table { border-collapse: collapse; font-size: 9pt; margin: 1.5mm 0 2mm 0; }
tr { break-inside: avoid; page-break-inside: avoid; }
th, td { border-bottom: 0.2mm solid #999; padding: 0.5mm 2mm; text-align: left;
         vertical-align: top; }
th { border-bottom: 0.4mm solid #000; font-weight: bold; }
table.data th { border-bottom: 0.2mm solid #999; }
table.data td + th { padding-left: 6mm; }
td.n, th.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.blank { min-width: 35mm; border-bottom: 0.3mm solid #000; }
ol.steps { list-style: none; padding: 0; margin: 0; }
li.step { margin: 0 0 4mm 0; orphans: 1; }  /* a step may start at a column's foot (its
   number shows where it goes on): two lines kept there left a page 4/5 empty */
/* the steps in three columns (a step may continue in the next column; its figure never
   breaks).  A finished diagram that does not fit what is left of a page floats to the next
   one and the next section fills the rest: its columns too, because the section is a table
   (one cell).  Chromium loses the part of a multicolumn list that falls on the page of a
   float it pushed on (and a list kept below the float leaves the gap empty); a table's
   continuation on that page starts below the float, and its columns with it. */
section.construction { display: table; table-layout: fixed; width: 100%; }
ol.steps.staged { column-count: 3; column-gap: 5mm; }
/* a worksheet's steps (sentences and symbolic formulas, no figure) in two columns: the
   drawing area after them then shares their page (Fig 7's velocity area was pushed on,
   leaving half a page blank) */
body.worksheet ol.steps { column-count: 2; column-gap: 6mm; }
body.worksheet ol.steps > aside.explain { margin: 0 0 2mm 0; }
ol.steps.staged li.step { margin: 0 0 1.5mm 0; font-size: 8.5pt; line-height: 1.28; }
ol.steps.staged figure { margin: 0.5mm 0 0 0; }
ol.steps.staged figure.narrow { float: right; margin: 0 0 1mm 2mm; }
ol.steps.staged figure.narrow figcaption { max-width: 40mm; }
ol.steps.staged > aside.explain { margin: 0 0 2mm 0; }
li.step .say { margin: 0.5mm 0; }
li.step .num { font-family: "DejaVu Sans", Verdana, Arial, sans-serif; font-weight: bold;
               display: inline-block; min-width: 8mm; }
.formula { font-size: 9.5pt; margin: 0.5mm 0 1mm 8mm; }
.formula .meet { white-space: nowrap; }
/* a worked line is not split between columns (li.step's orphans: 1 is inherited): "m/s²
   (lines meet at 90°)" opened a column of Fig 7's key */
.formula { orphans: 2; widows: 2; }
.formula.symbolic { color: #333; }
.explain { border: 0.3mm solid #000; padding: 1mm 2.5mm; margin: 1mm 0 2mm 0;
           break-inside: avoid; page-break-inside: avoid; font-size: 8pt; line-height: 1.28; }
.explain h4 { margin: 0 0.4em 0 0; font-size: 8pt; display: inline; }
.explain p { display: inline; }
.explain p { margin: 0; }
figure { margin: 1.5mm 0 1mm 8mm; break-inside: avoid; page-break-inside: avoid; }
figure svg { display: block; max-width: 100%; height: auto; }
figure svg.drawing-area { max-width: none; }
figcaption, .figure-note { font-size: 8.5pt; color: #333; }
section.plate { margin-top: 1.5mm; }
section.plate div.sheet { float: left; width: 100%; break-inside: avoid;
                          page-break-inside: avoid; margin-bottom: 0.5mm; }
section.plate + section, #results { clear: none; }
/* a worksheet's space diagram does not float: every step is read off it, so the velocity steps
   never come before it (Fig 7's worksheet set steps 1-4 first, the diagram after them) */
body.worksheet section#space div.sheet { float: none; }
section.plate h2, section.plate h3 { break-after: avoid; page-break-after: avoid; }
/* a drawing area with its heading and note, and the answer table, are never split */
section.area, section#your-answers { break-inside: avoid; page-break-inside: avoid; }
/* the words of Klein's construction and of an equivalent linkage are a few lines: in one
   piece (their last two lines made a key's last page: rolling-wheel-forces) */
section#klein pre, section#equivalent pre { break-inside: avoid; page-break-inside: avoid; }
/* a narrow space diagram beside the data (one datum a row) and its own heading and words */
div.beside { display: flex; gap: 5mm; align-items: flex-start; }
div.beside > div.beside-text { flex: 1 1 0; min-width: 0; }
div.beside > section.plate { flex: 0 0 auto; margin-top: 2mm; }
div.beside > section.plate div.sheet { float: none; }
div.beside table.data { width: 100%; }
/* each datum in the narrow column: its name, and its value under it */
div.beside table.data tr { display: block; border-bottom: 0.2mm solid #999;
                           padding: 0.4mm 0 0.6mm 0; }
div.beside table.data th, div.beside table.data td { display: block; border: none;
                                                     padding: 0; }
div.beside table.data td { padding-left: 3mm; }
section.plate figure { margin: 0; }
figure.centres { float: left; margin: 0 4mm 2mm 0; }
section#centres { overflow: hidden; break-inside: avoid; }
section.plate h3 { margin: 0 0 0.5mm 0; }
section.plate .figure-note { margin: 0.3mm 0 0.5mm 0; }
p.note { margin: 0.5mm 0; }
.note { font-size: 9.5pt; }
.slip { border-left: 1mm solid #000; padding: 0.5mm 0 0.5mm 3mm; margin: 1.5mm 0; }
.about p { font-size: 8.5pt; color: #222; margin: 0.3mm 0 1mm 0; }
.about h3 { font-size: 9pt; margin: 2mm 0 0.3mm 0; }
footer { font-size: 8pt; color: #333; margin-top: 2mm; border-top: 0.2mm solid #999;
         padding-top: 1mm; line-height: 1.2; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 8.5pt; }
.ok { font-weight: normal; }
.off { font-weight: bold; }
@media print {
  body { max-width: none; padding: 0; }
  .screen-only { display: none; }     /* a command line is no use on paper */
  footer { display: none; }           /* the key's footer too: a command line (it took a
                                         page of its own on three cases) */
}
@page { @bottom-right { content: "page " counter(page) " of " counter(pages);
                        font: 8pt "DejaVu Sans", Verdana, Arial, sans-serif; color: #333; } }
table.wide { width: 100%; }
section.forces ul.construction { margin: 1mm 0; padding-left: 5mm; font-size: 8.5pt;
                               column-count: 2; column-gap: 6mm; }
section.forces ul.construction li { break-inside: avoid; }
section.forces table { font-size: 8.5pt; }
div.force-group h3, div.force-group ul.construction { break-after: avoid;
                                                 page-break-after: avoid; }
table.wide td.q { width: 30%; }
@media screen {
  body { padding: 8mm 6mm; }
  section.plate { border-top: 0.3mm dashed #999; margin-top: 8mm; padding-top: 4mm;
                  overflow-x: auto; }
}
""" + NOTATION_CSS + "\n" + SUBSUP_CSS + "\n"
