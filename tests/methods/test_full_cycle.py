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
