"""Problems stated as the books state them (issue 18): a slider whose pin drives a slotted
lever, a pivot placed from another, a plate's corner by its two distances."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from polygons.errors import SceneError
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.scene import load_scene, parse_scene

CASES = Path(__file__).resolve().parents[1] / "cases"


def screw_reference(x=0.15, y=0.2, xd=0.5, xdd=0.0):
    """Polar coordinates of the pin P = (x, y) on the fixed line y = const:
    θ' = (x y' − y x')/r², r' = (x x' + y y')/r; θ'' and r'' by differentiating again."""
    r2 = x * x + y * y
    r = math.sqrt(r2)
    w = (-y * xd) / r2
    rd = x * xd / r
    # θ'' = d/dt(−y x'/r²) = −(y x'' r² − y x' · 2 r r')/r⁴ ;  r'' = (x'² + x x'' − r'²)/r
    al = -(y * xdd * r2 - y * xd * 2 * r * rd) / (r2 * r2)
    rdd = (xd * xd + x * xdd - rd * rd) / r
    return {"omega(OQ)": w, "alpha(OQ)": al, "vs(P)": rd, "as(P)": rdd,
            "cor(P)": abs(2 * w * rd)}


def test_a_slotted_arm_driven_by_a_collar_on_a_screw():
    sol = solve(load_scene(CASES / "new-screw-slotted-arm.toml"))
    for q, v in screw_reference().items():
        assert quantity(sol, q) == pytest.approx(v, rel=1e-12, abs=1e-15), q


def test_the_screw_case_exact_answers_are_the_closed_form():
    ref = screw_reference()
    for a in load_scene(CASES / "new-screw-slotted-arm.toml").answers:
        assert a.exact == pytest.approx(ref[a.quantity] if a.mode == "signed"
                                        else abs(ref[a.quantity]), rel=1e-12), a.quantity


@pytest.mark.parametrize("x,xd,xdd", [(0.15, 0.5, 0.0), (-0.1, -0.3, 2.0), (0.4, 1.0, -1.5)])
def test_the_screw_at_other_instants(x, xd, xdd):
    text = (CASES / "new-screw-slotted-arm.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    data["driver"] = {"slider": "P", "position": f"{x * 1e3!r} mm",
                      "velocity": f"{xd!r} m/s", "acceleration": f"{xdd!r} m/s^2"}
    data.pop("answers")
    sol = solve(parse_scene(data, file="t.toml"))
    for q, v in screw_reference(x=x, xd=xd, xdd=xdd).items():
        assert quantity(sol, q) == pytest.approx(v, rel=1e-10, abs=1e-14), q


def _triad(ground_e, x_spec):
    data = tomllib.loads((CASES / "triad-ternary-coupler.toml").read_text(encoding="utf-8"))
    data.pop("answers")
    data["ground"]["E"] = ground_e
    for k in ("BX", "CX"):
        data["links"].pop(k)
    data["points"] = {"X": x_spec}
    return parse_scene(data, file="t.toml")


def test_a_plate_corner_by_two_distances_is_the_triangle_of_links():
    tri = solve(load_scene(CASES / "triad-ternary-coupler.toml"))
    plate = solve(_triad(["150 mm", "300 mm"], {"on": "BC", "distances": ["100 mm", "120 mm"],
                                                 "side": "left"}))
    for lab in "BCX":
        assert plate.points[lab].position == pytest.approx(tri.points[lab].position, abs=1e-12)
        assert plate.points[lab].acceleration == pytest.approx(
            tri.points[lab].acceleration, rel=1e-9, abs=1e-12)


def test_a_pivot_placed_from_another_by_distance_and_angle():
    frm = {"from": "D", "distance": f"{math.hypot(150, 300)!r} mm",
           "angle": f"{math.degrees(math.atan2(300, -150))!r} deg"}
    scene = _triad(frm, {"on": "BC", "distances": ["100 mm", "120 mm"], "side": "left"})
    assert scene.ground["E"] == pytest.approx((0.15, 0.3), abs=1e-15)
    cw = {"from": "O", "distance": "100 mm", "angle": "90 deg CW"}
    assert _triad(cw, {"on": "BC", "distances": ["100 mm", "120 mm"],
                       "side": "left"}).ground["E"] == pytest.approx((0.0, -0.1), abs=1e-15)


@pytest.mark.parametrize("e,x,words", [
    ({"from": "Z", "distance": "1 m", "angle": "0 deg"},
     {"on": "BC", "distances": ["100 mm", "120 mm"], "side": "left"}, "given before"),
    (["150 mm", "300 mm"], {"on": "BC", "distances": ["100 mm", "120 mm"]}, "side must be"),
    (["150 mm", "300 mm"], {"on": "BC", "distances": ["10 mm", "120 mm"], "side": "left"},
     "no triangle"),
    (["150 mm", "300 mm"], {"on": "BC", "distances": ["100 mm"], "side": "left"},
     "distances = [from the first label"),
    (["150 mm", "300 mm"], {"on": "BC", "distances": ["100 mm", "120 mm"], "side": "left",
                            "along": "5 mm"}, "not both"),
])
def test_book_forms_refused_in_words(e, x, words):
    with pytest.raises(SceneError) as exc:
        _triad(e, x)
    assert words in str(exc.value)


@pytest.mark.parametrize("words,equiv", [("30 deg from tdc", "30 deg from idc"),
                                         ("30 deg from bdc", "30 deg from odc")])
def test_top_and_bottom_dead_centre_are_the_inner_and_outer(words, equiv):
    base = tomllib.loads((CASES / "new-engine-from-idc.toml").read_text(encoding="utf-8"))
    base.pop("answers", None)
    a, b = dict(base), dict(base)
    a["driver"] = {**base["driver"], "angle": words}
    b["driver"] = {**base["driver"], "angle": equiv}
    assert parse_scene(a, file="t.toml").driver.angle == parse_scene(b, file="t.toml").driver.angle


def test_a_crank_without_a_sense_names_the_key_to_add():
    base = tomllib.loads((CASES / "s001-we1.toml").read_text(encoding="utf-8"))
    base["driver"] = {k: v for k, v in base["driver"].items() if k != "sense"}
    base["driver"]["omega"] = "300 rad/s"
    with pytest.raises(SceneError) as e:
        parse_scene(base, file="t.toml")
    assert "sense" in str(e.value) and "CW" in str(e.value)


def _engine(driver, assembly):
    return parse_scene({"ground": {"O": ["0 mm", "0 mm"]},
                        "links": {"OA": "50 mm", "AB": "170 mm"},
                        "sliders": {"B": {"through": ["0 mm", "0 mm"], "direction": "0 deg"}},
                        "driver": {"slider": "B", "velocity": "5 m/s", **driver},
                        "assembly": assembly}, file="t.toml")


def test_a_slider_driver_placed_by_the_angle_of_its_rod():
    """|B + L u(170°)| = r on the x-axis: s = −L cos φ ± √(r² − L² sin² φ)."""
    L, r, phi = 0.17, 0.05, math.radians(170)
    far = -L * math.cos(phi) + math.sqrt(r * r - (L * math.sin(phi)) ** 2)
    scene = _engine({"rod": "BA", "rod_angle": "170 deg"},
                    {"A": "A above O", "B": {"near": ["200 mm", "0 mm"]}})
    assert scene.driver.position == pytest.approx(far, rel=1e-14)
    sol = solve(scene)
    a, b = sol.points["A"].position, sol.points["B"].position
    assert math.degrees(math.atan2(a[1] - b[1], a[0] - b[0])) == pytest.approx(170, abs=1e-10)
    same = solve(_engine({"position": f"{far * 1e3!r} mm"}, {"A": "A above O"}))
    assert same.points["A"].velocity == pytest.approx(sol.points["A"].velocity, rel=1e-12)


def test_a_trammel_driven_by_one_slider_placed_by_its_bar_angle():
    scene = parse_scene({"ground": {"O": ["0 mm", "0 mm"]}, "links": {"AB": "100 mm"},
                         "sliders": {"A": {"through": ["0 mm", "0 mm"], "direction": "0 deg"},
                                     "B": {"through": ["0 mm", "0 mm"],
                                           "direction": "90 deg"}},
                         "driver": {"slider": "A", "rod": "AB", "rod_angle": "120 deg",
                                    "velocity": "1 m/s"},
                         "assembly": {"B": "B above O"}}, file="t.toml")
    assert scene.driver.position == pytest.approx(0.05, rel=1e-14)     # 100 cos 60°
    assert solve(scene).points["B"].position == pytest.approx((0.0, 0.1 * math.sin(
        math.radians(60))), abs=1e-15)


@pytest.mark.parametrize("driver,words", [
    ({"rod": "BA", "rod_angle": "170 deg", "position": "1 mm"}, "give exactly one"),
    ({"rod": "BA", "rod_angle": "170 deg"}, "two positions of B"),
    ({"rod": "OA", "rod_angle": "170 deg"}, "with the slider B at one end"),
    ({"rod": "BA", "rod_angle": "90 deg"}, "cannot reach"),
])
def test_a_rod_angle_that_does_not_place_the_slider_is_refused(driver, words):
    with pytest.raises(SceneError) as e:
        _engine(driver, {"A": "A above O"})
    assert words in str(e.value)


def block_reference():
    import analytic
    import analytic_more as am
    ad, ab, bc, cd, th, w, rho = 0.6, 0.2, 0.5, 0.4, math.radians(60), 10.0, 1.5
    ref = analytic.four_bar((0, 0), (ad, 0), ab, bc, cd, th, w, 0.0, +1)
    C = (complex(*ref["C"]), complex(*ref["vC"]), complex(*ref["aC"]))
    sl = am.slot(am.crank(am.fixed(0, 0), rho * ab, th, w, 0.0), C, 0.0)
    return {"omega(CQ)": sl["omega"], "alpha(CQ)": sl["alpha"], "vs(E)": sl["t_dot"],
            "as(E)": sl["t_ddot"], "cor(E)": abs(2 * sl["omega"] * sl["t_dot"])}


def test_a_block_pinned_to_one_moving_link_sliding_on_another():
    scene = load_scene(CASES / "new-block-on-moving-link.toml")
    sol = solve(scene)
    ref = block_reference()
    for q, v in ref.items():
        assert quantity(sol, q) == pytest.approx(v, rel=1e-9), q
    for a in scene.answers:
        assert a.exact == pytest.approx(ref[a.quantity] if a.mode == "signed"
                                        else abs(ref[a.quantity]), rel=1e-12), a.quantity


def engine_reference():
    """The slider-crank at the crank angle the rod's angle gives, at ω = 1 (analytic), then
    scaled: ω = v_B / ṡ₁, α = −ω² s̈₁ / ṡ₁ (the piston's acceleration zero)."""
    import analytic
    L, r, phi = 0.17, 0.05, math.radians(170)
    s = -L * math.cos(phi) + math.sqrt(r * r - (L * math.sin(phi)) ** 2)
    th = math.atan2(L * math.sin(phi), s + L * math.cos(phi))
    one = analytic.slider_crank((0, 0), r, L, th, 1.0, 0.0, (0, 0), 0.0, +1)
    w = 5.0 / one["s_dot"]
    al = -w * w * one["s_ddot"] / one["s_dot"]
    full = analytic.slider_crank((0, 0), r, L, th, w, al, (0, 0), 0.0, +1)
    return {"omega(OA)": w, "alpha(OA)": al, "omega(AB)": full["omega_AB"],
            "alpha(AB)": full["alpha_AB"], "v(A)": float(np.hypot(*full["vA"])),
            "a(A)": float(np.hypot(*full["aA"]))}


def test_the_engine_placed_by_its_rod_angle_matches_the_closed_form():
    scene = load_scene(CASES / "new-engine-rod-angle.toml")
    sol = solve(scene)
    ref = engine_reference()
    for q, v in ref.items():
        assert quantity(sol, q) == pytest.approx(v, rel=1e-9), q
    for a in scene.answers:
        assert a.exact == pytest.approx(ref[a.quantity] if a.mode == "signed"
                                        else abs(ref[a.quantity]), rel=1e-12), a.quantity


# ---------------------------------------------------------------- the rod's ω and α given
def ladder_reference(L, phi, w, al):
    """A bar AB, A on the x-axis, B on the y-axis, at φ (A → B, CCW from +x) turning at ω, α:
    A = (−L cos φ, 0), B = (0, L sin φ);  ẋ_A = L sin φ ω,  ẍ_A = L sin φ α + L cos φ ω²,
    ẏ_B = L cos φ ω,  ÿ_B = L cos φ α − L sin φ ω²."""
    s, c = math.sin(phi), math.cos(phi)
    return {"vA": L * s * w, "aA": L * s * al + L * c * w * w,
            "vB": L * c * w, "aB": L * c * al - L * s * w * w}


def _ladder(rod_rate: dict, angle="150 deg", assembly=None):
    data = {"ground": {"O": ["0 m", "0 m"]}, "links": {"AB": "4 m"},
            "sliders": {"A": {"through": ["0 m", "0 m"], "direction": "0 deg"},
                        "B": {"through": ["0 m", "0 m"], "direction": "90 deg"}},
            "driver": {"slider": "A", "rod": "AB", "rod_angle": angle, **rod_rate}}
    if assembly:
        data["assembly"] = assembly
    return parse_scene(data, file="t.toml")


def test_a_ladder_driven_by_the_bar_s_omega_and_alpha():
    """'The ladder AB (4 m) makes 30° with the floor and turns at 2 rad/s CCW, 1.5 rad/s² CW':
    the slider's v and a follow, B is where the bar's angle puts it (no [assembly] needed), and
    the polygons give the bar the stated ω and α back."""
    scene = _ladder({"rod_omega": "2 rad/s CCW", "rod_alpha": "1.5 rad/s^2",
                     "rod_alpha_sense": "CW"})
    ref = ladder_reference(4.0, math.radians(150), 2.0, -1.5)
    assert scene.driver.velocity == pytest.approx(ref["vA"], rel=1e-14)
    assert scene.driver.acceleration == pytest.approx(ref["aA"], rel=1e-13)
    assert scene.driver.rod_rate == ("AB", 2.0, -1.5) and scene.driver.rod_angle_deg == \
        pytest.approx(90.0)      # the two guides at right angles
    sol = solve(scene)
    assert sol.points["B"].position == pytest.approx((0.0, 2.0), abs=1e-12)
    assert sol.points["B"].velocity == pytest.approx((0.0, ref["vB"]), abs=1e-12)
    assert sol.points["B"].acceleration == pytest.approx((0.0, ref["aB"]), abs=1e-12)
    assert sol.links["AB"].omega == pytest.approx(2.0, rel=1e-12)
    assert sol.links["AB"].alpha == pytest.approx(-1.5, rel=1e-12)


@pytest.mark.parametrize("seed", range(12))
def test_the_rod_gets_its_stated_omega_and_alpha_back(seed):
    """Random trammels (guides at any angles) and engines (the rod's far end on a crank): the
    polygons, drawn from the slider's derived v and a, give the rod exactly the stated ω, α."""
    rng = np.random.default_rng(seed)
    w, al = float(rng.uniform(-20, 20)), float(rng.uniform(-200, 200))
    rate = {"rod_omega": f"{abs(w)!r} rad/s {'CCW' if w > 0 else 'CW'}",
            "rod_alpha": f"{abs(al)!r} rad/s^2 {'CCW' if al > 0 else 'CW'}"}
    if seed % 2:
        g1, g2 = (float(x) for x in rng.uniform(0, 180, 2))
        if abs(math.sin(math.radians(g1 - g2))) < 0.3:
            g2 = g1 + 70
        phi = float(rng.uniform(0, 360))
        data = {"ground": {"O": ["0 m", "0 m"]}, "links": {"AB": "0.3 m"},
                "sliders": {"A": {"through": ["0 m", "0 m"], "direction": f"{g1!r} deg"},
                            "B": {"through": ["0 m", "0 m"], "direction": f"{g2!r} deg"}},
                "driver": {"slider": "A", "rod": "AB", "rod_angle": f"{phi!r} deg", **rate}}
        rod = "AB"
    else:
        phi = float(rng.uniform(140, 220))
        data = {"ground": {"O": ["0 mm", "0 mm"]}, "links": {"OA": "50 mm", "AB": "170 mm"},
                "sliders": {"B": {"through": ["0 mm", "0 mm"], "direction": "0 deg"}},
                "driver": {"slider": "B", "rod": "BA", "rod_angle": f"{phi!r} deg", **rate},
                "assembly": {"B": {"near": ["200 mm", "0 mm"]}}}
        rod = "AB"
    try:
        scene = parse_scene(data, file="t.toml")
    except SceneError as e:
        assert "does not turn" in str(e) or "cannot reach" in str(e) or "parallel" in str(e)
        return
    sol = solve(scene)
    assert sol.links[rod].omega == pytest.approx(w, rel=1e-9, abs=1e-9)
    assert sol.links[rod].alpha == pytest.approx(al, rel=1e-9, abs=1e-7)


@pytest.mark.parametrize("rate,words", [
    ({"rod_omega": "2 rad/s CCW", "velocity": "1 m/s"}, "exactly one"),
    ({"rod_omega": "2 rad/s"}, "rod_omega needs its sense"),
    ({"rod_omega": "2 rad/s CCW", "acceleration": "1 m/s^2"}, "not acceleration"),
    ({"rod_omega": "2 rad/s CCW", "rod_alpha": "3 rad/s^2"}, "rod_alpha needs"),
    ({"rod_sense": "CW", "velocity": "1 m/s"}, "go with rod_omega"),
])
def test_the_rod_rate_refused_in_words(rate, words):
    with pytest.raises(SceneError) as e:
        _ladder(rate)
    assert words in str(e.value)


def test_the_rod_omega_where_the_rod_does_not_turn_is_refused():
    """An engine with its crank at right angles to the line of stroke: the rod does not turn
    at this instant, whatever the piston's speed, so its ω cannot give the piston's."""
    phi = math.degrees(math.atan2(0.05, -math.sqrt(0.17 ** 2 - 0.05 ** 2)))
    with pytest.raises(SceneError) as e:
        _engine_rate(phi, {"rod_omega": "2 rad/s CCW"})
    assert "does not turn at this instant" in str(e.value)


def _engine_rate(phi, rate):
    return parse_scene({"ground": {"O": ["0 mm", "0 mm"]},
                        "links": {"OA": "50 mm", "AB": "170 mm"},
                        "sliders": {"B": {"through": ["0 mm", "0 mm"], "direction": "0 deg"}},
                        "driver": {"slider": "B", "rod": "BA", "rod_angle": f"{phi!r} deg",
                                   **rate},
                        "assembly": {"B": {"near": ["200 mm", "0 mm"]}}}, file="t.toml")


def test_the_ladder_case_exact_answers_are_the_closed_form():
    scene = load_scene(Path(__file__).resolve().parents[1] / "cases" / "book-ladder-bar-omega.toml")
    ref = ladder_reference(4.0, math.radians(150), 2.0, -1.5)
    want = {"v(A)": ref["vA"], "v(B)": ref["vB"], "a(A)": ref["aA"], "a(B)": ref["aB"]}
    for a in scene.answers:
        assert a.exact == pytest.approx(abs(want[str(a.quantity)]), rel=1e-14)
    sol = solve(scene)
    for a in scene.answers:
        assert quantity(sol, str(a.quantity)) == pytest.approx(a.exact, rel=1e-12)


def test_the_rod_omega_near_where_the_rod_does_not_turn_is_warned():
    """0.002° from the engine's extreme rod angle the two directions giving the piston's speed
    meet at under 1°: solved, and said to be unreliable (as a construction near a toggle)."""
    phi = math.degrees(math.atan2(0.05, -math.sqrt(0.17 ** 2 - 0.05 ** 2)))
    scene = _engine_rate(phi + 0.002, {"rod_omega": "2 rad/s CCW"})
    assert scene.driver.rod_angle_deg < 1.0
    assert any("the rod barely turns" in w for w in solve(scene).warnings)
    far = _engine_rate(170.0, {"rod_omega": "2 rad/s CCW"})
    assert far.driver.rod_angle_deg > 10.0
    assert not any("the rod barely turns" in w for w in solve(far).warnings)
