"""Label placement: deterministic, clear of each other, of strokes and of avoided directions."""
from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.render.labels import boxes_overlap, place_labels, text_box_size
from graphmech.drawing.primitives import Label


def box_hits_segment(box, p0, p1, n: int = 400) -> bool:
    x0, y0, x1, y1 = box
    for k in range(n + 1):
        t = k / n
        x, y = p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1])
        if x0 < x < x1 and y0 < y < y1:
            return True
    return False


def test_same_input_same_positions() -> None:
    labels = [
        Label(t, (10.0 * (i % 4), 7.0 * (i // 4)), avoid=((1.0, 0.2),))
        for i, t in enumerate("abcdefghij")
    ]
    segs = [((0.0, 0.0), (30.0, 14.0)), ((5.0, 20.0), (25.0, -3.0))]
    discs = [((10.0, 7.0), 1.4)]
    first = place_labels(labels, segs, discs)
    for _ in range(3):
        assert place_labels(labels, segs, discs) == first
    assert [p.label for p in first] == labels


def test_box_has_the_estimated_size_and_clears_the_anchor() -> None:
    (p,) = place_labels([Label("O1", (5.0, 5.0), size=3.5)])
    w, h = text_box_size("O1", 3.5)
    x0, y0, x1, y1 = p.box
    assert (w, h) == (4.2, 3.5)
    assert (x1 - x0, y1 - y0) == pytest.approx((w, h), abs=1e-12)
    assert p.center == pytest.approx(((x0 + x1) / 2, (y0 + y1) / 2), abs=1e-12)
    # the anchor (and a hinge of radius 1.2 mm around it) stays outside the box
    cx = min(max(5.0, x0), x1)
    cy = min(max(5.0, y0), y1)
    assert math.hypot(cx - 5.0, cy - 5.0) >= 1.6
    # nothing in the way: upper right
    assert p.center[0] > 5.0 and p.center[1] > 5.0


def test_avoid_covering_the_right_side_puts_the_label_on_the_left() -> None:
    right = tuple(
        (math.cos(math.radians(a)), math.sin(math.radians(a))) for a in range(-80, 81, 20)
    )
    (p,) = place_labels([Label("B", (0.0, 0.0), avoid=right)])
    assert p.box[2] < 0.0  # the whole box left of the anchor


def test_label_does_not_cross_a_line_through_its_anchor() -> None:
    segs = [((-20.0, -20.0), (20.0, 20.0)), ((-20.0, 20.0), (20.0, -20.0))]
    (p,) = place_labels([Label("C", (0.0, 0.0))], segs)
    assert not any(box_hits_segment(p.box, a, b) for a, b in segs)


def test_second_label_of_a_crowded_anchor_moves_elsewhere() -> None:
    a, b = place_labels([Label("A", (0.0, 0.0)), Label("A′", (0.0, 0.0))])
    assert boxes_overlap(a.box, b.box) == 0.0
    assert a.center != b.center


def test_label_keeps_off_a_hinge_next_to_it() -> None:
    (free,) = place_labels([Label("B", (0.0, 0.0))])
    c = free.center
    (p,) = place_labels([Label("B", (0.0, 0.0))], discs=[(c, 1.3)])
    x0, y0, x1, y1 = p.box
    nx, ny = min(max(c[0], x0), x1), min(max(c[1], y0), y1)
    assert math.hypot(nx - c[0], ny - c[1]) >= 1.3


def spread(points: list[tuple[float, float]], min_dist: float) -> list[tuple[float, float]]:
    """Keep each point that is at least ``min_dist`` from all kept before it."""
    kept: list[tuple[float, float]] = []
    for p in points:
        if all(math.dist(p, q) >= min_dist for q in kept):
            kept.append(p)
    return kept


coords = st.floats(0.0, 100.0, allow_nan=False, allow_infinity=False)
texts = st.text(alphabet="abcdpqABCO123′", min_size=1, max_size=2)


@settings(max_examples=200, deadline=None)
@given(
    st.lists(st.tuples(coords, coords), min_size=1, max_size=60),
    st.lists(texts, min_size=60, max_size=60),
    st.lists(st.sampled_from([3.0, 3.5]), min_size=60, max_size=60),
)
def test_placed_boxes_never_overlap_when_anchors_are_10mm_apart(points, names, sizes) -> None:
    anchors = spread(points, 10.0)[:30]
    labels = [Label(names[i], a, size=sizes[i]) for i, a in enumerate(anchors)]
    placed = place_labels(labels)
    assert len(placed) == len(labels)
    for p, q in itertools.combinations(placed, 2):
        assert boxes_overlap(p.box, q.box) == 0.0, (p, q)
    # and no box covers another label's anchor
    for p in placed:
        for lab in labels:
            x, y = lab.anchor
            if lab is not p.label:
                assert not (p.box[0] < x < p.box[2] and p.box[1] < y < p.box[3])
