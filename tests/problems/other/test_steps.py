"""The other mechanisms' protocol: every value is the check's, in three notations."""
from __future__ import annotations

import dataclasses

from graphmech.problems import steps
from graphmech.problems.reader import Page
from graphmech.scene import load_scene
from tests.conftest import SCENES


def test_the_geneva_protocol_lays_out_the_wheel_and_reads_the_check():
    lines = steps(load_scene(SCENES / "mech.geneva_six_slot.toml"))
    assert lines[1] == "draw the line of centres O₁O₂ = L/μl = 60 mm"
    assert "k = 2φ₁/360° = 0.3333" in lines[4] and "T = 45 s, n = 60/T = 1.333 r/min" in lines[5]
    assert "read h_slot = 26.96 mm × 0.005 = 0.1348 m" in lines
    assert lines[-1] == "read omega_wheel_max = 41.89 mm × 0.003333 = 0.1396 rad/s"


def test_the_screw_protocol_in_chinese_and_russian():
    s = load_scene(SCENES / "mech.differential_screw.toml")
    zh = steps(dataclasses.replace(s, page=Page(notation="zh")))
    assert zh[1] == "构件2与1的移动方向相反移动s = 0.2 mm：螺旋副B应使其相对1退回p_B = 3 mm，右旋"
    ru = steps(dataclasses.replace(s, page=Page(notation="ru")))
    assert ru[0] == "за оборот звено 1 смещается по винту A (правый) на p_A = 2.8 mm"
