"""A block on a fixed guide driven through its pin by the (offset) slot of a turning lever —
the tangent mechanism, a kind added in its own module (polygons/dyads/slot_slider.py) —
against its closed form, differentiated by hand (never the solver):

    slot O + δ n + u f (f = (cos θ, sin θ), n = perp f),  guide G + s e:
    s = N / D,  N = (O − G) × f − δ,  D = e × f;   N′ = (O − G)·f,  D′ = e·f,
    s′ = (N′ D − N D′) / D²,  s″ = −(δ + 2 D′ s′) / D;
    u = (G − O + s e)·f,  u′ = s′ e·f + (G − O + s e)·n,  u″ = s″ e·f + 2 s′ e·n − u;
    d/dt = ω d/dθ,  d²/dt² = ω² d²/dθ² + α d/dθ.

The block's velocity ṡ e and acceleration s̈ e, the pin's sliding ü and u̇ along the slot
(O → Q), the Coriolis 2 ω u̇, and the lever's torque by a power balance; every method handles
the kind or refuses it in one line naming it."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from polygons.evaluate import solve
from polygons.scene import load_scene, parse_scene

CASE = Path(__file__).resolve().parents[1] / "cases" / "new-slot-slider.toml"
REL = 1e-9


def closed_form(theta, w, al, delta, G, beta):
    """(X, v_X, a_X, u̇, ü) of the block for the lever at θ (pivot at the origin)."""
    f = np.array([math.cos(theta), math.sin(theta)])
    n = np.array([-f[1], f[0]])
    e = np.array([math.cos(beta), math.sin(beta)])
    wv = -np.asarray(G, dtype=float)                           # O − G
    N = wv[0] * f[1] - wv[1] * f[0] - delta
    D = e[0] * f[1] - e[1] * f[0]
    N1, D1 = wv @ f, e @ f
    s = N / D
    s1 = (N1 * D - N * D1) / D ** 2
    s2 = -(delta + 2.0 * D1 * s1) / D
    r = -wv + s * e                                            # X − O
    u, u1 = r @ f, s1 * (e @ f) + r @ n
    u2 = s2 * (e @ f) + 2.0 * s1 * (e @ n) - u
    X = np.asarray(G, dtype=float) + s * e
    return X, w * s1 * e, (w * w * s2 + al * s1) * e, w * u1, w * w * u2 + al * u1


def _scene(theta_deg, w, al, delta_mm, gx_mm, gy_mm, beta_deg, length_mm=400.0):
    return parse_scene(tomllib.loads(f"""
[ground]
O = ["0 mm", "0 mm"]
[links]
OQ = "{length_mm} mm"
[sliders.P]
through = ["{gx_mm} mm", "{gy_mm} mm"]
direction = "{beta_deg} deg"
[slots.P]
lever = "OQ"
coincident = "P1"
offset = "{delta_mm} mm"
[driver]
crank = "OQ"
angle = "{theta_deg} deg"
omega = "{w} rad/s CCW"
alpha = "{abs(al)} rad/s^2 {'CCW' if al >= 0 else 'CW'}"
"""))


def _agrees(sol, theta, w, al, delta, G, beta):
    X, v, a, ud, udd = closed_form(theta, w, al, delta, G, beta)
    P = sol.points["P"]
    scale = max(float(np.hypot(*X)), 1e-3)
    assert np.hypot(*(np.array(P.position) - X)) <= REL * scale
    assert np.hypot(*(np.array(P.velocity) - v)) <= REL * max(np.hypot(*v), w * scale)
    assert np.hypot(*(np.array(P.acceleration) - a)) <= REL * max(np.hypot(*a), w * w * scale)
    sl = sol.slides["P"]
    sign = 1.0 if delta else float(np.sign((X @ [math.cos(theta), math.sin(theta)])))
    assert abs(sl.velocity - sign * ud) <= REL * max(abs(ud), w * scale)
    assert abs(sl.acceleration - sign * udd) <= REL * max(abs(udd), w * w * scale)
    assert abs(np.hypot(*sl.coriolis) - 2 * abs(w * ud)) <= REL * max(2 * abs(w * ud), 1e-9)


def test_the_closed_forms_derivatives_are_its_finite_differences():
    """The oracle itself checked: s′, s″ (and u′, u″) against central differences of s(θ)."""
    args = (0.02, (0.03, 0.15), 0.2)
    h = 1e-4
    for th in (0.6, 1.3, 2.2):
        X0 = closed_form(th, 1.0, 0.0, *args)
        Xp, Xm = closed_form(th + h, 1.0, 0.0, *args)[0], closed_form(th - h, 1.0, 0.0, *args)[0]
        assert np.allclose(X0[1], (Xp - Xm) / (2 * h), rtol=1e-6, atol=1e-9)
        assert np.allclose(closed_form(th, 1.0, 0.0, *args)[2], (Xp - 2 * X0[0] + Xm) / h ** 2,
                           rtol=1e-5, atol=1e-6)
        f = lambda t: closed_form(t, 1.0, 0.0, *args)[0] @ [math.cos(t), math.sin(t)]  # noqa: E731
        assert math.isclose(X0[3], (f(th + h) - f(th - h)) / (2 * h), rel_tol=1e-6)
        assert math.isclose(X0[4], (f(th + h) - 2 * f(th) + f(th - h)) / h ** 2, rel_tol=1e-5)


def test_the_case_is_its_closed_form_and_its_answers_are_the_oracles():
    scene = load_scene(CASE)
    sol = solve(scene)
    theta, w, al, delta, G, beta = math.radians(50), 2.0, 20.0, 0.02, (0.0, 0.15), 0.0
    _agrees(sol, theta, w, al, delta, G, beta)
    X, v, a, ud, udd = closed_form(theta, w, al, delta, G, beta)
    oracle = {"v(P)": np.hypot(*v), "a(P)": np.hypot(*a), "vs(P)": ud, "as(P)": udd,
              "cor(P)": 2 * abs(w * ud), "v(P1)": w * np.hypot(*X),
              "a(P1)": np.hypot(*X) * math.hypot(al, w * w),
              # the torque on the lever: power balance, T ω = −(F − m a)·v (a massless lever)
              "Tin": -((np.array([200.0, 0.0]) - 2.0 * a) @ v) / w}
    stated = {a_.quantity: a_.exact for a_ in scene.answers}
    stated.update({f.quantity: f.exact for f in scene.loads.answers})
    assert set(stated) == set(oracle)
    for q, exact in stated.items():
        assert math.isclose(exact, oracle[q], rel_tol=1e-12), q


@pytest.mark.parametrize("seed", range(6))
def test_random_tangent_mechanisms_are_their_closed_forms(seed):
    rng = np.random.default_rng(seed)
    th = rng.uniform(25, 155) + (0 if seed % 2 else 180)     # the pin either side of O
    beta = rng.uniform(-10, 10)
    delta = 0.0 if seed % 3 == 0 else rng.uniform(-40, 40)
    gx, gy = rng.uniform(-100, 100), rng.uniform(80, 250) * (1 if seed % 4 < 2 else -1)
    w, al = rng.uniform(1, 15), rng.uniform(-50, 50)
    sol = solve(_scene(th, w, al, delta, gx, gy, beta))
    _agrees(sol, math.radians(th), w, al, delta / 1e3, (gx / 1e3, gy / 1e3), math.radians(beta))


def test_every_command_takes_it_or_refuses_it_in_one_line_naming_it(tmp_path, capsys):
    """forces (Newton–Euler, virtual work, Zhukovsky: the same torque), centres, sweep, draw
    and check take it (solve, the compiled program, the drawing board and the numba kernel:
    every case's tests); the graphical force polygons refuse it in one line, in words."""
    from polygons.cli import main
    path = str(CASE)
    out = {}
    for cmd, extra in (("forces", ()), ("centres", ("-o", str(tmp_path / "c"))),
                       ("sweep", ("--steps", "12", "--no-plot", "-o", str(tmp_path / "s"))),
                       ("draw", ("-o", str(tmp_path / "d"))),
                       ("check", ("--measured", "v_P=0.4674"))):
        assert main([cmd, path, *extra]) == 0, cmd
        out[cmd] = capsys.readouterr().out
    refusal = [ln for ln in out["forces"].splitlines() if "does not handle" in ln]
    assert len(refusal) == 1 and "the force-polygon construction does not handle a slider on " \
        "a fixed guide driven through its pin by the slot of a turning lever" in refusal[0]
    assert "virtual work 48.241444 N m CCW; difference" in out["forces"]
    assert "limit at θ = 180°: the slot of OQ is parallel to the guide of P" in out["sweep"]
    assert "I13     frame / block P" in out["centres"]


def test_a_slot_parallel_to_the_guide_is_refused_in_words():
    from polygons.errors import PolygonsError
    with pytest.raises(PolygonsError) as e:
        solve(_scene(0.0, 10.0, 0.0, 0.0, 0.0, 150.0, 0.0))
    assert "the slot of OQ is parallel to the guide of P" in str(e.value)


def test_the_kind_registers_itself():
    """Its module declares ROLE and BEFORE; polygons/dyads/__init__.py does not name it."""
    import inspect
    from polygons import dyads
    from polygons.dyads import slot_slider
    assert "slot_slider" not in inspect.getsource(dyads)
    kinds = list(dyads.POINT_KINDS)
    assert kinds.index(slot_slider) < kinds.index(dyads.rrr)
    assert dyads.SlotSlider is slot_slider.SlotSlider and "SlotSlider" in dyads.__all__
