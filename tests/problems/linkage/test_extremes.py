"""Stiff and extreme cases: dead centres, near-collinear links, extreme sizes and speeds.

Each case either stays accurate (rel. error ≤ 1e-9) or says clearly that it cannot — a row
flagged ill-conditioned with a warning, or a one-line error naming the step — never a silent
wrong value.
"""
from __future__ import annotations

import math

import pytest

from tests.conftest import check_json, fourbar_scene, run_cli, values
from tests.scenes import scene_text, write_scene


def non_grashof(angle: float) -> str:
    """AB 60, BC 30, CD 40, AD 80: a double rocker whose crank stops where C lies on BD."""
    return fourbar_scene(a=60, b=30, c=40, d=80, angle=repr(angle), scales="[scales]\nl_m_per_mm = 0.001",
                         find='["v_C", "omega_2", "omega_3", "a_C", "alpha_2", "alpha_3"]')

# B, C, D collinear (|BD| = BC + CD = 70 mm): cos φ = (60² + 80² − 70²)/(2·60·80)
PHI_TOGGLE = math.degrees(math.acos((60 ** 2 + 80 ** 2 - 70 ** 2) / (2 * 60 * 80)))


write = write_scene


def test_four_bar_exactly_at_the_toggle_is_refused_naming_the_step(tmp_path):
    p = write(tmp_path, non_grashof(PHI_TOGGLE))
    code, out, err = run_cli("check", str(p))
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "scene.toml" in err and "parallel" in err and "⟂" in err  # names the velocity step


@pytest.mark.parametrize("offset_deg", [1e-2, 1e-4, 1e-6])
def test_four_bar_next_to_the_toggle_is_accurate_or_warns(tmp_path, offset_deg):
    p = write(tmp_path, non_grashof(PHI_TOGGLE - offset_deg))
    doc = check_json(p)
    assert doc["warnings"], "an intersection this shallow must be reported"
    assert any("intersection" in w for w in doc["warnings"])
    for row in doc["quantities"]:
        assert math.isfinite(row["graphical"]) and math.isfinite(row["exact"])
        assert row["rel_error"] <= 1e-9 or row["ill_conditioned"], row
    rows = values(doc)
    # the rocker's angular velocity grows like 1/√δφ as the toggle nears: a real, large value
    assert abs(rows["omega_3"]["exact"]) > 10.0


SLIDER_DRIVEN = """
title = "slider-crank driven by its slider"
show = ["mechanism", "velocity", "acceleration"]
find = ["omega_1", "omega_2", "v_B"]
[units]
length = "mm"
[frame]
A = [0, 0]
[driver]
type = "slider"
link = "3"
point = "C"
guide = {{ through = [0, 0], angle_deg = 0 }}
position = {s}
velocity_m_s = 1.0
acceleration_m_s2 = 0.0
[[dyad]]
type = "RRR"
joints = ["C", "B", "A"]
links = ["2", "1"]
lengths = [100, 40]
branch = "left"
"""


@pytest.mark.parametrize("s", [140.0, 60.0])  # outer and inner dead centre: l2 ± l1
def test_slider_driven_slider_crank_at_a_dead_centre_cannot_be_constructed(tmp_path, s):
    p = write(tmp_path, SLIDER_DRIVEN.format(s=s))
    code, out, err = run_cli("check", str(p))
    assert code == 2, err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "parallel" in err or "assembled" in err


def test_slider_driven_dead_centres_in_a_batch_are_marked_and_the_rest_checked(tmp_path):
    p = write(tmp_path, SLIDER_DRIVEN.format(s="[60.0, 80.0, 100.0, 120.0, 140.0]"))
    doc = check_json(p)
    names = {q["name"].split("@")[1] for q in doc["quantities"]}
    assert names == {"80", "100", "120"}
    assert sum("construction impossible" in w for w in doc["warnings"]) == 2
    for row in doc["quantities"]:
        assert row["rel_error"] <= 1e-9 or row["ill_conditioned"]


def test_slider_driven_near_dead_centre_warns(tmp_path):
    p = write(tmp_path, SLIDER_DRIVEN.format(s=140.0 - 1e-7))
    doc = check_json(p)
    assert any("ill-conditioned" in w or "shallow" in w for w in doc["warnings"])
    for row in doc["quantities"]:
        assert row["rel_error"] <= 1e-9 or row["ill_conditioned"], row


CRANK_SLIDER = scene_text("linkage/slider_crank_centred")


def test_crank_driven_slider_crank_dead_centres_are_normal_results(tmp_path):
    doc = check_json(write(tmp_path, CRANK_SLIDER))
    rows = values(doc)
    for at in ("0", "180"):
        assert abs(rows[f"v_C@{at}"]["graphical"]) < 1e-15  # v_C = 0 is a result, not an error
        assert rows[f"omega_2@{at}"]["graphical"] == pytest.approx(
            (-1 if at == "0" else 1) * 10 * 40 / 100, rel=1e-12)
        assert rows[f"alpha_2@{at}"]["graphical"] == pytest.approx(0.0, abs=1e-12)
        # a_C = ω1²·l1·(1 ± l1/l2) at the dead centres
        ac = 100 * 0.04 * (1 + 0.4) if at == "0" else 100 * 0.04 * (1 - 0.4)
        assert abs(rows[f"a_C@{at}"]["graphical"]) == pytest.approx(ac, rel=1e-12)
    assert all(r["rel_error"] <= 1e-12 for r in doc["quantities"])
    assert not any("ill-conditioned" in w for w in doc["warnings"])


FIND9 = '["v_C", "v_CB", "omega_2", "omega_3", "a_C", "a_CB_n", "a_CB_t", "alpha_2", "alpha_3"]'


def fourbar(a: float, b: float, c: float, d: float, w: float, e: float) -> str:
    return fourbar_scene(a=a, b=b, c=c, d=d, omega=w, epsilon=e, angle="[30, 100, 165, 250]", find=FIND9)


@pytest.mark.parametrize("w", [1e-6, 1.0, 1e6, -1e6])
def test_angular_velocity_from_1e_minus_6_to_1e6(tmp_path, w):
    doc = check_json(write(tmp_path, fourbar(60, 120, 90, 120, w, 0)))
    assert len(doc["quantities"]) == 36
    for row in doc["quantities"]:
        assert row["rel_error"] <= 1e-9, row
    rows = values(doc)
    assert rows["omega_2@165"]["graphical"] == pytest.approx(w * 0.25384873231226734, rel=1e-9)


def test_link_lengths_differing_by_a_million(tmp_path):
    # a 1 µm crank driving 1 m links: a crank-rocker whose rocker barely moves
    doc = check_json(write(tmp_path, fourbar(0.001, 1000, 1000, 1000, 10, 5)))
    for row in doc["quantities"]:
        assert row["rel_error"] <= 1e-9, row
    rows = values(doc)
    assert abs(rows["omega_3@100"]["exact"]) < 1e-5 * 10


def test_angular_acceleration_of_the_crank_is_drawn(tmp_path):
    doc = check_json(write(tmp_path, fourbar(60, 120, 90, 120, 10, -40)))
    for row in doc["quantities"]:
        assert row["rel_error"] <= 1e-12, row


def test_speeds_beyond_double_precision_are_one_line_errors(tmp_path):
    code, out, err = run_cli("check", str(write(tmp_path, fourbar(60, 120, 90, 120, 1e155, 0))))
    assert code == 2 and err.count("\n") == 1 and "out of the range of double precision" in err


def test_a_mechanism_far_from_the_origin_is_flagged_not_trusted(tmp_path):
    text = fourbar(60, 120, 90, 120, 10, 0).replace(
        "A = [0, 0]\nD = [120, 0]", "A = [1e11, 0]\nD = [100000000120, 0]")
    doc = check_json(write(tmp_path, text))
    assert any("from the origin" in w for w in doc["warnings"])
    assert doc["quantities"] and all(r["ill_conditioned"] for r in doc["quantities"])


def test_a_guide_bar_through_its_own_crank_pin_is_refused_not_drawn(tmp_path):
    """AB = AC = 100 mm at φ = −90°: the crank pin B lies on the bar's pivot C."""
    text = scene_text("linkage/guide_bar_pin_near_pivot").replace("length = 99.9998", "length = 100")
    code, out, err = run_cli("check", str(write(tmp_path, text)))
    assert code == 2 and "coincide" in err and err.count("\n") == 1
