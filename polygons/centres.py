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
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from .errors import SceneError, UnsupportedError, show, suggest
from .kennedy import SAME, canonical, kennedy, pair_name
from .contacts import wheel_of
from .model import BODY_KINDS, FRAME, check_handles
from .scene import Crank
from .steps import sense

Vec = tuple[float, float]

#: the kinds of body and pair the centres handle (a rolling or cam pair is refused in words)
HANDLES = frozenset(BODY_KINDS) | {"turning", "sliding"}
#: up to this many bodies every centre is found (the full circle diagram); beyond, only those
#: the velocities need
FULL_BODIES = 16
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def sub(text: str) -> str:
    """Digits as subscripts: '13' → '₁₃' (textbook I₁₃, ω₃)."""
    return str(text).translate(_SUB)


# ---------------------------------------------------------------- records
@dataclass(frozen=True)
class Body:
    """Link ``number`` of the circle diagram: a body of the model (``key``), named as a report
    names it ('frame', 'BC', 'slider C', 'block P2', 'collar C', 'yoke Y')."""

    number: int
    name: str
    kind: str                    # the model's kind: frame, link, lever, block, pin-block, ...
    labels: tuple[str, ...]      # the space-diagram points carried by this body
    key: str = ""                # the model's name of the body
    fixed: tuple[str, ...] = ()  # bodies of the model fixed to it (a link between two pivots)


@dataclass(frozen=True)
class Centre:
    """The instantaneous centre I_ij of links ``i`` < ``j``.

    ``point`` when finite, else ``direction``: the unit vector along which it lies at infinity
    (every line through it is parallel to it).  ``how`` in words: 'pin B', 'block C on its
    guide: at infinity ⟂ the guide', 'Kennedy: 13 on 12–23 and 14–43', 'from the velocity
    field'.  ``lines``: the two lines of centres intersected, each as the centres it joins
    ('I12', 'I23'); ``order``: 0 for the primary centres, then 1, 2, ... as found."""

    i: int
    j: int
    names: tuple[str, str]
    point: Vec | None
    direction: Vec | None
    how: str
    primary: bool
    order: int
    lines: tuple[tuple[str, ...], ...] = ()
    angle_deg: float | None = None          # angle between the two lines intersected
    by_field: bool = False                  # read off the velocity field (two inputs)

    @property
    def label(self) -> str:
        return "I" + pair_name(self.i, self.j)

    @property
    def at_infinity(self) -> bool:
        return self.point is None


@dataclass(frozen=True)
class Omega:
    """ω of link ``number`` found by the centres: ``how`` in words with the numbers."""

    number: int
    name: str
    omega: float                 # CCW positive, rad/s
    velocity: Vec | None         # a translating link's velocity (ω = 0, I_1j at infinity)
    how: str
    rule: str = ""               # given | ratio | same | translates | field | fixed
    via: int | None = None       # the link i whose ω gave it, through I_ij
    speed: float | None = None   # |v| of I_ij (ratio, translates)
    radius: float | None = None  # |I_1j I_ij| (ratio)


@dataclass(frozen=True)
class PointVelocity:
    """Velocity of ``label`` by the centres: v = ω_j · I_1j X on link ``number``."""

    label: str
    number: int
    velocity: Vec
    speed: float
    radius: float | None         # |I_1j X|, None for a translating link or a fixed point
    how: str
    omega: float = 0.0           # ω_j of the body whose centre is used


@dataclass(frozen=True)
class Centres:
    bodies: tuple[Body, ...]
    centres: tuple[Centre, ...]            # the centres found, in (i, j) order
    omegas: tuple[Omega, ...]              # by link number
    velocities: Mapping[str, PointVelocity]
    size: float                            # the mechanism's size (m), for drawing
    complete: bool = True                  # every I_ij of the circle diagram found
    note: str = ""                         # how the centres were found, in words

    _index: Mapping = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "_index", MappingProxyType({(c.i, c.j): c
                                                             for c in self.centres}))

    def centre(self, i: int, j: int) -> Centre:
        return self._index[(min(i, j), max(i, j))]

    def body(self, key: int | str) -> Body:
        for b in self.bodies:
            if key in (b.number, b.name, b.key) or key in b.fixed:
                return b
        raise KeyError(key)

    def omega(self, key: int | str) -> float:
        n = self.body(key).number
        return next(o.omega for o in self.omegas if o.number == n)


# ---------------------------------------------------------------- links
def bodies(solution) -> tuple[Body, ...]:
    """The links of the circle diagram, numbered 1 (frame), 2 (the driver), then in the order
    the construction places them, or as the scene's ``[centres] numbers`` says.  Bodies fixed
    to one another (:func:`rigid_groups`: a link between two fixed pivots, a triangle of
    links on a body) are one link of the circle diagram."""
    scene = solution.scene
    model = scene.model
    pos = solution.placement.points

    def axis(b) -> tuple[str, ...]:
        return tuple(x for x in (b.a, b.b) if x is not None)

    drv = model.inputs[0]
    order = [drv] if drv in model.named else []
    waiting: dict[str, list] = {}           # a label → the bodies that wait for it
    for b in model.moving:
        if b.name not in order:
            for x in axis(b):
                waiting.setdefault(x, []).append(b)
    seen = set(order)
    rank = {b.name: k for k, b in enumerate(model.bodies)}
    placed = set(model.bodies[0].labels)
    steps = [tuple(d.placed) for d in solution.plan.dyads]
    for step in steps + [tuple(pos)]:
        placed.update(step)
        ready = {b.name: b for x in step for b in waiting.get(x, ())
                 if b.name not in seen and all(y in placed for y in axis(b))}
        for name in sorted(ready, key=rank.__getitem__):    # the model's order in a step
            order.append(name)
            seen.add(name)
    group = rigid_groups(model)
    members: dict[str, list[str]] = {}
    for name in [FRAME] + order:
        members.setdefault(group[name], []).append(name)
    first = {g: m[0] for g, m in members.items()}           # each group by its first placed
    order = [name for name in order if first[group[name]] == name]
    wanted = _numbers(scene, model, order)
    if wanted:
        rest = iter(n for n in range(2, len(order) + 2) if n not in wanted.values())
        numbered = {name: wanted.get(name) or next(rest) for name in order}
        order = sorted(order, key=numbered.__getitem__)
    out = []
    for name in [FRAME] + order:
        others = tuple(m for m in members[group[name]] if m != name)
        b = model.body(name)
        labels = tuple(dict.fromkeys(x for m in (name,) + others for x in model.body(m).labels
                                     if x in pos))
        title = "frame" if name == FRAME else b.title
        if others and name != FRAME:
            titles = [model.body(m).title for m in others]
            title += (f" (with {', '.join(titles)})" if len(titles) <= 3 else
                      f" (with {len(titles)} links fixed to it)")
        out.append(Body(len(out) + 1, title, b.kind, labels, name, others))
    return tuple(out)


def rigid_groups(model) -> dict[str, str]:
    """Each body of the model → the first body of the rigid group it belongs to (the frame's
    name for the frame's): a link whose two points are on one group joins it (a link between
    two fixed pivots is part of the frame), and so do two links pinned together whose other
    points are two points of one group (a triangle: a truss carried by a link)."""
    parent = {b.name: b.name for b in model.bodies}

    def find(x: str) -> str:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    def join(a: str, b: str) -> None:
        ra, rb = find(a), find(b)
        if ra != rb:
            keep, drop = sorted((ra, rb), key=rank.__getitem__)
            parent[drop] = keep

    rank = {b.name: k for k, b in enumerate(model.bodies)}
    bars = [b for b in model.moving if b.kind in ("link", "lever")]

    def on(label: str, besides: str) -> set[str]:
        """The groups carrying ``label`` other than ``besides``'s."""
        own = find(besides)
        return {find(m) for m in model.members.get(label, ()) if find(m) != own}

    changed = True
    while changed:
        changed = False
        for b in bars:
            labs = b.labels
            for k, x in enumerate(labs):
                for y in labs[k + 1:]:
                    common = on(x, b.name) & on(y, b.name)
                    if common:
                        join(b.name, min(common, key=rank.__getitem__))
                        changed = True
                        break
                else:
                    continue
                break
        for t in model.turning:
            at = [model.body(n) for n in t.bodies if model.body(n).kind in ("link", "lever")]
            for a, p in enumerate(at):
                for q in at[a + 1:]:
                    if find(p.name) == find(q.name):
                        continue
                    hits = {g for x in p.labels if x != t.label for y in q.labels
                            if y != t.label and y != x for g in on(x, p.name) & on(y, q.name)}
                    if hits:
                        g = min(hits, key=rank.__getitem__)
                        join(p.name, g)
                        join(q.name, g)
                        changed = True
    return {b.name: find(b.name) for b in model.bodies}


def _numbers(scene, model, order) -> dict[str, int]:
    """The scene's ``[centres] numbers`` (a body of the model → its number), checked against
    the mechanism: each name a moving link, each number within 2 .. the number of links."""
    numbers = scene.options.centres.numbers
    if not numbers:
        return {}
    titles = {model.body(n).title: n for n in order} | {n: n for n in order}
    out: dict[str, int] = {}
    for name, num in numbers.items():
        if name not in titles:
            raise SceneError(f"{show(name)} is not a moving link of this mechanism: "
                             f"{suggest(name, list(titles))}", file=scene.file,
                             where=f"centres.numbers.{name}")
        if num > len(order) + 1:
            raise SceneError(f"{show(name)} cannot be number {num}: the moving links are "
                             f"numbered 2 to {len(order) + 1} (1 is the frame)",
                             file=scene.file, where=f"centres.numbers.{name}")
        if titles[name] in out:
            raise SceneError(f"{show(name)} is numbered twice", file=scene.file,
                             where="centres.numbers")
        out[titles[name]] = num
    return out


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


# ---------------------------------------------------------------- helpers
def _size(solution) -> float:
    pts = list(solution.placement.points.values())
    xs = [float(p[0]) for p in pts]
    ys = [float(p[1]) for p in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-300)


def _t(v) -> Vec:
    return (float(v[0]), float(v[1]))


def _f(x: float) -> str:
    return f"{x:.5g}"


__all__ = ["Body", "Centre", "Omega", "PointVelocity", "Centres", "FULL_BODIES", "bodies",
           "find_centres", "instant_centres", "pair_name", "sub"]


def _wheel_radius(label, scene) -> float:
    """The radius of the rolling wheel centred at ``label`` (a driven wheel's body)."""
    return wheel_of(scene, label).radius
