"""Every closure of a class-III group with a block on a guide at a corner (two links and a
block), checked at many random poses as benchmarks/triad_closures.py checks the three-link
triad's: the closures of :func:`polygons.dyads.triad_slider_math.all_corners` against a second
algebraic route (the same group eliminated from the corner C instead of B: another polynomial,
another φ₀) and, on a share of the poses, against the independent dense scan of the four-bar's
coupler curve against the guide (tests/analytic_triad_slider.scan_closures).  Half the groups
are random, half have two closures a hair apart (the guide within 1e-9 … 1e-5 m of an extremum
of the coupler curve's distance from it).

    python benchmarks/triad_slider_closures.py [N] [scan_every]   # default 100000, 1 in 200

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

import analytic_triad_slider as ats                                # noqa: E402
from triad_closures import run, tally                              # noqa: E402
from polygons.dyads.triad_slider_math import all_corners           # noqa: E402


def main(n: int = 100_000, scan_every: int = 200, seed: int = 28) -> dict:
    rng = np.random.default_rng(seed)
    counts = dict(poses=0, closures=0, routes_disagree=0, scanned=0, scan_disagree=0)
    closest = math.inf
    t0 = time.perf_counter()
    for i in range(n):
        A, a, D, d, G, nn, L, xi, eta = ats.random_group(rng, close=i % 2 == 1)
        e = (nn[1], -nn[0])
        one = all_corners((*A, a, *D, d, *G, *e, L, xi, eta, 0.0), 0.5)
        # the same group from the corner C: C at the origin of the plate, B at (L, 0)
        two = all_corners((*D, d, *A, a, *G, *e, L, L - xi, -eta, 0.0), 0.5)
        scanned = (len(ats.scan_closures(A, a, D, d, G, nn, L, xi, eta, samples=360))
                   if scan_every and i % scan_every == 0 else None)
        closest = min(closest, tally(counts, one, two, scanned))
    counts["closest_m"] = closest
    counts["us_per_pose"] = 1e6 * (time.perf_counter() - t0) / max(n, 1)
    return counts


if __name__ == "__main__":
    run(main)
