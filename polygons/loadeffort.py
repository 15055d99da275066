"""``[dynamics] effort``: where the force analysis finds the balancing effort (scene layer).

The driver stays the kinematic input (its motion is given); the one unknown of the force
analysis is then the effort at the named place instead of the driver's torque:

* ``"torque on DC"`` — a couple on the link DC (CCW positive);
* ``"force at C"`` — a force on the slider C along its guide (positive along the guide's
  stated direction);
* ``"force along E F"`` (or ``"force along EF"`` when the split into two labels is unique) — a
  massless actuator (hydraulic cylinder) between the points E and F, positive pushing them
  apart (the cylinder in compression).

Checked at load; every problem is one line naming ``dynamics.effort``.
"""
from __future__ import annotations

from .errors import SceneError
from .loadmodel import Effort

# (its key, EFFORT_KEY, is declared with the others in polygons.loadtables)
WHERE = "dynamics.effort"
FORMS = "'torque on LINK', 'force at C' (a slider) or 'force along E F' (an actuator)"


def _split(text: str, labels) -> tuple[str, str] | None:
    """Two labels from 'E F', 'E-F' or 'EF' (a unique split into two known labels)."""
    for sep in (" ", "-", "–", ","):
        if sep in text:
            parts = [p for p in text.split(sep) if p]
            return (parts[0], parts[1]) if len(parts) == 2 else None
    splits = [(text[:i], text[i:]) for i in range(1, len(text))
              if text[:i] in labels and text[i:] in labels]
    return splits[0] if len(splits) == 1 else None


def parse_effort(ctx, raw, mode: str, flywheel=None, efficiency=None) -> Effort | None:
    """The :class:`Effort` of ``raw`` (None when the key is absent: the driver's effort)."""
    if raw is None:
        return None
    file = ctx.r.file
    if flywheel is not None or efficiency is not None:
        raise SceneError("[flywheel] and [efficiency] work on the driver's own effort: remove "
                         "dynamics.effort", file=file, where=WHERE)
    if not isinstance(raw, str):
        raise SceneError(f"effort is a string: {FORMS}", file=file, where=WHERE)
    if mode != "kinetostatic":
        raise SceneError(f"an effort is found with mode = \"kinetostatic\" (the motion given); "
                         f"mode is {mode!r}", file=file, where=WHERE)
    text = " ".join(raw.split())
    words = text.split(" ", 2)
    if len(words) == 3 and words[0] == "torque" and words[1] == "on":
        body = ctx.body_name(words[2], WHERE)
        if ctx.bodies[body].kind == "block":
            raise SceneError(f"{body} is a slider block (it does not turn): write "
                             f"'force at {body}'", file=file, where=WHERE)
        return Effort("torque", text, body=body)
    if len(words) == 3 and words[0] == "force" and words[1] == "at":
        lab = words[2]
        if lab not in ctx.bodies or ctx.bodies[lab].kind != "block":
            raise SceneError(f"'force at {lab[:60]}' needs a slider on a fixed guide ([sliders."
                             f"{lab[:60]}]); a force along a link or actuator is written "
                             f"'force along E F'", file=file, where=WHERE)
        return Effort("force", text, body=lab)
    if len(words) == 3 and words[0] == "force" and words[1] == "along":
        ends = _split(words[2], ctx.members)
        if ends is None:
            raise SceneError(f"'force along' names two points, e.g. 'force along E F'; got "
                             f"{words[2][:60]!r}", file=file, where=WHERE)
        out = []
        for lab in ends:
            body = ctx.point_body(lab, None, WHERE, allow_ground=True)
            out.append((lab, body))
        if out[0][1] is None and out[1][1] is None:
            raise SceneError("both ends of the actuator are fixed: it does no work",
                             file=file, where=WHERE)
        if out[0][1] == out[1][1]:
            raise SceneError(f"both ends of the actuator are on {out[0][1]}: it does no work",
                             file=file, where=WHERE)
        return Effort("actuator", text, ends=tuple(out))
    raise SceneError(f"effort must be {FORMS}; got {text[:60]!r}", file=file, where=WHERE)
