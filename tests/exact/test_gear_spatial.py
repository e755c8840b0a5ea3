"""Helical, bevel and worm gears in closed form (graphmech/exact/gear_spatial.py): the bank's values,
β = 0 as a spur pair, Σ ≠ 90°, many starts, and what is refused."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.exact import gear as spur
from graphmech.exact.gear_spatial import bevel, helical, helix_angle, worm
from graphmech.mechanisms.gear import GearSet, SpatialPair, SpurGear, ToothSystem

DEG = math.radians


def pair(kind, z=(20, 40), m=0.008, a=None, c=0.25, **sp):
    return GearSet(ToothSystem(m, DEG(20), 1.0, c), tuple(SpurGear(v) for v in z), kind, a, SpatialPair(**sp))


def test_the_helical_bank_problem(problems):
    ex = problems["gear.helical_20_40_mn8"]["exact"]
    h = helical(pair("helical", a=0.25, beta=DEG(15), face_width=0.03))
    got = {"a_initial_mm": h.a_initial * 1e3, "beta_deg": math.degrees(h.beta), "alpha_t_deg": math.degrees(h.alpha_t),
           "d1_mm": h.d[0] * 1e3, "da2_mm": h.da[1] * 1e3, "df1_mm": h.df[0] * 1e3, "db2_mm": h.db[1] * 1e3,
           "alpha_at1_deg": math.degrees(h.alpha_at[0]), "alpha_at2_deg": math.degrees(h.alpha_at[1]),
           "zv1": h.zv[0], "zv2": h.zv[1], "sn_mm": h.sn * 1e3, "st_mm": h.st * 1e3, "pn_mm": h.pn * 1e3,
           "pt_mm": h.pt * 1e3, "eps_alpha": h.eps_alpha, "eps_beta": h.eps_beta, "eps_gamma": h.eps_gamma}
    for key, v in got.items():
        assert v == pytest.approx(ex[key], rel=1e-12), key
    assert h.a == pytest.approx(0.25, rel=1e-15)


def test_beta_zero_is_the_spur_pair():
    h = helical(pair("helical", beta=0.0, face_width=0.03))
    s = spur.meshing(GearSet(ToothSystem(0.008, DEG(20)), (SpurGear(20), SpurGear(40)), "external"))
    assert h.eps_alpha == pytest.approx(s.eps_alpha, rel=1e-14)
    assert (h.zv, h.mt, h.eps_beta, h.pz, h.beta_b) == ((20.0, 40.0), 0.008, 0.0, None, 0.0)


def test_beta_near_45():
    h = helical(pair("helical", beta=DEG(44.9), face_width=0.03))
    assert h.zv[0] == pytest.approx(20 / math.cos(DEG(44.9)) ** 3, rel=1e-14) and h.zv[0] > 56.0
    assert h.mt == pytest.approx(0.008 / math.cos(DEG(44.9)), rel=1e-15)
    assert h.eps_beta == pytest.approx(0.03 * math.sin(DEG(44.9)) / (math.pi * 0.008), rel=1e-14)


@pytest.mark.parametrize("beta, a, why", [(DEG(45), None, "outside 0 ≤ β < 45°"), (-0.1, None, "outside"),
                                          (DEG(10), 0.2, "is less than"), (DEG(10), 0.4, "needs β")])
def test_helix_angles_refused(beta, a, why):
    with pytest.raises(OutOfDomain, match=why):
        helix_angle(pair("helical", a=a, beta=beta))


@pytest.mark.parametrize("sigma", [60.0, 90.0, 110.0])
def test_bevel_for_any_shaft_angle(sigma):
    b = bevel(pair("bevel", m=0.004, c=0.2, shaft_angle=DEG(sigma)))
    assert sum(b.delta) == pytest.approx(DEG(sigma), rel=1e-15)
    # both pitch cones share the cone distance: d₁/(2 sin δ₁) = d₂/(2 sin δ₂)
    assert b.R == pytest.approx(b.d[1] / (2 * math.sin(b.delta[1])), rel=1e-14)
    assert b.zv[1] == pytest.approx(40 / math.cos(b.delta[1]), rel=1e-15)
    if sigma == 90.0:
        assert math.tan(b.delta[0]) == pytest.approx(0.5, rel=1e-15)


def test_bevel_crown_refused():
    # δ₂ = 90° at cos Σ = −z₁/z₂: Σ = 120° with z = 20, 40; beyond it an internal bevel gear
    with pytest.raises(NotApplicable, match="crown"):
        bevel(pair("bevel", shaft_angle=DEG(125)))


def test_the_worm_bank_problem(problems):
    ex = problems["gear.worm_i20.5_m5"]["exact"]
    w = worm(pair("worm", z=(2, 41), m=0.005, c=0.2, worm_diameter=0.05))
    assert (w.z2, w.q, w.ratio) == (41, 10.0, 20.5)
    for key, v in {"gamma1_deg": math.degrees(w.gamma1), "beta2_deg": math.degrees(w.beta2), "d1_mm": w.d1 * 1e3,
                   "d2_mm": w.d2 * 1e3, "da1_mm": w.da1 * 1e3, "da2_mm": w.da2 * 1e3, "df1_mm": w.df1 * 1e3,
                   "df2_mm": w.df2 * 1e3, "a_mm": w.a * 1e3}.items():
        assert v == pytest.approx(ex[key], rel=1e-13), key


def test_a_worm_with_many_starts():
    w = worm(pair("worm", z=(8, 40), m=0.005, c=0.2, worm_diameter=0.04))
    assert math.degrees(w.gamma1) == pytest.approx(45.0, rel=1e-14)   # z₁ = q: γ = 45°
    assert w.pz1 == pytest.approx(8 * math.pi * 0.005, rel=1e-15)
    with pytest.raises(OutOfDomain, match="no worm core"):
        worm(pair("worm", z=(2, 40), m=0.005, c=0.2, worm_diameter=0.01))
