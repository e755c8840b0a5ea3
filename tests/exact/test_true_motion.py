"""The true motion by scipy's integrators (exact/true_motion.py) against the energy equation and
fly.compressor_course_project; the stiff motor; explicit solvers' step counts; errors."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.problems.flywheel.bench import compressor_machine
from graphmech.exact.flywheel import ExactMachine
from graphmech.exact.true_motion import (
    TrueMotion,
    TrueMotionError,
    braking_time,
    integrate,
    true_motion,
)
from graphmech.mechanisms.machine import CrankMoment, Machine, Motor, Table

DEG = math.pi / 180.0


@pytest.fixture(scope="module")
def comp() -> tuple[Machine, ExactMachine, float]:
    m = compressor_machine()
    ex = ExactMachine(m)
    return m, ex, ex.wittenbauer("exact").J_F


@pytest.fixture(scope="module")
def ref(problems) -> dict:
    return problems["fly.compressor_course_project"]["exact"]


@pytest.fixture(scope="module")
def stiff(comp) -> TrueMotion:
    m, ex, jf = comp
    return true_motion(dataclasses.replace(m, motor=Motor(stiffness=1e5)), ex, jf, rtol=1e-12)


def stepped(delta: float, inertia: float = 0.0) -> Machine:
    """No linkage (Jп constant): a resisting moment with a step at 2 rad and a kink at 4 rad."""
    md = Table((0.0, 2.0, 2.0, 4.0, 2 * math.pi), (-50.0, -50.0, -400.0, -200.0, -200.0))
    return Machine(None, 0.0, 2 * math.pi, 100.0, delta, loads=(CrankMoment(md),), inertia=inertia)


# --------------------------------------------------------------------------------------------
# Constant driving moment


def test_compressor_constant_moment(comp, ref):
    m, ex, jf = comp
    tm = true_motion(m, ex, jf, rtol=1e-10)
    assert abs(tm.delta / 0.04 - 1) <= 1e-8
    assert abs(tm.omega_max / ref["omega_max_ode_rad_s"] - 1) <= 1e-9
    assert abs(tm.omega_min / ref["omega_min_ode_rad_s"] - 1) <= 1e-9
    assert abs(tm.period / ref["cycle_period_s"] - 1) <= 1e-9
    assert abs(tm.omega_time_mean / ref["omega_time_mean_rad_s"] - 1) <= 1e-9
    assert abs(tm.omega_phi_mean / ref["omega_phi_mean_rad_s"] - 1) <= 1e-9
    assert abs(0.5 * (tm.omega_max + tm.omega_min) - m.omega_m) <= 1e-10 * m.omega_m
    # flat extremes: the angle is good to far less than the value
    assert abs(tm.phi_omega_max / DEG - ref["phi_omega_max_deg"]) < 1e-3
    assert abs(tm.phi_omega_min / DEG - ref["phi_l_deg"]) < 1e-3
    assert tm.omega_s is None and tm.solver == "Radau" and tm.steps > 0 and tm.njev > 0


def test_ode_agrees_with_energy_equation_better_as_rtol_falls(comp):
    m, ex, jf = comp
    d_energy = ex.energy_motion(jf).delta
    errs = []
    for rtol in (1e-6, 1e-8, 1e-10):
        tm = true_motion(m, ex, jf, rtol=rtol)
        errs.append(abs(tm.delta / d_energy - 1))
        assert errs[-1] <= 100 * rtol
    assert errs[-1] < errs[0]


@pytest.mark.parametrize("delta", [0.5, 1e-4])
def test_load_with_a_step(delta):
    m = stepped(delta, inertia=0.2)
    ex = ExactMachine(m)
    assert 2.0 in ex.breaks().tolist()
    jf = ex.wittenbauer().J_F
    mo = ex.energy_motion(jf)
    assert abs(mo.delta / delta - 1) < 1e-12
    for solver in ("Radau", "LSODA"):
        tm = true_motion(m, ex, jf, solver=solver, rtol=1e-10)
        assert abs(tm.delta / mo.delta - 1) <= 1e-7, solver
        assert abs(tm.omega_max / mo.omega_max - 1) <= 1e-9
        # the minimum sits on the step (ΔT has a corner there): found exactly
        assert abs(tm.phi_omega_min - mo.phi_omega_min) <= 1e-9


def test_the_machine_that_stalls():
    md = Table((0.0, math.pi, math.pi, 2 * math.pi), (-1000.0, -1000.0, 900.0, 900.0))
    m = Machine(None, 0.0, 2 * math.pi, 100.0, 0.5, loads=(CrankMoment(md),), inertia=0.01)
    with pytest.raises(TrueMotionError, match=r"stalls \(ω → 0\) near φ = "):
        true_motion(m, ExactMachine(m), 0.0)


# --------------------------------------------------------------------------------------------
# Motor characteristic


def test_stiff_motor(comp, stiff, ref):
    m = comp[0]
    assert abs(stiff.omega_s / ref["stiff_omega_s_rad_s"] - 1) <= 1e-13
    # δ is a difference of two speeds 4.9e-5 rad/s apart near 100.5 rad/s: its rounding floor is
    # ~1e-14·100/4.9e-5 ≈ 3e-8 relative
    assert abs(stiff.delta / ref["stiff_delta"] - 1) <= 1e-6
    assert abs(stiff.omega_max / ref["stiff_omega_max_rad_s"] - 1) <= 1e-12
    assert abs(stiff.omega_min / ref["stiff_omega_min_rad_s"] - 1) <= 1e-12
    assert abs(stiff.phi_omega_max / DEG - ref["stiff_phi_omega_max_deg"]) < 0.01
    assert abs(stiff.phi_omega_min / DEG - ref["stiff_phi_omega_min_deg"]) < 0.01
    # the work balance makes the φ-mean speed ω_m; the time mean is below it by ~1e-12 rad/s
    assert abs(stiff.omega_phi_mean - m.omega_m) <= 1e-10
    assert abs(stiff.omega_time_mean - m.omega_m) <= 1e-10
    assert stiff.cycles == ref["stiff_cycles_to_periodic_radau"]


@pytest.mark.parametrize("solver", ["BDF", "LSODA"])
def test_stiff_motor_other_solvers(comp, stiff, solver):
    m, ex, jf = comp
    tm = true_motion(dataclasses.replace(m, motor=Motor(stiffness=1e5)), ex, jf, solver=solver, rtol=1e-12)
    assert abs(tm.delta / stiff.delta - 1) <= 1e-6
    assert tm.cycles == 2


def test_explicit_solver_needs_far_more_steps(comp, stiff):
    """RK45's accepted steps over three 1° windows, extrapolated to a cycle, against Radau's."""
    m, ex, jf = comp
    ms = dataclasses.replace(m, motor=Motor(stiffness=1e5))
    radau = true_motion(ms, ex, jf, rtol=1e-10)
    steps = 0
    for a in np.radians([35.0, 155.0, 275.0]):
        w = integrate(ms, ex, jf, (0.0, a), radau.omega0, rtol=1e-10).omega
        steps += integrate(ms, ex, jf, (a, a + DEG), w, solver="RK45", rtol=1e-10).steps
    assert steps * 120 >= 100 * radau.steps
    with pytest.raises(TrueMotionError, match=r"explicit solver RK45 exceeded 2000 steps: the equation is "
                                              r"stiff, use Radau/BDF/LSODA"):
        true_motion(ms, ex, jf, solver="RK45", rtol=1e-10, max_steps=2000)


def test_integrate_builds_its_model_once_per_exact_machine_and_flywheel(comp):
    """A drawn true motion steps through ~150 stretches: the model (Jп tabulated, ω_s found) is
    built once for the exact machine's own machine and J_F, and gives the numbers a fresh one gives;
    an explicit solver's budget still counts from zero on each call."""
    m, _, jf = comp
    ms = dataclasses.replace(m, motor=Motor(stiffness=1e5))
    ex = ExactMachine(ms)
    w0 = true_motion(ms, ex, jf, rtol=1e-10).omega0
    a, b = 0.3, 0.9
    first = integrate(ms, ex, jf, (0.0, a), w0, rtol=1e-10)
    again = integrate(ms, ex, jf, (0.0, a), w0, rtol=1e-10)
    fresh = integrate(dataclasses.replace(ms), ex, jf, (0.0, a), w0, rtol=1e-10)  # another machine: its own model
    assert first == again == fresh
    assert list(ex.__dict__["_stepping_models"]) == [jf]
    run = integrate(ms, ex, jf, (a, b), first.omega, solver="RK45", rtol=1e-10, max_steps=200_000)
    with pytest.raises(TrueMotionError, match="explicit solver RK45 exceeded 5 steps"):
        integrate(ms, ex, jf, (a, b), first.omega, solver="RK45", rtol=1e-10, max_steps=5)
    again_rk = integrate(ms, ex, jf, (a, b), first.omega, solver="RK45", rtol=1e-10, max_steps=200_000)
    assert run.steps > 5 and again_rk == run  # the budget spent above does not linger
    assert integrate(ms, ex, jf, (0.0, a), w0, rtol=1e-10) == first
    assert integrate(ms, ex, 2 * jf, (0.0, a), w0, rtol=1e-10) != first
    assert list(ex.__dict__["_stepping_models"]) == [jf, 2 * jf]


def test_weak_motor_converges_by_secant_and_keeps_the_work_balance():
    m = dataclasses.replace(stepped(0.05, inertia=0.3), motor=Motor(synchronous=104.0))
    ex = ExactMachine(m)
    tm = true_motion(m, ex, 0.5, rtol=1e-11)
    assert tm.omega_s == 104.0
    assert abs(tm.omega_phi_mean - m.omega_m) <= 1e-8
    assert 2 <= tm.cycles < 10
    with pytest.raises(TrueMotionError, match="not periodic within 2 cycles"):
        true_motion(m, ex, 0.5, rtol=1e-11, max_cycles=2)


def test_motor_needs_a_driving_balance():
    m = dataclasses.replace(stepped(0.05), motor=Motor(synchronous=104.0), balance="resisting",
                            loads=(CrankMoment(Table((0.0, 2 * math.pi), (50.0, 80.0))),))
    with pytest.raises(TrueMotionError, match="must be 'driving'"):
        true_motion(m, ExactMachine(m), 1.0)


# --------------------------------------------------------------------------------------------


def test_braking_time(problems):
    p = problems["fly.brake_time"]
    b = braking_time(p["inputs"]["Je_kgm2"], p["inputs"]["omega_rad_s"], p["inputs"]["Mr_Nm"])
    assert b.t == p["exact"]["t_s"]
    assert abs(b.t_numeric - 2.5) < 1e-12
    with pytest.raises(ValueError):
        braking_time(0.5, 100.0, 0.0)


def test_true_motion_is_frozen(stiff):
    with pytest.raises(dataclasses.FrozenInstanceError):
        stiff.delta = 0.0  # type: ignore[misc]
