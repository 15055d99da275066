"""solve_many: many variants of one scene in one vectorised pass, checked row by row against
the independent closed forms (tests/analytic.py); failed rows are data, never a crash."""
import math
from pathlib import Path

import numpy as np
import pytest

import analytic
from conftest import cli
from scenes import crank_driver, m
from polygons.batch import solve_many
from polygons.errors import UnknownLabelError
from polygons.scene import parse_scene

ROOT = Path(__file__).resolve().parent.parent


def four_bar(ad=0.5, ab=0.1, bc=0.4, cd=0.3, theta=1.0, omega=10.0, alpha=20.0):
    return parse_scene({
        "ground": {"A": ["0 m", "0 m"], "D": [m(ad), "0 m"]},
        "links": {"AB": m(ab), "BC": m(bc), "CD": m(cd)},
        "driver": crank_driver("AB", theta, omega, alpha),
        "assembly": {"C": "C above AD"},
    })


def _reference(ad, ab, bc, cd, theta, omega, alpha, C):
    """The closed-form solution of the closure the batch row took (the one at C); None where
    the closed form cannot tell the closures apart by side of AD (both on one side)."""
    ambiguous = False
    for branch in (1, -1):
        try:
            ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, theta, omega, alpha, branch)
        except ValueError as exc:
            ambiguous |= "same side" in str(exc)
            continue
        if math.dist(ref["C"], C) <= 1e-9 * ad:
            return ref
    if ambiguous:
        return None
    raise AssertionError(f"row's C {C} is neither closure")


def test_random_four_bars_row_by_row_against_the_closed_form():
    rng = np.random.default_rng(12)
    n = 400
    cols = dict(D_x=rng.uniform(0.4, 0.6, n), AB=rng.uniform(0.05, 0.15, n),
                BC=rng.uniform(0.35, 0.45, n), CD=rng.uniform(0.25, 0.35, n),
                theta=rng.uniform(0, 2 * math.pi, n), omega=rng.uniform(-50, 50, n),
                alpha=rng.uniform(-500, 500, n))
    b = solve_many(four_bar(), **cols)
    assert b.n == n and b.shape == (n,)
    assert len(b.errors) == (~b.ok).sum()
    C, vC, aC = b.position("C"), b.velocity("C"), b.acceleration("C")
    checked = 0
    wBC, aBC, wCD = b.omega("BC"), b.alpha("BC"), b.omega("CD")
    for i in range(n):
        args = [cols[k][i] for k in ("D_x", "AB", "BC", "CD", "theta", "omega", "alpha")]
        if not b.ok[i]:         # the closed form must agree that this row cannot close
            with pytest.raises(ValueError, match="distance"):
                analytic.four_bar((0, 0), (args[0], 0), *args[1:], 1)
            continue
        ref = _reference(*args, C[i])
        if ref is None:
            continue
        checked += 1
        vs = abs(args[5]) * args[1]
        as_ = (args[5] ** 2 + abs(args[6])) * args[1]
        assert math.dist(vC[i], ref["vC"]) <= 1e-9 * vs
        assert math.dist(aC[i], ref["aC"]) <= 1e-9 * as_
        assert abs(wBC[i] - ref["omega_BC"]) <= 1e-9 * vs / args[2]
        assert abs(wCD[i] - ref["omega_CD"]) <= 1e-9 * vs / args[3]
        assert abs(aBC[i] - ref["alpha_BC"]) <= 1e-8 * as_ / args[2]
    assert checked >= n // 2 and b.ok.sum() >= n // 2


def test_grid_solves_every_combination_in_index_order():
    ab = np.array([0.08, 0.1, 0.12])
    th = np.linspace(0.0, 2 * math.pi, 5, endpoint=False)
    b = solve_many(four_bar(), grid=True, AB=ab, theta=th)
    assert b.shape == (3, 5) and b.n == 15
    for i in range(15):
        j, k = np.unravel_index(i, b.shape)
        assert (b.inputs["AB"][i], b.inputs["theta"][i]) == (ab[j], th[k])
        ref = _reference(0.5, ab[j], 0.4, 0.3, th[k], 10.0, 20.0, b.position("C")[i])
        assert math.dist(b.velocity("C")[i], ref["vC"]) <= 1e-9 * 10 * ab[j]


def test_rows_that_cannot_close_are_errors_with_row_dyad_and_reason():
    # AB = 0.3 > the Grashof limit: at θ = π, B is 0.8 from D, beyond BC + CD = 0.7
    b = solve_many(four_bar(), AB=[0.1, 0.3, 0.1], theta=[math.pi, math.pi, 0.5])
    assert list(b.ok) == [True, False, True]
    (err,) = b.errors
    assert (err.row, err.where) == (1, "C")
    assert "cannot close" in err.reason and "BC + CD" in err.reason
    assert np.isnan(b.velocity("C")[1]).all() and np.isfinite(b.velocity("C")[[0, 2]]).all()


def test_a_toggle_row_is_an_error_naming_the_step():
    # BD = BC + CD = 0.35 where 0.2² + 0.5² − 2·0.2·0.5 cos θ = 0.35²: B, C, D in line
    toggle = math.acos((0.04 + 0.25 - 0.35 ** 2) / 0.2)
    b = solve_many(four_bar(ad=0.5, ab=0.2, bc=0.15, cd=0.2, theta=0.3), theta=[0.3, toggle])
    assert list(b.ok) == [True, False]
    (err,) = b.errors
    assert err.row == 1 and err.where.startswith("velocity")
    assert "parallel" in err.reason


def test_bad_values_and_unknown_names():
    b = solve_many(four_bar(), AB=[0.1, -0.1, 0.0])
    assert list(b.ok) == [True, False, False]
    assert [e.where for e in b.errors] == ["AB", "AB"]
    assert "positive" in b.errors[0].reason
    with pytest.raises(UnknownLabelError, match="XY"):
        solve_many(four_bar(), XY=[1.0])


def test_cli_vary_writes_one_csv_row_per_value(tmp_path):
    out = cli("sweep", "cases/s001-we6.toml", "--vary", "AB=60..100mm:5", "--out", tmp_path,
              cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
    csv = next(tmp_path.glob("*.csv")).read_text().splitlines()
    assert len(csv) == 1 + 5
    assert csv[0].startswith("row,AB [m]")
    assert [float(r.split(",")[1]) for r in csv[1:]] == pytest.approx(
        [0.06, 0.07, 0.08, 0.09, 0.1])


def test_cli_vary_rejects_a_bad_range_in_one_line(tmp_path):
    out = cli("sweep", "cases/s001-we6.toml", "--vary", "AB=60..", "--out", tmp_path, cwd=ROOT)
    assert out.returncode != 0
    assert out.stderr.startswith("polygons: error:") and out.stderr.count("\n") == 1


CASES = sorted((ROOT / "cases").glob("*.toml"))


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_every_case_as_a_batch_matches_its_staged_solve(path):
    """One row at the scene's own values = the staged construction (to 1e-12 of the polygon's
    size); rows varying every link length by ±1 % solve, the middle row is the scene's."""
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    scene = load_scene(str(path))
    ref = solve(scene)
    lengths = {n: l.length * np.array([0.99, 1.0, 1.01]) for n, l in scene.links.items()
               if l.length is not None}
    b = solve_many(scene, lengths)
    assert b.ok.all(), b.errors
    for d, get in (("velocity", b.velocity), ("acceleration", b.acceleration)):
        pts = {lab: getattr(p, d) for lab, p in ref.points.items() if getattr(p, d) is not None}
        if not pts:
            continue
        scale = max(math.hypot(*v) for v in pts.values()) or 1.0
        mid = 1 if lengths else 0           # the unvaried row (a scene with no links: one)
        for lab, v in pts.items():
            assert math.dist(get(lab)[mid], v) <= 1e-12 * scale, (d, lab)


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_the_compiled_and_the_located_engines_give_the_same_rows(path):
    """Points from the generated code against points from each dyad's numpy ``locate``, the
    step program on top of each: the same rows, errors and angles."""
    from polygons.scene import load_scene
    scene = load_scene(str(path))
    lengths = {n: l.length * np.array([0.98, 1.0, 1.02]) for n, l in scene.links.items()
               if l.length is not None}
    a = solve_many(scene, lengths, engine="compiled")
    b = solve_many(scene, lengths, engine="located")
    assert list(a.ok) == list(b.ok) and a.errors == b.errors
    np.testing.assert_allclose(a.angle_deg, b.angle_deg, rtol=1e-12)
    for lab in a._pos:
        for get in ("position", "velocity", "acceleration"):
            x, y = getattr(a, get)(lab), getattr(b, get)(lab)
            scale = max(1e-300, float(np.nanmax(np.abs(y))))
            assert np.nanmax(np.abs(x - y)) <= 1e-12 * scale, (lab, get)
    for name in b._links[0]:
        np.testing.assert_allclose(a.omega(name), b.omega(name), rtol=1e-11, atol=1e-13)
