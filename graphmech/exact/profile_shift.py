"""Profile shift as the book designs it, in closed form: the least shift without undercut, the
shifts that fit a stated centre distance, a repair's zero-sum shift, the centre-distance
modification y and the tip shortening Δy, and the kind of drive.

Independent of the constructions (:mod:`graphmech.methods.profile_shift`): the formulas here are
the book's — inv α′ = 2 tan α (x₁ + x₂)/(z₁ + z₂) + inv α, y = (a′ − a)/m, Δy = x₁ + x₂ − y,
x_min = h*a (z_min − z)/z_min — with inv and its inverse from :mod:`graphmech.exact.gear`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.exact.gear import inv
from graphmech.mechanisms.gear import ToothSystem
from graphmech.tolerances import EPS

#: The kinds of drive by the sum of the shifts (external pairs).
Drive = Literal["standard", "equal and opposite", "positive", "negative"]
#: A shift sum this small (relative to 1) is zero: the book's "x₁ + x₂ = 0".
ZERO_SUM = 1e-12


def z_min_book(system: ToothSystem) -> int:
    """The book's least tooth number without undercut, 2h*a/sin²α rounded to the nearest whole
    number (17 for α = 20°, h*a = 1, whose exact value 17.097 allows a trace of undercut; 14 for
    the stub tooth h*a = 0.8).

    >>> z_min_book(ToothSystem(m=1.0, alpha=math.radians(20))), z_min_book(ToothSystem(1.0, math.radians(20), 0.8))
    (17, 14)
    """
    _system(system)
    return max(1, round(z_min_exact(system)))


def z_min_exact(system: ToothSystem) -> float:
    """2h*a/sin²α: the tooth number whose N₁ lies exactly on the rack cutter's addendum line.

    >>> round(z_min_exact(ToothSystem(m=1.0, alpha=math.radians(20))), 9)
    17.097264341
    """
    _system(system)
    return 2.0 * system.ha_star / math.sin(system.alpha) ** 2


def x_min_book(system: ToothSystem, z: int) -> float:
    """x_min = h*a (z_min − z)/z_min with the book's z_min.

    >>> round(x_min_book(ToothSystem(m=1.0, alpha=math.radians(20)), 12), 12)
    0.294117647059
    """
    zm = z_min_book(system)
    return system.ha_star * (zm - z) / zm


def x_min_exact(system: ToothSystem, z: int) -> float:
    """The exact limit h*a − z·sin²α/2 (the cutter's addendum line through N₁)."""
    _system(system)
    return system.ha_star - 0.5 * z * math.sin(system.alpha) ** 2


@dataclass(frozen=True)
class ShiftDesign:
    """The shifts of an external pair on a stated centre distance a′ (m, rad): the working
    pressure angle α′ = arccos(a cos α/a′), x₁ + x₂ from inv α′, the shifts, y = (a′ − a)/m and
    Δy = x₁ + x₂ − y (the tips shortened by Δy·m)."""

    a: float
    a_w: float
    alpha_w: float
    x_sum: float
    x1: float
    x2: float
    y: float
    delta_y: float


def shifts_for_centre_distance(system: ToothSystem, z1: int, z2: int, a_w: float,
                               x1: float | None = None) -> ShiftDesign:
    """x₁ + x₂ = (inv α′ − inv α)(z₁ + z₂)/(2 tan α) for an external pair at a′, split equally
    unless x₁ is given.

    >>> d = shifts_for_centre_distance(ToothSystem(m=0.01, alpha=math.radians(20)), 12, 12, 0.13)
    >>> round(math.degrees(d.alpha_w), 9), round(d.x_sum, 9), round(d.delta_y, 9)
    (29.841118724, 1.250498184, 0.250498184)
    """
    _system(system, addendum=False)
    if not (math.isfinite(a_w) and a_w > 0.0):
        raise OutOfDomain(f"the centre distance a′ must be a positive length, not {a_w!r} m")
    m, alpha = system.m, system.alpha
    a = 0.5 * m * (z1 + z2)
    c = a * math.cos(alpha) / a_w
    if c > 1.0:
        raise NoSolution(f"at a′ = {a_w:.6g} m the base circles would cross (a′ < a·cos α = "
                         f"{a * math.cos(alpha):.6g} m): no shifts fit it")
    # at a′ = a (to a few ulps) the pair is standard: acos(cos α) would leave x₁ + x₂ ≈ 1e-15, a "shift" of noise
    alpha_w = alpha if abs(a_w - a) <= 4.0 * EPS * a else math.acos(c)
    x_sum = (inv(alpha_w) - inv(alpha)) * (z1 + z2) / (2.0 * math.tan(alpha))
    first = 0.5 * x_sum if x1 is None else x1
    y = (a_w - a) / m
    return ShiftDesign(a=a, a_w=a_w, alpha_w=alpha_w, x_sum=x_sum, x1=first, x2=x_sum - first, y=y,
                       delta_y=x_sum - y)


def tip_shortening(system: ToothSystem, z1: int, z2: int, x_sum: float, a_w: float) -> float:
    """Δy = x₁ + x₂ − (a′ − a)/m: how much (× m) the tips of an external pair at a′ must lose to
    keep the standard clearance c*m (0 when a′ ≥ a + (x₁ + x₂)m: nothing to shorten).

    >>> round(tip_shortening(ToothSystem(m=0.01, alpha=math.radians(20)), 12, 12, 1.0, 0.128), 12)
    0.2
    """
    _system(system, addendum=False)
    a = 0.5 * system.m * (z1 + z2)
    return max(0.0, x_sum - (a_w - a) / system.m)


def repair_shift(system: ToothSystem, thickness_loss: float) -> float:
    """The worn wheel's negative shift: its reference thickness πm/2 + 2xm·tan α less the loss,
    x₂ = −loss/(2m·tan α) (the new pinion takes x₁ = −x₂).

    >>> round(repair_shift(ToothSystem(m=0.005, alpha=math.radians(20)), 0.00075), 12)
    -0.206060806459
    """
    _system(system, addendum=False)
    if not (math.isfinite(thickness_loss) and thickness_loss > 0.0):
        raise OutOfDomain(f"the thickness loss must be a positive length, not {thickness_loss!r} m")
    return -thickness_loss / (2.0 * system.m * math.tan(system.alpha))


def drive_kind(x1: float, x2: float) -> Drive:
    """Standard (both unshifted), equal and opposite (x₁ + x₂ = 0), positive or negative.

    >>> drive_kind(0.0, 0.0), drive_kind(0.2, -0.2), drive_kind(0.6, 0.6), drive_kind(-0.1, 0.0)
    ('standard', 'equal and opposite', 'positive', 'negative')
    """
    total = x1 + x2
    if abs(total) <= ZERO_SUM * max(1.0, abs(x1), abs(x2)):
        return "standard" if x1 == 0.0 and x2 == 0.0 else "equal and opposite"
    return "positive" if total > 0.0 else "negative"


def _system(system: ToothSystem, addendum: bool = True) -> None:
    if not (math.isfinite(system.m) and system.m > 0.0):
        raise OutOfDomain(f"the module m must be a positive length, not {system.m!r} m")
    if not (math.isfinite(system.alpha) and 0.0 < system.alpha < 0.5 * math.pi):
        raise OutOfDomain(f"the pressure angle α must lie between 0 and 90°, not {system.alpha!r} rad")
    if addendum and not (math.isfinite(system.ha_star) and system.ha_star > 0.0):
        raise NotApplicable(f"without an addendum (h*a = {system.ha_star!r}) no tooth is undercut: "
                            "there is no least shift")


__all__ = ["ZERO_SUM", "Drive", "ShiftDesign", "drive_kind", "repair_shift", "shifts_for_centre_distance",
           "tip_shortening", "x_min_book", "x_min_exact", "z_min_book", "z_min_exact"]
