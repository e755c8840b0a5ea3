"""The frozen geometric value objects of the public API: vector arithmetic, directions, lines."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.geometry.primitives import Circle, Line, Point, Vector, as_point, degrees_0_360


def test_vector_arithmetic() -> None:
    u, v = Vector(3.0, 4.0), Vector(-1.0, 2.0)
    assert abs(u) == 5.0
    assert u + v == Vector(2.0, 6.0) and u - v == Vector(4.0, 2.0)
    assert u * 2.0 == 2.0 * u == Vector(6.0, 8.0)
    assert u.perp() == Vector(-4.0, 3.0)
    assert u.perp().perp() == u * -1.0  # two quarter turns reverse it


def test_unit_keeps_the_direction_and_refuses_the_zero_vector() -> None:
    assert Vector(3.0, 4.0).unit() == Vector(0.6, 0.8)
    assert abs(Vector(1e-300, 1e-300).unit()) == pytest.approx(1.0, rel=1e-15)
    with pytest.raises(ArithmeticError, match="zero-length"):
        Vector(0.0, 0.0).unit()


@pytest.mark.parametrize("x, y, deg", [(1.0, 0.0, 0.0), (0.0, 1.0, 90.0), (-1.0, 0.0, 180.0),
                                        (0.0, -1.0, 270.0), (1.0, -1.0, 315.0)])
def test_angle_is_in_0_to_two_pi(x: float, y: float, deg: float) -> None:
    a = Vector(x, y).angle
    assert 0.0 <= a < math.tau and a == pytest.approx(math.radians(deg), abs=1e-15)


def test_points_and_vectors() -> None:
    p, q = Point(1.0, 2.0), Point(4.0, 6.0)
    assert q - p == Vector(3.0, 4.0)
    assert p + (q - p) == q


def test_line_through_two_points_has_a_unit_direction() -> None:
    line = Line.through(Point(1.0, 1.0), Point(1.0, -4.0))
    assert line.point == Point(1.0, 1.0) and line.direction == Vector(0.0, -1.0)
    with pytest.raises(ArithmeticError):
        Line.through(Point(2.0, 2.0), Point(2.0, 2.0))


def test_as_point_accepts_a_point_or_a_pair() -> None:
    p = Point(1.0, 2.0)
    assert as_point(p) is p
    got = as_point((3, 4))
    assert got == Point(3.0, 4.0) and type(got.x) is float
    assert as_point(np.array([0.5, -1.5])) == Point(0.5, -1.5)


def test_values_are_frozen_and_hashable() -> None:
    c = Circle(Point(0.0, 0.0), 2.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.r = 3.0  # type: ignore[misc]
    assert len({Point(1.0, 2.0), Point(1.0, 2.0), Point(2.0, 1.0)}) == 2


@pytest.mark.parametrize("theta, degrees", [
    (0.0, 0.0), (-0.0, 0.0), (math.pi / 2, 90.0), (-math.pi / 2, 270.0),
    (math.atan2(math.sin(2 * math.pi), math.cos(2 * math.pi)), 0.0),  # −2.4e-16 rad: not 360.0
    (5 * math.pi, 180.0),
])
def test_degrees_0_360_never_gives_360(theta, degrees):
    got = degrees_0_360(theta)
    assert got == pytest.approx(degrees, abs=1e-12) and 0.0 <= got < 360.0 and math.copysign(1.0, got) == 1.0
