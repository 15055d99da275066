"""Every kind across its domain (issue 28, item 6; the checks in tests/domain.py): a random
mechanism of each kind at random poses, within 1e-6° of each end of what ``solve`` answers and
at each parallel pair — ``solve`` against the sweep's row, rates against finite differences of
positions, bodies against their rigidity, higher-pair outputs against their differentiated
geometry; nowhere a silent disagreement.  One mechanism per kind here (a few seconds);
``POLYGONS_DEEP=1`` four; benchmarks/domain_checks.py runs ≥ 10⁵ poses."""
import pytest

import domain
from conftest import DEEP

MECHANISMS = 4 if DEEP else 1
#: kinds an everyday run leaves to their own tests (the case of the triad with a block:
#: tests/test_triad_slider.py checks it against its oracle, finite differences and the sweep)
DEEP_ONLY = {"triad-slider"}


@pytest.mark.parametrize("kind", list(domain.KINDS))
def test_no_silent_disagreement_across_the_domain(kind):
    if kind in DEEP_ONLY and not DEEP:
        pytest.skip("checked by its own tests; POLYGONS_DEEP=1 runs it here too")
    # (an everyday run: a coarse scan, one random pose, the ends and parallel pairs it finds)
    out = domain.run([kind], range(50), 3 if DEEP else 1, limit=MECHANISMS,
                     grid=48 if DEEP else 12)
    silent = [o for o in out if o.verdict == "silent"]
    assert not silent, "\n".join(o.replay for o in silent)
    # the checks ran: some pose of the kind agreed on every count, with checks made
    assert any(o.verdict == "agree" and o.checks > 0 for o in out), [o.replay for o in out]
    # and the hard poses were reached: beside an end, or at a parallel pair, for most kinds
    assert {o.why for o in out} >= {"random"}


def test_the_check_finds_a_wrong_contact_number(monkeypatch):
    """The old bearing output (the contact point's speed along the bar reported as the
    sliding velocity) is a silent disagreement for the check."""
    import polygons.higher as contacts
    right = contacts.bearing

    def old(sol, q):
        h = right(sol, q)
        if h is not None:
            h = dict(h, sliding_velocity=h["contact_velocity_along_bar"])
        return h
    monkeypatch.setattr(contacts, "bearing", old)
    out = domain.run(["bearing"], range(50), 3, limit=1)
    assert any(o.verdict == "silent" and "sliding_velocity" in o.detail for o in out)


def test_the_check_finds_a_wrong_rate(monkeypatch):
    """A velocity off by 1e-4 of itself, at every pose, is caught (finite differences)."""
    from polygons.evaluate import PointResult, Solution
    real = Solution.points

    def points(self):
        pts = dict(real.func(self))
        p = pts["C"]
        if p.velocity is not None:
            pts["C"] = PointResult(p.position, (p.velocity[0] * (1 + 1e-4), p.velocity[1]),
                                   p.acceleration)
        return pts
    monkeypatch.setattr(Solution, "points", property(points))
    out = domain.run(["rrr"], range(50), 3, limit=1)
    assert any(o.verdict == "silent" and "v(C)" in o.detail for o in out)


@pytest.mark.parametrize("seed, theta", [(1, 6.060844313563413), (6, 1.6355113561284838),
                                         (16, 4.6754682837414006), (23, 2.2362720482893357),
                                         (25, 3.7455932777206318)])
def test_a_triad_at_a_parallel_pair_keeps_the_nearest_closure(seed, theta):
    """The large run's five silent poses (the triad's closures found by sampling missed the one
    with AB ∥ DC, and near took another up to 0.75 m away): now found algebraically."""
    mech = domain.make("triad-random", seed)
    out = domain.check(mech, theta, 1.0, "at a parallel pair")
    assert out.verdict != "silent", out.replay


def test_a_triad_near_a_parallel_pair_keeps_the_nearest_closure():
    """Found by the domain check (triad-random seed 1): at θ = 6.060844808734302 rad solve,
    asked for X near the point it was built at, gives X 0.1199 m from it, while 1e-3 rad
    either side a closure 0.0074 m from it exists and is followed back to θ by the sweep."""
    mech = domain.make("triad-random", 1)
    out = domain.check(mech, 6.060844808734302, 1.0, "at a parallel pair")
    assert out.verdict != "silent", out.replay
