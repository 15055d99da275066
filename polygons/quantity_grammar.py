"""The grammar of an answer's quantity: 'v(C,B)', 'omega(BC)', 'dist(O,N)', a ratio 'v(C) / v(B)'
(:mod:`polygons.quantities` evaluates them), and the ``[[answers]]`` tables read with it."""
from __future__ import annotations

import re

from .errors import SceneError, show
from .reader import answer_fields, record
from .records import Answer, Quantity
from .units import dimension_of


_CALL = re.compile(r"^\s*([a-z_]+)\(\s*([^,()\s]+)\s*(?:,\s*([^,()\s]+)\s*)?"
                   r"(?:,\s*([^,()\s]+)\s*)?\)\s*$")
#: the functions of an answer's ``quantity`` (see :mod:`polygons.quantities`)
QUANTITY_FUNCTIONS = ("v", "a", "an", "at", "omega", "alpha", "vs", "as", "cor", "dist", "x",
                      "y", "dir_v", "dir_a", "angle", "arm")
#: the kind of each function's value (a ratio is of two of one kind)
_KIND = {"v": "a velocity", "vs": "a velocity", "a": "an acceleration", "an": "an acceleration",
         "at": "an acceleration", "as": "an acceleration", "cor": "an acceleration",
         "omega": "an angular velocity", "alpha": "an angular acceleration", "dist": "a length",
         "x": "a length", "y": "a length", "arm": "a length", "dir_v": "an angle",
         "dir_a": "an angle", "angle": "an angle"}
_ARITY = {"angle": (3,), "arm": (3,), "v": (1, 2), "a": (1, 2), "an": (2,), "at": (2,),
          "dist": (2,), "vs": (1, 2), "as": (1, 2), "cor": (1, 2)}


def parse_quantity_expr(expr: str, *, file: str | None = None, where: str | None = None):
    """'v(C,B)' -> ('v', ('C', 'B')): the grammar of a result quantity, checked."""
    read = _READ_EXPR.get(expr) if isinstance(expr, str) else None
    if read is not None:
        return read
    if isinstance(expr, str) and "/" in expr:   # a ratio: 'v(C) / v(B)' -> ('ratio', (X, Y))
        num, _, den = expr.partition("/")
        if "/" in den or not num.strip() or not den.strip():
            raise SceneError(f"cannot read the ratio {show(expr)}: write one quantity over "
                             f"another, e.g. 'v(C) / v(B)'", file=file, where=where)
        kinds = [_KIND.get(parse_quantity_expr(x.strip(), file=file, where=where)[0])
                 for x in (num, den)]
        if kinds[0] != kinds[1]:
            raise SceneError(f"{show(expr)}: a ratio of {kinds[0]} to {kinds[1]} has a unit; "
                             f"ask for a ratio of two quantities of one kind (v(C) / v(B), "
                             f"omega(CD) / omega(AB))", file=file, where=where)
        return "ratio", (num.strip(), den.strip())
    m = _CALL.match(expr) if isinstance(expr, str) else None
    if not m or m.group(1) not in QUANTITY_FUNCTIONS:
        raise SceneError(f"cannot read quantity {show(expr)}: write e.g. 'v(C)', 'v(C,B)', "
                         f"'omega(BC)', 'alpha(CD)', 'an(C,B)', 'at(C,B)', 'vs(C)', 'cor(A)' "
                         f"(functions: {', '.join(QUANTITY_FUNCTIONS)})", file=file,
                         where=where)
    fn, args = m.group(1), tuple(g for g in m.groups()[1:] if g is not None)
    counts = _ARITY.get(fn, (1,))
    if len(args) not in counts:
        raise SceneError(f"{fn}() takes {' or '.join(map(str, counts))} labels, got "
                         f"{show(expr)}", file=file, where=where)
    if len(_READ_EXPR) >= 4096:         # a long run's many texts: start afresh
        _READ_EXPR.clear()
    _READ_EXPR[expr] = (fn, args)       # a pure function of the text: remembered
    return fn, args


_READ_EXPR: dict[str, tuple[str, tuple[str, ...]]] = {}


def _parse_answers(answers_raw: list, r: _Reader, default_tol: float) -> tuple[Answer, ...]:
    """``[[answers]]``: each table's fields checked (:func:`answer_fields`) and its quantity's
    grammar (:func:`parse_quantity_expr`)."""
    answers = []
    for i, spec in enumerate(answers_raw):
        where = f"answers[{i}]"
        fields = answer_fields(spec, r, where, default_tol)
        fn, args = parse_quantity_expr(fields["quantity"], file=r.file,
                                       where=where + ".quantity")
        answers.append(record(Answer, **fields, q=Quantity(fn, args)))
    return tuple(answers)


def unit_dimension(unit: str) -> str:
    if unit in ("-", "1"):
        return "fraction"
    return dimension_of(unit)
