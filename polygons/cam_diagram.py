"""The displacement diagram of a cam stated by its profile ([cam_profiles]): at each cam angle
the part in contact found and its equivalent linkage built (:mod:`polygons.cam_profiles`) and
solved by the staged construction — a sweep cannot follow it, the linkage changing with the
part."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .cam_profiles import TABLE, _q, contact, profile_of
from .errors import UnsupportedError
from .evaluate import solve
from .scene import parse_scene


@dataclass(frozen=True)
class Row:
    """One cam angle of the displacement diagram: the nose axis's angle (rad), the part in
    contact, the follower's displacement from O along the stroke (m; a flat face's face), its
    velocity and acceleration along the stroke (0 while it dwells)."""

    angle: float
    part: str
    s: float
    v: float
    a: float


MAX_DIAGRAM_STEPS = 100_000


def diagram(scene, steps: int = 360) -> tuple[Row, ...]:
    """The follower's displacement diagram over a turn of the cam of ``scene`` (a scene with
    [cam_profiles]): at each of ``steps`` nose-axis angles the part in contact is found and its
    equivalent linkage built and solved (:func:`rewrite`, the staged construction); on the
    base circle the follower dwells (s = r₁ + roller, v = a = 0)."""
    raw = scene.extra.get(TABLE)
    if not raw:
        raise UnsupportedError("the scene states no cam by its profile ([cam_profiles])",
                               file=scene.file)
    if isinstance(steps, bool) or not isinstance(steps, int) or not \
            2 <= steps <= MAX_DIAGRAM_STEPS:
        raise UnsupportedError(f"steps must be a whole number 2 … {MAX_DIAGRAM_STEPS:,}",
                               file=scene.file)
    (label, table), = raw.items()
    drv = scene.driver
    centre_o = scene.model.body(drv.link).a if hasattr(scene.model, "body") else None
    o = scene.ground[centre_o] if centre_o in scene.ground else next(iter(scene.ground.values()))
    name = next(k for k, v in scene.ground.items() if v == o)
    prof = profile_of(table, scene.file, f"{TABLE}.{label}")
    follower = table.get("follower", "roller")
    roller = _q(table["roller"], "length", scene.file, "roller") if follower == "roller" else 0.0
    stroke = _q(table["stroke"], "angle", scene.file, "stroke")
    base = {"ground": {name: [f"{o[0]!r} m", f"{o[1]!r} m"]}, TABLE: raw,
            "driver": {"crank": drv.link, "omega": f"{abs(drv.omega)!r} rad/s",
                       "sense": "CW" if drv.omega < 0 else "CCW",
                       "alpha": f"{abs(drv.alpha)!r} rad/s^2",
                       "alpha_sense": "CW" if drv.alpha < 0 else "CCW"}}
    rows = []
    for k in range(steps):
        axis = 2 * math.pi * k / steps
        got = contact(prof, follower, roller, stroke - axis)
        if got.part == "base circle":
            rows.append(Row(axis, got.part, prof.base + roller, 0.0, 0.0))
            continue
        if got.part == "tangent flank":
            rows.append(Row(axis, got.part, math.nan, math.nan, math.nan))
            continue
        data = {**base, "driver": {**base["driver"], "angle": f"{math.degrees(axis)!r} deg"}}
        sol = solve(parse_scene(data, file=scene.file))
        sr = sol.slides[label]
        e = (math.cos(stroke), math.sin(stroke))
        p = sol.points[label].position
        s_along = (p[0] - o[0]) * e[0] + (p[1] - o[1]) * e[1]
        rows.append(Row(axis, got.part, s_along + (got.radius if follower == "flat" else 0.0),
                        sr.velocity, sr.acceleration if sr.acceleration is not None
                        else math.nan))
    return tuple(rows)


__all__ = ["Row", "diagram", "MAX_DIAGRAM_STEPS"]
