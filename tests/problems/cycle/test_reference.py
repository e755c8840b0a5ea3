"""The "linkage-properties" problems of tests/reference/problems.toml reproduced by their scenes.

The drawn values (extreme positions constructed at μl, angles measured on the drawing) agree with
the closed forms (cosine rule) to 1e-12 and the bank's exact values to 1e-9; the book's graphical
answers within 0.3 %.
"""
from __future__ import annotations

import pytest

from tests.conftest import SCENES, check_json, values


def test_every_linkage_properties_problem_has_a_scene(problems):
    wanted = {pid for pid, p in problems.items() if p["area"] == "linkage-properties"}
    have = {p.stem.split("-")[0] for p in SCENES.glob("*.toml")}
    assert wanted <= have


def test_fourbar_28_52_50_72(problems):
    p = problems["linkage.fourbar_28_52_50_72"]
    doc = check_json(SCENES / "linkage.fourbar_28_52_50_72.toml")
    q = values(doc)
    assert doc["characteristics"]["grashof"] == p["exact"]["type"] == p["book"]["type"]
    assert doc["characteristics"]["grashof_exact"] == p["exact"]["type"]
    pairs = {"theta": "theta_deg", "psi": "psi_deg", "gamma_min": "gamma_min_deg", "K": "K"}
    for name, key in pairs.items():
        row = q[name]
        assert row["graphical"] == pytest.approx(row["exact"], rel=1e-12)
        assert row["exact"] == pytest.approx(p["exact"][key], rel=1e-9)
        assert row["graphical"] == pytest.approx(p["book"][key], rel=3e-3)
    assert q["theta"]["exact"] == pytest.approx(18.56167198391183, rel=1e-12)  # cosine rule, by hand
    # γmin where the crank lies along the frame, away from D; the working stroke starts folded
    assert q["gamma_min_at"]["graphical"] == pytest.approx(180.0, abs=1e-9)
    assert (q["phi_end"]["graphical"] - q["phi_start"]["graphical"]) % 360 == pytest.approx(180 + q["theta"]["exact"])
    assert all(v["ok"] for v in doc["measured"])  # the book's readings are within drawing precision


def test_grashof_ranges(problems):
    p = problems["linkage.grashof_ranges"]
    doc = check_json(SCENES / "linkage.grashof_ranges.toml")
    q = values(doc)
    ex, book = p["exact"], p["book"]
    pairs = {"l_AB_crank_rocker_AB_max": "crank_rocker_lAB_max_mm", "l_AB_double_crank_min": "double_crank_lAB_min_mm",
             "l_AB_double_crank_max": "double_crank_lAB_max_mm", "l_AB_double_rocker_2_max": "double_rocker_upper_limit_mm"}
    for name, key in pairs.items():
        assert q[name]["graphical"] * 1000 == pytest.approx(ex[key], rel=1e-12)
        assert q[name]["exact"] * 1000 == pytest.approx(book[key], rel=1e-12)
    # the class sequence of the bank: crank-rocker → double rocker → double crank → double rocker → none
    classes = [r["class"] for r in doc["grashof_ranges"]]
    assert classes == ["crank_rocker_AB", "double_rocker", "double_crank", "double_rocker"]
    assert [round(r["max"] * 1000, 9) for r in doc["grashof_ranges"]] == [15.0, 45.0, 55.0, 115.0]
    assert doc["characteristics"]["grashof"] == "crank_rocker_AB"  # as drawn, AB = 10 mm


def test_quick_return_timing(problems):
    p = problems["linkage.quick_return_timing"]
    q = values(check_json(SCENES / "linkage.quick_return_timing.toml"))
    assert q["theta"]["exact"] == pytest.approx(p["inputs"]["theta_deg"], rel=1e-12)
    assert q["K"]["graphical"] == pytest.approx(1.4, rel=1e-12)
    for name, key in {"phi_work": "phi_work_deg", "phi_return": "phi_return_deg", "t_return": "t_return_s",
                      "crank_period": "crank_period_s", "n_crank": "n_crank_r_min"}.items():
        assert q[name]["graphical"] == pytest.approx(p["exact"][key], rel=1e-12)
        if key in p["book"]:
            assert q[name]["graphical"] == pytest.approx(p["book"][key], rel=1e-12)


def test_quick_return_timing_on_a_guide_bar(problems):
    """The same timing on a guide-bar mechanism: θ = ψ = 2·arcsin(AB/AC), γ = 90°."""
    p = problems["linkage.quick_return_timing"]
    q = values(check_json(SCENES / "linkage.quick_return_timing-guide_bar.toml"))
    assert q["theta"]["graphical"] == pytest.approx(p["inputs"]["theta_deg"], rel=1e-12)
    assert q["psi"]["graphical"] == pytest.approx(q["theta"]["graphical"], rel=1e-12)
    assert q["gamma_min"]["graphical"] == q["gamma_min"]["exact"] == 90.0
    for name, key in {"t_return": "t_return_s", "crank_period": "crank_period_s", "n_crank": "n_crank_r_min"}.items():
        assert q[name]["graphical"] == pytest.approx(p["exact"][key], rel=1e-12)


def test_offset_slider_crank_characteristics_by_hand():
    """H = √(400² − 30²) − √(200² − 30²), θ = asin(30/200) − asin(30/400), cos γmin = (100 + 30)/300."""
    import math

    q = values(check_json(SCENES / "linkage.slider_crank_offset-characteristics.toml"))
    assert q["stroke"]["graphical"] * 1000 == pytest.approx(math.sqrt(400**2 - 30**2) - math.sqrt(200**2 - 30**2), rel=1e-12)
    theta = math.degrees(math.asin(30 / 200) - math.asin(30 / 400))
    assert q["theta"]["graphical"] == pytest.approx(theta, rel=1e-12)
    assert q["K"]["graphical"] == pytest.approx((180 + theta) / (180 - theta), rel=1e-12)
    assert q["gamma_min"]["graphical"] == pytest.approx(math.degrees(math.acos(130 / 300)), rel=1e-12)
    assert q["gamma_min_at"]["graphical"] == pytest.approx(270.0)  # the guide is above A: the crank points down
    assert q["stroke"]["drawn_mm"] == pytest.approx(q["stroke"]["graphical"] / 0.004, rel=1e-12)
