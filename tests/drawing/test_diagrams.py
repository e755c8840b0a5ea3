"""Diagrams against the crank angle: nice steps, thinning the numbers so they stand clear, the
numbers along the φ axis, and moving drawn items."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.drawing.diagrams import (
    BELOW,
    NICE_STEPS,
    NUMBER_SIZE,
    count_every,
    moved,
    nice_step,
    numbers_every,
    phi_axis_numbers,
)
from graphmech.drawing.primitives import ArcArrow, Arrow, Circle, FixedPivot, Hinge, Label, Polyline, Segment


def test_nice_steps_run_1_2_3_4_5_6_8_then_tens() -> None:
    assert NICE_STEPS[:12] == (1, 2, 3, 4, 5, 6, 8, 10, 20, 30, 40, 50)
    assert list(NICE_STEPS) == sorted(set(NICE_STEPS)) and NICE_STEPS[-1] == 10 ** 6


@pytest.mark.parametrize("least, step", [(-3.0, 1), (0.0, 1), (1.0, 1), (6.5, 8), (8.0 + 1e-13, 8),
                                         (8.001, 10), (11.0, 20), (25.0, 30), (7e5, 800000), (1e9, 10 ** 6)])
def test_nice_step_is_the_smallest_nice_step_not_below(least: float, step: int) -> None:
    assert nice_step(least) == step


def test_numbers_every_keeps_the_numbers_clear_of_each_other() -> None:
    # "100" at 3.5 mm is 6.3 mm wide, plus 1.2 mm clear each side: 8.7 mm; at 2 mm apart, every 5th
    assert NUMBER_SIZE == 3.5  # the least body text of a drawing
    assert numbers_every(100, 2.0) == 5
    assert numbers_every(100, 8.7) == 1
    assert numbers_every(100, 8.6) == 2
    assert numbers_every(36, 0.0) == 36 and numbers_every(36, -1.0) == 36  # no room: only the first


def test_count_every_takes_at_most_so_many() -> None:
    assert count_every(36, 36) == 1
    assert count_every(37, 36) == 2
    assert count_every(360, 36) == 10 and count_every(361, 36) == 20


def test_phi_axis_numbers_every_kth_and_1_again_at_the_end() -> None:
    x = np.linspace(0.0, 120.0, 13)  # 12 positions and the cycle's end
    every1 = phi_axis_numbers(x, 1, y=-2.0)
    assert [lb.text for lb in every1] == [str(k) for k in range(1, 13)] + ["1"]
    assert every1[-1].anchor == (120.0, -2.0) and every1[3].anchor == (30.0, -2.0)
    assert all(lb.avoid == BELOW and lb.size == NUMBER_SIZE and not lb.italic for lb in every1)
    assert [lb.text for lb in phi_axis_numbers(x, 3)] == ["1", "4", "7", "10", "1"]
    assert [lb.text for lb in phi_axis_numbers(x, 5)] == ["1", "6", "11"]  # 12 is not a multiple of 5


def test_moved_translates_every_kind_of_diagram_item() -> None:
    dx, dy = 10.0, -2.0
    assert moved(Segment((0.0, 0.0), (1.0, 1.0), dashed=True), dx, dy) == Segment((10.0, -2.0), (11.0, -1.0), dashed=True)
    assert moved(Arrow((1.0, 2.0), (3.0, 4.0)), dx, dy) == Arrow((11.0, 0.0), (13.0, 2.0))
    assert moved(Circle((1.0, 1.0), 5.0), dx, dy) == Circle((11.0, -1.0), 5.0)
    arc = moved(ArcArrow((0.0, 0.0), 3.0, 0.0, math.pi), dx, dy)
    assert arc == ArcArrow((10.0, -2.0), 3.0, 0.0, math.pi)
    assert moved(Polyline(((0.0, 0.0), (1.0, 0.0)), closed=True), dx, dy) == Polyline(((10.0, -2.0), (11.0, -2.0)), closed=True)
    assert moved(Label("1", (0.0, 0.0), BELOW), dx, dy) == Label("1", (10.0, -2.0), BELOW)


@pytest.mark.parametrize("item", [Hinge((0.0, 0.0)), FixedPivot((0.0, 0.0))])
def test_moved_refuses_what_a_diagram_does_not_hold(item) -> None:
    with pytest.raises(TypeError, match="cannot move"):
        moved(item, 1.0, 1.0)


def test_transformed_enlarges_drawing_sizes_but_keeps_paper_sizes_and_moves_every_kind() -> None:
    from graphmech.drawing.diagrams import moved, transformed
    from graphmech.drawing.primitives import Circle, GuideLine, Hinge, Label, Slider

    block = transformed(Slider((1.0, 1.0), 0.0, 8.0, 5.0), 2.0, 1.0, 0.0)
    assert (block.center, block.length, block.width) == ((3.0, 2.0), 16.0, 10.0)
    assert transformed(GuideLine((0.0, 0.0), (1.0, 0.0)), 3.0).p1 == (3.0, 0.0)
    label = transformed(Label("B", (1.0, 1.0), size=3.5), 2.0)
    assert label.anchor == (2.0, 2.0) and label.size == 3.5  # the letter keeps its paper size
    assert moved(Circle((0.0, 0.0), 2.0), 5.0, -1.0) == Circle((5.0, -1.0), 2.0)
    with pytest.raises(TypeError):
        transformed(Hinge((0.0, 0.0)), 2.0)
