"""The coaxial condition as the book writes it (graphmech/methods/train_coaxial.py), against the
independent exact.gear_train.coaxial_tooth_number."""
from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact.gear_train import coaxial_tooth_number
from graphmech.methods.train_coaxial import ArmMesh, arms, solve_missing


def test_the_book_s_cases():
    assert solve_missing("3", [ArmMesh("1", 10, "2", 32, "external"), ArmMesh("3", None, "2", 32, "internal")]) \
        == (74, "z3 = z1 + 2·z2 = 74")
    assert solve_missing("2'", [ArmMesh("1", 15, "2", 25, "external"), ArmMesh("3", 60, "2'", None, "internal")]) \
        == (20, "z2' = z3 − (z1 + z2) = 20")
    assert solve_missing("3", [ArmMesh("1", 20, "2", 40, "external"), ArmMesh("3", None, "2'", 20, "internal")]) \
        == (80, "z3 = z1 + z2 + z2' = 80")
    assert solve_missing("6", [ArmMesh("5", 18, "6", None, "external"), ArmMesh("7", 152, "6", None, "internal")]) \
        == (67, "z6 = (z7 − z5)/2 = 67")
    assert arms([ArmMesh("1", 24, "2", 52, "external"), ArmMesh("4", 78, "3", 21, "internal")]) == [38, 28.5]


def test_refusals():
    with pytest.raises(NoSolution, match="not a whole number"):
        solve_missing("2", [ArmMesh("1", 20, "2", None, "external"), ArmMesh("3", 81, "2", None, "internal")])
    with pytest.raises(NoSolution, match="no such gear"):
        solve_missing("3", [ArmMesh("1", 20, "2", 30, "external"), ArmMesh("3", None, "2", 55, "external")])
    with pytest.raises(OutOfDomain, match="external and internal"):
        solve_missing("3", [ArmMesh("1", 20, "2", 30, "bevel"), ArmMesh("3", None, "2", 30, "internal")])
    with pytest.raises(NoSolution, match="still not coaxial"):
        solve_missing("3", [ArmMesh("1", 20, "2", 30, "external"), ArmMesh("3", None, "2", 30, "internal"),
                            ArmMesh("4", 21, "2", 30, "external")])


@given(st.integers(5, 200), st.integers(5, 200), st.integers(5, 200))
def test_against_the_exact_reference(z1, z2, z2p):
    # sun 1 – double planet 2/2' – ring 3 meshing 2': z3 from the condition, both ways
    z, _ = solve_missing("3", [ArmMesh("1", z1, "2", z2, "external"), ArmMesh("3", None, "2'", z2p, "internal")])
    assert z == coaxial_tooth_number((z1, z2, "external"), (None, z2p, "internal")) == z1 + z2 + z2p
