"""Closed-form efficiency and self-locking: inclined plane, screw threads, the wedge, machine chains.

The textbook's trigonometric answers, written out so that they can check the force polygons of
:mod:`graphmech.methods.efficiency` (which intersect lines in a drawing): nothing here imports
``graphmech.construction``, ``graphmech.methods`` or ``graphmech.geometry``.

Conventions
-----------
φ = arctan f is the friction angle; a V (triangular) thread of half-angle β has the equivalent
friction angle φv = arctan(f / cos β). "forward" is the stroke in which the applied force F
drives and the load Q resists (raising a load, tightening a nut, pushing the wedge in);
"reverse" the stroke in which Q drives and F is the force that holds it back (lowering,
loosening, the wedge pushed back). The efficiency is η = (ideal driving force) / (actual
driving force): forward η = F0/F, reverse η = F/F0 (the ideal F0 is the same both ways).
η ≤ 0 in the reverse stroke is self-locking: F must pull the other way to move at all.
Angles in rad, forces in N, moments in N·m.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, Sequence

from graphmech.errors import OutOfDomain

Direction = Literal["forward", "reverse"]


def _sign(direction: Direction) -> float:
    """+1 forward, −1 reverse: reversing the motion turns every total reaction the other way by φ."""
    if direction not in ("forward", "reverse"):
        raise OutOfDomain(f"direction must be 'forward' or 'reverse', not {direction!r}")
    return 1.0 if direction == "forward" else -1.0


# ---------------------------------------------------------------------------- inclined plane


def incline_force(Q: float, alpha: float, phi: float, direction: Direction, push: str = "horizontal") -> float:
    """The force F on a block of weight Q on an incline of angle α, friction angle φ.

    Parameters
    ----------
    Q : float
        The load (weight), N, vertical.
    alpha : float
        The incline's angle to the horizontal, rad.
    phi : float
        The friction angle, rad.
    direction : {"forward", "reverse"}
        Forward: F pushes the block up; reverse: the block slides down and F holds it.
    push : {"horizontal", "parallel"}
        F horizontal (the unrolled screw) or parallel to the incline.

    Returns
    -------
    float
        F in N (forward: Q·tan(α + φ); reverse: Q·tan(α − φ) for a horizontal F;
        Q·sin(α ± φ)/cos φ for a parallel one). Negative in the reverse stroke means
        self-locking.

    Examples
    --------
    >>> round(incline_force(100.0, math.radians(30), 0.0, "forward"), 9)
    57.735026919
    """
    s = _sign(direction)
    if push == "horizontal":
        return Q * math.tan(alpha + s * phi)
    return Q * math.sin(alpha + s * phi) / math.cos(phi)


def incline_efficiency(alpha: float, phi: float, direction: Direction, push: str = "horizontal") -> float:
    """η of the incline: tan α / tan(α + φ) forward, tan(α − φ)/tan α reverse (horizontal F);
    sin α·cos φ / sin(α + φ) and sin(α − φ)/(sin α·cos φ) for F parallel to the incline.

    >>> round(incline_efficiency(math.radians(10), math.atan(0.1), "forward"), 12)
    0.626858296109
    """
    if push == "horizontal":
        if direction == "forward":
            return math.tan(alpha) / math.tan(alpha + phi)
        return math.tan(alpha - phi) / math.tan(alpha)
    if direction == "forward":
        return math.sin(alpha) * math.cos(phi) / math.sin(alpha + phi)
    return math.sin(alpha - phi) / (math.sin(alpha) * math.cos(phi))


def incline_reaction(Q: float, alpha: float, phi: float, direction: Direction, push: str = "horizontal") -> float:
    """|R|, the incline's total reaction on the block, N: Q/cos(α ± φ) for a horizontal F,
    Q·cos α / cos φ ... more precisely Q·cos(α)/cos(φ)·(1) for a parallel F (its normal part Q cos α).

    >>> round(incline_reaction(100.0, 0.0, 0.0, "forward"), 9)
    100.0
    """
    s = _sign(direction)
    if push == "horizontal":
        return Q / math.cos(alpha + s * phi)
    return Q * math.cos(alpha) / math.cos(phi)


# ---------------------------------------------------------------------------- screws


def equivalent_friction_angle(f: float, half_angle: float = 0.0) -> float:
    """φv = arctan(f / cos β): a V thread of half-angle β (0 for a square thread), rad.

    >>> round(math.degrees(equivalent_friction_angle(0.1, math.radians(30))), 9)
    6.586775554
    """
    return math.atan(f / math.cos(half_angle))


def lead_angle(lead: float, d2: float) -> float:
    """ψ = arctan(L / (π d2)), rad, for a lead L = n·P and a pitch (mean) diameter d2.

    >>> round(math.degrees(lead_angle(2.5e-3, 18.376e-3)), 9)
    2.479650796
    """
    return math.atan(lead / (math.pi * d2))


def screw_torque(Q: float, d2: float, psi: float, phi_v: float, direction: Direction) -> float:
    """The thread torque M = Q·d2/2·tan(ψ ± φv), N·m (forward: raising/tightening; reverse:
    the torque that holds the load while it lowers — negative when the screw self-locks)."""
    return Q * d2 / 2.0 * math.tan(psi + _sign(direction) * phi_v)


def screw_efficiency(psi: float, phi_v: float, direction: Direction) -> float:
    """η = tan ψ / tan(ψ + φv) raising, tan(ψ − φv)/tan ψ lowering."""
    return incline_efficiency(psi, phi_v, direction)


def self_locking_efficiency_bound(phi_v: float) -> float:
    """The largest raising efficiency of a screw that self-locks (ψ ≤ φv): at ψ = φv,
    η = tan φv / tan 2φv = (1 − tan² φv)/2 < 1/2.

    >>> self_locking_efficiency_bound(math.atan(0.1))
    0.495
    """
    t = math.tan(phi_v)
    return (1.0 - t * t) / 2.0


# ---------------------------------------------------------------------------- the wedge


@dataclass(frozen=True)
class WedgeForces:
    """The wedge's forces, N: the force F on slider 1 and the total reactions R12 (1 on 2),
    R32 (frame on 2), R31 (frame on 1), magnitudes."""

    F: float
    R12: float
    R32: float
    R31: float


def _angle_between(a: float, b: float) -> float:
    """|sin| of the angle between two directions given as angles, as a sine (sign kept)."""
    return math.sin(b - a)


def wedge_forces(Q: float, gamma: float, beta: float, phi: float, direction: Direction) -> WedgeForces:
    """The reconstructed wedge of problem F1430 by the sine rule, triangle by triangle.

    Slider 2 slides on a horizontal guide against the resistance Q (acting towards −x); the face
    between sliders 1 and 2 is inclined at γ to that guide; slider 1 slides on a frame guide at
    β below the horizontal on the other side of the face (γ + β between face and guide 1) and is
    pushed along it by F. Each total reaction makes the angle φ with its normal, turned against
    the sliding velocity; the side each contact bears on is that of the frictionless solution,
    corrected if friction reverses it.

    Notes
    -----
    Directions as angles from +x (rad): guide 2 at 0, the face at γ, guide 1 at −β. Velocities
    (forward: slider 1 moves down along −β): slider 2 moves +x, slider 2 relative to 1 slides up
    the face. In the triangle (Q, R12, R32) the sine rule gives
    ``R12 = Q·sin(Q, R32)/sin(R12, R32)`` and in (F, R21, R31) ``F = R12·sin(R21, R31)/sin(F, R31)``.
    With γ + β > 90° both frictional turns add up: F = Q·sin(γ + β − 2φ)/sin(γ − 2φ) (the
    book's formula, forward); below 90° guide 1 bears on the other side and the turns of R21 and
    R31 cancel: F = Q·sin(γ + β)/sin(γ − 2φ).

    Examples
    --------
    >>> w = wedge_forces(1000.0, math.radians(60), math.radians(60), math.atan(0.15), "forward")
    >>> round(w.F, 6)
    1430.700422
    """
    s = _sign(direction)
    # slider 2: Q along 180°; R32 near +90° (the guide pushes up: Q's triangle decides), turned
    # against slider 2's velocity (+x forward): towards −x, i.e. +φ; R12 near the face normal
    # γ + 180° (slider 1 pushes slider 2 right and down), turned against 2's sliding relative to 1.
    # 2 relative to 1 moves along the face towards +γ forward: friction on 2 points along γ+180°.
    a_Q = math.pi
    a_R32 = math.pi / 2 + s * phi
    a_R12 = gamma - math.pi / 2 - s * phi
    R12 = Q * _angle_between(a_Q, a_R32) / _angle_between(a_R32, a_R12)
    R32 = Q * _angle_between(a_R12, a_Q) / _angle_between(a_R32, a_R12)
    # slider 1: R21 = −R12 along a_R12 + π; F along −β (forward push); R31 normal to guide 1:
    # guide 1 at −β, its normal (90° − β) when the frame pushes slider 1 up (γ + β > 90°), else
    # (−90° − β); turned against slider 1's velocity (down along −β forward).
    a_R21 = a_R12 + math.pi
    a_F = -beta
    up = math.cos(gamma + beta) < 0.0  # which side of guide 1 bears (frictionless R31's sense)
    n31 = math.pi / 2 - beta if up else -math.pi / 2 - beta
    turn = s * phi if up else -s * phi  # against −β motion: towards +β direction (up-left)
    a_R31 = n31 + turn
    F = R12 * math.sin(a_R21 - a_R31) / math.sin(a_R31 - a_F)
    R31 = R12 * math.sin(a_F - a_R21) / math.sin(a_R31 - a_F)
    return WedgeForces(F, abs(R12), abs(R32), abs(R31))


def wedge_ideal_force(Q: float, gamma: float, beta: float) -> float:
    """F0 = Q·sin(γ + β)/sin γ, the frictionless force."""
    return Q * math.sin(gamma + beta) / math.sin(gamma)


# ---------------------------------------------------------------------------- the wedge clamp


def wedge_clamp_force(Q: float, alpha: float, phi1: float, phi2: float, direction: Direction) -> float:
    """The force F along face 1 on a wedge of angle α whose face 2 bears the clamping force Q
    (the body's total reaction, 000 效率 2): the triangle (F, R1, R2 = Q) by the sine rule.

    F ∥ face 1 makes 90° ± φ1 with R1 and 90° − α ∓ φ2 with R2; hence
    F = Q·sin(α ± (φ1 + φ2))/cos φ1 (forward: F drives the wedge in; reverse: the clamp drives it
    out and F holds it — the book's R23 = P·cos φ/sin(α − 2φ) turned round). Frictionless:
    F0 = Q·sin α.

    >>> round(wedge_clamp_force(1000.0, math.radians(10), math.atan(0.1), math.atan(0.1), "reverse"), 9)
    -24.925537048
    """
    return Q * math.sin(alpha + _sign(direction) * (phi1 + phi2)) / math.cos(phi1)


def wedge_clamp_reaction(Q: float, alpha: float, phi1: float, phi2: float, direction: Direction) -> float:
    """R1, face 1's total reaction on the clamp's wedge: Q·cos(α ± φ2)/cos φ1 (its normal part
    balances R2's, Q·cos(α ± φ2)).

    >>> round(wedge_clamp_reaction(1000.0, math.radians(60), 0.0, 0.0, "forward"), 9)
    500.0
    """
    return Q * math.cos(alpha + _sign(direction) * phi2) / math.cos(phi1)


def wedge_clamp_locking(phi1: float, phi2: float) -> float:
    """The clamp's self-locking limit on the wedge angle α, rad: the reverse stroke locks for
    α ≤ φ1 + φ2 (the book's α − 2φ ≤ 0). The forward stroke never locks: F would have to lie
    along R1, which needs φ1 = 90°.

    >>> round(math.degrees(wedge_clamp_locking(math.atan(0.15), 0.0)), 9)
    8.53076561
    """
    return phi1 + phi2


# ---------------------------------------------------------------------------- the wedge buffer


def buffer_force(Q: float, alpha: float, phi: float, direction: Direction) -> float:
    """P on the buffer's driving wedge 1 against the spring Q on wedge 2 (000 效率 3): the face
    between them at α to the spring's line, the guides frictionless: P = Q·cot(α ∓ φ) (forward:
    P pushes the wedges apart; reverse: the spring pushes them back and P holds); P0 = Q·cot α.

    >>> round(buffer_force(1000.0, math.radians(45), 0.0, "forward"), 9)
    1000.0
    """
    return Q / math.tan(alpha - _sign(direction) * phi)


def buffer_reaction(Q: float, alpha: float, phi: float, direction: Direction) -> float:
    """R12, wedge 1's total reaction on wedge 2: Q/sin(α ∓ φ) (its part along the spring's line is Q).

    >>> round(buffer_reaction(1000.0, math.radians(30), 0.0, "reverse"), 9)
    2000.0
    """
    return Q / math.sin(alpha - _sign(direction) * phi)


def buffer_locking(phi: float) -> tuple[float, float]:
    """The buffer's self-locking limits on the face angle α, rad: the forward stroke locks for
    α ≤ φ, the reverse one for α ≥ 90° − φ; neither locks for φ < α < 90° − φ.

    >>> [round(math.degrees(a), 9) for a in buffer_locking(math.radians(10))]
    [10.0, 80.0]
    """
    return phi, math.pi / 2 - phi


def buffer_locking_coefficients(alpha: float) -> tuple[float, float]:
    """The same limits as friction coefficients for a given α: the forward stroke locks for
    f ≥ tan α, the reverse one for f ≥ cot α.

    >>> [round(x, 12) for x in buffer_locking_coefficients(math.radians(45))]
    [1.0, 1.0]
    """
    return math.tan(alpha), 1.0 / math.tan(alpha)


# ---------------------------------------------------------------------------- a screw's collar and drive


def annulus_friction_radius(d0: float, dw: float) -> float:
    """The exact friction radius of a bearing annulus under uniform pressure, m:
    (2/3)(R³ − r³)/(R² − r²) = (dw³ − d0³)/(3(dw² − d0²)) — above the mean radius (d0 + dw)/4.

    >>> round(annulus_friction_radius(9e-3, 11.5e-3) * 1e3, 9)
    5.150406504
    """
    return (dw ** 3 - d0 ** 3) / (3.0 * (dw ** 2 - d0 ** 2))


def tightening_torque(Q: float, d2: float, psi: float, phi_v: float, f_c: float, r_c: float) -> float:
    """T = Q·[d2/2·tan(ψ + φv) + f_c·r_c], N·m: the thread's torque and the collar's friction.

    >>> round(tightening_torque(25500.0, 7.188e-3, math.radians(3.0), math.radians(6.0), 0.12, 5.125e-3), 6)
    30.197959
    """
    return Q * (d2 / 2.0 * math.tan(psi + phi_v) + f_c * r_c)


def bolt_force_from_torque(T: float, d2: float, psi: float, phi_v: float, f_c: float, r_c: float) -> float:
    """F_a = T/[d2/2·tan(ψ + φv) + f_c·r_c], N: the axial force a wrench torque T produces.

    >>> round(bolt_force_from_torque(30.0, 7.188e-3, math.atan(1.25e-3 / (math.pi * 7.188e-3)), math.atan(0.1),
    ...                              0.12, 5.125e-3), 6)
    25500.412449
    """
    return T / (d2 / 2.0 * math.tan(psi + phi_v) + f_c * r_c)


def screw_drive_power(Q: float, v: float, psi: float, phi_v: float) -> float:
    """P = Q·v/η with η = tan ψ/tan(ψ + φv), W: the power that lifts Q at the speed v.

    >>> round(screw_drive_power(1e5, 0.8 / 60.0, math.atan(0.04 / (math.pi * 0.065)), math.atan(0.1)), 6)
    2054.251028
    """
    return Q * v * math.tan(psi + phi_v) / math.tan(psi)


def screw_speed(v: float, lead: float) -> float:
    """n = v/L, the screw's speed in rev/s for a lift speed v and a lead L = n·P.

    >>> round(screw_speed(0.8 / 60.0, 0.04) * 60.0, 12)
    20.0
    """
    return v / lead


# ---------------------------------------------------------------------------- machine chains


def series_efficiency(etas: Sequence[float]) -> float:
    """η = η1·η2·…·ηk of machines in series.

    >>> round(series_efficiency([0.95, 0.97, 0.97, 0.9]), 10)
    0.8044695
    """
    out = 1.0
    for e in etas:
        out *= e
    return out


def parallel_efficiency(shares: Sequence[float], etas: Sequence[float]) -> float:
    """η = Σ Nᵢηᵢ / Σ Nᵢ of machines in parallel that share the input power in the ratios Nᵢ.

    >>> round(parallel_efficiency([0.5, 0.5], [0.9, 0.8]), 12)
    0.85
    """
    return sum(s * e for s, e in zip(shares, etas)) / sum(shares)


def efficiency(direction: Direction, ideal: float, actual: float) -> float:
    """η from the forces: F0/F forward, F/F0 reverse."""
    return ideal / actual if direction == "forward" else actual / ideal


__all__ = [
    "Direction", "WedgeForces", "annulus_friction_radius", "bolt_force_from_torque", "buffer_force",
    "buffer_locking", "buffer_locking_coefficients", "buffer_reaction", "efficiency", "equivalent_friction_angle",
    "incline_efficiency", "incline_force", "incline_reaction", "lead_angle", "parallel_efficiency",
    "screw_drive_power", "screw_efficiency", "screw_speed", "screw_torque", "self_locking_efficiency_bound",
    "series_efficiency", "tightening_torque", "wedge_clamp_force", "wedge_clamp_locking", "wedge_clamp_reaction",
    "wedge_forces", "wedge_ideal_force",
]
