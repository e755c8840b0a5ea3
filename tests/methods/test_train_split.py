"""The split of a compound train into basic trains and their joint solution
(graphmech/methods/train_split.py) against the exact linear system, on the book's compound trains
and on random ordinary chains."""
from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact import gear_train as ex
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh
from graphmech.methods.train_split import solve, split


def train(members, gears, meshes, fixed=(), inputs=None):
    return GearTrain(tuple(Member(n, c) for n, c in members.items()), tuple(Gear(*g) for g in gears),
                     tuple(m if isinstance(m, Mesh) else Mesh(*m) for m in meshes), tuple(fixed), dict(inputs or {}))


def winch(inputs=None):
    # 杨可桢 10-8: differential 1-2-3-4-7 closed by the ordinary 5-6-7
    return train({"1": None, "2": "7", "4": None, "6": None, "7": None},
                 [("1", 24, "1"), ("2", 52, "2"), ("3", 21, "2"), ("4", 78, "4"), ("5", 18, "4"), ("6", 30, "6"),
                  ("7", 78, "7")],
                 [("1", "2"), ("3", "4", "internal"), ("5", "6"), ("6", "7", "internal")], inputs=inputs or {"1": 1.0})


def test_the_winch_reducer_splits_as_the_book_does():
    sp = split(winch())
    assert [(b.kind, b.carrier, b.label) for b in sp.trains] == [("differential", "7", "1-2-3-4-7"),
                                                                  ("ordinary", None, "5-6-7")]
    assert sp.trains[0].equations() == ["i^7_1,4 = (n1 − n7)/(n4 − n7) = −z2·z4/(z1·z3) = −8.04762"]
    assert sp.trains[1].equations() == ["i5,7 = n5/n7 = −z7/z5 = −4.33333"]
    assert sp.links == ("n4 = n5: member 4 is in 1-2-3-4-7, 5-6-7", "n7: member 7 is in 1-2-3-4-7, 5-6-7")
    assert (sp.mobility, sp.redundant) == (1, 0)
    assert sp.converted_ratio("1", "4", "7") == Fraction(-52 * 78, 24 * 21)
    s = solve(winch())
    e = ex.solve(winch())
    for k, w in e.omega.items():
        assert s.speed(k) == pytest.approx(w, rel=1e-15)
    assert s.speed("1") / s.speed("7") == pytest.approx(43.920634920634896, rel=1e-14)


def test_the_split_refuses_as_the_exact_solution_does():
    with pytest.raises(OutOfDomain, match="mobility 1 but 2 inputs"):
        solve(winch({"1": 1.0, "7": 1.0}))
    lock = train({"1": None, "2": "H", "3": None, "H": None}, [("1", 20, "1"), ("2", 30, "2"), ("2'", 30, "2"),
                                                              ("3", 20, "3")],
                 [("1", "2"), ("2'", "3")], ["3"], {"1": 1.0})
    with pytest.raises(NoSolution, match=r"the train locks.*i\^H_1,3 = 1 with 3 fixed"):
        solve(lock)
    assert solve(lock.with_inputs({"H": 1.0})).speed("1") == 0.0
    orphan = train({"1": None, "2": "H", "3": None, "H": None}, [("1", 20, "1"), ("2", 30, "2"), ("3", 30, "3")],
                   [("2", "3")], inputs={"1": 1.0})
    assert split(orphan).mobility == 3  # 1 and H free, 3 with the planet: three inputs


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(8, 200), st.integers(8, 200), st.sampled_from(["external", "internal"])),
                min_size=1, max_size=6), st.integers(8, 200))
def test_an_ordinary_chain_is_the_tooth_product(stages, z_first):
    members = {"0": None} | {str(k): None for k in range(1, len(stages) + 1)}
    gears, meshes = [("0'", z_first, "0")], []
    driven, driving = [], [z_first]
    for k, (z, zp, kind) in enumerate(stages, 1):
        gears += [(str(k), z, str(k)), (f"{k}'", zp, str(k))]
        meshes.append((f"{k - 1}'", str(k), kind))
        driven.append(z)
        driving.append(zp)
    m = sum(kind == "external" for _, _, kind in stages)
    t = train(members, gears, meshes, inputs={"0": 1.0})
    want = (-1) ** m * math.prod(driven) / math.prod(driving[:-1])
    assert 1.0 / solve(t).speed(str(len(stages))) == pytest.approx(want, rel=1e-14)
    assert split(t).trains[0].ratios[-1].value == Fraction((-1) ** m * math.prod(driven), math.prod(driving[:-1]))
