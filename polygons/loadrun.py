"""How the force analysis runs and what it is checked against, read from the scene:
[dynamics] (the mode — kinetostatic, torque-driven, release — its rotations and steps),
[flywheel] (I = m k², the resisting torque T_R = P/ω), [efficiency] (η, the effort) and
[[force_answers]] (the exact and printed values a case states).

Split from :mod:`polygons.loads` (the loads themselves: masses, forces, torques, springs),
which calls these readers; every problem is a :class:`~polygons.errors.SceneError` naming
the key.
"""
from __future__ import annotations

from typing import Callable

from .errors import SceneError, UnsupportedError, show
from .loadmodel import Efficiency, Flywheel, ForceAnswer
from .loadtables import (DEFAULT_MODE, DEFAULT_STEPS, MAX_AFTER, MAX_RELEASE_STEPS, MODES,
                         keys_of as _keys)
from .reader import Reader as _Values

#: reads the fields every answer table shares (``scene.answer_fields`` bound to its reader)
AnswerFields = Callable[..., dict]


def is_crank(driver) -> bool:
    """Whether the driver is a crank (it has a pivot), not a slider."""
    return hasattr(driver, "pivot")


_is_crank = is_crank


def dynamics(r: _Values, scene, draw, active: bool) -> tuple[str, tuple[float, ...], int]:
    file = r.file
    r.table(draw, "dynamics", _keys("dynamics"))
    mode = draw.get("mode", DEFAULT_MODE)
    if mode not in MODES:
        raise SceneError(f"mode must be one of {', '.join(MODES)}; got {mode!r}", file=file,
                         where="dynamics.mode")
    after_raw = draw.get("after", [])
    if isinstance(after_raw, str):
        after_raw = [after_raw]
    if not isinstance(after_raw, list):
        raise SceneError("after = [\"30 deg\"]: the rotations of the driver at which to report",
                         file=file, where="dynamics.after")
    if len(after_raw) > MAX_AFTER:
        raise SceneError(f"{len(after_raw):,} rotations: at most {MAX_AFTER} are reported",
                         file=file, where="dynamics.after")
    after = tuple(abs(r.quantity(a, "angle", f"dynamics.after[{i}]"))
                  for i, a in enumerate(after_raw))
    if after and mode != "release":
        raise SceneError("'after' is for mode = \"release\"", file=file, where="dynamics.after")
    steps = draw.get("steps", DEFAULT_STEPS)
    if (isinstance(steps, bool) or not isinstance(steps, int)
            or not 4 <= steps <= MAX_RELEASE_STEPS):
        raise SceneError(f"steps must be a whole number from 4 to {MAX_RELEASE_STEPS:,}, got "
                         f"{show(steps)}", file=file, where="dynamics.steps")
    if not active:
        return mode, after, steps
    drv = scene.driver
    if mode in ("torque-driven", "release"):
        if _is_crank(drv) and drv.alpha != 0.0:
            raise SceneError(f"mode = {mode!r} finds the driver's angular acceleration from the "
                             f"torques: remove driver.alpha", file=file, where="driver.alpha")
        if not _is_crank(drv) and drv.acceleration != 0.0:
            raise SceneError(f"mode = {mode!r} finds the driver's acceleration from the forces: "
                             f"remove driver.acceleration", file=file,
                             where="driver.acceleration")
    if mode == "release" and not _is_crank(drv):
        raise UnsupportedError("mode = \"release\" needs a crank as the driver (its angle is the "
                               "coordinate)", file=file, where="dynamics.mode")
    if "acceleration" not in scene.solve:
        raise SceneError("forces need the acceleration polygon: remove 'solve' or write "
                         "solve = [\"velocity\", \"acceleration\"]", file=file, where="solve")
    return mode, after, steps


def flywheel(r: _Values, scene, raw, mode: str) -> Flywheel | None:
    """I = m k² (or inertia); T_R = P/ω (or resisting_torque)."""
    if raw is None:
        return None
    r.table(raw, "flywheel", _keys("flywheel"))
    if not _is_crank(scene.driver):
        raise SceneError("a flywheel turns with a crank driver", file=r.file, where="flywheel")
    if mode != "kinetostatic":
        raise SceneError("the flywheel's α = (T − T_R)/I is for mode = \"kinetostatic\" (the "
                         "crank's ω as given)", file=r.file, where="flywheel")
    if ("inertia" in raw) == ("mass" in raw or "radius_of_gyration" in raw):
        raise SceneError("give mass + radius_of_gyration (I = m k²) or inertia", file=r.file,
                         where="flywheel")
    if "inertia" in raw:
        inertia = r.quantity(raw["inertia"], "inertia", "flywheel.inertia")
        how = "given"
    else:
        if "mass" not in raw or "radius_of_gyration" not in raw:
            raise SceneError("I = m k² needs both mass and radius_of_gyration", file=r.file,
                             where="flywheel")
        m = r.quantity(raw["mass"], "mass", "flywheel.mass")
        k = r.quantity(raw["radius_of_gyration"], "length", "flywheel.radius_of_gyration")
        inertia, how = m * k * k, f"m k² = {m:.6g} × {k:.6g}²"
    if inertia <= 0:
        raise SceneError("the flywheel's moment of inertia must be positive", file=r.file,
                         where="flywheel")
    if ("power" in raw) == ("resisting_torque" in raw):
        raise SceneError("give the power taken off (T_R = P/ω) or the resisting_torque",
                         file=r.file, where="flywheel")
    power = r.quantity(raw["power"], "power", "flywheel.power") if "power" in raw else None
    tr = (r.quantity(raw["resisting_torque"], "torque", "flywheel.resisting_torque")
          if "resisting_torque" in raw else None)
    if power is not None and scene.driver.omega == 0.0:
        raise SceneError("T_R = P/ω needs the crank turning (omega is 0)", file=r.file,
                         where="flywheel.power")
    return Flywheel(inertia, how, tr, power)


def efficiency(r: _Values, scene, raw) -> Efficiency | None:
    if raw is None:
        return None
    r.table(raw, "efficiency", _keys("efficiency"), required=("eta",))
    eta = r.quantity(raw["eta"], "fraction", "efficiency.eta")
    if not 1e-6 <= eta <= 1.0:      # (an η of 1e-320 would make T_in/η infinite)
        raise SceneError(f"an efficiency is a fraction from 1e-6 (0.0001 %) to 1 (100 %), got "
                         f"{raw['eta']!r}", file=r.file, where="efficiency.eta")
    crank = _is_crank(scene.driver)
    key, dim = ("input_torque", "torque") if crank else ("input_force", "force")
    wrong = "input_force" if crank else "input_torque"
    if wrong in raw:
        raise SceneError(f"the driver is a {'crank' if crank else 'slider'}: give {key}",
                         file=r.file, where=f"efficiency.{wrong}")
    effort = abs(r.quantity(raw[key], dim, f"efficiency.{key}")) if key in raw else None
    return Efficiency(eta, effort)


#: units a force answer may be stated in beyond polygons.units (answer_fields checks the rest)
ANSWER_UNITS = ("-", "1")


def answers(r: _Values, raw, answer_fields: AnswerFields) -> tuple[ForceAnswer, ...]:
    if not isinstance(raw, list):
        raise SceneError("write force answers as [[force_answers]] tables", file=r.file,
                         where="force_answers")
    out = []
    for i, spec in enumerate(raw):
        where = f"force_answers[{i}]"
        fields = answer_fields(spec, where, extra_keys=("positive", "state"),
                               extra_units=ANSWER_UNITS)
        positive = r.sense(spec.get("positive", "CCW"), where + ".positive")
        state = spec.get("state")
        if state is not None and not isinstance(state, str):
            raise SceneError("state must be text ('release' or a rotation such as '30 deg')",
                             file=r.file, where=where + ".state")
        out.append(ForceAnswer(positive=positive, state=state, **fields))
    return tuple(out)


__all__ = ["AnswerFields", "is_crank", "dynamics", "flywheel", "efficiency", "answers",
           "ANSWER_UNITS"]
