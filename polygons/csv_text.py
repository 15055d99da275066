"""The CSV text of float64 columns: the bytes of ``'%.17g' % x`` for every value (what
``np.savetxt(fmt="%.17g")`` writes, so every number reads back to the same double), fast.

With numba installed (optional: the ``jit`` extra) one compiled loop writes the whole block of
rows (~20–40 M values/s against ~1.5 M for ``np.savetxt``); without it the block goes through
``np.savetxt`` — the same bytes either way (tests/test_csv_text.py compares the two on
millions of values across the whole float64 range).

How a value becomes text in the compiled loop:

* its 17 significant digits ``D`` and decimal exponent ``k`` with ``x = D·10^k``:
  ``D = round(|x|·10^-k)``, the product formed exactly as a double-double (Dekker's split) with
  ``10^-k`` held as a double-double (scaled by 2^±200 at the ends of the range, so the split
  cannot overflow), so ``D`` is the correctly rounded one except where ``|x|·10^-k`` lies within
  ~1e-15 of a half and is not one — there the 17th digit may be one off, which still reads back
  to ``x`` (17 digits step by at most 0.9 ulp); an exact half (found from the binary exponent
  and the trailing zero bits of the mantissa) goes to the even neighbour, as ``%g`` does;
* the ``%g`` layout: fixed notation for decimal exponents −4 … 16, else ``d.ddde±XX`` (at least
  two exponent digits), trailing zeros and a bare point dropped; ``nan``, ``inf``, ``-0``.
"""
from __future__ import annotations

import importlib.util
import math
from fractions import Fraction
from functools import lru_cache

import numpy as np

#: rows written per block (31 columns: ~25 MB of text at most)
BLOCK = 32768
#: fewer values than this are written by np.savetxt (importing numba costs ~0.3 s)
COMPILED_FROM = 200_000
from .csv_format import _E16, _E17, _K_HI, _K_LO, _put  # noqa: F401  (the formatter)
_SCALE_K = 150                      # beyond ±this k the power and |x| are scaled by 2^∓200


@lru_cache(maxsize=1)
def _powers():
    """(hi, lo, s): 10^-k·2^s = hi + lo to ~2^-106 for k = _K_LO … _K_HI."""
    ks = range(_K_LO, _K_HI + 1)
    hi, lo, sc = np.empty(len(ks)), np.empty(len(ks)), np.zeros(len(ks), np.int64)
    for i, k in enumerate(ks):
        s = -200 if k < -_SCALE_K else (200 if k > _SCALE_K else 0)
        p = Fraction(10) ** -k * Fraction(2) ** s
        h = float(p)
        hi[i], lo[i], sc[i] = h, float(p - Fraction(h)), s
    return hi, lo, sc


@lru_cache(maxsize=1)
def _compiled():
    """The compiled row writer (:mod:`polygons.csv_jit`, kept in numba's on-disk cache), or
    None without numba."""
    if importlib.util.find_spec("numba") is None:
        return None
    try:
        from .csv_jit import rows
        return rows
    except Exception:                            # noqa: BLE001 - any numba failure: np.savetxt
        return None


def csv_rows(columns, n: int, compiled: bool | None = None) -> bytes:
    """The CSV text of ``n`` rows of ``columns`` (each a scalar or an (n,) array): ``'%.17g'``
    fields joined by ',' and each row ended by a newline — ``np.savetxt``'s bytes.
    ``compiled``: None = the compiled loop where numba is installed and the block is large."""
    m = len(columns)
    if n == 0 or m == 0:
        return b"\n" * n if n else b""
    data = np.empty((n, m))
    for j, c in enumerate(columns):
        data[:, j] = c
    kernel = _compiled() if compiled or (compiled is None and n * m >= COMPILED_FROM) \
        else None
    if kernel is None:
        import io
        buf = io.BytesIO()
        np.savetxt(buf, data, delimiter=",", fmt="%.17g")
        return buf.getvalue()
    from .csv_jit import FIELD, PARTS
    hi, lo, sc = _powers()
    out = np.empty(n * m * FIELD, np.uint8)
    used = np.zeros(PARTS, np.int64)
    kernel(data, hi, lo, sc, out, used)
    step = -(-n // PARTS) * m * FIELD
    return b"".join(out[p * step:p * step + used[p]] for p in range(PARTS))


def write_csv_rows(fh, columns, n: int, compiled: bool | None = None) -> None:
    """Write ``n`` rows of ``columns`` to the binary file ``fh``, BLOCK rows at a time (the
    compiled writer where numba is installed and there are COMPILED_FROM values or more, or
    ``compiled`` says so)."""
    if compiled is None:
        compiled = n * len(columns) >= COMPILED_FROM
    for s in range(0, n, BLOCK):
        e = min(n, s + BLOCK)
        fh.write(csv_rows([c if np.ndim(c) == 0 else c[s:e] for c in columns], e - s,
                          compiled=compiled))


#: the fixed timestamp of every member of a written .npz (the same bytes at every run)
_ZIP_TIME = (1980, 1, 1, 0, 0, 0)


class NpzColumns:
    """A ``.npz`` (numpy's zip of ``.npy`` arrays, read by ``np.load``) written row block by
    row block in constant memory: ``data`` — float64 (rows, columns), every value exact —,
    ``columns`` and ``units`` — the names and units of its columns.  Deterministic bytes (fixed
    member times, no compression).  Use as a context manager; ``add(columns, n)`` appends ``n``
    rows (each column a scalar or an (n,) array)."""

    def __init__(self, path, names_units, rows: int):
        self.path, self.names_units, self.rows = path, list(names_units), rows
        self.done = 0

    def __enter__(self):
        import zipfile
        self.zf = zipfile.ZipFile(self.path, "w", compression=zipfile.ZIP_STORED,
                                  allowZip64=True)
        for key, i in (("columns", 0), ("units", 1)):
            arr = np.array([nu[i] for nu in self.names_units], dtype="U")
            with self.zf.open(self._info(key), "w", force_zip64=True) as fh:
                np.lib.format.write_array(fh, arr, allow_pickle=False)
        self.fh = self.zf.open(self._info("data"), "w", force_zip64=True)
        np.lib.format.write_array_header_2_0(self.fh, {
            "descr": np.lib.format.dtype_to_descr(np.dtype("<f8")), "fortran_order": False,
            "shape": (self.rows, len(self.names_units))})
        return self

    def _info(self, key):
        import zipfile
        info = zipfile.ZipInfo(f"{key}.npy", date_time=_ZIP_TIME)
        info.compress_type = zipfile.ZIP_STORED
        info.external_attr = 0o644 << 16
        return info

    def add(self, columns, n: int) -> None:
        block = np.empty((n, len(columns)), "<f8")
        for j, c in enumerate(columns):
            block[:, j] = c
        self.fh.write(block.tobytes())
        self.done += n

    def __exit__(self, *exc):
        self.fh.close()
        self.zf.close()
        if exc[0] is None and self.done != self.rows:
            raise RuntimeError(f"{self.path}: {self.done} rows written of {self.rows}")
        return False


def write_npz(path, names_units, columns, n: int) -> None:
    """The in-memory table as :class:`NpzColumns` writes it."""
    with NpzColumns(path, names_units, n) as w:
        for s in range(0, n, BLOCK):
            e = min(n, s + BLOCK)
            w.add([c if np.ndim(c) == 0 else c[s:e] for c in columns], e - s)
