"""A cold `polygons solve` imports no drawing library and nothing only an error, --json or a
wrong name needs (issue 31: the cold start; the time itself is measured by benchmarks/run.py)."""
import subprocess
import sys

from conftest import CASES

PROBE = """
import io, sys, contextlib
from polygons.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    code = main(["solve", sys.argv[1]])
print(code, " ".join(sorted(m for m in sys.modules
                           if m in sys.argv[2:] or m.split(".")[0] in sys.argv[2:])))
"""

LAZY = ("matplotlib", "svgwrite", "diagrams", "cairosvg", "numba", "tqdm", "tomllib", "json",
        "difflib",
        # the tables and triads this scene has none of: imported where they are used
        "polygons.cam_profiles", "polygons.contacts", "polygons.pins", "polygons.question_table", "polygons.forces",
        "numpy.polynomial")


def test_solve_imports_no_drawing_library():
    out = subprocess.run([sys.executable, "-c", PROBE, str(CASES / "s003-fig7.toml"), *LAZY],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    code, *loaded = out.stdout.split()
    assert code == "0" and loaded == []
