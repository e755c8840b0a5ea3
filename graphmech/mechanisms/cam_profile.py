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
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from graphmech.mechanisms.cam import Follower
from graphmech.spline import PeriodicSpline


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
    def _spline(self) -> tuple[PeriodicSpline, float]:
        p = np.asarray(self.points, dtype=float)
        if _area(p) < 0.0:
            p = p[::-1]
        closed = np.vstack([p, p[:1]])
        t = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
        return PeriodicSpline(t.tolist(), closed.tolist()), float(t[-1])

    @property
    def length(self) -> float:
        """L, the period of the parameter (the closed polygon's perimeter), m."""
        return self._spline[1]

    def at(self, t: np.ndarray, order: int = 0) -> np.ndarray:
        """The spline's points (order 0) or derivatives d^k p/dt^k at t, shape (len(t), 2)."""
        spline, period = self._spline
        return spline.at(np.mod(t, period), order)

    def point(self, t: float, order: int = 0) -> tuple[float, float]:
        """:meth:`at` at one t in scalar arithmetic, the same floats: what the root finders call."""
        spline, period = self._spline
        x, y = spline.point(float(t) % period, order)
        return x, y

    def point_and_slope(self, t: float) -> tuple[float, float, float, float]:
        """:meth:`point` of order 0 and 1 at once: (x, y, dx/dt, dy/dt)."""
        spline, period = self._spline
        (x, y), (dx, dy) = spline.point_and_slope(float(t) % period)
        return x, y, dx, dy


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
