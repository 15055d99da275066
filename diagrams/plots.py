"""Motion curves of a sweep with matplotlib: the only module of the project that imports it.

The caller (``polygons sweep``) hands over plain panels: a title, an x label and, per panel,
a y label and the lines to draw (already in display units, already decimated).  This module
only draws.  Output is deterministic: the Agg backend, no date or version in the SVG or PNG
metadata, and a fixed ``svg.hashsalt`` so the SVG element ids do not change between runs.
"""
from __future__ import annotations

import textwrap
from dataclasses import dataclass, field
import math
from pathlib import Path
from typing import Sequence

import matplotlib
import numpy as np

matplotlib.use("Agg")

from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

#: the same salt every run, so the SVG ids (clip paths, glyphs) are stable
HASHSALT = "polygons-sweep"


@dataclass
class Line:
    label: str
    x: Sequence[float]
    y: Sequence[float]
    style: str = "-"          # matplotlib line style: '-', '--', ':'
    color: str | None = None
    width: float = 1.5
    marker: str | None = None  # the marker ('o', 's', ...); style 'none' for no line


@dataclass
class Panel:
    ylabel: str
    lines: list[Line] = field(default_factory=list)
    title: str = ""
    zero_line: bool = True    # draw y = 0 (not for displacements far from the origin)


@dataclass
class Marker:
    """A vertical line at ``x`` (a limit or toggle position, the scene's own input) with a
    short label."""
    x: float
    label: str
    color: str = "tab:red"


def plot_panels(title: str, xlabel: str, panels: Sequence[Panel], stem: str | Path,
                formats: Sequence[str] = ("png", "svg"), markers: Sequence[Marker] = (),
                xlim: tuple[float, float] | None = None, xticks: Sequence[float] | None = None,
                width: float = 8.0, panel_height: float = 2.6, dpi: int = 110,
                reverse_x: bool = False) -> list[Path]:
    """Draw ``panels`` stacked over one shared x axis and save ``stem.<fmt>`` for each format.

    ``reverse_x`` runs the x axis from high to low values: for a crank turning CW (its angle
    decreasing) the curves then read left to right in time.  Returns the paths written."""
    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    with matplotlib.rc_context({"svg.hashsalt": HASHSALT, "svg.fonttype": "path",
                                "font.size": 9, "axes.grid": True, "grid.alpha": 0.35,
                                "path.simplify": True}):
        fig = Figure(figsize=(width, panel_height * len(panels) + 0.8), dpi=dpi)
        FigureCanvasAgg(fig)
        axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)[:, 0]
        for ax, panel in zip(axes, panels):
            for ln in panel.lines:
                ax.plot(ln.x, ln.y, linestyle=ln.style, marker=ln.marker, color=ln.color,
                        lw=ln.width, ms=4.5, label=ln.label or None)
            for mk in markers:
                ax.axvline(mk.x, color=mk.color, lw=0.9, ls="--")
            if panel.zero_line:
                ax.axhline(0.0, color="0.3", lw=0.6)
            _robust_ylim(ax, panel)
            ax.set_ylabel(panel.ylabel)
            if panel.title:
                ax.set_title(panel.title, fontsize=9, loc="left")
            if panel.lines:
                ax.legend(loc="best", fontsize=8, framealpha=0.85)
        if markers:
            top = axes[0]
            for mk in markers:
                top.annotate(mk.label, xy=(mk.x, 1.0), xycoords=("data", "axes fraction"),
                             xytext=(2, 2), textcoords="offset points", fontsize=7,
                             color=mk.color, rotation=0, va="bottom")
        if xlim is not None:
            axes[-1].set_xlim(*xlim)
        if xticks is not None:
            axes[-1].set_xticks(list(xticks))
        if reverse_x:
            axes[-1].invert_xaxis()
        axes[-1].set_xlabel(xlabel)
        fig.suptitle("\n".join(textwrap.fill(t, 100) for t in title.split("\n")),
                     fontsize=10)
        fig.tight_layout()
        written = []
        for fmt in formats:
            path = stem.with_suffix(f".{fmt}")
            if fmt == "svg":
                meta = {"Date": None, "Creator": None}
            elif fmt == "png":
                meta = {"Software": None}
            elif fmt == "pdf":
                meta = {"CreationDate": None, "Creator": None, "Producer": None}
            else:
                meta = {}
            fig.savefig(path, format=fmt, metadata=meta)
            written.append(path)
    return written


def _robust_ylim(ax, panel: Panel) -> None:
    """Near a limit position the rates grow without bound; keep the axis on the bulk of the
    curve (1st-99th percentile, with a margin) and say that the spikes are clipped."""
    ys = [np.asarray(ln.y, dtype=float) for ln in panel.lines if len(ln.y)]
    if not ys:
        return
    y = np.concatenate(ys)
    y = y[np.isfinite(y)]
    if y.size < 20:
        return
    lo, hi = np.percentile(y, [1.0, 99.0])
    span = hi - lo
    if span <= 0 or (y.max() - y.min()) <= 4.0 * span:
        return
    ax.set_ylim(lo - 0.3 * span, hi + 0.3 * span)
    ax.text(0.01, 0.03, "clipped: grows without bound towards the limit", fontsize=7,
            color="0.35", transform=ax.transAxes)


def plot_xy(title: str, xlabel: str, ylabel: str, series: Sequence[Line], stem: str | Path,
            formats: Sequence[str] = ("png", "svg"), logx: bool = False, logy: bool = False,
            annotate: bool = True, width: float = 7.5, height: float = 5.0,
            dpi: int = 110, legend_outside: bool = False) -> list[Path]:
    """A single scatter/line chart (used by the benchmark's speed-vs-error plot): each
    :class:`Line` is drawn with markers; ``annotate`` writes its label next to its points."""
    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    with matplotlib.rc_context({"svg.hashsalt": HASHSALT, "svg.fonttype": "path",
                                "font.size": 9, "axes.grid": True, "grid.alpha": 0.35}):
        fig = Figure(figsize=(width, height), dpi=dpi)
        FigureCanvasAgg(fig)
        ax = fig.subplots()
        for ln in series:
            ax.plot(ln.x, ln.y, linestyle=ln.style, color=ln.color, lw=ln.width,
                    label=ln.label, marker=ln.marker or "o", ms=5)
            if annotate and len(ln.x):
                ax.annotate(ln.label, xy=(ln.x[-1], ln.y[-1]), xytext=(4, 3),
                            textcoords="offset points", fontsize=7)
        if logx:
            ax.set_xscale("log")
        if logy:
            ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        if legend_outside:
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), framealpha=0.85)
        else:
            ax.legend(fontsize=7, loc="best", framealpha=0.85)
        fig.tight_layout()
        written = []
        for fmt in formats:
            path = stem.with_suffix(f".{fmt}")
            meta = ({"Date": None, "Creator": None} if fmt == "svg"
                    else {"Software": None} if fmt == "png" else {})
            fig.savefig(path, format=fmt, metadata=meta)
            written.append(path)
    return written


def plot_turning_moment(cy, scene, stem: str | Path, title: str,
                        formats: Sequence[str] = ("png", "svg")) -> list[Path]:
    """The turning-moment diagram ``cy`` (:class:`polygons.forces.cycle.Cycle`): T(θ) with its
    mean over the crank angle, and the energy above the mean E(θ); the scene's angle marked."""
    deg = np.degrees(cy.theta) % 360.0
    order = np.argsort(deg)
    return plot_panels(
        title, "crank angle (deg, CCW from +x)",
        [Panel("input torque (N m)", [Line("T(θ)", deg[order], cy.torque[order]),
                                      Line(f"mean {cy.mean:.4g} N m", deg[order],
                                           np.full(len(deg), cy.mean), style="--")]),
         Panel("energy above the mean (J)", [Line("E(θ)", deg[order], cy.energy[order])])],
        stem, formats=formats,
        markers=[Marker(math.degrees(scene.driver.angle) % 360.0, "scene")],
        xlim=(0.0, 360.0))
