"""``polygons`` command line.  Every bad input ends in one readable line and a non-zero exit.

Each command lives in its own module of this package with ``register(subparsers)``.  Only the
module of the command being run is imported (``polygons --help`` imports none of them, so it
starts without numpy); the table below gives the one-line help shown in the command list.
"""
from __future__ import annotations

import argparse
import importlib
import os
import sys

#: command -> (module, one-line help for the command list)
COMMANDS = {
    "solve": ("polygons.cli.solve", "solve a scene: velocities, accelerations, ω, α, steps"),
    "sweep": ("polygons.cli.sweep", "solve a scene over a full input revolution: CSV + plots"),
    "draw": ("polygons.cli.draw", "draw the space, velocity and acceleration diagrams (SVG)"),
    "forces": ("polygons.cli.forces", "forces: inertia forces, input torque, pin reactions, "
                                      "free-body diagrams"),
    "check": ("polygons.cli.check", "grade a student's measured values against the "
                                    "construction"),
    "handout": ("polygons.cli.handout", "write a printable handout (HTML, optional PDF) or "
                                        "worksheet"),
    "centres": ("polygons.cli.centres", "instantaneous centres (Kennedy), rubbing and least "
                                        "velocities"),
    "exam": ("polygons.cli.exam", "seeded exam variants: Moodle XML, GIFT, QTI, key and "
                                  "worksheets"),
    "ask": ("polygons.cli.ask", "answer the scene's [[questions]]: the angle or speed at which "
                                "a condition holds, stroke, dead centres, time ratio"),
    "gallery": ("polygons.cli.gallery", "write every case's handout and worksheet and an "
                                        "index page"),
}


def columns() -> int:
    """The terminal's width as ``shutil.get_terminal_size()`` gives it to argparse: ``$COLUMNS``
    when a positive number, else the width of standard output's terminal, else 80 — without
    importing shutil (with bz2 and lzma: ~3 ms of every start, ``--help`` included)."""
    try:
        width = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        width = 0
    if width <= 0:
        try:
            width = os.get_terminal_size(sys.__stdout__.fileno()).columns or 80
        except (AttributeError, ValueError, OSError):
            width = 80
    return width


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2, like every other error
        self.exit(2, f"polygons: error: {message}\n")

    def _get_formatter(self):  # argparse's, the width found as shutil finds it (columns)
        return self.formatter_class(prog=self.prog, width=columns() - 2)


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The argument parser; only ``command``'s module is imported (all of them when None)."""
    parser = _Parser(prog="polygons",
                     description="Velocity and acceleration polygons of planar mechanisms, "
                                 "constructed step by step as on a drawing board.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name, (module, help_text) in COMMANDS.items():
        if command is None or name == command:
            importlib.import_module(module).register(sub)
        else:
            sub.add_parser(name, help=help_text, add_help=False)
    return parser


_PARSERS: dict = {}


def _parser(command: str | None) -> argparse.ArgumentParser:
    """:func:`build_parser`, built once per command in a process (a parser is not changed by
    parsing; building one costs ~10 ms of argparse and gettext, more than many a solve)."""
    parser = _PARSERS.get(command)
    if parser is None:
        parser = _PARSERS[command] = build_parser(command)
    return parser


def _command_of(argv: list[str]) -> str | None:
    for arg in argv:
        if not arg.startswith("-"):
            return arg if arg in COMMANDS else ""
    return ""


#: exit codes (README, "Exit codes")
EXIT_OK, EXIT_ERROR, EXIT_USAGE, EXIT_INTERNAL = 0, 1, 2, 70


def _one_line(text: str, limit: int = 2000) -> str:
    """A message on one line, cut to ``limit`` characters (it must stay readable)."""
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


#: the variables OpenBLAS reads for its number of threads
BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS")


def one_blas_thread(environ) -> None:
    """numpy's OpenBLAS started with one thread when the user set none of
    :data:`BLAS_THREADS`: at import it starts a worker thread per core and sets it up (~55 ms
    of CPU on a 2-core machine, a quarter of a cold ``polygons solve``, and wall time too when
    the other core is busy), while no command multiplies matrices large enough to gain from a
    second thread (the force analysis solves 3 equations per body).  Only the program does
    this (``polygons`` and ``python -m polygons``), before numpy is imported; a Python caller
    of :func:`main` keeps its own environment."""
    if not any(k in environ for k in BLAS_THREADS):
        environ["OPENBLAS_NUM_THREADS"] = "1"


def main(argv=None) -> int:
    """Run one command (:func:`run_command`); run as the program (``argv`` None: ``polygons``
    and ``python -m polygons``) its start-up (imports, parsing) runs without the cyclic
    collector (:func:`_started`), and the process exits as it returns, so the objects made are
    frozen out of the collector first: the interpreter's last full collection at exit then has
    nothing to traverse (~15-40 ms of a cold ``polygons solve``; every file a command writes is
    closed by then, standard output is flushed at exit all the same)."""
    if argv is not None:
        return run_command(argv)
    one_blas_thread(os.environ)
    import gc
    gc.disable()                       # the start-up runs without the collector (_started)
    code = run_command(sys.argv[1:], started=_started)
    gc.freeze()
    return code


def _started() -> None:
    """The command's modules imported and its arguments parsed: what the start-up made (the
    modules, their functions and classes) lives as long as the process, so it is frozen out of
    the collector, which runs from here on.  The start-up ran without it: the collector's ~56
    passes over those objects, which never die, were ~5-10 % of a cold ``polygons solve``."""
    import gc
    gc.freeze()
    gc.enable()


def run_command(argv, started=None) -> int:
    """Run one command.  Exit codes: 0 done; 1 an error in the input or its solution (one
    line ``polygons: error: FILE [key] reason`` on stderr); 2 a usage error (argparse); 70 an
    internal error (a bug: ``polygons: internal error: ... (please report this)``).

    Every warning (numpy, shapely, matplotlib...) is an error while a command runs: nothing
    may reach stderr but the one line.
    """
    argv = list(argv)
    parser = _parser(_command_of(argv))
    args = parser.parse_args(argv)
    if started is not None:           # (the program: main)
        started()
    from ..errors import PolygonsError
    import warnings
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            # a character missing from the plot font (a CJK title) is drawn as a box: cosmetic
            warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from font")
            from ._output import refuse_overwriting_input
            refuse_overwriting_input(args)       # the input file is never written over
            func = args.func     # looked up again: the parser is reused, a test may patch it
            func = getattr(sys.modules.get(func.__module__), func.__name__, func)
            from ..model import RUNNING          # a refusal names the command run
            token = RUNNING.set(f"polygons {_command_of(argv)}")
            try:
                return int(func(args) or 0)
            finally:
                RUNNING.reset(token)
    except PolygonsError as exc:
        scene = getattr(args, "scene", None)
        if not exc.file and isinstance(scene, str):
            try:                 # every error names the scene file the command was given
                exc = exc.located(file=scene)
            except Exception:    # pragma: no cover - a subclass with another signature
                pass
        print(f"polygons: error: {_one_line(exc)}", file=sys.stderr)
        return EXIT_ERROR
    except BrokenPipeError:
        return EXIT_OK
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"polygons: error: {_one_line(where + (exc.strerror or str(exc)))}",
              file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        print("polygons: error: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:                     # a bug: say so, in one line, and ask for a report
        print(f"polygons: internal error: {_one_line(f'{type(exc).__name__}: {exc}', 300)} "
              f"(please report this)", file=sys.stderr)
        return EXIT_INTERNAL


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
