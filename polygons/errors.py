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

import difflib


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


def suggest(name: str, options) -> str:
    """' (did you mean 'x'?)' if a close match exists, else the list of options."""
    options = sorted(options)
    close = difflib.get_close_matches(name, options, n=1)
    if close:
        return f"did you mean '{close[0]}'?"
    if not options:
        return "none are defined"
    return "expected one of: " + ", ".join(repr(o) for o in options)
