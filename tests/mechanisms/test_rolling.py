"""Where two wheels touch, and when they do not."""
from __future__ import annotations

import pytest

from graphmech.mechanisms.rolling import (
    Revolute,
    Rolling,
    RollingDrive,
    Wheel,
    contact,
    on_wheel,
)


def test_external_and_internal_contacts():
    sun, planet = Wheel("1", "O", 0.04), Wheel("2", "C", 0.015)
    assert contact(sun, (0.0, 0.0), planet, (0.0, 0.055)) == pytest.approx((0.0, 0.04), abs=1e-15)
    ring = Wheel("4", "O", 0.07, internal=True)
    assert contact(planet, (0.033, 0.044), ring, (0.0, 0.0)) == pytest.approx((0.042, 0.056), abs=1e-15)


def test_wheels_that_do_not_touch_or_cannot_roll_are_said():
    sun, planet = Wheel("1", "O", 0.04), Wheel("2", "C", 0.015)
    assert contact(sun, (0.0, 0.0), planet, (0.0, 0.05)) == \
        "the wheels do not touch: |OC| = 50 mm, r1 + r2 = 55 mm"
    r1, r2 = Wheel("1", "O", 0.07, True), Wheel("2", "C", 0.02, True)
    assert contact(r1, (0.0, 0.0), r2, (0.05, 0.0)) == "two rings cannot roll on each other (both internal)"
    assert "does not fit inside ring 4" in contact(Wheel("2", "C", 0.08), (0.0, 0.0), Wheel("4", "O", 0.07, True),
                                                   (0.0, 0.0))


def test_on_wheel_and_the_links_in_the_books_order():
    w = Wheel("1", "O", 0.04)
    assert on_wheel(w, (0.0, 0.0), (0.0, 0.04)) and not on_wheel(w, (0.0, 0.0), (0.0, 0.0401))
    d = RollingDrive("4", "1", 1.0, {"O": (0.0, 0.0)}, (w,), (Revolute(("10", "4"), "O"),),
                     (Rolling(("1", "2"), (0.04, 0.0)),))
    assert d.links() == ("1", "2", "4", "10") and d.wheel("1") is w and d.wheel("2") is None
