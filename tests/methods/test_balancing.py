"""graphmech.methods.balancing called directly: the mass-radius polygons against the equations of
balance (exact.balancing) on random rotors; a zero scale or radius refused."""
from __future__ import annotations

import cmath
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.exact import balancing as ex
from graphmech.mechanisms.rotor import RotorMass
from graphmech.methods import balancing as gm


masses = st.lists(st.tuples(st.floats(0.1, 50.0), st.floats(0.01, 0.5), st.floats(-180.0, 360.0),
                            st.floats(-0.3, 1.3)), min_size=1, max_size=7)


@settings(max_examples=80, deadline=None)
@given(ms=masses, mu=st.sampled_from([0.01, 0.05, 0.2]))
def test_dynamic_polygons_meet_the_equations_of_balance(ms, mu):
    rotor = [RotorMass(str(k + 1), m, r, math.radians(a), z) for k, (m, r, a, z) in enumerate(ms)]
    I, II = gm.dynamic_balance(rotor, 0.0, 1.0, (0.2, 0.3), mu)
    WI, WII = ex.dynamic_correction([ex.Unbalance(u.m, u.r, u.theta, u.z) for u in rotor], 0.0, 1.0)
    size = sum(u.m * u.r for u in rotor) * 3
    for c, w in ((I, WI), (II, WII)):
        drawn = 0j if c.balanced else cmath.rect(c.W, c.theta)
        assert abs(drawn - w) <= 1e-13 * size
    force, moment = ex.residuals([ex.Unbalance(u.m, u.r, u.theta, u.z) for u in rotor],
                                 [(0j if c.balanced else cmath.rect(c.W, c.theta), z) for c, z in ((I, 0.0), (II, 1.0))])
    assert force <= 1e-13 * size and moment <= 1e-13 * size


@settings(max_examples=60, deadline=None)
@given(ms=masses)
def test_static_polygon_closes_on_the_correction(ms):
    rotor = [RotorMass(str(k + 1), m, r, math.radians(a)) for k, (m, r, a, _) in enumerate(ms)]
    c = gm.static_balance(rotor, 0.1, 0.02)
    w = ex.static_correction([ex.Unbalance(u.m, u.r, u.theta) for u in rotor])
    size = sum(u.m * u.r for u in rotor)
    if c.balanced:
        assert abs(w) <= 1e-11 * size
    else:
        assert abs(cmath.rect(c.W, c.theta) - w) <= 1e-13 * size
        assert c.m_b == pytest.approx(c.W / 0.1, rel=1e-15)


def test_the_library_refuses_a_zero_scale_or_correction_radius():
    # static_balance(…, mu_W=0) raised ZeroDivisionError from inside the polygon
    from graphmech.mechanisms.rotor import RotorMass
    from graphmech.methods.balancing import static_balance

    m = [RotorMass("1", 1.0, 0.1, 0.0)]
    with pytest.raises(ValueError, match="μW and r_b must be positive"):
        static_balance(m, 0.1, 0.0)
    with pytest.raises(ValueError, match="r_b = 0.0"):
        static_balance(m, 0.0, 1.0)
    assert static_balance(m, 0.1, 0.01).m_b == pytest.approx(1.0, rel=1e-15)
