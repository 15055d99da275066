"""The answers-only program's own passes (:func:`polygons.codegen.generate` with ``outputs``).

* :func:`inline`: a placement's function (:data:`_INLINE`) written out in place from its own
  source — no second statement of the formula;
* :class:`Perp`: a line ⟂ r kept as r, so that the 2×2 solve reads r itself;
* :func:`fold`: locals read once written into their reader, copies aliased, formulas of the
  parameters only computed once per scene.

Every pass keeps the floating-point operations and their order: the answers are the
construction's (tests/test_compiled.py holds them to the full program's).
"""
from __future__ import annotations

import ast
import copy
import inspect
import textwrap

from .dyads.base import circle_circle_scalar, circle_line_scalar
from .program import Expr, Line, Name

#: the placements the answers-only program writes out in place (:func:`inline`): each
#: a straight-line body whose early returns (``if ...: return``) are all failures of its
#: dyad's margin test, ending in one ``return`` of its results
_INLINE = frozenset((circle_circle_scalar, circle_line_scalar))
_TREES: dict = {}


def _inline_tree(fn) -> ast.FunctionDef:
    """``fn``'s definition parsed once (its docstring dropped), checked to be of the shape
    :func:`inline` writes out: assignments to one name, ``if ...: return ...``, one
    final ``return`` of a tuple."""
    tree = _TREES.get(fn)
    if tree is None:
        tree = ast.parse(textwrap.dedent(inspect.getsource(fn))).body[0]
        body = tree.body[1:] if isinstance(tree.body[0], ast.Expr) else tree.body
        *head, last = body
        ok = isinstance(last, ast.Return) and isinstance(last.value, ast.Tuple) and all(
            isinstance(st, ast.Assign) and len(st.targets) == 1
            and isinstance(st.targets[0], ast.Name)
            or isinstance(st, ast.If) and not st.orelse and len(st.body) == 1
            and isinstance(st.body[0], ast.Return) for st in head)
        if not ok:
            raise TypeError(f"{fn.__name__} is not straight-line code Source.inline can write")
        tree.body = body
        tree = _TREES[fn] = tree
    return tree


def inline(g, fn, args, n: int) -> list[Name]:
    """``fn(*args)`` written out in place (the answers-only program): ``fn``'s own body,
    read from its source (:func:`inspect.getsource`), each of its locals a fresh local,
    each global it reads bound as ``_g_<name>``, its last ``return`` the ``n`` results;
    an early ``return`` (a placement that fails: every function of :data:`_INLINE`
    returns early only where its margin fails the dyad's test) raises ``_Fail`` (the
    full program is then run).  No second statement of the formula is written."""
    tree = _inline_tree(fn)
    names: dict[str, Name] = {}
    for a, o in zip((a.arg for a in tree.args.args), args):
        names[a] = g.let(o) if isinstance(o, Expr) else o
    glob = fn.__globals__

    def text(node) -> tuple[str, frozenset]:
        reads = set()

        class Rename(ast.NodeTransformer):
            def visit_Name(self, nd):
                if nd.id in names:
                    v = names[nd.id]
                    if isinstance(v, Name):
                        reads.add(v)
                    return ast.copy_location(ast.Name(id=str(v), ctx=nd.ctx), nd)
                if nd.id in glob:
                    bound = f"_g_{nd.id}"
                    g.namespace[bound] = glob[nd.id]
                    return ast.copy_location(ast.Name(id=bound, ctx=nd.ctx), nd)
                return nd          # a builtin (abs)
        return ast.unparse(Rename().visit(copy.deepcopy(node))), frozenset(reads)

    for st in tree.body:
        if isinstance(st, ast.Assign):
            t, reads = text(st.value)
            g._n += 1
            name = names[st.targets[0].id] = Name(f"v{g._n}")
            g.lines.append(Line((name,), f"{name} = {t}", reads))
        elif isinstance(st, ast.If):
            t, reads = text(st.test)
            g.fails.append(("inline", fn.__name__))
            g.lines.append(Line((), f"if {t}: raise _Fail({len(g.fails) - 1})",
                                   reads))
        else:                       # the final return (n results)
            outs = []
            for el in st.value.elts:
                t, reads = text(el)
                if t in names.values() or type(el) is ast.Name and el.id in names:
                    outs.append(Name(t))
                    continue
                g._n += 1
                name = Name(f"v{g._n}")
                g.lines.append(Line((name,), f"{name} = {t}", reads))
                outs.append(name)
            return outs


class Perp:
    """A line direction ⟂ r = (−r_y, r_x), held as r (the answers-only program's)."""

    __slots__ = ("r",)

    def __init__(self, r):
        self.r = r


_PURE = (ast.BinOp, ast.UnaryOp, ast.IfExp, ast.Compare, ast.BoolOp, ast.Name, ast.Constant,
         ast.Add, ast.Sub, ast.Mult, ast.USub, ast.UAdd, ast.Gt, ast.GtE, ast.Lt, ast.LtE,
         ast.Eq, ast.NotEq, ast.And, ast.Or, ast.Not, ast.Load)


def _of_params(node, nparams: int) -> bool:
    """Whether ``node`` is a formula over parameters only (``k<i>``, numbers) made of +, −, ×,
    comparisons and choices — none of which can raise — and not a bare name or number."""
    if isinstance(node, (ast.Name, ast.Constant)):
        return False
    for nd in ast.walk(node):
        if not isinstance(nd, _PURE):
            return False
        if isinstance(nd, ast.Name) and not (nd.id[:1] == "k" and nd.id[1:].isdigit()
                                             and int(nd.id[1:]) < nparams):
            return False
    return True


def fold(src: str, nparams: int) -> tuple[str, list[str]]:
    """``src`` with every local assigned once and read once written into the statement that
    reads it (the expression in its place, parenthesised by :func:`ast.unparse`): the same
    floating-point operations in the same order, without a store and a load each; and every
    formula of parameters only (:func:`_of_params`: a link's r₁² − r₂², the larger of two
    lengths) read as a name ``c<j>`` that follows the parameters — the formulas returned, to be
    computed once per scene (the same operations on the same numbers: the same values)."""
    fn = ast.parse(src).body[0]
    consts: dict[str, str] = {}

    class Hoist(ast.NodeTransformer):
        def generic_visit(self, nd):
            if isinstance(nd, ast.expr) and _of_params(nd, nparams):
                text = ast.unparse(nd)
                name = consts.setdefault(text, f"c{len(consts)}")
                return ast.copy_location(ast.Name(id=name, ctx=ast.Load()), nd)
            return super().generic_visit(nd)

    unpack = fn.body[0]
    fn.body = [unpack] + [Hoist().visit(st) for st in fn.body[1:]]
    if consts:
        unpack.targets[0].elts += [ast.Name(id=c, ctx=ast.Store()) for c in consts.values()]
    loads: dict = {}
    for nd in ast.walk(fn):
        if isinstance(nd, ast.Name) and isinstance(nd.ctx, ast.Load):
            loads[nd.id] = loads.get(nd.id, 0) + 1
    held: dict = {}
    alias: dict = {}

    class Put(ast.NodeTransformer):
        def visit_Name(self, nd):
            if isinstance(nd.ctx, ast.Load) and nd.id in alias:
                return ast.Name(id=alias[nd.id], ctx=ast.Load())
            return held.pop(nd.id) if isinstance(nd.ctx, ast.Load) and nd.id in held else nd

    body = []
    for st in fn.body:
        st = Put().visit(st)
        one = (isinstance(st, ast.Assign) and len(st.targets) == 1
               and isinstance(st.targets[0], ast.Name))
        if one and isinstance(st.value, ast.Name):      # a copy: its name read instead
            alias[st.targets[0].id] = st.value.id
        elif one and loads.get(st.targets[0].id) == 1:
            held[st.targets[0].id] = st.value
        else:
            body.append(st)
    fn.body = body
    return ast.unparse(fn) + "\n", list(consts)
