"""A disc cam and its follower: the motion program and the follower's geometry (no drawing).

Everything is SI (m, rad, rad/s) and immutable.

Conventions
-----------
Cam angle δ runs from 0 to 2π in the sense the cam turns; the program's segments follow one
another from δ = 0. The cam frame has its centre O at the origin and, for a translating
follower, the follower's line of motion parallel to +y at δ = 0. By inversion (反转法) the cam
stands still and the follower turns the opposite way, so for a cam turning counter-clockwise
the follower's δ-th position is its start position turned δ clockwise.

A translating follower's ``offset`` e is signed: e > 0 puts its axis at x = +e (to the right of
O, seen along +y), e < 0 at x = −e on the left. The base circle radius r0 is that of the pitch
curve (the roller centre's path) for knife-edge and roller followers, and that of the profile
itself for a flat face.

An oscillating follower is pivoted at A, a distance ``pivot_distance`` from O along +x at
δ = 0, with an arm of length ``arm`` to its contact point (roller centre) B. Its angular
stroke is measured from the start angle ψ0 = ∠OAB with B on the base circle. ``sense`` says
whether, during the rise, the rocker turns opposite to the cam ("opposite") or with it ("same").
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, Union

Law = Literal["uniform", "parabolic", "cosine", "sine", "poly345", "table"]
Contact = Literal["knife", "roller", "flat"]
SegmentKind = Literal["rise", "return", "dwell"]
#: Which way the rocker turns during the rise, against the cam's turning.
Sense = Literal["opposite", "same"]


@dataclass(frozen=True)
class Segment:
    """One part of the motion program.

    Parameters
    ----------
    kind : "rise", "return" or "dwell"
    angle : float
        The cam angle it lasts, rad (> 0).
    law : str or None
        The motion law of a rise or return (None for a dwell).
    table : tuple of (x, y)
        For ``law = "table"``: points (fraction of the segment's angle 0…1, fraction of the
        stroke 0…1), first (0, 0) and last (1, 1); interpolated by a monotone cubic.
    """

    kind: SegmentKind
    angle: float
    law: Law | None = None
    table: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True)
class MotionProgram:
    """Rise, dwell, return, dwell …: segments whose angles add up to 2π; stroke h (m, or rad
    for an oscillating follower)."""

    stroke: float
    segments: tuple[Segment, ...]


@dataclass(frozen=True)
class TranslatingFollower:
    offset: float = 0.0  # e, m, signed (see the module docstring)
    contact: Contact = "knife"
    roller_radius: float = 0.0  # r_r, m (roller only)
    kind: Literal["translating"] = "translating"


@dataclass(frozen=True)
class OscillatingFollower:
    pivot_distance: float  # |OA|, m
    arm: float  # |AB|, m
    contact: Contact = "roller"
    roller_radius: float = 0.0
    sense: Sense = "opposite"
    kind: Literal["oscillating"] = "oscillating"


Follower = Union[TranslatingFollower, OscillatingFollower]


@dataclass(frozen=True)
class DiscCam:
    """A disc cam: base radius r0 (m), sense of rotation (+1 CCW, −1 CW), ω (rad/s, > 0),
    its follower and motion program, and an optional permissible pressure angle [α] (rad)."""

    base_radius: float
    follower: Follower
    program: MotionProgram
    rotation: int = 1
    omega: float = 1.0
    alpha_permissible: float | None = None
