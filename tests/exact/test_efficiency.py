"""graphmech.exact.efficiency: the textbook's closed forms of the incline, the screw, the wedge and
chains of machines, checked against the equilibrium they come from and the book's values."""
from __future__ import annotations

import math

import pytest

from graphmech.exact import efficiency as ex


@pytest.mark.parametrize("alpha_deg, f", [(10.0, 0.1), (30.0, 0.2), (60.0, 0.05)])
def test_incline_forces_balance_the_block(alpha_deg, f):
    """Q down, F, the normal N and friction f·N against the motion: the two equations of equilibrium."""
    Q, a, phi = 1000.0, math.radians(alpha_deg), math.atan(f)
    s, c = math.sin(a), math.cos(a)
    # horizontal F raising the block: N·(cos α − f sin α) = Q, F = N·(sin α + f cos α)
    N = Q / (c - f * s)
    assert ex.incline_force(Q, a, phi, "forward") == pytest.approx(N * (s + f * c), rel=1e-12)
    assert ex.incline_reaction(Q, a, phi, "forward") == pytest.approx(N * math.hypot(1.0, f), rel=1e-12)
    # F along the incline: N = Q cos α; F = Q sin α ± f N
    assert ex.incline_force(Q, a, phi, "forward", "parallel") == pytest.approx(Q * (s + f * c), rel=1e-12)
    assert ex.incline_force(Q, a, phi, "reverse", "parallel") == pytest.approx(Q * (s - f * c), rel=1e-12)
    assert ex.incline_reaction(Q, a, phi, "reverse", "parallel") == pytest.approx(Q * c * math.hypot(1.0, f),
                                                                                  rel=1e-12)


@pytest.mark.parametrize("push", ["horizontal", "parallel"])
def test_incline_efficiency_is_the_ideal_over_the_actual_force(push):
    Q, a, phi = 500.0, math.radians(25.0), math.atan(0.15)
    F0 = ex.incline_force(Q, a, 0.0, "forward", push)
    assert F0 == pytest.approx(ex.incline_force(Q, a, 0.0, "reverse", push), rel=1e-15)
    for d in ("forward", "reverse"):
        F = ex.incline_force(Q, a, phi, d, push)
        assert ex.incline_efficiency(a, phi, d, push) == pytest.approx(ex.efficiency(d, F0, F), rel=1e-13)
    assert ex.incline_efficiency(a, 0.0, "forward", push) == pytest.approx(1.0, rel=1e-15)


def test_an_incline_self_locks_at_and_below_the_friction_angle():
    phi = math.atan(0.2)
    assert ex.incline_efficiency(phi, phi, "reverse") == 0.0
    assert ex.incline_force(100.0, phi, phi, "reverse") == 0.0
    below = math.radians(5.0)
    assert ex.incline_efficiency(below, phi, "reverse") < 0 and ex.incline_force(100.0, below, phi, "reverse") < 0
    assert 0 < ex.incline_efficiency(below, phi, "forward") < 0.5  # a self-locking incline wastes over half


def test_screw_of_an_m20_thread():
    """M20 coarse: d2 = 18.376 mm, P = 2.5 mm, ψ = 2.48°; f = 0.1, β = 30°: φv = 6.59° > ψ, self-locking."""
    psi = ex.lead_angle(2.5e-3, 18.376e-3)
    phi_v = ex.equivalent_friction_angle(0.1, math.radians(30.0))
    assert math.degrees(psi) == pytest.approx(2.4796508, rel=1e-7)
    assert math.tan(phi_v) == pytest.approx(0.1 / math.cos(math.radians(30.0)), rel=1e-15)
    assert ex.equivalent_friction_angle(0.1) == pytest.approx(math.atan(0.1), rel=1e-15)  # square thread
    eta = ex.screw_efficiency(psi, phi_v, "forward")
    assert eta == pytest.approx(math.tan(psi) / math.tan(psi + phi_v), rel=1e-15)
    assert eta < ex.self_locking_efficiency_bound(phi_v) < 0.5
    assert ex.screw_efficiency(psi, phi_v, "reverse") < 0
    M = ex.screw_torque(10000.0, 18.376e-3, psi, phi_v, "forward")
    assert M == pytest.approx(10000.0 * 0.018376 / 2 * math.tan(psi + phi_v), rel=1e-15)
    assert M * eta == pytest.approx(ex.screw_torque(10000.0, 18.376e-3, psi, 0.0, "forward"), rel=1e-12)
    assert ex.screw_torque(10000.0, 18.376e-3, psi, phi_v, "reverse") < 0  # it must be turned back


def test_the_self_locking_bound_is_the_efficiency_at_psi_equal_phi_v():
    for phi_v in (0.01, 0.1, 0.3, 0.7):
        assert ex.self_locking_efficiency_bound(phi_v) == pytest.approx(
            ex.screw_efficiency(phi_v, phi_v, "forward"), rel=1e-12)
    assert ex.self_locking_efficiency_bound(1e-9) == pytest.approx(0.5, rel=1e-15)


def test_wedge_F1430_and_the_books_formulas():
    g, b, phi = math.radians(60.0), math.radians(60.0), math.atan(0.15)
    w = ex.wedge_forces(1000.0, g, b, phi, "forward")
    assert w.F == pytest.approx(1430.7004224765801, rel=1e-12)
    # γ + β > 90°: F = Q sin(γ + β − 2φ)/sin(γ − 2φ)
    assert w.F == pytest.approx(1000.0 * math.sin(g + b - 2 * phi) / math.sin(g - 2 * phi), rel=1e-12)
    # γ + β < 90°: guide 1 bears on the other side: F = Q sin(γ + β)/sin(γ − 2φ)
    g2, b2 = math.radians(50.0), math.radians(20.0)
    assert ex.wedge_forces(1000.0, g2, b2, phi, "forward").F == pytest.approx(
        1000.0 * math.sin(g2 + b2) / math.sin(g2 - 2 * phi), rel=1e-12)
    # without friction both strokes need the ideal force
    for d in ("forward", "reverse"):
        assert ex.wedge_forces(1000.0, g, b, 0.0, d).F == pytest.approx(ex.wedge_ideal_force(1000.0, g, b), rel=1e-13)
    assert ex.wedge_ideal_force(1000.0, g, b) == pytest.approx(1000.0 * math.sin(g + b) / math.sin(g), rel=1e-15)


def test_wedge_forces_are_a_closed_triangle_on_slider_2():
    """Q, R32 and R12 on slider 2 at their directions (180°, 90° + φ, γ − 90° − φ) sum to zero."""
    g, b, phi, Q = math.radians(60.0), math.radians(60.0), math.atan(0.15), 1000.0
    w = ex.wedge_forces(Q, g, b, phi, "forward")
    total = Q * complex(-1.0, 0.0) + w.R32 * complex(math.cos(math.pi / 2 + phi), math.sin(math.pi / 2 + phi)) \
        + w.R12 * complex(math.cos(g - math.pi / 2 - phi), math.sin(g - math.pi / 2 - phi))
    assert abs(total) < 1e-9


def test_chains_in_series_and_in_parallel():
    assert ex.series_efficiency([0.95, 0.97, 0.97, 0.9]) == pytest.approx(0.8044695, rel=1e-12)
    assert ex.series_efficiency([]) == 1.0
    assert ex.parallel_efficiency([3.0, 1.0], [0.9, 0.8]) == pytest.approx(0.875, rel=1e-15)
    assert ex.parallel_efficiency([1.0, 2.0, 5.0], [0.7, 0.7, 0.7]) == pytest.approx(0.7, rel=1e-15)
    assert ex.efficiency("forward", 80.0, 100.0) == 0.8 and ex.efficiency("reverse", 100.0, 80.0) == 0.8


def test_an_unknown_direction_is_refused():
    for call in (lambda: ex.incline_force(1.0, 0.3, 0.1, "up"), lambda: ex.incline_reaction(1.0, 0.3, 0.1, "down"),
                 lambda: ex.screw_torque(1.0, 0.01, 0.05, 0.1, "back"),
                 lambda: ex.wedge_forces(1.0, 1.0, 1.0, 0.1, "in")):
        with pytest.raises(ValueError, match="'forward' or 'reverse'"):
            call()


# ---------------------------------------------------------------------------- issue 22: clamp, buffer, collar, drive



def test_wedge_clamp_closed_form_is_the_books_with_two_angles():
    a, p1, p2 = math.radians(12), math.atan(0.15), math.atan(0.15)
    # 000 效率 2: R23 = P·cos φ/sin(α − 2φ) → P = R23·sin(α − 2φ)/cos φ
    assert ex.wedge_clamp_force(1000.0, a, p1, p2, "reverse") == pytest.approx(
        1000.0 * math.sin(a - 2 * p1) / math.cos(p1), rel=1e-15)
    assert ex.wedge_clamp_force(1000.0, a, 0.0, 0.0, "forward") == pytest.approx(1000.0 * math.sin(a), rel=1e-15)
    assert ex.wedge_clamp_reaction(1000.0, a, 0.0, 0.0, "reverse") == pytest.approx(1000.0 * math.cos(a), rel=1e-15)
    assert ex.wedge_clamp_locking(0.1, 0.2) == pytest.approx(0.3, rel=1e-15)


def test_buffer_closed_forms_and_both_limits():
    a, phi = math.radians(40), math.radians(10)
    assert ex.buffer_force(1.0, a, phi, "forward") == pytest.approx(1.0 / math.tan(math.radians(30)), rel=1e-15)
    assert ex.buffer_force(1.0, a, phi, "reverse") == pytest.approx(1.0 / math.tan(math.radians(50)), rel=1e-15)
    assert ex.buffer_reaction(2.0, a, phi, "forward") == pytest.approx(2.0 / math.sin(math.radians(30)), rel=1e-15)
    assert [math.degrees(x) for x in ex.buffer_locking(phi)] == pytest.approx([10.0, 80.0], rel=1e-14)
    assert ex.buffer_locking_coefficients(math.radians(30)) == pytest.approx((3 ** -0.5, 3 ** 0.5), rel=1e-14)


def test_collar_radius_bolt_force_and_drive_power():
    # annulus d0 = 9, dw = 11.5 mm: (11.5³ − 9³)/(3(11.5² − 9²)) = 791.875/153.75 mm
    assert ex.annulus_friction_radius(9e-3, 11.5e-3) == pytest.approx(791.875 / 153.75e3, rel=1e-14)
    psi, phv = math.atan(1.25e-3 / (math.pi * 7.188e-3)), math.atan(0.1)
    T = ex.tightening_torque(25500.0, 7.188e-3, psi, phv, 0.12, 5.125e-3)
    assert ex.bolt_force_from_torque(T, 7.188e-3, psi, phv, 0.12, 5.125e-3) == pytest.approx(25500.0, rel=1e-14)
    assert T == pytest.approx(29.9995, abs=1e-4)
    # 10-4: P = Q·v/η equals T·ω
    psi = math.atan(0.04 / (math.pi * 0.065))
    T = 1e5 * 0.065 / 2 * math.tan(psi + phv)
    assert ex.screw_drive_power(1e5, 0.8 / 60, psi, phv) == pytest.approx(T * 2 * math.pi * 20 / 60, rel=1e-14)
    assert ex.screw_speed(0.8 / 60, 0.04) == pytest.approx(1 / 3, rel=1e-15)
