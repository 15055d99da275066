"""Scaled lengths: read the drawings back as a student reads them with a ruler.

:func:`read_svg` parses a written SVG (nothing else): the stated scale ('Scale 1 cm = 2 m/s'),
the polygon vertices, the arrows (tail of the shaft to the tip of the head) and the space
diagram's points, in mm.  :func:`scaled` turns a drawn length into the quantity (mm ÷ scale,
optionally rounded to the ruler's resolution first).  :func:`compare` reads every answer of
the scene that is a length on the drawings (v, a, an, at, cor, vs, as, dist, and ω, α as a
scaled length divided by the link's scaled length, with the sense from the drawing) and
compares it with the tutorial's printed value.
"""
from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

from polygons.evaluate import link_ends
from polygons.notation import vertex, vertices_in
from polygons.scene import Quantity
from polygons.units import UNITS

from .scale import DiagramError
from .text import number, untoken

SVG_NS = "{http://www.w3.org/2000/svg}"
Pt = tuple[float, float]
#: a ruler on paper is read to half a millimetre
RULER_MM = 0.5


@dataclass(frozen=True)
class DrawnVector:
    frm: str
    to: str
    role: str
    tail: Pt      # mm, y up: the vertices it joins
    tip: Pt
    shift: Pt = (0.0, 0.0)    # drawn moved by this beside a collinear vector (its translation)

    @property
    def drawn(self) -> tuple[Pt, Pt]:
        """(tail, tip) as the ink lies on the paper."""
        return ((self.tail[0] + self.shift[0], self.tail[1] + self.shift[1]),
                (self.tip[0] + self.shift[0], self.tip[1] + self.shift[1]))

    @property
    def mm(self) -> float:
        return math.hypot(self.tip[0] - self.tail[0], self.tip[1] - self.tail[1])


@dataclass
class Reading:
    """What one SVG shows, in mm (y up) and its stated scale."""
    title: str
    per_cm: float                 # SI units per cm, read from the scale statement
    statement: str
    vertices: dict = field(default_factory=dict)   # polygon vertex -> (x, y) mm
    vectors: list = field(default_factory=list)    # DrawnVector
    points: dict = field(default_factory=dict)     # space label -> (x, y) mm

    def si(self, mm: float, ruler: float | None = None) -> float:
        """The SI magnitude of a drawn length, read to ``ruler`` mm if given."""
        if ruler:
            mm = round(mm / ruler) * ruler
        return mm * self.per_cm / 10.0

    def length(self, a: Pt, b: Pt) -> float:
        return math.hypot(b[0] - a[0], b[1] - a[1])


_TRANSLATE = re.compile(r"translate\(([0-9.eE+-]+)[ ,]+([0-9.eE+-]+)\)")
_STATEMENT = re.compile(r"1 cm = ([0-9.eE+-]+) (\S+)")


def _f(x: str) -> float:
    return float(str(x).replace("mm", ""))


def read_svg(source) -> Reading:
    """Parse an SVG written by :mod:`diagrams.svg` (a path, bytes or text)."""
    if isinstance(source, (str, Path)) and not str(source).lstrip().startswith("<"):
        data = Path(source).read_bytes()
    else:
        data = source.encode() if isinstance(source, str) else source
    root = ET.fromstring(data)
    H = float(root.get("viewBox").split()[3])
    title_el = root.find(f"{SVG_NS}title")
    title = title_el.text if title_el is not None else ""

    def p(x, y) -> Pt:
        return (_f(x), H - _f(y))

    statement = None
    for t in root.iter(f"{SVG_NS}text"):
        if t.get("id") == "scale-statement":
            statement = t.text
    if statement is None:
        raise DiagramError("no scale statement ('Scale 1 cm = ...') in the drawing")
    m = _STATEMENT.search(statement)
    unit = m.group(2).replace("²", "^2")
    if unit not in UNITS:
        raise DiagramError(f"unknown unit {unit!r} in the scale statement {statement!r}")
    per_cm = float(m.group(1)) * UNITS[unit][1]
    r = Reading(title, per_cm, statement)
    for c in root.iter(f"{SVG_NS}circle"):
        ident = c.get("id") or ""
        cls = (c.get("class") or "").split()
        if "-vertex-" in ident:
            r.vertices[untoken(ident.split("-vertex-", 1)[1])] = p(c.get("cx"), c.get("cy"))
        if "point" in cls:
            for tok in cls:
                if tok.startswith("at-"):
                    r.points[untoken(tok[3:])] = p(c.get("cx"), c.get("cy"))
    for g in root.iter(f"{SVG_NS}g"):
        cls = (g.get("class") or "").split()
        if not cls or cls[0] != "vector":
            continue
        frm = next(untoken(t[5:]) for t in cls if t.startswith("from-"))
        to = next(untoken(t[3:]) for t in cls if t.startswith("to-"))
        shaft = next(e for e in g.iter(f"{SVG_NS}line"))
        tail = p(shaft.get("x1"), shaft.get("y1"))
        head = next((e for e in g.iter(f"{SVG_NS}polygon")), None)
        if head is not None:
            x, y = head.get("points").split()[0].split(",")
            tip = p(x, y)
        else:
            tip = p(shaft.get("x2"), shaft.get("y2"))
        shift = (0.0, 0.0)
        for e in g.iter(f"{SVG_NS}g"):
            m = _TRANSLATE.fullmatch(e.get("transform") or "")
            if m:
                shift = (float(m.group(1)), -float(m.group(2)))
        r.vectors.append(DrawnVector(frm, to, cls[1], tail, tip, shift))
    return r


# ---------------------------------------------------------------- answers read off the drawings
@dataclass(frozen=True)
class Scaled:
    quantity: str
    unit: str
    scaled: float | None          # in `unit`, signed when the answer's mode is signed
    tutorial: float | None
    exact: float | None
    tolerance: float
    resolution: float             # what the ruler's resolution is worth, in `unit`
    how: str                      # which drawn lengths were used
    slip: bool
    signed: float | None = None   # the reading with its sign (ω, α: CCW positive)
    sense: str | None = None      # the tutorial's direction word, if any

    @property
    def diff_pct(self) -> float | None:
        if self.scaled is None or self.tutorial is None or self.scaled == 0:
            return None
        return (self.tutorial - self.scaled) / abs(self.scaled) * 100.0

    @property
    def within(self) -> bool | None:
        """Tutorial and drawing agree within the drawing tolerance (plus a ruler division)."""
        if self.scaled is None or self.tutorial is None:
            return None
        base = max(abs(self.tutorial), abs(self.scaled))
        return abs(self.tutorial - self.scaled) <= self.tolerance * base + self.resolution




def _unit_factor(unit: str) -> float:
    if unit in ("-", "1", ""):
        return 1.0
    return UNITS[unit][1]


def read_quantity(sol, readings: dict, q: Quantity, ruler: float | None = RULER_MM):
    """(SI value, SI resolution, how) of the quantity ``q`` (typed at load: an answer's
    ``q``) read off the drawings, or None."""
    if len(q.args) > 2:
        return None
    fn, P, Q = q.fn, q.args[0], (q.args[1] if len(q.args) > 1 else None)
    scene = sol.scene
    V = sol.vertex_of
    vel, acc, sp = (readings.get(k) for k in ("velocity", "acceleration", "space"))

    def dist(r, a, b):
        return r.si(r.length(a, b), ruler)

    def poly(r, a, b):
        if r is None or a not in r.vertices or b not in r.vertices:
            return None
        return dist(r, r.vertices[a], r.vertices[b])

    def vec(r, a, b):
        pa, pb = r.vertices[a], r.vertices[b]
        return (pb[0] - pa[0], pb[1] - pa[1])

    def space_len(a, b):
        if sp is None or a not in sp.points or b not in sp.points:
            return None
        return dist(sp, sp.points[a], sp.points[b])

    def space_vec(a, b):
        pa, pb = sp.points[a], sp.points[b]
        return (pb[0] - pa[0], pb[1] - pa[1])

    def res(r):
        return r.si(RULER_MM) / 2 if ruler else 0.0

    def step(diagram, op, pred):
        return next((s for s in sol.steps if s.diagram == diagram and s.op == op and pred(s)),
                    None)

    def centripetal(a, b):
        return step("acceleration", "centripetal", lambda s: {s.args[1], s.args[2]} == {a, b})

    def cross(u, v):
        return u[0] * v[1] - u[1] * v[0]

    def along(u, e):
        n = math.hypot(*e)
        return (u[0] * e[0] + u[1] * e[1]) / n

    if fn in ("v", "a"):
        r = vel if fn == "v" else acc
        if r is None:
            return None
        a, b = (V(Q), V(P)) if Q else (sol.pole, V(P))
        val = poly(r, a, b)
        return None if val is None else (val, res(r), f"{a}{b}")
    if fn in ("an", "at") and acc is not None:
        s = centripetal(P, Q)
        if s is None:
            return None
        if fn == "an":
            return (poly(acc, s.start, s.end), res(acc), f"{s.start}{s.end}")
        x = V(s.args[2])
        return (poly(acc, s.end, x), res(acc), f"{s.end}{x}")
    if fn == "cor" and acc is not None:
        s = step("acceleration", "coriolis", lambda s: s.args == (P,))
        return None if s is None else (poly(acc, s.start, s.end), res(acc), f"{s.start}{s.end}")
    if fn == "dist":
        val = space_len(P, Q)
        return None if val is None else (val, res(sp), f"{P}{Q} on the space diagram")
    if fn in ("omega", "alpha"):
        try:
            a, b = link_ends(scene, P)
        except KeyError:
            return None
        if fn == "omega":
            L = space_len(a, b)
            if not L or vel is None or V(a) not in vel.vertices or V(b) not in vel.vertices:
                return None
            rel = vec(vel, V(a), V(b))
            mag = poly(vel, V(a), V(b))
            sign = 1.0 if cross(space_vec(a, b), rel) >= 0 else -1.0
            # a ruler error in either length: d(m/L) = dm/L + m dL/L²
            return (sign * mag / L, res(vel) / L + mag * res(sp) / L ** 2,
                    f"{V(a)}{V(b)} ÷ {a}{b} (space diagram)")
        if acc is None:
            return None
        s = step("acceleration", "centripetal", lambda s: s.args[0] == P)
        if s is None:
            return None
        p_, x_ = s.args[1], s.args[2]      # tangential acceleration of x_ about p_
        L = space_len(p_, x_)
        if not L:
            return None
        x = V(x_)
        t = vec(acc, s.end, x)
        mag = poly(acc, s.end, x)
        sign = 1.0 if cross(space_vec(p_, x_), t) >= 0 else -1.0
        return (sign * mag / L, res(acc) / L + mag * res(sp) / L ** 2,
                f"{s.end}{x} ÷ {p_}{x_} (space diagram)")
    if fn in ("vs", "as"):
        r = vel if fn == "vs" else acc
        if r is None:
            return None
        if P in scene.model.slot:
            slot = scene.model.slot[P]
            if sp is None:
                return None
            # the pin and the lever's point under it share one mark on the space diagram
            e = space_vec(slot.line.origin, P if P in sp.points else slot.coincident)
            if fn == "vs":
                a, b = V(slot.coincident), V(P)
            else:
                s = step("acceleration", "join", lambda s: s.args == (P,))
                if s is None:
                    return None
                a, b = s.start, s.end
        elif P in scene.model.guide:
            e = scene.model.guide[P].line.direction
            a, b = sol.pole, V(P)
        else:
            return None
        if a not in r.vertices or b not in r.vertices:
            return None
        mag = poly(r, a, b)
        sign = 1.0 if along(vec(r, a, b), e) >= 0 else -1.0
        return (sign * mag, res(r), f"{a}{b}")
    if fn in ("dir_v", "dir_a"):
        r = vel if fn == "dir_v" else acc
        if r is None:
            return None
        u = vec(r, sol.pole, V(P))
        return (math.radians(math.degrees(math.atan2(u[1], u[0])) % 360.0),
                math.radians(0.5), f"direction of {sol.pole}{V(P)}")
    return None


def compare(sol, readings: dict, ruler: float | None = RULER_MM) -> list[Scaled]:
    """Every scene answer read off the drawings (``readings``: kind -> :class:`Reading`)."""
    out = []
    for ans in sol.scene.answers:
        got = read_quantity(sol, readings, ans.q, ruler)
        f = _unit_factor(ans.unit)
        if got is None or got[0] is None:
            out.append(Scaled(ans.quantity, ans.unit, None, ans.tutorial, ans.exact,
                              ans.tolerance, 0.0, "not a length on the drawings", ans.slip,
                              None, ans.sense))
            continue
        val, res, how = got
        signed = val / f
        val = abs(signed) if ans.mode == "abs" else signed
        out.append(Scaled(ans.quantity, ans.unit, val, ans.tutorial, ans.exact, ans.tolerance,
                          res / f, how, ans.slip, signed, ans.sense))
    return out


def readings_of(drawings) -> dict:
    """kind -> Reading for the finished drawings among ``drawings`` (model objects)."""
    from .svg import to_svg
    return {d.kind: read_svg(to_svg(d)) for d in drawings if d.stage is None}


def table(sol, readings: dict, ruler: float | None = RULER_MM) -> str:
    """The --measure report: every drawn vector's length, then the answers compared."""
    lines = []
    for kind in ("space", "velocity", "acceleration"):
        r = readings.get(kind)
        if r is None:
            continue
        lines.append(f"{kind} diagram: {r.statement}")
        if kind == "space":
            labels = list(r.points)
            for i, a in enumerate(labels):
                for b in labels[i + 1:]:
                    if any({a, b} == {ln.a, ln.b} for ln in sol.scene.model.links()):
                        mm = r.length(r.points[a], r.points[b])
                        lines.append(f"  {a + b:<12} {mm:8.1f} mm   {number(r.si(mm, ruler) * 1000):>10} mm")
            continue
        unit = "m/s" if kind == "velocity" else "m/s²"
        seen = set()
        for v in r.vectors:
            key = (v.frm, v.to)
            if key in seen:
                continue
            seen.add(key)
            name = vertex(v.frm) + vertex(v.to)              # p4_1p4 → p₄′p₄, as printed
            lines.append(f"  {name:<12} {v.mm:8.1f} mm   {number(r.si(v.mm, ruler)):>10} {unit}"
                         f"   {v.role}")
    rows = compare(sol, readings, ruler)
    names = {n for vx in sol.vertices.values() for n in vx}
    if rows:
        lines.append("")
        lines.append(f"answers scaled from the drawings (ruler {ruler or 0:g} mm)")
        lines.append(f"{'quantity':<16} {'unit':<9} {'scaled':>11} {'tutorial':>11} "
                     f"{'diff %':>7}  note")
        for row in rows:
            sc = "-" if row.scaled is None else number(row.scaled, 5)
            tut = "-" if row.tutorial is None else f"{row.tutorial:g}"
            diff = "" if row.diff_pct is None else f"{row.diff_pct:+.2f}"
            if row.scaled is None:
                note = row.how
            elif row.tutorial is None:
                note = row.how
            elif row.slip:
                note = "tutorial slip (not reproduced)" if not row.within else "SLIP REPRODUCED"
            else:
                note = ("within drawing tolerance" if row.within else "OUTSIDE tolerance") + \
                       f" ({row.how})"
            note = vertices_in(note, names)
            lines.append(f"{row.quantity:<16} {row.unit:<9} {sc:>11} {tut:>11} {diff:>7}  {note}")
    return "\n".join(lines) + "\n"
