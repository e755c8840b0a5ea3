"""The Geneva wheel's and the differential screw's closed forms against the bank and by finite differences."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import OutOfDomain
from graphmech.exact import geneva as ex

# the bank's mech.geneva_six_slot (copied, the tests never read /work/shared)
Z, L, R_PIN, B, T_REST = 6, 0.300, 0.025, 0.0125, 30.0
BANK = {"R_mm": 149.99999999999997, "S_mm": 259.8076211353316, "h_mm": 134.80762113533157,
        "r_lock_mm": 112.49999999999997, "k": 0.3333333333333333, "T_s": 44.99999999999999,
        "n_r_min": 1.3333333333333335}


def test_the_six_slot_geneva_matches_the_bank():
    got = {"R_mm": ex.crank_radius(Z, L) * 1000, "S_mm": ex.wheel_radius(Z, L) * 1000,
           "h_mm": ex.slot_depth(Z, L, R_PIN) * 1000, "r_lock_mm": ex.locking_radius(Z, L, R_PIN, B) * 1000,
           "k": ex.motion_coefficient(Z), "T_s": ex.period_from_rest(Z, T_REST),
           "n_r_min": 60 / ex.period_from_rest(Z, T_REST)}
    for k, want in BANK.items():
        assert got[k] == pytest.approx(want, rel=1e-12), k
    assert round(got["h_mm"]) == 135  # the book rounds 134.81 to 135


@pytest.mark.parametrize("z", [3, 4, 6, 8, 12])
def test_epsilon_is_the_derivative_of_omega(z):
    w1, h = 2.0, 1e-5
    half = ex.engaged_half_angle(z)
    for phi in (-0.9 * half, -0.3 * half, 0.1, 0.7 * half):
        fd = (ex.wheel_omega(z, phi + h, w1) - ex.wheel_omega(z, phi - h, w1)) / (2 * h) * w1
        assert ex.wheel_epsilon(z, phi, w1) == pytest.approx(fd, rel=1e-7, abs=1e-9)


@pytest.mark.parametrize("z", [3, 6, 10])
def test_the_pin_enters_tangentially_and_drives_fastest_on_the_line_of_centres(z):
    half = ex.engaged_half_angle(z)
    assert ex.wheel_omega(z, half, 3.0) == pytest.approx(0.0, abs=1e-14)
    lam = math.sin(math.pi / z)
    assert ex.wheel_omega(z, 0.0, 3.0) == pytest.approx(ex.wheel_omega_max(z, 3.0), rel=1e-15)
    assert ex.wheel_omega_max(z, 3.0) == pytest.approx(3.0 * lam / (1 - lam), rel=1e-15)
    # at entry the pin slides along the slot at the full ω₁R, and ε₂ jumps from 0 to ω₁² tan(π/z)
    assert ex.slide_velocity(z, 1.0, -half, 3.0) == pytest.approx(3.0 * lam, rel=1e-12)
    assert ex.wheel_epsilon(z, -half, 3.0) == pytest.approx(9.0 * math.tan(math.pi / z), rel=1e-12)


def test_a_pin_out_of_the_slot_is_refused():
    with pytest.raises(OutOfDomain, match="out of the slot"):
        ex.wheel_omega(6, math.radians(61), 1.0)


def test_the_differential_screw_has_two_branches():
    (pB, same), alt = ex.screw_leads(2.8, 0.2)
    assert (pB, same) == (pytest.approx(3.0, abs=1e-12), True)  # the book's: 3 mm right-hand
    assert alt == (pytest.approx(2.5999999999999996, abs=1e-12), True)
    assert ex.screw_travel(2.8, 3.0, True) == pytest.approx(-0.2, abs=1e-12)
    assert ex.screw_travel(2.8, 3.0, False) == pytest.approx(5.8, abs=1e-12)
    assert ex.screw_leads(2.0, 2.0)[1] is None  # p_B = 0: one branch
