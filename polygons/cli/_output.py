"""Where a command's text goes: ``-o/--out FILE`` or standard output (one helper for all)."""
from __future__ import annotations

import sys
from pathlib import Path

from ..errors import PolygonsError


def add_out_option(p) -> None:
    """``-o/--out FILE``: the table (or JSON) goes to FILE instead of standard output."""
    p.add_argument("-o", "--out", metavar="FILE",
                   help="write the table (or the JSON with --json) to FILE instead of standard "
                        "output")


def emit(text: str, out: str | None) -> None:
    """Write ``text`` to standard output, or to the file ``out``."""
    if not out:
        sys.stdout.write(text)
        return
    path = Path(out)
    if path.is_dir():
        raise PolygonsError(f"{path} is a folder: -o takes a file name", where=str(path))
    try:
        path.write_text(text, encoding="utf-8")
    except OSError as exc:
        raise PolygonsError(f"cannot write {path} ({exc.strerror})", where=str(path)) from None
