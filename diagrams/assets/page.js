// The interactive construction page: stages, the live mechanism and polygons (diagrams/page.py).
// Data: the JSON blob #frames (diagrams/pagedata.py).  Shared helpers on window.polygonsKit.
(function () {
  'use strict';
  var D = JSON.parse(document.getElementById('frames').textContent);
  var NS = 'http://www.w3.org/2000/svg';
  var FONT = 12;                      // label size, CSS px, whatever the panel's size
  var stages = Array.prototype.slice.call(document.querySelectorAll('figure.stage'));
  var cur = 0, frame = D.start, hover = -1;

  function el(parent, tag, attrs) {
    var e = document.createElementNS(NS, tag);
    for (var k in attrs) { if (attrs[k] !== undefined && attrs[k] !== null) { e.setAttribute(k, attrs[k]); } }
    parent.appendChild(e); return e;
  }
  function clear(svg) { while (svg.firstChild) { svg.removeChild(svg.firstChild); } }
  function unitOf(svg) {              // viewBox units per CSS px
    var w = svg.getBoundingClientRect().width, vb = svg.viewBox.baseVal;
    return w > 0 ? vb.width / w : 1;
  }
  // does the segment (x1,y1)-(x2,y2) cross the rectangle r = {x, y, w, h}?  (Liang–Barsky)
  function segHits(s, r) {
    var x1 = s[0], y1 = s[1], dx = s[2] - s[0], dy = s[3] - s[1], t0 = 0, t1 = 1;
    var p = [-dx, dx, -dy, dy], q = [x1 - r.x, r.x + r.w - x1, y1 - r.y, r.y + r.h - y1];
    for (var i = 0; i < 4; i++) {
      if (p[i] === 0) { if (q[i] < 0) { return false; } continue; }
      var t = q[i] / p[i];
      if (p[i] < 0) { if (t > t1) { return false; } if (t > t0) { t0 = t; } }
      else { if (t < t0) { return false; } if (t < t1) { t1 = t; } }
    }
    return true;
  }
  function boxHits(a, b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
  }
  // a label near `at`, inside the view, off every segment and every earlier label if it can be
  // (within: {c, r, font, box}: an inset's label, its own size, kept inside the inset's
  // circle where it can be, its place, box, no obstacle to it)
  function label(svg, text, at, segs, boxes, U, attrs, within) {
    var root = svg.ownerSVGElement || svg;
    var W = root.viewBox.baseVal.width, H = root.viewBox.baseVal.height;
    var fs = (within ? within.font : FONT) * U, t = el(svg, 'text', attrs || {});
    t.setAttribute('font-size', fs); t.setAttribute('x', 0); t.setAttribute('y', 0);
    t.textContent = text;
    var bb = t.getBBox(), lines = null;
    if (bb.width > W - 8 * U) {       // too wide for the panel (many coincident names): lines
      var parts = text.split(/(?= = |, )/), line = '';
      lines = [];
      t.textContent = '';
      parts.forEach(function (part) {
        t.textContent = line + part;
        if (line && t.getBBox().width > W - 8 * U) { lines.push(line); line = part.replace(/^( = |, )/, '= '); }
        else { line += part; }
      });
      lines.push(line);
      t.textContent = '';
      lines = lines.map(function (l, i) {
        var s = el(t, 'tspan', {x: 0, dy: i ? 1.15 * fs : 0}); s.textContent = l; return s;
      });
      bb = t.getBBox();
    }
    var w = bb.width, h = bb.height, pad = 1.5 * U, best = null;
    function tryAt(k) {               // beyond 3 label heights: with a leader
      for (var j = 0; j < N; j++) {
        var ang = -Math.PI / 4 + j * 2 * Math.PI / N, ux = Math.cos(ang), uy = Math.sin(ang);
        var d = k * fs + 0.5 * Math.abs(ux) * w + 0.5 * Math.abs(uy) * h;
        var r = {x: at[0] + ux * d - w / 2, y: at[1] + uy * d - h / 2, w: w, h: h};
        var g = {x: r.x - pad, y: r.y - pad, w: r.w + 2 * pad, h: r.h + 2 * pad};
        var out = r.x < 2 * U || r.y < 2 * U || r.x + w > W - 2 * U || r.y + h > H - 2 * U;
        var score = (out ? 1e6 : 0) + k;
        if (within && [[r.x, r.y], [r.x + w, r.y], [r.x, r.y + h], [r.x + w, r.y + h]].some(function (p) {
          return Math.hypot(p[0] - within.c[0], p[1] - within.c[1]) > within.r - U; })) { score += 50; }
        segs.forEach(function (s) { if (segHits(s, g)) { score += 100; } });
        boxes.forEach(function (b) {  // (an inset's label: not its own inset's place)
          if (!(within && b === within.box) && boxHits(b, g)) { score += 1000; }
        });
        if (k > 3) {                  // its leader (as drawn: from 2 U off the point) crosses no
          var lx = Math.max(r.x, Math.min(at[0], r.x + w)), ly = Math.max(r.y, Math.min(at[1], r.y + h));
          var ll = Math.hypot(lx - at[0], ly - at[1]), l0 = 2 * U / Math.max(ll, 1e-9);
          var lseg = [at[0] + (lx - at[0]) * l0, at[1] + (ly - at[1]) * l0, lx, ly];
          boxes.forEach(function (b) {  // other text (not the box of its own point), or costs less
            var own = at[0] >= b.x && at[0] <= b.x + b.w && at[1] >= b.y && at[1] <= b.y + b.h;
            if (!own && segHits(lseg, b)) { score += 60; }   // than a label on a vector (100)
          });
        }
        if (best === null || score < best.score) { best = {score: score, r: r, k: k}; }
      }
    }
    // (an inset's label, in a crowded circle: twice the directions and distances)
    var N = within ? 48 : 24;
    (within ? [0.35, 0.6, 0.8, 1.1, 1.5, 1.9, 2.4, 3, 3.6, 4.3, 5, 5.7, 6.5, 8]
            : [0.35, 0.8, 1.5, 2.4, 3.6, 5, 6.5, 8]).forEach(tryAt);
    // crowded, or on a line (a vertex at the panel's edge, a fixed scale's polygon run off it):
    // further off, with a leader
    if (best.score >= 1000 || (!within && best.score >= 100)) { [10, 12.5, 15, 18].forEach(tryAt); }
    t.setAttribute('x', best.r.x - bb.x); t.setAttribute('y', best.r.y - bb.y);
    (lines || []).forEach(function (s) { s.setAttribute('x', best.r.x - bb.x); });
    boxes.push(best.r);
    if (best.k > 3) {                 // set away: a thin leader from the label to its point
      var cx = Math.max(best.r.x, Math.min(at[0], best.r.x + w)), cy = Math.max(best.r.y, Math.min(at[1], best.r.y + h));
      var L = Math.hypot(cx - at[0], cy - at[1]), s0 = 2 * U / Math.max(L, 1e-9);
      var ld = [at[0] + (cx - at[0]) * s0, at[1] + (cy - at[1]) * s0, cx, cy];
      el(svg, 'line', {x1: ld[0], y1: ld[1], x2: ld[2], y2: ld[3], stroke: '#777', 'stroke-width': 0.6 * U,
                       'class': 'leader'});
      segs.push(ld);
    }
    return t;
  }
  // an arrow a → b in a component's look (width, dashes in mm; ×px per mm, × U)
  function arrow(g, a, b, look, U, cls, extra) {
    var px = 2.6 * U, dx = b[0] - a[0], dy = b[1] - a[1], L = Math.hypot(dx, dy);
    var colour = look.colour, hl = Math.min(9 * U, 0.45 * L), hw = 3.2 * U;
    var ux = L > 0 ? dx / L : 0, uy = L > 0 ? dy / L : 0;
    var stop = look.open ? hl : 0.6 * hl;          // the shaft ends inside the head
    var attrs = {x1: a[0], y1: a[1], x2: b[0] - ux * stop, y2: b[1] - uy * stop, stroke: colour,
                 'stroke-width': Math.max(1 * U, look.width * px), 'class': cls};
    if (look.dash) {
      attrs['stroke-dasharray'] = look.dash.split(' ').map(function (v) { return +v * px; }).join(' ');
    }
    for (var k in extra || {}) { attrs[k] = extra[k]; }
    el(g, 'line', attrs);
    if (L > 2 * U && look.head !== false) {
      var bx = b[0] - ux * hl, by = b[1] - uy * hl;
      el(g, 'polygon', {points: b[0] + ',' + b[1] + ' ' + (bx - uy * hw) + ',' + (by + ux * hw) +
                        ' ' + (bx + uy * hw) + ',' + (by - ux * hw),
                        fill: look.open ? '#fff' : colour, stroke: colour,
                        'stroke-width': look.open ? 1.2 * U : 0.5 * U, 'class': cls + ' head'});
    }
    return [a[0], a[1], b[0], b[1]];
  }
  function box(pts) {
    var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    pts.forEach(function (p) {
      if (!p || p[0] === null || p[1] === null) { return; }
      x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
      y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
    });
    if (!isFinite(x0)) { x0 = y0 = 0; x1 = y1 = 1; }
    return [x0, y0, x1, y1];
  }
  function fit(b, W, H, pad) {        // y up (SI) → y down (SVG), one scale k
    var w = Math.max(b[2] - b[0], 1e-12), h = Math.max(b[3] - b[1], 1e-12);
    var k = Math.min((W - 2 * pad) / w, (H - 2 * pad) / h);
    var ox = pad + ((W - 2 * pad) - k * w) / 2, oy = pad + ((H - 2 * pad) - k * h) / 2;
    var f = function (p) { return [ox + k * (p[0] - b[0]), H - (oy + k * (p[1] - b[1]))]; };
    f.k = k; return f;
  }
  window.polygonsKit = {el: el, clear: clear, unitOf: unitOf, label: label, arrow: arrow,
                        segHits: segHits, boxHits: boxHits, data: D, FONT: FONT};

  function showStage(k) {
    cur = Math.max(0, Math.min(stages.length - 1, k));
    stages.forEach(function (s, i) { s.hidden = i !== cur; });
    document.getElementById('stage-name').textContent =
      (cur + 1) + ' / ' + stages.length + ': ' + stages[cur].dataset.name;
  }

  // ---------------------------------------------------------------- the mechanism panel
  var all = [], vmax = 0, off = {};
  (D.mech_off || []).forEach(function (i) { off[i] = true; });   // near a toggle: off scale
  D.labels.forEach(function (l) {
    all = all.concat(D.pos[l].filter(function (p, i) { return !off[i]; }));
    (D.vel[l] || []).forEach(function (v, i) {
      if (v[0] !== null && !off[i]) { vmax = Math.max(vmax, Math.hypot(v[0], v[1])); }
    });
  });
  var mb = box(all), span = Math.max(mb[2] - mb[0], mb[3] - mb[1]);
  var kv = vmax > 0 ? 0.22 * span / vmax : 0;
  var withV = all.slice();
  D.labels.forEach(function (l) {
    (D.pos[l] || []).forEach(function (p, i) {
      var v = (D.vel[l] || [])[i];
      if (v && v[0] !== null && p[0] !== null && !off[i]) { withV.push([p[0] + kv * v[0], p[1] + kv * v[1]]); }
    });
  });
  var mech = document.getElementById('mech');
  var M = fit(box(withV), mech.viewBox.baseVal.width, mech.viewBox.baseVal.height, 34);
  function mechanism() {
    var svg = mech, U = unitOf(svg), segs = [], boxes = [];
    clear(svg);
    D.edges.forEach(function (e, i) {
      var p = D.pos[e[0]][frame], q = D.pos[e[1]][frame];
      if (p[0] === null || q[0] === null) { return; }
      var a = M(p), b = M(q);
      var ln = el(svg, 'line', {x1: a[0], y1: a[1], x2: b[0], y2: b[1], 'stroke-width': 3.2 * U,
                                'class': 'link' + (i === hover ? ' hi' : ''), 'data-edge': i,
                                'data-link': e[2]});
      var t = document.createElementNS(NS, 'title'); t.textContent = 'link ' + e[2];
      ln.appendChild(t);
      ln.addEventListener('mouseenter', function () { setHover(i); });
      ln.addEventListener('mouseleave', function () { setHover(-1); });
      segs.push([a[0], a[1], b[0], b[1]]);
    });
    var given = {colour: D.colours.given, width: 0.45, dash: null};
    D.labels.forEach(function (l) {
      var p = D.pos[l][frame], v = (D.vel[l] || [])[frame];
      if (p[0] === null || !v || v[0] === null || !(kv > 0) || Math.hypot(v[0], v[1]) === 0) { return; }
      segs.push(arrow(svg, M(p), M([p[0] + kv * v[0], p[1] + kv * v[1]]), given, U, 'vel'));
    });
    var groups = [];
    D.labels.forEach(function (l) {
      var p = D.pos[l][frame]; if (p[0] === null) { return; }
      var q = M(p), ground = D.ground.indexOf(l) >= 0;
      el(svg, 'circle', {cx: q[0], cy: q[1], r: (ground ? 4 : 3) * U, fill: '#fff', stroke: '#000',
                         'stroke-width': 1.2 * U, 'data-point': l});
      var g = groups.filter(function (g) { return Math.hypot(g.at[0] - q[0], g.at[1] - q[1]) < 2 * U; })[0];
      if (g) { g.names.push(D.names[l]); } else { groups.push({at: q, names: [D.names[l]], first: l}); }
    });
    groups.forEach(function (g) {
      boxes.push({x: g.at[0] - 4 * U, y: g.at[1] - 4 * U, w: 8 * U, h: 8 * U});
    });
    var W = svg.viewBox.baseVal.width, H = svg.viewBox.baseVal.height;
    groups.forEach(function (g) {     // (a point run off the panel, near a toggle: no label)
      if (g.at[0] < 0 || g.at[0] > W || g.at[1] < 0 || g.at[1] > H) { return; }
      label(svg, g.names.join(', '), g.at, segs, boxes, U, {'data-name': g.first, 'class': 'pt'});
    });
    if (off[frame]) { note(svg, 'beyond the scale here: near a toggle', U, boxes); }
  }

  // ---------------------------------------------------------------- the polygon panels
  var T = {}, BASE = {};
  ['velocity', 'acceleration'].forEach(function (d) {     // a scene may solve velocity only
    if (!D.polys[d]) { document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly').style.display = 'none'; }
  });
  Object.keys(D.polys).forEach(function (d) {
    var P = D.polys[d], svg = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly');
    var b = P.box, W = svg.viewBox.baseVal.width;
    var w = Math.max(b[2] - b[0], 1e-12), hh = Math.max(b[3] - b[1], 1e-12);
    var H = Math.round(Math.max(170, Math.min(380, (W - 60) * hh / w + 86)));
    svg.setAttribute('viewBox', '0 0 ' + W + ' ' + H);      // the panel takes the cycle's shape
    BASE[d] = H;                      // (a strip of insets below the polygon adds to it)
    svg.setAttribute('data-base', H);
    T[d] = fit([b[0], b[1], b[2], b[3]], W, H - 26, 30);   // one scale for the whole cycle
  });
  var LOOK = {};
  Object.keys(D.polys).forEach(function (d) {
    D.polys[d].key.forEach(function (k) { LOOK[k.kind] = k; });
  });
  // 'fill' (the start): each polygon fitted to its panel at the position shown, its bar
  // stating that position's scale (a polygon over the cycle's largest one drew ~15 mm);
  // × 1, 2, 4, 8: one scale for every position, the cycle's polygons in the panel at × 1
  var zoom = 'auto';
  function at(d, f) {
    var P = D.polys[d];
    return Object.keys(P.vx).map(function (v) { return P.vx[v][f]; })
      .filter(function (p) { return p && p[0] !== null; });
  }
  function room(d, reserve) {         // reserve: {side: 'right' | 'bottom', size} for insets
    var svg = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly');
    var W = svg.viewBox.baseVal.width, H = BASE[d];
    var r = [30, 32 + FONT, W - 30, H - 50];       // below the caption, above the bar
    if (reserve) { r[reserve.side === 'right' ? 2 : 3] -= reserve.size; }
    return r;
  }
  function fitted(d, reserve) {       // the enlargement over × 1 that fits this position
    var pts = at(d, frame), F = T[d], r = room(d, reserve);
    if (pts.length < 2) { return 1; }
    var b = box(pts), w = (b[2] - b[0]) * F.k, h = (b[3] - b[1]) * F.k;
    var z = Math.min((r[2] - r[0]) / Math.max(w, 1e-9), (r[3] - r[1]) / Math.max(h, 1e-9));
    return isFinite(z) && z > 0 ? Math.min(z, 1e6) : 1;
  }
  function frameOf(d, reserve) {
    if (zoom !== 'auto') { return zoomed(T[d], zoom); }
    var F = T[d], z = fitted(d, reserve), r = room(d, reserve), b = box(at(d, frame));
    var c = F([(b[0] + b[2]) / 2, (b[1] + b[3]) / 2]), m = [(r[0] + r[2]) / 2, (r[1] + r[3]) / 2];
    var g = function (p) { var q = F(p); return [m[0] + z * (q[0] - c[0]), m[1] + z * (q[1] - c[1])]; };
    g.k = F.k * z; g.z = z; return g;
  }
  function nice(x) {                  // a round bar length (1, 2, 2.5, 5 × 10ⁿ) not above x
    var k = Math.pow(10, Math.floor(Math.log10(x)));
    var m = [5, 2.5, 2, 1].filter(function (m) { return m * k <= x * (1 + 1e-12); })[0] || 1;
    return +(m * k).toPrecision(6);
  }
  function zoomed(F, z) {             // z × about the pole: still one scale for every frame
    if (z === 1) { return F; }
    var c = F([0, 0]);
    var g = function (p) { var q = F(p); return [c[0] + z * (q[0] - c[0]), c[1] + z * (q[1] - c[1])]; };
    g.k = F.k * z; g.z = z; return g;
  }

  // ---------------------------------------------------------------- insets ('detail ×k')
  // The static drawings' rule (diagrams/inset.py, ported in inset.js on its constants): in
  // mm at the page's 96 CSS px to the inch, vertices nearer each other than a label is tall
  // are ringed and drawn again k × larger in a circle of their own in a free place of the
  // panel (in "fit", the polygon is fitted beside it when no corner is free), captioned
  // 'detail ×k'; a vector shorter than the rule there too is not drawn and said '≈ 0'.
  // Recomputed at every frame (a few dozen vertices: well under a millisecond).
  var laid = {};                      // the last layout of each polygon (for the tests)
  var PXMM = 96 / 25.4, RULE = window.polygonsInset(D.inset);
  var INSET_FONT = 11;                // the inset's labels, CSS px
  function chords(c, r, n) {
    var out = [], p = [];
    for (var i = 0; i <= n; i++) { p.push([c[0] + r * Math.cos(2 * Math.PI * i / n), c[1] + r * Math.sin(2 * Math.PI * i / n)]); }
    for (i = 0; i < n; i++) { out.push([p[i][0], p[i][1], p[i + 1][0], p[i + 1][1]]); }
    return out;
  }
  function clipCircle(a, b, c, r) {   // crowd.clip_to_circle
    var dx = b[0] - a[0], dy = b[1] - a[1], fx = a[0] - c[0], fy = a[1] - c[1];
    var A = dx * dx + dy * dy; if (A === 0) { return null; }
    var B = 2 * (fx * dx + fy * dy), Cc = fx * fx + fy * fy - r * r, disc = B * B - 4 * A * Cc;
    if (disc <= 0) { return null; }
    var s = Math.sqrt(disc), t0 = Math.max(0, (-B - s) / (2 * A)), t1 = Math.min(1, (-B + s) / (2 * A));
    if (t1 - t0 <= 1e-9) { return null; }
    return [[a[0] + t0 * dx, a[1] + t0 * dy], [a[0] + t1 * dx, a[1] + t1 * dy]];
  }
  // the panel's geometry at this frame: vertices (viewBox units and mm), the rule's plan
  function geometry(d, F, U) {
    var P = D.polys[d], s = U * PXMM, V = {}, mm = {};
    Object.keys(P.vx).forEach(function (v) {
      var p = P.vx[v][frame];
      if (p && p[0] !== null) { V[v] = F(p); mm[v] = [V[v][0] / s, V[v][1] / s]; }
    });
    var vecs = [];
    P.strokes.forEach(function (st) {
      if (st.k === 'arrow' && V[st.f] && V[st.t]) { vecs.push([st.f, st.t]); }
    });
    // the inset's largest radii: the static drawing's, within a quarter (a third, for a
    // vector's sake) of the panel's shorter side
    var root = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly').viewBox.baseVal;
    var side = Math.min(root.width, root.height) / s;
    var maxR = Math.min(D.inset.max_radius, 0.25 * side);
    var maxRV = Math.min(D.inset.max_radius_vectors, 0.33 * side);
    var plan = RULE.plan(mm, FONT / PXMM, vecs, maxR, maxRV);
    return {V: V, mm: mm, s: s, plan: plan, F: F, vecs: vecs, near: FONT / PXMM, maxR: maxR, maxRV: maxRV};
  }
  function insetBox(C, R, capH, capW) {
    var w = Math.max(2 * R, capW || 0);
    return {x: C[0] - w / 2, y: C[1] - R, w: w, h: 2 * R + capH};
  }
  function captionWidth(k, U) { return (0.62 * FONT * ('detail ×' + k).length + 4) * U; }
  // place every inset of g (viewBox units): a free corner or edge of the panel, else the
  // least crowded one; returns those that found no free place (layout puts them in a strip)
  function placeInsets(g, W, H, U, fixed) {
    var segs = [], pts = [], taken = fixed.slice(), bad = [], capH = 1.5 * FONT * U;
    g.strokes.forEach(function (s) { segs.push(s); });
    Object.keys(g.V).forEach(function (v) { pts.push(g.V[v]); });
    var ringBoxes = g.insets.map(function (i) {
      return {x: i.cv[0] - i.rv, y: i.cv[1] - i.rv, w: 2 * i.rv, h: 2 * i.rv};
    });
    g.insets.forEach(function (ins) {
      var R = ins.Rv, m = 3 * U, cw = captionWidth(ins.k, U), hw = Math.max(R, cw / 2), x0 = m + hw, x1 = W - m - hw, y0 = (FONT + 10) * U + R, y1 = H - 24 * U - FONT * U - R - capH;
      var cand = [[x1, y0], [x0, y1], [x1, y1], [x0, y0]];       // the corners, then the edges
      for (var f = 0.25; f < 1; f += 0.25) {
        cand.push([x0 + f * (x1 - x0), y1], [x1, y0 + f * (y1 - y0)], [x0 + f * (x1 - x0), y0],
                  [x0, y0 + f * (y1 - y0)]);
      }
      var best = null;
      cand.forEach(function (C) {
        if (x1 < x0 || y1 < y0) { return; }
        var b = insetBox(C, R, capH, cw), gb = {x: b.x - 2 * U, y: b.y - 2 * U, w: b.w + 4 * U, h: b.h + 4 * U};
        var score = 0;
        segs.forEach(function (s) { if (segHits(s, gb)) { score += 100; } });
        pts.forEach(function (p) { if (p[0] > gb.x && p[0] < gb.x + gb.w && p[1] > gb.y && p[1] < gb.y + gb.h) { score += 100; } });
        taken.concat(ringBoxes).forEach(function (t) { if (boxHits(t, gb)) { score += 1000; } });
        if (b.x < 0 || b.x + b.w > W || b.y < 0 || b.y + b.h > H) { score += 1e6; }
        if (best === null || score < best.score) { best = {score: score, C: C}; }
      });
      if (best === null) { best = {score: 1e9, C: [W / 2, H / 2]}; }
      ins.C = best.C;
      if (best.score > 0) { bad.push(ins); } else { taken.push(insetBox(ins.C, R, capH, cw)); }
    });
    return bad;
  }
  // the layout of one polygon at this frame: its transform, geometry and placed insets.
  // An inset finds a free corner or edge of the panel; in "fit", failing that, the polygon is
  // fitted beside a strip for them if it keeps 3/4 of its size; else the insets without a
  // place go in a strip added below the polygon (the panel grows: g.H)
  function layout(d, svg, U, fixed) {
    var W = svg.viewBox.baseVal.width, H = BASE[d], g = null, capH = 1.5 * FONT * U;
    function at(reserve) {
      var g = geometry(d, frameOf(d, reserve), U);
      g.strokes = [];
      D.polys[d].strokes.forEach(function (st) {
        var a = g.V[st.f], b = g.V[st.t];
        if (a && b) { g.strokes.push([a[0], a[1], b[0], b[1]]); }
      });
      g.insets = g.plan.insets.map(function (i) {
        return {names: i.names, k: i.k, c: i.c, r: i.r, R: i.R, cv: [i.c[0] * g.s, i.c[1] * g.s],
                rv: i.r * g.s, Rv: i.R * g.s};
      });
      g.bad = placeInsets(g, W, H, U, fixed);
      g.H = H;
      return g;
    }
    g = at(null);
    if (g.bad.length && zoom === 'auto') {
      var need = 0;
      g.bad.forEach(function (i) { need = Math.max(need, 2 * Math.max(i.Rv, captionWidth(i.k, U) / 2) + 8 * U); });
      var z0 = fitted(d, null), zr = fitted(d, {side: 'right', size: need});
      if (zr >= 0.75 * z0) {
        var h = at({side: 'right', size: need});
        if (!h.bad.length) { return h; }
      }
    }
    if (g.bad.length) {               // a strip below the polygon, above the scale bar
      var top = H - 20 * U, x = 3 * U, row = 0, rowH = 0;
      g.bad.forEach(function (ins) {
        var hw = Math.max(ins.Rv, captionWidth(ins.k, U) / 2);
        if (x + 2 * hw > W - 3 * U && x > 3 * U) { top += rowH; x = 3 * U; rowH = 0; }
        ins.C = [x + hw, top + ins.Rv + 4 * U];
        x += 2 * hw + 6 * U; rowH = Math.max(rowH, 2 * ins.Rv + capH + 8 * U);
      });
      g.H = top + rowH + 24 * U;
    }
    return g;
  }
  // the items of one inset: ring, circle, caption, enlarged strokes, vertices (labels later)
  function drawInset(svg, ins, g, d, U, look, segs, boxes, link) {
    var P = D.polys[d], C = ins.C, R = ins.Rv, k = ins.k;
    var show = function (p) { return [C[0] + k * (p[0] - ins.cv[0]), C[1] + k * (p[1] - ins.cv[1])]; };
    var grp = el(svg, 'g', {'class': 'inset', 'data-k': k});
    el(grp, 'circle', {cx: ins.cv[0], cy: ins.cv[1], r: ins.rv, fill: 'none', stroke: '#555',
                       'stroke-width': 0.8 * U, 'class': 'inset-ring'});
    el(grp, 'circle', {cx: C[0], cy: C[1], r: R, fill: '#fff', stroke: '#555',
                       'stroke-width': 0.8 * U, 'class': 'inset-frame'});
    var dj = Math.hypot(C[0] - ins.cv[0], C[1] - ins.cv[1]);
    if (dj > ins.rv + R + 4 * U) {    // the join, when it crosses no vector
      var ux = (C[0] - ins.cv[0]) / dj, uy = (C[1] - ins.cv[1]) / dj;
      var j = [ins.cv[0] + ux * ins.rv, ins.cv[1] + uy * ins.rv, C[0] - ux * R, C[1] - uy * R];
      var jb = function (s) {
        var o = function (p, q, r) { return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]); };
        var a = [j[0], j[1]], b = [j[2], j[3]], c = [s[0], s[1]], e = [s[2], s[3]];
        return (o(c, e, a) > 0) !== (o(c, e, b) > 0) && (o(a, b, c) > 0) !== (o(a, b, e) > 0);
      };
      if (!g.strokes.some(jb)) {
        el(grp, 'line', {x1: j[0], y1: j[1], x2: j[2], y2: j[3], stroke: '#888',
                         'stroke-width': 0.6 * U, 'class': 'inset-join'});
      }
    }
    var gone = {};
    g.plan.ghosts.forEach(function (v) { gone[v[0] + '\u0000' + v[1]] = true; });
    P.strokes.forEach(function (st) {
      var a = g.V[st.f], b = g.V[st.t];
      if (!a || !b || (st.k === 'arrow' && gone[st.f + '\u0000' + st.t])) { return; }
      var ta = show(a), tb = show(b), seg = clipCircle(ta, tb, C, R);
      if (!seg) { return; }
      var lk = look(st), tipIn = st.k === 'arrow' && Math.hypot(tb[0] - C[0], tb[1] - C[1]) <= R + 1e-9;
      var whole = tipIn && Math.hypot(seg[0][0] - ta[0], seg[0][1] - ta[1]) < 1e-6 * R;
      // a vector of another ring, whole here but under the rule: its own inset shows it
      if (whole && Math.hypot(tb[0] - ta[0], tb[1] - ta[1]) < D.inset.min_mm * g.s) { return; }
      if (!tipIn) { lk = {colour: lk.colour, width: lk.width, dash: lk.dash, open: lk.open, head: false}; }
      var on = link !== null && st.link === link, e = tipIn ? tb : seg[1];
      if (on) {                       // the hovered link's vectors, as on the polygon
        el(grp, 'line', {x1: seg[0][0], y1: seg[0][1], x2: e[0], y2: e[1], stroke: '#F0E442',
                         'stroke-width': 9 * U, 'stroke-linecap': 'round', 'class': 'halo'});
      }
      segs.push(arrow(grp, seg[0], e, lk, U, 'inset-vector ' + st.c + (on ? ' hi' : ''),
                      {'data-from': st.f, 'data-to': st.t, 'data-kind': st.c, 'data-k': st.k,
                       'data-whole': whole ? 1 : 0}));
    });
    chords(C, R, 24).forEach(function (s) { segs.push(s); });
    var groups = [];
    Object.keys(g.V).forEach(function (v) {
      if (Math.hypot(g.mm[v][0] - ins.c[0], g.mm[v][1] - ins.c[1]) > ins.r) { return; }
      var q = show(g.V[v]), name = v === P.pole ? P.pole_label : P.names[v];
      el(grp, 'circle', {cx: q[0], cy: q[1], r: (v === P.pole ? 2.5 : 1.6) * U,
                         fill: v === P.pole ? '#fff' : '#000', stroke: '#000', 'stroke-width': U,
                         'class': 'inset-vertex'});
      boxes.push({x: q[0] - 2 * U, y: q[1] - 2 * U, w: 4 * U, h: 4 * U});
      var gr = groups.filter(function (gr) { return Math.hypot(gr.at[0] - q[0], gr.at[1] - q[1]) < 0.6 * g.s; })[0];
      if (gr) { if (v === P.pole) { gr.names.unshift(name); } else { gr.names.push(name); } }
      else { groups.push({at: q, names: [name], first: v}); }
    });
    var cap = el(grp, 'text', {x: C[0], y: C[1] + R + 1.2 * FONT * U, 'font-size': FONT * U,
                               'text-anchor': 'middle', 'class': 'inset-caption'});
    cap.textContent = 'detail ×' + k;
    var cb = cap.getBBox();
    boxes.push({x: cb.x - U, y: cb.y - U, w: cb.width + 2 * U, h: cb.height + 2 * U});
    ins.groups = groups; ins.grp = grp;
  }
  function polygon(d) {
    var P = D.polys[d], svg = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly');
    var W = svg.viewBox.baseVal.width, H = BASE[d];
    svg.setAttribute('viewBox', '0 0 ' + W + ' ' + H);
    var U = unitOf(svg);
    var segs = [], boxes = [], link = hover >= 0 ? D.edges[hover][2] : null;
    clear(svg);
    var cap = el(svg, 'text', {x: 4 * U, y: 4 * U + FONT * U, 'font-size': FONT * U, 'class': 'cap'});
    var fixedBoxes = [];
    var capBox = function () { return {x: 0, y: 0, w: cap.getBBox().width + 8 * U, h: (FONT + 8) * U}; };
    cap.textContent = d + ' polygon' + (zoom === 'auto' ? ' (fitted here)' : '');
    fixedBoxes.push(capBox());
    fixedBoxes.push({x: 0, y: H - 16 * U - FONT * U, w: W / 2, h: H});   // the scale bar's place
    if (P.vx[P.pole][frame] === null) {
      var t = el(svg, 'text', {x: W / 2, y: H / 2, 'font-size': FONT * U, 'text-anchor': 'middle'});
      t.textContent = 'undefined at this position (a toggle)';
      return;
    }
    var g = layout(d, svg, U, fixedBoxes), notes = [];
    var said = function (g) {         // the notes: off the scale; vectors too short for any inset
      var out = P.off.indexOf(frame) >= 0 ? ['beyond the scale here: near a toggle'] : [], small = [];
      var nm = function (x) { return P.names[x]; };
      g.plan.ghosts.forEach(function (v) {
        var L = Math.hypot(g.mm[v[0]][0] - g.mm[v[1]][0], g.mm[v[0]][1] - g.mm[v[1]][1]);
        if (L >= 0.005 && small.indexOf(nm(v[0]) + nm(v[1])) < 0) { small.push(nm(v[0]) + nm(v[1])); }
      });
      if (small.length) { out.push(small.join(', ') + ' ≈ 0 here (not drawn)'); }
      var o = g.mm[P.pole];
      if (o && Object.keys(g.mm).every(function (v) {
        return Math.hypot(g.mm[v][0] - o[0], g.mm[v][1] - o[1]) < D.inset.same; })) {
        out.push('every ' + d + ' is zero here');
      }
      return out;
    };
    notes = said(g);
    if (notes.length) {               // the notes' place kept clear of insets, then laid out again
      fixedBoxes.push({x: 0, y: 0, w: W, h: (10 + 1.3 * FONT * (notes.length + 1)) * U});
      g = layout(d, svg, U, fixedBoxes);
      notes = said(g);
    }
    if (g.H !== H) { H = g.H; svg.setAttribute('viewBox', '0 0 ' + W + ' ' + H); }
    var F = g.F, z = zoom === 'auto' ? F.z : zoom;
    if (zoom !== 'auto' && z > 1) { cap.textContent += ' (×' + z + ')'; }
    boxes.push(capBox());
    // the scale bar: one scale for the whole cycle
    if (P.bar) {
      var bar = z === 1 ? P.bar : nice(P.bar / z);
      var bl = bar * F.k, by = H - 10 * U;
      el(svg, 'path', {d: 'M' + 6 * U + ' ' + (by - 4 * U) + 'v' + 4 * U + 'h' + bl + 'v' + (-4 * U),
                       stroke: '#000', fill: 'none', 'stroke-width': U, 'class': 'bar'});
      var bt = el(svg, 'text', {x: 10 * U + bl, y: by + 2 * U, 'font-size': FONT * U, 'class': 'bar'});
      bt.textContent = bar + ' ' + P.unit;
      boxes.push({x: 0, y: by - 6 * U - FONT * U, w: 16 * U + bl + bt.getBBox().width, h: H});
    }
    notes.forEach(function (text, i) { note(svg, text, U, boxes, i); });
    var gone = {};
    g.plan.ghosts.forEach(function (v) { gone[v[0] + '\u0000' + v[1]] = true; });
    var V = function (v) { return g.V[v] || null; };
    var lookOf = function (st) {
      var look = LOOK[st.c];
      return st.k === 'side' ? {colour: look.colour, width: look.width, dash: look.dash, head: false} : look;
    };
    P.strokes.forEach(function (s, i) {
      var a = V(s.f), b = V(s.t); if (!a || !b) { return; }
      if (s.k === 'arrow' && gone[s.f + '\u0000' + s.t]) { return; }     // ≈ 0: said, not drawn
      var on = link !== null && s.link === link;
      if (on) {
        el(svg, 'line', {x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: '#F0E442',
                         'stroke-width': 9 * U, 'stroke-linecap': 'round', 'class': 'halo'});
      }
      segs.push(arrow(svg, a, b, lookOf(s), U, 'comp ' + s.c + (on ? ' hi' : ''),
                      {'data-from': s.f, 'data-to': s.t, 'data-kind': s.c, 'data-k': s.k}));
    });
    var pole = V(P.pole);
    el(svg, 'circle', {cx: pole[0], cy: pole[1], r: 3 * U, fill: '#fff', stroke: '#000',
                       'stroke-width': 1.2 * U});
    // the insets: ring, circle (white), enlarged strokes and vertices; their labels last
    var inRing = {};
    g.insets.forEach(function (ins) {
      chords(ins.cv, ins.rv, 16).forEach(function (s) { segs.push(s); });
      Object.keys(g.V).forEach(function (v) {
        if (Math.hypot(g.mm[v][0] - ins.c[0], g.mm[v][1] - ins.c[1]) <= ins.r) { inRing[v] = true; }
      });
    });
    g.insets.forEach(function (ins) {
      ins.box = insetBox(ins.C, ins.Rv, 0);           // kept clear by the polygon's labels
      boxes.push(ins.box);
      drawInset(svg, ins, g, d, U, lookOf, segs, boxes, link);
    });
    var groups = [];
    Object.keys(P.vx).forEach(function (v) {
      var q = V(v); if (!q || inRing[v]) { return; }                  // (labelled in its inset)
      var gr = groups.filter(function (gr) { return Math.hypot(gr.at[0] - q[0], gr.at[1] - q[1]) < 2 * U; })[0];
      var name = v === P.pole ? P.pole_label : P.names[v];
      if (gr) { if (v === P.pole) { gr.names.unshift(name); } else { gr.names.push(name); } }
      else { groups.push({at: q, names: [name], first: v}); }
    });
    groups.forEach(function (gr) {   // (zoomed in, a vertex may lie beyond the panel)
      if (gr.at[0] < 0 || gr.at[0] > W || gr.at[1] < 0 || gr.at[1] > H) { return; }
      label(svg, gr.names.join(' = '), gr.at, segs, boxes, U, {'data-label': gr.first, 'class': 'vx'});
    });
    g.insets.forEach(function (ins) {
      ins.groups.forEach(function (gr) {
        label(ins.grp, gr.names.join(' = '), gr.at, segs, boxes, U,
              {'data-label': gr.first, 'class': 'vx inset-label'}, {c: ins.C, r: ins.Rv, font: INSET_FONT, box: ins.box});
      });
    });
    laid[d] = {mm: g.mm, near: g.near, max_radius: g.maxR, max_radius_vectors: g.maxRV,
               vectors: g.vecs, drawn: g.plan.drawn, ghosts: g.plan.ghosts,
               insets: g.insets.map(function (i) { return {names: i.names, c: i.c, r: i.r, k: i.k, R: i.R}; })};
  }
  function note(svg, text, U, boxes, i) {  // under the caption, top left
    var t = el(svg, 'text', {x: 4 * U, y: 8 * U + (2 + 1.3 * (i || 0)) * FONT * U, 'font-size': FONT * U,
                             'class': 'off', fill: '#882255'});
    t.textContent = text;
    var W = svg.viewBox.baseVal.width;
    if (t.getBBox().width > W - 8 * U && /, /.test(text)) {   // a long list: its first names, and how many more
      var parts = text.split(' ≈ ')[0].split(', '), tail = ' ≈ ' + text.split(' ≈ ').slice(1).join(' ≈ ');
      for (var n = parts.length - 1; n >= 1; n--) {
        t.textContent = parts.slice(0, n).join(', ') + ' +' + (parts.length - n) + tail;
        if (t.getBBox().width <= W - 8 * U) { break; }
      }
    }
    var b = t.getBBox(); boxes.push({x: b.x - 2 * U, y: b.y - 2 * U, w: b.width + 4 * U, h: b.height + 4 * U});
    return t;
  }
  function setHover(i) { hover = i; draw(); }
  function setZoom(z) { zoom = z === 'auto' ? 'auto' : [1, 2, 4, 8].indexOf(+z) >= 0 ? +z : 1;
                        document.getElementById('zoom').value = String(zoom); draw(); }
  document.getElementById('zoom').addEventListener('change', function (e) { setZoom(e.target.value); });
  function draw() {
    mechanism();
    Object.keys(D.polys).forEach(polygon);
    document.getElementById('angle-out').textContent =
      D.inputs[frame] + ' ' + D.unit + (D.sense ? ' (crank turns ' + D.sense + ')' : '') +
      (frame === D.start ? ' — the position of the drawings' : '');
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
    var t = e.target;
    if (/^(SELECT|INPUT|TEXTAREA|BUTTON)$/.test(t.tagName) && t.id !== 'back' && t.id !== 'next') { return; }
    if (t.closest && t.closest('#draw')) { return; }
    if (e.key === 'ArrowRight') { showStage(cur + 1); }
    if (e.key === 'ArrowLeft') { showStage(cur - 1); }
  });
  var resizing = null;
  window.addEventListener('resize', function () {
    clearTimeout(resizing); resizing = setTimeout(draw, 100);
  });
  var h = {};
  location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
    var p = kv.split('='); if (p.length === 2) { h[p[0]] = p[1]; }
  });
  showStage(h.stage ? (+h.stage || 1) - 1 : 0);
  setFrame(h.frame !== undefined && !isNaN(+h.frame) ? +h.frame : D.start);
  window.polygonsPage = {
    stage: function () { return stages[cur].dataset.name; },
    stages: stages.length, next: function () { showStage(cur + 1); },
    back: function () { showStage(cur - 1); }, frame: function () { return frame; },
    setFrame: setFrame, hover: setHover, zoom: setZoom, draw: draw,
    // the rule's inputs and insets of polygon d as last drawn (mm, y down)
    insets: function (d) { return laid[d] || null; }
  };
})();
