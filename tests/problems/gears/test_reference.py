"""The textbook's gear problems of issue 17 (tests/reference/problems.toml) reproduced by their
scenes: the construction and the closed form both against the bank's exact values, the book's
printed answers within its flag."""
from __future__ import annotations

import pytest

from tests.conftest import SCENES, check_json, values

#: The gear problems issue 17 poses (profile shift, the rack cutter, helical and worm gears are the next issue's).
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
