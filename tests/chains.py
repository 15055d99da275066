"""A large valid mechanism for the safety and fuzz tests: a crank driving a chain of RRR dyads.

``chain_scene(n)`` is the TOML text of a crank OB followed by ``n`` dyads, 2 n + 1 links: dyad
k places P<k> from the moving point before it (B, P1, ...) and its own fixed pivot G<k>.  The
configuration is chosen first and every length is measured from it, so the scene assembles at
its own crank angle by construction; each closure is picked with ``near`` (the point as
placed).  Every dyad's angle at P<k> is near 90°, far from a toggle.  (A helper writing the
benchmarks' large-scene generator works in benchmarks/; this one is the tests' own.)
"""
from __future__ import annotations

import math


def chain_points(n: int, scale: float = 1.0, wobble: float = 0.0):
    """(crank pin B, [(P_k, G_k)]) in mm: P_k along a gentle zig-zag, G_k below it (offsets
    varied from dyad to dyad, so that no two dyads form a parallelogram)."""
    b = (20.0 * scale * math.cos(math.radians(60)), 20.0 * scale * math.sin(math.radians(60)))
    out = []
    for k in range(1, n + 1):
        p = (60.0 * k * scale, (60.0 + 10.0 * (-1) ** k + wobble * math.sin(k)) * scale)
        g = (p[0] + (20.0 + 7.0 * (k % 3)) * scale, p[1] - (90.0 + 11.0 * (k % 4)) * scale)
        out.append((p, g))
    return b, out


def chain_scene(n: int, *, scale: float = 1.0, wobble: float = 0.0,
                title: str | None = None) -> str:
    """The scene text of a crank and ``n`` RRR dyads (2 n + 1 links)."""
    b, dyads = chain_points(n, scale, wobble)
    mm = lambda v: f'"{v:.12g} mm"'  # noqa: E731
    ground = ['O = ["0 mm", "0 mm"]'] + [f"G{k} = [{mm(g[0])}, {mm(g[1])}]"
                                         for k, (_, g) in enumerate(dyads, 1)]
    links = [f"OB = {mm(math.hypot(*b))}"]
    assembly = []
    prev, prev_xy = "B", b
    for k, (p, g) in enumerate(dyads, 1):
        links.append(f"{prev}P{k} = {mm(math.dist(prev_xy, p))}")
        links.append(f"P{k}G{k} = {mm(math.dist(p, g))}")
        assembly.append(f"P{k} = {{ near = [{mm(p[0])}, {mm(p[1])}] }}")
        prev, prev_xy = f"P{k}", p
    return "\n".join([
        f'title = "{title or f"chain of {n} RRR dyads ({2 * n + 1} links)"}"',
        "[ground]", *ground, "[links]", *links,
        "[driver]", 'crank = "OB"', 'angle = "60 deg"', 'omega = "10 rad/s"', 'sense = "CCW"',
        "[assembly]", *assembly, ""])
