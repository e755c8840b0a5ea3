"""The loads on a linkage for kinetostatic analysis: masses, external forces and moments, friction.

Everything is SI (kg, kg·m², N, N·m, m) and immutable. This is *structure*, like the linkage it
loads: which link carries which mass, where a force acts, which pair has friction. The numbers that
follow from the motion (inertia loads, reactions) are found by the methods and by the exact check.

Conventions
-----------
x to the right, y up; moments and angles counter-clockwise positive. Gravity acts along −y.
Reactions are named ``R_ij``: the force exerted *by* link i *on* link j (the frame is the scene's
frame link, "0" in most books).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.mechanisms.machine import Mass


#: A moving link's inertia: m at its centre of mass S and J_S about S — the same record the
#: flywheel's machine uses (one concept, one class).
LinkMass = Mass


@dataclass(frozen=True)
class PointForce:
    """An external force on a link, applied at one of its named points.

    Parameters
    ----------
    link, point : str
        The link loaded and the point of application (on that link).
    magnitude : float
        |F|, N (≥ 0).
    angle : float
        Direction of the force, rad from +x CCW.
    resistance : bool
        A working resistance: it acts only while it opposes the point's velocity (the working
        stroke of a shaper's ram) and is zero otherwise.
    name : str
        Its label on the drawing ("P_r", "F_3").
    """

    link: str
    point: str
    magnitude: float
    angle: float
    resistance: bool = False
    name: str = "F"

    @property
    def vector(self) -> tuple[float, float]:
        return (self.magnitude * math.cos(self.angle), self.magnitude * math.sin(self.angle))


@dataclass(frozen=True)
class LinkCouple:
    """An external moment on a moving link, N·m, CCW positive."""

    link: str
    moment: float
    name: str = "M"


@dataclass(frozen=True)
class RevoluteFriction:
    """A journal's friction: the friction circle ρ = f_v·r about the joint at ``point``.

    ``f_v`` is the (equivalent) friction coefficient, ``radius`` the journal radius r, m.
    """

    point: str
    f_v: float
    radius: float

    @property
    def rho(self) -> float:
        return self.f_v * self.radius


@dataclass(frozen=True)
class SlidingFriction:
    """A slider's friction on its frame guide: the reaction tilted by φ = arctan f."""

    link: str
    f: float

    @property
    def angle(self) -> float:
        return math.atan(self.f)


@dataclass(frozen=True)
class ForceModel:
    """Everything the kinetostatic analysis needs besides the linkage and its motion.

    Parameters
    ----------
    masses : tuple of LinkMass
    forces : tuple of PointForce
    couples : tuple of LinkCouple
    gravity : float
        g, m/s² along −y (0: weights ignored, as books often do).
    revolute_friction : tuple of RevoluteFriction
    sliding_friction : tuple of SlidingFriction
    tolerance : float
        Successive approximation stops when no reaction changes by more than this, N (N·m for
        moments).
    max_iterations : int
        ... and gives up after this many rounds.
    """

    masses: tuple[LinkMass, ...] = ()
    forces: tuple[PointForce, ...] = ()
    couples: tuple[LinkCouple, ...] = ()
    gravity: float = 0.0
    revolute_friction: tuple[RevoluteFriction, ...] = ()
    sliding_friction: tuple[SlidingFriction, ...] = ()
    tolerance: float = 1e-10
    max_iterations: int = 100

    @property
    def has_friction(self) -> bool:
        """True where any pair has a non-zero friction coefficient (f = 0 is frictionless)."""
        return any(fr.rho > 0 for fr in self.revolute_friction) or any(
            fr.f > 0 for fr in self.sliding_friction)


__all__ = ["LinkMass", "PointForce", "LinkCouple", "RevoluteFriction", "SlidingFriction", "ForceModel"]
