"""Forces through a cam: the contact force of the equivalent linkage against the follower's
equation of motion along its guide and the cam's moment equation, written here by hand (never
the solver), on the shipped case and on random cams; the oscillating flat face against the
arm's moment equation with the tangency condition differentiated by hand; a lost contact, the
refusals."""
import math
import re
from pathlib import Path

import numpy as np
import pytest

from analytic_contacts import oscillating_flat_follower
from polygons.errors import PolygonsError, UnsupportedError
from polygons.forces import analyse
from polygons.scene import load_scene, parse_scene, parse_toml

CASES = Path(__file__).resolve().parent.parent / "cases"


def _scene(text: str):
    return parse_scene(parse_toml(text, "x.toml"), file="x.toml")


def roller_follower(e, theta, omega, alpha, radius, roller, m, P, g):
    """An in-line translating roller follower on the +y axis through the shaft O, on a
    circular arc (centre C at e from O, at θ) of ``radius``: L = radius + roller,
    y = e sin θ + s, s = √(L² − e² cos² θ);  y' = e cos θ + e² cos θ sin θ / s,
    y'' = −e sin θ + e² (cos² θ − sin² θ)/s − e⁴ cos² θ sin² θ / s³;  v = y' ω,
    a = y'' ω² + y' α.  The contact force N along n = (R − C)/L:  N n_y − P − m g = m a
    (P the spring's force downwards);  the cam's torque T = C × N n (its only other force,
    at the massless cam's pivot O, has no moment)."""
    c, s_ = math.cos(theta), math.sin(theta)
    L = radius + roller
    s = math.sqrt(L * L - e * e * c * c)
    y = e * s_ + s
    y1 = e * c + e * e * c * s_ / s
    y2 = -e * s_ + e * e * (c * c - s_ * s_) / s - e ** 4 * c * c * s_ * s_ / s ** 3
    v, a = y1 * omega, y2 * omega * omega + y1 * alpha
    C = np.array([e * c, e * s_])
    n = (np.array([0.0, y]) - C) / L
    N = (P + m * g + m * a) / n[1]
    T = float(C[0] * N * n[1] - C[1] * N * n[0])
    phi = math.acos(abs(n[1]))
    return {"N": N, "T": T, "v": v, "a": a, "phi": phi, "n": n}


def _roller_text(e, theta, omega, alpha, radius, roller, m, P, g):
    return f"""
title = "random roller follower"
[ground]
O = ["0 m", "0 m"]
[links]
OC = "{e!r} m"
[driver]
crank = "OC"
angle = "{theta!r} rad"
omega = "{abs(omega)!r} rad/s"
sense = "{'CCW' if omega > 0 else 'CW'}"
alpha = "{abs(alpha)!r} rad/s^2"
alpha_sense = "{'CCW' if alpha > 0 else 'CW'}"
[sliders.R]
through = ["0 m", "0 m"]
direction = "90 deg"
[cams.R]
centre = "C"
radius = "{radius!r} m"
roller = "{roller!r} m"
[assembly]
R = "R above O"
[masses.R]
mass = "{m!r} kg"
[gravity]
g = "{g!r} m/s^2"
[forces.Spring]
at = "R"
magnitude = "{P!r} N"
direction = "-90 deg"
"""


def test_shipped_case_equals_the_follower_equation_of_motion():
    """cases/cam-roller-forces.toml: its exact force answers are the closed form here."""
    scene = load_scene(CASES / "cam-roller-forces.toml")
    ex = roller_follower(0.025, math.radians(60), 20.0, 0.0, 0.04, 0.01, 2.0, 100.0, 9.81)
    an = analyse(scene)
    st = an.states[0]
    (c,) = st.contacts
    assert c.label == "R" and c.cam == "OC" and c.follower == "R" and not c.lost
    assert abs(c.push - ex["N"]) < 1e-9 * ex["N"]
    assert abs(st.ne.effort - ex["T"]) < 1e-9 * abs(ex["T"])
    assert abs(c.pressure_angle - ex["phi"]) < 1e-12
    want = {"Fc(R)": ex["N"], "Tin": abs(ex["T"]), "phi(R)": math.degrees(ex["phi"])}
    got = {a.quantity: a.exact for a in scene.loads.answers}
    assert set(want) <= set(got)
    for q, w in want.items():
        assert abs(got[q] - w) < 1e-9 * abs(w), q
    kin = {a.quantity: a.exact for a in scene.answers}
    assert kin == pytest.approx({"v(R)": abs(ex["v"]), "a(R)": abs(ex["a"])}, rel=1e-12)


def test_random_roller_followers():
    rng = np.random.default_rng(11)
    done = 0
    while done < 25:
        e, radius, roller = rng.uniform(0.01, 0.03), rng.uniform(0.035, 0.06), \
            rng.uniform(0.0, 0.015)
        theta = rng.uniform(-math.pi, math.pi)
        omega = rng.choice((-1, 1)) * rng.uniform(1, 30)
        alpha = rng.uniform(-50, 50)
        m, P, g = rng.uniform(0.2, 5), rng.uniform(0, 300), rng.choice((0.0, 9.81))
        args = tuple(float(x) for x in (e, theta, omega, alpha, radius, roller, m, P, g))
        ex = roller_follower(*args)
        st = analyse(_scene(_roller_text(*args))).states[0]
        (c,) = st.contacts
        assert np.allclose(c.force, ex["N"] * ex["n"], rtol=1e-9, atol=1e-9 * abs(ex["N"]))
        assert abs(c.push - ex["N"]) <= 1e-9 * max(1.0, abs(ex["N"]))
        assert c.lost == (ex["N"] < 0)
        assert abs(st.ne.effort - ex["T"]) <= 1e-9 * max(1.0, abs(ex["T"]))
        done += 1


def test_a_cam_that_would_have_to_pull_says_the_follower_leaves_it():
    """The spring lifting the follower instead of holding it down: N < 0, said in a warning
    and in the JSON (contact_lost); `Fc` is then negative."""
    args = (0.025, math.radians(60), 20.0, 0.0, 0.04, 0.01, 2.0, -100.0, 0.0)
    ex = roller_follower(*args)
    assert ex["N"] < 0
    st = analyse(_scene(_roller_text(*args))).states[0]
    (c,) = st.contacts
    assert c.lost and abs(c.push - ex["N"]) < 1e-9 * abs(ex["N"])
    assert any("leaves the cam" in w for w in st.warnings)


def test_translating_flat_face_is_the_scotch_yoke_equation():
    """cam-flat-follower with a mass, gravity and a spring: N = P + m (g + a), a = −e ω² sin θ
    (tests/analytic_contacts.flat_follower's closed form), vertical, at C's abscissa:
    T = N · C_x."""
    text = (CASES / "cam-flat-follower.toml").read_text().split("[[answers]]")[0] + """
[masses.F]
mass = "1.5 kg"
[gravity]
g = "9.81 m/s^2"
[forces.Spring]
at = "F"
magnitude = "50 N"
direction = "-90 deg"
"""
    st = analyse(_scene(text)).states[0]
    e, th, w = 0.02, math.radians(30), 10.0
    a = -e * w * w * math.sin(th)
    N = 50.0 + 1.5 * (9.81 + a)
    (c,) = st.contacts
    assert c.kind == "flat-faced cam" and c.follower == "F" and c.push is None
    assert np.allclose(c.force, (0.0, N), rtol=0, atol=1e-9 * N)
    assert abs(st.ne.effort - N * e * math.cos(th)) < 1e-9 * N * e
    assert c.pressure_angle == pytest.approx(0.0, abs=1e-12)


def test_oscillating_flat_face_is_the_arm_moment_equation():
    """cam-oscillating-flat-follower with a uniform arm (0.8 kg, I_Q = m l²/3), gravity and a
    2 N m CW spring torque: the arm's moment about Q,  d·N − M_s − m g (G_x − Q_x)·… = I_Q α,
    gives the push N at the contact d along the arm from Q (the face through Q); the input
    torque is the power balance T ω = I_Q ω_a α_a + m g v_Gy − M_s ω_a."""
    text = (CASES / "cam-oscillating-flat-follower.toml").read_text().split("[[answers]]")[0]
    text += """
[masses.QF]
mass = "0.8 kg"
[gravity]
g = "9.81 m/s^2"
[torques.Spring]
on = "QF"
torque = "2 N m"
sense = "CW"
"""
    st = analyse(_scene(text)).states[0]
    sol = st.sol
    Q = np.array([0.1, 0.08])
    C = 0.02 * np.array([math.cos(math.radians(30)), math.sin(math.radians(30))])
    ex = oscillating_flat_follower((0, 0), 0.02, math.radians(30), 10.0, tuple(Q), 0.05, -1,
                                   math.atan2(C[1] - Q[1], C[0] - Q[0]))
    wa, aa, phi = ex["omega"], ex["alpha"], ex["phi"]
    u = np.array([math.cos(phi), math.sin(phi)])
    left = np.array([-u[1], u[0]])
    m, l, g, Ms = 0.8, 0.15, 9.81, -2.0
    IQ = m * l * l / 3
    G = Q + 0.5 * l * u
    # the contact: the foot of the perpendicular from C on the face (the arm line through Q)
    d = float((C - Q) @ u)
    contact = Q + d * u
    assert (C - Q) @ left < 0                        # the cam on the arm's right
    # moment about Q of the contact force push·left at `contact`: d·push
    push = (IQ * aa - Ms + m * g * (G[0] - Q[0])) / d
    (c,) = st.contacts
    assert np.allclose(c.contact, contact, atol=1e-12)
    assert abs(c.push - push) < 1e-9 * abs(push) and not c.lost
    T = (IQ * wa * aa + m * g * wa * (G[0] - Q[0]) - Ms * wa) / 10.0
    assert abs(st.ne.effort - T) < 1e-9 * abs(T)
    assert sol.links["QF"].omega == pytest.approx(wa, rel=1e-9)


def test_curved_slot_force_is_normal_to_the_slot():
    """A pin in a circular-arc slot: the force on the pin's body lies along KP (normal to the
    slot); a slot has two walls, so no push check."""
    text = (CASES / "curved-slot-pin.toml").read_text().split("[[answers]]")[0]
    scene0 = _scene(text)
    body = next(n for n, b in scene0.links.items() if n != "KP")
    text += f"""
[masses.{body}]
mass = "1 kg"
[gravity]
g = "9.81 m/s^2"
"""
    st = analyse(_scene(text)).states[0]
    (c,) = st.contacts
    K = np.array(st.sol.points["K"].position)
    P = np.array(st.sol.points["P"].position)
    n = (P - K) / np.hypot(*(P - K))
    f = np.array(c.force)
    assert abs(f[0] * n[1] - f[1] * n[0]) < 1e-9 * max(1.0, np.hypot(*f))
    assert c.push is None and c.kind == "curved slot"


@pytest.mark.parametrize("table,words", [
    ('[masses.CR]\nmass = "1 kg"\n', "CR is the equivalent link of the cam at R"),
    ('[forces.X]\nat = "R"\non = "CR"\nmagnitude = "1 N"\ndirection = "0 deg"\n',
     "CR is the equivalent link"),
])
def test_no_load_on_the_equivalent_link(table, words):
    text = _roller_text(0.025, 1.0, 20.0, 0.0, 0.04, 0.01, 2.0, 100.0, 9.81) + table
    with pytest.raises(PolygonsError, match=words):
        analyse(_scene(text))


@pytest.mark.parametrize("stem,words", [
    ("rolling-cylinder-between-plates", "between plates"),
    ("rolling-wheel-rim-pin", "a wheel driving the linkage"),
    ("bar-on-half-cylinder", "a bar bearing on a circle"),
])
def test_other_rolling_contacts_with_loads_are_refused(stem, words):
    text = (CASES / f"{stem}.toml").read_text().split("[[answers]]")[0]
    with pytest.raises(UnsupportedError, match="does not handle a rolling contact") as e:
        _scene(text + '\n[gravity]\ng = "9.81 m/s^2"\n')
    assert words in str(e.value)


def test_force_answers_name_an_unknown_follower():
    from polygons.forces import check_force_answers
    text = _roller_text(0.025, 1.0, 20.0, 0.0, 0.04, 0.01, 2.0, 100.0, 9.81) + \
        '[[force_answers]]\nquantity = "Fc(Q)"\nunit = "N"\nexact = 1.0\n'
    an = analyse(_scene(text))
    with pytest.raises(PolygonsError, match="not the follower's point"):
        check_force_answers(an)


def test_the_handout_s_force_section_states_the_contact_force(tmp_path):
    from polygons.cli.handout import build
    path = tmp_path / "cam.toml"
    path.write_text((CASES / "cam-roller-forces.toml").read_text()
                    + "\n[handout]\nforce_polygons = true\n")
    key = build(str(path))
    assert '<p class="force-contact">' in key and "along the common normal" in key
    assert "99.7878 N" in key


# ---------------------------------------------------------------- a wheel rolling on the floor
def rolling_wheel_forces(theta, omega, alpha, m, I, g, r=0.05, OA=0.04, AW=0.15, y=0.02):
    """The crank OA drives a massless rod AW to the centre W of a wheel (mass m, I_G) rolling
    without slipping on the floor, its centre on the line y (tests/analytic.py slider_crank,
    never the solver).  Rolling: ω_W = −v_W/r, α_W = −a_W/r.  The wheel:
        x: P u_x + F = m a_W,  y: P u_y + N − m g = 0,  about W: r F = I_G α_W
    (F the friction at the contact below W, P the rod's force along u = (W − A)/|W − A|);
    the crank: T = A × P u.  Also the power balance T ω = m a_W v_W + I_G α_W ω_W."""
    import analytic
    k = analytic.slider_crank((0.0, 0.0), OA, AW, theta, omega, alpha, (0.0, y), 0.0, +1)
    vW, aW = k["vB"][0], k["aB"][0]
    wW, alW = -vW / r, -aW / r
    F = I * alW / r
    A, W = k["A"], k["B"]
    u = (W - A) / np.hypot(*(W - A))
    P = (m * aW - F) / u[0]
    N = m * g - P * u[1]
    T = float(A[0] * P * u[1] - A[1] * P * u[0])
    assert abs(T * omega - (m * aW * vW + I * alW * wW)) <= 1e-9 * max(1.0, abs(T * omega))
    return {"F": F, "N": N, "T": T, "mu": abs(F) / N, "aW": aW, "vW": vW, "alpha": alW}


def _wheel_text(theta, omega, alpha, m, g):
    return f"""
title = "wheel driven by a crank and rod"
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "40 mm"
AW = "150 mm"
[driver]
crank = "OA"
angle = "{theta!r} rad"
omega = "{abs(omega)!r} rad/s"
sense = "{'CCW' if omega > 0 else 'CW'}"
alpha = "{abs(alpha)!r} rad/s^2"
alpha_sense = "{'CCW' if alpha > 0 else 'CW'}"
[rolling.W]
radius = "50 mm"
through = ["0 mm", "-30 mm"]
direction = "0 deg"
[assembly]
W = "W right of O"
[masses.W]
mass = "{m!r} kg"
[gravity]
g = "{g!r} m/s^2"
"""


def test_shipped_rolling_case_is_the_wheel_s_equations():
    scene = load_scene(CASES / "rolling-wheel-forces.toml")
    ex = rolling_wheel_forces(math.radians(50), 12.0, 0.0, 3.0, 0.5 * 3.0 * 0.05 ** 2, 9.81)
    st = analyse(scene).states[0]
    f, e, at = st.ne.rolling["W"]
    assert abs(f - ex["F"]) <= 1e-9 * abs(ex["F"])
    assert abs(st.ne.guide["W"][0] - ex["N"]) <= 1e-9 * ex["N"]
    assert abs(st.ne.effort - ex["T"]) <= 1e-9 * abs(ex["T"])
    assert np.allclose(at, (st.sol.points["W"].position[0], -0.03), atol=1e-12)
    want = {"Ff(W)": ex["F"], "Rg(W)": ex["N"], "mu(W)": ex["mu"], "Tin": abs(ex["T"])}
    got = {a.quantity: a.exact for a in scene.loads.answers}
    for q, w in want.items():
        assert abs(got[q] - w) <= 1e-9 * abs(w), q
    kin = {a.quantity: a.exact for a in scene.answers}
    assert kin == pytest.approx({"v(W)": abs(ex["vW"]), "a(W)": abs(ex["aW"]),
                                 "alpha(W)": abs(ex["alpha"])}, rel=1e-12)


@pytest.mark.parametrize("seed", range(10))
def test_random_wheels_rolling_under_a_crank(seed):
    rng = np.random.default_rng(100 + seed)
    theta = float(rng.uniform(-math.pi, math.pi))
    omega = float(rng.choice((-1, 1)) * rng.uniform(2, 30))
    alpha = float(rng.uniform(-100, 100))
    m, g = float(rng.uniform(0.5, 5)), float(rng.choice((0.0, 9.81)))
    ex = rolling_wheel_forces(theta, omega, alpha, m, 0.5 * m * 0.05 ** 2, g)
    st = analyse(_scene(_wheel_text(theta, omega, alpha, m, g))).states[0]
    f = st.ne.rolling["W"][0]
    assert abs(f - ex["F"]) <= 1e-9 * max(1.0, abs(ex["F"]))
    assert abs(st.ne.guide["W"][0] - ex["N"]) <= 1e-9 * max(1.0, abs(ex["N"]))
    assert abs(st.ne.effort - ex["T"]) <= 1e-9 * max(1.0, abs(ex["T"]))
    assert abs(st.vw_effort - ex["T"]) <= 1e-9 * max(1.0, abs(ex["T"]))
    lifted = ex["N"] <= 0
    assert any("leaves it" in w for w in st.warnings) == lifted


def test_a_rolling_wheel_is_refused_by_the_force_polygons_and_taken_by_the_lever():
    """Zhukovsky's lever: the wheel's velocity image turns with it, so a brake torque on the
    wheel (a pair at its centre and its rim) and its inertia couple do their work there."""
    from polygons.forces import graphical, zhukovsky
    brake = '[torques.Brake]\non = "W"\ntorque = "0.5 N m"\nsense = "CW"\n'
    an = analyse(_scene(_wheel_text(0.9, 12.0, 30.0, 3.0, 9.81) + brake))
    st = an.states[0]
    with pytest.raises(UnsupportedError, match="does not handle a rolling contact"):
        graphical.construct(an, st)
    lever = zhukovsky.construct(an, st)
    assert abs(lever.effort - st.ne.effort) <= 1e-9 * abs(st.ne.effort)


def test_the_wheel_s_free_body_closes_with_friction_at_its_contact(tmp_path):
    """The free body of the wheel: the surface's normal and friction at the contact (not a
    guide force at the centre), and with its inertia force the forces sum to zero and their
    moments about the centre to −(−I_G α); the SVG draws the rim."""
    from diagrams.fbd import body_forces, write
    an = analyse(load_scene(CASES / "rolling-wheel-forces.toml"))
    st = an.states[0]
    vecs, couples = body_forces(an, st, "W")
    names = [v.name for v in vecs]
    assert "N_W (surface)" in names and "F_W (friction)" in names
    assert not any("guide" in n for n in names)
    W = np.array(st.sol.points["W"].position)
    total = sum((v.force for v in vecs), np.zeros(2))
    assert np.allclose(total, 0.0, atol=1e-9)
    moment = sum(float((v.at - W)[0] * v.force[1] - (v.at - W)[1] * v.force[0]) for v in vecs)
    moment += sum(c.value for c in couples)
    assert abs(moment) < 1e-9
    files = write(an, tmp_path)
    svg = next(p for p in files if p.name == "fbd-instant-w.svg").read_text()
    assert "wheel W" in svg


# ---------------------------------------------------------------- the turning-moment diagram
def _crank_under_gravity(n_text=""):
    return """
title = "crank with a weight at its tip"
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "200 mm"
[driver]
crank = "OA"
angle = "30 deg"
omega = "10 rad/s"
sense = "CCW"
[masses.Tip]
at = "A"
mass = "5 kg"
[gravity]
g = "9.81 m/s^2"
"""


def test_turning_moment_of_a_weight_on_a_crank_is_m_g_r_cos_theta():
    """A point mass at the crank's tip at constant ω: its inertia force is centripetal
    (through O), so T(θ) = m g r cos θ exactly, the mean is 0 and E(θ) = m g r sin θ + c:
    ΔE = 2 m g r, greatest at 90°, least at 270°, T greatest m g r at 0° — exactly (the
    quadrature's, not the samples': 20 of them)."""
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import turning_moment
    scene = _scene(_crank_under_gravity())
    cy = turning_moment(load_model(scene), scene, 20)
    mgr = 5 * 9.81 * 0.2
    assert np.allclose(cy.torque, mgr * np.cos(cy.theta), rtol=0, atol=1e-9 * mgr)
    assert cy.mean == 0.0
    assert cy.fluctuation == pytest.approx(2 * mgr, rel=1e-10)
    assert math.degrees(cy.at_max) % 360 == pytest.approx(90.0, abs=1e-7)
    assert math.degrees(cy.at_min) % 360 == pytest.approx(270.0, abs=1e-7)
    assert cy.max_torque[0] == pytest.approx(mgr, rel=1e-12)
    assert cy.min_torque[0] == pytest.approx(-mgr, rel=1e-12)
    assert cy.vw_error < 1e-9 * mgr
    assert cy.flywheel_inertia(0.02) == pytest.approx(cy.fluctuation / (100 * 0.02))


def test_turning_moment_of_a_piston_s_inertia_is_its_power():
    """An engine whose only mass is the piston (massless crank and rod), at constant ω:
    T ω = m a_P v_P at every angle, a_P and v_P from tests/analytic.py's slider-crank loop."""
    import analytic
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import turning_moment
    text = """
title = "engine, piston inertia only"
[ground]
O = ["0 mm", "0 mm"]
[links]
OA = "50 mm"
AB = "200 mm"
[sliders.B]
through = ["0 mm", "0 mm"]
direction = "0 deg"
[driver]
crank = "OA"
angle = "40 deg"
omega = "100 rad/s"
sense = "CCW"
[assembly]
B = "B right of O"
[masses.B]
mass = "2 kg"
"""
    scene = _scene(text)
    cy = turning_moment(load_model(scene), scene, 90)
    for th, T in zip(cy.theta, cy.torque):
        k = analytic.slider_crank((0, 0), 0.05, 0.2, float(th), 100.0, 0.0, (0, 0), 0.0, +1)
        want = 2.0 * float(k["aB"] @ k["vB"]) / 100.0
        assert abs(T - want) <= 1e-9 * 2.0 * 0.05 * 100.0 ** 2 * 0.05


def test_turning_moment_refusals_and_cli(tmp_path):
    from polygons.cli import main
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import turning_moment
    scene = _scene(_crank_under_gravity())
    with pytest.raises(PolygonsError, match="4 to 3600"):
        turning_moment(load_model(scene), scene, 2)
    ladder = load_scene(CASES / "book-ladder-bar-omega.toml")
    with pytest.raises(UnsupportedError, match="driver is a slider"):
        turning_moment(load_model(ladder), ladder, 36)
    p = tmp_path / "w.toml"
    p.write_text(_crank_under_gravity())
    out = tmp_path / "o.txt"
    assert main(["forces", str(p), "--cycle", "36", "--fluctuation", "2 %", "-o", str(out),
                 "--svg", str(tmp_path / "d")]) == 0
    text = out.read_text()
    assert "maximum fluctuation of energy ΔE" in text and "I = ΔE / (ω² C_s)" in text
    assert (tmp_path / "d" / "turning-moment.svg").exists()
    assert main(["forces", str(p), "--fluctuation", "2 %"]) == 1    # said in one line


@pytest.mark.parametrize("stem", ["forces-triad", "forces-whitworth", "s001-we8",
                                  "forces-scotch-yoke", "forces-toggle-press",
                                  "cam-roller-forces", "rolling-wheel-forces",
                                  "khurmi-flywheel-steam-engine"])
def test_over_a_turn_steady_loads_do_no_net_work(stem):
    """Every load of these cases is steady (weights, constant forces and springs) and the
    crank turns uniformly, so the mechanism's energy returns after a turn: the mean input
    torque is zero (to the quadrature's 1e-9, from 24 samples) — a check of every angle's
    analysis at once
    (the triad's, with the case's α, was not: the diagram now takes α = 0)."""
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import turning_moment
    scene = load_scene(CASES / f"{stem}.toml")
    cy = turning_moment(load_model(scene), scene, 24, table=False)
    assert abs(cy.mean) <= 1e-9 * float(np.max(np.abs(cy.torque)))     # by quadrature
    assert cy.vw_error <= 1e-9 * float(np.max(np.abs(cy.torque)))


def test_a_resisting_cut_does_the_stroke_s_work_each_turn():
    """Whitworth with its 2 kN cut `resisting = true` (acting only on the working stroke):
    over a uniform turn the crank's work, |T_m|·2π, is the cut's, F × the ram's stroke (its
    travel's range, each end refined between samples) to 1e-9; at an instant of the return stroke the cut
    is absent."""
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import turning_moment
    from polygons.sweep import sweep
    text = (CASES / "forces-whitworth.toml").read_text().split("[[answers]]")[0].replace(
        'direction = "180 deg"', 'direction = "180 deg"\nresisting = true')
    scene = _scene(text)
    from polygons.sweep_extremes import greatest
    cy = turning_moment(load_model(scene), scene, 24, table=False)
    sw = sweep(scene, 360)
    stroke = (greatest(sw, lambda w: w.travel["R"])[0]
              + greatest(sw, lambda w: -w.travel["R"])[0])       # the ram's travel, exact
    assert abs(abs(cy.mean) * 2 * math.pi - 2000.0 * stroke) < 1e-9 * 2000.0 * stroke
    for angle, working in (("60 deg", True), ("240 deg", False)):   # ram +x / −x
        st = analyse(_scene(text.replace('angle = "60 deg"', f'angle = "{angle}"'))).states[0]
        assert (st.sol.points["R"].velocity[0] > 0) == working
        assert any(ld.source == "Cut" for ld in st.ne.loads) == working


def test_the_handout_s_turning_moment_section(tmp_path):
    """[handout] turning_moment = true: the plot (an inline SVG) and the numbers of the
    diagram (its ΔE the same from 12 samples as from the handout's 72); refused in one line, naming the key, where it cannot be drawn."""
    from polygons.cli.handout import build
    from polygons.forces.analysis import load_model
    from polygons.forces.cycle import turning_moment
    text = (CASES / "forces-whitworth.toml").read_text().replace(
        'direction = "180 deg"', 'direction = "180 deg"\nresisting = true')
    path = tmp_path / "w.toml"
    path.write_text(text + "\n[handout]\nturning_moment = true\n")
    key = build(str(path))
    sec = re.search(r'<section id="turning-moment".*?</section>', key, re.S).group(0)
    assert "<svg" in sec and "maximum fluctuation of energy ΔE" in sec
    scene = load_scene(str(path))
    cy = turning_moment(load_model(scene), scene, 12, table=False)   # the same numbers
    assert f"{cy.fluctuation:.6g} J".replace("-", "−") in sec
    osc = tmp_path / "o.toml"
    osc.write_text((CASES / "forces-oscillating-cylinder.toml").read_text()
                   + "\n[handout]\nturning_moment = true\n")
    with pytest.raises(UnsupportedError, match=r"turning_moment = true: the crank does not "):
        build(str(osc))


def test_the_handout_data_table_states_the_loads(tmp_path):
    """A force problem's data table (key and worksheet) lists its masses, gravity and forces
    as the problem states them, a resisting force said so."""
    from polygons.cli.handout import build
    text = (CASES / "forces-whitworth.toml").read_text().replace(
        'direction = "180 deg"', 'direction = "180 deg"\nresisting = true')
    path = tmp_path / "w.toml"
    path.write_text(text)
    for ws in (False, True):
        page = build(str(path), worksheet=ws)
        table = re.search(r'<table class="data">.*?</table>', page, re.S).group(0)
        for words in ("mass R</th><td", "30 kg on R", "gravity</th>", "g = 9.81 m/s² towards 270°",
                      "force Cut</th>", "2000 N at 180° at R on R; it acts only while it "
                      "opposes its point&#x27;s motion"):
            assert words in table, (ws, words)


def test_check_grades_a_student_s_force_answers():
    """`polygons check --measured Tin=1.75 "Fc(R)=100"`: force answers graded against the
    force analysis with the case's stated tolerance (3 %), a wrong one off with a hint; a case
    without loads refuses them in one line."""
    from conftest import cli

    def run(*args):
        p = cli("check", *args)          # the entry point function, in this process
        return p.returncode, p.stdout, p.stderr
    case = str(CASES / "cam-roller-forces.toml")
    code, out, _ = run(case, "--measured", "Tin=1.75", "Fc(R)=100", "v(R)=0.36")
    assert code == 0 and "3 of 3 within tolerance" in out
    assert "expected 1.748 N m" in out and "expected 99.79 N" in out
    code, out, _ = run(case, "--measured", "Tin=1.5")
    assert code == 3 and "off: Tin" in out and "polygons forces" in out
    code, _, err = run(str(CASES / "s003-fig7.toml"), "--measured", "Tin=1")
    assert code == 1 and err.count("\n") == 1 and "needs the scene's loads" in err
