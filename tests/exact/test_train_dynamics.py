"""The exact dynamics and efficiency of a train: the power balance against the book's known
closed forms, the reduced inertia against a kinetic energy summed from 3-D vectors."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact.gear_train import solve
from graphmech.exact.train_dynamics import (
    angular_parts,
    converted_driver,
    converted_efficiency,
    independent_meshes,
    power_flow,
    reduced_inertia,
    reduced_moment,
    train_efficiency,
)
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh
from graphmech.mechanisms.train_dynamics import Body, MeshLosses, Worm


def two_k_h(z1: int = 20, z2: int = 30, z3: int = 80, copies: int = 1) -> GearTrain:
    """Sun 1, planet(s) 2 on H, ring 3 fixed; 1 driven."""
    planets = [f"2{'b' * c}" for c in range(copies)]
    members = (Member("1"), *(Member(p, "H") for p in planets), Member("3"), Member("H"))
    gears = (Gear("1", z1, "1"), *(Gear(p, z2, p) for p in planets), Gear("3", z3, "3"))
    meshes = tuple(m for p in planets for m in (Mesh("1", p), Mesh(p, "3", "internal")))
    return GearTrain(members, gears, meshes, fixed=("3",), inputs={"1": 1.0})


def seed_planetary() -> GearTrain:
    """Seed 000, 机械的运转 3: z1 = z2' = 20, z2 = z3 = 40, double planet 2–2', 3 fixed."""
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                     (Gear("1", 20, "1"), Gear("2", 40, "2"), Gear("2'", 20, "2"), Gear("3", 40, "3")),
                     (Mesh("1", "2"), Mesh("2'", "3")), fixed=("3",), inputs={"1": 10.0})


def test_seed_planetary_reduced_inertia_and_moment() -> None:
    t = seed_planetary()
    w = solve(t).omega
    bodies = [Body("1", 0.01), Body("2", 0.05, mass=6.0), Body("H", 0.18, moment=60.0)]
    assert reduced_inertia(t, w, bodies, "1", 0.01) == pytest.approx(0.14, rel=1e-14)
    assert reduced_moment(t, w, bodies, "1") == pytest.approx(-20.0, rel=1e-14)  # i_1H = −3


@pytest.mark.parametrize("z", [(20, 30, 80), (17, 40, 97), (12, 60, 132)])
@pytest.mark.parametrize("eta", [(0.98, 0.99), (0.9, 0.95)])
def test_sun_driving_power_balance_is_the_books_formula(z: tuple[int, int, int], eta: tuple[float, float]) -> None:
    t = two_k_h(*z)
    w = solve(t).omega
    i1h = w["1"] / w["H"]
    eta_h = eta[0] * eta[1]
    got = train_efficiency(t, w, MeshLosses(eta), "1", "H")
    assert got == pytest.approx(1 - (1 - eta_h) * (i1h - 1) / i1h, rel=1e-12, abs=0)
    # the carrier driving the sun: the sun is driven in the converted train, loss (1/η^H − 1)|P^H_1|
    back = train_efficiency(t, w, MeshLosses(eta), "H", "1")
    x = 1 - 1 / i1h
    assert back == pytest.approx(1 / (1 + x * (1 / eta_h - 1)), rel=1e-12, abs=0)


def test_identical_planets_are_counted_once_and_change_nothing() -> None:
    one, three = two_k_h(), two_k_h(copies=3)
    assert independent_meshes(three) == [0, 1, 2, 4]  # the 2nd and 3rd planets' ring meshes repeat
    e1 = train_efficiency(one, solve(one).omega, MeshLosses((0.97, 0.98)), "1", "H")
    e3 = train_efficiency(three, solve(three).omega, MeshLosses((0.97, 0.98) * 3), "1", "H")
    assert e3 == pytest.approx(e1, rel=1e-15)


def test_ordinary_trains_in_series_multiply() -> None:
    t = GearTrain((Member("1"), Member("2"), Member("3")),
                  (Gear("1", 20, "1"), Gear("2", 40, "2"), Gear("2'", 18, "2"), Gear("3", 54, "3")),
                  (Mesh("1", "2"), Mesh("2'", "3")), inputs={"1": 100.0})
    w = solve(t).omega
    assert train_efficiency(t, w, MeshLosses((0.97, 0.95)), "1", "3") == pytest.approx(0.97 * 0.95, rel=1e-15)
    # driven backwards the meshes still lose (1 − η) each
    assert train_efficiency(t, w, MeshLosses((0.97, 0.95)), "3", "1") == pytest.approx(0.97 * 0.95, rel=1e-15)


def test_a_worm_that_self_locks_cannot_be_driven_by_its_wheel() -> None:
    t = GearTrain((Member("1", None), Member("2")), (Gear("1", 1, "1"), Gear("2", 40, "2")),
                  (Mesh("1", "2", "worm", sign=1),), inputs={"1": 150.0})
    w = solve(t).omega
    gamma, phi = math.atan(1 / 10), math.atan(0.12)  # tan γ = 0.1 < f_v = 0.12
    losses = MeshLosses((1.0,), (Worm(0, gamma, phi),))
    assert train_efficiency(t, w, losses, "1", "2") == pytest.approx(math.tan(gamma) / math.tan(gamma + phi), rel=1e-14)
    back = power_flow(t, w, losses, "2", "1")
    assert back.eta == pytest.approx(math.tan(gamma - phi) / math.tan(gamma), rel=1e-14)
    assert back.eta < 0


def test_converted_train_efficiency_and_its_driver() -> None:
    t = two_k_h()
    w = solve(t).omega
    losses = MeshLosses((0.98, 0.99))
    flow = power_flow(t, w, losses, "1", "H")
    assert converted_driver(t, w, flow, "H") == "1"
    assert converted_efficiency(t, losses, "H", "1") == pytest.approx(0.98 * 0.99, rel=1e-15)
    flow = power_flow(t, w, losses, "H", "1")
    assert converted_driver(t, w, flow, "H") == "3"  # the fixed ring drives the converted train


def test_refusals() -> None:
    t = two_k_h()
    w = solve(t).omega
    with pytest.raises(OutOfDomain, match="one member"):
        power_flow(t, w, MeshLosses((1.0, 1.0)), "1", "1")
    with pytest.raises(OutOfDomain, match="fixed"):
        power_flow(t, w, MeshLosses((1.0, 1.0)), "1", "3")
    with pytest.raises(NoSolution, match="at rest"):
        reduced_inertia(t, w, [], "3", 1e-3)
    with pytest.raises(OutOfDomain, match="fixed axis"):
        reduced_inertia(t, w, [Body("1", 0.1, mass=1.0)], "1", 1e-3)


def _bevel_train(zs: tuple[int, int, int]) -> GearTrain:
    """A bevel differential: 1 and 3 on the main axis, planet 2 at 90° on H; 3 fixed."""
    z1, z2, z3 = zs
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                     (Gear("1", z1, "1"), Gear("2", z2, "2"), Gear("3", z3, "3")),
                     (Mesh("1", "2", "bevel", sign=-1), Mesh("2", "3", "bevel", sign=1)),
                     fixed=("3",), inputs={"1": 3.0})


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(12, 60), z2=st.integers(12, 60), dz=st.integers(0, 60), w1=st.floats(-500, 500).filter(lambda x: abs(x) > 1e-3),
       j=st.lists(st.floats(0.0, 2.0), min_size=4, max_size=4), jt=st.floats(0.0, 2.0), m=st.floats(0.0, 10.0),
       arm=st.floats(0.01, 1.0), count=st.integers(1, 4), bevel=st.booleans())
def test_reduced_inertia_is_twice_the_kinetic_energy(z1: int, z2: int, dz: int, w1: float, j: list[float], jt: float,
                                                     m: float, arm: float, count: int, bevel: bool) -> None:
    """T from 3-D vectors: the planet's absolute ω = ω_H ẑ_H + spin û_p, its inertia tensor
    diag(J_t, J_t, J) in its own frame, its centre at the arm."""
    if bevel:
        t = _bevel_train((z1, z2, z1 + dz))
        axes = {"2": "+y"}
    else:
        t = GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                      (Gear("1", z1, "1"), Gear("2", z2, "2"), Gear("3", z1 + 2 * z2 + dz, "3")),
                      (Mesh("1", "2"), Mesh("2", "3", "internal")), fixed=("3",), inputs={"1": w1})
        axes = {}
    t = t.with_inputs({"1": w1})
    w = solve(t).omega
    bodies = [Body("1", j[0]), Body("2", j[1], jt, m, arm, count=count), Body("3", j[2]), Body("H", j[3])]
    u_h = np.array([1.0, 0.0, 0.0])
    u_p = np.array([0.0, 1.0, 0.0]) if bevel else u_h
    omega_p = w["H"] * u_h + (w["2"] - w["H"]) * u_p  # the spin relative to H, along the planet's axis
    axial = float(omega_p @ u_p)
    across = float(np.linalg.norm(omega_p - axial * u_p))
    centre_v = np.cross(w["H"] * u_h, np.array([0.0, 0.0, arm]))
    t_planet = 0.5 * (j[1] * axial**2 + jt * across**2 + m * float(centre_v @ centre_v))
    energy = 0.5 * (j[0] * w["1"] ** 2 + j[3] * w["H"] ** 2) + count * t_planet
    assert reduced_inertia(t, w, bodies, "1", 1e-3, axes) == pytest.approx(2 * energy / w1**2, rel=1e-12, abs=1e-300)


def test_a_bevel_planets_speed_is_a_vector_sum() -> None:
    t = _bevel_train((20, 20, 20))
    w = solve(t).omega  # ω_1 = 3, ω_H = 1.5, spin ω_2 − ω_H relative to H
    axial, across = angular_parts(t, w, "2", {"2": "+y"})
    assert across == pytest.approx(1.5)
    assert axial == pytest.approx(w["2"] - w["H"])
    with pytest.raises(OutOfDomain, match="diameter"):
        reduced_inertia(t, w, [Body("2", 0.1)], "1", 1e-3, {"2": "+y"})
    with pytest.raises(OutOfDomain, match="state its arm"):
        reduced_inertia(t, w, [Body("2", 0.1, 0.05, 1.0)], "1", 1e-3, {"2": "+y"})
