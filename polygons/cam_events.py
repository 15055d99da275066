"""A cam's instant stated as a book states it — by the event, not by the angle: "as the
roller just leaves the straight flank", "when the follower reaches the nose", "as it leaves
the nose on the return".

    [cam_profiles.R] when = "leaves the straight flank"        (on the rise, the default)
                     when = "reaches the base circle on the return"

The parts meet the follower in the order the cam turns them past it, from the middle of its
dwell on the base circle: base circle → flank → nose → flank → base circle (a tangent cam's
flanks straight).  "leaves P" is the last nose-axis angle at which P is in contact, "reaches
P" the first, each edge found by bisection on the part in contact to the last bit of the
angle (the event's own part: at a flank's end the flank's linkage, whose acceleration is not
the nose's) — but the base circle, where the follower rests and there is no linkage, is left
for the first angle of the next part (the motion starting) and reached at the last of the
part before (its end); "on the rise" takes the first such event of the turn, "on the return"
the last.
The [driver]'s angle is then found, not stated.
"""
from __future__ import annotations

import math
import re

from .errors import SceneError, show

#: the parts a cam's follower meets, as the words name them
PARTS = ("base circle", "straight flank", "flank", "nose")
_WHEN = re.compile(r"^\s*(leaves|reaches)\s+(?:the\s+)?(base circle|straight flank|flank|nose)"
                   r"(?:\s+on\s+the\s+(rise|return))?\s*$")
#: the cam angles sampled to order the parts (each a contact test, no construction)
SAMPLES = 3600


def _same(stated: str, part: str) -> bool:
    return part == stated or (stated == "flank" and part == "straight flank")


def axis_when(when, part_at, sense: float, file: str, where: str) -> float:
    """The nose axis's angle (rad) at the event ``when`` (the module docstring), the cam
    turning in ``sense`` (+1 CCW, −1 CW); ``part_at(axis)`` the part in contact there."""
    m = _WHEN.match(when) if isinstance(when, str) else None
    if m is None:
        raise SceneError(f"when: expected 'leaves' or 'reaches' and a part ({', '.join(PARTS)}"
                         f"), optionally 'on the rise' or 'on the return'; got {show(when)}",
                         file=file, where=where)
    verb, part, leg = m.groups()
    step = sense * 2.0 * math.pi / SAMPLES
    parts = [part_at(k * step) for k in range(SAMPLES)]
    dwell = [k for k, p in enumerate(parts) if p == "base circle"]
    if not dwell:
        raise SceneError("when: the follower never dwells on the base circle, so the turn has "
                         "no rise to count from; state the driver's angle", file=file,
                         where=where)
    runs, k0 = [], dwell[0]           # the longest run on the base circle: its middle
    for k in dwell:
        if runs and k == runs[-1][1] + 1:
            runs[-1][1] = k
        else:
            runs.append([k, k])
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == SAMPLES - 1:
        runs[0][0] = runs.pop()[0] - SAMPLES
    lo, hi = max(runs, key=lambda r: r[1] - r[0])
    k0 = (lo + hi) // 2
    order = [(k0 + j) % SAMPLES for j in range(SAMPLES + 1)]
    events = []
    for a, b in zip(order, order[1:]):
        before, after = parts[a], parts[b]
        if before != after and _same(part, before if verb == "leaves" else after):
            events.append(a)
    if not events:
        raise SceneError(f"when = {show(when)}: the follower never {verb} the {part} of this "
                         f"cam", file=file, where=where)
    a = events[-1] if leg == "return" else events[0]
    x0, x1 = a * step, (a + 1) * step
    first = parts[a]
    for _ in range(200):                # the edge, to the last bit
        mid = 0.5 * (x0 + x1)
        if mid in (x0, x1):
            break
        if part_at(mid) == first:
            x0 = mid
        else:
            x1 = mid
    if part == "base circle":       # at rest there, no linkage: the moving part's side
        return x1 if verb == "leaves" else x0
    return x0 if verb == "leaves" else x1


def nose_axis_of(table: dict, drv: dict, part_of, file: str, where: str) -> float:
    """The nose axis's angle (rad): the driver's, or found from the cam's ``when``;
    ``part_of(axis)`` the part in contact (a SceneError where none is)."""
    from .units import parse_quantity
    if "when" not in table:
        return parse_quantity(drv["angle"], "angle", file=file, where="driver.angle")
    if "angle" in drv:
        raise SceneError("give the driver's angle or the cam's when, not both", file=file,
                         where=f"{where}.when")
    from .senses import sense_in, turn_word
    # the cam's sense as the driver states it: `sense`, or written after its rate ('180 rpm
    # CW': read as CCW before, which put "on the rise" on the return)
    if "sense" in drv:
        turn = turn_word(drv["sense"]) or 1.0
    else:
        turn = sense_in(drv.get("omega", drv.get("speed")))[1] or 1.0
    sense = -1.0 if turn < 0 else 1.0

    def part_at(axis: float) -> str:
        try:
            return part_of(axis)
        except SceneError:
            return "none"
    return axis_when(table["when"], part_at, sense, file, f"{where}.when")


__all__ = ["axis_when", "nose_axis_of", "PARTS"]
