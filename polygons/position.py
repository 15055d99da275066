"""Position analysis: assemble the mechanism at the given input, dyad by dyad, in closed form.

Each dyad has at most two closures; the scene's ``[assembly]`` entry says which one, in the
tutorial's words ("C below AD", "B right of O") or as an approximate position.  When two
closures exist and the scene does not say, we stop with a :class:`BranchError` that describes
both: nothing is guessed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import AssemblyError, BranchError
from .plan import RPP, RPR, RRP, RRR, CrankDyad, Image, Plan, SliderDriveDyad
from .scene import Branch, Crank, Scene
from .theorems import cross, perp


#: a [drawn] position may differ from the assembled one by this fraction of the mechanism size
DRAWN_TOL = 1e-3


@dataclass(frozen=True)
class Placement:
    """Where every point is, and which closure was taken for each two-closure dyad."""

    points: dict
    branches: tuple[tuple[str, str], ...]   # (label, description of the chosen closure)


def assemble(plan: Plan) -> Placement:
    scene = plan.scene
    pos: dict[str, np.ndarray] = {k: np.array(v, dtype=float) for k, v in scene.ground.items()}
    chosen: list[tuple[str, str]] = []
    size = _size(scene)
    for dyad in plan.dyads:
        if isinstance(dyad, CrankDyad):
            drv: Crank = scene.driver  # type: ignore[assignment]
            length = scene.links[dyad.link].length
            pos[dyad.tip] = pos[dyad.pivot] + length * np.array([math.cos(drv.angle),
                                                                 math.sin(drv.angle)])
        elif isinstance(dyad, SliderDriveDyad):
            g = scene.sliders[dyad.point]
            pos[dyad.point] = np.array(g.through) + scene.driver.position * np.array(g.direction)
        elif isinstance(dyad, RRR):
            r1 = scene.links[dyad.link_p].length
            r2 = scene.links[dyad.link_q].length
            cands = _circle_circle(pos[dyad.p], r1, pos[dyad.q], r2, dyad, scene)
            pos[dyad.x], why = _choose(dyad.x, cands, scene, pos, size,
                                       default_ref=(dyad.p, dyad.q))
            if why:
                chosen.append((dyad.x, why))
        elif isinstance(dyad, RRP):
            g = scene.sliders[dyad.x]
            cands = _circle_line(pos[dyad.p], scene.links[dyad.link].length, g, dyad, scene)
            pos[dyad.x], why = _choose(dyad.x, cands, scene, pos, size, default_ref=(dyad.p,))
            if why:
                chosen.append((dyad.x, why))
        elif isinstance(dyad, RPR):
            d = pos[dyad.pin] - pos[dyad.pivot]
            s = float(np.hypot(*d))
            if s <= 1e-12 * size:
                raise AssemblyError(f"the pin {dyad.pin} is on the pivot {dyad.pivot} of lever "
                                    f"{dyad.lever}: the slot direction is undefined",
                                    file=scene.file, where=dyad.lever)
            pos[dyad.coincident] = pos[dyad.pin].copy()
            if dyad.far:
                pos[dyad.far] = pos[dyad.pivot] + scene.slots[dyad.pin].far_length * d / s
        elif isinstance(dyad, Image):
            pos[dyad.x] = body_point(scene, dyad, pos)
        elif isinstance(dyad, RPP):    # Scotch yoke: guide line ∩ slot line through the pin
            g = scene.sliders[dyad.x]
            e, f = np.array(g.direction), np.array(g.slot_direction)
            t = cross(pos[dyad.pin] - np.array(g.through), f) / cross(e, f)
            pos[dyad.x] = np.array(g.through) + t * e
    for label, xy in scene.drawn.items():
        if label in pos:
            off = float(np.hypot(*(pos[label] - np.array(xy))))
            if off > DRAWN_TOL * size:
                raise AssemblyError(
                    f"{label} is drawn at {_fmt(np.array(xy))} but the links put it at "
                    f"{_fmt(pos[label])} ({1e3 * off:.4g} mm away): the drawing and the lengths "
                    f"disagree", file=scene.file, where=f"drawn.{label}")
    return Placement({k: (float(v[0]), float(v[1])) for k, v in pos.items()}, tuple(chosen))


def body_point(scene: Scene, dyad: Image, pos) -> np.ndarray:
    bp = scene.points[dyad.x]
    d = pos[dyad.q] - pos[dyad.p]
    n = float(np.hypot(*d))
    if n == 0.0:
        raise AssemblyError(f"link {dyad.link} has zero length at this instant, so {dyad.x} "
                            f"cannot be placed on it", file=scene.file, where=dyad.x)
    u = d / n
    along = bp.along if bp.along is not None else bp.fraction * n
    return pos[dyad.p] + along * u + bp.left * perp(u)


def _size(scene: Scene) -> float:
    lengths = [l.length for l in scene.links.values() if l.length]
    coords = [abs(c) for v in scene.ground.values() for c in v]
    return max(lengths + coords + [1e-300])


def _circle_circle(p, r1, q, r2, dyad: RRR, scene: Scene):
    d = q - p
    dist = float(np.hypot(*d))
    if dist == 0.0:
        raise AssemblyError(f"{dyad.p} and {dyad.q} coincide, so {dyad.x} is not fixed by "
                            f"{dyad.link_p} and {dyad.link_q}", file=scene.file, where=dyad.x)
    a = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist)
    h2 = r1 * r1 - a * a
    tol = 1e-12 * max(r1, r2, dist) ** 2
    if h2 < -tol:
        if dist > r1 + r2:
            why = (f"{dyad.link_p} + {dyad.link_q} = {1e3 * (r1 + r2):.6g} mm is shorter than "
                   f"{dyad.p}{dyad.q} = {1e3 * dist:.6g} mm")
        else:
            why = (f"|{dyad.link_p} − {dyad.link_q}| = {1e3 * abs(r1 - r2):.6g} mm is longer "
                   f"than {dyad.p}{dyad.q} = {1e3 * dist:.6g} mm")
        raise AssemblyError(f"the links cannot close at this input: {why}, so {dyad.x} "
                            f"cannot be placed", file=scene.file, where=dyad.x)
    h = math.sqrt(max(h2, 0.0))
    u = d / dist
    base = p + a * u
    return [base + h * perp(u), base - h * perp(u)]


def _circle_line(p, length, guide, dyad: RRP, scene: Scene):
    e = np.array(guide.direction)
    g = np.array(guide.through)
    w = g - p
    bq = float(e @ w)
    c = float(w @ w) - length * length
    disc = bq * bq - c
    if disc < -1e-12 * length * length:
        dist = abs(cross(e, -w))
        raise AssemblyError(f"the links cannot close at this input: {dyad.link} = "
                            f"{1e3 * length:.6g} mm cannot reach the guide of {dyad.x}, which "
                            f"is {1e3 * dist:.6g} mm from {dyad.p}", file=scene.file,
                            where=dyad.x)
    root = math.sqrt(max(disc, 0.0))
    return [g + (-bq + root) * e, g + (-bq - root) * e]


def satisfies(branch: Branch, cand, pos, scene: Scene) -> bool:
    """Whether candidate position ``cand`` satisfies the scene's wording of the closure."""
    rel = branch.relation
    if rel == "near":
        raise AssertionError("near is decided by distance")
    for r in branch.ref:
        if r not in pos:
            raise BranchError(f"'{branch.text}' refers to {r}, which is not placed before "
                              f"{branch.label}", file=scene.file, where=f"assembly.{branch.label}")
    if len(branch.ref) == 1:
        ref = pos[branch.ref[0]]
        return {"above": cand[1] > ref[1], "below": cand[1] < ref[1],
                "left of": cand[0] < ref[0], "right of": cand[0] > ref[0]}[rel]
    a, b = pos[branch.ref[0]], pos[branch.ref[1]]
    side = cross(b - a, cand - a)
    dx, dy = b[0] - a[0], b[1] - a[1]
    scale = float(np.hypot(dx, dy))
    if rel in ("above", "below"):
        if abs(dx) <= 1e-9 * scale:
            raise BranchError(f"'{branch.text}': the line {''.join(branch.ref)} is vertical; "
                              f"say 'left of' or 'right of' instead", file=scene.file,
                              where=f"assembly.{branch.label}")
        up = side * math.copysign(1.0, dx) > 0
        return up if rel == "above" else not up
    if abs(dy) <= 1e-9 * scale:
        raise BranchError(f"'{branch.text}': the line {''.join(branch.ref)} is horizontal; "
                          f"say 'above' or 'below' instead", file=scene.file,
                          where=f"assembly.{branch.label}")
    left = side * math.copysign(1.0, dy) > 0
    return left if rel == "left of" else not left


def _choose(x, cands, scene: Scene, pos, size, default_ref):
    c1, c2 = cands
    if float(np.hypot(*(c1 - c2))) <= 1e-12 * size:
        return c1, ""   # a single (double) closure: nothing to choose
    branch = scene.assembly.get(x)
    where = f"assembly.{x}"
    if branch is None and x in scene.drawn:
        branch = Branch(x, f"{x} as drawn", "near", near=scene.drawn[x])
    if branch is None:
        raise BranchError(
            f"{x} has two closures, {_fmt(c1)} and {_fmt(c2)}; say which in [assembly], e.g. "
            f"{x} = \"{_suggest_words(x, c1, c2, pos, default_ref)}\" or "
            f"{x} = {{ near = [...] }}", file=scene.file, where=where)
    if branch.relation == "near":
        near = np.array(branch.near)
        d1, d2 = float(np.hypot(*(c1 - near))), float(np.hypot(*(c2 - near)))
        if abs(d1 - d2) <= 1e-9 * size:
            raise BranchError(f"'{branch.text}' is equally near both closures {_fmt(c1)} and "
                              f"{_fmt(c2)}", file=scene.file, where=where)
        pick = c1 if d1 < d2 else c2
        return pick, f"{branch.text} → {_fmt(pick)}"
    ok = [c for c in (c1, c2) if satisfies(branch, c, pos, scene)]
    if len(ok) != 1:
        raise BranchError(f"{'both' if ok else 'neither'} of the closures {_fmt(c1)} and "
                          f"{_fmt(c2)} satisfies '{branch.text}'; use another reference or "
                          f"near = [...]", file=scene.file, where=where)
    return ok[0], f"{branch.text} → {_fmt(ok[0])}"


def _fmt(c) -> str:
    return f"({1e3 * c[0]:.4g}, {1e3 * c[1]:.4g}) mm"


def _suggest_words(x, c1, c2, pos, refs) -> str:
    for rel in ("above", "below", "right of", "left of"):
        for ref in ([refs] if len(refs) == 2 else []) + [(r,) for r in refs]:
            b = Branch(x, "", rel, tuple(ref))
            try:
                s1 = satisfies(b, c1, pos, _NoScene)
                s2 = satisfies(b, c2, pos, _NoScene)
            except BranchError:
                continue
            if s1 != s2:
                return f"{x} {rel} {''.join(ref)}"
    return f"{x} above {refs[0]}"


class _NoScene:
    file = None
