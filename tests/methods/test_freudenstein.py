"""Freudenstein's function generator: the precision points, the 3×3 solution, the named functions."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphmech.errors import OutOfDomain
from graphmech.methods.freudenstein import (
    FUNCTIONS,
    Function,
    chebyshev_points,
    design,
    named_function,
    uniform_points,
)

D = math.radians


def log10_design(**kw):
    # the textbook's classic: y = log10 x on [1, 2], Δφ = 60°, Δψ = 90°; started at φ₀ = 45°, ψ₀ = 135°
    args = {"x0": 1.0, "x1": 2.0, "phi0": D(45), "dphi": D(60), "psi0": D(135), "dpsi": D(90)}
    args.update(kw)
    return design(named_function("log10"), **args)


def test_chebyshev_points_follow_the_cosine_rule():
    assert np.allclose(chebyshev_points(1.0, 2.0, 3), [1.5 - 0.5 * math.sqrt(3) / 2, 1.5, 1.5 + 0.5 * math.sqrt(3) / 2],
                       atol=1e-15)
    x4 = chebyshev_points(0.0, 4.0, 4)
    assert np.allclose(x4, 2 - 2 * np.cos(np.array([1, 3, 5, 7]) * math.pi / 8))
    assert np.allclose(x4 + x4[::-1], 4.0)  # symmetric about the middle
    assert np.allclose(uniform_points(1.0, 2.0, 3), [1.0, 1.5, 2.0])


def test_log10_classic_link_lengths():
    r = log10_design()
    # computed here (no published solution found for these start angles): d = 1
    assert r.R == pytest.approx((0.5206947170, -0.5402891983, 0.0156725465), abs=1e-9)
    assert (r.a, r.b, r.c) == pytest.approx((1.8508606189, 2.8680075409, 1.9205111315), abs=1e-9)
    assert r.input_reversed and not r.output_reversed  # R₂ < 0: AB points at φ + 180°
    assert r.n == 3 and r.spacing == "chebyshev" and "exactly" in r.method
    assert np.max(np.abs(r.residuals)) < 1e-14
    assert np.allclose(np.degrees(r.phi), 45 + 60 * (r.x - 1)) and np.allclose(r.phi_of(r.x), r.phi)
    assert np.allclose(r.psi, r.psi_of(r.x)) and r.psi_of(np.array([2.0]))[0] == pytest.approx(D(225))
    # the joints at the precision points: the coupler has the same length b at all three
    p = r.precision_positions()
    assert np.allclose(np.abs(p["C"] - p["B"]), r.b, atol=1e-12, rtol=0)
    assert np.allclose(np.abs(p["B"] - p["A"]), r.a) and np.allclose(np.abs(p["C"] - p["D"]), r.c)


def test_lengths_scale_with_the_frame():
    r1, r3 = log10_design(), log10_design(d=0.3)
    assert (r3.a, r3.b, r3.c) == pytest.approx((0.3 * r1.a, 0.3 * r1.b, 0.3 * r1.c), rel=1e-12)
    assert r3.R == pytest.approx(r1.R, rel=1e-12)


def test_more_points_least_squares_and_two_points_minimum_norm():
    r5 = log10_design(n=5)
    assert "least squares" in r5.method and r5.x.size == 5
    assert 1e-8 < np.max(np.abs(r5.residuals)) < 1e-2  # not met exactly, but nearly
    assert abs(float(np.sum(r5.residuals * np.column_stack(
        [np.cos(r5.phi), -np.cos(r5.psi), np.ones(5)]).T[2]))) < 1e-12  # normal equations
    r2 = log10_design(n=2)
    assert "minimum-norm" in r2.method and np.max(np.abs(r2.residuals)) < 1e-14
    p = r2.precision_positions()
    assert np.allclose(np.abs(p["C"] - p["B"]), r2.b, atol=1e-12, rtol=0)
    assert r2.x == pytest.approx(chebyshev_points(1.0, 2.0, 2))


def test_given_points_and_uniform_spacing():
    ru = log10_design(spacing="uniform")
    assert ru.x == pytest.approx([1.0, 1.5, 2.0]) and ru.spacing == "uniform"
    rg = log10_design(points=np.array([1.1, 1.5, 1.9]))
    assert rg.spacing == "given" and rg.x == pytest.approx([1.1, 1.5, 1.9])


@pytest.mark.parametrize("name, x0, x1, words", [
    ("log10", 0.0, 2.0, "x > 0"), ("ln", -1.0, 1.0, "x > 0"), ("sqrt", -1.0, 0.5, "x ≥ 0"),
    ("reciprocal", -1.0, 1.0, "x = 0"), ("tan", 0.0, 2.0, "pole at x = 1.5708"),
    ("tan", 4.0, 5.0, "pole at x = 4.71239"),
])
def test_domains_refused_in_words(name, x0, x1, words):
    with pytest.raises(OutOfDomain, match=words):
        design(named_function(name), x0, x1, 0.0, D(60), 0.0, D(90))


def test_function_table_and_power():
    x = np.array([1.0, 2.0, 4.0])
    assert named_function("power", 0.5)(x) == pytest.approx(np.sqrt(x))
    assert named_function("cube")(x) == pytest.approx(x ** 3)
    assert named_function("reciprocal")(x) == pytest.approx(1 / x)
    assert set(FUNCTIONS) >= {"log10", "ln", "exp", "sqrt", "square", "cube", "reciprocal", "sin", "cos", "tan"}
    with pytest.raises(OutOfDomain, match="x ≥ 0"):
        design(named_function("power", 1.5), -1.0, 1.0, 0.0, 1.0, 0.0, 1.0)
    with pytest.raises(OutOfDomain, match="x = 0"):
        design(named_function("power", -2), -1.0, 1.0, 0.0, 1.0, 0.0, 1.0)
    with pytest.raises(OutOfDomain, match="x > 0"):
        design(named_function("power", -0.5), 0.0, 1.0, 0.0, 1.0, 0.0, 1.0)
    design(named_function("power", 3), -1.0, 1.0, 0.0, 1.0, 0.0, 1.0)  # x³ is fine through 0
    with pytest.raises(OutOfDomain, match="exponent"):
        named_function("power")
    with pytest.raises(OutOfDomain, match="no exponent"):
        named_function("sqrt", 2.0)
    with pytest.raises(OutOfDomain, match="no function 'x\\*\\*2'"):
        named_function("x**2")


@pytest.mark.parametrize("kw, words", [
    ({"dpsi": 0.0}, "Δψ = 0"), ({"dphi": 0.0}, "Δφ = 0"), ({"x1": 1.0}, "x₀ = x₁"),
    ({"d": 0.0}, "frame d"), ({"n": 6}, "2 … 5"), ({"n": 1}, "2 … 5"),
    ({"dphi": 1e-9}, "nearly\\) dependent"), ({"dpsi": math.nan}, "not finite"),
    ({"points": np.array([1.2, 1.2, 1.8])}, "coincide"),
    ({"points": np.array([0.5, 1.2, 1.8])}, "must lie in"),
])
def test_extremes_refused_in_words(kw, words):
    with pytest.raises(OutOfDomain, match=words):
        log10_design(**kw)


def test_small_swing_still_designed():
    r = log10_design(dphi=D(5), dpsi=D(5))  # well conditioned enough: a result, not a refusal
    assert r.condition < 1e8 and np.max(np.abs(r.residuals)) < 1e-12


def test_overflow_refused():
    with pytest.raises(OutOfDomain, match="exp is not finite at the ends"):
        design(named_function("exp"), 0.0, 1000.0, 0.0, 1.0, 0.0, 1.0)


def test_equal_ends_refused():
    with pytest.raises(OutOfDomain, match="f\\(x₀\\) = f\\(x₁\\)"):
        design(named_function("cos"), -1.0, 1.0, 0.0, 1.0, 0.0, 1.0)


def own_output(a, b, c, d, side):
    """ψ(φ) of the four-bar A = 0, D = (−d, 0): C on circle(B, b) ∩ circle(D, c), by the law of
    cosines in triangle B C D, written here apart from the library."""
    def psi(phi):
        B = a * np.exp(1j * phi)
        DB = B + d
        L = np.abs(DB)
        cos_g = (c * c + L * L - b * b) / (2 * c * L)  # the angle at D between DB and DC
        return np.angle(DB) + side * np.arccos(cos_g)
    return psi


def own_design(a, b, c, phi0, dphi, side):
    """The generator designed for the four-bar (a, b, c, d = 1)'s own ψ(φ) over φ₀ … φ₀ + Δφ (the
    input is its own x), where it assembles away from its toggles; hypothesis rejects the rest."""
    psi = own_output(a, b, c, 1.0, side)
    phis = phi0 + dphi * np.linspace(0, 1, 201)
    DB = np.abs(a * np.exp(1j * phis) + 1.0)
    assume(np.all(np.abs(c * c + DB * DB - b * b) < 0.95 * 2 * c * DB))  # assembles, away from toggles
    assume(np.min(DB) > 0.1)  # B well away from D: ψ defined (no change point)
    ref = float(psi(np.array(phi0))[()])
    f = Function("own", lambda x: ref + np.angle(np.exp(1j * (psi(x) - ref))))
    y0, y1 = f(np.array([phi0, phi0 + dphi]))
    assume(abs(y1 - y0) > 0.05)
    try:
        r = design(f, phi0, phi0 + dphi, phi0, dphi, y0, y1 - y0)
    except OutOfDomain:
        assume(False)
    assume(r.condition < 1e6)
    return r


#: The four-bars a generator is asked to reproduce: a, b, c, φ₀, Δφ, the branch's side.
OWN_FOURBARS = (st.floats(0.3, 3.0), st.floats(0.3, 3.0), st.floats(0.3, 3.0), st.floats(0.0, 2 * math.pi),
                st.floats(0.3, 1.5), st.sampled_from([1.0, -1.0]))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(*OWN_FOURBARS)
def test_a_four_bars_own_function_gives_back_its_lengths(a, b, c, phi0, dphi, side):
    r = own_design(a, b, c, phi0, dphi, side)
    assert (r.a, r.b, r.c) == pytest.approx((a, b, c), rel=1e-6)
    assert not r.input_reversed and not r.output_reversed
