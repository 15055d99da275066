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
