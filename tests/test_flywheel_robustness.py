"""Flywheel and braking scenes at the edges (issue 12): refusals in one line at their key path,
no hang, one rule at a table's step, angles compared modulo the cycle."""
from __future__ import annotations

import math

import pytest

from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

BRAKE = (SCENES / "fly.brake_time.toml").read_text(encoding="utf-8")
ENGINE = (SCENES / "fly.ic_engine_flywheel.toml").read_text(encoding="utf-8")
STIFF = (SCENES / "fly.compressor_course_project-stiff.toml").read_text(encoding="utf-8")
COMPRESSOR = (SCENES / "fly.compressor_course_project.toml").read_text(encoding="utf-8")


def scene(tmp_path, text: str, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def with_find(text: str, find: str) -> str:
    """The scene with its (possibly multi-line) ``find = [...]`` replaced."""
    i = text.index("find = [")
    j = text.index("]", i)
    return text[:i] + f"find = {find}" + text[j + 1:]


# ------------------------------------------------------------------ 1. no internal error


def test_a_driving_torque_that_absorbs_work_is_refused_at_balance(tmp_path):
    p = scene(tmp_path, ENGINE.replace("moment_Nm = [0, 200, 200, 0]", "moment_Nm = [0, -200, -200, 0]"))
    for cmd in ("check", "render"):
        argv = (cmd, str(p)) if cmd == "check" else (cmd, str(p), "-o", str(tmp_path / "out.svg"))
        assert_refused(run_cli(*argv), p.name, "flywheel.balance", "absorbs 366.519 J", 'balance = "driving"')
    assert not (tmp_path / "out.svg").exists()


def test_loads_that_deliver_work_against_a_driving_balance_are_refused_at_balance(tmp_path):
    p = scene(tmp_path, COMPRESSOR.replace('sense = "backward"', 'sense = "forward"'))
    assert_refused(run_cli("check", str(p)), p.name, "flywheel.balance", "deliver", 'balance = "resisting"')


def test_omega_s_without_a_motor_is_refused_at_its_find_entry(tmp_path):
    p = scene(tmp_path, STIFF.replace("[flywheel.motor]\nstiffness = 1e5\n", ""))
    assert_refused(run_cli("check", str(p)), p.name, "find[1]", "[flywheel.motor]")


@pytest.mark.parametrize("speed", ["1e-9", "1e-300", "1e300"])
def test_braking_from_any_speed_is_checked_or_refused_in_one_line(tmp_path, speed):
    """The run-down's ODE is solved in units of ω0 and J·ω0/M: brentq's event search no longer
    fails on a stopping time of 2.5e-11 s."""
    p = scene(tmp_path, BRAKE.replace("speed_rad_s = 100", f"speed_rad_s = {speed}"))
    t = 0.5 * float(speed) / 20.0
    if math.isfinite(t) and t > 1e-290:
        q = values(check_json(p))["t_stop"]
        assert q["exact"] == pytest.approx(t, rel=1e-15) and q["rel_error"] < 1e-12
    else:
        assert_refused(run_cli("check", str(p)), p.name, "flywheel.braking.moment_Nm")


def test_braking_time_is_found_for_any_scale_of_the_run_down():
    from graphmech.exact.true_motion import braking_time

    for J, w, M in [(1e-9, 1e-9, 0.01), (0.05, 1.0, 1e6), (0.5, 1e-12, 1e6), (0.5, 100.0, 20.0)]:
        b = braking_time(J, w, M)
        assert b.t_numeric == pytest.approx(J * w / M, rel=1e-10)


def test_braking_a_machine_of_no_inertia_is_refused_at_braking(tmp_path):
    """Loads, no inertia and no masses: nothing for the brake to stop (was a bare ValueError)."""
    p = scene(tmp_path, ENGINE + "\n[flywheel.braking]\nmoment_Nm = 20\n")
    assert_refused(run_cli("check", str(p)), p.name, "flywheel.braking", "nothing to stop")


def test_a_run_down_too_short_to_read_off_its_drawing_is_warned(tmp_path):
    p = scene(tmp_path, BRAKE.replace("speed_rad_s = 100", "speed_rad_s = 1e-9"))
    code, out, err = run_cli("check", str(p))
    assert code == 0 and err.count("\n") == 1 and "below the drawing's precision" in err, err


# ------------------------------------------------------------------ 2. no hang


@pytest.mark.parametrize("moment", ["5e-324", "1e-310"])
def test_a_vanishing_braking_moment_is_refused_not_integrated_for_ever(tmp_path, moment):
    p = scene(tmp_path, BRAKE.replace("moment_Nm = 20", f"moment_Nm = {moment}"))
    for cmd in ("check", "render"):
        argv = (cmd, str(p)) if cmd == "check" else (cmd, str(p), "-o", str(tmp_path / "out.svg"))
        assert_refused(run_cli(*argv), p.name, "flywheel.braking.moment_Nm", "J·ω/M = inf s")
    assert not (tmp_path / "out.svg").exists()


# ------------------------------------------------------------------ 5. wrong answers

STEPS = """\
title = "A crank moment whose steps fall on positions"
find = ["Mr", "Mp@8", "Mp@9"]
[flywheel]
positions = 12
speed_rpm = 620
delta = 0.01
balance = "resisting"
method = "indicator"
inertia_kgm2 = 1
[[flywheel.load]]
type = "crank"
phi_deg = [0, 60, 60, 120, 120, 210, 210, 300, 300, 360]
moment_Nm = [0, 0, 40000, 40000, 0, 0, 40000, 40000, 0, 0]
"""


def test_steps_on_positions_take_the_mean_of_both_sides_and_say_so(tmp_path):
    """210° is one ulp above 7·30° in radians: it was sampled from the left there and from the
    right at the other steps (M_r −13 333 against −16 667). With the mean at every step on a
    position the chords' work is exact for a moment constant between steps."""
    p = scene(tmp_path, STEPS)
    doc = check_json(p)
    q = values(doc)
    assert q["Mr"]["exact"] == pytest.approx(-40000.0 * 150 / 360, rel=1e-12)
    assert q["Mr"]["graphical"] == pytest.approx(q["Mr"]["exact"], rel=1e-12)
    assert q["Mp@8"]["graphical"] == q["Mp@8"]["exact"] == 20000.0  # on the step at 210°: the mean
    assert q["Mp@9"]["graphical"] == q["Mp@9"]["exact"] == 40000.0
    steps = [w for w in doc["warnings"] if "step" in w]
    assert len(steps) == 1 and "flywheel.load[0]" in steps[0] and "positions 3 (φ = 60°), 5" in steps[0]
    assert "8 (φ = 210°)" in steps[0]


def test_a_half_cycle_step_on_positions_by_24(tmp_path):
    """40 000 N·m over [45°, 225°) at 24 positions: 225° is one ulp above 15·15° in radians, so
    that step was read from the left and the other from the right: M_r −21 666.7 where −20 000."""
    text = STEPS.replace("positions = 12", "positions = 24").replace(
        "phi_deg = [0, 60, 60, 120, 120, 210, 210, 300, 300, 360]", "phi_deg = [0, 45, 45, 225, 225, 360]"
    ).replace("moment_Nm = [0, 0, 40000, 40000, 0, 0, 40000, 40000, 0, 0]",
              "moment_Nm = [0, 0, 40000, 40000, 0, 0]").replace('["Mr", "Mp@8", "Mp@9"]', '["Mr"]')
    q = values(check_json(scene(tmp_path, text)))["Mr"]
    assert q["exact"] == pytest.approx(-20000.0, rel=1e-12)
    assert q["graphical"] == pytest.approx(-20000.0, rel=1e-12)


def test_angles_in_the_cycle_are_compared_modulo_the_cycle(tmp_path):
    """ΔT_min of the compressor is at position 1 (0°) by 12 positions, at 353.47° exactly: 6.1°
    apart, not 353.9° (rel_error was 1.0)."""
    p = scene(tmp_path, with_find(COMPRESSOR, '["phi_DeltaT_min", "phi_DeltaT_max"]'))
    q = values(check_json(p))
    lo = q["phi_DeltaT_min"]
    assert lo["graphical"] == 0.0 and lo["exact"] == pytest.approx(353.894, abs=1e-3)
    assert lo["rel_error"] == pytest.approx((360.0 - lo["exact"]) / 360.0, rel=1e-12)
    hi = q["phi_DeltaT_max"]
    assert hi["rel_error"] == pytest.approx(abs(hi["graphical"] - hi["exact"]) / 360.0, rel=1e-12)
