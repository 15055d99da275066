"""Named result quantities, in textbook notation, read off a :class:`Solution`.

    v(C)        |v_C|, the length oc of the velocity polygon        (m/s)
    v(C,B)      |(v_C)_B| = |bc|                                    (m/s)
    a(C), a(C,B)  the same on the acceleration polygon               (m/s²)
    an(C,B)     centripetal part of (a_C)_B, ω²·BC                  (m/s²)
    at(C,B)     tangential part of (a_C)_B, |α|·BC                  (m/s²)
    omega(BC), alpha(BC)   signed, CCW positive                     (rad/s, rad/s²)
    vs(P), as(P)  sliding velocity / acceleration of P along its guide or slot, signed
    cor(P)      magnitude of the Coriolis acceleration of pin P     (m/s²)
    dist(B,A)   distance between two points at this instant         (m); either may be an
                instantaneous centre, I13 (:func:`instant_centre`): dist(I13,C), or a
                point of Klein's figure of a slider-crank (M, K, L, Q, N): dist(O,N)
    angle(P,Q,R)  angle at Q between QP and QR, 0..180°               (rad in SI)
    arm(O,P,C)  perpendicular distance from O to the line PC         (m)
    x(C), y(C)  coordinates                                         (m)
    dir_v(C), dir_a(C)   direction of v_C / a_C, degrees CCW from +x in [0, 360)
    X / Y       the ratio of two quantities of one kind (a velocity ratio v(C) / v(B), a
                mechanical advantage): a pure number, signed as their quotient
    omega(W), alpha(W)   a rolling wheel's ([rolling.W]) ω and α, signed, CCW positive;
                every point function also of a wheel's named points ([rolling.W] rim) and
                of a cylinder's centre between two plates (not points of the polygons:
                v_P = v_W + ω k × WP, a_P = a_W + α k × WP − ω² WP, contacts.wheel_point)

Used by the answers table, the tests and ``polygons check``.
"""
from __future__ import annotations

import math
import re

import numpy as np

from .errors import PolygonsError, SceneError, UnknownLabelError, show, suggest
from .evaluate import PointResult, Solution
# FUNCTIONS is read by polygons.forces as quantities.FUNCTIONS
from .scene import QUANTITY_FUNCTIONS as FUNCTIONS, parse_quantity_expr as _parse  # noqa: F401

def dimension_of_quantity(expr: str) -> str:
    fn, args = _parse(expr)
    if fn == "ratio":
        dims = [dimension_of_quantity(x) for x in args]
        if dims[0] != dims[1]:
            raise SceneError(f"{expr!r}: a ratio of {article_of(dims[0])} to "
                             f"{article_of(dims[1])} has a unit; ask for a ratio of two "
                             f"quantities of one kind (v(C) / v(B), omega(CD) / omega(AB))")
        return "fraction"
    return {"v": "velocity", "a": "acceleration", "an": "acceleration", "at": "acceleration",
            "omega": "angular_velocity", "alpha": "angular_acceleration", "cor": "acceleration",
            "dist": "length", "x": "length", "y": "length", "dir_v": "angle",
            "dir_a": "angle", "angle": "angle", "arm": "length"}.get(fn, "velocity" if fn == "vs" else "acceleration")


def article_of(dimension: str) -> str:
    word = dimension.replace("_", " ")
    return ("an " if word[0] in "aeiou" else "a ") + word


def drawn_on_polygon(sol: Solution, expr: str, value: float) -> tuple[str, float]:
    """(diagram, length on that polygon in SI) of the line ``expr`` is read from: |ω|·length
    (|α|·length) for a link's — a rolling wheel's: its radius — and |value| otherwise.  A
    ratio X / Y read off two lines x, y: the length whose reading error is the ratio's,
    1 / (1/x + 1/y) (relative errors add; the numerator's diagram)."""
    fn, args = _parse(expr)
    if fn == "ratio":
        (dx, lx), (_, ly) = (drawn_on_polygon(sol, x, quantity(sol, x)) for x in args)
        return dx, (1.0 / (1.0 / lx + 1.0 / ly) if lx > 0 and ly > 0 else 0.0)
    if fn in ("omega", "alpha"):
        lr = sol.links.get(args[0])
        if lr is None:                      # a rolling wheel's (polygons.contacts, imported here)
            from .contacts import wheel_of
            length = wheel_of(sol.scene, args[0]).radius
        else:
            length = lr.length
        return ("velocity" if fn == "omega" else "acceleration"), abs(value) * length
    return ("velocity" if fn in ("v", "vs") else "acceleration"), abs(value)


def _known(scene) -> set[str]:
    """Every point label a quantity may name: the space diagram's, and rolling wheels'
    centres and rim points."""
    out = set(scene.labels)
    for e in getattr(scene, "equivalents", ()):
        if e.kind == "rolling":
            out |= {e.at} | {r[0] for r in e.rim}
    return out


def labels_needed(scene, expr: str) -> tuple[str, ...]:
    """The point labels the plan must place to read ``expr``: its points, a link's ends, and
    for a rolling wheel (its ω, α, centre or a rim point) the centre and the plates it rolls
    on and under (the no-slip conditions read both: :func:`contacts.rolling`)."""
    fn, args = _parse(expr)
    out: list[str] = []
    for name in args:
        wheel = next((e for e in getattr(scene, "equivalents", ()) if e.kind == "rolling" and
                      (name == e.at or any(r[0] == name for r in e.rim))), None)
        if wheel is not None:
            out += [x for x in (wheel.at, wheel.on, wheel.opposite) if x is not None]
            continue
        if fn in ("omega", "alpha"):
            try:
                out += list(scene.model.body(name).labels)
            except (KeyError, ValueError, PolygonsError):
                pass                 # not a link: refused by name when the answer is read
            continue
        out.append(name)
    return tuple(dict.fromkeys(out))


#: the polygon a quantity of each dimension is read from (a quantity this scene's ``solve``
#: leaves unsolved is refused by its kind, whatever its name)
_POLYGON_OF = {"velocity": "velocity", "angular_velocity": "velocity",
               "acceleration": "acceleration", "angular_acceleration": "acceleration"}


#: an instantaneous centre's label, I13 (links numbered as `polygons centres` numbers them)
_CENTRE = re.compile(r"^I(\d)(\d)$")


def instant_centre(sol: Solution, label: str) -> tuple[float, float]:
    """The position of the instantaneous centre ``label`` (``I13``: of links 1 and 3, numbered
    as :func:`polygons.centres.instant_centres` numbers them — the frame 1, the driver 2 ...,
    or as ``[centres] numbers`` says), a point of the space diagram for ``dist``, ``arm``,
    ``angle``, ``x`` and ``y`` (its velocity is not a point's: it is a pair of bodies')."""
    from .centres import find_centres
    from .memo import memo_of
    memo = memo_of(sol)
    found = memo.get("centres")
    if found is None:
        bodies, centres = find_centres(sol)
        found = memo["centres"] = {c.label: c for c in centres}
        memo["centre_count"] = len(bodies)
    i, j = sorted(map(int, _CENTRE.match(label).groups()))
    c = found.get(f"I{i}{j}")
    if c is None:
        raise UnknownLabelError(f"no instant centre {label}: the links are numbered 1 … "
                                f"{memo['centre_count']} (polygons centres lists them)",
                                file=sol.scene.file)
    if c.point is None:
        raise SceneError(f"{label} is at infinity (links {c.names[0]} and {c.names[1]} "
                         f"translate relative to each other): it has no distance",
                         file=sol.scene.file)
    return (float(c.point[0]), float(c.point[1]))


def quantity(sol: Solution, expr: str) -> float:
    """The SI value of ``expr`` (see module docstring) in solution ``sol``; a quantity of a
    polygon the scene does not solve (``solve = ["velocity"]`` and any acceleration answer:
    ``a(C)``, ``as(P)``, ``at(C,B)``, ``alpha(BC)``...) refused in one line by its kind."""
    value = _quantity(sol, expr)
    if value is None:
        _unsolved(sol, expr)
    return value


def _unsolved(sol: Solution, expr: str):
    need = _POLYGON_OF.get(dimension_of_quantity(expr), "acceleration")
    raise SceneError(f"{expr!r} needs the {need} polygon, which this scene does not solve "
                     f"(solve = {list(sol.scene.solve)})", file=sol.scene.file)


def _quantity(sol: Solution, expr: str) -> float | None:
    fn, args = _parse(expr)
    if fn == "ratio":
        dimension_of_quantity(expr)             # of one kind, or refused
        num, den = quantity(sol, args[0]), quantity(sol, args[1])
        if not abs(den) > 1e-12 * abs(num):
            raise SceneError(f"{args[1]} is zero at this instant: the ratio {expr!r} is not "
                             f"defined", file=sol.scene.file)
        return num / den
    p, q, rest = args[0], (args[1] if len(args) > 1 else None), args[2:]
    scene = sol.scene

    def point(label):
        if label not in sol.points:         # a wheel's centre between plates, a rim point
            for e in getattr(scene, "equivalents", ()):
                from .contacts import wheel_point
                got = wheel_point(sol, e, label) if e.kind == "rolling" else None
                if got is not None:
                    return PointResult(*got)
        targets = getattr(getattr(sol, "plan", None), "targets", None)
        if (label not in sol.points and targets is not None and
                tuple(targets) != tuple(scene.labels) and label in _known(scene)):
            raise SceneError(f"{show(expr)} reads {show(label)}, which this solution does not "
                             f"place (it was solved for {', '.join(targets)} only): solve "
                             f"{show(label)} too", file=scene.file)


        if label not in sol.points and _CENTRE.match(label):   # an instant centre, I13
            return PointResult(instant_centre(sol, label), None, None)
        if label not in sol.points:         # a point of Klein's figure: Klein's ON
            from .classic.klein import figure_point
            got = figure_point(sol, label)
            if got is not None:
                return PointResult(got, None, None)
        if label not in sol.points:
            raise UnknownLabelError(f"unknown point {show(label)} in {show(expr)}: "
                                    f"{suggest(label, sol.points)}", file=scene.file)
        return sol.points[label]

    def vec(label, kind):
        value = getattr(point(label), kind)
        if value is None and label not in sol.points:
            raise SceneError(f"{label} in {expr!r} is a point of a construction (an instant "
                             f"centre, Klein's figure), not of the mechanism: it has no "
                             f"{kind}; ask for its place (dist, x, y)", file=scene.file)
        if value is None:
            _unsolved(sol, expr)
        return np.array(value)

    def link(name):
        if name not in sol.links:
            from .contacts import wheel_of  # (imported only here: a quicker start)
            if wheel_of(scene, name) is not None:
                return None
            raise UnknownLabelError(f"unknown link {name!r} in {expr!r}: "
                                    f"{suggest(name, sol.links)}", file=scene.file)
        return sol.links[name]

    def link_of(x, y):
        for name, lr in sol.links.items():
            if {x, y} <= set(scene.model.body(name).labels):
                return lr
        raise SceneError(f"{x} and {y} are not on one link, so {expr!r} has no "
                         f"centripetal/tangential split", file=scene.file)

    def wheel_value(label, what):
        """ω / α of the wheel (ω = (v₁ − v_W)/r; between plates (v₁ − v₂)/2r:
        :func:`contacts.rolling`)."""
        from .contacts import rolling, wheel_of
        h = rolling(sol, wheel_of(scene, label))
        if h is None or what not in h:
            need = "velocity" if what == "omega" else "acceleration"
            raise SceneError(f"{expr!r} needs the {need} polygon, which this scene does not solve "
                             f"(solve = {list(scene.solve)})", file=scene.file)
        return float(h[what])

    if fn in ("v", "a"):
        kind = "velocity" if fn == "v" else "acceleration"
        value = vec(p, kind) - (vec(q, kind) if q else 0.0)
        return float(np.hypot(*value))
    if fn in ("an", "at"):
        lr = link_of(p, q)
        r = float(np.hypot(*(np.array(point(p).position) - np.array(point(q).position))))
        rate = lr.omega if fn == "an" else lr.alpha
        if rate is None:
            _unsolved(sol, expr)
        return rate * rate * r if fn == "an" else abs(rate) * r
    if fn in ("omega", "alpha"):
        lr = link(p)
        return getattr(lr, fn) if lr is not None else wheel_value(p, fn)
    if fn in ("vs", "as", "cor"):
        if q is not None:      # vs(P,P2): P sliding relative to the lever's point P2 under it
            pair = scene.model.under.get(q)
            if pair is None or pair.at != p:
                raise UnknownLabelError(f"{q!r} in {expr!r} is not a lever's point under "
                                        f"{p}", file=scene.file)
            p = p if p in sol.slides and pair.key.startswith("slots.") else \
                f"{p} in {pair.carrier}"
        if p not in sol.slides:
            raise UnknownLabelError(f"{p!r} in {expr!r} is not a slider or a pin in a slot: "
                                    f"{suggest(p, sol.slides)}", file=scene.file)
        sr = sol.slides[p]
        if fn == "vs":
            return sr.velocity
        if fn == "as":
            return sr.acceleration
        if sr.coriolis is None and sr.acceleration is None:
            _unsolved(sol, expr)
        if sr.coriolis is None:
            raise SceneError(f"{p} slides on a fixed guide: it has no Coriolis component",
                             file=scene.file)
        return float(np.hypot(*sr.coriolis))
    if fn == "dist":
        return float(np.hypot(*(np.array(point(p).position) - np.array(point(q).position))))
    if fn in ("angle", "arm"):
        P, Q, R = (np.array(point(lab).position) for lab in (p, q, rest[0]))
        if fn == "angle":
            u, w = P - Q, R - Q
            return math.atan2(abs(u[0] * w[1] - u[1] * w[0]), float(u @ w))
        d = R - Q
        return abs(float(d[0] * (P - Q)[1] - d[1] * (P - Q)[0])) / float(np.hypot(*d))
    if fn in ("x", "y"):
        return point(p).position[0 if fn == "x" else 1]
    kind = "velocity" if fn == "dir_v" else "acceleration"
    v = vec(p, kind)
    return math.radians(math.degrees(math.atan2(v[1], v[0])) % 360.0)
