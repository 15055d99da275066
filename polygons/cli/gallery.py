"""``polygons gallery cases/ -o DIR``: every case's handout and worksheet, and an index page.

Writes ``DIR/<case>.html`` (the answer key), ``DIR/<case>-worksheet.html`` and
``DIR/index.html`` linking them: one card per case file (every file once, the file's name shown
where two share a source id) with a thumbnail of its space diagram, its title, mechanism and
how the tutorial's printed answers compare.  ``--pdf`` also prints every handout and worksheet.  A case
that cannot be solved is listed with its one-line error; the command then exits 1.
"""
from __future__ import annotations

import hashlib
import html
import re
import sys
from pathlib import Path

from ..errors import PolygonsError
from ..evaluate import solve
from ..report import check_answers
from ..scene import load_scene


def register(sub) -> None:
    p = sub.add_parser("gallery", help="write every case's handout and worksheet and an "
                                       "index page linking them",
                       description="Write a handout and a worksheet for every *.toml case in "
                                   "a folder, and DIR/index.html linking them.")
    p.add_argument("cases", help="folder of scene files (*.toml), or one scene file")
    p.add_argument("-o", "--out", required=True, metavar="DIR", help="output folder")
    p.add_argument("--pdf", action="store_true", help="also print every page to PDF "
                                                      "(needs headless Chromium)")
    p.set_defaults(func=run)


def _summary(sol) -> str:
    checks = [c for c in check_answers(sol) if c.answer.tutorial is not None]
    if not checks:
        return "no printed answers"
    slips = sum(1 for c in checks if c.answer.slip)
    within = sum(1 for c in checks if c.within and not c.answer.slip)
    text = f"{within} of {len(checks)} printed answers within tolerance"
    if slips:
        text += f", {slips} slip{'s' if slips > 1 else ''} in the tutorial"
    return text


def build_gallery(cases: Path, out: Path, pdf: bool = False) -> tuple[list[Path], list[str]]:
    from diagrams import handout_forces
    from diagrams.handout import figures, handout
    from diagrams.html import esc

    from .handout import add_sections
    files = sorted(cases.glob("*.toml")) if cases.is_dir() else [cases]
    if not files:
        raise PolygonsError(f"no *.toml scene files in {cases}")
    out.mkdir(parents=True, exist_ok=True)
    rows, written, errors = [], [], []
    ids = [_source_id(path) for path in files]
    for path in files:
        stem = path.stem
        try:
            sol = solve(load_scene(str(path)))
            an = handout_forces.check(sol)      # [handout] force methods (refused: a card)
            figs = figures(sol)
            pages = {}
            for kind, worksheet in (("handout", False), ("worksheet", True)):
                name = f"{stem}.html" if kind == "handout" else f"{stem}-worksheet.html"
                target = out / name
                text = handout(sol, worksheet=worksheet, figs=figs)
                if not worksheet:               # Klein's, equivalent linkage, force methods
                    text = add_sections(text, sol, an=an)
                target.write_text(text, encoding="utf-8")
                written.append(target)
                pages[kind] = name
                if pdf:
                    from diagrams.browser import print_pdf
                    written.append(print_pdf(target, target.with_suffix(".pdf")))
                    pages[kind + "-pdf"] = target.with_suffix(".pdf").name
        except PolygonsError as exc:
            errors.append(str(exc) if exc.file else f"{path}: {exc}")
            rows.append(f'<article class="card failed" id="case-{_anchor(stem)}"><h2>'
                        f'<span class="id">{esc(stem)}</span></h2><p>could not be solved: '
                        f"{esc(str(exc))}</p></article>")
            continue
        src = sol.scene.source
        links = [f'<a href="{_href(pages["handout"])}">handout</a>',
                 f'<a href="{_href(pages["worksheet"])}">worksheet</a>']
        if pdf:
            links += [f'<a href="{_href(pages["handout-pdf"])}">PDF</a>',
                      f'<a href="{_href(pages["worksheet-pdf"])}">worksheet PDF</a>']
        tags = (" <em>(synthetic geometry)</em>" if src.get("synthetic")
                and "SYNTHETIC" not in sol.scene.title.upper() else "")
        ident = src.get("id", stem)
        if ids.count(ident) > 1:
            ident = f"{ident} ({stem})"
        rows.append(f'<article class="card" id="case-{_anchor(stem)}">'
                    f'<a class="thumb" href="{_href(pages["handout"])}">'
                    f'{_thumbnail(figs, stem)}</a>'
                    f'<h2><span class="id">{esc(ident)}</span> '
                    f'<a href="{_href(pages["handout"])}">{esc(sol.scene.title)}</a>{tags}</h2>'
                    f'<p class="mech">{esc(_mechanism(sol))}</p>'
                    f'<p class="answers">{esc(_summary(sol))}</p>'
                    f'<p class="links">{" · ".join(links)}</p></article>')
    index = out / "index.html"
    index.write_text(_index(rows, cases), encoding="utf-8")
    written.append(index)
    return written, errors


def _source_id(path: Path) -> str:
    """The ``[source] id`` of a scene file read without solving it (its stem when absent);
    read as every scene is (a FIFO or a device in the folder is refused, never waited on)."""
    from ..scene import parse_toml, read_scene_text
    try:
        source = parse_toml(read_scene_text(path), str(path)).get("source", {})
        return str(source.get("id", path.stem)) if isinstance(source, dict) else path.stem
    except PolygonsError:
        return path.stem


def _href(name: str) -> str:
    """A link to a file written beside the index: relative ('./'), every character of the
    name that is not safe in a URL percent-encoded (a case named 'javascript:x.toml' links to
    './javascript%3Ax.html', never runs), then escaped for the attribute."""
    from urllib.parse import quote
    return html.escape("./" + quote(name, safe=""), quote=True)


def _anchor(stem: str) -> str:
    """An id token for a case: letters, digits, '-' and '_' only (anything else becomes '-'),
    with a short digest of the name so that two names that read alike stay apart."""
    token = re.sub(r"[^A-Za-z0-9_-]", "-", stem)[:60]
    if token != stem:
        token += "-" + hashlib.sha1(stem.encode("utf-8", "surrogatepass")).hexdigest()[:8]
    return token


def _mechanism(sol) -> str:
    """The source's words for the mechanism, else what the scene is made of."""
    words = sol.scene.source.get("mechanism")
    if words:
        return words
    scene = sol.scene
    model = scene.model
    n = len(model.links())
    parts = [f"{n} link{'s' if n != 1 else ''}"]
    if model.guide:
        parts.append(f"{len(model.guide)} slider{'s' if len(model.guide) != 1 else ''}")
    if model.slot:
        parts.append(f"{len(model.slot)} slot{'s' if len(model.slot) != 1 else ''}")
    return ", ".join(parts)


def _thumbnail(figs, stem: str) -> str:
    """The space diagram without its heading, key and legend, inlined at 70 mm wide."""
    from diagrams.figures import trimmed
    from diagrams.html import inline_svg
    from diagrams.svg import to_svg
    d = figs.drawing.get("space")
    if d is None:
        return ""
    t = trimmed(d, ("heading", "caption", "key", "legend", "scale-bar"))
    return inline_svg(to_svg(t), f"thumb-{_anchor(stem)}", "thumb", 70.0,
                      f"Space diagram of {stem}")


def _index(rows: list[str], cases: Path) -> str:
    from diagrams.html import esc
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>polygons — handouts</title>\n<style>\n"
            "body { font-family: 'DejaVu Sans', Verdana, Arial, sans-serif; font-size: 10pt; "
            "max-width: 270mm; margin: 8mm auto; padding: 0 6mm; }\n"
            "h1 { font-size: 16pt; }\n"
            ".cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(78mm, 1fr));"
            " gap: 5mm; }\n"
            ".card { border: 0.3mm solid #999; padding: 3mm; break-inside: avoid; }\n"
            ".card h2 { font-size: 10.5pt; margin: 1.5mm 0; } .card p { margin: 1mm 0; }\n"
            ".card .id { display: block; font-size: 8.5pt; color: #333; }\n"
            ".card .thumb svg { display: block; width: 100%; height: 50mm; }\n"
            ".card.failed { font-style: italic; } a { color: #003a8c; }\n"
            "@page { size: A4 portrait; margin: 12mm; }\n</style>\n</head>\n<body>\n"
            "<h1>Velocity and acceleration polygons: handouts</h1>\n"
            f"<p>One handout (the answer key, constructions narrated step by step) and one "
            f"worksheet (no answers, empty drawing areas at scale) per case of "
            f"<code>{esc(str(cases))}</code>. Regenerate: <code>polygons gallery "
            f"{esc(str(cases))} -o DIR</code>.</p>\n"
            '<main class="cards">\n' + "\n".join(rows) + "\n</main>\n</body>\n</html>\n")


def run(args) -> int:
    written, errors = build_gallery(Path(args.cases), Path(args.out), args.pdf)
    n_html = sum(1 for p in written if p.suffix == ".html")
    print(f"wrote {n_html} pages ({len(written)} files) to {args.out}; open "
          f"{Path(args.out) / 'index.html'}")
    for e in errors:
        print(f"polygons: error: {e}", file=sys.stderr)
    return 1 if errors else 0
