"""Variants of a scene by key path: reading --set, writing a value into the TOML data, naming."""
from __future__ import annotations

import pytest

from graphmech.errors import SceneError
from graphmech.variants import MAX_NAME_BYTES, MAX_VARIANTS, combinations, parse_assignment, replace, value_text, variant_name

DATA = {"title": "t", "driver": {"angle_deg": [0, 90], "omega": 10, "omega_rpm": 1},
        "dyad": [{"lengths": [40, 50], "guide": {"angle": 0}}], "page": {"notation": "en"}}


@pytest.mark.parametrize("text, expected", [
    ("driver.angle=30,45,60", ("driver.angle", [30, 45, 60])),
    ("dyad[0].lengths[1]=55.5", ("dyad[0].lengths[1]", [55.5])),
    ("driver.angle=[0,90],[10,100]", ("driver.angle", [[0, 90], [10, 100]])),
    ("page.notation=zh,ru", ("page.notation", ["zh", "ru"])),
    ('title="a, b"', ("title", ["a, b"])),
    (" driver.omega = 1e1 ", ("driver.omega", [10.0])),
])
def test_an_assignment_is_read_as_toml_values(text, expected):
    assert parse_assignment(text) == expected


@pytest.mark.parametrize("text, words", [
    ("driver.angle", "expected KEY=VALUE"), ("=30", "expected KEY=VALUE"), ("driver.angle=", "expected KEY=VALUE"),
    ("driver.angle=3 0", "not a value"), ("driver.angle=[1,", "not a value"),
])
def test_a_malformed_assignment_is_refused_on_the_command_line(text, words):
    with pytest.raises(SceneError) as e:
        parse_assignment(text)
    assert e.value.source == "command line" and words in str(e.value)


def test_replace_finds_a_unit_suffixed_key_and_leaves_the_original():
    out = replace(DATA, {"driver.angle": 30, "dyad[0].lengths[1]": 55, "dyad[0].guide.angle": 10})
    assert out["driver"]["angle_deg"] == 30 and out["dyad"][0]["lengths"] == [40, 55]
    assert out["dyad"][0]["guide"] == {"angle": 10}
    assert DATA["driver"]["angle_deg"] == [0, 90] and DATA["dyad"][0]["lengths"] == [40, 50]


@pytest.mark.parametrize("path, words", [
    ("driver.angel", "driver.angel: not in the scene; did you mean angle?"),
    ("driver.omega_r", "driver.omega_r: not in the scene"),
    ("dyad[3].lengths", "dyad[3]: the array has 1 element"),
    ("dyad[0].lengths[2]", "dyad[0].lengths[2]: the array has 2 elements"),
    ("driver[0]", "driver[0]: not an array"),
    ("title.x", "title.x: not a table"),
    ("dyad[0].guide", "dyad[0].guide: the scene has a table here"),
    ("driver..angle", "not a key path"),
])
def test_a_wrong_key_path_is_named_with_the_reason(path, words):
    with pytest.raises(SceneError) as e:
        replace(DATA, {path: 1}, "s.toml")
    assert str(e.value).startswith("s.toml: ") and words in str(e.value), str(e.value)


def test_a_key_written_twice_with_units_is_ambiguous():
    with pytest.raises(SceneError, match="ambiguous: the table has omega, omega_rpm|ambiguous"):
        replace({"driver": {"omega_rad_s": 1, "omega_rpm": 2}}, {"driver.omega": 3})


def test_combinations_vary_the_first_key_slowest_and_the_last_given_wins():
    got = combinations([("a", [1, 2]), ("b", ["x", "y"]), ("a", [3])])
    assert got == [{"b": "x", "a": 3}, {"b": "y", "a": 3}]
    assert combinations([]) == [{}]
    assert len(combinations([("a", [1, 2]), ("b", [1, 2, 3])])) == 6
    with pytest.raises(SceneError, match="at most"):
        combinations([("a", list(range(101))), ("b", list(range(100)))])
    assert MAX_VARIANTS == 10_000


def test_variant_names_are_file_names():
    assert value_text(30.0) == "30" and value_text(0.5) == "0.5" and value_text(True) == "true"
    assert value_text([0, 90.0]) == "[0,90]"
    assert variant_name("s", {"title": "a/b c"}) == "s-title=a_b_c"
    assert variant_name("s", {}) == "s"
    assert value_text({"name": "E", "along": 50.0}) == "{name=E,along=50}"  # an inline table, not Python's repr


def test_a_long_variant_name_is_cut_whole_characters_and_stays_distinct():
    """A title of 100 Chinese characters is 300 bytes: as a file name it could not be written."""
    long_a, long_b = variant_name("s", {"title": "长" * 100}), variant_name("s", {"title": "长" * 99 + "短"})
    for name in (long_a, long_b):
        assert len(name.encode("utf-8")) <= MAX_NAME_BYTES and name.startswith("s-title=长长")
        name.encode("utf-8")  # whole characters: still UTF-8
    assert long_a != long_b
    assert variant_name("s", {"title": "x" * 180}) == "s-title=" + "x" * 180  # short enough: as it was
