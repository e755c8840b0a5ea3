"""Scene files: TOML in, SI out; every problem reported with the key path the user wrote."""

from __future__ import annotations

import copy
import dataclasses
import math
import re
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import reference_area
from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import RPP, RPR, RRP, RRR, Crank, Guide, LinkPoint, SliderInput
from graphmech.problems.reader import Page
from graphmech.scene import MAX_BYTES, Scene, load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "scene-format.md"

FOURBAR = """\
title = "Four-bar, φ = 30°"
show = ["mechanism", "velocity"]
find = ["v_C", "omega_3"]

[units]
length = "mm"
angle = "deg"

[scales]
l_m_per_mm = 0.002
v = 0.01            # not allowed without [units] velocity -> used only in the error test

[frame]
A = [0, 0]
D = [120, 0]

[driver]
type = "crank"
link = "2"
pivot = "A"
tip = "B"
length = 60
angle = 30
omega_rpm = 100
epsilon_rad_s2 = 4

[[dyad]]
type = "RRR"
joints = ["B", "C", "D"]
links = ["3", "4"]
lengths = [120, 90]
branch = "left"

[[point]]
name = "E"
link = "3"
base = ["B", "C"]
along = 188.8
left = -5
"""

#: The same four-bar, valid: the velocity scale is written with its unit.
GOOD = FOURBAR.replace(
    "v = 0.01            # not allowed without [units] velocity -> used only in the error test",
    "v_m_s_per_mm = 0.01",
)


def write(tmp_path: Path, text: str | bytes, name: str = "scene.toml") -> Path:
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8")
    return path


def problems_of(text: str) -> SceneError:
    with pytest.raises(SceneError) as info:
        parse_scene(tomllib.loads(text), "scene.toml")
    return info.value


def message_of(text: str) -> str:
    return str(problems_of(text))


# ------------------------------------------------------------------------------------------
# Round trip
# ------------------------------------------------------------------------------------------


def test_fourbar_round_trip_in_si(tmp_path: Path) -> None:
    scene = load_scene(write(tmp_path, GOOD, "fourbar.toml"))
    assert isinstance(scene, Scene)
    assert scene.source == "fourbar.toml"
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


def test_scene_is_frozen(tmp_path: Path) -> None:
    scene = load_scene(write(tmp_path, GOOD))
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.title = "other"  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.linkage.driver.length = 1.0  # type: ignore[misc]


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
            """
            [units]
            omega = "deg/s"
            epsilon = "deg/s2"
            [frame]
            A_mm = [0, 0]
            [driver]
            type = "crank"
            link = 1
            pivot = "A"
            tip = "B"
            length_cm = 5
            angle_deg = 90
            omega = 180
            epsilon = -90
            """
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
            """
            [units]
            length = "mm"
            angle = "deg"
            velocity = "mm/s"
            acceleration = "m/s2"
            [frame]
            O = [0, 0]
            D = [100, 60]
            [driver]
            type = "slider"
            link = "1"
            point = "B"
            guide = { through = "O", angle = 90 }
            position = [40, 60]
            velocity = 500
            [[dyad]]
            type = "RRR"
            joints = ["B", "C", "D"]
            links = ["2", "3"]
            lengths = [80, 50]
            branch = "right"
            [[dyad]]
            type = "RRP"
            joints = ["C", "F"]
            links = ["4", "5"]
            length = 70
            guide = { through = [0, 120] }
            branch = "backward"
            [[dyad]]
            type = "RPR"
            joints = ["F", "D"]
            links = ["6", "7"]
            bar = "second"
            [[dyad]]
            type = "RPP"
            joints = ["C", "G"]
            links = ["8", "9"]
            slot_angle = 60
            guide = { through = [0, -50], angle = 0 }
            [[point]]
            name = "K"
            link = "9"
            base = ["G"]
            offset = [5, 10]
            """
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
            """
            [units]
            length = "m"
            angle = "deg"
            omega = "rad/s"
            [frame]
            link = "0"
            A = [0, 0]
            C = [-0.1, 0]
            D = [0.3, -0.06]
            [driver]
            type = "crank"
            link = "1"
            pivot = "A"
            tip = "B"
            length = 0.03
            angle = 45
            omega = 10
            [[dyad]]
            type = "RPR"
            joints = ["B", "C"]
            links = ["2", "3"]
            bar = "first"
            [[point]]
            name = "E"
            link = "2"
            base = ["B", "C2"]
            along = 0.05
            left = 0.04
            [[dyad]]
            type = "RRR"
            joints = ["E", "F", "D"]
            links = ["4", "5"]
            lengths = [0.2, 0.2]
            branch = "left"
            """
        )
    )
    assert scene.linkage.frame_link == "0"
    assert scene.linkage.points[0].base == ("B", "C2")
    assert [type(d) for d in scene.linkage.dyads] == [RPR, RRR]


# ------------------------------------------------------------------------------------------
# Error messages
# ------------------------------------------------------------------------------------------


def test_bad_length_names_the_list_item(tmp_path: Path) -> None:
    path = write(tmp_path, GOOD.replace("lengths = [120, 90]", "lengths = [120, 0]"))
    with pytest.raises(SceneError) as info:
        load_scene(path)
    assert str(info.value) == "scene.toml: dyad[0].lengths[1]: must be > 0"
    assert info.value.problems == [("dyad[0].lengths[1]", "must be > 0")]
    assert isinstance(info.value, ValueError)


def test_negative_crank_length() -> None:
    assert message_of(GOOD.replace("length = 60", "length = -60")) == (
        "scene.toml: driver.length: must be > 0"
    )


def test_unknown_key_suggests_the_nearest() -> None:
    assert message_of(GOOD.replace("omega_rpm = 100", "omgea_rpm = 100")) == (
        "scene.toml: driver.omgea_rpm: unknown key; did you mean omega_rpm? (and 1 more)"
    )
    assert message_of(GOOD.replace("[[point]]", "[[points]]")).startswith(
        "scene.toml: points: unknown key; did you mean point?"
    )
    assert message_of(GOOD.replace("branch =", "brunch =")).startswith(
        "scene.toml: dyad[0].brunch: unknown key; did you mean branch?"
    )


def test_a_misspelt_kinds_table_gets_a_suggestion_in_any_scene() -> None:
    assert message_of(GOOD + "\n[efficency]\ntype = 'incline'\n") == (
        "scene.toml: efficency: unknown key; did you mean efficiency?"
    )


def test_a_table_of_another_kind_is_not_called_a_misspelling_of_itself() -> None:
    """Two kinds' tables in one file: one kind reads it and refuses the other's table in one line,
    never with "cycle: unknown key; did you mean cycle?" (the registry's tables are suggestions
    for a misspelt key only)."""
    from graphmech.problems import tables

    for a in tables():
        for b in tables():
            if a == b:
                continue
            with pytest.raises(SceneError) as info:
                parse_scene({a: {}, b: {}}, "mix.toml")
            err = info.value
            assert "\n" not in str(err)
            for path, reason in err.problems:
                assert not reason.endswith(f"did you mean {path}?"), (a, b, path, reason)


def test_unknown_choice_suggests_the_nearest() -> None:
    assert message_of(GOOD.replace('type = "RRR"', 'type = "rrr"')) == (
        "scene.toml: dyad[0].type: unknown value 'rrr': use RRR, RRP, RPR or RPP "
        "(did you mean RRR?)"
    )


@pytest.mark.parametrize("value", ["inf", "-inf", "nan"])
def test_non_finite_numbers_are_refused(value: str) -> None:
    err = problems_of(GOOD.replace("D = [120, 0]", f"D = [{value}, 0]"))
    assert err.problems[0] == ("frame.D[0]", f"must be a finite number, not {float(value)!r}")


def test_undefined_joint() -> None:
    text = (
        GOOD
        + """
[[dyad]]
type = "RRR"
joints = ["G", "H", "D"]
links = ["5", "6"]
lengths = [50, 50]
branch = "right"
"""
    )
    assert message_of(text) == "scene.toml: dyad[1].joints[0]: G is not defined before dyad[1]"


def test_joint_defined_by_a_later_dyad_is_named() -> None:
    text = (
        GOOD
        + """
[[dyad]]
type = "RRR"
joints = ["F", "H", "D"]
links = ["5", "6"]
lengths = [50, 50]
branch = "right"

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


def test_markup_in_names_is_refused() -> None:
    err = problems_of(GOOD.replace('name = "E"', 'name = "E<script>"'))
    assert err.problems[0][0] == "point[0].name"
    assert "is not a point name" in err.problems[0][1]
    err = problems_of(GOOD.replace('tip = "B"', 'tip = "B\\n"'))  # "$" would let this through
    assert err.problems[0] == (
        "driver.tip",
        "'B\\n' is not a point name: capital letters, then digits or primes (B, C2, E')",
    )
    assert "\n" not in str(err)


def test_weird_keys_are_quoted_in_messages() -> None:
    err = problems_of(GOOD + '\n[measured]\n"a\\nb" = 1\n')
    assert err.problems[0][0] == "measured.'a\\nb'"
    assert "\n" not in str(err)


def test_too_many_positions() -> None:
    many = ", ".join(str(k) for k in range(3601))
    assert message_of(GOOD.replace("angle = 30", f"angle = [{many}]")) == (
        "scene.toml: driver.angle: absurd position count (3601 > 3600)"
    )
    assert message_of(
        GOOD.replace("angle = 30", "angle = {start = 0, stop = 360, step = 0.01}")
    ) == ("scene.toml: driver.angle: absurd position count (36000 > 3600)")
    # exactly 3600 is fine
    scene = parse_scene(
        tomllib.loads(GOOD.replace("angle = 30", "angle = {start = 0, stop = 360, step = 0.1}"))
    )
    assert len(scene.positions.values) == 3600


def test_oversized_file_is_refused_before_parsing(tmp_path: Path) -> None:
    text = GOOD + "# " + "x" * MAX_BYTES + "\n= broken toml"
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, text))
    assert str(info.value) == (
        "scene.toml: file is larger than 1 MiB; a scene is a few kilobytes, refusing to read it"
    )


def test_toml_syntax_error_gives_the_line(tmp_path: Path) -> None:
    text = GOOD.replace("angle = 30", "angle = 30 deg")
    line = GOOD.splitlines().index("angle = 30") + 1
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, text))
    message = str(info.value)
    assert message.startswith(f"scene.toml: line {line}: invalid TOML: ")
    assert "\n" not in message


def test_not_utf8(tmp_path: Path) -> None:
    raw = GOOD.replace("φ = 30°", "phi = 30\xb0").encode("latin-1")
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, raw))
    assert (
        str(info.value) == "scene.toml: line 1: not UTF-8 text (byte 0xb0); save the file as UTF-8"
    )


def test_utf8_with_bom_is_read(tmp_path: Path) -> None:
    assert load_scene(write(tmp_path, b"\xef\xbb\xbf" + GOOD.encode())).title == "Four-bar, φ = 30°"


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match=r"^nothere\.toml: cannot read the file"):
        load_scene(tmp_path / "nothere.toml")


def test_missing_unit(tmp_path: Path) -> None:
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, FOURBAR))
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


def test_unit_that_does_not_fit() -> None:
    assert message_of(GOOD.replace("length = 60", "length_deg = 60")) == (
        "scene.toml: driver.length_deg: deg is not a unit of a length; "
        "write length_mm, length_cm or length_m"
    )
    assert message_of(GOOD.replace('angle = "deg"', 'angle = "degree"')) == (
        "scene.toml: units.angle: unknown unit 'degree': use deg or rad (did you mean deg?)"
    )


def test_quantity_given_twice() -> None:
    assert message_of(GOOD.replace("length = 60", "length = 60\nlength_m = 0.06")) == (
        "scene.toml: driver.length_m: given twice (also as length)"
    )


def test_all_problems_are_collected() -> None:
    text = GOOD.replace("lengths = [120, 90]", "lengths = [120, -90]").replace(
        "omega_rpm = 100", "omega_rpm = inf"
    )
    err = problems_of(text)
    assert len(err.problems) >= 2
    assert err.problems == [
        ("driver.omega_rpm", "must be a finite number, not inf"),
        ("dyad[0].lengths[1]", "must be > 0"),
    ]
    assert str(err) == "scene.toml: driver.omega_rpm: must be a finite number, not inf (and 1 more)"


def test_header_problems() -> None:
    text = GOOD.replace(
        'title = "Four-bar, φ = 30°"\nshow = ["mechanism", "velocity"]\nfind = ["v_C", "omega_3"]',
        'title = "'
        + "x" * 201
        + '"\nshow = ["velocity", "velocity", "speed"]\nfind = ["v_C", "", "v_C"]',
    )
    assert problems_of(text).problems == [
        ("title", "too long (201 characters; at most 200)"),
        ("show[1]", "velocity is listed twice"),
        ("show[2]", "unknown value 'speed': use mechanism, velocity, acceleration, instant_centres, cycle, paths, diagrams or characteristics"),
        ("find[1]", "must be a non-empty string (a quantity name)"),
        ("find[2]", "'v_C' is listed twice"),
    ]


def test_wrong_types() -> None:
    err = problems_of(
        GOOD.replace('links = ["3", "4"]', 'links = "34"').replace("length = 60", 'length = "60"')
    )
    assert ("driver.length", "must be a number, not a string") in err.problems
    assert ("dyad[0].links", "must be a list of 2, not a string") in err.problems
    assert message_of(GOOD.replace("[[dyad]]", "[dyad]")) == (
        "scene.toml: dyad: must be an array of tables: write [[dyad]]"
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


def test_dyad_branch_is_required() -> None:
    assert message_of(GOOD.replace('branch = "left"\n', "")) == (
        'scene.toml: dyad[0].branch: missing: write branch = "left" or "right"'
    )


# ------------------------------------------------------------------------------------------
# Positions, frame link, measured, check, page
# ------------------------------------------------------------------------------------------


def test_ranges_expand_with_stop_excluded() -> None:
    scene = parse_scene(
        tomllib.loads(GOOD.replace("angle = 30", "angle = {start = 0, stop = 360, step = 30}"))
    )
    assert scene.positions.labels == tuple(str(a) for a in range(0, 360, 30))
    assert scene.positions.values == pytest.approx([math.radians(a) for a in range(0, 360, 30)])

    down = parse_scene(
        tomllib.loads(GOOD.replace("angle = 30", "angle = {start = 90, stop = -1, step = -45}"))
    )
    assert down.positions.labels == ("90", "45", "0")

    tenths = parse_scene(
        tomllib.loads(GOOD.replace("angle = 30", "angle = {start = 0.1, stop = 0.4, step = 0.1}"))
    )
    assert tenths.positions.labels == ("0.1", "0.2", "0.3")  # 0.30000000000000004 is written 0.3


def test_range_problems() -> None:
    assert message_of(GOOD.replace("angle = 30", "angle = {start = 0, stop = 360, step = 0}")) == (
        "scene.toml: driver.angle.step: must not be 0"
    )
    assert "the range is empty" in message_of(
        GOOD.replace("angle = 30", "angle = {start = 0, stop = 360, step = -30}")
    )
    assert message_of(GOOD.replace("angle = 30", "angle = {start = 0, stop = 360, stpe = 30}")) == (
        "scene.toml: driver.angle.stpe: unknown key; did you mean step? (and 1 more)"
    )


def test_position_labels_are_compact_and_unique() -> None:
    scene = parse_scene(
        tomllib.loads(GOOD.replace("angle = 30", "angle = [50, 12.5, 220.0, -0.0]"))
    )
    assert scene.positions.labels == ("50", "12.5", "220", "0")
    assert message_of(GOOD.replace("angle = 30", "angle = [50, 220, 50.0]")) == (
        "scene.toml: driver.angle[2]: position 50 is given twice"
    )
    assert message_of(GOOD.replace("angle = 30", "angle = []")) == (
        "scene.toml: driver.angle: no positions: give at least one"
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


def test_measured_table_is_kept_raw_and_in_order() -> None:
    text = (
        GOOD.replace("angle = 30", "angle = [30, 60]")
        + """
[measured]
pc = 52
"v_C@30" = 0.26
"p'c'" = 40.5
"n'c'@60" = 12
"b′c′" = 18
omega_3 = -2.5
a_k_C2C3 = 1.25

[check]
precision_mm = 0.25
"""
    )
    scene = parse_scene(tomllib.loads(text))
    assert scene.measured == (
        ("pc", 52.0),
        ("v_C@30", 0.26),
        ("p'c'", 40.5),
        ("n'c'@60", 12.0),
        ("b′c′", 18.0),
        ("omega_3", -2.5),
        ("a_k_C2C3", 1.25),
    )
    assert scene.precision_mm == 0.25


def test_measured_problems() -> None:
    text = (
        GOOD
        + """
[measured]
"v_C@50" = 1
"<b>" = 2
pc = "52"
"p'c'" = nan

[check]
precision_mm = 0
"""
    )
    err = problems_of(text)
    assert err.problems == [
        ("measured.v_C@50", "no position is labelled 50 (positions: 30)"),
        (
            "measured.'<b>'",
            "not a measured name: a quantity (v_C, omega_2, a_k_C2C3, v_C@50) "
            "or a drawn segment (pc, \"p'c'\", \"n'c'\")",
        ),
        ("measured.pc", "must be a number, not a string"),
        ("measured.p'c'", "must be a finite number, not nan"),
        ("check.precision_mm", "must be > 0"),
    ]


@pytest.mark.parametrize(
    ("size", "expected"),
    [
        ('"A4"', (297.0, 210.0)),
        ('"A3"', (420.0, 297.0)),
        ('"A4-portrait"', (210.0, 297.0)),
        ('"A3-portrait"', (297.0, 420.0)),
        ("[200, 150.5]", (200.0, 150.5)),
    ],
)
def test_page_sizes(size: str, expected: tuple[float, float]) -> None:
    assert parse_scene(tomllib.loads(GOOD + f"\n[page]\nsize = {size}\n")).page == Page(expected)


def test_bad_page() -> None:
    assert message_of(GOOD + '\n[page]\nsize = "a3"\n') == (
        "scene.toml: page.size: unknown paper 'a3': use A4, A4-portrait, A3 or A3-portrait "
        "or [width, height] in mm (did you mean A3?)"
    )
    assert (
        message_of(GOOD + "\n[page]\nsize = [0, 100]\n") == "scene.toml: page.size[0]: must be > 0"
    )


def test_problems_come_in_file_order() -> None:
    text = GOOD.replace("[units]", "[page]\nsize = 3\n\n[units]").replace(
        "length = 60", "length = 0"
    )
    err = problems_of(text)
    assert [p for p, _ in err.problems] == ["page.size", "driver.length"]


# ------------------------------------------------------------------------------------------
# The documentation and the reference problems
# ------------------------------------------------------------------------------------------


def doc_blocks() -> list[str]:
    return re.findall(r"^```toml\n(.*?)^```", DOCS.read_text(encoding="utf-8"), re.S | re.M)


def test_docs_have_an_example_of_every_feature() -> None:
    blocks = doc_blocks()
    scenes = [parse_scene(tomllib.loads(b), "scene-format.md") for b in blocks]
    # the cam, flywheel, force and structure scenes have tests of their own
    scenes = [s for s in scenes if s.kind != "cam" and s.kind != "flywheel" and s.linkage is not None]
    dyad_types = {type(d) for s in scenes for d in s.linkage.dyads}
    assert dyad_types == {RRR, RRP, RPR, RPP}
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


@pytest.mark.parametrize("index", range(len(doc_blocks())))
def test_each_doc_example_parses(index: int, tmp_path: Path) -> None:
    scene = load_scene(write(tmp_path, doc_blocks()[index], "example.toml"))
    assert scene.source == "example.toml"
    if scene.kind == "cam":  # a cam scene
        assert scene.linkage is None and scene.positions is None
        return
    if scene.kind == "flywheel" and scene.linkage is None:  # a machine without a linkage
        assert scene.positions is None
        return
    if scene.kind == "efficiency" or scene.kind == "balancing" or scene.kind == "structure":  # no mechanism
        assert scene.linkage is None and scene.positions is None
        return
    assert scene.linkage.frame_link not in scene.linkage.links()



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


# ------------------------------------------------------------------------------------------
# Robustness: whatever the data, the answer is a Scene or a SceneError
# ------------------------------------------------------------------------------------------

toml_values = st.recursive(
    st.booleans()
    | st.integers(-(2**63), 2**63 - 1)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=8)
    | st.sampled_from(["A", "B", "C", "D", "2", "mm", "deg", "RRR", "left", "crank", "slider"]),
    lambda inner: (
        st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner, max_size=4)
    ),
    max_leaves=12,
)


def leaves(data: object, path: tuple = ()) -> list[tuple]:
    if isinstance(data, dict):
        return [path] + [q for k, v in data.items() for q in leaves(v, path + (k,))]
    if isinstance(data, list):
        return [path] + [q for i, v in enumerate(data) for q in leaves(v, path + (i,))]
    return [path]


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_any_mutation_gives_a_scene_or_a_scene_error(data: st.DataObject) -> None:
    base = tomllib.loads(data.draw(st.sampled_from([GOOD, *doc_blocks()])))
    mutated = copy.deepcopy(base)
    path = data.draw(st.sampled_from(leaves(mutated)[1:]))
    parent = mutated
    for step in path[:-1]:
        parent = parent[step]
    if data.draw(st.booleans()) and isinstance(parent, dict):
        del parent[path[-1]]
    else:
        parent[path[-1]] = data.draw(toml_values)
    try:
        scene = parse_scene(mutated, "fuzz.toml")
    except SceneError as err:
        assert err.problems
        assert "\n" not in str(err)
        return
    if scene.kind == "cam":
        cam = scene.problem.cam
        assert scene.linkage is None and scene.positions is None
        assert cam.base_radius > 0 and cam.omega > 0 and cam.rotation in (1, -1)
        assert 0 < scene.problem.step <= math.pi / 2
        assert math.isclose(sum(seg.angle for seg in cam.program.segments), 2 * math.pi)
        return
    if scene.kind == "flywheel" and scene.linkage is None:
        assert scene.positions is None
        return
    if scene.kind == "efficiency" or scene.kind == "balancing":  # fuzzed further in tests/test_efficiency.py
        assert scene.linkage is None and scene.positions is None
        return
    if scene.kind == "structure":  # a topology: its analysis must not fail either
        import json

        from graphmech.problems.structure.check import analyse_structure

        assert scene.linkage is None and scene.positions is None
        json.dumps(analyse_structure(scene).summary(), allow_nan=False)
        return
    assert all(math.isfinite(v) for v in scene.positions.values)
    assert 1 <= len(scene.positions.values) <= 3600


@settings(max_examples=100, deadline=None)
@given(st.binary(max_size=300))
def test_any_bytes_give_a_scene_error(tmp_path_factory: pytest.TempPathFactory, raw: bytes) -> None:
    path = tmp_path_factory.mktemp("fuzz") / "fuzz.toml"
    path.write_bytes(raw)
    with pytest.raises(SceneError):
        load_scene(path)
