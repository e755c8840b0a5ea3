"""The find names of a gear-train scene (graphmech/problems/trains/names.py)."""
from __future__ import annotations

import pytest

from graphmech.errors import UnknownName
from graphmech.problems.trains.names import known_names, parse_name
from graphmech.scene import load_scene
from tests.conftest import SCENES


@pytest.fixture(scope="module")
def winch():
    return load_scene(SCENES / "train.ysj10_8_winch_reducer.toml").problem


def test_speeds_ratios_and_converted_ratios(winch):
    t, z = winch.train, winch.solved_z
    assert (parse_name("n4", t, z).what, parse_name("n4", t, z).a) == ("n", "4")
    assert parse_name("omega_5", t, z).a == "5" and parse_name("omega_5", t, z).unit == "rad/s"
    n = parse_name("i7_14", t, z)
    assert (n.what, n.carrier, n.a, n.b) == ("iH", "7", "1", "4")
    n = parse_name("i17", t, z)
    assert (n.what, n.a, n.b) == ("i", "1", "7")
    assert parse_name("dof", t, z).what == "dof"


def test_list_indices():
    p = load_scene(SCENES / "train.textile_differential_n6.toml").problem
    assert parse_name("n6[1]", p.train, p.solved_z, 2).index == 1
    with pytest.raises(UnknownName, match=r"has 2 values, \[0\] … \[1\]"):
        parse_name("n6[2]", p.train, p.solved_z, 2)
    with pytest.raises(UnknownName, match="takes no"):
        parse_name("n6[0]", p.train, p.solved_z, 1)


def test_refusals(winch):
    t, z = winch.train, winch.solved_z
    with pytest.raises(UnknownName, match="unknown gear-train quantity 'N4'; did you mean n4?"):
        parse_name("N4", t, z)
    with pytest.raises(UnknownName, match="unknown gear-train quantity 'z6'"):
        parse_name("z6", t, z)  # stated, not solved from the coaxial condition
    assert "i7_14" not in known_names(t, z) and "i714" in known_names(t, z)
