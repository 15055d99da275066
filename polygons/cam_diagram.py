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
    table = {k: v for k, v in table.items() if k not in (AXIS_KEY, "when")}
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


class _Turn:
    """A cam stated by its profile, ready to give its follower's row at any cam angle."""

    def __init__(self, scene):
        self.scene = scene
        self.data = _base(scene)
        self.label, table, self.prof, self.fol, centre_o, self.o, crank, k = stated(
            self.data, scene.file)
        self.arm = (table["pivot"] + self.label) if self.fol.oscillating else None

    def part(self, axis: float) -> str:
        return contact(self.prof, self.fol, axis).part

    def row(self, axis: float) -> Row:
        """The follower at the nose axis ``axis`` (rad): its part and, off the base circle,
        its equivalent linkage solved."""
        fol, o, label = self.fol, self.o, self.label
        got = contact(self.prof, fol, axis)
        if got.part == "base circle":
            return Row(axis, got.part, got.s, 0.0, 0.0, "dwell")
        data = self.data
        here = {**data, "driver": {**data["driver"], "angle": f"{axis!r} rad"}}
        sol = solve(parse_scene(here, file=self.scene.file))
        if fol.oscillating:         # the arm's angle, ω and α from the construction
            lk = sol.links[self.arm]
            p = sol.points[label].position
            q = (o[0] + fol.pivot[0], o[1] + fol.pivot[1])
            return Row(axis, got.part, math.atan2(p[1] - q[1], p[0] - q[0]), lk.omega,
                       lk.alpha)
        e = (math.cos(fol.stroke), math.sin(fol.stroke))
        pr = sol.points[label]       # the follower's block on its line of stroke
        p, v, a = pr.position, pr.velocity, pr.acceleration
        s_along = (p[0] - o[0] - fol.foot[0]) * e[0] + (p[1] - o[1] - fol.foot[1]) * e[1]
        return Row(axis, got.part, s_along + (got.radius if fol.kind == "flat" else 0.0),
                   v[0] * e[0] + v[1] * e[1], a[0] * e[0] + a[1] * e[1])


def diagram(scene, steps: int = 360) -> tuple[Row, ...]:
    """The follower's displacement diagram over a turn of the cam of ``scene`` (a scene with
    [cam_profiles]) at ``steps`` nose-axis angles 0, 2π/steps, …: the part in contact found and
    its equivalent linkage built and solved; on the base circle the follower dwells (v = a =
    0)."""
    if isinstance(steps, bool) or not isinstance(steps, int) or not \
            2 <= steps <= MAX_DIAGRAM_STEPS:
        raise UnsupportedError(f"steps must be a whole number 2 … {MAX_DIAGRAM_STEPS:,}",
                               file=scene.file)
    turn = _Turn(scene)
    return tuple(turn.row(2 * math.pi * i / steps) for i in range(steps))


#: the cam angles at which the parts in contact are first sampled (each a contact test, no
#: construction: ~20 µs), and the fewest rows an extreme is looked for in
PART_SAMPLES = 3600
EXTREME_SAMPLES = 360


def parts(scene) -> tuple[tuple[str, float, float, str], ...]:
    """The parts in contact over a turn, in the order the follower meets them from a nose
    axis at 0: (part, first angle, last angle, 'dwell' or 'linkage'), each edge where the
    part changes found by bisection on the part, to full precision (rad), between
    :data:`PART_SAMPLES` sampled angles (a part held over less than 0.1° may be missed)."""
    turn = _Turn(scene)

    def edge(lo: float, hi: float, before: str) -> tuple[float, float]:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if not lo < mid < hi:
                break
            if turn.part(mid) == before:
                lo = mid
            else:
                hi = mid
        return lo, hi

    xs = [2 * math.pi * i / PART_SAMPLES for i in range(PART_SAMPLES + 1)]
    ps = [turn.part(x) for x in xs]
    runs = [[ps[0], 0.0, 0.0]]
    for i in range(1, len(xs)):
        if ps[i] == runs[-1][0]:
            runs[-1][2] = xs[i]
            continue
        runs[-1][2], start = edge(xs[i - 1], xs[i], ps[i - 1])
        runs.append([ps[i], start, xs[i]])
    return tuple((p, a, b, "dwell" if p == "base circle" else "linkage") for p, a, b in runs)


#: the golden section's ratio, and where the search stops (rad of cam angle)
_GOLD = (math.sqrt(5.0) - 1.0) / 2.0
_TOL = 1e-11


def extremes(scene, rows: tuple[Row, ...], key: str, sense: int = 0) -> tuple[Row, ...]:
    """Where the diagram's quantity ``key`` ('s', 'v' or 'a') is greatest over the turn —
    its greatest value (``sense`` +1), least (−1) or greatest magnitude (0) — to full
    precision, not at the nearest sample: each sample that beats both neighbours (and is
    within 10 % of the best) is refined by golden-section search between its neighbours
    (to 1e-11 rad; at a part's edge, where the acceleration jumps, the search closes on the
    edge and keeps the best side).  Returns every row where the extreme is reached (within
    1e-9 of it), by angle."""
    score = ((lambda r: abs(getattr(r, key))) if sense == 0 else
             (lambda r: sense * getattr(r, key)))
    if len(rows) < EXTREME_SAMPLES:         # a coarse diagram: look on a finer one
        rows = diagram(scene, EXTREME_SAMPLES)
    n = len(rows)
    f = [score(r) for r in rows]
    best = max(f)
    cands = [i for i in range(n) if f[i] >= f[i - 1] and f[i] >= f[(i + 1) % n]
             and f[i] >= best - 0.1 * abs(best)]
    turn = _Turn(scene)
    step = 2 * math.pi / n
    found = []
    for i in sorted(cands, key=lambda i: -f[i])[:8]:
        a, b = rows[i].angle - step, rows[i].angle + step
        top = rows[i]
        x1, x2 = b - _GOLD * (b - a), a + _GOLD * (b - a)
        r1, r2 = turn.row(x1), turn.row(x2)
        for r in (r1, r2):
            top = r if score(r) > score(top) else top
        while b - a > _TOL:
            if score(r1) >= score(r2):
                b, x2, r2 = x2, x1, r1
                x1 = b - _GOLD * (b - a)
                r1 = turn.row(x1)
                top = r1 if score(r1) > score(top) else top
            else:
                a, x1, r1 = x1, x2, r2
                x2 = a + _GOLD * (b - a)
                r2 = turn.row(x2)
                top = r2 if score(r2) > score(top) else top
        found.append(Row(top.angle % (2 * math.pi), top.part, top.s, top.v, top.a, top.by))
    peak = max(score(r) for r in found)
    keep = sorted((r for r in found if score(r) >= peak - 1e-9 * max(abs(peak), 1e-300)),
                  key=lambda r: r.angle)
    out = []
    for r in keep:              # one row per place (two samples about one peak: one row)
        if not out or r.angle - out[-1].angle > 1e-6:
            out.append(r)
    return tuple(out)


__all__ = ["Row", "diagram", "extremes", "parts", "movable", "has_profile", "nose_axis", "scene_at", "part_at",
           "MAX_DIAGRAM_STEPS"]
