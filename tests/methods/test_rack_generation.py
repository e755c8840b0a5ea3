"""The tooth the rack cutter's positions leave: it converges to the exact generated profile as
1/N² (the scallops), keeps the reference thickness where a position rolls through the pitch
point, and shows the undercut; the rolling circle is constructed from the speeds."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.exact import gear as ex
from graphmech.exact import rack_generation as erg
from graphmech.mechanisms.gear import SpurGear, ToothSystem
from graphmech.methods import rack_generation as rg

M4 = ToothSystem(0.004, math.radians(20.0))


def error(gear: SpurGear, n: int) -> float:
    g = rg.generate(M4, gear, n)
    return float(erg.generated_profile(M4, gear).distance(np.asarray(g.profile)).max()) / M4.m


@pytest.mark.parametrize("gear", [SpurGear(15), SpurGear(30, 0.3), SpurGear(18, -1.5)])
def test_the_envelope_converges_to_the_exact_profile_as_one_over_n_squared(gear):
    e8, e16, e32 = error(gear, 8), error(gear, 16), error(gear, 32)
    assert e8 > e16 > e32 > 0.0
    for a, b in ((e8, e16), (e16, e32)):
        assert 1.5 < math.log2(a / b) < 2.6, (a, b)
    assert e32 < 3e-3


def test_a_standard_tooth_keeps_its_reference_thickness():
    # the position at φ = 0 rolls through the pitch point: it cuts the flank exactly on the reference circle
    g = rg.generate(M4, SpurGear(15), 12)
    t = ex.tooth(M4, SpurGear(15))
    assert rg.thickness(g, g.r) == pytest.approx(t.s, rel=1e-9)
    sa = rg.thickness(g, g.ra)
    assert sa is not None and 0.0 < sa - t.sa < 1e-3 * t.sa  # scallops leave the tip a little thicker


def test_half_a_step_later_the_scallops_fall_elsewhere():
    a = rg.generate(M4, SpurGear(15, 0.2), 12)
    b = rg.generate(M4, SpurGear(15, 0.2), 12, stagger=0.5)
    assert a.phis[0] != b.phis[0] and len(a.phis) == len(b.phis)
    assert rg.thickness(a, a.r) != rg.thickness(b, b.r)


def test_the_undercut_tooth_is_narrower_at_its_root_than_its_involute():
    gear = SpurGear(18, -1.5)
    g = rg.generate(M4, gear, 64)
    prof = erg.generated_profile(M4, gear)
    assert prof.undercut
    rho = 0.5 * (g.rf + g.ra)
    got = rg.thickness(g, rho)
    assert got is not None and got == pytest.approx(prof.thickness(rho), rel=1e-3)
    assert got < ex.at_radius(M4, gear, max(rho, ex.tooth(M4, gear).db / 2.0)).s_k


def test_the_profile_runs_from_tooth_axis_to_tooth_axis():
    g = rg.generate(M4, SpurGear(20), 8)
    p = np.asarray(g.profile)
    th = np.arctan2(p[:, 1], p[:, 0])
    assert th[0] == pytest.approx(math.pi / 2 - math.pi / 20, abs=1e-12)
    assert th[-1] == pytest.approx(math.pi / 2 + math.pi / 20, abs=1e-12)
    assert g.rf <= np.hypot(*p.T).min() < g.rf * (1.0 + 1e-4)  # the root circle, scalloped between vertices
    teeth = g.teeth(range(-1, 2))
    assert len(teeth) == 3 * len(p) - 2


def test_the_rolling_circle_from_the_speeds():
    assert rg.rolling_radius(0.002, 0.7958 * math.pi / 30.0) == pytest.approx(0.002 / (0.7958 * math.pi / 30.0),
                                                                               rel=1e-14)
    with pytest.raises(OutOfDomain):
        rg.rolling_radius(0.002, 0.0)


def test_the_cutter_outline():
    pts = np.asarray(rg.cutter_outline(M4, SpurGear(15)))
    assert pts[:, 1].min() == pytest.approx(-(1.25) * M4.m, rel=1e-12)  # h*a + c* below the datum line
    assert pts[:, 0].min() == pytest.approx(-1.5 * math.pi * M4.m)


def test_refusals():
    with pytest.raises(NotApplicable):
        rg.generate(M4, SpurGear(40, internal=True))
    with pytest.raises(OutOfDomain):
        rg.generate(M4, SpurGear(20), 1)


@pytest.mark.parametrize("v, omega", [(1e-300, 1e-298), (1e-12, 3e-11), (1e300, 1e301), (5.0, 1e12)])
def test_the_rolling_radius_at_extreme_speeds_is_v_over_omega(v, omega):
    """A blank turning at 1e-298 rad/s or 1e12 rad/s: the velocities are drawn at a round scale,
    so the ω·y line still crosses the cutter's v (unscaled it ran parallel to it)."""
    assert rg.rolling_radius(v, omega) == pytest.approx(v / omega, rel=1e-12)
