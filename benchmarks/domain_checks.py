"""Checks across each kind's whole domain, at scale (issue 28, item 6):
``python benchmarks/domain_checks.py [--poses 100000] [--readme]``.

Random mechanisms of every kind (tests/domain.py: every dyad of polygons/dyads/, random
triads, the bar on a circle, cams, curved slots, rolling wheels, the wheel driver) at random
poses and within 1e-6° of every end of what ``solve`` answers (a toggle, a meeting of two
closures, words that stop choosing) and of every local minimum of the construction's smallest
angle (a parallel pair).  At each pose ``solve`` is held to the sweep's row, every velocity and
acceleration to finite differences of positions, every pair of points of a body to its
rigidity, every higher-pair output to the differentiated geometry (tests/domain.py ``check``).

Counts per kind: agree (every check held), rigid only (the finite differences could not judge
— a step small enough to stay off the singularity rounds too much — and the rigidity checks
held), warned, refused, and **silent** (a check failed where the tool neither warned nor
refused: must be 0; each is printed with its kind, seed and pose to replay).  ``flips``: poses
where the closure the words choose at x ± h is not the one followed from x (informational: the
words' choice jumps there).  ``--readme`` rewrites the README's table between its markers.
"""
from __future__ import annotations

import argparse
import collections
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

import domain  # noqa: E402

VERDICTS = ("agree", "unsure", "warned", "refused", "silent")
TITLES = {"agree": "agree", "unsure": "rigid only", "warned": "warned", "refused": "refused",
          "silent": "**silent**"}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--poses", type=int, default=100_000, help="poses in all (at least)")
    ap.add_argument("--random", type=int, default=12, help="random poses per mechanism")
    ap.add_argument("--kinds", default=",".join(domain.KINDS))
    ap.add_argument("--readme", action="store_true")
    args = ap.parse_args(argv)
    kinds = [k for k in args.kinds.split(",") if k]
    per_kind = max(1, args.poses // len(kinds))
    counts = {k: collections.Counter() for k in kinds}
    mechs = collections.Counter()
    silent, flips = [], collections.Counter()
    t0 = time.perf_counter()
    for kind in kinds:
        seed = 0
        while sum(counts[kind].values()) < per_kind and seed < 100 * per_kind:
            for o in domain.run([kind], [seed], args.random):
                counts[kind][o.verdict] += 1
                flips[kind] += bool(o.flip)
                if o.verdict == "silent":
                    silent.append(o.replay)
            mechs[kind] += domain.make(kind, seed) is not None
            seed += 1
        print(f"{kind:22s} {mechs[kind]:5d} mechanisms {sum(counts[kind].values()):7d} poses  "
              + "  ".join(f"{TITLES[v]} {counts[kind][v]}" for v in VERDICTS)
              + f"  flips {flips[kind]}", flush=True)
    total = sum(sum(c.values()) for c in counts.values())
    secs = time.perf_counter() - t0
    print(f"{total} poses of {sum(mechs.values())} mechanisms in {secs:.0f} s; "
          f"silent disagreements: {len(silent)}")
    for s in silent:
        print("  SILENT", s)
    if args.readme:
        from protocol import write_readme_section
        rows = ["| kind | mechanisms | poses | " + " | ".join(TITLES[v] for v in VERDICTS)
                + " | flips |", "|---" * (len(VERDICTS) + 4) + "|"]
        for k in kinds:
            rows.append(f"| {k} | {mechs[k]} | {sum(counts[k].values())} | "
                        + " | ".join(str(counts[k][v]) for v in VERDICTS)
                        + f" | {flips[k]} |")
        rows.append(f"| **all** | {sum(mechs.values())} | {total} | "
                    + " | ".join(str(sum(c[v] for c in counts.values())) for v in VERDICTS)
                    + f" | {sum(flips.values())} |")
        write_readme_section("domain", "\n".join(rows) + f"\n\n{total} poses in {secs:.0f} s "
                             f"(`python benchmarks/domain_checks.py --poses {args.poses} --readme`).")
    return 1 if silent else 0


if __name__ == "__main__":
    raise SystemExit(main())
