"""The layout rule, measured on the written SVG (nothing else): what a reader with a ruler sees.

:func:`measure` reads one SVG written by :mod:`diagrams.svg` and returns

* every drawn vector's length (mm: the tail of the shaft to the tip of the head, as the
  drawing's ``arrow`` groups hold it), and for one shorter than the rule's minimum whether it
  lies inside an inset's ring ('detail ×k': ring radius r, inset radius R) and so is also
  drawn k = R / r times larger there;
* the boxes of every text (its runs' advance widths, :mod:`diagrams.metrics`, at their sizes,
  from the anchor and the baseline) and the pairs of them that overlap by more than
  :data:`OVERLAP_MM` each way;
* the smallest text height once the drawing is printed reduced by ``reduction`` (the page's).

:func:`verdict` holds a measurement against the rule: no vector shorter than ``min_mm``
unless its inset shows it at least ``min_mm`` long, no overlapping label, no text printed
lower than ``min_text_mm``.  A vector too short to draw at any enlargement is not drawn: its
drawing says so in words ('≈ 0 (0.03 mm at this scale)'), and the audit sees no arrow.
"""
from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from .metrics import plain_width
from .text import ASCENT, DESCENT

NS = "{http://www.w3.org/2000/svg}"
#: the shortest vector a drawing may hold (mm), on the drawing or in its inset
MIN_VECTOR_MM = 3.0
#: the lowest a text may print (mm, cap-and-descender height = font size) once reduced
MIN_TEXT_MM = 2.0
#: two text boxes overlapping less than this (mm) each way touch, they do not collide: the
#: width table is DejaVu Sans's, another sans font draws a few per cent wider or narrower
OVERLAP_MM = 0.15
_TRANSLATE = re.compile(r"translate\(([0-9.eE+-]+)[ ,]+([0-9.eE+-]+)\)")

Pt = tuple[float, float]


@dataclass
class Measured:
    """What one SVG shows (mm, y down as in the file)."""
    name: str
    vectors: list = field(default_factory=list)    # (label, mm, magnified mm or None)
    texts: list = field(default_factory=list)      # (text, size, [run boxes x0 y0 x1 y1])
    overlaps: list = field(default_factory=list)   # (text, text, overlap x, overlap y)
    reduction: float = 1.0

    @property
    def shortest(self) -> float | None:
        """The shortest vector as it can be read: in its inset if it has one."""
        lens = [m if k is None else max(m, k) for _, m, k in self.vectors]
        return min(lens, default=None)

    @property
    def smallest_text(self) -> float | None:
        """The lowest text printed (mm) once the drawing is reduced."""
        return min((s * self.reduction for _, s, _ in self.texts), default=None)


def _f(v) -> float:
    return float(str(v).replace("mm", ""))


def _insets(root) -> list[tuple[Pt, float, Pt, float]]:
    """(ring centre, ring radius, inset centre, inset radius) of every inset."""
    out = []
    for g in root.iter(f"{NS}g"):
        if "inset" not in (g.get("class") or "").split():
            continue
        ring = frame = None
        for c in g.iter(f"{NS}circle"):
            cls = (c.get("class") or "").split()
            if "inset-ring" in cls:
                ring = ((_f(c.get("cx")), _f(c.get("cy"))), _f(c.get("r")))
            elif "inset-frame" in cls:
                frame = ((_f(c.get("cx")), _f(c.get("cy"))), _f(c.get("r")))
        if ring and frame and ring[1] > 0:
            out.append((ring[0], ring[1], frame[0], frame[1]))
    return out


_DESCENDERS = set("gjpqyQ(),;[]{}|µ")
_TALL = set("ABCDEFGHIJKLMNOPQRSTUVWXYZbdfhklt0123456789()[]{}|/!?%&#$@'\"ωαθΔΣ√⊥∥′″°²³")


def _ink(text: str) -> tuple[float, float]:
    """(height above the baseline, depth below it) of the ink of ``text``, × font size: a
    run of x-height letters (a, n, c) stands 0.56 high, one with a capital, a digit or an
    ascender :data:`ASCENT`; only descenders (g, p, y, brackets) go below the baseline."""
    up = ASCENT if any(ch in _TALL for ch in text) else 0.56
    down = DESCENT if any(ch in _DESCENDERS for ch in text) else 0.02
    return up, down


def _text_box(t) -> tuple[str, float, list]:
    """(text, font size, boxes) of one ``<text>``: a box for each of its runs (a sub- or
    superscript is its own box, shifted and smaller), set one after another."""
    size = _f(t.get("font-size"))
    x, y = _f(t.get("x")), _f(t.get("y"))
    runs = [((t.text or ""), size, 0.0, 0.0)]
    for s in t.iter(f"{NS}tspan"):
        dx = _f((s.get("dx") or "0").split()[0])
        dy = _f((s.get("dy") or "0").split()[0])
        runs.append((s.text or "", _f(s.get("font-size")) if s.get("font-size") else size,
                     dx, dy))
    pen, base = 0.0, 0.0
    spans = []
    for text, sz, dx, dy in runs:
        pen += dx
        base += dy
        w = plain_width(text, sz)
        if text.strip():
            up, down = _ink(text)
            spans.append((pen, base - up * sz, pen + w, base + down * sz))
        pen += w
    anchor = t.get("text-anchor") or "start"
    x0 = {"start": x, "middle": x - pen / 2, "end": x - pen}.get(anchor, x)
    text = "".join(r[0] for r in runs)
    return text, size, [(x0 + a, y + b, x0 + c, y + d) for a, b, c, d in spans]


def measure(svg: bytes | str, name: str = "", reduction: float = 1.0,
            min_mm: float = MIN_VECTOR_MM) -> Measured:
    """Read one SVG: its vectors, text boxes and their overlaps (see the module)."""
    data = svg.encode() if isinstance(svg, str) else svg
    root = ET.fromstring(data)
    out = Measured(name, reduction=reduction)
    insets = _insets(root)
    for g in root.iter(f"{NS}g"):
        cls = (g.get("class") or "").split()
        if not cls or cls[0] != "arrow" or "arc-head" in cls:
            continue                  # an arc's head (an input ω, a couple) is no vector
        shaft = next((e for e in g if e.tag == f"{NS}line"), None)
        if shaft is None:
            continue
        m = _TRANSLATE.fullmatch(g.get("transform") or "")
        sx, sy = (float(m.group(1)), float(m.group(2))) if m else (0.0, 0.0)
        tail = (_f(shaft.get("x1")) + sx, _f(shaft.get("y1")) + sy)
        head = next((e for e in g if e.tag == f"{NS}polygon"), None)
        if head is not None:
            x, y = head.get("points").split()[0].split(",")
            tip = (float(x) + sx, float(y) + sy)
        else:
            tip = (_f(shaft.get("x2")) + sx, _f(shaft.get("y2")) + sy)
        mm = math.dist(tail, tip)
        shown = None
        if mm < min_mm:
            # its vertices' middle (one drawn beside a collinear vector is moved off them)
            mid = ((tail[0] + tip[0]) / 2 - sx, (tail[1] + tip[1]) / 2 - sy)
            for c, r, _, R in insets:
                if math.dist(mid, c) <= r + 1e-6:
                    shown = max(shown or 0.0, mm * R / r)
        parent = _label_of(root, g)
        out.vectors.append((parent, round(mm, 3), None if shown is None else round(shown, 3)))
    runs = []
    for i, t in enumerate(root.iter(f"{NS}text")):
        text, size, boxes = _text_box(t)
        if boxes:
            out.texts.append((text, size, boxes))
            runs += [(b, i, text) for b in boxes]
    runs.sort(key=lambda r: r[0][0])
    seen = set()
    for j, (a, ia, ta) in enumerate(runs):          # sweep along x
        for b, ib, tb in runs[j + 1:]:
            if b[0] >= a[2]:
                break
            if ia == ib or (min(ia, ib), max(ia, ib)) in seen:
                continue
            ox = min(a[2], b[2]) - max(a[0], b[0])
            oy = min(a[3], b[3]) - max(a[1], b[1])
            if ox > OVERLAP_MM and oy > OVERLAP_MM:
                seen.add((min(ia, ib), max(ia, ib)))
                out.overlaps.append((ta, tb, round(ox, 2), round(oy, 2)))
    return out


_PARENTS: dict = {}


def _label_of(root, g) -> str:
    """The name of a vector: its enclosing group's accessible title, else its id."""
    parents = _PARENTS.get(id(root))
    if parents is None:
        parents = {c: p for p in root.iter() for c in p}
        _PARENTS.clear()
        _PARENTS[id(root)] = parents
    p = parents.get(g)
    for e in (g, p):
        if e is None:
            continue
        title = e.find(f"{NS}title")
        if title is not None and title.text:
            return title.text.split(" — ")[0]
        if e.get("id"):
            return e.get("id")
    return "?"


def verdict(m: Measured, min_mm: float = MIN_VECTOR_MM,
            min_text_mm: float = MIN_TEXT_MM) -> list[str]:
    """The breaches of the rule in ``m``, in words (empty: it holds)."""
    out = []
    for label, mm, shown in m.vectors:
        if mm < min_mm - 1e-6 and (shown is None or shown < min_mm - 1e-6):
            where = "" if shown is None else f", {shown:.2f} mm in its inset"
            out.append(f"{m.name}: vector {label} drawn {mm:.2f} mm{where} (< {min_mm:g} mm)")
    for a, b, ox, oy in m.overlaps:
        out.append(f"{m.name}: labels {a!r} and {b!r} overlap {ox:.2f} × {oy:.2f} mm")
    low = m.smallest_text
    if low is not None and low < min_text_mm - 1e-6:
        worst = min(m.texts, key=lambda r: r[1])
        out.append(f"{m.name}: text {worst[0]!r} prints {low:.2f} mm high "
                   f"(reduced ×{m.reduction:.2f}; < {min_text_mm:g} mm)")
    return out
