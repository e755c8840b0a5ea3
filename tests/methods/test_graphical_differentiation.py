"""Graphical differentiation by chords: the ray through the pole, values at the middles, order 2."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.methods.graphical_differentiation import (derivative_scale, differentiate_by_chords,
                                                         differentiate_cycle)
from graphmech.methods.graphical_integration import differentiate_by_ray, integrate_by_chords


def test_the_ray_through_the_pole_parallel_to_each_chord_cuts_the_ordinate_at_H_times_its_slope():
    d = differentiate_by_chords([0.0, 10.0, 30.0], [0.0, 5.0, -15.0], 40.0)
    assert d.pole == (-40.0, 0.0)
    assert d.derivative_mm.tolist() == [20.0, -40.0]
    assert d.mid_mm.tolist() == [5.0, 20.0]
    for (x0, y0, x1, y1), v in zip(d.chords, d.derivative_mm):  # the ray P→(0, v) is parallel to the chord
        assert (v - 0.0) / 40.0 == pytest.approx((y1 - y0) / (x1 - x0), rel=1e-15)


def test_a_straight_line_is_the_one_chord_case_shared_with_integration():
    assert differentiate_by_ray(160.0, -20.0, 40.0) == differentiate_by_chords([0, 160.0], [0, -20.0], 40.0).derivative_mm[0]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-50, 50), min_size=3, max_size=30), st.floats(5.0, 100.0))
def test_differentiation_undoes_integration_by_chords(ys, H):
    """Integrate by chords with H, differentiate the chord polygon with the same H: the mean ordinates."""
    x = np.arange(len(ys), dtype=float) * 7.0
    g = integrate_by_chords(x, ys, H)
    d = differentiate_by_chords(x, g.integral_mm, H)
    np.testing.assert_allclose(d.derivative_mm, g.mean_mm, rtol=1e-9, atol=1e-9 * (1 + max(map(abs, ys))))


def test_a_cycle_closes_and_converges_at_order_two():
    errs = []
    for n in (12, 120, 1200):
        x = np.arange(n) * 120.0 / n
        d = differentiate_cycle(x, 20.0 * np.sin(2 * np.pi * x / 120.0), 120.0, 30.0)
        exact = 30.0 * 20.0 * (2 * np.pi / 120.0) * np.cos(2 * np.pi * d.mid_mm / 120.0)
        errs.append(float(np.max(np.abs(d.derivative_mm - exact))))
        assert d.derivative_mm.size == n and d.mid_mm[-1] == pytest.approx(120.0 - 60.0 / n)
    assert errs[0] / errs[1] == pytest.approx(100.0, rel=0.05)  # 96.3: N = 12 is not yet asymptotic
    assert errs[1] / errs[2] == pytest.approx(100.0, rel=0.02)


def test_scale_is_the_inverse_of_the_integrals():
    assert derivative_scale(math.radians(2.0), 0.002, 20.0) * (math.radians(2.0) * 20.0) == pytest.approx(0.002)


@pytest.mark.parametrize("args", [([0.0], [0.0], 1.0), ([0.0, 1.0], [0.0], 1.0), ([0.0, 0.0], [0.0, 1.0], 1.0),
                                  ([0.0, 1.0], [0.0, math.nan], 1.0), ([0.0, 1.0], [0.0, 1.0], 0.0)])
def test_bad_input_is_refused(args):
    with pytest.raises(ValueError):
        differentiate_by_chords(*args)


def test_the_result_is_frozen_and_read_only():
    import dataclasses

    d = differentiate_by_chords([0.0, 10.0], [0.0, 5.0], 20.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.H_mm = 1.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        d.derivative_mm[0] = 0.0
