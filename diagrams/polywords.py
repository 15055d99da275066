"""The words of a polygon drawing: direction words, a measure step's value with its sense and
formula, a step's sentence in the drawings' notation (used by the legend and the captions of
:mod:`diagrams.polygon`, and by the handouts).  No layout here."""
from __future__ import annotations

import math
from dataclasses import replace

from polygons.evaluate import Solution
from polygons.plan import Step

from . import scale as scales
from .notation import join_vectors, link_names, name_bare_omegas, slot_names
from .strokes import Construction, sliding_arrow
from .text import display, number


def along_words(angle: float) -> str:
    """Direction words for a direction ``angle`` (radians, CCW from +x): 'to the right',
    'up and to the left (135°)'."""
    deg = math.degrees(angle) % 360.0
    names = ["to the right", "up and to the right", "up", "up and to the left", "to the left",
             "down and to the left", "down", "down and to the right"]
    k = int(((deg + 22.5) % 360.0) // 45.0)
    exact = abs(deg - 45.0 * k) < 0.05 or abs(deg - 45.0 * k - 360.0) < 0.05
    return names[k] + ("" if exact else f" ({number(deg, 4)}°)")


def _slider_sense(m: Step, sol: Solution | None, con: Construction | None = None) -> str:
    """' to the left': the sense of a signed slider measure (along its guide) or slide
    measure (the way its sliding vector is drawn)."""
    if sol is None or m.value in (None, 0):
        return ""
    guides = sol.scene.model.guide
    guide = next((guides[a].line for a in m.args if a in guides), None)
    if guide is not None:
        return f" {along_words(guide.angle + (0.0 if m.value > 0 else math.pi))}"
    if con is not None and m.theorem == "sliding":
        x = sol.vertex_of(m.args[0]) if m.args and m.args[0] in sol.points else None
        arrow = sliding_arrow(con.strokes, con.steps, x, m.args[1:])
        if arrow is not None:
            d = (arrow.b[0] - arrow.a[0], arrow.b[1] - arrow.a[1])
            return f" {along_words(math.atan2(d[1], d[0]))}"
    return ""


def measure_text(m: Step, sol: Solution | None = None, con: Construction | None = None,
                 scale: scales.Scale | None = None) -> str:
    """'ω_BC = 45.62 rad/s CW  (bc / BC)': a measure step's value, its sense, its formula;
    a signed slider result with its direction words ('1589 m/s² to the left').  A speed or
    acceleration is given in the unit of the drawing's ``scale`` (mm/s on a mm/s scale)."""
    unit = display(m.unit)
    if m.value is None:
        return display(m.draws)
    if scale is not None and display(m.unit) in ("m/s", "m/s²") and scale.factor != 1.0 \
            and scale.quantity in ("velocity", "acceleration"):
        m = replace(m, value=m.value / scale.factor)
        unit = display(scale.unit)
    if m.unit.startswith("rad"):
        sense = "" if m.value == 0 else (" CCW" if m.value > 0 else " CW")
        val = f"{number(abs(m.value))} {unit}{sense}"
    else:
        words = _slider_sense(m, sol, con)
        val = (f"{number(abs(m.value))} {unit}{words}" if words
               else f"{number(m.value)} {unit}")
    rhs = m.formula.split("=", 1)[1].strip() if "=" in m.formula else ""
    name = m.draws
    if con is not None and m.quantity and m.quantity != m.draws and sum(
            x.draws == m.draws for x in con.measures) > 1:
        # two results of one name (a pin in crossing slots: two sliding accelerations)
        # named apart by their quantity: 'a_slide = (a_P)_P2 = …'
        name = f"{m.draws} = {m.quantity}"
    return display(f"{name} = {val}" + (f"  (= {rhs})" if rhs else ""))


def prose(sol: Solution, con: Construction, text: str) -> str:
    """A step's sentence in the drawings' notation: vector names split (b1b → b₁b), a bare ω
    or α before '× XY' named after its link (ω² × AB → ω_AB² × AB)."""
    return join_vectors(name_bare_omegas(slot_names(display(text), sol.scene),
                                         _link_names(sol.scene)),
                        set(con.vertices) | set(con.pole_label.split(" = ")))


_LINK_NAMES: list = [None, {}]


def _link_names(scene) -> dict:
    """:func:`notation.link_names` of ``scene``, made once per scene (a large mechanism's
    legend and captions ask it for every line; read only)."""
    if _LINK_NAMES[0] is not scene:
        _LINK_NAMES[:] = [scene, link_names(scene)]
    return _LINK_NAMES[1]
