"""The cam check (problems/cam/check.py): the inversion's divisions and impacts, the rows read off
the drawing against the exact cam, the division table, the scales, and the hand readings judged."""
from __future__ import annotations

import dataclasses
import math
import tomllib

import numpy as np
import pytest

from graphmech.errors import SceneError
from graphmech.exact import cam as exact_cam
from graphmech.mechanisms.motion import displacement
from graphmech.problems.cam.check import (CAM_QUANTITIES, analyse_cam, choose_cam_scales, judge_cam,
                                          profile_deviation)
from graphmech.scene import Scene, parse_scene
from tests.scenes import scene_text

H, OMEGA = 0.016, 10.0  # cam.offset_roller_translating: stroke 16 mm at ω = 10 rad/s
RISE, RETURN = math.radians(150), math.radians(120)


def scene(name: str, **changes) -> Scene:
    s = parse_scene(tomllib.loads(scene_text(f"cam/{name}")), f"{name}.toml")
    return dataclasses.replace(s, **changes)


@pytest.fixture(scope="module")
def offset_roller():
    """The reference cam's find = alpha_max, alpha_max_at, rho_min_pitch at 15° divisions."""
    return analyse_cam(scene("offset_roller"), estimates=False)


def test_the_divisions_and_displacements_of_the_inversion(offset_roller):
    an = offset_roller
    assert np.degrees(an.delta) == pytest.approx(np.arange(0.0, 360.0, 15.0), abs=1e-9)  # joints fall on them
    assert an.step == pytest.approx(math.radians(15.0), rel=1e-15)
    assert an.s == pytest.approx(displacement(an.cam.program, an.delta), abs=0.0)
    assert an.s[2] == pytest.approx(H * 30 / 150, rel=1e-9)  # the uniform rise at 30°


def test_the_impacts_in_si_with_the_cams_omega(offset_roller):
    """Uniform rise: the velocity jumps by hω/δ0 at both ends; parabolic return: the acceleration
    jumps by 4hω²/δ0² at its ends and twice that at its middle."""
    v, a = H * OMEGA / RISE, 4 * H * OMEGA ** 2 / RETURN ** 2
    got = [(round(i["angle_deg"], 6), i["kind"], i["jump"], i["jump_unit"]) for i in offset_roller.impacts]
    assert got == [(0.0, "rigid", pytest.approx(v), "m/s"), (150.0, "rigid", pytest.approx(-v), "m/s"),
                   (180.0, "soft", pytest.approx(-a), "m/s²"), (240.0, "soft", pytest.approx(2 * a), "m/s²"),
                   (300.0, "soft", pytest.approx(-a), "m/s²")]
    assert sum(w.startswith("δ = ") and "impact" in w for w in offset_roller.warnings) == 5


def test_the_rows_are_what_find_asks_read_off_the_drawing(offset_roller):
    an = offset_roller
    assert [r.name for r in an.rows] == ["alpha_max", "alpha_max_at", "rho_min_pitch"]
    alpha, at = exact_cam.max_pressure_angle(an.cam)
    a_max, a_at, rho = an.rows
    assert a_max.exact == pytest.approx(math.degrees(alpha), rel=1e-12) and a_max.unit == "deg"
    assert a_max.graphical == pytest.approx(math.degrees(an.reading.alpha_max), rel=1e-15)
    assert a_max.rel_error == pytest.approx(abs(a_max.graphical - a_max.exact) / 90.0, rel=1e-12)
    assert a_at.exact == pytest.approx(math.degrees(at)) and a_at.graphical == pytest.approx(255.0)
    assert rho.exact == pytest.approx(exact_cam.min_convex_rho_pitch(an.cam)[0], rel=1e-12)
    assert rho.drawn_mm * rho.scale == pytest.approx(rho.graphical, rel=1e-15) and rho.scale == 0.001


def test_ordinates_at_a_division_and_the_stroke():
    an = analyse_cam(scene("offset_roller", find=("s@30", "h")), estimates=False)
    s30, h = an.rows
    assert (s30.name, s30.unit, s30.scale) == ("s@30", "m", 0.0005)
    assert s30.graphical == pytest.approx(0.0032, rel=1e-9) and s30.drawn_mm == pytest.approx(6.4, rel=1e-9)
    assert s30.rel_error == 0.0  # an ordinate laid off exactly
    assert (h.graphical, h.exact, h.drawn_mm) == (H, H, 32.0)


def test_a_reading_between_divisions_is_refused_at_its_find_entry():
    with pytest.raises(SceneError) as info:
        analyse_cam(scene("offset_roller", find=("h", "s@40")), estimates=False)
    assert info.value.problems == [
        ("find[1]", "s@40: 40° is not a division of this drawing (every 15° and at the laws' joints)")]


@pytest.mark.parametrize("name, find, message", [
    ("offset_roller", ("alpha_mx",), "unknown cam quantity 'alpha_mx'"),
    ("offset_roller", ("s@half",), "'s@half': write s@<cam angle in degrees>, e.g. s@45 (or alpha@45)"),
    ("offset_roller", ("alpha@inf",), "'alpha@inf': write s@<cam angle in degrees>, e.g. s@45 (or alpha@45)"),
    ("knife_sine", ("r0_min",), "r0_min needs the permissible pressure angle: set [cam] alpha_permissible"),
    ("flat_translating", ("rho_min_pitch",), "rho_min_pitch has no meaning for a flat face"),
])
def test_what_cannot_be_found_is_refused_before_drawing(name, find, message):
    with pytest.raises(SceneError) as info:
        analyse_cam(scene(name, find=find), estimates=False)
    ((path, reason),) = info.value.problems
    assert path == "find[0]" and reason.startswith(message)


def test_no_profile_is_drawn_for_the_diagrams_alone():
    an = analyse_cam(scene("knife_sine", find=("v_max", "v_max_at")), estimates=False)
    assert an.drawn is None and an.divisions == [] and an.reading is None
    v, at = an.rows
    # the sine rise over 90°: v_max = 2hω/δ0 at the rise's middle, 45° (ω = 60 rpm = 2π rad/s)
    assert v.exact == pytest.approx(2 * 0.05 * 2 * math.pi / (math.pi / 2), rel=1e-12)
    assert v.graphical == pytest.approx(v.exact, rel=1e-12)  # 45° is a division at 7.5° steps
    assert (at.graphical, at.exact) == (pytest.approx(45.0), pytest.approx(45.0))


def test_the_division_table(offset_roller):
    table = offset_roller.divisions
    assert [r["division"] for r in table] == list(range(24))
    assert table[2]["s"] == pytest.approx(0.0032, rel=1e-9) and table[2]["s_unit"] == "m"
    exact = exact_cam.profile(offset_roller.cam, offset_roller.delta)
    assert [r["alpha_exact_deg"] for r in table] == pytest.approx(np.degrees(exact.pressure_angle).tolist())
    assert table[2]["rho_pitch"] == pytest.approx(table[2]["rho_pitch_exact"], rel=1e-3)
    rocker = analyse_cam(scene("oscillating_roller"), estimates=False).divisions
    assert rocker[3]["s_unit"] == "deg"  # an oscillating follower's displacement is an angle
    assert rocker[3]["s"] == pytest.approx(25 * (1 - math.cos(math.pi / 4)) / 2, rel=1e-9)  # cosine rise at 45°


def test_stated_scales_are_kept_and_the_others_chosen_round():
    an = analyse_cam(scene("offset_roller"), estimates=False)
    assert an.stated == {"l", "s", "phi", "v", "a"}
    assert an.scale_notes() == ["μl = 0.001 m/mm", "μs = 0.0005 m/mm", "μφ = 2 °/mm", "μv = 0.01 (m/s)/mm",
                                "μa = 0.5 (m/s²)/mm"]
    knife = scene("knife_sine")
    scales, stated = choose_cam_scales(knife, knife.problem.cam, None)
    assert stated == set() and scales == {"l": 0.005, "phi": math.radians(5.0), "s": 0.002, "v": 0.05, "a": 0.5}
    rocker = analyse_cam(scene("oscillating_roller"), estimates=False)
    assert rocker.scale_notes()[0] == "μψ = 0.00872665 rad/mm" and rocker.scale_notes()[-1].endswith("(chosen)")


def test_a_stated_scale_that_draws_beyond_a_page_is_refused():
    s = scene("offset_roller")
    tiny = dataclasses.replace(s, scales={**s.scales, "s": 1e-7})  # 16 mm of stroke drawn 160 m long
    with pytest.raises(SceneError) as info:
        analyse_cam(tiny, estimates=False)
    ((path, reason),) = info.value.problems
    assert path == "scales" and "displacement" in reason


def test_profile_deviation_is_the_largest_distance_to_the_exact_profile():
    cam = scene("offset_roller").problem.cam
    exact, _ = exact_cam.working_profile(cam, 8192)
    assert profile_deviation(cam, exact) == 0.0
    # shifted by 0.5 mm: the exact points where the profile's tangent is across the shift are 0.5 mm off
    assert profile_deviation(cam, exact + [0.0005, 0.0]) == pytest.approx(0.0005, rel=1e-9)
    flat = scene("offset_roller").problem.cam
    flat = dataclasses.replace(flat, follower=dataclasses.replace(flat.follower, contact="flat", roller_radius=0.0))
    with pytest.raises(ArithmeticError, match="flat face cannot follow"):  # the uniform rise's velocity jump
        profile_deviation(flat, exact)


def test_hand_readings_are_judged_within_the_precision_at_the_scale(offset_roller):
    """An angle's tolerance is the precision seen from the base circle, 0.5 mm / 30 mm = 0.955°; a
    length's is the precision times μl, 0.5 mm · 0.001 m/mm."""
    an = dataclasses.replace(offset_roller, extra_measured=(("alpha_max", 34.5), ("rho_min_pitch", 0.0301)))
    alpha, rho = judge_cam(an)
    assert alpha.tolerance == pytest.approx(math.degrees(0.5 / 30.0), rel=1e-12) and alpha.ok
    assert alpha.expected == pytest.approx(34.8645256, rel=1e-8)
    assert rho.tolerance == pytest.approx(0.0005, rel=1e-12) and not rho.ok  # 0.69 mm off
    assert judge_cam(an, precision_mm=1.0)[1].ok
    with pytest.raises(SceneError) as info:
        judge_cam(dataclasses.replace(offset_roller, extra_measured=(("pc", 3.0),)))
    assert info.value.problems[0][1] == "unknown cam quantity 'pc'"
    assert "pc" not in CAM_QUANTITIES
