"""The staged solver's intersection (geometry.meet: GEOS's arithmetic written out in floats,
polygons/geos_crossing.py) against shapely's on the same drawn segments (geometry.meet_drawn):
the same doubles, bit for bit (the design asks ≤ 1e-12), on random lines (and on every
intersection of every shipped case: tests/test_step_records.py)."""
import inspect
import math
import random

from conftest import CASES
from polygons import geometry, geos_crossing


def _same(a, b) -> bool:
    """Equal as doubles, the sign of a zero and NaN included."""
    return all(repr(x) == repr(y) for x, y in zip(a, b))


def test_the_written_out_arithmetic_is_the_generators():
    assert inspect.getsource(geos_crossing._dd_intersection) == geos_crossing.source()


def _lines(rng, n):
    """n random pairs of construction lines: anchors from 1e-6 to 1e4, one anchor at the pole
    at times, lines along the axes at times, angles from 90° down to 1e-5° and up to 180°."""
    axes = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
    for _ in range(n):
        scale = 10 ** rng.uniform(-6, 4)
        px, py, qx, qy = (rng.uniform(-1, 1) * scale for _ in range(4))
        if rng.random() < 0.2:
            qx, qy = 0.0, 0.0
        if rng.random() < 0.1:
            px, qx = 0.0, -0.0
        a = rng.uniform(0, 2 * math.pi)
        gamma = rng.choice([rng.uniform(0.1, 179.9), 10 ** rng.uniform(-5, 0),
                            180 - 10 ** rng.uniform(-5, 0)])
        u = (math.cos(a), math.sin(a))
        v = (math.cos(a + math.radians(gamma)), math.sin(a + math.radians(gamma)))
        if rng.random() < 0.2:
            u = rng.choice(axes)
        if rng.random() < 0.1:
            v = rng.choice([w for w in axes if w[0] != u[0] and w[1] != u[1]])
        yield px, py, *u, qx, qy, *v


def test_meet_is_shapelys_intersection_bit_for_bit():
    rng = random.Random(31)
    for args in _lines(rng, 3000):
        assert _same(geometry.meet(*args), geometry.meet_drawn(*args)), args


def test_where_geos_would_branch_otherwise_shapely_is_asked():
    """An end on the other line (GEOS copies the end point), segments that do not cross and
    parallel ones: crossing() declines, and meet's answer is shapely's."""
    assert geos_crossing.crossing(0.0, 0.0, 2.0, 0.0, 1.0, 0.0, 1.0, 1.0) is None     # T
    assert geos_crossing.crossing(0.0, 0.0, 1.0, 0.0, 2.0, -1.0, 2.0, 1.0) is None    # apart
    assert geos_crossing.crossing(0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0) is None     # ∥
    hit = geos_crossing.crossing(0.0, 0.0, 2.0, 2.0, 0.0, 2.0, 2.0, 0.0)
    assert hit == (1.0, 1.0)
    # lines meeting under the angle the caller refuses: meet and shapely still agree
    args = (0.1, 0.2, 1.0, 0.0, 0.3, 0.4, 1.0, 1e-9)
    assert _same(geometry.meet(*args), geometry.meet_drawn(*args))


def test_the_staged_solve_does_not_load_shapely():
    """polygons.geometry imports shapely only where it is asked (issue 31: a cold solve)."""
    import subprocess
    import sys
    code = ("import sys; from polygons.evaluate import solve; from polygons.scene import "
            f"load_scene; solve(load_scene({str(CASES / 's001-we6.toml')!r})).steps; "
            "print('shapely' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert out.stdout.split() == ["False"], out.stderr
