"""The Geneva wheel by construction against its closed forms (graphmech.exact.geneva)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import OutOfDomain
from graphmech.exact import geneva as ex
from graphmech.methods.geneva import layout, polygons


@pytest.mark.parametrize("z", [3, 4, 5, 6, 8, 12])
def test_the_sizes_laid_out_are_the_closed_forms(z):
    mu = 0.002
    lay = layout(z, 0.3, 0.01, 0.005, mu)
    assert lay.R_mm * mu == pytest.approx(ex.crank_radius(z, 0.3), rel=1e-13)
    assert lay.S_mm * mu == pytest.approx(ex.wheel_radius(z, 0.3), rel=1e-13)
    assert lay.h_mm * mu == pytest.approx(ex.slot_depth(z, 0.3, 0.01), rel=1e-13)
    assert lay.r_lock_mm * mu == pytest.approx(ex.locking_radius(z, 0.3, 0.01, 0.005), rel=1e-12)
    assert lay.half_angle == pytest.approx(ex.engaged_half_angle(z), rel=1e-14)


@pytest.mark.parametrize("z", [3, 6, 8])
def test_the_pin_polygons_give_the_closed_form_omega_and_epsilon(z):
    mu_l, w1 = 0.002, 2 * math.pi / 45
    lay = layout(z, 0.3, 0.01, 0.005, mu_l)
    half = ex.engaged_half_angle(z)
    for k in range(-10, 11):
        phi = half * k / 10
        pp = polygons(lay, phi, w1, mu_l, 1e-4, 1e-5)
        # the wheel turns against the dial: the construction's signed ω₂ is the book's with a minus
        assert -pp.omega2 == pytest.approx(ex.wheel_omega(z, phi, w1), rel=1e-11, abs=1e-15)
        assert -pp.epsilon2 == pytest.approx(ex.wheel_epsilon(z, phi, w1), rel=1e-11, abs=1e-15)
        assert pp.v_slide == pytest.approx(ex.slide_velocity(z, 0.3, phi, w1), rel=1e-11, abs=1e-15)
        assert pp.a_k == pytest.approx(ex.coriolis(z, 0.3, phi, w1), rel=1e-10, abs=1e-15)


def test_the_six_slot_wheel_at_minus_20_degrees():
    """Hand values: ω₂ = ω₁λ(cos φ − λ)/(1 − 2λ cos φ + λ²) with λ = 1/2, ω₁ = 2π/45 rad/s."""
    w1, c = 2 * math.pi / 45, math.cos(math.radians(-20))
    pp = polygons(layout(6, 0.3, 0.025, 0.0125, 0.005), math.radians(-20), w1, 0.005, 5e-4, 2e-4)
    assert -pp.omega2 == pytest.approx(w1 * 0.5 * (c - 0.5) / (1.25 - c), rel=1e-12)
    assert -pp.omega2 == pytest.approx(0.0989223517516462, rel=1e-12)
    assert -pp.epsilon2 == pytest.approx(0.025967698182211525, rel=1e-12)


def test_too_few_slots_and_a_pin_out_of_its_slot_are_refused():
    with pytest.raises(OutOfDomain, match="at least 3 slots"):
        layout(2, 0.3, 0.01, 0.005, 0.002)
    lay = layout(6, 0.3, 0.01, 0.005, 0.002)
    with pytest.raises(OutOfDomain, match="out of the slot"):
        polygons(lay, math.radians(-61), 1.0, 0.002, 1e-3, 1e-3)


@settings(max_examples=80, deadline=None)
@given(z=st.integers(3, 40), L=st.floats(0.01, 10.0), share=st.floats(-1.0, 1.0), w1=st.floats(0.1, 100.0))
def test_any_wheel_at_any_engaged_angle_agrees_with_the_closed_forms(z, L, share, w1):
    mu_l = L / 100  # the wheel about 100 mm across
    lay = layout(z, L, 0.01 * L, 0.01 * L, mu_l)
    phi = share * ex.engaged_half_angle(z)
    R = ex.crank_radius(z, L)
    pp = polygons(lay, phi, w1, mu_l, w1 * R / 50, w1 * w1 * R / 50)
    assert -pp.omega2 == pytest.approx(ex.wheel_omega(z, phi, w1), rel=1e-9, abs=1e-12 * w1)
    assert -pp.epsilon2 == pytest.approx(ex.wheel_epsilon(z, phi, w1), rel=1e-9, abs=1e-12 * w1 * w1)
