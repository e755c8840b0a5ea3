"""graphmech.methods.kinetostatics called directly: group-by-group force polygons against the
matrix method (exact.kinetostatics) on random loads, with and without friction; the parallel guard."""
from __future__ import annotations


import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import graphmech.methods.kinetostatics as K
from graphmech.mechanisms.forces import ForceModel, LinkMass


def test_exactly_parallel_closing_lines_are_one_line_errors():
    kin = K.PolygonKinematics({}, {}, {}, {}, {}, 1.0, np.array([True]))
    with pytest.raises(K.DegenerateConstruction, match="grow without bound"):
        K._guard_parallel(np.array([0.0]), kin.valid, "group 2–3: parallel")


def _fourbar_linkage(a: float, b: float, c: float, d: float):
    from graphmech.mechanisms.linkage import RRR, Crank, Linkage, LinkPoint

    return Linkage({"A": (0.0, 0.0), "D": (d, 0.0)}, Crank("1", "A", "B", a, 10.0, 3.0),
                   (RRR("B", "C", "D", ("2", "3"), (b, c), "left"),),
                   (LinkPoint("S2", "2", ("B", "C"), b / 2, 0.01), LinkPoint("S3", "3", ("D", "C"), c / 3, 0.0)), "0")


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0.0, 6.28), m2=st.floats(0.1, 10.0), m3=st.floats(0.1, 10.0), f=st.floats(0.0, 500.0),
       angle=st.floats(-3.14, 3.14), friction=st.booleans())
def test_polygons_equal_the_matrix_method_on_random_loads(phi, m2, m3, f, angle, friction):
    """A crank-rocker (AB 60, BC 120, CD 90, AD 120 mm) at any angle, any loads, with or without
    friction: the group-by-group polygons and the matrix method give the same reactions and M_b."""
    from graphmech.exact.kinetostatics import solve_forces
    from graphmech.mechanisms.forces import PointForce, RevoluteFriction
    from graphmech.methods.polygons import build_polygons

    lk = _fourbar_linkage(0.06, 0.12, 0.09, 0.12)
    journals = tuple(RevoluteFriction(p, 0.1, 0.005) for p in "ABCD") if friction else ()
    model = ForceModel((LinkMass("2", "S2", m2, m2 * 0.002), LinkMass("3", "S3", m3, m3 * 0.001)),
                       (PointForce("3", "C", f, angle),), gravity=9.81, revolute_friction=journals)
    b = build_polygons(lk, {"l": 0.001, "v": 0.01, "a": 0.1})
    batch = b.g.prune(K.construction_targets(b)).evaluate_batch({"phi": np.array([phi])})
    kin = K.kinematics_from_construction(b, batch.values, batch.valid)
    sol = K.kinetostatics(lk, model, kin, polygons=False)
    ex = solve_forces(lk, model, np.array([phi]))
    size = max(abs(complex(r[0])) for r in sol.reactions.values())
    for key, r in sol.reactions.items():
        assert abs(complex(r[0]) - complex(*ex.reactions[key][0])) <= 1e-9 * size, key
    assert abs(sol.balancing_moment[0] - ex.balancing_moment[0]) <= 1e-9 * size * 0.06
    if not friction:
        lever = K.zhukovsky_lever(lk, model, kin)
        assert abs(lever.balancing_moment[0] - ex.balancing_moment[0]) <= 1e-9 * size * 0.06


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0.0, 6.28), m3=st.floats(0.1, 10.0), f=st.floats(0.0, 2000.0), fs=st.floats(0.0, 0.4),
       fv=st.floats(0.0, 0.3), e=st.floats(-30.0, 30.0))
def test_slider_crank_with_friction_equals_the_matrix_method(phi, m3, f, fs, fv, e):
    """An offset slider-crank (AB 100, BC 300 mm, offset e) at any angle, a piston force against +x,
    friction on the guide and in all three journals: polygons = matrix method (scipy root)."""
    from graphmech.exact.kinetostatics import solve_forces
    from graphmech.mechanisms.forces import PointForce, RevoluteFriction, SlidingFriction
    from graphmech.mechanisms.linkage import RRP, Crank, Guide, Linkage, LinkPoint
    from graphmech.methods.polygons import build_polygons

    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 150.0),
                 (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, e / 1000.0), 0.0), "forward"),),
                 (LinkPoint("S2", "2", ("B", "C"), 0.1, 0.0),), "0")
    model = ForceModel((LinkMass("2", "S2", 2.0, 0.02), LinkMass("3", "C", m3)), (PointForce("3", "C", f, np.pi),),
                       gravity=9.81, revolute_friction=tuple(RevoluteFriction(p, fv, 0.01) for p in "ABC"),
                       sliding_friction=(SlidingFriction("3", fs),))
    b = build_polygons(lk, {"l": 0.002, "v": 0.1, "a": 10.0})
    batch = b.g.prune(K.construction_targets(b)).evaluate_batch({"phi": np.array([phi])})
    kin = K.kinematics_from_construction(b, batch.values, batch.valid)
    sol = K.kinetostatics(lk, model, kin, polygons=False)
    ex = solve_forces(lk, model, np.array([phi]))
    assert ex.valid[0]
    size = max(abs(complex(r[0])) for r in sol.reactions.values())
    for key, r in sol.reactions.items():
        assert abs(complex(r[0]) - complex(*ex.reactions[key][0])) <= 1e-8 * size, key
    assert abs(sol.balancing_moment[0] - ex.balancing_moment[0]) <= 1e-8 * size * 0.1


# ----------------------------------------------------------------------------- the module's own pieces


def _slider_crank(omega: float = 10.0):
    from graphmech.mechanisms.linkage import RRP, Crank, Guide, Linkage

    return Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, omega),
                   (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, 0.0), 0.0), "forward"),), (), "0")


def _kinematics(lk, phi: float):
    from graphmech.methods.polygons import build_polygons

    b = build_polygons(lk, {"l": 0.002, "v": 0.01, "a": 0.5})
    batch = b.g.prune(K.construction_targets(b)).evaluate_batch({"phi": np.array([phi])})
    return K.kinematics_from_construction(b, batch.values, batch.valid)


def test_inertia_load_is_minus_m_a_and_minus_J_alpha():
    F, M, h = K.inertia_load(2.0, 0.01, 3.0 + 4.0j, -50.0)
    assert F == -6.0 - 8.0j and M == pytest.approx(0.5) and h == pytest.approx(0.05, rel=1e-15)
    # over positions, a centre of mass at rest has no force and no arm (not 0/0)
    F, M, h = K.inertia_load(1.0, 0.02, np.array([0j, 2.0 + 0j]), np.array([10.0, 10.0]))
    assert F.tolist() == [0j, -2.0 + 0j] and M.tolist() == [-0.2, -0.2] and h.tolist() == [0.0, 0.1]


def test_the_single_resultant_is_moved_so_that_its_moment_about_S_is_M_i():
    load = K.InertiaLoad("2", "S2", np.array([30.0 - 40.0j, 0j]), np.array([2.5, 1.0]), np.array([0.05, 0.0]))
    r = load.resultant_shift
    assert abs(r[0]) == pytest.approx(0.05, rel=1e-15)  # h = |M_i|/|F_i|
    assert (r[0].conjugate() * load.force[0]).imag == pytest.approx(2.5, rel=1e-14)  # r × F = M_i
    assert r[1] == 0j  # no force: a pure couple, nothing to move


def test_iteration_error_estimates_what_the_last_change_leaves():
    # q = 0.5: the changes 0.4, 0.2 leave 0.2 more
    assert K.iteration_error(1.6, 1.4, 1.0) == pytest.approx(0.2, rel=1e-12)
    # overshooting by turns (q = −0.5): what is left is a third of the last change
    assert K.iteration_error(0.9, 1.2, 0.6) == pytest.approx(0.1, rel=1e-12)
    # a ratio near 1 is kept at 0.9 (at most 9 × the last change), no change before: none estimated
    assert K.iteration_error(2.0, 1.0, 0.0) == pytest.approx(9.0, rel=1e-12)
    assert K.iteration_error(1.5, 1.0, 1.0) == 0.0


def test_carriers_name_the_link_that_first_carries_each_point():
    assert K.carriers(_slider_crank()) == {"A": "0", "B": "1", "C": "2"}
    assert K.carriers(_fourbar_linkage(0.06, 0.12, 0.09, 0.12)) == {"A": "0", "D": "0", "B": "1", "C": "2",
                                                                     "S2": "2", "S3": "3"}


def test_polygons_and_lever_on_the_slider_crank_at_90_degrees():
    """100 N against +x on the slider: the rod carries P/cos β, the crank needs M_b = −P·r (it brakes)."""
    from graphmech.mechanisms.forces import PointForce

    lk, model = _slider_crank(), ForceModel(forces=(PointForce("3", "C", 100.0, np.pi),))
    kin = _kinematics(lk, np.pi / 2)
    sol = K.kinetostatics(lk, model, kin)
    cos_b = np.sqrt(0.08) / 0.3
    assert abs(complex(sol.reactions[("2", "3")][0])) == pytest.approx(100.0 / cos_b, rel=1e-12)
    assert sol.balancing_moment[0] == pytest.approx(-10.0, rel=1e-12) and sol.iterations == 0
    assert K.zhukovsky_lever(lk, model, kin).balancing_moment[0] == pytest.approx(-10.0, rel=1e-12)


def test_the_lever_of_a_crank_at_rest_is_refused():
    from graphmech.mechanisms.forces import PointForce

    lk = _slider_crank(omega=0.0)
    with pytest.raises(K.DegenerateConstruction, match="the crank stands still: no virtual power"):
        K.zhukovsky_lever(lk, ForceModel(forces=(PointForce("3", "C", 100.0, np.pi),)), _kinematics(lk, 1.0))


def test_a_guide_on_a_moving_link_bears_the_opposite_reaction_on_the_same_line():
    """The tangent mechanism with a couple on the block 2 (it rides the bar 1): the bar's reaction on
    the block R_12 ⟂ AB acts off C by e = M_12/|R_12|; the bar bears −R_12 on that same line, so its
    moment about A is that of −R_12 at C less M_12 — and M_b balances it (nothing else on the bar)."""
    from graphmech.mechanisms.forces import LinkCouple, PointForce
    from graphmech.mechanisms.linkage import PRP, Crank, Guide, Linkage, LinkGuide

    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.15, 10.0),
                 (PRP("C", ("2", "3"), (LinkGuide("1", "A", "B"), Guide((0.1, 0.0), np.pi / 2))),), (), "4")
    model = ForceModel(forces=(PointForce("3", "C", 400.0, -np.pi / 2),), couples=(LinkCouple("2", 5.0, "M_2"),))
    kin = _kinematics(lk, np.radians(30.0))
    sol = K.kinetostatics(lk, model, kin)
    g12 = next(g for g in sol.guides if (g.frame, g.slider) == ("1", "2"))
    assert float(g12.moment[0]) == pytest.approx(-5.0, rel=1e-12)  # the block's moments about C
    r12, C = complex(g12.force[0]), complex(kin.point["C"][0])
    assert (np.conj(r12) * np.exp(1j * np.radians(30.0))).real == pytest.approx(0.0, abs=1e-9)  # ⟂ AB
    m_bar = (np.conj(C) * -r12).imag + 5.0  # −R_12 at C and the couple +5 N·m of its offset line, about A
    assert sol.balancing_moment[0] == pytest.approx(-m_bar, rel=1e-9)
    bar = next(g for g in sol.groups if g.name == "driver 1")
    assert dict(bar.chain)["R_21"][0] == pytest.approx(-r12, rel=1e-12)
