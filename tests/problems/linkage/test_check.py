"""The linkage's check (graphmech/problems/linkage/check.py): the polygons' values against the
closed-form four-bar and textbook formulas, the scales chosen or kept, the exact value of each
quantity, and hand measurements judged within the drawing precision."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from graphmech.errors import SceneError
from graphmech.problems.linkage.bench import closed_form_fourbar
from graphmech.problems.linkage.check import analyse, exact_value, judge, rows_that_fit
from graphmech.scene import parse_scene
from tests.conftest import SCENES, assert_refused, check_json, fourbar_scene, run_cli, values
from tests.scenes import scene_path, scene_text, write_scene

#: AD 120, AB 60 (link 2) at 30°, BC 120 (3), CD 90 mm (4); 100 rpm, ε = 4 rad/s²; μl, μv stated.
FOURBAR = scene_text("linkage/fourbar_phi30")
OMEGA = 100 * 2 * math.pi / 60


def scene(find="[]", measured=""):
    text = FOURBAR.replace('find = ["v_C", "omega_3"]', f"find = {find}")
    return parse_scene(tomllib.loads(text + (f"\n[measured]\n{measured}\n" if measured else "")), "fourbar.toml")


def rows(find):
    return {r.name: r for r in analyse(scene(find)).rows}


def test_the_cranks_pin_by_the_textbook_formulas():
    """v_B = ω₁·AB, a_B = AB·√(ω₁⁴ + ε₁²) (normal ω₁²·AB, tangential ε₁·AB)."""
    got = rows('["v_B", "a_B", "a_B_n", "a_B_t"]')
    assert got["v_B"].graphical == pytest.approx(OMEGA * 0.06, rel=1e-14)
    assert got["a_B"].graphical == pytest.approx(0.06 * math.hypot(OMEGA ** 2, 4.0), rel=1e-14)
    assert got["a_B_n"].graphical == pytest.approx(OMEGA ** 2 * 0.06, rel=1e-14)
    assert got["a_B_t"].graphical == pytest.approx(4.0 * 0.06, rel=1e-14)
    assert got["v_B"].drawn_mm == pytest.approx(OMEGA * 0.06 / 0.01)  # pb at the stated μv
    assert all(r.rel_error < 1e-14 and r.error_source == "construction" for r in got.values())


def test_the_polygons_agree_with_the_closed_form_four_bar():
    """The coupler BC is link 3 (θ2 of the closed form), the rocker CD link 4 (θ3)."""
    ref = closed_form_fourbar(np.radians([30.0]), w1=OMEGA)
    got = rows('["v_C", "v_CB", "omega_3", "omega_4"]')
    assert got["omega_3"].graphical == pytest.approx(float(ref["omega_2"][0]), rel=1e-12)
    assert got["omega_4"].graphical == pytest.approx(float(ref["omega_3"][0]), rel=1e-12)
    assert got["v_C"].graphical == pytest.approx(float(ref["v_C"][0]), rel=1e-12)
    assert got["v_CB"].graphical == pytest.approx(float(ref["v_CB"][0]), rel=1e-12)


def test_stated_scales_are_kept_and_the_others_chosen_round():
    an = analyse(scene())
    assert an.scales == {"l": 0.002, "v": 0.01, "a": 0.2} and an.stated == {"l", "v"}
    assert an.scale_notes() == ["μl = 0.002 m/mm", "μv = 0.01 (m/s)/mm", "μa = 0.2 (m/s²)/mm (chosen)"]
    assert an.labels == ("30",) and an.warnings == []


def test_the_exact_value_of_each_kind_of_quantity():
    kin = analyse(scene()).exact
    assert exact_value(kin, ("speed", "B"), 0) == pytest.approx(OMEGA * 0.06, rel=1e-14)
    assert exact_value(kin, ("length", "B", "C"), 0) == pytest.approx(0.12, rel=1e-14)
    assert exact_value(kin, ("angle", "2"), 0) == pytest.approx(30.0, rel=1e-14)
    assert exact_value(kin, ("omega", "2"), 0) == pytest.approx(OMEGA, rel=1e-14)
    assert exact_value(kin, ("normal", "B", "A", "2"), 0) == pytest.approx(OMEGA ** 2 * 0.06, rel=1e-14)
    with pytest.raises(ValueError, match="unknown exact quantity"):
        exact_value(kin, ("jerk", "B"), 0)


def test_one_row_of_panels_per_position_fits_the_page():
    assert [rows_that_fit(p) for p in [(297, 210), (420, 297), (210, 297), (100, 50)]] == [2, 4, 4, 1]


def test_a_drawn_length_is_judged_in_mm_a_value_within_precision_times_mu():
    v_c = rows('["v_C"]')["v_C"]
    pc = v_c.graphical / 0.01  # mm at μv = 0.01
    an = analyse(scene(measured=f'pc = {pc + 0.4}\nv_C = {v_c.graphical + 0.006}\nomega_4 = 2'))
    drawn, value, omega = judge(an)
    assert (drawn.unit, drawn.expected, drawn.tolerance, drawn.ok) == ("mm", pytest.approx(pc), 0.5, True)
    assert (value.tolerance, value.ok) == (pytest.approx(0.005), False)  # 0.5 mm × 0.01 (m/s)/mm
    assert not omega.ok  # ω4 = 1.04 rad/s
    assert [v.ok for v in judge(an, precision_mm=0.7)] == [True, True, False]  # a coarser precision given


@pytest.mark.parametrize("measured, reason", [
    ("\"b'c'\" = 3", "the scene does not state μa, so a drawn length cannot be judged: state it in [scales] or "
                     "give the value (a_BC) instead"),
    ('xx = 1', "a drawn segment needs two different ends, not 'xx'"),
    ('phi_3 = 10', "unknown quantity or segment 'phi_3'; did you mean alpha_3?"),
])
def test_a_measured_value_that_cannot_be_judged_says_why(measured, reason):
    with pytest.raises(SceneError) as info:
        judge(analyse(scene(measured=measured)))
    assert info.value.problems == [(f"measured.{measured.split(' =')[0].strip(chr(34))}", reason)]


def test_unknown_find_names_are_refused_with_suggestions():
    with pytest.raises(SceneError) as info:
        analyse(scene('["v_X", "v_C@45"]'))
    assert info.value.problems == [("find[0]", "unknown quantity 'v_X'; did you mean v_E, v_D, v_C?"),
                                   ("find[1]", "no position '45' (positions: 30)")]


def test_a_link_angle_at_a_full_turn_is_0_on_both_sides(tmp_path):
    """At φ = 360° sin φ ≈ -2.4e-16, and ``x % 360`` of the tiny negative angle is 360.0: both the
    drawn θ and the exact one fold to 0, so a measured 0° is judged against 0°, not 360°."""
    p = write_scene(tmp_path, fourbar_scene(angle="360", find='["theta_1"]'))
    doc = check_json(p, "--measured", "theta_1=0")
    (row,) = doc["quantities"]
    assert (row["graphical"], row["exact"]) == (0.0, 0.0)
    (m,) = doc["measured"]
    assert (m["expected"], m["ok"]) == (0.0, True)


def test_a_vector_drawn_under_10_mm_is_named_with_its_reading_error():
    """At the stated μv = 0.01 (m/s)/mm, v_CB of the four-bar at 90° is 0.0258 m/s: 2.58 mm on paper,
    so ±0.5 mm is ±19 %; v_C (59 mm) is not named."""
    import tomllib

    from graphmech.scene import parse_scene
    from tests.conftest import fourbar_scene

    text = fourbar_scene(angle="90", find='["v_C", "v_CB"]', scales="[scales]\nv_m_s_per_mm = 0.01")
    an = analyse(parse_scene(tomllib.loads(text), "s.toml"))
    short = [w for w in an.warnings if "under 10 mm" in w]
    assert short == ["v_CB is drawn 2.58 mm long at μv = 0.01 (m/s)/mm, under 10 mm: read to ±0.5 mm it is ±19 % "
                     "(a smaller μv or a larger page makes it longer)"]


#: A centred slider-crank at φ = 0: B and C on the guide, C at its dead centre (v_C = 0).
SLIDER_AT_DEAD_CENTRE = """
title = "dead centre"
show = ["mechanism", "velocity"]
find = ["v_C", "v_B"]
[units]
length = "mm"
angle = "deg"
omega = "rad/s"
[scales]
l_m_per_mm = 0.005
v_m_s_per_mm = 0.025
[frame]
link = "4"
A = [0, 0]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "B"
length = 100
angle = 0
omega = 10
[[dyad]]
type = "RRP"
joints = ["B", "C"]
links = ["2", "3"]
length = 300
guide = { through = [0, 0], angle = 0 }
branch = "forward"
"""


def test_a_zero_velocity_at_a_dead_centre_is_no_vector():
    """v_C = 0 at the dead centre is the pole itself, not a vector shorter than 10 mm; v_B is 40 mm."""
    import tomllib

    from graphmech.problems.linkage.check import short_vector_warnings
    from graphmech.scene import parse_scene

    an = analyse(parse_scene(tomllib.loads(SLIDER_AT_DEAD_CENTRE), "dc.toml"))
    rows = {r.name: r for r in an.rows}
    assert abs(rows["v_C"].drawn_mm) < 1e-9 and abs(rows["v_B"].drawn_mm) == pytest.approx(40.0)
    assert short_vector_warnings(an) == [] and not any("under 10 mm" in w for w in an.warnings)


SCOTCH_YOKE = """
title = "Scotch yoke"
show = ["mechanism", "velocity", "acceleration"]
find = ["v_C", "a_C", "v_B2B3"]
[frame]
A_mm = [0, 0]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "B"
length_mm = 50
angle_deg = [0, 30, 120, 250]
omega_rad_s = 10
[[dyad]]
type = "RPP"
joints = ["B", "C"]
links = ["2", "3"]
slot_angle_deg = 90
guide = { through = "A", angle_deg = 0 }
"""


def test_the_scotch_yoke_is_an_rpp_dyad_with_the_slot_square_to_the_guide(tmp_path):
    # x_C = r·cos φ: v_C = −r·ω·sin φ, a_C = −r·ω²·cos φ; the block slides in the slot at r·ω·cos φ
    q = {r["name"]: r for r in check_json(write_scene(tmp_path, SCOTCH_YOKE))["quantities"]}
    r, w = 0.05, 10.0
    for phi in (0, 30, 120, 250):
        c, s = math.cos(math.radians(phi)), math.sin(math.radians(phi))
        assert q[f"v_C@{phi}"]["graphical"] == pytest.approx(-r * w * s, abs=1e-9 * r * w)
        assert q[f"a_C@{phi}"]["graphical"] == pytest.approx(-r * w * w * c, abs=1e-9 * r * w * w)
        assert abs(q[f"v_B2B3@{phi}"]["graphical"]) == pytest.approx(abs(r * w * c), abs=1e-9 * r * w)


def test_a_slotted_link_drives_a_pin_with_the_coriolis_side_drawn(tmp_path):
    # an RRP group whose guide is the moving crank's slot: every value against exact/ to 1e-9, and
    # a^k = 2ω2·v_C4C2 with the block turning with the slotted crank
    got = values(check_json(scene_path("linkage/slotted_link_pin")))
    assert len(got) == 8 and all(r["rel_error"] <= 1e-9 for r in got.values()), got
    assert got["omega_4"]["graphical"] == pytest.approx(10.0, rel=1e-12)
    assert got["a_k_C4C2"]["graphical"] == pytest.approx(2 * 10.0 * got["v_C4C2"]["exact"], rel=1e-12)


@pytest.mark.parametrize("name", ["kin.tangent_mechanism", "ic.tangent_mechanism"])
def test_tangent_mechanism_polygons_and_centres_agree_with_exact(name):
    # seed 001 1-14 (PRP): every value the scene finds, graphical against exact/, to 1e-9; and the
    # closed form v3 = ω1·h/cos²φ1, a3 = 2ω1²·h·tan φ1/cos²φ1 (h = 0.1 m, φ1 = 30°, ω1 = 10 rad/s)
    doc = check_json(SCENES / f"{name}.toml")
    got = values(doc)
    assert got and all(r["rel_error"] <= 1e-9 for r in got.values()), got
    phi = math.radians(30.0)
    assert got["v_C"]["exact"] == pytest.approx(1.0 / math.cos(phi) ** 2, rel=1e-12)
    if name.startswith("kin"):
        assert got["a_C"]["exact"] == pytest.approx(20.0 * math.tan(phi) / math.cos(phi) ** 2, rel=1e-12)
        assert got["a_k_C2C1"]["graphical"] == pytest.approx(2 * 10.0 * got["v_C2C1"]["exact"], rel=1e-12)
        assert got["omega_2"]["graphical"] == pytest.approx(10.0, rel=1e-12)
    else:  # P13 on the x axis at h/cos²φ1; v3 = ω1·P14P13
        assert got["x_P13"]["graphical"] == pytest.approx(0.1 / math.cos(phi) ** 2, rel=1e-12)
        assert got["v_C_ic"]["graphical"] == pytest.approx(got["v_C"]["exact"], rel=1e-12)


def test_an_rpr_group_on_two_moving_pivots_already_agrees_with_exact():
    # the pin in a rotating slot, the slot's bar pivoted on a coupler and the block on a rocker
    got = values(check_json(scene_path("linkage/rpr_moving_pivots")))
    assert len(got) == 6 and all(r["rel_error"] <= 1e-9 for r in got.values()), got
    assert got["v_F5F6"]["exact"] > 0.1 and got["a_k_F5F6"]["exact"] > 0.0


def test_tangent_mechanism_near_its_parallel_position_is_flagged(tmp_path):
    # at φ1 = 90° the bar runs along the guide (C at infinity): refused at that position; at 88° the
    # intersections meet at 2°, named as shallow, as for the other dyads
    from tests.conftest import run_cli

    text = (SCENES / "kin.tangent_mechanism.toml").read_text(encoding="utf-8")
    text = text.replace("angle = 30\n", "angle = [30, 88, 90]\n").replace('find = ["v_C", ', 'find = [')
    text = "\n".join(line for line in text.splitlines() if not line.startswith(("v_m_s_per_mm", "a_m_s2_per_mm")))
    code, out, err = run_cli("check", str(write_scene(tmp_path, text)))
    assert code == 0 and "v_C1@88" in out
    assert "φ₁ = 90°: construction impossible — C = AB ∩ the guide: the two lines are parallel" in err
    assert "φ₁ = 88°: shallow intersection 'C = AB ∩ the guide' at 2°" in err
    assert "φ₁ = 88°: shallow intersection 'c = the two lines ∥ the guides meet' at 2°" in err


def test_a_slotted_link_s_instant_centres_agree_with_exact(tmp_path):
    # the block 4 slides in the crank 2's slot: P24 at infinity ⟂ AB (130° at φ2 = 40°), the rest by Kennedy
    text = scene_text("linkage/slotted_link_pin").replace(
        'show = ["mechanism", "velocity", "acceleration"]', 'show = ["instant_centres"]')
    text = text.replace(text[text.index("find = "):text.index("\n", text.index("find = "))],
                        'find = ["P23", "P34", "P24", "P45", "omega_3_ic", "v_C_ic"]')
    got = values(check_json(write_scene(tmp_path, text)))
    assert len(got) == 9 and all(r["rel_error"] <= 1e-9 for r in got.values()), got
    assert got["dir_P24"]["graphical"] == pytest.approx(130.0, abs=1e-9)


# ---------------------------------------------------------------------------- class III groups

def _class_iii(tmp_path, old: str = "", new: str = "") -> dict:
    from tests.conftest import SCENES

    text = (SCENES / "kin.class_iii_sixbar.toml").read_text(encoding="utf-8")
    assert old in text
    return check_json(write_scene(tmp_path, text.replace(old, new)))


def test_class_iii_sixbar_every_value_agrees_with_the_exact_elimination(tmp_path):
    # every ω, α, velocity, acceleration and component the polygons give, at three crank angles
    doc = _class_iii(tmp_path, "angle = 60\n", "angle = [50, 60, 75]\n")
    rows = doc["quantities"]
    assert len(rows) == 14 * 3
    assert max(r["rel_error"] for r in rows) < 1e-9
    assert not any(r["ill_conditioned"] for r in rows)
    got = {r["name"]: r["exact"] for r in rows}
    # the figure's assembly (C near (84.5, 72.9) mm), not the other one: ω3 = −2.7533 rad/s at 60°
    assert got["omega_3@60"] == pytest.approx(-2.75328271, abs=1e-8)
    assert got["alpha_4@60"] == pytest.approx(59.8160094, abs=1e-6)


def test_class_iii_start_picks_the_assembly(tmp_path):
    doc = _class_iii(tmp_path, "start = [[85, 73], [123, 34], [128, 98]]", "start = [[93, 20], [145, 40], [87, 69]]")
    got = {r["name"]: r for r in doc["quantities"]}
    assert got["omega_3"]["exact"] == pytest.approx(2.39714462, abs=1e-8)  # the other assembly turns the other way
    assert max(r["rel_error"] for r in doc["quantities"]) < 1e-9


def _locked_group(tmp_path, extra_mm: float):
    """C, D, E a triangle and B, F, G on the lines OC, OD, OE through one point O (the frame):
    the binary links' lines concurrent — the group locks; l_GE longer by ``extra_mm`` moves it off."""
    c, d, e = complex(100, 0), complex(0, 120), complex(-80, -50)
    b, f, g = 2 * c, 1.6 * d, 1.8 * e
    text = f'''show = ["mechanism", "velocity"]
find = ["v_C", "omega_3"]
[units]
length = "mm"
angle = "deg"
omega = "rad/s"
[frame]
A = [0, -200]
B = [{b.real}, {b.imag}]
F = [{f.real}, {f.imag}]
G = [{g.real}, {g.imag}]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "K"
length = 20
angle = 30
omega = 10
[[triad]]
type = "RRR-III"
outer = ["B", "F", "G"]
inner = ["C", "D", "E"]
links = ["2", "4", "5", "3"]
lengths = [100, {abs(d - f)!r}, {abs(e - g) + extra_mm!r}]
ternary = [{abs(d - c)!r}, {abs(e - d)!r}, {abs(c - e)!r}]
start = [[100, 0], [0, 120], [-80, -50]]
'''
    return check_json(write_scene(tmp_path, text))


def test_a_nearly_locked_class_iii_group_is_flagged_ill_conditioned(tmp_path):
    near = _locked_group(tmp_path, 1e-4)
    assert all(r["ill_conditioned"] for r in near["quantities"])
    assert any("ill-conditioned intersection 'C, D, E: the class III group's loops solved by Newton's method" in w
               for w in near["warnings"])
    off = _locked_group(tmp_path, 1.0)
    assert not any(r["ill_conditioned"] for r in off["quantities"])
    assert not any("ill-conditioned" in w for w in off["warnings"])


def test_a_locked_class_iii_group_is_not_checked(tmp_path):
    doc = _locked_group(tmp_path, 0.0)
    assert any("dead centre (its velocity equations are singular)" in w for w in doc["warnings"])
    assert any("ill-conditioned" in w for w in doc["warnings"])


def test_class_iii_sixbar_instant_centres_by_kennedy_agree_with_the_exact():
    from tests.conftest import SCENES

    doc = check_json(SCENES / "ic.class_iii_sixbar.toml")
    rows = {r["name"]: r for r in doc["quantities"]}
    assert max(r["rel_error"] for r in rows.values()) < 1e-9
    # P36 is where FD and GE meet: on both lines
    p = np.array([rows["x_P36"]["exact"], rows["y_P36"]["exact"]]) * 1000
    f, g = np.array([150.0, -20.0]), np.array([60.0, 150.0])
    kin = analyse(parse_scene(tomllib.loads((SCENES / "kin.class_iii_sixbar.toml").read_text(encoding="utf-8")),
                              "six.toml")).exact
    d, e = kin.point["D"][0] * 1000, kin.point["E"][0] * 1000
    def cross(u, w):
        return u[0] * w[1] - u[1] * w[0]

    assert abs(cross(d - f, p - f)) < 1e-8 * np.dot(d - f, d - f)
    assert abs(cross(e - g, p - g)) < 1e-8 * np.dot(e - g, e - g)
    assert rows["omega_3_ic"]["exact"] == pytest.approx(-2.75328271, abs=1e-8)


def test_a_class_iii_group_in_another_assembly_than_the_exact_one_is_not_compared(monkeypatch):
    # Newton from the start and "the exact assembly nearest the start" are two rules: where they part,
    # the table compared two different mechanisms (36 % apart, exit 0, no word). Here the exact
    # solution is moved 10 mm off to stand for the other assembly.
    from dataclasses import replace

    from graphmech.errors import DegenerateConstruction
    from graphmech.problems.linkage import check as linkage_check

    real = linkage_check.solve_exact

    def other(linkage, positions):
        kin = real(linkage, positions)
        return replace(kin, point={**kin.point, "D": kin.point["D"] + 0.01})

    monkeypatch.setattr(linkage_check, "solve_exact", other)
    text = (SCENES / "kin.class_iii_sixbar.toml").read_text(encoding="utf-8")
    with pytest.raises(DegenerateConstruction, match="another assembly of the class III group B-C, F-D, G-E"):
        analyse(parse_scene(tomllib.loads(text), "six.toml"))
    an = analyse(parse_scene(tomllib.loads(text.replace("angle = 60", "angle = [55, 60]")), "six.toml"))
    assert an.rows == []
    assert sum("another assembly" in w and "not checked" in w for w in an.warnings) == 2


# ------------------------------------------------- a class III group with a slider leg (IC engine)

def test_ic_engine_from_eg_every_value_by_assurs_point_agrees_with_the_exact(tmp_path):
    # the piston's leg: S on AB and on the normal to C's guide; at three angles of GE
    text = (SCENES / "kin.ic_engine_EG.toml").read_text(encoding="utf-8")
    doc = check_json(write_scene(tmp_path, text.replace("angle = 116\n", "angle = [112, 116, 124]\n")))
    rows = doc["quantities"]
    assert len(rows) == 14 * 3
    assert max(r["rel_error"] for r in rows) < 1e-9
    assert not any(r["ill_conditioned"] for r in rows)
    got = {r["name"]: r for r in rows}
    # the figure's assembly: ω2 = 11.2483 rad/s at 116° (tests/exact: the AB-driven engine's, scaled)
    assert got["omega_2@116"]["exact"] == pytest.approx(11.2483096, abs=1e-7)
    assert got["v_C@116"]["exact"] == pytest.approx(-0.409328282, abs=1e-9)  # the piston moves down
    assert got["omega_3@112"]["exact"] != pytest.approx(got["omega_3@124"]["exact"], abs=1e-3)


def test_ic_engine_from_eg_the_velocity_image_of_s_is_the_pole():
    """Both legs of S stand on the frame (A, and C's guide): v_S = 0 — S is the ternary link's instant
    centre P13, and the instant-centre scene finds it there."""
    from graphmech.problems.linkage.check import analyse as run

    doc = check_json(SCENES / "ic.ic_engine_EG.toml")
    rows = {r["name"]: r for r in doc["quantities"]}
    assert max(r["rel_error"] for r in rows.values()) < 1e-9
    kin = run(parse_scene(tomllib.loads((SCENES / "kin.ic_engine_EG.toml").read_text(encoding="utf-8")),
                          "eg.toml")).exact
    b, c = kin.point["B"][0], kin.point["C"][0]
    p13 = np.array([rows["x_P13"]["exact"], rows["y_P13"]["exact"]])
    assert p13[1] == pytest.approx(c[1], abs=1e-12)  # on the normal to the guide (horizontal) through C
    assert abs(b[0] * p13[1] - b[1] * p13[0]) < 1e-12  # on AB (A at the origin)
    assert rows["omega_3_ic"]["exact"] == pytest.approx(-2.78896857, abs=1e-7)


def test_the_same_engine_from_ab_is_three_dyads_and_agrees_with_the_exact():
    doc = check_json(SCENES / "kin.ic_engine_AB.toml")
    assert max(r["rel_error"] for r in doc["quantities"]) < 1e-9
    assert values(doc)["omega_6"]["exact"] == pytest.approx(2.30417008, abs=1e-7)


def test_a_class_iii_group_through_a_whole_turn_keeps_its_branch(tmp_path):
    """The cycle scene: 12 positions, Newton from the previous one (continuation) and the exact's
    assembly nearest the previous agree to 1e-9 at every position, and the branch is the figure's
    all round (C moves by less than 12 mm between positions; the other assembly is always far)."""
    from graphmech.exact import solve
    from graphmech.exact.triad import assemblies
    from graphmech.scene import load_scene

    text = (SCENES / "linkage.class_iii_sixbar-cycle.toml").read_text(encoding="utf-8")
    old = 'find = ["psi_3@7", "omega_3@3", "alpha_3@5", "omega_3_diagram@4.5", "alpha_3_diagram@9"]'
    assert old in text
    doc = check_json(write_scene(tmp_path, text.replace(old, 'find = ["omega_3", "alpha_3", "omega_4", "alpha_5"]')))
    rows = doc["quantities"]
    assert len(rows) == 4 * 12
    assert max(r["rel_error"] for r in rows) < 1e-9
    assert {r["name"]: r["exact"] for r in rows}["omega_3@3"] == pytest.approx(1.39305419, abs=1e-7)
    linkage = load_scene(SCENES / "linkage.class_iii_sixbar-cycle.toml").linkage
    kin = solve(linkage, np.radians(60.0 + 30.0 * np.arange(12)))
    assert kin.valid.all()
    c = kin.point["C"][:, 0] + 1j * kin.point["C"][:, 1]
    assert np.abs(np.diff(np.append(c, c[0]))).max() < 0.012  # m: 12 positions of a 15 mm crank
    y = linkage.dyads[0]
    zb = kin.point["B"][:, 0] + 1j * kin.point["B"][:, 1]
    f, g = complex(0.150, -0.020), complex(0.060, 0.150)
    for i in range(12):
        found = assemblies(y, complex(zb[i]), f, g)
        assert len(found) == 2
        assert min(abs(t[0] - c[i]) for t in found) < 1e-12
        assert max(abs(t[0] - c[i]) for t in found) > 0.02


def test_the_offset_guide_bar_scene_agrees_with_exact_and_with_its_closed_form():
    """linkage.offset_guide_bar: every drawn value within 1e-9 of exact/; and exact against the bar's
    angle by hand, θ3 = ∠CB − atan2(e, t), t = √(CB² − e²), with ω3 = its derivative and the instant
    centres' ω3 = ω1·P14P13/P34P13 (P23 at infinity ⟂ the line FB, not ⟂ CB)."""
    got = values(check_json(SCENES / "linkage.offset_guide_bar.toml"))
    assert len(got) == 24 and all(r["rel_error"] <= 1e-9 for r in got.values()), got
    e, ac, r, w1 = 0.04, 0.35, 0.11, 5.0
    for phi in (30.0, 150.0):
        bx, by = r * math.cos(math.radians(phi)), r * math.sin(math.radians(phi)) + ac  # CB
        vx, vy = -w1 * r * math.sin(math.radians(phi)), w1 * r * math.cos(math.radians(phi))
        d2 = bx * bx + by * by
        t = math.sqrt(d2 - e * e)
        theta = math.atan2(by, bx) - math.atan2(e, t)
        w3 = (bx * vy - by * vx) / d2 + e * ((bx * vx + by * vy) / t) / d2
        assert got[f"theta_3@{phi:g}"]["exact"] == pytest.approx(math.degrees(theta), rel=1e-13)
        assert got[f"omega_3@{phi:g}"]["exact"] == pytest.approx(w3, rel=1e-12)
        assert got[f"omega_3_ic@{phi:g}"]["graphical"] == pytest.approx(w3, rel=1e-12)
        turn = (got[f"dir_P23@{phi:g}"]["graphical"] - math.degrees(theta) - 90.0) % 180.0  # a direction: mod 180°
        assert min(turn, 180.0 - turn) == pytest.approx(0.0, abs=1e-10)
        assert got[f"a_k_B3B2@{phi:g}"]["exact"] == pytest.approx(2 * abs(w3) * got[f"v_B3B2@{phi:g}"]["exact"],
                                                                  rel=1e-12)


# ---------------------------------------------------------------------------- angles at a position
# γ, α and the directions of velocities at any stated position (001 2-3, 000 运动 7): the
# protractor's readings on the drawing against closed forms written here, the marks on the
# figure, and what is refused.


def _gamma_fourbar(a: float, b: float, c: float, d: float, phi_deg: float) -> float:
    """γ by the cosine rule: BD from triangle ABD, then the angle BCD, taken acute."""
    bd2 = a * a + d * d - 2 * a * d * math.cos(math.radians(phi_deg))
    bcd = math.degrees(math.acos((b * b + c * c - bd2) / (2 * b * c)))
    return min(bcd, 180.0 - bcd)


def _write(tmp_path, text: str, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


@pytest.mark.parametrize("phi", [0, 37, 90, 165, 180, 250, 330])
def test_fourbar_gamma_and_alpha_equal_the_cosine_rule(tmp_path, phi):
    p = _write(tmp_path, fourbar_scene(a=28, b=52, c=50, d=72, angle=str(phi), show='["mechanism"]',
                                       find='["gamma_C", "pressure_angle_C"]'))
    v = values(check_json(p))
    g = _gamma_fourbar(28, 52, 50, 72, phi)
    assert v["gamma_C"]["graphical"] == pytest.approx(g, abs=1e-9)
    assert v["pressure_angle_C"]["graphical"] == pytest.approx(90.0 - g, abs=1e-9)
    assert v["gamma_C"]["rel_error"] < 1e-12


def test_fourbar_scene_gives_the_smallest_gamma_at_the_crank_along_the_frame():
    # γ at φ = 180° (crank pointing away from D) is the characteristics' γ_min of 28/52/50/72
    v = values(check_json(SCENES / "kin.transmission_angle-fourbar.toml"))
    assert v["gamma_C@60"]["graphical"] == pytest.approx(_gamma_fourbar(28, 52, 50, 72, 60), abs=1e-9)
    assert v["gamma_C@200"]["graphical"] == pytest.approx(28.8903065, abs=1e-7)
    assert v["pressure_angle_C@200"]["graphical"] == pytest.approx(61.1096935, abs=1e-7)


def test_slider_crank_alpha_is_the_coupler_against_the_guide():
    # guide 12 mm above A, crank 30, coupler 80: sin α = |r sin φ − e| / l
    v = values(check_json(SCENES / "kin.transmission_angle-slider_crank.toml"))
    for phi in (45, 250):
        alpha = math.degrees(math.asin(abs(30 * math.sin(math.radians(phi)) - 12) / 80))
        assert v[f"pressure_angle_C@{phi}"]["graphical"] == pytest.approx(alpha, abs=1e-9)
        assert v[f"gamma_C@{phi}"]["graphical"] == pytest.approx(90 - alpha, abs=1e-9)


def test_guide_bar_alpha_from_the_offset():
    # offset bar: sin α = e / CB; A = (0, 0), C = (0, −100), B at 40 mm, 30°
    v = values(check_json(SCENES / "kin.transmission_angle-guide_bar.toml"))
    B = (40 * math.cos(math.radians(30)), 40 * math.sin(math.radians(30)))
    cb = math.hypot(B[0], B[1] + 100)
    assert v["pressure_angle_B"]["graphical"] == pytest.approx(math.degrees(math.asin(15 / cb)), abs=1e-9)
    assert v["gamma_B"]["exact"] == pytest.approx(90 - math.degrees(math.asin(15 / cb)), abs=1e-9)


def test_centred_guide_bar_transmits_at_90_degrees(tmp_path):
    text = (SCENES / "kin.transmission_angle-guide_bar.toml").read_text(encoding="utf-8")
    text = text.replace("offset = 15", "").replace("angle = 30", "angle = [0, 75, 200]")
    v = values(check_json(_write(tmp_path, text)))
    for at in ("0", "75", "200"):
        assert v[f"gamma_B@{at}"]["graphical"] == pytest.approx(90.0, abs=1e-12)
        assert v[f"pressure_angle_B@{at}"]["graphical"] == pytest.approx(0.0, abs=1e-12)


def test_double_slider_velocity_of_c_points_to_the_lower_right_at_30_degrees():
    # 000 运动 7: v_A = 100 mm/s →, AB = 500, x_A = 250: ω2 = v_A/(l sin 60°), v_C = v_A/√3 at −30°
    doc = check_json(SCENES / "kin.double_slider_direction.toml")
    v = values(doc)
    assert v["omega_2"]["graphical"] == pytest.approx(0.1 / (0.5 * math.sin(math.radians(60))), rel=1e-12)
    assert v["v_C"]["graphical"] == pytest.approx(0.1 / math.sqrt(3), rel=1e-12)
    assert v["dir_v_C"]["graphical"] == pytest.approx(330.0, abs=1e-9)
    assert all(m["ok"] for m in doc["measured"])


@pytest.mark.parametrize("phi", [10, 135, 270])
def test_crank_tip_velocity_is_perpendicular_to_the_crank(tmp_path, phi):
    p = _write(tmp_path, fourbar_scene(angle=str(phi), find='["dir_v_B", "dir_a_B"]'))
    v = values(check_json(p))
    assert v["dir_v_B"]["graphical"] == pytest.approx((phi + 90) % 360, abs=1e-9)
    assert v["dir_a_B"]["graphical"] == pytest.approx((phi + 180) % 360, abs=1e-9)  # ε = 0: centripetal


def test_a_direction_near_zero_is_judged_across_360(tmp_path):
    # φ = 270°, ω > 0: v_B points along +x, 0°; a reading of 359.9° is 0.1° off
    p = _write(tmp_path, fourbar_scene(angle="270", find='["dir_v_B"]'))
    doc = check_json(p, "--measured", "dir_v_B=359.9", "--measured", "dir_v_B=3")
    ok = [m["ok"] for m in doc["measured"]]
    assert ok == [True, False]


def test_the_direction_of_a_zero_velocity_is_refused_at_one_position(tmp_path):
    # slider-crank at its dead centre φ = 0 (e = 0): v_C = 0
    text = (SCENES / "kin.transmission_angle-slider_crank.toml").read_text(encoding="utf-8")
    text = text.replace("angle = [45, 250]", "angle = 0").replace("through = [0, 12]", "through = [0, 0]")
    text = text.replace('find = ["gamma_C", "pressure_angle_C"]', 'find = ["dir_v_C"]')
    assert_refused(run_cli("check", str(_write(tmp_path, text))), "s.toml", "find[0]", "v_C = 0", "dir_v_C", "no direction")


def test_a_cycle_skips_a_zero_velocity_direction_with_a_warning(tmp_path):
    text = (SCENES / "kin.transmission_angle-slider_crank.toml").read_text(encoding="utf-8")
    text = text.replace("angle = [45, 250]", "angle = [0, 90]").replace("through = [0, 12]", "through = [0, 0]")
    text = text.replace('find = ["gamma_C", "pressure_angle_C"]', 'find = ["dir_v_C"]')
    doc = check_json(_write(tmp_path, text))
    assert [q["name"] for q in doc["quantities"]] == ["dir_v_C@90"]
    assert any("v_C = 0" in w for w in doc["warnings"])


def test_gamma_is_not_defined_at_a_rocker_on_a_moving_link(tmp_path):
    # a six-bar's second dyad E–F hung on the coupler and the rocker: neither outer joint on the frame
    text = (SCENES / "kin.transmission_angle-fourbar.toml").read_text(encoding="utf-8")
    text = text.replace('find = ["gamma_C", "pressure_angle_C"]', 'find = ["gamma_F"]')
    text += '\n[[dyad]]\ntype = "RRR"\njoints = ["B", "F", "C"]\nlinks = ["4", "5"]\nlengths = [40, 40]\nbranch = "left"\n'
    assert_refused(run_cli("check", str(_write(tmp_path, text))), "s.toml", "find[0]", "gamma_F", "frame pivot")


def test_the_figure_marks_alpha_and_gamma_only_where_asked(tmp_path):
    out = tmp_path / "a.svg"
    code, _, err = run_cli("render", str(SCENES / "kin.transmission_angle-fourbar.toml"), "-o", str(out))
    assert code == 0, err
    svg = out.read_text(encoding="utf-8")
    assert svg.count(">α<") == 2 and svg.count(">γ<") == 2  # one of each per position
    text = (SCENES / "kin.transmission_angle-fourbar.toml").read_text(encoding="utf-8")
    plain = _write(tmp_path, text.replace('find = ["gamma_C", "pressure_angle_C"]', 'find = ["theta_3"]'))
    code, _, err = run_cli("render", str(plain), "-o", str(tmp_path / "b.svg"))
    assert code == 0, err
    assert ">α<" not in (tmp_path / "b.svg").read_text(encoding="utf-8")


def test_long_names_keep_the_table_aligned():
    code, out, _ = run_cli("check", str(SCENES / "kin.transmission_angle-fourbar.toml"))
    assert code == 0
    lines = [ln for ln in out.splitlines() if ln.startswith(("quantity", "gamma", "pressure"))]
    ends = {ln.index(" deg") for ln in lines[1:]}
    assert len(ends) == 1 and lines[0].index("unit") == ends.pop() + 1


def test_a_direction_asked_for_is_marked_on_its_polygon(tmp_path):
    # 000 运动 7: pc runs 30° below +x; the arc from the reference line is lettered 30°
    out = tmp_path / "d.svg"
    code, _, err = run_cli("render", str(SCENES / "kin.double_slider_direction.toml"), "-o", str(out))
    assert code == 0, err
    assert out.read_text(encoding="utf-8").count(">30°<") == 1
