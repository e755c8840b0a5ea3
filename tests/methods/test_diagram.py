"""The kinematic diagram at μl (methods/diagram.py): each point as the draftsman finds it, against
closed forms, in drawing millimetres from the first frame point."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.errors import AssemblyError
from graphmech.mechanisms.linkage import RPP, RPR, RRP, RRR, Crank, Guide, Linkage, LinkPoint, SliderInput
from graphmech.methods import diagram
from graphmech.methods.linkage_construction import LinkageConstruction

MU = 0.002  # m/mm


def build(linkage: Linkage, param: str = "phi") -> LinkageConstruction:
    b = LinkageConstruction(linkage, {"l": MU}, param=param)
    b.g.param(param)
    diagram.add_frame(b)
    for part in (linkage.driver, *linkage.dyads, *linkage.points):
        diagram.add(b, part)
    return b


def drawn(b: LinkageConstruction, value: float, position: str | None = None) -> dict[str, np.ndarray]:
    """Every mechanism point, mm, with the driver at ``value`` (φ in rad or s in m)."""
    got = b.g.prune(list(b.mech.values())).evaluate({b.param: value}, position)
    return {name: np.array(got[step]) for name, step in b.mech.items()}


def fourbar(branch: str = "left", d: float = 0.1) -> Linkage:
    return Linkage({"A": (0.0, 0.0), "D": (d, 0.0)}, Crank("1", "A", "B", 0.04, 10.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), branch),),  # type: ignore[arg-type]
                   (LinkPoint("E", "2", ("B", "C"), 0.06, 0.02), LinkPoint("F", "1", ("B",), 0.01, -0.005)))


def cross(u: np.ndarray, v: np.ndarray) -> float:
    return float(u[0] * v[1] - u[1] * v[0])


@pytest.mark.parametrize("phi_deg", [0.0, 60.0, 135.0, 250.0])
def test_the_crank_tip_and_the_rrr_joint_keep_their_lengths(phi_deg):
    phi = math.radians(phi_deg)
    p = drawn(build(fourbar()), phi)
    assert p["A"] == pytest.approx([0.0, 0.0]) and p["D"] == pytest.approx([50.0, 0.0])
    assert p["B"] == pytest.approx([20.0 * math.cos(phi), 20.0 * math.sin(phi)], abs=1e-12)  # 40 mm at μl
    assert np.hypot(*(p["C"] - p["B"])) == pytest.approx(60.0, rel=1e-13)
    assert np.hypot(*(p["C"] - p["D"])) == pytest.approx(45.0, rel=1e-13)
    assert cross(p["D"] - p["B"], p["C"] - p["B"]) > 0.0  # left of B→D


def test_the_right_branch_is_the_mirror_image_in_bd():
    left, right = drawn(build(fourbar("left")), 1.0), drawn(build(fourbar("right")), 1.0)
    b, d = left["B"], left["D"]
    u = (d - b) / np.hypot(*(d - b))
    c = left["C"] - b
    mirrored = b + 2 * np.dot(c, u) * u - c
    assert right["C"] == pytest.approx(mirrored, abs=1e-12)


def test_extra_points_along_and_left_of_their_base():
    p = drawn(build(fourbar()), math.radians(60.0))
    u = (p["C"] - p["B"]) / 60.0
    n = np.array([-u[1], u[0]])
    assert p["E"] == pytest.approx(p["B"] + 30.0 * u + 10.0 * n, abs=1e-12)  # 60 mm along BC, 20 mm left
    assert p["F"] == pytest.approx(p["B"] + [5.0, -2.5], abs=1e-12)  # one base point: a fixed offset


@pytest.mark.parametrize("branch, sign", [("forward", 1.0), ("backward", -1.0)])
def test_the_rrp_slider_on_its_offset_guide(branch, sign):
    """x_C = r cos φ ± √(l² − (r sin φ − e)²) on the guide y = e."""
    r, l, e, phi = 0.05, 0.2, 0.01, math.radians(40.0)
    link = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", r, 1.0),
                   (RRP("B", "C", ("2", "3"), l, Guide((0.0, e), 0.0), branch),))  # type: ignore[arg-type]
    b = build(link)
    x = r * math.cos(phi) + sign * math.sqrt(l * l - (r * math.sin(phi) - e) ** 2)
    assert drawn(b, phi)["C"] == pytest.approx([x / MU, e / MU], rel=1e-13)
    assert b.slider_dir["C"] == (1.0, 0.0) and "3" in b.translating


def test_the_rpp_joint_is_the_slot_through_b_on_the_guide():
    phi, slot, guide = math.radians(70.0), math.radians(60.0), math.radians(30.0)
    link = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.04, 1.0),
                   (RPP("B", "C", ("2", "3"), slot, Guide((0.0, 0.0), guide)),))
    b = build(link)
    p = drawn(b, phi)
    # B + t (cos 60°, sin 60°) = u (cos 30°, sin 30°)
    bx, by = 20.0 * math.cos(phi), 20.0 * math.sin(phi)
    t, u = np.linalg.solve([[math.cos(slot), -math.cos(guide)], [math.sin(slot), -math.sin(guide)]], [-bx, -by])
    assert p["C"] == pytest.approx([u * math.cos(guide), u * math.sin(guide)], abs=1e-12)
    assert p["B2"] == pytest.approx(p["B"]) and p["B3"] == pytest.approx(p["B"])  # B on the block and on the slot
    assert b.translating >= {"2", "3"}


def test_a_slider_driver_and_an_rpr_block_name_their_coincident_points():
    """A slider driven along a 30° guide: no frame point, so the guide's point is the drawing's origin."""
    guide = Guide((1.0, 2.0), math.radians(30.0))
    link = Linkage({}, SliderInput("1", "B", guide, 1.0), ())
    p = drawn(build(link, "s"), 0.05)
    assert p["B"] == pytest.approx([12.5 * math.sqrt(3.0), 12.5], rel=1e-14)  # 50 mm along at μl
    quick = Linkage({"A": (0.0, 0.0), "C": (0.0, 0.1)}, Crank("1", "A", "B", 0.03, 1.0),
                    (RPR("C", "B", ("3", "2")),))
    b = build(quick)
    assert b.mech["B3"] == b.mech["B2"] == b.mech["B"]  # the block's pivot B, on the bar 3 and on the block 2


def test_a_mechanism_far_from_the_origin_is_drawn_from_its_first_frame_point():
    far = Linkage({"A": (1.0e6, -2.0e6), "D": (1.0e6 + 0.1, -2.0e6)}, Crank("1", "A", "B", 0.04, 10.0),
                  (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"),))
    near = drawn(build(fourbar()), 0.7)
    got = drawn(build(far), 0.7)
    assert got["B"] == pytest.approx(near["B"], abs=1e-12)  # no digits lost to the offset
    assert got["C"] == pytest.approx(near["C"], abs=1e-6)  # D itself is 1e6 + 0.1 m, rounded at 1e-10 m


def test_each_joint_step_says_how_it_is_found():
    b = build(fourbar())
    c = b.g.steps[b.mech["C"]]
    assert c.text == "C = circle(B, l2) ∩ circle(D, l3), left of B→D"
    assert (c.kind, c.role, c.panel, c.label, c.inputs) == ("point", "given", "mechanism", "C", ("B", "D"))
    assert b.g.steps[b.mech["B"]].text == "B on the crank circle about A at φ"
    assert b.g.steps[b.mech["A"]].text == "frame point A"


def test_a_linkage_that_cannot_close_names_the_step_and_the_lengths():
    b = build(fourbar(d=0.3))  # |BD| ≥ 0.26 m > l2 + l3 = 0.21 m
    with pytest.raises(AssemblyError) as info:
        drawn(b, 0.0, "3")
    assert str(info.value) == ("C = circle(B, l2) ∩ circle(D, l3), left of B→D: cannot be assembled at 3: "
                               "|BD| = 0.26 m > l2 + l3 = 0.21 m")
    assert isinstance(info.value, ArithmeticError)


# ---------------------------------------------------------------------------- class III group


def _group_kernel(ops, b, start, lengths=(75.0, 60.0, 85.0)):
    from graphmech.methods.diagram import triad_position

    return triad_position(ops, b, (150.0, -20.0), (60.0, 150.0), lengths=lengths, ternary=(55.0, 65.0, 50.0),
                          hand=1.0, start=start, name="class III group X")


FIGURE_START = ((85.0, 73.0), (123.0, 34.0), (128.0, 98.0))


def test_newton_finds_the_class_iii_assembly_nearest_the_start_to_the_last_bits():
    from graphmech.exact.triad import assemblies
    from graphmech.geometry.kernels import ScalarOps
    from graphmech.mechanisms.linkage import Triad

    b = (40.0 * math.cos(math.radians(60)), 40.0 * math.sin(math.radians(60)))
    ops = ScalarOps()
    got = _group_kernel(ops, b, FIGURE_START)
    y = Triad(("B", "F", "G"), ("C", "D", "E"), ("2", "4", "5", "3"), (75.0, 60.0, 85.0), (55.0, 65.0, 50.0),
              FIGURE_START)
    want = min(assemblies(y, complex(*b), complex(150, -20), complex(60, 150)),
               key=lambda t: abs(t[0] - complex(*FIGURE_START[0])))
    for k in range(3):
        assert abs(complex(got[2 * k], got[2 * k + 1]) - want[k]) < 1e-12 * 100
    assert all(isinstance(v, float) for v in got)
    assert 1.0 <= ops.conds["?"] < 10.0  # a well-shaped group: the Jacobian's condition number


def test_newton_for_a_class_iii_group_batch_marks_the_positions_out_of_reach():
    from graphmech.geometry.kernels import ArrayOps, ScalarOps

    phi = np.radians([60.0, 250.0, 75.0])
    b = (40.0 * np.cos(phi), 40.0 * np.sin(phi))
    ops = ArrayOps(3)
    got = _group_kernel(ops, b, FIGURE_START)
    assert list(ops.bad) == [False, True, False]
    (why,) = [text for _, text in ops.failures.values()]
    assert why.startswith("cannot be assembled: class III group X: Newton's method from the start found no assembly")
    assert got[0][1] == 0.0 and np.all(np.isfinite(got[0]))
    one = ScalarOps()  # the scalar path raises, naming the step
    with pytest.raises(AssemblyError, match="found no assembly"):
        _group_kernel(one, (b[0][1], b[1][1]), FIGURE_START)


def test_newton_over_several_positions_follows_the_branch_from_the_previous_one():
    """Continuation: the crank from 135° back to 90° with the group started on its upper assembly.
    Each position starts from the last, so the upper branch is kept all the way — Newton from the
    start at every position would fall to the lower one at 90° (nearer the start there) — and the
    exact elimination, taking the assembly nearest the previous one's, agrees to the last bits."""
    from graphmech.exact.triad import assemblies, solve_triad
    from graphmech.geometry.kernels import ArrayOps
    from graphmech.mechanisms.linkage import Triad

    b135 = 40.0 * complex(math.cos(math.radians(135)), math.sin(math.radians(135)))
    y = Triad(("B", "F", "G"), ("C", "D", "E"), ("2", "4", "5", "3"), (75.0, 60.0, 85.0), (55.0, 65.0, 50.0),
              FIGURE_START)
    upper = max(assemblies(y, b135, complex(150, -20), complex(60, 150)), key=lambda t: t[0].imag)
    start = tuple((z.real, z.imag) for z in upper)
    phi = np.radians(np.arange(135.0, 89.0, -5.0))
    zb = 40.0 * np.exp(1j * phi)
    got = _group_kernel(ArrayOps(len(phi)), (zb.real, zb.imag), start)
    c = got[0] + 1j * got[1]
    assert np.abs(np.diff(c)).max() < 6.0  # mm: a continuous path, no jump to the other branch
    assert c[-1].imag > 60.0  # at 90°: the upper assembly C ≈ (71.2, 63.6), not the lower (70.9, 15.4)
    # the lower one is the nearer to the start there: from the start alone Newton would take it
    at90 = assemblies(y, complex(zb[-1]), complex(150, -20), complex(60, 150))
    nearest = min(at90, key=lambda t: sum(abs(t[k] - complex(*start[k])) ** 2 for k in range(3)))
    assert nearest[0].imag < 20.0
    line = np.full(len(phi), 1.0 + 0j)
    known = {"B": (zb, 0 * line, 0 * line), "F": (complex(150, -20) * line, 0 * line, 0 * line),
             "G": (complex(60, 150) * line, 0 * line, 0 * line)}
    sol = solve_triad(Triad(y.outer, y.inner, y.links, y.lengths, y.ternary, start), known)
    for k in range(3):
        assert np.abs(sol.z[k] - (got[2 * k] + 1j * got[2 * k + 1])).max() < 1e-10


@pytest.mark.parametrize("e", [0.03, -0.03])
def test_an_offset_guide_bars_foot_is_where_its_line_touches_the_circle_of_radius_e(e: float) -> None:
    """φ = 0: C = (0, −0.04), B = (0.03, 0): the circle on CB as diameter cuts the circle (C, |e|) at
    F = C + e·n̂ with û = CB/(t + ie) (t = 0.04): F = (−0.0084, −0.0112) for e = 0.03 (left of C→B),
    its mirror in CB, (0.03, −0.04), for e = −0.03 (F→B straight up)."""
    from tests.scenes.methods.linkages import OFFSET_GUIDE_BAR

    y = OFFSET_GUIDE_BAR.dyads[0]
    link = Linkage(OFFSET_GUIDE_BAR.frame_points, OFFSET_GUIDE_BAR.driver,
                   (RPR(y.p, y.q, y.links, "second", e),))  # type: ignore[union-attr]
    b = build(link)
    got = b.g.prune([b.mech[diagram.tangent_name(link.dyads[0])]]).evaluate({b.param: 0.0})  # type: ignore[arg-type]
    f = np.array(got[diagram.tangent_name(link.dyads[0])]) * MU  # type: ignore[arg-type]
    want = (-0.0084, -0.0112) if e > 0 else (0.03, -0.04)
    assert f == pytest.approx(want, abs=1e-15)
    c, bb = np.array([0.0, -0.04]), np.array([0.03, 0.0])
    assert np.linalg.norm(f - c) == pytest.approx(0.03, rel=1e-13)
    assert np.dot(f - c, bb - f) == pytest.approx(0.0, abs=1e-16)  # CF ⟂ FB: FB is tangent at F
    assert "B3" in b.mech and b.mech["B3"] == b.mech["B"]
