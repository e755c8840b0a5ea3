"""Reading [geneva] and [differential_screw]: values in SI, and bad input refused in one line."""
from __future__ import annotations

import math

import pytest

from graphmech.scene import load_scene
from tests.conftest import SCENES, assert_refused, run_cli

GENEVA = """
find = ["R_crank"]
[geneva]
slots = {z}
dial_wheel_distance_mm = {L}
pin_radius_mm = {r}
tip_thickness_mm = 12.5
{time}
{extra}
"""


def _geneva(tmp_path, z="6", L="300", r="25", time="dwell_time_s = 30", extra=""):
    p = tmp_path / "g.toml"
    p.write_text(GENEVA.format(z=z, L=L, r=r, time=time, extra=extra), encoding="utf-8")
    return p


def test_the_reference_scene_reads_in_si():
    s = load_scene(SCENES / "mech.geneva_six_slot.toml")
    g = s.problem.geneva
    assert s.kind == "other" and s.problem.screw is None
    assert (g.z, g.L, g.r_pin, g.b, g.t_rest) == (6, 0.3, 0.025, 0.0125, 30.0)
    assert g.omega1 == pytest.approx(2 * math.pi / 45, rel=1e-15)  # T = 30 s/(1 − 1/3)
    assert g.phi == pytest.approx(math.radians(-20), rel=1e-15)
    sc = load_scene(SCENES / "mech.differential_screw.toml").problem.screw
    assert (sc.p_A, sc.hand_A, sc.travel, sc.p_B) == (pytest.approx(0.0028), "right", pytest.approx(0.0002), None)


def test_a_dial_speed_instead_of_the_dwell(tmp_path):
    s = load_scene(_geneva(tmp_path, time="dial_speed_rpm = 2"))
    assert s.problem.geneva.omega1 == pytest.approx(2 * math.pi / 30, rel=1e-15)
    assert s.problem.geneva.t_rest is None


@pytest.mark.parametrize(("kw", "words"), [
    ({"z": "2"}, ("geneva.slots", "whole number of slots from 3")),
    ({"z": "6.5"}, ("geneva.slots", "6.5")),
    ({"L": "0"}, ("geneva.dial_wheel_distance_mm", "must be > 0")),
    ({"L": "-300"}, ("geneva.dial_wheel_distance_mm", "must be > 0")),
    ({"time": "dwell_time_s = 0"}, ("geneva.dwell_time_s", "must be > 0")),
    ({"time": ""}, ("geneva.dwell_time", "missing")),
    ({"time": "dwell_time_s = 30\ndial_speed_rpm = 2"}, ("geneva.dial_speed_rpm", "not both")),
    ({"r": "140"}, ("geneva.pin_radius_mm", "leaves no locking arc", "R = L sin(π/z) = 150 mm")),
    ({"z": "3", "r": "45"}, ("geneva.pin_radius_mm", "slots past the wheel's centre")),
    ({"extra": "dial_angle_deg = 61"}, ("geneva.dial_angle_deg", "out of the slot", "60°")),
    ({"extra": "slot_count = 3"}, ("geneva.slot_count", "unknown key")),
])
def test_bad_geneva_input_is_refused_in_one_line(tmp_path, kw, words):
    p = _geneva(tmp_path, **kw)
    assert_refused(run_cli("check", str(p)), "g.toml", *words)
    assert_refused(run_cli("render", str(p), "-o", str(tmp_path / "g.svg")), "g.toml", *words)
    assert not (tmp_path / "g.svg").exists()


@pytest.mark.parametrize(("body", "words"), [
    ('lead_A_mm = 2.8\nhand_A = "right"', ("differential_screw.travel", "missing")),
    ('lead_A_mm = 2.8\nhand_A = "up"\ntravel_mm = 0.2', ("differential_screw.hand_A", "unknown value")),
    ('lead_A_mm = 0\nhand_A = "right"\ntravel_mm = 0.2', ("differential_screw.lead_A_mm", "must be > 0")),
    ('lead_A_mm = 2.8\nhand_A = "right"\ntravel_mm = 0.2\nlead_B_mm = 3\nhand_B = "left"',
     ("differential_screw.lead_B_mm", "not both")),
    ('lead_A_mm = 2.8\nhand_A = "right"\nlead_B_mm = 3', ("differential_screw.hand_B", "missing")),
])
def test_bad_screw_input_is_refused_in_one_line(tmp_path, body, words):
    p = tmp_path / "s.toml"
    p.write_text(f"[differential_screw]\n{body}\n", encoding="utf-8")
    assert_refused(run_cli("check", str(p)), "s.toml", *words)
