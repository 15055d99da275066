"""The unknown effort anywhere (``[dynamics] effort``): a torque on any link, a force at a
slider along its guide, or a force along an actuator between two points — found while the
driver stays the kinematic input (its motion given, no torque on it).

:func:`terms` is the effort's unit action on the bodies (Newton–Euler puts it in the column
the driver's torque would take); :func:`rate` is its power at a unit input rate (the virtual
work divides by it).  Without an effort key the effort is the driver's: a torque on a crank,
a force along the guide of a slider driver.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import UnsupportedError
from ..evaluate import Solution
from ..scene import Crank
from .model import ForceModel, body_omega, image, position


@dataclass(frozen=True)
class Term:
    """The unit effort's action on ``body``: a force ``direction`` at ``pos`` and/or a couple."""
    body: str
    pos: np.ndarray | None
    direction: np.ndarray
    couple: float


def is_torque(model: ForceModel) -> bool:
    """Whether the effort is a torque (N m) rather than a force (N)."""
    e = model.parsed.effort
    if e is None:
        return isinstance(model.scene.driver, Crank)
    return e.kind == "torque"


def unit(model: ForceModel) -> str:
    return "N m" if is_torque(model) else "N"


def key(model: ForceModel) -> str:
    """An identifier for the effort: input_torque_OA, effort_force_C, effort_actuator_E_F."""
    e = model.parsed.effort
    drv = model.scene.driver
    if e is None:
        what = "torque" if isinstance(drv, Crank) else "force"
        return f"input_{what}_{model.driver_body}"
    if e.kind == "actuator":
        return f"effort_actuator_{e.ends[0][0]}_{e.ends[1][0]}"
    return f"effort_{e.kind}_{e.body}"


def words(model: ForceModel) -> str:
    """The effort in words: 'input torque on OA', 'force at slider C along its guide' ..."""
    e = model.parsed.effort
    drv = model.scene.driver
    if e is None:
        if isinstance(drv, Crank):
            return f"input torque on {model.driver_body}"
        return f"input force on slider {drv.point} along its guide"
    if e.kind == "torque":
        return f"effort: torque on {e.body}"
    if e.kind == "force":
        return f"effort: force on slider {e.body} along its guide"
    (a, _), (b, _) = e.ends
    return f"effort: actuator force along {a}{b} (positive pushing {a} and {b} apart)"


def short(model: ForceModel) -> str:
    """The effort's short name for a drawing: 'T on OA', 'F at P', 'F along HF'."""
    e = model.parsed.effort
    drv = model.scene.driver
    if e is None:
        return f"T on {drv.link}" if isinstance(drv, Crank) else f"F at {drv.point}"
    if e.kind == "torque":
        return f"T on {e.body}"
    if e.kind == "force":
        return f"F at {e.body}"
    return f"F along {e.ends[0][0]}{e.ends[1][0]}"


def terms(model: ForceModel, sol: Solution) -> list[Term]:
    """The unit effort's action (1 N m, or 1 N) on the bodies at ``sol``."""
    e = model.parsed.effort
    drv = model.scene.driver
    guide = model.scene.model.guide
    zero = np.zeros(2)
    if e is None:
        if isinstance(drv, Crank):
            return [Term(drv.link, None, zero, 1.0)]
        return [Term(drv.point, position(sol, drv.point),
                     np.array(guide[drv.point].line.direction), 0.0)]
    if e.kind == "torque":
        return [Term(e.body, None, zero, 1.0)]
    if e.kind == "force":
        return [Term(e.body, position(sol, e.body), np.array(guide[e.body].line.direction),
                     0.0)]
    (a, ba), (b, bb) = e.ends
    d = position(sol, a) - position(sol, b)
    length = float(np.hypot(*d))
    if not length > 0.0:
        raise UnsupportedError(f"the actuator {a}{b} has no length at this instant ({a} and "
                               f"{b} coincide): its force has no direction",
                               file=model.scene.file)
    d = d / length                                   # from F towards E: pushes E away from F
    out = []
    if ba is not None:
        out.append(Term(ba, position(sol, a), d, 0.0))
    if bb is not None:
        out.append(Term(bb, position(sol, b), -d, 0.0))
    return out


def rate(model: ForceModel, vsol: Solution) -> float:
    """The power of the unit effort at the velocities ``vsol`` of a unit input rate."""
    p = 0.0
    for t in terms(model, vsol):
        body = model.bodies[t.body]
        p += t.couple * body_omega(vsol, body)
        if t.pos is not None:
            p += float(t.direction @ image(vsol, body, t.pos, "velocity"))
    return p
