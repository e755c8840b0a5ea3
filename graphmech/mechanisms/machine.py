"""A machine for the flywheel problem: a linkage (or none) with masses, loads and a driver.

Everything is SI (m, kg, kg·m², N, N·m, rad, rad/s) and immutable.

Conventions
-----------
The reduced (equivalent) link is the crank. Its angle φ is measured from *position 1* in the
sense the crank turns (``φ = 0`` at position 1, whatever the crank's absolute angle there):
positions ``k = 1 … N`` lie at ``φ = (k − 1)·Φ/N`` where Φ is the machine's cycle (2π for a
one-revolution cycle, π for an engine whose torque repeats every half turn).

Moments reduced to the crank are signed by the *power* they deliver: positive drives the crank
(acts in its sense of rotation), negative resists it. So ``Mп = Σ P/ω1`` with ``ω1 = |ω1|``,
and a CW crank needs no change of sign in any table.

A slider load (an indicator diagram) acts along its slider's guide. Its displacement ``s`` is
measured along the guide's direction from the slider's backward extreme (``s = 0`` at the dead
centre nearest the guide's tail, ``s = H`` at the other), so ``s/H`` runs 0 … 1 on every stroke.
``during`` says on which stroke the load acts (the slider moving forward = along the guide's
direction, backward, or both); ``sense`` the direction of the force along the guide (+1 along
the guide's direction, −1 against it).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, Union, cast

import numpy as np

from graphmech.mechanisms.linkage import Crank, Linkage

TWO_PI = 2.0 * math.pi
#: A table's argument within this fraction of the table's span of a step is on the step.
ON_STEP = 1e-12


@dataclass(frozen=True)
class Table:
    """A piecewise-linear function y(x) through the points (x_i, y_i).

    ``x`` is non-decreasing; a repeated x is a step (the value jumps there; exactly at the step
    the value is the mean of both sides). Outside the table the end values hold. Periodic use (a moment over the cycle) is the caller's business: it
    passes ``x mod Φ``.
    """

    x: tuple[float, ...]
    y: tuple[float, ...]

    def breaks(self) -> tuple[float, ...]:
        """The x where the function has a kink or a step (interior points), sorted, unique."""
        return tuple(sorted(set(self.x[1:-1])))

    def steps(self, period: float | None = None) -> tuple[tuple[float, float, float], ...]:
        """Each step as (x, value just before, value just after): a repeated x, the first and
        the last value written at it (the value before the table's first x is its first y).

        With ``period`` (a moment against φ over the cycle Φ) the table repeats: the value at
        the end of the cycle meets the one at its start, which is a step at x = 0 when they differ.
        """
        xs, ys = self.x, self.y
        out = []
        i, n = 0, len(xs)
        while i < n:
            j = i
            while j + 1 < n and xs[j + 1] == xs[i]:
                j += 1
            inner = period is None or 0.0 < xs[i] < period
            if j > i and ys[i] != ys[j] and inner:
                out.append((xs[i], ys[i], ys[j]))
            i = j + 1
        if period is not None:
            end = next((y for x, y in zip(xs, ys) if x >= period), ys[-1])  # the limit from below at Φ
            start = [y for x, y in zip(xs, ys) if x <= 0.0]
            start_value = start[-1] if start else ys[0]  # the limit from above at 0
            if end != start_value:
                out.append((0.0, end, start_value))
        return tuple(out)

    def mean_at_steps(self, x: "np.ndarray", values: "np.ndarray", period: float | None = None
                      ) -> tuple["np.ndarray", "np.ndarray"]:
        """``values`` (the table at ``x`` by any one-sided rule) with the mean of both sides
        wherever x falls on a step, and where it did (a bool mask); ``period`` as for
        :meth:`steps` (x then in [0, Φ)).

        "On" is to within ``ON_STEP`` of the table's span: a step written at 210° and a position
        computed as k·Φ/N differ by rounding only, and would otherwise be sampled from whichever
        side the rounding fell on. One rule for the graphical method and the exact solution
        (docs/scene-format.md, "Flywheel scenes").
        """
        x = np.asarray(x, dtype=float)
        out = np.array(values, dtype=float, copy=True)
        hit = np.zeros(x.shape, dtype=bool)
        span = max(abs(self.x[-1] - self.x[0]), abs(self.x[-1]), abs(self.x[0]), period or 0.0)
        tol = ON_STEP * span
        for xs, before, after in self.steps(period):
            on = np.abs(x - xs) <= tol
            if period is not None and xs == 0.0:
                on |= np.abs(x - period) <= tol
            out = np.where(on, 0.5 * (before + after), out)
            hit |= on
        return out, hit


@dataclass(frozen=True)
class Mass:
    """The inertia of one moving link.

    Parameters
    ----------
    link : str
        The link's id ("2").
    point : str
        Its centre of mass S, a named point of the linkage (for a crank balanced about its
        pivot, the pivot itself: then only ``inertia`` counts).
    mass : float
        m, kg (≥ 0).
    inertia : float
        J_S about S, kg·m² (≥ 0).
    """

    link: str
    point: str
    mass: float
    inertia: float = 0.0


@dataclass(frozen=True)
class SliderLoad:
    """A force on a slider along its guide, given as an indicator diagram F(s/H).

    Parameters
    ----------
    point : str
        The slider's point (its path is the guide line).
    axis : float
        The guide's direction, rad from +x CCW; ``s`` grows along it.
    sense : int
        +1: the force acts along ``axis``; −1: against it.
    during : "forward", "backward" or "both"
        The stroke on which the force acts (slider moving along ``axis``, against it, either).
    table : Table
        Force magnitude (N, ≥ 0) against s/H (0 … 1).
    """

    point: str
    axis: float
    sense: int
    during: Literal["forward", "backward", "both"]
    table: Table
    kind: Literal["slider"] = "slider"


@dataclass(frozen=True)
class LinkMoment:
    """A moment on a moving link, against the crank angle: M(φ) from a table, N·m, CCW positive.

    ``table.x`` is φ (rad from position 1, 0 … Φ); the moment's power is M·ω_link.
    """

    link: str
    table: Table
    kind: Literal["moment"] = "moment"


@dataclass(frozen=True)
class CrankMoment:
    """A moment applied to the crank itself, given reduced: M(φ) from a table, N·m.

    Signed by power (positive drives). ``table.x`` is φ (rad from position 1, 0 … Φ). An
    engine's torque curve, or a resisting moment with a step.
    """

    table: Table
    kind: Literal["crank"] = "crank"


Load = Union[SliderLoad, LinkMoment, CrankMoment]


@dataclass(frozen=True)
class Motor:
    """The driving moment of a motor whose working characteristic is a straight line:
    ``M(ω) = M0·(ω_s − ω)/(ω_s − ω_m)``, M0 being the balancing constant moment, so that the
    motor delivers M0 at the mean speed ω_m and nothing at its synchronous speed ω_s.

    Give either ``synchronous`` (ω_s, rad/s, > ω_m) or ``stiffness`` — the ratio
    ``[M0/(ω_s − ω_m)]/(J_F + max Jп)`` divided by ω_m, a measure of how stiff the equation of
    motion is (1e5: the motor's own time constant is 1e-5 of a radian of crank travel).
    """

    synchronous: float | None = None
    stiffness: float | None = None


@dataclass(frozen=True)
class Machine:
    """What the flywheel problem needs to know about a machine.

    Parameters
    ----------
    linkage : Linkage or None
        The mechanism whose crank is the reduced link (None: a machine given by its reduced
        inertia and moments only, such as an engine's torque curve).
    start : float
        The crank's absolute angle at position 1, rad (ignored without a linkage).
    cycle : float
        Φ, the crank angle of one cycle, rad (2π; π for a torque that repeats every half turn;
        4π for a four-stroke engine, whose working cycle is two turns).
    omega_m : float
        The mean angular velocity of the crank, rad/s (> 0).
    delta : float
        The allowed coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m (0 < δ < 2).
    masses : tuple of Mass
        The moving links' inertias.
    loads : tuple of Load
        Forces and moments acting on the machine (the balancing constant moment is not one).
    inertia : float
        Constant reduced inertia of what turns rigidly with the crank and is not a Mass
        (rotor, gears …), kg·m²; with no linkage, the machine's whole Jп.
    balance : "driving" or "resisting"
        Which moment is constant and found from the balance of work over a cycle: a constant
        driving moment (a motor: compressor, shaper) or a constant resistance (an engine driving
        a pump).
    motor : Motor or None
        For the true motion only: the driving moment depends on speed (``balance`` must be
        "driving"); None: the constant balancing moment.
    inertia_table : Table or None
        Jп(φ) given directly as a table (a course project's table of Jп at the positions), kg·m²,
        added to ``inertia`` and the masses: ``x`` is φ from 0 to Φ (closed: the last value equals
        the first), linear between its points, no steps.
    energy_table : Table or None
        ΔT(φ) given directly as a table (``[flywheel.energy_increment]``), J, instead of the loads
        (then ``loads`` is empty): ``x`` is φ from 0 to Φ, ``y`` 0 at both ends, linear between
        its points, no steps.
    """

    linkage: Linkage | None
    start: float
    cycle: float
    omega_m: float
    delta: float
    masses: tuple[Mass, ...] = ()
    loads: tuple[Load, ...] = ()
    inertia: float = 0.0
    balance: Literal["driving", "resisting"] = "driving"
    motor: Motor | None = None
    inertia_table: Table | None = None
    energy_table: Table | None = None

    def __hash__(self) -> int:  # holds a Linkage (a dict inside): identity is enough
        return id(self)

    @property
    def sense(self) -> int:
        """+1 if the crank turns CCW, −1 if CW (+1 without a linkage)."""
        if self.linkage is None:
            return 1
        return 1 if cast(Crank, self.linkage.driver).omega >= 0 else -1  # a machine's linkage is driven by a crank

    def crank_angle(self, phi: float) -> float:
        """The crank's absolute angle (rad) at φ from position 1."""
        return self.start + self.sense * phi

    def positions(self, n: int) -> tuple[float, ...]:
        """φ of positions 1 … n, equally spaced over one cycle (rad from position 1)."""
        return tuple(self.cycle * k / n for k in range(n))


__all__ = ["ON_STEP", "Table", "Mass", "SliderLoad", "LinkMoment", "CrankMoment", "Load", "Motor", "Machine", "TWO_PI"]
