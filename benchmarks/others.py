"""Adapters for the existing Python packages the benchmark compares against, on the same scenes
and the same crank angles: ``pylinkage`` (numba fast path and pure-Python path, positions,
velocities and accelerations) and ``mechanism`` (loop equations solved by scipy's fsolve at every
position).  Each is optional (``pip install -e .[bench]``); :func:`available` says which are
importable, and why not when not."""
from __future__ import annotations

import importlib
import math
import time

import numpy as np


def available() -> dict[str, str | None]:
    """name -> None if importable, else the reason (the benchmark reports it and skips)."""
    out = {}
    for name in ("pylinkage", "mechanism"):
        try:
            mod = importlib.import_module(name)
            out[name] = None
            if name == "pylinkage":
                from pylinkage.simulation import Linkage  # noqa: F401
                if not hasattr(Linkage, "step_fast_with_kinematics"):
                    out[name] = (f"pylinkage {getattr(mod, '__version__', '?')} has no "
                                 f"step_fast_with_kinematics (need >= 1.3)")
        except Exception as exc:  # ImportError, or a broken install
            out[name] = f"not importable ({type(exc).__name__}: {exc}); pip install -e .[bench]"
    return out


# ---------------------------------------------------------------- pylinkage
class PyLinkage:
    """One pylinkage Linkage for a benchmark mechanism (``p`` from closed_form.params)."""

    def __init__(self, p: dict, start_positions: dict):
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import RRPDyad, RRRDyad
        from pylinkage.simulation import Linkage

        self.p = p
        kind = p["kind"]
        piv = Ground(*p["pivot"], name="pivot")
        self.crank = Crank(anchor=piv, radius=p["r"], angular_velocity=0.0,
                           initial_angle=p["theta0"], name=p["tip"])
        comps = [piv]
        if kind == "four-bar":
            D = Ground(*p["D"], name="D")
            cx, cy = start_positions[p["C"]]
            self.out = RRRDyad(self.crank.output, D, distance1=p["b"], distance2=p["c"],
                               x=cx, y=cy, name=p["C"])
            comps += [D, self.crank, self.out]
        elif kind == "slider-crank":
            g = p["through"]
            e = (math.cos(p["psi"]), math.sin(p["psi"]))
            G1 = Ground(g[0], g[1], name="G1")
            G2 = Ground(g[0] + e[0], g[1] + e[1], name="G2")
            bx, by = start_positions[p["B"]]
            self.out = RRPDyad(self.crank.output, G1, G2, distance=p["L"], x=bx, y=by,
                               name=p["B"])
            comps += [G1, G2, self.crank, self.out]
        elif kind == "slotted-lever":
            # the slot: a point F on the lever at a fixed distance from its pivot, on the line
            # through the pivot and the pin (pylinkage has no pin-in-slot joint)
            B = Ground(*p["B"], name="B")
            self.far = 0.5
            ax, ay = start_positions[p["tip"]]
            d = math.hypot(ax - p["B"][0], ay - p["B"][1])
            fx = p["B"][0] + self.far * (ax - p["B"][0]) / d
            fy = p["B"][1] + self.far * (ay - p["B"][1]) / d
            self.out = RRPDyad(B, B, self.crank.output, distance=self.far, x=fx, y=fy,
                               name="F")
            comps += [B, self.crank, self.out]
        self.linkage = Linkage(comps, name=kind)
        self.linkage.set_input_velocity(self.crank, omega=p["omega"], alpha=p["alpha"])
        self.comps = comps

    def _place(self, theta: float) -> None:
        x0 = self.p["pivot"][0] + self.p["r"] * math.cos(theta)
        y0 = self.p["pivot"][1] + self.p["r"] * math.sin(theta)
        self.crank.x, self.crank.y = x0, y0

    def prepare(self, dtheta: float) -> None:
        """Set the crank's step (radians per iteration) and rebuild pylinkage's numba solver
        data, whose constraints hold that step (done outside the timings)."""
        if self.crank.angular_velocity != dtheta or self.linkage._solver_data is None:
            self.crank.angular_velocity = dtheta
            self.linkage.compile()

    def sweep_fast(self, theta_start: float, n: int, dtheta: float):
        """The numba path: ``n`` positions θ_start, θ_start + dθ, ... (the crank steps by
        angular_velocity each iteration, from the position before the first)."""
        self.prepare(dtheta)
        self._place(theta_start - dtheta)
        return self.linkage.step_fast_with_kinematics(iterations=n)

    def single_python(self, theta: float):
        """One position with derivatives on the pure-Python path."""
        self.prepare(0.0)
        self._place(theta)
        return next(self.linkage.step_with_derivatives(iterations=1))

    def single_fast(self, theta: float):
        """One position with derivatives on the numba path."""
        self.prepare(0.0)
        self._place(theta)
        return self.linkage.step_fast_with_kinematics(iterations=1)

    def outputs(self, pos, vel, acc) -> dict:
        """pylinkage's arrays (iterations, components, 2) -> the benchmark's named outputs."""
        p = self.p
        idx = {c: i for i, c in enumerate(self.comps)}
        ic, io = idx[self.crank], idx[self.out]
        P, V, A = pos[:, io].T, vel[:, io].T, acc[:, io].T
        Pc, Vc, Ac = pos[:, ic].T, vel[:, ic].T, acc[:, ic].T
        tip = p["tip"]
        out = {f"{tip}.x": Pc[0], f"{tip}.y": Pc[1], f"{tip}.vx": Vc[0], f"{tip}.vy": Vc[1],
               f"{tip}.ax": Ac[0], f"{tip}.ay": Ac[1]}
        if p["kind"] == "four-bar":
            C = p["C"]
            out |= {f"{C}.x": P[0], f"{C}.y": P[1], f"{C}.vx": V[0], f"{C}.vy": V[1],
                    f"{C}.ax": A[0], f"{C}.ay": A[1]}
            out |= _rates(P - np.array(p["D"])[:, None], V, A, p["rocker"])
            out |= _rates(P - Pc, V - Vc, A - Ac, p["coupler"])
        elif p["kind"] == "slider-crank":
            B = p["B"]
            e = np.array([math.cos(p["psi"]), math.sin(p["psi"])])
            out |= {f"{B}.x": P[0], f"{B}.y": P[1], f"{B}.vx": V[0], f"{B}.vy": V[1],
                    f"{B}.ax": A[0], f"{B}.ay": A[1],
                    f"{B}.v_s": e @ V, f"{B}.a_s": e @ A}
            out |= _rates(P - Pc, V - Vc, A - Ac, p["rod"])
        else:
            r = Pc - np.array(p["B"])[:, None]                # lever pivot -> pin
            rates = _rates(P - np.array(p["B"])[:, None], V, A, p["lever"])
            w, al = rates[f"{p['lever']}.omega"], rates[f"{p['lever']}.alpha"]
            s = np.hypot(*r)
            e = r / s
            A1 = p["A1"]
            out |= rates
            out |= {f"{A1}.vx": -w * r[1], f"{A1}.vy": w * r[0],
                    f"{A1}.ax": -al * r[1] - w * w * r[0], f"{A1}.ay": al * r[0] - w * w * r[1],
                    f"{tip}.v_s": (e * Vc).sum(0), f"{tip}.a_s": (e * Ac).sum(0) + w * w * s}
        return out


def _rates(r, v, a, name):
    n2 = r[0] * r[0] + r[1] * r[1]
    return {f"{name}.omega": (r[0] * v[1] - r[1] * v[0]) / n2,
            f"{name}.alpha": (r[0] * a[1] - r[1] * a[0]) / n2}


# ---------------------------------------------------------------- mechanism
class MechanismPkg:
    """The same mechanism in the ``mechanism`` package: vectors + loop equations, fsolve."""

    def __init__(self, p: dict, start_positions: dict):
        from mechanism import Mechanism, Vector, get_joints  # noqa: F401

        self.p = p
        kind = p["kind"]
        self.kind = kind
        self.start = start_positions
        self.Mechanism = Mechanism
        if kind == "four-bar":
            A, B, C, D = get_joints("A B C D")
            ad = math.hypot(p["D"][0] - p["pivot"][0], p["D"][1] - p["pivot"][1])
            th1 = math.atan2(p["D"][1] - p["pivot"][1], p["D"][0] - p["pivot"][0])
            a = Vector((A, B), r=p["r"])
            b = Vector((B, C), r=p["b"])
            c = Vector((D, C), r=p["c"])
            d = Vector((A, D), r=ad, theta=th1, style="ground")
            self.vectors, self.origin = (a, b, c, d), A
            self.loop = lambda x, i: a(i) + b(x[0]) - c(x[1]) - d()
            self.joints = {"B": B, "C": C}
            Cp, Bp = start_positions[p["C"]], start_positions[p["tip"]]
            self.guess0 = np.array([math.atan2(Cp[1] - Bp[1], Cp[0] - Bp[0]),
                                    math.atan2(Cp[1] - p["D"][1], Cp[0] - p["D"][0])])
            self.names = {"B": p["tip"], "C": p["C"]}
            self.links = {p["coupler"]: b, p["rocker"]: c}
        elif kind == "slider-crank":
            O, A, B, G = get_joints("O A B G")
            a = Vector((O, A), r=p["r"])
            b = Vector((A, B), r=p["L"])
            g = p["through"]
            s = Vector((G, B), theta=p["psi"], style="ground")
            if g[0] == 0 and g[1] == 0:
                s = Vector((O, B), theta=p["psi"], style="ground")
                self.loop = lambda x, i: a(i) + b(x[0]) - s(x[1])
                self.vectors = (a, b, s)
            else:
                gv = Vector((O, G), r=math.hypot(*g), theta=math.atan2(g[1], g[0]),
                            style="ground")
                self.loop = lambda x, i: a(i) + b(x[0]) - gv() - s(x[1])
                self.vectors = (a, b, gv, s)
            self.origin = O
            self.joints = {"A": A, "B": B}
            Bp, Ap = start_positions[p["B"]], start_positions[p["tip"]]
            s0 = (Bp[0] - g[0]) * math.cos(p["psi"]) + (Bp[1] - g[1]) * math.sin(p["psi"])
            self.guess0 = np.array([math.atan2(Bp[1] - Ap[1], Bp[0] - Ap[0]), s0])
            self.names = {"A": p["tip"], "B": p["B"]}
            self.links = {p["rod"]: b}
            self.slide = s
        else:
            O4, O2, P = get_joints("O4 O2 P")
            bx, by = p["B"]
            ox, oy = p["pivot"]
            o = Vector((O4, O2), r=math.hypot(ox - bx, oy - by),
                       theta=math.atan2(oy - by, ox - bx), style="ground")
            c = Vector((O2, P), r=p["r"])
            lev = Vector((O4, P))
            self.loop = lambda x, i: o() + c(i) - lev(x[0], x[1])
            self.vectors, self.origin = (o, c, lev), O4
            Ap = start_positions[p["tip"]]
            self.guess0 = np.array([math.hypot(Ap[0] - bx, Ap[1] - by),
                                    math.atan2(Ap[1] - by, Ap[0] - bx)])
            self.joints = {"P": P}
            self.names = {"P": p["tip"]}
            self.lever = lev
        self.guess = (self.guess0, np.array([1.0, 1.0]), np.array([1.0, 1.0]))

    def run(self, thetas: np.ndarray):
        p = self.p
        n = len(thetas)
        mech = self.Mechanism(vectors=self.vectors, origin=self.origin, loops=self.loop,
                              pos=np.asarray(thetas, dtype=float),
                              vel=np.full(n, p["omega"]), acc=np.full(n, p["alpha"]),
                              guess=self.guess)
        mech.iterate()
        return mech

    def outputs(self, mech) -> dict:
        p = self.p
        out = {}
        shift = np.array(p["B"] if self.kind == "slotted-lever" else p["pivot"])
        for key, j in self.joints.items():
            lab = self.names[key]
            out |= {f"{lab}.x": j.x_positions + shift[0], f"{lab}.y": j.y_positions + shift[1],
                    f"{lab}.vx": j.x_velocities, f"{lab}.vy": j.y_velocities,
                    f"{lab}.ax": j.x_accelerations, f"{lab}.ay": j.y_accelerations}
        if self.kind in ("four-bar", "slider-crank"):
            for name, vec in self.links.items():
                out[f"{name}.omega"] = vec.vel.omegas
                out[f"{name}.alpha"] = vec.acc.alphas
        if self.kind == "slider-crank":
            out[f"{p['B']}.v_s"] = self.slide.vel.r_dots
            out[f"{p['B']}.a_s"] = self.slide.acc.r_ddots
        if self.kind == "slotted-lever":
            lev = self.lever
            out[f"{p['lever']}.omega"] = lev.vel.omegas
            out[f"{p['lever']}.alpha"] = lev.acc.alphas
            out[f"{p['tip']}.v_s"] = lev.vel.r_dots
            out[f"{p['tip']}.a_s"] = lev.acc.r_ddots
        return out


def timed(fn, *args, repeat: int = 3):
    best, result = math.inf, None
    for _ in range(repeat):
        t = time.perf_counter()
        result = fn(*args)
        best = min(best, time.perf_counter() - t)
    return best, result
