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
  function label(svg, text, at, segs, boxes, U, attrs) {
    var W = svg.viewBox.baseVal.width, H = svg.viewBox.baseVal.height;
    var fs = FONT * U, t = el(svg, 'text', attrs || {});
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
    [0.35, 0.8, 1.5, 2.4].forEach(function (k) {
      for (var j = 0; j < 16; j++) {
        var ang = -Math.PI / 4 + j * Math.PI / 8, ux = Math.cos(ang), uy = Math.sin(ang);
        var d = k * fs + 0.5 * Math.abs(ux) * w + 0.5 * Math.abs(uy) * h;
        var r = {x: at[0] + ux * d - w / 2, y: at[1] + uy * d - h / 2, w: w, h: h};
        var g = {x: r.x - pad, y: r.y - pad, w: r.w + 2 * pad, h: r.h + 2 * pad};
        var out = r.x < 2 * U || r.y < 2 * U || r.x + w > W - 2 * U || r.y + h > H - 2 * U;
        var score = (out ? 1e6 : 0) + k;
        segs.forEach(function (s) { if (segHits(s, g)) { score += 100; } });
        boxes.forEach(function (b) { if (boxHits(b, g)) { score += 1000; } });
        if (best === null || score < best.score) { best = {score: score, r: r}; }
      }
    });
    t.setAttribute('x', best.r.x - bb.x); t.setAttribute('y', best.r.y - bb.y);
    (lines || []).forEach(function (s) { s.setAttribute('x', best.r.x - bb.x); });
    boxes.push(best.r);
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
  var T = {};
  ['velocity', 'acceleration'].forEach(function (d) {     // a scene may solve velocity only
    if (!D.polys[d]) { document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly').style.display = 'none'; }
  });
  Object.keys(D.polys).forEach(function (d) {
    var P = D.polys[d], svg = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly');
    var b = P.box, W = svg.viewBox.baseVal.width;
    var w = Math.max(b[2] - b[0], 1e-12), hh = Math.max(b[3] - b[1], 1e-12);
    var H = Math.round(Math.max(170, Math.min(380, (W - 60) * hh / w + 86)));
    svg.setAttribute('viewBox', '0 0 ' + W + ' ' + H);      // the panel takes the cycle's shape
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
  function room(d) {
    var svg = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly');
    var W = svg.viewBox.baseVal.width, H = svg.viewBox.baseVal.height;
    return [30, 34 + FONT, W - 30, H - 56];        // below the caption, above the bar
  }
  function fitted(d) {                // the enlargement over × 1 that fits this position
    var pts = at(d, frame), F = T[d], r = room(d);
    if (pts.length < 2) { return 1; }
    var b = box(pts), w = (b[2] - b[0]) * F.k, h = (b[3] - b[1]) * F.k;
    var z = Math.min((r[2] - r[0]) / Math.max(w, 1e-9), (r[3] - r[1]) / Math.max(h, 1e-9));
    return isFinite(z) && z > 0 ? Math.min(z, 1e6) : 1;
  }
  function zoomOf(d) { return zoom === 'auto' ? fitted(d) : zoom; }
  function frameOf(d) {
    if (zoom !== 'auto') { return zoomed(T[d], zoom); }
    var F = T[d], z = fitted(d), r = room(d), b = box(at(d, frame));
    var c = F([(b[0] + b[2]) / 2, (b[1] + b[3]) / 2]), m = [(r[0] + r[2]) / 2, (r[1] + r[3]) / 2];
    var g = function (p) { var q = F(p); return [m[0] + z * (q[0] - c[0]), m[1] + z * (q[1] - c[1])]; };
    g.k = F.k * z; return g;
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
    g.k = F.k * z; return g;
  }
  function polygon(d) {
    var P = D.polys[d], svg = document.getElementById(d === 'velocity' ? 'vpoly' : 'apoly');
    var z = zoomOf(d), U = unitOf(svg), F = frameOf(d), W = svg.viewBox.baseVal.width, H = svg.viewBox.baseVal.height;
    var segs = [], boxes = [], link = hover >= 0 ? D.edges[hover][2] : null;
    clear(svg);
    var cap = el(svg, 'text', {x: 4 * U, y: 4 * U + FONT * U, 'font-size': FONT * U, 'class': 'cap'});
    cap.textContent = d + ' polygon' + (zoom === 'auto' ? ' (fitted here)' : z > 1 ? ' (×' + z + ')' : '');
    boxes.push({x: 0, y: 0, w: cap.getBBox().width + 8 * U, h: (FONT + 8) * U});
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
    if (P.off.indexOf(frame) >= 0) { note(svg, 'beyond the scale here: near a toggle', U, boxes); }
    var V = function (v) { var p = P.vx[v] ? P.vx[v][frame] : null; return p && p[0] !== null ? F(p) : null; };
    if (P.vx[P.pole][frame] === null) {
      var t = el(svg, 'text', {x: W / 2, y: H / 2, 'font-size': FONT * U, 'text-anchor': 'middle'});
      t.textContent = 'undefined at this position (a toggle)';
      return;
    }
    P.strokes.forEach(function (s, i) {
      var a = V(s.f), b = V(s.t); if (!a || !b) { return; }
      var on = link !== null && s.link === link;
      if (on) {
        el(svg, 'line', {x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: '#F0E442',
                         'stroke-width': 9 * U, 'stroke-linecap': 'round', 'class': 'halo'});
      }
      var look = LOOK[s.c];
      if (s.k === 'side') { look = {colour: look.colour, width: look.width, dash: look.dash, head: false}; }
      segs.push(arrow(svg, a, b, look, U, 'comp ' + s.c + (on ? ' hi' : ''),
                      {'data-from': s.f, 'data-to': s.t, 'data-kind': s.c}));
    });
    var groups = [];
    Object.keys(P.vx).forEach(function (v) {
      var q = V(v); if (!q) { return; }
      var g = groups.filter(function (g) { return Math.hypot(g.at[0] - q[0], g.at[1] - q[1]) < 2 * U; })[0];
      var name = v === P.pole ? P.pole_label : P.names[v];
      if (g) { if (v === P.pole) { g.names.unshift(name); } else { g.names.push(name); } }
      else { groups.push({at: q, names: [name], first: v}); }
    });
    var pole = V(P.pole);
    el(svg, 'circle', {cx: pole[0], cy: pole[1], r: 3 * U, fill: '#fff', stroke: '#000',
                       'stroke-width': 1.2 * U});
    groups.forEach(function (g) {     // (zoomed in, a vertex may lie beyond the panel)
      if (g.at[0] < 0 || g.at[0] > W || g.at[1] < 0 || g.at[1] > H) { return; }
      label(svg, g.names.join(' = '), g.at, segs, boxes, U, {'data-label': g.first, 'class': 'vx'});
    });
  }
  function note(svg, text, U, boxes) {  // under the caption, top left
    var t = el(svg, 'text', {x: 4 * U, y: 8 * U + 2 * FONT * U, 'font-size': FONT * U, 'class': 'off',
                             fill: '#882255'});
    t.textContent = text;
    var b = t.getBBox(); boxes.push({x: b.x - 2 * U, y: b.y - 2 * U, w: b.width + 4 * U, h: b.height + 4 * U});
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
    setFrame: setFrame, hover: setHover, zoom: setZoom, draw: draw
  };
})();
