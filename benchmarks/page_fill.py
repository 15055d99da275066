"""How full every printed page is: each case's answer key and worksheet, and the exam
worksheets of a few cases, printed by headless Chromium (the product's own print path,
:func:`diagrams.browser.print_pdf`) and measured on the PDF (:mod:`diagrams.page_fill`).

    python benchmarks/page_fill.py                  # every case: key + worksheet, exams
    python benchmarks/page_fill.py CASE ...         # only these (file stems or paths)
    python benchmarks/page_fill.py --exam-only      # only the exam worksheets
    python benchmarks/page_fill.py --jobs 1         # one Chromium at a time (default 2)

One line per document: its page count, each page's fill (how far down its content area the
last block of ink reaches) and the findings: ``gap`` — a page other than the last under
55 % full whose next page opens with a block that would have fitted there; ``tail`` — a last
page without a heading under 30 % full (a table's tail, a lone caption); ``low`` (reported,
not a defect) — a page under 55 % whose next block is taller than the room left.  Ends with
the page-count histogram of the keys and worksheets and every defect; exit status 1 when
there is one.  Needs Chromium and poppler-utils.  ~4 min for everything on a quiet 2-core
machine (most of it Chromium).
"""
from __future__ import annotations

import argparse
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

#: the exam worksheets measured: (case, variants, seed) — Fig 7 as the README's command
EXAMS = (("s003-fig7", 12, 2026), ("s001-we4", 6, 1), ("s001-we6", 6, 1),
         ("s001-we3", 6, 1), ("new-watt-six-bar", 4, 1))


def documents(path: Path):
    """(name, html) of a case's answer key and worksheet (the CLI's own build)."""
    from polygons.cli.handout import build
    yield f"{path.stem} key", build(str(path))
    yield f"{path.stem} worksheet", build(str(path), worksheet=True)


def exam_documents(stem: str, n: int, seed: int):
    """(name, html) of the worksheets of ``n`` variants of an exam of case ``stem``."""
    from diagrams import exam_sheets
    from polygons.exam import make_exam
    exam = make_exam(str(ROOT / "cases" / f"{stem}.toml"), n, seed)
    for v in exam.variants:
        yield (f"{stem} exam v{v.number:02d}",
               exam_sheets.worksheet_html(v, None, exam_sheets.finished(v)))


def measure_html(name: str, text: str, tmp: Path):
    """(name, pages, findings) of one HTML document printed to PDF."""
    from diagrams.browser import print_pdf
    from diagrams.page_fill import headings_of, measure, outlined, verdict
    stem = tmp / name.replace(" ", "_").replace(".", "_")
    html = stem.with_suffix(".html")
    html.write_text(outlined(text), encoding="utf-8")
    pdf = print_pdf(html, stem.with_suffix(".pdf"))
    pages = measure(pdf, headings=headings_of(text))
    return name, pages, verdict(pages)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("cases", nargs="*")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--exam-only", action="store_true")
    ap.add_argument("--no-exam", action="store_true")
    ap.add_argument("--keep", metavar="DIR", help="keep the HTML and PDF files here")
    args = ap.parse_args(argv)
    from diagrams.page_fill import report
    from polygons.errors import PolygonsError
    paths = [Path(c) if c.endswith(".toml") else ROOT / "cases" / f"{c}.toml"
             for c in args.cases] or sorted((ROOT / "cases").glob("*.toml"))
    t0 = time.perf_counter()
    tmp_ctx = tempfile.TemporaryDirectory(prefix="page-fill-")
    tmp = Path(args.keep) if args.keep else Path(tmp_ctx.name)
    tmp.mkdir(parents=True, exist_ok=True)

    def jobs():
        if not args.exam_only:
            for p in paths:
                try:
                    yield from documents(p)
                except PolygonsError as exc:           # a case without a handout
                    print(f"{p.stem}: no handout ({exc})", flush=True)
        if not args.no_exam:
            for stem, n, seed in EXAMS:
                if args.cases and stem not in {Path(c).stem for c in args.cases}:
                    continue
                yield from exam_documents(stem, n, seed)

    counts = {"key": Counter(), "worksheet": Counter()}
    defects = []
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(measure_html, name, text, tmp) for name, text in jobs()]
        for fut in futures:
            name, pages, found = fut.result()
            kind = name.split()[-1]
            if kind in counts:
                counts[kind][len(pages)] += 1
            marks = "; ".join(str(f) for f in found)
            print(f"{name:44s} {report(pages)}" + (f"   [{marks}]" if marks else ""),
                  flush=True)
            defects += [(name, f) for f in found if f.defect]
    tmp_ctx.cleanup()
    for kind, c in counts.items():
        if c:
            print(f"{kind}s (pages: documents): "
                  + ", ".join(f"{k}: {c[k]}" for k in sorted(c)))
    print(f"{len(defects)} defects" + "".join(f"\n  {n}: {f}" for n, f in defects))
    print(f"({time.perf_counter() - t0:.0f} s)")
    return 1 if defects else 0


if __name__ == "__main__":
    sys.exit(main())
