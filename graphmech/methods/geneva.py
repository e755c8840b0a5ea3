"""The Geneva wheel by construction: its sizes laid out at μl, and the wheel's ω₂ and ε₂ read off
the pin's velocity and acceleration polygons, as the book does it for two links joined by a
sliding pair (the pin A₁ of the dial in the slot A₂ of the wheel).

Sizes: the line of centres O₁O₂ = L/μl; through O₂ the slot's line at π/z to O₂O₁; the foot K of
the perpendicular from O₁ onto it is the pin's entry point (the slot is tangent to the pin's circle
there), so O₁K is the arm R and O₂K the wheel's radius S; the pin's nearest approach to O₂ is on
the line of centres, L − R from O₂, and the slot's bottom lies r beyond it: h = S − (L − R − r);
the locking arc's radius R − r − b is laid off from O₁.

Velocities, v_A2 = v_A1 + v_A2A1: pa₁ = ω₁R/μv ⟂ O₁A; through p a line ⟂ O₂A (v_A2), through a₁
a line ∥ O₂A (the sliding, ∥ the slot); their intersection a₂: ω₂ = pa₂·μv/O₂A.
Accelerations, a_A1 = a_A2ⁿ + a_A2ᵗ + a^k_A1A2 + a^r_A1A2 (ω₁ constant): π a₁′ = ω₁²R/μa ∥ AO₁;
π n₂′ = ω₂²·O₂A/μa ∥ AO₂; the Coriolis term 2ω₂ × v_A1A2, ⟂ the slot, laid off back from a₁′ to
k′; through n₂′ a line ⟂ O₂A (a_A2ᵗ), through k′ a line ∥ O₂A (a^r); their intersection a₂′:
ε₂ = n₂′a₂′·μa/O₂A.

Coordinates: O₁ at the origin, O₂ on +x; the dial turns counter-clockwise at ω₁ > 0 from φ on the
line of centres. Lengths are drawing mm; the values a caller reads are drawn × μ.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.errors import OutOfDomain
from graphmech.geometry.kernels import (
    ScalarOps,
    intersect_lines,
    line_parallel_to,
    line_perpendicular_to,
    unit,
)

XY = tuple[float, float]
_OPS = ScalarOps()


@dataclass(frozen=True)
class GenevaLayout:
    """The sizes laid out at μl, drawing mm: O₁, O₂, the entry point K, and the lengths drawn."""

    O1: XY
    O2: XY
    K: XY
    R_mm: float  # O₁K
    S_mm: float  # O₂K
    h_mm: float  # the slot's depth
    r_lock_mm: float  # the locking arc's radius

    @property
    def half_angle(self) -> float:
        """φ₁: the angle of O₁K from the line of centres (the engaged dial turns through 2φ₁)."""
        return math.atan2(self.K[1] - self.O1[1], self.K[0] - self.O1[0])


@dataclass(frozen=True)
class PinPolygons:
    """The pin's polygons at one dial angle: velocity (p, a₁, a₂) at μv, acceleration (π, a₁′,
    n₂′, k′, a₂′) at μa, drawing mm with p = π = origin; the pin A at μl."""

    A: XY
    a1: XY
    a2: XY
    a1_: XY
    n2_: XY
    k_: XY
    a2_: XY
    O2A_mm: float  # the wheel's radius to the pin, at μl
    omega2: float  # signed, rad/s, counter-clockwise positive (the wheel turns against the dial: < 0)
    epsilon2: float  # signed likewise, rad/s²
    v_slide: float  # |a₁a₂|·μv, m/s
    a_k: float  # |a₁′k′|·μa, m/s²


def layout(z: int, L: float, r_pin: float, b: float, mu_l: float) -> GenevaLayout:
    """The mechanism's sizes by construction at μl (m/mm)."""
    if z < 3:
        raise OutOfDomain(f"a Geneva wheel has at least 3 slots, not {z}")
    O1, O2 = (0.0, 0.0), (L / mu_l, 0.0)
    slot = (math.cos(math.pi - math.pi / z), math.sin(math.pi - math.pi / z))  # from O₂, π/z off O₂O₁
    K = intersect_lines(_OPS, line_parallel_to(_OPS, O2, slot), line_perpendicular_to(_OPS, O1, slot))
    R = math.hypot(K[0] - O1[0], K[1] - O1[1])
    S = math.hypot(K[0] - O2[0], K[1] - O2[1])
    nearest = O2[0] - R  # the pin on the line of centres, L − R from O₂
    bottom = nearest - r_pin / mu_l
    return GenevaLayout(O1, O2, (float(K[0]), float(K[1])), R, S, S - bottom, R - r_pin / mu_l - b / mu_l)


def polygons(lay: GenevaLayout, phi: float, omega1: float, mu_l: float, mu_v: float, mu_a: float) -> PinPolygons:
    """The pin's velocity and acceleration polygons at dial angle φ (rad, from O₁O₂)."""
    if abs(phi) > lay.half_angle * (1 + 1e-12):
        raise OutOfDomain(f"the pin is out of the slot at φ = {math.degrees(phi):g}°: it drives the wheel for "
                          f"|φ| ≤ {math.degrees(lay.half_angle):g}°")
    R = lay.R_mm
    A = (lay.O1[0] + R * math.cos(phi), lay.O1[1] + R * math.sin(phi))
    va = omega1 * R * mu_l / mu_v  # pa₁, ⟂ O₁A in the dial's sense
    a1 = (-va * math.sin(phi), va * math.cos(phi))
    slot = unit(_OPS, lay.O2, A)  # along O₂A
    p = (0.0, 0.0)
    a2 = intersect_lines(_OPS, line_perpendicular_to(_OPS, p, slot), line_parallel_to(_OPS, a1, slot))
    a2 = (float(a2[0]), float(a2[1]))
    O2A = float(slot[2])
    # ω₂ about O₂: v_A2 = ω₂ × O₂A, so ω₂ = (O₂A × v_A2)/|O₂A|²
    omega2 = (slot[0] * a2[1] - slot[1] * a2[0]) * mu_v / (O2A * mu_l)
    rel = ((a1[0] - a2[0]) * mu_v, (a1[1] - a2[1]) * mu_v)  # v_A1A2, m/s
    an1 = omega1 * omega1 * R * mu_l / mu_a  # π a₁′, toward O₁
    a1_ = (-an1 * math.cos(phi), -an1 * math.sin(phi))
    an2 = omega2 * omega2 * O2A * mu_l / mu_a  # π n₂′, toward O₂
    n2_ = (-an2 * slot[0], -an2 * slot[1])
    ak = (-2 * omega2 * rel[1] / mu_a, 2 * omega2 * rel[0] / mu_a)  # 2ω₂ × v_A1A2
    k_ = (a1_[0] - ak[0], a1_[1] - ak[1])
    a2_ = intersect_lines(_OPS, line_perpendicular_to(_OPS, n2_, slot), line_parallel_to(_OPS, k_, slot))
    a2_ = (float(a2_[0]), float(a2_[1]))
    t = (a2_[0] - n2_[0], a2_[1] - n2_[1])  # a_A2ᵗ = ε₂ × O₂A
    epsilon2 = (slot[0] * t[1] - slot[1] * t[0]) * mu_a / (O2A * mu_l)
    return PinPolygons(A, a1, a2, a1_, n2_, k_, a2_, O2A, omega2, epsilon2,
                       math.hypot(*rel), math.hypot(*ak) * mu_a)


__all__ = ["GenevaLayout", "PinPolygons", "layout", "polygons"]
