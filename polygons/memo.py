"""Memos kept beside frozen records without changing their fields.

What is worked out once per record (a scene's plan and program, its size, its unused links)
is kept in a memo dictionary that lives *on the record itself*, under one attribute that is
not a field (so equality, hashing, ``repr`` and :func:`dataclasses.replace` never see it).
A memo may refer back to its record (a scene's plan holds the scene): that is an ordinary
reference cycle, collected with the record, so many short-lived records (``polygons exam``
draws thousands of variants and rejects most) never pile up.

The memo is tagged with its record's ``id``: a shallow copy of a record (which copies the
attribute) starts its own, empty memo instead of sharing the original's.

Records without a ``__dict__`` (slotted classes) keep their memo in a table keyed by
``id`` and dropped when the record is collected (:func:`weakref.finalize`); such a memo
must not refer back to its record, or the caller records the memos made meanwhile
(:func:`recording`) and drops them (:func:`forget`).
"""
from __future__ import annotations

import weakref
from contextlib import contextmanager

_ATTRIBUTE = "_polygons_memo"
_MEMOS: dict[int, dict] = {}
_RECORDERS: list[set] = []


def memo_of(obj) -> dict:
    """The memo dictionary of ``obj`` (created empty on first use)."""
    key = id(obj)
    own = getattr(obj, "__dict__", None)
    if own is not None:
        held = own.get(_ATTRIBUTE)
        if held is not None and held[0] == key:
            return held[1]
        memo: dict = {}
        own[_ATTRIBUTE] = (key, memo)          # not a field: frozen records stay frozen
        return memo
    memo = _MEMOS.get(key)
    if memo is None:
        memo = _MEMOS[key] = {}
        weakref.finalize(obj, _MEMOS.pop, key, None)
        for made in _RECORDERS:
            made.add(key)
    return memo


@contextmanager
def recording():
    """The keys of every table memo made inside the ``with`` block (for :func:`forget`)."""
    made: set[int] = set()
    _RECORDERS.append(made)
    try:
        yield made
    finally:
        _RECORDERS.remove(made)


def forget(keys) -> None:
    """Drop the table memos of ``keys`` (from :func:`recording`): their records may then be
    collected; one used again starts an empty memo."""
    for key in keys:
        _MEMOS.pop(key, None)


__all__ = ["memo_of", "recording", "forget"]
