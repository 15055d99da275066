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
_K_LO, _K_HI = -345, 300            # k = decimal exponent − 16 over the whole float64 range
_E16, _E17 = 10000000000000000, 100000000000000000
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


def _put(x, hi, lo, sc, out, pos, dig):
    """Write ``'%.17g' % x`` into ``out`` from ``pos``; the position after it."""
    if x != x:
        out[pos] = 110
        out[pos + 1] = 97
        out[pos + 2] = 110                                   # nan
        return pos + 3
    if x < 0 or (x == 0 and math.copysign(1.0, x) < 0):
        out[pos] = 45                                        # -
        pos += 1
        x = -x
    if x == math.inf:
        out[pos] = 105
        out[pos + 1] = 110
        out[pos + 2] = 102                                   # inf
        return pos + 3
    if x == 0:
        out[pos] = 48
        return pos + 1
    k = int(math.floor(math.log10(x))) - 16
    if k < _K_LO:
        k = _K_LO
    D = 0
    down = False
    for _ in range(4):                          # log10 may be one off next to a power of ten
        i = k - _K_LO
        ph = hi[i]
        pl = lo[i]
        a = x
        if sc[i] != 0:
            a = math.ldexp(x, -int(sc[i]))      # exact: |x|·2^-s
        p = a * ph
        t = 134217729.0 * a                     # Dekker: a·ph = p + e exactly
        ah = t - (t - a)
        al = a - ah
        t = 134217729.0 * ph
        qh = t - (t - ph)
        ql = ph - qh
        e = ((ah * qh - p) + ah * ql + al * qh) + al * ql
        e = e + a * pl
        below = math.floor(e)
        f = e - below
        D = int(p) + int(below)                 # p ≥ 2^53 here is a whole number
        if D < _E16:                        # the digits start one place later
            k -= 1
            down = True
            continue
        if D >= _E17:
            if down:                            # 10^16 just under it, 10^17 just over it:
                D = _E17                    # the power of ten itself (made 10^16 below)
                break
            k += 1
            continue
        if f > 0.5:
            D += 1
        elif f == 0.5 or (k < 0 and abs(f - 0.5) < 1e-9):
            # a half, or next to one: exact (m·5^-k·2^(q−53+tz−k), m odd, has q−53+tz−k = −1)
            # only for k < 0; then to the even neighbour, as %g does
            mant, q = math.frexp(x)
            mi = int(mant * 9007199254740992.0)
            tz = 0
            while mi & 1 == 0:
                mi >>= 1
                tz += 1
            if k < 0 and q - 53 + tz - k == -1:
                D += D & 1
            elif f > 0.5:
                D += 1
        break
    if D == _E17:                           # rounded up to 10^17: one digit fewer
        D = _E16
        k += 1
    E = k + 16
    top = D // 100000000                        # 9 and 8 digits, each in unsigned 32 bits
    low = np.uint32(D - top * 100000000)         # (3× quicker than 64-bit signed division)
    top = np.uint32(top)
    ten = np.uint32(10)
    for j in range(8):
        q = low // ten
        dig[16 - j] = 48 + (low - q * ten)
        low = q
    for j in range(9):
        q = top // ten
        dig[8 - j] = 48 + (top - q * ten)
        top = q
    nsig = 17
    while nsig > 1 and dig[nsig - 1] == 48:
        nsig -= 1
    if -4 <= E < 17:
        if E >= 0:
            for j in range(E + 1):
                out[pos + j] = dig[j]
            pos += E + 1
            if nsig > E + 1:
                out[pos] = 46
                pos += 1
                for j in range(E + 1, nsig):
                    out[pos] = dig[j]
                    pos += 1
        else:
            out[pos] = 48
            out[pos + 1] = 46
            pos += 2
            for j in range(-E - 1):
                out[pos] = 48
                pos += 1
            for j in range(nsig):
                out[pos] = dig[j]
                pos += 1
        return pos
    out[pos] = dig[0]
    pos += 1
    if nsig > 1:
        out[pos] = 46
        pos += 1
        for j in range(1, nsig):
            out[pos] = dig[j]
            pos += 1
    out[pos] = 101
    out[pos + 1] = 45 if E < 0 else 43
    pos += 2
    ae = -E if E < 0 else E
    if ae >= 100:
        out[pos] = 48 + ae // 100
        pos += 1
    out[pos] = 48 + (ae // 10) % 10
    out[pos + 1] = 48 + ae % 10
    return pos + 2


def _rows(data, hi, lo, sc, out, put):
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


@lru_cache(maxsize=1)
def _compiled():
    """``_rows`` with ``_put`` compiled by numba (kept in numba's on-disk cache), or None
    without numba."""
    if importlib.util.find_spec("numba") is None:
        return None
    try:
        import numba
        put = numba.njit(cache=True, error_model="numpy")(_put)
        rows = numba.njit(cache=True, error_model="numpy")(_rows)
        return lambda data, hi, lo, sc, out: rows(data, hi, lo, sc, out, put)
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
    hi, lo, sc = _powers()
    out = np.empty(n * m * 25, np.uint8)
    used = kernel(data, hi, lo, sc, out)
    return out[:used].tobytes()


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
