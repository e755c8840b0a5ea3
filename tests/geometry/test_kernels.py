"""Geometry kernels: properties (Hypothesis), one code path for floats and arrays, frozen values."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import AssemblyError, DegenerateConstruction
from graphmech.geometry import Point, Vector
from graphmech.geometry import kernels as K

coord = st.floats(-1e3, 1e3, allow_nan=False)
angle = st.floats(0, 2 * math.pi, allow_nan=False)


@given(coord, coord, angle, coord, coord, angle)
def test_line_intersection_lies_on_both_lines(px, py, a, qx, qy, b):
    s = math.sin(b - a)
    if abs(s) < 1e-3:
        return
    l1 = (px, py, math.cos(a), math.sin(a))
    l2 = (qx, qy, math.cos(b), math.sin(b))
    x, y = K.intersect_lines(K.ScalarOps(), l1, l2)
    scale = 1 + abs(px) + abs(py) + abs(qx) + abs(qy)
    for (ox, oy, dx, dy) in (l1, l2):
        assert abs((x - ox) * dy - (y - oy) * dx) <= 1e-9 * scale / abs(s)


@settings(max_examples=200)
@given(coord, coord, st.floats(1, 500), coord, coord, st.floats(1, 500), st.sampled_from([1.0, -1.0]))
def test_circle_intersection_is_on_both_circles_and_on_the_stated_side(x1, y1, r1, x2, y2, r2, side):
    d = math.hypot(x2 - x1, y2 - y1)
    if not (max(abs(r1 - r2) * 1.001, 1e-6 * (r1 + r2)) < d < (r1 + r2) * 0.999):
        return
    x, y = K.intersect_circles(K.ScalarOps(), (x1, y1), r1, (x2, y2), r2, side, str)
    assert math.hypot(x - x1, y - y1) == pytest.approx(r1, rel=1e-7, abs=1e-9)
    assert math.hypot(x - x2, y - y2) == pytest.approx(r2, rel=1e-7, abs=1e-9)
    assert math.copysign(1, K.cross(x2 - x1, y2 - y1, x - x1, y - y1)) == side


@given(st.lists(st.tuples(coord, coord), min_size=5, max_size=5))
def test_similar_point_keeps_the_shape(pts):
    (U, V, E, u, v) = pts
    if math.dist(U, V) < 1e-3 or math.dist(u, v) < 1e-3:
        return
    e = K.similar_point(K.ScalarOps(), U, V, E, u, v)
    ratio = math.dist(u, v) / math.dist(U, V)
    assert math.dist(u, e) == pytest.approx(ratio * math.dist(U, E), rel=1e-6, abs=1e-6)
    assert math.dist(v, e) == pytest.approx(ratio * math.dist(V, E), rel=1e-6, abs=1e-6)


def test_scalar_and_batch_paths_agree():
    rng = np.random.default_rng(1)
    c2x = rng.uniform(80, 120, 50)
    ops = K.ArrayOps(50)
    xs, ys = K.intersect_circles(ops, (0.0, 0.0), 60.0, (c2x, 0.0 * c2x), 70.0, 1.0, str)
    for i in range(50):
        x, y = K.intersect_circles(K.ScalarOps(), (0.0, 0.0), 60.0, (float(c2x[i]), 0.0), 70.0, 1.0, str)
        assert (x, y) == (xs[i], ys[i])


def test_degenerate_single_raises_naming_the_step_batch_marks():
    ops = K.ScalarOps()
    ops.step = "c = (⟂BC through b) ∩ (⟂DC through p)"
    with pytest.raises(DegenerateConstruction, match=r"⟂BC through b.*parallel"):
        K.intersect_lines(ops, (0.0, 0.0, 1.0, 0.0), (0.0, 1.0, -1.0, 0.0))
    ops = K.ArrayOps(3)
    ops.step = "c"
    dx = np.array([1.0, 0.0, 1.0])
    dy = np.array([0.0, 1.0, 0.0])
    x, y = K.intersect_lines(ops, (0.0, 0.0, 1.0, 0.0), (0.0, 1.0, dx, dy))
    assert ops.bad.tolist() == [True, False, True]
    assert np.isfinite(x).all() and np.isfinite(y).all()
    assert "parallel" in ops.failures["c"][1]


def test_circles_that_do_not_meet_are_an_assembly_error():
    with pytest.raises(AssemblyError, match="too far"):
        K.intersect_circles(K.ScalarOps(), (0.0, 0.0), 1.0, (5.0, 0.0), 1.0, 1.0, lambda d: f"too far: {d}")


def test_tangent_circles_meet_with_infinite_condition():
    ops = K.ScalarOps()
    x, y = K.intersect_circles(ops, (0.0, 0.0), 1.0, (3.0, 0.0), 2.0, 1.0, str)
    assert (x, y) == pytest.approx((1.0, 0.0))
    assert ops.conds["?"] >= 1e299


def test_value_objects_are_frozen():
    p = Point(1.0, 2.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.x = 3.0  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        Vector(1.0, 0.0).y = 2.0  # type: ignore[misc]


def test_circle_meets_line_ahead_or_behind_the_foot():
    ops = K.ScalarOps()
    line = (-10.0, 3.0, 1.0, 0.0)  # y = 3, along +x
    assert K.intersect_circle_line(ops, (0.0, 0.0), 5.0, line, 1.0, str) == pytest.approx((4.0, 3.0))
    assert ops.conds["?"] == pytest.approx(5.0 / 4.0)  # r / half chord
    assert K.intersect_circle_line(ops, (0.0, 0.0), 5.0, line, -1.0, str) == pytest.approx((-4.0, 3.0))
    # the same line drawn the other way round: "ahead" follows its direction
    back = (10.0, 3.0, -1.0, 0.0)
    assert K.intersect_circle_line(ops, (0.0, 0.0), 5.0, back, 1.0, str) == pytest.approx((-4.0, 3.0))


def test_circle_and_line_that_touch_or_miss():
    ops = K.ScalarOps()
    assert K.intersect_circle_line(ops, (0.0, 0.0), 5.0, (0.0, 5.0, 1.0, 0.0), 1.0, str) == pytest.approx((0.0, 5.0))
    assert ops.conds["?"] >= 1e299
    with pytest.raises(AssemblyError, match="6.0 from the line"):
        K.intersect_circle_line(ops, (0.0, 0.0), 5.0, (0.0, -6.0, 1.0, 0.0), 1.0, lambda e: f"{e} from the line")
    batch = K.ArrayOps(2)
    x, y = K.intersect_circle_line(batch, (0.0, 0.0), 5.0, (0.0, np.array([3.0, 6.0]), 1.0, 0.0), 1.0, str)
    assert batch.bad.tolist() == [False, True] and (x[0], y[0]) == pytest.approx((4.0, 3.0))
    assert np.isfinite(x).all() and np.isfinite(y).all()


def test_unit_direction_and_coincident_points():
    assert K.unit(K.ScalarOps(), (1.0, 1.0), (4.0, 5.0)) == (0.6, 0.8, 5.0)
    with pytest.raises(DegenerateConstruction, match="coincide"):
        K.unit(K.ScalarOps(), (2.0, 2.0), (2.0, 2.0))
    # coincidence is relative to the points' size: 1e-11 mm is rounding at 100 mm, not near 0
    with pytest.raises(DegenerateConstruction):
        K.unit(K.ScalarOps(), (100.0, 100.0), (100.0 + 1e-11, 100.0))
    assert K.unit(K.ScalarOps(), (0.0, 0.0), (1e-11, 0.0)) == pytest.approx((1.0, 0.0, 1e-11))


def test_lines_perpendicular_parallel_and_fixed():
    u = (0.6, 0.8, 5.0)
    assert K.line_perpendicular_to(K.ScalarOps(), (1.0, 2.0), u) == (1.0, 2.0, -0.8, 0.6)
    assert K.line_parallel_to(K.ScalarOps(), (1.0, 2.0), u) == (1.0, 2.0, 0.6, 0.8)
    # a fixed direction through points that move takes the points' shape
    px, py, dx, dy = K.line_fixed(K.ArrayOps(3), (np.zeros(3), np.ones(3)), 0.0, 1.0)
    assert dx.shape == dy.shape == (3,) and dy.tolist() == [1.0, 1.0, 1.0]


def test_line_intersection_condition_is_one_over_the_sine():
    ops = K.ScalarOps()
    a = math.radians(30.0)
    x, y = K.intersect_lines(ops, (0.0, 0.0, 1.0, 0.0), (1.0, 0.0, math.cos(a), math.sin(a)))
    assert (x, y) == pytest.approx((1.0, 0.0)) and ops.conds["?"] == pytest.approx(2.0)


def test_similar_point_keeps_the_orientation_not_a_mirror_image():
    # UVE is turned 90° CCW and doubled into uve: E above U goes to the left of u
    e = K.similar_point(K.ScalarOps(), (0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (5.0, 5.0), (5.0, 7.0))
    assert e == pytest.approx((3.0, 5.0))
    with pytest.raises(DegenerateConstruction, match="base points coincide"):
        K.similar_point(K.ScalarOps(), (1.0, 1.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0), (1.0, 0.0))


def test_a_batch_keeps_the_first_reason_of_each_position():
    ops = K.ArrayOps(3)
    ops.step = "first"
    got = ops.fix(np.array([True, False, False]), np.array([1.0, 2.0, 3.0]), 0.0, "one")
    ops.step = "second"
    ops.fix(np.array([True, True, False]), np.zeros(3), 0.0, "two")
    assert got.tolist() == [0.0, 2.0, 3.0]
    assert ops.bad.tolist() == [True, True, False]
    assert ops.failures["first"][0].tolist() == [True, False, False]
    assert ops.failures["second"][0].tolist() == [False, True, False]  # position 0 failed first at "first"
