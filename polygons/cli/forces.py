"""``polygons forces CASE.toml``: inertia forces, the input torque, every pin reaction.

``polygons solve`` appends the same results (:func:`forces_table`, or a ``"forces"`` key made
by :func:`to_dict` in its JSON) when the scene has masses or loads.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import PolygonsError, SceneError
from ..forces import (Analysis, State, analyse, check_force_answers, has_forces, section,
                      spring_state)
from ..forces import effort, machine
from ..forces import words as force_words
from ..forces.cams import mu_needed, rolling_words, words as cam_words
from ..forces.model import position, unit_r
from ..report import json_text, undefined_note
from . import _graphical
from ._output import add_out_option, emit
from ..scene import Crank, load_scene
from ..theorems import perp


def register(sub) -> None:
    p = sub.add_parser("forces", help="forces: inertia forces, input torque, pin reactions, "
                                      "torque-driven and released motion",
                       description="Force analysis of a scene with [masses], [forces], "
                                   "[torques], [springs], [gravity] and [dynamics] tables: "
                                   "table, or JSON with --json.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--json", action="store_true", help="print a JSON object instead of a table")
    add_out_option(p)
    p.add_argument("--svg", metavar="DIR", help="also write a free-body diagram and a force "
                                               "polygon (SVG) per body and state to DIR")
    p.add_argument("--cycle", type=int, metavar="N",
                   help="the turning-moment diagram instead: the input torque at N crank "
                        "angles round the turn (4 to 3600), its mean and the maximum "
                        "fluctuation of energy; with --svg, its plot")
    p.add_argument("--fluctuation", metavar="CS",
                   help="with --cycle: the coefficient of fluctuation of speed ('2 %%' or "
                        "0.02; from 1e-6 up to, not including, 1), for the flywheel's inertia "
                        "I = ΔE / (ω² C_s)")
    p.add_argument("--long", action="store_true",
                   help="with --cycle: run a turning-moment diagram estimated above the work "
                        "budget (N × (3 × moving bodies)³ > 2e10, about 25 s here) anyway")
    p.set_defaults(func=run)


def run(args) -> int:
    scene = load_scene(args.scene)
    if not has_forces(scene) and scene.loads.efficiency is None \
            and scene.loads.flywheel is None:
        raise SceneError("this scene has no [masses], [forces], [torques], [springs], "
                         "[efficiency] or [flywheel]: there is nothing for a force analysis "
                         "to do", file=scene.file)
    if args.cycle is not None or args.fluctuation is not None:
        return _run_cycle(args, scene)
    an = analyse(scene)
    paths = []
    if args.svg:
        from diagrams.fbd import write
        from diagrams.forcepoly import write as write_graphical
        paths = write(an, args.svg) + write_graphical(an, args.svg)
    text = json_text(to_dict(an)) if args.json else forces_table(an)
    if paths and not args.json:
        text += f"\ndiagrams: {len(paths)} SVG files in {args.svg}\n"
    emit(text, args.out)
    return 0




# ---------------------------------------------------------------- words
def _sense(x: float) -> str:
    if x == 0.0 or abs(x) < 1e-300:
        return ""
    return "CCW" if x > 0 else "CW"


def _deg(v) -> float | None:
    if float(np.hypot(*v)) == 0.0:
        return None
    return math.degrees(math.atan2(v[1], v[0])) % 360.0


def _g(x, digits=6) -> str:
    if x is None:
        return "-"
    if x == 0:
        return "0"
    return f"{x:.{digits}g}"


def _mode_words(an: Analysis) -> str:
    m = an.model.mode
    if m == "kinetostatic":
        return (f"kinetostatic: the driver's motion is given; the "
                f"{effort.words(an.model).removeprefix('effort: ')} that keeps it is found")
    if m == "torque-driven":
        return ("torque-driven: the driver's ω is given, its α follows from the applied "
                "torques (acceleration polygon affine in α: solved at α = 0 and α = 1)")
    return ("released: no motor; α from the loads at each state, ω from energy (checked by "
            "RK4 integration)")


def _effort_unit(an: Analysis) -> str:
    return effort.unit(an.model)


def _effort_value(an: Analysis, st: State, e: float) -> str:
    """An effort in words (the one formatter, :func:`polygons.forces.words.effort_words`): a
    torque with its sense; a force with its direction (a force has no rotation sense), an
    actuator's as pushing or pulling."""
    return force_words.effort_words(an.model, e, st.sol)


def _machine_text(an: Analysis, st: State, m: dict) -> str:
    """A machine result's value in words, each signed one once with its sense: the turning
    moment in or against the sense of rotation, a piston effort towards its direction, the
    flywheel speeding up or slowing down."""
    v, key = m["value"], m["key"]
    if key == "turning_moment":
        drv = an.model.scene.driver
        w = st.sol.links[drv.link].omega or 0.0
        return force_words.rotation_words(v, w)
    if key.startswith("piston_effort_") and v:
        u = np.array(an.model.scene.model.guide[key.removeprefix("piston_effort_")]
                     .line.direction)
        return f"{abs(v):.8g} N towards {force_words.angle(u * v)}° (along the guide)"
    if key == "flywheel_alpha" and v:
        return f"{abs(v):.8g} rad/s² ({'speeding up' if v > 0 else 'slowing down'})"
    return f"{v:.8g} {m['unit']}".replace("-", "−")


# ---------------------------------------------------------------- JSON
def _vec(v) -> list[float]:
    return [float(v[0]), float(v[1])]


def _state_dict(an: Analysis, st: State) -> dict:
    model = an.model
    ne = st.ne
    drv = st.sol.scene.driver
    out: dict = {"name": st.name}
    if isinstance(drv, Crank):
        out["driver"] = {"link": drv.link, "angle_deg": math.degrees(drv.angle),
                         "omega": st.sol.links[drv.link].omega,
                         "alpha": st.sol.links[drv.link].alpha}
    else:
        out["driver"] = {"slider": drv.point, "velocity": st.sol.slides[drv.point].velocity,
                         "acceleration": st.sol.slides[drv.point].acceleration}
    if model.mode == "kinetostatic":
        out["input"] = {"newton_euler": ne.effort, "virtual_work": st.vw_effort,
                        "unit": _effort_unit(an), "key": effort.key(model),
                        "words": effort.words(model),
                        "sense": _sense(ne.effort) if effort.is_torque(model) else None,
                        "turning_moment": (-ne.effort if effort.is_torque(model)
                                           and model.parsed.effort is None else None),
                        "breakdown": _shares(st)}
    else:
        out["alpha_in"] = ne.alpha
        out["virtual_work_residual"] = st.vw_effort
        out["breakdown"] = _shares(st)
    out["inertia"] = [{"item": i.item, "body": i.body, "centre": _vec(i.centre),
                       "a_G": _vec(i.a), "m_a_G": _vec(i.ma),
                       "inertia_force": _vec(-i.ma), "I_G_alpha": i.i_alpha,
                       "inertia_torque": -i.i_alpha}
                      for i in st.inertia]
    pins = []
    for (lab, body), f in ne.pin.items():
        pins.append({"key": f"pin_{lab}_on_{body}", "pin": lab, "on": body, "force": _vec(f),
                     "magnitude": float(np.hypot(*f)), "direction_deg": _deg(f),
                     "components": _components(an, st, lab, body, f)})
    out["pins"] = pins
    out["ground"] = [{"pin": lab, "force_on_ground": _vec(f)} for lab, f in ne.ground.items()]
    out["slots"] = [{"pin": pin, "normal_force_on_lever": v, "normal": _vec(n)}
                    for pin, (v, n) in ne.slot.items()]
    out["guides"] = [{"slider": lab, "normal_force": v, "normal": _vec(n), "couple": c}
                     for lab, (v, n, c) in ne.guide.items()]
    out["rolling_contacts"] = [
        {"wheel": lab, "friction": f, "along": _vec(e), "contact_point": _vec(at),
         "normal_force": ne.guide[lab][0], "mu_needed": mu_needed(lab, ne)}
        for lab, (f, e, at) in ne.rolling.items()]
    out["cam_contacts"] = [
        {"at": c.label, "kind": c.kind, "cam": c.cam, "follower": c.follower,
         "force_on_follower": _vec(c.force), "magnitude": c.magnitude,
         "direction_deg": _deg(c.force), "push": c.push, "contact_lost": c.lost,
         "contact_point": None if c.contact is None else _vec(c.contact),
         "pressure_angle_deg": (None if c.pressure_angle is None
                                else math.degrees(c.pressure_angle)), "via": c.via}
        for c in st.contacts]
    out["springs"] = []
    for s in model.springs:
        stt = spring_state(model, st.sol, s)
        out["springs"].append({k: (float(v) if not isinstance(v, np.ndarray) else _vec(v))
                               for k, v in stt.items()} | {"name": s.name, "kind": s.kind})
    out["loads"] = [{"source": ld.source, "kind": ld.kind, "on": ld.body, "at": ld.at,
                     "force": _vec(ld.force), "couple": ld.couple} for ld in ne.loads]
    out["sections"] = [{"section": lab, "link": link, "N": n, "S": s, "M": m}
                       for lab, link, n, s, m in _sections(an, st)]
    for k in ("kinetic", "potential", "work_nc", "omega_energy", "omega_ode", "time",
              "energy_vs_ode_rel"):
        if k in st.extra:
            out.setdefault("energy", {})[k] = float(st.extra[k])
    out["newton_euler_residual"] = ne.residual
    out["warnings"] = list(st.warnings)
    out["unknowns"] = [{"key": k, "words": name, "value": float(x)}
                       for k, name, x in zip(ne.keys, ne.names, ne.values)]
    machine_results = _machine(an, st)
    if machine_results:
        out["machine"] = machine_results
    out["force_polygons"] = _graphical.polygons_dict(an, st)
    out["zhukovsky"] = _graphical.lever_dict(an, st)
    return out


def _shares(st: State) -> list[dict]:
    return [{"key": t.key, "words": t.words, "value": t.value} for t in st.breakdown]


def _components(an: Analysis, st: State, lab: str, body: str, f) -> list[dict]:
    """The pin force on ``body`` along and across it (a slider block: its guide); at the crank
    pin, on the crank, also radial (outwards) and tangential (in the sense of rotation)."""
    model, sol = an.model, st.sol
    b = model.bodies[body]
    f = np.asarray(f)
    if b.kind == "link":
        u = unit_r(sol, b)
        out = [{"key": f"{body}_along", "words": f"component along {body} (from {b.a} to "
                f"{b.b})", "value": float(f @ u)},
               {"key": f"{body}_across", "words": f"component across {body} (90° CCW from "
                f"{b.a}→{b.b})", "value": float(f @ perp(u))}]
    else:
        u = np.array(model.scene.model.guide[body].line.direction)
        out = [{"key": f"{body}_along_guide", "words": f"component along the guide of {body} "
                f"(towards {_deg(u):.6g}°)", "value": float(f @ u)},
               {"key": f"{body}_across_guide", "words": f"component across the guide of "
                f"{body} (90° CCW of it)", "value": float(f @ perp(u))}]
    drv = sol.scene.driver
    if isinstance(drv, Crank) and body == drv.link and lab == drv.tip:
        radial = position(sol, drv.tip) - position(sol, drv.pivot)
        radial = radial / float(np.hypot(*radial))
        w = sol.links[drv.link].omega or 0.0
        tangential = perp(radial) * (1.0 if w >= 0 else -1.0)
        out += [{"key": "crank_radial", "words": f"radial component at the crank pin {lab} "
                 f"(along {drv.pivot}→{lab}, outwards)", "value": float(f @ radial)},
                {"key": "crank_tangential", "words": f"tangential component at the crank pin "
                 f"{lab} (in the sense of rotation, {_sense(w) or 'CCW'})",
                 "value": float(f @ tangential)}]
    return out


def _machine(an: Analysis, st: State) -> list[dict]:
    """The flywheel and efficiency results of one state, each with an identifier key."""
    model = an.model
    out = []

    def add(key, words, value, unit):
        out.append({"key": key, "words": words, "value": value, "unit": unit})
    kinetostatic_crank = (model.mode == "kinetostatic" and isinstance(model.scene.driver, Crank)
                          and model.parsed.effort is None)
    if kinetostatic_crank:                 # with or without a flywheel
        add("turning_moment", "turning moment T on the crank, in the sense of rotation",
            machine.turning_moment(st), "N m")
    if kinetostatic_crank:                 # each loaded piston on its rod: its effort F_P
        from ..forces.answers import piston_effort
        loaded = {x.at for x in model.parsed.forces} | {
            m.at if m.at else model.bodies[m.body].a for m in model.parsed.masses
            if m.kind in ("block", "point") and (m.at or m.body in model.bodies)}
        for lab in model.scene.model.guide:
            if lab in loaded:
                try:
                    value = piston_effort(model.scene, st.ne, model, lab, model.scene.file)
                except SceneError:         # not a piston on one rod
                    continue
                add(f"piston_effort_{lab}", f"piston effort F_P at {lab} (the net force along "
                    f"the line of stroke on the rod, + along the guide)", value, "N")
    if model.parsed.flywheel is not None and model.mode == "kinetostatic":
        fw = model.parsed.flywheel
        add("resisting_torque", "resisting torque T_R (= P/ω)" if fw.power is not None
            else "resisting torque T_R (given)", machine.resisting_torque(model, st), "N m")
        add("flywheel_inertia", f"flywheel I ({fw.how})", fw.inertia, "kg m^2")
        add("flywheel_alpha", "flywheel angular acceleration (T − T_R)/I (positive: speeding "
            "up)", machine.flywheel_alpha(model, st), "rad/s^2")
    eff = model.parsed.efficiency
    if eff is not None:
        add("efficiency", "efficiency η", eff.eta, "-")
        if model.mode == "kinetostatic" and model.parsed.active:
            add("input_with_efficiency", "input effort with the losses (T_in/η when driving)",
                machine.input_with_efficiency(model, st), _effort_unit(an))
        _outputs(an, st, add)
    return out


def output_bodies(model) -> list[str]:
    """The mechanism's outputs, for the machine results an efficiency gives unasked: the
    bodies carrying a stated torque or force (the load), else the bodies pivoted on the frame
    and the slider blocks — every one but the driver's."""
    drv = model.parsed.driver_body
    loaded = [x.body for x in (*model.parsed.torques, *model.parsed.forces)]
    if not loaded:
        loaded = [m for j in model.parsed.joints if j.ground for m in j.members]
        loaded += [n for n, b in model.bodies.items() if b.kind == "block"]
    out: list[str] = []
    for name in loaded:
        if name != drv and name in model.bodies and name not in out:
            out.append(name)
    return out


def _outputs(an: Analysis, st: State, add) -> None:
    """Velocity ratio, mechanical advantage and the output effort that the [efficiency]
    table's input gives, for each output body (:func:`output_bodies`)."""
    model = an.model
    eff = model.parsed.efficiency
    crank = isinstance(model.scene.driver, Crank)
    for name in output_bodies(model):
        out = model.bodies[name]
        try:
            vr = machine.velocity_ratio(model, st, out)
        except SceneError:          # the output is at rest at this instant
            add(f"velocity_ratio_{name}", f"velocity ratio: {name} is at rest at this instant",
                None, "-")
            continue
        block = out.kind == "block"
        drv = model.scene.driver
        rate_in = f"ω_{drv.link}" if crank else f"v_{drv.point}"
        rate_out = f"v_{name}" if block else f"ω_{name}"
        vr_unit = "-" if crank != block else ("1/m" if block else "m")
        add(f"velocity_ratio_{name}", f"velocity ratio {rate_in}/{rate_out}", vr, vr_unit)
        if vr_unit == "-" and not block:
            add(f"mechanical_advantage_{name}", f"mechanical advantage η {rate_in}/{rate_out} "
                f"(output torque per input torque)", machine.mechanical_advantage(model, st, out),
                "-")
        if eff.input_effort is not None:
            what = "force on" if block else "torque on"
            add(f"output_{'force' if block else 'torque'}_{name}",
                f"output {what} {name} from the input {_g(eff.input_effort)} {_effort_unit(an)}"
                f" with the losses (η × input × ratio)", machine.output_effort(model, st, out),
                "N" if block else "N m")


def to_dict(an: Analysis) -> dict:
    model = an.model
    scene = model.scene
    masses = [{"name": m.name, "body": m.body, "kind": m.kind, "mass": m.mass,
               "inertia": m.inertia, "inertia_from": m.how, "free": m.free, "spin": m.spin}
              for m in model.masses]
    answers = []
    for c in check_force_answers(an):
        a = c.answer
        answers.append({"quantity": a.quantity, "state": a.state, "desc": a.desc,
                        "unit": a.unit, "positive": "CW" if a.positive < 0 else "CCW",
                        "ours": c.ours, "tutorial": a.tutorial, "exact": a.exact,
                        "tutorial_diff_pct": c.diff_pct, "tutorial_within_tolerance": c.within,
                        "tolerance_pct": a.tolerance * 100.0, "slip": a.slip, "note": a.note})
    return {
        "case": {"file": scene.file, "title": scene.title, "id": scene.source.get("id")},
        "mode": model.mode,
        "units": {"force": "N", "torque": "N m (CCW positive)", "angles": "deg CCW from +x"},
        "gravity": _vec(model.gravity),
        "masses": masses,
        "states": [_state_dict(an, st) for st in an.states],
        "dynamics": an.dynamics,
        "answers": answers,
    }


# ---------------------------------------------------------------- table
def _sections(an: Analysis, st: State):
    """N, S, M at the labelled points of rod links that carry no load or joint."""
    model = an.model
    out = []
    loaded = {ld.at for ld in st.ne.loads if ld.at} | {j.label for j in model.joints}
    loaded |= {s.pin for s in model.slots}
    spec = model.parsed.effort
    loaded |= {lab for lab, _ in spec.ends} if spec is not None and spec.kind == "actuator" \
        else set()
    for name, body in model.bodies.items():
        items = model.items_of(name)
        if body.kind != "link" or not items or any(i.kind == "link" and not i.rod
                                                    for i in items):
            continue
        for lab in body.labels:
            if lab in (body.a, body.b) or lab in loaded:
                continue
            if lab not in model.scene.model.points:
                continue
            try:
                n, s, m = section(model, st, lab, name)
            except PolygonsError:
                continue
            out.append((lab, name, n, s, m))
    return out


def forces_table(an: Analysis, header: bool = True) -> str:
    model = an.model
    scene = model.scene
    lines = []
    if header:
        lines += [scene.title, f"  scene: {scene.file}"
                  + (f"   [{scene.source['id']}]" if scene.source.get("id") else ""), ""]
    lines.append(f"forces — {_mode_words(an)}")
    if not header and model.mode != "kinetostatic":
        lines.append("  (the kinematic table above is the scene as written, input α = 0; the "
                     "states below are at the α the loads give)")
    g = model.gravity
    lines.append("gravity: " + (f"{np.hypot(*g):.6g} m/s² towards {_deg(g):.6g}°" if g.any()
                                else "ignored"))
    if model.masses:
        lines.append("")
        lines.append(f"{'mass':<10} {'on':<6} {'m kg':>8} {'I_G kg m²':>12}  inertia from")
        for m in model.masses:
            lines.append(f"{m.name:<10} {m.body:<6} {_g(m.mass):>8} {_g(m.inertia):>12}  "
                         f"{m.how}{' (free, spin ' + _g(m.spin) + ' rad/s)' if m.free else ''}")
    if model.forces or model.torques or model.frictions or model.springs:
        lines.append("")
        lines.append("loads:")
        for f in model.forces:
            lines.append(f"  {f.name}: force at {f.at} on {f.body}: {f.how}")
        for t in model.torques:
            lines.append(f"  {t.name}: torque on {t.body}: {abs(t.torque):.6g} N m "
                         f"{_sense(t.torque)}")
        for fr in model.frictions:
            lines.append(f"  {fr.name}: friction torque {fr.torque:.6g} N m at {fr.at} "
                         f"({fr.first} against {fr.second or 'the ground'}), opposing the "
                         f"relative rotation")
        for s in model.springs:
            if s.kind == "torsional":
                lines.append(f"  {s.name}: torsional spring {s.stiffness:.6g} N m/rad at "
                             f"{s.at} ({s.first} against {s.second or 'the ground'})")
            elif s.kind == "linear":
                lines.append(f"  {s.name}: spring {s.stiffness:.6g} N/m between "
                             f"{s.ends[0][0]} and {s.ends[1][0]}")
            else:
                lines.append(f"  {s.name}: spring {s.stiffness:.6g} N/m at {s.at}, kept "
                             f"parallel to {_deg(s.direction):.6g}°")
    for st in an.states:
        lines += [""] + _state_lines(an, st)
    if an.dynamics and an.dynamics.get("checks"):
        lines.append("")
        lines.append(f"energy vs RK4 integration (motion {an.dynamics['motion']}):")
        for c in an.dynamics["checks"]:
            lines.append(f"  {c['state']}: ω energy {c['omega_energy']:.10g} rad/s, RK4 "
                         f"{c['omega_ode']:.10g} rad/s ({c['rk4_steps']} steps, "
                         f"t = {c['time_s']:.6g} s), relative difference "
                         f"{c['relative_difference']:.2e}")
    checks = check_force_answers(an)
    if checks and all(c.answer.tutorial is None for c in checks):
        lines.append("")        # no printed values: the exact ones (a synthetic case)
        lines.append(f"{'force answer':<40} {'unit':<9} {'polygons':>12} {'exact':>12} "
                     f"{'rel. diff':>9}")
        for c in checks:
            a = c.answer
            rel = f"{c.exact_rel:>9.1e}" if c.exact_rel is not None else f"{'-':>9}"
            lines.append(f"{(a.desc + (f' [{a.state}]' if a.state else ''))[:40]:<40} "
                         f"{a.unit:<9} {_g(c.compared):>12} {_g(a.exact):>12} {rel}")
    elif checks:
        lines.append("")
        lines.append(f"{'force answer':<40} {'unit':<9} {'polygons':>12} {'tutorial':>10} "
                     f"{'diff %':>8}  note")
        for c in checks:
            a = c.answer
            if a.tutorial is None:
                continue
            note = "SLIP in the tutorial (see reference)" if a.slip else (
                "within drawing tolerance" if c.within else f"outside ±{a.tolerance * 100:g}%")
            note += undefined_note(a.tutorial, c.diff_pct)
            state = f" [{a.state}]" if a.state else ""
            desc = (a.desc + state)[:40]
            diff = f"{c.diff_pct:>8.2f}" if c.diff_pct is not None else f"{'-':>8}"
            lines.append(f"{desc:<40} {a.unit:<9} {_g(c.compared):>12} {_g(a.tutorial):>10} "
                         f"{diff}  {note}")
    return "\n".join(lines) + "\n"


def _state_lines(an: Analysis, st: State) -> list[str]:
    model = an.model
    ne = st.ne
    sol = st.sol
    drv = sol.scene.driver
    out = []
    if isinstance(drv, Crank):
        w = sol.links[drv.link].omega
        al = sol.links[drv.link].alpha
        head = (f"state: {st.name} — {drv.link} at {math.degrees(drv.angle) % 360:.6g}°, "
                f"ω = {abs(w):.6g} rad/s {_sense(w)}, α = {abs(al):.6g} rad/s² {_sense(al)}")
    else:
        sr = sol.slides[drv.point]
        head = (f"state: {st.name} — slider {drv.point}: v = {sr.velocity:.6g} m/s, "
                f"a = {sr.acceleration:.6g} m/s²")
    out.append(head)
    if "omega_energy" in st.extra and st.name != "release":
        out.append(f"  ω from energy {st.extra['omega_energy']:.10g} rad/s, from RK4 "
                   f"{st.extra['omega_ode']:.10g} rad/s; T = {st.extra['kinetic']:.6g} J, "
                   f"V = {st.extra['potential']:.6g} J, W_nc = {st.extra['work_nc']:.6g} J")
    unit = _effort_unit(an)
    if model.mode == "kinetostatic":
        e = ne.effort
        what = "torque" if unit == "N m" else "force"
        out.append(f"  {effort.words(model)}: {_effort_value(an, st, e)} (Newton–Euler); "
                   f"virtual work {_effort_value(an, st, st.vw_effort)}; difference "
                   f"{abs(e - st.vw_effort):.1e}")
        if unit == "N m" and model.parsed.effort is None:
            out.append(f"  the mechanism's turning moment on {model.driver_body}: "
                       f"{force_words.moment_words(-e, digits=8)}")
        out.append(f"  virtual-work breakdown ({unit} of the {what} per term):")
    else:
        a = ne.alpha
        out.append(f"  input angular acceleration from the loads: {abs(a):.10g} rad/s² "
                   f"{_sense(a)}; virtual-work check: extra input needed "
                   f"{st.vw_effort:.2e} {unit}")
        out.append(f"  virtual-work breakdown ({unit} each term asks of the input; sum 0):")
    for t in st.breakdown:
        out.append(f"    {t.words:<44} {t.value:>14.8g}")
    if st.inertia:
        out.append(f"  {'inertia of':<10} {'|a_G| m/s²':>12} {'dir°':>8} {'−m a_G N':>12} "
                   f"{'dir°':>8} {'−I_G α N m':>12}")
        for i in st.inertia:
            fi = -i.ma
            out.append(f"  {i.item:<10} {_g(float(np.hypot(*i.a))):>12} "
                       f"{_g(_deg(i.a) if _deg(i.a) is not None else None, 5):>8} "
                       f"{_g(float(np.hypot(*fi))):>12} "
                       f"{_g(_deg(fi) if _deg(fi) is not None else None, 5):>8} "
                       f"{_g(abs(i.i_alpha)):>12} {_sense(-i.i_alpha)}")
    out.append(f"  {'pin':<5} {'force on':<9} {'Fx N':>12} {'Fy N':>12} {'|F| N':>12} "
               f"{'dir°':>8}")
    for (lab, body), f in ne.pin.items():
        d = _deg(f)
        out.append(f"  {lab:<5} {body:<9} {_g(f[0]):>12} {_g(f[1]):>12} "
                   f"{_g(float(np.hypot(*f))):>12} {_g(d, 5) if d is not None else '-':>8}")
    for pin, (v, n) in ne.slot.items():
        s = next(x for x in model.slots if x.pin == pin)
        out.append(f"  slot: the pin {pin} pushes {s.lever} with {abs(v):.6g} N normal to the "
                   f"slot, towards {force_words.angle(n * v)}° (and {s.carrier} is pushed "
                   f"back)")
    for lab, (v, n, c) in ne.guide.items():
        if lab in ne.rolling:
            continue
        out.append(f"  guide: on {lab} {abs(v):.6g} N normal to the guide, towards "
                   f"{force_words.angle(n * v)}°; couple "
                   f"{force_words.moment_words(c, digits=3)}")
    for lab, (f, e, at) in ne.rolling.items():
        out.append(f"  {rolling_words(lab, ne)}")
    for c in st.contacts:
        if not c.lost:                  # (a lost contact is said among the warnings)
            out.append(f"  {cam_words(c)}")
    for lab, link, n, s, m in _sections(an, st):
        out.append(f"  section {lab} of {link} (on the part from {model.bodies[link].a}): "
                   f"N = {n:.6g} N, S = {s:.6g} N (CCW normal), M = "
                   f"{force_words.moment_words(m)}")
    for m in _machine(an, st):
        if m["value"] is None:
            out.append(f"  {m['words']}")
        else:
            words = ("turning moment T on the crank" if m["key"] == "turning_moment"
                     else m["words"])        # its value says 'in the sense of rotation'
            out.append(f"  {words}: {_machine_text(an, st, m)}")
    out.append(f"  equations: {ne.equations}, residual {ne.residual:.1e}")
    out += _graphical.polygons_lines(an, st)
    out += _graphical.lever_lines(an, st)
    for w in st.warnings:
        out.append(f"  warning: {w}")
    return out


def _run_cycle(args, scene) -> int:
    """``--cycle N``: the turning-moment diagram (polygons.forces.cycle)."""
    from ..forces.cycle import (MAX_CYCLE, check_cycle_budget, check_fluctuation, table_rows,
                                 turning_moment)
    from ..forces.analysis import load_model
    from ..units import parse_quantity
    if args.cycle is None:
        raise SceneError("--fluctuation goes with --cycle N (the turning-moment diagram)",
                         file=scene.file)
    cs = None
    if args.fluctuation is not None:
        # a plain number is the fraction itself, '2 %' a percentage (units.parse_quantity)
        cs = check_fluctuation(parse_quantity(args.fluctuation.strip(), "fraction",
                                              file=scene.file, where="--fluctuation"))
    model = load_model(scene)
    if not args.long and 4 <= args.cycle <= MAX_CYCLE:     # (a count out of range: refused
        check_cycle_budget(model, args.cycle, scene.file)  # by turning_moment, in its words)
    cy = turning_moment(model, scene, args.cycle)
    inertia = None if cs is None else cy.flywheel_inertia(cs)   # refused before any output
    if args.json:
        rows = list(table_rows(len(cy.theta)))
        text = json_text({"theta_deg": [math.degrees(t) for t in cy.theta],
                          "torque": cy.torque.tolist(),
                          "energy_sampled": cy.energy.tolist(),
                          "rows": [{"theta_deg": math.degrees(cy.theta[i]) % 360.0,
                                    "torque": float(cy.torque[i]), "energy": e}
                                   for i, e in zip(rows, cy.row_energy)],
                          "crossings": [{"theta_deg": math.degrees(t) % 360.0, "energy": e}
                                        for t, e in cy.crossings],
                          "max_torque": cy.max_torque[0],
                          "max_torque_at_deg": math.degrees(cy.max_torque[1]) % 360.0,
                          "min_torque": cy.min_torque[0],
                          "min_torque_at_deg": math.degrees(cy.min_torque[1]) % 360.0,
                          "mean_torque": cy.mean, "max_fluctuation_of_energy": cy.fluctuation,
                          "energy_max_at_deg": math.degrees(cy.at_max) % 360.0,
                          "energy_min_at_deg": math.degrees(cy.at_min) % 360.0,
                          "virtual_work_max_difference": cy.vw_error,
                          "flywheel_inertia": inertia,
                          "fluctuation_of_speed": cs, "warnings": list(cy.warnings)})
    else:
        text = cycle_table(scene, cy, cs)
    if args.svg:
        from diagrams.plots import plot_turning_moment
        paths = plot_turning_moment(cy, scene, f"{args.svg}/turning-moment",
                                    f"Turning-moment diagram: {scene.title}")
        if not args.json:
            text += f"\ndiagrams: {', '.join(str(p) for p in paths)}\n"
    emit(text, args.out)
    return 0


def cycle_table(scene, cy, cs=None) -> str:
    """The turning-moment diagram in text: its summary, then T and E at (up to) 36 angles."""
    from ..forces.cycle import table_rows
    (t_hi, at_hi), (t_lo, at_lo) = cy.max_torque, cy.min_torque

    def deg(t):
        return f"{round(math.degrees(t) % 360.0, 9) % 360.0:.6g}°"
    lines = [f"turning-moment diagram: {scene.title}",
             f"  input torque on {scene.driver.link} at {len(cy.theta)} angles round the "
             f"turn (kinetostatic, uniform ω = {abs(scene.driver.omega):.6g} rad/s "
             f"{_sense(scene.driver.omega)}, α = 0; CCW +)",
             f"  maximum {t_hi:.6g} N m at {deg(at_hi)}; minimum {t_lo:.6g} N m at "
             f"{deg(at_lo)}; mean {cy.mean:.6g} N m",
             f"  maximum fluctuation of energy ΔE = {cy.fluctuation:.6g} J (E greatest at "
             f"{deg(cy.at_max)}, least at {deg(cy.at_min)})",
             f"  virtual work equals Newton–Euler at every angle (largest difference "
             f"{cy.vw_error:.1e} N m)"]
    if cs is not None:
        lines.append(f"  flywheel for a coefficient of fluctuation of speed {cs:g}: "
                     f"I = ΔE / (ω² C_s) = {cy.flywheel_inertia(cs):.6g} kg m²")
    lines += [f"  warning: {w}" for w in cy.warnings]
    if cy.crossings:
        lines.append("  where T = T_m (the ends of the areas above and below the mean): "
                     + "; ".join(f"{deg(t)} E = {e:.6g} J" for t, e in cy.crossings))
    lines.append(f"  {'θ':>10} {'T N m':>14} {'E J':>14}")
    for i, e in zip(table_rows(len(cy.theta)), cy.row_energy):
        lines.append(f"  {deg(cy.theta[i]):>10} {cy.torque[i]:>14.6g} {e:>14.6g}")
    return "\n".join(lines) + "\n"
