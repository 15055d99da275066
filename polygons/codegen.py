"""The step program written out as straight-line Python source: every interpreter runs it.

Every dyad's placement comes from its module's :meth:`source`; every construction step from
its op's generator in :class:`_Steps` — the one implementation of each
:class:`~polygons.steps.Op`, the theorem of :mod:`polygons.theorems` written term for term
over named locals.  :func:`generate` turns a plan into one function ``_solve(x, params)``
returning a flat record of floats, with the layout that says where each step's numbers are
in it.  The interpreters are flavours of the same text:

* over floats, the 2×2 line intersection inline (the compiled evaluator, :mod:`polygons.compiled`);
* over floats, the intersections by a ``meet`` function (the staged solver:
  :mod:`polygons.evaluate` passes shapely's, :func:`polygons.geometry.meet`);
* over (N,) arrays, no checks, dyad margins kept (sweeps and batches,
  :func:`polygons.compiled.compile_arrays`), or on points given as parameters (a batch's
  located engine, :func:`polygons.compiled.compile_given`);
* over arrays with every vector, direction and mark drawn by noisy instruments (the
  drawing-board emulation, :mod:`polygons.drawing_board`).

This module imports neither shapely nor the diagrams.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from .codegen_lean import _INLINE, Perp as _Perp, fold as _fold, inline
from .dyads.base import ARRAY_TWIN
from .dyads.numeric import hypot_cols, namespace, where_scalar
from .errors import UnsupportedError
from .plan import Plan
from .program import Expr, Line, Lit, Name, live
from .scene import Crank, Scene
from .steps import Diagram, Op, Step, Vertices

#: the staged solver's thresholds (polygons.geometry; a test keeps them equal)
PARALLEL_DEG = 1e-5
WARN_DEG = 1.0

#: the answers-only program's test of two lines u, v (of any length) meeting:
#: (u × v)² > LEAN_TAN² (u · v)², i.e. an angle above PARALLEL_DEG by a relative 1e-9 — stricter
#: than the full program's test by more than its rounding, so that where the lean program
#: passes the full one does too; where it fails, the full program is run (its error, or its
#: numbers: :meth:`polygons.compiled.Program.solve`).  A zero direction fails it too.
LEAN_TAN = math.tan(math.radians(PARALLEL_DEG)) * (1.0 + 1e-9)

#: what an answers-only program may compute (``compile_scene(scene, outputs=...)``): every
#: placed point's position, velocity and acceleration, every link's ω and α, every slide's
#: sliding velocity and acceleration
ANSWERS = ("pos", "velocity", "acceleration", "omega", "alpha", "slide_v", "slide_a")

V, A = Diagram.VELOCITY, Diagram.ACCELERATION
_FIELDS = ("at", "vector", "point", "direction")


_where, _hypot_cols = where_scalar, hypot_cols     # (the names jit reads)

class _Fail(Exception):
    """Raised by generated code: ``args[0]`` indexes the program's failure table."""


E = Expr


# ---------------------------------------------------------------- code generation
class Source:
    """What a dyad's ``source(g)`` and the op generators write with: fresh local names,
    scene parameters, placed positions, checks.  (The ``g`` of :meth:`Dyad.source`.)"""

    x = Name("x")   # the driver's input (θ in rad or s in m)

    # Names the generated code may call: polygons.dyads.numeric.namespace (the same names a
    # primitive's statement is evaluated in, so its locate is the program's to the last bit).

    def __init__(self, scene: Scene, sigma: dict, arrays: bool = False, meet=None,
                 instruments=None, lean: bool = False):
        self.scene = scene
        self.lean = lean               # answers only: raw directions, the 2×2 solve (LEAN)
        self.arrays = arrays           # the same code over (N,) arrays: no checks, margins kept
        self.meet = meet               # the intersection of two lines, or None: inline 2×2
        self.instruments = instruments  # the drawing board's noisy strokes, or None: exact
        self.margins: list[str] = []
        self.margin_of: list = []      # the dyad of each margin
        self.crossings: list = []      # (u × v, u · v, step) of every intersection
        self.lines: list[Line] = []     # the statements, typed (polygons.program)
        self.getters: list = []        # scene -> float, one per parameter k<i>
        self.namespace: dict = dict(namespace(arrays), _Fail=_Fail)
        self.fails: list = []          # ("dyad", dyad) | ("step", step, reason)
        self.placed: dict[str, tuple[str, str]] = {}
        self.sigma_of = sigma
        self.dyad = None
        self._n = 0
        self._memo: dict[str, str] = {}
        self._checked: set[str] = set()
        self.untyped: list[str] = []   # formulas given as bare text (see let)

    # -- used by the dyad modules ----------------------------------------------------------
    def param(self, getter) -> str:
        """A scene number as a parameter of the compiled function: ``getter(scene)`` (or
        ("sigma", label) for a closure) is read per scene, so the code serves a topology."""
        self.getters.append(getter)
        return Name(f"k{len(self.getters) - 1}")

    def sigma(self, label: str) -> str:
        return self.param(("sigma", label))

    def e(self, template: str, *operands) -> Expr:
        """A formula over names: ``template`` with one ``{}`` per operand (Names from
        :meth:`let`, :meth:`param`, :meth:`pos`; Exprs; numbers), what it reads typed."""
        return Expr(template, *operands)

    def let(self, expr: Expr | Name | str, *operands) -> Name:
        """``expr`` in a fresh local (or the local that already holds it: every local is
        assigned once, so equal text is an equal value); a template and its operands make
        the formula (:meth:`e`): ``g.let("{} - {}", qx, px)``."""
        if type(expr) is str and not operands:
            # text whose names are not typed (an f-string: the way before typed formulas):
            # taken as reading every name made so far, so no statement it needs is dropped;
            # counted (``untyped``) — tests/test_program.py holds the shipped groups at none
            self.untyped.append(expr)
            reads = frozenset(Name(f"v{i}") for i in range(1, self._n + 1)) | frozenset(
                Name(f"k{i}") for i in range(len(self.getters)))
            expr = Expr("{}", Lit(expr))
            expr.reads = reads
        elif type(expr) is str:
            expr = Expr(expr, *operands)
        elif not isinstance(expr, (Expr, Name)) or operands:
            raise TypeError(f"let takes a typed formula (Source.e), not {expr!r}")
        text = str(expr)
        name = self._memo.get(text)
        if name is not None:
            return name
        self._n += 1
        name = Name(f"v{self._n}")
        self.lines.append(Line((name,), f"{name} = {text}", expr.reads))
        self._memo[text] = name
        return name

    def call(self, fn, *args, n: int = 1) -> list[Name]:
        if self.arrays:
            fn = ARRAY_TWIN.get(fn, fn)
        elif self.lean and fn in _INLINE:
            return self.inline(fn, args, n)
        fname = f"_f_{fn.__name__}"
        self.namespace[fname] = fn
        names = [Name(f"v{self._n + i + 1}") for i in range(n)]
        self._n += n
        args = Expr(", ".join("{}" for _ in args), *args)
        self.lines.append(Line(tuple(names), f"{', '.join(names)} = {fname}({args})",
                               args.reads))
        return names

    def inline(self, fn, args, n: int) -> list[Name]:
        """``fn(*args)`` written out in place (:func:`polygons.codegen_lean.inline`)."""
        return inline(self, fn, args, n)

    def margin(self, m: str) -> None:
        """Fail where the dyad cannot close (the staged assembly's test: a two-closure dyad
        needs a margin ≥ 0, any other > 0)."""
        if self.arrays:                 # over arrays: NaN where it cannot close, and the
            self.margins.append(m)      # margin kept (the sweep's conditioning)
            self.margin_of.append(self.dyad)
            return
        test = ">= 0.0" if self.dyad.two_closures else "> 0.0"
        self.fail_unless(E("{} " + test, m), ("dyad", self.dyad))

    def pos(self, label: str) -> tuple[str, str]:
        """The local names of a placed point's coordinates."""
        return self.placed[label]

    def place(self, label: str, x: str, y: str) -> None:
        self.placed[label] = (x, y)

    # -- used by the op generators ---------------------------------------------------------
    def fail_unless(self, cond: Expr, why) -> None:
        # over arrays there are no checks; a test already made on the same locals has passed
        if self.arrays or cond.text in self._checked:
            return
        self._checked.add(cond.text)
        self.fails.append(why)
        self.lines.append(Line((), f"if not ({cond}): raise _Fail({len(self.fails) - 1})",
                               cond.reads))

    def vec(self, ex: Expr, ey: Expr) -> tuple[Name, Name]:
        return self.let(ex), self.let(ey)


@dataclass
class _Out:
    """Where one step's numbers are in the flat record (indices), and its units/symbols."""
    fields: dict
    value: int | None
    angle: int | None
    unit: str
    terms: tuple           # ((symbol, index, unit), ...)


class _Steps:
    """The op generators: one per :class:`Op` (the only code that says what an op means).

    Each writes its theorem over plane vectors held as pairs of local names: (v_B)_A = ω × AB
    (``rel_vel``), (a_B)_A^n = −ω² AB (``centripetal``), a_cor = 2 ω × v (the Coriolis ops),
    ω or α = (AB × ab) / AB² (``ang``), a line through a vertex along a unit direction, and
    the intersection of two lines (P + t u = Q + s v, the 2×2 solve or ``meet``)."""

    def __init__(self, g: Source, scene: Scene, names: Vertices, omega: dict, alpha: dict):
        self.g, self.scene, self.names = g, scene, names
        zero = ("0.0", "0.0")
        self.vx = {V: {names.pole: zero}, A: {names.pole: zero}}
        self.omega, self.alpha = omega, alpha
        self.lines: dict = {}
        self.slide_v: dict = {}
        self.slide_a: dict = {}
        self.cor: dict = {}

    # vector helpers over pairs of local names
    def r(self, p, x):
        (px, py), (xx, xy) = self.g.pos(p), self.g.pos(x)
        return self.g.vec(E("{} - {}", xx, px), E("{} - {}", xy, py))

    def of(self, d, label):
        return self.vx[d][self.names.of(label)]

    def held(self, e):
        """``e`` in a local (a name or a literal as it is)."""
        return e if isinstance(e, (Name, Lit)) or type(e) is str else self.g.let(e)

    def norm(self, v):
        return self.g.let("hypot({}, {})", v[0], v[1])

    def sub(self, a, b):
        if b == ("0.0", "0.0"):
            return a
        if self.g.lean and a == ("0.0", "0.0"):
            return self.g.vec(E("-{}", b[0]), E("-{}", b[1]))
        return self.g.vec(E("{} - {}", a[0], b[0]), E("{} - {}", a[1], b[1]))

    def cross(self, a, b):
        return self.g.let("{} * {} - {} * {}", a[0], b[1], a[1], b[0])

    def dot(self, a, b):
        return self.g.let("{} * {} + {} * {}", a[0], b[0], a[1], b[1])

    def slider_e(self, X, attr="direction"):
        """The unit vector of the fixed guide of ``X`` (``attr`` 'slot_direction': of the slot
        its yoke carries), read off the mechanism model."""
        g = self.g
        if attr == "direction":
            return (g.param(lambda s: s.model.guide[X].line.direction[0]),
                    g.param(lambda s: s.model.guide[X].line.direction[1]))
        pin = next(p.at for p in self.scene.model.yoke_slots() if p.carrier == X)
        return (g.param(lambda s: s.model.slide_of(f"block {pin}").line.direction[0]),
                g.param(lambda s: s.model.slide_of(f"block {pin}").line.direction[1]))

    def slide_key(self, args) -> str:
        """Where a slide's numbers are kept (the key of ``Solution.slides`` and of a sweep's
        ``slide_v``): the pin (args (A,)), or 'A in LEVER' for a pin in two slots (args
        (A, A1), A1 the lever's point under the pin)."""
        if len(args) == 1:
            return args[0]
        return f"{args[0]} in {self.scene.model.under[args[1]].carrier}"

    def slot_e(self, A_, under=None):
        """The unit vector along the slot of pin ``A_`` (the model's slide line: pivot → far
        end for an offset slot or a lever placed before its pin, else pivot → pin); and the
        slot's sliding pair.  ``under`` (the lever's point under the pin) names the slot of a
        pin in two slots."""
        model = self.scene.model
        slot = model.slot[A_] if under is None else model.under[under]
        return self.unit(self.r(slot.line.origin, slot.line.toward)), slot

    def unit(self, r):
        """r / |r|."""
        n = self.norm(r)
        return self.g.vec(E("{} / {}", r[0], n), E("{} / {}", r[1], n))

    def rel_vel(self, w, r):
        return self.g.vec(E("{} * -{}", w, r[1]), E("{} * {}", w, r[0]))

    def centripetal(self, w, r):
        w2 = self.g.let("-({} * {})", w, w)
        return self.g.vec(E("{} * {}", w2, r[0]), E("{} * {}", w2, r[1]))

    def ang(self, r, rel):
        """cross(r, rel) / dot(r, r): ω or α from a relative vector."""
        return self.g.let("({} * {} - {} * {}) / ({} * {} + {} * {})",
                            r[0], rel[1], r[1], rel[0], r[0], r[0], r[1], r[1])

    def drawn(self, s, stroke: str, xy):
        """``xy`` as the drawing board's instrument draws it (``stroke``: 'vector' set off
        with rule and protractor, 'direction' with the set square, 'mark' with the pencil:
        ``instruments.<stroke>(diagram, x, y) → (x, y)``); as it is in an exact construction."""
        inst = self.g.instruments
        if inst is None:
            return xy
        return tuple(self.g.call(getattr(inst, stroke), Lit(repr(str(s.diagram))), *xy, n=2))

    def vector(self, s, vec, unit, terms):
        vec = self.drawn(s, "vector", vec)
        start = self.vx[s.diagram][s.start]
        if self.g.lean and start == ("0.0", "0.0"):
            end = (self.held(vec[0]), self.held(vec[1]))
        else:
            end = self.g.vec(E("{} + {}", start[0], vec[0]), E("{} + {}", start[1], vec[1]))
        self.vx[s.diagram][s.end] = end
        return dict(at=start, vector=vec, point=end), None, None, unit, terms

    def line(self, s, d, anchor):
        g = self.g
        if g.lean:      # the direction as it comes (LEAN): its length cancels in the 2×2 solve
            d = (self.held(d[0]), self.held(d[1]))
            self.lines[(s.diagram, s.number)] = (anchor, d)
            return anchor, d
        d = self.drawn(s, "direction", d)
        n = self.norm(d)
        g.fail_unless(E("{} != 0.0 and {} == {}", n, n, n), ("step", s, "zero"))
        u = g.vec(E("{} / {}", d[0], n), E("{} / {}", d[1], n))
        self.lines[(s.diagram, s.number)] = (anchor, u)
        return anchor, u

    def line_result(self, s, ln):
        return dict(at=ln[0], direction=ln[1]), None, None, "", ()

    # the ops
    def crank_velocity(self, s):
        L, P, X = s.args
        w = self.omega[L]
        r = self.r(P, X)
        vec = self.rel_vel(w, r)
        return self.vector(s, vec, "m/s", ((f"ω_{L}", ("abs", w), "rad/s"),
                                           (f"{P}{X}", ("hypot", r), "m"),
                                           (s.quantity, ("hypot", vec), "m/s")))

    def slider_drive(self, s):
        (X,) = s.args
        e = self.slider_e(X)
        vel = s.diagram == V
        val = self.g.param((lambda sc: sc.driver.velocity) if vel
                           else (lambda sc: sc.driver.acceleration))
        unit = _unit_of(s.diagram)
        vec = self.g.vec(E("{} * {}", val, e[0]), E("{} * {}", val, e[1]))
        return self.vector(s, vec, unit, ((s.quantity, val, unit),))

    def centripetal_op(self, s):
        L, P, X = s.args
        w = self.omega[L]
        r = self.r(P, X)
        vec = self.centripetal(w, r)
        return self.vector(s, vec, "m/s^2", ((f"ω_{L}", ("abs", w), "rad/s"),
                                             (f"{P}{X}", ("hypot", r), "m"),
                                             (s.quantity, ("hypot", vec), "m/s^2")))

    def crank_tangential(self, s):
        L, P, X = s.args
        al = self.alpha[L]
        r = self.r(P, X)
        vec = self.rel_vel(al, r)
        return self.vector(s, vec, "m/s^2", ((f"α_{L}", ("abs", al), "rad/s^2"),
                                             (f"{P}{X}", ("hypot", r), "m"),
                                             (s.quantity, ("hypot", vec), "m/s^2")))

    def line_perp(self, s):
        P, X = s.args
        r = self.r(P, X)
        if self.g.lean:     # kept as ⟂ r: the 2×2 solve reads r itself (intersect)
            self.lines[(s.diagram, s.number)] = (self.vx[s.diagram][s.start], _Perp(r))
            return {}, None, None, "", ()
        return self.line_result(s, self.line(s, (E("-{}", r[1]), r[0]),
                                             self.vx[s.diagram][s.start]))

    def line_along(self, s):
        P, X = s.args
        return self.line_result(s, self.line(s, self.r(P, X), self.vx[s.diagram][s.start]))

    def line_guide(self, s):
        (X,) = s.args
        return self.line_result(s, self.line(s, self.slider_e(X), self.vx[s.diagram][s.start]))

    def line_slot(self, s):
        (X,) = s.args
        return self.line_result(s, self.line(s, self.slider_e(X, "slot_direction"),
                                             self.vx[s.diagram][s.start]))

    def coriolis_offset_line(self, s):
        (A_,) = s.args
        g = self.g
        e, slot = self.slot_e(A_)
        w = self.omega[slot.carrier]
        v_s = self.slide_v[A_]
        ve = g.vec(E("{} * {}", v_s, e[0]), E("{} * {}", v_s, e[1]))
        w2 = g.let("2.0 * {}", w)
        a_cor = g.vec(E("{} * -{}", w2, ve[1]), E("{} * {}", w2, ve[0]))
        self.cor[A_] = a_cor
        anchor = self.sub(self.of(s.diagram, A_), self.drawn(s, "vector", a_cor))
        ln = self.line(s, e, anchor)
        neg = g.vec(E("-{}", a_cor[0]), E("-{}", a_cor[1]))
        return dict(at=ln[0], vector=neg, direction=ln[1]), None, None, "m/s^2", (
            (f"ω_{slot.carrier}", ("abs", w), "rad/s"),
            (f"(v_{A_})_{slot.coincident}", ("abs", v_s), "m/s"),
            ("2ωv", ("hypot", a_cor), "m/s^2"))

    def coriolis_op(self, s):
        """2 ω × ṡ e: the offset line's when it computed it, else computed here (a pin found
        in a lever's slot; a prescribed slide, ṡ given, along its link)."""
        A_, key = s.args[0], self.slide_key(s.args)
        g = self.g
        if key in self.cor:
            a_cor = self.cor[key]
            return self.vector(s, a_cor, "m/s^2", (("2ωv", ("hypot", a_cor), "m/s^2"),))
        sl = self.scene.model.collar.get(A_)
        if sl is not None:
            e = self.unit(self.r(sl.line.origin, sl.line.toward))
            L, v_s = sl.carrier, g.param(lambda sc: sc.prescribed[A_].velocity)
        else:
            e, slot = self.slot_e(*s.args)
            L, v_s = slot.carrier, self.slide_v[key]
        w = self.omega[L]
        ve = g.vec(E("{} * {}", v_s, e[0]), E("{} * {}", v_s, e[1]))
        w2 = g.let("2.0 * {}", w)
        a_cor = self.cor[key] = g.vec(E("{} * -{}", w2, ve[1]), E("{} * {}", w2, ve[0]))
        return self.vector(s, a_cor, "m/s^2", ((f"ω_{L}", ("abs", w), "rad/s"),
                                               (f"ṡ_{A_}", ("abs", v_s), "m/s"),
                                               ("2ωv", ("hypot", a_cor), "m/s^2")))

    def line_slide(self, s):
        e, _ = self.slot_e(*s.args)
        return self.line_result(s, self.line(s, e, self.vx[s.diagram][s.start]))

    def slide_drive(self, s):
        """A prescribed sliding velocity ṡ e or acceleration s̈ e along the link PQ."""
        C, P, Q = s.args
        g = self.g
        e = self.unit(self.r(P, Q))
        if s.diagram == V:
            val = self.slide_v[C] = g.param(lambda sc: sc.prescribed[C].velocity)
        else:
            val = self.slide_a[C] = g.param(lambda sc: sc.prescribed[C].acceleration)
        unit = _unit_of(s.diagram)
        vec = g.vec(E("{} * {}", val, e[0]), E("{} * {}", val, e[1]))
        return self.vector(s, vec, unit, ((s.quantity, val, unit),))

    def join(self, s):
        vx = self.vx[s.diagram]
        vec = self.sub(vx[s.end], vx[s.start])
        return dict(at=vx[s.start], vector=vec, point=vx[s.end]), None, None, "m/s^2", (
            (f"{s.start}{s.end}", ("hypot", vec), "m/s^2"),)

    def intersect(self, s):
        g = self.g
        (p, u), (q, v) = (self.lines[(s.diagram, n)] for n in s.lines)
        if g.lean and type(u) is _Perp and type(v) is _Perp:
            return self.intersect_perp(s, p, u.r, q, v.r)
        if g.lean:
            u, v = (self.unperp(d) for d in (u, v))
        den = self.cross(u, v)
        dot = self.dot(u, v)
        if g.lean:      # P + t u = Q + s v, u and v of any length: t = ((Q − P) × v)/(u × v)
            g.fail_unless(E("{} * {} > {} * ({} * {})", den, den, Lit(repr(LEAN_TAN ** 2)),
                            dot, dot), ("lean", s))
            w = self.sub(q, p)
            t = g.let("({} * {} - {} * {}) / {}", w[0], v[1], w[1], v[0], den)
            if p == ("0.0", "0.0"):
                pt = g.vec(E("{} * {}", t, u[0]), E("{} * {}", t, u[1]))
            else:
                pt = g.vec(E("{} + {} * {}", p[0], t, u[0]), E("{} + {} * {}", p[1], t, u[1]))
            self.vx[s.diagram][s.end] = pt
            return dict(point=pt), None, None, _unit_of(s.diagram), ()
        angle = g.let("degrees(atan2(abs({}), abs({})))", den, dot)
        g.crossings.append((den, dot, s))
        g.fail_unless(E("{} >= {}", angle, PARALLEL_DEG), ("step", s, "parallel"))
        if g.meet is not None:        # the staged solver: drawn and intersected by shapely
            pt = tuple(g.call(g.meet, *p, *u, *q, *v, n=2))
            g.fail_unless(E("{} == {}", pt[0], pt[0]), ("step", s, "meet"))
        else:
            w = self.sub(q, p)
            t = g.let("({} * {} - {} * {}) / {}", w[0], v[1], w[1], v[0], den)
            pt = g.vec(E("{} + {} * {}", p[0], t, u[0]), E("{} + {} * {}", p[1], t, u[1]))
        pt = self.drawn(s, "mark", pt)
        self.vx[s.diagram][s.end] = pt
        unit = _unit_of(s.diagram)
        return dict(point=pt), None, angle, unit, (
            ("angle", angle, "deg"),
            # from the fixed pivot the resultant is read about, as the book names it (dc
            # about D where the pole is a = d), else from the pole
            (f"{self.names.named(s.args[0]) if s.args else self.names.pole}{s.end}",
             ("hypot", pt), unit))

    def unperp(self, d):
        """A direction kept as ⟂ r (:class:`_Perp`) as its components (−r_y, r_x)."""
        return (self.held(E("-{}", d.r[1])), d.r[0]) if type(d) is _Perp else d

    def intersect_perp(self, s, p, a, q, b):
        """The 2×2 solve of the lines P + t ⟂a and Q + s ⟂b (⟂r = (−r_y, r_x)), written on a
        and b: ⟂a × ⟂b = a × b, (Q − P) × ⟂b = (Q − P)·b, so t = ((Q − P)·b)/(a × b) and the
        point is P + t ⟂a; the same test as :meth:`intersect`'s ((⟂a · ⟂b) = a·b)."""
        g = self.g
        den, dot = self.cross(a, b), self.dot(a, b)
        g.fail_unless(E("{} * {} > {} * ({} * {})", den, den, Lit(repr(LEAN_TAN ** 2)),
                        dot, dot), ("lean", s))
        if q == ("0.0", "0.0"):         # Q the pole: (Q − P)·b = −(P·b)
            t = g.let("-({} * {} + {} * {}) / {}", p[0], b[0], p[1], b[1], den)
        else:
            w = self.sub(q, p)
            t = g.let("({} * {} + {} * {}) / {}", w[0], b[0], w[1], b[1], den)
        if p == ("0.0", "0.0"):
            pt = g.vec(E("-({} * {})", t, a[1]), E("{} * {}", t, a[0]))
        else:
            pt = g.vec(E("{} - {} * {}", p[0], t, a[1]), E("{} + {} * {}", p[1], t, a[0]))
        self.vx[s.diagram][s.end] = pt
        return dict(point=pt), None, None, _unit_of(s.diagram), ()

    def omega_op(self, s):
        L, P, Q = s.args
        r = self.r(P, Q)
        rel = self.sub(self.of(s.diagram, Q), self.of(s.diagram, P))
        w = self.ang(r, rel)
        self.omega[L] = w
        return {}, w, None, "rad/s", (
            (s.reads or f"{self.names.of(P)}{self.names.of(Q)}", ("hypot", rel), "m/s"),
            (f"{P}{Q}", ("hypot", r), "m"), (f"ω_{L}", w, "rad/s"))

    def alpha_op(self, s):
        L, P, X = s.args
        r = self.r(P, X)
        rel = self.sub(self.of(s.diagram, X), self.of(s.diagram, P))
        al = self.ang(r, rel)
        self.alpha[L] = al
        return {}, al, None, "rad/s^2", (
            (s.reads or f"(a_{X})_{P}^t", ("tangential", r, rel), "m/s^2"),
            (f"{P}{X}", ("hypot", r), "m"),
            (f"α_{L}", al, "rad/s^2"))

    def slider_value(self, s):
        (X,) = s.args
        val = self.dot(self.of(s.diagram, X), self.slider_e(X))
        unit = _unit_of(s.diagram)
        return {}, val, None, unit, ((s.quantity, val, unit),)

    def slide_value(self, s):
        A_, key = s.args[0], self.slide_key(s.args)
        e, slot = self.slot_e(*s.args)
        rel = self.sub(self.of(s.diagram, A_), self.of(s.diagram, slot.coincident))
        if s.diagram == V:
            val = self.dot(rel, e)
            self.slide_v[key] = val
        else:
            val = self.dot(self.sub(rel, self.cor[key]), e)
            self.slide_a[key] = val
        unit = _unit_of(s.diagram)
        return {}, val, None, unit, ((s.quantity, val, unit),)

    def image(self, s):
        L, P, Q, X = s.args
        if L not in self.omega:
            self.omega[L] = self.ang(self.r(P, Q), self.sub(self.of(V, Q), self.of(V, P)))
        r = self.r(P, X)
        if s.diagram == V:
            vec = self.rel_vel(self.omega[L], r)
        else:
            if L not in self.alpha:
                self.alpha[L] = self.ang(self.r(P, Q), self.sub(self.of(A, Q), self.of(A, P)))
            t = self.rel_vel(self.alpha[L], r)
            c = self.centripetal(self.omega[L], r)
            vec = self.g.vec(E("{} + {}", t[0], c[0]), E("{} + {}", t[1], c[1]))
        unit = _unit_of(s.diagram)
        return self.vector(s, vec, unit, ((f"{s.start}{s.end}", ("hypot", vec), unit),))

    def roll_rate(self, s):
        """A wheel rolling on a fixed line turns at ω = −(v_W · e)/r, α = −(a_W · e)/r (its
        centre W moves along the equivalent guide ∥ the surface, e; the contact at rest)."""
        L, W = s.args
        e = self.slider_e(W)
        from .contacts import wheel_of          # (a rolling wheel only: a quicker start)
        r = self.g.param(lambda sc: wheel_of(sc, W).radius)
        along = self.dot(self.of(s.diagram, W), e)
        val = self.g.let("-{} / {}", along, r)
        vel = s.diagram == V
        (self.omega if vel else self.alpha)[L] = val
        unit, rate = ("m/s", "rad/s") if vel else ("m/s^2", "rad/s^2")
        return {}, val, None, rate, ((s.reads or f"{self.names.pole}{self.names.of(W)}",
                                      ("abs", along), unit),
                                     (f"r_{L}", r, "m"), (s.quantity, val, rate))

    OPS = {
        Op.ROLL_OMEGA: roll_rate, Op.ROLL_ALPHA: roll_rate,
        Op.CRANK_VELOCITY: crank_velocity, Op.SLIDER_DRIVE: slider_drive,
        Op.CENTRIPETAL: centripetal_op, Op.CRANK_TANGENTIAL: crank_tangential,
        Op.LINE_PERP: line_perp, Op.LINE_ALONG: line_along, Op.LINE_GUIDE: line_guide,
        Op.LINE_SLOT: line_slot, Op.LINE_SLIDE: line_slide, Op.SLIDE_DRIVE: slide_drive,
        Op.CORIOLIS_OFFSET_LINE: coriolis_offset_line,
        Op.CORIOLIS: coriolis_op, Op.JOIN: join, Op.INTERSECT: intersect, Op.OMEGA: omega_op,
        Op.ALPHA: alpha_op, Op.SLIDER_VELOCITY: slider_value,
        Op.SLIDER_ACCELERATION: slider_value, Op.SLIDE_VELOCITY: slide_value,
        Op.SLIDE_ACCELERATION: slide_value, Op.IMAGE: image,
    }


def _unit_of(diagram) -> str:
    return "m/s" if diagram == Diagram.VELOCITY else "m/s^2"



@dataclass(frozen=True)
class _Code:
    """The compiled function of one topology and where its numbers go."""
    fn: object
    getters: tuple
    layout: tuple           # one _Out per step
    index: dict             # ('pos'|'velocity'|'acceleration'|'omega'|'alpha'|..., key) -> idx
    fails: tuple
    source: str
    namespace: dict = field(default=None, compare=False, repr=False)  # the names it calls
    #: an answers-only program's: ``derive(params)`` → the parameters' own combinations its
    #: function reads after the parameters (``c0``, ``c1`` …; :func:`_fold`), or None
    derive: object = field(default=None, compare=False, repr=False)




class NotCompiled(UnsupportedError):
    """The compiled evaluator does not cover this scene (the staged solver and the kernel do):
    its message names what is missing."""


def check_compilable(scene: Scene, plan: Plan, steps: tuple[Step, ...]) -> None:
    """Refuse, naming it, what the generated code does not model yet: a dyad without a
    ``source``, a step op without its generator (every shipped dyad and op has one now; this
    stays the guard for a new kind added to the kernel before its generator)."""
    for d in plan.dyads:
        if not callable(getattr(d, "source", None)):
            raise NotCompiled(f"the compiled evaluator does not generate the "
                              f"{type(d).__name__} dyad at {', '.join(d.placed)} yet",
                              file=scene.file)
    for s in steps:
        if s.op not in _Steps.OPS:
            raise NotCompiled(f"the compiled evaluator has no code for the step op "
                              f"{str(s.op)!r} yet", file=scene.file)


def _code_name(text: str) -> str:
    """The scene's title as the generated code's file name: printable characters only (a NUL
    is refused by ``compile``), at most 80 of them."""
    text = "".join(c if c.isprintable() else "?" for c in str(text)[:80])
    return text if text else "scene"


def generate(scene: Scene, plan: Plan, steps: tuple[Step, ...], sigma: dict,
             arrays: bool = False, meet=None, instruments=None, positions: bool = False,
             outputs: tuple | None = None) -> _Code:
    """The source of ``_solve(x, params)`` for ``plan``'s construction ``steps``, compiled.

    With ``meet`` (the staged solver) the intersections call ``meet(px, py, ux, uy, qx, qy,
    vx, vy) → (x, y)`` (NaN where it finds none) and the record also holds every polygon
    vertex and slot direction (what a :class:`polygons.evaluate.Solution` reports).

    With ``instruments`` (the drawing board) every vector, line direction and marked point
    passes through its noisy stroke (:meth:`_Steps.drawn`); with ``positions`` every point is
    a parameter ``("pos", label, 0 | 1)`` (the space diagram as drawn), not placed again.

    With ``outputs`` (kinds of :data:`ANSWERS`) the program is *answers only* (over floats):
    its record holds those numbers and nothing of the steps; each line keeps its direction as
    the op gives it (unnormalised) and an intersection is the 2×2 solve
    P + t u = Q + s v, t = ((Q − P) × v)/(u × v), its test ``(u × v)² > LEAN_TAN² (u · v)²``;
    the rest is dropped as dead code, and each local read once is written into its reader
    (:func:`_fold`: the same operations in the same order, fewer statements)."""
    check_compilable(scene, plan, steps)
    lean = outputs is not None
    g = Source(scene, sigma, arrays, meet, instruments, lean=lean)
    if positions:
        for label in list(scene.ground) + [x for d in plan.dyads for x in d.placed]:
            g.place(label, g.param(("pos", label, 0)), g.param(("pos", label, 1)))
    else:
        for label in scene.ground:
            g.place(label, g.param(lambda s, _l=label: s.ground[_l][0]),
                    g.param(lambda s, _l=label: s.ground[_l][1]))
        for d in plan.dyads:
            g.dyad = d
            d.source(g)
        g.dyad = None
    names = Vertices(scene)
    omega, alpha = {}, {}
    drv = scene.driver
    if isinstance(drv, Crank):
        omega[drv.link] = g.param(lambda s: s.driver.omega)
        alpha[drv.link] = g.param(lambda s: s.driver.alpha)
    st = _Steps(g, scene, names, omega, alpha)
    out: list[str] = []
    slot: dict[str, int] = {}

    def put(name) -> int:
        """The record index of local ``name`` (each local once in the record)."""
        i = slot.get(name)
        if i is None:
            i = slot[name] = len(out)
            out.append(name)
        return i

    layout = []
    for s in steps:
        fields, value, angle, unit, terms = _Steps.OPS[s.op](st, s)
        layout.append(_Out({k: (put(v[0]), put(v[1])) for k, v in fields.items()},
                           None if value is None else put(value),
                           None if angle is None else put(angle), unit,
                           tuple((sym, _lazy(v, put), u) for sym, v, u in terms)))
    if arrays or lean:  # only the vertices, rates and margins: the step records' numbers
        out.clear()     # are left out (and their code dropped as dead)
        slot.clear()
        layout = []
    asked = set(ANSWERS + ("coriolis",) if outputs is None else outputs)
    index = {}
    for label, (x, y) in g.placed.items():
        if "pos" in asked:
            index[("pos", label)] = (put(x), put(y))
        for d in (V, A):
            if d.value in asked and names.of(label) in st.vx[d]:
                vx = st.vx[d][names.of(label)]
                index[(d.value, label)] = (put(vx[0]), put(vx[1]))
    for key, table in (("omega", st.omega), ("alpha", st.alpha), ("slide_v", st.slide_v),
                       ("slide_a", st.slide_a)):
        for name, v in table.items():
            if key in asked:
                index[(key, name)] = put(v)
    for pin, c in st.cor.items():
        if "coriolis" in asked:
            index[("coriolis", pin)] = (put(c[0]), put(c[1]))
    if meet is not None:        # what the staged Solution reports besides the steps
        for d in (V, A):
            for vertex, (x, y) in st.vx[d].items():
                index[("vx", d.value, vertex)] = (put(x), put(y))
        for pin, sl in scene.model.slot.items():
            if sl.coincident in g.placed:
                e, _ = st.slot_e(pin)
                index[("slot_e", pin)] = (put(e[0]), put(e[1]))
        for sl in scene.model.crossings():
            if sl.coincident in g.placed:
                e, _ = st.slot_e(sl.at, sl.coincident)
                key = st.slide_key((sl.at, sl.coincident))
                index[("slot_e", key)] = (put(e[0]), put(e[1]))
        for pin, sl in scene.model.collar.items():
            if pin in g.placed:
                e = st.unit(st.r(sl.line.origin, sl.line.toward))
                index[("slot_e", pin)] = (put(e[0]), put(e[1]))
    lines = g.lines
    if arrays:
        index[("margins", "")] = tuple(put(m) for m in g.margins)
        index[("margin_of", "")] = tuple(g.margin_of)
        index[("crossings", "")] = tuple((put(c[0]), put(c[1]), c[2]) for c in g.crossings)
    lines = live(lines, out)            # the ops the outputs need (polygons.program)
    params = ", ".join(f"k{i}" for i in range(len(g.getters)))
    body = "\n    ".join(line.text for line in lines)
    src = (f"def _solve(x, _k):\n    ({params}{',' if len(g.getters) == 1 else ''}) = _k\n"
           f"    {body}\n    return ({', '.join(out)},)\n")
    ns = dict(g.namespace)
    run, derive = src, None
    if lean:
        run, consts = _fold(src, len(g.getters))
        if consts:      # the parameters' own combinations, computed once per scene
            dsrc = (f"def _derive(_k):\n    ({params},) = _k\n"
                    f"    return ({', '.join(consts)},)\n")
            exec(compile(dsrc, "<polygons.compiled derive>", "exec"), ns)
            derive = ns["_derive"]
    if not arrays:      # over floats every name it calls a local (bound as a default)
        bound = ", ".join(f"{k}={k}" for k in ns if k.isidentifier())
        run = run.replace("def _solve(x, _k):", f"def _solve(x, _k, {bound}):", 1)
    exec(compile(run, f"<polygons.compiled {_code_name(scene.title or scene.file)}>", "exec"),
         ns)
    return _Code(ns["_solve"], tuple(g.getters), tuple(layout), index, tuple(g.fails), src,
                 g.namespace, derive)


def _lazy(v, put):
    """A term's place in the record: an index, or (for a magnitude the record's vectors
    already determine) how to compute it when the Step records are built."""
    if not isinstance(v, tuple):
        return put(v)
    if v[0] == "abs":
        return ("abs", put(v[1]))
    if v[0] == "hypot":
        return ("hypot", put(v[1][0]), put(v[1][1]))
    r, rel = v[1], v[2]                 # the tangential part |r/|r| × rel|
    return ("tangential", put(r[0]), put(r[1]), put(rel[0]), put(rel[1]))


def _slot_kinds(scene: Scene) -> tuple:
    """What of the slots the generated code is shaped by (part of the cache key): whether each
    is offset (the lever's far end from the pin) and runs along its lever (pivot → far end)."""
    return tuple(sorted((pin, bool(sl.line.offset), sl.along_lever)
                        for pin, sl in scene.model.slot.items()))
