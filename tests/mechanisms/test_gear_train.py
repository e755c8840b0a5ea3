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


@pytest.mark.parametrize("change, message", [
    (dict(members=(Member("1"), Member("1"))), "member names repeat"),
    (dict(gears=(Gear("1", 18, "1"), Gear("1", 36, "2"))), "gear names repeat"),
    (dict(gears=(Gear("1", 0, "1"),)), "whole number ≥ 1"),
    (dict(gears=(Gear("1", 18.5, "1"),)), "whole number ≥ 1"),
    (dict(gears=(Gear("9", 18, "nine"),)), "no member 'nine'"),
    (dict(members=(Member("1"), Member("2", "X"))), "its carrier 'X' is not another member"),
    (dict(members=(Member("1", "2"), Member("2", "3"), Member("3"))), "is itself a planet"),
    (dict(meshes=(Mesh("2", "2'"),)), "both gears on one member"),
    (dict(meshes=(Mesh("1", "2", "spur"),)), "kind 'spur'"),
    (dict(meshes=(Mesh("1", "2", "worm", 2),)), "sign 2 is not"),
    (dict(fixed=("5",)), "no member '5'"),
    (dict(inputs={"K": 1.0}), "no member 'K'"),
])
def test_what_the_model_refuses(change, message):
    base = dict(members=planetary().members, gears=planetary().gears, meshes=(), fixed=(), inputs={})
    kept = {k: v for k, v in base.items() if k not in change or k in ("members", "gears")}
    if "members" in change and "gears" not in change:
        kept["gears"] = ()
    with pytest.raises(OutOfDomain, match=message):
        GearTrain(**(kept | change))


def test_planets_of_two_carriers_do_not_mesh():
    with pytest.raises(OutOfDomain, match=r"planets of two carriers \(H1, H2\)"):
        GearTrain((Member("2", "H1"), Member("5", "H2"), Member("H1"), Member("H2")),
                  (Gear("2", 16, "2"), Gear("5", 16, "5")), (Mesh("2", "5"),))
