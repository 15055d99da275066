"""The turning-moment diagram: the input torque over a turn of the crank, as books draw it
before sizing a flywheel.

At N crank angles round the turn the kinetostatic analysis is solved (the loads, springs and
inertia of the scene; the crank turning uniformly at its stated ω, α = 0, as the diagram is
drawn for a flywheel), each closure pinned near the one the
sweep follows from the scene's instant (:func:`polygons.sweep.sweep`), so the mechanism keeps
its assembly.  Then, with T(θ) the input torque and T_m its mean over the turn,

    E(θ) = ∫₀^θ (T − T_m) dθ        (the energy above the mean),
    ΔE = max E − min E               (the maximum fluctuation of energy),

to the precision of the construction, not of the N samples: T_m and E by adaptive
Gauss–Kronrod quadrature between the crossings of T = T_m (found by Brent's method), where E
is extreme; the torque's extremes refined between the samples (:func:`_exact_cycle`).

and a flywheel keeping the speed within ±C_s/2 of ω needs I = ΔE / (ω² C_s).  Virtual work
is checked against Newton–Euler at every angle.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from types import MappingProxyType

import numpy as np

from ..errors import SceneError, UnsupportedError
from ..scene import Crank, Scene
from ..calculus import brent, integral
from ..sweep_range import golden_min
from .model import spring_refs
from .states import driver_state, kinetostatic

#: the most angles one cycle may have (each a full force analysis, ~2 ms)
MAX_CYCLE = 3600
#: the work ``forces --cycle`` takes on without ``--long``: N angles × (3 × moving bodies)³,
#: the dense Newton–Euler equations solved and checked at each angle (a four-bar at 3600
#: angles is 7e7; a 100-link scene, 300 equations, reaches it at ~740 angles, about 25 s on
#: the 2-core reference machine — 3600 angles there took 116 s)
CYCLE_BUDGET = 2e10


def cycle_work(model, n: int) -> float:
    """The estimated work of a turning-moment diagram of ``n`` angles (see CYCLE_BUDGET)."""
    return float(n + refinement_analyses(n)) * (3.0 * len(model.bodies)) ** 3


def refinement_analyses(n: int) -> int:
    """About how many more force analyses the exact numbers take beyond the N samples: a
    15-point rule between the table's rows and about the crossings, Brent's and the golden
    sections' steps."""
    return 15 * (len(table_rows(n)) + 8) + 200


def check_cycle_budget(model, n: int, file: str | None = None) -> None:
    """Refuse, before any work, a turning-moment diagram above :data:`CYCLE_BUDGET`, naming
    the estimate, the largest N within it and the flag that allows it."""
    work = cycle_work(model, n)
    if work > CYCLE_BUDGET:
        lo, hi = 0, n               # the largest N within the budget (work grows with N)
        while lo < hi:
            mid = (lo + hi + 1) // 2
            lo, hi = (mid, hi) if cycle_work(model, mid) <= CYCLE_BUDGET else (lo, mid - 1)
        most = lo
        raise SceneError(f"--cycle {n} on {len(model.bodies)} moving bodies is about "
                         f"{work:.2g} units of work ({n} angles × (3 × {len(model.bodies)} "
                         f"equations)³), above the budget of {CYCLE_BUDGET:.0e} (minutes on "
                         f"a small machine): use --cycle {max(most, 4)} or less, or add --long "
                         f"to run it anyway", file=file, where="--cycle")


@dataclass(frozen=True)
class Cycle:
    """``theta`` (rad, absolute crank angles from the scene's), ``torque`` (N m, the input
    torque, CCW +), ``energy`` (J, E(θ) above the mean at the samples, by trapezoids: the drawn
    curve), the mean, ΔE and where E is greatest and least (by quadrature to the precision of
    the construction); ``vw_error``: the largest |T_NE − T_VW| over the turn."""
    theta: np.ndarray
    torque: np.ndarray
    energy: np.ndarray
    mean: float
    fluctuation: float
    at_max: float
    at_min: float
    vw_error: float
    omega: float
    warnings: tuple[str, ...] = ()      # the sweep's: toggles and near-toggles on the way
    #: (T, θ) where the torque is greatest / least, refined between the samples
    max_torque: tuple[float, float] = (math.nan, math.nan)
    min_torque: tuple[float, float] = (math.nan, math.nan)
    #: E at the table's rows (:func:`table_rows`), by quadrature (``energy`` is the drawn
    #: curve, trapezoids of the samples)
    row_energy: tuple[float, ...] = ()
    #: (θ, E) where T = T_m, in the order of the turn: the ends of the areas above and below
    crossings: tuple[tuple[float, float], ...] = ()

    def flywheel_inertia(self, cs: float) -> float:
        """I = ΔE / (ω² C_s): the flywheel that keeps the speed within the coefficient of
        fluctuation ``cs`` (ω_max − ω_min = C_s ω); ``cs`` in :data:`CS_RANGE`, and an
        inertia too large to state refused (ω² C_s underflowing)."""
        check_fluctuation(cs)
        inertia = self.fluctuation / (self.omega ** 2 * cs) if self.fluctuation else 0.0
        if not math.isfinite(inertia) or inertia > INERTIA_MOST:
            raise SceneError(f"the flywheel for C_s = {cs:g} would need I = ΔE / (ω² C_s) "
                             f"above {INERTIA_MOST:g} kg m² (ΔE = {self.fluctuation:.6g} J, "
                             f"ω = {abs(self.omega):.6g} rad/s): no flywheel keeps the speed "
                             f"that steady")
        return inertia


#: the coefficients of fluctuation of speed C_s accepted (--fluctuation): from 1e-6 (a
#: millionth of the speed; engines' flywheels are 0.002–0.2) up to, not including, 1
CS_RANGE = (1e-6, 1.0)
#: the largest flywheel inertia stated (kg m²), as a scene's inertia (polygons.units.LIMITS)
INERTIA_MOST = 1e9


def check_fluctuation(cs: float, where: str = "--fluctuation") -> float:
    """``cs`` if it is a coefficient of fluctuation of speed in :data:`CS_RANGE`."""
    lo, hi = CS_RANGE
    if not (lo <= cs < hi):
        raise SceneError(f"the coefficient of fluctuation of speed must be from {lo:g} "
                         f"({lo * 100:g} %) up to, not including, 1 (100 %); got {cs:g}",
                         where=where)
    return cs


def turning_moment(model, scene: Scene, n: int, table: bool = True) -> Cycle:
    """The input torque at ``n`` angles round the turn from the scene's crank angle (with
    ``table``, E at the table's rows too: :func:`table_rows`)."""
    drv = scene.driver
    if not isinstance(drv, Crank):
        raise UnsupportedError("the turning-moment diagram is drawn over a crank's turn: this "
                               "scene's driver is a slider", file=scene.file)
    if model.mode != "kinetostatic":
        raise UnsupportedError(f"the turning-moment diagram is a kinetostatic analysis at "
                               f"the crank's stated ω; [dynamics] mode = {model.mode!r}",
                               file=scene.file)
    if model.parsed.effort is not None:
        raise UnsupportedError("the turning-moment diagram is the crank's torque; this scene "
                               "finds its effort elsewhere ([dynamics] effort)",
                               file=scene.file)
    if not 4 <= n <= MAX_CYCLE:
        raise SceneError(f"--cycle takes 4 to {MAX_CYCLE} angles, got {n}", file=scene.file)
    if drv.omega == 0.0:
        raise UnsupportedError("the crank is at rest: a turning-moment diagram needs it "
                               "turning (its ω)", file=scene.file)
    from ..evaluate import solve
    from ..sweep import sweep
    sense = 1.0 if drv.omega > 0 else -1.0
    thetas = drv.angle + sense * 2.0 * math.pi * np.arange(n + 1) / n
    sw = sweep(scene, inputs=thetas)        # (one more: the turn's end, to compare)
    lost = [i for i in range(n + 1) if not sw.margin[i] > 0]
    if lost:
        raise UnsupportedError(f"the crank does not turn fully: the mechanism cannot be "
                               f"assembled at {math.degrees(thetas[lost[0]]) % 360:.4g}° "
                               f"(a limit of its range), so there is no turning-moment "
                               f"diagram over a turn", file=scene.file)
    paths = {lab: np.asarray(xy) for lab, xy in sw.pos.items() if np.ndim(xy) == 2}
    size = max([float(np.max(np.abs(xy))) for xy in paths.values()], default=1.0)
    moved = [lab for lab, xy in paths.items()
             if float(np.hypot(xy[0][n] - xy[0][0], xy[1][n] - xy[1][0])) > 1e-6 * size]
    if moved:
        raise UnsupportedError(f"after one turn of the crank the mechanism is not where it "
                               f"started ({moved[0]} is elsewhere: its closure changed on the "
                               f"way), so one turn is no cycle of its turning moment",
                               file=scene.file)
    thetas = thetas[:n]
    model = replace(model, ref=MappingProxyType(spring_refs(model, solve(scene))))
    torque, worst = np.empty(n), 0.0
    for i, th in enumerate(thetas):
        st = kinetostatic(model, driver_state(sw.scene_at(i), alpha=0.0),
                          name=f"{math.degrees(th) % 360:.6g} deg")
        torque[i] = st.ne.effort
        worst = max(worst, abs(st.ne.effort - st.vw_effort))
    notes = [f"the {q.kind} at {q.at}: its profile is taken as the circular arc stated at the "
             f"contact all round the turn (an eccentric disc); for another profile only the "
             f"scene's instant holds" for q in getattr(scene, "equivalents", ())
             if q.kind in ("cam", "flat-faced cam", "curved slot")]
    return _exact_cycle(model, sw, drv, sense, thetas, torque, worst,
                        tuple(sw.warnings) + tuple(notes), table)


def _torque_at(model, sw, drv, sense: float, n: int):
    """T(u): the input torque with the crank turned u (rad, in its sense) from the scene's
    angle, each closure pinned near the sweep's nearest sample."""
    step = 2.0 * math.pi / n

    def T(u: float) -> float:
        i = int(round(u / step)) % n
        sc = sw.scene_at(i)
        sc = replace(sc, driver=replace(sc.driver, angle=drv.angle + sense * u))
        return kinetostatic(model, driver_state(sc, alpha=0.0),
                            name=f"{math.degrees(drv.angle + sense * u) % 360:.6g} deg").ne.effort
    return T


def table_rows(n: int) -> range:
    """The sample indices the turning-moment table prints (at most ~36 rows, or every one)."""
    return range(0, n, max(1, n // 36))


def _exact_cycle(model, sw, drv, sense, thetas, torque, worst, warnings, table) -> Cycle:
    """The cycle's numbers to the precision of the construction, not of the N samples: with
    u the turn from the scene's angle and T(u) solved wherever it is needed,

        T_m = (1/2π) ∮ T du             (adaptive Gauss–Kronrod between the crossings)
        T(c) = T_m at each crossing c   (Brent's method between the samples either side)
        E(u) = s ∫₀ᵘ (T − T_m) du       (s the crank's sense; the same quadrature)

    ΔE = max E − min E over the crossings (E is extreme only where T = T_m); the torque's
    greatest and least refined by golden section between the samples either side.  The
    sampled energy (trapezoids) is kept for the drawn curve only."""
    n = len(thetas)
    step = 2.0 * math.pi / n
    T = _torque_at(model, sw, drv, sense, n)
    us = step * np.arange(n)
    scale = float(np.max(np.abs(torque))) or 1.0

    def crossings(mean: float) -> list[float]:
        ex = torque - mean
        out = []
        for i in range(n):
            j = (i + 1) % n
            if ex[i] == 0.0:
                out.append(float(us[i]))
            elif ex[i] * ex[j] < 0.0:
                b = us[i] + step
                out.append(brent(lambda u: T(u) - mean, float(us[i]), float(b),
                                 float(ex[i]), float(ex[j])))
        return out

    rows = list(table_rows(n)) if table else [0]
    # ∫T between fixed marks (the table's rows and the samples before each sign change of
    # T − its sampled mean), so that T_m and the areas are found once, whatever T_m is
    rough = torque - float(np.mean(torque))
    before = [i for i in range(n) if rough[i] * rough[(i + 1) % n] <= 0.0]
    marks = sorted(set(float(us[i]) for i in rows) | set(float(us[i]) for i in before))
    ends = marks[1:] + [2.0 * math.pi]
    pieces = [integral(T, a, b, rel=1e-11)[0] for a, b in zip(marks, ends)]
    mean = math.fsum(pieces) / (2.0 * math.pi)
    if abs(mean) <= 1e-12 * scale:
        mean = 0.0          # rounding noise of a mean that is zero (conservative loads)
    energy_at, e = {}, 0.0
    for a, b, piece in zip(marks, ends, pieces):
        energy_at[a] = e
        e += sense * (piece - mean * (b - a))
    cuts = crossings(mean)
    for c in cuts:                      # E at a crossing: from the last mark before it
        m = max((x for x in marks if x <= c), default=0.0)
        energy_at[c] = energy_at[m] + sense * (integral(T, m, c, rel=1e-11)[0]
                                               - mean * (c - m))
    if cuts:
        at_hi = max(cuts, key=lambda c: energy_at[c])
        at_lo = min(cuts, key=lambda c: energy_at[c])
        fluct = energy_at[at_hi] - energy_at[at_lo]
    else:                               # T is its mean everywhere
        at_hi = at_lo = 0.0
        fluct = 0.0
    # the torque's extremes, refined between the samples either side
    i_hi, i_lo = int(np.argmax(torque)), int(np.argmin(torque))
    u_hi, t_hi = golden_min(lambda u: -T(u), float(us[i_hi] - step), float(us[i_hi] + step),
                            iters=40)
    u_lo, t_lo = golden_min(T, float(us[i_lo] - step), float(us[i_lo] + step), iters=40)
    t_hi = -t_hi
    if t_hi < torque[i_hi]:
        u_hi, t_hi = float(us[i_hi]), float(torque[i_hi])
    if t_lo > torque[i_lo]:
        u_lo, t_lo = float(us[i_lo]), float(torque[i_lo])
    excess = torque - mean
    drawn = sense * np.concatenate(([0.0], np.cumsum(0.5 * (excess[1:] + excess[:-1]) * step)))
    row_energy = tuple(energy_at[float(us[i])] for i in rows) if table else ()

    def theta(u: float) -> float:
        return float(drv.angle + sense * u)
    return Cycle(thetas, torque, drawn, mean, fluct, theta(at_hi), theta(at_lo), worst,
                 abs(drv.omega), warnings, max_torque=(t_hi, theta(u_hi)),
                 min_torque=(t_lo, theta(u_lo)), row_energy=row_energy,
                 crossings=tuple((theta(c), energy_at[c]) for c in cuts))


__all__ = ["Cycle", "turning_moment", "MAX_CYCLE", "CYCLE_BUDGET", "cycle_work",
           "check_cycle_budget"]
