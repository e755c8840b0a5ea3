"""The forces on a translating roller follower with friction, as a linear system (exact.cam_forces)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact import cam as exact_cam
from graphmech.exact.cam_forces import CamFriction, solve
from graphmech.mechanisms.cam import (
    DiscCam,
    MotionProgram,
    Segment,
    TranslatingFollower,
)
from graphmech.mechanisms.motion import displacement

PROGRAM = MotionProgram(0.020, (Segment("rise", math.radians(150), "sine"), Segment("dwell", math.radians(30)),
                                Segment("return", math.radians(150), "sine"), Segment("dwell", math.radians(30))))


def cam(rotation: int = 1, offset: float = 0.008) -> DiscCam:
    return DiscCam(0.040, TranslatingFollower(offset, "roller", 0.010), PROGRAM, rotation=rotation, omega=10.0)


def data(at: float = 60.0, phi: float = 6.0, f: float = 0.15, overhang: float = 0.030) -> CamFriction:
    return CamFriction(math.radians(at), 500.0, math.radians(phi), f, 0.060, overhang)


@pytest.mark.parametrize("rotation", [1, -1])
@pytest.mark.parametrize("at", [20.0, 60.0, 110.0])
def test_without_friction_the_cams_work_is_the_loads(rotation, at):
    c = cam(rotation)
    r = solve(c, data(at, 0.0, 0.0))
    ds = float(displacement(PROGRAM, np.array([math.radians(at)]), 1)[0])
    assert r.M1 * c.omega == pytest.approx(500.0 * ds * c.omega, rel=1e-12)  # M1·ω = Q·v
    # the reaction along the normal carries the load: R cos α = Q
    alpha = float(exact_cam.profile(c, np.array([math.radians(at)])).pressure_angle[0])
    assert r.R * math.cos(alpha) == pytest.approx(500.0, rel=1e-12)
    assert r.N1 + r.N2 == pytest.approx(-r.R * r.position.d[0], abs=1e-9)


@pytest.mark.parametrize("rotation", [1, -1])
def test_with_friction_the_follower_is_in_equilibrium_and_the_cam_works_harder(rotation):
    c = cam(rotation)
    r = solve(c, data())
    p = r.position
    R12 = r.R * p.d
    total = R12 + r.R_B1 + r.R_B2 + np.array([0.0, -500.0])
    assert np.abs(total).max() < 1e-9
    moment = sum(float((q - p.B)[0] * F[1] - (q - p.B)[1] * F[0]) for q, F in ((p.K, R12), (p.B1, r.R_B1), (p.B2, r.R_B2)))
    assert abs(moment) < 1e-9
    assert r.R_B1[1] <= 0.0 and r.R_B2[1] <= 0.0  # the guide's friction holds the rising follower back
    assert math.degrees(math.acos(float(np.dot(p.n, p.d)))) == pytest.approx(6.0, abs=1e-9)  # R12 leans by φ
    ideal = solve(c, data(phi=0.0, f=0.0)).M1
    assert 0.5 < ideal / r.M1 < 1.0  # the efficiency at this position
    # the friction at K opposes the follower's sliding on the cam
    w = c.rotation * c.omega
    ds = float(displacement(PROGRAM, np.array([math.radians(60)]), 1)[0])
    slide = np.array([0.0, ds * c.omega]) - w * np.array([-p.K[1], p.K[0]])
    assert float(np.dot(R12 - np.dot(R12, p.n) * p.n, slide)) < 0.0


def test_a_long_overhang_and_a_rough_guide_jam_the_follower():
    with pytest.raises(NoSolution, match="jams"):
        solve(cam(), data(f=3.0, overhang=0.100))


def test_the_forces_are_found_on_the_rise_of_a_translating_roller_follower():
    with pytest.raises(OutOfDomain, match="does not rise"):
        solve(cam(), data(at=160.0))  # the far dwell
    with pytest.raises(OutOfDomain, match="does not rise"):
        solve(cam(), data(at=200.0))  # the return: the spring drives
    knife = DiscCam(0.040, TranslatingFollower(0.0), PROGRAM)
    with pytest.raises(OutOfDomain, match="translating roller"):
        solve(knife, data())


def test_bearings_a_hair_apart_for_their_height_are_refused_not_a_singular_matrix():
    # fuzz seed 94: overhang 1.8e16 m against a 60 mm guide made numpy's solve raise LinAlgError
    with pytest.raises(NoSolution, match="too close"):
        solve(cam(), data(f=0.0, overhang=1.8e16))
    assert solve(cam(), data(f=0.0, overhang=3.0)).N1 != 0.0  # a long but sane overhang is still solved
