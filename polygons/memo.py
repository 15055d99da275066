"""Memos kept beside frozen records without changing them.

A frozen record (a scene, a plan, a program) is never changed through its ``__dict__``: what
is worked out once per record (its plan and program, its size, its unused links) is kept
here instead, keyed by the record's identity and dropped when the record is collected
(:func:`weakref.finalize`), so a new record with the same ``id`` never sees an old memo.

A memo that refers back to its record (a scene's plan holds the scene) keeps the record
alive through this module's table, so it is never collected: a caller that makes many
short-lived records (``polygons exam`` draws thousands of variants and rejects most) records
the memos made meanwhile (:func:`recording`) and drops them (:func:`forget`).
"""
from __future__ import annotations

import weakref
from contextlib import contextmanager

_MEMOS: dict[int, dict] = {}
_RECORDERS: list[set] = []


def memo_of(obj) -> dict:
    """The memo dictionary of ``obj`` (created empty on first use)."""
    key = id(obj)
    memo = _MEMOS.get(key)
    if memo is None:
        memo = _MEMOS[key] = {}
        weakref.finalize(obj, _MEMOS.pop, key, None)
        for made in _RECORDERS:
            made.add(key)
    return memo


@contextmanager
def recording():
    """The keys of every memo made inside the ``with`` block (for :func:`forget`)."""
    made: set[int] = set()
    _RECORDERS.append(made)
    try:
        yield made
    finally:
        _RECORDERS.remove(made)


def forget(keys) -> None:
    """Drop the memos of ``keys`` (from :func:`recording`): their records may then be
    collected; one used again starts an empty memo."""
    for key in keys:
        _MEMOS.pop(key, None)


__all__ = ["memo_of", "recording", "forget"]
