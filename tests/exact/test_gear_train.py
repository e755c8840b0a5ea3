"""A gear train's speeds as one linear system (graphmech/exact/gear_train.py): every gear-train problem
of the bank as a model instance (topology inferred from the statement and the printed formulas, said
in a comment), and the extreme cases: a locked train, a 10⁶ reducer, many starts, a mobility the
inputs contradict, identical planets counted once; a random ordinary chain against (−1)^m ∏z/∏z."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact.gear_train import (coaxial_tooth_number, converted_train_ratio, mobility, redundant,
                                        solve)
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh, rpm
from tests.conftest import reference_problem

REL = 1e-12


def rmin(w):
    return w * 30.0 / math.pi


def train(members, gears, meshes, fixed=(), inputs=None):
    """members: name → carrier (None: axis fixed in the frame); gears: (name, z, member)."""
    return GearTrain(tuple(Member(n, c) for n, c in members.items()), tuple(Gear(*g) for g in gears),
                     tuple(m if isinstance(m, Mesh) else Mesh(*m) for m in meshes), tuple(fixed), dict(inputs or {}))


def close(got, want, rel=REL):
    assert got == pytest.approx(want, rel=rel, abs=0.0)


# ------------------------------------------------------------------------------- the bank's trains


def test_hand_hoist_i15():
    # Inferred (figure missing): the printed i15 = z2z3z4z5/(z1z2'z3'z4') is a chain of four meshes
    # 1–2, 2'–3, 3'–4, 4'–5 on fixed axes; 3' is the worm (z3' = 1 start). Which pairs are bevel is
    # not known and does not change |i15|; the worm's sign is arbitrary (the handle's sense needs the
    # figure), so the magnitude is compared.
    p = reference_problem("train.hand_hoist_i15")
    z2, z3, z4, z5 = p["inputs"]["z2_z3_z4_z5_as_printed"]
    z1, z2p, z3p, z4p = p["inputs"]["z1_z2p_z3p_z4p_as_printed"]
    t = train({"1": None, "2": None, "3": None, "4": None, "5": None},
              [("1", z1, "1"), ("2", z2, "2"), ("2'", z2p, "2"), ("3", z3, "3"), ("3'", z3p, "3"),
               ("4", z4, "4"), ("4'", z4p, "4"), ("5", z5, "5")],
              [("1", "2"), ("2'", "3"), Mesh("3'", "4", "worm", +1), ("4'", "5")], inputs={"1": 1.0})
    s = solve(t)
    assert s.mobility == 1
    close(abs(s.ratio("1", "5")), p["exact"]["i15"])


def conveyor(n1):
    # Sun 1, double planet 2–2' on carrier H, ring 3 (fixed) meshing 2, ring 4 (output) meshing 2'
    # (the note's coaxiality z1 + 2z2 = z3, z1 + z2 + z2' = z4 fixes which planet gear meets which ring).
    p = reference_problem("train.conveyor_planetary_n4")["inputs"]
    return train({"1": None, "2": "H", "3": None, "4": None, "H": None},
                 [("1", p["z1"], "1"), ("2", p["z2"], "2"), ("2'", p["z2p"], "2"), ("3", p["z3"], "3"),
                  ("4", p["z4"], "4")],
                 [("1", "2"), ("2", "3", "internal"), ("2'", "4", "internal")], ["3"], {"1": rpm(n1)})


def test_conveyor_planetary_n4():
    p = reference_problem("train.conveyor_planetary_n4")
    i = p["inputs"]
    assert coaxial_tooth_number((i["z1"], i["z2"], "external"), (None, i["z2"], "internal")) == i["z3"]
    assert coaxial_tooth_number((i["z1"], i["z2"], "external"), (None, i["z2p"], "internal")) == i["z4"]
    s = solve(conveyor(i["n1_r_min"]))
    close(rmin(s.speed("4")), p["exact"]["n4_r_min"])
    close(rmin(s.speed("H")), p["exact"]["nH_r_min"])
    assert s.speed("4") > 0  # same sense as n1 (the book)


def test_textile_differential_n6():
    # Inferred (figure missing): i^H_16 = +z2z4z6/(z1z3z5) is the chain sun 1 – planet 2, 3 on the
    # planet of 2 – planet 4, 5 on the planet of 4 – central 6, all planets on H; the book's sign +
    # (two external meshes) makes 1–2 and 3–4 external and 5–6 internal (6: z = 121, a ring).
    p = reference_problem("train.textile_differential_n6")
    i = p["inputs"]

    def t(n1):
        return train({"1": None, "2": "H", "4": "H", "6": None, "H": None},
                     [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"),
                      ("5", i["z5"], "4"), ("6", i["z6"], "6")],
                     [("1", "2"), ("3", "4"), ("5", "6", "internal")],
                     inputs={"1": rpm(n1), "H": rpm(i["nH_r_min"])})

    assert mobility(t(48.0)) == 2  # a differential: two inputs
    close(converted_train_ratio(t(48.0), "1", "6", "H"), p["exact"]["iH16"])
    for n1, n6 in zip(i["n1_r_min"], p["exact"]["n6_r_min"]):
        s = solve(t(n1))
        close(rmin(s.speed("6")), n6)
        close(s.converted_ratio("1", "6", "H"), p["exact"]["iH16"])


def test_builders_winch_nH():
    # Inferred (figure missing): the whole train is one planetary train with carrier H (the drum), 7
    # the fixed central gear, i^H_17 = (−1)^1 z2z4z7/(z1z3z5). Modelled as sun 1 – double planet 2–3
    # – sun 4 (4 and 5 one central member: z1 + z2 = z3 + z4 = 56, coaxial) – sun 5 – idler planet 6
    # – ring 7; three external meshes and one internal give the sign −. z6 = 67 from the coaxial
    # condition z7 = z5 + 2z6 (it cancels).
    p = reference_problem("train.builders_winch_nH")
    i = p["inputs"]
    z6 = coaxial_tooth_number((i["z5"], None, "external"), (i["z7"], None, "internal"))
    assert z6 == 67
    t = train({"1": None, "2": "H", "4": None, "6": "H", "7": None, "H": None},
              [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"),
               ("5", i["z5"], "4"), ("6", z6, "6"), ("7", i["z7"], "7")],
              [("1", "2"), ("3", "4"), ("5", "6"), ("6", "7", "internal")], ["7"], {"1": rpm(i["n1_r_min"])})
    s = solve(t)
    close(s.ratio("1", "H"), p["exact"]["i1H"])
    close(rmin(s.speed("H")), p["exact"]["nH_r_min"])
    close(converted_train_ratio(t, "1", "7", "H"), -i["z2"] * i["z4"] * i["z7"] / (i["z1"] * i["z3"] * i["z5"]))


def test_electric_screwdriver():
    # Split as the book does: 1-2-3-H1 and 4-5-6-H2, sun 4 cut on the first carrier H1, rings 3 and 6
    # fixed; planets 2 and 5 get 16 teeth (coaxial: (39 − 7)/2), which cancel.
    p = reference_problem("train.electric_screwdriver")
    i = p["inputs"]
    z2 = coaxial_tooth_number((i["z1"], None, "external"), (i["z3"], None, "internal"))
    assert z2 == 16
    t = train({"1": None, "2": "H1", "3": None, "H1": None, "5": "H2", "6": None, "H2": None},
              [("1", i["z1"], "1"), ("2", z2, "2"), ("3", i["z3"], "3"), ("4", i["z4"], "H1"), ("5", z2, "5"),
               ("6", i["z6"], "6")],
              [("1", "2"), ("2", "3", "internal"), ("4", "5"), ("5", "6", "internal")], ["3", "6"],
              {"1": rpm(i["n1_r_min"])})
    s = solve(t)
    close(s.ratio("1", "H2"), p["exact"]["i1H2"])
    close(rmin(s.speed("H2")), p["exact"]["nH2_r_min"])


def test_closed_differential_n3_n5():
    # The book's split: differential 1-2(2')-3-5 (carrier 5, ring 3 meshing 2') closed by the
    # ordinary 3'-4-5 (idler 4 between 3' and the ring 5 cut on the carrier). The copies 6-6' (a
    # second double planet) and 7 (a second idler) are modelled too: redundant, counted once.
    p = reference_problem("train.closed_differential_n3_n5")
    i, ex = p["inputs"], p["exact"]
    z3 = coaxial_tooth_number((i["z1"], i["z2"], "external"), (None, i["z2p"], "internal"))
    z5 = coaxial_tooth_number((i["z3p"], i["z4"], "external"), (None, i["z4"], "internal"))
    assert (z3, z5) == (ex["z3"], ex["z5"])
    t = train({"1": None, "2": "5", "6": "5", "3": None, "4": None, "7": None, "5": None},
              [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", i["z2p"], "2"), ("6", i["z2"], "6"),
               ("6'", i["z2p"], "6"), ("3", z3, "3"), ("3'", i["z3p"], "3"), ("4", i["z4"], "4"),
               ("7", i["z4"], "7"), ("5", z5, "5")],
              [("1", "2"), ("2'", "3", "internal"), ("1", "6"), ("6'", "3", "internal"),
               ("3'", "4"), ("4", "5", "internal"), ("3'", "7"), ("7", "5", "internal")],
              inputs={"1": rpm(i["n1_r_min"])})
    s = solve(t)
    # 6–6' and 7 each bring one speed and two meshes: one redundant constraint each (the book's p′ = 2)
    assert s.mobility == ex["dof"] and s.redundant == i["dof_p_redundant"] == 2
    close(rmin(s.speed("5")), ex["n5_r_min"])
    close(rmin(s.speed("3")), ex["n3_r_min"])
    close(converted_train_ratio(t, "1", "3", "5"), -8.0)  # the book's (a)
    close(s.ratio("3'", "5"), -5.0)  # the book's (b)


def test_ysj10_4_worm_train():
    # Inferred (figure 10-23 missing): i15 = z3z4z5/(z1z3'z4') with z2 cancelling — 1–2–3 with the
    # idler 2 (given 40 teeth here: any), worm 3' (1 start) on the shaft of 3 driving 4, 4'–5; the
    # worm's sign is arbitrary (the figure's arrows), so the magnitude is compared.
    p = reference_problem("train.ysj10_4_worm_train")
    z3, z4, z5 = p["inputs"]["numerator_teeth_as_printed"]
    z1, z3p, z4p = p["inputs"]["denominator_teeth_as_printed"]
    t = train({"1": None, "2": None, "3": None, "4": None, "5": None},
              [("1", z1, "1"), ("2", 40, "2"), ("3", z3, "3"), ("3'", z3p, "3"), ("4", z4, "4"), ("4'", z4p, "4"),
               ("5", z5, "5")],
              [("1", "2"), ("2", "3"), Mesh("3'", "4", "worm", -1), ("4'", "5")], inputs={"1": 1.0})
    close(abs(solve(t).ratio("1", "5")), p["exact"]["i15_magnitude"])


def test_ysj10_6_differential():
    # Sun 1, double planet 2–2' on the carrier 4, ring 3 meshing 2' (the printed z2' = z3 − z1 − z2).
    p = reference_problem("train.ysj10_6_differential")
    i, ex = p["inputs"], p["exact"]
    z2p = coaxial_tooth_number((i["z1"], i["z2"], "external"), (i["z3"], None, "internal"))
    assert z2p == ex["z2p"]

    def t(n3):
        return train({"1": None, "2": "4", "3": None, "4": None},
                     [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", z2p, "2"), ("3", i["z3"], "3")],
                     [("1", "2"), ("2'", "3", "internal")], inputs={"1": rpm(i["n1_r_min"]), "3": rpm(n3)})

    close(converted_train_ratio(t(0.0), "1", "3", "4"), ex["iH13"])
    close(rmin(solve(t(i["n3_r_min"])).speed("4")), ex["n4_same_r_min"])
    close(rmin(solve(t(-i["n3_r_min"])).speed("4")), ex["n4_opposite_r_min"])


def test_ysj10_8_winch_reducer():
    # The book's split: differential 1-2-3-4-7 (carrier 7; double planet 2–3; ring 4 meshing 3: the
    # printed sign −) and the ordinary 5-6-7 (5 on the member of 4: n4 = n5; idler 6 into the ring
    # 7 cut on the carrier: i57 = −z7/z5). z6 = 30 is inferred (coaxial, it cancels).
    p = reference_problem("train.ysj10_8_winch_reducer")
    i, ex = p["inputs"], p["exact"]
    z6 = coaxial_tooth_number((i["z5"], None, "external"), (i["z7"], None, "internal"))
    t = train({"1": None, "2": "7", "4": None, "6": None, "7": None},
              [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"),
               ("5", i["z5"], "4"), ("6", z6, "6"), ("7", i["z7"], "7")],
              [("1", "2"), ("3", "4", "internal"), ("5", "6"), ("6", "7", "internal")], inputs={"1": 1.0})
    s = solve(t)
    assert s.mobility == 1
    close(converted_train_ratio(t, "1", "4", "7"), ex["i7_14"])
    close(s.converted_ratio("1", "4", "7"), ex["i7_14"])
    close(s.ratio("5", "7"), ex["i57"])
    close(s.ratio("1", "7"), ex["i17"])


def test_ysj10_9_planetary_i14():
    # Sun 1, double planet 2 (meshing the fixed ring 3) – 2' (meshing the output ring 4), carrier H.
    p = reference_problem("train.ysj10_9_planetary_i14")
    i, ex = p["inputs"], p["exact"]
    t = train({"1": None, "2": "H", "3": None, "4": None, "H": None},
              [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", i["z2p"], "2"), ("3", i["z3"], "3"),
               ("4", i["z4"], "4")],
              [("1", "2"), ("2", "3", "internal"), ("2'", "4", "internal")], ["3"], {"1": 1.0})
    s = solve(t)
    close(converted_train_ratio(t, "1", "3", "H"), ex["iH13"])
    close(converted_train_ratio(t, "3", "4", "H"), ex["iH34"])
    close(s.ratio("1", "H"), ex["i1H"])
    close(s.ratio("1", "4"), ex["i14"])


def double_worm(z=(1, 99, 101, 100, 1, 100), zb=20, inputs=None):
    # Inferred (figure 10-30 missing), after the printed split: worm 1 (1 start, right-hand) – wheel
    # 2 on fixed axes; 1' (on the worm's shaft) – 5' (on the shaft of worm 5) – worm 5 – wheel 4';
    # the bevel differential 2'–3–4–H (2' on the member of wheel 2, 4 on the member of 4', z2' = z4:
    # 20 here, cancels; i^H_2'4 = −1). The worm signs (+1 both) give n2 and n4' opposite senses, as
    # printed; the bevel signs give the converted ratio −1.
    z1, z2, z1p, z5p, z5, z4p = z
    return train({"1": None, "2": None, "5": None, "4": None, "3": "H", "H": None},
                 [("1", z1, "1"), ("1'", z1p, "1"), ("2", z2, "2"), ("2'", zb, "2"), ("5'", z5p, "5"),
                  ("5", z5, "5"), ("4'", z4p, "4"), ("4", zb, "4"), ("3", zb, "3")],
                 [Mesh("1", "2", "worm", +1), ("1'", "5'"), Mesh("5", "4'", "worm", +1),
                  Mesh("2'", "3", "bevel", -1), Mesh("3", "4", "bevel", +1)], inputs=inputs or {"1": 1.0})


def test_ysj10_11_worm_differential():
    p = reference_problem("train.ysj10_11_worm_differential")
    i = p["inputs"]
    t = double_worm((i["z1"], i["z2"], i["z1p"], i["z5p"], i["z5"], i["z4p"]))
    s = solve(t)
    close(converted_train_ratio(t, "2'", "4", "H"), -1.0)
    assert s.speed("2") * s.speed("4") < 0  # n2 and n4' opposite, as printed
    # Exactly 2·99·10000/(10000 − 99·101) = 1 980 000 (the book's value): the rational elimination
    # gives it to the last bit. The bank's float 1979999.999997539 lost 1.24e-12 to the cancellation
    # ½(1/99 − 101/10000), so it is met to 2e-12.
    assert s.ratio("1", "H") == 1980000.0 == p["book"]["i1H"]
    close(s.ratio("1", "H"), p["exact"]["i1H"], rel=2e-12)


# ------------------------------------------------------------------------------------ extreme cases


def test_a_ratio_of_a_million():
    # two single-start worms into 1000-tooth wheels in series
    t = train({"1": None, "2": None, "3": None},
              [("1", 1, "1"), ("2", 1000, "2"), ("2'", 1, "2"), ("3", 1000, "3")],
              [Mesh("1", "2", "worm", -1), Mesh("2'", "3", "worm", -1)], inputs={"1": 1.0e6})
    s = solve(t)
    assert s.ratio("1", "3") == 1.0e6 and s.speed("3") == 1.0


@pytest.mark.parametrize("starts, wheel", [(1, 40), (4, 60), (10, 30), (45, 50)])
def test_a_worm_with_many_starts(starts, wheel):
    t = train({"1": None, "2": None}, [("1", starts, "1"), ("2", wheel, "2")], [Mesh("1", "2", "worm", +1)],
              inputs={"1": 3.0})
    close(solve(t).ratio("1", "2"), wheel / starts)


def locking(inputs, fixed=("3",)):
    # sun 1 (20) – double planet 2 (30) / 2' (30) – sun 3 (20), two external meshes: i^H_13 = +1
    return train({"1": None, "2": "H", "3": None, "H": None},
                 [("1", 20, "1"), ("2", 30, "2"), ("2'", 30, "2"), ("3", 20, "3")],
                 [("1", "2"), ("2'", "3")], fixed, inputs)


def test_a_converted_ratio_of_one_locks_the_train():
    assert converted_train_ratio(locking({}), "1", "3", "H") == 1.0
    with pytest.raises(NoSolution) as e:
        solve(locking({"1": 1.0}))
    msg = str(e.value)
    assert msg.startswith("the train locks") and "i^H_1,3 = 1" in msg and "\n" not in msg
    # driven by the carrier instead, the sun 1 stays at rest with the fixed 3
    s = solve(locking({"H": 1.0}))
    assert s.speed("1") == 0.0 and s.speed("H") == 1.0


def test_inputs_that_contradict_the_mobility_are_refused():
    dif = locking({"1": 1.0}, fixed=())  # no member fixed: a differential
    assert mobility(dif) == 2
    with pytest.raises(OutOfDomain, match=r"^the train has mobility 2 \(a differential: two inputs drive it\) "
                                          r"but 1 input is given \(1\)$"):
        solve(dif)
    with pytest.raises(OutOfDomain, match=r"mobility 1 .* but 2 inputs are given \(1, H\)$"):
        solve(conveyor(1450.0).with_inputs({"1": 1.0, "H": 2.0}))
    with pytest.raises(OutOfDomain, match=r"mobility 1 .* but 0 inputs are given \(none\)$"):
        solve(conveyor(1450.0).with_inputs({}))
    # two inputs on one rigid pair: the count is right, they are not independent
    pair = train({"1": None, "2": None, "3": "H", "H": None},
                 [("1", 20, "1"), ("2", 40, "2"), ("3", 10, "3")], [("1", "2"), ("2", "3")], [],
                 {"1": 1.0, "2": -0.5})
    assert mobility(pair) == 2
    with pytest.raises(NoSolution, match=r"^the inputs \(1, 2\) do not fix every speed"):
        solve(pair)


def test_identical_planets_are_counted_once():
    def planetary(k):
        members = {"1": None, "3": None, "H": None} | {f"2{'abc'[j]}": "H" for j in range(k)}
        gears = [("1", 20, "1"), ("3", 80, "3")] + [(f"2{'abc'[j]}", 30, f"2{'abc'[j]}") for j in range(k)]
        meshes = [m for j in range(k) for m in [("1", f"2{'abc'[j]}"), (f"2{'abc'[j]}", "3", "internal")]]
        return train(members, gears, meshes, ["3"], {"1": 1.0})

    one, three = solve(planetary(1)), solve(planetary(3))
    assert (one.mobility, one.redundant) == (1, 0)
    assert (three.mobility, three.redundant) == (1, 2)  # the second and third planets repeat the first
    assert three.omega["H"] == one.omega["H"] == 0.2  # i1H = 1 + 80/20
    assert three.omega["2a"] == three.omega["2c"] == one.omega["2a"]
    # a planet's own z cancels (a 31-tooth third planet still fits) ...
    odd = planetary(3)
    odd = GearTrain(odd.members, odd.gears[:-1] + (Gear("2c", 31, "2c"),), odd.meshes, odd.fixed, {})
    assert (mobility(odd), redundant(odd)) == (1, 2)
    # ... but a double planet 30/31 is no copy: another converted ratio, and the set cannot turn
    odd = GearTrain(odd.members, odd.gears[:-1] + (Gear("2c", 30, "2c"), Gear("2c'", 31, "2c")),
                    odd.meshes[:-1] + (Mesh("2c'", "3", "internal"),), odd.fixed, {})
    assert (mobility(odd), redundant(odd)) == (0, 1)


def test_coaxial_condition():
    assert coaxial_tooth_number((20, 30, "external"), (None, 30, "internal")) == 80
    assert coaxial_tooth_number((20, None, "external"), (80, None, "internal")) == 30
    assert coaxial_tooth_number((15, 25, "external"), (60, None, "internal")) == 20
    with pytest.raises(NoSolution, match="z = -5"):
        coaxial_tooth_number((20, 30, "external"), (None, 55, "external"))
    with pytest.raises(NoSolution, match="not a whole number"):
        coaxial_tooth_number((20, None, "external"), (81, None, "internal"))
    with pytest.raises(OutOfDomain, match="cancels"):
        coaxial_tooth_number((20, None, "external"), (50, None, "external"))
    with pytest.raises(NoSolution, match="not coaxial"):
        coaxial_tooth_number((20, 30, "external"), (80, 30, "internal"), (None, 30, "external"), (20, 31, "external"))


# ------------------------------------------------------------------------------------- hypothesis


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(8, 200), st.integers(8, 200), st.sampled_from(["external", "internal"])),
                min_size=1, max_size=7),
       st.integers(8, 200))
def test_an_ordinary_chain_ratio_is_the_tooth_product(stages, z_first):
    # member k carries the driven gear k and the driving gear k'; stage k meshes (k−1)' with k
    members = {"0": None} | {str(k): None for k in range(1, len(stages) + 1)}
    gears = [("0'", z_first, "0")]
    meshes = []
    driving, driven = [z_first], []
    for k, (z, zp, kind) in enumerate(stages, 1):
        gears += [(str(k), z, str(k)), (f"{k}'", zp, str(k))]
        meshes.append((f"{k - 1}'", str(k), kind))
        driven.append(z)
        driving.append(zp)
    m = sum(kind == "external" for _, _, kind in stages)
    s = solve(train(members, gears, meshes, inputs={"0": 1.0}))
    close(s.ratio("0", str(len(stages))), (-1) ** m * math.prod(driven) / math.prod(driving[:-1]), rel=1e-14)


def test_a_spatial_mesh_s_sense_is_found_from_its_geometry_not_from_the_arrows_read():
    """The reference finds a bevel pair's and a worm's sense from the pitch points' velocity vectors
    itself: a wrong sign carried by the mesh (as a slip in the book's arrow rule would carry it)
    does not reach the exact solution, so the check sees the disagreement."""
    # bevel: 1 on +x with its pitch point up (+y), 2 on +y with its pitch point right (+x): 1's
    # pitch point moves along +x × +y = +z, 2's along +y × +x = −z: opposite senses, s = −1
    bevel = GearTrain((Member("1", None, "+x"), Member("2", None, "+y")), (Gear("1", 20, "1"), Gear("2", 40, "2")),
                      (Mesh("1", "2", "bevel", +1, ("+y", "+x")),), (), {"1": 1.0})
    close(solve(bevel).speed("2"), -0.5)
    # a right-hand worm 1 on +x above its wheel 2 on +z: the wheel's pitch point moves against the
    # thumb (−x) for ω1 > 0; +z × (+y) = −x, so ω2 > 0: s = +1 whatever the mesh carries
    for carried in (+1, -1):
        worm = GearTrain((Member("1", None, "+x"), Member("2", None, "+z")), (Gear("1", 2, "1"), Gear("2", 40, "2")),
                         (Mesh("1", "2", "worm", carried, ("-y", "+y"), "right"),), (), {"1": 1.0})
        close(solve(worm).speed("2"), 2 / 40)
        left = GearTrain(worm.members, worm.gears, (Mesh("1", "2", "worm", carried, ("-y", "+y"), "left"),), (),
                         {"1": 1.0})
        close(solve(left).speed("2"), -2 / 40)
    # parallel axes drawn opposite: an external mesh's −1 times û_a·û_b = −1
    reversed_axes = GearTrain((Member("1"), Member("2", None, "-x")), (Gear("1", 20, "1"), Gear("2", 40, "2")),
                              (Mesh("1", "2"),), (), {"1": 1.0})
    close(solve(reversed_axes).speed("2"), 0.5)
