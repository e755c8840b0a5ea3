"""What both constructions by chords share: the checked divisions and the read-only copies."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.errors import OutOfDomain
from graphmech.methods.chords import divisions, frozen_array


def test_frozen_array_is_a_read_only_float_copy() -> None:
    src = np.array([1, 2, 3])
    a = frozen_array(src)
    assert a.dtype == float and a.tolist() == [1.0, 2.0, 3.0]
    with pytest.raises(ValueError, match="read-only"):  # numpy's own refusal
        a[0] = 9.0
    src[0] = 7  # the caller's array is not the copy
    assert a[0] == 1.0
    f = np.array([0.5, 1.5])
    assert not np.shares_memory(frozen_array(f), f) and f.flags.writeable


def test_divisions_come_back_as_floats() -> None:
    x, y, H = divisions([0, 10, 25], (0, -3, 4), 40)
    assert x.dtype == y.dtype == float
    assert x.tolist() == [0.0, 10.0, 25.0] and y.tolist() == [0.0, -3.0, 4.0]
    assert H == 40.0 and type(H) is float


@pytest.mark.parametrize("x, y, message", [
    ([[0.0, 1.0], [2.0, 3.0]], [[0.0, 1.0], [2.0, 3.0]], r"got shapes \(2, 2\) and \(2, 2\)"),  # not 1-D
    ([0.0, 1.0, 2.0], [0.0, 1.0], r"got shapes \(3,\) and \(2,\)"),  # lengths differ
    ([], [], r"got shapes \(0,\) and \(0,\)"),  # nothing
    ([math.inf, 1.0], [0.0, 0.0], "must be finite"),  # an abscissa not finite
    ([0.0, -1.0], [0.0, 0.0], "strictly increasing"),  # decreasing
])
def test_bad_divisions_are_refused(x, y, message) -> None:
    with pytest.raises(OutOfDomain, match=message):
        divisions(x, y, 10.0)


@pytest.mark.parametrize("H", [math.inf, math.nan, -0.0, -1e-300])
def test_the_pole_distance_must_be_positive_and_finite(H: float) -> None:
    with pytest.raises(ValueError, match="pole distance"):
        divisions([0.0, 1.0], [0.0, 1.0], H)


def test_the_least_pole_distance_and_a_tiny_interval_pass() -> None:
    x, _, H = divisions([0.0, 5e-324], [1.0, 1.0], 5e-324)
    assert H > 0.0 and x[1] > x[0]
