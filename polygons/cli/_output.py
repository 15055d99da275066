"""Where a command's text goes: ``-o/--out FILE`` or standard output (one helper for all)."""
from __future__ import annotations

import os
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


#: the suffixes of the files a command writes into an output folder (draw, sweep, centres,
#: gallery, solve/forces --svg): a scene of such a name in that folder would be overwritten
WRITTEN_SUFFIXES = (".svg", ".png", ".pdf", ".csv", ".html", ".json")


def _same(a: str | Path, b: str | Path) -> bool:
    """Whether ``a`` and ``b`` name one existing file (another path, a symbolic or a hard
    link to it included)."""
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):
        return False


def refuse_overwriting_input(args) -> None:
    """Refuse, before any work, an output (``-o``/``--out``, ``--svg``) that is the input
    scene file itself or would overwrite it: the input is never written over."""
    inputs = [v for v in (getattr(args, "scene", None), getattr(args, "cases", None))
              if isinstance(v, str) and v]
    for key, flag in (("out", "--out"), ("svg", "--svg")):
        target = getattr(args, key, None)
        if not isinstance(target, str) or not target:
            continue
        files = [target]
        if getattr(args, "pdf", False) and key == "out":
            p = Path(target)
            files.append(str(p.with_suffix(".pdf") if p.suffix else p.with_name(p.name + ".pdf")))
        for src in inputs:
            if not os.path.isfile(src):
                continue
            if any(_same(f, src) for f in files):
                raise PolygonsError(f"{flag} {target} is the input file {src}: refusing to "
                                    f"overwrite it (give another output name)", where=flag)
            if (Path(src).suffix.lower() in WRITTEN_SUFFIXES and os.path.isdir(target)
                    and _same(target, Path(src).parent)):
                raise PolygonsError(f"the input {src} is in the output folder {target} under a "
                                    f"name this command may write: refusing to risk "
                                    f"overwriting it (give another folder)", where=flag)
