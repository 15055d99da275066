"""The Python API: polygons.load / polygons.solve / Result, the README's example, notebooks."""
import json
import re
import subprocess
import sys
import xml.dom.minidom

import pytest

import polygons
from conftest import ROOT, cli
from polygons.errors import SceneError, SceneSyntaxError
from polygons.evaluate import solve as core_solve
from polygons.report import table, to_json
from polygons.scene import Scene, load_scene

CASE = ROOT / "cases" / "s001-we4.toml"


def readme_python_blocks():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## Python API", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", section, re.S)


def test_readme_has_a_python_example():
    assert readme_python_blocks()


@pytest.mark.parametrize("i", range(len(readme_python_blocks())))
def test_readme_python_blocks_run(i, monkeypatch):
    """Each ```python block of the README's API section runs as written, from the repo root."""
    monkeypatch.chdir(ROOT)
    code = readme_python_blocks()[i]
    exec(compile(code, f"README.md python block {i}", "exec"), {"__name__": "__readme__"})


def test_load_accepts_a_path_text_or_scene():
    by_path = polygons.load(str(CASE))
    assert isinstance(by_path, Scene)
    by_text = polygons.load(CASE.read_text(encoding="utf-8"))
    assert by_text.file == "<text>" and by_text.links == by_path.links
    assert polygons.load(by_path) is by_path
    assert polygons.load(CASE).title == by_path.title


def test_load_errors_are_scene_errors():
    with pytest.raises(SceneSyntaxError, match=r"^<text>: not valid TOML"):
        polygons.load("title = \n[[[")
    with pytest.raises(SceneError, match="no such scene file"):
        polygons.load("cases/none.toml")


def test_result_reads_through_to_the_solution():
    res = polygons.solve(CASE)
    core = core_solve(load_scene(CASE))
    assert res.links["BC"].omega == core.links["BC"].omega
    assert res.points["C"].velocity == core.points["C"].velocity
    assert res.steps == core.steps and res.slides == core.slides
    assert res.solution.scene.title == res.scene.title
    # the existing call style keeps working (a Scene in, Solution attributes out)
    assert polygons.solve(load_scene(CASE)).links["AB"].omega == core.links["AB"].omega
    with pytest.raises(AttributeError):
        res.no_such_attribute
    with pytest.raises(Exception):
        res.solution = None                      # frozen


def test_result_reports_are_the_commands_reports():
    res = polygons.solve(CASE)
    core = core_solve(load_scene(CASE))
    assert json.loads(res.to_json()) == json.loads(json.dumps(to_json(core)))
    assert res.table() == table(core)
    out = cli("solve", CASE, "--json", cwd=ROOT)
    assert json.loads(out.stdout)["links"] == json.loads(res.to_json())["links"]


@pytest.mark.parametrize("diagram", ["space", "velocity", "acceleration", "centres"])
def test_svg_of_each_diagram(diagram):
    svg = polygons.solve(CASE).svg(diagram)
    doc = xml.dom.minidom.parseString(svg.encode())
    assert doc.documentElement.tagName == "svg"
    assert svg == polygons.solve(CASE).svg(diagram)          # deterministic


def test_svg_refuses_unknown_or_unsolved_diagrams(write_scene):
    with pytest.raises(SceneError, match="unknown diagram"):
        polygons.solve(CASE).svg("force")
    text = 'solve = ["velocity"]\n' + CASE.read_text(encoding="utf-8")
    res = polygons.solve(write_scene(text))
    with pytest.raises(SceneError, match="acceleration diagram was not solved"):
        res.svg("acceleration")


def test_notebook_display_shows_the_diagrams():
    """What a Jupyter cell shows: _repr_html_ with the space, velocity and acceleration SVGs
    inline (each one parses as SVG), and _repr_svg_ with the space diagram."""
    res = polygons.solve(CASE)
    page = res._repr_html_()
    svgs = re.findall(r"<svg.*?</svg>", page, re.S)
    assert len(svgs) == 3
    for s, diagram in zip(svgs, ("space", "velocity", "acceleration")):
        assert s == res.svg(diagram).split("?>", 1)[1].lstrip().rstrip("\n")
        xml.dom.minidom.parseString(s.encode())
    assert "<?xml" not in page
    assert res.scene.title.split(":")[0] in page and "BC" in page
    assert res._repr_svg_().startswith("<svg")


def test_import_polygons_stays_lazy():
    code = ("import sys, polygons; assert 'numpy' not in sys.modules; "
            "polygons.load_scene; polygons.load; assert 'numpy' not in sys.modules; "
            "polygons.solve; print('ok')")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT)
    assert out.stdout.strip() == "ok", out.stderr


def test_result_rubbing_and_least_velocity():
    res = polygons.solve(ROOT / "cases" / "khurmi-ex7.2.toml")
    assert {r.pin for r in res.rubbing()} == {"O", "B", "P"}
    lv = res.least_velocity("BP")
    assert lv.on_link and 0 < lv.fraction < 1
    assert "rubbing velocities" in res.table() and '"pins"' in res.to_json()
    assert res.centres().centre(1, 3).how == "Kennedy: 13 on 12–23 and 14–43"
