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
* **RPR** (a block pinned at A, placed, sliding in the slot of a lever turning about B: the
  crank and slotted lever, Whitworth): the slot's force on the lever, normal to the slot
  through A, by moments about B of the lever alone; the polygon closes on the pivot's force;
  the block is light, so the pin A carries the same force back to A's body;
* **RRP on a moving guide** (a link PX whose pin X slides in the slot of a lever placed
  before: the oscillating cylinder): as RRP, the slot normal taking the guide normal's place;
  the lever receives the slot's force with its own group;
* **RPP** (a Scotch yoke: the block at the placed pin P slides in the yoke's slot, the yoke on
  a fixed guide): the yoke's polygon closes on the slot's force (normal to the slot) and the
  guide's normal force, two lines of known direction; the guide couple by moments;
* the **class-III group** (a triad: a ternary plate with corners B, C, X, each joined by a
  binary link to a placed point A, D, E; or a triangle of links): each link's outer pin
  force split as in RRR, its normal component by moments about its corner; the three
  components along the links remain:
  the one along the link whose line does not pass through the Assur point S (where the other
  two links' lines meet) by moments of the whole group about S, the other two close the
  group's polygon; each corner's force is a diagonal.  No dyad's polygon closes alone here: S
  does what the middle pin does for a dyad.  A plate that is a triangle of links is then a
  truss, solved joint by joint (the polygon of the forces on each corner pin);
* the **crank** (the driver, last): its bearing force closes its polygon, the input torque is
  the moment about its pivot; a **slider driver**: the input force along the guide and the
  guide normal close the block's polygon.

A pin is carried with the body placed first (the frame, or the group's first link): the forces
later groups pass on through a pin act on that body.  Each reaction is returned as the force
on a body at a pin, the same as :func:`polygons.forces.newton_euler.newton_euler`'s, and the
tests hold them equal to 1e-9.  Kinds the construction does not handle are refused in one line
naming the kind (:data:`HANDLES`; a group whose kind names no :data:`POLYGONS` entry).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from ..errors import UnsupportedError
from ..model import FRAME, check_handles
from ..plan import make_plan
from . import words
from .model import cross, perp, position
from .states import Analysis, State

#: the kinds of body and pair the construction handles (polygons.model)
HANDLES = frozenset({"frame", "link", "lever", "block", "yoke", "pin-block", "turning",
                     "sliding"})
#: a group kind without ``force_polygon`` (the plan's groups handled: those naming one of
#: :data:`POLYGONS`, and points on links, which name None)
_MISSING = object()
#: Group.kind of the groups drawn as a dyad (two bodies, a middle pin's force as the diagonal)
DYAD_KINDS = ("RRR", "RRP", "RRP, moving guide")
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
    'effort' (the input), 'reaction' (a pin force read as a diagonal, or passed on by a light
    block), 'joint' (a plate link's end force, from the polygon of a joint of the plate)."""
    name: str
    body: str
    at: str
    direction: np.ndarray
    value: float
    how: str
    along: str = "normal to the link"   # the direction in words (by-moments components)

    @property
    def force(self) -> np.ndarray:
        return self.value * self.direction


@dataclass(frozen=True)
class Group:
    """One group's construction: its bodies, what was known, what the polygon found."""
    index: int                 # 1 = the driver
    kind: str                  # 'crank', 'slider driver', 'RRR', 'RRP', 'RPR',
                               # 'RRP, moving guide', 'RPP', 'triad'
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
    slot: dict = None                  # pin -> (signed normal force on the lever, unit normal)
    joints: tuple[Group, ...] = ()     # a triangle plate's joints (kind 'joint'), in order


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
    rolled = [q.at for q in getattr(scene, "equivalents", ()) if q.kind == "rolling"]
    if rolled:          # its slider's guide couple is friction at the contact, not a couple
        raise _refuse("a rolling contact (its friction is no guide couple)", rolled[0], file)
    out = []
    for d in make_plan(scene).dyads:
        # the construction is the group's own (``force_polygon``): a kind that names none
        # it knows, or has no such attribute, is refused by construction
        kind = getattr(d, "force_polygon", _MISSING)
        if kind is None:                 # no body of its own (a point on a placed link)
            continue
        if kind is _MISSING or kind not in POLYGONS:
            # named in the group's own words (``words``) where it gives them
            raise _refuse(getattr(d, "words", None) or f"a group of kind {type(d).__name__}",
                          "placing " + ", ".join(d.placed), file)
        out.append((kind, d, tuple(d.force_bodies())))
    return out


def _solve2(u1, u2, rhs, file, what) -> tuple[float, float]:
    """a u1 + b u2 = rhs: where the two lines of known direction meet."""
    det = cross(u1, u2)
    if abs(det) < 1e-9:
        raise UnsupportedError(f"the force polygon of {what} cannot close: the two lines of "
                               f"known direction are parallel (a toggle)", file=file)
    return cross(rhs, u2) / det, cross(u1, rhs) / det


class _Board:
    """The drawing board of one state: where every pin is, the forces found so far (``pin``:
    (label, body) → the force on the body from the pin; ``guide``, ``slot``), the groups drawn
    (``done``), and what each body carries when its group is drawn (:meth:`knowns`)."""

    def __init__(self, an: Analysis, st: State, groups):
        model = an.model
        self.model, self.scene, self.st = model, model.scene, st
        self.file, self.sol = self.scene.file, st.sol
        order = [FRAME] + [b for _, _, bs in groups for b in bs]
        group_of = {b: i for i, (_, _, bs) in enumerate(groups) for b in bs}
        missing = [b for b in model.bodies if b not in group_of]
        if missing:
            raise _refuse("a body placed by no group", ", ".join(missing), self.file)
        self.carriers: dict[str, list[str]] = {}
        for lab in self.scene.labels:
            cs = ([FRAME] if lab in self.scene.ground else []) + list(
                model.members.get(lab, ()))
            self.carriers[lab] = sorted(dict.fromkeys(cs), key=order.index)
        self.owner = {lab: cs[0] for lab, cs in self.carriers.items() if cs}
        self.pin: dict = {}
        self.guide: dict = {}
        self.slot: dict = {}
        self.joints: list[Group] = []
        self.done: set[str] = set()
        self.effort = 0.0

    def P(self, lab):
        return position(self.sol, lab)

    def knowns(self, body: str) -> list[Known]:
        """The loads, weights and inertia forces on ``body``, and the forces the groups
        already drawn pass on to it through its pins and slots."""
        model, st, P = self.model, self.st, self.P
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
            if self.owner.get(lab) != body:
                continue
            for other in self.carriers[lab]:
                if other != body and other in self.done:
                    ks.append(Known(f"from {other} at {lab}", "transmitted", body,
                                    -self.pin[(lab, other)], P(lab)))
        for s in model.slots:                   # a slot's force found with the other body
            if s.pin not in self.slot or body not in (s.lever, s.carrier):
                continue
            other = s.carrier if body == s.lever else s.lever
            if other in self.done:
                val, n = self.slot[s.pin]
                ks.append(Known(f"from {other} at {s.pin} (slot)", "transmitted", body,
                                (val if body == s.lever else -val) * n, P(s.pin)))
        return ks

    def slot_of(self, pin: str):
        return next(s for s in self.model.slots if s.pin == pin)

    def slot_normal(self, s) -> np.ndarray:
        """The slot's unit normal, as Newton–Euler takes it (perp of the slot's direction)."""
        P = self.P
        u = (np.array(s.direction) if s.direction else
             P(s.far) - P(s.pivot) if s.far else P(s.pin) - P(s.pivot))
        return perp(u / float(np.hypot(*u)))

    def guide_normal(self, label: str) -> tuple[np.ndarray, np.ndarray]:
        """(e, n): the fixed guide's unit direction at ``label`` and its unit normal."""
        e = np.array(self.scene.model.guide[label].line.direction)
        return e, perp(e)


def _K(ks) -> np.ndarray:
    return sum((k.force for k in ks), np.zeros(2))


def _M(ks, about) -> float:
    return sum(((cross(k.pos - about, k.force) if k.pos is not None else 0.0) + k.couple
                for k in ks), 0.0)


# the words of a force result: the one formatter (polygons.forces.words)
moment_words, sense_words, found_words, balance_words = (
    words.moment_words, words.sense_words, words.found_words, words.balance_words)


def _words(body, about, m):
    return f"moments about {about} of {body}'s known forces: {moment_words(m)}"


def _unit(r) -> tuple[np.ndarray, float]:
    rv = float(np.hypot(*r))
    return (r / rv if rv else np.array([1.0, 0.0])), rv


def construct(an: Analysis, st: State) -> ForcePolygons:
    """The force polygons of every group at the state ``st``: each group's construction is
    the one it names (``force_polygon``, a key of :data:`POLYGONS`), drawn from the group
    furthest from the driver to the driver."""
    groups = groups_of(an.model.scene)
    board = _Board(an, st, groups)
    out: list[Group] = []
    for gi in range(len(groups) - 1, -1, -1):
        kind, d, bodies = groups[gi]
        ks = {b: board.knowns(b) for b in bodies}
        allk = tuple(k for b in bodies for k in ks[b])
        out.append(POLYGONS[kind](board, gi, d, bodies, ks, allk))
        board.done.update(bodies)
    # every pin's owner: minus the forces on the others; the frame's: the ground reaction
    pin = board.pin
    ground = {}
    for lab, cs in board.carriers.items():
        if len(cs) < 2:
            continue
        total = sum((pin[(lab, b)] for b in cs[1:]), np.zeros(2))
        if cs[0] == FRAME:
            ground[lab] = -total
        else:
            pin[(lab, cs[0])] = -total
    return ForcePolygons(st.name, tuple(out), pin, ground, board.guide, board.effort,
                         board.slot, tuple(board.joints))


def _rrr(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """RRR: the outer pins' normal components by moments about X, the polygon closing on the
    two along-link components; the middle pin's force from one link's polygon."""
    P, file, pin = b.P, b.file, b.pin
    l1, l2 = d.link_p, d.link_q
    for outer, body in ((d.p, l1), (d.q, l2)):
        if b.owner.get(outer) in bodies:
            raise _refuse("an RRR group whose outer pin is its own", outer, file)
    x = P(d.x)
    u1 = x - P(d.p)
    len1 = float(np.hypot(*u1))
    u1 = u1 / len1
    u2 = x - P(d.q)
    len2 = float(np.hypot(*u2))
    u2 = u2 / len2
    m1, m2 = _M(ks[l1], x), _M(ks[l2], x)
    t1 = Found(f"F_{d.p}^t on {l1}", l1, d.p, perp(u1), m1 / len1, "moments")
    t2 = Found(f"F_{d.q}^t on {l2}", l2, d.q, perp(u2), m2 / len2, "moments")
    rhs = -(_K(ks[l1]) + _K(ks[l2]) + t1.force + t2.force)
    a, bv = _solve2(u1, u2, rhs, file, f"the group {l1}, {l2}")
    n1 = Found(f"F_{d.p}^n on {l1}", l1, d.p, u1, a, "polygon")
    n2 = Found(f"F_{d.q}^n on {l2}", l2, d.q, u2, bv, "polygon")
    fq = t2.force + n2.force
    pin[(d.p, l1)] = t1.force + n1.force
    pin[(d.q, l2)] = fq
    r = -(_K(ks[l2]) + fq)
    pin[(d.x, l2)] = r
    reac = (Found(f"R_{d.x} on {l2}", l2, d.x, *_unit(r), "reaction"),)
    return Group(gi + 1, "RRR", f"group {gi + 1}: dyad {l1}, {l2} (RRR, pins "
                 f"{d.p}, {d.x}, {d.q})", bodies, allk, (t1, t2), (n2, n1), reac,
                 (_words(l1, d.x, m1), _words(l2, d.x, m2)))


def _rrp(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """RRP: P's normal component by moments about X, the polygon closing on the along-link
    component and the guide's normal force; the guide couple from the block's moments."""
    P, file, pin = b.P, b.file, b.pin
    link, blk = d.link, d.x
    x = P(d.x)
    u = x - P(d.p)
    ln = float(np.hypot(*u))
    u = u / ln
    _, ng = b.guide_normal(blk)
    m1 = _M(ks[link], x)
    t1 = Found(f"F_{d.p}^t on {link}", link, d.p, perp(u), m1 / ln, "moments")
    rhs = -(_K(ks[link]) + _K(ks[blk]) + t1.force)
    a, nval = _solve2(u, ng, rhs, file, f"the group {link}, slider {blk}")
    n1 = Found(f"F_{d.p}^n on {link}", link, d.p, u, a, "polygon")
    nn = Found(f"N_{blk} (guide)", blk, blk, ng, nval, "polygon")
    pin[(d.p, link)] = t1.force + n1.force
    r = -(_K(ks[blk]) + nn.force)
    pin[(d.x, blk)] = r
    couple = -_M(ks[blk], x) + 0.0
    b.guide[blk] = (nval, ng, couple)
    reac = (Found(f"R_{d.x} on slider {blk}", blk, d.x, *_unit(r), "reaction"),)
    return Group(gi + 1, "RRP", f"group {gi + 1}: dyad {link}, slider {blk} (RRP, "
                 f"pins {d.p}, {d.x}, guide)", bodies, allk, (t1,), (nn, n1), reac,
                 (_words(link, d.x, m1), f"the guide couple on {blk}: {moment_words(couple)}"))


def _rpr(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """RPR: the slot's force on the lever, normal to the slot through the pin, by moments
    about the pivot; the polygon closes on the pivot's force; the light block passes the
    slot's force back to the pin's body."""
    P, file = b.P, b.file
    lever, s = d.lever, b.slot_of(d.pin)
    bp, a = P(d.pivot), P(d.pin)
    n = b.slot_normal(s)
    m = _M(ks[lever], bp)
    arm = cross(a - bp, n)
    if abs(arm) < 1e-9 * max(1e-12, float(np.hypot(*(a - bp)))):
        raise UnsupportedError(f"the force polygon of the lever {lever} cannot close: "
                               f"the slot's normal at {d.pin} passes through the pivot "
                               f"{d.pivot}", file=file)
    nval = -m / arm
    b.slot[d.pin] = (nval, n)
    nn = Found(f"N_{d.pin} on {lever}", lever, d.pin, n, nval, "moments",
               "normal to the slot")
    fb = -(_K(ks[lever]) + nn.force)
    b.pin[(d.pivot, lever)] = fb
    fo = Found(f"F_{d.pivot} on {lever}", lever, d.pivot, *_unit(fb), "polygon")
    ra = Found(f"R_{d.pin} on {s.carrier} (through the block)", s.carrier, d.pin,
               *_unit(-nn.force), "reaction")
    return Group(gi + 1, "RPR", f"group {gi + 1}: the slotted lever {lever} and the "
                 f"block {d.pin} in its slot (RPR, pins {d.pin}, {d.pivot})",
                 bodies, allk, (nn,), (fo,), (ra,),
                 (f"moments about {d.pivot} of {lever}'s known forces: "
                  f"{moment_words(m)}; the slot's force at {d.pin} has arm "
                  f"{abs(arm) * 1e3:.6g} mm: N = {abs(nval):.6g} N",))


def _moving_guide(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """RRP on a moving guide: as RRP, the slot's normal taking the guide normal's place; the
    lever receives the slot's force with its own group."""
    P, file = b.P, b.file
    link, s = d.link, b.slot_of(d.x)
    if s.carrier != link:
        raise _refuse(f"a pin in a moving slot carried by another body than its link "
                      f"({s.carrier})", d.x, file)
    x = P(d.x)
    u = x - P(d.p)
    ln = float(np.hypot(*u))
    u = u / ln
    n = b.slot_normal(s)
    m1 = _M(ks[link], x)
    t1 = Found(f"F_{d.p}^t on {link}", link, d.p, perp(u), m1 / ln, "moments")
    a, c = _solve2(u, n, -(_K(ks[link]) + t1.force), file,
                   f"the group {link}, block {d.x} in the slot of {d.lever}")
    n1 = Found(f"F_{d.p}^n on {link}", link, d.p, u, a, "polygon")
    nn = Found(f"N_{d.x} from {d.lever}", link, d.x, n, c, "polygon")
    b.pin[(d.p, link)] = t1.force + n1.force
    b.slot[d.x] = (-c, n)
    reac = (Found(f"R_{d.x} on block {d.x}", link, d.x, *_unit(-nn.force), "reaction"),)
    return Group(gi + 1, "RRP, moving guide", f"group {gi + 1}: {link} and the block {d.x} "
                 f"in the slot of {d.lever} (RRP on a moving guide, pins {d.p}, {d.x})",
                 bodies, allk, (t1,), (nn, n1), reac, (_words(link, d.x, m1),))


def _rpp(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """RPP (a Scotch yoke): the yoke's polygon closes on the slot's force and the guide's
    normal force; the guide couple by moments."""
    P, file = b.P, b.file
    yoke, s = d.x, b.slot_of(d.pin)
    y = P(yoke)
    ns = b.slot_normal(s)
    _, ng = b.guide_normal(yoke)
    sval, nval = _solve2(ns, ng, -_K(ks[yoke]), file, f"the yoke {yoke}")
    b.slot[d.pin] = (sval, ns)
    couple = -(_M(ks[yoke], y) + cross(P(d.pin) - y, sval * ns)) + 0.0
    b.guide[yoke] = (nval, ng, couple)
    nsl = Found(f"N_{d.pin} on yoke {yoke}", yoke, d.pin, ns, sval, "polygon")
    nn = Found(f"N_{yoke} (guide)", yoke, yoke, ng, nval, "polygon")
    ra = Found(f"R_{d.pin} on {s.carrier} (through the block)", s.carrier, d.pin,
               *_unit(-nsl.force), "reaction")
    return Group(gi + 1, "RPP", f"group {gi + 1}: the yoke {yoke} and the block "
                 f"{d.pin} in its slot (RPP, Scotch yoke)", bodies, allk, (),
                 (nsl, nn), (ra,),
                 (f"the guide couple on {yoke}: {moment_words(couple)} (moments about "
                  f"{yoke})",))


def _crank(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """The crank (the driver): its bearing force closes its polygon, the input torque is the
    moment about its pivot."""
    body = d.link
    o = b.P(d.pivot)
    f = -_K(ks[body])
    b.effort = effort = -_M(ks[body], o)
    b.pin[(d.pivot, body)] = f
    fo = Found(f"F_{d.pivot} on {body}", body, d.pivot, *_unit(f), "polygon")
    te = Found(f"T on {body}", body, d.pivot, np.zeros(2), effort, "effort")
    # a driven slotted lever (an oscillating cylinder) is no crank
    what = ("slotted lever" if any(sl.carrier == body for sl in b.scene.model.slot.values())
            else "crank")
    return Group(gi + 1, "crank", f"group {gi + 1}: the {what} {body} (driver)",
                 bodies, allk, (), (fo,), (te,),
                 (f"moments about {d.pivot}: {balance_words(_M(ks[body], o), effort)}",))


def _slider_driver(b: _Board, gi, d, bodies, ks, allk) -> Group:
    """A slider driver: the input force along the guide and the guide normal close the
    block's polygon."""
    blk = d.point
    x = b.P(blk)
    e, ng = b.guide_normal(blk)
    effort, nval = _solve2(e, ng, -_K(ks[blk]), b.file, f"the slider {blk}")
    b.effort = effort
    couple = -_M(ks[blk], x) + 0.0
    b.guide[blk] = (nval, ng, couple)
    fin = Found(f"F_in on slider {blk}", blk, blk, e, effort, "effort")
    nn = Found(f"N_{blk} (guide)", blk, blk, ng, nval, "polygon")
    return Group(gi + 1, "slider driver", f"group {gi + 1}: the slider {blk} (driver)",
                 bodies, allk, (), (fin, nn), (),
                 (f"the guide couple on {blk}: {moment_words(couple)}",))


def _triad_group(b: _Board, gi, d, bodies, ks, allk) -> Group:
    return _triad(gi, d, bodies, ks, allk, b.P, _K, _M, b.pin, b.file, b.model, b.joints)


def _triad(gi, d, bodies, ks, allk, P, K, M, pin, file, model, joints) -> Group:
    """The class-III group: normal components by moments about the corners, the along-link
    component of the link off the Assur point S by moments about S, the other two closing.
    A plate that is a triangle of links is then solved as a truss, joint by joint
    (:func:`_plate_truss`)."""
    legs = [(d.link_b, d.ob, d.b), (d.link_c, d.oc, d.c), (d.link_x, d.ox, d.x)]
    us, ts, ms = [], [], []
    for link, o, c in legs:
        u = P(c) - P(o)
        ln = float(np.hypot(*u))
        us.append(u / ln)
        m = M(ks[link], P(c))
        ms.append(m)
        ts.append(Found(f"F_{o}^t on {link}", link, o, perp(u / ln), m / ln, "moments"))
    # S where two links' lines meet, the pair furthest from parallel (AB, DC unless worse)
    i, j = max(((0, 1), (0, 2), (1, 2)), key=lambda p: abs(cross(us[p[0]], us[p[1]])))
    k = 3 - i - j
    oi, oj, ok = (P(legs[q][1]) for q in (i, j, k))
    al, _ = _solve2(us[i], -us[j], oj - oi, file, f"the triad {d.plate}: links "
                    f"{legs[i][0]}, {legs[j][0]}")
    s = oi + al * us[i]
    ktot = sum((K(ks[b]) for b in bodies), np.zeros(2)) + sum((t.force for t in ts),
                                                              np.zeros(2))
    mtot = sum((M(ks[b], s) for b in bodies), 0.0) + sum(
        (cross(P(legs[q][1]) - s, ts[q].force) for q in range(3)), 0.0)
    arm = cross(ok - s, us[k])
    size = max(float(np.hypot(*(P(c) - P(o)))) for _, o, c in legs)
    if abs(arm) < 1e-9 * size:
        raise UnsupportedError(f"the force polygon of the triad {d.plate} cannot close: the "
                               f"line of {legs[k][0]} passes through the Assur point (a "
                               f"dead centre)", file=file)
    ak = -mtot / arm
    ai, aj = _solve2(us[i], us[j], -(ktot + ak * us[k]), file, f"the triad {d.plate}")
    along = {i: ai, j: aj, k: ak}
    fn = {q: Found(f"F_{legs[q][1]}^n on {legs[q][0]}", legs[q][0], legs[q][1], us[q],
                   along[q], "moments" if q == k else "polygon",
                   "along the link, about the Assur point S" if q == k else "along the link")
          for q in range(3)}
    reac = []
    for q, (link, o, c) in enumerate(legs):
        pin[(o, link)] = ts[q].force + fn[q].force
        r = -(K(ks[link]) + pin[(o, link)])          # on the link at its corner
        pin[(c, link)] = r
        rv = float(np.hypot(*r))
        reac.append(Found(f"R_{c} on {d.plate if d.ternary else 'the plate'}", d.plate, c,
                          -r / rv if rv else np.array([1.0, 0.0]), rv, "reaction"))
    moments_truss: tuple[str, ...] = ()
    if not d.ternary:
        members, moments_truss, js = _plate_truss(gi, d, legs, ks, P, K, M, pin, file, model)
        reac += members
        joints += js
    sname = f"S ({legs[i][0]} × {legs[j][0]})"
    moments = tuple(f"moments about {c} of {link}'s known forces: {moment_words(ms[q])}"
                    for q, (link, o, c) in enumerate(legs)) + (
        f"moments about the Assur point {sname}: known {moment_words(mtot)}, "
        f"{fn[k].name} (its arm {abs(arm) * 1e3:.6g} mm) = {found_words(fn[k])}",) + moments_truss
    plate = d.plate if d.ternary else "the triangle " + ", ".join(d.plate_links)
    return Group(gi + 1, "triad", f"group {gi + 1}: the triad (class III) plate {plate}, "
                 f"links {d.link_b}, {d.link_c}, {d.link_x} (corners {d.b}, {d.c}, {d.x})",
                 bodies, allk, tuple(ts) + (fn[k],), (fn[j], fn[i]), tuple(reac), moments)


def _plate_truss(gi, d, legs, ks, P, K, M, pin, file, model):
    """A plate that is a triangle of links BC, CX, BX, once the corner forces of the binary
    links are known: each plate link's end forces split into normal components (moments about
    its other end) and one unknown along it (the other end's follows from the link's balance
    along itself); the joint B's polygon closes on the two plate links there (two lines of
    known direction), the joint C's gives the third link's, the joint X checks.  Returns the
    plate links' end forces, the words, and each joint's polygon (a :class:`Group` of kind
    'joint': the forces on the pin)."""
    ends, axis, tn, lens = {}, {}, {}, {}
    for name in d.plate_links:
        a, b = model.bodies[name].a, model.bodies[name].b
        u = P(b) - P(a)
        ln = float(np.hypot(*u))
        u = u / ln
        ends[name], axis[name], lens[name] = (a, b), u, ln
        tn[(name, a)] = perp(u) * M(ks[name], P(b)) / ln
        tn[(name, b)] = -perp(u) * M(ks[name], P(a)) / ln
    s: dict[str, float] = {}

    def force(name, corner, sval):
        """The force on the plate link ``name`` at ``corner`` with the axial unknown sval."""
        a, _ = ends[name]
        u = axis[name]
        if corner == a:
            return tn[(name, corner)] + sval * u
        return tn[(name, corner)] - (sval + float(K(ks[name]) @ u)) * u

    def at(corner):
        return [n for n in d.plate_links if corner in ends[n]]

    leg_of = {c: link for link, _, c in legs}
    lines = []
    for corner in (d.b, d.c, d.x):
        known = pin[(corner, leg_of[corner])]
        todo = [n for n in at(corner) if n not in s]
        base = known + sum((force(n, corner, s[n]) for n in at(corner) if n in s),
                           np.zeros(2))
        coef = {n: force(n, corner, 1.0) - force(n, corner, 0.0) for n in todo}
        zero = {n: force(n, corner, 0.0) for n in todo}
        rhs = -(base + sum(zero.values(), np.zeros(2)))
        if len(todo) == 2:
            s[todo[0]], s[todo[1]] = _solve2(coef[todo[0]], coef[todo[1]], rhs, file,
                                             f"the joint {corner} of the plate")
            lines.append(f"the joint {corner}: {leg_of[corner]}'s force and the normal "
                         f"components close on {todo[0]} and {todo[1]} along themselves")
        elif len(todo) == 1:
            c = coef[todo[0]]
            s[todo[0]] = float(rhs @ c) / float(c @ c)
            lines.append(f"the joint {corner}: its polygon gives {todo[0]} along itself")
    js = []
    found_at = {}
    for corner in (d.b, d.c, d.x):
        todo = [n for n in at(corner) if n not in found_at]
        for n in todo:
            found_at[n] = corner
        leg = leg_of[corner]
        ks_j = [Known(f"from {leg} at {corner}", "transmitted", leg, -pin[(corner, leg)],
                      P(corner))]
        normals, closing = [], []
        for n in at(corner):
            u = axis[n] if corner == ends[n][0] else -axis[n]
            tv = -tn[(n, corner)]
            normals.append(Found(f"F_{corner}^t from {n}", n, corner, perp(u),
                                 float(tv @ perp(u)), "moments"))
            ax = -(force(n, corner, s[n]) - tn[(n, corner)])       # on the pin, along n
            fa = Found(f"F_{corner}^n from {n}", n, corner, u, float(ax @ u),
                       "polygon", "along the link")
            if found_at[n] == corner:
                closing.append(fa)
            else:
                ks_j.append(Known(f"F_{corner}^n from {n} (its balance along itself)",
                                  "transmitted", n, fa.force, P(corner)))
        js.append(Group(gi + 1, "joint", f"group {gi + 1}: the joint {corner} of the plate "
                        f"{', '.join(d.plate_links)}", tuple(at(corner)), tuple(ks_j),
                        tuple(normals), tuple(closing), (),
                        (f"the forces on the pin {corner}: {leg}'s, and each plate link's "
                         f"normal component (moments about its other end) and its component "
                         f"along itself" + (" — a check: nothing is left to find"
                                            if not closing else ""),)))
    out = []
    for name in d.plate_links:
        for corner in ends[name]:
            f = force(name, corner, s[name])
            pin[(corner, name)] = f
            fv = float(np.hypot(*f))
            out.append(Found(f"F_{corner} on {name}", name, corner,
                             f / fv if fv else np.array([1.0, 0.0]), fv, "joint"))
    return out, tuple(lines), js


#: each group's force polygon, by the name the group gives (its ``force_polygon``): a
#: group kind names one of these, or none (it adds no body: a point on a placed link)
POLYGONS = MappingProxyType({
    "crank": _crank, "slider driver": _slider_driver, "RRR": _rrr, "RRP": _rrp,
    "RPR": _rpr, "RRP, moving guide": _moving_guide, "RPP": _rpp, "triad": _triad_group})


def handled(scene) -> str | None:
    """None when the force polygons handle ``scene``, else the one-line reason."""
    try:
        groups_of(scene)
    except UnsupportedError as e:
        return e.args[0] if e.args else str(e)
    return None


__all__ = ["HANDLES", "POLYGONS", "Known", "Found", "Group", "ForcePolygons", "construct",
           "groups_of", "handled"]
