"""The staged solve's quick paths against the code they replaced, to the bit, on every case.

The Step records a solution shows (compiled.steps_from_record: their reading written out once
per layout) against the reading as a loop over the layout (the reference below, the code it
replaced): the same records, every number to the bit, on every shipped case, staged and
compiled; and every intersection of those staged solves (geometry.meet) repeated by shapely
(geometry.meet_drawn) to the bit; and the assembly over plain floats
(position._assemble_floats) against the assembly over arrays (position._assemble_arrays)."""
import math

from conftest import CASES
from polygons import geometry, position
from polygons.compiled import compile_scene, steps_from_record
from polygons.evaluate import planned, solve
from polygons.reader import record_of
from polygons.scene import load_scene
from polygons.steps import Step, Term, noise_floor

_FIELDS = ("at", "vector", "point", "direction")
_RATES = ("rad/s", "rad/s^2", "m/s", "m/s^2")


def _term(r, i):
    if type(i) is int:
        return r[i]
    if i[0] == "abs":
        return abs(r[i[1]])
    if i[0] == "hypot":
        return math.hypot(r[i[1]], r[i[2]])
    r0, r1, q0, q1 = (r[j] for j in i[1:])
    n = math.hypot(r0, r1)
    return abs(r0 / n * q1 - r1 / n * q0)


def _zero(numbers, layout):
    scale = dict.fromkeys(_RATES, 0.0)
    for (terms, value), o in zip(numbers, layout):
        for _, v, u in terms:
            if u in scale and abs(v) > scale[u]:
                scale[u] = abs(v)
        if value is not None and o.unit in scale and abs(value) > scale[o.unit]:
            scale[o.unit] = abs(value)
    scale["rad/s^2"] = max(scale["rad/s^2"], scale["rad/s"] ** 2)
    floor = {u: noise_floor([v]) for u, v in scale.items()}

    def zero(v, u):
        f = floor.get(u)
        return 0.0 if f is not None and abs(v) <= f else v
    return zero


def reference(steps, layout, r):
    """The records read by a loop over the layout (the code steps_from_record replaced)."""
    numbers = [([(sym, _term(r, i), u) for sym, i, u in o.terms],
                None if o.value is None else r[o.value]) for o in layout]
    zero = _zero(numbers, layout)
    done = []
    for step, o, (terms, value) in zip(steps, layout, numbers):
        vals = step.__dict__.copy()
        for k in _FIELDS:
            ij = o.fields.get(k)
            vals[k] = None if ij is None else (r[ij[0]], r[ij[1]])
        vals["value"] = None if value is None else zero(value, o.unit)
        vals["unit"] = o.unit
        vals["angle_deg"] = None if o.angle is None else r[o.angle]
        vals["terms"] = tuple(Term(sym, zero(v, u), u) for sym, v, u in terms)
        done.append(record_of(Step, vals))
    return tuple(done)


def test_the_step_records_are_the_loops_on_every_case(monkeypatch):
    calls = []
    meet = geometry.meet

    def spy(*args):
        calls.append(args)
        return meet(*args)

    monkeypatch.setattr(geometry, "meet", spy)
    seen = 0
    for path in sorted(CASES.glob("*.toml")):
        scene = load_scene(str(path))
        try:
            sol = solve(scene)
        except Exception:           # refused either way
            continue
        _, steps, staged = planned(scene, None)
        got = sol.steps
        want = reference(steps, staged.code.layout, sol.record)
        assert got == want and repr(got) == repr(want), path.name
        assert all(type(s) is Step and all(type(t) is Term for t in s.terms) for s in got)
        assert [list(s.__dict__) for s in got] == [list(s.__dict__) for s in want]
        seen += 1
        if path.stem in ("s003-fig7", "rest-slider-crank"):
            prog = compile_scene(scene)
            sol2 = prog.solve()
            assert repr(sol2.steps) == repr(reference(prog.steps, prog.code.layout,
                                                      sol2.record))
    assert seen > 60 and len(calls) > 100
    for args in calls:
        assert repr(meet(*args)) == repr(geometry.meet_drawn(*args)), args


def test_a_builder_is_written_once_per_layout():
    scene = load_scene(str(CASES / "s001-we6.toml"))
    sol = solve(scene)
    _, steps, staged = planned(scene, None)
    from polygons.compiled import steps_builder
    assert steps_builder(staged.code.layout) is steps_builder(staged.code.layout)
    assert steps_from_record(scene, steps, staged.code.layout, sol.record) == sol.steps


def test_the_assembly_over_floats_is_the_assembly_over_arrays():
    """Every case the float path takes: the same points, closures and words as over arrays;
    the cases it leaves to the arrays (a triad, a slot slider) are left whole."""
    taken = 0
    for path in sorted(CASES.glob("*.toml")):
        plan = planned(load_scene(str(path)), None)[0]
        fast = position._assemble_floats(plan)
        if fast is None:
            continue
        slow = position._assemble_arrays(plan)
        assert repr(fast.points) == repr(slow.points), path.name
        assert fast.branches == slow.branches and dict(fast.sigmas) == dict(slow.sigmas)
        taken += 1
    assert taken > 60


def _shape_reference(value):
    """compiled._shape as a plain walk (each value's kind worked out at each visit)."""
    import numpy as np
    from dataclasses import fields, is_dataclass
    from typing import Mapping
    out, stack = [], [value]
    while stack:
        v = stack.pop()
        if v is None or isinstance(v, (str, bool, int)) and not isinstance(v, np.integer):
            out.append(v)
        elif isinstance(v, (float, np.floating)):
            out.append(float)
        elif is_dataclass(v):
            out.append(type(v).__qualname__)
            for f in fields(v):
                if f.compare:
                    stack.append(getattr(v, f.name))
                    out.append(f.name)
        elif isinstance(v, Mapping):
            out.append((type(v).__name__, len(v)))
            for k, item in v.items():
                stack.append(item)
                stack.append(k)
        elif isinstance(v, (tuple, list, np.ndarray)):
            out.append(("seq", len(v)))
            stack.extend(reversed(list(v)))
        else:
            out.append(type(v).__qualname__)
    return tuple(out)


def test_the_code_cache_key_reads_each_type_as_the_plain_walk():
    """compiled._shape (how each type is read, worked out once per type) gives the key the
    plain walk gives, on every case's tables and model (and on a class, a numpy integer)."""
    import numpy as np
    from polygons import compiled
    for path in sorted(CASES.glob("*.toml")):
        scene = load_scene(str(path))
        for name in compiled._SHAPED_BY + ("model", "assembly", "answers"):
            v = getattr(scene, name, None)
            assert compiled._shape(v) == _shape_reference(v), (path.name, name)
    odd = [int, np.int64(3), np.float32(1.5), {"a": (1, 2.0, None)}, [True, "x"], object()]
    assert compiled._shape(odd)[:-1] == _shape_reference(odd)[:-1]
