"""The textbook spelling of polygon vertex names, shared by the text outputs and the drawings.

A vertex name is written in scene-safe source form — a lower-case letter, digits, and ``_k``
for the k-th dash: ``p4_1`` — and printed as a tutorial prints it, digits subscripted and
dashes as primes: p₄′ (``_2`` → ″, ``_3`` → ‴).  :func:`vertex` spells one name,
:func:`vertices_in` every vertex name in a sentence (``p2_1p2`` → p₂′p₂, a vector named by its
two ends).  :mod:`diagrams.notation` builds its typesetting on :data:`PRIMES` and
:data:`VERTEX`, so the table, the hints and the drawings spell a vertex the same way.
"""
from __future__ import annotations

import re

#: the dash a vertex name's ``_k`` suffix stands for
PRIMES = {"1": "′", "2": "″", "3": "‴"}
#: one vertex name in source form: letter, digits, optional ``_k`` dash
VERTEX = r"(?P<vl>[a-z])(?:(?P<vd>\d+)(?:_(?P<vp>[123]))?|_(?P<vq>[123]))"
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_ONE = re.compile(rf"{VERTEX}|(?P<bare>[a-z])")
_WORD = re.compile(r"(?<![\w/′.\-])[a-z][a-z0-9_]*(?![\w])")


def vertex(name: str) -> str:
    """'p4_1' → 'p₄′', 'b1' → 'b₁', 'p_1' → 'p′', 'o' → 'o' (anything else unchanged)."""
    m = re.fullmatch(VERTEX, name)
    if m is None:
        return name
    if m["vq"]:                                     # 'p_1' → 'p′' (a Coriolis foot)
        return m["vl"] + PRIMES[m["vq"]]
    return m["vl"] + m["vd"].translate(_SUB) + (PRIMES[m["vp"]] if m["vp"] else "")


#: a component's superscript as the table prints it (docs/notation.md)
SUPERSCRIPTS = {"n": "ⁿ", "t": "ᵗ", "slide": "^slide"}


def quantity(q: str) -> str:
    """A step's quantity in the table's one-line spelling, the superscript after the
    parenthesis: '(a_C)_B^t' → '(a_C)ᵗ_B', '(a_P2)_P4^slide' → '(a_P2)^slide_P4'; 'v_C',
    '(v_C)_B', 'ω_BC' unchanged.  The exam's symbols are written by it."""
    head, _, sup = q.partition("^")
    if not sup or sup not in SUPERSCRIPTS or not head.startswith("(") or ")_" not in head:
        return q
    inner, _, ref = head.partition(")_")
    return f"{inner}){SUPERSCRIPTS[sup]}_{ref}"


def vertices_in(text: str, names) -> str:
    """Every vertex name of ``names`` in ``text`` spelled as printed, also two of them
    written together as a vector ('p2_1p2' → 'p₂′p₂'); other words are left alone."""
    known = set(names)
    # the longest name that begins the word and leaves a name (of one length only one name
    # can begin it): a set lookup per length, not a scan of every name
    lengths = sorted({len(n) for n in known}, reverse=True)

    def repl(m):
        w = m.group(0)
        if w in known:
            return vertex(w)
        for k in lengths:
            if k < len(w) and w[:k] in known and w[k:] in known:
                return vertex(w[:k]) + vertex(w[k:])
        return w
    return _WORD.sub(repl, text)
