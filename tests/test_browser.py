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

from conftest import CASES

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
                                            ("s001-we6.toml", True)])
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
  try {
    var P = window.polygonsPage, names = [];
    out.stages = P.stages;
    out.visible0 = document.querySelectorAll('figure.stage:not([hidden])').length;
    names.push(P.stage()); P.next(); names.push(P.stage()); P.next(); names.push(P.stage());
    P.back(); names.push(P.stage());
    out.names = names;
    out.start = P.frame();
    var s = document.getElementById('angle');
    s.value = String(FRAME); s.dispatchEvent(new Event('input'));       // a drag's events
    out.frame = P.frame();
    out.points = {};
    document.querySelectorAll('#mech circle[data-point]').forEach(function (c) {
      out.points[c.getAttribute('data-point')] = [+c.getAttribute('cx'), +c.getAttribute('cy')];
    });
    out.vel_arrows = document.querySelectorAll('#mech line.vel').length;
    out.vlabels = document.querySelectorAll('#vpoly text[data-label]').length;
    out.alabels = document.querySelectorAll('#apoly text[data-label]').length;
    P.hover(0);
    out.hi = document.querySelectorAll('.hi').length;
    out.hi_polys = document.querySelectorAll('#vpoly .hi, #apoly .hi').length;
  } catch (e) { out.error = String(e); }
  var pre = document.createElement('pre'); pre.id = 'drive';
  pre.textContent = JSON.stringify(out); document.body.appendChild(pre);
});
</script>"""

PAGE_CASES = [p.name for p in sorted(CASES.glob("*.toml"))]


def _page_data(text: str) -> dict:
    m = re.search(r'<script type="application/json" id="frames">(.*?)</script>', text, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


@needs_chromium
@pytest.mark.parametrize("case", PAGE_CASES)
def test_interactive_page_steps_drags_and_highlights(case, tmp_path):
    """Every shipped case: the page loads with no error and fetches nothing, Next/Back step
    through the stages one at a time, a slider drag redraws the mechanism at that frame of
    the sweep (the drawn points are the frame's points up to one similarity with y flipped)
    and hovering a link highlights its relative vectors in both polygons."""
    page = tmp_path / "page.html"
    out = polygons("handout", CASES / case, "--interactive", "-o", page)
    assert out.returncode == 0, out.stderr
    text = page.read_text(encoding="utf-8")
    assert "http://" not in text.replace("http://www.w3.org/", "")
    assert "https://" not in text and "<link" not in text and " src=" not in text
    data = _page_data(text)
    k = (data["start"] + len(data["inputs"]) // 3) % len(data["inputs"])
    probed = tmp_path / "probed.html"
    probed.write_text(text.replace("<head>", "<head>\n" + PROBE + "\n"
                                   + DRIVE.replace("FRAME", str(k)), 1), encoding="utf-8")
    res = browser.dump_dom(probed)
    m = re.search(r'<pre id="probe">(.*?)</pre>', res.stdout, re.S)
    d = re.search(r'<pre id="drive">(.*?)</pre>', res.stdout, re.S)
    assert m and d, res.stderr[-400:]
    probe_data = json.loads(htmllib.unescape(m.group(1)))
    drive = json.loads(htmllib.unescape(d.group(1)))
    assert probe_data["errors"] == [] and console_errors(res.stderr) == []
    assert probe_data["resources"] == []
    assert "error" not in drive, drive
    names = re.findall(r'<figure class="stage" id="stage-[^"]+" data-name="([^"]+)"', text)
    assert drive["stages"] == len(names) >= 4 and drive["visible0"] == 1
    assert drive["names"] == [names[0], names[1], names[2], names[1]]
    assert drive["start"] == data["start"] and drive["frame"] == k
    # the drawn mechanism is frame k: one scale for every distance, y up becomes y down
    pts = {lab: data["pos"][lab][k] for lab in drive["points"]}
    labs = [lab for lab in pts if pts[lab][0] is not None]
    ratios = []
    for i, a in enumerate(labs):
        for b in labs[i + 1:]:
            si = math.dist(pts[a], pts[b])
            if si > 1e-6:
                ratios.append(math.dist(drive["points"][a], drive["points"][b]) / si)
    assert ratios and max(ratios) == pytest.approx(min(ratios), rel=2e-3)
    a, b = labs[0], labs[-1]
    if abs(pts[b][1] - pts[a][1]) > 1e-6:
        assert (drive["points"][b][1] - drive["points"][a][1]) * (pts[b][1] - pts[a][1]) < 0
    moving = [lab for lab, v in data["vel"].items() if math.hypot(*v[k]) > 0]
    assert drive["vlabels"] == len(data["vel"]) and drive["alabels"] == len(data["acc"])
    assert drive["vel_arrows"] == len([lab for lab in moving if lab in drive["points"]])
    assert drive["hi"] >= 1
    if moving:            # a link's relative vectors light up in both polygons
        assert drive["hi_polys"] >= 2


def test_interactive_page_stages_are_the_static_svgs_and_output_is_deterministic(tmp_path):
    """The page's stage figures are the SVGs `polygons draw` writes (ids prefixed), so a
    stage on the page looks exactly as the static file; two runs give the same bytes."""
    case = CASES / "s001-sae4-q3.toml"
    for name in ("a.html", "b.html"):
        assert polygons("handout", case, "--interactive", "-o", tmp_path / name).returncode == 0
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
    assert data["sense"] == "CCW" and all(b > a for a, b in zip(ins, ins[1:]))


RECT = """<script>
window.addEventListener('load', function () {
  var f = document.querySelector('figure.stage:not([hidden]) svg').getBoundingClientRect();
  var pre = document.createElement('pre'); pre.id = 'rect';
  pre.textContent = JSON.stringify([f.left, f.top, f.width, f.height]);
  document.body.appendChild(pre);
});
</script>"""


@needs_chromium
def test_interactive_stage_screenshot_matches_the_static_svg(tmp_path):
    """A stage shown on the page looks as its static SVG does: Chromium's screenshot of the
    page, cropped to the stage figure, against Chromium's rendering of the SVG file at the
    same size — and unlike the next stage's SVG (so the comparison can fail)."""
    from PIL import Image
    case, k = CASES / "s001-sae4-q3.toml", 3
    page = tmp_path / "page.html"
    assert polygons("handout", case, "--interactive", "-o", page).returncode == 0
    assert polygons("draw", case, "-o", tmp_path / "svg").returncode == 0
    names = re.findall(r'data-name="([^"]+)"', page.read_text(encoding="utf-8"))
    size = "--window-size=1400,1000"
    text = page.read_text(encoding="utf-8").replace("<head>", "<head>\n" + RECT, 1)
    probed = tmp_path / "probed.html"
    probed.write_text(text, encoding="utf-8")
    url = probed.resolve().as_uri() + f"#stage={k}"
    out = browser.run(url, "--dump-dom", size, "--virtual-time-budget=3000")
    x, y, w, h = json.loads(re.search(r'<pre id="rect">(.*?)</pre>', out.stdout).group(1))
    shot = tmp_path / "page.png"
    browser.run(url, f"--screenshot={shot}", size, "--virtual-time-budget=3000")
    page_img = Image.open(shot).convert("L").crop((round(x), round(y), round(x + w),
                                                   round(y + h)))

    def static(name):
        wrap = tmp_path / f"{name}-wrap.html"
        wrap.write_text(f'<html><body style="margin:0"><img src="svg/{name}.svg" '
                        f'style="display:block;width:{w}px;height:{h}px"></body></html>',
                        encoding="utf-8")
        png = tmp_path / f"{name}.png"
        browser.run(wrap, f"--screenshot={png}", f"--window-size={round(w) + 20},"
                    f"{round(h) + 20}")
        return Image.open(png).convert("L").crop((0, 0, round(w), round(h)))

    def diff(a, b):
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        return float(np.abs(a - b).mean())

    same = diff(page_img, static(names[k - 1]))
    other = diff(page_img, static(names[k]))
    print(f"mean |difference|: same stage {same:.2f}, next stage {other:.2f} (of 255)")
    assert same < 3.0 and other > 2 * same, (same, other)
