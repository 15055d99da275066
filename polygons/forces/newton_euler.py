"""Newton–Euler: every body's F = m a_G and M = I_G α + r × m a_G, one linear solve.

Three equations per moving body (links, slotted levers, slider blocks); the unknowns are the
pin forces, the guide and slot normal forces, the guide couples and the input torque (or,
torque-driven, the input's angular acceleration: the acceleration polygon is affine in it, so
two kinematic solutions, at α = 0 and α = 1, give its column).  Also the internal forces at a
section of a uniform rod (:func:`section`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import UnknownLabelError, UnsupportedError, suggest
from ..evaluate import Solution
from ..scene import Crank
from . import effort
from .model import (ForceModel, Load, body_alpha, centre, cross, image, inertias, loads, perp,
                    position as _pos, unit_r, wheel)


@dataclass
class NEResult:
    """Newton–Euler at one state."""
    names: list[str]                  # the unknowns, in words
    keys: list[str]                   # the unknowns, as identifiers (pin_O_on_OA_x, ...)
    values: np.ndarray
    pin: dict                         # (label, body) -> force on body at label (from the pin)
    ground: dict                      # label -> force on the ground at the pin
    slot: dict                        # pin -> (signed normal force on the lever, unit normal)
    guide: dict                       # label -> (normal force on block, unit normal, couple)
    effort: float | None              # input torque (crank) / force (slider) — kinetostatic
    alpha: float | None               # torque-driven: the input's angular (or linear) accel.
    loads: list[Load]
    residual: float
    equations: int
    #: a wheel rolling on a fixed surface: label -> (friction on the wheel along the surface,
    #: the surface's direction, the contact point)
    rolling: dict = field(default_factory=dict)


def newton_euler(model: ForceModel, sol: Solution, vsol: Solution, sol1: Solution | None = None,
                 motion: int | None = None, lds: list[Load] | None = None) -> NEResult:
    """Solve every body's F = m a_G and M = I_G α + r × m a_G at once.

    Kinetostatic (``sol1`` None): the input torque is the last unknown.  Torque-driven: ``sol``
    is the kinematic solution with the input's α = 0 and ``sol1`` with α = 1; the unknown is α.
    """
    scene = model.scene
    bodies = model.bodies
    order = list(bodies)
    idx = {n: i for i, n in enumerate(order)}
    ref = {n: _pos(sol, bodies[n].a) for n in order}
    cols: list[str] = []
    keys: list[str] = []
    neq = 3 * len(order)
    entries: list[tuple[int, int, float]] = []

    def col(key, name):
        keys.append(key)
        cols.append(name)
        return len(cols) - 1

    def add_force(c, body, r, f):
        i = 3 * idx[body]
        entries.append((i, c, f[0]))
        entries.append((i + 1, c, f[1]))
        entries.append((i + 2, c, cross(r - ref[body], f)))

    def add_couple(c, body, m):
        entries.append((3 * idx[body] + 2, c, m))

    ex, ey = np.array([1.0, 0.0]), np.array([0.0, 1.0])
    pin_cols = []
    for j in model.joints:
        r = _pos(sol, j.label)
        free = j.members if j.ground else j.members[:-1]
        cs = []
        for m in free:
            cx = col(f"pin_{j.label}_on_{m}_x", f"pin {j.label} on {m}, x")
            cy = col(f"pin_{j.label}_on_{m}_y", f"pin {j.label} on {m}, y")
            add_force(cx, m, r, ex)
            add_force(cy, m, r, ey)
            if not j.ground:
                add_force(cx, j.members[-1], r, -ex)
                add_force(cy, j.members[-1], r, -ey)
            cs.append((m, cx, cy))
        pin_cols.append((j, cs))
    slot_cols = []
    for s in model.slots:
        rp = _pos(sol, s.pin)
        u = (np.array(s.direction) if s.direction else
             _pos(sol, s.far) - _pos(sol, s.pivot) if s.far else rp - _pos(sol, s.pivot))
        n = perp(u / float(np.hypot(*u)))
        c = col(f"slot_{s.pin}_on_{s.lever}", f"slot force on {s.lever} at {s.pin} (⟂ slot)")
        add_force(c, s.lever, rp, n)
        add_force(c, s.carrier, rp, -n)
        slot_cols.append((s, c, n))
    guide_cols, roll_cols = [], []
    for lab in model.guides:
        n = perp(np.array(scene.model.guide[lab].line.direction))
        r = _pos(sol, lab)
        q = wheel(sol, bodies[lab])
        cn = col(f"guide_force_{lab}", f"guide force on {lab} (⟂ guide)" if q is None else
                 f"normal force of the surface on the wheel {lab}")
        add_force(cn, lab, r, n)
        if q is not None:       # a rolling wheel turns: friction at the contact, no couple
            e = np.array((math.cos(q.face), math.sin(q.face)))     # along the surface
            contact = r - q.radius * perp(e)        # (the wheel above its surface's left)
            cf = col(f"friction_{lab}", f"friction on the wheel {lab} at its contact (along "
                                        f"the surface)")
            add_force(cf, lab, contact, e)
            roll_cols.append((lab, cf, e, contact))
            guide_cols.append((lab, cn, None, n))
            continue
        cm = col(f"guide_couple_{lab}", f"guide couple on {lab}")
        add_couple(cm, lab, 1.0)
        guide_cols.append((lab, cn, cm, n))
    drv = scene.driver
    cdrv = col(effort.key(model), effort.words(model))
    lds = loads(model, sol, vsol, motion) if lds is None else lds

    def inertia_rhs(s: Solution) -> np.ndarray:
        out = np.zeros(neq)
        for it in inertias(model, s):
            i = 3 * idx[it.body]
            out[i:i + 2] += it.ma
            out[i + 2] += it.i_alpha + cross(it.centre - ref[it.body], it.ma)
        return out

    rhs = inertia_rhs(sol)
    for ld in lds:
        i = 3 * idx[ld.body]
        rhs[i:i + 2] -= ld.force
        if ld.pos is not None:
            rhs[i + 2] -= cross(ld.pos - ref[ld.body], ld.force)
        rhs[i + 2] -= ld.couple
    if sol1 is None:
        for t in effort.terms(model, sol):      # the driver's, or [dynamics] effort's
            if t.couple:
                add_couple(cdrv, t.body, t.couple)
            if t.pos is not None:
                add_force(cdrv, t.body, t.pos, t.direction)
    else:
        cols[cdrv] = ("input angular acceleration" if isinstance(drv, Crank)
                      else "input acceleration")
        keys[cdrv] = "input_alpha" if isinstance(drv, Crank) else "input_acceleration"
    A = np.zeros((neq, len(cols)))
    for i, c, v in entries:
        A[i, c] += v
    if sol1 is not None:
        A[:, cdrv] = -(inertia_rhs(sol1) - inertia_rhs(sol))
    if A.shape[0] != A.shape[1]:
        raise UnsupportedError(
            f"the force analysis has {A.shape[0]} equations (3 per moving body: "
            f"{', '.join(order)}) but {A.shape[1]} unknowns ({'; '.join(cols)}): the mechanism "
            f"is not a single closed chain this module can resolve", file=scene.file)
    scale = np.abs(A).max(axis=0)
    scale[scale == 0] = 1.0
    As = A / scale
    sv = np.linalg.svd(As, compute_uv=False)
    if sv[-1] <= 1e-11 * sv[0]:
        raise UnsupportedError(
            "the force equations are singular at this position (a toggle, or a body the "
            "unknowns cannot hold): the reactions are not determined", file=scene.file)
    x = np.linalg.solve(As, rhs) / scale
    residual = float(np.abs(A @ x - rhs).max())
    pin, ground = {}, {}
    for j, cs in pin_cols:
        total = np.zeros(2)
        for m, cx, cy in cs:
            f = np.array([x[cx], x[cy]])
            pin[(j.label, m)] = f
            total += f
        if j.ground:
            ground[j.label] = -total
        else:
            pin[(j.label, j.members[-1])] = -total
    slot = {s.pin: (float(x[c]), n) for s, c, n in slot_cols}
    guide = {lab: (float(x[cn]), n, 0.0 if cm is None else float(x[cm]))
             for lab, cn, cm, n in guide_cols}
    rolling = {lab: (float(x[cf]), e, contact) for lab, cf, e, contact in roll_cols}
    return NEResult(cols, keys, x, pin, ground, slot, guide,
                    None if sol1 is not None else float(x[cdrv]),
                    float(x[cdrv]) if sol1 is not None else None, lds, residual, neq, rolling)


def contact_force(model: ForceModel, ne: NEResult, label: str, body: str) -> np.ndarray:
    """The force on ``body`` at ``label`` from what it is joined to there (pins and slots)."""
    f = np.zeros(2)
    found = False
    if (label, body) in ne.pin:
        f = f + ne.pin[(label, body)]
        found = True
    for s in model.slots:
        labs = {s.pin}
        if s.lever == body and s.coincident is not None:
            labs.add(s.coincident)
        if label in labs and body in (s.lever, s.carrier):
            value, n = ne.slot[s.pin]
            f = f + (value * n if body == s.lever else -value * n)
            found = True
    if not found:
        if body not in model.bodies:
            raise UnknownLabelError(f"unknown body {body!r}: {suggest(body, model.bodies)}",
                                    file=model.scene.file)
        raise UnknownLabelError(f"{body} is not joined to anything at {label!r} (its joints: "
                                f"{', '.join(_joint_labels(model, body)) or 'none'})",
                                file=model.scene.file)
    return f


def _joint_labels(model, body) -> list[str]:
    out = [j.label for j in model.joints if body in j.members]
    for s in model.slots:
        if body in (s.lever, s.carrier):
            out.append(s.pin)
    return out


def section(model: ForceModel, st, label: str, link: str) -> tuple[float, float, float]:
    """Internal normal force N, shear S and bending moment M at the section ``label`` of
    ``link``: the force and moment on the part from the link's first label to the section,
    exerted by the rest.  N along the link (first → second label), S along k × that, M CCW."""
    scene = model.scene
    if link not in model.bodies or model.bodies[link].kind != "link":
        raise UnknownLabelError(f"unknown link {link!r}: "
                                f"{suggest(link, [b for b in model.bodies if model.bodies[b].kind == 'link'])}",
                                file=scene.file)
    body = model.bodies[link]
    if label not in body.labels:
        raise UnknownLabelError(f"{label!r} is not a point of {link}; declare it with "
                                f"[points.{label}] on = \"{link}\"", file=scene.file)
    sol, ne = st.sol, st.ne
    items = model.items_of(link)
    for it in items:
        if it.kind == "link" and not it.rod:
            raise UnsupportedError(f"section forces need {link}'s mass spread as a uniform rod "
                                   f"(inertia = \"rod\")", file=scene.file)
    pa = _pos(sol, body.a)
    u = unit_r(sol, body)
    n = perp(u)
    rx = _pos(sol, label)
    s_x = float((rx - pa) @ u)
    length = body.length

    def inside(lab) -> bool:
        s = float((_pos(sol, lab) - pa) @ u)
        return s < s_x - 1e-12 * max(1.0, abs(s_x))

    F = np.zeros(2)
    M = 0.0
    # contact forces at the labels of the inner part
    for lab in body.labels:
        if not inside(lab):
            continue
        try:
            f = contact_force(model, ne, lab, link)
        except UnknownLabelError:
            continue
        F += f
        M += cross(_pos(sol, lab) - rx, f)
    # loads: forces at labels, couples at pins (a couple with no location cannot be placed)
    for ld in ne.loads:
        if ld.body != link:
            continue
        if ld.kind == "gravity":
            it = next(m for m in model.masses if m.name == ld.item)
            if it.kind == "link":
                continue                       # the rod's own weight is spread: below
            if not inside(it.at):
                continue
        elif ld.at is None:
            if ld.couple:
                raise UnsupportedError(f"{ld.source} acts on {link} with no point: give it "
                                       f"at = LABEL to cut {link} at {label}", file=scene.file)
            continue
        elif not inside(ld.at):
            continue
        F += ld.force
        if ld.pos is not None:
            M += cross(ld.pos - rx, ld.force)
        M += ld.couple
    for t in (effort.terms(model, sol) if ne.effort else ()):
        if t.body != link:
            continue
        if t.pos is not None and float((t.pos - pa) @ u) < s_x - 1e-12 * max(1.0, abs(s_x)):
            F += ne.effort * t.direction
            M += cross(t.pos - rx, ne.effort * t.direction)
        if t.couple:
            drv = scene.driver
            if not (isinstance(drv, Crank) and drv.link == link):
                raise UnsupportedError(f"the effort couple on {link} has no point: {link} "
                                       f"cannot be cut at {label}", file=scene.file)
            if inside(drv.pivot):
                M += ne.effort * t.couple
    # inertia of the inner part
    need_f = np.zeros(2)
    need_m = 0.0
    al = body_alpha(sol, body)
    for it in items:
        if it.kind == "link":
            frac = s_x / length
            m = it.mass * frac
            g_pos = pa + 0.5 * s_x * u
            a = image(sol, body, g_pos, "acceleration")
            i_g = m * s_x * s_x / 12.0
            F += m * model.gravity
            M += cross(g_pos - rx, m * model.gravity)
            need_f += m * a
            need_m += i_g * al + cross(g_pos - rx, m * a)
        elif inside(it.at):
            g_pos = centre(model, sol, it)
            a = image(sol, body, g_pos, "acceleration")
            need_f += it.mass * a
            need_m += (0.0 if it.free else it.inertia * al) + cross(g_pos - rx, it.mass * a)
    f_int = need_f - F
    m_int = need_m - M
    return float(f_int @ u), float(f_int @ n), float(m_int)
