"""The full cycle's read-off: what is measured on the kinematic diagram at N positions is exact."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphmech.exact.linkage import solve
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage
from graphmech.methods.characteristics import grashof_class
from graphmech.methods.full_cycle import cycle_positions, evaluate_cycle


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(st.floats(0.05, 0.9), st.floats(0.03, 0.2), st.floats(0.03, 0.2), st.floats(0.03, 0.2),
       st.sampled_from([1.0, -1.0]), st.integers(4, 400))
def test_a_rockers_angle_read_off_the_drawing_is_exact(share, b, c, d, sense, n):
    a = share * min(b, c, d)
    assume(grashof_class(a, b, c, d) == "crank_rocker_AB")
    assume(a + max(b, c, d) < 0.98 * (a + b + c + d - max(b, c, d)))  # not at a change point
    lk = Linkage({"A": (0.0, 0.0), "D": (d, 0.0)}, Crank("1", "A", "B", a, 10.0 * sense),
                 (RRR("B", "C", "D", ("2", "3"), (b, c), "left"),))
    angles = cycle_positions(0.3, n, sense)
    cyc = evaluate_cycle(lk, {"l": 0.001, "v": 0.01, "a": 0.1}, angles, diagrams=["3", "C"], mu_phi=math.radians(3),
                         mu_s={"3": math.radians(1.0), "C": 0.001}, H_mm=(20.0, 20.0))
    ex = solve(lk, angles)
    psi = cyc.diagrams[0].s_mm * math.radians(1.0)
    np.testing.assert_allclose(psi, np.unwrap(ex.angle["3"] - ex.angle["3"][0]), atol=1e-9)
    # the path's chords end to end: never longer than the arc, and both close to it for many positions
    way = cyc.diagrams[1].s_mm * 0.001
    assert np.all(np.diff(way) >= 0.0)


def test_a_slider_read_off_the_drawing_is_exact():
    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 10.0),
                 (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, 0.03), 0.0), "forward"),))
    angles = cycle_positions(0.0, 36, 1.0)
    cyc = evaluate_cycle(lk, {"l": 0.005, "v": 0.05, "a": 0.5}, angles, diagrams=["C"], mu_phi=math.radians(3),
                         mu_s={"C": 0.005}, H_mm=(20.0, 20.0))
    ex = solve(lk, angles)
    s = cyc.diagrams[0].s_mm * 0.005
    np.testing.assert_allclose(s, ex.point["C"][:, 0] - ex.point["C"][0, 0], atol=1e-12)
    assert cyc.diagrams[0].rise_mm == 0.0
    with pytest.raises(ValueError):
        cyc.diagrams[0].s_mm[0] = 1.0  # read-only arrays: the read-off cannot be changed afterwards


def test_a_swings_return_stroke_reverses_every_velocity_and_keeps_every_acceleration():
    from graphmech.methods.full_cycle import reversed_driver
    from graphmech.methods.swing import driver_limits, swing_positions

    rocker = Linkage({"A": (0.0, 0.0), "D": (0.05, 0.0)}, Crank("1", "A", "B", 0.08, 5.0),
                     (RRR("B", "C", "D", ("2", "3"), (0.04, 0.06), "left"),))
    q, back = swing_positions(*driver_limits(rocker, 0.0), 12)
    cyc = evaluate_cycle(rocker, {"l": 0.001, "v": 0.01, "a": 0.1}, q, polygons=["velocity", "acceleration"],
                         mu_phi=1.0, paths=["C"], backward=back)
    assert sorted(cyc.polygon_failures) == [0, 6]  # the limits: BC and CD in one line, v_C parallel to both
    ok = np.array([i not in (0, 6) for i in range(12)])
    fwd, rev = solve(rocker, q), solve(reversed_driver(rocker), q)
    expected_v = np.where(back[:, None], rev.vel["C"], fwd.vel["C"])
    assert np.allclose(rev.vel["C"], -fwd.vel["C"], rtol=0, atol=1e-12) and np.allclose(rev.acc["C"], fwd.acc["C"])
    v = cyc.vel["C"] * 0.01  # the images at μv
    a = cyc.acc["C"] * 0.1
    assert np.max(np.abs(v - expected_v)[ok]) <= 1e-9 * np.max(np.abs(expected_v[ok]))
    assert np.max(np.abs(a - fwd.acc["C"])[ok]) <= 1e-9 * np.max(np.abs(fwd.acc["C"][ok]))
    assert np.allclose(v[1], -v[11]) and np.allclose(a[1], a[11])  # position 2 and 12: one place, out and back
    path = cyc.paths["C"]  # traced over the first stroke, from position 1 to position 7
    assert np.allclose(path[0], cyc.mech["C"][0]) and np.allclose(path[-1], cyc.mech["C"][6])
