"""The other mechanisms' check: the reference scenes against the bank's values, hand values judged."""
from __future__ import annotations

import json
import math

import pytest

from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

GENEVA = SCENES / "mech.geneva_six_slot.toml"
SCREW = SCENES / "mech.differential_screw.toml"
# the bank's mech.geneva_six_slot: exact values (SI here), and the book's printed ones with their rounding
EXACT = {"R_crank": 0.14999999999999997, "S_wheel": 0.2598076211353316, "h_slot": 0.13480762113533157,
         "r_lock": 0.11249999999999997, "k_motion": 0.3333333333333333, "T_cycle": 44.99999999999999,
         "n_dial": 1.3333333333333335}
BOOK = {"R_crank": 0.150, "S_wheel": 0.25981, "h_slot": 0.135, "r_lock": 0.1125, "T_cycle": 45.0}


def test_the_six_slot_geneva_matches_the_bank():
    q = values(check_json(GENEVA))
    for name, want in EXACT.items():
        assert q[name]["exact"] == pytest.approx(want, rel=1e-12), name
        assert q[name]["graphical"] == pytest.approx(want, rel=1e-12), name
    for name, want in BOOK.items():
        assert q[name]["graphical"] == pytest.approx(want, abs=0.5 * 10 ** -(len(str(want).split(".")[1]))), name
    assert q["h_slot"]["drawn_mm"] == pytest.approx(134.80762113533157 / 5, rel=1e-12)  # at μl = 0.005 m/mm
    assert q["n_dial"]["unit"] == "r/min"


def test_the_wheel_at_minus_20_degrees_by_the_polygons():
    q = values(check_json(GENEVA))
    w1, c, s = 2 * math.pi / 45, math.cos(math.radians(-20)), math.sin(math.radians(-20))
    d = 1.25 - c  # 1 − 2λ cos φ + λ², λ = 1/2
    assert q["omega_wheel"]["graphical"] == pytest.approx(w1 * 0.5 * (c - 0.5) / d, rel=1e-12)
    assert q["epsilon_wheel"]["graphical"] == pytest.approx(-w1 * w1 * 0.5 * 0.75 * s / d ** 2, rel=1e-12)
    assert q["omega_wheel_max"]["graphical"] == pytest.approx(w1, rel=1e-12)  # λ/(1 − λ) = 1 for z = 6
    assert max(r["rel_error"] for r in q.values()) < 1e-12


def test_the_hand_values_of_the_book_are_judged():
    # the book's 135 mm for the slot depth is 0.19 mm off 134.81: within 0.5 mm × μl on the drawing
    code, out, _ = run_cli("check", str(GENEVA), "--json", "--measured", "h_slot=0.135",
                           "--measured", "n_dial=1.3333", "--measured", "S_wheel=0.263")
    v = {m["name"]: m for m in json.loads(out)["measured"]}
    assert v["h_slot"]["ok"] and v["n_dial"]["ok"] and v["h_slot"]["tolerance"] == pytest.approx(0.0025)
    assert not v["S_wheel"]["ok"] and code == 1


def test_the_differential_screw_reports_both_branches():
    doc = check_json(SCREW)
    q = values(doc)
    assert q["p_B"]["graphical"] * 1000 == pytest.approx(3.0, abs=1e-12)  # the book's: pB = pA + s
    assert q["p_B_alt"]["graphical"] * 1000 == pytest.approx(2.5999999999999996, abs=1e-12)
    assert [(b["name"], b["hand"], b["link_2_moves"]) for b in doc["differential_screw"]] == [
        ("p_B", "right", "against"), ("p_B_alt", "right", "with")]
    code, out, _ = run_cli("check", str(SCREW))
    assert code == 0 and "p_B = 3 mm, right-hand" in out and "p_B_alt = 2.6 mm, right-hand" in out


@pytest.mark.parametrize(("hand_B", "travel"), [("right", -0.2), ("left", 5.8)])
def test_screw_b_given_gives_the_travel(tmp_path, hand_B, travel):
    p = tmp_path / "s.toml"
    p.write_text(f'[differential_screw]\nlead_A_mm = 2.8\nhand_A = "right"\nlead_B_mm = 3\nhand_B = "{hand_B}"\n',
                 encoding="utf-8")
    q = values(check_json(p))
    assert q["s_B"]["graphical"] * 1000 == pytest.approx(travel, abs=1e-12)
    assert q["s_B"]["exact"] * 1000 == pytest.approx(travel, abs=1e-12)


def test_a_name_the_scene_cannot_find_is_refused(tmp_path):
    assert_refused(run_cli("check", str(SCREW), "--measured", "s_B=1"), "mech.differential_screw.toml",
                   "s_B needs [differential_screw] lead_B")
    text = GENEVA.read_text(encoding="utf-8").replace("dial_angle_deg = -20\n", "")
    p = tmp_path / "g.toml"
    p.write_text(text, encoding="utf-8")
    assert_refused(run_cli("check", str(p)), "g.toml", "find[7]", "omega_wheel needs [geneva] dial_angle")


def test_a_hand_value_not_in_find_is_constructed_and_judged():
    # the rest and the motion are 2/3 and 1/3 of T = 45 s; the wheel's speed at −20° by the polygon
    code, out, _ = run_cli("check", str(GENEVA), "--json", "--measured", "t_rest=30", "--measured", "t_motion=15.1",
                           "--measured", "v_slide=0.0128")
    v = {m["name"]: m for m in json.loads(out)["measured"]}
    assert v["t_rest"]["ok"] and v["t_rest"]["expected"] == pytest.approx(30.0, rel=1e-14)
    assert not v["t_motion"]["ok"] and code == 1  # 15.1 s is 0.7 % off 15 s: more than 0.1 %
    assert v["v_slide"]["ok"] and v["v_slide"]["expected"] == pytest.approx(0.012859208752900383, rel=1e-12)


def test_extreme_times_and_speeds_are_refused_with_their_key(tmp_path):
    text = GENEVA.read_text(encoding="utf-8")
    for old, new, key in (("dwell_time_s = 30", "dwell_time_s = 1e-300", "geneva.dwell_time_s"),
                          ("dwell_time_s = 30", "dial_speed_rpm = 1e300", "geneva.dial_speed_rpm"),
                          ("dial_wheel_distance_mm = 300", "dial_wheel_distance_mm = 1e-300",
                           "geneva.dial_wheel_distance_mm")):
        p = tmp_path / "g.toml"
        p.write_text(text.replace(old, new), encoding="utf-8")
        assert_refused(run_cli("check", str(p)), "g.toml", key, "absurd for a mechanism")
