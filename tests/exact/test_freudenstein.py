"""The structural error of Freudenstein's function generator, by the exact four-bar."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings

from graphmech.errors import OutOfDomain
from graphmech.exact.freudenstein import (
    FourBar,
    convergence,
    output_angle,
    structural_error,
)
from graphmech.methods.freudenstein import design, named_function
from tests.methods.test_freudenstein import OWN_FOURBARS, own_design, own_output

D = math.radians


def error_of(r, samples=2001):
    bar = FourBar(r.a, r.b, r.c, r.d, r.input_reversed, r.output_reversed)
    return structural_error(bar, r.function, r.x0, r.x1, r.phi0, r.dphi, r.psi0, r.dpsi, r.phi, samples)


def log10(spacing="chebyshev", **kw):
    args = {"x0": 1.0, "x1": 2.0, "phi0": D(45), "dphi": D(60), "psi0": D(135), "dpsi": D(90), "spacing": spacing}
    args.update(kw)
    return design(named_function("log10"), **args)


def test_log10_chebyshev_structural_error():
    s = error_of(log10())
    assert s.assembles and s.why == "" and s.branch == "left"
    assert s.zero_at_points(1e-9) and np.max(np.abs(s.at_points)) < 1e-13
    # the four extremes (n + 1 for three points) alternate in sign; the largest at φ₀
    assert np.degrees(s.extremes) == pytest.approx([-0.1686366204, 0.1270480, -0.0711612, 0.0521220], abs=1e-6)
    assert np.all(np.sign(s.extremes[1:]) == -np.sign(s.extremes[:-1]))
    assert np.degrees(s.max_error) == pytest.approx(0.1686366204, abs=1e-9)
    assert s.max_error_y == pytest.approx(s.max_error * math.log10(2) / D(90))
    assert np.degrees(s.extremes_phi[1:3]) == pytest.approx([58.6221027, 88.4850540], abs=1e-6)
    # the curve crosses zero exactly between the extremes: three sign changes
    assert np.count_nonzero(np.diff(np.sign(s.error[np.abs(s.error) > 1e-12]))) == 3


def test_chebyshev_beats_uniform_spacing_for_log10():
    cheb, uni = error_of(log10()), error_of(log10("uniform"))
    assert np.degrees(uni.max_error) == pytest.approx(0.1962396139, abs=1e-9)
    assert cheb.max_error < 0.86 * uni.max_error
    # uniform spacing puts two precision points at the ends: zero error there
    assert abs(uni.extremes[0]) < 1e-12 and abs(uni.extremes[-1]) < 1e-12


def test_located_extremes_are_the_curves_maxima():
    s = error_of(log10())
    phi = s.extremes_phi[1]
    dense = D(45) + D(60) * np.linspace(0, 1, 400001)
    dense = dense[np.abs(dense - phi) < 1e-3]
    fine = error_of(log10(), samples=2001)
    bar = FourBar(*(getattr(log10(), k) for k in "abcd"), True, False)
    psi, ok = output_angle(bar, dense, "left")
    assert ok.all()
    r = log10()
    want = r.psi_of(1 + (dense - r.phi0) / r.dphi)
    assert np.max(np.abs(psi - want)) <= abs(fine.extremes[1]) + 1e-15
    assert np.max(np.abs(psi - want)) == pytest.approx(abs(fine.extremes[1]), abs=1e-12)


def test_refinement_makes_the_located_extreme_independent_of_the_sampling():
    # uniform spacing: the largest error is inside the range, where it is refined
    rows = convergence(*_args(log10("uniform")), case="log10-uniform", samples=(11, 31, 101, 2001), repeat=1)
    assert [row["n"] for row in rows] == [11, 31, 101, 2001]
    assert {row["method"] for row in rows} == {"freudenstein structural error"}
    assert max(row["max_rel_error"] for row in rows) < 1e-12
    assert rows[0]["max_error_deg"] == pytest.approx(0.1962396139, abs=1e-9)
    # the samples alone: off by about the square of the step
    assert rows[0]["sampled_rel_error"] > 1e-3 and rows[-1]["sampled_rel_error"] < 1e-6
    assert all(row["seconds"] > 0 for row in rows)


def _args(r):
    return (FourBar(r.a, r.b, r.c, r.d, r.input_reversed, r.output_reversed), r.function, r.x0, r.x1,
            r.phi0, r.dphi, r.psi0, r.dpsi, r.phi)


def test_more_points_are_not_met_exactly():
    s5 = error_of(log10(n=5))
    assert s5.assembles and not s5.zero_at_points(1e-9)
    s2 = error_of(log10(n=2))
    assert s2.assembles and s2.zero_at_points(1e-9)


def test_a_branch_that_breaks_is_said():
    # sin over [0, 1.5] rad with these swings: the design's linkage leaves its branch in the range
    r = design(named_function("sin"), 0.0, 1.5, D(45), D(60), D(135), D(90))
    s = error_of(r)
    assert not s.assembles and "cannot be assembled on the left branch from φ = " in s.why
    assert s.max_error == math.inf and s.zero_at_points(1e-9)


def test_tiny_input_swing_designs_a_linkage_at_its_toggle():
    s = error_of(log10(dphi=1e-4))
    assert not s.assembles and "cannot be assembled" in s.why


def test_a_double_rocker_over_a_full_turn_is_said():
    bar = FourBar(0.95, 0.5, 0.6, 1.0)
    psi0, ok = output_angle(bar, np.array([2.5]), "left")
    assert ok[0]
    s = structural_error(bar, lambda x: x, 0.0, 1.0, 2.5, 2 * math.pi, float(psi0[0]), 1.0, np.array([2.5]))
    assert not s.assembles and math.isinf(s.max_error_y) and s.branch == "left"
    assert s.zero_at_points(1e-9) and np.isnan(s.error).any()
    s = structural_error(bar, lambda x: x, 0.0, 1.0, math.pi, 1.0, 0.0, 1.0, np.array([math.pi]))
    assert not s.assembles and "at the first precision point φ = 180.0000° on either branch" in s.why


def test_refusals():
    r = log10()
    with pytest.raises(OutOfDomain, match="at least 3"):
        error_of(r, samples=2)
    with pytest.raises(OutOfDomain, match="must be finite and > 0"):
        structural_error(FourBar(0.0, 1.0, 1.0, 1.0), np.log10, 1, 2, 0.0, 1.0, 0.0, 1.0, np.array([0.1]))
    with pytest.raises(OutOfDomain, match="must not be 0"):
        structural_error(FourBar(1.0, 1.0, 1.0, 1.0), np.log10, 1, 2, 0.0, 1.0, 0.0, 0.0, np.array([0.1]))
    with pytest.raises(OutOfDomain, match="no precision point"):
        structural_error(FourBar(1.0, 1.0, 1.0, 1.0), np.log10, 1, 2, 0.0, 1.0, 0.0, 1.0, np.array([]))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(*OWN_FOURBARS)
def test_a_four_bars_own_function_has_zero_structural_error(a, b, c, phi0, dphi, side):
    r = own_design(a, b, c, phi0, dphi, side)
    s = error_of(r, samples=201)
    assert s.assembles and s.branch in ("left", "right")
    assert s.zero_at_points(1e-9)
    assert s.max_error < 1e-9


def test_log10_ends_by_the_law_of_cosines():
    # the error at x = 1 and x = 2 recomputed apart: AB reversed (R₂ < 0), C on the side −1
    r = log10()
    psi = own_output(r.a, r.b, r.c, 1.0, -1.0)
    x = np.array([1.0, 2.0])
    e = np.angle(np.exp(1j * (psi(r.phi_of(x) + math.pi) - r.psi_of(x))))
    s = error_of(r)
    assert e == pytest.approx(s.extremes[[0, -1]], abs=1e-13)
    assert np.degrees(e) == pytest.approx([-0.1686366204, 0.0521220], abs=1e-6)
