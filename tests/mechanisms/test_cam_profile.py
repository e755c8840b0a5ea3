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


def test_points_profile_is_the_spline_through_them_counter_clockwise() -> None:
    import math

    import numpy as np

    from graphmech.mechanisms.cam_profile import PointsProfile, shape_problem

    square = ((0.02, 0.0), (0.0, -0.02), (-0.02, 0.0), (0.0, 0.02))  # given clockwise
    prof = PointsProfile(square)
    assert prof.length == pytest.approx(4 * 0.02 * math.sqrt(2))
    p, d = prof.at(np.linspace(0.0, prof.length, 4, endpoint=False)), prof.at(np.array([0.0]), 1)
    assert sorted(map(tuple, np.round(p, 15).tolist())) == sorted(square)  # through every point
    assert p[0, 0] * d[0, 1] - p[0, 1] * d[0, 0] > 0.0  # turned counter-clockwise round O
    assert shape_problem(prof) is None
    dented = PointsProfile(((0.03, 0.0), (0.0, 0.03), (-0.03, 0.0), (-0.005, -0.005), (0.0, -0.03)))
    assert "not convex" in str(shape_problem(dented))
    away = PointsProfile(tuple((0.05 + 0.01 * math.cos(a), 0.01 * math.sin(a)) for a in np.linspace(0, 6, 8)))
    assert "inside" in str(shape_problem(away))


def test_one_point_of_a_points_profile_is_scipys_bit_for_bit() -> None:
    """The exact cam asks for one point at a time ~10⁵ times a scene: that point is evaluated in
    floats, and must be the number scipy's CubicSpline gives — at the knots, just beside them, at
    the ends of the period, outside it, −0, for every derivative."""
    import math

    import numpy as np
    from scipy.interpolate import CubicSpline

    from graphmech.mechanisms.cam_profile import PointsProfile, _area

    rng = np.random.default_rng(23)
    for turn in (1, -1):  # given clockwise: reversed inside
        a = np.sort(rng.uniform(0.0, 2.0 * math.pi, 17))[::turn]
        r = 0.05 + 0.01 * rng.uniform(size=a.size)
        prof = PointsProfile(tuple((float(x * math.cos(b)), float(x * math.sin(b))) for x, b in zip(r, a)))
        p = np.asarray(prof.points, dtype=float)
        p = p[::-1] if _area(p) < 0.0 else p
        closed = np.vstack([p, p[:1]])
        knots = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
        spline, period = CubicSpline(knots, closed, bc_type="periodic"), prof.length
        ts = np.concatenate([rng.uniform(-3 * period, 3 * period, 300), knots, knots + period, knots - period,
                             np.nextafter(knots, -1.0), np.nextafter(knots, 1.0),
                             [0.0, -0.0, period, -period, np.nextafter(period, 0.0), 5e-324, -5e-324]])
        for order in range(4):
            for t in ts:
                one = np.array([t])
                got, want = prof.at(one, order), np.asarray(spline(np.mod(one, period), order))
                assert got.shape == want.shape == (1, 2)
                assert got.tobytes() == want.tobytes(), (order, t, got, want)
                assert np.array(prof.point(float(t), order)).tobytes() == want[0].tobytes()
        many = prof.at(ts, 1)  # many points at once
        assert many.tobytes() == np.asarray(spline(np.mod(ts, period), 1)).tobytes()
