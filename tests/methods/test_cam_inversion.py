"""The cam profile by inversion against the reference problems and the exact envelope."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest
import shapely

from graphmech.mechanisms.cam import (DiscCam, MotionProgram, OscillatingFollower, Segment,
                                      TranslatingFollower)
from graphmech.mechanisms.motion import breakpoints, displacement, impacts
from graphmech.exact.cam import max_pressure_angle, profile, undercut
from graphmech.methods.cam_inversion import divisions, draw_profile, read_cam
from graphmech.scene import parse_scene
from tests.scenes import scene_text


def offset_roller(e: float) -> DiscCam:
    """cam.offset_roller_translating: e = ±10, r0 = 30, r_r = 10, h = 16 mm, cam CCW."""
    program = MotionProgram(0.016, (Segment("rise", math.radians(150), "uniform"),
                                     Segment("dwell", math.radians(30)),
                                     Segment("return", math.radians(120), "parabolic"),
                                     Segment("dwell", math.radians(60))))
    return DiscCam(0.03, TranslatingFollower(e, "roller", 0.01), program, rotation=1, omega=1.0)


def oscillating(sense: str = "opposite") -> DiscCam:
    program = MotionProgram(math.radians(25), (Segment("rise", math.pi, "cosine"),
                                               Segment("return", math.pi, "sine")))
    return DiscCam(0.025, OscillatingFollower(0.055, 0.05, "roller", 0.008, sense), program, rotation=1)


def drawn(cam: DiscCam, delta: np.ndarray):
    return draw_profile(cam, delta, displacement(cam.program, delta))


@pytest.mark.parametrize("sense, e", [("pos", 0.01), ("neg", -0.01)])
def test_pitch_points_of_the_offset_roller_cam(problems, sense, e):
    p = problems["cam.offset_roller_translating"]
    cam = offset_roller(e)
    delta = np.radians(p["inputs"]["profile_angles_deg"])
    d = drawn(cam, delta)
    assert d.valid.all()
    np.testing.assert_allclose(d.pitch[:, 0] * 1000, p["exact"][f"pitch_x_mm_{sense}"], atol=6e-5)  # printed to 1e-4 mm
    np.testing.assert_allclose(d.pitch[:, 1] * 1000, p["exact"][f"pitch_y_mm_{sense}"], atol=6e-5)


def test_rocker_angles_of_the_oscillating_cam(problems):
    p = problems["cam.oscillating_roller"]
    cam = oscillating()
    delta = np.radians(p["inputs"]["table_angles_deg_corrected"])
    d = drawn(cam, delta)
    # the rocker's angle ∠OAB read off the drawing, less ψ0
    a = 0.055 * np.column_stack([np.cos(delta), -np.sin(delta)])
    ao, ab = -a, d.pitch - a
    ang = np.degrees(np.arccos((ao * ab).sum(1) / (np.hypot(*ao.T) * np.hypot(*ab.T))))
    psi0 = p["exact"]["phi0_initial_rocker_angle_deg"]
    np.testing.assert_allclose(ang - psi0, p["exact"]["phi_table_deg"], rtol=1e-9, atol=1e-11)
    np.testing.assert_allclose(np.hypot(*ab.T), 0.05, rtol=1e-12)


@pytest.mark.parametrize("cam", [offset_roller(0.01), offset_roller(-0.01), oscillating(), oscillating("same")],
                         ids=["pos", "neg", "osc-opposite", "osc-same"])
def test_pressure_angle_read_off_the_drawing_converges_to_the_exact_one(cam):
    from graphmech.exact.cam import max_pressure_angle, profile

    errors = []
    for n in (72, 144, 288):
        delta = divisions(cam, math.tau / n, breakpoints(cam.program))
        d = drawn(cam, delta)
        exact = profile(cam, delta).pressure_angle
        # away from the joints and the jumps of s'', where a chord through neighbours averages
        # two different curvatures and the reading is only first order
        kinks = np.concatenate([breakpoints(cam.program), [i.angle for i in impacts(cam.program)]])
        far = np.min(np.abs(((delta[:, None] - kinks[None, :]) + math.pi) % math.tau - math.pi),
                     axis=1) > 2.5 * math.tau / n
        errors.append(np.max(np.abs(d.pressure_angle[far] - np.abs(exact[far]))))
    assert errors[0] < math.radians(1.0)
    assert errors[1] < errors[0] / 3 and errors[2] < errors[1] / 3  # second order: ×4 per halving
    amax, _ = max_pressure_angle(cam)
    assert amax >= np.max(d.pressure_angle[far]) - 1e-3


# ----------------------------------------------------------------------------- an oscillating flat face
#: The oscillating flat-faced follower (tests/scenes/cam/oscillating_flat.toml): a = 80, r0 = 30 mm.
R0 = 0.030
CASES = [(sense, rot) for sense in ("opposite", "same") for rot in (1, -1)]
# interior angles of the smooth pieces (away from the law's joints)
D = np.concatenate([np.linspace(0.05, 2.55, 40), np.linspace(3.2, 5.1, 30), np.linspace(5.3, 6.2, 10)])


def cam_of(sense: str, rot: int) -> DiscCam:
    text = scene_text("cam/oscillating_flat").replace('sense = "opposite"', f'sense = "{sense}"')
    text = text.replace('rotation = "ccw"', f'rotation = "{"ccw" if rot == 1 else "cw"}"')
    return parse_scene(tomllib.loads(text), "oscillating_flat.toml").problem.cam


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
