"""Velocities by the instantaneous centres (split from :mod:`polygons.centres`, which finds
the centres): a point X of link j moves at v = ω_j · I_1j X, perpendicular to I_1j X; ω_j
follows from a link i whose ω_i is known through the common point I_ij, whose velocity is the
same in both links: ω_i · I_1i I_ij = ω_j · I_1j I_ij.  A link whose I_1j is at infinity
translates (every point moves as I_ij); with I_ij at infinity, ω_j = ω_i.
"""
from __future__ import annotations

import math

from .centres_links import Omega, PointVelocity, Vec, _f, _t, sub
from .contacts import wheel_of
from .errors import UnsupportedError
from .kennedy import SAME, pair_name
from .scene import Crank
from .steps import sense


def _construction_points(solution, bods, carriers) -> dict[str, int]:
    """A point the construction places that no body carries (a triad's auxiliary point S) is
    a point of the one link carrying every other point its step places (the triad's plate)."""
    on: dict[str, set[int]] = {}
    for b in bods:
        for x in b.labels:
            on.setdefault(x, set()).add(b.number)
    out: dict[str, int] = {}
    for d in solution.plan.dyads:
        placed = tuple(d.placed)
        for x in placed:
            if x in carriers or x not in solution.placement.points:
                continue
            sets = [on[y] for y in placed if y != x and y in on]
            common = set.intersection(*sets) if sets else set()
            if len(common) == 1:
                out[x] = common.pop()
    return out


def _propagate(solution, bods, found, motion, omegas, names, size) -> None:
    """ω of every link from the driver's, through the centres it shares with links whose ω
    is known."""
    scene = solution.scene
    model = scene.model
    pos = solution.placement.points
    drv = scene.driver
    n2 = 2
    if isinstance(drv, Crank):
        c = found[(1, n2)]
        motion[n2] = (drv.omega, _v0(drv.omega, c.point))
        omegas[n2] = Omega(n2, names[n2], drv.omega, None, "given (the driver)", "given")
    elif model.body(drv.point).kind == "wheel":    # a driven wheel turns about its contact
        w = -drv.velocity / _wheel_radius(drv.point, scene)
        c = found[(1, n2)]
        motion[n2] = (w, _v0(w, c.point))
        omegas[n2] = Omega(n2, names[n2], w, None, "given (the driven wheel: ω = −v_W / r)",
                           "given")
    else:
        e = model.guide[drv.point].line.at(pos)[1]
        u = (drv.velocity * e[0], drv.velocity * e[1])
        motion[n2] = (0.0, u)
        omegas[n2] = Omega(n2, names[n2], 0.0, u, "given (the driver translates)", "given",
                           speed=abs(drv.velocity))
    adj: dict[int, list[int]] = {b.number: [] for b in bods}
    for (i, j) in sorted(found):
        adj[i].append(j)
        adj[j].append(i)
    todo = [b.number for b in bods if b.number not in motion]
    while todo:
        left = []
        for j in todo:
            if (1, j) not in found:
                left.append(j)
                continue
            for i in adj[j]:
                if i == 1 or i not in motion:
                    continue
                res = _omega_from(i, j, motion[i], found, names, size)
                if res is not None:
                    motion[j], omegas[j] = res
                    break
            else:
                left.append(j)
        if len(left) == len(todo):
            named = ", ".join(names[j] for j in left[:4]) + (
                f" and {len(left) - 4} more" if len(left) > 4 else "")
            raise UnsupportedError(f"the centres do not give the angular velocity of {named} "
                                   f"at this instant (each shares its centres with the frame "
                                   f"and the links of known ω at one point)", file=scene.file)
        todo = left


def _v0(omega: float, centre: Vec) -> Vec:
    """v0 of the field v(P) = ω k × (P − centre) = v0 + ω k × P."""
    return (omega * centre[1], -omega * centre[0])


def _at(m, p) -> Vec:
    w, v0 = m
    return (v0[0] - w * p[1], v0[1] + w * p[0])


def _omega_from(i, j, mi, found, names, size):
    """ω_j from ω_i through I_ij (the same velocity in both links), or None."""
    cij, c1j = found[(min(i, j), max(i, j))], found[(1, j)]
    wi = mi[0]
    nij, n1j = sub(pair_name(min(i, j), max(i, j))), sub(pair_name(1, j))
    if cij.point is not None:
        v = _at(mi, cij.point)
        if c1j.point is None:           # link j translates: every point moves as I_ij
            return (0.0, v), Omega(j, names[j], 0.0, v, (
                f"I{n1j} at infinity: link {j} translates with v_I{nij} = "
                f"{_f(math.hypot(*v))} m/s"), "translates", i, math.hypot(*v))
        r = (cij.point[0] - c1j.point[0], cij.point[1] - c1j.point[1])
        rr = r[0] * r[0] + r[1] * r[1]
        if math.sqrt(rr) <= SAME * size:
            return None                 # I_ij on I_1j: this pair does not fix ω_j
        wj = (r[0] * v[1] - r[1] * v[0]) / rr
        if found[(1, i)].point is None:
            vi = f"v_I{nij} = v of link {i} (it translates) = {_f(math.hypot(*v))} m/s"
        else:
            vi = (f"v_I{nij} = ω{sub(i)} · I{sub(pair_name(1, i))}I{nij} = "
                  f"{_f(math.hypot(*v))} m/s")
        return (wj, _v0(wj, c1j.point)), Omega(j, names[j], wj, None, (
            f"{vi}; ω{sub(j)} = v_I{nij} / I{n1j}I{nij} = {_f(math.hypot(*v))} / "
            f"{_f(math.sqrt(rr))} = {_f(abs(wj))} rad/s {sense(wj)}".rstrip()), "ratio", i,
            math.hypot(*v), math.sqrt(rr))
    if cij.direction is None or c1j.point is None:
        return None
    # I_ij at infinity: links i and j translate relative to each other, ω_j = ω_i
    return (wi, _v0(wi, c1j.point)), Omega(j, names[j], wi, None, (
        f"I{nij} at infinity: ω{sub(j)} = ω{sub(i)} = {_f(abs(wi))} rad/s {sense(wi)}".rstrip()),
        "same", i)


def _point_velocity(x, j, p, motion, found, names) -> PointVelocity:
    if j == 1:
        return PointVelocity(x, 1, (0.0, 0.0), 0.0, None, f"v_{x} = 0 (a fixed point)")
    w, v0 = motion[j]
    c = found[(1, j)]
    if c.point is None:
        v = v0
        return PointVelocity(x, j, _t(v), math.hypot(*v), None,
                             f"v_{x} = v{sub(j)} = {_f(math.hypot(*v))} m/s ({names[j]} "
                             f"translates: I{sub(pair_name(1, j))} at infinity)", 0.0)
    r = (p[0] - c.point[0], p[1] - c.point[1])
    v = (-w * r[1], w * r[0])
    rad = math.hypot(*r)
    return PointVelocity(x, j, _t(v), abs(w) * rad, rad, (
        f"v_{x} = ω{sub(j)} · I{sub(pair_name(1, j))}{x} = {_f(abs(w))} × {_f(rad)} = "
        f"{_f(abs(w) * rad)} m/s"), w)


def _wheel_radius(label, scene) -> float:
    """The radius of the rolling wheel centred at ``label`` (a driven wheel's body)."""
    return wheel_of(scene, label).radius
