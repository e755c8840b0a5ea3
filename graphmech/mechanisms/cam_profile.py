"""A disc cam given by its profile instead of its motion law (the reverse of inversion).

Everything is SI (m, rad, rad/s) and immutable. The frames are those of
:mod:`graphmech.mechanisms.cam`: the cam frame has the turning centre O at the origin and
coincides with the fixed (follower) frame at δ = 0, a translating follower moving along +y with
its axis at x = e, an oscillating follower pivoted at A = (a, 0). The profile is given in the cam
frame as it stands at δ = 0.

An eccentric circular disc (偏心圆盘) has radius R and its geometric centre C at ``centre``; its
eccentricity is |OC| < R (O lies inside the disc). A contact (E, F … of the book) is a point of
the working profile, given by its polar angle about O in the cam frame, or by the cam angle at
which the follower touches.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.mechanisms.cam import Follower


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

    profile: EccentricDisc
    follower: Follower
    rotation: int = 1
    omega: float = 1.0
    contacts: tuple[GivenContact, ...] = ()

    def pitch_radius(self) -> float:
        """The radius of the pitch (theoretical) curve, a circle about C: R + r_r (R for a knife
        edge or a flat face, whose reference is the profile itself)."""
        f = self.follower
        return self.profile.radius + (f.roller_radius if f.contact == "roller" else 0.0)

    def base_radius(self) -> float:
        """r0, the base circle: the least radius about O of the pitch curve (knife, roller) or of
        the profile (flat face), R + r_r − |OC| or R − |OC|."""
        return self.pitch_radius() - self.profile.eccentricity
