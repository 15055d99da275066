"""Sweeps: the vectorised path agrees with the staged constructor on every case, reproduces the
seed's worked example 1 and the Scotch yoke, follows the branch, finds and reports the limits of
the reachable range, and never loops in Python per position."""
import math
import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import analytic
from scenes import crank_driver, slider_crank_case
from conftest import CASES, ROOT, case_files
from polygons import sweep as sweep_mod
from polygons.cli import main
from polygons.evaluate import solve
from polygons.scene import Branch, Crank, load_scene, parse_scene
from polygons.sweep import harmonic, sweep

AGREE = 1e-12
#: every case a sweep follows (a cam stated by its profile changes its linkage with the part
#: in contact: its diagram is polygons.cam_diagram's, tests/test_cam_profiles.py)
FILES = [f for f in case_files() if "[cam_profiles." not in f.read_text(encoding="utf-8")]
IDS = [f.stem for f in FILES]


def test_thresholds_are_those_of_the_staged_constructor():
    from polygons import geometry
    assert sweep_mod.PARALLEL_DEG == geometry.PARALLEL_DEG
    assert sweep_mod.WARN_DEG == geometry.WARN_DEG


def test_the_vectorised_path_does_not_import_shapely():
    """polygons.sweep and everything it imports inside the package stay clear of shapely
    (checked statically: the staged solver is importable beside it)."""
    from imports import closure, imports
    from polygons.dyads._index import ORDER
    graph = imports()
    mods = closure(graph, "polygons.sweep")
    # (the planner imports the dyad kinds by name, as it asks them: polygons.dyads.kinds)
    for kind in {k for names in ORDER.values() for k in names}:
        mods |= closure(graph, f"polygons.dyads.{kind}")
    assert "polygons.codegen" in mods and "polygons.dyads.rrr" in mods
    for m in mods:
        assert not any(n.split(".")[0] == "shapely" for n in graph[m]), m


# ---------------------------------------------------------------- staged == vectorised
def _compare(sol, sw, i, tol=AGREE):
    """Every number of a staged Solution against row ``i`` of a sweep, relative to the
    largest vector of its diagram (positions: to the mechanism's size)."""
    scene = sol.scene
    size = max([l.length for l in scene.links.values() if l.length] +
               [abs(c) for v in scene.ground.values() for c in v])
    for lab, p in sol.points.items():
        if lab in scene.ground:
            continue
        xy = sw.pos[lab]
        got = np.array([xy[0][i], xy[1][i]]) if np.ndim(xy[0]) else np.array(xy)
        assert np.hypot(*(got - p.position)) <= tol * size, (lab, got, p.position)
    for diagram, key in (("velocity", "vel"), ("acceleration", "acc")):
        if diagram not in scene.solve:
            continue
        scale = max(math.hypot(*getattr(p, diagram)) for p in sol.points.values())
        for lab, p in sol.points.items():
            arr = getattr(sw, key)[lab]
            got = np.zeros(2) if arr is None else arr[:, i]
            assert np.hypot(*(got - getattr(p, diagram))) <= tol * scale, (diagram, lab)
        rate = {"velocity": "omega", "acceleration": "alpha"}[diagram]
        omegas = [abs(l.omega) for l in sol.links.values() if l.omega is not None]
        rscale = max([abs(getattr(l, rate)) for l in sol.links.values()
                      if getattr(l, rate) is not None] + [1e-300])
        if rate == "alpha":            # α's natural scale includes ω² (α may be ~0 at dead centres)
            rscale = max([rscale] + [w * w for w in omegas])
        for name, link in sol.links.items():
            if getattr(link, rate) is None:
                continue
            got = getattr(sw, rate)[name][i]
            assert abs(got - getattr(link, rate)) <= tol * rscale, (rate, name)
        for lab, sl in sol.slides.items():
            val = sl.velocity if diagram == "velocity" else sl.acceleration
            if val is None:
                continue
            got = (sw.slide_v if diagram == "velocity" else sw.slide_a)[lab][i]
            assert abs(got - val) <= tol * scale, (diagram, "slide", lab)
            if diagram == "acceleration" and sl.coriolis is not None:
                assert np.hypot(*(sw.coriolis[lab][:, i] - sl.coriolis)) <= tol * scale


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_vectorised_path_agrees_with_staged_constructor_at_the_scene_input(path):
    scene = load_scene(path)
    sol = solve(scene)
    drv = scene.driver
    x0 = drv.angle if isinstance(drv, Crank) else drv.position
    sw = sweep(scene, inputs=[x0])
    _compare(sol, sw, 0)


def _at_input(scene, x, sw, i):
    """The scene restated at input ``x``, with each closure pinned near the sweep's choice."""
    drv = scene.driver
    drv = replace(drv, angle=float(x)) if isinstance(drv, Crank) else replace(drv, position=float(x))
    assembly = {lab: Branch(lab, f"{lab} near sweep", "near",
                            near=(float(sw.pos[lab][0][i]), float(sw.pos[lab][1][i])))
                for lab in sw.branches}
    return replace(scene, driver=drv, assembly=assembly)


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_vectorised_path_agrees_with_staged_constructor_over_the_cycle(path):
    scene = load_scene(path)
    sw = sweep(scene, 24)
    checked = 0
    for i, x in enumerate(sw.inputs):
        if not sw.angle_deg[i] > 1.0:
            continue
        sol = solve(_at_input(scene, x, sw, i))
        _compare(sol, sw, i)
        checked += 1
    assert checked >= 12


# ---------------------------------------------------------------- the seed's examples
def test_worked_example_1_maximum_piston_acceleration():
    sw = sweep(load_scene(CASES / "s001-we1.toml"), 360)
    a = np.abs(sw.slide_a["B"])
    i = int(np.argmax(a))
    assert sw.inputs[i] == 0.0
    assert a[i] * 1e3 == pytest.approx(699.0969784104963, rel=1e-12)    # reference, mm/s²
    assert sw.travel["B"][i] == pytest.approx(0.170, rel=1e-12)          # 170 mm from O
    # and it is the maximum over the cycle on a finer grid too
    fine = sweep(load_scene(CASES / "s001-we1.toml"), 36000)
    assert np.max(np.abs(fine.slide_a["B"])) * 1e3 == pytest.approx(699.0969784104963,
                                                                       rel=1e-12)


def test_worked_example_1_with_a_10_mm_crank_is_nearly_harmonic():
    sw = sweep(load_scene(CASES / "s001-we1-r10.toml"), 3600)
    a = sw.slide_a["B"]
    assert np.max(np.abs(a)) * 1e3 == pytest.approx(106.92071434513473, rel=1e-12)
    h = harmonic(sw, "B")
    w, r = math.pi, 0.010
    assert np.max(np.abs(h.acceleration)) == pytest.approx(w * w * r, rel=1e-12)
    diff = np.max(np.abs(a - h.acceleration))
    # the difference is the second harmonic, about r²ω²/L (1 + ...): 8.25 mm/s² = 7.7 % of the peak
    assert diff * 1e3 == pytest.approx(8.2534, rel=1e-4)
    assert diff / np.max(np.abs(a)) < 0.08
    big = sweep(load_scene(CASES / "s001-we1.toml"), 3600)
    big_diff = np.max(np.abs(big.slide_a["B"] - harmonic(big, "B").acceleration))
    assert big_diff / np.max(np.abs(big.slide_a["B"])) > 0.3    # 50 mm crank: far from SHM


def test_scotch_yoke_is_exactly_simple_harmonic():
    scene = load_scene(CASES / "scotch-yoke.toml")
    sw = sweep(scene, 3600)
    R, w = 0.050, 10.0
    th = sw.inputs
    assert sw.full_cycle
    assert np.max(np.abs(sw.travel["Y"] - R * np.sin(th))) <= 1e-16 * 10
    assert np.max(np.abs(sw.slide_v["Y"] - w * R * np.cos(th))) <= 1e-15 * w * R
    assert np.max(np.abs(sw.slide_a["Y"] + w * w * R * np.sin(th))) <= 1e-15 * w * w * R
    h = harmonic(sw, "Y")
    assert np.max(np.abs(sw.slide_a["Y"] - h.acceleration)) <= 1e-15 * w * w * R
    # the staged construction of the yoke: guide line ∩ slot line, no Coriolis
    sol = solve(scene)
    assert sol.slides["Y"].velocity == pytest.approx(w * R * math.cos(math.radians(30)),
                                                     rel=1e-14)
    assert [s.op for s in sol.steps if s.diagram == "velocity"][1:4] == [
        "line_guide", "line_slot", "intersect"]


# ---------------------------------------------------------------- range, limits, branch
def four_bar(ab, bc, cd, ad, theta_deg, near):
    return parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [f"{ad!r} m", "0 m"]},
        "links": {"AB": f"{ab!r} m", "BC": f"{bc!r} m", "DC": f"{cd!r} m"},
        "driver": {"crank": "AB", "angle": f"{theta_deg!r} deg", "omega": "10 rad/s",
                   "sense": "CCW"},
        "assembly": {"C": {"near": [f"{near[0]!r} m", f"{near[1]!r} m"]}},
    })


def test_non_grashof_four_bar_stops_at_its_limit_positions():
    ab, bc, cd, ad = 1.0, 1.4, 0.7, 1.0           # cases/s001-we3: a rocker, not a crank
    scene = four_bar(ab, bc, cd, ad, 120.0, (0.5, 0.9))
    sw = sweep(scene, 200)
    assert not sw.full_cycle
    lo, hi = sw.range
    # B is |BC - CD| from D at both limits: cos θ = (ab² + ad² - (bc - cd)²) / (2 ab ad)
    t = math.acos((ab * ab + ad * ad - (bc - cd) ** 2) / (2 * ab * ad))
    assert lo == pytest.approx(t, rel=1e-9)
    assert hi == pytest.approx(2 * math.pi - t, rel=1e-9)
    kinds = [lim.kind for lim in sw.limits]
    assert kinds == ["limit", "limit"]
    assert all("BC and DC are in line" in lim.reason and "folded back" in lim.reason
               for lim in sw.limits)
    assert lo < sw.inputs.min() and sw.inputs.max() < hi     # strictly inside
    assert np.all(np.isfinite(sw.alpha["DC"]))


def test_branch_is_followed_continuously_over_a_full_cycle():
    # Grashof crank-rocker; C starts below AD and stays in that closure all the way round
    scene = four_bar(0.2, 0.7, 0.6, 0.8, 30.0, (0.8, -0.6))
    sw = sweep(scene, 720)
    assert sw.full_cycle and sw.branches == {"C": -1}
    C = sw.position("C")
    steps = np.hypot(*np.diff(np.vstack([C, C[:1]]), axis=0).T)
    assert steps.max() < 0.01                                      # no jump to the other closure
    ref = [analytic.four_bar((0, 0), (0.8, 0), 0.2, 0.7, 0.6, t, 10.0, 0.0, -1)
           for t in sw.inputs[::40]]
    for r, i in zip(ref, range(0, 720, 40)):
        assert np.hypot(*(C[i] - r["C"])) <= 1e-12
        assert np.hypot(*(sw.acceleration("C")[i] - r["aC"])) <= 1e-11 * 100 * 0.2


def test_slider_driver_is_swept_over_its_stroke_between_dead_centres():
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]},
        "links": {"OA": "0.05 m", "AB": "0.2 m"},
        "driver": {"slider": "B", "position": "0.2 m", "velocity": "1 m/s"},
        "sliders": {"B": {"through": ["0 m", "0 m"], "direction": "0 deg"}},
        "assembly": {"A": "A above OB"},
    })
    sw = sweep(scene, 100)
    assert sw.input_kind == "slider" and not sw.full_cycle
    assert sw.range[0] == pytest.approx(0.15, rel=1e-9)
    assert sw.range[1] == pytest.approx(0.25, rel=1e-9)
    assert all("OA and AB are in line" in lim.reason or "AB and OA are in line" in lim.reason
               for lim in sw.limits)


def test_inputs_given_explicitly_are_solved_in_the_scene_branch():
    scene = load_scene(CASES / "s001-we6.toml")
    th = np.linspace(0, 2 * np.pi, 7, endpoint=False)
    sw = sweep(scene, inputs=th)
    assert sw.n == 7 and np.array_equal(sw.inputs, th)


def test_a_long_sweep_is_evaluated_in_chunks_not_per_position(monkeypatch):
    calls = []
    real = sweep_mod.evaluate

    def counting(prog, inputs, **kw):
        calls.append(len(np.atleast_1d(inputs)))
        return real(prog, inputs, **kw)

    monkeypatch.setattr(sweep_mod, "evaluate", counting)
    n = 200_000
    done = []
    scene = load_scene(CASES / "s003-fig7.toml")
    sw = sweep(scene, inputs=np.linspace(0, 6.28, n), progress=done.append)
    chunk = sweep_mod.chunk_for(sweep_mod.compile_plan(scene))
    assert 1024 <= chunk <= 4 * sweep_mod.CHUNK
    assert sum(calls) == n and len(calls) == math.ceil(n / chunk)
    assert sum(done) == n
    assert sw.omega["O4P4"].shape == (n,)


# ---------------------------------------------------------------- the command
def test_sweep_command_writes_csv_and_deterministic_plots(tmp_path, capsys):
    case = str(CASES / "s001-we1.toml")
    assert main(["sweep", case, "--steps", "72", "--out", str(tmp_path), "--shm"]) == 0
    out = capsys.readouterr().out
    from polygons.steps import number      # the summary rounds as the solve table does
    assert f"max |a| = {number(699.0969784104963)} mm/s² at θ = 0°" in out
    assert "max |a| = 699.1 mm/s²" in out
    assert "full revolution" in out and "difference from SHM" in out
    csv = (tmp_path / "s001-we1-sweep.csv").read_text().splitlines()
    assert csv[0].startswith("theta [rad],theta_deg [deg],B.x [m]")
    assert len(csv) == 73
    svg1 = (tmp_path / "s001-we1-sweep.svg").read_bytes()
    png1 = (tmp_path / "s001-we1-sweep.png").read_bytes()
    assert png1[:8] == b"\x89PNG\r\n\x1a\n" and b"<svg" in svg1[:400]
    assert main(["sweep", case, "--steps", "72", "--out", str(tmp_path), "--shm"]) == 0
    assert (tmp_path / "s001-we1-sweep.svg").read_bytes() == svg1
    assert (tmp_path / "s001-we1-sweep.png").read_bytes() == png1


def test_sweep_command_reports_the_limits_of_the_reachable_range(tmp_path, capsys):
    assert main(["sweep", str(CASES / "s001-we3.toml"), "--steps", "50", "--out",
                 str(tmp_path), "--no-plot"]) == 0
    out = capsys.readouterr().out
    assert out.count("limit at θ =") == 2 and "BC and DC are in line" in out
    assert "reachable range" in out


def test_sweep_command_progress_bar_and_errors(tmp_path, capsys):
    assert main(["sweep", str(CASES / "scotch-yoke.toml"), "--steps", "1000", "--out",
                 str(tmp_path), "--no-plot", "--progress", "on"]) == 0
    assert "sweep" in capsys.readouterr().err
    assert main(["sweep", str(CASES / "scotch-yoke.toml"), "--points", "Q", "--out",
                 str(tmp_path), "--no-plot"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "unknown point 'Q'" in err[0]
    assert main(["sweep", str(CASES / "scotch-yoke.toml"), "--steps", "1"]) == 1
    assert "steps must be" in capsys.readouterr().err


# ---------------------------------------------------------------- properties
lengths = st.floats(0.01, 1.0)
angles = st.floats(0.0, 2 * math.pi)
omegas = st.floats(0.5, 500.0) | st.floats(-500.0, -0.5)
alphas = st.floats(-1e4, 1e4)
props = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


def _driver(theta, omega, alpha, link="AB"):
    return crank_driver(link, theta, omega, alpha)


@props
@given(ad=st.floats(0.2, 1.0), ab=lengths, bc=lengths, cd=lengths, theta=angles,
       omega=omegas, alpha=alphas, branch=st.sampled_from([1, -1]),
       others=st.lists(angles, min_size=3, max_size=3))
def test_random_four_bars_sweep_like_the_closed_form(ad, ab, bc, cd, theta, omega, alpha,
                                                       branch, others):
    try:
        ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, branch)
    except ValueError:
        assume(False)
    scene = parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [f"{ad!r} m", "0 m"]},
        "links": {"AB": f"{ab!r} m", "BC": f"{bc!r} m", "DC": f"{cd!r} m"},
        "driver": _driver(theta, omega, alpha),
        "assembly": {"C": {"near": [f"{float(ref['C'][0])!r} m", f"{float(ref['C'][1])!r} m"]}},
    })
    sw = sweep(scene, inputs=[theta] + others)
    assume(sw.angle_deg[0] > 1.0)
    vs, as_ = abs(omega) * ab, (omega ** 2 + abs(alpha)) * ab
    tol = 1e-9
    assert np.hypot(*(sw.position("C")[0] - ref["C"])) <= tol * max(ab, bc, cd, ad)
    assert np.hypot(*(sw.velocity("C")[0] - ref["vC"])) <= tol * vs
    assert np.hypot(*(sw.acceleration("C")[0] - ref["aC"])) <= tol * as_
    assert abs(sw.alpha["BC"][0] - ref["alpha_BC"]) <= tol * as_ / bc
    # the other inputs stay on the closure on the same side of B->D (σ is kept), and close
    C, B = sw.position("C"), sw.position("B")
    side = np.sign((ad - B[:, 0]) * (C[:, 1] - B[:, 1]) - (0 - B[:, 1]) * (C[:, 0] - B[:, 0]))
    for i in range(1, 4):
        if sw.angle_deg[i] > 1.0:
            assert side[i] == side[0]
            assert np.hypot(*(C[i] - B[i])) == pytest.approx(bc, rel=1e-12)
            assert np.hypot(C[i][0] - ad, C[i][1]) == pytest.approx(cd, rel=1e-12)
            branch_i = 1 if C[i][1] > 0 else -1
            try:
                r = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, others[i - 1], omega, alpha,
                                      branch_i)
            except ValueError:
                continue
            if np.hypot(*(r["C"] - C[i])) <= 1e-9:
                assert np.hypot(*(sw.acceleration("C")[i] - r["aC"])) <= tol * as_ * (
                    1.0 / math.sin(math.radians(sw.angle_deg[i]))) ** 3


@props
@given(r=lengths, ratio=st.floats(1.2, 6.0), theta=angles, omega=omegas, alpha=alphas,
       line_dir=angles, offset=st.floats(-0.8, 0.8), branch=st.sampled_from([1, -1]))
def test_random_slider_cranks_sweep_like_the_closed_form(r, ratio, theta, omega, alpha,
                                                          line_dir, offset, branch):
    scene, ref = slider_crank_case(r, ratio, theta, omega, alpha, line_dir, offset, branch)
    L = r * ratio
    sw = sweep(scene, inputs=[theta])
    assume(sw.angle_deg[0] > 1.0)
    vs, as_ = abs(omega) * r, (omega ** 2 + abs(alpha)) * r
    assert abs(sw.slide_v["B"][0] - ref["s_dot"]) <= 1e-9 * vs
    assert abs(sw.slide_a["B"][0] - ref["s_ddot"]) <= 1e-9 * as_
    assert abs(sw.alpha["AB"][0] - ref["alpha_AB"]) <= 1e-9 * as_ / L
    # an in-line or offset slider-crank whose rod is longer than crank + offset turns fully
    if L > r * (1 + abs(offset)) * 1.01:
        full = sweep(scene, 90)
        assert full.full_cycle


@props
@given(r=lengths, h=st.floats(0.05, 2.0), theta=angles, omega=omegas, alpha=alphas)
def test_random_slotted_levers_sweep_like_the_closed_form(r, h, theta, omega, alpha):
    assume(abs(h - r) > 0.02 * r)
    ref = analytic.slotted_lever((0, h), r, theta, omega, alpha, (0, 0))
    assume(ref["s"] > 1e-3 * r)
    scene = parse_scene({
        "ground": {"B": ["0 m", "0 m"], "O": ["0 m", f"{h!r} m"]},
        "links": {"OA": f"{r!r} m"},
        "driver": _driver(theta, omega, alpha, "OA"),
        "slots": {"A": {"lever": "BA1"}},
    })
    sw = sweep(scene, inputs=[theta])
    vs, as_ = abs(omega) * r, (omega ** 2 + abs(alpha)) * r
    s = ref["s"]
    assert abs(sw.omega["BA1"][0] - ref["omega_lever"]) <= 1e-9 * vs / s
    assert abs(sw.alpha["BA1"][0] - ref["alpha_lever"]) <= 1e-9 * (as_ / s + (vs / s) ** 2)
    assert abs(sw.slide_a["A"][0] - ref["s_ddot"]) <= 1e-9 * (as_ + vs * vs / s)


def test_benchmark_command_runs_and_reports_the_targets(tmp_path):
    """A smoke run of benchmarks/run.py (tiny sizes, without the optional packages)."""
    out = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "run.py"), "--quick",
                          "--no-others", "--no-jit", "--sizes", "4096", "--out", str(tmp_path)],
                         capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    assert "targets (ratios measured in this run):" in out.stdout
    assert "error ≤ 1e-12 relative" in out.stdout and "pylinkage: not compared" in out.stdout
    for name in ("bench.json", "speed-vs-error.png", "speed-vs-error.svg"):
        assert (tmp_path / name).exists()


def test_scene_at_restates_the_scene_where_the_sweep_was():
    """Sweep.scene_at(i): the scene at the i-th input with its closures pinned near the
    followed ones; a staged solve there lands on the sweep's positions."""
    from polygons.evaluate import solve
    scene = load_scene(CASES / "s001-we6.toml")
    sw = sweep(scene, inputs=[0.3, 1.2, 2.5, 4.0])
    for i in range(sw.n):
        sol = solve(sw.scene_at(i))
        assert sol.scene.driver.angle == sw.inputs[i]
        for lab in sw.branches:
            assert np.allclose(sol.points[lab].position,
                               (sw.pos[lab][0][i], sw.pos[lab][1][i]), atol=1e-12)
