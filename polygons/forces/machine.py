"""The machine around the mechanism: a flywheel on the crank shaft and the mechanism's
efficiency (``[flywheel]``, ``[efficiency]`` in :mod:`polygons.loads`).

* resisting torque from the power taken off: T_R = P/ω;
* flywheel angular acceleration from the torque surplus: α = (T − T_R)/I, with T the turning
  moment the mechanism exerts on the crank (counted in the sense of rotation) and I = m k²;
* input torque with an efficiency η: T_in/η when the input drives (T_in·ω > 0), T_in·η when
  the mechanism drives the input back;
* velocity ratio q̇_in/q̇_out from the velocities of a unit input rate, mechanical advantage
  MA = η ω_in/ω_out, and the output effort η × E_in × q̇_in/q̇_out (a torque on a link, a
  force on a slider).
"""
from __future__ import annotations

import numpy as np

from ..errors import SceneError
from ..loadmodel import Body, Efficiency, Flywheel
from ..scene import Crank
from .model import ForceModel, body_omega
from .states import State


def driver_rate(st: State) -> float:
    """The input's rate at this state: the crank's ω (rad/s) or the slider's v (m/s)."""
    drv = st.sol.scene.driver
    if isinstance(drv, Crank):
        return float(st.sol.links[drv.link].omega or 0.0)
    return float(st.sol.slides[drv.point].velocity)


def _flywheel(model: ForceModel) -> Flywheel:
    if model.parsed.flywheel is None:
        raise SceneError("this needs a [flywheel] table (mass + radius_of_gyration, power)",
                         file=model.scene.file)
    return model.parsed.flywheel


def _efficiency(model: ForceModel) -> Efficiency:
    if model.parsed.efficiency is None:
        raise SceneError("this needs an [efficiency] table (eta = \"80 %\")",
                         file=model.scene.file)
    return model.parsed.efficiency


def resisting_torque(model: ForceModel, st: State) -> float:
    """T_R = P/ω (or as given), a magnitude opposing the rotation."""
    fw = _flywheel(model)
    if fw.resisting_torque is not None:
        return fw.resisting_torque
    return fw.power / abs(driver_rate(st))


def turning_moment(st: State) -> float:
    """T: the mechanism's turning moment on the crank, positive in the sense of rotation
    (= −T_in · sign ω)."""
    w = driver_rate(st)
    return -st.ne.effort * (1.0 if w >= 0 else -1.0)


def flywheel_alpha(model: ForceModel, st: State) -> float:
    """α = (T − T_R)/I: positive when the flywheel speeds up."""
    fw = _flywheel(model)
    return (turning_moment(st) - resisting_torque(model, st)) / fw.inertia


def input_with_efficiency(model: ForceModel, st: State) -> float:
    """T_in/η when the input drives the mechanism (T_in·ω ≥ 0), T_in·η when it is driven back."""
    eta = _efficiency(model).eta
    e = st.ne.effort
    return e / eta if e * driver_rate(st) >= 0 else e * eta


def velocity_ratio(model: ForceModel, st: State, out: Body) -> float:
    """|q̇_in / q̇_out|: ω_in/ω_out for a link, ω_in/v_out (1/m) for a slider block."""
    if out.kind == "block":
        direction = np.array(st.vsol.scene.model.guide[out.a].line.direction)
        rate = float(np.array(st.vsol.points[out.a].velocity) @ direction)
    else:
        rate = body_omega(st.vsol, out)
    if rate == 0.0:
        raise SceneError(f"{out.name} does not move at this instant: no velocity ratio",
                         file=model.scene.file)
    return 1.0 / abs(rate)          # vsol: the input turns (or slides) at unit rate


def mechanical_advantage(model: ForceModel, st: State, out: Body) -> float:
    """MA = η ω_in/ω_out (output torque per input torque)."""
    if out.kind == "block":
        raise SceneError(f"{out.name} is a slider: its output per input torque has a unit; ask "
                         f"for Fout_eta({out.name})", file=model.scene.file)
    return _efficiency(model).eta * velocity_ratio(model, st, out)


def output_effort(model: ForceModel, st: State, out: Body) -> float:
    """η × E_in × q̇_in/q̇_out: the torque on link ``out`` (or force on slider ``out``) that the
    input effort E_in of ``[efficiency]`` delivers."""
    eff = _efficiency(model)
    if eff.input_effort is None:
        raise SceneError("the output effort needs the input: [efficiency] input_torque "
                         "(or input_force for a slider driver)", file=model.scene.file)
    return eff.eta * eff.input_effort * velocity_ratio(model, st, out)
