"""The Python API: load a scene, solve it, read and show the results (notebooks included).

    >>> import polygons
    >>> res = polygons.solve("cases/s001-we4.toml")     # a path, TOML text or a Scene
    >>> res.links["BC"].omega                            # the Solution's attributes
    >>> print(res.table())                               # the report of ``polygons solve``
    >>> res.svg("velocity")                              # 'space' | 'velocity' | ...
    >>> res                                              # in Jupyter: the diagrams

This is the top (commands) layer, beside :mod:`polygons.cli`: it may import :mod:`diagrams`,
and does so only when a drawing is asked for.
"""
from __future__ import annotations

import html
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable

from .errors import SceneError, show
from .scene import Scene, load_scene, parse_scene

DIAGRAMS = ("space", "velocity", "acceleration", "centres")


def load(source: str | Path | Scene) -> Scene:
    """A :class:`~polygons.scene.Scene` from a file path or from TOML text.

    A ``str`` is TOML text when it has a newline or an ``=`` in it, else a file path.
    Errors are :class:`~polygons.errors.SceneError`\\ s naming the file (``<text>`` for text).
    """
    if isinstance(source, Scene):
        return source
    if isinstance(source, Path):
        return load_scene(source)
    if not isinstance(source, str):
        raise SceneError(f"expected a path, TOML text or a Scene, got "
                         f"{type(source).__name__}", file="<api>")
    if "\n" in source or "=" in source:
        from .scene import parse_toml        # the loader's own reading (rtoml, the checks)
        return parse_scene(parse_toml(source, "<text>"), file="<text>")
    return load_scene(source)


def solve(source: str | Path | Scene, targets: Iterable[str] | None = None) -> "Result":
    """Solve a scene (a :class:`Scene`, a path or TOML text): a :class:`Result`."""
    from .evaluate import solve as _solve
    scene = load(source)
    return Result(_solve(scene, _labels(targets, scene, "targets")))


def _labels(value, scene: Scene, what: str) -> tuple[str, ...] | None:
    """None, or point labels given as an iterable of strings (one comma-separated string is
    read as the command line reads --points); anything else is refused in one line."""
    if value is None:
        return None
    if isinstance(value, str):
        value = [v.strip() for v in value.split(",") if v.strip()]
    try:
        items = tuple(value)
    except TypeError:
        items = None
    if items is None or not all(isinstance(v, str) for v in items):
        raise SceneError(f"{what}: expected point labels (a list of strings such as "
                         f"['B', 'C']), got {show(value)}", file=scene.file)
    return items


@dataclass(frozen=True)
class Result:
    """A solved scene: every attribute of the core :class:`~polygons.evaluate.Solution`
    (``points``, ``links``, ``slides``, ``steps``, ``vertices``, ``scene`` ...) is read
    through, and these add the reports and the drawings."""

    solution: Any

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(object.__getattribute__(self, "solution"), name)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(dir(self.solution)))

    # ---------------------------------------------------------------- reports
    def to_dict(self) -> dict:
        """What ``polygons solve --json`` prints (:func:`polygons.cli.solve.report_data`): the
        kinematics, plus ``pins`` and ``forces`` when the scene has those tables, a contact's
        ``equivalent_links`` and a cam stated by its profile's ``cam_profile``."""
        from .cli.solve import report_data
        from .forces import analyse, has_forces
        forces = (analyse(self.scene, method="polygons.api (Result.to_dict)")
                  if has_forces(self.scene) else None)
        return report_data(self.solution, forces)

    def to_json(self) -> str:
        """:meth:`to_dict` as deterministic JSON text."""
        from .report import json_text
        return json_text(self.to_dict())

    def table(self, steps: bool = True) -> str:
        """The text report of ``polygons solve`` (:func:`polygons.cli.solve.report_text`): the
        table, the rubbing / least velocities, the forces, a contact's equivalent linkage and
        a cam's profile, as the command adds them."""
        from .cli.solve import report_text
        from .forces import analyse, has_forces
        forces = analyse(self.scene) if has_forces(self.scene) else None
        return report_text(self.solution, forces, steps=steps)

    def centres(self, points: Iterable[str] | None = None):
        """The instantaneous centres (:func:`polygons.centres.instant_centres`)."""
        from .centres import instant_centres
        return instant_centres(self.solution, _labels(points, self.scene, "points"))

    def rubbing(self):
        """Rubbing velocities at the scene's [pins] (:func:`polygons.pins.rubbing_velocities`)."""
        from .pins import rubbing_velocities
        return rubbing_velocities(self.solution)

    def least_velocity(self, link: str):
        """The point of ``link`` with least velocity (:func:`polygons.pins.least_velocity`)."""
        from .pins import least_velocity
        if not isinstance(link, str):
            raise SceneError(f"least_velocity: expected a link name such as 'BC', got "
                             f"{show(link)}", file=self.scene.file)
        return least_velocity(self.solution, link)

    # ---------------------------------------------------------------- drawings
    def svg(self, diagram: str = "space") -> str:
        """One finished diagram as SVG text: 'space', 'velocity', 'acceleration' or
        'centres'."""
        if not isinstance(diagram, str) or diagram not in DIAGRAMS:
            raise SceneError(f"unknown diagram {show(diagram)}: one of {', '.join(DIAGRAMS)}",
                             file=self.scene.file)
        if diagram == "centres":
            from diagrams.centres import svg
            return svg(self.solution)
        import diagrams
        from diagrams import polygon, space
        from diagrams.svg import to_svg
        opts = diagrams.options(self.solution)
        sc = opts["scales"]
        if diagram == "space":
            d = space.drawing(self.solution, sc.get("space"), opts["paper"])
        else:
            if diagram not in self.solution.vertices:
                raise SceneError(f"the {diagram} diagram was not solved (solve = "
                                 f"{list(self.scene.solve)})", file=self.scene.file)
            lay = polygon.layout(self.solution, diagram, sc.get(diagram), opts["paper"])
            d = polygon.drawing(self.solution, lay)
        return to_svg(d).decode()

    def _repr_svg_(self) -> str:
        return _inline(self.svg("space"))

    def _repr_html_(self) -> str:
        sol = self.solution
        parts = [f"<div class='polygons-result'><h3>{html.escape(self.scene.title)}</h3>",
                 "<table><tr><th>link</th><th>ω rad/s</th><th>α rad/s²</th></tr>"]
        for name, lr in sol.links.items():
            parts.append(f"<tr><td>{html.escape(name)}</td><td>{_num(lr.omega)}</td>"
                         f"<td>{_num(lr.alpha)}</td></tr>")
        parts.append("</table>")
        for diagram in ("space",) + tuple(self.scene.solve):
            parts.append(f"<figure>{_inline(self.svg(diagram))}"
                         f"<figcaption>{diagram} diagram</figcaption></figure>")
        parts.append("</div>")
        return "\n".join(parts)

    def __repr__(self) -> str:
        return f"<polygons.Result {self.scene.title!r} ({self.scene.file})>"


def _inline(svg: str) -> str:
    """SVG text without its XML declaration, to sit inside HTML."""
    if svg.startswith("<?xml"):
        svg = svg.split("?>", 1)[1].lstrip()
    return svg


def _num(x) -> str:
    if x is None:
        return "–"
    return f"{abs(x):.5g} {'CCW' if x > 0 else 'CW' if x < 0 else ''}".strip()


__all__ = ["load", "solve", "Result"]
