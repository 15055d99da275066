"""A cam stated by its profile ([cam_profiles], polygons/cam_profiles.py) on the space diagram:
the whole profile at the cam angle solved (base circle, flanks, nose) shaded as a plate, the
part in contact traced heavier, the nose axis and the flanks' meeting points marked, and the
follower's face (a flat face: a line along its face; a knife: its wedge; a roller is drawn
with the equivalent link by the space diagram).  Nothing is computed here but the outline's
points, each from :meth:`polygons.cam_profiles.Profile.support_point`."""
from __future__ import annotations

import math

from polygons.cam_profiles import pose

from .model import Circle, Polyline, Segment

Pt = tuple[float, float]
#: points of the outline (one per degree of outward normal, and the flank's length)
OUTLINE_POINTS = 720


def _outline(prof, axis, o) -> list[Pt]:
    pts = prof.outline(axis, OUTLINE_POINTS)
    return [(o[0] + p[0], o[1] + p[1]) for p in pts]


def extent(sol) -> list[Pt]:
    """SI points the space diagram must hold for the cam's whole profile and the follower."""
    got = pose(sol.scene)
    if got is None:
        return []
    prof, fol, axis, o, label, c = got
    pts = _outline(prof, axis, o)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return [(min(xs), min(ys)), (max(xs), max(ys))]


def space_items(sol, to_paper, k, placer=None) -> tuple[list, list]:
    """(background items, notes) of the cam's profile; ``to_paper`` maps SI to the paper; the
    outline kept clear of labels (``placer``)."""
    got = pose(sol.scene)
    if got is None:
        return [], []
    prof, fol, axis, o, label, c = got
    back, notes = [], []
    outline = tuple(to_paper(p) for p in _outline(prof, axis, o))
    back.append(Polyline(outline, "plate", closed=True, cls="cam-profile"))
    if placer is not None:
        ring = outline[::8] + outline[:1]
        for a, b in zip(ring, ring[1:]):
            placer.hard(a, b, 0.5)
    # the part in contact, traced heavier over ±12° of its normals about the contact
    part = next(p for p in prof.parts(axis) if p.name == c.part and p.side == c.side)
    if part.radius < math.inf:
        trace = []
        for t in range(-12, 13):
            d = c.normal + math.radians(t)
            if part.holds(d):
                trace.append(to_paper((o[0] + part.centre[0] + part.radius * math.cos(d),
                                       o[1] + part.centre[1] + part.radius * math.sin(d))))
        if len(trace) >= 2:
            back.append(Polyline(tuple(trace), "link", cls="cam-contact-part"))
    else:       # the straight flank: from the base circle's tangent point to the nose's
        if fol.kind == "roller":            # (no equivalent link draws the roller here)
            back.append(Circle(to_paper((o[0] + c.point[0], o[1] + c.point[1])),
                               round(fol.roller * k, 3), "slot", cls="roller"))
        n = (math.cos(c.normal), math.sin(c.normal))
        nose = (prof.d * math.cos(axis), prof.d * math.sin(axis))
        a = (o[0] + prof.base * n[0], o[1] + prof.base * n[1])
        b = (o[0] + nose[0] + prof.nose * n[0], o[1] + nose[1] + prof.nose * n[1])
        back.append(Segment(to_paper(a), to_paper(b), "link", cls="cam-contact-part"))
    # the nose axis: O → the nose centre
    tip = (o[0] + prof.d * math.cos(axis), o[1] + prof.d * math.sin(axis))
    back.append(Segment(to_paper(o), to_paper(tip), "centre", cls="cam-nose-axis"))
    rr = fol.roller if fol.kind == "roller" else 0.0
    n = (math.cos(c.normal), math.sin(c.normal))
    touch = (o[0] + c.point[0] - rr * n[0], o[1] + c.point[1] - rr * n[1])
    if fol.kind == "flat" and fol.oscillating:   # the face along the lever, pivot to its end
        q = (o[0] + fol.pivot[0], o[1] + fol.pivot[1])
        t = (math.cos(c.s), math.sin(c.s))
        reach = max(fol.arm, (touch[0] - q[0]) * t[0] + (touch[1] - q[1]) * t[1])
        left = (-t[1] * fol.face_offset, t[0] * fol.face_offset)
        back.append(Segment(to_paper((q[0] + left[0], q[1] + left[1])),
                            to_paper((q[0] + left[0] + reach * t[0],
                                      q[1] + left[1] + reach * t[1])),
                            "link", cls="cam-follower-face"))
    elif fol.kind == "flat":    # the face: a line through the contact, ⟂ the normal
        half = 0.6 * prof.base
        t = (-n[1], n[0])
        back.append(Segment(to_paper((touch[0] - half * t[0], touch[1] - half * t[1])),
                            to_paper((touch[0] + half * t[0], touch[1] + half * t[1])),
                            "link", cls="cam-follower-face"))
    elif fol.kind == "knife":   # a wedge on the contact, opening away from the cam
        w = 1.2 / k            # 1.2 mm of paper
        t = (-n[1], n[0])
        back.append(Polyline((to_paper(touch),
                              to_paper((touch[0] + 3 * w * n[0] + w * t[0],
                                        touch[1] + 3 * w * n[1] + w * t[1])),
                              to_paper((touch[0] + 3 * w * n[0] - w * t[0],
                                        touch[1] + 3 * w * n[1] - w * t[1]))),
                             "link-thin", closed=True, cls="cam-follower-knife"))
    kind = "circular-arc" if prof.flank is not None else "tangent"
    low = min(outline, key=lambda p: p[1])       # the note under the cam
    notes.append((f"{kind} cam (profile drawn): {c.part} in contact",
                  (low[0], low[1] - 2.0)))
    return back, notes
