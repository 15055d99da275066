"""Large valid scenes, generated: ``python benchmarks/large.py`` measures every command on them.

Two families, both carried by the same crank-rocker four-bar ABCD (A = (0, 0), D = (250, 0) mm,
AB 60, BC 240, CD 180 mm, the crank at 60° turning at 10 rad/s CCW):

* :func:`truss` -- a triangulated strip (a Warren truss) on the coupler BC: node T1 on B and C,
  then every node on the two before it (T2 on C and T1, T3 on T1 and T2, ...), the nodes
  alternately on the chord through B and C and on the chord 50 mm above it, 60 mm apart.  Every
  node is an RRR dyad on two moving points; the truss moves rigidly with the coupler.
* :func:`chain` -- N RRR dyads in series: P1 = C, then P(k+1) on Pk and the ground pivot
  Ok+1 (Ok at 250 + 100(k−1) mm on the x axis, O1 = D): a chain of four-bars each driving the
  next, every stage a near-parallelogram (rockers 180 mm, coupler 105 mm over 100 mm of
  ground) so every stage closes at every crank angle.  ``chain(1)`` is the four-bar itself.

``scene_text(...)`` is valid TOML with units; the number of links is ``3 + 2·nodes`` for the
truss and ``1 + 2·N`` for the chain.  Assembly branches are stated the textbook way ("T5 above
T3T4"), chosen from the positions at the scene's crank angle, computed here with numpy
(independent of polygons: circle–circle intersections, :func:`positions`).

Measured: ``python benchmarks/large.py [--links 61,101] [--commands solve,draw,...]`` runs each
command in a fresh process on generated scenes and prints the seconds and, with ``--fit``, the
exponent of a log-log fit of the time against the links from 10 to 200.
"""
from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: the four-bar carrying both families (mm, degrees)
A, D = (0.0, 0.0), (250.0, 0.0)
AB, BC, CD = 60.0, 240.0, 180.0
THETA = 60.0
#: truss: node spacing along the chords and the chords' separation (mm)
STEP, RISE = 60.0, 50.0
#: chain: ground pitch, each stage's coupler and rocker (mm)
PITCH, COUPLER, ROCKER = 100.0, 105.0, 180.0


# ---------------------------------------------------------------- geometry (numpy-free floats)
def _meet(p, rp, q, rq, near):
    """The intersection of circle (p, rp) and circle (q, rq) nearer ``near``."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    a = (rp * rp - rq * rq + d * d) / (2 * d)
    h2 = rp * rp - a * a
    if h2 < 0:
        raise ValueError(f"no closure: |pq| = {d:.6g}, radii {rp:.6g}, {rq:.6g}")
    h = math.sqrt(h2)
    mx, my = p[0] + a * dx / d, p[1] + a * dy / d
    c1 = (mx - h * dy / d, my + h * dx / d)
    c2 = (mx + h * dy / d, my - h * dx / d)
    return min((c1, c2), key=lambda c: math.dist(c, near))


def _four_bar(theta_deg: float):
    t = math.radians(theta_deg)
    b = (A[0] + AB * math.cos(t), A[1] + AB * math.sin(t))
    c = _meet(b, BC, D, CD, (b[0] + 100.0, b[1] + 200.0))       # C above AD
    return b, c


def truss_nodes(nodes: int):
    """[(label, parent1, parent2, (u, v))]: each node's parents and its place in the coupler's
    frame (B at the origin, C on +u)."""
    out = []
    # chord nodes: even index on v = 0 at u = STEP·k/2·2 ... node k at u = k·STEP/2·(BC/STEP)
    # B is node 0 (u = 0), C node 2 (u = BC); node 1 at (BC/2, RISE); node k ≥ 3 at
    # u = BC + (k − 2)·STEP/2, on v = RISE when k is odd, else v = 0.
    names = {0: "B", 2: "C"}
    place = {0: (0.0, 0.0), 2: (BC, 0.0), 1: (BC / 2, RISE)}
    for k in range(3, nodes + 2):
        place[k] = (BC + (k - 2) * STEP / 2, RISE if k % 2 else 0.0)
    order = [1] + list(range(3, nodes + 2))
    for i, k in enumerate(order):
        names[k] = f"T{i + 1}"
    for k in order:
        parents = (0, 2) if k == 1 else ((2, 1) if k == 3 else (k - 2, k - 1))
        out.append((names[k], names[parents[0]], names[parents[1]], place[k]))
    return out


def positions(kind: str, size: int, theta_deg: float = THETA) -> dict:
    """Every point's position (mm) at crank angle ``theta_deg``, by circle intersections
    followed from the assembly at :data:`THETA` in small steps (independent of polygons)."""
    b, c = _four_bar(theta_deg)
    pos = {"A": A, "D": D, "B": b, "C": c}
    if kind == "truss":
        ex = ((c[0] - b[0]) / BC, (c[1] - b[1]) / BC)
        ey = (-ex[1], ex[0])
        for lab, p1, p2, (u, v) in truss_nodes(size):
            pos[lab] = (b[0] + u * ex[0] + v * ey[0], b[1] + u * ex[1] + v * ey[1])
        return pos
    # chain: follow the branch from THETA to theta in steps of at most 2 degrees
    n = max(1, math.ceil(abs(theta_deg - THETA) / 2.0))
    prev = _chain_at(size, THETA, None)
    for i in range(1, n + 1):
        prev = _chain_at(size, THETA + (theta_deg - THETA) * i / n, prev)
    return prev


def _chain_at(size: int, theta_deg: float, prev):
    b, c = _four_bar(theta_deg)
    pos = {"A": A, "D": D, "B": b, "C": c}
    last = "C"
    for k in range(2, size + 1):
        o = (D[0] + PITCH * (k - 1), 0.0)
        pos[f"O{k}"] = o
        guess = prev[f"P{k}"] if prev else (pos[last][0] + PITCH, pos[last][1])
        pos[f"P{k}"] = _meet(pos[last], COUPLER, o, ROCKER, guess)
        last = f"P{k}"
    return pos


def _side(x, p, q):
    """'above' / 'below' (or 'left of' / 'right of' for a steep line) of x from line pq."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    cross = dx * (x[1] - p[1]) - dy * (x[0] - p[0])
    if abs(dx) > 0.2 * math.hypot(dx, dy):
        return "above" if cross * math.copysign(1, dx) > 0 else "below"
    return "left of" if cross * math.copysign(1, dy) > 0 else "right of"


# ---------------------------------------------------------------- scene text
def _mm(x: float) -> str:
    return f'"{x:.12g} mm"'


def scene_text(kind: str, size: int, *, loads: bool = False, title: str | None = None) -> str:
    """A valid scene: ``kind`` 'truss' (``size`` nodes) or 'chain' (``size`` RRR dyads)."""
    if kind not in ("truss", "chain") or size < 1:
        raise ValueError(f"kind 'truss' or 'chain' and size >= 1, got {kind!r}, {size!r}")
    pos = positions(kind, size)
    links = [("AB", AB), ("BC", BC), ("CD" if kind == "truss" else "DC", CD)]
    ground = [("A", A), ("D", D)]
    assembly = [("C", "C above AD")]
    if kind == "truss":
        for lab, p1, p2, _ in truss_nodes(size):
            links.append((p1 + lab, math.dist(pos[p1], pos[lab])))
            links.append((p2 + lab, math.dist(pos[p2], pos[lab])))
            assembly.append((lab, f"{lab} {_side(pos[lab], pos[p1], pos[p2])} {p1}{p2}"))
    else:
        last = "C"
        for k in range(2, size + 1):
            o, p = f"O{k}", f"P{k}"
            ground.append((o, pos[o]))
            links.append((last + p, COUPLER))
            links.append((o + p, ROCKER))
            assembly.append((p, f"{p} {_side(pos[p], pos[last], pos[o])} {last}{o}"))
            last = p
    n = len(links)
    title = title or (f"{kind} of {size} {'nodes' if kind == 'truss' else 'RRR dyads'} "
                      f"on a four-bar ({n} links)")
    out = [f'# generated by benchmarks/large.py: scene_text("{kind}", {size})',
           f'title = "{title}"', "", "[ground]"]
    out += [f"{k} = [{_mm(x)}, {_mm(y)}]" for k, (x, y) in ground]
    out += ["", "[links]"]
    out += [f"{k} = {_mm(v)}" for k, v in links]
    out += ["", "[driver]", 'crank = "AB"', f'angle = "{THETA:g} deg"', 'omega = "10 rad/s"',
            'sense = "CCW"', "", "[assembly]"]
    out += [f'{k} = "{v}"' for k, v in assembly]
    if loads:
        for k, v in links:
            out += ["", f"[masses.{k}]", f'mass = "{0.001 * v:.6g} kg"']
        on = links[-1][0]                          # the last link, at its last point
        tip = split_name(on)[1]
        out += ["", "[forces.Load]", f'at = "{tip}"', f'on = "{on}"',
                'force = ["0 N", "-50 N"]']
    return "\n".join(out) + "\n"


def split_name(name: str) -> tuple[str, str]:
    """'T3T5' -> ('T3', 'T5') (a label: a capital letter and digits)."""
    i = next(i for i in range(1, len(name)) if name[i].isupper())
    return name[:i], name[i:]


def links_of(kind: str, size: int) -> int:
    return 3 + 2 * size if kind == "truss" else 1 + 2 * size


def size_for_links(kind: str, links: int) -> int:
    """The size whose scene has ``links`` links (rounded down to an odd count)."""
    return max(1, (links - 3) // 2 if kind == "truss" else (links - 1) // 2)


# ---------------------------------------------------------------- measuring
COMMANDS = ("solve", "draw", "handout", "check", "sweep", "forces", "centres")


def _argv(cmd: str, path: str, out: str) -> list[str]:
    base = [sys.executable, "-m", "polygons", cmd, path]
    if cmd in ("draw", "centres", "sweep"):
        return base + ["-o", out]
    if cmd == "handout":
        return base + ["-o", os.path.join(out, "handout.html")]
    if cmd == "check":                                  # exit 3: a value off (still graded)
        return base + ["--measured", "v_C=1", "omega_BC=1", "-o", os.path.join(out, "check.txt")]
    if cmd in ("solve", "forces"):
        return base + ["-o", os.path.join(out, f"{cmd}.txt")]
    return base


def _children_cpu() -> float:
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def measure(kind: str, links: int, commands, *, timeout: float = 600.0,
            loads: bool = True, cpu: bool = True) -> dict:
    """Seconds of each command in a fresh process (``python -m polygons CMD scene``) on the
    scene of ``links`` links: its CPU time (user + system; the machine is shared, so the
    wall time says more about the neighbours), or with ``cpu`` False the wall time; a failure
    is recorded as its one-line message."""
    size = size_for_links(kind, links)
    text = scene_text(kind, size, loads=loads)
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, f"{kind}-{links}.toml")
        Path(path).write_text(text)
        for cmd in commands:
            t0 = time.perf_counter()
            c0 = _children_cpu()
            try:
                run = subprocess.run(_argv(cmd, path, tmp), capture_output=True, text=True,
                                     timeout=timeout, cwd=ROOT)
                dt = _children_cpu() - c0 if cpu else time.perf_counter() - t0
                if run.returncode not in (0, 3 if cmd == "check" else 0):
                    tail = (run.stderr or run.stdout).strip().splitlines()
                    out[cmd] = (dt, f"exit {run.returncode}: {tail[-1] if tail else ''}")
                else:
                    out[cmd] = (dt, "")
            except subprocess.TimeoutExpired:
                out[cmd] = (timeout, f"over {timeout:g} s")
    return out


def fit_exponent(xs, ys) -> float:
    """The slope of log y against log x (least squares)."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return (sum((a - mx) * (b - my) for a, b in zip(lx, ly))
            / sum((a - mx) ** 2 for a in lx))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kind", default="truss", choices=("truss", "chain"))
    ap.add_argument("--links", default="61,101", help="comma-separated link counts")
    ap.add_argument("--commands", default=",".join(COMMANDS))
    ap.add_argument("--fit", action="store_true",
                    help="also time 11, 21, 41, 81, 141, 201 links and print each command's "
                         "log-log exponent (the process start subtracted)")
    ap.add_argument("--readme", action="store_true",
                    help="--fit, and rewrite README.md's block between "
                         "<!-- large:begin --> and <!-- large:end --> with the table")
    ap.add_argument("--write", metavar="FILE", help="write the scene of the first --links "
                    "count to FILE and stop")
    args = ap.parse_args(argv)
    cmds = [c for c in args.commands.split(",") if c]
    counts = [int(x) for x in args.links.split(",") if x]
    if args.write:
        Path(args.write).write_text(scene_text(args.kind, size_for_links(args.kind, counts[0]),
                                               loads=True))
        return 0
    if args.readme:
        args.fit = True
    if args.fit:
        counts = sorted(set(counts) | {11, 21, 41, 81, 141, 201})
    rows = {}
    for n in counts:
        rows[n] = measure(args.kind, n, cmds)
        cells = "  ".join(f"{c} {t:6.2f}s{' (' + e + ')' if e else ''}"
                          for c, (t, e) in rows[n].items())
        print(f"{args.kind} {links_of(args.kind, size_for_links(args.kind, n)):4d} links: "
              f"{cells}", flush=True)
    slopes = {}
    start = None
    if args.fit:
        start = _start_time()
        print(f"process start (python -m polygons --help): {start:.2f} s CPU")
        xs = [links_of(args.kind, size_for_links(args.kind, n)) for n in counts]
        for c in cmds:
            ys = [max(rows[n][c][0] - start, 1e-3) for n in counts]
            slopes[c] = fit_exponent(xs, ys)
            print(f"{c:8s} exponent {slopes[c]:.2f} (time − start, {xs[0]}–{xs[-1]} links)")
    md = _markdown(args.kind, counts, cmds, rows, slopes, start)
    print(md)
    if args.readme:
        import protocol
        protocol.write_readme_section("large", md)
        print("README.md rewritten")
    return 0


def _markdown(kind, counts, cmds, rows, slopes, start) -> str:
    """The table: CPU seconds of each command (fresh process) by size, and the exponents."""
    head = "| links | " + " | ".join(f"`{c}`" for c in cmds) + " |"
    out = [f"CPU seconds per command, fresh process (`python benchmarks/large.py --readme`, "
           f"{kind}, {time.strftime('%Y-%m-%d')}; the machine shared, so CPU rather than wall "
           f"time):", "", head, "|---" * (len(cmds) + 1) + "|"]
    for n in counts:
        cells = []
        for c in cmds:
            t, err = rows[n][c]
            cells.append(f"{t:.2f}" + (f" ({err[:60]})" if err else ""))
        out.append(f"| {links_of(kind, size_for_links(kind, n))} | " + " | ".join(cells) + " |")
    if slopes:
        out.append("| exponent (log-log fit of time − process start) | "
                   + " | ".join(f"**{slopes[c]:.2f}**" for c in cmds) + " |")
        lo, hi = [n for n in counts if n >= 101][:1], counts[-1:]
        if lo and hi and hi[0] > lo[0]:
            a, b = lo[0], hi[0]
            out.append(f"| local exponent, {a} → {b} links | " + " | ".join(
                f"{math.log(max(rows[b][c][0] - start, 1e-3) / max(rows[a][c][0] - start, 1e-3)) / math.log(b / a):.2f}"
                for c in cmds) + " |")
        out += ["", f"(process start, `python -m polygons --help`: {start:.2f} s CPU)"]
    if 101 in rows:
        worst = max(cmds, key=lambda c: rows[101][c][0])
        t = rows[101][worst][0]
        failed = [c for c in cmds if rows[101][c][1]]
        ok = t <= 10.0 and not failed
        out += ["", f"Goal of issue 20, every command on the 101-link scene in ≤ 10 s: "
                    f"**{'met' if ok else 'not met'}** (slowest `{worst}`, {t:.1f} s"
                    + (f"; failed: {', '.join(failed)}" if failed else "") + ")."]
    return "\n".join(out)


def _start_time() -> float:
    """CPU seconds of ``python -m polygons --help`` (best of 3), as the commands are timed."""
    best = math.inf
    for _ in range(3):
        c0 = _children_cpu()
        subprocess.run([sys.executable, "-m", "polygons", "--help"], capture_output=True,
                       cwd=ROOT)
        best = min(best, _children_cpu() - c0)
    return best


if __name__ == "__main__":
    sys.exit(main())
