"""The one exception hierarchy of polygons.

Every error names the culprit: the scene file, the key or label, and (for construction
problems) the step.  The CLI prints ``str(error)`` on one line and exits non-zero; nothing in
this package lets a bare traceback reach the user for a bad scene.

    PolygonsError
    ├── SceneError            the scene file itself is wrong
    │   ├── SceneSyntaxError      not valid TOML
    │   ├── UnknownKeyError       a key the format does not know (typo)
    │   ├── UnitError             missing unit, unknown unit, wrong dimension
    │   ├── UnknownLabelError     a point or link label that is not defined
    │   └── BranchError           assembly branch missing, ambiguous or unsatisfiable
    ├── AssemblyError         the lengths cannot close at the given input
    ├── ConstructionError     a construction step cannot be drawn
    │   └── ParallelLinesError    two construction lines are parallel (toggle / change point)
    └── UnsupportedError      the scene asks for a mechanism the solver cannot yet express
"""
from __future__ import annotations

import re


class PolygonsError(Exception):
    """Base class: ``file``, ``where`` (key, label or link) and ``step`` locate the problem."""

    def __init__(self, reason: str, *, file: str | None = None, where: str | None = None,
                 step: str | None = None):
        self.reason = reason
        self.file = file
        self.where = where
        self.step = step
        super().__init__(self._format())

    def _format(self) -> str:
        self.reason = _cut_long(str(self.reason))
        head = []
        if self.file:
            head.append(str(self.file))
        if self.where:
            head.append(f"[{self.where}]")
        if self.step:
            head.append(f"step {self.step}")
        prefix = " ".join(head)
        return f"{prefix}: {self.reason}" if prefix else self.reason

    def located(self, *, file: str | None = None, where: str | None = None,
                step: str | None = None) -> "PolygonsError":
        """Return a copy of this error with missing location fields filled in."""
        return type(self)(self.reason, file=self.file or file, where=self.where or where,
                          step=self.step or step)


class SceneError(PolygonsError):
    """The scene file is wrong."""


class SceneSyntaxError(SceneError):
    """The scene file is not valid TOML."""


class UnknownKeyError(SceneError):
    """A key the scene format does not know."""


class UnitError(SceneError):
    """A value without a unit, with an unknown unit, or with the wrong dimension."""


class UnknownLabelError(SceneError):
    """A point or link label that the scene does not define."""


class BranchError(SceneError):
    """The assembly branch is missing, ambiguous or cannot be satisfied."""


class AssemblyError(PolygonsError):
    """The mechanism cannot be assembled at the given input (lengths cannot close)."""


class ConstructionError(PolygonsError):
    """A construction step cannot be carried out."""


class ParallelLinesError(ConstructionError):
    """Two construction lines that must intersect are parallel: a toggle or change point."""


class UnsupportedError(PolygonsError):
    """The scene describes something the solver cannot express yet."""


#: a run of more than MAX_VALUE characters without a space (a long value quoted in a message)
#: is cut, and a whole reason longer than MAX_REASON: a safety net for messages built without
#: :func:`show`, so that an error stays one readable line
MAX_VALUE, MAX_REASON = 60, 600
_LONG_RUN = re.compile(r"\S{%d,}" % (MAX_VALUE + 1))


def _cut_long(reason: str) -> str:
    """Cut every run of over :data:`MAX_VALUE` non-space characters, then the whole reason."""
    reason = _LONG_RUN.sub(lambda m: m.group(0)[:MAX_VALUE - 1] + "…", reason)
    return reason if len(reason) <= MAX_REASON else reason[:MAX_REASON - 1] + "…"


def show(value, limit: int = MAX_VALUE) -> str:
    """``repr(value)`` cut to ``limit`` characters, so a message stays one short line."""
    try:
        text = repr(value)
    except RecursionError:         # a value nested thousands deep
        text = f"<{type(value).__name__} nested too deeply to show>"
    except Exception:              # noqa: BLE001 - a value whose repr fails
        text = f"<{type(value).__name__}>"
    if "\n" in text:              # a numpy array's repr: one line
        text = " ".join(text.split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


def suggest(name: str, options) -> str:
    """' (did you mean 'x'?)' if a close match exists, else the list of options."""
    options = sorted(str(o) for o in options)
    import difflib                    # only when a name is wrong: a quicker start
    close = difflib.get_close_matches(str(name)[:200], options, n=1)
    if close:
        return f"did you mean {show(close[0])}?"
    if not options:
        return "none are defined"
    listed = ", ".join(show(o) for o in options[:12])
    return "expected one of: " + listed + (", ..." if len(options) > 12 else "")
