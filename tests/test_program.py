"""The generated program's statements are typed (polygons.program): what each formula reads
is known when it is made, and dead code is removed on those reads — no regular expression
over the generated text (codegen once found the names with one)."""
from __future__ import annotations

from pathlib import Path

import pytest

from polygons.program import Expr, Line, Lit, Name, live, reads_of


def test_a_formula_knows_what_it_reads():
    a, b, k = Name("v1"), Name("v2"), Name("k0")
    e = Expr("{} * -{} + {}", a, b, 2.5)
    assert e.text == "v1 * -v2 + 2.5" and e.reads == {a, b}
    nested = Expr("hypot({}, {})", e, k)
    assert nested.text == "hypot(v1 * -v2 + 2.5, k0)" and nested.reads == {a, b, k}
    assert reads_of(Lit("'velocity'")) == frozenset() and reads_of("0.0") == frozenset()


@pytest.mark.parametrize("bad", ["v1 + v2", object(), True])
def test_an_untyped_operand_is_refused(bad):
    with pytest.raises(TypeError):
        Expr("{} + 1.0", bad)


def test_live_keeps_what_an_output_or_a_check_reads():
    v = [Name(f"v{i}") for i in range(6)]
    lines = [Line((v[1],), "v1 = x", frozenset({Name("x")})),
             Line((v[2],), "v2 = v1 * 2.0", frozenset({v[1]})),
             Line((v[3],), "v3 = v1 + 1.0", frozenset({v[1]})),          # dead
             Line((), "if not (v2 > 0.0): raise _Fail(0)", frozenset({v[2]})),
             Line((v[4], v[5]), "v4, v5 = _f(v1)", frozenset({v[1]})),  # v5 needed
             ]
    kept = live(lines, [v[5]])
    assert [ln.text for ln in kept] == ["v1 = x", "v2 = v1 * 2.0",
                                        "if not (v2 > 0.0): raise _Fail(0)", "v4, v5 = _f(v1)"]


def test_a_generated_program_is_made_of_typed_lines():
    from polygons.codegen import Source
    from polygons.scene import load_scene
    scene = load_scene(Path(__file__).resolve().parents[1] / "cases" / "s003-fig7.toml")
    g = Source(scene, {})
    px = g.param(lambda s: 1.0)
    n = g.let("hypot({}, {})", px, g.x)
    assert isinstance(n, Name) and g.lines[-1].reads == {px, g.x}
    assert g.let("hypot({}, {})", px, g.x) == n            # the same formula: the same local
    with pytest.raises(TypeError):
        g.let(Expr("{} + 1.0", n), n)
    m = g.let(f"{n} + 1.0")              # bare text: its names untyped, taken as all so far
    assert g.untyped == [f"{n} + 1.0"] and g.lines[-1].reads >= {n, px}
    assert [ln.text for ln in live(g.lines, [m])][-1] == f"{m} = {n} + 1.0"


def test_no_shipped_group_writes_untyped_text():
    """Every formula of every case's generated programs is typed (a bare f-string given to
    ``let`` is kept working, reading every name made before it, and counted here)."""
    from polygons.codegen import generate
    from polygons.plan import construction, make_plan
    from polygons.scene import load_scene
    from polygons import codegen
    seen = []
    real = codegen.Source.__init__

    def spy(self, *a, **k):
        real(self, *a, **k)
        seen.append(self)
    codegen.Source.__init__ = spy
    try:
        for path in sorted((Path(__file__).resolve().parents[1] / "cases").glob("*.toml")):
            scene = load_scene(path)
            plan = make_plan(scene)
            generate(scene, plan, construction(plan), {}, arrays=True)
    finally:
        codegen.Source.__init__ = real
    assert seen and [u for g in seen for u in g.untyped] == []


def test_codegen_reads_no_text_back():
    src = (Path(__file__).resolve().parents[1] / "polygons" / "codegen.py").read_text()
    assert "import re\n" not in src and "re.compile" not in src
