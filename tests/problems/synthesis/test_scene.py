"""Reading [synthesis]: dispatched on its task; every bad scene refused in one line naming its key."""
from __future__ import annotations

import math

import pytest

from graphmech.problems.synthesis.scene import TASKS
from tests.conftest import SCENES, assert_refused, run_cli
from tests.scenes import only_problem, parse_text, replace_once, scene_text, write_scene

SWING = scene_text("synthesis/swing")


def test_a_swing_scene_reads_in_si():
    s = parse_text(SWING)
    assert s.kind == "synthesis" and s.problem.task == "time_ratio" and s.show == ("design",)
    p = s.problem.problem
    assert (p.mechanism, p.K, p.rocker, p.frame, p.limit_angle) == ("crank_rocker", 1.4, 0.075, 0.1, None)
    assert p.swing == pytest.approx(math.radians(40)) and p.key == "synthesis.swing_deg"
    assert math.degrees(p.theta) == pytest.approx(30.0)


def test_the_tasks_are_the_readers_listed():
    assert list(TASKS) == ["time_ratio", "positions", "function"]


@pytest.mark.parametrize("old, new, where, words", [
    ("K = 1.4", "K = 0.8", "synthesis.K", "K = 0.8 < 1"),
    ("K = 1.4", "K = 3", "synthesis.K", "θ = 90° ≥ 90°: no crank-rocker"),
    ("K = 1.4", "K = 1.0000001", "synthesis.K", "within 1e-6 of 1"),
    ("K = 1.4", "K = 7", "synthesis.K", "no crank-rocker is designed so"),
    ("K = 1.4", 'K = "1.4"', "synthesis.K", "must be a number"),
    ("K = 1.4\n", "", "synthesis.K", "missing"),
    ("swing_deg = 40", "", "synthesis.swing", "missing: write swing_deg"),
    ("swing_deg = 40", "swing_deg = 40\nlimit_angle_deg = 45", "synthesis.limit_angle_deg", "not both"),
    ("swing_deg = 40", "swing_deg = 190", "synthesis.swing_deg", "between 0 and 180°"),
    ("rocker_mm = 75", "rocker_mm = -75", "synthesis.rocker_mm", "> 0"),
    ("frame_mm = 100", "frame = 100", "synthesis.frame", "unit not stated"),
    ("swing_deg = 40", "swing_deg = 40\nstroke_mm = 10", "synthesis.stroke_mm", "not for a crank-rocker"),
    ('mechanism = "crank_rocker"', 'mechanism = "crank"', "synthesis.mechanism", "unknown value"),
    ('task = "time_ratio"', 'task = "cam"', "synthesis.task", "unknown value"),
    ("swing_deg = 40", "swing_deg = 40\nhandle = 1", "synthesis.handle", "unknown key"),
])
def test_bad_synthesis_scenes_are_refused_in_one_line(old, new, where, words):
    path, reason = only_problem(replace_once(SWING, old, new))
    assert path == where and words in reason, (path, reason)


def test_a_refusal_on_the_command_line_is_one_line(tmp_path):
    p = write_scene(tmp_path, replace_once(SWING, "K = 1.4", "K = 0.5"), "s.toml")
    assert_refused(run_cli("check", str(p)), "s.toml", "synthesis.K: K = 0.5 < 1")


GUIDE = '[synthesis]\ntask = "time_ratio"\nmechanism = "guide_bar"\nK = 2\nframe_mm = 300\nstroke_mm = 400\n'


def test_a_guide_bar_reads_its_frame_and_stroke():
    p = parse_text(GUIDE).problem.problem
    assert (p.mechanism, p.K, p.frame, p.stroke) == ("guide_bar", 2.0, 0.3, 0.4)
    assert math.degrees(p.theta) == pytest.approx(60.0)


@pytest.mark.parametrize("old, new, where, words", [
    ("K = 2", "K = 1", "synthesis.K", "no guide bar has K = 1"),
    ("K = 2", "K = 40", "synthesis.K", "≥ 170°"),
    ("stroke_mm = 400", "stroke_mm = 400\nswing_deg = 30", "synthesis.swing_deg", "not for a guide bar"),
    ("stroke_mm = 400", "stroke_mm = 0", "synthesis.stroke_mm", "> 0"),
    ("frame_mm = 300\n", "", "synthesis.frame", "missing"),
])
def test_bad_guide_bars_are_refused_in_one_line(old, new, where, words):
    path, reason = only_problem(replace_once(GUIDE, old, new))
    assert path == where and words in reason, (path, reason)


SLIDER = '[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = 1.5\nstroke_mm = 50\noffset_mm = 10\n'


def test_a_slider_crank_reads_its_stroke_and_offset():
    p = parse_text(SLIDER).problem.problem
    assert (p.mechanism, p.K, p.stroke, p.offset, p.key) == ("slider_crank", 1.5, 0.05, 0.01, "synthesis.offset_mm")


@pytest.mark.parametrize("old, new, where, words", [
    ("K = 1.5", "K = 1", "synthesis.K", "K does not fix the design"),
    ("K = 1.5", "K = 3.5", "synthesis.K", "no slider-crank is designed so"),
    ("offset_mm = 10", "offset_mm = -10", "synthesis.offset_mm", "a distance ≥ 0"),
    ("offset_mm = 10\n", "", "synthesis.offset", "missing"),
    ("offset_mm = 10", "offset_mm = 0", "synthesis.offset_mm", "a quick return needs an offset"),
    ("stroke_mm = 50", "stroke_mm = 50\nframe_mm = 3", "synthesis.frame_mm", "not for a slider-crank"),
])
def test_bad_slider_cranks_are_refused_in_one_line(old, new, where, words):
    path, reason = only_problem(replace_once(SLIDER, old, new))
    assert path == where and words in reason, (path, reason)


def test_the_bank_scene_reads_its_limit_angle():
    from graphmech.scene import load_scene

    p = load_scene(SCENES / "linkage.crank_rocker_synthesis_K1.5.toml").problem.problem
    assert p.swing is None and p.limit_angle == pytest.approx(math.pi / 4) and p.key == "synthesis.limit_angle_deg"
