"""The links of the circle diagram and the records of their centres (split from
:mod:`polygons.centres`, which finds the centres and re-exports these names).

The links are the bodies of the mechanism model (:mod:`polygons.model`), numbered as a
textbook numbers them: 1 the frame, 2 the driver, then in the order the construction places
them (the plan's dyads: a body is numbered when the points it turns on are placed), or as the
scene's ``[centres] numbers`` says; bodies fixed together (a link between two pivots, a rigid
group) are one link.  The records: :class:`Body`, :class:`Centre` I_ij (finite, or at
infinity along a direction), :class:`Omega`, :class:`PointVelocity`, :class:`Centres`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from .errors import SceneError, show, suggest
from .kennedy import pair_name
from .model import FRAME

Vec = tuple[float, float]

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


__all__ = ["Vec", "sub", "Body", "Centre", "Omega", "PointVelocity", "Centres", "bodies",
           "rigid_groups"]
