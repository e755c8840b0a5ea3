"""Balancing a rigid rotor by mass-radius polygons (质径积多边形), at μW (kg·m)/mm.

Static balancing (one plane, a disc): lay off the mass-radius products Wᵢ = mᵢrᵢ head to tail,
each parallel to its mass's radius; the side that closes the polygon, from the last end back to
the start, is the correction W_b = m_b·r_b, its direction the correction mass's angle.

Dynamic balancing (two correction planes I and II): first resolve each Wᵢ into the two planes by
the lever rule (the static substitution of a mass by two masses in the planes),
W_iI = Wᵢ·(z_II − zᵢ)/(z_II − z_I), W_iII = Wᵢ·(zᵢ − z_I)/(z_II − z_I) — a mass outside the span
gives a reversed share — then close one polygon in each plane.

Magnitudes and angles are read off the drawing (drawn length × μW; the closing side's direction).
The balance conditions that check them are solved independently in
:mod:`graphmech.exact.balancing`.
"""
from __future__ import annotations

import cmath
import math
from graphmech.errors import OutOfDomain
from graphmech.mechanisms.rotor import RotorMass
from dataclasses import dataclass
from typing import Callable, Sequence

XY = tuple[float, float]
#: A closing side shorter than this fraction of the polygon's total length is no correction:
#: the rotor is already balanced in that plane (no angle can be read off a point).
BALANCED_REL = 1e-12


@dataclass(frozen=True)
class DrawnSide:
    """One side of a mass-radius polygon, drawing mm; ``name`` such as ``"W1"``, ``"Wb"``."""

    name: str
    start: XY
    end: XY


@dataclass(frozen=True)
class Correction:
    """What one plane's polygon gives: the closing side, W = m_b·r_b (kg·m), the angle (rad,
    None when the plane is already balanced), the correction mass m_b at radius r_b."""

    plane: str
    sides: tuple[DrawnSide, ...]
    closing: DrawnSide
    drawn_mm: float
    W: float
    theta: float | None
    r_b: float
    m_b: float
    shares: tuple[tuple[str, float], ...] = ()  # name → lever factor into this plane (dynamic)

    @property
    def balanced(self) -> bool:
        return self.theta is None

    @property
    def vector(self) -> complex:
        """W·e^{iθ}, the correction as a complex number (0 when the plane is already balanced)."""
        return 0j if self.theta is None else cmath.rect(self.W, self.theta)


def close_mass_radius_polygon(plane: str, vectors: Sequence[tuple[str, float, float]], r_b: float,
                              mu_W: float, shares: tuple[tuple[str, float], ...] = ()) -> Correction:
    """Lay off (name, W kg·m, angle rad) head to tail at μW from the origin and close it.

    >>> c = close_mass_radius_polygon("I", [("W1", 0.1, 0.0), ("W2", 0.1, math.pi / 2)], 0.1, 0.002)
    >>> round(c.W, 12), round(math.degrees(c.theta), 9), round(c.m_b, 12)
    (0.141421356237, -135.0, 1.414213562373)

    Raises
    ------
    ValueError
        When μW or the correction radius r_b is not a positive finite number (it is divided by).
    """
    if not (0 < mu_W < math.inf and 0 < r_b < math.inf):
        raise OutOfDomain(f"μW and r_b must be positive and finite, not μW = {mu_W!r}, r_b = {r_b!r}")
    sides = []
    p = (0.0, 0.0)
    total = 0.0
    for name, w, th in vectors:
        q = (p[0] + w / mu_W * math.cos(th), p[1] + w / mu_W * math.sin(th))
        sides.append(DrawnSide(name, p, q))
        total += abs(w) / mu_W
        p = q
    closing = DrawnSide("Wb" if plane == "" else f"Wb{plane}", p, (0.0, 0.0))
    drawn = math.hypot(p[0], p[1])
    if drawn <= BALANCED_REL * max(total, 1e-300):
        return Correction(plane, tuple(sides), closing, 0.0, 0.0, None, r_b, 0.0, shares)
    theta = math.atan2(-p[1], -p[0])  # the closing side points from the last end back to the start
    W = drawn * mu_W
    return Correction(plane, tuple(sides), closing, drawn, W, theta, r_b, W / r_b, shares)


def static_balance(masses: Sequence[RotorMass], r_b: float, mu_W: float) -> Correction:
    """The one-plane correction: Σ Wᵢ + W_b = 0 by the polygon."""
    return close_mass_radius_polygon("", [(f"W{u.name}", u.m * u.r, u.theta) for u in masses], r_b, mu_W)


def dynamic_balance(masses: Sequence[RotorMass], z_I: float, z_II: float, r_b: tuple[float, float],
                    mu_W: float) -> tuple[Correction, Correction]:
    """The two-plane correction: each Wᵢ resolved into planes I and II, one polygon in each.

    Raises
    ------
    ValueError
        When the planes coincide (no lever to resolve the moments with); the scene refuses this
        before it gets here.
    """
    span = z_II - z_I
    if span == 0.0:
        raise OutOfDomain("the correction planes coincide")
    out = []
    lever: Callable[[float], float]
    for plane, r, lever in (("I", r_b[0], lambda z: (z_II - z) / span), ("II", r_b[1], lambda z: (z - z_I) / span)):
        vecs = []
        shares = []
        for u in masses:
            k = lever(u.z)
            shares.append((u.name, k))
            w = u.m * u.r * k
            th = u.theta if w >= 0 else u.theta + math.pi  # a reversed share points the other way
            vecs.append((f"W{u.name}{plane}", abs(w), th))
        out.append(close_mass_radius_polygon(plane, vecs, r, mu_W, tuple(shares)))
    return out[0], out[1]


__all__ = ["BALANCED_REL", "Correction", "DrawnSide", "close_mass_radius_polygon", "dynamic_balance",
           "static_balance"]
