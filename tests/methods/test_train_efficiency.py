"""The book's efficiency of a train (converted-train method, series, worm) against the exact power balance."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import OutOfDomain
from graphmech.exact.gear_train import solve
from graphmech.exact.train_dynamics import train_efficiency
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh
from graphmech.mechanisms.train_dynamics import MeshLosses, Worm
from graphmech.methods.train_efficiency import (
    book_train_efficiency,
    converted_eta,
    planetary_efficiency,
    self_locks,
    series,
    train_path,
    worm_efficiency,
)


def planetary(z: tuple[int, int, int, int], ring: bool) -> GearTrain:
    """1 — double planet 2/2' on H — 3 fixed; 3 a ring (internal) or an external gear."""
    z1, z2, z2p, z3 = z
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                     (Gear("1", z1, "1"), Gear("2", z2, "2"), Gear("2'", z2p, "2"), Gear("3", z3, "3")),
                     (Mesh("1", "2"), Mesh("2'", "3", "internal" if ring else "external")),
                     fixed=("3",), inputs={"1": 1.0})


CASES = [((20, 30, 30, 80), True),     # i_1H = 5: the ordinary reducer
         ((20, 40, 20, 40), False),    # i_1H = −3: seed 000's train
         ((100, 101, 100, 99), False),  # i_H1 = 10000: driven from the sun it self-locks
         ((99, 100, 101, 100), False)]  # i_1H = −1/9999


@pytest.mark.parametrize("z,ring", CASES)
@pytest.mark.parametrize("source,sink", [("1", "H"), ("H", "1")])
def test_converted_train_method_agrees_with_the_power_balance(z: tuple[int, int, int, int], ring: bool,
                                                              source: str, sink: str) -> None:
    t = planetary(z, ring)
    losses = MeshLosses((0.98, 0.97))
    book = book_train_efficiency(t, losses, source, sink)
    exact = train_efficiency(t, solve(t).omega, losses, source, sink)
    assert book == pytest.approx(exact, rel=1e-12, abs=1e-12)


def test_the_books_known_case_sun_driving_fixed_ring() -> None:
    t = planetary((20, 30, 30, 80), True)  # i_1H = 1 + 80/20 = 5
    (stage,) = train_path(t, MeshLosses((0.98, 0.97)), "1", "H")
    assert stage.i == pytest.approx(5.0) and stage.eta_H == pytest.approx(0.98 * 0.97)
    assert stage.eta == pytest.approx(1 - (1 - 0.98 * 0.97) * 4 / 5, rel=1e-14)
    p = planetary_efficiency(5.0, 0.95, True)
    assert p.a_drives_converted and p.eta == pytest.approx(0.96, rel=1e-14)
    # the carrier driving: the sun is driven in the converted train, 1/η^H
    back = planetary_efficiency(5.0, 0.95, False)
    assert not back.a_drives_converted and back.eta == pytest.approx(1 / (1 + 0.8 * (1 / 0.95 - 1)), rel=1e-14)


def test_the_large_reduction_is_poor_one_way_and_self_locks_the_other() -> None:
    """z1 = 100, z2 = 101, z2' = 100, z3 = 99: i_H1 = 10000. The carrier driving, the sun drives
    the converted train (x = 1 − 1/i_1H = −9999): η = 1/(1 + 9999(1 − η^H)); the sun driving, it
    is driven there: η = 1 − 9999(1/η^H − 1) < 0, the train self-locks."""
    t = planetary((100, 101, 100, 99), False)
    losses = MeshLosses((0.99, 0.99))
    eta_h = converted_eta(t, losses, "H", "1", "3")
    assert eta_h == pytest.approx(0.99**2)
    assert solve(t).ratio("H", "1") == pytest.approx(10000.0, rel=1e-12)
    assert book_train_efficiency(t, losses, "H", "1") == pytest.approx(1 / (1 + 9999 * (1 - eta_h)), rel=1e-12)
    assert book_train_efficiency(t, losses, "1", "H") == pytest.approx(1 - 9999 * (1 / eta_h - 1), rel=1e-12)
    assert book_train_efficiency(t, losses, "1", "H") < 0


def test_a_compound_train_in_series_multiplies_its_stages() -> None:
    """An ordinary pair 4–1 ahead of the planetary reducer: η = η_41 · η_1H."""
    t = GearTrain((Member("4"), Member("1"), Member("2", "H"), Member("3"), Member("H")),
                  (Gear("4", 30, "4"), Gear("1'", 60, "1"), Gear("1", 20, "1"), Gear("2", 30, "2"), Gear("3", 80, "3")),
                  (Mesh("4", "1'"), Mesh("1", "2"), Mesh("2", "3", "internal")), fixed=("3",), inputs={"4": 1.0})
    losses = MeshLosses((0.95, 0.98, 0.97))
    stages = train_path(t, losses, "4", "H")
    assert [s.kind for s in stages] == ["mesh", "planetary"]
    assert book_train_efficiency(t, losses, "4", "H") == pytest.approx(0.95 * stages[1].eta, rel=1e-15)
    assert book_train_efficiency(t, losses, "4", "H") == pytest.approx(
        train_efficiency(t, solve(t).omega, losses, "4", "H"), rel=1e-12)
    assert series([0.95, 0.97, 0.97, 0.9]) == pytest.approx(0.8044695, rel=1e-12)


def test_a_differential_inside_has_no_series_rule() -> None:
    t = GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                  (Gear("1", 20, "1"), Gear("2", 30, "2"), Gear("3", 80, "3")),
                  (Mesh("1", "2"), Mesh("2", "3", "internal")), inputs={"1": 1.0, "3": 0.5})
    with pytest.raises(OutOfDomain, match="power divides"):
        book_train_efficiency(t, MeshLosses((0.98, 0.98)), "1", "H")


def test_worm_efficiency_and_self_locking() -> None:
    gamma, phi = math.atan(2 / 10), math.atan(0.05)
    assert worm_efficiency(gamma, phi) == pytest.approx(0.2 / math.tan(gamma + phi), rel=1e-14)
    assert worm_efficiency(gamma, phi, False) == pytest.approx(math.tan(gamma - phi) / 0.2, rel=1e-14)
    assert not self_locks(gamma, phi)
    single = math.atan(1 / 10)
    assert self_locks(single, math.atan(0.12)) and worm_efficiency(single, math.atan(0.12), False) < 0
    with pytest.raises(OutOfDomain):
        worm_efficiency(0.0, phi)
    # a worm in an ordinary train: worm driving η, wheel driving η′, as the power balance finds
    t = GearTrain((Member("1"), Member("2"), Member("3")),
                  (Gear("1", 4, "1"), Gear("2", 40, "2"), Gear("2'", 20, "2"), Gear("3", 60, "3")),
                  (Mesh("1", "2", "worm", sign=-1), Mesh("2'", "3")), inputs={"1": 1.0})
    losses = MeshLosses((1.0, 0.97), (Worm(0, math.atan(4 / 10), phi),))
    w = solve(t).omega
    for src, snk in (("1", "3"), ("3", "1")):
        assert book_train_efficiency(t, losses, src, snk) == pytest.approx(
            train_efficiency(t, w, losses, src, snk), rel=1e-12)
