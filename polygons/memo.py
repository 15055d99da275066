"""Memos kept beside frozen records without changing them.

A frozen record (a scene, a plan, a program) is never changed through its ``__dict__``: what
is worked out once per record (its plan and program, its size, its unused links) is kept
here instead, keyed by the record's identity and dropped when the record is collected
(:func:`weakref.finalize`), so a new record with the same ``id`` never sees an old memo.
"""
from __future__ import annotations

import weakref

_MEMOS: dict[int, dict] = {}


def memo_of(obj) -> dict:
    """The memo dictionary of ``obj`` (created empty on first use)."""
    key = id(obj)
    memo = _MEMOS.get(key)
    if memo is None:
        memo = _MEMOS[key] = {}
        weakref.finalize(obj, _MEMOS.pop, key, None)
    return memo


__all__ = ["memo_of"]
