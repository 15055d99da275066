"""The force answers: named quantities read off an :class:`~polygons.forces.states.Analysis`
(``Tin``, ``Rx(O,OA)``, ``N(B,OA)`` ... and every kinematic quantity of
:mod:`polygons.quantities`), sums of them, and the check of ``[[force_answers]]`` against the
tutorial's printed values and the exact ones (see README, "Forces")."""
from __future__ import annotations

import math
import string
from dataclasses import dataclass

import numpy as np

from .. import quantities as kq
from ..errors import PolygonsError, SceneError, UnitError, UnknownLabelError, suggest
from ..scene import Scene, unit_dimension
from ..units import UNITS
from ..loadmodel import ForceAnswer
from ..steps import percent_diff
from . import machine
from .model import (Inertia, centre, cross, perp, position as _pos, spring_state, unit_r)
from .cams import mu_needed
from .newton_euler import contact_force, section
from .states import Analysis, State

#: function -> (dimension, flips with positive = 'CW', arg count range)
FORCE_FUNCTIONS: dict[str, tuple[str, bool, tuple[int, int]]] = {
    "Tin": ("torque", True, (0, 0)), "Tin_vw": ("torque", True, (0, 0)),
    "Tout": ("torque", True, (0, 0)),
    "Rx": ("force", False, (2, 2)), "Ry": ("force", False, (2, 2)),
    "R": ("force", False, (2, 2)), "Rr": ("force", False, (2, 3)),
    "Rn": ("force", True, (2, 3)), "Rm": ("torque", True, (3, 3)),
    "Rg": ("force", False, (1, 1)), "Cg": ("torque", True, (1, 1)),
    "Gx": ("force", False, (1, 1)), "Gy": ("force", False, (1, 1)),
    "Fx": ("force", False, (1, 1)), "Fy": ("force", False, (1, 1)),
    "F": ("force", False, (1, 1)), "Fr": ("force", False, (2, 2)),
    "Fn": ("force", True, (2, 2)), "Fm": ("torque", True, (2, 2)),
    "Fs": ("force", True, (1, 1)), "ext": ("length", False, (1, 1)),
    "mass": ("mass", False, (1, 1)),
    "I": ("inertia", False, (1, 2)), "J": ("inertia", False, (1, 2)),
    "H": ("angular_momentum", True, (1, 1)),
    "aG": ("acceleration", False, (1, 1)), "aGx": ("acceleration", False, (1, 1)),
    "aGy": ("acceleration", False, (1, 1)), "aGr": ("acceleration", False, (1, 2)),
    "aGn": ("acceleration", True, (1, 2)),
    "maG": ("force", False, (1, 1)), "IGa": ("torque", True, (1, 1)),
    "Hdot": ("torque", True, (2, 2)),
    "N": ("force", False, (2, 2)), "S": ("force", True, (2, 2)), "M": ("torque", True, (2, 2)),
    "T": ("energy", False, (0, 0)), "V": ("energy", False, (0, 0)),
    "TR": ("torque", False, (0, 0)), "Ifw": ("inertia", False, (0, 0)),
    "Tturn": ("torque", False, (0, 0)), "alpha_fw": ("angular_acceleration", False, (0, 0)),
    "Tin_eta": ("torque", True, (0, 0)), "VR": ("fraction", False, (1, 1)),
    "MA": ("fraction", False, (1, 1)), "Tout_eta": ("torque", False, (1, 1)),
    "Fout_eta": ("force", False, (1, 1)),
    "Fc": ("force", False, (1, 1)), "phi": ("angle", False, (1, 1)),
    "Ff": ("force", False, (1, 1)), "mu": ("fraction", False, (1, 1)),
    "Fp": ("force", False, (1, 1)),
}
_KIN_FLIP = ("omega", "alpha")
_NAME = frozenset(string.ascii_letters + "_")


def _split_terms(expr: str) -> list[tuple[int, str]]:
    """'Rx(B,AB) + Rx(A,OA)' -> [(1, 'Rx(B,AB)'), (1, 'Rx(A,OA)')]."""
    terms, depth, start, sign = [], 0, 0, 1
    s = expr.strip()
    if s.startswith("-"):
        sign, s = -1, s[1:]
    for i, ch in enumerate(s):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif ch in "+-" and depth == 0 and i > start and s[i - 1] == " ":
            terms.append((sign, s[start:i].strip()))
            sign = 1 if ch == "+" else -1
            start = i + 1
    terms.append((sign, s[start:].strip()))
    return terms


def parse_call(term: str) -> tuple[str, list[str]]:
    """'Rx(B, AB)' -> ('Rx', ['B', 'AB']); 'Tin' -> ('Tin', [])."""
    name, paren, rest = term.strip().partition("(")
    name = name.strip()
    inner = rest[:-1] if rest.endswith(")") else None
    if (not name or not set(name) <= _NAME
            or (paren and (inner is None or "(" in inner or ")" in inner))):
        raise SceneError(f"cannot read quantity {term!r}")
    inner = (inner or "").strip()
    return name, [a.strip() for a in inner.split(",")] if inner else []


def _dimension_of(fn: str, args) -> str:
    if fn in FORCE_FUNCTIONS:
        return FORCE_FUNCTIONS[fn][0]
    return kq.dimension_of_quantity(f"{fn}({','.join(args)})")


def _ratio(expr: str) -> tuple[str, str] | None:
    """'Tout / Tin' -> ('Tout', 'Tin'): a ratio of two quantities (or sums), else None."""
    num, slash, den = expr.partition("/")
    return (num.strip(), den.strip()) if slash else None


def check_expr(expr: str, unit: str, scene: Scene, where: str) -> None:
    ratio = _ratio(expr)
    if ratio is not None:            # a ratio of two quantities of one kind: a pure number
        if "/" in ratio[1] or not all(ratio):
            raise SceneError(f"cannot read the ratio {expr!r}: write one quantity over another",
                             file=scene.file, where=where + ".quantity")
        from ..units import UNITS as _U
        si = {d: u for u, (d, f) in reversed(list(_U.items())) if f == 1.0}
        dims = []
        for part in ratio:
            fn = parse_call(_split_terms(part)[0][1])[0] if part else ""
            try:
                dims.append(_dimension_of(fn, parse_call(_split_terms(part)[0][1])[1]))
            except SceneError as exc:
                raise SceneError(exc.reason, file=scene.file, where=where + ".quantity") \
                    from None
        if dims[0] != dims[1]:
            raise SceneError(f"{expr!r}: a ratio of a {dims[0].replace('_', ' ')} to a "
                             f"{dims[1].replace('_', ' ')} has a unit; ask for a ratio of two "
                             f"quantities of one kind", file=scene.file,
                             where=where + ".quantity")
        for part in ratio:
            check_expr(part, si.get(dims[0], "-") if dims[0] != "fraction" else "-", scene,
                       where)
        if unit_dimension(unit) != "fraction":
            raise UnitError(f"{expr!r} is a ratio, a pure number: unit = \"-\"",
                            file=scene.file, where=where + ".unit")
        return
    dims = set()
    for _, term in _split_terms(expr):
        try:
            fn, args = parse_call(term)
            if fn in FORCE_FUNCTIONS:
                lo, hi = FORCE_FUNCTIONS[fn][2]
                if not lo <= len(args) <= hi:
                    raise SceneError(f"{fn} takes {lo if lo == hi else f'{lo} to {hi}'} "
                                     f"argument(s), got {len(args)} in {term!r}")
            elif fn not in kq.FUNCTIONS:
                raise SceneError(f"unknown quantity function {fn!r}: "
                                 f"{suggest(fn, list(FORCE_FUNCTIONS) + list(kq.FUNCTIONS))}")
            dims.add(_dimension_of(fn, args))
        except SceneError as exc:
            raise SceneError(exc.reason, file=scene.file, where=where + ".quantity") from None
    udim = unit_dimension(unit)
    for d in dims:
        ok = d == udim or (d == "torque" and udim == "force")   # a slider driver's 'Tin'
        if d == "angle" and udim == "angle":
            ok = True
        if not ok:
            raise UnitError(f"{expr!r} is a {d.replace('_', ' ')}, but the unit {unit!r} is a "
                            f"{udim.replace('_', ' ')}", file=scene.file, where=where + ".unit")


def to_unit(value: float, unit: str) -> float:
    """An SI value in ``unit`` ('-' and '1': a plain number)."""
    return value / UNITS[unit][1] if unit in UNITS else value


def force_quantity(an: Analysis, expr: str, state: str | None = None,
                   positive: int = 1) -> float:
    """The SI value of ``expr`` (see README, "Forces") at ``state``; ``positive`` = −1 takes
    normal components, moments, ω and α positive clockwise."""
    ratio = _ratio(expr)
    if ratio is not None:
        num, den = (force_quantity(an, part, state, positive) for part in ratio)
        if not abs(den) > 1e-12 * abs(num):
            raise SceneError(f"{ratio[1]} is zero at this instant: the ratio {expr!r} is not "
                             f"defined", file=an.model.scene.file)
        return num / den
    st = an.state(state)
    total = 0.0
    for sign, term in _split_terms(expr):
        total += sign * _term(an, st, term, positive)
    return total


def _term(an: Analysis, st: State, term: str, positive: int) -> float:
    model = an.model
    scene = model.scene
    file = scene.file
    fn, args = parse_call(term)
    if fn not in FORCE_FUNCTIONS:
        value = kq.quantity(st.sol, term)
        return value * positive if fn in _KIN_FLIP else value
    flip = positive if FORCE_FUNCTIONS[fn][1] else 1
    sol, ne = st.sol, st.ne

    def body(name):
        if name in model.bodies:
            return model.bodies[name]
        raise UnknownLabelError(f"unknown link or slider {name!r} in {term!r}: "
                                f"{suggest(name, model.bodies)}", file=file)

    def named(items, kind, name):
        for x in items:
            if x.name == name:
                return x
        raise UnknownLabelError(f"unknown {kind} {name!r} in {term!r}: "
                                f"{suggest(name, [x.name for x in items])}", file=file)

    def item(name):
        return named(model.masses, "mass", name)

    def point(label):
        if label not in sol.points:
            raise UnknownLabelError(f"unknown point {label!r} in {term!r}: "
                                    f"{suggest(label, sol.points)}", file=file)
        return _pos(sol, label)

    def applied(name):
        return named(model.forces, "force", name)

    def spring(name):
        return named(model.springs, "spring", name)

    def inert(name) -> Inertia:
        item(name)
        return next(i for i in st.inertia if i.item == name)

    if fn in ("Tin", "Tout", "Tin_vw"):
        if model.mode != "kinetostatic":
            raise SceneError(f"{fn} is the input torque a kinetostatic analysis finds; in mode "
                             f"{model.mode!r} the applied torques drive the mechanism",
                             file=file)
        v = st.vw_effort if fn == "Tin_vw" else ne.effort
        return flip * (-v if fn == "Tout" else v)
    if fn in ("Rx", "Ry", "R", "Rr", "Rn", "Rm"):
        lab, bname = args[0], args[1]
        point(lab)
        f = contact_force(model, ne, lab, body(bname).name)
        if fn == "Rx":
            return float(f[0])
        if fn == "Ry":
            return float(f[1])
        if fn == "R":
            return float(np.hypot(*f))
        if fn in ("Rr", "Rn"):
            fr = body(args[2] if len(args) > 2 else bname)
            u = unit_r(sol, fr)
            return float(f @ u) if fn == "Rr" else flip * float(f @ perp(u))
        return flip * cross(_pos(sol, lab) - point(args[2]), f)
    if fn in ("Rg", "Cg"):
        lab = args[0]
        if lab not in ne.guide:
            raise UnknownLabelError(f"{lab!r} is not a slider on a guide: "
                                    f"{suggest(lab, ne.guide)}", file=file)
        value, n, c = ne.guide[lab]
        return value if fn == "Rg" else flip * c
    if fn in ("Gx", "Gy"):
        lab = args[0]
        if lab not in ne.ground:
            raise UnknownLabelError(f"{lab!r} is not a fixed pivot with a link on it: "
                                    f"{suggest(lab, ne.ground)}", file=file)
        return float(ne.ground[lab][0 if fn == "Gx" else 1])
    if fn in ("Fx", "Fy", "F", "Fr", "Fn", "Fm"):
        f = applied(args[0])
        v = np.array(f.force)
        if fn == "Fx":
            return float(v[0])
        if fn == "Fy":
            return float(v[1])
        if fn == "F":
            return float(np.hypot(*v))
        if fn == "Fm":
            return flip * cross(_pos(sol, f.at) - point(args[1]), v)
        u = unit_r(sol, body(args[1]))
        return float(v @ u) if fn == "Fr" else flip * float(v @ perp(u))
    if fn in ("Fs", "ext"):
        s = spring(args[0])
        stt = spring_state(model, sol, s)
        if fn == "ext":
            if s.kind == "torsional":
                raise SceneError(f"{s.name} is torsional: its twist is not a length", file=file)
            return stt["extension"]
        return stt["tension"] if s.kind != "torsional" else flip * stt["torque"]
    if fn in ("Ff", "mu"):          # a rolling wheel's friction (along its surface) / μ needed
        if args[0] not in ne.rolling:
            raise UnknownLabelError(f"{args[0]!r} is not a wheel rolling on a fixed surface: "
                                    f"{suggest(args[0], ne.rolling)}", file=file)
        if fn == "Ff":
            return ne.rolling[args[0]][0]
        mu = mu_needed(args[0], ne)
        if mu is None:
            raise SceneError(f"the surface does not press on the wheel {args[0]} at this "
                             f"instant: no friction can keep it rolling", file=file)
        return mu
    if fn in ("Fc", "phi"):         # a cam's contact force (+ a push) / pressure angle
        c = next((c for c in st.contacts if c.label == args[0]), None)
        if c is None:
            raise UnknownLabelError(f"{args[0]!r} is not the follower's point of a [cams] or "
                                    f"[curved_slots] contact: "
                                    f"{suggest(args[0], [c.label for c in st.contacts])}",
                                    file=file)
        if fn == "phi":
            if c.pressure_angle is None:
                raise SceneError(f"the follower at {c.label} is at rest at this instant: its "
                                 f"pressure angle is not defined", file=file)
            return c.pressure_angle
        return c.push if c.push is not None else c.magnitude
    if fn == "Fp":      # the piston effort: what the piston hands its rod along the stroke
        return piston_effort(scene, ne, model, args[0], file)
    if fn == "mass":
        return item(args[0]).mass
    if fn == "I":
        it = item(args[0])
        i = it.inertia
        if len(args) > 1:
            i += it.mass * float(np.sum((centre(model, sol, it) - point(args[1])) ** 2))
        return i
    if fn == "J":
        b = body(args[0])
        items = [m for m in model.items_of(b.name)]
        mtot = sum(m.mass for m in items)
        if len(args) > 1:
            p = point(args[1])
        elif mtot:
            p = sum(m.mass * centre(model, sol, m) for m in items) / mtot
        else:
            p = _pos(sol, b.a)
        return sum((0.0 if m.free else m.inertia)
                   + m.mass * float(np.sum((centre(model, sol, m) - p) ** 2)) for m in items)
    if fn == "H":
        it = item(args[0])
        if not it.free or it.spin is None:
            raise SceneError(f"H({it.name}) is the spin momentum of a free disc (spin = ...)",
                             file=file)
        return flip * it.inertia * it.spin
    if fn in ("aG", "aGx", "aGy", "aGr", "aGn", "maG", "IGa"):
        i = inert(args[0])
        if fn == "aG":
            return float(np.hypot(*i.a))
        if fn == "aGx":
            return float(i.a[0])
        if fn == "aGy":
            return float(i.a[1])
        if fn == "maG":
            return float(np.hypot(*i.ma))
        if fn == "IGa":
            return flip * i.i_alpha
        u = unit_r(sol, body(args[1] if len(args) > 1 else i.body))
        return float(i.a @ u) if fn == "aGr" else flip * float(i.a @ perp(u))
    if fn == "Hdot":
        b = body(args[0])
        p = point(args[1])
        return flip * sum(i.i_alpha + cross(i.centre - p, i.ma) for i in st.inertia
                          if i.body == b.name)
    if fn in ("N", "S", "M"):
        n, s, m = section(model, st, args[0], args[1])
        return {"N": n, "S": flip * s, "M": flip * m}[fn]
    if fn in ("T", "V"):
        key = "kinetic" if fn == "T" else "potential"
        if key not in st.extra:
            raise SceneError(f"{fn} is reported for mode = 'release' states", file=file)
        return st.extra[key]
    if fn in ("TR", "Ifw", "Tturn", "alpha_fw"):
        if fn == "Ifw":
            return machine._flywheel(model).inertia
        if model.mode != "kinetostatic":
            raise SceneError(f"{fn} needs mode = 'kinetostatic' (the crank's ω as given)",
                             file=file)
        return {"TR": machine.resisting_torque, "Tturn": lambda m, s: machine.turning_moment(s),
                "alpha_fw": machine.flywheel_alpha}[fn](model, st)
    if fn == "Tin_eta":
        if model.mode != "kinetostatic":
            raise SceneError("Tin_eta is the input torque a kinetostatic analysis finds",
                             file=file)
        return flip * machine.input_with_efficiency(model, st)
    if fn in ("VR", "MA", "Tout_eta", "Fout_eta"):
        out = body(args[0])
        if fn == "VR":
            if out.kind == "block":
                raise SceneError(f"VR({out.name}): a slider's ratio has a unit (1/m); ask for "
                                 f"Fout_eta", file=file)
            return machine.velocity_ratio(model, st, out)
        if fn == "MA":
            return machine.mechanical_advantage(model, st, out)
        if (fn == "Fout_eta") != (out.kind == "block"):
            raise SceneError(f"{fn} is for {'a slider' if fn == 'Fout_eta' else 'a link'}; "
                             f"{out.name} is {'a slider' if out.kind == 'block' else 'a link'}",
                             file=file)
        return machine.output_effort(model, st, out)
    raise SceneError(f"unknown quantity {fn!r}", file=file)  # pragma: no cover


def piston_effort(scene, ne, model, lab: str, file) -> float:
    """F_P, the piston effort of the slider ``lab``: the net force along the line of stroke
    that the piston hands its connecting rod at the gudgeon pin (the gas force less the
    piston's inertia force, its weight and guide friction where given), signed along the
    guide's direction: the force of the pin on the rod, projected on the stroke."""
    sliding = scene.model.guide.get(lab)
    if sliding is None:
        raise UnknownLabelError(f"{lab!r} is not a slider on a fixed guide (a piston): "
                                f"{suggest(lab, scene.model.guide)}", file=file)
    rods = [n for n in scene.model.members.get(lab, ())
            if scene.model.body(n).kind in ("link", "lever")]
    if len(rods) != 1:
        raise SceneError(f"the piston effort at {lab} is the force on its connecting rod; "
                         f"{lab} carries {len(rods)} links ({', '.join(rods) or 'none'})",
                         file=file)
    f = contact_force(model, ne, lab, rods[0])
    return float(np.asarray(f) @ np.asarray(sliding.line.direction))


@dataclass(frozen=True)
class ForceCheck:
    answer: ForceAnswer
    ours: float          # in answer.unit, signed (in the answer's positive sense)
    compared: float
    diff_pct: float | None
    within: bool | None
    exact_rel: float | None


def _scale(an: Analysis) -> float:
    """A force scale for 'zero' answers: the largest load or inertia force of the first state."""
    st = an.states[0]
    mags = [float(np.hypot(*ld.force)) for ld in st.ne.loads]
    mags += [float(np.hypot(*i.ma)) for i in st.inertia]
    return max(mags + [1.0])


def check_force_answers(an: Analysis) -> list[ForceCheck]:
    out = []
    for ans in an.model.answers:
        try:
            value = force_quantity(an, ans.quantity, ans.state, ans.positive)
        except PolygonsError as exc:
            raise exc.located(file=an.model.scene.file, where="force_answers") from None
        ours = to_unit(value, ans.unit)
        compared = abs(ours) if ans.mode == "abs" else ours
        diff = within = rel = None
        if ans.tutorial is not None:
            diff = percent_diff(ans.tutorial, compared) if ans.tutorial != 0.0 else None
            if ans.tutorial == 0.0:
                within = abs(compared) <= 1e-9 * max(1.0, _scale(an))
            else:                      # (an infinite value is never within: inf <= inf)
                within = math.isfinite(compared) and abs(ans.tutorial - compared) <= \
                    ans.tolerance * max(abs(ans.tutorial), abs(compared))
        if ans.exact is not None:
            rel = abs(compared - ans.exact) / abs(ans.exact) if ans.exact else abs(compared)
            rel = rel if math.isfinite(rel) else None     # a subnormal exact value: no ratio
        out.append(ForceCheck(ans, ours, compared, diff, within, rel))
    return out
