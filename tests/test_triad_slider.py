"""A class-III group with a block on a guide at a corner — two links and a block (issue 28,
item 5): stated as a book states it, every closure found algebraically (against an independent
dense scan), the case's answers from an independent oracle (tests/analytic_triad_slider.py),
rates equal to finite differences of positions, solve equal to the sweep's row, the Assur
point S taken on a link and the guide's normal where the two links are parallel, and the
graphical force polygon refused in one line naming the group and the method."""
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import analytic_triad as at
import analytic_triad_slider as ats
import domain
from polygons.dyads.triad_slider_math import all_corners
from polygons.errors import PolygonsError
from polygons.evaluate import solve
from polygons.scene import load_scene, parse_scene
from polygons.sweep import sweep

CASES = Path(__file__).resolve().parents[1] / "cases"
CASE = CASES / "triad-slider-corner.toml"


def _oracle(theta=math.radians(160.0)):
    """The case's group at crank angle θ by the oracle: every closure by the dense scan, the
    one nearest the stated point polished by Newton on the six equations, its rates by the
    differentiated equations.  Returns ({quantity: value}, (B, C, X), closures)."""
    w = 10.0
    A = 0.1 * np.array([math.cos(theta), math.sin(theta)])
    D, G, n = np.array([0.3, 0.0]), np.array([0.0, 0.2]), np.array([0.0, 1.0])
    a, d, L, xi, eta = 0.3, 0.2, 0.1, 0.02, 0.11
    cl = ats.scan_closures(A, a, D, d, G, n, L, xi, eta, samples=720)
    B, C, X = min(cl, key=lambda c: np.hypot(*(c[2] - [0.25, 0.2])))
    B, C, X = ats.solve_position(A, D, G, n, (a, d, L, math.hypot(L - xi, eta),
                                             math.hypot(xi, eta)), (B, C, X))
    vA, aA, z = w * np.array([-A[1], A[0]]), -w * w * A, np.zeros(2)
    (vB, vC, vX), (aB, aC, aX) = ats.rates(B, C, X, A, D, n, vA, z, aA, z)

    def alpha(P, Q, vP, vQ, aP, aQ):
        r = Q - P
        wv = at.omega(P, Q, vP, vQ)
        ar = aQ - aP + wv * wv * r
        return float((r[0] * ar[1] - r[1] * ar[0]) / (r @ r))
    out = {"v(B)": np.hypot(*vB), "a(B)": np.hypot(*aB), "v(C)": np.hypot(*vC),
           "a(C)": np.hypot(*aC), "v(X)": np.hypot(*vX), "a(X)": np.hypot(*aX),
           "omega(AB)": at.omega(A, B, vA, vB), "alpha(AB)": alpha(A, B, vA, vB, aA, aB),
           "omega(CD)": at.omega(D, C, z, vC), "alpha(CD)": alpha(D, C, z, vC, z, aC),
           "omega(BC)": at.omega(B, C, vB, vC), "alpha(BC)": alpha(B, C, vB, vC, aB, aC)}
    return {k: float(v) for k, v in out.items()}, (B, C, X), cl, (vX, aX)


def test_the_case_exact_answers_come_from_the_oracle():
    ref, (B, C, X), cl, (vX, aX) = _oracle()
    assert len(cl) == 2
    scene = load_scene(CASE)
    checked = 0
    for a in scene.answers:
        value = ref[a.quantity] if a.mode == "signed" else abs(ref[a.quantity])
        assert a.exact == pytest.approx(value, rel=1e-12), a.quantity
        checked += 1
    assert checked >= 12
    sol = solve(scene)
    for k, P in zip("BCX", (B, C, X)):
        assert math.dist(sol.points[k].position, P) < 1e-12
    assert np.allclose(sol.points["X"].velocity, vX, rtol=0, atol=1e-12)
    assert np.allclose(sol.points["X"].acceleration, aX, rtol=0, atol=1e-10)
    assert "2 closures, the next 137.6 mm away" in " ".join(w for _, w in
                                                            sol.placement.branches)


def test_the_closures_of_random_groups_are_those_of_a_dense_scan():
    """Half the groups with two closures a hair apart (the guide within 1e-9 … 1e-5 m of an
    extremum of the coupler curve's distance from it): the count and the corners agree."""
    rng = np.random.default_rng(2028)
    closures = 0
    for i in range(6):
        A, a, D, d, G, n, L, xi, eta = ats.random_group(rng, close=i % 2 == 1)
        got = all_corners((*A, a, *D, d, *G, n[1], -n[0], L, xi, eta, 0.0), 0.5)
        ref = ats.scan_closures(A, a, D, d, G, n, L, xi, eta, samples=360)
        assert len(got) == len(ref), i
        for B, C, X in ref:
            assert min(max(math.dist(B, g[0]), math.dist(X, g[2])) for g in got) < 1e-8
        closures += len(got)
    assert closures >= 6


def test_rates_are_finite_differences_of_the_oracle_positions():
    """Newton on the six equations at θ ± h and ± 2h (continuing from the solved closure):
    the 4th-order central differences equal the construction's velocity and acceleration."""
    sol = solve(load_scene(CASE))
    guess = [sol.points[k].position for k in "BCX"]
    G, n = (0.0, 0.2), (0.0, 1.0)
    lens = (0.3, 0.2, 0.1, math.hypot(0.08, 0.11), math.hypot(0.02, 0.11))
    th, w, h = math.radians(160.0), 10.0, 1e-3

    def pos(t):
        A = (0.1 * math.cos(t), 0.1 * math.sin(t))
        return np.concatenate(ats.solve_position(A, (0.3, 0.0), G, n, lens, guess))
    p = {k: pos(th + k * h) for k in (-2, -1, 0, 1, 2)}
    d1 = (p[-2] - 8 * p[-1] + 8 * p[1] - p[2]) / (12 * h) * w
    d2 = (-p[-2] + 16 * p[-1] - 30 * p[0] + 16 * p[1] - p[2]) / (12 * h * h) * w * w
    for i, k in enumerate("BCX"):
        assert np.allclose(sol.points[k].velocity, d1[2 * i:2 * i + 2], rtol=0, atol=1e-11)
        assert np.allclose(sol.points[k].acceleration, d2[2 * i:2 * i + 2], rtol=0,
                           atol=1e-7)


def test_solve_equals_the_sweeps_row():
    """The sweep follows the scene's closure by continuation; the scene restated at each row
    (X near the row's X) solves to the row."""
    from dataclasses import replace
    from polygons.records import Branch
    scene = load_scene(CASE)
    xs = np.radians([0.0, 60.0, 120.0, 200.0, 300.0])
    sw = sweep(scene, inputs=xs)
    for i, x in enumerate(xs):
        X = tuple(float(v) for v in sw.position("X")[i])
        at_x = replace(scene, driver=replace(scene.driver, angle=float(x)),
                       assembly={"X": Branch("X", "X near the row", "near", near=X)})
        sol = solve(at_x)
        for k in "BCX":
            assert math.dist(sw.position(k)[i], sol.points[k].position) < 1e-12, (x, k)


def test_at_a_parallel_pair_s_is_taken_on_a_link_and_the_guides_normal():
    """Where AB ∥ DC (S at infinity: no singularity of the group) S is where DC meets the
    normal to the guide at X; the rates hold every check (a seed of the domain suite at the
    pose found by its golden-section search, to 1e-16 rad)."""
    mech = domain.make("triad-slider-random", 11)
    x = 0.5338605148560522
    sol = solve(mech.at(x))
    d = next(g for g in sol.plan.dyads if getattr(g, "many_closures", False))
    assert d.via == 2
    assert any("S is taken where the lines DC and the normal to the guide of X at X meet" in w
               for _, w in sol.placement.branches)
    assert d.assur_sine(sol.placement.points, 0) < 1e-6
    out = domain.check(mech, x, 1e-3, "at a parallel pair")
    assert out.verdict == "agree" and out.checks > 20, out.replay


@pytest.mark.parametrize("seed", [2, 17])
def test_a_triangle_plate_with_the_block_at_any_corner(seed):
    """The plate a triangle of links (its mirror image a closure too), the block at X (seed
    17) or at B, the corner the crank's link does not reach (seed 2): every check holds."""
    data = domain.KINDS["triad-slider-random"](
        __import__("random").Random(f"triad-slider-random/{seed}"))[0]
    assert "points" not in data and list(data["sliders"]) == [{2: "B", 17: "X"}[seed]]
    mech = domain.make("triad-slider-random", seed)      # at the pose it was built at
    out = domain.check(mech, mech.x0(), 1e-2, "random")
    assert out.verdict == "agree" and out.checks > 20, out.replay


def test_the_force_polygon_refuses_naming_the_group_and_newton_euler_solves():
    data = tomllib.loads(CASE.read_text(encoding="utf-8"))
    for k in ("answers", "source"):
        data.pop(k)
    data["masses"] = {"AB": {"mass": "2 kg"}, "BC": {"mass": "5 kg"}, "CD": {"mass": "2 kg"}}
    data["forces"] = {"Load": {"at": "X", "on": "BC", "magnitude": "400 N",
                               "direction": "180 deg"}}
    scene = parse_scene(data, file="block.toml")
    from polygons.forces import graphical
    with pytest.raises(PolygonsError, match="a slider on a fixed guide at a corner"):
        graphical.groups_of(scene)
    from polygons.forces.analysis import analyse
    an = analyse(scene)
    st = an.states[0]
    assert abs(st.ne.effort - st.vw_effort) < 1e-9 * max(1.0, abs(st.ne.effort))


def test_a_second_point_on_the_plate_stated_first_does_not_change_the_plate():
    """The plate's third corner is the block's point, not the first [points] entry on the
    plate's link (a point P on BC stated before X once gave the plate the wrong shape)."""
    data = tomllib.loads(CASE.read_text(encoding="utf-8"))
    data["points"] = {"P": {"on": "BC", "along": "20 mm", "left": "-30 mm"},
                      **data["points"]}
    one, two = solve(load_scene(CASE)), solve(parse_scene(data, file="p.toml"))
    for k in "BCX":
        assert math.dist(one.points[k].position, two.points[k].position) < 1e-12


def test_blocks_at_two_corners_are_refused_saying_so():
    """Not the bare "B is not placed before it": the sentence names the blocks and says
    which class-III groups with a block are solved."""
    data = tomllib.loads(CASE.read_text(encoding="utf-8"))
    for k in ("answers", "source", "assembly"):
        data.pop(k)
    data["links"] = {"OA": "100 mm", "AC": "200 mm", "BC": "150 mm"}
    data["sliders"]["B"] = {"through": ["0 mm", "250 mm"], "direction": "90 deg"}
    with pytest.raises(PolygonsError, match="blocks at two corners are not supported"):
        solve(parse_scene(data, file="two-blocks.toml"))
