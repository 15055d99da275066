"""``polygons sweep CAM.toml``: a cam stated by its profile ([cam_profiles]) swept over a turn
— its displacement diagram (:func:`polygons.cam_diagram.diagram`): each cam angle's part in
contact and its equivalent linkage solved, written as CSV, plotted and summed up (the lift,
the parts and where they hold, the greatest velocity and acceleration)."""
from __future__ import annotations

import math
import sys
from pathlib import Path

from ..cam_diagram import EXTREME_SAMPLES, MAX_DIAGRAM_STEPS, diagram, extremes, parts
from ..cam_profiles import TABLE, stated
from ..errors import SceneError
from ..steps import number

#: the sweep flags that have no meaning for a cam's displacement diagram
NOT_FOR_CAMS = (("vary", "--vary"), ("npz", "--npz"), ("points", "--points"),
                ("links", "--links"), ("shm", "--shm"), ("grid", "--grid"),
                ("large", "--large"))


def run_cam(args, scene) -> int:
    for key, flag in NOT_FOR_CAMS:
        if getattr(args, key, None):
            raise SceneError(f"{flag} is not for a cam stated by its profile: its sweep is the "
                             f"follower's displacement diagram", file=scene.file, where=flag)
    steps = args.steps if args.steps is not None else (scene.options.sweep.steps or 360)
    if not 2 <= steps <= MAX_DIAGRAM_STEPS:
        raise SceneError(f"steps must be a whole number from 2 to {MAX_DIAGRAM_STEPS:,} for a "
                         f"cam's displacement diagram (each angle a construction), got "
                         f"{steps:,}", file=scene.file, where="--steps")
    rows = diagram(scene, steps)
    label, table, prof, fol, *_ = stated({TABLE: {k: {kk: vv for kk, vv in v.items()
                                                      if not kk.startswith("_")}
                                                  for k, v in scene.extra[TABLE].items()},
                                          "driver": {"crank": scene.driver.link,
                                                     "angle": "0 deg"},
                                          "ground": {g: [f"{p[0]!r} m", f"{p[1]!r} m"]
                                                     for g, p in scene.ground.items()}},
                                         scene.file)
    osc = fol.oscillating
    # the extremes are looked for on one diagram of at least EXTREME_SAMPLES rows, made once
    fine = rows if len(rows) >= EXTREME_SAMPLES else diagram(scene, EXTREME_SAMPLES)
    dwell = extremes(scene, fine, "s", -1)[0].s if not osc else None
    out = Path(args.out)
    stem = out / f"{Path(args.scene).stem}-cam"
    stem.parent.mkdir(parents=True, exist_ok=True)
    if osc:
        head = ["cam angle [deg]", "part", "found by", "arm angle [deg]",
                "omega [rad/s]", "alpha [rad/s^2]"]
        vals = [(math.degrees(r.angle), r.part, r.by, math.degrees(r.s), r.v, r.a)
                for r in rows]
    else:
        head = ["cam angle [deg]", "part", "found by", "s [mm]", "lift [mm]", "v [m/s]",
                "a [m/s^2]"]
        vals = [(math.degrees(r.angle), r.part, r.by, r.s * 1e3, (r.s - dwell) * 1e3, r.v, r.a)
                for r in rows]
    path = stem.with_suffix(".csv")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(",".join(head) + "\n")
        for v in vals:
            fh.write(",".join(x if isinstance(x, str) else f"{x:.17g}" for x in v) + "\n")
    written = [path]
    if not args.no_plot:
        written += _plot(scene, rows, osc, dwell, stem, list(args.formats))
    sys.stdout.write(_summary(scene, rows, fine, osc, dwell, label, table, written))
    return 0


def _plot(scene, rows, osc, dwell, stem, formats):
    from diagrams.plots import Line, Panel, plot_panels
    x = [math.degrees(r.angle) for r in rows]
    if osc:
        panels = [Panel("arm angle (deg)", zero_line=False), Panel("ω (rad/s, CCW +)"),
                  Panel("α (rad/s², CCW +)")]
        ys = ([math.degrees(r.s) for r in rows], [r.v for r in rows], [r.a for r in rows])
    else:
        panels = [Panel("lift (mm)", zero_line=False), Panel("velocity (m/s)"),
                  Panel("acceleration (m/s²)")]
        ys = ([(r.s - dwell) * 1e3 for r in rows], [r.v for r in rows], [r.a for r in rows])
    colours = {"nose": "tab:red", "flank": "tab:blue", "straight flank": "tab:blue",
               "base circle": "0.4"}
    for panel, y in zip(panels, ys):
        seen = set()
        start = 0
        for i in range(1, len(rows) + 1):     # one line per run of a part (breaks at changes)
            if i == len(rows) or rows[i].part != rows[start].part:
                part = rows[start].part
                end = i + (i < len(rows))        # joined to the next part's first point
                panel.lines.append(Line(part if part not in seen else "", x[start:end],
                                        y[start:end], "-", colours[part]))
                seen.add(part)
                start = i
    drv = scene.driver
    title = (f"{scene.title[:100]}\ndisplacement diagram: ω = {abs(drv.omega):.4g} rad/s "
             f"{'CCW' if drv.omega > 0 else 'CW'}, {len(rows)} cam angles")
    return plot_panels(title, "nose axis angle (deg, CCW from +x)", panels, stem, formats, [],
                       (0.0, 360.0), list(range(0, 361, 45)))


def _summary(scene, rows, fine, osc, dwell, label, table, written) -> str:
    """The diagram in words: its parts, and the lift (swing) and greatest rates found on
    ``fine`` (the diagram, or a finer one where it is coarse)."""
    lines = [f"{Path(scene.file).name}: displacement diagram of the follower {label} over a "
             f"turn ({len(rows)} cam angles; nose axis angle CCW from +x)"]
    for part, a0, a1, by in parts(scene):
        lines.append(f"  {part:15s} {math.degrees(a0):>9.6g}° … {math.degrees(a1):.6g}°  ({by})")

    def at(found) -> str:
        return " and ".join(f"{math.degrees(r.angle):.6g}° ({r.part})" for r in found)

    if osc:
        lo, hi = extremes(scene, fine, "s", -1)[0].s, extremes(scene, fine, "s", +1)[0].s
        lines.append(f"  arm swing: {number(math.degrees(hi - lo))}°")
        unit_v, unit_a, name_v, name_a = "rad/s", "rad/s²", "ω", "α"
    else:
        top = extremes(scene, fine, "s", +1)
        lines.append(f"  lift: {number((top[0].s - dwell) * 1e3)} mm at {at(top)}")
        unit_v, unit_a, name_v, name_a = "m/s", "m/s²", "v", "a"
    for name, key, unit in ((name_v, "v", unit_v), (name_a, "a", unit_a)):
        big = extremes(scene, fine, key)
        lines.append(f"  greatest |{name}|: {number(abs(getattr(big[0], key)))} {unit} at "
                     f"{at(big)}")
    lines += [f"wrote {p}" for p in written]
    return "\n".join(lines) + "\n"
