"""Position analysis: assemble the mechanism at the given input, dyad by dyad, in closed form.

Each dyad has at most two closures; the scene's ``[assembly]`` entry says which one, in the
tutorial's words ("C below AD", "B right of O") or as an approximate position.  When two
closures exist and the scene does not say, we stop with a :class:`BranchError` that describes
both: nothing is guessed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import numpy as np

from .dyads.base import size_of
from .dyads.numeric import Stated, interpret_floats
from .dyads.primitives import Constructed
from .errors import AssemblyError, BranchError, PolygonsError
from .mobility import check_redundant_lengths
from .plan import Plan
from .scene import Branch, Crank, Scene


#: a [drawn] position may differ from the assembled one by this fraction of the mechanism size
DRAWN_TOL = 1e-3
#: ``near`` chooses a closure of a class-III group only when the next is farther by this
#: factor (the chosen one at most this fraction of the next one's distance)
NEAR_CLEAR = 0.5


@dataclass(frozen=True)
class Placement:
    """Where every point is, and which closure was taken for each two-closure dyad."""

    points: dict
    branches: tuple[tuple[str, str], ...]   # (label, description of the chosen closure)
    sigmas: Mapping[str, float] = field(default_factory=dict)   # label -> closure (+1 / −1)


def assemble(plan: Plan) -> Placement:
    """Place every dyad of ``plan`` at the scene's input, in order; each two-closure dyad's
    closure is chosen by the scene's words (:func:`_choose`).  Over plain floats where every
    group is one stated primitive and nothing fails (:func:`_assemble_floats`: the same
    numbers), else over arrays — where every refusal is made."""
    fast = _assemble_floats(plan)
    return fast if fast is not None else _assemble_arrays(plan)


def _assemble_arrays(plan: Plan) -> Placement:
    """:func:`assemble` over numpy arrays (each group's ``locate``), every refusal made."""
    scene = plan.scene
    pos: dict[str, np.ndarray] = {k: np.array(v, dtype=float) for k, v in scene.ground.items()}
    chosen: list[tuple[str, str]] = []
    sigmas: dict[str, float] = {}
    size = size_of(scene)
    x_in = driver_input(scene)
    with np.errstate(all="ignore"):   # a degenerate dyad gives NaN and says why below
        _place(plan, scene, pos, chosen, sigmas, size, x_in)
    _check_rod_angle(scene, pos)
    for label, xy in scene.drawn.items():
        if label in pos:
            off = float(np.hypot(*(pos[label] - np.array(xy))))
            if off > DRAWN_TOL * size:
                raise AssemblyError(
                    f"{label} is drawn at {_fmt(np.array(xy))} but the links put it at "
                    f"{_fmt(pos[label])} ({1e3 * off:.4g} mm away): the drawing and the lengths "
                    f"disagree", file=scene.file, where=f"drawn.{label}")
    points = {k: (float(v[0]), float(v[1])) for k, v in pos.items()}
    check_redundant_lengths(scene, plan, points)
    return Placement(points, tuple(chosen), MappingProxyType(sigmas))


def _assemble_floats(plan: Plan) -> Placement | None:
    """:func:`assemble` with every point a plain float pair, each group's statement run
    through :func:`~polygons.dyads.numeric.interpret_floats` (the statement :func:`assemble`
    runs, so the same numbers and the same closures): None — :func:`assemble` then does it
    over arrays and makes the refusal — where a group is not one stated primitive (a group
    of several closures), the scene has [drawn] positions, a number is an array, a closure
    fails or the words refuse."""
    scene = plan.scene
    if scene.drawn:
        return None
    x_in = driver_input(scene)
    pos = {}
    for k, (x, y) in scene.ground.items():
        if type(x) is not float or type(y) is not float:     # (a batch's arrays)
            return None
        pos[k] = (x, y)
    chosen: list[tuple[str, str]] = []
    sigmas: dict[str, float] = {}
    size = size_of(scene)
    try:
        for dyad in plan.dyads:
            prim = getattr(dyad, "construction", None)
            if (type(dyad).locate is not Constructed.locate or not isinstance(prim, Stated)
                    or type(prim).locate is not Stated.locate
                    or getattr(dyad, "many_closures", False)):
                return None
            if dyad.two_closures:
                x = dyad.placed[0]
                got = interpret_floats(prim, scene, pos, 1.0, x_in)
                if got is None or not got[1] >= 0:
                    return None
                c1 = got[0]
                c2 = interpret_floats(prim, scene, pos, -1.0, x_in)[0]
                pick, why = _choose(x, (c1[x], c2[x]), scene, pos, size,
                                    default_ref=dyad.default_ref)
                c = c1 if pick is c1[x] else c2
                sigmas[x] = 1.0 if c is c1 else -1.0
                for label in dyad.placed:
                    pos[label] = c[label]
                if why:
                    chosen.append((x, why))
                continue
            got = interpret_floats(prim, scene, pos, None, x_in)
            if got is None or got[1] is not None and not got[1] > 0:
                return None
            pos.update(got[0])
            _check_words(got[0], scene, pos)
        _check_rod_angle(scene, pos)    # refused over arrays, below
    except PolygonsError:
        return None
    points = {k: (float(v[0]), float(v[1])) for k, v in pos.items()}
    check_redundant_lengths(scene, plan, points)
    return Placement(points, tuple(chosen), MappingProxyType(sigmas))


def _place(plan: Plan, scene: Scene, pos, chosen, sigmas, size, x_in) -> None:
    """Each dyad's ``locate`` in order; a closure that fails says why in the dyad's words."""
    for dyad in plan.dyads:
        if getattr(dyad, "many_closures", False):
            pts, why = _choose_group(dyad, scene, pos, size)
            pos.update(pts)
            ref = (pts[dyad.b][0], pts[dyad.b][1], pts[dyad.x][0], pts[dyad.x][1])
            sigmas.update(zip(dyad.sigma_keys, (float(v) for v in ref)))
            if why:
                chosen.append((dyad.b, why))
            continue
        if dyad.two_closures:
            x = dyad.placed[0]
            c1, m1 = dyad.locate(scene, pos, 1.0, x_in)
            if not m1 >= 0:
                raise AssemblyError(dyad.why_not(scene, pos), file=scene.file, where=x)
            c2, _ = dyad.locate(scene, pos, -1.0, x_in)
            pos[x], why = _choose(x, (c1[x], c2[x]), scene, pos, size,
                                  default_ref=dyad.default_ref)
            sigmas[x] = 1.0 if pos[x] is c1[x] else -1.0
            for other in dyad.placed[1:]:      # points placed with x (a lever's point under it)
                pos[other] = (c1 if pos[x] is c1[x] else c2)[other]
            if why:
                chosen.append((x, why))
            continue
        pts, margin = dyad.locate(scene, pos, None, x_in)
        if margin is not None and not margin > 0:
            raise dyad_failure(scene, dyad, pos)
        pos.update(pts)
        _check_words(pts, scene, pos)


def _check_words(pts, scene: Scene, pos) -> None:
    """Points with one position: [assembly] words about them must hold there (refused, not
    silently passed over, when the scene's words describe another configuration)."""
    for x, xy in pts.items():
        branch = scene.assembly.get(x)
        if branch is None or branch.relation == "near" or np.ndim(xy) != 1 \
                or any(r not in pos for r in branch.ref):
            continue
        if not satisfies(branch, xy, pos, scene):
            raise BranchError(f"{x} has one position here, {_fmt(xy)}, and it is not "
                              f"'{branch.text}': the [assembly] words describe another "
                              f"configuration (check the data, or leave the words out)",
                              file=scene.file, where=f"assembly.{x}")


def _check_rod_angle(scene: Scene, pos) -> None:
    """A slider driver placed by its rod's angle with [assembly] words for the rod's far end:
    the closure the words chose must put the rod at its stated angle (the mirror closure,
    the rod at another angle, was answered silently before)."""
    end = getattr(scene.driver, "rod_end", None)
    if end is None or scene.driver.position != end[3]:
        return                          # another position (a sweep, a question): no angle
    name, other, angle = end[:3]
    if other not in pos or scene.driver.point not in pos:
        return                          # a solve of some targets only: the rod not placed
    (ox, oy), (sx, sy) = pos[other], pos[scene.driver.point]
    dx, dy = float(ox) - float(sx), float(oy) - float(sy)
    got = math.atan2(dy, dx)
    if abs(math.remainder(got - angle, 2.0 * math.pi)) > 1e-7:
        branch = scene.assembly[other]
        raise BranchError(f"'{branch.text}' puts {other} at {_fmt(pos[other])}, where the rod "
                          f"{name} is at {math.degrees(got) % 360.0:.6g}°, not at its stated "
                          f"rod_angle {math.degrees(angle) % 360.0:.6g}°: the words choose the "
                          f"other closure (leave them out: the rod's angle places {other})",
                          file=scene.file, where=f"assembly.{other}")


def dyad_failure(scene: Scene, d, pos) -> AssemblyError:
    """The error of dyad ``d`` that cannot close on the points ``pos``, in its own words,
    under its key (the lever's name for a slot, else the point it places)."""
    return AssemblyError(d.why_not(scene, pos), file=scene.file,
                         where=getattr(d, "lever", None) or d.placed[0])


def driver_input(scene: Scene) -> float:
    """The driver's input at the scene's instant: θ (rad) of a crank, s (m) of a slider."""
    drv = scene.driver
    return drv.angle if isinstance(drv, Crank) else drv.position


def satisfies(branch: Branch, cand, pos, scene: Scene) -> bool:
    """Whether candidate position ``cand`` satisfies the scene's wording of the closure."""
    rel = branch.relation
    if rel == "near":
        raise AssertionError("near is decided by distance")
    if not branch.ref:
        raise BranchError(f"'{branch.text}' compares the corners of a class-III group, and "
                          f"{branch.label} is not one; say '{branch.label} above' a point or "
                          f"a line",
                          file=scene.file, where=f"assembly.{branch.label}")
    for r in branch.ref:
        if r not in pos:
            raise BranchError(f"'{branch.text}' refers to {r}, which is not placed before "
                              f"{branch.label}", file=scene.file, where=f"assembly.{branch.label}")
    if rel in ("open", "crossed"):     # a four-bar A–B–C–D: crossed when two links cross
        (b, d, a), c = (tuple(map(float, pos[k])) for k in branch.ref), tuple(map(float, cand))
        crossed = _cross(a, b, c, d) or _cross(b, c, d, a)      # AB × CD or BC × DA
        return crossed if rel == "crossed" else not crossed
    if len(branch.ref) == 1:
        ref = pos[branch.ref[0]]
        return {"above": cand[1] > ref[1], "below": cand[1] < ref[1],
                "left of": cand[0] < ref[0], "right of": cand[0] > ref[0]}[rel]
    (ax, ay), (bx, by) = pos[branch.ref[0]], pos[branch.ref[1]]
    dx, dy = float(bx - ax), float(by - ay)
    side = dx * (float(cand[1]) - ay) - dy * (float(cand[0]) - ax)      # (B − A) × (X − A)
    scale = math.hypot(dx, dy)
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
    if math.hypot(float(c1[0] - c2[0]), float(c1[1] - c2[1])) <= 1e-12 * size:
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
        nx, ny = branch.near
        d1 = math.hypot(float(c1[0]) - nx, float(c1[1]) - ny)
        d2 = math.hypot(float(c2[0]) - nx, float(c2[1]) - ny)
        if abs(d1 - d2) <= 1e-9 * size:
            raise BranchError(f"'{branch.text}' is equally near both closures {_fmt(c1)} and "
                              f"{_fmt(c2)}", file=scene.file, where=where)
        pick = c1 if d1 < d2 else c2
        return pick, f"{branch.text} → {_fmt(pick)}"
    ok = [c for c in (c1, c2) if satisfies(branch, c, pos, scene)]
    if len(ok) != 1:
        raise BranchError(f"{'both' if ok else 'neither'} of the closures {_fmt(c1)} and "
                          f"{_fmt(c2)} {'satisfy' if ok else 'satisfies'} '{branch.text}'; "
                          f"use another reference or "
                          f"near = [...]", file=scene.file, where=where)
    return ok[0], f"{branch.text} → {_fmt(ok[0])}"


def _choose_group(dyad, scene: Scene, pos, size):
    """The closure of a group with several (a triad: up to six) that the scene's words choose:
    ``[assembly]`` on any of its points (words or ``near``), or its [drawn] positions; one
    closure needs no words.  Returns (points, description)."""
    cands = dyad.closures(scene, pos)
    if not cands:
        raise AssemblyError(dyad.why_not(scene, pos), file=scene.file, where=dyad.placed[0])
    labels = dyad.placed[:3]
    stated = [(k, scene.assembly[k]) for k in labels if k in scene.assembly]
    stated += [(k, Branch(k, f"{k} as drawn", "near", near=scene.drawn[k])) for k in labels
               if k in scene.drawn and k not in scene.assembly]
    listing = "; ".join(", ".join(f"{k} {_fmt(c[k])}" for k in labels) for c in cands)
    if not stated:
        if len(cands) == 1:
            return cands[0], ""
        k = labels[-1]
        raise BranchError(
            f"the class-III group {''.join(labels)} has {len(cands)} closures ({listing}); say "
            f"which in [assembly], e.g. {k} = {{ near = [x, y] }} or {k} = \"{k} above ...\"",
            file=scene.file, where=f"assembly.{k}")
    ok = list(cands)
    for k, branch in stated:
        if branch.relation == "near":
            nx, ny = branch.near
            dist = [math.hypot(float(c[k][0]) - nx, float(c[k][1]) - ny) for c in ok]
            order = sorted(range(len(ok)), key=dist.__getitem__)
            if len(ok) > 1 and not dist[order[0]] < NEAR_CLEAR * dist[order[1]]:
                i, j = order[:2]
                raise BranchError(
                    f"'{branch.text}' is not clearly nearer one closure of the class-III group "
                    f"{''.join(labels)}: {k} {_fmt(ok[i][k])} is {1e3 * dist[i]:.4g} mm away and "
                    f"{k} {_fmt(ok[j][k])} {1e3 * dist[j]:.4g} mm (of {len(cands)} closures: "
                    f"{listing}); give a nearer point", file=scene.file,
                    where=f"assembly.{k}")
            ok = [ok[order[0]]]
        elif not branch.ref:        # 'D uppermost': the extreme of the group's corners
            ok = [c for c in ok if _extreme(branch.relation, k, c, labels)]
        else:       # words may name another corner of the group ("C lower than B")
            ok = [c for c in ok if satisfies(branch, c[k], {**pos, **c}, scene)]
    if len(ok) != 1:
        words = " and ".join(f"'{b.text}'" for _, b in stated)
        raise BranchError(f"{'more than one' if ok else 'none'} of the {len(cands)} closures "
                          f"of the class-III group {''.join(labels)} ({listing}) satisfies "
                          f"{words}; add words for another corner or near = [...]",
                          file=scene.file, where=f"assembly.{stated[0][0]}")
    pick = ok[0]
    others = [max(math.dist(pick[k], c[k]) for k in labels) for c in cands if c is not pick]
    apart = (f"; {len(cands)} closures, the next {1e3 * min(others):.4g} mm away" if others
             else "; the only closure")
    return pick, (f"{' and '.join(b.text for _, b in stated)} → "
                  f"{', '.join(f'{k} {_fmt(pick[k])}' for k in labels)}{apart}")


def _cross(p, q, r, s) -> bool:
    """Whether the segments PQ and RS cross at a point inside both (a touch is no crossing)."""
    def turn(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    return turn(p, q, r) * turn(p, q, s) < 0 and turn(r, s, p) * turn(r, s, q) < 0


def _extreme(rel: str, k: str, c, labels) -> bool:
    """Whether corner ``k`` is the ``rel`` ('uppermost', 'lowest', 'leftmost', 'rightmost')
    of the corners ``labels`` in the closure ``c``."""
    axis, sign = {"uppermost": (1, 1.0), "lowest": (1, -1.0), "rightmost": (0, 1.0),
                  "leftmost": (0, -1.0)}[rel]
    return all(sign * float(c[k][axis]) > sign * float(c[o][axis]) for o in labels if o != k)


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
