"""Component kinds of the polygons' vectors and the one look (colour, width, dashes) of each.

Every vector of a velocity or acceleration polygon is one kind of component: the given input,
a relative velocity, a centripetal, tangential, sliding or Coriolis acceleration, an image
side or the resultant (absolute, from the pole); construction lines of unknown length are
'construction'.  :func:`component_of` derives the kind of a step (ONE place: when
``Step.component`` exists it becomes ``return str(step.component)``) and :data:`LOOKS` gives
each kind one colour (Okabe–Ito, safe for colour-blind readers) *and* one width/dash pattern
so the drawing still reads in greyscale.  No svgwrite here: :mod:`diagrams.svg` reads
:data:`LOOKS`.
"""
from __future__ import annotations

from dataclasses import dataclass

ORDER = ("given", "relative", "centripetal", "tangential", "sliding", "coriolis",
         "coriolis-aux", "image", "resultant", "construction")


@dataclass(frozen=True)
class Look:
    name: str            # the legend's words
    colour: str          # stroke colour
    width: float         # stroke width (mm)
    dash: str | None     # SVG dash array (mm), None: solid
    open_head: bool = False


LOOKS: dict[str, Look] = {
    "given": Look("given (input)", "#000000", 0.6, None),
    "relative": Look("relative velocity", "#0072B2", 0.45, None),
    "centripetal": Look("centripetal", "#009E73", 0.45, None),
    "tangential": Look("tangential", "#D55E00", 0.5, "2.6 0.9"),
    "sliding": Look("sliding", "#8F6400", 0.5, "2.6 0.8 0.5 0.8"),
    "coriolis": Look("Coriolis 2ωv", "#882255", 0.9, None, open_head=True),
    # the copy of 2ωv stepped back from the pin's vertex to place the offset line: drawn once as
    # a vector (heavy), its auxiliary copy as a light construction line, as books draw it
    "coriolis-aux": Look("2ωv stepped back (construction)", "#882255", 0.25, "1.2 0.8",
                         open_head=True),
    "image": Look("image side (rigid body)", "#332288", 0.4, "0.9 0.7"),
    "resultant": Look("resultant (absolute, from the pole)", "#000000", 0.75, "0.5 0.8"),
    "construction": Look("construction line", "#555555", 0.25, "3 1.5"),
    # the force methods (diagrams.forcepoly): force polygons per group, Zhukovsky's lever
    "force-load": Look("applied load or weight", "#000000", 0.55, None),
    "force-inertia": Look("inertia force −m a_G (offset by h)", "#CC79A7", 0.6, "0.6 0.6"),
    "force-passed": Look("force passed on by a group solved", "#0072B2", 0.45, "1.6 0.6"),
    "force-moments": Look("normal component, by moments", "#D55E00", 0.5, "2.6 0.9"),
    "force-closing": Look("closing side (along a link, guide normal)", "#009E73", 0.7, None),
    "force-reaction": Look("pin reaction (diagonal)", "#000000", 0.75, "0.5 0.8"),
    "force-effort": Look("balancing effort", "#882255", 0.9, None, open_head=True),
    "force-lever": Look("Zhukovsky's lever (velocity polygon turned 90°)", "#332288", 0.35,
                        "0.9 0.7"),
}


def component_of(step) -> str:
    """The component kind of ``step`` (its :class:`polygons.steps.Component`): what lies along
    a vector or a line; measures are not drawn."""
    if step.kind == "measure":
        return "construction"
    return str(step.component)


def new_width(look: Look) -> float:
    """Stroke width of a component in the stage that draws it (heavier)."""
    return round(look.width * 1.5, 3)


#: the component of the vector found on a line of unknown length, by the line's op, when the
#: step does not say (a dyad that leaves its line 'construction': the triad's auxiliary lines)
_ON_LINE = {"line_perp": ("relative", "tangential"), "line_slide": ("sliding", "sliding"),
            "line_along": ("sliding", "sliding"), "line_slot": ("sliding", "sliding")}


def carried_by(line) -> str:
    """The component kind of the vector the construction finds on ``line`` (a 'line' step):
    its own component, else the one its op draws (⟂ a link: relative velocity or tangential
    acceleration; along a slot or guide: sliding) — never a thin grey construction arrow."""
    kind = component_of(line)
    if kind != "construction":
        return kind
    pair = _ON_LINE.get(str(line.op))
    if pair is None:
        return kind
    return pair[0] if str(line.diagram) == "velocity" else pair[1]
