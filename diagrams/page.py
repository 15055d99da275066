"""The interactive construction page: one self-contained HTML file, no server, no network.

    polygons handout CASE.toml --interactive -o CASE-page.html

Left, the construction as a teacher draws it on the board: the static SVG stages of
:func:`diagrams.drawings` (the same bytes ``polygons draw`` writes), one at a time and in order
(the space diagram, then each polygon's stages and last its finished drawing), with Back / Next
buttons (and the arrow keys).  Right, a crank-position slider that redraws the mechanism (its
velocity vectors on the links) and both polygons *in components*, in the static drawings'
colours, line styles and key, at one scale for the whole cycle; the slider starts exactly at
the scene's own position; crowded vertices are drawn again in an inset ('detail ×k', the rule
of :mod:`diagrams.inset` ported to ``assets/inset.js``, recomputed at every position).  Hovering
a link highlights the polygon vectors that belong to it.
Below, "draw it yourself": the student places a polygon's vertices with the mouse or the
keyboard alone and saves the drawing as JSON (what ``polygons check SCENE --drawing FILE``
grades) or SVG; "Check my drawing" grades it in the page, offline, by the same rules
(``diagrams/assets/grade.js`` on :func:`polygons.grade_drawing.rules`): each vector's mark,
what is wrong with it and the step to redo, the wrong arrows drawn red.  The data come from :mod:`diagrams.pagedata`; the script and style are the
files in ``diagrams/assets``.

The page's state can be set from its address (``#stage=7&frame=40``) and read or driven by a
script through ``window.polygonsPage`` and ``window.polygonsDrawing`` (the browser tests do).
"""
from __future__ import annotations

import json
import re
from importlib import resources

from .components import LOOKS
from .html import esc, inline_svg
from .notation import HTML_CSS, html as typeset, plain
from .pagedata import FRAMES, frames

__all__ = ["page", "frames", "FRAMES", "ordered", "asset"]


def asset(name: str) -> str:
    """The text of ``diagrams/assets/<name>`` (the page's script and style)."""
    return resources.files(__package__).joinpath("assets", name).read_text(encoding="utf-8")


def ordered(drawings) -> list:
    """The drawings as the board shows them: the space diagram, then each polygon's stages in
    order and its finished drawing after them."""
    out, finished = [], None
    for d in drawings:
        if d.stage is None:
            if finished is not None:
                out.append(finished)
            finished = d if d.kind != "space" else None
            if finished is None:
                out.append(d)
        else:
            out.append(d)
    if finished is not None:
        out.append(finished)
    return out


def script_json(data) -> str:
    """JSON safe inside a ``<script>`` element: no ``<`` at all (so no ``</script>``, no
    ``<!--``), still the same JSON."""
    blob = json.dumps(data, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return blob.replace("<", "\\u003c")


def fill(template: str, values: dict[str, str]) -> str:
    """``{NAME}`` → ``values[NAME]`` in ONE pass: a substituted value is never scanned again
    (a title reading '{CSS}' stays those five characters)."""
    return re.sub(r"\{([A-Z][A-Z0-9_]*)\}", lambda m: values.get(m.group(1), m.group(0)), template)


def _key(kinds) -> str:
    """The key of the live polygons: one sample line per component kind, as the SVGs draw it."""
    items = []
    for k in kinds:
        lk = LOOKS[k["kind"]]
        dash = (f' stroke-dasharray="{" ".join(f"{float(v) * 2.6:g}" for v in lk.dash.split())}"'
                if lk.dash else "")
        head = ('<polygon points="36,5 28,1.5 28,8.5" fill="#fff" stroke="{c}" '
                'stroke-width="1.2"/>' if lk.open_head else
                '<polygon points="36,5 28,1.5 28,8.5" fill="{c}"/>').format(c=esc(lk.colour))
        items.append(f'<li data-kind="{esc(k["kind"])}"><svg width="38" height="10" '
                     f'viewBox="0 0 38 10" aria-hidden="true"><line x1="1" y1="5" x2="29" y2="5" '
                     f'stroke="{esc(lk.colour)}" stroke-width="{max(1.0, lk.width * 2.6):g}"'
                     f'{dash}/>{head}</svg>{esc(lk.name)}</li>')
    return '<ul class="live-key" aria-label="Key of the live polygons">' + "".join(items) + "</ul>"


def page(sol, figs=None, n: int = FRAMES) -> str:
    """The interactive page of ``sol`` as one HTML document (deterministic)."""
    import diagrams
    from .svg import to_svg
    drawings = diagrams.drawings(sol) if figs is None else list(figs)
    stages = []
    for d in ordered(drawings):
        svg = inline_svg(to_svg(d), f"st-{d.name}", "stage-svg", None, d.title)
        stages.append(f'<figure class="stage" id="stage-{esc(d.name)}" data-name="{esc(d.name)}"'
                      f' hidden>{svg}</figure>')      # the SVG carries its title and caption
    data = frames(sol, drawings, n)
    scene = sol.scene
    title = scene.title
    sid = scene.source.get("id", "")
    head = plain(f"{sid}: {title}" if sid else title)
    from pathlib import PurePath
    base = PurePath(str(scene.file)).stem if scene.file else (sid or "scene")
    stem = re.sub(r"[^A-Za-z0-9._-]+", "-", base).strip("-.") or "scene"
    data["title"] = head
    data["file"] = stem[:60]
    kinds, seen = [], set()
    for p in data["polys"].values():
        for k in p["key"]:
            if k["kind"] not in seen:
                seen.add(k["kind"])
                kinds.append(k)
    order = {k: i for i, k in enumerate(LOOKS)}
    kinds.sort(key=lambda k: order[k["kind"]])
    data["diagrams"] = [d for d in scene.solve if d in data["drawing"]]
    options = "".join(f'<option value="{esc(d)}">{esc(d)} polygon</option>'
                      for d in data["diagrams"])
    return fill(_TEMPLATE, {
        "TITLE": esc(head), "CSS": asset("page.css") + HTML_CSS, "H1": typeset(title),
        "SID": esc(sid), "STAGES": "\n".join(stages), "KEY": _key(kinds),
        "OPTIONS": options, "DATA": script_json(data),
        "JS": asset("inset.js") + "\n" + asset("page.js") + "\n" + asset("grade.js") + "\n" + asset("draw.js"),
    })


_TEMPLATE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{TITLE} — interactive construction</title>
<style>
{CSS}
</style>
</head>
<body>
<h1>{H1}</h1>
<p class="sub">{SID} — the construction stage by stage (left) and the mechanism through its cycle
(right). Arrow keys: stages; the slider: crank position, in the crank's sense of rotation.</p>
<main>
<section id="board"><div class="bar"><button id="back" type="button">◀ Back</button>
<span id="stage-name"></span> <button id="next" type="button">Next ▶</button></div>
{STAGES}
</section>
<section id="live"><div class="bar"><label for="angle">Crank position</label>
<input id="angle" type="range" min="0" step="1"> <output id="angle-out" for="angle"></output>
<label for="zoom">Polygons</label> <select id="zoom"><option value="auto">fit</option>
<option value="1">× 1</option>
<option value="2">× 2</option><option value="4">× 4</option><option value="8">× 8</option>
</select></div>
<svg id="mech" class="live" viewBox="0 0 400 280" role="img"
 aria-label="Mechanism with its velocity vectors"></svg>
<div class="polys"><svg id="vpoly" class="live" viewBox="0 0 300 300" role="img"
 aria-label="Velocity polygon"></svg><svg id="apoly" class="live" viewBox="0 0 300 300"
 role="img" aria-label="Acceleration polygon"></svg></div>
{KEY}
<p class="note">Hover a link to highlight its vectors in both polygons. The polygons are drawn
in components as in the static drawings, each at one scale for the whole cycle (the bar, at "× 1";
"× 2" … enlarges them about the pole, still one scale for every position; "fit", the start,
fits each polygon to its panel at the position shown, the bar giving that scale); vertices
too near each other to read are drawn again enlarged in a ringed inset, 'detail ×k', every
vector in it at least 3 mm long; the velocity vectors on the linkage share one scale too.</p>
</section>
</main>
<section id="draw" aria-labelledby="draw-h">
<h2 id="draw-h">Draw it yourself</h2>
<p class="draw-help" id="draw-help">Pick the polygon and a vertex, then place it on the paper:
click, or with the keyboard alone — Tab to the paper, arrow keys move the cursor 1 mm
(Shift + arrow: 10 mm), Enter places the vertex and selects the next one in construction order,
N / P select the next / previous vertex, Delete removes it. Arrows appear between consecutive
construction vertices. Save the drawing as JSON (for <code>polygons check SCENE --drawing
FILE</code>) or as SVG. "Check my drawing" grades it here, by the rules of
<code>polygons check</code>: each vector's mark, what is wrong and the step to redo.</p>
<div class="bar"><label for="draw-diagram">Polygon</label> <select id="draw-diagram">{OPTIONS}
</select> <span id="draw-scale"></span></div>
<div class="bar" role="group" aria-label="Vertex to place"><span>Vertex:</span>
<span id="draw-vertices"></span></div>
<svg id="paper" tabindex="0" role="application" aria-describedby="draw-help"
 aria-label="Drawing paper" viewBox="0 0 120 90"></svg>
<p id="draw-status" role="status" aria-live="polite"></p>
<div class="bar"><button id="save-json" type="button">Save JSON</button>
<button id="save-svg" type="button">Save SVG</button>
<button id="draw-clear" type="button">Clear</button>
<button id="draw-check" type="button">Check my drawing</button></div>
<div id="draw-grade" aria-live="polite"></div>
</section>
<script type="application/json" id="frames">{DATA}</script>
<script>
{JS}
</script>
</body>
</html>
"""
