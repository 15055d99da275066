"""``polygons sweep CASE.toml --steps N``: a full input revolution (or the reachable range),
solved at once, written as CSV and plotted (PNG + SVG).

Chosen points and links come from ``--points`` / ``--links`` or the scene's optional
``[sweep]`` table::

    [sweep]
    points = ["B"]      # displacement, velocity, acceleration against the input
    links = ["AB"]      # ω and α against the input
    steps = 720
    shm = true          # overlay the simple-harmonic curve (crank pin projected on the guide)
    unit = "mm"         # display unit of length in the summary and the plots
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from ..errors import SceneError, UnknownLabelError, suggest
from ..options import MAX_STEPS, labels
from ..scene import Crank, Scene, parse_scene, parse_toml, read_scene_text
from ..steps import number
from ..dyads.base import size_of
from ..sweep import Sweep, default_points, harmonic, sweep
from ..sweep_extremes import greatest

#: above this many positions the summary draws a progress bar (on a terminal)
PROGRESS_FROM = 100_000
#: from this many positions the sweep is streamed to the CSV (polygons/cli/_stream.py)
STREAM_FROM = 1_000_000
#: the output a sweep may write without --large (estimated before any work)
MAX_OUTPUT_BYTES = 1_000_000_000
#: the time a sweep may take without --large (estimated from a timed probe of its positions)
MAX_SECONDS = 300.0
#: from this many positions the output and the time are estimated before the sweep starts
BUDGET_FROM = 100_000
#: positions solved (and timed) to estimate a sweep's time
BUDGET_PROBE = 2048
#: bytes of one value: a CSV field ('%.17g', ~19 characters, and its comma), a .npz float64
VALUE_BYTES = {"csv": 21, "npz": 8}
#: values written a second (a CSV with and without numba's compiled writer, a .npz)
WRITE_RATE = {"csv": 4e6, "csv-python": 1.2e6, "npz": 5e7}
#: most points drawn per curve (the maxima are always taken from every position)
PLOT_POINTS = 4000
#: the formats a plot can be written in (--formats)
PLOT_FORMATS = ("png", "svg", "pdf")
#: the longest scene title a plot shows (cut with an ellipsis beyond)
PLOT_TITLE = 120
#: most curves named in one panel's key (a large mechanism has dozens of links)
PLOT_KEYED = 8


def _formats(text: str) -> tuple[str, ...]:
    """--formats: a comma-separated list of PLOT_FORMATS, refused by the parser."""
    import argparse
    formats = tuple(dict.fromkeys(f.strip().lower() for f in text.split(",") if f.strip()))
    bad = [f for f in formats if f not in PLOT_FORMATS]
    if bad or not formats:
        head = f"unknown plot format {bad[0][:40]!r}" if bad else "no plot format"
        raise argparse.ArgumentTypeError(f"{head}: choose from {', '.join(PLOT_FORMATS)} "
                                         f"(comma-separated)")
    return formats


def register(sub) -> None:
    p = sub.add_parser("sweep", help="solve a scene over a full input revolution: CSV + plots",
                       description="Solve a scene over a full input revolution (or its "
                                   "reachable range, reporting the limits), all positions at "
                                   "once; write CSV and plots of displacement, velocity and "
                                   "acceleration of chosen points and ω/α of chosen links. "
                                   "A cam stated by its profile ([cam_profiles]): the "
                                   "follower's displacement diagram over a turn of the cam.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--steps", type=int, default=None,
                   help=f"positions over the cycle, 2 .. {MAX_STEPS:,} (default: [sweep] steps "
                        f"or 360)")
    p.add_argument("--points", help="comma-separated point labels to plot (default: [sweep] "
                                    "points, else the sliders, else the last point placed)")
    p.add_argument("--links", help="comma-separated link names for ω/α (default: [sweep] "
                                   "links, else every link but the crank)")
    p.add_argument("-o", "--out", default="out", metavar="DIR",
                   help="output directory (default: out)")
    p.add_argument("--formats", type=_formats, default=("png", "svg"),
                   help=f"plot formats, comma-separated: {', '.join(PLOT_FORMATS)} "
                        f"(default: png,svg)")
    p.add_argument("--no-plot", action="store_true", help="write the CSV only")
    p.add_argument("--npz", action="store_true",
                   help="write every point and every link as numpy's .npz (float64, 8 bytes "
                        "a value, np.load) instead of the chosen ones as CSV")
    p.add_argument("--large", action="store_true",
                   help=f"run a sweep estimated above the budget ({MAX_OUTPUT_BYTES / 1e9:g} GB "
                        f"written or {MAX_SECONDS / 60:g} min)")
    p.add_argument("--shm", action="store_true", default=None,
                   help="overlay the simple-harmonic curve on each slider (crank pin "
                        "projected on its guide) and report the difference")
    p.add_argument("--unit", choices=("mm", "m"), default=None,
                   help="display unit of length (default: [sweep] unit, else mm when every "
                        "link is shorter than 1 m)")
    p.add_argument("--progress", choices=("auto", "on", "off"), default="auto",
                   help=f"progress bar on stderr (auto: on a terminal, from "
                        f"{PROGRESS_FROM:,} positions)")
    p.add_argument("--vary", action="append", metavar="NAME=LO..HI UNIT:N",
                   help="solve the scene once per value of a quantity instead of sweeping the "
                        "input (a link length, G_x/G_y, theta, omega, alpha), e.g. "
                        "AB=40..60mm:100; repeatable (see polygons/cli/_vary.py)")
    p.add_argument("--grid", action="store_true",
                   help="with several --vary: every combination instead of row by row")
    p.set_defaults(func=run)


def _options(scene: Scene, args) -> dict:
    """The scene's ``[sweep]`` (checked at load: :mod:`polygons.options`) under the flags."""
    sw = scene.options.sweep
    points = list(labels(args.points, file=scene.file, where="--points")) if args.points \
        else (list(sw.points) if sw.points is not None else None)
    links = list(labels(args.links, file=scene.file, where="--links")) if args.links \
        else (list(sw.links) if sw.links is not None else None)
    # each label once (a repeat would add columns and curves, never information)
    points = list(dict.fromkeys(points)) if points is not None else None
    links = list(dict.fromkeys(links)) if links is not None else None
    steps = args.steps if args.steps is not None else (sw.steps or 360)
    if not 2 <= steps <= MAX_STEPS:      # the scene's [sweep] steps bound, before any work
        raise SceneError(f"steps must be a whole number from 2 to {MAX_STEPS:,}, got "
                         f"{steps:,}", file=scene.file, where="--steps")
    shm = args.shm if args.shm is not None else bool(sw.shm)
    unit = args.unit or sw.unit
    if unit is None:
        unit = "mm" if size_of(scene) < 1.0 else "m"     # (a scene with no links: its size)
    return {"points": points, "links": links, "steps": steps, "shm": shm, "unit": unit,
            "npz": bool(getattr(args, "npz", False))}


def _default_points(sw: Sweep) -> list[str]:
    return default_points(sw.scene, sw.plan, sw.pos, sw.travel)


def _default_links(sw: Sweep) -> list[str]:
    drv = sw.scene.driver
    crank = drv.link if isinstance(drv, Crank) else None
    return [name for name in sw.omega if name != crank]


def run(args) -> int:
    data = parse_toml(read_scene_text(args.scene), args.scene)
    if isinstance(data, dict) and "cam_profiles" in data:   # the displacement diagram
        from ..cam_diagram import movable
        from ._cam import run_cam
        return run_cam(args, movable(data, args.scene))
    scene = parse_scene(data, file=args.scene)
    if args.steps is not None and not 2 <= args.steps <= MAX_STEPS:    # checked with --vary too
        raise SceneError(f"steps must be a whole number from 2 to {MAX_STEPS:,}, got "
                         f"{args.steps:,}", file=scene.file, where="--steps")
    if args.vary:
        from ._vary import run_vary
        return run_vary(args, scene)
    opt = _options(scene, args)
    n = opt["steps"]
    bar = None
    show = {"on": True, "off": False, "auto": n >= PROGRESS_FROM and sys.stderr.isatty()}[
        args.progress]
    st = None
    if n >= BUDGET_FROM:        # the output and the time estimated before the sweep
        st = check_budget(scene, opt, allow=args.large)
    if n >= STREAM_FROM:        # chunk by chunk into the CSV, in constant memory
        from ._stream import run_stream
        return run_stream(args, scene, opt, show, plot, _units, st=st)
    if show:
        from tqdm import tqdm
        bar = tqdm(total=n, unit="pos", unit_scale=True, desc="sweep", file=sys.stderr,
                   leave=False)
    try:
        sw = sweep(scene, n, progress=bar.update if bar else None)
    finally:
        if bar is not None:
            bar.close()

    for lab in opt["points"] or []:
        if lab not in sw.pos:
            raise UnknownLabelError(f"unknown point {lab!r}: {suggest(lab, sw.pos)}",
                                    file=scene.file, where="sweep.points")
    for name in opt["links"] or []:
        if name not in sw.omega:
            raise UnknownLabelError(f"unknown link {name!r}: {suggest(name, sw.omega)}",
                                    file=scene.file, where="sweep.links")
    points = opt["points"] or _default_points(sw)
    links = opt["links"] if opt["links"] is not None else _default_links(sw)
    shm = {}
    if opt["shm"]:
        for lab in points:
            if lab in sw.travel and isinstance(scene.driver, Crank):
                shm[lab] = harmonic(sw, lab)

    out = Path(args.out)
    stem = out / f"{Path(args.scene).stem}-sweep"
    if opt["npz"]:
        from ..csv_text import write_npz
        cols = columns(sw, list(sw.pos), list(sw.omega))
        path = stem.with_suffix(".npz")
        path.parent.mkdir(parents=True, exist_ok=True)
        write_npz(path, [(nm, u) for nm, u, _ in cols], [c for _, _, c in cols], sw.n)
        written = [path]
    else:
        written = [write_csv(sw, points, links, stem.with_suffix(".csv"))]
    if not args.no_plot:
        written += plot(sw, points, links, shm, opt["unit"], stem, list(args.formats))
    sys.stdout.write(summary(sw, points, links, shm, opt["unit"], written))
    return 0


# ---------------------------------------------------------------- the budget
def estimate(scene: Scene, opt: dict):
    """(stream plan, bytes, seconds, columns) of the sweep ``opt`` asks for, before it runs:
    the columns from a probe, the time from BUDGET_PROBE positions spread over the range,
    solved and timed (their rate times the steps), and the writing at WRITE_RATE."""
    import time
    from ..csv_text import _compiled
    from ..streams import evaluate_compiled, plan_stream
    from ._stream import _columns, _inputs_at, chosen
    n = opt["steps"]
    st = plan_stream(scene, n)
    evaluate_compiled(st, st.inputs(0, 2))        # first-call costs are not the rate
    # positions spread over the whole range (a range's ends can be slower: a triad's Newton)
    xs = _inputs_at(st, np.linspace(0, n - 1, min(n, BUDGET_PROBE)).astype(np.int64))
    t0 = time.perf_counter()
    res = evaluate_compiled(st, xs)
    solve_s = (time.perf_counter() - t0) / len(xs) * n
    points, links = chosen(scene, opt, st, res)
    if opt["npz"]:
        points, links = list(res["pos"]), list(res["omega"])
    m = len(_columns(st, xs, res, points, links))
    kind = "npz" if opt["npz"] else "csv"
    rate = WRITE_RATE[kind if kind == "npz" or _compiled() is not None else "csv-python"]
    return st, n * m * VALUE_BYTES[kind], solve_s + n * m / rate, m


def _size(b: float) -> str:
    return f"{b / 1e9:.3g} GB" if b >= 1e9 else f"{b / 1e6:.3g} MB"


def _duration(s: float) -> str:
    return f"{s / 60:.3g} min" if s >= 90 else f"{s:.2g} s"


def check_budget(scene: Scene, opt: dict, allow: bool = False):
    """Refuse a sweep estimated above MAX_OUTPUT_BYTES written or MAX_SECONDS (unless
    ``allow``: ``--large``), naming the estimate and the flag; the stream plan made for it."""
    st, size, seconds, m = estimate(scene, opt)
    if (size > MAX_OUTPUT_BYTES or seconds > MAX_SECONDS) and not allow:
        what = ".npz" if opt["npz"] else "CSV"
        raise SceneError(
            f"this sweep would write about {_size(size)} of {what} ({opt['steps']:,} rows × {m} "
            f"columns) and take about {_duration(seconds)}: above the budget of "
            f"{_size(MAX_OUTPUT_BYTES)} and {MAX_SECONDS / 60:g} min; pass --large to run it "
            f"anyway, or ask for fewer --steps, --points or --links", file=scene.file,
            where="--steps")
    return st


# ---------------------------------------------------------------- units and columns
def _units(unit: str):
    f = 1e3 if unit == "mm" else 1.0
    return f, unit, f"{unit}/s", f"{unit}/s²"


def _x_axis(sw: Sweep):
    if sw.input_kind == "crank":
        return np.degrees(sw.inputs), "crank angle θ (deg, CCW from +x)"
    return sw.inputs * 1e3, "input slider position s (mm along its guide)"


def columns(sw: Sweep, points, links):
    """(header, unit, array) for every CSV column, SI."""
    cols = []
    if sw.input_kind == "crank":
        cols.append(("theta", "rad", sw.inputs))
        cols.append(("theta_deg", "deg", np.degrees(sw.inputs)))
    else:
        cols.append(("s_input", "m", sw.inputs))
    for lab in points:
        P = sw.position(lab)
        cols += [(f"{lab}.x", "m", P[:, 0]), (f"{lab}.y", "m", P[:, 1])]
        V, A = sw.velocity(lab), sw.acceleration(lab)
        cols += [(f"{lab}.vx", "m/s", V[:, 0]), (f"{lab}.vy", "m/s", V[:, 1]),
                 (f"{lab}.ax", "m/s^2", A[:, 0]), (f"{lab}.ay", "m/s^2", A[:, 1])]
        if lab in sw.travel:
            cols += [(f"{lab}.s", "m", sw.travel[lab])]
        if lab in sw.slide_v:
            cols += [(f"{lab}.v_s", "m/s", sw.slide_v[lab]),
                     (f"{lab}.a_s", "m/s^2", sw.slide_a[lab])]
    for name in links:
        cols += [(f"{name}.omega", "rad/s", sw.omega[name]),
                 (f"{name}.alpha", "rad/s^2", sw.alpha[name])]
    cols.append(("min_angle", "deg", sw.angle_deg))
    return cols


def write_csv(sw: Sweep, points, links, path: Path) -> Path:
    """The CSV: a header of names and units, then ``'%.17g'`` of every value (each reads back
    to the same double; :mod:`polygons.csv_text`)."""
    from ..csv_text import write_csv_rows
    cols = columns(sw, points, links)
    path.parent.mkdir(parents=True, exist_ok=True)
    header = ",".join(f"{name} [{unit}]" for name, unit, _ in cols)
    with open(path, "wb") as fh:
        fh.write(header.encode() + b"\n")
        write_csv_rows(fh, [c[2] for c in cols], sw.n)
    return path


# ---------------------------------------------------------------- plots
def _decimate(n: int) -> slice:
    return slice(None, None, max(1, math.ceil(n / PLOT_POINTS)))


def plot(sw: Sweep, points, links, shm, unit, stem: Path, formats) -> list[Path]:
    from diagrams.plots import Line, Marker, Panel, plot_panels

    f, lu, vu, au = _units(unit)
    x, xlabel = _x_axis(sw)
    colors = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink"]
    disp, vel, acc = Panel(f"displacement ({lu})", zero_line=False), Panel(f"velocity ({vu})"), \
        Panel(f"acceleration ({au})")
    here, x0 = _at_scene(sw)
    for i, lab in enumerate(points):
        c = colors[i % len(colors)]
        for (name, s, v, a, style), mark in zip(_series(sw, lab), _series(here, lab)):
            _add(disp, vel, acc, sw, x, name, s * f, v * f, a * f, style, c)
            for panel, y in zip((disp, vel, acc), mark[1:4]):   # the scene's own position
                panel.lines.append(Line("", [x0], [float(y[0]) * f], "none", c, marker="o"))
        if lab in shm and np.isfinite(sw.slide_a[lab]).any():
            h = shm[lab]
            _add(disp, vel, acc, sw, x, f"{lab} simple harmonic (pin {h.pin} projected)",
                 h.travel * f, h.velocity * f, h.acceleration * f, ":", "black")
    panels = [disp, vel, acc]
    if links:
        om, al = Panel("ω (rad/s, CCW +)"), Panel("α (rad/s², CCW +)")
        for i, name in enumerate(links):
            c = colors[(i + len(points)) % len(colors)]
            for seg in sw.segments:
                sl = slice(*seg)
                d = _decimate(seg[1] - seg[0])
                first = seg == sw.segments[0]
                om.lines.append(Line(f"ω {name}" if first else "", x[sl][d],
                                     sw.omega[name][sl][d], "-", c))
                al.lines.append(Line(f"α {name}" if first else "", x[sl][d],
                                     sw.alpha[name][sl][d], "-", c))
            om.lines.append(Line("", [x0], [float(here.omega[name][0])], "none", c,
                                 marker="o"))
            al.lines.append(Line("", [x0], [float(here.alpha[name][0])], "none", c,
                                 marker="o"))
        panels += [om, al]
    for panel in panels:          # a key of dozens of curves cannot fit the figure
        keyed = [ln for ln in panel.lines if ln.label]
        if len(keyed) > PLOT_KEYED:
            for ln in keyed[PLOT_KEYED:]:
                ln.label = ""
            panel.title = f"key: the first {PLOT_KEYED} of {len(keyed)} curves"
    where = (f"θ = {number(x0)}°" if sw.input_kind == "crank"
             else f"s = {number(x0)} mm")
    markers = [Marker(x0, f"scene: {where} (dots)", "0.35")]
    for lim in sw.limits:
        if lim.kind in ("limit", "toggle", "near-toggle"):
            xm = math.degrees(lim.input) if sw.input_kind == "crank" else lim.input * 1e3
            if sw.full_cycle and sw.input_kind == "crank":
                xm %= 360.0
            markers.append(Marker(xm, f"{lim.kind} ({lim.point})",
                                  "tab:red" if lim.kind != "near-toggle" else "tab:orange"))
    if sw.full_cycle and sw.input_kind == "crank":
        xlim, xticks = (0.0, 360.0), list(range(0, 361, 45))
    else:
        lo, hi = sw.range
        k = (lambda v: math.degrees(v)) if sw.input_kind == "crank" else (lambda v: v * 1e3)
        xlim, xticks = (k(lo), k(hi)), None
    drv = sw.scene.driver
    rate = (f"ω = {abs(drv.omega):.4g} rad/s {'CCW' if drv.omega > 0 else 'CW'}"
            if isinstance(drv, Crank) else f"v = {drv.velocity:.4g} m/s")
    title = f"{plot_title(sw.scene.title)}\n{rate}, {sw.n} positions"
    if not sw.full_cycle:
        title += " (reachable range)"
    cw = isinstance(drv, Crank) and drv.omega < 0     # the axis in the crank's sense of rotation
    if cw:
        xlabel += "; axis reversed: the crank turns CW, time runs left to right"
    return plot_panels(title, xlabel, panels, stem, formats, markers, xlim, xticks, reverse_x=cw)


def _series(sw: Sweep, lab: str):
    """(name, s, v, a, line style) of the curves drawn for point ``lab``."""
    if lab in sw.travel and lab in sw.slide_v:
        return [(f"{lab} along its guide", sw.travel[lab], sw.slide_v[lab], sw.slide_a[lab],
                 "-")]
    P, V, A = sw.position(lab), sw.velocity(lab), sw.acceleration(lab)
    return [(f"{lab} x", P[:, 0], V[:, 0], A[:, 0], "-"),
            (f"{lab} y", P[:, 1], V[:, 1], A[:, 1], "--")]


def _at_scene(sw: Sweep):
    """The sweep solved at the scene's own input (its branch), and that input on the x axis:
    the dots on every curve where the drawings and ``solve`` stand."""
    drv = sw.scene.driver
    x0 = drv.angle if sw.input_kind == "crank" else drv.position
    here = sweep(sw.scene, inputs=[x0])
    if sw.input_kind == "crank":
        deg = math.degrees(x0)
        return here, (deg % 360.0 if sw.full_cycle else deg)
    return here, x0 * 1e3


def plot_title(title: str) -> str:
    """A scene title as a plot shows it: one line, at most PLOT_TITLE characters (a longer one
    cannot fit the figure)."""
    text = " ".join(str(title).split())
    return text if len(text) <= PLOT_TITLE else text[:PLOT_TITLE - 1] + "…"


def _add(disp, vel, acc, sw, x, name, s, v, a, style, color):
    from diagrams.plots import Line
    for seg in sw.segments:
        sl = slice(*seg)
        d = _decimate(seg[1] - seg[0])
        lab = name if seg == sw.segments[0] else ""
        disp.lines.append(Line(lab, x[sl][d], s[sl][d], style, color))
        vel.lines.append(Line(lab, x[sl][d], v[sl][d], style, color))
        acc.lines.append(Line(lab, x[sl][d], a[sl][d], style, color))


# ---------------------------------------------------------------- summary
def _at(sw: Sweep, i: int) -> str:
    if sw.input_kind == "crank":
        deg = math.degrees(sw.inputs[i])
        return f"θ = {deg % 360.0 if sw.full_cycle else deg:.4g}°"
    x = sw.inputs[i]
    span = float(max(sw.inputs) - min(sw.inputs)) if len(sw.inputs) else 0.0
    if abs(x) <= 1e-9 * span:           # a rounding residue of the grid (−1e-298) reads 0
        x = 0.0
    return f"s = {x * 1e3:.6g} mm"


def _inp(sw: Sweep, x: float) -> str:
    if sw.input_kind == "crank":
        return f"θ = {math.degrees(x):.6g}°"
    return f"s = {x * 1e3:.6g} mm"


def summary(sw: Sweep, points, links, shm, unit, written) -> str:
    f, lu, vu, au = _units(unit)
    scene, drv = sw.scene, sw.scene.driver
    out = [f"{scene.title}", f"  scene: {scene.file}", ""]
    if isinstance(drv, Crank):
        out.append(f"input: crank {drv.link}, ω = {abs(drv.omega):.6g} rad/s "
                   f"{'CCW' if drv.omega > 0 else 'CW'}"
                   + (f", α = {drv.alpha:.6g} rad/s² (held at every position)"
                      if drv.alpha else "") + f"; {sw.n} positions")
    else:
        out.append(f"input: slider {drv.point}, v = {drv.velocity:.6g} m/s, "
                   f"a = {drv.acceleration:.6g} m/s²; {sw.n} positions")
    if sw.full_cycle:
        out.append("range: full revolution, θ = 0…360° (every angle assembles)")
    else:
        lo, hi = sw.range
        out.append(f"range: {_inp(sw, lo)} … {_inp(sw, hi)} (reachable range around the "
                   f"scene's input; positions strictly inside it)")
    for lim in sw.limits:
        if lim.kind == "limit":
            out.append(f"  limit at {_inp(sw, lim.input)}: {lim.reason} — the input cannot "
                       f"pass")
        elif lim.kind == "unbounded":
            out.append(f"  no limit found at {_inp(sw, lim.input)}: {lim.reason}")
    if sw.branches:
        out.append("branch followed from the scene's position: " + ", ".join(
            f"{lab} ({_branch_words(scene, lab)})" for lab in sw.branches))
    good = np.isfinite(sw.angle_deg)
    if good.any():
        worst, x = greatest(sw, lambda s: -s.angle_deg)
        out.append(f"conditioning: smallest construction angle {-worst:.4g}° at "
                   f"{_where(sw, x)}")
    for w in sw.warnings:
        out.append(f"warning: {w}")
    out.append("")
    for lab in points:
        if lab in sw.travel and lab in sw.slide_v:
            s, v, a = sw.travel[lab], sw.slide_v[lab], sw.slide_a[lab]
            e = scene.model.guide[lab].line.angle
            if np.isfinite(s).any():    # the ends of the travel, refined between samples
                s_hi = greatest(sw, lambda w, k=lab: w.travel[k])[0]
                s_lo = -greatest(sw, lambda w, k=lab: -w.travel[k])[0]
                travel = (f"{number(s_lo * f)} … {number(s_hi * f)} {lu} (stroke "
                          f"{number((s_hi - s_lo) * f)} {lu})")
            else:
                travel = "— (no position of the sweep solves it)"
            out.append(f"point {lab} (along its guide at {math.degrees(e):.4g}°): travel "
                       f"{travel}")
            out.append(f"  max |v| = {_peak(sw, lambda s, k=lab: np.abs(s.slide_v[k]), f, vu)}")
            out.append(f"  max |a| = {_peak(sw, lambda s, k=lab: np.abs(s.slide_a[k]), f, au)}")
        else:
            out.append(f"point {lab}:")
            out.append(f"  max |v| = {_peak(sw, lambda s, k=lab: _length(s.velocity(k)), f, vu)}")
            out.append(f"  max |a| = "
                       f"{_peak(sw, lambda s, k=lab: _length(s.acceleration(k)), f, au)}")
        if lab in shm and np.isfinite(sw.slide_a[lab]).any():
            h = shm[lab]
            a = sw.slide_a[lab]
            d = a - h.acceleration
            idd = int(np.nanargmax(np.abs(d)))
            amax = float(np.nanmax(np.abs(a)))
            hmax = float(np.nanmax(np.abs(h.acceleration)))
            dv = float(np.nanmax(np.abs(sw.slide_v[lab] - h.velocity)))
            ds = float(np.nanmax(np.abs(sw.travel[lab] - h.travel)))
            out.append(f"  simple harmonic (crank pin {h.pin} projected on the guide): max |a| "
                       f"= {number(hmax * f)} {au}")
            out.append(f"  difference from SHM: max |Δa| = {number(abs(d[idd]) * f)} {au} at "
                       f"{_at(sw, idd)} ({abs(d[idd]) / amax * 100 if amax else 0:.3g} % of "
                       f"max |a|), max |Δv| = {number(dv * f)} {vu}, max |Δs| = "
                       f"{number(ds * f)} {lu} (travel offset {number(h.offset * f)} {lu})")
    for name in links:
        out.append(f"link {name}: max |ω| = "
                   f"{_peak(sw, lambda s, k=name: np.abs(s.omega[k]), 1.0, 'rad/s')}; max |α| = "
                   f"{_peak(sw, lambda s, k=name: np.abs(s.alpha[k]), 1.0, 'rad/s²')}")
    out.append("")
    out.append("written: " + ", ".join(str(p) for p in written))
    return "\n".join(out) + "\n"


def _length(vec) -> np.ndarray:
    """|v| of (N, 2) vectors."""
    return np.hypot(vec[:, 0], vec[:, 1])


def _peak(sw, values, f: float, unit: str) -> str:
    """'V unit at POSITION' for the greatest of ``values(sweep)`` (NaN where a position is
    not solved) to full precision, refined between the samples
    (:func:`polygons.sweep_extremes.greatest`); 'the same at every position' where it does
    not change; or words saying no position has it (never an argmax of nothing)."""
    vals = values(sw)
    if not np.isfinite(vals).any():
        return "— (no position of the sweep solves it)"
    top, low = float(np.nanmax(vals)), float(np.nanmin(vals))
    if top - low <= 1e-9 * abs(top):
        return f"{number(top * f)} {unit} (the same at every position)"
    value, x = greatest(sw, values)
    return f"{number(value * f)} {unit} at {_where(sw, x)}"


def _where(sw: Sweep, x: float) -> str:
    """The input ``x`` in words (θ within the turn for a full revolution)."""
    if sw.input_kind == "crank":
        deg = math.degrees(x)
        return f"θ = {deg % 360.0 if sw.full_cycle else deg:.6g}°"
    return f"s = {x * 1e3:.6g} mm"


def _branch_words(scene: Scene, lab: str) -> str:
    b = scene.assembly.get(lab)
    return b.text if b is not None else "the only closure at the scene's input"
