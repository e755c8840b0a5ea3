"""The designs by given positions re-analysed: each designed linkage driven through its prescribed
positions by the exact position analysis, the positions reached to 1e-9 of the longest link."""
from __future__ import annotations

import cmath
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from graphmech.errors import DegenerateConstruction, NoSolution, OutOfDomain
from graphmech.exact import characteristics as XC
from graphmech.exact.linkage import solve
from graphmech.exact.synthesis_positions import (
    circumcentre,
    reanalyse_coupler,
    reanalyse_fourbar,
    reanalyse_rocker_slider,
    reanalyse_slider_crank,
)
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage
from graphmech.methods import synthesis_positions as M

lengths = st.floats(0.02, 0.2)
gaps = st.floats(math.radians(25.0), math.radians(100.0))
SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


def z(p) -> complex:
    return complex(float(p[0]), float(p[1]))


def sampled(A, D, a, b, c, branch, phi):
    lk = Linkage({"A": (A.real, A.imag), "D": (D.real, D.imag)}, Crank("1", "A", "B", a, 1.0),
                 (RRR("B", "C", "D", ("2", "3"), (b, c), branch),))
    kin = solve(lk, np.asarray(phi))
    if not kin.valid.all():
        return None
    return [z(p) for p in kin.point["B"]], [z(p) for p in kin.point["C"]]


def turned(x: float) -> float:
    return abs((x + math.pi) % (2 * math.pi) - math.pi)


fourbars = st.tuples(lengths, st.floats(0, 2 * math.pi), lengths, lengths, lengths,
                     st.sampled_from(["left", "right"]), st.floats(0, 2 * math.pi), gaps, gaps)


def draw(sample):
    d, tilt, a, b, c, branch, phi1, g1, g2 = sample
    A = 0.03 - 0.01j
    D = A + d * cmath.exp(1j * tilt)
    phi = [phi1, phi1 + g1, phi1 + g1 + g2]
    got = sampled(A, D, a, b, c, branch, phi)
    assume(got is not None)
    B, C = got
    psi = [cmath.phase(p - D) for p in C]
    assume(min(turned(psi[1] - psi[0]), turned(psi[2] - psi[1]), turned(psi[2] - psi[0])) > math.radians(5.0))
    # away from a dead point (γ = 0 at a prescribed position the re-analysis keeps only √ε of its digits)
    assume(min(turned(cmath.phase((B[i] - C[i]) / (D - C[i]))) for i in range(3)) > 0.01)
    assume(max(turned(cmath.phase((B[i] - C[i]) / (D - C[i]))) for i in range(3)) < math.pi - 0.01)
    return A, D, a, b, c, branch, phi, psi, B, C


def test_circumcentre() -> None:
    assert circumcentre(1 + 0j, 1j, -1 + 0j) == pytest.approx(0j, abs=1e-15)
    # far from the origin the centre keeps the figure's digits
    far = 1e4 + 1e4j
    assert circumcentre(far + 3, far + 4j, far - 3) == pytest.approx(far + 0.875j, abs=1e-11)
    with pytest.raises(NoSolution, match="lie on one straight line"):
        circumcentre(0j, 1 + 1j, 2 + 2j)
    with pytest.raises(NoSolution, match="lie on one straight line"):
        circumcentre(0j, 0j, 2 + 2j)


@SETTINGS
@given(st.complex_numbers(max_magnitude=1.0), st.complex_numbers(max_magnitude=1.0),
       st.complex_numbers(max_magnitude=1.0))
def test_circumcentre_is_equally_far_and_agrees_with_the_bisectors(p1, p2, p3) -> None:
    size = max(abs(p2 - p1), abs(p3 - p1), abs(p3 - p2))
    sin = abs(((p2 - p1).conjugate() * (p3 - p1)).imag) / max(abs(p2 - p1) * abs(p3 - p1), 1e-300)
    assume(min(abs(p2 - p1), abs(p3 - p1), abs(p3 - p2)) > 1e-3 and sin > 1e-3)
    o = circumcentre(p1, p2, p3)
    r = abs(o - p1)
    assert abs(o - p2) == pytest.approx(r, rel=1e-9) and abs(o - p3) == pytest.approx(r, rel=1e-9)
    drawn, _ = M.circumcentre([(p.real, p.imag) for p in (p1, p2, p3)], ["1", "2", "3"])
    assert abs(z(drawn) - o) <= 1e-9 * max(r, size)


@SETTINGS
@given(fourbars)
def test_the_coupler_design_reaches_its_positions(sample) -> None:
    A, D, a, b, c, branch, _phi, _psi, B, C = draw(sample)
    des = M.coupler_positions([(p.real, p.imag) for p in B], [(p.real, p.imag) for p in C])
    r = reanalyse_coupler(z(des.A), z(des.D), B, C)
    assert r.error <= 1e-9 and r.one_branch and r.branch == branch
    assert r.grashof == XC.fourbar_class(a, b, c, abs(D - A))
    if r.characteristics is None:
        assert r.note and "turn fully" in r.note
    else:
        assert r.note == ""
        assert r.characteristics.gamma_min <= min(r.gamma) + 1e-9  # the cycle's least is no greater
    assert all(0.0 <= g <= math.pi / 2 for g in r.gamma)


@SETTINGS
@given(fourbars)
def test_the_inversion_design_reaches_its_positions(sample) -> None:
    A, D, a, b, c, branch, phi, psi, _B, C = draw(sample)
    try:
        des = M.fourbar_positions((A.real, A.imag), (D.real, D.imag), a, phi, psi)
    except DegenerateConstruction as e:
        # B₃′ on B₁ (positions 1 and 3 alike as seen from DC): no circle, rightly refused
        assert "coincide" in str(e) or "one straight line" in str(e)
        assume(False)
    # B₁, B₂′, B₃′ close together (positions alike as seen from DC): the circle is ill-conditioned
    images = [des.B1, *(v.image for v in des.construction.inversions)]
    assume(min(math.dist(p, q) for k, p in enumerate(images) for q in images[k + 1:]) > 0.01 * max(a, b, c))
    r = reanalyse_fourbar(A, D, des.l_AB, des.l_BC, des.l_CD, phi, psi, z(des.C1))
    assert r.error <= 1e-9 and r.branch == branch
    assert [abs(x - y) for x, y in zip(r.reached, C)] == pytest.approx([0, 0, 0], abs=1e-9 * max(a, b, c))


@SETTINGS
@given(lengths, st.floats(0.0, 2 * math.pi), st.floats(-0.05, 0.05), st.floats(0, 2 * math.pi), gaps, gaps,
       st.sampled_from(["forward", "backward"]))
def test_the_slider_crank_design_reaches_its_positions(a, guide, e, phi1, g1, g2, branch) -> None:
    b = a + abs(e) + 0.05
    A = 0.01 + 0.02j
    G = A + e * 1j * cmath.exp(1j * guide)
    lk = Linkage({"A": (A.real, A.imag)}, Crank("1", "A", "B", a, 1.0),
                 (RRP("B", "C", ("2", "3"), b, Guide((G.real, G.imag), guide), branch),))
    phi = [phi1, phi1 + g1, phi1 + g1 + g2]
    C = [z(p) for p in solve(lk, np.asarray(phi)).point["C"]]
    s = [((p - G) / cmath.exp(1j * guide)).real for p in C]
    assume(min(abs(s[1] - s[0]), abs(s[2] - s[1]), abs(s[2] - s[0])) > 0.02 * a)
    des = M.slider_crank_positions((A.real, A.imag), a, phi, s, guide)
    r = reanalyse_slider_crank(A, a, des.l_BC, phi, s, guide, z(des.C1))
    assert r.error <= 1e-9 and r.branch == branch and r.grashof == "crank" and r.note == ""
    assert r.characteristics is not None and r.characteristics.gamma_min <= min(r.gamma) + 1e-9


def test_a_design_off_its_positions_is_seen() -> None:
    A, D = 0j, 0.08 + 0.01j
    _B, C = sampled(A, D, 0.03, 0.07, 0.06, "left", np.radians([20.0, 70.0, 130.0]))
    phi = np.radians([20.0, 70.0, 130.0]).tolist()
    psi = [cmath.phase(p - D) for p in C]
    good = reanalyse_fourbar(A, D, 0.03, 0.07, 0.06, phi, psi, C[0])
    assert good.error <= 1e-12 and good.grashof == "crank_rocker_AB"
    ch = good.characteristics
    assert ch is not None and ch.gamma_min == pytest.approx(XC.fourbar(A, D, 0.03, 0.07, 0.06, "left").gamma_min)
    bad = reanalyse_fourbar(A, D, 0.03, 0.0701, 0.06, phi, psi, C[0])
    assert 1e-5 < bad.error < 1e-2


def test_positions_that_admit_no_grashof_crank_are_said() -> None:
    A, D = 0j, 0.05 + 0j
    a, b, c = 0.06, 0.03, 0.07  # s + l = 0.03 + 0.07 > 0.05 + 0.06: a double rocker
    phi = np.radians([60.0, 75.0, 90.0])
    B, C = sampled(A, D, a, b, c, "left", phi)
    des = M.coupler_positions([(p.real, p.imag) for p in B], [(p.real, p.imag) for p in C])
    r = reanalyse_coupler(z(des.A), z(des.D), B, C)
    assert r.error <= 1e-9 and r.grashof == "double_rocker" and r.characteristics is None
    assert r.note == "the positions admit no Grashof crank (double rocker): AB does not turn fully"


def test_positions_on_both_branches_are_said() -> None:
    A, D = 0j, 0.08 + 0j
    phi = np.radians([40.0, 100.0, 200.0])
    left = sampled(A, D, 0.03, 0.07, 0.06, "left", phi)
    right = sampled(A, D, 0.03, 0.07, 0.06, "right", phi)
    B, C = left[0], [left[1][0], left[1][1], right[1][2]]
    des = M.coupler_positions([(p.real, p.imag) for p in B], [(p.real, p.imag) for p in C])
    assert abs(z(des.D) - D) <= 1e-12  # the construction finds the pivots all the same
    r = reanalyse_coupler(z(des.A), z(des.D), B, C)
    assert not r.one_branch and r.branch == "left" and r.error > 0.1
    assert "lie on both branches" in r.note


def test_the_rocker_slider_of_seed_000_linkage_4_form() -> None:
    D, E1 = 0j, 0.06 + 0.03j
    rocker = [0.0, math.radians(25.0), math.radians(55.0)]
    lk = Linkage({"D": (0.0, 0.0)}, Crank("3", "D", "E", abs(E1), 1.0),
                 (RRP("E", "F", ("5", "6"), 0.2, Guide((0.0, -0.08), 0.0), "forward"),), frame_link="1")
    F = [z(p) for p in solve(lk, np.asarray([cmath.phase(E1) + r for r in rocker])).point["F"]]
    des = M.joint_by_inversion([(p.real, p.imag) for p in F], (0.0, 0.0), rocker, "F", "E")
    r = reanalyse_rocker_slider(D, rocker, z(des.joint), F)
    # the guide is taken along F₁ → F₃, here −x: the slider trails E along it
    assert r.error <= 1e-9 and r.one_branch and r.branch == "backward"
    assert abs(F[0] - z(des.joint)) == pytest.approx(0.2, rel=1e-12)


def test_position_counts_are_checked() -> None:
    with pytest.raises(OutOfDomain, match="two or three"):
        reanalyse_fourbar(0j, 1 + 0j, 0.3, 1.0, 1.0, [0.0], [0.0], 1 + 1j)
    with pytest.raises(OutOfDomain, match="two or three"):
        reanalyse_slider_crank(0j, 0.3, 1.0, [0.0, 1.0], [0.0, 0.1, 0.2], 0.0, 1 + 0j)


def test_a_coupler_point_design_with_the_lengths_of_seed_000_linkage_5() -> None:
    """l_CD = 95 mm, l_EC = 70 mm as the seed gives; its A, D and E_i stand in a figure the seed has
    lost, so these are our own: E_i on the line y = 120 mm, as the seed's lie on one line."""
    E = [(-0.05, 0.12), (0.0, 0.12), (0.05, 0.12)]
    des = M.fourbar_through_coupler_points((-0.1, 0.0), (0.0, 0.0), E, 0.095, 0.07, side=-1.0)
    assert (des.l_AB, des.l_BC, des.l_BE) == pytest.approx((0.04022, 0.15343, 0.15292), abs=5e-6)
    r = reanalyse_coupler(z(des.A), z(des.D), [z(p) for p in des.B], [z(p) for p in des.C], [z(p) for p in E])
    assert r.error <= 1e-12 and r.grashof == "crank_rocker_AB" and r.note == ""
    # γ_min where the crank lies along the frame, folded: BD = AD − AB (the cosine rule, by hand)
    bd = des.l_AD - des.l_AB
    cos_delta = (des.l_BC ** 2 + des.l_CD ** 2 - bd ** 2) / (2 * des.l_BC * des.l_CD)
    assert r.characteristics is not None and r.characteristics.gamma_min == pytest.approx(math.acos(cos_delta))
    assert math.degrees(r.characteristics.gamma_min) == pytest.approx(5.9885, abs=1e-4)
    # a coupler point off its line is seen: E₃ moved 1 mm
    off = reanalyse_coupler(z(des.A), z(des.D), [z(p) for p in des.B], [z(p) for p in des.C],
                            [z(E[0]), z(E[1]), z(E[2]) + 0.001])
    assert off.error == pytest.approx(0.001 / max(des.l_AB, des.l_BC, des.l_CD, des.l_AD), rel=1e-6)
