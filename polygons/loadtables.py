"""The force tables' format, as data: every key of [masses], [gravity], [forces],
[torques], [springs], [dynamics], [flywheel], [efficiency] and [[force_answers]] with its
kind, unit and words (:data:`TABLES`: docs/scene-reference.md and the JSON schema are
generated from it, :mod:`polygons.reference`), and the defaults and bounds the readers apply.

Split from :mod:`polygons.loads` (which reads the tables and re-exports these names): what a
scene may say, apart from how it is read.
"""
from __future__ import annotations

from .schema import Key, Table

#: the [dynamics] key (polygons.loadeffort reads it)
EFFORT_KEY = Key("effort", "string", "kinetostatic: where the balancing effort is found, the "
                 "driver staying the kinematic input: 'torque on LINK' (a couple, CCW "
                 "positive), 'force at C' (on slider C along its guide) or 'force along E F' (a "
                 "massless actuator between the points E and F, positive pushing them apart)",
                 "force at C", default="torque on the driver (a force for a slider driver)")

#: the scene tables polygons.loads reads
FORCE_TABLES = ("masses", "forces", "torques", "springs", "gravity", "dynamics")
#: a scene has a force analysis when it has one of these
LOAD_TABLES = ("masses", "forces", "torques", "springs")
MODES = ("kinetostatic", "torque-driven", "release")
#: every table polygons.loads reads from ``Scene.extra``
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


def keys_of(name: str) -> tuple[str, ...]:
    """The keys the table ``name`` declares."""
    return next(tuple(k.name for k in t.keys) for t in TABLES if t.name == name)


__all__ = ["FORCE_TABLES", "LOAD_TABLES", "MODES", "READS", "NO_GRAVITY", "DEFAULT_MODE",
           "DEFAULT_STEPS", "MAX_RELEASE_STEPS", "MAX_AFTER", "TABLES", "keys_of"]
