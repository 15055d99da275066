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
written once (:class:`Stated`).  :func:`interpret` does not build the formulas at each call:
the first one writes the statement down as one Python function (:class:`Traced`: each
``let`` a line of the same text), kept per primitive and shared by equal ones, which later
calls run on the scene's numbers — :class:`Numeric`'s values to the last bit
(tests/test_primitives.py).  Over one position every point is a plain float pair; over
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


class Traced:
    """The ``g`` of a primitive's ``source`` that writes it down once: every name a variable
    of one Python function (:func:`_compile`), each ``let`` its formula's text — the same
    text :class:`Numeric` evaluates, so the function's numbers are :class:`Numeric`'s to the
    last bit, without building the formulas again at each call."""

    def __init__(self, scene, arrays: bool):
        self.scene, self.arrays, self.x = scene, arrays, "_x"
        self.getters: list = []
        self.labels: list = []
        self.sigmas: list = []
        self.fns: dict = {}
        self.lines: list = []
        self.placed: dict = {}
        self.margins: list = []

    def _var(self, text: str) -> str:
        name = f"_v{len(self.lines)}"
        self.lines.append(f"{name} = {text}")
        return name

    def param(self, getter):
        if isinstance(getter, tuple):
            return self.sigma(getter[1])
        self.getters.append(getter)
        return f"_k[{len(self.getters) - 1}]"

    def sigma(self, label: str):
        self.sigmas.append(label)
        return f"_s[{len(self.sigmas) - 1}]"

    def e(self, template: str, *operands) -> Formula:
        return Formula(template, operands)

    def let(self, expr, *operands):
        if type(expr) is str:
            expr = Formula(expr, operands)
        return self._var(expr.text) if isinstance(expr, Formula) else expr

    def call(self, fn, *args, n: int = 1) -> list:
        if self.arrays:
            fn = ARRAY_TWIN.get(fn, fn)
        name = self.fns.setdefault(fn, f"_f{len(self.fns)}")
        vals = [self.let(a) for a in args]
        out = self._var(f"{name}({', '.join(vals)})")
        if n > 1:
            return [self._var(f"{out}[{i}]") for i in range(n)]
        return [self._var(f"_first({out})")]

    def margin(self, m) -> None:
        self.margins.append(m)

    def pos(self, label: str):
        got = self.placed.get(label)
        if got is not None:
            return got
        self.labels.append(label)
        i = len(self.labels) - 1
        if self.arrays:
            return self._var(f"_p[{i}][0]"), self._var(f"_p[{i}][1]")
        return self._var(f"float(_p[{i}][0])"), self._var(f"float(_p[{i}][1])")

    def place(self, label: str, x, y) -> None:
        self.placed[label] = (x, y)


def _first(out):
    return out[0] if isinstance(out, tuple) else out


def _compile(prim, scene, arrays: bool):
    """``prim.source`` written down once as one function (per primitive, kind of numbers and
    :meth:`Stated.variant`), with the scene's getters, the labels it reads and its closures."""
    t = Traced(scene, arrays)
    m = prim.source(t)
    ns = {**_NS[arrays], "_first": _first, **{v: f for f, v in t.fns.items()}}
    out = ", ".join(f"{k!r}: ({x}, {y})" for k, (x, y) in t.placed.items())
    body = "\n".join(["def _stmt(_k, _p, _s, _x):", *(f"    {ln}" for ln in t.lines),
                      f"    return {{{out}}}, {m if m is not None else None}"])
    exec(body, ns)
    return ns["_stmt"], tuple(t.getters), tuple(t.labels), tuple(t.sigmas)


#: every statement compiled, by (primitive, (arrays, variant)): equal primitives share one
_STATEMENTS: dict = {}


def _statement(prim, scene, arrays: bool):
    """The compiled statement, kept on the primitive itself (a frozen value: its fields, and
    so its equality and hash, untouched; no hash of nested fields at each call)."""
    kept = prim.__dict__.get("_statements")
    if kept is None:
        kept = prim.__dict__.setdefault("_statements", {})
    key = (arrays, prim.variant(scene))
    got = kept.get(key)
    if got is None:                 # a new instance of an equal primitive (a new plan): shared
        got = _STATEMENTS.get((prim, key))
        if got is None:
            got = _STATEMENTS[(prim, key)] = _compile(prim, scene, arrays)
        kept[key] = got
    return got


def _ndim(v) -> int:
    return v.ndim if type(v) is np.ndarray else np.ndim(v)


def interpret(prim, scene, pos, sigma, x):
    """``prim.source`` evaluated at the positions ``pos`` (one position, or (2, N) arrays of a
    sweep), closure ``sigma``, input ``x``: (the points it places, its margin — None where
    it has none).  The statement is written down once per primitive (:func:`_statement`);
    each call reads the scene's numbers and runs it."""
    arrays = type(x) is not float and np.ndim(x) > 0
    fn, getters, labels, sigmas = _statement(prim, scene, arrays)
    p = [pos[lab] for lab in labels]
    k = [get(scene) for get in getters]
    if not arrays and (any(_ndim(v) > 1 for v in p)                    # a sweep's positions
                       or any(type(v) is not float and np.ndim(v) > 0 for v in k)):  # a batch's
        arrays = True
        fn, getters, labels, sigmas = _statement(prim, scene, True)
        p = [pos[lab] for lab in labels]
        k = [get(scene) for get in getters]
    s = [sigma[lab] for lab in sigmas] if isinstance(sigma, dict) else [sigma] * len(sigmas)
    placed, m = fn(k, p, s, x)
    if arrays:
        pts = {k_: np.array(np.broadcast_arrays(np.asarray(a, dtype=float),
                                                np.asarray(b, dtype=float)))
               for k_, (a, b) in placed.items()}
        if m is not None and np.ndim(m) == 0 and pts:    # a margin of the scene's numbers
            m = np.full(next(iter(pts.values())).shape[1:], float(m))    # alone: one a position
    else:
        pts = {k_: np.array([a, b], dtype=float) for k_, (a, b) in placed.items()}
    return pts, m


def interpret_floats(prim, scene, pos, sigma, x):
    """:func:`interpret` at one position given as plain float pairs (``pos``: label → (x, y)),
    returning the points it places as float pairs (no arrays made): (points, margin), or None
    where :func:`interpret` would run over arrays (a scene number or the input an array, as in
    a batch).  The same statement, so the same numbers to the last bit."""
    if type(x) is not float:
        return None
    fn, getters, labels, sigmas = _statement(prim, scene, False)
    k = [get(scene) for get in getters]
    for v in k:
        if type(v) is not float:
            return None
    s = [sigma[lab] for lab in sigmas] if isinstance(sigma, dict) else [sigma] * len(sigmas)
    return fn(k, [pos[lab] for lab in labels], s, x)


class Stated:
    """A primitive stated once, as its ``source``: its ``locate`` is that statement
    evaluated (:func:`interpret`)."""

    def locate(self, scene, pos, sigma, x):
        return interpret(self, scene, pos, sigma, x)

    def variant(self, scene) -> tuple:
        """What of the scene changes the statement's shape (a branch of ``source`` on the
        scene): none."""
        return ()


__all__ = ["namespace", "where_scalar", "hypot_cols", "Formula", "Numeric", "Traced", "interpret",
           "interpret_floats", "Stated"]
