"""One fused sweep kernel per mechanism, generated from its groups' typed primitives.

The staged construction (:mod:`polygons.codegen`) draws each dyad's velocity and acceleration
polygons: directions, then the intersection of two lines.  A sweep needs the same numbers at
millions of inputs, so here the whole chain is written as *one* numba function over a block
of results, in chunks of :data:`CHUNK` positions:

* struct of arrays: every output is a row of the result block (x, y, vx, vy, ax, ay of each
  moving point, ω and α of each link, travel and slide rates of each guided point, the
  margin), written straight there: no per-chunk record, no copy afterwards;
* dyads in the outer loop, positions in the inner one (each dyad's loop reads the rows the
  dyads before it wrote for the same chunk, still in the caches);
* each primitive's rates by the lean Cartesian solve of its closure equations differentiated
  once and twice — for :class:`~polygons.dyads.primitives.CircleCircle` (|PX| = r₁,
  |QX| = r₂) the 2×2 system

      (X − P)·v_X = (X − P)·v_P,      (X − Q)·v_X = (X − Q)·v_Q,
      (X − P)·a_X = (X − P)·a_P − |v_X − v_P|²,   likewise for Q,

  whose determinant D = (X − P) × (X − Q) is zero at a toggle (one division, 1/D, shared by
  v and a); for :class:`~polygons.dyads.primitives.CircleLine` on a fixed guide X = G + t e,
  ṫ = ((X − P)·v_P)/((X − P)·e), ẗ = ((X − P)·a_P − |v_X − v_P|²)/((X − P)·e); for a point
  rigid with a link, v = v_P + ω × PX, a = a_P + α × PX − ω² PX;
* positions by the primitive's own formula (:func:`~polygons.dyads.base.circle_circle_scalar`,
  :func:`~polygons.dyads.base.circle_line_scalar`, written without branches so that the
  inner loop vectorises), ω, α of every link (r × Δv)/|r|², (r × Δa)/|r|² and the margin
  (the smallest of the dyads' margins, as the staged sweep's) computed inside.

A construction with a primitive not listed here (a slotted lever, a triad, moving slots, a
wheel) or an output the kernel does not make gives ``None`` (:func:`fused_of`): the caller
keeps the compiled arrays program (:mod:`polygons.jit`).  The kernel's source holds no
number of the scene (parameters come in an array), so one compile serves every scene of the
same topology and closures.  ``tests/test_fused.py`` holds it equal to the numpy sweep (the
staged construction on arrays) to 1e-12 of each quantity's scale.

numba stays optional: this module imports it only inside :func:`fused_of`.
"""
from __future__ import annotations

import math

import numpy as np

from .dyads.base import CLOSE_TOL
from .dyads.primitives import CircleCircle, CircleLine, FixedLine, RigidImage, Rotation, Translation
from .memo import memo_of

#: positions per chunk of the fused kernel (every dyad's loop runs over one chunk in turn)
CHUNK = 512

_COMP = ("x", "y", "vx", "vy", "ax", "ay")


class _Gen:
    """The kernel's source being written: parameters (``k7`` = ``_k[7]``), rows of the result
    block (``r12`` = ``_O[12]``) and the loops."""

    def __init__(self):
        self.params: list[float] = []
        self.rows: list[str] = []           # what each row holds (for reading the block)
        self.loops: list[list[str]] = []
        self.pts: dict[str, tuple] = {}     # label -> its 6 components as source text

    def k(self, value) -> str:
        self.params.append(float(value))
        return f"k{len(self.params) - 1}"

    def row(self, what) -> int:
        self.rows.append(what)
        return len(self.rows) - 1

    def point_rows(self, label) -> tuple:
        """Six new rows for ``label``'s x, y, vx, vy, ax, ay; their element names."""
        first = self.row(("point", label))
        for c in _COMP[1:]:
            self.row(("point+", label))
        names = tuple(f"r{first + i}[i]" for i in range(6))
        self.pts[label] = names
        return names

    def loop(self, lines) -> None:
        self.loops.append(list(lines))


def _dot(ax, ay, bx, by) -> str:
    """a·b as source, a term whose factor is the literal 0.0 left out."""
    terms = [f"{u} * {v}" for u, v in ((ax, bx), (ay, by)) if "0.0" not in (u, v)]
    return " + ".join(terms) if terms else "0.0"


def _solve2(x, y, b1, b2, q) -> list:
    """The 2×2 solve (X − P)·v = b1, (X − Q)·v = b2 by the shared 1/D: ``x``, ``y``; where Q
    is fixed (``q`` its literal zero rates, so b2 = 0) the b2 terms left out."""
    if tuple(q) == ("0.0", "0.0"):
        return [f"{x} = dqy * {b1} * iD", f"{y} = -(dqx * {b1}) * iD"]
    return [f"{x} = (dqy * {b1} - dpy * {b2}) * iD", f"{y} = (dpx * {b2} - dqx * {b1}) * iD"]


def _sub(a, b) -> str:
    """a − b as source (b the literal 0.0: a)."""
    return a if b == "0.0" else f"{a} - {b}"


def _ground(g: _Gen, prog) -> None:
    for label, (x, y) in prog.ground.items():
        g.pts[label] = (g.k(x), g.k(y), "0.0", "0.0", "0.0", "0.0")


class Unsupported(Exception):
    """A construction the fused kernel does not make (the caller keeps the arrays program)."""


def _link_rates(g, prog, done_links, O, X, L, Z, d) -> list[str]:
    """The rows of ω and α of the link O X of length ``L`` (once a link): ω = (OX × v_X/O)
    / L², α = (OX × a_X/O) / L² — the loop's names d{d}x, d{d}y for OX and r{d}x, r{d}y for
    v_X − v_O, ``Z`` O's rows."""
    name = _link_of(prog, O, X)
    if name is None or name in done_links:
        return []
    kin = g.k(1.0 / (L * L))
    wr, ar = g.row(("omega", name)), g.row(("alpha", name))
    done_links[name] = (wr, ar)
    return [f"r{wr}[i] = (d{d}x * r{d}y - d{d}y * r{d}x) * {kin}",
            f"r{ar}[i] = (d{d}x * ({_sub('ay', Z[5])}) - d{d}y * ({_sub('ax', Z[4])})) * {kin}"]


def _link_of(prog, p, x):
    """The reported link joining ``p`` and ``x`` (name), or None."""
    for name, a, b in prog.links:
        if {a, b} == {p, x}:
            return name
    return None


def _emit(g: _Gen, prog, c, done_links: dict) -> None:
    """The loop of one primitive ``c``."""
    scene = prog.scene
    if isinstance(c, Rotation):
        if prog.input_kind != "crank":
            raise Unsupported("a rotation driven by a slider")
        P = g.pts[c.p]
        R, w, al = g.k(c.r.value(scene)), g.k(prog.rate), g.k(prog.rate2)
        X = g.point_rows(c.x)
        body = [f"dx = {R} * _cos(xs[i])", f"dy = {R} * _sin(xs[i])",
                f"{X[0]} = {P[0]} + dx", f"{X[1]} = {P[1]} + dy",
                f"{X[2]} = {P[2]} - {w} * dy", f"{X[3]} = {P[3]} + {w} * dx",
                f"{X[4]} = {P[4]} - {al} * dy - {w} * {w} * dx",
                f"{X[5]} = {P[5]} + {al} * dx - {w} * {w} * dy"]
        link = c.r.link
        if link in {n for n, _, _ in prog.links}:
            done_links[link] = ("const", prog.rate, prog.rate2)
        g.loop(body)
        return
    if isinstance(c, Translation):
        if prog.input_kind != "slider":
            raise Unsupported("a translation driven by a crank")
        (tx, ty), (ex, ey) = c.line.through(scene), c.line.direction(scene)
        tx, ty, ex, ey = g.k(tx), g.k(ty), g.k(ex), g.k(ey)
        v, a = g.k(prog.rate), g.k(prog.rate2)
        X = g.point_rows(c.x)
        g.loop([f"{X[0]} = {tx} + xs[i] * {ex}", f"{X[1]} = {ty} + xs[i] * {ey}",
                f"{X[2]} = {v} * {ex}", f"{X[3]} = {v} * {ey}",
                f"{X[4]} = {a} * {ex}", f"{X[5]} = {a} * {ey}"])
        return
    if isinstance(c, CircleCircle):
        P, Q = g.pts[c.p], g.pts[c.q]
        r1, r2 = c.r1.value(scene), c.r2.value(scene)
        k1, k2, sg = g.k(r1), g.k(r2), g.k(prog.sigma[c.x])
        inv12, kbig = g.k(1.0 / (r1 * r2)), g.k(max(r1, r2))
        X = g.point_rows(c.x)
        body = [f"px = {P[0]}", f"py = {P[1]}", f"qx = {Q[0]}", f"qy = {Q[1]}",
                "dx = qx - px", "dy = qy - py", "dist = _sqrt(dx * dx + dy * dy)",
                f"a = ({k1} * {k1} - {k2} * {k2} + dist * dist) / (2.0 * dist)",
                f"h2 = {k1} * {k1} - a * a",
                f"big = _max({kbig}, dist)",
                f"ok = h2 >= -({CLOSE_TOL!r} * (big * big))",
                "rt = _sqrt(_abs(h2))",
                "h = _sel(h2 > 0.0, rt, _sel(ok, 0.0, nan))",
                "ux = dx / dist", "uy = dy / dist", f"sh = {sg} * h",
                "x = px + a * ux + sh * -uy", "y = py + a * uy + sh * ux",
                f"m = _sel(ok, h, -rt) * dist * {inv12}",
                # rates: the 2x2 Cartesian solve
                "dpx = x - px", "dpy = y - py", "dqx = x - qx", "dqy = y - qy",
                "iD = 1.0 / (dpx * dqy - dpy * dqx)",
                f"b1 = {_dot('dpx', 'dpy', P[2], P[3])}", f"b2 = {_dot('dqx', 'dqy', Q[2], Q[3])}",
                ] + _solve2("vx", "vy", "b1", "b2", Q[2:4]) + [
                f"rpx = {_sub('vx', P[2])}", f"rpy = {_sub('vy', P[3])}",
                f"rqx = {_sub('vx', Q[2])}", f"rqy = {_sub('vy', Q[3])}",
                f"c1 = {_dot('dpx', 'dpy', P[4], P[5])} - (rpx * rpx + rpy * rpy)",
                f"c2 = {_dot('dqx', 'dqy', Q[4], Q[5])} - (rqx * rqx + rqy * rqy)"
                if Q[4:6] != ("0.0", "0.0") else "c2 = -(rqx * rqx + rqy * rqy)",
                "ax = (dqy * c1 - dpy * c2) * iD", "ay = (dpx * c2 - dqx * c1) * iD",
                f"{X[0]} = x", f"{X[1]} = y", f"{X[2]} = vx", f"{X[3]} = vy",
                f"{X[4]} = ax", f"{X[5]} = ay", "_mg(M, i, m)"]
        for d, L, Z, O in (("p", r1, P, c.p), ("q", r2, Q, c.q)):
            body += _link_rates(g, prog, done_links, O, c.x, L, Z, d)
        g.loop(body)
        return
    if isinstance(c, CircleLine):
        if not isinstance(c.line, FixedLine):
            raise Unsupported("a circle and a moving line")
        P = g.pts[c.p]
        L = c.r.value(scene)
        (gx, gy), (ex, ey) = c.line.through(scene), c.line.direction(scene)
        kl, sg = g.k(L), g.k(prog.sigma[c.x])
        gx, gy, ex, ey, il = g.k(gx), g.k(gy), g.k(ex), g.k(ey), g.k(1.0 / L)
        X = g.point_rows(c.x)
        for lab in c.also:
            g.pts[lab] = X
        body = [f"px = {P[0]}", f"py = {P[1]}",
                f"wx = {gx} - px", f"wy = {gy} - py",
                f"bq = {ex} * wx + {ey} * wy",
                f"c = wx * wx + wy * wy - {kl} * {kl}",
                "disc = bq * bq - c",
                f"ok = disc >= -{CLOSE_TOL!r} * {kl} * {kl}",
                "rt = _sqrt(_abs(disc))",
                "root = _sel(disc > 0.0, rt, _sel(ok, 0.0, nan))",
                f"t = -bq + {sg} * root",
                f"x = {gx} + t * {ex}", f"y = {gy} + t * {ey}",
                f"m = _sel(ok, root, -rt) / {kl}",
                "dpx = x - px", "dpy = y - py",
                f"iD = 1.0 / (dpx * {ex} + dpy * {ey})",
                f"td = ({_dot('dpx', 'dpy', P[2], P[3])}) * iD",
                f"vx = td * {ex}", f"vy = td * {ey}",
                f"rpx = {_sub('vx', P[2])}", f"rpy = {_sub('vy', P[3])}",
                f"tdd = ({_dot('dpx', 'dpy', P[4], P[5])} - (rpx * rpx + rpy * rpy)) * iD",
                f"ax = tdd * {ex}", f"ay = tdd * {ey}",
                f"{X[0]} = x", f"{X[1]} = y", f"{X[2]} = vx", f"{X[3]} = vy",
                f"{X[4]} = ax", f"{X[5]} = ay", "_mg(M, i, m)"]
        body += _link_rates(g, prog, done_links, c.p, c.x, L, P, "p")
        g.loop(body)
        return
    if isinstance(c, RigidImage):
        P, Q = g.pts[c.p], g.pts[c.q]
        along, frac, left = (g.k(v) for v in c.offsets(scene))
        X = g.point_rows(c.x)
        g.loop([f"px = {P[0]}", f"py = {P[1]}",
                f"dx = {Q[0]} - px", f"dy = {Q[1]} - py",
                "n2 = dx * dx + dy * dy", "n = _sqrt(n2)",
                "_mg(M, i, _sel(n > 0, 1.0, -1.0))",
                "ux = dx / n", "uy = dy / n", f"a = {along} + {frac} * n",
                f"x = px + a * ux + {left} * -uy", f"y = py + a * uy + {left} * ux",
                f"w = (dx * ({Q[3]} - {P[3]}) - dy * ({Q[2]} - {P[2]})) / n2",
                f"al = (dx * ({Q[5]} - {P[5]}) - dy * ({Q[4]} - {P[4]})) / n2",
                "ex = x - px", "ey = y - py",
                f"{X[0]} = x", f"{X[1]} = y",
                f"{X[2]} = {P[2]} - w * ey", f"{X[3]} = {P[3]} + w * ex",
                f"{X[4]} = {P[4]} - al * ey - w * w * ex",
                f"{X[5]} = {P[5]} + al * ex - w * w * ey"])
        return
    raise Unsupported(type(c).__name__)


def _links_and_guides(g: _Gen, prog, done_links: dict) -> None:
    """The last loop: ω, α of every reported link not made by its dyad, travel and slide
    rates of every guided point."""
    body = []
    for name, a, b in prog.links:
        if name in done_links:
            continue
        if a not in g.pts or b not in g.pts:
            continue
        if a in prog.ground and b in prog.ground:
            raise Unsupported("a link between two fixed points")
        A, B = g.pts[a], g.pts[b]
        wr, ar = g.row(("omega", name)), g.row(("alpha", name))
        done_links[name] = (wr, ar)
        body += [f"dx = {B[0]} - {A[0]}", f"dy = {B[1]} - {A[1]}", "n2 = dx * dx + dy * dy",
                 f"r{wr}[i] = (dx * ({B[3]} - {A[3]}) - dy * ({B[2]} - {A[2]})) / n2",
                 f"r{ar}[i] = (dx * ({B[5]} - {A[5]}) - dy * ({B[4]} - {A[4]})) / n2"]
    for label, gd in prog.scene.model.guide.items():
        if label not in g.pts or label in prog.ground:
            continue
        X = g.pts[label]
        (tx, ty), (ex, ey) = gd.line.through, gd.line.direction
        tx, ty, ex, ey = g.k(tx), g.k(ty), g.k(ex), g.k(ey)
        rt, rv, ra = g.row(("travel", label)), g.row(("slide_v", label)), \
            g.row(("slide_a", label))
        body += [f"r{rt}[i] = ({X[0]} - {tx}) * {ex} + ({X[1]} - {ty}) * {ey}",
                 f"r{rv}[i] = {X[2]} * {ex} + {X[3]} * {ey}",
                 f"r{ra}[i] = {X[4]} * {ex} + {X[5]} * {ey}"]
    if body:
        g.loop(body)


def generate(prog, index):
    """(loops, params, rows, links, margin row) of ``prog``'s fused kernel, which must make every output
    in ``index`` (the arrays program's, :func:`polygons.sweep.arrays_program`); raises
    :class:`Unsupported`."""
    g = _Gen()
    _ground(g, prog)
    done: dict = {}
    for d in prog.plan.dyads:
        c = getattr(d, "construction", None)
        if c is None:
            raise Unsupported(type(d).__name__)
        _emit(g, prog, c, done)
    _links_and_guides(g, prog, done)
    # every output of the arrays program must be one the kernel makes
    for key, label in index:
        if key in ("pos", "velocity", "acceleration"):
            if label not in g.pts:
                raise Unsupported(f"{key} of {label}")
        elif key in ("omega", "alpha"):
            if label not in done:
                raise Unsupported(f"{key} of {label}")
        elif key not in ("margins", "margin_of", "crossings"):
            raise Unsupported(key)
    margin = g.row(("margin", ""))
    return g.loops, g.params, g.rows, done, margin


def source(loops, nparams: int, nrows: int, margin: int, arrays: bool) -> str:
    """The kernel's text: ``_fused(xs, _k, _O)`` filling the block ``_O`` chunk by chunk, each
    loop body over one position (numba: ``i`` runs over the chunk, unsigned so that LLVM
    vectorises the loop) or over the whole chunk (numpy: ``i`` is the chunk's slice)."""
    # (the loops' own names start with an underscore: a body's locals never do)
    chunk = CHUNK_ARRAYS if arrays else CHUNK
    src = ["def _fused(xs, _k, _O):", "    _n = xs.shape[0]"]
    src += [f"    k{j} = _k[{j}]" for j in range(nparams)]
    src += [f"    r{j} = _O[{j}]" for j in range(nrows)]
    src.append(f"    M = _O[{margin}]")
    src.append(f"    for _c in range((_n + {chunk - 1}) // {chunk}):")
    if arrays:
        src.append(f"        i = slice(_c * {chunk}, min(_n, _c * {chunk} + {chunk}))")
        src.append("        M[i] = 1.0")
        for body in loops:
            src += [f"        {b}" for b in body]
        return "\n".join(src) + "\n"
    src.append(f"        _s = np.uint64(_c * {chunk})")
    src.append(f"        _e = np.uint64(min(_n, _c * {chunk} + {chunk}))")
    src.append("        for i in range(_s, _e):")
    src.append("            M[i] = 1.0")
    for body in loops:
        src.append("        for i in range(_s, _e):")
        src += [f"            {b}" for b in body]
    return "\n".join(src) + "\n"


def _mg(M, i, m):
    """The margin row at ``i`` lowered to ``m`` (NaN kept, as numpy.minimum keeps it)."""
    cur = M[i]
    M[i] = cur if (cur != cur or cur <= m) else m


def _sel(c, a, b):
    return a if c else b


def _max(a, b):
    return a if a > b else b


def _mg_cols(M, i, m):
    """The margin rows ``M[i]`` lowered to ``m`` (NaN kept)."""
    M[i] = np.minimum(M[i], m)


#: positions per chunk of the numpy kernel (numpy's cost per call outweighs the caches below)
CHUNK_ARRAYS = 8192

_COMPILED: dict = {}


def _compile(src: str, arrays: bool):
    fn = _COMPILED.get((src, arrays))
    if fn is not None:
        return fn
    if arrays:
        ns = {"np": np, "nan": math.nan, "_cos": np.cos, "_sin": np.sin, "_sqrt": np.sqrt,
              "_abs": np.abs, "_sel": np.where, "_max": lambda a, b: np.where(a > b, a, b),
              "_mg": _mg_cols}
        exec(compile(src, "<polygons.fused arrays>", "exec"), ns)
        raw = ns["_fused"]

        def fn(xs, k, O):
            with np.errstate(all="ignore"):
                raw(xs, k, O)
    else:
        import numba
        inline = numba.njit(inline="always")
        ns = {"np": np, "nan": math.nan, "_cos": math.cos, "_sin": math.sin,
              "_sqrt": math.sqrt, "_abs": abs, "_sel": inline(_sel), "_max": inline(_max),
              "_mg": inline(_mg)}
        exec(compile(src, "<polygons.fused>", "exec"), ns)
        fn = numba.njit("void(float64[::1], float64[::1], float64[:, ::1])",
                        error_model="numpy", cache=False, boundscheck=False)(ns["_fused"])
    if len(_COMPILED) >= 256:
        _COMPILED.clear()
    _COMPILED[(src, arrays)] = fn
    return fn


class Fused:
    """A fused kernel and how to read its result block."""

    __slots__ = ("fn", "params", "rows", "links", "source", "index")

    def __init__(self, fn, params, rows, links, source, index):
        self.fn, self.params, self.rows, self.links = fn, params, rows, links
        self.source, self.index = source, index

    def run(self, prog, xs: np.ndarray) -> dict:
        """:func:`polygons.sweep.run`'s result at ``xs``: one block, its rows the results."""
        n = xs.shape[0]
        from .sweep_store import result_block
        O = result_block(len(self.rows), n)
        self.fn(np.ascontiguousarray(xs, dtype=float), self.params, O)
        pos, vel, acc = {}, {}, {}
        for label, xy in prog.ground.items():
            pos[label], vel[label], acc[label] = xy, None, None
        W, AL, TR, SV, SA = {}, {}, {}, {}, {}
        first = {}
        for j, (kind, label) in enumerate(self.rows):
            if kind == "point":
                first[label] = j
            elif kind == "omega":
                W[label] = O[j]
            elif kind == "alpha":
                AL[label] = O[j]
            elif kind == "travel":
                TR[label] = O[j]
            elif kind == "slide_v":
                SV[label] = O[j]
            elif kind == "slide_a":
                SA[label] = O[j]
        for label, j in first.items():
            pos[label], vel[label], acc[label] = O[j:j + 2], O[j + 2:j + 4], O[j + 4:j + 6]
        for name, how in self.links.items():
            if how[0] == "const":
                W[name] = np.broadcast_to(np.float64(how[1]), (n,))
                AL[name] = np.broadcast_to(np.float64(how[2]), (n,))
        # in the arrays program's order (the columns a caller writes follow it)
        order = [label for (key, label) in self.index if key == "pos"]
        pos, vel, acc = (_ordered(d, order) for d in (pos, vel, acc))
        order = [label for (key, label) in self.index if key == "omega"]
        W, AL = _ordered(W, order), _ordered(AL, order)
        return {"pos": pos, "vel": vel, "acc": acc, "omega": W, "alpha": AL, "slide_v": SV,
                "slide_a": SA, "travel": TR, "coriolis": {}, "margin": O[-1]}


def _ordered(d: dict, order) -> dict:
    out = {k: d[k] for k in order if k in d}
    out.update((k, v) for k, v in d.items() if k not in out)
    return out


def fused_of(prog, index, arrays: bool = False):
    """``prog``'s :class:`Fused` kernel, made once per program, or None (a construction the
    kernel does not make; numba missing, unless ``arrays``); ``index``: the outputs it must
    make (the arrays program's); ``arrays``: the same loops over numpy slices (no numba)."""
    memo = memo_of(prog)
    key = "_fused_arrays" if arrays else "_fused"
    if key not in memo:
        from . import jit
        fused = None
        if arrays or jit.available():
            try:
                loops, params, rows, links, margin = generate(prog, index)
                src = source(loops, len(params), len(rows), margin, arrays)
                fused = Fused(_compile(src, arrays), np.array(params, dtype=float),
                              tuple(rows), links, src, tuple(index))
            except Unsupported:
                fused = None
        memo[key] = fused
    return memo[key]


__all__ = ["CHUNK", "CHUNK_ARRAYS", "Fused", "Unsupported", "fused_of", "generate", "source"]
