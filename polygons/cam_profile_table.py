"""The [cam_profiles] table: a cam stated by its profile, as data (its keys, checked at load
by :mod:`polygons.cam_profiles`; the scene reference and schema generated from it)."""
from __future__ import annotations

from .schema import Key, Table

TABLE = "cam_profiles"
FOLLOWERS = ("knife", "roller", "flat")
KINDS = ("circular arc", "tangent")
SIDES = ("left", "right")
#: the stated cam angle kept in the table carried to Scene.extra (for the drawing)
AXIS_KEY = "_axis"

TABLES: tuple[Table, ...] = (
    Table(TABLE, "[cam_profiles.R]: a cam stated by its profile (base circle, nose, flanks: "
                 "circular-arc or tangent) with a knife-edge, roller or flat-faced follower, "
                 "translating (its line of stroke through the cam's centre or offset) or "
                 "oscillating (an arm pivoted in [ground]); R: the follower's point.  The "
                 "part in contact at the driver's angle (the nose's axis) is found and the "
                 "equivalent linkage built: the driver's crank O → K (K: the part's centre of "
                 "curvature, rigid with the cam) and a [cams.R] entry, or a slot of the cam "
                 "for a straight flank (a translating knife or roller: the tangent "
                 "mechanism, a pin in the slot on the fixed line of stroke).  The follower "
                 "dwelling on the base circle is refused in words at an instant (`polygons "
                 "sweep` gives the displacement diagram over a turn).", (
        Key("base_radius", "quantity", "the base circle's radius r₁", example='"25 mm"',
            dimension="length", required=True),
        Key("nose_radius", "quantity", "the nose's radius r₂", example='"8 mm"',
            dimension="length", required=True),
        Key("lift", "quantity", "the cam's lift L (nose centre at r₁ + L − r₂ from O); a "
                                "tangent cam may give faces_angle instead",
            example='"20 mm"', dimension="length"),
        Key("kind", "string", "'circular arc' (with flank_radius) or 'tangent'",
            example='"circular arc"', default="circular arc"),
        Key("flank_radius", "quantity", "a circular-arc cam's flank radius R",
            example='"60 mm"', dimension="length"),
        Key("faces_angle", "quantity", "a tangent cam's angle between its tangential faces "
                                       "(π − 2β): the lift found from it",
            example='"90 deg"', dimension="angle"),
        Key("angle_of_action", "quantity", "the cam's turn while the follower moves (rise "
                                           "and return, 2 φ_b): with a circular-arc cam and "
                                           "no flank_radius, the flank radius is found from "
                                           "it; otherwise checked against the profile (to "
                                           "0.05°)", example='"150 deg"', dimension="angle"),
        Key("follower", "string", "'knife', 'roller' or 'flat'",
            example='"roller"', default="roller"),
        Key("roller", "quantity", "the roller's radius", example='"10 mm"',
            dimension="length"),
        Key("stroke", "quantity", "a translating follower: the line of stroke's direction "
                                  "from the cam's centre towards the follower, CCW from +x",
            example='"90 deg"', dimension="angle"),
        Key("offset", "quantity", "a translating follower: the line of stroke's distance "
                                  "from the cam's centre", example='"10 mm"',
            dimension="length", default="0 mm", sign="positive to the left of the stroke"),
        Key("pivot", "label", "an oscillating follower: its arm's fixed pivot (a [ground] "
                              "point); the arm is the link pivot + R", example='"Q"'),
        Key("arm", "quantity", "an oscillating follower: the arm's length from the pivot to "
                               "the roller's centre or the knife's edge (a flat face: the "
                               "face along the arm from the pivot, the contact on it)",
            example='"80 mm"', dimension="length"),
        Key("side", "string", "an oscillating follower: 'left' or 'right' — a knife or "
                              "roller: the side of the line pivot → cam centre its point is "
                              "on; a flat face: the side of the face, looking along the arm "
                              "from its pivot, the cam is on", example='"left"'),
        Key("when", "string", "the instant by its event, not the driver's angle: 'leaves' or "
                              "'reaches' a part, 'on the rise' (default) or 'on the return'",
            example='"leaves the straight flank"'),
        Key("face_offset", "quantity", "an oscillating flat face's distance from the line "
                                       "of its arm", example='"0 mm"', dimension="length",
            default="0 mm", sign="positive to the left of pivot → R"),
    ), many=True),
)
KEYS = tuple(k.name for k in TABLES[0].keys)
