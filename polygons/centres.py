"""Instantaneous centres of a solved mechanism, found the drawing-board way (Kennedy's theorem).

    I_ij: the point common to links i and j that has the same velocity in both.
    Kennedy: the three centres I_ij, I_jk, I_ik of any three links lie on one straight line.

The links are the bodies of the mechanism model (:mod:`polygons.model`), numbered as a
textbook numbers them: 1 the frame, 2 the driver, then in the order the construction places
them (the plan's dyads: a body is numbered when the points it turns on are placed, so the block
of Fig 7's crank pin is 3 and the slotted link 4), or as the scene's ``[centres] numbers`` says.

The *primary* centres are read off the pairs: a turning pair is the centre of the bodies it
joins; a sliding pair (a block on a fixed guide, a block in a slot, a collar on a rod) has its
centre at infinity perpendicular to the line it slides on.  The others come from the circle
diagram (:mod:`polygons.kennedy`): I_ij where two lines of centres I_ik–I_kj meet, points at
infinity included (the line through two centres at infinity is the line at infinity).

Velocities by the centres: a point X of link j moves at v = ω_j · I_1j X, perpendicular to
I_1j X; ω_j follows from a link i whose ω_i is known through the common point I_ij, whose
velocity is the same in both links: ω_i · I_1i I_ij = ω_j · I_1j I_ij.

A mechanism with a second input given at the instant (a prescribed slide: two degrees of
freedom) has no unique centres from the joints alone: each body's centre I_1j is then read off
its velocity field (the polygon's velocities of two of its points: ω, and the point of zero
velocity), said so in words; the joints and Kennedy give the rest.

A large mechanism (more than :data:`FULL_BODIES` bodies) is solved in small windows, step by
step in the construction's order: only the centres the velocities need (and every primary
centre) are found, not all n(n − 1)/2.
"""
from __future__ import annotations

import math
from types import MappingProxyType

from .errors import UnsupportedError
from .kennedy import SAME, canonical, kennedy, pair_name
from .model import BODY_KINDS, FRAME, check_handles
# the links and the records (numbering, Body, Centre, ...) and the velocities by the centres,
# split out; their names re-exported for the callers
from .centres_links import (Body, Centre, Centres, Omega, PointVelocity, Vec,  # noqa: F401
                            _size, _t, bodies, rigid_groups, sub)
from .centres_velocity import _construction_points, _point_velocity, _propagate, _wheel_radius


#: the kinds of body and pair the centres handle (a rolling or cam pair is refused in words)
HANDLES = frozenset(BODY_KINDS) | {"turning", "sliding"}
#: up to this many bodies every centre is found (the full circle diagram); beyond, only those
#: the velocities need
FULL_BODIES = 16


# ---------------------------------------------------------------- primary centres
def _primary(solution, bods: tuple[Body, ...]) -> dict[tuple[int, int], Centre]:
    """The centres read off the pairs: pins, and sliding pairs at infinity."""
    model = solution.scene.model
    pos = solution.placement.points
    num = {b.key: b.number for b in bods}
    for b in bods:          # the bodies fixed to one (a plate's other links): its number
        for m in b.fixed:
            num.setdefault(m, b.number)
    names = {b.number: b.name for b in bods}
    known: dict[tuple[int, int], Centre] = {}
    for t in model.turning:
        if t.label not in pos:
            continue
        nums = sorted({num[b] for b in t.bodies if b in num})
        for a in range(len(nums)):
            for c in range(a + 1, len(nums)):
                i, j = nums[a], nums[c]
                if (i, j) not in known:
                    known[(i, j)] = Centre(i, j, (names[i], names[j]), _t(pos[t.label]), None,
                                           f"pin {t.label}", True, 0)
    for s in model.sliding:
        if s.block not in num or s.carrier not in num:
            continue
        i, j = sorted((num[s.block], num[s.carrier]))
        if i == j or (i, j) in known:
            continue
        e = s.line.at(pos)[1]
        d = canonical((-e[1], e[0]))
        block = model.body(s.block).title
        if s.carrier == FRAME and model.body(s.block).kind == "wheel":
            r = _wheel_radius(model.body(s.block).a, solution.scene)
            W = pos[s.at]                         # rolling: the contact, at rest
            known[(i, j)] = Centre(i, j, (names[i], names[j]),
                                   _t((W[0] + r * e[1], W[1] - r * e[0])), None,
                                   f"wheel {s.at} rolling: the contact with the fixed surface",
                                   True, 0)
            continue
        if s.carrier == FRAME:
            how = f"{block} on its guide: at infinity ⟂ the guide"
        elif s.prescribed:
            how = f"{block} along {s.carrier}: at infinity ⟂ {s.carrier}"
        elif " in " in block:
            how = f"{block}: at infinity ⟂ the slot"
        else:
            how = f"{block} in the slot of {model.body(s.carrier).title}: at infinity ⟂ the slot"
        known[(i, j)] = Centre(i, j, (names[i], names[j]), None, d, how, True, 0)
    return known


# ---------------------------------------------------------------- Kennedy
def find_centres(solution) -> tuple[tuple[Body, ...], tuple[Centre, ...]]:
    """The centres of the solved mechanism (see :func:`instant_centres`) and its links."""
    cs = _find(solution)
    return cs[0], tuple(cs[1][k] for k in sorted(cs[1]))


def _find(solution):
    check_handles("polygons centres", HANDLES, solution.scene.model, solution.scene.file)
    bods = bodies(solution)
    n = len(bods)
    names = {b.number: b.name for b in bods}
    size = _size(solution)
    known = _primary(solution, bods)
    two_inputs = len(solution.scene.model.inputs) > 1
    motion = _field(solution, bods) if two_inputs else None
    if motion is not None:              # each body's centre I_1j from its velocity field
        for b in bods[1:]:
            if (1, b.number) not in known:
                known[(1, b.number)] = _field_centre(1, b.number, motion, names, size)
    counter = [0]

    def close(window) -> None:
        window = sorted(window)
        changed = True
        while changed:
            changed = False
            for a, i in enumerate(window):
                for j in window[a + 1:]:
                    if (i, j) in known:
                        continue
                    f = kennedy(i, j, window, known, size)
                    if f is None:
                        continue
                    counter[0] += 1
                    (k1, k2) = f.via
                    how = (f"Kennedy: {pair_name(i, j)} on {pair_name(i, k1)}–"
                           f"{pair_name(k1, j)} and {pair_name(i, k2)}–{pair_name(k2, j)}"
                           + (" (parallel: at infinity)" if f.point is None and
                              f.angle_deg == 0.0 else
                              " (meeting the line at infinity)" if f.point is None else ""))
                    known[(i, j)] = Centre(i, j, (names[i], names[j]), f.point, f.direction,
                                           how, False, counter[0], f.lines, f.angle_deg)
                    changed = True

    if n <= FULL_BODIES:
        close(range(1, n + 1))
    else:
        _windows(solution, bods, known, close)
    open_ = [b.number for b in bods[1:] if (1, b.number) not in known]
    partial = False
    if open_ and motion is None and "velocity" in solution.scene.solve:
        # Kennedy leaves these open (the links of a group of three on a plate — a class-III
        # group — or a toggle): each one's centre from its velocity field, said so; Kennedy
        # then gives what it can from them
        motion, partial = _field(_moving(solution), bods), True
        for j in open_:
            known[(1, j)] = _field_centre(1, j, motion, names, size, open_=True)
        close(range(1, n + 1) if n <= FULL_BODIES else
              {1} | set(open_) | {k for (i, k) in list(known) if i in open_}
              | {i for (i, k) in list(known) if k in open_})
    if motion is not None and n <= FULL_BODIES:     # whatever is left, from the fields
        for i in range(1, n + 1):
            for j in range(i + 1, n + 1):
                if (i, j) not in known:
                    known[(i, j)] = _field_centre(i, j, motion, names, size, open_=partial)
    missing = [f"I{pair_name(1, b.number)}" for b in bods[1:] if (1, b.number) not in known]
    if missing:
        named = ", ".join(missing[:4]) + (f" and {len(missing) - 4} more" if len(missing) > 4
                                          else "")
        raise UnsupportedError(f"Kennedy's theorem does not fix the centre"
                               f"{'s' if len(missing) > 1 else ''} {named} of this mechanism "
                               f"at this instant (no two distinct lines of centres meet there: "
                               f"a toggle, or links locked together)", file=solution.scene.file)
    return bods, known, (None if partial else motion), size


def _windows(solution, bods, known, close) -> None:
    """Kennedy link by link in the construction's order: for each newly numbered link, the
    window of it, the links whose centre I_1j is still unknown, the links they are paired
    with and the frame; at the end, windows widened by neighbours around any link whose I_1j
    is still unknown, then (only if that fails) the whole diagram."""
    nb: dict[int, set[int]] = {b.number: set() for b in bods}
    for (i, j), c in known.items():
        if c.primary:
            nb[i].add(j)
            nb[j].add(i)
    pending: set[int] = set()
    numbered: set[int] = {1}

    def around(xs) -> set[int]:
        out = {1} | set(xs)
        for x in xs:
            if x != 1:
                out |= nb[x] & numbered
        return out

    for b in bods[1:]:
        numbered.add(b.number)
        pending.add(b.number)
        close(around(pending))
        pending = {j for j in pending if (1, j) not in known}
    window = around(pending)
    for _ in range(8):
        if not pending:
            return
        close(window)
        pending = {j for j in pending if (1, j) not in known}
        grown = around(window)
        if grown == window:
            break
        window = grown
    if pending:                          # still unknown: the whole diagram, once
        close(range(1, len(bods) + 1))


# ---------------------------------------------------------------- two inputs: velocity fields
def _field(solution, bods):
    """Each body's motion (ω, v0), v(P) = v0 + ω k × P, from the polygon's velocities: ω from
    two of its points (a block turns with what it slides on), v0 from one."""
    scene = solution.scene
    if "velocity" not in scene.solve:
        raise UnsupportedError("instant centres of a mechanism with two inputs are read off the "
                               "velocity polygon: solve the velocities too (solve = "
                               "[\"velocity\", ...])", file=scene.file)
    model = scene.model
    pos = solution.placement.points
    pts = solution.points
    out: dict[int, tuple[float, Vec, str]] = {1: (0.0, (0.0, 0.0), "")}
    by_key = {b.key: b for b in bods}
    for b in bods[0].fixed:
        by_key[b] = bods[0]

    def omega_of(body) -> tuple[float, str]:
        if body.key == FRAME or body.number == 1:
            return 0.0, ""
        labels = [x for x in body.labels if x in pos]
        if len(labels) >= 2:
            a, c = labels[0], labels[1]
            r = (pos[c][0] - pos[a][0], pos[c][1] - pos[a][1])
            va, vc = pts[a].velocity, pts[c].velocity
            w = (r[0] * (vc[1] - va[1]) - r[1] * (vc[0] - va[0])) / (r[0] ** 2 + r[1] ** 2)
            return w, f"ω{sub(body.number)} from v_{a} and v_{c}"
        s = model.slide_of(body.key)
        if s is None:
            return 0.0, ""
        carrier = by_key[s.carrier]
        w, _ = omega_of(carrier)
        return w, f"ω{sub(body.number)} = ω{sub(carrier.number)} (it slides on {carrier.name})"

    for b in bods[1:]:
        w, how = omega_of(b)
        a = b.labels[0]
        v = pts[a].velocity
        p = pos[a]
        out[b.number] = (w, (v[0] + w * p[1], v[1] - w * p[0]), how + f", v_{a}")
    return out


def _moving(solution):
    """``solution``, or — the mechanism at rest (every velocity zero: ω = 0) — the same pose
    driven at a unit rate: a centre is where the velocity *ratios* put it, the same at any
    rate, and at rest the polygon has no field to read them from."""
    from dataclasses import replace
    pts = solution.points.values()
    if any(p.velocity is not None and (p.velocity[0] or p.velocity[1]) for p in pts):
        return solution
    scene, drv = solution.scene, solution.scene.driver
    rate = next((k for k in ("omega", "velocity") if getattr(drv, k, None) == 0.0), None)
    if rate is None:
        return solution
    from .evaluate import solve
    return solve(replace(scene, driver=replace(drv, **{rate: 1.0})))


def _field_centre(i, j, motion, names, size, open_: bool = False) -> Centre:
    """I_ij where the two velocity fields agree: the relative motion's point of zero
    velocity, or at infinity ⟂ the relative velocity when the two turn alike.  ``open_``:
    read off the fields because Kennedy's theorem leaves it open (one input), not because
    two inputs are given."""
    wi, vi, hi = motion[i]
    wj, vj, hj = motion[j]
    dw = wj - wi
    dv = (vj[0] - vi[0], vj[1] - vi[1])
    why = "; ".join(h for h in (hi, hj) if h)
    cause = ("Kennedy's theorem leaves it open: no two distinct lines of centres meet there"
             if open_ else "two inputs given")
    speed = max(math.hypot(*dv), abs(dw) * size)
    if abs(dw) * size > SAME * speed and speed > 0:
        p = (-dv[1] / dw, dv[0] / dw)
        how = (f"from the velocity field ({cause}; the point of zero "
               f"{'velocity' if i == 1 else 'relative velocity'}: {why})")
        return Centre(i, j, (names[i], names[j]), p, None, how, False, 0, (), None, True)
    if math.hypot(*dv) > 0:
        return Centre(i, j, (names[i], names[j]), None, canonical((-dv[1], dv[0])),
                      f"from the velocity field ({cause}; {names[j]} translates "
                      f"relative to {names[i]}: {why})", False, 0, (), None, True)
    return Centre(i, j, (names[i], names[j]), None, None,
                  f"{names[i]} and {names[j]} have no relative motion at this instant: every "
                  f"point is a centre", False, 0, (), None, True)


# ---------------------------------------------------------------- velocities by the centres
def instant_centres(solution, points=None) -> Centres:
    """The centres, every link's ω and the velocities of ``points`` (default: every placed
    point) by the centres.  ``solution`` is a :class:`polygons.evaluate.Solution`; with one
    input only its positions, its plan and the driver's input are used, never its polygon
    (with two, each body's centre comes from the polygon's velocity field, said so)."""
    bods, found, field, size = _find(solution)
    scene = solution.scene
    pos = solution.placement.points
    names = {b.number: b.name for b in bods}
    n = len(bods)
    motion: dict[int, tuple[float, Vec]] = {1: (0.0, (0.0, 0.0))}
    omegas: dict[int, Omega] = {1: Omega(1, "frame", 0.0, None, "fixed", "fixed")}
    if field is not None:
        for b in bods[1:]:
            w, v0, how = field[b.number]
            motion[b.number] = (w, v0)
            c = found[(1, b.number)]
            omegas[b.number] = Omega(b.number, b.name, w, v0 if c.point is None else None,
                                     f"from the velocity field (two inputs given): {how}",
                                     "field")
    else:
        _propagate(solution, bods, found, motion, omegas, names, size)
    carriers: dict[str, int] = {}
    for b in bods:
        for x in b.labels:
            carriers.setdefault(x, b.number)
    carriers |= _construction_points(solution, bods, carriers)
    labels = list(points) if points is not None else [x for x in pos if x in carriers]
    vel = {}
    for x in labels:
        if x not in carriers:
            raise UnsupportedError(f"point {x} is on no link of the circle diagram",
                                   file=scene.file)
        vel[x] = _point_velocity(x, carriers[x], pos[x], motion, found, names)
    count = len(found)
    total = n * (n - 1) // 2
    if field is not None:
        note = ("two inputs are given at this instant: each body's centre I1j is read off its "
                "velocity field (the polygon's velocities), the rest from the pairs and "
                "Kennedy's theorem")
    elif any(c.by_field for c in found.values()):
        opened = sum(c.by_field for c in found.values())
        note = (f"{n} links: Kennedy's theorem leaves {opened} of the {total} centres open (no "
                f"two distinct lines of centres meet there: a group of three links on a plate, "
                f"or a toggle); those are read off the velocity fields (the polygon's "
                f"velocities), the rest from the pairs and Kennedy's theorem")
    elif count < total:
        note = (f"{n} links: the {count} centres the velocities need and every primary one "
                f"are found, not all {total}")
    else:
        note = f"{n} links: all {total} centres, from the pairs and Kennedy's theorem"
    return Centres(bods, tuple(found[k] for k in sorted(found)),
                   tuple(omegas[k] for k in sorted(omegas)), MappingProxyType(vel), size,
                   count == total, note)


__all__ = ["Body", "Centre", "Omega", "PointVelocity", "Centres", "FULL_BODIES", "bodies",
           "find_centres", "instant_centres", "pair_name", "sub"]
