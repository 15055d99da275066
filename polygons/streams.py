"""Sweeps of any length in constant memory: the positions solved chunk by chunk and the
summaries (maxima and where they occur, the smallest construction angle) folded on the stream.

:func:`plan_stream` does what :func:`polygons.sweep.sweep` does before solving (plan, the
branch of every closure, the reachable range, limits and toggles) and compiles the construction
for arrays (:func:`polygons.compiled.compile_arrays`); :func:`stream` then yields
``(start, inputs, results)`` chunk by chunk, each chunk's inputs computed, never the whole
sweep's; :class:`Extremes` keeps the summaries.  The results are those of
:func:`polygons.sweep.evaluate`, bit for bit on the shipped cases (tests/test_stream.py).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import PolygonsError
from .scene import Scene
from .sweep import (CHUNK, PROBE, Limit, Program, _SIN_PARALLEL, _fmt_input, arrays_program,
                    compile_plan, evaluate, find_range, from_arrays, run)
from .sweep_follow import _assur_rows, _groups, _referenced, _refined, _take, anchored
from .sweep_store import adopt


@dataclass(frozen=True)
class Stream:
    """A sweep planned but not yet run: what :func:`stream` needs to produce its positions
    chunk by chunk, and what is known before the first one (range, limits, toggles)."""

    prog: Program
    n: int
    full_cycle: bool
    range: tuple[float, float]
    limits: tuple[Limit, ...]
    warnings: tuple[str, ...]
    code: object = None       # the construction compiled for arrays (polygons.compiled)
    params: tuple = ()

    def inputs(self, s: int, e: int) -> np.ndarray:
        """The inputs of positions ``s`` … ``e − 1`` (computed, never stored whole)."""
        lo, hi = self.range
        k = np.arange(s, e, dtype=float)
        if self.full_cycle:
            return 2.0 * math.pi * k / self.n
        return lo + (hi - lo) * (k + 0.5) / self.n


def plan_stream(scene: Scene, steps: int, *, probe: int = PROBE) -> Stream:
    """The sweep :func:`sweep` would run over ``steps`` positions, as a :class:`Stream`."""
    if steps < 2:
        raise PolygonsError(f"a sweep needs at least 2 steps, got {steps}", file=scene.file)
    prog = compile_plan(scene)
    full, rng, limits, toggles = find_range(prog, probe)
    if full:
        rng = (0.0, 2.0 * math.pi)
    warnings = []
    for tg in toggles:
        where = _fmt_input(prog, tg.input)
        warnings.append(f"toggle at {where}: {tg.reason}" if tg.kind == "toggle" else
                        f"near toggle at {where}: {tg.reason}; the construction lines meet "
                        f"at only {tg.angle_deg:.3g}°")
    code, params = arrays_program(prog)
    return Stream(prog, steps, full, rng, tuple(limits) + tuple(toggles), tuple(warnings),
                  code, params)


def stream(st: Stream, *, chunk: int = CHUNK * 4):
    """Yield ``(start, inputs, results)`` for consecutive chunks of ``st``'s positions: the
    results of :func:`evaluate` (toggle positions NaN), in memory one chunk at a time, so a
    sweep of any length runs in constant memory."""
    follow = _groups(st.prog) and st.n > 0
    if follow:      # a triad: from the scene's closure to the first input, then chunk to chunk
        prog = anchored(st.prog, st.inputs(0, 1), evaluate)
        last = None
    for s in range(0, st.n, chunk):
        e = min(st.n, s + chunk)
        xs = st.inputs(s, e)
        if follow:  # each chunk continues from the last row of the one before
            ext = xs if last is None else np.concatenate(([last[0]], xs))
            code, params = arrays_program(prog)
            fine, rows = _refined(prog, ext)        # steps no coarser than continuation's
            res = adopt(from_arrays(prog, code, params, fine), len(fine))
            if len(fine) != len(ext):
                res = _take(res, rows)
            res, _ = _assur_rows(prog, ext, res, run)
            if last is not None:
                res = _rows_from(res, 1)
            prog, last = _referenced(prog, res["pos"], len(xs) - 1), xs[-1:]
        else:
            res = evaluate_compiled(st, xs)
        m = res["margin"]
        at = np.isfinite(m) & (m >= 0) & (m < _SIN_PARALLEL)
        if at.any():
            _undefine_chunk(res, at)
        yield s, xs, res


def _rows_from(res: dict, k: int) -> dict:
    """``res`` without its first ``k`` rows (a chunk's lead-in row, the last of the one
    before)."""
    out = {}
    for key, d in res.items():
        if key == "margin":
            out[key] = d[k:]
            continue
        out[key] = {lab: (v if v is None or (np.ndim(v) == 1 and key == "pos" and
                                             np.shape(v) == (2,)) else np.asarray(v)[..., k:])
                    for lab, v in d.items()}
    return out


def evaluate_compiled(st: Stream, xs: np.ndarray) -> dict:
    """:func:`polygons.sweep.run`'s results for the inputs ``xs``: the fused kernel's loops
    over numpy (:mod:`polygons.fused`) where it makes the construction, as the in-memory
    sweep, else the stream's construction compiled for arrays."""
    from . import sweep as _sweep
    if _sweep.FUSED_NUMPY and len(xs):
        from .fused import fused_of
        fused = fused_of(st.prog, st.code.index, arrays=True)
        if fused is not None:
            return fused.run(st.prog, np.asarray(xs, dtype=float))
    return from_arrays(st.prog, st.code, st.params, xs)


def _undefine_chunk(res: dict, mask: np.ndarray) -> None:
    for key in ("vel", "acc", "coriolis"):
        res[key] = {lab: (None if xy is None else
                          tuple(np.where(mask, np.nan, np.broadcast_to(c, mask.shape))
                                for c in xy))
                    for lab, xy in res[key].items()}
    for key in ("omega", "alpha", "slide_v", "slide_a"):
        res[key] = {lab: np.where(mask, np.nan, np.broadcast_to(v, mask.shape))
                    for lab, v in res[key].items()}


class Extremes:
    """Summaries computed on the stream: for every quantity ``key`` fed to :meth:`add`, the
    largest magnitude and the input where it occurs and the smallest magnitude (NaN positions
    skipped), plus the smallest
    construction angle and the count of positions that could not be assembled."""

    def __init__(self):
        self.max: dict[str, tuple[float, float]] = {}     # key -> (|value|, input)
        self.least: dict[str, float] = {}                # key -> the smallest |value|
        self.at_travel: dict[str, tuple[float, float]] = {}   # slider -> inputs of its ends
        self.min_angle = (math.inf, math.nan)
        self.bad = 0
        self.n = 0

    def add(self, key: str, values, xs) -> None:
        v = np.abs(np.broadcast_to(values, xs.shape))
        if not np.isfinite(v).any():
            return
        i = int(np.nanargmax(v))
        if key not in self.max or v[i] > self.max[key][0]:
            self.max[key] = (float(v[i]), float(xs[i]))
        self.least[key] = min(self.least.get(key, math.inf), float(np.nanmin(v)))

    def add_chunk(self, xs, res) -> None:
        """Every point's |v|, |a|, every link's |ω|, |α|, every slide's rates and travel."""
        self.n += len(xs)
        m = res["margin"]
        self.bad += int((~np.isfinite(m) | (m < 0)).sum())
        with np.errstate(invalid="ignore"):
            ang = np.degrees(np.arcsin(np.where(m >= 0, np.minimum(m, 1.0), np.nan)))
        if np.isfinite(ang).any():
            i = int(np.nanargmin(ang))
            if ang[i] < self.min_angle[0]:
                self.min_angle = (float(ang[i]), float(xs[i]))
        for key, tag in (("vel", "v"), ("acc", "a")):
            for lab, xy in res[key].items():
                if xy is not None:
                    self.add(f"{tag}:{lab}", np.sqrt(xy[0] * xy[0] + xy[1] * xy[1]), xs)
        for key, tag in (("omega", "omega"), ("alpha", "alpha"), ("slide_v", "v_s"),
                         ("slide_a", "a_s")):
            for lab, v in res[key].items():
                self.add(f"{tag}:{lab}", v, xs)
        for lab, s in res["travel"].items():
            lo, hi = self.max.get(f"travel:{lab}", (math.inf, -math.inf))
            at_lo, at_hi = self.at_travel.get(lab, (math.nan, math.nan))
            s = np.broadcast_to(s, xs.shape)
            if np.isfinite(s).any():
                i, j = int(np.nanargmin(s)), int(np.nanargmax(s))
                if s[i] < lo:
                    lo, at_lo = float(s[i]), float(xs[i])
                if s[j] > hi:
                    hi, at_hi = float(s[j]), float(xs[j])
            self.max[f"travel:{lab}"] = (lo, hi)
            self.at_travel[lab] = (at_lo, at_hi)
