"""``polygons centres CASE.toml``: every instantaneous centre by Kennedy's theorem, the angular
velocities and point velocities by the centres, rubbing velocities and least velocities."""
from __future__ import annotations

import math
import sys


def register(sub) -> None:
    p = sub.add_parser("centres", help="instantaneous centres (Kennedy), velocities by the "
                                       "centres, rubbing and least velocities",
                       description="Find every instantaneous centre of a scene by Kennedy's "
                                   "theorem, the velocities by the centres, the rubbing "
                                   "velocities at [pins] and the least velocities; print a "
                                   "table (or JSON with --json); -o DIR also writes "
                                   "centres.svg.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--json", action="store_true", help="print a JSON object instead of a table")
    p.add_argument("--points", help="comma-separated labels whose velocities to report "
                                    "(default: every point)")
    p.add_argument("--units", choices=("mm", "si", "imperial"), default="mm",
                   help="units of the table: mm (positions in mm, speeds in m/s; default), "
                        "si (m, m/s) or imperial (in, ft/s); JSON is always SI")
    p.add_argument("-o", "--out", metavar="DIR", help="write centres.svg to this folder")
    p.add_argument("--paper", choices=("A5", "A4"), help="paper for the drawing (default A4)")
    p.set_defaults(func=run)


def run(args) -> int:
    from ..centres import instant_centres
    from ..evaluate import solve
    from ..pins import report_lines, spec, to_dict
    from ..report import json_text
    from ..scene import load_scene
    scene = load_scene(args.scene)
    spec(scene)                            # bad [pins] tables fail before anything is written
    sol = solve(scene)
    pts = [t.strip() for t in args.points.split(",")] if args.points else None
    if pts is not None:
        from ..errors import UnknownLabelError, suggest
        for t in pts:
            if t not in sol.placement.points:
                raise UnknownLabelError(f"unknown point {t!r}: "
                                        f"{suggest(t, list(sol.placement.points))}",
                                        file=scene.file, where="--points")
    cs = instant_centres(sol, pts)
    if args.out:
        from pathlib import Path
        from diagrams.centres import svg
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "centres.svg").write_bytes(svg(sol, cs, args.paper).encode())
    from ..contacts import wheel_centres    # rolling wheels' centres (no-slip)
    if args.json:
        wheels = {"rolling_centres": wheel_centres(sol, cs)} if wheel_centres(sol, cs) else {}
        sys.stdout.write(json_text(to_json(sol, cs) | ({"pins": to_dict(sol)}
                                                        if to_dict(sol) else {}) | wheels))
    else:
        extra = centre_lines(sol, cs)
        sys.stdout.write(table(sol, cs, args.units) + "".join(
            ln + "\n" for ln in (["", *report_lines(sol)] if report_lines(sol) else []))
            + "".join(ln + "\n" for ln in (["", *extra] if extra else [])))
        if args.out:
            sys.stdout.write(f"wrote {args.out}/centres.svg\n")
    return 0


def _key(b) -> str:
    return b.key or b.name


def to_json(sol, cs) -> dict:
    keys = {b.number: _key(b) for b in cs.bodies}
    return {
        "scene": sol.scene.file,
        "units": {"length": "m", "velocity": "m/s", "omega": "rad/s (CCW positive)",
                  "direction": "unit vector of a centre at infinity (no sense)"},
        "note": cs.note,
        "complete": cs.complete,
        # "key": the model's name of the body, the same whatever else the mechanism has
        # (a lookup by name: "name" is a report's words, "CP (with 4 links fixed to it)")
        "links": [{"number": b.number, "name": b.name, "key": _key(b), "kind": b.kind,
                   "labels": list(b.labels), "fixed": list(b.fixed)} for b in cs.bodies],
        "centres": [{"label": c.label, "i": c.i, "j": c.j, "names": list(c.names),
                     "keys": [keys[c.i], keys[c.j]],
                     "point": list(c.point) if c.point is not None else None,
                     "direction": list(c.direction) if c.direction is not None else None,
                     "how": c.how, "primary": c.primary, "order": c.order,
                     "from_velocity_field": c.by_field,
                     "lines": [list(x) for x in c.lines], "angle_deg": c.angle_deg}
                    for c in cs.centres],
        "omegas": [{"number": o.number, "name": o.name, "key": keys[o.number],
                    "omega": o.omega,
                    "velocity": list(o.velocity) if o.velocity is not None else None,
                    "how": o.how, "rule": o.rule, "via": o.via, "speed": o.speed,
                    "radius": o.radius} for o in cs.omegas],
        "velocities": {x: {"link": v.number, "key": keys[v.number], "velocity": list(v.velocity), "speed": v.speed,
                           "radius": v.radius, "omega": v.omega, "how": v.how}
                       for x, v in cs.velocities.items()},
    }


def _g(x: float) -> str:
    return "0" if x == 0 else f"{x:.5g}"


def table(sol, cs, units: str = "mm") -> str:
    """The centres, the ω of each link and each point's velocity as a book writes it
    (v_C = ω₃ · I₁₃C = ω × distance), in the unit system ``units`` (mm, si, imperial)."""
    from ..centres import pair_name, sub
    from ..units import SYSTEMS, UNITS
    lu, vu = SYSTEMS[units]["length"], SYSTEMS[units]["velocity"]
    lf, vf = 1.0 / UNITS[lu][1], 1.0 / UNITS[vu][1]
    scene = sol.scene
    size = cs.size
    names = {b.number: b.name for b in cs.bodies}
    lines = [scene.title, f"  scene: {scene.file}", "",
             "links: " + ", ".join(f"{b.number} {b.name}" for b in cs.bodies), "",
             cs.note, "",
             f"{'centre':<7} {'links':<22} {'x ' + lu:>10} {'y ' + lu:>10}   how"]

    def ln(x):
        return _g(0.0 if abs(x) < 1e-9 * size else x * lf)

    for c in cs.centres:
        if c.point is not None:
            x, y = ln(c.point[0]), ln(c.point[1])
        elif c.direction is not None:
            ang = round(math.degrees(math.atan2(c.direction[1], c.direction[0])), 6) + 0.0
            x, y = "∞", f"∞ {_g(ang)}°"
        else:
            x, y = "any", "any"
        lines.append(f"{c.label:<7} {c.names[0] + ' / ' + c.names[1]:<22} {x:>10} {y:>10}   "
                     f"{c.how}")
    lines += ["", "angular velocities by the centres:"]
    for o in cs.omegas[1:]:
        sense = "" if o.omega == 0 else ("CCW" if o.omega > 0 else "CW")
        head = f"  ω{sub(o.number)} ({o.name}) = {_g(abs(o.omega))} rad/s {sense}".rstrip()
        j, i = o.number, o.via
        if o.rule == "ratio":
            ij = sub(pair_name(min(i, j), max(i, j)))
            lines.append(f"{head}   [ω{sub(j)} = v_I{ij} / I{sub(pair_name(1, j))}I{ij} = "
                         f"{_g(o.speed * vf)} {vu} / {_g(o.radius * lf)} {lu}; v_I{ij} from "
                         f"link {i} ({names[i]})]")
        elif o.rule == "translates":
            ij = sub(pair_name(min(i, j), max(i, j)))
            lines.append(f"{head}   [I{sub(pair_name(1, j))} at infinity: {o.name} translates "
                         f"with v_I{ij} = {_g(o.speed * vf)} {vu}]")
        elif o.rule == "given" and o.speed is not None:
            lines.append(f"{head}   [given: the driver translates at {_g(o.speed * vf)} {vu}]")
        else:
            lines.append(f"{head}   [{o.how}]")
    lines += ["", "velocities by the centres (v = ω × distance from the link's centre I1j):"]
    for x, v in cs.velocities.items():
        j = v.number
        if j == 1:
            lines.append(f"  v_{x} = 0   (a fixed point)")
        elif v.radius is None:
            lines.append(f"  v_{x} = v{sub(j)} = {_g(v.speed * vf)} {vu}   ({names[j]} "
                         f"translates: I{sub(pair_name(1, j))} at infinity)")
        else:
            lines.append(f"  v_{x} = ω{sub(j)} · I{sub(pair_name(1, j))}{x} = "
                         f"{_g(abs(v.omega))} rad/s × {_g(v.radius * lf)} {lu} = "
                         f"{_g(v.speed * vf)} {vu}   (on {names[j]})")
    return "\n".join(lines) + "\n"


def centre_lines(sol, cs) -> list[str]:
    """:func:`polygons.contacts.wheel_centres` in words, as ``polygons centres`` prints them."""
    from ..centres import pair_name, sub
    from ..contacts import wheel_centres
    rows = wheel_centres(sol, cs)
    if not rows:
        return []
    mm = lambda p: f"({p[0] * 1000:.6g}, {p[1] * 1000:.6g}) mm"   # noqa: E731
    lines = ["rolling contacts (each wheel is not a link of the equivalent linkage: its centres "
             "from the no-slip conditions):"]
    for r in rows:
        j = r["number"]
        for rel in r["relative"]:
            i = rel["number"]
            if rel["body"] == "frame":        # the same centre as the absolute one below
                continue
            what = "the frame" if rel["body"] == "frame" else f"the plate of {rel['body']}"
            lines.append(f"  I{sub(pair_name(min(i, j), max(i, j)))} (wheel {r['wheel']} / "
                         f"{what}) = the contact point {mm(rel['point'])}")
        if r["absolute"] is None:
            lines.append(f"  I{sub(pair_name(1, j))} (wheel {r['wheel']} / frame): at infinity "
                         f"(the wheel translates, ω = 0)")
            continue
        d = math.dist(r["absolute"], r["centre"])
        where = ("the contact point with the fixed surface"
                 if r["relative"][0]["body"] == "frame" and len(r["relative"]) == 1 else
                 "on the line of the contact points")
        lines.append(f"  I{sub(pair_name(1, j))} (wheel {r['wheel']} / frame) = "
                     f"{mm(r['absolute'])}, {where}; "
                     f"v_{r['wheel']} = ω{sub(str(j))} · I{sub(pair_name(1, j))}{r['wheel']} = "
                     f"{abs(r['omega']):.6g} rad/s × {d * 1000:.6g} mm = {r['speed']:.6g} m/s")
    return lines
