"""``polygons sweep`` for long sweeps (``--steps`` ≥ ``STREAM_FROM``), in constant memory: the
positions are solved chunk by chunk (:func:`polygons.sweep.stream`), each chunk appended to the
CSV and folded into the summary (:class:`polygons.sweep.Extremes`: maxima and where they occur,
the smallest construction angle) and then dropped.  The plots are drawn from every k-th
position (at most ``PLOT_POINTS`` per curve, as for a short sweep).
"""
from __future__ import annotations

import math
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..csv_text import COMPILED_FROM, NpzColumns, write_csv_rows
from ..errors import UnknownLabelError, suggest
from ..scene import Crank, Scene
from ..streams import Extremes, evaluate_compiled, plan_stream, stream
from ..sweep import _segments, default_points, sweep
from ..sweep_extremes import refine
from ..steps import number

PLOT_POINTS = 4000


def chosen(scene: Scene, opt: dict, st, probe) -> tuple[list, list]:
    """(points, links) of the CSV, the plots and the summary: the asked ones (checked), else
    the defaults."""
    labels = [k for k in probe["pos"]]
    for lab in opt["points"] or []:
        if lab not in labels:
            raise UnknownLabelError(f"unknown point {lab!r}: {suggest(lab, labels)}",
                                    file=scene.file, where="sweep.points")
    for name in opt["links"] or []:
        if name not in probe["omega"]:
            raise UnknownLabelError(f"unknown link {name!r}: {suggest(name, probe['omega'])}",
                                    file=scene.file, where="sweep.links")
    drv = scene.driver
    points = opt["points"] or default_points(scene, st.prog.plan, probe["pos"],
                                             probe["travel"])
    crank = drv.link if isinstance(drv, Crank) else None
    links = opt["links"] if opt["links"] is not None else [k for k in probe["omega"]
                                                           if k != crank]
    return points, links


def run_stream(args, scene: Scene, opt: dict, progress: bool, plot, units, st=None) -> int:
    n = opt["steps"]
    st = st if st is not None else plan_stream(scene, n)
    probe = evaluate_compiled(st, st.inputs(0, 2))
    points, links = chosen(scene, opt, st, probe)
    # the .npz holds every point placed and every link
    data_points, data_links = (list(probe["pos"]), list(probe["omega"])) if opt.get("npz") \
        else (points, links)
    out = Path(args.out)
    stem = out / f"{Path(args.scene).stem}-sweep"
    path = stem.with_suffix(".npz" if opt.get("npz") else ".csv")
    path.parent.mkdir(parents=True, exist_ok=True)
    ext = Extremes()
    compiled = n >= COMPILED_FROM        # a long sweep: the compiled writer wherever numba is
    bar = None
    if progress:
        from tqdm import tqdm
        bar = tqdm(total=n, unit="pos", unit_scale=True, desc="sweep", file=sys.stderr,
                   leave=False)
    try:
        if opt.get("npz"):
            probe_cols = _columns(st, st.inputs(0, 2), probe, data_points, data_links)
            with NpzColumns(path, [(nm, u) for nm, u, _ in probe_cols], n) as w:
                for s, xs, res in stream(st):
                    w.add([c for _, _, c in _columns(st, xs, res, data_points, data_links)],
                          len(xs))
                    ext.add_chunk(xs, res)
                    if bar is not None:
                        bar.update(len(xs))
        else:
            with open(path, "wb") as fh:
                head = None
                for s, xs, res in stream(st):
                    cols = _columns(st, xs, res, points, links)
                    if head is None:
                        head = ",".join(f"{name} [{unit}]" for name, unit, _ in cols)
                        fh.write(head.encode() + b"\n")
                    write_csv_rows(fh, [c for _, _, c in cols], len(xs), compiled=compiled)
                    ext.add_chunk(xs, res)
                    if bar is not None:
                        bar.update(len(xs))
    finally:
        if bar is not None:
            bar.close()
    written = [path]
    if not args.no_plot:
        k = max(1, math.ceil(n / PLOT_POINTS))
        idx = np.arange(0, n, k)
        xs = st.inputs(0, n)[idx] if n <= 10 * PLOT_POINTS else _inputs_at(st, idx)
        sw = sweep(scene, inputs=xs)
        toggles = [lim for lim in st.limits if lim.kind == "toggle"]
        sw = replace(sw, full_cycle=st.full_cycle, range=st.range, limits=st.limits,
                     segments=_segments(xs, toggles, st.full_cycle))
        formats = list(args.formats)
        written += plot(sw, points, links, {}, opt["unit"], stem, formats)
    sys.stdout.write(_summary(st, ext, points, links, opt["unit"], units, written, k_plot=(
        max(1, math.ceil(n / PLOT_POINTS)) if not args.no_plot else None)))
    return 0


def _inputs_at(st, idx):
    lo, hi = st.range
    k = idx.astype(float)
    if st.full_cycle:
        return 2.0 * math.pi * k / st.n
    return lo + (hi - lo) * (k + 0.5) / st.n


def _columns(st, xs, res, points, links):
    cols = []
    if st.prog.input_kind == "crank":
        cols += [("theta", "rad", xs), ("theta_deg", "deg", np.degrees(xs))]
    else:
        cols.append(("s_input", "m", xs))
    zero = (0.0, 0.0)
    for lab in points:
        P = res["pos"][lab]
        V = res["vel"].get(lab)
        A = res["acc"].get(lab)
        V, A = zero if V is None else V, zero if A is None else A
        cols += [(f"{lab}.x", "m", P[0]), (f"{lab}.y", "m", P[1]),
                 (f"{lab}.vx", "m/s", V[0]), (f"{lab}.vy", "m/s", V[1]),
                 (f"{lab}.ax", "m/s^2", A[0]), (f"{lab}.ay", "m/s^2", A[1])]
        if lab in res["travel"]:
            cols.append((f"{lab}.s", "m", res["travel"][lab]))
        if lab in res["slide_v"]:
            cols += [(f"{lab}.v_s", "m/s", res["slide_v"][lab]),
                     (f"{lab}.a_s", "m/s^2", res["slide_a"][lab])]
    for name in links:
        cols += [(f"{name}.omega", "rad/s", res["omega"][name]),
                 (f"{name}.alpha", "rad/s^2", res["alpha"][name])]
    m = res["margin"]
    with np.errstate(invalid="ignore"):
        cols.append(("min_angle", "deg",
                     np.degrees(np.arcsin(np.where(m >= 0, np.minimum(m, 1.0), np.nan)))))
    return cols


def _at(st, x: float) -> str:
    if st.prog.input_kind == "crank":
        deg = math.degrees(x)
        return f"θ = {deg % 360.0 if st.full_cycle else deg:.6g}°"
    return f"s = {x * 1e3:.6g} mm"


def _length(vec) -> np.ndarray:
    return np.hypot(vec[:, 0], vec[:, 1])


#: what a key of :class:`~polygons.streams.Extremes` measures, over a sweep
_MEASURES = {"v": lambda s, k: _length(s.velocity(k)),
             "a": lambda s, k: _length(s.acceleration(k)),
             "v_s": lambda s, k: np.abs(s.slide_v[k]), "a_s": lambda s, k: np.abs(s.slide_a[k]),
             "omega": lambda s, k: np.abs(s.omega[k]), "alpha": lambda s, k: np.abs(s.alpha[k]),
             "travel": lambda s, k: s.travel[k], "-travel": lambda s, k: -s.travel[k]}


def _refined(st, key: str, start: tuple[float, float]) -> tuple[float, float]:
    """The stream's greatest of ``key`` (|value|, input), refined between the positions either
    side of it as the whole-sweep summary refines its samples
    (:func:`polygons.sweep_extremes.refine`; no toggle crossed)."""
    tag, _, lab = key.partition(":")
    if key == "angle":
        fn = (lambda s: -s.angle_deg)
    else:
        fn = (lambda s, m=_MEASURES[tag], k=lab: m(s, k))
    value, x = start
    lo, hi = st.range
    if st.full_cycle:
        step = 2.0 * math.pi / st.n
        a, b = x - step, x + step
    else:
        step = (hi - lo) / st.n
        a, b = max(x - step, lo + 0.5 * step), min(x + step, hi - 0.5 * step)
    for lim in st.limits:
        if lim.kind == "toggle" and a < lim.input < x:
            a = x
        if lim.kind == "toggle" and x < lim.input < b:
            b = x
    if st.full_cycle and any(lim.kind == "toggle" for lim in st.limits):
        a, b = max(a, 0.0), min(b, 2.0 * math.pi - step)
    return refine(st.prog.scene, a, b, fn, (value, x))


def _peak(st, ext: Extremes, key: str, f: float, unit: str) -> str:
    """As the whole sweep's: the greatest to full precision, or the same everywhere."""
    if key not in ext.max:
        return "— (no position of the sweep solves it)"
    value, x = ext.max[key]
    low = ext.least.get(key, -math.inf)
    if value - low <= 1e-9 * abs(value):
        return f"{number(value * f)} {unit} (the same at every position)"
    value, x = _refined(st, key, (value, x))
    return f"{number(value * f)} {unit} at {_at(st, x)}"


def _summary(st, ext: Extremes, points, links, unit, units, written, k_plot) -> str:
    f, lu, vu, au = units(unit)
    scene, drv = st.prog.scene, st.prog.scene.driver
    out = [f"{scene.title}", f"  scene: {scene.file}", ""]
    if isinstance(drv, Crank):
        out.append(f"input: crank {drv.link}, ω = {abs(drv.omega):.6g} rad/s "
                   f"{'CCW' if drv.omega > 0 else 'CW'}; {st.n} positions, streamed (summaries "
                   f"on the stream, constant memory)")
    else:
        out.append(f"input: slider {drv.point}, v = {drv.velocity:.6g} m/s; {st.n} positions, "
                   f"streamed (summaries on the stream, constant memory)")
    lo, hi = st.range
    out.append("range: full revolution, θ = 0…360° (every angle assembles)" if st.full_cycle
               else f"range: {_at(st, lo)} … {_at(st, hi)} (reachable range)")
    for lim in st.limits:
        if lim.kind == "limit":
            out.append(f"  limit at {_at(st, lim.input)}: {lim.reason}")
    for w in st.warnings:
        out.append(f"warning: {w}")
    if ext.bad:
        out.append(f"warning: {ext.bad} of {ext.n} positions cannot be assembled (NaN)")
    if math.isfinite(ext.min_angle[0]):
        worst, x = _refined(st, "angle", (-ext.min_angle[0], ext.min_angle[1]))
        out.append(f"conditioning: smallest construction angle {-worst:.4g}° at "
                   f"{_at(st, x)}")
    out.append("")
    for lab in points:
        if f"travel:{lab}" in ext.max:
            s_lo, s_hi = ext.max[f"travel:{lab}"]
            s_hi = _refined(st, f"travel:{lab}", (s_hi, ext.at_travel[lab][1]))[0]
            s_lo = -_refined(st, f"-travel:{lab}", (-s_lo, ext.at_travel[lab][0]))[0]
            out.append(f"point {lab}: travel {number(s_lo * f)} … {number(s_hi * f)} {lu} "
                       f"(stroke {number((s_hi - s_lo) * f)} {lu})")
        else:
            out.append(f"point {lab}:")
        for tag, u in (("v", vu), ("a", au)):
            key = f"{tag}_s:{lab}" if f"{tag}_s:{lab}" in ext.max else f"{tag}:{lab}"
            if key in ext.max:
                out.append(f"  max |{tag}| = {_peak(st, ext, key, f, u)}")
    for name in links:
        out.append(f"link {name}: max |ω| = {_peak(st, ext, f'omega:{name}', 1.0, 'rad/s')}; "
                   f"max |α| = {_peak(st, ext, f'alpha:{name}', 1.0, 'rad/s²')}")
    out.append("")
    if k_plot:
        out.append(f"plots drawn from every {k_plot}th position")
    out.append("written: " + ", ".join(str(p) for p in written))
    return "\n".join(out) + "\n"
