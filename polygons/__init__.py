"""polygons: planar mechanisms solved the way a drawing board does.

    scene (TOML) → plan (dyads → construction steps) → interpreters (numbers) → render

>>> import polygons
>>> res = polygons.solve("cases/s003-fig7.toml")          # doctest: +SKIP
>>> res.links["O4P4"].omega                                # doctest: +SKIP
1.2145955942749975

``solve`` and ``load`` are the Python API (:mod:`polygons.api`): a path, TOML text or a
:class:`Scene` in, a :class:`~polygons.api.Result` out (the core ``Solution``'s attributes
plus ``to_json()``, ``table()``, ``svg()`` and the notebook displays).

Nothing is imported until it is used (``import polygons`` stays cheap, so the command line
starts fast): the names below are resolved on first access.
"""
from __future__ import annotations

import importlib

#: public name -> module that defines it
_EXPORTS = {
    "load_scene": "polygons.scene",
    "Scene": "polygons.scene",
    "load": "polygons.api",
    "solve": "polygons.api",
    "Result": "polygons.api",
    "Solution": "polygons.evaluate",
    "PolygonsError": "polygons.errors",
    "solve_many": "polygons.batch",
}

__all__ = sorted(_EXPORTS)
__version__ = "0.1.0"


def __getattr__(name: str):
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'polygons' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(list(globals()) + list(_EXPORTS))
