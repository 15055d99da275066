"""The drawing model: what is on the paper, in mm with y up, without svgwrite.

Layout modules (:mod:`diagrams.polygon`, :mod:`diagrams.space`) build a :class:`Drawing` of
these items; :mod:`diagrams.svg` (the only svgwrite importer) writes it.  Styles are names
(``'link'``, ``'c-centripetal'``, ``'c-coriolis-new'`` ...) whose meaning is carried by line
weight, dash pattern and arrowhead shape as well as colour; see :mod:`diagrams.components`.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

Pt = tuple[float, float]


def _mv(p: Pt, dx: float, dy: float) -> Pt:
    return (p[0] + dx, p[1] + dy)


@dataclass(frozen=True)
class Segment:
    a: Pt
    b: Pt
    style: str
    faded: bool = False
    cls: str = ""

    def moved(self, dx, dy):
        return replace(self, a=_mv(self.a, dx, dy), b=_mv(self.b, dx, dy))


@dataclass(frozen=True)
class Polyline:
    points: tuple[Pt, ...]
    style: str
    closed: bool = False
    faded: bool = False
    cls: str = ""

    def moved(self, dx, dy):
        return replace(self, points=tuple(_mv(p, dx, dy) for p in self.points))


@dataclass(frozen=True)
class Circle:
    centre: Pt
    r: float
    style: str
    faded: bool = False
    cls: str = ""
    ident: str = ""

    def moved(self, dx, dy):
        return replace(self, centre=_mv(self.centre, dx, dy))


@dataclass(frozen=True)
class Arrow:
    """A vector: shaft from ``tail`` to ``tip`` and an arrowhead whose first point is the tip.

    ``frm``/``to`` are the polygon vertices (lower case) it joins; ``role`` is 'known',
    'resolved', 'result', 'coriolis', 'image', 'join', 'input' or 'arc' (the head of an
    arc: an input ω, a couple; its length is no quantity's).  ``tail``/``tip`` are
    always the vertices; a vector lying on a longer collinear one is drawn moved sideways by
    ``shift`` (:mod:`diagrams.crowd`; the SVG writes it as a translation of the arrow).
    """
    tail: Pt
    tip: Pt
    style: str
    head: tuple[Pt, ...]          # polygon, tip first ('' when too short to draw)
    shaft_end: Pt                  # where the shaft stops (base of the head)
    name: str = ""
    frm: str = ""
    to: str = ""
    role: str = ""
    title: str = ""
    faded: bool = False
    new: bool = False
    shift: Pt = (0.0, 0.0)         # drawn moved by this (mm) beside a collinear vector

    @property
    def drawn(self) -> tuple[Pt, Pt]:
        """(tail, tip) where the shaft is drawn: the vector's ends moved by ``shift``."""
        return _mv(self.tail, *self.shift), _mv(self.tip, *self.shift)

    def moved(self, dx, dy):
        return replace(self, tail=_mv(self.tail, dx, dy), tip=_mv(self.tip, dx, dy),
                       head=tuple(_mv(p, dx, dy) for p in self.head),
                       shaft_end=_mv(self.shaft_end, dx, dy))


@dataclass(frozen=True)
class Text:
    x: float
    baseline: float
    text: str
    size: float
    anchor: str = "start"      # 'start' | 'middle' | 'end'
    role: str = "label"        # 'vertex', 'line', 'title', 'legend', 'caption', 'scale' ...
    weight: str = "normal"
    faded: bool = False
    cls: str = ""
    ident: str = ""
    ink: str = ""              # text colour ('' : black); a component label takes its look's

    def moved(self, dx, dy):
        return replace(self, x=self.x + dx, baseline=self.baseline + dy)


@dataclass(frozen=True)
class Group:
    """A named group (an SVG ``<g>`` with an id, classes and an accessible title)."""
    ident: str
    cls: str
    title: str
    items: tuple = ()

    def moved(self, dx, dy):
        return replace(self, items=tuple(i.moved(dx, dy) for i in self.items))


@dataclass(frozen=True)
class Drawing:
    """One SVG page: ``width`` × ``height`` mm; items in mm with y up from the bottom."""
    name: str                  # file stem: 'space', 'velocity', 'velocity-2'
    kind: str                  # 'space' | 'velocity' | 'acceleration'
    stage: int | None
    width: float
    height: float
    title: str
    desc: str
    groups: tuple[Group, ...]
    scale_statement: str = ""
    meta: dict = field(default_factory=dict, compare=False, hash=False)

    def items(self, cls: str | None = None):
        """All items (recursively), optionally only those of groups whose class has ``cls``.

        The key's sample lines are not part of the drawing: only ``items('key')`` has them."""
        def walk(g):
            for it in g.items:
                if isinstance(it, Group):
                    yield from walk(it)
                else:
                    yield it
        for g in self.groups:
            if (cls is None and g.cls != "key") or (cls is not None and cls in g.cls.split()):
                yield from walk(g)
