"""Backend-neutral draw primitives: an arc arrow's points, a polyline's checks, an angle's arc."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.drawing.primitives import ARC_MOST, ArcArrow, Hinge, Label, Panel, Polyline, Sheet, Slider, angle_arc


def test_arc_arrow_points_run_from_start_through_sweep() -> None:
    pts = ArcArrow((1.0, 2.0), 2.0, math.pi / 2, -math.pi).points(4)
    assert len(pts) == 5
    assert pts[0] == pytest.approx((1.0, 4.0), abs=1e-15)
    assert pts[2] == pytest.approx((3.0, 2.0), abs=1e-15)  # clockwise: through +x
    assert pts[-1] == pytest.approx((1.0, 0.0), abs=1e-15)
    assert all(math.dist(p, (1.0, 2.0)) == pytest.approx(2.0, rel=1e-15) for p in pts)


def test_polyline_takes_an_array_and_keeps_float_pairs() -> None:
    line = Polyline(np.array([[0, 0], [10, 0], [10, 5]]), closed=True)  # type: ignore[arg-type]
    assert line.points == ((0.0, 0.0), (10.0, 0.0), (10.0, 5.0))
    assert all(type(v) is float for p in line.points for v in p)
    assert hash(line) == hash(Polyline(((0, 0), (10, 0), (10, 5)), closed=True))


@pytest.mark.parametrize("points, words", [
    (((0.0, 0.0),), "at least two"),
    ((), "at least two"),
    (((0.0, 0.0), (math.nan, 1.0)), "finite"),
    (((0.0, math.inf), (1.0, 1.0)), "finite"),
])
def test_polyline_refuses_too_few_or_non_finite_points(points, words: str) -> None:
    with pytest.raises(ValueError, match=words):
        Polyline(points)


def test_angle_arc_marks_the_smaller_angle() -> None:
    arc = angle_arc((1.0, 1.0), (1.0, 0.0), (0.0, 1.0), 10.0)
    assert arc is not None and arc.role == "label"
    assert arc.points[0] == pytest.approx((11.0, 1.0)) and arc.points[-1] == pytest.approx((1.0, 11.0), abs=1e-14)
    assert len(arc.points) == int(math.pi / 2 * 10.0 / 0.5) + 1  # chords of about 0.5 mm
    assert all(math.dist(p, (1.0, 1.0)) == pytest.approx(10.0) for p in arc.points)
    # from +x to a direction just below −x the smaller angle turns clockwise, through −y
    cw = angle_arc((0.0, 0.0), (1.0, 0.0), (-1.0, -0.01), 10.0)
    assert cw is not None and min(p[1] for p in cw.points) == pytest.approx(-10.0, abs=0.05)


def test_angle_arc_of_a_small_angle_is_short_and_of_a_huge_radius_capped() -> None:
    assert angle_arc((0.0, 0.0), (1.0, 0.0), (1.0, 0.01), 10.0) is None  # under 0.3 mm of arc
    assert len(angle_arc((0.0, 0.0), (1.0, 0.0), (1.0, 0.1), 10.0).points) == 5  # at least 4 chords
    assert len(angle_arc((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), 1e15).points) == ARC_MOST + 1


def test_defaults_and_frozen_records() -> None:
    assert Hinge((0.0, 0.0)).r == 1.2
    assert (Slider((0.0, 0.0), 0.0).length, Slider((0.0, 0.0), 0.0).width) == (8.0, 5.0)
    assert (Label("A", (0.0, 0.0)).size, Label("A", (0.0, 0.0)).italic) == (3.5, True)
    sheet = Sheet("t", (Panel("p", "P", ()),))
    assert sheet.page == (297.0, 210.0) and sheet.footer == () and sheet.panels[0].row is None
    with pytest.raises(dataclasses.FrozenInstanceError):
        sheet.title = "u"  # type: ignore[misc]
