"""The displacement diagram of a cam stated by its profile ([cam_profiles]): at each cam angle
the part in contact found and its equivalent linkage built (:mod:`polygons.cam_profiles`) and
solved by the staged construction — a sweep cannot follow it, the linkage changing with the
part.  Where there is no linkage the row says how it was found: the dwell on the base circle
(at rest), a translating knife or roller on a tangent cam's straight flank (the closed form,
:func:`polygons.cam_profiles.straight_flank_motion`)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .cam_profiles import TABLE, AXIS_KEY, contact, stated, straight_flank_motion
from .errors import SceneError, UnsupportedError
from .evaluate import solve
from .scene import parse_scene


@dataclass(frozen=True)
class Row:
    """One cam angle of the displacement diagram: the nose axis's angle (rad), the part in
    contact, how the row was found (``by``: 'linkage', 'dwell', 'closed form'); a translating
    follower's displacement from the foot of O along the stroke (m; the roller's centre, the
    knife's edge, a flat face), its velocity and acceleration along the stroke; an oscillating
    follower's arm angle (rad, pivot → R), ω and α (CCW positive)."""

    angle: float
    part: str
    s: float
    v: float
    a: float
    by: str = "linkage"


#: most cam angles of a displacement diagram (each a construction: ~1 ms)
MAX_DIAGRAM_STEPS = 20_000


def _base(scene):
    """The scene's data restated for one cam angle (ground, cam table, driver's rates)."""
    raw = scene.extra.get(TABLE)
    if not raw:
        raise UnsupportedError("the scene states no cam by its profile ([cam_profiles])",
                               file=scene.file)
    (label, table), = raw.items()
    table = {k: v for k, v in table.items() if k != AXIS_KEY}
    drv = scene.driver
    ground = {g: [f"{p[0]!r} m", f"{p[1]!r} m"] for g, p in scene.ground.items()}
    data = {"ground": ground, TABLE: {label: table},
            "driver": {"crank": drv.link, "angle": "0 deg",
                       "omega": f"{abs(drv.omega)!r} rad/s",
                       "sense": "CW" if drv.omega < 0 else "CCW",
                       "alpha": f"{abs(drv.alpha)!r} rad/s^2",
                       "alpha_sense": "CW" if drv.alpha < 0 else "CCW"}}
    return data


def movable(data: dict, file: str):
    """The scene of ``data`` (parsed TOML with [cam_profiles]) restated at a cam angle where
    the follower moves on a part with a linkage (the stated angle, else the first of each
    degree): a scene stated on the base circle or a translating follower's straight flank
    refuses an instant, yet has a displacement diagram."""
    label, table, prof, fol, *_ = stated(data, file)
    try:
        return parse_scene(data, file=file)
    except SceneError as exc:
        if "dwells" not in str(exc) and "straight flank" not in str(exc):
            raise
    for i in range(360):
        got = contact(prof, fol, math.radians(i))
        if got.part in ("nose", "flank") or (got.part == "straight flank" and fol.oscillating):
            return parse_scene({**data, "driver": {**data["driver"], "angle": f"{i} deg"}},
                               file=file)
    raise SceneError("the follower never leaves the base circle", file=file,
                     where=TABLE)  # pragma: no cover


def diagram(scene, steps: int = 360) -> tuple[Row, ...]:
    """The follower's displacement diagram over a turn of the cam of ``scene`` (a scene with
    [cam_profiles]) at ``steps`` nose-axis angles 0, 2π/steps, …: the part in contact found and
    its equivalent linkage built and solved; on the base circle the follower dwells (v = a =
    0); a translating knife or roller on a straight flank by the closed form."""
    if isinstance(steps, bool) or not isinstance(steps, int) or not \
            2 <= steps <= MAX_DIAGRAM_STEPS:
        raise UnsupportedError(f"steps must be a whole number 2 … {MAX_DIAGRAM_STEPS:,}",
                               file=scene.file)
    data = _base(scene)
    label, table, prof, fol, centre_o, o, crank, k = stated(data, scene.file)
    drv = scene.driver
    arm = (table["pivot"] + label) if fol.oscillating else None
    rows = []
    for i in range(steps):
        axis = 2 * math.pi * i / steps
        got = contact(prof, fol, axis)
        if got.part == "base circle":
            rows.append(Row(axis, got.part, got.s, 0.0, 0.0, "dwell"))
            continue
        if got.part == "straight flank" and not fol.oscillating:
            s, v, a = straight_flank_motion(prof, fol, axis, drv.omega, drv.alpha)
            rows.append(Row(axis, got.part, s, v, a, "closed form"))
            continue
        here = {**data, "driver": {**data["driver"], "angle": f"{axis!r} rad"}}
        sol = solve(parse_scene(here, file=scene.file))
        if fol.oscillating:         # the arm's angle, ω and α from the construction
            lk = sol.links[arm]
            p = sol.points[label].position
            q = (o[0] + fol.pivot[0], o[1] + fol.pivot[1])
            rows.append(Row(axis, got.part, math.atan2(p[1] - q[1], p[0] - q[0]), lk.omega,
                            lk.alpha))
            continue
        sr = sol.slides[label]
        e = (math.cos(fol.stroke), math.sin(fol.stroke))
        p = sol.points[label].position
        s_along = (p[0] - o[0] - fol.foot[0]) * e[0] + (p[1] - o[1] - fol.foot[1]) * e[1]
        rows.append(Row(axis, got.part, s_along + (got.radius if fol.kind == "flat" else 0.0),
                        sr.velocity, sr.acceleration))
    return tuple(rows)


__all__ = ["Row", "diagram", "movable", "MAX_DIAGRAM_STEPS"]
