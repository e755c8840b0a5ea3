"""A linkage's structure: guides, the roles in each dyad, and which link carries which points."""
from __future__ import annotations

import dataclasses
import math

import pytest

from graphmech.mechanisms.linkage import (
    RPP,
    RPR,
    RRP,
    RRR,
    Crank,
    Guide,
    Linkage,
    LinkPoint,
    Positions,
    SliderInput,
)


def test_guide_direction() -> None:
    assert Guide((0.0, 0.0), 0.0).direction == (1.0, 0.0)
    assert Guide((1.0, 2.0), math.radians(120.0)).direction == pytest.approx((-0.5, math.sqrt(3) / 2), rel=1e-15)


@pytest.mark.parametrize("bar, want", [
    ("first", ("2", "3", "B", "C", ("C2", "C3"))),
    ("second", ("3", "2", "C", "B", ("B3", "B2"))),
])
def test_rpr_roles_follow_which_link_is_the_bar(bar: str, want: tuple) -> None:
    y = RPR("B", "C", ("2", "3"), bar=bar)  # type: ignore[arg-type]
    assert (y.bar_link, y.block_link, y.bar_pivot, y.block_pivot, y.coincident) == want


def test_rpp_coincident_points_are_the_pin_on_each_link() -> None:
    assert RPP("B", "C", ("2", "3"), math.pi / 2, Guide((0.0, 0.0), 0.0)).coincident == ("B2", "B3")


def test_links_of_a_four_bar_with_a_coupler_point() -> None:
    lk = Linkage({"A": (0.0, 0.0), "D": (0.1, 0.0)}, Crank("1", "A", "B", 0.03, 1.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.1, 0.08)),), (LinkPoint("E", "2", ("B", "C"), 0.05, 0.01),))
    assert lk.links() == {"1": ["A", "B"], "2": ["B", "C", "E"], "3": ["D", "C"]}


def test_links_of_each_dyad_kind_list_each_point_once() -> None:
    guide = Guide((0.0, 0.0), 0.0)
    assert Linkage({}, SliderInput("3", "C", guide, 1.0), (RRR("C", "B", "A", ("2", "1"), (0.3, 0.1)),),
                   frame_link="0").links() == {"3": ["C"], "2": ["C", "B"], "1": ["A", "B"]}
    assert Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, 1.0),
                   (RRP("B", "C", ("2", "3"), 0.1, guide),), (LinkPoint("K", "3", ("C",), 0.01, 0.0),)
                   ).links() == {"1": ["A", "B"], "2": ["B", "C"], "3": ["C", "K"]}
    assert Linkage({"A": (0.0, 0.0), "C": (0.0, -0.1)}, Crank("1", "A", "B", 0.03, 1.0),
                   (RPR("B", "C", ("2", "3"), bar="second"),)).links() == {"1": ["A", "B"], "3": ["C", "B3"], "2": ["B"]}
    assert Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, 1.0),
                   (RPP("B", "C", ("2", "3"), 1.0, guide),)).links() == {"1": ["A", "B"], "2": ["B"], "3": ["C"]}


def test_a_linkage_hashes_by_identity_and_is_frozen() -> None:
    def make() -> Linkage:
        return Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, 1.0))

    one, two = make(), make()
    assert one == two and hash(one) == id(one) and len({one, two}) == 2
    with pytest.raises(dataclasses.FrozenInstanceError):
        one.frame_link = "0"  # type: ignore[misc]


def test_defaults() -> None:
    c = Crank("1", "A", "B", 0.03, 10.0)
    assert (c.epsilon, c.kind) == (0.0, "crank")
    assert RRR("B", "C", "D", ("2", "3"), (0.1, 0.1)).branch == "left"
    assert RRP("B", "C", ("2", "3"), 0.1, Guide((0.0, 0.0), 0.0)).branch == "forward"
    assert Positions((0.0, 1.0)).labels == ()
