"""The exact class III group (RRR-III): every assembly closes its loops, the rates are the positions'
derivatives, an impossible or locked group is reported, and the six-bar's solution through exact.solve."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact import solve
from graphmech.exact.triad import assemblies, solve_triad
from graphmech.mechanisms.linkage import Crank, Linkage, Triad

MM = 1e-3
#: The scene kin.class_iii_sixbar: crank AB = 40 about A; B–C 75, F–D 60, G–E 85; CDE 55/65/50 mm.
GROUP = Triad(("B", "F", "G"), ("C", "D", "E"), ("2", "4", "5", "3"), (75 * MM, 60 * MM, 85 * MM),
              (55 * MM, 65 * MM, 50 * MM), ((85 * MM, 73 * MM), (123 * MM, 34 * MM), (128 * MM, 98 * MM)))
F, G = complex(150, -20) * MM, complex(60, 150) * MM
SIXBAR = Linkage({"A": (0.0, 0.0), "F": (F.real, F.imag), "G": (G.real, G.imag)},
                 Crank("1", "A", "B", 40 * MM, 10.0, 2.0), (GROUP,), frame_link="6")


def closes(y: Triad, zb: complex, zf: complex, zg: complex, t: tuple[complex, complex, complex]) -> float:
    """The largest relative misfit of an assembly's six lengths."""
    c, d, e = t
    got = [abs(c - zb), abs(d - zf), abs(e - zg), abs(d - c), abs(e - d), abs(c - e)]
    want = [*y.lengths, *y.ternary]
    return max(abs(g - w) / w for g, w in zip(got, want))


def test_every_assembly_closes_all_six_lengths_and_they_differ():
    zb = 40 * MM * complex(math.cos(math.radians(60)), math.sin(math.radians(60)))
    found = assemblies(GROUP, zb, F, G)
    assert len(found) == 2  # this group at φ = 60°: two assemblies, 40 mm and more apart
    assert max(closes(GROUP, zb, F, G, t) for t in found) < 1e-13
    assert abs(found[0][0] - found[1][0]) > 0.04
    # the ternary triangle keeps the start's hand: E left of C→D
    for c, d, e in found:
        assert ((d - c).conjugate() * (e - c)).imag > 0


@pytest.mark.parametrize("deg", [0.0, 80.0])
def test_an_assembly_next_to_the_dyads_limit_is_found(deg):
    # at φ = 0° and 80° the assembly near the figure has θ2 between the last scan node where the dyad
    # C–D–F closes and its limit (|CF| = l_CD + l4): the scan saw no sign change there and lost it —
    # the exact solution took the other assembly, 60 mm off, while the construction's Newton found this one
    zb = 40 * MM * complex(math.cos(math.radians(deg)), math.sin(math.radians(deg)))
    found = assemblies(GROUP, zb, F, G)
    assert len(found) == 2 and max(closes(GROUP, zb, F, G, t) for t in found) < 1e-12
    start = np.array([complex(*p) for p in GROUP.start])
    assert min(float(np.max(np.abs(np.array(t) - start))) for t in found) < 25 * MM


def test_the_nearest_assembly_to_the_start_is_taken():
    kin = solve(SIXBAR, np.radians([60.0]))
    assert kin.valid[0]
    c = complex(*kin.point["C"][0])
    assert abs(c - complex(84.5, 72.9) * MM) < 0.2 * MM  # the figure's C, not the other assembly's (93.5, 19.8)


def test_rates_are_the_derivatives_of_the_positions():
    # a crank turning at ω = 10 with ε = 2: positions at t = ±h along the motion, to second order
    h = 1e-5
    phi0 = math.radians(75.0)
    w, eps = 10.0, 2.0
    phis = phi0 + np.array([-w * h + eps * h * h / 2, 0.0, w * h + eps * h * h / 2])
    kin = solve(SIXBAR, phis)
    assert kin.valid.all()
    for p in "CDE":
        z = kin.point[p]
        v = (z[2] - z[0]) / (2 * h)
        a = (z[2] - 2 * z[1] + z[0]) / (h * h)
        assert np.allclose(v, kin.vel[p][1], rtol=0, atol=1e-7 * np.hypot(*kin.vel[p][1]))
        assert np.allclose(a, kin.acc[p][1], rtol=0, atol=1e-3 * np.hypot(*kin.acc[p][1]))
    for link in "2345":
        th = np.unwrap(kin.angle[link])
        assert (th[2] - th[0]) / (2 * h) == pytest.approx(kin.omega[link][1], rel=1e-7)


def test_velocities_satisfy_every_constraint_exactly():
    kin = solve(SIXBAR, np.radians([50.0, 60.0, 70.0]))
    P, V = kin.point, kin.vel
    for x, y in (("C", "B"), ("D", "F"), ("E", "G"), ("C", "D"), ("D", "E"), ("E", "C")):
        rate = np.sum((P[x] - P[y]) * (V[x] - V[y]), axis=1)  # d/dt |XY|²/2 = 0 on a rigid link
        assert np.max(np.abs(rate)) < 1e-15


def test_out_of_reach_is_invalid_with_a_reason():
    kin = solve(SIXBAR, np.radians([60.0, 250.0]))
    assert list(kin.valid) == [True, False]
    assert "class III group B-C, F-D, G-E (CDE): cannot be assembled" in kin.reason[1]
    assert np.all(kin.point["C"][1] == 0.0)


def test_three_binary_links_through_one_point_lock_the_group():
    # C, D, E a triangle; B, F, G on the lines OC, OD, OE through the origin O: the three binary
    # links' lines are concurrent, the group can turn about O to first order — its rates are unbounded
    c, d, e = complex(0.1, 0.0), complex(0.0, 0.12), complex(-0.08, -0.05)
    b, f, g = 2.0 * c, 1.6 * d, 1.8 * e
    y = Triad(("B", "F", "G"), ("C", "D", "E"), ("2", "4", "5", "3"),
              (abs(c - b), abs(d - f), abs(e - g)), (abs(d - c), abs(e - d), abs(c - e)),
              ((c.real, c.imag), (d.real, d.imag), (e.real, e.imag)))
    one = np.ones(1, dtype=complex)
    known = {n: (z * one, 0 * one, 0 * one) for n, z in (("B", b), ("F", f), ("G", g))}
    sol = solve_triad(y, known)
    assert sol.assembled[0] and not sol.valid[0]
    assert "dead centre" in sol.reason[0]
    assert abs(sol.z[0, 0] - c) < 1e-8  # the position is kept (a double root of the scan: to about √ε)
