"""Reading a [centres] scene: the direct centres from wheels and revolutes; bad input refused in one line."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import SceneError
from graphmech.problems.centres.scene import name_problem, parse_name
from graphmech.scene import load_scene
from tests.conftest import SCENES, assert_refused, run_cli

PLANETARY = SCENES / "ic.friction_planetary.toml"


def planetary(tmp_path, **edits: str) -> str:
    """The reference scene with lines replaced (``old=new`` by the first matching line start)."""
    text = PLANETARY.read_text(encoding="utf-8")
    for old, new in edits.items():
        text = text.replace(old, new, 1)
    p = tmp_path / "fp.toml"
    p.write_text(text, encoding="utf-8")
    return str(p)


def test_the_reference_scene_reads_its_wheels_and_finds_the_contacts():
    d = load_scene(PLANETARY).problem.drive
    assert d.links() == ("1", "2", "3", "4") and d.frame == "4" and d.driver == "1" and d.omega == 10.0
    p12, p24 = (c.at for c in d.contacts)
    u = (math.cos(math.pi / 4), math.sin(math.pi / 4))
    assert p12 == pytest.approx((0.040 * u[0], 0.040 * u[1]), abs=1e-15)  # r1 from O towards C
    assert p24 == pytest.approx((0.070 * u[0], 0.070 * u[1]), abs=1e-15)  # R4 from O through C
    assert d.wheel("4") is not None and d.wheel("4").internal and not d.wheel("1").internal


def test_names_parse_and_the_frame_does_not_turn():
    links = ("1", "2", "3", "4")
    assert parse_name("P24", links) == ("centre", ("", "2", "4"))
    assert parse_name("y_P12", links) == ("centre", ("y_", "1", "2"))
    assert parse_name("ratio_1_2", links) == ("ratio", ("1", "2"))
    assert parse_name("omega_3_ic", links) == ("omega", ("3",))
    assert name_problem("ratio_1_4", links, "4") == "'ratio_1_4': link 4 is the frame: it does not turn"
    assert "no link '9'" in name_problem("P19", links, "4")
    assert "unknown quantity 'v_C'" in name_problem("v_C", links, "4")


@pytest.mark.parametrize("edit, words", [
    ({"points = { O = [0, 0], C = [38.89087296526011, 38.89087296526011] }":
      "points = { O = [0, 0], C = [40, 40] }"},
     ("centres.rolling[0].links", "the wheels do not touch: |OC| = 56.5685 mm, r1 + r2 = 55 mm")),
    ({"radius = 70": "radius = 72"},
     ("centres.rolling[1].links", "the wheels do not touch", "R4 − r2 = 57 mm")),
    ({'links = ["1", "2"]': 'links = ["1", "2"]\nat = [28.2843, 0]'},
     ("centres.rolling[0].at", "is not on wheel 1")),
    ({'links = ["1", "2"]': 'links = ["1", "3"]'},
     ("centres.rolling[0].links", "link '3' has no [[centres.wheel]]")),
    ({'driver = "1"': 'driver = "2"'},
     ("centres.driver", "link '2' must turn about a revolute on the frame '4'")),
    ({"radius = 15": "radius = 15\ninternal = true"},
     ("centres.rolling[0].links", "does not fit inside ring 2")),
    ({'find = ["P12"': 'find = ["P19"'}, ("find[0]", "no link '9'")),
])
def test_bad_input_is_refused_in_one_line(tmp_path, edit, words):
    path = planetary(tmp_path, **edit)
    assert_refused(run_cli("check", path), "fp.toml", *words)


def test_a_contact_given_where_the_wheels_touch_is_taken(tmp_path):
    path = planetary(tmp_path, **{'links = ["1", "2"]':
                                  'links = ["1", "2"]\nat = [28.284271247461902, 28.284271247461902]'})
    assert load_scene(path).problem.drive.contacts[0].at == pytest.approx((0.0282842712, 0.0282842712))


def test_a_linkage_table_in_a_centres_scene_is_refused(tmp_path):
    path = planetary(tmp_path, **{"[units]": '[driver]\ntype = "crank"\n\n[units]'})
    with pytest.raises(SceneError, match="belongs to a linkage scene"):
        load_scene(path)
