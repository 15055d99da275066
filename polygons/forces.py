"""Forces: inertia forces, the input torque, every pin reaction, torque-driven instants.

The force tables of a scene (kept raw in ``Scene.extra`` by :mod:`polygons.scene`) are read by
:func:`load_model` into a :class:`ForceModel`:

    [masses.BC]                 # a link (or a slider point: the piston / block)
    mass = "0.8 kg"
    inertia = "rod"             # 'rod' (m l²/12, default), 'disc' (+ radius), 'point', or "0.002 kg m^2"
    centre = 0.5                # fraction of the link from its first label, or "90 mm"
    [masses.End]                # a point mass carried by the body at C
    at = "C"
    mass = "0.4 kg"
    [gravity]
    g = "9.81 m/s^2"            # direction = "-90 deg" by default (down)
    [forces.Gas]
    at = "P"
    pressure = "1.2 MPa"        # × π d²/4
    bore = "80 mm"
    direction = "0 deg"         # or force = ["0 N", "20 N"], or magnitude + direction
    [torques.Out]
    on = "DB"
    torque = "6 N m"
    sense = "CW"
    [torques.Pin]
    at = "O"
    friction = "0.1 N m"        # constant, opposes the relative rotation at the pin
    [springs.K]
    stiffness = "100 N/m"       # between = ["S", "H"] + free_length, or at + direction + extension
    [springs.Kt]
    stiffness = "2 N m/rad"     # torsional, at a pin; twist = "0 deg" at this instant
    [dynamics]
    mode = "kinetostatic"       # | "torque-driven" | "release"  (see polygons.dynamics)

The analysis consumes the kinematic :class:`~polygons.evaluate.Solution`: accelerations of
centres of mass are read off the acceleration polygon as images of the link (similar figures),
velocities likewise; nothing is differentiated again here.

* Newton–Euler: three equations per moving body (links, slotted levers, slider blocks), the
  unknowns being the pin forces, the guide and slot normal forces, the guide couples and the
  input torque (or, torque-driven, the input angular acceleration: the acceleration polygon is
  affine in it, so two kinematic solutions, at α = 0 and α = 1, give the column).  One linear
  solve.
* Virtual work: with the velocities of a unit input rate, T_in = −Σ(F·v* + C ω*) over every
  load and every inertia force and couple, term by term (the breakdown).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

import numpy as np

from . import quantities as kq
from .errors import (PolygonsError, SceneError, UnitError, UnknownLabelError, UnsupportedError,
                     suggest)
from .evaluate import Solution, solve
from .scene import Crank, Scene, SliderDrive, _Reader, answer_fields, drawing_tolerance
from .units import UNITS

Vec = tuple[float, float]

#: the scene tables this module reads
FORCE_TABLES = ("masses", "forces", "torques", "springs", "gravity", "dynamics")
MODES = ("kinetostatic", "torque-driven", "release")
#: answer units beyond polygons.units
EXTRA_UNITS = {"kg m^2/s": ("angular_momentum", 1.0), "kg m²/s": ("angular_momentum", 1.0),
               "J": ("energy", 1.0), "W": ("power", 1.0), "-": ("fraction", 1.0),
               "1": ("fraction", 1.0)}
_SMALL = 1e-12


def has_forces(scene: Scene) -> bool:
    """True when the scene has any force table (masses, forces, torques, springs, gravity)."""
    return any(k in scene.extra for k in ("masses", "forces", "torques", "springs"))


# ---------------------------------------------------------------- model
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
class SlotContact:
    pin: str            # the pin label (on ``carrier``)
    lever: str          # the slotted body (a lever, or a Scotch yoke's slider block)
    pivot: str | None   # the lever's pivot (the slot runs through it); None for a yoke
    carrier: str
    direction: Vec | None = None   # a yoke's slot keeps this direction


@dataclass(frozen=True)
class MassItem:
    name: str
    body: str
    kind: str                   # 'link' | 'block' | 'point'
    mass: float
    inertia: float              # about its own centre of mass
    how: str                    # how the inertia was obtained, in words
    along: float | None = None  # link items: centre along a → b
    left: float = 0.0
    at: str | None = None       # point items
    rod: bool = False           # uniform slender rod between the link's ends
    free: bool = False          # turns freely on a frictionless pin: no rotational coupling
    spin: float | None = None   # free disc: its constant spin (rad/s)


@dataclass(frozen=True)
class AppliedForce:
    name: str
    body: str
    at: str
    force: Vec
    how: str


@dataclass(frozen=True)
class AppliedTorque:
    name: str
    body: str
    at: str | None
    torque: float               # CCW positive


@dataclass(frozen=True)
class Friction:
    name: str
    at: str
    first: str
    second: str | None          # None: the ground
    torque: float               # magnitude


@dataclass(frozen=True)
class Spring:
    name: str
    kind: str                   # 'linear' | 'directional' | 'torsional'
    stiffness: float
    ends: tuple = ()            # linear: ((label, body|None), (label, body|None))
    free_length: float | None = None
    extension: float | None = None   # at the scene's instant (linear / directional)
    at: str | None = None
    body: str | None = None          # directional: the body carrying ``at``
    direction: Vec | None = None     # directional: from ``at`` towards the far end
    first: str | None = None         # torsional
    second: str | None = None
    twist: float = 0.0               # torsional: at the scene's instant, CCW of first rel. second


@dataclass(frozen=True)
class ForceAnswer:
    quantity: str
    unit: str
    tutorial: float | None
    exact: float | None
    mode: str
    positive: int               # +1 CCW, -1 CW: sense of positive normal components / moments
    state: str | None
    tolerance: float
    slip: bool
    ref: str | None
    desc: str
    note: str
    sense: str | None


@dataclass
class ForceModel:
    scene: Scene
    bodies: dict[str, Body]
    members: dict[str, list[str]]       # label -> bodies carrying it
    joints: tuple[Joint, ...]
    slots: tuple[SlotContact, ...]
    guides: tuple[str, ...]
    masses: tuple[MassItem, ...]
    forces: tuple[AppliedForce, ...]
    torques: tuple[AppliedTorque, ...]
    frictions: tuple[Friction, ...]
    springs: tuple[Spring, ...]
    gravity: np.ndarray
    mode: str
    after: tuple[float, ...]
    steps: int
    answers: tuple[ForceAnswer, ...]
    driver_body: str
    ref: dict = field(default_factory=dict)   # spring references at the scene's instant

    def items_of(self, body: str) -> list[MassItem]:
        return [m for m in self.masses if m.body == body]


def _bodies(scene: Scene) -> dict[str, Body]:
    bodies: dict[str, Body] = {}
    levers = {s.lever: s for s in scene.slots.values()}
    for name, link in scene.links.items():
        labels = [link.a, link.b]
        if name in levers:
            labels.append(levers[name].coincident)
        labels += [p for p, bp in scene.points.items() if bp.link == name]
        bodies[name] = Body(name, "link", link.a, link.b, tuple(dict.fromkeys(labels)),
                            link.length)
    for name, slot in levers.items():
        if name in bodies:
            continue
        labels = [slot.pivot, slot.coincident]
        labels += [p for p, bp in scene.points.items() if bp.link == name]
        bodies[name] = Body(name, "link", slot.pivot, slot.coincident,
                            tuple(dict.fromkeys(labels)), None)
    for label in scene.sliders:
        bodies[label] = Body(label, "block", label, None, (label,), None)
    return bodies


def load_model(scene: Scene) -> ForceModel:
    """Read and check the force tables of ``scene`` (every problem is a :class:`SceneError`)."""
    file = scene.file
    r = _Reader(file)
    ex = scene.extra
    bodies = _bodies(scene)
    members: dict[str, list[str]] = {lab: [] for lab in scene.labels}
    for b in bodies.values():
        for lab in b.labels:
            members.setdefault(lab, []).append(b.name)

    joints = []
    for lab in scene.labels:
        mem = tuple(members.get(lab, ()))
        if lab in scene.ground and mem:
            joints.append(Joint(lab, mem, True))
        elif len(mem) >= 2:
            joints.append(Joint(lab, mem, False))
    slots = []
    for slot in scene.slots.values():
        carriers = [b for b in members.get(slot.pin, []) if b != slot.lever]
        if not carriers:
            raise UnsupportedError(f"the pin {slot.pin} in the slot of {slot.lever} is on no "
                                   f"moving body", file=file, where=f"slots.{slot.pin}")
        slots.append(SlotContact(slot.pin, slot.lever, slot.pivot, carriers[0]))
    for lab, g in scene.sliders.items():
        if g.pin is None:
            continue
        carriers = [b for b in members.get(g.pin, []) if b != lab]
        if not carriers:
            raise UnsupportedError(f"the pin {g.pin} in the slot of the yoke {lab} is on no "
                                   f"moving body", file=file, where=f"sliders.{lab}.pin")
        slots.append(SlotContact(g.pin, lab, None, carriers[0], g.slot_direction))

    def body_name(name, where) -> str:
        if not isinstance(name, str):
            raise SceneError(f"expected a link name or a slider point, got {name!r}", file=file,
                             where=where)
        if name in bodies:
            return name
        if len(name) >= 2:
            from .scene import split_link_name
            try:
                p, q = split_link_name(name)
                if q + p in bodies:
                    return q + p
            except SceneError:
                pass
        raise UnknownLabelError(f"unknown link or slider {name!r}: {suggest(name, bodies)}",
                                file=file, where=where)

    def point_body(label, on, where, allow_ground=False) -> str | None:
        if not isinstance(label, str):
            raise SceneError(f"expected a point label, got {label!r}", file=file, where=where)
        if label not in members:
            raise UnknownLabelError(f"unknown point {label!r}: {suggest(label, members)}",
                                    file=file, where=where)
        carriers = members[label]
        if on is not None:
            b = body_name(on, where.rsplit(".", 1)[0] + ".on")
            if b not in carriers:
                raise SceneError(f"{label} is not a point of {b} (it is on "
                                 f"{', '.join(carriers) or 'the ground only'})", file=file,
                                 where=where)
            return b
        if not carriers:
            if allow_ground:
                return None
            raise SceneError(f"{label} is a fixed point: a load or mass there does nothing",
                             file=file, where=where)
        if label in carriers and bodies[label].kind == "block":
            return label          # a load at a slider point acts on its block (the piston)
        if len(carriers) > 1:
            raise SceneError(f"{label} joins {' and '.join(carriers)}: say which body carries "
                             f"it, e.g. on = \"{carriers[0]}\"", file=file, where=where)
        return carriers[0]

    # ---- masses
    masses = []
    raw = ex.get("masses", {})
    r.table(raw, "masses", tuple(raw))
    for name, spec in raw.items():
        where = f"masses.{name}"
        r.table(spec, where, ("mass", "at", "on", "inertia", "radius", "radius_of_gyration",
                              "centre", "centre_left", "free", "spin"), required=("mass",))
        mass = r.quantity(spec["mass"], "mass", where + ".mass")
        if mass < 0:
            raise SceneError(f"mass must not be negative, got {spec['mass']!r}", file=file,
                             where=where + ".mass")
        free = spec.get("free", "spin" in spec)
        if not isinstance(free, bool):
            raise SceneError("free must be true or false", file=file, where=where + ".free")
        spin = r.quantity(spec["spin"], "angular_velocity", where + ".spin") \
            if "spin" in spec else None
        if spin is not None and not free:
            raise SceneError("a spin needs free = true (a disc turning freely on a frictionless "
                             "pin)", file=file, where=where + ".spin")
        if "at" in spec:
            for bad in ("centre", "centre_left"):
                if bad in spec:
                    raise SceneError(f"a point mass sits at its point: {bad!r} does not apply",
                                     file=file, where=f"{where}.{bad}")
            at = spec["at"]
            body = point_body(at, spec.get("on"), where + ".at")
            inertia, how = _inertia(r, spec, mass, None, where, default="point")
            kind = "block" if bodies[body].kind == "block" else "point"
            masses.append(MassItem(name, body, kind, mass, inertia, how, at=at, free=free,
                                   spin=spin))
            continue
        if "on" in spec:
            raise SceneError("'on' goes with 'at' (a point mass); a link's own mass is written "
                             "[masses.LINK]", file=file, where=where + ".on")
        body = body_name(name, where)
        b = bodies[body]
        if b.kind == "block":
            for bad in ("inertia", "radius", "radius_of_gyration", "centre", "centre_left",
                        "free", "spin"):
                if bad in spec:
                    raise SceneError(f"{body} is a slider block (it does not turn): {bad!r} "
                                     f"does not apply", file=file, where=f"{where}.{bad}")
            masses.append(MassItem(name, body, "block", mass, 0.0, "translating block",
                                   at=body))
            continue
        if free:
            raise SceneError("free = true is for a disc on a pin: write it with at = ...",
                             file=file, where=where + ".free")
        length = b.length
        if "centre" in spec:
            c = spec["centre"]
            if isinstance(c, (int, float)) and not isinstance(c, bool):
                if length is None:
                    raise SceneError(f"{body} has no stated length, so give the centre as a "
                                     f"distance from {b.a}, e.g. centre = \"90 mm\"", file=file,
                                     where=where + ".centre")
                along = float(c) * length
            else:
                along = r.quantity(c, "length", where + ".centre")
        elif length is not None:
            along = length / 2.0
        else:
            raise SceneError(f"{body} has no stated length: give its centre of mass as a "
                             f"distance from {b.a}, e.g. centre = \"90 mm\"", file=file,
                             where=where + ".centre")
        left = r.quantity(spec.get("centre_left", "0 m"), "length", where + ".centre_left")
        inertia, how = _inertia(r, spec, mass, length, where, default="rod")
        rod = how.startswith("uniform rod")
        if rod and (abs(along - length / 2.0) > 1e-12 * length or left != 0.0):
            raise SceneError("a uniform rod has its centre at the mid-point: remove 'centre' or "
                             "give the inertia", file=file, where=where + ".centre")
        masses.append(MassItem(name, body, "link", mass, inertia, how, along=along, left=left,
                               rod=rod))

    # ---- gravity
    graw = ex.get("gravity", None)
    gravity = np.zeros(2)
    if graw is not None:
        r.table(graw, "gravity", ("g", "direction", "enabled"))
        enabled = graw.get("enabled", True)
        if not isinstance(enabled, bool):
            raise SceneError("enabled must be true or false", file=file,
                             where="gravity.enabled")
        g = r.quantity(graw.get("g", "9.81 m/s^2"), "acceleration", "gravity.g")
        d = r.quantity(graw.get("direction", "-90 deg"), "angle", "gravity.direction")
        if enabled:
            gravity = g * np.array([math.cos(d), math.sin(d)])

    # ---- forces
    forces = []
    raw = ex.get("forces", {})
    r.table(raw, "forces", tuple(raw))
    for name, spec in raw.items():
        where = f"forces.{name}"
        r.table(spec, where, ("at", "on", "force", "magnitude", "direction", "pressure", "bore",
                              "diameter"), required=("at",))
        body = point_body(spec["at"], spec.get("on"), where + ".at")
        ways = [k for k in ("force", "magnitude", "pressure") if k in spec]
        if len(ways) != 1:
            raise SceneError("give the force one way: force = [\"0 N\", \"20 N\"], or "
                             "magnitude + direction, or pressure + bore + direction",
                             file=file, where=where)
        if "force" in spec:
            v = spec["force"]
            if not isinstance(v, list) or len(v) != 2:
                raise SceneError(f"expected force = [Fx, Fy] with units, e.g. [\"0 N\", "
                                 f"\"20 N\"], got {v!r}", file=file, where=where + ".force")
            f = (r.quantity(v[0], "force", where + ".force[0]"),
                 r.quantity(v[1], "force", where + ".force[1]"))
            how = f"({f[0]:.6g}, {f[1]:.6g}) N"
        else:
            if "direction" not in spec:
                raise SceneError("missing key 'direction' (the angle of the force, CCW from "
                                 "+x)", file=file, where=where)
            d = r.quantity(spec["direction"], "angle", where + ".direction")
            if "magnitude" in spec:
                mag = r.quantity(spec["magnitude"], "force", where + ".magnitude")
                how = f"{mag:.6g} N at {math.degrees(d):.6g}°"
            else:
                p = r.quantity(spec["pressure"], "pressure", where + ".pressure")
                key = "bore" if "bore" in spec else "diameter"
                if key not in spec:
                    raise SceneError("a pressure needs the bore (piston diameter): "
                                     "bore = \"80 mm\"", file=file, where=where)
                dia = r.quantity(spec[key], "length", f"{where}.{key}")
                if dia <= 0:
                    raise SceneError(f"{key} must be positive", file=file,
                                     where=f"{where}.{key}")
                area = math.pi * dia * dia / 4.0
                mag = p * area
                how = (f"p × π d²/4 = {p:.6g} Pa × π × {dia:.6g}²/4 = {mag:.6g} N at "
                       f"{math.degrees(d):.6g}°")
            f = (mag * math.cos(d), mag * math.sin(d))
        forces.append(AppliedForce(name, body, spec["at"], f, how))

    # ---- torques (applied, and friction at pins)
    torques, frictions = [], []
    raw = ex.get("torques", {})
    r.table(raw, "torques", tuple(raw))
    for name, spec in raw.items():
        where = f"torques.{name}"
        r.table(spec, where, ("on", "at", "torque", "sense", "friction", "between"))
        if ("torque" in spec) == ("friction" in spec):
            raise SceneError("give either torque = \"6 N m\" (with on = LINK and sense) or "
                             "friction = \"0.1 N m\" (with at = PIN)", file=file, where=where)
        for bad in (("between",) if "torque" in spec else ("sense", "on")):
            if bad in spec:
                raise SceneError(f"{bad!r} does not apply to "
                                 f"{'an applied torque' if 'torque' in spec else 'a friction torque (it opposes the relative rotation at its pin)'}",
                                 file=file, where=f"{where}.{bad}")
        if "torque" in spec:
            if "on" not in spec:
                raise SceneError("missing key 'on' (the link the torque acts on)", file=file,
                                 where=where)
            body = body_name(spec["on"], where + ".on")
            t = r.quantity(spec["torque"], "torque", where + ".torque")
            if "sense" not in spec:
                raise SceneError("missing key 'sense' ('CW' or 'CCW')", file=file, where=where)
            t = abs(t) * r.sense(spec["sense"], where + ".sense")
            at = spec.get("at")
            if at is not None and (at not in members or body not in members[at]):
                raise UnknownLabelError(f"{at!r} is not a point of {body}", file=file,
                                        where=where + ".at")
            torques.append(AppliedTorque(name, body, at, t))
        else:
            if "at" not in spec:
                raise SceneError("friction needs the pin: at = \"O\"", file=file, where=where)
            t = r.quantity(spec["friction"], "torque", where + ".friction")
            if t < 0:
                raise SceneError("a friction torque is a magnitude: it must not be negative",
                                 file=file, where=where + ".friction")
            first, second = _pin_pair(scene, members, spec, where, body_name)
            frictions.append(Friction(name, spec["at"], first, second, t))

    # ---- springs
    springs = []
    raw = ex.get("springs", {})
    r.table(raw, "springs", tuple(raw))
    for name, spec in raw.items():
        where = f"springs.{name}"
        r.table(spec, where, ("stiffness", "between", "free_length", "extension", "at", "on",
                              "direction", "twist"), required=("stiffness",))
        sv = spec["stiffness"]
        try:
            k = r.quantity(sv, "stiffness", where + ".stiffness")
            kind = "linear"
        except UnitError:
            try:
                k = r.quantity(sv, "torsional_stiffness", where + ".stiffness")
                kind = "torsional"
            except UnitError:
                raise UnitError(f"stiffness {sv!r} needs a unit: 'N/m' (linear spring) or "
                                f"'N m/rad' (torsional spring)", file=file,
                                where=where + ".stiffness") from None
        if k < 0:
            raise SceneError("stiffness must not be negative", file=file,
                             where=where + ".stiffness")
        if kind == "torsional":
            for bad in ("free_length", "extension", "direction"):
                if bad in spec:
                    raise SceneError(f"{bad!r} is for a linear spring; a torsional spring has "
                                     f"at = PIN and twist", file=file, where=f"{where}.{bad}")
            if "at" not in spec:
                raise SceneError("a torsional spring needs its pin: at = \"O\"", file=file,
                                 where=where)
            first, second = _pin_pair(scene, members, spec, where, body_name)
            twist = r.quantity(spec.get("twist", "0 deg"), "angle", where + ".twist")
            springs.append(Spring(name, "torsional", k, at=spec["at"], first=first,
                                  second=second, twist=twist))
            continue
        if "between" in spec:
            ends = spec["between"]
            if not isinstance(ends, list) or len(ends) != 2:
                raise SceneError("between = [\"S\", \"H\"]: the two points the spring joins",
                                 file=file, where=where + ".between")
            if ("free_length" in spec) == ("extension" in spec):
                raise SceneError("give exactly one of free_length or extension (at this "
                                 "instant; negative when compressed)", file=file, where=where)
            on = spec.get("on", ["", ""])
            if not isinstance(on, list) or len(on) != 2:
                raise SceneError("on = [\"BC\", \"\"]: the body carrying each end ('' when "
                                 "there is only one)", file=file, where=where + ".on")
            e = tuple((lab, point_body(lab, o or None, f"{where}.between", allow_ground=True))
                      for lab, o in zip(ends, on))
            fl = r.quantity(spec["free_length"], "length", where + ".free_length") \
                if "free_length" in spec else None
            ext = r.quantity(spec["extension"], "length", where + ".extension") \
                if "extension" in spec else None
            springs.append(Spring(name, "linear", k, ends=e, free_length=fl, extension=ext))
        else:
            if "at" not in spec or "direction" not in spec or "extension" not in spec:
                raise SceneError("a linear spring is either between = [\"S\", \"H\"] with "
                                 "free_length, or at = \"S\" with direction (towards its far "
                                 "end, which keeps it parallel) and extension at this instant",
                                 file=file, where=where)
            body = point_body(spec["at"], spec.get("on"), where + ".at")
            d = r.quantity(spec["direction"], "angle", where + ".direction")
            ext = r.quantity(spec["extension"], "length", where + ".extension")
            springs.append(Spring(name, "directional", k, at=spec["at"], body=body,
                                  direction=(math.cos(d), math.sin(d)), extension=ext))

    # ---- dynamics
    draw = ex.get("dynamics", {})
    r.table(draw, "dynamics", ("mode", "after", "steps"))
    mode = draw.get("mode", "kinetostatic")
    if mode not in MODES:
        raise SceneError(f"mode must be one of {', '.join(MODES)}; got {mode!r}", file=file,
                         where="dynamics.mode")
    after_raw = draw.get("after", [])
    if isinstance(after_raw, str):
        after_raw = [after_raw]
    if not isinstance(after_raw, list):
        raise SceneError("after = [\"30 deg\"]: the rotations of the driver at which to report",
                         file=file, where="dynamics.after")
    after = tuple(abs(r.quantity(a, "angle", f"dynamics.after[{i}]"))
                  for i, a in enumerate(after_raw))
    if after and mode != "release":
        raise SceneError("'after' is for mode = \"release\"", file=file, where="dynamics.after")
    steps = draw.get("steps", 200)
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 4:
        raise SceneError("steps must be a whole number ≥ 4", file=file, where="dynamics.steps")
    drv = scene.driver
    if mode in ("torque-driven", "release"):
        if isinstance(drv, Crank) and drv.alpha != 0.0:
            raise SceneError(f"mode = {mode!r} finds the driver's angular acceleration from the "
                             f"torques: remove driver.alpha", file=file, where="driver.alpha")
        if isinstance(drv, SliderDrive) and drv.acceleration != 0.0:
            raise SceneError(f"mode = {mode!r} finds the driver's acceleration from the forces: "
                             f"remove driver.acceleration", file=file,
                             where="driver.acceleration")
    if mode == "release" and not isinstance(drv, Crank):
        raise UnsupportedError("mode = \"release\" needs a crank as the driver (its angle is the "
                               "coordinate)", file=file, where="dynamics.mode")
    if "acceleration" not in scene.solve:
        raise SceneError("forces need the acceleration polygon: remove 'solve' or write "
                         "solve = [\"velocity\", \"acceleration\"]", file=file, where="solve")

    answers = _answers(scene, r)
    driver_body = drv.link if isinstance(drv, Crank) else drv.point
    return ForceModel(scene, bodies, members, tuple(joints), tuple(slots),
                      tuple(scene.sliders), tuple(masses), tuple(forces), tuple(torques),
                      tuple(frictions), tuple(springs), gravity, mode, after, steps, answers,
                      driver_body)


def _pin_pair(scene, members, spec, where, body_name) -> tuple[str, str | None]:
    """The two bodies a pin element (friction, torsional spring) acts between."""
    file = scene.file
    at = spec["at"]
    if not isinstance(at, str) or at not in members:
        raise UnknownLabelError(f"unknown point {at!r}: {suggest(str(at), members)}", file=file,
                                where=where + ".at")
    carriers = list(members[at])
    if "between" in spec:
        b = spec["between"]
        if not isinstance(b, list) or len(b) not in (1, 2):
            raise SceneError("between = [\"AB\", \"BC\"] (or one link, against the ground)",
                             file=file, where=where + ".between")
        names = [body_name(x, where + ".between") for x in b]
        for n in names:
            if n not in carriers:
                raise SceneError(f"{n} is not pinned at {at}", file=file, where=where + ".between")
        if len(names) == 1:
            if at not in scene.ground:
                raise SceneError(f"{at} is not a fixed pivot: name both links", file=file,
                                 where=where + ".between")
            return names[0], None
        return names[0], names[1]
    if at in scene.ground and len(carriers) == 1:
        return carriers[0], None
    if at not in scene.ground and len(carriers) == 2:
        return carriers[0], carriers[1]
    if not carriers:
        raise SceneError(f"no moving link is pinned at {at}", file=file, where=where + ".at")
    raise SceneError(f"{at} joins {', '.join(carriers)}"
                     f"{' and the ground' if at in scene.ground else ''}: say which, "
                     f"between = [\"{carriers[0]}\"{', ...' if len(carriers) > 1 else ''}]",
                     file=file, where=where)


def _inertia(r: _Reader, spec, mass, length, where, default) -> tuple[float, str]:
    if "radius_of_gyration" in spec:
        if "inertia" in spec:
            raise SceneError("give inertia or radius_of_gyration, not both", file=r.file,
                             where=where)
        k = r.quantity(spec["radius_of_gyration"], "length", where + ".radius_of_gyration")
        return mass * k * k, f"m k² = {mass:.6g} × {k:.6g}²"
    how = spec.get("inertia", default)
    if how == "rod":
        if length is None:
            raise SceneError("a uniform rod needs the link's length: this link has none "
                             "(give inertia = \"... kg m^2\")", file=r.file,
                             where=where + ".inertia")
        return mass * length * length / 12.0, f"uniform rod m l²/12 = {mass:.6g} × {length:.6g}²/12"
    if how == "disc":
        if "radius" not in spec:
            raise SceneError("a disc needs its radius: radius = \"100 mm\"", file=r.file,
                             where=where)
        rad = r.quantity(spec["radius"], "length", where + ".radius")
        return mass * rad * rad / 2.0, f"disc m r²/2 = {mass:.6g} × {rad:.6g}²/2"
    if how in ("point", "none"):
        if "radius" in spec:
            raise SceneError("radius goes with inertia = \"disc\"", file=r.file,
                             where=where + ".radius")
        return 0.0, "point mass"
    if "radius" in spec:
        raise SceneError("radius goes with inertia = \"disc\"", file=r.file,
                         where=where + ".radius")
    if isinstance(how, str) and how and (how[0].isdigit() or how[0] in "+-."):
        i = r.quantity(how, "inertia", where + ".inertia")
        if i < 0:
            raise SceneError("a moment of inertia must not be negative", file=r.file,
                             where=where + ".inertia")
        return i, "given"
    raise SceneError(f"inertia must be 'rod', 'disc', 'point' or a value such as "
                     f"'0.002 kg m^2'; got {how!r}", file=r.file, where=where + ".inertia")


def _answers(scene: Scene, r: _Reader) -> tuple[ForceAnswer, ...]:
    raw = scene.extra.get("force_answers", [])
    if not isinstance(raw, list):
        raise SceneError("write force answers as [[force_answers]] tables", file=scene.file,
                         where="force_answers")
    default_tol = drawing_tolerance(scene.source, r)
    out = []
    for i, spec in enumerate(raw):
        where = f"force_answers[{i}]"
        fields = answer_fields(spec, r, where, default_tol, extra_keys=("positive", "state"),
                               extra_units=EXTRA_UNITS)
        positive = r.sense(spec.get("positive", "CCW"), where + ".positive")
        state = spec.get("state")
        if state is not None and not isinstance(state, str):
            raise SceneError("state must be text ('release' or a rotation such as '30 deg')",
                             file=r.file, where=where + ".state")
        _check_expr(fields["quantity"], fields["unit"], scene, where)
        out.append(ForceAnswer(positive=positive, state=state, **fields))
    return tuple(out)


# ---------------------------------------------------------------- reading the polygons
def _pos(sol: Solution, label: str) -> np.ndarray:
    return np.array(sol.points[label].position)


def _kin(sol: Solution, label: str, kind: str) -> np.ndarray:
    v = getattr(sol.points[label], kind)
    return np.zeros(2) if v is None else np.array(v)


def _c(v) -> complex:
    return complex(v[0], v[1])


def image(sol: Solution, body: Body, r: np.ndarray, kind: str) -> np.ndarray:
    """Velocity or acceleration of the point at ``r`` of ``body``: the image of the body in the
    polygon is similar to the body, so the point's vertex is where ``r`` sits relative to the
    body's two labelled vertices (complex ratio).  A slider block translates."""
    if body.kind == "block":
        return _kin(sol, body.a, kind)
    pa, pb = _c(_pos(sol, body.a)), _c(_pos(sol, body.b))
    va, vb = _c(_kin(sol, body.a, kind)), _c(_kin(sol, body.b, kind))
    z = va + (vb - va) * ((_c(r) - pa) / (pb - pa))
    return np.array([z.real, z.imag])


def body_omega(sol: Solution, body: Body) -> float:
    if body.kind == "block":
        return 0.0
    return float(sol.links[body.name].omega or 0.0)


def body_alpha(sol: Solution, body: Body) -> float:
    if body.kind == "block":
        return 0.0
    return float(sol.links[body.name].alpha or 0.0)


def body_angle(sol: Solution, body: Body) -> float:
    if body.kind == "block":
        return 0.0
    d = _pos(sol, body.b) - _pos(sol, body.a)
    return math.atan2(d[1], d[0])


def unit_r(sol: Solution, body: Body) -> np.ndarray:
    if body.kind == "block":
        g = sol.scene.sliders[body.a]
        return np.array(g.direction)
    d = _pos(sol, body.b) - _pos(sol, body.a)
    return d / float(np.hypot(*d))


def perp(v) -> np.ndarray:
    return np.array([-v[1], v[0]])


def cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def centre(model: ForceModel, sol: Solution, item: MassItem) -> np.ndarray:
    if item.kind in ("point", "block"):
        return _pos(sol, item.at)
    body = model.bodies[item.body]
    u = unit_r(sol, body)
    return _pos(sol, body.a) + item.along * u + item.left * perp(u)


# ---------------------------------------------------------------- loads
@dataclass(frozen=True)
class Load:
    """A force ``force`` at ``pos`` (label ``at``) and/or a couple on ``body``; ``source`` names
    the table entry it comes from; ``item`` marks the weight of a mass item."""
    source: str
    kind: str              # 'force' | 'torque' | 'gravity' | 'spring' | 'friction' | 'input'
    body: str
    at: str | None
    pos: np.ndarray | None
    force: np.ndarray
    couple: float
    item: str | None = None


def prepare(model: ForceModel, base: Solution) -> None:
    """Record the springs' references at the scene's instant (``base``)."""
    for s in model.springs:
        if s.kind == "linear":
            (l1, _), (l2, _) = s.ends
            length = float(np.hypot(*(_pos(base, l2) - _pos(base, l1))))
            model.ref[s.name] = s.free_length if s.free_length is not None \
                else length - s.extension
            if model.ref[s.name] < 0:
                raise SceneError(f"the free length comes out negative "
                                 f"({model.ref[s.name]:.6g} m)", file=model.scene.file,
                                 where=f"springs.{s.name}")
        elif s.kind == "directional":
            model.ref[s.name] = _pos(base, s.at)
        else:
            model.ref[s.name] = _rel_angle(model, base, s.first, s.second) - s.twist


def _rel_angle(model, sol, first, second) -> float:
    a = body_angle(sol, model.bodies[first])
    b = body_angle(sol, model.bodies[second]) if second else 0.0
    return a - b


def _wrap(x: float) -> float:
    return (x + math.pi) % (2.0 * math.pi) - math.pi


def spring_state(model: ForceModel, sol: Solution, s: Spring) -> dict:
    """Extension (or twist), force (or torque) and potential energy of a spring at ``sol``."""
    if s.kind == "linear":
        (l1, _), (l2, _) = s.ends
        d = _pos(sol, l2) - _pos(sol, l1)
        length = float(np.hypot(*d))
        ext = length - model.ref[s.name]
        return {"extension": ext, "tension": s.stiffness * ext, "length": length,
                "energy": 0.5 * s.stiffness * ext * ext, "unit": d / length}
    if s.kind == "directional":
        e = np.array(s.direction)
        ext = s.extension - float((_pos(sol, s.at) - model.ref[s.name]) @ e)
        return {"extension": ext, "tension": s.stiffness * ext,
                "energy": 0.5 * s.stiffness * ext * ext, "unit": e}
    twist = _wrap(_rel_angle(model, sol, s.first, s.second) - model.ref[s.name])
    return {"twist": twist, "torque": -s.stiffness * twist,
            "energy": 0.5 * s.stiffness * twist * twist}


def loads(model: ForceModel, sol: Solution, vsol: Solution,
          motion: int | None = None) -> list[Load]:
    """Every external load at the state ``sol``.  ``vsol`` (velocities per unit input rate) and
    ``motion`` (+1/−1, the sense of the input's motion) fix a friction's sense when the pin does
    not turn at this instant (released from rest)."""
    out: list[Load] = []
    g = model.gravity
    if g.any():
        for it in model.masses:
            out.append(Load(f"weight of {it.name}", "gravity", it.body, it.at,
                            centre(model, sol, it), it.mass * g, 0.0, it.name))
    for f in model.forces:
        out.append(Load(f.name, "force", f.body, f.at, _pos(sol, f.at), np.array(f.force), 0.0))
    for t in model.torques:
        out.append(Load(t.name, "torque", t.body, t.at, None, np.zeros(2), t.torque))
    for s in model.springs:
        st = spring_state(model, sol, s)
        if s.kind == "linear":
            (l1, b1), (l2, b2) = s.ends
            f = st["tension"] * st["unit"]          # pulls l1 towards l2
            if b1:
                out.append(Load(s.name, "spring", b1, l1, _pos(sol, l1), f, 0.0))
            if b2:
                out.append(Load(s.name, "spring", b2, l2, _pos(sol, l2), -f, 0.0))
        elif s.kind == "directional":
            out.append(Load(s.name, "spring", s.body, s.at, _pos(sol, s.at),
                            st["tension"] * st["unit"], 0.0))
        else:
            out.append(Load(s.name, "spring", s.first, s.at, None, np.zeros(2), st["torque"]))
            if s.second:
                out.append(Load(s.name, "spring", s.second, s.at, None, np.zeros(2),
                                -st["torque"]))
    for fr in model.frictions:
        sense = friction_sense(model, sol, vsol, fr, motion)
        t = -fr.torque * sense
        out.append(Load(fr.name, "friction", fr.first, fr.at, None, np.zeros(2), t))
        if fr.second:
            out.append(Load(fr.name, "friction", fr.second, fr.at, None, np.zeros(2), -t))
    return out


def friction_sense(model, sol, vsol, fr: Friction, motion) -> int:
    """Sense (+1 CCW / −1 CW / 0) of the relative rotation of ``fr.first`` against
    ``fr.second`` at its pin; at rest, the sense it is about to turn in (``motion``)."""
    b1 = model.bodies[fr.first]
    b2 = model.bodies[fr.second] if fr.second else None
    w = body_omega(sol, b1) - (body_omega(sol, b2) if b2 else 0.0)
    scale = max(1.0, abs(body_omega(sol, b1)))
    if abs(w) > 1e-12 * scale:
        return 1 if w > 0 else -1
    if motion:
        ws = body_omega(vsol, b1) - (body_omega(vsol, b2) if b2 else 0.0)
        if abs(ws) > 1e-12:
            return int(math.copysign(1, ws * motion))
    return 0


# ---------------------------------------------------------------- Newton–Euler
@dataclass(frozen=True)
class Inertia:
    """A mass item's inertia at one state: m a_G and I_G α (the inertia force is −m a_G)."""
    item: str
    body: str
    mass: float
    inertia: float
    centre: np.ndarray
    v: np.ndarray
    a: np.ndarray
    alpha: float            # of its body (0 for a free disc)
    omega: float

    @property
    def ma(self) -> np.ndarray:
        return self.mass * self.a

    @property
    def i_alpha(self) -> float:
        return self.inertia * self.alpha


def inertias(model: ForceModel, sol: Solution) -> list[Inertia]:
    out = []
    for it in model.masses:
        body = model.bodies[it.body]
        g = centre(model, sol, it)
        w = 0.0 if it.free else body_omega(sol, body)
        al = 0.0 if it.free else body_alpha(sol, body)
        out.append(Inertia(it.name, it.body, it.mass, it.inertia, g,
                           image(sol, body, g, "velocity"), image(sol, body, g, "acceleration"),
                           al, w))
    return out


@dataclass
class NEResult:
    """Newton–Euler at one state."""
    names: list[str]                  # the unknowns, in words
    values: np.ndarray
    pin: dict                         # (label, body) -> force on body at label (from the pin)
    ground: dict                      # label -> force on the ground at the pin
    slot: dict                        # pin -> (signed normal force on the lever, unit normal)
    guide: dict                       # label -> (normal force on block, unit normal, couple)
    effort: float | None              # input torque (crank) / force (slider) — kinetostatic
    alpha: float | None               # torque-driven: the input's angular (or linear) accel.
    loads: list[Load]
    residual: float
    equations: int


def newton_euler(model: ForceModel, sol: Solution, vsol: Solution, sol1: Solution | None = None,
                 motion: int | None = None, lds: list[Load] | None = None) -> NEResult:
    """Solve every body's F = m a_G and M = I_G α + r × m a_G at once.

    Kinetostatic (``sol1`` None): the input torque is the last unknown.  Torque-driven: ``sol``
    is the kinematic solution with the input's α = 0 and ``sol1`` with α = 1; the unknown is α.
    """
    scene = model.scene
    bodies = model.bodies
    order = list(bodies)
    idx = {n: i for i, n in enumerate(order)}
    ref = {n: _pos(sol, bodies[n].a) for n in order}
    cols: list[str] = []
    neq = 3 * len(order)
    entries: list[tuple[int, int, float]] = []

    def col(name):
        cols.append(name)
        return len(cols) - 1

    def add_force(c, body, r, f):
        i = 3 * idx[body]
        entries.append((i, c, f[0]))
        entries.append((i + 1, c, f[1]))
        entries.append((i + 2, c, cross(r - ref[body], f)))

    def add_couple(c, body, m):
        entries.append((3 * idx[body] + 2, c, m))

    ex, ey = np.array([1.0, 0.0]), np.array([0.0, 1.0])
    pin_cols = []
    for j in model.joints:
        r = _pos(sol, j.label)
        free = j.members if j.ground else j.members[:-1]
        cs = []
        for m in free:
            cx, cy = col(f"pin {j.label} on {m}, x"), col(f"pin {j.label} on {m}, y")
            add_force(cx, m, r, ex)
            add_force(cy, m, r, ey)
            if not j.ground:
                add_force(cx, j.members[-1], r, -ex)
                add_force(cy, j.members[-1], r, -ey)
            cs.append((m, cx, cy))
        pin_cols.append((j, cs))
    slot_cols = []
    for s in model.slots:
        rp = _pos(sol, s.pin)
        u = np.array(s.direction) if s.direction else rp - _pos(sol, s.pivot)
        n = perp(u / float(np.hypot(*u)))
        c = col(f"slot force on {s.lever} at {s.pin} (⟂ slot)")
        add_force(c, s.lever, rp, n)
        add_force(c, s.carrier, rp, -n)
        slot_cols.append((s, c, n))
    guide_cols = []
    for lab in model.guides:
        n = perp(np.array(scene.sliders[lab].direction))
        r = _pos(sol, lab)
        cn = col(f"guide force on {lab} (⟂ guide)")
        add_force(cn, lab, r, n)
        cm = col(f"guide couple on {lab}")
        add_couple(cm, lab, 1.0)
        guide_cols.append((lab, cn, cm, n))
    drv = scene.driver
    cdrv = col("input torque on " + model.driver_body if isinstance(drv, Crank)
               else "input force on " + model.driver_body)
    lds = loads(model, sol, vsol, motion) if lds is None else lds

    def inertia_rhs(s: Solution) -> np.ndarray:
        out = np.zeros(neq)
        for it in inertias(model, s):
            i = 3 * idx[it.body]
            out[i:i + 2] += it.ma
            out[i + 2] += it.i_alpha + cross(it.centre - ref[it.body], it.ma)
        return out

    rhs = inertia_rhs(sol)
    for ld in lds:
        i = 3 * idx[ld.body]
        rhs[i:i + 2] -= ld.force
        if ld.pos is not None:
            rhs[i + 2] -= cross(ld.pos - ref[ld.body], ld.force)
        rhs[i + 2] -= ld.couple
    if sol1 is None:
        if isinstance(drv, Crank):
            add_couple(cdrv, drv.link, 1.0)
        else:
            add_force(cdrv, drv.point, _pos(sol, drv.point),
                      np.array(scene.sliders[drv.point].direction))
    else:
        cols[cdrv] = ("input angular acceleration" if isinstance(drv, Crank)
                      else "input acceleration")
    A = np.zeros((neq, len(cols)))
    for i, c, v in entries:
        A[i, c] += v
    if sol1 is not None:
        A[:, cdrv] = -(inertia_rhs(sol1) - inertia_rhs(sol))
    if A.shape[0] != A.shape[1]:
        raise UnsupportedError(
            f"the force analysis has {A.shape[0]} equations (3 per moving body: "
            f"{', '.join(order)}) but {A.shape[1]} unknowns ({'; '.join(cols)}): the mechanism "
            f"is not a single closed chain this module can resolve", file=scene.file)
    scale = np.abs(A).max(axis=0)
    scale[scale == 0] = 1.0
    As = A / scale
    sv = np.linalg.svd(As, compute_uv=False)
    if sv[-1] <= 1e-11 * sv[0]:
        raise UnsupportedError(
            "the force equations are singular at this position (a toggle, or a body the "
            "unknowns cannot hold): the reactions are not determined", file=scene.file)
    x = np.linalg.solve(As, rhs) / scale
    residual = float(np.abs(A @ x - rhs).max())
    pin, ground = {}, {}
    for j, cs in pin_cols:
        total = np.zeros(2)
        for m, cx, cy in cs:
            f = np.array([x[cx], x[cy]])
            pin[(j.label, m)] = f
            total += f
        if j.ground:
            ground[j.label] = -total
        else:
            pin[(j.label, j.members[-1])] = -total
    slot = {s.pin: (float(x[c]), n) for s, c, n in slot_cols}
    guide = {lab: (float(x[cn]), n, float(x[cm])) for lab, cn, cm, n in guide_cols}
    return NEResult(cols, x, pin, ground, slot, guide,
                    None if sol1 is not None else float(x[cdrv]),
                    float(x[cdrv]) if sol1 is not None else None, lds, residual, neq)


def contact_force(model: ForceModel, ne: NEResult, label: str, body: str) -> np.ndarray:
    """The force on ``body`` at ``label`` from what it is joined to there (pins and slots)."""
    f = np.zeros(2)
    found = False
    if (label, body) in ne.pin:
        f = f + ne.pin[(label, body)]
        found = True
    for s in model.slots:
        labs = {s.pin}
        if s.lever == body and s.pin in model.scene.slots:
            labs.add(model.scene.slots[s.pin].coincident)
        if label in labs and body in (s.lever, s.carrier):
            value, n = ne.slot[s.pin]
            f = f + (value * n if body == s.lever else -value * n)
            found = True
    if not found:
        if body not in model.bodies:
            raise UnknownLabelError(f"unknown body {body!r}: {suggest(body, model.bodies)}",
                                    file=model.scene.file)
        raise UnknownLabelError(f"{body} is not joined to anything at {label!r} (its joints: "
                                f"{', '.join(_joint_labels(model, body)) or 'none'})",
                                file=model.scene.file)
    return f


def _joint_labels(model, body) -> list[str]:
    out = [j.label for j in model.joints if body in j.members]
    for s in model.slots:
        if body in (s.lever, s.carrier):
            out.append(s.pin)
    return out


# ---------------------------------------------------------------- virtual work
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


# ---------------------------------------------------------------- states
@dataclass
class State:
    """One analysed instant: kinematics (final), virtual velocities, Newton–Euler, virtual work."""
    name: str
    sol: Solution
    vsol: Solution
    ne: NEResult
    inertia: list[Inertia]
    vw_effort: float | None
    breakdown: list[tuple[str, float]]
    applied_driver: float            # torque (force) applied to the driver by [torques]/[forces]
    rotation: float = 0.0            # release: the driver's rotation from the release position
    extra: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)


def driver_state(scene: Scene, *, angle=None, omega=None, alpha=None) -> Scene:
    drv = scene.driver
    if isinstance(drv, Crank):
        d = replace(drv, angle=drv.angle if angle is None else angle,
                    omega=drv.omega if omega is None else omega,
                    alpha=drv.alpha if alpha is None else alpha)
    else:
        d = replace(drv, velocity=drv.velocity if omega is None else omega,
                    acceleration=drv.acceleration if alpha is None else alpha)
    return replace(scene, driver=d)


def virtual_solution(scene: Scene) -> Solution:
    """Velocities per unit input rate (ω_in = 1 rad/s CCW, or 1 m/s along the guide)."""
    s = driver_state(scene, omega=1.0, alpha=0.0)
    return solve(s)


def driver_applied(model: ForceModel, ne: NEResult, vsol: Solution) -> float:
    """The input-equivalent of the loads on the driver body itself (torques, for reporting)."""
    return sum(ld.couple for ld in ne.loads if ld.body == model.driver_body
               and ld.kind == "torque")


def kinetostatic(model: ForceModel, scene: Scene, name: str = "instant",
                 motion: int | None = None) -> State:
    sol = solve(scene)
    vsol = virtual_solution(scene)
    ne = newton_euler(model, sol, vsol, motion=motion)
    vw, parts = virtual_work(model, sol, vsol, ne.loads)
    return State(name, sol, vsol, ne, inertias(model, sol), vw, parts,
                 driver_applied(model, ne, vsol), warnings=_friction_warnings(model, sol, vsol,
                                                                             motion))


def _friction_warnings(model, sol, vsol, motion) -> list[str]:
    return [f"the pin {fr.at} ({fr.name}) does not turn at this instant: its friction torque "
            f"is taken as 0 (its sense is undefined)" for fr in model.frictions
            if friction_sense(model, sol, vsol, fr, motion) == 0]


def torque_driven(model: ForceModel, scene: Scene, name: str = "instant",
                  motion: int | None = None) -> State:
    """The input's α from the applied loads (kinematics at α = 0 and α = 1, affine), then the
    kinematics at that α and every reaction."""
    s0 = driver_state(scene, alpha=0.0)
    sol0 = solve(s0)
    sol1 = solve(driver_state(scene, alpha=1.0))
    vsol = virtual_solution(scene)
    if motion is None and model.frictions and _input_rate(scene) == 0.0:
        motion = _motion_from_rest(model, sol0, sol1, vsol)
    ne = newton_euler(model, sol0, vsol, sol1, motion=motion)
    alpha = ne.alpha
    sol = solve(driver_state(scene, alpha=alpha))
    vw, parts = virtual_work(model, sol, vsol, ne.loads)
    st = State(name, sol, vsol, ne, inertias(model, sol), vw, parts,
               driver_applied(model, ne, vsol),
               warnings=_friction_warnings(model, sol, vsol, motion))
    st.extra["alpha_in"] = alpha
    return st


def _input_rate(scene: Scene) -> float:
    drv = scene.driver
    return drv.omega if isinstance(drv, Crank) else drv.velocity


def _motion_from_rest(model, sol0, sol1, vsol) -> int:
    """At rest with friction: the sense the input starts to move in (friction opposing it)."""
    results = {}
    for m in (1, -1):
        results[m] = newton_euler(model, sol0, vsol, sol1, motion=m).alpha
    if results[1] > 0:
        return 1
    if results[-1] < 0:
        return -1
    raise UnsupportedError("friction holds the mechanism at rest here (static friction is not "
                           "modelled): no motion starts", file=model.scene.file)


def analyse(scene: Scene, model: ForceModel | None = None) -> "Analysis":
    """Every state the scene asks for: one instant (kinetostatic or torque-driven), or the
    release position and the positions after the given rotations (see polygons.dynamics)."""
    model = load_model(scene) if model is None else model
    base = solve(scene)
    prepare(model, base)
    if model.mode == "kinetostatic":
        states = [kinetostatic(model, scene)]
        return Analysis(model, states, None)
    if model.mode == "torque-driven":
        return Analysis(model, [torque_driven(model, scene)], None)
    from .dynamics import release
    return release(model, scene)


@dataclass
class Analysis:
    model: ForceModel
    states: list[State]
    dynamics: dict | None       # release: energy vs integration check

    def state(self, name: str | None) -> State:
        if name is None:
            return self.states[0]
        for s in self.states:
            if s.name == name or s.name == f"after {name}":
                return s
        raise SceneError(f"no state {name!r}: the states are "
                         f"{', '.join(repr(s.name) for s in self.states)}",
                         file=self.model.scene.file)


# ---------------------------------------------------------------- sections
def section(model: ForceModel, st: State, label: str, link: str) -> tuple[float, float, float]:
    """Internal normal force N, shear S and bending moment M at the section ``label`` of
    ``link``: the force and moment on the part from the link's first label to the section,
    exerted by the rest.  N along the link (first → second label), S along k × that, M CCW."""
    scene = model.scene
    if link not in model.bodies or model.bodies[link].kind != "link":
        raise UnknownLabelError(f"unknown link {link!r}: "
                                f"{suggest(link, [b for b in model.bodies if model.bodies[b].kind == 'link'])}",
                                file=scene.file)
    body = model.bodies[link]
    if label not in body.labels:
        raise UnknownLabelError(f"{label!r} is not a point of {link}; declare it with "
                                f"[points.{label}] on = \"{link}\"", file=scene.file)
    sol, ne = st.sol, st.ne
    items = model.items_of(link)
    for it in items:
        if it.kind == "link" and not it.rod:
            raise UnsupportedError(f"section forces need {link}'s mass spread as a uniform rod "
                                   f"(inertia = \"rod\")", file=scene.file)
    pa = _pos(sol, body.a)
    u = unit_r(sol, body)
    n = perp(u)
    rx = _pos(sol, label)
    s_x = float((rx - pa) @ u)
    length = body.length

    def inside(lab) -> bool:
        s = float((_pos(sol, lab) - pa) @ u)
        return s < s_x - 1e-12 * max(1.0, abs(s_x))

    F = np.zeros(2)
    M = 0.0
    # contact forces at the labels of the inner part
    for lab in body.labels:
        if not inside(lab):
            continue
        try:
            f = contact_force(model, ne, lab, link)
        except UnknownLabelError:
            continue
        F += f
        M += cross(_pos(sol, lab) - rx, f)
    # loads: forces at labels, couples at pins (a couple with no location cannot be placed)
    for ld in ne.loads:
        if ld.body != link:
            continue
        if ld.kind == "gravity":
            it = next(m for m in model.masses if m.name == ld.item)
            if it.kind == "link":
                continue                       # the rod's own weight is spread: below
            if not inside(it.at):
                continue
        elif ld.at is None:
            if ld.couple:
                raise UnsupportedError(f"{ld.source} acts on {link} with no point: give it "
                                       f"at = LABEL to cut {link} at {label}", file=scene.file)
            continue
        elif not inside(ld.at):
            continue
        F += ld.force
        if ld.pos is not None:
            M += cross(ld.pos - rx, ld.force)
        M += ld.couple
    if isinstance(scene.driver, Crank) and scene.driver.link == link and ne.effort:
        if inside(scene.driver.pivot):
            M += ne.effort
    # inertia of the inner part
    need_f = np.zeros(2)
    need_m = 0.0
    al = body_alpha(sol, body)
    for it in items:
        if it.kind == "link":
            frac = s_x / length
            m = it.mass * frac
            g_pos = pa + 0.5 * s_x * u
            a = image(sol, body, g_pos, "acceleration")
            i_g = m * s_x * s_x / 12.0
            F += m * model.gravity
            M += cross(g_pos - rx, m * model.gravity)
            need_f += m * a
            need_m += i_g * al + cross(g_pos - rx, m * a)
        elif inside(it.at):
            g_pos = centre(model, sol, it)
            a = image(sol, body, g_pos, "acceleration")
            need_f += it.mass * a
            need_m += (0.0 if it.free else it.inertia * al) + cross(g_pos - rx, it.mass * a)
    f_int = need_f - F
    m_int = need_m - M
    return float(f_int @ u), float(f_int @ n), float(m_int)


# ---------------------------------------------------------------- answer quantities
#: function -> (dimension, flips with positive = 'CW', arg count range)
FORCE_FUNCTIONS: dict[str, tuple[str, bool, tuple[int, int]]] = {
    "Tin": ("torque", True, (0, 0)), "Tin_vw": ("torque", True, (0, 0)),
    "Tout": ("torque", True, (0, 0)),
    "Rx": ("force", False, (2, 2)), "Ry": ("force", False, (2, 2)),
    "R": ("force", False, (2, 2)), "Rr": ("force", False, (2, 3)),
    "Rn": ("force", True, (2, 3)), "Rm": ("torque", True, (3, 3)),
    "Rg": ("force", False, (1, 1)), "Cg": ("torque", True, (1, 1)),
    "Gx": ("force", False, (1, 1)), "Gy": ("force", False, (1, 1)),
    "Fx": ("force", False, (1, 1)), "Fy": ("force", False, (1, 1)),
    "F": ("force", False, (1, 1)), "Fr": ("force", False, (2, 2)),
    "Fn": ("force", True, (2, 2)), "Fm": ("torque", True, (2, 2)),
    "Fs": ("force", True, (1, 1)), "ext": ("length", False, (1, 1)),
    "mass": ("mass", False, (1, 1)),
    "I": ("inertia", False, (1, 2)), "J": ("inertia", False, (1, 2)),
    "H": ("angular_momentum", True, (1, 1)),
    "aG": ("acceleration", False, (1, 1)), "aGx": ("acceleration", False, (1, 1)),
    "aGy": ("acceleration", False, (1, 1)), "aGr": ("acceleration", False, (1, 2)),
    "aGn": ("acceleration", True, (1, 2)),
    "maG": ("force", False, (1, 1)), "IGa": ("torque", True, (1, 1)),
    "Hdot": ("torque", True, (2, 2)),
    "N": ("force", False, (2, 2)), "S": ("force", True, (2, 2)), "M": ("torque", True, (2, 2)),
    "T": ("energy", False, (0, 0)), "V": ("energy", False, (0, 0)),
}
_KIN_FLIP = ("omega", "alpha")
_CALL = re.compile(r"^\s*([A-Za-z_]+)\s*(?:\(\s*([^()]*?)\s*\))?\s*$")


def _split_terms(expr: str) -> list[tuple[int, str]]:
    """'Rx(B,AB) + Rx(A,OA)' -> [(1, 'Rx(B,AB)'), (1, 'Rx(A,OA)')]."""
    terms, depth, start, sign = [], 0, 0, 1
    s = expr.strip()
    if s.startswith("-"):
        sign, s = -1, s[1:]
    for i, ch in enumerate(s):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif ch in "+-" and depth == 0 and i > start and s[i - 1] == " ":
            terms.append((sign, s[start:i].strip()))
            sign = 1 if ch == "+" else -1
            start = i + 1
    terms.append((sign, s[start:].strip()))
    return terms


def _parse_call(term: str) -> tuple[str, list[str]]:
    m = _CALL.match(term)
    if not m:
        raise SceneError(f"cannot read quantity {term!r}")
    args = [a.strip() for a in m.group(2).split(",")] if m.group(2) else []
    return m.group(1), args


def _dimension_of(fn: str, args) -> str:
    if fn in FORCE_FUNCTIONS:
        return FORCE_FUNCTIONS[fn][0]
    return kq.dimension_of_quantity(f"{fn}({','.join(args)})")


def _check_expr(expr: str, unit: str, scene: Scene, where: str) -> None:
    dims = set()
    for _, term in _split_terms(expr):
        try:
            fn, args = _parse_call(term)
            if fn in FORCE_FUNCTIONS:
                lo, hi = FORCE_FUNCTIONS[fn][2]
                if not lo <= len(args) <= hi:
                    raise SceneError(f"{fn} takes {lo if lo == hi else f'{lo} to {hi}'} "
                                     f"argument(s), got {len(args)} in {term!r}")
            elif fn not in kq.FUNCTIONS:
                raise SceneError(f"unknown quantity function {fn!r}: "
                                 f"{suggest(fn, list(FORCE_FUNCTIONS) + list(kq.FUNCTIONS))}")
            dims.add(_dimension_of(fn, args))
        except SceneError as exc:
            raise SceneError(exc.reason, file=scene.file, where=where + ".quantity") from None
    udim = UNITS[unit][0] if unit in UNITS else EXTRA_UNITS[unit][0]
    for d in dims:
        ok = d == udim or (d == "torque" and udim == "force")   # a slider driver's 'Tin'
        if d == "angle" and udim == "angle":
            ok = True
        if not ok:
            raise UnitError(f"{expr!r} is a {d.replace('_', ' ')}, but the unit {unit!r} is a "
                            f"{udim.replace('_', ' ')}", file=scene.file, where=where + ".unit")


def to_unit(value: float, unit: str) -> float:
    if unit in UNITS:
        return value / UNITS[unit][1]
    return value / EXTRA_UNITS[unit][1]


def force_quantity(an: Analysis, expr: str, state: str | None = None,
                   positive: int = 1) -> float:
    """The SI value of ``expr`` (see README, "Forces") at ``state``; ``positive`` = −1 takes
    normal components, moments, ω and α positive clockwise."""
    st = an.state(state)
    total = 0.0
    for sign, term in _split_terms(expr):
        total += sign * _term(an, st, term, positive)
    return total


def _term(an: Analysis, st: State, term: str, positive: int) -> float:
    model = an.model
    scene = model.scene
    file = scene.file
    fn, args = _parse_call(term)
    if fn not in FORCE_FUNCTIONS:
        value = kq.quantity(st.sol, term)
        return value * positive if fn in _KIN_FLIP else value
    flip = positive if FORCE_FUNCTIONS[fn][1] else 1
    sol, ne = st.sol, st.ne

    def body(name):
        if name in model.bodies:
            return model.bodies[name]
        raise UnknownLabelError(f"unknown link or slider {name!r} in {term!r}: "
                                f"{suggest(name, model.bodies)}", file=file)

    def named(items, kind, name):
        for x in items:
            if x.name == name:
                return x
        raise UnknownLabelError(f"unknown {kind} {name!r} in {term!r}: "
                                f"{suggest(name, [x.name for x in items])}", file=file)

    def item(name):
        return named(model.masses, "mass", name)

    def point(label):
        if label not in sol.points:
            raise UnknownLabelError(f"unknown point {label!r} in {term!r}: "
                                    f"{suggest(label, sol.points)}", file=file)
        return _pos(sol, label)

    def applied(name):
        return named(model.forces, "force", name)

    def spring(name):
        return named(model.springs, "spring", name)

    def inert(name) -> Inertia:
        item(name)
        return next(i for i in st.inertia if i.item == name)

    if fn in ("Tin", "Tout", "Tin_vw"):
        if model.mode != "kinetostatic":
            raise SceneError(f"{fn} is the input torque a kinetostatic analysis finds; in mode "
                             f"{model.mode!r} the applied torques drive the mechanism",
                             file=file)
        v = st.vw_effort if fn == "Tin_vw" else ne.effort
        return flip * (-v if fn == "Tout" else v)
    if fn in ("Rx", "Ry", "R", "Rr", "Rn", "Rm"):
        lab, bname = args[0], args[1]
        point(lab)
        f = contact_force(model, ne, lab, body(bname).name)
        if fn == "Rx":
            return float(f[0])
        if fn == "Ry":
            return float(f[1])
        if fn == "R":
            return float(np.hypot(*f))
        if fn in ("Rr", "Rn"):
            fr = body(args[2] if len(args) > 2 else bname)
            u = unit_r(sol, fr)
            return float(f @ u) if fn == "Rr" else flip * float(f @ perp(u))
        return flip * cross(_pos(sol, lab) - point(args[2]), f)
    if fn in ("Rg", "Cg"):
        lab = args[0]
        if lab not in ne.guide:
            raise UnknownLabelError(f"{lab!r} is not a slider on a guide: "
                                    f"{suggest(lab, ne.guide)}", file=file)
        value, n, c = ne.guide[lab]
        return value if fn == "Rg" else flip * c
    if fn in ("Gx", "Gy"):
        lab = args[0]
        if lab not in ne.ground:
            raise UnknownLabelError(f"{lab!r} is not a fixed pivot with a link on it: "
                                    f"{suggest(lab, ne.ground)}", file=file)
        return float(ne.ground[lab][0 if fn == "Gx" else 1])
    if fn in ("Fx", "Fy", "F", "Fr", "Fn", "Fm"):
        f = applied(args[0])
        v = np.array(f.force)
        if fn == "Fx":
            return float(v[0])
        if fn == "Fy":
            return float(v[1])
        if fn == "F":
            return float(np.hypot(*v))
        if fn == "Fm":
            return flip * cross(_pos(sol, f.at) - point(args[1]), v)
        u = unit_r(sol, body(args[1]))
        return float(v @ u) if fn == "Fr" else flip * float(v @ perp(u))
    if fn in ("Fs", "ext"):
        s = spring(args[0])
        stt = spring_state(model, sol, s)
        if fn == "ext":
            if s.kind == "torsional":
                raise SceneError(f"{s.name} is torsional: its twist is not a length", file=file)
            return stt["extension"]
        return stt["tension"] if s.kind != "torsional" else flip * stt["torque"]
    if fn == "mass":
        return item(args[0]).mass
    if fn == "I":
        it = item(args[0])
        i = it.inertia
        if len(args) > 1:
            i += it.mass * float(np.sum((centre(model, sol, it) - point(args[1])) ** 2))
        return i
    if fn == "J":
        b = body(args[0])
        items = [m for m in model.items_of(b.name)]
        mtot = sum(m.mass for m in items)
        if len(args) > 1:
            p = point(args[1])
        elif mtot:
            p = sum(m.mass * centre(model, sol, m) for m in items) / mtot
        else:
            p = _pos(sol, b.a)
        return sum((0.0 if m.free else m.inertia)
                   + m.mass * float(np.sum((centre(model, sol, m) - p) ** 2)) for m in items)
    if fn == "H":
        it = item(args[0])
        if not it.free or it.spin is None:
            raise SceneError(f"H({it.name}) is the spin momentum of a free disc (spin = ...)",
                             file=file)
        return flip * it.inertia * it.spin
    if fn in ("aG", "aGx", "aGy", "aGr", "aGn", "maG", "IGa"):
        i = inert(args[0])
        if fn == "aG":
            return float(np.hypot(*i.a))
        if fn == "aGx":
            return float(i.a[0])
        if fn == "aGy":
            return float(i.a[1])
        if fn == "maG":
            return float(np.hypot(*i.ma))
        if fn == "IGa":
            return flip * i.i_alpha
        u = unit_r(sol, body(args[1] if len(args) > 1 else i.body))
        return float(i.a @ u) if fn == "aGr" else flip * float(i.a @ perp(u))
    if fn == "Hdot":
        b = body(args[0])
        p = point(args[1])
        return flip * sum(i.i_alpha + cross(i.centre - p, i.ma) for i in st.inertia
                          if i.body == b.name)
    if fn in ("N", "S", "M"):
        n, s, m = section(model, st, args[0], args[1])
        return {"N": n, "S": flip * s, "M": flip * m}[fn]
    if fn in ("T", "V"):
        key = "kinetic" if fn == "T" else "potential"
        if key not in st.extra:
            raise SceneError(f"{fn} is reported for mode = 'release' states", file=file)
        return st.extra[key]
    raise SceneError(f"unknown quantity {fn!r}", file=file)  # pragma: no cover


@dataclass(frozen=True)
class ForceCheck:
    answer: ForceAnswer
    ours: float          # in answer.unit, signed (in the answer's positive sense)
    compared: float
    diff_pct: float | None
    within: bool | None
    exact_rel: float | None


def _scale(an: Analysis) -> float:
    """A force scale for 'zero' answers: the largest load or inertia force of the first state."""
    st = an.states[0]
    mags = [float(np.hypot(*ld.force)) for ld in st.ne.loads]
    mags += [float(np.hypot(*i.ma)) for i in st.inertia]
    return max(mags + [1.0])


def check_force_answers(an: Analysis) -> list[ForceCheck]:
    out = []
    for ans in an.model.answers:
        try:
            value = force_quantity(an, ans.quantity, ans.state, ans.positive)
        except PolygonsError as exc:
            raise exc.located(file=an.model.scene.file, where="force_answers") from None
        ours = to_unit(value, ans.unit)
        compared = abs(ours) if ans.mode == "abs" else ours
        diff = within = rel = None
        if ans.tutorial is not None:
            diff = ((ans.tutorial - compared) / abs(compared) * 100.0) \
                if compared and ans.tutorial != 0.0 else None
            if ans.tutorial == 0.0:
                within = abs(compared) <= 1e-9 * max(1.0, _scale(an))
            else:
                within = abs(ans.tutorial - compared) <= ans.tolerance * max(
                    abs(ans.tutorial), abs(compared))
        if ans.exact is not None:
            rel = abs(compared - ans.exact) / abs(ans.exact) if ans.exact else abs(compared)
        out.append(ForceCheck(ans, ours, compared, diff, within, rel))
    return out
