"""A sweep's result arrays: one block for all positions, filled pass by pass
(:func:`allocate`, :func:`store`), or a single pass's own arrays kept (:func:`adopt`, the
numba kernel's rows).  Split from :mod:`polygons.sweep`, which uses them."""
from __future__ import annotations

import numpy as np


def adopt(res: dict, n: int) -> dict:
    """:func:`polygons.sweep.run`'s result from one pass's :func:`polygons.sweep.evaluate` (its arrays kept, not copied;
    constants broadcast read-only as :func:`allocate` makes them)."""
    out = {}
    for key in _VEC_KEYS:
        out[key] = {lab: xy if xy is None or isinstance(xy, np.ndarray)
                    or (key == "pos" and np.ndim(xy[0]) == 0) else np.array(xy)
                    for lab, xy in res[key].items()}
    for key in _SCALAR_KEYS:
        out[key] = {lab: np.broadcast_to(np.float64(v), (n,)) if np.ndim(v) == 0
                    else np.asarray(v) for lab, v in res[key].items()}
    out["margin"] = res["margin"]
    return out


_VEC_KEYS = ("pos", "vel", "acc", "coriolis")
_SCALAR_KEYS = ("omega", "alpha", "slide_v", "slide_a", "travel")


def result_block(rows: int, n: int) -> np.ndarray:
    """An uninitialised ``(rows, n)`` float64 block for a sweep's results, written once front
    to back: numpy's own (with its huge-page advice for large blocks).  A block mapped with
    its pages populated and without that advice was tried (session 9) and measured on the
    quiet machine: 2.5–3× slower at every N ≤ 32 (N = 1, 10⁶ positions: 10.7 against
    31.7 M/s by numba; N = 32: 0.83 against 1.90 M/s), so it is not used."""
    return np.empty((rows, n))


def allocate(res: dict, n: int) -> dict:
    """Result arrays for ``n`` positions, shaped after one evaluated chunk ``res``: views into
    one block (one allocation, which the allocator can hand back whole to the next sweep).
    Constant results (the crank's ω and α) are read-only broadcasts, not filled arrays."""
    rows = 1
    for key in _VEC_KEYS:
        for lab, xy in res[key].items():
            if not (xy is None or (key == "pos" and np.ndim(xy[0]) == 0 and np.ndim(xy[1]) == 0)):
                rows += 2
    for key in _SCALAR_KEYS:
        rows += sum(1 for v in res[key].values() if np.ndim(v) != 0)
    block = result_block(rows, n)
    i = 0
    out = {}
    for key in _VEC_KEYS:
        d = {}
        for lab, xy in res[key].items():
            if xy is None or (key == "pos" and np.ndim(xy[0]) == 0 and np.ndim(xy[1]) == 0):
                d[lab] = xy
            else:
                d[lab] = block[i:i + 2]
                i += 2
        out[key] = d
    for key in _SCALAR_KEYS:
        d = {}
        for lab, v in res[key].items():
            if np.ndim(v) == 0:
                d[lab] = np.broadcast_to(np.float64(v), (n,))
            else:
                d[lab] = block[i]
                i += 1
        out[key] = d
    out["margin"] = block[i]
    return out


def store(out: dict, res: dict, s: int, e: int) -> None:
    for key in _VEC_KEYS:
        for lab, arr in out[key].items():
            if isinstance(arr, np.ndarray):
                x, y = res[key][lab]
                arr[0, s:e] = x
                arr[1, s:e] = y
    for key in _SCALAR_KEYS:
        for lab, arr in out[key].items():
            if arr.flags.writeable:
                arr[s:e] = res[key][lab]
    out["margin"][s:e] = res["margin"]
