"""The schematic's geometry of a gear train (graphmech/methods/train_layout.py): pitch radii, the
axes walked from the meshes, the coaxial condition as the loop's closure, the axial slots, and the
spatial axes placed from the ``towards`` directions."""
from __future__ import annotations

import pytest

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.mechanisms.gear_train import Gear, GearTrain, Mesh
from graphmech.methods.train_layout import WORM_Q, layout, slots
from tests.conftest import reference_problem
from tests.methods.test_train_velocity import bank, closed_differential, train


def test_the_conveyors_axes_and_slots():
    t, _ = bank()["conveyor_planetary_n4"]
    lay = layout(t, 2e-3)
    assert lay.radius == pytest.approx({"1": 0.010, "2": 0.032, "2'": 0.030, "3": 0.074, "4": 0.072}, rel=1e-15)
    # the sun, the rings and the carrier on one axis; the planet at the arm m(z1 + z2)/2 = 42 mm above
    assert {m: lay.height(m) for m in "134H"} == {m: 0.0 for m in "134H"}
    assert lay.height("2") == pytest.approx(0.042, abs=1e-15) and lay.arm("2") == pytest.approx(0.042, abs=1e-15)
    # two stages: 1–2–3 in slot 0, 2′–4 in slot 1; the planet's two gears one gap apart along x
    assert lay.slot == {"1": 0, "2": 0, "3": 0, "2'": 1, "4": 1}
    assert lay.centre("2'")[0] - lay.centre("2")[0] == lay.gap > 0
    # the pitch points: 1–2 at r1 above the sun, the rings' meshes at the top of the planet
    assert [round(lay.pitch[k][1], 12) for k in range(3)] == [0.010, 0.074, 0.072]
    assert lay.parallel


def test_a_planet_set_that_is_not_coaxial_is_refused_with_its_arms():
    t, _ = bank()["conveyor_planetary_n4"]
    bad = GearTrain(t.members, t.gears[:4] + (Gear("4", 70, "4"),), t.meshes, t.fixed, t.inputs)
    with pytest.raises(NoSolution, match=r"^the planet 2–2′ is not coaxial: arms 42 mm and 40 mm "
                                         r"\(the mesh 2′–4 does not close the planet set of H\)$"):
        layout(bad, 2e-3)


def test_the_winch_reducer_is_not_coaxial_at_one_module():
    # ysj10_8: sun 1 (24) – planet 2 (52), its 3 (21) in the ring 4 (78): arms m(24 + 52)/2 and
    # m(78 − 21)/2 differ, so the book's figure has two modules; one module cannot draw it
    i = reference_problem("train.ysj10_8_winch_reducer")["inputs"]
    t = train({"1": None, "2": "7", "4": None, "7": None},
              [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"),
               ("7", i["z7"], "7")], [("1", "2"), ("3", "4", "internal")], inputs={"1": 1.0})
    with pytest.raises(NoSolution, match=r"the planet 2–3 is not coaxial: arms 76 mm and 57 mm"):
        layout(t, 2e-3)


def test_a_reverted_train_is_closed_by_its_coaxial_pair():
    # 1 (20) – 2 (40) on the countershaft with 2′ (25) – 3 (35): 30 + 30 module units, coaxial
    t = train({"1": None, "2": None, "3": None}, [("1", 20, "1"), ("2", 40, "2"), ("2'", 25, "2"), ("3", 35, "3")],
              [("1", "2"), ("2'", "3")], inputs={"1": 1.0})
    lay = layout(t, 1e-3, sides={1: -1}, coaxial=(("1", "3"),))
    assert lay.height("3") == lay.height("1") == 0.0 and lay.height("2") == pytest.approx(0.030)
    bad = GearTrain(t.members, t.gears[:3] + (Gear("3", 36, "3"),), t.meshes, (), t.inputs)
    with pytest.raises(NoSolution, match=r"^the mesh 2′–3 does not close \(the coaxial condition\): its centre "
                                         r"distance is 30.5 mm, the other meshes put the axes of 2 and 3 30 mm apart$"):
        layout(bad, 1e-3, sides={1: -1}, coaxial=(("1", "3"),))
    # without the pair the layout draws 3 where the meshes put it
    assert layout(bad, 1e-3, sides={1: -1}).height("3") == pytest.approx(-0.0005)


def test_sides_and_internal_meshes():
    t = train({"1": None, "2": None, "3": None}, [("1", 20, "1"), ("2", 30, "2"), ("3", 80, "3")],
              [("1", "2"), ("2", "3", "internal")], inputs={"1": 1.0})
    up = layout(t, 1e-3)
    # 2 above 1; the ring 3 meshes at the top of 2, so its axis lies below 2's: r3 − r2 = 25 mm
    assert (up.height("2"), up.height("3")) == pytest.approx((0.025, 0.0))
    down = layout(t, 1e-3, sides={0: -1, 1: -1})
    assert (down.height("2"), down.height("3")) == pytest.approx((-0.025, 0.0))


def test_slots_share_a_stage_and_the_closed_differential_closes():
    t = closed_differential()
    s = slots(t)
    assert s["1"] == s["2"] == s["6"] and s["2'"] == s["3"] == s["6'"] and s["3'"] == s["4"] == s["5"] == s["7"]
    assert len(set(s.values())) == 3
    lay = layout(t, 1e-3, sides={2: -1, 3: -1, 6: -1, 7: -1})
    assert lay.arm("2") == -lay.arm("6") == pytest.approx(0.030)  # m(z1 + z2)/2 above, its copy below
    assert lay.height("4") == -lay.height("7") == pytest.approx(0.030)


def test_a_spatial_train_is_placed_from_its_towards():
    # worm 1 (axis +x, 2 starts) drives the wheel 2 (axis +z, 40 teeth) below it; 2′ a bevel pinion
    # (20) on the wheel's shaft drives the bevel 3 (axis +y, 30) standing on top of it
    t = train({"1": None, "2": None, "3": None}, [("1", 2, "1"), ("2", 40, "2"), ("2'", 20, "2"), ("3", 30, "3")],
              [Mesh("1", "2", "worm", +1), Mesh("2'", "3", "bevel", -1)], inputs={"1": 1.0})
    lay = layout(t, 1e-3, axes={"2": "+z", "3": "+y"}, towards={0: ("-y", "+y"), 1: ("+y", "+z")})
    assert lay.radius["1"] == pytest.approx(1e-3 * WORM_Q / 2) and not lay.parallel
    c2 = lay.centre("2")
    assert c2[:2] == pytest.approx((0.0, -(0.005 + 0.020)))  # the wheel's centre r1 + r2 below the worm
    # the bevels touch at P = centre(2′) + r2′·ŷ; 3's centre is P − r3·ẑ, its axis vertical through it
    c2p, p, c3 = lay.centre("2'"), lay.pitch[1], lay.centre("3")
    assert p == pytest.approx((c2p[0], c2p[1] + 0.010, c2p[2]))
    assert c3 == pytest.approx((p[0], p[1], p[2] - 0.015))
    # the same without towards: a bevel pair's defaults (t_a along b's axis, t_b along a's) agree
    assert layout(t, 1e-3, axes={"2": "+z", "3": "+y"}, towards={0: ("-y", "+y")}).centre("3") == pytest.approx(c3)
    with pytest.raises(OutOfDomain, match="from 3's axis lies along that axis"):
        layout(t, 1e-3, axes={"2": "+z", "3": "+y"}, towards={1: ("+x", "-y")})


def test_refusals():
    t, _ = bank()["conveyor_planetary_n4"]
    with pytest.raises(OutOfDomain, match="module"):
        layout(t, 0.0)
    with pytest.raises(OutOfDomain, match="not an axis direction"):
        layout(t, 1e-3, axes={"1": "x"})
    with pytest.raises(OutOfDomain, match="not parallel"):
        layout(t, 1e-3, axes={"2": "+y"})


def test_an_identical_planet_listed_again_goes_across_the_carrier_s_axis():
    # 2K-H: the sun 1 (20), two planets 2 and 2a (30) both meshing the ring 3 (80), every side "above":
    # 2a would stand on 2's pin; it is put below the carrier's axis, its meshes closed from there
    t = train({"1": None, "2": "H", "2a": "H", "3": None, "H": None},
              [("1", 20, "1"), ("2", 30, "2"), ("2a", 30, "2a"), ("3", 80, "3")],
              [("1", "2"), ("2", "3", "internal"), ("1", "2a"), ("2a", "3", "internal")], inputs={"3": 1.0})
    lay = layout(t, 2e-3, sides={0: 1, 1: 1, 2: 1, 3: 1})
    assert lay.arm("2") == pytest.approx(0.050) and lay.arm("2a") == pytest.approx(-0.050)
    assert [round(lay.pitch[k][1], 12) for k in range(4)] == [0.020, 0.080, -0.020, -0.080]


def test_a_bevel_differential_s_side_gears_face_each_other_across_the_planet():
    # the side gears 1 and 3 (20) on the case H's axis, the planet 2 (12, axis +y) on H's cross pin
    t = train({"1": None, "2": "H", "3": None, "H": None}, [("1", 20, "1"), ("2", 12, "2"), ("3", 20, "3")],
              [Mesh("1", "2", "bevel", -1), Mesh("2", "3", "bevel", -1)], inputs={"H": 1.0}, fixed=("3",))
    lay = layout(t, 1e-3, axes={"2": "+y"}, towards={0: ("+y", "-x"), 1: ("+x", "+y")})
    c1, c2, c3 = lay.centre("1"), lay.centre("2"), lay.centre("3")
    # one axis; the side gears 2·r2 = 12 mm apart, the planet's centre between them at r1 = 10 mm above it
    assert c1[1:] == c3[1:] == pytest.approx((0.0, 0.0)) and c3[0] - c1[0] == pytest.approx(0.012, abs=1e-15)
    assert c2 == pytest.approx(((c1[0] + c3[0]) / 2, 0.010, 0.0), abs=1e-15)


def test_a_double_worm_reducer_s_gears_stand_where_their_spatial_meshes_put_them():
    # 杨可桢 10-11 as its scene lays it out: worms 1 and 5 seen end-on (axis −z) over the wheels 2 and
    # 4′ (axis x, coaxial with the case H); 1′–5′ beside each other; the bevels 2′ and 4 either side of
    # the planet 3 (axis −y) on H's cross pin
    t = train({"1": None, "2": None, "5": None, "4": None, "3": "H", "H": None},
              [("1", 1, "1"), ("1'", 101, "1"), ("2", 99, "2"), ("2'", 20, "2"), ("3", 20, "3"), ("4", 20, "4"),
               ("4'", 100, "4"), ("5", 1, "5"), ("5'", 100, "5")],
              [Mesh("1", "2", "worm", 1), Mesh("1'", "5'", "external"), Mesh("5", "4'", "worm", 1),
               Mesh("2'", "3", "bevel", -1), Mesh("3", "4", "bevel", 1)], inputs={"1": 1.0})
    lay = layout(t, 1e-3, axes={"1": "-z", "5": "-z", "3": "-y"}, gap=0.016,
                 towards={0: ("-y", "+y"), 2: ("-y", "+y"), 3: ("+y", "-x"), 4: ("+x", "+y")})
    r = lay.radius
    c = {g: lay.centre(g) for g in r}
    # the end-on spur pair beside each other: one height, r1′ + r5′ apart along x
    assert c["5'"][1] == c["1'"][1] and c["5'"][0] - c["1'"][0] == pytest.approx(0.1005, abs=1e-15)
    # the bevels meet at the apex on the planet's axis: 2′ and 4 r3 either side of it, not in one plane
    assert c["2'"][0] == pytest.approx(c["3"][0] - r["3"], abs=1e-15)
    assert c["4"][0] == pytest.approx(c["3"][0] + r["3"], abs=1e-15)
    # each wheel centred under its worm, at r_worm + r_wheel: the second worm takes the diameter that
    # reaches 4′ (the wheels' radii differ by half a module; q is the drawing's choice)
    for w, g in (("1", "2"), ("5", "4'")):
        assert c[g][0] == pytest.approx(c[w][0], abs=1e-15) and c[w][2] == pytest.approx(c[g][2], abs=1e-15)
        assert c[w][1] - c[g][1] == pytest.approx(r[w] + r[g], abs=1e-15)
    assert r["1"] == pytest.approx(1e-3 * WORM_Q / 2) and r["5"] == pytest.approx(0.0045, abs=1e-15)
    # the differential between the wheels, the wheel 4′ past the bevel 4 on its own shaft
    assert c["2"][0] < c["2'"][0] < c["4"][0] < c["4'"][0]
