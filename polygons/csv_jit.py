"""The compiled CSV writer of :mod:`polygons.csv_text` (imported only where numba is installed
and a block is large): :func:`~polygons.csv_format._put` and a loop over the rows calling it as a
global, both kept in numba's on-disk cache — so a later process loads them (~0.1 s) instead of
compiling them again (~2 s: a writer handed the formatter as an argument is not cached)."""
from __future__ import annotations

import numba
import numpy as np

from .csv_format import _put

put = numba.njit(cache=True, error_model="numpy")(_put)


@numba.njit(cache=True, error_model="numpy")
def rows(data, hi, lo, sc, out):
    """Every row of ``data`` (n, m) as CSV into ``out``; the bytes used."""
    n, m = data.shape
    dig = np.empty(17, np.int64)
    pos = 0
    for r in range(n):
        for c in range(m):
            pos = put(data[r, c], hi, lo, sc, out, pos, dig)
            out[pos] = 44 if c < m - 1 else 10
            pos += 1
    return pos
