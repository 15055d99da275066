"""Hard cases, for the staged constructor and the vectorised sweep alike: a four-bar 0.01° from
its toggle (finite, accurate to what float64 allows there, conditioning reported), exactly at a
toggle / change point (a clear error naming the step and the parallel lines), lengths that
cannot close, slider-crank dead centres (zero vectors, no NaN), Coriolis with zero sliding
velocity, and links from 1 µm to 100 m with ω from 1e-3 to 1e5 rad/s."""
import math
import random
from decimal import Decimal, getcontext

import numpy as np
import pytest

import analytic
from polygons.cli import main
from polygons.errors import AssemblyError, ConstructionError, ParallelLinesError
from polygons.evaluate import solve
from polygons.scene import parse_scene
from polygons.sweep import sweep

EPS = np.finfo(float).eps


def m(x):
    return f"{float(x)!r} m"


def four_bar_scene(A, D, ab, bc, cd, theta, omega, near, alpha=0.0):
    drv = {"crank": "AB", "angle": f"{float(theta)!r} rad", "omega": f"{abs(omega)!r} rad/s",
           "sense": "CCW" if omega > 0 else "CW"}
    if alpha:
        drv |= {"alpha": f"{abs(alpha)!r} rad/s^2", "alpha_sense": "CCW" if alpha > 0 else "CW"}
    return parse_scene({
        "ground": {"A": [m(A[0]), m(A[1])], "D": [m(D[0]), m(D[1])]},
        "links": {"AB": m(ab), "BC": m(bc), "DC": m(cd)},
        "driver": drv,
        "assembly": {"C": {"near": [m(near[0]), m(near[1])]}},
    })


def at(sw, key, label):
    """Row 0 of a sweep result as a plain 2-vector."""
    arr = getattr(sw, key)[label]
    return np.array([arr[0][0], arr[1][0]])


# ---------------------------------------------------------------- high-precision reference
def _four_bar_decimal(B, D, vB, aB, bc, cd, near):
    """C, v_C, a_C, ω/α of BC and DC for given (exact binary) B, v_B, a_B, D and lengths, in
    50-digit decimal arithmetic: the float64 inputs are taken as exact."""
    getcontext().prec = 50
    Bx, By, Dx, Dy = (Decimal(float(v)) for v in (*B, *D))
    r1, r2 = Decimal(float(bc)), Decimal(float(cd))
    dx, dy = Dx - Bx, Dy - By
    d2 = dx * dx + dy * dy
    a = (r1 * r1 - r2 * r2 + d2) / (2 * d2)
    h = (r1 * r1 / d2 - a * a).sqrt()
    cands = [(Bx + a * dx - s * h * dy, By + a * dy + s * h * dx) for s in (1, -1)]
    C = min(cands, key=lambda c: (float(c[0]) - near[0]) ** 2 + (float(c[1]) - near[1]) ** 2)
    m1 = (C[0] - Bx, C[1] - By)
    m2 = (C[0] - Dx, C[1] - Dy)
    det = m1[0] * m2[1] - m1[1] * m2[0]
    vb = [Decimal(float(v)) for v in vB]
    ab_ = [Decimal(float(v)) for v in aB]
    dv = (-vb[0], -vb[1])                     # v_D − v_B
    wb = (dv[0] * m2[0] + dv[1] * m2[1]) / det
    wd = (dv[0] * m1[0] + dv[1] * m1[1]) / det
    vC = (vb[0] - wb * m1[1], vb[1] + wb * m1[0])
    R = (wb * wb * m1[0] - wd * wd * m2[0] - ab_[0], wb * wb * m1[1] - wd * wd * m2[1] - ab_[1])
    alb = (R[0] * m2[0] + R[1] * m2[1]) / det
    ald = (R[0] * m1[0] + R[1] * m1[1]) / det
    aC = (ab_[0] - alb * m1[1] - wb * wb * m1[0], ab_[1] + alb * m1[0] - wb * wb * m1[1])
    f = lambda v: np.array([float(v[0]), float(v[1])])
    return {"C": f(C), "vC": f(vC), "aC": f(aC), "wBC": float(wb), "wDC": float(wd),
            "aBC": float(alb), "aDC": float(ald)}


def _allowed(B, D, vB, aB, bc, cd, near, samples=12, seed=5):
    """What float64 allows: how far the exact answer moves when every input is rounded
    differently (each perturbed by up to one unit in the last place)."""
    ref = _four_bar_decimal(B, D, vB, aB, bc, cd, near)
    rng = random.Random(seed)
    spread = {k: 0.0 for k in ref}

    def ulp(x):
        return x + rng.choice((-1, 1)) * abs(x) * EPS

    for _ in range(samples):
        pert = _four_bar_decimal([ulp(v) for v in B], [ulp(v) for v in D],
                                 [ulp(v) for v in vB], [ulp(v) for v in aB], ulp(bc), ulp(cd),
                                 near)
        for k in ref:
            spread[k] = max(spread[k], float(np.max(np.abs(np.asarray(pert[k]) -
                                                            np.asarray(ref[k])))))
    return ref, spread


def test_four_bar_a_hundredth_of_a_degree_from_toggle():
    # build it backwards so the angle between BC and DC at C is exactly 0.01° (up to rounding):
    # B from the crank, C along BC, D along the nearly stretched-out continuation of BC
    ab, bc, cd, theta, omega, alpha = 0.4, 0.9, 0.7, math.radians(70.0), 25.0, 300.0
    B = np.array([ab * math.cos(theta), ab * math.sin(theta)])
    phi = math.radians(-20.0)
    C = B + bc * np.array([math.cos(phi), math.sin(phi)])
    gamma = math.radians(0.01)
    D = C + cd * np.array([math.cos(phi + gamma), math.sin(phi + gamma)])
    scene = four_bar_scene((0, 0), D, ab, bc, cd, theta, omega, C, alpha)
    sol = solve(scene)
    sw = sweep(scene, inputs=[theta])

    # conditioning reported: the smallest construction angle is the 0.01° and it warns
    assert sol.min_intersection_angle_deg == pytest.approx(0.01, rel=1e-4)
    assert any("toggle" in w for w in sol.warnings)
    assert sw.angle_deg[0] == pytest.approx(0.01, rel=1e-4)

    P = sol.placement.points
    pc = sol.points["C"]
    assert all(math.isfinite(v) for v in (*pc.position, *pc.velocity, *pc.acceleration))
    vB, aB = sol.points["B"].velocity, sol.points["B"].acceleration
    ref, spread = _allowed(P["B"], P["D"], vB, aB, bc, cd, C)
    scale = {"C": bc, "vC": abs(omega) * ab, "aC": (omega ** 2 + abs(alpha)) * ab,
             "wBC": abs(omega), "wDC": abs(omega), "aBC": omega ** 2, "aDC": omega ** 2}
    staged = {"C": pc.position, "vC": pc.velocity, "aC": pc.acceleration,
              "wBC": sol.links["BC"].omega, "wDC": sol.links["DC"].omega,
              "aBC": sol.links["BC"].alpha, "aDC": sol.links["DC"].alpha}
    vector = {"C": at(sw, "pos", "C"), "vC": at(sw, "vel", "C"), "aC": at(sw, "acc", "C"),
              "wBC": sw.omega["BC"][0], "wDC": sw.omega["DC"][0],
              "aBC": sw.alpha["BC"][0], "aDC": sw.alpha["DC"][0]}
    for name, ours in (("staged", staged), ("sweep", vector)):
        for k in ref:
            err = float(np.max(np.abs(np.asarray(ours[k]) - ref[k])))
            allowed = max(spread[k], EPS * scale[k])
            assert err <= 10 * allowed, (name, k, err, allowed)
    # the numbers are large but finite: ω of the links is ~1/sin(0.01°) times the crank's
    assert abs(sol.links["DC"].omega) > 100 * abs(omega)


def test_exactly_at_toggle_names_the_step_and_the_parallel_lines(tmp_path, capsys):
    # B, C, D in line (BC + CD = BD exactly in binary): A=(0,0), B=(1,0), C=(3,0), D=(6,0)
    scene = four_bar_scene((0, 0), (6, 0), 1.0, 2.0, 3.0, 0.0, 10.0, (3, 0))
    with pytest.raises(ParallelLinesError) as exc:
        solve(scene)
    msg = str(exc.value)
    assert "step velocity" in msg and "line ⟂ BC" in msg and "line ⟂ DC" in msg
    assert "parallel" in msg and "toggle" in msg
    # the sweep refuses to follow a branch from a position where the closures coincide
    with pytest.raises(ConstructionError, match="toggle for C.*BC and DC are in line"):
        sweep(scene, 36)


def test_change_point_of_a_parallelogram_is_an_error_not_a_guess():
    # A=(0,0), D=(1,0), AB = DC = 0.5, BC = 1 at θ = 0: A, B, D, C all on the x axis
    scene = four_bar_scene((0, 0), (1, 0), 0.5, 1.0, 0.5, 0.0, 3.0, (1.5, 0))
    with pytest.raises(ParallelLinesError, match="line ⟂ BC.*line ⟂ DC.*parallel"):
        solve(scene)


def test_sweep_reports_and_splits_at_change_points():
    th = math.radians(60)
    B = (0.5 * math.cos(th), 0.5 * math.sin(th))
    scene = four_bar_scene((0, 0), (1, 0), 0.5, 1.0, 0.5, th, 3.0, (1 + B[0], B[1]))
    sw = sweep(scene, 360)
    assert sw.full_cycle
    toggles = [lim for lim in sw.limits if lim.kind == "toggle"]
    assert sorted(round(math.degrees(t.input) % 360.0, 3) % 360.0 for t in toggles) == [0.0, 180.0]
    assert all("BC and DC are in line" in t.reason for t in toggles)
    assert len(sw.segments) >= 2
    assert any("toggle at" in w for w in sw.warnings)
    # the grid point exactly at θ = 180° is the change point: its rates are NaN, not noise
    i = int(np.argmin(np.abs(sw.inputs - math.pi)))
    assert np.isnan(sw.omega["BC"][i])
    assert np.isfinite(sw.omega["BC"][i + 3])


def test_lengths_that_cannot_close(tmp_path, capsys):
    scene = four_bar_scene((0, 0), (1, 0), 0.1, 0.3, 0.2, 0.5, 3.0, (0.5, 0.2))
    for fn in (solve, lambda s: sweep(s, 36)):
        with pytest.raises(AssemblyError) as exc:
            fn(scene)
        msg = str(exc.value)
        assert "cannot close" in msg and "BC + DC" in msg and "shorter than BD" in msg
    path = tmp_path / "open.toml"
    path.write_text("""
[ground]
A = ["0 mm", "0 mm"]
D = ["1000 mm", "0 mm"]
[links]
AB = "100 mm"
BC = "300 mm"
DC = "200 mm"
[driver]
crank = "AB"
angle = "30 deg"
omega = "3 rad/s"
sense = "CCW"
""")
    assert main(["sweep", str(path), "--out", str(tmp_path), "--no-plot"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "open.toml" in err[0] and "cannot close" in err[0]


def _all_finite(sol):
    for s in sol.steps:
        for v in (s.at, s.vector, s.point, s.direction):
            if v is not None:
                assert all(math.isfinite(c) for c in v), s
        for v in (s.value, s.angle_deg):
            if v is not None:
                assert math.isfinite(v), s


@pytest.mark.parametrize("theta_deg", [0.0, 180.0])
def test_slider_crank_dead_centres_have_zero_vectors_and_no_nan(theta_deg):
    theta = math.radians(theta_deg)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]},
        "links": {"OA": "0.05 m", "AB": "0.12 m"},
        "driver": {"crank": "OA", "angle": f"{theta_deg} deg", "omega": "30 rev/min",
                   "sense": "CW"},
        "sliders": {"B": {"through": ["0 m", "0 m"], "direction": "0 deg"}},
        "assembly": {"B": "B right of A"},
    })
    sol = solve(scene)
    _all_finite(sol)
    w = 2 * math.pi * 30 / 60
    assert abs(sol.slides["B"].velocity) <= 1e-15 * w * 0.05
    assert abs(sol.links["AB"].omega) == pytest.approx(w * 0.05 / 0.12, rel=1e-14)
    assert abs(sol.links["AB"].alpha) <= 1e-14 * w * w
    # the zero vectors are there: b falls on the pole (ob = 0) and the tangential part
    # b1 -> b of the rod's acceleration has zero length; the records stay finite
    hits = {s.diagram: s for s in sol.steps if s.kind == "intersection" and s.end == "b"}
    assert math.hypot(*hits["velocity"].point) <= 1e-15 * w * 0.05
    b1 = sol.vertices["acceleration"]["b1"]
    tangential = np.subtract(hits["acceleration"].point, b1)
    assert math.hypot(*tangential) <= 1e-14 * w * w * 0.05
    ref = analytic.slider_crank((0, 0), 0.05, 0.12, theta, -w, 0.0, (0, 0), 0.0, 1)
    assert np.allclose(sol.points["B"].acceleration, ref["aB"], rtol=0, atol=1e-12 * w * w * 0.05)
    sw = sweep(scene, inputs=[theta])
    for key in ("pos", "vel", "acc"):
        assert np.all(np.isfinite(sw.__dict__[key]["B"][:, 0]))
    assert np.isfinite(sw.omega["AB"][0]) and np.isfinite(sw.alpha["AB"][0])
    assert sw.slide_a["B"][0] == pytest.approx(ref["s_ddot"], rel=1e-12)
    # and the full sweep passes the dead centres (they are not toggles of the construction)
    full = sweep(scene, 360)
    assert full.full_cycle and not full.warnings
    assert np.all(np.isfinite(full.slide_a["B"]))


def test_coriolis_with_zero_sliding_velocity():
    # crank pivot O above the lever pivot B; crank pointing straight up: O, A, B in line, so the
    # pin moves across the slot (no sliding) and the Coriolis component vanishes
    scene = parse_scene({
        "ground": {"B": ["0 m", "0 m"], "O": ["0 m", "0.45 m"]},
        "links": {"OA": "0.2 m"},
        "driver": {"crank": "OA", "angle": "90 deg", "omega": "50 rev/min", "sense": "CCW",
                   "alpha": "2 rad/s^2", "alpha_sense": "CW"},
        "slots": {"A": {"lever": "BA1"}},
    })
    sol = solve(scene)
    _all_finite(sol)
    w = 2 * math.pi * 50 / 60
    ref = analytic.slotted_lever((0, 0.45), 0.2, math.pi / 2, w, -2.0, (0, 0))
    assert abs(sol.slides["A"].velocity) <= 1e-15
    assert math.hypot(*sol.slides["A"].coriolis) <= 1e-15
    assert sol.links["BA1"].omega == pytest.approx(ref["omega_lever"], rel=1e-12)
    assert sol.links["BA1"].alpha == pytest.approx(ref["alpha_lever"], rel=1e-12)
    assert sol.slides["A"].acceleration == pytest.approx(ref["s_ddot"], rel=1e-12)
    sw = sweep(scene, inputs=[math.pi / 2])
    assert abs(sw.slide_v["A"][0]) <= 1e-15
    assert np.hypot(*sw.coriolis["A"][:, 0]) <= 1e-15
    assert sw.alpha["BA1"][0] == pytest.approx(ref["alpha_lever"], rel=1e-12)


SCALES = [1e-6, 1.0, 100.0]
OMEGAS = [1e-3, 1.0, 1e5]


@pytest.mark.parametrize("scale", SCALES)
@pytest.mark.parametrize("omega", OMEGAS)
def test_relative_accuracy_from_micrometres_to_100_m_and_slow_to_fast(scale, omega):
    tol = 1e-11
    alpha = 0.3 * omega * omega
    th = 1.1
    # four-bar
    A, D = (0.0, 0.0), (1.0 * scale, 0.2 * scale)
    ab, bc, cd = 0.4 * scale, 1.1 * scale, 0.8 * scale
    ref = analytic.four_bar(A, D, ab, bc, cd, th, omega, alpha, 1)
    scene = four_bar_scene(A, D, ab, bc, cd, th, omega, ref["C"], alpha)
    sol = solve(scene)
    sw = sweep(scene, inputs=[th])
    vs, as_ = omega * ab, (omega ** 2 + alpha) * ab
    for pos, vel, acc, w, al in (
            (sol.points["C"].position, sol.points["C"].velocity, sol.points["C"].acceleration,
             sol.links["DC"].omega, sol.links["DC"].alpha),
            (at(sw, "pos", "C"), at(sw, "vel", "C"), at(sw, "acc", "C"), sw.omega["DC"][0],
             sw.alpha["DC"][0])):
        assert np.hypot(*(np.array(pos) - ref["C"])) <= tol * scale
        assert np.hypot(*(np.array(vel) - ref["vC"])) <= tol * vs
        assert np.hypot(*(np.array(acc) - ref["aC"])) <= tol * as_
        assert abs(w - ref["omega_CD"]) <= tol * omega
        assert abs(al - ref["alpha_CD"]) <= tol * (omega ** 2 + alpha)
    # offset slider-crank
    r, L, off = 0.3 * scale, 1.0 * scale, 0.1 * scale
    ref = analytic.slider_crank((0, 0), r, L, th, omega, alpha, (0, off), 0.0, 1)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]},
        "links": {"OA": m(r), "AB": m(L)},
        "driver": {"crank": "OA", "angle": f"{th!r} rad", "omega": f"{omega!r} rad/s",
                   "sense": "CCW", "alpha": f"{alpha!r} rad/s^2", "alpha_sense": "CCW"},
        "sliders": {"B": {"through": ["0 m", m(off)], "direction": "0 deg"}},
        "assembly": {"B": "B right of A"},
    })
    sol = solve(scene)
    sw = sweep(scene, inputs=[th])
    vs, as_ = omega * r, (omega ** 2 + alpha) * r
    for v, a in ((sol.slides["B"].velocity, sol.slides["B"].acceleration),
                 (sw.slide_v["B"][0], sw.slide_a["B"][0])):
        assert abs(v - ref["s_dot"]) <= tol * vs
        assert abs(a - ref["s_ddot"]) <= tol * as_
    # slotted lever
    ref = analytic.slotted_lever((0, 0.45 * scale), 0.2 * scale, th, omega, alpha, (0, 0))
    scene = parse_scene({
        "ground": {"B": ["0 m", "0 m"], "O": ["0 m", m(0.45 * scale)]},
        "links": {"OA": m(0.2 * scale)},
        "driver": {"crank": "OA", "angle": f"{th!r} rad", "omega": f"{omega!r} rad/s",
                   "sense": "CCW", "alpha": f"{alpha!r} rad/s^2", "alpha_sense": "CCW"},
        "slots": {"A": {"lever": "BA1"}},
    })
    sol = solve(scene)
    sw = sweep(scene, inputs=[th])
    for w, al, sdd in ((sol.links["BA1"].omega, sol.links["BA1"].alpha,
                        sol.slides["A"].acceleration),
                       (sw.omega["BA1"][0], sw.alpha["BA1"][0], sw.slide_a["A"][0])):
        assert abs(w - ref["omega_lever"]) <= tol * omega
        assert abs(al - ref["alpha_lever"]) <= tol * (omega ** 2 + alpha)
        assert abs(sdd - ref["s_ddot"]) <= tol * (omega ** 2 + alpha) * 0.2 * scale
