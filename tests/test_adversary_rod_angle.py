"""Adversary campaign: a slider driver placed by its rod's angle, with [assembly] words for the
rod's far end that pick the other closure.

Defect found on main: cases/new-engine-rod-angle.toml (OA 50 mm, AB 170 mm, the piston B at
5 m/s, ``A = "A above O"``) with ``rod_angle = "187 deg"``: the words placed A above the line,
where BA is at 173°, and `polygons solve` answered that pose silently — ω_OA = 190.077 rad/s
CW where the stated pose (BA at 187°, A below) gives 190.077 rad/s CCW; finite differences of
the positions at 187° ± 1e-4° gave v_B = −5 m/s against the stated +5. Now refused in words
naming [assembly.A]; without the words, or with "A below O", the stated pose is solved.
"""
from __future__ import annotations

import math

import pytest

import polygons
from polygons.errors import BranchError

from conftest import CASES

CASE = (CASES / "new-engine-rod-angle.toml").read_text()


def _scene(angle: float, words: str | None = "A above O"):
    text = CASE.replace('rod_angle = "170 deg"', f'rod_angle = "{angle!r} deg"')
    text = text.replace('A = "A above O"', f'A = "{words}"' if words else "")
    return polygons.load(text)


def _rod_angle(res) -> float:
    (bx, by), (ax, ay) = res.points["B"].position, res.points["A"].position
    return math.degrees(math.atan2(ay - by, ax - bx)) % 360.0


def test_words_picking_the_mirror_are_refused():
    with pytest.raises(BranchError, match=r"rod BA is at 173°, not at its stated rod_angle 187°"):
        polygons.solve(_scene(187.0))


@pytest.mark.parametrize("words", [None, "A below O"])
def test_the_stated_pose_is_solved(words):
    res = polygons.solve(_scene(187.0, words))
    assert _rod_angle(res) == pytest.approx(187.0, abs=1e-9)
    omega = res.links["OA"].omega
    assert omega == pytest.approx(190.077, rel=1e-5)        # CCW: A below the line
    # finite differences of B's position in time (dθ_rod/dt = ω_AB): the piston's +5 m/s
    h = 1e-4
    xs = [polygons.solve(_scene(187.0 + d, words)).points["B"].position[0] for d in (h, -h)]
    dt = math.radians(h) / res.links["AB"].omega
    assert (xs[0] - xs[1]) / (2 * dt) == pytest.approx(5.0, rel=1e-6)


def test_the_shipped_case_and_its_sweep_still_solve():
    scene = polygons.load(CASES / "new-engine-rod-angle.toml")
    res = polygons.solve(scene)
    assert _rod_angle(res) == pytest.approx(170.0, abs=1e-9)
    batch = polygons.solve_many(scene, s=[0.2, 0.205, 0.21])   # other positions: no angle
    assert not batch.errors


def test_a_solve_of_other_targets_only():
    res = polygons.solve(_scene(170.0), targets=["O"])      # the rod's ends not placed
    assert "A" not in res.points
