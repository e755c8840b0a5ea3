"""graphmech.exact.balancing: the correction masses from the equations of balance, in closed form."""
from __future__ import annotations

import cmath
import math

import pytest

from graphmech.exact.balancing import Unbalance, dynamic_correction, residuals, static_correction


def test_an_unbalance_is_m_r_at_its_angle():
    u = Unbalance(2.0, 0.05, math.radians(120.0), 0.3)
    assert abs(u.vector()) == pytest.approx(0.1, rel=1e-15)
    assert math.degrees(cmath.phase(u.vector())) == pytest.approx(120.0, rel=1e-14)
    assert Unbalance(1.0, 0.1, 0.0).z == 0.0  # one plane unless told


def test_static_correction_is_minus_the_sum_and_nothing_for_a_balanced_disc():
    # 2 kg at 50 mm and 1 kg at 100 mm opposite: already balanced
    assert abs(static_correction([Unbalance(2.0, 0.05, 0.3), Unbalance(1.0, 0.1, 0.3 + math.pi)])) < 1e-16
    # three equal masses at 0°, 90°, 180°: only the 90° one is left, the correction points at 270°
    w = static_correction([Unbalance(1.0, 0.1, a) for a in (0.0, math.pi / 2, math.pi)])
    assert abs(w) == pytest.approx(0.1, rel=1e-14)
    assert math.degrees(cmath.phase(w)) == pytest.approx(-90.0, rel=1e-12)
    assert static_correction([]) == 0j


def test_a_mass_between_the_planes_shares_by_the_lever_rule():
    # 1 kg·0.1 m at z = 0.25 between planes at 0 and 1: 3/4 in plane I, 1/4 in plane II, opposite
    W_I, W_II = dynamic_correction([Unbalance(1.0, 0.1, math.radians(30.0), 0.25)], 0.0, 1.0)
    assert abs(W_I) == pytest.approx(0.075, rel=1e-14) and abs(W_II) == pytest.approx(0.025, rel=1e-14)
    assert math.degrees(cmath.phase(W_I)) == pytest.approx(-150.0, rel=1e-12)
    # a mass in plane I is balanced there alone
    W_I, W_II = dynamic_correction([Unbalance(1.0, 0.1, 0.0, 0.2)], 0.2, 0.7)
    assert W_I == pytest.approx(-0.1) and W_II == 0j


def test_a_mass_outside_the_planes_gives_a_reversed_share():
    # z = 0.15 beyond plane II at 0.1: plane I gets +W·0.05/0.1 (along the mass), plane II −W·0.15/0.1
    W_I, W_II = dynamic_correction([Unbalance(1.0, 0.1, 0.0, 0.15)], 0.0, 0.1)
    assert W_I.real == pytest.approx(0.05, rel=1e-13) and W_II.real == pytest.approx(-0.15, rel=1e-13)
    assert abs(W_I.imag) < 1e-17 and abs(W_II.imag) < 1e-17


def test_a_pure_couple_needs_no_static_correction_but_two_dynamic_ones():
    # equal masses opposite each other at z = 0.1 and 0.3: Σ m·r = 0, but they rock the shaft
    couple = [Unbalance(1.0, 0.1, 0.0, 0.1), Unbalance(1.0, 0.1, math.pi, 0.3)]
    assert abs(static_correction(couple)) < 1e-16
    force, moment = residuals(couple, [])
    assert force < 1e-16 and moment == pytest.approx(0.02, rel=1e-12)  # 0.1 kg·m × 0.2 m
    W_I, W_II = dynamic_correction(couple, 0.0, 0.4)
    assert W_I == pytest.approx(-W_II, abs=1e-16) and abs(W_I) == pytest.approx(0.05, rel=1e-12)
    assert max(residuals(couple, [(W_I, 0.0), (W_II, 0.4)])) < 1e-16


def test_coinciding_planes_are_refused():
    with pytest.raises(ValueError, match="the correction planes coincide"):
        dynamic_correction([Unbalance(1.0, 0.1, 0.0, 0.1)], 0.2, 0.2)


def test_once_balanced_the_moment_is_the_same_about_any_axial_point():
    rotor = [Unbalance(3.0, 0.02, 0.4, 0.05), Unbalance(1.5, 0.08, 2.5, 0.35), Unbalance(0.7, 0.1, -1.0, 0.6)]
    W = dynamic_correction(rotor, 0.1, 0.5)
    corrections = list(zip(W, (0.1, 0.5)))
    for about in (0.0, 0.1, 0.5, 3.0):
        force, moment = residuals(rotor, corrections, about)
        assert force < 1e-16 and moment < 1e-15
    # unbalanced, the moment depends on where it is taken: the force's moment arm
    f0, m0 = residuals(rotor, [], 0.0)
    f1, m1 = residuals(rotor, [], 1.0)
    assert f0 == f1 and m0 != pytest.approx(m1)
