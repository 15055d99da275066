"""The reachable range of a sweep's input, its limit positions and the toggles inside it
(split from :mod:`polygons.sweep`, which passes its evaluation in and re-exports these names).

The margin (the sine of the smallest construction angle; negative where a group cannot
close) is probed over the input's cycle (a crank) or a span about it (a slider); every local
minimum below the warning angle is refined by a golden-section search (:func:`golden_min`),
which finds change points that only touch zero and unreachable slivers narrower than the
probe spacing; every end of the range by bisection (the last input that still closes).  A
:class:`Limit` says where and why, in the group's own words (``toggle_reason``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import ConstructionError
from .sweep_follow import _margin_fn

#: same thresholds as polygons.geometry (kept equal by tests/test_sweep.py)
PARALLEL_DEG = 1e-5
WARN_DEG = 1.0
_SIN_PARALLEL = math.sin(math.radians(PARALLEL_DEG))
_SIN_WARN = math.sin(math.radians(WARN_DEG))
#: probe points used to find the reachable range and the toggles inside it
PROBE = 4096


@dataclass(frozen=True)
class Limit:
    """A limit of the reachable range or a toggle / change point inside it."""

    input: float        # θ in rad (crank driver) or s in m (slider driver)
    kind: str           # 'limit' (the range ends here) | 'toggle' (branches meet, sweep split)
                        # | 'near-toggle' (smallest angle below WARN_DEG but not zero)
    point: str          # the point whose dyad degenerates
    reason: str         # in words, e.g. "BC and CD in line"
    angle_deg: float    # intersection angle of the construction there


def margin_at(prog, x, evaluate) -> np.ndarray:
    """The margin at the inputs ``x`` (``evaluate``: :func:`polygons.sweep.evaluate`)."""
    return evaluate(prog, np.atleast_1d(np.asarray(x, dtype=float)), rates=False)["margin"]


def culprit(prog, x: float, place) -> tuple[str, str]:
    """The dyad with the smallest margin at input ``x``, and what degenerates there
    (``place``: :func:`polygons.sweep.place`)."""
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        pos, margins = place(prog, np.array([x], dtype=float))
    if not margins:
        return "", ""
    d, _ = min(margins, key=lambda dm: float(dm[1][0]) if np.isfinite(dm[1][0]) else -math.inf)
    at = {k: (v[:, 0] if np.ndim(v) > 1 else v) for k, v in pos.items()}
    return d.placed[0], d.toggle_reason(prog.scene, at)


def _bisect(margin, good: float, bad: float, iters: int = 200) -> float:
    """The last input from ``good`` towards ``bad`` where the mechanism still closes
    (``margin``: the margin at an input, :func:`_margin_fn`)."""
    for _ in range(iters):
        mid = 0.5 * (good + bad)
        if mid == good or mid == bad:
            break
        m = margin(mid)
        if m >= 0:
            good = mid
        else:
            bad = mid
    return good


def golden_min(margin, a: float, b: float, iters: int = 120) -> tuple[float, float]:
    """(x, margin(x)) at the least of ``margin`` on [a, b] by golden section (a unimodal
    function: the margin near a toggle, |v| at a dead centre); a NaN counts as not less."""
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = margin(c), margin(d)
    for _ in range(iters):
        if not (fc >= fd):    # also when fc is NaN
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = margin(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = margin(d)
        if b - a <= 1e-15 * max(1.0, abs(a)):
            break
    x = 0.5 * (a + b)
    return x, float(margin(x))


def _deg_of(m: float) -> float:
    return math.degrees(math.asin(min(1.0, max(0.0, m))))


def find_range(prog, probe: int = PROBE, *, evaluate, place):
    """(full_cycle, (lo, hi), limits, events) for the scene's input: the reachable range
    around it, its limit positions, and the toggles / near-toggles inside it.

    The margin (sine of the smallest construction angle; negative where a dyad cannot close)
    is probed at ``probe`` inputs; every local minimum below ``WARN_DEG`` is refined by a
    golden-section search, which finds change points that only touch zero and unreachable
    slivers narrower than the probe spacing; every end of the range is refined by bisection.
    ``evaluate`` and ``place``: the sweep's (:mod:`polygons.sweep` passes them).
    """
    def _margin(p, x):
        return margin_at(p, x, evaluate)

    def _culprit(p, x):
        return culprit(p, x, place)

    x0 = prog.input0
    closed = prog.input_kind == "crank"
    if closed:
        period = 2.0 * math.pi
        step = period / probe
        xs = x0 + step * np.arange(probe)
        span = period
    else:
        span = 2.0 * (sum(l.length for l in prog.scene.model.links() if l.length)
                      + max([math.hypot(*g) for g in prog.ground.values()] + [0.0]))
        span = max(span, prog.scale, 4.0 * abs(x0))    # (no links: the input's own size)
        half = probe // 2
        step = span / half
        xs = x0 + step * np.arange(-half, half + 1)
    m = _margin(prog, xs)
    ok = m >= 0
    if not (m >= _SIN_PARALLEL).any() and ok.any():
        # a toggle everywhere (a slot parallel to its guide at every input): no position has
        # its polygons, refused as solve refuses the scene's own position
        point, why = _culprit(prog, float(xs[int(np.flatnonzero(ok)[0])]))
        raise ConstructionError(f"every probed position of the input is a toggle or change "
                                f"point ({point}: {why}): the polygons are undefined throughout "
                                f"the cycle", file=prog.scene.file)
    margin, near = _margin_fn(prog, xs, ok, evaluate, _margin)
    # local minima below the warning angle, refined
    left = np.roll(m, 1)
    right = np.roll(m, -1)
    cand = ok & (m < _SIN_WARN) & (m <= left) & (m <= right) & np.roll(ok, 1) & np.roll(ok, -1)
    if not closed:
        cand[0] = cand[-1] = False
    events: list[Limit] = []
    gaps: list[float] = []
    for i in np.flatnonzero(cand):
        xm, fm = golden_min(margin, xs[i] - step, xs[i] + step)
        if not np.isfinite(fm) or fm < 0:
            gaps.append(xm)
        else:
            kind = "toggle" if fm < _SIN_PARALLEL else "near-toggle"
            events.append(Limit(xm, kind, *_culprit(near(xm), xm), angle_deg=_deg_of(fm)))
    bad = [float(x) for x in xs[~ok]] + gaps
    if closed and not bad:
        return True, (x0, x0 + period), (), tuple(events)
    # the nearest unreachable input on each side of the scene's input (unwrapped for a crank)
    if closed:
        rel = [(b - x0) % period for b in bad]
        rel = [r for r in rel if r > 0] or [period]
        hi_bad = x0 + min(rel)
        lo_bad = x0 - min(period - r for r in rel)
    else:
        above = [b for b in bad if b > x0]
        below = [b for b in bad if b < x0]
        hi_bad = min(above) if above else None
        lo_bad = max(below) if below else None
    limits: list[Limit] = []
    ends = []
    for bad_x, sign in ((lo_bad, -1), (hi_bad, 1)):
        if bad_x is None:
            edge = xs[0] if sign < 0 else xs[-1]
            ends.append(float(edge))
            limits.append(Limit(float(edge), "unbounded", "", f"the mechanism still closes "
                                f"here; the probe stopped {span:.3g} m from the scene's "
                                f"input", 90.0))
            continue
        k = math.floor(abs(bad_x - x0) / step - 1e-9)      # probes strictly before bad_x
        good = x0 + sign * k * step
        x = _bisect(margin, good, bad_x)
        ends.append(x)
        pt, why = _culprit(near(x), x)
        limits.append(Limit(x, "limit", pt, why, _deg_of(max(margin(x), 0.0))))
    lo, hi = ends
    inside = []
    for ev in events:
        x = ev.input
        if closed:
            x = lo + (x - lo) % period
        if lo < x < hi:
            inside.append(Limit(x, ev.kind, ev.point, ev.reason, ev.angle_deg))
    return False, (lo, hi), tuple(limits), tuple(sorted(inside, key=lambda e: e.input))


__all__ = ["PARALLEL_DEG", "WARN_DEG", "PROBE", "Limit", "margin_at", "culprit",
           "golden_min", "find_range"]
