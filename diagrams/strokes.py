"""The strokes of a velocity or acceleration polygon, read from the step records.

:func:`construction` turns the evaluated steps of one diagram into :class:`Stroke` records
(arrows, construction lines, the Coriolis offset, image sides) with their component kind;
:func:`asked` finds, for each of the scene's asked ``[[answers]]``, the stroke or measure that
shows it.  No layout and no svgwrite here (:mod:`diagrams.polygon` lays the strokes out).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from polygons.errors import PolygonsError
from polygons.evaluate import Solution
from polygons.plan import Step
from polygons.steps import points_back

from .components import carried_by, component_of
from .notation import slot_names, vector

Pt = tuple[float, float]
UNIT_SI = {"velocity": "m/s", "acceleration": "m/s²"}
DRAWABLE = ("vector", "image", "line", "intersection")


@dataclass(frozen=True)
class Stroke:
    """One thing drawn on the polygon, in polygon coordinates (SI)."""
    step: int           # the step that draws it
    kind: str           # 'arrow' | 'line' | 'offset' | 'side'
    role: str           # arrows: 'known' 'resolved' 'result' 'coriolis' 'join' 'image'
    a: Pt               # arrow tail / line anchor / segment start
    b: Pt               # arrow tip / line direction / segment end
    frm: str = ""
    to: str = ""
    label: str = ""     # lines: what the step draws; arrows: the quantity
    title: str = ""
    component: str = "construction"   # diagrams.components kind
    of: int = 0         # the step whose quantity it is (a resolved arrow: its line's step)


@dataclass(frozen=True)
class Construction:
    diagram: str
    pole: str
    pole_label: str
    steps: tuple[Step, ...]          # the drawable steps, in order (stage k = steps[k-1])
    measures: tuple[Step, ...]
    strokes: tuple[Stroke, ...]
    vertices: dict                   # name -> SI polygon coordinates
    born: dict                       # vertex -> step number that creates it (pole: 0)
    asked: tuple = ()                # Asked: the scene's answers this diagram shows


def construction(sol: Solution, diagram: str) -> Construction:
    """The strokes of ``diagram`` from the solution's evaluated steps (no recomputation)."""
    steps = [s for s in sol.steps if s.diagram == diagram]
    vx = dict(sol.vertices[diagram])
    pole = sol.pole
    aliases = [pole] + [g.lower() for g in sol.scene.ground if g.lower() != pole]
    born = {pole: 0}
    strokes: list[Stroke] = []
    lines: dict[int, Step] = {}
    measures = []
    for s in steps:
        comp = component_of(s)
        if s.kind in ("vector", "image"):
            role = {"coriolis": "coriolis", "join": "join"}.get(
                s.op, "image" if s.kind == "image" else "known")
            label = _image_quantity(sol, s) if s.kind == "image" else s.quantity
            if s.op == "coriolis":
                label = "2ωv"
            strokes.append(Stroke(s.number, "arrow", role, s.at, s.point, s.start, s.end,
                                  label, f"{vector(s.start, s.end)}: {label}", comp, s.number))
            q = sol.vertex_of(s.args[2]) if s.kind == "image" else None
            # a flat image (D on AB produced) has no side of its own: it lies on the vectors
            if q is not None and not _in_line(s.at, s.point, vx[q]):
                strokes.append(Stroke(s.number, "side", "image-side", vx[q], s.point, q, s.end,
                                      component="image"))
            born.setdefault(s.end, s.number)
        elif s.kind == "line":
            lines[s.number] = s
            strokes.append(Stroke(s.number, "line", "construction", s.at, s.direction,
                                  s.start or "", "", slot_names(s.draws, sol.scene), s.reason))
            if s.op == "coriolis_offset_line" and s.start is not None:
                # the step back from the pin's vertex: anchor + 2ωv = the pin's vertex
                strokes.append(Stroke(s.number, "offset", "offset", s.at, vx[s.start],
                                      "", s.start, "2ωv", "Coriolis offset 2ωv", "coriolis"))
        elif s.kind == "intersection":
            born.setdefault(s.end, s.number)
            made = set()
            for n in s.lines:
                ln = lines[n]
                if ln.op == "coriolis_offset_line" or ln.start is None:
                    continue
                if _points_back(sol, ln, s.end):   # e.g. the slot line: pin relative to
                    tail, tip, frm, to = s.point, ln.at, s.end, ln.start   # the lever point
                else:
                    tail, tip, frm, to = ln.at, s.point, ln.start, s.end
                strokes.append(Stroke(s.number, "arrow", "resolved", tail, tip, frm, to,
                                      ln.quantity, f"{vector(frm, to)}: {ln.quantity}",
                                      carried_by(ln), ln.number))
                made.add((frm, to))
            if (pole, s.end) not in made:
                strokes.append(Stroke(s.number, "arrow", "result", vx[pole], s.point, pole,
                                      s.end, s.quantity, f"{vector(pole, s.end)}: {s.quantity}",
                                      "resultant", s.number))
        elif s.kind == "measure":
            measures.append(s)
    strokes += _asked(sol, diagram, strokes, born, vx)
    drawable = tuple(s for s in steps if s.kind in DRAWABLE)
    return Construction(diagram, pole, " = ".join(aliases), drawable, tuple(measures),
                        tuple(strokes), vx, born, asked(sol, diagram, steps, strokes))


def _in_line(a: Pt, b: Pt, c: Pt) -> bool:
    """True when a, b, c lie on one line (to 1e-9 of the sides' lengths)."""
    u = (b[0] - a[0], b[1] - a[1])
    v = (c[0] - a[0], c[1] - a[1])
    return abs(u[0] * v[1] - u[1] * v[0]) <= 1e-9 * (math.hypot(*u) * math.hypot(*v) or 1.0)


def _image_quantity(sol: Solution, s: Step) -> str:
    """The quantity of an image step's arrow start → end: '(v_D)_A' (not the absolute 'v_D')."""
    sym = "v" if s.diagram == "velocity" else "a"
    x = s.args[-1]
    ref = next((lab for lab in s.args[1:-1] if sol.vertex_of(lab) == s.start), None)
    if ref is None or sol.vertex_of(ref) == sol.pole:
        return f"{sym}_{x}"
    return f"({sym}_{x})_{ref}"


def read_answer(ans) -> tuple[str, tuple[str, ...]] | None:
    """An answer's quantity as (function, labels), typed at load (``Answer.q``): 'v(B,A)' →
    ('v', ('B', 'A')); None when it has none."""
    q = getattr(ans, "q", None)
    return None if q is None else (q.fn, tuple(q.args))


def asked_quantities(sol: Solution, diagram: str) -> list[tuple[str, ...]]:
    """The scene's asked absolute/relative vectors of this diagram as point labels:
    [('D',), ('B', 'A')] — 'v(D)' / 'a(D)' (or its direction 'dir_v(D)') from the pole,
    'v(B,A)' B relative to A.  Components, sliding and Coriolis: see :func:`asked`."""
    fns = ("v", "dir_v") if diagram == "velocity" else ("a", "dir_a")
    out = []
    for ans in sol.scene.answers:
        read = read_answer(ans)
        if read is None or read[0] not in fns:
            continue
        args = read[1]
        if all(a in sol.points for a in args) and args not in out:
            out.append(args)
    return out


def _asked(sol: Solution, diagram: str, strokes, born, vx) -> list[Stroke]:
    """Arrows for the asked quantities the construction has not drawn yet (od for v_D)."""
    sym = "v" if diagram == "velocity" else "a"
    drawn = {(st.frm, st.to) for st in strokes if st.kind == "arrow"}
    out = []
    for args in asked_quantities(sol, diagram):
        x = sol.vertex_of(args[0])
        y = sol.pole if len(args) == 1 else sol.vertex_of(args[1])
        if x == y or (y, x) in drawn or x not in vx or y not in vx or x not in born:
            continue
        step = max(born[x], born.get(y, 0))
        if y == sol.pole:
            label, role, comp = f"{sym}_{args[0]}", "result", "resultant"
        else:
            label, role = f"({sym}_{args[0]})_{args[1]}", "join"
            comp = "relative" if diagram == "velocity" else "resultant"
        out.append(Stroke(step, "arrow", role, vx[y], vx[x], y, x, label,
                          f"{vector(y, x)}: {label} (asked)", comp))
        drawn.add((y, x))
    return out


def _points_back(sol: Solution, line: Step, end: str) -> bool:
    """:func:`polygons.steps.points_back` (the one rule, the grader's too)."""
    return points_back(sol.vertex_of, line, end)


@dataclass(frozen=True)
class Asked:
    """One of the scene's ``[[answers]]`` shown on this diagram: the answer's ``quantity``
    text, the arrow that shows it (``vector``: (frm, to) polygon vertices, or None) and the
    measure step that prints it (``measure``: step number, or None)."""
    quantity: str
    vector: tuple[str, str] | None
    measure: int | None
    zero: str = ""       # asked but zero, so nothing drawn: its name ('(a_B)_A^t')


_MEASURES = {"omega": ("omega",), "alpha": ("alpha",),
             "vs": ("slide_velocity", "slider_velocity"),
             "as": ("slide_acceleration", "slider_acceleration")}


def asked(sol: Solution, diagram: str, steps, strokes) -> tuple[Asked, ...]:
    """Where each asked quantity of ``diagram`` is on the drawing: absolute and relative
    vectors, centripetal and tangential components, sliding, Coriolis (its arrow), ω and α
    (the measure that prints them and the vector they are read from)."""
    vel = diagram == "velocity"
    by_step = {s.number: s for s in steps}
    arrows = [st for st in strokes if st.kind == "arrow"]
    V = sol.vertex_of
    pole = sol.pole
    out = []

    def step_of(st):
        return by_step.get(st.of)

    def between(x, y):
        return next(((st.frm, st.to) for st in arrows if {st.frm, st.to} == {x, y}), None)

    for ans in sol.scene.answers:
        read = read_answer(ans)
        if read is None:
            continue
        fn, args = read
        if any(a not in sol.points and a not in sol.links for a in args):
            continue
        vec = meas = None
        if fn in (("v", "dir_v") if vel else ("a", "dir_a")):
            x = V(args[0])
            vec = between(x, pole if len(args) == 1 else V(args[1]))
        elif fn in ("an", "at") and not vel:
            want = {V(args[0]), V(args[1])}
            comp = "centripetal" if fn == "an" else "tangential"
            for st in arrows:
                s = step_of(st)
                if st.component == comp and s is not None and len(s.args) >= 2 \
                        and {V(a) for a in s.args[-2:] if a in sol.points} == want:
                    vec = (st.frm, st.to)
                    break
            if vec is None and _zero(sol, ans.quantity):    # no vector: say so
                out.append(Asked(ans.quantity, None, None,
                                 f"(a_{args[0]})_{args[1]}^{fn[1]}"))
                continue
        elif fn == "cor" and not vel:
            vec = next(((st.frm, st.to) for st in arrows if st.component == "coriolis"
                        and step_of(st) is not None and args[0] in step_of(st).args), None)
        elif fn in _MEASURES and (fn in ("omega", "vs")) == vel:
            m = next((s for s in steps if s.kind == "measure" and s.op in _MEASURES[fn]
                      and all(a in s.args for a in args)), None)
            if m is None and fn in ("omega", "alpha"):     # the driver's own rate: its vector
                op = "crank_velocity" if vel else "crank_tangential"
                vec = next(((st.frm, st.to) for st in arrows if step_of(st) is not None
                            and step_of(st).link == args[0] and step_of(st).op == op), None)
                if vec is not None:
                    out.append(Asked(ans.quantity, vec, None))
                continue
            if m is None:
                continue
            meas = m.number
            if fn in ("omega", "alpha"):
                comp = "relative" if vel else "tangential"
                vec = next(((st.frm, st.to) for st in arrows if step_of(st) is not None
                            and step_of(st).link == args[0] and st.component == comp), None)
            elif m.op.startswith("slider"):      # along a fixed guide: the absolute vector
                vec = between(V(args[0]), pole)
            else:
                st = sliding_arrow(strokes, steps, V(args[0]), args[1:])
                vec = None if st is None else (st.frm, st.to)
        else:
            continue
        if vec is not None or meas is not None:
            out.append(Asked(ans.quantity, vec, meas))
    return tuple(out)


def _zero(sol: Solution, expr: str) -> bool:
    """True when the asked quantity ``expr`` is zero in ``sol`` (the rounding noise of the
    construction aside: :func:`polygons.steps.noise_floor` of the polygon's vectors)."""
    from polygons.quantities import quantity
    from polygons.steps import noise_floor
    try:
        value = quantity(sol, expr)
    except PolygonsError:
        return False
    sizes = [math.hypot(*p.acceleration) for p in sol.points.values()
             if p.acceleration is not None]
    return abs(value) <= noise_floor(sizes)


def sliding_arrow(strokes, steps, x: str, under=()) -> Stroke | None:
    """The sliding vector at vertex ``x``; of a pin in two slots (crossing slots), the one
    relative to the lever point ``under[0]`` (its step names it)."""
    by_step = {s.number: s for s in steps}
    found = [st for st in strokes if st.kind == "arrow" and st.component == "sliding"
             and x in (st.frm, st.to)]
    if under:
        named = [st for st in found if st.of in by_step and under[0] in by_step[st.of].args]
        found = named or found
    return found[0] if found else None
