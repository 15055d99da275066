"""A one-degree-of-freedom mechanism released at the scene's instant (``[dynamics] mode =
"release"``): its state at the release and after each rotation in ``after``.

The crank driver's angle is the coordinate θ.  At any (θ, ω) the angular acceleration comes
from the torque-driven Newton–Euler solve (:mod:`polygons.forces.newton_euler`: two kinematic
solutions, α = 0 and α = 1, the acceleration polygon being affine in α), so the same code
serves every mechanism the kinematics can draw.  The state after a rotation is found twice:

* energy:  T(θ) + V(θ) = T₀ + V₀ + W_nc, with T = ½ ω² Σ(m v*_G² + I_G ω*²) from the velocity
  polygon of a unit input rate, V from gravity and the springs, and W_nc the work of the applied
  forces and torques and of the friction torques (−T_f |Δφ|, valid while each pin turns one
  way);
* integration: fourth-order Runge–Kutta in time on (θ, ω), the last step shortened to land on
  the target angle.

They must agree (the tests hold them to 1e-7); the energy value is the one reported.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import UnsupportedError
from ..evaluate import Solution, solve
from ..scene import Crank, Scene
from .model import (ForceModel, body_angle, body_omega, centre, image, position as _pos,
                    rel_angle as _rel_angle, spring_state, wrap as _wrap)
from .newton_euler import newton_euler
from .states import Analysis, driver_state, torque_driven, virtual_solution


def kinetic_per_unit_rate(model: ForceModel, vsol: Solution) -> float:
    """T / ω_in² (the free discs' constant spin energy left out)."""
    t = 0.0
    for it in model.masses:
        body = model.bodies[it.body]
        g = centre(model, vsol, it)
        v = image(vsol, body, g, "velocity")
        t += 0.5 * it.mass * float(v @ v)
        if not it.free:
            w = body_omega(vsol, body)
            t += 0.5 * it.inertia * w * w
    return t


def spin_energy(model: ForceModel) -> float:
    return sum(0.5 * it.inertia * it.spin ** 2 for it in model.masses
               if it.free and it.spin is not None)


def potential(model: ForceModel, sol: Solution) -> float:
    v = 0.0
    for it in model.masses:
        v -= it.mass * float(model.gravity @ centre(model, sol, it))
    for s in model.springs:
        v += spring_state(model, sol, s)["energy"]
    return v


def work_nc(model: ForceModel, sol: Solution, sol0: Solution) -> float:
    """Work of the applied forces and torques and of friction from ``sol0`` to ``sol``."""
    w = 0.0
    for f in model.forces:
        w += float(np.array(f.force) @ (_pos(sol, f.at) - _pos(sol0, f.at)))
    for t in model.torques:
        b = model.bodies[t.body]
        w += t.torque * _wrap(body_angle(sol, b) - body_angle(sol0, b))
    for fr in model.frictions:
        d = _wrap(_rel_angle(model, sol, fr.first, fr.second)
                  - _rel_angle(model, sol0, fr.first, fr.second))
        w -= fr.torque * abs(d)
    return w


def _alpha(model: ForceModel, scene: Scene, theta: float, omega: float, motion: int) -> float:
    s = driver_state(scene, angle=theta, omega=omega, alpha=0.0)
    sol0 = solve(s)
    sol1 = solve(driver_state(scene, angle=theta, omega=omega, alpha=1.0))
    vsol = virtual_solution(s) if omega == 0.0 else sol0
    return newton_euler(model, sol0, vsol, sol1, motion=motion).alpha


def _rk4(f, y, h):
    k1 = f(y)
    k2 = f(y + 0.5 * h * k1)
    k3 = f(y + 0.5 * h * k2)
    k4 = f(y + h * k3)
    return y + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)


def integrate(model: ForceModel, scene: Scene, motion: int, targets: list[float],
              t_guess: list[float], steps: int) -> list[dict]:
    """RK4 in time from the release to each target angle (absolute θ, in the sense
    ``motion``); returns θ, ω, t at each."""
    drv: Crank = scene.driver  # type: ignore[assignment]

    def f(y):
        return np.array([y[1], _alpha(model, scene, float(y[0]), float(y[1]), motion)])

    y = np.array([drv.angle, drv.omega])
    t = 0.0
    out = []
    prev_target_time = 0.0
    for target, tg in zip(targets, t_guess):
        h = max(tg - prev_target_time, 1e-9) / steps
        n = 0
        while True:
            y_next = _rk4(f, y, h)
            n += 1
            if motion * y_next[1] < 0 or (y[1] != 0 and motion * y[1] < 0):
                raise UnsupportedError(
                    f"the mechanism stops and turns back after "
                    f"{abs(math.degrees(y_next[0] - drv.angle)):.4g}° of rotation, before "
                    f"reaching {abs(math.degrees(target - drv.angle)):.4g}°",
                    file=scene.file, where="dynamics.after")
            if motion * (y_next[0] - target) >= 0:
                # shorten the last step to land on the target (secant on the step length)
                h0, h1 = 0.0, h
                g0, g1 = y[0] - target, y_next[0] - target
                for _ in range(60):
                    if g1 == g0:
                        break
                    h2 = h1 - g1 * (h1 - h0) / (g1 - g0)
                    h2 = min(max(h2, 0.0), h)
                    y2 = _rk4(f, y, h2)
                    h0, g0, h1, g1 = h1, g1, h2, y2[0] - target
                    if abs(g1) <= 1e-14 * max(1.0, abs(target)):
                        break
                y = _rk4(f, y, h1)
                t += h1
                break
            y, t = y_next, t + h
            if n > 50 * steps:
                raise UnsupportedError(f"the integration did not reach "
                                       f"{math.degrees(target - drv.angle):.4g}° in "
                                       f"{50 * steps} steps", file=scene.file,
                                       where="dynamics.after")
        out.append({"theta": float(y[0]), "omega": float(y[1]), "time": float(t), "steps": n})
        prev_target_time = t
    return out


def release(model: ForceModel, scene: Scene) -> Analysis:
    drv: Crank = scene.driver  # type: ignore[assignment]
    st0 = torque_driven(model, scene, "release")
    a0 = st0.extra["alpha_in"]
    if drv.omega != 0.0:
        motion = 1 if drv.omega > 0 else -1
    elif a0 != 0.0:
        motion = 1 if a0 > 0 else -1
    else:
        raise UnsupportedError("released here the mechanism stays at rest (no net torque)",
                               file=scene.file, where="dynamics")
    if model.frictions:   # the release state with friction opposing the motion that starts
        st0 = torque_driven(model, scene, "release", motion=motion)
    sol_ref = st0.sol
    k0 = kinetic_per_unit_rate(model, st0.vsol)
    e_spin = spin_energy(model)
    t0 = k0 * drv.omega ** 2
    v0 = potential(model, sol_ref)
    st0.extra.update({"kinetic": t0 + e_spin, "potential": v0, "work_nc": 0.0,
                      "omega_energy": drv.omega, "omega_ode": drv.omega, "time": 0.0})
    states = [st0]
    targets = [drv.angle + motion * a for a in model.after]
    checks = []
    energy = []
    for a, th in zip(model.after, targets):
        s = driver_state(scene, angle=th, omega=0.0, alpha=0.0)
        vsol = virtual_solution(s)
        sol = solve(s)
        k = kinetic_per_unit_rate(model, vsol)
        v = potential(model, sol)
        w = work_nc(model, sol, sol_ref)
        w2 = (t0 + v0 - v + w) / k if k > 0 else float("nan")
        if not w2 >= 0:
            raise UnsupportedError(f"the energy runs out before the driver turns by "
                                   f"{math.degrees(a):.4g}° (T would be negative)",
                                   file=scene.file, where="dynamics.after")
        energy.append({"rotation": a, "theta": th, "omega": motion * math.sqrt(w2),
                       "kinetic": k * w2 + e_spin, "potential": v, "work_nc": w})
    # time guesses for the step size: constant acceleration between the known speeds
    guesses = []
    prev_w, prev_th, t = drv.omega, drv.angle, 0.0
    for e in energy:
        mean = 0.5 * (abs(prev_w) + abs(e["omega"]))
        dt = abs(e["theta"] - prev_th) / mean if mean > 0 else math.sqrt(
            2 * abs(e["theta"] - prev_th) / max(abs(a0), 1e-12))
        t += dt
        guesses.append(t)
        prev_w, prev_th = e["omega"], e["theta"]
    ode = integrate(model, scene, motion, targets, guesses, model.steps) if targets else []
    for e, o in zip(energy, ode):
        name = f"after {math.degrees(e['rotation']):g} deg"
        st = torque_driven(model, driver_state(scene, angle=e["theta"], omega=e["omega"]),
                           name, motion=motion)
        rel = abs(o["omega"] - e["omega"]) / max(abs(e["omega"]), 1e-300)
        st.rotation = e["rotation"]
        st.extra.update({"kinetic": e["kinetic"], "potential": e["potential"],
                         "work_nc": e["work_nc"], "omega_energy": e["omega"],
                         "omega_ode": o["omega"], "time": o["time"], "ode_steps": o["steps"],
                         "energy_vs_ode_rel": rel})
        states.append(st)
        checks.append({"state": name, "rotation_deg": math.degrees(e["rotation"]),
                       "omega_energy": e["omega"], "omega_ode": o["omega"],
                       "relative_difference": rel, "time_s": o["time"],
                       "rk4_steps": o["steps"]})
    return Analysis(model, states, {"motion": "CCW" if motion > 0 else "CW",
                                    "checks": checks})
