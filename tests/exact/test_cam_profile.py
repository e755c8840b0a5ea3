"""The closed form of an eccentric disc cam's follower motion, against hand formulas and itself."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact import cam_profile as X
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import EccentricDisc, GivenCam

FOLLOWERS = [TranslatingFollower(0.0, "roller", 0.005), TranslatingFollower(0.015, "roller", 0.005),
             TranslatingFollower(-0.01, "knife"), TranslatingFollower(0.01, "flat"),
             OscillatingFollower(0.05, 0.04, "roller", 0.005, "opposite"),
             OscillatingFollower(0.05, 0.04, "roller", 0.005, "same"),
             OscillatingFollower(0.09, 0.0, "flat", 0.0, "opposite")]


def test_centred_roller_on_a_disc_is_the_book_formula() -> None:
    # C at (0, −e) at δ = 0, cam ccw: C turns to angle −90° + δ; s = e·sin θ + √(ρ² − e²cos²θ) + e − ... from the lowest
    e, big_r, r = 0.010, 0.030, 0.005
    cam = GivenCam(EccentricDisc(big_r, (0.0, -e)), TranslatingFollower(0.0, "roller", r))
    d = np.linspace(0.0, 2 * math.pi, 37)
    theta = -math.pi / 2 + d
    y = e * np.sin(theta) + np.sqrt((big_r + r) ** 2 - (e * np.cos(theta)) ** 2)
    np.testing.assert_allclose(X.displacement(cam, d), y - (big_r + r - e), atol=1e-15)
    assert X.rise(cam) == pytest.approx(2 * e, rel=1e-14)  # h = 2e for a centred follower
    np.testing.assert_allclose(X.pressure_angle(cam, d), np.arcsin(np.abs(e * np.cos(theta)) / (big_r + r)), atol=1e-15)


def test_flat_rocker_of_001_1_17() -> None:
    # ω2 = ω1·AC/BC with C on AB: 10·15/75 = 2 and 10·15/105 at θ = 180°
    cam = GivenCam(EccentricDisc(0.020, (0.015, 0.0)), OscillatingFollower(0.090, 0.0, "flat", 0.0, "opposite"), 1, 10.0)
    assert abs(cam.omega * X.rate(cam, 0.0)) == pytest.approx(2.0, rel=1e-13)
    assert abs(cam.omega * X.rate(cam, math.pi)) == pytest.approx(10 * 15 / 105, rel=1e-13)
    assert X.rise(cam) == pytest.approx(math.asin(0.035 / 0.09) - math.asin(0.005 / 0.09), rel=1e-14)


@pytest.mark.parametrize("f", FOLLOWERS, ids=lambda f: f"{f.kind}-{f.contact}-{getattr(f, 'sense', '')}")
@pytest.mark.parametrize("rot", [1, -1])
def test_extremes_rate_and_contacts_agree(f: object, rot: int) -> None:
    cam = GivenCam(EccentricDisc(0.030, (0.004, -0.010)), f, rot, 3.0)  # type: ignore[arg-type]
    d = np.linspace(0.0, 2 * math.pi, 200001)
    q = X.position(cam, d)
    lo, hi = X.lowest_highest(cam)
    assert q.min() == pytest.approx(lo, abs=1e-9) and q.max() == pytest.approx(hi, abs=1e-9)
    assert q.min() >= lo - 1e-15
    for at in (0.3, 2.0, 5.1):
        h = 1e-6
        num = (X.position(cam, at + h) - X.position(cam, at - h)) / (2 * h)
        assert float(X.rate(cam, at)) == pytest.approx(float(num), abs=1e-8)
        px, py = X.contact_point(cam, at)
        assert X.contact_delta(cam, math.atan2(py, px)) == pytest.approx(at, abs=1e-12)



@pytest.mark.parametrize("f", FOLLOWERS, ids=lambda f: f"{f.kind}-{f.contact}-{getattr(f, 'sense', '')}")
def test_root_finding_on_points_round_a_disc_meets_its_closed_form(f: object) -> None:
    """A disc given as 96 points: the spline through them lies within ~1e-8 m of the circle, and so
    do the follower's motion, pressure angle and velocity found by root finding on it."""
    from graphmech.mechanisms.cam_profile import PointsProfile

    big_r, c = 0.030, (0.004, -0.010)
    ang = np.linspace(0.0, 2 * math.pi, 97)[:-1]
    pts = tuple((c[0] + big_r * math.cos(a), c[1] + big_r * math.sin(a)) for a in ang)
    for rot in (1, -1):
        disc = GivenCam(EccentricDisc(big_r, c), f, rot, 10.0)  # type: ignore[arg-type]
        spline = GivenCam(PointsProfile(pts), f, rot, 10.0)  # type: ignore[arg-type]
        d = np.radians([0.0, 37.0, 200.0, 300.0])
        np.testing.assert_allclose(X.displacement(spline, d), X.displacement(disc, d), atol=5e-8)
        np.testing.assert_allclose(X.pressure_angle(spline, d), X.pressure_angle(disc, d), atol=5e-6)
        np.testing.assert_allclose(X.rate(spline, d), X.rate(disc, d), atol=5e-6)
        assert X.rise(spline) == pytest.approx(X.rise(disc), abs=1e-9)
        assert X.radii(spline) == pytest.approx(X.radii(disc), abs=1e-9)
        px, py = X.contact_point(spline, 0.7)
        assert X.contact_delta(spline, math.atan2(py, px)) == pytest.approx(0.7, abs=1e-12)
