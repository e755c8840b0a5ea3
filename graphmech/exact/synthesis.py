"""Linkage synthesis in closed form: the designs the construction of
:mod:`graphmech.methods.synthesis_time_ratio` draws, found by the cosine rule alone.

Design from the time ratio K (θ = 180°(K − 1)/(K + 1)):

crank-rocker from the rocker c = l_CD, the frame d = l_AD and one limit position ∠ADC₁ = λ
    With A = 0 and D = d on the x axis, C₁ = D + c·(−cos λ, sin λ); AC₁ = √(c² + d² − 2cd·cos λ)
    and ∠DAC₁ = α₁ by the cosine rule. C₂ lies on a ray from A at α₁ ∓ θ to the frame line and on
    the rocker's circle: AC₂ = d·cos β ± √(c² − d²·sin² β) for the ray at β.
crank-rocker from c, d and the swing ψ
    With D = 0 and C₁, C₂ at 90° ± ψ/2, the chord C₁C₂ = 2c·sin(ψ/2); A sees it at θ, so A lies on
    a circle of radius C₁C₂/(2 sin θ) about a centre on the chord's bisector (either side), and at
    d from D: the angle at D of the triangle D–O–A by the cosine rule.

Either way l_AB = |AC₂ − AC₁|/2, l_BC = (AC₁ + AC₂)/2. A design is kept only where C₁ and C₂ lie
on one side of the frame line (one assembly branch) and the crank is the shortest link of a
Grashof chain (:func:`graphmech.exact.characteristics.fourbar_class`); mirror images are one
design. Nothing here uses the construction code. Lengths in one unit, angles in radians.
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import Literal

from graphmech.exact.characteristics import fourbar_class

__all__ = ["Design", "crank_rocker_from_limit", "crank_rocker_from_swing", "guide_bar_from_K", "slider_crank_from_K",
           "theta_of_K"]

#: Below this, relative to the linkage's size, a crank has no length (C₂ on C₁).
NO_CRANK = 1e-9


@dataclass(frozen=True)
class Design:
    """One designed crank-rocker: pivots A, D and the rocker's limit positions C₁, C₂ (x + iy)."""

    A: complex
    D: complex
    C1: complex
    C2: complex

    @property
    def AC1(self) -> float:
        return abs(self.C1 - self.A)

    @property
    def AC2(self) -> float:
        return abs(self.C2 - self.A)

    @property
    def lAB(self) -> float:
        return abs(self.AC2 - self.AC1) / 2.0

    @property
    def lBC(self) -> float:
        return (self.AC1 + self.AC2) / 2.0

    @property
    def lCD(self) -> float:
        return abs(self.C1 - self.D)

    @property
    def lAD(self) -> float:
        return abs(self.D - self.A)

    @property
    def branch(self) -> Literal["left", "right"]:
        """The side of the directed line B₁ → D that C₁ lies to (the dyad's branch), B₁ the crank
        pin at C₁'s limit: on AC₁, ahead of A when C₁ is the extended position."""
        u = (self.C1 - self.A) / self.AC1
        B = self.A + (u if self.AC1 > self.AC2 else -u) * self.lAB
        z = (self.C1 - B) / (self.D - B)
        return "left" if z.imag > 0.0 else "right"


def theta_of_K(K: float) -> float:
    """θ = π(K − 1)/(K + 1), rad.

    >>> round(math.degrees(theta_of_K(1.5)), 12)
    36.0
    """
    return math.pi * (K - 1.0) / (K + 1.0)


def _keep(design: Design) -> bool:
    """One branch, a crank of some length, and that crank the Grashof crank."""
    a, b, c, d = design.lAB, design.lBC, design.lCD, design.lAD
    if a <= NO_CRANK * (b + c + d):
        return False
    same_side = ((design.C1 - design.A) / (design.D - design.A)).imag * \
        ((design.C2 - design.A) / (design.D - design.A)).imag > 0.0
    return same_side and fourbar_class(a, b, c, d) == "crank_rocker_AB"


def _distinct(designs: list[Design]) -> list[Design]:
    out: list[Design] = []
    for x in designs:
        if not any(abs(x.AC2 - y.AC2) <= 1e-12 * x.lAD and abs(x.AC1 - y.AC1) <= 1e-12 * x.lAD for y in out):
            out.append(x)
    return out


def crank_rocker_from_limit(c: float, d: float, limit: float, theta: float) -> list[Design]:
    """The crank-rockers with rocker c, frame d, a limit position at ∠ADC₁ = ``limit`` and the
    crank angle θ between the limits, longest l_BC first.

    >>> [round(x.lAB, 6) for x in crank_rocker_from_limit(75.0, 100.0, math.radians(45), math.radians(36))]
    [49.311764, 22.511995]
    """
    D = complex(d, 0.0)
    C1 = D + c * cmath.exp(1j * (math.pi - limit))
    # the law of cosines with 1 − cos α = 2 sin²(α/2): no cancellation where C₁ is near A (c = d
    # and a small limit angle put AC₁ at round-off of c² + d² − 2cd·cos α, then 0: a division by zero)
    ac1 = math.sqrt((c - d) ** 2 + 4.0 * c * d * math.sin(limit / 2.0) ** 2)
    alpha1 = math.acos(max(-1.0, min(1.0, (ac1 * ac1 + d * d - c * c) / (2.0 * ac1 * d))))
    if C1.imag < 0.0:
        alpha1 = -alpha1
    found = []
    for beta in (alpha1 - theta, alpha1 + theta):
        disc = c * c - (d * math.sin(beta)) ** 2
        if disc < 0.0:
            continue
        for t in (d * math.cos(beta) + math.sqrt(disc), d * math.cos(beta) - math.sqrt(disc)):
            if t > 0.0:
                found.append(Design(0j, D, C1, t * cmath.exp(1j * beta)))
    return sorted(_distinct([x for x in found if _keep(x)]), key=lambda x: -x.lBC)


def crank_rocker_from_swing(c: float, d: float, psi: float, theta: float) -> list[Design]:
    """The crank-rockers with rocker c, frame d, swing ψ and crank angle θ (one of each mirror
    pair: A left of the rocker's middle position), longest l_BC first.

    >>> [round(x.lAB, 6) for x in crank_rocker_from_swing(75.0, 100.0, math.radians(40), math.radians(36))]
    [22.037387]
    """
    C1, C2 = c * cmath.exp(1j * (math.pi / 2 + psi / 2)), c * cmath.exp(1j * (math.pi / 2 - psi / 2))
    chord, mid = abs(C2 - C1), c * math.cos(psi / 2.0)
    found = []
    if theta == 0.0:  # A on the line C₁C₂ itself: y = mid
        if d >= mid:
            found.append(Design(complex(-math.sqrt(d * d - mid * mid), mid), 0j, C1, C2))
    else:
        R = chord / (2.0 * math.sin(theta))
        for s in (-1.0, 1.0):  # the centre below the chord (D's side) and above it
            h = mid + s * chord / (2.0 * math.tan(theta))
            if h == 0.0:
                continue
            cos_phi = (d * d + h * h - R * R) / (2.0 * d * abs(h))
            if abs(cos_phi) > 1.0:
                continue
            phi = math.acos(cos_phi)  # from the direction D → O
            A = d * complex(-math.sin(phi), math.cos(phi) * math.copysign(1.0, h))
            if s * (A.imag - mid) > 0.0:  # on the arc that sees C₁C₂ at θ: the centre's side
                found.append(Design(A, 0j, C1, C2))
    return sorted(_distinct([x for x in found if _keep(x)]), key=lambda x: -x.lBC)


def guide_bar_from_K(d: float, theta: float, H: float | None = None) -> tuple[float, float | None]:
    """(l_AB, l_CD) of the guide bar with l_AC = d and θ = ψ: the crank is ⟂ the bar at the limits,
    so l_AB = d·sin(θ/2); the ram's stroke H = 2·l_CD·sin(ψ/2) gives the bar (None without H).

    >>> [round(x, 9) for x in guide_bar_from_K(100.0, math.radians(60), 100.0)]
    [50.0, 100.0]
    """
    s = math.sin(theta / 2.0)
    return d * s, None if H is None else H / (2.0 * s)


def slider_crank_from_K(H: float, e: float, theta: float) -> tuple[complex, float, float] | None:
    """(A, AC₁, AC₂) of the slider-crank with stroke H, offset e ≥ 0 and θ > 0, the slider's limits
    at 0 and H on the x axis: A at height e on the circle of radius H/(2 sin θ) about
    (H/2, H/(2 tan θ)), behind C₁; None where there is none or the crank does not turn fully.

    >>> A, ac1, ac2 = slider_crank_from_K(50.0, 10.0, math.radians(36))
    >>> round((ac2 - ac1) / 2, 6), round((ac1 + ac2) / 2, 6)
    (23.318878, 37.341945)
    """
    R, h = H / (2.0 * math.sin(theta)), H / (2.0 * math.tan(theta))
    disc = R * R - (e - h) ** 2
    if disc < 0.0:
        return None
    A = complex(H / 2.0 - math.sqrt(disc), e)
    if not A.real < -NO_CRANK * H:  # behind C₁, not on it
        return None
    ac1, ac2 = abs(A), abs(A - H)
    a, b = (ac2 - ac1) / 2.0, (ac1 + ac2) / 2.0
    if a <= NO_CRANK * b or a + e >= b:
        return None
    return A, ac1, ac2
