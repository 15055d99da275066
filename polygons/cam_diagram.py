"""The displacement diagram of a cam stated by its profile ([cam_profiles]): at each cam angle
the part in contact found and its equivalent linkage built (:mod:`polygons.cam_profiles`) and
solved by the staged construction — a sweep cannot follow it, the linkage changing with the
part (a translating knife or roller on a tangent cam's straight flank: the tangent mechanism,
its closed form :func:`polygons.cam_profiles.straight_flank_motion` the tests' oracle).  Where
there is no linkage the row says so: the dwell on the base circle (at rest)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .cam_profiles import TABLE, AXIS_KEY, contact, stated
from .errors import SceneError, UnsupportedError
from .evaluate import solve
from .scene import parse_scene
from .units import parse_quantity


@dataclass(frozen=True)
class Row:
    """One cam angle of the displacement diagram: the nose axis's angle (rad), the part in
    contact, how the row was found (``by``: 'linkage', 'dwell'); a translating
    follower's displacement from the foot of O along the stroke (m; the roller's centre, the
    knife's edge, a flat face), its velocity and acceleration along the stroke; an oscillating
    follower's arm angle (rad, pivot → R), ω and α (CCW positive)."""

    angle: float
    part: str
    s: float
    v: float
    a: float
    by: str = "linkage"


#: the force tables restated with the cam at each angle (they name the follower, O, ground)
LOAD_TABLES = ("masses", "forces", "torques", "springs", "gravity")
#: most cam angles of a displacement diagram (each a construction: ~1 ms)
MAX_DIAGRAM_STEPS = 20_000


def _base(scene, omega: float | None = None):
    """The scene's data restated for one cam angle (ground, cam table, driver's rates; the
    cam's speed ``omega`` in rad/s, CCW positive, for the scene's own)."""
    raw = scene.extra.get(TABLE)
    if not raw:
        raise UnsupportedError("the scene states no cam by its profile ([cam_profiles])",
                               file=scene.file)
    (label, table), = raw.items()
    table = {k: v for k, v in table.items() if k != AXIS_KEY}
    drv = scene.driver
    w = drv.omega if omega is None else omega
    ground = {g: [f"{p[0]!r} m", f"{p[1]!r} m"] for g, p in scene.ground.items()}
    loads = {t: scene.extra[t] for t in LOAD_TABLES if t in scene.extra}
    data = {**loads, "ground": ground, TABLE: {label: table},
            "driver": {"crank": drv.link, "angle": "0 deg",
                       "omega": f"{abs(w)!r} rad/s",
                       "sense": "CW" if w < 0 else "CCW",
                       "alpha": f"{abs(drv.alpha)!r} rad/s^2",
                       "alpha_sense": "CW" if drv.alpha < 0 else "CCW"}}
    return data


def has_profile(scene) -> bool:
    """Whether ``scene`` states a cam by its profile ([cam_profiles])."""
    return bool(scene.extra.get(TABLE))


def nose_axis(scene) -> float:
    """The stated cam angle (the nose axis's, rad) of a scene with [cam_profiles]."""
    (table,) = scene.extra[TABLE].values()
    return parse_quantity(table[AXIS_KEY], "angle", file=scene.file, where=TABLE)


def scene_at(scene, axis: float, omega: float | None = None):
    """The scene of a cam stated by its profile restated at the nose axis ``axis`` (rad; the
    cam's speed ``omega``, rad/s CCW +, for the scene's): the part in contact found and its
    equivalent linkage built; None where the follower dwells on the base circle or no part
    meets it (no linkage: the scene loaded at its own angle, the geometry's refusal here).
    Only the cam, its follower, the driver and the force tables are restated."""
    data = _base(scene, None if omega is None else float(omega))
    data["driver"]["angle"] = f"{float(axis)!r} rad"
    try:
        return parse_scene(data, file=scene.file)
    except SceneError:
        return None


def part_at(scene, axis: float) -> tuple[str, int]:
    """The part of the profile in contact (its name and side) with the nose axis at ``axis``
    ('none' where no part meets the follower)."""
    label, table, prof, fol, *_ = stated(_base(scene), scene.file)
    try:
        got = contact(prof, fol, float(axis))
    except SceneError:          # no part meets the follower at this angle
        return "none", 0
    return got.part, got.side


def movable(data: dict, file: str):
    """The scene of ``data`` (parsed TOML with [cam_profiles]) restated at a cam angle where
    the follower moves on a part with a linkage (the stated angle, else the first of each
    degree): a scene stated on the base circle refuses an instant, yet has a displacement
    diagram."""
    label, table, prof, fol, *_ = stated(data, file)
    try:
        return parse_scene(data, file=file)
    except SceneError as exc:
        if "dwells" not in str(exc):
            raise
    for i in range(360):
        got = contact(prof, fol, math.radians(i))
        if got.part != "base circle":
            return parse_scene({**data, "driver": {**data["driver"], "angle": f"{i} deg"}},
                               file=file)
    raise SceneError("the follower never leaves the base circle", file=file,
                     where=TABLE)  # pragma: no cover


def diagram(scene, steps: int = 360) -> tuple[Row, ...]:
    """The follower's displacement diagram over a turn of the cam of ``scene`` (a scene with
    [cam_profiles]) at ``steps`` nose-axis angles 0, 2π/steps, …: the part in contact found and
    its equivalent linkage built and solved; on the base circle the follower dwells (v = a =
    0)."""
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
        here = {**data, "driver": {**data["driver"], "angle": f"{axis!r} rad"}}
        sol = solve(parse_scene(here, file=scene.file))
        if fol.oscillating:         # the arm's angle, ω and α from the construction
            lk = sol.links[arm]
            p = sol.points[label].position
            q = (o[0] + fol.pivot[0], o[1] + fol.pivot[1])
            rows.append(Row(axis, got.part, math.atan2(p[1] - q[1], p[0] - q[0]), lk.omega,
                            lk.alpha))
            continue
        e = (math.cos(fol.stroke), math.sin(fol.stroke))
        pr = sol.points[label]       # the follower's block on its line of stroke
        p, v, a = pr.position, pr.velocity, pr.acceleration
        s_along = (p[0] - o[0] - fol.foot[0]) * e[0] + (p[1] - o[1] - fol.foot[1]) * e[1]
        rows.append(Row(axis, got.part, s_along + (got.radius if fol.kind == "flat" else 0.0),
                        v[0] * e[0] + v[1] * e[1], a[0] * e[0] + a[1] * e[1]))
    return tuple(rows)


__all__ = ["Row", "diagram", "movable", "has_profile", "nose_axis", "scene_at", "part_at",
           "MAX_DIAGRAM_STEPS"]
