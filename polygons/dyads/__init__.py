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
this package that declares ``ROLE`` is found (:func:`discovered`) and its group class (the
one with ``emit``) exported with the others.

What discovery finds is written once into a static index, ``_index.py``
(``python -m polygons.dyads`` writes it; tests/test_cold_start.py holds it equal to
discovery), so that the planner imports a kind's module only when it first asks that kind
(:func:`kinds`): a crank's scene never imports the slider driver, a scene whose points the
dyads place never imports the triads.  The tuples, ``Dyad`` and the group classes are
resolved on first access (every kind of a role imported then).
"""
from __future__ import annotations

import importlib

from ._index import CLASSES, ORDER

#: the kinds the planner named before any registered itself (their modules declare no
#: ``ROLE``), in its order; the self-registered ones join by their ``ROLE`` and ``BEFORE``
BUILT_IN = {"driver": ("crank", "slider_drive"),
            "slot": ("rpr", "slide"),
            "point": ("wheel_pin", "rpp", "image", "rrp", "guided", "crossing", "rrr"),
            "group": ("triad",)}
_ROLES = tuple(BUILT_IN)
#: the exported tuples of kind modules, by role
TUPLES = {"DRIVERS": "driver", "SLOT_KINDS": "slot", "POINT_KINDS": "point",
          "GROUP_KINDS": "group"}
#: group class -> its module
_MODULE_OF = {cls: mod for mod, cls in CLASSES.items()}

__all__ = [*_MODULE_OF, "Dyad", "GROUP_KINDS", "DRIVERS", "SLOT_KINDS", "POINT_KINDS"]

_loaded: dict = {}


def kind(name: str):
    """The kind module ``name`` (``'rrr'``), imported on first use."""
    mod = _loaded.get(name)
    if mod is None:
        mod = _loaded[name] = importlib.import_module(f"{__name__}.{name}")
    return mod


def kinds(role: str):
    """The kind modules of ``role`` ('driver', 'slot', 'point', 'group') in the planner's
    order, each imported when the iteration reaches it."""
    for name in ORDER[role]:
        yield _loaded.get(name) or kind(name)


def __getattr__(name: str):
    """``DRIVERS`` … ``GROUP_KINDS`` (every kind of the role imported), ``Dyad`` (the union of
    every group class), a group class (``RRR``) or a kind module (``rrr``), on first access."""
    if name in TUPLES:
        value = tuple(kinds(TUPLES[name]))
    elif name == "Dyad":
        value = None
        for mod, cls in CLASSES.items():
            c = getattr(kind(mod), cls)
            value = c if value is None else value | c
    elif name in _MODULE_OF:
        value = getattr(kind(_MODULE_OF[name]), name)
    elif name in CLASSES:
        value = kind(name)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__) | set(CLASSES))


# ---------------------------------------------------------------- discovery (the index's source)
def _registered() -> list:
    """The kind modules of this package that register themselves (``ROLE``), in name order
    (the order is fixed: a listing of the package, sorted)."""
    import pkgutil
    built_in = {n for names in BUILT_IN.values() for n in names}
    out = []
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        if info.name.startswith("_") or info.name in built_in:
            continue
        mod = importlib.import_module(f"{__name__}.{info.name}")
        if getattr(mod, "ROLE", None) is not None:
            if mod.ROLE not in _ROLES:
                raise TypeError(f"{mod.__name__}.ROLE = {mod.ROLE!r}: one of {_ROLES}")
            out.append(mod)
    return out


def _insert(names: tuple, name: str, before) -> tuple:
    """``names`` with ``name`` before the first of ``before`` (else last)."""
    at = min((names.index(n) for n in before if n in names), default=len(names))
    return names[:at] + (name,) + names[at:]


def _group_class(mod) -> str:
    """The module's group record: the class defined there with ``emit`` and ``placed``."""
    return next(k for k, v in vars(mod).items()
                if isinstance(v, type) and v.__module__ == mod.__name__
                and hasattr(v, "emit") and hasattr(v, "placed"))


def discovered() -> tuple[dict, dict]:
    """(ORDER, CLASSES) as discovery finds them: :data:`BUILT_IN`, then every module that
    declares ``ROLE`` joined to its role before the first of its ``BEFORE`` (else last); each
    kind module's group class.  Imports every module of the package."""
    order = dict(BUILT_IN)
    for mod in _registered():
        short = mod.__name__.rsplit(".", 1)[-1]
        order[mod.ROLE] = _insert(order[mod.ROLE], short, getattr(mod, "BEFORE", ()))
    classes = {}
    for role in _ROLES:
        for short in order[role]:
            classes[short] = _group_class(importlib.import_module(f"{__name__}.{short}"))
    return order, classes


def index_source() -> str:
    """The text of ``_index.py`` for what :func:`discovered` finds."""
    order, classes = discovered()
    lines = ['"""The dyad kinds, as discovery finds them (polygons.dyads.discovered): written by',
             "``python -m polygons.dyads``; do not edit (tests/test_cold_start.py holds it equal",
             'to discovery)."""', "",
             "#: role -> kind modules, in the order the planner asks them", "ORDER = {"]
    lines += [f"    {role!r}: {tuple(names)!r}," for role, names in order.items()]
    lines += ["}", "#: kind module -> its group class", "CLASSES = {"]
    lines += [f"    {mod!r}: {cls!r}," for mod, cls in classes.items()]
    lines += ["}", ""]
    return "\n".join(lines)
