"""The step program compiled to straight-line Python over plain floats.

Every interpreter of the step program runs the code :mod:`polygons.codegen` writes from it
(every dyad's placement from its module's :meth:`source`, every step from its op's generator),
compiled once per scene topology and cached; they differ in how the code is generated: here
over plain floats with the 2×2 line intersection (the fast evaluator), for the staged solver
with shapely's intersection (:func:`compile_staged`, :mod:`polygons.evaluate`), over arrays for
sweeps and batches (:func:`compile_arrays`, :func:`compile_given`) and with noisy instruments
for the drawing board.  Calling the float program fills every step's numbers into one flat tuple;
:class:`CompiledSolution` builds the :class:`~polygons.steps.Step` records (numbers and
terms) from that tuple only when asked.

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
from dataclasses import dataclass, fields, is_dataclass
from typing import Mapping

import numpy as np

from .codegen import (ANSWERS, PARALLEL_DEG, WARN_DEG,  # noqa: F401 (read from here)
                      NotCompiled, _Code, _Fail, _slot_kinds, generate)
from .errors import ConstructionError, ParallelLinesError, UnsupportedError
from .plan import Plan, construction, make_plan
from .position import assemble, driver_input, dyad_failure
from .scene import Scene
from .steps import Diagram, Step, Term, noise_floor
from .memo import memo_of
from .model import BUILT, check_handles

_FIELDS = ("at", "vector", "point", "direction")
_CACHE: dict = {}


#: the kinds of body and pair the compiled evaluator handles (polygons.model)
HANDLES = BUILT

#: the scene fields the generated code is shaped by (its topology: what is placed, driven,
#: guided and slotted, and how); the rest — names of the file, texts, answers, loads,
#: options — never reach the code, and the numbers are read at run time by its getters
_SHAPED_BY = ("ground", "links", "driver", "sliders", "slots", "points", "solve", "crossing",
              "prescribed", "equivalents")


def _shape(value):
    """``value`` with every float replaced by its type: the whole identity of a record tree
    but its measures (a record's kind and every field name, label, flag, count and None),
    walked without recursion (the tree is the user's scene); how each type is read is worked
    out once per type (:func:`_how`)."""
    out: list = []
    stack = [value]
    append, push, how_of = out.append, stack.append, _HOW.get
    while stack:
        v = stack.pop()
        how = how_of(type(v))
        if how is None:
            how = _how(v)
        if how is _ATOM:
            append(v)
        elif how is _FLOAT:
            append(float)
        elif how is _MAP:
            append((type(v).__name__, len(v)))
            for k, item in v.items():
                push(item)
                push(k)
        elif how is _SEQ:
            append(("seq", len(v)))
            stack.extend(reversed(list(v)))
        elif how[0] is _RECORD:
            append(how[1])
            for name in how[2]:
                push(getattr(v, name))
                append(name)
        else:                                   # (_OTHER, its type's name)
            append(how[1])
    return tuple(out)


_ATOM, _FLOAT, _MAP, _SEQ, _RECORD, _OTHER = "atom", "float", "map", "seq", "record", "other"
#: how :func:`_shape` reads a value of each type met so far
_HOW: dict = {}


def _how(v):
    """How :func:`_shape` reads ``v``: as it is (None, text, a flag, an integer), as its type
    (a float), a record's kind and compared fields, a mapping, a sequence, or by its type's
    name; kept for ``type(v)`` unless ``v`` is itself a class."""
    if v is None or isinstance(v, (str, bool, int)) and not isinstance(v, np.integer):
        how = _ATOM
    elif isinstance(v, (float, np.floating)):
        how = _FLOAT
    elif is_dataclass(v):
        how = (_RECORD, type(v).__qualname__, tuple(f.name for f in fields(v) if f.compare))
    elif isinstance(v, Mapping):
        how = _MAP
    elif isinstance(v, (tuple, list, np.ndarray)):
        how = _SEQ
    else:
        how = (_OTHER, type(v).__qualname__)
    if not isinstance(v, type):
        _HOW[type(v)] = how
    return how


def topology_key(scene: Scene) -> tuple:
    """The part of every code-cache key that is the scene's own: its driver's kind, its
    guides, slots, points and contacts as well as the plan (kept with the scene)."""
    memo = memo_of(scene)
    key = memo.get("topology_key")
    if key is None:
        key = memo["topology_key"] = tuple(_shape(getattr(scene, name, None))
                                           for name in _SHAPED_BY)
    return key


def _cached(key, make, scene: Scene | None = None) -> _Code:
    """The code kept under ``key`` and the scene's :func:`topology_key`, made by ``make()``
    the first time."""
    if scene is not None:
        key = (key, topology_key(scene))
    code = _CACHE.get(key)
    if code is None:
        if len(_CACHE) >= 256:          # a bound, not a policy: topologies are few
            _CACHE.clear()
        code = _CACHE[key] = make()
    return code


def _sigmas(plan: Plan) -> dict:
    """The closure of every two-closure dyad taken by the staged assembly at the scene's input
    (+1 / −1, as its module's :meth:`locate` numbers them)."""
    return dict(assemble(plan).sigmas)


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
    outputs: tuple | None = None    # answers only: the kinds computed (None: every step's)
    full: "Program | None" = None   # answers only: the full program, run where this fails

    def solve(self, x: float | None = None) -> "CompiledSolution":
        """Every step's numbers at input ``x`` (θ in rad or s in m; default the scene's); an
        answers-only program's (``outputs``) answers only."""
        try:
            return CompiledSolution(self, self.fn(self.x0 if x is None else float(x),
                                                  self.params))
        except _Fail as f:
            if self.full is not None:
                return self._by_full(x)
            raise self._error(self.code.fails[f.args[0]], x) from None
        except ArithmeticError:
            if self.full is not None:
                return self._by_full(x)
            raise

    def _by_full(self, x) -> "CompiledSolution":
        """Where the answers-only test of a construction line fails (two lines within
        PARALLEL_DEG × (1 + 1e-9) of parallel): the full program's error, or its answers."""
        r = self.full.solve(x).record
        r = r.tolist() if isinstance(r, np.ndarray) else r
        full, mine = self.full.code.index, self.code.index
        rec = [0.0] * (1 + max((max(i) if isinstance(i, tuple) else i)
                               for i in mine.values()))
        for key, i in mine.items():
            if isinstance(i, tuple):
                for a, b in zip(i, full[key]):
                    rec[a] = r[b]
            else:
                rec[i] = r[full[key]]
        return CompiledSolution(self, tuple(rec))


    def solve_along(self, xs, start: int = 0) -> list:
        """:meth:`solve` at each input of ``xs`` (a path of neighbouring inputs), outwards from
        ``xs[start]``: a group of several closures (a triad) follows its closure from each
        position to the next, as a sweep does.  None where the construction fails."""
        from dataclasses import replace
        from .errors import PolygonsError
        groups = [d for d in self.plan.dyads if getattr(d, "many_closures", False)]
        out: list = [None] * len(xs)
        for order in (range(start, len(xs)), range(start, -1, -1)):
            prog = self
            for k in order:
                try:
                    sol = prog.solve(float(xs[k]))
                except (PolygonsError, ArithmeticError, ValueError):
                    continue            # this frame fails (a toggle): the next follows on
                out[k] = sol
                if groups:
                    sigma = dict(prog.sigma)
                    for d in groups:
                        B, X = sol.position(d.b), sol.position(d.x)
                        sigma.update(zip(d.sigma_keys, (B[0], B[1], X[0], X[1])))
                    params = _params(prog.code, prog.scene, sigma)
                    if isinstance(prog.params, np.ndarray):     # the numba kernel's
                        params = np.array(params, dtype=float)
                    full = prog.full        # (an answers-only program's follows too)
                    if full is not None:
                        full = replace(full, sigma=sigma,
                                       params=_params(full.code, full.scene, sigma))
                    prog = replace(prog, sigma=sigma, params=params, full=full)
        return out

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
            return dyad_failure(scene, d, pos)
        return step_failure(scene, self.steps, why)



def step_failure(scene: Scene, steps: tuple[Step, ...], why) -> Exception:
    """The error a failed check of the generated code stands for: ``why`` = ("step", step,
    "zero" | "parallel" | "meet")."""
    _, s, kind = why
    where = f"{s.diagram} {s.number} ({s.draws})"
    if kind == "zero":
        return ParallelLinesError(f"construction line {s.draws} has no direction (its "
                                  f"defining vector is zero)", file=scene.file, step=where)
    l1, l2 = (steps[_step_index(steps, s.diagram, n)].draws for n in s.lines)
    if kind == "meet":
        return ConstructionError(f"shapely found no single intersection of the {l1} and the "
                                 f"{l2}", file=scene.file, step=where)
    return ParallelLinesError(
        f"the {l1} and the {l2} are parallel: the mechanism is at a toggle or change "
        f"point and this point of the polygon is undefined", file=scene.file, step=where)


def _step_index(steps, diagram, number) -> int:
    for i, s in enumerate(steps):
        if s.diagram == diagram and s.number == number:
            return i
    raise ConstructionError(f"no step {diagram} {number}")


def _kernel(code: _Code):
    """``code`` compiled by numba (:func:`polygons.jit.record_kernel`), once per code; None
    where numba is missing or cannot compile it."""
    from . import jit
    return jit.cached(code, jit.record_kernel)


def compile_scene(scene: Scene, plan: Plan | None = None, jit: bool = False,
                  outputs=None) -> Program:
    """Plan ``scene``, take its closures from the staged assembly, and compile (or fetch from
    the cache, keyed on the plan's dyads and steps) the float function of its construction.
    With ``jit=True`` and numba installed the function is also compiled to machine code
    (:mod:`polygons.jit`; a float64 array for the record, the same numbers to rounding).

    ``outputs`` (some of :data:`ANSWERS`: "pos", "velocity", "acceleration", "omega",
    "alpha", "slide_v", "slide_a") makes an *answers-only* program: the same construction
    generated from the same statements (both diagrams), keeping only what those answers need —
    no step records, no unit directions (each intersection the 2×2 solve of its lines as
    given), the rest dropped as dead code.  Its solution answers ``position``, ``velocity``,
    ``acceleration``, ``omega``, ``alpha`` for the kinds asked; ``steps`` it refuses.  Where
    one of its line tests fails (near a toggle) the full program is run: its error, or its
    numbers."""
    check_handles("the compiled evaluator", HANDLES, scene.model, scene.file)
    plan = plan or make_plan(scene)
    if outputs is not None:
        return _answers_only(scene, plan, jit, outputs)
    steps = construction(plan)
    sigma = _sigmas(plan)
    key = (plan.dyads, steps, tuple(scene.ground), tuple(sorted(sigma)), _slot_kinds(scene))
    code = _cached(key, lambda: generate(scene, plan, steps, sigma), scene)
    kernel = _kernel(code) if jit else None
    if kernel is not None:
        return Program(scene, plan, steps, sigma, code,
                       np.array(_params(code, scene, sigma), dtype=float),
                       float(driver_input(scene)), kernel)
    return Program(scene, plan, steps, sigma, code, _params(code, scene, sigma),
                   float(driver_input(scene)), code.fn)


def _answers_only(scene: Scene, plan: Plan, jit: bool, outputs) -> Program:
    """:func:`compile_scene` with ``outputs``: the answers-only program (and the full one of
    both diagrams, run where its line tests fail)."""
    kinds = (outputs,) if isinstance(outputs, str) else tuple(outputs)
    bad = [k for k in kinds if k not in ANSWERS]
    if bad or not kinds:
        raise UnsupportedError(f"compile_scene outputs {', '.join(map(repr, bad)) or '()'}: "
                               f"an answers-only program computes {', '.join(ANSWERS)}",
                               file=scene.file)
    kinds = tuple(k for k in ANSWERS if k in kinds)
    steps = construction(plan, tuple(Diagram))
    sigma = _sigmas(plan)
    shape = (plan.dyads, steps, tuple(scene.ground), tuple(sorted(sigma)), _slot_kinds(scene))
    code = _cached(("answers", kinds) + shape,
                   lambda: generate(scene, plan, steps, sigma, outputs=kinds), scene)
    fcode = _cached(shape, lambda: generate(scene, plan, steps, sigma), scene)
    x0 = float(driver_input(scene))
    full = Program(scene, plan, steps, sigma, fcode, _params(fcode, scene, sigma), x0,
                   fcode.fn)
    kernel = _kernel(code) if jit else None
    if kernel is not None:
        return Program(scene, plan, steps, sigma, code,
                       np.array(_params(code, scene, sigma), dtype=float), x0, kernel,
                       kinds, full)
    return Program(scene, plan, steps, sigma, code, _params(code, scene, sigma), x0, code.fn,
                   kinds, full)


def _params(code: _Code, scene: Scene, sigma: dict) -> tuple:
    """The parameters of a program generated from ``scene``'s topology, read from ``scene``:
    its numbers, and the closures (``("sigma", label)``) from ``sigma``."""
    params = tuple(float(sigma[get[1]] if isinstance(get, tuple) else get(scene))
                   for get in code.getters)
    return params if code.derive is None else params + code.derive(params)


def compile_staged(scene: Scene, plan: Plan, steps: tuple[Step, ...], meet) -> "Staged":
    """The staged solver's program for ``plan`` (:func:`polygons.codegen.generate` with
    ``meet``, which draws and intersects the construction lines)."""
    key = ("staged", meet, plan.dyads, steps, tuple(scene.ground), _slot_kinds(scene))
    code = _cached(key, lambda: generate(scene, plan, steps, {}, meet=meet), scene)
    fixed = [None if isinstance(get, tuple) else float(get(scene)) for get in code.getters]
    closures = tuple((i, get[1]) for i, get in enumerate(code.getters) if isinstance(get, tuple))
    positions = tuple((key[1], ij[0], ij[1]) for key, ij in code.index.items() if key[0] == "pos")
    groups = any(getattr(d, "many_closures", False) for d in plan.dyads)
    return Staged(scene, plan, steps, code, fixed, closures, positions, groups)


@dataclass(frozen=True)
class Staged:
    """A scene's staged program: :meth:`record` runs it at the scene's input."""

    scene: Scene
    plan: Plan
    steps: tuple[Step, ...]
    code: _Code
    fixed: list            # the scene's parameters (None where a closure goes)
    closures: tuple        # (parameter index, label of a two-closure dyad)
    positions: tuple = ()  # (label, index of x, index of y) of every point placed
    groups: bool = False   # whether a group has many closures (a triad: its Assur point)

    def record(self, placement) -> tuple:
        """The record at the scene's input, each two-closure dyad on the closure the staged
        assembly (``placement``) took."""
        params = list(self.fixed)
        for i, label in self.closures:
            params[i] = placement.sigmas[label]
        try:
            return self.code.fn(driver_input(self.scene), params)
        except _Fail as f:
            why = self.code.fails[f.args[0]]
            if why[0] == "dyad":
                pos = {k: np.array(v) for k, v in placement.points.items()}
                raise dyad_failure(self.scene, why[1], pos) from None
            raise step_failure(self.scene, self.steps, why) from None

    def placed(self, record: tuple) -> dict:
        """Every point's position in ``record``."""
        return {label: (record[i], record[j]) for label, i, j in self.positions}


def compile_arrays(scene: Scene, plan: Plan, sigma: dict) -> tuple[_Code, tuple]:
    """The same construction generated for (N,) arrays of inputs (every position of a sweep
    chunk at once): the code and this scene's parameters.  Only the vertices, rates and dyad
    margins are computed (the step records' numbers are dropped as dead code); where a dyad
    cannot close the numbers are NaN and its margin negative, as in :mod:`polygons.sweep`."""
    steps = construction(plan, tuple(Diagram))
    key = ("arrays", plan.dyads, steps, tuple(scene.ground), tuple(sorted(sigma)),
           _slot_kinds(scene))
    code = _cached(key, lambda: generate(scene, plan, steps, sigma, arrays=True), scene)
    return code, _params(code, scene, sigma)


def compile_given(scene: Scene, plan: Plan, instruments=None) -> _Code:
    """The construction of both diagrams generated for arrays on the points as given (every
    point a parameter ``("pos", label, 0 | 1)``: placed by each dyad's ``locate``, or the
    space diagram as drawn), every stroke through ``instruments`` when given (the drawing
    board, :mod:`polygons.drawing_board`; its code is not kept)."""
    steps = construction(plan, tuple(Diagram))
    if instruments is not None:
        return generate(scene, plan, steps, {}, arrays=True, instruments=instruments,
                        positions=True)
    key = ("given", plan.dyads, steps, tuple(scene.ground), _slot_kinds(scene))
    return _cached(key, lambda: generate(scene, plan, steps, {}, arrays=True, positions=True),
                   scene)


def given_params(code: _Code, scene, points: dict) -> tuple:
    """The parameters of a :func:`compile_given` program: the points, then the scene's."""
    return tuple(points[get[1]][get[2]] if isinstance(get, tuple) else get(scene)
                 for get in code.getters)


class CompiledSolution:
    """One position's numbers (``record``: a flat tuple of floats) with the step records
    built from it on first access."""

    __slots__ = ("program", "record", "_steps")

    def __init__(self, program: Program, record: tuple):
        self.program = program
        self.record = record

    def position(self, label: str) -> tuple[float, float]:
        i, j = self._at("pos", label)
        return float(self.record[i]), float(self.record[j])

    def _at(self, kind: str, key: str):
        """Where ``kind`` of ``key`` is in the record; an answers-only program's refusal
        naming what it computes where that kind was not asked."""
        try:
            return self.program.code.index[(kind, key)]
        except KeyError:
            outs = self.program.outputs
            if outs is None or kind in outs:
                raise
            raise UnsupportedError(f"this program was compiled for {', '.join(outs)} only, "
                                   f"not {kind}: compile_scene(scene, outputs=...) with "
                                   f"{kind!r} among them") from None

    def velocity(self, label: str) -> tuple[float, float]:
        return self._pair("velocity", label)

    def acceleration(self, label: str) -> tuple[float, float]:
        return self._pair("acceleration", label)

    def _pair(self, d, label):
        if label in self.program.scene.ground:
            return 0.0, 0.0
        i, j = self._at(d, label)
        return float(self.record[i]), float(self.record[j])

    def omega(self, link: str) -> float:
        return float(self.record[self._at("omega", link)])

    def alpha(self, link: str) -> float:
        return float(self.record[self._at("alpha", link)])

    def _stepped(self) -> None:
        """Refuse what only the full program's record holds (the steps, the angles)."""
        outs = self.program.outputs
        if outs is not None:
            raise UnsupportedError(f"this program was compiled for {', '.join(outs)} only: "
                                   f"compile_scene(scene) without outputs gives the steps")

    @property
    def min_intersection_angle_deg(self) -> float | None:
        self._stepped()
        return min_angle(self.program.code.layout, self._floats())

    @property
    def steps(self) -> tuple[Step, ...]:
        """The :class:`Step` records with their numbers and terms (as the staged solver fills
        them), built on first access."""
        try:
            return self._steps
        except AttributeError:
            self._steps = self._build_steps()
            return self._steps

    def _build_steps(self) -> tuple[Step, ...]:
        self._stepped()
        return steps_from_record(self.program.scene, self.program.steps,
                                 self.program.code.layout, self._floats())

    def _floats(self):
        """The record as Python floats (the numba kernel's is a float64 array)."""
        r = self.record
        return r.tolist() if isinstance(r, np.ndarray) else r


def steps_from_record(scene: Scene, steps: tuple[Step, ...], layout, r: tuple
                      ) -> tuple[Step, ...]:
    """The planned ``steps`` with their numbers read from the record ``r`` (``layout`` says
    where): what the staged and the compiled solutions show.  Each record is made once, every
    field set at once (:func:`steps_builder`: the reading written out as straight-line code
    once per layout); its formula with the numbers is written from its terms when shown
    (:func:`polygons.narrate.substitute`)."""
    return steps_builder(layout)(r, steps)


#: the builders written so far, by the id of their layout (kept with it: the id stays its own)
_BUILDERS: dict = {}


def steps_builder(layout):
    """``build(r, steps)``: the :class:`Step` records of ``steps`` with their numbers from the
    record ``r``, written out for ``layout`` once (each term's value, the rounding-noise
    floors, every record set in one go: equal to ``dataclasses.replace``)."""
    hit = _BUILDERS.get(id(layout))
    if hit is not None and hit[0] is layout:
        return hit[1]
    if len(_BUILDERS) >= 256:           # a bound, as the code cache's
        _BUILDERS.clear()
    fn = _write_builder(layout)
    _BUILDERS[id(layout)] = (layout, fn)
    return fn


def _write_builder(layout):
    """The source of :func:`steps_builder`'s function for ``layout``, compiled.  The same
    reading as the loop it replaces: the terms' values (:func:`_term`'s expressions), each
    unit's scale (the largest magnitude of its unit in the construction; an α's counts ω²
    too) and noise floor (:func:`polygons.steps.noise_floor`), a rate at or below its floor
    read as 0.0 — a translating link's ω, a body starting from rest, which the construction
    leaves at ~1e-15 and a book prints as 0."""
    lines = []
    values: list[tuple[str, str]] = []          # (local, unit) of every number a floor sees

    def term(i) -> str:
        if type(i) is int:
            return f"r[{i}]"
        if i[0] == "abs":
            return f"abs(r[{i[1]}])"
        if i[0] == "hypot":
            return f"hypot(r[{i[1]}], r[{i[2]}])"
        r0, r1, q0, q1 = (f"r[{j}]" for j in i[1:])
        n = f"n{len(lines)}"
        lines.append(f"{n} = hypot({r0}, {r1})")
        return f"abs({r0} / {n} * {q1} - {r1} / {n} * {q0})"

    per_step = []
    for k, o in enumerate(layout):
        names = []
        for t, (sym, i, u) in enumerate(o.terms):
            name = f"v{k}_{t}"
            lines.append(f"{name} = {term(i)}")
            names.append((sym, name, u))
            values.append((name, u))
        value = None
        if o.value is not None:
            value = f"w{k}"
            lines.append(f"{value} = r[{o.value}]")
        per_step.append((names, value))
        values.extend([] if value is None else [(value, o.unit)])
    # the scales, in the loop's order (max keeps the first of equals; NaN never wins)
    floor = {}
    for u in _RATES:
        mags = [f"abs({v})" for v, unit in values if unit == u]
        lines.append(f"s{_RATES.index(u)} = max(0.0, {', '.join(mags)})" if mags
                     else f"s{_RATES.index(u)} = 0.0")
    lines.append("s1 = max(s1, s0 ** 2)")               # α's scale: ω² too
    for u in _RATES:
        k = _RATES.index(u)
        floor[u] = f"f{k}"
        lines.append(f"f{k} = noise_floor((s{k},))")

    def zero(v, u) -> str:
        return f"(0.0 if abs({v}) <= {floor[u]} else {v})" if u in floor else v

    lines.append("out = []")
    for k, (o, (names, value)) in enumerate(zip(layout, per_step)):
        f = o.fields
        lines.append(f"d = steps[{k}].__dict__.copy()")
        for key in _FIELDS:
            ij = f.get(key)
            lines.append(f"d[{key!r}] = " + ("None" if ij is None else
                                              f"(r[{ij[0]}], r[{ij[1]}])"))
        lines.append("d['value'] = " + ("None" if value is None else zero(value, o.unit)))
        lines.append(f"d['unit'] = {o.unit!r}")
        lines.append("d['angle_deg'] = " + ("None" if o.angle is None else f"r[{o.angle}]"))
        for t, (sym, name, u) in enumerate(names):
            lines.append(f"t{t} = new(Term); e = t{t}.__dict__; e['symbol'] = {sym!r}; "
                         f"e['value'] = {zero(name, u)}; e['unit'] = {u!r}")
        lines.append(f"d['terms'] = ({''.join(f't{t}, ' for t in range(len(names)))})")
        lines.append("o = new(Step); set_dict(o, '__dict__', d); out.append(o)")
    lines.append("return tuple(out)")
    src = "def _build(r, steps):\n" + "".join(f"    {ln}\n" for ln in lines)
    ns = {"new": object.__new__, "set_dict": object.__setattr__, "Step": Step, "Term": Term,
          "hypot": math.hypot, "noise_floor": noise_floor}
    exec(compile(src, "<polygons.compiled steps>", "exec"), ns)
    return ns["_build"]


#: the units whose near-zero values are rounding noise of the construction
_RATES = ("rad/s", "rad/s^2", "m/s", "m/s^2")


def min_angle(layout, r: tuple) -> float | None:
    """The smallest angle between two intersected construction lines (degrees), or None."""
    angles = [r[o.angle] for o in layout if o.angle is not None]
    return min(angles) if angles else None
