"""The circular cam's closed forms against their own definitions: the position from the geometry
(the roller's centre at R + r from the disc's centre, on the guide), the derivatives by central
differences, and the rolling wheel's sense."""
from __future__ import annotations

import math

import pytest

from graphmech.exact.higher_pair import (
    eccentric_cam_flat,
    eccentric_cam_roller,
    rolling_wheel_omega,
)

E, R, ROLLER, D, OMEGA = 0.02, 0.04, 0.015, 0.01, 10.0


@pytest.mark.parametrize("deg", [0, 45, 90, 150, 210, 300])
def test_roller_centre_is_at_R_plus_r_from_the_disc_centre_on_the_guide(deg):
    phi = math.radians(deg)
    y, _, _ = eccentric_cam_roller(E, R, ROLLER, D, phi, OMEGA)
    c = (E * math.cos(phi), E * math.sin(phi))
    assert math.dist(c, (D, y)) == pytest.approx(R + ROLLER, rel=1e-12)
    assert y > c[1]  # the roller above the disc's centre (the follower's branch)


@pytest.mark.parametrize("deg", [10, 45, 120, 210, 333])
def test_velocity_and_acceleration_are_the_derivatives(deg):
    phi, h = math.radians(deg), 1e-4
    y = [eccentric_cam_roller(E, R, ROLLER, D, phi + k * h, OMEGA)[0] for k in (-1, 0, 1)]
    _, v, a = eccentric_cam_roller(E, R, ROLLER, D, phi, OMEGA)
    assert v == pytest.approx(OMEGA * (y[2] - y[0]) / (2 * h), rel=1e-7)
    assert a == pytest.approx(OMEGA ** 2 * (y[2] - 2 * y[1] + y[0]) / h ** 2, rel=1e-5)


def test_angular_acceleration_adds_y_prime_epsilon():
    _, v0, a0 = eccentric_cam_roller(E, R, ROLLER, D, 0.7, OMEGA)
    _, _, a1 = eccentric_cam_roller(E, R, ROLLER, D, 0.7, OMEGA, epsilon=3.0)
    assert a1 - a0 == pytest.approx(3.0 * v0 / OMEGA, rel=1e-12)


def test_known_values_at_45_degrees():
    # the kin.eccentric_cam_substitute scene's first position, worked by hand:
    # u = d − e·cos45° = −0.0041421, w = √(0.055² − u²) = 0.0548438, y = e·sin45° + w
    y, v, a = eccentric_cam_roller(E, R, ROLLER, D, math.radians(45), OMEGA)
    assert y == pytest.approx(0.0689859385, abs=1e-10)
    assert v == pytest.approx(0.1521023522, abs=1e-10)
    assert a == pytest.approx(-1.674155772, abs=1e-9)


def test_a_centred_follower_at_the_top_stands_still():
    y, v, a = eccentric_cam_roller(E, R, ROLLER, 0.0, math.pi / 2, OMEGA)
    assert (y, v) == (pytest.approx(E + R + ROLLER), pytest.approx(0.0, abs=1e-15))
    assert a == pytest.approx(-OMEGA ** 2 * E * (1 + E / (R + ROLLER)), rel=1e-12)


def test_flat_face_is_the_scotch_yoke():
    y, v, a = eccentric_cam_flat(E, R, math.radians(30), OMEGA)
    assert (y, v, a) == pytest.approx((E * 0.5 + R, E * OMEGA * math.sqrt(3) / 2, -E * OMEGA ** 2 * 0.5), rel=1e-12)


def test_a_roller_that_cannot_reach_the_guide_is_refused():
    with pytest.raises(ValueError, match="cannot reach"):
        eccentric_cam_roller(E, R, ROLLER, 0.2, 0.0, OMEGA)


def test_a_wheel_rolling_forward_turns_clockwise():
    assert rolling_wheel_omega(0.3, 0.04) == pytest.approx(-7.5)
    assert rolling_wheel_omega(-0.3, 0.04) == pytest.approx(7.5)
