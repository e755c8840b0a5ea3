"""An oscillating follower with a flat face (摆动平底从动件): exact envelope, inversion, scene.

The face is the line through the pivot A along the rocker, tangent to the base circle at the
start (ψ0 = asin(r0/a)); its contact with the cam is the envelope of the inverted face lines.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely

from graphmech.errors import SceneError
from graphmech.exact.cam import (
    initial_rocker_angle,
    max_pressure_angle,
    profile,
    undercut,
)
from graphmech.mechanisms.cam import (
    DiscCam,
    MotionProgram,
    OscillatingFollower,
    Segment,
)
from graphmech.mechanisms.motion import breakpoints, displacement
from graphmech.methods.cam_inversion import divisions, draw_profile, read_cam
from graphmech.scene import parse_scene

A, R0 = 0.080, 0.030
PROGRAM = MotionProgram(math.radians(20), (
    Segment("rise", math.radians(150), "poly345"), Segment("dwell", math.radians(30)),
    Segment("return", math.radians(120), "cosine"), Segment("dwell", math.radians(60))))
CASES = [(sense, rot) for sense in ("opposite", "same") for rot in (1, -1)]


def cam_of(sense: str, rot: int, r0: float = R0, program: MotionProgram = PROGRAM) -> DiscCam:
    return DiscCam(r0, OscillatingFollower(A, 0.1, "flat", 0.0, sense), program, rotation=rot)  # type: ignore[arg-type]


def face(cam: DiscCam, d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The inverted pivot A(δ) and face direction u(δ) in the cam frame, worked out here afresh."""
    f, rot = cam.follower, cam.rotation
    sigma = rot * (1 if f.sense == "opposite" else -1)
    psi = math.asin(cam.base_radius / f.pivot_distance) + displacement(cam.program, d)
    ang = -rot * d
    c, s = np.cos(ang), np.sin(ang)
    pivot = f.pivot_distance * np.column_stack([c, s])
    ux, uy = -np.cos(psi), sigma * np.sin(psi)
    return pivot, np.column_stack([c * ux - s * uy, s * ux + c * uy])


def cross(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    return p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0]


# interior angles of the smooth pieces (away from the law's joints)
D = np.concatenate([np.linspace(0.05, 2.55, 40), np.linspace(3.2, 5.1, 30), np.linspace(5.3, 6.2, 10)])


def test_start_angle_and_start_tangency() -> None:
    cam = cam_of("opposite", 1)
    assert initial_rocker_angle(cam) == pytest.approx(math.asin(R0 / A), abs=1e-15)
    p = profile(cam, np.array([0.0, 5.5]))  # the dwell at the bottom: the profile is the base circle
    assert np.hypot(*p.actual.T) == pytest.approx(R0, abs=1e-15)
    assert np.hypot(*p.pitch.T) == pytest.approx(R0, abs=1e-15)  # the foot of the perpendicular


@pytest.mark.parametrize("sense, rot", CASES)
def test_envelope_points_lie_on_their_faces_and_the_faces_touch_there(sense: str, rot: int) -> None:
    cam = cam_of(sense, rot)
    p = profile(cam, D)
    pivot, u = face(cam, D)
    assert np.abs(cross(p.actual - pivot, u)).max() < 1e-15  # on face δ
    # the pitch point is the foot of the perpendicular from O
    assert np.abs(cross(p.pitch - pivot, u)).max() < 1e-15
    assert np.abs(np.einsum("ij,ij->i", p.pitch, u)).max() < 1e-15
    h = 1e-5
    ahead, behind = profile(cam, D + h).actual, profile(cam, D - h).actual
    tangent = (ahead - behind) / (2 * h)
    speed = np.hypot(*tangent.T)
    assert np.abs(cross(tangent, u)).max() < 1e-8 * speed.max()  # face δ is tangent to the envelope
    # t = (A′ × u)/(u × u′), with A′ and u′ by finite differences
    (pa, ua), (pb, ub) = face(cam, D + h), face(cam, D - h)
    dA, du = (pa - pb) / (2 * h), (ua - ub) / (2 * h)
    t = cross(dA, u) / cross(u, du)
    assert np.abs(pivot + t[:, None] * u - p.actual).max() < 1e-9
    # ρ of the envelope against the parametric formula −rot·|C′|³/(C′ × C″) by finite differences
    second = (ahead - 2 * p.actual + behind) / h**2
    rho_fd = -rot * speed**3 / cross(tangent, second)
    assert np.all(p.rho_actual > 0)
    assert np.abs(rho_fd / p.rho_actual - 1).max() < 1e-4


@pytest.mark.parametrize("sense, rot", CASES)
def test_the_drawn_profile_converges_at_second_order(sense: str, rot: int) -> None:
    cam = cam_of(sense, rot)
    exact = shapely.LineString(profile(cam, np.linspace(0.0, math.tau, 200_001)).actual)
    errors = []
    for n in (72, 144, 288):
        delta = divisions(cam, math.tau / n, breakpoints(cam.program))
        drawn = draw_profile(cam, delta, displacement(cam.program, delta))
        assert drawn.valid.all() and len(drawn.actual) == len(delta)
        errors.append(max(exact.distance(shapely.Point(q)) for q in drawn.actual))
    ratios = [errors[0] / errors[1], errors[1] / errors[2]]
    assert errors[0] < 5e-3 * R0
    assert all(3.5 < r < 4.5 for r in ratios), (errors, ratios)


@pytest.mark.parametrize("sense, rot", CASES)
def test_pressure_angle_is_zero_and_readings_agree(sense: str, rot: int) -> None:
    cam = cam_of(sense, rot)
    assert np.all(profile(cam, D).pressure_angle == 0.0)
    assert max_pressure_angle(cam)[0] == 0.0
    reading = read_cam(cam, 288)
    assert reading.alpha_max == 0.0
    rho = profile(cam, np.linspace(0.0, math.tau, 20_001)).rho_actual.min()
    assert reading.rho_min == pytest.approx(rho, rel=2e-2)
    assert not reading.undercut and undercut(cam) == []


def test_a_cusp_is_reported() -> None:
    steep = MotionProgram(math.radians(40), PROGRAM.segments)
    found = undercut(cam_of("same", 1, r0=0.010, program=steep))
    assert len(found) == 1 and found[0].startswith("the flat face's profile has a cusp")


def test_the_base_circle_must_lie_inside_the_pivot_distance() -> None:
    with pytest.raises(ValueError, match="r0 < a"):
        profile(cam_of("opposite", 1, r0=A), D)


SCENE = """\
title = "Oscillating flat-faced follower"
show = ["profile"]

[units]
length = "mm"
angle = "deg"

[cam]
base_radius = 30
rotation = "ccw"
omega_rad_s = 1

[cam.follower]
type = "oscillating"
contact = "flat"
pivot_distance = 80
arm = 100
sense = "opposite"

[cam.program]
stroke = 20

[[cam.segment]]
kind = "rise"
angle = 180
law = "poly345"

[[cam.segment]]
kind = "return"
angle = 180
law = "cosine"
"""


def test_the_scene_parser_accepts_it() -> None:
    import tomllib

    scene = parse_scene(tomllib.loads(SCENE), "cam.toml")
    f = scene.problem.cam.follower
    assert (f.kind, f.contact, f.pivot_distance, f.sense) == ("oscillating", "flat", 0.08, "opposite")
    with pytest.raises(SceneError) as info:
        parse_scene(tomllib.loads(SCENE.replace("base_radius = 30", "base_radius = 80")), "cam.toml")
    assert info.value.problems == [(
        "cam.follower.pivot_distance",
        ("a flat face through the pivot cannot touch the base circle: the base radius r0 = 80 mm "
         "must be smaller than pivot_distance a = 80 mm"),
    )]
