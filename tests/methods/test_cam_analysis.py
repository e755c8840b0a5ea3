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


POINTS = ((0.03, 0.0), (0.02, 0.025), (-0.01, 0.03), (-0.03, 0.005), (-0.02, -0.02), (0.01, -0.028))


@pytest.mark.parametrize("f", [TranslatingFollower(0.005, "roller", 0.005), TranslatingFollower(0.0, "knife"),
                               TranslatingFollower(0.01, "flat"), OscillatingFollower(0.07, 0.05, "roller", 0.005),
                               OscillatingFollower(0.09, 0.0, "flat", 0.0, "same")],
                         ids=lambda f: f"{f.kind}-{f.contact}")
def test_the_drawn_curve_converges_on_the_spline(f: object) -> None:
    """Read off the curve drawn as chords, s, α and v approach the root-found values as the chords
    multiply (about as 1/chords²)."""
    from graphmech.mechanisms.cam_profile import PointsProfile
    from graphmech.methods.cam_analysis import PolylineInversion, inversion

    cam = GivenCam(PointsProfile(POINTS), f, 1, 2.0)  # type: ignore[arg-type]
    assert isinstance(inversion(cam), PolylineInversion)

    def worst(chords: int) -> float:
        inv = PolylineInversion(cam, chords)
        out = [abs(inv.rise() - X.rise(cam)) / 0.03]
        for d in (0.3, 2.5, 4.4):
            p = inv.at(d)
            out += [abs(p.s - float(X.displacement(cam, d))) / 0.03, abs(p.alpha - float(X.pressure_angle(cam, d))),
                    abs(p.v - cam.omega * float(X.rate(cam, d))) / (cam.omega * 0.03)]
            px, py = X.contact_point(cam, d)
            out.append(abs(inv.contact(math.atan2(py, px)) - d))
        return max(out)

    coarse, fine = worst(360), worst(1440)
    assert fine < 2e-4 and fine < coarse / 5.0, (coarse, fine)
