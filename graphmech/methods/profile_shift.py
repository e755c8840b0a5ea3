"""Profile shift by construction: the undercut limit read off the generating rack's drawing, and
the shifts that fit a centre distance or a repair found from teeth constructed by points.

No inv α = tan α − α here: the working pressure angle is the angle of the line of action drawn
between the base circles at a′ (:func:`graphmech.methods.gear_meshing.line_of_action`), and a
tooth's thickness on any circle is measured between its constructed flanks
(:func:`graphmech.methods.involute.at_radius`). A shift moves the cutter out by xm and so widens
the tooth on every circle by an amount proportional to x (the same involutes, turned apart): two
constructions, at x = 0 and x = 1, give that straight line, and the shift is where it reaches the
thickness wanted — exact, no iteration.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.geometry.kernels import ScalarOps, intersect_lines
from graphmech.mechanisms.gear import SpurGear, ToothSystem
from graphmech.methods.gear_meshing import line_of_action
from graphmech.methods.involute import at_radius, circles

XY = tuple[float, float]


@dataclass(frozen=True)
class UndercutLimit:
    """The rack cutter generating a gear of z teeth: its pitch line tangent to the reference
    circle at P (O₁ at the origin, P straight above), the line of action through P at α, N₁ the
    foot of the perpendicular from O₁ on it. The cutter's addendum line may lie at most
    ``depth`` = the height of P above N₁ below the pitch line: x_min = h*a − depth/m; and the
    tooth number whose N₁ lies on an unshifted cutter's addendum line, z_min = z·h*a·m/depth
    (the depth grows as z)."""

    P: XY
    N1: XY
    depth: float
    x_min: float
    z_min: float


def undercut_limit(system: ToothSystem, z: int) -> UndercutLimit:
    """N₁ constructed and its depth below the pitch line measured."""
    if not (system.ha_star > 0.0 and math.isfinite(system.ha_star)):
        raise NotApplicable(f"without an addendum (h*a = {system.ha_star!r}) no tooth is undercut")
    r, _, _, _ = circles(system, SpurGear(z))
    ops = ScalarOps()
    P = (0.0, r)
    u = (math.cos(system.alpha), -math.sin(system.alpha))   # the line of action, down to the right
    ops.step = "N1 = the line of action ∩ its perpendicular from O1"
    N = intersect_lines(ops, (P[0], P[1], u[0], u[1]), (0.0, 0.0, -u[1], u[0]))
    N1 = (float(N[0]), float(N[1]))
    depth = P[1] - N1[1]
    m = system.m
    return UndercutLimit(P=P, N1=N1, depth=depth, x_min=system.ha_star - depth / m,
                         z_min=z * system.ha_star * m / depth)


@dataclass(frozen=True)
class ShiftForCentreDistance:
    """An external pair at a′: the line of action drawn between the unshifted base circles, α′ its
    angle, the working pitch radii r′ = O₁P, O₂P; each tooth's thickness on its r′ constructed at
    x = 0 (s0) and its growth per unit shift (k, from the construction at x = 1); the shifts that
    close the backlash, s₁′ + s₂′ = 2π r₁′/z₁: x₁ + x₂ = (p′ − s₁0 − s₂0)/k."""

    alpha_w: float
    r_w: tuple[float, float]
    s0: tuple[float, float]
    k: tuple[float, float]
    x_sum: float


def shift_for_centre_distance(system: ToothSystem, z1: int, z2: int, a_w: float) -> ShiftForCentreDistance:
    """x₁ + x₂ for an external pair to mesh without backlash at a′."""
    if not (math.isfinite(a_w) and a_w > 0.0):
        raise OutOfDomain(f"the centre distance must be positive and finite, not {a_w!r}")
    g1, g2 = SpurGear(z1), SpurGear(z2)
    line = line_of_action(system, g1, g2, "external", a_w)
    assert line.O2 is not None
    r_w = (math.hypot(*line.P), math.hypot(line.P[0] - line.O2[0], line.P[1] - line.O2[1]))
    s0 = (at_radius(system, g1, r_w[0]).s_k, at_radius(system, g2, r_w[1]).s_k)
    k = (at_radius(system, SpurGear(z1, 1.0), r_w[0]).s_k - s0[0],
         at_radius(system, SpurGear(z2, 1.0), r_w[1]).s_k - s0[1])
    pitch = 2.0 * math.pi * r_w[0] / z1
    x_sum = (pitch - s0[0] - s0[1]) / (0.5 * (k[0] + k[1]))  # k₁ = k₂ = 2m tan α·r′/r: equal on both gears
    return ShiftForCentreDistance(alpha_w=math.atan2(line.u[1], line.u[0]), r_w=r_w, s0=s0, k=k, x_sum=x_sum)


def shift_for_thickness(system: ToothSystem, z: int, change: float) -> float:
    """The shift that changes the tooth's thickness on its reference circle by ``change`` (m):
    the thickness constructed at x = 0 and x = 1, the straight line between them (the repair's
    wheel re-cut thinner: change = −loss)."""
    r, _, _, _ = circles(system, SpurGear(z))
    s0 = at_radius(system, SpurGear(z), r).s_k
    s1 = at_radius(system, SpurGear(z, 1.0), r).s_k
    return change / (s1 - s0)


__all__ = ["ShiftForCentreDistance", "UndercutLimit", "shift_for_centre_distance", "shift_for_thickness",
           "undercut_limit"]
