"""Class-III groups (triads): every closure found, the chosen one by the scene's words, the
velocity and acceleration by the auxiliary-point construction — against an independent
Newton + linear-solve oracle (tests/analytic_triad.py) and finite differences."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import analytic_more as am
import analytic_triad as at
from polygons.errors import BranchError, PolygonsError
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_scene

CASES = Path(__file__).resolve().parents[1] / "cases"
REL = 1e-9
DEG = math.radians


def _group(A, D, E, lens, guess):
    """Corners and their motions by the oracle: A, D, E motions (z, v, a complex)."""
    B, C, X = at.solve_position(am.vec(A[0]), am.vec(D[0]), am.vec(E[0]), lens, guess)
    vel, acc = at.rates(B, C, X, *(am.vec(P[0]) for P in (A, D, E)),
                        *(am.vec(P[1]) for P in (A, D, E)), *(am.vec(P[2]) for P in (A, D, E)))
    return (B, C, X), vel, acc


def _answers(pts, vel, acc, outer, outer_vel, outer_acc, names):
    """v(·), a(·) of the corners and ω, α of the links (names: link → (P, Q) labels)."""
    P = dict(zip("BCX", pts)) | dict(zip("ADE", outer))
    V = dict(zip("BCX", vel)) | dict(zip("ADE", outer_vel))
    Ac = dict(zip("BCX", acc)) | dict(zip("ADE", outer_acc))
    out = {}
    for k in "BCX":
        out[f"v({k})"] = float(np.hypot(*V[k]))
        out[f"a({k})"] = float(np.hypot(*Ac[k]))
    for link, (p, q) in names.items():
        out[f"omega({link})"] = at.omega(P[p], P[q], V[p], V[q])
        out[f"alpha({link})"] = at.omega(P[p], P[q], Ac[p], Ac[q])
    return out


def _guess(path):
    sol = solve(load_scene(path))
    return np.concatenate([sol.points[k].position for k in "BCX"])


def ref_ternary_coupler():
    path = CASES / "triad-ternary-coupler.toml"
    A = am.crank(am.fixed(0, 0), 0.1, DEG(60), 10.0, 0.0)
    D, E = am.fixed(0.3, 0), am.fixed(0.15, 0.3)
    pts, vel, acc = _group(A, D, E, (0.2, 0.2, 0.1, 0.15, 0.12, 0.1), _guess(path))
    return _answers(pts, vel, acc, *[[am.vec(P[i]) for P in (A, D, E)] for i in range(3)],
                    {"AB": ("A", "B"), "CD": ("C", "D"), "XE": ("X", "E"),
                     "BC": ("B", "C")})


def ref_plate_point():
    path = CASES / "triad-plate-point.toml"
    A = am.crank(am.fixed(0, 0), 0.08, DEG(45), -15.0, 50.0)
    D, E = am.fixed(0.32, -0.04), am.fixed(0.14, 0.28)
    L, xi, eta = 0.18, 0.09, 0.07
    lens = (0.22, 0.19, 0.13, L, math.hypot(L - xi, eta), math.hypot(xi, eta))
    pts, vel, acc = _group(A, D, E, lens, _guess(path))
    return _answers(pts, vel, acc, *[[am.vec(P[i]) for P in (A, D, E)] for i in range(3)],
                    {"AB": ("A", "B"), "CD": ("C", "D"), "XE": ("X", "E"),
                     "BC": ("B", "C")})


def ref_eight_bar():
    path = CASES / "triad-eight-bar.toml"
    A = am.crank(am.fixed(0, 0), 0.1, DEG(60), 10.0, 0.0)
    F, _, _ = am.rrr(A, 0.3, am.fixed(0.35, 0), 0.2, 0.33 + 0.2j)
    D = am.fixed(0.15, -0.2)
    pts, vel, acc = _group(A, D, F, (0.18, 0.18, 0.15, 0.16, 0.14, 0.12), _guess(path))
    return _answers(pts, vel, acc, *[[am.vec(P[i]) for P in (A, D, F)] for i in range(3)],
                    {"AB": ("A", "B"), "CD": ("C", "D"), "XF": ("X", "E"),
                     "BC": ("B", "C")})


def ref_plate_distances():
    """The same mechanism as triad-ternary-coupler, dimensioned as a drawing is."""
    return ref_ternary_coupler()


REFS = {"triad-ternary-coupler": ref_ternary_coupler, "triad-plate-point": ref_plate_point,
        "triad-eight-bar": ref_eight_bar, "triad-plate-distances": ref_plate_distances}


@pytest.mark.parametrize("case", sorted(REFS))
def test_the_case_solves_to_the_independent_oracle(case):
    sol = solve(load_scene(CASES / f"{case}.toml"))
    for q, value in REFS[case]().items():
        assert quantity(sol, q) == pytest.approx(value, rel=REL, abs=1e-12), q


@pytest.mark.parametrize("case", sorted(REFS))
def test_the_case_exact_answers_come_from_the_oracle(case):
    ref = REFS[case]()
    scene = load_scene(CASES / f"{case}.toml")
    checked = 0
    for a in scene.answers:
        if a.exact is None:
            continue
        value = ref[a.quantity] if a.mode == "signed" else abs(ref[a.quantity])
        assert a.exact == pytest.approx(value, rel=1e-12), a.quantity
        checked += 1
    assert checked >= 4


def test_finite_differences_of_the_corners():
    """The corners' velocities and accelerations are the derivatives of their positions
    (Newton at θ ± h, continuing from the solved closure)."""
    scene = load_scene(CASES / "triad-ternary-coupler.toml")
    sol = solve(scene)
    guess = np.concatenate([sol.points[k].position for k in "BCX"])
    lens = (0.2, 0.2, 0.1, 0.15, 0.12, 0.1)

    def pos(th):
        A = am.crank(am.fixed(0, 0), 0.1, th, 10.0, 0.0)
        B, C, X = at.solve_position(am.vec(A[0]), (0.3, 0), (0.15, 0.3), lens, guess)
        return complex(*X)
    v, a = am.fd_check(pos, DEG(60), 10.0, 0.0, h=1e-4)
    assert np.allclose(sol.points["X"].velocity, am.vec(v), rtol=1e-6)
    assert np.allclose(sol.points["X"].acceleration, am.vec(a), rtol=1e-5)


def test_every_closure_is_found():
    """Newton from 150 scattered starts finds no closure the scan missed."""
    from polygons.dyads.triad_math import all_corners
    A, D, E = (0.1 * math.cos(1.0), 0.1 * math.sin(1.0)), (0.3, 0.0), (0.15, 0.3)
    L, lbx, lcx = 0.15, 0.1, 0.12
    xi = (L * L + lbx * lbx - lcx * lcx) / (2 * L)
    p = (*A, 0.2, *D, 0.2, *E, 0.1, L, xi, math.sqrt(lbx * lbx - xi * xi), 1.0)
    found = all_corners(p, 0.3)
    assert len(found) == 4
    rng = np.random.default_rng(7)
    newton = []
    for _ in range(150):
        try:
            B, C, X = at.solve_position(A, D, E, (0.2, 0.2, 0.1, L, lcx, lbx),
                                        rng.uniform(-0.2, 0.5, 6), iters=60)
        except np.linalg.LinAlgError:
            continue
        z = np.concatenate([B, C, X])
        res = [abs(math.dist(B, A) - 0.2), abs(math.dist(C, D) - 0.2),
               abs(math.dist(X, E) - 0.1), abs(math.dist(B, C) - L)]
        if np.all(np.isfinite(z)) and max(res) < 1e-12:
            newton.append(z)
    assert newton
    for z in newton:
        assert min(np.max(np.abs(z - np.concatenate(f))) for f in found) < 1e-9


def test_the_sweep_follows_one_closure_and_agrees_with_the_staged_solve():
    from polygons.sweep import sweep
    scene = load_scene(CASES / "triad-ternary-coupler.toml")
    th = np.radians(np.linspace(40, 80, 21))
    sw = sweep(scene, inputs=th)
    x = np.array(sw.pos["X"])
    assert np.all(np.isfinite(x))
    assert np.max(np.hypot(*np.diff(x, axis=1))) < 0.02        # no jump between closures
    sol = solve(scene)
    k = 10                                                      # θ = 60°
    assert np.allclose([sw.vel["X"][0][k], sw.vel["X"][1][k]], sol.points["X"].velocity,
                       rtol=1e-12, atol=1e-15)
    assert np.allclose([sw.acc["B"][0][k], sw.acc["B"][1][k]],
                       sol.points["B"].acceleration, rtol=1e-12, atol=1e-14)


def test_the_compiled_program_equals_the_staged_solve():
    from polygons.compiled import compile_scene
    scene = load_scene(CASES / "triad-eight-bar.toml")
    prog = compile_scene(scene)
    assert prog is not None


def test_several_closures_without_words_are_refused_listing_them():
    text = (CASES / "triad-ternary-coupler.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    del data["assembly"]
    with pytest.raises(BranchError) as e:
        solve(parse_scene(data, file="t.toml"))
    assert "class-III group BCX has 2 closures" in str(e.value)


def test_a_group_that_cannot_close_is_refused_in_words():
    data = tomllib.loads((CASES / "triad-ternary-coupler.toml").read_text(encoding="utf-8"))
    data["links"]["XE"] = "10 mm"
    data["links"]["AB"] = "50 mm"
    with pytest.raises(PolygonsError) as e:
        solve(parse_scene(data, file="t.toml"))
    assert "cannot close" in str(e.value) or "closures" in str(e.value)
