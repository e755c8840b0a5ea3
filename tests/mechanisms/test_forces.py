"""graphmech.mechanisms.forces: the load and friction records of a kinetostatic model."""
from __future__ import annotations

import dataclasses
import math

import pytest

from graphmech.mechanisms.forces import (ForceModel, LinkCouple, LinkMass, PointForce, RevoluteFriction,
                                         SlidingFriction)


def test_value_objects_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        LinkMass("2", "S2", 1.0).mass = 2.0  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        ForceModel().gravity = 9.81  # type: ignore[misc]


def test_a_point_force_is_resolved_along_its_angle():
    f = PointForce("3", "C", 200.0, math.radians(150.0))
    assert f.vector == pytest.approx((200.0 * math.cos(math.radians(150.0)), 100.0), rel=1e-14)
    assert (f.resistance, f.name) == (False, "F")  # a plain force unless told


def test_friction_circle_and_friction_angle():
    assert RevoluteFriction("B", 0.15, 0.02).rho == pytest.approx(0.003, rel=1e-15)  # ρ = f_v·r
    assert math.degrees(SlidingFriction("3", 0.1).angle) == pytest.approx(5.710593137, rel=1e-9)  # arctan 0.1


def test_a_model_has_friction_only_where_a_coefficient_is_not_zero():
    assert not ForceModel().has_friction
    assert not ForceModel(revolute_friction=(RevoluteFriction("A", 0.0, 0.01),),
                          sliding_friction=(SlidingFriction("3", 0.0),)).has_friction
    assert ForceModel(sliding_friction=(SlidingFriction("3", 0.05),)).has_friction
    assert ForceModel(revolute_friction=(RevoluteFriction("A", 0.1, 0.01),)).has_friction
    m = ForceModel()
    assert (m.gravity, m.tolerance, m.max_iterations, m.couples) == (0.0, 1e-10, 100, ())  # weights off by default


def test_a_link_mass_is_the_flywheels_mass_record():
    from graphmech.mechanisms.machine import Mass

    assert LinkMass is Mass
    assert LinkMass("2", "S2", 1.5).inertia == 0.0  # a point mass unless J_S is given
    assert LinkCouple("3", -4.0).name == "M"
