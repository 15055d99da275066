"""Virtual work: with the velocities of a unit input rate, T_in = −Σ(F·v* + C ω*) over every
load and every inertia force and couple, term by term (the breakdown)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..evaluate import Solution
from .model import ForceModel, Load, body_omega, image, inertias


@dataclass(frozen=True)
class Share:
    """One term of the power balance: ``key`` an identifier (``force_Gas``, ``weight_BC``,
    ``inertia_force_P``, ``inertia_torque_BC``), ``words`` the same in words, ``value`` its
    share of the input effort (N m, or N for a slider driver)."""
    key: str
    words: str
    value: float


def virtual_work(model: ForceModel, sol: Solution, vsol: Solution, lds: list[Load]
                 ) -> tuple[float, list[Share]]:
    """The input effort from the power balance with the velocities ``vsol`` of a unit input
    rate: T_in = −Σ P*, and each term's share (N m per source, inertia of each item)."""
    parts: dict[str, float] = {}
    words: dict[str, str] = {}
    for ld in lds:
        body = model.bodies[ld.body]
        p = ld.couple * body_omega(vsol, body)
        if ld.pos is not None and ld.force.any():
            p += float(ld.force @ image(vsol, body, ld.pos, "velocity"))
        if ld.kind == "gravity":
            key, words[key] = f"weight_{ld.item}", f"weight of {ld.item}"
        else:
            key, words[key] = f"{ld.kind}_{ld.source}", f"{ld.kind} {ld.source}"
        parts[key] = parts.get(key, 0.0) - p
    for it in inertias(model, sol):
        body = model.bodies[it.body]
        vg = image(vsol, body, it.centre, "velocity")
        wv = 0.0 if next(m for m in model.masses if m.name == it.item).free \
            else body_omega(vsol, body)
        key = f"inertia_force_{it.item}"
        parts[key], words[key] = float(it.ma @ vg), f"inertia force of {it.item} (m a_G)"
        if it.inertia and it.alpha:
            key = f"inertia_torque_{it.item}"
            parts[key], words[key] = it.i_alpha * wv, f"inertia torque of {it.item} (I_G α)"
    total = math.fsum(parts.values())
    return total, [Share(k, words[k], v) for k, v in parts.items()]
