"""Frozen geometric value objects for the public API (not used in inner loops).

>>> p = Point(3.0, 4.0)
>>> abs(Vector(3.0, 4.0))
5.0
>>> Line.through(Point(0, 0), Point(3, 4)).direction
Vector(x=0.6, y=0.8)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence, Union


def degrees_0_360(theta: float) -> float:
    """An angle (rad) in degrees in [0, 360): −0° and −1e-17° are 0°, not 360° (``x % 360`` is
    360.0 itself for a tiny negative x, as sin 2π ≈ −2.4e-16 gives).

    >>> degrees_0_360(-0.0), degrees_0_360(-1e-19), degrees_0_360(-math.pi / 2)
    (0.0, 0.0, 270.0)
    """
    g = math.degrees(theta) % 360.0
    return 0.0 if g >= 360.0 else g + 0.0


@dataclass(frozen=True)
class Vector:
    """A free vector (dx, dy)."""

    x: float
    y: float

    def __abs__(self) -> float:
        return math.hypot(self.x, self.y)

    def __add__(self, o: "Vector") -> "Vector":
        return Vector(self.x + o.x, self.y + o.y)

    def __sub__(self, o: "Vector") -> "Vector":
        return Vector(self.x - o.x, self.y - o.y)

    def __mul__(self, k: float) -> "Vector":
        return Vector(self.x * k, self.y * k)

    __rmul__ = __mul__

    def perp(self) -> "Vector":
        """The vector turned 90° counter-clockwise."""
        return Vector(-self.y, self.x)

    def unit(self) -> "Vector":
        n = abs(self)
        if n == 0.0:
            from graphmech.errors import DegenerateConstruction

            raise DegenerateConstruction("unit vector", "zero-length vector has no direction")
        return Vector(self.x / n, self.y / n)

    @property
    def angle(self) -> float:
        """Direction in radians, [0, 2π)."""
        return math.atan2(self.y, self.x) % math.tau


@dataclass(frozen=True)
class Point:
    """A point (x, y)."""

    x: float
    y: float

    def __sub__(self, o: "Point") -> Vector:
        return Vector(self.x - o.x, self.y - o.y)

    def __add__(self, v: Vector) -> "Point":
        return Point(self.x + v.x, self.y + v.y)


@dataclass(frozen=True)
class Line:
    """An infinite line through ``point`` along the unit ``direction``."""

    point: Point
    direction: Vector

    @staticmethod
    def through(a: Point, b: Point) -> "Line":
        return Line(a, (b - a).unit())


@dataclass(frozen=True)
class Circle:
    center: Point
    r: float


PointLike = Union[Point, Sequence[float]]


def as_point(p: PointLike) -> Point:
    """Accept a Point or an (x, y) pair (input alias → returned type)."""
    return p if isinstance(p, Point) else Point(float(p[0]), float(p[1]))
