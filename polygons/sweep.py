"""Full-cycle sweeps: every position of the input solved at once, vectorised with numpy.

The staged constructor (:mod:`polygons.evaluate`) draws one position at a time, stroke by
stroke.  A sweep asks the same questions for thousands of input angles, so here the same
:class:`~polygons.plan.Plan` dyads are evaluated on whole arrays, one numpy expression per
dyad, with no Python loop over positions.  Each dyad's closed form is the algebra of its
construction:

* crank ``PX``:        v = ω × PX,  a = α × PX − ω² PX
* RRR ``P–X–Q``:       v_x = v_p + ω_p × PX = v_q + ω_q × QX, solved for (ω_p, ω_q) by the
  same two perpendicular lines the polygon intersects (their determinant is
  ``PX × QX``, zero at a toggle); the accelerations likewise with the centripetal
  terms known
* RRP ``P–X`` + guide: v_x = v_p + ω × PX along the guide (determinant ``PX · e``)
* RPR slotted lever:   ω = (BA × v_A)/BA², sliding ṡ = e·v_A, α with the Coriolis 2ωṡ
* RPP Scotch yoke:     the yoke point on the guide, v and a along the guide (no rotation)
* image points:        v = v_p + ω × PX, a = a_p + α × PX − ω² PX

The branch of every two-closure dyad is taken from the staged assembly at the scene's own
input (the scene's words) and then *followed continuously*: the sign σ of the chosen
closure relative to its base line is kept, which is continuity as long as the closure
discriminant stays positive.  Where it reaches zero the mechanism is at a toggle: the
reachable range ends there (a limit position) or, if the discriminant only touches zero, the
branches meet (a change point); both are reported in :attr:`Sweep.limits`, never crossed
silently.

This module must not import shapely (``polygons.geometry`` is the only shapely importer);
the two angle thresholds below are the same numbers as there (a test checks it).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Callable, Iterable, Mapping, Sequence

import numpy as np

from .dyads.base import size_of
from .harmonic import Harmonic, harmonic  # noqa: F401  (re-exported: the SHM comparison)
from .errors import ConstructionError, PolygonsError, show
from .plan import Plan, construction, make_plan
from .position import assemble, driver_input
from .scene import Crank, Scene
from .steps import Diagram, Step
from .theorems import angular_acceleration, angular_velocity
from .memo import memo_of
from .sweep_store import adopt, allocate, store
from .sweep_follow import (_assur_rows, _groups, _margin_fn, _refined, _take,  # noqa: F401
                           _referenced, anchored)

# the range of the input, its limits and toggles (the thresholds, Limit), split out:
# re-exported for the callers (streams, the page, conditions)
from .sweep_range import (PARALLEL_DEG, PROBE, WARN_DEG, Limit, _SIN_PARALLEL,  # noqa: F401
                          golden_min)
from .sweep_range import find_range as _find_range

#: default chunk of positions evaluated per numpy pass (memory and cache friendly)
CHUNK = 1 << 14


# ---------------------------------------------------------------- results
@dataclass
class Sweep:
    """All positions of one sweep, SI units.

    ``pos``, ``vel``, ``acc``: label -> array (2, N) (x row, y row);  ``omega``, ``alpha``:
    link name -> array (N,);  ``slide_v``/``slide_a``: slider or pin label -> array (N,)
    (signed along the guide, or along the slot away from the lever pivot);  ``travel``: slider
    label -> position along its guide from its ``through`` point;  ``angle_deg``: the smallest
    intersection angle of the construction at each position (its conditioning).
    """

    scene: Scene
    plan: Plan
    input_kind: str                 # 'crank' | 'slider'
    inputs: np.ndarray              # θ (rad) or s (m), shape (N,)
    omega_in: float                 # input rate (rad/s or m/s)
    alpha_in: float
    full_cycle: bool
    range: tuple[float, float]      # reachable range (closed), in input units
    limits: tuple[Limit, ...]
    segments: tuple[tuple[int, int], ...]   # [start, stop) index ranges between toggles
    branches: Mapping[str, int]     # label -> σ (+1 / −1) followed over the sweep
    pos: dict
    vel: dict
    acc: dict
    omega: dict
    alpha: dict
    slide_v: dict
    slide_a: dict
    travel: dict
    coriolis: dict
    margin: np.ndarray              # sine of the smallest intersection angle, per position
    warnings: tuple[str, ...] = ()

    @cached_property
    def angle_deg(self) -> np.ndarray:
        """The smallest intersection angle of the construction at each position (degrees):
        its conditioning (NaN where the mechanism cannot be assembled)."""
        with np.errstate(invalid="ignore"):
            return np.degrees(np.arcsin(np.where(self.margin >= 0,
                                                 np.minimum(self.margin, 1.0), np.nan)))

    @property
    def n(self) -> int:
        return int(self.inputs.shape[0])

    def position(self, label: str) -> np.ndarray:
        """(N, 2) positions of ``label``."""
        return _as_n2(self.pos[self._known(label)], self.n)

    def velocity(self, label: str) -> np.ndarray:
        return _as_n2(self.vel[self._known(label)], self.n)

    def acceleration(self, label: str) -> np.ndarray:
        return _as_n2(self.acc[self._known(label)], self.n)

    def scene_at(self, i: int) -> Scene:
        """The scene restated at the sweep's ``i``-th input, each followed closure pinned
        'near' where the sweep put it (so a staged solve there takes the same assembly)."""
        from dataclasses import replace
        from .scene import Branch
        asm = {lab: Branch(lab, f"{lab} as followed from the scene's instant", "near",
                           near=(float(self.pos[lab][0][i]), float(self.pos[lab][1][i])))
               for lab in self.branches}
        drv = self.scene.driver
        x = float(self.inputs[i])
        drv = replace(drv, angle=x) if isinstance(drv, Crank) else replace(drv, position=x)
        return replace(self.scene, driver=drv, assembly=asm)

    def _known(self, label) -> str:
        """``label`` if the sweep solved it, else a one-line UnknownLabelError."""
        if isinstance(label, str) and label in self.pos:
            return label
        from .errors import UnknownLabelError, suggest
        raise UnknownLabelError(f"unknown point {show(label)}: {suggest(str(label), self.pos)}",
                                file=self.scene.file)


def _as_n2(xy, n: int) -> np.ndarray:
    if xy is None:
        return np.zeros((n, 2))
    x, y = xy
    out = np.empty((n, 2))
    out[:, 0] = x
    out[:, 1] = y
    return out


# ---------------------------------------------------------------- the program
@dataclass(frozen=True)
class Program:
    """The plan's dyads with the closure of every two-closure dyad taken from the staged
    assembly at the scene's own input, and the step program of both diagrams."""

    scene: Scene
    plan: Plan
    steps: tuple[Step, ...]
    sigma: Mapping[str, float]                # label -> closure followed (+1 / −1)
    ground: Mapping[str, tuple[float, float]]
    input_kind: str
    input0: float
    rate: float
    rate2: float
    links: tuple[tuple[str, str, str], ...]   # (name, a, b) of every link to report
    scale: float

    @property
    def branches(self) -> Mapping[str, int]:
        """label -> σ of each two-closure dyad; a group of several closures (a triad's, kept
        as 'B#bx' ... in ``sigma`` and followed by continuation) -> 0 under the corner the
        scene's [assembly] names (else its first)."""
        out = {k: int(v) for k, v in self.sigma.items() if "#" not in k}
        for d in self.plan.dyads:
            if getattr(d, "many_closures", False):
                named = [k for k in d.placed[:3] if k in self.scene.assembly] or [d.placed[0]]
                out[named[0]] = 0
        return out


def compile_plan(scene: Scene, plan: Plan | None = None) -> Program:
    """Plan once, and take each two-closure branch from the staged assembly at the scene's own
    input (raises the staged :class:`AssemblyError` / ``BranchError`` if the scene itself
    cannot be assembled)."""
    plan = plan or make_plan(scene)
    placement = assemble(plan)
    pos0 = {k: np.array(v) for k, v in placement.points.items()}
    sigma: dict[str, float] = {}
    for d in plan.dyads:
        if d.two_closures:
            x = d.placed[0]
            with np.errstate(all="ignore"):
                c1, m1 = d.locate(scene, pos0, 1.0, driver_input(scene))
                c2, _ = d.locate(scene, pos0, -1.0, driver_input(scene))
            if float(np.hypot(*(c1[x] - c2[x]))) <= 1e-12 * size_of(scene) or not m1 > 0:
                raise ConstructionError(
                    f"the scene's own position is a toggle for {x} ({d.toggle_reason(scene, pos0)}"
                    f"): the two closures coincide, so there is no branch to follow; state the "
                    f"scene at another input", file=scene.file, where=x)
            sigma[x] = placement.sigmas[x]      # the closure the assembly took
        elif getattr(d, "many_closures", False):     # a triad: the closure's corners
            sigma.update({k: placement.sigmas[k] for k in d.sigma_keys})
    drv = scene.driver
    if isinstance(drv, Crank):
        kind, x0, rate, rate2 = "crank", drv.angle, drv.omega, drv.alpha
    else:
        kind, x0, rate, rate2 = "slider", drv.position, drv.velocity, drv.acceleration
    links = [(b.name, b.a, b.b) for b in scene.model.bodies if b.kind in ("link", "lever")]
    ground = {k: (float(v[0]), float(v[1])) for k, v in scene.ground.items()}
    return Program(scene, plan, construction(plan, tuple(Diagram)), sigma, ground, kind,
                   float(x0), float(rate), float(rate2), tuple(links), size_of(scene))


# ---------------------------------------------------------------- vectorised evaluation
def evaluate(prog: Program, inputs, *, rates: bool = True, jit: bool = False,
             out: np.ndarray | None = None) -> dict:
    """Solve every position in ``inputs`` (θ in rad or s in m) at once.

    Returns a dict with ``pos``, ``vel``, ``acc`` (label -> (x, y) arrays, ``None`` for a
    fixed point's velocity/acceleration), ``omega``, ``alpha``, ``slide_v``, ``slide_a``,
    ``travel``, ``coriolis`` and ``margin`` (the sine of the smallest intersection angle of
    the construction; negative where a dyad cannot close, NaN downstream of that).
    """
    t = np.asarray(inputs, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        if rates and jit:
            code, params = arrays_program(prog)
            return from_arrays(prog, code, params, t, kernel_of(prog), out)
        return _evaluate(prog, t, rates)


def place(prog: Program, t: np.ndarray):
    """Every point at the inputs ``t`` (each dyad's ``locate`` on arrays), and each dyad's
    margin: ``(pos, [(dyad, margin), ...])``."""
    scene = prog.scene
    pos = {k: np.array(v).reshape((2,) + (1,) * np.ndim(t)) for k, v in prog.ground.items()}
    margins = []
    for d in prog.plan.dyads:
        sigma = ({k: prog.sigma[k] for k in d.sigma_keys}       # a triad: its closure's corners
                 if getattr(d, "many_closures", False) else prog.sigma.get(d.placed[0]))
        pts, m = d.locate(scene, pos, sigma, t)
        pos.update(pts)
        if m is not None:
            margins.append((d, m))
    return pos, margins


def _evaluate(prog: Program, t: np.ndarray, rates: bool) -> dict:
    if rates:
        code, params = arrays_program(prog)
        return from_arrays(prog, code, params, t)
    scene = prog.scene
    n = t.shape
    pos, margins = place(prog, t)
    margin = np.ones(n)
    for _, m in margins:
        margin = np.minimum(margin, m)
    P = {k: (v[0], v[1]) if k not in prog.ground else prog.ground[k] for k, v in pos.items()}
    travel = {}
    for label, g in scene.model.guide.items():
        if label in pos and label not in prog.ground:
            e, through = g.line.direction, g.line.through
            travel[label] = ((pos[label][0] - through[0]) * e[0]
                             + (pos[label][1] - through[1]) * e[1])
    return {"pos": P, "travel": travel, "margin": margin}


def arrays_program(prog: Program):
    """The construction of ``prog`` generated for (N,) arrays of inputs (:mod:`polygons.codegen`
    via :func:`polygons.compiled.compile_arrays`) and the scene's parameters: made once per
    program and kept with it."""
    memo = memo_of(prog)
    if "_arrays" not in memo:
        from .compiled import compile_arrays
        memo["_arrays"] = compile_arrays(prog.scene, prog.plan, dict(prog.sigma))
    return memo["_arrays"]


def kernel_of(prog: Program):
    """The arrays program compiled by numba (:func:`polygons.jit.sweep_kernel`) with its
    parameters as an array, made once per program: ``(kernel, params)``, or None where numba
    is not installed or cannot compile this construction."""
    memo = memo_of(prog)
    if "_jit" not in memo:
        from . import jit
        code, params = arrays_program(prog)
        kernel = jit.cached(code, jit.sweep_kernel)
        memo["_jit"] = None if kernel is None else (kernel, np.array(params, dtype=float))
    return memo["_jit"]


#: bytes of a pass's record (one row of N floats per output of the generated code)
CHUNK_BYTES = {False: 1 << 22, True: 1 << 22}
#: the fewest positions a pass takes (numpy, numba)
CHUNK_FLOOR = {False: 4096, True: 1024}


def chunk_for(prog: Program, jit: bool = False) -> int:
    """Positions per pass, from the program's size: a pass's record kept within
    :data:`CHUNK_BYTES` (numpy, whose temporaries are as many again; a numba kernel, which
    makes none), so that it stays in the caches: at most 4 :data:`CHUNK`, at least
    :data:`CHUNK_FLOOR` (numpy's cost per call outweighs the caches below 4096 positions:
    twice the rate at N = 32 dyads)."""
    return int(min(4 * CHUNK, max(CHUNK_FLOOR[bool(jit)],
                                  CHUNK_BYTES[bool(jit)] // 8 // _rows(prog))))


def from_arrays(prog: Program, code, params, xs: np.ndarray, kernel=None, out=None) -> dict:
    """:func:`evaluate`'s results at the inputs ``xs``: the arrays program run once, its flat
    record read into positions, polygon vertices, rates, slides and the dyads' margin
    (``kernel``: the same program compiled by numba, :func:`kernel_of`, writing into ``out``
    when given: a buffer of its rows that the caller reuses, so the results are views of it
    until the next pass)."""
    idx = code.index
    scene = prog.scene
    n = xs.shape
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        full = lambda v: v if type(v) is np.ndarray else np.broadcast_to(v, n)  # noqa: E731
        if kernel is not None and xs.ndim == 1:
            r, O = kernel[0].record(np.ascontiguousarray(xs), kernel[1], out)
            rows = kernel[0].rows

            def pair(ij):   # a (2, N) view of the kernel's rows where they are adjacent
                a, b = rows[ij[0]], rows[ij[1]]
                if a is not None and b == a + 1:
                    return O[a:a + 2]
                return np.array([full(r[ij[0]]), full(r[ij[1]])])
        else:
            r = code.fn(xs, params)

            def pair(ij):
                return (full(r[ij[0]]), full(r[ij[1]]))
        P, V, A = {}, {}, {}
        pos = {}
        for (key, label), ij in idx.items():
            if key == "pos":
                if label in prog.ground:
                    P[label] = prog.ground[label]
                    pos[label] = np.array([full(r[ij[0]]), full(r[ij[1]])])
                else:
                    P[label] = pair(ij)
                    pos[label] = np.asarray(P[label])
        for label in pos:
            if label in prog.ground:
                V[label] = A[label] = None
                continue
            V[label] = pair(idx[("velocity", label)])
            A[label] = pair(idx[("acceleration", label)])
        W = {k: full(r[i]) if np.ndim(r[i]) else r[i] for (key, k), i in idx.items()
             if key == "omega"}
        AL = {k: full(r[i]) if np.ndim(r[i]) else r[i] for (key, k), i in idx.items()
              if key == "alpha"}
        for name, a, b in prog.links:
            if name in W or a not in pos or b not in pos:
                continue
            rr = pos[b] - pos[a]
            W[name] = angular_velocity(rr, _diff(V[b], V[a]))
            AL[name] = angular_acceleration(rr, _diff(A[b], A[a]))
        travel, SV, SA = {}, {}, {}
        for label, g in scene.model.guide.items():
            if label in pos and label not in prog.ground:
                e, through = g.line.direction, g.line.through
                travel[label] = ((pos[label][0] - through[0]) * e[0]
                                 + (pos[label][1] - through[1]) * e[1])
                SV[label] = V[label][0] * e[0] + V[label][1] * e[1]
                SA[label] = A[label][0] * e[0] + A[label][1] * e[1]
        for (key, k), i in idx.items():
            if key == "slide_v":
                SV[k] = full(r[i])
            elif key == "slide_a":
                SA[k] = full(r[i])
        COR = {k: pair(ij) for (key, k), ij in idx.items() if key == "coriolis"}
        margin = np.ones(n)
        for i in idx[("margins", "")]:
            margin = np.minimum(margin, r[i])
    return {"pos": P, "travel": travel, "margin": margin, "vel": V, "acc": A, "omega": W,
            "alpha": AL, "slide_v": SV, "slide_a": SA, "coriolis": COR}




def _col(v, n):
    return v if np.ndim(v) > 1 else np.reshape(v, (2,) + (1,) * len(n))


def _diff(b, a):
    """b − a for (x, y) pairs where ``None`` is the zero vector."""
    if b is None and a is None:
        return np.zeros(2)
    if a is None:
        return np.array(b)
    if b is None:
        return -np.array(a)
    return np.array(b) - np.array(a)


def find_range(prog: Program, probe: int = PROBE):
    """(full_cycle, (lo, hi), limits, events) for the scene's input
    (:func:`polygons.sweep_range.find_range`, with this module's evaluation)."""
    return _find_range(prog, probe, evaluate=evaluate, place=place)



# ---------------------------------------------------------------- the sweep
def _check_sweep_args(scene, steps, inputs, chunk):
    """The arguments of :func:`sweep` refused (one line) as the scene's ``[sweep] steps`` is:
    ``steps`` a whole number from 2 to MAX_STEPS, ``inputs`` at most MAX_STEPS finite
    numbers, ``chunk`` a positive whole number.  Returns ``inputs`` as an array (or None)."""
    from .options import MAX_STEPS
    if not isinstance(scene, Scene):
        raise PolygonsError(f"sweep: expected a Scene (polygons.load(...)), got "
                            f"{type(scene).__name__}", file="<api>")
    if "cam_profiles" in scene.extra:       # its linkage holds for the part in contact only
        raise PolygonsError("a cam stated by its profile changes its equivalent linkage as the "
                            "part in contact changes: its displacement diagram over a turn is "
                            "polygons.cam_diagram.diagram(scene, steps)", file=scene.file)
    for name, value, low in (("steps", steps, 2),) + ((("chunk", chunk, 1),)
                                                       if chunk is not None else ()):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) \
                or not low <= value <= (MAX_STEPS if name == "steps" else 1 << 40):
            raise PolygonsError(f"{name} must be a whole number from {low} to "
                                f"{MAX_STEPS if name == 'steps' else 1 << 40:,}, got "
                                f"{show(value)}", file=scene.file, where=f"sweep {name}")
    if inputs is None:
        return None
    if getattr(inputs, "size", None) is None and not isinstance(inputs, (list, tuple)):
        raise PolygonsError(f"inputs must be a sequence of numbers, got "
                            f"{type(inputs).__name__}", file=scene.file, where="sweep inputs")
    if (inputs.size if hasattr(inputs, "size") else len(inputs)) > MAX_STEPS:
        raise PolygonsError(f"at most {MAX_STEPS:,} inputs in one sweep", file=scene.file,
                            where="sweep inputs")
    try:
        xs = np.asarray(inputs, dtype=float).reshape(-1)
    except (TypeError, ValueError, OverflowError):
        raise PolygonsError(f"inputs must be numbers (θ in rad or s in m), got "
                            f"{show(inputs)}", file=scene.file, where="sweep inputs") from None
    if not np.isfinite(xs).all() or (xs.size and float(np.max(np.abs(xs))) > 1e6):
        raise PolygonsError("inputs must be finite and at most 1e6 (rad or m) in magnitude",
                            file=scene.file, where="sweep inputs")
    return xs


def sweep(scene: Scene, steps: int = 360, *, inputs: Sequence[float] | None = None,
          chunk: int | None = None, progress: Callable[[int], None] | None = None,
          probe: int = PROBE, jit: bool = False) -> Sweep:
    """Solve ``scene`` over a full input revolution (or its reachable range).

    Without ``inputs``: a crank driver is swept over θ = 0 … 360° in ``steps`` equal steps
    when every angle closes, else over the reachable range around the scene's angle
    (``steps`` points strictly inside it: the limit positions themselves have infinite
    rates); a slider driver over its reachable travel.  With ``inputs`` (θ in rad or s in
    m) exactly those positions are solved, all of them in the branch of the scene's own
    position.  ``progress(k)`` is called with the number of positions done after each chunk
    (``chunk`` positions per pass; default from the program's size, :func:`chunk_for`).
    ``jit=True`` runs the construction compiled by numba when numba is installed
    (:mod:`polygons.jit`; the same numbers to rounding), numpy otherwise.
    """
    inputs = _check_sweep_args(scene, steps, inputs, chunk)
    memo = memo_of(scene)           # planned once per scene (a frozen record)
    prog = memo.get("sweep_program")
    if prog is None:
        prog = memo["sweep_program"] = compile_plan(scene)
    limits: tuple[Limit, ...] = ()
    toggles: tuple[Limit, ...] = ()
    if inputs is None:
        full, (lo, hi), limits, toggles = find_range(prog, probe)
        if full:
            xs = 2.0 * math.pi * np.arange(steps) / steps
            rng = (0.0, 2.0 * math.pi)
        else:
            xs = lo + (hi - lo) * (np.arange(steps) + 0.5) / steps
            rng = (lo, hi)
    else:
        xs = np.asarray(inputs, dtype=float).reshape(-1)
        full = False
        rng = (float(xs.min()), float(xs.max())) if xs.size else (0.0, 0.0)
    if _groups(prog):       # a triad follows its closure from the scene's input: one pass,
        prog = anchored(prog, xs, evaluate)   # in steps no coarser than the continuation's
        fine, rows = _refined(prog, xs)
        res = run(prog, fine, chunk=max(len(fine), 1), jit=jit)
        if len(fine) != len(xs):
            res = _take(res, rows)
        if progress:
            progress(len(xs))
    else:
        res = run(prog, xs, chunk=chunk, progress=progress, jit=jit)
    res, assur_notes = _assur_rows(prog, xs, res, run)
    segments = _segments(xs, toggles, full)
    warnings = []
    for tg in toggles:
        where = _fmt_input(prog, tg.input)
        if tg.kind == "toggle":
            warnings.append(f"toggle at {where}: {tg.reason}; the two closures of {tg.point} "
                            f"meet here, so the sweep is split there and beyond it follows the "
                            f"closure on the same side (the mechanism itself may take either)")
        else:
            warnings.append(f"near toggle at {where}: {tg.reason}; the construction lines "
                            f"meet at only {tg.angle_deg:.3g}°")
    warnings.extend(assur_notes)
    margin = res["margin"]
    lowest = float(np.min(margin)) if len(margin) else 1.0
    if not lowest >= _SIN_PARALLEL:          # one pass when all is well (NaN compares False)
        bad = ~np.isfinite(margin) | (margin < 0)
        if bad.any():
            warnings.append(f"{int(bad.sum())} of {len(xs)} positions cannot be assembled in "
                            f"the followed branch (NaN in the results)")
        at = ~bad & (margin < _SIN_PARALLEL)
        if at.any():
            _undefine(res, at)
            warnings.append(f"{int(at.sum())} of {len(xs)} positions lie on a toggle "
                            f"(construction lines parallel within {PARALLEL_DEG:g}°): their "
                            f"velocities and accelerations are undefined and left as NaN")
    return Sweep(scene, prog.plan, prog.input_kind, xs, prog.rate, prog.rate2, full, rng,
                 tuple(limits) + tuple(toggles), segments, prog.branches,
                 res["pos"], res["vel"], res["acc"], res["omega"], res["alpha"],
                 res["slide_v"], res["slide_a"], res["travel"], res["coriolis"], margin,
                 tuple(warnings))


def _undefine(res: dict, mask: np.ndarray) -> None:
    """Rates at the positions in ``mask`` (toggles) are undefined: NaN, not huge numbers."""
    for key in ("vel", "acc", "coriolis"):
        for arr in res[key].values():
            if arr is not None and not isinstance(arr, tuple):
                arr[:, mask] = np.nan
    for key in ("omega", "alpha", "slide_v", "slide_a"):
        for lab, arr in res[key].items():
            if not arr.flags.writeable:
                arr = res[key][lab] = np.array(arr)
            arr[mask] = np.nan


def run(prog: Program, xs: np.ndarray, *, chunk: int | None = None,
        progress: Callable[[int], None] | None = None, jit: bool = False) -> dict:
    """:func:`evaluate` in chunks of ``chunk`` positions (small enough for the CPU caches;
    default from the program's size, :func:`chunk_for`), each written straight into
    preallocated (2, N) / (N,) result arrays; fixed points keep their scalar positions and
    ``None`` rates.  ``jit``: the numba kernel where there is one (:func:`kernel_of`)."""
    xs = np.asarray(xs, dtype=float)
    n = len(xs)
    if n and (FUSED if jit else FUSED_NUMPY):
        from .fused import fused_of
        fused = fused_of(prog, arrays_program(prog)[0].index, arrays=not jit)
        if fused is not None:           # one kernel for the whole chain, into the results
            out = fused.run(prog, xs)
            if progress:
                progress(n)
            return out
    jit = bool(jit) and kernel_of(prog) is not None
    rows = kernel_of(prog)[0].size if jit else 0
    if jit and not chunk and rows <= JIT_ONE_PASS_ROWS and 0 < n <= JIT_ONE_PASS // rows:
        out = adopt(evaluate(prog, xs, jit=True), n)    # one pass, its rows kept: no copy
        if progress:
            progress(n)
        return out
    chunk = chunk or chunk_for(prog, jit)
    buf = np.empty((rows, min(chunk, max(n, 1)))) if jit else None   # the kernel's, reused
    out: dict | None = None
    for s in range(0, max(n, 1), chunk):
        e = min(n, s + chunk)
        res = evaluate(prog, xs[s:e], jit=jit, out=buf)
        if out is None:
            out = allocate(res, n)
        store(out, res, s, e)
        if progress:
            progress(e - s)
    return out


#: numba sweeps by the fused kernel (:mod:`polygons.fused`) where it makes the construction
#: (False: the compiled arrays program, :mod:`polygons.jit`; for comparison)
FUSED = True
#: numpy sweeps by the same kernel's loops over slices of positions (False: the arrays
#: program, the staged construction on arrays; for comparison)
FUSED_NUMPY = True
#: positions × record rows up to which a numba sweep is one pass whose rows are the results,
#: for records of at most JIT_ONE_PASS_ROWS rows (more rows, each a stream of stores to its
#: own pages, and the stores miss the TLB: chunks that stay in the caches are faster)
JIT_ONE_PASS = 1 << 25
JIT_ONE_PASS_ROWS = 64


def _rows(prog: Program) -> int:
    """The outputs of the program generated for arrays (rows of its record)."""
    code, _ = arrays_program(prog)
    return max(len(code.source.rsplit("return (", 1)[-1].split(",")) - 1, 1)


def _segments(xs: np.ndarray, toggles: Iterable[Limit], full: bool):
    cuts = []
    for tg in toggles:
        if tg.kind != "toggle":
            continue
        x = tg.input % (2 * math.pi) if full else tg.input
        cuts.append(int(np.searchsorted(xs, x)))
    cuts = sorted(set(c for c in cuts if 0 < c < len(xs)))
    bounds = [0] + cuts + [len(xs)]
    return tuple((bounds[i], bounds[i + 1]) for i in range(len(bounds) - 1))


def _fmt_input(prog: Program, x: float) -> str:
    if prog.input_kind == "crank":
        return f"θ = {math.degrees(x) % 360.0:.6g}°"
    return f"s = {1e3 * x:.6g} mm"


def fmt_input(sw: Sweep, x: float) -> str:
    return f"θ = {math.degrees(x):.6g}°" if sw.input_kind == "crank" else f"s = {1e3 * x:.6g} mm"


__all__ = ["Sweep", "Limit", "Harmonic", "harmonic", "Program", "compile_plan", "evaluate", "run", "sweep",
           "find_range", "PARALLEL_DEG", "WARN_DEG"]


def default_points(scene, plan, placed, travel) -> list[str]:
    """The points a user asks about: those the scene's ``[[answers]]`` name (moving points
    only, in the order asked); else the sliders; else the last point placed — never a lever
    point under a pin (P4 under P2) unless it is asked for.  ``placed``: the labels swept,
    ``travel``: the sliders with a travel (the in-memory and the streamed sweep alike)."""
    drv = scene.driver
    asked = []
    for ans in scene.answers:
        if ans.q is None or ans.q.fn in ("omega", "alpha", "angle", "arm", "dist"):
            continue
        for lab in ans.q.args:
            if lab in placed and lab not in scene.ground and lab not in asked:
                asked.append(lab)
    if asked:
        return asked
    sliders = [s for s in scene.model.guide if s in travel
               and not (not isinstance(drv, Crank) and s == drv.point)]
    if sliders:
        return sliders
    under = set(scene.model.under)                  # lever points under a pin (P4)
    last = [lab for d in plan.dyads for lab in d.placed if lab not in under]
    return [last[-1]] if last else [plan.dyads[-1].placed[-1]]
