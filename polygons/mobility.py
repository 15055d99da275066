"""Mobility: does the scene move, and with how many inputs?  Checked before anything is solved.

Grübler–Kutzbach for plane mechanisms::

    F = 3 (n − 1) − 2 j₁ − j₂

with n the number of bodies including the frame, j₁ the lower pairs (each pin joining k bodies
counts k − 1 revolutes; each sliding pair one prismatic) and j₂ the higher pairs (none here: a
pin in a slot is modelled, as the textbooks draw it, by a sliding block pinned to the pin and
sliding in the slot).  The scene must have exactly as many degrees of freedom as it states
inputs: F = 0 is a locked structure (a frame), F < 0 an over-constrained one, F > inputs needs
more inputs.  After assembly, a link whose two ends were placed by other links (a redundant
link) must have its stated length.

The bodies and pairs are the mechanism model's (:mod:`polygons.model`, built once at load):
the frame, the links and slotted levers, a block for each slider, each pin in a slot and each
collar (a prescribed slide, a second input), a yoke for each Scotch yoke.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import SceneError
from .model import FRAME  # noqa: F401  (the frame's name, as the model writes it)
from .memo import memo_of



class MobilityError(SceneError):
    """The scene does not move with its stated inputs: locked, over-constrained, too few
    inputs, or a redundant link of the wrong length.  Carries the count as data."""

    def __init__(self, message: str, *, dof: int | None = None, links: tuple[str, ...] = (),
                 file: str | None = None, where: str | None = None):
        super().__init__(message, file=file, where=where)
        self.dof = dof
        self.links = links


@dataclass(frozen=True)
class Mobility:
    """The Grübler–Kutzbach count of a scene."""
    bodies: tuple[str, ...]       # moving bodies (the frame not included)
    revolutes: int                # j₁ from pins
    prismatics: int               # j₁ from sliding pairs
    inputs: tuple[str, ...]       # what the scene drives
    dof: int                      # F

    @property
    def formula(self) -> str:
        n = len(self.bodies) + 1
        j = self.revolutes + self.prismatics
        return f"F = 3({n} − 1) − 2 × {j} = {self.dof}"


def mobility(scene) -> Mobility:
    """F = 3(n − 1) − 2 j₁ − j₂ for the scene's mechanism model (:mod:`polygons.model`): a pin
    joining k bodies counts k − 1 revolutes, each sliding pair one prismatic."""
    model = scene.model
    revolutes = sum(len(p.bodies) - 1 for p in model.turning)
    prismatic = len(model.sliding)
    moving = tuple(b.name for b in model.moving)
    dof = 3 * len(moving) - 2 * (revolutes + prismatic)
    inputs = tuple(model.body(n).title for n in model.inputs)
    return Mobility(moving, revolutes, prismatic, inputs, dof)


def check_mobility(scene, redundant: tuple[str, ...] = ()) -> Mobility:
    """Refuse a scene whose degrees of freedom differ from its stated inputs; ``redundant``
    names the links no dyad needs (the planner's), blamed first when the scene is locked."""
    m = mobility(scene)
    k = len(m.inputs)
    links = tuple(b for b in m.bodies if b in scene.links)
    named = ", ".join(links)
    if m.dof == k:
        return m
    frame = [n for n, ln in scene.links.items() if ln.a in scene.ground and ln.b in scene.ground]
    if frame:              # not a locked structure: the mechanism moves, this link cannot
        n, ln = frame[0], scene.links[frame[0]]
        raise MobilityError(
            f"link {n} joins the fixed points {ln.a} and {ln.b}: it is part of the frame (the "
            f"fixed link, stated by [ground]), not a moving link, and redundant in [links]; "
            f"remove it", dof=m.dof, links=tuple(frame), file=scene.file, where=f"links.{n}")
    blame = (f"{', '.join(redundant)} {'is' if len(redundant) == 1 else 'are'} redundant "
             f"(both ends already placed by the other links)" if redundant else
             "remove the redundant link")
    if m.dof == 0:
        raise MobilityError(
            f"the links {named} form a locked structure (a frame), not a mechanism: "
            f"Grübler–Kutzbach gives {m.formula} degrees of freedom, so the input "
            f"{m.inputs[0]} cannot move; {blame}", dof=m.dof, links=redundant or links,
            file=scene.file, where=f"links.{redundant[0]}" if redundant else "links")
    if m.dof < 0:
        raise MobilityError(
            f"the links {named} are over-constrained (a statically indeterminate structure): "
            f"Grübler–Kutzbach gives {m.formula} degrees of freedom; {blame}", dof=m.dof,
            links=redundant or links, file=scene.file,
            where=f"links.{redundant[0]}" if redundant else "links")
    if m.dof > k:
        more = ("1 more input (another driver)" if m.dof - k == 1 else
                f"{m.dof - k} more inputs (more drivers)")
        raise MobilityError(
            f"the mechanism has {m.dof} degrees of freedom ({m.formula}) but {k} input"
            f"{'' if k == 1 else 's'} ({', '.join(m.inputs)}): it needs {more} before it is "
            f"constrained; the links are {named}", dof=m.dof, links=links, file=scene.file,
            where="driver")
    raise MobilityError(
        f"the mechanism has {m.dof} degree of freedom ({m.formula}) but {k} inputs "
        f"({', '.join(m.inputs)}): the inputs fight each other", dof=m.dof, links=links,
        file=scene.file, where="driver")


def used_links(dyads) -> set[str]:
    """The links the ``dyads`` place a point with (all others are redundant)."""
    used: set[str] = set()
    for d in dyads:
        for attr in ("link", "link_p", "link_q", "lever"):
            name = getattr(d, attr, None)
            if name:
                used.add(name)
        used.update(getattr(d, "links", ()))
    return used


def _unused(plan) -> tuple[str, ...]:
    """The links with a length that no dyad of ``plan`` uses (kept with the frozen plan)."""
    memo = memo_of(plan)
    if "_unused" not in memo:
        used = used_links(plan.dyads)
        memo["_unused"] = tuple(n for n, ln in plan.scene.links.items()
                                if n not in used and ln.length is not None)
    return memo["_unused"]


def check_redundant_lengths(scene, plan, points, rel: float = 1e-9) -> None:
    """A link whose two ends are placed by other means must have its stated length."""
    for name in _unused(plan):
        link = scene.links[name]
        if link.a not in points or link.b not in points:
            continue
        (ax, ay), (bx, by) = points[link.a], points[link.b]
        actual = math.hypot(bx - ax, by - ay)
        if abs(actual - link.length) > rel * max(link.length, actual):
            raise MobilityError(
                f"link {name} is {1e3 * link.length:.6g} mm in [links], but its ends {link.a} "
                f"and {link.b} are placed {1e3 * actual:.6g} mm apart by the other links: a "
                f"redundant link must fit exactly (or remove it)", links=(name,),
                file=scene.file, where=f"links.{name}")
