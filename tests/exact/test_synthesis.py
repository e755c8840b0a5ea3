"""The closed-form designs from the time ratio: the bank's two crank-rockers, and every design
re-analysed by exact/characteristics reproduces the K and the limit angle or swing it was made for."""
from __future__ import annotations

import cmath
import math

import pytest

from graphmech.exact.characteristics import fourbar, guide_bar, slider_crank
from graphmech.exact.synthesis import (
    crank_rocker_from_limit,
    crank_rocker_from_swing,
    guide_bar_from_K,
    slider_crank_from_K,
    theta_of_K,
)
from tests.conftest import reference_problem


def test_the_banks_two_designs_are_its_exact_values():
    ref = reference_problem("linkage.crank_rocker_synthesis_K1.5")
    i, ex = ref["inputs"], ref["exact"]
    got = crank_rocker_from_limit(i["lCD_mm"], i["lAD_mm"], math.radians(i["psi_limit_deg"]), theta_of_K(i["K"]))
    assert len(got) == 2
    for k, d in enumerate(got, 1):
        for name, value in (("lAB", d.lAB), ("lBC", d.lBC), ("AC1", d.AC1), ("AC2", d.AC2)):
            assert value == pytest.approx(ex[f"sol{k}_{name}_mm"], rel=1e-12)


@pytest.mark.parametrize("K", [1.0, 1.2, 1.5, 2.0])
@pytest.mark.parametrize("c, d, limit", [(75, 100, 45), (75, 100, 30), (150, 100, 90)])
def test_each_limit_design_reanalysed_has_its_K_and_its_limit(K, c, d, limit):
    designs = crank_rocker_from_limit(c, d, math.radians(limit), theta_of_K(K))
    for x in designs:
        ch = fourbar(x.A, x.D, x.lAB, x.lBC, x.lCD, x.branch)
        assert ch.grashof == "crank_rocker_AB"
        assert ch.K == pytest.approx(K, rel=1e-9, abs=1e-9)
        # one extreme of the re-analysed linkage has the rocker at the stated limit: ∠ADC at ψ's ends
        to_C1 = math.degrees(abs(cmath.phase((x.A - x.D) / (x.C1 - x.D))))
        assert to_C1 == pytest.approx(limit, abs=1e-9)
        psi = math.degrees(abs(cmath.phase((x.C2 - x.D) / (x.C1 - x.D))))
        assert math.degrees(ch.psi) == pytest.approx(psi, abs=1e-9)


@pytest.mark.parametrize("K", [1.0, 1.4, 2.9])
@pytest.mark.parametrize("c, d, psi", [(75, 100, 40), (150, 100, 90), (150, 100, 60)])
def test_each_swing_design_reanalysed_has_its_K_and_its_swing(K, c, d, psi):
    for x in crank_rocker_from_swing(c, d, math.radians(psi), theta_of_K(K)):
        ch = fourbar(x.A, x.D, x.lAB, x.lBC, x.lCD, x.branch)
        assert ch.K == pytest.approx(K, rel=1e-9, abs=1e-9)
        assert math.degrees(ch.psi) == pytest.approx(psi, abs=1e-9)
        assert abs(x.D - x.A) == pytest.approx(d, rel=1e-12)


def test_K_near_3_still_designs_and_a_short_rocker_admits_no_crank():
    assert len(crank_rocker_from_swing(150, 100, math.radians(90), theta_of_K(2.99))) == 1
    assert crank_rocker_from_swing(50, 100, math.radians(60), theta_of_K(1.5)) == []


def test_K_1_gives_the_limits_on_one_line_through_A():
    (x,) = crank_rocker_from_limit(75, 100, math.radians(45), 0.0)
    assert abs(cmath.phase((x.C2 - x.A) / (x.C1 - x.A))) < 1e-12 and x.lAB > 1.0


@pytest.mark.parametrize("K", [1.1, 1.5, 2.0, 3.0, 10.0])
def test_a_guide_bar_reanalysed_has_its_K_and_its_stroke(K):
    a, l_cd = guide_bar_from_K(300.0, theta_of_K(K), 400.0)
    ch = guide_bar(300j, 0j, a)
    assert ch.K == pytest.approx(K, rel=1e-12) and ch.psi == pytest.approx(theta_of_K(K), rel=1e-12)
    assert 2 * l_cd * math.sin(ch.psi / 2) == pytest.approx(400.0, rel=1e-12)
    assert guide_bar_from_K(300.0, theta_of_K(K))[1] is None


@pytest.mark.parametrize("K, H, e", [(1.5, 50, 10), (1.2, 50, 0.1), (2.9, 50, 1), (1.5, 50, 60)])
def test_a_slider_crank_reanalysed_has_its_K_and_its_stroke(K, H, e):
    A, ac1, ac2 = slider_crank_from_K(H, e, theta_of_K(K))
    a, b = (ac2 - ac1) / 2, (ac1 + ac2) / 2
    ch = slider_crank(A, 0j, 0.0, a, b, "forward")
    assert ch.K == pytest.approx(K, rel=1e-9) and ch.stroke == pytest.approx(H, rel=1e-9)
    assert A.imag == e and a + e < b


def test_a_slider_crank_with_no_crank_or_no_offset_is_none():
    assert slider_crank_from_K(50, 60, theta_of_K(2.5)) is None  # l_AB + e ≥ l_BC
    assert slider_crank_from_K(50, 0, theta_of_K(1.5)) is None  # A would fall on C₁


def test_a_limit_position_with_C1_near_A_has_no_cancellation():
    """l_CD = l_AD and ∠ADC₁ = 1e-7°: C₁ is 1.7e-9 of l_AD from A. The law of cosines as
    c² + d² − 2cd·cos α gave AC₁ = 0 and divided by zero; as (c − d)² + 4cd·sin²(α/2) it is exact."""
    alpha = math.radians(1e-7)
    (x,) = crank_rocker_from_limit(0.1, 0.1, alpha, math.radians(36))
    assert x.AC1 == pytest.approx(0.2 * math.sin(alpha / 2), rel=1e-12)
    assert x.lBC - x.lAB == pytest.approx(x.AC1, rel=1e-6)  # AC₁ = BC − AB at the limit
    assert fourbar(x.A, x.D, x.lAB, x.lBC, x.lCD, x.branch).K == pytest.approx(1.5, rel=1e-12)
