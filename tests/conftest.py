import contextlib
import io
import json
import os
import subprocess
import sys
from functools import cache
from pathlib import Path

import pytest
from hypothesis import settings


ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "cases"
#: the project's copy of the reference answers (exact values, tutorial answers, slips): see
#: tests/reference/README.md for where it comes from.  Always present: a fresh clone checks
#: every answer with nothing beside it.
REFERENCE = Path(__file__).resolve().parent / "reference" / "cases.json"
#: the steering side's reference, beside the repository on CI and developers' machines: only an
#: extra cross-check (tests/test_cases.py) that the copy above is still the same, where present.
SHARED_REFERENCE = ROOT.parent / "shared" / "reference" / "cases.json"

sys.path.insert(0, str(Path(__file__).resolve().parent))

# CI replays the same property-test examples every run (a submission lands or not on its code,
# not on a random draw); a developer's run keeps exploring new ones.  Same bounds either way.
settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

#: Property tests (hypothesis) run at full depth (the number their settings pass to ``examples``)
#: on CI, whose examples are the same every run, and with ``POLYGONS_DEEP=1``; an everyday run
#: draws a quarter as many (at least 10), new ones each run, to keep the suite within its time
#: budget.  ``POLYGONS_DEEP=0`` makes CI shallow too.
DEEP = os.environ.get("POLYGONS_DEEP", "1" if os.environ.get("CI") else "") not in ("", "0")


def examples(full: int) -> int:
    """The number of hypothesis examples for a property test whose full depth is ``full``."""
    return full if DEEP else max(10, full // 4)


def case_files():
    return sorted(CASES.glob("*.toml"))


@cache
def _reference(path: Path) -> dict:
    return {c["id"]: c for c in json.loads(path.read_text(encoding="utf-8"))["cases"]}


def reference_cases() -> dict:
    """The project reference's records by case id (``S001-WE2`` …)."""
    return _reference(REFERENCE)


def shared_reference_cases() -> dict | None:
    """The shared reference's records by case id, or None where it is not beside the repository."""
    return _reference(SHARED_REFERENCE) if SHARED_REFERENCE.is_file() else None


@pytest.hookimpl(tryfirst=True)
def pytest_cmdline_main(config):
    """The whole suite (``pytest`` with no path: the README's test command) runs on every core
    when pytest-xdist is installed (it is in the test extras), each idle worker taking tests
    from a busy one (``worksteal``: a few tests take seconds, most milliseconds).  ``-n N``
    chooses, ``-n 0`` runs in one process; a run of chosen files or tests stays in one process
    unless ``-n`` is given.  (Before xdist's own hook, which turns ``-n`` into workers.)"""
    if (config.pluginmanager.hasplugin("xdist") and not hasattr(config, "workerinput")
            and config.option.numprocesses is None and config.option.dist == "no"
            and config.args_source == pytest.Config.ArgsSource.TESTPATHS
            and not config.getoption("collectonly") and not config.getoption("usepdb")):
        config.option.numprocesses = "auto"
        config.option.dist = "worksteal"


def cli(*args, cwd=None) -> subprocess.CompletedProcess:
    """``polygons ARGS`` through its entry point function in this process
    (``polygons.cli.main(argv)``: the same parsing, commands, exit codes and one-line errors,
    without a cold start of ~0.2 s a call), as a ``CompletedProcess`` with text
    ``stdout``/``stderr``; a usage error's ``SystemExit`` (argparse) is its exit code.  Where
    the separate process is what is checked (the console script, stdin, byte-identical output
    across processes, nothing but one line on a real stderr), the tests still run one."""
    from polygons.cli import main
    argv = [str(a) for a in args]
    out, err = io.StringIO(), io.StringIO()
    with contextlib.chdir(cwd or os.getcwd()), contextlib.redirect_stdout(out), \
            contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:          # argparse: --help (0), a usage error (2)
            code = exc.code
            if code is None:
                code = 0
            elif not isinstance(code, int):   # sys.exit("message"): the message on stderr
                print(code, file=sys.stderr)
                code = 1
    return subprocess.CompletedProcess(["polygons", *argv], code, out.getvalue(),
                                       err.getvalue())


@pytest.fixture
def write_scene(tmp_path):
    """Write a scene text to a temporary .toml file and return its path."""
    def write(text: str, name: str = "scene.toml") -> Path:
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path
    return write


@pytest.fixture(scope="module")
def session():
    """One headless Chromium for a module's page tests (DevTools over a pipe; skipped where
    Chromium is not installed): tests/test_browser.py, tests/test_page_audit.py."""
    from diagrams import browser
    if browser.find() is None:
        pytest.skip("headless Chromium is not installed (Debian package 'chromium')")
    with browser.Session(1400, 1000) as s:
        yield s
