"""graphmech.mechanisms.forces: the load and friction records of a kinetostatic model."""
from __future__ import annotations

import dataclasses

import pytest

from graphmech.mechanisms.forces import ForceModel, LinkMass


def test_value_objects_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        LinkMass("2", "S2", 1.0).mass = 2.0  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        ForceModel().gravity = 9.81  # type: ignore[misc]
