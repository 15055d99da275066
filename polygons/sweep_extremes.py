"""The greatest of a swept quantity to full precision, not at the nearest sample.

A sweep samples its input (θ every 1°, say); the largest sample of |v_C| is within
f''·Δθ²/8 of the true greatest — 1e-4 of it at 1°, in the fourth printed figure.  The
summary's "max |v| = … at θ = …" is instead refined between the sample's neighbours: the
quantity is swept again on :data:`SAMPLES` inputs spanning them (in the branch of the
scene's own position, as the sweep and its plots follow it), the bracket narrowed about the
best and swept again, :data:`ROUNDS` times (a bracket of 2Δθ shrinks by
(n − 1)/2 each round: 1° → 1e-7° in six rounds of 33, the value exact to rounding where the
quantity is smooth; at a range's end, where it may be greatest, the bracket stops there).
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from .errors import PolygonsError

#: the sweeps of the refinement: inputs per sweep, and how many
SAMPLES = 33
ROUNDS = 6


def _bracket(sw, i: int) -> tuple[float, float]:
    """The inputs either side of sample ``i`` within its segment (no toggle crossed); a full
    revolution wraps round."""
    xs, n = sw.inputs, sw.n
    seg = next((s for s in sw.segments if s[0] <= i < s[1]), (0, n))
    whole = sw.full_cycle and len(sw.segments) <= 1
    if i - 1 >= seg[0]:
        lo = float(xs[i - 1])
    elif whole and n > 1:
        lo = float(xs[n - 1]) - 2.0 * math.pi
    else:
        lo = float(xs[i])
    if i + 1 < seg[1]:
        hi = float(xs[i + 1])
    elif whole and n > 1:
        hi = float(xs[0]) + 2.0 * math.pi
    else:
        hi = float(xs[i])
    return lo, hi


def refine(scene, lo: float, hi: float, values: Callable,
           start: tuple[float, float]) -> tuple[float, float]:
    """(value, input): the greatest of ``values(sweep)`` over inputs in [lo, hi], from the
    sample ``start`` = (value, input): swept on :data:`SAMPLES` inputs of the scene's own
    branch (as the sweep followed it), the bracket narrowed about the best, :data:`ROUNDS`
    times; ``start`` where no refining sweep can be made."""
    best = start
    if not hi > lo:
        return best
    from .sweep import sweep
    try:
        for _ in range(ROUNDS):
            xs = np.linspace(lo, hi, SAMPLES)
            vals = values(sweep(scene, inputs=xs))
            if not np.isfinite(vals).any():
                break
            j = int(np.nanargmax(vals))
            if vals[j] > best[0]:
                best = (float(vals[j]), float(xs[j]))
            step = (hi - lo) / (SAMPLES - 1)
            lo, hi = max(lo, float(xs[j]) - step), min(hi, float(xs[j]) + step)
    except PolygonsError:
        pass
    return best


def greatest(sw, values: Callable, i: int | None = None) -> tuple[float, float]:
    """(value, input): the greatest of ``values(sweep)`` (an array over a sweep's inputs,
    NaN where not solved) about the sample ``i`` (default: the sweep's largest), refined
    between its neighbours (:func:`refine`)."""
    v0 = values(sw)
    if i is None:
        i = int(np.nanargmax(v0))
    lo, hi = _bracket(sw, i)
    return refine(sw.scene, lo, hi, values, (float(v0[i]), float(sw.inputs[i])))


__all__ = ["greatest", "refine", "SAMPLES", "ROUNDS"]
