"""The model of a cam given by its profile: the eccentric disc's pitch and base radii."""
from __future__ import annotations

import pytest

from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import EccentricDisc, GivenCam


def test_radii_of_an_eccentric_disc() -> None:
    disc = EccentricDisc(0.030, (0.006, -0.008))
    assert disc.eccentricity == pytest.approx(0.010, rel=1e-15)
    roller = GivenCam(disc, TranslatingFollower(0.0, "roller", 0.005))
    assert roller.pitch_radius() == pytest.approx(0.035) and roller.base_radius() == pytest.approx(0.025)
    flat = GivenCam(disc, OscillatingFollower(0.09, 0.0, "flat"))
    assert flat.pitch_radius() == 0.030 and flat.base_radius() == pytest.approx(0.020)
