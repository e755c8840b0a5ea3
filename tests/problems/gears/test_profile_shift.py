"""Profile shift designed in a gear scene: x chosen for a′, a repair, the least shift; y, Δy and the
tips shortened; the kind of drive; the book's problems (000 齿轮 5, 7, 8) by their scenes; the
extreme cases of issue 18 (undercut, negative shifts below a, a pointed tooth)."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.scene import parse_scene
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

PAIR = '[gear]\nm_mm = 10\nz = [12, 12]\nmeshing = "external"\n'


def read(text: str):
    return parse_scene(tomllib.loads(text), "g.toml").problem


def scene(tmp_path, text: str, find: list[str] | None = None):
    f = tmp_path / "g.toml"
    f.write_text((f"find = {find!r}\n".replace("'", '"') if find else "") + text)
    return f


# ------------------------------------------------------------------ reading the design words
def test_x_for_the_centre_distance_equal_or_with_x1():
    p = read(PAIR + 'centre_distance_mm = 130\nx = "for_centre_distance"\n')
    g1, g2 = p.gears.gears
    assert p.shift == "for_centre_distance"
    assert g1.x == g2.x == pytest.approx(0.625249092245772, rel=1e-13)
    assert g1.delta_y == g2.delta_y == pytest.approx(0.25049818449154393, rel=1e-12)   # tips shortened
    p = read(PAIR + 'centre_distance_mm = 130\nx = "for_centre_distance"\nx1 = 0.7\n')
    assert (p.gears.gears[0].x, p.gears.gears[1].x) == (0.7, pytest.approx(1.250498184491544 - 0.7, rel=1e-12))


def test_tip_shortening_can_be_switched_off_and_is_nil_for_a_zero_sum():
    p = read(PAIR + 'centre_distance_mm = 130\nx = "for_centre_distance"\ntip_shortening = false\n')
    assert p.gears.gears[0].delta_y == 0.0
    p = read(PAIR + "x = [0.3, -0.3]\n")
    assert p.gears.gears[0].delta_y == 0.0
    # stated shifts, no a′: shortened at the distance without backlash, as the book does
    p = read(PAIR + "x = [0.5, 0.5]\n")
    assert p.gears.gears[0].delta_y > 0.0


def test_least_shifts_by_the_rule_and_exactly():
    p = read('[gear]\nm_mm = 4\nz = 15\nx = "least"\n')
    assert p.gears.gears[0].x == pytest.approx(2.0 / 17.0, rel=1e-15)
    p = read('[gear]\nm_mm = 4\nz = 15\nx = "least_exact"\n')
    assert p.gears.gears[0].x == pytest.approx(1.0 - 7.5 * math.sin(math.radians(20)) ** 2, rel=1e-14)


def test_a_rack_pinion_takes_its_shift_from_the_centre_distance():
    p = read('[gear]\nm_mm = 2\nz = [12]\nmeshing = "rack"\ncentre_distance_mm = 12.8\nx = "for_centre_distance"\n')
    assert p.gears.gears[0].x == pytest.approx(0.4, rel=1e-12)


@pytest.mark.parametrize("body, where, words", [
    ('x = "maximal"\n', "gear.x", ("unknown value", "for_centre_distance")),
    ('x = "for_centre_distance"\n', "gear.centre_distance", ("missing", "a′")),
    ('x = "repair"\n', "gear.thickness_loss", ("missing", "thickness loss")),
    ('x = [0.1, 0.2]\nx1 = 0.1\n', "gear.x1", ('x = "for_centre_distance"',)),
    ('thickness_loss_mm = 1\n', "gear.thickness_loss_mm", ('x = "repair"',)),
    ('x = "repair"\nthickness_loss_mm = 0.5\ncentre_distance_mm = 121\n', "gear.centre_distance_mm",
     ("zero-sum", "120 mm")),
    ('x = "for_centre_distance"\ncentre_distance_mm = 100\n', "gear.centre_distance_mm", ("base circles",)),
])
def test_bad_design_keys_are_refused_in_one_line(tmp_path, body, where, words):
    f = scene(tmp_path, PAIR + body)
    err = assert_refused(run_cli("check", str(f)), "g.toml", *words)
    assert f"{where}: " in err


def test_design_words_that_do_not_fit_the_set_are_refused(tmp_path):
    ring = '[gear]\nm_mm = 2\nz = [20, 80]\nmeshing = "internal"\nx = "least"\n'
    assert_refused(run_cli("check", str(scene(tmp_path, ring))), "g.toml", "gear.x", "pinion cutter")
    one = '[gear]\nm_mm = 2\nz = 20\nx = "repair"\nthickness_loss_mm = 0.5\n'
    assert_refused(run_cli("check", str(scene(tmp_path, one))), "g.toml", "gear.x", "external pair")
    short = '[gear]\nm_mm = 2\nz = 20\ntip_shortening = true\n'
    assert_refused(run_cli("check", str(scene(tmp_path, short))), "g.toml", "gear.tip_shortening")
    find_dy = '[gear]\nm_mm = 2\nz = [20, 80]\nmeshing = "internal"\n'
    assert_refused(run_cli("check", str(scene(tmp_path, find_dy, ["delta_y"]))), "g.toml",
                   "find[0]", "delta_y")


# ------------------------------------------------------------------ rows: construction against closed form
def test_every_shift_row_agrees_and_says_the_drive(tmp_path):
    f = scene(tmp_path, PAIR + 'centre_distance_mm = 130\nx = "for_centre_distance"\n',
              ["x_sum", "x1", "x2", "x_min1", "x_min_exact1", "z_min", "z_min_exact", "y", "delta_y", "da1", "sa1"])
    doc = check_json(f)
    q = values(doc)
    for name in q:
        assert q[name]["graphical"] == pytest.approx(q[name]["exact"], rel=1e-9, abs=1e-12), name
    assert q["z_min"]["graphical"] == 17 and q["z_min_exact"]["exact"] == pytest.approx(17.097264340826062)
    assert doc["gear"]["drive"] == "positive"
    code, out, _ = run_cli("check", str(f))
    assert "positive drive" in out and "tips shortened by Δy·m = 2.50498 mm" in out


@pytest.mark.parametrize("x, kind", [("[0, 0]", "standard"), ("[0.4, -0.4]", "equal and opposite"),
                                     ("[0.4, 0.2]", "positive"), ("[-0.3, 0.1]", "negative")])
def test_the_kind_of_drive_in_json(tmp_path, x, kind):
    f = scene(tmp_path, '[gear]\nm_mm = 2\nz = [30, 40]\nmeshing = "external"\n' + f"x = {x}\n", ["a_w"])
    assert check_json(f)["gear"]["drive"] == kind


# ------------------------------------------------------------------ extreme cases
def test_below_the_standard_distance_with_negative_shifts(tmp_path):
    f = scene(tmp_path, '[gear]\nm_mm = 10\nz = [30, 40]\nmeshing = "external"\ncentre_distance_mm = 345\n'
                        'x = "for_centre_distance"\n', ["x_sum", "x1", "y", "delta_y", "alpha_w", "eps_alpha"])
    doc = check_json(f)
    q = values(doc)
    assert q["x_sum"]["graphical"] < 0 and q["y"]["graphical"] == pytest.approx(-0.5)
    assert q["alpha_w"]["graphical"] < 20.0
    for name in q:
        assert q[name]["graphical"] == pytest.approx(q[name]["exact"], rel=1e-9, abs=1e-12), name
    assert doc["gear"]["drive"] == "negative"


def test_a_shift_below_x_min_is_undercut_drawn_and_said(tmp_path):
    f = scene(tmp_path, '[gear]\nm_mm = 4\nz = 18\nx = -1.5\n', ["x", "x_min", "x_min_exact", "s_pitch"])
    code, out, err = run_cli("check", str(f))
    assert code == 0 and "undercut" in err and "x_min = -0.0528" in err
    svg = tmp_path / "g.svg"
    assert run_cli("render", str(f), "-o", str(svg))[0] == 0
    assert ">undercut<" in svg.read_text()


def test_a_shift_that_makes_the_tooth_pointed_is_said(tmp_path):
    f = scene(tmp_path, '[gear]\nm_mm = 4\nz = 10\nx = 1.2\n', ["sa", "ra_pointed"])
    code, out, err = run_cli("check", str(f))
    assert code == 0 and "pointed below its tip circle" in err
    q = values(check_json(f))
    assert q["ra_pointed"]["graphical"] < 0.5 * 0.004 * 10 + 2.2 * 0.004


# ------------------------------------------------------------------ the book's problems
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
