"""Brent's bounded search of graphmech.minimum: the same floats as scipy's
minimize_scalar(method="bounded") (the same algorithm), and the refusals; and that the scenes whose
exact solution needs no solver of scipy's do not load it (issue 23: cold starts)."""
from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import OutOfDomain
from graphmech.minimum import fminbound
from tests.conftest import SCENES


def _wavy(c: tuple[float, float, float, float]):
    return lambda x: c[0] + c[1] * x + c[2] * x * x + c[3] * x ** 4 + math.sin(5.0 * x)


@settings(max_examples=150, deadline=None)
@given(st.tuples(*[st.floats(-3.0, 3.0)] * 4), st.floats(-3.0, 2.9), st.floats(1e-3, 3.0),
       st.sampled_from([1e-5, 1e-12, 1e-14]), st.sampled_from([500, 7]))
def test_every_minimum_is_scipys_to_the_last_bit(c, lo, width, xatol, maxiter):
    from scipy.optimize import minimize_scalar

    f = _wavy(c)
    want = minimize_scalar(f, bounds=(lo, lo + width), method="bounded", options={"xatol": xatol, "maxiter": maxiter})
    assert fminbound(f, lo, lo + width, xatol=xatol, maxiter=maxiter) == (float(want.x), float(want.fun))


@pytest.mark.parametrize(("f", "lo", "hi", "at"), [
    (lambda x: (x - 1.0) ** 2, 0.0, 3.0, 1.0),
    (math.cos, 2.0, 4.0, math.pi),
    (lambda x: x, 0.0, 1.0, 0.0),  # the least value at an end
    (lambda x: 7.0, 0.0, 1.0, None),  # a constant: any point
])
def test_known_minima(f, lo, hi, at):
    x, fx = fminbound(f, lo, hi, xatol=1e-12)
    assert lo <= x <= hi and fx == f(x)
    if at is not None:
        assert x == pytest.approx(at, abs=1e-7)


@pytest.mark.parametrize("f, lo, hi", [(lambda x: np.float64(abs(x - 1.0)), 0.0, 3.0),
                                       (lambda x: np.float64((x - 0.999) ** 2), 0.0, 1.0)])
def test_numpy_scalar_values_are_scipys_too(f, lo, hi):
    """A function returning numpy scalars (the steps then are numpy scalars too): no TypeError on
    the sign of a numpy bool difference near a bound, and scipy's floats (a sweep found it)."""
    from scipy.optimize import minimize_scalar

    want = minimize_scalar(f, bounds=(lo, hi), method="bounded")
    assert fminbound(f, lo, hi) == (want.x, want.fun)


def test_a_point_interval_is_that_point():
    assert fminbound(lambda x: x * x, 2.0, 2.0) == (2.0, 4.0)


@pytest.mark.parametrize("bounds", [(1.0, 0.0), (0.0, math.inf), (math.nan, 1.0)])
def test_what_is_refused(bounds):
    with pytest.raises(OutOfDomain, match="bounds"):
        fminbound(math.cos, *bounds)


@pytest.mark.parametrize(("scene", "unloaded"), [
    ("cam.given_profile_points", ("scipy",)),  # the spline, its roots and extremes: graphmech's own
    ("cam.offset_roller_translating-pos", ("scipy.optimize",)),  # a convex corner's vertex (Newton)
    ("cam.eccentric_disc_oscillating", ("scipy.optimize",)),
    ("force.sixbar_kinetostatic-friction", ("scipy.optimize",)),  # the friction equations (Newton)
    ("fly.brake_time", ("scipy.integrate", "scipy.optimize")),  # the stopping time in closed form
])
@pytest.mark.parametrize("command", ["check", "render"])
def test_what_needs_no_solver_of_scipys_does_not_load_it(scene, unloaded, command, tmp_path):
    argv = [command, str(SCENES / f"{scene}.toml")] + (["-o", str(tmp_path / "f.svg")] if command == "render" else [])
    code = (f"import sys; from graphmech.cli import main; sys.argv = ['graphmech', *{argv!r}]; main(); "
            f"print('LOADED', *sorted(m for m in {unloaded!r} if m in sys.modules))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert run.returncode in (0, 1), run.stderr  # 1: a value out of tolerance is still a check
    assert run.stdout.splitlines()[-1] == "LOADED"
