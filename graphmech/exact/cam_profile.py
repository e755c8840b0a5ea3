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
from functools import lru_cache
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import NoSolution
from graphmech.minimum import fminbound
from graphmech.roots import brentq
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import GivenCam, PointsProfile

__all__ = ["contact_delta", "contact_point", "displacement", "lowest_highest", "max_pressure_angle", "position",
           "pressure_angle", "radii", "rate", "rise"]

_TWO_PI = 2.0 * math.pi
#: A contact found at δ whose contact point lies further than this (relative to R) from the given
#: point is not a contact there.
_SAME_POINT_REL = 1e-9


def _centre(cam: GivenCam, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """C_f = (x, y) and C_f′ = dC_f/dδ in the fixed frame."""
    cx, cy = cam.disc.centre
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
    if isinstance(cam.profile, PointsProfile):
        return np.asarray(np.vectorize(lambda x: _spline_state(cam, float(x))[0], otypes=[float])(d))
    x, y, _, _ = _centre(cam, d)
    f, rho, big_r = cam.follower, cam.pitch_radius(), cam.disc.radius
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


def radii(cam: GivenCam) -> tuple[float, float]:
    """r0 and r_max: the least and greatest radius about O of the pitch curve (knife, roller) or
    of the profile (flat face); a disc's ρ ∓ |OC|."""
    if isinstance(cam.profile, PointsProfile):
        return _spline_radii(cam)
    rho, c = cam.pitch_radius(), cam.disc.eccentricity
    return rho - c, rho + c


def lowest_highest(cam: GivenCam) -> tuple[float, float]:
    """The follower's lowest and highest positions over a turn, resting on the circles r0 and
    r_max about O (module Notes), y in m or ψ in rad."""
    f = cam.follower
    r_lo, r_hi = radii(cam)
    if isinstance(f, TranslatingFollower):
        if f.contact == "flat":
            return r_lo, r_hi
        return math.sqrt(r_lo ** 2 - f.offset ** 2), math.sqrt(r_hi ** 2 - f.offset ** 2)
    a, l = f.pivot_distance, f.arm
    if f.contact == "flat":
        return math.asin(r_lo / a), math.asin(r_hi / a)
    return (math.acos((a * a + l * l - r_lo * r_lo) / (2.0 * a * l)),
            math.acos((a * a + l * l - r_hi * r_hi) / (2.0 * a * l)))


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
    if isinstance(cam.profile, PointsProfile):
        return np.asarray(np.vectorize(lambda x: _spline_rate(cam, float(x)), otypes=[float])(d))
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
    if isinstance(cam.profile, PointsProfile):
        return np.asarray(np.vectorize(lambda x: _spline_alpha(cam, float(x)), otypes=[float])(d))
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
    if isinstance(cam.profile, PointsProfile):
        profile = cam.profile
        p = profile.at(np.array([_contact_t(cam, float(delta))]))[0]
        return float(p[0]), float(p[1])
    d = np.asarray(float(delta))
    x, y, _, _ = _centre(cam, d)
    f, big_r = cam.follower, cam.disc.radius
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
    """The profile's point at polar angle φ about O and its outward unit normal (a given profile:
    the root of p(t) × w = 0 with p·w > 0)."""
    if isinstance(cam.profile, PointsProfile):
        profile = cam.profile
        w = np.array([math.cos(polar), math.sin(polar)])

        w0, w1 = float(w[0]), float(w[1])

        def g(t: float) -> float:
            p0, p1 = profile.point(t)
            return p0 * w1 - p1 * w0

        grid = np.linspace(0.0, profile.length, _GRID + 1)
        pts = profile.at(grid)
        vals = pts[:, 0] * w[1] - pts[:, 1] * w[0]
        for k in np.flatnonzero((np.sign(vals[:-1]) != np.sign(vals[1:])) & (pts[:-1] @ w > 0)):
            t = grid[k] if vals[k] == 0.0 else brentq(g, grid[k], grid[k + 1], xtol=1e-15 * profile.length)
            p, n, _ = (v[0] for v in _frames(profile, [float(t)], 0.0))
            return float(p[0]), float(p[1]), float(n[0]), float(n[1])
        raise NoSolution(f"the ray at {math.degrees(polar):.6g}° misses the profile")  # pragma: no cover - O is inside
    cx, cy = cam.disc.centre
    big_r = cam.disc.radius
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
    size = cam.size
    for turn in turns:
        delta = (-rot * turn) % _TWO_PI
        if delta >= _TWO_PI:  # −1e-17 % 2π is 2π
            delta = 0.0
        qx, qy = contact_point(cam, delta)
        if math.hypot(qx - px, qy - py) <= _SAME_POINT_REL * size:
            return delta
    raise NoSolution(f"the follower never touches the profile at {name or 'the contact'} (polar angle "
                     f"{math.degrees(polar):.6g}° about O): that point of the cam faces away from it")


# ------------------------------------------------------------------ a profile given by points: root finding on the spline
#
# The profile is the periodic cubic spline p(t) of the model (counter-clockwise, convex, O inside),
# its outward normal n = (p′_y, −p′_x)/|p′| and pitch curve B = p + r_r·n. The inverted follower at
# δ (turned by T = −rot·δ about O) touches where one scalar condition g(t) = 0 holds, found by
# brentq between the sign changes of g on a grid of _GRID parameter values:
#
#   translating knife/roller  (B − Q) × d = 0, the upper root (n·d > 0);  Q = R(T)(e, 0), d = R(T)(0, 1)
#   translating flat face     n × d = 0 with n·d > 0
#   rocker roller/knife       |B − A|² − l² = 0, the root of larger ψ;   A = R(T)(a, 0)
#   rocker flat face          (p − A)·n = 0, the tangent of larger ψ
#
# (the choices that the disc's closed form makes). Back in the fixed frame the velocity follows from
# n·(v_follower − v_cam) = 0 at the contact, the cam's point moving at rot·ω·J·X: v = n·(rot·J·B)/(n·m)
# for a roller or knife (m its point's motion, (0, 1) or l·u_ψ), rot·X_x for a translating face, and
# dψ/dδ = −σ·rot·(n·J·X)/(n·J·(X − A)) for a rocker's face. The roots are found to 1e-15 of the
# profile's length: the values are exact to ~1e-12 relative (the spline itself is the given profile).

_GRID = 1024


def _frame(profile: PointsProfile, t: np.ndarray, r: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """p, n (outward unit normal) and B = p + r·n at t, each (len(t), 2)."""
    p, dp = profile.at(t), profile.at(t, 1)
    n = np.column_stack([dp[:, 1], -dp[:, 0]]) / np.hypot(dp[:, 0], dp[:, 1])[:, None]
    return p, n, p + r * n


def _frame1(profile: PointsProfile, t: float, r: float) -> tuple[float, float, float, float, float, float]:
    """:func:`_frame` at one t in scalar arithmetic, the same floats: (p_x, p_y, n_x, n_y, B_x, B_y).
    The root finders' inner loop (numpy's hypot, as the arrays take it: libm's, not Python's)."""
    p0, p1, d0, d1 = profile.point_and_slope(t)
    h = float(np.hypot(d0, d1))
    n0, n1 = d1 / h, -d0 / h
    return p0, p1, n0, n1, p0 + r * n0, p1 + r * n1


def _frames(profile: PointsProfile, ts: list[float], r: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`_frame` at a few t, by :func:`_frame1`: the same arrays without the cost of array
    arithmetic on a handful of values."""
    rows = np.array([_frame1(profile, t, r) for t in ts]).reshape(-1, 6)
    c = np.ascontiguousarray  # laid out as _frame's, so that products take the same path
    return c(rows[:, 0:2]), c(rows[:, 2:4]), c(rows[:, 4:6])


@lru_cache(maxsize=16)
def _grid_frame(profile: PointsProfile, r: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The grid of _GRID + 1 parameter values the roots are bracketed on, and :func:`_frame` there
    (the same for every cam angle: taken once per profile)."""
    grid = np.linspace(0.0, profile.length, _GRID + 1)
    return (grid, *_frame(profile, grid, r))


def _contact_t(cam: GivenCam, delta: float) -> float:
    """The spline parameter of the contact at cam angle δ (module section above)."""
    profile = cast(PointsProfile, cam.profile)
    f, r = cam.follower, cam.roller
    turn = -cam.rotation * delta
    c, s = math.cos(turn), math.sin(turn)
    d = np.array([-s, c])
    d0, d1 = -s, c

    def g(p0: Any, p1: Any, n0: Any, n1: Any, b0: Any, b1: Any) -> Any:
        """The contact's equation on the components of p, n and B: floats at one t, arrays on the
        grid (the same operations either way, so both give the same floats)."""
        if isinstance(f, TranslatingFollower):
            if f.contact == "flat":
                return n0 * d1 - n1 * d0
            return (b0 - f.offset * c) * d1 - (b1 - f.offset * s) * d0
        a0, a1 = f.pivot_distance * c, f.pivot_distance * s
        if f.contact == "flat":
            return (p0 - a0) * n0 + (p1 - a1) * n1
        e0, e1 = b0 - a0, b1 - a1
        return (e0 * e0 + e1 * e1) - f.arm ** 2

    def g1(t: float) -> float:
        return float(g(*_frame1(profile, t, r)))

    length = profile.length
    grid, p, n, b = _grid_frame(profile, r)
    vals = g(p[:, 0], p[:, 1], n[:, 0], n[:, 1], b[:, 0], b[:, 1])
    roots = []
    for k in np.flatnonzero(np.sign(vals[:-1]) != np.sign(vals[1:])):
        if vals[k] == 0.0:
            roots.append(float(grid[k]))
        else:
            roots.append(float(brentq(g1, float(grid[k]), float(grid[k + 1]),
                                      xtol=1e-15 * length, rtol=4 * np.finfo(float).eps)))
    if not roots:
        raise NoSolution(f"the follower does not reach the profile at δ = {math.degrees(delta):.6g}°")
    ts = np.array(roots)
    p, n, b = _frames(profile, roots, r)
    if isinstance(f, TranslatingFollower):
        up = n @ d
        return float(ts[int(np.argmax(np.where(up > 0, b @ d, -np.inf)))])
    x = p if f.contact == "flat" else b
    sig = _sigma(f, cam.rotation)
    rel = x - np.array([f.pivot_distance * c, f.pivot_distance * s])
    back_x, back_y = c * rel[:, 0] + s * rel[:, 1], -s * rel[:, 0] + c * rel[:, 1]
    return float(ts[int(np.argmax(np.arctan2(sig * back_y, -back_x)))])


def _spline_state(cam: GivenCam, delta: float) -> tuple[float, np.ndarray, np.ndarray, np.ndarray]:
    """(q, X, n, B) at δ in the fixed frame: the position, the contact point, its normal, the
    follower point."""
    profile = cast(PointsProfile, cam.profile)
    f = cam.follower
    t = _contact_t(cam, delta)
    p, n, b = (v[0] for v in _frames(profile, [t], cam.roller))
    rot = cam.rotation * delta  # back to the fixed frame
    m = np.array([[math.cos(rot), -math.sin(rot)], [math.sin(rot), math.cos(rot)]])
    p, n, b = m @ p, m @ n, m @ b
    if isinstance(f, TranslatingFollower):
        q = float(p[1]) if f.contact == "flat" else float(b[1])
    else:
        x = p if f.contact == "flat" else b
        q = math.atan2(_sigma(f, cam.rotation) * x[1], -(x[0] - f.pivot_distance))
    return q, p, n, b


@lru_cache(maxsize=16)  # asked again by every reading of the check's drawn profile (the same cam)
def _spline_radii(cam: GivenCam) -> tuple[float, float]:
    """The least and greatest radius about O of the pitch curve (knife, roller) or the profile
    (flat face): the roots of B·B′ = 0."""
    profile = cast(PointsProfile, cam.profile)
    r = 0.0 if cam.follower.contact == "flat" else cam.roller
    length = profile.length

    def radius(t: float) -> float:
        b0, b1 = _frame1(profile, t, r)[4:]
        return float(np.hypot(b0, b1))

    grid, _, _, b = _grid_frame(profile, r)
    rs = np.hypot(*b.T)
    out = []
    for pick in (np.argmin, np.argmax):
        k = int(pick(rs))
        lo, hi = grid[k] - grid[1], grid[k] + grid[1]  # the spline is periodic: t < 0 is fine
        sign = 1.0 if pick is np.argmin else -1.0
        _, fun = fminbound(lambda x: sign * radius(x), lo, hi, xatol=1e-14 * length)  # called here: no late binding
        out.append(min(float(rs[k]), fun) if sign > 0 else max(float(rs[k]), -fun))
    return out[0], out[1]


def _motion(cam: GivenCam, q: float) -> np.ndarray:
    """The direction in which the follower point moves as q grows, per unit q (fixed frame)."""
    f = cam.follower
    if isinstance(f, TranslatingFollower):
        return np.array([0.0, 1.0])
    s = _sigma(f, cam.rotation)
    return f.arm * np.array([math.sin(q), s * math.cos(q)])


def _spline_rate(cam: GivenCam, delta: float) -> float:
    q, x, n, b = _spline_state(cam, delta)
    f, rot = cam.follower, cam.rotation
    if f.contact == "flat":
        if isinstance(f, TranslatingFollower):
            return float(rot * x[0])
        s = _sigma(f, rot)
        jx, jxa = np.array([-x[1], x[0]]), np.array([-x[1], x[0] - f.pivot_distance])
        return float(-s * rot * (n @ jx) / (n @ jxa))
    jb = np.array([-b[1], b[0]])
    return float(rot * (n @ jb) / (n @ _motion(cam, q)))


def _spline_alpha(cam: GivenCam, delta: float) -> float:
    q, _, n, _ = _spline_state(cam, delta)
    m = _motion(cam, q)
    m = m / math.hypot(*m)
    return math.asin(min(abs(float(n[0] * m[1] - n[1] * m[0])), 1.0))


#: Samples of a turn bracketing the largest pressure angle before it is refined.
_ALPHA_SAMPLES = 360


@lru_cache(maxsize=16)  # asked again by every reading of the check's drawn profile (the same cam)
def max_pressure_angle(cam: GivenCam) -> tuple[float, float]:
    """The largest pressure angle over a turn and the cam angle where it occurs (rad): the
    largest of a turn's samples refined by a bounded search between its neighbours (α is smooth
    for a disc or a spline). An eccentric disc driving a translating knife or roller reaches
    asin((|e| + |OC|)/ρ), where C stands on the line ⟂ the axis."""
    d = np.linspace(0.0, _TWO_PI, _ALPHA_SAMPLES, endpoint=False)
    a = pressure_angle(cam, d)
    k = int(np.argmax(a))
    step = _TWO_PI / _ALPHA_SAMPLES
    x, fun = fminbound(lambda x: -float(pressure_angle(cam, x)), d[k] - step, d[k] + step, xatol=1e-12)
    if -fun >= float(a[k]):
        return -fun, x % _TWO_PI
    return float(a[k]), float(d[k])
