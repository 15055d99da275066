"""The analysed instants: kinematics, virtual velocities, Newton–Euler and virtual work at one
state, kinetostatic (the input torque found) or torque-driven (the input's α found)."""
from __future__ import annotations

from dataclasses import dataclass, field, replace

from ..errors import SceneError, UnsupportedError
from ..evaluate import Solution, solve
from ..scene import Crank, Scene
from . import effort
from .cams import cam_contacts, mu_needed, rolling_words, words
from .model import ForceModel, Inertia, friction_sense, inertias
from .newton_euler import NEResult, newton_euler
from .virtual_work import Share, virtual_work


@dataclass
class State:
    """One analysed instant: kinematics (final), virtual velocities, Newton–Euler, virtual work."""
    name: str
    sol: Solution
    vsol: Solution
    ne: NEResult
    inertia: list[Inertia]
    vw_effort: float | None
    breakdown: list[Share]            # the virtual-work terms (key, words, value)
    applied_driver: float            # torque (force) applied to the driver by [torques]/[forces]
    rotation: float = 0.0            # release: the driver's rotation from the release position
    extra: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    #: the cam / curved-slot contacts' forces (:mod:`polygons.forces.cams`)
    contacts: tuple = ()


def driver_state(scene: Scene, *, angle=None, omega=None, alpha=None) -> Scene:
    drv = scene.driver
    if isinstance(drv, Crank):
        d = replace(drv, angle=drv.angle if angle is None else angle,
                    omega=drv.omega if omega is None else omega,
                    alpha=drv.alpha if alpha is None else alpha)
    else:
        d = replace(drv, velocity=drv.velocity if omega is None else omega,
                    acceleration=drv.acceleration if alpha is None else alpha)
    return replace(scene, driver=d)


def virtual_solution(scene: Scene) -> Solution:
    """Velocities per unit input rate (ω_in = 1 rad/s CCW, or 1 m/s along the guide)."""
    s = driver_state(scene, omega=1.0, alpha=0.0)
    return solve(s)


def driver_applied(model: ForceModel, ne: NEResult, vsol: Solution) -> float:
    """The input-equivalent of the loads on the driver body itself (torques, for reporting)."""
    return sum(ld.couple for ld in ne.loads if ld.body == model.driver_body
               and ld.kind == "torque")


def kinetostatic(model: ForceModel, scene: Scene, name: str = "instant",
                 motion: int | None = None) -> State:
    sol = solve(scene)
    vsol = virtual_solution(scene)
    ne = newton_euler(model, sol, vsol, motion=motion)
    vw, parts = virtual_work(model, sol, vsol, ne.loads)
    if model.parsed.effort is not None:       # the effort elsewhere: per its own rate
        vw, parts = _per_effort(model, vsol, vw, parts)
    return _contacts(model, State(name, sol, vsol, ne, inertias(model, sol), vw, parts,
                                  driver_applied(model, ne, vsol),
                                  warnings=_friction_warnings(model, sol, vsol, motion)))


def _contacts(model: ForceModel, st: State) -> State:
    """``st`` with its cam contacts' forces, and a warning where a cam would have to pull."""
    st.contacts = cam_contacts(model, st.ne, st.sol)
    st.warnings += [words(c) for c in st.contacts if c.lost]
    st.warnings += [rolling_words(lab, st.ne) for lab in st.ne.rolling
                    if mu_needed(lab, st.ne) is None]
    return st


def _per_effort(model, vsol, vw, parts):
    """The virtual work's effort at a place other than the driver: −ΣP* divided by the
    unit effort's own power at the unit input rate."""
    r = effort.rate(model, vsol)
    if abs(r) < 1e-12:
        raise UnsupportedError(f"the {effort.words(model)} does no work at this instant "
                               f"(its point does not move along it): it cannot balance the "
                               f"loads", file=model.scene.file)
    return vw / r, [replace(t, value=t.value / r) for t in parts]


def _friction_warnings(model, sol, vsol, motion) -> list[str]:
    return [f"the pin {fr.at} ({fr.name}) does not turn at this instant: its friction torque "
            f"is taken as 0 (its sense is undefined)" for fr in model.frictions
            if friction_sense(model, sol, vsol, fr, motion) == 0]


def torque_driven(model: ForceModel, scene: Scene, name: str = "instant",
                  motion: int | None = None) -> State:
    """The input's α from the applied loads (kinematics at α = 0 and α = 1, affine), then the
    kinematics at that α and every reaction."""
    s0 = driver_state(scene, alpha=0.0)
    sol0 = solve(s0)
    sol1 = solve(driver_state(scene, alpha=1.0))
    vsol = virtual_solution(scene)
    if motion is None and model.frictions and _input_rate(scene) == 0.0:
        motion = _motion_from_rest(model, sol0, sol1, vsol)
    ne = newton_euler(model, sol0, vsol, sol1, motion=motion)
    alpha = ne.alpha
    sol = solve(driver_state(scene, alpha=alpha))
    vw, parts = virtual_work(model, sol, vsol, ne.loads)
    st = _contacts(model, State(name, sol, vsol, ne, inertias(model, sol), vw, parts,
                                driver_applied(model, ne, vsol),
                                warnings=_friction_warnings(model, sol, vsol, motion)))
    st.extra["alpha_in"] = alpha
    return st


def _input_rate(scene: Scene) -> float:
    drv = scene.driver
    return drv.omega if isinstance(drv, Crank) else drv.velocity


def _motion_from_rest(model, sol0, sol1, vsol) -> int:
    """At rest with friction: the sense the input starts to move in (friction opposing it)."""
    results = {}
    for m in (1, -1):
        results[m] = newton_euler(model, sol0, vsol, sol1, motion=m).alpha
    if results[1] > 0:
        return 1
    if results[-1] < 0:
        return -1
    raise UnsupportedError("friction holds the mechanism at rest here (static friction is not "
                           "modelled): no motion starts", file=model.scene.file)


@dataclass
class Analysis:
    model: ForceModel
    states: list[State]
    dynamics: dict | None       # release: energy vs integration check

    def state(self, name: str | None) -> State:
        if name is None:
            return self.states[0]
        for s in self.states:
            if s.name == name or s.name == f"after {name}":
                return s
        raise SceneError(f"no state {name!r}: the states are "
                         f"{', '.join(repr(s.name) for s in self.states)}",
                         file=self.model.scene.file)
