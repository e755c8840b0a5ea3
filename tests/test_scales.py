"""Scale factors μ (graphmech/scales.py): the round scales textbooks use, the notes written on a
drawing, and the scales refused because the figure would be a dot or leave every page."""
from __future__ import annotations

import math

import pytest

from graphmech.scales import (DRAWN_SIZE_RANGE_MM, FIT, FIT_WORKING_AREA, PAPER, PHI_AXIS_RANGE_MM, SCALE_INFO, drawn_size_problem,
                              format_scale, phi_axis_problem, round_scale, scale_out_of_range)
from graphmech.errors import OutOfDomain
from graphmech.scales import is_round_scale, round_scale_below


@pytest.mark.parametrize("minimum, scale", [
    (0.0031, 0.005), (0.0021, 0.0025), (0.002, 0.002), (0.003, 0.005), (0.0051, 0.01), (2.0, 2.0),
    (7.3, 10.0), (0.3, 0.5), (1e-7, 1e-7), (123.0, 200.0), (0.00099, 0.001),
])
def test_the_smallest_round_scale_not_below_the_minimum(minimum, scale):
    assert round_scale(minimum) == scale


@pytest.mark.parametrize("most, scale", [(3.214, 2.5), (2.5, 2.5), (17.48, 10.0), (0.0099, 0.005), (1.0, 1.0),
                                         (9.99, 5.0), (1.99e-7, 1e-7)])
def test_the_largest_round_scale_not_above_the_most(most, scale):
    # μF that draws a 32.14 N force at least 10 mm long: 2.5 N/mm, not 5
    assert round_scale_below(most) == scale and is_round_scale(scale)
    assert scale <= most < round_scale(scale * 1.01)  # the next round scale up is too coarse


def test_a_round_scale_is_known_as_one():
    assert [is_round_scale(x) for x in (0.25, 1e-9, 50.0, 1.25, 3.0, 0.0, float("inf"))] == [
        True, True, True, False, False, False, False]
    with pytest.raises(OutOfDomain):
        round_scale_below(0.0)


def test_round_scales_are_exact_decimals():
    assert repr(round_scale(0.29)) == "0.5" and repr(round_scale(0.21)) == "0.25"
    assert round_scale(0.002 * (1 + 1e-13)) == 0.002  # a hair over by round-off is the same scale


@pytest.mark.parametrize("bad", [0.0, -0.002, math.inf, math.nan])
def test_a_scale_must_be_positive_and_finite(bad):
    with pytest.raises(ValueError, match="positive and finite"):
        round_scale(bad)


def test_the_note_on_a_drawing_names_the_scale_and_its_unit():
    assert format_scale("l", 0.002) == "μl = 0.002 m/mm"
    assert format_scale("v", 0.005) == "μv = 0.005 (m/s)/mm"
    assert format_scale("a", 0.25) == "μa = 0.25 (m/s²)/mm"
    assert format_scale("phi", math.radians(3)) == "μφ = 3 °/mm"  # kept in rad, written in degrees
    assert set(SCALE_INFO) >= {"l", "v", "a", "s", "phi", "M", "J", "T", "F"}


def test_paper_sizes_are_landscape_unless_portrait():
    assert PAPER["A4"] == (297.0, 210.0) and PAPER["A3"] == (420.0, 297.0)
    assert PAPER["A4-portrait"] == PAPER["A4"][::-1] and PAPER["A3-portrait"] == PAPER["A3"][::-1]
    assert PAPER["A2"] == (594.0, 420.0) and PAPER["A1"] == (841.0, 594.0)
    assert list(PAPER) == ["A4", "A4-portrait", "A3", "A3-portrait", "A2", "A2-portrait", "A1", "A1-portrait"]
    for name, (w, h) in PAPER.items():
        assert (w > h) != name.endswith("-portrait")
        if not name.endswith("-portrait"):
            assert PAPER[name + "-portrait"] == (h, w)
            assert w * h / (297.0 * 210.0) == pytest.approx(2 ** (4 - int(name[1])), rel=0.01)  # each twice the next
    assert FIT == "fit" and FIT_WORKING_AREA in PAPER.values()


def test_a_stated_scale_out_of_every_page():
    assert scale_out_of_range(0.002) == "" and scale_out_of_range(1e-15) == "" and scale_out_of_range(1e15) == ""
    assert scale_out_of_range(5e-324).startswith("under 1e-15 SI units per mm")
    assert scale_out_of_range(1e300).startswith("over 1e+15 SI units per mm")


def test_a_figure_between_a_dot_and_ten_metres_of_paper_can_be_drawn():
    lo, hi = DRAWN_SIZE_RANGE_MM
    assert drawn_size_problem(0.2, 0.002) is None  # 100 mm
    assert drawn_size_problem(lo * 0.002, 0.002) is None and drawn_size_problem(hi * 0.002, 0.002) is None
    assert drawn_size_problem(0.1, 1e-9) == ("μl = 1e-09 m/mm draws the mechanism 1e+08 mm across: choose μl so "
                                             "that it is 0.1 … 10000 mm")
    assert drawn_size_problem(1e-5, 1.0, "v", "the velocity polygon").startswith(
        "μv = 1 (m/s)/mm draws the velocity polygon 1e-05 mm across")
    assert drawn_size_problem(1e300, 1e-300) == ("the mechanism is too large for double precision (the scene's "
                                                 "sizes are too extreme) at μl = 1e-300 m/mm")
    assert drawn_size_problem(1.0, 1e-9, "s", "the follower", note="μs = 1e-09 rad/mm").startswith(
        "μs = 1e-09 rad/mm draws the follower")


def test_a_whole_turns_phi_axis_fits_a_drawing():
    lo, hi = PHI_AXIS_RANGE_MM
    assert phi_axis_problem(math.radians(2.5)) is None  # 144 mm
    assert phi_axis_problem(2 * math.pi / hi) is None and phi_axis_problem(2 * math.pi / lo) is None
    assert phi_axis_problem(math.radians(72)) == ("μφ makes the φ axis of a turn 5 mm long: choose μφ so that it "
                                                  "is 10 … 2000 mm (phi_deg_per_mm = 0.18 … 36)")


def test_an_oscillating_followers_swing_has_a_scale_in_degrees_per_mm_and_epsilon_its_own():
    import math

    from graphmech.scales import SCALE_INFO, format_scale

    assert format_scale("psi", math.radians(0.5)) == "μψ = 0.5 °/mm"
    assert SCALE_INFO["epsilon"] == ("με", "(rad/s²)/mm") and SCALE_INFO["omega"][0] == "μω"
