"""Every closure of a class-III group, checked at many random poses (issue 28): the closures
of :func:`polygons.dyads.triad_math.all_corners` against a second algebraic route (the same
group eliminated from the corner C instead of B: another polynomial, another φ₀) and, on a
share of the poses, against the independent dense scan of the coupler curve
(tests/analytic_triad.scan_closures).  Half the groups are random, half have two closures
a hair apart (the X link's length within 1e-9 … 1e-5 m of an extremum of |X − E|).

    python benchmarks/triad_closures.py [N] [scan_every]       # default 100000 poses, 1 in 200 scanned

Prints the counts: poses, closures, poses where the two routes disagree, where the scan
disagrees, the closest two closures listed, and the time per pose.
"""
from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import analytic_triad as at                                    # noqa: E402
from polygons.dyads.triad_math import all_corners, separation  # noqa: E402


def random_group(rng, close: bool):
    """(A, a, D, d, E, e, L, ξ, η): random, or with two closures a hair apart
    (tests/analytic_triad.close_group on 181 coupler angles)."""
    if close:
        return at.close_group(rng, samples=181)
    A = rng.uniform(-0.1, 0.1, 2)
    D = rng.uniform(0.2, 0.4, 2) * [1, rng.choice([-1, 1])]
    E = rng.uniform(-0.2, 0.4, 2)
    a, d, L = rng.uniform(0.08, 0.3, 3)
    xi, eta = rng.uniform(-0.1, 0.2), rng.uniform(-0.15, 0.15)
    return A, a, D, d, E, rng.uniform(0.05, 0.4), L, xi, eta


def tally(counts: dict, one, two, scanned=None) -> float:
    """One pose added to ``counts``: its closures by the first route (B's corner), whether
    the second route (C's corner: C and B swapped) lists the same ones to 1e-9, and — given
    ``scanned``, the dense scan's count — whether the scan agrees.  Returns the separation of
    the pose's two closest closures."""
    counts["poses"] += 1
    counts["closures"] += len(one)
    counts["routes_disagree"] += not (len(one) == len(two) and all(
        min(max(math.dist(c[0], o[1]), math.dist(c[2], o[2])) for o in two) < 1e-9
        for c in one))
    if scanned is not None:
        counts["scanned"] += 1
        counts["scan_disagree"] += scanned != len(one)
    return separation(one)


def main(n: int = 100_000, scan_every: int = 200, seed: int = 28) -> dict:
    rng = np.random.default_rng(seed)
    counts = dict(poses=0, closures=0, routes_disagree=0, scanned=0, scan_disagree=0)
    closest = math.inf
    t0 = time.perf_counter()
    for i in range(n):
        A, a, D, d, E, e, L, xi, eta = random_group(rng, close=i % 2 == 1)
        one = all_corners((*A, a, *D, d, *E, e, L, xi, eta, 0.0), 0.5)
        # the same group from the corner C: C at the origin of the plate, B at (L, 0)
        two = all_corners((*D, d, *A, a, *E, e, L, L - xi, -eta, 0.0), 0.5)
        scanned = (len(at.scan_closures(A, a, D, d, E, e, L, xi, eta, n=360))
                   if scan_every and i % scan_every == 0 else None)
        closest = min(closest, tally(counts, one, two, scanned))
    counts["closest_m"] = closest
    counts["us_per_pose"] = 1e6 * (time.perf_counter() - t0) / max(n, 1)
    return counts


def run(main) -> None:
    """``main(POSES, SCAN_EVERY)`` from the command line, its usage said on a bad argument."""
    try:
        args = [int(a) for a in sys.argv[1:3]]
        if any(a < 0 or a > 10_000_000 for a in args):
            raise ValueError
    except ValueError:
        sys.exit(f"usage: python {sys.argv[0]} [POSES [SCAN_EVERY]]  (whole numbers, 0 … 10^7)")
    print(main(*args))


if __name__ == "__main__":
    run(main)
