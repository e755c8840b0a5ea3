"""build_polygons: the three figures laid out part after part, points placed as soon as they can
be, and every quantity a scene may ask for."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact.linkage import solve
from graphmech.mechanisms.linkage import RRR, Crank, Linkage, LinkPoint
from graphmech.methods.polygons import PANELS, build_polygons
from graphmech.problems.linkage.check import exact_value
from graphmech.problems.linkage.sizes import characteristic
from tests.scenes.methods.linkages import GUIDE_BAR, RIGHT_FOURBAR, SCALES, SLIDER_DRIVEN, evaluate, value

# A six-bar: the four-bar's coupler point E drives a second RRR dyad E–F–G; H on link 5 is listed
# before the dyad that places F, so it must wait for it.
SIXBAR = Linkage(
    {"A": (0.0, 0.0), "D": (0.12, 0.0), "G": (0.2, 0.2)}, Crank("1", "A", "B", 0.06, 10.0, 3.0),
    (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"), RRR("E", "F", "G", ("5", "6"), (0.15, 0.15), "right")),
    (LinkPoint("H", "5", ("E", "F"), 0.1, 0.02), LinkPoint("E", "2", ("B", "C"), 0.06, 0.03)),
)


def test_each_panel_has_its_drawable_steps() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    assert PANELS == ("mechanism", "velocity", "acceleration")
    for panel in PANELS:
        names = b.steps_of_panel(panel)
        assert names and all(b.g.steps[n].role != "hidden" for n in names)
    assert {"B", "C", "E"} <= set(b.steps_of_panel("mechanism"))
    assert {"v:b", "v:c", "v:e"} <= set(b.steps_of_panel("velocity"))
    assert "m:v_C" not in b.steps_of_panel("velocity")  # a measurement is never drawn


def test_the_drivers_parameter_names_the_position() -> None:
    assert build_polygons(RIGHT_FOURBAR, SCALES).param == "phi"
    b = build_polygons(SLIDER_DRIVEN, SCALES)
    assert b.param == "s" and "s" in b.g.steps
    sol = evaluate(b, 0.1, "C", "l_CB")  # C 0.1 m up the 60° guide from (−0.3, 0), A at the origin
    assert sol["C"] == pytest.approx(((-0.3 + 0.05) / 0.001, 0.1 * math.sqrt(3) / 2 / 0.001), rel=1e-14)
    assert value(b, sol, "l_CB") == pytest.approx(0.3, rel=1e-14)


def test_epsilon_is_another_name_for_alpha() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    for link in ("1", "2", "3"):
        eps, alpha = b.quantities[f"epsilon_{link}"], b.quantities[f"alpha_{link}"]
        assert (eps.slot, eps.exact) == (alpha.slot, alpha.exact)


def test_a_guide_bars_length_between_its_pivots_is_measured_both_ways() -> None:
    b = build_polygons(GUIDE_BAR, SCALES)
    for phi, length in ((0.0, 0.05), (math.pi / 2, 0.07)):
        sol = evaluate(b, phi, "l_BC", "l_CB")
        assert value(b, sol, "l_BC") == value(b, sol, "l_CB") == pytest.approx(length, rel=1e-14)


def test_a_sixbar_hung_on_a_coupler_point_agrees_with_the_exact_solution() -> None:
    b = build_polygons(SIXBAR, SCALES)
    assert list(b.mech).index("E") < list(b.mech).index("F") < list(b.mech).index("H")
    phi = math.radians(40.0)
    names = [n for n, q in b.quantities.items() if q.unit != "deg"]
    sol = evaluate(b, phi, *names)
    kin = solve(SIXBAR, np.array([phi]))
    assert kin.valid[0]
    for n in names:
        q = b.quantities[n]
        want = exact_value(kin, q.exact, 0)
        assert abs(value(b, sol, n) - want) <= 1e-12 * max(abs(want), characteristic(SIXBAR, q.unit)), n
    assert {"omega_5", "omega_6", "v_H", "a_H", "a_FE_t"} <= set(b.quantities)


def test_a_point_on_a_base_that_is_never_placed_names_it() -> None:
    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.04, 10.0), (),
                 (LinkPoint("E", "2", ("B", "Z"), 0.01, 0.0),))
    with pytest.raises(KeyError, match="Z"):
        build_polygons(lk, SCALES)


def test_the_scales_are_copied_not_shared() -> None:
    scales = dict(SCALES)
    b = build_polygons(RIGHT_FOURBAR, scales)
    scales["v"] = 1.0
    assert b.scales["v"] == SCALES["v"]
