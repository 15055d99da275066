"""``polygons forces``: the force polygons per Assur group and Zhukovsky's lever, as text and
JSON (:mod:`polygons.forces.graphical`, :mod:`polygons.forces.zhukovsky`)."""
from __future__ import annotations

import math

import numpy as np

from ..errors import UnsupportedError
from ..forces import effort, graphical, zhukovsky
from ..forces import words as force_words


def _deg(v) -> float:
    return round(math.degrees(math.atan2(v[1], v[0])), 2) % 360.0


def _vec(v) -> list[float]:
    return [float(v[0]), float(v[1])]


def polygons_of(an, st):
    """The force polygons of ``st``, or the one-line reason they are refused."""
    try:
        return graphical.construct(an, st), None
    except UnsupportedError as e:
        return None, (e.args[0] if e.args else str(e))


def _found(f) -> dict:
    return {"name": f.name, "on": f.body, "at": f.at, "direction": _vec(f.direction),
            "value": f.value, "how": f.how, "force": _vec(f.force)}


def _difference(fp, st) -> float:
    """The largest difference from Newton–Euler over the pin and slot forces (N)."""
    d = [float(np.hypot(*(fp.pin[k] - v))) for k, v in st.ne.pin.items()]
    d += [float(np.hypot(*(fp.slot[k][0] * fp.slot[k][1] - v * n)))
          for k, (v, n) in st.ne.slot.items() if k in (fp.slot or {})]
    return max(d, default=0.0)


def polygons_dict(an, st) -> dict:
    fp, why = polygons_of(an, st)
    if fp is None:
        return {"refused": why}
    groups = []
    for g in fp.groups:
        groups.append({
            "group": g.index, "kind": g.kind, "title": g.title, "bodies": list(g.bodies),
            "knowns": [{"name": k.name, "kind": k.kind, "on": k.body, "force": _vec(k.force),
                        "at": None if k.pos is None else _vec(k.pos), "couple": k.couple,
                        "inertia_offset_h": k.offset} for k in g.knowns],
            "by_moments": [_found(f) for f in g.normals],
            "closing": [_found(f) for f in g.closing],
            "reactions": [_found(f) for f in g.reactions],
            "moments": list(g.moments)})
    return {"groups": groups, "effort": fp.effort, "unit": effort.unit(an.model),
            "pins": [{"key": f"pin_{lab}_on_{b}", "force": _vec(f)}
                     for (lab, b), f in fp.pin.items()],
            "slots": [{"pin": pin, "normal_force_on_lever": v, "unit_normal": _vec(n)}
                      for pin, (v, n) in (fp.slot or {}).items()],
            "largest_difference_from_newton_euler_N": _difference(fp, st)}


def lever_dict(an, st) -> dict:
    try:
        lv = zhukovsky.construct(an, st)
    except UnsupportedError as e:
        return {"refused": e.args[0] if e.args else str(e)}

    def one(a):
        return {"name": a.name, "kind": a.kind, "on": a.body, "force": _vec(a.force),
                "at": _vec(a.at), "label": a.label, "image_turned": _vec(a.lever),
                "moment_about_pole": a.moment}
    return {"unit_rate_polygon": lv.unit_rate, "applied": [one(a) for a in lv.applied],
            "effort_forces": [one(a) for a in lv.effort_forces], "effort": lv.effort,
            "unit": effort.unit(an.model), "words": effort.words(an.model),
            "moment_sum": lv.moment_sum, "unit_effort_moment": lv.unit_moment,
            "virtual_work": st.vw_effort, "difference": lv.effort - (st.vw_effort or 0.0)}


def _f(x: float) -> str:
    return f"{x:.6g}"


def polygons_lines(an, st) -> list[str]:
    fp, why = polygons_of(an, st)
    out = ["  force polygons per Assur group (the group furthest from the driver first):"]
    if fp is None:
        return out + [f"    refused: {why}"]
    for g in fp.groups:
        out.append(f"    {g.title}")
        for k in g.knowns:
            if k.pos is not None and k.force.any():
                extra = f", offset h = {k.offset * 1e3:.4g} mm" if k.kind == "inertia" else ""
                out.append(f"      known: {k.name} {_f(float(np.hypot(*k.force)))} N ∠"
                           f"{_deg(k.force):.2f}° on {k.body}{extra}")
            if k.couple:
                out.append(f"      known: {k.name} couple {graphical.moment_words(k.couple)} "
                           f"on {k.body}")
        for m in g.moments:
            out.append(f"      {m}")
        for f in g.normals:
            out.append(f"      by moments: {f.name} = {graphical.found_words(f)} "
                       f"({f.along})")
        for f in g.closing:
            if f.how == "effort":
                continue
            out.append(f"      the polygon closes on: {f.name} = {_f(abs(f.value))} N ∠"
                       f"{_deg(f.force) if f.value else _deg(f.direction):.2f}°")
        for f in g.reactions:
            if f.how == "reaction":
                what = ("diagonal" if g.kind in graphical.DYAD_KINDS or g.kind == "triad"
                        else "passed on by the light block")
                out.append(f"      {what}: {f.name} = {_f(f.value)} N ∠"
                           f"{_deg(f.direction):.2f}°")
            elif f.how == "joint":
                out.append(f"      at the joint: {f.name} = {_f(f.value)} N ∠"
                           f"{_deg(f.direction):.2f}°")
    diff = _difference(fp, st)
    words = force_words.effort_words(an.model, fp.effort, st.sol)
    out.append(f"    {effort.words(an.model)}: {words}; every reaction equals Newton–Euler's "
               f"(largest difference {diff:.1e} N)")
    return out


def lever_lines(an, st) -> list[str]:
    try:
        lv = zhukovsky.construct(an, st)
    except UnsupportedError as e:
        return ["  Zhukovsky's lever:", f"    refused: {e.args[0] if e.args else e}"]
    out = ["  Zhukovsky's lever (the velocity polygon turned 90° CCW, pivoted at the pole"
           + (", drawn for a unit input rate: the input is at rest)" if lv.unit_rate else ")")
           + ":",
           f"    {'force':<26} {'N':>11} {'∠°':>8} {'applied at image':>22} "
           f"{'moment about o, N m/s':>22}"]
    for a in lv.applied + lv.effort_forces:
        img = f"({a.lever[0] + 0.0:.4g}, {a.lever[1] + 0.0:.4g})"
        out.append(f"    {a.name[:26]:<26} {_f(float(np.hypot(*a.force))):>11} "
                   f"{_deg(a.force) if a.force.any() else 0:>8.2f} {img:>22} "
                   f"{force_words.table_moment(a.moment):>22}")
    out.append(f"    {force_words.lever_sum_words(an.model, lv)}: {effort.words(an.model)} = "
               f"{force_words.effort_words(an.model, lv.effort, st.sol, 10)}; virtual work "
               f"{force_words.effort_words(an.model, st.vw_effort, st.sol, 10)} "
               f"(difference {abs(lv.effort - st.vw_effort):.1e})")
    return out
