"""Klein's construction (and Ritterhaus's, Bennett's) for the slider-crank, read off the space diagram.

A crank OA turning uniformly at ω, a connecting rod AB, the piston B on a fixed straight
guide (the line of stroke).  The books' figure (Khurmi, *Theory of Machines*, §8.2–8.3; the
letters here are the books' where the scene does not use them):

* **velocity** — the line through O perpendicular to the stroke meets the rod's line (produced)
  at M.  The triangle O A M is the velocity polygon turned 90°, at ω per unit length:
  oa = ω·OA, ab = ω·AM, ob = v_B = ω·OM;
* **acceleration (Klein)** — the *Klein circle*, centre A radius AM, and the circle on AB as
  diameter cut at K and L; the common chord KL meets AB at Q and the line through O parallel
  to the stroke at N.  O A Q N is the acceleration polygon turned 180°, at ω² per unit length:
  a_A = ω²·OA (towards O), (a_B)ⁿ_A = ω²·AQ (AQ·AB = AM², the chord's foot), (a_B)ᵗ_A =
  ω²·QN, a_B = ω²·NO;
* **acceleration (Ritterhaus)** — the line through M parallel to the stroke meets the crank OA
  (produced) at K; the line through K perpendicular to the stroke meets the rod at Q (the same
  Q: the triangles A K Q and A O M are similar, as A K M and A O B are, so AQ = AM²/AB); the
  perpendicular to the rod at Q meets the stroke at N, as in Klein's;
* **acceleration (Bennett)** — the crank at right angles to the stroke, O A₁, with its rod
  A₁ B₁: the foot L₁ of the perpendicular from O on A₁ B₁ gives A₁L₁ = OA²/AB (the same for
  every crank angle); L on the rod with AL = A₁L₁; the perpendicular to the rod at L meets
  the line of stroke at K, the perpendicular to the stroke at K meets the rod at Q (again
  AQ = AM²/AB), and the perpendicular to the rod at Q meets the stroke at N, as in Klein's.
  The steps are Khurmi's as quoted in lecture notes (the printed page was not seen); where
  the quotation is unclear (which line LK meets) the line of stroke is taken, the one choice
  that makes Q Klein's Q: along the rod from A, Q is at (AL + y_A·u_y)/u_x² with u the rod's
  direction and y_A the pin's height over the stroke, which is AM²/AB exactly when
  AL = OA²/AB and O lies on the stroke.

Klein's construction holds for an in-line and an offset engine (then N lies on the line
through O *parallel* to the stroke, not on the stroke); Ritterhaus's and Bennett's for an
in-line engine only (their similar triangles / projections need O on the line of stroke) and
all three for a crank turning uniformly (α = 0): a crank with α ≠ 0, a scene that is not a
slider-crank or an offset engine asked for Ritterhaus or Bennett is refused in one line.

Every intersection is :func:`polygons.geometry.intersect` (its angle reported); every number
is read off the figure's points and compared with the polygons' (``difference``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

from .. import geometry
from ..errors import PolygonsError, UnsupportedError
from ..records import Crank

Vec = tuple[float, float]

#: the constructions this module draws
METHODS = ("klein", "ritterhaus", "bennett")
#: their names as reports print them
TITLES = {"klein": "Klein's construction", "ritterhaus": "Ritterhaus's construction",
          "bennett": "Bennett's construction"}
#: an engine is in-line when O is this close to the line of stroke (relative to the rod)
INLINE_REL = 1e-9

#: the figure's own points, each with the letters the books use first
ROLES = ("M", "K", "L", "Q", "N")
#: Bennett's crank at right angles (A₁), its piston (B₁) and the foot L₁ (named after A, B)
BENNETT_ROLES = ("A1", "B1", "L1")


@dataclass(frozen=True)
class Figure:
    """One construction at one instant, in metres (space-diagram coordinates)."""

    method: str
    names: Mapping[str, str]       # role ('O', 'A', 'B', 'M', 'K', 'L', 'Q', 'N'; Bennett's
    #                                'A1', 'B1', 'L1') -> label
    points: Mapping[str, Vec]      # role -> position
    stroke: Vec                    # unit vector along the line of stroke
    stroke_point: Vec              # a point of the line of stroke
    offset: float                  # signed distance of O from the stroke (left positive)
    omega: float                   # the crank's ω, CCW positive
    rod: str                       # the connecting rod's name
    crank: str
    #: the Klein circle (centre A, radius AM) and the circle on AB (centre, radius)
    klein_circle: tuple[Vec, float]
    rod_circle: tuple[Vec, float]
    angles: Mapping[str, float]    # intersection -> its angle (deg)
    #: read off the figure: the piston's velocity and acceleration (signed along ``stroke``),
    #: the rod's ω and α (CCW positive)
    v_piston: float
    a_piston: float
    omega_rod: float
    alpha_rod: float
    #: the same four read off the polygons, for the comparison
    polygon: Mapping[str, float]

    @property
    def inline(self) -> bool:
        return self.names["inline"] == "yes"

    @property
    def difference(self) -> float:
        """Largest relative difference between the figure's numbers and the polygons'."""
        mine = {"v_piston": self.v_piston, "a_piston": self.a_piston,
                "omega_rod": self.omega_rod, "alpha_rod": self.alpha_rod}
        out = 0.0
        for k, v in mine.items():
            ref = self.polygon[k]
            out = max(out, abs(v - ref) / max(abs(ref), _floor(k, self)))
        return out


def _floor(key: str, f: Figure) -> float:
    """A magnitude below which a difference is judged absolutely (a quantity that is zero)."""
    L = math.dist(f.points["A"], f.points["B"])
    r = math.dist(f.points["O"], f.points["A"])
    w = abs(f.omega)
    return {"v_piston": w * r, "a_piston": w * w * r, "omega_rod": w,
            "alpha_rod": w * w * r / L}[key]


def refuse(reason: str, scene) -> UnsupportedError:
    return UnsupportedError(reason, file=scene.file, where="diagram.klein")


def engine(scene):
    """(crank, rod, O, A, B, guide) of a slider-crank scene, or an error saying why not."""
    drv = scene.driver
    what = ("Klein's construction is for the slider-crank (a crank OA, a connecting rod AB, "
            "the piston B on a fixed straight guide)")
    if not isinstance(drv, Crank):
        raise refuse(f"{what}: this scene is driven by a slider, not a crank", scene)
    model = scene.model
    rods = []
    for body in model.bodies:
        if body.kind != "link" or body.name == drv.link:
            continue
        for a, b in ((body.a, body.b), (body.b, body.a)):
            g = model.fixed_guide(b)
            if a == drv.tip and g is not None and b not in model.slot and \
                    model.body(b).kind == "block":
                rods.append((body.name, a, b, g))
    if len(rods) != 1:
        found = "no link joins the crank pin to a slider on a fixed guide" if not rods else \
            "more than one rod joins the crank pin to a slider"
        raise refuse(f"{what}: in this scene {found}", scene)
    if model.slot or model.crossings() or model.collar:
        raise refuse(f"{what}: this scene also has slots or a second input", scene)
    rod, a, b, g = rods[0]
    return drv, rod, drv.pivot, a, b, g


def figure(sol, method: str = "klein") -> Figure:
    """The construction ``method`` ('klein' or 'ritterhaus') at ``sol``'s instant."""
    scene = sol.scene
    if method not in METHODS:
        raise refuse(f"unknown construction {method!r}: one of {', '.join(METHODS)}", scene)
    drv, rod, O_, A_, B_, guide = engine(scene)
    if "acceleration" not in scene.solve:
        raise refuse(f"{TITLES[method]} reads the acceleration too: the scene stops at the "
                     f"velocity polygon (solve = {list(scene.solve)})", scene)
    if drv.alpha != 0.0:
        raise refuse(f"{TITLES[method]} is for a crank turning uniformly; this crank has "
                     f"α = {abs(drv.alpha):.6g} rad/s² (the polygons handle it)", scene)
    if drv.omega == 0.0:
        raise refuse(f"{TITLES[method]} draws at ω per unit length: this crank is at rest "
                     f"(ω = 0)", scene)
    pos = sol.placement.points
    O, A, B = pos[O_], pos[A_], pos[B_]
    sp, e = guide.line.at(pos)
    n = (-e[1], e[0])
    L = math.dist(A, B)
    offset = (O[0] - sp[0]) * n[0] + (O[1] - sp[1]) * n[1]
    inline = abs(offset) <= INLINE_REL * L
    if method in ("ritterhaus", "bennett") and not inline:
        raise refuse(f"{TITLES[method]} is for an in-line engine; this one is offset "
                     f"{abs(offset) * 1000:.6g} mm (use Klein's, which covers both)", scene)
    w = drv.omega
    angles = {}

    def cut(p, u, q, v, what):
        x = geometry.intersect(geometry.line(p, u, what[0]), geometry.line(q, v, what[1]),
                               step=f"{method} {what[2]}")
        angles[what[2]] = x.angle_deg
        return x.point

    rod_u = (B[0] - A[0], B[1] - A[1])
    M = cut(O, n, A, rod_u, ("line through O ⟂ the stroke", "rod's line", "M"))
    lam = ((M[0] - A[0]) * rod_u[0] + (M[1] - A[1]) * rod_u[1]) / (L * L)   # AM = λ·AB
    AM = math.dist(A, M)
    pts = {"O": O, "A": A, "B": B, "M": M}
    klein_circle = (A, AM)
    mid = ((A[0] + B[0]) / 2, (A[1] + B[1]) / 2)
    rod_circle = (mid, L / 2)
    if method == "klein":
        # the two circles cut on the chord whose foot Q on AB has AQ = AM²/AB
        AQ = AM * AM / L
        Q = (A[0] + rod_u[0] * AQ / L, A[1] + rod_u[1] * AQ / L)
        h2 = AM * AM - AQ * AQ
        if h2 >= 0.0:
            h = math.sqrt(h2)
            t = (-rod_u[1] / L, rod_u[0] / L)
            pts["K"] = (Q[0] + h * t[0], Q[1] + h * t[1])
            pts["L"] = (Q[0] - h * t[0], Q[1] - h * t[1])
    elif method == "bennett":
        # the crank at right angles to the stroke (on the side of A) and its rod
        r = math.dist(O, A)
        side = 1.0 if (A[0] - O[0]) * n[0] + (A[1] - O[1]) * n[1] >= 0 else -1.0
        A1 = (O[0] + side * r * n[0], O[1] + side * r * n[1])
        tb = (B[0] - O[0]) * e[0] + (B[1] - O[1]) * e[1]
        B1 = (O[0] + math.copysign(math.sqrt(L * L - r * r), tb) * e[0],
              O[1] + math.copysign(math.sqrt(L * L - r * r), tb) * e[1])
        u1 = (B1[0] - A1[0], B1[1] - A1[1])
        L1 = cut(O, (-u1[1], u1[0]), A1, u1, ("perpendicular from O to A₁B₁", "rod A₁B₁", "L1"))
        AL = math.dist(A1, L1)
        Lp = (A[0] + rod_u[0] * AL / L, A[1] + rod_u[1] * AL / L)
        K = cut(Lp, (-rod_u[1], rod_u[0]), sp, e,
                ("perpendicular to the rod at L", "line of stroke", "K"))
        Q = cut(K, n, A, rod_u, ("line through K ⟂ the stroke", "rod's line", "Q"))
        pts.update({"A1": A1, "B1": B1, "L1": L1, "L": Lp, "K": K})
    else:
        K = cut(M, e, O, (A[0] - O[0], A[1] - O[1]),
                ("line through M ∥ the stroke", "crank's line", "K"))
        pts["K"] = K
        Q = cut(K, n, A, rod_u, ("line through K ⟂ the stroke", "rod's line", "Q"))
    pts["Q"] = Q
    N = cut(Q, (-rod_u[1], rod_u[0]), O, e,
            ("perpendicular to the rod at Q", "line through O ∥ the stroke", "N"))
    pts["N"] = N
    # read off the figure (turned 90° for velocity, 180° for acceleration)
    vM = (M[0] - O[0], M[1] - O[1])
    v_b = (-w * vM[1], w * vM[0])                    # ω k × OM
    a_b = (-w * w * (N[0] - O[0]), -w * w * (N[1] - O[1]))
    dn = (N[0] - Q[0], N[1] - Q[1])
    alpha_rod = -w * w * (dn[0] * -rod_u[1] + dn[1] * rod_u[0]) / (L * L)
    vb, ab = sol.points[B_].velocity, sol.points[B_].acceleration
    link = sol.links[rod]
    polygon = {"v_piston": vb[0] * e[0] + vb[1] * e[1], "a_piston": ab[0] * e[0] + ab[1] * e[1],
               "omega_rod": link.omega, "alpha_rod": link.alpha}
    used = set(scene.labels)
    names = {"O": O_, "A": A_, "B": B_, "inline": "yes" if inline else "no"}
    for role in ROLES:
        names[role] = _fresh(role, used)
        used.add(names[role])
    if method == "bennett":
        for role, base in zip(BENNETT_ROLES, (A_, B_, names["L"])):
            names[role] = _fresh(base + "1", used)
            used.add(names[role])
    return Figure(method, names, pts, e, sp, offset, w, rod, drv.link, klein_circle,
                  rod_circle, angles, v_b[0] * e[0] + v_b[1] * e[1],
                  a_b[0] * e[0] + a_b[1] * e[1], w * lam, alpha_rod, polygon)


def asked(sol) -> bool:
    """Whether an answer of ``sol``'s scene names a point of Klein's figure (``dist(O,N)``,
    "Klein's ON"): then the figure is drawn and reported without ``--klein``."""
    import re
    labels = {x for a in sol.scene.answers
              for x in re.findall(r"[A-Z][a-z0-9_']*", a.quantity)} - set(sol.points)
    if not labels:
        return False
    try:
        f = figure(sol)
    except PolygonsError:
        return False
    return bool(labels & {f.names[r] for r in ROLES})


def figure_point(sol, label: str) -> Vec | None:
    """The position of ``label`` if it is a point of Klein's figure at ``sol`` (M, K, L, Q, N
    or the letters the figure took), else None (not a slider-crank: None too)."""
    from ..memo import memo_of
    memo = memo_of(sol)
    if "klein" not in memo:
        try:
            memo["klein"] = figure(sol)
        except PolygonsError:
            memo["klein"] = None
    f = memo["klein"]
    if f is None:
        return None
    role = next((r for r in ROLES if f.names[r] == label), None)
    return f.points.get(role) if role is not None else None


def _fresh(letter: str, used: set) -> str:
    """The book's letter, or the first of letter′, letter₁ ... the scene does not use."""
    for cand in (letter, letter + "1", letter + "2", letter + "3", letter + "4"):
        if cand not in used:
            return cand
    n = 5
    while f"{letter}{n}" in used:
        n += 1
    return f"{letter}{n}"


def report_lines(f: Figure, units_mm: bool = True) -> list[str]:
    """The construction in words with its numbers, and the comparison with the polygons."""
    nm, p = f.names, f.points
    O, A, B, M, Q, N = (nm[k] for k in ("O", "A", "B", "M", "Q", "N"))
    w = abs(f.omega)

    def d(a, b):
        return math.dist(p[a], p[b]) * 1000

    def sense(x):
        return "CCW" if x > 0 else ("CW" if x < 0 else "")
    kind = "in-line" if f.inline else f"offset {abs(f.offset) * 1000:.6g} mm"
    lines = [f"{TITLES[f.method]} ({kind} slider-crank; crank {f.crank} at ω = {w:.6g} rad/s "
             f"uniform, rod {f.rod}):",
             f"  velocity: the line through {O} ⟂ the stroke meets {A}{B} produced at {M}; "
             f"triangle {O}{A}{M} is the velocity polygon turned 90° at ω per mm",
             f"    {O}{M} = {d('O', 'M'):.6g} mm → v_{B} = ω·{O}{M} = {abs(f.v_piston):.6g} m/s "
             f"(polygon {abs(f.polygon['v_piston']):.6g} m/s)",
             f"    {A}{M} = {d('A', 'M'):.6g} mm → ω_{f.rod} = ω·{A}{M}/{A}{B} = "
             f"{abs(f.omega_rod):.6g} rad/s {sense(f.omega_rod)} (polygon "
             f"{abs(f.polygon['omega_rod']):.6g} rad/s)"]
    if f.method == "klein":
        K, L_ = nm["K"], nm["L"]
        lines.append(f"  acceleration: the Klein circle (centre {A}, radius {A}{M}) and the "
                     f"circle on {A}{B} as diameter cut at {K}, {L_}; {K}{L_} meets {A}{B} at "
                     f"{Q} and the line through {O} ∥ the stroke at {N}; {O}{A}{Q}{N} is the "
                     f"acceleration polygon turned 180° at ω² per mm")
    elif f.method == "bennett":
        K, L_, A1, B1, L1 = (nm[k] for k in ("K", "L", "A1", "B1", "L1"))
        lines.append(f"  acceleration: with the crank at right angles to the stroke ({O}{A1}, rod "
                     f"{A1}{B1}) the perpendicular from {O} meets {A1}{B1} at {L1} "
                     f"({A1}{L1} = {d('A1', 'L1'):.6g} mm = {O}{A}²/{A}{B}); {L_} on {A}{B} "
                     f"with {A}{L_} = {A1}{L1}; the perpendicular to {A}{B} at {L_} meets the "
                     f"stroke at {K}; the line through {K} ⟂ the stroke meets {A}{B} at {Q}; "
                     f"the perpendicular to {A}{B} at {Q} meets the stroke at {N}; "
                     f"{O}{A}{Q}{N} is the acceleration polygon turned 180° at ω² per mm")
    else:
        K = nm["K"]
        lines.append(f"  acceleration: the line through {M} ∥ the stroke meets {O}{A} at {K}; "
                     f"the line through {K} ⟂ the stroke meets {A}{B} at {Q}; the "
                     f"perpendicular to {A}{B} at {Q} meets the stroke at {N}; {O}{A}{Q}{N} is "
                     f"the acceleration polygon turned 180° at ω² per mm")
    lines += [f"    {A}{Q} = {d('A', 'Q'):.6g} mm (= {A}{M}²/{A}{B}) → (a_{B})ⁿ_{A} = "
              f"ω²·{A}{Q} = {w * w * d('A', 'Q') / 1000:.6g} m/s²",
              f"    {N}{O} = {d('N', 'O'):.6g} mm → a_{B} = ω²·{N}{O} = {abs(f.a_piston):.6g} "
              f"m/s² (polygon {abs(f.polygon['a_piston']):.6g} m/s²)",
              f"    {Q}{N} = {d('Q', 'N'):.6g} mm → α_{f.rod} = ω²·{Q}{N}/{A}{B} = "
              f"{abs(f.alpha_rod):.6g} rad/s² {sense(f.alpha_rod)} (polygon "
              f"{abs(f.polygon['alpha_rod']):.6g} rad/s²)",
              f"  largest relative difference from the polygons: {f.difference:.1e}"]
    return lines


def to_dict(f: Figure) -> dict:
    """The figure for JSON (SI; signed along the stroke / CCW positive)."""
    return {"method": f.method, "inline": f.inline, "offset_m": f.offset,
            "labels": {k: v for k, v in f.names.items() if k != "inline"},
            "points": {f.names[k]: list(v) for k, v in f.points.items()},
            "stroke_direction": list(f.stroke), "omega": f.omega,
            "piston_velocity": f.v_piston, "piston_acceleration": f.a_piston,
            "rod_omega": f.omega_rod, "rod_alpha": f.alpha_rod,
            "polygon": dict(f.polygon), "intersection_angles_deg": dict(f.angles),
            "max_relative_difference": f.difference}


__all__ = ["Figure", "figure", "asked", "figure_point", "engine", "report_lines", "to_dict", "METHODS", "TITLES"]
