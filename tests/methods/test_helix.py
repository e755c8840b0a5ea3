"""The helical, bevel and worm constructions (graphmech/methods/helix.py) against the closed forms of
graphmech/exact/gear_spatial.py: every measured length and angle within 1e-9."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.exact import gear_spatial as ex
from graphmech.mechanisms.gear import GearSet, SpatialPair, SpurGear, ToothSystem
from graphmech.methods.helix import (
    construct_bevel,
    construct_helical,
    construct_worm,
    normal_section,
)

DEG = math.radians
TOL = 1e-9


def pair(kind, z=(20, 40), m=0.008, a=None, c=0.25, **sp):
    return GearSet(ToothSystem(m, DEG(20), 1.0, c), tuple(SpurGear(v) for v in z), kind, a, SpatialPair(**sp))


def worst(pairs):
    return max(abs(g - e) / abs(e) if e else abs(g) for g, e in pairs)


@pytest.mark.parametrize("beta, a", [(15.0, 0.25), (8.0, None), (30.0, None), (44.9, None), (1e-6, None)])
def test_helical_construction_against_the_closed_forms(beta, a):
    g = pair("helical", a=a, beta=DEG(beta), face_width=0.03)
    c, e = construct_helical(g), ex.helical(g)
    d = c.development
    got = [(c.angle.beta, e.beta), (c.angle.a_initial, e.a_initial), (c.mesh.a_w, e.a), (d.pt, e.pt), (d.st, e.st),
           (math.hypot(*d.Pn), e.pn), (d.mt, e.mt), (d.alpha_t, e.alpha_t), (c.alpha_at[0], e.alpha_at[0]),
           (c.alpha_at[1], e.alpha_at[1]), (c.sections[0].zv, e.zv[0]), (c.sections[1].zv, e.zv[1]),
           (c.eps_alpha, e.eps_alpha), (c.eps_beta, e.eps_beta), (c.eps_gamma, e.eps_gamma)]
    assert c.leads is not None and e.pz is not None
    got += [(c.leads[0].pz, e.pz[0]), (c.leads[1].pz, e.pz[1]), (c.leads[0].beta_b, e.beta_b),
            (c.leads[1].beta_b, e.beta_b)]
    assert worst(got) < TOL


def test_the_bank_pair_measured(problems):
    c = construct_helical(pair("helical", a=0.25, beta=DEG(15), face_width=0.03))
    ex_ = problems["gear.helical_20_40_mn8"]["exact"]
    assert math.degrees(c.angle.beta) == pytest.approx(ex_["beta_deg"], rel=TOL)
    assert c.sections[1].zv == pytest.approx(ex_["zv2"], rel=TOL)       # the book printed z_v1 again
    assert c.eps_alpha == pytest.approx(ex_["eps_alpha"], rel=TOL)      # the book printed 1.592
    # the development: ε_β is the advance B·tan β over p_t
    assert c.development.advance / c.development.pt == pytest.approx(ex_["eps_beta"], rel=TOL)


def test_beta_zero_has_no_lead_and_the_spur_ratio():
    c = construct_helical(pair("helical", beta=0.0, face_width=0.03))
    assert c.leads is None and c.eps_beta == 0.0 and c.sections[0].zv == pytest.approx(20.0, rel=1e-15)


def test_the_osculating_circle_of_the_normal_section():
    s = normal_section(0.1, DEG(30), 0.005)
    assert s.a_e == pytest.approx(0.1 / math.cos(DEG(30)), rel=1e-15)
    assert s.rho == pytest.approx(s.a_e ** 2 / s.b_e, rel=1e-14)         # the rectangle's construction
    assert s.K[0] == pytest.approx(0.0, abs=1e-16)


def test_a_circle_too_small_for_the_pair_is_refused():
    with pytest.raises(OutOfDomain, match="does not reach"):
        construct_helical(pair("helical", a=0.2, beta=DEG(10)))


@pytest.mark.parametrize("sigma", [45.0, 70.0, 90.0, 115.0])
def test_bevel_construction_against_the_closed_forms(sigma):
    g = pair("bevel", m=0.004, c=0.2, shaft_angle=DEG(sigma))
    c, e = construct_bevel(g), ex.bevel(g)
    got = [(c.delta[0], e.delta[0]), (c.delta[1], e.delta[1]), (c.R, e.R), (c.theta_a, e.theta_a),
           (c.theta_f, e.theta_f), (c.zv[0], e.zv[0]), (c.zv[1], e.zv[1])]
    got += [(c.da[i], e.da[i]) for i in (0, 1)] + [(c.df[i], e.df[i]) for i in (0, 1)]
    assert worst(got) < TOL


@pytest.mark.parametrize("z, sigma", [((1, 1), 30.0), ((1, 40), 90.0), ((1, 1), 90.0)])
def test_a_bevel_root_past_the_axis_is_a_negative_diameter_as_the_closed_form(z, sigma):
    """Few teeth: the root point F lies beyond the gear's axis; its d_f is negative (as a spur
    gear's d − 2h_f), not the distance's absolute value."""
    g = pair("bevel", z=z, m=0.005, shaft_angle=DEG(sigma))
    c, e = construct_bevel(g), ex.bevel(g)
    assert e.df[0] < 0.0 and c.df[0] < 0.0
    assert worst([(c.df[i], e.df[i]) for i in (0, 1)] + [(c.da[i], e.da[i]) for i in (0, 1)]) < TOL


def test_bevel_crown_refused():
    with pytest.raises(NotApplicable, match="90°"):
        construct_bevel(pair("bevel", shaft_angle=DEG(130)))


@pytest.mark.parametrize("z1, d1", [(1, 0.09), (2, 0.05), (4, 0.05), (6, 0.04), (10, 0.04)])
def test_worm_construction_against_the_closed_forms(z1, d1):
    g = pair("worm", z=(z1, 40), m=0.005, c=0.2, worm_diameter=d1)
    c, e = construct_worm(g), ex.worm(g)
    assert worst([(c.gamma1, e.gamma1), (c.beta2, e.beta2), (c.pz1, e.pz1), (c.px, e.px)]) < TOL
    assert len(c.threads) == z1 and c.threads[1 % z1][0][1] == pytest.approx((1 % z1) * c.px, rel=1e-15)
