"""`polygons exam`: seeded variants, their conditioning, and the LMS files field by field.

Moodle XML is checked against what Moodle's importer reads (question/format/xml/format.php:
``import_headers`` — name/text, questiontext@format + its <file name path encoding>,
defaultgrade, penalty; ``import_numerical`` — answer@fraction / 100, answer/text,
answer/tolerance, units/unit/multiplier + unit_name, unitgradingtype, showunits, unitsleft;
``import_multichoice`` — single, answer@fraction), and graded with Moodle's numerical rule:
the first answer with |response − answer| ≤ tolerance gives its fraction.  The QTI package is
checked for its structure (XML parsed; no IMS schema is available offline to validate
against).
"""
import base64
import math
import re
import shutil
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import pytest

from analytic import four_bar, slotted_lever
from polygons.cli import main
from polygons.exam import lms, make_exam
from polygons.exam.variants import MAX_VARIANTS

CASES = Path(__file__).resolve().parents[1] / "cases"
WE3 = CASES / "s001-we3.toml"
FIG7 = CASES / "s003-fig7.toml"

#: the [exam] table Fig 7 ships (the README's example); FIG7_BARE is the case without it
FIG7_EXAM = FIG7.read_text(encoding="utf-8")[FIG7.read_text(encoding="utf-8").index("[exam]"):]
FIG7_BARE = FIG7.read_text(encoding="utf-8").replace(FIG7_EXAM, "")


@pytest.fixture(scope="module")
def we3_exam():
    return make_exam(str(WE3), 3, 11)


@pytest.fixture(scope="module")
def fig7_path(tmp_path_factory):
    path = tmp_path_factory.mktemp("fig7") / "fig7-exam.toml"
    path.write_text(FIG7.read_text(encoding="utf-8"), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def fig7_exam(fig7_path):
    return make_exam(str(fig7_path), 3, 5)


def test_variants_are_well_conditioned_and_answers_match_the_closed_form(we3_exam):
    assert len(we3_exam.variants) == 3
    for v in we3_exam.variants:
        assert v.min_angle_deg >= 30 and v.closure_deg >= 15
        for a in v.asked:                  # no noise answer
            assert abs(a.value) >= we3_exam.spec.min_ratio * a.tolerance
        drv = v.scene.driver
        A, D = v.scene.ground["A"], v.scene.ground["D"]
        ln = {n: l.length for n, l in v.scene.links.items()}
        c = v.solution.points["C"].position
        # the closure the scene's words chose (C above AD): the closed form's matching branch
        exact = min((four_bar(A, D, ln["AB"], ln["BC"], ln["DC"], drv.angle, drv.omega, 0.0, b)
                     for b in (1, -1)), key=lambda r: math.dist(r["C"], c))
        want = {"v(B)": math.hypot(*exact["vB"]), "v(C)": math.hypot(*exact["vC"]),
                "omega(BC)": exact["omega_BC"], "omega(DC)": exact["omega_CD"],
                "alpha(BC)": exact["alpha_BC"], "alpha(DC)": exact["alpha_CD"],
                "a(C)": math.hypot(*exact["aC"])}
        for a in v.asked:
            if a.expr in want:
                assert a.value == pytest.approx(want[a.expr], rel=1e-9, abs=1e-9)
                if a.sense:
                    assert a.sense == ("CCW" if want[a.expr] > 0 else "CW")
            assert a.tolerance > 0


def test_fig7_exam_varies_the_table_and_matches_the_slotted_lever(fig7_exam):
    seen = set()
    for v in fig7_exam.variants:
        values = dict(v.values)
        assert set(values) == {"O2P2", "angle", "omega"}
        seen.add(tuple(values.values()))
        drv = v.scene.driver
        assert v.scene.links["O2P2"].length == pytest.approx(float(values["O2P2"].split()[0])
                                                             / 1000)
        ex = slotted_lever(v.scene.ground["O2"], v.scene.links["O2P2"].length, drv.angle,
                           drv.omega, 0.0, v.scene.ground["O4"])
        got = {a.expr: a.value for a in v.asked}
        assert got["omega(O4P4)"] == pytest.approx(ex["omega_lever"], rel=1e-9)
        assert got["alpha(O4P4)"] == pytest.approx(ex["alpha_lever"], rel=1e-9)
        assert got["cor(P2)"] == pytest.approx(math.hypot(*ex["coriolis"]), rel=1e-9)
        assert got["vs(P2)"] == pytest.approx(ex["s_dot"], rel=1e-9)
    assert len(seen) == 3                    # no two variants alike


def test_quiz_tolerance_is_what_polygons_check_accepts(fig7_exam):
    """The numerical question's tolerance is check's: the emulated 95th percentile, else the
    stated tolerance, never under a 0.5 mm reading at the variant's scale."""
    from polygons.cli.check import grade
    from polygons.exam.variants import _Scale
    for v in fig7_exam.variants:
        scales = {d: _Scale(per_cm) for d, per_cm in v.scales.items()}
        for a in v.asked:                   # moved away from zero: any sign rule agrees
            away = math.copysign(1.0, a.value)
            inside = a.value + away * 0.99 * a.tolerance
            outside = a.value + away * 1.01 * a.tolerance
            for x, ok in ((inside, True), (outside, False)):
                g = grade(v.solution, [(a.symbol, a.expr, x, None)], scales=scales)[0]
                assert g.ok is ok, (a.expr, x, g.tolerance, a.tolerance)
                assert g.tolerance == pytest.approx(a.tolerance, rel=1e-12)
                assert g.source == a.source


def test_same_seed_same_variants_other_seed_other(fig7_path):
    a, b = make_exam(str(fig7_path), 2, 9), make_exam(str(fig7_path), 2, 9)
    assert lms.moodle_xml(a) == lms.moodle_xml(b) and lms.gift(a) == lms.gift(b)
    assert lms.qti_zip(a) == lms.qti_zip(b)
    c = make_exam(str(fig7_path), 2, 10)
    assert [v.values for v in c.variants] != [v.values for v in a.variants]


def test_rejections_are_counted_with_reasons(fig7_path, tmp_path):
    text = fig7_path.read_text(encoding="utf-8").replace(
        'O2P2 = "150..250 mm step 10"', 'O2P2 = "150..250 mm step 10"\nmin_angle = "89.9 deg"')
    strict = tmp_path / "strict.toml"
    strict.write_text(text, encoding="utf-8")
    ex = make_exam(str(strict), 1, 1)       # the slot's lines always cross at 90°
    assert len(ex.variants) == 1
    text = text.replace('min_angle = "89.9 deg"', 'min_vector = "150 mm"\nattempts = 5')
    strict.write_text(text, encoding="utf-8")
    with pytest.raises(Exception, match="under 150 mm") as e:
        make_exam(str(strict), 1, 1)
    # how many the ranges can give (an estimate when the attempts ran out) and what limits them
    assert "combinations would be" in str(e.value) and "the limiting criterion: an asked " \
        "answer's line under 150 mm" in str(e.value)


def _moodle_grade(question, x: float) -> float:
    """Moodle's numerical rule: the first answer whose |x − answer| ≤ tolerance."""
    for ans in question.findall("answer"):
        if abs(x - float(ans.find("text").text)) <= float(ans.find("tolerance").text):
            return float(ans.get("fraction")) / 100
    return 0.0


def test_moodle_xml_field_by_field_and_simulated_grading(fig7_exam):
    """Moodle's question/format/xml/format.php ``import_numerical`` reads answer@fraction,
    answer/text and answer/tolerance; question/type/numerical/question.php
    ``get_matching_answer`` grades by the FIRST answer whose tolerance interval holds the
    response, so the full band comes first and the partial (wider) one second."""
    images = {v.number: b"<svg xmlns='http://www.w3.org/2000/svg'/>" for v in
              fig7_exam.variants}
    root = ET.fromstring(lms.moodle_xml(fig7_exam, images))
    assert root.tag == "quiz"
    qs = root.findall("question")
    types = [q.get("type") for q in qs]
    nvar = len(fig7_exam.variants)
    assert types.count("category") == nvar
    assert types.count("numerical") == 5 * nvar
    assert types.count("multichoice") == 0     # ω, α answered signed: no separate sense
    asked = {(v.number, a.expr): a for v in fig7_exam.variants for a in v.asked}
    for q in qs:
        if q.get("type") == "category":
            assert q.find("category/text").text.startswith("$course$/top/")
            continue
        name = q.find("name/text").text
        number = int(re.match(r"V(\d+) ", name).group(1))
        qt = q.find("questiontext")
        assert qt.get("format") == "html"
        f = qt.find("file")
        assert f.get("encoding") == "base64" and f.get("path") == "/"
        assert f"@@PLUGINFILE@@/{f.get('name')}" in qt.find("text").text
        stem = qt.find("text").text                 # answerable without the picture
        assert "max-width" not in stem and "not to scale" in stem
        assert "fixed point O2" in stem and "fixed point O4" in stem and "O2P2 = " in stem
        assert base64.b64decode(f.text) == images[number]
        assert float(q.find("defaultgrade").text) == 1.0
        if q.get("type") == "numerical":
            expr = q.find("idnumber").text.split("-", 2)[2]
            a = asked[(number, expr)]
            answers = q.findall("answer")
            assert [x.get("fraction") for x in answers] == ["100", "50"]
            assert float(answers[0].find("text").text) == pytest.approx(a.answer, rel=1e-5)
            tol = float(answers[0].find("tolerance").text)
            assert tol == pytest.approx(a.tolerance, rel=1e-5)
            assert float(answers[1].find("tolerance").text) == pytest.approx(3 * tol, rel=1e-5)
            unit = q.find("units/unit")
            assert unit.find("multiplier").text == "1"
            assert unit.find("unit_name").text == lms.ASCII_UNIT[a.unit]
            assert q.find("unitgradingtype").text == "0"
            assert q.find("showunits").text in ("0", "1", "2", "3")
            # graded as Moodle grades it
            assert _moodle_grade(q, a.answer) == 1.0
            assert _moodle_grade(q, a.answer + 0.9 * a.tolerance) == 1.0
            assert _moodle_grade(q, a.answer + 2 * a.tolerance) == 0.5
            assert _moodle_grade(q, a.answer - 2 * a.tolerance) == 0.5
            assert _moodle_grade(q, a.answer + 3.5 * a.tolerance) == 0.0
            if a.signed:                            # the sign is graded: −answer earns 0
                assert _moodle_grade(q, -a.answer) == 0.0
                assert "signed" in stem and ("counter-clockwise" in stem or "away from" in stem)
            else:
                assert a.answer > 0 and "magnitude" in stem


def test_qti_package_structure(fig7_exam):
    """Canvas's importer (gems/plugins/qti_exporter/lib/qti/numeric_interaction.rb,
    ``get_canvas_answers``) makes an answer of ``:weight=>100`` of every respcondition — an
    ``or`` of a varequal (the exact value) and an ``and`` whose varlte gives the margin — so
    each numerical item carries exactly one: the full band (a partial band would be graded
    fully correct)."""
    images = {1: b"<svg xmlns='http://www.w3.org/2000/svg'/>"}
    z = zipfile.ZipFile(__import__("io").BytesIO(lms.qti_zip(fig7_exam, images)))
    names = z.namelist()
    assert names[:2] == ["imsmanifest.xml", "quiz.xml"]
    assert "images/variant-01-space.svg" in names
    man = ET.fromstring(z.read("imsmanifest.xml"))
    ns = {"m": "http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1"}
    res = man.find("m:resources/m:resource", ns)
    assert res.get("type") == "imsqti_xmlv1p2" and res.get("href") == "quiz.xml"
    quiz = ET.fromstring(z.read("quiz.xml"))
    q = {"q": "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"}
    items = quiz.findall(".//q:item", q)
    kinds = [i.find(".//q:fieldentry", q).text for i in items]
    first = items[0].find(".//q:mattext", q).text
    assert 'src="%24IMS-CC-FILEBASE%24/images/variant-01-space.svg"' in first
    assert kinds.count("numerical_question") == 5 * len(fig7_exam.variants)
    asked = {f"v{v.number:02d}-{lms._ident(a.expr)}": a for v in fig7_exam.variants
             for a in v.asked}
    for item in items:
        if item.get("ident") not in asked:
            continue
        a = asked[item.get("ident")]
        conds = item.findall(".//q:respcondition", q)
        assert len(conds) == 1                      # no partial band for Canvas to make 100 %
        assert float(conds[0].find(".//q:varequal", q).text) == pytest.approx(a.answer, rel=1e-5)
        lo = float(conds[0].find(".//q:vargte", q).text)
        hi = float(conds[0].find(".//q:varlte", q).text)
        assert lo == pytest.approx(a.answer - a.tolerance, rel=1e-5, abs=1e-9)
        assert hi == pytest.approx(a.answer + a.tolerance, rel=1e-5, abs=1e-9)
        assert conds[0].find(".//q:setvar", q).text == "100"


NASTY = "<script>alert(1)</script> ]]> & ~ = # { } : \\ end"


def test_user_text_stays_escaped_in_xml_gift_and_qti(fig7_path, tmp_path):
    text = fig7_path.read_text(encoding="utf-8")
    title = "title = " + __import__("json").dumps(NASTY)
    text = re.sub(r'^title = ".*"$', lambda m: title, text, flags=re.M)   # both titles
    path = tmp_path / "nasty.toml"
    path.write_text(text, encoding="utf-8")
    ex = make_exam(str(path), 1, 1)
    assert ex.scene.title == NASTY and ex.variants[0].scene.title.startswith(NASTY)
    xml = lms.moodle_xml(ex)
    root = ET.fromstring(xml)                              # well formed
    stem = root.find("question[@type='numerical']/questiontext/text").text
    assert "<script>" not in stem and "&lt;script&gt;" in stem
    assert b"<script>" not in xml
    gift = lms.gift(ex)
    for line in gift.splitlines():
        if not line.startswith("::"):
            continue
        body = re.sub(r"\\.", "", line)                     # drop every escaped character
        head, _, rest = body[2:].partition("::")
        stem_part, brace, answer = rest.partition("{")
        assert brace and answer.endswith("}") and "{" not in answer[:-1]
        assert not any(c in stem_part for c in "~=#{}:")   # specials only escaped
        assert "<script>" not in line
    z = zipfile.ZipFile(__import__("io").BytesIO(lms.qti_zip(ex)))
    quiz = z.read("quiz.xml")
    ET.fromstring(quiz)
    assert b"<script>" not in quiz


def test_cli_writes_the_files_deterministically(fig7_path, tmp_path):
    out1, out2 = tmp_path / "a", tmp_path / "b"
    for out in (out1, out2):
        assert main(["exam", str(fig7_path), "--variants", "1", "--seed", "4", "--out",
                     str(out), "--html"]) == 0
    for name in ("quiz.xml", "quiz.gift", "quiz-qti.zip", "key.html",
                 "worksheets/variant-01.html"):
        assert (out1 / name).read_bytes() == (out2 / name).read_bytes(), name
    key = (out1 / "key.html").read_text(encoding="utf-8")
    assert key.count("<h2>Variant ") == 1 and "ω_O4P4" in key


def test_cli_students_and_refusals(fig7_path, tmp_path, capsys):
    names = tmp_path / "class.csv"
    names.write_text("name\nAda Lovelace\n../../etc/passwd\n<b>Bob</b> & Co\n",
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["exam", str(fig7_path), "--variants", "1", "--out", str(out), "--html",
                 "--students", str(names)]) == 0
    files = sorted(p.name for p in (out / "worksheets").iterdir())
    assert len(files) == 3 and all(re.fullmatch(r"[A-Za-z0-9_.-]+", f) for f in files)
    assert files[1].startswith("002-etc-passwd")
    bob = (out / "worksheets" / files[2]).read_text(encoding="utf-8")
    assert "&lt;b&gt;Bob&lt;/b&gt; &amp; Co" in bob and "<b>Bob" not in bob
    capsys.readouterr()
    # a bound checked before any work, an out "dir" that is a file: one line, exit 1
    assert main(["exam", str(fig7_path), "--variants", str(MAX_VARIANTS + 1), "--out",
                 str(out)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"1 to {MAX_VARIANTS}" in err
    afile = tmp_path / "file"
    afile.write_text("x")
    assert main(["exam", str(fig7_path), "--variants", "1", "--out", str(afile)]) == 1
    assert "not a folder" in capsys.readouterr().err
    # the scene is never written over, even when it sits where quiz.xml would go
    inside = tmp_path / "inside"
    inside.mkdir()
    scene = inside / "quiz.xml"
    shutil.copy(fig7_path, scene)
    before = scene.read_bytes()
    assert main(["exam", str(scene), "--variants", "1", "--out", str(inside), "--html"]) == 1
    assert scene.read_bytes() == before
    assert "refusing to write over it" in capsys.readouterr().err


def test_exam_table_is_checked_at_load(fig7_path, tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    for extra, words in (('[exam]\nXY = "1..2 mm step 1"\n', "unknown key"),
                         ('[exam]\nomega = "-30..-10 rad/s step 5"\n', "a magnitude"),
                         ('[exam]\nmin_ratio = 2\n', "more than partial_factor"),
                         ('[exam]\npose_margin = "40 deg"\n', "pose_margin"),
                         ('[exam]\nO2P2 = "10..20 mm"\n', "LOW..HIGH UNIT step STEP"),
                         ('[exam]\nangle = "1..2 mm step 1"\n', "angle"),
                         ('[exam]\nO2P2 = "1..100000 mm step 1"\n', "at most"),
                         ('[exam]\nask = ["x(C)"]\n', "cannot be asked")):
        bad.write_text(FIG7_BARE + extra, encoding="utf-8")
        assert main(["solve", str(bad)]) == 1
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "[exam" in err and words in err, err


def test_key_and_quiz_print_the_same_numbers():
    from diagrams.exam_sheets import _num
    for x in (0.0, 1e-7, 0.0123456789, 1.0, 29.78268, 123456.789, -2.689234, 4.0e9):
        assert _num(x) == lms.number(x)


def test_pdf_dates_and_id_are_made_constant():
    from diagrams.exam_sheets import pdf_stable
    a = (b"%PDF-1.4\n1 0 obj << /CreationDate (D:20261125144301+00'00') "
         b"/ModDate (D:20261125144301+00'00') >> endobj\ntrailer << /ID [<0A1B2C3D> <4E5F6071>] >>")
    b = a.replace(b"144301", b"150959").replace(b"0A1B2C3D", b"99999999")
    assert pdf_stable(a) == pdf_stable(b) and len(pdf_stable(a)) == len(a)
    assert b"2026" not in pdf_stable(a)
    c = a.replace(b"obj <<", b"obj << /Other 1")
    assert pdf_stable(c) != pdf_stable(a)          # the ID follows the content


CHROMIUM = shutil.which("chromium") or __import__("os").environ.get("POLYGONS_CHROMIUM")


@pytest.mark.skipif(not CHROMIUM, reason="headless Chromium is not installed: the PDF key "
                                         "and worksheets are not printed (their HTML is "
                                         "tested above)")
def test_pdfs_are_printed(tmp_path):
    out = tmp_path / "a"
    assert main(["exam", str(WE3), "--variants", "1", "--seed", "2", "--out", str(out)]) == 0
    for name in ("key.pdf", "worksheets/variant-01.pdf"):
        data = (out / name).read_bytes()
        assert data.startswith(b"%PDF") and b"/CreationDate (D:1980" in data, name
    if __import__("os").environ.get("POLYGONS_SLOW"):     # a second print: the same bytes
        again = tmp_path / "b"
        assert main(["exam", str(WE3), "--variants", "1", "--seed", "2", "--out",
                     str(again)]) == 0
        for name in ("key.pdf", "worksheets/variant-01.pdf"):
            assert (out / name).read_bytes() == (again / name).read_bytes(), name


# ---------------------------------------------------------------- slider drivers
def _with_exam(tmp_path, stem, exam: str) -> Path:
    p = tmp_path / f"{stem}.toml"
    p.write_text((CASES / f"{stem}.toml").read_text() + "\n[exam]\n" + exam)
    return p


def test_a_slider_driven_by_its_rod_varies_the_rod_angle_and_omega(tmp_path):
    """The ladder: each variant's bar is at one of the angles and turns at one of the rates,
    its sense (CCW) and α's (CW) kept; the answers are the polygons' of that variant, which
    give the bar its stated ω back."""
    p = _with_exam(tmp_path, "book-ladder-bar-omega",
                   'rod_angle = "120..160 deg step 5"\nrod_omega = "1..4 rad/s step 0.5"\n')
    ex = make_exam(str(p), 4, 3)
    assert len(ex.variants) == 4
    for v in ex.variants:
        values = dict(v.values)
        name, w, al = v.scene.driver.rod_rate
        assert w == pytest.approx(float(values["rod_omega"].split()[0]), rel=1e-12) and w > 0
        assert al == pytest.approx(-1.5)
        assert v.solution.links["AB"].omega == pytest.approx(w, rel=1e-9)
        B = v.solution.points["B"].position
        A = v.solution.points["A"].position
        ang = math.degrees(math.atan2(B[1] - A[1], B[0] - A[0]))
        assert ang == pytest.approx(float(values["rod_angle"].split()[0]), abs=1e-9)


def test_a_slider_driven_at_a_velocity_varies_its_position_and_velocity(tmp_path):
    p = _with_exam(tmp_path, "new-elliptic-trammel",
                   'position = "40..90 mm step 5"\nvelocity = "0.5..2 m/s step 0.25"\n')
    ex = make_exam(str(p), 3, 2)
    for v in ex.variants:
        values = dict(v.values)
        assert v.scene.driver.velocity == pytest.approx(
            float(values["velocity"].split()[0]), rel=1e-12)
        assert v.scene.driver.position * 1e3 == pytest.approx(
            float(values["position"].split()[0]), rel=1e-12)


@pytest.mark.parametrize("stem,exam,words", [
    ("book-ladder-bar-omega", 'velocity = "1..2 m/s step 0.5"', "driven by its rod's ω"),
    ("book-ladder-bar-omega", 'position = "1..2 m step 0.5"', "places it by its rod"),
    ("new-elliptic-trammel", 'rod_omega = "1..2 rad/s step 0.5"', "driven by its velocity"),
    ("new-elliptic-trammel", 'rod_angle = "100..120 deg step 5"', "places it by position"),
    ("s001-we3", 'position = "1..2 m step 0.5"', "a crank"),
])
def test_slider_keys_that_do_not_fit_the_driver_are_refused(tmp_path, stem, exam, words):
    from polygons.errors import SceneError
    p = _with_exam(tmp_path, stem, exam + "\n")
    with pytest.raises(SceneError) as e:
        make_exam(str(p), 2, 1)
    assert words in str(e.value)
