"""Handouts, worksheets, ``polygons check`` and ``polygons gallery`` (no browser needed)."""
import html as htmllib
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import CASES, case_files, cli
from polygons.narrate import substitute
from polygons.cli.check import grade, offered, parse_measured, resolve
from polygons.evaluate import solve
from polygons.quantities import quantity
from polygons.report import to_unit
from polygons.scene import load_scene

from diagrams.handout import (figures, formula_with_numbers, handout, redact_answers,
                              textbook_name, worksheet_questions)

def run(*args, cwd=None):
    """``polygons ARGS`` in this process (conftest.cli: the entry point function)."""
    return cli(*args, cwd=cwd)


def text_of(page: str) -> str:
    """What a reader sees: tags and the inline SVGs' markup removed, entities decoded."""
    page = re.sub(r"<style>.*?</style>", " ", page, flags=re.S)
    page = re.sub(r'<span class="subsup">(.*?)</span>', r"\1", page)
    page = re.sub(r"</?(sub|sup|tspan)\b[^>]*>", "", page)
    page = re.sub(r"<[^>]+>", " ", page)
    return re.sub(r"\s+", " ", htmllib.unescape(page))


_CACHE = {}
_FIGURES = {}


def pages(path):
    """(solution, key, worksheet) of a case, made once per test process."""
    if path not in _CACHE:
        sol = solve(load_scene(str(path)))
        figs = _FIGURES[id(sol)] = figures(sol)
        _CACHE[path] = (sol, handout(sol, figs=figs), handout(sol, worksheet=True, figs=figs))
    return _CACHE[path]


def figures_of(sol):
    """The figures the pages of ``sol`` were made from (a solution from :func:`pages`)."""
    return _FIGURES[id(sol)]


IDS = [p.stem for p in case_files()]


# ---------------------------------------------------------------- the answer key
@pytest.mark.parametrize("path", case_files(), ids=IDS)
def test_handout_narrates_every_step_with_its_figure_and_numbers(path):
    sol, key, _ = pages(path)
    text = text_of(key)
    assert sol.scene.title in htmllib.unescape(key)
    from diagrams.figures import cells
    for diagram in sol.scene.solve:
        groups = cells(sol, diagram)
        for i, cell in enumerate(groups):
            first = cell[0].number
            li = re.search(rf'<li class="step" id="{diagram}-step-{first}".*?</li>', key, re.S)
            assert li, (diagram, first)
            body = li.group(0)
            for step in cell:
                assert f'<span class="num">{step.number}.</span>' in body
                if substitute(step, sol.scene):
                    assert 'class="formula answer"' in body
            # one figure a group of steps ending in a drawn point; the group completing the
            # diagram points to the finished diagram instead (printed full size after it)
            drawn = cell[-1].kind in ("vector", "image", "intersection")
            final = drawn and not any(c[-1].kind in ("vector", "image", "intersection")
                                      for c in groups[i + 1:])
            assert ("<svg" in body) == (drawn and not final), (diagram, first)
            if final:
                assert "finished diagram is printed full size" in body
    # every finished diagram and the space diagram, inline
    for name in ("space", *sol.scene.solve):
        assert f'id="plate-{name}"' in key or f'id="{name}"' in key
    assert "Results" in text and "Comparison with the tutorial" in text
    ids = re.findall(r'\bid="([^"]+)"', key)
    assert len(ids) == len(set(ids)), "duplicate ids between the inline figures"
    # self-contained: nothing fetched, nothing run
    assert "<script" not in key and "<link" not in key and " src=" not in key
    assert not re.search(r"""(href|src)=["']https?:""", key)
    assert not re.search(r"url\((?!#)", key)


def test_formula_with_numbers_reads_like_the_tutorial():
    sol, key, _ = pages(CASES / "s001-we2.toml")
    first = next(s for s in sol.steps if s.diagram == "velocity")
    assert formula_with_numbers(first, sol.scene) == "(v_A)_O = ω × OA = 209.44 × 0.05 = 10.472 m/s"
    # printed with the link named: no bare ω where ω_OA is meant
    assert "(vA)O = ωOA × OA = 209.44 × 0.05 = 10.472 m/s" in text_of(key)
    sol, key, _ = pages(CASES / "s001-we6.toml")
    text = text_of(key)
    # centripetal with the square of a CW (negative) ω written as a person writes it
    assert "(aB)An = ωAB² × AB = 480² × 0.08 = 18432 m/s²" in text
    assert not re.search(r"(?<![\w])ω² ×", text)
    assert "−480²" not in text and "-480²" not in text
    assert "ωBC = bc / BC = 31 / 0.136 = 227.94 rad/s CCW" in text
    assert "e+05" not in text


def test_acceleration_components_are_explained_where_they_occur():
    _, key, ws = pages(CASES / "s003-fig7.toml")
    for page in (key, ws):
        for what in ("centripetal", "tangential", "coriolis"):
            assert page.count(f'data-explains="{what}"') == 1, what
    # the Coriolis box comes just before the group of steps that draws 2ωv
    from diagrams.figures import cells
    sol = pages(CASES / "s003-fig7.toml")[0]
    groups = cells(sol, "acceleration")
    at = next(i for i, c in enumerate(groups) if any(s.number == 4 for s in c))
    box = key.index('data-explains="coriolis"')
    assert key.index(f'id="acceleration-step-{groups[at][0].number}"') > box
    assert at == 0 or box > key.index(f'id="acceleration-step-{groups[at - 1][0].number}"')
    _, key, _ = pages(CASES / "s001-we6.toml")
    assert 'data-explains="coriolis"' not in key


def test_comparison_gives_percent_differences_and_names_the_slips():
    sol, key, _ = pages(CASES / "s001-we8.toml")
    text = text_of(key)
    table = re.search(r'<table class="answer wide" id="comparison-table">.*?</table>', key,
                      re.S).group(0)
    slips = [a for a in sol.scene.answers if a.slip and a.tutorial is not None]
    assert slips, "WE8 has slips in the reference"
    assert table.count("slip in the tutorial") == len(slips)
    assert "Slips in the printed working" in text
    first = " ".join(sol.scene.source["slips"].split()[:6])
    assert first in text
    assert re.search(r"[−+]\d+\.\d\d %", text_of(table))


# ---------------------------------------------------------------- the worksheet
UNIT_RE = {"velocity": r"\s*(m/s|mm/s)(?![²^])", "acceleration": r"\s*(m/s|mm/s)(²|\^2)",
           "angular_velocity": r"\s*rad/s(?![²^])", "angular_acceleration": r"\s*rad/s(²|\^2)",
           "fraction": r""}     # a ratio (v(C) / v(B)): the bare number


def _answer_strings(sol):
    """Every answer as it could be printed, (number, unit pattern): the tutorial's and ours."""
    from polygons.quantities import dimension_of_quantity
    out = set()
    drv = sol.scene.driver
    given = {f"omega({getattr(drv, 'link', '')})", f"alpha({getattr(drv, 'link', '')})"}
    for a in sol.scene.answers:
        fn = a.quantity.split("(")[0]
        if fn not in ("v", "a", "an", "at", "omega", "alpha", "cor", "vs", "as"):
            continue
        if a.quantity in given:
            continue
        values = [abs(to_unit(quantity(sol, a.quantity), a.unit))]
        if a.tutorial is not None:
            values.append(abs(a.tutorial))
        for v in values:
            if v == 0:
                continue
            unit = UNIT_RE[dimension_of_quantity(a.quantity)]
            for text in {f"{v:.3g}", f"{v:.4g}", f"{v:.5g}", f"{v:g}"}:
                if len(text.replace(".", "")) >= 2:
                    out.add((text, unit))
    return out


@pytest.mark.parametrize("path", case_files(), ids=IDS)
def test_worksheet_contains_no_answers(path):
    sol, key, ws = pages(path)
    # the empty drawing areas' scale bars are multiples of the scale, not answers
    text = text_of(re.sub(r'<svg[^>]*class="drawing-area".*?</svg>', " ", ws, flags=re.S))
    # a stated drawing scale ('Scale 1 cm = 100 m/s²') is the sheet's, not an answer
    text = re.sub(r"1 cm = [-+0-9.e]+ \S+", " ", text)
    # no results, no comparison, no stage figures, no substituted numbers
    assert 'class="answer' not in ws and "formula answer" not in ws
    assert "Comparison with the tutorial" not in text and "Results" not in text
    assert not re.search(r'id="(velocity|acceleration)-\d+-', ws)
    assert not re.search(r'id="plate-(velocity|acceleration)"', ws)
    for s, units in _answer_strings(sol):
        hit = re.search(r"(?<![\d.])" + re.escape(s) + units, text)
        assert not hit, f"answer {s} shows in the worksheet: ...{text[max(0, hit.start() - 60):hit.end() + 20]}..."
    # the drawing areas, at the key's scales
    for diagram in sol.scene.solve:
        assert f'id="area-{diagram}"' in ws
        lay = figures_of(sol).drawing[diagram].meta["layout"]
        area = re.search(rf'<svg[^>]*id="area-{diagram}".*?</svg>', ws, re.S).group(0)
        # the key's scale, or (a drawing wider than a portrait A4 page) the next round
        # scale that fits, with the note saying the key's needs a larger sheet
        assert (f"Scale {htmllib.escape(lay.scale.statement)}" in area
                or f"drawn at {htmllib.escape(lay.scale.statement)}, which needs a sheet "
                   f"larger than A4" in ws)
    # blanks to fill in, gradeable by polygons check
    for q in worksheet_questions(sol):
        assert f"<code>{textbook_name(q)}</code>" in ws
        assert resolve(sol, textbook_name(q)) == q.replace(" ", "")


def test_worksheet_statement_keeps_the_data_but_not_the_printed_answers():
    s = ("Find the velocity of the piston.\n1. The crank rotates at 3000 rev/min.\n"
         "(Answer 34 m/s and 21.25 rad/s)\n- points A, B and D (1.5 m/s, 2.6 m/s and 2.7 m/s)\n"
         "(Ans. 76 rad/s clockwise.)  (alpha is 21.052 deg at this position)")
    out = redact_answers(s)
    for gone in ("34 m/s", "21.25", "1.5 m/s", "2.7 m/s", "76 rad/s"):
        assert gone not in out
    assert "3000 rev/min" in out and "(alpha is 21.052 deg at this position)" in out
    assert out.count("(answer on the key)") == 3


def test_worksheet_drawing_area_is_true_size():
    sol, _, ws = pages(CASES / "s001-we6.toml")
    area = re.search(r'<svg[^>]*id="area-velocity"[^>]*>', ws).group(0)
    vb = [float(v) for v in re.search(r'viewBox="([^"]+)"', area).group(1).split()]
    width = float(re.search(r'width="([\d.]+)mm"', area).group(1))
    assert width == pytest.approx(vb[2])          # 1 user unit = 1 mm on paper
    # grid lines every 5 mm, the scale bar in whole centimetres
    assert "M5 0V" in ws and "M10 0V" in ws


# ---------------------------------------------------------------- polygons check
def test_check_accepts_good_measurements():
    out = run("check", CASES / "s001-we6.toml", "--measured", "v_C=15.05", "v_CB=30.8",
              "omega_BC=228CCW", "alpha_CD=155500", "a_C=25.1e3", "an_CB=7066")
    assert out.returncode == 0, out.stdout + out.stderr
    assert out.stdout.count("ok ") == 6 and "OFF" not in out.stdout
    assert "6 of 6 within tolerance" in out.stdout


def test_check_flags_bad_measurements_with_the_step_to_recheck():
    out = run("check", CASES / "s001-we6.toml", "--measured", "v_C=7.1",
              "alpha_CD=150000", "v_CB=31.2", "omega_CD=93.75CCW")
    assert out.returncode == 3, out.stderr
    lines = out.stdout.splitlines()
    vc = next(i for i, l in enumerate(lines) if "v_C " in l)
    assert lines[vc].lstrip().startswith("OFF") and "-52.7 %" in lines[vc]
    assert "hint: velocity step 4 (stage 4)" in lines[vc + 1]
    assert "The two lines meet at c" in lines[vc + 1]
    al = next(i for i, l in enumerate(lines) if "alpha_CD" in l)
    assert lines[al].lstrip().startswith("OFF") and "-3.9 %" in lines[al]
    assert "hint: acceleration step 8" in lines[al + 1]
    assert any("matches the tutorial's printed 150000" in l for l in lines[al:al + 4])
    assert next(l for l in lines if "v_CB" in l).lstrip().startswith("ok")
    om = next(i for i, l in enumerate(lines) if "omega_CD" in l)
    assert lines[om].lstrip().startswith("OFF") and "sense is wrong" in lines[om + 1]
    assert "1 of 4 within tolerance; off: v_C, alpha_CD, omega_CD" in out.stdout


def test_check_grades_coriolis_and_sliding_on_the_quick_return():
    sol = solve(load_scene(str(CASES / "s003-fig7.toml")))
    ms = parse_measured(sol, ["cor_P2=1.95", "v_P2P4=0.81", "omega_O4P4=1.2",
                              "alpha_O4P4=4.11 rad/s^2", "vs_P2=0.806", "as_P2=-2.69"])
    g = {x.name: x for x in grade(sol, ms, tolerance=0.01)}
    assert g["cor_P2"].ok and g["v_P2P4"].ok and g["vs_P2"].ok and g["as_P2"].ok
    assert g["alpha_O4P4"].ok
    assert not g["omega_O4P4"].ok                      # -1.2 % with a 1 % tolerance
    assert g["omega_O4P4"].step.diagram == "velocity" and g["omega_O4P4"].step.op == "omega"
    assert g["cor_P2"].step.op == "coriolis_offset_line"


def test_check_tolerance_is_at_least_half_a_millimetre_at_the_scale():
    sol = solve(load_scene(str(CASES / "s001-we6.toml")))
    from polygons.cli.check import diagram_scales
    sc = diagram_scales(sol)
    [g] = grade(sol, parse_measured(sol, ["v_B=38.4"]), 0.0001, sc)
    assert g.tolerance == pytest.approx(0.5 / sc["velocity"].mm_per_si)


def test_check_uses_the_emulated_tolerance_where_there_is_one():
    sol = solve(load_scene(str(CASES / "s001-we6.toml")))
    ms = parse_measured(sol, ["v_C=15.6", "v_CB=31.7"])       # +4.0 %, +2.3 %
    g = {x.name: x for x in grade(sol, ms, emulated={"v(C)": 0.05})}
    assert g["v_C"].ok and g["v_C"].source == "emulated" and g["v_C"].tolerance_pct == 5.0
    assert not g["v_CB"].ok and g["v_CB"].source == "stated"  # the case's 2 %
    g = {x.name: x for x in grade(sol, ms, tolerance=0.05)}
    assert g["v_CB"].ok and g["v_CB"].source == "given"


def test_check_uses_the_drawing_board_emulation():
    from polygons.cli.check import emulated_tolerances
    sol = solve(load_scene(str(CASES / "s001-we6.toml")))
    tol = emulated_tolerances(sol, trials=100)
    assert "v(C)" in tol and "alpha(CD)" in tol
    assert all(0 < t < 0.5 for t in tol.values())
    assert emulated_tolerances(sol, trials=100) == tol          # fixed seed


def test_check_unknown_name_is_one_line_listing_the_names():
    out = run("check", CASES / "s001-we6.toml", "--measured", "v_Q=3")
    assert out.returncode == 1
    assert out.stdout == ""
    err = out.stderr.strip().splitlines()
    assert len(err) == 1
    assert err[0].startswith("polygons: error: ") and "'v_Q'" in err[0]
    assert "v_C" in err[0] and "omega_BC" in err[0] and "alpha_CD" in err[0]
    bad = run("check", CASES / "s001-we6.toml", "--measured", "v_C=fast")
    assert bad.returncode == 1 and len(bad.stderr.strip().splitlines()) == 1


def test_check_names_cover_what_the_case_offers():
    sol = solve(load_scene(str(CASES / "s001-sae4-q3.toml")))
    for name, expr in offered(sol):
        assert resolve(sol, name) == expr
    assert resolve(sol, "v_BA") == "v(B,A)" and resolve(sol, "omega_BA") == "omega(AB)"
    assert resolve(sol, "v(D)") == "v(D)"


def test_check_reading_limit_follows_the_students_scale():
    coarse = run("check", CASES / "s001-we6.toml", "--measured", "v_B=38",
                 "--scale", "velocity=10 m/s")          # 0.5 mm = 0.5 m/s at 1 cm = 10 m/s
    assert coarse.returncode == 0, coarse.stdout + coarse.stderr
    assert "0.5 mm reading" in coarse.stdout and "1 cm = 10 m/s" in coarse.stdout
    fine = run("check", CASES / "s001-we6.toml", "--measured", "v_B=38")
    assert fine.returncode == 3


def test_check_json():
    out = run("check", CASES / "s003-fig7.toml", "--measured", "cor_P2=1.96", "--json")
    data = json.loads(out.stdout)
    assert out.returncode == 0 and data["all_ok"] and data["grades"][0]["quantity"] == "cor(P2)"


# ---------------------------------------------------------------- commands
def test_handout_and_worksheet_commands(tmp_path):
    out = run("handout", CASES / "s003-fig7.toml", "-o", tmp_path / "fig7.html")
    assert out.returncode == 0, out.stderr
    page = (tmp_path / "fig7.html").read_text(encoding="utf-8")
    assert 'content="handout"' in page and "Coriolis" in page
    out = run("handout", CASES / "s003-fig7.toml", "-o", tmp_path / "ws.html", "--worksheet",
              "--scale", "velocity=0.05 m/s")
    assert out.returncode == 0, out.stderr
    ws = (tmp_path / "ws.html").read_text(encoding="utf-8")
    # a forced scale at which the diagram does not fit the page: the round scale that does,
    # stated with the one asked
    assert 'content="worksheet"' in ws and "Scale 1 cm = 0.1 m/s" in ws
    assert "rather than 1 cm = 50 mm/s" in ws


def test_gallery_links_every_case(tmp_path):
    cases = tmp_path / "cases"
    cases.mkdir()
    for name in ("s001-we4.toml", "s003-fig7.toml"):
        shutil.copy(CASES / name, cases / name)
    (cases / "broken.toml").write_text('title = "x"\n[ground]\nA = [0, 0]\n', encoding="utf-8")
    out = run("gallery", cases, "-o", tmp_path / "site")
    assert out.returncode == 1          # the broken case is reported, the others written
    assert "broken.toml" in out.stderr and len(out.stderr.strip().splitlines()) == 1
    index = (tmp_path / "site" / "index.html").read_text(encoding="utf-8")
    for stem in ("s001-we4", "s003-fig7"):
        assert f'href="./{stem}.html"' in index and f'href="./{stem}-worksheet.html"' in index
        assert (tmp_path / "site" / f"{stem}.html").stat().st_size > 10000
        assert (tmp_path / "site" / f"{stem}-worksheet.html").exists()
    assert "could not be solved" in index
    # one card per case file, each once, each with a thumbnail and no empty field
    cards = re.findall(r'<article class="card[^"]*" id="case-([^"]+)">(.*?)</article>', index,
                       re.S)
    assert sorted(c for c, _ in cards) == ["broken", "s001-we4", "s003-fig7"]
    for stem, body in cards:
        if stem == "broken":
            continue
        assert body.count("<svg") == 1 and 'class="thumb"' in body
        for field in re.findall(r'<p class="[^"]+">(.*?)</p>', body, re.S):
            assert field.strip(), (stem, body[:200])


def test_the_key_checks_the_polygon_by_the_instant_centres():
    """The answer key has a section with the centres (Kennedy) and the velocities they give,
    for every mechanism (an offset slot too)."""
    from polygons.centres import instant_centres
    sol = solve(load_scene(CASES / "s001-we6.toml"))
    key = handout(sol, centres=True)
    assert '<section id="centres"' not in handout(sol)          # on request only
    assert '<section id="centres"' in key and "Kennedy" in key
    v_c = instant_centres(sol).velocities["C"]
    assert "= " + v_c.how.rsplit("= ", 1)[1] in key      # v_C by the centres
    other = handout(solve(load_scene(CASES / "new-offset-slot.toml")), centres=True)
    assert "Not drawn for this mechanism" not in other       # an offset slot: drawn too
    assert "Kennedy" in other.split('<section id="centres"')[1].split("</section>")[0]
    assert '<section id="centres"' not in handout(sol, worksheet=True, centres=True)


# ---------------------------------------------------------------- printed sizes
PRINTED_CASES = ["s001-we4", "s003-fig7", "new-whitworth"]


def _svgs(page: str, kind: str):
    """(opening <svg> tag, whole element) of the figures of class ``kind`` ('full': the
    finished diagrams and the space diagram, 'stage': the stage figures), in order."""
    return [(m.group(1), m.group(0)) for m in re.finditer(
        rf'<figure class="diagram {kind}[^"]*">(<svg\b[^>]*>).*?</svg>', page, re.S)]


def _attr(tag: str, name: str) -> str:
    return re.search(rf'\b{name}="([^"]*)"', tag).group(1)


def _printed_k(tag: str) -> tuple[float, float, float]:
    """(printed width mm / viewBox width, printed width mm, printed height mm) of a figure."""
    vb = [float(v) for v in re.search(r'viewBox="([^"]+)"', tag).group(1).split()]
    w = float(re.search(r'\bwidth="([\d.]+)mm"', tag).group(1))
    h = float(re.search(r'\bheight="([\d.]+)mm"', tag).group(1))
    return w / vb[2], w, h


@pytest.mark.parametrize("stem", PRINTED_CASES)
def test_finished_diagrams_print_at_their_stated_scale(stem):
    """A finished diagram prints at 100 %: 1 unit of its SVG (a millimetre of the drawing, at
    the stated scale) is 1 mm on paper, so the key can be laid over a student's drawing; it
    fits the portrait page; the 10 mm divisions of its scale bar are 10 mm."""
    from diagrams.figures import PAGE
    sol, key, _ = pages(CASES / f"{stem}.toml")
    figs = figures(sol)
    plates = _svgs(key, "full")
    names = ("space", *sol.scene.solve)
    assert len(plates) == len(names)
    for name, (tag, svg) in zip(names, plates):
        k, w, h = _printed_k(tag)
        assert k == pytest.approx(1.0, abs=1e-3), (name, k)
        assert w <= PAGE[0] + 0.1 and h <= PAGE[1], (name, w, h)
        line = re.search(r'<line\b[^>]*class="scale-bar-line"[^>]*>', svg).group(0)
        cm = (float(_attr(line, "x2")) - float(_attr(line, "x1"))) / 10.0
        assert cm == pytest.approx(round(cm), abs=1e-6) and cm >= 2     # whole centimetres
        stated = figs.drawing[name].scale_statement
        ident = "space" if name == "space" else f"plate-{name}"
        note = re.search(rf'<section[^>]*id="{ident}".*?<p class="figure-note">(.*?)</p>', key,
                         re.S).group(1)
        assert f"Full size ({htmllib.escape(stated)})" in note and "Reduced" not in note
    assert "Reduced to" not in key


@pytest.mark.parametrize("stem", PRINTED_CASES)
def test_stage_figure_labels_print_at_least_2_5_mm(stem):
    """The stage figures are printed reduced: their labels (points, lines, vectors) and the
    scale bar's numbers are set so that they print 2.5 mm high or more."""
    from diagrams.figures import PRINTED_LABEL, STAGE_WIDTH
    sol, key, _ = pages(CASES / f"{stem}.toml")
    stages = _svgs(key, "stage")
    assert stages
    for tag, svg in stages:
        k, w, _ = _printed_k(tag)
        assert w <= STAGE_WIDTH + 0.1
        sizes = [float(_attr(m.group(0), "font-size")) for m in re.finditer(r"<text\b[^>]*>", svg)
                 if _attr(m.group(0), "class").split()[0] in ("vertex", "line", "component",
                                                              "scale")]
        assert sizes
        assert min(sizes) * k >= PRINTED_LABEL - 1e-3, (tag[-60:], min(sizes) * k)


def test_a_scale_that_does_not_fit_the_page_gives_way_to_one_that_does():
    """A forced scale at which the finished diagram would not fit an A4 page: the next round
    scale that fits, stated (never a reduced print)."""
    from diagrams.scale import parse_cli
    sol = solve(load_scene(CASES / "s003-fig7.toml"))
    figs = figures(sol, parse_cli(["velocity=0.05 m/s"]))
    assert figs.rescaled["velocity"] == ("1 cm = 50 mm/s", "1 cm = 0.1 m/s")
    key = handout(sol, figs=figs)
    assert "rather than 1 cm = 50 mm/s" in key and "Reduced to" not in key


def test_stacked_sub_and_superscript_css():
    """(a_P2)ⁿ_O2: the handout's rule puts the superscript first (over the subscript) in a
    column raised to a superscript's height (the check by rendering is in test_browser)."""
    from diagrams.handout import CSS, SUBSUP_CSS
    assert CSS.index(SUBSUP_CSS) > CSS.index(".subsup{")         # overrides the shared rule
    assert ".subsup sup{order:-1}" in SUBSUP_CSS and "flex-direction:column;" in SUBSUP_CSS


# ---------------------------------------------------------------- printed (Chromium)
def _pdf_tools():
    from diagrams.browser import find
    if find() is None or not (shutil.which("pdfinfo") and shutil.which("pdftotext")):
        pytest.skip("needs headless Chromium and poppler's pdfinfo/pdftotext")


def _pdf(stem: str, tmp_path, worksheet: bool = False) -> tuple[int, str]:
    """(pages, text) of the PDF Chromium prints of a case's key or worksheet."""
    from polygons.cli.handout import write
    out = tmp_path / f"{stem}{'-ws' if worksheet else ''}.pdf"
    write(str(CASES / f"{stem}.toml"), out, worksheet=worksheet)
    info = subprocess.run(["pdfinfo", str(out)], capture_output=True, text=True).stdout
    text = subprocess.run(["pdftotext", str(out), "-"], capture_output=True, text=True).stdout
    return int(re.search(r"Pages:\s+(\d+)", info).group(1)), re.sub(r"\s+", " ", text)


#: printed page limits of the answer keys (the lecturer's review asked for WE4 ≤ 4 and none
#: over 6): WE4 and the longest construction (the triad's 26 steps) are printed by default;
#: POLYGONS_PDF_ALL=1 prints every shipped case's key (~2.5 min), each within 6 pages or its
#: own limit here.
PAGE_LIMITS = {"s001-we4": 4, "s001-we6": 5, "s003-fig7": 5}
PRINTED = (["s001-we4", "triad-eight-bar"] if not __import__("os").environ.get(
    "POLYGONS_PDF_ALL") else [p.stem for p in case_files()])


@pytest.mark.parametrize("stem", PRINTED)
def test_printed_key_page_count_and_every_step_printed(stem, tmp_path):
    """The key prints on at most its page limit, and no step's text is lost on the way
    (Chromium lays columns over a float on the same page: the steps never share one)."""
    _pdf_tools()
    n, text = _pdf(stem, tmp_path)
    assert n <= PAGE_LIMITS.get(stem, 6), f"{stem}: {n} pages"
    # every word of the page's text (figures aside) is printed as often as the page has it
    from collections import Counter
    sol = solve(load_scene(CASES / f"{stem}.toml"))
    page = re.sub(r"<svg\b.*?</svg>", " ", handout(sol), flags=re.S)
    page = re.sub(r"<footer\b.*?</footer>|<head>.*?</head>", " ", page, flags=re.S)

    def words(s):       # (a hyphen at a line's end is dropped by pdftotext: 'four-bar')
        return Counter(w for w in re.findall(r"[A-Za-z]+", s.replace("-", ""))
                       if len(w) >= 4)
    printed = words(text)
    missing = {w: c - printed[w] for w, c in words(text_of(page)).items() if printed[w] < c}
    assert not missing, f"{stem}: words not printed: {missing}"


# ---------------------------------------------------------------- compact key (page count)
def test_long_data_table_sets_two_short_data_a_row_in_order():
    """More than PAIRED_DATA data: two consecutive short ones share a row (read across, then
    down); a long datum has its row to itself; a short table keeps one datum a row."""
    from diagrams.handout import PAIRED_DATA, _data_rows
    short = [(f"link L{i}", f"{i}00 mm") for i in range(5)]
    long = ("input crank OA", "turns about O; at this instant OA is at 60° (CCW from +x)")
    rows = short[:3] + [long] + short[3:] + [("ω of the crank", "10 rad/s CCW")]
    assert len(rows) <= PAIRED_DATA
    assert _data_rows(rows) == [[r] for r in rows]
    rows = rows + [("α of the crank", "0"), ("fixed point O", "(0, 0) mm")]
    assert len(rows) > PAIRED_DATA
    got = _data_rows(rows)
    assert [r for row in got for r in row] == rows                 # nothing lost, order kept
    assert got[:3] == [[short[0], short[1]], [short[2]], [long]]
    assert all(len(row) <= 2 for row in got) and [long] in got
    sol, key, _ = pages(CASES / "triad-eight-bar.toml")
    table = re.search(r'<table class="data">.*?</table>', key, re.S).group(0)
    assert re.search(r'<tr><th scope="row">link \w+</th><td>\d+ mm</td>'
                     r'<th scope="row">link \w+</th><td>\d+ mm</td></tr>', table)
    assert '<td colspan="3">turns about O;' in table


def test_results_table_names_the_fixed_points_instead_of_rows_of_zeros():
    sol, key, _ = pages(CASES / "triad-eight-bar.toml")
    res = re.search(r'<section id="results">.*?</section>', key, re.S).group(0)
    rows = re.findall(r"<tr><td>([^<]+)</td>", re.search(
        r'id="results-points".*?</table>', res, re.S).group(0))
    assert rows == ["A", "F", "B", "C", "X", "S"]
    assert "O, Q and D are fixed: no velocity, no acceleration." in res


def test_legend_in_two_columns_below_a_drawing_too_wide_for_it_beside():
    """The triad's acceleration legend (38 lines) is split at its blank line: 'Scaled from the
    drawing' at the left, the key over 'From the construction' at the right, nothing on the
    drawing or on each other, and the plate shorter than with the legend in one column."""
    from diagrams.layout import LEGEND_SIZE, LINE, extent
    sol, _, _ = pages(CASES / "triad-eight-bar.toml")
    d = figures(sol).drawing["acceleration"]
    by = {g.ident: g for g in d.groups}
    texts = [it for it in by["legend"].items if it.text]
    xs = sorted({round(it.x, 3) for it in texts})
    assert len(xs) == 2
    first = [it.text for it in texts if round(it.x, 3) == xs[0]]
    second = [it.text for it in texts if round(it.x, 3) == xs[1]]
    assert first[0].startswith("Scaled from the drawing") and second[0] == "From the construction:"
    assert [it.text for it in texts] == first + second            # the legend's order kept
    kb, lb = extent(by["key"].items), extent(by["legend"].items)
    col2 = extent([it for it in texts if round(it.x, 3) == xs[1]])
    assert kb.x0 >= xs[1] - 1e-3 and kb.y0 > col2.y1                # the key over column 2
    drawn = extent([g for g in d.groups if g.ident not in
                    ("heading", "key", "legend", "scale-bar", "caption")])
    assert lb.y1 < drawn.y0 and kb.y1 < drawn.y0                    # below the drawing
    assert extent(by["scale-bar"].items).y1 < lb.y0
    row = LINE * LEGEND_SIZE                  # in one column it was a row a legend line
    assert lb.y1 - lb.y0 < (len(first) + 1) * row and len(first) + 6 < len(by["legend"].items)


def test_key_and_legend_beside_are_moved_up_to_the_drawing_before_going_below():
    """The triad's space diagram is composed with its key and legend beside it 19 mm from
    what it draws (the content box is wider); moved up to GAP from it, the page is narrow
    enough for the portrait page, so they stay beside (the plate is shorter)."""
    from diagrams.figures import PAGE, PLATE_MARGIN
    from diagrams.layout import GAP, MARGIN, extent
    sol, _, _ = pages(CASES / "triad-eight-bar.toml")
    d = figures(sol).drawing["space"]
    by = {g.ident: g for g in d.groups}
    drawn = extent([g for g in d.groups if g.ident not in
                    ("heading", "key", "legend", "scale-bar", "caption")])
    kb, lb = extent(by["key"].items), extent(by["legend"].items)
    assert abs(kb.x0 - (drawn.x1 + GAP)) < 1e-6 and abs(lb.x0 - kb.x0) < 1e-6
    assert lb.y0 > drawn.y0                                         # beside, not below
    assert d.width <= PAGE[0] + 2 * (MARGIN - PLATE_MARGIN) + 1e-9


def test_worksheet_answer_table_never_alone_on_a_last_page():
    """The answer table comes before the last drawing area, under that diagram's steps, in
    one piece: after the area, the table or its tail could print alone on a last page (an
    exam worksheet's did: tests/test_page_fill.py measures the printed pages); an area
    taller than A5 is as tall as the key's drawing needs, not a whole page."""
    from diagrams.handout import AREA_ROOM, AREAS, CSS, area_dims
    assert "section#your-answers { break-inside: avoid;" in CSS
    for stem in ("s001-we2", "s001-we4"):
        sol, _, ws = pages(CASES / f"{stem}.toml")
        table, area = ws.find('id="your-answers"'), ws.find('id="plate-area-acceleration"')
        assert 0 < table < area, stem
        figs = figures_of(sol)
        for diagram in sol.scene.solve:
            lay = figs.drawing[diagram].meta["layout"]
            fw, fh = lay.frame.x1 - lay.frame.x0, lay.frame.y1 - lay.frame.y0
            w, h = area_dims(figs, diagram)
            if (w, h) != AREAS["A5"]:
                assert w == AREAS["portrait"][0] and fh <= h - AREA_ROOM + 1e-6 \
                    and h <= AREAS["portrait"][1] and h % 10 == 0, (stem, diagram, h)
            assert fw <= w and fh <= h