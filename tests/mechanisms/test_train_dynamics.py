"""A train's bodies and losses: the planet's arm, the axes' angle, what a body may carry."""
from __future__ import annotations

import pytest

from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh
from graphmech.mechanisms.train_dynamics import (
    Body,
    MeshLosses,
    Worm,
    axis_cos,
    check_body,
    planet_arm,
)


def train() -> GearTrain:
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                     (Gear("1", 20, "1"), Gear("2", 30, "2"), Gear("3", 80, "3")),
                     (Mesh("2", "3", "internal"), Mesh("1", "2")), fixed=("3",))


def test_planet_arm_from_either_mesh() -> None:
    assert planet_arm(train(), 2e-3, "2") == pytest.approx(2e-3 * 50 / 2)  # m(z3 − z2)/2 = m(z1 + z2)/2
    with pytest.raises(OutOfDomain, match="not a planet"):
        planet_arm(train(), 2e-3, "1")


def test_axis_cos_and_bodies() -> None:
    assert axis_cos({"2": "+y"}, "H", "2") == 0.0
    assert axis_cos({"2": "-x"}, "H", "2") == -1.0
    check_body(train(), Body("2", 0.1, mass=2.0, count=3))
    with pytest.raises(OutOfDomain, match="fixed axis"):
        check_body(train(), Body("1", mass=1.0))
    with pytest.raises(OutOfDomain, match="≥ 0"):
        check_body(train(), Body("2", -0.1))
    losses = MeshLosses((0.9, 0.8), (Worm(1, 0.1, 0.05),))
    assert losses.worm(1) == Worm(1, 0.1, 0.05) and losses.worm(0) is None
