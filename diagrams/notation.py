"""Textbook notation, one spelling for SVG, HTML and PDF: p₂′, ω_BC, (a_B)_A^n, (a_P4)^t.

The drawings and the handouts carry labels in a plain source spelling and typeset them here:

=====================  ==============================  ===================================
source                 meaning                         typeset
=====================  ==============================  ===================================
``p2_1``               polygon vertex p, 2, first dash  p₂′  (``_2`` → ″)
``a1``                 polygon vertex a, 1              a₁
``ω_BC`` ``omega_BC``  angular velocity of BC           ω with subscript BC
``(a_B)_A^n``          centripetal accel. of B about A  (a_B) with subscript A, superscript n
                                                        stacked over it
``(a_P4)^t``           tangential accel. of P4          (a_P4) with superscript t
``2ωv``                Coriolis                         unchanged
=====================  ==============================  ===================================

:func:`runs` splits a text into (text, 'base' | 'sub' | 'sup') runs; :func:`svg_runs` gives the
``tspan`` offsets, :func:`html` the ``<sub>``/``<sup>`` markup (the PDF is printed from the
HTML) and :func:`width` the advance width used by the label placer.  A vector's name is two
vertex names joined by :data:`JOIN` (``vector('b1', 'b')`` → b₁b), so ``b1b`` is never read
as one name.  No svgwrite here.
"""
from __future__ import annotations

import functools
import html as _html
import re

from polygons.notation import PRIMES, VERTEX

from .metrics import plain_width

#: invisible separator between two vertex names in a vector's name (never drawn)
JOIN = "\u2060"
#: sub- and superscripts are drawn this much smaller than the text
SMALL = 0.7
#: baseline shifts of sub- and superscripts, × font size (y down, as in SVG)
SHIFT = {"sub": 0.22, "sup": -0.36}

_PRIMES = PRIMES

_TOKEN = re.compile(
    # (a vertex 'a_1' is a′, a Coriolis foot, not the quantity a with subscript 1)
    r"(?P<sym>(?<![A-Za-z])(?:omega|alpha|[ωαRWNIGFT]|[va](?=_(?![123](?!\w)))))"
    r"_(?P<symsub>[A-Za-z0-9]+)"
    r"|\)_(?P<psub>[A-Za-z0-9]+)"
    r"|\^(?P<sup>n|t|slide|r)\b"
    rf"|(?<![\w/′.\-]){VERTEX}(?![\w])"
    # a space label marked by :func:`mark_labels` (O⁣2): its digits subscripted
    r"|(?P<ul>[A-Z])\u2063(?P<ud>\d+)")
#: invisible mark (never drawn) between a space label's letter and its digits: O2 → O₂
MARK = "\u2063"
_CAPS = re.compile(r"(?<![\w/′.])[A-Z][A-Za-z0-9]*(?![\w])")

Run = tuple[str, str]


def vector(frm: str, to: str) -> str:
    """The source spelling of the vector from vertex ``frm`` to vertex ``to`` ('b1' 'b' → b₁b)."""
    return f"{frm}{JOIN}{to}"


_WORD = re.compile(r"(?<![\w/′.\-])[a-z][a-z0-9_]*(?![\w])")


def join_vectors(text: str, vertices) -> str:
    """Mark vector names made of two vertex names ('b1b' → b1 :data:`JOIN` b) so they
    typeset as b₁b; ``vertices`` are the polygon's vertex names."""
    names = set(vertices)
    # the longest vertex name that begins the word and leaves a vertex name (of one length
    # only one name can begin it): a set lookup per length, not a scan of every name
    lengths = sorted({len(n) for n in names}, reverse=True)

    def repl(m):
        w = m.group(0)
        if w in names:
            return w
        for k in lengths:
            if k < len(w) and w[:k] in names and w[k:] in names:
                return vector(w[:k], w[k:])
        return w
    return _WORD.sub(repl, text)


def _spell(text: str) -> str:
    """'⟂' (missing from common fonts) as '⊥', '^2' as '²', omega/alpha as ω/α."""
    text = (text.replace("⟂", "⊥").replace("^2", "²").replace("^3", "³")
            .replace("rad/s2", "rad/s²"))
    text = re.sub(r"(?<![A-Za-z])omega_(?=[A-Z])", "ω_", text)
    return re.sub(r"(?<![A-Za-z])alpha_(?=[A-Z])", "α_", text)


def runs(text: str) -> list[Run]:
    """``text`` as typeset runs: [(text, 'base' | 'sub' | 'sup'), ...], merged and ordered."""
    text = _spell(text)
    out: list[Run] = []

    def add(s: str, kind: str) -> None:
        s = s.replace(JOIN, "").replace(MARK, "")
        if not s:
            return
        if out and out[-1][1] == kind:
            out[-1] = (out[-1][0] + s, kind)
        else:
            out.append((s, kind))

    pos = 0
    for m in _TOKEN.finditer(text):
        add(text[pos:m.start()], "base")
        if m.group("sym"):
            add(m.group("sym"), "base")
            add(m.group("symsub"), "sub")
        elif m.group("psub"):
            add(")", "base")
            add(m.group("psub"), "sub")
        elif m.group("sup"):
            out.append((m.group("sup"), "sup"))
        elif m.group("ul"):
            add(m.group("ul"), "base")
            add(m.group("ud"), "sub")
        else:
            add(m.group("vl"), "base")
            if m.group("vq"):                       # 'p_1': p′ (a Coriolis foot)
                add(_PRIMES[m.group("vq")], "base")
            else:
                add(m.group("vd"), "sub")
                if m.group("vp"):
                    add(_PRIMES[m.group("vp")], "base")
        pos = m.end()
    add(text[pos:], "base")
    return out


def stacked(rs: list[Run], i: int) -> bool:
    """True when run ``i`` is a superscript set over the subscript before it ((a_B)_A^n)."""
    return rs[i][1] == "sup" and i > 0 and rs[i - 1][1] == "sub"


def width(text: str, size: float) -> float:
    """Advance width of the typeset ``text`` at font ``size`` (mm)."""
    rs = runs(text)
    w = 0.0
    for i, (s, kind) in enumerate(rs):
        rw = plain_width(s, size * (SMALL if kind != "base" else 1.0))
        if stacked(rs, i):
            prev = plain_width(rs[i - 1][0], size * SMALL)
            w += max(0.0, rw - prev)
        else:
            w += rw
    return w


def svg_runs(text: str, size: float) -> list[tuple[str, float, float, float | None]]:
    """(text, dx, dy, font size or None) for each ``tspan`` of ``text`` drawn at ``size``.

    ``dy`` moves the baseline (relative, so each run undoes the previous shift); ``dx`` sets a
    superscript back over the subscript it stacks on.
    """
    rs = runs(text)
    out = []
    shift = 0.0
    carry = 0.0      # a stacked superscript narrower than its subscript: what follows
    for i, (s, kind) in enumerate(rs):   # starts after the subscript, not after it
        target = SHIFT.get(kind, 0.0) * size
        dx, carry = carry, 0.0
        if stacked(rs, i):
            under = plain_width(rs[i - 1][0], size * SMALL)
            dx = -under
            carry = max(0.0, under - plain_width(s, size * SMALL))
        out.append((s, round(dx, 3), round(target - shift, 3),
                    None if kind == "base" else round(size * SMALL, 3)))
        shift = target
    return out


def plain(text: str) -> str:
    """One-line Unicode spelling for titles and text outputs: p2_1 → p₂′, subscripts kept as _X."""
    sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
    out = []
    for s, kind in runs(text):
        if kind == "sub":
            out.append(s.translate(sub) if s.isdigit() else f"_{s}")
        elif kind == "sup":
            out.append({"2": "²", "3": "³"}.get(s, f"^{s}"))
        else:
            out.append(s)
    return "".join(out)


def html(text: str) -> str:
    """Escaped HTML with ``<sub>``/``<sup>``; a stacked pair is one ``span.subsup`` (style
    :data:`HTML_CSS` sets the superscript over the subscript)."""
    rs = runs(text)
    out = []
    i = 0
    while i < len(rs):
        s, kind = rs[i]
        e = _html.escape(s, quote=True)
        if kind == "sub" and i + 1 < len(rs) and stacked(rs, i + 1):
            sup = _html.escape(rs[i + 1][0], quote=True)
            out.append(f'<span class="subsup"><sub>{e}</sub><sup>{sup}</sup></span>')
            i += 2
            continue
        out.append(e if kind == "base" else f"<{kind}>{e}</{kind}>")
        i += 1
    return "".join(out)


#: CSS the pages that use :func:`html` include
HTML_CSS = (".subsup{display:inline-flex;flex-direction:column-reverse;vertical-align:-0.45em;"
            "line-height:1;font-size:0.7em}.subsup sub,.subsup sup{font-size:1em;"
            "vertical-align:baseline;line-height:1.05}")


def link_symbol(sym: str, link: str) -> str:
    """'ω', 'BC' → 'ω_BC': the angular velocity/acceleration of a named link."""
    return f"{sym}_{link}"


_BARE = re.compile(r"(?<![\w_])(ω|α)(²?) × ([A-Z][A-Z0-9]*)\b")


def name_bare_omegas(text: str, links: dict[str, str] | None = None) -> str:
    """'ω² × OA' → 'ω_OA² × OA': a bare ω or α before '× XY' is the angular velocity
    (acceleration) of the link through X and Y, named as ``links`` names it ('CB' → 'BC')."""
    links = links or {}

    def repl(m):
        name = links.get(m.group(3), m.group(3))
        return f"{m.group(1)}_{name}{m.group(2)} × {m.group(3)}"
    return _BARE.sub(repl, text)


def slot_names(text: str, scene) -> str:
    """One name per slotted lever: the pivot–pin line O4P2 is written as the lever's own
    O4P4 (P4 is the lever point under the pin P2, so the length is the same)."""
    for slot in getattr(scene, "slots", {}).values():
        if not slot.coincident:
            continue
        for a, b in ((slot.pivot, slot.pin), (slot.pin, slot.pivot)):
            new = (f"{slot.pivot}{slot.coincident}" if a == slot.pivot
                   else f"{slot.coincident}{slot.pivot}")
            text = re.sub(rf"(?<![A-Za-z0-9_]){a}{b}(?![A-Za-z0-9])", new, text)
    return text


def link_names(scene) -> dict[str, str]:
    """'AB', 'BA' (and the link's own name) → the scene's name of that link."""
    out: dict[str, str] = {}
    for name, ln in getattr(scene, "links", {}).items():
        for key in (name, f"{ln.a}{ln.b}", f"{ln.b}{ln.a}"):
            out.setdefault(key, name)
    return out


def mark_labels(text: str, labels) -> str:
    """Mark the space labels with digits in ``text`` so they typeset with subscripts (O2 →
    O₂, the link O2P2 → O₂P₂): only words made wholly of the scene's ``labels`` (so 'Q3' of
    'SAE4 Q3' stays unless Q3 is a point), never a subscript already (ω_O4P4)."""
    names, lengths, digits = _label_index(tuple(labels))
    if not digits:
        return text

    def split(w):
        """w as labels, the longest label first where more than one fits (of one length only
        one can begin a word): by a table from the end of w, not by recursion (a title word
        of thousands of capitals is user text)."""
        n = len(w)
        take = [0] * (n + 1)           # take[i]: length of the label that begins w[i:], 0: none
        fits = [False] * n + [True]    # fits[i]: w[i:] is made wholly of labels
        for i in range(n - 1, -1, -1):
            for k in lengths:
                if i + k <= n and fits[i + k] and w[i:i + k] in names:
                    take[i], fits[i] = k, True
                    break
        if not n or not fits[0]:
            return [] if not n else None
        parts, i = [], 0
        while i < n:
            parts.append(w[i:i + take[i]])
            i += take[i]
        return parts

    def repl(m):
        parts = split(m.group(0))
        if not parts or not any(ch.isdigit() for ch in m.group(0)):
            return m.group(0)
        return "".join(re.sub(r"^([A-Z])(\d+)$", rf"\1{MARK}\2", p) for p in parts)
    return _CAPS.sub(repl, text)


@functools.lru_cache(maxsize=16)
def _label_index(labels: tuple) -> tuple[frozenset, tuple[int, ...], bool]:
    """(the labels, their lengths longest first, whether any has a digit): made once per
    drawing's labels, not once per text (a large mechanism's drawing has thousands)."""
    names = frozenset(n for n in labels if n)
    return (names, tuple(sorted({len(n) for n in names}, reverse=True)),
            any(ch.isdigit() for n in names for ch in n))


def mark_drawing(drawing, labels):
    """``drawing`` carrying the scene's ``labels`` (``meta['labels']``): the SVG writer
    typesets them where its texts name them (:func:`mark_labels`); the texts themselves
    stay as written, so readers of the drawing model match plain words."""
    from dataclasses import replace as _replace
    return _replace(drawing, meta={**drawing.meta, "labels": tuple(sorted(labels))})
