"""``'%.17g' % x`` as bytes, one value: the formatter of :mod:`polygons.csv_text` (its module
docstring says how), plain Python that :mod:`polygons.csv_jit` compiles with numba."""
from __future__ import annotations

import math

import numpy as np

_K_LO, _K_HI = -345, 300            # k = decimal exponent − 16 over the whole float64 range
_E16, _E17 = 10000000000000000, 100000000000000000


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
