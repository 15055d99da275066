"""One hand-checked test per geometric primitive and theorem."""
import math

import numpy as np
import pytest

from polygons import geometry, theorems, units
from polygons.errors import ParallelLinesError, SceneError, UnitError
from polygons.scene import split_link_name


def test_relative_velocity_is_omega_times_length_perpendicular():
    # crank 50 mm at 90 deg turning CCW at 10 rad/s: v = 0.5 m/s towards -x
    v = theorems.relative_velocity(10.0, [0.0, 0.05])
    assert v == pytest.approx([-0.5, 0.0], abs=1e-15)


def test_centripetal_points_towards_the_centre_with_omega_squared_r():
    # B at (0.1, 0) about A at origin, ω = 3 (either sense): a = 0.9 m/s² towards A (-x)
    assert theorems.centripetal(3.0, [0.1, 0.0]) == pytest.approx([-0.9, 0.0])
    assert theorems.centripetal(-3.0, [0.1, 0.0]) == pytest.approx([-0.9, 0.0])


def test_tangential_is_alpha_cross_r():
    # α = 2 rad/s² CW on r = (0, 0.5): α × r = -2 k × 0.5 j = +1.0 i
    assert theorems.tangential(-2.0, [0.0, 0.5]) == pytest.approx([1.0, 0.0])


def test_coriolis_is_2_omega_v_turned_in_sense_of_omega():
    # ω = 1.5 CCW, sliding v = 2 m/s along +x: 2ω × v = 6 m/s² along +y
    assert theorems.coriolis(1.5, [2.0, 0.0]) == pytest.approx([0.0, 6.0])
    assert theorems.coriolis(-1.5, [2.0, 0.0]) == pytest.approx([0.0, -6.0])


def test_angular_velocity_and_acceleration_invert_the_theorems():
    r = np.array([0.03, -0.04])
    assert theorems.angular_velocity(r, theorems.relative_velocity(-7.0, r)) == pytest.approx(-7.0)
    a = theorems.tangential(12.0, r) + theorems.centripetal(5.0, r)
    assert theorems.angular_acceleration(r, a) == pytest.approx(12.0)


def test_intersect_perpendicular_lines():
    hit = geometry.intersect(geometry.line((0, 1), (1, 0), "horizontal"),
                             geometry.line((2, 0), (0, 1), "vertical"))
    assert hit.point == pytest.approx((2.0, 1.0), abs=1e-15)
    assert hit.angle_deg == pytest.approx(90.0)


def test_intersect_reports_the_acute_angle_and_is_exact_for_30_degrees():
    l1 = geometry.line((0, 0), (1, 0), "slider line")
    l2 = geometry.line((1, 0), (math.cos(math.radians(150)), math.sin(math.radians(150))), "c line")
    hit = geometry.intersect(l1, l2)
    assert hit.point == pytest.approx((1.0, 0.0), abs=1e-15)
    assert hit.angle_deg == pytest.approx(30.0)


def test_intersect_far_away_point_of_nearly_parallel_lines():
    # lines through (0,0) and (0,1) at 0 and 0.01 deg: they meet 1/tan(0.01°) to the left
    t = math.tan(math.radians(0.01))
    hit = geometry.intersect(geometry.line((0, 0), (1, 0)), geometry.line((0, 1), (1, t)))
    assert hit.point[0] == pytest.approx(-1 / t, rel=1e-9)
    assert hit.angle_deg == pytest.approx(0.01, rel=1e-9)


def test_subnormal_coordinates_do_not_derail_the_intersection():
    # found by hypothesis: a crank at 2e-313 rad put a vertical line at x = -5e-314, and GEOS
    # returned the segment's end point instead of the crossing
    hit = geometry.intersect(geometry.line((-5.215016856e-314, 0.234375), (-0.0, 1.0)),
                             geometry.line((0.0, 0.0), (1.0, 0.0)))
    assert hit.point == pytest.approx((0.0, 0.0), abs=1e-300)


def test_meet_is_the_crossing_of_the_drawn_segments():
    """X = P + t u = Q + s v, hand-checked: the 3-4-5 lines from (0, 0) and (6, 0) meet at
    (3, 4); lines through one point meet there exactly (an instant at rest)."""
    assert geometry.meet(0.0, 0.0, 0.6, 0.8, 6.0, 0.0, -0.6, 0.8) == pytest.approx((3.0, 4.0),
                                                                             abs=1e-15)
    assert geometry.meet(2.0, 5.0, 1.0, 0.0, 2.0, 5.0, 0.0, 1.0) == (2.0, 5.0)


def test_meet_of_anchors_an_ulp_apart_far_from_the_origin():
    """Anchors 1e-12 apart at 7700 m/s² (a parallelogram four-bar's acceleration polygon): the
    segments are drawn at least as long as the coordinates' size, so shapely still finds the
    point (it found none on segments 1e-12 long)."""
    x, y = geometry.meet(-7712.741183798629, -7575.981453466156, -5.551115123125783e-17, 1.0,
                         -7712.741183798629, -7575.9814534661555, -0.7007535786004547,
                         0.7134034076724448)
    assert abs(x + 7712.741183798629) <= 1e-11 and abs(y + 7575.981453466156) <= 1e-11


def test_parallel_lines_raise_a_named_error():
    with pytest.raises(ParallelLinesError, match="c line.*slider line.*parallel"):
        geometry.intersect(geometry.line((0, 0), (1, 0), "c line"),
                           geometry.line((0, 1), (-2, 0), "slider line"), step="acceleration 4")


def test_units_convert_to_si():
    assert units.parse_quantity("50 mm", "length") == pytest.approx(0.05)
    assert units.parse_quantity("2000 rev/min", "angular_velocity") == pytest.approx(209.43951023931953)
    assert units.parse_quantity("60 deg", "angle") == pytest.approx(math.pi / 3)
    assert units.parse_quantity("1.2 MPa", "pressure") == pytest.approx(1.2e6)
    assert units.parse_quantity("3 %", "fraction") == pytest.approx(0.03)


@pytest.mark.parametrize("value,dimension,message", [
    (50, "length", "missing unit"),
    ("50", "length", "missing unit"),
    ("50 furlong", "length", "unknown unit"),
    ("50 rad/s", "length", "angular velocity"),
    ("fifty mm", "length", "cannot read"),
])
def test_units_reject_bad_values(value, dimension, message):
    with pytest.raises(UnitError, match=message):
        units.parse_quantity(value, dimension, file="x.toml", where="links.AB")


def test_link_names_split_into_labels():
    assert split_link_name("BC") == ("B", "C")
    assert split_link_name("O2P2") == ("O2", "P2")
    with pytest.raises(SceneError):
        split_link_name("ABC")
    with pytest.raises(SceneError):
        split_link_name("bc")
