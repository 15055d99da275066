"""A triad's closure followed through a sweep (split from :mod:`polygons.sweep`, which uses
it; the sweep's own ``evaluate`` and ``run`` are handed in): the program re-referenced at a
row's closure, anchored by continuation from the scene's input, refined to continuation steps,
bisected along the followed branch, and the rows near S at infinity constructed through
another pair of links."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .plan import construction
from .steps import Diagram


def _groups(prog) -> list:
    """The plan's groups of several closures (triads), followed by continuation."""
    return [d for d in prog.plan.dyads if getattr(d, "many_closures", False)]


def _referenced(prog, pos: dict, i: int):
    """``prog`` following, in each triad, the closure at position ``i`` of ``pos`` (an
    evaluation's positions) instead of the scene's own."""
    sigma = dict(prog.sigma)
    for d in _groups(prog):
        sigma.update(zip(d.sigma_keys, (float(pos[d.b][0][i]), float(pos[d.b][1][i]),
                                        float(pos[d.x][0][i]), float(pos[d.x][1][i]))))
    return replace(prog, sigma=sigma)


def _margin_fn(prog, xs: np.ndarray, ok: np.ndarray, evaluate, _margin):
    """The margin at an input x as a function: for a triad, by continuation from the nearest
    probe that assembled (the probes followed the scene's closure), so that bisection and
    golden section stay on the followed branch; else :func:`_margin`."""
    if not _groups(prog):
        return lambda x: float(_margin(prog, x)[0]), (lambda x: prog)
    pos = evaluate(prog, xs, rates=False)["pos"]
    good = np.flatnonzero(ok)
    cache: dict = {}
    turn = 2.0 * math.pi if prog.input_kind == "crank" else math.inf

    def gap(x):         # x − each good probe (round the turn for a crank)
        d = x - xs[good]
        return (d + 0.5 * turn) % turn - 0.5 * turn if math.isfinite(turn) else d

    def near(x):
        i = int(good[np.argmin(np.abs(gap(x)))]) if len(good) else 0
        if i not in cache:
            cache[i] = _referenced(prog, pos, i)
        return i, cache[i]

    def margin(x):
        i, p = near(x)
        dx = float(gap(x)[list(good).index(i)]) if len(good) else 0.0
        return float(_margin(p, [xs[i], xs[i] + dx])[1])
    return margin, (lambda x: near(x)[1])


def anchored(prog, xs: np.ndarray, evaluate):
    """``prog`` following, in each triad, the closure reached by continuation from the
    scene's own input to the input of ``xs`` nearest it (steps of at most 0.25° or 1/1000 of
    the size): every row then follows the scene's closure, whatever inputs are asked.  The
    other way round the turn is tried where the branch ends first; where neither reaches,
    nothing is followed (NaN rows)."""
    if not _groups(prog) or not len(xs):
        return prog
    x0 = prog.input0
    crank = prog.input_kind == "crank"
    if crank:
        rel = (xs - x0 + math.pi) % (2 * math.pi) - math.pi
        j = int(np.argmin(np.abs(rel)))
        targets = [x0 + rel[j], x0 + rel[j] - math.copysign(2 * math.pi, rel[j])]
        h = math.radians(0.25)
    else:
        j = int(np.argmin(np.abs(xs - x0)))
        targets = [float(xs[j])]
        h = 1e-3 * prog.scale
    for target in targets:
        m = int(min(max(2, math.ceil(abs(target - x0) / h) + 1), 20000))
        path = np.linspace(x0, target, m)
        pos = evaluate(prog, path, rates=False)["pos"]
        if all(np.all(np.isfinite(np.asarray(pos[d.b])[:, -1])) for d in _groups(prog)):
            return _referenced(prog, pos, m - 1)
    sigma = dict(prog.sigma)
    for d in _groups(prog):
        sigma.update(dict.fromkeys(d.sigma_keys, math.nan))
    return replace(prog, sigma=sigma)


def _refined(prog, xs: np.ndarray, most: int = 1 << 18):
    """The inputs ``xs`` with inputs inserted between neighbours farther apart than a
    triad's continuation steps (0.25° of a crank, 1/1000 of the size of a slider), and where
    each of ``xs`` is in them: (fine, rows).  At most ``most`` inputs in all (beyond, ``xs``
    as they are)."""
    h = math.radians(0.25) if prog.input_kind == "crank" else 1e-3 * prog.scale
    if len(xs) < 2:
        return xs, np.arange(len(xs))
    gaps = np.abs(np.diff(xs))
    extra = np.ceil(gaps / h).astype(int) - 1
    extra = np.maximum(extra, 0)
    if not extra.any() or len(xs) + int(extra.sum()) > most:
        return xs, np.arange(len(xs))
    parts, rows, at = [], [], 0
    for i in range(len(xs) - 1):
        seg = np.linspace(xs[i], xs[i + 1], extra[i] + 2)[:-1]
        rows.append(at)
        parts.append(seg)
        at += len(seg)
    rows.append(at)
    parts.append(xs[-1:])
    return np.concatenate(parts), np.array(rows)


def _take(res: dict, rows: np.ndarray) -> dict:
    """The results at ``rows`` only."""
    out = {}
    for key, d in res.items():
        if key == "margin":
            out[key] = np.ascontiguousarray(d[rows])
            continue
        out[key] = {lab: (v if v is None or (key == "pos" and np.ndim(v[0]) == 0)
                          else np.array(np.asarray(v)[..., rows]))
                    for lab, v in d.items()}
    return out


def _assur_rows(prog, xs: np.ndarray, res: dict, run):
    """The rows where a triad's auxiliary point S is at infinity or nearly (its two links
    parallel within 1°: a point of the construction, not a singularity of the group) taken
    from the same construction through the pair of links that meet best there (the same
    positions: the closure followed is the same).  Returns (results, notes)."""
    groups = _groups(prog)
    if not groups or not len(xs):
        return res, []
    pos = {k: np.asarray(v, dtype=float) for k, v in res["pos"].items()}

    def sine(d, via):
        if hasattr(d, "pair_sine"):         # a group saying its own pairs (a block at a corner)
            return d.pair_sine(pos, via)
        (p1, o1, _), (p2, o2, _), _ = replace(d, via=via).roles
        u = pos[p1] - pos[o1].reshape(2, -1)
        w = pos[p2] - pos[o2].reshape(2, -1)
        with np.errstate(all="ignore"):
            return np.abs(u[0] * w[1] - u[1] * w[0]) / (np.hypot(*u) * np.hypot(*w))

    def words(d, via):
        if hasattr(d, "pair_words"):
            return d.pair_words(via)
        (q1, r1, _), (q2, r2, _), _ = replace(d, via=via).roles
        return f"{r1}{q1} and {r2}{q2}"
    notes = []
    for gi, d in enumerate(groups):
        s = np.array([sine(d, v) for v in range(3)])
        own = s[d.via]
        rows = np.isfinite(own) & (own < math.sin(math.radians(1.0)))
        if not rows.any():
            continue
        best = np.argmax(np.where(np.isfinite(s), s, -1.0), axis=0)
        pairs = []
        for via in {int(v) for v in best[rows]} - {d.via}:
            take = np.flatnonzero(rows & (best == via))
            dyads = tuple(replace(e, via=via) if e is d else e for e in prog.plan.dyads)
            plan = replace(prog.plan, dyads=dyads)
            alt = replace(prog, plan=plan, steps=construction(plan, tuple(Diagram)))
            other = run(alt, xs[take[0]:take[-1] + 1], chunk=max(len(xs), 1))
            for key in ("vel", "acc", "coriolis", "omega", "alpha", "slide_v", "slide_a"):
                for lab, arr in res[key].items():       # the rows' rates through the other
                    got = other[key].get(lab)          # pair (their positions agree)
                    if isinstance(arr, np.ndarray) and arr.flags.writeable and got is not None:
                        arr[..., take] = np.asarray(got)[..., take - take[0]]
            S = np.asarray(res["pos"][d.s])          # S itself: where that pair meets
            if S.flags.writeable:
                S[:, take] = np.asarray(other["pos"][d.s])[:, take - take[0]]
            pairs.append(f"{words(d, via)} ({len(take)})")
        notes.append(f"{int(rows.sum())} of {len(xs)} positions have {words(d, d.via)} "
                     f"parallel within 1° (the auxiliary point {d.s} at infinity, not a "
                     f"singularity of the group): their rates are constructed with {d.s} "
                     f"where {' or '.join(pairs) or 'they'} meet")
    return res, notes
