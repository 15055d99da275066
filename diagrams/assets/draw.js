// "Draw it yourself": place a polygon's vertices with the mouse or the keyboard alone, save the
// drawing as JSON (for `polygons check SCENE --drawing FILE`) or as SVG (diagrams/page.py).
(function () {
  'use strict';
  var K = window.polygonsKit, D = K.data, el = K.el;
  var STEP = 1, BIG = 10, SNAP = 0.5;            // mm: arrow key, Shift+arrow, mouse
  var root = document.getElementById('draw'), paper = document.getElementById('paper');
  var pick = document.getElementById('draw-diagram'), list = document.getElementById('draw-vertices');
  var status = document.getElementById('draw-status'), scaleOut = document.getElementById('draw-scale');
  var looks = {};
  Object.keys(D.polys).forEach(function (d) { D.polys[d].key.forEach(function (k) { looks[k.kind] = k; }); });
  var state = {};                                // diagram → {placed, sel, cursor, graded}
  var gradeOut = document.getElementById('draw-grade');
  var WRONG = '#C00000';                         // a wrong vector, once graded
  var d = null;

  function S() { return state[d]; }
  function G() { return D.drawing[d]; }
  function xml(s) {
    return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;')
      .replace(/"/g, '&quot;').replace(/'/g, '&#39;');
  }
  function fmt(x) { return String(Math.round(x * 100) / 100); }
  function say(text) { status.textContent = text; }
  function kindOf(f, t) {
    var s = D.polys[d].strokes.filter(function (s) { return s.f === f && s.t === t; })[0];
    return s ? s.c : 'resultant';
  }
  function choose(name) {
    d = name; pick.value = name;
    if (!state[d]) { state[d] = {placed: {}, sel: 0, cursor: G().cursor.slice(), graded: null}; }
    showGrade(state[d].graded);
    var P = G().paper;
    paper.setAttribute('viewBox', '0 0 ' + P[0] + ' ' + P[1]);
    paper.setAttribute('width', P[0] + 'mm'); paper.setAttribute('height', P[1] + 'mm');
    scaleOut.textContent = 'Scale ' + G().statement + ' (' + G().scale.replace('^2', '²') +
                           '). Grid: 5 mm.';
    buttons(); render();
  }
  function buttons() {
    K.clear(list);
    G().vertices.forEach(function (v, i) {
      var b = document.createElement('button');
      b.type = 'button'; b.className = 'vx-pick'; b.dataset.v = v;
      b.textContent = G().labels[v];
      b.setAttribute('aria-pressed', i === S().sel ? 'true' : 'false');
      b.setAttribute('aria-label', 'vertex ' + G().labels[v] +
                     (S().placed[v] ? ', placed' : ', not placed'));
      if (S().placed[v]) { b.classList.add('placed'); }
      b.addEventListener('click', function () { select(i); paper.focus(); });
      list.appendChild(b);
    });
  }
  function select(i) {
    var n = G().vertices.length;
    S().sel = ((i % n) + n) % n;
    var v = G().vertices[S().sel], p = S().placed[v];
    if (p) { S().cursor = p.slice(); }
    say('Selected ' + G().labels[v] + (p ? ' (placed at ' + fmt(p[0]) + ', ' + fmt(p[1]) + ' mm)' : '') +
        '. Cursor at ' + fmt(S().cursor[0]) + ', ' + fmt(S().cursor[1]) + ' mm.');
    buttons(); render();
  }
  function place() {
    var v = G().vertices[S().sel];
    S().placed[v] = S().cursor.slice();
    var msg = G().labels[v] + ' placed at ' + fmt(S().cursor[0]) + ', ' + fmt(S().cursor[1]) + ' mm';
    var order = G().vertices, next = -1;
    for (var k = 1; k <= order.length; k++) {
      var j = (S().sel + k) % order.length;
      if (!S().placed[order[j]]) { next = j; break; }
    }
    if (next >= 0) { S().sel = next; msg += '; next: ' + G().labels[order[next]]; }
    else { msg += '; every vertex is placed: save the drawing'; }
    if (S().graded) { gradeNow(); }
    say(msg + '.'); buttons(); render();
  }
  function move(dx, dy) {
    var P = G().paper, c = S().cursor;
    c[0] = Math.max(0, Math.min(P[0], Math.round((c[0] + dx) * 100) / 100));
    c[1] = Math.max(0, Math.min(P[1], Math.round((c[1] + dy) * 100) / 100));
    say('Cursor at ' + fmt(c[0]) + ', ' + fmt(c[1]) + ' mm.'); render();
  }
  function vectors() {
    var P = S().placed;
    return G().vectors.filter(function (v) { return P[v[0]] && P[v[1]]; });
  }
  // paper mm, y up → SVG user units (mm), y down
  function Y(p) { return [p[0], G().paper[1] - p[1]]; }
  function render() {
    var U = K.unitOf(paper), W = G().paper[0], H = G().paper[1], segs = [], boxes = [];
    var px = 25.4 / 96;                          // mm per CSS px at 100 %
    K.clear(paper);
    el(paper, 'rect', {x: 0, y: 0, width: W, height: H, fill: '#fff'});
    var minor = [], major = [];
    for (var x = 5; x < W; x += 5) { (x % 10 ? minor : major).push('M' + x + ' 0V' + H); }
    for (var y = 5; y < H; y += 5) { (y % 10 ? minor : major).push('M0 ' + (H - y) + 'H' + W); }
    el(paper, 'path', {d: minor.join(''), stroke: '#e3e3e3', 'stroke-width': 0.15, fill: 'none'});
    el(paper, 'path', {d: major.join(''), stroke: '#c4c4c4', 'stroke-width': 0.25, fill: 'none'});
    var sc = el(paper, 'text', {x: 2, y: H - 2, 'font-size': 3.2, 'class': 'scale'});
    sc.textContent = 'Scale ' + G().statement;
    boxes.push({x: 0, y: H - 6, w: 4 + 1.9 * sc.textContent.length, h: 6});
    vectors().forEach(function (v) {
      var a = Y(S().placed[v[0]]), b = Y(S().placed[v[1]]);
      var lk = looks[kindOf(v[0], v[1])] || {colour: '#000', width: 0.5, dash: null};
      var bad = wrongOf(v[0], v[1]);
      var look = {colour: bad ? WRONG : lk.colour, width: lk.width, dash: lk.dash, open: lk.open};
      var attrs = {'data-from': v[0], 'data-to': v[1]};
      if (bad) { attrs['data-wrong'] = bad; }
      segs.push(K.arrow(paper, a, b, look, px, 'dv' + (bad ? ' wrong' : ''), attrs));
    });
    var names = Object.keys(S().placed);
    names.forEach(function (v) {
      var q = Y(S().placed[v]);
      el(paper, 'circle', {cx: q[0], cy: q[1], r: 0.9, fill: '#000', 'data-vertex': v});
      boxes.push({x: q[0] - 1, y: q[1] - 1, w: 2, h: 2});
    });
    names.forEach(function (v) {
      K.label(paper, G().labels[v], Y(S().placed[v]), segs, boxes, px, {'class': 'dl', 'data-v': v});
    });
    var c = Y(S().cursor), sel = G().vertices[S().sel];
    var g = el(paper, 'g', {'class': 'cursor', 'aria-hidden': 'true'});
    el(g, 'circle', {cx: c[0], cy: c[1], r: 2.2, fill: 'none', stroke: '#D55E00', 'stroke-width': 0.35});
    el(g, 'path', {d: 'M' + (c[0] - 4) + ' ' + c[1] + 'h8M' + c[0] + ' ' + (c[1] - 4) + 'v8',
                   stroke: '#D55E00', 'stroke-width': 0.3});
    var t = el(g, 'text', {x: c[0] + 2.8, y: c[1] - 2.8, 'font-size': 3.4, fill: '#D55E00'});
    t.textContent = G().labels[sel] + '?';
    paper.setAttribute('aria-label', 'Drawing paper for the ' + d + ' polygon, ' + W + ' by ' + H +
                       ' mm, scale ' + G().statement + '. Placing ' + G().labels[sel] +
                       '; cursor at ' + fmt(S().cursor[0]) + ', ' + fmt(S().cursor[1]) + ' mm.');
  }
  // ---- grading in the page: grade.js on the rules of `polygons check --drawing`
  function wrongOf(f, t) {
    var g = S().graded;
    if (!g) { return null; }
    var m = g.vectors.concat(g.extras).filter(function (m) {
      return m.mark < 1 && (m.vector === f + t || m.vector === t + f);
    })[0];
    return m ? (m.problem || 'wrong') : null;
  }
  function gradeNow() {
    var j = json();
    var drawing = {diagram: d, scale: G().si_per_mm, scale_text: G().scale,
                   vertices: j.vertices, vectors: j.vectors};
    S().graded = window.polygonsGrade.grade(G().rules, drawing);
    showGrade(S().graded);
    return S().graded;
  }
  function showGrade(g) {
    K.clear(gradeOut);
    if (!g) { return; }
    var h = document.createElement('p');
    h.className = 'grade-total';
    h.textContent = g.score + ' of ' + g.out_of + ' vectors' + (g.all_ok ? ' — all right' : '') +
      ' (the rules of polygons check: a line is graded by its direction through your own ' +
      'vertices; a known vector by its direction and its length at ' + G().statement + ')';
    gradeOut.appendChild(h);
    var ul = document.createElement('ul');
    ul.className = 'grade-list';
    g.vectors.forEach(function (m) {
      var li = document.createElement('li');
      li.dataset.vector = m.vector;
      li.dataset.mark = String(m.mark);
      li.className = m.mark === 1 ? 'ok' : (m.mark === 0.5 ? 'half' : 'off');
      var v = document.createElement('b');
      v.textContent = (m.mark === 1 ? '✓ ' : (m.mark === 0.5 ? '½ ' : '✗ ')) + m.shown;
      li.appendChild(v);
      li.appendChild(document.createTextNode(' ' + m.rule + (m.problem ? ': ' + m.problem : '')));
      [m.note, m.mark < 1 ? m.hint : ''].forEach(function (t) {
        if (t) { var p = document.createElement('div'); p.className = 'grade-hint'; p.textContent = t; li.appendChild(p); }
      });
      ul.appendChild(li);
    });
    g.closures.forEach(function (c) {
      if (c.ok) { return; }
      var li = document.createElement('li'); li.className = 'off';
      li.textContent = '✗ closure: ' + c.hint; ul.appendChild(li);
    });
    if (g.unknown_vertices.length) {
      var li = document.createElement('li'); li.className = 'off';
      li.textContent = 'not graded: vertices ' + g.unknown_vertices.join(', ');
      ul.appendChild(li);
    }
    gradeOut.appendChild(ul);
  }
  function json() {
    var out = {diagram: d, scale: G().scale, vertices: {}, vectors: vectors()};
    G().vertices.forEach(function (v) {
      var p = S().placed[v]; if (p) { out.vertices[v] = [+fmt(p[0]), +fmt(p[1])]; }
    });
    return out;
  }
  function svgText() {
    var W = G().paper[0], H = G().paper[1], title = D.title + ' — ' + d + ' polygon (drawn)';
    var body = paper.innerHTML;
    return '<?xml version="1.0" encoding="utf-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" ' +
      'data-polygons-drawing="' + xml(d) + '" data-scale="' + xml(G().scale) + '" ' +
      'width="' + W + 'mm" height="' + H + 'mm" viewBox="0 0 ' + W + ' ' + H + '" ' +
      'font-family="DejaVu Sans, Verdana, Arial, sans-serif">\n<title>' + xml(title) + '</title>\n' +
      '<desc>' + xml('Scale ' + G().statement + '; vertices: ' + Object.keys(S().placed).map(function (v) {
        return G().labels[v] + ' (' + fmt(S().placed[v][0]) + ', ' + fmt(S().placed[v][1]) + ') mm';
      }).join(', ')) + '</desc>\n' + body.replace(/<g class="cursor"[\s\S]*?<\/g>/, '') + '\n</svg>\n';
  }
  function save(text, type, ext) {
    var a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], {type: type}));
    a.download = D.file + '-' + d + '-drawing.' + ext;
    document.body.appendChild(a); a.click();
    setTimeout(function () { URL.revokeObjectURL(a.href); a.remove(); }, 0);
    say('Saved ' + a.download + '.');
  }
  paper.addEventListener('keydown', function (e) {
    var step = e.shiftKey ? BIG : STEP, done = true;
    switch (e.key) {
      case 'ArrowLeft': move(-step, 0); break;
      case 'ArrowRight': move(step, 0); break;
      case 'ArrowUp': move(0, step); break;
      case 'ArrowDown': move(0, -step); break;
      case 'Enter': case ' ': place(); break;
      case 'n': case ']': select(S().sel + 1); break;
      case 'p': case '[': select(S().sel - 1); break;
      case 'Delete': case 'Backspace':
        delete S().placed[G().vertices[S().sel]];
        if (S().graded) { gradeNow(); }
        say(G().labels[G().vertices[S().sel]] + ' removed.'); buttons(); render(); break;
      default: done = false;
    }
    if (done) { e.preventDefault(); e.stopPropagation(); }
  });
  paper.addEventListener('click', function (e) {
    var m = paper.getScreenCTM(); if (!m) { return; }
    var pt = paper.createSVGPoint(); pt.x = e.clientX; pt.y = e.clientY;
    var q = pt.matrixTransform(m.inverse());
    S().cursor = [Math.round(q.x / SNAP) * SNAP, Math.round((G().paper[1] - q.y) / SNAP) * SNAP];
    paper.focus(); place();
  });
  pick.addEventListener('change', function () { choose(pick.value); });
  document.getElementById('save-json').addEventListener('click', function () {
    save(JSON.stringify(json(), null, 1) + '\n', 'application/json', 'json');
  });
  document.getElementById('save-svg').addEventListener('click', function () {
    save(svgText(), 'image/svg+xml', 'svg');
  });
  document.getElementById('draw-clear').addEventListener('click', function () {
    state[d] = null; choose(d); showGrade(null); say('Cleared.');
  });
  document.getElementById('draw-check').addEventListener('click', function () {
    var g = gradeNow(); render();
    say('Graded: ' + g.score + ' of ' + g.out_of + ' vectors' + (g.all_ok ? ', all right.' : '; see below.'));
  });
  if (!D.diagrams.length) { root.hidden = true; return; }
  choose(D.diagrams[0]);
  window.polygonsDrawing = {json: json, svg: svgText, diagram: function () { return d; },
                            // a script places a vertex (mm, y up) and grades as the button does
                            set: function (v, p) { S().placed[v] = p.slice(); buttons(); render(); },
                            choose: function (name) { choose(name); },
                            check: function () { var g = gradeNow(); render(); return g; },
                            cursor: function () { return S().cursor.slice(); },
                            selected: function () { return G().vertices[S().sel]; }};
})();
