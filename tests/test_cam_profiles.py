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
                                           ("flat", "circular arc"), ("roller", "tangent")])
def test_follower_over_a_turn_is_each_parts_closed_form(follower, kind):
    seen = set()
    for k in range(36):
        axis = math.radians(5.0 + 10.0 * k)
        part, s, v, a = closed_form(axis, follower, kind)
        seen.add(part)
        text = scene_text(math.degrees(axis), follower, kind)
        if part in ("base circle", "tangent flank"):
            with pytest.raises(SceneError, match="dwells" if part == "base circle"
                               else "straight flank"):
                parse_scene(parse_toml(text, "cam.toml"), file="cam.toml")
            continue
        sol = solve(parse_scene(parse_toml(text, "cam.toml"), file="cam.toml"))
        # a flat face: R is the yoke's point under the centre of curvature, the face ρ beyond
        rho = {"nose": R2, "flank": RF}[part] if follower == "flat" else 0.0
        assert quantity(sol, "y(R)") + rho == pytest.approx(s, rel=1e-12), (k, part)
        assert quantity(sol, "vs(R)") == pytest.approx(v, rel=1e-9, abs=1e-12), (k, part)
        assert quantity(sol, "as(R)") == pytest.approx(a, rel=1e-9, abs=1e-9), (k, part)
    assert {"nose", "base circle"} <= seen
    assert ("flank" in seen) == (kind == "circular arc")


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


def test_the_interactive_page_is_refused_in_one_line(tmp_path):
    from polygons.cli import main
    assert main(["handout", str(CASE), "--interactive", "-o", str(tmp_path / "p.html")]) == 1
    assert not (tmp_path / "p.html").exists()
