"""The compiled CSV writer of :mod:`polygons.csv_text` (imported only where numba is installed
and a block is large): :func:`~polygons.csv_format._put` and a loop over the rows calling it as
a global, both kept in numba's on-disk cache — so a later process loads them (~0.1 s) instead
of compiling them again (~2 s: a writer handed the formatter as an argument is not cached).
The rows are cut into :data:`PARTS` parts written side by side (numba's ``prange``: one part a
core), each into its own region of ``out``."""
from __future__ import annotations

import numba
import numpy as np

from .csv_format import _put

#: parts of a block written side by side (at most one a core)
PARTS = 2
#: the longest field and its separator: '-' + 17 digits + '.' + 'e-308' + ','
FIELD = 25

put = numba.njit(cache=True, error_model="numpy")(_put)


@numba.njit(cache=True, error_model="numpy", parallel=True)
def rows(data, hi, lo, sc, out, used):
    """The rows of ``data`` (n, m) as CSV: part ``p`` (rows ``p·n/P`` … into
    ``out[p·⌈n/P⌉·m·FIELD:]``) written by one thread; ``used[p]`` its bytes."""
    n, m = data.shape
    parts = used.shape[0]
    step = (n + parts - 1) // parts
    for p in numba.prange(parts):
        dig = np.empty(17, np.int64)
        pos = p * step * m * FIELD
        start = pos
        for r in range(p * step, min(n, (p + 1) * step)):
            for c in range(m):
                pos = put(data[r, c], hi, lo, sc, out, pos, dig)
                out[pos] = 44 if c < m - 1 else 10
                pos += 1
        used[p] = pos - start
