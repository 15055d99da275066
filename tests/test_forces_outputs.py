"""``forces`` with an [efficiency] table: the machine results without being asked by name,
a scene whose only force table is [efficiency]; ``solve``'s table shows every asked answer."""
import json
import tomllib

import pytest

from conftest import CASES
from polygons.cli import main

CASE = CASES / "efficiency-four-bar.toml"


def _exact() -> dict:
    """The case's closed-form values (tests/analytic.py computed them), by quantity."""
    data = tomllib.loads(CASE.read_text(encoding="utf-8"))
    return {a["quantity"]: a["exact"] for a in data["force_answers"]}


def _machine(argv, capsys) -> dict:
    assert main(argv) == 0
    return {m["key"]: m for m in json.loads(capsys.readouterr().out)["states"][0]["machine"]}


def _unasked(tmp_path, keep_load: bool):
    """The case without its [[force_answers]] (nothing asked by name), and without its
    resisting torque unless ``keep_load``: [efficiency] is then its only force table."""
    text = CASE.read_text(encoding="utf-8")
    text = text[:text.index("[[force_answers]]")]
    if not keep_load:
        text = text[:text.index("[torques.Load]")] + text[text.index("[efficiency]"):]
    path = tmp_path / "unasked.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("keep_load", [True, False], ids=["with-load", "efficiency-only"])
def test_efficiency_reports_ratio_advantage_and_output_torque_unasked(tmp_path, capsys,
                                                                       keep_load):
    exact = _exact()
    path = _unasked(tmp_path, keep_load)
    m = _machine(["forces", str(path), "--json"], capsys)
    assert m["velocity_ratio_CD"]["value"] == pytest.approx(exact["VR(CD)"], rel=1e-9)
    assert m["mechanical_advantage_CD"]["value"] == pytest.approx(exact["MA(CD)"], rel=1e-9)
    assert m["output_torque_CD"]["value"] == pytest.approx(exact["Tout_eta(CD)"], rel=1e-9)
    assert m["output_torque_CD"]["unit"] == "N m"
    # only the output: the crank (driver) and the coupler (not on the frame) are not reported
    assert not any(k.endswith(("_AB", "_BC")) for k in m)
    assert ("input_with_efficiency" in m) == keep_load
    assert main(["forces", str(path)]) == 0
    text = capsys.readouterr().out
    assert "mechanical advantage η ω_AB/ω_CD" in text and "output torque on CD" in text


def test_a_scene_without_any_force_table_is_still_refused(tmp_path, capsys):
    text = CASE.read_text(encoding="utf-8")
    path = tmp_path / "none.toml"
    path.write_text(text[:text.index("[torques.Load]")], encoding="utf-8")
    assert main(["forces", str(path)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[efficiency]" in err[0]


def test_solve_table_shows_asked_answers_without_a_tutorial_value(capsys):
    data = tomllib.loads(CASE.read_text(encoding="utf-8"))
    assert main(["solve", str(CASE)]) == 0
    out = capsys.readouterr().out
    for a in data["answers"]:
        assert "tutorial" not in a
        row = next(ln for ln in out.splitlines() if ln.startswith(a["desc"][:34]))
        cells = row[34:].split()
        ours = float(cells[1])
        assert ours == pytest.approx(a["exact"], rel=1e-5)      # 6 significant figures
        assert cells[2:4] == ["-", "-"] and f"exact {a['exact']:.6g}" in row
