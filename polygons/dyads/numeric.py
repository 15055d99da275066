"""A primitive's numbers read off its one statement: ``locate`` is ``source`` evaluated.

A primitive stated once — as ``source(g)``, its formula over the generated program's typed
names (:class:`polygons.codegen.Source`) — gets its numpy interpretation by running that
same statement through :class:`Numeric`, which gives every name its value at once:

* ``g.let(template, *operands)`` evaluates the template on the operands' values, in the
  names the generated program calls (:func:`namespace`: math over floats, numpy over
  arrays), so the value is the program's to the last bit;
* ``g.call(fn, ...)`` calls ``fn`` (its array twin over arrays, :data:`base.ARRAY_TWIN`);
* ``g.param(getter)`` reads the scene now; ``g.sigma(label)`` the closure chosen;
* ``g.pos`` / ``g.place`` hold points; ``g.margin`` keeps the margin (the caller tests it).

So the staged solve, the numpy sweep and the generated program evaluate the same formulas,
written once (:class:`Stated`).  Over one position every point is a plain float pair; over
a sweep the arrays of shape (N,) (or a scene number that is an array: a batch's varied
lengths, which makes the statement run again over arrays).
"""
from __future__ import annotations

import math

import numpy as np

from .base import ARRAY_TWIN


def where_scalar(c, a, b):
    """``where`` over floats (both branches evaluated, as numpy's)."""
    return a if c else b


def hypot_cols(x, y):
    """The kernel's norm over arrays: √(x² + y²)."""
    return np.sqrt(x * x + y * y)


def namespace(arrays: bool) -> dict:
    """The names generated code (and :class:`Numeric`) may call: cos, sin, atan2, degrees,
    sqrt, nan, where (math or numpy); ``hypot`` the kernel's norm (√(x² + y²) over arrays),
    ``hypot_p`` a dyad locate's np.hypot (math.hypot over floats)."""
    if arrays:
        return {"cos": np.cos, "sin": np.sin, "hypot": hypot_cols, "atan2": np.arctan2,
                "degrees": np.degrees, "where": np.where, "sqrt": np.sqrt, "nan": np.nan,
                "hypot_p": np.hypot}
    return {"cos": math.cos, "sin": math.sin, "hypot": math.hypot, "atan2": math.atan2,
            "degrees": math.degrees, "where": where_scalar, "sqrt": math.sqrt, "nan": math.nan,
            "hypot_p": math.hypot}


_NS = {False: namespace(False), True: namespace(True)}


class Formula:
    """A formula not yet evaluated (``g.e``): its text, one ``{}`` per value, in order (a
    formula nested in another keeps its text: what the program writes), and the values."""

    __slots__ = ("text", "values")

    def __init__(self, template: str, operands):
        parts, values = [], []
        for o in operands:
            if isinstance(o, Formula):
                parts.append(o.text)
                values.extend(o.values)
            elif type(o) is str:                # a number's text ('0.0')
                parts.append(o)
            else:
                parts.append("{}")
                values.append(o)
        self.text = template.format(*parts)
        self.values = values


_COMPILED: dict = {}


def _evaluate(f: Formula, arrays: bool):
    fn = _COMPILED.get((f.text, arrays))
    if fn is None:
        args = [f"_{i}" for i in range(len(f.values))]
        fn = eval(f"lambda {', '.join(args)}: {f.text.format(*args)}", dict(_NS[arrays]))
        _COMPILED[(f.text, arrays)] = fn
    return fn(*f.values)


class _OverArrays(Exception):
    """A scene number is an array (a batch's): the statement is run again over arrays."""


class Numeric:
    """The ``g`` of a primitive's ``source`` that computes: every name its value."""

    def __init__(self, scene, pos, sigma, x, arrays: bool):
        self.scene, self.x, self.arrays = scene, x, arrays
        self.sigma_of = sigma
        self.given = pos
        self.placed: dict = {}
        self.margins: list = []

    def param(self, getter):
        if isinstance(getter, tuple):           # ("sigma", label)
            return self.sigma(getter[1])
        v = getter(self.scene)
        if not self.arrays and np.ndim(v) > 0:
            raise _OverArrays
        return v

    def sigma(self, label: str):
        s = self.sigma_of
        return s[label] if isinstance(s, dict) else s

    def e(self, template: str, *operands) -> Formula:
        return Formula(template, operands)

    def let(self, expr, *operands):
        if type(expr) is str:
            expr = Formula(expr, operands)
        return _evaluate(expr, self.arrays) if isinstance(expr, Formula) else expr

    def call(self, fn, *args, n: int = 1) -> list:
        if self.arrays:
            fn = ARRAY_TWIN.get(fn, fn)
        vals = [float(a) if type(a) is str else self.let(a) for a in args]
        out = fn(*vals)
        return list(out) if n > 1 else [out[0] if isinstance(out, tuple) else out]

    def margin(self, m) -> None:
        self.margins.append(m)

    def pos(self, label: str):
        got = self.placed.get(label)
        if got is not None:
            return got
        p = self.given[label]
        return (p[0], p[1]) if self.arrays else (float(p[0]), float(p[1]))

    def place(self, label: str, x, y) -> None:
        self.placed[label] = (x, y)


def interpret(prim, scene, pos, sigma, x):
    """``prim.source`` evaluated at the positions ``pos`` (one position, or (2, N) arrays of a
    sweep), closure ``sigma``, input ``x``: (the points it places, its margin — None where
    it has none)."""
    arrays = np.ndim(x) > 0 or any(np.ndim(v) > 1 for v in pos.values())
    try:
        g = Numeric(scene, pos, sigma, x, arrays)
        m = prim.source(g)
    except _OverArrays:
        g = Numeric(scene, pos, sigma, x, True)
        m = prim.source(g)
    if g.arrays:
        pts = {k: np.array(np.broadcast_arrays(np.asarray(a, dtype=float),
                                               np.asarray(b, dtype=float)))
               for k, (a, b) in g.placed.items()}
    else:
        pts = {k: np.array([a, b], dtype=float) for k, (a, b) in g.placed.items()}
    return pts, m


class Stated:
    """A primitive stated once, as its ``source``: its ``locate`` is that statement
    evaluated (:func:`interpret`)."""

    def locate(self, scene, pos, sigma, x):
        return interpret(self, scene, pos, sigma, x)


__all__ = ["namespace", "where_scalar", "hypot_cols", "Formula", "Numeric", "interpret",
           "Stated"]
