"""Every kind × every method: each method handles a kind of dyad, body and pair or refuses it
in one line naming both (polygons.model.check_handles) — never leaves it out silently.

A representative shipped case is taken for every dyad kind the planner knows and for every
kind of body and pair the mechanism model builds; each method runs on it and must either
finish or raise an ``UnsupportedError`` whose words name the method and the kind.
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from polygons import dyads
from polygons.errors import UnsupportedError
from polygons.evaluate import solve
from polygons.model import BUILT, KIND_WORDS
from polygons.scene import load_scene, parse_scene

CASES = sorted((Path(__file__).resolve().parents[1] / "cases").glob("*.toml"))


def _dyad_kinds() -> set[str]:
    mods = dyads.DRIVERS + dyads.SLOT_KINDS + dyads.POINT_KINDS
    return {name for name in dyads.__all__ if isinstance(getattr(dyads, name), type)
            and any(getattr(m, name, None) is getattr(dyads, name) for m in mods)}


def _kinds_of(path: Path) -> set[str]:
    scene = load_scene(path)
    sol = solve(scene)
    return ({type(d).__name__ for d in sol.plan.dyads} | set(scene.model.kinds))


KINDS = {p: _kinds_of(p) for p in CASES}
#: a cam stated by its profile last: its equivalent crank takes no mass of its own (_loaded)
CAM_LAST = sorted(CASES, key=lambda p: "[cam_profiles" in p.read_text(encoding="utf-8"))


def _representatives() -> dict[str, Path]:
    out: dict[str, Path] = {}
    for p in CAM_LAST:
        for k in sorted(KINDS[p]):
            out.setdefault(k, p)
    return out


REPS = _representatives()


def test_every_dyad_kind_and_every_built_body_and_pair_kind_has_a_case():
    assert _dyad_kinds() - set(REPS) == set()
    assert set(BUILT) - set(REPS) == set()


# ---------------------------------------------------------------- the methods
def _loaded(path: Path):
    """The case's scene, with a mass added when it has none."""
    text = path.read_text(encoding="utf-8")
    if "[masses" not in text:                   # give the force analysis something to do
        moving = load_scene(path).model.moving
        body = next((b for b in moving if b.kind == "link" and b.length), None) or next(
            (b for b in moving if b.kind == "block"), None)
        if body is None:                        # a lever without a length: its centre
            text += f'\n[masses.{moving[0].name}]\nmass = "1 kg"\ncentre = "10 mm"\n'
        else:
            text += f'\n[masses.{body.name}]\nmass = "1 kg"\n'
    import tomllib
    return parse_scene(tomllib.loads(text), file=str(path))


def _forces(path: Path):
    from polygons.forces.analysis import analyse
    analyse(_loaded(path))


def _force_polygons(path: Path):
    from polygons.forces import graphical
    from polygons.forces.analysis import analyse
    an = analyse(_loaded(path))
    for st in an.states:
        graphical.construct(an, st)


def _centres(path: Path):
    from polygons.centres import instant_centres
    instant_centres(solve(load_scene(path)))


def _space(path: Path):
    from diagrams.space import drawing
    drawing(solve(load_scene(path)))


def _board(path: Path):
    from polygons.drawing_board import emulate
    from polygons.position import driver_input
    scene = load_scene(path)
    emulate(scene, [driver_input(scene)], trials=2)


def _compiled(path: Path):
    from polygons.compiled import compile_scene
    scene = load_scene(path)
    prog = compile_scene(scene)
    assert prog is not None


_OK: dict = {}


def _analysed_ok(path: Path) -> bool:
    if path not in _OK:
        try:
            _forces(path)
            _OK[path] = True
        except UnsupportedError:
            _OK[path] = False
    return _OK[path]


METHODS = {"polygons forces": _forces, "polygons centres": _centres,
           "the space diagram": _space, "the drawing-board emulation": _board,
           "the compiled evaluator": _compiled,
           "the force-polygon construction": _force_polygons}


@pytest.mark.parametrize("method", sorted(METHODS))
@pytest.mark.parametrize("kind", sorted(REPS))
def test_each_method_handles_each_kind_or_refuses_it_in_words(kind, method):
    path = REPS[kind]
    if method == "the force-polygon construction":
        # it runs after `polygons forces` (whose own refusals are the row above): a case of
        # this kind that the force analysis takes
        path = next((p for p in CAM_LAST if kind in KINDS[p] and _analysed_ok(p)), None)
        if path is None:
            return
    try:
        METHODS[method](path)
    except UnsupportedError as e:
        msg = str(e)
        assert method in msg, f"{path.name}: the refusal does not name {method!r}: {msg}"
        assert any(w in msg for w in KIND_WORDS.values()), \
            f"{path.name}: the refusal does not name a kind in words: {msg}"
        assert "\n" not in msg and "Dyad" not in msg and "dyad" not in msg.split(":")[-1]


def test_a_refusal_names_the_method_and_the_kind():
    from polygons.model import check_handles
    scene = load_scene(REPS["collar"])
    with pytest.raises(UnsupportedError) as e:
        check_handles("polygons forces", BUILT - {"collar"}, scene.model)
    assert "polygons forces does not handle a collar driven along a link" in str(e.value)
    check_handles("the space diagram", BUILT, scene.model)      # handled: no error


def test_the_model_of_a_quick_return():
    m = load_scene(next(p for p in CASES if p.stem == "s003-fig7")).model
    assert [b.kind for b in m.bodies] == ["frame", "link", "lever", "pin-block"]
    (slot,) = m.slots()
    assert (slot.at, slot.carrier, slot.block, slot.coincident) == ("P2", "O4P4", "block P2",
                                                                   "P4")
    assert sorted((t.label, t.bodies) for t in m.turning) == [
        ("O2", ("frame", "O2P2")), ("O4", ("frame", "O4P4")), ("P2", ("O2P2", "block P2"))]
    pos = {"O4": (0.0, 0.0), "P2": (0.3, 0.4)}
    through, e = slot.line.at(pos)
    assert through == (0.0, 0.0) and math.isclose(e[0], 0.6) and math.isclose(e[1], 0.8)


def test_the_model_is_frozen():
    m = load_scene(CASES[0]).model
    with pytest.raises(Exception):
        m.bodies = ()           # type: ignore[misc]
