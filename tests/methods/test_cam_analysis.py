"""The book's inversion of a given eccentric disc: every reading is a compass cut, so it meets the
closed form to round-off."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact import cam_profile as X
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import EccentricDisc, GivenCam
from graphmech.methods.cam_analysis import Inversion

FOLLOWERS = [TranslatingFollower(0.0, "roller", 0.005), TranslatingFollower(0.015, "roller", 0.005),
             TranslatingFollower(-0.01, "knife"), TranslatingFollower(0.01, "flat"),
             OscillatingFollower(0.05, 0.04, "roller", 0.005, "opposite"),
             OscillatingFollower(0.05, 0.04, "knife", 0.0, "same"),
             OscillatingFollower(0.09, 0.0, "flat", 0.0, "opposite"), OscillatingFollower(0.09, 0.0, "flat", 0.0, "same")]


@pytest.mark.parametrize("f", FOLLOWERS, ids=lambda f: f"{f.kind}-{f.contact}-{getattr(f, 'sense', '')}")
@pytest.mark.parametrize("rot", [1, -1])
def test_inversion_meets_the_closed_form(f: object, rot: int) -> None:
    cam = GivenCam(EccentricDisc(0.030, (0.004, -0.010)), f, rot, 10.0)  # type: ignore[arg-type]
    inv = Inversion(cam)
    assert inv.r0 == pytest.approx(cam.base_radius(), abs=1e-15)
    assert inv.rise() == pytest.approx(X.rise(cam), abs=1e-14)
    for d in np.radians([0.0, 37.0, 90.0, 200.0, 311.0]):
        p = inv.at(float(d))
        assert p.s == pytest.approx(float(X.displacement(cam, d)), abs=1e-14)
        assert p.alpha == pytest.approx(float(X.pressure_angle(cam, d)), abs=1e-13)
        assert p.v == pytest.approx(cam.omega * float(X.rate(cam, d)), abs=1e-12)
        px, py = X.contact_point(cam, float(d))
        assert math.hypot(px - p.contact[0], py - p.contact[1]) < 1e-14
        assert inv.contact(math.atan2(py, px)) == pytest.approx(float(d) % (2 * math.pi), abs=1e-12)
