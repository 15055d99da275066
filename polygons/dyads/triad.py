"""The class-III Assur group (a triad): a rigid plate with corners B, C, X, each joined by a
binary link to a placed point (AB, DC, EX).  No dyad places it: the three corners close
together.

The scene states it as the book draws it, with no table of its own: the plate is a link BC
carrying a point X ([points.X] on = "BC", a ternary link), or a triangle of three links BC,
CX, BX (its mirror image is then a closure too); each corner has one more link to a placed
point.  ``[assembly]`` (words or ``near``) on any corner chooses the closure.

Position: every closure, algebraically (:mod:`polygons.dyads.triad_math`: the real roots of
a polynomial of degree ≤ 6, each polished by Newton); the one the scene's words or ``near``
choose, followed by continuation through a sweep.

Where AB and DC are parallel S is at infinity (a point of the construction, not a singularity
of the group): the construction then takes S where another pair of the three links meets
(:attr:`Triad.via`, :meth:`Triad.for_instant`).

Velocity, by the auxiliary (Assur) point S, where the lines of AB and DC cross: S is a point
of the plate on AB produced, so v_S − v_A = ω_AB × AB + ω_plate × BS is ⟂ AB, and likewise
v_S − v_D ⟂ DC: s is where the line ⟂ AB through a meets the line ⟂ DC through d.  Then
v_X − v_S ⟂ SX and v_X − v_E ⟂ EX give x, and b, c are images on the plate (s, x).

Acceleration, the same with the normal parts known: a_S = a_A + ω_AB² (A − B) + ω_p² (B − S)
+ [⟂ AB] = a_D + ω_DC² (D − C) + ω_p² (C − S) + [⟂ DC] gives s′; a_X = a_S + ω_p² (S − X)
+ [⟂ SX] = a_E + ω_EX² (E − X) + [⟂ EX] gives x′; b′, c′ are images.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..steps import Builder, Component, Kind, Op
from . import image
from .primitives import AssurPoint, Length, PlateShape, Then, TriadClosure


@dataclass(frozen=True)
class Triad:
    """Plate ``plate`` with corners ``b``, ``c``, ``x`` joined by ``link_b``, ``link_c``,
    ``link_x`` to the placed ``ob``, ``oc``, ``ox``; ``s`` the Assur point (on AB and DC
    produced); ``ternary``: the plate is a link with a [points] corner (else a triangle of
    links, whose mirror image is a closure too)."""
    b: str
    c: str
    x: str
    ob: str
    oc: str
    ox: str
    link_b: str
    link_c: str
    link_x: str
    plate: str
    plate_links: tuple[str, ...]
    s: str
    ternary: bool
    via: int = 0            # the two links whose lines meet at S: 0 AB, DC; 1 AB, EX; 2 DC, EX
    two_closures = False
    many_closures = True

    #: its force polygon: the construction of that name in
    #: :data:`polygons.forces.graphical.POLYGONS`
    force_polygon = "triad"

    def auxiliary_points(self) -> tuple[tuple[str, tuple[str, str], tuple[str, str]], ...]:
        """The construction points the space diagram draws with the group: (S, (OB, B),
        (OC, C)): Assur's point S where OB·B and OC·C produced meet."""
        (B, OB, _), (C, OC, _), _ = self.roles
        return ((self.s, (OB, B), (OC, C)),)

    def force_bodies(self) -> tuple[str, ...]:
        """The bodies whose force polygon this group closes."""
        return (((self.plate,) if self.ternary else tuple(self.plate_links))
                + (self.link_b, self.link_c, self.link_x))

    @property
    def roles(self):
        """((P₁, O₁, link₁), (P₂, O₂, link₂), (P₃, O₃, link₃)): S where O₁P₁ and O₂P₂
        produced meet (:attr:`via`), then the third corner P₃ from S and O₃."""
        r = ((self.b, self.ob, self.link_b), (self.c, self.oc, self.link_c),
             (self.x, self.ox, self.link_x))
        i, j, k = ((0, 1, 2), (0, 2, 1), (1, 2, 0))[self.via]
        return r[i], r[j], r[k]

    def assur_sine(self, points, via=None) -> float:
        """|sin| of the angle between the two links that meet at S (for ``via``, default
        this group's): 0 where they are parallel and S is at infinity."""
        from dataclasses import replace
        (p1, o1, _), (p2, o2, _), _ = replace(self, via=self.via if via is None
                                              else via).roles
        u = np.subtract(points[p1], points[o1])
        w = np.subtract(points[p2], points[o2])
        n = float(np.hypot(*u) * np.hypot(*w))
        return abs(float(u[0] * w[1] - u[1] * w[0])) / n if n > 0 else 0.0

    def pair_words(self, via=None) -> str:
        """The two links whose lines meet at S for ``via`` (default this group's), in words."""
        from dataclasses import replace
        (p1, o1, _), (p2, o2, _), _ = replace(self, via=self.via if via is None
                                              else via).roles
        return f"{o1}{p1} and {o2}{p2}"

    def for_instant(self, points):
        """This group with S taken on the pair of lines that meet best at the instant
        ``points`` when its own pair is parallel within 1° (S at infinity is a point of the
        construction, not a singularity of the group): (group, note) — note '' if kept."""
        from dataclasses import replace
        if self.assur_sine(points) >= math.sin(math.radians(1.0)):
            return self, ""
        best = max(range(3), key=lambda v: self.assur_sine(points, v))
        if best == self.via:
            return self, ""
        return replace(self, via=best), (
            f"the lines {self.pair_words()} are parallel here (the auxiliary point {self.s} "
            f"at infinity, not a singularity of the group): {self.s} is taken where "
            f"the lines {self.pair_words(best)} meet instead")

    @property
    def placed(self) -> tuple[str, ...]:
        return (self.b, self.c, self.x, self.s)

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.ob, self.oc, self.ox)

    @property
    def links(self) -> tuple[str, ...]:
        return (self.link_b, self.link_c, self.link_x) + self.plate_links

    @property
    def sigma_keys(self) -> tuple[str, ...]:
        """Where the chosen closure is kept (the record of the assembly), under B's label: B's
        and X's coordinates, the reference a sweep follows ('#': no label holds it)."""
        return (f"{self.b}#bx", f"{self.b}#by", f"{self.b}#xx", f"{self.b}#xy")

    # ------------------------------------------------------------ geometry
    @cached_property
    def construction(self) -> Then:
        """Its position, stated once (:mod:`polygons.dyads.primitives`): the corners B, C, X
        by the closure nearest the one kept (:class:`TriadClosure`), then Assur's point S
        where the pair of links :attr:`roles` names meet (:class:`AssurPoint`).  ``source``
        is this statement and ``locate`` its evaluation: the staged solve, the sweeps and
        the generated program run the same formulas."""
        (p1, o1, _), (p2, o2, _), _ = self.roles
        plate = PlateShape(self.x, (self.plate,) if self.ternary else self.plate_links)
        closure = TriadClosure((self.b, self.c, self.x), (self.ob, self.oc, self.ox),
                               (Length(self.link_b), Length(self.link_c), Length(self.link_x)),
                               plate, self.sigma_keys)
        return Then((closure, AssurPoint(self.s, o1, p1, o2, p2)))

    def shape(self, scene) -> tuple[float, float, float]:
        """The plate in its own frame: C = (L, 0), X = (ξ, η) from B."""
        return self.construction.steps[0].plate.value(scene)

    def closures(self, scene, pos) -> list[dict]:
        """Every closure at the positions ``pos``: {B, C, X, S} each."""
        closure, assur = self.construction.steps
        out = []
        for pts in closure.every(scene, pos):
            pts.update(assur.locate(scene, {**pos, **pts}, None, 0.0)[0])
            out.append(pts)
        return out

    def locate(self, scene, pos, sigma, x):
        """The closure nearest the reference ``sigma`` ({key: value} of :attr:`sigma_keys`;
        None: the first closure), over one position or (2, N) arrays (continuation)."""
        if not sigma:
            one = all(np.ndim(pos[k]) == 1 for k in self.needs)
            cands = self.closures(scene, pos) if one else None
            if one and not cands:
                return self._nan(pos), -1.0
            B, X = (cands[0][self.b], cands[0][self.x]) if one else ((0.0, 0.0), (0.0, 0.0))
            sigma = dict(zip(self.sigma_keys, (B[0], B[1], X[0], X[1])))
        return self.construction.locate(scene, pos, sigma, x)

    def _nan(self, pos):
        return {k: np.full_like(np.asarray(pos[self.ob], dtype=float), np.nan)
                for k in self.placed}

    def source(self, g):
        """:meth:`locate`'s statement in the generated program: the same primitives (its
        margin)."""
        return self.construction.source(g)

    def why_not(self, scene, pos) -> str:
        return (f"the class-III group (the plate {self.plate} with corners {self.b}, {self.c}, "
                f"{self.x} on the links {self.link_b}, {self.link_c}, {self.link_x}) cannot "
                f"close at this input: no position of the plate gives all three links their "
                f"lengths")

    def toggle_reason(self, scene, pos) -> str:
        return (f"two closures of the class-III group {self.b}{self.c}{self.x} meet here "
                f"(the plate {self.plate} cannot turn further this way)")

    # ------------------------------------------------------------ construction
    @staticmethod
    def assur_velocity(b: Builder, A, B, LB, D, C, LC, S, X, P) -> int:
        """v_S from the two lines ⟂ AB through a and ⟂ DC through d (S, where AB and DC
        produced meet, is a point of the plate P on both), then the line ⟂ SX through s that
        carries v_X: the number of that line (the group meets it with X's own line)."""
        a, d, s = b.names.of(A), b.names.of(D), b.names.of(S)
        Cm = Component
        n1 = b.add(Kind.LINE, Op.LINE_PERP, (A, B), f"line ⟂ {A}{B}", a, None,
                   "relative_velocity", f"(v_{S})_{A}", f"(v_{S})_{A} ⟂ {A}{B}",
                   f"The auxiliary point {S}, where {A}{B} and {D}{C} produced meet, is a "
                   f"point of the plate {P} on {A}{B} produced: its velocity relative to "
                   f"{A} is perpendicular to {A}{B}. Through {a} draw a line ⟂ {A}{B}.",
                   component=Cm.CONSTRUCTION, link=LB)
        n2 = b.add(Kind.LINE, Op.LINE_PERP, (D, C), f"line ⟂ {D}{C}", d, None,
                   "relative_velocity", f"(v_{S})_{D}", f"(v_{S})_{D} ⟂ {D}{C}",
                   f"{S} is also on {D}{C} produced: through {d} draw a line ⟂ {D}{C}.",
                   component=Cm.CONSTRUCTION, link=LC)
        Triad._meet(b, s, S, (n1, n2), of=f"the auxiliary point {S}", pivots=(A, D))
        n3 = b.add(Kind.LINE, Op.LINE_PERP, (S, X), f"line ⟂ {S}{X}", s, None,
                   "relative_velocity", f"(v_{X})_{S}", f"(v_{X})_{S} ⟂ {S}{X}",
                   f"{X} and {S} are points of the plate: through {s} draw a line "
                   f"⟂ {S}{X}.", component=Cm.CONSTRUCTION, link=P)
        return n3

    def emit(self, b: Builder) -> None:
        # B, C: the corners whose links meet at S; X the third (the roles, not the labels)
        (B, A, LB), (C, D, LC), (X, E, LX) = self.roles
        S, P = self.s, self.plate
        V = b.names.of
        a, d, e, s, x = V(A), V(D), V(E), V(S), V(X)
        Cm = Component
        if b.velocity:
            n3 = self.assur_velocity(b, A, B, LB, D, C, LC, S, X, P)
            n4 = b.add(Kind.LINE, Op.LINE_PERP, (E, X), f"line ⟂ {E}{X}", e, None,
                       "relative_velocity", f"(v_{X})_{E}", f"(v_{X})_{E} ⟂ {E}{X}",
                       f"Through {e} draw a line ⟂ {E}{X}: the velocity of {X} relative to "
                       f"{E}.", component=Cm.CONSTRUCTION, link=LX)
            self._meet(b, x, X, (n3, n4), pivots=(E,))
            self._rates(b, Op.OMEGA)
            return
        k = [b.fresh(B), b.fresh(S), b.fresh(C), b.fresh(S), b.fresh(X), b.fresh(X)]
        self._normal(b, LB, A, B, a, k[0], f"(a_{B})_{A}^n")
        self._normal(b, P, B, S, k[0], k[1], f"(a_{S})_{B}^n")
        # S is on AB produced: (a_B)_A^t and (a_S)_B^t are both ⟂ AB, so the line through s₁
        # carries their sum (one vector s₁s, of no single link: named as the sum it is)
        n1 = self._tangent_line(b, A, B, k[1], None, (B, A, S, B))
        self._normal(b, LC, D, C, d, k[2], f"(a_{C})_{D}^n")
        self._normal(b, P, C, S, k[2], k[3], f"(a_{S})_{C}^n")
        n2 = self._tangent_line(b, D, C, k[3], None, (C, D, S, C))
        self._meet(b, s, S, (n1, n2), of=f"the auxiliary point {S}", pivots=(A, D))
        self._normal(b, P, S, X, s, k[4], f"(a_{X})_{S}^n")
        n3 = self._tangent_line(b, S, X, k[4], P)
        self._normal(b, LX, E, X, e, k[5], f"(a_{X})_{E}^n")
        n4 = self._tangent_line(b, E, X, k[5], LX)
        self._meet(b, x, X, (n3, n4), pivots=(E,))
        # each α from its own tangential part: x₁x (plate), b₁b, c₁c, x₂x (the links), the
        # end of each centripetal vector to the point — never the whole relative acceleration
        self._rates(b, Op.ALPHA, {P: (k[4], X), LB: (k[0], B), LC: (k[2], C), LX: (k[5], X)})

    def _rates(self, b: Builder, op, tangential=None) -> None:
        """The plate's ω (α) from s and x, the images b and c, each link's ω (α).

        ω = (the relative velocity) / length; α = (the tangential part, from the end of the
        centripetal vector to the point: x₁x, b₁b, c₁c, x₂x) / length.  ``tangential``: link →
        (the end of its centripetal vector, the point), keyed by the roles' links."""
        (B, OB, LB), (C, OC, LC), (X, OX, LX) = self.roles
        S = self.s
        V = b.names.of
        sym, what, th = (("ω", "angular velocity", "angular_velocity") if op is Op.OMEGA
                         else ("α", "angular acceleration", "angular_acceleration"))
        comp = Component.RELATIVE if op is Op.OMEGA else Component.TANGENTIAL
        P = self.plate

        def read(L, O, Q):
            """(the vector the rate is read from, the words saying so)."""
            o = b.names.named(O)        # dc about the fixed D (the pole o = d = e)
            if tangential is None:
                return f"{o}{V(Q)}", f"{o}{V(Q)}"
            t = f"{tangential[L][0]}{V(tangential[L][1])}"
            return t, f"{t} (the tangential part of {o}{V(Q)})"
        vec, words = read(P, S, X)
        plate = f"{self.b}{self.c}{self.x}"   # the plate named for its corners (link P carries it)
        # one symbol for the plate's rate everywhere (legend, narration, table, grader):
        # the link's, ω_BC; the words name the plate by its corners
        called = plate if plate == P else f"{plate} (link {P})"
        b.add(Kind.MEASURE, op, (P, S, X), f"{sym}_{P}", None, None, th, f"{sym}_{P}",
              f"{sym}_{P} = {vec} / {S}{X}",
              f"The {what} of the plate {called} is {words} divided by {S}{X}.",
              component=comp, link=P)
        image.emit_image(b, B, P, S, X)
        image.emit_image(b, C, P, S, X)
        for L, O, Q in ((LB, OB, B), (LC, OC, C), (LX, OX, X)):
            vec, words = read(L, O, Q)
            b.add(Kind.MEASURE, op, (L, O, Q), f"{sym}_{L}", None, None, th, f"{sym}_{L}",
                  f"{sym}_{L} = {vec} / {O}{Q}",
                  f"The {what} of {L} is {words} divided by {O}{Q}.", component=comp, link=L)

    @staticmethod
    def _meet(b: Builder, p, P, lines, of=None, tail="", pivots=()) -> None:
        """The step where two construction lines meet at the vertex ``p``: pole → p is the
        velocity (acceleration) of ``P`` (in words ``of``, then ``tail``)."""
        # the resultant named from the fixed pivot one of its lines turns about, as the book
        # writes it (ds, ex where the pole is o = d = e; as the four-bar's dc)
        # (``pivots``: the outer pins the point is read about, the first fixed one names it)
        pole = b.names.pole
        fixed = next((q for q in pivots if q in b.scene.ground), None)
        about = b.names.named(fixed) if fixed else pole
        b.add(Kind.INTERSECTION, Op.INTERSECT, (fixed,) if fixed else (), p, None, p,
              "intersection", f"{b.q}_{P}", f"{p} = intersection of the two lines",
              f"The lines meet at {p}: {about}{p} is the {b.what} of {of or P}{tail}.",
              lines, component=Component.RESULTANT)

    @staticmethod
    def _normal(b: Builder, L, P, Q, frm, to, name) -> None:
        # from the pole: named from its centre's own letter (dc₁ about the fixed D)
        fn = b.names.named(P) if frm == b.names.pole else frm
        b.add(Kind.VECTOR, Op.CENTRIPETAL, (L, P, Q), f"{fn}{to}", frm, to, "centripetal",
              name, f"{name} = ω_{L}² × {P}{Q}",
              f"From {fn} draw the centripetal acceleration of {Q} relative to {P}, ω_{L}² × "
              f"{P}{Q}, pointing from {Q} towards {P}; call its end {to}.",
              component=Component.CENTRIPETAL, link=L)

    @staticmethod
    def _tangent_line(b: Builder, P, Q, frm, L, terms=None):
        """The line ⟂ PQ through ``frm`` for the tangential acceleration (a_Q)_P^t; with
        ``terms`` (Q, P, Q2, P2) for the sum (a_Q)_P^t + (a_Q2)_P2^t of two such terms along
        one line (S on PQ produced)."""
        if terms is None:
            name = f"(a_{Q})_{P}^t"
            why = "for the tangential accelerations"
        else:
            q1, p1, q2, p2 = terms
            name = f"(a_{q1})_{p1}^t + (a_{q2})_{p2}^t"
            why = f"for {name} (both ⟂ {P}{Q})"
        return b.add(Kind.LINE, Op.LINE_PERP, (P, Q), f"line ⟂ {P}{Q}", frm, None,
                     "tangential", name, f"{name} ⟂ {P}{Q}",
                     f"Through {frm} draw a line ⟂ {P}{Q} {why}, of unknown length.",
                     component=Component.CONSTRUCTION, link=L)


# ---------------------------------------------------------------- finding the groups
def _plates(scene):
    """(corners (B, C, X), plate name, plate links, ternary) of every rigid plate: a link
    with a [points] corner, or a triangle of three links."""
    links = {n: l for n, l in scene.links.items() if l.length is not None}
    for label, bp in scene.points.items():
        ln = links.get(bp.link)
        if ln is not None:
            yield (ln.a, ln.b, label), ln.name, (ln.name,), True
    ends = {}
    for n, l in links.items():
        ends.setdefault(l.a, {})[l.b] = n
        ends.setdefault(l.b, {})[l.a] = n
    seen = set()
    for n, l in links.items():
        for x in set(ends.get(l.a, {})) & set(ends.get(l.b, {})):
            key = frozenset((l.a, l.b, x))
            if key in seen:
                continue
            seen.add(key)
            yield (l.a, l.b, x), n, (n, ends[l.a][x], ends[l.b][x]), False


def _aux_label(scene, taken) -> str:
    for lab in ("S",) + tuple(f"S{i}" for i in range(1, 100)):
        if lab not in scene.labels and lab not in taken:
            return lab
    return "S_aux"


def matches(scene, placed):
    """Every triad whose three outer points are placed and whose corners are not."""
    found = []
    taken = set(placed)
    for (B, C, X), plate, plate_links, ternary in _plates(scene):
        corners = (B, C, X)
        if any(k in placed or k in scene.sliders or k in scene.slots for k in corners):
            continue
        outer = []
        for k in corners:
            out = [(l.b if l.a == k else l.a, l.name) for l in scene.links.values()
                   if k in (l.a, l.b) and l.length is not None and l.name not in plate_links
                   and (l.b if l.a == k else l.a) not in corners]
            outer.append(out)
        if not all(len(o) == 1 and o[0][0] in placed for o in outer):
            continue
        (ob, lb), (oc, lc), (ox, lx) = (o[0] for o in outer)
        s = _aux_label(scene, taken)
        taken.add(s)
        found.append(Triad(B, C, X, ob, oc, ox, lb, lc, lx, plate, plate_links, s, ternary))
    return found
