"""The construction from the time ratio, drawn at μl, against the closed forms: every design
found by both, its measured lengths equal to round-off."""
from __future__ import annotations

import math

import pytest

from graphmech.exact.synthesis import (
    crank_rocker_from_limit,
    crank_rocker_from_swing,
    guide_bar_from_K,
    slider_crank_from_K,
)
from graphmech.methods.synthesis_time_ratio import (
    draw_from_limit,
    draw_from_swing,
    draw_guide_bar,
    draw_slider_crank,
    theta_of_K,
)


def _same(drawn, exact, mu):
    assert len(drawn) == len(exact)
    for g, e in zip(drawn, exact):
        for mm, si in ((g.AC1_mm, e.AC1), (g.AC2_mm, e.AC2), (g.lAB_mm, e.lAB), (g.lBC_mm, e.lBC)):
            assert mm * mu == pytest.approx(si, rel=1e-12)
        assert g.branch == e.branch


@pytest.mark.parametrize("K", [1.0, 1.5, 2.0])
@pytest.mark.parametrize("c, d, limit", [(75, 100, 45), (75, 100, 30), (150, 100, 90)])
def test_the_limit_construction_draws_the_closed_forms(K, c, d, limit):
    mu = 2.0
    drawn = draw_from_limit(c / mu, d / mu, math.radians(limit), theta_of_K(K))
    _same(drawn, crank_rocker_from_limit(c, d, math.radians(limit), theta_of_K(K)), mu)
    for g in drawn:
        assert math.degrees(g.theta) == pytest.approx(180 * (K - 1) / (K + 1), abs=1e-9)


@pytest.mark.parametrize("K", [1.0, 1.4, 2.9])
@pytest.mark.parametrize("c, d, psi", [(75, 100, 40), (150, 100, 90)])
def test_the_theta_circle_construction_draws_the_closed_forms(K, c, d, psi):
    mu = 2.5
    drawn = draw_from_swing(c / mu, d / mu, math.radians(psi), theta_of_K(K))
    _same(drawn, crank_rocker_from_swing(c, d, math.radians(psi), theta_of_K(K)), mu)
    for g in drawn:
        if K > 1.0:  # the θ-circle passes through A, C₁ and C₂
            (O, R) = g.circle
            for p in ("A", "C1", "C2"):
                assert math.dist(O, g.points[p]) == pytest.approx(R, rel=1e-12)
        else:
            assert g.circle is None


def test_the_banks_drawing_lengths_are_the_books_within_its_reading():
    # the book's AC₁ = 35 mm, AC₂ = 84.5 and 13 mm on its μl = 2 mm/mm drawing
    d1, d2 = draw_from_limit(37.5, 50.0, math.radians(45), theta_of_K(1.5))
    assert (round(d1.AC1_mm, 2), round(d1.AC2_mm, 2), round(d2.AC2_mm, 2)) == (35.42, 84.73, 12.91)


def test_no_design_where_the_rocker_is_too_short_for_a_crank():
    assert draw_from_swing(25.0, 50.0, math.radians(60), theta_of_K(1.5)) == []


@pytest.mark.parametrize("K", [1.1, 2.0, 10.0])
def test_the_guide_bar_construction_draws_the_closed_forms(K):
    g = draw_guide_bar(150.0, theta_of_K(K), 200.0)
    a, l_cd = guide_bar_from_K(300.0, theta_of_K(K), 400.0)
    assert g.lAB_mm * 2 == pytest.approx(a, rel=1e-12) and g.lCD_mm * 2 == pytest.approx(l_cd, rel=1e-12)
    # the crank pins are where the bar touches the crank circle: AB ⟂ CB
    A, C = g.points["A"], g.points["C"]
    for B in (g.points["B1"], g.points["B2"]):
        assert abs((B[0] - A[0]) * (B[0] - C[0]) + (B[1] - A[1]) * (B[1] - C[1])) < 1e-9
    assert math.dist(g.points["D1"], g.points["D2"]) == pytest.approx(200.0, rel=1e-12)
    assert draw_guide_bar(150.0, theta_of_K(K)).lCD_mm is None


@pytest.mark.parametrize("K, H, e", [(1.5, 50, 10), (1.2, 50, 0.1), (2.9, 50, 1), (1.5, 50, 60), (2.5, 50, 60)])
def test_the_slider_crank_construction_draws_the_closed_forms(K, H, e):
    g = draw_slider_crank(H / 2, e / 2, theta_of_K(K))
    x = slider_crank_from_K(H, e, theta_of_K(K))
    assert (g is None) == (x is None)
    if g is not None:
        assert g.AC1_mm * 2 == pytest.approx(x[1], rel=1e-12) and g.AC2_mm * 2 == pytest.approx(x[2], rel=1e-12)
        O, R = g.circle
        for p in ("A", "C1", "C2"):  # the θ-circle through A, C₁, C₂
            assert math.dist(O, g.points[p]) == pytest.approx(R, rel=1e-12)
