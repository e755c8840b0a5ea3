"""Reading a linkage scene (graphmech/problems/linkage/scene.py): [frame], [driver], [[dyad]] and
[[point]] in SI, and the refusals of a linkage that is not well made, by the key path written."""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import pytest

from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import (
    PRP,
    RPP,
    RPR,
    RRP,
    RRR,
    Crank,
    Guide,
    LinkGuide,
    LinkPoint,
    SliderInput,
    Triad,
)
from graphmech.problems.reader import Page
from graphmech.scene import Scene, load_scene, parse_scene
from tests.conftest import ROOT, SCENES, assert_refused, reference_area, run_cli
from tests.scenes import doc_blocks, refusal, scene_path, scene_text, write_scene

DOCS = ROOT / "docs" / "scene-format.md"
#: The four-bar at φ = 30° with a coupler point E, valid; each test varies it.
GOOD = scene_text("linkage/fourbar_phi30")
#: A second dyad, to append to it, whose first joint G nothing defines.
DYAD_FROM_G = """
[[dyad]]
type = "RRR"
joints = ["G", "H", "D"]
links = ["5", "6"]
lengths = [50, 50]
branch = "right"
"""


problems_of = refusal
scene_file = write_scene


def message_of(text: str) -> str:
    return str(refusal(text))


# ------------------------------------------------------------------------------------------
# A linkage in SI
# ------------------------------------------------------------------------------------------


def test_fourbar_round_trip_in_si() -> None:
    scene = load_scene(scene_path("linkage/fourbar_phi30"))
    assert isinstance(scene, Scene)
    assert scene.source == "fourbar_phi30.toml"
    assert scene.title == "Four-bar, φ = 30°"
    assert scene.show == ("mechanism", "velocity")
    assert scene.find == ("v_C", "omega_3")
    assert scene.scales == {"l": pytest.approx(0.002), "v": pytest.approx(0.01)}

    link = scene.linkage
    assert link.frame_points == {"A": (0.0, 0.0), "D": (pytest.approx(0.12), 0.0)}
    assert link.frame_link == "5"  # one more than the largest moving link, 4
    crank = link.driver
    assert isinstance(crank, Crank)
    assert (crank.link, crank.pivot, crank.tip) == ("2", "A", "B")
    assert crank.length == pytest.approx(0.06, rel=1e-15)  # 60 mm
    assert crank.omega == pytest.approx(10.471975511965976, rel=1e-12)  # 100 rpm
    assert crank.omega == pytest.approx(100 * 2 * math.pi / 60)
    assert crank.epsilon == 4.0
    (dyad,) = link.dyads
    assert dyad == RRR(
        "B", "C", "D", ("3", "4"), (pytest.approx(0.12), pytest.approx(0.09)), "left"
    )
    (point,) = link.points
    assert point == LinkPoint("E", "3", ("B", "C"), pytest.approx(0.1888), pytest.approx(-0.005))
    assert link.links() == {"2": ["A", "B"], "3": ["B", "C", "E"], "4": ["D", "C"]}

    assert scene.positions.values == (pytest.approx(math.radians(30), rel=1e-15),)
    assert scene.positions.labels == ("30",)
    assert scene.measured == ()
    assert scene.precision_mm == 0.5
    assert scene.page == Page((297.0, 210.0))


def test_units_by_suffix_equal_units_by_table() -> None:
    by_table = parse_scene(tomllib.loads(GOOD))
    by_suffix = parse_scene(
        tomllib.loads(
            GOOD.replace('length = "mm"\nangle = "deg"\n', "")
            .replace("A = [0, 0]", "A_cm = [0, 0]")
            .replace("D = [120, 0]", "D_m = [0.12, 0]")
            .replace("length = 60", "length_mm = 60")
            .replace("angle = 30", f"angle_rad = {math.radians(30)!r}")
            .replace("lengths = [120, 90]", "lengths_mm = [120, 90]")
            .replace("along = 188.8", "along_mm = 188.8")
            .replace("left = -5", "left_cm = -0.5")
        )
    )
    assert by_suffix.linkage.frame_points == by_table.linkage.frame_points
    assert by_suffix.linkage.driver == by_table.linkage.driver
    assert by_suffix.linkage.dyads == by_table.linkage.dyads
    assert by_suffix.linkage.points[0].left == pytest.approx(by_table.linkage.points[0].left)
    assert by_suffix.positions.values == pytest.approx(by_table.positions.values)
    assert by_suffix.positions.labels == (repr(math.radians(30))[:14],)  # compact, as written


def test_other_units_convert() -> None:
    scene = parse_scene(
        tomllib.loads(
            scene_text("linkage/crank_other_units")
        )
    )
    assert scene.linkage.driver.length == pytest.approx(0.05)
    assert scene.linkage.driver.link == "1"  # an integer link number becomes its text
    assert scene.linkage.driver.omega == pytest.approx(math.pi)
    assert scene.linkage.driver.epsilon == pytest.approx(-math.pi / 2)


def test_clockwise_crank_is_stored_negative() -> None:
    text = GOOD.replace("epsilon_rad_s2 = 4", 'epsilon_rad_s2 = 4\ndirection = "cw"')
    crank = parse_scene(tomllib.loads(text)).linkage.driver
    assert crank.omega == pytest.approx(-100 * math.pi / 30)
    assert crank.epsilon == -4.0
    negative = text.replace("omega_rpm = 100", "omega_rpm = -100")
    assert "give omega as a magnitude" in message_of(negative)


def test_slider_driver_and_each_dyad_type() -> None:
    scene = parse_scene(
        tomllib.loads(
            scene_text("linkage/slider_every_dyad")
        )
    )
    link = scene.linkage
    assert link.driver == SliderInput(
        "1", "B", Guide((0.0, 0.0), pytest.approx(math.pi / 2)), 0.5, 0.0
    )
    assert scene.positions.values == (pytest.approx(0.04), pytest.approx(0.06))
    rrr, rrp, rpr, rpp = link.dyads
    assert isinstance(rrr, RRR) and rrr.branch == "right"
    assert rrp == RRP(
        "C", "F", ("4", "5"), pytest.approx(0.07), Guide((0.0, 0.12), 0.0), "backward"
    )
    assert rpr == RPR("F", "D", ("6", "7"), "second")
    assert rpr.coincident == ("F7", "F6")
    assert rpp == RPP(
        "C", "G", ("8", "9"), pytest.approx(math.radians(60)), Guide((0.0, -0.05), 0.0)
    )
    assert link.points == (LinkPoint("K", "9", ("G",), pytest.approx(0.005), pytest.approx(0.01)),)
    assert link.frame_link == "10"


def test_points_may_use_coincident_points_and_carry_later_dyads() -> None:
    """The six-bar pattern: E on link 3 (from D, C) is the outer joint of the next dyad."""
    scene = parse_scene(
        tomllib.loads(
            scene_text("linkage/rpr_sixbar")
        )
    )
    assert scene.linkage.frame_link == "0"
    assert scene.linkage.points[0].base == ("B", "C2")
    assert [type(d) for d in scene.linkage.dyads] == [RPR, RRR]


# ------------------------------------------------------------------------------------------
# A linkage that is not well made
# ------------------------------------------------------------------------------------------


def test_bad_length_names_the_list_item(tmp_path: Path) -> None:
    path = scene_file(tmp_path, GOOD.replace("lengths = [120, 90]", "lengths = [120, 0]"))
    with pytest.raises(SceneError) as info:
        load_scene(path)
    assert str(info.value) == "scene.toml: dyad[0].lengths[1]: must be > 0"
    assert info.value.problems == [("dyad[0].lengths[1]", "must be > 0")]
    assert isinstance(info.value, ValueError)


def test_negative_crank_length() -> None:
    assert message_of(GOOD.replace("length = 60", "length = -60")) == (
        "scene.toml: driver.length: must be > 0"
    )


def test_undefined_joint() -> None:
    text = GOOD + DYAD_FROM_G
    assert message_of(text) == "scene.toml: dyad[1].joints[0]: G is not defined before dyad[1]"


def test_joint_defined_by_a_later_dyad_is_named() -> None:
    text = (
        GOOD
        + DYAD_FROM_G.replace('"G"', '"F"')
        + """
[[dyad]]
type = "RRP"
joints = ["C", "F"]
links = ["7", "8"]
length = 30
guide = { through = [0, 0] }
branch = "forward"
"""
    )
    assert message_of(text) == (
        "scene.toml: dyad[1].joints[0]: F is not defined before dyad[1] "
        "(dyad[2] defines it: put that first)"
    )


def test_redefined_point_and_reused_link() -> None:
    err = problems_of(
        GOOD.replace('joints = ["B", "C", "D"]', 'joints = ["B", "A", "D"]').replace(
            'links = ["3", "4"]', 'links = ["2", "3"]'
        )
    )
    assert ("dyad[0].joints[1]", "A is already defined (a frame point)") in err.problems
    assert (
        "dyad[0].links[0]",
        "link 2 is already used by driver; each dyad adds two new links",
    ) in err.problems


def test_point_base_must_be_on_its_link() -> None:
    err = problems_of(GOOD.replace('base = ["B", "C"]', 'base = ["B", "D"]'))
    assert err.problems == [("point[0].base[1]", "D is not a point of link 3 (it carries B, C)")]


def test_offset_needs_a_translating_link() -> None:
    text = GOOD.replace(
        'base = ["B", "C"]\nalong = 188.8\nleft = -5', 'base = ["B"]\noffset = [1, 2]'
    )
    assert "link 3 turns" in message_of(text)


def test_missing_unit(tmp_path: Path) -> None:
    with pytest.raises(SceneError) as info:
        load_scene(scene_file(tmp_path, GOOD.replace("v_m_s_per_mm = 0.01", "v = 0.01")))
    assert str(info.value) == (
        "scene.toml: scales.v: unit not stated: write v_m_s_per_mm or set [units] velocity"
    )
    err = problems_of(GOOD.replace('length = "mm"\n', ""))
    assert (
        "driver.length",
        "unit not stated: write length_mm or set [units] length",
    ) in err.problems
    assert ("frame.D", "unit not stated: write D_mm or set [units] length") in err.problems
    # no cascade: the frame points still count as defined
    assert not any(
        "not defined" in reason or "not a frame point" in reason for _, reason in err.problems
    )


def test_rpp_slot_parallel_to_guide() -> None:
    text = (
        GOOD
        + """
[[dyad]]
type = "RPP"
joints = ["C", "G"]
links = ["5", "6"]
slot_angle = 180
guide = { through = [0, 0], angle = 0 }
"""
    )
    assert message_of(text) == (
        "scene.toml: dyad[1].slot_angle: the slot is parallel to the guide: the dyad cannot move"
    )


def test_prp_reads_a_guide_on_a_link_and_one_on_the_frame() -> None:
    scene = load_scene(ROOT / "figures" / "scenes" / "kin.tangent_mechanism.toml")
    (prp,) = scene.linkage.dyads
    assert prp == PRP("C", ("2", "3"), (LinkGuide("1", "A", "B"), Guide((0.1, 0.0), math.pi / 2)))
    assert prp.coincident == ("C2", "C3", "C1")
    assert scene.linkage.links()["1"] == ["A", "B", "C1"]


#: A PRP on the four-bar of GOOD: block 5 on the coupler 3's line B→C, block 6 on a frame guide.
PRP_ON_COUPLER = GOOD + """
[[dyad]]
type = "PRP"
joints = ["G"]
links = ["5", "6"]
guides = [{ link = "3", line = ["B", "C"] }, { through = [0, 0], angle = 90 }]
"""


def test_prp_on_a_coupler_parses() -> None:
    (_, prp) = parse_scene(tomllib.loads(PRP_ON_COUPLER), "s.toml").linkage.dyads
    assert prp.guides[0] == LinkGuide("3", "B", "C") and prp.coincident == ("G5", "G6", "G3")


@pytest.mark.parametrize("old, new, message", [
    ('line = ["B", "C"]', 'line = ["B", "D"]',
     "dyad[1].guides[0].line[1]: D is not a point of link 3 (it carries B, C, G3, E)"),
    ('link = "3", line', 'link = "7", line', "dyad[1].guides[0].link: link 7 is not a moving link defined before dyad[1]"),
    ('line = ["B", "C"]', 'line = ["B", "B"]', "dyad[1].guides[0].line[1]: the line's two points must differ (B twice)"),
    ('line = ["B", "C"]', 'line = ["B", "C"], angle = 3', ("dyad[1].guides[0].angle: a guide on a link is the line "
                                                           "through two of its points: give line, not angle")),
    ('{ link = "3", line = ["B", "C"] }', '{ through = [0, 0], angle = 0 }',
     ("dyad[1].guides: both guides on the frame: the dyad cannot move (put one on a moving link: "
      '{link = "1", line = ["A", "B"]})')),
    ('guides = [{ link = "3", line = ["B", "C"] }, ', 'guides = [',
     "dyad[1].guides: must be a list of 2 guide tables, one per block, in the order of links"),
    ('joints = ["G"]', 'joints = ["C"]', "dyad[1].joints[0]: C is already defined (by dyad[0])"),
    # these three were blamed on joints[0] ("G5 is already defined") or told to "put dyad[1] first"
    ('link = "3", line', 'link = "5", line', "dyad[1].guides[0].link: link 5 is dyad[1]'s own: a guide is on a link "
                                             "defined before it"),
    ('{ through = [0, 0], angle = 90 }', '{ link = "3", line = ["C", "B"] }',
     "dyad[1].guides[1].link: both guides on one link: C is fixed on it where their lines meet, the blocks cannot "
     "slide (put the guides on two links)"),
    ('line = ["B", "C"]', 'line = ["B", "G"]',
     "dyad[1].guides[0].line[1]: G is not defined before dyad[1] (it is this group's own new joint) (and 1 more)"),
])
def test_prp_refusals_name_the_key(old: str, new: str, message: str) -> None:
    assert old in PRP_ON_COUPLER
    assert message_of(PRP_ON_COUPLER.replace(old, new)) == f"scene.toml: {message}"


def test_rrp_on_a_moving_guide_defines_the_coincident_points() -> None:
    scene = load_scene(scene_path("linkage/slotted_link_pin"))
    (rrp,) = scene.linkage.dyads
    assert rrp.guide == LinkGuide("2", "A", "B") and rrp.coincident == ("C4", "C2")
    assert scene.linkage.links() == {"2": ["A", "B", "C2"], "3": ["D", "C"], "4": ["C"]}
    text = scene_text("linkage/slotted_link_pin")
    assert message_of(text.replace('line = ["A", "B"]', 'line = ["A", "D"]')) == (
        "scene.toml: dyad[0].guide.line[1]: D is not a point of link 2 (it carries A, B, C2)")
    assert message_of(text.replace('link = "2", line', 'link = "4", line')) == (
        "scene.toml: dyad[0].guide.link: link 4 is dyad[0]'s own: a guide is on a link defined before it")


def test_dyad_branch_is_required() -> None:
    assert message_of(GOOD.replace('branch = "left"\n', "")) == (
        'scene.toml: dyad[0].branch: missing: write branch = "left" or "right"'
    )


def test_frame_link_default_and_explicit() -> None:
    assert parse_scene(tomllib.loads(GOOD)).linkage.frame_link == "5"
    explicit = GOOD.replace("[frame]", '[frame]\nlink = "1"')
    assert parse_scene(tomllib.loads(explicit)).linkage.frame_link == "1"
    lettered = (
        GOOD.replace('link = "2"', 'link = "a"')
        .replace('["3", "4"]', '["b", "c"]')
        .replace('link = "3"', 'link = "b"')
    )
    assert parse_scene(tomllib.loads(lettered)).linkage.frame_link == "0"
    clash = GOOD.replace("[frame]", '[frame]\nlink = "3"')
    assert message_of(clash) == "scene.toml: frame.link: link 3 is a moving link (dyad[0])"


# ------------------------------------------------------------------------------------------
# The documentation and the reference problems
# ------------------------------------------------------------------------------------------


def test_docs_have_an_example_of_every_feature() -> None:
    blocks = doc_blocks()
    scenes = [parse_scene(tomllib.loads(b), "scene-format.md") for b in blocks]
    # the cam, flywheel, force and structure scenes have tests of their own
    scenes = [s for s in scenes if s.kind != "cam" and s.kind != "flywheel" and s.linkage is not None]
    dyad_types = {type(d) for s in scenes for d in s.linkage.dyads}
    assert dyad_types == {RRR, RRP, RPR, RPP, PRP, Triad}
    assert {type(s.linkage.driver) for s in scenes} == {Crank, SliderInput}
    assert {d.bar for s in scenes for d in s.linkage.dyads if isinstance(d, RPR)} == {
        "first",
        "second",
    }
    assert any(len(s.positions.values) == 12 for s in scenes)  # a range
    assert any(
        len(s.positions.values) > 1 for s in scenes if isinstance(s.linkage.driver, SliderInput)
    )
    assert any(s.measured for s in scenes)
    assert any(s.linkage.points for s in scenes)
    assert any(len(p.base) == 1 for s in scenes for p in s.linkage.points)  # an offset point
    assert {s.page.size for s in scenes} >= {(297.0, 210.0), (420.0, 297.0), (200.0, 200.0)}
    assert any(s.scales for s in scenes)
    assert any(s.linkage.driver.omega < 0 for s in scenes if isinstance(s.linkage.driver, Crank))


def test_the_reference_kinematics_problems_can_be_written() -> None:
    """Each `kinematics` problem's inputs, written as a scene, come back in SI."""
    problems = {pid: p["inputs"] for pid, p in reference_area("kinematics").items()}
    docs = {s.title: s for s in (parse_scene(tomllib.loads(b)) for b in doc_blocks())}

    p = problems["linkage.slider_crank_offset"]
    s = docs["Offset slider-crank (e = 30 mm)"]
    assert s.linkage.driver.length == pytest.approx(p["lAB_mm"] / 1000)
    assert s.linkage.driver.omega == p["omega1_rad_s"]
    assert s.positions.values == pytest.approx([math.radians(a) for a in p["theta1_deg"]])
    assert s.linkage.dyads[0].length == pytest.approx(p["lBC_mm"] / 1000)
    assert s.linkage.dyads[0].guide.through[1] == pytest.approx(p["e_mm"] / 1000)

    p = problems["linkage.slider_fixed_angle_guide"]
    s = docs["Slot at a fixed angle"]
    assert s.linkage.driver.length == pytest.approx(p["lAB_mm"] / 1000)
    assert s.linkage.driver.omega == p["omega1_rad_s"]
    assert s.positions.values == pytest.approx([math.radians(p["phi1_deg"])])
    assert s.linkage.dyads[0].slot_angle == pytest.approx(math.radians(p["theta_deg"]))

    p = problems["kin.fourbar_instant_centres"]
    s = docs["Four-bar linkage, φ = 165°"]
    assert s.linkage.driver.length == pytest.approx(p["lAB_mm"] / 1000)
    assert s.linkage.driver.omega == p["omega2_rad_s"]
    assert s.linkage.dyads[0].lengths == pytest.approx((p["lBC_mm"] / 1000, p["lCD_mm"] / 1000))
    assert s.linkage.frame_points["D"][0] == pytest.approx(p["lAD_mm"] / 1000)
    assert s.positions.values == pytest.approx([math.radians(p["phi_deg"])])

    p = problems["kin.oscillating_block"]
    s = docs["Oscillating block"]
    assert s.linkage.driver.length == pytest.approx(p["lAB_mm"] / 1000)
    assert math.dist(s.linkage.frame_points["A"], s.linkage.frame_points["C"]) == pytest.approx(
        p["lAC_mm"] / 1000
    )
    d, e = s.linkage.points
    assert d.along == pytest.approx(p["lBD_mm"] / 1000)
    assert (e.along, e.left) == pytest.approx((p["lBD_mm"] / 1000, p["lDE_mm"] / 1000))


def test_an_rpr_takes_an_offset_guide_bar_and_a_zero_offset_is_the_centred_bar(tmp_path):
    """The bar's line passes through the other link's pivot; ``offset`` puts it at e to the left of
    its own pivot (docs/scene-format.md, RPR): θ₃ = ∠CB − atan2(e, t), t = √(CB² − e²)."""
    text = """
[frame]
A_mm = [0, 0]
C_mm = [0, -200]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "B"
length_mm = 100
angle_deg = 30
omega_rad_s = 5
[[dyad]]
type = "RPR"
joints = ["B", "C"]
links = ["2", "3"]
bar = "second"
"""
    p = tmp_path / "g.toml"
    p.write_text('find = ["omega_3", "theta_3"]\n' + text, encoding="utf-8")
    code, out, _ = run_cli("check", "--json", str(p))
    # the bar through C and B: ω₃ = ω₁·AB·cos(∠ between AB and BC)/BC, from B = (86.6, 50), C = (0, −200)
    bx, by = 100 * math.cos(math.radians(30)), 100 * math.sin(math.radians(30))
    bc2 = bx ** 2 + (by + 200) ** 2
    w3 = 5.0 * (bx * bx + by * (by + 200)) / bc2  # d/dt atan2(y_B + 200, x_B) with ẋ = −ω·y_B, ẏ = ω·x_B
    dd = 5.0 * (-bx * by + bx * (by + 200))  # CB·d|CB|/dt = CB · v_B
    centred = [q["graphical"] for q in json.loads(out)["quantities"]]
    assert code == 0 and centred[0] == pytest.approx(w3, rel=1e-9)
    p.write_text('find = ["omega_3", "theta_3"]\n' + text + "offset_mm = 0\n", encoding="utf-8")
    code, out0, _ = run_cli("check", "--json", str(p))
    assert code == 0 and out0 == out  # e = 0 is the centred bar, to the byte
    for e in (20.0, -20.0):
        p.write_text('find = ["omega_3", "theta_3"]\n' + text + f"offset_mm = {e}\n", encoding="utf-8")
        code, out, _ = run_cli("check", "--json", str(p))
        t = math.sqrt(bc2 - e * e)
        # θ₃ = atan2(CB) − atan2(e, t): its rate gains e·ṫ/CB², ṫ = (CB·d|CB|/dt)/t
        theta = math.degrees(math.atan2(by + 200, bx) - math.atan2(e, t))
        got = [q["graphical"] for q in json.loads(out)["quantities"]]
        assert code == 0 and got[0] == pytest.approx(w3 + e * (dd / t) / bc2, rel=1e-9)
        assert got[1] == pytest.approx(theta, rel=1e-12)
    p.write_text(text + "offset_mm = 250\n", encoding="utf-8")  # |CB| ≈ 259.8 at 30°: 250 still fits
    assert run_cli("check", str(p))[0] == 0
    p.write_text(text.replace("angle_deg = 30", "angle_deg = 270") + "offset_mm = 150\n", encoding="utf-8")
    assert_refused(run_cli("check", str(p)), "g.toml", "cannot be assembled", "|CB| = 0.1 m < the offset |e| = 0.15 m")
    # e = |CB| = 100 mm at 270°: B on the circle of radius |e| about C, t = 0 — a dead centre, said so
    p.write_text('find = ["omega_3"]\n' + text.replace("angle_deg = 30", "angle_deg = [270, 30]")
                 + "offset_mm = 100\n", encoding="utf-8")
    code, out, err = run_cli("check", str(p))
    assert code == 0 and "omega_3@30" in out and "omega_3@270" not in out
    assert "φ₁ = 270°: construction impossible — the offset bar's line FB (B on the circle of radius |e| about C: " \
           "a dead centre)" in err


# ---------------------------------------------------------------------------- class III groups

SIXBAR_III = (SCENES / "kin.class_iii_sixbar.toml").read_text(encoding="utf-8")


def test_a_triad_is_read_and_placed_in_assembly_order() -> None:
    # a dyad that hangs on the group's E comes after it, although written first
    text = SIXBAR_III + """
[[dyad]]
type = "RRR"
joints = ["E", "H", "A"]
links = ["7", "8"]
lengths = [120, 150]
branch = "left"
"""
    s = parse_scene(tomllib.loads(text), "six.toml")
    group, dyad = s.linkage.dyads
    assert isinstance(group, Triad) and isinstance(dyad, RRR)
    assert group.outer == ("B", "F", "G") and group.inner == ("C", "D", "E")
    assert group.links == ("2", "4", "5", "3") and group.assur == (0, 1)
    assert group.lengths == pytest.approx((0.075, 0.06, 0.085)) and group.ternary == pytest.approx((0.055, 0.065, 0.05))
    assert group.start[2] == pytest.approx((0.128, 0.098)) and group.hand == 1.0
    assert s.linkage.links()["3"] == ["C", "D", "E"]


#: The six-bar's group hung on X, a point of a dyad's coupler 7 placed on B (so the values are the six-bar's).
ON_A_POINT = SIXBAR_III.replace('outer = ["B", "F", "G"]', 'outer = ["X", "F", "G"]').replace(
    'links = ["2", "4", "5", "3"]', 'links = ["9", "4", "5", "3"]').replace('"omega_2", ', "").replace(
    '"alpha_2", ', "").replace("G = [60, 150]", "G = [60, 150]\nH = [0, 150]") + """
[[dyad]]
type = "RRR"
joints = ["B", "Y", "H"]
links = ["7", "8"]
lengths = [80, 70]
branch = "left"

[[point]]
name = "X"
link = "7"
base = ["B", "Y"]
along = 0
"""


def test_a_triad_hangs_on_a_point_of_a_dyads_link(tmp_path: Path) -> None:
    # it was placed before the dyad and refused: "X is not defined before triad[0] (point[0] defines it: put that
    # first)" — which no order of the file could satisfy
    s = parse_scene(tomllib.loads(ON_A_POINT), "six.toml")
    dyad, group = s.linkage.dyads
    assert isinstance(dyad, RRR) and isinstance(group, Triad) and group.outer == ("X", "F", "G")
    values = {}
    for name, text in (("on_point", ON_A_POINT), ("six", SIXBAR_III)):
        p = tmp_path / f"{name}.toml"
        p.write_text(text, encoding="utf-8")
        code, out, err = run_cli("check", "--json", str(p))
        assert code == 0, err
        values[name] = {q["name"]: q["graphical"] for q in json.loads(out)["quantities"]}
    assert values["on_point"]["omega_3"] == pytest.approx(values["six"]["omega_3"], rel=1e-12)
    assert values["on_point"]["a_E"] == pytest.approx(values["six"]["a_E"], rel=1e-12)


def test_a_triad_on_a_point_of_its_own_link_is_refused() -> None:
    text = SIXBAR_III.replace('outer = ["B", "F", "G"]', 'outer = ["B", "F", "X"]') + (
        '\n[[point]]\nname = "X"\nlink = "3"\nbase = ["C", "D"]\nalong = 10\n')
    assert message_of(text) == ("scene.toml: triad[0].outer[2]: X is not defined before triad[0] (point[0] places it "
                                "from triad[0]'s own joints: a group cannot hang on itself)")


def test_two_triads_keep_their_file_order() -> None:
    second = SIXBAR_III[SIXBAR_III.index("[[triad]]"):SIXBAR_III.index("[page]")]
    err = refusal(SIXBAR_III + "\n" + second, "six.toml")
    assert err.problems[0] == ("triad[1].links[0]", "link 2 is already used by triad[0]; each dyad adds two new links")


@pytest.mark.parametrize("old, new, where, words", [
    ("ternary = [55, 65, 50]", "ternary = [55, 65, 130]", "triad[0].ternary", "do not make a triangle"),
    ("start = [[85, 73], [123, 34], [128, 98]]", "start = [[0, 0], [10, 10], [20, 20]]", "triad[0].start",
     "C, D, E in line"),
    ('links = ["2", "4", "5", "3"]', 'links = ["2", "4", "4", "3"]', "triad[0].links[2]", "must differ (4 twice)"),
    ('inner = ["C", "D", "E"]', 'inner = ["C", "D", "C"]', "triad[0].inner[2]", "six joints must differ"),
    ('outer = ["B", "F", "G"]', 'outer = ["B", "F", "H"]', "triad[0].outer[2]", "H is not defined"),
    ('type = "RRR-III"', 'type = "RRR-IV"', "triad[0].type", "RRR-III"),
    ("start = [[85, 73], [123, 34], [128, 98]]", "start = [[85, 73], [123, 34]]", "triad[0].start",
     "[[x, y], [x, y], [x, y]]"),
    ("start = [[85, 73], [123, 34], [128, 98]]", 'start = [[85, 73], [123, 34], [128, 98]]\nassur = ["2", "6"]',
     "triad[0].assur[1]", "6 is not one of the group's binary links"),
])
def test_a_wrong_triad_is_refused_in_one_line(old: str, new: str, where: str, words: str) -> None:
    assert old in SIXBAR_III
    err = refusal(SIXBAR_III.replace(old, new), "six.toml")
    assert "\n" not in str(err)
    assert any(path == where and words in reason for path, reason in err.problems), err.problems


IC_ENGINE_EG = (SCENES / "kin.ic_engine_EG.toml").read_text(encoding="utf-8")


def test_a_slider_leg_is_read_from_its_repeated_joint_and_its_guide() -> None:
    s = load_scene(SCENES / "kin.ic_engine_EG.toml")
    group = next(d for d in s.linkage.dyads if isinstance(d, Triad))
    assert group.outer == ("A", "C", "E") and group.inner == ("B", "C", "D")
    assert group.guides[0] is None and group.guides[2] is None
    assert group.guides[1] == Guide((0.0, 0.0), pytest.approx(math.pi / 2))
    assert group.lengths == pytest.approx((0.036, 0.0, 0.073)) and group.known_outer == ("A", "E")
    assert s.linkage.links()["4"] == ["C"] and s.linkage.links()["3"] == ["B", "C", "D"]
    assert group.name == "A-B, C on its guide, E-D (BCD)"


@pytest.mark.parametrize("old, new, where, words", [
    ("slider_guide = { through = [0, 0], angle = 90 }\n", "", "triad[0].slider_guide", "missing: outer repeats C"),
    ('outer = ["A", "C", "E"]', 'outer = ["A", "F", "E"]', "triad[0].slider_guide", "no slider leg"),
    ("lengths = [36, 0, 73]", "lengths = [36, 5, 73]", "triad[0].lengths[1]", "must be 0 for the slider leg"),
    ("lengths = [36, 0, 73]", "lengths = [0, 0, 73]", "triad[0].lengths[0]", "must be > 0"),
    ('outer = ["A", "C", "E"]', 'outer = ["B", "C", "D"]', "triad[0].outer[1]", "one slider leg at most"),
    ("slider_guide = { through = [0, 0], angle = 90 }", 'slider_guide = { through = "K", angle = 90 }',
     "triad[0].slider_guide.through", "is not a frame point"),
])
def test_a_wrong_slider_leg_is_refused_in_one_line(old: str, new: str, where: str, words: str) -> None:
    assert old in IC_ENGINE_EG
    err = refusal(IC_ENGINE_EG.replace(old, new), "eg.toml")
    assert "\n" not in str(err)
    assert any(path == where and words in reason for path, reason in err.problems), err.problems


def test_a_slider_leg_is_refused_in_a_force_scene() -> None:
    text = IC_ENGINE_EG.replace('show = ["mechanism", "velocity", "acceleration"]', 'show = ["forces"]')
    text = text.replace("v_m_s_per_mm = 0.003\na_m_s2_per_mm = 0.06\n", "")
    text = text[:text.index("find =")] + 'find = ["M_b"]\n' + text[text.index("[scales]"):]
    text += '\n[forces]\nmu_F_N_per_mm = 2\n\n[[forces.moment]]\nname = "M_r"\nlink = "2"\nmoment_Nm = -10\n'
    err = refusal(text, "eg.toml")
    assert any(path == "triad[0].slider_guide" and "not yet one with a slider leg" in reason
               for path, reason in err.problems), err.problems


@pytest.mark.parametrize("extra, where", [
    ("\n[characteristics]\n", "characteristics"),
])
def test_what_a_class_iii_group_cannot_do_yet_is_refused(extra: str, where: str) -> None:
    text = SIXBAR_III.replace('show = ["mechanism", "velocity", "acceleration"]', 'show = []') + extra
    err = refusal(text, "six.toml")
    assert "\n" not in str(err)
    assert any(path == where and "class III group is solved in linkage scenes (polygons, instant centres, the full "
               "cycle) and force scenes only" in reason
               for path, reason in err.problems), err.problems
