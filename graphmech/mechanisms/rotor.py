"""A rigid rotor's eccentric masses: what static and dynamic balancing work on."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class RotorMass:
    """An eccentric mass: its label (``"1"``), m kg, radius r m, angle θ rad (CCW), axial position z m."""

    name: str
    m: float
    r: float
    theta: float
    z: float = 0.0


__all__ = ["RotorMass"]
