"""The layout audit over every shipped case: every drawing kind rendered to SVG and measured
(diagrams.audit): shortest vector (in its inset when it has one), overlapping labels, the
lowest text once the page reduces the figure.

    python benchmarks/layout_audit.py            # table by kind + every breach
    python benchmarks/layout_audit.py CASE ...   # only these cases (file stems or paths)

Kinds: space, velocity, acceleration (finished), stages (velocity-1 ...), rolling, klein,
force polygons (group and joint), zhukovsky, free bodies, handout plates and stage figures
(text measured after the page's reduction).  The suite runs a representative subset
(tests/test_layout_audit.py); this runs them all (~1 min).
"""
from __future__ import annotations

import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def kind_of(name: str, d) -> str:
    if name.startswith("lever"):
        return "zhukovsky"
    if name.startswith("joint"):
        return "force-joint"
    if name.startswith("force") or name.startswith("group"):
        return "force-polygon"
    if name.startswith("fbd") or name.startswith("body"):
        return "free-body"
    if d is not None and d.kind in ("velocity", "acceleration") and d.stage is not None:
        return "stages"
    return getattr(d, "kind", None) or name.split("-")[0]


def drawings_of(path: Path, handout: bool = True, forces: bool = True, stages: bool = True):
    """(kind, name, svg bytes, reduction) of every drawing of one case (``forces``: its
    force polygons, Zhukovsky's lever and free bodies too; ``handout``: its figures)."""
    import diagrams
    from diagrams.svg import to_svg
    from polygons.api import solve
    from polygons.errors import PolygonsError
    sol = solve(str(path)).solution
    klein = sol.scene.options.diagram.klein
    for d in diagrams.drawings(sol, None, None, stages, klein=klein):
        kind = "klein" if d.name.startswith("klein") else kind_of(d.name, d)
        yield kind, d.name, to_svg(d), 1.0
    try:
        if not forces:
            raise PolygonsError("")
        from polygons.forces import analyse, has_forces
        scene = sol.scene
        if has_forces(scene):
            an = analyse(scene)
            from diagrams import fbd, forcepoly
            from diagrams.handout_forces import printed
            for st in an.states:
                for stem, d in (forcepoly.group_drawings(an, st) + forcepoly.joint_drawings(an, st)
                                + forcepoly.lever_drawings(an, st)):
                    yield kind_of(stem, d), stem, to_svg(d), 1.0
                    if handout and d.stage is None:    # as the handout prints it
                        r, _, k = printed(d)
                        yield (f"handout-{kind_of(stem, d)}", f"handout:{stem}", to_svg(r), k)
            for stem, d in fbd.drawings(an):
                yield "free-body", stem, to_svg(d), 1.0
    except PolygonsError:
        pass
    if not handout:
        return
    from diagrams.figures import PAGE, figures, plate, stage_width
    figs = figures(sol)
    for name, d in figs.drawing.items():
        if d.stage is None:
            t = plate(d)
            yield (f"handout-{d.kind}", f"handout:{name}", to_svg(t),
                   min(1.0, PAGE[0] / t.width))
        else:
            yield ("handout-stages", f"handout:{name}", figs.svg[name],
                   stage_width(d.width, d.height) / d.width)


def audit(paths, handout: bool = True):
    from diagrams.audit import MIN_VECTOR_MM, measure, verdict
    by_kind = defaultdict(lambda: {"n": 0, "short": 0, "shortest": None, "where": "",
                                   "overlaps": 0, "text": None, "twhere": ""})
    breaches = []
    for path in paths:
        for kind, name, svg, red in drawings_of(path, handout):
            m = measure(svg, f"{path.stem}/{name}", red)
            k = by_kind[kind]
            k["n"] += 1
            s = m.shortest
            if s is not None and (k["shortest"] is None or s < k["shortest"]):
                k["shortest"], k["where"] = s, f"{path.stem}/{name}"
            k["short"] += sum(1 for _, mm, sh in m.vectors
                              if mm < MIN_VECTOR_MM and (sh is None or sh < MIN_VECTOR_MM))
            k["overlaps"] += len(m.overlaps)
            t = m.smallest_text
            if t is not None and (k["text"] is None or t < k["text"]):
                k["text"], k["twhere"] = t, f"{path.stem}/{name}"
            breaches += verdict(m)
    return by_kind, breaches


def main(argv) -> int:
    cases = sorted((ROOT / "cases").glob("*.toml"))
    if argv:
        cases = [Path(a) if a.endswith(".toml") else ROOT / "cases" / f"{a}.toml" for a in argv]
    t0 = time.perf_counter()
    by_kind, breaches = audit(cases)
    dt = time.perf_counter() - t0
    print(f"{len(cases)} cases in {dt:.1f} s")
    print(f"{'kind':18} {'drawings':>8} {'short':>6} {'shortest mm':>12}  {'overlaps':>8} "
          f"{'text mm':>8}  worst")
    for kind in sorted(by_kind):
        k = by_kind[kind]
        sh = "-" if k["shortest"] is None else f"{k['shortest']:.2f}"
        tx = "-" if k["text"] is None else f"{k['text']:.2f}"
        print(f"{kind:18} {k['n']:>8} {k['short']:>6} {sh:>12}  {k['overlaps']:>8} {tx:>8}  "
              f"{k['where']} | {k['twhere']}")
    print(f"{len(breaches)} breaches")
    for b in breaches:
        print("  " + b)
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
