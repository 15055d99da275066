"""``polygons sweep SCENE --vary AB=40..60mm:100 [--vary theta=0..360deg:73 --grid]``: the
scene solved once per value of the varied quantities (:func:`polygons.batch.solve_many`) at
its own input, written as one CSV row per variant (failed rows keep their row with the
reason in the ``error`` column), with a short summary on stdout.

A ``--vary`` value is ``NAME=LO..HI UNIT:N`` (N equally spaced values, ends included) or
``NAME=V1,V2,... UNIT``; NAME is a link (its length), ``G_x``/``G_y`` of a fixed point G,
``theta``/``omega``/``alpha`` of a crank or ``s``/``velocity``/``acceleration`` of an input
slider.  Several ``--vary`` go row by row (equal counts) or, with ``--grid``, every
combination.
"""
from __future__ import annotations

import csv
import re
import sys
from pathlib import Path

import numpy as np

from ..batch import MAX_ROWS
from ..errors import PolygonsError
from ..scene import Crank, Scene
from ..units import parse_quantity

_DIMENSION = {"theta": "angle", "omega": "angular_velocity", "alpha": "angular_acceleration",
              "s": "length", "velocity": "velocity", "acceleration": "acceleration"}
#: LO..HI:N — LO up to the first '..' (a decimal LO such as 0.5 has one dot, not two)
_RANGE = re.compile(r"^\s*(.+?)\s*\.\.\s*(.+?)\s*:\s*(\d+)\s*$")


def parse_vary(spec: str, scene: Scene) -> tuple[str, np.ndarray]:
    """``'AB=40..60mm:5'`` → ('AB', array of 5 lengths in m)."""
    where = f"--vary {spec if len(spec) <= 60 else spec[:59] + '…'}"
    name, eq, rest = spec.partition("=")
    name = name.strip()
    if not eq or not name or not rest.strip():
        raise PolygonsError("expected NAME=LO..HI UNIT:N or NAME=V1,V2,... UNIT, e.g. "
                            "AB=40..60mm:100", file=scene.file, where=where)
    dim = _DIMENSION.get(name, "length")
    m = _RANGE.match(rest)
    if m:
        lo, hi, digits = m.group(1), m.group(2), m.group(3).lstrip("0") or "0"
        count = int(digits) if len(digits) <= 12 else MAX_ROWS + 1
        if count > MAX_ROWS:
            raise PolygonsError(f"{digits[:15]}{'…' if len(digits) > 15 else ''} values: "
                                f"a --vary gives at most {MAX_ROWS:,} (and with --grid, all "
                                f"combinations together at most that)", file=scene.file,
                                where=where)
        unit = re.sub(r"^[-+0-9.eE\s]+", "", hi)
        lo_v = _value(lo if re.search(r"[a-zA-Z/]", lo) else f"{lo} {unit}", dim, scene, where)
        hi_v = _value(hi, dim, scene, where)
        if count < 1:
            raise PolygonsError("the number of values must be at least 1", file=scene.file,
                                where=where)
        return name, np.linspace(lo_v, hi_v, count)
    if ".." in rest:
        raise PolygonsError("a range needs both ends and a count, e.g. AB=40..60mm:100",
                            file=scene.file, where=where)
    parts = [p.strip() for p in rest.split(",") if p.strip()]
    unit = re.sub(r"^[-+0-9.eE\s]+", "", parts[-1])
    vals = [_value(p if re.search(r"[a-zA-Z/]", p) else f"{p} {unit}", dim, scene, where)
            for p in parts]
    return name, np.array(vals)


def _value(text: str, dim: str, scene: Scene, where: str) -> float:
    return parse_quantity(text.strip(), dim, file=scene.file, where=where)


def run_vary(args, scene: Scene) -> int:
    from ..batch import solve_many

    values = dict(parse_vary(v, scene) for v in args.vary)
    b = solve_many(scene, values, grid=args.grid)
    drv = scene.driver
    if args.points:
        points = list(dict.fromkeys(p.strip() for p in args.points.split(",") if p.strip()))
    else:
        sliders = [s for s in scene.model.guide
                   if isinstance(drv, Crank) or s != getattr(drv, "point", None)]
        points = sliders or [b.plan.dyads[-1].placed[-1]]
    crank = drv.link if isinstance(drv, Crank) else None
    links = (list(dict.fromkeys(p.strip() for p in args.links.split(",") if p.strip()))
             if args.links else
             [name for name in b._links[0] if name != crank])
    cols = [("row", "", np.arange(b.n))]
    cols += [(name, _unit_of(name), b.inputs[name]) for name in values]
    for lab in points:
        P, V, A = b.position(lab), b.velocity(lab), b.acceleration(lab)
        cols += [(f"{lab}.x", "m", P[:, 0]), (f"{lab}.y", "m", P[:, 1]),
                 (f"{lab}.vx", "m/s", V[:, 0]), (f"{lab}.vy", "m/s", V[:, 1]),
                 (f"{lab}.ax", "m/s^2", A[:, 0]), (f"{lab}.ay", "m/s^2", A[:, 1])]
    for name in links:
        cols += [(f"{name}.omega", "rad/s", b.omega(name)),
                 (f"{name}.alpha", "rad/s^2", b.alpha(name))]
    cols.append(("min_angle", "deg", b.angle_deg))
    errors = {e.row: f"{e.where}: {e.reason}" for e in b.errors}
    path = Path(args.out) / f"{Path(args.scene).stem}-vary.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow([f"{n} [{u}]" if u else n for n, u, _ in cols] + ["error"])
        data = np.column_stack([np.asarray(c, dtype=float) for _, _, c in cols])
        for i, row in enumerate(data):
            w.writerow([str(i)] + [format(float(v), ".17g") for v in row[1:]]
                       + [errors.get(i, "")])
    out = [f"{scene.title}", f"  scene: {scene.file}",
           "varied: " + ", ".join(f"{n} ({len(v)} values)" for n, v in values.items())
           + (" — every combination" if args.grid else " — row by row"),
           f"solved {int(b.ok.sum())} of {b.n} variants"]
    for e in b.errors[:5]:
        out.append(f"  row {e.row}: {e.where}: {e.reason}")
    if len(b.errors) > 5:
        out.append(f"  ... and {len(b.errors) - 5} more (the error column of the CSV)")
    out.append(f"written: {path}")
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _unit_of(name: str) -> str:
    return {"theta": "rad", "omega": "rad/s", "alpha": "rad/s^2", "velocity": "m/s",
            "acceleration": "m/s^2"}.get(name, "m")
