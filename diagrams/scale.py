"""Drawing-board scales: '1 cm = 2 m/s', chosen from 1, 2, 2.5, 5 × 10ⁿ units per cm.

:func:`choose` picks the largest drawing whose polygon still fits the paper area (A5 first,
A4 when A5 would leave the shortest vector too short to draw and read), :func:`parse` reads a
scale forced by the user (``--scale velocity="2 m/s"`` or ``[diagram] velocity_scale``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from polygons.errors import PolygonsError, SceneError, suggest
from polygons.units import ROUND, UNITS, round_up  # noqa: F401 (one rule for round scales)

from .text import plain


class DiagramError(PolygonsError):
    """A diagram cannot be drawn as asked (bad scale, paper, output folder...)."""


class ScaleError(DiagramError):
    """A forced scale that cannot be used."""


#: the mantissas of a round drawing scale (units per cm)
#: the area (mm) the polygon or mechanism must fit, by paper size (landscape, less margins,
#: title, scale bar and legend)
PAPER = {"A5": (150.0, 100.0), "A4": (230.0, 150.0)}
#: below this drawn length (mm) a vector is too short to draw an arrowhead and read a length
MIN_VECTOR_MM = 5.0
#: largest drawing accepted with a forced scale (mm)
MAX_DRAWING_MM = 2000.0

QUANTITY_OF = {"space": "length", "velocity": "velocity", "acceleration": "acceleration"}
_DISPLAY = {  # quantity -> ((unit, SI factor) for ordinary scales, (unit, factor) for small)
    "length": (("mm", 1e-3), ("m", 1.0)),
    "velocity": (("m/s", 1.0), ("mm/s", 1e-3)),
    "acceleration": (("m/s²", 1.0), ("mm/s²", 1e-3)),
}


@dataclass(frozen=True)
class Scale:
    """``per_cm`` SI units are drawn as 1 cm; ``unit``/``factor`` are the unit stated."""

    quantity: str        # 'length' | 'velocity' | 'acceleration'
    per_cm: float        # SI units per cm of paper
    unit: str            # unit written on the drawing ('m/s', 'mm', 'm/s²' ...)
    factor: float        # SI value of one `unit`
    forced: bool = False

    @property
    def mm_per_si(self) -> float:
        return 10.0 / self.per_cm

    def mm(self, si: float) -> float:
        """Drawn length (mm) of an SI magnitude."""
        return si * self.mm_per_si

    def si(self, mm: float) -> float:
        """SI magnitude of a drawn length (mm): what a ruler reading means."""
        return mm / self.mm_per_si

    @property
    def per_cm_display(self) -> float:
        return self.per_cm / self.factor

    @property
    def statement(self) -> str:
        return f"1 cm = {plain(self.per_cm_display)} {self.unit}"


def make(quantity: str, per_cm: float, forced: bool = False) -> Scale:
    """A :class:`Scale` with the stated unit chosen for readability."""
    big, small = _DISPLAY[quantity]
    if quantity == "length":
        unit, factor = (big if per_cm < 1.0 else small)    # mm below 1 m per cm
    else:
        unit, factor = (big if per_cm >= 0.1 - 1e-12 else small)
    return Scale(quantity, per_cm, unit, factor, forced)


def choose(quantity: str, extent: tuple[float, float], vectors: list[float] = (),
           paper: str | None = None, pad_mm: float = 0.0) -> Scale:
    """Round scale for a drawing whose SI extent is ``extent`` (width, height).

    With ``paper`` None: A5 unless the shortest non-zero vector would be drawn shorter than
    :data:`MIN_VECTOR_MM`, then A4 if that lengthens it.  ``pad_mm`` is room the drawing needs
    beyond its scaled extent (symbols, labels).
    """
    if paper is not None and paper not in PAPER:
        raise ScaleError(f"unknown paper {paper!r}: {suggest(paper, PAPER)}")

    def fit(name: str) -> Scale:
        need = math.inf
        for aw, ah in (PAPER[name], PAPER[name][::-1]):     # landscape or portrait
            aw, ah = aw - pad_mm, ah - pad_mm
            need = min(need, max(extent[0] * 10.0 / aw if extent[0] > 0 else 0.0,
                                 extent[1] * 10.0 / ah if extent[1] > 0 else 0.0))
        return make(quantity, round_up(need))

    if paper:
        return fit(paper)
    small = fit("A5")
    longest = max(vectors, default=0.0)
    # vectors that are zero but for rounding (1e-16 of the longest) cannot be drawn anyway
    shortest = min((v for v in vectors if v > 1e-9 * longest), default=None)
    if shortest is None or small.mm(shortest) >= MIN_VECTOR_MM:
        return small
    large = fit("A4")
    return large if large.mm(shortest) >= MIN_VECTOR_MM else small


def round_down(x: float) -> float:
    """The largest round scale value (1, 2, 2.5, 5 × 10ⁿ) ≤ ``x`` (0 for a value that is not
    positive and finite)."""
    if not (x > 0 and math.isfinite(x)):
        return 0.0
    n = math.floor(math.log10(x))
    for k in (n + 1, n, n - 1):
        for m in reversed(ROUND):
            v = float(f"{m}e{k}")
            if v <= x * (1 + 1e-12):
                return v
    return 0.0  # pragma: no cover


#: the longest force of a force polygon is drawn this long (mm) ...
FORCE_MM = 90.0
#: ... or up to this long, so that its shortest force is drawn RULE_MM long
MAX_FORCE_MM = 160.0
#: the layout rule: no vector drawn shorter than this (mm) -- diagrams.inset.MIN_VECTOR_MM
RULE_MM = 3.0


def force_scale(big: float, small: float) -> float:
    """The round force scale (N per cm) of a polygon whose longest force is ``big`` and
    shortest ``small`` (N): the longest :data:`FORCE_MM` long, or longer, up to
    :data:`MAX_FORCE_MM`, at the coarsest round scale drawing the shortest
    :data:`RULE_MM` long (one still shorter is said in the legend, not drawn)."""
    usual = round_up(big * 10.0 / FORCE_MM)
    finest = round_up(big * 10.0 / MAX_FORCE_MM)
    want = round_down(small * 10.0 / RULE_MM)
    return min(usual, max(finest, want))


def parse(text, quantity: str, *, file: str | None = None, where: str | None = None
          ) -> Scale:
    """Read a forced scale: '2 m/s', '1 cm = 2 m/s', '20 mm' (per cm of paper), with the
    scene loader's own reading (:func:`polygons.options.scale_per_cm`)."""
    from polygons.options import scale_per_cm
    err = SceneError if file else ScaleError
    per_cm = scale_per_cm(text, quantity, file=file, where=where, error=err)
    return make(quantity, per_cm, forced=True)


def check_size(scale: Scale, extent: tuple[float, float], kind: str) -> None:
    w, h = scale.mm(extent[0]), scale.mm(extent[1])
    if max(w, h) > MAX_DRAWING_MM:
        raise ScaleError(f"the {kind} diagram at {scale.statement} would be "
                         f"{w:.0f} × {h:.0f} mm; choose a larger value per cm "
                         f"(automatic: leave --scale out)")


def options_from_scene(scene) -> dict:
    """The scene's ``[diagram]`` options (checked at load by :mod:`polygons.options`)."""
    d = scene.options.diagram
    out: dict = {"scales": {kind: make(QUANTITY_OF[kind], per_cm, forced=True)
                            for kind, per_cm in d.scales.items()}}
    if d.paper is not None:
        out["paper"] = d.paper
    if d.stages is not None:
        out["stages"] = d.stages
    return out


def parse_cli(items: list[str] | None) -> dict[str, Scale]:
    """``--scale velocity='2 m/s'`` (repeatable) → {'velocity': Scale}."""
    out: dict[str, Scale] = {}
    for item in items or ():
        if "=" not in item:
            raise ScaleError(f"--scale {item!r}: write KIND=VALUE, e.g. "
                             f"--scale velocity='2 m/s' (KIND: {', '.join(QUANTITY_OF)})")
        kind, value = item.split("=", 1)
        kind = kind.strip()
        if kind not in QUANTITY_OF:
            raise ScaleError(f"--scale {item!r}: unknown diagram {kind!r}: "
                             f"{suggest(kind, QUANTITY_OF)}")
        out[kind] = parse(value, QUANTITY_OF[kind])
    return out


__all__ = ["Scale", "DiagramError", "ScaleError", "choose", "parse", "parse_cli", "make",
           "round_up", "round_down", "force_scale", "PAPER", "MIN_VECTOR_MM", "UNITS"]
