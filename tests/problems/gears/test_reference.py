"""The textbook's gear problems of issue 17 (tests/reference/problems.toml) reproduced by their
scenes: the construction and the closed form both against the bank's exact values, the book's
printed answers within its flag."""
from __future__ import annotations

import html
import math
import tomllib

import pytest

from tests.conftest import SCENES, check_json, values

#: The gear problems issue 17 poses; issue 18's (profile shift, the rack cutter, helical and worm gears) are
#: tested below and in test_generation.py and test_spatial.py.
POSED = ("gear.involute_z20_m8", "gear.root_circle_equals_base_circle", "gear.contact_ratio_19_42")
#: Bank key → (check name, factor from the check's SI value to the bank's unit).
KEYS = {"d_mm": ("d", 1e3), "da_mm": ("da", 1e3), "db_mm": ("db", 1e3), "rho_pitch_mm": ("rho_pitch", 1e3),
        "alpha_a_deg": ("alpha_a", 1.0), "rho_a_mm": ("rho_a", 1e3), "sa_mm": ("sa", 1e3), "sb_mm": ("sb", 1e3),
        "inv_alpha_a_pointed": ("inv_alpha_a_pointed", 1.0), "alpha_a_pointed_deg": ("alpha_a_pointed", 1.0),
        "ra_pointed_mm": ("ra_pointed", 1e3), "z_root_eq_base": ("z_root_eq_base", 1.0),
        "alpha_a1_deg": ("alpha_a1", 1.0), "alpha_a2_deg": ("alpha_a2", 1.0), "B1B2_mm": ("B1B2", 1e3),
        "eps_alpha": ("eps_alpha", 1.0)}


def test_each_posed_problem_has_its_scene(problems):
    have = {p.stem for p in SCENES.glob("gear.*.toml")}
    assert set(POSED) <= have
    assert all(problems[pid]["area"] == "gear" for pid in POSED)


@pytest.mark.parametrize("pid", POSED)
def test_construction_and_closed_form_against_the_bank(problems, pid):
    p = problems[pid]
    q = values(check_json(SCENES / f"{pid}.toml"))
    checked = 0
    for key, want in p["exact"].items():
        if key not in KEYS:
            continue
        name, factor = KEYS[key]
        assert q[name]["exact"] * factor == pytest.approx(want, rel=1e-12), key
        assert q[name]["graphical"] * factor == pytest.approx(want, rel=1e-9), key
        book = p["book"].get(key)
        if book is not None:  # the book's tables and misprints: within its rel_diff, which the flag/note explains
            assert q[name]["graphical"] * factor == pytest.approx(book, rel=abs(p["rel_diff"][key]) + 1e-4), key
        checked += 1
    assert checked == len([k for k in p["exact"] if k in KEYS]) >= 1


def test_root_circle_is_larger_from_42_teeth(problems):
    q = values(check_json(SCENES / "gear.root_circle_equals_base_circle.toml"))
    ex = problems["gear.root_circle_equals_base_circle"]["exact"]
    # the scene's gear has z = 42, m = 1 mm: d_f − d_b in mm is the bank's per-module value
    assert (q["df"]["graphical"] - q["db"]["graphical"]) * 1e3 == pytest.approx(ex["z42_root_minus_base_mm_per_m"],
                                                                                rel=1e-9)


def test_the_misprinted_alpha_a2_is_the_books_not_ours(problems):
    q = values(check_json(SCENES / "gear.contact_ratio_19_42.toml"))
    book = problems["gear.contact_ratio_19_42"]["book"]["alpha_a2_deg"]
    assert abs(q["alpha_a2"]["graphical"] - book) > 0.05  # 26°19′ printed, 26°14.2′ true


# ------------------------------------------------------------------ issue 18: profile shift (000 齿轮 5, 7, 8)
def bank(problems, pid, scene_name, names):
    p = problems[pid]
    q = values(check_json(SCENES / f"{scene_name}.toml"))
    for key, name in names.items():
        want = p["exact"][key]
        got = q[name]["graphical"] * (1e3 if key.endswith("_mm") else 1.0)
        assert got == pytest.approx(want, rel=1e-9, abs=1e-12), key
        book = p["book"].get(key)
        if book is not None:
            assert got == pytest.approx(book, rel=abs(p["rel_diff"][key]) + 1e-4, abs=1e-9), key
    return q


def test_profile_shifted_12_12_a130(problems):
    bank(problems, "gear.profile_shifted_12_12_a130", "gear.profile_shifted_12_12_a130", {
        "a_mm": "a", "alpha_w_deg": "alpha_w", "x_sum": "x_sum", "x1": "x1", "x_min": "x_min1", "y": "y",
        "delta_y": "delta_y", "ha_mm": "ha1", "hf_mm": "hf1", "d_mm": "d1", "da_mm": "da1", "df_mm": "df1",
        "db_mm": "db1", "s_mm": "s_pitch1", "alpha_a_deg": "alpha_a1", "eps_alpha": "eps_alpha", "sa_mm": "sa1"})
    # the book's check: s_a ≥ 0.25m holds
    q = values(check_json(SCENES / "gear.profile_shifted_12_12_a130.toml"))
    assert q["sa1"]["graphical"] > 0.25 * 0.010


def test_reverted_train_scheme_1(problems):
    ex = problems["gear.reverted_train_centre_distances"]["exact"]
    q12 = values(check_json(SCENES / "gear.reverted_train_centre_distances-12.toml"))
    doc34 = check_json(SCENES / "gear.reverted_train_centre_distances-34.toml")
    q34 = values(doc34)
    assert q12["a"]["graphical"] * 1e3 == pytest.approx(ex["a12_mm"], rel=1e-12)
    assert q34["a"]["graphical"] * 1e3 == pytest.approx(ex["a34_mm"], rel=1e-12)
    assert q34["a_w"]["graphical"] == pytest.approx(q12["a_w"]["graphical"], rel=1e-12)   # one centre distance
    assert doc34["gear"]["drive"] == "positive" and q34["x_sum"]["graphical"] > 0


def test_repair_shift_17_118(problems):
    names = {"a_mm": "a", "x1": "x1", "x2": "x2", "d1_mm": "d1", "ha1_mm": "ha1", "hf1_mm": "hf1", "da1_mm": "da1",
             "df1_mm": "df1", "db1_mm": "db1", "s1_mm": "s_pitch1", "e1_mm": "e_pitch1", "d2_mm": "d2",
             "ha2_mm": "ha2", "hf2_mm": "hf2", "da2_mm": "da2", "df2_mm": "df2", "db2_mm": "db2",
             "s2_mm": "s_pitch2", "e2_mm": "e_pitch2", "p_mm": "p"}
    q = bank(problems, "gear.repair_shift_17_118", "gear.repair_shift_17_118", names)
    # the re-cut wheel is 0.75 mm thinner than a standard tooth, the new pinion 0.75 mm thicker
    assert (q["s_pitch1"]["graphical"] - math.pi * 0.005 / 2) * 1e3 == pytest.approx(0.75, rel=1e-12)


ISSUE18 = ("gear.profile_shifted_12_12_a130", "gear.rack_cutter_generation_cases", "gear.reverted_train_centre_distances",
           "gear.repair_shift_17_118", "gear.helical_20_40_mn8", "gear.worm_i20.5_m5")


@pytest.mark.parametrize("pid", ISSUE18)
def test_each_issue18_problem_has_its_scenes_and_figures(problems, pid):
    scenes = sorted(SCENES.glob(f"{pid}.toml")) + sorted(SCENES.glob(f"{pid}-*.toml"))
    assert scenes and problems[pid]["area"] == "gear"
    for scene in scenes:
        svg = (SCENES.parent / f"{scene.stem}.svg").read_text(encoding="utf-8")
        doc = check_json(scene)
        data = tomllib.loads(scene.read_text(encoding="utf-8"))
        assert html.escape(data["title"], quote=False) in svg, scene.stem     # the figure is this scene's
        # every value the scene asks for is found, and agrees with its closed form (or within its estimate)
        asked = data.get("find", [])
        names = [q["name"] for q in doc["quantities"]]
        assert names == asked if asked else len(names) >= 10, scene.stem   # no find: the bank's default list
        for q in doc["quantities"]:
            assert q["rel_error"] <= (q["error_estimate"] if q["error_estimate"] is not None else 1e-9), q
