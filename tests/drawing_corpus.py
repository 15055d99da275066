"""The corpus of typical student errors (tests/data/drawings): its cases and their checks,
shared by the Python grader's tests and the page's (grade.js in headless Chromium)."""
import re
import tomllib
from functools import lru_cache
from pathlib import Path

HERE = Path(__file__).resolve().parent
DRAWINGS = HERE / "data" / "drawings"
CASES = HERE.parent / "cases"
with open(DRAWINGS / "corpus.toml", "rb") as fh:
    CORPUS = tomllib.load(fh)
SOURCE_NAME = re.compile(r"\b[a-z]\d+_\d")          # p2_1: a vertex in source form


def case_of(name: str) -> Path:
    return CASES / ("s003-fig7.toml" if name.startswith("fig7") else "s001-we3.toml")


@lru_cache(maxsize=None)
def solved(path: Path):
    from polygons.cli.check import emulated_tolerances, stated_tolerance
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    sol = solve(load_scene(path))
    return sol, emulated_tolerances(sol), stated_tolerance(sol)


def check(name: str, result: dict) -> None:
    """``result``: a grade as plain data (polygons.cli._drawing.grade_json, or grade.js)."""
    want = CORPUS[name]
    got = {v["vector"]: v for v in result["vectors"]}
    assert {n: v["mark"] for n, v in got.items()} == want["marks"], (name, result)
    assert result["score"] == sum(want["marks"].values())
    for n, v in got.items():
        words = want.get("problems", {}).get(n, [])
        if not words:
            assert v["problem"] == "", (name, n, v["problem"])
        for w in words:
            assert w in v["problem"], (name, n, w, v["problem"])
        for text in (v["problem"], v["hint"], v["note"]):
            assert not SOURCE_NAME.search(text), (name, n, text)   # p₂′, never p2_1
        if v["mark"] < 1:
            assert v["hint"], (name, n)
    carried = [n for n, v in got.items() if v["note"].startswith("length carried forward")]
    assert carried == want.get("carried", []), (name, carried)
    off = [c["vertex"] for c in result["closures"] if not c["ok"]]
    assert off == want.get("closures_off", []), (name, result["closures"])
    assert result["unknown_vertices"] == want.get("unknown", [])
    assert result["all_ok"] == (name.endswith("-right") or all(
        m == 1 for m in want["marks"].values()) and not off), name


def mangled(n: int, seed: int = 29):
    """``n`` drawings made from the corpus by random slips of every kind at once (vertices
    moved up to 40 mm, one set onto another, arrows dropped, reversed or doubled, the pole
    called o): (name of the source drawing, StudentDrawing)."""
    import random
    from polygons.drawing_format import StudentDrawing, read_drawing
    rng = random.Random(seed)
    names = sorted(CORPUS)
    out = []
    for i in range(n):
        name = names[i % len(names)]
        d = read_drawing(str(DRAWINGS / CORPUS[name]["file"]))
        V = {v: (x + rng.choice((0, 0, rng.uniform(-40, 40))),
                 y + rng.choice((0, 0, rng.uniform(-40, 40)))) for v, (x, y) in d.vertices.items()}
        keys = sorted(V)
        if rng.random() < 0.2 and len(keys) > 1:
            V[keys[1]] = V[keys[0]]                                # two vertices on one point
        vecs = []
        for a, b in d.vectors:
            r = rng.random()
            if r < 0.15:
                continue
            vecs.append((b, a) if r < 0.3 else (a, b))
            if r > 0.9:
                vecs.append((a, b))
        if rng.random() < 0.2 and vecs:
            vecs.append((vecs[0][1], vecs[-1][0]))
        if rng.random() < 0.2:
            pole = sorted(V)[0]
            V = {("o" if v == pole else v): p for v, p in V.items()}
            vecs = [tuple("o" if x == pole else x for x in ab) for ab in vecs]
        out.append((name, StudentDrawing(d.diagram, d.scale, d.scale_text, V, tuple(vecs),
                                         f"<mangled {i}>")))
    return out
