"""The shared linkage construction: the names of its own points and poles, the drawing's origin,
the first quantity of a name kept, and what a panel draws."""
from __future__ import annotations

import pytest

from graphmech.methods.linkage_construction import ACCELERATION_POLE, VELOCITY_POLE, LinkageConstruction, own
from graphmech.methods.quantities import Quantity
from tests.scenes.methods.linkages import RIGHT_FOURBAR, SCALES


def test_own_points_are_bracketed_apart_from_any_image() -> None:
    assert own("velocity", "p") == "v:(p)" == VELOCITY_POLE
    assert own("acceleration", "p'") == "a:(p')" == ACCELERATION_POLE
    assert own("acceleration", "n2'") == "a:(n2')"
    # a point named P has the image "v:p", never the pole
    assert own("velocity", "p") != "v:p"


def test_to_drawing_divides_by_mu_l_from_the_origin() -> None:
    b = LinkageConstruction(RIGHT_FOURBAR, {"l": 0.002, "v": 0.01, "a": 0.1})
    assert b.mu_l == 0.002
    assert b.to_drawing((0.1, -0.04)) == pytest.approx((50.0, -20.0), rel=1e-15)
    b.origin = (1000.0, 2000.0)  # a linkage far from the scene's origin keeps its digits
    assert b.to_drawing((1000.1, 1999.96)) == pytest.approx((50.0, -20.0), rel=1e-9)


def test_a_quantity_named_twice_keeps_the_first() -> None:
    b = LinkageConstruction(RIGHT_FOURBAR, dict(SCALES))
    first = Quantity("v_C", "m/s", "m:v_C", ("speed", "C"), "velocity", ("p", "c"))
    b.quantity(first)
    b.quantity(Quantity("v_C", "m/s", "m:other", ("speed", "D"), "velocity"))
    assert b.quantities == {"v_C": first}


def test_steps_of_panel_leave_out_hidden_steps_and_other_panels() -> None:
    b = LinkageConstruction(RIGHT_FOURBAR, dict(SCALES))
    b.g.add("P", "point", lambda ops: (0.0, 0.0), (), role="given", panel="mechanism")
    b.g.add("m:l", "scalar", lambda ops: (1.0, 1.0), (), role="hidden", panel="mechanism")
    b.g.add("v:(p)", "point", lambda ops: (0.0, 0.0), (), role="result", panel="velocity")
    assert b.steps_of_panel("mechanism") == ["P"]
    assert b.steps_of_panel("velocity") == ["v:(p)"]
    assert b.steps_of_panel("acceleration") == []


def test_each_construction_has_its_own_containers() -> None:
    one, two = (LinkageConstruction(RIGHT_FOURBAR, dict(SCALES)) for _ in range(2))
    one.mech["A"] = "A"
    one.coincident.append(("B3", "B2"))
    assert two.mech == {} and two.coincident == [] and one.g is not two.g
