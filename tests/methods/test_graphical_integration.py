"""Graphical integration by chords and differentiation by a ray, on drawing millimetres."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.methods.graphical_integration import (Integration, differentiate_by_ray, integral_scale,
                                                     integrate_by_chords)


def test_each_chord_is_parallel_to_its_ray_and_starts_where_the_last_ended():
    rng = np.random.default_rng(1)
    x = np.cumsum(rng.uniform(2.0, 15.0, 13)) - 2.0
    y = rng.uniform(-30.0, 40.0, 13)
    g = integrate_by_chords(x, y, 35.0)
    assert g.pole == (-35.0, 0.0) and g.integral_mm[0] == 0.0
    # the ray from P to the projection (0, mean_i) of the mean ordinate
    ray = (0.0 - g.pole[1] + g.mean_mm) / (0.0 - g.pole[0])
    chords = g.chords
    np.testing.assert_allclose((chords[:, 3] - chords[:, 1]) / (chords[:, 2] - chords[:, 0]), ray, rtol=1e-12)
    np.testing.assert_array_equal(chords[1:, :2], chords[:-1, 2:])  # a polygon, no gaps
    np.testing.assert_allclose(g.ray_slopes, ray, rtol=1e-15)


def test_the_mean_ordinate_is_the_step_of_equal_area():
    x = np.array([0.0, 10.0, 25.0, 30.0])
    y = np.array([4.0, 10.0, -2.0, 6.0])
    g = integrate_by_chords(x, y, 20.0)
    np.testing.assert_array_equal(g.mean_mm, [7.0, 4.0, 2.0])
    # area under the step = area of the trapezoids = H × the chord polygon's rise
    assert g.integral_mm[-1] * 20.0 == pytest.approx(np.trapezoid(y, x), rel=1e-15)


def test_drawn_integral_times_its_scale_is_the_integral():
    """M(φ) at μM, φ at μφ, pole H: the drawn work times μA = μM·μφ·H is ∫M dφ (exact for a linear M)."""
    mu_phi, mu_M, H = math.radians(2.0), 5.0, 40.0
    phi = np.linspace(0.0, math.pi, 19)
    M = 120.0 - 30.0 * phi  # linear: chords integrate it exactly
    g = integrate_by_chords(phi / mu_phi, M / mu_M, H)
    mu_A = integral_scale(mu_phi, mu_M, H)
    assert mu_A == pytest.approx(mu_M * mu_phi * H)
    np.testing.assert_allclose(g.integral_mm * mu_A, 120.0 * phi - 15.0 * phi ** 2, rtol=1e-13, atol=1e-12)


def test_chords_converge_at_second_order():
    errors = []
    for n in (16, 32, 64, 128):
        x = np.linspace(0.0, math.pi, n + 1)
        g = integrate_by_chords(x, np.sin(x), 1.0)
        errors.append(np.max(np.abs(g.integral_mm - (1.0 - np.cos(x)))))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    np.testing.assert_allclose(orders, 2.0, atol=0.02)


def test_differentiation_by_a_ray_recovers_the_constant_that_was_integrated():
    x = np.linspace(0.0, 144.0, 13)
    for c in (-12.5, 0.0, 7.25):
        g = integrate_by_chords(x, np.full(13, c), 40.0)
        d = differentiate_by_ray(float(x[-1]), float(g.integral_mm[-1]), 40.0)
        assert d == pytest.approx(c, abs=1e-12)
        # the ray from P = (−H, 0) to (0, d) is parallel to the line from the origin to the end
        assert (d - 0.0) / 40.0 == pytest.approx(g.integral_mm[-1] / x[-1], abs=1e-15)


def test_the_construction_is_frozen_and_its_arrays_read_only():
    g = integrate_by_chords([0.0, 1.0, 2.0], [1.0, 1.0, 1.0], 1.0)
    assert isinstance(g, Integration)
    with pytest.raises(dataclasses.FrozenInstanceError):
        g.H_mm = 2.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        g.integral_mm[0] = 5.0
    x = np.array([0.0, 1.0, 2.0])
    g = integrate_by_chords(x, [0.0, 1.0, 2.0], 1.0)
    x[1] = 9.0  # the caller's array is not the construction's
    assert g.x_mm[1] == 1.0


@pytest.mark.parametrize("x, y, H", [
    ([0.0, 1.0], [1.0], 1.0),            # lengths differ
    ([0.0], [1.0], 1.0),                 # one division
    ([0.0, 2.0, 1.0], [1.0, 1.0, 1.0], 1.0),  # not increasing
    ([0.0, 1.0, 1.0], [1.0, 1.0, 1.0], 1.0),  # a zero interval
    ([0.0, 1.0], [1.0, math.nan], 1.0),  # not finite
    ([0.0, 1.0], [1.0, 1.0], 0.0),       # no pole distance
    ([0.0, 1.0], [1.0, 1.0], -5.0),
])
def test_bad_input_is_refused(x, y, H):
    with pytest.raises(ValueError):
        integrate_by_chords(x, y, H)


def test_differentiation_needs_a_line_of_positive_length_and_a_pole():
    with pytest.raises(ValueError):
        differentiate_by_ray(0.0, 1.0, 40.0)
    with pytest.raises(ValueError):
        differentiate_by_ray(100.0, 1.0, 0.0)
    with pytest.raises(ValueError):
        differentiate_by_ray(100.0, math.inf, 40.0)


def test_thousands_of_intervals_in_one_call():
    x = np.linspace(0.0, 150.0, 3601)
    g = integrate_by_chords(x, 20.0 * np.sin(x / 150.0 * 2 * math.pi), 40.0)
    assert g.integral_mm.shape == (3601,) and abs(g.integral_mm[-1]) < 1e-9
