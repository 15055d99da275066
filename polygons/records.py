"""The scene's value objects: the frozen records its tables are read into (links, guides,
the driver, slots, body points, assembly words, answers and their typed quantities).
:mod:`polygons.scene` builds them and re-exports them; :mod:`polygons.model` reads them."""
from __future__ import annotations

import math
from dataclasses import dataclass

Vec = tuple[float, float]


@dataclass(frozen=True)
class Link:
    """A rigid binary link between pins ``a`` and ``b`` (``length`` None for a slotted lever)."""

    name: str
    a: str
    b: str
    length: float | None


@dataclass(frozen=True)
class Guide:
    """A fixed straight slider guide through ``through`` at ``angle`` (rad, CCW from +x).

    A slider may carry a straight slot (a Scotch yoke): ``pin`` slides in it, and the slot
    keeps the fixed direction ``slot_angle`` because the slider only translates.  The
    slider's label is then the point of the yoke on its guide, under the slot line."""

    through: Vec
    angle: float
    pin: str | None = None
    slot_angle: float | None = None

    @property
    def direction(self) -> Vec:
        return (math.cos(self.angle), math.sin(self.angle))

    @property
    def slot_direction(self) -> Vec | None:
        if self.slot_angle is None:
            return None
        return (math.cos(self.slot_angle), math.sin(self.slot_angle))


@dataclass(frozen=True)
class Crank:
    """Driver: link ``link`` turning about fixed ``pivot``; ``tip`` is its other end."""

    link: str
    pivot: str
    tip: str
    angle: float
    omega: float   # signed, CCW positive
    alpha: float   # signed, CCW positive
    #: the angle as the book stated it, 'θ from REF' (idc, odc, AD, +y ...): (REF, the
    #: reference's angle CCW from +x, +1 / −1 the sense θ is measured in); None for 'θ'
    stated: tuple[str, float, float] | None = None


@dataclass(frozen=True)
class SliderDrive:
    """Driver: point ``point`` pushed along its guide; ``position`` measured from the guide's
    ``through`` point along its direction, ``velocity``/``acceleration`` signed the same way."""

    point: str
    position: float
    velocity: float
    acceleration: float
    #: (rod, ω, α) when the book states the rate as the rod's ('the bar AB turns at 2 rad/s
    #: CW'): ``velocity``/``acceleration`` follow from it (topology.slider_rate_by_rod)
    rod_rate: tuple[str, float, float] | None = None
    #: with ``rod_rate``: the angle (degrees) between the two directions whose meeting gives
    #: the slider's speed from the rod's ω (near 0: the rod barely turns whatever the speed)
    rod_angle_deg: float | None = None
    #: placed by its rod's angle with [assembly] words for the rod's far end: (the rod's name,
    #: the far end, the stated angle slider → far end in rad, the position it gives), checked
    #: when the mechanism is placed at that position (the words must not pick the mirror)
    rod_end: tuple[str, str, float, float] | None = None


@dataclass(frozen=True)
class Slot:
    """Pin ``pin`` slides in the straight slot of ``lever``, which turns about fixed ``pivot``;
    the slot runs through the pivot along the lever.  ``coincident`` is the point of the lever
    under the pin at this instant (P4 under P2, A1 under A); ``far`` is the lever's other
    labelled end when it has a stated length (C of lever BC), else None."""

    pin: str
    lever: str
    pivot: str
    coincident: str
    far: str | None
    far_length: float | None
    offset: float = 0.0     # the slot line's distance left of the lever's line (topology)
    length: float | None = None     # the slot's stated length from the pivot (topology)


@dataclass(frozen=True)
class BodyPoint:
    """Point ``label`` rigidly attached to link ``link`` (ends P, Q): at distance ``along`` from
    P towards Q plus ``left`` perpendicular (to the left of P→Q)."""

    label: str
    link: str
    along: float | None
    fraction: float | None
    left: float


@dataclass(frozen=True)
class Branch:
    """Assembly choice for ``label``: ``relation`` ('above', 'below', 'left of', 'right of',
    'near') a reference (a point label, a line of two labels, or coordinates for 'near')."""

    label: str
    text: str
    relation: str
    ref: tuple[str, ...] = ()
    near: Vec | None = None


@dataclass(frozen=True)
class Quantity:
    """A result quantity, typed once at load: 'v(C,B)' is Quantity('v', ('C', 'B')) — the
    function (one of :data:`QUANTITY_FUNCTIONS`) and its labels.  Readers (measures, marks,
    graders) read these fields; nobody parses the text again."""

    fn: str
    args: tuple[str, ...]

    def __str__(self) -> str:
        return f"{self.fn}({','.join(self.args)})"

    @property
    def display(self) -> str:
        """As a table heads it: |v_C|, |a_C|, ω_BC, α_BC (else the quantity's text)."""
        sym = {"omega": "ω", "alpha": "α"}.get(self.fn)
        if sym is not None and len(self.args) == 1:
            return f"{sym}_{self.args[0]}"
        if self.fn in ("v", "a") and len(self.args) == 1:
            return f"|{self.fn}_{self.args[0]}|"
        return str(self)


@dataclass(frozen=True)
class Answer:
    """One printed (tutorial) answer and/or exact reference value for a result quantity."""

    quantity: str
    unit: str
    tutorial: float | None      # in `unit`
    exact: float | None         # in `unit`
    mode: str                   # 'abs' compares magnitudes, 'signed' compares signed values
    sense: str | None           # the tutorial's direction word (CW/CCW/...), if any
    tolerance: float            # relative drawing tolerance for the tutorial value
    slip: bool                  # the reference found a slip: we must NOT reproduce it
    ref: str | None             # key in the reference cases.json
    desc: str
    note: str
    q: Quantity | None = None   # ``quantity`` typed (parse_quantity_expr), set at load


@dataclass(frozen=True)
class Crossing:
    """A pin ``pin`` sliding in the straight slots of two moving levers at once (crossing
    slots): ``levers`` (each a link in [links], its slot along its first label → its second)
    and ``coincident``, each lever's point under the pin."""

    pin: str
    levers: tuple[str, str]
    coincident: tuple[str, str]
