"""The interpreter kernel: what each construction :class:`~polygons.steps.Op` means.

Every interpreter of the step program — the exact staged solver (shapely intersections,
:mod:`polygons.evaluate`), the vectorised sweep (numpy over arrays of inputs,
:mod:`polygons.sweep`) and the drawing-board emulation (noisy strokes,
:mod:`polygons.drawing_board`) — runs the same steps through :class:`Kernel`, which implements
each op once, with numpy broadcasting: a vector is an array of shape (2,) for one position or
(2, N) for N positions.  What differs between interpreters is the :class:`Backend`: how a
construction line is made and how two lines are intersected (shapely on paper-sized segments,
or the 2×2 solve over arrays), and, for the emulation, the instruments' noise on every stroke.
No interpreter knows a dyad.
"""
from __future__ import annotations

import numpy as np

from .errors import ConstructionError
from .steps import Diagram, Op, Step, Term
from .topology import slot_along_lever
from .theorems import (angular_acceleration, angular_velocity, centripetal, coriolis, cross,
                       dot, norm, perp, relative_velocity, tangential)


class Backend:
    """Lines and intersections over numpy arrays (the sweep's backend).

    ``line(anchor, direction, name)`` returns ``(anchor, unit direction, name)``;
    ``intersect(l1, l2, step)`` returns ``(point, sine of the angle between the lines,
    angle in degrees or None)``.  Parallel lines give inf/NaN (the sweep marks those
    positions as toggles); lines through one point meet there (an instant at rest)."""

    def line(self, anchor, direction, name):
        n = norm(direction)
        return anchor, direction / n, name

    def intersect(self, l1, l2, step):
        (p, u, _), (q, v, _) = l1, l2
        den = cross(u, v)
        w = q - p
        t = cross(w, v) / den
        t = np.where(norm(w) == 0.0, 0.0, t) if np.ndim(t) else (0.0 if norm(w) == 0.0 else t)
        return p + t * u, np.abs(den), None

    # the instruments: exact here, noisy in the drawing-board emulation
    def vector(self, diagram, vec):
        return vec

    def mark(self, diagram, point):
        return point

    def direction(self, diagram, d):
        return d


class Kernel:
    """The state of one construction (one position, or N at once) and its ops.

    ``pos``: space label → position; ``vx[diagram][vertex]`` → polygon vertex;
    ``omega``/``alpha``: link → value; ``slide_v``/``slide_a``/``cor``: sliding pin → value.
    """

    def __init__(self, scene, pos, names, backend: Backend, omega=None, alpha=None,
                 arrays: bool = False, detail: bool = True):
        self.scene = scene
        self.pos = pos
        self.names = names
        self.b = backend
        self.arrays = arrays      # positions are (2, N) columns: constants become (2, 1)
        self.detail = detail      # compute each step's terms (the sweep does not need them)
        zero = self.const((0.0, 0.0))
        self.vx = {Diagram.VELOCITY: {names.pole: zero}, Diagram.ACCELERATION: {names.pole: zero}}
        self.omega = dict(omega or {})
        self.alpha = dict(alpha or {})
        self.lines: dict = {}
        self.slide_v: dict = {}
        self.slide_a: dict = {}
        self.cor: dict = {}
        self.margins: list = []
        self._r: dict = {}

    # -- helpers ------------------------------------------------------------------------
    def const(self, v):
        """A constant plane vector, as a (2, 1) column when the kernel runs on arrays."""
        v = np.array(v, dtype=float)
        return v.reshape(2, 1) if self.arrays else v

    def r(self, p: str, x: str):
        """The space vector PX (computed once per pair: the steps ask for it repeatedly)."""
        key = (p, x)
        v = self._r.get(key)
        if v is None:
            v = self._r[key] = self.pos[x] - self.pos[p]
        return v

    def of(self, diagram, label: str):
        return self.vx[diagram][self.names.of(label)]

    def _slot_e(self, A: str):
        """The unit vector along the slot of pin ``A``: pivot → pin for a slot through the
        lever's pivot (positive away from the pivot), pivot → far end for an offset slot or a
        driven lever (positive towards the far end)."""
        slot = self.scene.slots[A]
        if slot.far is not None and slot_along_lever(self.scene, slot):
            r = self.r(slot.pivot, slot.far)
        else:
            r = self.r(slot.pivot, A)
        return r / norm(r), slot

    # -- running a step -----------------------------------------------------------------
    def run(self, s: Step):
        """Execute ``s``; returns ``(at, vector, point, direction, value, unit, angle_deg,
        terms)`` (None where a field does not apply; ``terms`` a tuple of
        (symbol, value, unit))."""
        op = _OPS.get(s.op)
        if op is None:
            raise ConstructionError(f"unknown construction operation {s.op!r}")
        return op(self, s)

    def _vector(self, s: Step, vec, unit, terms):
        terms = terms() if self.detail else ()
        vx = self.vx[s.diagram]
        start = vx[s.start]
        vec = self.b.vector(s.diagram, vec)
        end = start + vec
        vx[s.end] = end
        return start, vec, end, None, None, unit, None, terms

    def terms(self, make):
        """``make()`` when the interpreter wants each step's terms, else ()."""
        return make() if self.detail else ()

    def _line(self, s: Step, direction, anchor):
        direction = self.b.direction(s.diagram, direction)
        ln = self.b.line(anchor, direction, s.draws)
        self.lines[(s.diagram, s.number)] = ln
        return ln


def _unit_of(diagram) -> str:
    return "m/s" if diagram == Diagram.VELOCITY else "m/s^2"


# ---------------------------------------------------------------- the ops
def _crank_velocity(k: Kernel, s: Step):
    L, P, X = s.args
    w = k.omega[L]
    r = k.r(P, X)
    vec = relative_velocity(w, r)
    return k._vector(s, vec, "m/s", lambda: ((f"ω_{L}", abs(w), "rad/s"), (f"{P}{X}", norm(r), "m"),
                                     (s.quantity, norm(vec), "m/s")))


def _slider_drive(k: Kernel, s: Step):
    (X,) = s.args
    e = k.const(k.scene.sliders[X].direction)
    vel = s.diagram == Diagram.VELOCITY
    val = k.scene.driver.velocity if vel else k.scene.driver.acceleration
    unit = _unit_of(s.diagram)
    return k._vector(s, val * e, unit, lambda: ((s.quantity, val, unit),))


def _centripetal(k: Kernel, s: Step):
    L, P, X = s.args
    w = k.omega[L]
    r = k.r(P, X)
    vec = centripetal(w, r)
    return k._vector(s, vec, "m/s^2", lambda: ((f"ω_{L}", abs(w), "rad/s"), (f"{P}{X}", norm(r), "m"),
                                       (s.quantity, norm(vec), "m/s^2")))


def _crank_tangential(k: Kernel, s: Step):
    L, P, X = s.args
    al = k.alpha[L]
    r = k.r(P, X)
    vec = tangential(al, r)
    return k._vector(s, vec, "m/s^2", lambda: ((f"α_{L}", abs(al), "rad/s^2"),
                                       (f"{P}{X}", norm(r), "m"),
                                       (s.quantity, norm(vec), "m/s^2")))


def _line_result(s: Step, ln):
    return ln[0], None, None, ln[1], None, "", None, ()


def _line_perp(k: Kernel, s: Step):
    P, X = s.args
    return _line_result(s, k._line(s, perp(k.r(P, X)), k.vx[s.diagram][s.start]))


def _line_along(k: Kernel, s: Step):
    P, X = s.args
    return _line_result(s, k._line(s, k.r(P, X), k.vx[s.diagram][s.start]))


def _line_guide(k: Kernel, s: Step):
    (X,) = s.args
    return _line_result(s, k._line(s, k.const(k.scene.sliders[X].direction),
                                   k.vx[s.diagram][s.start]))


def _line_slot(k: Kernel, s: Step):
    (X,) = s.args
    return _line_result(s, k._line(s, k.const(k.scene.sliders[X].slot_direction),
                                   k.vx[s.diagram][s.start]))


def _coriolis_offset_line(k: Kernel, s: Step):
    (A,) = s.args
    e, slot = k._slot_e(A)
    w = k.omega[slot.lever]
    v_s = k.slide_v[A]
    a_cor = coriolis(w, v_s * e)
    k.cor[A] = a_cor
    a_cor_drawn = k.b.vector(s.diagram, a_cor)
    ln = k._line(s, e, k.of(s.diagram, A) - a_cor_drawn)
    return ln[0], -a_cor, None, ln[1], None, "m/s^2", None, k.terms(lambda: (
        (f"ω_{slot.lever}", abs(w), "rad/s"), (f"(v_{A})_{slot.coincident}", abs(v_s), "m/s"),
        ("2ωv", norm(a_cor), "m/s^2")))


def _coriolis(k: Kernel, s: Step):
    """2 ω × ṡ e: computed here when the offset line did not already compute it (a pin found
    in a lever's slot; a prescribed slide, ṡ given, along its link)."""
    (A,) = s.args
    if A in k.cor:
        a_cor = k.cor[A]
        return k._vector(s, a_cor, "m/s^2", lambda: (("2ωv", norm(a_cor), "m/s^2"),))
    sl = k.scene.prescribed.get(A)
    if sl is not None:
        r = k.r(sl.p, sl.q)
        e, L, v_s = r / norm(r), sl.link, sl.velocity
    else:
        e, slot = k._slot_e(A)
        L, v_s = slot.lever, k.slide_v[A]
    w = k.omega[L]
    a_cor = k.cor[A] = coriolis(w, v_s * e)
    return k._vector(s, a_cor, "m/s^2", lambda: ((f"ω_{L}", abs(w), "rad/s"),
                                         (f"ṡ_{A}", abs(v_s), "m/s"),
                                         ("2ωv", norm(a_cor), "m/s^2")))


def _line_slide(k: Kernel, s: Step):
    (A,) = s.args
    e, _ = k._slot_e(A)
    return _line_result(s, k._line(s, e, k.vx[s.diagram][s.start]))


def _slide_drive(k: Kernel, s: Step):
    """A prescribed sliding velocity ṡ e or acceleration s̈ e along the link PQ."""
    C, P, Q = s.args
    r = k.r(P, Q)
    e = r / norm(r)
    spec = k.scene.prescribed[C]
    if s.diagram == Diagram.VELOCITY:
        val = spec.velocity
        k.slide_v[C] = val
    else:
        val = spec.acceleration
        k.slide_a[C] = val
    unit = _unit_of(s.diagram)
    return k._vector(s, val * e, unit, lambda: ((s.quantity, val, unit),))


def _join(k: Kernel, s: Step):
    vx = k.vx[s.diagram]
    vec = vx[s.end] - vx[s.start]
    return vx[s.start], vec, vx[s.end], None, None, "m/s^2", None, k.terms(lambda: (
        (f"{s.start}{s.end}", norm(vec), "m/s^2"),))


def _intersect(k: Kernel, s: Step):
    l1, l2 = (k.lines[(s.diagram, n)] for n in s.lines)
    p, sine, angle = k.b.intersect(l1, l2, s)
    p = k.b.mark(s.diagram, p)
    k.vx[s.diagram][s.end] = p
    if s.diagram == Diagram.VELOCITY:
        k.margins.append(sine)
    unit = _unit_of(s.diagram)
    return None, None, p, None, None, unit, angle, k.terms(lambda: (
        ("angle", angle, "deg"), (f"{k.names.pole}{s.end}", norm(p), unit)))


def _omega(k: Kernel, s: Step):
    L, P, Q = s.args
    r = k.r(P, Q)
    rel = k.of(s.diagram, Q) - k.of(s.diagram, P)
    w = angular_velocity(r, rel)
    k.omega[L] = w
    return None, None, None, None, w, "rad/s", None, k.terms(lambda: (
        (s.reads or f"{k.names.of(P)}{k.names.of(Q)}", norm(rel), "m/s"),
        (f"{P}{Q}", norm(r), "m"),
        (f"ω_{L}", w, "rad/s")))


def _alpha(k: Kernel, s: Step):
    L, P, X = s.args
    r = k.r(P, X)
    rel = k.of(s.diagram, X) - k.of(s.diagram, P)
    al = angular_acceleration(r, rel)
    k.alpha[L] = al
    return None, None, None, None, al, "rad/s^2", None, k.terms(lambda: (
        (s.reads or f"(a_{X})_{P}^t", np.abs(cross(r / norm(r), rel)), "m/s^2"),
        (f"{P}{X}", norm(r), "m"),
        (f"α_{L}", al, "rad/s^2")))


def _slider_value(k: Kernel, s: Step):
    (X,) = s.args
    e = k.const(k.scene.sliders[X].direction)
    val = dot(k.of(s.diagram, X), e)
    unit = _unit_of(s.diagram)
    return None, None, None, None, val, unit, None, k.terms(lambda: ((s.quantity, val, unit),))


def _slide_value(k: Kernel, s: Step):
    (A,) = s.args
    e, slot = k._slot_e(A)
    rel = k.of(s.diagram, A) - k.of(s.diagram, slot.coincident)
    if s.diagram == Diagram.VELOCITY:
        val = dot(rel, e)
        k.slide_v[A] = val
    else:
        val = dot(rel - k.cor[A], e)
        k.slide_a[A] = val
    unit = _unit_of(s.diagram)
    return None, None, None, None, val, unit, None, k.terms(lambda: ((s.quantity, val, unit),))


def _image(k: Kernel, s: Step):
    L, P, Q, X = s.args
    V, A = Diagram.VELOCITY, Diagram.ACCELERATION
    if L not in k.omega:
        k.omega[L] = angular_velocity(k.r(P, Q), k.of(V, Q) - k.of(V, P))
    r = k.r(P, X)
    if s.diagram == V:
        vec = relative_velocity(k.omega[L], r)
    else:
        if L not in k.alpha:
            k.alpha[L] = angular_acceleration(k.r(P, Q), k.of(A, Q) - k.of(A, P))
        vec = tangential(k.alpha[L], r) + centripetal(k.omega[L], r)
    unit = _unit_of(s.diagram)
    return k._vector(s, vec, unit, lambda: ((f"{s.start}{s.end}", norm(vec), unit),))


_OPS = {
    Op.CRANK_VELOCITY: _crank_velocity,
    Op.SLIDER_DRIVE: _slider_drive,
    Op.CENTRIPETAL: _centripetal,
    Op.CRANK_TANGENTIAL: _crank_tangential,
    Op.LINE_PERP: _line_perp,
    Op.LINE_ALONG: _line_along,
    Op.LINE_GUIDE: _line_guide,
    Op.LINE_SLOT: _line_slot,
    Op.LINE_SLIDE: _line_slide,
    Op.SLIDE_DRIVE: _slide_drive,
    Op.CORIOLIS_OFFSET_LINE: _coriolis_offset_line,
    Op.CORIOLIS: _coriolis,
    Op.JOIN: _join,
    Op.INTERSECT: _intersect,
    Op.OMEGA: _omega,
    Op.ALPHA: _alpha,
    Op.SLIDER_VELOCITY: _slider_value,
    Op.SLIDER_ACCELERATION: _slider_value,
    Op.SLIDE_VELOCITY: _slide_value,
    Op.SLIDE_ACCELERATION: _slide_value,
    Op.IMAGE: _image,
}


def terms_of(raw) -> tuple[Term, ...]:
    """Plain-float :class:`Term` records from a kernel result's raw terms (one position)."""
    return tuple(Term(sym, float(val), unit) for sym, val, unit in raw)
