"""The interactive page's cycle panel measured as the layout audit measures an SVG, in the
rendered DOM of headless Chromium (issue 33: the panel drew a ~15 mm polygon with labels on
each other, and vectors under 3 mm).

In a 1400 × 1000 px window, for Fig 7, WE3 and a triad, at the drawings' position and three
more crank positions (one page load a case): each polygon fills its panel (its drawn extent at
least 40 % of the panel's width or height: "fit", the start, fits it to its panel at the
position shown; the panel without the strip of insets a crowded polygon adds below
it); no two texts of a panel overlap (labels, insets' labels and captions, the
caption, notes and scale bar); no vertex label lies on a drawn vector (of the polygon or an
inset); every drawn vector is 3 mm long or more (96 CSS px to the inch) or lies in an inset's
ring and is drawn there 3 mm or more ('detail ×k', as the static drawings and
:mod:`diagrams.audit` have it), every whole vector of an inset is 3 mm or more; and the page's
port of the inset rule (``diagrams/assets/inset.js``) finds the rings, enlargements and
too-short vectors :mod:`diagrams.inset` finds on the same points.  Skipped without Chromium.
"""
import json
import math

import pytest

from conftest import CASES

from diagrams import browser, inset

CHROMIUM = browser.find()
PX_PER_MM = 96 / 25.4
PX_PER_MM = 96 / 25.4
MIN_PX = inset.MIN_VECTOR_MM * PX_PER_MM
CASES_ALL = ["s003-fig7", "s001-we3", "triad-eight-bar"]
#: crank positions measured: the drawings' own, then these fractions of the cycle on
TURNS = (0.0, 0.3, 0.55, 0.8)
#: the fixed scales ("× 1" … "× 8": one scale over the cycle, the polygon run off its panel at
#: some positions), on a triad whose vertices then lie at the panel's edge: (zoom, frame)s,
#: frame 45 in × 2 the position a sweep found a label on a vector at (b₁ = s₁ on sb)
FIXED_CASE = "triad-slider-corner"
FIXED = (("2", 45), ("2", 135), ("8", 45), ("8", 100))
#: "fit" at a position a sweep found an inset's label outside its crowded ring, on the
#: polygon's o→a₁ (its own inset's place then counted as another text's)
CROWDED_RING = ("triad-plate-point", 75)

MEASURE = """<script>
window.polygonsMeasure = function () {
  var out = {};
  function tipOf(l) {
    var h = l.nextElementSibling;
    if (h && h.tagName === 'polygon' && /head/.test(h.getAttribute('class') || '')) {
      var p = h.getAttribute('points').split(' ')[0].split(',');
      return [+p[0], +p[1]];
    }
    return null;
  }
  ['vpoly', 'apoly'].forEach(function (id) {
    var svg = document.getElementById(id);
    if (!svg || svg.style.display === 'none') { return; }
    var r = svg.getBoundingClientRect(), vb = svg.viewBox.baseVal, k = r.width / vb.width;
    var P = function (x, y) { return [r.left + k * x, r.top + k * y]; };
    var vecs = [], texts = [], insets = [];
    Array.prototype.forEach.call(svg.querySelectorAll('line.comp, line.inset-vector'), function (l) {
      var tip = tipOf(l), a = P(+l.getAttribute('x1'), +l.getAttribute('y1'));
      var b = tip ? P(tip[0], tip[1]) : P(+l.getAttribute('x2'), +l.getAttribute('y2'));
      if (l.getAttribute('data-k') !== 'arrow') { return; }     // an image's side: no vector
      vecs.push({f: l.getAttribute('data-from'), t: l.getAttribute('data-to'), a: a, b: b,
                 head: !!tip, inset: /inset-vector/.test(l.getAttribute('class')),
                 whole: l.getAttribute('data-whole') === '1'});
    });
    Array.prototype.forEach.call(svg.querySelectorAll('g.inset'), function (g) {
      var ring = g.querySelector('circle.inset-ring'), fr = g.querySelector('circle.inset-frame');
      insets.push({k: +g.getAttribute('data-k'),
                   c: P(+ring.getAttribute('cx'), +ring.getAttribute('cy')), r: k * ring.getAttribute('r'),
                   C: P(+fr.getAttribute('cx'), +fr.getAttribute('cy')), R: k * fr.getAttribute('r')});
    });
    Array.prototype.forEach.call(svg.querySelectorAll('text'), function (t) {
      var b = t.getBoundingClientRect();
      texts.push({text: t.textContent, cls: t.getAttribute('class') || '',
                  box: [b.left, b.top, b.right, b.bottom]});
    });
    out[id] = {panel: [r.left, r.top, r.right, r.top + k * +svg.getAttribute('data-base')],
               view: [r.left, r.top, r.right, r.bottom], vecs: vecs, texts: texts, insets: insets,
               rule: window.polygonsPage.insets(id === 'vpoly' ? 'velocity' : 'acceleration')};
  });
  return JSON.stringify(out);
};
</script>"""


def _hits(seg, box, pad=0.0) -> bool:
    """Does segment ``seg`` ((x, y), (x, y)) cross ``box`` (x0, y0, x1, y1) shrunk by pad?"""
    (x1, y1), (x2, y2) = seg
    x0, y0, X1, Y1 = box[0] + pad, box[1] + pad, box[2] - pad, box[3] - pad
    dx, dy, t0, t1 = x2 - x1, y2 - y1, 0.0, 1.0
    for p, q in ((-dx, x1 - x0), (dx, X1 - x1), (-dy, y1 - y0), (dy, Y1 - y1)):
        if p == 0:
            if q < 0:
                return False
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


def _rule_agrees(rule, where) -> None:
    """The page's inset rule (inset.js) against diagrams/inset.py on the same points (mm):
    the rings, each ring's enlargement (inset.plan at the panel's largest radii), and every
    vector left undrawn as too short for any inset."""
    pts = {v: tuple(p) for v, p in rule["mm"].items()}
    near = rule["near"]
    rings = inset.rings(pts, near)
    got = rule["insets"]
    assert [list(n) for n, _, _ in rings] == [i["names"] for i in got], where
    for (n, c, r), i in zip(rings, got):
        assert math.dist(c, i["c"]) < 2e-3 and abs(r - i["r"]) < 2e-3, (where, n, c, r, i)
    from diagrams.labels import Box
    old = inset.MAX_RADIUS, inset._labels
    try:                    # (the panel's largest radius; no labels: only k is compared)
        inset.MAX_RADIUS, inset._labels = rule["max_radius"], lambda ins, *args: ins
        plan = inset.plan(pts, [], [], Box(0, 0, 1e4, 1e4), 3.0, near,
                          vectors=[tuple(v) for v in rule["drawn"]],
                          max_radius=rule["max_radius_vectors"])
    finally:
        inset.MAX_RADIUS, inset._labels = old
    assert [p.k for p in plan] == [i["k"] for i in got], (where, [p.k for p in plan], got)
    ghosts = {tuple(v) for v in rule["ghosts"]}
    for f, t in rule["vectors"]:          # '≈ 0' (not drawn) exactly when no inset could
        L = math.dist(pts[f], pts[t])     # draw it 3 mm long (diagrams.polygon._ghosts)
        ring = next((r for n, _, r in rings if f in n and t in n), None)
        best = max([k for k in inset.FACTORS if ring and k * ring <= rule["max_radius_vectors"]]
                   or [inset.FACTORS[0]])
        short = L < inset.ZERO_MM or (L < inset.MIN_VECTOR_MM and (
            ring is None or L * best < inset.MIN_VECTOR_MM))
        assert short == ((f, t) in ghosts), (where, f, t, L, ring)
    drawn = {tuple(v) for v in rule["drawn"]}
    assert drawn | ghosts == {tuple(v) for v in rule["vectors"]} and not drawn & ghosts


def _check(case, frame, got, fill: bool = True) -> None:
    """The rule over one frame's measure (``fill``: the polygon fills 40 % of its panel, as
    "fit" draws it; a fixed scale, "× 1" …, need not)."""
    assert got, "no polygon panel"
    for pid, m in got.items():
        where = (case, frame, pid)
        x0, y0, x1, y1 = m["panel"]
        main = [v for v in m["vecs"] if not v["inset"]]
        pts = [p for v in main for p in (v["a"], v["b"])]
        if not pts:                       # a mechanism at rest: nothing to draw, said so
            assert any("is zero here" in t["text"] for t in m["texts"]), where
        elif fill:
            w = max(p[0] for p in pts) - min(p[0] for p in pts)
            h = max(p[1] for p in pts) - min(p[1] for p in pts)
            assert max(w / (x1 - x0), h / (y1 - y0)) >= 0.4, (where, w, h, m["panel"])
        boxes = [(t["text"], t["box"]) for t in m["texts"] if t["text"].strip()]
        for i, (ta, a) in enumerate(boxes):
            for tb, b in boxes[i + 1:]:
                ox = min(a[2], b[2]) - max(a[0], b[0])
                oy = min(a[3], b[3]) - max(a[1], b[1])
                assert ox <= 0.5 or oy <= 0.5, (where, ta, tb)
        for t in m["texts"]:
            if "vx" not in t["cls"].split():
                continue
            on = [(v["f"], v["t"]) for v in m["vecs"] if _hits((v["a"], v["b"]), t["box"], 1.0)]
            assert not on, (where, t["text"], on)
        # the rule: 3 mm, on the polygon or in an inset (its ring around the vector's middle)
        for v in main:
            L = math.dist(v["a"], v["b"])
            if L == 0 or L >= MIN_PX - 1e-6:
                continue
            mid = ((v["a"][0] + v["b"][0]) / 2, (v["a"][1] + v["b"][1]) / 2)
            ins = [i for i in m["insets"] if math.dist(mid, i["c"]) <= i["r"] + 0.5]
            big = [math.dist(u["a"], u["b"]) for u in m["vecs"]
                   if u["inset"] and u["whole"] and (u["f"], u["t"]) == (v["f"], v["t"])]
            assert ins and big and max(big) >= MIN_PX - 1e-6, (
                where, v["f"], v["t"], round(L / PX_PER_MM, 2), [round(b / PX_PER_MM, 2) for b in big])
        for u in m["vecs"]:               # every whole vector of an inset meets the rule
            if u["inset"] and u["whole"]:
                assert math.dist(u["a"], u["b"]) >= MIN_PX - 1e-6, (where, u["f"], u["t"])
        for i in m["insets"]:             # its stated enlargement is the drawn one
            assert abs(i["R"] / i["r"] - i["k"]) < 1e-6 * i["k"], (where, i)
        _rule_agrees(m["rule"], where)


@pytest.mark.parametrize("case", CASES_ALL)
def test_cycle_panel_meets_the_layout_rule(case, tmp_path, session):
    from polygons.cli.handout import write_page
    text = write_page(str(CASES / f"{case}.toml"), tmp_path / "page.html").read_text(
        encoding="utf-8")
    page = tmp_path / "measured.html"
    page.write_text(text.replace("<head>", "<head>\n" + MEASURE, 1), encoding="utf-8")
    session.open(page)
    n = session.evaluate("document.getElementById('angle').max | 0") + 1
    start = session.evaluate("window.polygonsPage.frame()")
    for turn in TURNS:
        frame = (start + round(turn * n)) % n
        session.evaluate(f"window.polygonsPage.setFrame({frame})")
        _check(case, frame, json.loads(session.evaluate("window.polygonsMeasure()")))


def test_cycle_panel_at_a_fixed_scale_meets_the_layout_rule(tmp_path, session):
    """"× 2" and "× 8" (one scale over the cycle, the polygon run off its panel here): the
    checks of "fit" but for filling the panel, and every text inside its panel (a vertex
    beyond it unlabelled; one at its edge labelled off every vector)."""
    from polygons.cli.handout import write_page
    text = write_page(str(CASES / f"{FIXED_CASE}.toml"), tmp_path / "page.html").read_text(
        encoding="utf-8")
    page = tmp_path / "measured.html"
    page.write_text(text.replace("<head>", "<head>\n" + MEASURE, 1), encoding="utf-8")
    session.open(page)
    for zoom, frame in FIXED:
        session.evaluate(f"window.polygonsPage.zoom({json.dumps(zoom)})")
        session.evaluate(f"window.polygonsPage.setFrame({frame})")
        got = json.loads(session.evaluate("window.polygonsMeasure()"))
        assert all(f"(×{zoom})" in t["text"] for m in got.values() for t in m["texts"]
                   if "cap" in t["cls"].split()), (zoom, frame)
        _check(f"{FIXED_CASE} ×{zoom}", frame, got, fill=False)
        for pid, m in got.items():        # every label inside its panel (none for a vertex beyond)
            x0, y0, x1, y1 = m["view"]
            for t in m["texts"]:
                b = t["box"]
                assert b[0] >= x0 - 0.5 and b[1] >= y0 - 0.5 and b[2] <= x1 + 0.5 and b[3] <= y1 + 0.5, (
                    zoom, frame, pid, t["text"], b, m["view"])


def test_crowded_inset_labels_its_vertices_in_its_ring(tmp_path, session):
    """triad-plate-point at frame 75 in "fit": the ×6 inset's labels (o = d = e among them) inside
    its ring, none on a vector of the polygon (the layout rule at that frame)."""
    from polygons.cli.handout import write_page
    case, frame = CROWDED_RING
    text = write_page(str(CASES / f"{case}.toml"), tmp_path / "page.html").read_text(
        encoding="utf-8")
    page = tmp_path / "measured.html"
    page.write_text(text.replace("<head>", "<head>\n" + MEASURE, 1), encoding="utf-8")
    session.open(page)
    session.evaluate(f"window.polygonsPage.setFrame({frame})")
    _check(case, frame, json.loads(session.evaluate("window.polygonsMeasure()")))


def test_inset_port_agrees_with_diagrams_inset(tmp_path, session):
    """assets/inset.js on random crowded drawings (clusters of vertices a fraction of a mm to
    a few mm apart, vectors among them, the panel's largest radii varied) finds the same
    rings, enlargements and '≈ 0' vectors as diagrams/inset.py: one page of the script alone."""
    import random
    from diagrams.page import asset, script_json
    from diagrams.pagedata import inset_rule
    rnd = random.Random(33)
    drawings = []
    for _ in range(60):
        pts = {}
        for c in range(rnd.randint(1, 3)):
            cx, cy = rnd.uniform(0, 80), rnd.uniform(0, 60)
            spread = rnd.choice([0.3, 1.0, 2.5, 4.0])
            for i in range(rnd.randint(2, 6)):
                pts[f"{'abcdefgh'[c]}{i}"] = [round(cx + rnd.uniform(-spread, spread), 4),
                                              round(cy + rnd.uniform(-spread, spread), 4)]
        a = rnd.choice(sorted(pts))           # a vertex a tenth of a mm or so from another
        ang, L = rnd.uniform(0, 6.3), rnd.uniform(0.05, 0.3)
        pts["z"] = [round(pts[a][0] + L * math.cos(ang), 4), round(pts[a][1] + L * math.sin(ang), 4)]
        names = sorted(pts)
        vectors = [[a, "z"]] + [[p, q] for p in names for q in names
                                if p < q and q != "z" and rnd.random() < 0.3]
        drawings.append({"mm": pts, "near": rnd.choice([3.175, 3.5]),
                         "max_radius": rnd.choice([26.0, 18.0, 12.0]),
                         "max_radius_vectors": rnd.choice([30.0, 24.0, 15.0]),
                         "vectors": vectors})
    page = tmp_path / "inset.html"
    page.write_text("<!DOCTYPE html><html><head><meta charset='utf-8'><script>"
                    + asset("inset.js") + "</script></head><body></body></html>",
                    encoding="utf-8")
    session.open(page)
    got = json.loads(session.evaluate(
        "(function (C, all) { var R = window.polygonsInset(C);"
        " return JSON.stringify(all.map(function (d) {"
        "  var p = R.plan(d.mm, d.near, d.vectors, d.max_radius, d.max_radius_vectors);"
        "  return {insets: p.insets, ghosts: p.ghosts, drawn: p.drawn}; })); })("
        + script_json(inset_rule()) + ", " + script_json(drawings) + ")"))
    assert sum(len(g["insets"]) for g in got) > 40 and sum(len(g["ghosts"]) for g in got) > 5
    for i, (d, g) in enumerate(zip(drawings, got)):
        _rule_agrees({**d, **g}, ("random", i))
