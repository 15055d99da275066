"""Checks across each kind's whole domain (issue 28, item 6): random mechanisms of every kind
at random poses and at the poses where a construction is hardest — within 1e-6° of where two
closures meet (a toggle, the end of the reachable range), and at and beside a local minimum of
the construction's smallest angle (a parallel pair) — each pose checked by routes that do not
share the construction:

* ``solve`` at the pose equals the sweep's row there (the staged and compiled interpreters,
  both started from the same statement);
* the closure the sweep follows is continuous in the input and every velocity and acceleration
  ``solve`` prints equals the finite difference of the sweep's positions (a 4th-order central
  stencil at steps h and 2h, their difference the difference's own error estimate);
* for a higher pair, every output :func:`polygons.contacts.higher` names, against finite
  differences of the geometry of the positions (the contact point, the bar's point there, the
  angle of the follower about the centre of curvature relative to the cam);
* wherever a check cannot hold, the tool warned (``Solution.warnings``) or refused (a
  ``PolygonsError``): a check that fails at a pose the tool neither warned about nor refused
  is a **silent disagreement**, the one outcome that must never occur.

Used by tests/test_domain.py (a few mechanisms per kind: seconds) and benchmarks/domain.py
(≥ 10⁵ poses, its counts in the README).  Every mechanism is made from a seed, so a finding is
replayed by (kind, seed, pose).
"""
from __future__ import annotations

import math
import random
import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from polygons.contacts import higher
from polygons.errors import PolygonsError
from polygons.evaluate import solve
from polygons.records import Crank
from polygons.scene import parse_scene
from polygons.sweep import sweep

CASES = Path(__file__).resolve().parents[1] / "cases"
DEG = math.pi / 180
#: the poses beside a meeting of closures / a parallel pair: this far from it (the issue's 1e-6°)
NEAR = 1e-6 * DEG
#: relative tolerance of an agreement (the finite differences' own error estimate is added)
TOL = 1e-6
#: a finite difference whose two step sizes disagree by more than this (relative) cannot judge
UNSURE = 1e-3
#: solve against the sweep's row (the interpreters are held equal to 1e-12; margin for rounding
#: at ill-conditioned poses)
SAME = 1e-9

STENCIL = np.array([-4.0, -2.0, -1.0, 0.0, 1.0, 2.0, 4.0])


# ----------------------------------------------------------------- random mechanisms, per kind
def _m(x):
    return f"{float(x)!r} m"


def _crank(link, rng, theta=0.0):
    w = rng.choice((-1, 1)) * rng.uniform(0.5, 50.0)
    al = rng.uniform(-200.0, 200.0)
    return {"crank": link, "angle": f"{theta!r} rad", "omega": f"{abs(w)!r} rad/s",
            "sense": "CCW" if w > 0 else "CW", "alpha": f"{abs(al)!r} rad/s^2",
            "alpha_sense": "CCW" if al > 0 else "CW"}


def _four_bar(rng):
    d, a, b, c = rng.uniform(0.2, 1.0), rng.uniform(0.05, 0.6), rng.uniform(0.1, 1.0), \
        rng.uniform(0.1, 1.0)
    return {"ground": {"A": ["0 m", "0 m"], "D": [_m(d), "0 m"]},
            "links": {"AB": _m(a), "BC": _m(b), "CD": _m(c)},
            "driver": _crank("AB", rng),
            "assembly": {"C": f"C {rng.choice(('above', 'below'))} AD"}}, ("B", "C")


def rrr(rng):
    return _four_bar(rng)


def image(rng):
    d, pts = _four_bar(rng)
    d["points"] = {"P": {"on": "BC", "along": _m(rng.uniform(-0.5, 1.0)),
                         "left": _m(rng.uniform(-0.5, 0.5))}}
    return d, pts + ("P",)


def rrp(rng):
    r = rng.uniform(0.02, 0.3)
    L = r * rng.uniform(1.1, 5.0)
    phi = rng.uniform(0, 2 * math.pi)
    off = rng.uniform(-0.9, 0.9) * L
    e, n = (math.cos(phi), math.sin(phi)), (-math.sin(phi), math.cos(phi))
    far = rng.choice((1, -1)) * 10 * L
    return {"ground": {"O": ["0 m", "0 m"]},
            "links": {"OA": _m(r), "AB": _m(L)},
            "sliders": {"B": {"through": [_m(off * n[0]), _m(off * n[1])],
                              "direction": f"{phi!r} rad"}},
            "driver": _crank("OA", rng),
            "assembly": {"B": {"near": [_m(off * n[0] + far * e[0]),
                                        _m(off * n[1] + far * e[1])]}}}, ("A", "B")


def rpr(rng):
    r, dist = rng.uniform(0.02, 0.3), rng.uniform(0.05, 0.6)
    return {"ground": {"O": ["0 m", "0 m"], "B": ["0 m", _m(-dist)]},
            "links": {"OA": _m(r), "BC": _m((dist + r) * rng.uniform(1.2, 2.0))},
            "driver": _crank("OA", rng),
            "slots": {"A": {"lever": "BC", "coincident": "A1"}}}, ("A", "C")


def rpp(rng):
    r, g = rng.uniform(0.02, 0.3), rng.uniform(0, math.pi)
    slot = g + rng.uniform(0.2, math.pi - 0.2)
    return {"ground": {"O": ["0 m", "0 m"]},
            "links": {"OP": _m(r)},
            "driver": _crank("OP", rng),
            "sliders": {"Y": {"through": [_m(rng.uniform(-1, 1)), _m(rng.uniform(-1, 1))],
                              "direction": f"{g!r} rad", "pin": "P",
                              "slot": f"{slot!r} rad"}}}, ("P", "Y")


def slider_drive(rng):
    """The slider-crank driven from its piston: the input is the slider's place s."""
    r = rng.uniform(0.02, 0.3)
    L = r * rng.uniform(1.2, 5.0)
    v = rng.choice((-1, 1)) * rng.uniform(0.1, 5.0)
    return {"ground": {"O": ["0 m", "0 m"]},
            "links": {"OA": _m(r), "AB": _m(L)},
            "sliders": {"B": {"through": ["0 m", _m(rng.uniform(-0.8, 0.8) * r)],
                              "direction": "0 deg"}},
            "driver": {"slider": "B", "position": _m(L), "velocity": f"{v!r} m/s",
                       "acceleration": f"{rng.uniform(-20, 20)!r} m/s^2"},
            "assembly": {"A": f"A {rng.choice(('above', 'below'))} O"}}, ("A", "B")


def bearing(rng):
    """A bar AQ whose end A is carried by a crank OA, bearing on a fixed circle (K, R)."""
    r, R = rng.uniform(0.02, 0.1), rng.uniform(0.03, 0.15)
    d = r + R + rng.uniform(0.02, 0.4)
    phi = rng.uniform(0, 2 * math.pi)
    K = (d * math.cos(phi), d * math.sin(phi))
    return {"ground": {"O": ["0 m", "0 m"], "K": [_m(K[0]), _m(K[1])]},
            "links": {"OA": _m(r), "AQ": _m((d + r) * rng.uniform(1.5, 3.0))},
            "driver": _crank("OA", rng),
            "bearing": {"K": {"bar": "AQ", "radius": _m(R),
                              "side": rng.choice(("left", "right"))}}}, ("A", "Q")


def curved_slot(rng):
    """A pin P on the coupler AP of a crank OA runs in a circular slot about K: cut in the
    frame, or (half the time) in a second crank's link DE (K a point of it), both turning."""
    d, pts = _four_bar(rng)
    ad = float(d["ground"]["D"][0].split()[0])
    if rng.random() < 0.5:
        K = [_m(rng.uniform(0, ad)), _m(rng.uniform(-0.3, 0.3))]
        d["ground"]["K"] = K
    else:
        d["points"] = {"K": {"on": "CD", "along": _m(rng.uniform(0.2, 1.0) * ad),
                             "left": _m(rng.uniform(-0.2, 0.2))}}
    d["links"]["BP"] = _m(rng.uniform(0.1, 0.8))
    d["curved_slots"] = {"P": {"centre": "K", "radius": _m(rng.uniform(0.1, 0.6))}}
    d["assembly"]["P"] = f"P {rng.choice(('above', 'below'))} K"
    return d, pts + ("P",)


def cam(rng):
    """A roller follower R on a guide, on an eccentric circular cam (centre C, the end of the
    crank OC): exact for every pose, the arc being the whole profile."""
    e, rho, roll = rng.uniform(0.005, 0.04), rng.uniform(0.02, 0.08), rng.uniform(0.0, 0.02)
    phi = rng.uniform(0, 2 * math.pi)
    off = rng.uniform(-0.5, 0.5) * rho
    n = (-math.sin(phi), math.cos(phi))
    return {"ground": {"O": ["0 m", "0 m"]},
            "links": {"OC": _m(e)},
            "driver": _crank("OC", rng),
            "sliders": {"R": {"through": [_m(off * n[0]), _m(off * n[1])],
                              "direction": f"{phi!r} rad"}},
            "cams": {"R": {"centre": "C", "radius": _m(rho), "roller": _m(roll)}},
            "assembly": {"R": {"near": [_m(math.cos(phi)), _m(math.sin(phi))]}}}, ("C", "R")


def triad(rng):
    """A random class-III group driven by a crank: built assembled (the plate B, C, X placed
    first, the links' far ends D, E fixed where they land), X chosen near where it was built."""
    def at(p, length, ang):
        return (p[0] + length * math.cos(ang), p[1] + length * math.sin(ang))
    th = rng.uniform(0, 2 * math.pi)
    r = rng.uniform(0.03, 0.15)
    A = at((0.0, 0.0), r, th)
    a, L, c, e = (rng.uniform(0.1, 0.5) for _ in range(4))
    B = at(A, a, rng.uniform(0, 2 * math.pi))
    psi = rng.uniform(0, 2 * math.pi)
    C = at(B, L, psi)
    xi, eta = rng.uniform(-0.2, 1.2) * L, rng.uniform(0.2, 0.8) * L * rng.choice((1, -1))
    X = (B[0] + xi * math.cos(psi) - eta * math.sin(psi),
         B[1] + xi * math.sin(psi) + eta * math.cos(psi))
    D, E = at(C, c, rng.uniform(0, 2 * math.pi)), at(X, e, rng.uniform(0, 2 * math.pi))
    return {"ground": {"O": ["0 m", "0 m"], "D": [_m(D[0]), _m(D[1])],
                       "E": [_m(E[0]), _m(E[1])]},
            "links": {"OA": _m(r), "AB": _m(a), "BC": _m(L), "CD": _m(c), "XE": _m(e)},
            "points": {"X": {"on": "BC", "along": _m(xi), "left": _m(eta)}},
            "driver": _crank("OA", rng, th),
            "assembly": {"X": {"near": [_m(X[0]), _m(X[1])]}}}, ("A", "B", "C", "X")


def triad_slider(rng):
    """A random class-III group with a block on a guide at a corner (two links and a block),
    driven by a crank: built assembled (the plate B, C, X placed first, D fixed where CD
    lands, the guide through X at a random angle), X chosen near where it was built; a third
    of them with the plate a triangle of three links and the block at a random corner."""
    def at(p, length, ang):
        return (p[0] + length * math.cos(ang), p[1] + length * math.sin(ang))
    th = rng.uniform(0, 2 * math.pi)
    r = rng.uniform(0.03, 0.15)
    A = at((0.0, 0.0), r, th)
    a, L, c = (rng.uniform(0.1, 0.5) for _ in range(3))
    B = at(A, a, rng.uniform(0, 2 * math.pi))
    psi = rng.uniform(0, 2 * math.pi)
    C = at(B, L, psi)
    xi, eta = rng.uniform(-0.2, 1.2) * L, rng.uniform(0.2, 0.8) * L * rng.choice((1, -1))
    X = (B[0] + xi * math.cos(psi) - eta * math.sin(psi),
         B[1] + xi * math.sin(psi) + eta * math.cos(psi))
    D = at(C, c, rng.uniform(0, 2 * math.pi))
    g = rng.uniform(0, math.pi)
    data = {"ground": {"O": ["0 m", "0 m"], "D": [_m(D[0]), _m(D[1])]},
            "links": {"OA": _m(r), "AB": _m(a), "BC": _m(L), "CD": _m(c)},
            "driver": _crank("OA", rng, th)}
    if rng.random() < 2 / 3:
        data["points"] = {"X": {"on": "BC", "along": _m(xi), "left": _m(eta)}}
        slid, P = "X", X
    else:       # a triangle plate; the block at X, or at B with AB moved to X
        data["links"].update({"BX": _m(math.dist(B, X)), "CX": _m(math.dist(C, X))})
        slid, P = "X", X
        if rng.random() < 0.5:
            A2 = at(X, a, rng.uniform(0, 2 * math.pi))
            r2 = math.hypot(*A2)
            data["links"]["OA"] = _m(r2)
            data["driver"] = _crank("OA", rng, math.atan2(A2[1], A2[0]))
            data["links"].pop("AB")
            data["links"]["AX"] = _m(a)
            slid, P = "B", B
    data["sliders"] = {slid: {"through": [_m(P[0]), _m(P[1])], "direction": f"{g!r} rad"}}
    data["assembly"] = {slid: {"near": [_m(P[0]), _m(P[1])]}}
    return data, ("A", "B", "C", "X")


def _from_case(name, labels, drop=()):
    """A shipped case with every stated length (in [links]) scaled by 0.9 … 1.1."""
    text = (CASES / f"{name}.toml").read_text()

    def make(rng):
        data = tomllib.loads(text)
        for k in ("answers", "source", "title", "drawing", "sweep", "handout", *drop):
            data.pop(k, None)
        links = data.get("links", {})
        for k, v in list(links.items()):
            num = re.match(r"\s*([-+0-9.eE]+)\s*(.*)$", v)
            links[k] = f"{float(num.group(1)) * rng.uniform(0.9, 1.1)!r} {num.group(2)}"
        return data, labels
    make.__name__ = name
    return make


#: every kind: (name, maker(rng) → (scene data, labels checked)).  The dyads of
#: polygons/dyads/ (crank and slider_drive are the drivers; pinned is RRR's and RRP's shared
#: construction), the triad, the higher pairs and the wheel driver.
KINDS = {
    "rrr": rrr, "rrp": rrp, "rpr": rpr, "rpp": rpp, "image": image,
    "slider_drive": slider_drive,
    "guided": _from_case("new-oscillating-cylinder", ("P", "Q")),
    "guided-moving-lever": _from_case("new-block-on-moving-link", ("C", "E", "Q")),
    "crossing": _from_case("new-crossing-slots", ("A", "B", "P")),
    "triad": _from_case("triad-ternary-coupler", ("B", "C", "X")),
    "triad-plate": _from_case("triad-plate-point", ("B", "C", "X")),
    "triad-random": triad,
    "triad-slider": _from_case("triad-slider-corner", ("B", "C", "X")),
    "triad-slider-random": triad_slider,
    "bearing": bearing, "curved_slot": curved_slot, "cam": cam,
    "cam-flat": _from_case("cam-flat-follower", ("C", "F")),
    "cam-oscillating-flat": _from_case("cam-oscillating-flat-follower", ("C", "F")),
    "rolling": _from_case("rolling-wheel-driven", ()),
    "wheel_driver": _from_case("rolling-wheel-rim-pin", ("W", "B", "C")),
}


# ----------------------------------------------------------------- one mechanism, its poses
@dataclass
class Mechanism:
    kind: str
    seed: int
    scene: object
    labels: tuple
    crank: bool
    rate: float                 # the input's rate (ω or ṡ)
    rate2: float                # its rate of change (α or s̈)
    size: float

    def at(self, x):
        drv = self.scene.driver
        drv = replace(drv, angle=float(x)) if self.crank else replace(drv, position=float(x))
        return replace(self.scene, driver=drv)

    def x0(self) -> float:
        drv = self.scene.driver
        return drv.angle if self.crank else drv.position


def make(kind: str, seed: int) -> Mechanism | None:
    """The ``seed``-th random mechanism of ``kind`` (None when it does not load at its pose:
    a random mechanism that cannot be stated)."""
    rng = random.Random(f"{kind}/{seed}")
    data, labels = KINDS[kind](rng)
    try:
        scene = parse_scene(data, file=f"{kind}-{seed}.toml")
    except PolygonsError:
        return None
    drv = scene.driver
    crank = isinstance(drv, Crank)
    if not crank and drv.rod_rate is not None:
        return None
    pts = [p for p in scene.ground.values()]
    size = max([math.hypot(*p) for p in pts] + [0.0]) + sum(
        getattr(l, "length", 0.0) or 0.0 for l in getattr(scene, "links", {}).values())
    return Mechanism(kind, seed, scene, labels, crank,
                     drv.omega if crank else drv.velocity,
                     drv.alpha if crank else drv.acceleration, max(size, 1e-3))


def _solves(mech, x):
    try:
        sol = solve(mech.at(x))
        return sol if sol.points else None
    except PolygonsError:
        return None


def _bisect(mech, good, bad, iters=80):
    """The end of what solve answers between ``good`` and ``bad``, to 1e-13 (rad or ×size)."""
    unit = 1.0 if mech.crank else mech.size
    for _ in range(iters):
        mid = 0.5 * (good + bad)
        if mid in (good, bad) or abs(good - bad) < 1e-13 * unit:
            break
        if _solves(mech, mid) is not None:
            good = mid
        else:
            bad = mid
    return good, bad


def _angle(mech, x):
    sol = _solves(mech, x)
    a = None if sol is None else sol.min_intersection_angle_deg
    return math.inf if a is None else a


def _golden(mech, lo, hi, iters=44):
    """The local minimum of the smallest construction angle in [lo, hi] (golden section, one
    solve per step: the interval shrinks to 0.618⁴⁴ ≈ 6e-10 of itself)."""
    g = (math.sqrt(5) - 1) / 2
    m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
    f1, f2 = _angle(mech, m1), _angle(mech, m2)
    for _ in range(iters):
        if f1 < f2:
            hi, m2, f2 = m2, m1, f1
            m1 = hi - g * (hi - lo)
            f1 = _angle(mech, m1)
        else:
            lo, m1, f1 = m1, m2, f2
            m2 = lo + g * (hi - lo)
            f2 = _angle(mech, m2)
    return 0.5 * (lo + hi)


def poses(mech: Mechanism, rng: random.Random, n_random: int, grid: int = 48):
    """(pose, distance to the nearest meeting of closures, why) to check: ``n_random`` random
    poses where it assembles, each end of the reachable range ± 1e-6° (and 1e-3°), each local
    minimum of the smallest construction angle, at it and 1e-6° either side."""
    if mech.crank:
        xs = [2 * math.pi * i / grid for i in range(grid)]
        span = 2 * math.pi
        near = NEAR
    else:
        x0 = mech.x0()
        xs = [x0 + mech.size * (2 * i / grid - 1) for i in range(grid + 1)]
        span = 2 * mech.size
        near = NEAR * mech.size
    ok = [_solves(mech, x) is not None for x in xs]
    ends = []
    pairs = list(zip(range(len(xs)), range(1, len(xs))))
    if mech.crank:
        pairs.append((len(xs) - 1, 0))
    for i, j in pairs:
        if ok[i] != ok[j]:
            a, b = xs[i], xs[j] + (span if mech.crank and j == 0 else 0.0)
            g, bad = _bisect(mech, a, b) if ok[i] else _bisect(mech, b, a)
            ends.append((g, math.copysign(1.0, g - bad)))
    out = []
    good = [x for x, k in zip(xs, ok) if k]
    if not good:
        return out
    dist = lambda x: min([abs(x - e) for e, _ in ends] + [span])   # noqa: E731
    for _ in range(n_random):
        x = rng.choice(good) + rng.uniform(-0.5, 0.5) * span / grid
        out.append((x, dist(x), "random"))
    for e, inward in ends:
        for d in (near, 1e3 * near):
            out.append((e + inward * d, d, "beside an end of what solve answers"))
    angles = [_angle(mech, x) if k else math.inf for x, k in zip(xs, ok)]
    for i in range(1, len(xs) - 1):
        if ok[i] and angles[i] < angles[i - 1] and angles[i] < angles[i + 1] and angles[i] < 20:
            x = _golden(mech, xs[i - 1], xs[i + 1])
            for d in (0.0, near, -near):
                out.append((x + d, max(dist(x + d), near), "at a parallel pair"))
    return out


# ----------------------------------------------------------------- the checks at one pose
@dataclass
class Outcome:
    kind: str
    seed: int
    pose: float
    why: str
    verdict: str        # agree | refused | warned | unsure | silent
    detail: str = ""
    checks: int = 0
    #: solve at a neighbouring pose (x ± h), stated in the same words, took another closure
    #: than the one the sweep follows from x (the words' choice jumps there)
    flip: str = ""

    @property
    def replay(self) -> str:
        return f"{self.kind} seed {self.seed} at {self.pose!r} ({self.why}): {self.detail}"


@dataclass
class _Diff:
    worst: list = field(default_factory=list)      # (excess, what)
    unsure: list = field(default_factory=list)
    n: int = 0

    def compare(self, what, ours, fd, fd2, scale, tol=TOL, rounding=0.0):
        """``ours`` against the finite difference ``fd`` (``fd2`` at twice the step);
        ``rounding``: the bound of the difference's rounding error (ε·size/h, ε·size/h²)."""
        ours, fd, fd2 = (np.asarray(v, float) for v in (ours, fd, fd2))
        if not (np.all(np.isfinite(fd)) and np.all(np.isfinite(fd2))):
            self.unsure.append(f"{what}: no finite difference")
            return
        # |fd − fd2| is 15× fd's error where the Taylor series has converged; taken whole
        est = float(np.max(np.abs(fd - fd2))) + rounding
        if est > UNSURE * scale:
            self.unsure.append(f"{what}: the finite difference is unsure ({est:.3g})")
            return
        self.n += 1
        err = float(np.max(np.abs(ours - fd))) if np.all(np.isfinite(ours)) else math.inf
        lim = tol * scale + 2 * est
        if not err <= lim:
            self.worst.append((err / max(lim, 1e-300), f"{what}: {np.round(ours, 9).tolist()} "
                                                       f"against {np.round(fd, 9).tolist()}"))


def _derivs(arr, h):
    """d/dx and d²/dx² at the stencil's centre, at steps h and 2h (4th order)."""
    p = {k: arr[i] for i, k in enumerate((-4, -2, -1, 0, 1, 2, 4))}
    d1h = (p[-2] - 8 * p[-1] + 8 * p[1] - p[2]) / (12 * h)
    d1H = (p[-4] - 8 * p[-2] + 8 * p[2] - p[4]) / (24 * h)
    d2h = (-p[-2] + 16 * p[-1] - 30 * p[0] + 16 * p[1] - p[2]) / (12 * h * h)
    d2H = (-p[-4] + 16 * p[-2] - 30 * p[0] + 16 * p[2] - p[4]) / (48 * h * h)
    return d1h, d1H, d2h, d2H


def check(mech: Mechanism, x: float, dist: float, why: str) -> Outcome:
    """Every check at pose ``x`` (``dist`` from the nearest meeting of closures)."""
    out = Outcome(mech.kind, mech.seed, x, why, "agree")
    scene = mech.at(x)
    try:
        sol = solve(scene)
        warned = tuple(sol.warnings)
        sol.points                                          # noqa: B018
    except PolygonsError as exc:
        out.verdict, out.detail = "refused", str(exc).splitlines()[0][:200]
        return out
    unit = 1.0 if mech.crank else mech.size
    h = min(1e-3 * unit, dist / 32)     # the stencil's reach (4h) an eighth of the way
    xs = x + h * STENCIL
    try:
        sw = sweep(scene, inputs=xs)
    except PolygonsError as exc:
        out.verdict = "warned" if warned else "silent"
        out.detail = f"solve answers but the sweep refuses: {str(exc).splitlines()[0][:160]}"
        return out
    w, al = mech.rate, mech.rate2
    labels = [p for p in mech.labels if p in sol.points and p in sw.pos]
    if not labels:
        labels = [p for p in sol.points if p in sw.pos and p not in scene.ground]
    vs = max([math.hypot(*sol.points[p].velocity) for p in labels
              if sol.points[p].velocity is not None] + [abs(w) * unit * 1e-3])
    as_ = max([math.hypot(*sol.points[p].acceleration) for p in labels
               if sol.points[p].acceleration is not None] + [abs(al) * unit * 1e-3, 1e-12])
    d = _Diff()
    eps = 4 * np.finfo(float).eps * mech.size       # the positions' rounding
    rv, ra = 3 * eps / h * abs(w), 10 * eps / (h * h) * w * w + 3 * eps / h * abs(al)
    mismatch = []
    for p in labels:
        P = sw.position(p)
        res = sol.points[p]
        if np.all(np.isfinite(P[3])):
            if math.dist(P[3], res.position) > SAME * mech.size:
                mismatch.append(f"{p}: solve {res.position} but the sweep's row {tuple(P[3])}")
        d1h, d1H, d2h, d2H = _derivs(P, h)
        if res.velocity is not None:
            d.compare(f"v({p})", res.velocity, d1h * w, d1H * w, vs, rounding=rv)
        if res.acceleration is not None:
            d.compare(f"a({p})", res.acceleration, d2h * w * w + d1h * al,
                      d2H * w * w + d1H * al, as_, rounding=ra)
    for q in getattr(scene, "equivalents", ()):
        _contact(d, sol, sw, q, h, w, al, vs, as_, rv, ra)
    nearest = _nearest(mech, scene, sol, x, xs)
    for i in (2, 4):        # the closure chosen by the words at x ± h: the one followed?
        nb = _solves(mech, xs[i])
        for p in labels if nb is not None else ():
            row = sw.position(p)[i]
            if np.all(np.isfinite(row)) and math.dist(row, nb.points[p].position) > \
                    1e-6 * mech.size:
                out.flip = f"at {xs[i]!r} solve takes {p} at {nb.points[p].position}, " \
                           f"the followed closure {tuple(row)}"
                break
    rigid = _rigid(sol, scene, vs, as_, mech.size)
    out.checks = d.n + len(labels) + rigid[0]
    failed = mismatch + ([max(d.worst)[1]] if d.worst else []) + rigid[1] + nearest
    if failed:
        out.verdict = "warned" if warned else "silent"
        out.detail = "; ".join(failed)[:400]
    elif d.unsure:
        out.verdict = "warned" if warned else "unsure"
        out.detail = d.unsure[0]
    elif warned:
        out.verdict = "warned"
        out.detail = warned[0][:200]
    return out


def _nearest(mech, scene, sol, x, xs):
    """A closure chosen ``near`` a point is the nearest of all: each neighbour's closure
    (solve at x ± h, then followed back to x by the sweep) found nearer than the one solve
    took at x means solve missed a closure there — a second route to the closures."""
    bad = []
    for label, br in scene.assembly.items():
        if br.relation != "near" or label not in sol.points:
            continue
        took = math.dist(sol.points[label].position, br.near)
        for i in (2, 4):
            try:
                back = sweep(mech.at(xs[i]), inputs=[x]).position(label)[0]
            except PolygonsError:
                continue
            if np.all(np.isfinite(back)) and math.dist(back, br.near) < took - 1e-6 * mech.size:
                bad.append(f"near {label}: solve took {sol.points[label].position} "
                           f"({took:.6g} from the near point) but the closure followed from "
                           f"{xs[i]!r} is at {tuple(back)} ({math.dist(back, br.near):.6g})")
                break
    return bad


def _rigid(sol, scene, vs, as_, size):
    """Every pair of points P, Q of one body (each link with its [points], a lever with the
    point under its pin): (v_Q − v_P)·PQ = 0 and (a_Q − a_P)·PQ + |v_Q − v_P|² = 0 — the
    rigidity of the body, differentiated; no finite difference, so it judges every pose,
    a toggle's neighbourhood too.  (count of checks, failures in words)"""
    n, bad = 0, []
    pts = sol.points
    for body in scene.model.bodies:
        if body.kind not in ("link", "lever"):
            continue
        labs = [p for p in body.labels if p in pts and pts[p].velocity is not None]
        for i, a in enumerate(labs):
            for b in labs[i + 1:]:
                r = np.subtract(pts[b].position, pts[a].position)
                L = float(np.hypot(*r))
                if L <= 1e-9 * size:
                    continue
                dv = np.subtract(pts[b].velocity, pts[a].velocity)
                n += 1
                if not abs(float(dv @ r)) <= TOL * vs * L:
                    bad.append(f"{a}{b} of {body.name} stretches: (v_{b} − v_{a})·{a}{b} = "
                               f"{float(dv @ r):.3g}")
                if pts[a].acceleration is not None and pts[b].acceleration is not None:
                    da = np.subtract(pts[b].acceleration, pts[a].acceleration)
                    n += 1
                    res = float(da @ r + dv @ dv)
                    if not abs(res) <= TOL * (as_ * L + float(dv @ dv) + vs * vs):
                        bad.append(f"{a}{b} of {body.name}: (a_{b} − a_{a})·{a}{b} + "
                                   f"|v_{b} − v_{a}|² = {res:.3g}")
    return n, bad


def _contact(d: _Diff, sol, sw, q, h, w, al, vs, as_, rv, ra):
    """Each output of the higher pair ``q`` against finite differences of the geometry of the
    sweep's positions (:data:`polygons.contacts.OUTPUTS`)."""
    hp = higher(sol, q)
    if hp is None:
        return
    pos = {k: sw.position(k) for k in sw.pos}

    def rate(arr, what, ours, scale, second=False, k=1.0):
        """``ours`` against the rate of ``arr`` (k: its rounding relative to a position's)."""
        d1h, d1H, d2h, d2H = _derivs(np.asarray(arr), h)
        if second:
            d.compare(what, ours, d2h * w * w + d1h * al, d2H * w * w + d1H * al, scale,
                      rounding=ra * k)
        else:
            d.compare(what, ours, d1h * w, d1H * w, scale, rounding=rv * k)

    if q.kind == "bearing":
        link = sol.links[q.link]
        A, B, K = pos[link.a], pos[link.b], pos[q.at]
        u = (B - A) / np.hypot(*(B - A).T)[:, None]
        n = np.stack([-u[:, 1], u[:, 0]], axis=1)
        t = np.sum((K - A) * u, axis=1)
        T = A + t[:, None] * u
        t0 = t[3]
        X = A + t0 * u                                   # the bar's material point at T
        phi = np.unwrap(np.arctan2(u[:, 1], u[:, 0]))
        rate(phi, "omega(bar)", hp["omega"], vs / max(t0, 1e-9) + abs(hp["omega"]),
             k=1 / link.length)
        rate(phi, "alpha(bar)", hp["alpha"], as_ / max(t0, 1e-9) + abs(hp["alpha"]), True,
             k=1 / link.length)
        rate(X, "bar_point_velocity", hp["bar_point_velocity"], vs)
        rate(X, "bar_point_acceleration", hp["bar_point_acceleration"], as_, True)
        rate(X @ u[3], "sliding_velocity", hp["sliding_velocity"], vs)
        rate(t, "contact_velocity_along_bar", hp["contact_velocity_along_bar"], vs)
        rate(T @ u[3], "contact_velocity_along_circle", hp["contact_velocity_along_circle"], vs)
        assert abs(float(np.dot(T[3] - K[3], u[3]))) < 1e-9 * (1 + np.hypot(*K[3]))
        assert abs(float(np.hypot(*(T[3] - K[3]))) - q.radius) < 1e-9 * (1 + q.radius)
        del n
        if "instant_centre" in hp:                      # v_X = ω k × (X − I)
            I = np.asarray(hp["instant_centre"])
            r = X[3] - I
            d.compare("instant_centre", (-hp["omega"] * r[1], hp["omega"] * r[0]),
                      *(_derivs(X, h)[k] * w for k in (0, 1)), vs)
    elif q.kind in ("curved slot", "cam"):
        P, C = pos[q.at], pos[q.centre]
        ang = np.unwrap(np.arctan2(P[:, 1] - C[:, 1], P[:, 0] - C[:, 0]))
        body = hp["slot_body" if q.kind == "curved slot" else "cam_body"]
        if body != "frame":
            lk = sol.links[body]
            E = pos[lk.b] - pos[lk.a]
            ang = ang - np.unwrap(np.arctan2(E[:, 1], E[:, 0]))
        r = float(np.hypot(*(P[3] - C[3])))
        if q.kind == "curved slot":
            rate(r * ang, "sliding_velocity", hp["sliding_velocity"], vs)
            rate(ang, "relative_omega", hp["relative_omega"], vs / r, k=1 / r)
        else:
            rate(r * ang, "follower_velocity_relative", hp["follower_velocity_relative"], vs)
            rate(q.radius * ang, "contact_velocity_along_profile",
                 hp["contact_velocity_along_profile"], vs)
    elif q.kind == "rolling" and not q.opposite and not q.on:
        W = pos[q.at]
        e = np.array([math.cos(q.face), math.sin(q.face)])
        # rolling without slip on a fixed surface: the wheel turns by −(travel)/r
        rate(-(W @ e) / q.radius, "omega(wheel)", hp["omega"], vs / q.radius, k=1 / q.radius)
        if "alpha" in hp:
            rate(-(W @ e) / q.radius, "alpha(wheel)", hp["alpha"], as_ / q.radius, True,
                 k=1 / q.radius)


def run(kinds, seeds, n_random: int, rng_seed: int = 0, limit: int | None = None,
        grid: int = 48):
    """Every outcome over the random mechanisms ``seeds`` of each of ``kinds`` — at most
    ``limit`` of them per kind that assemble somewhere (a random mechanism may not)."""
    out = []
    for kind in kinds:
        used = 0
        for seed in seeds:
            if limit is not None and used >= limit:
                break
            mech = make(kind, seed)
            if mech is None:
                continue
            rng = random.Random(f"poses/{kind}/{seed}/{rng_seed}")
            todo = poses(mech, rng, n_random, grid)
            used += bool(todo)
            for x, dist, why in todo:
                out.append(check(mech, x, dist, why))
    return out
