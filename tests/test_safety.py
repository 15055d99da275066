"""Regression tests for issue 20's adversarial findings (items 1-4): every one ends in a clean
one-line refusal or a correct answer, every count a user gives is bounded before work starts,
no output overwrites the input, and user text is escaped wherever it lands.

Fast by design (in process; the few commands that draw run on a four-bar, without stages).
"""
from __future__ import annotations

import contextlib
import io
import math
import os
import signal
import stat
from pathlib import Path

import numpy as np
import pytest

import polygons
from polygons.cli import main
from polygons.errors import PolygonsError, SceneError

FOUR_BAR = """title = "four-bar"
[ground]
A = ["0 mm", "0 mm"]
D = ["450 mm", "0 mm"]
[links]
AB = "100 mm"
BC = "400 mm"
CD = "350 mm"
[driver]
crank = "AB"
angle = "90 deg"
omega = "12 rad/s"
sense = "CCW"
[assembly]
C = "C above AD"
"""
#: ω_CD of FOUR_BAR (the closed-form four-bar, cases/efficiency-four-bar.toml)
OMEGA_CD = 2.9080235372011267


def run(*args) -> tuple[int, str, str]:
    """``polygons ARGS`` in process: (exit code, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main([str(a) for a in args])
        except SystemExit as exc:                  # argparse: usage errors
            code = exc.code if isinstance(exc.code, int) else 1
    return code, out.getvalue(), err.getvalue()


def refused(code, out, err, *words, exit_code=1) -> str:
    """Assert a clean refusal: the exit code, nothing on stdout, one stderr line with
    ``words``; never an internal error."""
    lines = err.splitlines()
    assert code == exit_code, (code, err)
    assert len(lines) == 1 and lines[0].startswith("polygons: error: "), err
    for w in words:
        assert w in lines[0], (w, lines[0])
    return lines[0]


@pytest.fixture
def scene(tmp_path):
    def write(text: str = FOUR_BAR, name: str = "s.toml") -> Path:
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path
    return write


@contextlib.contextmanager
def deadline(seconds: int):
    """Fail instead of hanging (a FIFO opened for reading waits for a writer)."""
    def boom(*_):
        raise TimeoutError(f"blocked for {seconds} s")
    old = signal.signal(signal.SIGALRM, boom)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


# ---------------------------------------------------------------- 1. internal errors → refusals
@pytest.mark.parametrize("escape", ["\\u0000", "\\u001b", "\\b", "\\u007f", "\\u0085"])
def test_a_control_character_in_the_title_is_refused(scene, escape):
    path = scene(FOUR_BAR.replace('title = "four-bar"', f'title = "a{escape}b"'))
    refused(*run("solve", path), "[title]", "control character")


def test_tabs_and_line_breaks_in_text_are_still_text(scene):
    path = scene(FOUR_BAR.replace('title = "four-bar"', 'title = "a\\tb\\nc\\r"'))
    code, out, err = run("solve", path, "--no-steps")
    assert code == 0 and err == ""


def test_the_generated_code_is_named_by_printable_characters_only():
    from polygons.codegen import _code_name
    assert _code_name("a\x00b\x1b") == "a?b?"
    assert len(_code_name("x" * 10_000)) == 80 and _code_name("") == "scene"


SPRING = FOUR_BAR + """[masses.BC]
mass = "2 kg"
[springs.s]
stiffness = "100 N/m"
free_length = "0.1 m"
"""


@pytest.mark.parametrize("ends", ['between = ["C", "C"]\non = ["BC", "CD"]',
                                  'between = ["A", "A"]'])
def test_a_spring_between_a_point_and_itself_is_refused(scene, ends):
    refused(*run("forces", scene(SPRING + ends + "\n")), "[springs.s.between]", "itself")


def test_a_spring_whose_ends_coincide_is_refused(scene):
    text = SPRING.replace("[masses.BC]", '[points.E]\non = "BC"\nfraction = 1\n[masses.BC]')
    path = scene(text + 'between = ["E", "C"]\non = ["BC", "CD"]\n')
    refused(*run("forces", path), "[springs.s]", "coincide")


@pytest.mark.parametrize("solve", ['["velocity"]', '["velocity", "velocity"]'])
def test_an_acceleration_answer_of_a_velocity_only_scene_is_refused(scene, solve):
    text = FOUR_BAR.replace("[ground]", f"solve = {solve}\n[ground]") + (
        '[[answers]]\nquantity = "a(C)"\nunit = "m/s^2"\nexact = 1.0\n')
    refused(*run("solve", scene(text)), "acceleration polygon")


@pytest.mark.parametrize("spec", ['along = "1000000000 mm"', "fraction = -1e6",
                                  'fraction = 0.5\nleft = "5 km"', 'distance = "1000 km"\nangle = "10 deg"'])
def test_a_point_far_beyond_the_mechanism_is_refused(scene, spec):
    path = scene(FOUR_BAR + f'[points.E]\non = "BC"\n{spec}\n')
    refused(*run("solve", path), "[points.E]", "too far")


def test_a_point_within_the_bound_and_a_link_too_short_to_draw_are_drawn(scene, tmp_path):
    """A crank of 0.5 µm beside a 0.45 m frame is a valid scene: drawn without a division by
    zero (a link shorter than the drawing's resolution has no continuation)."""
    text = (FOUR_BAR.replace('AB = "100 mm"', 'AB = "0.0005 mm"')
            .replace('BC = "400 mm"', 'BC = "450 mm"').replace('CD = "350 mm"', 'CD = "100 mm"')
            + '[points.E]\non = "AB"\nfraction = 2\n')
    code, out, err = run("draw", scene(text), "-o", tmp_path / "d", "--no-stages")
    assert code == 0 and err == "" and (tmp_path / "d" / "space.svg").exists()


def test_sweep_formats_are_checked_before_work(scene):
    for bad in ("bogus", "png,xyz", ",,"):
        refused(*run("sweep", scene(), "--formats", bad), "--formats", exit_code=2)


def test_vary_counts_are_bounded_before_anything_is_allocated(scene):
    path = scene()
    refused(*run("sweep", path, "--vary", "AB=40..60mm:1000000000000"), "at most 1,000,000")
    refused(*run("sweep", path, "--vary", "AB=40..60mm:" + "9" * 5000), "at most 1,000,000")
    refused(*run("sweep", path, "--vary", "AB=40..60mm:10000", "--vary", "BC=390..400mm:10000",
                 "--vary", "CD=340..350mm:10000", "--grid"), "1,000,000,000,000 combinations")
    line = refused(*run("sweep", path, "--vary", "AB=" + "x," * 3000 + "2 mm"))
    assert len(line) < 700          # the --vary text is cut where the message quotes it


def test_a_long_title_is_cut_for_the_plots():
    from polygons.cli.sweep import PLOT_TITLE, plot_title
    t = plot_title("x" * 10_000)
    assert len(t) == PLOT_TITLE and t.endswith("…")
    assert plot_title("a\n" * 500).count("\n") == 0
    assert plot_title("short title") == "short title"


def test_a_sweep_plot_of_a_10000_character_title_is_written(scene, tmp_path):
    path = scene(FOUR_BAR.replace('title = "four-bar"', f'title = "{"x" * 10_000}"'))
    code, out, err = run("sweep", path, "--steps", "24", "--formats", "svg", "-o", tmp_path)
    assert code == 0 and err == "" and (tmp_path / "s-sweep.svg").exists()


def test_diff_percent_is_undefined_when_ours_is_a_zero():
    from polygons.steps import percent_diff
    assert percent_diff(5.0, 3.9e-30) is None          # a computed zero
    assert percent_diff(5.0, 1e-320) is None           # a subnormal
    assert percent_diff(5.0, 0.0) is None
    assert percent_diff(1e300, 1e-300) is None         # the ratio would overflow
    assert percent_diff(3.0, 2.5) == pytest.approx(20.0)
    assert percent_diff(-3.0, 2.5) == pytest.approx(-220.0)


def test_the_table_says_why_a_percentage_is_missing(scene):
    text = FOUR_BAR + ('[[answers]]\nquantity = "v(A)"\nunit = "m/s"\ntutorial = 5.0\n'
                       '[[answers]]\nquantity = "omega(CD)"\nunit = "rad/s"\ntutorial = 3.0\n')
    code, out, err = run("solve", scene(text), "--no-steps")
    assert code == 0 and err == ""
    rows = {line.split()[0]: line for line in out.splitlines() if line[:2] in ("v(", "om")}
    assert "diff % undefined (ours ≈ 0)" in rows["v(A)"]
    pct = (3.0 - OMEGA_CD) / OMEGA_CD * 100
    assert f"{pct:.2f}" in rows["omega(CD)"] and "undefined" not in rows["omega(CD)"]


@pytest.mark.parametrize("mass", ['"1e-320 kg"', '"5e-324 kg"', '"1e-10 kg"'])
def test_a_mass_too_small_to_compute_with_is_refused(scene, mass):
    refused(*run("forces", scene(SPRING.replace('"2 kg"', mass) + 'between = ["B", "C"]\n'
                                 'on = ["AB", "CD"]\n')), "[masses.BC.mass]", "too small")


# ---------------------------------------------------------------- 2. bounds, file kinds
def test_a_fifo_a_device_and_a_directory_are_refused_without_blocking(tmp_path):
    fifo = tmp_path / "f.toml"
    os.mkfifo(fifo)
    targets = [(fifo, "FIFO"), (tmp_path, "directory")]
    targets += [(Path(d), "device") for d in ("/dev/null", "/dev/zero") if Path(d).exists()]
    with deadline(20):
        for target, words in targets:
            for command in ("solve", "forces", "centres", "sweep"):
                refused(*run(command, target), str(target), words, "not a scene file")


def test_a_fifo_inside_a_gallery_folder_does_not_block(tmp_path):
    folder = tmp_path / "cases"
    folder.mkdir()
    os.mkfifo(folder / "pipe.toml")
    (folder / "dir.toml").mkdir()
    with deadline(20):
        code, out, err = run("gallery", folder, "-o", tmp_path / "out")
    lines = err.splitlines()
    assert code == 1 and len(lines) == 2 and all("not a scene file" in x for x in lines)
    assert stat.S_ISFIFO(os.stat(folder / "pipe.toml").st_mode)      # left as it was


@pytest.mark.parametrize("steps", ["1000000000000", "10000001", "1", "-5"])
def test_sweep_steps_on_the_command_line_are_capped_like_the_scene(scene, steps):
    refused(*run("sweep", scene(), "--steps", steps), "[--steps]", "10,000,000")


@pytest.mark.parametrize("table, words", [
    ('[dynamics]\nmode = "release"\nsteps = 100000000\n', "4 to 10,000"),
    ('[dynamics]\nmode = "release"\nsteps = 2.5\n', "4 to 10,000"),
    ('[dynamics]\nmode = "release"\nafter = [' + '"1 deg", ' * 21 + "]\n", "at most 20")])
def test_dynamics_counts_are_bounded(scene, table, words):
    refused(*run("forces", scene(SPRING + 'between = ["B", "C"]\non = ["AB", "CD"]\n'
                                 + table)), "[dynamics.", words)


# ---------------------------------------------------------------- 3. data loss, injection
OUTPUT_COMMANDS = [("solve", "-o"), ("solve", "--svg"), ("check", "-o"), ("forces", "-o"),
                   ("handout", "-o"), ("draw", "-o"), ("sweep", "-o"), ("gallery", "-o"),
                   ("centres", "-o")]


@pytest.mark.parametrize("command, flag", OUTPUT_COMMANDS)
@pytest.mark.parametrize("how", ["same", "symlink", "hardlink", "dotted"])
def test_an_output_that_is_the_input_file_is_refused(scene, tmp_path, command, flag, how):
    path = scene(SPRING + 'between = ["B", "C"]\non = ["AB", "CD"]\n')
    before = path.read_bytes()
    target = {"same": path, "dotted": tmp_path / "." / path.name}.get(how)
    if how == "symlink":
        target = tmp_path / "link.toml"
        target.symlink_to(path)
    elif how == "hardlink":
        target = tmp_path / "hard.toml"
        os.link(path, target)
    extra = ["--measured", "omega(CD)=2.9rad/s"] if command == "check" else []
    refused(*run(command, path, flag, target, *extra), "refusing to overwrite")
    assert path.read_bytes() == before


def test_an_input_named_like_an_output_in_the_output_folder_is_refused(tmp_path):
    path = tmp_path / "space.svg"
    path.write_text(FOUR_BAR, encoding="utf-8")
    refused(*run("draw", path, "-o", tmp_path), "refusing to risk overwriting")
    assert path.read_text(encoding="utf-8") == FOUR_BAR


def test_gallery_links_and_ids_of_hostile_case_names_are_safe(tmp_path):
    from polygons.cli.gallery import _anchor, _href
    assert _href("javascript:alert(1).html") == "./javascript%3Aalert%281%29.html"
    assert _href('x" onmouseover="a.html') == "./x%22%20onmouseover%3D%22a.html"
    for name in ("javascript:alert(1)", 'x" onmouseover="alert(2)', "a b", "ok-name_1"):
        token = _anchor(name)
        assert all(c.isalnum() or c in "-_" for c in token)
    assert _anchor("ok-name_1") == "ok-name_1" and _anchor("a b") != _anchor("a-b")
    folder = tmp_path / "cases"
    folder.mkdir()
    (folder / 'javascript:alert(1)" onmouseover="alert(2).toml').write_text(FOUR_BAR,
                                                                             encoding="utf-8")
    code, out, err = run("gallery", folder, "-o", tmp_path / "out")
    assert code == 0 and err == ""
    index = (tmp_path / "out" / "index.html").read_text(encoding="utf-8")
    assert 'href="javascript' not in index and 'onmouseover="' not in index
    assert 'href="./javascript%3Aalert%281%29%22%20onmouseover' in index


def test_the_interactive_page_fills_its_placeholders_once():
    import re

    from diagrams.page import page
    text = FOUR_BAR.replace('title = "four-bar"', 'title = "{CSS} {TITLE} <b>"')
    html = page(polygons.solve(text).solution, n=8)
    title = re.search(r"<title>(.*?)</title>", html, re.S).group(1)
    assert title == "{CSS} {TITLE} &lt;b&gt; — interactive construction"
    assert html.count("<title>") == html.count("</title>")


def test_labels_are_matched_to_the_end_of_the_text(scene):
    from polygons.reader import LABEL
    from polygons.topology import _LINE
    assert LABEL.match("Z") and not LABEL.match("Z\n") and not _LINE.match("AB\n")
    path = scene(FOUR_BAR.replace('D = ["450 mm"', '"D\\n" = ["450 mm"'))
    refused(*run("solve", path), "is not a point label")


def test_a_link_between_two_fixed_points_is_called_a_frame_link(scene):
    path = scene(FOUR_BAR.replace('CD = "350 mm"', 'CD = "350 mm"\nAD = "450 mm"'))
    line = refused(*run("solve", path), "[links.AD]", "part of the frame")
    assert "locked structure" not in line


# ---------------------------------------------------------------- 4. the Python API
@pytest.fixture(scope="module")
def four_bar():
    return polygons.load(FOUR_BAR)


@pytest.mark.parametrize("kwargs, words", [
    ({"omega": [12.0, 1e300]}, "row 1"), ({"omega": [np.inf]}, "outside the domain"),
    ({"AB": [np.nan]}, "outside the domain"), ({"theta": [1e9]}, "outside the domain"),
    ({"omega": ["fast"]}, "expected numbers"), ({"omega": [[1.0, 2.0]]}, "1-D"),
    ({"omega": [1j]}, "expected numbers"), ({"omega": None}, "outside the domain"),
    ({"XY": [1.0]}, "cannot vary"), ({"engine": "x"}, "engine"),
    ({"omega": np.zeros(1_000_001)}, "at most 1,000,000")])
def test_solve_many_applies_the_scene_limits(four_bar, kwargs, words):
    with pytest.raises(PolygonsError) as e:
        polygons.solve_many(four_bar, **kwargs)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_solve_many_refuses_a_grid_too_large_before_allocating(four_bar):
    with pytest.raises(PolygonsError, match="combinations"):
        polygons.solve_many(four_bar, AB=np.full(10_000, 0.1), BC=np.full(10_000, 0.4),
                            grid=True)


@pytest.mark.parametrize("args", [("cases/s001-we4.toml",), (None,), (42,)])
def test_solve_many_wants_a_scene(args):
    with pytest.raises(PolygonsError, match="expected a Scene"):
        polygons.solve_many(*args)


def test_a_negative_omega_in_the_api_is_the_signed_rate_ccw_positive(four_bar):
    """Documented (polygons/batch.py): ω is signed, CCW positive — -12 is 12 rad/s CW, and
    every rate flips sign; never made positive."""
    b = polygons.solve_many(four_bar, omega=[12.0, -12.0])
    assert b.ok.all()
    assert b.omega("CD")[0] == pytest.approx(OMEGA_CD, rel=1e-12)
    assert b.omega("CD")[1] == pytest.approx(-OMEGA_CD, rel=1e-12)


@pytest.mark.parametrize("omega", ['"-12 rad/s"', '"-12 rad/s CCW"'])
def test_a_negative_omega_magnitude_in_a_scene_is_refused(scene, omega):
    text = FOUR_BAR.replace('omega = "12 rad/s"', f"omega = {omega}")
    if "CCW" in omega:
        text = text.replace('sense = "CCW"\n', "")
    refused(*run("solve", scene(text)), "[driver.omega]", "negative")


@pytest.mark.parametrize("kwargs, words", [
    ({"steps": 2.5}, "whole number"), ({"steps": True}, "whole number"),
    ({"steps": 10 ** 12}, "10,000,000"), ({"steps": 1}, "whole number"),
    ({"inputs": [math.nan]}, "finite"), ({"inputs": "abc"}, "sequence"),
    ({"inputs": [[1, "x"]]}, "numbers"), ({"chunk": 0}, "chunk")])
def test_sweep_applies_the_scene_limits(four_bar, kwargs, words):
    from polygons.sweep import sweep
    with pytest.raises(PolygonsError) as e:
        sweep(four_bar, **kwargs)
    assert words in str(e.value)


def test_the_api_load_refuses_wrong_types_with_its_own_errors(tmp_path):
    for bad in (42, None, b"bytes", ["list"]):
        with pytest.raises(SceneError):
            polygons.load(bad)
    with pytest.raises(SceneError, match="NUL"):
        polygons.load_scene("a\x00b.toml")
    with pytest.raises(SceneError, match="directory"):
        polygons.solve(tmp_path)


# ---------------------------------------------------------------- found while fuzzing
def test_a_sweep_of_a_large_mechanism_is_plotted_with_a_short_key(tmp_path):
    """A chain of 21 links: 20 ω curves by default; the key names the first 8 (a key of
    dozens could not fit: matplotlib's layout warning was an internal error)."""
    from chains import chain_scene
    path = tmp_path / "chain.toml"
    path.write_text(chain_scene(10), encoding="utf-8")
    code, out, err = run("sweep", path, "--steps", "24", "--formats", "svg", "-o", tmp_path)
    assert code == 0 and err == ""
    svg = (tmp_path / "chain-sweep.svg").read_text(encoding="utf-8")
    assert svg.count("key: the first 8 of 20 curves") == 2      # the ω and α panels


def test_repeated_sweep_labels_are_taken_once(scene, tmp_path):
    code, out, err = run("sweep", scene(), "--points", "C,C,C", "--links", "BC,BC",
                         "--steps", "4", "--no-plot", "-o", tmp_path)
    assert code == 0 and err == ""
    header = (tmp_path / "s-sweep.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    assert len(header) == len(set(header)) and header.count("C.x [m]") == 1


# ---------------------------------------------------------------- every count has a bound
#: every whole-number option of the command line, with a value beyond its documented bound
#: (README, "Counts"): a new one must be added here, with its bound checked before work
BOUNDED_COUNTS = {("sweep", "--steps"): ["--steps", "10000001"],
                  ("exam", "--variants"): ["--variants", "1000000000000", "--out", "{tmp}"],
                  ("exam", "--seed"): ["--variants", "1", "--seed", "-1", "--out", "{tmp}"],
                  ("forces", "--cycle"): ["--cycle", "100000", "-o", "{tmp}"]}


def test_every_whole_number_option_is_bounded_before_work(scene, tmp_path):
    from polygons.cli import build_parser
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    found = set()
    for name, p in sub.choices.items():
        for action in p._actions:
            if action.type is int:
                found.add((name, action.option_strings[-1] if action.option_strings
                           else action.dest))
    assert found == set(BOUNDED_COUNTS), "an unbounded whole-number option: " + str(
        found ^ set(BOUNDED_COUNTS))
    for (name, flag), extra in BOUNDED_COUNTS.items():
        code, out, err = run(name, scene(), *(a.format(tmp=tmp_path / "o") for a in extra))
        assert code in (1, 2) and err.count("\n") == 1 and "polygons: error: " in err, err
        assert not (tmp_path / "o").exists()        # refused before any work
