"""The textbook's cam problems (tests/reference/problems.toml) reproduced by their scenes."""
from __future__ import annotations

import math

import pytest

from tests.conftest import SCENES, check_json, values


def test_every_cam_problem_has_a_scene(problems):
    wanted = {pid for pid, p in problems.items() if p["area"] == "cam"}
    have = {p.stem.split("-")[0] for p in SCENES.glob("*.toml")}
    assert wanted <= have


@pytest.mark.parametrize("law, key", [("uniform", "uniform"), ("parabolic", "const_acc"), ("cosine", "cosine"),
                                      ("sine", "sine")])
def test_law_maxima(problems, law, key):
    p = problems["cam.law_maxima"]
    q = values(check_json(SCENES / f"cam.law_maxima-{law}.toml"))
    ex, book = p["exact"], p["book"]
    assert q["v_max"]["exact"] == pytest.approx(ex[f"{key}_vmax_m_s"], rel=1e-9)
    assert q["v_max"]["graphical"] == pytest.approx(ex[f"{key}_vmax_m_s"], rel=1e-9)  # on a division
    assert q["v_max"]["graphical"] == pytest.approx(book[f"{key}_vmax_m_s"], rel=1e-3)
    assert q["a_max"]["exact"] == pytest.approx(ex[f"{key}_amax_m_s2"], rel=1e-9, abs=1e-12)
    assert q["a_max"]["graphical"] == pytest.approx(book[f"{key}_amax_m_s2"], rel=1e-3, abs=1e-12)
    for which in ("vmax", "amax"):
        at = ex.get(f"{key}_{which}_at_rad")
        if isinstance(at, float):
            assert math.radians(q[f"{which[0]}_max_at"]["exact"]) == pytest.approx(at, abs=1e-9)


def test_uniform_law_reports_rigid_impacts_not_infinity():
    doc = check_json(SCENES / "cam.law_maxima-uniform.toml")
    rigid = sorted(i["angle_deg"] for i in doc["impacts"] if i["kind"] == "rigid")
    assert rigid == pytest.approx([0.0, 90.0, 180.0, 270.0])
    assert values(doc)["a_max"]["exact"] == 0.0  # inside the stroke; the ends are impulses
    assert sum("rigid impact" in w for w in doc["warnings"]) == 4


@pytest.mark.parametrize("sense", ["pos", "neg"])
def test_offset_roller_translating(problems, sense):
    p = problems["cam.offset_roller_translating"]
    doc = check_json(SCENES / f"cam.offset_roller_translating-{sense}.toml")
    q = values(doc)
    ex = p["exact"]
    assert q["alpha_max"]["exact"] == pytest.approx(ex[f"alpha_max_all_deg_{sense}"], rel=1e-9)
    assert q["alpha_max_at"]["exact"] == pytest.approx(ex[f"alpha_max_all_at_deg_{sense}"], abs=1e-9)
    # read off a 15° drawing, the largest pressure angle is within a few degrees (converges with the step)
    assert abs(q["alpha_max"]["graphical"] - q["alpha_max"]["exact"]) < 3.0
    # the book prints only the s table: every ordinate exact
    for angle, s_mm in zip(p["inputs"]["s_table_angles_deg"], p["book"]["s_table_mm"]):
        if angle < 360:
            assert q[f"s@{angle:g}"]["graphical"] * 1000 == pytest.approx(s_mm, abs=1e-9)
            assert q[f"s@{angle:g}"]["exact"] * 1000 == pytest.approx(s_mm, abs=1e-9)
    assert q["profile_deviation"]["graphical"] < 1e-3  # < 1 mm off the exact profile at 15° steps


def test_oscillating_roller(problems):
    p = problems["cam.oscillating_roller"]
    q = values(check_json(SCENES / "cam.oscillating_roller.toml"))
    for angle, phi_exact, phi_book in zip(p["inputs"]["table_angles_deg_corrected"], p["exact"]["phi_table_deg"],
                                          p["book"]["phi_table_deg"]):
        if angle == 0:
            continue
        row = q[f"s@{angle:g}"]
        assert row["graphical"] == pytest.approx(phi_exact, rel=1e-9)
        # printed to 2 decimals, and once (195°: 24.9 for 24.9061) rounded down
        assert row["graphical"] == pytest.approx(phi_book, abs=0.01)
    # the bank's α_max is sampled on a 0.01° grid, 1.7e-9 relative low (tests/exact/test_exact_cam.py)
    assert q["alpha_max"]["exact"] == pytest.approx(p["exact"]["alpha_max_deg_opposite_sense"], rel=5e-9)
    assert q["alpha_max_at"]["exact"] == pytest.approx(p["exact"]["alpha_max_at_deg_opposite_sense"], abs=0.005)


def test_the_division_table_lists_every_division_with_what_is_read_off_it(problems):
    p = problems["cam.offset_roller_translating"]
    doc = check_json(SCENES / "cam.offset_roller_translating-pos.toml")
    table = doc["divisions"]
    assert [round(r["delta_deg"], 6) for r in table] == p["inputs"]["profile_angles_deg"]
    assert [r["s"] * 1000 for r in table] == pytest.approx(p["exact"]["s_table_mm"][:24], abs=1e-9)
    # away from the joints the drawn pressure angle is within a degree of the exact one at 15° steps
    far = [r for r in table if min(abs(r["delta_deg"] - j) for j in (0, 150, 180, 240, 300, 360)) > 20]
    assert far and all(abs(r["alpha_deg"] - r["alpha_exact_deg"]) < 1.0 for r in far)
