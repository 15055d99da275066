"""Results as a readable table (units stated, senses named) and as a JSON object."""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from . import geometry
from .errors import PolygonsError
from .evaluate import Solution
from .narrate import substitute
from .quantities import quantity
from .notation import vertex, vertices_in
from .steps import noise_floor, percent_diff, sense as steps_sense
from .scene import Answer
from .units import SYSTEMS, UNITS


@dataclass(frozen=True)
class AnswerCheck:
    answer: Answer
    ours: float             # in answer.unit, signed
    compared: float         # |ours| for mode abs
    diff_pct: float | None  # vs tutorial
    within: bool | None     # tutorial within its drawing tolerance
    exact_rel: float | None # |ours - exact| / |exact|


def to_unit(value: float, unit: str) -> float:
    if unit in ("-", "1"):
        return value
    return value / UNITS[unit][1]


def check_answers(sol: Solution) -> list[AnswerCheck]:
    out = []
    for i, ans in enumerate(sol.scene.answers):
        try:
            ours = to_unit(quantity(sol, ans.quantity), ans.unit)
        except PolygonsError as exc:
            raise exc.located(file=sol.scene.file, where=f"answers[{i}].quantity") from None
        compared = abs(ours) if ans.mode == "abs" else ours
        diff = within = rel = None
        if ans.tutorial is not None:
            if ans.tutorial == 0:      # a printed zero: no percentage; ours must vanish too
                within = abs(compared) <= 1e-9
            else:
                diff = percent_diff(ans.tutorial, compared)
                within = (abs(ans.tutorial - compared)
                          <= ans.tolerance * max(abs(ans.tutorial), abs(compared)))
        if ans.exact is not None:
            exact = ans.exact
            rel = abs(compared - exact) / abs(exact) if exact != 0 else abs(compared)
            rel = rel if math.isfinite(rel) else None     # a subnormal exact value: no ratio
        out.append(AnswerCheck(ans, ours, compared, diff, within, rel))
    return out


def undefined_note(tutorial: float | None, diff: float | None) -> str:
    """'; diff % undefined (ours ≈ 0)' when a non-zero printed answer has no percentage."""
    return "; diff % undefined (ours ≈ 0)" if tutorial and diff is None else ""


def sense(value: float | None) -> str:
    """'CCW' / 'CW' / '' (:func:`polygons.steps.sense`), '' also for a value not solved."""
    return "" if value is None else steps_sense(value)


def _deg(v) -> float:
    return math.degrees(math.atan2(v[1], v[0])) % 360.0


def _mag(v) -> float:
    return float(np.hypot(v[0], v[1]))


def _every_point(sol: Solution):
    """(label, PointResult) of every point of the polygons, then each rolling wheel's named
    points not among them (its rim points, a centre between two plates: the same fields,
    from the wheel's ω and α, :func:`polygons.wheels.wheel_point`)."""
    yield from sol.points.items()
    from .contacts import wheel_point
    from .evaluate import PointResult
    for e in getattr(sol.scene, "equivalents", ()):
        if e.kind != "rolling":
            continue
        for label in (e.at, *(r[0] for r in e.rim)):
            if label in sol.points:
                continue
            got = wheel_point(sol, e, label)
            if got is not None:
                yield label, PointResult(*got)


def to_json(sol: Solution) -> dict:
    scene = sol.scene
    points = {}
    for label, pr in _every_point(sol):
        entry = {"position": list(pr.position)}
        if pr.velocity is not None:
            entry |= {"velocity": list(pr.velocity), "speed": _mag(pr.velocity),
                      "velocity_direction_deg": _deg(pr.velocity) if _mag(pr.velocity) else None}
        if pr.acceleration is not None:
            entry |= {"acceleration": list(pr.acceleration),
                      "acceleration_magnitude": _mag(pr.acceleration),
                      "acceleration_direction_deg":
                          _deg(pr.acceleration) if _mag(pr.acceleration) else None}
        points[label] = entry
    links = {}
    for name, lr in sol.links.items():
        pa, pb = sol.points[lr.a], sol.points[lr.b]
        entry = {"ends": [lr.a, lr.b], "length": lr.length, "omega": lr.omega,
                 "omega_sense": sense(lr.omega), "alpha": lr.alpha,
                 "alpha_sense": sense(lr.alpha)}
        if pa.velocity is not None:
            rel = np.subtract(pb.velocity, pa.velocity)
            entry[f"(v_{lr.b})_{lr.a}"] = list(map(float, rel))
        if pa.acceleration is not None:
            rel = np.subtract(pb.acceleration, pa.acceleration)
            r = np.subtract(pb.position, pa.position)
            u = r / np.hypot(*r)
            n = float(rel @ u) * u
            entry[f"(a_{lr.b})_{lr.a}"] = list(map(float, rel))
            entry[f"(a_{lr.b})_{lr.a}^n"] = list(map(float, n))
            entry[f"(a_{lr.b})_{lr.a}^t"] = list(map(float, rel - n))
        links[name] = entry
    slides = {}
    for label, sr in sol.slides.items():
        slides[label] = {"along": sr.along, "direction": list(sr.direction),
                         "velocity": sr.velocity, "acceleration": sr.acceleration,
                         "coriolis": list(sr.coriolis) if sr.coriolis else None}
    steps = []
    for s in sol.steps:
        d = asdict(s)
        d["substituted"] = substitute(s, sol.scene)      # the formula with its numbers
        for k in ("at", "vector", "point", "direction"):
            if d[k] is not None:
                d[k] = list(d[k])
        d["args"] = list(d["args"])
        d["lines"] = list(d["lines"])
        steps.append(d)
    answers = []
    for c in check_answers(sol):
        answers.append({"quantity": c.answer.quantity, "desc": c.answer.desc,
                        "unit": c.answer.unit, "ours": c.ours, "tutorial": c.answer.tutorial,
                        "exact": c.answer.exact, "tutorial_diff_pct": c.diff_pct,
                        "tutorial_within_tolerance": c.within,
                        "tolerance_pct": c.answer.tolerance * 100.0, "slip": c.answer.slip,
                        "sense": c.answer.sense, "note": c.answer.note})
    return {
        "case": {"file": scene.file, "title": scene.title, "id": scene.source.get("id"),
                 "synthetic": bool(scene.source.get("synthetic", False))},
        "units": {"length": "m", "velocity": "m/s", "acceleration": "m/s^2",
                  "omega": "rad/s (CCW positive)", "alpha": "rad/s^2 (CCW positive)",
                  "angles": "deg CCW from +x"},
        "pole": sol.pole,
        "branches": [{"point": p, "chosen": why} for p, why in sol.placement.branches],
        "points": points,
        "links": links,
        "slides": slides,
        "steps": steps,
        "min_intersection_angle_deg": sol.min_intersection_angle_deg,
        "warnings": list(sol.warnings),
        "answers": answers,
    }


def json_text(data: dict) -> str:
    """The one JSON formatting of every command (deterministic, no NaN)."""
    import json                       # only for --json: a quicker start
    return json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def dumps(sol: Solution) -> str:
    return json_text(to_json(sol))


def _noise(values, vector: bool = False) -> float:
    """The rounding noise of one column (:func:`polygons.steps.noise_floor`, the rule the
    steps' numbers follow too); the JSON's points and links keep the computed numbers."""
    return noise_floor([(_mag(v) if vector else abs(v)) for v in values if v is not None])


def _denoised(x: float | None, noise: float) -> float | None:
    return x if x is None or abs(x) > noise else 0.0


def _g(x, digits=5) -> str:
    if x is None:
        return "-"
    if x == 0:
        return "0"
    return f"{x:.{digits}g}"


def table(sol: Solution, *, steps: bool = True, units: str = "mm") -> str:
    """The results table; ``units`` picks the unit system of the columns (:data:`SYSTEMS`:
    'mm' -- positions in mm, speeds in m/s, the default; 'si'; 'imperial' -- in, ft/s, ft/s²).
    The construction steps keep the numbers they were drawn with (SI)."""
    if units not in SYSTEMS:
        raise PolygonsError(f"unknown unit system {units!r}: choose one of "
                            f"{', '.join(SYSTEMS)}")
    sysu = SYSTEMS[units]
    lu, vu, au = sysu["length"], sysu["velocity"], sysu["acceleration"]
    lf, vf, af = (1.0 / UNITS[u][1] for u in (lu, vu, au))
    scene = sol.scene
    lines = [f"{scene.title}", f"  scene: {scene.file}"
             + (f"   [{scene.source['id']}]" if scene.source.get("id") else "")]
    if scene.source.get("synthetic"):
        lines.append("  SYNTHETIC geometry: a stand-in, not the tutorial's missing figure")
    for p, why in sol.placement.branches:
        lines.append(f"  assembly: {why}")
    lines.append("")
    lines.append(f"{'point':<6} {'x ' + lu:>10} {'y ' + lu:>10}   {'|v| ' + vu:>11} "
                 f"{'dir°':>7}   {'|a| ' + au:>11} {'dir°':>7}")
    vnoise = _noise([pr.velocity for pr in sol.points.values()], vector=True)
    anoise = _noise([pr.acceleration for pr in sol.points.values()], vector=True)
    for label, pr in sol.points.items():
        row = f"{label:<6} {lf * pr.position[0]:>10.4f} {lf * pr.position[1]:>10.4f}"
        for vec, f, noise in ((pr.velocity, vf, vnoise), (pr.acceleration, af, anoise)):
            if vec is None:
                row += f"   {'':>11} {'':>7}"
            else:
                m = _mag(vec) * f if _mag(vec) > noise else 0.0
                row += f"   {_g(m, 6):>11} {(f'{_deg(vec):.2f}' if m else '-'):>7}"
        lines.append(row)
    lines.append("")
    lines.append(f"{'link':<8} {'length ' + lu:>10}   {'ω rad/s':>12}      {'α rad/s²':>12}")
    wnoise = _noise([lr.omega for lr in sol.links.values()])
    # α's scale is ω² as much as α (every link's α is 0 when the crank turns steadily)
    alnoise = max(_noise([lr.alpha for lr in sol.links.values()]), 1e12 * wnoise * wnoise)
    for name, lr in sol.links.items():
        w = _denoised(lr.omega, wnoise)
        al = _denoised(lr.alpha, alnoise)
        lines.append(f"{name:<8} {lf * lr.length:>10.4f}   "
                     f"{_g(abs(w) if w is not None else None, 6):>12} {sense(w):<4} "
                     f"{_g(abs(al) if al is not None else None, 6):>12} {sense(al)}")
    if sol.slides:
        lines.append("")
        for label, sr in sol.slides.items():
            where = "its guide" if sr.along == "guide" else f"the slot of {sr.along}"
            text = f"slide {label} along {where}: v = {_g(sr.velocity * vf, 6)} {vu}"
            if sr.acceleration is not None:
                text += f", a = {_g(sr.acceleration * af, 6)} {au}"
            if sr.coriolis is not None:
                text += f", Coriolis 2ωv = {_g(_mag(sr.coriolis) * af, 6)} {au}"
            lines.append(text + "  (signed along " + (f"{_deg(sr.direction):.2f}°)"))
    if steps:
        for diagram in scene.solve:
            lines.append("")
            lines.append(f"{diagram} construction (pole {vertex(sol.pole)}):")
            for s in sol.steps:
                if s.diagram != diagram:
                    continue
                text = f"  {s.number:>2}. {s.reason}"
                formula = substitute(s, sol.scene)
                if formula:
                    text += f"  [{formula}]"
                text = vertices_in(text, sol.printed_names(diagram))   # p4_1 → p₄′
                lines.append(text)
    lines.append("")
    if sol.min_intersection_angle_deg is not None:
        lines.append(f"conditioning: smallest angle between intersecting construction lines "
                     f"{sol.min_intersection_angle_deg:.3f}°"
                     + ("" if sol.min_intersection_angle_deg >= geometry.WARN_DEG
                        else "  (NEAR A TOGGLE)"))
    for w in sol.warnings:
        lines.append(f"warning: {w}")
    checks = check_answers(sol)
    if checks:
        lines.append("")
        lines.append(f"{'answer':<34} {'unit':<8} {'polygons':>12} {'tutorial':>10} {'diff %':>8}  note")
        for c in checks:
            a = c.answer
            if a.tutorial is None:       # asked, with no printed value: ours, and the exact
                note = f"exact {_g(a.exact, 6)}" if a.exact is not None else "asked"
            else:
                note = "SLIP in the tutorial (see reference)" if a.slip else (
                    "within drawing tolerance" if c.within else
                    f"outside ±{a.tolerance * 100:g}%") + undefined_note(a.tutorial, c.diff_pct)
            lines.append(f"{a.desc[:34]:<34} {a.unit:<8} {_g(c.compared, 6):>12} "
                         f"{_g(a.tutorial, 6):>10} "
                         f"{_pct(c.diff_pct):>8}  {note}")
    return "\n".join(lines) + "\n"


def _pct(d: float | None) -> str:
    """A difference in per cent to two places; one that rounds to zero is 0.00, never -0.00."""
    if d is None:
        return "-"
    text = f"{d:.2f}"
    return "0.00" if text == "-0.00" else text
