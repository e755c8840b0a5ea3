"""Cam scenes: [cam] in TOML, a DiscCam in SI out; every problem with the key path written."""

from __future__ import annotations

import math
import re
import tomllib
from functools import partial
from pathlib import Path

import numpy as np
import pytest

from graphmech.errors import SceneError
from graphmech.mechanisms.cam import (
    DiscCam,
    MotionProgram,
    OscillatingFollower,
    Segment,
    TranslatingFollower,
)
from graphmech.mechanisms.motion import displacement, maxima
from graphmech.problems.cam.scene import CAM_STEP_DEFAULT, CamScene
from graphmech.problems.reader import Page
from graphmech.scene import Scene, load_scene, parse_scene
from tests.conftest import ROOT, reference_area
from tests.scenes import only_problem, parse_text, refusal, replace_once, scene_text

DOCS = ROOT / "docs" / "scene-format.md"

#: cam.offset_roller_translating, follower axis at x = +e, omega_rad_s given.
GOOD = scene_text("cam/offset_roller")
#: The same cam with a plain omega and no [units] omega: for the error tests.
OFFSET_ROLLER = GOOD.replace("omega_rad_s = 10", "omega = 10")
#: cam.oscillating_roller, the rocker turning against the cam during the rise.
OSCILLATING = scene_text("cam/oscillating_roller")
#: A centred knife-edge follower, units in the key names, a sine rise (cam.law_maxima).
KNIFE = scene_text("cam/knife_sine")
#: A translating flat-face follower, clockwise cam.
FLAT = scene_text("cam/flat_translating")
#: An oscillating flat-faced follower (摆动平底从动件).
OSCILLATING_FLAT = scene_text("cam/oscillating_flat")


# Messages name the file cam.toml.
parse = partial(parse_text, source="cam.toml")
problems_of = partial(refusal, source="cam.toml")
only = partial(only_problem, source="cam.toml")
replace = replace_once


def segment_block(index: int, text: str) -> str:
    """The text of the ``index``-th [[cam.segment]] table."""
    return text.split("[[cam.segment]]")[index + 1]


# ------------------------------------------------------------------------------------------
# Round trips to SI
# ------------------------------------------------------------------------------------------


def test_offset_roller_round_trip_in_si(tmp_path: Path) -> None:
    path = tmp_path / "offset.toml"
    path.write_text(GOOD, encoding="utf-8")
    scene = load_scene(path)
    assert isinstance(scene, Scene)
    assert scene.source == "offset.toml"
    assert scene.linkage is None and scene.positions is None
    assert scene.title == "Offset roller follower, e = +10 mm"
    assert scene.show == ("profile", "displacement")
    assert scene.find == ("alpha_max", "alpha_max_at", "rho_min_pitch")
    assert scene.scales == {
        "l": pytest.approx(0.001),
        "s": pytest.approx(0.0005),
        "phi": pytest.approx(math.radians(2)),
        "v": pytest.approx(0.01),
        "a": pytest.approx(0.5),
    }
    assert scene.measured == ()
    assert scene.precision_mm == 0.5
    assert scene.page == Page((297.0, 210.0))

    cs = scene.problem
    assert isinstance(cs, CamScene)
    assert cs.step == pytest.approx(math.radians(15), rel=1e-15)
    assert cs.roller_circles is True
    cam = cs.cam
    assert isinstance(cam, DiscCam)
    assert cam.base_radius == pytest.approx(0.03, rel=1e-15)
    assert cam.rotation == 1
    assert cam.omega == 10.0
    assert cam.alpha_permissible == pytest.approx(math.radians(30), rel=1e-15)
    assert cam.follower == TranslatingFollower(
        pytest.approx(0.01), "roller", pytest.approx(0.01)
    )
    assert cam.program == MotionProgram(
        pytest.approx(0.016),
        (
            Segment("rise", pytest.approx(math.radians(150)), "uniform"),
            Segment("dwell", pytest.approx(math.radians(30))),
            Segment("return", pytest.approx(math.radians(120)), "parabolic"),
            Segment("dwell", pytest.approx(math.radians(60))),
        ),
    )


def test_cam_scene_is_frozen_and_hashable_parts() -> None:
    scene = parse(GOOD)
    with pytest.raises(AttributeError):
        scene.problem.step = 1.0  # type: ignore[misc]
    with pytest.raises(AttributeError):
        scene.problem.cam.base_radius = 1.0  # type: ignore[misc]
    hash(scene.problem)


def test_negative_offset_and_clockwise_cam() -> None:
    text = replace(GOOD, "offset = 10", "offset = -10").replace('rotation = "ccw"', 'rotation = "cw"')
    cam = parse(text).problem.cam
    assert cam.follower.offset == pytest.approx(-0.01)
    assert cam.rotation == -1


def test_offset_defaults_to_a_centred_follower() -> None:
    cam = parse(replace(GOOD, "offset = 10\n", "")).problem.cam
    assert cam.follower.offset == 0.0


def test_knife_edge_with_suffixes() -> None:
    scene = parse(KNIFE)
    cs = scene.problem
    cam = cs.cam
    assert scene.show == ("displacement", "velocity", "acceleration")
    assert scene.scales == {}
    assert cam.follower == TranslatingFollower(0.0, "knife", 0.0)
    assert cam.base_radius == pytest.approx(0.06)
    assert cam.omega == pytest.approx(2 * math.pi)  # 60 rpm
    assert cam.rotation == -1
    assert cam.alpha_permissible is None
    assert cs.step == pytest.approx(math.radians(7.5))
    assert cs.roller_circles is False  # no roller
    assert cam.program.stroke == pytest.approx(0.05)
    assert [s.law for s in cam.program.segments] == ["sine", None, "sine", None]
    assert sum(s.angle for s in cam.program.segments) == pytest.approx(2 * math.pi, abs=1e-12)


def test_flat_face_in_cm_and_rad() -> None:
    scene = parse(FLAT)
    cam = scene.problem.cam
    assert scene.show == ("profile",)  # the default
    assert scene.problem.step == CAM_STEP_DEFAULT == pytest.approx(math.radians(15))
    assert cam.follower == TranslatingFollower(pytest.approx(-0.01), "flat", 0.0)
    assert cam.base_radius == pytest.approx(0.04)
    assert cam.omega == pytest.approx(4 * math.pi)  # 120 rpm
    assert cam.rotation == -1
    assert cam.alpha_permissible == 0.5
    assert cam.program.stroke == pytest.approx(0.02)
    assert [(s.kind, s.law) for s in cam.program.segments] == [("rise", "poly345"), ("return", "cosine")]


def test_oscillating_round_trip_in_si() -> None:
    scene = parse(OSCILLATING)
    cam = scene.problem.cam
    assert cam.follower == OscillatingFollower(
        pytest.approx(0.055), pytest.approx(0.05), "roller", pytest.approx(0.008), "opposite"
    )
    assert cam.program.stroke == pytest.approx(math.radians(25), rel=1e-15)  # an angle: rad
    assert cam.base_radius == pytest.approx(0.025)
    assert cam.rotation == 1
    assert scene.problem.roller_circles is True
    # an oscillating follower's scales are angular
    assert scene.scales == {
        "s": pytest.approx(math.radians(0.5)),
        "phi": pytest.approx(0.05),
        "v": pytest.approx(0.05),
        "a": pytest.approx(0.5),
    }
    same = parse(replace(OSCILLATING, 'sense = "opposite"', 'sense = "same"'))
    assert same.problem.cam.follower.sense == "same"
    knife = parse(replace(OSCILLATING, 'contact = "roller"', 'contact = "knife"').replace("roller_radius = 8\n", ""))
    assert knife.problem.cam.follower.contact == "knife"
    assert knife.problem.cam.follower.roller_radius == 0.0


def test_oscillating_stroke_by_suffix() -> None:
    text = replace(OSCILLATING, "stroke = 25", "stroke_rad = 0.4363323129985824")
    assert parse(text).problem.cam.program.stroke == pytest.approx(math.radians(25))


def test_units_by_suffix_equal_units_by_table() -> None:
    by_table = parse(GOOD)
    by_suffix = parse(
        GOOD.replace('length = "mm"\nangle = "deg"\n', "")
        .replace("base_radius = 30", "base_radius_cm = 3")
        .replace("step = 15", "step_deg = 15")
        .replace("alpha_permissible = 30", f"alpha_permissible_rad = {math.radians(30)!r}")
        .replace("offset = 10", "offset_m = 0.01")
        .replace("roller_radius = 10", "roller_radius_mm = 10")
        .replace("stroke = 16", "stroke_mm = 16")
        .replace("angle = 150", "angle_deg = 150")
        .replace("angle = 30", "angle_deg = 30")
        .replace("angle = 120", "angle_deg = 120")
        .replace("angle = 60", "angle_deg = 60")
    )
    a, b = by_table.problem.cam, by_suffix.problem.cam
    assert b.base_radius == pytest.approx(a.base_radius)
    assert b.follower.offset == pytest.approx(a.follower.offset)
    assert b.alpha_permissible == pytest.approx(a.alpha_permissible)
    assert [s.angle for s in b.program.segments] == pytest.approx([s.angle for s in a.program.segments])
    assert by_suffix.problem.step == pytest.approx(by_table.problem.step)


def test_table_law() -> None:
    text = replace(
        GOOD,
        'law = "uniform"',
        'law = "table"\ntable = [[0, 0], [0.3, 0.2], [0.7, 0.8], [1, 1]]',
    )
    seg = parse(text).problem.cam.program.segments[0]
    assert seg.law == "table"
    assert seg.table == ((0.0, 0.0), (0.3, 0.2), (0.7, 0.8), (1.0, 1.0))


def test_roller_circles_may_be_turned_off() -> None:
    assert parse(replace(GOOD, "roller_circles = true", "roller_circles = false")).problem.roller_circles is False
    assert parse(replace(GOOD, "roller_circles = true\n", "")).problem.roller_circles is True


def test_measured_check_and_page_work_for_cams() -> None:
    text = GOOD + '\n[measured]\nalpha_max = 34.5\nrho_min_pitch = 0.029\npc = 12\n\n[check]\nprecision_mm = 0.25\n\n[page]\nsize = "A3"\n'
    scene = parse(text)
    assert scene.measured == (("alpha_max", 34.5), ("rho_min_pitch", 0.029), ("pc", 12.0))
    assert scene.precision_mm == 0.25
    assert scene.page == Page((420.0, 297.0))


def test_scene_keeps_its_positional_fields() -> None:
    """Scene(...) written for linkages still works: linkage and positions come first."""
    linkage_scene = parse_scene(
        {
            "frame": {"A_mm": [0, 0]},
            "driver": {"type": "crank", "link": "1", "pivot": "A", "tip": "B",
                       "length_mm": 50, "angle_deg": 0, "omega_rad_s": 1},
        }
    )
    again = Scene("s", "", ("mechanism",), (), {}, linkage_scene.linkage, linkage_scene.positions, ())
    assert again.linkage is linkage_scene.linkage and again.kind != "cam"
    cam_scene = parse(GOOD)
    assert Scene("s", "", ("profile",), (), {}, kind="cam", problem=cam_scene.problem).linkage is None


# ------------------------------------------------------------------------------------------
# What is refused: one line, the key path as written, every problem collected
# ------------------------------------------------------------------------------------------


def test_offset_not_smaller_than_the_base_radius() -> None:
    err = problems_of(replace(GOOD, "offset = 10", "offset = 35"))
    assert err.problems == [
        (
            "cam.follower.offset",
            "|e| = 35 mm is not smaller than the base radius r0 = 30 mm: "
            "the follower's axis misses the base circle",
        )
    ]
    assert str(err) == (
        "cam.toml: cam.follower.offset: |e| = 35 mm is not smaller than the base radius "
        "r0 = 30 mm: the follower's axis misses the base circle"
    )
    negative = only(replace(GOOD, "offset = 10", "offset = -35"))
    assert negative == err.problems[0]
    tangent = only(replace(GOOD, "offset = 10", "offset_cm = 3"))
    assert tangent[0] == "cam.follower.offset_cm"
    assert tangent[1].startswith("|e| = 3 cm is not smaller than the base radius r0 = 30 mm")


def test_radii_must_be_positive() -> None:
    assert only(replace(GOOD, "base_radius = 30", "base_radius = 0")) == ("cam.base_radius", "must be > 0")
    assert only(replace(GOOD, "roller_radius = 10", "roller_radius = -1")) == (
        "cam.follower.roller_radius",
        "must be > 0",
    )
    assert only(replace(OSCILLATING, "arm = 50", "arm = 0")) == ("cam.follower.arm", "must be > 0")
    assert only(replace(OSCILLATING, "pivot_distance = 55", "pivot_distance = -55")) == (
        "cam.follower.pivot_distance",
        "must be > 0",
    )


def test_roller_radius_for_rollers_only() -> None:
    path, reason = only(replace(GOOD, 'contact = "roller"', 'contact = "knife"').replace("roller_circles = true\n", ""))
    assert (path, reason) == ("cam.follower.roller_radius", 'only for contact = "roller" (this follower is knife)')
    no_circles = replace(GOOD, 'contact = "roller"', 'contact = "knife"').replace("roller_radius = 10\n", "")
    assert only(no_circles) == (
        "cam.roller_circles",
        'only for contact = "roller" (this follower is knife)',
    )
    assert only(replace(GOOD, "roller_radius = 10\n", "")) == (
        "cam.follower.roller_radius",
        "missing: write roller_radius_mm (or roller_radius with [units] length)",
    )
    path, reason = only(replace(GOOD, "roller_radius = 10", "roller_radius = 30"))
    assert path == "cam.follower.roller_radius"
    assert reason.startswith("r_r = 30 mm is not smaller than the base radius r0 = 30 mm")


def test_oscillating_arm_must_reach_the_base_circle() -> None:
    far = only(replace(OSCILLATING, "pivot_distance = 55", "pivot_distance = 90"))
    assert far == (
        "cam.follower.arm",
        "the arm cannot reach the base circle: r0 = 25 mm must lie between |a − l| = 40 mm and "
        "a + l = 140 mm (pivot_distance a = 90 mm, arm l = 50 mm)",
    )
    short = only(replace(OSCILLATING, "arm = 50", "arm = 10").replace("pivot_distance = 55", "pivot_distance = 10"))
    assert short[0] == "cam.follower.arm"
    assert "r0 = 25 mm must lie between |a − l| = 0 mm and a + l = 20 mm" in short[1]


def test_flat_face_oscillating_needs_the_base_circle_inside_the_pivot_distance() -> None:
    text = replace(OSCILLATING, 'contact = "roller"', 'contact = "flat"').replace("roller_radius = 8\n", "")
    follower = parse(text).problem.cam.follower
    assert (follower.kind, follower.contact, follower.pivot_distance) == ("oscillating", "flat", 0.055)
    assert only(replace(text, "base_radius = 25", "base_radius = 60")) == (
        "cam.follower.pivot_distance",
        "a flat face through the pivot cannot touch the base circle: the base radius r0 = 60 mm must "
        "be smaller than pivot_distance a = 55 mm",
    )


def test_keys_of_the_other_follower_type() -> None:
    err = problems_of(replace(GOOD, "roller_radius = 10", "roller_radius = 10\narm = 50\nsense = \"same\""))
    assert err.problems == [
        ("cam.follower.arm", "only for an oscillating follower (this one is translating)"),
        ("cam.follower.sense", "only for an oscillating follower (this one is translating)"),
    ]
    assert only(replace(OSCILLATING, "arm = 50", "arm = 50\noffset = 5")) == (
        "cam.follower.offset",
        "only for a translating follower (this one is oscillating)",
    )
    missing = problems_of(OSCILLATING.replace('sense = "opposite"\n', ""))
    assert missing.problems == [
        ("cam.follower.sense", 'missing: write sense = "opposite" or "same"'),
    ]


def test_segment_paths_from_motion_validate() -> None:
    """motion.validate's program.segments[i]… become cam.segment[i]…"""
    rise_twice = replace(GOOD, 'kind = "return"', 'kind = "rise"')
    err = problems_of(rise_twice)
    assert err.problems == [
        (
            "cam.segment[2].kind",
            "a rise after a rise: rises and returns must alternate (the follower is already up by the stroke)",
        ),
        (
            "cam.segment",
            "the displacement ends at the stroke, not 0: the program needs a return after its last rise",
        ),
    ]
    table = replace(GOOD, 'law = "uniform"', 'law = "table"\ntable = [[0.1, 0], [0.5, 0.6], [0.6, 0.4], [1, 1]]')
    assert problems_of(table).problems == [
        ("cam.segment[0].table[0]", "the first point must be (0, 0), got (0.1, 0)"),
        ("cam.segment[0].table[2]", "y must not decrease (the follower would turn back): 0.4 after 0.6"),
    ]


def test_segment_problems() -> None:
    assert only(replace(GOOD, 'law = "parabolic"', 'law = "parabolc"')) == (
        "cam.segment[2].law",
        "unknown value 'parabolc': use uniform, parabolic, cosine, sine, poly345 or table "
        "(did you mean parabolic?)",
    )
    assert only(replace(GOOD, 'law = "parabolic"\n', "")) == (
        "cam.segment[2].law",
        'missing: write law = "uniform", "parabolic", "cosine", "sine", "poly345" or "table"',
    )
    assert only(replace(GOOD, "angle = 30", 'angle = 30\nlaw = "uniform"')) == (
        "cam.segment[1].law",
        "a dwell has no motion law: leave law out",
    )
    assert only(replace(GOOD, 'law = "uniform"', 'law = "uniform"\ntable = [[0, 0], [1, 1]]')) == (
        "cam.segment[0].table",
        'only with law = "table"',
    )
    assert only(replace(GOOD, 'law = "uniform"', 'law = "table"')) == (
        "cam.segment[0].table",
        "missing: table = [[0, 0], [0.5, 0.3], [1, 1]] (fractions)",
    )
    assert only(replace(GOOD, 'law = "uniform"', 'law = "table"\ntable = [[0, 0], [1]]')) == (
        "cam.segment[0].table[1]",
        "must be [x, y]: a list of 2 numbers, not a list of 1",
    )
    assert only(replace(GOOD, 'kind = "dwell"', 'kind = "pause"'))[0] == "cam.segment[1].kind"


def test_segment_angles_must_add_up_to_a_turn() -> None:
    err = problems_of(replace(GOOD, "angle = 60", "angle = 50"))
    assert err.problems == [
        ("cam.segment", "the segment angles add up to 350°, not 360°: together they are one turn of the cam")
    ]
    in_rad = problems_of(KNIFE.replace("angle_rad = 1.5707963267948966", "angle_rad = 1.5"))
    ((path, reason),) = in_rad.problems
    assert path == "cam.segment"
    assert reason.startswith("the segment angles add up to 355.9436")
    assert "rad, not 2π = 6.28318531" in reason


def test_a_zero_dwell_is_left_out() -> None:
    text = GOOD.replace("angle = 60", "angle = 0") + '\n[[cam.segment]]\nkind = "dwell"\nangle = 60\n'
    with_zero = parse_scene(tomllib.loads(text), "z.toml").problem.cam.program
    plain = parse_scene(tomllib.loads(GOOD), "g.toml").problem.cam.program
    assert with_zero == plain  # a 0° dwell is no dwell
    assert only(replace(GOOD, "angle = 150", "angle = -150"))[1] == "must be > 0"


def test_stroke_problems() -> None:
    assert only(replace(GOOD, "stroke = 16", "stroke = 0")) == ("cam.program.stroke", "must be > 0")
    assert only(replace(OSCILLATING, "stroke = 25", "stroke_mm = 25")) == (
        "cam.program.stroke_mm",
        "mm is not a unit of an angle; write stroke_deg or stroke_rad",
    )
    assert only(replace(OSCILLATING, "stroke = 25", "stroke = 200"))[0] == "cam.program.stroke"
    assert only(replace(GOOD, "[cam.program]\nstroke = 16\n", "")) == (
        "cam.program",
        "missing: add a [cam.program] table with the stroke (stroke_mm = 16, or an oscillating "
        "follower's stroke_deg = 25)",
    )


def test_cam_table_problems() -> None:
    assert only(replace(GOOD, "step = 15", "step = 120")) == (
        "cam.step",
        "must lie between 0.1° and 90°, not 120°: too coarse to draw a profile",
    )
    assert only(replace(GOOD, "step = 15", "step = 0.01"))[1].endswith("too many divisions")
    assert only(replace(GOOD, "step = 15", "step = 0")) == ("cam.step", "must be > 0")
    assert only(replace(GOOD, "alpha_permissible = 30", "alpha_permissible = 90")) == (
        "cam.alpha_permissible",
        "must be below 90°, not 90°",
    )
    assert only(replace(GOOD, "omega_rad_s = 10", "omega_rad_s = -10")) == ("cam.omega_rad_s", "must be > 0")
    assert only(OFFSET_ROLLER) == (
        "cam.omega",
        "unit not stated: write omega_rad_s or set [units] omega",
    )
    assert only(replace(GOOD, 'rotation = "ccw"', 'rotation = "ccww"')) == (
        "cam.rotation",
        "unknown value 'ccww': use ccw or cw (did you mean ccw?)",
    )
    assert only(replace(GOOD, 'rotation = "ccw"', 'direction = "ccw"')) == (
        "cam.direction",
        'a cam\'s sense is written rotation = "ccw" or "cw"',
    )
    assert only(replace(GOOD, "roller_circles = true", "roller_circles = 1")) == (
        "cam.roller_circles",
        "must be true or false, not a number",
    )


def test_unknown_keys_suggest_the_nearest() -> None:
    err = problems_of(replace(GOOD, "roller_radius = 10", "rolller_radius = 10"))
    assert err.problems == [  # the typo first: it is why the other is missing
        ("cam.follower.rolller_radius", "unknown key; did you mean roller_radius?"),
        ("cam.follower.roller_radius", "missing: write roller_radius_mm (or roller_radius with [units] length)"),
    ]
    err = problems_of(replace(GOOD, "step = 15", "setp = 15"))
    assert err.problems == [("cam.setp", "unknown key; did you mean step?")]
    err = problems_of(GOOD.replace("[[cam.segment]]", "[[cam.segments]]"))
    assert err.problems[0] == ("cam.segments", "unknown key; did you mean segment?")
    assert err.problems[1][0] == "cam.segment"
    err = problems_of(replace(GOOD, 'kind = "dwell"\nangle = 30', 'kind = "dwell"\nangel = 30'))
    assert err.problems[0] == ("cam.segment[1].angel", "unknown key; did you mean angle?")


def test_show_choices_of_a_cam_scene() -> None:
    assert only(replace(GOOD, 'show = ["profile", "displacement"]', 'show = ["mechanism"]')) == (
        "show[0]",
        "unknown value 'mechanism': use profile, displacement, velocity or acceleration",
    )
    assert only(replace(GOOD, 'show = ["profile", "displacement"]', 'show = ["profile", "profile"]')) == (
        "show[1]",
        "profile is listed twice",
    )


def test_scales_follow_the_follower() -> None:
    assert only(replace(GOOD, "s_m_per_mm = 0.0005", "s_deg_per_mm = 1")) == (
        "scales.s_deg_per_mm",
        "deg_per_mm is not a unit of a length; write s_mm_per_mm, s_cm_per_mm or s_m_per_mm",
    )
    assert only(replace(OSCILLATING, "s_deg_per_mm = 0.5", "s_m_per_mm = 0.5")) == (
        "scales.s_m_per_mm",
        "m_per_mm is not a unit of an angle; write s_deg_per_mm or s_rad_per_mm",
    )


def test_measured_names_take_no_position_label() -> None:
    assert only(GOOD + '\n[measured]\n"alpha_max@30" = 30\n') == (
        "measured.alpha_max@30",
        "a cam scene has no driver positions: write the name without @30",
    )


def test_linkage_or_cam_not_both_nor_neither() -> None:
    both = GOOD + '\n[driver]\ntype = "crank"\n'
    assert only(both) == (
        "cam",
        "a scene is a linkage ([driver]) or a disc cam ([cam]), not both: put the cam in a scene of its own",
    )
    assert only('title = "nothing"\n') == (
        "",
        "nothing to draw: add a [driver] table (a linkage scene) or a [cam] table (a disc cam scene)",
    )
    assert str(problems_of('title = "nothing"\n')).startswith("cam.toml: nothing to draw")
    framed = GOOD + "\n[frame]\nA_mm = [0, 0]\n"
    assert only(framed) == ("frame", "[frame] belongs to a linkage scene; this is a cam scene ([cam])")
    assert only('title = "x"\ncam = 3\n') == ("cam", "must be a table, not a number")


def test_missing_cam_parts() -> None:
    err = problems_of('[cam]\nbase_radius_mm = 30\nrotation = "ccw"\nomega_rad_s = 1\n')
    assert [p for p, _ in err.problems] == ["cam.follower", "cam.program", "cam.segment"]
    err = problems_of(GOOD.split("[[cam.segment]]")[0] + "[cam.x]\n")
    assert [p for p, _ in err.problems] == ["cam.x", "cam.segment"]


def test_all_problems_are_collected_in_file_order() -> None:
    text = (
        GOOD.replace("base_radius = 30", "base_radius = 30\nbogus = 1")
        .replace("offset = 10", "offset = 40")
        .replace('law = "uniform"', 'law = "linear"')
        .replace("angle = 60", "angle = -60")
        .replace('[page]', '[page]')
    )
    err = problems_of(text)
    assert [p for p, _ in err.problems] == [
        "cam.bogus",
        "cam.follower.offset",
        "cam.segment[0].law",
        "cam.segment[3].angle",
    ]
    assert str(err).startswith("cam.toml: cam.bogus: unknown key")
    assert str(err).endswith("(and 3 more)")
    assert "\n" not in str(err)


def test_the_scene_parser_accepts_an_oscillating_flat_face() -> None:
    scene = parse_scene(tomllib.loads(OSCILLATING_FLAT), "cam.toml")
    f = scene.problem.cam.follower
    assert (f.kind, f.contact, f.pivot_distance, f.sense) == ("oscillating", "flat", 0.08, "opposite")
    with pytest.raises(SceneError) as info:
        parse_scene(tomllib.loads(OSCILLATING_FLAT.replace("base_radius = 30", "base_radius = 80")), "cam.toml")
    assert info.value.problems == [(
        "cam.follower.pivot_distance",
        ("a flat face through the pivot cannot touch the base circle: the base radius r0 = 80 mm "
         "must be smaller than pivot_distance a = 80 mm"),
    )]


# ------------------------------------------------------------------------------------------
# The documentation
# ------------------------------------------------------------------------------------------


def doc_cam_scenes() -> list[Scene]:
    blocks = re.findall(r"^```toml\n(.*?)^```", DOCS.read_text(encoding="utf-8"), re.S | re.M)
    scenes = [parse_scene(tomllib.loads(b), "scene-format.md") for b in blocks]
    return [s for s in scenes if s.kind == "cam" and hasattr(s.problem, "roller_circles")]  # a motion law's


def test_docs_have_a_cam_example_of_every_kind() -> None:
    scenes = doc_cam_scenes()
    followers = {(type(s.problem.cam.follower).__name__, s.problem.cam.follower.contact) for s in scenes}
    assert followers >= {
        ("TranslatingFollower", "roller"),
        ("TranslatingFollower", "knife"),
        ("TranslatingFollower", "flat"),
        ("OscillatingFollower", "roller"),
    }
    laws = {seg.law for s in scenes for seg in s.problem.cam.program.segments}
    assert laws >= {"uniform", "parabolic", "cosine", "sine", "poly345", "table"}
    assert {s.problem.cam.rotation for s in scenes} == {1, -1}
    assert any(s.problem.cam.follower.kind == "translating" and s.problem.cam.follower.offset == 0 for s in scenes)
    assert any(s.problem.cam.follower.kind == "translating" and s.problem.cam.follower.offset < 0 for s in scenes)
    shown = {v for s in scenes for v in s.show}
    assert shown == {"profile", "displacement", "velocity", "acceleration"}
    assert any(s.measured for s in scenes)


def test_documented_error_messages_are_real() -> None:
    """Every line of the cam 'What is refused' block is a message the reader gives."""
    text = DOCS.read_text(encoding="utf-8")
    section = text.split("### What is refused in a cam scene", 1)[1]
    documented = re.search(r"```text\n(.*?)```", section, re.S).group(1).strip().splitlines()
    osc = OSCILLATING.replace("pivot_distance = 55", "pivot_distance = 50").replace("arm = 50", "arm = 15")
    mistakes = [
        replace(GOOD, "offset = 10", "offset = 35"),
        osc,
        replace(GOOD, 'contact = "roller"', 'contact = "knife"').replace("roller_circles = true\n", ""),
        replace(OSCILLATING, 'contact = "roller"', 'contact = "flat"').replace("roller_radius = 8\n", "")
        .replace("base_radius = 25", "base_radius = 60"),
        GOOD + '\n[[cam.segment]]\nkind = "dwell"\nangle = -5\n',
        replace(GOOD, "angle = 60", "angle = 50"),
        replace(GOOD, 'kind = "return"', 'kind = "rise"'),
        replace(GOOD, 'law = "uniform"', 'law = "table"\ntable = [[0.1, 0], [1, 1]]'),
        replace(GOOD, "angle = 30", 'angle = 30\nlaw = "sine"'),
        GOOD + '\n[driver]\ntype = "crank"\n',
    ]
    got = [str(problems_of(m)).replace("(and 1 more)", "").strip() for m in mistakes]
    assert [line.replace("cam.toml: ", "", 1) for line in documented] == [
        g.replace("cam.toml: ", "", 1) for g in got
    ]


# ------------------------------------------------------------------------------------------
# The reference problems, written as scenes
# ------------------------------------------------------------------------------------------



def test_offset_roller_translating_problem_both_senses() -> None:
    p = reference_area("cam")["cam.offset_roller_translating"]
    inputs = p["inputs"]
    docs = {s.title: s for s in doc_cam_scenes()}
    for sign, scene in (
        (+1, docs["Offset roller follower, e = +10 mm"]),
        (-1, parse(replace(GOOD, "offset = 10", "offset = -10"))),
    ):
        cam = scene.problem.cam
        f = cam.follower
        assert isinstance(f, TranslatingFollower) and f.contact == "roller"
        assert f.offset == pytest.approx(sign * inputs["e_mm"] / 1000)
        assert cam.base_radius == pytest.approx(inputs["r0_mm"] / 1000)
        assert f.roller_radius == pytest.approx(inputs["rr_mm"] / 1000)
        assert cam.program.stroke == pytest.approx(inputs["h_mm"] / 1000)
        assert cam.rotation == (1 if inputs["cam_rotation"] == "CCW" else -1)
        assert [s.angle for s in cam.program.segments] == pytest.approx(
            [math.radians(inputs[k]) for k in ("rise_deg", "far_dwell_deg", "return_deg", "near_dwell_deg")]
        )
        assert [s.kind for s in cam.program.segments] == ["rise", "dwell", "return", "dwell"]
        # the displacement table follows from the program as written
        angles = np.radians(inputs["s_table_angles_deg"])
        s = displacement(cam.program, angles) * 1000
        assert s == pytest.approx(p["exact"]["s_table_mm"], abs=1e-9)


def test_oscillating_roller_problem() -> None:
    p = reference_area("cam")["cam.oscillating_roller"]
    inputs = p["inputs"]
    docs = {s.title: s for s in doc_cam_scenes()}
    for scene in (docs["Oscillating roller follower"], parse(OSCILLATING)):
        cam = scene.problem.cam
        f = cam.follower
        assert isinstance(f, OscillatingFollower) and f.contact == "roller"
        assert f.pivot_distance == pytest.approx(inputs["lOA_mm"] / 1000)
        assert f.arm == pytest.approx(inputs["lAB_mm"] / 1000)
        assert f.roller_radius == pytest.approx(inputs["rr_mm"] / 1000)
        assert cam.base_radius == pytest.approx(inputs["r0_mm"] / 1000)
        assert cam.program.stroke == pytest.approx(math.radians(inputs["phim_deg"]))
        assert [s.angle for s in cam.program.segments] == pytest.approx(
            [math.radians(inputs["rise_deg"]), math.radians(inputs["return_deg"])]
        )
        phi = np.degrees(displacement(cam.program, np.radians(inputs["table_angles_deg_corrected"])))
        assert phi == pytest.approx(p["exact"]["phi_table_deg"], rel=1e-9)
        # ψ0 = ∠OAB with B on the base circle
        a, l, r0 = f.pivot_distance, f.arm, cam.base_radius
        psi0 = math.degrees(math.acos((a * a + l * l - r0 * r0) / (2 * a * l)))
        assert psi0 == pytest.approx(p["exact"]["phi0_initial_rocker_angle_deg"])


@pytest.mark.parametrize(
    ("law", "key"),
    [("uniform", "uniform"), ("parabolic", "const_acc"), ("cosine", "cosine"), ("sine", "sine")],
)
def test_law_maxima_problem(law: str, key: str) -> None:
    p = reference_area("cam")["cam.law_maxima"]
    inputs, exact = p["inputs"], p["exact"]
    deg = math.degrees(inputs["delta0_rad"])
    rest = (360 - deg) / 3  # the rise, then dwell, return and dwell filling the turn
    text = f"""
        show = ["displacement", "velocity", "acceleration"]
        [cam]
        base_radius_mm = 60
        rotation = "ccw"
        omega_rad_s = {inputs["omega_rad_s"]}
        [cam.follower]
        type = "translating"
        contact = "knife"
        [cam.program]
        stroke_mm = {inputs["h_mm"]}
        [[cam.segment]]
        kind = "rise"
        angle_deg = {deg!r}
        law = "{law}"
        [[cam.segment]]
        kind = "dwell"
        angle_deg = {rest!r}
        [[cam.segment]]
        kind = "return"
        angle_deg = {rest!r}
        law = "sine"
        [[cam.segment]]
        kind = "dwell"
        angle_deg = {rest!r}
    """
    cam = parse(text).problem.cam
    rise = cam.program.segments[0]
    assert rise.angle == pytest.approx(inputs["delta0_rad"], rel=1e-15)
    assert cam.program.stroke == pytest.approx(inputs["h_mm"] / 1000)
    assert cam.omega == inputs["omega_rad_s"]
    # the rise alone, as the problem states it
    alone = MotionProgram(cam.program.stroke, (rise, Segment("return", 2 * math.pi - rise.angle, "sine")))
    m = maxima(alone, cam.omega)
    assert m["v"].value == pytest.approx(exact[f"{key}_vmax_m_s"], rel=1e-9)
    if key != "uniform":  # the uniform law's accelerations are impulses at the ends
        assert m["a"].value == pytest.approx(exact[f"{key}_amax_m_s2"], rel=1e-9)
