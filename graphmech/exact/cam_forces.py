"""The forces on a translating roller follower with friction, solved as a linear system.

At a position δ of the rise the cam (link 1) pushes the follower (link 2) at the contact K; the
guide (frame 3) holds the follower at its two ends B1 (near the cam) and B2. With friction the cam's
total reaction R12 leans from the common normal n by the friction angle φ, against the follower's
sliding on the cam; each guide reaction is N_i across the axis with the friction f·|N_i| along it,
against the follower's motion. The load Q acts down the axis. The machine frame is the cam frame
turned by the cam's angle: the follower's axis is x = e, moving along +y.

Three equations (the follower's ΣFx, ΣFy, ΣM about its pitch point B) in three unknowns (R12, N1,
N2) — linear once the signs of N1, N2 are known, which fix the guide friction's |N_i|; the signs
are taken from the frictionless solution and the result is checked to have them. The cam's driving
moment is the moment about O of the follower's reaction on it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact import cam as exact_cam
from graphmech.mechanisms.cam import DiscCam, TranslatingFollower
from graphmech.mechanisms.motion import displacement


@dataclass(frozen=True)
class CamFriction:
    """The data of a cam's force problem (SI): the position δ on the rise, the load Q on the follower
    (N, down its axis), the friction angle φ at the contact (rad), the guide's friction coefficient f,
    the guide's length b and its overhang l (from the pitch point B to the near guide end B1), m."""

    at: float
    load: float
    phi: float
    f: float
    guide_length: float
    overhang: float


@dataclass(frozen=True)
class CamPosition:
    """The follower at δ in the machine frame (m): pitch point B, contact K, guide ends B1, B2; the
    unit common normal n (from the cam into the follower); the direction of R12 with friction; the
    follower's velocity sign along +y."""

    B: np.ndarray
    K: np.ndarray
    B1: np.ndarray
    B2: np.ndarray
    n: np.ndarray
    d: np.ndarray  # the unit direction of R12 (n leant by φ)


@dataclass(frozen=True)
class CamForces:
    """The solution: R12 = R·d (N), N1, N2 (signed, +x), the guide reactions R32_i = (N_i, −f|N_i|),
    and the cam's driving moment M1 (N·m, > 0 in the sense of ω)."""

    position: CamPosition
    R: float
    N1: float
    N2: float
    R_B1: np.ndarray
    R_B2: np.ndarray
    M1: float


def _rot(p: np.ndarray, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])


def position(cam: DiscCam, data: CamFriction) -> CamPosition:
    """The follower at ``data.at`` in the machine frame, and the direction of R12 with friction."""
    f = cam.follower
    if not isinstance(f, TranslatingFollower) or f.contact != "roller":
        raise OutOfDomain("the forces are found for a translating roller follower")
    delta = data.at % math.tau
    v = float(displacement(cam.program, np.array([delta]), 1)[0])  # ds/dδ
    if not v > 0.0:
        raise OutOfDomain(f"at δ = {math.degrees(delta):.6g}° the follower does not rise (ds/dδ = {v:.3g}): "
                          "the forces are found on the rise, where the cam drives")
    ex = exact_cam.profile(cam, np.array([delta]))
    turn = cam.rotation * delta  # the cam turned by δ carries the cam frame onto the machine frame
    B, K = _rot(ex.pitch[0], turn), _rot(ex.actual[0], turn)
    n = (B - K) / np.hypot(*(B - K))
    # the follower's point K moves with (0, v·ω); the cam's with ω × K: the follower slides on the
    # cam along the tangent, and the friction on it points the other way
    w = cam.rotation * cam.omega
    slide = np.array([0.0, v * cam.omega]) - w * np.array([-K[1], K[0]])
    t = np.array([-n[1], n[0]])
    along = float(np.dot(slide, t))
    lean = -math.copysign(1.0, along) if along != 0.0 else 0.0
    d = n * math.cos(data.phi) + t * lean * math.sin(data.phi)
    B1 = B + np.array([0.0, data.overhang])
    B2 = B1 + np.array([0.0, data.guide_length])
    return CamPosition(B, K, B1, B2, n, d)


def solve(cam: DiscCam, data: CamFriction) -> CamForces:
    """R12, N1, N2 from the follower's three equilibrium equations, and the cam's driving moment."""
    p = position(cam, data)
    y1, y2 = float(p.B1[1] - p.B[1]), float(p.B2[1] - p.B[1])
    arm = float((p.K - p.B)[0] * p.d[1] - (p.K - p.B)[1] * p.d[0])  # the moment of R = 1 about B

    def system(s1: float, s2: float) -> np.ndarray:
        # unknowns (R, N1, N2): ΣFx, ΣFy (friction −f·s_i·N_i = −f|N_i|), ΣM about B (N_i at height y_i: −y_i·N_i)
        a = np.array([[p.d[0], 1.0, 1.0],
                      [p.d[1], -data.f * s1, -data.f * s2],
                      [arm, -y1, -y2]])
        if not np.isfinite(a).all() or np.linalg.cond(a) > 1e12:  # B1, B2 a hair apart for their height
            raise NoSolution("the guide's two bearings are too close, for their height above the roller, "
                             "to tell their reactions apart (guide_length much shorter than overhang)")
        return np.asarray(np.linalg.solve(a, np.array([0.0, data.load, 0.0])), dtype=float)

    free = system(0.0, 0.0)
    signs = [(math.copysign(1.0, free[1]), math.copysign(1.0, free[2]))]
    signs += [(a, b) for a in (1.0, -1.0) for b in (1.0, -1.0) if (a, b) != signs[0]]
    for s1, s2 in signs:
        R, N1, N2 = system(s1, s2)
        if R > 0.0 and N1 * s1 >= 0.0 and N2 * s2 >= 0.0:
            break
    else:
        raise NoSolution("no equilibrium with the cam pushing: the follower jams in its guide (self-locking)")
    force = R * p.d
    M1 = cam.rotation * float(p.K[0] * force[1] - p.K[1] * force[0])
    return CamForces(p, float(R), float(N1), float(N2), np.array([N1, -data.f * abs(N1)]),
                     np.array([N2, -data.f * abs(N2)]), M1)


__all__ = ["CamForces", "CamFriction", "CamPosition", "position", "solve"]
