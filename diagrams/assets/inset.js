// The inset rule of diagrams/inset.py ('detail ×k'), ported for the live panel: the same
// clusters, rings and enlargement, on the same constants (the page's data, D.inset, written
// from diagrams/inset.py by diagrams/pagedata.py).  Points in mm.  tests/test_page_audit.py
// holds this port equal to the Python (inset.rings, inset.plan's k, polygon._ghosts' rule).
window.polygonsInset = function (C) {
  'use strict';
  var F = C.factors;
  function r3(x) { return Math.round(x * 1000) / 1000; }
  function dist(p, q) { return Math.hypot(p[0] - q[0], p[1] - q[1]); }
  function byName(a, b) { return a < b ? -1 : a > b ? 1 : 0; }
  // crowd.clusters: vertices within `near` of another of their group, not all at one place
  function clusters(points, near) {
    var names = Object.keys(points).sort(byName), parent = {};
    names.forEach(function (n) { parent[n] = n; });
    function find(n) { while (parent[n] !== n) { n = parent[n]; } return n; }
    for (var i = 0; i < names.length; i++) {
      for (var j = i + 1; j < names.length; j++) {
        if (dist(points[names[i]], points[names[j]]) < near) { parent[find(names[j])] = find(names[i]); }
      }
    }
    var groups = {}, order = [];
    names.forEach(function (n) {
      var r = find(n);
      if (!groups[r]) { groups[r] = []; order.push(r); }
      groups[r].push(n);
    });
    var out = [];
    order.forEach(function (r) {
      var g = groups[r];
      if (g.length < 2) { return; }
      var spread = 0;
      g.forEach(function (a) { g.forEach(function (b) { spread = Math.max(spread, dist(points[a], points[b])); }); });
      if (spread > C.same) { out.push(g); }
    });
    return out.sort(function (a, b) {           // Python's sort of lists of names
      for (var i = 0; i < Math.min(a.length, b.length); i++) { if (a[i] !== b[i]) { return byName(a[i], b[i]); } }
      return a.length - b.length;
    });
  }
  // inset.rings: (names, centre, radius) around each cluster
  function rings(points, near) {
    return clusters(points, near).map(function (names) {
      var pts = names.map(function (n) { return points[n]; });
      var xs = pts.map(function (p) { return p[0]; }), ys = pts.map(function (p) { return p[1]; });
      var c = [r3((Math.min.apply(null, xs) + Math.max.apply(null, xs)) / 2),
               r3((Math.min.apply(null, ys) + Math.max.apply(null, ys)) / 2)];
      var r = 0;
      pts.forEach(function (p) { r = Math.max(r, dist(c, p)); });
      return {names: names, c: c, r: r3(r + C.ring_margin)};
    });
  }
  // inset._factor: nearest two vertices 1.6 label heights apart, every vector ≥ the rule
  function factor(pts, near, lens) {
    var d = Infinity;
    for (var i = 0; i < pts.length; i++) {
      for (var j = i + 1; j < pts.length; j++) {
        var e = dist(pts[i], pts[j]); if (e >= 0.6) { d = Math.min(d, e); }
      }
    }
    if (!isFinite(d)) { d = near; }
    for (var k = 0; k < F.length; k++) {
      if (d * F[k] >= 1.6 * near && lens.every(function (L) { return L * F[k] >= C.min_mm; })) { return F[k]; }
    }
    return F[F.length - 1];
  }
  function vectorFactor(lens) {                   // inset._vector_factor
    for (var k = 0; k < F.length; k++) {
      if (lens.every(function (L) { return L * F[k] >= C.min_mm; })) { return F[k]; }
    }
    return F[F.length - 1];
  }
  function largestFactor(r, maxRV) {              // inset.largest_factor
    var ok = F.filter(function (k) { return k * r <= maxRV; });
    return ok.length ? ok[ok.length - 1] : F[0];
  }
  // the enlargement of one ring (inset.plan): vectors = [[a, b]] of the drawing
  function enlargement(ring, points, near, vectors, maxR, maxRV) {
    var inside = {}, lens = [];
    ring.names.forEach(function (n) { inside[n] = true; });
    vectors.forEach(function (v) {
      if (inside[v[0]] && inside[v[1]] && points[v[0]] && points[v[1]]) {
        var L = dist(points[v[0]], points[v[1]]);
        if (L >= C.zero_mm - 1e-9) { lens.push(L); }
      }
    });
    var k = factor(ring.names.map(function (n) { return points[n]; }), near, lens);
    var need = vectorFactor(lens);
    while (k > F[0] && k * ring.r > maxR && (k > need || k * ring.r > maxRV)) { k = F[F.indexOf(k) - 1]; }
    return k;
  }
  // polygon._ghosts: vectors no inset can draw the rule's length (not drawn, said '≈ 0')
  function ghosts(points, near, vectors, maxRV) {
    var rs = rings(points, near), out = [];
    vectors.forEach(function (v) {
      var L = dist(points[v[0]], points[v[1]]);
      if (L < C.zero_mm) { out.push(v); return; }
      if (L >= C.min_mm) { return; }
      var ring = rs.filter(function (r) { return r.names.indexOf(v[0]) >= 0 && r.names.indexOf(v[1]) >= 0; })[0];
      if (!ring || L * largestFactor(ring.r, maxRV) < C.min_mm) { out.push(v); }
    });
    return out;
  }
  // every inset of a drawing: {names, c, r, k, R}; the ghosts left out first
  function plan(points, near, vectors, maxR, maxRV) {
    maxR = maxR === undefined ? C.max_radius : maxR;
    maxRV = maxRV === undefined ? C.max_radius_vectors : maxRV;
    var gone = ghosts(points, near, vectors, maxRV), key = {};
    gone.forEach(function (v) { key[v[0] + '\u0000' + v[1]] = true; });
    var drawn = vectors.filter(function (v) { return !key[v[0] + '\u0000' + v[1]]; });
    var insets = rings(points, near).map(function (ring) {
      var k = enlargement(ring, points, near, drawn, maxR, maxRV);
      return {names: ring.names, c: ring.c, r: ring.r, k: k, R: r3(k * ring.r)};
    });
    return {insets: insets, ghosts: gone, drawn: drawn};
  }
  return {clusters: clusters, rings: rings, factor: factor, vectorFactor: vectorFactor,
          largestFactor: largestFactor, enlargement: enlargement, ghosts: ghosts, plan: plan,
          constants: C};
};
