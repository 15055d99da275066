"""Every documented example runs (issue 30, item 3): each command line of the README's and
the docs' code blocks and each inline command of theirs that names a scene (placeholders
CASE, SCENE, DIR, FILE, N filled in), and every example value a ``--help`` text gives for
a flag ('e.g. X', "('2 %' or 0.02)", "--scale velocity='2 m/s'", "… written: v_C=7.1 …").

The examples are read out of the texts, so a new one is run without touching this file.
Those that print a PDF (Chromium) or make the whole gallery run only with ``POLYGONS_SLOW=1``
(minutes); without it a sweep example runs without its plots and an exam
example with 2 variants written as HTML (the same flags otherwise), so the rest take a few seconds.
``polygons check`` exits 3 when it grades a value off (the README's example does): a run.
"""
from __future__ import annotations

import os
import re
import shlex
import shutil
from pathlib import Path

import pytest

from conftest import ROOT
from test_safety import run

SLOW = os.environ.get("POLYGONS_SLOW") not in (None, "", "0")
DOCS = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
_COMMAND = re.compile(r"^(?:\$ )?polygons ([a-z].*)$")


def _code_lines(path: Path):
    """(line number, text) of every line in a fenced or indented code block."""
    fenced = False
    for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line.strip().startswith("```"):
            fenced = not fenced
            continue
        if fenced or line.startswith("    "):
            yield i, line.strip()


def documented_commands() -> list[tuple[str, str]]:
    """(where, command line without 'polygons') of every documented command example."""
    out = []
    for path in DOCS:
        for i, line in _code_lines(path):
            m = _COMMAND.match(line)
            if m:
                out.append((f"{path.name}:{i}", m.group(1).split("  #")[0].strip()))
        text = path.read_text(encoding="utf-8")
        for m in re.finditer(r"`polygons ([a-z][^`]*)`", text):
            cmd = m.group(1)
            if re.search(r"\bCASE\b|\bCASE\.toml\b|\bSCENE\b|cases/", cmd):
                line = text.count("\n", 0, m.start()) + 1
                plain = re.sub(r"\s*\[[^\]]*\]", "", cmd)
                out.append((f"{path.name}:{line}", plain))
                if plain != cmd:       # [optional parts] run too
                    out.append((f"{path.name}:{line}+", cmd.replace("[", "").replace("]", "")))
    return list(dict.fromkeys(out))


#: a case for each placeholder, by command (a slider-crank for Klein, force tables for forces)
def _case_for(cmd: str) -> str:
    if cmd.startswith("forces"):
        return "cases/forces-toggle-press.toml"
    if cmd.startswith("ask"):
        return "cases/question-engine-conditions.toml"
    if "--klein" in cmd:
        return "cases/klein-inline-engine.toml"
    if "--drawing" in cmd:
        return "cases/s003-fig7.toml"
    return "cases/s001-we4.toml"


def _slow(cmd: str) -> bool:
    return "--pdf" in cmd or cmd.startswith("gallery") or \
        (cmd.startswith("handout") and cmd.endswith(".pdf --worksheet"))


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """A folder like the README's reader's: cases/, fig7.toml, a class list and the drawing
    the README shows (its ```json block)."""
    (tmp_path / "cases").symlink_to(ROOT / "cases")
    shutil.copy(ROOT / "cases" / "s003-fig7.toml", tmp_path / "fig7.toml")
    (tmp_path / "class.csv").write_text("name\nAda Lovelace\nCharles Babbage\n",
                                        encoding="utf-8")
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    drawing = re.search(r"student-acc\.json.*?```json\n(.*?)```", readme, re.S).group(1)
    (tmp_path / "student-acc.json").write_text(drawing, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_the_documents_have_command_examples():
    assert len(documented_commands()) >= 15


@pytest.mark.parametrize("where, cmd", documented_commands(), ids=lambda x: x)
def test_every_documented_command_runs(where, cmd, workdir):
    if _slow(cmd) and not SLOW:
        pytest.skip("minutes (a PDF, the gallery): POLYGONS_SLOW=1")
    if "--pdf" in cmd or cmd.endswith(".pdf --worksheet"):
        if not (shutil.which("chromium") or os.environ.get("POLYGONS_CHROMIUM")):
            pytest.skip("no Chromium to print with")
    case = _case_for(cmd)
    filled = re.sub(r"\bCASE(\.toml)?\b|\bSCENE\b", case, cmd)
    filled = re.sub(r"\bDIR\b", "out-dir", filled)
    filled = re.sub(r"--cycle N\b", "--cycle 36", filled)
    filled = re.sub(r"\bFILE\b", "student-acc.json", filled)
    argv = shlex.split(filled)
    if argv[0] in ("solve", "forces", "centres") and "--svg" not in argv:
        argv += ["-o", "out.txt"]
    if not SLOW:                # the plots and the variants cost seconds each
        if argv[0] == "sweep" and "--vary" not in argv:
            argv.append("--no-plot")
        if argv[0] == "exam":   # (and HTML: Chromium takes ~15 s per PDF here)
            argv[argv.index("--variants") + 1] = "2"
            argv.append("--html")
    code, out, err = run(*argv)
    assert code in _RAN.get(argv[0], (0,)) and "error" not in err, (where, filled, err)


#: exit codes of a command that ran (check: 3 when a graded value is off)
_RAN = {"check": (0, 3)}


# ---------------------------------------------------------------- --help examples
_CMDS = ("solve", "draw", "sweep", "forces", "centres", "check", "handout", "exam", "gallery",
         "ask")


def _subparser(command: str):
    from polygons.cli import _parser
    p = _parser(command)
    sub = next(a for a in p._actions if a.__class__.__name__ == "_SubParsersAction")
    return sub.choices[command]


def help_examples() -> list[tuple[str, str, tuple[str, ...]]]:
    """(command, flag, values) for every example value a --help text gives."""
    out = []
    for command in _CMDS:
        sub = _subparser(command)
        flags = {s for a in sub._actions for s in a.option_strings}
        for a in sub._actions:
            text = " ".join((a.help or "").replace("%%", "%").split())
            own = next((s for s in a.option_strings if s.startswith("--")), None)
            if own is None:
                continue
            # --flag VALUE, of this command's flags, written in the help
            for m in re.finditer(r"(--[a-z-]+)[ =]((?:[A-Za-z_]+=)?'[^']*'|[^\s;,()'/]+)", text):
                if m.group(1) in flags and not m.group(2).startswith("-"):
                    out.append((command, m.group(1), (m.group(2),)))
            # e.g. X
            for m in re.finditer(r"e\.g\. ('[^']*'|[^\s;,)]+)", text):
                out.append((command, own, (m.group(1),)))
            # ('A' or B...): the alternatives of a value
            for m in re.finditer(r"\(('[^']*') or ([^;,)\s]+)", text):
                out.append((command, own, (m.group(1),)))
                out.append((command, own, (m.group(2),)))
            # "…: NAME=V NAME=V ..." for a flag taking many values
            m = re.search(r": ((?:[A-Za-z_]+=(?:'[^']*'|\S+)\s*){2,})$", text)
            if m:
                out.append((command, own, tuple(shlex.split(m.group(1)))))
    return list(dict.fromkeys(out))


def test_the_help_texts_have_examples():
    found = {(c, f) for c, f, _ in help_examples()}
    assert {("forces", "--fluctuation"), ("sweep", "--vary"), ("check", "--measured"),
            ("draw", "--scale"), ("check", "--tolerance")} <= found


#: what each command needs around the flag (a case it applies to, an output)
_BASE = {
    "solve": ["cases/s001-we4.toml", "-o", "out.txt"],
    "draw": ["cases/s001-we4.toml", "-o", "out-dir", "--no-stages"],
    "sweep": ["cases/s001-we4.toml", "-o", "out-dir", "--no-plot", "--steps", "12"],
    "forces": ["cases/forces-toggle-press.toml", "-o", "out.txt", "--cycle", "12"],
    "centres": ["cases/s001-we4.toml", "-o", "out.txt"],
    "check": ["cases/s001-we6.toml", "--measured", "v_C=15.1", "-o", "out.txt"],
    "handout": ["cases/s001-we4.toml", "-o", "out.html"],
    "ask": ["cases/question-engine-conditions.toml"],
}


@pytest.mark.parametrize("command, flag, values", help_examples(), ids=str)
def test_every_help_example_runs(command, flag, values, workdir):
    base = list(_BASE[command])
    if flag == "--measured":
        base = [x for x in base if x not in ("--measured", "v_C=15.1")]
    if flag == "--klein":
        base[0] = "cases/klein-inline-engine.toml"
    argv = [command, *base, flag, *[v.strip("'") if "=" not in v else v.replace("'", "")
                                    for v in values]]
    code, out, err = run(*argv)
    assert code in _RAN.get(command, (0,)) and err == "", (argv, err)
