"""``polygons`` command line.  Every bad input ends in one readable line and a non-zero exit."""
from __future__ import annotations

import argparse
import importlib
import sys

from .errors import PolygonsError

#: modules that add a sub-command: each has ``register(subparsers)``
COMMAND_MODULES = ("polygons.cmd_solve", "polygons.cmd_sweep", "polygons.cmd_draw",
                   "polygons.cmd_forces", "polygons.cmd_check", "polygons.cmd_handout",
                   "polygons.cmd_gallery")


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2, like every other error
        self.exit(2, f"polygons: error: {message}\n")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="polygons",
                     description="Velocity and acceleration polygons of planar mechanisms, "
                                 "constructed step by step as on a drawing board.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name in COMMAND_MODULES:
        importlib.import_module(name).register(sub)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except PolygonsError as exc:
        print(f"polygons: error: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        return 0
    except OSError as exc:
        print(f"polygons: error: {exc.filename or ''}: {exc.strerror}", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
