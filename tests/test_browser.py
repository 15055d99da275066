"""Handouts in a real browser: headless Chromium loads them from a local file and prints them.

How the page is probed: the handout itself runs no script, so the test loads a copy with one
small script added at the top of <head>.  It records every error event (script errors and
resources that fail to load, in the capture phase), every console.error call and every
resource fetched; on ``load`` it measures each inline SVG (getBoundingClientRect and its
number of drawn elements) and writes all of it as JSON into a <pre id="probe">.  Chromium's
``--dump-dom`` prints the DOM after load, so the test reads the probe back.  Chromium's own
console log (``--enable-logging=stderr``) is checked too.  A control page with a deliberate
error proves the probe sees errors.

PDF: Chromium prints with the handout's @page rules; pdftoppm (poppler-utils) renders each
page to PNG and every page must carry ink (no blank pages).

Chromium and poppler-utils are Debian packages that ``.ci/run`` installs when it can; without
them these tests skip and say why.
"""
import html as htmllib
import math
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import CASES, cli

from diagrams import browser

CHROMIUM = browser.find()
needs_chromium = pytest.mark.skipif(
    CHROMIUM is None, reason="headless Chromium is not installed (Debian package 'chromium'; "
                             ".ci/run installs it when apt-get works)")
needs_poppler = pytest.mark.skipif(
    shutil.which("pdftoppm") is None,
    reason="pdftoppm is not installed (Debian package 'poppler-utils')")

EXE = Path(sys.executable).with_name("polygons")

PROBE = """<script>
(function () {
  var errors = [];
  window.addEventListener('error', function (e) {
    var t = e.target;
    errors.push(e.message || ('failed to load ' + (t && (t.src || t.href || t.tagName))));
  }, true);
  window.addEventListener('unhandledrejection', function (e) { errors.push(String(e.reason)); });
  var ce = console.error;
  console.error = function () {
    errors.push(Array.prototype.join.call(arguments, ' ')); ce.apply(console, arguments);
  };
  window.addEventListener('load', function () {
    var figs = Array.prototype.map.call(document.querySelectorAll('svg'), function (s) {
      var r = s.getBoundingClientRect();
      return {id: s.id, w: r.width, h: r.height,
              drawn: s.querySelectorAll('line,path,polygon,polyline,circle,rect,text').length};
    });
    var res = performance.getEntriesByType('resource').map(function (r) { return r.name; });
    var pre = document.createElement('pre');
    pre.id = 'probe';
    pre.textContent = JSON.stringify({figs: figs, errors: errors, resources: res});
    document.body.appendChild(pre);
  });
})();
</script>"""


def polygons(*args):
    """``polygons ARGS`` in this process (conftest.cli: the entry point function; Chromium,
    where the command prints, is its own process all the same)."""
    return cli(*args)


def polygons_process(*args):
    """``polygons ARGS`` as a separate process (the console script)."""
    cmd = [str(EXE)] if EXE.exists() else [sys.executable, "-m", "polygons"]
    return subprocess.run(cmd + [str(a) for a in args], capture_output=True, text=True,
                          timeout=300)


def probe(page: Path, tmp_path: Path) -> tuple[dict, str]:
    text = page.read_text(encoding="utf-8")
    probed = tmp_path / (page.stem + "-probed.html")
    probed.write_text(text.replace("<head>", "<head>\n" + PROBE, 1), encoding="utf-8")
    out = browser.dump_dom(probed)
    m = re.search(r'<pre id="probe">(.*?)</pre>', out.stdout, re.S)
    assert m, f"the probe did not report (Chromium exit {out.returncode}): {out.stderr[-500:]}"
    return json.loads(htmllib.unescape(m.group(1))), out.stderr


def console_errors(stderr: str) -> list[str]:
    return [l for l in stderr.splitlines() if "CONSOLE" in l and
            re.search(r"error|uncaught", l, re.I)]


@needs_chromium
def test_probe_sees_errors(tmp_path):
    page = tmp_path / "broken.html"
    page.write_text("<!DOCTYPE html><html><head><title>x</title></head><body>"
                    "<svg width='10' height='10'></svg><script>notDefined();</script>"
                    "<img src='missing.png'></body></html>", encoding="utf-8")
    data, _ = probe(page, tmp_path)
    assert any("notDefined" in e for e in data["errors"])
    assert any("missing.png" in e for e in data["errors"])


@needs_chromium
@pytest.mark.parametrize("case,worksheet", [("s003-fig7.toml", False),
                                            ("s001-we6.toml", True),
                                            ("s001-we8.toml", False)])   # force polygons
def test_handout_renders_every_figure_without_errors(case, worksheet, tmp_path):
    page = tmp_path / "page.html"
    args = ["handout", CASES / case, "-o", page] + (["--worksheet"] if worksheet else [])
    out = polygons(*args)
    assert out.returncode == 0, out.stderr
    data, stderr = probe(page, tmp_path)
    assert data["errors"] == [] and console_errors(stderr) == []
    # nothing fetched: every figure is inline (the page itself is not a resource entry)
    assert data["resources"] == []
    html = page.read_text(encoding="utf-8")
    assert len(data["figs"]) == html.count("<svg") >= 3
    for fig in data["figs"]:
        assert fig["w"] > 50 and fig["h"] > 30, fig        # CSS px: a real box on the page
        assert fig["drawn"] > 3, fig
    if worksheet:
        # the empty drawing areas are at true size: CSS mm, 96 px per inch
        for fig in data["figs"]:
            if fig["id"].startswith("area-"):
                svg = re.search(rf'<svg[^>]*id="{fig["id"]}"[^>]*>', html).group(0)
                mm = float(re.search(r'width="([\d.]+)mm"', svg).group(1))
                assert fig["w"] == pytest.approx(mm * 96 / 25.4, abs=1.0)


@needs_chromium
@needs_poppler
def test_pdf_has_no_blank_pages(tmp_path):
    from PIL import Image
    page = tmp_path / "we4.html"
    out = polygons("handout", CASES / "s001-we4.toml", "-o", page, "--pdf")
    assert out.returncode == 0, out.stderr
    pdf = page.with_suffix(".pdf")
    assert pdf.read_bytes()[:5] == b"%PDF-"
    ws = tmp_path / "we4-worksheet.pdf"
    out = polygons("handout", CASES / "s001-we4.toml", "-o", ws, "--worksheet")
    assert out.returncode == 0, out.stderr
    for doc, at_least, at_most in ((pdf, 3, 6), (ws, 3, 8)):
        subprocess.run(["pdftoppm", "-r", "24", "-png", str(doc), str(tmp_path / doc.stem)],
                       check=True, timeout=120)
        pngs = sorted(tmp_path.glob(f"{doc.stem}-*.png"))
        assert at_least <= len(pngs) <= at_most, (doc, len(pngs))   # WE4: was 12 pages
        for i, png in enumerate(pngs):
            grey = np.asarray(Image.open(png).convert("L"))
            assert (grey < 200).mean() > 0.002, f"{png.name} is blank"
            if i < len(pngs) - 1 and doc == pdf:      # no page but the last half empty
                half = grey.shape[0] // 2
                for part in (grey[:half], grey[half:]):
                    assert (part < 200).mean() > 0.001, f"{png.name} has a blank half"
        # one orientation throughout (A4 portrait)
        sizes = {Image.open(p).size for p in pngs}
        assert len(sizes) == 1, sizes
        w, h = sizes.pop()
        assert h > w


@needs_chromium
@needs_poppler
def test_pdf_without_html_suffix_prints_the_page_not_its_source(tmp_path):
    out = tmp_path / "handout"
    res = polygons("handout", CASES / "s001-we2.toml", "-o", out, "--pdf")
    assert res.returncode == 0, res.stderr
    pdf = tmp_path / "handout.pdf"
    assert pdf.read_bytes()[:5] == b"%PDF-"
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True,
                          timeout=60).stdout
    assert "The velocity diagram" in text
    assert "<svg" not in text and "<!DOCTYPE" not in text and "viewBox" not in text


# ---------------------------------------------------------------- the interactive page
DRIVE = """<script>
window.addEventListener('load', function () {
  var out = {};
  function hits(s, r) {                       // segment s = [x1,y1,x2,y2] meets rect r?
    var n = 200;
    for (var i = 0; i <= n; i++) {
      var x = s[0] + (s[2] - s[0]) * i / n, y = s[1] + (s[3] - s[1]) * i / n;
      if (x > r.x && x < r.x + r.width && y > r.y && y < r.y + r.height) { return true; }
    }
    return false;
  }
  function texts(id) {                        // every label: inside the panel, readable
    var svg = document.getElementById(id), R = svg.getBoundingClientRect(), bad = [];
    svg.querySelectorAll('text').forEach(function (t) {
      var r = t.getBoundingClientRect();
      if (r.left < R.left - 0.5 || r.right > R.right + 0.5 || r.top < R.top - 0.5 ||
          r.bottom > R.bottom + 0.5) { bad.push('outside: ' + t.textContent); }
      if (r.height < 10) { bad.push('small (' + r.height.toFixed(1) + ' px): ' + t.textContent); }
    });
    return bad;
  }
  function onLinks() {                        // no point label on a link
    var bad = [], links = [];
    document.querySelectorAll('#mech line.link').forEach(function (l) {
      links.push([+l.getAttribute('x1'), +l.getAttribute('y1'), +l.getAttribute('x2'), +l.getAttribute('y2')]);
    });
    document.querySelectorAll('#mech text.pt').forEach(function (t) {
      var b = t.getBBox();
      links.forEach(function (s) { if (hits(s, b)) { bad.push(t.textContent); } });
    });
    return bad;
  }
  try {
    var P = window.polygonsPage, names = [];
    out.stages = P.stages;
    out.visible0 = document.querySelectorAll('figure.stage:not([hidden])').length;
    names.push(P.stage()); P.next(); names.push(P.stage()); P.next(); names.push(P.stage());
    P.back(); names.push(P.stage());
    out.names = names;
    out.start = P.frame();
    out.bad_start = texts('mech').concat(texts('vpoly'), texts('apoly'));
    out.on_links_start = onLinks();
    var s = document.getElementById('angle');
    s.value = String(FRAME); s.dispatchEvent(new Event('input'));       // a drag's events
    out.frame = P.frame();
    out.points = {};
    document.querySelectorAll('#mech circle[data-point]').forEach(function (c) {
      out.points[c.getAttribute('data-point')] = [+c.getAttribute('cx'), +c.getAttribute('cy')];
    });
    out.vel_arrows = document.querySelectorAll('#mech line.vel').length;
    out.vtext = Array.prototype.map.call(document.querySelectorAll('#vpoly text.vx'),
                                         function (t) { return t.textContent; }).join(' | ');
    out.atext = Array.prototype.map.call(document.querySelectorAll('#apoly text.vx'),
                                         function (t) { return t.textContent; }).join(' | ');
    out.bad = texts('mech').concat(texts('vpoly'), texts('apoly'));
    out.on_links = onLinks();
    out.kinds = Array.prototype.map.call(document.querySelectorAll('#apoly line.comp'),
                                         function (l) { return l.getAttribute('data-kind'); });
    out.ghosts = {};                  // too short for any inset here: said '≈ 0', not drawn
    ['velocity', 'acceleration'].forEach(function (d) {
      var g = P.insets(d);
      out.ghosts[d] = g ? g.ghosts.map(function (v) { return v[0] + '>' + v[1]; }) : [];
    });
    out.hi = {};
    var edges = JSON.parse(document.getElementById('frames').textContent).edges;
    edges.forEach(function (e, i) {
      P.hover(i);
      out.hi[i] = {link: document.querySelectorAll('#mech line.link.hi').length,
                   polys: Array.prototype.map.call(document.querySelectorAll('#vpoly line.comp.hi, #apoly line.comp.hi'),
                     function (l) { return l.getAttribute('data-from') + '>' + l.getAttribute('data-to'); })};
    });
    P.hover(-1);
  } catch (e) { out.error = String(e) + ' ' + e.stack; }
  var pre = document.createElement('pre'); pre.id = 'drive';
  pre.textContent = JSON.stringify(out); document.body.appendChild(pre);
});
</script>"""

#: (a cam stated by its profile has no page: its linkage changes with the part in contact, so
#: no sweep follows it — refused in one line, tests/test_cam_profiles.py)
PAGE_CASES = [p.name for p in sorted(CASES.glob("*.toml"))
              if "[cam_profiles." not in p.read_text(encoding="utf-8")]


def _page_data(text: str) -> dict:
    m = re.search(r'<script type="application/json" id="frames">(.*?)</script>', text, re.S)
    return json.loads(m.group(1))


def _load(s, path, pre_ids=("probe", "drive")) -> dict:
    """Open ``path`` in the session; the text of each <pre id=...> the page's probes write."""
    import time
    s.events.clear()
    s.open(path)
    for _ in range(100):
        got = s.evaluate("JSON.stringify([" + ",".join(
            f"(document.getElementById('{i}')||{{}}).textContent||null" for i in pre_ids) + "])")
        got = json.loads(got)
        if all(g is not None for g in got):
            return dict(zip(pre_ids, got))
        time.sleep(0.05)
    raise AssertionError(f"the page's probes did not report: {got}")


def _console_errors(s) -> list:
    """Script exceptions and console.error calls the DevTools session saw."""
    out = []
    for ev in s.events:
        if ev.get("method") == "Runtime.exceptionThrown":
            out.append(str(ev["params"]["exceptionDetails"].get("text")))
        elif (ev.get("method") == "Runtime.consoleAPICalled"
              and ev["params"].get("type") in ("error", "assert")):
            out.append(str(ev["params"].get("args")))
    return out


@needs_chromium
def test_session_sees_script_errors(tmp_path, session):
    """The control: a page with a deliberate error is caught by the session's checks."""
    page = tmp_path / "broken.html"
    page.write_text("<!DOCTYPE html><html><head>" + PROBE + "</head><body><script>"
                    "console.error('boom'); notDefined();</script></body></html>",
                    encoding="utf-8")
    probe_data = json.loads(_load(session, page, ("probe",))["probe"])
    assert any("notDefined" in e for e in probe_data["errors"])
    errs = _console_errors(session)
    assert any("boom" in e for e in errs) and any("Uncaught" in e for e in errs)


@needs_chromium
@pytest.mark.parametrize("case", PAGE_CASES)
def test_interactive_page_steps_drags_and_highlights(case, tmp_path, session):
    """Every shipped case: the page loads with no error and fetches nothing, Next/Back step
    through the stages one at a time, a slider drag redraws the mechanism at that frame of
    the sweep (the drawn points are the frame's points up to one similarity with y flipped),
    every label is inside its panel and at least 10 px high, no point label lies on a link,
    every polygon vertex is named, and hovering a link highlights exactly the polygon vectors
    that belong to it.  (One browser for every case; the page written in-process.)"""
    from polygons.cli.handout import write_page
    page = write_page(str(CASES / case), tmp_path / "page.html")
    text = page.read_text(encoding="utf-8")
    assert "http://" not in text.replace("http://www.w3.org/", "")
    assert "https://" not in text and "<link" not in text and " src=" not in text
    data = _page_data(text)
    k = (data["start"] + len(data["inputs"]) // 3) % len(data["inputs"])
    probed = tmp_path / "probed.html"
    probed.write_text(text.replace("<head>", "<head>\n" + PROBE + "\n"
                                   + DRIVE.replace("FRAME", str(k)), 1), encoding="utf-8")
    got = _load(session, probed)
    probe_data, drive = json.loads(got["probe"]), json.loads(got["drive"])
    assert probe_data["errors"] == [] and _console_errors(session) == []
    assert probe_data["resources"] == []
    assert "error" not in drive, drive
    names = re.findall(r'<figure class="stage" id="stage-[^"]+" data-name="([^"]+)"', text)
    assert drive["stages"] == len(names) >= 4 and drive["visible0"] == 1
    assert drive["names"] == [names[0], names[1], names[2], names[1]]
    assert drive["start"] == data["start"] and drive["frame"] == k
    assert drive["bad_start"] == [] and drive["bad"] == []
    assert drive["on_links_start"] == [] and drive["on_links"] == []
    # the drawn mechanism is frame k: one scale for every distance, y up becomes y down
    pts = {lab: data["pos"][lab][k] for lab in drive["points"]}
    labs = [lab for lab in pts if pts[lab][0] is not None]
    ratios = []
    for i, a in enumerate(labs):
        for b in labs[i + 1:]:
            si = math.dist(pts[a], pts[b])
            if si > 1e-6:
                ratios.append(math.dist(drive["points"][a], drive["points"][b]) / si)
    # (a lone input block, a plate under a rolling cylinder, is the only point drawn)
    assert ratios or len(labs) == 1, (labs, ratios)
    assert not ratios or max(ratios) == pytest.approx(min(ratios), rel=2e-3)
    a, b = labs[0], labs[-1]
    if abs(pts[b][1] - pts[a][1]) > 1e-6:
        assert (drive["points"][b][1] - drive["points"][a][1]) * (pts[b][1] - pts[a][1]) < 0
    moving = [lab for lab, v in data["vel"].items() if math.hypot(*v[k]) > 0]
    assert drive["vel_arrows"] == len([lab for lab in moving if lab in drive["points"]])
    for poly, shown in (("velocity", drive["vtext"]), ("acceleration", drive["atext"])):
        if poly in data["polys"] and k not in data["polys"][poly]["off"]:
            P = data["polys"][poly]           # (near a toggle a vertex may run off the panel)
            assert P["pole_label"] in shown
            for v in P["vx"]:
                assert P["names"][v] in shown, (poly, v, shown)
    if "acceleration" in data["polys"]:
        gone = drive["ghosts"]["acceleration"]     # arrows and image sides, but '≈ 0' ones
        assert sorted(drive["kinds"]) == sorted(s["c"] for s in data["polys"]["acceleration"]
                                                ["strokes"]
                                                if s["k"] != "arrow" or f'{s["f"]}>{s["t"]}' not in gone)
    for i, e in enumerate(data["edges"]):
        assert drive["hi"][str(i)]["link"] >= 1
        want = sorted(f'{s["f"]}>{s["t"]}' for d, P in data["polys"].items()
                      for s in P["strokes"] if s["link"] == e[2]
                      and (s["k"] != "arrow" or f'{s["f"]}>{s["t"]}' not in drive["ghosts"][d]))
        assert sorted(drive["hi"][str(i)]["polys"]) == want, (e, drive["hi"][str(i)])


SCALE = """<script>
window.addEventListener('load', function () {
  var P = window.polygonsPage, out = [];
  [[START, 1], [OTHER, 1], [START, 2]].forEach(function (fz) {
    P.zoom(fz[1]); P.setFrame(fz[0]);
    var tail = function (a, b) {
      var l = document.querySelector('#vpoly line.comp[data-from="' + a + '"][data-to="' + b + '"]');
      return [+l.getAttribute('x1'), +l.getAttribute('y1')];
    };
    var o = tail('o2', 'p4'), p = tail('p4', 'p2');
    out.push(Math.hypot(p[0] - o[0], p[1] - o[1]));
  });
  var pre = document.createElement('pre'); pre.id = 'scale';
  pre.textContent = JSON.stringify(out); document.body.appendChild(pre);
});
</script>"""


@needs_chromium
def test_live_polygon_keeps_one_scale_over_the_cycle(tmp_path, session):
    """Fig 7: the drawn length of o₂p₄ over |v_P4| is the same at two frames where |v_P4|
    differs (a polygon fitted to its panel at each frame would fail this); "× 2" doubles it."""
    from polygons.cli.handout import write_page
    text = write_page(str(CASES / "s003-fig7.toml"), tmp_path / "page.html").read_text(
        encoding="utf-8")
    data = _page_data(text)
    a, b = data["start"], (data["start"] + len(data["inputs"]) // 4) % len(data["inputs"])
    probed = tmp_path / "probed.html"
    probed.write_text(text.replace("<head>", "<head>\n" + SCALE.replace("START", str(a))
                                   .replace("OTHER", str(b)), 1), encoding="utf-8")
    px = json.loads(_load(session, probed, ("scale",))["scale"])
    v = [math.hypot(*data["vel"]["P4"][f]) for f in (a, b)]
    assert abs(v[0] - v[1]) > 0.2 * v[0]
    assert px[0] / v[0] == pytest.approx(px[1] / v[1], rel=2e-3)
    assert px[2] == pytest.approx(2 * px[0], rel=2e-3)          # × 2: twice, still one scale


def _tab_to(s, ident, limit=40):
    for _ in range(limit):
        s.press("Tab")
        if s.evaluate("document.activeElement.id") == ident:
            return
    raise AssertionError(f"Tab never reached #{ident}")


@needs_chromium
def test_drawing_mode_keyboard_only(tmp_path, session):
    """The "draw it yourself" mode worked with the keyboard alone (real key presses through
    the DevTools protocol): Tab to the polygon choice and a vertex, Enter, arrow keys at the
    stated 1 mm / 10 mm steps, Enter places and moves on; every vertex of Fig 7's acceleration
    polygon is placed where the true construction puts it at the stated scale; Save JSON and
    Save SVG (Tab, Enter) write the agreed JSON and an SVG with the vertex labels; the paper
    shows a focus ring and names itself to a screen reader."""
    import time
    import xml.etree.ElementTree as ET
    from polygons.cli.handout import write_page
    page = write_page(str(CASES / "s003-fig7.toml"), tmp_path / "page.html")
    data = _page_data(page.read_text(encoding="utf-8"))
    g = data["drawing"]["acceleration"]
    from polygons.evaluate import solve
    from polygons.options import scale_per_cm
    from polygons.scene import load_scene
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    k = 10.0 / scale_per_cm(g["scale"], "acceleration")        # mm per m/s²
    target = {v: [round(g["cursor"][0] + x * k), round(g["cursor"][1] + y * k)]
              for v, (x, y) in sol.vertices["acceleration"].items()}
    downloads = tmp_path / "downloads"
    downloads.mkdir()
    s = session
    s.downloads(downloads)
    s.open(page)
    _tab_to(s, "draw-diagram")
    s.press("ArrowDown")                                    # velocity → acceleration
    assert s.evaluate("window.polygonsDrawing.diagram()") == "acceleration"
    s.press("Tab")
    assert s.evaluate("document.activeElement.dataset.v") == g["vertices"][0]
    s.press("Enter")                                        # pick it: focus to the paper
    assert s.evaluate("document.activeElement.id") == "paper"
    ring = s.evaluate("getComputedStyle(document.getElementById('paper')).boxShadow")
    assert ring and ring != "none"
    label = s.evaluate("document.getElementById('paper').getAttribute('aria-label')")
    assert "acceleration polygon" in label and g["statement"] in label
    for v in g["vertices"]:
        assert s.evaluate("window.polygonsDrawing.selected()") == v
        cx, cy = s.evaluate("window.polygonsDrawing.cursor()")
        for d, pos, neg in ((target[v][0] - cx, "ArrowRight", "ArrowLeft"),
                            (target[v][1] - cy, "ArrowUp", "ArrowDown")):
            d = round(d)
            key = pos if d > 0 else neg
            if abs(d) >= 10:
                s.press(key, abs(d) // 10, shift=True)
            if abs(d) % 10:
                s.press(key, abs(d) % 10)
        assert s.evaluate("window.polygonsDrawing.cursor()") == target[v]
        s.press("Enter")
    status = s.evaluate("document.getElementById('draw-status').textContent")
    assert "every vertex is placed" in status
    _tab_to(s, "save-json", 3)
    s.press("Enter")
    _tab_to(s, "save-svg", 3)
    s.press("Enter")
    for _ in range(50):
        got = sorted(p.name for p in downloads.iterdir() if not p.name.endswith(".crdownload"))
        if len(got) == 2:
            break
        time.sleep(0.1)
    stem = "s003-fig7-acceleration-drawing"
    assert got == [f"{stem}.json", f"{stem}.svg"]
    drawn = json.loads((downloads / f"{stem}.json").read_text(encoding="utf-8"))
    assert set(drawn) == {"diagram", "scale", "vertices", "vectors"}
    assert drawn["diagram"] == "acceleration" and drawn["scale"] == g["scale"]
    assert drawn["vertices"] == target and drawn["vectors"] == g["vectors"]
    root = ET.fromstring((downloads / f"{stem}.svg").read_bytes())
    ns = "{http://www.w3.org/2000/svg}"
    words = [t.text for t in root.iter(f"{ns}text")]
    for v in g["vertices"]:
        assert g["labels"][v] in words
    assert root.get("width") == f'{g["paper"][0]:g}mm'
    assert len([e for e in root.iter(f"{ns}line") if e.get("data-from")]) == len(g["vectors"])
    assert "?" not in "".join(w for w in words if w)            # no cursor in the saved file
    assert root.get("data-polygons-drawing") == "acceleration"
    assert root.get("data-scale") == g["scale"]
    assert {e.get("data-vertex") for e in root.iter(f"{ns}circle")} == set(g["vertices"])
    import importlib.util
    if importlib.util.find_spec("polygons.drawing_format") is not None:
        # the grader (helper exam's `check --drawing`) passes both files, drawn on the truth
        for f in (f"{stem}.json", f"{stem}.svg"):
            res = polygons("check", CASES / "s003-fig7.toml", "--drawing", downloads / f)
            assert res.returncode == 0 and "all right" in res.stdout, res.stdout + res.stderr


def test_interactive_page_stages_are_the_static_svgs_and_output_is_deterministic(tmp_path):
    """The page's stage figures are the SVGs `polygons draw` writes (ids prefixed), so a
    stage on the page looks exactly as the static file; two runs give the same bytes."""
    case = CASES / "s001-sae4-q3.toml"
    for name in ("a.html", "b.html"):
        assert polygons_process("handout", case, "--interactive",      # two processes
                                "-o", tmp_path / name).returncode == 0
    text = (tmp_path / "a.html").read_text(encoding="utf-8")
    assert text == (tmp_path / "b.html").read_text(encoding="utf-8")
    assert polygons("draw", case, "-o", tmp_path / "svg").returncode == 0
    for svg in sorted((tmp_path / "svg").glob("*.svg")):
        static = svg.read_text(encoding="utf-8")
        texts = re.findall(r"<text\b[^>]*>.*?</text>", static, re.S)
        fig = re.search(rf'<figure class="stage" id="stage-{svg.stem}".*?</figure>', text, re.S)
        assert fig, svg.stem
        body = re.sub(r'\bid="st-[^"]*?-', 'id="', fig.group(0))
        assert texts and all(re.sub(r'\bid="[^"]*"', "", t) in re.sub(r'\bid="[^"]*"', "", body)
                             for t in texts), svg.stem
    data = _page_data(text)
    # the slider runs in the crank's sense of rotation (SAE4-Q3: CCW, angles increasing)
    ins = data["inputs"]
    assert data["sense"] == "CCW" and all(0 < (b - a) % 360 < 180 for a, b in zip(ins, ins[1:]))


@needs_chromium
def test_interactive_stage_screenshot_matches_the_static_svg(tmp_path, session):
    """A stage shown on the page looks as its static SVG does: Chromium's screenshot of the
    page, cropped to the stage figure, against Chromium's rendering of the SVG file at the
    same size — and unlike the next stage's SVG (so the comparison can fail)."""
    from PIL import Image
    import diagrams
    from polygons.cli.handout import write_page
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    case, k = CASES / "s001-sae4-q3.toml", 3
    page = write_page(str(case), tmp_path / "page.html")
    diagrams.write(solve(load_scene(case)), tmp_path / "svg")
    names = re.findall(r'data-name="([^"]+)"', page.read_text(encoding="utf-8"))
    session.open(page, f"#stage={k}")
    x, y, w, h = json.loads(session.evaluate(
        "(function () { var f = document.querySelector('figure.stage:not([hidden]) svg')"
        ".getBoundingClientRect(); return JSON.stringify([f.left + scrollX, f.top + scrollY,"
        " f.width, f.height]); })()"))
    clip = {"x": round(x), "y": round(y), "width": round(w), "height": round(h)}
    page_img = Image.open(session.screenshot(tmp_path / "page.png", clip)).convert("L")

    def static(name):
        wrap = tmp_path / f"{name}-wrap.html"
        wrap.write_text(f'<html><body style="margin:0"><img src="svg/{name}.svg" '
                        f'style="display:block;width:{w}px;height:{h}px"></body></html>',
                        encoding="utf-8")
        session.open(wrap)
        png = session.screenshot(tmp_path / f"{name}.png", {**clip, "x": 0, "y": 0})
        return Image.open(png).convert("L")

    def diff(a, b):
        """The share of pixels that differ strongly (by more than half the grey range):
        anti-aliasing moves edges by a shade, a missing or added stroke by black on white."""
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        return float((np.abs(a - b) > 128).mean())

    same = diff(page_img, static(names[k - 1]))
    other = diff(page_img, static(names[k]))
    print(f"pixels differing strongly: same stage {same:.2e}, next stage {other:.2e}")
    assert same < 1e-4 and other > 10 * same + 5e-5, (same, other)


@needs_chromium
def test_drawing_mode_by_mouse(tmp_path, session):
    """A click on the paper places the selected vertex there (to 0.5 mm, y up from the
    paper's lower edge) and selects the next one; the arrow between them appears."""
    from polygons.cli.handout import write_page
    page = write_page(str(CASES / "s001-we1.toml"), tmp_path / "page.html")
    data = _page_data(page.read_text(encoding="utf-8"))
    g = data["drawing"]["velocity"]
    W, H = g["paper"]
    session.open(page)
    session.evaluate("document.getElementById('paper').scrollIntoView()")
    r = json.loads(session.evaluate(          # the content box (the viewBox fills it)
        "(function () { var p = document.getElementById('paper'), b = p.getBoundingClientRect();"
        " return JSON.stringify({left: b.left + p.clientLeft, top: b.top + p.clientTop,"
        " width: p.clientWidth, height: p.clientHeight}); })()"))
    for v, (x, y) in zip(g["vertices"][:2], ((30.0, 40.0), (72.5, 61.0))):
        assert session.evaluate("window.polygonsDrawing.selected()") == v
        session.click(r["left"] + x * r["width"] / W, r["top"] + (H - y) * r["height"] / H)
    drawn = session.evaluate("window.polygonsDrawing.json()")
    a, b = g["vertices"][:2]
    assert drawn["vertices"] == {a: [30, 40], b: [72.5, 61]}
    assert drawn["vectors"] == [[a, b]] and [a, b] in g["vectors"]


@needs_chromium
def test_velocity_only_page_loads(tmp_path, session):
    """A scene solving the velocity diagram only: no script error, the acceleration panel
    hidden, the velocity polygon drawn."""
    from diagrams.page import page as make_page
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    text = (CASES / "s001-we1.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^(title = .*)$", r'\1\nsolve = ["velocity"]', text, count=1)
    scene = tmp_path / "v.toml"
    scene.write_text(text, encoding="utf-8")
    html = make_page(solve(load_scene(scene)), n=24)
    probed = tmp_path / "v.html"
    probed.write_text(html.replace("<head>", "<head>\n" + PROBE, 1), encoding="utf-8")
    probe_data = json.loads(_load(session, probed, ("probe",))["probe"])
    assert probe_data["errors"] == [] and _console_errors(session) == []
    assert session.evaluate("getComputedStyle(document.getElementById('apoly')).display") == "none"
    assert session.evaluate("document.querySelectorAll('#vpoly line.comp').length") >= 2


@needs_chromium
def test_hostile_title_is_text_on_the_page(tmp_path, session):
    """A title with markup and template names is shown as text: no script of it runs, the
    page's own script still does, the drawing saved as SVG stays well-formed XML."""
    import xml.etree.ElementTree as ET
    from diagrams.page import page as make_page
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    hostile = "X </script><script>window.pwned=1</script> <b>&amp; {CSS} {JS} <!-- '\""
    text = (CASES / "s001-we1.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^title = .*$", lambda m: f"title = {json.dumps(hostile)}", text, count=1)
    scene = tmp_path / "h.toml"
    scene.write_text(text, encoding="utf-8")
    html = make_page(solve(load_scene(scene)), n=24)
    probed = tmp_path / "h.html"
    probed.write_text(html.replace("<head>", "<head>\n" + PROBE, 1), encoding="utf-8")
    probe_data = json.loads(_load(session, probed, ("probe",))["probe"])
    assert probe_data["errors"] == [] and _console_errors(session) == []
    assert session.evaluate("window.pwned === undefined && !!window.polygonsPage")
    assert hostile in session.evaluate("document.querySelector('h1').textContent")
    assert hostile in session.evaluate("document.title")
    svg = session.evaluate("window.polygonsDrawing.svg()")
    root = ET.fromstring(svg.split("?>", 1)[1])
    assert hostile in root.find("{http://www.w3.org/2000/svg}title").text


# ---------------------------------------------------------------- grading in the page
def _drawing_data(d) -> dict:
    return {"diagram": d.diagram, "scale": d.scale, "scale_text": d.scale_text,
            "vertices": {n: list(p) for n, p in d.vertices.items()},
            "vectors": [list(v) for v in d.vectors]}


def _same(js, py, path="grade"):
    """The page's grade equals the Python grader's: every string and flag exactly, every
    number to 1e-9."""
    if isinstance(py, float) or isinstance(js, float):
        assert js is not None and py is not None, (path, js, py)
        assert math.isclose(js, py, rel_tol=1e-9, abs_tol=1e-9), (path, js, py)
    elif isinstance(py, dict):
        assert set(js) == set(py), (path, set(js) ^ set(py))
        for k in py:
            _same(js[k], py[k], f"{path}.{k}")
    elif isinstance(py, list):
        assert len(js) == len(py), (path, js, py)
        for i, (a, b) in enumerate(zip(js, py)):
            _same(a, b, f"{path}[{i}]")
    else:
        assert js == py, (path, js, py)


@needs_chromium
def test_page_grades_the_corpus_as_the_python_grader(tmp_path, session):
    """grade.js in the page, on the rules the page carries, grades every drawing of the
    corpus of typical errors (tests/data/drawings) exactly as `polygons check --drawing`:
    the same marks, problems, hints and notes, numbers to 1e-9, and the corpus's expected
    marks and feedback."""
    from drawing_corpus import CORPUS, DRAWINGS, case_of, check, mangled
    from polygons.cli._drawing import grade_json
    from polygons.cli.handout import write_page
    from polygons.drawing_format import read_drawing
    from polygons.grade_drawing import grade_rules
    by_case = {}
    for name in sorted(CORPUS):
        by_case.setdefault(case_of(name), []).append(name)
    for case, names in by_case.items():
        page = write_page(str(case), tmp_path / f"{case.stem}.html")
        data = _page_data(page.read_text(encoding="utf-8"))
        session.open(page)
        for name in names:
            d = read_drawing(str(DRAWINGS / CORPUS[name]["file"]))
            R = data["drawing"][d.diagram]["rules"]
            py = grade_json(grade_rules(R, d))
            js = session.evaluate(f"window.polygonsGrade.grade(JSON.parse(document."
                                  f"getElementById('frames').textContent).drawing"
                                  f"['{d.diagram}'].rules, {json.dumps(_drawing_data(d))})")
            _same(js, py, name)
            check(name, js)
        for name, d in mangled(60):            # random slips of every kind at once
            if case_of(name) != case:
                continue
            R = data["drawing"][d.diagram]["rules"]
            js = session.evaluate(f"window.polygonsGrade.grade(JSON.parse(document."
                                  f"getElementById('frames').textContent).drawing"
                                  f"['{d.diagram}'].rules, {json.dumps(_drawing_data(d))})")
            _same(js, grade_json(grade_rules(R, d)), d.file)
        assert not _console_errors(session)
    # an image vertex (bce similar to BCE) carried forward: a case with coupler points
    import importlib.util
    from polygons.drawing_format import StudentDrawing
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    spec = importlib.util.spec_from_file_location("make_corpus", DRAWINGS / "make_corpus.py")
    mk = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mk)
    case = CASES / "forces-actuator-four-bar.toml"
    sol = solve(load_scene(case))
    page = write_page(str(case), tmp_path / "four-bar.html")
    data = _page_data(page.read_text(encoding="utf-8"))
    session.open(page)
    for diagram in ("velocity", "acceleration"):
        steps = [st for st in sol.steps if st.diagram == diagram]
        R = data["drawing"][diagram]["rules"]
        assert any(e["image"] for e in R["expected"])
        k = data["drawing"][diagram]["si_per_mm"]
        for mods in ({}, {st.number: {"scale": 0.9, "turn": 3.0} for st in steps
                          if st.kind == "vector"}):
            P = mk.replay(sol, diagram, mods)
            d = StudentDrawing(diagram, k, "1 mm", {v: (p[0] / k + 50, p[1] / k + 40)
                                                    for v, p in P.items()},
                               tuple((e["start"], e["end"]) for e in R["expected"]), "<four-bar>")
            js = session.evaluate(f"window.polygonsGrade.grade(JSON.parse(document."
                                  f"getElementById('frames').textContent).drawing"
                                  f"['{diagram}'].rules, {json.dumps(_drawing_data(d))})")
            py = grade_json(grade_rules(R, d))
            _same(js, py, f"four-bar {diagram} {bool(mods)}")
            images = [v for v, e in zip(py["vectors"], R["expected"]) if e["image"]]
            assert images and all(v["mark"] == 1 for v in images)
    assert not _console_errors(session)


@needs_chromium
def test_page_shows_a_reversed_coriolis(tmp_path, session):
    """Draw it yourself, Fig 7's acceleration polygon with the Coriolis component reversed:
    "Check my drawing" marks p₄p₂′ ½ and says why (reversed, the drawn direction, the step),
    draws that arrow red, and keeps full marks for the steps built on it; a right drawing
    checks "all right"."""
    from drawing_corpus import DRAWINGS
    from polygons.cli.handout import write_page
    from polygons.drawing_format import read_drawing
    page = write_page(str(CASES / "s003-fig7.toml"), tmp_path / "page.html")
    session.open(page)
    session.evaluate("window.polygonsDrawing.choose('acceleration')")
    for f, right in (("fig7-a-coriolis-reversed.svg", False), ("fig7-a-right.json", True)):
        d = read_drawing(str(DRAWINGS / f))
        for v, p in d.vertices.items():
            session.evaluate(f"window.polygonsDrawing.set({json.dumps(v)}, {json.dumps(list(p))})")
        session.evaluate("document.getElementById('draw-check').click()")
        got = json.loads(session.evaluate(
            "JSON.stringify({text: document.getElementById('draw-grade').textContent,"
            " marks: Array.prototype.map.call(document.querySelectorAll('#draw-grade li[data-vector]'),"
            "   function (li) { return [li.dataset.vector, +li.dataset.mark]; }),"
            " wrong: Array.prototype.map.call(document.querySelectorAll('#paper line.wrong'),"
            "   function (l) { return [l.getAttribute('data-from'), l.getAttribute('data-to'),"
            "                          l.getAttribute('stroke')]; }),"
            " status: document.getElementById('draw-status').textContent})"))
        marks = dict(got["marks"])
        if right:
            assert "5 of 5 vectors — all right" in got["text"] and not got["wrong"]
            assert all(m == 1 for m in marks.values())
            continue
        assert marks["p4p2_1"] == 0.5 and marks["p4_1p4"] == 1 and marks["p2_1p2"] == 1
        assert "p₄p₂′" in got["text"] and "the Coriolis component is reversed" in got["text"]
        assert "acceleration step 6" in got["text"] and "p2_1" not in got["text"]
        assert ["p4", "p2_1", "#C00000"] in got["wrong"]
        assert "4.5 of 5" in got["status"]
    assert not _console_errors(session)
