"""The exact velocities of wheels in rolling contact, from the pairs' velocity equations."""
from __future__ import annotations

import pytest

from graphmech.errors import OutOfDomain
from graphmech.exact.rolling import twists
from graphmech.mechanisms.rolling import Revolute, Rolling, RollingDrive


def planetary(p24: tuple[float, float] = (0.0, 0.07)) -> RollingDrive:
    """Sun 1 (r1 = 40 mm) about O, planet 2 (r2 = 15 mm) on the carrier 3 at C, fixed ring 4 (R = 70 mm)."""
    return RollingDrive("4", "1", 10.0, {"O": (0.0, 0.0), "C": (0.0, 0.055)}, (),
                        (Revolute(("1", "3", "4"), "O"), Revolute(("2", "3"), "C")),
                        (Rolling(("1", "2"), (0.0, 0.04)), Rolling(("2", "4"), p24)))


def test_the_planetary_against_willis():
    t = twists(planetary())
    w2 = t["2"][0]
    assert 10.0 / w2 == pytest.approx(-2 * 0.015 / 0.04, abs=1e-12)  # ω1/ω2 = −2·r2/r1
    assert t["3"][0] == pytest.approx(-0.015 * w2 / 0.055, abs=1e-12)  # ωH = −r2·ω2/(r1 + r2)
    w, vx, vy = t["2"]
    assert (vx - w * 0.07, vy) == pytest.approx((0.0, 0.0), abs=1e-13)  # the planet's point P24 is at rest
    assert t["4"] == (0.0, 0.0, 0.0)


def test_locked_and_undetermined_drives_are_refused():
    with pytest.raises(OutOfDomain, match="the contacts lock the drive"):
        twists(planetary((0.01, 0.069)))  # the ring's contact off the line OC
    free = RollingDrive("4", "1", 10.0, {"O": (0.0, 0.0)}, (), (Revolute(("1", "4"), "O"),),
                        (Rolling(("1", "2"), (0.0, 0.04)),))
    with pytest.raises(OutOfDomain, match="1 freedom"):
        twists(free)  # the planet may still turn about its contact with the sun
