"""Page composition shared by every diagram: title, drawing, legend, scale bar, caption.

Works in mm with y up (the model's convention); no svgwrite here.
"""
from __future__ import annotations

import math
from dataclasses import replace

from .labels import Box
from .model import Arrow, Drawing, Group, Segment, Text
from .scale import Scale
from .text import ASCENT, DESCENT, display, plain, width, wrap

MARGIN = 10.0
GAP = 8.0
TITLE_SIZE = 4.2
SUBTITLE_SIZE = 3.0
LEGEND_SIZE = 2.8
#: a wrapped legend row's further lines start this much (mm) to the right
LEGEND_INDENT = 3.0
#: the force drawings' legend rows are wrapped to this width (mm, typeset)
FORCE_LEGEND_MM = 70.0
CAPTION_SIZE = 3.0
SCALE_SIZE = 2.6
LINE = 1.45           # line spacing, × font size
KEY_SAMPLE = 9.0      # length (mm) of a key's sample line
PAGE_WIDTH = 277.0    # A4 landscape less 10 mm margins: the widest page a drawing takes


def arrow_head(tail, tip, length=3.0, half=1.0, open_head=False):
    """(head polygon tip-first, shaft end) for an arrow; no head for a zero-length vector."""
    dx, dy = tip[0] - tail[0], tip[1] - tail[1]
    L = math.hypot(dx, dy)
    if L < 0.05:
        return (), tip
    hl = min(length, 0.45 * L)
    hw = half * hl / length
    ux, uy = dx / L, dy / L
    bx, by = tip[0] - ux * hl, tip[1] - uy * hl
    head = ((tip[0], tip[1]), (bx - uy * hw, by + ux * hw), (bx + uy * hw, by - ux * hw))
    # a filled head hides the shaft's end; an open head must not be crossed by it
    back = 0.0 if open_head else 0.25 * hl
    return head, (bx + ux * back, by + uy * back)


def scale_bar(scale: Scale, max_len_mm: float, size: float = SCALE_SIZE,
              statement: bool = True) -> tuple[Group, float, float]:
    """A bar of whole centimetres with ticks and values, and the stated scale.

    Returns (group at origin, width, height).  Its statement text has id 'scale-statement'
    (the measuring code reads it) and the bar line has id 'scale-bar-line'.
    """
    n = int(max(2, min(10, math.floor(max_len_mm / 10.0))))
    # label every k-th centimetre so the numbers do not collide
    vals = [plain(round(i * scale.per_cm_display, 12)) for i in range(n + 1)]
    k = 1
    while any(width(v, size) + 2.0 > 10.0 * k for v in vals) and k < n:
        k += 1
    if n % k and n > k:     # end on a labelled centimetre: the last number has room too
        n -= n % k
        vals = vals[:n + 1]
    items = [Segment((0.0, 0.0), (10.0 * n, 0.0), "scalebar", cls="scale-bar-line")]
    tick_y = 1.5
    for i in range(n + 1):
        items.append(Segment((10.0 * i, 0.0), (10.0 * i, tick_y if i % k == 0 else 0.8),
                             "scalebar"))
        if i % k == 0 or i == n:
            items.append(Text(10.0 * i, tick_y + 0.8, vals[i], size, "middle",
                              role="scale"))
    # the unit after the last number, clear of it however large the numbers are set
    unit_x = 10.0 * n + max(2.0, width(vals[n], size) / 2.0 + 1.0)
    items.append(Text(unit_x, -0.4, display(scale.unit), size, role="scale"))
    text = f"Scale {scale.statement}"
    sx = unit_x + width(display(scale.unit), size) + 4.0
    if statement:
        items.append(Text(sx, -0.4, text, size + 0.4, role="scale", weight="bold",
                          ident="scale-statement"))
        w = sx + width(text, size + 0.4)
    else:      # a stage figure in a handout whose text states the scale
        w = sx - 4.0
    g = Group("scale-bar", "scale-bar", f"Scale bar: {scale.statement}", tuple(items))
    return g, w, tick_y + 0.8 + ASCENT * size + 1.5


def _text_lines(lines, size, role, x, top, weight="normal", faded=False):
    """Text items for ``lines`` starting with the first baseline below ``top`` (y up)."""
    out = []
    y = top - ASCENT * size
    for i, ln in enumerate(lines):
        w = weight[i] if isinstance(weight, (list, tuple)) else weight
        out.append(Text(x, y, ln, size, role=role, weight=w, faded=faded))
        y -= LINE * size
    return out


def compose(*, name: str, kind: str, stage: int | None, title: str, subtitle: str,
            desc: str, content: list[Group], content_box: Box, legend: list[tuple[str, str]],
            scale: Scale, caption: list[str], scale_statement: str, meta: dict,
            key: list[tuple[str, str, bool]] = (),
            legend_width: float | None = None) -> Drawing:
    """Put the drawing (``content`` inside ``content_box``, content coordinates) on a page.

    ``legend`` is a list of (text, weight); ``caption`` a list of paragraphs; ``key`` the
    line styles drawn, as (style, words, arrow?), shown as samples above the legend.
    ``legend_width`` (mm): a longer legend row is wrapped to it, measured by its typeset
    width, its further lines indented (the force drawings' rows: '−m a_G (O2P) ≈ 0 (1.13 mm
    at this scale: 2.824 N, not drawn)' widened the figure by half).
    """
    indent: list[float] = [0.0] * len(legend)
    if legend_width:
        rows, indent = [], []
        for text, weight in legend:
            for i, ln in enumerate(wrap(text, legend_width, LEGEND_SIZE) if text else [text]):
                rows.append((ln, weight))
                indent.append(LEGEND_INDENT if i else 0.0)
        legend = rows
    cw, ch = content_box.x1 - content_box.x0, content_box.y1 - content_box.y0
    key_rows = ([("Key:", "bold")] + [(w, "normal") for _, w, _ in key]) if key else []
    key_w = max([KEY_SAMPLE + 2.0 + width(t, LEGEND_SIZE) for t, _ in key_rows[1:]]
                + [width(t, LEGEND_SIZE) for t, _ in key_rows[:1]], default=0.0)
    leg_w = max((width(t, LEGEND_SIZE) + d for (t, _), d in zip(legend, indent)), default=0.0)
    row = LINE * LEGEND_SIZE
    # beside the drawing while the page stays within A4 landscape; else below it, key and
    # legend side by side
    below = bool(legend or key) and cw + GAP + max(key_w, leg_w) > PAGE_WIDTH - 2 * MARGIN
    if below:
        side_w = 0.0
        under_w = key_w + (GAP if key and legend else 0.0) + leg_w
        under_h = max(len(key_rows), len(legend)) * row + 3.0
        body_h = ch + under_h
    else:
        side_w = (GAP + max(key_w, leg_w)) if (legend or key) else 0.0
        under_w = 0.0
        body_h = max(ch, (len(key_rows) + (1 if key and legend else 0) + len(legend)) * row)
    bar, bar_w, bar_h = scale_bar(scale, max(cw, 60.0))
    title_w = max(width(title, TITLE_SIZE), width(subtitle, SUBTITLE_SIZE))
    inner_w = max(cw + side_w, under_w, bar_w, title_w, 120.0)
    cap_lines: list[str] = []
    for para in caption:
        cap_lines += wrap(para, inner_w, CAPTION_SIZE)
    title_h = LINE * TITLE_SIZE + LINE * SUBTITLE_SIZE + 3.0
    cap_h = (len(cap_lines) * LINE * CAPTION_SIZE + 3.0) if cap_lines else 0.0
    W = round(inner_w + 2 * MARGIN, 1)
    H = round(MARGIN + title_h + body_h + 4.0 + bar_h + cap_h + MARGIN, 1)

    top = H - MARGIN
    groups: list[Group] = []
    groups.append(Group("heading", "heading", "Title", tuple(
        _text_lines([title], TITLE_SIZE, "title", MARGIN, top, "bold")
        + _text_lines([subtitle], SUBTITLE_SIZE, "subtitle", MARGIN,
                      top - LINE * TITLE_SIZE))))
    body_top = top - title_h
    dx = MARGIN - content_box.x0
    dy = body_top - content_box.y1
    groups += [g.moved(dx, dy) for g in content]
    if below:
        kx, ky = MARGIN, body_top - ch - 3.0
        lx, ly = MARGIN + (key_w + GAP if key else 0.0), ky
    else:
        kx, ky = MARGIN + cw + GAP, body_top
        lx = kx
        ly = body_top - (len(key_rows) + 1) * row if key else body_top
    if key:
        items = []
        y = ky - ASCENT * LEGEND_SIZE
        for i, (text, weight) in enumerate(key_rows):
            if i >= 1:
                style, _, is_arrow = key[i - 1]
                ym = y + 0.3 * LEGEND_SIZE
                a, b = (kx, ym), (kx + KEY_SAMPLE, ym)
                if is_arrow:
                    open_head = style.startswith("c-coriolis") or style == "input-alpha"
                    head, shaft = arrow_head(a, b, 2.2, 0.8, open_head)
                    items.append(Arrow(a, b, style, head, shaft, role="key"))
                else:
                    items.append(Segment(a, b, style, cls="key-sample"))
                items.append(Text(kx + KEY_SAMPLE + 2.0, y, text, LEGEND_SIZE, role="key"))
            else:
                items.append(Text(kx, y, text, LEGEND_SIZE, role="key", weight=weight))
            y -= row
        groups.append(Group("key", "key", "Key: one line style per component", tuple(items)))
    if legend:
        items = []
        y = ly - ASCENT * LEGEND_SIZE
        for (text, weight), d in zip(legend, indent):
            items.append(Text(lx + d, y, text, LEGEND_SIZE, role="legend", weight=weight))
            y -= row
        groups.append(Group("legend", "legend", "Legend: values measured on the drawing",
                            tuple(items)))
    bar_y = body_top - body_h - 4.0 - bar_h + DESCENT * SCALE_SIZE + 1.0
    groups.append(bar.moved(MARGIN, bar_y + 1.0))
    if cap_lines:
        ctop = bar_y - 3.0
        groups.append(Group("caption", "caption", "Caption", tuple(
            _text_lines(cap_lines, CAPTION_SIZE, "caption", MARGIN, ctop))))
    meta = dict(meta)
    meta["content_offset"] = (dx, dy)
    return Drawing(name, kind, stage, W, H, title, desc, tuple(groups), scale_statement, meta)


def extent(items) -> Box | None:
    """The box (mm) the drawn ``items`` cover (recursively, text by its typeset box)."""
    from .labels import text_box
    from .model import Circle, Polyline
    xs: list[float] = []
    ys: list[float] = []

    def walk(its):
        for it in its:
            if isinstance(it, Segment):
                xs.extend((it.a[0], it.b[0]))
                ys.extend((it.a[1], it.b[1]))
            elif isinstance(it, Polyline):
                xs.extend(p[0] for p in it.points)
                ys.extend(p[1] for p in it.points)
            elif isinstance(it, Circle):
                xs.extend((it.centre[0] - it.r, it.centre[0] + it.r))
                ys.extend((it.centre[1] - it.r, it.centre[1] + it.r))
            elif isinstance(it, Arrow):
                sx, sy = getattr(it, "shift", (0.0, 0.0)) or (0.0, 0.0)
                pts = [*it.drawn, *((p[0] + sx, p[1] + sy) for p in it.head)]
                xs.extend(p[0] for p in pts)
                ys.extend(p[1] for p in pts)
            elif isinstance(it, Text):
                b = text_box(it.x, it.baseline, it.text, it.size, it.anchor)
                if it.weight == "bold":          # bold is about a tenth wider than regular
                    b = type(b)(b.x0, b.y0, b.x1 + 0.1 * (b.x1 - b.x0), b.y1)
                xs.extend((b.x0, b.x1))
                ys.extend((b.y0, b.y1))
            elif hasattr(it, "items"):
                walk(it.items)
    walk(items)
    return Box(min(xs), min(ys), max(xs), max(ys)) if xs else None


#: groups :func:`compose` puts around the drawing itself
FURNITURE = ("heading", "key", "legend", "scale-bar", "caption")


def _legend_in_two(key: Group | None, legend: Group | None, top: float, max_width: float
                   ) -> tuple[Group, Group, float] | None:
    """Key and legend below the drawing with the legend in two columns, split at one of its
    blank lines (between its sections, as 'Scaled from the drawing' | 'From the
    construction'): the first part at the left, the key over the second part at its right
    (reading order kept: the legend's parts left to right).  (key, legend, bottom) of the
    shortest such layout no wider than ``max_width``; None when the legend has no blank line
    or none fits."""
    if key is None or legend is None:
        return None
    blanks = [it.baseline for it in legend.items if isinstance(it, Text) and not it.text]
    kb = extent(key.items)
    row = LINE * LEGEND_SIZE
    best = None
    for y in blanks:
        first = [it for it in legend.items if extent([it]) is None or extent([it]).y0 > y]
        second = [it for it in legend.items if it not in first
                  and not (isinstance(it, Text) and it.baseline == y)]
        if not first or not second:
            continue
        fb, sb = extent(first), extent(second)
        x2 = MARGIN + (fb.x1 - fb.x0) + GAP
        if x2 + max(kb.x1 - kb.x0, sb.x1 - sb.x0) > max_width - MARGIN + 1e-9:
            continue
        k = key.moved(x2 - kb.x0, top - kb.y1)
        s_top = top - (kb.y1 - kb.y0) - row
        items = ([it.moved(MARGIN - fb.x0, top - fb.y1) for it in first]
                 + [it.moved(x2 - sb.x0, s_top - sb.y1) for it in second])
        bottom = min(top - (fb.y1 - fb.y0), s_top - (sb.y1 - sb.y0))
        if best is None or bottom > best[2]:
            best = (k, replace(legend, items=tuple(items)), bottom)
    return best


def _rewrapped(g: Group, max_width: float) -> Group:
    """A caption group's lines wrapped anew to ``max_width`` mm (one paragraph)."""
    texts = [it for it in g.items if isinstance(it, Text)]
    if not texts:
        return g
    first = texts[0]
    lines = wrap(" ".join(t.text for t in texts), max_width, first.size)
    return replace(g, items=tuple(replace(first, text=ln,
                                          baseline=first.baseline - i * LINE * first.size)
                                  for i, ln in enumerate(lines)))


def restack(d: Drawing, max_width: float) -> Drawing:
    """``d`` (made by :func:`compose`) no wider than ``max_width`` mm if moving its key and
    legend from beside the drawing to below it achieves that (a portrait page's width); the
    drawing itself is not touched: same scale, same positions relative to each other."""
    if d.width <= max_width + 1e-9:
        return d
    by = {g.ident: g for g in d.groups if g.ident in FURNITURE}
    content = [g for g in d.groups if g.ident not in FURNITURE]
    if not content or not ("key" in by or "legend" in by):
        return d
    old = extent(d.groups)
    drop = 0.0
    head = by.get("heading")
    hb = extent(head.items) if head is not None else None
    if hb is not None and hb.x1 > max_width - MARGIN:      # wrap the title and subtitle
        items, drop = [], 0.0
        texts = [it for it in head.items if isinstance(it, Text)]
        y = texts[0].baseline if texts else 0.0
        for i, it in enumerate(texts):
            if i:
                y -= LINE * it.size
            lines = wrap(it.text, max_width - 2 * MARGIN - (it.x - MARGIN), it.size)
            for j, ln in enumerate(lines):
                if j:
                    y -= LINE * it.size
                items.append(replace(it, text=ln, baseline=y))
        drop = y - texts[-1].baseline if texts else 0.0
        by["heading"] = replace(head, items=tuple(items))
        content = [g.moved(0.0, drop) for g in content]
        by = {k: (g if k == "heading" else g.moved(0.0, drop)) for k, g in by.items()}
    cb = extent(content)
    moved: dict[str, Group] = {}
    # the key and legend beside the drawing, moved up to it (GAP from what it draws: the
    # content box it was composed in may be wider); with the heading wrapped, narrow enough?
    beside = {n: by[n] for n in ("key", "legend")
              if n in by and extent(by[n].items).x0 > cb.x1}
    if beside:
        shift = cb.x1 + GAP - min(extent(g.items).x0 for g in beside.values())
        if shift < 0:
            moved = {n: g.moved(shift, 0.0) for n, g in beside.items()}
    if extent([*content, *(moved.get(n, g) for n, g in by.items())]).x1 + MARGIN \
            > max_width + 1e-9:
        moved = {}
        top = cb.y0 - 3.0
        x = MARGIN
        bottom = top
        for name in ("key", "legend"):
            g = by.get(name)
            if g is None:
                continue
            b = extent(g.items)
            w = b.x1 - b.x0
            if x > MARGIN and x + w > max_width - MARGIN:     # no room beside the key: below it
                x, top = MARGIN, bottom - LINE * LEGEND_SIZE
            moved[name] = g.moved(x - b.x0, top - b.y1)
            bottom = min(bottom, top - (b.y1 - b.y0))
            x += w + GAP
        split = _legend_in_two(by.get("key"), by.get("legend"), cb.y0 - 3.0, max_width)
        if split is not None and split[2] > bottom + 1e-9:    # shorter so
            moved["key"], moved["legend"], bottom = split
        below = bottom - 4.0
        for name in ("scale-bar", "caption"):
            g = by.get(name)
            if g is None:
                continue
            b = extent(g.items)
            if name == "caption" and b.x1 - b.x0 > max_width - 2 * MARGIN:   # rewrapped
                g = _rewrapped(g, max_width - 2 * MARGIN)
                b = extent(g.items)
            moved[name] = g.moved(0.0, below - b.y1)
            below -= (b.y1 - b.y0) + 3.0
    content_iter = iter(content)
    groups = [moved.get(g.ident, by[g.ident]) if g.ident in FURNITURE else next(content_iter)
              for g in d.groups]
    new = extent(groups)
    lift = old.y0 - new.y0                     # the same margin under the lowest item
    groups = [g.moved(0.0, lift) for g in groups]
    width = round(max(new.x1 + (d.width - old.x1), cb.x1 + MARGIN), 1)
    if width >= d.width:
        return d
    height = round(new.y1 + lift + (d.height - old.y1), 1)
    meta = dict(d.meta)
    if "content_offset" in meta:
        dx, dy = meta["content_offset"]
        meta["content_offset"] = (dx, dy + lift + drop)
    return replace(d, width=width, height=height, groups=tuple(groups), meta=meta)
