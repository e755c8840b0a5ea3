"""The gear-train model (graphmech/mechanisms/gear_train.py): members carrying several gears, planets
on a carrier, each mesh's frame and sign, and what the model refuses."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh, rpm


def planetary(**kw):
    """ysj 10-9: sun 1, double planet 2–2' on H, fixed ring 3, output ring 4."""
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("4"), Member("H")),
                     (Gear("1", 18, "1"), Gear("2", 36, "2"), Gear("2'", 33, "2"), Gear("3", 90, "3"),
                      Gear("4", 87, "4")),
                     (Mesh("1", "2"), Mesh("2", "3", "internal"), Mesh("2'", "4", "internal")), ("3",),
                     **kw)


def test_a_double_planet_is_one_member_with_two_gears():
    t = planetary(inputs={"1": 1.0})
    assert t.carriers == ("H",) and t.planets("H") == ("2",)
    assert [g.name for g in t.gears if g.member == "2"] == ["2", "2'"]
    assert t.gear("2'").z == 33 and t.member("2").carrier == "H"


def test_each_mesh_is_written_in_the_frame_of_the_member_carrying_both_axes():
    t = planetary()
    assert [t.mesh_frame(m) for m in t.meshes] == ["H", "H", "H"]
    ordinary = GearTrain((Member("1"), Member("2")), (Gear("1", 20, "1"), Gear("2", 40, "2")), (Mesh("1", "2"),))
    assert ordinary.mesh_frame(ordinary.meshes[0]) is None and ordinary.carriers == ()


def test_signs_follow_the_kind_for_parallel_axes_and_are_stated_for_spatial_meshes():
    assert Mesh("1", "2").relative_sign == -1 and Mesh("2", "3", "internal").relative_sign == +1
    assert Mesh("1", "2", "worm", +1).relative_sign == +1 and Mesh("1", "2", "bevel", -1).relative_sign == -1
    # a figure's arrows may also override a parallel pair's sign (the book's stated sense)
    assert Mesh("1", "2", "external", +1).relative_sign == +1
    with pytest.raises(OutOfDomain, match="the bevel mesh 1–2 needs its sign"):
        GearTrain((Member("1"), Member("2")), (Gear("1", 20, "1"), Gear("2", 20, "2")), (Mesh("1", "2", "bevel"),))


def test_with_inputs_drives_the_same_train_otherwise():
    t = planetary(inputs={"1": 1.0})
    u = t.with_inputs({"H": 2.0}, fixed=())
    assert u.meshes == t.meshes and u.fixed == () and dict(u.inputs) == {"H": 2.0}
    assert rpm(30.0) == pytest.approx(math.pi, rel=1e-15)


M = (Member("1"), Member("2"))
G = (Gear("1", 18, "1"), Gear("2", 36, "2"))


@pytest.mark.parametrize("args, message", [
    ((M + (Member("1"),), ()), "member names repeat"),
    ((M, G + (Gear("1", 20, "2"),)), "gear names repeat"),
    ((M, (Gear("1", 0, "1"),)), "whole number ≥ 1, not 0"),
    ((M, (Gear("1", 18.5, "1"),)), "whole number ≥ 1, not 18.5"),
    ((M, (Gear("9", 18, "nine"),)), "gear 9: no member 'nine'"),
    ((M + (Member("3", "X"),), ()), "member 3: its carrier 'X' is not another member"),
    ((M + (Member("3", "2"), Member("4", "3")), ()), "member 4: its carrier 3 is itself a planet"),
    ((M, G + (Gear("2'", 20, "2"),), (Mesh("2", "2'"),)), "mesh 2–2': both gears on one member"),
    ((M, G, (Mesh("1", "2", "spur"),)), "kind 'spur' is not one of"),
    ((M, G, (Mesh("1", "2", "worm", 2),)), "sign 2 is not"),
    ((M, G, (), ("5",)), "no member '5'"),
    ((M, G, (), (), {"K": 1.0}), "no member 'K'"),
    ((M, G, (), ("1",), {"1": 1.0}), "member 1 is both fixed and an input"),
    ((M, G, (), (), {"1": math.inf}), "finite number, not inf"),
])
def test_what_the_model_refuses(args, message):
    members, gears, *rest = args
    meshes = rest[0] if rest else ()
    with pytest.raises(OutOfDomain, match=message):
        GearTrain(members, gears, meshes, *rest[1:])


def test_planets_of_two_carriers_do_not_mesh():
    with pytest.raises(OutOfDomain, match=r"planets of two carriers \(H1, H2\)"):
        GearTrain((Member("2", "H1"), Member("5", "H2"), Member("H1"), Member("H2")),
                  (Gear("2", 16, "2"), Gear("5", 16, "5")), (Mesh("2", "5"),))


def test_a_name_is_a_member_first_then_the_member_of_a_gear():
    t = planetary()
    assert [t.member_of(n) for n in ("2", "2'", "H", "4")] == ["2", "2", "H", "4"]
    with pytest.raises(OutOfDomain, match="no gear '9'"):
        t.member_of("9")
