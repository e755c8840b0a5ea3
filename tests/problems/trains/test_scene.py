"""Reading a gear-train scene (graphmech/problems/trains/scene.py): the model, the senses from the
arrows, the coaxial condition, list inputs, the stated mobility; refusals by key path."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.errors import SceneError
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES


def base(**train):
    t = {"z": {"1": 20, "2": 40}, "mesh": [{"gears": ["1", "2"]}], "input": [{"member": "1", "speed_rpm": 100}]}
    t.update(train)
    return {"train": t}


def refused(data, *words):
    with pytest.raises(SceneError) as e:
        parse_scene(data, "t.toml")
    msg = str(e.value)
    for w in words:
        assert w in msg, (w, msg)
    return msg


def test_the_conveyor_reads_as_the_docs_say():
    s = load_scene(SCENES / "train.conveyor_planetary_n4.toml")
    p = s.problem
    assert s.kind == "trains" and s.show == ("schematic", "velocity") and p.parallel
    assert p.module == 0.002 and p.module_stated
    assert p.solved_z == {"3": 74} and p.coaxial_equations == {"3": "z3 = z1 + 2·z2 = 74"}
    assert [m.name for m in p.train.members] == ["1", "2", "3", "4", "H"]
    assert p.train.member("2").carrier == "H" and p.train.fixed == ("3",)
    assert p.train.inputs == {"1": 1450 * math.pi / 30}
    assert p.axes == {"1": "+x", "2": "+x", "3": "+x", "4": "+x", "H": "+x"}
    assert p.sides == {0: 1, 1: 1, 2: 1}


def test_a_list_input_and_the_stated_mobility():
    p = load_scene(SCENES / "train.textile_differential_n6.toml").problem
    assert p.input_values["1"] == (48 * math.pi / 30, 200 * math.pi / 30)
    assert p.train.inputs["1"] == 48 * math.pi / 30 and p.stated_mobility == 2
    refused(base(input=[{"member": "1", "speed_rpm": [1, 2]}, {"member": "2", "speed_rpm": [1, 2]}]),
            "train.input[1].speed_rpm: at most one input has a list")


def test_spatial_senses_from_the_arrows():
    s = parse_scene(base(member=[{"name": "2", "axis": "+y"}],
                         mesh=[{"gears": ["1", "2"], "kind": "bevel", "towards": ["+y", "+x"]}]), "t.toml")
    p = s.problem
    assert p.train.meshes[0].sign == -1 and p.towards == {0: ("+y", "+x")} and not p.parallel
    assert s.show == ("schematic",)
    s = parse_scene(base(member=[{"name": "2", "axis": "+z"}],
                         mesh=[{"gears": ["1", "2"], "kind": "worm", "hand": "left", "towards": ["+y", "-y"]}]),
                    "t.toml")
    assert s.problem.train.meshes[0].sign == 1 and s.problem.hands == {0: "left"}
    # a parallel pair drawn with one axis reversed: the kind's sign, times û_a·û_b
    s = parse_scene(base(member=[{"name": "2", "axis": "-x"}]), "t.toml")
    assert s.problem.train.meshes[0].relative_sign == 1


@pytest.mark.parametrize("train, words", [
    ({"z": {"1": 0, "2": 40}}, ["train.z.1: must be a whole number of teeth"]),
    ({"z": {"1": "x", "2": 40}}, ["train.z.1"]),
    ({"mesh": [{"gears": ["1", "3"]}]}, ["train.mesh[0].gears: no gear 3 in train.z"]),
    ({"member": [{"name": "H"}]}, ["train.member[0].name: no gear H in train.z", "gears = []"]),
    ({"member": [{"name": "2", "carrier": "K"}]}, ["train.member[0].carrier: 'K' is not another member"]),
    ({"fixed": ["1"]}, ["train.input[0].member: member 1 is fixed"]),
    ({"mobility": 2}, ["train.mobility: the meshes give mobility 1 (planetary or ordinary: one input), not 2"]),
    ({"input": []}, ["train.input: the train has mobility 1 (planetary or ordinary: one input) but 0 inputs are given"]),
    ({"m_mm": 1e6}, ["train.m_mm: 1000000 mm is no module"]),
    ({"gear": 1}, ["train.gear: unknown key"]),
])
def test_refusals(train, words):
    refused(base(**train), *words)


def test_another_kind_s_table_is_refused():
    data = base()
    data["driver"] = {}
    refused(data, "driver: unknown key")  # a linkage's table: the scene reads as a gear train


def test_coaxial_pairs_solve_and_check():
    s = load_scene(SCENES / "train.closed_differential_n3_n5.toml")
    assert s.problem.solved_z == {"3": 80, "5": 100}
    assert s.problem.coaxial == (("3", "5"),)
    text = (SCENES / "train.ysj10_8_winch_reducer.toml").read_text(encoding="utf-8")
    assert load_scene(SCENES / "train.ysj10_8_winch_reducer.toml").problem.coaxial_notes == ()  # stage modules
    one = tomllib.loads(text.replace("m_mm = 3\n", "").replace("m_mm = 4\n", ""))
    note = ("not coaxial with one module: (z1 + z2)/2 = 38, (z4 − z3)/2 = 28.5 module units "
            "(the gears' modules must differ)")
    assert parse_scene(one, "w.toml").problem.coaxial_notes == (note,)
    wrong = tomllib.loads(text.replace("m_mm = 4\n", "m_mm = 5\n"))
    assert parse_scene(wrong, "w.toml").problem.coaxial_notes == (
        "not coaxial with the meshes' modules: (z1 + z2)/2·m = 114 mm, (z4 − z3)/2·m = 142.5 mm",)
