"""Reading [synthesis]: dispatched on its task; every bad scene refused in one line naming its key."""
from __future__ import annotations

import math
import re

import pytest

from graphmech.problems.synthesis.scene import TASKS
from tests.conftest import ROOT, SCENES, assert_refused, run_cli
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
    # the fuzz's: ψ = 1e-300° put C₁ on C₂ and the chord's direction divided by zero (exit 3)
    ("swing_deg = 40", "swing_deg = 1e-300", "synthesis.swing_deg",
     "ψ = 1e-300° is under 5.7e-08°: C₁ and C₂ all but coincide (the chord C₁C₂ under 1e-9 of l_CD)"),
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


def _lines(text: str, *pairs: str) -> str:
    """``text`` with each whole line ``old`` replaced by ``new`` (a key, not a title that names it)."""
    for old, new in zip(pairs[::2], pairs[1::2]):
        found = re.search(r"^" + re.escape(old) + r"$", text, re.MULTILINE)
        assert found, old
        text = text[:found.start()] + new + text[found.end():]
    return text


def test_documented_error_messages_are_real():
    """Every line of the synthesis 'What is refused' block is, word for word, what is printed."""
    from graphmech.errors import GraphmechError
    from graphmech.problems.synthesis.check import analyse_synthesis

    section = (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8").split(
        "### What is refused in a synthesis scene", 1)[1]
    documented = re.search(r"```text\n(.*?)```", section, re.DOTALL).group(1).strip().splitlines()
    sc, gb, cp, fb, sp, rs, pt, fn = ((SCENES / f"synthesis.{n}.toml").read_text(encoding="utf-8") for n in (
        "offset_slider_crank_K1.5", "shaper_guide_bar", "coupler_three_positions", "fourbar_three_positions",
        "slider_crank_positions", "rocker_slider_three_positions", "coupler_point_three_positions", "function_log10"))
    mistakes = [
        _lines(SWING, "K = 1.4", "K = 0.8"),
        _lines(SWING, "K = 1.4", "K = 3"),
        _lines(SWING, "K = 1.4", "K = 1.5", "rocker_mm = 75", "rocker_mm = 50", "swing_deg = 40", "swing_deg = 60"),
        _lines(SWING, "swing_deg = 40", ""),
        _lines(sc, "K = 1.5", "K = 1"),
        _lines(sc, "offset_mm = 10", "offset_mm = 0"),
        _lines(sc, "K = 1.5", "K = 2.5", "offset_mm = 10", "offset_mm = 60"),
        _lines(gb, "K = 2", "K = 1"),
        _lines(gb, "stroke_mm = 400", "stroke_mm = 400\nrocker_mm = 75"),
        _lines(cp, "B_mm = [40, 30]", "B_mm = [42, 48]", "C_mm = [79, 82]", "C_mm = [102, 73]"),
        _lines(fb, "phi_deg = [45, 90, 135]", "phi_deg = [45, 90]", "psi_deg = [60, 80, 105]",
               "psi_deg = [60, 80]\nl_CD_mm = 50\nside = -1"),
        cp.rsplit("[[synthesis.position]]", 1)[0],
        _lines(sp, "phi_deg = [180, 255, 315]", "phi_deg = [0, 90, 180]", "s_mm = [0, 20, 51]", "s_mm = [0, 30, 0]",
               "guide_angle_deg = 0", "guide_angle_deg = 90"),
        _lines(rs, "C_mm = [75, -100]", "C_mm = [75, -101]"),
        _lines(rs, "F_mm = [140, 25]", "F_mm = [140, 26]"),
        _lines(rs, "C_mm = [75, -100]", "C_mm = [0, -125]"),
        _lines(sp, "s_mm = [0, 20, 51]", "s_mm = [0, 20]"),
        _lines(pt, "E_mm = [20, 140]", "E_mm = [200, 0]"),
        _lines(fn, 'function = "log10"', 'function = "log"'),
        _lines(fn, "x_range = [1, 2]", "x_range = [-1, 2]"),
        _lines(fn, "points = 3", "points = 6"),
        _lines(fn, "phi_range_deg = 60", "phi_range_deg = 0"),
        _lines(fn, "phi_start_deg = 45", "phi_start_deg = 0", "psi_start_deg = 135", "psi_start_deg = 45",
               "psi_range_deg = 90", "psi_range_deg = -90"),
        _lines(fn, "phi_start_deg = 45", "phi_start_deg = 0", "psi_start_deg = 135", "psi_start_deg = 0",
               "psi_range_deg = 90", "psi_range_deg = 45"),
        _lines(fn, "phi_start_deg = 45", "phi_start_deg = 210", "phi_range_deg = 60", "phi_range_deg = 90",
               "psi_start_deg = 135", "psi_start_deg = 225", "psi_range_deg = 90", "psi_range_deg = -90",
               "points = 3", "points = 4"),
        _lines(fn, "frame_mm = 50", "frame_mm = 1e-300"),
    ]
    got = []
    for m in mistakes:
        with pytest.raises(GraphmechError) as e:
            analyse_synthesis(parse_text(m, "s.toml"))
        got.append(str(e.value))
    assert got == documented


def test_a_swing_too_small_to_draw_is_refused_on_the_command_line(tmp_path):
    p = write_scene(tmp_path, replace_once(SWING, "swing_deg = 40", "swing_deg = 1e-300"), "s.toml")
    assert_refused(run_cli("check", str(p)), "s.toml", "synthesis.swing_deg: ψ = 1e-300° is under 5.7e-08°")
    # a swing just above the bound is constructed: no design, said in words
    p = write_scene(tmp_path, replace_once(SWING, "swing_deg = 40", "swing_deg = 1e-7"), "t.toml")
    assert_refused(run_cli("check", str(p)), "t.toml", "synthesis.swing_deg: no Grashof crank")


@pytest.mark.parametrize("angle", ["1e-300", "179.99999999999"])
def test_a_limit_angle_on_the_frame_line_is_refused(angle):
    limit = replace_once(SWING, "swing_deg = 40", f"limit_angle_deg = {angle}")
    path, reason = only_problem(limit)
    assert path == "synthesis.limit_angle_deg" and reason.endswith(
        "of the frame line: the rocker lies along the frame, C₁ all but on the line AD"), reason

