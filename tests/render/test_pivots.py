"""A frame pivot's base stands below it unless a link runs down through it."""
from __future__ import annotations

import math

import pytest

from graphmech.drawing.primitives import FixedPivot, Panel, Segment
from graphmech.render.layout import item_box
from graphmech.render.pivots import BASES, base_of, oriented
from graphmech.render.sheet import LineShape, pivot_shapes


def crank(angle_deg: float) -> Panel:
    a = math.radians(angle_deg)
    return Panel("m", "", (FixedPivot((0.0, 0.0)), Segment((0.0, 0.0), (30 * math.cos(a), 30 * math.sin(a)))))


@pytest.mark.parametrize(("angle", "base"), [(90.0, (0.0, -1.0)), (30.0, (0.0, -1.0)), (-90.0, (1.0, 0.0)),
                                             (-80.0, (1.0, 0.0)), (-100.0, (1.0, 0.0)), (0.0, (0.0, -1.0))])
def test_the_base_stands_below_unless_the_crank_points_down(angle: float, base: tuple[float, float]) -> None:
    [pivot] = [i for i in oriented(crank(angle)).items if isinstance(i, FixedPivot)]
    assert pivot.base == base


def test_a_stated_base_is_kept_and_a_panel_without_pivots_is_left_as_it_is() -> None:
    stated = Panel("m", "", (FixedPivot((0.0, 0.0), (0.0, 1.0)), Segment((0.0, 0.0), (0.0, 30.0))))
    assert oriented(stated) is stated
    bare = Panel("m", "", (Segment((0.0, 0.0), (0.0, 30.0)),))
    assert oriented(bare) is bare
    # with lines every way the base stays below (no side is better by GAIN_MM)
    cross = [((-20.0, 0.0), (20.0, 0.0)), ((0.0, -20.0), (0.0, 20.0))]
    assert base_of(FixedPivot((0.0, 0.0)), cross) == BASES[0]


@pytest.mark.parametrize("base", BASES)
def test_the_turned_symbol_stands_on_its_side_and_its_box_holds_it(base: tuple[float, float]) -> None:
    pivot = FixedPivot((5.0, 7.0), base)
    shapes = [s for _, s in pivot_shapes(pivot)]
    ground = shapes[2]
    assert isinstance(ground, LineShape)
    mid = ((ground.p0[0] + ground.p1[0]) / 2 - 5.0, (ground.p0[1] + ground.p1[1]) / 2 - 7.0)
    assert mid == pytest.approx((4.0 * base[0], 4.0 * base[1]))  # pivot_height along the base
    x0, y0, x1, y1 = item_box(pivot)
    pts = [p for s in shapes if isinstance(s, LineShape) for p in (s.p0, s.p1)]
    assert all(x0 - 1e-9 <= x <= x1 + 1e-9 and y0 - 1e-9 <= y <= y1 + 1e-9 for x, y in pts)
