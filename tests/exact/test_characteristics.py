"""Characteristics: the drawn construction against the closed forms, over many linkages."""
from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphmech.exact import characteristics as X
from graphmech.mechanisms.linkage import RPR, RRP, RRR, Crank, Guide, Linkage
from graphmech.methods.characteristics import draw_characteristics, grashof_class, grashof_ranges

lengths = st.floats(0.01, 0.2)


def _wrap_diff(a: float, b: float) -> float:
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(st.floats(0.02, 1.0), lengths, lengths, lengths, st.sampled_from(["left", "right"]),
       st.sampled_from([1.0, -1.0]), st.floats(0, 2 * math.pi))
def test_fourbar_drawn_agrees_with_the_cosine_rule(share, b, c, d, branch, sense, tilt):
    a = share * min(b, c, d)  # mostly the shortest link: crank-rockers and double cranks
    kind = grashof_class(a, b, c, d)
    assert kind == X.fourbar_class(a, b, c, d) or kind == "change_point" or X.fourbar_class(a, b, c, d) == "change_point"
    assume(kind in ("crank_rocker_AB", "double_crank"))
    D = (d * math.cos(tilt), d * math.sin(tilt))
    lk = Linkage({"A": (0.0, 0.0), "D": D}, Crank("1", "A", "B", a, 10.0 * sense),
                 (RRR("B", "C", "D", ("2", "3"), (b, c), branch),))
    dr = draw_characteristics(lk, 0.001)
    ex = X.fourbar(0j, complex(*D), a, b, c, branch, sense)
    assert dr.grashof == ex.grashof
    assert dr.gamma_min == pytest.approx(ex.gamma_min, abs=1e-9)
    if ex.theta is None:
        assert dr.theta is None and kind == "double_crank"
        return
    # near a change point the extremes are tangent intersections: the drawing keeps √ε of its digits
    tol = 1e-9 if min(abs(b + c - a - d), abs(b - a - abs(d - c))) > 1e-4 * (a + b + c + d) else 1e-5
    assert dr.theta == pytest.approx(ex.theta, abs=tol)
    assert dr.psi == pytest.approx(ex.psi, abs=tol)
    assert _wrap_diff(dr.phi_start, ex.phi_start) < tol and _wrap_diff(dr.phi_end, ex.phi_end) < tol
    # the working stroke is the longer one: 180° + θ in the crank's sense
    travel = (sense * (ex.phi_end - ex.phi_start)) % (2 * math.pi)
    assert travel == pytest.approx(math.pi + ex.theta, abs=1e-9)


@settings(max_examples=100, deadline=None)
@given(lengths, st.floats(1.2, 5.0), st.floats(-0.9, 0.9), st.sampled_from(["forward", "backward"]),
       st.sampled_from([1.0, -1.0]), st.floats(-math.pi, math.pi))
def test_slider_crank_drawn_agrees(a, ratio, off, branch, sense, angle):
    b = a * ratio
    e = off * (b - a)
    g = (math.cos(angle), math.sin(angle))
    through = (-e * g[1], e * g[0])  # the guide passes e to the left of A
    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", a, 10.0 * sense),
                 (RRP("B", "C", ("2", "3"), b, Guide(through, angle), branch),))
    dr = draw_characteristics(lk, 0.001)
    ex = X.slider_crank(0j, complex(*through), angle, a, b, branch, sense)
    assert dr.theta == pytest.approx(ex.theta, abs=1e-9)
    assert dr.stroke_mm * 0.001 == pytest.approx(ex.stroke, rel=1e-9)
    assert dr.gamma_min == pytest.approx(ex.gamma_min, abs=1e-9)
    assert _wrap_diff(dr.gamma_min_at, ex.gamma_min_at) < 1e-9
    assert _wrap_diff(dr.phi_start, ex.phi_start) < 1e-9


@given(st.floats(0.1, 0.95), st.sampled_from([1.0, -1.0]))
def test_guide_bar_theta_equals_psi(r, sense):
    lk = Linkage({"A": (0.0, 0.0), "C": (0.0, -0.2)}, Crank("1", "A", "B", 0.2 * r, 10.0 * sense),
                 (RPR("B", "C", ("2", "3"), "second"),))
    dr = draw_characteristics(lk, 0.001)
    ex = X.guide_bar(0j, -0.2j, 0.2 * r, sense)
    assert dr.theta == pytest.approx(ex.theta, abs=1e-9) == pytest.approx(2 * math.asin(r), abs=1e-9)
    assert dr.psi == pytest.approx(ex.theta, abs=1e-9)
    assert ex.gamma_min == dr.gamma_min == math.pi / 2


def test_ranges_by_the_sum_rule_and_by_closure_agree():
    for b, c, d in ((50, 35, 30), (40, 60, 80), (100, 30, 45), (20, 20, 20)):
        assert [(k, pytest.approx(lo), pytest.approx(hi)) for k, lo, hi in grashof_ranges(b, c, d)] == \
            X.grashof_ranges(b, c, d)


def test_results_are_frozen():
    ex = X.fourbar(0j, 72 + 0j, 28, 52, 50, "left")
    with pytest.raises(dataclasses.FrozenInstanceError):
        ex.theta = 0.0  # type: ignore[misc]


def test_a_crank_that_does_not_turn_has_no_characteristics():
    with pytest.raises(ValueError, match="does not turn fully"):
        X.fourbar(0j, 30 + 0j, 30, 50, 35, "left")
    lk = Linkage({"A": (0.0, 0.0), "D": (0.03, 0.0)}, Crank("1", "A", "B", 0.03, 10.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.05, 0.035), "left"),))
    with pytest.raises(ValueError, match="does not turn fully"):
        draw_characteristics(lk, 0.001)


def test_the_drawn_characteristics_are_frozen():
    lk = Linkage({"A": (0.0, 0.0), "D": (0.072, 0.0)}, Crank("1", "A", "B", 0.028, 10.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.052, 0.05), "left"),))
    dr = draw_characteristics(lk, 0.001)
    with pytest.raises(dataclasses.FrozenInstanceError):
        dr.theta = 0.0  # type: ignore[misc]


def test_a_deltoid_has_no_extreme_positions_and_says_why():
    """AB = BC, CD = AD (a kite at Grashof's equality): folded, C falls on A and the crank's angle
    there is undetermined — a one-line reason from both, never a division by zero."""
    lk = Linkage({"A": (0.0, 0.0), "D": (0.072, 0.0)}, Crank("1", "A", "B", 0.030, 10.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.030, 0.072), "left"),))
    with pytest.raises(ValueError, match="deltoid"):
        draw_characteristics(lk, 0.0005)
    with pytest.raises(ValueError, match="deltoid"):
        X.fourbar(0j, 0.072 + 0j, 0.030, 0.030, 0.072, "left")
    # the other kite (AB = AD, BC = CD) is a double crank with γ only, as before
    other = X.fourbar(0j, 0.030 + 0j, 0.030, 0.072, 0.072, "left")
    assert other.theta is None and other.grashof == "change_point"


# --------------------------------------------------------------------------------------------
# An offset guide bar: the extremes where its line (at e from C) is tangent to the crank circle


def _offset_bar(a: float, e: float, omega: float = 5.0) -> Linkage:
    return Linkage({"A": (0.0, 0.0), "C": (0.0, -0.35)}, Crank("1", "A", "B", a, omega),
                   (RPR("B", "C", ("2", "3"), bar="second", offset=e),))


@pytest.mark.parametrize("e", [0.04, -0.04, 0.1, 1e-5])
@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_an_offset_guide_bars_extremes_are_where_the_bar_stops(e, sense):
    """At φ_start and φ_end the exact kinematics give ω3 = 0 (independent of the closed form), the
    bar's swing between them is ψ, and γ = arccos(|e|/|CB|) sampled over a turn has its least at
    γ_min, with the crank pointing at C."""
    import numpy as np

    from graphmech.exact.linkage import solve

    ch = X.offset_guide_bar(0j, -0.35j, 0.11, e, sense)
    lk = _offset_bar(0.11, e, 5.0 * sense)
    kin = solve(lk, np.array([ch.phi_start, ch.phi_end]))
    assert kin.valid.all() and np.abs(kin.omega["3"]).max() < 1e-12
    swing = abs((kin.angle["3"][1] - kin.angle["3"][0] + math.pi) % (2 * math.pi) - math.pi)
    assert ch.psi == pytest.approx(swing, rel=1e-12) and ch.theta == pytest.approx(ch.psi, rel=1e-12)
    phi = np.linspace(0.0, 2 * math.pi, 20001)
    cb = np.hypot(*(solve(lk, phi).point["B"] - np.array([0.0, -0.35])).T)
    assert ch.gamma_min == pytest.approx(float(np.arccos(abs(e) / cb).min()), rel=1e-12)
    assert ch.gamma_min_at == pytest.approx(3 * math.pi / 2, rel=1e-15)
    # the working (slow) stroke runs from φ_start to φ_end in the crank's sense: 180° + θ of the turn
    travel = (sense * (ch.phi_end - ch.phi_start)) % (2 * math.pi)
    assert travel == pytest.approx(math.pi + ch.theta, rel=1e-12)


def test_a_zero_offset_is_the_centred_guide_bar_and_a_reaching_crank_is_refused():
    assert X.guide_bar(0j, -0.35j, 0.11, 1.0, 0.0) == X.guide_bar(0j, -0.35j, 0.11)
    assert X.offset_guide_bar(0j, -0.35j, 0.11, 0.0).theta == pytest.approx(X.guide_bar(0j, -0.35j, 0.11).theta,
                                                                             rel=1e-12)
    with pytest.raises(ValueError, match="reaches the circle of radius"):
        X.offset_guide_bar(0j, -0.35j, 0.11, 0.24)


@pytest.mark.parametrize("e", [0.04, -0.07])
def test_the_drawn_offset_guide_bar_agrees_with_its_closed_form(e):
    ch = X.offset_guide_bar(0j, -0.35j, 0.11, e)
    dr = draw_characteristics(_offset_bar(0.11, e), 0.002)
    for got, want in ((dr.theta, ch.theta), (dr.psi, ch.psi), (dr.phi_start, ch.phi_start),
                      (dr.phi_end, ch.phi_end), (dr.gamma_min, ch.gamma_min), (dr.gamma_min_at, ch.gamma_min_at)):
        assert got == pytest.approx(want, rel=1e-12)
    C, F1 = dr.points["C"], dr.points["F1"]
    assert math.dist(C, F1) == pytest.approx(abs(e) / 0.002, rel=1e-12)  # the foot on the circle (C, |e|)
