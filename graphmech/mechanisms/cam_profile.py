"""A disc cam given by its profile instead of its motion law (the reverse of inversion).

Everything is SI (m, rad, rad/s) and immutable. The frames are those of
:mod:`graphmech.mechanisms.cam`: the cam frame has the turning centre O at the origin and
coincides with the fixed (follower) frame at δ = 0, a translating follower moving along +y with
its axis at x = e, an oscillating follower pivoted at A = (a, 0). The profile is given in the cam
frame as it stands at δ = 0.

An eccentric circular disc (偏心圆盘) has radius R and its geometric centre C at ``centre``; its
eccentricity is |OC| < R (O lies inside the disc). A profile given by points (``PointsProfile``) is
the closed periodic cubic spline through them, parameterised by the chord length; it must be
convex and hold O inside, so that each follower position has one contact. A contact (E, F … of the book) is a point of
the working profile, given by its polar angle about O in the cam frame, or by the cam angle at
which the follower touches.
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from graphmech.mechanisms.cam import Follower


#: k!/(k − order)!, the factor of c[3−k]·s^(k−order) in the order-th derivative (scipy's prefactor).
_FACTORS = tuple(tuple(float(math.perm(k, order)) for k in range(4)) for order in range(4))


@dataclass(frozen=True)
class EccentricDisc:
    """A circular disc of radius R (m) whose geometric centre C = ``centre`` (m, cam frame at
    δ = 0) lies |OC| = e_c < R from the turning centre O."""

    radius: float
    centre: tuple[float, float]

    @property
    def eccentricity(self) -> float:
        """|OC|, m."""
        return math.hypot(*self.centre)


@dataclass(frozen=True)
class PointsProfile:
    """A cam's working profile through ``points`` (m, cam frame at δ = 0, in either sense, not
    closed: the last joins the first): the periodic cubic spline through them in the chord
    length t ∈ [0, L), turned counter-clockwise."""

    points: tuple[tuple[float, float], ...]

    @cached_property
    def _spline(self) -> tuple[object, float]:
        from scipy.interpolate import CubicSpline

        p = np.asarray(self.points, dtype=float)
        if _area(p) < 0.0:
            p = p[::-1]
        closed = np.vstack([p, p[:1]])
        t = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
        return CubicSpline(t, closed, bc_type="periodic"), float(t[-1])

    @property
    def length(self) -> float:
        """L, the period of the parameter (the closed polygon's perimeter), m."""
        return self._spline[1]

    @cached_property
    def _pieces(self) -> tuple[list[float], list[tuple[tuple[float, float], ...]]]:
        """The spline's breakpoints and, per piece, its coefficients (x, y) from the highest power,
        as floats: one point is evaluated in Python (:meth:`at`)."""
        spline: Any = self._spline[0]  # scipy's CubicSpline (untyped)
        c = np.asarray(spline.c, dtype=np.float64)
        pieces = [tuple((float(c[k, i, 0]), float(c[k, i, 1])) for k in range(c.shape[0])) for i in range(c.shape[1])]
        return np.asarray(spline.x, dtype=np.float64).tolist(), pieces

    def at(self, t: np.ndarray, order: int = 0) -> np.ndarray:
        """The spline's points (order 0) or derivatives d^k p/dt^k at t, shape (len(t), 2).

        One point (the exact cam's root finding asks ~10⁵ times a scene) is evaluated in floats
        the way scipy's ``CubicSpline`` evaluates it, bit for bit (a test), without its call's
        overhead: its periodic wrap, the piece ``x[i] ≤ t < x[i+1]`` (the last one closed), and
        ``Σ c[3−k]·s^(k−order)·k!/(k−order)!`` over k ≥ order, s = t − x[i], term by term."""
        spline, period = self._spline
        tm = np.mod(t, period)
        if not (isinstance(tm, np.ndarray) and tm.shape == (1,) and 0 <= order <= 3):
            return np.asarray(spline(tm, order))  # type: ignore[operator]
        xs, pieces = self._pieces
        v = xs[0] + (float(tm[0]) - xs[0]) % (xs[-1] - xs[0])  # scipy's periodic extrapolation
        i = min(max(bisect_right(xs, v) - 1, 0), len(xs) - 2)
        s = v - xs[i]
        cs = pieces[i]
        r0 = r1 = 0.0
        z = 1.0
        for k in range(order, 4):
            f = _FACTORS[order][k]
            cx, cy = cs[3 - k]
            r0 = r0 + cx * z * f
            r1 = r1 + cy * z * f
            if k < 3:
                z *= s
        return np.array([[r0, r1]])


def shape_problem(profile: PointsProfile, samples: int = 4096) -> str | None:
    """Why the spline through the points cannot be a cam's profile here, or None: it must turn
    one way all round (convex) and hold O strictly inside."""
    t = np.linspace(0.0, profile.length, samples, endpoint=False)
    p, d1, d2 = profile.at(t), profile.at(t, 1), profile.at(t, 2)
    bend = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    if np.any(bend <= 0.0):
        k = int(np.argmin(bend))
        return (f"the curve through the points is not convex (it bends back near ({p[k, 0] * 1e3:.4g}, "
                f"{p[k, 1] * 1e3:.4g}) mm): a follower could touch it at two places")
    if np.any(p[:, 0] * d1[:, 1] - p[:, 1] * d1[:, 0] <= 0.0):
        return "the turning centre O must lie inside the curve through the points"
    return None


def _area(p: np.ndarray) -> float:
    """The polygon's signed area (> 0 counter-clockwise)."""
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


#: A given profile.
Profile = EccentricDisc | PointsProfile


@dataclass(frozen=True)
class GivenContact:
    """A named contact position: the working profile's point at polar angle ``polar`` (rad,
    about O, cam frame) where the follower touches, or the cam angle ``delta`` (rad); one of
    the two is None."""

    name: str
    polar: float | None = None
    delta: float | None = None


@dataclass(frozen=True)
class GivenCam:
    """A disc cam whose profile is given: the profile, the follower, the sense of rotation
    (+1 CCW, −1 CW), ω (rad/s) and the named contacts."""

    profile: Profile
    follower: Follower
    rotation: int = 1
    omega: float = 1.0
    contacts: tuple[GivenContact, ...] = ()

    @property
    def roller(self) -> float:
        """r_r, 0 without a roller."""
        f = self.follower
        return f.roller_radius if f.contact == "roller" else 0.0

    @property
    def size(self) -> float:
        """The cam's size, m: a disc's R, the farthest given point's distance from O."""
        if isinstance(self.profile, EccentricDisc):
            return self.profile.radius
        return max(math.hypot(x, y) for x, y in self.profile.points)

    @property
    def disc(self) -> EccentricDisc:
        """The profile of a disc cam (a statement for the type checker: callers know it is one)."""
        assert isinstance(self.profile, EccentricDisc)
        return self.profile

    def pitch_radius(self) -> float:
        """A disc's pitch (theoretical) curve, a circle about C: R + r_r (R for a knife edge or a
        flat face, whose reference is the profile itself)."""
        return self.disc.radius + self.roller

    def base_radius(self) -> float:
        """A disc's base circle r0: the least radius about O of the pitch curve (knife, roller) or
        of the profile (flat face), R + r_r − |OC| or R − |OC|."""
        return self.pitch_radius() - self.disc.eccentricity
