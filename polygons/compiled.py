"""The step program compiled to straight-line Python over plain floats.

The staged solver (:mod:`polygons.evaluate`) runs the construction stroke by stroke on numpy
vectors and intersects its lines with shapely: right for drawing, slow for asking the same
mechanism thousands of questions.  Here the same plan is turned, once per scene topology, into
the source text of one Python function (every dyad's placement from its module's
:meth:`source`, every step from the op's code below: the same formulas as
:mod:`polygons.interpret`, term for term, with the 2×2 line intersection instead of shapely)
which is ``compile``d and cached.  Calling it fills every step's numbers into one flat tuple;
:class:`CompiledSolution` builds the :class:`~polygons.steps.Step` records and their
substituted text from that tuple only when asked.

    program = compile_scene(scene)       # plan + assembly + code (cached by topology)
    sol = program.solve()                # the scene's own input; program.solve(theta) another
    sol.omega("BC"), sol.velocity("C"), sol.steps

Conditioning is the staged solver's: the angle between two construction lines is
``degrees(atan2(|u × v|, |u · v|))`` (:func:`polygons.geometry.angle_between`), below
``PARALLEL_DEG`` the lines are parallel and the step fails with the same error.
Two-closure dyads follow the closure the staged assembly takes at the scene's own input (the
same side of their base line, as in :mod:`polygons.sweep`).  This module imports neither shapely
nor the diagrams.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from .dyads.base import ARRAY_TWIN
from .errors import UnsupportedError, AssemblyError, ConstructionError, ParallelLinesError
from .narrate import substitute
from .plan import Plan, construction, make_plan
from .position import assemble, driver_input
from .scene import Crank, Scene
from .steps import Diagram, Op, Step, Term, Vertices
from .topology import slot_along_lever

#: the staged solver's thresholds (polygons.geometry; a test keeps them equal)
PARALLEL_DEG = 1e-5
WARN_DEG = 1.0

V, A = Diagram.VELOCITY, Diagram.ACCELERATION
_FIELDS = ("at", "vector", "point", "direction")


def _where(c, a, b):
    return a if c else b


def _hypot_cols(x, y):
    return np.sqrt(x * x + y * y)


class _Fail(Exception):
    """Raised by generated code: ``args[0]`` indexes the program's failure table."""


# ---------------------------------------------------------------- code generation
class Source:
    """What a dyad's ``source(g)`` and the op generators write with: fresh local names,
    scene parameters, placed positions, checks.  (The ``g`` of :meth:`Dyad.source`.)"""

    x = "x"   # the driver's input (θ in rad or s in m)

    # Names the generated code may call: cos, sin, atan2, degrees, sqrt, nan, where (math or
    # numpy); ``hypot`` is the kernel's norm (√(x² + y²) over arrays), ``hypot_p`` a dyad
    # locate's np.hypot (math.hypot over floats), so that positions over arrays are the
    # kernel's to the last bit.

    def __init__(self, scene: Scene, sigma: dict, arrays: bool = False):
        self.scene = scene
        self.arrays = arrays           # the same code over (N,) arrays: no checks, margins kept
        self.margins: list[str] = []
        self.margin_of: list = []      # the dyad of each margin
        self.crossings: list = []      # (u × v, u · v, step) of every intersection
        self.lines: list[str] = []
        self.getters: list = []        # scene -> float, one per parameter k<i>
        self.namespace: dict = ({"cos": np.cos, "sin": np.sin, "hypot": _hypot_cols,
                                 "atan2": np.arctan2, "degrees": np.degrees, "where": np.where,
                                 "sqrt": np.sqrt, "nan": np.nan, "hypot_p": np.hypot,
                                 "_Fail": _Fail} if arrays else
                                {"cos": math.cos, "sin": math.sin, "hypot": math.hypot,
                                 "atan2": math.atan2, "degrees": math.degrees,
                                 "where": _where, "sqrt": math.sqrt, "nan": math.nan,
                                 "hypot_p": math.hypot,
                                 "_Fail": _Fail})
        self.fails: list = []          # ("dyad", dyad) | ("step", step, reason)
        self.placed: dict[str, tuple[str, str]] = {}
        self.sigma_of = sigma
        self.dyad = None
        self._n = 0
        self._memo: dict[str, str] = {}
        self._checked: set[str] = set()

    # -- used by the dyad modules ----------------------------------------------------------
    def param(self, getter) -> str:
        """A scene number as a parameter of the compiled function: ``getter(scene)`` (or
        ("sigma", label) for a closure) is read per scene, so the code serves a topology."""
        self.getters.append(getter)
        return f"k{len(self.getters) - 1}"

    def sigma(self, label: str) -> str:
        return self.param(("sigma", label))

    def let(self, expr: str) -> str:
        """``expr`` in a fresh local (or the local that already holds it: every local is
        assigned once, so equal text is an equal value)."""
        name = self._memo.get(expr)
        if name is not None:
            return name
        self._n += 1
        name = f"v{self._n}"
        self.lines.append(f"{name} = {expr}")
        self._memo[expr] = name
        return name

    def call(self, fn, *args, n: int = 1):
        if self.arrays:
            fn = ARRAY_TWIN.get(fn, fn)
        fname = f"_f_{fn.__name__}"
        self.namespace[fname] = fn
        names = [f"v{self._n + i + 1}" for i in range(n)]
        self._n += n
        self.lines.append(f"{', '.join(names)} = {fname}({', '.join(args)})")
        return names

    def margin(self, m: str) -> None:
        """Fail where the dyad cannot close (the staged assembly's test: a two-closure dyad
        needs a margin ≥ 0, any other > 0)."""
        if self.arrays:                 # over arrays: NaN where it cannot close, and the
            self.margins.append(m)      # margin kept (the sweep's conditioning)
            self.margin_of.append(self.dyad)
            return
        test = ">= 0.0" if self.dyad.two_closures else "> 0.0"
        self.fail_unless(f"{m} {test}", ("dyad", self.dyad))

    def pos(self, label: str) -> tuple[str, str]:
        """The local names of a placed point's coordinates."""
        return self.placed[label]

    def place(self, label: str, x: str, y: str) -> None:
        self.placed[label] = (x, y)

    # -- used by the op generators ---------------------------------------------------------
    def fail_unless(self, cond: str, why) -> None:
        # over arrays there are no checks; a test already made on the same locals has passed
        if self.arrays or cond in self._checked:
            return
        self._checked.add(cond)
        self.fails.append(why)
        self.lines.append(f"if not ({cond}): raise _Fail({len(self.fails) - 1})")

    def vec(self, ex: str, ey: str) -> tuple[str, str]:
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
    """The op generators: one per :class:`Op`, the kernel's formulas over floats."""

    def __init__(self, g: Source, scene: Scene, names: Vertices, omega: dict, alpha: dict):
        self.g, self.scene, self.names = g, scene, names
        zero = ("0.0", "0.0")
        self.vx = {V: {names.pole: zero}, A: {names.pole: zero}}
        self.omega, self.alpha = omega, alpha
        self.lines: dict = {}
        self.slide_v: dict = {}
        self.slide_a: dict = {}
        self.cor: dict = {}

    # helpers mirroring Kernel
    def r(self, p, x):
        (px, py), (xx, xy) = self.g.pos(p), self.g.pos(x)
        return self.g.vec(f"{xx} - {px}", f"{xy} - {py}")

    def of(self, d, label):
        return self.vx[d][self.names.of(label)]

    def norm(self, v):
        return self.g.let(f"hypot({v[0]}, {v[1]})")

    def sub(self, a, b):
        if b == ("0.0", "0.0"):
            return a
        return self.g.vec(f"{a[0]} - {b[0]}", f"{a[1]} - {b[1]}")

    def cross(self, a, b):
        return self.g.let(f"{a[0]} * {b[1]} - {a[1]} * {b[0]}")

    def dot(self, a, b):
        return self.g.let(f"{a[0]} * {b[0]} + {a[1]} * {b[1]}")

    def slider_e(self, X, attr="direction"):
        g = self.g
        return (g.param(lambda s: getattr(s.sliders[X], attr)[0]),
                g.param(lambda s: getattr(s.sliders[X], attr)[1]))

    def slot_e(self, A_):
        """The unit vector along the slot of pin ``A_`` (``Kernel._slot_e``): pivot → far end
        for an offset slot or a lever placed before its pin, else pivot → pin."""
        slot = self.scene.slots[A_]
        if slot.far is not None and slot_along_lever(self.scene, slot):
            r = self.r(slot.pivot, slot.far)
        else:
            r = self.r(slot.pivot, A_)
        return self.unit(r), slot

    def unit(self, r):
        """r / |r|."""
        n = self.norm(r)
        return self.g.vec(f"{r[0]} / {n}", f"{r[1]} / {n}")

    def rel_vel(self, w, r):
        return self.g.vec(f"{w} * -{r[1]}", f"{w} * {r[0]}")

    def centripetal(self, w, r):
        w2 = self.g.let(f"-({w} * {w})")
        return self.g.vec(f"{w2} * {r[0]}", f"{w2} * {r[1]}")

    def ang(self, r, rel):
        """cross(r, rel) / dot(r, r): ω or α from a relative vector."""
        return self.g.let(f"({r[0]} * {rel[1]} - {r[1]} * {rel[0]}) / "
                          f"({r[0]} * {r[0]} + {r[1]} * {r[1]})")

    def vector(self, s, vec, unit, terms):
        start = self.vx[s.diagram][s.start]
        end = self.g.vec(f"{start[0]} + {vec[0]}", f"{start[1]} + {vec[1]}")
        self.vx[s.diagram][s.end] = end
        return dict(at=start, vector=vec, point=end), None, None, unit, terms

    def line(self, s, d, anchor):
        g = self.g
        n = self.norm(d)
        g.fail_unless(f"{n} != 0.0 and {n} == {n}", ("step", s, "zero"))
        u = g.vec(f"{d[0]} / {n}", f"{d[1]} / {n}")
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
        vec = self.g.vec(f"{val} * {e[0]}", f"{val} * {e[1]}")
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
        return self.line_result(s, self.line(s, (f"-{r[1]}", r[0]), self.vx[s.diagram][s.start]))

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
        w = self.omega[slot.lever]
        v_s = self.slide_v[A_]
        ve = g.vec(f"{v_s} * {e[0]}", f"{v_s} * {e[1]}")
        w2 = g.let(f"2.0 * {w}")
        a_cor = g.vec(f"{w2} * -{ve[1]}", f"{w2} * {ve[0]}")
        self.cor[A_] = a_cor
        anchor = self.sub(self.of(s.diagram, A_), a_cor)
        ln = self.line(s, e, anchor)
        neg = g.vec(f"-{a_cor[0]}", f"-{a_cor[1]}")
        return dict(at=ln[0], vector=neg, direction=ln[1]), None, None, "m/s^2", (
            (f"ω_{slot.lever}", ("abs", w), "rad/s"),
            (f"(v_{A_})_{slot.coincident}", ("abs", v_s), "m/s"),
            ("2ωv", ("hypot", a_cor), "m/s^2"))

    def coriolis_op(self, s):
        """2 ω × ṡ e: the offset line's when it computed it, else computed here (a pin found
        in a lever's slot; a prescribed slide, ṡ given, along its link)."""
        (A_,) = s.args
        g = self.g
        if A_ in self.cor:
            a_cor = self.cor[A_]
            return self.vector(s, a_cor, "m/s^2", (("2ωv", ("hypot", a_cor), "m/s^2"),))
        sl = self.scene.prescribed.get(A_)
        if sl is not None:
            e = self.unit(self.r(sl.p, sl.q))
            L, v_s = sl.link, g.param(lambda sc: sc.prescribed[A_].velocity)
        else:
            e, slot = self.slot_e(A_)
            L, v_s = slot.lever, self.slide_v[A_]
        w = self.omega[L]
        ve = g.vec(f"{v_s} * {e[0]}", f"{v_s} * {e[1]}")
        w2 = g.let(f"2.0 * {w}")
        a_cor = self.cor[A_] = g.vec(f"{w2} * -{ve[1]}", f"{w2} * {ve[0]}")
        return self.vector(s, a_cor, "m/s^2", ((f"ω_{L}", ("abs", w), "rad/s"),
                                               (f"ṡ_{A_}", ("abs", v_s), "m/s"),
                                               ("2ωv", ("hypot", a_cor), "m/s^2")))

    def line_slide(self, s):
        (A_,) = s.args
        e, _ = self.slot_e(A_)
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
        vec = g.vec(f"{val} * {e[0]}", f"{val} * {e[1]}")
        return self.vector(s, vec, unit, ((s.quantity, val, unit),))

    def join(self, s):
        vx = self.vx[s.diagram]
        vec = self.sub(vx[s.end], vx[s.start])
        return dict(at=vx[s.start], vector=vec, point=vx[s.end]), None, None, "m/s^2", (
            (f"{s.start}{s.end}", ("hypot", vec), "m/s^2"),)

    def intersect(self, s):
        g = self.g
        (p, u), (q, v) = (self.lines[(s.diagram, n)] for n in s.lines)
        den = self.cross(u, v)
        dot = self.dot(u, v)
        angle = g.let(f"degrees(atan2(abs({den}), abs({dot})))")
        g.crossings.append((den, dot, s))
        g.fail_unless(f"{angle} >= {PARALLEL_DEG!r}", ("step", s, "parallel"))
        w = self.sub(q, p)
        t = g.let(f"({w[0]} * {v[1]} - {w[1]} * {v[0]}) / {den}")
        pt = g.vec(f"{p[0]} + {t} * {u[0]}", f"{p[1]} + {t} * {u[1]}")
        self.vx[s.diagram][s.end] = pt
        unit = _unit_of(s.diagram)
        return dict(point=pt), None, angle, unit, (
            ("angle", angle, "deg"), (f"{self.names.pole}{s.end}", ("hypot", pt), unit))

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
        (A_,) = s.args
        e, slot = self.slot_e(A_)
        rel = self.sub(self.of(s.diagram, A_), self.of(s.diagram, slot.coincident))
        if s.diagram == V:
            val = self.dot(rel, e)
            self.slide_v[A_] = val
        else:
            val = self.dot(self.sub(rel, self.cor[A_]), e)
            self.slide_a[A_] = val
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
            vec = self.g.vec(f"{t[0]} + {c[0]}", f"{t[1]} + {c[1]}")
        unit = _unit_of(s.diagram)
        return self.vector(s, vec, unit, ((f"{s.start}{s.end}", ("hypot", vec), unit),))

    OPS = {
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


_CACHE: dict = {}


class NotCompiled(UnsupportedError):
    """The compiled evaluator does not cover this scene (the staged solver and the kernel do):
    its message names what is missing."""


def check_compilable(scene: Scene, plan: Plan, steps: tuple[Step, ...]) -> None:
    """Refuse, naming it, what the generated code does not model yet: a dyad without a
    ``source``, a step op without its generator (every shipped dyad and op has one now; this
    stays the guard for a new kind added to the kernel before its generator)."""
    for d in plan.dyads:
        if not hasattr(d, "source"):
            raise NotCompiled(f"the compiled evaluator does not generate the "
                              f"{type(d).__name__} dyad at {', '.join(d.placed)} yet",
                              file=scene.file)
    for s in steps:
        if s.op not in _Steps.OPS:
            raise NotCompiled(f"the compiled evaluator has no code for the step op "
                              f"{str(s.op)!r} yet", file=scene.file)


def _generate(scene: Scene, plan: Plan, steps: tuple[Step, ...], sigma: dict,
              arrays: bool = False) -> _Code:
    check_compilable(scene, plan, steps)
    g = Source(scene, sigma, arrays)
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
    if arrays:      # only the vertices, rates and margins: the step records' numbers are
        out.clear()     # left out (and their code dropped as dead)
        slot.clear()
        layout = []
    index = {}
    for label, (x, y) in g.placed.items():
        index[("pos", label)] = (put(x), put(y))
        for d in (V, A):
            if names.of(label) in st.vx[d]:
                vx = st.vx[d][names.of(label)]
                index[(d.value, label)] = (put(vx[0]), put(vx[1]))
    for key, table in (("omega", st.omega), ("alpha", st.alpha), ("slide_v", st.slide_v),
                       ("slide_a", st.slide_a)):
        for name, v in table.items():
            index[(key, name)] = put(v)
    for pin, c in st.cor.items():
        index[("coriolis", pin)] = (put(c[0]), put(c[1]))
    lines = g.lines
    if arrays:
        index[("margins", "")] = tuple(put(m) for m in g.margins)
        index[("margin_of", "")] = tuple(g.margin_of)
        index[("crossings", "")] = tuple((put(c[0]), put(c[1]), c[2]) for c in g.crossings)
    lines = _live(lines, out)
    params = ", ".join(f"k{i}" for i in range(len(g.getters)))
    body = "\n    ".join(lines)
    src = (f"def _solve(x, _k):\n    ({params}{',' if len(g.getters) == 1 else ''}) = _k\n"
           f"    {body}\n    return ({', '.join(out)},)\n")
    ns = dict(g.namespace)
    exec(compile(src, f"<polygons.compiled {scene.title or scene.file}>", "exec"), ns)
    return _Code(ns["_solve"], tuple(g.getters), tuple(layout), index, tuple(g.fails), src)


_NAME = re.compile(r"\bv\d+\b")


def _live(lines: list[str], out: list[str]) -> list[str]:
    """Dead-code elimination on the straight-line code: keep the assignments ``out`` needs."""
    need = {n for o in out for n in _NAME.findall(o)}
    kept = []
    for line in reversed(lines):
        if line.startswith("if "):      # a check stays, with what it tests
            kept.append(line)
            need.update(_NAME.findall(line))
            continue
        targets, _, expr = line.partition(" = ")
        if any(t.strip() in need for t in targets.split(",")):
            kept.append(line)
            need.update(_NAME.findall(expr))
    return kept[::-1]


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


def _term(r, i):
    """A term's value from the record (the same expression as the kernel's, over floats)."""
    if type(i) is int:
        return r[i]
    if i[0] == "abs":
        return abs(r[i[1]])
    if i[0] == "hypot":
        return math.hypot(r[i[1]], r[i[2]])
    r0, r1, q0, q1 = (r[j] for j in i[1:])
    n = math.hypot(r0, r1)
    return abs(r0 / n * q1 - r1 / n * q0)


def _sigmas(plan: Plan) -> dict:
    """The closure of every two-closure dyad taken by the staged assembly at the scene's input
    (+1 / −1, by the numpy :meth:`locate` of its module)."""
    scene = plan.scene
    placement = assemble(plan)
    pos = {k: np.array(v) for k, v in placement.points.items()}
    x0 = driver_input(scene)
    sigma = {}
    for d in plan.dyads:
        if d.two_closures:
            x = d.placed[0]
            c1, _ = d.locate(scene, pos, 1.0, x0)
            c2, _ = d.locate(scene, pos, -1.0, x0)
            d1 = float(np.hypot(*(c1[x] - pos[x])))
            d2 = float(np.hypot(*(c2[x] - pos[x])))
            sigma[x] = 1.0 if d1 <= d2 else -1.0
    return sigma


# ---------------------------------------------------------------- the compiled program
@dataclass(frozen=True)
class Program:
    """A scene's construction compiled to one float function (see the module docstring)."""

    scene: Scene
    plan: Plan
    steps: tuple[Step, ...]
    sigma: dict
    code: _Code
    params: tuple
    x0: float
    fn: object = None         # code.fn, held here for the call's sake

    def solve(self, x: float | None = None) -> "CompiledSolution":
        """Every step's numbers at input ``x`` (θ in rad or s in m; default the scene's)."""
        try:
            return CompiledSolution(self, self.fn(self.x0 if x is None else x, self.params))
        except _Fail as f:
            raise self._error(self.code.fails[f.args[0]], x) from None


    def _error(self, why, x):
        scene = self.scene
        if why[0] == "dyad":
            d = why[1]
            pos = {k: np.array(v, dtype=float) for k, v in scene.ground.items()}
            xin = self.x0 if x is None else x
            for e in self.plan.dyads:
                if e is d:
                    break
                pts, _ = e.locate(scene, pos, self.sigma.get(e.placed[0]), xin)
                pos.update(pts)
            return AssemblyError(d.why_not(scene, pos), file=scene.file,
                                 where=getattr(d, "lever", None) or d.placed[0])
        _, s, kind = why
        where = f"{s.diagram} {s.number} ({s.draws})"
        if kind == "zero":
            return ParallelLinesError(f"construction line {s.draws} has no direction (its "
                                      f"defining vector is zero)", file=scene.file, step=where)
        l1, l2 = (self.steps[_step_index(self.steps, s.diagram, n)].draws for n in s.lines)
        return ParallelLinesError(
            f"the {l1} and the {l2} are parallel: the mechanism is at a toggle or change "
            f"point and this point of the polygon is undefined", file=scene.file, step=where)


def _step_index(steps, diagram, number) -> int:
    for i, s in enumerate(steps):
        if s.diagram == diagram and s.number == number:
            return i
    raise ConstructionError(f"no step {diagram} {number}")


def _slot_kinds(scene: Scene) -> tuple:
    """What of the slots the generated code is shaped by (part of the cache key): whether each
    is offset (the lever's far end from the pin) and runs along its lever (pivot → far end)."""
    return tuple(sorted((pin, bool(sl.offset), sl.far is not None and
                         slot_along_lever(scene, sl)) for pin, sl in scene.slots.items()))


def compile_scene(scene: Scene, plan: Plan | None = None) -> Program:
    """Plan ``scene``, take its closures from the staged assembly, and compile (or fetch from
    the cache, keyed on the plan's dyads and steps) the float function of its construction."""
    plan = plan or make_plan(scene)
    steps = construction(plan)
    sigma = _sigmas(plan)
    key = (plan.dyads, steps, tuple(scene.ground), tuple(sorted(sigma)), _slot_kinds(scene))
    code = _CACHE.get(key)
    if code is None:
        if len(_CACHE) >= 256:          # a bound, not a policy: topologies are few
            _CACHE.clear()
        code = _CACHE[key] = _generate(scene, plan, steps, sigma)
    # the closures are parameters too: fetch them from this scene
    params = tuple(float(sigma[get[1]] if isinstance(get, tuple) else get(scene))
                   for get in code.getters)
    return Program(scene, plan, steps, sigma, code, params, float(driver_input(scene)),
                   code.fn)


def _copy(step: Step, vals: dict, **more) -> Step:
    """``dataclasses.replace(step, **vals, **more)`` without re-running ``__init__`` (a frozen
    record copied field for field: 20× faster, the same value)."""
    new = object.__new__(Step)
    d = new.__dict__
    d.update(step.__dict__)
    d.update(vals)
    d.update(more)
    return new


def compile_arrays(scene: Scene, plan: Plan, sigma: dict) -> tuple[_Code, tuple]:
    """The same construction generated for (N,) arrays of inputs (every position of a sweep
    chunk at once): the code and this scene's parameters.  Only the vertices, rates and dyad
    margins are computed (the step records' numbers are dropped as dead code); where a dyad
    cannot close the numbers are NaN and its margin negative, as in :mod:`polygons.sweep`."""
    steps = construction(plan, tuple(Diagram))
    key = ("arrays", plan.dyads, steps, tuple(scene.ground), tuple(sorted(sigma)),
           _slot_kinds(scene))
    code = _CACHE.get(key)
    if code is None:
        code = _CACHE[key] = _generate(scene, plan, steps, sigma, arrays=True)
    params = tuple(float(sigma[get[1]] if isinstance(get, tuple) else get(scene))
                   for get in code.getters)
    return code, params


class CompiledSolution:
    """One position's numbers (``record``: a flat tuple of floats) with the step records and
    their substituted text built from it on first access."""

    __slots__ = ("program", "record", "_steps")

    def __init__(self, program: Program, record: tuple):
        self.program = program
        self.record = record

    def position(self, label: str) -> tuple[float, float]:
        i, j = self.program.code.index[("pos", label)]
        return self.record[i], self.record[j]

    def velocity(self, label: str) -> tuple[float, float]:
        return self._pair("velocity", label)

    def acceleration(self, label: str) -> tuple[float, float]:
        return self._pair("acceleration", label)

    def _pair(self, d, label):
        if label in self.program.scene.ground:
            return 0.0, 0.0
        i, j = self.program.code.index[(d, label)]
        return self.record[i], self.record[j]

    def omega(self, link: str) -> float:
        return self.record[self.program.code.index[("omega", link)]]

    def alpha(self, link: str) -> float:
        return self.record[self.program.code.index[("alpha", link)]]

    @property
    def min_intersection_angle_deg(self) -> float | None:
        angles = [self.record[o.angle] for o in self.program.code.layout if o.angle is not None]
        return min(angles) if angles else None

    @property
    def steps(self) -> tuple[Step, ...]:
        """The :class:`Step` records with their numbers and substituted text (as the staged
        solver fills them), built on first access."""
        try:
            return self._steps
        except AttributeError:
            self._steps = self._build_steps()
            return self._steps

    def _build_steps(self) -> tuple[Step, ...]:
        r = self.record
        scene = self.program.scene
        done = []
        for step, o in zip(self.program.steps, self.program.code.layout):
            vals = {k: (r[o.fields[k][0]], r[o.fields[k][1]]) if k in o.fields else None
                    for k in _FIELDS}
            filled = _copy(step, vals, value=None if o.value is None else r[o.value],
                           unit=o.unit, angle_deg=None if o.angle is None else r[o.angle],
                           terms=tuple(Term(sym, _term(r, i), u) for sym, i, u in o.terms))
            filled.__dict__["substituted"] = substitute(filled, scene)
            done.append(filled)
        return tuple(done)
