"""The acceleration polygon at μa: normal components laid off, tangential lines met, the Coriolis
component of a sliding pair, the acceleration image; closed forms worked out by hand
(tests/scenes/methods/linkages.py)."""
from __future__ import annotations

import math

import pytest

from graphmech.methods import acceleration
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

MU_A = SCALES["a"]


def test_image_letters_are_primed() -> None:
    assert acceleration.label("B") == "b'"
    assert acceleration.label("C2") == "c2'"
    assert acceleration.POLE == "a:(p')"


def test_crank_tip_with_angular_acceleration() -> None:
    """a_B = ω²·l towards A plus ε·l across AB; both components reported under the crank's name
    and the tip's (a_BA_n, a_B_n)."""
    b = build_polygons(slider_crank(omega=10.0, epsilon=3.0), SCALES)
    sol = evaluate(b, 0.0, "a:b'", "a_B_n", "a_B_t", "a_BA_t", "alpha_1", "epsilon_1")
    assert sol["a:b'"] == pytest.approx((-100.0 * 0.03 / MU_A, 3.0 * 0.03 / MU_A), rel=1e-14)
    assert value(b, sol, "a_B_n") == pytest.approx(3.0, rel=1e-14)
    assert value(b, sol, "a_B_t") == value(b, sol, "a_BA_t") == pytest.approx(0.09, rel=1e-13)
    assert value(b, sol, "alpha_1") == value(b, sol, "epsilon_1") == pytest.approx(3.0, rel=1e-13)
    assert b.g.has("a:(n1')")


def test_crank_without_angular_acceleration_has_no_tangential_component() -> None:
    b = build_polygons(slider_crank(omega=10.0), SCALES)
    sol = evaluate(b, math.radians(40.0), "a_B_t", "a_B_n", "alpha_1")
    assert value(b, sol, "a_B_t") == 0.0 and value(b, sol, "alpha_1") == 0.0
    assert value(b, sol, "a_B_n") == pytest.approx(3.0, rel=1e-14)
    assert not b.g.has("a:(n1')")  # the normal component is the whole of p′b′


def test_four_bar_with_the_rocker_upright_closed_form() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    names = ("a:c'", "alpha_2", "alpha_3", "a_CB_n", "a_CB_t", "a_CD_n", "a_CD_t", "epsilon_3")
    sol = evaluate(b, math.pi / 2, *names)
    assert sol["a:c'"] == pytest.approx((-0.46875 / MU_A, -3.125 / MU_A), rel=1e-13)
    assert value(b, sol, "alpha_2") == pytest.approx(15.625, rel=1e-13)
    assert value(b, sol, "alpha_3") == value(b, sol, "epsilon_3") == pytest.approx(5.859375, rel=1e-13)
    assert value(b, sol, "a_CB_n") == pytest.approx(0.0, abs=1e-13)  # ω2 = 0
    assert value(b, sol, "a_CB_t") == pytest.approx(15.625 * math.hypot(0.12, 0.03), rel=1e-13)
    assert value(b, sol, "a_CD_n") == pytest.approx(6.25 ** 2 * 0.08, rel=1e-13)
    assert value(b, sol, "a_CD_t") == pytest.approx(5.859375 * 0.08, rel=1e-13)


def test_acceleration_image_of_a_coupler_point() -> None:
    """b′e′ = (α2 × BE − ω2²·BE)·μl/μa: the image of the link, turned and scaled."""
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    sol = evaluate(b, math.radians(60.0), "B", "E", "a:b'", "a:e'", "omega_2", "alpha_2")
    w2, a2 = value(b, sol, "omega_2"), value(b, sol, "alpha_2")
    assert abs(w2) > 1.0 and abs(a2) > 1.0
    k = SCALES["l"] / MU_A
    dx, dy = sol["E"][0] - sol["B"][0], sol["E"][1] - sol["B"][1]
    want = (k * (-a2 * dy - w2 ** 2 * dx), k * (a2 * dx - w2 ** 2 * dy))
    got = (sol["a:e'"][0] - sol["a:b'"][0], sol["a:e'"][1] - sol["a:b'"][1])
    assert got == pytest.approx(want, abs=1e-10)


def test_slider_crank_at_a_right_angle() -> None:
    """φ = 90°, ε = 0: a_C = ω²a²/√(b² − a²) = √3 along the guide, α2 = ω²a/√(b² − a²)."""
    b = build_polygons(slider_crank(), SCALES)
    sol = evaluate(b, math.pi / 2, "a_C", "alpha_2", "alpha_3", "a_CB_n")
    root = math.sqrt(0.06 ** 2 - 0.03 ** 2)
    assert value(b, sol, "a_C") == pytest.approx(math.sqrt(3.0), rel=1e-13)
    assert value(b, sol, "alpha_2") == pytest.approx(100.0 * 0.03 / root, rel=1e-13)
    assert value(b, sol, "alpha_3") == 0.0
    assert value(b, sol, "a_CB_n") == pytest.approx(0.0, abs=1e-13)


def test_guide_bar_lays_off_the_coriolis_component() -> None:
    """At φ = 0: a^k = 2·ω3·v_B3B2 = 1.728, v_B3B2 turned in the sense of ω3 (CCW); α3 = 13.44
    and the relative (sliding) acceleration 1.152, both by hand in polar coordinates on the bar."""
    b = build_polygons(GUIDE_BAR, SCALES)
    sol = evaluate(b, 0.0, "a:(k')", "a:b'", "a_k_B3B2", "a_r_B3B2", "alpha_3", "alpha_2", "epsilon_2")
    assert value(b, sol, "a_k_B3B2") == pytest.approx(1.728, rel=1e-13)
    # the block slides away from C, so v_B3B2 = v_B3 − v_B2 runs towards C, along (−0.6, −0.8);
    # turned 90° CCW: (0.8, −0.6), laid off from b′ (= b2′), 17.28 mm long at μa
    kx, ky = sol["a:(k')"][0] - sol["a:b'"][0], sol["a:(k')"][1] - sol["a:b'"][1]
    assert (kx, ky) == pytest.approx((0.8 * 17.28, -0.6 * 17.28), rel=1e-13)
    assert value(b, sol, "alpha_3") == pytest.approx(13.44, rel=1e-13)
    assert value(b, sol, "alpha_2") == value(b, sol, "epsilon_2") == value(b, sol, "alpha_3")
    assert value(b, sol, "a_r_B3B2") == pytest.approx(1.152, rel=1e-13)


@pytest.mark.parametrize("deg", [30.0, 200.0])
def test_scotch_yoke_with_angular_acceleration(deg: float) -> None:
    b = build_polygons(scotch_yoke(epsilon=50.0), SCALES)
    phi = math.radians(deg)
    sol = evaluate(b, phi, "a_C", "alpha_2", "alpha_3")
    assert value(b, sol, "a_C") == pytest.approx(-0.04 * (100.0 * math.cos(phi) + 50.0 * math.sin(phi)), rel=1e-13)
    assert value(b, sol, "alpha_2") == value(b, sol, "alpha_3") == 0.0


def test_a_driven_slider_images_along_its_guide() -> None:
    b = build_polygons(SLIDER_DRIVEN, SCALES)
    sol = evaluate(b, 0.0, "a:c'", "a_C")
    k = 4.0 / MU_A
    assert sol["a:c'"] == pytest.approx((k * 0.5, k * math.sqrt(3) / 2), rel=1e-14)
    assert value(b, sol, "a_C") == pytest.approx(4.0, rel=1e-14)


def test_every_frame_point_is_the_pole() -> None:
    b = build_polygons(RIGHT_FOURBAR, SCALES)
    assert b.acc["A"] == b.acc["D"] == acceleration.POLE
    assert evaluate(b, 1.0, acceleration.POLE)[acceleration.POLE] == (0.0, 0.0)


def test_an_offset_guide_bar_lays_off_the_coriolis_component_across_its_line() -> None:
    """φ = 0 (tests/scenes/methods/linkages.py): a^k = 2ω3·v_B2B3 = 4.32 ⟂ û = (0.96, 0.28), the
    relative acceleration 2.25 ∥ û, α3 = −48.12 (by hand in the bar's frame)."""
    from tests.scenes.methods.linkages import OFFSET_GUIDE_BAR

    b = build_polygons(OFFSET_GUIDE_BAR, SCALES)
    sol = evaluate(b, 0.0, "a:(k')", "a:b'", "a_k_B3B2", "a_r_B3B2", "alpha_3", "epsilon_2")
    assert value(b, sol, "a_k_B3B2") == pytest.approx(4.32, rel=1e-13)
    # v_B3B2 = v_B3 − v_B2 = −0.3·û turned 90° CCW (ω3 > 0): (0.28, −0.96), 43.2 mm at μa = 0.1
    kx, ky = sol["a:(k')"][0] - sol["a:b'"][0], sol["a:(k')"][1] - sol["a:b'"][1]
    assert (kx, ky) == pytest.approx((0.28 * 43.2, -0.96 * 43.2), rel=1e-13)
    assert value(b, sol, "alpha_3") == pytest.approx(-48.12, rel=1e-12)
    assert value(b, sol, "epsilon_2") == value(b, sol, "alpha_3")
    assert value(b, sol, "a_r_B3B2") == pytest.approx(2.25, rel=1e-12)
