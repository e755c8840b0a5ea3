"""graphmech.mechanisms.topology called directly: mobility by count and by the Jacobian's rank, local
freedoms of rollers, Assur groups."""
from __future__ import annotations

import pytest



from graphmech.mechanisms.topology import Pair, Topology, grubler, mobility, structure
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES


def test_a_roller_whose_normal_misses_its_pin_has_no_local_freedom():
    scene = load_scene(SCENES / "dof.hfut_cases-3-2.toml")
    topo = scene.problem.topology
    pairs = tuple(Pair(p.kind, p.links, p.name, p.at, 1.2 if p.kind == "higher" else p.angle) for p in topo.pairs)
    m = mobility(Topology(topo.frame, topo.links, pairs, topo.drivers), True)
    assert m.F_local == 1  # the count still says roller …
    # … but a "roller" whose contact normal misses its pin is no round roller: turning it moves the
    # follower, so its turn is a second freedom of the mechanism, not a local one
    assert m.rank == 25 and m.F_actual == 2


def test_a_five_bar_with_two_drivers_is_one_dyad():
    pairs = (Pair("R", ("1", "2"), "A", (0.0, 0.0)), Pair("R", ("2", "3"), "B", (0.02, 0.05)),
             Pair("R", ("3", "4"), "C", (0.08, 0.09)), Pair("R", ("4", "5"), "D", (0.13, 0.04)),
             Pair("R", ("5", "1"), "E", (0.15, 0.0)))
    five = Topology("1", ("2", "3", "4", "5"), pairs, ("2", "5"))
    m = mobility(five, True)
    assert (m.F, m.F_actual, m.rank) == (2, 2, 10)
    s = structure(five)
    assert [(g.links, g.grade) for g in s.groups] == [(("3", "4"), 2)] and not s.messages
    one = structure(Topology("1", ("2", "3", "4", "5"), pairs, ("2",)))
    assert one.leftover == ("3", "4", "5") and "drivers differs from the mobility" in one.messages[0]


def test_an_oscillating_follower_pivoted_on_the_frame_is_not_a_roller():
    """Cam 2 and a follower 3 pinned to the frame and touching the cam: F = 3·2 − (2·2 + 1) = 1.
    The follower (one R, one higher pair) was taken for a roller: F′ = 1, F = 0, "cannot move"."""
    data = {"structure": {"frame": "1", "drivers": ["2"], "pair": [
        {"kind": "R", "links": ["1", "2"]}, {"kind": "higher", "links": ["2", "3"]},
        {"kind": "R", "links": ["3", "1"]}]}}
    topo = parse_scene(data, "cam.toml").problem.topology
    assert topo.rollers() == ()
    m = mobility(topo, False)
    assert (m.F_local, m.F) == (0, 1)
    assert structure(topo).grade == 2  # the contact replaced by a link and two revolutes: one dyad
    # with the roller on a translating follower it is still recognised (HFUT 3-2 has one)
    data["structure"]["pair"] = [
        {"kind": "R", "links": ["1", "2"]}, {"kind": "higher", "links": ["2", "3"]},
        {"kind": "R", "links": ["3", "4"]}, {"kind": "P", "links": ["4", "1"]}]
    m = mobility(parse_scene(data, "roller.toml").problem.topology, False)
    assert (m.F_local, m.F) == (1, 1)


@pytest.mark.parametrize("n, pl, ph, p_redundant, F_local, F", [
    (3, 4, 0, 0, 0, 1),   # four-bar
    (4, 5, 0, 0, 0, 2),   # five-bar
    (2, 2, 1, 0, 0, 1),   # cam and flat-faced follower
    (3, 3, 1, 0, 1, 1),   # cam and roller follower: the roller's spin is local
    (4, 6, 0, 1, 0, 1),   # parallelogram with a redundant parallel link
    (3, 4, 1, 0, 0, 0),   # the punch press's first design: cannot move
])
def test_grubler_kutzbach(n, pl, ph, p_redundant, F_local, F):
    assert grubler(n, pl, ph, p_redundant, F_local) == F


def test_a_four_bar_by_count_and_by_rank():
    pairs = (Pair("R", ("1", "2"), "A", (0.0, 0.0)), Pair("R", ("2", "3"), "B", (0.02, 0.05)),
             Pair("R", ("3", "4"), "C", (0.1, 0.06)), Pair("R", ("4", "1"), "D", (0.12, 0.0)))
    four = Topology("1", ("2", "3", "4"), pairs, ("2",))
    counted = mobility(four, False)
    assert (counted.n, counted.pl, counted.ph, counted.F, counted.rank) == (3, 4, 0, 1, None)
    m = mobility(four, True)
    assert (m.rank, m.F_actual, m.p_redundant_actual) == (8, 1, 0)  # 8 equations, 9 coordinates
    s = structure(four)
    assert s.drivers == ("2",) and [(g.links, g.grade) for g in s.groups] == [(("3", "4"), 2)] and s.grade == 2
