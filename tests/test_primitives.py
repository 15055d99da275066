"""The typed primitives a group's position is stated in (polygons/dyads/primitives.py): each
one's numpy ``locate`` meets its defining equations, and its generated ``source`` gives the
same point to 1e-12 — one statement, two interpreters."""
from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest

from polygons import dyads
from polygons.codegen import Source
from polygons.dyads.primitives import (PRIMITIVES, AlongLink, CircleCircle, CircleLine,
                                       Constructed, FixedLine, Guarded, LeverLine, Length,
                                       LineLine, LinesMeet, PinInSlot, Prescribed, RigidImage, RimPoint,
                                       Rotation, SlotUnstated, Translation, WheelRim,
                                       AssurPoint, CornerFrame, PlateShape, Then, TriadClosure,
                                       TriadSliderClosure)
from polygons.dyads.numeric import Stated

class _Scene(NS):
    """A scene's tables, as the primitives read them (a weak reference allowed: memos)."""


SCENE = _Scene(links={"PX": NS(length=0.9), "QX": NS(length=0.7), "OA": NS(length=0.3)},
           sliders={"X": NS(through=(0.1, -0.2), direction=(math.cos(0.3), math.sin(0.3)),
                            slot_direction=(math.cos(1.4), math.sin(1.4)))},
           points={"X": NS(along=None, fraction=0.4, left=0.15)},
           slots={"X": NS(offset=0.05, length=None),
                  "A": NS(offset=0.0, length=None, far_length=0.8)}, prescribed={"X": NS(position=0.3)},
           equivalents=[NS(kind="rolling", driven=True, radius=0.2, rim=[("X", 0.5, 0.15)])],
           ground={"P": (0.0, 0.0)})
POS = {"P": np.array([0.0, 0.0]), "Q": np.array([1.0, 0.2]), "A": np.array([0.3, 0.5]),
       "D": np.array([1.2, 1.1])}


def _triad_links():
    """A class-III group on the outer points P, Q, A: corners X, C, Y, the plate XC carrying
    Y ([points.Y]), its links' lengths read off one pose of it (X, C chosen, Y the plate's
    point)."""
    B, C = np.array([0.2, 0.6]), np.array([0.9, 0.7])
    L = float(np.hypot(*(C - B)))
    u = (C - B) / L
    X = B + 0.4 * L * u + 0.15 * np.array([-u[1], u[0]])
    SCENE.links.update(XC=NS(length=L), PX_=NS(length=float(np.hypot(*(B - POS["P"])))),
                       QC=NS(length=float(np.hypot(*(C - POS["Q"])))),
                       AY=NS(length=float(np.hypot(*(X - POS["A"])))))
    SCENE.points["Y"] = NS(along=None, fraction=0.4, left=0.15, label="Y")
    SCENE.links["XC"].a, SCENE.links["XC"].b = "X", "C"
    SCENE.sliders["Y"] = NS(through=(float(X[0]) - 0.3, float(X[1]) - 0.1),
                            direction=(0.3 / math.hypot(0.3, 0.1), 0.1 / math.hypot(0.3, 0.1)))


_triad_links()
TRIAD = TriadClosure(("X", "C", "Y"), ("P", "Q", "A"),
                     (Length("PX_"), Length("QC"), Length("AY")), PlateShape("Y", ("XC",)),
                     ("X#bx", "X#by", "X#xx", "X#xy"))


#: the triad with a block: corners X, C on links to P, Q; the plate's point Y a block on the
#: guide through the pose's Y
SLIDER_TRIAD = TriadSliderClosure(("X", "C", "Y"), ("P", "Q"), (Length("PX_"), Length("QC")),
                                  FixedLine("Y"), CornerFrame("X", "C", "Y", ("XC",)),
                                  ("X#bx", "X#by", "X#xx", "X#xy"))


def generated(prim, sigma=1.0, x=0.7, label=None):
    """The point ``prim.source`` writes, run as a program over floats."""
    g = Source(SCENE, {prim.x: sigma})
    for lab, (px, py) in POS.items():
        g.place(lab, g.param(lambda s, v=float(px): v), g.param(lambda s, v=float(py): v))
    g.dyad = NS(two_closures=True)
    prim.source(g)
    params = [sigma if isinstance(get, tuple) else get(SCENE) for get in g.getters]
    ns = dict(g.namespace, x=x, **{f"k{i}": v for i, v in enumerate(params)})
    for line in g.lines:
        exec(line.text, ns)
    xs, ys = g.pos(label or prim.x)
    return np.array([ns[xs], ns[ys]])


CASES = [
    CircleCircle("X", "P", Length("PX"), "Q", Length("QX")),
    CircleLine("X", "A", Length("PX"), FixedLine("X")),
    Rotation("X", "P", Length("OA")),
    Translation("X", FixedLine("X")),
    LineLine("X", "A", FixedLine("X")),
    RigidImage("X", "P", "Q"),
    LinesMeet("X", "P", "Q", "A", "P", also=("X1",)),
    AlongLink("X", "P", "Q", Prescribed("X"), also=("X1",)),
    RimPoint("X", "A", WheelRim("X")),
    Guarded(CircleLine("X", "A", Length("PX"), LeverLine("X", "P", "Q"), also=("X1",)),
            SlotUnstated("X")),
    PinInSlot("X", "A", "P", "F"),
    TRIAD,
    SLIDER_TRIAD,
    AssurPoint("X", "P", "A", "Q", "D"),
    AssurPoint("X", "P", "A", "D", "D", normal=FixedLine("X")),
    Then((CircleCircle("X", "P", Length("PX"), "Q", Length("QX")),
          AssurPoint("X1", "P", "X", "Q", "A"))),
]


@pytest.mark.parametrize("offset", [0.0, 0.1])
def test_a_lever_through_its_pin(offset):
    """PinInSlot: X = A, the far end F at the lever's length along the slot (offset δ from
    the pivot: F − P = l e with (A − P) = t e + δ perp(e)); locate = source."""
    SCENE.slots["A"].offset = offset
    try:
        prim = PinInSlot("X", "A", "P", "F")
        pts, m = prim.locate(SCENE, POS, 1.0, 0.0)
        A, P = POS["A"], POS["P"]
        e = (pts["F"] - P) / 0.8
        assert np.allclose(pts["X"], A) and math.isclose(np.hypot(*e), 1.0) and m > 0
        assert math.isclose(_cross(e, A - P), offset, abs_tol=1e-15)
        assert np.max(np.abs(generated(prim) - pts["X"])) <= 1e-12
        assert np.max(np.abs(generated(prim, label="F") - pts["F"])) <= 1e-12
    finally:
        SCENE.slots["A"].offset = 0.0


def test_every_primitive_is_tested():
    assert {type(c) for c in CASES} == set(PRIMITIVES)


@pytest.mark.parametrize("prim", CASES, ids=lambda p: type(p).__name__)
@pytest.mark.parametrize("sigma", [1.0, -1.0])
def test_locate_and_source_agree(prim, sigma):
    X = prim.locate(SCENE, POS, sigma, 0.7)[0]["X"]
    assert np.max(np.abs(generated(prim, sigma) - X)) <= 1e-12


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _at(prim, sigma, x):
    pts, m = prim.locate(SCENE, POS, sigma, x)
    return pts["X"], m


def test_each_primitive_meets_its_equations():
    P, Q, A = POS["P"], POS["Q"], POS["A"]
    X, m = _at(CASES[0], 1.0, 0.0)
    assert math.isclose(np.hypot(*(X - P)), 0.9) and math.isclose(np.hypot(*(X - Q)), 0.7)
    assert m > 0 and _cross(Q - P, X - P) > 0              # σ = +1: left of P→Q
    g = SCENE.sliders["X"]
    X, _ = _at(CASES[1], 1.0, 0.0)
    assert math.isclose(np.hypot(*(X - A)), 0.9)
    assert abs(_cross(g.direction, X - np.array(g.through))) < 1e-12
    X, _ = _at(CASES[2], 1.0, 0.7)
    assert np.allclose(X, 0.3 * np.array([math.cos(0.7), math.sin(0.7)]), atol=1e-15)
    X, _ = _at(CASES[3], 1.0, 0.7)
    assert np.allclose(X, np.array(g.through) + 0.7 * np.array(g.direction), atol=1e-15)
    X, m = _at(CASES[4], 1.0, 0.0)
    assert abs(_cross(g.direction, X - np.array(g.through))) < 1e-12    # on the guide
    assert abs(_cross(g.slot_direction, X - A)) < 1e-12                 # under the slot
    X, _ = _at(CASES[5], 1.0, 0.0)
    u = (Q - P) / np.hypot(*(Q - P))
    assert math.isclose((X - P) @ u, 0.4 * np.hypot(*(Q - P)))
    assert math.isclose(_cross(u, X - P), 0.15)
    X, m = _at(CASES[6], 1.0, 0.0)                    # on both lines P→Q and A→P
    assert abs(_cross(Q - P, X - P)) < 1e-12 and abs(_cross(P - A, X - A)) < 1e-12 and m > 0
    X, m = _at(CASES[7], 1.0, 0.0)
    assert np.allclose(X, P + 0.3 * u, atol=1e-15) and m > 0
    X, _ = _at(CASES[8], 1.0, 0.4)                    # φ = φ₀ − s/r
    assert np.allclose(X, A + 0.15 * np.array([math.cos(0.5 - 2.0), math.sin(0.5 - 2.0)]))
    X, m = _at(CASES[9], 1.0, 0.0)                    # |AX| = 0.9, on the slot offset 0.05
    assert math.isclose(np.hypot(*(X - A)), 0.9) and math.isclose(_cross(u, X - P), 0.05)
    SCENE.slots["X"].length = 0.2                      # a stated slot length: refused
    try:
        assert _at(CASES[9], 1.0, 0.0)[1] == -1.0
    finally:
        SCENE.slots["X"].length = None


def test_a_sweep_of_positions_is_the_same_primitive():
    xs = np.linspace(0.0, 6.0, 7)
    cols = {k: v.reshape(2, 1) for k, v in POS.items()}        # a fixed point in a sweep
    X = CASES[2].locate(SCENE, cols, 1.0, xs)[0]["X"]
    for i, x in enumerate(xs):
        assert np.max(np.abs(X[:, i] - _at(CASES[2], 1.0, float(x))[0])) < 1e-15


def test_the_groups_stated_in_primitives():
    """Their locate and source are the primitive's (no second statement in the module)."""
    for kind in (dyads.RRR, dyads.RRP, dyads.CrankDyad, dyads.SliderDriveDyad, dyads.RPP,
                 dyads.Image, dyads.Guided, dyads.Crossing, dyads.SlideDyad, dyads.WheelPin,
                 dyads.RPR):
        assert issubclass(kind, Constructed)
        assert "locate" not in vars(kind) and "source" not in vars(kind)


def test_every_primitive_has_one_statement():
    """Every primitive is written once, as ``source``: ``locate`` is that statement evaluated
    (polygons.dyads.numeric), never a second, hand-written formula."""
    from polygons.dyads.slot_slider import SlotCrossesGuide
    for kind in (*PRIMITIVES, SlotCrossesGuide):
        assert issubclass(kind, Stated), kind.__name__
        own = [c for c in kind.__mro__ if c is not Stated and issubclass(c, Stated)]
        assert any("source" in vars(c) for c in own), kind.__name__      # (its own or its
        assert not any("locate" in vars(c) for c in own), kind.__name__  # family's)
        assert kind.locate is Stated.locate, kind.__name__
    assert "source" in vars(dyads.Triad) and isinstance(
        dyads.Triad("B", "C", "X", "P", "Q", "A", "PB", "QC", "AX", "BC", ("BC",), "S",
                    True).construction, Then)


@pytest.mark.parametrize("prim", CASES, ids=lambda p: type(p).__name__)
def test_the_compiled_statement_is_the_statement(prim):
    """``locate`` runs the statement written down once per primitive (numeric.Traced); it is
    the statement evaluated name by name (numeric.Numeric) to the last bit, over one position
    and over a sweep."""
    from polygons.dyads.numeric import Numeric
    xs = np.linspace(-0.02, 0.02, 3)
    sweep = {k: v.reshape(2, 1) + np.array([xs, 0.5 * xs]) for k, v in POS.items()}
    for pos, x, arrays in ((POS, 0.7, False), (sweep, 0.7 + xs, True)):
        sigma = {k: 0.1 for k in getattr(prim, "keys", ())} or 1.0
        g = Numeric(SCENE, pos, sigma, x, arrays)
        m = prim.source(g)
        pts, m2 = prim.locate(SCENE, pos, sigma, x)
        assert set(pts) == set(g.placed)
        for k, (a, b) in g.placed.items():
            assert np.array_equal(np.broadcast_to(pts[k], np.shape(pts[k])),
                                  np.array(np.broadcast_arrays(a, b), dtype=float),
                                  equal_nan=True), (type(prim).__name__, k)
        assert (m is None and m2 is None) or np.array_equal(np.broadcast_to(m, np.shape(m2)), m2,
                                                           equal_nan=True)
        if arrays and m2 is not None:                  # over a sweep: a margin per position
            assert np.shape(m2) == (len(xs),), type(prim).__name__


def test_the_triads_closure_and_assur_point_meet_their_equations():
    """TriadClosure: |PX|, |QC|, |AY| their links' lengths and Y the plate's point (each
    closure of every()); AssurPoint: S on both lines produced."""
    P, Q, A = POS["P"], POS["Q"], POS["A"]
    closures = TRIAD.every(SCENE, POS)
    assert len(closures) >= 2
    for c in closures:
        B, C, X = c["X"], c["C"], c["Y"]
        for a, b, link in ((P, B, "PX_"), (Q, C, "QC"), (A, X, "AY"), (B, C, "XC")):
            assert math.isclose(np.hypot(*(b - a)), SCENE.links[link].length, abs_tol=1e-12)
        u = (C - B) / np.hypot(*(C - B))
        assert math.isclose((X - B) @ u, 0.4 * SCENE.links["XC"].length, abs_tol=1e-12)
        assert math.isclose(_cross(u, X - B), 0.15, abs_tol=1e-12)
        ref = dict(zip(TRIAD.keys, (B[0], B[1], X[0], X[1])))
        pts, m = TRIAD.locate(SCENE, POS, ref, 0.0)      # the closure nearest its own corners
        assert m > 0 and max(np.max(np.abs(pts[k] - c[k])) for k in "XCY") <= 1e-12
        S = AssurPoint("S", "P", "X", "Q", "C").locate(SCENE, {**POS, **c}, None, 0.0)[0]["S"]
        assert abs(_cross(B - P, S - P)) <= 1e-12 and abs(_cross(C - Q, S - Q)) <= 1e-12


def test_the_triad_with_a_blocks_closure_and_assur_point_meet_their_equations():
    """TriadSliderClosure: |PX|, |QC| their links' lengths, Y the plate's point and on its
    guide (each closure of every()), the one nearest its own corners found again;
    AssurPoint with ``normal``: S on PX produced and on the guide's normal at Y."""
    P, Q = POS["P"], POS["Q"]
    g = SCENE.sliders["Y"]
    closures = SLIDER_TRIAD.every(SCENE, POS)
    assert len(closures) >= 2
    for c in closures:
        B, C, X = c["X"], c["C"], c["Y"]
        for a, b, link in ((P, B, "PX_"), (Q, C, "QC"), (B, C, "XC")):
            assert math.isclose(np.hypot(*(b - a)), SCENE.links[link].length, abs_tol=1e-12)
        u = (C - B) / np.hypot(*(C - B))
        assert math.isclose((X - B) @ u, 0.4 * SCENE.links["XC"].length, abs_tol=1e-12)
        assert math.isclose(_cross(u, X - B), 0.15, abs_tol=1e-12)
        assert abs(_cross(g.direction, X - np.array(g.through))) <= 1e-12
        ref = dict(zip(SLIDER_TRIAD.keys, (B[0], B[1], X[0], X[1])))
        pts, m = SLIDER_TRIAD.locate(SCENE, POS, ref, 0.0)
        assert m > 0 and max(np.max(np.abs(pts[k] - c[k])) for k in "XCY") <= 1e-12
        S = AssurPoint("S", "P", "X", "Y", "Y", normal=FixedLine("Y")).locate(
            SCENE, {**POS, **c}, None, 0.0)[0]["S"]
        assert abs(_cross(B - P, S - P)) <= 1e-12 and abs((S - X) @ g.direction) <= 1e-12


def test_a_stated_primitive_over_a_sweep_is_itself_at_each_position():
    """Over (2, N) positions the same statement runs on arrays (numpy's names, the closure
    followed by triad_cols): each column its one-position value."""
    xs = np.linspace(-0.02, 0.02, 5)
    pos = {k: v.reshape(2, 1) + np.array([xs, 0.5 * xs]) for k, v in POS.items()}
    for prim in (TRIAD, SLIDER_TRIAD, *CASES[-3:]):
        sig = 1.0
        pts, _ = prim.locate(SCENE, pos, sig, 0.3)
        for i in range(len(xs)):
            one = {k: v[:, i] for k, v in pos.items()}
            got, _ = prim.locate(SCENE, one, sig, 0.3)
            for k, v in got.items():
                assert np.max(np.abs(pts[k][:, i] - v)) <= 1e-12, (type(prim).__name__, k, i)


def test_the_triad_with_a_block_is_stated_once():
    """The triad with a block writes its position once, as ``source``: its ``locate`` (after
    choosing the reference closure) is that statement evaluated, to the last bit."""
    from pathlib import Path
    from polygons.dyads.numeric import interpret
    from polygons.dyads.triad_slider import TriadSlider
    from polygons.evaluate import solve
    from polygons.scene import load_scene
    case = Path(__file__).resolve().parents[1] / "cases" / "triad-slider-corner.toml"
    sol = solve(load_scene(str(case)))
    groups = [d for d in sol.plan.dyads if isinstance(d, TriadSlider)]
    assert groups and "source" in vars(TriadSlider)
    for grp in groups:
        pos = {k: np.asarray(v, dtype=float) for k, v in sol.placement.points.items()}
        sigma = dict(zip(grp.sigma_keys, (*pos[grp.b], *pos[grp.x])))
        pts, m = grp.locate(sol.scene, pos, sigma, 0.0)
        want, m2 = interpret(grp, sol.scene, pos, sigma, 0.0)
        assert m == m2 and all(np.array_equal(pts[k], want[k]) for k in want)
        assert all(np.allclose(pts[k], pos[k], atol=1e-12) for k in grp.placed)
