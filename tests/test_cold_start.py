"""A cold `polygons solve` imports no drawing library and nothing only an error, --json or a
wrong name needs (issue 31: the cold start; the time itself is measured by benchmarks/run.py)."""
import subprocess
import sys

import pytest

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
        "numpy.polynomial",
        # the dyad kinds the planner never asks for a crank and a slotted lever (their static
        # index, polygons/dyads/_index.py: each imported when first asked)
        "polygons.dyads.slider_drive", "polygons.dyads.rrr", "polygons.dyads.rrp",
        "polygons.dyads.rpp", "polygons.dyads.guided", "polygons.dyads.crossing",
        "polygons.dyads.wheel_pin", "polygons.dyads.slot_slider", "polygons.dyads.triad",
        "polygons.dyads.triad_slider",
        # the force tables' readers and records: this scene has none (polygons.loadbodies)
        "polygons.loads", "polygons.loadmodel", "polygons.loadrun",
        # argparse's terminal width found without shutil (polygons.cli.columns)
        "shutil", "bz2", "lzma")


def test_solve_imports_no_drawing_library():
    out = subprocess.run([sys.executable, "-c", PROBE, str(CASES / "s003-fig7.toml"), *LAZY],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    code, *loaded = out.stdout.split()
    assert code == "0" and loaded == []


BLAS_PROBE = """
import io, os, sys, contextlib
sys.argv = ["polygons", "solve", sys.argv[1]]
from polygons.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    code = main()                      # as the program runs it (argv None)
print(code, os.environ.get("OPENBLAS_NUM_THREADS"), len(os.listdir("/proc/self/task")))
"""


def _blas_probe(**env):
    import os
    clean = {k: v for k, v in os.environ.items()
             if k not in ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS")}
    out = subprocess.run([sys.executable, "-c", BLAS_PROBE, str(CASES / "s003-fig7.toml")],
                         capture_output=True, text=True, timeout=120, env={**clean, **env})
    assert out.returncode == 0, out.stderr
    return out.stdout.split()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="threads read off /proc")
def test_program_starts_openblas_with_one_thread():
    """The program starts numpy's OpenBLAS with one thread (no worker per core set up at import:
    ~55 ms of CPU of a cold solve) — and a number the user chose is kept."""
    assert _blas_probe() == ["0", "1", "1"]                 # one thread in the whole process
    code, blas, threads = _blas_probe(OMP_NUM_THREADS="2")
    assert (code, blas) == ("0", "None") and int(threads) >= 1


def test_one_blas_thread_keeps_a_number_the_user_chose():
    from polygons.cli import one_blas_thread
    env = {"OMP_NUM_THREADS": "4"}
    one_blas_thread(env)
    assert env == {"OMP_NUM_THREADS": "4"}
    env = {}
    one_blas_thread(env)
    assert env == {"OPENBLAS_NUM_THREADS": "1"}


def test_the_kinds_index_is_what_discovery_finds():
    """polygons/dyads/_index.py (the planner's order, each kind's group class) is written by
    ``python -m polygons.dyads`` from the modules' ROLE and BEFORE: a new or moved kind shows
    here until it is rewritten."""
    from polygons import dyads
    from polygons.dyads import _index
    assert (_index.ORDER, _index.CLASSES) == dyads.discovered(), \
        "run: python -m polygons.dyads (the index is stale)"
    for tup, role in dyads.TUPLES.items():     # the exported tuples follow the index
        assert [m.__name__.rsplit(".", 1)[1] for m in getattr(dyads, tup)] == \
            list(_index.ORDER[role])


@pytest.mark.parametrize("env", [{}, {"COLUMNS": "60"}, {"COLUMNS": "0"}, {"COLUMNS": "x"}])
def test_the_help_width_is_shutils(env, monkeypatch):
    """argparse's width (polygons.cli.columns) is what shutil.get_terminal_size gives it."""
    import shutil
    from polygons.cli import columns
    monkeypatch.delenv("COLUMNS", raising=False)
    for k, v in env.items():
        monkeypatch.setenv(k, v)
    assert columns() == shutil.get_terminal_size().columns


GC_PROBE = """
import gc, io, sys, contextlib
seen = {}
def hook(event, args):
    if event == "import" and args[0] == "polygons.evaluate" and "evaluate" not in seen:
        seen["evaluate"] = gc.isenabled()
sys.addaudithook(hook)
sys.argv = ["polygons", "solve", sys.argv[1]]
from polygons.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    code = main()
print(code, seen["evaluate"], gc.isenabled(), gc.get_freeze_count() > 0)
"""


def test_the_program_starts_without_the_collector():
    """The program's start-up (the solver's imports) runs without the cyclic collector, which
    runs again for the command itself, what the start-up made frozen out of its way."""
    out = subprocess.run([sys.executable, "-c", GC_PROBE, str(CASES / "s003-fig7.toml")],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["0", "False", "True", "True"]
