"""The exact follower motion of a disc cam given by its profile: an eccentric circular disc, in
closed form.

The independent reference for :mod:`graphmech.methods.cam_analysis` (the book's inversion drawn
with compass and straightedge): nothing here is taken from ``graphmech.methods``,
``graphmech.construction`` or ``graphmech.geometry``.

Notes
-----
The frames are those of :mod:`graphmech.exact.cam`. Turning the cam by rot·δ carries the disc's
centre C to C_f(δ) = R(rot·δ)·C in the fixed (follower) frame; write θ(δ) = β + rot·δ, β the polar
angle of C, c = |OC|, ρ the pitch radius (R + r_r, or R), C_f′ = rot·J·C_f.

**Translating follower** (axis x = e, along +y). Knife or roller: the follower point is the upper
meet of x = e with the pitch circle, y = c·sin θ + √(ρ² − (e − c·cos θ)²); a flat face ⟂ the axis
rests on the disc's highest point, y = c·sin θ + R. The pitch curve lies between the circles of
radius ρ − c and ρ + c about O and touches each once a turn, so the lowest and highest positions
are y = √((ρ ∓ c)² − e²) (flat face: R ∓ c): s = y − √((ρ − c)² − e²), h = √((ρ + c)² − e²) −
√((ρ − c)² − e²) (2c for e = 0 or a flat face).

**Oscillating follower** (pivot A = (a, 0), B = A + l·u(ψ), u = (−cos ψ, σ·sin ψ), σ as in
:mod:`graphmech.exact.cam`). With D = C_f − A, d = |D| and ψ_D = atan2(σ·D_y, −D_x) (so that
u(ψ_D) = D/d), u(ψ)·D = d·cos(ψ − ψ_D). Roller or knife: |B − C_f| = ρ gives
ψ = ψ_D + acos((l² + d² − ρ²)/(2·l·d)). Flat face (the line through A along u, the disc on O's
side): its distance from C_f, d·sin(ψ − ψ_D), is R: ψ = ψ_D + asin(R/d). |OB| grows with ψ, so the
lowest and highest ψ are those of the circles ρ ∓ c: cos ψ = (a² + l² − (ρ ∓ c)²)/(2al), or
sin ψ = (R ∓ c)/a for a flat face; the displacement is ψ − ψ_min, the swing ψ_max − ψ_min.

**Velocity** by implicit differentiation of the contact condition F(q, δ) = 0 (q = y or ψ):
dq/dδ = −F_δ/F_q, times ω. Roller: F = |B − C_f|² − ρ², so dq/dδ = (B − C_f)·C_f′ / ((B − C_f)·∂B/∂q);
flat face: translating dy/dδ = C_f′·(0, 1), oscillating dψ/dδ = −(C_f′ × u)/((C_f − A) × u_ψ).
Positive is the rise (y or ψ growing).

**Pressure angle** between the contact normal B − C_f and the follower point's motion m ((0, 1),
or u_ψ = (sin ψ, σ·cos ψ) ⟂ the arm): sin α = |(B − C_f) × m|/ρ; 0 for a flat face.

**A contact** at polar angle φ about O: the ray meets the disc at P = t·w, w = (cos φ, sin φ),
t = C·w + √((C·w)² − c² + R²); its normal n = (P − C)/R, its pitch point P + r_r·n. The cam angle
at which the follower touches there is where the inverted follower passes through it: a
translating axis x = e through the pitch point, a flat face with its normal along n, the inverted
pivot (on the circle a about O) an arm l from the pitch point, or on the tangent at P. Of the two
candidates the one whose contact point (this module's, at that δ) is P is taken; none is a point
the follower never touches.
"""
from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import NoSolution
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import GivenCam

__all__ = ["contact_delta", "contact_point", "displacement", "lowest_highest", "position",
           "pressure_angle", "rate", "rise"]

_TWO_PI = 2.0 * math.pi
#: A contact found at δ whose contact point lies further than this (relative to R) from the given
#: point is not a contact there.
_SAME_POINT_REL = 1e-9


def _centre(cam: GivenCam, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """C_f = (x, y) and C_f′ = dC_f/dδ in the fixed frame."""
    cx, cy = cam.profile.centre
    c, beta = math.hypot(cx, cy), math.atan2(cy, cx)
    theta = beta + cam.rotation * delta
    x, y = c * np.cos(theta), c * np.sin(theta)
    return x, y, -cam.rotation * y, cam.rotation * x


def _sigma(f: OscillatingFollower, rot: int) -> int:
    return rot if f.sense == "opposite" else -rot


def position(cam: GivenCam, delta: ArrayLike) -> np.ndarray:
    """The follower's position at cam angle δ: the ordinate y of its point (m; a flat face's
    height) for a translating follower, ψ = ∠OAB (rad; the face's angle) for a rocker."""
    d = np.asarray(delta, dtype=float)
    x, y, _, _ = _centre(cam, d)
    f, rho, big_r = cam.follower, cam.pitch_radius(), cam.profile.radius
    if isinstance(f, TranslatingFollower):
        if f.contact == "flat":
            return np.asarray(y + big_r)
        return np.asarray(y + np.sqrt(rho * rho - (f.offset - x) ** 2))
    dx, dy = x - f.pivot_distance, y
    s = _sigma(f, cam.rotation)
    dd = np.hypot(dx, dy)
    psi_d = np.arctan2(s * dy, -dx)
    if f.contact == "flat":
        return np.asarray(psi_d + np.arcsin(big_r / dd))
    l = f.arm
    return np.asarray(psi_d + np.arccos((l * l + dd * dd - rho * rho) / (2.0 * l * dd)))


def lowest_highest(cam: GivenCam) -> tuple[float, float]:
    """The follower's lowest and highest positions over a turn (module Notes), y in m or ψ in rad."""
    f, rho, c = cam.follower, cam.pitch_radius(), cam.profile.eccentricity
    if isinstance(f, TranslatingFollower):
        if f.contact == "flat":
            return rho - c, rho + c
        return math.sqrt((rho - c) ** 2 - f.offset ** 2), math.sqrt((rho + c) ** 2 - f.offset ** 2)
    a, l = f.pivot_distance, f.arm
    if f.contact == "flat":
        return math.asin((rho - c) / a), math.asin((rho + c) / a)
    return tuple(math.acos((a * a + l * l - r * r) / (2.0 * a * l)) for r in (rho - c, rho + c))  # type: ignore[return-value]


def displacement(cam: GivenCam, delta: ArrayLike) -> np.ndarray:
    """s(δ) from the lowest position (m), or the rocker's ψ(δ) − ψ_min (rad)."""
    return position(cam, delta) - lowest_highest(cam)[0]


def rise(cam: GivenCam) -> float:
    """The stroke h (m) or the rocker's swing (rad)."""
    lo, hi = lowest_highest(cam)
    return hi - lo


def _follower_point(cam: GivenCam, delta: np.ndarray, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The follower point B (roller centre, knife tip) in the fixed frame at position q."""
    f = cam.follower
    if isinstance(f, TranslatingFollower):
        return f.offset + 0.0 * q, q
    s = _sigma(f, cam.rotation)
    return f.pivot_distance - f.arm * np.cos(q), s * f.arm * np.sin(q)


def rate(cam: GivenCam, delta: ArrayLike) -> np.ndarray:
    """dq/dδ, q = y (m/rad) or ψ (rad/rad), by implicit differentiation (module Notes); × ω is
    the follower's velocity, positive while it rises."""
    d = np.asarray(delta, dtype=float)
    x, y, xp, yp = _centre(cam, d)
    f = cam.follower
    q = position(cam, d)
    if f.contact == "flat":
        if isinstance(f, TranslatingFollower):
            return np.asarray(yp)
        s = _sigma(f, cam.rotation)
        ux, uy = -np.cos(q), s * np.sin(q)
        upx, upy = np.sin(q), s * np.cos(q)
        return np.asarray(-(xp * uy - yp * ux) / ((x - f.pivot_distance) * upy - y * upx))
    bx, by = _follower_point(cam, d, q)
    nx, ny = bx - x, by - y
    if isinstance(f, TranslatingFollower):
        dbx, dby = 0.0 * q, 1.0 + 0.0 * q
    else:
        s = _sigma(f, cam.rotation)
        dbx, dby = f.arm * np.sin(q), s * f.arm * np.cos(q)
    return np.asarray((nx * xp + ny * yp) / (nx * dbx + ny * dby))


def pressure_angle(cam: GivenCam, delta: ArrayLike) -> np.ndarray:
    """|α| (rad) between the contact normal and the follower point's motion; 0 for a flat face."""
    d = np.asarray(delta, dtype=float)
    f = cam.follower
    if f.contact == "flat":
        return np.zeros_like(d)
    x, y, _, _ = _centre(cam, d)
    q = position(cam, d)
    bx, by = _follower_point(cam, d, q)
    nx, ny = bx - x, by - y
    if isinstance(f, TranslatingFollower):
        mx, my = 0.0 * q, 1.0 + 0.0 * q
    else:
        s = _sigma(f, cam.rotation)
        mx, my = np.sin(q), s * np.cos(q)
    return np.asarray(np.arcsin(np.minimum(np.abs(nx * my - ny * mx) / cam.pitch_radius(), 1.0)))


def contact_point(cam: GivenCam, delta: float) -> tuple[float, float]:
    """The point of the working profile the follower touches at δ, in the cam frame (m)."""
    d = np.asarray(float(delta))
    x, y, _, _ = _centre(cam, d)
    f, big_r = cam.follower, cam.profile.radius
    q = position(cam, d)
    if f.contact == "flat":
        if isinstance(f, TranslatingFollower):
            px, py = x, y + big_r
        else:
            s = _sigma(f, cam.rotation)
            gx, gy = -np.sin(q), -s * np.cos(q)  # −σ·(u_y, −u_x): the face's unit normal towards O
            px, py = x - big_r * gx, y - big_r * gy
    else:
        bx, by = _follower_point(cam, d, q)
        k = big_r / cam.pitch_radius()
        px, py = x + k * (bx - x), y + k * (by - y)
    back = -cam.rotation * float(delta)  # the fixed frame turned back into the cam frame
    cb, sb = math.cos(back), math.sin(back)
    return float(cb * px - sb * py), float(sb * px + cb * py)


def _on_disc(cam: GivenCam, polar: float) -> tuple[float, float, float, float]:
    """The disc's point at polar angle φ about O and its outward unit normal."""
    cx, cy = cam.profile.centre
    big_r = cam.profile.radius
    wx, wy = math.cos(polar), math.sin(polar)
    cw = cx * wx + cy * wy
    t = cw + math.sqrt(cw * cw - (cx * cx + cy * cy) + big_r * big_r)
    px, py = t * wx, t * wy
    return px, py, (px - cx) / big_r, (py - cy) / big_r


def contact_delta(cam: GivenCam, polar: float, name: str = "") -> float:
    """The cam angle δ ∈ [0, 2π) at which the follower touches the profile's point at polar
    angle ``polar`` (module Notes); NoSolution when it never touches there."""
    px, py, nx, ny = _on_disc(cam, polar)
    f, rot = cam.follower, cam.rotation
    r = f.roller_radius if f.contact == "roller" else 0.0
    bx, by = px + r * nx, py + r * ny
    b, phi_b = math.hypot(bx, by), math.atan2(by, bx)
    turns: list[float] = []  # the inverted follower's angle −rot·δ, candidates
    if isinstance(f, TranslatingFollower):
        if f.contact == "flat":
            turns = [math.atan2(ny, nx) - math.pi / 2.0]
        elif abs(f.offset) <= b:
            a0 = math.acos(f.offset / b)  # R(rot·δ)·B has x = e, y > 0
            turns = [phi_b - a0, phi_b + a0]
    elif f.contact == "flat":
        tx, ty = -ny, nx  # the tangent at P; A_δ = P + t·(tx, ty) with |A_δ| = a
        pt = px * tx + py * ty
        disc = pt * pt - (px * px + py * py) + f.pivot_distance ** 2
        if disc >= 0.0:
            for t in (-pt + math.sqrt(disc), -pt - math.sqrt(disc)):
                turns.append(math.atan2(py + t * ty, px + t * tx))
    else:
        a, l = f.pivot_distance, f.arm
        cos_g = (a * a + b * b - l * l) / (2.0 * a * b)
        if abs(cos_g) <= 1.0:
            g = math.acos(cos_g)
            turns = [phi_b - g, phi_b + g]
    size = cam.profile.radius
    for turn in turns:
        delta = (-rot * turn) % _TWO_PI
        if delta >= _TWO_PI:  # −1e-17 % 2π is 2π
            delta = 0.0
        qx, qy = contact_point(cam, delta)
        if math.hypot(qx - px, qy - py) <= _SAME_POINT_REL * size:
            return delta
    raise NoSolution(f"the follower never touches the profile at {name or 'the contact'} (polar angle "
                     f"{math.degrees(polar):.6g}° about O): that point of the disc faces away from it")
