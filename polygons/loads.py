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
scene's topology.  ``TABLES`` declares every key this module accepts (:mod:`polygons.schema`).
This module imports nothing above the scene layer (and not :mod:`polygons.scene` itself: the
scene calls it), so the analysis in :mod:`polygons.forces` reads a finished model.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Callable, Mapping

from .errors import SceneError, UnitError, UnknownLabelError, UnsupportedError, show, suggest
from .loadmodel import (EQUIVALENT_LINK, AppliedForce, AppliedTorque, Efficiency, Flywheel,
                        ForceAnswer, Friction, Joint, Loads, MassItem, Spring, bodies_of,
                        slot_contacts)
from .loadeffort import EFFORT_KEY, parse_effort
from .model import BUILT, unhandled
from .reader import Reader, record
from .schema import Key, Table

Vec = tuple[float, float]

#: the scene tables this module reads
FORCE_TABLES = ("masses", "forces", "torques", "springs", "gravity", "dynamics")
#: a scene has a force analysis when it has one of these
LOAD_TABLES = ("masses", "forces", "torques", "springs")
MODES = ("kinetostatic", "torque-driven", "release")
#: every table this module reads from ``Scene.extra``
READS = FORCE_TABLES + ("flywheel", "efficiency", "force_answers")
#: what an absent [gravity] and [dynamics] give
NO_GRAVITY = (0.0, 0.0)
DEFAULT_MODE = MODES[0]
DEFAULT_STEPS = 200
#: bounds of [dynamics]: RK4 steps per interval (each a solve, ~4 ms) and rotations reported
MAX_RELEASE_STEPS, MAX_AFTER = 10_000, 20

_Q = "quantity"
TABLES: tuple[Table, ...] = (
    Table("masses", "A mass: a link's own ([masses.BC]), a slider block's ([masses.P]) or a point "
          "mass carried at a label (at = \"C\").", (
              Key("mass", _Q, "the mass", "0.8 kg", "mass", required=True),
              Key("at", "label", "a point mass at this label", "C"),
              Key("on", "link", "the body carrying 'at' when the label joins two", "BC"),
              Key("inertia", "string", "'rod' (m l²/12), 'disc' (+ radius), 'point' or a value "
                  "about the centre of mass", "rod", default="rod"),
              Key("radius", _Q, "radius of a disc (inertia = \"disc\")", "100 mm", "length"),
              Key("radius_of_gyration", _Q, "I_G = m k²", "45 mm", "length"),
              Key("centre", "string", "centre of mass: fraction of the link from its first "
                  "label, or a distance", "0.5", default="0.5"),
              Key("centre_left", _Q, "offset of the centre to the left of the link", "5 mm",
                  "length", default="0 m"),
              Key("free", "bool", "a disc turning freely on a frictionless pin", "true",
                  default=False),
              Key("spin", _Q, "the constant spin of a free disc", "40 rad/s",
                  "angular_velocity", sign="CCW positive"),
          ), many=True),
    Table("gravity", "Gravity (absent: ignored, as most tutorials do).", (
        Key("g", _Q, "gravitational acceleration", "9.81 m/s^2", "acceleration",
            default="9.81 m/s^2"),
        Key("direction", _Q, "direction of g", "-90 deg", "angle", default="-90 deg",
            sign="CCW from +x"),
        Key("enabled", "bool", "false switches gravity off", "true", default=True),
    )),
    Table("forces", "An applied force at a labelled point (keeps its direction).", (
        Key("at", "label", "point of application", "P", required=True),
        Key("on", "link", "the body carrying 'at' when the label joins two", "BC"),
        Key("force", "array", "[Fx, Fy]", "[\"0 N\", \"20 N\"]", "force"),
        Key("magnitude", _Q, "magnitude (with direction)", "20 N", "force"),
        Key("direction", _Q, "direction of the force", "0 deg", "angle", sign="CCW from +x"),
        Key("pressure", _Q, "pressure on a piston (× π bore²/4)", "1.2 MPa", "pressure"),
        Key("bore", _Q, "piston diameter (with pressure)", "80 mm", "length"),
        Key("diameter", _Q, "same as bore", "80 mm", "length"),
        Key("back_pressure", _Q, "double-acting cylinder: the pressure on the other side of "
            "the piston (it pushes back)", "70 kPa", "pressure"),
        Key("rod", _Q, "diameter of the piston rod, on the back-pressure side unless "
            "rod_side = 'front' (that side's area is the annulus π(D² − d²)/4)", "50 mm",
            "length"),
        Key("rod_side", "string", "'back' (default) or 'front': the side the piston rod is on",
            "back", default="back"),
        Key("resisting", "bool", "true: the force acts only while it opposes its point's motion "
            "(a cutting force on the working stroke, none on the return)", "true",
            default=False),
    ), many=True),
    Table("torques", "An applied couple on a link, or a constant friction torque at a pin.", (
        Key("on", "link", "the link the couple acts on", "DB"),
        Key("at", "label", "where the couple acts (a friction's pin)", "O"),
        Key("torque", _Q, "applied couple (with sense)", "6 N m", "torque"),
        Key("sense", "string", "'CW' or 'CCW'", "CW"),
        Key("friction", _Q, "friction torque (a magnitude; opposes the relative rotation)",
            "0.1 N m", "torque"),
        Key("between", "array", "the links a friction acts between", "[\"AB\", \"BC\"]"),
    ), many=True),
    Table("springs", "A linear spring (between two points, or at a point along a direction) or a "
          "torsional spring at a pin (the unit of stiffness says which).", (
              Key("stiffness", _Q, "N/m (linear) or N m/rad (torsional)", "100 N/m",
                  required=True),
              Key("between", "array", "the two points a linear spring joins (or, torsional, "
                  "the links)", "[\"S\", \"H\"]"),
              Key("free_length", _Q, "free length of a spring between two points", "0.2 m",
                  "length"),
              Key("extension", _Q, "extension at this instant (negative: compressed)",
                  "-40 mm", "length"),
              Key("at", "label", "a spring at a point (or a torsional spring's pin)", "S"),
              Key("on", "array", "the body carrying each end", "[\"BC\", \"\"]"),
              Key("direction", _Q, "towards the far end, which keeps it parallel", "90 deg",
                  "angle", sign="CCW from +x"),
              Key("twist", _Q, "torsional: twist at this instant", "10 deg", "angle",
                  default="0 deg", sign="CCW of the first link against the second"),
          ), many=True),
    Table("dynamics", "Which problem the force analysis solves.", (
        Key("mode", "string", "'kinetostatic' (find the input torque), 'torque-driven' (find "
            "the input's α) or 'release' (no motor)", "release", default="kinetostatic"),
        Key("after", "array", f"release: rotations of the driver at which to report (at most "
                              f"{MAX_AFTER})",
            "[\"30 deg\"]", "angle"),
        Key("steps", "integer", f"release: RK4 steps per interval, 4 .. {MAX_RELEASE_STEPS:,}",
            "200", default=200),
        EFFORT_KEY,
    )),
    Table("flywheel", "A flywheel on the crank shaft: its angular acceleration from the torque "
          "surplus, α = (T − T_R)/I (kinetostatic: the crank's ω as given).", (
              Key("mass", _Q, "mass of the flywheel (with radius_of_gyration)", "60 kg", "mass"),
              Key("radius_of_gyration", _Q, "I = m k²", "600 mm", "length"),
              Key("inertia", _Q, "or the moment of inertia itself", "21.6 kg m^2", "inertia"),
              Key("power", _Q, "power taken off at the mean speed: T_R = P/ω", "20 kW",
                  "power"),
              Key("resisting_torque", _Q, "or the resisting torque T_R itself", "1590 N m",
                  "torque"),
          )),
    Table("efficiency", "The mechanism's efficiency η: input torque T_in/η when the input "
          "drives; output effort η × ideal; mechanical advantage η ω_in/ω_out.", (
              Key("eta", _Q, "efficiency (a fraction or a percentage)", "80 %", "fraction",
                  required=True),
              Key("input_torque", _Q, "the torque applied to the crank driver (or "
                  "input_force for a slider driver), for Tout_eta / Fout_eta", "20 N m",
                  "torque"),
              Key("input_force", _Q, "the force applied to a slider driver", "200 N", "force"),
          )),
    Table("force_answers", "Printed and exact answers of the force analysis (as [[answers]], "
          "plus state and positive).", (
              Key("quantity", "string", "e.g. 'Tin', 'Rx(O,OA)', 'Rx(B,AB) + Rx(A,OA)'", "Tin",
                  required=True),
              Key("unit", "string", "unit of the printed value", "N m", required=True),
              Key("tutorial", "number", "the printed value", "6.03"),
              Key("exact", "number", "the exact value", "6.029423"),
              Key("mode", "string", "'abs' or 'signed'", "abs", default="abs"),
              Key("sense", "string", "the printed sense word", "CW"),
              Key("tolerance", _Q, "drawing tolerance", "3 %", "fraction"),
              Key("slip", "bool", "the printed value is a known slip", "false", default=False),
              Key("ref", "string", "key in the reference record", "T_in"),
              Key("desc", "string", "what the answer is, in words", "input torque"),
              Key("note", "string", "remark", ""),
              Key("positive", "string", "'CCW' (default) or 'CW': the sense counted positive",
                  "CW", default="CCW"),
              Key("state", "string", "'release' or a rotation such as '30 deg'", "30 deg"),
          ), array=True),
)


# ---------------------------------------------------------------- reading values
_Values = Reader        # the scene tables' one reader (polygons.reader)


def _keys(name: str) -> tuple[str, ...]:
    return next(tuple(k.name for k in t.keys) for t in TABLES if t.name == name)


def _is_crank(driver) -> bool:
    return hasattr(driver, "pivot")


def has_loads(extra: Mapping[str, Any]) -> bool:
    """True when the raw tables include masses, forces, torques or springs."""
    return any(k in extra for k in LOAD_TABLES)


#: reads the fields every answer table shares (``scene.answer_fields`` bound to its reader)
AnswerFields = Callable[..., dict]


#: the kinds of body and pair the force analysis handles (polygons.model): not a collar
#: driven along a link, whose prescribed slide has no force model yet, nor a pin in two
#: moving slots (two slot normals at one massless pin: not modelled yet)
HANDLES = BUILT - {"collar", "cross-block"}


def _guides(model) -> tuple[str, ...]:
    """The blocks on fixed guides (sliders and yokes), by their labels."""
    return tuple(s.at for s in model.sliding if s.carrier == "frame")


def parse(scene, answer_fields: AnswerFields, *, shortcut: bool = True) -> Loads:
    """Read and check the force tables of ``scene`` (every problem is a :class:`SceneError`).

    ``answer_fields(spec, where, extra_keys=..., extra_units=...)`` reads the fields shared with
    ``[[answers]]`` (bound by the scene to its reader and the case's drawing tolerance).
    A scene with none of :data:`READS` has nothing to read or refuse: its bodies and joints
    are found and every table takes its empty default, as reading the absent tables gives
    (``shortcut=False`` reads them all the same; the tests compare the two)."""
    file = scene.file
    ex = scene.extra
    bodies = bodies_of(scene.model)
    labels = scene.labels
    members: dict[str, list[str]] = {lab: [] for lab in labels}
    for b in bodies.values():
        for lab in b.labels:
            members.setdefault(lab, []).append(b.name)
    ground = scene.ground
    joints = []
    for lab in labels:
        mem = tuple(members.get(lab, ()))
        if lab in ground and mem:
            joints.append(record(Joint, label=lab, members=mem, ground=True))
        elif len(mem) >= 2:
            joints.append(record(Joint, label=lab, members=mem, ground=False))
    drv = scene.driver
    driver_body = drv.link if _is_crank(drv) else drv.point
    if shortcut and not any(k in ex for k in READS):
        return record(Loads, file=file, bodies=MappingProxyType(bodies),
                      members=MappingProxyType({k: tuple(v) for k, v in members.items()}),
                      joints=tuple(joints), slots=(), guides=_guides(scene.model), masses=(),
                      forces=(), torques=(), frictions=(), springs=(), gravity=NO_GRAVITY,
                      mode=DEFAULT_MODE, after=(), steps=DEFAULT_STEPS, answers=(),
                      driver_body=driver_body, active=False, flywheel=None, efficiency=None,
                      effort=None)
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
    r.table(raw, "masses", tuple(raw))
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
    return (g * math.cos(d), g * math.sin(d))


def _forces(ctx: _Context, raw) -> list[AppliedForce]:
    r, file = ctx.r, ctx.r.file
    forces = []
    r.table(raw, "forces", tuple(raw))
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
    r.table(raw, "torques", tuple(raw))
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
    r.table(raw, "springs", tuple(raw))
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


def _dynamics(r: _Values, scene, draw, active: bool) -> tuple[str, tuple[float, ...], int]:
    file = r.file
    r.table(draw, "dynamics", _keys("dynamics"))
    mode = draw.get("mode", DEFAULT_MODE)
    if mode not in MODES:
        raise SceneError(f"mode must be one of {', '.join(MODES)}; got {mode!r}", file=file,
                         where="dynamics.mode")
    after_raw = draw.get("after", [])
    if isinstance(after_raw, str):
        after_raw = [after_raw]
    if not isinstance(after_raw, list):
        raise SceneError("after = [\"30 deg\"]: the rotations of the driver at which to report",
                         file=file, where="dynamics.after")
    if len(after_raw) > MAX_AFTER:
        raise SceneError(f"{len(after_raw):,} rotations: at most {MAX_AFTER} are reported",
                         file=file, where="dynamics.after")
    after = tuple(abs(r.quantity(a, "angle", f"dynamics.after[{i}]"))
                  for i, a in enumerate(after_raw))
    if after and mode != "release":
        raise SceneError("'after' is for mode = \"release\"", file=file, where="dynamics.after")
    steps = draw.get("steps", DEFAULT_STEPS)
    if (isinstance(steps, bool) or not isinstance(steps, int)
            or not 4 <= steps <= MAX_RELEASE_STEPS):
        raise SceneError(f"steps must be a whole number from 4 to {MAX_RELEASE_STEPS:,}, got "
                         f"{show(steps)}", file=file, where="dynamics.steps")
    if not active:
        return mode, after, steps
    drv = scene.driver
    if mode in ("torque-driven", "release"):
        if _is_crank(drv) and drv.alpha != 0.0:
            raise SceneError(f"mode = {mode!r} finds the driver's angular acceleration from the "
                             f"torques: remove driver.alpha", file=file, where="driver.alpha")
        if not _is_crank(drv) and drv.acceleration != 0.0:
            raise SceneError(f"mode = {mode!r} finds the driver's acceleration from the forces: "
                             f"remove driver.acceleration", file=file,
                             where="driver.acceleration")
    if mode == "release" and not _is_crank(drv):
        raise UnsupportedError("mode = \"release\" needs a crank as the driver (its angle is the "
                               "coordinate)", file=file, where="dynamics.mode")
    if "acceleration" not in scene.solve:
        raise SceneError("forces need the acceleration polygon: remove 'solve' or write "
                         "solve = [\"velocity\", \"acceleration\"]", file=file, where="solve")
    return mode, after, steps


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


def _flywheel(r: _Values, scene, raw, mode: str) -> Flywheel | None:
    """I = m k² (or inertia); T_R = P/ω (or resisting_torque)."""
    if raw is None:
        return None
    r.table(raw, "flywheel", _keys("flywheel"))
    if not _is_crank(scene.driver):
        raise SceneError("a flywheel turns with a crank driver", file=r.file, where="flywheel")
    if mode != "kinetostatic":
        raise SceneError("the flywheel's α = (T − T_R)/I is for mode = \"kinetostatic\" (the "
                         "crank's ω as given)", file=r.file, where="flywheel")
    if ("inertia" in raw) == ("mass" in raw or "radius_of_gyration" in raw):
        raise SceneError("give mass + radius_of_gyration (I = m k²) or inertia", file=r.file,
                         where="flywheel")
    if "inertia" in raw:
        inertia = r.quantity(raw["inertia"], "inertia", "flywheel.inertia")
        how = "given"
    else:
        if "mass" not in raw or "radius_of_gyration" not in raw:
            raise SceneError("I = m k² needs both mass and radius_of_gyration", file=r.file,
                             where="flywheel")
        m = r.quantity(raw["mass"], "mass", "flywheel.mass")
        k = r.quantity(raw["radius_of_gyration"], "length", "flywheel.radius_of_gyration")
        inertia, how = m * k * k, f"m k² = {m:.6g} × {k:.6g}²"
    if inertia <= 0:
        raise SceneError("the flywheel's moment of inertia must be positive", file=r.file,
                         where="flywheel")
    if ("power" in raw) == ("resisting_torque" in raw):
        raise SceneError("give the power taken off (T_R = P/ω) or the resisting_torque",
                         file=r.file, where="flywheel")
    power = r.quantity(raw["power"], "power", "flywheel.power") if "power" in raw else None
    tr = (r.quantity(raw["resisting_torque"], "torque", "flywheel.resisting_torque")
          if "resisting_torque" in raw else None)
    if power is not None and scene.driver.omega == 0.0:
        raise SceneError("T_R = P/ω needs the crank turning (omega is 0)", file=r.file,
                         where="flywheel.power")
    return Flywheel(inertia, how, tr, power)


def _efficiency(r: _Values, scene, raw) -> Efficiency | None:
    if raw is None:
        return None
    r.table(raw, "efficiency", _keys("efficiency"), required=("eta",))
    eta = r.quantity(raw["eta"], "fraction", "efficiency.eta")
    if not 1e-6 <= eta <= 1.0:      # (an η of 1e-320 would make T_in/η infinite)
        raise SceneError(f"an efficiency is a fraction from 1e-6 (0.0001 %) to 1 (100 %), got "
                         f"{raw['eta']!r}", file=r.file, where="efficiency.eta")
    crank = _is_crank(scene.driver)
    key, dim = ("input_torque", "torque") if crank else ("input_force", "force")
    wrong = "input_force" if crank else "input_torque"
    if wrong in raw:
        raise SceneError(f"the driver is a {'crank' if crank else 'slider'}: give {key}",
                         file=r.file, where=f"efficiency.{wrong}")
    effort = abs(r.quantity(raw[key], dim, f"efficiency.{key}")) if key in raw else None
    return Efficiency(eta, effort)


#: units a force answer may be stated in beyond polygons.units (answer_fields checks the rest)
ANSWER_UNITS = ("-", "1")


def _answers(r: _Values, raw, answer_fields: AnswerFields) -> tuple[ForceAnswer, ...]:
    if not isinstance(raw, list):
        raise SceneError("write force answers as [[force_answers]] tables", file=r.file,
                         where="force_answers")
    out = []
    for i, spec in enumerate(raw):
        where = f"force_answers[{i}]"
        fields = answer_fields(spec, where, extra_keys=("positive", "state"),
                               extra_units=ANSWER_UNITS)
        positive = r.sense(spec.get("positive", "CCW"), where + ".positive")
        state = spec.get("state")
        if state is not None and not isinstance(state, str):
            raise SceneError("state must be text ('release' or a rotation such as '30 deg')",
                             file=r.file, where=where + ".state")
        out.append(ForceAnswer(positive=positive, state=state, **fields))
    return tuple(out)
