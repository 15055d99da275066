"""Conditions as questions: the input at which a quantity takes a value, changes sign or is at
its extreme, and the extremes over the cycle (:mod:`polygons.question_table`).

    g(x) = q(x) − value                 zero / value: every x in the range where g changes sign
    q'(x) = [q(x+h) − q(x−h)] / 2h = 0  max / min / stationary, dead centres
    stroke = max q − min q;  time ratio = (turn from one dead centre to the other) / (the rest)

Each q(x) is the full construction at input x (the staged solve, or the force analysis for a
force quantity), the closures followed from the scene's own instant by the sweep
(:func:`polygons.sweep.sweep`, pinned ``near`` each sample by :meth:`Sweep.scene_at`).  The
roots are bracketed on ``samples`` instants and polished by Brent's method (:func:`brent`)
to the precision of the construction; a condition that never holds in the range is said in
words (:attr:`Finding.words`).  ``Finding.roots[k].scene`` is the scene restated at the root:
solve it for the construction there (``polygons ask --show``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np

from . import cam_diagram
from . import quantities as kq
from .errors import PolygonsError, SceneError, show
from .question_table import CYCLE, Question, questions
from .records import Crank
from .scene import Scene, drawing_tolerance, parse_quantity_expr
from .sweep import golden_min
from .calculus import brent
from .reader import Reader
from .units import UNITS

_TAU = 2.0 * math.pi
#: the relative step of the central difference whose zero is an extreme
_H = 1e-6


# ------------------------------------------------------------------ the records
@dataclass(frozen=True)
class Root:
    """One input at which the condition holds: ``input`` in SI (rad, rad/s, m), the
    quantity's ``value`` there (SI), ``kind`` ('crossing', 'max', 'min') and the scene
    restated there."""

    input: float
    value: float
    kind: str
    scene: Scene


@dataclass(frozen=True)
class Finding:
    """A question answered: its roots (increasing), the cycle's ``result`` (a stroke in SI, a
    time ratio) and, where the condition never holds, the words saying so."""

    question: Question
    roots: tuple[Root, ...]
    result: float | None
    words: str
    dimension: str          # the quantity's

    def reported(self) -> tuple[float, ...]:
        """What is compared with ``exact``: the roots (or the result) in the question's unit."""
        q = self.question
        if self.result is not None and q.condition in ("stroke", "time ratio"):
            return (to_unit(self.result, q.unit),)
        return tuple(input_in_unit(q, r.input) for r in self.roots)

    def values(self) -> tuple[float, ...]:
        unit = self.question.value_unit
        return tuple(to_unit(r.value, unit) if unit else r.value for r in self.roots)


def to_unit(value: float, unit: str | None) -> float:
    return value / UNITS[unit][1] if unit in UNITS else value


def input_in_unit(q: Question, x: float) -> float:
    """A found input in the question's unit (a crank angle in [0, 360°) for a full turn)."""
    if q.find == "angle" and q.condition in ("stroke", "time ratio"):
        unit = "deg"                       # the dead centres of a stroke: crank angles
    else:
        unit = q.unit
    if q.find == "angle" and q.range is None:
        x = math.fmod(x, _TAU)
        x = x + _TAU if x < 0 else x
        if _TAU - x <= 1e-9 * _TAU:        # a full turn is 0
            x = 0.0
    return to_unit(x, unit)


# ------------------------------------------------------------------ q(x)
def _measure(scene: Scene, q: Question):
    """(q(scene) -> float, the quantity's dimension); force quantities by the force analysis."""
    try:
        parse_quantity_expr(q.quantity)
        kinematic = True
    except PolygonsError:
        kinematic = False
    if kinematic:
        from .evaluate import solve
        return (lambda s: kq.quantity(solve(s), q.quantity)), kq.dimension_of_quantity(
            q.quantity)
    from .forces import FORCE_FUNCTIONS, analyse, force_quantity, has_forces
    from .forces.answers import check_expr, parse_call, _split_terms
    if not has_forces(scene):
        raise SceneError(f"{show(q.quantity)} is not a kinematic quantity, and the scene has no "
                         f"force tables to find it from", file=scene.file,
                         where=q.where + ".quantity")
    fn0 = parse_call(_split_terms(q.quantity)[0][1])[0] if q.quantity.strip() else ""
    dim = FORCE_FUNCTIONS[fn0][0] if fn0 in FORCE_FUNCTIONS else \
        kq.dimension_of_quantity(_split_terms(q.quantity)[0][1])
    if q.value_unit is not None:
        check_expr(q.quantity, q.value_unit, scene, q.where)
    else:
        check_expr(q.quantity, next(u for u, (d, f) in UNITS.items() if d == dim and f == 1.0)
                   if dim != "fraction" else "-", scene, q.where)
    return (lambda s: force_quantity(analyse(s), q.quantity)), dim


def _restated(scene: Scene, q: Question, x: float, near: Scene | None = None) -> Scene:
    """The scene with its input set to ``x`` (closures pinned as in ``near``)."""
    if cam_diagram.has_profile(scene):      # a cam by its profile: x the nose axis's angle
        if q.find == "angle":
            return cam_diagram.scene_at(scene, x)
        sense = -1.0 if scene.driver.omega < 0 else 1.0
        return cam_diagram.scene_at(scene, cam_diagram.nose_axis(scene), sense * x)
    base = near if near is not None else scene
    drv = base.driver
    if q.find == "angle":
        return replace(base, driver=replace(drv, angle=x))
    if q.find == "position":
        return replace(base, driver=replace(drv, position=x))
    sense = -1.0 if scene.driver.omega < 0 else 1.0
    return replace(base, driver=replace(drv, omega=sense * x))


def _samples(scene: Scene, q: Question) -> tuple[np.ndarray, list[Scene], bool]:
    """The sample inputs, the scene at each (closures followed from the scene's instant) and
    whether the range is a whole turn (periodic)."""
    if q.range is None:
        x0 = cam_diagram.nose_axis(scene) if cam_diagram.has_profile(scene) \
            else scene.driver.angle
        xs = x0 + _TAU * np.arange(q.samples) / q.samples
        periodic = True
    else:
        xs = np.linspace(q.range[0], q.range[1], q.samples)
        periodic = q.find == "angle" and abs(q.range[1] - q.range[0] - _TAU) < 1e-12
        if periodic:
            xs = xs[:-1]
    if q.find == "omega":                # the configuration does not change with the speed
        return xs, [_restated(scene, q, x) for x in xs], False
    if cam_diagram.has_profile(scene):  # each cam angle its own part and linkage: no sweep
        return xs, [_restated(scene, q, x) for x in xs], periodic
    try:
        from .sweep import sweep
        sw = sweep(scene, inputs=xs)
        pinned = [sw.scene_at(i) for i in range(len(xs))]
        ok = np.isfinite(sw.margin) & (sw.margin >= 0)
        return xs, [p if good else None for p, good in zip(pinned, ok)], periodic
    except PolygonsError:       # a scene the sweep does not follow: its own closure words
        return xs, [_restated(scene, q, x) for x in xs], periodic


def _safe(f, s) -> float:
    if s is None:
        return math.nan
    try:
        v = float(f(s))
    except PolygonsError:
        return math.nan
    return v if math.isfinite(v) else math.nan


def _cam_question(scene: Scene, q: Question) -> None:
    """A question on a cam stated by its profile ([cam_profiles]): the input is the nose
    axis's angle (or the cam's speed), each instant its own part in contact and linkage
    (:func:`polygons.cam_diagram.scene_at`; the base circle's dwell has none: no value
    there; the force tables restated with it, :data:`polygons.cam_diagram.LOAD_TABLES`).
    Refused in one line: a force quantity with a spring stated by its extension or twist
    at this instant, or another [dynamics] mode than kinetostatic; the follower's slide vs /
    as / cor on a tangent cam (the slide on the line of stroke at the nose, in the cam's slot
    on a straight flank: not one quantity over the turn)."""
    try:
        fn, args = parse_quantity_expr(q.quantity)
    except PolygonsError:
        springs = scene.extra.get("springs") or {}
        fixed = [n for n, sp in springs.items() if isinstance(sp, dict)
                 and ("extension" in sp or "twist" in sp)]
        mode = (scene.extra.get("dynamics") or {}).get("mode", "kinetostatic")
        if fixed or mode != "kinetostatic":
            raise SceneError(f"{show(q.quantity)} over the turn of a cam stated by its "
                             f"profile: " + (f"the spring {fixed[0]} is stated by its "
                                             f"extension at this instant only (state it "
                                             f"between two points with a free length)"
                                             if fixed else f"[dynamics] mode {show(mode)} is "
                                             f"not served (kinetostatic only)"),
                             file=scene.file, where=q.where + ".quantity") from None
        return
    (label, table), = scene.extra["cam_profiles"].items()
    if fn in ("vs", "as", "cor") and label in args and table.get("kind") == "tangent":
        raise SceneError(f"{show(q.quantity)} on a tangent cam is the slide along the line of "
                         f"stroke on the nose but in the cam's slot on a straight flank: ask "
                         f"for the follower's v({label}), a({label}) or y({label}) (x({label}))",
                         file=scene.file, where=q.where + ".quantity")


def _cam_edge(scene: Scene, q: Question, a: float, b: float) -> tuple[float, float] | None:
    """Where a cam's part in contact changes in [a, b] (the acceleration jumps there with the
    curvature, the velocity's slope too: a flank's end), as the two sides' last angles found
    by bisection on the part to full precision; None when one part holds [a, b] (or the
    input is the cam's speed)."""
    if q.find != "angle":
        return None
    pa = cam_diagram.part_at(scene, a)
    if pa == cam_diagram.part_at(scene, b):
        return None
    lo, hi = a, b
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if cam_diagram.part_at(scene, mid) == pa:
            lo = mid
        else:
            hi = mid
    return lo, hi


def answer(scene: Scene, q: Question) -> Finding:
    """Answer one question of the scene (see module docstring); on a cam stated by its
    profile, the turn where the follower dwells on the base circle said in words (it has no
    linkage there, so no value: an extreme is over the rest)."""
    found = _answer(scene, q)
    if q.find != "angle" or not cam_diagram.has_profile(scene):
        return found
    xs = _samples_only(scene, q)
    if not any(cam_diagram.part_at(scene, x)[0] == "base circle" for x in xs):
        return found
    runs = [(a, b) for part, a, b, _ in cam_diagram.parts(scene) if part == "base circle"]
    if len(runs) > 1 and runs[0][0] == 0.0 and runs[-1][1] == _TAU:    # one dwell round 0
        runs = [(runs[-1][0], runs[0][1])] + runs[1:-1]
    full = replace(q, range=None)       # an angle within the turn, in the question's unit
    spans = " and ".join(f"{_fmt(input_in_unit(full, a))} … {_fmt(input_in_unit(full, b))}"
                         for a, b in runs)
    words = (f"the follower dwells on the base circle (at rest, no linkage) from {spans} "
             f"{q.unit} (the nose axis's angle; its edges to the last bit): the quantity is "
             f"not taken there")
    return replace(found, words=f"{found.words}; {words}" if found.words else words)


def _samples_only(scene: Scene, q: Question) -> np.ndarray:
    if q.range is None:
        return cam_diagram.nose_axis(scene) + _TAU * np.arange(q.samples) / q.samples
    return np.linspace(q.range[0], q.range[1], q.samples)


def _answer(scene: Scene, q: Question) -> Finding:
    if q.find != "position" and not isinstance(scene.driver, Crank):
        raise SceneError("find = 'angle' or 'omega' needs a crank driver", file=scene.file,
                         where=q.where + ".find")
    cams = [e.at for e in getattr(scene, "equivalents", ()) if "cam" in e.kind]
    profile = cam_diagram.has_profile(scene)
    if profile:
        _cam_question(scene, q)
    elif cams:
        raise SceneError(f"the cam at {cams[0]} is replaced by its equivalent linkage at this "
                         f"instant only (the profile's part in contact changes as it turns): "
                         f"a question over a range of inputs is not served for it",
                         file=scene.file, where=q.where)
    f, dim = _measure(scene, q)
    xs, scenes, periodic = _samples(scene, q)
    fs = np.array([_safe(f, s) for s in scenes])
    if not np.isfinite(fs).any():
        raise SceneError(f"{show(q.quantity)} cannot be found at any instant of the range",
                         file=scene.file, where=q.where)
    n = len(xs)
    span = (xs[-1] - xs[0]) if not periodic else _TAU
    pairs = [(i, i + 1) for i in range(n - 1)] + ([(n - 1, 0)] if periodic else [])

    def x_of(i, j):     # the bracket's ends, unwrapped across a whole turn
        return xs[i], (xs[j] if j > i else xs[j] + _TAU)

    def at(x, i):
        return _safe(f, _restated(scene, q, x, scenes[i]))

    roots: list[Root] = []
    if q.condition in ("zero", "value"):
        target = q.value or 0.0
        g = fs - target
        finite = np.abs(fs[np.isfinite(fs)])
        noise = 1e-9 * max(float(finite.max()) if finite.size else 0.0, abs(target))
        for i, j in pairs:
            if not (math.isfinite(g[i]) and math.isfinite(g[j])):
                continue
            if g[i] == 0.0:
                roots.append(Root(xs[i], fs[i], "crossing", scenes[i]))
                continue
            if g[i] * g[j] < 0.0:
                a, b = x_of(i, j)
                x = brent(lambda x, i=i: at(x, i) - target, a, b, g[i], g[j])
                v = at(x, i)
                if abs(v - target) <= noise:     # the value asked, to rounding: say it
                    v = target                   # (a jump across it keeps its own value)
                roots.append(Root(x, v, "crossing", _restated(scene, q, x, scenes[i])))
        if not periodic and math.isfinite(g[-1]) and g[-1] == 0.0:
            roots.append(Root(xs[-1], fs[-1], "crossing", scenes[-1]))
        words = "" if roots else _never(q, xs, fs, periodic, span, scene)
        return Finding(q, tuple(sorted(roots, key=lambda r: input_in_unit(q, r.input))), None,
                       words, dim)

    h = _H * max(span, 1e-300) if q.find != "angle" else _H

    def slope(x, i):
        return (at(x + h, i) - at(x - h, i)) / (2 * h)

    extremes: list[Root] = []
    idx = range(n) if periodic else range(1, n - 1)
    for i in idx:
        lo, hi = (i - 1) % n, (i + 1) % n
        fl, fi, fh = fs[lo], fs[i], fs[hi]
        if not (math.isfinite(fl) and math.isfinite(fi) and math.isfinite(fh)):
            continue
        kind = "max" if fl < fi >= fh else "min" if fl > fi <= fh else None
        if kind is None:
            continue
        a = xs[lo] - (_TAU if lo > i else 0.0)
        b = xs[hi] + (_TAU if hi < i else 0.0)
        edge = _cam_edge(scene, q, a, b) if profile else None
        if edge is not None:        # a cam's part changes in the bracket: its edge's limits
            cands = [(xe, at(xe, i)) for xe in edge]      # and each side's own extreme
            for u, t in ((a, edge[0] - 2 * h), (edge[1] + 2 * h, b)):
                su, st = (slope(u, i), slope(t, i)) if u < t else (math.nan, math.nan)
                if math.isfinite(su) and math.isfinite(st) and su * st <= 0.0:
                    xb = brent(lambda x, i=i: slope(x, i), u, t, su, st)
                    cands.append((xb, at(xb, i)))
            cands = [c for c in cands if math.isfinite(c[1])] or [(xs[i], fi)]
            x, v = (max if kind == "max" else min)(cands, key=lambda c: c[1])
        else:
            sa, sb = slope(a, i), slope(b, i)
            if math.isfinite(sa) and math.isfinite(sb) and sa * sb <= 0.0:
                x = brent(lambda x, i=i: slope(x, i), a, b, sa, sb)
            else:                      # a cusp or an unbracketed slope: golden section
                x = golden_min(lambda x, i=i: (-1 if kind == "max" else 1) * at(x, i), a,
                               b)[0]
            v = at(x, i)
        if kind == "max" and fi > v or kind == "min" and fi < v:   # never worse than a sample
            x, v = xs[i], fi
        extremes.append(Root(x, v, kind, _restated(scene, q, x, scenes[i])))
    if not periodic:                       # the ends of the range may hold the extremes
        for i in (0, n - 1):
            if math.isfinite(fs[i]):
                extremes.append(Root(xs[i], fs[i], "end", scenes[i]))
    extremes.sort(key=lambda r: input_in_unit(q, r.input))
    scale = max(float(np.nanmax(np.abs(fs))), 1e-300)
    if q.condition == "stationary":
        found = [r for r in extremes if r.kind != "end"]
        words = "" if found else (f"{q.quantity} rises or falls throughout "
                                  f"{_range_words(q, xs, periodic)}: no stationary value")
        return Finding(q, tuple(found), None, words, dim)
    if not extremes:
        raise SceneError(f"no extreme of {show(q.quantity)} found in the range",
                         file=scene.file, where=q.where)
    top = max(r.value for r in extremes)
    bottom = min(r.value for r in extremes)
    tol = 1e-9 * scale
    maxima = [replace(r, kind="max") for r in extremes if r.value >= top - tol]
    minima = [replace(r, kind="min") for r in extremes if r.value <= bottom + tol]
    if q.condition == "max":
        return Finding(q, tuple(maxima), None, "", dim)
    if q.condition == "min":
        return Finding(q, tuple(minima), None, "", dim)
    # the cycle: dead centres at the least and the greatest value
    lo_r, hi_r = minima[0], maxima[0]
    if q.condition == "stroke":
        return Finding(q, (lo_r, hi_r), top - bottom, "", dim)
    if q.condition == "dead centres":
        both = sorted((lo_r, hi_r), key=lambda r: input_in_unit(q, r.input))
        return Finding(q, tuple(both), None, "", dim)
    sense = 1.0 if scene.driver.omega >= 0 else -1.0
    turn = math.fmod(sense * (hi_r.input - lo_r.input), _TAU) % _TAU   # least → greatest
    ratio = max(turn, _TAU - turn) / min(turn, _TAU - turn)
    return Finding(q, (lo_r, hi_r), ratio, "", dim)


def _range_words(q: Question, xs, periodic: bool) -> str:
    if periodic:
        return "the whole turn"
    return (f"{_fmt(input_in_unit(q, xs[0]))} {q.unit} to {_fmt(input_in_unit(q, xs[-1]))} "
            f"{q.unit}")


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _never(q: Question, xs, fs, periodic, span, scene) -> str:
    """The words of a condition that never holds in the range."""
    ok = np.isfinite(fs)
    lo, hi = int(np.nanargmin(np.where(ok, fs, np.inf))), int(np.nanargmax(
        np.where(ok, fs, -np.inf)))
    u = q.value_unit
    what = ("never changes sign" if q.condition == "zero" else
            f"never equals {_fmt(to_unit(q.value, u) if u else q.value)}"
            f"{' ' + u if u else ''}")
    text = (f"{q.quantity} {what} over {_range_words(q, xs, periodic)}: it runs from "
            f"{_fmt(to_unit(fs[lo], u) if u else fs[lo])} (at {_fmt(input_in_unit(q, xs[lo]))} "
            f"{q.unit}) to {_fmt(to_unit(fs[hi], u) if u else fs[hi])} (at "
            f"{_fmt(input_in_unit(q, xs[hi]))} {q.unit})")
    fn = q.quantity.split("(", 1)[0]
    if q.condition == "zero" and fn in ("v", "a", "an", "at", "cor", "dist") and fs[lo] >= 0:
        text += (f"; {fn}() is a magnitude, never negative: ask for its least value "
                 f"(condition = 'min') or a signed quantity (vs, x, y, omega)")
    return text


def answer_all(scene: Scene) -> list[Finding]:
    """Every ``[[questions]]`` entry of the scene, answered."""
    return [answer(scene, q) for q in scene_questions(scene)]


def scene_questions(scene: Scene) -> tuple[Question, ...]:
    """The scene's ``[[questions]]`` records (:func:`polygons.question_table.questions`)."""
    return questions(scene, parse_quantity_expr,
                     drawing_tolerance(scene.source, Reader(scene.file)))


# ------------------------------------------------------------------ checks and report
@dataclass(frozen=True)
class QuestionCheck:
    """A finding against the question's ``exact`` / ``tutorial`` / ``value_exact``."""

    finding: Finding
    exact_ok: bool | None
    tutorial_ok: bool | None
    value_ok: bool | None
    worst_rel: float | None


def _close(ours, theirs, rel: float, scale: float = 0.0) -> tuple[bool, float]:
    if len(ours) != len(theirs):
        return False, math.inf
    worst = 0.0
    for a, b in zip(ours, theirs):
        d = abs(a - b) / max(abs(b), scale, 1e-300)
        worst = max(worst, d)
    return worst <= rel, worst


def check(finding: Finding, exact_rel: float = 1e-9) -> QuestionCheck:
    """Compare a finding with the question's numbers: exact to ``exact_rel`` (relative to the
    larger of the number and a turn, for an angle: 0° is an angle too), the tutorial's within
    its tolerance."""
    q = finding.question
    got = finding.reported()
    scale = to_unit(_TAU, q.unit) if q.find == "angle" and q.condition not in (
        "stroke", "time ratio") else 0.0
    ex = tut = val = None
    worst = None
    if q.exact is not None:
        ex, worst = _close(got, q.exact, exact_rel, scale)
    if q.tutorial is not None:
        tut = _close(got, q.tutorial, q.tolerance, 0.0)[0]
    if q.value_exact is not None:
        vs = finding.values()
        val, w = _close(vs, q.value_exact, exact_rel, max(map(abs, q.value_exact), default=0))
        worst = max(worst or 0.0, w)
    return QuestionCheck(finding, ex, tut, val, worst)


def report_lines(findings: list[Finding]) -> list[str]:
    """The answers in words, one block per question."""
    out = []
    for k, fd in enumerate(findings):
        q = fd.question
        out.append(f"Q{k + 1}. {q.desc}")
        out.append(f"    find {q.find} where {q.quantity} {_cond_words(q, fd.dimension)}")
        if fd.words:
            out.append(f"    {fd.words}")
        if q.condition == "stroke":
            out.append(f"    stroke = {_fmt(to_unit(fd.result, q.unit))} {q.unit}")
        if q.condition == "time ratio":
            out.append(f"    time ratio = {_fmt(fd.result)}")
        # unstated, a value in the units the solve's table prints: angles in deg, lengths in mm
        vu = q.value_unit or _SHOWN.get(fd.dimension) or _si(fd.dimension)
        for j, r in enumerate(fd.roots):
            val = to_unit(r.value, vu) if vu != "-" else r.value
            iu = "deg" if q.condition in ("stroke", "time ratio") else q.unit
            st = as_stated(q, r)
            said = f" = {_fmt(st[1])} {iu} from {st[0]}" if st else ""
            out.append(f"    {j + 1}) {q.find} = {_fmt(input_in_unit(q, r.input))} {iu}"
                       f"{said}   {q.quantity} = {_fmt(val)} {vu}   ({r.kind})")
        c = check(fd)
        for label, ok in (("exact", c.exact_ok), ("tutorial", c.tutorial_ok),
                          ("value exact", c.value_ok)):
            if ok is not None:
                theirs = {"exact": q.exact, "tutorial": q.tutorial,
                          "value exact": q.value_exact}[label]
                out.append(f"    {label}: {', '.join(map(_fmt, theirs))} "
                           f"{'✓' if ok else '✗ differs'}")
    return out


def as_stated(q: Question, r: Root):
    """A root crank angle as the scene states its angle ('θ from idc', '60 deg CW from +y'):
    (the reference's words, θ in the question's unit, in [0, 360°)); None otherwise."""
    drv = r.scene.driver if r.scene is not None else None
    stated = getattr(drv, "stated", None)
    if q.find != "angle" or stated is None or cam_diagram.has_profile(r.scene):
        return None
    ref, base, turn = stated
    words = ref if turn > 0 or ref.lower() in ("idc", "odc", "tdc", "bdc") or "dead" in \
        ref.lower() else f"{ref} (CW)"
    theta = math.fmod(turn * (r.input - base), _TAU)
    theta = theta + _TAU if theta < 0 else theta
    unit = "deg" if q.condition in ("stroke", "time ratio") else q.unit
    return words, to_unit(0.0 if _TAU - theta <= 1e-9 * _TAU else theta, unit)


_SHOWN = {"angle": "deg", "length": "mm"}


def _si(dim: str) -> str:
    return next((u for u, (d, f) in UNITS.items() if d == dim and f == 1.0), "-")


def _cond_words(q: Question, dim: str) -> str:
    if q.condition == "value":
        shown = to_unit(q.value, q.value_unit) if q.value_unit else q.value
        return f"= {_fmt(shown)} {q.value_unit or _si(dim)}"
    return {"zero": "changes sign", "max": "is greatest", "min": "is least",
            "stationary": "is stationary", "stroke": "(its stroke over the turn)",
            "dead centres": "is at an extreme (the dead centres)",
            "time ratio": "(the time ratio of its two strokes)"}[q.condition]


def to_dict(findings: list[Finding]) -> list[dict]:
    """The answers for JSON: every root's input (in the question's unit and SI) and value."""
    out = []
    for fd in findings:
        q = fd.question
        c = check(fd)
        out.append({"find": q.find, "quantity": q.quantity, "condition": q.condition,
                    "unit": q.unit, "desc": q.desc, "words": fd.words,
                    "result": (to_unit(fd.result, q.unit) if q.condition == "stroke"
                               else fd.result),
                    "roots": [{"input": input_in_unit(q, r.input), "input_si": r.input,
                               "value": r.value, "kind": r.kind,
                               **({"as_stated": {"from": st[0], "input": st[1]}}
                                  if (st := as_stated(q, r)) else {})} for r in fd.roots],
                    "exact": list(q.exact) if q.exact is not None else None,
                    "exact_ok": c.exact_ok, "tutorial_ok": c.tutorial_ok,
                    "value_ok": c.value_ok})
    return out


__all__ = ["Root", "Finding", "QuestionCheck", "answer", "answer_all", "brent", "check",
           "report_lines", "to_dict", "CYCLE"]
