"""``polygons draw CASE.toml -o DIR``: the space, velocity and acceleration diagrams as SVG,
the polygons stage by stage, and (``--measure``) the lengths scaled back off the drawings."""
from __future__ import annotations

import sys

from ..evaluate import solve
from ..scene import load_scene


def add_diagram_options(p) -> None:
    """Options shared by ``draw`` and ``solve --svg``."""
    p.add_argument("--scale", action="append", metavar="KIND=VALUE",
                   help="force a scale, per cm of paper: --scale velocity='2 m/s' "
                        "--scale acceleration='1 cm = 500 m/s^2' --scale space='20 mm' "
                        "(repeatable; default: a round scale that fits the paper)")
    p.add_argument("--paper", choices=("A5", "A4"),
                   help="fit the drawings to this paper (default: A5, or A4 when a vector "
                        "would be too short to read on A5)")
    p.add_argument("--no-stages", action="store_true",
                   help="only the finished diagrams, not velocity-1.svg ... stage by stage")


def register(sub) -> None:
    p = sub.add_parser("draw", help="draw the space, velocity and acceleration diagrams (SVG)",
                       description="Write labelled SVG diagrams of a scene to a folder: "
                                   "space.svg, velocity.svg, acceleration.svg and the "
                                   "construction stage by stage (velocity-1.svg ...).")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--out", required=True, metavar="DIR", help="output folder")
    add_diagram_options(p)
    p.add_argument("--measure", action="store_true",
                   help="print every drawn length scaled back off the SVGs (ruler 0.5 mm) and "
                        "compare the tutorial's answers with them")
    p.set_defaults(func=run)


def write_diagrams(sol, args, out, klein: str | None = None):
    import diagrams
    from diagrams.scale import parse_cli
    scales = parse_cli(args.scale)
    return diagrams.write(sol, out, scales, args.paper, False if args.no_stages else None,
                          klein=klein)


def run(args) -> int:
    from diagrams import measure
    scene = load_scene(args.scene)
    sol = solve(scene)
    paths = write_diagrams(sol, args, args.out)
    if args.measure:
        finals = {}
        for path in paths:
            if "-" not in path.stem:
                finals[path.stem] = measure.read_svg(path)
        sys.stdout.write(measure.table(sol, finals))
    else:
        print(f"wrote {len(paths)} SVG files to {args.out}: "
              + " ".join(p.name for p in paths))
    return 0
