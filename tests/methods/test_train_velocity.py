"""The velocity diagram of a gear train (graphmech/methods/train_velocity.py) against the exact
solution (graphmech/exact/gear_train.py): the bank's trains whose axes are parallel (topologies as
tests/exact/test_gear_train.py infers them; the sides of the meshes as the book's figures stand),
random chains and planetary trains; the spatial trains refused."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NotApplicable
from graphmech.exact.gear_train import coaxial_tooth_number, solve
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh, rpm
from graphmech.methods.train_layout import layout
from graphmech.methods.train_velocity import velocity_diagram
from tests.conftest import reference_problem

REL = 1e-9


def train(members, gears, meshes, fixed=(), inputs=None):
    """members: name → carrier; gears: (name, z, member); meshes: (a, b[, kind]) or Mesh."""
    return GearTrain(tuple(Member(n, c) for n, c in members.items()), tuple(Gear(*g) for g in gears),
                     tuple(m if isinstance(m, Mesh) else Mesh(*m) for m in meshes), tuple(fixed), dict(inputs or {}))


def bank() -> dict[str, tuple[GearTrain, dict[int, int]]]:
    """The bank's parallel-axis trains: (train, sides of the meshes that are not "above")."""
    out: dict[str, tuple[GearTrain, dict[int, int]]] = {}
    i = reference_problem("train.conveyor_planetary_n4")["inputs"]
    out["conveyor_planetary_n4"] = (train(
        {"1": None, "2": "H", "3": None, "4": None, "H": None},
        [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", i["z2p"], "2"), ("3", i["z3"], "3"), ("4", i["z4"], "4")],
        [("1", "2"), ("2", "3", "internal"), ("2'", "4", "internal")], ["3"], {"1": rpm(i["n1_r_min"])}), {})
    i = reference_problem("train.textile_differential_n6")["inputs"]
    for k, n1 in enumerate(i["n1_r_min"]):
        out[f"textile_differential_n6[{k}]"] = (train(
            {"1": None, "2": "H", "4": "H", "6": None, "H": None},
            [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"), ("5", i["z5"], "4"),
             ("6", i["z6"], "6")],
            [("1", "2"), ("3", "4"), ("5", "6", "internal")], inputs={"1": rpm(n1), "H": rpm(i["nH_r_min"])}), {})
    i = reference_problem("train.builders_winch_nH")["inputs"]
    z6 = coaxial_tooth_number((i["z5"], None, "external"), (i["z7"], None, "internal"))
    out["builders_winch_nH"] = (train(
        {"1": None, "2": "H", "4": None, "6": "H", "7": None, "H": None},
        [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"), ("5", i["z5"], "4"),
         ("6", z6, "6"), ("7", i["z7"], "7")],
        [("1", "2"), ("3", "4"), ("5", "6"), ("6", "7", "internal")], ["7"], {"1": rpm(i["n1_r_min"])}), {1: -1})
    out["electric_screwdriver"] = (screwdriver(), {})
    out["closed_differential_n3_n5"] = (closed_differential(), {2: -1, 3: -1, 6: -1, 7: -1})
    i = reference_problem("train.ysj10_6_differential")["inputs"]
    z2p = coaxial_tooth_number((i["z1"], i["z2"], "external"), (i["z3"], None, "internal"))
    for name, n3 in (("same", i["n3_r_min"]), ("opposite", -i["n3_r_min"])):
        out[f"ysj10_6_differential[{name}]"] = (train(
            {"1": None, "2": "4", "3": None, "4": None},
            [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", z2p, "2"), ("3", i["z3"], "3")],
            [("1", "2"), ("2'", "3", "internal")], inputs={"1": rpm(i["n1_r_min"]), "3": rpm(n3)}), {})
    i = reference_problem("train.ysj10_9_planetary_i14")["inputs"]
    out["ysj10_9_planetary_i14"] = (train(
        {"1": None, "2": "H", "3": None, "4": None, "H": None},
        [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", i["z2p"], "2"), ("3", i["z3"], "3"), ("4", i["z4"], "4")],
        [("1", "2"), ("2", "3", "internal"), ("2'", "4", "internal")], ["3"], {"1": 1.0}), {})
    return out


def screwdriver() -> GearTrain:
    i = reference_problem("train.electric_screwdriver")["inputs"]
    z2 = coaxial_tooth_number((i["z1"], None, "external"), (i["z3"], None, "internal"))
    return train({"1": None, "2": "H1", "3": None, "H1": None, "5": "H2", "6": None, "H2": None},
                 [("1", i["z1"], "1"), ("2", z2, "2"), ("3", i["z3"], "3"), ("4", i["z4"], "H1"), ("5", z2, "5"),
                  ("6", i["z6"], "6")],
                 [("1", "2"), ("2", "3", "internal"), ("4", "5"), ("5", "6", "internal")], ["3", "6"],
                 {"1": rpm(i["n1_r_min"])})


def closed_differential() -> GearTrain:
    """The bank's 1-2(2′)-3-5 closed by 3′-4-5, with the copies 6–6′ and 7 drawn below the axis."""
    i = reference_problem("train.closed_differential_n3_n5")["inputs"]
    z3 = coaxial_tooth_number((i["z1"], i["z2"], "external"), (None, i["z2p"], "internal"))
    z5 = coaxial_tooth_number((i["z3p"], i["z4"], "external"), (None, i["z4"], "internal"))
    return train({"1": None, "2": "5", "6": "5", "3": None, "4": None, "7": None, "5": None},
                 [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("2'", i["z2p"], "2"), ("6", i["z2"], "6"),
                  ("6'", i["z2p"], "6"), ("3", z3, "3"), ("3'", i["z3p"], "3"), ("4", i["z4"], "4"),
                  ("7", i["z4"], "7"), ("5", z5, "5")],
                 [("1", "2"), ("2'", "3", "internal"), ("1", "6"), ("6'", "3", "internal"),
                  ("3'", "4"), ("4", "5", "internal"), ("3'", "7"), ("7", "5", "internal")],
                 inputs={"1": rpm(i["n1_r_min"])})


def worst(t: GearTrain, sides: dict[int, int], module: float = 2e-3, mu_v: float = 0.05, H: float = 30.0):
    """The largest error of the diagram's ω against the exact ω, relative to the largest |ω|."""
    d = velocity_diagram(layout(t, module, sides=sides), 0.002, mu_v, H)
    s = solve(t)
    scale = max(abs(w) for w in s.omega.values())
    return max(abs(d.omega(m) - w) for m, w in s.omega.items()) / scale, d


@pytest.mark.parametrize("name", list(bank()))
def test_the_banks_parallel_trains(name):
    t, sides = bank()[name]
    err, d = worst(t, sides)
    assert err <= REL
    # the ω line's lengths give ω = μv·ℓ/(μl·H)
    for m in d.lengths:
        assert d.omega(m) == pytest.approx(d.mu_v * d.lengths[m] / (d.mu_l * d.H), rel=1e-15, abs=0.0)
    for f in t.fixed:
        assert d.lengths[f] == 0.0 and d.lines[f].slope == 0.0


def test_the_closed_differential_is_drawn_by_false_position():
    _, d = worst(closed_differential(), {2: -1, 3: -1, 6: -1, 7: -1})
    assert d.trials == ("2",)  # the planet 2 by trial: every other line follows round the loop
    _, d = worst(screwdriver(), {})
    assert d.trials == ()  # a train with an order of construction needs no trial


def test_a_planets_line_passes_through_its_carriers_velocity_at_its_axis():
    t, _ = bank()["conveyor_planetary_n4"]
    lay = layout(t, 2e-3)
    d = velocity_diagram(lay, 0.002, 0.05, 30.0)
    y = lay.height("2") / 0.002
    assert d.lines["2"].x_at(y) == pytest.approx(d.lines["H"].x_at(y), rel=1e-12)
    # each pitch point is on both members' lines
    for k, m in enumerate(t.meshes):
        y = lay.pitch[k][1] / 0.002
        a, b = t.gear(m.a).member, t.gear(m.b).member
        assert d.lines[a].x_at(y) == pytest.approx(d.lines[b].x_at(y), rel=1e-12, abs=1e-12)
    # a fixed-axis member's line passes through its axis at v = 0
    for m in ("1", "3", "4", "H"):
        assert d.lines[m].x_at(lay.height(m) / 0.002) == pytest.approx(0.0, abs=1e-12)


def test_a_minus_x_axis_reverses_the_sense_read():
    t, _ = bank()["conveyor_planetary_n4"]
    lay = layout(t, 2e-3, axes={"4": "-x"})
    d = velocity_diagram(lay, 0.002, 0.05, 30.0)
    # the drawing is the same; the speed of 4 read along its own axis (−x) changes sign
    assert d.lengths["4"] > 0 and d.omega("4") < 0
    assert abs(d.omega("4") + solve(t).omega["4"]) <= 1e-12 * abs(solve(t).omega["4"])


@pytest.mark.parametrize("pid", ["hand_hoist_i15", "ysj10_4_worm_train", "ysj10_11_worm_differential"])
def test_the_banks_spatial_trains_are_refused(pid):
    # their worms (and ysj10_11's bevel differential) cross the axes: the book solves them by the
    # equations and the arrows, not by the diagram (the topologies of tests/exact/test_gear_train.py)
    worm = Mesh("3'", "4", "worm", +1)
    t = {"hand_hoist_i15": train({"1": None, "3": None, "4": None}, [("1", 20, "1"), ("3'", 1, "3"), ("4", 40, "4")],
                                 [("1", "3'"), worm], inputs={"1": 1.0}),
         "ysj10_4_worm_train": train({"3": None, "4": None}, [("3'", 1, "3"), ("4", 40, "4")], [worm],
                                     inputs={"3": 1.0}),
         "ysj10_11_worm_differential": train({"2": None, "3": "H", "4": None, "H": None},
                                             [("2'", 20, "2"), ("3", 20, "3"), ("4", 20, "4")],
                                             [Mesh("2'", "3", "bevel", -1), Mesh("3", "4", "bevel", +1)],
                                             inputs={"2": 1.0, "4": 1.0})}[pid]
    axes = {"4": "+z"} if pid != "ysj10_11_worm_differential" else {"3": "+y"}
    with pytest.raises(NotApplicable, match="axes are all parallel"):
        velocity_diagram(layout(t, 1e-3, axes=axes), 0.001, 0.01, 20.0)


def test_a_spatial_train_is_refused():
    t = train({"1": None, "2": None}, [("1", 1, "1"), ("2", 40, "2")], [Mesh("1", "2", "worm", +1)],
              inputs={"1": 1.0})
    with pytest.raises(NotApplicable, match="axes are all parallel"):
        velocity_diagram(layout(t, 1e-3, axes={"2": "+z"}), 0.001, 0.01, 20.0)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(8, 150), st.integers(8, 150), st.sampled_from(["external", "internal"]),
                          st.sampled_from([1, -1])), min_size=1, max_size=6),
       st.integers(8, 150), st.floats(-3000.0, 3000.0).filter(lambda w: abs(w) > 1e-3))
def test_a_random_ordinary_chain(stages, z_first, w):
    members = {"0": None} | {str(k): None for k in range(1, len(stages) + 1)}
    gears = [("0'", z_first, "0")]
    meshes = []
    sides = {}
    for k, (z, zp, kind, side) in enumerate(stages, 1):
        if kind == "internal" and z == gears[-1][1]:
            z += 1  # a ring as large as its pinion is no internal mesh
        gears += [(str(k), z, str(k)), (f"{k}'", zp, str(k))]
        meshes.append((f"{k - 1}'", str(k), kind))
        sides[k - 1] = side
    t = train(members, gears, meshes, inputs={"0": w})
    err, _ = worst(t, sides, mu_v=abs(w) * 0.01)
    assert err <= REL


@settings(max_examples=60, deadline=None)
@given(st.integers(8, 60), st.integers(8, 60), st.integers(8, 60),
       st.sampled_from(["fixed ring", "fixed sun", "differential", "carrier input"]),
       st.floats(-3000.0, 3000.0).filter(lambda w: abs(w) > 1e-2), st.floats(-3000.0, 3000.0))
def test_a_random_double_planet_train(z1, z2, z2p, how, w, w2):
    # sun 1 – double planet 2–2′ – ring 3 (coaxial: z3 = z1 + z2 + z2′), driven four ways
    # (i^H_13 = −z2z3/(z1z2′) < 0: never 1, the train never locks)
    z3 = z1 + z2 + z2p
    inputs, fixed = {"1": w}, ["3"]
    if how == "fixed sun":
        inputs, fixed = {"3": w}, ["1"]
    elif how == "differential":
        inputs, fixed = {"1": w, "H": w2}, []
    elif how == "carrier input":
        inputs = {"H": w}
    t = train({"1": None, "2": "H", "3": None, "H": None}, [("1", z1, "1"), ("2", z2, "2"), ("2'", z2p, "2"),
                                                            ("3", z3, "3")],
              [("1", "2"), ("2'", "3", "internal")], fixed, inputs)
    s = solve(t)
    scale = max(abs(v) for v in s.omega.values())
    d = velocity_diagram(layout(t, 1e-3), 0.001, scale * 0.001, 40.0)
    assert max(abs(d.omega(m) - v) for m, v in s.omega.items()) <= REL * scale
