"""Instantaneous centres of a solved mechanism, found the drawing-board way (Kennedy's theorem).

    I_ij: the point common to links i and j that has the same velocity in both.
    Kennedy: the three centres I_ij, I_jk, I_ik of any three links lie on one straight line.

Links are numbered as a textbook numbers them: 1 the frame, 2 the driver, then the links in the
order the construction places them (a slider block gets its own number).  The *primary*
centres are read off the joints: a pin is the centre of the two links it joins; a block
sliding on a fixed straight guide has its centre with the frame at infinity, perpendicular to
the guide; a pin sliding in a straight slot (a sliding pair) has its centre with the slotted
link somewhere on the common normal, the line through the pin perpendicular to the slot.  The
others come from the circle diagram: an unknown I_ij is the intersection of two lines of
centres I_ik–I_kj and I_il–I_lj (two triangles that share the side ij), or of one such line
with the common normal.  The intersections are shapely's (:mod:`polygons.geometry`).

Velocities by the centres: a point X of link j moves at v = ω_j · I_1j X, perpendicular to
I_1j X; ω_j follows from a link i whose ω_i is known through the common point I_ij, whose
velocity is the same in both links: ω_i · I_1i I_ij = ω_j · I_1j I_ij.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from . import geometry
from .errors import ParallelLinesError, UnsupportedError
from .steps import sense
from .scene import Crank

Vec = tuple[float, float]

#: two lines of centres closer than this fraction of the mechanism's size are the same line
_SAME_LINE = 1e-9


# ---------------------------------------------------------------- records
@dataclass(frozen=True)
class Body:
    """Link number ``number`` of the circle diagram: the frame (1), a binary link or slotted
    lever (named as in the scene, 'BC'), or a slider block ('slider C')."""

    number: int
    name: str
    kind: str                    # 'frame' | 'link' | 'lever' | 'slider'
    labels: tuple[str, ...]      # the space-diagram points carried by this link


@dataclass(frozen=True)
class Centre:
    """The instantaneous centre I_ij of links ``i`` < ``j``.

    ``point`` when finite, else ``direction``: the unit vector along which it lies at infinity
    (every line through it is parallel to it).  ``how`` in words: 'pin', 'slider (at infinity
    ⟂ guide)', 'Kennedy: 13 on 12–23 and 14–43'.  ``lines``: the two lines of centres
    intersected, each as the centres it joins ('I12', 'I23') or ('normal at A',) for a
    common normal (empty for a primary centre); ``order``: 0 for the
    primary centres, then 1, 2, ... in the order Kennedy found them."""

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


@dataclass(frozen=True)
class PointVelocity:
    """Velocity of ``label`` by the centres: v = ω_j × I_1j X on link ``number``."""

    label: str
    number: int
    velocity: Vec
    speed: float
    radius: float | None         # |I_1j X|, None for a translating link
    how: str


@dataclass(frozen=True)
class Centres:
    bodies: tuple[Body, ...]
    centres: tuple[Centre, ...]            # every I_ij, i < j, in (i, j) order
    omegas: tuple[Omega, ...]              # by link number
    velocities: Mapping[str, PointVelocity]
    size: float                            # the mechanism's size (m), for drawing

    def centre(self, i: int, j: int) -> Centre:
        i, j = min(i, j), max(i, j)
        return next(c for c in self.centres if (c.i, c.j) == (i, j))

    def body(self, key: int | str) -> Body:
        for b in self.bodies:
            if key in (b.number, b.name):
                return b
        raise KeyError(key)

    def omega(self, key: int | str) -> float:
        n = self.body(key).number
        return next(o.omega for o in self.omegas if o.number == n)


def pair_name(i: int, j: int) -> str:
    """'13', or '1,13' when a number has two digits."""
    return f"{i}{j}" if i < 10 and j < 10 else f"{i},{j}"


# ---------------------------------------------------------------- links
def bodies(solution) -> tuple[Body, ...]:
    """The links of the circle diagram, numbered 1 (frame), 2 (driver), then in the order the
    construction places them."""
    scene = solution.scene
    order: list[tuple[str, str]] = []       # (name, kind)

    def add(name: str, kind: str) -> None:
        if (name, kind) not in order:
            order.append((name, kind))

    if scene.prescribed:
        raise UnsupportedError(f"instant centres need a mechanism of one degree of freedom; "
                               f"the prescribed slide of {', '.join(scene.prescribed)} is a "
                               f"second input", file=scene.file)
    for d in solution.plan.dyads:
        brought = getattr(d, "circle_bodies", lambda scene: None)(scene)
        if brought is None:
            raise UnsupportedError(f"polygons centres does not yet place the instant centres "
                                   f"of the {type(d).__name__} dyad at {', '.join(d.placed)} "
                                   f"(an offset slot or a guided pin); use the polygons",
                                   file=scene.file)
        for name, kind in brought:
            add(name, kind)
    placed = solution.placement.points
    out = [Body(1, "frame", "frame", tuple(scene.ground))]
    for name, kind in order:
        if kind == "slider":
            labels = (name,)
            label_name = f"slider {name}"
        else:
            slot = next((s for s in scene.slots.values() if s.lever == name), None)
            if slot is not None:
                ends = (slot.pivot, slot.coincident)
                if slot.far is not None:
                    ends += (slot.far,)
            else:
                link = scene.links[name]
                ends = (link.a, link.b)
            extra = tuple(p for p, bp in scene.points.items() if bp.link == name)
            labels = tuple(x for x in ends + extra if x in placed)
            label_name = name
            if all(x in scene.ground for x in ends):
                continue                    # both ends fixed: part of the frame
        out.append(Body(len(out) + 1, label_name, kind, labels))
    return tuple(out)


# ---------------------------------------------------------------- primary centres
@dataclass(frozen=True)
class _Known:
    point: Vec | None
    direction: Vec | None


def _primary(solution, bods: tuple[Body, ...]):
    """Primary centres {(i, j): (_Known, how)} and common normals {(i, j): (Line, pin)}."""
    scene = solution.scene
    pos = solution.placement.points
    known: dict[tuple[int, int], tuple[_Known, str]] = {}
    normals: dict[tuple[int, int], tuple[geometry.Line, str]] = {}
    carriers: dict[str, list[int]] = {}
    for b in bods:
        for x in b.labels:
            carriers.setdefault(x, []).append(b.number)
    for x, nums in carriers.items():
        for a in range(len(nums)):
            for c in range(a + 1, len(nums)):
                i, j = sorted((nums[a], nums[c]))
                if (i, j) not in known:
                    known[(i, j)] = (_Known(_t(pos[x]), None), f"pin {x}")
    by_name = {b.name: b.number for b in bods}
    for label, g in scene.sliders.items():
        n = by_name.get(f"slider {label}")
        if n is None:
            continue
        d = _canonical((-g.direction[1], g.direction[0]))
        known[(1, n)] = (_Known(None, d), "slider (at infinity ⟂ guide)")
        if g.pin is not None and g.pin in pos:       # Scotch yoke: pin in the yoke's slot
            s = g.slot_direction
            for m in carriers.get(g.pin, []):
                if m != n:
                    i, j = sorted((m, n))
                    normals[(i, j)] = (geometry.line(pos[g.pin], (-s[1], s[0]),
                                                     f"common normal at {g.pin}"), g.pin)
    for pin, slot in scene.slots.items():
        n = by_name.get(slot.lever)
        if n is None or pin not in pos:
            continue
        e = (pos[pin][0] - pos[slot.pivot][0], pos[pin][1] - pos[slot.pivot][1])
        for m in carriers.get(pin, []):
            if m != n:
                i, j = sorted((m, n))
                normals[(i, j)] = (geometry.line(pos[pin], (-e[1], e[0]),
                                                 f"common normal at {pin}"), pin)
    return known, normals


# ---------------------------------------------------------------- Kennedy
def find_centres(solution) -> tuple[tuple[Body, ...], tuple[Centre, ...]]:
    """Every centre I_ij of the solved mechanism: the primary ones from the joints, the rest
    by Kennedy's theorem, taking the unknowns in (i, j) order and for each the first two lines
    of centres the circle diagram offers (or one line and the common normal)."""
    bods = bodies(solution)
    n = len(bods)
    names = {b.number: b.name for b in bods}
    known, normals = _primary(solution, bods)
    size = _size(solution)
    found: dict[tuple[int, int], Centre] = {}
    for (i, j), (k, how) in known.items():
        found[(i, j)] = Centre(i, j, (names[i], names[j]), k.point, k.direction, how, True, 0)
    order = 0
    while True:
        progress = False
        for i in range(1, n + 1):
            for j in range(i + 1, n + 1):
                if (i, j) in found:
                    continue
                c = _kennedy(i, j, n, found, normals.get((i, j)), size, names)
                if c is not None:
                    order += 1
                    found[(i, j)] = Centre(**{**c.__dict__, "order": order})
                    progress = True
                    break
            if progress:
                break
        if not progress:
            break
    missing = [pair_name(i, j) for i in range(1, n + 1) for j in range(i + 1, n + 1)
               if (i, j) not in found]
    if missing:
        raise UnsupportedError(f"Kennedy's theorem does not fix the centres "
                               f"{', '.join('I' + m for m in missing)} of this mechanism "
                               f"(no two lines of centres meet there)", file=solution.scene.file)
    return bods, tuple(found[k] for k in sorted(found))


def _get(found, a: int, b: int) -> Centre | None:
    return found.get((min(a, b), max(a, b)))


def _line_through(c1: Centre, c2: Centre, name: str, size: float) -> geometry.Line | None:
    """The line of centres through c1 and c2 (None if it is undefined or at infinity)."""
    if c1.point is not None and c2.point is not None:
        d = (c2.point[0] - c1.point[0], c2.point[1] - c1.point[1])
        if math.hypot(*d) <= _SAME_LINE * size:
            return None                       # the two centres coincide
        return geometry.line(c1.point, d, name)
    if c1.point is not None:
        return geometry.line(c1.point, c2.direction, name)
    if c2.point is not None:
        return geometry.line(c2.point, c1.direction, name)
    return None


def _same_line(l1: geometry.Line, l2: geometry.Line, size: float) -> bool:
    """Parallel lines through (nearly) the same points."""
    if geometry.angle_between(l1, l2) >= geometry.PARALLEL_DEG:
        return False
    dx, dy = l2.point[0] - l1.point[0], l2.point[1] - l1.point[1]
    off = abs(l1.direction[0] * dy - l1.direction[1] * dx)
    return off <= _SAME_LINE * max(size, 1e-300)


def _kennedy(i, j, n, found, normal, size, names) -> Centre | None:
    lines: list[tuple[geometry.Line, tuple[str, ...], str]] = []
    for k in range(1, n + 1):
        if k in (i, j):
            continue
        a, b = _get(found, i, k), _get(found, k, j)
        if a is None or b is None:
            continue
        ln = _line_through(a, b, f"line {pair_name(i, k)}–{pair_name(k, j)}", size)
        if ln is None or any(_same_line(ln, m, size) for m, _, _ in lines):
            continue
        lines.append((ln, (a.label, b.label), f"{pair_name(i, k)}–{pair_name(k, j)}"))
    if normal is not None:
        nl, pin = normal
        lines = [l for l in lines if not _same_line(l[0], nl, size)]
        if not lines:
            return None
        lines = [lines[0], (nl, (f"normal at {pin}",), f"the common normal at {pin}")]
    if len(lines) < 2:
        return None
    (l1, n1, w1), (l2, n2, w2) = lines[0], lines[1]
    how = f"Kennedy: {pair_name(i, j)} on {w1} and {w2}"
    ln_names = (n1, n2)
    try:
        hit = geometry.intersect(l1, l2, step=f"centre I{pair_name(i, j)}")
    except ParallelLinesError:
        # two distinct parallel lines of centres meet at infinity: the two links translate
        # relative to each other
        d = l1.direction
        return Centre(i, j, (names[i], names[j]), None, _canonical(d),
                      how + " (parallel: at infinity)", False, 0, ln_names, 0.0)
    return Centre(i, j, (names[i], names[j]), hit.point, None, how, False, 0, ln_names,
                  hit.angle_deg)


def _canonical(d) -> Vec:
    """A direction at infinity has no sense: pick the one with x > 0 (or y > 0)."""
    x, y = float(d[0]), float(d[1])
    if x < 0 or (x == 0 and y < 0):
        x, y = -x, -y
    return (x + 0.0, y + 0.0)


# ---------------------------------------------------------------- velocities by the centres
def instant_centres(solution, points=None) -> Centres:
    """All centres, every link's ω and the velocities of ``points`` (default: every placed
    point) by the centres.  ``solution`` is a :class:`polygons.evaluate.Solution`; only its
    positions, its plan and the driver's input are used, never its polygon."""
    bods, cents = find_centres(solution)
    found = {(c.i, c.j): c for c in cents}
    scene = solution.scene
    pos = solution.placement.points
    drv = scene.driver
    # each link's motion: (ω, v0) with v(P) = v0 + ω k × P
    motion: dict[int, tuple[float, tuple[float, float]]] = {1: (0.0, (0.0, 0.0))}
    omegas: dict[int, Omega] = {1: Omega(1, "frame", 0.0, None, "fixed")}
    if isinstance(drv, Crank):
        n2 = next(b.number for b in bods if b.name == drv.link)
        c = found[(1, n2)]
        motion[n2] = (drv.omega, _v0(drv.omega, c.point))
        omegas[n2] = Omega(n2, drv.link, drv.omega, None, "given (the driver)")
    else:
        n2 = next(b.number for b in bods if b.name == f"slider {drv.point}")
        g = scene.sliders[drv.point]
        u = (drv.velocity * g.direction[0], drv.velocity * g.direction[1])
        motion[n2] = (0.0, u)
        omegas[n2] = Omega(n2, f"slider {drv.point}", 0.0, u, "given (the driver translates)")
    names = {b.number: b.name for b in bods}
    size = _size(solution)
    while len(motion) < len(bods):
        progress = False
        for b in bods:
            j = b.number
            if j in motion:
                continue
            for i in sorted(motion):
                if i == 1:
                    continue
                res = _omega_from(i, j, motion[i], found, names, size)
                if res is not None:
                    motion[j], omegas[j] = res
                    progress = True
                    break
        if not progress:
            left = [names[b.number] for b in bods if b.number not in motion]
            raise UnsupportedError(f"the centres do not give the angular velocity of "
                                   f"{', '.join(left)}", file=scene.file)
    carriers: dict[str, int] = {}
    for b in bods:
        for x in b.labels:
            if x in scene.ground:
                carriers.setdefault(x, 1)
            elif b.number != 1:
                carriers.setdefault(x, b.number)
    labels = list(points) if points is not None else [x for x in pos if x in carriers]
    vel = {}
    for x in labels:
        if x not in carriers:
            raise UnsupportedError(f"point {x} is on no link of the circle diagram",
                                   file=scene.file)
        vel[x] = _point_velocity(x, carriers[x], pos[x], motion, found, names)
    return Centres(bods, cents, tuple(omegas[k] for k in sorted(omegas)),
                   MappingProxyType(vel), _size(solution))


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
    nij, n1j = pair_name(min(i, j), max(i, j)), pair_name(1, j)
    if cij.point is not None:
        v = _at(mi, cij.point)
        if c1j.point is None:           # link j translates: every point moves as I_ij
            return (0.0, v), Omega(j, names[j], 0.0, v, (
                f"I{n1j} at infinity: link {j} translates with v_I{nij} = "
                f"{_f(math.hypot(*v))} m/s"))
        r = (cij.point[0] - c1j.point[0], cij.point[1] - c1j.point[1])
        rr = r[0] * r[0] + r[1] * r[1]
        if math.sqrt(rr) <= _SAME_LINE * size:
            return None                 # I_ij on I_1j: this pair does not fix ω_j
        wj = (r[0] * v[1] - r[1] * v[0]) / rr
        if found[(1, i)].point is None:
            vi = f"v_I{nij} = v of link {i} (it translates) = {_f(math.hypot(*v))} m/s"
        else:
            vi = f"v_I{nij} = ω{i} × I{pair_name(1, i)}I{nij} = {_f(math.hypot(*v))} m/s"
        return (wj, _v0(wj, c1j.point)), Omega(j, names[j], wj, None, (
            f"{vi}; ω{j} = v_I{nij} / I{n1j}I{nij} = {_f(math.hypot(*v))} / "
            f"{_f(math.sqrt(rr))} = {_f(abs(wj))} rad/s {sense(wj)}"))
    # I_ij at infinity: links i and j translate relative to each other, ω_j = ω_i
    if c1j.point is None:
        return None
    return (wi, _v0(wi, c1j.point)), Omega(j, names[j], wi, None, (
        f"I{nij} at infinity: ω{j} = ω{i} = {_f(abs(wi))} rad/s {sense(wi)}"))


def _point_velocity(x, j, p, motion, found, names) -> PointVelocity:
    if j == 1:
        return PointVelocity(x, 1, (0.0, 0.0), 0.0, 0.0, "fixed")
    w, v0 = motion[j]
    c = found[(1, j)]
    if c.point is None:
        v = v0
        return PointVelocity(x, j, _t(v), math.hypot(*v), None,
                             f"link {j} ({names[j]}) translates: v_{x} = {_f(math.hypot(*v))} m/s")
    r = (p[0] - c.point[0], p[1] - c.point[1])
    v = (-w * r[1], w * r[0])
    rad = math.hypot(*r)
    return PointVelocity(x, j, _t(v), abs(w) * rad, rad, (
        f"v_{x} = ω{j} × I{pair_name(1, j)}{x} = {_f(abs(w))} × {_f(rad)} = "
        f"{_f(abs(w) * rad)} m/s"))


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


__all__ = ["Body", "Centre", "Omega", "PointVelocity", "Centres", "bodies", "find_centres",
           "instant_centres", "pair_name"]
