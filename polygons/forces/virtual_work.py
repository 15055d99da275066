"""Virtual work: with the velocities of a unit input rate, T_in = −Σ(F·v* + C ω*) over every
load and every inertia force and couple, term by term (the breakdown)."""
from __future__ import annotations

import math

from ..evaluate import Solution
from .model import ForceModel, Load, body_omega, image, inertias


def virtual_work(model: ForceModel, sol: Solution, vsol: Solution, lds: list[Load]
                 ) -> tuple[float, list[tuple[str, float]]]:
    """The input effort from the power balance with the velocities ``vsol`` of a unit input
    rate: T_in = −Σ P*, and each term's share (N m per source, inertia of each item)."""
    parts: dict[str, float] = {}
    for ld in lds:
        body = model.bodies[ld.body]
        p = ld.couple * body_omega(vsol, body)
        if ld.pos is not None and ld.force.any():
            p += float(ld.force @ image(vsol, body, ld.pos, "velocity"))
        key = f"{ld.kind} {ld.source}" if ld.kind != "gravity" else f"weight of {ld.item}"
        parts[key] = parts.get(key, 0.0) - p
    for it in inertias(model, sol):
        body = model.bodies[it.body]
        vg = image(vsol, body, it.centre, "velocity")
        wv = 0.0 if next(m for m in model.masses if m.name == it.item).free \
            else body_omega(vsol, body)
        parts[f"inertia force of {it.item} (m a_G)"] = float(it.ma @ vg)
        if it.inertia and it.alpha:
            parts[f"inertia torque of {it.item} (I_G α)"] = it.i_alpha * wv
    total = math.fsum(parts.values())
    return total, list(parts.items())
