"""Senses in words, as books write them: one table of the turning words ('CW', 'anti
clockwise', 'a.c.w.' …, any case) read after a rate ('120 rpm anti clockwise'), as a sense key
and by every driver's reader; α stated against ω ('5 rad/s^2 retarding').  Imports only the
errors (the scene's readers call it).
"""
from __future__ import annotations

from .errors import SceneError, show

_TURN_WORDS = {"cw": -1.0, "clockwise": -1.0, "c.w.": -1.0, "ccw": 1.0, "anticlockwise": 1.0,
               "anti-clockwise": 1.0, "anti clockwise": 1.0, "counterclockwise": 1.0,
               "counter-clockwise": 1.0, "counter clockwise": 1.0, "acw": 1.0, "a.c.w.": 1.0,
               "c.c.w.": 1.0}


def turn_word(text) -> int | None:
    """'CW' → −1, 'Anti Clockwise' → +1 (any case, spaces as written): a sense word of the
    one table; None for anything else (a number, an unknown word)."""
    if not isinstance(text, str):
        return None
    turn = _TURN_WORDS.get(" ".join(text.split()).lower())
    return None if turn is None else int(turn)


def sense_in(text) -> tuple[object, int | None]:
    """'300 rad/s CW' → ('300 rad/s', −1); '120 rpm anti clockwise' → ('120 rpm', +1);
    '300 rad/s' → ('300 rad/s', None): a rate with its sense written after it, as books do."""
    if not isinstance(text, str):
        return text, None
    words = text.split()
    for n in (2, 1):            # 'anti clockwise' before 'clockwise'
        turn = turn_word(" ".join(words[-n:])) if len(words) > n else None
        if turn is not None:
            return " ".join(words[:-n]), turn
    return text, None


#: α stated against ω as books do ('retarding at 5 rad/s²'): −1 opposite ω's sense, +1 with it
_ALPHA_WORDS = {"retarding": -1, "decelerating": -1, "accelerating": 1}


def alpha_words(drv, omega: float, file, key: str = "alpha", sense_key: str = "alpha_sense"):
    """``alpha = "5 rad/s^2 retarding"`` (or ``decelerating``; ``accelerating``): the sense of
    α from ω's, opposite (slowing down) or the same (speeding up) → ``drv`` with that sense
    written as CW / CCW; ``drv`` unchanged without such a word."""
    text = drv.get(key)
    if not isinstance(text, str):
        return drv
    head, _, last = text.strip().rpartition(" ")
    rel = _ALPHA_WORDS.get(last.lower())
    if rel is None or not head:
        return drv
    if sense_key in drv:
        raise SceneError(f"{key} = {show(text)} already says its sense against the rotation: "
                         f"leave out {sense_key}", file=file, where=f"driver.{sense_key}")
    if omega == 0.0:
        raise SceneError(f"{key} = {show(text)}: '{last}' is measured against the rotation, "
                         f"but the driver is at rest (omega = 0): give alpha's sense, CW or CCW",
                         file=file, where=f"driver.{key}")
    return {**drv, key: f"{head.strip()} {'CCW' if rel * omega > 0 else 'CW'}"}
