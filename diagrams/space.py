"""The space diagram: the mechanism at the instant solved, to a round scale.

Positions come from ``Solution.placement.points`` and the scene (guides, slots, body points);
nothing is computed here but where the symbols go.  Links are heavy lines, pins open circles,
fixed pivots carry a hatched ground symbol, sliders a block between hatched guides, slotted
levers an open slot around the pin, and the input crank an arc arrow with its sense (ω, and
α dashed with an open head when given).  Point labels are upper case, as in the tutorial.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from polygons.evaluate import Solution, link_ends
from polygons.contacts import wheel_of
from polygons.scene import Crank
from polygons.model import BUILT, check_handles

from . import scale as scales
from .labels import Box, Placer, bounds, clip_line, largest_gap_direction
from .layout import arrow_head, compose
from .model import Arrow, Circle, Drawing, Group, Polyline, Segment, Text
from .text import display, number, token
from .notation import mark_drawing

Pt = tuple[float, float]
LABEL_SIZE = 3.8
NOTE_SIZE = 2.8
PIN_R = 1.1
PAD_MM = 30.0            # room (mm) around the mechanism for symbols and labels


#: the kinds of body and pair the space diagram draws (polygons.model)
HANDLES = BUILT

def _add(p, q, k=1.0):
    return (p[0] + k * q[0], p[1] + k * q[1])


def _unit(v):
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n) if n else (1.0, 0.0)


def _rot(v, ang):
    c, s = math.cos(ang), math.sin(ang)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def _r(p):
    return (round(p[0], 3), round(p[1], 3))


def _hatch(a: Pt, b: Pt, side: Pt, step=2.0, length=1.6):
    """Short 45° strokes on ``side`` of the ground line a–b (the 'fixed' symbol)."""
    L = math.hypot(b[0] - a[0], b[1] - a[1])
    u = _unit((b[0] - a[0], b[1] - a[1]))
    n = int(L // step)
    out = []
    slant = _unit(_add(side, u, -1.0))
    for i in range(n + 1):
        p = _add(a, u, i * L / max(n, 1))
        out.append(Segment(_r(p), _r(_add(p, slant, length)), "hatch"))
    return out


@dataclass(frozen=True)
class _Auxiliary:
    """A construction point a group draws on the space diagram: s where ob·b and oc·c
    produced meet (a class-III group's Assur point S)."""
    s: str
    ob: str
    b: str
    oc: str
    c: str


def _triads(sol: Solution) -> list:
    """The auxiliary points of the solution's groups (each group says its own: a class-III
    group's Assur point S)."""
    return [_Auxiliary(s, ob, b, oc, c) for d in sol.plan.dyads
            for s, (ob, b), (oc, c) in getattr(d, "auxiliary_points", tuple)()]


#: the fixed link between pivots is listed pair by pair up to this many pivots (beyond it,
#: pivot to next pivot in the scene's order)
MAX_FIXED_PAIRS = 3


def fixed_links(scene) -> list[str]:
    """The fixed link (the frame) as the books give it: 'AD = 1000 mm (fixed link)' between
    the fixed pivots, so that a four-bar's fourth link is listed with the other three."""
    g = list(scene.ground.items())
    named = {frozenset((ln.a, ln.b)) for ln in scene.model.links()}
    pairs = ([(g[i], g[j]) for i in range(len(g)) for j in range(i + 1, len(g))]
             if len(g) <= MAX_FIXED_PAIRS else list(zip(g, g[1:])))
    out = []
    for (a, pa), (b, pb) in pairs:
        if frozenset((a, b)) in named:
            continue
        out.append(f"{a}{b} = {number(math.dist(pa, pb) * 1000)} mm (fixed link)")
    return out


def rolling_wheels(scene) -> dict:
    """The wheels rolling on the fixed ground, by centre: each is solved as its equivalent
    slider (the centre on a line parallel to the ground) but drawn and listed as a wheel."""
    return {q.at: q for q in scene.equivalents
            if q.kind == "rolling" and not (q.on or q.opposite)}


def space_layout(sol: Solution, scale: scales.Scale | None = None, paper: str | None = None):
    check_handles("the space diagram", HANDLES, sol.scene.model, sol.scene.file)
    scene = sol.scene
    wheels = rolling_wheels(scene)
    pos = {k: tuple(v) for k, v in sol.placement.points.items()}
    from . import rolling           # a wheel on a moving surface (placed by no-slip)
    from . import cam_profile       # a cam stated by its profile: the whole outline
    triads = _triads(sol)
    aux = {t.s for t in triads}
    bb = bounds([p for lab, p in pos.items() if lab not in aux] + rolling.extent(sol)
                + cam_profile.extent(sol))
    far = set()
    for lab in aux:     # the Assur point S: drawn when near, else said (at infinity: AB ∥ DC)
        if lab in pos:
            grown = bounds([(bb.x0, bb.y0), (bb.x1, bb.y1), pos[lab]])
            if (grown.x1 - grown.x0) + (grown.y1 - grown.y0) > \
                    2.0 * ((bb.x1 - bb.x0) + (bb.y1 - bb.y0)):
                far.add(lab)
            else:
                bb = grown
    extent = (bb.x1 - bb.x0, bb.y1 - bb.y0)
    if scale is None:
        scale = scales.choose("length", extent, [], paper, pad_mm=PAD_MM)
    scales.check_size(scale, extent, "space")
    k = scale.mm_per_si
    P = {lab: (round((p[0] - bb.x0) * k, 3), round((p[1] - bb.y0) * k, 3))
         for lab, p in pos.items()}
    frame = Box(-15.0, -15.0, extent[0] * k + 15.0, extent[1] * k + 15.0)
    placer = Placer(frame=frame, soft_cost=8.0)
    back, links, symbols, pins, inputs = [], [], [], [], []
    neighbours: dict[str, list[Pt]] = {lab: [] for lab in P}

    def link(a: Pt, b: Pt, style="link", cls=""):
        links.append(Segment(_r(a), _r(b), style, cls=cls))
        placer.hard(a, b, 1.0)

    # line of centres between the fixed pivots
    ground = [g for g in scene.ground if g in P]
    if len(ground) >= 2:
        back.append(Segment(P[ground[0]], P[ground[1]], "centre", cls="line-of-centres"))
        placer.soft(P[ground[0]], P[ground[1]])

    # slotted levers
    slotted = set()
    # a bar bearing on a fixed circle is drawn as the bar (its slot is only the equivalent)
    bearing = {q.at for q in scene.equivalents if q.kind == "bearing"}
    # a cam stated by its profile: its slot (a straight flank's equivalent) is cut in the
    # cam's plate, drawn by cam_profile: no lever bar; its crank end K a point of the plate
    cam_lever = (scene.driver.link if scene.extra.get("cam_profiles")
                 and isinstance(scene.driver, Crank) else None)
    face_arms = {q.arm for q in scene.equivalents if q.kind == "flat-faced cam" and q.arm}
    for slot in scene.model.slots() + scene.model.crossings():
        pivot, lever = slot.line.origin, slot.carrier
        if slot.at not in P or pivot not in P or slot.at in bearing:
            continue
        piv, pin = P[pivot], P[slot.at]
        e = _unit((pin[0] - piv[0], pin[1] - piv[1]))
        off = 0.0
        if slot.line.offset and slot.along_lever and slot.far in P and P[slot.far] != piv:
            # an offset slot: along its own line, ∥ pivot → far end
            e = _unit((P[slot.far][0] - piv[0], P[slot.far][1] - piv[1]))
            off = slot.line.offset * k          # its offset to the left of pivot → far
        n = (-e[1], e[0])
        end = P[slot.far] if slot.far and slot.far in P else _add(pin, e, 12.0)
        s0, s1 = _add(pin, e, -9.0), _add(pin, e, 9.0)
        foot = _add(piv, n, off)                # the slot line's foot of the pivot
        far_off = _add(end, n, off)             # … and of the far end
        if lever == cam_lever:
            pass
        elif lever in face_arms:    # a flat face's equivalent slot: the face is the arm
            link(piv, end, cls=f"link {lever}")
        elif abs(off) > 0.05:       # an offset slot: the lever bent to carry it
            link(piv, foot, cls=f"link {lever}")
            if (s0[0] - foot[0]) * e[0] + (s0[1] - foot[1]) * e[1] > 0.0:
                link(foot, s0, cls=f"link {lever}")
            if (far_off[0] - s1[0]) * e[0] + (far_off[1] - s1[1]) * e[1] > 0.0:
                link(s1, far_off, cls=f"link {lever}")
            link(far_off, end, cls=f"link {lever}")
        else:
            link(piv, s0, cls=f"link {lever}")
            if math.hypot(end[0] - s1[0], end[1] - s1[1]) > 0.5 and \
                    (end[0] - pin[0]) * e[0] + (end[1] - pin[1]) * e[1] > 9.0:
                link(s1, end, cls=f"link {lever}")
        w = 1.9
        outline = (_add(s0, n, w), _add(s1, n, w), _add(s1, n, -w), _add(s0, n, -w))
        links.append(Polyline(tuple(_r(p) for p in outline), "slot", closed=True,
                              cls=f"slot {lever}"))
        for p, q in zip(outline, outline[1:] + outline[:1]):
            placer.hard(p, q, 0.6)
        blk = (_add(_add(pin, e, -2.6), n, 1.5), _add(_add(pin, e, 2.6), n, 1.5),
               _add(_add(pin, e, 2.6), n, -1.5), _add(_add(pin, e, -2.6), n, -1.5))
        symbols.append(Polyline(tuple(_r(p) for p in blk), "block", closed=True,
                                cls="slot-block"))
        slotted.add(lever)
        neighbours[pivot].append(pin)
        neighbours[slot.at] += [piv, end]
        if slot.coincident in neighbours:
            neighbours[slot.coincident] += [piv, end]
        if slot.far and slot.far in neighbours:
            neighbours[slot.far].append(piv)

    # collars: a block driven along its link (a prescribed slide, the second input)
    for collar in scene.model.collars():
        o, t = collar.line.origin, collar.line.toward
        if collar.at not in P or o not in P or t not in P:
            continue
        c = P[collar.at]
        e = _unit((P[t][0] - P[o][0], P[t][1] - P[o][1]))
        n = (-e[1], e[0])
        blk = tuple(_add(_add(c, e, sx * 3.2), n, sy * 2.2)
                    for sx, sy in ((-1, 1), (1, 1), (1, -1), (-1, -1)))
        symbols.append(Polyline(tuple(_r(p) for p in blk), "block", closed=True,
                                cls="collar-block"))
        for p, q in zip(blk, blk[1:] + blk[:1]):
            placer.hard(p, q, 0.4)

    # binary links (a cam's or curved slot's equivalent link dashed, its arcs drawn thin:
    # polygons.contacts)
    equivalent = {q.link: q for q in scene.equivalents if q.kind in ("cam", "curved slot")}
    eq_notes = []
    b_, n_ = cam_profile.space_items(
        sol, lambda p: (round((p[0] - bb.x0) * k, 3), round((p[1] - bb.y0) * k, 3)), k, placer)
    back += b_
    eq_notes += n_
    for q in scene.equivalents:
        if q.kind == "rolling" and (q.on or q.opposite):
            b_, l_, n_ = rolling.space_items(
                sol, q, lambda p: (round((p[0] - bb.x0) * k, 3), round((p[1] - bb.y0) * k, 3)),
                k, placer)
            back += b_
            links += l_
            eq_notes += n_
            continue
        if q.centre not in P or q.at not in P:
            continue
        c, at = P[q.centre], P[q.at]
        if q.kind == "rolling":   # the wheel, the surface under it, the contact (instant centre)
            e = (math.cos(q.face), math.sin(q.face))
            rad = q.radius * k
            I = (c[0] + rad * e[1], c[1] - rad * e[0])
            back.append(Circle(_r(c), round(rad, 3), "link-thin", cls="wheel"))
            placer.rim(c, rad)                   # no note or label across the wheel's rim
            s1, s2 = _add(I, e, -rad * 1.1), _add(I, e, rad * 1.1)
            back.append(Segment(_r(s1), _r(s2), "ground", cls="rolling-surface"))
            back += _hatch(s1, s2, _unit((I[0] - c[0], I[1] - c[1])))
            placer.hard(s1, s2, 1.0)
            placer.hard(_add(s1, _unit((I[0] - c[0], I[1] - c[1])), 0.9),
                        _add(s2, _unit((I[0] - c[0], I[1] - c[1])), 0.9), 1.1)
            back.append(Circle(_r(I), 0.6, "vertex", cls="instant-centre"))
            eq_notes.append((f"I: instant centre of wheel {q.at}", _add(I, e, -rad * 0.9)))
            b_, n_ = rolling.rim_items(
                sol, q, lambda p: (round((p[0] - bb.x0) * k, 3), round((p[1] - bb.y0) * k, 3)))
            back += b_
            eq_notes += n_
            continue
        if q.kind == "bearing":   # the fixed circle the bar leans on
            back.append(Circle(_r(c), round(q.radius * k, 3), "link-thin", cls="cylinder"))
            eq_notes.append((f"fixed circle about {q.centre} (equivalent: {q.centre} in a "
                             f"slot ∥ {q.link})", _add(c, (0.0, -1.0), q.radius * k)))
            continue
        if q.link is None:        # a flat face: the yoke's slot through the centre stands for it
            eq_notes.append((f"flat face ≡ slot through {q.centre} (equivalent)", c))
            continue
        # the slot's or the profile's arc about the centre of curvature, ±30° about the contact
        th = math.atan2(at[1] - c[1], at[0] - c[0])
        # (a slot: its two sides, 1.5 mm of paper either side of the pin's path)
        for rad in ((q.radius * k - 1.5, q.radius * k + 1.5) if q.kind == "curved slot"
                    else (q.radius * k,)):
            arc = tuple(_r((c[0] + rad * math.cos(th + math.radians(t)),
                            c[1] + rad * math.sin(th + math.radians(t))))
                        for t in range(-20, 21, 2))
            back.append(Polyline(arc, "slot", cls="contact-arc"))
        if q.roller:
            back.append(Circle(_r(at), round(q.roller * k, 3), "slot", cls="roller"))
    for ln in scene.model.links():
        name = ln.name
        if name in slotted or ln.a not in P or ln.b not in P:
            continue
        if name in equivalent:
            links.append(Segment(_r(P[ln.a]), _r(P[ln.b]), "equivalent",
                                 cls=f"link {name} equivalent"))
            placer.hard(P[ln.a], P[ln.b], 1.0)
            eq_notes.append((f"equivalent link {name}", (
                (P[ln.a][0] + P[ln.b][0]) / 2, (P[ln.a][1] + P[ln.b][1]) / 2)))
            continue
        link(P[ln.a], P[ln.b], cls=f"link {name}")
        neighbours[ln.a].append(P[ln.b])
        neighbours[ln.b].append(P[ln.a])

    # a class-III group's auxiliary point S, where AB and DC produced meet (its velocity and
    # acceleration polygons are drawn through it): the lines produced dashed, S marked
    for t in triads:
        if t.s not in P:
            continue
        if t.s in far:
            mid = P[t.b] if t.b in P else None
            if mid is not None:
                eq_notes.append((f"{t.s} (where {t.ob}{t.b} and {t.oc}{t.c} produced meet) is "
                                 f"off the drawing: the lines are nearly parallel", mid))
            continue
        sp = P[t.s]
        for a_, b_ in ((t.ob, t.b), (t.oc, t.c)):
            if a_ not in P or b_ not in P:
                continue
            pa, pb = P[a_], P[b_]
            ab = (pb[0] - pa[0], pb[1] - pa[1])
            L2 = ab[0] ** 2 + ab[1] ** 2
            u = ((sp[0] - pa[0]) * ab[0] + (sp[1] - pa[1]) * ab[1]) / L2 if L2 else 0.5
            if u > 1.0 or u < 0.0:          # S beyond an end: the link produced to it
                end = pb if u > 1.0 else pa
                back.append(Segment(_r(end), _r(sp), "construction", cls=f"produced {a_}{b_}"))
                placer.soft(end, sp)
        back.append(Circle(_r(sp), 0.7, "vertex", cls=f"auxiliary-point at-{t.s}"))
        placer.block(Box(sp[0] - 0.8, sp[1] - 0.8, sp[0] + 0.8, sp[1] + 0.8))
        eq_notes.append((f"{t.s}: {t.ob}{t.b} and {t.oc}{t.c} produced meet (auxiliary point)",
                         sp))

    # points rigid with a link: continuation or plate
    for lab, bp in scene.model.points.items():
        if lab not in P:
            continue
        try:
            a, b = link_ends(scene, bp.link)
        except KeyError:
            continue
        if a not in P or b not in P:
            continue
        pa, pb, px = P[a], P[b], P[lab]
        ab = (pb[0] - pa[0], pb[1] - pa[1])
        L2 = ab[0] ** 2 + ab[1] ** 2
        off = (abs(ab[0] * (px[1] - pa[1]) - ab[1] * (px[0] - pa[0])) / math.sqrt(L2)
               if L2 > 0.0 else math.inf)      # a link too short to draw: no continuation
        if off < 0.05:
            t = ((px[0] - pa[0]) * ab[0] + (px[1] - pa[1]) * ab[1]) / L2
            if t > 1:
                link(pb, px, cls=f"link {bp.link}")
                neighbours[b].append(px)
                neighbours[lab].append(pb)
            elif t < 0:
                link(pa, px, cls=f"link {bp.link}")
                neighbours[a].append(px)
                neighbours[lab].append(pa)
            else:
                neighbours[lab] += [pa, pb]
        else:
            links.append(Polyline((pa, pb, px), "plate", closed=True, cls=f"plate {bp.link}"))
            placer.hard(pa, px, 1.0)
            placer.hard(pb, px, 1.0)
            neighbours[lab] += [pa, pb]
            neighbours[a].append(px)
            neighbours[b].append(px)

    # slider guides and blocks (a wheel rolling on the fixed ground is drawn as a wheel on a
    # hatched ground, not as its equivalent slider: its centre is a pin)
    for lab, guide in scene.model.guide.items():
        if lab not in P or lab in wheels:
            continue
        c = P[lab]
        e = guide.line.direction
        n = (-e[1], e[0])
        path = clip_line(c, e, frame)
        if path:
            back.append(Segment(_r(path[0]), _r(path[1]), "guide-path", cls="guide-path"))
            placer.soft(*path)
        hw, hh, L = 5.5, 3.2, 17.0
        for side in (1, -1):
            a = _add(_add(c, e, -L), n, side * (hh + 0.2))
            b = _add(_add(c, e, L), n, side * (hh + 0.2))
            symbols.append(Segment(_r(a), _r(b), "ground", cls="guide"))
            symbols += _hatch(a, b, (n[0] * side, n[1] * side))
            placer.hard(a, b, 0.4)
            # the hatching: its strokes lean back past a (towards −e) by 1.6/√2
            placer.hard(_add(_add(a, n, side * 0.9), e, -1.4), _add(b, n, side * 0.9), 1.1)
        yoke = next((y for y in scene.model.yoke_slots() if y.carrier == lab), None)
        pin = yoke.at if yoke is not None else None
        sd = yoke.line.direction if yoke is not None else None
        if pin and sd and pin in P:      # a yoke: the slider carries a straight slot
            q = P[pin]
            t = (q[0] - c[0]) * sd[0] + (q[1] - c[1]) * sd[1]
            lo, hi = min(0.0, t) - 8.0, max(0.0, t) + 8.0
            sn = (-sd[1], sd[0])
            w = 1.9
            outline = (_add(_add(c, sd, lo), sn, w), _add(_add(c, sd, hi), sn, w),
                       _add(_add(c, sd, hi), sn, -w), _add(_add(c, sd, lo), sn, -w))
            links.append(Polyline(tuple(_r(p) for p in outline), "slot", closed=True,
                                  cls=f"slot yoke {lab}"))
            for p0, p1 in zip(outline, outline[1:] + outline[:1]):
                placer.hard(p0, p1, 0.6)
            pb = (_add(_add(q, sd, -2.6), sn, 1.5), _add(_add(q, sd, 2.6), sn, 1.5),
                  _add(_add(q, sd, 2.6), sn, -1.5), _add(_add(q, sd, -2.6), sn, -1.5))
            symbols.append(Polyline(tuple(_r(p) for p in pb), "block", closed=True,
                                    cls="slot-block"))
            neighbours[pin] += [_add(c, sd, lo), _add(c, sd, hi)]
            neighbours[lab] += [q]
        blk = (_add(_add(c, e, -hw), n, hh), _add(_add(c, e, hw), n, hh),
               _add(_add(c, e, hw), n, -hh), _add(_add(c, e, -hw), n, -hh))
        symbols.append(Polyline(tuple(_r(p) for p in blk), "block", closed=True,
                                cls=f"slider {lab}"))
        placer.block(bounds(blk))
        neighbours[lab] += [_add(c, e, L), _add(c, e, -L)]

    # fixed pivots: triangle and hatched base, away from the links
    for gl in scene.ground:
        if gl not in P:
            continue
        p = P[gl]
        d = largest_gap_direction(p, neighbours.get(gl, []))
        u = (math.cos(d), math.sin(d)) if d is not None else (0.0, -1.0)
        if d is not None and len(neighbours.get(gl, [])) == 1:
            u = (0.0, -1.0) if abs(u[0]) < 0.9 or True else u
            nb = neighbours[gl][0]
            v = _unit((nb[0] - p[0], nb[1] - p[1]))
            if v[1] < -0.7:     # link goes down: put the ground up or to the side
                u = _unit((-v[0], -v[1]))
        n = (-u[1], u[0])
        base = _add(p, u, 5.0)
        tri = (_add(p, u, PIN_R), _add(base, n, 3.0), _add(base, n, -3.0))
        symbols.append(Polyline(tuple(_r(q) for q in tri), "ground", closed=True,
                                cls=f"ground {gl}"))
        a, b = _add(base, n, -4.5), _add(base, n, 4.5)
        symbols.append(Segment(_r(a), _r(b), "ground", cls="ground-base"))
        symbols += _hatch(a, b, u)
        placer.block(bounds([p, _add(base, n, 4.5), _add(base, n, -4.5),
                             _add(_add(base, u, 1.8), n, 4.5), _add(_add(base, u, 1.8), n, -4.5)])
                     .grown(1.0))
        neighbours[gl].append(_add(p, u, 6.0))

    # pins (one per place) and labels
    groups: list[list[str]] = []
    for lab in scene.labels:
        if lab not in P or lab in aux:
            continue
        for gr in groups:
            q = P[gr[0]]
            if math.hypot(P[lab][0] - q[0], P[lab][1] - q[1]) < 0.3:
                gr.append(lab)
                break
        else:
            groups.append([lab])
    body = set(scene.model.points)
    for gr in groups:
        p = P[gr[0]]
        at = " ".join(f"at-{token(lab)}" for lab in gr)
        if all(lab in body for lab in gr) or (cam_lever is not None and gr == [
                scene.model.named[cam_lever].b] and cam_lever in slotted):
            pins.append(Circle(p, 0.7, "vertex", cls=f"point {at}",
                               ident=f"space-point-{token(gr[0])}"))
        else:
            pins.append(Circle(p, PIN_R, "pin", cls=f"point pin {at}",
                               ident=f"space-point-{token(gr[0])}"))
        placer.block(Box(p[0] - PIN_R, p[1] - PIN_R, p[0] + PIN_R, p[1] + PIN_R))

    # the input: arc arrows for a crank, straight arrows beside a driven slider
    drv = scene.driver
    notes = []
    def arc_inputs(c, L, mid, arcs):
        """Arc arrows about ``c`` (ω, then α outside it) centred on the direction ``mid``."""
        for i, (val, sym, unit, style, open_head) in enumerate(arcs):
            R = max(5.5, min(0.5 * L, 13.0)) + 3.2 * i
            sgn = 1.0 if val >= 0 else -1.0
            span = math.radians(110)
            angs = [mid - sgn * span / 2 + sgn * span * j / 24 for j in range(25)]
            pts = [(c[0] + R * math.cos(a), c[1] + R * math.sin(a)) for a in angs]
            tip = pts[-1]
            tang = (-math.sin(angs[-1]) * sgn, math.cos(angs[-1]) * sgn)
            tail = _add(tip, tang, -3.0)
            head, _ = arrow_head(tail, tip, 2.6, 1.0, open_head)
            inputs.append(Polyline(tuple(_r(q) for q in pts[:-2]), style,
                                   cls=f"input-arc {sym}"))
            inputs.append(Arrow(_r(tail), _r(tip), style, tuple(_r(q) for q in head), _r(tail),
                                role="arc", title=f"{sym} {'CCW' if val > 0 else 'CW'}"))
            for q0, q1 in zip(pts, pts[1:]):
                placer.hard(q0, q1, 0.5)
            placer.hard(tail, tip, 0.8)          # the arrow itself, head included
            text = f"{sym} = {number(abs(val))} {unit} {'CCW' if val > 0 else 'CW'}"
            notes.append((text, [tip, pts[12], pts[0]],
                          math.atan2(tip[1] - c[1], tip[0] - c[0])))

    rod = getattr(drv, "rod_rate", None)
    if isinstance(drv, Crank) and drv.pivot in P and drv.tip in P:
        c = P[drv.pivot]
        L = math.hypot(P[drv.tip][0] - c[0], P[drv.tip][1] - c[1])
        arcs = [(drv.omega, "ω", "rad/s", "input", False)]
        if drv.alpha:
            arcs.append((drv.alpha, "α", "rad/s²", "input-alpha", True))
        arc_inputs(c, L, drv.angle, arcs)
    elif rod is not None:   # the book gives the rod's ω and α: arcs about its middle (the
        name, w, al = rod   # slider's v and a are answers then, not drawn)
        a, b = next(((ln.a, ln.b) for ln in scene.model.links()
                     if name in (ln.a + ln.b, ln.b + ln.a)), (None, None))
        if a in P and b in P:
            c = ((P[a][0] + P[b][0]) / 2, (P[a][1] + P[b][1]) / 2)
            L = math.hypot(P[b][0] - P[a][0], P[b][1] - P[a][1])
            arcs = [(w, "ω", "rad/s", "input", False)]
            if al:
                arcs.append((al, "α", "rad/s²", "input-alpha", True))
            arc_inputs(c, 0.5 * L, math.atan2(P[b][1] - P[a][1], P[b][0] - P[a][0])
                       + math.pi / 2, arcs)
    elif not isinstance(drv, Crank) and drv.point in P:
        c = P[drv.point]
        e = scene.model.guide[drv.point].line.direction
        n = (-e[1], e[0])
        for i, (val, sym, unit, style) in enumerate(
                [(drv.velocity, "v", "m/s", "input"), (drv.acceleration, "a", "m/s²",
                                                       "input-alpha")]):
            if val == 0 and sym == "a":
                continue
            sgn = 1.0 if val >= 0 else -1.0
            base = _add(c, n, 9.0 + 4.0 * i)
            tail, tip = _add(base, e, -6.0 * sgn), _add(base, e, 6.0 * sgn)
            head, shaft = arrow_head(tail, tip, 2.6, 1.0, sym == "a")
            inputs.append(Arrow(_r(tail), _r(tip), style, tuple(_r(q) for q in head),
                                _r(shaft), role="input", title=f"{sym} of {drv.point}"))
            placer.hard(tail, tip, 0.8)
            notes.append((f"{sym}_{drv.point} = {number(abs(val))} {unit}", [tip, tail],
                          math.atan2(n[1], n[0])))

    labels = []
    for gr in groups:
        p = P[gr[0]]
        text = ", ".join(gr)
        prefer = largest_gap_direction(p, neighbours.get(gr[0], []))
        x, base, _, box = placer.place(text, p, LABEL_SIZE, prefer=prefer,
                                       distances=(1.5, 2.5, 3.5, 5.0, 7.0, 10.0))
        labels.append(Text(x, base, text, LABEL_SIZE, role="point", weight="bold",
                           cls="point-label"))
    for text, at in eq_notes:      # beside the equivalent link's middle (or the yoke's pin)
        notes.append((text, [at], None))
    for text, anchors, prefer in notes:
        dirs = [2 * math.pi * k / 24 for k in range(24)]
        x, base, _, box = placer.place_any(display(text), NOTE_SIZE,
                                           [(a, dirs) for a in anchors], prefer=prefer,
                                           distances=(0.8, 1.5, 2.5, 4.0, 6.0, 9.0))
        labels.append(Text(x, base, display(text), NOTE_SIZE, role="input", cls="input-label"))

    content = [Group("space-background", "centre-lines", "Centre lines and guide paths",
                     tuple(back)),
               Group("space-links", "links", "Links", tuple(links)),
               Group("space-symbols", "symbols", "Fixed pivots, guides and sliders",
                     tuple(symbols)),
               Group("space-pins", "pins", "Pins and points", tuple(pins)),
               Group("space-input", "input", "Input motion", tuple(inputs)),
               Group("space-labels", "labels", "Labels", tuple(labels))]
    box = frame
    for g in content:
        for it in g.items:
            if isinstance(it, Circle) and it.cls in ("wheel", "cylinder"):   # contacts
                c, rr = it.centre, it.r
                box = box.union(Box(c[0] - rr, c[1] - rr, c[0] + rr, c[1] + rr))
            if isinstance(it, Text):
                from .labels import text_box
                box = box.union(text_box(it.x, it.baseline, it.text, it.size))
    return content, box.grown(1.0), scale, placer


def drawing(sol: Solution, scale: scales.Scale | None = None, paper: str | None = None
            ) -> Drawing:
    scene = sol.scene
    content, box, sc, _ = space_layout(sol, scale, paper)
    legend = [("Links:", "bold")]
    for ln in scene.model.links():
        if ln.a in sol.placement.points and ln.b in sol.placement.points:
            legend.append((f"{ln.name} = {number(ln.length * 1000)} mm", "normal"))
    legend += [(text, "normal") for text in fixed_links(scene)]
    for slot in scene.model.slots() + scene.model.crossings():
        legend.append((f"{slot.at} slides in the slot of {slot.carrier} "
                       f"(pivot {slot.line.origin})", "normal"))
    wheels = rolling_wheels(scene)
    for lab, g in scene.model.guide.items():
        if lab in wheels:
            legend.append((f"wheel {lab}: radius {number(wheels[lab].radius * 1000)} mm, rolls "
                           f"without slipping on the fixed ground", "normal"))
            continue
        legend.append((f"{lab} slides on a guide at {number(math.degrees(g.line.angle), 4)}°",
                       "normal"))
    for collar in scene.model.collars():
        legend.append((f"collar {collar.at} slides along {collar.carrier}", "normal"))
    drv = scene.driver
    legend.append(("", "normal"))
    legend.append(("Input:", "bold"))
    if isinstance(drv, Crank):
        legend.append((f"crank {drv.link} at {number(math.degrees(drv.angle), 4)}°, "
                       f"ω = {number(abs(drv.omega))} rad/s {'CCW' if drv.omega > 0 else 'CW'}",
                       "normal"))
        if drv.alpha:
            legend.append((f"α = {number(abs(drv.alpha))} rad/s² "
                           f"{'CCW' if drv.alpha > 0 else 'CW'}", "normal"))
    elif scene.model.body(drv.point).kind == "wheel":    # a driven rolling wheel
        r = wheel_of(scene, drv.point).radius
        w, al = -drv.velocity / r, -drv.acceleration / r
        legend.append((f"wheel {drv.point} rolling: ω = {number(abs(w))} rad/s "
                       f"{'CCW' if w > 0 else 'CW' if w < 0 else ''}, α = {number(abs(al))} "
                       f"rad/s² {'CCW' if al > 0 else 'CW' if al < 0 else ''}".rstrip(),
                       "normal"))
    else:
        if drv.rod_rate is not None:                 # the book gives the rod's ω and α
            rod, w, al = drv.rod_rate
            legend.append((f"rod {rod}: ω = {number(abs(w))} rad/s "
                           f"{'CCW' if w > 0 else 'CW' if w < 0 else ''}, α = "
                           f"{number(abs(al))} rad/s² "
                           f"{'CCW' if al > 0 else 'CW' if al < 0 else ''}".rstrip(), "normal"))
        else:
            legend.append((f"slider {drv.point}: v = {number(drv.velocity)} m/s, "
                           f"a = {number(drv.acceleration)} m/s² along its guide", "normal"))
    for point, sl in scene.model.prescribed.items():      # the second input's values
        legend.append((f"collar {point}: {number(sl.position * 1000)} mm from "
                       f"{sl.p}, ṡ = {number(sl.velocity)} m/s, s̈ = "
                       f"{number(sl.acceleration)} m/s² along {sl.link}", "normal"))
    sid = scene.source.get("id", "")
    subtitle = f"{sid}: {scene.title}" if sid else scene.title
    desc = (f"Space diagram of {scene.title} at the instant solved, drawn to scale "
            f"{sc.statement}. Points: " +
            ", ".join(f"{lab} ({number(p[0] * 1000)} mm, {number(p[1] * 1000)} mm)"
                      for lab, p in sol.placement.points.items()) + ".")
    key = [("link", "link (rigid body)", False)]
    if any(q.kind in ("cam", "curved slot") for q in scene.equivalents):
        key.append(("equivalent", "equivalent link (this instant)", False))
        key.append(("slot", "curved slot / cam profile at the contact", False))
    if len(scene.ground) >= 2:
        key.append(("centre", "line of centres", False))
    if any(lab not in wheels for lab in scene.model.guide):
        key.append(("guide-path", "guide path of a slider", False))
    if isinstance(drv, Crank) or getattr(drv, "rod_rate", None) is not None:
        key.append(("input", "input ω (sense of rotation)", True))
        if drv.alpha if isinstance(drv, Crank) else drv.rod_rate[2]:
            key.append(("input-alpha", "input α (open head)", True))
    else:
        key.append(("input", "input velocity of the slider", True))
        if drv.acceleration:
            key.append(("input-alpha", "input acceleration (open head)", True))
    page = compose(name="space", kind="space", stage=None, title="Space diagram",
                   subtitle=subtitle, desc=desc, content=content, content_box=box,
                   legend=legend, scale=sc, caption=[], scale_statement=sc.statement, key=key,
                   meta={"positions": {k: tuple(v) for k, v in sol.placement.points.items()}})
    return mark_drawing(page, sol.points)       # O2 → O₂: the scene's labels typeset
