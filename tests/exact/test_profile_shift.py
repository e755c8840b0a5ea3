"""The book's profile-shift design in closed form, against values worked by hand and identities."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.exact import gear as ex
from graphmech.exact import profile_shift as ps
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem

S20 = ToothSystem(m=0.01, alpha=math.radians(20.0))


@pytest.mark.parametrize("alpha, ha, want", [(20.0, 1.0, 17), (20.0, 0.8, 14), (15.0, 1.0, 30), (25.0, 1.0, 11)])
def test_the_books_z_min_is_the_exact_one_rounded(alpha, ha, want):
    s = ToothSystem(1.0, math.radians(alpha), ha)
    assert ps.z_min_book(s) == want
    assert ps.z_min_exact(s) == pytest.approx(2.0 * ha / math.sin(math.radians(alpha)) ** 2, rel=1e-15)


def test_x_min_by_the_rule_and_the_exact_limit():
    assert ps.x_min_book(S20, 12) == pytest.approx(5.0 / 17.0, rel=1e-15)
    assert ps.x_min_book(S20, 17) == 0.0 and ps.x_min_book(S20, 34) == pytest.approx(-1.0)
    # the exact limit is where the undercut of exact/gear begins
    for z in (5, 12, 17, 30):
        x = ps.x_min_exact(S20, z)
        assert not ex.undercut(S20, SpurGear(z, x)).undercut
        assert ex.undercut(S20, SpurGear(z, x - 1e-9)).undercut


def test_the_shifts_for_a_centre_distance_close_the_backlash():
    d = ps.shifts_for_centre_distance(S20, 12, 12, 0.13)
    assert (d.a, d.y) == (pytest.approx(0.12), pytest.approx(1.0))
    assert d.x_sum == pytest.approx(1.250498184491544, rel=1e-13)   # the bank's exact value
    assert d.x1 == d.x2 == pytest.approx(d.x_sum / 2)
    assert d.delta_y == pytest.approx(0.25049818449154393, rel=1e-12)
    # meshed with those shifts the pair has no backlash at a′ = 130 mm
    mv = ex.meshing(GearSet(S20, (SpurGear(12, d.x1), SpurGear(12, d.x2)), "external", 0.13))
    assert mv.backlash == pytest.approx(0.0, abs=1e-15)
    uneven = ps.shifts_for_centre_distance(S20, 12, 12, 0.13, x1=0.8)
    assert (uneven.x1, uneven.x2) == (0.8, pytest.approx(d.x_sum - 0.8))


def test_on_the_standard_distance_the_shifts_are_zero():
    # 000 齿轮 7: pair 1, 2 (z = 20, 48, m = 2 mm) on a′ = a = 68 mm is standard, not "equal and opposite"
    d = ps.shifts_for_centre_distance(ToothSystem(0.002, math.radians(20.0)), 20, 48, 0.068)
    assert (d.x_sum, d.x1, d.x2, d.delta_y) == (0.0, 0.0, 0.0, 0.0)
    assert ps.drive_kind(d.x1, d.x2) == "standard"


def test_below_the_standard_distance_the_shifts_are_negative():
    d = ps.shifts_for_centre_distance(S20, 30, 40, 0.345)
    assert d.x_sum < 0 and d.y == pytest.approx(-0.5) and d.delta_y > 0
    assert ps.drive_kind(d.x1, d.x2) == "negative"
    with pytest.raises(NoSolution, match="base circles would cross"):
        ps.shifts_for_centre_distance(S20, 30, 40, 0.3)
    with pytest.raises(OutOfDomain):
        ps.shifts_for_centre_distance(S20, 30, 40, -1.0)


def test_tip_shortening_and_repair():
    assert ps.tip_shortening(S20, 12, 12, 1.0, 0.128) == pytest.approx(0.2)
    assert ps.tip_shortening(S20, 12, 12, 1.0, 0.135) == 0.0        # a′ past a + (x₁+x₂)m: nothing to cut
    x2 = ps.repair_shift(ToothSystem(0.005, math.radians(20.0)), 0.00075)
    assert x2 == pytest.approx(-0.2060608064590967, rel=1e-13)
    t = ex.tooth(ToothSystem(0.005, math.radians(20.0)), SpurGear(118, x2))
    assert t.s == pytest.approx(math.pi * 0.005 / 2 - 0.00075, rel=1e-14)
    with pytest.raises(OutOfDomain):
        ps.repair_shift(S20, 0.0)


def test_no_addendum_no_least_shift():
    with pytest.raises(NotApplicable):
        ps.z_min_book(ToothSystem(0.01, math.radians(20.0), 0.0))


@pytest.mark.parametrize("x1, x2, kind", [(0.0, 0.0, "standard"), (0.3, -0.3, "equal and opposite"),
                                          (0.5, 0.0, "positive"), (-0.2, -0.1, "negative"),
                                          (0.1 + 0.2, -0.3, "equal and opposite")])
def test_the_kind_of_drive(x1, x2, kind):
    assert ps.drive_kind(x1, x2) == kind
