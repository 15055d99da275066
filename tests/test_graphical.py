"""The drawing board's force methods (issue 23 items 1, 2, 6): force polygons per Assur group,
Zhukovsky's lever, and the unknown effort anywhere.

Every reaction of the force polygons equals Newton–Euler's (polygons/forces/newton_euler.py)
to 1e-9 on every shipped case with loads whose kinds the construction handles (refused in one
line naming the kind otherwise); the lever's effort equals the virtual work's to 1e-9 on every
case with loads; the effort cases' answers equal closed forms written here from the loop
solutions of tests/analytic.py (power balance by hand), independent of all three methods.
"""
from __future__ import annotations

import cmath
import math
from pathlib import Path

import numpy as np
import pytest

import analytic
from conftest import cli
from polygons.errors import PolygonsError, UnsupportedError
from polygons.forces import analyse, has_forces
from polygons.forces import graphical, zhukovsky
from polygons.evaluate import solve
from polygons.scene import load_scene

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted((ROOT / "cases").glob("*.toml"))
REL = 1e-9


def _loaded():
    out = []
    for p in CASES:
        sc = load_scene(p)
        if has_forces(sc):
            out.append(p)
    return out


LOADED = _loaded()


@pytest.fixture(scope="module")
def analysed():
    memo = {}

    def get(path):
        if path not in memo:
            memo[path] = analyse(load_scene(path))
        return memo[path]
    return get


def test_there_are_cases_for_each_method():
    handled = [p for p in LOADED if graphical.handled(load_scene(p)) is None]
    assert len(handled) >= 4 and len(LOADED) >= 8
    efforts = [p for p in LOADED if load_scene(p).loads.effort is not None]
    assert len(efforts) >= 2


@pytest.mark.parametrize("path", LOADED, ids=[p.stem for p in LOADED])
def test_force_polygons_equal_newton_euler(path, analysed):
    scene = load_scene(path)
    why = graphical.handled(scene)
    if why is not None:
        # refused in one line naming the kind (or the effort)
        assert "\n" not in why and ("does not handle" in why or "effort" in why)
        with pytest.raises(UnsupportedError):
            graphical.construct(analysed(path), analysed(path).states[0])
        return
    an = analysed(path)
    for st in an.states:
        fp = graphical.construct(an, st)
        ne = st.ne
        big = max([1.0] + [float(np.hypot(*v)) for v in ne.pin.values()])
        assert set(fp.pin) == set(ne.pin)
        for k, v in ne.pin.items():
            assert np.hypot(*(fp.pin[k] - v)) <= REL * big, (path.name, st.name, k)
        for k, v in ne.ground.items():
            assert np.hypot(*(fp.ground[k] - v)) <= REL * big
        for k, (n, _, c) in ne.guide.items():
            assert abs(fp.guide[k][0] - n) <= REL * big and abs(fp.guide[k][2] - c) <= REL * big
        assert set(fp.slot) == set(ne.slot)
        for k, (v, n) in ne.slot.items():
            assert np.hypot(*(fp.slot[k][0] * fp.slot[k][1] - v * n)) <= REL * big
        expected = ne.effort if ne.effort is not None else 0.0
        assert abs(fp.effort - expected) <= REL * max(1.0, abs(expected), big * 0.01)
        # each group's polygon closes: knowns + found sum to zero
        for g in fp.groups:
            total = sum((k.force for k in g.knowns), np.zeros(2))
            total = total + sum((f.force for f in g.normals + g.closing), np.zeros(2))
            assert np.hypot(*total) <= REL * big


@pytest.mark.parametrize("path", LOADED, ids=[p.stem for p in LOADED])
def test_zhukovsky_lever_equals_virtual_work(path, analysed):
    an = analysed(path)
    for st in an.states:
        lv = zhukovsky.construct(an, st)
        scale = max([1.0, abs(st.vw_effort)] + [abs(a.moment / lv.unit_moment)
                                                 for a in lv.applied])
        assert abs(lv.effort - st.vw_effort) <= REL * scale, (path.name, st.name)
        # moments about the pole balance
        total = lv.moment_sum + sum(a.moment for a in lv.effort_forces)
        assert abs(total) <= REL * max(1.0, *(abs(a.moment) for a in lv.applied))


def test_the_lever_moment_is_minus_the_power():
    """r × F with r the image turned 90° CCW is −F·v (the lever's principle)."""
    rng = np.random.default_rng(3)
    for _ in range(20):
        v, f = rng.normal(size=2), rng.normal(size=2)
        r = np.array([-v[1], v[0]])
        assert r[0] * f[1] - r[1] * f[0] == pytest.approx(-(f @ v), abs=1e-12)


# ---------------------------------------------------------------- the effort anywhere
def piston_effort_exact() -> float:
    """WE8's engine (OC 40 mm, PC 140 mm, 3000 rpm CW at 135°), 150 N m CCW on the crank,
    piston 0.5 kg: F v_P + T ω − m a_P v_P = 0 (power balance, closed-form kinematics)."""
    w = -3000 * 2 * math.pi / 60
    r = analytic.slider_crank((0, 0), 0.04, 0.14, math.radians(135), w, 0.0, (0, 0), 0.0, -1)
    vp, ap = float(r["s_dot"]), float(r["s_ddot"])
    return (0.5 * ap * vp - 150.0 * w) / vp


def actuator_effort_exact() -> float:
    """The four-bar of forces-actuator-four-bar: 200 N down at E (200 mm along BC, 40 mm
    left), rocker CD 2 kg uniform, g 9.81; actuator H (600, 0) → F (mid CD).
    E (u·v_F) + W·v_E + m g·v_G − m a_G·v_G − I α ω = 0, u from H to F."""
    r = analytic.four_bar((0, 0), (0.45, 0), 0.1, 0.4, 0.35, math.pi / 2, 12.0, 0.0, 1)
    e = analytic.coupler_point(r["B"], r["vB"], r["aB"], r["phi_BC"], r["omega_BC"],
                               r["alpha_BC"], 0.2, 0.04)
    D = np.array([0.45, 0.0])
    g = analytic.coupler_point(D, np.zeros(2), np.zeros(2), r["phi_CD"], r["omega_CD"],
                               r["alpha_CD"], 0.175, 0.0)
    H = np.array([0.6, 0.0])
    u = g["P"] - H
    u = u / np.hypot(*u)
    m, inertia = 2.0, 2.0 * 0.35 ** 2 / 12
    p = (np.array([0, -200.0]) @ e["vP"] + m * np.array([0, -9.81]) @ g["vP"]
         - m * g["aP"] @ g["vP"] - inertia * r["alpha_CD"] * r["omega_CD"])
    return float(-p / (u @ g["vP"]))


@pytest.mark.parametrize("name,exact", [("forces-engine-piston-effort", piston_effort_exact),
                                        ("forces-actuator-four-bar", actuator_effort_exact)])
def test_effort_anywhere_equals_the_closed_form(name, exact, analysed):
    an = analysed(ROOT / "cases" / f"{name}.toml")
    st = an.states[0]
    x = exact()
    assert st.ne.effort == pytest.approx(x, rel=REL)
    assert st.vw_effort == pytest.approx(x, rel=REL)
    assert zhukovsky.construct(an, st).effort == pytest.approx(x, rel=REL)


def test_a_slider_drivers_effort_is_a_force_without_a_sense(tmp_path):
    src = (ROOT / "cases" / "new-elliptic-trammel.toml").read_text()
    case = tmp_path / "t.toml"
    case.write_text(src + '\n[masses.AB]\nmass = "2 kg"\n')
    out = cli("forces", case, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    line = next(x for x in out.stdout.splitlines() if "(Newton–Euler)" in x)
    assert " N towards " in line and " CW" not in line and "CCW" not in line
    assert "turning moment" not in out.stdout


@pytest.mark.parametrize("effort,words", [
    ("torque on XY", "unknown link"), ("force at C2", "needs a slider"),
    ("force along", "must be"), ("force along QQQ", "names two points"),
    ("push it", "must be"), (3, "is a string")])
def test_bad_efforts_are_one_line(tmp_path, effort, words):
    src = (ROOT / "cases" / "forces-engine-piston-effort.toml").read_text()
    val = f'"{effort}"' if isinstance(effort, str) else str(effort)
    case = tmp_path / "bad.toml"
    case.write_text(src.replace('effort = "force at P"', f"effort = {val}"))
    with pytest.raises(PolygonsError) as e:
        load_scene(case)
    assert words in str(e.value) and "dynamics.effort" in str(e.value)


def test_effort_with_torque_driven_is_refused(tmp_path):
    src = (ROOT / "cases" / "s002-ex3.17.toml").read_text()
    case = tmp_path / "t.toml"
    case.write_text(src.replace("[dynamics]\n", '[dynamics]\neffort = "torque on DB"\n', 1))
    with pytest.raises(PolygonsError, match="kinetostatic"):
        load_scene(case)


# ---------------------------------------------------------------- the command
def test_forces_command_prints_both_methods_and_json(tmp_path):
    from polygons.cli.forces import to_dict
    an = analyse(load_scene(ROOT / "cases" / "s001-we8.toml"))
    data = to_dict(an)
    st = data["states"][0]
    assert st["zhukovsky"]["effort"] == pytest.approx(st["input"]["newton_euler"], rel=REL)
    groups = st["force_polygons"]["groups"]
    assert [g["kind"] for g in groups] == ["RRP", "crank"]
    assert st["force_polygons"]["effort"] == pytest.approx(st["input"]["newton_euler"],
                                                           rel=REL)
    an2 = analyse(load_scene(ROOT / "cases" / "s000-d225-2003-q3.toml"))
    st2 = to_dict(an2)["states"][0]
    assert [g["kind"] for g in st2["force_polygons"]["groups"]] == ["RPR", "crank"]
    # an effort away from the driver: refused in one line
    st3 = to_dict(analyse(load_scene(ROOT / "cases" / "forces-actuator-four-bar.toml")))
    why = st3["states"][0]["force_polygons"]["refused"]
    assert "the force-polygon construction finds the driver's effort" in why
    assert "\n" not in why


def toggle_torque_exact() -> float:
    """The toggle press of forces-toggle-press: T ω + Σ F·v − Σ m a_G·v_G − Σ I α ω = 0 on the
    closed-form loop solution (tests/analytic_more.py), uniform rods, g 9.81, 5 kN up at D."""
    import analytic_more as am
    w = 200 * 2 * math.pi / 60
    O = am.fixed(0, 0)
    A = am.crank(O, 0.08, math.radians(45), w, 0.0)
    C = am.fixed(0.3, 0.25)
    B, (wab, aab), (wcb, acb) = am.rrr(A, 0.32, C, 0.2, 0.38 + 0.07j)
    D, (wbd, abd), _ = am.rrp(B, 0.22, complex(0.3, 0), math.radians(90), 0.3 - 0.14j)
    g = -9.81j
    p = (5000j * D[1].conjugate()).real            # the stone's force on the head
    for (P, Q, m, L, om, al) in ((A, B, 3.0, 0.32, wab, aab), (C, B, 2.0, 0.2, wcb, acb),
                                 (B, D, 2.5, 0.22, wbd, abd)):
        G = am.image(P, Q, L / 2)
        p += (m * (g - G[2]) * G[1].conjugate()).real - m * L * L / 12 * al * om
    p += (20.0 * (g - D[2]) * D[1].conjugate()).real
    return -p / w


def test_toggle_press_torque_equals_the_closed_form(analysed):
    an = analysed(ROOT / "cases" / "forces-toggle-press.toml")
    st = an.states[0]
    fp = graphical.construct(an, st)
    x = toggle_torque_exact()
    assert [g.kind for g in fp.groups] == ["RRP", "RRR", "crank"]
    assert fp.effort == pytest.approx(x, rel=REL)
    assert zhukovsky.construct(an, st).effort == pytest.approx(x, rel=REL)


def test_drawings_of_every_loaded_case(analysed):
    """Every loaded case draws its group polygons (when handled) and its lever; each SVG is
    well-formed, the stages come before the finished drawing, no two labels overlap."""
    import xml.etree.ElementTree as ET
    from diagrams.forcepoly import group_drawings, joint_drawings, lever_drawings
    from diagrams.labels import text_box
    from diagrams.model import Text
    from diagrams.svg import to_svg
    for path in LOADED:
        an = analysed(path)
        st = an.states[0]
        ds = group_drawings(an, st) + joint_drawings(an, st) + lever_drawings(an, st)
        stems = [s for s, _ in ds]
        assert any(s.startswith("zhukovsky-") for s in stems), path.name
        if graphical.handled(load_scene(path)) is None:
            assert any(s.startswith("group-") for s in stems), path.name
        if path.stem == "forces-triad-truss":
            assert {f"joint-instant-2-{c}" for c in "bcx"} <= set(stems)
        for stem, d in ds[:12]:
            ET.fromstring(to_svg(d))
            for cls in ("labels",):
                texts = [t for t in d.items(cls) if isinstance(t, Text)]
                assert texts, (path.name, stem)
                boxes = [text_box(t.x, t.baseline, t.text, t.size, t.anchor) for t in texts]
                for i, a in enumerate(boxes):
                    for b in boxes[i + 1:]:
                        assert not a.overlaps(b), (path.name, stem)


def test_forces_svg_writes_the_force_methods(tmp_path):
    out = cli("forces", ROOT / "cases" / "forces-toggle-press.toml", "--svg", tmp_path,
              cwd=ROOT)
    assert out.returncode == 0, out.stderr
    names = {p.name for p in tmp_path.iterdir()}
    assert {"group-instant-1.svg", "group-instant-2.svg", "group-instant-3.svg",
            "group-instant-3-4.svg", "zhukovsky-instant.svg", "zhukovsky-instant-3.svg"} <= names


def _printed(scene, quantity):
    return next(a for a in scene.loads.answers if a.quantity == quantity)


def test_the_graphical_methods_reproduce_printed_answers(analysed):
    """Printed answers (read from the case files, with their drawing tolerance): Khurmi &
    Gupta's steam engine (turning moment 3929 N m, crank-pin radial force 11980 N) by the force
    polygons and the lever; Example 3.17 (seed 002, R1, R2, R7, R8) by the force polygons."""
    path = ROOT / "cases" / "khurmi-flywheel-steam-engine.toml"
    an = analysed(path)
    st = an.states[0]
    fp = graphical.construct(an, st)
    scene = an.model.scene
    t = _printed(scene, "Tturn")
    for ours in (-fp.effort, -zhukovsky.construct(an, st).effort):
        assert abs(abs(ours) - t.tutorial) <= t.tolerance * t.tutorial
    rr = _printed(scene, "Rr(C,OC)")
    oc = np.array(st.sol.points["C"].position) - np.array(st.sol.points["O"].position)
    radial = float(fp.pin[("C", "OC")] @ (oc / np.hypot(*oc)))
    assert abs(abs(radial) - rr.tutorial) <= rr.tolerance * rr.tutorial
    path = ROOT / "cases" / "s002-ex3.17.toml"
    an = analysed(path)
    fp = graphical.construct(an, an.states[0])
    for q, (lab, body, i) in {"Rx(O,OA)": ("O", "OA", 0), "Ry(O,OA)": ("O", "OA", 1),
                              "Rx(D,DB)": ("D", "DB", 0), "Ry(D,DB)": ("D", "DB", 1)}.items():
        a = _printed(an.model.scene, q)
        assert abs(fp.pin[(lab, body)][i] - a.tutorial) <= a.tolerance * abs(a.tutorial) + 1e-3


def test_the_diagonal_joins_the_two_bodies_parts(analysed):
    """In each dyad's polygon (K1, t1, K2, t2, closing sides) the diagonal drawn is the middle
    pin's force: from the closing sides' meeting point back to the end of the first body's
    part, equal to the reaction found (the massless coupler of efficiency-four-bar too); in a
    triad's, each corner's force on the plate, across its link's part."""
    from diagrams.forcepoly import _vectors
    for name in ("efficiency-four-bar", "forces-toggle-press", "s002-ex3.17", "s001-we8",
                 "forces-oscillating-cylinder", "forces-triad", "forces-triad-truss"):
        an = analysed(ROOT / "cases" / f"{name}.toml")
        fp = graphical.construct(an, an.states[0])
        for g in fp.groups:
            seq, _, diag = _vectors(g)
            verts = np.cumsum([np.zeros(2)] + [s[1] for s in seq], axis=0)
            assert len(diag) == {"triad": 3, "crank": 0, "RPR": 0, "RPP": 0}.get(g.kind, 1)
            for a, b, rname in diag:
                r = next(f for f in g.reactions if f.name == rname)
                assert np.hypot(*(verts[b] - verts[a] - r.force)) <= 1e-9 * max(1.0, r.value)


@pytest.mark.parametrize("name,source", [("forces-toggle-press", "new-toggle-press"),
                                         ("forces-actuator-four-bar", "efficiency-four-bar"),
                                         ("forces-engine-piston-effort", "s001-we8"),
                                         ("forces-whitworth", "new-whitworth"),
                                         ("forces-scotch-yoke", "scotch-yoke"),
                                         ("forces-oscillating-cylinder",
                                          "new-oscillating-cylinder"),
                                         ("forces-triad", "triad-plate-point"),
                                         ("forces-triad-truss", "triad-ternary-coupler")])
def test_the_force_cases_kinematic_answers_are_their_sources(name, source):
    """The force cases share their mechanism and instant with a case whose exact values
    have an independent check of their own: each kinematic answer is that case's, and the
    solver gives it (the shared check is then the independent one)."""
    from polygons.quantities import quantity
    mine, theirs = (load_scene(ROOT / "cases" / f"{n}.toml") for n in (name, source))
    exact = {a.quantity: a.exact for a in theirs.answers if a.exact is not None}
    sol = solve(mine)
    assert mine.answers
    for a in mine.answers:
        if a.quantity in exact:
            assert a.exact == pytest.approx(exact[a.quantity], rel=1e-12), a.quantity
        value = quantity(sol, a.quantity)
        value = value if a.mode == "signed" else abs(value)
        assert value == pytest.approx(a.exact, rel=1e-9), a.quantity


# ---------------------------------------------------------------- slots, yokes, triads
def _power(bodies, forces, g=-9.81j) -> float:
    """Σ (m g − m a_G)·v_G − I_G α ω + Σ F·v: every term's power but the driver's (complex
    motions (z, v, a) of tests/analytic_more.py)."""
    p = 0.0
    for m, inertia, G, w, al in bodies:
        p += (m * (g - G[2]) * G[1].conjugate()).real - inertia * al * w
    for f, v in forces:
        p += (f * v.conjugate()).real
    return p


def _rod(m, length):
    return m, m * length * length / 12


def _mid(P, Q):
    return tuple((p + q) / 2 for p, q in zip(P, Q))


def whitworth_torque_exact() -> float:
    """forces-whitworth: the quick return's loop (tests/analytic_more.py), CD, DR uniform rods
    of 4 and 6 kg, the ram 30 kg, 2 kN at the ram along −x, g 9.81."""
    import analytic_more as am
    w = -math.pi
    A = am.crank(am.fixed(0, 0), 0.15, math.radians(60), w, 0.0)
    C = am.fixed(0, -0.1)
    s = am.slot(A, C)
    D = am.lever_point(C, s["phi"], s["omega"], s["alpha"], 0.125)
    R, (wr, ar), _ = am.rrp(D, 0.5, complex(0, -0.1), 0.0, -0.45 - 0.1j)
    p = _power([(*_rod(4.0, 0.125), _mid(C, D), s["omega"], s["alpha"]),
                (*_rod(6.0, 0.5), _mid(D, R), wr, ar), (30.0, 0.0, R, 0.0, 0.0)],
               [(-2000.0, R[1])])
    return -p / w


def yoke_torque_exact() -> float:
    """forces-scotch-yoke: y = r sin θ, the crank a 1.5 kg rod, the yoke 5 kg, 400 N at 240°
    on the yoke, g 9.81."""
    import analytic_more as am
    w, th = 10.0, math.radians(30)
    P = am.crank(am.fixed(0, 0), 0.05, th, w, 0.0)
    Y = tuple(1j * z.imag for z in P)
    p = _power([(*_rod(1.5, 0.05), am.crank(am.fixed(0, 0), 0.025, th, w, 0.0), w, 0.0),
                (5.0, 0.0, Y, 0.0, 0.0)],
               [(400.0 * cmath.exp(1j * math.radians(240)), Y[1])])
    return -p / w


def cylinder_torque_exact() -> float:
    """forces-oscillating-cylinder: the pin on a moving slot (tests/analytic_more.py guided),
    O2P a 2 kg rod, the cylinder O4Q an 8 kg rod, 30 N m CW on O2P, g 9.81."""
    import analytic_more as am
    w, al, phi = -2.0, 5.0, math.radians(170)
    O2, O4 = am.fixed(0, 0), am.fixed(0.3, 0)
    X, (wt, at), *_ = am.guided(O2, 0.1, O4, phi, w, al, 0.0, 0.093 + 0.036j)
    p = _power([(*_rod(2.0, 0.1), _mid(O2, X), wt, at),
                (*_rod(8.0, 0.5), am.lever_point(O4, phi, w, al, 0.25), w, al)], [])
    p += -30.0 * wt
    return -p / w


def triad_torque_exact() -> float:
    """forces-triad: the class-III group by the independent oracle (tests/analytic_triad.py,
    Newton on the six distances from the solver's closure as a start), uniform rods OA 1,
    AB 2, BC 5, CD 2, XE 1.5 kg, 400 N at X along −x, g 9.81."""
    import analytic_more as am
    import analytic_triad as at
    w, al, th = -15.0, 50.0, math.radians(45)
    O = am.fixed(0, 0)
    A = am.crank(O, 0.08, th, w, al)
    D, E = am.fixed(0.32, -0.04), am.fixed(0.14, 0.28)
    L, xi, eta = 0.18, 0.09, 0.07
    lens = (0.22, 0.19, 0.13, L, math.hypot(L - xi, eta), math.hypot(xi, eta))
    sol = solve(load_scene(ROOT / "cases" / "forces-triad.toml"))
    guess = np.concatenate([sol.points[k].position for k in "BCX"])
    pts = at.solve_position(am.vec(A[0]), am.vec(D[0]), am.vec(E[0]), lens, guess)
    vel, acc = at.rates(*pts, *(am.vec(P[0]) for P in (A, D, E)),
                        *(am.vec(P[1]) for P in (A, D, E)), *(am.vec(P[2]) for P in (A, D, E)))
    B, C, X = (tuple(complex(*q) for q in m) for m in zip(pts, vel, acc))

    def rates(P, Q):
        return am.rates(P, Q)
    bodies = [(*_rod(1.0, 0.08), am.crank(O, 0.04, th, w, al), w, al)]
    for m, P, Q, ln in ((2.0, A, B, 0.22), (5.0, B, C, L), (2.0, C, D, 0.19),
                        (1.5, X, E, 0.13)):
        bodies.append((*_rod(m, ln), _mid(P, Q), *rates(P, Q)))
    p = _power(bodies, [(-400.0, X[1])])
    return -p / w


def triad_truss_torque_exact() -> float:
    """forces-triad-truss: the class-III group on the triangle BC, CX, BX by the independent
    oracle, uniform rods OA 1, AB 2, BC 3, CX 2, BX 2, CD 2, XE 1 kg, 300 N down at X,
    g 9.81."""
    import analytic_more as am
    import analytic_triad as at
    w, th = 10.0, math.radians(60)
    O = am.fixed(0, 0)
    A = am.crank(O, 0.1, th, w, 0.0)
    D, E = am.fixed(0.3, 0), am.fixed(0.15, 0.3)
    sol = solve(load_scene(ROOT / "cases" / "forces-triad-truss.toml"))
    guess = np.concatenate([sol.points[k].position for k in "BCX"])
    pts = at.solve_position(am.vec(A[0]), am.vec(D[0]), am.vec(E[0]),
                            (0.2, 0.2, 0.1, 0.15, 0.12, 0.1), guess)
    vel, acc = at.rates(*pts, *(am.vec(P[0]) for P in (A, D, E)),
                        *(am.vec(P[1]) for P in (A, D, E)), *(am.vec(P[2]) for P in (A, D, E)))
    B, C, X = (tuple(complex(*q) for q in m) for m in zip(pts, vel, acc))
    bodies = [(*_rod(1.0, 0.1), am.crank(O, 0.05, th, w, 0.0), w, 0.0)]
    for m, P, Q, ln in ((2.0, A, B, 0.2), (3.0, B, C, 0.15), (2.0, C, X, 0.12),
                        (2.0, B, X, 0.1), (2.0, C, D, 0.2), (1.0, X, E, 0.1)):
        bodies.append((*_rod(m, ln), _mid(P, Q), *am.rates(P, Q)))
    p = _power(bodies, [(-300j, X[1])])
    return -p / w


SLOT_CASES = {"forces-triad-truss": (triad_truss_torque_exact, ["triad", "crank"]),
"forces-whitworth": (whitworth_torque_exact, ["RRP", "RPR", "crank"]),
              "forces-scotch-yoke": (yoke_torque_exact, ["RPP", "crank"]),
              "forces-oscillating-cylinder": (cylinder_torque_exact,
                                              ["RRP, moving guide", "crank"]),
              "forces-triad": (triad_torque_exact, ["triad", "crank"])}


@pytest.mark.parametrize("name", sorted(SLOT_CASES))
def test_slot_yoke_and_triad_torques_equal_the_power_balance(name, analysed):
    """The input torque of each new kind's case (a slotted lever, a pin in a moving slot, the
    Scotch yoke, the class-III group) by the force polygons, Newton–Euler and Zhukovsky's
    lever equals a power balance on independent closed-form kinematics; the case's exact
    Tin is that value; each slot's force equals Newton–Euler's."""
    exact, kinds = SLOT_CASES[name]
    an = analysed(ROOT / "cases" / f"{name}.toml")
    st = an.states[0]
    fp = graphical.construct(an, st)
    x = exact()
    assert [g.kind for g in fp.groups] == kinds
    assert fp.effort == pytest.approx(x, rel=REL)
    assert st.ne.effort == pytest.approx(x, rel=REL)
    assert _printed(an.model.scene, "Tin").exact == pytest.approx(x, rel=1e-12)
    big = max([1.0] + [float(np.hypot(*v)) for v in st.ne.pin.values()])
    assert set(fp.slot) == set(st.ne.slot)
    for k, (v, n) in st.ne.slot.items():
        assert np.hypot(*(fp.slot[k][0] * fp.slot[k][1] - v * n)) <= REL * big


def _with_masses(path):
    """The case with a mass on every link of stated length and every slider or yoke, and
    gravity: its force polygons have something to carry (None: nothing to load)."""
    import tomllib
    from polygons.scene import parse_scene
    text = path.read_text(encoding="utf-8")
    extra = ""
    for b in load_scene(path).model.moving:
        if b.kind == "link" and b.length:
            extra += f'\n[masses.{b.name}]\nmass = "{1 + len(b.name) % 3} kg"\n'
        elif b.kind in ("block", "yoke"):
            extra += f'\n[masses.{b.name}]\nmass = "2 kg"\n'
    if not extra:
        return None
    return parse_scene(tomllib.loads(text + extra + '\n[gravity]\ng = "9.81 m/s^2"\n'),
                       file=str(path))


def test_force_polygons_equal_newton_euler_on_every_case_with_masses_added():
    """Every unloaded case whose kinds the construction handles (slotted levers, offset slots,
    pins in moving slots, yokes, triads on a ternary plate or a triangle of links, slider
    drivers), loaded with
    masses and gravity: each pin, slot and guide force and the effort equal Newton–Euler's."""
    kinds = set()
    truss = 0
    for path in CASES:
        if path in LOADED:
            continue
        try:
            scene = _with_masses(path)
            if scene is None or graphical.handled(scene) is not None:
                continue
            an = analyse(scene)
        except PolygonsError:
            continue                            # refused by the force analysis itself
        for st in an.states:
            fp = graphical.construct(an, st)
            ne = st.ne
            big = max([1.0] + [float(np.hypot(*v)) for v in ne.pin.values()])
            assert set(fp.pin) == set(ne.pin) and set(fp.slot) == set(ne.slot), path.name
            for k, v in ne.pin.items():
                assert np.hypot(*(fp.pin[k] - v)) <= REL * big, (path.name, k)
            for k, (v, n) in ne.slot.items():
                assert np.hypot(*(fp.slot[k][0] * fp.slot[k][1] - v * n)) <= REL * big
            for k, (n, _, c) in ne.guide.items():
                assert abs(fp.guide[k][0] - n) <= REL * big
                assert abs(fp.guide[k][2] - c) <= REL * big
            assert abs(fp.effort - (ne.effort or 0.0)) <= REL * big
            kinds |= {g.kind for g in fp.groups}
            truss += sum(1 for g in fp.groups for f in g.reactions if f.how == "joint") // 6
    assert {"RPR", "RPP", "RRP, moving guide", "triad", "slider driver"} <= kinds
    assert truss >= 2                       # triads whose plate is a triangle of links


def test_the_joints_of_a_triangle_plate_close(analysed):
    """forces-triad-truss: each joint's polygon (the forces on the pin B, C, X) closes; the
    first two joints close on the plate links not met before, the last only checks."""
    an = analysed(ROOT / "cases" / "forces-triad-truss.toml")
    fp = graphical.construct(an, an.states[0])
    assert [len(j.closing) for j in fp.joints] == [2, 1, 0]
    big = max(float(np.hypot(*v)) for v in fp.pin.values())
    for j in fp.joints:
        total = sum((k.force for k in j.knowns), np.zeros(2))
        total = total + sum((f.force for f in j.normals + j.closing), np.zeros(2))
        assert np.hypot(*total) <= REL * big, j.title
