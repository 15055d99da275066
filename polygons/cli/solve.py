"""``polygons solve CASE.toml``: the numbers, the construction and the conditioning."""
from __future__ import annotations

from ._output import add_out_option, emit
from ..evaluate import solve
from ..report import json_text, table, to_json
from ..scene import load_scene


def register(sub) -> None:
    p = sub.add_parser("solve", help="solve a scene: velocities, accelerations, ω, α, steps",
                       description="Solve a scene file and print the results table "
                                   "(or JSON with --json).")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--json", action="store_true", help="print a JSON object instead of a table")
    add_out_option(p)
    p.add_argument("--points", help="comma-separated labels: plan only what these need "
                                    "(and what the scene's answers read, which are checked)")
    p.add_argument("--units", choices=("mm", "si", "imperial"), default="mm",
                   help="units of the table: mm (positions in mm, speeds in m/s; default), "
                        "si (m, m/s, m/s²) or imperial (in, ft/s, ft/s²); JSON is always SI")
    p.add_argument("--no-steps", action="store_true", help="leave the construction out of "
                                                          "the table")
    p.add_argument("--svg", metavar="DIR", help="also write the labelled SVG diagrams (as "
                                               "'polygons draw -o DIR') to this folder")
    p.add_argument("--klein", nargs="?", const="klein", choices=("klein", "ritterhaus", "bennett"),
                   help="also Klein's construction for a slider-crank (in-line or offset; "
                        "--klein ritterhaus / bennett: Ritterhaus's or Bennett's, in-line only): the piston's velocity "
                        "and acceleration read off the space diagram (as [diagram] klein)")
    from .draw import add_diagram_options
    add_diagram_options(p)
    p.set_defaults(func=run)


def _targets(scene, points: str | None, method) -> list[str] | None:
    """The labels ``--points`` asks for, and what the rest of the output reads: the points
    the scene's answers name (a wheel's: its plates too) and Klein's crank and piston — the
    answers are checked, not skipped.  None (the whole plan) when the output needs a point
    no target can name (a slider block on no link)."""
    if not points:
        return None
    from ..quantities import labels_needed
    asked = [t.strip() for t in points.split(",")]
    extra: list[str] = []
    for ans in scene.answers:
        extra += labels_needed(scene, ans.quantity)
    if method:
        from ..classic.klein import engine
        _, _, O, A, B, _ = engine(scene)
        extra += [O, A, B]
    known = set(scene.labels)
    if any(t not in known for t in extra) and all(t in known for t in asked):
        return None
    return list(dict.fromkeys(asked + [t for t in extra if t in known]))


def run(args) -> int:
    scene = load_scene(args.scene)
    method = args.klein or scene.options.diagram.klein
    targets = _targets(scene, args.points, method)
    sol = solve(scene, targets)
    forces = None
    if scene.loads is not None and scene.loads.active:   # bad force tables fail first
        # (the forces package is imported only for a scene with loads: a quicker start)
        from ..forces import analyse
        forces = analyse(scene)
    if not method and scene.answers:   # an answer naming a point of Klein's figure (ON)
        from ..classic.klein import asked
        method = "klein" if asked(sol) else None
    fig = None
    if method:
        from ..classic.klein import figure
        fig = figure(sol, method)
    if args.svg:
        from .draw import write_diagrams
        write_diagrams(sol, args, args.svg, klein=method)
    text = (json_text(report_data(sol, forces, fig)) if args.json else
            report_text(sol, forces, fig, steps=not args.no_steps, units=args.units))
    emit(text, args.out)
    return 0


def report_data(sol, forces=None, fig=None) -> dict:
    """What ``polygons solve --json`` prints: the kinematics (:func:`polygons.report.to_json`)
    and what the scene's tables add — the rubbing and least velocities, the forces
    (``forces``: their analysis), Klein's figure (``fig``), a contact's equivalent links, a
    cam stated by its profile's profile and part in contact.  The Python API's
    ``Result.to_dict`` is this too."""
    scene = sol.scene
    data = to_json(sol)
    if any(k in scene.extra for k in ("pins", "least_velocity")):    # pins.has_pins
        from .. import pins        # (imported only for a scene with those tables)
        data["pins"] = pins.to_dict(sol)
    if forces is not None:
        from .forces import to_dict
        data["forces"] = to_dict(forces)
    if fig is not None:
        from ..classic.klein import to_dict as klein_dict
        data["klein"] = klein_dict(fig)
    if scene.equivalents:
        from ..contacts import to_list
        data["equivalent_links"] = to_list(sol)
    if "cam_profiles" in scene.extra:        # the profile found, the part in contact
        from ..cam_profiles import to_dict as cam_dict
        data["cam_profile"] = cam_dict(scene)
    return data


def report_text(sol, forces=None, fig=None, *, steps: bool = True, units: str = "mm") -> str:
    """What ``polygons solve`` prints: the results table (:func:`polygons.report.table`) and
    the sections :func:`report_data` adds, in words.  The API's ``Result.table`` is this."""
    scene = sol.scene
    text = table(sol, steps=steps, units=units)
    if any(k in scene.extra for k in ("pins", "least_velocity")):
        from .. import pins
        text += "\n" + "\n".join(pins.report_lines(sol)) + "\n"
    if forces is not None:
        from .forces import forces_table
        text += "\n" + forces_table(forces, header=False)
    if fig is not None:
        from ..classic.klein import report_lines
        text += "\n" + "\n".join(report_lines(fig)) + "\n"
    if scene.equivalents:
        from ..contacts import report_lines as equivalent_lines
        text += "\n" + "\n".join(equivalent_lines(sol)) + "\n"
    if "cam_profiles" in scene.extra:
        from ..cam_profiles import report_lines as cam_lines
        text += "\n" + "\n".join(cam_lines(scene)) + "\n"
    return text
