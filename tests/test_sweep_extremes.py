"""The sweep summary's maxima are the greatest values themselves, refined between samples
(polygons/sweep_extremes.py), not the largest sample: checked against the question engine
(Brent's method on the staged construction, polygons/conditions.py) on Fig 7's quick return."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from conftest import ROOT
from polygons.conditions import answer
from polygons.question_table import Question
from polygons.scene import load_scene
from polygons.sweep import sweep
from polygons.sweep_extremes import greatest


def _question(quantity: str, condition: str) -> Question:
    return Question(index=1, find="angle", quantity=quantity, condition=condition, value=None,
                    range=None, samples=72, unit="deg", value_unit=None, exact=None,
                    tutorial=None, value_exact=None, tolerance=0.0, desc="")


@pytest.fixture(scope="module")
def fig7():
    scene = load_scene(str(ROOT / "cases" / "s003-fig7.toml"))
    return scene, sweep(scene, 360)


@pytest.mark.parametrize("quantity, values", [
    ("a(P4)", lambda s: np.hypot(*s.acceleration("P4").T)),
    ("alpha(O4P4)", lambda s: np.abs(s.alpha["O4P4"])),
])
def test_the_greatest_is_the_question_engines_extreme(fig7, quantity, values):
    scene, sw = fig7
    value, x = greatest(sw, values)
    sampled = float(np.nanmax(values(sw)))
    conds = ("max", "min") if quantity.startswith("alpha") else ("max",)
    roots = [r for c in conds for r in answer(scene, _question(quantity, c)).roots]
    want = max(abs(r.value) for r in roots)
    assert value == pytest.approx(want, rel=1e-9)
    assert min(abs(math.remainder(x - r.input, 2 * math.pi)) for r in roots
               if abs(r.value) == pytest.approx(want, rel=1e-9)) < 1e-6
    assert (want - sampled) / want > 1e-6          # the largest sample is not it


def test_the_summary_prints_the_refined_greatest(fig7, tmp_path, capsys):
    from polygons.cli import main
    assert main(["sweep", str(ROOT / "cases" / "s003-fig7.toml"), "--no-plot", "-o",
                 str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "max |a| = 8015.9 mm/s² at θ = 300.295°" in out       # the sample: 8015.4 at 300°
    assert "max |v| = 1047.2 mm/s (the same at every position)" in out      # the crank pin
