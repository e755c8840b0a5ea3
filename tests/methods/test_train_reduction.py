"""The book's reduced inertia and moment through a train against the kinetic energy and power."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact.gear_train import solve
from graphmech.exact.train_dynamics import reduced_inertia, reduced_moment
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh
from graphmech.mechanisms.train_dynamics import Body
from graphmech.methods.train_reduction import (
    book_reduced_inertia,
    book_reduced_moment,
    ratios,
)


def seed() -> GearTrain:
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                     (Gear("1", 20, "1"), Gear("2", 40, "2"), Gear("2'", 20, "2"), Gear("3", 40, "3")),
                     (Mesh("1", "2"), Mesh("2'", "3")), fixed=("3",), inputs={"1": 1.0})


def test_the_seeds_planetary_train() -> None:
    """Seed 000: J = J1 + (J2 + J2')(ω2/ω1)² + (m2 + m2')(v2/ω1)² + J_H(ω_H/ω1)² = 0.14 kg·m²;
    M = M_H ω_H/ω1 = 60·(−1/3) = −20 N·m; the arm m(z1 + z2)/2 = 0.3 m."""
    t = seed()
    w = solve(t).omega
    bodies = [Body("1", 0.01), Body("2", 0.05, mass=6.0), Body("H", 0.18, moment=60.0)]
    assert ratios(t, w, "1")["H"] == pytest.approx(-1 / 3)
    assert book_reduced_inertia(t, w, bodies, "1", 0.01) == pytest.approx(0.14, rel=1e-14)
    assert book_reduced_moment(t, w, bodies, "1") == pytest.approx(-20.0, rel=1e-14)
    # reduced to the carrier: J_H = J_1·i_1H² …, M = M_H
    assert book_reduced_moment(t, w, bodies, "H") == pytest.approx(60.0, rel=1e-14)
    assert book_reduced_inertia(t, w, bodies, "H", 0.01) == pytest.approx(0.14 * 9, rel=1e-14)


@settings(max_examples=40, deadline=None)
@given(j=st.lists(st.floats(0.0, 1.0), min_size=3, max_size=3), m=st.floats(0.0, 5.0), jt=st.floats(0.0, 1.0),
       mom=st.lists(st.floats(-100, 100), min_size=3, max_size=3), count=st.integers(1, 5), bevel=st.booleans())
def test_book_and_exact_agree(j: list[float], m: float, jt: float, mom: list[float], count: int, bevel: bool) -> None:
    if bevel:
        t = GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                      (Gear("1", 24, "1"), Gear("2", 16, "2"), Gear("3", 30, "3")),
                      (Mesh("1", "2", "bevel", sign=-1), Mesh("2", "3", "bevel", sign=1)),
                      fixed=("3",), inputs={"1": 7.0})
        axes, arm = {"2": "-y"}, 0.05
    else:
        t = seed()
        axes, arm = {}, None
    w = solve(t).omega
    bodies = [Body("1", j[0], moment=mom[0]), Body("2", j[1], jt, m, arm, mom[1], count), Body("H", j[2], moment=mom[2])]
    for to in ("1", "H", "2"):
        assert book_reduced_inertia(t, w, bodies, to, 0.01, axes) == pytest.approx(
            reduced_inertia(t, w, bodies, to, 0.01, axes), rel=1e-12, abs=1e-300)
        assert book_reduced_moment(t, w, bodies, to, axes) == pytest.approx(
            reduced_moment(t, w, bodies, to, axes), rel=1e-12, abs=1e-9)


def test_refusals() -> None:
    t = seed()
    w = solve(t).omega
    with pytest.raises(NoSolution, match="at rest"):
        book_reduced_inertia(t, w, [], "3", 0.01)
    with pytest.raises(OutOfDomain, match="fixed axis"):
        book_reduced_inertia(t, w, [Body("H", 0.1, mass=2.0)], "1", 0.01)
