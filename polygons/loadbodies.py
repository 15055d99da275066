"""The records every scene's :class:`Loads` is made of, force tables or none: the moving bodies,
the joints and the loads record itself (:mod:`polygons.loadmodel` holds the records of the
tables and re-exports these).  A scene without force tables imports only this module and
:mod:`polygons.loadtables` (:func:`without_tables`), not the readers of the tables."""
from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from .reader import record
from .loadtables import DEFAULT_MODE, DEFAULT_STEPS, NO_GRAVITY

Vec = tuple[float, float]


@dataclass(frozen=True)
class Body:
    """A moving rigid body: a link (or slotted lever) with frame ``a`` → ``b``, or the block of a
    slider point (``b`` None, translating along its guide)."""
    name: str
    kind: str                   # 'link' | 'block'
    a: str
    b: str | None
    labels: tuple[str, ...]
    length: float | None        # stated length of a link


@dataclass(frozen=True)
class Joint:
    """A pin at ``label`` joining ``members`` (bodies), and the ground when ``ground``."""
    label: str
    members: tuple[str, ...]
    ground: bool


@dataclass(frozen=True)
class Loads:
    """Everything the force tables say, in SI, checked against the scene's topology."""
    file: str
    bodies: Mapping[str, Body]
    members: Mapping[str, tuple[str, ...]]      # label -> bodies carrying it
    joints: tuple[Joint, ...]
    slots: tuple[SlotContact, ...]
    guides: tuple[str, ...]
    masses: tuple[MassItem, ...]
    forces: tuple[AppliedForce, ...]
    torques: tuple[AppliedTorque, ...]
    frictions: tuple[Friction, ...]
    springs: tuple[Spring, ...]
    gravity: Vec
    mode: str
    after: tuple[float, ...]
    steps: int
    answers: tuple[ForceAnswer, ...]
    driver_body: str
    active: bool                # the scene has masses, forces, torques or springs
    flywheel: Flywheel | None = None
    efficiency: Efficiency | None = None
    effort: "Effort | None" = None      # [dynamics] effort: the unknown effort's place

    def items_of(self, body: str) -> list[MassItem]:
        return [m for m in self.masses if m.body == body]


def bodies_of(model) -> dict[str, Body]:
    """The moving bodies that carry loads, read off the mechanism model
    (:mod:`polygons.model`): its links and slotted levers (kind 'link'), its slider blocks and
    yokes ('block').  The blocks of pins in slots and collars are massless: the force analysis
    meets them as contacts (:func:`slot_contacts`)."""
    bodies: dict[str, Body] = {}
    for b in model.moving:
        if b.kind in ("link", "lever"):
            bodies[b.name] = record(Body, name=b.name, kind="link", a=b.a, b=b.b,
                                    labels=b.labels, length=b.length)
        elif b.kind in ("block", "yoke"):
            bodies[b.name] = record(Body, name=b.name, kind="block", a=b.name, b=None,
                                    labels=(b.name,), length=None)
    return bodies


def guides(model) -> tuple[str, ...]:
    """The blocks on fixed guides (sliders and yokes), by their labels."""
    return tuple(s.at for s in model.sliding if s.carrier == "frame")


def joints_of(scene, bodies) -> tuple[dict, list]:
    """(label -> the bodies carrying it, the joints: a label on the ground and a body, or on
    two bodies or more)."""
    members: dict[str, list[str]] = {lab: [] for lab in scene.labels}
    for b in bodies.values():
        for lab in b.labels:
            members.setdefault(lab, []).append(b.name)
    ground = scene.ground
    joints = []
    for lab in scene.labels:
        mem = tuple(members.get(lab, ()))
        if lab in ground and mem:
            joints.append(record(Joint, label=lab, members=mem, ground=True))
        elif len(mem) >= 2:
            joints.append(record(Joint, label=lab, members=mem, ground=False))
    return members, joints


def without_tables(scene) -> Loads:
    """The :class:`Loads` of a scene with none of the force tables (``loadtables.READS``): its
    bodies and joints, every table at its empty default — what reading the absent tables gives
    (:func:`polygons.loads.parse` with ``shortcut=False``; the tests compare the two)."""
    bodies = bodies_of(scene.model)
    members, joints = joints_of(scene, bodies)
    drv = scene.driver
    return record(Loads, file=scene.file, bodies=MappingProxyType(bodies),
                  members=MappingProxyType({k: tuple(v) for k, v in members.items()}),
                  joints=tuple(joints), slots=(), guides=guides(scene.model), masses=(),
                  forces=(), torques=(), frictions=(), springs=(), gravity=NO_GRAVITY,
                  mode=DEFAULT_MODE, after=(), steps=DEFAULT_STEPS, answers=(),
                  driver_body=drv.link if hasattr(drv, "pivot") else drv.point,
                  active=False, flywheel=None, efficiency=None, effort=None)
