"""The dyad kinds: one module each, the only place that knows a dyad's geometry.

``DRIVERS`` place the input; ``SLOT_KINDS`` are tried first in each pass of the planner (they
are found from the scene's slots, not from a point); ``POINT_KINDS`` are tried for each point
not yet placed, in order: the first kind that *claims* the point (by how the scene declares
it) decides whether it can be placed now.  Adding a dyad kind = one module here with its
record (``placed``, ``needs``, ``locate``, ``why_not``, ``emit``) and ``claims``/``match``,
and its tests (README: "Adding a dyad").

A new kind's module registers itself — nothing here is edited: it declares ``ROLE``
('driver', 'slot', 'point' or 'group': which of the tuples below it joins) and, for a point
kind, ``BEFORE`` (the kinds whose points it must be asked about first: a block on a guide
with a slot is asked before the slider crank, which claims every block); every module of
this package that declares ``ROLE`` is found (:func:`_registered`) and its group class (the
one with ``emit``) exported with the others.
"""
from __future__ import annotations

import importlib
import pkgutil

from . import (crank, crossing, guided, image, rpp, rpr, rrp, rrr, slide, slider_drive, triad,
               wheel_pin)
from .crossing import Crossing
from .triad import Triad
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
GROUP_KINDS = (triad,)

Dyad = (CrankDyad | SliderDriveDyad | RRR | RRP | RPR | Image | RPP | Guided | SlideDyad
        | Crossing | Triad | WheelPin)

__all__ = ["CrankDyad", "SliderDriveDyad", "RRR", "RRP", "RPR", "Image", "RPP", "Dyad", "Guided",
           "SlideDyad", "Crossing", "Triad", "WheelPin", "GROUP_KINDS",
           "DRIVERS", "SLOT_KINDS", "POINT_KINDS"]

_ROLES = ("driver", "slot", "point", "group")


def _registered() -> list:
    """The kind modules of this package that register themselves (``ROLE``), in name order
    (the order is fixed: a listing of the package, sorted)."""
    listed = set(DRIVERS + SLOT_KINDS + POINT_KINDS + GROUP_KINDS)
    out = []
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        mod = importlib.import_module(f"{__name__}.{info.name}")
        if mod not in listed and getattr(mod, "ROLE", None) is not None:
            if mod.ROLE not in _ROLES:
                raise TypeError(f"{mod.__name__}.ROLE = {mod.ROLE!r}: one of {_ROLES}")
            out.append(mod)
    return out


def _insert(kinds: tuple, mod) -> tuple:
    """``kinds`` with ``mod`` before the first of its ``BEFORE`` (else last)."""
    names = [k.__name__.rsplit(".", 1)[-1] for k in kinds]
    at = min((names.index(n) for n in getattr(mod, "BEFORE", ()) if n in names),
             default=len(kinds))
    return kinds[:at] + (mod,) + kinds[at:]


def _group_class(mod):
    """The module's group record: the class defined there with ``emit`` and ``placed``."""
    return next(v for v in vars(mod).values()
                if isinstance(v, type) and v.__module__ == mod.__name__
                and hasattr(v, "emit") and hasattr(v, "placed"))


def _register() -> None:
    """Each self-registering module joined to its tuple, its group class exported."""
    global DRIVERS, SLOT_KINDS, POINT_KINDS, GROUP_KINDS, Dyad
    for mod in _registered():
        if mod.ROLE == "driver":
            DRIVERS = _insert(DRIVERS, mod)
        elif mod.ROLE == "slot":
            SLOT_KINDS = _insert(SLOT_KINDS, mod)
        elif mod.ROLE == "point":
            POINT_KINDS = _insert(POINT_KINDS, mod)
        else:
            GROUP_KINDS = _insert(GROUP_KINDS, mod)
        cls = _group_class(mod)
        globals()[cls.__name__] = cls
        Dyad = Dyad | cls
        __all__.append(cls.__name__)


_register()
