"""The flywheel problem's machine: a table's kinks and steps, the mean taken at a step, and the
crank's angle and positions over the cycle."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.mechanisms.linkage import RRR, Crank, Linkage
from graphmech.mechanisms.machine import ON_STEP, TWO_PI, Machine, Table

STEP = Table((0.0, 1.0, 1.0, 2.0), (0.0, 0.0, 5.0, 5.0))


def test_breaks_are_the_interior_abscissae_once_each() -> None:
    assert STEP.breaks() == (1.0,)
    assert Table((0.0, 2.0, 1.0, 1.0, 3.0), (0, 0, 0, 0, 0)).breaks() == (1.0, 2.0)
    assert Table((0.0, 1.0), (1.0, 2.0)).breaks() == ()


def test_steps_are_repeated_abscissae_with_different_values() -> None:
    assert STEP.steps() == ((1.0, 0.0, 5.0),)
    # three values at one x: the first and the last are the two sides
    assert Table((0.0, 1.0, 1.0, 1.0, 2.0), (0.0, 2.0, 7.0, 5.0, 5.0)).steps() == ((1.0, 2.0, 5.0),)
    assert Table((0.0, 1.0, 1.0, 2.0), (0.0, 3.0, 3.0, 1.0)).steps() == ()  # same value twice: a kink


def test_a_periodic_table_steps_where_the_cycle_closes() -> None:
    t = Table((0.0, math.pi, TWO_PI), (1.0, 1.0, 2.0))
    assert t.steps() == ()
    assert t.steps(TWO_PI) == ((0.0, 2.0, 1.0),)  # 2 at the end of the cycle, 1 at its start
    # a step written at 0 whose value before meets the cycle's end is no step at all
    assert Table((0.0, 0.0, math.pi, TWO_PI), (3.0, 1.0, 1.0, 1.0)).steps(TWO_PI) == ()


def test_mean_at_steps_within_the_tolerance_only() -> None:
    # the table spans 2: "on" the step is within 2·ON_STEP of it
    x = np.array([0.5, 1.0, 1.0 + ON_STEP, 1.0 + 3.0 * ON_STEP])
    values = np.array([0.0, 5.0, 5.0, 5.0])
    out, hit = STEP.mean_at_steps(x, values)
    assert out.tolist() == [0.0, 2.5, 2.5, 5.0]
    assert hit.tolist() == [False, True, True, False]
    assert values.tolist() == [0.0, 5.0, 5.0, 5.0]  # the caller's values are not changed


def test_mean_at_the_step_where_the_cycle_closes_at_both_ends() -> None:
    t = Table((0.0, math.pi, TWO_PI), (1.0, 1.0, 2.0))
    out, hit = t.mean_at_steps(np.array([0.0, TWO_PI, 1.0]), np.array([1.0, 2.0, 1.0]), TWO_PI)
    assert out.tolist() == [1.5, 1.5, 1.0] and hit.tolist() == [True, True, False]


def machine(omega: float | None, start: float = 1.0, cycle: float = TWO_PI) -> Machine:
    lk = None if omega is None else Linkage(
        {"A": (0.0, 0.0), "D": (0.1, 0.0)}, Crank("1", "A", "B", 0.03, omega),
        (RRR("B", "C", "D", ("2", "3"), (0.1, 0.08)),))
    return Machine(lk, start, cycle, 10.0, 0.05)


def test_the_crank_angle_follows_the_crank_sense() -> None:
    ccw, cw, none = machine(10.0), machine(-10.0), machine(None)
    assert (ccw.sense, cw.sense, none.sense) == (1, -1, 1)
    assert ccw.crank_angle(0.5) == 1.5 and cw.crank_angle(0.5) == 0.5
    assert machine(0.0).sense == 1


def test_positions_divide_one_cycle() -> None:
    assert machine(10.0).positions(4) == pytest.approx((0.0, math.pi / 2, math.pi, 1.5 * math.pi))
    assert machine(10.0, cycle=math.pi).positions(3) == pytest.approx((0.0, math.pi / 3, 2 * math.pi / 3))
    assert machine(10.0).positions(1) == (0.0,)


def test_a_machine_hashes_by_identity_and_is_frozen() -> None:
    a, b = machine(None), machine(None)
    assert a == b and hash(a) == id(a)
    with pytest.raises(dataclasses.FrozenInstanceError):
        a.delta = 0.1  # type: ignore[misc]
    assert (a.balance, a.motor, a.masses, a.loads) == ("driving", None, (), ())
