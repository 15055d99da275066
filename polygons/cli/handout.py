"""``polygons handout CASE.toml -o FILE.html``: a printable teaching handout (or worksheet).

The answer key narrates the construction step by step with its figures and numbers and
compares the results with the tutorial's printed answers; ``--worksheet`` writes the student's
version (no answers, empty drawing areas at the key's scale).  ``--pdf`` also prints it to
PDF with headless Chromium (``-o FILE.pdf`` writes only the PDF).  ``--interactive`` writes
the interactive construction page instead (:mod:`diagrams.page`: stages forward/back, a
crank-angle slider redrawing the mechanism and both polygons from the sweep).
"""
from __future__ import annotations

import tempfile
from pathlib import Path

from ..evaluate import solve
from ..scene import load_scene


def register(sub) -> None:
    p = sub.add_parser("handout", help="write a printable handout (HTML, optional PDF) or "
                                       "a worksheet for a case",
                       description="Write a self-contained HTML handout: the problem, the "
                                   "space diagram, the velocity and acceleration constructions "
                                   "step by step with figures and numbers, the results and "
                                   "the comparison with the tutorial. --worksheet: the "
                                   "student's version without answers.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--out", required=True, metavar="FILE",
                   help="output file (.html; .pdf writes only the PDF)")
    p.add_argument("--worksheet", action="store_true",
                   help="no answers, empty drawing areas at the chosen scale")
    p.add_argument("--interactive", action="store_true",
                   help="write the interactive construction page instead: one self-contained "
                        "HTML file stepping through the construction, with a crank-angle "
                        "slider (frames from the sweep)")
    p.add_argument("--centres", action="store_true",
                   help="add a section checking the velocities by the instantaneous centres "
                        "(Kennedy's theorem, the circle diagram) to the answer key")
    p.add_argument("--pdf", action="store_true",
                   help="also print FILE.pdf next to FILE.html (needs headless Chromium)")
    p.add_argument("--scale", action="append", metavar="KIND=VALUE",
                   help="force a scale per cm of paper, as for 'polygons draw' "
                        "(--scale velocity='2 m/s')")
    p.add_argument("--paper", choices=("A5", "A4"),
                   help="fit the diagrams to this paper (default: A5, or A4 when needed)")
    p.set_defaults(func=run)


def build(scene_path: str, *, worksheet: bool = False, scale=None, paper=None,
          centres: bool = False) -> str:
    from diagrams.handout import figures, handout
    from diagrams.scale import parse_cli
    from diagrams import handout_forces
    sol = solve(load_scene(scene_path))
    an = handout_forces.check(sol)      # [handout] force methods: refused before any work
    figs = figures(sol, parse_cli(scale), paper)
    text = handout(sol, worksheet=worksheet, figs=figs, centres=centres)
    return text if worksheet else add_sections(text, sol, parse_cli(scale).get("space"), paper,
                                               an)


def add_sections(text: str, sol, space_scale=None, paper=None, an=None) -> str:
    """The answer key ``text`` with the sections the scene asks for inserted before its
    footer: Klein's construction, the equivalent linkage (:mod:`diagrams.handout_klein`), the
    force methods (:mod:`diagrams.handout_forces`; ``an`` from its ``check``)."""
    from diagrams import handout_forces
    from diagrams.handout_klein import sections
    extra = sections(sol, space_scale, paper) + handout_forces.sections(sol, an)
    end = "<footer" if "<footer" in text else "</body>"      # before the footer
    if extra and end in text:
        head, tail = text.rsplit(end, 1)
        text = head + extra + end + tail
    return text


def write(scene_path: str, out: str | Path, *, worksheet: bool = False, pdf: bool = False,
          scale=None, paper=None, centres: bool = False) -> list[Path]:
    """Write the handout; return the files written (HTML and/or PDF)."""
    text = build(scene_path, worksheet=worksheet, scale=scale, paper=paper, centres=centres)
    out = Path(out)
    written = []
    if out.suffix.lower() == ".pdf":
        from diagrams.browser import print_pdf
        with tempfile.TemporaryDirectory(prefix="polygons-handout-") as tmp:
            html = Path(tmp) / (out.stem + ".html")
            html.write_text(text, encoding="utf-8")
            written.append(print_pdf(html, out))
        return written
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text, encoding="utf-8")
    written.append(out)
    if pdf:
        from diagrams.browser import print_pdf
        target = out.with_suffix(".pdf") if out.suffix else out.with_name(out.name + ".pdf")
        if out.suffix.lower() in (".html", ".htm"):
            written.append(print_pdf(out, target))
        else:    # Chromium reads a file without .html as plain text: print a .html copy
            with tempfile.TemporaryDirectory(prefix="polygons-handout-") as tmp:
                html = Path(tmp) / (out.stem + ".html")
                html.write_text(text, encoding="utf-8")
                written.append(print_pdf(html, target))
    return written


def write_page(scene_path: str, out: str | Path, *, scale=None, paper=None) -> Path:
    """Write the interactive construction page (one self-contained HTML file)."""
    import diagrams
    from diagrams.page import page
    from diagrams.scale import parse_cli
    scene = load_scene(scene_path)
    if "cam_profiles" in scene.extra:      # the page's cycle follows one linkage
        from ..errors import SceneError
        raise SceneError("the interactive page follows one linkage round the cycle, and a cam "
                         "stated by its profile changes its equivalent linkage as the part in "
                         "contact changes: 'polygons sweep' gives its displacement diagram over "
                         "a turn, 'polygons handout' its key at the stated instant",
                         file=scene.file)
    sol = solve(scene)
    drawings = diagrams.drawings(sol, parse_cli(scale), paper, True)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(page(sol, drawings), encoding="utf-8")
    return out


def run(args) -> int:
    if args.interactive:
        if args.worksheet or args.pdf:
            from ..errors import PolygonsError
            raise PolygonsError("--interactive writes an HTML page: it takes neither "
                                "--worksheet nor --pdf")
        print(f"wrote {write_page(args.scene, args.out, scale=args.scale, paper=args.paper)}")
        return 0
    paths = write(args.scene, args.out, worksheet=args.worksheet, pdf=args.pdf,
                  scale=args.scale, paper=args.paper, centres=args.centres)
    print("wrote " + " ".join(str(p) for p in paths))
    return 0
