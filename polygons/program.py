"""The typed statements of a generated program (:mod:`polygons.codegen`).

Every value the generated code holds is a :class:`Name` (a local ``v7``, a parameter ``k3``,
the input ``x``); every formula an :class:`Expr` built from a template and its operands, so
what it reads is known when it is made — never searched for in the text afterwards.  A
statement is a :class:`Line`: the names it assigns, its text and the names it reads; a check
(``if not (...): raise``) assigns none.  :func:`live` keeps the statements an output needs,
by those typed reads (dead-code elimination on the ops, not on the text).
"""
from __future__ import annotations

import math
from dataclasses import dataclass


class Name(str):
    """A name of the generated program: its own text, and the one name it reads."""

    __slots__ = ()

    @property
    def reads(self) -> frozenset:
        return frozenset((self,))


class Lit(str):
    """A literal of the generated program (a number written out, a quoted string): it reads
    no name."""

    __slots__ = ()

    @property
    def reads(self) -> frozenset:
        return frozenset()


def _operand(o) -> tuple[str, frozenset]:
    """(text, reads) of one operand: a Name, an Expr, a Lit, a plain number, or the text of a
    number ('0.0', '1.0').  Anything else is refused: a formula's reads must be typed."""
    if isinstance(o, (Name, Lit, Expr)):
        return str(o), o.reads
    if isinstance(o, (int, float)) and not isinstance(o, bool):
        return repr(o), frozenset()
    if type(o) is str:
        try:
            math.isfinite(float(o))
        except ValueError:
            raise TypeError(f"an untyped operand in a generated formula: {o!r} (make it "
                            f"with Source.let / Source.e)") from None
        return o, frozenset()
    raise TypeError(f"an operand of a generated formula must be a Name, an Expr or a number, "
                    f"not {type(o).__name__}")


class Expr:
    """A formula: ``template`` (Python, one ``{}`` per operand) over ``operands``; its text
    and the names it reads, both fixed when it is made."""

    __slots__ = ("text", "reads")

    def __init__(self, template: str, *operands):
        parts = [_operand(o) for o in operands]
        self.text = template.format(*(t for t, _ in parts))
        self.reads = frozenset().union(*(r for _, r in parts))

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"Expr({self.text!r})"


def reads_of(o) -> frozenset:
    """The names a Name, Lit, Expr or number text reads."""
    return _operand(o)[1]


@dataclass(frozen=True)
class Line:
    """One statement: ``targets = text`` (a check when ``targets`` is empty), reading
    ``reads``."""
    targets: tuple[Name, ...]
    text: str
    reads: frozenset

    @property
    def check(self) -> bool:
        return not self.targets


def live(lines: list[Line], out) -> list[Line]:
    """Dead-code elimination on the straight-line program: keep every check (with what it
    tests) and each assignment whose target a kept statement or an output (``out``) reads."""
    need: set = set()
    for o in out:
        need |= reads_of(o)
    kept = []
    for line in reversed(lines):
        if line.check or any(t in need for t in line.targets):
            kept.append(line)
            need |= line.reads
    return kept[::-1]


__all__ = ["Name", "Lit", "Expr", "Line", "live", "reads_of"]
