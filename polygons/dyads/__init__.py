"""The dyad kinds: one module each, the only place that knows a dyad's geometry.

``DRIVERS`` place the input; ``SLOT_KINDS`` are tried first in each pass of the planner (they
are found from the scene's slots, not from a point); ``POINT_KINDS`` are tried for each point
not yet placed, in order: the first kind that *claims* the point (by how the scene declares
it) decides whether it can be placed now.  Adding a dyad kind = one module here with its
record (``placed``, ``needs``, ``locate``, ``why_not``, ``emit``) and ``claims``/``match``,
its scene keys (new ones in :mod:`polygons.topology`), and its tests (README: "Adding a
dyad").
"""
from __future__ import annotations

from . import (crank, crossing, guided, image, rpp, rpr, rrp, rrr, slide, slider_drive, triad,
               triad_slider, wheel_pin)
from .crossing import Crossing
from .triad import Triad
from .triad_slider import TriadSlider
from .guided import Guided
from .slide import SlideDyad
from .crank import CrankDyad
from .image import Image
from .rpp import RPP
from .rpr import RPR
from .rrp import RRP
from .rrr import RRR
from .slider_drive import SliderDriveDyad
from .wheel_pin import WheelPin

#: modules with ``driver(scene) -> dyad | None``
DRIVERS = (crank, slider_drive)
#: modules with ``matches(scene, placed) -> iterable of dyads`` (tried first in every pass)
SLOT_KINDS = (rpr, slide)
#: modules with ``claims(scene, x)`` and ``match(scene, x, placed, known) -> dyad | None``
POINT_KINDS = (wheel_pin, rpp, image, rrp, guided, crossing, rrr)
#: modules with ``matches(scene, placed)``: groups of a higher class (a triad), tried when no
#: dyad can be placed
GROUP_KINDS = (triad, triad_slider)

Dyad = (CrankDyad | SliderDriveDyad | RRR | RRP | RPR | Image | RPP | Guided | SlideDyad
        | Crossing | Triad | TriadSlider | WheelPin)

__all__ = ["CrankDyad", "SliderDriveDyad", "RRR", "RRP", "RPR", "Image", "RPP", "Dyad", "Guided",
           "SlideDyad", "Crossing", "Triad", "TriadSlider", "WheelPin", "GROUP_KINDS",
           "DRIVERS", "SLOT_KINDS", "POINT_KINDS"]
