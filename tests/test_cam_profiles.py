"""Cams stated by their profile ([cam_profiles], polygons/cam_profiles.py): the part in contact
and the equivalent linkage over a turn, against the closed form of each part — the follower
of a circular part (centre c, radius ρ) moves as a slider-crank (knife, roller: crank |c|, rod
ρ + r) or a Scotch yoke (flat face: s = c·e + ρ) — with the parts found here by the test's own
geometry; the displacement's finite differences give the velocity."""
import math

import pytest

from conftest import ROOT
from polygons.errors import SceneError
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_toml, parse_scene

CASE = ROOT / "cases" / "cam-profile-circular-arc.toml"
R1, R2, LIFT, RF, RR, W = 0.025, 0.008, 0.020, 0.060, 0.010, 10.0


def scene_text(axis_deg, follower="roller", kind="circular arc", stroke=90.0):
    extra = {"roller": f'roller = "{RR * 1e3!r} mm"', "knife": "", "flat": ""}[follower]
    flank = f'flank_radius = "{RF * 1e3!r} mm"' if kind == "circular arc" else ""
    return f"""
[ground]
O = ["0 mm", "0 mm"]
[driver]
crank = "OK"
angle = "{axis_deg!r} deg"
omega = "{W!r} rad/s"
sense = "CCW"
[cam_profiles.R]
base_radius = "{R1 * 1e3!r} mm"
nose_radius = "{R2 * 1e3!r} mm"
lift = "{LIFT * 1e3!r} mm"
kind = "{kind}"
{flank}
follower = "{follower}"
{extra}
stroke = "{stroke!r} deg"
"""


def geometry(kind):
    """The test's own profile: nose centre at d on the axis; a flank arc's centre P on the
    far side with |OP| = R − r1, |QP| = R − r2 (two circles met); the normal spans."""
    d = R1 + LIFT - R2
    if kind == "tangent":
        b = math.acos((R1 - R2) / d)
        return d, None, b, b
    a, b, c = RF - R1, RF - R2, d                  # triangle O, Q, P: sides OP, QP, OQ
    ang = math.acos((a * a + c * c - b * b) / (2 * a * c))   # angle QOP
    P = (a * math.cos(ang), -a * math.sin(ang))
    return d, P, math.atan2(-P[1], d - P[0]), math.atan2(-P[1], -P[0])


def closed_form(axis, follower, kind):
    """(part, s, v, a) of the follower on the +y stroke through O, the cam at ``axis``."""
    d, P, phi_n, phi_b = geometry(kind)
    phi = math.atan2(math.sin(math.pi / 2 - axis), math.cos(math.pi / 2 - axis))
    side = 1 if phi >= 0 else -1
    rr = RR if follower == "roller" else 0.0
    parts = [("nose", (d, 0.0), R2, 0.0, phi_n)]
    if P is not None:
        parts.append(("flank", (P[0], side * P[1]), RF, phi_n, phi_b))
    parts.append(("base circle", (0.0, 0.0), R1, phi_b, math.pi))
    if P is None and follower != "flat" and abs(phi) < phi_b:
        # the book's tangent cam: on the flank x = p / cos θ, θ = β − |φ| the flank normal from
        # the stroke, the contact p tan θ along the flank from the base circle (while on it)
        p, theta = R1 + (RR if follower == "roller" else 0.0), phi_b - abs(phi)
        if p * math.tan(theta) <= math.sqrt(d * d - (R1 - R2) ** 2):
            c = math.cos(theta)
            return ("straight flank", p / c, side * W * p * math.sin(theta) / c ** 2,
                    W * W * p * (2 - c * c) / c ** 3)
    for name, c, rho, lo, hi in parts:
        cr = math.hypot(*c)
        gamma = math.atan2(c[1], c[0]) - phi         # the crank |c| from the stroke
        if follower == "flat":
            normal, s = abs(phi), cr * math.cos(gamma) + rho
            v = -cr * math.sin(gamma) * W          # dγ/dt = +ω: the cam turns CCW
            acc = -cr * math.cos(gamma) * W * W
        else:
            L = rho + rr
            if L * L < (cr * math.sin(gamma)) ** 2:    # the ray misses this part's arc
                continue
            S = math.sqrt(L * L - (cr * math.sin(gamma)) ** 2)
            s = cr * math.cos(gamma) + S
            # the contact normal: from the part's centre to the roller's, in the cam's frame
            normal = abs(math.atan2(s * math.sin(phi) - c[1], s * math.cos(phi) - c[0]))
            ds = -cr * math.sin(gamma) - cr * cr * math.sin(gamma) * math.cos(gamma) / S
            dds = (-cr * math.cos(gamma) - cr * cr * math.cos(2 * gamma) / S
                   - cr ** 4 * (math.sin(gamma) * math.cos(gamma)) ** 2 / S ** 3)
            v, acc = ds * W, dds * W * W
        if lo - 1e-12 <= normal <= hi + 1e-12:
            return name, s, v, acc
    return "tangent flank", None, None, None


@pytest.mark.parametrize("follower,kind", [("roller", "circular arc"),
                                           ("knife", "circular arc"),
                                           ("flat", "circular arc"), ("roller", "tangent"),
                                           ("knife", "tangent")])
def test_follower_over_a_turn_is_each_parts_closed_form(follower, kind):
    seen = set()
    for k in range(36):
        axis = math.radians(5.0 + 10.0 * k)
        part, s, v, a = closed_form(axis, follower, kind)
        seen.add(part)
        text = scene_text(math.degrees(axis), follower, kind)
        if part == "base circle":
            with pytest.raises(SceneError, match="dwells"):
                parse_scene(parse_toml(text, "cam.toml"), file="cam.toml")
            continue
        sol = solve(parse_scene(parse_toml(text, "cam.toml"), file="cam.toml"))
        if part == "straight flank":    # the tangent mechanism: the block R on the stroke
            r = sol.points["R"]
            assert r.position[1] == pytest.approx(s, rel=1e-12), (k, part)
            assert r.velocity[1] == pytest.approx(v, rel=1e-9, abs=1e-12), (k, part)
            assert r.acceleration[1] == pytest.approx(a, rel=1e-9, abs=1e-9), (k, part)
            continue
        # a flat face: R is the yoke's point under the centre of curvature, the face ρ beyond
        rho = {"nose": R2, "flank": RF}[part] if follower == "flat" else 0.0
        assert quantity(sol, "y(R)") + rho == pytest.approx(s, rel=1e-12), (k, part)
        assert quantity(sol, "vs(R)") == pytest.approx(v, rel=1e-9, abs=1e-12), (k, part)
        assert quantity(sol, "as(R)") == pytest.approx(a, rel=1e-9, abs=1e-9), (k, part)
    assert {"nose", "base circle"} <= seen
    assert ("flank" in seen) == (kind == "circular arc")
    assert ("straight flank" in seen) == (kind == "tangent")


def test_the_parts_meet_smoothly_where_the_profile_changes():
    """At the angle where the nose meets the flank (and the flank the base circle) the two
    parts' closed forms give the same displacement and velocity: the profile's tangency."""
    d, P, phi_n, phi_b = geometry("circular arc")
    for edge in (phi_n, phi_b):        # a flat face's contact normal is the stroke itself
        for eps in (1e-9,):
            inner = closed_form(math.pi / 2 - (edge - eps), "flat", "circular arc")
            outer = closed_form(math.pi / 2 - (edge + eps), "flat", "circular arc")
            assert inner[0] != outer[0]
            assert inner[1] == pytest.approx(outer[1], abs=1e-9)
            assert inner[2] == pytest.approx(outer[2], abs=1e-6)


def test_velocity_is_the_displacements_derivative():
    """v = ω ds/dθ by central differences of the construction's own displacement."""
    h = 1e-6

    def s(axis_deg):
        sol = solve(parse_scene(parse_toml(scene_text(axis_deg), "c.toml"), file="c.toml"))
        return quantity(sol, "y(R)"), quantity(sol, "vs(R)")
    for axis in (60.0, 85.0, 100.0):
        (sp, _), (sm, _), (_, v) = s(axis + math.degrees(h)), s(axis - math.degrees(h)), s(axis)
        # the cam turning CCW by dθ moves the axis by +dθ
        assert (sp - sm) / (2 * h) * W == pytest.approx(v, rel=1e-6)


def test_case_exact_answers_are_the_closed_form():
    scene = load_scene(CASE)
    axis = scene.driver.angle          # the crank to the flank centre: read the stated axis
    part, s, v, a = closed_form(math.radians(60.0), "roller", "circular arc")
    assert part == "flank"
    want = {"y(R)": s * 1e3, "vs(R)": v, "as(R)": a}
    for ans in scene.answers:
        assert ans.exact == pytest.approx(want[ans.quantity], rel=1e-12), ans.quantity
    sol = solve(scene)
    for ans in scene.answers:
        factor = 1e3 if ans.unit == "mm" else 1.0
        assert quantity(sol, ans.quantity) * factor == pytest.approx(ans.exact, rel=1e-9)
    assert axis != math.radians(60.0)   # the driver turned to the flank's centre K


@pytest.mark.parametrize("change,words", [
    (('flank_radius = "60.0 mm"', 'flank_radius = "26 mm"'), "cannot touch"),
    (('nose_radius = "8.0 mm"', 'nose_radius = "30 mm"'), "smaller than the base"),
    (('follower = "roller"', 'follower = "spring"'), "follower must be"),
    (('stroke = "90.0 deg"', 'stroke = "ninety"'), "stroke"),
    (('kind = "circular arc"', 'kind = "tangent"'), "leave flank_radius out"),
])
def test_a_bad_profile_is_refused_in_one_line(change, words):
    text = scene_text(60.0).replace(*change)
    with pytest.raises(SceneError, match=words):
        parse_scene(parse_toml(text, "c.toml"), file="c.toml")


def test_the_flank_radius_from_the_angle_of_action():
    """"... a circular-arc cam, base circle 25 mm, nose 8 mm, lift 20 mm, angle of action
    175.13°": the flank radius found is the one whose flank meets the base circle at half that
    angle from the nose axis (geometry() of this test: 60 mm gives 2 × 87.566°)."""
    from polygons.cam_profiles import profile_of
    d, P, phi_n, phi_b = geometry("circular arc")
    table = {"base_radius": "25 mm", "nose_radius": "8 mm", "lift": "20 mm",
             "angle_of_action": f"{math.degrees(2 * phi_b)!r} deg", "stroke": "90 deg"}
    assert profile_of(table, "c.toml", "cam_profiles.R").flank == pytest.approx(RF, rel=1e-9)
    bad = dict(table, flank_radius="50 mm")
    with pytest.raises(SceneError, match="does not fit the profile"):
        profile_of(bad, "c.toml", "cam_profiles.R")
    with pytest.raises(SceneError, match="between 125.296 deg"):
        profile_of(dict(table, angle_of_action="100 deg"), "c.toml", "cam_profiles.R")


def test_the_displacement_diagram_over_a_turn_is_each_parts_closed_form():
    """cam_diagram.diagram: the equivalent linkage of the part in contact solved at each
    cam angle (the dwell on the base circle at r1 + roller, at rest), against closed_form;
    a sweep, which would follow one part's linkage round the turn, is refused."""
    from polygons import cam_diagram
    from polygons.errors import PolygonsError
    from polygons.sweep import sweep
    scene = load_scene(CASE)
    rows = cam_diagram.diagram(scene, 24)
    assert len(rows) == 24 and {r.part for r in rows} == {"base circle", "flank", "nose"}
    for r in rows:
        part, s, v, a = closed_form(r.angle, "roller", "circular arc")
        assert r.part == part
        if part == "base circle":
            assert (r.s, r.v, r.a) == (R1 + RR, 0.0, 0.0)
            continue
        assert r.s == pytest.approx(s, rel=1e-12)
        assert r.v == pytest.approx(v, rel=1e-9, abs=1e-12)
        assert r.a == pytest.approx(a, rel=1e-9)
    assert max(r.s for r in rows) == pytest.approx(R1 + RR + LIFT, rel=1e-12)   # the lift
    with pytest.raises(PolygonsError, match="diagram"):
        sweep(scene, 8)


def test_the_interactive_page_is_refused_in_one_line(tmp_path, capsys):
    """Refused in the command line's words (the commands that do draw it), not the Python
    API's ('polygons.cam_diagram.diagram(scene, steps)')."""
    from polygons.cli import main
    assert main(["handout", str(CASE), "--interactive", "-o", str(tmp_path / "p.html")]) == 1
    assert not (tmp_path / "p.html").exists()
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "'polygons sweep'" in err[0] and str(CASE) in err[0]
    assert "cam_diagram" not in err[0]


# ------------------------------------------------------------------ offset and oscillating
# The follower's place at each cam angle checked by the test's own profile (the exact distance
# from a point to each arc and segment: the roller touches the cam and nowhere cuts it; a
# flat face is the cam's supporting line), and its velocity and acceleration by central
# differences of the construction's own displacement (h = 1e-5 rad: truncation ~1e-9).
def outline_parts(kind, axis):
    """(centre, radius, from, to) arcs (angles CCW) or (a, b) segments of the test's profile
    with the nose axis at ``axis``: nose, two flanks, base circle."""
    d, P, phi_n, phi_b = geometry(kind)
    rot = lambda p: (p[0] * math.cos(axis) - p[1] * math.sin(axis),
                     p[0] * math.sin(axis) + p[1] * math.cos(axis))
    parts = [("arc", rot((d, 0.0)), R2, axis - phi_n, axis + phi_n),
             ("arc", (0.0, 0.0), R1, axis + phi_b, axis + 2 * math.pi - phi_b)]
    for side in (1, -1):
        if P is not None:
            lo, hi = sorted((side * phi_n, side * phi_b))
            parts.append(("arc", rot((P[0], side * P[1])), RF, axis + lo, axis + hi))
        else:
            n = (math.cos(side * phi_b), math.sin(side * phi_b))
            parts.append(("seg", rot((R1 * n[0], R1 * n[1])),
                          rot((d + R2 * n[0], R2 * n[1]))))
    return parts


def distance_to_cam(x, kind, axis):
    best = math.inf
    for part in outline_parts(kind, axis):
        if part[0] == "arc":
            _, c, rho, a0, a1 = part
            ang = math.atan2(x[1] - c[1], x[0] - c[0])
            if (ang - a0) % (2 * math.pi) <= (a1 - a0) + 1e-12:
                best = min(best, abs(math.hypot(x[0] - c[0], x[1] - c[1]) - rho))
            for a in (a0, a1):
                best = min(best, math.hypot(x[0] - c[0] - rho * math.cos(a),
                                            x[1] - c[1] - rho * math.sin(a)))
        else:
            _, a, b = part
            ab = (b[0] - a[0], b[1] - a[1])
            t = max(0.0, min(1.0, ((x[0] - a[0]) * ab[0] + (x[1] - a[1]) * ab[1])
                             / (ab[0] ** 2 + ab[1] ** 2)))
            best = min(best, math.hypot(x[0] - a[0] - t * ab[0], x[1] - a[1] - t * ab[1]))
    return best


def support(kind, axis, n):
    """max over the cam of x·n (the test's profile)."""
    best = -math.inf
    for part in outline_parts(kind, axis):
        if part[0] == "arc":
            _, c, rho, a0, a1 = part
            ang = math.atan2(n[1], n[0])
            cands = [a0, a1] + ([ang] if (ang - a0) % (2 * math.pi) <= (a1 - a0) else [])
            best = max(best, max((c[0] + rho * math.cos(a)) * n[0]
                                 + (c[1] + rho * math.sin(a)) * n[1] for a in cands))
        else:
            best = max(best, *(p[0] * n[0] + p[1] * n[1] for p in part[1:]))
    return best


Q = (0.070, 0.050)
MOVERS = {
    "offset roller": ('roller = "10 mm"\nstroke = "90 deg"\noffset = "10 mm"\n', "", "y(R)"),
    "oscillating roller": ('roller = "10 mm"\npivot = "Q"\narm = "60 mm"\nside = "left"\n',
                           'Q = ["70 mm", "50 mm"]', "omega(QR)"),
    "oscillating knife": ('pivot = "Q"\narm = "70 mm"\nside = "left"\n',
                          'Q = ["70 mm", "50 mm"]', "omega(QR)"),
    "oscillating flat": ('pivot = "Q"\narm = "150 mm"\nside = "right"\n',
                         'Q = ["70 mm", "50 mm"]', "omega(QR)"),
}


def mover_scene(axis_deg, kind, mover):
    body, ground, _ = MOVERS[mover]
    follower = mover.split()[1]
    flank = f'flank_radius = "{RF * 1e3!r} mm"' if kind == "circular arc" else ""
    return parse_scene(parse_toml(f"""
[ground]
O = ["0 mm", "0 mm"]
{ground}
[driver]
crank = "OK"
angle = "{axis_deg!r} deg"
omega = "{W!r} rad/s"
sense = "CCW"
[cam_profiles.R]
base_radius = "25 mm"
nose_radius = "8 mm"
lift = "20 mm"
kind = "{kind}"
{flank}
follower = "{follower}"
{body}""", "c.toml"), file="c.toml")


@pytest.mark.parametrize("kind,mover", [
    ("circular arc", "offset roller"), ("circular arc", "oscillating roller"),
    ("tangent", "oscillating roller"), ("circular arc", "oscillating knife"),
    ("circular arc", "oscillating flat")])
def test_offset_and_oscillating_followers_touch_the_cam_and_move_as_it_turns(kind, mover):
    follower = mover.split()[1]
    rr = RR if follower == "roller" else 0.0
    h = 1e-5
    parts = set()
    for axis_deg in range(5, 360, 20):
        axis = math.radians(axis_deg)
        try:
            sols = [solve(mover_scene(axis_deg + math.degrees(dx), kind, mover))
                    for dx in (-h, 0.0, h)]
        except SceneError as exc:
            assert "dwells on the base circle" in str(exc)
            parts.add("base circle")
            continue
        sol = sols[1]
        parts.add(sol.scene.extra["cam_profiles"]["R"]["_axis"] and "moving")
        R = sol.points["R"].position
        if mover == "offset roller":       # on the line x = −10 mm, touching
            assert R[0] == pytest.approx(-0.010, abs=1e-15)
            assert distance_to_cam(R, kind, axis) == pytest.approx(rr, abs=1e-12)
            s = [quantity(x, "y(R)") for x in sols]
            v, a = quantity(sol, "vs(R)"), quantity(sol, "as(R)")
        else:
            assert math.hypot(R[0] - Q[0], R[1] - Q[1]) == pytest.approx(
                {"roller": 0.060, "knife": 0.070, "flat": 0.150}[follower], rel=1e-12)
            assert (R[0] - Q[0]) * (0 - Q[1]) - (R[1] - Q[1]) * (0 - Q[0]) < 0 \
                if follower != "flat" else True       # left of Q → O (y up)
            if follower == "flat":     # the face along QR, the cam on its right: supporting
                t = ((R[0] - Q[0]) / 0.15, (R[1] - Q[1]) / 0.15)
                n = (-t[1], t[0])       # the left normal: from the cam towards the face
                assert support(kind, axis, n) == pytest.approx(Q[0] * n[0] + Q[1] * n[1],
                                                               abs=1e-12)
            else:
                assert distance_to_cam(R, kind, axis) == pytest.approx(rr, abs=1e-12)
            s = [math.atan2(x.points["R"].position[1] - Q[1],
                            x.points["R"].position[0] - Q[0]) for x in sols]
            v, a = quantity(sol, "omega(QR)"), quantity(sol, "alpha(QR)")
        ws = [quantity(x, "vs(R)") if mover == "offset roller" else quantity(x, "omega(QR)")
              for x in sols]
        assert (s[2] - s[0]) / (2 * h) * W == pytest.approx(v, rel=1e-6, abs=1e-9)
        assert (ws[2] - ws[0]) / (2 * h) * W == pytest.approx(a, rel=1e-5, abs=1e-6)
    assert parts == {"base circle", "moving"}


def test_a_translating_roller_on_a_straight_flank_is_the_books_closed_form():
    """Tangent cam, roller follower in line: on the flank x = (r₁ + r)(1 − cos θ)/cos θ,
    v = ω (r₁ + r) sin θ / cos² θ, a = ω² (r₁ + r)(2 − cos² θ)/cos³ θ, θ the cam's turn from
    where the flank's normal lies along the stroke (the displacement diagram's rows, built as
    the tangent mechanism); with α too, straight_flank_motion's a = ω² s″ + α s′."""
    from polygons import cam_diagram
    from polygons.cam_profiles import contact, follower_of, profile_of, straight_flank_motion
    data = parse_toml(scene_text(60.0, "roller", "tangent"), "c.toml")
    scene = parse_scene(data, file="c.toml")          # stated on the flank: solved there
    d, _, beta, _ = geometry("tangent")
    rows = [r for r in cam_diagram.diagram(scene, 72) if r.part == "straight flank"]
    assert len(rows) >= 8 and all(r.by == "linkage" for r in rows)
    p = R1 + RR
    for r in rows:
        # the flank's normal at axis ± β; the stroke at 90°
        theta = min(abs(math.remainder(r.angle + sgn * beta - math.pi / 2, 2 * math.pi))
                    for sgn in (1, -1))
        rising = r.v > 0
        assert r.s - p == pytest.approx(p * (1 - math.cos(theta)) / math.cos(theta), rel=1e-12)
        assert abs(r.v) == pytest.approx(W * p * math.sin(theta) / math.cos(theta) ** 2,
                                         rel=1e-9)
        assert r.a == pytest.approx(W * W * p * (2 - math.cos(theta) ** 2)
                                    / math.cos(theta) ** 3, rel=1e-9)
        assert rising == (r.angle < math.pi / 2)
    # speeding up at 40 rad/s², offset 7 mm, a knife: the construction against the closed form
    text = (scene_text(62.0, "knife", "tangent").replace('sense = "CCW"', 'sense = "CCW"\n'
            'alpha = "40 rad/s^2"\nalpha_sense = "CCW"') + 'offset = "7 mm"\n')
    data = parse_toml(text, "c.toml")
    r = solve(parse_scene(data, file="c.toml")).points["R"]
    table, o = data["cam_profiles"]["R"], (0.0, 0.0)
    prof, fol = profile_of(table, "c", "t"), follower_of(table, data["ground"], o, "c", "t")
    assert contact(prof, fol, math.radians(62.0)).part == "straight flank"
    s, v, a = straight_flank_motion(prof, fol, math.radians(62.0), W, 40.0)
    assert (r.position[0], r.position[1]) == pytest.approx((-0.007, s), rel=1e-12)
    assert r.velocity[1] == pytest.approx(v, rel=1e-9)
    assert r.acceleration[1] == pytest.approx(a, rel=1e-9)


def arc_cam(r1, r2, lift, R):
    """(d, P, φ_n, φ_b) of a circular-arc cam (the triangle O Q P, as geometry())."""
    d = r1 + lift - r2
    a, b = R - r1, R - r2
    ang = math.acos((a * a + d * d - b * b) / (2 * a * d))
    P = (a * math.cos(ang), -a * math.sin(ang))
    return d, P, math.atan2(-P[1], d - P[0]), math.atan2(-P[1], -P[0])


def oscillating_flat(c, Q, k, omega, sign):
    """An arm pivoted at Q whose face, along the arm through Q, touches the circle of the
    cam's part whose centre is c (turning about O at ω): (c − Q)·n = k, n the arm's left
    normal (k = ∓ρ, the cam on the face's right/left).  ψ = ∠(c − Q) − 90° + sign·acos(k/|c − Q|);
    differentiating F = (c − Q)·n − k with c′ = J c, c″ = −c, n′ = −t, t′ = n:
    ψ′ = (J c·n)/((c − Q)·t), ψ″ = (N′ D − N D′)/D², N′ = −c·n − ψ′ (J c·t),
    D′ = J c·t + ψ′ (c − Q)·n.  Returns (ψ, ω ψ′, ω² ψ″)."""
    w = (c[0] - Q[0], c[1] - Q[1])
    psi = math.atan2(w[1], w[0]) - math.pi / 2 + sign * math.acos(k / math.hypot(*w))
    t = (math.cos(psi), math.sin(psi))
    n = (-t[1], t[0])
    Jc = (-c[1], c[0])
    N = Jc[0] * n[0] + Jc[1] * n[1]
    D = w[0] * t[0] + w[1] * t[1]
    d1 = N / D
    N1 = -(c[0] * n[0] + c[1] * n[1]) - d1 * (Jc[0] * t[0] + Jc[1] * t[1])
    D1 = (Jc[0] * t[0] + Jc[1] * t[1]) + d1 * (w[0] * n[0] + w[1] * n[1])
    return psi, omega * d1, omega ** 2 * (N1 * D - N * D1) / D ** 2


def test_the_new_cases_exact_answers_are_the_closed_forms():
    """cam-profile-tangent-roller (Khurmi's tangent cam): the lift from 90° between the faces
    (β = 45°, d = (r₁ − r₂)/cos β), at the top of the nose y = d + r₂ + r and
    a = −ω² d (1 + d/(r₂ + r)); cam-profile-arc-flat-oscillating (Khurmi's convex-flank cam):
    R from the angle of action (φ_b = 60°) by the triangle O, nose centre, flank centre, and
    the lever's ω, α by oscillating_flat — each against the case's exact and the solve."""
    from polygons.scene import load_scene
    w = 180 * 2 * math.pi / 60
    d = (0.060 - 0.012) / math.cos(math.pi / 4)
    want = {"y(R)": (d + 0.012 + 0.024) * 1e3, "as(R)": -w * w * d * (1 + d / 0.036)}
    checks = [(ROOT / "cases" / "cam-profile-tangent-roller.toml", want)]
    r1, r2, lift, w = 0.025, 0.012, 0.008, 500 * 2 * math.pi / 60
    d = r1 + lift - r2
    c60 = 0.5
    R = (r2 ** 2 - r1 ** 2 - d ** 2 + 2 * d * r1 * c60) / (2 * (d * c60 - r1 + r2))
    assert R == pytest.approx(0.0794, rel=1e-12)
    _, P, phi_n, phi_b = arc_cam(r1, r2, lift, R)
    assert phi_b == pytest.approx(math.radians(60), rel=1e-12)
    found = []
    for side in (1, -1):               # the flank's centre with the nose axis at 270°
        c = (side * P[1], -P[0])       # (P_x, side P_y) turned by 270°
        for sign in (1, -1):
            try:
                psi, om, al = oscillating_flat(c, (0.070, 0.050), -R, w, sign)
            except ValueError:
                continue
            t = (math.cos(psi), math.sin(psi))
            touch = (c[0] - R * t[1], c[1] + R * t[0])     # the cam on the face's right
            normal = math.atan2(touch[1] - c[1], touch[0] - c[0]) - 3 * math.pi / 2
            rel = math.remainder(normal, 2 * math.pi) * side   # from the nose axis
            ahead = (touch[0] - 0.070) * t[0] + (touch[1] - 0.050) * t[1] > 0
            if ahead and phi_n <= rel <= phi_b:            # on this flank's arc
                found.append((om, al, math.hypot(*c)))
    (om, al, ok), = found
    checks.append((ROOT / "cases" / "cam-profile-arc-flat-oscillating.toml",
                   {"dist(O,K)": ok * 1e3, "omega(QR)": om, "alpha(QR)": al}))
    for case, want in checks:
        scene = load_scene(case)
        sol = solve(scene)
        for ans in scene.answers:
            assert ans.exact == pytest.approx(abs(want[ans.quantity]) if ans.sense
                                              else want[ans.quantity], rel=1e-12), ans.quantity
            factor = 1e3 if ans.unit == "mm" else 1.0
            assert quantity(sol, ans.quantity) * factor == pytest.approx(want[ans.quantity],
                                                                         rel=1e-9)


def test_sweep_of_a_cam_by_its_profile_writes_its_displacement_diagram(tmp_path, capsys):
    """`polygons sweep` on a [cam_profiles] scene: the displacement diagram as CSV (the lift
    from the dwell, the part and how each row was found) and a summary — a tangent cam stated
    on its straight flank included; the sweep's other flags refused."""
    from polygons.cli import main
    case = ROOT / "cases" / "cam-profile-tangent-roller.toml"
    flank = tmp_path / "flank.toml"
    flank.write_text(case.read_text().replace('\nangle = "90 deg"', '\nangle = "50 deg"'))
    assert main(["sweep", str(flank), "--steps", "36", "--no-plot", "-o", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "straight flank" in out and "closed form" not in out and "lift: 19.882 mm" in out
    rows = (tmp_path / "flank-cam.csv").read_text().splitlines()
    assert rows[0].startswith("cam angle [deg],part,found by,s [mm],lift [mm]")
    assert len(rows) == 37
    top = next(r.split(",") for r in rows if r.startswith("90,"))
    assert top[1] == "nose" and float(top[4]) == pytest.approx(19.882250993908557, rel=1e-12)
    assert main(["sweep", str(flank), "--vary", "OK=1..2mm:3", "-o", str(tmp_path)]) == 1
    assert "--vary is not for a cam" in capsys.readouterr().err
    assert main(["sweep", str(case), "--steps", "20001", "-o", str(tmp_path)]) == 1
    assert "20,000" in capsys.readouterr().err


def test_the_space_diagram_draws_the_whole_profile_touching_the_roller():
    """The profile's outline on the space diagram (diagrams/cam_profile.py): a closed shaded
    polyline whose nearest point to the roller's centre is the roller's radius away."""
    from diagrams.space import space_layout
    from diagrams.model import Circle, Polyline
    sol = solve(load_scene(CASE))
    content, _, sc, _ = space_layout(sol)
    items = [it for g in content for it in g.items]
    outline, = [it for it in items if isinstance(it, Polyline) and it.cls == "cam-profile"]
    roller, = [it for it in items if isinstance(it, Circle) and it.cls == "roller"]
    assert outline.closed and len(outline.points) >= 360
    gap = min(math.hypot(p[0] - roller.centre[0], p[1] - roller.centre[1])
              for p in outline.points)
    assert gap == pytest.approx(roller.r, abs=0.05)          # mm of paper (the outline's chords)
    assert any(it.cls == "cam-contact-part" for it in items)


def test_solve_reports_the_profile_found_and_the_part_in_contact(capsys):
    """"Find the radius of the flanks": `solve` states the profile it found (R from the angle
    of action) and the part in contact, in words and in JSON (`cam_profile`)."""
    import json
    from polygons.cli import main
    case = ROOT / "cases" / "cam-profile-arc-flat-oscillating.toml"
    assert main(["solve", str(case), "--no-steps"]) == 0
    out = capsys.readouterr().out
    assert "flanks 79.4 mm, angle of action 120°" in out
    assert "the flank touches the oscillating flat follower R" in out
    assert main(["solve", str(case), "--json"]) == 0
    cam = json.loads(capsys.readouterr().out)["cam_profile"]
    assert cam["flank_radius"] == pytest.approx(0.0794, rel=1e-12)
    assert (cam["part_in_contact"], cam["motion"], cam["follower"]) == ("flank", "oscillating",
                                                                        "flat")


def test_the_oscillating_diagram_passes_through_the_case():
    """The displacement diagram of the oscillating lever (cam_diagram.diagram, 72 angles): at
    the case's 270° its row is the case's construction (the arm's angle, ω, α), the lever
    rests on the base circle somewhere and moves on the flanks and the nose elsewhere."""
    from polygons import cam_diagram
    case = ROOT / "cases" / "cam-profile-arc-flat-oscillating.toml"
    scene = load_scene(case)
    sol = solve(scene)
    rows = cam_diagram.diagram(scene, 72)
    row = rows[54]
    assert row.angle == pytest.approx(math.radians(270), rel=1e-15)
    R, Qp = sol.points["R"].position, (0.070, 0.050)
    assert row.s == pytest.approx(math.atan2(R[1] - Qp[1], R[0] - Qp[0]), rel=1e-12)
    assert (row.v, row.a) == (pytest.approx(sol.links["QR"].omega, rel=1e-12),
                              pytest.approx(sol.links["QR"].alpha, rel=1e-12))
    assert {r.part for r in rows} == {"nose", "flank", "base circle"}
    assert all(r.v == 0.0 and r.a == 0.0 for r in rows if r.part == "base circle")


def test_the_tangent_flank_case_is_the_books_closed_form():
    """cam-profile-tangent-flank (Khurmi's tangent cam, part (1)): on the flank, as the
    tangent mechanism, y = p / cos θ, v = ω p sin θ / cos² θ, a = ω² p (2 − cos² θ)/cos³ θ
    (p = r₁ + r, θ = the nose axis − 45°); its questions: the speed and the acceleration are
    greatest where the flanks end (tan θ = l / p, l = (r₁ − r₂) tan β the flank's length),
    the acceleration there the nose's slider-crank's (crank d, rod r₂ + r) — against the
    case's exact and `ask`; the cam's torque greatest there too; the follower's slide, a
    spring stated at this instant, the cam's mass on OK and a load at K refused in one line."""
    from polygons import conditions
    from polygons.scene import load_scene
    case = ROOT / "cases" / "cam-profile-tangent-flank.toml"
    w, p, beta = 180 * 2 * math.pi / 60, 0.084, math.pi / 4
    d = (0.060 - 0.012) / math.cos(beta)
    th = math.atan(48 / 84)             # when = "leaves the straight flank": the edge itself
    c = math.cos(th)
    want = {"y(R)": p / c * 1e3, "v(R)": w * p * math.sin(th) / c ** 2,
            "a(R)": w * w * p * (2 - c * c) / c ** 3}
    scene = load_scene(case)
    sol = solve(scene)
    assert [e for e in scene.equivalents if "cam" in e.kind] == []     # no [cams]: the slot
    for ans in scene.answers:
        assert ans.exact == pytest.approx(want[ans.quantity], rel=1e-12), ans.quantity
        factor = 1e3 if ans.unit == "mm" else 1.0
        assert quantity(sol, ans.quantity) * factor == pytest.approx(want[ans.quantity],
                                                                     rel=1e-9)
    the = math.atan(d * math.sin(beta) / p)          # the flank's end
    edges = [math.degrees(beta + the), 180 - math.degrees(beta + the)]
    g, L = beta - the, 0.012 + 0.024                  # the nose's crank from the stroke
    S = math.sqrt(L * L - (d * math.sin(g)) ** 2)
    a_nose = w * w * (d * math.cos(g) + d * d * math.cos(2 * g) / S
                      + d ** 4 * (math.sin(g) * math.cos(g)) ** 2 / S ** 3)
    v_end = w * p * math.sin(the) / math.cos(the) ** 2
    for fd, value in zip(conditions.answer_all(scene), (v_end, a_nose)):
        q = fd.question
        assert list(q.exact) == pytest.approx(edges, rel=1e-12)
        assert list(q.value_exact) == pytest.approx([value] * 2, rel=1e-12)
        assert list(fd.reported()) == pytest.approx(edges, rel=1e-10)
        assert list(fd.values()) == pytest.approx([value] * 2, rel=1e-9)
        c = conditions.check(fd)
        assert c.exact_ok and c.value_ok
        assert "dwells on the base circle" in fd.words      # no value there: said,
        assert "from 135 … 45 deg" in fd.words              # its edges exact, not samples
    import tomllib
    data = tomllib.loads(case.read_text(encoding="utf-8"))
    # the cam's torque over the turn against a 80 N spring load and a 1.5 kg follower: the
    # greatest at the flank's end (rising), T ω = (F + m a) v there
    data |= {"masses": {"R": {"mass": "1.5 kg"}},
             "forces": {"Spring": {"at": "R", "force": ["0 N", "-80 N"]}},
             "questions": [{"find": "angle", "quantity": "Tin", "condition": "max",
                            "unit": "deg", "samples": 24}]}
    a_end = w * w * p * (2 - math.cos(the) ** 2) / math.cos(the) ** 3
    (fd,) = conditions.answer_all(parse_scene(data, file=str(case)))
    assert list(fd.reported()) == pytest.approx(edges[:1], rel=1e-10)
    assert list(fd.values()) == pytest.approx([(80 + 1.5 * a_end) * v_end / w], rel=1e-9)
    for quantity_, change, words in (
            ("as(R)", {}, "slot on a straight flank"),
            ("Tin", {"springs": {"S": {"at": "R", "stiffness": "1 N/mm", "direction": "90 deg",
                                       "extension": "-5 mm"}}}, "at this instant only"),
            ("Tin", {"masses": {"OK": {"mass": "2 kg"}}}, r"masses.OK\] on a cam"),
            ("Tin", {"forces": {"P": {"at": "K", "force": ["1 N", "0 N"]}}}, "no point of")):
        bad = {**data, **change, "questions": [{"find": "angle", "quantity": quantity_,
                                                "condition": "max", "unit": "deg"}]}
        with pytest.raises(SceneError, match=words):
            conditions.answer_all(parse_scene(bad, file=str(case)))


def test_the_displacement_diagrams_summary_is_exact_not_the_nearest_sample():
    """The summary's greatest |v| and |a| (and the lift) are the extremes themselves, refined
    between samples (cam_diagram.extremes): on Khurmi's tangent cam the greatest speed is at
    the flanks' ends, 74.744881…° and 105.255118…°, 1.0420798510656863 m/s (the case's
    [[questions]] exact, the book's closed form) — the 1°-sampled diagram's best is 1.0222 m/s
    at 105°; the greatest |a| 84.3168059297373 m/s² there; the lift the profile's.  The parts'
    edges likewise, however coarse the diagram."""
    from polygons import cam_diagram
    scene = load_scene(str(ROOT / "cases" / "cam-profile-tangent-flank.toml"))
    rows = cam_diagram.diagram(scene, 36)
    v = cam_diagram.extremes(scene, rows, "v")
    assert [math.degrees(r.angle) for r in v] == pytest.approx(
        [74.74488129694221, 105.25511870305779], abs=1e-7)
    assert all(abs(r.v) == pytest.approx(1.0420798510656863, rel=1e-9) for r in v)
    a = cam_diagram.extremes(scene, rows, "a")
    assert abs(a[0].a) == pytest.approx(84.3168059297373, rel=1e-9)
    top, = cam_diagram.extremes(scene, rows, "s", +1)
    low = cam_diagram.extremes(scene, rows, "s", -1)[0]
    assert (top.s - low.s) == pytest.approx(0.019882250993908557, rel=1e-12)
    edges = [math.degrees(e) for p in cam_diagram.parts(scene) for e in p[1:3]]
    assert edges == pytest.approx([0, 45, 45, 74.74488129694221, 74.74488129694221,
                                   105.25511870305779, 105.25511870305779, 135, 135, 360],
                                  abs=1e-9)


@pytest.mark.parametrize("when, sense, deg", [
    ("leaves the base circle", "CCW", 45.0),
    ("reaches the nose", "CCW", 74.74488129694221),
    ("leaves the straight flank", "CCW", 74.74488129694221),
    ("leaves the nose", "CCW", 105.25511870305779),
    ("leaves the flank on the return", "CCW", 135.0),
    ("reaches the base circle on the return", "CCW", 135.0),
    ("leaves the straight flank", "CW", 105.25511870305779),   # turning the other way
])
def test_a_cams_instant_stated_by_its_event(when, sense, deg):
    """[cam_profiles.R] when = "…": the nose axis at the event (module cam_events), the
    edge to the last bit and the event's own part in contact (leaving a part: still on it;
    reaching one: on it already; the base circle, where the follower rests: the moving
    part's side)."""
    from polygons.cam_profiles import contact, stated
    text = (ROOT / "cases" / "cam-profile-tangent-flank.toml").read_text()
    text = text.replace('when = "leaves the straight flank"', f'when = "{when}"')
    text = text.replace('sense = "CCW"', f'sense = "{sense}"')
    data = parse_toml(text, "t.toml")
    scene = parse_scene(data, file="t.toml")
    from polygons.cam_diagram import nose_axis
    axis = nose_axis(scene)
    assert math.degrees(axis) % 360 == pytest.approx(deg, abs=1e-9)
    label, table, prof, fol, *_ = stated(data, "t.toml")
    part = contact(prof, fol, axis).part
    verb, _, rest = when.partition(" the ")
    named = rest.replace(" on the return", "")
    later = axis + (1e-9 if sense == "CCW" else -1e-9)
    if named == "base circle":     # at rest there: the moving part's side of the edge
        assert part != named and (contact(prof, fol, later).part == named) == (verb != "leaves")
    elif verb == "leaves":
        assert named in part and named not in contact(prof, fol, later).part
    else:
        assert named in part


def test_a_cams_when_refused_in_one_line():
    text = (ROOT / "cases" / "cam-profile-tangent-flank.toml").read_text()
    data = parse_toml(text.replace('when = "leaves the straight flank"',
                                   'when = "passes the nose"'), "t.toml")
    with pytest.raises(SceneError, match="expected 'leaves' or 'reaches'"):
        parse_scene(data, file="t.toml")
    data = parse_toml(text.replace('[driver]', '[driver]\nangle = "70 deg"'), "t.toml")
    with pytest.raises(SceneError, match="angle or the cam's when, not both"):
        parse_scene(data, file="t.toml")
    arc = parse_toml((ROOT / "cases" / "cam-profile-circular-arc.toml").read_text(), "t.toml")
    arc["driver"].pop("angle")
    arc["cam_profiles"]["R"]["when"] = "leaves the straight flank"
    with pytest.raises(SceneError, match="never leaves the straight flank"):
        parse_scene(arc, file="t.toml")
