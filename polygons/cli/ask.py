"""``polygons ask CASE.toml``: the scene's [[questions]] answered — the input at which a
condition holds, the extremes over the cycle — and, with ``--show Q[:K]``, the full
construction at the K-th root of question Q."""
from __future__ import annotations

from ._output import add_out_option, emit


def register(sub) -> None:
    p = sub.add_parser("ask", help="answer the scene's [[questions]]: the angle or speed at "
                                   "which a condition holds, stroke, dead centres, time ratio",
                       description="Answer the scene's [[questions]] (every root in the "
                                   "range, bracketed on a sweep and polished by Brent's "
                                   "method on the construction).")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--json", action="store_true", help="print a JSON object instead of text")
    p.add_argument("--show", metavar="Q[:K]",
                   help="also solve and narrate the construction at root K (default 1) of "
                        "question Q (numbered from 1)")
    add_out_option(p)
    p.set_defaults(func=run)


def _pick(text: str, findings) -> tuple[int, int]:
    from ..errors import PolygonsError
    q, _, k = text.partition(":")
    try:
        qi, ki = int(q), int(k or "1")
    except ValueError:
        raise PolygonsError(f"--show {text!r}: write Q or Q:K (question and root numbers, "
                            f"from 1)") from None
    if not 1 <= qi <= len(findings):
        raise PolygonsError(f"--show {text!r}: the scene has {len(findings)} question(s)")
    roots = findings[qi - 1].roots
    if not 1 <= ki <= len(roots):
        raise PolygonsError(f"--show {text!r}: question {qi} has {len(roots)} root(s)")
    return qi - 1, ki - 1


def run(args) -> int:
    from .. import conditions
    from ..errors import PolygonsError
    from ..scene import load_scene
    scene = load_scene(args.scene)
    if "questions" not in scene.extra:
        raise PolygonsError("the scene asks no [[questions]] (see docs/scene-reference.md)",
                            file=scene.file)
    findings = conditions.answer_all(scene)
    shown = None
    if args.show:
        qi, ki = _pick(args.show, findings)
        shown = findings[qi].roots[ki].scene
    if args.json:
        from ..report import json_text, to_json
        from ..evaluate import solve
        data = {"questions": conditions.to_dict(findings)}
        if shown is not None:
            data["shown"] = to_json(solve(shown))
        text = json_text(data)
    else:
        text = "\n".join(conditions.report_lines(findings)) + "\n"
        if shown is not None:
            from ..evaluate import solve
            from ..report import table
            text += f"\nThe construction at root {ki + 1} of question {qi + 1}:\n\n"
            text += table(solve(shown))
            if shown.loads is not None and shown.loads.active:
                from ..forces import analyse
                from .forces import forces_table
                text += "\n" + forces_table(analyse(shown), header=False)
    emit(text, args.out)
    return 0
