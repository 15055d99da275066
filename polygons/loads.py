"""The force tables of a scene, parsed and checked when the scene loads: a frozen :class:`Loads`.

    [masses.BC]                 # a link (or a slider point: the piston / block)
    mass = "0.8 kg"
    inertia = "rod"             # 'rod' (m l²/12, default), 'disc' (+ radius), 'point', or "0.002 kg m^2"
    centre = 0.5                # fraction of the link from its first label, or "90 mm"
    [masses.End]                # a point mass carried by the body at C: at = "C", mass = ...
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
    [springs.K]
    stiffness = "100 N/m"       # between = ["S", "H"] + free_length, or at + direction + extension
    [dynamics]
    mode = "kinetostatic"       # | "torque-driven" | "release"  (see polygons.forces.release)
    # pin friction torques, torsional springs, efforts: docs/scene-reference.md

:func:`parse` reads them from ``Scene.extra`` (where :mod:`polygons.scene` keeps them raw) into
frozen records; every problem is a :class:`~polygons.errors.SceneError` naming the key.  The
bodies (links, slotted levers, slider blocks) and the joints between them come from the
scene's topology.  ``TABLES`` declares every key this module accepts (:mod:`polygons.schema`;
stated in :mod:`polygons.loadtables`), and :mod:`polygons.loadrun` reads how the analysis runs
and what it is checked against ([dynamics], [flywheel], [efficiency], [[force_answers]]);
this module reads the loads themselves.
This module imports nothing above the scene layer (and not :mod:`polygons.scene` itself: the
scene calls it), so the analysis in :mod:`polygons.forces` reads a finished model.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Callable, Mapping

from .errors import SceneError, UnitError, UnknownLabelError, show, suggest
from .loadbodies import guides, joints_of, without_tables
from .loadeffort import parse_effort
from .loadmodel import (EQUIVALENT_LINK, AppliedForce, AppliedTorque, Friction, Joint, Loads,
                        MassItem, Spring, bodies_of, slot_contacts)
# the tables' format and the analysis' settings, split out (re-exported: TABLES for the
# reference, the defaults for the readers)
from .loadrun import AnswerFields, answers as _answers, dynamics as _dynamics
from .loadrun import efficiency as _efficiency, flywheel as _flywheel, is_crank as _is_crank
from .loadtables import (DEFAULT_MODE, DEFAULT_STEPS, FORCE_TABLES, LOAD_TABLES,  # noqa: F401
                         MAX_AFTER, MAX_RELEASE_STEPS, MODES, NO_GRAVITY, READS, TABLES)
from .loadtables import keys_of as _keys
from .model import BUILT, unhandled
from .units import cos_sin
from .reader import Reader, record

Vec = tuple[float, float]

# ---------------------------------------------------------------- reading values
_Values = Reader        # the scene tables' one reader (polygons.reader)


def has_loads(extra: Mapping[str, Any]) -> bool:
    """True when the raw tables include masses, forces, torques or springs."""
    return any(k in extra for k in LOAD_TABLES)


#: the kinds of body and pair the force analysis handles (polygons.model): not a collar
#: driven along a link, whose prescribed slide has no force model yet, nor a pin in two
#: moving slots (two slot normals at one massless pin: not modelled yet)
HANDLES = BUILT - {"collar", "cross-block"}


_guides = guides


def parse(scene, answer_fields: AnswerFields, *, shortcut: bool = True) -> Loads:
    """Read and check the force tables of ``scene`` (every problem is a :class:`SceneError`).

    ``answer_fields(spec, where, extra_keys=..., extra_units=...)`` reads the fields shared with
    ``[[answers]]`` (bound by the scene to its reader and the case's drawing tolerance).
    A scene with none of :data:`READS` has nothing to read or refuse: its bodies and joints
    are found and every table takes its empty default, as reading the absent tables gives
    (``shortcut=False`` reads them all the same; the tests compare the two)."""
    file = scene.file
    ex = scene.extra
    if shortcut and not any(k in ex for k in READS):
        return without_tables(scene)
    bodies = bodies_of(scene.model)
    members, joints = joints_of(scene, bodies)
    drv = scene.driver
    driver_body = drv.link if _is_crank(drv) else drv.point
    r = _Values(file)
    active = has_loads(ex)
    # an unhandled kind is refused by the command asking for forces (forces.analysis)
    handled = unhandled(HANDLES, scene.model) is None
    reversed_names = {b.b + b.a: n for n, b in bodies.items() if b.kind == "link"}

    slots = slot_contacts(scene.model, members, file) if active and handled else []

    equivalent = {q.link: q for q in getattr(scene, "equivalents", ()) if q.link}

    def body_name(name, where) -> str:
        if not isinstance(name, str):
            raise SceneError(f"expected a link name or a slider point, got {name!r}", file=file,
                             where=where)
        name = reversed_names.get(name, name) if name not in bodies else name
        if name in equivalent:
            raise SceneError(EQUIVALENT_LINK.format(name, equivalent[name]), file=file,
                             where=where)
        if name in bodies:
            return name
        raise UnknownLabelError(f"unknown link or slider {name!r}: {suggest(name, bodies)}",
                                file=file, where=where)

    def point_body(label, on, where, allow_ground=False) -> str | None:
        if not isinstance(label, str):
            raise SceneError(f"expected a point label, got {label!r}", file=file, where=where)
        if label not in members:
            raise UnknownLabelError(f"unknown point {label!r}: {suggest(label, members)}",
                                    file=file, where=where)
        carriers = [c for c in members[label] if c not in equivalent]
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

    ctx = _Context(scene, r, bodies, members, body_name, point_body)
    masses = _masses(ctx, ex.get("masses", {}))
    gravity = _gravity(r, ex.get("gravity", None))
    forces = _forces(ctx, ex.get("forces", {}))
    torques, frictions = _torques(ctx, ex.get("torques", {}))
    springs = _springs(ctx, ex.get("springs", {}))
    mode, after, steps = _dynamics(r, scene, ex.get("dynamics", {}), active)
    flywheel = _flywheel(r, scene, ex.get("flywheel"), mode)
    efficiency = _efficiency(r, scene, ex.get("efficiency"))
    effort = parse_effort(ctx, ex.get("dynamics", {}).get("effort"), mode, flywheel, efficiency)
    answers = _answers(r, ex.get("force_answers", []), answer_fields)
    return Loads(file, MappingProxyType(bodies),
                 MappingProxyType({k: tuple(v) for k, v in members.items()}), tuple(joints),
                 tuple(slots), _guides(scene.model), tuple(masses), tuple(forces),
                 tuple(torques), tuple(frictions), tuple(springs), gravity, mode, after, steps,
                 answers, driver_body, active, flywheel, efficiency, effort)


@dataclass(frozen=True)
class _Context:
    scene: Any
    r: _Values
    bodies: dict
    members: dict
    body_name: Callable
    point_body: Callable


# ---------------------------------------------------------------- tables
def _masses(ctx: _Context, raw) -> list[MassItem]:
    r, file, bodies = ctx.r, ctx.r.file, ctx.bodies
    masses = []
    r.named(raw, "masses")
    for name, spec in raw.items():
        where = f"masses.{name}"
        r.table(spec, where, _keys("masses"), required=("mass",))
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
            body = ctx.point_body(at, spec.get("on"), where + ".at")
            inertia, how = _inertia(r, spec, mass, None, where, default="point")
            kind = "block" if bodies[body].kind == "block" else "point"
            masses.append(MassItem(name, body, kind, mass, inertia, how, at=at, free=free,
                                   spin=spin))
            continue
        if "on" in spec:
            raise SceneError("'on' goes with 'at' (a point mass); a link's own mass is written "
                             "[masses.LINK]", file=file, where=where + ".on")
        body = ctx.body_name(name, where)
        b = bodies[body]
        wheel = next((q for q in ctx.scene.equivalents if q.kind == "rolling" and q.at == body),
                      None) if b.kind == "block" else None     # a rolling wheel turns
        if b.kind == "block":
            for bad in ("centre", "centre_left", "free", "spin") + (
                    () if wheel else ("inertia", "radius", "radius_of_gyration")):
                if bad in spec:
                    raise SceneError(f"{body} is a slider block (it does not turn): {bad!r} "
                                     f"does not apply", file=file, where=f"{where}.{bad}")
            i, how = _inertia(r, spec if "inertia" in spec or "radius_of_gyration" in spec else
                              {"inertia": "disc", "radius": f"{wheel.radius!r} m"}, mass, None,
                              where, "disc") if wheel else (0.0, "translating block")
            masses.append(MassItem(name, body, "block", mass, i, how, at=body))
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
    return masses


def _gravity(r: _Values, graw) -> Vec:
    if graw is None:
        return NO_GRAVITY
    r.table(graw, "gravity", _keys("gravity"))
    enabled = graw.get("enabled", True)
    if not isinstance(enabled, bool):
        raise SceneError("enabled must be true or false", file=r.file, where="gravity.enabled")
    g = r.quantity(graw.get("g", "9.81 m/s^2"), "acceleration", "gravity.g")
    d = r.quantity(graw.get("direction", "-90 deg"), "angle", "gravity.direction")
    if not enabled:
        return (0.0, 0.0)
    c, s = cos_sin(d)                       # exact at -90° (not 6e-16 m/s² sideways)
    return (g * c, g * s)


def _forces(ctx: _Context, raw) -> list[AppliedForce]:
    r, file = ctx.r, ctx.r.file
    forces = []
    r.named(raw, "forces")
    for name, spec in raw.items():
        where = f"forces.{name}"
        r.table(spec, where, _keys("forces"), required=("at",))
        body = ctx.point_body(spec["at"], spec.get("on"), where + ".at")
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
                mag, how = _pressure_force(r, spec, where)
                how += f" at {math.degrees(d):.6g}°"
            f = (mag * math.cos(d), mag * math.sin(d))
        resisting = spec.get("resisting", False)
        if not isinstance(resisting, bool):
            raise SceneError("resisting must be true or false", file=file, where=where)
        forces.append(AppliedForce(name, body, spec["at"], f, how, resisting))
    return forces


def _pressure_force(r: _Values, spec, where) -> tuple[float, str]:
    """F = p π D²/4 on a piston of diameter D (the bore); double-acting, F = p A − p_b A_b
    with the annulus A = π(D² − d²)/4 on the side of the piston rod (diameter d)."""
    p = r.quantity(spec["pressure"], "pressure", where + ".pressure")
    key = "bore" if "bore" in spec else "diameter"
    if key not in spec:
        raise SceneError("a pressure needs the bore (piston diameter): bore = \"80 mm\"",
                         file=r.file, where=where)
    dia = r.quantity(spec[key], "length", f"{where}.{key}")
    if dia <= 0:
        raise SceneError(f"{key} must be positive", file=r.file, where=f"{where}.{key}")
    area = math.pi * dia * dia / 4.0
    if not any(k in spec for k in ("back_pressure", "rod", "rod_side")):
        mag = p * area
        return mag, f"p × π d²/4 = {p:.6g} Pa × π × {dia:.6g}²/4 = {mag:.6g} N"
    pb = r.quantity(spec.get("back_pressure", "0 Pa"), "pressure", where + ".back_pressure")
    rod = r.quantity(spec.get("rod", "0 m"), "length", where + ".rod")
    side = spec.get("rod_side", "back")
    if side not in ("back", "front"):
        raise SceneError(f"rod_side must be 'back' or 'front', got {side!r}", file=r.file,
                         where=where + ".rod_side")
    if not 0 <= rod < dia:
        raise SceneError(f"the piston rod ({rod:.6g} m) must be thinner than the bore",
                         file=r.file, where=where + ".rod")
    annulus = math.pi * (dia * dia - rod * rod) / 4.0
    front, back = (area, annulus) if side == "back" else (annulus, area)
    mag = p * front - pb * back
    return mag, (f"p A − p_b A_b = {p:.6g} Pa × {front:.6g} m² − {pb:.6g} Pa × {back:.6g} m² "
                 f"(rod {rod:.6g} m on the {side} side: π(D² − d²)/4) = {mag:.6g} N")


def _torques(ctx: _Context, raw) -> tuple[list[AppliedTorque], list[Friction]]:
    r, file, members = ctx.r, ctx.r.file, ctx.members
    torques, frictions = [], []
    r.named(raw, "torques")
    for name, spec in raw.items():
        where = f"torques.{name}"
        r.table(spec, where, _keys("torques"))
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
            body = ctx.body_name(spec["on"], where + ".on")
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
            first, second = _pin_pair(ctx, spec, where)
            frictions.append(Friction(name, spec["at"], first, second, t))
    return torques, frictions


def _springs(ctx: _Context, raw) -> list[Spring]:
    r, file = ctx.r, ctx.r.file
    springs = []
    r.named(raw, "springs")
    for name, spec in raw.items():
        where = f"springs.{name}"
        r.table(spec, where, _keys("springs"), required=("stiffness",))
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
            first, second = _pin_pair(ctx, spec, where)
            twist = r.quantity(spec.get("twist", "0 deg"), "angle", where + ".twist")
            springs.append(Spring(name, "torsional", k, at=spec["at"], first=first,
                                  second=second, twist=twist))
            continue
        if "between" in spec:
            ends = spec["between"]
            if not isinstance(ends, list) or len(ends) != 2:
                raise SceneError("between = [\"S\", \"H\"]: the two points the spring joins",
                                 file=file, where=where + ".between")
            if ends[0] == ends[1]:
                raise SceneError(f"the spring joins {show(ends[0])} to itself: a linear spring "
                                 f"joins two different points", file=file,
                                 where=where + ".between")
            if ("free_length" in spec) == ("extension" in spec):
                raise SceneError("give exactly one of free_length or extension (at this "
                                 "instant; negative when compressed)", file=file, where=where)
            on = spec.get("on", ["", ""])
            if not isinstance(on, list) or len(on) != 2:
                raise SceneError("on = [\"BC\", \"\"]: the body carrying each end ('' when "
                                 "there is only one)", file=file, where=where + ".on")
            e = tuple((lab, ctx.point_body(lab, o or None, f"{where}.between",
                                           allow_ground=True))
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
            body = ctx.point_body(spec["at"], spec.get("on"), where + ".at")
            d = r.quantity(spec["direction"], "angle", where + ".direction")
            ext = r.quantity(spec["extension"], "length", where + ".extension")
            springs.append(Spring(name, "directional", k, at=spec["at"], body=body,
                                  direction=(math.cos(d), math.sin(d)), extension=ext))
    return springs


def _pin_pair(ctx: _Context, spec, where) -> tuple[str, str | None]:
    """The two bodies a pin element (friction, torsional spring) acts between."""
    scene, members, file = ctx.scene, ctx.members, ctx.r.file
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
        names = [ctx.body_name(x, where + ".between") for x in b]
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


def _inertia(r: _Values, spec, mass, length, where, default) -> tuple[float, str]:
    if "radius_of_gyration" in spec:
        if "inertia" in spec:
            raise SceneError("give inertia or radius_of_gyration, not both", file=r.file,
                             where=where)
        k = r.quantity(spec["radius_of_gyration"], "length", where + ".radius_of_gyration")
        return mass * k * k, f"m k² = {mass:.6g} × {k:.6g}²"
    how = spec.get("inertia", default)
    if how != "disc" and "radius" in spec:
        raise SceneError("radius goes with inertia = \"disc\"", file=r.file, where=where + ".radius")
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
        return 0.0, "point mass"
    if isinstance(how, str) and how and (how[0].isdigit() or how[0] in "+-."):
        i = r.quantity(how, "inertia", where + ".inertia")
        if i < 0:
            raise SceneError("a moment of inertia must not be negative", file=r.file,
                             where=where + ".inertia")
        return i, "given"
    raise SceneError(f"inertia must be 'rod', 'disc', 'point' or a value such as "
                     f"'0.002 kg m^2'; got {how!r}", file=r.file, where=where + ".inertia")
