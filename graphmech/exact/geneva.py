"""The Geneva wheel (槽轮机构) and the differential screw (差动螺旋) in closed form: the
independent solution the constructions of :mod:`graphmech.methods.geneva` are checked against.

Geneva wheel, one pin, z radial slots, centre distance L between the dial (拨盘, turning at ω₁)
and the wheel; the slot is tangent to the pin's circle where the pin enters, so the dial's arm
and the wheel's radius to the entry point are at right angles:
R = L sin(π/z), S = L cos(π/z); the slot's depth h = L(sin(π/z) + cos(π/z) − 1) + r (r the pin's
radius), the locking arc's radius r_s = R − r − b (b the wheel's tip thickness); the motion
coefficient k = (z − 2)/(2z) (the share of a dial turn the wheel moves), so a rest t_j asks for a
dial period T = t_j/(1 − k). With λ = R/L and the dial's angle φ from the line of centres:
ω₂ = ω₁ λ(cos φ − λ)/(1 − 2λ cos φ + λ²), ε₂ = −ω₁² λ(1 − λ²) sin φ/(1 − 2λ cos φ + λ²)²
(ω₁ constant; positive ω₂ turns the wheel against the dial, as an external Geneva does).

Differential screw: link 1 turns in the frame through screw A (lead p_A) and in link 2 through
screw B (lead p_B); link 2 only slides. One turn of 1 moves 2 by p_A − p_B with both screws of
one hand, by p_A + p_B with opposite hands (a compound screw).
"""
from __future__ import annotations

import math

from graphmech.errors import OutOfDomain


def crank_radius(z: int, L: float) -> float:
    """R = L sin(π/z): the dial's arm to the pin centre."""
    return L * math.sin(math.pi / z)


def wheel_radius(z: int, L: float) -> float:
    """S = L cos(π/z): the wheel's radius to the slot's mouth (the pin's entry point)."""
    return L * math.cos(math.pi / z)


def slot_depth(z: int, L: float, r_pin: float) -> float:
    """h = L(sin(π/z) + cos(π/z) − 1) + r: from the mouth to the slot's bottom.

    >>> round(slot_depth(6, 0.3, 0.025), 12)
    0.134807621135
    """
    return L * (math.sin(math.pi / z) + math.cos(math.pi / z) - 1.0) + r_pin


def locking_radius(z: int, L: float, r_pin: float, b: float) -> float:
    """r_s = R − r − b: the locking arc of the dial (锁止弧)."""
    return L * math.sin(math.pi / z) - r_pin - b


def motion_coefficient(z: int) -> float:
    """k = (z − 2)/(2z), single pin."""
    return (z - 2) / (2 * z)


def period_from_rest(z: int, t_rest: float) -> float:
    """The dial's period T = t_j/(1 − k) = 2z·t_j/(z + 2)."""
    return 2 * z * t_rest / (z + 2)


def engaged_half_angle(z: int) -> float:
    """φ₁ = π/2 − π/z: the pin drives the wheel for |φ| ≤ φ₁."""
    return math.pi / 2 - math.pi / z


def _check_engaged(z: int, phi: float) -> None:
    if abs(phi) > engaged_half_angle(z) * (1 + 1e-12):
        raise OutOfDomain(f"the pin is out of the slot at φ = {math.degrees(phi):g}°: it drives the wheel for "
                          f"|φ| ≤ {math.degrees(engaged_half_angle(z)):g}°")


def wheel_omega(z: int, phi: float, omega1: float) -> float:
    """ω₂ = ω₁ λ(cos φ − λ)/(1 − 2λ cos φ + λ²), λ = sin(π/z)."""
    _check_engaged(z, phi)
    lam = math.sin(math.pi / z)
    return omega1 * lam * (math.cos(phi) - lam) / (1 - 2 * lam * math.cos(phi) + lam * lam)


def wheel_epsilon(z: int, phi: float, omega1: float) -> float:
    """ε₂ = dω₂/dt = −ω₁² λ(1 − λ²) sin φ/(1 − 2λ cos φ + λ²)² (ω₁ constant)."""
    _check_engaged(z, phi)
    lam = math.sin(math.pi / z)
    d = 1 - 2 * lam * math.cos(phi) + lam * lam
    return -omega1 * omega1 * lam * (1 - lam * lam) * math.sin(phi) / (d * d)


def wheel_omega_max(z: int, omega1: float) -> float:
    """ω₂ at φ = 0 (the pin on the line of centres): ω₁ λ/(1 − λ)."""
    lam = math.sin(math.pi / z)
    return omega1 * lam / (1 - lam)


def slide_velocity(z: int, L: float, phi: float, omega1: float) -> float:
    """The pin's speed along the slot: ω₁R sin(angle between the arm and the slot),
    = ω₁R·L sin φ/√(L² + R² − 2LR cos φ) in magnitude (zero at φ = 0, ω₁R at entry)."""
    _check_engaged(z, phi)
    R = L * math.sin(math.pi / z)
    return abs(omega1 * R * L * math.sin(phi)) / math.sqrt(L * L + R * R - 2 * L * R * math.cos(phi))


def coriolis(z: int, L: float, phi: float, omega1: float) -> float:
    """|a^k| = 2|ω₂|·v_slide of the pin relative to the slot."""
    return 2 * abs(wheel_omega(z, phi, omega1)) * slide_velocity(z, L, phi, omega1)


def screw_travel(p_A: float, p_B: float, same_hand: bool) -> float:
    """Link 2's travel per turn of link 1: p_A − p_B (same hands), p_A + p_B (opposite)."""
    return p_A - p_B if same_hand else p_A + p_B


def screw_leads(p_A: float, travel: float) -> tuple[tuple[float, bool], tuple[float, bool] | None]:
    """Screw B for a travel s = |travel| of link 2 per turn of link 1, both branches as
    (p_B, same hand as A): 2 moving against link 1's own advance, p_B = p_A + s of A's hand (the
    book's branch), or with it, p_B = |p_A − s| — of A's hand while s < p_A, of the other hand
    beyond (None where s = p_A: B would have no lead).

    >>> screw_leads(2.8, 0.2)
    ((3.0, True), (2.5999999999999996, True))
    >>> screw_leads(2.0, 5.0)
    ((7.0, True), (3.0, False))
    """
    s = abs(travel)
    other = None if s == p_A else (abs(p_A - s), s < p_A)
    return (p_A + s, True), other


__all__ = ["coriolis", "crank_radius", "engaged_half_angle", "locking_radius", "motion_coefficient",
           "period_from_rest", "screw_leads", "screw_travel", "slide_velocity", "slot_depth", "wheel_epsilon",
           "wheel_omega", "wheel_omega_max", "wheel_radius"]
