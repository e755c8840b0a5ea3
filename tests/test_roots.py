"""graphmech.roots: Brent's method (the same floats as scipy.optimize.brentq, the same algorithm),
the refusals, that a cam check no longer loads scipy.optimize; Newton's method to the last bit, and
its best point where it cycles."""
from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.roots import RTOL, brentq, newton
from tests.conftest import SCENES


def _cubic_with_a_wave(c: tuple[float, float, float, float]):
    return lambda x: c[0] + c[1] * x + c[2] * x * x + c[3] * x ** 3 + math.sin(5.0 * x)


@settings(max_examples=150, deadline=None)
@given(st.tuples(*[st.floats(-3.0, 3.0)] * 4), st.sampled_from([2e-12, 1e-15, 1e-6]))
def test_every_root_is_scipys_to_the_last_bit(c, xtol):
    from scipy.optimize import brentq as scipy_brentq

    f = _cubic_with_a_wave(c)
    xs = [k / 25.0 - 3.0 for k in range(151)]
    for a, b in zip(xs, xs[1:]):
        if (f(a) > 0.0) != (f(b) > 0.0):
            assert brentq(f, a, b, xtol=xtol) == scipy_brentq(f, a, b, xtol=xtol, rtol=RTOL)


@pytest.mark.parametrize(("f", "a", "b", "root", "xtol"), [
    (lambda x: x * x - 2.0, 0.0, 2.0, math.sqrt(2.0), 1e-15),
    (math.sin, 3.0, 4.0, math.pi, 1e-15),
    (lambda x: math.atan(x - 0.3) * 1e6, -5.0, 5.0, 0.3, 1e-15),
])
def test_known_roots(f, a, b, root, xtol):
    assert brentq(f, a, b, xtol=xtol) == pytest.approx(root, abs=4 * xtol)


def test_an_end_that_is_a_root_is_returned_as_it_is():
    assert brentq(lambda x: x, 0.0, 1.0) == 0.0 and brentq(lambda x: x - 1.0, 0.0, 1.0) == 1.0


def test_what_is_refused():
    with pytest.raises(OutOfDomain, match="differ in sign"):
        brentq(math.cos, 0.0, 1.0)
    with pytest.raises(OutOfDomain, match="tolerances"):
        brentq(math.sin, 3.0, 4.0, rtol=1e-17)
    with pytest.raises(NoSolution, match="did not converge"):  # a pole, not a root: tan x − x on [4, 4.6]
        brentq(lambda x: math.tan(x) - x, 4.0, 4.6, maxiter=5)


def test_a_cam_check_does_not_load_scipy_optimize():
    scene = SCENES / "cam.law_maxima-sine.toml"
    code = ("import sys; from graphmech.cli import main; sys.argv = ['graphmech', 'check', %r]; main(); "
            "assert 'scipy.optimize' not in sys.modules, 'scipy.optimize loaded'" % str(scene))
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert "a_max_at" in run.stdout  # its extremes were found (by brentq)


def test_newton_reaches_the_root_to_the_last_bit_of_a_system():
    # the unit circle and the line y = x: (√½, √½)
    def f(z):
        return np.array([z[0] ** 2 + z[1] ** 2 - 1.0, z[0] - z[1]])

    z, calls = newton(f, lambda z: np.array([[2.0 * z[0], 2.0 * z[1]], [1.0, -1.0]]), np.array([2.0, 0.5]))
    assert abs(z[0] - math.sqrt(0.5)) <= 2.3e-16 and z[0] == z[1]
    assert 5 <= calls <= 12


def test_where_newton_cycles_it_returns_its_best_point_after_maxiter():
    # x³ − 2x + 2 from 0: the steps go 0 → 1 → 0 → … for ever; the best point is x = 1 (f = 1)
    z, calls = newton(lambda z: z ** 3 - 2.0 * z + 2.0, lambda z: np.array([[3.0 * z[0] ** 2 - 2.0]]),
                      np.array([0.0]), maxiter=20)
    assert float(z[0]) == 1.0 and calls == 21
