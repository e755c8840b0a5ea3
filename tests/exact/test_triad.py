"""The exact class III group (RRR-III): every assembly closes its loops, the rates are the positions'
derivatives, an impossible or locked group is reported, and the six-bar's solution through exact.solve."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact import solve
from graphmech.exact.triad import assemblies, assemblies_at, solve_triad
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


def test_the_assemblies_at_several_positions_are_those_found_one_position_at_a_time_to_the_bit():
    # every root of every position is narrowed in one bisection: the same halvings as alone; at 200°
    # (AB = 40) the group cannot be assembled, and at 0° one root sits next to the dyad's limit
    zb = 40 * MM * np.exp(1j * np.radians([60.0, 200.0, 0.0, 80.0, 135.0]))
    line = np.ones(zb.size, dtype=complex)
    together = assemblies_at(GROUP, zb, F * line, G * line)
    alone = [assemblies(GROUP, complex(b), F, G) for b in zb]
    assert together == alone
    assert [len(t) for t in together] == [2, 0, 2, 2, 2]


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


# ------------------------------------------------------- a slider leg: the IC engine driven from EG

def _engines():
    """The IC engine as scened twice: driven from EG (a class III group with the piston C as a slider
    leg) and from AB (three dyads) — the same linkage link for link."""
    from graphmech.scene import load_scene
    from tests.conftest import SCENES

    eg = load_scene(SCENES / "kin.ic_engine_EG.toml").linkage
    ab = load_scene(SCENES / "kin.ic_engine_AB.toml").linkage
    return eg, ab


def test_a_slider_legs_assemblies_put_its_pin_on_the_guide_and_close_the_other_legs():
    import dataclasses

    eg, _ = _engines()
    y = next(d for d in eg.dyads if isinstance(d, Triad))
    assert y.slides(1) and not y.slides(0) and y.known_outer == ("A", "E")
    ze = complex(-100, -20) * MM + 63 * MM * complex(math.cos(math.radians(116)), math.sin(math.radians(116)))
    found = assemblies(y, 0j, 0j, ze)
    assert len(found) >= 2
    for b, c, d in found:
        assert abs(c.real) < 1e-15  # C on the vertical guide x = 0
        assert abs(abs(b) - 36 * MM) < 1e-13 and abs(abs(d - ze) - 73 * MM) < 1e-13
        assert abs(abs(c - b) - 90 * MM) < 1e-13 and abs(abs(d - c) - 75 * MM) < 1e-13
        assert abs(abs(b - d) - 75 * MM) < 1e-13
    # the scan starts at the first pivoted leg whichever leg slides: the same group with its legs
    # listed C, B, D finds the same assemblies
    moved = dataclasses.replace(y, outer=("C", "A", "E"), inner=("C", "B", "D"), links=("4", "2", "5", "3"),
                                lengths=(0.0, 36 * MM, 73 * MM), ternary=(90 * MM, 75 * MM, 75 * MM),
                                start=(y.start[1], y.start[0], y.start[2]), guides=(y.guides[1], None, None))
    again = assemblies(moved, 0j, 0j, ze)
    assert sorted((round(b.real, 12), round(b.imag, 12)) for _, b, _ in again) == \
        sorted((round(b.real, 12), round(b.imag, 12)) for b, _, _ in found)


@pytest.mark.parametrize("phi_ab", [100.0, 120.0, 135.0, 150.0, 170.0, 200.0, 250.0, 280.0, 330.0])
def test_the_engine_driven_from_eg_moves_as_the_engine_driven_from_ab(phi_ab):
    """An independent check of the class III solution: the class II engine (closed-form dyads) at
    φ2 gives GE's angle, ω6 and α6; the class III engine driven from EG with exactly those must
    give every point's position, velocity and acceleration and ω2 = 10 rad/s, α2 = 0 back."""
    import dataclasses

    eg, ab = _engines()
    k2 = solve(ab, np.radians([phi_ab]))
    assert k2.valid[0]
    theta6, w6, a6 = (float(k2.angle["6"][0]), float(k2.omega["6"][0]), float(k2.alpha["6"][0]))
    y = next(d for d in eg.dyads if isinstance(d, Triad))
    near = tuple((round(k2.point[p][0][0], 3), round(k2.point[p][0][1], 3)) for p in y.inner)  # the start, to a mm
    eg = dataclasses.replace(eg, driver=dataclasses.replace(eg.driver, omega=w6, epsilon=a6),
                             dyads=tuple(dataclasses.replace(d, start=near) if d is y else d for d in eg.dyads))
    k3 = solve(eg, np.array([theta6]))
    assert k3.valid[0], k3.reason
    size = 0.2  # m: the engine's size, for positions
    for p in ("B", "C", "D", "E", "H", "I"):
        assert np.abs(k3.point[p][0] - k2.point[p][0]).max() < 1e-12 * size
        assert np.abs(k3.vel[p][0] - k2.vel[p][0]).max() < 1e-9 * max(1.0, np.abs(k2.vel[p][0]).max())
        assert np.abs(k3.acc[p][0] - k2.acc[p][0]).max() < 1e-9 * max(1.0, np.abs(k2.acc[p][0]).max())
    assert float(k3.omega["2"][0]) == pytest.approx(10.0, abs=1e-9)
    assert float(k3.alpha["2"][0]) == pytest.approx(0.0, abs=1e-8)
    for link in ("3", "5", "7"):
        assert float(k3.omega[link][0]) == pytest.approx(float(k2.omega[link][0]), abs=1e-9)
        assert float(k3.alpha[link][0]) == pytest.approx(float(k2.alpha[link][0]), abs=1e-7)
    assert float(k3.omega["4"][0]) == 0.0 and float(k3.angle["4"][0]) == pytest.approx(math.pi / 2)


def test_the_eg_scenes_velocities_are_the_ab_engines_scaled_by_the_drivers_ratio():
    """At the crank angle where GE stands at the EG scene's 116°, the EG scene (ω6 = 3 rad/s) has the
    AB engine's velocities times 3/ω6(AB)."""
    eg, ab = _engines()
    lo, hi = math.radians(120.0), math.radians(150.0)  # θ6 rises through 116° here
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if float(solve(ab, np.array([mid])).angle["6"][0]) < math.radians(116.0):
            lo = mid
        else:
            hi = mid
    k2 = solve(ab, np.array([0.5 * (lo + hi)]))
    assert float(k2.angle["6"][0]) == pytest.approx(math.radians(116.0), abs=1e-12)
    k3 = solve(eg, np.radians([116.0]))
    ratio = 3.0 / float(k2.omega["6"][0])
    for p in ("B", "C", "D", "E", "I"):
        assert np.abs(k3.point[p][0] - k2.point[p][0]).max() < 1e-12
        assert np.abs(k3.vel[p][0] - ratio * k2.vel[p][0]).max() < 1e-9 * np.abs(k3.vel[p][0]).max()
    assert float(k3.omega["2"][0]) == pytest.approx(10.0 * ratio, rel=1e-9)
    assert float(k3.omega["2"][0]) == pytest.approx(11.2483096, abs=1e-7)  # the figure's ω2


def test_a_branch_that_ends_between_two_positions_is_reported_not_jumped(monkeypatch):
    """A branch never crosses a singular position, so its velocity determinant keeps its sign. Where
    only the other assembly is left at a position (the group locked since the last one: here the
    figure's assembly is taken away from 80° on, as if it had ended at 77°), that position is
    reported invalid, not jumped to. (The six-bar's two assemblies both live from 268° to 140° and
    vanish together at its lock near 142°, so the case is staged by removing one.)"""
    import graphmech.exact.triad as triad

    phi = np.radians([60.0, 70.0, 80.0, 90.0])
    zb = 40 * MM * np.exp(1j * phi)
    line = np.ones(len(phi), dtype=complex)
    known = {"B": (zb, 0 * line, 0 * line), "F": (F * line, 0 * line, 0 * line), "G": (G * line, 0 * line, 0 * line)}
    followed = solve_triad(GROUP, known)
    assert list(followed.valid) == [True, True, True, True]  # the figure's assembly lives on to 140°
    true_assemblies = triad.assemblies_at

    def without_the_followed(y, b, f, g):  # from 80° on only the other assembly is left
        found = true_assemblies(y, b, f, g)
        return [at if k < 2 else [t for t in at if abs(t[0] - followed.z[0, k]) > 1e-9]
                for k, at in enumerate(found)]

    monkeypatch.setattr(triad, "assemblies_at", without_the_followed)
    sol = solve_triad(GROUP, known)
    assert list(sol.valid) == [True, True, False, False]
    assert list(sol.assembled) == [True, True, True, True]
    assert "its branch ends before this position" in sol.reason[2]
    assert sol.sign[0] == sol.sign[1] == -sol.sign[2]
    # one position at a time (each from the start) nothing is reported: the other branch is a branch
    alone = solve_triad(GROUP, {k: tuple(v[2:3] for v in t) for k, t in known.items()})
    assert alone.valid[0]
