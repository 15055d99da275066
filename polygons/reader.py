"""The one reader of scene tables: types, units and labels checked, errors naming file and key."""
from __future__ import annotations

import re

from .errors import SceneError, UnknownKeyError, show, suggest
from .units import parse_quantity

Vec = tuple[float, float]

#: a point label: a capital letter, then lower-case letters, digits, '_' or primes
LABEL = re.compile(r"^[A-Z][a-z0-9_']*$")
_LABEL = LABEL


def record(cls, **fields):
    """A frozen dataclass record from ``fields`` (every field of ``cls``, values checked), set
    at once: equal to ``cls(**fields)``, whose ``__init__`` sets each field through
    ``object.__setattr__`` (for a scene's seventeen fields, three times as long).
    tests/test_scene_load.py checks that the records a scene is built of carry every field."""
    obj = _new(cls)
    obj.__dict__.update(fields)
    return obj


_new = object.__new__


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
        if value in ("CCW", "ccw", "anticlockwise", "anti-clockwise", "counter-clockwise"):
            return 1
        if value in ("CW", "cw", "clockwise"):
            return -1
        raise SceneError(f"sense must be 'CW' or 'CCW', got {show(value)}", file=self.file,
                         where=where)

    def string(self, value, where: str) -> str:
        if not isinstance(value, str):
            raise SceneError(f"expected text, got {show(value)}", file=self.file, where=where)
        return value
