"""The class-III Assur group with a block on a guide at a corner ("two links and a block"):
a rigid plate whose corners B, C are joined by binary links to placed points (AB, DC) and
whose third corner X is a pin in a block sliding on a fixed straight guide ([sliders.X]).
No dyad places it: the three corners close together.

The scene states it as the book draws it: the plate is a link carrying a point ([points.X]
on = "BC", a ternary link) or a triangle of three links; the corner on the guide has
[sliders.X] and no link of its own, each other corner one link to a placed point.  Any corner
may be the one on the guide.  ``[assembly]`` (words or ``near``) on any corner chooses the
closure.

Position: every closure, algebraically (:mod:`polygons.dyads.triad_slider_math`: the real
roots of a polynomial of degree ≤ 6, each polished by Newton); the one the scene's words or
``near`` choose, followed by continuation through a sweep.

Velocity, by the auxiliary (Assur) point S where AB and DC produced meet (a point of the
plate): v_S − v_A ⟂ AB and v_S − v_D ⟂ DC give s; then v_X − v_S ⟂ SX and v_X ∥ the guide (a
block on a fixed guide) give x; b, c are images on the plate (s, x); the slider's velocity is
ox along the guide.

Acceleration, the same with the normal parts known: a_S = a_A + ω_AB² (A − B) + ω_p² (B − S)
+ [⟂ AB] = a_D + ω_DC² (D − C) + ω_p² (C − S) + [⟂ DC] gives s′; a_X = a_S + ω_p² (S − X)
+ [⟂ SX] = [∥ guide] gives x′ (no Coriolis term: the guide is fixed); b′, c′ are images.

Where AB and DC are parallel (S at infinity, a point of the construction, not a singularity
of the group) S is taken where a link meets the normal to the guide at X (:meth:`for_instant`,
said in the solution's notes); the position is stated once (:attr:`construction`: the closure,
then Assur's point, both primitives of :mod:`polygons.dyads.primitives`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from ..steps import Builder, Component, Kind, Op
from . import image
from .base import size_of
from .primitives import AssurPoint, CornerFrame, FixedLine, Length, Then, TriadSliderClosure
from .triad import Triad, _aux_label, _plates

#: the module registers itself (:mod:`polygons.dyads`): a group of a higher class, tried when
#: no dyad can be placed, after the three-link triad
ROLE = "group"


@dataclass(frozen=True)
class TriadSlider:
    """Plate ``plate`` with corners ``b``, ``c`` joined by ``link_b``, ``link_c`` to the placed
    ``ob``, ``oc``, and corner ``x`` a block on its fixed guide ([sliders.x]); ``s`` the
    Assur point (AB and DC produced, or where AB ∥ DC a link and the normal to the guide:
    ``via``); ``ternary``: the plate is a link with a [points] corner (else a triangle of
    links, whose mirror image is a closure too); ``guide_e`` the guide's direction."""
    b: str
    c: str
    x: str
    ob: str
    oc: str
    link_b: str
    link_c: str
    plate: str
    plate_links: tuple[str, ...]
    s: str
    ternary: bool
    #: the guide's direction (kept for the construction's choice of S)
    guide_e: tuple = field(default=(1.0, 0.0), compare=False)
    #: the lines meeting at S: 0 AB, DC; 1 AB and the normal to the guide at X; 2 DC and it
    via: int = 0
    two_closures = False
    many_closures = True

    @property
    def _guide_e(self):
        return self.guide_e

    #: no ``force_polygon``: the graphical force polygon of this group is not written, so
    #: :func:`polygons.forces.graphical.groups_of` refuses it in one line, in these words
    #: (Newton–Euler and Zhukovsky's lever solve it)
    words = ("a class-III group with a slider on a fixed guide at a corner (two links and "
             "a block)")

    def auxiliary_points(self):
        """(S, (A, B), (D, C)): Assur's point S where AB and DC produced meet; none drawn when
        S is taken on a link and the normal to the guide (:attr:`via` 1, 2: no second named
        point on that line; the steps say where S is)."""
        if self.via:
            return ()
        return ((self.s, (self.ob, self.b), (self.oc, self.c)),)

    def force_bodies(self) -> tuple[str, ...]:
        return (((self.plate,) if self.ternary else tuple(self.plate_links))
                + (self.link_b, self.link_c, self.x))

    @property
    def roles(self):
        """((P₁, O₁, link₁), (P₂, O₂, link₂)): S on O₁P₁ produced and on O₂P₂ produced
        (:attr:`via` 0: AB, DC), or on O₁P₁ produced and the normal to the guide at X (via 1:
        AB; via 2: DC), the other link's corner P₂ found from S and O₂ then."""
        rb, rc = (self.b, self.ob, self.link_b), (self.c, self.oc, self.link_c)
        return (rc, rb) if self.via == 2 else (rb, rc)

    def pair_words(self, via=None) -> str:
        """The two lines meeting at S for ``via`` (default this group's), in words."""
        via = self.via if via is None else via
        if via == 0:
            return f"{self.ob}{self.b} and {self.oc}{self.c}"
        o, p = (self.ob, self.b) if via == 1 else (self.oc, self.c)
        return f"{o}{p} and the normal to the guide of {self.x} at {self.x}"

    def pair_sine(self, points, via=None):
        """|sin| of the angle between the two lines meeting at S for ``via`` (0: AB, DC; 1:
        AB and the guide's normal; 2: DC and the normal), over one position or arrays."""
        via = self.via if via is None else via
        P = {k: np.asarray(points[k], dtype=float) for k in (self.b, self.c, self.ob, self.oc)}
        col = (lambda v: v.reshape(2, 1) if v.ndim == 1 and P[self.b].ndim > 1 else v)
        u = P[self.b] - col(P[self.ob])
        w = P[self.c] - col(P[self.oc])
        e = self._guide_e
        n = np.array([-e[1], e[0]]).reshape((2,) + (1,) * (u.ndim - 1))
        first, second = {0: (u, w), 1: (u, n), 2: (w, n)}[via]
        with np.errstate(all="ignore"):
            return (np.abs(first[0] * second[1] - first[1] * second[0])
                    / (np.hypot(*first) * np.hypot(*second)))

    def assur_sine(self, points, via=None) -> float:
        return float(self.pair_sine(points, via))

    for_instant = Triad.for_instant

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.b, self.c, self.x, self.s)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.ob, self.oc)

    @property
    def links(self) -> tuple[str, ...]:
        return (self.link_b, self.link_c) + self.plate_links

    @property
    def sigma_keys(self) -> tuple[str, ...]:
        """Where the chosen closure is kept: B's and X's coordinates under B's label."""
        return (f"{self.b}#bx", f"{self.b}#by", f"{self.b}#xx", f"{self.b}#xy")

    # ------------------------------------------------------------ geometry
    @cached_property
    def construction(self) -> Then:
        """Its position, stated once (:mod:`polygons.dyads.primitives`): the corners B, C, X
        by the closure nearest the one kept (:class:`TriadSliderClosure`), then Assur's
        point S where the pair of lines :attr:`via` names meet (:class:`AssurPoint`: AB and
        DC, or a link and the normal to the guide at X).  ``source`` is this statement and
        ``locate`` its evaluation: the staged solve, the sweeps and the generated program
        run the same formulas."""
        guide = FixedLine(self.x)
        plate = CornerFrame(self.b, self.c, self.x,
                            (self.plate,) if self.ternary else self.plate_links)
        closure = TriadSliderClosure((self.b, self.c, self.x), (self.ob, self.oc),
                                     (Length(self.link_b), Length(self.link_c)), guide, plate,
                                     self.sigma_keys)
        (p1, o1, _), (p2, o2, _) = self.roles
        assur = (AssurPoint(self.s, o1, p1, o2, p2) if self.via == 0 else
                 AssurPoint(self.s, o1, p1, self.x, self.x, normal=guide))
        return Then((closure, assur))

    def frame(self, scene):
        """The plate in the roles' frame: C = (L, 0), X = (ξ, η) from B (arrays in a batch)."""
        return self.construction.steps[0].plate.value(scene)

    # as the three-link triad's: its construction's every closure, the one nearest the
    # reference, NaN where none, the statement itself
    closures = Triad.closures
    locate = Triad.locate
    _nan = Triad._nan
    source = Triad.source

    def variant(self, scene) -> tuple:
        """The statement's shape does not change with the scene's numbers."""
        return ()

    def why_not(self, scene, pos) -> str:
        return (f"the class-III group (the plate {self.plate} with corners {self.b}, {self.c} "
                f"on the links {self.link_b}, {self.link_c} and {self.x} a block on its "
                f"guide) cannot close at this input: no position of the plate gives both links "
                f"their lengths with {self.x} on the guide")

    def toggle_reason(self, scene, pos) -> str:
        return (f"two closures of the class-III group {self.b}{self.c}{self.x} meet here (the "
                f"lines of {self.link_b}, {self.link_c} and the normal to the guide of "
                f"{self.x} through {self.x} are concurrent: the plate {self.plate} cannot turn "
                f"further this way)")

    # ------------------------------------------------------------ construction
    def emit(self, b: Builder) -> None:
        if self.via:
            self._emit_on_normal(b)
            return
        B, A, LB, C, D, LC, X = (self.b, self.ob, self.link_b, self.c, self.oc, self.link_c,
                                 self.x)
        S, P = self.s, self.plate
        V = b.names.of
        a, d, s, x, pole = V(A), V(D), V(S), V(X), b.names.pole
        Cm = Component
        if b.velocity:
            n3 = Triad.assur_velocity(b, A, B, LB, D, C, LC, S, X, P)
            n4 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", pole, None,
                       "slider_line", f"v_{X}", f"v_{X} ∥ guide of {X}",
                       f"The block at {X} slides on a fixed guide: through {pole} draw a line "
                       f"along the guide of {X}.", component=Cm.RESULTANT)
            Triad._meet(b, x, X, (n3, n4), tail=", along its guide")
            self._rates(b, Op.OMEGA)
            return
        k = [b.fresh(B), b.fresh(S), b.fresh(C), b.fresh(S), b.fresh(X)]
        Triad._normal(b, LB, A, B, a, k[0], f"(a_{B})_{A}^n")
        Triad._normal(b, P, B, S, k[0], k[1], f"(a_{S})_{B}^n")
        n1 = Triad._tangent_line(b, A, B, k[1], None, (B, A, S, B))
        Triad._normal(b, LC, D, C, d, k[2], f"(a_{C})_{D}^n")
        Triad._normal(b, P, C, S, k[2], k[3], f"(a_{S})_{C}^n")
        n2 = Triad._tangent_line(b, D, C, k[3], None, (C, D, S, C))
        Triad._meet(b, s, S, (n1, n2), of=f"the auxiliary point {S}")
        Triad._normal(b, P, S, X, s, k[4], f"(a_{X})_{S}^n")
        n3 = Triad._tangent_line(b, S, X, k[4], P)
        n4 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", pole, None, "slider_line",
                   f"a_{X}", f"a_{X} ∥ guide of {X}",
                   f"Through {pole} draw a line along the guide of {X}: the block's "
                   f"acceleration lies along it (the guide is fixed: no Coriolis term).",
                   component=Cm.RESULTANT)
        Triad._meet(b, x, X, (n3, n4), tail=", along its guide")
        self._rates(b, Op.ALPHA, {P: (k[4], X), LB: (k[0], B), LC: (k[2], C)})

    def _emit_on_normal(self, b: Builder) -> None:
        """S on the link O₁P₁ produced and on the normal to the guide at X (where AB ∥ DC):
        v_S − v_X = ω_p × XS is along the guide, and so is v_X: s is where the line ⟂ O₁P₁
        through o₁ meets the guide's direction through the pole; then v_P₂ − v_S ⟂ SP₂ and
        v_P₂ − v_O₂ ⟂ O₂P₂ give p₂; x, p₁ are images.  Acceleration: a_S = a_O₁ + ω₁² (O₁ − P₁)
        + ω_p² (P₁ − S) + [⟂ O₁P₁] = ω_p² (X − S) + [∥ guide] (a_X and (a_S)ᵗ_X both along
        it), then p₂′ as v."""
        (P1, O1, L1), (P2, O2, L2) = self.roles
        X, S, P = self.x, self.s, self.plate
        V = b.names.of
        o1, o2, s, p2, pole = V(O1), V(O2), V(S), V(P2), b.names.pole
        Cm = Component
        where = (f"The auxiliary point {S}, where {O1}{P1} produced meets the normal to the "
                 f"guide of {X} at {X} ({self.pair_words(0)} are parallel here), is a point "
                 f"of the plate {P}")
        if b.velocity:
            n1 = b.add(Kind.LINE, Op.LINE_PERP, (O1, P1), f"line ⟂ {O1}{P1}", o1, None,
                       "relative_velocity", f"(v_{S})_{O1}", f"(v_{S})_{O1} ⟂ {O1}{P1}",
                       f"{where}: its velocity relative to {O1} is perpendicular to "
                       f"{O1}{P1}. Through {o1} draw a line ⟂ {O1}{P1}.",
                       component=Cm.CONSTRUCTION, link=L1)
            n2 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", pole, None,
                       "slider_line", f"v_{S}", f"v_{S} ∥ guide of {X}",
                       f"{S} is on the normal to the guide at {X}: v_{S} − v_{X} = ω × "
                       f"{X}{S} is along the guide, and so is v_{X}. Through {pole} draw a "
                       f"line along the guide of {X}.", component=Cm.CONSTRUCTION)
            Triad._meet(b, s, S, (n1, n2), of=f"the auxiliary point {S}")
            n3 = b.add(Kind.LINE, Op.LINE_PERP, (S, P2), f"line ⟂ {S}{P2}", s, None,
                       "relative_velocity", f"(v_{P2})_{S}", f"(v_{P2})_{S} ⟂ {S}{P2}",
                       f"{P2} and {S} are points of the plate: through {s} draw a line "
                       f"⟂ {S}{P2}.", component=Cm.CONSTRUCTION, link=P)
            n4 = b.add(Kind.LINE, Op.LINE_PERP, (O2, P2), f"line ⟂ {O2}{P2}", o2, None,
                       "relative_velocity", f"(v_{P2})_{O2}", f"(v_{P2})_{O2} ⟂ {O2}{P2}",
                       f"Through {o2} draw a line ⟂ {O2}{P2}: the velocity of {P2} relative "
                       f"to {O2}.", component=Cm.CONSTRUCTION, link=L2)
            Triad._meet(b, p2, P2, (n3, n4))
            self._rates(b, Op.OMEGA)
            return
        k = [b.fresh(P1), b.fresh(S), b.fresh(S), b.fresh(P2), b.fresh(P2)]
        Triad._normal(b, L1, O1, P1, o1, k[0], f"(a_{P1})_{O1}^n")
        Triad._normal(b, P, P1, S, k[0], k[1], f"(a_{S})_{P1}^n")
        n1 = Triad._tangent_line(b, O1, P1, k[1], None, (P1, O1, S, P1))
        Triad._normal(b, P, X, S, pole, k[2], f"(a_{S})_{X}^n")
        n2 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", k[2], None, "slider_line",
                   f"a_{X} + (a_{S})_{X}^t", f"a_{X} + (a_{S})_{X}^t ∥ guide of {X}",
                   f"Through {k[2]} draw a line along the guide of {X}: a_{X} (the block on "
                   f"a fixed guide) and (a_{S})_{X}^t (⟂ {X}{S}) both lie along it.",
                   component=Cm.CONSTRUCTION)
        Triad._meet(b, s, S, (n1, n2), of=f"the auxiliary point {S}")
        Triad._normal(b, P, S, P2, s, k[3], f"(a_{P2})_{S}^n")
        n3 = Triad._tangent_line(b, S, P2, k[3], P)
        Triad._normal(b, L2, O2, P2, o2, k[4], f"(a_{P2})_{O2}^n")
        n4 = Triad._tangent_line(b, O2, P2, k[4], L2)
        Triad._meet(b, p2, P2, (n3, n4))
        self._rates(b, Op.ALPHA, {P: (k[3], P2), L1: (k[0], P1), L2: (k[4], P2)})

    def _rates(self, b: Builder, op, tangential=None) -> None:
        """The plate's ω (α) from s and x, the images b and c, each link's ω (α), the
        block's velocity (acceleration) along its guide.  ω = relative velocity / length;
        α = the tangential part (from the end of the centripetal vector to the point) /
        length."""
        B, A, LB, C, D, LC, X = (self.b, self.ob, self.link_b, self.c, self.oc, self.link_c,
                                 self.x)
        S, P = self.s, self.plate
        V = b.names.of
        vel = op is Op.OMEGA
        sym, what, th = (("ω", "angular velocity", "angular_velocity") if vel
                         else ("α", "angular acceleration", "angular_acceleration"))
        comp = Component.RELATIVE if vel else Component.TANGENTIAL

        def read(L, O, Q):
            if tangential is None:
                return f"{V(O)}{V(Q)}", f"{V(O)}{V(Q)}"
            t = f"{tangential[L][0]}{V(tangential[L][1])}"
            return t, f"{t} (the tangential part of {V(O)}{V(Q)})"
        T = X if self.via == 0 else self.roles[1][0]      # the corner found with S
        vec, words = read(P, S, T)
        plate = f"{self.b}{self.c}{self.x}"
        # one symbol for the plate's rate everywhere (legend, narration, table, grader):
        # the link's, ω_BC; the words name the plate by its corners
        called = plate if plate == P else f"{plate} (link {P})"
        b.add(Kind.MEASURE, op, (P, S, T), f"{sym}_{P}", None, None, th, f"{sym}_{P}",
              f"{sym}_{P} = {vec} / {S}{T}",
              f"The {what} of the plate {called} is {words} divided by {S}{T}.",
              component=comp, link=P)
        for Q in (B, C, X):
            if Q != T:
                image.emit_image(b, Q, P, S, T)
        for L, O, Q in ((LB, A, B), (LC, D, C)):
            vec, words = read(L, O, Q)
            b.add(Kind.MEASURE, op, (L, O, Q), f"{sym}_{L}", None, None, th, f"{sym}_{L}",
                  f"{sym}_{L} = {vec} / {O}{Q}",
                  f"The {what} of {L} is {words} divided by {O}{Q}.", component=comp, link=L)
        pole, x = b.names.pole, V(X)
        b.add(Kind.MEASURE, Op.SLIDER_VELOCITY if vel else Op.SLIDER_ACCELERATION, (X,),
              f"{b.q}_{X}", None, None, "slider", f"{b.q}_{X} along guide",
              f"{b.q}_{X} = {pole}{x}",
              f"The block's {b.what} is {pole}{x}, along its guide.",
              component=Component.RESULTANT)


# ---------------------------------------------------------------- finding the groups
def matches(scene, placed):
    """Every plate whose one corner is a block on a fixed guide ([sliders], no slot or pin on
    it) with no link of its own, and whose two other corners each have one link to a placed
    point, none of the corners placed."""
    found = []
    taken = set(placed)
    for corners, plate, plate_links, ternary in _plates(scene):
        if any(k in placed or k in scene.slots for k in corners):
            continue
        on_guide = [k for k in corners if k in scene.sliders]
        if len(on_guide) != 1:
            continue
        x = on_guide[0]
        g = scene.sliders[x]
        if g.pin is not None or g.slot_angle is not None:
            continue
        outer = {}
        for k in corners:
            outer[k] = [(l.b if l.a == k else l.a, l.name) for l in scene.links.values()
                        if k in (l.a, l.b) and l.length is not None
                        and l.name not in plate_links and (l.b if l.a == k else l.a)
                        not in corners]
        if outer[x]:
            continue
        b, c = (k for k in corners if k != x)
        if not all(len(outer[k]) == 1 and outer[k][0][0] in placed for k in (b, c)):
            continue
        (ob, lb), (oc, lc) = outer[b][0], outer[c][0]
        s = _aux_label(scene, taken)
        taken.add(s)
        found.append(TriadSlider(b, c, x, ob, oc, lb, lc, plate, plate_links, s, ternary,
                                 guide_e=tuple(float(v) for v in g.direction)))
    return found
