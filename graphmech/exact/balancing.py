"""Closed-form balancing of a rigid rotor: the correction masses from the equations of balance.

The polygons of :mod:`graphmech.methods.balancing` are checked against the two conditions a
balanced rotor meets, written with complex numbers (x + iy in the plane of rotation) and solved
directly — nothing is taken from ``graphmech.methods``, ``graphmech.construction`` or
``graphmech.geometry``:

* static (one plane): Σ mᵢrᵢ + W_b = 0;
* dynamic (planes I and II at z_I ≠ z_II): the resultant force Σ mᵢrᵢ + W_I + W_II = 0 and the
  resultant moment, Σ mᵢrᵢzᵢ + W_I·z_I + W_II·z_II = 0, solved by Cramer's rule (the moments
  taken about the correction planes, so that nothing cancels in round-off).

The ω² of the centrifugal forces is left out throughout (it multiplies every term), so forces are
in kg·m and moments in kg·m². Angles in rad, lengths in m.
"""
from __future__ import annotations

import cmath
import math  # noqa: F401  (the doctests use it)
from dataclasses import dataclass
from typing import Sequence

from graphmech.errors import OutOfDomain


@dataclass(frozen=True)
class Unbalance:
    """An eccentric mass: m (kg) at radius r (m), angle θ (rad), axial position z (m)."""

    m: float
    r: float
    theta: float
    z: float = 0.0

    def vector(self) -> complex:
        """m·r as a complex number, kg·m."""
        return self.m * self.r * cmath.exp(1j * self.theta)


def static_correction(masses: Sequence[Unbalance]) -> complex:
    """W_b = −Σ mᵢrᵢ, kg·m (complex).

    >>> w = static_correction([Unbalance(1.0, 0.1, 0.0), Unbalance(1.0, 0.1, math.pi / 2)])
    >>> round(abs(w), 12), round(math.degrees(cmath.phase(w)), 9)
    (0.141421356237, -135.0)
    """
    return -sum((u.vector() for u in masses), 0j)


def dynamic_correction(masses: Sequence[Unbalance], z_I: float, z_II: float) -> tuple[complex, complex]:
    """(W_I, W_II), kg·m, from the balance of moments about each correction plane.

    Raises
    ------
    ValueError
        When the planes coincide (the moment equation cannot be met).

    Examples
    --------
    >>> a, b = dynamic_correction([Unbalance(1.0, 0.1, 0.0, 0.25)], 0.0, 1.0)
    >>> round(a.real, 12), round(b.real, 12)
    (-0.075, -0.025)
    """
    if z_I == z_II:
        raise OutOfDomain("the correction planes coincide")
    # Cramer's rule with the moments taken about each correction plane in turn (about plane II
    # for W_I, about plane I for W_II): the same solution as about z = 0, without the round-off
    # of Σ mᵢrᵢzᵢ − U·z_II cancelling when the planes are close together far from z = 0.
    det = z_II - z_I
    W_I = -sum((u.vector() * (z_II - u.z) for u in masses), 0j) / det
    W_II = -sum((u.vector() * (u.z - z_I) for u in masses), 0j) / det
    return W_I, W_II


def residuals(masses: Sequence[Unbalance], corrections: Sequence[tuple[complex, float]],
              about: float = 0.0) -> tuple[float, float]:
    """|resultant force| (kg·m) and |resultant moment about z = ``about``| (kg·m²) of the rotor with
    the corrections (W, z) added: zero to round-off when it is balanced.

    Take ``about`` at a correction plane: with planes close together the corrections are large
    and opposite, and their moments about a far-away z = 0 would cancel in round-off (a residual
    of 1e-2 of the moments for planes 1e-3 mm apart 9 m out), which is the check's error, not
    the balance's.

    >>> W = dynamic_correction([Unbalance(1.0, 0.1, 0.0, 9.0)], 9.0, 9.000001)
    >>> [x < 1e-12 for x in residuals([Unbalance(1.0, 0.1, 0.0, 9.0)], list(zip(W, (9.0, 9.000001))), 9.0)]
    [True, True]
    """
    F = sum((u.vector() for u in masses), 0j) + sum((w for w, _ in corrections), 0j)
    M = sum((u.vector() * (u.z - about) for u in masses), 0j) + sum((w * (z - about) for w, z in corrections), 0j)
    return abs(F), abs(M)


__all__ = ["Unbalance", "dynamic_correction", "residuals", "static_correction"]
