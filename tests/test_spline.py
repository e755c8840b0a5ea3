"""The periodic cubic spline of graphmech.spline: the same floats as scipy's
CubicSpline(bc_type="periodic") (the same construction and evaluation), and the refusals."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import OutOfDomain
from graphmech.spline import PeriodicSpline


def _closed_run(radii: list[float], turns: list[float]) -> tuple[np.ndarray, np.ndarray]:
    ang = np.cumsum(turns) / np.sum(turns) * 2.0 * math.pi
    p = np.column_stack([np.multiply(radii, np.cos(ang)), np.multiply(radii, np.sin(ang))])
    closed = np.vstack([p, p[:1]])
    return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))]), closed


@settings(max_examples=120, deadline=None)
@given(st.integers(3, 40).flatmap(lambda n: st.tuples(st.lists(st.floats(0.01, 0.08), min_size=n, max_size=n),
                                                      st.lists(st.floats(0.05, 1.0), min_size=n, max_size=n))),
       st.lists(st.floats(-3.0, 3.0), min_size=1, max_size=20))
def test_every_coefficient_and_value_is_scipys_to_the_last_bit(run, where):
    from scipy.interpolate import CubicSpline

    t, closed = _closed_run(*run)
    want = CubicSpline(t, closed, bc_type="periodic")
    got = PeriodicSpline(t.tolist(), closed.tolist())
    assert np.array_equal(got.c, want.c)
    ts = np.concatenate([np.asarray(where) * t[-1], t])  # beyond a period either way, and the knots
    for order in range(4):
        expected = want(ts, order)
        assert np.array_equal(got.at(ts, order), expected)
        assert [got.point(float(x), order) for x in ts] == [tuple(row) for row in expected]
    assert [got.point_and_slope(float(x)) for x in ts] == [(got.point(float(x)), got.point(float(x), 1)) for x in ts]


def test_a_circle_through_four_points():
    s = PeriodicSpline([0.0, 1.0, 2.0, 3.0, 4.0], [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0], [1.0, 0.0]])
    assert s.period == 4.0 and s.point(1.0) == (0.0, 1.0) and s.point(-3.0) == s.point(5.0) == (0.0, 1.0)
    assert s.at(np.array([[0.0, 2.0]])).shape == (1, 2, 2)  # t's shape, then the coordinates
    x, y = s.point(0.5)
    assert 0.7 < math.hypot(x, y) < 1.1


@pytest.mark.parametrize(("x", "y", "why"), [
    ([0.0, 1.0, 2.0], [[0.0], [1.0], [0.0]], "at least 4"),
    ([0.0, 1.0, 2.0, 3.0], [[0.0], [1.0], [2.0], [1.0]], "last equal"),
    ([0.0, 1.0, 1.0, 3.0], [[0.0], [1.0], [2.0], [0.0]], "increase"),
    ([0.0, 1.0, 2.0, 3.0], [[0.0], [math.nan], [2.0], [0.0]], "finite"),  # scipy: ValueError, not NaN coefficients
    ([0.0, 1.0, 2.0, math.inf], [[0.0], [1.0], [2.0], [0.0]], "finite"),
    ([0.0, 1.0, 2.0, 3.0], [[0.0], [1e308], [-1e308], [0.0]], "overflow"),  # scipy: `dydx` must be finite
])
def test_what_is_refused(x, y, why):
    with pytest.raises(OutOfDomain, match=why):
        PeriodicSpline(x, y)


def test_a_derivative_beyond_the_third_is_refused():
    s = PeriodicSpline([0.0, 1.0, 2.0, 3.0], [[0.0], [1.0], [-1.0], [0.0]])
    with pytest.raises(OutOfDomain, match="order"):
        s.point(0.5, 4)
    with pytest.raises(OutOfDomain, match="order"):
        s.at(np.array([0.5]), 4)
