"""Measuring the drawing: each quantity a (drawn mm, scale) step; signs, units, segments, angles."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.mechanisms.linkage import Crank, Linkage
from graphmech.methods import measure
from graphmech.methods.polygons import build_polygons
from tests.scenes.methods.linkages import GUIDE_BAR, RIGHT_FOURBAR, SCALES, evaluate, slider_crank, value


def test_omega_is_signed_counter_clockwise() -> None:
    cw = Linkage(RIGHT_FOURBAR.frame_points, Crank("1", "A", "B", 0.05, -10.0), RIGHT_FOURBAR.dyads)
    b = build_polygons(cw, SCALES)
    sol = evaluate(b, math.pi / 2, "omega_1", "omega_3")
    assert value(b, sol, "omega_1") == pytest.approx(-10.0, rel=1e-14)
    assert value(b, sol, "omega_3") == pytest.approx(-6.25, rel=1e-14)  # the rocker turns CW too


@pytest.mark.parametrize("deg, want", [
    (30.0, 30.0), (225.0, 225.0), (-90.0, 270.0),
    # sin(2π) = −2.4e-16: atan2 gives −1e-16 rad, and −1.4e-14 % 360.0 rounds to 360.0
    (360.0, 0.0),
])
def test_link_angle_is_degrees_in_0_360(deg: float, want: float) -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    sol = evaluate(b, math.radians(deg), "theta_1")
    assert value(b, sol, "theta_1") == pytest.approx(want, abs=1e-11)
    assert b.quantities["theta_1"].unit == "deg"


def test_link_angle_in_a_batch_equals_one_position_at_a_time() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    plan = b.g.prune([b.quantities["theta_2"].slot, b.quantities["theta_1"].slot])
    phis = np.radians([10.0, 95.0, 200.0, 350.0])
    batch = plan.evaluate_batch({"phi": phis})
    drawn, scale = batch[b.quantities["theta_1"].slot]
    assert np.asarray(drawn) * scale == pytest.approx([10.0, 95.0, 200.0, 350.0], abs=1e-11)
    for i, phi in enumerate(phis):
        one = value(b, plan.evaluate({"phi": float(phi)}), "theta_2")
        assert batch.at(i)[b.quantities["theta_2"].slot][0] == pytest.approx(one, abs=1e-12)


def test_a_translating_link_has_no_angle_and_rates_exactly_zero() -> None:
    b = build_polygons(slider_crank(), SCALES)
    assert "theta_3" not in b.quantities and "theta_2" in b.quantities
    sol = evaluate(b, 0.7, "omega_3", "alpha_3")
    assert sol[b.quantities["omega_3"].slot] == (0.0, 1.0)
    assert sol[b.quantities["alpha_3"].slot] == (0.0, 1.0)


def test_slider_speed_is_signed_along_its_guide_and_relative_speeds_are_lengths() -> None:
    b = build_polygons(slider_crank(), SCALES)
    for deg in (60.0, 300.0):  # moving backward, then forward
        sol = evaluate(b, math.radians(deg), "v_C", "v_CB", "v_B")
        v = value(b, sol, "v_C")
        assert math.copysign(1.0, v) == (-1.0 if deg < 180 else 1.0)
        assert value(b, sol, "v_CB") > 0.0 and value(b, sol, "v_B") == pytest.approx(0.3, rel=1e-14)
    assert b.quantities["v_C"].exact == ("slide_v", "C", 1.0, 0.0)
    assert b.quantities["v_B"].exact == ("speed", "B")


def test_lengths_are_measured_on_the_diagram_at_any_position() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    for phi in (0.3, 2.0, 4.5):
        sol = evaluate(b, phi, "l_AB", "l_CD", "l_BE", "l_EB")
        assert value(b, sol, "l_AB") == pytest.approx(0.05, rel=1e-14)
        assert value(b, sol, "l_CD") == pytest.approx(0.08, rel=1e-14)
        assert value(b, sol, "l_BE") == value(b, sol, "l_EB") == pytest.approx(math.hypot(0.04, 0.02), rel=1e-14)


def test_quantities_carry_their_unit_panel_and_the_drawn_segment() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    q = b.quantities
    assert (q["v_C"].unit, q["v_C"].panel, q["v_C"].segment) == ("m/s", "velocity", ("p", "c"))
    assert (q["a_CB_t"].unit, q["a_CB_t"].segment) == ("m/s²", ("n2'", "c'"))
    assert (q["omega_2"].unit, q["omega_2"].segment) == ("rad/s", ("b", "c"))
    assert (q["alpha_3"].unit, q["alpha_3"].panel) == ("rad/s²", "acceleration")
    assert (q["l_BC"].unit, q["l_BC"].panel, q["l_BC"].segment) == ("m", "mechanism", ("B", "C"))
    assert q["a_CD_n"].exact == ("normal", "C", "D", "3")


def test_a_block_on_a_bar_shares_the_bars_measurement() -> None:
    b = build_polygons(GUIDE_BAR, SCALES)
    assert b.omega["2"] == b.omega["3"]
    assert b.quantities["omega_2"].slot == b.quantities["omega_3"].slot
    assert b.quantities["omega_2"].exact == ("omega", "2")


def test_measuring_twice_adds_nothing() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    steps, q = len(b.g.steps), b.quantities["l_BC"]
    measure.length(b, "B", "C")
    measure.relative(b, "C", "B")
    measure.point_speed(b, "C")
    assert len(b.g.steps) == steps and b.quantities["l_BC"] is q


def test_component_measures_a_laid_off_segment() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    measure.component(b, "a_test", b.acc["B"], b.acc["C"], ("rel_a", "C", "B"))
    sol = evaluate(b, math.pi / 2, "a_test", "a_CB")
    assert value(b, sol, "a_test") == value(b, sol, "a_CB") == pytest.approx(15.625 * math.hypot(0.12, 0.03), rel=1e-13)
    assert b.quantities["a_test"].segment == ("b'", "c'")
