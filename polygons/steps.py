"""Typed construction steps: the single currency between the solver and everything drawn.

A :class:`Step` is one stroke of a tutorial's construction ("from o draw oa = ω·OA ⟂ OA",
"through b1 draw the b line ⟂ AB", "the lines meet at b").  The dyad modules
(:mod:`polygons.dyads`) plan steps with no numbers in them; the step program written out by
:mod:`polygons.codegen` executes them (for each interpreter: staged with shapely, compiled over
floats, vectorised over arrays, on a noisy drawing board) and the numbers are filled into copies:
the vertex it creates, the vector it draws, the direction of a line, a measured value, and the
:class:`Term` records substituted into the formula.  Renderers, narrators and graders read
these fields; nobody parses the prose (``reason``, ``substituted``) back.

The enums are ``StrEnum``: they compare equal to the strings written in JSON.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import StrEnum


class Diagram(StrEnum):
    VELOCITY = "velocity"
    ACCELERATION = "acceleration"


class Kind(StrEnum):
    """What the stroke puts on paper."""
    VECTOR = "vector"              # a known vector from ``start`` to the new vertex ``end``
    LINE = "line"                  # a line of unknown length through ``start``
    INTERSECTION = "intersection"  # two earlier lines meet: a new vertex
    MEASURE = "measure"            # a number read off the polygon (ω, α, a sliding speed)
    IMAGE = "image"                # a vertex by the velocity/acceleration image of a link


class Op(StrEnum):
    """The operation an interpreter performs (one implementation per op, per interpreter)."""
    CRANK_VELOCITY = "crank_velocity"            # ω × r
    SLIDER_DRIVE = "slider_drive"                # the given value along a unit direction
    CENTRIPETAL = "centripetal"                  # −ω² r
    CRANK_TANGENTIAL = "crank_tangential"        # α × r
    SLIDE_DRIVE = "slide_drive"                  # a prescribed sliding rate along a link
    CORIOLIS_DRIVE = "coriolis_drive"            # 2 ω × ṡ e with ṡ prescribed
    LINE_PERP = "line_perp"                      # a line ⟂ a link
    LINE_ALONG = "line_along"                    # a line ∥ a link
    LINE_GUIDE = "line_guide"                    # a line ∥ a fixed guide
    LINE_SLOT = "line_slot"                      # a line ∥ a translating yoke's slot
    LINE_SLIDE = "line_slide"                    # a line ∥ a lever's slot (offset or driven)
    CORIOLIS_OFFSET_LINE = "coriolis_offset_line"  # a line ∥ the slot, stepped back by 2ωv
    CORIOLIS = "coriolis"                        # the Coriolis vector 2 ω × v
    JOIN = "join"                                # the vector between two known vertices
    INTERSECT = "intersect"                      # two lines meet
    OMEGA = "omega"                              # ω = (r × v_rel) / r²
    ALPHA = "alpha"                              # α = (r × a_rel) / r²
    SLIDER_VELOCITY = "slider_velocity"          # v · e along a fixed guide
    SLIDER_ACCELERATION = "slider_acceleration"
    SLIDE_VELOCITY = "slide_velocity"            # sliding velocity along a rotating slot
    SLIDE_ACCELERATION = "slide_acceleration"
    IMAGE = "image"                              # v = v_p + ω × r; a = a_p + α × r − ω² r
    ROLL_OMEGA = "roll_omega"                    # a wheel rolling on a fixed line: ω = −v·e / r
    ROLL_ALPHA = "roll_alpha"                    # α = −a·e / r


class Component(StrEnum):
    """The kind of component a stroke is: one colour and line style each on the drawings."""
    GIVEN = "given"                # an input stated by the question
    RELATIVE = "relative"          # ω × r: a relative velocity
    CENTRIPETAL = "centripetal"    # ω² r towards the centre
    TANGENTIAL = "tangential"      # α × r
    SLIDING = "sliding"            # along a slot or guide
    CORIOLIS = "coriolis"          # 2 ω × v
    IMAGE = "image"                # by the image of a rigid link
    RESULTANT = "resultant"        # an absolute quantity, from the pole
    CONSTRUCTION = "construction"  # a construction aid (a line carries the component on it)


@dataclass(frozen=True)
class Term:
    """One number substituted into a step's formula: ``symbol`` (textbook notation, e.g.
    ``ω_BC``, ``AB``, ``v_C``), its SI ``value`` (signed where the sign means a sense) and
    ``unit`` ('rad/s', 'm', 'm/s', 'm/s^2', ...).  The step's result is the last term."""
    symbol: str
    value: float
    unit: str


@dataclass(frozen=True)
class Step:
    """One stroke of the construction, as a tutorial figure adds it.

    Planned with ``op``/``args`` and words only; an interpreter returns a copy with the
    numbers (``at``, ``vector``, ``point``, ``direction``, ``value``, ``angle_deg``,
    ``terms``, from which :func:`polygons.narrate.substitute` writes the formula) filled in.  The diagrams draw these
    records and never recompute them.
    """

    diagram: Diagram        # velocity | acceleration
    number: int             # 1, 2, ... within its diagram (stage 1, 2, 3 ...)
    kind: Kind
    op: Op
    args: tuple[str, ...]   # space labels / link names the operation uses (an intersection:
    #                         the fixed pivot its resultant is named from, if any: dc)
    draws: str              # what appears on paper: 'oa', 'line ⟂ BC', 'b', 'ω_BC'
    start: str | None       # polygon vertex the vector starts at / the line passes through
    end: str | None         # polygon vertex this step creates
    theorem: str            # 'relative_velocity', 'centripetal', 'coriolis', ...
    quantity: str           # '(v_A)_O', '(a_C)_B^t', 'ω_BC'
    formula: str            # symbolic formula
    reason: str             # the sentence a tutorial would write
    lines: tuple[int, ...] = ()          # for an intersection: the step numbers of its lines
    component: Component = Component.CONSTRUCTION
    link: str | None = None              # the link whose ω/α this step gives or uses
    relative: tuple[str, str] | None = None  # (X, Y): the step carries X relative to Y
    reads: str | None = None             # for a measure: the polygon vector it reads ('c1c')
    # -- filled by an interpreter -----------------------------------------------------------
    at: tuple[float, float] | None = None         # start vertex / line anchor, polygon coords
    vector: tuple[float, float] | None = None     # for vectors and images: end - start
    point: tuple[float, float] | None = None      # vertex created
    direction: tuple[float, float] | None = None  # for lines: unit direction
    value: float | None = None                    # for measures (SI, signed)
    unit: str = ""
    angle_deg: float | None = None                # for intersections: angle between the lines
    terms: tuple[Term, ...] = ()                  # the numbers of the substituted formula
    # (the formula with its numbers is written from ``terms`` when shown:
    # :func:`polygons.narrate.substitute`, never stored as text)

    @property
    def gives(self) -> str | None:
        """The symbol this step determines ('ω_BC', 'α_BC', 'v_C', ...) or None."""
        return self.terms[-1].symbol if self.terms else None


# ---------------------------------------------------------------- vector names
def points_back(vertex_of, line: Step, end: str) -> bool:
    """True when the vector on ``line`` runs from the new vertex ``end`` back to the line's
    anchor.

    A line of unknown length carries a relative vector '(v_X)_Y' (X relative to Y, drawn
    y → x).  Usually the line goes through y and the intersection makes x; when it goes
    through x (the slot line through the pin's vertex) the arrow points back at the anchor.
    ``vertex_of``: a label's vertex (``Solution.vertex_of``).
    """
    if line.relative:
        x, ref = line.relative
        if line.start == vertex_of(x) and end == vertex_of(ref):
            return True
        if line.start == vertex_of(ref):
            return False
    return line.op == "line_along"


def tail_name(step: Step, start: str, pole: str, fixed, meet: Step | None = None) -> str:
    """The name a vector's tail is printed with, as the books write it: from the pole, the
    fixed point the vector is read about — the pivot an intersection names (dc, the velocity
    of C about the fixed D where the pole is a = d) or a centripetal vector's fixed centre
    (dc₂) — else its vertex.  ``fixed``: the pole's names (every fixed point's letter);
    ``meet``: the intersection that ends a line's vector.  The drawings' legend, the
    narration and the grader's rows all name a vector by it."""
    if start != pole:
        return start
    if meet is not None and meet.args and meet.args[0].lower() in fixed:
        return meet.args[0].lower()
    if step.op == "centripetal" and len(step.args) > 1 and step.args[1].lower() in fixed:
        return step.args[1].lower()
    return start


# ---------------------------------------------------------------- vertex names
class Vertices:
    """Polygon vertex names: lower-case space labels; every fixed point is the pole."""

    def __init__(self, scene):
        self.scene = scene
        self.pole = pole_of(scene)
        self.taken = {lab.lower() for lab in scene.labels} | {self.pole}

    def of(self, label: str) -> str:
        return self.pole if label in self.scene.ground else label.lower()

    def named(self, label: str) -> str:
        """The vertex of ``label`` as a book names it in words: a fixed point by its own
        letter, one of the pole's names ('dc' for the velocity of C about the fixed D, where
        the pole is 'a = d'), any other point as :meth:`of` does."""
        return label.lower() if label in self.scene.ground else self.of(label)

    def fresh(self, label: str, diagram_taken: set[str], dash: bool = False) -> str:
        """A new vertex near ``label``'s, as the books name them: the end of a known component
        numbered, b1, b2, ... (b₁, b₂); the foot of a Coriolis vector dashed, ``dash``: b_1
        (b′); a label ending in a digit always dashed, p2_1, p2_2 (p₂′, p₂″), since p21
        would read as the vertex of P21."""
        base = label.lower()
        sep = "_" if dash or base[-1].isdigit() else ""
        k = 1
        while True:
            name = f"{base}{sep}{k}"
            if name not in self.taken and name not in diagram_taken:
                diagram_taken.add(name)
                return name
            k += 1

    def alias(self) -> str:
        """'o = a = d': every name of the pole (fixed points have no velocity)."""
        g = [g.lower() for g in self.scene.ground if g.lower() != self.pole]
        return " = ".join([self.pole] + g)


def pole_of(scene) -> str:
    """The pole's name: the driving crank's pivot, else the first fixed point, lower-case."""
    drv = scene.driver
    first = getattr(drv, "pivot", None) or next(iter(scene.ground))
    return first.lower()


@dataclass
class Builder:
    """Collects one diagram's steps, numbering them; dyad modules call :meth:`add`."""

    scene: object
    diagram: Diagram
    names: Vertices
    steps: list[Step] = field(default_factory=list)
    taken: set[str] = field(default_factory=set)

    @property
    def velocity(self) -> bool:
        return self.diagram is Diagram.VELOCITY

    @property
    def q(self) -> str:
        """'v' or 'a': the symbol of this diagram's quantity."""
        return "v" if self.velocity else "a"

    @property
    def what(self) -> str:
        return "velocity" if self.velocity else "acceleration"

    def add(self, kind: Kind, op: Op, args, draws, start, end, theorem, quantity, formula,
            reason, lines=(), *, component: Component, link: str | None = None,
            relative: tuple[str, str] | None = None, reads: str | None = None) -> int:
        n = len(self.steps) + 1
        self.steps.append(Step(self.diagram, n, kind, op, tuple(args), draws, start, end,
                               theorem, quantity, formula, reason, tuple(lines), component,
                               link, relative, reads))
        return n

    def fresh(self, label: str, dash: bool = False) -> str:
        """A new vertex near ``label``'s (:meth:`Vertices.fresh`; ``dash``: a Coriolis foot)."""
        return self.names.fresh(label, self.taken, dash)


# ---------------------------------------------------------------- the one number formatter
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number(x: float, printed: bool = False) -> str:
    """Five significant figures written out in full, trailing zeros dropped, as a tutorial
    would (156105, 0.80587, 0.05); outside 1e-4 … 1e9 in e-notation (1.5e+10), or, when
    ``printed``, as a printed page writes it (1.5 × 10¹⁰)."""
    x = float(x)
    if x == 0.0 or not 1e-4 <= abs(x) < 1e9:
        text = f"{x:.5g}"
        if printed and "e" in text:
            mant, _, exp = text.partition("e")
            return f"{mant} × 10{str(int(exp)).translate(_SUPERSCRIPT)}"
        return text
    decimals = max(0, 4 - math.floor(math.log10(abs(x))))
    text = f"{x:.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def noise_floor(magnitudes) -> float:
    """The rounding noise of numbers of one kind in one construction: 1e-12 of the largest.
    A number at or below it is a zero of the construction (a translating link's ω, a body
    starting from rest, left at ~1e-15), printed as 0 with no sense, as a book prints it."""
    return 1e-12 * max(magnitudes, default=0.0)


#: ours (a printed answer's reference) is a zero beside the tutorial's value below this
#: ratio: no percentage of it
ZERO_RATIO = 1e-9


def percent_diff(tutorial: float, ours: float) -> float | None:
    """(tutorial − ours) / |ours| × 100; None — undefined — when ours is zero or a computed
    zero (|ours| ≤ 1e-9 |tutorial|: 3.9e-30 for 0, a subnormal mass's forces) or the ratio is
    not finite, so that no 1.5e34 % or inf is ever printed."""
    if not abs(ours) > ZERO_RATIO * abs(tutorial):
        return None
    diff = (tutorial - ours) / abs(ours) * 100.0
    return diff if math.isfinite(diff) else None


def sense(w: float) -> str:
    """'CCW' for a positive angular quantity, 'CW' for a negative one, '' for zero."""
    if w == 0.0:
        return ""
    return "CCW" if w > 0 else "CW"


def unit_text(unit: str) -> str:
    """'m/s^2' → 'm/s²' for prose."""
    return unit.replace("^2", "²")
