"""The velocity polygon at μv: each dyad's image where two lines meet, checked against closed
forms at positions worked out by hand (tests/scenes/methods/linkages.py), and the velocity image."""
from __future__ import annotations

import math

import pytest

from graphmech.mechanisms.linkage import Crank, Linkage
from graphmech.methods import diagram, velocity
from graphmech.methods.linkage_construction import LinkageConstruction
from graphmech.methods.polygons import build_polygons
from tests.scenes.methods.linkages import (
    GUIDE_BAR,
    RIGHT_FOURBAR,
    SCALES,
    SLIDER_DRIVEN,
    evaluate,
    scotch_yoke,
    slider_crank,
    value,
)

MU_V = SCALES["v"]


def test_image_letters_are_the_points_lower_case() -> None:
    assert velocity.label("B") == "b"
    assert velocity.label("C2") == "c2"
    assert velocity.POLE == "v:(p)"


def test_the_polygon_needs_only_the_kinematic_diagram() -> None:
    """diagram + velocity alone (no acceleration polygon) give v_C; frame points are the pole."""
    b = LinkageConstruction(RIGHT_FOURBAR, dict(SCALES))
    b.g.param(b.param)
    diagram.add_frame(b)
    velocity.add_pole(b)
    for part in (RIGHT_FOURBAR.driver, *RIGHT_FOURBAR.dyads):
        diagram.add(b, part)
        velocity.add(b, part)
    assert b.vel["A"] == b.vel["D"] == velocity.POLE
    assert not any(s.startswith("a:") for s in b.g.steps)
    sol = evaluate(b, math.pi / 2, "v:c", "omega_3")
    assert sol["v:c"] == pytest.approx((-50.0, 0.0), abs=1e-12)  # v_C = v_B = 0.5 m/s, to the left
    assert value(b, sol, "omega_3") == pytest.approx(6.25, rel=1e-14)


@pytest.mark.parametrize("omega", [10.0, -4.0])
def test_crank_image_is_perpendicular_to_the_crank_and_omega_l_over_mu_long(omega: float) -> None:
    lk = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.05, omega),
                 RIGHT_FOURBAR.dyads)
    b = build_polygons(lk, SCALES)
    phi = math.radians(30.0)
    sol = evaluate(b, phi, "v:b", "omega_1", "v_B")
    k = omega * 0.05 / MU_V  # mm, signed: pb is AB turned 90° in the sense of ω
    assert sol["v:b"] == pytest.approx((-k * math.sin(phi), k * math.cos(phi)), rel=1e-14)
    assert value(b, sol, "omega_1") == pytest.approx(omega, rel=1e-14)
    assert value(b, sol, "v_B") == pytest.approx(abs(omega) * 0.05, rel=1e-14)


def test_four_bar_with_the_rocker_upright_closed_form() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    sol = evaluate(b, math.pi / 2, "v:c", "v_C", "v_CB", "omega_2", "omega_3")
    assert sol["v:c"] == pytest.approx((-50.0, 0.0), abs=1e-12)
    assert value(b, sol, "v_C") == pytest.approx(0.5, rel=1e-14)
    assert value(b, sol, "v_CB") == pytest.approx(0.0, abs=1e-15)
    assert value(b, sol, "omega_2") == pytest.approx(0.0, abs=1e-14)
    assert value(b, sol, "omega_3") == pytest.approx(0.05 * 10.0 / 0.08, rel=1e-14)


def test_velocity_image_of_a_coupler_point_is_the_link_turned_by_omega() -> None:
    """bce ∼ BCE: each side of the image is the link's side turned 90° in the sense of ω2 and
    scaled by ω2·μl/μv (at a position where ω2 ≠ 0)."""
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    sol = evaluate(b, math.radians(60.0), "B", "C", "E", "v:b", "v:c", "v:e", "omega_2")
    w2 = value(b, sol, "omega_2")
    assert abs(w2) > 1.0
    k = w2 * SCALES["l"] / MU_V
    for (P, p), (Q, q) in ((("B", "v:b"), ("E", "v:e")), (("C", "v:c"), ("E", "v:e")), (("B", "v:b"), ("C", "v:c"))):
        dx, dy = sol[Q][0] - sol[P][0], sol[Q][1] - sol[P][1]
        assert (sol[q][0] - sol[p][0], sol[q][1] - sol[p][1]) == pytest.approx((-k * dy, k * dx), abs=1e-11)


def test_slider_crank_at_a_right_angle_moves_the_slider_as_fast_as_the_pin() -> None:
    """At φ = 90° the coupler translates for an instant: v_C = v_B, ω2 = 0; at the dead centre
    the slider stands still. v_C is signed along the guide."""
    b = build_polygons(slider_crank(), SCALES)
    sol = evaluate(b, math.pi / 2, "v_C", "omega_2", "omega_3")
    assert value(b, sol, "v_C") == pytest.approx(-0.3, rel=1e-14)
    assert value(b, sol, "omega_2") == pytest.approx(0.0, abs=1e-14)
    assert value(b, sol, "omega_3") == 0.0  # the slider translates
    assert value(b, evaluate(b, 0.0, "v_C"), "v_C") == pytest.approx(0.0, abs=1e-15)


def test_guide_bar_splits_the_pin_velocity_across_and_along_the_bar() -> None:
    b = build_polygons(GUIDE_BAR, SCALES)
    sol = evaluate(b, 0.0, "omega_3", "omega_2", "v_B3", "v_B3B2", "v_B2")
    assert value(b, sol, "omega_3") == pytest.approx(3.6, rel=1e-14)
    assert value(b, sol, "omega_2") == value(b, sol, "omega_3")  # the block turns with the bar
    assert value(b, sol, "v_B3") == pytest.approx(3.6 * 0.05, rel=1e-14)
    assert value(b, sol, "v_B3B2") == pytest.approx(0.24, rel=1e-14)
    assert value(b, sol, "v_B2") == pytest.approx(math.hypot(0.18, 0.24), rel=1e-14)
    assert b.coincident == [("B3", "B2")]


@pytest.mark.parametrize("deg", [30.0, 135.0, 270.0])
def test_scotch_yoke_moves_harmonically(deg: float) -> None:
    b = build_polygons(scotch_yoke(), SCALES)
    phi = math.radians(deg)
    sol = evaluate(b, phi, "v_C", "omega_2", "omega_3", "v_B2B3")
    assert value(b, sol, "v_C") == pytest.approx(-0.04 * 10.0 * math.sin(phi), abs=1e-15)
    assert value(b, sol, "omega_2") == value(b, sol, "omega_3") == 0.0
    # the block slides in the vertical slot with the pin's vertical velocity
    assert value(b, sol, "v_B2B3") == pytest.approx(abs(0.4 * math.cos(phi)), abs=1e-15)


def test_a_driven_slider_images_along_its_guide() -> None:
    b = build_polygons(SLIDER_DRIVEN, SCALES)
    sol = evaluate(b, 0.0, "v:c", "v_C")
    k = -1.5 / MU_V
    assert sol["v:c"] == pytest.approx((k * 0.5, k * math.sqrt(3) / 2), rel=1e-14)
    assert value(b, sol, "v_C") == pytest.approx(-1.5, rel=1e-14)


def test_an_offset_guide_bar_slides_along_its_line_not_along_cb() -> None:
    """φ = 0 (tests/scenes/methods/linkages.py): v_B3 ⟂ CB, v_B2B3 ∥ û = FB = (0.96, 0.28): ω3 = 7.2,
    |v_B3B2| = 0.3 and |v_B3| = ω3·|CB| = 0.36; θ3 is the line's direction, not CB's."""
    from tests.scenes.methods.linkages import OFFSET_GUIDE_BAR

    b = build_polygons(OFFSET_GUIDE_BAR, SCALES)
    sol = evaluate(b, 0.0, "omega_3", "omega_2", "v_B3B2", "v_B3", "theta_3", "v:b3", "v:b")
    assert value(b, sol, "omega_3") == pytest.approx(7.2, rel=1e-13)
    assert value(b, sol, "omega_2") == value(b, sol, "omega_3")
    assert value(b, sol, "v_B3B2") == pytest.approx(0.3, rel=1e-13)
    assert value(b, sol, "v_B3") == pytest.approx(0.36, rel=1e-13)
    assert value(b, sol, "theta_3") == pytest.approx(math.degrees(math.atan2(0.28, 0.96)), rel=1e-13)
    rel = (sol["v:b"][0] - sol["v:b3"][0], sol["v:b"][1] - sol["v:b3"][1])  # b3→b, the sliding velocity
    assert rel == pytest.approx((0.96 * 30.0, 0.28 * 30.0), rel=1e-13)  # 0.3 m/s at μv = 0.01
