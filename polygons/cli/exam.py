"""``polygons exam SCENE --variants N --seed S --out DIR``: seeded exam variants for a class.

Writes into DIR (made if missing; every file is created new — an existing file or link of
that name is refused, so nothing is written through a link, over the scene or the class list): ``quiz.xml`` (Moodle XML), ``quiz.gift`` (GIFT),
``quiz-qti.zip`` (QTI 1.2, Canvas), ``key.pdf`` (the teacher's key) and ``worksheets/`` (one
PDF per variant, or per student with ``--students names.csv``).  PDFs are printed by headless
Chromium; without it the command says so in one line and writes the HTML instead.  What
varies and what is asked come from the scene's ``[exam]`` table (:mod:`polygons.exam_table`;
without one, the crank angle round the turn and the scene's ``[[answers]]``).
"""
from __future__ import annotations

import csv
import io
from pathlib import Path

from ..errors import PolygonsError, SceneError

#: most students of one class list (the same bound as the variants)
MAX_STUDENTS = 500
MAX_CLASS_LIST = 1_000_000      # bytes
#: the default and the largest worst-case work budget (minutes)
BUDGET_MIN, MAX_BUDGET_MIN = 10.0, 24 * 60.0


class ExamError(PolygonsError):
    """A bad option of ``polygons exam``."""


def register(sub) -> None:
    from ..exam import MAX_VARIANTS
    p = sub.add_parser(
        "exam", help="seeded exam variants: Moodle XML, GIFT, QTI, key and worksheets",
        description="Write N well-posed variants of a scene (its [exam] table says "
                    "what varies and what is asked) as a Moodle XML quiz, GIFT, a QTI 1.2 "
                    "package, the teacher's key and one worksheet per variant or student. "
                    "The same seed gives the same files.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--variants", type=int, required=True, metavar="N",
                   help=f"how many variants, 1 .. {MAX_VARIANTS}")
    p.add_argument("--seed", type=int, default=1, help="random seed (default 1)")
    p.add_argument("--out", required=True, metavar="DIR", help="output folder")
    p.add_argument("--students", metavar="CSV",
                   help=f"class list, one name per line (first column; at most "
                        f"{MAX_STUDENTS}): one worksheet per student, variants dealt in turn")
    p.add_argument("--budget", type=float, default=BUDGET_MIN, metavar="MINUTES",
                   help=f"the most worst-case work to start (default {BUDGET_MIN:g} min, at "
                        f"most {MAX_BUDGET_MIN:g}): the draws an exam may need (variants × "
                        f"attempts) are estimated before any work and refused above it")
    p.add_argument("--html", action="store_true",
                   help="write the key and worksheets as HTML (no Chromium needed)")
    p.set_defaults(func=run)


def read_students(path: str) -> list[str]:
    p = Path(path)
    if not p.is_file():
        raise ExamError(f"--students {path}: no such file")
    raw = p.read_bytes()[:MAX_CLASS_LIST + 1]
    if len(raw) > MAX_CLASS_LIST:
        raise ExamError(f"--students {path}: larger than {MAX_CLASS_LIST:,} bytes")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ExamError(f"--students {path}: not UTF-8 text") from None
    names = []
    try:
        for row in csv.reader(io.StringIO(text)):
            name = " ".join("".join(c for c in row[0] if c.isprintable() or c.isspace())
                            .split()) if row else ""
            if name and not (not names and name.lower() in ("name", "student", "names")):
                names.append(name[:200])
    except csv.Error as exc:
        raise ExamError(f"--students {path}: not a CSV class list ({exc})") from None
    if not names:
        raise ExamError(f"--students {path}: no names (one name per line)")
    if len(names) > MAX_STUDENTS:
        raise ExamError(f"--students {path}: {len(names)} names; at most {MAX_STUDENTS}")
    return names


def _out_dir(out: str) -> Path:
    d = Path(out)
    if d.exists() and not d.is_dir():
        raise ExamError(f"--out {out} exists and is not a folder")
    d.mkdir(parents=True, exist_ok=True)
    return d


def _sub_dir(d: Path) -> Path:
    """A folder inside --out, made new or already a real folder (never a link)."""
    if d.is_symlink():
        raise ExamError(f"{d} is a symbolic link: refusing to write through it")
    if d.exists() and not d.is_dir():
        raise ExamError(f"{d} exists and is not a folder")
    d.mkdir(exist_ok=True)
    return d


def _write(path: Path, data: bytes, protect: set[Path]) -> Path:
    """Create ``path`` new (O_CREAT | O_EXCL | O_NOFOLLOW): an existing file, folder or
    symbolic link of that name is refused, so nothing is written through a link or over
    an input."""
    import os
    if path.is_symlink():
        raise ExamError(f"{path} is a symbolic link: refusing to write through it")
    if path.resolve() in protect:
        raise ExamError(f"{path} is an input file: refusing to write over it")
    if path.exists():
        what = "a folder" if path.is_dir() else "a file"
        raise ExamError(f"{path} exists ({what}): refusing to write over it; choose a new "
                        f"--out folder or remove it")
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) \
        | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(path, flags, 0o644)
    except FileExistsError:
        raise ExamError(f"{path} appeared while writing: refusing to write over it") from None
    except OSError as exc:
        raise ExamError(f"cannot create {path}: {exc.strerror}") from None
    with os.fdopen(fd, "wb") as f:
        f.write(data)
    return path


def run(args) -> int:
    from ..exam import MAX_VARIANTS, make_exam
    from ..exam import lms
    if not 1 <= args.variants <= MAX_VARIANTS:
        raise ExamError(f"--variants must be from 1 to {MAX_VARIANTS}, got {args.variants}")
    if not 0 <= args.seed < 2 ** 63:
        raise ExamError(f"--seed must be from 0 to 2^63 - 1, got {args.seed}")
    import math
    if not (math.isfinite(args.budget) and 0 < args.budget <= MAX_BUDGET_MIN):
        raise ExamError(f"--budget is minutes, more than 0 and at most {MAX_BUDGET_MIN:g}, "
                        f"got {args.budget:g}")
    students = read_students(args.students) if args.students else None
    protect = {Path(args.scene).resolve()}
    if args.students:
        protect.add(Path(args.students).resolve())
    exam = make_exam(args.scene, args.variants, args.seed, budget_s=args.budget * 60.0)
    out = _out_dir(args.out)
    for name in ("quiz.xml", "quiz.gift", "quiz-qti.zip", "key.pdf", "key.html"):
        if (out / name).is_symlink() or (out / name).exists():    # before writing any
            _write(out / name, b"", protect)
    sheets_dir = _sub_dir(out / "worksheets")

    from diagrams import exam_sheets as sheets
    from diagrams.browser import TIMEOUT, BrowserError, find, run as chromium

    def print_pdf(html_path: Path, pdf_path: Path, timeout: int) -> Path:
        """diagrams.browser.print_pdf with a timeout that grows with the key."""
        out = chromium(html_path, f"--print-to-pdf={pdf_path.resolve()}",
                       "--no-pdf-header-footer", "--run-all-compositor-stages-before-draw",
                       timeout=timeout)
        if not pdf_path.exists() or pdf_path.stat().st_size == 0:
            last = (out.stderr.strip().splitlines() or ["no message"])[-1]
            raise BrowserError(f"Chromium did not write {pdf_path.name} (exit "
                               f"{out.returncode}: {last})")
        return pdf_path
    figs = {v.number: sheets.finished(v) for v in exam.variants}
    images = {v.number: sheets.space_svg(v, figs[v.number]) for v in exam.variants}
    written = [_write(out / "quiz.xml", lms.moodle_xml(exam, images), protect),
               _write(out / "quiz.gift", lms.gift(exam).encode("utf-8"), protect),
               _write(out / "quiz-qti.zip", lms.qti_zip(exam, images), protect)]

    pdf = not args.html and find() is not None
    if not args.html and not pdf:
        print("Chromium not found (Debian: apt-get install chromium; or set "
              "POLYGONS_CHROMIUM): writing the key and worksheets as HTML")

    def document(html_text: str, stem: Path, timeout: int = TIMEOUT) -> Path:
        html_path = stem.with_suffix(".html")
        if not pdf:
            return _write(html_path, html_text.encode("utf-8"), protect)
        import tempfile
        with tempfile.TemporaryDirectory(prefix="polygons-exam-") as tmp:
            tmp_html = Path(tmp) / "doc.html"
            tmp_html.write_text(html_text, encoding="utf-8")
            tmp_pdf = print_pdf(tmp_html, Path(tmp) / "doc.pdf", timeout)
            data = sheets.pdf_stable(tmp_pdf.read_bytes())
        return _write(stem.with_suffix(".pdf"), data, protect)

    # the key grows with the class: ~0.3 s of Chromium per variant
    written.append(document(sheets.key_html(exam, figs), out / "key",
                            TIMEOUT + len(exam.variants)))
    if students:
        for i, name in enumerate(students):
            v = exam.variants[i % len(exam.variants)]
            stem = sheets_dir / f"{i + 1:03d}-{sheets.safe_name(name)}-v{v.number:02d}"
            written.append(document(sheets.worksheet_html(v, name, figs[v.number]), stem))
    else:
        for v in exam.variants:
            written.append(document(sheets.worksheet_html(v, None, figs[v.number]),
                                    sheets_dir / f"variant-{v.number:02d}"))
    kept = len(exam.variants)
    print(f"{kept} variant{'s' if kept != 1 else ''} (seed {exam.seed}) from {exam.drawn} "
          f"drawn; rejected {exam.drawn - kept}"
          + ("" if not exam.rejected else ": " + "; ".join(
              f"{c} {r}" for r, c in exam.rejected.items())))
    for expr, why in exam.dropped:
        from ..exam.variants import symbol
        print(f"  not asked: {symbol(expr)} {why}")
    if exam.default_ranges:
        print("  (no [exam] table: the crank angle was varied round the turn and the "
              "scene's [[answers]] asked)")
    asked = exam.variants[0].asked
    print(f"  asked per variant: {', '.join(a.symbol for a in asked)}")
    print(f"  wrote {len(written)} files in {out}: quiz.xml, quiz.gift, quiz-qti.zip, "
          f"key.{'pdf' if pdf else 'html'}, worksheets/ ({len(written) - 4})")
    return 0


__all__ = ["run", "register", "read_students", "ExamError", "SceneError"]
