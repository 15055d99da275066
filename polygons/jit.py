"""An optional machine-code backend: the generated straight-line code compiled by numba.

:mod:`polygons.codegen` writes one construction as Python source; over floats CPython runs it
at ~30 ns a statement and over arrays numpy makes a temporary of every statement.  When numba
is installed (it is not a dependency: ``pip install numba``, or the ``bench`` extra that
pylinkage brings it with) and asked for (``compile_scene(scene, jit=True)``,
``sweep(scene, ..., jit=True)``), the *same text* is compiled once more by numba:

* :func:`record_kernel` — one position: ``kernel(x, params) → record`` (a float64 array with
  the float program's record layout; the failure checks raise the same ``_Fail``);
* :func:`sweep_kernel` — a loop over the inputs around the code generated for arrays (no
  checks, margins kept): a :class:`SweepKernel`, whose ``record(xs, params)`` is what the
  numpy program returns (a row per varying output, the parameters and literals as scalars).

Both are made from the source text only (the statements are not re-derived), so they compute
the same expressions as the interpreters; ``tests/test_jit.py`` holds them equal to the
staged solve and the numpy sweep.  A construction numba cannot compile (a helper it does not
type, as the triad's root finder) gives ``None``: the caller keeps the Python program.
Compiling takes 0.2–5 s per topology (numba's time, once per process; kept with the code).

This module imports numba only inside :func:`available` and the kernel makers.
"""
from __future__ import annotations

import importlib.util
import math

import numpy as np

from .codegen import _Fail, _hypot_cols, _where
from .dyads.base import ARRAY_TWIN

#: no fast-math: the same IEEE operations as the Python program (flags tried gave no speed)
FAST = False
_SCALAR_OF = {arr: sc for sc, arr in ARRAY_TWIN.items()}


_MADE: dict = {}


def cached(code, make):
    """``make(code)`` once per generated code (kept while the code is: the code caches of
    :mod:`polygons.compiled` hold one per topology), or None where numba is not installed."""
    hit = _MADE.get((id(code), make))
    if hit is None or hit[0] is not code:
        if len(_MADE) >= 256:
            _MADE.clear()
        hit = _MADE[(id(code), make)] = (code, make(code) if available() else None)
    return hit[1]


def available() -> bool:
    """Whether numba can be imported (without importing it)."""
    return importlib.util.find_spec("numba") is not None


def _scalar_hypot(x, y):
    return math.sqrt(x * x + y * y)


def _namespace(code, numba) -> dict:
    """The generated code's names as numba-compiled scalar functions."""
    nj = numba.njit(cache=False)
    ns = {"math": math, "np": __import__("numpy"), "_Fail": _Fail, "nan": math.nan,
          "cos": math.cos, "sin": math.sin, "atan2": math.atan2, "degrees": math.degrees,
          "sqrt": math.sqrt, "hypot_p": math.hypot}
    for name, fn in code.namespace.items():
        if name.startswith("_f_"):
            ns[name] = nj(_SCALAR_OF.get(fn, fn))
        elif name.startswith("_g_"):    # a global of a placement written out in place
            ns[name] = fn
    ns["where"] = nj(_where)
    ns["hypot"] = nj(_scalar_hypot) if code.namespace.get("hypot") is _hypot_cols \
        else math.hypot
    return ns


def _parts(source: str):
    """(number of parameters, body lines, output expressions) of a ``_solve`` source."""
    lines = source.rstrip("\n").split("\n")
    head, unpack, body, ret = lines[0], lines[1], lines[2:-1], lines[-1].strip()
    assert head.startswith("def _solve(x, _k):") and ret.startswith("return (")
    params = [p.strip() for p in unpack.strip()[1:].split(")")[0].split(",") if p.strip()]
    outs = [o.strip() for o in ret[len("return ("):-1].split(",") if o.strip()]
    return params, [b.strip() for b in body], outs


def _compile(src: str, ns: dict, name: str, sig: str, numba, error_model: str):
    exec(compile(src, f"<polygons.jit {name}>", "exec"), ns)
    return numba.njit(sig, error_model=error_model, cache=False, fastmath=FAST)(ns[name])


def record_kernel(code):
    """``kernel(x, params) → record`` (float64 array) for the float program ``code``
    (:func:`polygons.codegen.generate` over floats), or None if numba cannot compile it."""
    try:
        import numba
        params, body, outs = _parts(code.source)
        src = ["def _rec(x, _k):"]
        src += [f"    {p} = _k[{i}]" for i, p in enumerate(params)]
        src += [f"    {b}" for b in body]
        src.append(f"    _o = np.empty({len(outs)})")
        src += [f"    _o[{i}] = {o}" for i, o in enumerate(outs)]
        src.append("    return _o")
        return _compile("\n".join(src) + "\n", _namespace(code, numba), "_rec",
                        "float64[::1](float64, float64[::1])", numba, "python")
    except Exception:           # noqa: BLE001 — numba's refusals are many kinds; keep Python
        return None


class SweepKernel:
    """A program for arrays compiled by numba: ``fn(xs, params) → (M, N)``, one row per output
    of the generated code that varies with the input; ``rows[i]`` is output ``i``'s row, or
    None for an output that is a parameter or a literal (``const[i]``: the parameter's index,
    or the number), which the numpy program also returns as a scalar."""

    __slots__ = ("fn", "rows", "const")

    def __init__(self, fn, rows, const):
        self.fn, self.rows, self.const = fn, rows, const

    @property
    def size(self) -> int:
        """Rows of the kernel's output (the outputs that vary)."""
        return max(sum(r is not None for r in self.rows), 1)

    def record(self, xs, params, out=None) -> list:
        """The numpy program's record at ``xs``: (N,) rows and scalars, and the array they are
        rows of (``out[:, :N]`` when given: a buffer reused pass after pass, else new)."""
        n = xs.shape[0]
        O = np.empty((self.size, n)) if out is None else out[:, :n]
        self.fn(xs, params, O)
        return [O[row] if row is not None else (float(params[c]) if type(c) is int else c)
                for row, c in zip(self.rows, self.const)], O


def sweep_kernel(code):
    """The :class:`SweepKernel` of the program generated for arrays ``code``
    (:func:`polygons.compiled.compile_arrays`), or None if numba cannot compile it."""
    try:
        import numba
        params, body, outs = _parts(code.source)
        rows, const, live = [], [], []
        for o in outs:
            if o in params:
                rows.append(None)
                const.append(params.index(o))
            elif not o.startswith("v"):
                rows.append(None)
                const.append(float(o))
            else:
                rows.append(len(live))
                const.append(None)
                live.append(o)
        src = ["def _many(xs, _k, _O):", "    _n = xs.shape[0]"]
        src += [f"    {p} = _k[{i}]" for i, p in enumerate(params)]
        src.append("    for _i in range(_n):")
        src.append("        x = xs[_i]")
        src += [f"        {b}" for b in body]
        src += [f"        _O[{i}, _i] = {o}" for i, o in enumerate(live)]
        fn = _compile("\n".join(src) + "\n", _namespace(code, numba), "_many",
                      "void(float64[::1], float64[::1], float64[:, :])", numba, "numpy")
        return SweepKernel(fn, tuple(rows), tuple(const))
    except Exception:           # noqa: BLE001
        return None
