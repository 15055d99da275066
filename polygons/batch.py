"""Many variants of one scene solved at once: design studies, exam variants, synthesis loops.

``solve_many(scene, AB=lengths, theta=angles, ...)`` gives any scene quantity an array of
values and solves every row (or, with ``grid=True``, every combination) in one vectorised
pass: the step program generated for arrays (:mod:`polygons.codegen`) runs on (N,) columns,
as in a sweep.  The quantities, by name (SI units):

* a link's name (``AB``): its length in m;
* ``<G>_x`` / ``<G>_y`` for a fixed point ``G``: its coordinates in m;
* ``theta`` (a crank's angle, rad) or ``s`` (an input slider's position along its guide, m);
* ``omega`` / ``alpha`` (a crank's rates, rad/s and rad/s², CCW positive) or ``velocity`` /
  ``acceleration`` (an input slider's, m/s and m/s²).

Names that are not Python identifiers can be given in the ``values`` mapping.  Every
two-closure dyad takes, in every row, the closure the scene's own assembly takes (the same side
of its base line).  A row that cannot be solved — the links cannot close, two construction
lines are parallel (a toggle), a length is not positive — is reported in
:attr:`Batch.errors` (which row, which dyad or step, why) and its numbers are NaN; a bad row
never stops the others.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Mapping

import numpy as np

from .errors import PolygonsError, UnitError, UnknownLabelError, show, suggest
from .plan import construction, make_plan
from .scene import MIN_LENGTH, Crank, Scene, link_length_ok
from .steps import Diagram
from .units import LIMITS, SI_UNIT
from .sweep import compile_plan

#: the staged solver's threshold (polygons.geometry.PARALLEL_DEG)
_TAN_PARALLEL = math.tan(math.radians(1e-5))


@dataclass(frozen=True)
class RowError:
    """Row ``row`` could not be solved: ``where`` names the dyad's point or the step
    ('velocity 3 (b)'), ``reason`` says why in words."""
    row: int
    where: str
    reason: str


class Batch:
    """The solved rows.  ``inputs``: quantity → (N,) values of each row; ``shape``: (N,) or
    the grid's shape (row i is ``np.unravel_index(i, shape)``); ``ok``: (N,) rows solved.
    Accessors return (N, 2) vectors or (N,) scalars, NaN in failed rows."""

    def __init__(self, scene, plan, inputs, shape, pos, kernel, links, failures, angle):
        self.scene = scene
        self.plan = plan
        self.inputs = inputs
        self.shape = shape
        self._pos = pos
        self._k = kernel
        self._links = links
        self._fail = failures            # (N,) int: 0 ok, else 1 + index into _where
        self.ok = failures == 0
        self.angle_deg = angle           # smallest construction angle per row (deg)

    @property
    def n(self) -> int:
        return int(self.ok.shape[0])

    def _pair(self, xy) -> np.ndarray:
        out = np.empty((self.n, 2))
        out[:, 0] = xy[0]
        out[:, 1] = xy[1]
        out[~self.ok] = np.nan
        return out

    def position(self, label: str) -> np.ndarray:
        return self._pair(self._pos[self._known(label, self._pos)])

    def velocity(self, label: str) -> np.ndarray:
        return self._pair(self._k.of(Diagram.VELOCITY, self._known(label, self._pos)))

    def acceleration(self, label: str) -> np.ndarray:
        return self._pair(self._k.of(Diagram.ACCELERATION, self._known(label, self._pos)))

    def omega(self, link: str) -> np.ndarray:
        return self._scalar(self._links[0][self._known(link, self._links[0])])

    def alpha(self, link: str) -> np.ndarray:
        return self._scalar(self._links[1][self._known(link, self._links[1])])

    def _scalar(self, v) -> np.ndarray:
        out = np.array(np.broadcast_to(v, (self.n,)), dtype=float)
        out[~self.ok] = np.nan
        return out

    def _known(self, name, table):
        if not isinstance(name, str) or name not in table:
            raise UnknownLabelError(f"unknown name {show(name)}: {suggest(str(name), table)}",
                                    file=self.scene.file)
        return name

    @cached_property
    def errors(self) -> tuple[RowError, ...]:
        """One :class:`RowError` per failed row (the first failure in construction order)."""
        out = []
        for i in np.flatnonzero(~self.ok):
            where, why = self._where[int(self._fail[i]) - 1]
            out.append(RowError(int(i), where, why(int(i)) if callable(why) else why))
        return tuple(out)


def solve_many(scene: Scene, values: Mapping[str, object] | None = None, *,
               grid: bool = False, engine: str = "compiled", **arrays) -> Batch:
    """Solve ``scene`` once per row of the given quantities (see the module docstring), or
    for every combination of them with ``grid=True``; scalars broadcast.  ``engine``:
    'compiled' (the construction compiled for arrays, :mod:`polygons.compiled`) or 'located'
    (the points placed by each dyad's numpy ``locate``, then the step program for arrays on
    them): the same numbers to rounding."""
    if not isinstance(scene, Scene):
        raise PolygonsError(f"solve_many: expected a Scene (polygons.load(...)), got "
                            f"{type(scene).__name__}", file="<api>")
    if engine not in ("compiled", "located"):
        raise PolygonsError(f"solve_many: engine must be 'compiled' or 'located', got "
                            f"{show(engine)}", file=scene.file)
    if values is not None and not isinstance(values, Mapping):
        raise PolygonsError(f"solve_many: values must be a mapping of quantity → values, got "
                            f"{type(values).__name__}", file=scene.file)
    given = dict(values or {})
    given.update(arrays)
    names = _quantities(scene)
    cols = {}
    for name, v in given.items():
        if name not in names:
            raise UnknownLabelError(f"cannot vary {show(name)}: {suggest(name, names)} (a "
                                    f"link's length by its name, a fixed point's G_x / G_y, the "
                                    f"input {', '.join(n for n in names if n in _DRIVER_NAMES)})",
                                    file=scene.file)
        cols[name] = _column(scene, name, v)
    if grid:
        shape = tuple(np.atleast_1d(a).shape[0] for a in cols.values())
        if math.prod(shape) > MAX_ROWS:
            raise PolygonsError(f"{' × '.join(f'{k:,}' for k in shape)} = "
                                f"{math.prod(shape):,} combinations: a batch solves at most "
                                f"{MAX_ROWS:,} rows", file=scene.file)
        mesh = np.meshgrid(*(np.atleast_1d(a) for a in cols.values()), indexing="ij")
        cols = {k: m.reshape(-1) for k, m in zip(cols, mesh)}
    else:
        try:
            b = np.broadcast_arrays(*cols.values()) if cols else []
        except ValueError:
            raise PolygonsError("the arrays have different lengths: "
                                + ", ".join(f"{k} {np.shape(a)}" for k, a in cols.items())
                                + " (give equal lengths, or grid=True / --grid for every "
                                  "combination)",
                                file=scene.file) from None
        cols = {k: np.atleast_1d(v) for k, v in zip(cols, b)}
        shape = (next(iter(cols.values())).shape[0],) if cols else (1,)
        if shape[0] > MAX_ROWS:
            raise PolygonsError(f"{shape[0]:,} rows: a batch solves at most {MAX_ROWS:,}",
                                file=scene.file)
    n = int(np.prod(shape))
    solve = {"compiled": _solve_compiled, "located": _solve_located}[engine]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return solve(scene, cols, shape, n)


_DRIVER_NAMES = ("theta", "s", "omega", "alpha", "velocity", "acceleration")
#: the most rows one batch solves (about 1 kB of memory a row for a six-bar), checked before
#: any array is made: the same bound for solve_many and ``polygons sweep --vary``
MAX_ROWS = 1_000_000
#: the dimension of each driver quantity (any other name is a length: a link, G_x, G_y)
_DIMENSION = {"theta": "angle", "omega": "angular_velocity", "alpha": "angular_acceleration",
              "s": "length", "velocity": "velocity", "acceleration": "acceleration"}


def _column(scene: Scene, name: str, v) -> np.ndarray:
    """The values of ``name`` as a float array, refused (one line) unless they are numbers
    within the scene file's domain limits (:data:`polygons.units.LIMITS`), at most MAX_ROWS."""
    size = getattr(v, "size", None)
    if size is None:
        size = len(v) if isinstance(v, (list, tuple)) else 1
    if size > MAX_ROWS:
        raise PolygonsError(f"{name}: {size:,} values: a batch solves at most {MAX_ROWS:,} "
                            f"rows", file=scene.file, where=name)
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise PolygonsError(f"expected numbers (SI units), got {show(v)}",
                            file=scene.file, where=name) from None
    if a.ndim > 1:
        raise PolygonsError(f"expected a 1-D array of values, got shape {a.shape}",
                            file=scene.file, where=name)
    if a.size > MAX_ROWS:
        raise PolygonsError(f"{name}: {a.size:,} values: a batch solves at most {MAX_ROWS:,} "
                            f"rows", file=scene.file, where=name)
    dim = _DIMENSION.get(name, "length")
    low, high = LIMITS[dim]
    with np.errstate(invalid="ignore"):
        mag = np.abs(a)
        bad = ~np.isfinite(a) | (mag > high) | ((a != 0) & (mag < low))
    if bad.any():
        i = int(np.flatnonzero(np.atleast_1d(bad))[0])
        shown = f"{high * 180 / math.pi:g} deg" if dim == "angle" else \
            f"{high:g} {SI_UNIT.get(dim, '')}".rstrip()
        raise UnitError(f"value {float(np.atleast_1d(a)[i])!r} (row {i}) is outside "
                        f"the domain: finite and at most {shown} in magnitude, as in a scene "
                        f"file", file=scene.file, where=name)
    return a


def _quantities(scene: Scene) -> list[str]:
    names = list(scene.links)
    for g in scene.ground:
        names += [f"{g}_x", f"{g}_y"]
    names += (["theta", "omega", "alpha"] if isinstance(scene.driver, Crank)
              else ["s", "velocity", "acceleration"])
    return names


def _varied_scene(scene: Scene, cols: dict, n: int) -> tuple[Scene, np.ndarray]:
    """The scene with array values (each (N,)) in place of the varied quantities, and the
    driver input of every row."""
    full = lambda a: np.broadcast_to(a, (n,))  # noqa: E731
    links = {k: (replace(l, length=full(cols[k])) if k in cols else l)
             for k, l in scene.links.items()}
    ground = {}
    for g, (x, y) in scene.ground.items():
        ground[g] = (full(cols[f"{g}_x"]) if f"{g}_x" in cols else x,
                     full(cols[f"{g}_y"]) if f"{g}_y" in cols else y)
    drv = scene.driver
    if isinstance(drv, Crank):
        drv = replace(drv, omega=full(cols["omega"]) if "omega" in cols else drv.omega,
                      alpha=full(cols["alpha"]) if "alpha" in cols else drv.alpha)
        x = full(cols["theta"]) if "theta" in cols else np.full(n, drv.angle)
    else:
        drv = replace(drv, velocity=full(cols["velocity"]) if "velocity" in cols
                      else drv.velocity,
                      acceleration=full(cols["acceleration"]) if "acceleration" in cols
                      else drv.acceleration)
        x = full(cols["s"]) if "s" in cols else np.full(n, drv.position)
    return replace(scene, links=links, ground=ground, driver=drv), np.asarray(x, dtype=float)


def _row_scene(scene: Scene, cols: dict, i: int) -> Scene:
    one = {k: v[i:i + 1] for k, v in cols.items()}
    vs, x = _varied_scene(scene, one, 1)
    links = {k: replace(l, length=None if l.length is None else float(np.ravel(l.length)[0]))
             for k, l in vs.links.items()}
    ground = {g: (float(np.ravel(a)[0]), float(np.ravel(b)[0])) for g, (a, b) in vs.ground.items()}
    return replace(vs, links=links, ground=ground), float(x[0])


_PREPARED: dict = {}


def prepare(scene: Scene):
    """(plan, sweep program, step program) of ``scene``, made once per scene object: the
    closures of the scene's own assembly, which every row follows."""
    hit = _PREPARED.get(id(scene))
    if hit is not None and hit[0] is scene:
        return hit[1:]
    plan = make_plan(scene)
    prog = compile_plan(scene, plan)
    steps = construction(plan)
    if len(_PREPARED) > 64:
        _PREPARED.clear()
    _PREPARED[id(scene)] = (scene, plan, prog, steps)
    return plan, prog, steps


class _Polygons:
    """The polygon vertices of every row (``of(diagram, label)``)."""

    def __init__(self, vx):
        self.vx = vx

    def of(self, diagram, label):
        return self.vx[(str(diagram), label)]


def _solve_compiled(scene: Scene, cols: dict, shape, n: int) -> Batch:
    """The rows by the construction compiled for arrays (:func:`polygons.compiled.
    compile_arrays`), the varied quantities passed as (N,) parameters."""
    from .compiled import compile_arrays
    plan, prog, steps = prepare(scene)
    vs, x = _varied_scene(scene, cols, n)
    fail, where, mark = _failures(scene, cols, n)
    code, _ = compile_arrays(scene, plan, dict(prog.sigma))
    params = tuple(prog.sigma[g[1]] if isinstance(g, tuple) else g(vs) for g in code.getters)
    idx = code.index
    r = code.fn(x, params)
    full = lambda v: np.broadcast_to(v, (n,))  # noqa: E731
    pos = {label: np.array([full(r[ij[0]]), full(r[ij[1]])])
           for (key, label), ij in idx.items() if key == "pos"}
    for i, d in zip(idx[("margins", "")], idx[("margin_of", "")]):
        m = full(r[i])
        mark(~(m >= 0) if d.two_closures else ~(m > 0),
             getattr(d, "lever", None) or d.placed[0], _why_not(scene, cols, d))
    return _read(scene, plan, prog, steps, cols, shape, n, idx, r, pos, fail, where, mark)


def _solve_located(scene: Scene, cols: dict, shape, n: int) -> Batch:
    """The rows placed by each dyad's ``locate`` on (2, N) arrays (its numpy form, not the
    generated one), then the step program for arrays run on those points
    (:func:`polygons.compiled.compile_given`)."""
    from .compiled import compile_given, given_params
    plan, prog, steps = prepare(scene)
    vs, x = _varied_scene(scene, cols, n)
    fail, where, mark = _failures(scene, cols, n)
    pos = {}
    for g, (gx, gy) in vs.ground.items():
        pos[g] = np.array([np.broadcast_to(gx, (n,)), np.broadcast_to(gy, (n,))], dtype=float)
    for d in plan.dyads:
        sig = ({k: prog.sigma[k] for k in d.sigma_keys} if getattr(d, "many_closures", False)
               else prog.sigma.get(d.placed[0]))
        pts, m = d.locate(vs, pos, sig, x)
        pos.update({k: np.broadcast_to(v, (2, n)) for k, v in pts.items()})
        if m is not None:
            m = np.broadcast_to(m, (n,))
            bad = ~(m >= 0) if d.two_closures else ~(m > 0)
            mark(bad, getattr(d, "lever", None) or d.placed[0], _why_not(scene, cols, d))
    code = compile_given(scene, plan)
    r = code.fn(x, given_params(code, vs, pos))
    return _read(scene, plan, prog, steps, cols, shape, n, code.index, r, pos, fail, where,
                 mark)


def _read(scene, plan, prog, steps, cols, shape, n, idx, r, pos, fail, where, mark) -> Batch:
    """The batch from an arrays program's record ``r``: polygon vertices, rates, and the
    conditioning (the staged solver's angle between the lines, atan2(|u × v|, |u · v|), from
    the pair with the smallest ratio; rows below PARALLEL_DEG marked as toggles)."""
    full = lambda v: np.broadcast_to(v, (n,))  # noqa: E731
    vx = {(key, label): np.array([full(r[ij[0]]), full(r[ij[1]])])
          for (key, label), ij in idx.items() if key in ("velocity", "acceleration")}
    cmin = dmin = None
    for i, j, s in idx[("crossings", "")]:
        c, d = np.abs(full(r[i])), np.abs(full(r[j]))
        if cmin is None:
            cmin, dmin = c, d
        else:
            lower = c * dmin < cmin * d
            cmin, dmin = np.where(lower, c, cmin), np.where(lower, d, dmin)
        mark(~(c >= _TAN_PARALLEL * d), f"{s.diagram} {s.number} ({s.draws})",
             _parallel(steps, s))
    W = {name: full(r[i]) for (key, name), i in idx.items() if key == "omega"}
    AL = {name: full(r[i]) for (key, name), i in idx.items() if key == "alpha"}
    return _finish(scene, plan, prog, cols, shape, n, pos, _Polygons(vx), W, AL, fail, where,
                   cmin, dmin)


def _failures(scene, cols, n):
    fail = np.zeros(n, dtype=np.int64)
    where: list = []

    def mark(bad, label, why):
        new = bad & (fail == 0)
        if new.any():
            where.append((label, why))
            fail[new] = len(where)

    for name, a in cols.items():
        if name in scene.links:
            a = np.broadcast_to(a, (n,))
            mark(~(a > 0), name, f"the length of {name} must be positive")
            # the scene file's rule (scene.link_length_ok): 5e-324 m is refused as in [links]
            mark(~link_length_ok(a), name, f"the length of {name} is too small to compute "
                                           f"with: a link must be at least {MIN_LENGTH:g} m long")
    return fail, where, mark


def _parallel(steps, s):
    return lambda i: (f"the {_draws(steps, s.diagram, s.lines[0])} and the "
                      f"{_draws(steps, s.diagram, s.lines[1])} are parallel: the mechanism is "
                      f"at a toggle or change point")


def _finish(scene, plan, prog, cols, shape, n, pos, k, W, AL, fail, where, cmin, dmin):
    from .theorems import angular_acceleration, angular_velocity
    for name, a, b in prog.links:
        if name in W or a not in pos or b not in pos:
            continue
        r = pos[b] - pos[a]
        W[name] = angular_velocity(r, _rel(k, Diagram.VELOCITY, b, a, n))
        AL[name] = angular_acceleration(r, _rel(k, Diagram.ACCELERATION, b, a, n))
    angle = np.degrees(np.arctan2(cmin, dmin)) if cmin is not None else np.full(n, np.nan)
    angle[fail != 0] = np.nan
    batch = Batch(scene, plan, {kk: np.broadcast_to(v, (n,)) for kk, v in cols.items()}, shape,
                  pos, k, (W, AL), fail, angle)
    batch._where = where
    return batch


def _rel(k, d, b, a, n):
    return (np.broadcast_to(k.of(d, b), (2, n)) if k.of(d, b).ndim > 1 else
            np.broadcast_to(np.reshape(k.of(d, b), (2, 1)), (2, n))) - \
        (np.broadcast_to(k.of(d, a), (2, n)) if k.of(d, a).ndim > 1 else
         np.broadcast_to(np.reshape(k.of(d, a), (2, 1)), (2, n)))


def _draws(steps, diagram, number) -> str:
    for s in steps:
        if s.diagram == diagram and s.number == number:
            return s.draws
    return "line"


def _why_not(scene, cols, dyad):
    """The dyad's own sentence, for one failed row (evaluated only when asked)."""
    def why(i: int) -> str:
        row, x = _row_scene(scene, cols, i)
        plan = make_plan(row)
        prog_sigma = prepare(scene)[1].sigma
        pos = {g: np.array(v, dtype=float) for g, v in row.ground.items()}
        for d in plan.dyads:
            if d == dyad:
                return d.why_not(row, pos)
            pts, _ = d.locate(row, pos, prog_sigma.get(d.placed[0]), x)
            pos.update(pts)
        return "cannot be placed"
    return why
