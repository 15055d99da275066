"""How full the printed pages are (issue 33, "Pages"), measured on the PDF Chromium prints
(:mod:`diagrams.page_fill`): no page but the last under 55 % full when the next page's first
block would have fitted on it, no last page holding only a table's tail or a lone caption.

Always: the measure itself on made-up pages (no browser), and Fig 7's worksheet printed once
(~2 s: its space diagram beside the data on page 1, which it left half empty; the drawing
areas' notes whole; no command line on paper).  ``POLYGONS_PAGE_FILL=1`` prints every shipped
case's key and worksheet and the exam worksheets of benchmarks/page_fill.py (~5 min):
no defect, and no key over 6 pages.
"""
import os
import re
import shutil
import subprocess
import sys

import pytest

from conftest import CASES, ROOT, case_files
from diagrams.page_fill import GAP_MM, Page, _runs, headings_of, measure, outlined, verdict

sys.path.insert(0, str(ROOT / "benchmarks"))


def _tools():
    from diagrams.browser import find
    if find() is None or not (shutil.which("pdftoppm") and shutil.which("pdftotext")):
        pytest.skip("needs headless Chromium and poppler-utils (pdftoppm, pdftotext)")


# ---------------------------------------------------------------- the measure (no browser)
def test_blocks_are_runs_of_ink_parted_by_blank_paper():
    mm = 0.5
    gap = int(GAP_MM / mm)
    rows = [False] * 4 + [True] * 10 + [False] * (gap - 1) + [True] * 6 + [False] * gap \
        + [True] * 2 + [False] * 3
    assert _runs(rows, mm) == [(2.0, 2.0 + 0.5 * (10 + gap - 1 + 6)),
                               (0.5 * (20 + 2 * gap - 1), 0.5 * (22 + 2 * gap - 1))]
    assert _runs([False] * 9, mm) == []


def _page(n, blocks, heads=(), text="x"):
    return Page(n, 277.0, tuple(blocks), tuple(heads), text)


def test_verdict_flags_a_movable_gap_and_a_tail_not_a_tall_drawing():
    full = _page(1, [(0, 270)], ["1. The problem"])
    half = _page(2, [(0, 100)], ["3. The velocity diagram"])        # 36 % full, 177 mm free
    fits = _page(3, [(0, 150), (160, 270)], ["Draw it here"])      # a 150 mm block: fits
    tall = _page(3, [(0, 200), (205, 270)], ["Draw it here"])      # 200 mm: does not
    tail = _page(4, [(0, 40)], (), "v_P4 velocity of P4 m/s")      # no heading, 14 %
    found = verdict([full, half, fits, tail])
    assert [(f.page, f.kind) for f in found] == [(2, "gap"), (4, "tail")]
    assert all(f.defect for f in found) and "150 mm block" in str(found[0])
    found = verdict([full, half, tall, _page(4, [(0, 40)], ["5. Your answers"])])
    assert [(f.page, f.kind, f.defect) for f in found] == [(2, "low", False)]
    assert verdict([_page(1, [(0, 20)])]) == []                    # one short page: fine


def test_headings_are_read_outside_the_drawings_and_outlines_take_no_room():
    page = ('<html><head><style></style></head><body><h1>T &amp; U</h1><svg><text>'
            '<h2>no</h2></text></svg><h2>1. <em>The</em> problem</h2><h3>Data</h3></body>'
            '</html>')
    assert headings_of(page) == ["T & U", "1. The problem", "Data"]
    out = outlined(page)
    assert out.count("<style>") == 2 and "outline:" in out and "border" not in out.split(
        "</head>")[0].split("<style>")[-1]


# ---------------------------------------------------------------- Fig 7's worksheet, printed
@pytest.fixture(scope="module")
def fig7_sheet(tmp_path_factory):
    """Fig 7's worksheet as the CLI builds it, printed once (outlined: the measure's blocks;
    an outline moves nothing): (html, pdf, its text, its pages measured)."""
    _tools()
    from diagrams.browser import print_pdf
    from polygons.cli.handout import build
    tmp = tmp_path_factory.mktemp("fill")
    text = build(str(CASES / "s003-fig7.toml"), worksheet=True)
    html = tmp / "fig7-ws.html"
    html.write_text(outlined(text), encoding="utf-8")
    pdf = print_pdf(html, tmp / "fig7-ws.pdf")
    words = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True,
                           timeout=60).stdout
    return text, pdf, re.sub(r"\s+", " ", words), measure(pdf, headings=headings_of(text))


def test_fig7_worksheet_has_its_space_diagram_beside_the_data_on_page_1(fig7_sheet):
    text, pdf, _, pages = fig7_sheet
    assert '<div class="beside">' in text and '<section class="plate beside" id="space"' in text
    assert len(pages) <= 4, [p.fill for p in pages]                # 5 before
    first = pages[0]
    assert any(h.startswith("2. The space") for h in first.headings) and first.fill > 0.85, first
    page1 = subprocess.run(["pdftotext", "-f", "1", "-l", "1", str(pdf), "-"],
                           capture_output=True, text=True, timeout=60).stdout
    assert "Full size (1 cm = 50 mm)" in re.sub(r"\s+", " ", page1)
    assert not [f for f in verdict(pages) if f.defect], verdict(pages)


def test_printed_worksheet_keeps_notes_whole_and_no_command_line(fig7_sheet):
    _, _, words, _ = fig7_sheet
    assert words.count("start here") == 2          # each drawing area's pole note, whole
    assert "polygons check" not in words and "regenerate" not in words
    assert "Your answers" in words


# ---------------------------------------------------------------- every case (opt-in)
ALL = os.environ.get("POLYGONS_PAGE_FILL")


@pytest.mark.skipif(not ALL, reason="POLYGONS_PAGE_FILL=1 prints every case (~5 min)")
def test_every_printed_page_is_filled(tmp_path):
    _tools()
    import page_fill as bench
    from polygons.errors import PolygonsError
    docs = []
    for path in case_files():
        try:
            docs += list(bench.documents(path))
        except PolygonsError:
            continue
    for stem, n, seed in bench.EXAMS:
        docs += list(bench.exam_documents(stem, n, seed))
    bad, long = [], []
    for name, html in docs:
        _, pages, found = bench.measure_html(name, html, tmp_path)
        bad += [f"{name}: {f}" for f in found if f.defect]
        if name.endswith(" key") and len(pages) > 6:
            long.append(f"{name}: {len(pages)} pages")
    assert not bad and not long, "\n".join(bad + long)
