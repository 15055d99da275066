"""The one formatter of substituted formulas: a step's terms written into its theorem.

``substitute(step, scene)`` reads only the step's fields (``op``, ``args``, ``quantity``,
``start``/``end`` and its :class:`~polygons.steps.Term` records) and writes the line a
tutorial prints under the figure ("ω² × AB = 300² × 0.05 = 4500 m/s²").  Numbers go through
:func:`polygons.steps.number`, senses through :func:`polygons.steps.sense`.
"""
from __future__ import annotations

import math

from functools import partial

from .steps import Op, Step, number, sense, unit_text



def substitute(s: Step, scene, printed: bool = False) -> str:
    """The substituted formula of ``s`` (``printed``: powers of ten as 1.5 × 10¹⁰)."""
    f = partial(number, printed=printed)
    t = s.terms
    op = s.op
    if op is Op.CRANK_VELOCITY:
        L, P, X = s.args
        return (f"{s.quantity} = ω × {P}{X} = {f(t[0].value)} × {f(t[1].value)} = "
                f"{f(t[2].value)} m/s")
    if op is Op.SLIDER_DRIVE:
        return f"{f(t[0].value)} {unit_text(t[0].unit)} along the guide"
    if op is Op.CENTRIPETAL:
        L, P, X = s.args
        return (f"ω² × {P}{X} = {f(t[0].value)}² × {f(t[1].value)} = {f(t[2].value)} m/s²")
    if op is Op.CRANK_TANGENTIAL:
        L, P, X = s.args
        return f"α × {P}{X} = {f(t[0].value)} × {f(t[1].value)} = {f(t[2].value)} m/s²"
    if op is Op.CORIOLIS_OFFSET_LINE:
        return f"2ωv = 2 × {f(t[0].value)} × {f(t[1].value)} = {f(t[2].value)} m/s²"
    if op is Op.CORIOLIS:
        if len(t) == 3:
            return f"2ωv = 2 × {f(t[0].value)} × {f(t[1].value)} = {f(t[2].value)} m/s²"
        return f"2ωv = {f(t[0].value)} m/s²"
    if op is Op.SLIDE_DRIVE:
        C, P, Q = s.args
        return (f"{s.quantity} = {f(t[0].value)} {unit_text(t[0].unit)} along {P}{Q} "
                f"(given)")
    if op is Op.JOIN:
        return f"{s.start}{s.end} = {f(t[0].value)} m/s²"
    if op is Op.INTERSECT:
        return (f"{t[1].symbol} = {f(t[1].value)} {unit_text(t[1].unit)} (lines meet at "
                f"{t[0].value:.3g}°)")
    if op in _RATES:
        return _rate(t, _RATES[op], f)
    if op in (Op.SLIDER_VELOCITY, Op.SLIDER_ACCELERATION):
        # the sign is in the words, not the number: its size and the way it points along
        # the guide ('11.191 m/s² along the guide, towards 270°'; was '-11.191 … (90°)')
        (X,) = s.args
        val = t[0].value
        deg = (math.degrees(scene.model.guide[X].line.angle) + (0.0 if val >= 0 else 180.0)) \
            % 360.0
        deg = 0.0 if round(deg, 6) >= 360.0 else deg
        return f"{f(abs(val))} {unit_text(t[0].unit)} along the guide, towards {f(deg)}°"
    if op in (Op.SLIDE_VELOCITY, Op.SLIDE_ACCELERATION):
        A = s.args[0]
        val = t[0].value
        slot = scene.model.slot[A] if len(s.args) == 1 else scene.model.under[s.args[1]]
        pivot = slot.line.origin
        if slot.along_lever:                      # the sign is in the words, not the number
            ends = (pivot, slot.far) if val >= 0 else (slot.far, pivot)
            return f"{f(abs(val))} {unit_text(t[0].unit)} (along {''.join(ends)})"
        return (f"{f(abs(val))} {unit_text(t[0].unit)} "
                f"({'away from' if val >= 0 else 'towards'} {pivot})")
    if op is Op.IMAGE:
        return f"{t[0].symbol} = {f(t[0].value)} {unit_text(t[0].unit)}"
    return ""


def worked(s: Step, scene, printed: bool = False) -> str:
    """The worked line a tutorial prints under a figure: the asked symbol, the theorem in
    symbols, then the numbers ("ω_BC = bc / BC = 7.8 / 0.17 = 45.9 rad/s CW",
    "(a_C)_B^n = ω² × BC = 45.9² × 0.17 = 358 m/s²").  Empty for a line of unknown length.
    Built from the step's fields and terms only; ``printed`` writes powers of ten as a page
    does (1.5 × 10¹⁰) instead of e-notation."""
    f = partial(number, printed=printed)
    sub = substitute(s, scene, printed)
    if not sub:
        return ""
    op, t = s.op, s.terms
    if op is Op.CRANK_VELOCITY:
        return sub
    if op in (Op.CORIOLIS_OFFSET_LINE, Op.CORIOLIS):
        return f"a_cor = {sub}"
    if op in _RATES:
        return _rate(t, _RATES[op], f, symbols=True)
    return f"{s.quantity} = {sub}"


#: the ops that measure a link's rate, and its unit
_RATES = {Op.OMEGA: "rad/s", Op.ALPHA: "rad/s²", Op.ROLL_OMEGA: "rad/s",
          Op.ROLL_ALPHA: "rad/s²"}


def _rate(t, unit: str, f, symbols: bool = False) -> str:
    """'ω_BC = 7.8 / 0.17 = 45.9 rad/s CW' from the terms (relative vector, length, rate);
    with ``symbols`` the worked form 'ω_BC = bc / BC = 7.8 / 0.17 = …'.  A zero rate has no
    sense word."""
    w = t[2].value
    names = f"{t[0].symbol} / {t[1].symbol} = " if symbols else ""
    return (f"{t[2].symbol} = {names}{f(t[0].value)} / {f(t[1].value)} = {f(abs(w))} {unit} "
            f"{sense(w)}").rstrip()
