"""Synthesis by given positions, constructed: a random linkage's positions sampled, the linkage
synthesised back from them (the re-analysis of the designs is tests/exact/test_synthesis_positions.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphmech.errors import DegenerateConstruction, OutOfDomain
from graphmech.exact.linkage import solve
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, LinkPoint
from graphmech.methods.synthesis_positions import (
    circumcentre,
    coupler_positions,
    fourbar_positions,
    fourbar_through_coupler_points,
    invert_rotation,
    joint_by_inversion,
    slider_crank_positions,
)

lengths = st.floats(0.02, 0.2)
gaps = st.floats(math.radians(25.0), math.radians(100.0))
SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


def sampled_fourbar(A, D, a, b, c, branch, phi):
    """B_i, C_i of the four-bar at crank angles φ_i, or None where it cannot be assembled."""
    lk = Linkage({"A": A, "D": D}, Crank("1", "A", "B", a, 1.0), (RRR("B", "C", "D", ("2", "3"), (b, c), branch),))
    kin = solve(lk, np.asarray(phi))
    if not kin.valid.all():
        return None
    return [tuple(map(float, p)) for p in kin.point["B"]], [tuple(map(float, p)) for p in kin.point["C"]]


def angle(P, O):
    return math.atan2(P[1] - O[1], P[0] - O[0])


def turned(x: float) -> float:
    """|x| wrapped into [0, π]."""
    return abs((x + math.pi) % (2 * math.pi) - math.pi)


def close(P, Q, size: float, rel: float = 1e-9) -> bool:
    return math.hypot(P[0] - Q[0], P[1] - Q[1]) <= rel * size


fourbars = st.tuples(st.floats(-0.1, 0.1), st.floats(-0.1, 0.1), lengths, st.floats(0, 2 * math.pi), lengths, lengths,
                     lengths, st.sampled_from(["left", "right"]), st.floats(0, 2 * math.pi), gaps, gaps)


def draw(sample):
    ax, ay, d, tilt, a, b, c, branch, phi1, g1, g2 = sample
    A, D = (ax, ay), (ax + d * math.cos(tilt), ay + d * math.sin(tilt))
    phi = [phi1, phi1 + g1, phi1 + g1 + g2]
    got = sampled_fourbar(A, D, a, b, c, branch, phi)
    assume(got is not None)
    B, C = got
    psi = [angle(p, D) for p in C]
    # the output must turn between the positions, else its circle is ill-conditioned
    assume(min(turned(psi[1] - psi[0]), turned(psi[2] - psi[1]), turned(psi[2] - psi[0])) > math.radians(5.0))
    return A, D, a, b, c, phi, psi, B, C


@SETTINGS
@given(fourbars)
def test_coupler_through_three_positions_recovers_the_pivots(sample) -> None:
    A, D, a, b, c, _, _, B, C = draw(sample)
    des = coupler_positions(B, C)
    size = max(a, b, c, math.dist(A, D))
    assert close(des.A, A, size) and close(des.D, D, size)
    assert (des.l_AB, des.l_BC, des.l_CD) == pytest.approx((a, b, c), rel=1e-9)
    assert [x.label for x in des.bisectors] == ["bB1B2", "bB2B3", "bC1C2", "bC2C3"]
    # each bisector passes through the pivot it found, at right angles to its chord
    for bis, pivot in zip(des.bisectors, (A, A, D, D)):
        px, py, dx, dy = bis.line
        (x1, y1), (x2, y2) = bis.ends
        assert abs((pivot[0] - px) * dy - (pivot[1] - py) * dx) <= 1e-9 * size
        assert abs(dx * (x2 - x1) + dy * (y2 - y1)) <= 1e-12 * size


@SETTINGS
@given(fourbars)
def test_inversion_recovers_the_coupler_and_the_output(sample) -> None:
    A, D, a, b, c, phi, psi, B, C = draw(sample)
    try:
        des = fourbar_positions(A, D, a, phi, psi)
    except DegenerateConstruction as e:
        # B₃′ on B₁ (positions 1 and 3 alike as seen from DC): no circle, rightly refused
        assert "coincide" in str(e) or "one straight line" in str(e)
        assume(False)
    # B₁, B₂′, B₃′ close together (positions alike as seen from DC): the circle is ill-conditioned
    images = [des.B1, *(v.image for v in des.construction.inversions)]
    assume(min(math.dist(p, q) for k, p in enumerate(images) for q in images[k + 1:]) > 0.01 * max(a, b, c))
    size = max(a, b, c, math.dist(A, D))
    assert close(des.C1, C[0], size) and close(des.B1, B[0], size)
    assert (des.l_BC, des.l_CD, des.l_AD) == pytest.approx((b, c, math.dist(A, D)), rel=1e-9)
    assert turned(des.psi_offset) <= 1e-9
    # the inverted points keep their distance from D and lie on the circle about C₁ through B₁
    for inv, Bi in zip(des.construction.inversions, B[1:]):
        assert math.dist(inv.image, D) == pytest.approx(math.dist(Bi, D), rel=1e-12)
        assert math.dist(inv.image, des.C1) == pytest.approx(b, rel=1e-9)
    # measured from another datum, ψ gives the same linkage, turned: C₁ is the same point
    shifted = fourbar_positions(A, D, a, phi, [p + 0.3 for p in psi])
    assert close(shifted.C1, des.C1, size) and shifted.psi_offset == pytest.approx(des.psi_offset - 0.3, abs=1e-9)


@SETTINGS
@given(fourbars, st.floats(-0.5, 0.5))
def test_two_positions(sample, frame_turn) -> None:
    A, D, a, b, c, phi, psi, B, C = draw(sample)
    size = max(a, b, c, math.dist(A, D))
    # the coupler: the frame line through the true pivots picks them on the bisectors — unless a
    # bisector runs along the frame line (B₁B₂ ⟂ AD: every point of it is a pivot), said as parallel
    try:
        des = coupler_positions(B[:2], C[:2], frame=(A, angle(D, A)))
    except DegenerateConstruction as e:
        u = (math.cos(angle(D, A)), math.sin(angle(D, A)))
        chords = [(P[1][0] - P[0][0], P[1][1] - P[0][1]) for P in (B[:2], C[:2])]
        assert "parallel" in str(e)
        assert min(abs(x * u[0] + y * u[1]) / math.hypot(x, y) for x, y in chords) < 1e-9
        assume(False)
    assert close(des.A, A, size, 1e-7) and close(des.D, D, size, 1e-7)
    # the inversion: with l_CD stated, C₁ is one of the two points of the bisector at c from D
    two = [fourbar_positions(A, D, a, phi[:2], psi[:2], l_CD=c, side=s) for s in (1.0, -1.0)]
    assert any(close(t.C1, C[0], size, 1e-7) for t in two)
    assert all(t.l_CD == pytest.approx(c, rel=1e-12) for t in two)
    assert [x.label for x in two[0].construction.arcs] == ["C1"]


@SETTINGS
@given(st.floats(-0.1, 0.1), lengths, st.floats(0.0, 2 * math.pi), st.floats(-0.05, 0.05), st.floats(0, 2 * math.pi),
       gaps, gaps, st.sampled_from(["forward", "backward"]))
def test_slider_crank_by_inversion(ay, a, guide, e, phi1, g1, g2, branch) -> None:
    b = a + abs(e) + 0.05  # the crank turns fully
    A = (0.01, ay)
    G = (A[0] - e * math.sin(guide), A[1] + e * math.cos(guide))  # A is e to the left... of the guide through G
    lk = Linkage({"A": A}, Crank("1", "A", "B", a, 1.0), (RRP("B", "C", ("2", "3"), b, Guide(G, guide), branch),))
    phi = [phi1, phi1 + g1, phi1 + g1 + g2]
    kin = solve(lk, np.asarray(phi))
    C = [tuple(map(float, p)) for p in kin.point["C"]]
    s = [0.2 + (p[0] - G[0]) * math.cos(guide) + (p[1] - G[1]) * math.sin(guide) for p in C]
    assume(min(abs(s[1] - s[0]), abs(s[2] - s[1]), abs(s[2] - s[0])) > 0.02 * a)
    des = slider_crank_positions(A, a, phi, s, guide)
    # the slider's pin is found up to its conditioning: the three B′ may be near one line
    assert close(des.C1, C[0], b, 1e-6)
    assert des.l_BC == pytest.approx(b, rel=1e-6) and des.offset == pytest.approx(-e, abs=1e-6 * b)
    two = slider_crank_positions(A, a, phi[:2], s[:2], guide, guide_point=G)
    assert close(two.C1, C[0], b, 1e-7) and two.l_BC == pytest.approx(b, rel=1e-7)


def test_the_rocker_drives_a_slider_through_three_positions() -> None:
    """Seed 000 连杆 4's form: a rocker about D in three positions, a slider's three positions F_i;
    E on the rocker is the circumcentre of F₁ and the F_i turned back about D."""
    D, E1, l_EF = (0.0, 0.0), (0.06, 0.03), 0.2
    rocker = [0.0, math.radians(25.0), math.radians(55.0)]
    guide = Guide((0.0, -0.08), 0.0)
    lk = Linkage({"D": D}, Crank("3", "D", "E", math.hypot(*E1), 1.0),
                 (RRP("E", "F", ("5", "6"), l_EF, guide, "forward"),), frame_link="1")
    kin = solve(lk, np.asarray([angle(E1, D) + r for r in rocker]))
    assert kin.valid.all()
    F = [tuple(map(float, p)) for p in kin.point["F"]]
    des = joint_by_inversion(F, D, rocker, "F", "E")
    assert close(des.joint, E1, 0.1)
    assert [v.label for v in des.inversions] == ["F2'", "F3'"]
    assert [v.angle for v in des.inversions] == pytest.approx([-rocker[1], -rocker[2]])
    assert math.dist(des.joint, F[0]) == pytest.approx(l_EF, rel=1e-12)


def test_by_hand() -> None:
    centre, (b12, b23) = circumcentre([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)], ["B1", "B2", "B3"], "A")
    assert centre == pytest.approx((0.0, 0.0), abs=1e-15)
    assert (b12.label, b23.label) == ("bB1B2", "bB2B3") and b12.line[:2] == (0.5, 0.5)
    assert invert_rotation((1.0, 0.0), (0.0, 0.0), math.pi / 2, "B2'").image == pytest.approx((0.0, 1.0))
    # a unit-square coupler turned a quarter about (0, 0): A and D both at the centre of turning
    des = coupler_positions([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)], [(2.0, 0.0), (0.0, 2.0), (-2.0, 0.0)])
    assert des.A == pytest.approx((0, 0), abs=1e-15) and des.D == pytest.approx((0, 0), abs=1e-15)
    assert (des.l_AB, des.l_BC, des.l_CD, des.l_AD) == pytest.approx((1.0, 1.0, 2.0, 0.0), abs=1e-15)


# ------------------------------------------------------------------------------- the refusals


def test_three_collinear_points_are_refused_in_words() -> None:
    with pytest.raises(DegenerateConstruction, match="B1, B2, B3 lie on one straight line: no circle passes"):
        coupler_positions([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)], [(0.0, 1.0), (1.0, 2.0), (2.0, 3.0)])
    # crank and slider positions that put B₁, B₂′, B₃′ on one line: the same sentence
    with pytest.raises(DegenerateConstruction, match="B1, B2', B3' lie on one straight line"):
        slider_crank_positions((0.0, 0.0), 1.0, [0.0, math.pi / 2, math.pi], [0.0, 1.0, 0.0], math.pi / 2)


def test_coincident_positions_are_refused() -> None:
    with pytest.raises(DegenerateConstruction, match="B1 and B2 coincide"):
        coupler_positions([(0.0, 0.0), (0.0, 0.0), (2.0, 2.0)], [(0.0, 1.0), (0.0, 1.0), (2.0, 3.0)])
    with pytest.raises(DegenerateConstruction, match="C1 and C2 coincide"):
        coupler_positions([(1.0, 0.0), (0.0, 1.0)], [(0.0, 0.0), (0.0, 0.0)], frame=((0.0, 0.0), 1.0))


def test_bad_data_are_refused() -> None:
    with pytest.raises(OutOfDomain, match="not rigid"):
        coupler_positions([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)], [(2.0, 0.0), (0.0, 2.5), (-2.0, 0.0)])
    with pytest.raises(OutOfDomain, match="two or three positions"):
        coupler_positions([(1.0, 0.0)], [(2.0, 0.0)])
    with pytest.raises(OutOfDomain, match="state the frame line"):
        coupler_positions([(1.0, 0.0), (0.0, 1.0)], [(2.0, 0.0), (0.0, 2.0)])
    with pytest.raises(OutOfDomain, match="state its length"):
        fourbar_positions((0.0, 0.0), (5.0, 0.0), 1.0, [0.0, 1.0], [0.0, 0.3])
    with pytest.raises(DegenerateConstruction, match="the arc does not reach it"):
        fourbar_positions((0.0, 0.0), (5.0, 0.0), 1.0, [0.0, 1.0], [0.0, 0.3], l_CD=0.01)
    with pytest.raises(OutOfDomain, match="positive"):
        fourbar_positions((0.0, 0.0), (5.0, 0.0), -1.0, [0.0, 1.0, 2.0], [0.0, 0.3, 0.5])


def sampled_with_coupler_point(A, D, a, b, c, branch, phi, along, left):
    lk = Linkage({"A": A, "D": D}, Crank("1", "A", "B", a, 1.0), (RRR("B", "C", "D", ("2", "3"), (b, c), branch),),
                 (LinkPoint("E", "2", ("B", "C"), along, left),))
    kin = solve(lk, np.asarray(phi))
    if not kin.valid.all():
        return None
    return tuple([tuple(map(float, p)) for p in kin.point[k]] for k in "BCE")


@SETTINGS
@given(fourbars, st.floats(-0.1, 0.1), st.floats(-0.1, 0.1))
def test_a_coupler_point_through_three_positions(sample, along, left) -> None:
    """Seed 000 连杆 5's form: A, D, E_i, l_CD and l_EC given; C_i from the arcs, B₁ by carrying A
    back with the coupler."""
    ax, ay, d, tilt, a, b, c, branch, phi1, g1, g2 = sample
    A, D = (ax, ay), (ax + d * math.cos(tilt), ay + d * math.sin(tilt))
    got = sampled_with_coupler_point(A, D, a, b, c, branch, [phi1, phi1 + g1, phi1 + g1 + g2], along, left)
    assume(got is not None)
    B, C, E = got
    turns = [angle(C[i], B[i]) for i in range(3)]
    assume(min(turned(turns[1] - turns[0]), turned(turns[2] - turns[1]), turned(turns[2] - turns[0])) > 0.1)
    l_EC = math.dist(E[0], C[0])
    # the arcs meet at an angle
    assume(l_EC > 0.01 and min(abs(math.sin(angle(C[i], D) - angle(E[i], C[i]))) for i in range(3)) > 0.05)
    sides = [1.0 if (E[i][0] - D[0]) * (C[i][1] - D[1]) - (E[i][1] - D[1]) * (C[i][0] - D[0]) > 0 else -1.0
             for i in range(3)]
    try:
        des = fourbar_through_coupler_points(A, D, E, c, l_EC, sides)
    except DegenerateConstruction as e:
        # the coupler turns about A itself between two positions (a kite folded with C on A, or a
        # rhombus whose C keeps its distance from A): A carried back with the coupler lands on
        # one point twice, so two of A, A2′, A3′ coincide — C is then as far from A at both
        assert "coincide" in str(e)
        rA = [math.dist(Ci, A) for Ci in C]
        assert min(abs(rA[i] - rA[j]) for i, j in ((0, 1), (1, 2), (0, 2))) <= 1e-9 * max(c, d)
        assume(False)
    size = max(a, b, c, d)
    assert all(close(des.C[i], C[i], size, 1e-8) for i in range(3))
    assert all(close(des.B[i], B[i], size, 1e-7) for i in range(3))
    assert (des.l_AB, des.l_BC) == pytest.approx((a, b), rel=1e-7)
    assert [v.label for v in des.construction.inversions] == ["A2'", "A3'"]
    assert [x.label for x in des.construction.arcs] == ["C", "C1", "C2", "C3"]


def test_a_coupler_point_out_of_reach_is_said() -> None:
    with pytest.raises(DegenerateConstruction, match="E2 is 0.5 m from D: the arcs CD = 0.095 m and EC = 0.07 m"):
        fourbar_through_coupler_points((0.0, 0.0), (0.1, 0.0), [(0.1, 0.1), (0.6, 0.0), (0.0, 0.1)], 0.095, 0.07)
