"""The profile shift constructed (N₁ on the generating rack's line of action; the thickness on the
working pitch circles) against the closed forms of exact/profile_shift."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.exact import profile_shift as exs
from graphmech.mechanisms.gear import ToothSystem
from graphmech.methods import profile_shift as ps

S20 = ToothSystem(m=0.01, alpha=math.radians(20.0))


@pytest.mark.parametrize("z", [5, 12, 17, 40, 200])
def test_the_undercut_limit_drawn(z):
    lim = ps.undercut_limit(S20, z)
    assert lim.x_min == pytest.approx(exs.x_min_exact(S20, z), rel=1e-12, abs=1e-14)
    assert lim.z_min == pytest.approx(exs.z_min_exact(S20), rel=1e-12)
    # N₁ is on the base circle, and P on the reference circle straight above O₁
    assert math.hypot(*lim.N1) == pytest.approx(S20.m * z / 2 * math.cos(S20.alpha), rel=1e-14)


def test_the_shifts_for_the_books_a130():
    c = ps.shift_for_centre_distance(S20, 12, 12, 0.13)
    assert c.x_sum == pytest.approx(1.250498184491544, rel=1e-12)
    assert math.degrees(c.alpha_w) == pytest.approx(29.841118724279806, rel=1e-13)
    assert c.k[0] == pytest.approx(c.k[1], rel=1e-12)   # one growth per unit shift for both gears


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(8, 120), z2=st.integers(8, 300), dy=st.floats(-0.03, 0.08))
def test_shift_sum_agrees_with_inv_for_any_pair(z1, z2, dy):
    a = 0.005 * (z1 + z2)
    a_w = a * (1.0 + dy)
    if a * math.cos(S20.alpha) / a_w >= 1.0:
        return
    c = ps.shift_for_centre_distance(S20, z1, z2, a_w)
    e = exs.shifts_for_centre_distance(S20, z1, z2, a_w)
    assert c.x_sum == pytest.approx(e.x_sum, rel=1e-9, abs=1e-11)


def test_the_repairs_shift_from_the_thickness():
    s = ToothSystem(0.005, math.radians(20.0))
    assert ps.shift_for_thickness(s, 118, -0.00075) == pytest.approx(exs.repair_shift(s, 0.00075), rel=1e-12)
