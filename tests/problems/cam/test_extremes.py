"""Extreme cam cases: undercut, a roller exactly at the limit, bad offsets, tiny rises, 3600 divisions,
and only what the scene asks for being built."""
from __future__ import annotations

import math

import pytest

from tests.conftest import check_json, run_cli, values

CAM = """
title = "cam"
show = {show}
find = {find}
[units]
length = "mm"
angle = "deg"
[cam]
base_radius = {r0}
rotation = "ccw"
omega_rad_s = 10
step = {step}
[cam.follower]
type = "translating"
contact = "{contact}"
offset = {e}
{roller}
[cam.program]
stroke = {h}
[[cam.segment]]
kind = "rise"
angle = {rise}
law = "{law}"
[[cam.segment]]
kind = "dwell"
angle = {dwell}
[[cam.segment]]
kind = "return"
angle = 150
law = "{law}"
[[cam.segment]]
kind = "dwell"
angle = 30
"""


def scene(tmp_path, *, show='["profile"]', find='["alpha_max", "rho_min_pitch"]', r0=40, step=15, contact="roller",
          e=0, rr=10, h=20, rise=150, law="sine", name="c.toml"):
    roller = f"roller_radius = {rr}" if contact == "roller" else ""
    text = CAM.format(show=show, find=find, r0=r0, step=step, contact=contact, e=e, roller=roller, h=h, rise=rise,
                      dwell=180 - rise, law=law)
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_a_base_circle_so_small_that_the_roller_undercuts(tmp_path):
    doc = check_json(scene(tmp_path, r0=12, rr=10, h=30, rise=60))
    assert any("undercut" in w for w in doc["warnings"])


def test_a_roller_equal_to_the_smallest_radius_of_curvature_is_reported(tmp_path):
    from graphmech.problems.cam.check import analyse_cam
    from graphmech.exact.cam import min_convex_rho_pitch
    from graphmech.scene import load_scene

    steep = dict(r0=30, h=30, rise=60)  # a steep rise: the pitch curve is sharpest near its top
    rho, _ = min_convex_rho_pitch(load_scene(scene(tmp_path, rr=5, **steep)).problem.cam)
    assert rho < 0.030
    at_limit = analyse_cam(load_scene(scene(tmp_path, rr=rho * 1000, name="eq.toml", **steep)))
    assert any("roller undercuts" in w for w in at_limit.warnings)
    below = analyse_cam(load_scene(scene(tmp_path, rr=rho * 1000 * 0.9, name="below.toml", **steep)))
    assert not any("roller undercuts" in w for w in below.warnings)


def test_an_offset_larger_than_the_base_radius_is_bad_input(tmp_path):
    code, out, err = run_cli("check", str(scene(tmp_path, e=45, r0=40)))
    assert code == 2 and err.count("\n") == 1 and "cam.follower.offset" in err


def test_a_zero_dwell_is_no_dwell(tmp_path):
    from graphmech.scene import load_scene

    p = scene(tmp_path, rise=180, find='["v_max", "a_max", "alpha_max"]')  # rise 180°, dwell 0°, return 150°
    assert [seg.kind for seg in load_scene(p).problem.cam.program.segments] == ["rise", "return", "dwell"]
    doc = check_json(p)
    assert all(math.isfinite(r["graphical"]) for r in doc["quantities"])
    # sine into sine at the top: no impact there
    assert not [i for i in doc["impacts"] if abs(i["angle_deg"] - 180.0) < 1e-9]


def test_a_rise_over_one_degree(tmp_path):
    doc = check_json(scene(tmp_path, rise=1, h=1, step=0.25, find='["v_max", "a_max", "alpha_max"]'))
    q = values(doc)
    # sine law: v_max = 2hω/δ0, a_max = 2πhω²/δ0²
    d0 = math.radians(1)
    assert q["v_max"]["exact"] == pytest.approx(2 * 0.001 * 10 / d0, rel=1e-12)
    assert q["a_max"]["exact"] == pytest.approx(2 * math.pi * 0.001 * 100 / d0 ** 2, rel=1e-12)
    assert all(math.isfinite(r["graphical"]) for r in doc["quantities"])


def test_3600_divisions_converge(tmp_path):
    coarse = values(check_json(scene(tmp_path, step=15, find='["alpha_max", "profile_deviation"]')))
    fine = values(check_json(scene(tmp_path, step=0.1, find='["alpha_max", "profile_deviation"]', name="f.toml")))
    assert fine["alpha_max"]["rel_error"] < coarse["alpha_max"]["rel_error"] / 100
    assert fine["profile_deviation"]["graphical"] < coarse["profile_deviation"]["graphical"] / 1000
    assert fine["profile_deviation"]["graphical"] < 2e-7  # m: 0.2 µm on a 60 mm cam


def test_a_scene_that_wants_the_diagrams_alone_builds_no_profile(tmp_path):
    from graphmech.problems.cam.check import analyse_cam
    from graphmech.scene import load_scene

    an = analyse_cam(load_scene(scene(tmp_path, show='["displacement"]', find='["v_max"]')))
    assert an.drawn is None
    code, _, _ = run_cli("render", str(scene(tmp_path, show='["displacement"]', find='["v_max"]', name="d.toml")),
                         "-o", str(tmp_path / "d.svg"))
    assert code == 0 and "Cam profile" not in (tmp_path / "d.svg").read_text(encoding="utf-8")


def test_pressure_angle_at_a_division_and_the_working_profile_radius(tmp_path):
    find = '["alpha@45", "alpha@100", "rho_min_actual", "rho_min_pitch"]'
    coarse = values(check_json(scene(tmp_path, step=5, find=find)))
    fine = values(check_json(scene(tmp_path, step=0.5, find=find, name="f.toml")))
    for name in ("alpha@45", "alpha@100"):
        assert fine[name]["exact"] == pytest.approx(coarse[name]["exact"], rel=1e-12)  # same exact point
        coarse_err = abs(coarse[name]["graphical"] - coarse[name]["exact"])
        assert abs(fine[name]["graphical"] - fine[name]["exact"]) <= max(coarse_err / 50, 1e-9)
    # a roller's working profile is the pitch curve offset inwards by r_r: ρ_actual = ρ_pitch − r_r
    assert fine["rho_min_actual"]["exact"] == pytest.approx(fine["rho_min_pitch"]["exact"] - 0.010, rel=1e-12)
    assert fine["rho_min_actual"]["rel_error"] <= max(coarse["rho_min_actual"]["rel_error"], 1e-9)


def test_an_undercut_profile_is_warned_not_crashed(tmp_path):
    p = scene(tmp_path, rise=1, h=1, step=15, find='["profile_deviation", "alpha_max"]')
    code, out, err = run_cli("check", str(p), "--json")
    assert code == 0, err
    import json

    doc = json.loads(out)
    assert any("undercut" in w for w in doc["warnings"])
    assert any(w.startswith("profile_deviation: not measured") for w in doc["warnings"])
    assert run_cli("render", str(p), "-o", str(tmp_path / "u.svg"))[0] == 0


def test_questions_a_cam_cannot_answer_are_bad_input(tmp_path):
    code, _, err = run_cli("check", str(scene(tmp_path, contact="flat", find='["r0_min"]')))
    assert code == 2 and "find[0]" in err and "flat face" in err
    code, _, err = run_cli("check", str(scene(tmp_path, find='["s@nan"]', name="n.toml")))
    assert code == 2 and "find[0]" in err


def test_a_flat_face_has_no_pressure_angle(tmp_path):
    q = values(check_json(scene(tmp_path, contact="flat", e=12, find='["alpha@45", "alpha@210", "alpha_max"]')))
    assert all(q[n]["graphical"] == 0.0 and q[n]["exact"] == 0.0 for n in ("alpha@45", "alpha@210", "alpha_max"))


def test_impact_jumps_carry_units_and_omega(tmp_path):
    doc = check_json(scene(tmp_path, law="uniform", find='["v_max"]'))
    rigid = [i for i in doc["impacts"] if i["kind"] == "rigid"]
    # uniform rise of 20 mm over 150° at ω = 10: v jumps by hω/δ0
    assert rigid[0]["jump"] == pytest.approx(0.020 * 10 / math.radians(150), rel=1e-12)
    assert rigid[0]["jump_unit"] == "m/s"


def test_the_exact_largest_pressure_angle_is_found_past_a_steep_flank():
    from graphmech.exact.cam import max_pressure_angle, profile
    from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower

    import numpy as np

    program = MotionProgram(0.030, (Segment("rise", math.radians(20), "sine"), Segment("dwell", math.radians(160)),
                                    Segment("return", math.radians(150), "sine"), Segment("dwell", math.radians(30))))
    cam = DiscCam(0.02, TranslatingFollower(0.0, "knife"), program)
    a, at = max_pressure_angle(cam)
    dense = profile(cam, np.linspace(0, math.tau, 200_001)[:-1]).pressure_angle
    assert a >= dense.max() - 1e-12


def test_an_extreme_reached_at_several_places_is_no_error_of_its_place():
    from graphmech.problems.cam.check import _tied

    # the drawing's place is another place where the exact extreme is reached: it is right
    assert _tied(5.0, 0.0, exact_there=0.040, extreme=0.040) == 5.0
    # … and where the exact value there is not the extreme, the exact place stands
    assert _tied(5.0, 0.0, exact_there=0.041, extreme=0.040) == 0.0
