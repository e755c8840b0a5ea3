"""Reading the [gear] table: the set in SI; each bad scene refused in one line naming its key."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.mechanisms.gear import SpurGear
from graphmech.problems.gears.scene import GearScene, known_names, quantity_unit
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values
from tests.scenes import only_problem


def read(text: str) -> GearScene:
    scene = parse_scene(tomllib.loads(text), "g.toml")
    assert scene.kind == "gears"
    return scene.problem


def test_one_gear_in_si_with_the_book_defaults():
    p = read("[gear]\nm_mm = 8\nz = 20\n")
    s = p.gears.system
    assert (s.m, s.alpha, s.ha_star, s.c_star) == (0.008, math.radians(20.0), 1.0, 0.25)
    assert p.gears.gears == (SpurGear(20),) and p.gears.meshing is None and p.labels == ("",)


def test_pairs_internal_and_rack():
    p = read('[gear]\nm_cm = 0.4\nz = [20, 80]\nx = [0.1, -0.2]\nmeshing = "internal"\ncentre_distance_mm = 121\n')
    assert p.gears.gears == (SpurGear(20, 0.1), SpurGear(80, -0.2, internal=True))
    assert p.gears.system.m == pytest.approx(0.004) and p.gears.centre_distance == pytest.approx(0.121)
    assert p.labels == ("1", "2")
    r = read('[gear]\nm_mm = 4\nz = [18]\nmeshing = "rack"\n')
    assert r.gears.gears == (SpurGear(18),) and r.labels == ("1",)
    ring = read("[gear]\nm_mm = 4\nz = 60\ninternal = true\n")
    assert ring.gears.gears == (SpurGear(60, 0.0, internal=True),)


def test_span_and_pins_per_gear():
    p = read('[gear]\nm_mm = 5\nz = [18, 40]\nmeshing = "external"\nspan_teeth = [3, 5]\npin_diameter_mm = 8\n')
    assert p.span_teeth == (3, 5) and p.pin_diameter == pytest.approx((0.008, 0.008))


@pytest.mark.parametrize("name, unit", [("da2", "m"), ("alpha_a1", "deg"), ("s_k1@85", "m"), ("alpha_k2@200.5", "deg"),
                                        ("B1B2", "m"), ("eps_alpha", ""), ("eta_root2", ""), ("z_root_eq_base", "")])
def test_pair_names(name, unit):
    p = read('[gear]\nm_mm = 5\nz = [19, 42]\nmeshing = "external"\n')
    assert quantity_unit(name, p) == unit


@pytest.mark.parametrize("name", ["da", "s_k@85", "B1B2x", "da3", "s_k1@x", "rw2"])
def test_names_a_scene_does_not_have(name):
    rack = read('[gear]\nm_mm = 5\nz = [19]\nmeshing = "rack"\n')
    assert quantity_unit(name, rack) is None
    assert "rw2" not in known_names(rack) and "rw1" in known_names(rack)


@pytest.mark.parametrize("body, where, words", [
    ("z = [19, 42]\nm_mm = 5", "gear.meshing", "needs meshing"),
    ('z = [0]\nm_mm = 5\nmeshing = "rack"', "gear.z[0]", "at least 1 tooth"),
    ("z = 20.5\nm_mm = 5", "gear.z", "whole number, not 20.5"),
    ("z = 20\nm = 5", "gear.m", "unit not stated"),
    ('z = [20, 10]\nm_mm = 5\nmeshing = "internal"', "gear.z", "more teeth than the pinion"),
    ("z = 20\nm_mm = 5\ncentre_distance_mm = 100", "gear.centre_distance_mm", "no centre distance"),
    ('z = [20, 30]\nm_mm = 5\nmeshing = "external"\nspan_teeth = [3, 40]', "gear.span_teeth[1]", "1 … z − 1"),
    ('z = [20, 30]\nm_mm = 5\nmeshing = "external"\nx = [0, 11]', "gear.x", "±10"),
    ('z = [20, 30]\nm_mm = 5\nmeshing = "crossed"', "gear.meshing", "use external, internal, rack, helical, bevel or worm"),
    ('z = [20, 30, 40]\nm_mm = 5\nmeshing = "external"', "gear.z", "one or two"),
    ("z = 20\nm_mm = 5\nalpha_deg = 60", "gear.alpha_deg", "no involute gear's"),
    ("z = 20\nm_mm = 0", "gear.m_mm", "> 0"),
    ("z = 20\nm_mm = 5\nha_star = -1", "gear.ha_star", "outside"),
    ('z = 20\nm_mm = 5\nmeshing = "external"\n', "gear.z", "needs z = [z1, z2]"),
    ('z = [20, 30]\nm_mm = 5\nmeshing = "rack"\n', "gear.z", "z = [z1]"),
    ("z = 20\nm_mm = 5\npin_diameter_mm = -3", "gear.pin_diameter_mm", "> 0"),
    ("z = 20\nm_mm = 5\nfoo = 1", "gear.foo", "unknown key"),
])
def test_bad_gear_tables_are_refused_in_one_line(body, where, words):
    path, reason = only_problem(f"[gear]\n{body}\n", "g.toml")
    assert path == where and words in reason, (path, reason)


@pytest.mark.parametrize("find, words", [('["eps"]', "did you mean eps_alpha"), ('["s_k@abc"]', "number of mm"),
                                         ('["B1B2"]', "belongs to a pair")])
def test_unknown_names_are_refused_naming_find(find, words):
    path, reason = only_problem(f"find = {find}\n[gear]\nz = 20\nm_mm = 5\n", "g.toml")
    assert path == "find[0]" and words in reason, reason


def test_a_linkage_table_in_a_gear_scene_is_refused():
    path, reason = only_problem('[gear]\nz = 20\nm_mm = 5\n[frame]\nA_mm = [0, 0]\n', "g.toml")
    assert path == "frame" and "gear scene" in reason


def test_reference_scenes_read():
    for name in ("gear.involute_z20_m8", "gear.contact_ratio_19_42", "gear.root_circle_equals_base_circle"):
        assert load_scene(SCENES / f"{name}.toml").kind == "gears"


# ------------------------------------------------------------------ profile shift: the design words

PAIR = '[gear]\nm_mm = 10\nz = [12, 12]\nmeshing = "external"\n'


def shift_scene(tmp_path, text: str, find: list[str] | None = None):
    f = tmp_path / "g.toml"
    f.write_text((f"find = {find!r}\n".replace("'", '"') if find else "") + text)
    return f

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
    ('x = "for_centre_distance"\ncentre_distance_mm = 1e6\n', "gear.centre_distance_mm", ("beyond ±10",)),
    ('x = "for_centre_distance"\ncentre_distance_mm = 130\nx1 = 50\n', "gear.x1", ("x = 50, -48.7495",)),
    ('x = "repair"\nthickness_loss_mm = 1e5\n', "gear.thickness_loss_mm", ("beyond ±10",)),
    ('x = "for_centre_distance"\ncentre_distance_mm = 130\nx1 = nan\n', "gear.x1", ("finite",)),
    # Δy past 2h*a + c*: the shortened tip circle inside the root circle (was a keyless scale error)
    ('x = "for_centre_distance"\ncentre_distance_mm = 200\n', "gear.centre_distance_mm", ("below the roots", "7.76414")),
    ('x = [4, 4]\n', "gear.x", ("below the roots", "2.25")),
    # a′ is where these shifts mesh: not "the teeth overlap … the least centre distance is 155 mm"
    ('x = "for_centre_distance"\ncentre_distance_mm = 155\n', "gear.centre_distance_mm", ("do not come into contact",)),
])
def test_bad_design_keys_are_refused_in_one_line(tmp_path, body, where, words):
    f = shift_scene(tmp_path, PAIR + body)
    err = assert_refused(run_cli("check", str(f)), "g.toml", *words)
    assert f"{where}: " in err


def test_design_words_that_do_not_fit_the_set_are_refused(tmp_path):
    ring = '[gear]\nm_mm = 2\nz = [20, 80]\nmeshing = "internal"\nx = "least"\n'
    assert_refused(run_cli("check", str(shift_scene(tmp_path, ring))), "g.toml", "gear.x", "pinion cutter")
    one = '[gear]\nm_mm = 2\nz = 20\nx = "repair"\nthickness_loss_mm = 0.5\n'
    assert_refused(run_cli("check", str(shift_scene(tmp_path, one))), "g.toml", "gear.x", "external pair")
    short = '[gear]\nm_mm = 2\nz = 20\ntip_shortening = true\n'
    assert_refused(run_cli("check", str(shift_scene(tmp_path, short))), "g.toml", "gear.tip_shortening")
    # a ring has no rack's least shift to find either (it was −1.35 for z = 40), the pinion has
    err = assert_refused(run_cli("check", str(shift_scene(tmp_path, ring.replace('x = "least"\n', ""), ["x_min2"]))),
                         "g.toml", "find[0]", "x_min2")
    assert "did you mean x_min1" in err and "x_min2," not in err
    q = values(check_json(shift_scene(tmp_path, ring.replace('x = "least"\n', ""), ["x_min1"])))
    assert q["x_min1"]["exact"] == pytest.approx(-3.0 / 17.0, rel=1e-15)
    find_dy = '[gear]\nm_mm = 2\nz = [20, 80]\nmeshing = "internal"\n'
    assert_refused(run_cli("check", str(shift_scene(tmp_path, find_dy, ["delta_y"]))), "g.toml",
                   "find[0]", "delta_y")


def test_a_least_shift_far_below_minus_10_says_no_shift_is_needed(tmp_path):
    f = shift_scene(tmp_path, '[gear]\nm_mm = 2\nz = [12, 400]\nmeshing = "external"\nx = "least"\n')
    assert_refused(run_cli("check", str(f)), "g.toml", "gear.x", "far below −10", "needs no shift")
