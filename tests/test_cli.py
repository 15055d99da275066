"""The CLI through its entry point: output, JSON shape, and one-line errors.

Most tests call the entry point function in this process (conftest.cli: ``main(argv)``); the
console script runs as a real process where that is what is checked: byte-identical output
across processes, exit codes and nothing but one line on a real stderr."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import CASES, cli

EXE = Path(sys.executable).with_name("polygons")


def run(*args, cwd=None):
    """``polygons ARGS`` in this process (the entry point function)."""
    return cli(*args, cwd=cwd)


def run_process(*args, cwd=None):
    """``polygons ARGS`` as a separate process (the console script)."""
    cmd = [str(EXE)] if EXE.exists() else [sys.executable, "-m", "polygons"]
    return subprocess.run(cmd + [str(a) for a in args], capture_output=True, text=True,
                          cwd=cwd, timeout=120)


def test_solve_fig7_prints_omega4_alpha4_and_coriolis_with_senses():
    out = run("solve", CASES / "s003-fig7.toml")
    assert out.returncode == 0, out.stderr
    link = next(l for l in out.stdout.splitlines() if l.startswith("O4P4 "))
    assert "1.2146 CCW" in link and "4.10822 CCW" in link
    assert "Coriolis 2ωv = 1.9576 m/s²" in out.stdout
    assert "conditioning" in out.stdout


def test_solve_json_has_the_documented_keys():
    out = run("solve", CASES / "s003-fig7.toml", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["links"]["O4P4"]["omega"] == pytest.approx(1.2145955942749975, rel=1e-12)
    assert data["links"]["O4P4"]["alpha"] == pytest.approx(4.108215643870321, rel=1e-9)
    assert len(data["points"]["P2"]["velocity"]) == 2
    assert len(data["points"]["P4"]["acceleration"]) == 2
    assert data["min_intersection_angle_deg"] == pytest.approx(90.0)
    kinds = [s["kind"] for s in data["steps"]]
    assert "intersection" in kinds and "vector" in kinds
    assert all(s["formula"] and s["reason"] for s in data["steps"])


def test_json_is_byte_identical_across_runs():
    a = run_process("solve", CASES / "s003-fig7.toml", "--json").stdout
    b = run_process("solve", CASES / "s003-fig7.toml", "--json").stdout
    assert a == b and a


GOOD = """
title = "test four-bar"
[ground]
A = ["0 mm", "0 mm"]
D = ["200 mm", "0 mm"]
[links]
AB = "80 mm"
BC = "136 mm"
CD = "160 mm"
[driver]
crank = "AB"
angle = "300 deg"
omega = "480 rad/s"
sense = "CW"
[assembly]
C = "C below AD"
"""


def test_good_scene_solves(write_scene):
    out = run("solve", write_scene(GOOD))
    assert out.returncode == 0, out.stderr


@pytest.mark.parametrize("change,expected", [
    (("omega = ", "omgea = "), "unknown key 'omgea'.*did you mean 'omega'"),
    (('"80 mm"', "80"), r"\[links.AB\].*missing unit"),
    (('"80 mm"', '"80 rad/s"'), r"\[links.AB\].*angular velocity"),
    (('"200 mm", "0 mm"', '"600 mm", "0 mm"'), r"\[C\].*cannot close.*BC \+ CD = 296 mm is shorter than BD"),
    (('C = "C below AD"', 'C = "C below AE"'), r"unknown point 'E'"),
    (('C = "C below AD"', ''), r"\[assembly.C\].*two closures.*say which in \[assembly\], e.g. C = \"C (above|below) [A-D]{2}\""),
    (('crank = "AB"', 'crank = "BA"'), r"first label B.*fixed pivot"),
    (('sense = "CW"', 'sense = "clockwise-ish"'), r"sense must be 'CW' or 'CCW'"),
    (("[links]", "[links\n"), r"not valid TOML"),
])
def test_bad_scenes_give_one_readable_line(write_scene, change, expected):
    import re
    old, new = change
    assert old in GOOD
    out = run("solve", write_scene(GOOD.replace(old, new, 1)))
    assert out.returncode != 0
    assert "Traceback" not in out.stderr
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert "scene.toml" in lines[0]
    assert re.search(expected, lines[0]), lines[0]


def test_toggle_position_names_the_step_and_the_parallel_lines(write_scene):
    # AB + BC = AC: at 0 deg the crank and coupler are in line with C on the axis
    # A, B, C, D in one line (AD = AB + BC + CD): the lines ⟂ BC and ⟂ CD are parallel
    text = GOOD.replace('"300 deg"', '"0 deg"').replace('D = ["200 mm", "0 mm"]',
                                                      'D = ["376 mm", "0 mm"]')
    out = run("solve", write_scene(text))
    assert out.returncode != 0
    assert "Traceback" not in out.stderr
    line = out.stderr.strip()
    assert "\n" not in line
    assert "step velocity" in line and "parallel" in line and "toggle" in line


def test_missing_file_and_unknown_command():
    out = run_process("solve", "no/such/file.toml")
    assert out.returncode != 0 and "no such scene file" in out.stderr
    out = run_process("frobnicate")
    assert out.returncode == 2 and "invalid choice" in out.stderr
    assert "Traceback" not in out.stderr


DRAWN = """
title = "SAE4-Q3 style: positions as drawn instead of lengths"
[ground]
O = ["0 mm", "0 mm"]
C = ["135 mm", "-64.01924 mm"]
[drawn]
A = ["15 mm", "25.98076 mm"]
B = ["135 mm", "25.98076 mm"]
[links]
OA = "drawn"
AB = "drawn"
BC = "drawn"
[driver]
crank = "OA"
omega = "100 rad/s"
sense = "CCW"
"""


def test_drawn_positions_give_lengths_angle_and_branch(write_scene):
    from polygons import load_scene, solve
    sol = solve(load_scene(write_scene(DRAWN)))
    assert sol.links["OA"].length == pytest.approx(0.03, rel=1e-6)
    assert sol.points["B"].position == pytest.approx((0.135, 0.02598076), abs=1e-9)
    assert sol.placement.branches[0][1].startswith("B as drawn")


def test_drawn_position_that_contradicts_the_lengths_is_an_error(write_scene):
    text = DRAWN.replace('AB = "drawn"', 'AB = "110 mm"')
    out = run("solve", write_scene(text))
    assert out.returncode != 0 and "Traceback" not in out.stderr
    assert "[drawn.B]" in out.stderr and "disagree" in out.stderr


# ---------------------------------------------------------------- scene text is escaped
EVIL = "<script>alert('x')</script> & <b>"


def test_scene_text_is_escaped_in_handouts_svgs_and_the_gallery(tmp_path):
    """A title, a statement and an answer's words holding markup come out escaped in the
    handout, the worksheet, every SVG and the gallery index (never as live markup)."""
    text = (CASES / "s001-we4.toml").read_text(encoding="utf-8")
    text = text.replace('title = "Worked example 4', f'title = "{EVIL} Worked example 4', 1)
    text = text.replace('desc = "', f'desc = "{EVIL} ', 1)
    folder = tmp_path / "cases"
    folder.mkdir()
    scene = folder / "evil.toml"
    scene.write_text(text, encoding="utf-8")
    outputs = []
    for args in (["handout", scene, "-o", tmp_path / "h.html"],
                 ["handout", scene, "-o", tmp_path / "w.html", "--worksheet"],
                 ["draw", scene, "-o", tmp_path / "svg"],
                 ["gallery", folder, "-o", tmp_path / "gallery"]):
        out = run(*args)
        assert out.returncode == 0, out.stderr
    outputs = [tmp_path / "h.html", tmp_path / "w.html", *sorted((tmp_path / "svg").glob("*.svg")),
               *sorted((tmp_path / "gallery").rglob("*.html")),
               *sorted((tmp_path / "gallery").rglob("*.svg"))]
    assert len(outputs) >= 5
    seen_escaped = 0
    for path in outputs:
        body = path.read_text(encoding="utf-8")
        assert "<script>alert" not in body, path.name
        assert "<b>" not in body, path.name
        seen_escaped += "&lt;script&gt;" in body
    assert seen_escaped >= 3      # the title really is in the pages, escaped


def test_dev_zero_and_a_directory_are_one_line_errors(tmp_path):
    for target, words in (("/dev/zero", "character device"), (tmp_path, "directory")):
        if not Path(target).exists():
            continue
        out = run("solve", target)
        assert out.returncode == 1 and out.stdout == ""
        assert out.stderr.count("\n") == 1 and words in out.stderr, out.stderr
        assert out.stderr.startswith(f"polygons: error: {target}")


def test_usage_error_is_exit_2_and_one_line():
    out = run_process("solve", "--no-such-flag", CASES / "s001-we4.toml")
    assert out.returncode == 2 and out.stderr.count("\n") == 1
    assert out.stderr.startswith("polygons: error: ")
