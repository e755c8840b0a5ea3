"""The gear check: every row a construction against the closed form, to round-off; warnings said
plainly (undercut, pointed, ε < 1, interference); a student's measurements judged."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.errors import SceneError
from graphmech.problems import check
from graphmech.problems.gears.check import analyse, judge, panels_for
from graphmech.scene import parse_scene
from tests.conftest import SCENES, check_json, run_cli, values
from tests.scenes import scene_path


def scene(text: str):
    return parse_scene(tomllib.loads(text), "g.toml")


def rows(text: str) -> dict:
    return {r.name: r for r in analyse(scene(text)).rows}


ALL_TOOTH = '["d", "db", "da", "df", "ha", "hf", "p", "pb", "s_pitch", "e_pitch", "sa", "sb", "alpha_a", ' \
            '"rho_pitch", "rho_a", "ra_pointed", "alpha_a_pointed", "inv_alpha_a_pointed", "s_k@85", "alpha_k@85", ' \
            '"rho_k@85", "theta_k@85", "W", "d_pin", "M", "z_root_eq_base"]'


@pytest.mark.parametrize("gear", ["z = 20\nx = 0", "z = 13\nx = 0.3", "z = 60\nx = -0.4", "z = 17\nx = 0",
                                  "z = 101\nx = 0.1"])
def test_every_tooth_quantity_agrees_with_the_closed_form(gear):
    got = rows(f"find = {ALL_TOOTH.replace('@85', '@' + _inside(gear))}\n[gear]\nm_mm = 8\n{gear}\n")
    assert len(got) == 26
    for r in got.values():
        assert r.rel_error <= 1e-9, r
        if r.drawn_mm is not None:
            assert r.graphical == pytest.approx(r.drawn_mm * r.scale, rel=1e-12)


def _inside(gear: str) -> str:
    """A radius between the base and the tip circle of that gear (m = 8), in mm."""
    z = int(gear.split()[2])
    return f"{8 * z / 2 * (0.5 * math.cos(math.radians(20)) + 0.5) + 2:.1f}"


@pytest.mark.parametrize("pair", [
    'z = [19, 42]\nmeshing = "external"',
    'z = [12, 12]\nx = [0.35, 0.35]\nmeshing = "external"',
    'z = [12, 12]\nx = [0.3, 0.3]\nmeshing = "external"\ncentre_distance_mm = 131',
    'z = [20, 80]\nmeshing = "internal"',
    'z = [24, 70]\nx = [0.2, 0.5]\nmeshing = "internal"\ncentre_distance_mm = 232.5',
    'z = [18]\nmeshing = "rack"',
    'z = [18]\nx = [0.2]\nmeshing = "rack"\ncentre_distance_mm = 92',
    'z = [20, 1000]\nmeshing = "external"',
])
def test_every_pair_quantity_agrees_with_the_closed_form(pair):
    names = '["a", "a_w", "alpha_w", "rw1", "rw2", "N1N2", "B1B2", "pb", "eps_alpha", "single_contact", ' \
            '"double_contact", "eta_tip1", "eta_root1", "eta_tip2", "eta_root2", "backlash", "da1", "alpha_a1"]'
    sc = scene(f"[gear]\nm_mm = 10\n{pair}\n")
    from graphmech.problems.gears.scene import quantity_unit

    names_here = [n for n in tomllib.loads(f"f = {names}")["f"] if quantity_unit(n, sc.problem) is not None]
    got = rows(f"find = {names_here!r}\n[gear]\nm_mm = 10\n{pair}\n".replace("'", '"'))
    assert {"B1B2", "eps_alpha", "alpha_w", "a_w"} <= set(got)
    for r in got.values():
        assert r.rel_error <= 1e-9 or abs(r.graphical - r.exact) <= 1e-12, r


def test_the_book_pair_19_42():
    q = values(check_json(SCENES / "gear.contact_ratio_19_42.toml"))
    assert q["B1B2"]["graphical"] == pytest.approx(24.10920747019434e-3, rel=1e-12)
    assert q["eps_alpha"]["graphical"] == pytest.approx(1.6333424177366997, rel=1e-12)
    pb = 5e-3 * math.pi * math.cos(math.radians(20))
    assert q["double_contact"]["graphical"] == pytest.approx((1.6333424177366997 - 1) * pb, rel=1e-9)
    assert q["single_contact"]["graphical"] == pytest.approx((2 - 1.6333424177366997) * pb, rel=1e-9)


def test_a_hand_measured_contact_ratio_is_judged_within_what_the_drawing_allows():
    an = analyse(scene('find = ["B1B2", "eps_alpha"]\n[gear]\nm_mm = 5\nz = [19, 42]\nmeshing = "external"\n'
                       '[measured]\nB1B2 = 0.0240\neps_alpha = 1.62\n[scales]\nzones_mm_per_mm = 0.2\n'))
    v = {x.name: x for x in judge(an)}
    # 0.5 mm of drawing precision at μl = 0.2 mm/mm: ±0.1 mm on B1B2; ε within 1.633·(0.1/24.1 + 0.1/14.76)
    assert v["B1B2"].tolerance == pytest.approx(0.5 * 0.2e-3) and not v["B1B2"].ok  # 24.0 vs 24.109
    assert v["eps_alpha"].tolerance == pytest.approx(1.6333424 * (0.1 / 24.1092 + 0.1 / 14.7607), rel=1e-4)
    assert v["eps_alpha"].ok  # 1.62 is within ±0.018
    an = analyse(scene('[gear]\nm_mm = 5\nz = [19, 42]\nmeshing = "external"\n[measured]\neps_alpha = 1.5\n'))
    assert not judge(an)[0].ok


def test_contact_ratio_below_one_is_said_plainly():
    # a very high working pressure angle: teeth of h*a = 0.6 on a pair pulled apart
    sc = scene('[gear]\nm_mm = 5\nz = [20, 20]\nha_star = 0.6\nmeshing = "external"\ncentre_distance_mm = 101.5\n')
    an, _, doc, lines = check(sc)
    r = {x.name: x for x in an.rows}
    assert r["eps_alpha"].graphical < 1.0
    assert any("not continuous" in ln for ln in lines)
    assert doc["gear"]["continuous"] is False


def test_undercut_is_said_at_and_below_the_limit():
    def warns(z: int, x: float = 0.0) -> list[str]:
        return analyse(scene(f"[gear]\nm_mm = 5\nz = {z}\nx = {x!r}\n")).warnings

    # the book's z_min = 17 is the exact 2h*a/sin²α = 17.097 rounded: z = 17 is undercut by a hair
    assert not any("undercut" in w for w in warns(18))
    assert any("undercut" in w and "17.1" in w for w in warns(17)) and any("undercut" in w for w in warns(8))
    x_min = 1 - 17 * math.sin(math.radians(20)) ** 2 / 2  # exactly at the limit: not undercut
    assert not any("undercut" in w for w in warns(17, x_min + 1e-12))
    assert any("undercut" in w for w in warns(17, x_min - 1e-6))


def test_a_pointed_tooth_is_said_and_its_radius_checked():
    an = analyse(scene('find = ["ra_pointed", "sa"]\n[gear]\nm_mm = 5\nz = 10\nx = 0.9\n'))
    assert any("pointed below its tip circle" in w for w in an.warnings)
    r = {x.name: x for x in an.rows}
    assert r["sa"].graphical < 0 and r["ra_pointed"].rel_error < 1e-9


def test_a_ring_whose_tip_circle_is_inside_its_base_circle():
    an = analyse(scene('find = ["d", "db", "da"]\n[gear]\nm_mm = 4\nz = 30\ninternal = true\n'))
    assert any("inside its base" in w for w in an.warnings)
    with pytest.raises(SceneError, match="inside the base circle"):
        analyse(scene('find = ["sa"]\n[gear]\nm_mm = 4\nz = 30\ninternal = true\n'))


def test_z_1000_tends_to_the_rack():
    big = {r.name: r for r in analyse(scene('find = ["B1B2", "eps_alpha"]\n[gear]\nm_mm = 4\nz = [18, 1000]\n'
                                            'meshing = "external"\n')).rows}
    rack = {r.name: r for r in analyse(scene('find = ["B1B2", "eps_alpha"]\n[gear]\nm_mm = 4\nz = [18]\n'
                                             'meshing = "rack"\n')).rows}
    assert big["eps_alpha"].rel_error < 1e-9
    bigger = {r.name: r for r in analyse(scene('find = ["eps_alpha"]\n[gear]\nm_mm = 4\nz = [18, 100000]\n'
                                               'meshing = "external"\n')).rows}
    gap = abs(big["eps_alpha"].graphical - rack["eps_alpha"].graphical)
    assert gap < 5e-3 * rack["eps_alpha"].graphical  # 0.42 % at z2 = 1000
    assert abs(bigger["eps_alpha"].graphical - rack["eps_alpha"].graphical) < gap / 50  # ~1/z2


def test_too_close_a_centre_distance_is_refused_in_one_line(tmp_path):
    p = tmp_path / "g.toml"
    p.write_text('[gear]\nm_mm = 5\nz = [20, 30]\nmeshing = "external"\ncentre_distance_mm = 124\n')
    code, _, err = run_cli("check", str(p))
    assert code == 2 and err.startswith("g.toml: gear.centre_distance") and err.count("\n") == 1, err


def test_only_what_is_asked_is_constructed():
    an = analyse(scene('find = ["da1"]\n[gear]\nm_mm = 5\nz = [19, 42]\nmeshing = "external"\n'))
    assert an.mesh is None and not an.spans and not an.pins and an.panels == ("tooth",)
    an = analyse(scene('find = ["W"]\n[gear]\nm_mm = 5\nz = 30\n'))
    assert an.mesh is None and set(an.spans) == {""} and an.panels == ("measurement",)


def test_panels_follow_the_names():
    p = scene('[gear]\nm_mm = 5\nz = [19, 42]\nmeshing = "external"\n').problem
    assert panels_for(["B1B2"], p) == ("meshing", "zones")
    assert panels_for(["sa1", "M2"], p) == ("tooth", "measurement")
    assert panels_for(["alpha_w"], p) == ("meshing",)


def test_pins_of_the_book():
    q = values(check_json(scene_path("gears/pins_18_m5")))
    assert q["d_pin"]["graphical"] / 2 == pytest.approx(4.33e-3, abs=5e-6)  # the book's r_p
    assert q["M"]["graphical"] == pytest.approx(101.98e-3, abs=1e-5)
    assert q["W"]["graphical"] == pytest.approx(5e-3 * math.cos(math.radians(20)) * (2.5 * math.pi + 18 * (
        math.tan(math.radians(20)) - math.radians(20))), rel=1e-12)  # k = 3 for z = 18


@pytest.mark.parametrize("name", ["gears/internal_20_80", "gears/rack_18"])
def test_shared_pairs_check(name):
    doc = check_json(scene_path(name))
    for r in doc["quantities"]:
        assert r["rel_error"] <= 1e-9 or abs(r["graphical"] - r["exact"]) < 1e-12, r


def test_a_students_span_and_pins_are_judged_at_the_drawings_scale():
    an = analyse(scene('find = ["W", "M"]\n[scales]\nl_mm_per_mm = 1\n[gear]\nm_mm = 5\nz = 18\n'
                       '[measured]\nW = 0.0380\nM = 0.1025\n'))
    v = {x.name: x for x in judge(an)}
    # 0.5 mm of precision at μl = 1 mm/mm: ±0.5 mm; W₃ = 38.16 mm, M = 101.97 mm
    assert v["W"].tolerance == pytest.approx(0.5e-3) and v["W"].ok
    assert v["M"].tolerance == pytest.approx(0.5e-3) and not v["M"].ok
    assert v["M"].expected == pytest.approx(0.10197016294, rel=1e-9)


# ------------------------------------------------------------------ profile shift: rows and the drive

PAIR = '[gear]\nm_mm = 10\nz = [12, 12]\nmeshing = "external"\n'


def shift_scene(tmp_path, text: str, find: list[str] | None = None):
    f = tmp_path / "g.toml"
    f.write_text((f"find = {find!r}\n".replace("'", '"') if find else "") + text)
    return f

def test_every_shift_row_agrees_and_says_the_drive(tmp_path):
    f = shift_scene(tmp_path, PAIR + 'centre_distance_mm = 130\nx = "for_centre_distance"\n',
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
    f = shift_scene(tmp_path, '[gear]\nm_mm = 2\nz = [30, 40]\nmeshing = "external"\n' + f"x = {x}\n", ["a_w"])
    assert check_json(f)["gear"]["drive"] == kind


def test_generation_without_an_addendum_is_refused_at_its_key(tmp_path):
    # fuzz seed 95: h*a = 0 in a rack-cutter scene raised NotApplicable with no key path
    from tests.conftest import assert_refused, edited_scene

    p = edited_scene(tmp_path, "gear.rack_cutter_generation_cases-4.toml", "ha_star = 1", "ha_star = 0", "g.toml")
    assert_refused(run_cli("check", str(p)), "g.toml", "gear.generation", "no tooth is undercut")
