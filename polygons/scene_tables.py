"""The tables and keys :mod:`polygons.scene` reads, as data (:class:`~polygons.schema.Table`).

The loader takes its lists of allowed keys from here, and ``docs/scene-reference.md`` and
``polygons/scene.schema.json`` are generated from here (``python -m polygons.reference``), so
the three cannot drift apart.  A key named ``<LABEL>`` / ``<LINK>`` stands for any point label
or link name (the entries of ``[ground]``, ``[links]`` ...).

Label grammar: a point label is a capital letter followed by lower-case letters, digits, ``_``
or primes: ``A``, ``O2``, ``P4``, ``B'``, ``Cx``.  A link is named by its two end labels run
together: ``AB``, ``O2P2``, ``O4P4``.
"""
from __future__ import annotations

from .schema import Key, Table

#: the tables polygons.contacts rewrites into equivalent links (named here, so that a scene
#: without them is read without importing that module)
CONTACT_TABLES = ("curved_slots", "cams", "rolling", "bearing")

#: the assembly words (``[assembly] C = "C above AD"``)
RELATIONS = ("above", "below", "left of", "right of")
#: a corner named the extreme one of its class-III group's corners
EXTREMES = {"uppermost": "uppermost", "highest": "uppermost", "topmost": "uppermost",
             "lowest": "lowest", "lowermost": "lowest", "bottommost": "lowest",
             "leftmost": "leftmost", "rightmost": "rightmost"}
#: other phrasings of the assembly words, read as the relation beside them
SYNONYMS = (("lower than", "below"), ("higher than", "above"), ("is below", "below"),
             ("is above", "above"), ("to the left of", "left of"),
             ("to the right of", "right of"), ("is left of", "left of"),
             ("is right of", "right of"))


def book_words(rest: str) -> str:
    """Assembly words with another phrasing of a relation ('lower than B') as the relation
    ('below B')."""
    for said, rel in SYNONYMS:
        if rest.startswith(said + " "):
            return rel + rest[len(said):]
    return rest

#: a four-bar's circuit as Norton, Uicker and Myszka name it ('C open', 'C crossed')
CIRCUITS = {"open": "open", "crossed": "crossed", "open circuit": "open",
            "crossed circuit": "crossed", "open configuration": "open",
            "crossed configuration": "crossed"}


def circuit_refs(label: str, rest: str, links, ground):
    """'open' / 'crossed' for the pin ``label`` of a four-bar A–B–label–D (D and A fixed, AB
    turning about A) → (relation, (B, D, A)): crossed when two of its links cross (AB and CD,
    or BC and the frame DA), open when none do, as the books' figures show them (one of the
    two closures is always open; where both are, the words are refused as not choosing);
    (relation, None) when the pin is not such a joint; None for other words."""
    rel = CIRCUITS.get(rest.lower())
    if rel is None:
        return None
    ends = [ln.b if ln.a == label else ln.a for ln in links.values() if label in (ln.a, ln.b)]
    for b, d in ((ends[0], ends[1]), (ends[1], ends[0])) if len(ends) == 2 else ():
        if d in ground and b not in ground:
            pivots = [ln.b if ln.a == b else ln.a for ln in links.values()
                      if b in (ln.a, ln.b) and label not in (ln.a, ln.b)]
            pivots = [p for p in pivots if p in ground and p != d]
            if len(pivots) == 1:
                return rel, (b, d, pivots[0])
    return rel, None


ANSWER_FIELDS = _ANSWER_KEYS = (
    Key("quantity", "string", "the result, in textbook notation: v(C), v(C,B), a(C), "
                              "a(C,B), an(C,B), at(C,B), omega(BC), alpha(BC), vs(P), as(P), "
                              "cor(P), dist(B,A), x(C), y(C), dir_v(C), dir_a(C), "
                              "angle(P,Q,R), arm(O,P,C) (a point may be an instant centre "
                              "I13, numbered as `polygons centres` numbers the links, or a "
                              "point of Klein's figure of a slider-crank: dist(O,N)); "
                              "a [rolling.W] wheel's omega(W), "
                              "alpha(W) (and v(W), a(W) between two plates); the ratio of "
                              "two of one kind, X / Y (velocity ratio v(C) / v(B), "
                              "mechanical advantage omega(AB) / omega(CD), unit '-')",
        example='"omega(BC)"', required=True),
    Key("unit", "string", "the unit of tutorial and exact (any unit of the table below, or "
                          "'-' for a pure number)", example='"rad/s"', required=True),
    Key("tutorial", "number", "the tutorial's printed answer, in `unit`", example="7.2"),
    Key("exact", "number", "the exact answer (from an independent closed form), in `unit`",
        example="7.213"),
    Key("mode", "string", "'abs' compares magnitudes, 'signed' signed values",
        example='"signed"', default="abs"),
    Key("sense", "string", "the tutorial's direction word (CW, CCW, ...), shown beside the "
                           "answer", example='"CW"'),
    Key("tolerance", "quantity", "drawing tolerance for the tutorial value (overrides "
                                 "[source] drawing_tolerance)", example='"2 %"',
        dimension="fraction"),
    Key("slip", "bool", "the printed value is a known slip: the solver must NOT reproduce it",
        example="true", default=False),
    Key("ref", "string", "key of the answer in the reference cases.json", example='"omega_BC"'),
    Key("desc", "string", "the words printed beside the answer", example='"ω of BC"'),
    Key("note", "string", "a remark shown with the comparison", example='"read off Fig. 3"'),
)

TOP = Table("", "Top-level keys.", (
    Key("title", "string", "the heading of reports, drawings and handouts; default: the file "
                           "name", example='"Worked example 4"'),
    Key("solve", "array", "which polygons to construct: ['velocity'] or ['velocity', "
                          "'acceleration']", example='["velocity"]',
        default=["velocity", "acceleration"]),
))

TABLES: tuple[Table, ...] = (
    TOP,
    Table("source", "Where the case comes from (shown in reports and handouts; all optional).", (
        Key("id", "string", "case identifier", example='"S001-WE4"'),
        Key("seed", "string", "the source document", example='"tutorial 1"'),
        Key("example", "string", "the example's number in the source", example='"4"'),
        Key("category", "string", "kind of mechanism or question", example='"slider-crank"'),
        Key("statement", "string", "the problem statement as printed", example='"..."'),
        Key("conventions", "string", "the source's sign or naming conventions", example='"..."'),
        Key("notes", "string", "remarks", example='"..."'),
        Key("backsolved", "string", "which data were back-solved from printed answers",
            example='"BC from the printed ω"'),
        Key("slips", "string", "known slips of the source", example='"..."'),
        Key("mechanism", "string", "the mechanism in words", example='"four-bar"'),
        Key("synthetic", "bool", "the geometry is a stand-in for a missing figure",
            example="true", default=False),
        Key("drawing_tolerance", "quantity", "relative tolerance of the tutorial's drawn "
                                             "answers", example='"3 %"', dimension="fraction",
            default="3 %"),
    )),
    Table("ground", "Fixed pivots: one entry per label, its coordinates [x, y]; or, as books "
                    "place a pivot from another, a table { from = \"A\", distance = "
                    "\"300 mm\", angle = \"30 deg\" } (the angle CCW from +x, or \"30 deg CW\"; "
                    "from a pivot given before it).  A lone wheel ([driver] wheel, "
                    "[rolling.O]) needs none: its road is the frame, whose point G is the "
                    "road's `through` point.", (
        Key("<LABEL>", "point", "position [x, y] of a fixed pivot (or { from, distance, angle })",
            example='["0 mm", "0 mm"]', dimension="length", sign="x to the right, y up"),
    ), required=True),
    Table("links", "Binary links, named by their two end labels.", (
        Key("<LINK>", "length_or_drawn", "the link's length, or \"drawn\" to take it from the "
                                  "positions in [ground]/[drawn]; a slotted lever whose "
                                  "length is not needed is left out", example='"50 mm"',
            dimension="length"),
    )),
    Table("driver", "The input: a crank turning about its first label, or a slider pushed "
                    "along its guide (give exactly one of crank / slider).", (
        Key("crank", "link", "the driving link, pivot label first (the pivot must be in "
                             "[ground])", example='"AB"'),
        Key("angle", "string", "crank angle (an angle with its unit), CCW from +x (reduced to one turn exactly; "
                                 "beyond ±1e6° refused); also 'θ from idc' / 'θ from odc' "
                                 "(slider-crank: from inner / outer dead centre, in the "
                                 "crank's sense; any line of stroke, a vertical engine's "
                                 "too: [assembly] P = \"P above O\" puts the cylinder above "
                                 "O, idc the crank pointing at it; 'from tdc' / 'from bdc' "
                                 "the same), 'θ from AD' (CCW from the ray A→D), "
                                 "'θ from +y' (or +x, -x, -y) and 'θ CW from AD' / "
                                 "'θ clockwise from +y' (measured clockwise); "
                                 "default: from the tip's [drawn] position",
            example='"60 deg"', sign="CCW from +x"),
        Key("omega", "quantity", "crank speed (magnitude; its sense is `sense`, or written "
                                 "after it as books do: '300 rad/s CW', '120 rpm "
                                 "clockwise'); 0 for an instant at rest", example='"300 rad/s"',
            dimension="angular_velocity"),
        Key("speed", "quantity", "instead of omega, the crank pin's speed as books give it "
                                 "('the crank pin moves at 5 m/s'): ω = speed / crank length; "
                                 "its sense as omega's", example='"5 m/s"',
            dimension="velocity"),
        Key("sense", "string", "sense of rotation: 'CW' or 'CCW' (also clockwise, "
                               "anticlockwise, anti clockwise, counter-clockwise, ACW, "
                               "c.w., a.c.w., in any case)", example='"CW"'),
        Key("alpha", "quantity", "crank angular acceleration (magnitude; its sense is "
                                 "`alpha_sense`, or written after it: '80 rad/s^2 CCW'; or "
                                 "against the rotation, as books say it: '5 rad/s^2 "
                                 "retarding' (or decelerating: opposite ω; accelerating: "
                                 "with it))",
            example='"80000 rad/s^2"', dimension="angular_acceleration", default="0 rad/s^2"),
        Key("alpha_sense", "string", "sense of alpha, 'CW' or 'CCW' (needed when alpha ≠ 0; "
                                     "independent of `sense`)", example='"CCW"'),
        Key("slider", "label", "a slider as the driver: the point pushed along its "
                               "[sliders.X] guide", example='"C"'),
        Key("position", "quantity", "slider driver: position along the guide, from the "
                                    "guide's `through` point in its `direction`",
            example='"120 mm"', dimension="length", sign="positive along `direction`"),
        Key("rod", "link", "slider driver placed by the angle of its rod instead of position "
                           "('the connecting rod AB makes 30° with the line of stroke'): the "
                           "rod, a link at the slider whose other end is on a fixed guide or "
                           "joined by one link to a fixed pivot (two positions: [assembly] "
                           "near chooses)", example='"BA"'),
        Key("rod_angle", "string", "with rod: the rod's direction, first label → second, CCW "
                                   "from +x (or '30 deg CW')", example='"150 deg"'),
        Key("rod_omega", "string", "with rod and rod_angle, instead of velocity: the rod's "
                                   "angular velocity as the book gives it ('the bar AB turns at "
                                   "2 rad/s CW'; the sense here or in rod_sense); the slider's "
                                   "velocity and acceleration follow", example='"2 rad/s CW"'),
        Key("rod_sense", "string", "the sense of rod_omega, 'CW' or 'CCW'", example='"CW"'),
        Key("rod_alpha", "string", "with rod_omega: the rod's angular acceleration (sense here "
                                   "or in rod_alpha_sense)", example='"5 rad/s^2 CCW"'),
        Key("rod_alpha_sense", "string", "the sense of rod_alpha, 'CW' or 'CCW'",
            example='"CCW"'),
        Key("velocity", "quantity", "slider driver: velocity along the guide, signed, or its "
                                     "size and direction in words as books give it ('2 m/s to "
                                     "the left'; right, up, down: the guide along that axis) "
                                     "(or rod_omega); "
                                     "a wheel driver: its centre's velocity along the "
                                     "surface's direction instead of omega ('the centre moves "
                                     "at 2 m/s': ω = −v / r)",
            example='"2 m/s"', dimension="velocity", sign="positive along `direction`"),
        Key("acceleration", "quantity", "slider driver: acceleration along the guide (signed, or "
                                         "'5 m/s^2 to the right'); a wheel "
                                         "driver with velocity: its centre's (α = −a / r)",
            example='"0 m/s^2"', dimension="acceleration", default="0 m/s^2",
            sign="positive along `direction`"),
        Key("lever", "link", "a slotted lever driven like a crank (the oscillating cylinder, "
                             "the rotary engine): needs a length in [links] and [slots.PIN] "
                             "lever = this lever", example='"O4Q"'),
        Key("wheel", "label", "a wheel rolling without slipping on a fixed surface as the "
                              "input ([rolling.W] with this label), turning at omega (sense), "
                              "alpha (alpha_sense) — or its centre's velocity and "
                              "acceleration along the surface: links may be pinned to its "
                              "named points ([rolling.W] rim)", example='"W"'),
        Key("slide", "table", "a second input: a point moved along a link at a prescribed "
                              "sliding velocity and acceleration ([driver.slide])",
            example='{ point = "C", along = "OA", position = "300 mm", velocity = "1.5 m/s" }'),
    ), required=True),
    Table("sliders", "[sliders.C]: point C slides on a fixed straight guide (or, with pin and "
                     "slot, is the yoke of a Scotch yoke).", (
        Key("through", "point", "a point of the guide line (or give `from` and `offset`)",
            example='["0 mm", "0 mm"]', dimension="length"),
        Key("from", "label", "a fixed point the guide is measured from (with `offset`): the "
                             "slider driver's offset guide stated by its distance from a pivot",
            example='"O"'),
        Key("offset", "quantity", "with `from`: perpendicular distance of the guide line from "
                                  "that point", example='"20 mm"', dimension="length",
            sign="positive to the left of `direction`"),
        Key("direction", "quantity", "direction of the guide, CCW from +x",
            example='"0 deg"', dimension="angle", required=True, sign="CCW from +x"),
        Key("pin", "label", "Scotch yoke: the placed pin sliding in the yoke's slot",
            example='"B"'),
        Key("slot", "quantity", "Scotch yoke: direction of the slot (not parallel to the "
                                "guide)", example='"90 deg"', dimension="angle",
            sign="CCW from +x"),
    ), many=True),
    Table("slots", "[slots.P]: pin P slides in the straight slot of a lever pivoted at a fixed "
                   "point (quick return, Coriolis).  A slotted lever with a length in [links] "
                   "may carry a further rod from its far end.", (
        Key("lever", "link", "the slotted lever, pivot label first (its pivot in [ground] or a "
                             "pin of a link)",
            example='"BC"', required=True),
        Key("coincident", "label", "the point of the lever under the pin at this instant "
                                   "(required when the lever has a length; otherwise it is the "
                                   "lever's second label)", example='"A1"'),
        Key("offset", "quantity", "perpendicular distance of the slot line from the lever's "
                                  "line (needs the lever's length in [links])",
            example='"20 mm"', dimension="length", default="0 mm",
            sign="positive to the left of the lever's pivot → far end"),
        Key("length", "quantity", "how far the slot runs along the lever from its pivot: the "
                                  "pin beyond it has left the slot (unstated: open-ended, "
                                  "whatever the lever's length)", example='"300 mm"',
            dimension="length"),
    ), many=True),
    Table("points", "[points.D]: a point rigid with a link (coupler point, a continuation, a "
                    "mid-point).", (
        Key("on", "link", "the link (as named in [links], or a slotted lever)",
            example='"AB"', required=True),
        Key("along", "quantity", "distance from the link's FIRST label towards its second "
                                 "(negative: behind the first label); or use fraction",
            example='"168 mm"', dimension="length",
            sign="from the first label of `on` towards the second"),
        Key("fraction", "quantity", "position as a fraction of the link from its first label "
                                    "(0.5: the mid-point); or use along", example="0.5",
            dimension="fraction"),
        Key("left", "quantity", "perpendicular offset, positive to the LEFT of the direction "
                                "first label → second label", example='"10 mm"',
            dimension="length", default="0 m",
            sign="positive to the left of first → second label"),
        Key("distance", "quantity", "the point by polar coordinates from the link's first label, "
                                    "as books state it ('BE = 40 mm and angle CBE = 30°'): "
                                    "the distance; with angle, instead of along/fraction/left",
            example='"40 mm"', dimension="length"),
        Key("angle", "string", "with distance: the angle from the link (first → second label) "
                               "to the point, CCW (or '30 deg CW')", example='"30 deg"',
            sign="CCW from first → second label"),
        Key("distances", "array", "a corner of a plate by its distances from the link's first "
                                  "and second labels, as books state it ('BX = 100 mm, "
                                  "CX = 120 mm'), with side; instead of along/left",
            example='["100 mm", "120 mm"]'),
        Key("side", "string", "with distances: 'left' or 'right' of the link's first → second "
                              "label", example='"left"'),
    ), many=True),
    Table("assembly", "Which of the two closures of a dyad, in words: C = \"C above AD\", "
                      "\"below AD\", \"left of B\", \"right of B\" (the leading label is "
                      "optional; the reference is a point or a line of two points; also "
                      "\"lower than\", \"higher than\", \"to the left of\"; a corner of a "
                      "class-III group may name another corner, or be \"uppermost\", "
                      "\"lowest\", \"leftmost\", \"rightmost\" of its corners; a four-bar's "
                      "coupler–rocker pin \"C open\" or \"C crossed\", as Norton, Uicker and "
                      "Myszka name its circuits: crossed when two of its links cross in the "
                      "figure), or C = { near = [x, y] }.", (
        Key("<LABEL>", "branch", "'above', 'below', 'left of' or 'right of' a point or a line "
                                 "of two labels ('lower than', 'higher than', 'to the left of', "
                                 "'to the right of' too; a triad's corner: 'uppermost', "
                                 "'lowest', 'leftmost', 'rightmost'), or an inline table "
                                 "{ near = [x, y] }",
            example='"C right of A"'),
    )),
    Table("drawn", "The space diagram as drawn: coordinates of moving points at this instant "
                   "(picks the closure nearest to it, gives lengths written \"drawn\" and the "
                   "crank angle when `angle` is omitted; checked against [assembly] to 0.1 % "
                   "of the mechanism's size).", (
        Key("<LABEL>", "point", "the drawn position [x, y]", example='["135 mm", "26 mm"]',
            dimension="length"),
    )),
    Table("answers", "[[answers]]: the tutorial's printed answers and the exact ones (used by "
                     "the tests and printed in the report).", _ANSWER_KEYS, array=True),
)

#: table name -> its key names (the loader's allowed lists)
KEYS = {t.name: tuple(k.name for k in t.keys) for t in TABLES}
TOP_KEYS = KEYS[""] + tuple(t.name for t in TABLES if t.name)
ANSWER_KEYS = KEYS["answers"]
