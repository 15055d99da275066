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
