"""The closed forms of a driver's limits (graphmech/exact/swing.py): the dyad on its point
toggles there — checked by the toggle itself, not by the construction."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.errors import NotApplicable
from graphmech.exact.linkage import solve
from graphmech.exact.swing import driver_limits
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, SliderInput


def test_a_rocker_goes_to_its_limits_and_no_further():
    lk = Linkage({"A": (0.0, 0.0), "D": (0.05, 0.0)}, Crank("1", "A", "B", 0.08, 5.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.04, 0.06), "left"),))
    lo, hi = driver_limits(lk, 0.3)
    assert hi == pytest.approx(math.acos(-0.1375), abs=1e-15)  # (80² + 50² − 100²)/(2·80·50)
    inside = solve(lk, [lo + 1e-6, hi - 1e-6, 0.3])
    outside = solve(lk, [lo - 1e-6, hi + 1e-6])
    assert inside.valid.all() and not outside.valid.any()


def test_a_slider_goes_to_its_limits_and_no_further():
    lk = Linkage({"O": (0.0, 0.0), "D": (0.1, 0.06)}, SliderInput("1", "B", Guide((0.0, 0.0), 0.0), 0.5),
                 (RRR("B", "C", "D", ("2", "3"), (0.08, 0.05), "right"),))
    lo, hi = driver_limits(lk, 0.06)
    assert solve(lk, [lo + 1e-9, hi - 1e-9]).valid.all() and not solve(lk, [lo - 1e-9, hi + 1e-9]).valid.any()


def test_an_rrp_rocker_stops_where_bc_is_square_to_the_guide():
    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.05, 1.0),
                 (RRP("B", "C", ("2", "3"), 0.03, Guide((0.0, 0.06), 0.0)),))
    lo, hi = driver_limits(lk, -math.pi / 2)
    for q in (lo, hi):  # B is BC = 30 mm below the guide y = 60 mm
        assert 0.05 * math.sin(q) == pytest.approx(0.03, abs=1e-15)


def test_a_crank_that_turns_fully_has_no_limits():
    lk = Linkage({"A": (0.0, 0.0), "D": (0.072, 0.0)}, Crank("1", "A", "B", 0.028, 1.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.052, 0.05), "left"),))
    with pytest.raises(NotApplicable, match="turns fully"):
        driver_limits(lk, 0.0)
    free = Linkage({"O": (0.0, 0.0)}, SliderInput("1", "B", Guide((0.0, 0.0), 0.0), 1.0),
                   (RRP("B", "C", ("2", "3"), 0.03, Guide((0.0, 0.01), 0.0)),))  # the guides are parallel
    with pytest.raises(NotApplicable, match="no limit"):
        driver_limits(free, 0.0)


def test_the_outputs_swing_is_the_spread_of_its_angle_over_the_swing():
    from graphmech.exact.swing import output_swing

    lk = Linkage({"A": (0.0, 0.0), "D": (0.05, 0.0)}, Crank("1", "A", "B", 0.08, 5.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.04, 0.06), "left"),))
    lo, hi = driver_limits(lk, 0.0)
    # sampled (1e-12 inside the limits, where ψ moves as √(φ − φ_limit): to ~1e-6)
    q = np.linspace(lo + 1e-12, hi - 1e-12, 400001)
    C = solve(lk, q).point["C"]
    psi = np.unwrap(np.arctan2(C[:, 1], C[:, 0] - 0.05))
    assert output_swing(lk, lo, hi) == pytest.approx(psi.max() - psi.min(), abs=1e-5)
    # by hand: from B, C, D in one line at the upper limit to A, B, C folded (AC = 40, cos ∠ADC = 0.75)
    B = 0.08 * complex(math.cos(hi), math.sin(hi))
    by_hand = math.atan2(B.imag, B.real - 0.05) - math.atan2(-math.sqrt(1 - 0.75 ** 2), -0.75)
    assert output_swing(lk, lo, hi) == pytest.approx(by_hand, abs=1e-12)
