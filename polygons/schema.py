"""The scene-file schema as data: every table and key the loader accepts.

Each parser module (``scene``, ``loads``, ``options``, ...) declares its tables with
:class:`Key` / :class:`Table`; the scene-file reference (``docs/scene-reference.md``) and the
JSON Schema shipped with the package are generated from these declarations, so they cannot
drift from what the loader really reads (a test holds them together).
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Key:
    """One key of a scene table.

    ``type``: 'quantity' (a string with a unit of ``dimension``), 'string', 'number', 'bool',
    'label' (a point label), 'link' (a link name), 'point' (a pair of lengths), 'array',
    'numbers' (a number or an array of them), 'table'.  ``default`` is None for a required key (``required``) or when absent means
    "not stated".
    """

    name: str
    type: str
    doc: str
    example: str = ""
    dimension: str | None = None
    default: object | None = None
    required: bool = False
    sign: str = ""          # sign convention in words, where one applies


@dataclass(frozen=True)
class Table:
    """A top-level table (``[driver]``), a table of named sub-tables (``[sliders.C]``,
    ``many=True``) or an array of tables (``[[answers]]``, ``array=True``)."""

    name: str
    doc: str
    keys: tuple[Key, ...]
    many: bool = False
    array: bool = False
    required: bool = False
