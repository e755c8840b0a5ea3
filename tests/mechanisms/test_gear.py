"""The gear model: frozen SI records, a pair known by its meshing."""
from __future__ import annotations

import dataclasses
import math

import pytest

from graphmech.mechanisms.gear import MESHINGS, GearSet, SpurGear, ToothSystem


def test_a_set_is_a_pair_when_it_meshes():
    s = ToothSystem(0.005, math.radians(20.0))
    assert (s.ha_star, s.c_star) == (1.0, 0.25)
    one = GearSet(s, (SpurGear(20),))
    pair = GearSet(s, (SpurGear(19), SpurGear(42)), "external", 0.1525)
    assert not one.pair and pair.pair and MESHINGS == ("external", "internal", "rack", "helical", "bevel", "worm")
    with pytest.raises(dataclasses.FrozenInstanceError):
        pair.centre_distance = 0.2  # type: ignore[misc]
