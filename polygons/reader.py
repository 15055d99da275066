"""The one reader of scene tables: types, units and labels checked, errors naming file and key;
and the fields every answer table shares ([[answers]], [[force_answers]], [[pin_answers]])."""
from __future__ import annotations

import math
import os
import re
import stat
from pathlib import Path

from .errors import SceneError, SceneSyntaxError, UnitError, UnknownKeyError, show, suggest
from .scene_tables import ANSWER_KEYS
from .units import UNITS, parse_quantity

Vec = tuple[float, float]

#: a point label: a capital letter, then lower-case letters, digits, '_' or primes
LABEL = re.compile(r"[A-Z][a-z0-9_']*\Z")     # \Z, not $: "Z\n" is no label
_LABEL = LABEL


def record(cls, **fields):
    """A frozen dataclass record from ``fields`` (every field of ``cls``, values checked), set
    at once: equal to ``cls(**fields)``, whose ``__init__`` sets each field through
    ``object.__setattr__`` (for a scene's seventeen fields, three times as long).
    tests/test_scene_load.py checks that the records a scene is built of carry every field."""
    return record_of(cls, fields)


def record_of(cls, fields: dict):
    """:func:`record` from a dictionary already made (no keyword repacking: the step records
    of a solution are made this way, one per step)."""
    obj = _new(cls)
    obj.__dict__.update(fields)
    return obj


_new = object.__new__


#: a TOML escape that gives a control character (a raw one is not valid TOML): NUL, backspace,
#: form feed, escape, DEL, C1 ... (tab, newline and carriage return are text)
_CONTROL_ESCAPE = re.compile(r"\\(?:[bfe]|x[0-9A-Fa-f]{2}|u00[0189][0-9A-Fa-f]|u007[Ff]"
                             r"|U0000[0189][0-9A-Fa-f]|U00007[Ff])")
_CONTROL = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f]")


def refuse_control_characters(text: str, data, file: str) -> None:
    """Refuse a text value (or key) holding a control character other than tab and line
    ends: it would land in file names, SVG and HTML (where XML forbids it).  Walked only when
    ``text``, the TOML read, has an escape that can give one, so a scene costs one search."""
    if "\\" not in text or not _CONTROL_ESCAPE.search(text):
        return
    stack = [("", data)]
    while stack:
        where, value = stack.pop()
        if isinstance(value, str):
            m = _CONTROL.search(value)
            if m:
                raise SceneError(f"control character U+{ord(m.group(0)):04X} in the text "
                                 f"{show(value)}: only printable characters, tabs and line "
                                 f"breaks are allowed", file=file, where=where or None)
        elif isinstance(value, dict):
            for k, v in value.items():
                stack.append((f"{where}.{k}" if where else str(k), k))
                stack.append((f"{where}.{k}" if where else str(k), v))
        elif isinstance(value, list):
            stack.extend((f"{where}[{i}]", v) for i, v in enumerate(value))


class Reader:
    """Reads one scene table with location-aware errors: the one reader of every scene
    table (the scene's own, the force tables in :mod:`polygons.loads`, the pins)."""

    def __init__(self, file: str):
        self.file = file

    def table(self, data, where: str, allowed: tuple[str, ...], required: tuple[str, ...] = ()
              ) -> dict:
        if not isinstance(data, dict):
            raise SceneError(f"expected a table, got {type(data).__name__}", file=self.file,
                             where=where)
        for key in data:
            if key not in allowed:
                raise UnknownKeyError(f"unknown key {show(key)}: {suggest(key, allowed)}",
                                      file=self.file, where=f"{where}.{key}" if where else key)
        for key in required:
            if key not in data:
                raise SceneError(f"missing key {key!r} (required: {', '.join(required)})",
                                 file=self.file, where=where)
        return data

    def named(self, data, where: str) -> dict:
        """A table of named entries (``[ground]``, ``[sliders.C]`` ...): any key allowed."""
        if not isinstance(data, dict):
            raise SceneError(f"expected a table, got {type(data).__name__}", file=self.file,
                             where=where)
        return data

    def quantity(self, value, dimension: str, where: str, reduce: bool = False) -> float:
        return parse_quantity(value, dimension, file=self.file, where=where, reduce=reduce)

    def vec(self, value, where: str) -> Vec:
        if not isinstance(value, list) or len(value) != 2:
            raise SceneError(f"expected coordinates [x, y] with units, e.g. ['0 mm', '70 mm'], "
                             f"got {show(value)}", file=self.file, where=where)
        return (self.quantity(value[0], "length", where + "[0]"),
                self.quantity(value[1], "length", where + "[1]"))

    def label(self, value, where: str) -> str:
        if not isinstance(value, str) or not _LABEL.match(value):
            raise SceneError(f"{show(value)} is not a point label (a capital letter followed by "
                             f"lower-case letters or digits, e.g. 'C' or 'O2')", file=self.file,
                             where=where)
        return value

    def sense(self, value, where: str) -> int:
        from .senses import turn_word      # the one table of sense words, any case
        turn = turn_word(value)
        if turn is not None:
            return turn
        raise SceneError(f"sense must be 'CW' or 'CCW', got {show(value)}", file=self.file,
                         where=where)

    def string(self, value, where: str) -> str:
        if not isinstance(value, str):
            raise SceneError(f"expected text, got {show(value)}", file=self.file, where=where)
        return value


# ---------------------------------------------------------------- the scene file
#: largest scene file read (bytes): a scene is a few kB; checked before parsing, and no more
#: than this plus one byte is ever read (so /dev/zero or a huge file cannot exhaust memory)
MAX_SCENE_BYTES = 1_000_000


def _read_bounded(fd: int) -> bytes:
    """At most ``MAX_SCENE_BYTES + 1`` bytes of the open file ``fd``: asked for by the file's
    stated size (one ``read`` of a 1 MB buffer costs more than parsing a scene), the rest, if
    any, read up to the bound (a file that grew, a pipe or a device stating no size).  Read
    with ``os.read`` (a buffered file object costs more to set up than the read itself)."""
    size = os.fstat(fd).st_size
    want = size + 1 if 0 < size <= MAX_SCENE_BYTES else MAX_SCENE_BYTES + 1
    parts = []
    got = 0
    while got < want:
        chunk = os.read(fd, want - got)
        if not chunk:
            break
        parts.append(chunk)
        got += len(chunk)
        if got == want and want <= MAX_SCENE_BYTES:
            want = MAX_SCENE_BYTES + 1          # more than its stated size: read on
    return parts[0] if len(parts) == 1 else b"".join(parts)


#: bytes as they are (Windows would translate line ends without O_BINARY), not inherited
_OPEN_FLAGS = getattr(os, "O_BINARY", 0) | getattr(os, "O_CLOEXEC", 0)


#: opening a FIFO or a terminal must not wait for a writer (regular files ignore the flag)
_NONBLOCK = getattr(os, "O_NONBLOCK", 0)
_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISSOCK, "a socket"))


def kind_of_file(path) -> str | None:
    """None for a regular file; else what ``path`` is, in words ('no such file', 'a FIFO
    (named pipe)', 'a directory', ...) — looked at without opening it (a FIFO would block)."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return "no such file"
    except (OSError, ValueError) as exc:
        return f"not readable ({getattr(exc, 'strerror', None) or exc})"
    if stat.S_ISREG(mode):
        return None
    return next((words for test, words in _KINDS if test(mode)), "not a regular file")


def _regular_file(mode: int, file: str) -> None:
    """Refuse anything but a regular file (a FIFO, a device, a directory): it could block or
    never end, and a scene is a file of a few kB."""
    if stat.S_ISREG(mode):
        return
    kind = next((words for test, words in _KINDS if test(mode)), "not a regular file")
    raise SceneError(f"is {kind}, not a scene file (a scene is a regular file)", file=file)


def read_scene_text(path: str | Path) -> str:
    """The text of a scene file: at most :data:`MAX_SCENE_BYTES`, UTF-8, valid TOML nesting."""
    file = str(path)
    try:
        _regular_file(os.stat(path).st_mode, file)     # a FIFO would block the open itself
        fd = os.open(path, os.O_RDONLY | _OPEN_FLAGS | _NONBLOCK)
        try:
            _regular_file(os.fstat(fd).st_mode, file)  # (replaced between the two looks)
            raw = _read_bounded(fd)
        finally:
            os.close(fd)
    except FileNotFoundError:
        raise SceneError("no such scene file", file=file) from None
    except IsADirectoryError:
        raise SceneError("is a directory, not a scene file", file=file) from None
    except OSError as exc:
        raise SceneError(f"cannot read the scene file ({exc.strerror or exc})",
                         file=file) from None
    except ValueError:                # a NUL in the path (the Python API)
        raise SceneError("a file name cannot hold a NUL character", file=show(file)) from None
    if len(raw) > MAX_SCENE_BYTES:
        raise SceneError(f"the file is larger than the {MAX_SCENE_BYTES:,} byte limit for a "
                         f"scene file (a scene is a few kB)", file=file)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise SceneSyntaxError(f"not UTF-8 text: byte 0x{raw[exc.start]:02x} at line {line} "
                               f"(save the file as UTF-8)", file=file) from None


# ---------------------------------------------------------------- answer tables
def answer_fields(spec, r: Reader, where: str, default_tol: float, *,
                  extra_keys: tuple[str, ...] = (), extra_units=()) -> dict:
    """The fields every answer table shares (``[[answers]]``, ``[[force_answers]]``), checked:
    unknown keys, units, plain numbers for tutorial/exact, mode, tolerance, slip (each key
    the table gives, once; a scene file carries tens of answers).

    The checks run in this order, whichever refusal comes first being the one reported: the
    keys (unknown, then required), the unit, the quantity's text, then each value in the
    table's order."""
    if (extra_keys or spec.__class__ is not dict or not spec.keys() <= _ANSWER_KEY_SET
            or "quantity" not in spec or "unit" not in spec):
        r.table(spec, where, ANSWER_KEYS + extra_keys if extra_keys else ANSWER_KEYS,
                required=("quantity", "unit"))
    unit = spec["unit"]
    if not isinstance(unit, str):
        r.string(unit, where + ".unit")
    if unit not in UNITS and unit not in ("-", "1") and unit not in extra_units:
        raise UnitError(f"unknown unit {show(unit)}", file=r.file, where=where + ".unit")
    quantity = spec["quantity"]
    if not isinstance(quantity, str):
        r.string(quantity, where + ".quantity")
    out = {"quantity": quantity, "unit": unit, "tutorial": None, "exact": None, "mode": "abs",
           "sense": None, "tolerance": default_tol, "slip": False, "ref": None,
           "desc": quantity, "note": ""}
    for key, value in spec.items():
        kind = _ANSWER_KIND.get(key)
        if kind is None:                  # quantity, unit (read above), a caller's extra key
            continue
        if kind == _TEXT:
            if not isinstance(value, str):
                r.string(value, f"{where}.{key}")
            out[key] = value
        elif kind == _NUMBER:
            # a finite float within 1e15 as it is; anything else is _answer_number's to judge
            out[key] = (value if value.__class__ is float and -1e15 <= value <= 1e15
                        else _answer_number(value, key, unit, r, where))
        elif kind == _MODE:
            if value != "abs" and value != "signed":
                raise SceneError(f"mode must be 'abs' or 'signed', got {show(value)}",
                                 file=r.file, where=where + ".mode")
            out[key] = value
        elif kind == _TOLERANCE:
            out[key] = r.quantity(value, "fraction", where + ".tolerance")
        else:                             # slip
            if not isinstance(value, bool):
                raise SceneError("slip must be true or false", file=r.file,
                                 where=where + ".slip")
            out[key] = value
    return out


_ANSWER_KEY_SET = frozenset(ANSWER_KEYS)
_TEXT, _NUMBER, _MODE, _TOLERANCE, _SLIP = range(5)
#: how each answer key's value is read (quantity and unit are read first)
_ANSWER_KIND = {"sense": _TEXT, "ref": _TEXT, "desc": _TEXT, "note": _TEXT,
                "tutorial": _NUMBER, "exact": _NUMBER, "mode": _MODE,
                "tolerance": _TOLERANCE, "slip": _SLIP}


def _answer_number(value, key: str, unit: str, r: Reader, where: str) -> float:
    """A tutorial's or an exact answer: a plain finite number (in the answer's unit)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{key} must be a plain number in {show(unit)}, got {show(value)}",
                         file=r.file, where=f"{where}.{key}")
    if not math.isfinite(value) or abs(value) > 1e15:
        raise SceneError(f"{key} must be a finite number below 1e15 in magnitude, got "
                         f"{show(value)}", file=r.file, where=f"{where}.{key}")
    return float(value)
