"""The Wittenbauer diagram, the energy indicator and the whole graphical flywheel design."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.methods.flywheel import design_flywheel
from graphmech.methods.wittenbauer import energy_indicator, flywheel_inertia, tangent_slopes, wittenbauer
from graphmech.scales import round_scale
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


# ----------------------------------------------------------------------------- the design
def sine_machine(n: int, J=None, **kw):
    phi = positions(n)
    J = np.full(n, 0.8) if J is None else J(phi)
    M = -40.0 + 100.0 * np.sin(phi)
    kw.setdefault("need", ("wittenbauer", "indicator"))
    return design_flywheel(phi, J, M, cycle=TAU, omega_m=50.0, delta=0.02, **kw)


def test_constant_inertia_wittenbauer_equals_the_energy_indicator():
    for n in (12, 36, 360):
        d = sine_machine(n)
        assert d.J_mean == pytest.approx(0.8, rel=1e-15)
        assert d.J_F == pytest.approx(d.J_F_indicator, rel=1e-12)
        assert d.wittenbauer.kl_mm * d.scales["T"] == pytest.approx(
            d.DeltaW_max - 0.8 * 50.0 ** 2 * 0.02, rel=1e-12)


def test_varying_inertia_the_two_methods_differ():
    d = sine_machine(36, J=lambda p: 0.8 + 0.3 * np.cos(p) ** 2)
    assert abs(d.J_F - d.J_F_indicator) > 1e-3 * abs(d.J_F)


def test_sinusoidal_moment_converges_at_second_order():
    """M = −40 + 100 sin φ, Jп constant: ΔT(φ) = 100(1 − cos φ), ΔW_max = 200 J; chords err by O(h²)."""
    err_T, err_W = [], []
    ns = (16, 32, 64, 128, 256)
    for n in ns:
        d = sine_machine(n)
        assert d.balancing_moment == pytest.approx(40.0, rel=1e-12)
        err_T.append(np.max(np.abs(d.dT - 100.0 * (1.0 - np.cos(d.phi)))))
        err_W.append(abs(d.DeltaW_max - 200.0))
        assert (d.energy_max_index, d.energy_min_index) == (n // 2, 0)
    for err in (err_T, err_W):
        orders = np.log2(np.array(err[:-1]) / np.array(err[1:]))
        np.testing.assert_allclose(orders, 2.0, atol=0.05)


def test_compressor_twelve_positions_match_the_reference(problems):
    """fly.compressor_course_project: ΔT and Md by chords at the 12 positions, and J_F from them."""
    ex = problems["fly.compressor_course_project"]["exact"]
    d = design_flywheel(np.radians(ex["positions_phi_deg"]), ex["Jp_kgm2"], ex["Mp_Nm"], cycle=TAU,
                        omega_m=ex["omega_m_rad_s"], delta=0.04, need=("wittenbauer", "indicator"))
    assert d.balancing_moment == pytest.approx(ex["Md_12pos_trapz_Nm"], rel=1e-12)
    np.testing.assert_allclose(d.dT, ex["DeltaT_12pos_trapz_J"], rtol=1e-12, atol=1e-10)
    assert d.J_F == pytest.approx(ex["JF_12pos_trapz_kgm2"], rel=1e-12)
    assert d.J_mean == pytest.approx(np.mean(ex["Jp_kgm2"]), rel=1e-14)
    assert d.balancing_mm * d.scales["M"] == d.balancing_moment


def test_ic_engine_constant_resistance_over_half_a_turn(problems):
    """fly.ic_engine_flywheel: Md(φ) repeats every π, the resistance is constant, Jп = 0 (only the flywheel).
    At N = 216 the positions fall on the moment's breakpoints and on the ΔT extremes: chords are exact (to the
    reference's rounding, 1e-11)."""
    p = problems["fly.ic_engine_flywheel"]
    i, ex = p["inputs"], p["exact"]
    n = 216
    phi = positions(n, math.pi)
    M = np.interp(np.degrees(phi), i["Md_breakpoints_deg"], i["Md_breakpoints_Nm"])
    wm = i["nm_r_min"] * math.pi / 30.0
    d = design_flywheel(phi, np.zeros(n), M, cycle=math.pi, omega_m=wm, delta=i["delta"], balance="resisting",
                        need=("wittenbauer", "indicator"))
    assert d.balancing_moment == pytest.approx(-ex["Mr_Nm"], rel=1e-10)
    assert d.DeltaW_max == pytest.approx(ex["DeltaW_max_J"], rel=1e-10)
    assert d.J_F == pytest.approx(ex["JF_kgm2"], rel=1e-10)
    assert d.J_F_indicator == pytest.approx(ex["JF_kgm2"], rel=1e-10)
    assert math.degrees(d.phi[d.energy_max_index]) == pytest.approx(p["book"]["phi_max_deg"], abs=1e-9)
    assert math.degrees(d.phi[d.energy_min_index]) == pytest.approx(35 / 3, rel=1e-12)  # 11°40′
    assert math.degrees(d.phi[d.energy_min_index]) == pytest.approx(ex["phi_min_deg"], abs=0.5e-4)  # printed to 4 decimals
    assert d.wittenbauer.k_index == d.energy_max_index  # Jп = 0: ω_max where ΔT is largest


def test_chosen_scales_are_round_and_fit_the_panels():
    d = sine_machine(24, J=lambda p: 0.8 + 0.3 * np.cos(p) ** 2)
    s = d.scales
    assert math.degrees(s["phi"]) == round_scale(math.degrees(s["phi"])) and TAU / s["phi"] <= 150.0
    assert s["M"] == round_scale(s["M"]) and 140.0 / s["M"] <= 60.0
    assert s["J"] == round_scale(s["J"]) and d.inertia_mm.max() <= 60.0
    assert s["T"] == pytest.approx(s["M"] * s["phi"] * d.H_mm, rel=1e-15)
    spread = np.concatenate([d.work_mm, d.balance_work_mm, [0.0]])
    assert spread.max() - spread.min() <= 60.0
    assert d.sources["phi"] == d.sources["M"] == d.sources["J"] == "chosen" and d.sources["T"] == "μM·μφ·H"


def test_given_scales_and_pole_distance():
    d = sine_machine(12, scales={"M": 2.0, "phi": math.radians(3.0)}, H_mm=25.0)
    assert d.H_mm == 25.0 and d.scales["T"] == pytest.approx(2.0 * math.radians(3.0) * 25.0)
    assert d.sources["H"] == "given" and d.sources["M"] == "given"
    d = sine_machine(12, scales={"M": 2.0, "phi": math.radians(3.0), "T": 5.0})  # H from μT
    assert d.H_mm == pytest.approx(5.0 / (2.0 * math.radians(3.0))) and d.sources["H"] == "μT/(μM·μφ)"
    assert d.balancing_mm * 2.0 == pytest.approx(40.0)
    with pytest.raises(ValueError, match="contradicts"):
        sine_machine(12, scales={"M": 2.0, "phi": math.radians(3.0), "T": 5.0}, H_mm=25.0)
    with pytest.raises(ValueError, match="unknown scale"):
        sine_machine(12, scales={"v": 1.0})


def test_only_what_is_needed_is_computed():
    d = sine_machine(12, need=())
    assert d.wittenbauer is None and d.J_F is None and d.indicator is None and d.DeltaW_max is None
    assert d.energy_mm.shape == (13,) and d.energy_mm[0] == 0.0 and d.energy_mm[-1] == 0.0
    d = sine_machine(12, need=("indicator",))
    assert d.wittenbauer is None and d.indicator is not None
    with pytest.raises(ValueError):
        sine_machine(12, need=("flywheel",))


def test_the_constant_moment_must_have_the_sign_its_role_gives_it():
    phi = positions(12)
    with pytest.raises(ValueError, match="driving"):
        design_flywheel(phi, np.ones(12), 10.0 + np.sin(phi), cycle=TAU, omega_m=10.0, delta=0.05)
    d = design_flywheel(phi, np.ones(12), 10.0 + np.sin(phi), cycle=TAU, omega_m=10.0, delta=0.05,
                        balance="resisting")
    assert d.balancing_moment == pytest.approx(-10.0)
    with pytest.raises(ValueError, match="resist"):
        design_flywheel(phi, np.ones(12), -10.0 + np.sin(phi), cycle=TAU, omega_m=10.0, delta=0.05,
                        balance="resisting")
    # a zero net work (sin over a whole cycle) rounds either way and is not refused
    assert abs(design_flywheel(phi, np.ones(12), np.sin(phi), cycle=TAU, omega_m=10.0,
                               delta=0.05).balancing_moment) < 1e-12


@pytest.mark.parametrize("phi, J, M", [
    (np.arange(12) * 0.5 + 0.1, np.ones(12), np.zeros(12)),  # position 1 not at φ = 0
    (np.arange(12) * 0.6, np.ones(12), np.zeros(12)),        # past the cycle
    (np.zeros(12), np.ones(12), np.zeros(12)),               # not increasing
    (positions(12), -np.ones(12), np.zeros(12)),             # negative inertia
    (positions(12), np.ones(11), np.zeros(12)),              # lengths differ
    (positions(12), np.ones(12), np.full(12, np.nan)),       # not finite
])
def test_bad_data_is_refused(phi, J, M):
    with pytest.raises(ValueError):
        design_flywheel(phi, J, M, cycle=TAU, omega_m=10.0, delta=0.05)


def test_the_design_is_frozen_with_read_only_arrays():
    d = sine_machine(12)
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.J_F = 0.0  # type: ignore[misc]
    for a in (d.phi, d.energy_mm, d.work_mm, d.balance_work_mm, d.dT, d.inertia_mm):
        with pytest.raises(ValueError):
            a[0] = 1.0
    with pytest.raises(TypeError):
        d.scales["T"] = 1.0  # type: ignore[index]


def test_thousands_of_positions():
    d = sine_machine(3600, J=lambda p: 0.8 + 0.3 * np.cos(p) ** 2)
    assert d.n == 3600 and d.energy_mm.shape == (3601,)
    assert d.DeltaW_max == pytest.approx(200.0, rel=1e-6)
