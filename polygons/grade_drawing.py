"""Grade a student's drawn velocity or acceleration polygon against the construction.

The vectors a finished polygon must show are read off the construction's typed steps
(:class:`polygons.steps.Step`: ``op``, ``component``, ``link``, ``start``/``end``, ``lines``),
never from their text:

* every known vector (``kind`` vector or image): from its ``start`` to its ``end`` vertex —
  ω·r ⟂ the crank, the centripetal ω²·r ∥ the link towards its centre, the Coriolis 2ωv ⟂ the
  slot, the sliding part ∥ the slot;
* every line of unknown length that two lines' ``intersection`` ends: from the line's
  ``start`` to the vertex the intersection makes (⟂ a link, ∥ a guide or a slot); the
  Coriolis offset line is a construction aid, not a vector.

For each of them the student's arrow is checked for its **direction** by the step's rule,
its **sense** (a reversed Coriolis component is named as such), and its **length** at the
student's stated scale; each **intersection** is checked for closure (the vertex lies where
its two lines, drawn through the student's own start vertices by their rules, meet).  A
consistent length error in every vector is reported as a **wrong scale**.

Tolerances come from the drawing-board emulation (:mod:`polygons.drawing_board`):

* length: the 95th percentile of the relative error of the quantity the vector carries (|v|,
  |a| of a point from the pole; ω of its link for a relative velocity; α for a tangential
  part; 2 × that of ω for ω²r and 2ωv), passed in as ``emulated`` (``polygons check``
  computes it); for anything else the case's stated drawing tolerance; never less than
  :data:`FLOOR_MM` of paper (two pencil marks and a rule reading);
* direction: the instruments' worst case — the protractor (±0.25°) on the line, the link as
  drawn on a 150 mm space diagram (two pencil marks ±0.25 mm over its drawn length) and the
  two pencil marks of the vector's own ends over its drawn length;
* closure: :data:`FLOOR_MM` divided by the sine of the angle at which the lines cross.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .drawing_board import PENCIL_MM, PROTRACTOR_DEG, SPACE_MM
from .drawing_format import StudentDrawing
from .evaluate import Solution
from .steps import Kind, Op, Step

#: the smallest length tolerance on paper: two pencil marks (±0.25 mm in x and y) and a rule
#: reading (±0.25 mm)
FLOOR_MM = 2 * PENCIL_MM * math.sqrt(2) + PENCIL_MM
LINE_OPS = (Op.LINE_PERP, Op.LINE_ALONG, Op.LINE_GUIDE, Op.LINE_SLOT, Op.LINE_SLIDE)


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
    name: str                      # 'bc'
    expected: Expected | None
    drawn: bool
    direction_ok: bool
    sense_ok: bool
    length_ok: bool
    angle_err_deg: float | None
    length_err_pct: float | None
    direction_tol_deg: float
    length_tol_pct: float
    mark: float                    # 1, 0.5 (direction right, length off) or 0
    problem: str                   # '' when right
    hint: str


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
    scale_ratio: float | None             # drawn / true lengths when every length is off alike
    unknown: tuple[str, ...]              # vertex names the construction does not have
    score: float                          # sum of marks
    out_of: int

    @property
    def ok(self) -> bool:
        return (all(m.mark == 1.0 for m in self.marks) and all(c.ok for c in self.closures)
                and self.scale_ratio is None)


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


# ---------------------------------------------------------------- grading
def _angle(u, v) -> float:
    """Signed angle from u to v, degrees in (-180, 180]."""
    return math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))


def _space_mm(sol: Solution) -> float:
    """Metres per mm of a 150 mm space diagram (the emulation's)."""
    pts = [p.position for p in sol.points.values()]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-12) / SPACE_MM


def _link_mm(sol: Solution, link: str | None, k_space: float) -> float | None:
    if not link or link not in sol.links:
        return None
    return sol.links[link].length / k_space


def direction_tol(sol: Solution, e: Expected, drawn_mm: float, k_space: float) -> float:
    tol = PROTRACTOR_DEG
    lm = _link_mm(sol, e.perp_to or e.along, k_space)
    if lm:
        tol += math.degrees(math.atan2(2 * PENCIL_MM, lm))
    if drawn_mm > 0:
        tol += math.degrees(math.atan2(2 * PENCIL_MM * math.sqrt(2), drawn_mm))
    return tol


def _name_map(sol: Solution, drawing: StudentDrawing, diagram: str) -> dict[str, str]:
    """Student vertex name -> construction vertex name (the pole by any fixed point's
    letter or 'o')."""
    verts = sol.vertices[diagram]
    pole = sol.vertex_of(next(iter(sol.scene.ground)))
    out = {}
    for name in drawing.vertices:
        if name in verts:
            out[name] = name
        elif name == "o" or name.upper() in sol.scene.ground:
            out[name] = pole
    return out


def grade(sol: Solution, drawing: StudentDrawing, emulated: dict | None = None,
          stated: float = 0.02) -> DrawingGrade:
    """Grade ``drawing`` (see :mod:`polygons.drawing_format`) against the construction.
    ``emulated``: {quantity: relative p95} (:func:`polygons.cli.check.emulated_tolerances`)."""
    emulated = emulated or {}
    diagram = drawing.diagram
    k = drawing.scale                                # SI per mm
    k_space = _space_mm(sol)
    names = _name_map(sol, drawing, diagram)
    unknown = tuple(sorted(n for n in drawing.vertices if n not in names))
    P = {names[n]: p for n, p in drawing.vertices.items() if n in names}
    drawn = {}
    for a, b in drawing.vectors:
        if a in names and b in names:
            drawn.setdefault((names[a], names[b]), (a, b))
    expected = expected_vectors(sol, diagram)
    marks = []
    for e in expected:
        marks.append(_mark(sol, e, drawn, P, k, k_space, emulated, stated, diagram))
    need = {(e.start, e.end) for e in expected} | {(e.end, e.start) for e in expected}
    extras = []
    verts = sol.vertices[diagram]
    for (a, b), (sa, sb) in drawn.items():
        if (a, b) in need or a == b:
            continue
        vec = (verts[b][0] - verts[a][0], verts[b][1] - verts[a][1])
        step = next((s for s in sol.steps if s.diagram == diagram and s.end == b), None)
        if step is None or math.hypot(*vec) == 0:
            continue
        pole = sol.vertex_of(next(iter(sol.scene.ground)))
        label = next((lab for lab in sol.points if sol.vertex_of(lab) == b), None)
        q = ("v" if diagram == "velocity" else "a") + f"({label})" if (
            a == pole and label) else None
        e = Expected(a, b, vec, "the resultant" if a == pole else "by the polygon", None, None,
                     step, False, q, 1.0)
        extras.append(_mark(sol, e, drawn, P, k, k_space, emulated, stated, diagram))
    closures = _closures(sol, diagram, expected, P, k)
    ratio = _wrong_scale(marks)
    if ratio is not None:
        marks = [_scale_hint(m, ratio, k, diagram) for m in marks]
    score = sum(m.mark for m in marks)
    return DrawingGrade(diagram, drawing.scale_text, tuple(marks), tuple(extras),
                        tuple(closures), ratio, unknown, score, len(marks))


def _where(sol: Solution, step: Step) -> str:
    return f"{step.diagram} step {step.number}: \u201c{step.reason}\u201d"


def _mark(sol, e: Expected, drawn, P, k, k_space, emulated, stated, diagram) -> VectorMark:
    name = f"{e.start}{e.end}"
    true_mm = math.hypot(*e.vector) / k
    given = getattr(sol.scene.driver, "link", None)
    if e.quantity in emulated:
        rel = emulated[e.quantity] * e.factor
    elif given is not None and e.quantity == f"omega({given})":
        rel = 0.0           # the crank's ω is given: only the pencil and the rule
    else:
        rel = stated
    len_tol_mm = max(rel * true_mm, FLOOR_MM)
    where = _where(sol, e.step)
    if (e.start, e.end) not in drawn:
        if (e.end, e.start) in drawn and e.step.kind == Kind.LINE:
            # a line has no sense of its own: the arrow may run either way along it
            from dataclasses import replace
            back = replace(e, start=e.end, end=e.start, vector=(-e.vector[0], -e.vector[1]))
            return _mark(sol, back, drawn, P, k, k_space, emulated, stated, diagram)
        if (e.end, e.start) in drawn:
            return VectorMark(name, e, True, True, False, True, 180.0, None,
                              direction_tol(sol, e, true_mm, k_space), 0.0, 0.0,
                              f"the arrow runs {e.end}→{e.start}",
                              f"{name} runs from {e.start} to {e.end} ({where})")
        return VectorMark(name, e, False, False, False, False, None, None, 0.0, 0.0, 0.0,
                          "missing", f"draw {name} {e.rule} ({where})")
    if e.start not in P or e.end not in P:       # pragma: no cover - drawn implies placed
        return VectorMark(name, e, False, False, False, False, None, None, 0.0, 0.0, 0.0,
                          "missing", f"draw {name} {e.rule} ({where})")
    s = (P[e.end][0] - P[e.start][0], P[e.end][1] - P[e.start][1])
    s_mm = math.hypot(*s)
    dtol = direction_tol(sol, e, s_mm, k_space)
    len_err = (s_mm - true_mm) / true_mm * 100.0 if true_mm > 0 else None
    len_ok = abs(s_mm - true_mm) <= len_tol_mm
    tol_pct = len_tol_mm / true_mm * 100.0 if true_mm > 0 else math.inf
    if s_mm == 0:
        return VectorMark(name, e, True, False, False, False, None, len_err, dtol, tol_pct,
                          0.0, "drawn with no length", f"{name} must be {e.rule} ({where})")
    err = _angle(e.vector, s)
    dir_ok = abs(err) <= dtol
    sense_ok = abs(err) < 180.0 - dtol
    problem = hint = ""
    if not sense_ok:
        if e.coriolis:
            problem = "the Coriolis component is reversed"
            hint = f"{name} must be {e.rule} ({where})"
        else:
            problem = "points the wrong way"
            hint = f"{name} must point the other way: {e.rule} ({where})"
    elif not dir_ok:
        off90 = abs(abs(err) - 90.0) <= dtol
        if off90 and e.perp_to:
            problem = f"drawn ∥ {e.perp_to} instead of ⟂ {e.perp_to}"
        elif off90 and e.along:
            problem = f"drawn ⟂ instead of ∥ ({e.rule})"
        else:
            problem = f"direction off by {abs(err):.1f}° (± {dtol:.1f}°)"
        hint = f"{name} must be {e.rule} ({where})"
    elif not len_ok:
        problem = (f"length {s_mm:.1f} mm, expected {true_mm:.1f} mm ± {len_tol_mm:.1f} "
                   f"at {drawing_scale(k, diagram)}")
        hint = f"{name}: recheck its length ({where})"
    mark = 1.0 if (dir_ok and len_ok) else (0.5 if dir_ok else 0.0)
    return VectorMark(name, e, True, dir_ok, sense_ok, len_ok, err, len_err, dtol, tol_pct,
                      mark, problem, hint)


def drawing_scale(k: float, diagram: str) -> str:
    return f"1 mm = {k:.4g} {'m/s' if diagram == 'velocity' else 'm/s²'}"


def _closures(sol, diagram, expected, P, k) -> list[ClosureMark]:
    """Each intersection vertex against the crossing of its two lines drawn through the
    student's own start vertices with the rules' directions."""
    out = []
    for s in sol.steps:
        if s.diagram != diagram or s.kind != Kind.INTERSECTION or len(s.lines) != 2:
            continue
        ln = [next((x for x in sol.steps if x.diagram == diagram and x.number == n), None)
              for n in s.lines]
        if any(x is None or x.direction is None or x.at is None for x in ln):
            continue
        # the anchors: the student's start vertex for a line through a drawn vertex; for an
        # offset line (Coriolis), the student's start vertex shifted by the true offset
        anchors = []
        for x in ln:
            if x.start not in P:
                break
            shift = (x.at[0] - sol.vertices[diagram][x.start][0],
                     x.at[1] - sol.vertices[diagram][x.start][1])
            anchors.append((P[x.start][0] + shift[0] / k, P[x.start][1] + shift[1] / k))
        if len(anchors) != 2 or s.end not in P:
            continue
        (a1, d1), (a2, d2) = (anchors[0], ln[0].direction), (anchors[1], ln[1].direction)
        den = d1[0] * d2[1] - d1[1] * d2[0]
        if abs(den) < 1e-9:
            continue
        t = ((a2[0] - a1[0]) * d2[1] - (a2[1] - a1[1]) * d2[0]) / den
        q = (a1[0] + t * d1[0], a1[1] + t * d1[1])
        off = math.hypot(P[s.end][0] - q[0], P[s.end][1] - q[1])
        lengths = [math.hypot(P[s.end][0] - a[0], P[s.end][1] - a[1]) for a in anchors]
        # the vertex's own pencil mark, plus each line's protractor error over its length,
        # magnified by the crossing angle
        tol = (FLOOR_MM + max(lengths) * math.radians(PROTRACTOR_DEG) * 2) / abs(den)
        ok = off <= tol
        hint = "" if ok else (f"{s.end} is {off:.1f} mm from where the lines of steps "
                              f"{s.lines[0]} and {s.lines[1]} meet ({_where(sol, s)})")
        out.append(ClosureMark(s.end, off, tol, ok, hint))
    return out


def _wrong_scale(marks) -> float | None:
    """drawn/true when every drawn vector has its direction right, its length off, and all
    by one ratio (within 5 %): the polygon is right but drawn at another scale."""
    rs = [1 + m.length_err_pct / 100.0 for m in marks
          if m.drawn and m.direction_ok and m.length_err_pct is not None]
    if len(rs) < 2 or not all(m.drawn and m.direction_ok and not m.length_ok
                              for m in marks if m.expected is not None and m.drawn):
        return None
    rs.sort()
    mid = rs[len(rs) // 2]
    if mid <= 0 or any(abs(r / mid - 1) > 0.05 for r in rs):
        return None
    return mid


def _scale_hint(m: VectorMark, ratio: float, k: float, diagram: str) -> VectorMark:
    from dataclasses import replace
    if not m.drawn or m.length_ok:
        return m
    true_mm = math.hypot(*m.expected.vector) / k
    return replace(m, problem=f"wrong scale: every length is {ratio:.3g}× what the stated "
                              f"scale gives",
                   hint=f"draw at the stated scale ({drawing_scale(k, diagram)}): {m.name} is "
                        f"{true_mm:.1f} mm long")


__all__ = ["grade", "expected_vectors", "DrawingGrade", "VectorMark", "ClosureMark",
           "Expected", "FLOOR_MM"]
