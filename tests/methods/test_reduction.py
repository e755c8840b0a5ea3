"""Reduction to the crank from the velocity polygons (Jп, Mп at the course-project positions)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact.linkage import solve as solve_exact
from graphmech.mechanisms.linkage import RRR, Crank, Guide, Linkage, LinkPoint, RRP
from graphmech.mechanisms.machine import CrankMoment, LinkMoment, Machine, Mass, SliderLoad, Table
from graphmech.methods.reduction import reduce_to_crank, table_at

E_OFF, L_AB, L_BC = 0.010, 0.075, 0.300
W_M = 960 * math.pi / 30
PRESSURE = (0, .014, .032, .055, .087, .132, .201, .317, .5, .5, .5)


def compressor(sense: float = 1.0) -> Machine:
    link = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", L_AB, sense * W_M),
                   (RRP("B", "C", ("2", "3"), L_BC, Guide((0.0, E_OFF), 0.0), "forward"),),
                   (LinkPoint("S2", "2", ("B", "C"), 0.100, 0.0),), frame_link="4")
    area = math.pi * 0.12 ** 2 / 4
    table = Table(tuple(k / 10 for k in range(11)), tuple(p * 1e6 * area for p in PRESSURE))
    return Machine(link, math.asin(E_OFF / (L_AB + L_BC)), 2 * math.pi, W_M, 0.04,
                   masses=(Mass("1", "A", 0.0, 0.05), Mass("2", "S2", 3.0, 0.025), Mass("3", "C", 4.5)),
                   loads=(SliderLoad("C", 0.0, -1, "forward", table),))


def test_compressor_every_10_degrees_matches_the_reference(problems):
    ref = problems["fly.compressor_course_project"]["exact"]
    phi = np.radians(np.arange(0.0, 360.0, 10.0))
    r = reduce_to_crank(compressor(), phi, {"l": 0.002, "v": 0.05})
    assert r.valid.all()
    np.testing.assert_allclose(r.J, ref["Jp_every10deg_kgm2"], rtol=1e-12)
    # Mп is 0 on the suction stroke; elsewhere up to 370 N·m
    np.testing.assert_allclose(r.M, ref["Mp_every10deg_Nm"], rtol=1e-11, atol=1e-10)
    s_min, s_max = r.strokes["C"]
    assert s_max - s_min == pytest.approx(ref["stroke_H_m"], rel=1e-13)


def test_values_do_not_depend_on_the_scales():
    phi = np.radians([30.0, 250.0, 300.0])
    a = reduce_to_crank(compressor(), phi, {"l": 0.002, "v": 0.05})
    b = reduce_to_crank(compressor(), phi, {"l": 0.0037, "v": 0.11})
    np.testing.assert_allclose(a.J, b.J, rtol=1e-13)
    np.testing.assert_allclose(a.M, b.M, rtol=1e-12)


def test_clockwise_crank_gives_the_same_reduced_values_at_the_same_phase():
    """φ runs in the sense of rotation and moments are signed by power: a CW crank from the
    mirror position gives the same Jп and Mп (the mechanism mirrored in the guide's normal)."""
    phi = np.radians([0.0, 200.0, 280.0, 330.0])
    ccw = reduce_to_crank(compressor(), phi, {"l": 0.002, "v": 0.05})
    m = compressor(-1.0)
    # mirror x → −x: guide pointing −x, start angle π − θ_ODC
    mirrored = Linkage({"A": (0.0, 0.0)}, m.linkage.driver,
                       (RRP("B", "C", ("2", "3"), L_BC, Guide((0.0, E_OFF), math.pi), "forward"),),
                       m.linkage.points, frame_link="4")
    load = m.loads[0]
    m2 = Machine(mirrored, math.pi - m.start, m.cycle, m.omega_m, m.delta, m.masses,
                 (SliderLoad("C", math.pi, -1, "forward", load.table),))
    cw = reduce_to_crank(m2, phi, {"l": 0.002, "v": 0.05})
    np.testing.assert_allclose(cw.J, ccw.J, rtol=1e-12)
    np.testing.assert_allclose(cw.M, ccw.M, rtol=1e-11, atol=1e-9)


def test_link_moment_and_crank_moment_reduce_by_power():
    four = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.06, 10.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"),), frame_link="4")
    resist = Table((0.0, math.pi, math.pi, 2 * math.pi), (0.0, 0.0, -40.0, -40.0))
    m = Machine(four, 0.0, 2 * math.pi, 10.0, 0.05,
                loads=(LinkMoment("3", resist), CrankMoment(Table((0.0, 2 * math.pi), (5.0, 5.0)))))
    phi = np.radians([30.0, 190.0, 275.0])
    r = reduce_to_crank(m, phi, {"l": 0.001, "v": 0.01})
    kin = solve_exact(four, phi)
    expected = 5.0 + np.array([0.0, -40.0, -40.0]) * kin.omega["3"] / 10.0
    np.testing.assert_allclose(r.M, expected, rtol=1e-12)
    assert r.J.tolist() == [0.0, 0.0, 0.0]


def test_a_repeated_node_is_a_step_taking_the_mean_of_both_sides_on_it():
    """One rule at a jump: on the step (to rounding) the mean, either side its own value."""
    t = Table((0.0, 1.0, 1.0, 2.0), (0.0, 0.0, 5.0, 5.0))
    assert table_at(t, np.array([0.999, 1.0, 1.0 - 2e-16, 1.0 + 2e-16, 1.5])).tolist() == [0.0, 2.5, 2.5, 2.5, 5.0]


def test_a_moment_over_the_cycle_steps_where_its_end_meets_its_start():
    """Repeated every Φ, a table ending at −300 and starting at 0 jumps at φ = 0: the mean there."""
    t = Table((0.0, 1.0, 1.0, 2.0), (0.0, 0.0, -300.0, -300.0))
    assert table_at(t, np.array([0.0, 0.5, 1.0]), period=2.0).tolist() == [-150.0, 0.0, -150.0]
    assert table_at(t, np.array([0.0]), period=None).tolist() == [0.0]


def test_a_jp_table_is_read_at_the_positions_and_adds_to_the_constant_inertia():
    jt = Table((0.0, math.pi, 2 * math.pi), (0.5, 0.9, 0.5))
    m = Machine(None, 0.0, 4 * math.pi, 10.0, 0.05, inertia=0.1, inertia_table=jt,
                loads=(CrankMoment(Table((0.0, 4 * math.pi), (1.0, 1.0))),))
    r = reduce_to_crank(m, np.array([0.0, math.pi / 2, 3 * math.pi / 2]), {})
    assert r.J.tolist() == pytest.approx([0.6, 0.8, 0.8], rel=1e-15)
