"""The whole graphical flywheel design (methods/flywheel.py): scales, integration by chords, the
balancing moment, ΔT, and J_F by the Wittenbauer diagram and by the energy indicator."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.errors import OutOfDomain
from graphmech.methods.flywheel import (
    CYCLE_MM,
    H_STEP,
    HEIGHT_MM,
    WrongBalance,
    design_flywheel,
)
from graphmech.scales import round_scale

TAU = 2.0 * math.pi


def positions(n: int, cycle: float = TAU) -> np.ndarray:
    return np.arange(n) * cycle / n


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
    with pytest.raises(OutOfDomain, match="^need may hold wittenbauer and indicator, not 'flywheel'$"):
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


@pytest.mark.parametrize("phi, J, M, message", [
    (np.arange(12) * 0.5 + 0.1, np.ones(12), np.zeros(12), r"phi\[0\] must be 0, not 0\.1$"),  # position 1 not at φ = 0
    (np.arange(12) * 0.6, np.ones(12), np.zeros(12), "must increase strictly within one cycle"),  # past the cycle
    (np.zeros(12), np.ones(12), np.zeros(12), "must increase strictly within one cycle"),  # not increasing
    (positions(12), -np.ones(12), np.zeros(12), "inertia cannot be negative"),
    (positions(12), np.ones(11), np.zeros(12), r"got shapes \(12,\), \(11,\), \(12,\)"),  # lengths differ
    (positions(12), np.ones(12), np.full(12, np.nan), "must be finite"),
])
def test_bad_data_is_refused(phi, J, M, message):
    with pytest.raises(OutOfDomain, match=message):
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


# ----------------------------------------------------------------------------- closed forms and refusals
def test_the_docstring_machine_chooses_the_pole_distance_that_fits():
    """M = −50 + 100 sin φ, Jп = 0.5: the driving moment is 50 N·m; H = 40 mm would draw A(φ) over
    HEIGHT_MM, so H is raised to the smallest multiple of H_STEP that fits."""
    phi = positions(12)
    d = design_flywheel(phi, np.full(12, 0.5), -50.0 + 100.0 * np.sin(phi), cycle=TAU, omega_m=100.0,
                        delta=0.02, need=("wittenbauer", "indicator"))
    assert d.balancing_moment == pytest.approx(50.0, rel=1e-12)
    assert (d.H_mm, d.sources["H"]) == (50.0, "chosen") and d.H_mm % H_STEP == 0.0
    spread = max(np.ptp(np.concatenate([d.work_mm, d.balance_work_mm, [0.0]])), np.ptp(d.energy_mm))
    assert spread <= HEIGHT_MM < spread * d.H_mm / (d.H_mm - H_STEP)  # one step lower would overflow
    assert d.J_F == pytest.approx(d.J_F_indicator, rel=1e-12)


def test_a_constant_moment_needs_no_flywheel():
    """Mп ≡ −25 N·m is balanced by Mд = 25 N·m exactly: ΔT ≡ 0, ΔW_max = 0, and J_F = −J_mean by
    either method (the machine's own inertia already more than suffices)."""
    d = design_flywheel(positions(12), np.full(12, 0.3), np.full(12, -25.0), cycle=TAU, omega_m=10.0,
                        delta=0.05, need=("wittenbauer", "indicator"))
    assert d.balancing_moment == pytest.approx(25.0, rel=1e-14)
    assert np.abs(d.dT).max() < 1e-12 and d.DeltaW_max < 1e-12
    assert d.J_F == pytest.approx(-0.3, rel=1e-12) and d.J_F_indicator == pytest.approx(-0.3, rel=1e-12)


def test_wrong_balance_carries_the_loads_work_over_the_cycle():
    """M = ±10 + sin φ over a turn: Aп(Φ) = ±20π J (the sine's chords cancel)."""
    phi = positions(12)
    with pytest.raises(WrongBalance) as info:
        design_flywheel(phi, np.ones(12), 10.0 + np.sin(phi), cycle=TAU, omega_m=10.0, delta=0.05)
    assert isinstance(info.value, ValueError)
    assert info.value.work == pytest.approx(20.0 * math.pi, rel=1e-12)
    assert "Aп(Φ) = 62.8319 J > 0" in str(info.value)
    with pytest.raises(WrongBalance) as info:
        design_flywheel(phi, np.ones(12), -10.0 + np.sin(phi), cycle=TAU, omega_m=10.0, delta=0.05,
                        balance="resisting")
    assert info.value.work == pytest.approx(-20.0 * math.pi, rel=1e-12)


@pytest.mark.parametrize("kw, message", [
    ({"cycle": 0.0}, "the cycle Φ must be positive and finite, not 0.0"),
    ({"omega_m": -10.0}, "ω_m must be positive and finite, not -10.0"),
    ({"delta": math.nan}, "δ must be positive and finite, not nan"),
    ({"delta": "1/25"}, "δ must be a number, not '1/25'"),
    ({"balance": "both"}, "balance must be 'driving' or 'resisting', not 'both'"),
    ({"form": "approximate"}, "form must be 'exact' or 'book', not 'approximate'"),
    ({"H_mm": 0.0}, "the pole distance H must be positive and finite, not 0.0"),
    ({"scales": {"M": -1.0}}, "the scale μM must be positive and finite, not -1.0"),
])
def test_each_parameter_is_refused_by_name(kw, message):
    args = {"cycle": TAU, "omega_m": 10.0, "delta": 0.05, **kw}
    with pytest.raises(OutOfDomain) as info:
        design_flywheel(positions(12), np.ones(12), np.sin(positions(12)), **args)
    assert str(info.value) == message


def test_half_a_turn_without_inertia_chooses_mu_phi_and_mu_J_from_the_cycle_and_mu_T():
    """Φ = π: μφ the round °/mm that keeps 180° within CYCLE_MM; Jп ≡ 0 leaves μJ to 2μT/ω_m²."""
    phi = positions(24, math.pi)
    d = design_flywheel(phi, np.zeros(24), 200.0 * np.sin(2 * phi) ** 2, cycle=math.pi, omega_m=60.0,
                        delta=0.02, balance="resisting")
    assert d.scales["phi"] == math.radians(round_scale(180.0 / CYCLE_MM)) == math.radians(2.0)
    assert d.scales["J"] == round_scale(2.0 * d.scales["T"] / 60.0 ** 2)
    assert d.balancing_moment == pytest.approx(-100.0, rel=1e-12)  # the mean of 200 sin² 2φ
    assert d.J_mean == 0.0 and np.all(d.inertia_mm == 0.0)
