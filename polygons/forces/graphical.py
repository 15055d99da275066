"""Force polygons per Assur group: the drawing board's static force analysis (with d'Alembert's
inertia forces), group by group from the one furthest from the driver to the crank.

The plan's dyads (:mod:`polygons.plan`) in reverse order are the groups.  Each group is
separated at its outer pins, its loads and inertia forces applied (the inertia force −m a_G
moved off the centre of mass by h = I_G α / (m a_G) so that it carries the inertia couple
too), the forces that the groups already solved pass on through shared pins added, and the
force polygon closed on the unknown reactions:

* **RRR** (P — X — Q; links PX, QX): each outer pin's reaction is split into a component
  normal to its link, found by moments about the middle pin X of that link alone, and one
  along the link; the polygon of the whole group then closes on the two along-link
  components (two lines of known direction).  The middle pin's force follows from one link's
  polygon;
* **RRP** (P — X, X a slider on a fixed guide): the pin P's normal component by moments about
  X, then the polygon closes on the along-link component and the guide's normal force; the
  guide couple from the block's moments;
* the **crank** (the driver, last): its bearing force closes its polygon, the input torque is
  the moment about its pivot; a **slider driver**: the input force along the guide and the
  guide normal close the block's polygon.

A pin is carried with the body placed first (the frame, or the group's first link): the forces
later groups pass on through a pin act on that body.  Each reaction is returned as the force
on a body at a pin, the same as :func:`polygons.forces.newton_euler.newton_euler`'s, and the
tests hold them equal to 1e-9.  Kinds the construction does not handle are refused in one line
naming the kind (:data:`HANDLES`, :data:`GROUP_KINDS`).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..dyads import RRP, RRR, CrankDyad, Image, SliderDriveDyad
from ..errors import UnsupportedError
from ..model import FRAME, check_handles
from ..plan import make_plan
from .model import cross, perp, position
from .states import Analysis, State

#: the kinds of body and pair the construction handles (polygons.model)
HANDLES = frozenset({"frame", "link", "block", "turning", "sliding"})
#: the plan's dyads it handles: the driver (crank or slider), RRR, RRP, points on links
GROUP_KINDS = (CrankDyad, SliderDriveDyad, RRR, RRP, Image)
METHOD = "the force-polygon construction"


@dataclass(frozen=True)
class Known:
    """A force (``force`` at ``pos``) and/or couple on ``body`` known when its group is drawn:
    a load, a weight, an inertia force (at its offset point), or a force passed on by a group
    already solved (``kind`` 'transmitted')."""
    name: str
    kind: str
    body: str
    force: np.ndarray
    pos: np.ndarray | None
    couple: float = 0.0
    offset: float = 0.0        # an inertia force: h = I_G α / (m a_G), m


@dataclass(frozen=True)
class Found:
    """A force the polygon found: on ``body`` at ``at`` along the unit ``direction``, signed
    ``value`` (N); ``how`` 'moments' (normal components), 'polygon' (the closing sides),
    'effort' (the input), 'reaction' (a pin force read as a diagonal)."""
    name: str
    body: str
    at: str
    direction: np.ndarray
    value: float
    how: str

    @property
    def force(self) -> np.ndarray:
        return self.value * self.direction


@dataclass(frozen=True)
class Group:
    """One group's construction: its bodies, what was known, what the polygon found."""
    index: int                 # 1 = the driver
    kind: str                  # 'crank', 'slider driver', 'RRR', 'RRP'
    title: str
    bodies: tuple[str, ...]
    knowns: tuple[Known, ...]
    normals: tuple[Found, ...]         # by moments (first)
    closing: tuple[Found, ...]         # closing the polygon
    reactions: tuple[Found, ...]       # diagonals (the middle pin) and resultants
    moments: tuple[str, ...]           # the moment equations in words


@dataclass(frozen=True)
class ForcePolygons:
    state: str
    groups: tuple[Group, ...]          # in the order drawn: furthest first, the driver last
    pin: dict                          # (label, body) -> force on body from the pin
    ground: dict                       # label -> force on the ground
    guide: dict                        # label -> (normal force, unit normal, couple)
    effort: float                      # the input torque (N m) or force (N)


def _refuse(kind: str, where: str, file) -> UnsupportedError:
    return UnsupportedError(f"{METHOD} does not handle {kind} ({where}); Newton–Euler and "
                            f"Zhukovsky's lever do", file=file)


def groups_of(scene):
    """(kind, dyad, bodies) of each group, the driver first; refused in one line naming any
    kind the construction does not handle."""
    file = scene.file
    check_handles(METHOD, HANDLES, scene.model, file)
    if scene.loads is not None and scene.loads.effort is not None:
        e = scene.loads.effort
        if not (e.kind in ("torque", "force") and e.body == scene.loads.driver_body):
            raise UnsupportedError(f"{METHOD} finds the driver's effort, group by group to "
                                   f"the driver; [dynamics] effort = {e.text!r} is found by "
                                   f"Newton–Euler and Zhukovsky's lever", file=file)
    out = []
    for d in make_plan(scene).dyads:
        if not isinstance(d, GROUP_KINDS):
            raise _refuse(f"a group of kind {type(d).__name__}", "placing "
                          + ", ".join(d.placed), file)
        if isinstance(d, CrankDyad):
            out.append(("crank", d, (d.link,)))
        elif isinstance(d, SliderDriveDyad):
            out.append(("slider driver", d, (d.point,)))
        elif isinstance(d, RRR):
            out.append(("RRR", d, (d.link_p, d.link_q)))
        elif isinstance(d, RRP):
            out.append(("RRP", d, (d.link, d.x)))
    return out


def _solve2(u1, u2, rhs, file, what) -> tuple[float, float]:
    """a u1 + b u2 = rhs: where the two lines of known direction meet."""
    det = cross(u1, u2)
    if abs(det) < 1e-9:
        raise UnsupportedError(f"the force polygon of {what} cannot close: the two lines of "
                               f"known direction are parallel (a toggle)", file=file)
    return cross(rhs, u2) / det, cross(u1, rhs) / det


def construct(an: Analysis, st: State) -> ForcePolygons:
    """The force polygons of every group at the state ``st``."""
    model = an.model
    scene = model.scene
    file = scene.file
    sol = st.sol
    groups = groups_of(scene)
    order = [FRAME] + [b for _, _, bs in groups for b in bs]
    group_of = {b: i for i, (_, _, bs) in enumerate(groups) for b in bs}
    missing = [b for b in model.bodies if b not in group_of]
    if missing:
        raise _refuse("a body placed by no group", ", ".join(missing), file)
    carriers: dict[str, list[str]] = {}
    for lab in scene.labels:
        cs = ([FRAME] if lab in scene.ground else []) + list(model.members.get(lab, ()))
        carriers[lab] = sorted(dict.fromkeys(cs), key=order.index)
    owner = {lab: cs[0] for lab, cs in carriers.items() if cs}

    def P(lab):
        return position(sol, lab)

    pin: dict = {}
    guide: dict = {}
    done: set[str] = set()
    out: list[Group] = []
    effort = 0.0

    def knowns(body: str) -> list[Known]:
        ks = []
        for ld in st.ne.loads:
            if ld.body != body:
                continue
            kind = {"gravity": "weight"}.get(ld.kind, ld.kind)
            name = f"W_{ld.item}" if ld.kind == "gravity" else ld.source
            if ld.force.any() and ld.pos is not None:
                ks.append(Known(name, kind, body, ld.force, ld.pos))
            if ld.couple:
                ks.append(Known(name, kind, body, np.zeros(2), None, ld.couple))
        for it in st.inertia:
            if it.body != body:
                continue
            f = -it.ma
            c = -it.i_alpha if not next(m for m in model.masses if m.name == it.item).free \
                else 0.0
            n2 = float(f @ f)
            if n2 > 0:
                d = -c * perp(f) / n2          # (d × f) = c: the couple carried by the offset
                ks.append(Known(f"−m a_G ({it.item})", "inertia", body, f, it.centre + d,
                                offset=float(np.hypot(*d))))
            elif c:
                ks.append(Known(f"−I_G α ({it.item})", "inertia", body, np.zeros(2), None, c))
        for lab in model.bodies[body].labels:
            if owner.get(lab) != body:
                continue
            for other in carriers[lab]:
                if other != body and other in done:
                    ks.append(Known(f"from {other} at {lab}", "transmitted", body,
                                    -pin[(lab, other)], P(lab)))
        return ks

    def K(ks) -> np.ndarray:
        return sum((k.force for k in ks), np.zeros(2))

    def M(ks, about) -> float:
        return sum(((cross(k.pos - about, k.force) if k.pos is not None else 0.0) + k.couple
                    for k in ks), 0.0)

    def words(body, about, m):
        return f"moments about {about} of {body}'s known forces: {m + 0.0:.6g} N m (CCW)"

    for gi in range(len(groups) - 1, -1, -1):
        kind, d, bodies = groups[gi]
        ks = {b: knowns(b) for b in bodies}
        allk = tuple(k for b in bodies for k in ks[b])
        if kind == "RRR":
            l1, l2 = d.link_p, d.link_q
            for outer, body in ((d.p, l1), (d.q, l2)):
                if owner.get(outer) in bodies:
                    raise _refuse("an RRR group whose outer pin is its own", outer, file)
            x = P(d.x)
            u1 = x - P(d.p)
            len1 = float(np.hypot(*u1))
            u1 = u1 / len1
            u2 = x - P(d.q)
            len2 = float(np.hypot(*u2))
            u2 = u2 / len2
            m1, m2 = M(ks[l1], x), M(ks[l2], x)
            t1 = Found(f"F_{d.p}^t on {l1}", l1, d.p, perp(u1), m1 / len1, "moments")
            t2 = Found(f"F_{d.q}^t on {l2}", l2, d.q, perp(u2), m2 / len2, "moments")
            rhs = -(K(ks[l1]) + K(ks[l2]) + t1.force + t2.force)
            a, b = _solve2(u1, u2, rhs, file, f"the group {l1}, {l2}")
            n1 = Found(f"F_{d.p}^n on {l1}", l1, d.p, u1, a, "polygon")
            n2 = Found(f"F_{d.q}^n on {l2}", l2, d.q, u2, b, "polygon")
            fq = t2.force + n2.force
            pin[(d.p, l1)] = t1.force + n1.force
            pin[(d.q, l2)] = fq
            r = -(K(ks[l2]) + fq)
            pin[(d.x, l2)] = r
            rv = float(np.hypot(*r))
            reac = (Found(f"R_{d.x} on {l2}", l2, d.x, r / rv if rv else np.array([1.0, 0.0]),
                          rv, "reaction"),)
            out.append(Group(gi + 1, kind, f"group {gi + 1}: dyad {l1}, {l2} (RRR, pins "
                             f"{d.p}, {d.x}, {d.q})", bodies, allk, (t1, t2), (n2, n1), reac,
                             (words(l1, d.x, m1), words(l2, d.x, m2))))
        elif kind == "RRP":
            link, blk = d.link, d.x
            x = P(d.x)
            u = x - P(d.p)
            ln = float(np.hypot(*u))
            u = u / ln
            e = np.array(scene.model.guide[blk].line.direction)
            ng = perp(e)
            m1 = M(ks[link], x)
            t1 = Found(f"F_{d.p}^t on {link}", link, d.p, perp(u), m1 / ln, "moments")
            rhs = -(K(ks[link]) + K(ks[blk]) + t1.force)
            a, nval = _solve2(u, ng, rhs, file, f"the group {link}, slider {blk}")
            n1 = Found(f"F_{d.p}^n on {link}", link, d.p, u, a, "polygon")
            nn = Found(f"N_{blk} (guide)", blk, blk, ng, nval, "polygon")
            pin[(d.p, link)] = t1.force + n1.force
            r = -(K(ks[blk]) + nn.force)
            pin[(d.x, blk)] = r
            couple = -M(ks[blk], x) + 0.0
            guide[blk] = (nval, ng, couple)
            rv = float(np.hypot(*r))
            reac = (Found(f"R_{d.x} on slider {blk}", blk, d.x,
                          r / rv if rv else np.array([1.0, 0.0]), rv, "reaction"),)
            out.append(Group(gi + 1, kind, f"group {gi + 1}: dyad {link}, slider {blk} (RRP, "
                             f"pins {d.p}, {d.x}, guide)", bodies, allk, (t1,), (nn, n1), reac,
                             (words(link, d.x, m1), f"the guide couple on {blk}: "
                              f"{couple:.6g} N m")))
        elif kind == "crank":
            body = d.link
            o = P(d.pivot)
            f = -K(ks[body])
            fv = float(np.hypot(*f))
            effort = -M(ks[body], o)
            pin[(d.pivot, body)] = f
            fo = Found(f"F_{d.pivot} on {body}", body, d.pivot,
                       f / fv if fv else np.array([1.0, 0.0]), fv, "polygon")
            te = Found(f"T on {body}", body, d.pivot, np.zeros(2), effort, "effort")
            out.append(Group(gi + 1, kind, f"group {gi + 1}: the crank {body} (driver)",
                             bodies, allk, (), (fo,), (te,),
                             (f"moments about {d.pivot}: T + ({M(ks[body], o) + 0.0:.6g} N m) "
                              f"= 0, T = {effort + 0.0:.6g} N m (CCW)",)))
        else:                                     # slider driver
            blk = d.point
            x = P(blk)
            e = np.array(scene.model.guide[blk].line.direction)
            ng = perp(e)
            effort, nval = _solve2(e, ng, -K(ks[blk]), file, f"the slider {blk}")
            couple = -M(ks[blk], x) + 0.0
            guide[blk] = (nval, ng, couple)
            fin = Found(f"F_in on slider {blk}", blk, blk, e, effort, "effort")
            nn = Found(f"N_{blk} (guide)", blk, blk, ng, nval, "polygon")
            out.append(Group(gi + 1, kind, f"group {gi + 1}: the slider {blk} (driver)",
                             bodies, allk, (), (fin, nn), (),
                             (f"the guide couple on {blk}: {couple:.6g} N m",)))
        done.update(bodies)
    # every pin's owner: minus the forces on the others; the frame's: the ground reaction
    ground = {}
    for lab, cs in carriers.items():
        if len(cs) < 2:
            continue
        total = sum((pin[(lab, b)] for b in cs[1:]), np.zeros(2))
        if cs[0] == FRAME:
            ground[lab] = -total
        else:
            pin[(lab, cs[0])] = -total
    return ForcePolygons(st.name, tuple(out), pin, ground, guide, effort)


def handled(scene) -> str | None:
    """None when the force polygons handle ``scene``, else the one-line reason."""
    try:
        groups_of(scene)
    except UnsupportedError as e:
        return e.args[0] if e.args else str(e)
    return None


__all__ = ["HANDLES", "GROUP_KINDS", "Known", "Found", "Group", "ForcePolygons", "construct",
           "groups_of", "handled"]
