"""``polygons check CASE.toml --measured v_C=7.1 alpha_CD=150000``: grade a student's drawing.

Each measured value is compared with the construction's value.  A careful drawing is expected
to be within the larger of

* what a careful drawing achieves: the 95th percentile of the error of that quantity in the
  drawing-board emulation (``polygons/drawing_board.py``: pencil and rule ±0.25 mm, protractor
  ±0.25°, at this crank angle, fixed seed) for |v|, |a|, ω and α of the points and links it
  covers; for anything else, or when the emulation is not available (it lives in a source
  checkout), the case's stated drawing tolerance (``[source] drawing_tolerance``, default 2 %);
  ``--tolerance`` sets one value for all;
* a ruler reading of ±0.5 mm on the line of the polygon the value is read from, at the scale
  the diagrams are drawn to (``1 cm = 2.5 m/s``): a short vector cannot be read to 2 %.

Every value that is off gets a hint: the construction step that produces it (diagram,
number, stage figure and its sentence).

Measured names are the textbook's: ``v_C``, ``v_CB`` (velocity of C relative to B),
``omega_BC``, ``alpha_CD``, ``a_C``, ``a_CB``, ``an_CB`` / ``at_CB`` (centripetal / tangential
part of a_CB), ``cor_A`` (Coriolis 2ωv of pin A), ``vs_C`` / ``as_C`` (sliding velocity /
acceleration); a quantity expression of :mod:`polygons.quantities` (``v(C,B)``) also works.
Values are SI (m/s, m/s², rad/s, rad/s²) unless a unit is written (``v_C="7.1 m/s"``,
``omega_BC=2000rpm``); ``CW``/``CCW`` after ω or α (``alpha_CD=150000CW``) also checks the
sense, and so does a negative ω or α (CCW positive).  A sliding velocity or acceleration
(``vs_C``, ``as_C``) is signed along its guide's or slot's direction: written with a sign
(``vs_C=+6.9``, ``vs_C=-6.9``) it is graded with its sign; written without one, only its
magnitude is graded (a length read off a polygon has none) and the report says so, giving the
direction the sign is taken along.

Exit status: 0 when every value is within tolerance, 3 when some are off, 1 on an error
(unknown name, bad value), 2 on a usage error.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import PolygonsError, SceneError
from ..evaluate import Solution, link_ends, solve
from ..plan import Step
from ..notation import vertices_in
from ..quantities import dimension_of_quantity, quantity
from ..scene import load_scene
from ..units import parse_quantity
from ._output import add_out_option, emit
from ..steps import sense as sense_word
# the tolerances a measured value is graded against (shared with the exam's keys)
from ..tolerances import (DEFAULT_TOLERANCE, READING_MM, emulated_tolerances,  # noqa: F401
                          stated_tolerance, tolerance_for)

#: textbook prefix -> quantities function
PREFIX = {"v": "v", "a": "a", "omega": "omega", "w": "omega", "alpha": "alpha", "an": "an",
          "at": "at", "cor": "cor", "vs": "vs", "as": "as"}
#: how many point labels each function takes after the prefix (links take a link name)
_POINTS = {"v": (1, 2), "a": (1, 2), "an": (2,), "at": (2,), "cor": (1,), "vs": (1,),
           "as": (1,)}
UNIT = {"velocity": "m/s", "acceleration": "m/s²", "angular_velocity": "rad/s",
        "angular_acceleration": "rad/s²", "force": "N", "torque": "N m", "angle": "rad",
        "fraction": "", "length": "m", "energy": "J"}
SIGNED = ("omega", "alpha", "vs", "as")

_VALUE = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


class MeasuredError(SceneError):
    """A measured value that cannot be read or names no quantity of the case."""


@dataclass(frozen=True)
class Grade:
    name: str               # as the student wrote it
    expr: str               # quantities expression
    unit: str               # SI unit shown
    measured: float         # SI, as given (signed if the student signed it)
    expected: float         # SI, signed for ω, α and sliding values
    tolerance: float        # absolute, SI
    tolerance_pct: float    # the same, as % of |expected|
    diff_pct: float | None  # (|measured| - |expected|) / |expected| × 100
    ok: bool
    sense_given: str | None  # 'CW'/'CCW' for ω, α; '+'/'-' for a signed slide; else None
    sense_ok: bool | None
    step: Step | None
    hint: str
    tutorial_note: str
    source: str = "stated"  # where the tolerance comes from: emulated, stated, given, reading


# ---------------------------------------------------------------- names
def _labels(sol: Solution) -> list[str]:
    return sorted(sol.points, key=len, reverse=True)


def _split_labels(sol: Solution, text: str) -> list[str] | None:
    """'CB' -> ['C', 'B'], 'P2P4' -> ['P2', 'P4'], 'P2_P4' likewise; None if impossible."""
    labels = _labels(sol)
    seps = "_,"
    n = len(text)
    # by a table from the end (not recursion: a student's text may be thousands of capitals):
    # take[i] is the label (longest first) that begins text[i:] when the rest splits too
    take: list[str | None] = [None] * (n + 1)
    fits = [False] * n + [True]
    for i in range(n - 1, -1, -1):
        if text[i] in seps:
            fits[i] = fits[i + 1]
            continue
        for lab in labels:
            if text.startswith(lab, i) and fits[i + len(lab)]:
                take[i], fits[i] = lab, True
                break
    if not fits[0]:
        return None
    parts, i = [], 0
    while i < n:
        if text[i] in seps:
            i += 1
            continue
        parts.append(take[i])
        i += len(take[i])
    return parts


def _link_named(sol: Solution, text: str) -> str | None:
    if text in sol.links:
        return text
    parts = _split_labels(sol, text)
    if parts and len(parts) == 2:
        for name in sol.links:
            if set(link_ends(sol.scene, name)) == set(parts):
                return name
    return None


def offered(sol: Solution) -> list[tuple[str, str]]:
    """(textbook name, expression) of every quantity this case can grade, in drawing order."""
    scene = sol.scene
    out: list[tuple[str, str]] = []
    moving = [lab for lab in sol.points if lab not in scene.ground]
    pairs = []
    for name in sol.links:
        a, b = link_ends(scene, name)
        pairs.append((b, a))
    for bp in scene.model.points.values():
        if bp.link in sol.links:
            a, _ = link_ends(scene, bp.link)
            pairs.append((bp.label, a))
    if "velocity" in scene.solve:
        out += [(f"v_{x}", f"v({x})") for x in moving]
        out += [(f"v_{x}{y}", f"v({x},{y})") for x, y in pairs]
        out += [(f"omega_{n}", f"omega({n})") for n in sol.links]
    if "acceleration" in scene.solve:
        out += [(f"a_{x}", f"a({x})") for x in moving]
        out += [(f"a_{x}{y}", f"a({x},{y})") for x, y in pairs]
        out += [(f"an_{x}{y}", f"an({x},{y})") for x, y in pairs]
        out += [(f"at_{x}{y}", f"at({x},{y})") for x, y in pairs]
        out += [(f"alpha_{n}", f"alpha({n})") for n in sol.links]
    for label, sr in sol.slides.items():
        if sr.velocity is not None:
            out.append((f"vs_{label}", f"vs({label})"))
        if sr.acceleration is not None:
            out.append((f"as_{label}", f"as({label})"))
        if sr.coriolis is not None:
            out.append((f"cor_{label}", f"cor({label})"))
    return out


def _unknown(sol: Solution, name: str, why: str = "") -> MeasuredError:
    names = ", ".join(n for n, _ in offered(sol))
    from ..forces import has_forces
    if has_forces(sol.scene):
        names += "; and the force answers of polygons forces (Tin, R(O,OA), Fc(R), ...)"
    return MeasuredError(f"unknown measured quantity {name!r}{why}; this case offers: {names}",
                         file=sol.scene.file)


def _force_fn(name: str) -> str | None:
    """The force function a measured name calls ('Tin', 'R(O,OA)', 'Fc(R)'), or None."""
    from ..forces.answers import FORCE_FUNCTIONS
    fn = name.split("(")[0].strip()
    return fn if fn in FORCE_FUNCTIONS and fn not in PREFIX.values() else None


def force_analysis(sol: Solution):
    """The force analysis of ``sol``'s scene (made once per solution, kept in its memo): what a
    measured force answer is graded against; refused in one line when the scene has no
    loads."""
    from ..forces import analyse, has_forces
    from ..memo import memo_of
    memo = memo_of(sol)
    if "force_analysis" not in memo:
        if not has_forces(sol.scene):
            raise MeasuredError("a force answer needs the scene's loads ([masses], [forces], "
                                "[torques] or [springs]): this case has none",
                                file=sol.scene.file)
        memo["force_analysis"] = analyse(sol.scene)
    return memo["force_analysis"]


def resolve(sol: Solution, name: str) -> str:
    """The :mod:`polygons.quantities` expression for a textbook name such as ``v_CB``, or a
    force answer's (``Tin``, ``R(O,OA)``, ``Fc(R)``: :mod:`polygons.forces.answers`)."""
    name = name.strip()
    if _force_fn(name) is not None:
        from ..forces.answers import force_quantity
        try:
            force_quantity(force_analysis(sol), name, None, 1)
        except MeasuredError:
            raise
        except PolygonsError as exc:
            raise _unknown(sol, name, f" ({exc.reason})") from None
        return name.replace(" ", "")
    if "(" in name:
        expr = name
    else:
        if "_" not in name:
            raise _unknown(sol, name)
        prefix, rest = name.split("_", 1)
        fn = PREFIX.get(prefix.lower())
        if fn is None or not rest:
            raise _unknown(sol, name)
        if fn in ("omega", "alpha"):
            link = _link_named(sol, rest)
            if link is None:
                raise _unknown(sol, name, f" (no link {rest})")
            expr = f"{fn}({link})"
        else:
            parts = _split_labels(sol, rest)
            if not parts or len(parts) not in _POINTS[fn]:
                raise _unknown(sol, name)
            expr = f"{fn}({','.join(parts)})"
    try:
        quantity(sol, expr)
    except PolygonsError as exc:
        raise _unknown(sol, name, f" ({exc.reason})") from None
    return expr


# ---------------------------------------------------------------- values
def parse_value(text: str, dimension: str, name: str, file: str | None) -> tuple[float, str | None]:
    """'7.1', '7.1 m/s', '150000CW', '2000 rpm CCW' -> (SI value, sense or None)."""
    s = text.strip().replace("\u2212", "-")
    sense = None
    m = re.search(r"(?<![A-Za-z/])(CCW|ACW|CW)\s*$", s, re.IGNORECASE)
    if m:
        sense = "CCW" if m.group(1).upper() in ("CCW", "ACW") else "CW"
        s = s[:m.start()].strip()
    m = _VALUE.match(s)
    if not m:
        raise MeasuredError(f"cannot read the measured value {name}={text!r}: write a number, "
                            f"e.g. {name}=7.1 (SI) or {name}='7.1 {UNIT.get(dimension, '')}'",
                            file=file)
    number, unit = float(m.group(1)), m.group(2)
    if unit:
        try:
            value = parse_quantity(f"{number} {unit}", dimension)
        except PolygonsError as exc:
            raise MeasuredError(f"{name}={text!r}: {exc.reason}", file=file) from None
    else:
        value = number
    if not math.isfinite(value):
        raise MeasuredError(f"{name}={text!r} is not a finite number", file=file)
    if sense and dimension not in ("angular_velocity", "angular_acceleration"):
        raise MeasuredError(f"{name}={text!r}: a sense (CW/CCW) only goes with ω or α",
                            file=file)
    return value, sense


def parse_measured(sol: Solution, items: list[str]) -> list[tuple[str, str, float, str | None]]:
    out = []
    seen = set()
    for item in items:
        if "=" not in item:
            raise MeasuredError(f"--measured {item!r}: write NAME=VALUE, e.g. v_C=7.1",
                                file=sol.scene.file)
        name, text = (part.strip() for part in item.split("=", 1))
        expr = resolve(sol, name)
        if expr in seen:
            raise MeasuredError(f"{name} is given twice", file=sol.scene.file)
        seen.add(expr)
        value, sense = parse_value(text, _dimension(expr), name, sol.scene.file)
        if _fn_args(expr)[0] in ("vs", "as") and text.strip()[:1] in ("+", "-", "\u2212"):
            sense = "-" if value < 0 else "+"     # a written sign: the slide's sense graded
        out.append((name, expr, value, sense))
    return out


def _dimension(expr: str) -> str:
    fn = _force_fn(expr)
    if fn is not None:
        from ..forces.answers import FORCE_FUNCTIONS
        return FORCE_FUNCTIONS[fn][0]
    return dimension_of_quantity(expr)


# ---------------------------------------------------------------- where a value comes from
def _fn_args(expr: str) -> tuple[str, tuple[str, ...]]:
    """'v(C,B)' -> ('v', ('C', 'B'))."""
    fn, _, rest = expr.replace(" ", "").partition("(")
    return fn, tuple(a for a in rest.rstrip(")").split(",") if a)


def producing_step(sol: Solution, expr: str) -> Step | None:
    """The construction step that fixes ``expr`` on the drawing (None: given data)."""
    fn, args = _fn_args(expr)
    scene = sol.scene
    vel = [s for s in sol.steps if s.diagram == "velocity"]
    acc = [s for s in sol.steps if s.diagram == "acceleration"]

    def creates(steps, label):
        if label in scene.ground:
            return None
        v = sol.vertex_of(label)
        return next((s for s in steps if s.end == v and s.kind != "measure"), None)

    def later(steps, labels):
        made = [s for s in (creates(steps, lab) for lab in labels) if s is not None]
        return max(made, key=lambda s: s.number) if made else None

    def measure(steps, op, first):
        return next((s for s in steps if s.kind == "measure" and s.op in op
                     and s.args and s.args[0] == first), None)

    if fn == "v":
        return later(vel, args)
    if fn == "a":
        return later(acc, args)
    if fn == "omega":
        return measure(vel, ("omega",), args[0])
    if fn == "alpha":
        return (measure(acc, ("alpha",), args[0])
                or next((s for s in acc if s.op == "crank_tangential" and s.args[0] == args[0]),
                        None))
    if fn == "an":
        hit = next((s for s in acc if s.op == "centripetal" and set(s.args[1:3]) == set(args)),
                   None)
        return hit or later(acc, args)
    if fn == "at":
        for s in acc:
            if s.op == "crank_tangential" and set(s.args[1:3]) == set(args):
                return s
        for s in acc:
            if s.kind == "measure" and s.op == "alpha":
                try:
                    if set(link_ends(scene, s.args[0])) == set(args) or set(s.args[1:3]) == set(args):
                        return s
                except KeyError:
                    pass
        return later(acc, args)
    if fn == "cor":
        return next((s for s in acc if s.op == "coriolis_offset_line" and s.args[0] == args[0]),
                    None)
    if fn in ("vs", "as"):
        steps = vel if fn == "vs" else acc
        return next((s for s in steps if s.kind == "measure" and s.args[:1] == (args[0],)
                     and s.op in ("slider_velocity", "slide_velocity", "slider_acceleration",
                                  "slide_acceleration")), None)
    return None


def stage_number(sol: Solution, step: Step) -> int | None:
    """The stage figure (1, 2, 3 ...) that draws ``step`` (stages are numbered, never
    lettered: 'Fig. b' would read as the vertex b)."""
    drawable = [s for s in sol.steps if s.diagram == step.diagram
                and s.kind in ("vector", "image", "line", "intersection")]
    for i, s in enumerate(drawable, 1):
        if s.number == step.number:
            return i
    return None


def describe_step(sol: Solution, step: Step) -> str:
    k = stage_number(sol, step)
    where = f"{step.diagram} step {step.number}" + (f" (stage {k})" if k else "")
    text = f"{where}: \u201c{step.reason}\u201d"
    if step.kind == "intersection" and step.lines:
        text += (f" Check the lines of steps {step.lines[0]} and {step.lines[1]} and where "
                 f"they cross.")
    elif step.kind == "measure":
        text += f" [{step.formula}]"
        if step.op in ("omega", "alpha") and len(step.args) == 3:
            drawn = next((s for s in sol.steps if s.diagram == step.diagram
                          and s.end == sol.vertex_of(step.args[2]) and s.kind != "measure"),
                         None)
            if drawn is not None:
                k = stage_number(sol, drawn)
                text += (f" The line it is read from ends at {drawn.end}, fixed in step "
                         f"{drawn.number}" + (f" (stage {k})" if k else "") + ".")
    return vertices_in(text, sol.printed_names(step.diagram))     # p4_1 → p₄′, as printed


# ---------------------------------------------------------------- grading
def diagram_scales(sol: Solution, forced: dict | None = None) -> dict:
    """The scale each polygon is drawn to, by diagram name: ``forced`` (the student's, from
    ``--scale``), else the scene's ``[diagram]`` scale, else the diagrams' own choice."""
    out = {}
    try:
        import diagrams
        from diagrams import polygon
        opts = diagrams.options(sol, forced)
        for d in sol.scene.solve:
            out[d] = polygon.scale_of(sol, d, opts["scales"].get(d), opts["paper"])[0]
    except Exception:       # diagrams not available: choose as they would, from the vertices
        try:
            from diagrams import scale as scales
        except Exception:
            return {}
        for d in sol.scene.solve:
            pts = list(sol.vertices[d].values())
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            out[d] = scales.choose(d, (max(xs) - min(xs), max(ys) - min(ys)))
    return out


def grade(sol: Solution, measured: list[tuple[str, str, float, str | None]],
          tolerance: float | None = None, scales: dict | None = None,
          emulated: dict | None = None) -> list[Grade]:
    """Grade ``measured`` (from :func:`parse_measured`).  ``tolerance`` (a fraction) applies
    to every value when given; otherwise the emulated tolerance of the quantity when there is
    one (``emulated``, default :func:`emulated_tolerances`), else the stated drawing
    tolerance.  No tolerance is below a 0.5 mm ruler reading at the diagram's scale."""
    stated = stated_tolerance(sol)
    scales = diagram_scales(sol) if scales is None else scales
    if emulated is None:
        emulated = {} if tolerance is not None else emulated_tolerances(sol)
    out = []
    for name, expr, value, sense in measured:
        if _force_fn(expr) is not None:
            out.append(_grade_force(sol, name, expr, value, tolerance, stated))
            continue
        fn = _fn_args(expr)[0]
        expected = quantity(sol, expr)
        if tolerance is not None:
            pct, source = tolerance, "given"
        elif expr in emulated:
            pct, source = emulated[expr], "emulated"
        else:
            pct, source = stated, "stated"
        tol = tolerance_for(sol, expr, expected, pct, scales)
        if tol > pct * abs(expected) * (1 + 1e-9):
            source = "reading"
        signed = fn in SIGNED and (value < 0 or sense is not None)
        if fn in ("vs", "as") and value < 0 and sense is None:
            sense = "-"
        if fn in ("omega", "alpha") and sense is not None:
            value = abs(value) if sense == "CCW" else -abs(value)
        if signed and fn in ("vs", "as"):
            err = value - expected
        else:               # ω, α: the magnitude here, the sense separately
            err = abs(value) - abs(expected)
        diff = err / abs(expected) * 100.0 if expected != 0 else None
        sense_ok = None
        if fn in ("omega", "alpha") and (sense is not None or value < 0) and expected != 0:
            sense_ok = (value > 0) == (expected > 0)
        if signed and fn in ("vs", "as") and expected != 0 and value != 0:
            sense_ok = (value > 0) == (expected > 0)
        ok = abs(err) <= tol * (1 + 1e-12) and sense_ok is not False
        step = producing_step(sol, expr)
        hint = ""
        wheel = next((q for q in sol.scene.equivalents if q.kind == "rolling"
                      and q.at == _fn_args(expr)[1][0] and q.at not in sol.links), None) \
            if fn in ("omega", "alpha", "v", "a") else None
        if not ok and wheel is not None and (fn in ("omega", "alpha")
                                             or wheel.at not in sol.points):
            hint = wheel.words.split(": ", 1)[-1]       # a wheel: its no-slip condition(s)
        elif not ok:
            hint = (describe_step(sol, step) if step is not None
                    else "this value is given data: recheck the problem statement and units")
        out.append(Grade(name, expr, UNIT[dimension_of_quantity(expr)], value, expected, tol,
                         tol / abs(expected) * 100.0 if expected else math.inf, diff, ok,
                         sense, sense_ok, step, hint, _tutorial_note(sol, expr, value),
                         source))
    return out


def _grade_force(sol: Solution, name: str, expr: str, value: float, tolerance, stated
                 ) -> Grade:
    """A force answer (a value read off a force polygon or a free body) against the force
    analysis: its magnitude, or signed when the student gives a sign; the stated (or given)
    tolerance, the polygons' drawing tolerance carried into the forces."""
    from ..forces.answers import force_quantity
    expected = force_quantity(force_analysis(sol), expr, None, 1)
    pct, source = (tolerance, "given") if tolerance is not None else (stated, "stated")
    tol = pct * abs(expected)
    err = (value - expected) if value < 0 else (abs(value) - abs(expected))
    diff = err / abs(expected) * 100.0 if expected != 0 else None
    ok = abs(err) <= tol * (1 + 1e-12) if expected != 0 else abs(value) <= 1e-9
    hint = "" if ok else ("recheck it against the free body and the force polygon of its "
                          "body: `polygons forces` prints every reaction and the input effort")
    return Grade(name, expr, UNIT.get(_dimension(expr), ""), value, expected, tol,
                 pct * 100.0 if expected else math.inf, diff, ok, None, None, None, hint, "",
                 source)


def _tutorial_note(sol: Solution, expr: str, value: float) -> str:
    """When the value matches the tutorial's printed answer that differs from the exact one."""
    from ..report import to_unit
    for ans in sol.scene.answers:
        if ans.quantity != expr or ans.tutorial is None or ans.mode != "abs":
            continue
        printed = ans.tutorial / to_unit(1.0, ans.unit)   # SI
        exact = abs(quantity(sol, expr))
        if exact == 0 or printed == 0:
            continue
        off = (printed - exact) / exact
        if abs(off) > 0.005 and abs(abs(value) - printed) <= 0.005 * printed:
            what = "a slip the reference found" if ans.slip else "the tutorial's drawing"
            return (f"your value matches the tutorial's printed {ans.tutorial:g} {ans.unit}, "
                    f"which is {_signed(off * 100)} % from the exact value ({what}"
                    + (f": {ans.note}" if ans.note else "") + ")")
    return ""


# ---------------------------------------------------------------- output
def _num(x: float) -> str:
    if x == 0:
        return "0"
    mag = abs(x)
    if 1e-3 <= mag < 1e7:
        decimals = max(0, 4 - 1 - int(math.floor(math.log10(mag))))
        return f"{x:.{decimals}f}"
    return f"{x:.4g}"


def _signed(x: float) -> str:
    """A percentage ``x`` with its sign: '+12.3', and above 10⁵ in four figures, '+1.846e+13'
    (an absurd measured value printed a run of 14 digits)."""
    return f"{x:+.1f}" if abs(x) < 1e5 else f"{x:+.4g}"


def _sense(v: float) -> str:
    """' CCW' / ' CW' after a number, '' for zero."""
    return f" {sense_word(v)}" if v != 0 else ""


SOURCE_WORDS = {"emulated": "careful drawing", "stated": "stated", "given": "--tolerance",
                "reading": "0.5 mm reading"}


def report(sol: Solution, grades: list[Grade], pct: float, scales: dict,
           emulated: bool = True) -> str:
    scene = sol.scene
    sid = scene.source.get("id")
    lines = [f"{scene.title}" + (f"   [{sid}]" if sid else ""),
             f"  scene: {scene.file}"]
    sc = ", ".join(f"{d} {s.statement}" for d, s in scales.items())
    lines.append("  tolerance of each value, the larger of:")
    if any(g.source == "given" for g in grades):
        lines.append(f"    --tolerance   ±{pct * 100:g} % for every value")
    elif emulated:
        lines.append("    careful drawing  95th percentile of its error in the drawing-board "
                     "emulation (pencil, rule ±0.25 mm, protractor ±0.25°)")
        lines.append(f"    stated           the case's drawing tolerance ±{pct * 100:g} % "
                     f"(quantities the emulation does not cover)")
    else:
        lines.append(f"    stated           the case's drawing tolerance ±{pct * 100:g} % "
                     f"(the drawing-board emulation does not cover this mechanism)")
    lines.append("    0.5 mm reading   a ruler reading at the scale drawn"
                 + (f" ({sc})" if sc else ""))
    lines.append("")
    wn = max(len(g.name) for g in grades)
    for g in grades:
        fn = g.expr.split("(")[0]
        force = _force_fn(g.expr) is not None
        if fn in ("omega", "alpha"):
            shown = f"{_num(abs(g.measured))} {g.unit}" + (
                _sense(g.measured) if g.sense_given or g.measured < 0 else "")
            exp = f"{_num(abs(g.expected))} {g.unit}{_sense(g.expected)}"
        elif fn in ("vs", "as") and g.sense_given is None:     # the magnitude only
            shown = f"{_num(abs(g.measured))} {g.unit}"
            exp = f"{_num(abs(g.expected))} {g.unit} (magnitude)"
        elif fn in ("vs", "as"):
            shown = f"{'+' if g.measured > 0 else ''}{_num(g.measured)} {g.unit}"
            exp = f"{'+' if g.expected > 0 else ''}{_num(g.expected)} {g.unit}"
        elif force and g.measured < 0:        # a force answer given with its sign: graded so
            if g.unit == "N m":               # a moment's sign is its sense (CCW +)
                shown = f"{_num(abs(g.measured))} {g.unit}{_sense(g.measured)}"
                exp = f"{_num(abs(g.expected))} {g.unit}{_sense(g.expected)}"
            else:
                shown = f"{_num(g.measured)} {g.unit} (signed)".replace("-", "−", 1)
                exp = f"{_num(g.expected)} {g.unit}".replace("-", "−", 1)
        else:
            shown = f"{_num(abs(g.measured))} {g.unit}"
            exp = f"{_num(abs(g.expected))} {g.unit}"
        verdict = "ok " if g.ok else "OFF"
        diff = f"{_signed(g.diff_pct)} %" if g.diff_pct is not None else "-"
        lines.append(f"  {verdict}  {g.name:<{wn}}  measured {shown}, expected {exp} "
                     f"± {_num(g.tolerance)} (±{g.tolerance_pct:.2g} %, "
                     f"{SOURCE_WORDS[g.source]}): {diff}")
        if g.sense_ok is False and fn in ("vs", "as"):
            lines.append(f"       the sense is wrong: {_slide_words(sol, g.expr, g.expected)}")
        elif g.sense_ok is False:
            lines.append(f"       the sense is wrong: it turns{_sense(g.expected)}")
        if g.hint:
            lines.append(f"       hint: {g.hint}")
        if g.tutorial_note:
            lines.append(f"       note: {g.tutorial_note}")
        if fn in ("omega", "alpha") and g.sense_ok is None and g.expected != 0:
            lines.append(f"       magnitude only: no sense was written, so it is not graded "
                         f"(write {_num(abs(g.measured))}CW or CCW, or a negative value for "
                         f"CW, to have it graded)")
        if force and g.measured < 0 and g.expected != 0 and (g.measured > 0) != (
                g.expected > 0):
            lines.append(f"       the sense is wrong: {g.name} is "
                         + (f"{_num(abs(g.expected))} N m{_sense(g.expected)}"
                            if g.unit == "N m" else f"{_num(g.expected)} N (signed)"))
        if fn not in ("omega", "alpha", "vs", "as") and g.measured < 0 and not force:
            lines.append(f"       a magnitude has no sign: {_num(g.measured)} was graded as "
                         f"{_num(abs(g.measured))} (the length of its vector in the polygon)")
        if fn in ("vs", "as") and g.sense_given is None and g.expected != 0:
            lines.append(f"       magnitude only: no sign was written, so its sense is not "
                         f"graded; {g.name} is signed, {_slide_words(sol, g.expr, g.expected)}"
                         f" (write {_num(abs(g.measured))} with + or - to have it graded)")
    off = [g for g in grades if not g.ok]
    lines.append("")
    lines.append(f"{len(grades) - len(off)} of {len(grades)} within tolerance"
                 + (f"; off: {', '.join(g.name for g in off)}" if off else "."))
    return "\n".join(lines) + "\n"


def _slide_words(sol: Solution, expr: str, expected: float) -> str:
    """'+ along the guide's direction 90°; the construction gives -6.928 (towards 270°)'."""
    p = _fn_args(expr)[1][0]
    sr = sol.slides.get(p)
    if sr is None:
        return f"the construction gives {_num(expected)}"
    ang = math.degrees(math.atan2(sr.direction[1], sr.direction[0])) % 360.0
    toward = ang if expected > 0 else (ang + 180.0) % 360.0
    along = "the guide" if sr.along == "guide" else f"the slot of {sr.along}"
    return (f"+ along {along}'s direction {ang:.0f}° (CCW from +x); the construction gives "
            f"{_num(expected)}, towards {toward:.0f}°")


def _graded(g: Grade) -> str:
    """What of a value was graded: 'signed', 'magnitude and sense' or 'magnitude'."""
    fn = g.expr.split("(")[0]
    if fn in ("vs", "as") and g.sense_given is not None:
        return "signed"
    if fn in ("omega", "alpha") and g.sense_ok is not None:
        return "magnitude and sense"
    return "magnitude"


def _finite(x):
    """A percentage of a zero expected value is infinite: JSON says null instead."""
    return x if x is None or math.isfinite(x) else None


def to_json(sol: Solution, grades: list[Grade], pct: float, scales: dict,
            emulated: bool = True) -> dict:
    return {
        "case": {"file": sol.scene.file, "id": sol.scene.source.get("id"),
                 "title": sol.scene.title},
        "stated_tolerance_pct": pct * 100.0,
        "emulation": emulated,
        "reading_mm": READING_MM,
        "scales": {d: s.statement for d, s in scales.items()},
        "grades": [{"name": g.name, "quantity": g.expr, "unit": g.unit, "measured": g.measured,
                    "expected": g.expected, "tolerance": g.tolerance,
                    "tolerance_pct": _finite(g.tolerance_pct), "tolerance_source": g.source,
                    "diff_pct": _finite(g.diff_pct), "ok": g.ok,
                    "sense": g.sense_given, "sense_ok": g.sense_ok,
                    "graded": _graded(g),
                    "step": ({"diagram": g.step.diagram, "number": g.step.number,
                              "op": g.step.op, "gives": g.step.gives,
                              "reason": g.step.reason} if g.step else None),
                    "hint": g.hint, "note": g.tutorial_note} for g in grades],
        "all_ok": all(g.ok for g in grades),
    }


def register(sub) -> None:
    p = sub.add_parser(
        "check", help="grade a student's measured values against the construction",
        description="Grade measured values (textbook names: v_C, v_CB, omega_BC, alpha_CD, "
                    "a_C, an_CB, at_CB, cor_A, vs_C) against the construction, each within "
                    "the tolerance of a careful drawing; hints name the step to recheck. "
                    "Exit 0: all within tolerance; 3: some off; 1: error.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--drawing", metavar="FILE",
                   help="grade a drawn velocity or acceleration polygon (JSON or the "
                        "interactive page's SVG; README, 'Exams and grading')")
    p.add_argument("--measured", nargs="+", metavar="NAME=VALUE",
                   help="measured values, SI unless a unit is written: v_C=7.1 "
                        "alpha_CD=150000CW omega_BC='230 rad/s'")
    p.add_argument("--tolerance", help="one relative tolerance for every value instead of "
                                       "the emulated / stated ones, e.g. '3 %%'")
    p.add_argument("--scale", action="append", metavar="KIND=VALUE",
                   help="the scale the student drew at, for the 0.5 mm reading limit "
                        "(--scale velocity='2 m/s'; default: the diagrams' scale)")
    p.add_argument("--json", action="store_true", help="print a JSON object")
    add_out_option(p)
    p.set_defaults(func=run)


def run(args) -> int:
    scene = load_scene(args.scene)
    sol = solve(scene)
    if not args.measured and not args.drawing:
        raise MeasuredError("give --measured NAME=VALUE ... or --drawing FILE")
    if args.drawing:
        if args.measured or args.scale or args.tolerance is not None:
            raise MeasuredError("--drawing takes neither --measured, --scale nor --tolerance "
                                "(the drawing states its scale; its tolerances are the "
                                "emulation's)")
        from . import _drawing
        g = _drawing.grade_file(sol, args.drawing, emulated_tolerances(sol),
                                stated_tolerance(sol))
        if args.json:
            from ..report import json_text
            emit(json_text(_drawing.to_json(sol, g, args.drawing)), args.out)
        else:
            emit(_drawing.report(sol, g, args.drawing), args.out)
        return 0 if g.ok else 3
    measured = parse_measured(sol, args.measured)
    pct = None
    if args.tolerance is not None:
        try:
            pct = parse_quantity(args.tolerance.strip(), "fraction")
        except PolygonsError as exc:
            raise MeasuredError(f"--tolerance {args.tolerance!r}: {exc.reason}") from None
        if not (0 < pct < 1):
            raise MeasuredError(f"--tolerance {args.tolerance!r}: give a percentage such as "
                                f"'3 %'")
    forced = None
    if args.scale:
        from diagrams.scale import parse_cli
        forced = parse_cli(args.scale)
    scales = diagram_scales(sol, forced)
    pct_used = stated_tolerance(sol) if pct is None else pct
    emulated = {} if pct is not None else emulated_tolerances(sol)
    grades = grade(sol, measured, pct, scales, emulated)
    if args.json:
        from ..report import json_text
        emit(json_text(to_json(sol, grades, pct_used, scales, bool(emulated))), args.out)
    else:
        emit(report(sol, grades, pct_used, scales, bool(emulated)), args.out)
    return 0 if all(g.ok for g in grades) else 3
