// Grade a drawn polygon in the browser: the rules of polygons/grade_drawing.py (grade_rules),
// line for line, on the same data (rules(): the page carries it as D.drawing[d].rules).
// The result is the data polygons.cli._drawing.grade_json gives, field for field; the tests
// hold the two equal on the corpus of typical errors (tests/data/drawings).
(function () {
  'use strict';

  function fixed(x, d) { return x.toFixed(d); }
  // Python's format(x, '.Ng'): N significant figures, trailing zeros dropped
  function gfmt(x, p) {
    if (x === 0) { return '0'; }
    if (!isFinite(x)) { return String(x); }
    var e = Math.floor(Math.log10(Math.abs(x)));
    var t = x.toExponential(p - 1), m = /e([-+]\d+)$/.exec(t);
    e = parseInt(m[1], 10);                      // the exponent after rounding
    var s;
    if (e < -4 || e >= p) {
      var mant = t.slice(0, m.index);
      if (mant.indexOf('.') >= 0) { mant = mant.replace(/0+$/, '').replace(/\.$/, ''); }
      s = mant + 'e' + (e < 0 ? '-' : '+') + (Math.abs(e) < 10 ? '0' : '') + Math.abs(e);
    } else {
      s = x.toFixed(Math.max(0, p - 1 - e));
      if (s.indexOf('.') >= 0) { s = s.replace(/0+$/, '').replace(/\.$/, ''); }
    }
    return s;
  }
  function within(x, tol, d) {
    return parseFloat(Math.abs(x).toFixed(d)) <= parseFloat(tol.toFixed(d));
  }
  function deg(r) { return r * 180 / Math.PI; }
  function angle(u, v) {
    return deg(Math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]));
  }
  function heading(v) {
    var h = deg(Math.atan2(v[1], v[0]));
    return h < 0 ? h + 360 : h;
  }
  function hypot(x, y) { return Math.hypot(x, y); }
  function directionTol(R, e, drawnMm) {
    var c = R.constants, tol = c.protractor_deg;
    if (e.link_mm) { tol += deg(Math.atan2(2 * c.pencil_mm, e.link_mm)); }
    if (drawnMm > 0) { tol += deg(Math.atan2(2 * c.pencil_mm * Math.SQRT2, drawnMm)); }
    return tol;
  }
  function drawingScale(k, diagram) {
    return '1 mm = ' + gfmt(k, 4) + ' ' + (diagram === 'velocity' ? 'm/s' : 'm/s²');
  }
  function has(list, a, b) {
    return list.some(function (p) { return p[0] === a && p[1] === b; });
  }
  function vm(base, o) {
    var out = {vector: base.name, shown: base.shown, rule: base.rule, step: base.step,
               line: base.line};
    ['drawn', 'mark', 'direction_ok', 'sense_ok', 'length_ok', 'angle_error_deg',
     'length_error_pct', 'direction_tolerance_deg', 'length_tolerance_pct', 'problem',
     'hint'].forEach(function (key) { out[key] = o[key]; });
    out.note = o.note || '';
    return out;
  }

  function mark(R, e, drawn, P, k) {
    var N = R.names;
    var name = e.start + e.end, shown = e.shown || (N[e.start] || e.start) + (N[e.end] || e.end);
    var im = e.image, ev;
    if (im && P[im.base] && P[e.start]) {
      // carried forward: the image of the student's own start → base, by the link's ratio
      var bb = [P[im.base][0] - P[e.start][0], P[im.base][1] - P[e.start][1]], z = im.z;
      ev = [z[0] * bb[0] - z[1] * bb[1], z[0] * bb[1] + z[1] * bb[0]];
    } else {
      ev = [e.vector[0] / k, e.vector[1] / k];
    }
    var trueMm = hypot(ev[0], ev[1]);
    var lenTolMm = Math.max(e.rel * trueMm, R.constants.floor_mm);
    var where = e.where, rule = e.rule, line = e.line;
    var back = has(drawn, e.end, e.start);
    var base = {name: name, shown: shown, rule: rule, step: e.step, line: line};
    if (!has(drawn, e.start, e.end)) {
      if (back && line) {
        var flipped = Object.assign({}, e, {start: e.end, end: e.start, image: null,
                                            vector: [-e.vector[0], -e.vector[1]]});
        return mark(R, flipped, drawn, P, k);
      }
      if (back) {
        return vm(base, {drawn: true, direction_ok: false, sense_ok: false, length_ok: null,
          angle_error_deg: 180.0, length_error_pct: null,
          direction_tolerance_deg: directionTol(R, e, trueMm), length_tolerance_pct: null,
          mark: 0.0, problem: 'the arrow runs ' + N[e.end] + '→' + N[e.start],
          hint: shown + ' runs from ' + N[e.start] + ' to ' + N[e.end] + ' (' + where + ')'});
      }
      return vm(base, {drawn: false, direction_ok: false, sense_ok: false, length_ok: null,
        angle_error_deg: null, length_error_pct: null, direction_tolerance_deg: 0.0,
        length_tolerance_pct: null, mark: 0.0, problem: 'missing',
        hint: 'draw ' + shown + ' ' + rule + ' (' + where + ')'});
    }
    var s = [P[e.end][0] - P[e.start][0], P[e.end][1] - P[e.start][1]];
    var sMm = hypot(s[0], s[1]);
    var dtol = directionTol(R, e, sMm);
    if (sMm === 0 || trueMm === 0) {
      return vm(base, {drawn: true, direction_ok: false, sense_ok: false, length_ok: false,
        angle_error_deg: null, length_error_pct: null, direction_tolerance_deg: dtol,
        length_tolerance_pct: null, mark: 0.0, problem: 'drawn with no length',
        hint: shown + ' must be ' + rule + ' (' + where + ')'});
    }
    var err = angle(ev, s);
    if (line && Math.abs(err) > 90.0) { err = err > 0 ? err - 180.0 : err + 180.0; }
    var dirOk = within(err, dtol, 1);
    var senseOk = line || !within(Math.abs(err) - 180.0, dtol, 1);
    var drawnAt = 'drawn towards ' + fixed(heading(s), 1) + '°';
    var rightAt = fixed(heading(ev), 1) + '°';
    var problem = '', hint = '';
    if (!senseOk) {
      if (e.coriolis) {
        problem = 'the Coriolis component is reversed: ' + drawnAt + ', 2ω × v points ' +
                  'towards ' + rightAt;
      } else if (e.centripetal) {
        problem = 'the centripetal part points away from ' + e.centre + ': ' + drawnAt +
                  ', towards ' + e.centre + ' is ' + rightAt;
      } else {
        problem = 'points the wrong way: ' + drawnAt + ', ' + rule + ' is towards ' + rightAt;
      }
      hint = shown + ' must be ' + rule + ' (' + where + ')';
    } else if (!dirOk) {
      var off90 = within(Math.abs(err) - 90.0, dtol, 1);
      if (off90 && e.perp_to) {
        problem = 'drawn ∥ ' + e.perp_to + ' instead of ⟂ ' + e.perp_to;
      } else if (off90 && e.along) {
        problem = 'drawn ⟂ ' + e.along + ' instead of ∥ (' + rule + ')';
      } else {
        problem = drawnAt + ', ' + fixed(Math.abs(err), 1) + '° off ' + rule + ' (± ' +
                  fixed(dtol, 1) + '°)';
      }
      hint = shown + ' must be ' + rule + ' (' + where + ')';
    }
    var lineOk = dirOk && senseOk;
    if (line) {
      return vm(base, {drawn: true, direction_ok: dirOk, sense_ok: true, length_ok: null,
        angle_error_deg: err, length_error_pct: null, direction_tolerance_deg: dtol,
        length_tolerance_pct: null, mark: dirOk ? 1.0 : 0.0, problem: problem, hint: hint});
    }
    var lenErr = (sMm - trueMm) / trueMm * 100.0;
    // inside when either way it is shown (mm in the problem, % in the report) says so
    var lenOk = within(sMm - trueMm, lenTolMm, 1) || within(lenErr, lenTolMm / trueMm * 100.0, 1);
    if (!lenOk) {
      var ratio = sMm / trueMm;
      var fits = e.slips.filter(function (rw) {
        return within(sMm - rw[0] * trueMm, lenTolMm * Math.max(1.0, rw[0]), 1);
      }).map(function (rw) { return [Math.abs(sMm - rw[0] * trueMm), rw[1]]; });
      fits.sort(function (a, b) { return a[0] - b[0] || (a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0); });
      var slip = fits.length ? fits[0][1] : null;
      var what = 'length ' + fixed(sMm, 1) + ' mm, expected ' + fixed(trueMm, 1) + ' mm ± ' +
                 fixed(lenTolMm, 1) + ' at ' + drawingScale(k, R.diagram) + ' (' +
                 gfmt(ratio, 3) + '×)';
      var more = slip ? 'the value is wrong, not the scale: likely ' + slip : 'recheck its value';
      problem = problem ? problem + '; ' + what + ': ' + more : what + ': ' + more;
      if (!hint) { hint = shown + ': ' + more + ' (' + where + ')'; }
    }
    return vm(base, {drawn: true, direction_ok: dirOk, sense_ok: senseOk, length_ok: lenOk,
      angle_error_deg: err, length_error_pct: lenErr, direction_tolerance_deg: dtol,
      length_tolerance_pct: lenTolMm / trueMm * 100.0,
      mark: (lineOk && lenOk) ? 1.0 : ((lineOk || lenOk) ? 0.5 : 0.0),
      problem: problem, hint: hint});
  }

  function carryForward(R, marks) {
    var known = marks.filter(function (m) {
      return !m.line && m.length_ok !== null && m.length_error_pct !== null;
    });
    var first = known.filter(function (m) { return m.length_ok === false; })[0];
    if (!first) { return [marks, null]; }
    var r = 1.0 + first.length_error_pct / 100.0, shared = 0;
    var out = marks.map(function (m) {
      if (m !== first && !m.line && m.length_ok === false && m.length_error_pct !== null &&
          r !== 0 && Math.abs((1.0 + m.length_error_pct / 100.0) / r - 1.0) <= R.constants.same_ratio) {
        shared += 1;
        var direction = m.direction_ok && m.sense_ok;
        var i = m.problem.indexOf('; length ');
        return Object.assign({}, m, {length_ok: true, mark: direction ? 1.0 : 0.5,
          problem: i >= 0 ? m.problem.slice(0, i) : '', hint: direction ? '' : m.hint,
          note: 'length carried forward from ' + first.shown + ' (' + gfmt(r, 3) +
                '× at the stated scale)'});
      }
      return m;
    });
    if (shared) {
      var e = R.expected.filter(function (x) { return x.start + x.end === first.vector; })[0];
      var named = (e ? e.slips : []).some(function (rw) { return first.problem.indexOf(rw[1]) >= 0; });
      if (!named) {
        var j = out.indexOf(first);
        out[j] = Object.assign({}, first, {problem: first.problem + ' (every known vector is ' +
          gfmt(r, 3) + '× what the stated scale gives: was it drawn at another scale?)'});
      }
    }
    return [out, shared ? r : null];
  }

  function closures(R, P, k) {
    var out = [], c = R.constants, N = R.names;
    R.closures.forEach(function (cl) {
      var ln = cl.lines;
      if (ln.some(function (x) { return !P[x.start]; }) || !P[cl.vertex]) { return; }
      var anchors = ln.map(function (x) {
        var by = x.by, sh;
        if (by && P[by[0]] && P[by[1]]) {
          sh = [by[2] * (P[by[1]][0] - P[by[0]][0]), by[2] * (P[by[1]][1] - P[by[0]][1])];
        } else {
          sh = [x.shift[0] / k, x.shift[1] / k];
        }
        return [P[x.start][0] + sh[0], P[x.start][1] + sh[1]];
      });
      var a1 = anchors[0], d1 = ln[0].direction, a2 = anchors[1], d2 = ln[1].direction;
      var den = d1[0] * d2[1] - d1[1] * d2[0];
      if (Math.abs(den) < 1e-9) { return; }
      var t = ((a2[0] - a1[0]) * d2[1] - (a2[1] - a1[1]) * d2[0]) / den;
      var q = [a1[0] + t * d1[0], a1[1] + t * d1[1]], v = P[cl.vertex];
      var off = hypot(v[0] - q[0], v[1] - q[1]);
      var lengths = anchors.map(function (a) { return hypot(v[0] - a[0], v[1] - a[1]); });
      var tol = (c.floor_mm + Math.max.apply(null, lengths) * (c.protractor_deg * Math.PI / 180) * 2) /
                Math.abs(den);
      var ok = within(off, tol, 2);
      out.push({vertex: cl.vertex, off_mm: off, tolerance_mm: tol, ok: ok,
                hint: ok ? '' : N[cl.vertex] + ' is ' + fixed(off, 2) + ' mm from where the ' +
                  'lines of steps ' + ln[0].number + ' and ' + ln[1].number + ' meet (' +
                  cl.where + ')'});
    });
    return out;
  }

  // drawing: {diagram, scale (SI per mm), scale_text, vertices {name: [x, y] mm, y up},
  //           vectors [[from, to], ...]}
  function grade(R, drawing) {
    var k = drawing.scale, names = {}, unknown = [];
    Object.keys(drawing.vertices).forEach(function (n) {
      if (Object.prototype.hasOwnProperty.call(R.vertices, n)) { names[n] = n; }
      else if (n === 'o' || R.ground.indexOf(n.toUpperCase()) >= 0) { names[n] = R.pole; }
      else { unknown.push(n); }
    });
    unknown.sort();
    var P = {};
    Object.keys(drawing.vertices).forEach(function (n) {
      if (names[n] !== undefined) { P[names[n]] = drawing.vertices[n]; }
    });
    var drawn = [];
    drawing.vectors.forEach(function (ab) {
      var a = names[ab[0]], b = names[ab[1]];
      if (a !== undefined && b !== undefined && !has(drawn, a, b)) { drawn.push([a, b]); }
    });
    var marks = R.expected.map(function (e) { return mark(R, e, drawn, P, k); });
    var cf = carryForward(R, marks);
    marks = cf[0];
    var need = [];
    R.expected.forEach(function (e) { need.push([e.start, e.end]); need.push([e.end, e.start]); });
    // a vector the construction does not draw (the resultant) joins two of the student's
    // own vertices: carried forward, it is right whenever they are; not graded
    var extras = drawn.filter(function (ab) { return !has(need, ab[0], ab[1]) && ab[0] !== ab[1]; })
      .map(function (ab) {
        var a = ab[0], b = ab[1], N = R.names;
        return {vector: a + b, shown: (N[a] || a) + (N[b] || b), rule: 'joins two of your vertices',
                step: null, line: false, drawn: true, mark: 1.0, direction_ok: true, sense_ok: true,
                length_ok: null, angle_error_deg: null, length_error_pct: null,
                direction_tolerance_deg: 0.0, length_tolerance_pct: null, problem: '', hint: '',
                note: 'not graded on its own'};
      });
    var cls = closures(R, P, k);
    var score = marks.reduce(function (t, m) { return t + m.mark; }, 0);
    return {diagram: R.diagram, scale: drawing.scale_text, score: score, out_of: marks.length,
            all_ok: marks.every(function (m) { return m.mark === 1.0 && !m.note; }) &&
                    cls.every(function (c) { return c.ok; }),
            vectors: marks, extras: extras, closures: cls, carried_ratio: cf[1],
            unknown_vertices: unknown};
  }

  window.polygonsGrade = {grade: grade, within: within, gfmt: gfmt};
})();
