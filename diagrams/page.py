"""The interactive construction page: one self-contained HTML file, no server, no network.

    polygons handout CASE.toml --interactive -o CASE-page.html

Left, the construction as a teacher draws it on the board: the static SVG stages of
:func:`diagrams.drawings` (the same bytes ``polygons draw`` writes), one at a time, with Back /
Next buttons (and the arrow keys).  Right, a crank-angle slider that redraws the mechanism, its
velocity polygon and its acceleration polygon from frames precomputed by
:func:`polygons.sweep.sweep` (each frame exact at its angle; the slider runs in the crank's
sense of rotation), with the velocity vectors also drawn on the linkage; hovering a link
highlights its relative vectors in both polygons.

The page's state can be set from its address (``#stage=7&frame=40``) and read or driven by a
script through ``window.polygonsPage`` (the browser tests do both).  No svgwrite here: the
stage figures come from :mod:`diagrams.svg`, the live panels are drawn by the page's script.
"""
from __future__ import annotations

import json
import math
import re

import numpy as np

from .components import LOOKS
from .html import esc, inline_svg
from .notation import HTML_CSS, html as typeset, plain

#: positions in the slider (frames of the sweep)
FRAMES = 180


def _r(x: float) -> float:
    """Six significant figures: a deterministic, compact JSON number."""
    if not math.isfinite(x):
        return None
    return float(f"{x:.6g}") + 0.0        # + 0.0: no '-0.0' in the data


def _edges(scene) -> list[tuple[str, str, str]]:
    """(end, end, link name) of every line the mechanism panel draws."""
    from polygons.evaluate import link_ends
    out = []
    for name, ln in scene.links.items():
        out.append((ln.a, ln.b, name))
    for slot in scene.slots.values():
        out.append((slot.pivot, slot.pin, slot.lever))
        if slot.far:
            out.append((slot.pivot, slot.far, slot.lever))
    for lab, bp in scene.points.items():
        try:
            a, b = link_ends(scene, bp.link)
        except KeyError:
            continue
        out.append((a, lab, bp.link))
        out.append((b, lab, bp.link))
    seen, uniq = set(), []
    for a, b, n in out:
        if (a, b) not in seen and (b, a) not in seen and a != b:
            seen.add((a, b))
            uniq.append((a, b, n))
    return uniq


def frames(sol, n: int = FRAMES) -> dict:
    """The sweep's positions, velocities and accelerations as page data (SI, rounded).

    Frames are ordered in the crank's sense of rotation (a CW crank's angle decreasing), so
    moving the slider to the right is moving forward in time; ``start`` is the frame nearest
    the scene's own position.
    """
    from polygons.scene import Crank
    from polygons.sweep import sweep
    scene = sol.scene
    sw = sweep(scene, n)
    xs = np.asarray(sw.inputs, dtype=float)
    order = list(range(len(xs)))
    drv = scene.driver
    crank = isinstance(drv, Crank)
    if crank and drv.omega < 0:
        order = order[::-1]
    N = len(xs)

    def arr(d, lab):
        a = np.asarray(d[lab] if d[lab] is not None else (0.0, 0.0), dtype=float)
        if a.shape == (2,):                    # a fixed point: one position for every frame
            a = np.broadcast_to(a, (N, 2))
        elif a.shape == (2, N):                # (xs, ys)
            a = a.T
        v = a
        return [[_r(v[i, 0]), _r(v[i, 1])] for i in order]

    labels = [lab for lab in scene.labels if lab in sw.pos]
    own = drv.angle if crank else getattr(drv, "position", 0.0)
    if crank:
        dist = [abs((xs[i] - own + math.pi) % (2 * math.pi) - math.pi) for i in order]
    else:
        dist = [abs(xs[i] - own) for i in order]
    start = int(min(range(N), key=lambda k: (dist[k], k)))
    return {
        "kind": sw.input_kind,
        "inputs": [_r(math.degrees(xs[i]) if crank else xs[i] * 1000) for i in order],
        "unit": "°" if crank else "mm",
        "sense": ("CW" if drv.omega < 0 else "CCW") if crank else "",
        "start": start,
        "full": bool(sw.full_cycle),
        "labels": labels,
        "ground": [g for g in scene.ground if g in sw.pos],
        "pos": {lab: arr(sw.pos, lab) for lab in labels},
        "vel": {lab: arr(sw.vel, lab) for lab in labels if lab in sw.vel},
        "acc": {lab: arr(sw.acc, lab) for lab in labels if lab in sw.acc},
        "edges": [list(e) for e in _edges(scene) if e[0] in sw.pos and e[1] in sw.pos],
        "colours": {k: LOOKS[k].colour for k in ("given", "relative", "resultant")},
    }


def page(sol, figs=None, n: int = FRAMES) -> str:
    """The interactive page of ``sol`` as one HTML document (deterministic)."""
    import diagrams
    from .svg import to_svg
    drawings = diagrams.drawings(sol) if figs is None else figs
    stages = []
    for d in drawings:
        svg = inline_svg(to_svg(d), f"st-{d.name}", "stage-svg", None, d.title)
        stages.append(f'<figure class="stage" id="stage-{esc(d.name)}" data-name="{esc(d.name)}"'
                      f' hidden>{svg}</figure>')      # the SVG carries its title and caption
    data = frames(sol, n)
    title = sol.scene.title
    sid = sol.scene.source.get("id", "")
    blob = json.dumps(data, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    blob = blob.replace("</", "<\\/")
    fill = {"TITLE": esc(plain(f"{sid}: {title}" if sid else title)), "CSS": _CSS + HTML_CSS}
    return (re.sub(r"\{(TITLE|CSS)\}", lambda m: fill[m.group(1)], _HEAD)   # once: a title
            # '{CSS}' stays text
            + f'<h1>{typeset(title)}</h1>\n<p class="sub">{esc(sid)} — the construction stage by '
            f"stage (left) and the mechanism through its cycle (right). Arrow keys: stages; "
            f"the slider: crank position, in the crank's sense of rotation.</p>\n"
            '<main>\n<section id="board"><div class="bar"><button id="back" type="button">'
            '◀ Back</button> <span id="stage-name"></span> <button id="next" type="button">'
            'Next ▶</button></div>\n' + "\n".join(stages) + "\n</section>\n"
            '<section id="live"><div class="bar"><label for="angle">Crank position</label> '
            '<input id="angle" type="range" min="0" step="1"> <output id="angle-out">'
            "</output></div>\n"
            '<svg id="mech" class="live" viewBox="0 0 100 70" role="img" '
            'aria-label="Mechanism with its velocity vectors"></svg>\n'
            '<div class="polys"><svg id="vpoly" class="live" viewBox="0 0 100 100" role="img" '
            'aria-label="Velocity polygon"></svg><svg id="apoly" class="live" '
            'viewBox="0 0 100 100" role="img" aria-label="Acceleration polygon"></svg></div>\n'
            '<p class="note">Hover a link to highlight its relative vectors. Velocity vectors '
            "are drawn on the linkage at one scale for the whole cycle; each polygon is fitted "
            "to its panel at every frame (its shape, not its size, compares from frame to "
            "frame).</p>\n</section>\n</main>\n"
            f'<script type="application/json" id="frames">{blob}</script>\n'
            f"<script>\n{_JS}\n</script>\n</body>\n</html>\n")


_HEAD = """<!DOCTYPE html>
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
"""

_CSS = """
body { font-family: "DejaVu Sans", Verdana, Arial, sans-serif; font-size: 10pt; margin: 4mm; }
h1 { font-size: 14pt; margin: 0 0 1mm 0; } .sub { margin: 0 0 3mm 0; color: #333; }
main { display: grid; grid-template-columns: minmax(0, 3fr) minmax(0, 2fr); gap: 5mm; }
.bar { margin: 0 0 2mm 0; } button { font-size: 10pt; }
figure.stage { margin: 0; } figure.stage svg { width: 100%; height: auto; max-height: 78vh; }
figcaption { font-size: 9.5pt; margin-top: 1mm; }
svg.live { width: 100%; height: auto; border: 0.3mm solid #ccc; background: #fff; }
.polys { display: grid; grid-template-columns: 1fr 1fr; gap: 2mm; margin-top: 2mm; }
.live .link { stroke: #000; stroke-width: 1.1; stroke-linecap: round; cursor: pointer; }
.live .link.hi, .live .rel.hi { stroke: #D55E00; stroke-width: 1.8; }
.live text { font-size: 3.2px; font-family: "DejaVu Sans", sans-serif; }
.note { font-size: 8.5pt; color: #333; }
"""

_JS = r"""
(function () {
  'use strict';
  var D = JSON.parse(document.getElementById('frames').textContent);
  var NS = 'http://www.w3.org/2000/svg';
  var stages = Array.prototype.slice.call(document.querySelectorAll('figure.stage'));
  var cur = 0, frame = D.start, hover = -1;
  var SUB = '₀₁₂₃₄₅₆₇₈₉';
  function typeset(name) {            // O4 → O₄, p2 → p₂ (the drawings' notation)
    return name.replace(/([A-Za-z])(\d+)/g, function (m, l, d) {
      return l + d.split('').map(function (c) { return SUB[+c]; }).join('');
    });
  }
  function el(parent, tag, attrs) {
    var e = document.createElementNS(NS, tag);
    for (var k in attrs) { e.setAttribute(k, attrs[k]); }
    parent.appendChild(e); return e;
  }
  function showStage(k) {
    cur = Math.max(0, Math.min(stages.length - 1, k));
    stages.forEach(function (s, i) { s.hidden = i !== cur; });
    document.getElementById('stage-name').textContent =
      (cur + 1) + ' / ' + stages.length + ': ' + stages[cur].dataset.name;
  }
  function box(pts) {
    var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    pts.forEach(function (p) {
      if (p[0] === null || p[1] === null) { return; }
      x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
      y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
    });
    if (!isFinite(x0)) { x0 = y0 = 0; x1 = y1 = 1; }
    return [x0, y0, x1, y1];
  }
  function fit(b, W, H, pad) {
    var w = Math.max(b[2] - b[0], 1e-12), h = Math.max(b[3] - b[1], 1e-12);
    var k = Math.min((W - 2 * pad) / w, (H - 2 * pad) / h);
    var ox = pad + ((W - 2 * pad) - k * w) / 2, oy = pad + ((H - 2 * pad) - k * h) / 2;
    return function (p) { return [ox + k * (p[0] - b[0]), H - (oy + k * (p[1] - b[1]))]; };
  }
  var all = [], vmax = 0;
  D.labels.forEach(function (l) {
    all = all.concat(D.pos[l]);
    (D.vel[l] || []).forEach(function (v) { vmax = Math.max(vmax, Math.hypot(v[0], v[1])); });
  });
  var mb = box(all), span = Math.max(mb[2] - mb[0], mb[3] - mb[1]);
  var kv = vmax > 0 ? 0.22 * span / vmax : 0;
  var withV = all.slice();
  D.labels.forEach(function (l) {
    (D.pos[l] || []).forEach(function (p, i) {
      var v = (D.vel[l] || [])[i]; if (v) { withV.push([p[0] + kv * v[0], p[1] + kv * v[1]]); }
    });
  });
  var M = fit(box(withV), 100, 70, 6);
  function arrow(g, a, b, colour, dash, cls, edge) {
    var dx = b[0] - a[0], dy = b[1] - a[1], L = Math.hypot(dx, dy);
    var attrs = {x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: colour, 'stroke-width': 0.6,
                 'class': cls};
    if (dash) { attrs['stroke-dasharray'] = dash; }
    if (edge !== undefined) { attrs['data-edge'] = edge; }
    el(g, 'line', attrs);
    if (L > 1.5) {
      var ux = dx / L, uy = dy / L, h = Math.min(2.4, 0.4 * L), w = 0.8 * h / 2.4 * 1.2;
      var bx = b[0] - ux * h, by = b[1] - uy * h;
      el(g, 'polygon', {points: b[0] + ',' + b[1] + ' ' + (bx - uy * w) + ',' + (by + ux * w) +
                        ' ' + (bx + uy * w) + ',' + (by - ux * w), fill: colour,
                        'class': cls + ' head', 'data-edge': edge === undefined ? '' : edge});
    }
  }
  function polygon(svg, vec, sym) {
    while (svg.firstChild) { svg.removeChild(svg.firstChild); }
    var here = [[0, 0]];             // fitted to its panel at each frame
    D.labels.forEach(function (l) { if (vec[l] && vec[l][frame][0] !== null) {
      here.push(vec[l][frame]); } });
    var T = fit(box(here), 100, 100, 10);
    var pole = T([0, 0]);
    el(svg, 'circle', {cx: pole[0], cy: pole[1], r: 1.1, fill: '#fff', stroke: '#000',
                       'stroke-width': 0.4});
    D.labels.forEach(function (l) {
      var v = vec[l]; if (!v) { return; }
      var p = v[frame]; if (p[0] === null) { return; }
      var q = T(p);
      if (Math.hypot(p[0], p[1]) > 0) {
        arrow(svg, pole, q, D.colours.resultant, '0.6 0.9', 'abs', undefined);
      }
    });
    D.edges.forEach(function (e, i) {
      var a = vec[e[0]], b = vec[e[1]]; if (!a || !b) { return; }
      arrow(svg, T(a[frame]), T(b[frame]), D.colours.relative, null,
            'rel' + (i === hover ? ' hi' : ''), i);
    });
    var placed = {};
    D.labels.forEach(function (l) {
      var v = vec[l]; if (!v) { return; }
      var q = T(v[frame]), key = Math.round(q[0]) + ',' + Math.round(q[1]);
      placed[key] = (placed[key] ? placed[key] + ' = ' : '') + typeset(l.toLowerCase());
      var t = el(svg, 'text', {x: q[0] + 1.2, y: q[1] - 1.2, 'data-label': l});
      t.textContent = placed[key];
    });
    var cap = el(svg, 'text', {x: 2, y: 5}); cap.textContent = sym + ' polygon';
  }
  function mechanism() {
    var svg = document.getElementById('mech');
    while (svg.firstChild) { svg.removeChild(svg.firstChild); }
    D.edges.forEach(function (e, i) {
      var a = M(D.pos[e[0]][frame]), b = M(D.pos[e[1]][frame]);
      var ln = el(svg, 'line', {x1: a[0], y1: a[1], x2: b[0], y2: b[1],
                                'class': 'link' + (i === hover ? ' hi' : ''), 'data-edge': i});
      var t = document.createElementNS(NS, 'title'); t.textContent = 'link ' + e[2];
      ln.appendChild(t);
      ln.addEventListener('mouseenter', function () { setHover(i); });
      ln.addEventListener('mouseleave', function () { setHover(-1); });
    });
    var names = {};
    D.labels.forEach(function (l) {
      var p = D.pos[l][frame], v = (D.vel[l] || [])[frame];
      var q = M(p);
      if (v && kv > 0 && Math.hypot(v[0], v[1]) > 0) {
        arrow(svg, q, M([p[0] + kv * v[0], p[1] + kv * v[1]]), D.colours.given, null, 'vel');
      }
      var ground = D.ground.indexOf(l) >= 0;
      el(svg, 'circle', {cx: q[0], cy: q[1], r: ground ? 1.2 : 0.9, fill: '#fff',
                         stroke: '#000', 'stroke-width': 0.4, 'data-point': l});
      var key = Math.round(q[0] * 2) + ',' + Math.round(q[1] * 2);
      if (names[key]) { names[key].textContent += ', ' + typeset(l); return; }   // coincident
      names[key] = el(svg, 'text', {x: q[0] + 1.4, y: q[1] - 1.4});
      names[key].textContent = typeset(l);
    });
  }
  function setHover(i) { hover = i; draw(); }
  function draw() {
    mechanism();
    polygon(document.getElementById('vpoly'), D.vel, 'velocity');
    polygon(document.getElementById('apoly'), D.acc, 'acceleration');
    document.getElementById('angle-out').textContent =
      D.inputs[frame] + ' ' + D.unit + (D.sense ? ' (crank turns ' + D.sense + ')' : '');
  }
  function setFrame(i) {
    frame = Math.max(0, Math.min(D.inputs.length - 1, i | 0));
    document.getElementById('angle').value = frame; draw();
  }
  var slider = document.getElementById('angle');
  slider.max = D.inputs.length - 1;
  slider.addEventListener('input', function () { setFrame(+slider.value); });
  document.getElementById('back').addEventListener('click', function () { showStage(cur - 1); });
  document.getElementById('next').addEventListener('click', function () { showStage(cur + 1); });
  document.addEventListener('keydown', function (e) {
    if (e.target === slider) { return; }
    if (e.key === 'ArrowRight') { showStage(cur + 1); }
    if (e.key === 'ArrowLeft') { showStage(cur - 1); }
  });
  var h = {};
  location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
    var p = kv.split('='); if (p.length === 2) { h[p[0]] = +p[1]; }
  });
  showStage(h.stage ? h.stage - 1 : 0);
  setFrame(h.frame !== undefined && !isNaN(h.frame) ? h.frame : D.start);
  window.polygonsPage = {
    stage: function () { return stages[cur].dataset.name; },
    stages: stages.length, next: function () { showStage(cur + 1); },
    back: function () { showStage(cur - 1); }, frame: function () { return frame; },
    setFrame: setFrame, hover: setHover
  };
})();
"""
