"""How full each printed page is, measured on the PDF (what a reader turning the pages sees).

:func:`measure` renders each page of a PDF with poppler's ``pdftoppm`` (grey, 50 dpi) and
reads its text boxes with ``pdftotext -bbox-layout``; for each page it returns

* the **blocks**: the runs of inked rows inside the page's content area (the @page margins
  left out, so the page number in the bottom margin is not content), two blocks parted by at
  least :data:`GAP_MM` of blank paper;
* its **fill**: how far down the content area the last block reaches (0 … 1);
* its **headings**: the lines that print one of the document's headings (their texts given
  by the caller, e.g. :func:`headings_of` an HTML page's ``h1``–``h3``).

:func:`verdict` holds the pages against the rule (issue 33, "Pages"):

* a page other than the last under :data:`LOW_FILL` full whose next page opens with a block
  that would have fitted in the space left (``gap``): moving it back loses nothing;
* a last page without a heading holding less than :data:`TAIL_FILL` of a page (``tail``):
  the end of a table, a lone caption or a note cut off from what it belongs to.

A page under :data:`LOW_FILL` whose next block does not fit is reported (``low``), not
flagged: a drawing at its stated scale that needs more than the rest of the page.
The PDF measured is printed from :func:`outlined` HTML (every unbreakable block outlined,
which moves nothing).  Needs poppler-utils (``pdftoppm``, ``pdftotext``); nothing else in
the package does.
"""
from __future__ import annotations

import html as _html
import re
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

#: paper height (mm): every page of a handout is A4 portrait
A4_HEIGHT = 297.0
#: rendering resolution (dots per inch): 0.51 mm a row
DPI = 50
#: a grey level below this is ink (a drawing area's light grid included)
INK = 245
#: blank paper at least this tall (mm) parts two blocks
GAP_MM = 3.0
#: a page (not the last) filled less than this is low
LOW_FILL = 0.55
#: a last page without a heading filled less than this is a tail
TAIL_FILL = 0.30
#: a moved block needs this much more room than its height (mm: the margins around it)
SLACK_MM = 2.0


@dataclass(frozen=True)
class Page:
    """One printed page: its content area's height (mm), the blocks of ink in it (top,
    bottom in mm from the area's top), its heading lines and its first line of text."""
    number: int
    area_mm: float
    blocks: tuple[tuple[float, float], ...]
    headings: tuple[str, ...]
    first_text: str

    @property
    def fill(self) -> float:
        """How far down its content area the page's last block reaches (0 … 1)."""
        return self.blocks[-1][1] / self.area_mm if self.blocks else 0.0

    @property
    def free_mm(self) -> float:
        return self.area_mm - (self.blocks[-1][1] if self.blocks else 0.0)

    @property
    def first_block_mm(self) -> float:
        """The height of the page's first block (mm)."""
        return self.blocks[0][1] - self.blocks[0][0] if self.blocks else 0.0


@dataclass(frozen=True)
class Finding:
    page: int
    kind: str          # 'gap', 'tail' (defects) or 'low' (reported)
    text: str

    @property
    def defect(self) -> bool:
        return self.kind in ("gap", "tail")

    def __str__(self) -> str:
        return f"page {self.page}: {self.kind}: {self.text}"


#: drawn round every block a page break may not split (a figure, a drawing with its heading
#: and note, a drawing area with its own): an outline takes no room, so the pages break where
#: they did, and the block's ink is one run however much blank paper its drawing holds (not
#: round an explanation box in columns: Chromium leaves an empty fragment of one it pushes
#: on, and its outline would be ink at the foot of the page)
OUTLINE_CSS = ("<style>figure, section.plate div.sheet, section.area "
               "{ outline: 0.2mm solid #bbb; }</style>")


def outlined(page_html: str) -> str:
    """``page_html`` with :data:`OUTLINE_CSS` (to print for :func:`measure`)."""
    return page_html.replace("</head>", OUTLINE_CSS + "</head>", 1)


def _runs(ink_rows, mm_per_row: float) -> list[tuple[float, float]]:
    """(top, bottom) mm of each run of inked rows, runs parted by ≥ GAP_MM of blank."""
    gap = max(1, round(GAP_MM / mm_per_row))
    out: list[list[int]] = []
    blank = gap
    for i, inked in enumerate(ink_rows):
        if inked:
            if out and blank < gap:
                out[-1][1] = i + 1
            else:
                out.append([i, i + 1])
            blank = 0
        else:
            blank += 1
    return [(a * mm_per_row, b * mm_per_row) for a, b in out]


def _norm(text: str) -> str:
    return re.sub(r"[^0-9a-z]+", "", text.lower())


def headings_of(page_html: str) -> list[str]:
    """The texts of an HTML page's h1, h2 and h3 headings (outside its SVG drawings)."""
    body = re.sub(r"<svg\b.*?</svg>", " ", page_html, flags=re.S)
    out = []
    for m in re.finditer(r"<h([123])\b[^>]*>(.*?)</h\1>", body, flags=re.S):
        text = _html.unescape(re.sub(r"<[^>]+>", "", m.group(2))).strip()
        if _norm(text):
            out.append(text)
    return out


def _pgm(path: Path):
    """A binary greymap (P5, 8 bits: what ``pdftoppm -gray`` writes) as a numpy array."""
    import numpy as np
    data = path.read_bytes()
    m = re.match(rb"P5\s+(?:#[^\n]*\n\s*)*(\d+)\s+(\d+)\s+(\d+)\s", data)
    w, h = int(m.group(1)), int(m.group(2))
    return np.frombuffer(data, dtype=np.uint8, count=w * h, offset=m.end()).reshape(h, w)


def _text_lines(pdf: Path) -> list[list[tuple[float, float, str]]]:
    """Per page, its lines of text: (top, bottom in points, text)."""
    out = subprocess.run(["pdftotext", "-bbox-layout", str(pdf), "-"], capture_output=True,
                         text=True, timeout=120, check=True).stdout
    pages = []
    for page in re.findall(r"<page\b.*?</page>", out, flags=re.S):
        lines = []
        for m in re.finditer(r'<line xMin="[^"]*" yMin="([^"]*)" xMax="[^"]*" '
                             r'yMax="([^"]*)">(.*?)</line>', page, flags=re.S):
            words = re.findall(r"<word[^>]*>(.*?)</word>", m.group(3), flags=re.S)
            lines.append((float(m.group(1)), float(m.group(2)),
                          _html.unescape(" ".join(words))))
        lines.sort()
        pages.append(lines)
    return pages


def measure(pdf, margins: tuple[float, float] = (10.0, 10.0),
            headings: list[str] = ()) -> list[Page]:
    """The pages of ``pdf`` measured (``margins``: the @page top and bottom margins, mm;
    ``headings``: the document's heading texts, found again on the pages)."""
    pdf = Path(pdf)
    top, bottom = margins
    wanted = [_norm(h) for h in headings]
    lines = _text_lines(pdf)
    pages = []
    with tempfile.TemporaryDirectory(prefix="polygons-fill-") as tmp:
        subprocess.run(["pdftoppm", "-r", str(DPI), "-gray", str(pdf), f"{tmp}/p"],
                       check=True, timeout=300, capture_output=True)
        files = sorted(Path(tmp).glob("p-*.pgm"), key=lambda p: int(p.stem.split("-")[-1]))
        for n, f in enumerate(files, 1):
            grey = _pgm(f)
            mm_row = A4_HEIGHT / grey.shape[0]
            r0, r1 = round(top / mm_row), grey.shape[0] - round(bottom / mm_row)
            ink = (grey[r0:r1] < INK).any(axis=1)
            area = (r1 - r0) * mm_row
            page_lines = lines[n - 1] if n - 1 < len(lines) else []
            heads = []
            for _, _, text in page_lines:
                t = _norm(text)
                if t and any(w and (t.startswith(w) or w.startswith(t) and len(t) > 6)
                             for w in wanted):
                    heads.append(text)
            first = page_lines[0][2] if page_lines else ""
            pages.append(Page(n, area, tuple(_runs(ink, mm_row)), tuple(heads), first))
    return pages


def verdict(pages: list[Page]) -> list[Finding]:
    """The findings of :func:`measure`'s pages: ``gap`` and ``tail`` are defects (see the
    module's docstring), ``low`` a page under :data:`LOW_FILL` whose next block is too tall."""
    out = []
    for i, p in enumerate(pages[:-1]):
        if p.fill >= LOW_FILL:
            continue
        nxt = pages[i + 1]
        need = nxt.first_block_mm + SLACK_MM
        what = (f"{p.fill:.0%} full, {p.free_mm:.0f} mm free; the next page opens with a "
                f"{nxt.first_block_mm:.0f} mm block ({nxt.first_text[:50]!r})")
        out.append(Finding(p.number, "gap" if need <= p.free_mm else "low", what))
    if len(pages) > 1:
        last = pages[-1]
        if not last.headings and last.fill < TAIL_FILL:
            out.append(Finding(last.number, "tail", f"{last.fill:.0%} full, no heading: "
                                                    f"{last.first_text[:60]!r} …"))
    return out


def report(pages: list[Page]) -> str:
    """One line: the page count and each page's fill ('4 pages: 97 % 88 % 91 % 40 %')."""
    return f"{len(pages)} pages: " + " ".join(f"{p.fill:.0%}" for p in pages)


__all__ = ["Page", "Finding", "measure", "verdict", "report", "headings_of", "outlined"]
