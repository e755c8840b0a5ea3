"""graphmech.methods.efficiency called directly: the incline's and the wedge's force polygons against
the closed forms of exact.efficiency, closing, frozen, refusing an unknown direction or push."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.exact import efficiency as ex
from graphmech.methods import efficiency as gm


@settings(max_examples=60, deadline=None)
@given(alpha=st.floats(1.0, 80.0), f=st.floats(0.0, 0.6), push=st.sampled_from(["horizontal", "parallel"]),
       direction=st.sampled_from(["forward", "reverse"]))
def test_incline_polygon_is_the_closed_form(alpha, f, push, direction):
    a, phi = math.radians(alpha), math.atan(f)
    if push == "horizontal" and direction == "forward" and a + phi > math.radians(89.0):
        return  # beyond the forward stroke's locking: tested below
    s = gm.incline(1000.0, a, phi, direction, 10.0, push)
    assert s.F == pytest.approx(ex.incline_force(1000.0, a, phi, direction, push), rel=1e-11, abs=1e-9)
    assert s.F0 == pytest.approx(ex.incline_force(1000.0, a, 0.0, direction, push), rel=1e-12)
    eta = ex.incline_efficiency(a, phi, direction, push)
    assert s.eta == pytest.approx(eta, rel=1e-10, abs=1e-10)
    assert dict(s.reactions)["R"] == pytest.approx(ex.incline_reaction(1000.0, a, phi, direction, push), rel=1e-11)


@settings(max_examples=60, deadline=None)
@given(gamma=st.floats(3.0, 85.0), beta=st.floats(5.0, 85.0), f=st.floats(0.0, 0.2),
       direction=st.sampled_from(["forward", "reverse"]))
def test_wedge_polygons_are_the_sine_rule(gamma, beta, f, direction):
    if abs(gamma + beta - 90.0) < 3.0 or gamma + beta > 170.0:
        return  # the contact side of guide 1 undecided, or the reconstruction's other regime
    g, b, phi = math.radians(gamma), math.radians(beta), math.atan(f)
    try:
        s = gm.wedge(1000.0, g, b, phi, direction, 20.0)
    except Exception as e:  # a side reversed by friction is refused, never mis-answered
        assert "reverses the side" in str(e)
        return
    w = ex.wedge_forces(1000.0, g, b, phi, direction)
    assert s.F == pytest.approx(w.F, rel=1e-10)
    r = dict(s.reactions)
    assert (r["R12"], r["R32"], r["R31"]) == pytest.approx((w.R12, w.R32, w.R31), rel=1e-9, abs=1e-9)
    assert s.F0 == pytest.approx(ex.wedge_ideal_force(1000.0, g, b), rel=1e-12)


def test_every_polygon_closes():
    s = gm.wedge(1000.0, math.radians(60), math.radians(60), math.atan(0.15), "forward", 25.0)
    for poly in s.polygons:
        sx = sum(f.end[0] - f.start[0] for f in poly.forces)
        sy = sum(f.end[1] - f.start[1] for f in poly.forces)
        assert abs(sx) < 1e-12 and abs(sy) < 1e-12
        assert poly.forces[0].start == poly.forces[-1].end


def test_frozen_results():
    s = gm.incline(10.0, 0.3, 0.1, "forward", 1.0)
    with pytest.raises(AttributeError):
        s.F = 3.0  # type: ignore[misc]


def test_the_library_refuses_an_unknown_direction_or_push():
    # incline(..., "up", ...) was drawn as a reverse stroke, push="vertical" as a parallel one
    with pytest.raises(ValueError, match="'forward' or 'reverse', not 'up'"):
        gm.incline(100.0, 0.3, 0.1, "up", 1.0)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="'horizontal' or 'parallel', not 'vertical'"):
        gm.incline(100.0, 0.3, 0.1, "forward", 1.0, "vertical")
    with pytest.raises(ValueError, match="not 'down'"):
        gm.wedge(1000.0, 1.0, 1.0, 0.1, "down", 20.0)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="not 'up'"):
        ex.incline_force(100.0, 0.3, 0.1, "up")  # type: ignore[arg-type]
    assert gm.incline(100.0, 0.3, 0.1, "reverse", 1.0).F == pytest.approx(ex.incline_force(100.0, 0.3, 0.1, "reverse"),
                                                                          rel=1e-12)


# ---------------------------------------------------------------------------- issue 22: clamp and buffer


def test_wedge_clamp_polygon_closes_on_the_sine_rule():
    from graphmech.methods.efficiency import wedge_clamp

    a, p1, p2 = math.radians(20), math.atan(0.1), math.atan(0.15)
    stroke = wedge_clamp(1000.0, a, p1, p2, "forward", 10.0)
    assert stroke.F == pytest.approx(1000.0 * math.sin(a + p1 + p2) / math.cos(p1), rel=1e-12)
    assert stroke.F0 == pytest.approx(1000.0 * math.sin(a), rel=1e-12)
    assert dict(stroke.reactions)["R_face1"] == pytest.approx(1000.0 * math.cos(a + p2) / math.cos(p1), rel=1e-12)
    real = stroke.polygons[-1]
    assert [s.name for s in real.forces] == ["Q", "F", "R1"]
    assert real.forces[-1].end == pytest.approx(real.forces[0].start, abs=1e-12)  # the polygon closes
    # reverse at α = φ1 + φ2: R2 and R1 balance alone, F = 0 — the self-locking limit
    limit = wedge_clamp(1.0, p1 + p2, p1, p2, "reverse", 1.0)
    assert limit.F == pytest.approx(0.0, abs=1e-15) and limit.eta == 0.0


def test_buffer_polygons_are_joined_along_R12():
    from graphmech.methods.efficiency import buffer

    a, phi = math.radians(40), math.atan(0.15)
    stroke = buffer(1000.0, a, phi, "reverse", 20.0)
    assert stroke.F == pytest.approx(1000.0 / math.tan(a + phi), rel=1e-12)
    p2, p1 = stroke.polygons[-2:]
    r12 = next(s for s in p2.forces if s.name == "R12")
    r21 = next(s for s in p1.forces if s.name == "R21")
    assert (r21.start, r21.end) == (r12.end, r12.start)
    assert dict(stroke.reactions)["R31"] == pytest.approx(1000.0, rel=1e-12)  # the guide takes the spring's line


@settings(max_examples=60, deadline=None)
@given(alpha=st.floats(1.0, 80.0), f1=st.floats(0.0, 0.6), f2=st.floats(0.0, 0.6),
       direction=st.sampled_from(["forward", "reverse"]))
def test_wedge_clamp_polygon_is_the_closed_form(alpha, f1, f2, direction):
    from graphmech.exact.efficiency import wedge_clamp_force, wedge_clamp_reaction
    from graphmech.methods.efficiency import wedge_clamp

    a, p1, p2 = math.radians(alpha), math.atan(f1), math.atan(f2)
    if direction == "forward" and a + p2 >= math.pi / 2 - 1e-6:  # face 1 would pull: refused
        return
    s = wedge_clamp(1000.0, a, p1, p2, direction, 20.0)
    assert s.F == pytest.approx(wedge_clamp_force(1000.0, a, p1, p2, direction), rel=1e-9, abs=1e-9)
    assert dict(s.reactions)["R_face1"] == pytest.approx(wedge_clamp_reaction(1000.0, a, p1, p2, direction), rel=1e-9)


@settings(max_examples=60, deadline=None)
@given(alpha=st.floats(1.0, 89.0), f=st.floats(0.0, 0.6), direction=st.sampled_from(["forward", "reverse"]))
def test_buffer_polygons_are_the_cotangent(alpha, f, direction):
    from graphmech.exact.efficiency import buffer_force, buffer_reaction
    from graphmech.methods.efficiency import buffer

    a, phi = math.radians(alpha), math.atan(f)
    if abs(a - phi) < 1e-3 or abs(a + phi - math.pi / 2) < 1e-3:  # at a limit: F ∞ or 0, ill-conditioned
        return
    s = buffer(1000.0, a, phi, direction, 20.0)
    if s.F is None:
        return
    assert s.F == pytest.approx(buffer_force(1000.0, a, phi, direction), rel=1e-9)
    assert dict(s.reactions)["R12"] == pytest.approx(abs(buffer_reaction(1000.0, a, phi, direction)), rel=1e-9)
