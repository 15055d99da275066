"""The mechanism model: the scene's joint tables read once into bodies and pairs, at load.

Every method reads this model — mobility (Grübler–Kutzbach), the force tables and
Newton–Euler, instant centres, rubbing velocities at pins, slides, the space diagram and the
drawing-board emulation — and none of them reads the scene's joint tables ([links], [sliders],
[slots], [points], [driver.slide]) again.

**Bodies** (:class:`Body`), in a fixed order (the order every report lists them in):

* the **frame** (kind ``frame``): every [ground] point and every fixed guide;
* each [links] entry (``link``): its two end points, the [points] declared on it and, when it
  is a slotted lever, the lever point under the pin;
* a slotted lever not in [links] (``lever``): its pivot, the point under the pin, its points;
* per slot, the **block** of the pin sliding in it (``pin-block``: pinned at the pin, sliding
  in the slot), as the textbooks draw a pin in a slot;
* per fixed guide, its **slider** (``block``), or, for a Scotch yoke, the **yoke** (``yoke``,
  sliding on the guide) and the block of the pin in its slot (``pin-block``);
* per prescribed slide ([driver.slide]), the **collar** (``collar``) sliding along its link;
* per pin in two moving slots ([crossing]), two blocks (``cross-block``) pinned together at
  the pin, each sliding in its lever's slot.

**Pairs**: a turning pair (:class:`Turning`) at every label carried by two or more bodies (a
pin joining k bodies counts k − 1 revolutes), a sliding pair (:class:`Sliding`) per block,
with its line (:class:`SlideLine`: fixed, or carried by a moving body).  Rolling and cam
contact are kinds of pair to come (:data:`PAIR_KINDS`); a method that meets a kind it does
not handle refuses it in one line naming both (:func:`refuse`).
"""
from __future__ import annotations

import math
from contextvars import ContextVar
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

from .errors import UnsupportedError

Vec = tuple[float, float]

#: the frame's name
FRAME = "frame"

#: every kind of body the model holds (``Body.kind``)
BODY_KINDS = ("frame", "link", "lever", "block", "yoke", "pin-block", "collar", "cross-block",
              "wheel")
#: every kind of pair: the lower pairs the model builds today, the higher ones to come
PAIR_KINDS = ("turning", "sliding", "rolling", "cam")


@dataclass(frozen=True)
class Body:
    """A rigid body of the mechanism.

    ``a`` → ``b`` is the body's own axis (a link's ends; a lever's pivot and the point under
    the pin; a block's point and None: it only translates or turns on its pin).
    ``labels``: every space-diagram point it carries; ``length``: a link's stated length."""

    name: str
    kind: str
    a: str | None
    b: str | None
    labels: tuple[str, ...]
    length: float | None = None

    @property
    def title(self) -> str:
        """The body as a report names it: 'BC', 'slider C', 'block A', 'yoke Y'."""
        if self.kind == "block":
            return f"slider {self.name}"
        if self.kind == "yoke":
            return f"yoke {self.name}"
        return self.name


@dataclass(frozen=True)
class Turning:
    """A turning pair (pin) at ``label`` joining ``bodies`` (the frame first when fixed)."""

    label: str
    bodies: tuple[str, ...]

    kind = "turning"

    @property
    def ground(self) -> bool:
        return FRAME in self.bodies


@dataclass(frozen=True)
class SlideLine:
    """The straight line a block slides on: ``through`` + t e.

    Fixed (``origin`` None): through ``through`` at ``angle``.  Carried by a moving body:
    through its point ``origin``, along ``origin`` → ``toward`` (or at the fixed ``angle`` when
    the carrier only translates: a yoke's slot), ``offset`` left of that line."""

    through: Vec | None = None
    angle: float | None = None
    origin: str | None = None
    toward: str | None = None
    offset: float = 0.0

    @property
    def fixed(self) -> bool:
        return self.origin is None

    @property
    def direction(self) -> Vec:
        """The unit direction of a line at a fixed angle (a fixed guide, a yoke's slot)."""
        return (math.cos(self.angle), math.sin(self.angle))

    def at(self, pos: Mapping[str, Vec]) -> tuple[Vec, Vec]:
        """(a point of the line, its unit direction) at the positions ``pos``."""
        if self.toward is None:
            e = (math.cos(self.angle), math.sin(self.angle))
        else:
            (ox, oy), (tx, ty) = pos[self.origin], pos[self.toward]
            n = math.hypot(tx - ox, ty - oy)
            e = ((tx - ox) / n, (ty - oy) / n) if n > 0 else (math.nan, math.nan)
        if self.origin is None:
            return (float(self.through[0]), float(self.through[1])), e
        ox, oy = (float(c) for c in pos[self.origin])
        return (ox - self.offset * e[1], oy + self.offset * e[0]), e


@dataclass(frozen=True)
class Sliding:
    """A sliding pair: ``block`` slides on ``carrier`` along ``line``; ``at`` is the block's
    point (a slider's label, the pin in a slot, a collar), ``coincident`` the carrier's point
    under it (None on the frame), ``key`` the scene table that states it
    ('sliders.C', 'slots.A', 'sliders.Y.pin', 'driver.slide')."""

    at: str
    block: str
    carrier: str
    line: SlideLine
    key: str
    coincident: str | None = None
    prescribed: bool = False        # a second input: the slide is given
    far: str | None = None          # a slotted lever's far end

    @property
    def along_lever(self) -> bool:
        """A slot whose direction is its lever's pivot → far end (an offset slot, or a lever
        placed before its pin), not pivot → pin."""
        return self.line.toward is not None and self.line.toward != self.at

    kind = "sliding"


@dataclass(frozen=True)
class Mechanism:
    """The frozen model of one scene: bodies, pairs, inputs."""

    bodies: tuple[Body, ...]                   # the frame first
    turning: tuple[Turning, ...]
    sliding: tuple[Sliding, ...]
    inputs: tuple[str, ...]                    # the driven body, then each prescribed slide
    members: Mapping[str, tuple[str, ...]]     # label → the bodies carrying it (frame first)
    named: Mapping[str, Body]                  # name → body
    guide: Mapping[str, Sliding]               # label → its block's pair on a fixed guide
    slot: Mapping[str, Sliding]                # pin → its block's pair in a lever's slot
    collar: Mapping[str, Sliding]              # point → its collar's prescribed slide
    under: Mapping[str, Sliding]               # a carrier's point under a block → its pair
    #: label → the [points] record of a point rigid with a body (its ``link``, ``along`` or
    #: ``fraction``, ``left``), in the scene's order
    points: Mapping[str, object] = field(default_factory=lambda: MappingProxyType({}))
    #: point → its [driver.slide] record (the second input: its link, ends ``p`` → ``q`` and
    #: the slide's ``position``, ``velocity``, ``acceleration``)
    prescribed: Mapping[str, object] = field(default_factory=lambda: MappingProxyType({}))

    def body(self, name: str) -> Body:
        return self.named[name]

    def links(self) -> tuple[Body, ...]:
        """The [links] entries as bodies (kind 'link': ``a``, ``b``, ``length`` — None for a
        slotted lever without one), in the scene's order: the lengths as loaded (a batch's
        varied lengths are the scene's own, read by the groups)."""
        return tuple(b for b in self.bodies if b.kind == "link")

    def link(self, name: str) -> Body | None:
        """The [links] entry ``name`` as a body, or None."""
        b = self.named.get(name)
        return b if b is not None and b.kind == "link" else None

    @property
    def moving(self) -> tuple[Body, ...]:
        return self.bodies[1:]

    def slides_at(self, label: str) -> tuple[Sliding, ...]:
        """The sliding pairs whose block is at ``label``."""
        return tuple(s for s in self.sliding if s.at == label)

    def slide_of(self, block: str) -> Sliding | None:
        return next((s for s in self.sliding if s.block == block), None)

    def fixed_guide(self, label: str) -> Sliding | None:
        """The sliding pair of the block at ``label`` on a fixed guide (a slider, a yoke)."""
        return next((s for s in self.sliding if s.at == label and s.carrier == FRAME), None)

    def slots(self) -> tuple[Sliding, ...]:
        """The pins sliding in the slot of a turning lever ([slots])."""
        return tuple(self.slot.values())

    def yoke_slots(self) -> tuple[Sliding, ...]:
        return tuple(s for s in self.sliding if s.key.endswith(".pin"))

    def crossings(self) -> tuple[Sliding, ...]:
        """The pairs of pins in two moving slots at once ([crossing]), two per pin."""
        return tuple(s for s in self.sliding if s.key.startswith("crossing."))

    def collars(self) -> tuple[Sliding, ...]:
        return tuple(self.collar.values())

    def lever_slots(self, lever: str) -> tuple[Sliding, ...]:
        """The slots cut in ``lever``."""
        return tuple(s for s in self.slot.values() if s.carrier == lever)

    def carried_by(self, label: str, exclude: tuple[str, ...] = ()) -> tuple[str, ...]:
        return tuple(b for b in self.members.get(label, ()) if b not in exclude)

    @property
    def kinds(self) -> frozenset[str]:
        """Every kind of body and pair in the mechanism ('link', 'sliding', ...)."""
        return frozenset([b.kind for b in self.bodies] + [p.kind for p in self.turning]
                         + [p.kind for p in self.sliding])


def build(*, ground, links, sliders, slots, points, prescribed, driver, crossing=None,
          along_lever=lambda slot: False, wheel_pins=None) -> Mechanism:
    """The model of a scene's joint tables (its parsed records: ``links`` name → Link,
    ``sliders`` label → Guide, ``slots`` pin → Slot, ``points`` label → BodyPoint,
    ``prescribed`` point → Slide).  ``along_lever(slot)``: whether the slot runs along its
    lever's pivot → far end rather than pivot → pin (:func:`polygons.topology.slot_along`)."""
    on_body: dict[str, list[str]] = {}
    for label, bp in points.items():
        on_body.setdefault(bp.link, []).append(label)
    levers = {s.lever: s for s in slots.values()}
    bodies: list[Body] = [Body(FRAME, "frame", None, None, tuple(ground))]
    sliding: list[Sliding] = []
    levers_seen: set[str] = set()

    def labels(*xs) -> tuple[str, ...]:
        return tuple(dict.fromkeys(x for x in xs if x is not None))

    for name, link in links.items():
        extra = (levers[name].coincident,) if name in levers else ()
        bodies.append(Body(name, "link", link.a, link.b,
                           labels(link.a, link.b, *extra, *on_body.get(name, ())),
                           link.length))
    for pin, slot in slots.items():
        if slot.lever not in links and slot.lever not in levers_seen:
            levers_seen.add(slot.lever)
            bodies.append(Body(slot.lever, "lever", slot.pivot, slot.coincident,
                               labels(slot.pivot, slot.coincident,
                                      *on_body.get(slot.lever, ()))))
        block = f"block {pin}"
        bodies.append(Body(block, "pin-block", pin, None, (pin,)))
        toward = slot.far if slot.far is not None and along_lever(slot) else pin
        sliding.append(Sliding(pin, block, slot.lever,
                               SlideLine(origin=slot.pivot, toward=toward, offset=slot.offset),
                               f"slots.{pin}", slot.coincident, far=slot.far))
    for label, g in sliders.items():
        fixed = SlideLine(through=tuple(g.through), angle=g.angle)
        if g.pin is not None:                      # a Scotch yoke and the block in its slot
            bodies.append(Body(label, "yoke", label, None, (label,)))
            sliding.append(Sliding(label, label, FRAME, fixed, f"sliders.{label}"))
            block = f"block {g.pin}"
            bodies.append(Body(block, "pin-block", g.pin, None, (g.pin,)))
            sliding.append(Sliding(g.pin, block, label,
                                   SlideLine(origin=label, angle=g.slot_angle),
                                   f"sliders.{label}.pin"))
        elif label in (wheel_pins or {}):        # a driven rolling wheel and its rim pins
            bodies.append(Body(label, "wheel", label, None,
                               labels(label, *wheel_pins[label])))
            sliding.append(Sliding(label, label, FRAME, fixed, f"sliders.{label}"))
        else:
            bodies.append(Body(label, "block", label, None, (label,)))
            sliding.append(Sliding(label, label, FRAME, fixed, f"sliders.{label}"))
    for point, sl in prescribed.items():
        block = f"collar {point}"
        bodies.append(Body(block, "collar", point, None, (point,)))
        sliding.append(Sliding(point, block, sl.link, SlideLine(origin=sl.p, toward=sl.q),
                               "driver.slide", sl.coincident, prescribed=True))
        carrier = next(b for b in bodies if b.name == sl.link)
        bodies[bodies.index(carrier)] = Body(carrier.name, carrier.kind, carrier.a, carrier.b,
                                             labels(*carrier.labels, sl.coincident),
                                             carrier.length)

    for pin, cr in (crossing or {}).items():      # a pin in two moving slots
        for lever, under in zip(cr.levers, cr.coincident):
            block = f"block {pin} in {lever}"
            bodies.append(Body(block, "cross-block", pin, None, (pin,)))
            link = links[lever]
            sliding.append(Sliding(pin, block, lever, SlideLine(origin=link.a, toward=link.b),
                                   f"crossing.{pin}", under, far=link.b))
            carrier = bodies.index(next(b for b in bodies if b.name == lever))
            c = bodies[carrier]
            bodies[carrier] = Body(c.name, c.kind, c.a, c.b, labels(*c.labels, under),
                                   c.length)

    members: dict[str, list[str]] = {}
    for b in bodies:
        for x in b.labels:
            members.setdefault(x, []).append(b.name)
    turning = tuple(Turning(x, tuple(m)) for x, m in members.items() if len(m) > 1)
    drv = getattr(driver, "link", None) or getattr(driver, "point", None)
    inputs = (drv,) + tuple(f"collar {p}" for p in prescribed)
    def by(keep) -> Mapping[str, Sliding]:
        return MappingProxyType({s.at: s for s in sliding if keep(s)})
    return Mechanism(tuple(bodies), turning, tuple(sliding), inputs,
                     MappingProxyType({k: tuple(v) for k, v in members.items()}),
                     MappingProxyType({b.name: b for b in bodies}),
                     by(lambda s: s.carrier == FRAME), by(lambda s: s.key.startswith("slots.")),
                     by(lambda s: s.prescribed),
                     MappingProxyType({s.coincident: s for s in sliding if s.coincident}),
                     MappingProxyType(dict(points)), MappingProxyType(dict(prescribed)))


# ---------------------------------------------------------------- capabilities
#: each kind of body and pair in words, for a refusal
KIND_WORDS = {
    "frame": "the frame", "link": "a link", "lever": "a slotted lever",
    "block": "a slider on a fixed guide", "yoke": "a Scotch yoke",
    "pin-block": "a pin sliding in a slot",
    "cross-block": "a pin sliding in the slots of two moving levers (crossing slots)",
    "collar": "a collar driven along a link (a "
    "prescribed slide, a second input)", "wheel": "a driven wheel rolling on a fixed surface "
    "(its centre on the equivalent guide, pins on its rim)", "turning": "a turning pair", "sliding": "a sliding "
    "pair", "rolling": "a rolling contact", "cam": "a cam contact"}
#: every kind the model builds today (rolling and cam contact are to come)
BUILT = frozenset(BODY_KINDS) | {"turning", "sliding"}


#: the command the user ran ('polygons sweep'), while it runs (set by polygons.cli.main): a
#: method refusing a kind names it (:func:`running`), whichever module the guard sits in
RUNNING: ContextVar[str | None] = ContextVar("polygons_command", default=None)


def running(default: str) -> str:
    """The command the user ran, or ``default`` (the method's own name, when it is called
    from Python rather than from the command line)."""
    return RUNNING.get() or default


def refuse(method: str, kind: str, where: str = "", file: str | None = None
           ) -> UnsupportedError:
    """The one-line refusal of a kind a method does not handle, naming both."""
    at = f" ({where})" if where else ""
    return UnsupportedError(f"{method} does not handle {KIND_WORDS.get(kind, kind)}{at}",
                            file=file)


def unhandled(handles: frozenset[str], model: Mechanism) -> tuple[str, str] | None:
    """The first (kind, where) of a body or pair of ``model`` outside ``handles``, or None."""
    for b in model.bodies:
        if b.kind not in handles:
            return b.kind, b.name
    for p in model.turning + model.sliding:
        if p.kind not in handles:
            return p.kind, getattr(p, "label", None) or p.at
    return None


def check_handles(method: str, handles: frozenset[str], model: Mechanism,
                  file: str | None = None) -> None:
    """Refuse, in one line naming ``method`` and the kind, a mechanism holding a kind of body
    or pair that ``method`` does not declare in ``handles`` (its ``HANDLES``).  ``method`` is
    what the user ran ('polygons forces', 'polygons solve', 'the space diagram')."""
    found = unhandled(handles, model)
    if found is not None:
        raise refuse(method, *found, file)


__all__ = ["BODY_KINDS", "PAIR_KINDS", "FRAME", "Body", "Turning", "SlideLine", "Sliding",
           "Mechanism", "build", "refuse", "check_handles", "unhandled", "RUNNING", "running", "KIND_WORDS", "BUILT"]
