"""The Wittenbauer diagram and the energy indicator (the whole design: tests/methods/test_flywheel.py)."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.methods.wittenbauer import energy_indicator, flywheel_inertia, tangent_slopes, wittenbauer
from graphmech.tolerances import SHALLOW_DEG

TAU = 2.0 * math.pi


def positions(n: int, cycle: float = TAU) -> np.ndarray:
    return np.arange(n) * cycle / n


# ----------------------------------------------------------------------------- the tangents
def test_tangent_slopes_exact_and_book_readings():
    c = 0.002 * 100.0 ** 2 / (2 * 10.0)
    assert tangent_slopes(100.0, 0.04, 0.002, 10.0, "exact") == pytest.approx((c * 1.02 ** 2, c * 0.98 ** 2))
    assert tangent_slopes(100.0, 0.04, 0.002, 10.0, "book") == pytest.approx((c * 1.04, c * 0.96))
    # both readings differ by μJ·ω_m²·δ/μT: J_F = μT·kl/(ω_m²δ) holds for either
    for form in ("exact", "book"):
        hi, lo = tangent_slopes(100.0, 0.04, 0.002, 10.0, form)
        assert hi - lo == pytest.approx(0.002 * 100.0 ** 2 * 0.04 / 10.0, rel=1e-13)


def test_course_project_tangents_and_flywheel(problems):
    p = problems["fly.wittenbauer_course_project"]
    i, ex, book = p["inputs"], p["exact"], p["book"]
    hi, lo = tangent_slopes(i["omega1_rad_s"], i["delta"], i["muJ_kgm2_per_mm"], i["muT_J_per_mm"], "book")
    assert (hi, lo) == pytest.approx((ex["tan_psi_max"], ex["tan_psi_min"]), rel=1e-12)
    assert math.degrees(math.atan(hi)) == pytest.approx(book["psi_max_deg"], abs=0.05)
    J = flywheel_inertia(i["kl_mm"], i["muT_J_per_mm"], i["omega1_rad_s"], i["delta"])
    assert J == pytest.approx(ex["JM_kgm2"], rel=1e-12) and J == pytest.approx(book["JM_kgm2"], abs=0.05)


@pytest.mark.parametrize("args", [(0.0, 0.1, 1.0, 1.0, "exact"), (10.0, 0.0, 1.0, 1.0, "exact"),
                                  (10.0, 2.0, 1.0, 1.0, "exact"), (10.0, 1.0, 1.0, 1.0, "book"),
                                  (10.0, 0.1, 0.0, 1.0, "exact"), (10.0, 0.1, 1.0, 1.0, "neither")])
def test_tangent_slopes_refuse_what_has_no_tangents(args):
    with pytest.raises(ValueError):
        tangent_slopes(*args)


# ----------------------------------------------------------------------------- the diagram
def brute_force(x, y, tmax, tmin):
    """k and l by trying every point's line, one at a time."""
    ks = [yi - xi * tmax for xi, yi in zip(x, y)]
    ls = [yi - xi * tmin for xi, yi in zip(x, y)]
    return max(ks), ks.index(max(ks)), min(ls), ls.index(min(ls))


def test_the_tangents_touch_the_points_from_above_and_below():
    rng = np.random.default_rng(7)
    x, y = rng.uniform(20.0, 50.0, 40), rng.uniform(-10.0, 30.0, 40)
    w = wittenbauer(x, y, 0.7, 0.5)
    k, ki, l, li = brute_force(x, y, 0.7, 0.5)
    assert (w.k_mm, w.k_index, w.l_mm, w.l_index) == (k, ki, l, li)
    assert np.all(y <= w.k_mm + 0.7 * x + 1e-12) and np.all(y >= w.l_mm + 0.5 * x - 1e-12)
    assert y[ki] == pytest.approx(w.k_mm + 0.7 * x[ki]) and y[li] == pytest.approx(w.l_mm + 0.5 * x[li])
    assert w.kl_mm == w.k_mm - w.l_mm
    xs, ys = w.intersection
    assert ys == pytest.approx(w.k_mm + 0.7 * xs) and ys == pytest.approx(w.l_mm + 0.5 * xs)
    assert w.angle_between_deg == pytest.approx(math.degrees(math.atan(0.7) - math.atan(0.5)))
    assert w.psi_max_deg == pytest.approx(math.degrees(math.atan(0.7)))


def test_a_machine_with_a_known_flywheel_gives_it_back():
    """Points from T = (J_F + Jп)·ω²/2 with ω within [ω_min, ω_max], reaching both: the tangents meet at the
    true origin O′ = (−J_F/μJ, −T₀/μT) and kl gives J_F."""
    rng = np.random.default_rng(3)
    wm, delta, JF, mu_J, mu_T = 60.0, 0.05, 2.0, 0.01, 20.0
    wmax, wmin = wm * (1 + delta / 2), wm * (1 - delta / 2)
    J = rng.uniform(0.3, 0.6, 30)
    omega = rng.uniform(wmin, wmax, 30)
    omega[4], omega[17] = wmax, wmin
    T = (JF + J) * omega ** 2 / 2.0
    T0 = T[0]
    w = wittenbauer(J / mu_J, (T - T0) / mu_T, *tangent_slopes(wm, delta, mu_J, mu_T, "exact"))
    assert (w.k_index, w.l_index) == (4, 17)
    assert flywheel_inertia(w.kl_mm, mu_T, wm, delta) == pytest.approx(JF, rel=1e-12)
    assert w.intersection == pytest.approx((-JF / mu_J, -T0 / mu_T), rel=1e-9)


def test_tiny_delta_almost_parallel_tangents_are_flagged_but_k_and_l_stay_sharp():
    rng = np.random.default_rng(5)
    x, y = rng.uniform(20.0, 50.0, 24), rng.uniform(-10.0, 30.0, 24)
    hi, lo = tangent_slopes(100.0, 1e-6, 0.002, 10.0)
    w = wittenbauer(x, y, hi, lo)
    assert w.ill_conditioned and w.angle_between_deg < SHALLOW_DEG
    assert abs(w.intersection[0]) > 1e6  # far off the sheet
    k, _, l, _ = brute_force(x, y, hi, lo)
    assert (w.k_mm, w.l_mm) == (k, l)
    assert not wittenbauer(x, y, 1.0, 0.5).ill_conditioned


def test_the_diagram_is_frozen_and_refuses_tangents_that_do_not_diverge():
    w = wittenbauer([1.0, 2.0], [0.0, 1.0], 1.0, 0.5)
    with pytest.raises(dataclasses.FrozenInstanceError):
        w.k_mm = 0.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        w.x_mm[0] = 3.0
    with pytest.raises(ValueError):
        wittenbauer([1.0, 2.0], [0.0, 1.0], 0.5, 0.5)
    with pytest.raises(ValueError):
        wittenbauer([1.0, 2.0], [0.0], 1.0, 0.5)


# ----------------------------------------------------------------------------- the energy indicator
def test_energy_indicator_chain_closes_and_alternates():
    t = np.array([0.0, 4.0, 9.0, 9.0, 7.0, 1.0, -3.0, -1.0, 2.0, 5.0, 3.0, 1.5])
    e = energy_indicator(t)
    assert e.vertices.tolist() == [0, 2, 6, 9, 12]  # the plateau 9, 9 is one maximum
    assert e.levels_mm.tolist() == [0.0, 9.0, -3.0, 5.0, 0.0]
    assert e.vectors_mm.tolist() == [9.0, -12.0, 8.0, -5.0]
    assert sum(e.vectors_mm) == 0.0  # back to a′ on a's level
    assert np.all(np.sign(e.vectors_mm[1:]) == -np.sign(e.vectors_mm[:-1]))
    assert (e.highest, e.lowest, e.dW_max_mm) == (1, 2, 12.0)


def test_energy_indicator_start_inside_a_run_and_rounding_noise():
    # the cycle starts on a rising run that ends the cycle too: first and last vectors point the same way
    t = np.array([0.0, 2.0, 1.0, -1.0, -2.0]) + 1e-17 * np.array([0, 1, -1, 1, 0])
    e = energy_indicator(t)
    assert e.vertices.tolist() == [0, 1, 4, 5] and np.sign(e.vectors_mm).tolist() == [1, -1, 1]
    flat = energy_indicator(np.array([1.0, 1.0 + 1e-15, 1.0 - 1e-15]))  # rounding, not work
    assert flat.vertices.tolist() == [0, 3] and flat.dW_max_mm < 1e-14
