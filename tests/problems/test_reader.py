"""The reading toolkit every kind's reader uses (graphmech/problems/reader.py): typed values and
their refusals, units, the header, positions, [measured], [check], [page], the order of problems.

The first part reads the shared four-bar through parse_scene, so each message is the one a user
sees; the second asks the toolkit's functions directly.
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib

import pytest

from graphmech.drawing.primitives import TitleBlock
from graphmech.errors import SceneError
from graphmech.scales import FIT_WORKING_AREA, PAPER
from graphmech.problems.reader import (
    Page,
    Reader,
    compact,
    did_you_mean,
    file_order,
    key_text,
    maybe,
    one_of,
    page_size,
    pole_distances,
    raise_sorted,
    read_units,
    say,
    type_name,
)
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, assert_refused, run_cli
from tests.scenes import refusal, scene_path, scene_text

#: The four-bar at φ = 30° with a coupler point E, valid; each test varies it.
GOOD = scene_text("linkage/fourbar_phi30")


problems_of = refusal


def message_of(text: str) -> str:
    return str(refusal(text))


# ------------------------------------------------------------------------------------------
# Through a scene: the messages a user reads
# ------------------------------------------------------------------------------------------


def test_scene_is_frozen() -> None:
    scene = load_scene(scene_path("linkage/fourbar_phi30"))
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.title = "other"  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.linkage.driver.length = 1.0  # type: ignore[misc]


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


def test_unknown_choice_suggests_the_nearest() -> None:
    assert message_of(GOOD.replace('type = "RRR"', 'type = "rrr"')) == (
        "scene.toml: dyad[0].type: unknown value 'rrr': use RRR, RRP, RPR, RPP or PRP "
        "(did you mean RRR?)"
    )


@pytest.mark.parametrize("value", ["inf", "-inf", "nan"])
def test_non_finite_numbers_are_refused(value: str) -> None:
    err = problems_of(GOOD.replace("D = [120, 0]", f"D = [{value}, 0]"))
    assert err.problems[0] == ("frame.D[0]", f"must be a finite number, not {float(value)!r}")


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
pc = "52 mm"
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
        ("measured.pc", "must be a finite number as written (1.44, +2.17, -0.0120, 1.44e3), not '52 mm'"),
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
        ('"A2"', (594.0, 420.0)),
        ('"A2-portrait"', (420.0, 594.0)),
        ('"A1"', (841.0, 594.0)),
        ('"A1-portrait"', (594.0, 841.0)),
        ("[200, 150.5]", (200.0, 150.5)),
    ],
)
def test_page_sizes(size: str, expected: tuple[float, float]) -> None:
    assert parse_scene(tomllib.loads(GOOD + f"\n[page]\nsize = {size}\n")).page == Page(expected)


def test_page_notation_is_read_and_checked() -> None:
    page = parse_scene(tomllib.loads(GOOD + '\n[page]\nnotation = "zh"\n')).page
    assert page.notation == "zh" and Page().notation == "en"
    assert message_of(GOOD + '\n[page]\nnotation = "cn"\n').startswith(
        "scene.toml: page.notation: unknown value 'cn': use en, zh or ru")


def test_bad_page() -> None:
    assert message_of(GOOD + '\n[page]\nsize = "a3"\n') == (
        "scene.toml: page.size: unknown paper 'a3': use A4, A4-portrait, A3, A3-portrait, A2, "
        "A2-portrait, A1, A1-portrait, fit (the drawing cropped) or [width, height] in mm (did you mean A3?)"
    )
    assert message_of(GOOD + '\n[page]\nsize = "fitt"\n').endswith("(did you mean fit?)")
    assert (
        message_of(GOOD + "\n[page]\nsize = [0, 100]\n") == "scene.toml: page.size[0]: must be > 0"
    )


def test_a_fit_page_chooses_its_scales_for_the_working_area() -> None:
    scene = parse_scene(tomllib.loads(GOOD + '\n[page]\nsize = "fit"\nnotation = "ru"\n'))
    assert scene.page == Page(FIT_WORKING_AREA, "ru", fit=True)
    assert page_size(scene) == FIT_WORKING_AREA == PAPER["A3"]


def test_a_title_block_is_read_as_the_scene_writes_it() -> None:
    text = GOOD + ('\n[page]\nnotation = "zh"\n[page.title_block]\ntitle = "曲柄摇杆机构"\nname = "张三"\n'
                   'group = "机械 2101"\ndate = "2024-06-01"\nsheet = "1"\n')
    page = parse_scene(tomllib.loads(text)).page
    assert page.title_block == TitleBlock("曲柄摇杆机构", "张三", "机械 2101", "2024-06-01", "1", "zh")
    bare = parse_scene(tomllib.loads(GOOD + "\n[page.title_block]\n")).page
    assert bare.title_block == TitleBlock() and not bare.fit and bare.size == (297.0, 210.0)
    assert parse_scene(tomllib.loads(GOOD)).page.title_block is None


@pytest.mark.parametrize(("body", "message"), [
    ("date = 2024-06-01", 'page.title_block.date: must be a string in quotes: date = "2024-06-01"'),
    ("sheet = 1", "page.title_block.sheet: must be a string, not a number"),
    ('nmae = "x"', "page.title_block.nmae: unknown key; did you mean name?"),
    ('name = "' + "x" * 61 + '"', "page.title_block.name: too long (61 characters; at most 60 fit a cell)"),
    ('title = "' + "x" * 201 + '"', "page.title_block.title: too long (201 characters; at most 200 fit a cell)"),
    ('group = "a\\nb"', "page.title_block.group: must be one line: a cell of the title block holds one line"),
])
def test_a_bad_title_block_is_one_line_naming_the_key(body: str, message: str) -> None:
    assert message_of(GOOD + f"\n[page.title_block]\n{body}\n") == f"scene.toml: {message}"
    assert message_of(GOOD + "\n[page]\ntitle_block = 3\n") == "scene.toml: page.title_block: must be a table, not a number"


def test_problems_come_in_file_order() -> None:
    text = GOOD.replace("[units]", "[page]\nsize = 3\n\n[units]").replace(
        "length = 60", "length = 0"
    )
    err = problems_of(text)
    assert [p for p, _ in err.problems] == ["page.size", "driver.length"]


@pytest.mark.parametrize("scene_id, h", [("linkage.slider_crank_offset-cycle", "5e-324"),
                                         ("linkage.slider_crank_offset-cycle", "1e-300"),
                                         ("linkage.slider_crank_offset-cycle", "[20, 0.5]"),
                                         ("fly.compressor_course_project", "5e-324"),
                                         ("fly.compressor_course_project", "2000")])
def test_a_pole_distance_that_cannot_be_drawn_is_refused_where_it_is_read(tmp_path, scene_id, h):
    """H = 5e-324 mm divided by zero (cycle) or made an infinite ordinate (flywheel): exit 3."""
    text = (SCENES / f"{scene_id}.toml").read_text(encoding="utf-8")
    p = tmp_path / "h.toml"
    if "pole_distance_mm" not in text:
        text = text.replace("[flywheel]\n", "[flywheel]\npole_distance_mm = 30\n")
    p.write_text(re.sub(r"pole_distance_mm = .*", f"pole_distance_mm = {h}", text), encoding="utf-8")
    for argv in (("render", str(p), "-o", str(tmp_path / "x.svg")), ("check", str(p), "--json")):
        assert_refused(run_cli(*argv), "h.toml", "pole_distance_mm", "a pole distance lies between 1 and 1000 mm")


# ------------------------------------------------------------------------------------------
# The toolkit's functions, directly
# ------------------------------------------------------------------------------------------


def reader(table, units=None):
    """A reader of ``table`` at key path "t", with its own list of problems."""
    return Reader(table, "t", [], units or {})


def test_a_key_path_quotes_what_is_not_a_plain_key():
    assert key_text("omega_rpm") == "omega_rpm" and key_text("p'c'@3") == "p'c'@3"
    assert key_text("a b") == "'a b'" and key_text("a\nb") == "'a\\nb'"
    r = reader({})
    assert (r.at("x"), r.at(2), Reader({}, "", [], {}).at("x")) == ("t.x", "t[2]", "x")


def test_messages_say_values_short_and_on_one_line():
    assert say("x" * 50) == repr("x" * 39 + "…")
    assert say("A\nB") == "'A\\nB'"
    assert [type_name(v) for v in (True, 3, 2.5, "s", [], {})] == [
        "true/false", "a number", "a number", "a string", "a list", "a table"]
    assert (compact(50.0), compact(12.5), compact(-0.0), compact(0.1 + 0.2)) == ("50", "12.5", "0", "0.3")
    assert (one_of(["A4"]), one_of(["deg", "rad"]), one_of("abc")) == ("A4", "deg or rad", "a, b or c")


def test_the_nearest_word_is_suggested_letters_swapped_first():
    assert did_you_mean("stpe", ["step", "stop", "start"]) == "; did you mean step?"
    assert did_you_mean("RRR", ["rrr", "RRP"]) == "; did you mean rrr?"  # the same letters in another case
    assert did_you_mean("zzz", ["step", "stop"]) == ""
    assert maybe("degree", ["deg", "rad"]) == " (did you mean deg?)" and maybe("x", ["deg"]) == ""


def test_a_number_is_finite_and_not_a_boolean():
    r = reader({})
    assert r.number(3, "t.a") == 3.0 and r.number(2.5, "t.b", positive=True) == 2.5
    assert r.number(True, "t.c") is None
    assert r.number(0, "t.d", positive=True) is None
    assert r.number(10**400, "t.e") is None
    assert r.problems == [("t.c", "must be a number, not true/false"), ("t.d", "must be > 0"),
                          ("t.e", "number too large")]


def test_numbers_are_exactly_count_and_each_checked():
    r = reader({})
    assert r.numbers([1, 2], "t.p", 2) == [1.0, 2.0]
    assert r.numbers([1, 2, 3], "t.q", 2) is None
    assert r.numbers([1, -2], "t.r", 2, positive=True) is None
    assert r.problems == [("t.q", "must be [x, y]: a list of 2 numbers, not a list of 3"), ("t.r[1]", "must be > 0")]


def test_a_quantity_by_its_suffix_or_the_units_table_in_si():
    assert reader({"length_cm": 5}).scalar("length", "length") == pytest.approx(0.05)
    assert reader({"length": 5}, {"length": "mm"}).scalar("length", "length") == pytest.approx(0.005)
    assert reader({"angle_deg": 90}).scalar("angle", "angle") == pytest.approx(math.pi / 2)
    assert reader({"omega_rpm": 60}).scalar("omega", "omega") == pytest.approx(2 * math.pi)
    value = reader({"offset_mm": 35}).value("offset", "length")
    assert (value.si, value.text(), value.text(0.02)) == (pytest.approx(0.035), "35 mm", "20 mm")
    r = reader({"length": 5})
    assert r.scalar("length", "length") is None
    assert r.problems == [("t.length", "unit not stated: write length_mm or set [units] length")]


def test_an_unread_key_is_unknown_and_a_near_one_suggested():
    r = reader({"lenght": 1, "angle": 2})
    r.raw("angle")
    r.raw("length")
    r.finish()
    assert r.problems == [("t.lenght", "unknown key; did you mean length?")]


def test_a_string_choice_and_a_flag():
    r = reader({"branch": "lft", "ranges": "yes", "start": "extreme"})
    assert r.string("start", choices=("driver", "extreme")) == "extreme"
    assert r.string("branch", choices=("left", "right")) is None
    assert r.string("sense", default="ccw") == "ccw"
    assert r.flag("ranges") is None and r.flag("absent") is None
    assert r.problems == [("t.branch", "unknown value 'lft': use left or right (did you mean left?)"),
                          ("t.ranges", "must be true or false, not a string")]


def test_the_units_table_refuses_an_unknown_unit_without_a_cascade():
    top = Reader({"units": {"length": "inch", "angle": "rad"}}, "", [], {})
    units = read_units(top)
    assert units["angle"] == "rad" and units["length"] is None
    assert top.problems == [("units.length", "unknown unit 'inch': use mm, cm or m")]


def test_a_pole_distance_is_millimetres_of_drawing_within_range():
    assert pole_distances(reader({})) is None
    assert pole_distances(reader({"pole_distance_mm": 25}), 2) == (25.0, 25.0)
    assert pole_distances(reader({"pole_distance_mm": [30, 20]}), 2) == (30.0, 20.0)
    r = reader({"pole_distance_m": 0.02})
    assert pole_distances(r) is None
    assert r.problems == [("t.pole_distance_m", "H is a distance on the drawing: write pole_distance_mm")]
    r = reader({"pole_distance_mm": [30, 0.5]})
    assert pole_distances(r, 2) is None
    assert r.problems[0][0] == "t.pole_distance_mm[1]" and r.problems[0][1].startswith("H2 = 0.5 mm: a pole distance lies between 1 and 1000 mm")


def test_problems_sort_in_file_order_an_unknown_key_before_a_missing_one():
    """Top-level tables by ``order``, then the section's keys as written, an array's items before
    the whole array; a misspelt key (often why another is missing) before the missing one."""
    order = {"title": 0, "cam": 1, "page": 2}
    sub = {"follower": 0, "segment": 1}
    problems = [("page.size", "must be > 0"), ("cam.segment[1].angle", "must be > 0"), ("cam.segment", "the angles"),
                ("cam.base_radius", "missing"), ("cam.base_radus", "unknown key; did you mean base_radius?"),
                ("cam.follower.offset", "missing"), ("cam.segment[0].law", "unknown value")]
    got = sorted(problems, key=lambda p: file_order(p, order, sub, "cam"))
    assert [p for p, _ in got] == ["cam.follower.offset", "cam.segment[0].law", "cam.segment[1].angle",
                                   "cam.segment", "cam.base_radus", "cam.base_radius", "page.size"]
    with pytest.raises(SceneError) as info:
        raise_sorted(problems, {"cam": {"follower": {}, "segment": []}}, order, "cam", "c.toml")
    assert str(info.value) == "c.toml: cam.follower.offset: missing (and 6 more)"


def test_a_scenes_page_size_in_mm():
    assert page_size(parse_scene(tomllib.loads(GOOD))) == (297.0, 210.0)
    assert page_size(parse_scene(tomllib.loads(GOOD + '\n[page]\nsize = "A3-portrait"\n'))) == (297.0, 420.0)
    assert page_size(parse_scene(tomllib.loads(GOOD + "\n[page]\nsize = [200, 150]\n"))) == (200.0, 150.0)
