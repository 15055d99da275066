"""Grade a student's drawn velocity or acceleration polygon against the construction.

The vectors a finished polygon must show are read off the construction's typed steps
(:class:`polygons.steps.Step`: ``op``, ``component``, ``link``, ``start``/``end``, ``lines``),
never from their text:

* every **known vector** (``kind`` vector or image): from its ``start`` to its ``end`` vertex —
  ω·r ⟂ the crank, the centripetal ω²·r ∥ the link towards its centre, the Coriolis 2ωv ⟂ the
  slot;
* every **line** of unknown length that an ``intersection`` ends, from the line's ``start`` to
  the vertex the intersection makes (⟂ a link, ∥ a guide or a slot), and a join of two vertices
  already placed (the sliding part p₂′p₂ ∥ the slot); the Coriolis offset line is a
  construction aid, not a vector.

The rules (:func:`grade_rules`, and the same rules in the interactive page's
``diagrams/assets/grade.js``, both reading the plain data of :func:`rules`):

* **The stated scale is the scale.**  A known vector is right when its direction (with its
  sense) is within the direction tolerance and its length within the length tolerance at the
  stated scale: 1 mark; one of the two right: ½; neither: 0.  A length off by the ratio of a
  typical slip is named as that slip (ω taken as N/10 for 2πN/60, rpm used as rad/s, a
  diameter for a radius, ω·r for ω²·r, ωv for 2ωv); otherwise the value is named wrong.
* **Error carried forward.**  A line is graded by its direction only, through the student's
  own start vertex (its length follows from the student's earlier vertices; a line has no
  sense, so an arrow either way along it is right): 1 or 0.  When the first known vector's
  length is off by a ratio r and later known vectors are off by the same r (every known
  acceleration vector scales with ω², every velocity with ω), they are consistent with it and
  keep their marks ("carried forward"): one slip costs one half mark.
* **Closure**: each intersection vertex against the crossing of its two lines drawn through
  the student's own start vertices (reported, not scored: a line's direction carries it).
* A value is compared as it is shown: a direction error shown equal to its tolerance
  ("0.9° (± 0.9°)") is inside it (:func:`within`).
* Messages describe the student's vector (its drawn direction, CCW from +x) and name
  vertices as the handout prints them (p₂′, :func:`polygons.notation.vertex`).

Tolerances come from the drawing-board emulation (:mod:`polygons.drawing_board`):

* length: the 95th percentile of the relative error of the quantity the vector carries (|v|,
  |a| of a point from the pole; ω of its link for a relative velocity; α for a tangential
  part; 2 × that of ω for ω²r and 2ωv), passed in as ``emulated`` (``polygons check``
  computes it); for anything else the case's stated drawing tolerance; never less than
  :data:`FLOOR_MM` of paper (two pencil marks and a rule reading);
* direction: the instruments' worst case — the protractor (±0.25°) on the line, the link as
  drawn on a 150 mm space diagram (two pencil marks ±0.25 mm over its drawn length) and the
  two pencil marks of the vector's own ends over its drawn length;
* closure: :data:`FLOOR_MM` plus each line's protractor error over its length, divided by the
  sine of the angle at which the lines cross.

An image vertex (similar triangles) is graded against the image of the student's own two
vertices of that link (the triangle's complex ratio, :func:`rules`), carried forward too.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .drawing_board import PENCIL_MM, PROTRACTOR_DEG, SPACE_MM
from .drawing_format import StudentDrawing
from .evaluate import Solution
from .notation import vertex, vertices_in
from .steps import Kind, Op, Step, points_back, tail_name

#: the smallest length tolerance on paper: two pencil marks (±0.25 mm in x and y) and a rule
#: reading (±0.25 mm)
FLOOR_MM = 2 * PENCIL_MM * math.sqrt(2) + PENCIL_MM
LINE_OPS = (Op.LINE_PERP, Op.LINE_ALONG, Op.LINE_GUIDE, Op.LINE_SLOT, Op.LINE_SLIDE)
#: two lengths whose ratio is within this of each other are "the same ratio" (carried forward)
SAME_RATIO = 0.02


@dataclass(frozen=True)
class Expected:
    """One vector the finished polygon must show."""
    start: str
    end: str
    vector: tuple[float, float]    # SI, polygon coordinates
    rule: str                      # '⟂ AB', '∥ AB, towards A', ...
    perp_to: str | None            # the link the rule is ⟂ to (for '∥ instead of ⟂')
    along: str | None              # the link / guide the rule is ∥ to
    step: Step
    coriolis: bool
    quantity: str | None           # the emulated quantity whose error its length carries
    factor: float                  # ... times that relative error


@dataclass(frozen=True)
class VectorMark:
    name: str                      # 'p4p2_1': the two vertex names in source form
    shown: str                     # 'p₄p₂′': as the handout prints them
    rule: str                      # '⟂ AB', '∥ BC, towards B', ...
    step: int | None               # the construction step that draws it
    line: bool                     # a line of unknown length (graded by direction only)
    drawn: bool
    direction_ok: bool
    sense_ok: bool
    length_ok: bool | None         # None for a line (its length is the student's own)
    angle_err_deg: float | None
    length_err_pct: float | None
    direction_tol_deg: float
    length_tol_pct: float | None
    mark: float                    # 1, 0.5 (line or length right, not both) or 0
    problem: str                   # '' when right
    hint: str
    note: str = ""                 # e.g. 'length carried forward from ab'


@dataclass(frozen=True)
class ClosureMark:
    vertex: str
    off_mm: float
    tol_mm: float
    ok: bool
    hint: str


@dataclass(frozen=True)
class DrawingGrade:
    diagram: str
    scale_text: str
    marks: tuple[VectorMark, ...]
    extras: tuple[VectorMark, ...]        # vectors drawn that the construction does not need
    closures: tuple[ClosureMark, ...]
    scale_ratio: float | None             # drawn / true of the known vectors when all are off
    unknown: tuple[str, ...]              # vertex names the construction does not have
    score: float                          # sum of marks
    out_of: int

    @property
    def ok(self) -> bool:
        return (all(m.mark == 1.0 and not m.note for m in self.marks)
                and all(c.ok for c in self.closures))


# ---------------------------------------------------------------- what must be drawn
def _unit(v):
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n) if n > 0 else (0.0, 0.0)


def expected_vectors(sol: Solution, diagram: str) -> list[Expected]:
    steps = [s for s in sol.steps if s.diagram == diagram]
    verts = sol.vertices[diagram]
    ends = {}
    for s in steps:
        if s.kind == Kind.INTERSECTION:
            for n in s.lines:
                ends[n] = s.end
    out = []
    pole = sol.vertex_of(next(iter(sol.scene.ground)))
    for s in steps:
        start = end = None
        if s.kind in (Kind.VECTOR, Kind.IMAGE) and s.start and s.end:
            start, end = s.start, s.end
        elif s.kind == Kind.LINE and s.op in LINE_OPS and s.number in ends and s.start:
            start, end = s.start, ends[s.number]
        if start is None or start == end or start not in verts or end not in verts:
            continue
        vec = (verts[end][0] - verts[start][0], verts[end][1] - verts[start][1])
        out.append(_rule(sol, s, start, end, vec, pole, diagram))
    return out


def _link_words(sol: Solution, s: Step) -> str:
    if s.link:
        return s.link
    if s.op in (Op.LINE_PERP, Op.LINE_ALONG) and len(s.args) >= 2:
        return "".join(s.args[:2])
    return ""


def _rule(sol, s: Step, start, end, vec, pole, diagram) -> Expected:
    link = _link_words(sol, s)
    q = "v" if diagram == "velocity" else "a"
    absolute = None
    if start == pole:      # from the pole: an absolute quantity
        label = next((lab for lab in sol.points if sol.vertex_of(lab) == end), None)
        absolute = f"{q}({label})" if label else None
    perp = along = None
    coriolis = False
    quantity, factor = absolute, 1.0
    if s.op in (Op.CRANK_VELOCITY, Op.LINE_PERP):
        rule, perp = f"⟂ {link}", link
        if diagram == "velocity":
            quantity = absolute or (f"omega({s.link})" if s.link else None)
        else:
            quantity = absolute or (f"alpha({s.link})" if s.link else None)
    elif s.op == Op.CRANK_TANGENTIAL:
        rule, perp, quantity = f"⟂ {link}", link, absolute or f"alpha({s.link})"
    elif s.op == Op.CENTRIPETAL:
        centre = s.args[1] if len(s.args) > 1 else ""
        rule, along = f"∥ {link}, towards {centre}", link
        if not absolute and s.link:          # ω²r: twice the relative error of ω
            quantity, factor = f"omega({s.link})", 2.0
    elif s.op in (Op.CORIOLIS, Op.CORIOLIS_DRIVE):
        rule, coriolis = "⟂ the slot, 2ω × v: the sliding velocity turned 90° in the sense " \
                         f"of ω_{s.link}", True
        perp = s.link
        quantity, factor = (f"omega({s.link})", 2.0) if s.link else (None, 1.0)
    elif s.op in (Op.LINE_ALONG, Op.LINE_SLIDE, Op.LINE_SLOT, Op.LINE_GUIDE, Op.SLIDER_DRIVE,
                  Op.SLIDE_DRIVE) or (s.op == Op.JOIN and s.component == "sliding"):
        what = {Op.LINE_GUIDE: "the guide", Op.SLIDER_DRIVE: "the guide",
                Op.LINE_SLOT: "the yoke's slot"}.get(s.op, f"the slot of {link}" if link
                                                     else "the slot")
        rule, along = f"∥ {what}", link or None
    elif s.kind == Kind.IMAGE:
        rule = f"by the image of {link}" if link else "by the image of its link"
    else:
        rule = "as constructed"
    return Expected(start, end, vec, rule, perp, along, s, coriolis, quantity, factor)


# ---------------------------------------------------------------- tolerances
DEFAULT_TOLERANCE = 0.02


def emulated_tolerances(sol: Solution, trials: int = 400) -> dict[str, float]:
    """{expression: relative tolerance}: the 95th percentile of a careful drawing's error from
    the drawing-board emulation (:mod:`polygons.drawing_board`: pencil and rule ±0.25 mm,
    protractor ±0.25°), at this case's crank angle; {} when the emulation does not cover the
    case (a slider driver, or a dyad it does not draw).  Fixed seed, so the grading is
    reproducible."""
    from . import drawing_board
    from .errors import UnsupportedError
    from .scene import Crank
    drv = sol.scene.driver
    if not isinstance(drv, Crank):
        return {}
    try:
        result = drawing_board.summary(drawing_board.emulate(sol.scene, [drv.angle],
                                                             trials=trials, seed=1))
    except UnsupportedError:  # a dyad the emulation does not draw: the stated ± % applies
        return {}
    out = {}
    for q, stats in result.items():        # keyed by the typed quantity (scene.Quantity)
        p95 = float(stats["p95"])
        if math.isfinite(p95) and p95 > 0:
            out[str(q)] = p95
    return out


def stated_tolerance(sol: Solution) -> float:
    """The case's stated drawing tolerance (``[source] drawing_tolerance``, default 2 %)."""
    from .units import parse_quantity
    text = sol.scene.source.get("drawing_tolerance")
    if text is None:
        return DEFAULT_TOLERANCE
    return parse_quantity(text, "fraction")


# ---------------------------------------------------------------- the rules' data
def _space_mm(sol: Solution) -> float:
    """Metres per mm of a 150 mm space diagram (the emulation's)."""
    pts = [p.position for p in sol.points.values()]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-12) / SPACE_MM


def _link_mm(sol: Solution, link: str | None, k_space: float) -> float | None:
    if not link or link not in sol.links:
        return None
    return sol.links[link].length / k_space


def _rel(sol: Solution, quantity, factor, emulated: dict, stated: float) -> float:
    given = getattr(sol.scene.driver, "link", None)
    if quantity in emulated:
        return emulated[quantity] * factor
    if given is not None and quantity == f"omega({given})":
        return 0.0          # the crank's ω is given: only the pencil and the rule
    return stated


RPM = 60.0 / (2.0 * math.pi)          # rad/s per rpm, inverted: an rpm figure used as rad/s


def slips(sol: Solution, e: Expected, diagram: str) -> list[tuple[float, str]]:
    """(drawn / true, words) of the typical slips that scale a known vector's length."""
    power = 1 if diagram == "velocity" else 2          # every vector ∝ ω (velocity), ω² (acc.)
    rpm = [((3.0 / math.pi) ** power, "ω taken as N/10 (or π as 3) instead of 2πN/60"),
           (RPM ** power, "ω in rev/min used as rad/s (ω = 2πN/60)"),
           ((1.0 / RPM) ** power, "ω converted to rad/s twice (2πN/60 applied to rad/s)")]
    out = []
    op = e.step.op
    if op == Op.CRANK_VELOCITY:
        out = rpm[:]
        out += [(2.0, "the diameter used for the radius (ω·d instead of ω·r)"),
                (0.5, "half the length used (a radius taken as the diameter's half)")]
    elif op == Op.CENTRIPETAL:
        out = rpm[:]
        out += [(2.0, "the diameter used for the radius (ω²·d)"),
                (0.5, "half the link length used")]
        lr = sol.links.get(e.step.link) if e.step.link else None
        if lr is not None and lr.omega:
            w = abs(lr.omega)
            out += [(1.0 / w, f"ω·r drawn instead of ω²·r (ω = {w:.4g} rad/s)"),
                    (w, "ω³·r: ω squared twice")]
    elif op in (Op.CORIOLIS, Op.CORIOLIS_DRIVE):
        out = rpm[:] + [(0.5, "ωv drawn instead of 2ωv"), (2.0, "4ωv drawn instead of 2ωv")]
    elif op == Op.CRANK_TANGENTIAL:
        out = [(2.0, "the diameter used for the radius (α·d)"), (0.5, "half the length used")]
    return [(r, w) for r, w in out if r > 0 and math.isfinite(r) and abs(r - 1) > 0.02]


def _shown(sol: Solution, e, pole: str, steps: dict) -> str:
    """A vector's printed name, as the drawing's legend and the narration print it: the
    way its arrow runs (a slot line's vector back to its anchor, :func:`points_back`) and
    its tail named by :func:`tail_name` (o₄b about the fixed O4, dc₂ about D, where the
    pole is another fixed point's vertex), each vertex as :func:`notation.vertex` spells
    it."""
    tail, head = e.start, e.end
    meet = None
    if e.step.kind == Kind.LINE:
        meet = next((s for s in steps.values() if s.kind == Kind.INTERSECTION
                     and e.step.number in s.lines), None)
        if points_back(sol.vertex_of, e.step, e.end):
            tail, head = e.end, e.start
    fixed = {g.lower() for g in sol.scene.ground}
    return vertex(tail_name(e.step, tail, pole, fixed, meet)) + vertex(head)


def rules(sol: Solution, diagram: str, emulated: dict | None = None,
          stated: float = 0.02) -> dict:
    """Everything the grading rules need, as plain JSON data (SI; the interactive page carries
    it and ``diagrams/assets/grade.js`` grades with it in the browser): the vectors to draw
    with their rules, tolerances and slips, the closures, the vertex names as printed."""
    emulated = emulated or {}
    k_space = _space_mm(sol)
    verts = sol.vertices[diagram]
    names = sol.printed_names(diagram)
    pole = sol.vertex_of(next(iter(sol.scene.ground)))
    steps = {s.number: s for s in sol.steps if s.diagram == diagram}

    def where(step: Step) -> str:
        return f"{step.diagram} step {step.number}: \u201c{vertices_in(step.reason, names)}\u201d"

    out = []
    for e in expected_vectors(sol, diagram):
        line = e.step.kind == Kind.LINE or e.step.op == Op.JOIN
        image = None
        if e.step.kind == Kind.IMAGE and len(e.step.args) >= 4:
            # an image vertex: start + z·(q − start), z the complex ratio of the link's
            # triangle (similar, turned with the link): carried forward from the student's
            # own start and q
            q = sol.vertex_of(e.step.args[2])
            base = (verts[q][0] - verts[e.start][0], verts[q][1] - verts[e.start][1]) \
                if q in verts else (0.0, 0.0)
            n2 = base[0] ** 2 + base[1] ** 2
            if n2 > 0 and q != e.start:
                z = ((e.vector[0] * base[0] + e.vector[1] * base[1]) / n2,
                     (e.vector[1] * base[0] - e.vector[0] * base[1]) / n2)
                image = {"base": q, "z": list(z)}
        out.append({"image": image,
            "start": e.start, "end": e.end, "vector": list(e.vector),
            "rule": vertices_in(e.rule, names), "perp_to": e.perp_to, "along": e.along,
            "step": e.step.number, "op": str(e.step.op), "line": line, "coriolis": e.coriolis,
            "centripetal": e.step.op == Op.CENTRIPETAL,
            "centre": (e.step.args[1] if e.step.op == Op.CENTRIPETAL and len(e.step.args) > 1
                       else None),
            # the name printed, as the handout prints it: from the pole, a centripetal
            # vector is named from its fixed centre's letter (dc₂ where the pole is a = d)
            "shown": _shown(sol, e, pole, steps),
            "rel": _rel(sol, e.quantity, e.factor, emulated, stated),
            "link_mm": _link_mm(sol, e.perp_to or e.along, k_space),
            "slips": [] if line else [[r, w] for r, w in slips(sol, e, diagram)],
            "where": where(e.step)})
    absolute = {}
    q = "v" if diagram == "velocity" else "a"
    for lab in sol.points:
        v = sol.vertex_of(lab)
        if v in verts and v != pole:
            absolute.setdefault(v, _rel(sol, f"{q}({lab})", 1.0, emulated, stated))
    closures = []
    for s in steps.values():
        if s.kind != Kind.INTERSECTION or len(s.lines) != 2:
            continue
        ln = [steps.get(n) for n in s.lines]
        if any(x is None or x.direction is None or x.at is None or x.start not in verts
               for x in ln):
            continue
        lines = []
        for x in ln:
            # the line's offset from its start vertex (the Coriolis offset line), SI, and the
            # known vector it is set off by (-2ωv): the student's own when drawn
            shift = [x.at[0] - verts[x.start][0], x.at[1] - verts[x.start][1]]
            by = None
            size = math.hypot(*shift)
            for e in out:
                if size > 0 and not e["line"]:
                    for sign in (1, -1):
                        if math.hypot(shift[0] - sign * e["vector"][0],
                                      shift[1] - sign * e["vector"][1]) <= 1e-9 * size:
                            by = [e["start"], e["end"], sign]
            lines.append({"number": x.number, "start": x.start,
                          "direction": list(x.direction), "shift": shift, "by": by})
        closures.append({"vertex": s.end, "where": where(s), "lines": lines})
    return {"diagram": diagram, "pole": pole, "ground": sorted(sol.scene.ground),
            "vertices": {n: list(p) for n, p in verts.items()},
            "names": {n: vertex(n) for n in verts},
            "expected": out, "absolute": absolute, "stated": stated, "closures": closures,
            "constants": {"floor_mm": FLOOR_MM, "pencil_mm": PENCIL_MM,
                          "protractor_deg": PROTRACTOR_DEG, "same_ratio": SAME_RATIO},
            "unit": "m/s" if diagram == "velocity" else "m/s²"}


# ---------------------------------------------------------------- the rules
def within(x: float, tol: float, digits: int) -> bool:
    """|x| ≤ tol as both are shown to ``digits`` decimals (a value shown equal to its limit
    is inside it)."""
    return float(f"{abs(x):.{digits}f}") <= float(f"{tol:.{digits}f}")


def _angle(u, v) -> float:
    """Signed angle from u to v, degrees in (-180, 180]."""
    return math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))


def _heading(v) -> float:
    """Direction of v, degrees CCW from +x in [0, 360)."""
    return math.degrees(math.atan2(v[1], v[0])) % 360.0


def direction_tol(R: dict, e: dict, drawn_mm: float) -> float:
    c = R["constants"]
    tol = c["protractor_deg"]
    if e["link_mm"]:
        tol += math.degrees(math.atan2(2 * c["pencil_mm"], e["link_mm"]))
    if drawn_mm > 0:
        tol += math.degrees(math.atan2(2 * c["pencil_mm"] * math.sqrt(2), drawn_mm))
    return tol


def drawing_scale(k: float, diagram: str) -> str:
    return f"1 mm = {k:.4g} {'m/s' if diagram == 'velocity' else 'm/s²'}"


def _name_map(R: dict, drawing: StudentDrawing) -> dict[str, str]:
    """Student vertex name -> construction vertex name (the pole by any fixed point's
    letter or 'o')."""
    out = {}
    for name in drawing.vertices:
        if name in R["vertices"]:
            out[name] = name
        elif name == "o" or name.upper() in R["ground"]:
            out[name] = R["pole"]
    return out


def grade(sol: Solution, drawing: StudentDrawing, emulated: dict | None = None,
          stated: float = 0.02) -> DrawingGrade:
    """Grade ``drawing`` (see :mod:`polygons.drawing_format`) against the construction.
    ``emulated``: {quantity: relative p95} (:func:`polygons.cli.check.emulated_tolerances`)."""
    return grade_rules(rules(sol, drawing.diagram, emulated, stated), drawing)


def grade_rules(R: dict, drawing: StudentDrawing) -> DrawingGrade:
    """The rules of the module's docstring on the data of :func:`rules` (the page's grade.js
    is the same function in JavaScript)."""
    k = drawing.scale                                # SI per mm
    names = _name_map(R, drawing)
    unknown = tuple(sorted(n for n in drawing.vertices if n not in names))
    P = {names[n]: p for n, p in drawing.vertices.items() if n in names}
    drawn = []
    for a, b in drawing.vectors:
        if a in names and b in names and (names[a], names[b]) not in drawn:
            drawn.append((names[a], names[b]))
    marks = [_mark(R, e, drawn, P, k) for e in R["expected"]]
    marks, ratio = _carry_forward(R, marks, k)
    need = {(e["start"], e["end"]) for e in R["expected"]}
    need |= {(b, a) for a, b in need}
    # a vector the construction does not draw (the resultant o₂p₄ ...) joins two of the
    # student's own vertices: carried forward, it is right whenever they are; not graded
    N = R["names"]
    extras = [VectorMark(a + b, N.get(a, a) + N.get(b, b), "joins two of your vertices", None,
                         False, True, True, True, None, None, None, 0.0, None, 1.0, "", "",
                         "not graded on its own")
              for a, b in drawn if (a, b) not in need and a != b]
    closures = _closures(R, P, k)
    score = sum(m.mark for m in marks)
    return DrawingGrade(R["diagram"], drawing.scale_text, tuple(marks), tuple(extras),
                        tuple(closures), ratio, unknown, score, len(marks))


def _fmt(x: float, d: int = 1) -> str:
    return f"{x:.{d}f}"


def _mark(R: dict, e: dict, drawn, P, k) -> VectorMark:
    N = R["names"]
    name = e["start"] + e["end"]
    shown = e.get("shown") or N.get(e["start"], e["start"]) + N.get(e["end"], e["end"])
    im = e.get("image")
    if im and im["base"] in P and e["start"] in P:
        # carried forward: the image of the student's own start → base, by the link's ratio
        b = (P[im["base"]][0] - P[e["start"]][0], P[im["base"]][1] - P[e["start"]][1])
        z = im["z"]
        ev = (z[0] * b[0] - z[1] * b[1], z[0] * b[1] + z[1] * b[0])        # mm
    else:
        ev = (e["vector"][0] / k, e["vector"][1] / k)
    true_mm = math.hypot(*ev)
    len_tol_mm = max(e["rel"] * true_mm, R["constants"]["floor_mm"])
    where, rule, line = e["where"], e["rule"], e["line"]
    back = (e["end"], e["start"]) in drawn
    base = dict(name=name, shown=shown, rule=rule, step=e["step"], line=line)
    if (e["start"], e["end"]) not in drawn:
        if back and line:
            # a line has no sense of its own: the arrow may run either way along it
            flipped = dict(e, start=e["end"], end=e["start"], image=None,
                           vector=[-e["vector"][0], -e["vector"][1]])
            return _mark(R, flipped, drawn, P, k)
        if back:
            return VectorMark(**base, drawn=True, direction_ok=False, sense_ok=False,
                              length_ok=None, angle_err_deg=180.0, length_err_pct=None,
                              direction_tol_deg=direction_tol(R, e, true_mm),
                              length_tol_pct=None, mark=0.0,
                              problem=f"the arrow runs {N[e['end']]}→{N[e['start']]}",
                              hint=f"{shown} runs from {N[e['start']]} to {N[e['end']]} "
                                   f"({where})")
        return VectorMark(**base, drawn=False, direction_ok=False, sense_ok=False,
                          length_ok=None, angle_err_deg=None, length_err_pct=None,
                          direction_tol_deg=0.0, length_tol_pct=None, mark=0.0,
                          problem="missing", hint=f"draw {shown} {rule} ({where})")
    s = (P[e["end"]][0] - P[e["start"]][0], P[e["end"]][1] - P[e["start"]][1])
    s_mm = math.hypot(*s)
    dtol = direction_tol(R, e, s_mm)
    if s_mm == 0 or true_mm == 0:
        return VectorMark(**base, drawn=True, direction_ok=False, sense_ok=False,
                          length_ok=False, angle_err_deg=None, length_err_pct=None,
                          direction_tol_deg=dtol, length_tol_pct=None, mark=0.0,
                          problem="drawn with no length", hint=f"{shown} must be {rule} ({where})")
    err = _angle(ev, s)
    if line and abs(err) > 90.0:        # a line: either sense along it
        err = err - 180.0 if err > 0 else err + 180.0
    dir_ok = within(err, dtol, 1)
    sense_ok = line or not within(abs(err) - 180.0, dtol, 1)
    drawn_at = f"drawn towards {_fmt(_heading(s))}°"
    right_at = f"{_fmt(_heading(ev))}°"
    problem = hint = ""
    if not sense_ok:
        if e["coriolis"]:
            problem = (f"the Coriolis component is reversed: {drawn_at}, 2ω × v points "
                       f"towards {right_at}")
        elif e["centripetal"]:
            problem = (f"the centripetal part points away from {e['centre']}: {drawn_at}, "
                       f"towards {e['centre']} is {right_at}")
        else:
            problem = f"points the wrong way: {drawn_at}, {rule} is towards {right_at}"
        hint = f"{shown} must be {rule} ({where})"
    elif not dir_ok:
        off90 = within(abs(err) - 90.0, dtol, 1)
        if off90 and e["perp_to"]:
            problem = f"drawn ∥ {e['perp_to']} instead of ⟂ {e['perp_to']}"
        elif off90 and e["along"]:
            problem = f"drawn ⟂ {e['along']} instead of ∥ ({rule})"
        else:
            problem = (f"{drawn_at}, {_fmt(abs(err))}° off {rule} (± {_fmt(dtol)}°)")
        hint = f"{shown} must be {rule} ({where})"
    line_ok = dir_ok and sense_ok
    if line:
        return VectorMark(**base, drawn=True, direction_ok=dir_ok, sense_ok=True,
                          length_ok=None, angle_err_deg=err, length_err_pct=None,
                          direction_tol_deg=dtol, length_tol_pct=None,
                          mark=1.0 if dir_ok else 0.0, problem=problem, hint=hint)
    len_err = (s_mm - true_mm) / true_mm * 100.0
    # inside when either way it is shown (mm in the problem, % in the report) says so
    len_ok = within(s_mm - true_mm, len_tol_mm, 1) or within(len_err, len_tol_mm / true_mm
                                                             * 100.0, 1)
    if not len_ok:
        ratio = s_mm / true_mm
        fits = sorted((abs(s_mm - r * true_mm), w) for r, w in e["slips"]
                      if within(s_mm - r * true_mm, len_tol_mm * max(1.0, r), 1))
        slip = fits[0][1] if fits else None
        what = (f"length {_fmt(s_mm)} mm, expected {_fmt(true_mm)} mm ± {_fmt(len_tol_mm)} "
                f"at {drawing_scale(k, R['diagram'])} ({ratio:.3g}×)")
        more = (f"the value is wrong, not the scale: likely {slip}" if slip else
                "recheck its value")
        problem = f"{problem}; {what}: {more}" if problem else f"{what}: {more}"
        if not hint:
            hint = f"{shown}: {more} ({where})"
    mark = 1.0 if (line_ok and len_ok) else (0.5 if (line_ok or len_ok) else 0.0)
    return VectorMark(**base, drawn=True, direction_ok=dir_ok, sense_ok=sense_ok,
                      length_ok=len_ok, angle_err_deg=err, length_err_pct=len_err,
                      direction_tol_deg=dtol, length_tol_pct=len_tol_mm / true_mm * 100.0,
                      mark=mark, problem=problem, hint=hint)


def _ratio(m: VectorMark) -> float:
    return 1.0 + m.length_err_pct / 100.0


def _carry_forward(R: dict, marks: list, k: float):
    """The first known vector of the wrong length sets a ratio r; a later known vector off by
    the same r (within :data:`SAME_RATIO`) is consistent with it and keeps its length mark.
    Returns the marks and r when at least two known vectors share it (else None)."""
    known = [m for m in marks if not m.line and m.length_ok is not None
             and m.length_err_pct is not None]
    first = next((m for m in known if m.length_ok is False), None)
    if first is None:
        return marks, None
    r = _ratio(first)
    out, shared = [], 0
    for m in marks:
        if (m is not first and not m.line and m.length_ok is False
                and m.length_err_pct is not None and r != 0
                and abs(_ratio(m) / r - 1.0) <= R["constants"]["same_ratio"]):
            shared += 1
            direction = m.direction_ok and m.sense_ok
            cut = m.problem.split("; length ")[0] if "; length " in m.problem else ""
            from dataclasses import replace
            m = replace(m, length_ok=True, mark=1.0 if direction else 0.5, problem=cut,
                        hint="" if direction else m.hint,
                        note=f"length carried forward from {first.shown} "
                             f"({r:.3g}× at the stated scale)")
        out.append(m)
    if shared and not any(w in first.problem for _, w in
                          next((e["slips"] for e in R["expected"]
                                if e["start"] + e["end"] == first.name), [])):
        i = out.index(first)
        from dataclasses import replace
        out[i] = replace(first, problem=first.problem + f" (every known vector is "
                         f"{r:.3g}× what the stated scale gives: was it drawn at another "
                         f"scale?)")
    return out, (r if shared else None)


def _closures(R: dict, P, k) -> list[ClosureMark]:
    """Each intersection vertex against the crossing of its two lines drawn through the
    student's own start vertices with the rules' directions."""
    out = []
    c = R["constants"]
    N = R["names"]
    for cl in R["closures"]:
        ln = cl["lines"]
        if any(x["start"] not in P for x in ln) or cl["vertex"] not in P:
            continue
        # the anchors: the student's start vertex, shifted by the line's true offset (the
        # Coriolis offset line); through a drawn vertex the shift is zero
        anchors = []
        for x in ln:
            by = x["by"]
            if by and by[0] in P and by[1] in P:       # the student's own vector (2ωv)
                sh = (by[2] * (P[by[1]][0] - P[by[0]][0]), by[2] * (P[by[1]][1] - P[by[0]][1]))
            else:
                sh = (x["shift"][0] / k, x["shift"][1] / k)
            anchors.append((P[x["start"]][0] + sh[0], P[x["start"]][1] + sh[1]))
        (a1, d1), (a2, d2) = (anchors[0], ln[0]["direction"]), (anchors[1], ln[1]["direction"])
        den = d1[0] * d2[1] - d1[1] * d2[0]
        if abs(den) < 1e-9:
            continue
        t = ((a2[0] - a1[0]) * d2[1] - (a2[1] - a1[1]) * d2[0]) / den
        q = (a1[0] + t * d1[0], a1[1] + t * d1[1])
        v = P[cl["vertex"]]
        off = math.hypot(v[0] - q[0], v[1] - q[1])
        lengths = [math.hypot(v[0] - a[0], v[1] - a[1]) for a in anchors]
        # the vertex's own pencil mark, plus each line's protractor error over its length,
        # magnified by the crossing angle
        tol = (c["floor_mm"] + max(lengths) * math.radians(c["protractor_deg"]) * 2) / abs(den)
        ok = within(off, tol, 2)
        hint = "" if ok else (f"{N[cl['vertex']]} is {off:.2f} mm from where the lines of "
                              f"steps {ln[0]['number']} and {ln[1]['number']} meet "
                              f"({cl['where']})")
        out.append(ClosureMark(cl["vertex"], off, tol, ok, hint))
    return out


__all__ = ["grade", "grade_rules", "rules", "slips", "within", "expected_vectors",
           "DrawingGrade", "VectorMark", "ClosureMark", "Expected", "FLOOR_MM"]
