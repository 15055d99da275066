"""Full-cycle sweeps: every position of the input solved at once, vectorised with numpy.

The staged constructor (:mod:`polygons.evaluate`) draws one position at a time, stroke by
stroke.  A sweep asks the same questions for thousands of input angles, so here the same
:class:`~polygons.plan.Plan` dyads are evaluated on whole arrays, one numpy expression per
dyad, with no Python loop over positions.  Each dyad's closed form is the algebra of its
construction:

* crank ``PX``:        v = ω × PX,  a = α × PX − ω² PX
* RRR ``P–X–Q``:       v_x = v_p + ω_p × PX = v_q + ω_q × QX, solved for (ω_p, ω_q) by the
  same two perpendicular lines the polygon intersects (their determinant is
  ``PX × QX``, zero at a toggle); the accelerations likewise with the centripetal
  terms known
* RRP ``P–X`` + guide: v_x = v_p + ω × PX along the guide (determinant ``PX · e``)
* RPR slotted lever:   ω = (BA × v_A)/BA², sliding ṡ = e·v_A, α with the Coriolis 2ωṡ
* RPP Scotch yoke:     the yoke point on the guide, v and a along the guide (no rotation)
* image points:        v = v_p + ω × PX, a = a_p + α × PX − ω² PX

The branch of every two-closure dyad is taken from the staged assembly at the scene's own
input (the scene's words) and then *followed continuously*: the sign σ of the chosen
closure relative to its base line is kept, which is continuity as long as the closure
discriminant stays positive.  Where it reaches zero the mechanism is at a toggle: the
reachable range ends there (a limit position) or, if the discriminant only touches zero, the
branches meet (a change point); both are reported in :attr:`Sweep.limits`, never crossed
silently.

This module must not import shapely (``polygons.geometry`` is the only shapely importer);
the two angle thresholds below are the same numbers as there (a test checks it).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Callable, Iterable, Mapping, Sequence

import numpy as np

from .errors import ConstructionError, PolygonsError
from .plan import RPP, RPR, RRP, RRR, CrankDyad, Image, Plan, SliderDriveDyad, make_plan
from .position import assemble
from .scene import Crank, Scene

#: same thresholds as polygons.geometry (kept equal by tests/test_sweep.py)
PARALLEL_DEG = 1e-5
WARN_DEG = 1.0
_SIN_PARALLEL = math.sin(math.radians(PARALLEL_DEG))
_SIN_WARN = math.sin(math.radians(WARN_DEG))
#: probe points used to find the reachable range and the toggles inside it
PROBE = 4096
#: default chunk of positions evaluated per numpy pass (memory and cache friendly)
CHUNK = 1 << 12


# ---------------------------------------------------------------- results
@dataclass(frozen=True)
class Limit:
    """A limit of the reachable range or a toggle / change point inside it."""

    input: float        # θ in rad (crank driver) or s in m (slider driver)
    kind: str           # 'limit' (the range ends here) | 'toggle' (branches meet, sweep split)
                        # | 'near-toggle' (smallest angle below WARN_DEG but not zero)
    point: str          # the point whose dyad degenerates
    reason: str         # in words, e.g. "BC and CD in line"
    angle_deg: float    # intersection angle of the construction there


@dataclass
class Sweep:
    """All positions of one sweep, SI units.

    ``pos``, ``vel``, ``acc``: label -> array (2, N) (x row, y row);  ``omega``, ``alpha``:
    link name -> array (N,);  ``slide_v``/``slide_a``: slider or pin label -> array (N,)
    (signed along the guide, or along the slot away from the lever pivot);  ``travel``: slider
    label -> position along its guide from its ``through`` point;  ``angle_deg``: the smallest
    intersection angle of the construction at each position (its conditioning).
    """

    scene: Scene
    plan: Plan
    input_kind: str                 # 'crank' | 'slider'
    inputs: np.ndarray              # θ (rad) or s (m), shape (N,)
    omega_in: float                 # input rate (rad/s or m/s)
    alpha_in: float
    full_cycle: bool
    range: tuple[float, float]      # reachable range (closed), in input units
    limits: tuple[Limit, ...]
    segments: tuple[tuple[int, int], ...]   # [start, stop) index ranges between toggles
    branches: Mapping[str, int]     # label -> σ (+1 / −1) followed over the sweep
    pos: dict
    vel: dict
    acc: dict
    omega: dict
    alpha: dict
    slide_v: dict
    slide_a: dict
    travel: dict
    coriolis: dict
    margin: np.ndarray              # sine of the smallest intersection angle, per position
    warnings: tuple[str, ...] = ()

    @cached_property
    def angle_deg(self) -> np.ndarray:
        """The smallest intersection angle of the construction at each position (degrees):
        its conditioning (NaN where the mechanism cannot be assembled)."""
        with np.errstate(invalid="ignore"):
            return np.degrees(np.arcsin(np.where(self.margin >= 0,
                                                 np.minimum(self.margin, 1.0), np.nan)))

    @property
    def n(self) -> int:
        return int(self.inputs.shape[0])

    def position(self, label: str) -> np.ndarray:
        """(N, 2) positions of ``label``."""
        return _as_n2(self.pos[label], self.n)

    def velocity(self, label: str) -> np.ndarray:
        return _as_n2(self.vel[label], self.n)

    def acceleration(self, label: str) -> np.ndarray:
        return _as_n2(self.acc[label], self.n)


def _as_n2(xy, n: int) -> np.ndarray:
    if xy is None:
        return np.zeros((n, 2))
    x, y = xy
    out = np.empty((n, 2))
    out[:, 0] = x
    out[:, 1] = y
    return out


# ---------------------------------------------------------------- the compiled program
@dataclass(frozen=True)
class _Op:
    kind: str
    label: str                    # point placed (first one for RPR)
    data: tuple


@dataclass(frozen=True)
class Program:
    """The plan's dyads with every constant looked up once (lengths, guides, branches)."""

    scene: Scene
    plan: Plan
    ops: tuple[_Op, ...]
    ground: Mapping[str, tuple[float, float]]
    input_kind: str
    input0: float
    rate: float
    rate2: float
    branches: Mapping[str, int]
    links: tuple[tuple[str, str, str], ...]   # (name, a, b) of every link to report
    scale: float


def compile_plan(scene: Scene, plan: Plan | None = None) -> Program:
    """Look every constant up once and take each two-closure branch from the staged assembly
    at the scene's own input (raises the staged :class:`AssemblyError` / ``BranchError`` if
    the scene itself cannot be assembled)."""
    plan = plan or make_plan(scene)
    placement = assemble(plan)
    pos0 = {k: np.array(v) for k, v in placement.points.items()}
    ground = {k: (float(v[0]), float(v[1])) for k, v in scene.ground.items()}
    ops: list[_Op] = []
    branches: dict[str, int] = {}
    drv = scene.driver
    for d in plan.dyads:
        if isinstance(d, CrankDyad):
            ops.append(_Op("crank", d.tip, (d.pivot, scene.links[d.link].length, d.link)))
        elif isinstance(d, SliderDriveDyad):
            g = scene.sliders[d.point]
            ops.append(_Op("drive", d.point, (g.through, g.direction)))
        elif isinstance(d, RRR):
            r1 = scene.links[d.link_p].length
            r2 = scene.links[d.link_q].length
            p, q, x = pos0[d.p], pos0[d.q], pos0[d.x]
            side = float((q - p)[0] * (x - p)[1] - (q - p)[1] * (x - p)[0])
            sigma = _sign_or_toggle(side, d.x, f"{d.link_p} and {d.link_q} are in line", scene)
            branches[d.x] = sigma
            ops.append(_Op("rrr", d.x, (d.p, d.q, r1, r2, sigma, d.link_p, d.link_q)))
        elif isinstance(d, RRP):
            g = scene.sliders[d.x]
            L = scene.links[d.link].length
            e = np.array(g.direction)
            side = float((pos0[d.x] - pos0[d.p]) @ e)
            sigma = _sign_or_toggle(side, d.x, f"{d.link} is perpendicular to the guide of "
                                               f"{d.x}", scene)
            branches[d.x] = sigma
            ops.append(_Op("rrp", d.x, (d.p, L, g.through, g.direction, sigma, d.link)))
        elif isinstance(d, RPR):
            slot = scene.slots[d.pin]
            ops.append(_Op("rpr", d.coincident, (d.pin, d.pivot, d.far, slot.far_length,
                                                 d.lever)))
        elif isinstance(d, Image):
            bp = scene.points[d.x]
            ops.append(_Op("image", d.x, (d.link, d.p, d.q, bp.along, bp.fraction, bp.left)))
        elif isinstance(d, RPP):
            g = scene.sliders[d.x]
            ops.append(_Op("rpp", d.x, (d.pin, g.through, g.direction, g.slot_direction)))
        else:  # pragma: no cover - a dyad type this module does not know yet
            raise PolygonsError(f"sweeps do not support the dyad {type(d).__name__} yet",
                                file=scene.file)
    if isinstance(drv, Crank):
        kind, x0, rate, rate2 = "crank", drv.angle, drv.omega, drv.alpha
    else:
        kind, x0, rate, rate2 = "slider", drv.position, drv.velocity, drv.acceleration
    links = []
    for name, link in scene.links.items():
        links.append((name, link.a, link.b))
    for slot in scene.slots.values():
        if slot.lever not in scene.links:
            links.append((slot.lever, slot.pivot, slot.coincident))
    lengths = [l.length for l in scene.links.values() if l.length]
    coords = [abs(c) for v in scene.ground.values() for c in v]
    return Program(scene, plan, tuple(ops), ground, kind, float(x0), float(rate), float(rate2),
                   branches, tuple(links), max(lengths + coords + [1e-300]))


def _sign_or_toggle(side: float, x: str, why: str, scene: Scene) -> int:
    if side > 0:
        return 1
    if side < 0:
        return -1
    raise ConstructionError(f"the scene's own position is a toggle for {x} ({why}): the two "
                            f"closures coincide, so there is no branch to follow; state the "
                            f"scene at another input", file=scene.file, where=x)


# ---------------------------------------------------------------- vectorised evaluation
def evaluate(prog: Program, inputs, *, rates: bool = True) -> dict:
    """Solve every position in ``inputs`` (θ in rad or s in m) at once.

    Returns a dict with ``pos``, ``vel``, ``acc`` (label -> (x, y) arrays, ``None`` for a
    fixed point's velocity/acceleration), ``omega``, ``alpha``, ``slide_v``, ``slide_a``,
    ``travel``, ``coriolis`` and ``margin`` (the sine of the smallest intersection angle of
    the construction; negative where a dyad cannot close, NaN downstream of that).
    """
    t = np.asarray(inputs, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return _evaluate(prog, t, rates)


def _evaluate(prog: Program, t: np.ndarray, rates: bool) -> dict:
    P: dict = dict(prog.ground)
    V: dict = {k: None for k in prog.ground}
    A: dict = {k: None for k in prog.ground}
    W: dict = {}
    AL: dict = {}
    SV: dict = {}
    SA: dict = {}
    TR: dict = {}
    COR: dict = {}
    margins: list = []
    n = t.shape

    for op in prog.ops:
        k, X, data = op.kind, op.label, op.data
        if k == "crank":
            pivot, r, link = data
            px, py = P[pivot]
            rx = np.cos(t)
            rx *= r
            ry = np.sin(t)
            ry *= r
            P[X] = (_plus(px, rx), _plus(py, ry))
            w, al = prog.rate, prog.rate2
            W[link], AL[link] = w, al
            if rates:
                V[X] = (ry * -w, rx * w)
                w2 = -w * w
                if al:
                    A[X] = (rx * w2 - ry * al, ry * w2 + rx * al)
                else:
                    A[X] = (rx * w2, ry * w2)
        elif k == "drive":
            (gx, gy), (ex, ey) = data
            P[X] = (_plus(gx, t * ex), _plus(gy, t * ey))
            TR[X] = t
            if rates:
                v, a = prog.rate, prog.rate2
                V[X] = (np.full(n, v * ex), np.full(n, v * ey))
                A[X] = (np.full(n, a * ex), np.full(n, a * ey))
                SV[X] = np.full(n, v)
                SA[X] = np.full(n, a)
        elif k == "rrr":
            p, q, r1, r2, sigma, lp, lq = data
            px, py = P[p]
            qx, qy = P[q]
            dx = qx - px
            dy = qy - py
            d2 = dx * dx
            d2 += dy * dy
            inv_d2 = 1.0 / d2
            af = inv_d2 * (0.5 * (r1 * r1 - r2 * r2))
            af += 0.5
            h2 = inv_d2 * (r1 * r1)
            h2 -= af * af
            hf = np.sqrt(h2)
            if _has_nan(hf):
                # a double closure within the staged assembly's tolerance is a toggle, not a
                # failure; beyond it the position stays NaN (and the margin negative)
                hf = np.sqrt(np.where(h2 >= -1e-12 * (r1 * r1 + r2 * r2 + d2) * inv_d2,
                                      np.maximum(h2, 0.0), np.nan))
            if sigma < 0:
                np.negative(hf, out=hf)
            m1x = af * dx                    # PX
            m1x -= hf * dy
            m1y = af * dy
            m1y += hf * dx
            P[X] = (px + m1x, py + m1y)
            det = hf * d2                    # PX × QX: zero at a toggle
            if rates:
                margins.append(np.abs(det) * (1.0 / (r1 * r2)))   # sine of the lines' angle
            else:
                margins.append(np.where(h2 >= 0, np.abs(det),
                                        -np.sqrt(np.abs(h2)) * d2) * (1.0 / (r1 * r2)))
                continue
            m2x = m1x - dx                   # QX
            m2y = m1y - dy
            vp, vq = V[p], V[q]
            dvx, dvy = _diff(vq, vp)
            inv = 1.0 / det
            wp = dvx * m2x
            wp += dvy * m2y
            wp *= inv
            wq = dvx * m1x
            wq += dvy * m1y
            wq *= inv
            vx = m1y * -wp
            vy = m1x * wp
            if vp is not None:
                vx += vp[0]
                vy += vp[1]
            V[X] = (vx, vy)
            W[lp], W[lq] = wp, wq
            ap, aq = A[p], A[q]
            wp2 = wp * wp
            wq2 = wq * wq
            Rx = wp2 * m1x
            Rx -= wq2 * m2x
            Ry = wp2 * m1y
            Ry -= wq2 * m2y
            if aq is not None:
                Rx += aq[0]
                Ry += aq[1]
            if ap is not None:
                Rx -= ap[0]
                Ry -= ap[1]
            alp = Rx * m2x
            alp += Ry * m2y
            alp *= inv
            alq = Rx * m1x
            alq += Ry * m1y
            alq *= inv
            ax = alp * -m1y
            ax -= wp2 * m1x
            ay = alp * m1x
            ay -= wp2 * m1y
            if ap is not None:
                ax += ap[0]
                ay += ap[1]
            A[X] = (ax, ay)
            AL[lp], AL[lq] = alp, alq
        elif k == "rrp":
            # in the guide's frame (u along e, n across): the pin P at (pu, pn) relative to
            # the guide's point g; X = g + t e with (t - pu)² + pn² = L²
            p, L, (gx, gy), (ex, ey), sigma, link = data
            px, py = P[p]
            wx = px - gx if gx else px
            wy = py - gy if gy else py
            aligned = ey == 0.0 and ex == 1.0
            if aligned:
                pu, pn = wx, wy
            else:
                pu = ex * wx
                pu += ey * wy
                pn = ex * wy
                pn -= ey * wx
            disc = pn * pn
            np.subtract(L * L, disc, out=disc)
            root = np.sqrt(disc)
            if _has_nan(root):
                root = np.sqrt(np.where(disc >= -1e-12 * L * L, np.maximum(disc, 0.0), np.nan))
            me = root if sigma > 0 else -root       # PX · e: zero at a toggle
            tt = pu + me                            # travel along the guide from g
            if aligned:
                P[X] = (_plus(gx, tt), np.full(n, gy))
            else:
                P[X] = (_plus(gx, tt * ex), _plus(gy, tt * ey))
            TR[X] = tt
            if rates:
                margins.append(root * (1.0 / L))
            else:
                margins.append(np.where(disc >= 0, root, -np.sqrt(np.abs(disc))) * (1.0 / L))
                continue
            vp, ap = V[p], A[p]
            ninv = -1.0 / me
            if vp is None:
                w = 0.0 * me
                sd = 0.0 * me
            else:
                if aligned:
                    vu, vn = vp
                else:
                    vu = ex * vp[0]
                    vu += ey * vp[1]
                    vn = ex * vp[1]
                    vn -= ey * vp[0]
                w = vn * ninv                       # ω = (v_p × e) / (PX · e)
                sd = w * pn
                sd += vu                            # ṡ = v_p·e + ω (PX × e)
            w2 = w * w
            if ap is None:
                bu = w2 * -me
                bn = w2 * pn
            else:
                if aligned:
                    au, an = ap
                else:
                    au = ex * ap[0]
                    au += ey * ap[1]
                    an = ex * ap[1]
                    an -= ey * ap[0]
                bu = au - w2 * me                   # (a_p − ω² PX)·e
                bn = w2 * pn
                bn += an                            # (a_p − ω² PX)·n
            al = bn * ninv
            sdd = al * pn
            sdd += bu
            if aligned:
                V[X] = (sd, np.zeros(n))
                A[X] = (sdd, np.zeros(n))
            else:
                V[X] = (sd * ex, sd * ey)
                A[X] = (sdd * ex, sdd * ey)
            W[link], AL[link] = w, al
            SV[X], SA[X] = sd, sdd
        elif k == "rpr":
            pin, pivot, far, far_len, lever = data
            ax_, ay_ = P[pin]
            bx_, by_ = P[pivot]
            rx = ax_ - bx_
            ry = ay_ - by_
            rho2 = rx * rx
            rho2 += ry * ry
            rho = np.sqrt(rho2)
            P[X] = P[pin]
            # the lines of an RPR construction are always perpendicular; only a pin on the
            # pivot (no slot direction) degenerates it
            margins.append(np.where(rho > 1e-12 * prog.scale, 1.0, 0.0))
            if far is not None:
                f = far_len / rho
                fx, fy = f * rx, f * ry
                P[far] = (_plus(bx_, fx), _plus(by_, fy))
            if not rates:
                continue
            va, aa = V[pin], A[pin]
            inv2 = 1.0 / rho2
            inv1 = 1.0 / rho
            w = rx * va[1]
            w -= ry * va[0]
            w *= inv2
            sd = rx * va[0]
            sd += ry * va[1]
            sd *= inv1
            c2 = w * sd
            c2 *= 2.0 * inv1                             # 2ωṡ / ρ
            al = rx * aa[1]
            al -= ry * aa[0]
            al *= inv2
            al -= c2                                     # α = (BA × a_A)/BA² − 2ωṡ/BA
            w2 = w * w
            sdd = rx * aa[0]
            sdd += ry * aa[1]
            sdd *= inv1
            sdd += w2 * rho
            W[lever], AL[lever] = w, al
            SV[pin], SA[pin] = sd, sdd
            COR[pin] = (ry * -c2, rx * c2)
            V[X] = (ry * -w, rx * w)
            ax1 = al * -ry
            ax1 -= w2 * rx
            ay1 = al * rx
            ay1 -= w2 * ry
            A[X] = (ax1, ay1)
            if far is not None:
                V[far] = (fy * -w, fx * w)
                ax2 = al * -fy
                ax2 -= w2 * fx
                ay2 = al * fx
                ay2 -= w2 * fy
                A[far] = (ax2, ay2)
        elif k == "image":
            link, p, q, along, fraction, left = data
            px, py = P[p]
            qx, qy = P[q]
            dx = qx - px
            dy = qy - py
            n2 = dx * dx + dy * dy
            nn = np.sqrt(n2)
            ux = dx / nn
            uy = dy / nn
            al_ = along if along is not None else fraction * nn
            rx = al_ * ux - left * uy
            ry = al_ * uy + left * ux
            P[X] = (px + rx, py + ry)
            if not rates:
                continue
            vp, vq = V[p], V[q]
            if link not in W:
                dvx, dvy = _diff(vq, vp)
                W[link] = (dx * dvy - dy * dvx) / n2
            w = W[link]
            vx, vy = -w * ry, w * rx
            if vp is not None:
                vx, vy = vx + vp[0], vy + vp[1]
            V[X] = (vx, vy)
            ap, aq = A[p], A[q]
            if link not in AL:
                dax, day = _diff(aq, ap)
                AL[link] = (dx * day - dy * dax) / n2
            al = AL[link]
            w2 = w * w
            ax, ay = -al * ry - w2 * rx, al * rx - w2 * ry
            if ap is not None:
                ax, ay = ax + ap[0], ay + ap[1]
            A[X] = (ax, ay)
        elif k == "rpp":
            pin, (gx, gy), (ex, ey), (sx, sy) = data
            den = ex * sy - ey * sx                  # guide × slot
            ppx, ppy = P[pin]
            tt = ((ppx - gx) * sy - (ppy - gy) * sx) / den
            P[X] = (_plus(gx, tt * ex), _plus(gy, tt * ey))
            TR[X] = tt
            margins.append(np.full(n, abs(den)))
            if not rates:
                continue
            vp, ap = V[pin], A[pin]
            sd = (vp[0] * sy - vp[1] * sx) / den
            sdd = (ap[0] * sy - ap[1] * sx) / den
            V[X] = (sd * ex, sd * ey)
            A[X] = (sdd * ex, sdd * ey)
            SV[X], SA[X] = sd, sdd
        else:  # pragma: no cover
            raise AssertionError(k)

    if rates:
        for name, a, b in prog.links:
            if name in W or a not in P or b not in P:
                continue
            dx, dy = _diff(P[b], P[a])
            n2 = dx * dx + dy * dy
            dvx, dvy = _diff(V[b], V[a])
            dax, day = _diff(A[b], A[a])
            W[name] = (dx * dvy - dy * dvx) / n2
            AL[name] = (dx * day - dy * dax) / n2
    if not margins:
        margin = np.ones(n)
    else:
        margin = margins[0]
        for m in margins[1:]:
            margin = np.minimum(margin, m)
    return {"pos": P, "vel": V, "acc": A, "omega": W, "alpha": AL, "slide_v": SV,
            "slide_a": SA, "travel": TR, "coriolis": COR, "margin": margin}


def _plus(c: float, arr):
    """c + arr, without the pass over the array when c is 0 (a pivot at the origin)."""
    return arr if c == 0.0 else c + arr


def _has_nan(a) -> bool:
    m = np.min(a)
    return m != m


def _diff(b, a):
    """b − a for (x, y) pairs where ``None`` is the zero vector."""
    if b is None and a is None:
        return 0.0, 0.0
    if a is None:
        return b
    if b is None:
        return -a[0], -a[1]
    return b[0] - a[0], b[1] - a[1]


# ---------------------------------------------------------------- range and toggles
def _margin(prog: Program, x) -> np.ndarray:
    return evaluate(prog, np.atleast_1d(np.asarray(x, dtype=float)), rates=False)["margin"]


def _culprit(prog: Program, x: float) -> tuple[str, str]:
    """The dyad with the smallest margin at input ``x``, and what degenerates there."""
    P = evaluate(prog, np.array([x], dtype=float), rates=False)["pos"]
    best = (math.inf, "", "")
    for op in prog.ops:
        k, X, data = op.kind, op.label, op.data
        if k == "rrr":
            p, q, r1, r2, sigma, lp, lq = data
            d = math.hypot(_f0(P[q][0]) - _f0(P[p][0]), _f0(P[q][1]) - _f0(P[p][1]))
            a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
            h2 = r1 * r1 - a * a
            m = math.copysign(math.sqrt(abs(h2)), h2) * d / (r1 * r2)
            how = ("stretched out" if abs(d - (r1 + r2)) < abs(d - abs(r1 - r2))
                   else "folded back")
            best = min(best, (m, X, f"{lp} and {lq} are in line ({p}, {X}, {q} collinear, "
                                    f"{how})"))
        elif k == "rrp":
            p, L, g, e, sigma, link = data
            wx, wy = g[0] - _f0(P[p][0]), g[1] - _f0(P[p][1])
            bq = e[0] * wx + e[1] * wy
            disc = bq * bq - (wx * wx + wy * wy - L * L)
            m = math.copysign(math.sqrt(abs(disc)), disc) / L
            best = min(best, (m, X, f"{link} is perpendicular to the guide of {X} (it "
                                    f"reaches the guide no further)"))
        elif k == "rpr":
            pin, pivot, *_ = data
            m = math.hypot(_f0(P[pin][0]) - _f0(P[pivot][0]),
                           _f0(P[pin][1]) - _f0(P[pivot][1])) / prog.scale
            best = min(best, (m, X, f"the pin {pin} is on the lever pivot {pivot}"))
    return best[1], best[2]


def _f0(v) -> float:
    return float(v[0]) if np.ndim(v) else float(v)


def _bisect(prog: Program, good: float, bad: float, iters: int = 200) -> float:
    """The last input from ``good`` towards ``bad`` where the mechanism still closes."""
    for _ in range(iters):
        mid = 0.5 * (good + bad)
        if mid == good or mid == bad:
            break
        m = _margin(prog, mid)[0]
        if m >= 0:
            good = mid
        else:
            bad = mid
    return good


def _golden_min(prog: Program, a: float, b: float, iters: int = 120) -> tuple[float, float]:
    """Minimum of the margin on [a, b] (golden section; the margin is unimodal near a toggle)."""
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = _margin(prog, c)[0], _margin(prog, d)[0]
    for _ in range(iters):
        if not (fc >= fd):    # also when fc is NaN
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = _margin(prog, c)[0]
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = _margin(prog, d)[0]
        if b - a <= 1e-15 * max(1.0, abs(a)):
            break
    x = 0.5 * (a + b)
    return x, float(_margin(prog, x)[0])


def _deg_of(m: float) -> float:
    return math.degrees(math.asin(min(1.0, max(0.0, m))))


def find_range(prog: Program, probe: int = PROBE):
    """(full_cycle, (lo, hi), limits, events) for the scene's input: the reachable range
    around it, its limit positions, and the toggles / near-toggles inside it.

    The margin (sine of the smallest construction angle; negative where a dyad cannot close)
    is probed at ``probe`` inputs; every local minimum below ``WARN_DEG`` is refined by a
    golden-section search, which finds change points that only touch zero and unreachable
    slivers narrower than the probe spacing; every end of the range is refined by bisection.
    """
    x0 = prog.input0
    closed = prog.input_kind == "crank"
    if closed:
        period = 2.0 * math.pi
        step = period / probe
        xs = x0 + step * np.arange(probe)
        span = period
    else:
        span = 2.0 * (sum(l.length for l in prog.scene.links.values() if l.length)
                      + max([math.hypot(*g) for g in prog.ground.values()] + [0.0]))
        span = max(span, prog.scale)
        half = probe // 2
        step = span / half
        xs = x0 + step * np.arange(-half, half + 1)
    m = _margin(prog, xs)
    ok = m >= 0
    n = len(xs)
    # local minima below the warning angle, refined
    left = np.roll(m, 1)
    right = np.roll(m, -1)
    cand = ok & (m < _SIN_WARN) & (m <= left) & (m <= right) & np.roll(ok, 1) & np.roll(ok, -1)
    if not closed:
        cand[0] = cand[-1] = False
    events: list[Limit] = []
    gaps: list[float] = []
    for i in np.flatnonzero(cand):
        xm, fm = _golden_min(prog, xs[i] - step, xs[i] + step)
        if not np.isfinite(fm) or fm < 0:
            gaps.append(xm)
        else:
            kind = "toggle" if fm < _SIN_PARALLEL else "near-toggle"
            events.append(Limit(xm, kind, *_culprit(prog, xm), angle_deg=_deg_of(fm)))
    bad = [float(x) for x in xs[~ok]] + gaps
    if closed and not bad:
        return True, (x0, x0 + period), (), tuple(events)
    # the nearest unreachable input on each side of the scene's input (unwrapped for a crank)
    if closed:
        rel = [(b - x0) % period for b in bad]
        rel = [r for r in rel if r > 0] or [period]
        hi_bad = x0 + min(rel)
        lo_bad = x0 - min(period - r for r in rel)
    else:
        above = [b for b in bad if b > x0]
        below = [b for b in bad if b < x0]
        hi_bad = min(above) if above else None
        lo_bad = max(below) if below else None
    limits: list[Limit] = []
    ends = []
    for bad_x, sign in ((lo_bad, -1), (hi_bad, 1)):
        if bad_x is None:
            edge = xs[0] if sign < 0 else xs[-1]
            ends.append(float(edge))
            limits.append(Limit(float(edge), "unbounded", "", f"the mechanism still closes "
                                f"here; the probe stopped {span:.3g} m from the scene's "
                                f"input", 90.0))
            continue
        k = math.floor(abs(bad_x - x0) / step - 1e-9)      # probes strictly before bad_x
        good = x0 + sign * k * step
        x = _bisect(prog, good, bad_x)
        ends.append(x)
        pt, why = _culprit(prog, x)
        limits.append(Limit(x, "limit", pt, why, _deg_of(max(float(_margin(prog, x)[0]), 0.0))))
    lo, hi = ends
    inside = []
    for ev in events:
        x = ev.input
        if closed:
            x = lo + (x - lo) % period
        if lo < x < hi:
            inside.append(Limit(x, ev.kind, ev.point, ev.reason, ev.angle_deg))
    return False, (lo, hi), tuple(limits), tuple(sorted(inside, key=lambda e: e.input))


# ---------------------------------------------------------------- the sweep
def sweep(scene: Scene, steps: int = 360, *, inputs: Sequence[float] | None = None,
          chunk: int = CHUNK, progress: Callable[[int], None] | None = None,
          probe: int = PROBE) -> Sweep:
    """Solve ``scene`` over a full input revolution (or its reachable range).

    Without ``inputs``: a crank driver is swept over θ = 0 … 360° in ``steps`` equal steps
    when every angle closes, else over the reachable range around the scene's angle
    (``steps`` points strictly inside it: the limit positions themselves have infinite
    rates); a slider driver over its reachable travel.  With ``inputs`` (θ in rad or s in
    m) exactly those positions are solved, all of them in the branch of the scene's own
    position.  ``progress(k)`` is called with the number of positions done after each chunk.
    """
    prog = compile_plan(scene)
    limits: tuple[Limit, ...] = ()
    toggles: tuple[Limit, ...] = ()
    if inputs is None:
        if steps < 2:
            raise PolygonsError(f"a sweep needs at least 2 steps, got {steps}", file=scene.file)
        full, (lo, hi), limits, toggles = find_range(prog, probe)
        if full:
            xs = 2.0 * math.pi * np.arange(steps) / steps
            rng = (0.0, 2.0 * math.pi)
        else:
            xs = lo + (hi - lo) * (np.arange(steps) + 0.5) / steps
            rng = (lo, hi)
    else:
        xs = np.asarray(inputs, dtype=float).reshape(-1)
        full = False
        rng = (float(xs.min()), float(xs.max())) if xs.size else (0.0, 0.0)
    res = run(prog, xs, chunk=chunk, progress=progress)
    segments = _segments(xs, toggles, full)
    warnings = []
    for tg in toggles:
        where = _fmt_input(prog, tg.input)
        if tg.kind == "toggle":
            warnings.append(f"toggle at {where}: {tg.reason}; the two closures of {tg.point} "
                            f"meet here, so the sweep is split there and beyond it follows the "
                            f"closure on the same side (the mechanism itself may take either)")
        else:
            warnings.append(f"near toggle at {where}: {tg.reason}; the construction lines "
                            f"meet at only {tg.angle_deg:.3g}°")
    margin = res["margin"]
    lowest = float(np.min(margin)) if len(margin) else 1.0
    if not lowest >= _SIN_PARALLEL:          # one pass when all is well (NaN compares False)
        bad = ~np.isfinite(margin) | (margin < 0)
        if bad.any():
            warnings.append(f"{int(bad.sum())} of {len(xs)} positions cannot be assembled in "
                            f"the followed branch (NaN in the results)")
        at = ~bad & (margin < _SIN_PARALLEL)
        if at.any():
            _undefine(res, at)
            warnings.append(f"{int(at.sum())} of {len(xs)} positions lie on a toggle "
                            f"(construction lines parallel within {PARALLEL_DEG:g}°): their "
                            f"velocities and accelerations are undefined and left as NaN")
    return Sweep(scene, prog.plan, prog.input_kind, xs, prog.rate, prog.rate2, full, rng,
                 tuple(limits) + tuple(toggles), segments, dict(prog.branches),
                 res["pos"], res["vel"], res["acc"], res["omega"], res["alpha"],
                 res["slide_v"], res["slide_a"], res["travel"], res["coriolis"], margin,
                 tuple(warnings))


def _undefine(res: dict, mask: np.ndarray) -> None:
    """Rates at the positions in ``mask`` (toggles) are undefined: NaN, not huge numbers."""
    for key in ("vel", "acc", "coriolis"):
        for arr in res[key].values():
            if arr is not None and not isinstance(arr, tuple):
                arr[:, mask] = np.nan
    for key in ("omega", "alpha", "slide_v", "slide_a"):
        for lab, arr in res[key].items():
            if not arr.flags.writeable:
                arr = res[key][lab] = np.array(arr)
            arr[mask] = np.nan


def run(prog: Program, xs: np.ndarray, *, chunk: int = CHUNK,
        progress: Callable[[int], None] | None = None) -> dict:
    """:func:`evaluate` in chunks of ``chunk`` positions (small enough for the CPU caches),
    each written straight into preallocated (2, N) / (N,) result arrays; fixed points keep
    their scalar positions and ``None`` rates."""
    xs = np.asarray(xs, dtype=float)
    n = len(xs)
    out: dict | None = None
    for s in range(0, max(n, 1), chunk):
        e = min(n, s + chunk)
        res = evaluate(prog, xs[s:e])
        if out is None:
            out = _allocate(res, n)
        _store(out, res, s, e)
        if progress:
            progress(e - s)
    return out


_VEC_KEYS = ("pos", "vel", "acc", "coriolis")
_SCALAR_KEYS = ("omega", "alpha", "slide_v", "slide_a", "travel")


def _allocate(res: dict, n: int) -> dict:
    """Result arrays for ``n`` positions, shaped after one evaluated chunk ``res``: views into
    one block (one allocation, which the allocator can hand back whole to the next sweep).
    Constant results (the crank's ω and α) are read-only broadcasts, not filled arrays."""
    rows = 1
    for key in _VEC_KEYS:
        for lab, xy in res[key].items():
            if not (xy is None or (key == "pos" and np.ndim(xy[0]) == 0 and np.ndim(xy[1]) == 0)):
                rows += 2
    for key in _SCALAR_KEYS:
        rows += sum(1 for v in res[key].values() if np.ndim(v) != 0)
    block = np.empty((rows, n))
    i = 0
    out = {}
    for key in _VEC_KEYS:
        d = {}
        for lab, xy in res[key].items():
            if xy is None or (key == "pos" and np.ndim(xy[0]) == 0 and np.ndim(xy[1]) == 0):
                d[lab] = xy
            else:
                d[lab] = block[i:i + 2]
                i += 2
        out[key] = d
    for key in _SCALAR_KEYS:
        d = {}
        for lab, v in res[key].items():
            if np.ndim(v) == 0:
                d[lab] = np.broadcast_to(np.float64(v), (n,))
            else:
                d[lab] = block[i]
                i += 1
        out[key] = d
    out["margin"] = block[i]
    return out


def _store(out: dict, res: dict, s: int, e: int) -> None:
    for key in _VEC_KEYS:
        for lab, arr in out[key].items():
            if isinstance(arr, np.ndarray):
                x, y = res[key][lab]
                arr[0, s:e] = x
                arr[1, s:e] = y
    for key in _SCALAR_KEYS:
        for lab, arr in out[key].items():
            if arr.flags.writeable:
                arr[s:e] = res[key][lab]
    out["margin"][s:e] = res["margin"]


def _segments(xs: np.ndarray, toggles: Iterable[Limit], full: bool):
    cuts = []
    for tg in toggles:
        if tg.kind != "toggle":
            continue
        x = tg.input % (2 * math.pi) if full else tg.input
        cuts.append(int(np.searchsorted(xs, x)))
    cuts = sorted(set(c for c in cuts if 0 < c < len(xs)))
    bounds = [0] + cuts + [len(xs)]
    return tuple((bounds[i], bounds[i + 1]) for i in range(len(bounds) - 1))


def _fmt_input(prog: Program, x: float) -> str:
    if prog.input_kind == "crank":
        return f"θ = {math.degrees(x) % 360.0:.6g}°"
    return f"s = {1e3 * x:.6g} mm"


@dataclass(frozen=True)
class Harmonic:
    """The simple-harmonic curve a slider would follow if it were driven by the crank pin's
    projection on its line of stroke (a Scotch yoke with the same crank): ``travel``,
    ``velocity``, ``acceleration`` arrays (N,), signed along the slider's guide; ``offset`` is
    the constant added to the projection so both strokes have the same centre (the harmonic
    *motion* has no preferred origin)."""

    point: str
    pin: str
    travel: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    offset: float


def harmonic(sw: Sweep, point: str) -> Harmonic:
    """The SHM curve for slider ``point``: the crank pin projected on ``point``'s guide."""
    scene = sw.scene
    drv = scene.driver
    if not isinstance(drv, Crank):
        raise PolygonsError("the simple-harmonic comparison needs a crank driver",
                            file=scene.file)
    if point not in scene.sliders or point not in sw.travel:
        raise PolygonsError(f"the simple-harmonic comparison is for a slider; {point} has no "
                            f"guide", file=scene.file, where=point)
    ex, ey = scene.sliders[point].direction
    px, py = scene.ground[drv.pivot]
    (ax, ay), (vx, vy), (aax, aay) = sw.pos[drv.tip], sw.vel[drv.tip], sw.acc[drv.tip]
    proj = (ax - px) * ex + (ay - py) * ey
    tr = sw.travel[point]
    offset = float(0.5 * (np.nanmax(tr) + np.nanmin(tr)) - 0.5 * (np.nanmax(proj) + np.nanmin(proj)))
    return Harmonic(point, drv.tip, proj + offset, vx * ex + vy * ey, aax * ex + aay * ey,
                    offset)


def fmt_input(sw: Sweep, x: float) -> str:
    return f"θ = {math.degrees(x):.6g}°" if sw.input_kind == "crank" else f"s = {1e3 * x:.6g} mm"


__all__ = ["Sweep", "Limit", "Harmonic", "harmonic", "Program", "compile_plan", "evaluate", "run", "sweep",
           "find_range", "PARALLEL_DEG", "WARN_DEG"]
