"""Closed forms of circular-profile higher pairs, written from the cam's own geometry (not from a
substituted linkage), to check 高副低代 against.

An eccentric circular cam (偏心圆盘凸轮): a disc of radius R turning about A at the origin, its
centre C at eccentricity e, ∠(AC) = φ from +x, ω = dφ/dt, ε = dω/dt. A translating follower on
a guide parallel to +y through x = d (the follower's offset):

* a **roller** of radius r: its centre B = (d, y) stays at R + r from C, so
  ``y = e·sinφ + √((R + r)² − (d − e·cosφ)²)``;
* a **flat face** perpendicular to the guide: the face is tangent to the disc above C, so
  ``y_face = e·sinφ + R`` (the Scotch yoke: v = eω·cosφ).

Velocities and accelerations are the analytic derivatives: v = y′ω, a = y″ω² + y′ε.
"""
from __future__ import annotations

import math

from graphmech.errors import OutOfDomain


def eccentric_cam_roller(e: float, radius: float, roller: float, offset: float, phi: float,
                         omega: float, epsilon: float = 0.0) -> tuple[float, float, float]:
    """(y, v, a) of a translating roller follower's centre driven by an eccentric circular cam (SI).

    >>> y, v, a = eccentric_cam_roller(0.02, 0.04, 0.015, 0.0, math.pi / 2, 10.0)
    >>> round(y, 9), round(v, 9) + 0.0  # v is ±1e-17 at the top: no sign to print
    (0.075, 0.0)
    """
    length = radius + roller
    u = offset - e * math.cos(phi)  # the horizontal reach from C to the follower's line
    if abs(u) >= length:
        raise OutOfDomain(f"the roller cannot reach the guide: |d − e·cosφ| = {abs(u):.6g} m ≥ R + r = {length:.6g} m")
    w = math.sqrt(length * length - u * u)
    s, c = math.sin(phi), math.cos(phi)
    y = e * s + w
    d1 = e * c - u * e * s / w  # dy/dφ
    d2 = -e * s - (e * e * s * s + u * e * c) / w - (u * e * s) ** 2 / w ** 3  # d²y/dφ²
    return y, d1 * omega, d2 * omega * omega + d1 * epsilon


def eccentric_cam_flat(e: float, radius: float, phi: float, omega: float,
                       epsilon: float = 0.0) -> tuple[float, float, float]:
    """(y, v, a) of a translating flat-faced follower's face driven by an eccentric circular cam (SI)."""
    s, c = math.sin(phi), math.cos(phi)
    return e * s + radius, e * c * omega, -e * s * omega * omega + e * c * epsilon


def rolling_wheel_omega(v_centre: float, radius: float) -> float:
    """ω of a wheel of radius r rolling on a fixed straight track below it, its centre moving at
    v (+ along the track's direction, the wheel above it): ω = −v/r (rolling to +x turns it CW)."""
    return -v_centre / radius
