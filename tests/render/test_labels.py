"""Label placement: deterministic, clear of each other and of everything drawn, leaders for the
labels that had to move, coincident points merged, bounded time."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.drawing.lettering import text_extent
from graphmech.drawing.primitives import (
    Arrow,
    Circle,
    FixedPivot,
    GuideLine,
    Hinge,
    Label,
    Panel,
    Plate,
    Polyline,
    Segment,
    Slider,
)
from graphmech.render.labels import (
    LEADER_FROM,
    LEADER_GAP,
    Obstacles,
    _Grid,
    boxes_overlap,
    is_point_name,
    merge_coincident,
    merged_text,
    place_labels,
)
from graphmech.render.sheet import _obstacles, panel_labels, panel_shapes
from graphmech.render.style import DEFAULT
from graphmech.scene import load_scene
from graphmech.problems import sheet as scene_sheet
from tests.conftest import SCENES


def box_hits_segment(box, p0, p1, n: int = 400) -> bool:
    x0, y0, x1, y1 = box
    for k in range(n + 1):
        t = k / n
        x, y = p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1])
        if x0 < x < x1 and y0 < y < y1:
            return True
    return False


def ink(panel: Panel):
    """What the panel draws, as shapely geometry (independent of the placer): each stroke
    thickened by half its pen's width, filled shapes and hinges as areas; a shape filled with
    its stroke's colour (an arrowhead) is drawn without a stroke (SvgBackend)."""
    from graphmech.render.sheet import LineShape, PolyShape

    parts = []
    for s in panel_shapes(panel):
        pen = DEFAULT.pen(s.key)
        w = 0.0 if isinstance(s, PolyShape) and s.filled and pen.fill == pen.colour else pen.width / 2.0
        if isinstance(s, LineShape):
            parts.append(shapely.LineString([s.p0, s.p1]).buffer(w))
        elif isinstance(s, PolyShape):
            pts = list(s.points) + ([s.points[0]] if s.closed else [])
            parts.append(shapely.LineString(pts).buffer(w) if w else shapely.LineString(pts))
            if s.filled:
                parts.append(shapely.Polygon(s.points))
        else:
            c = shapely.Point(s.c)
            parts.append(c.buffer(s.r + w) if s.filled else c.buffer(s.r + w).difference(c.buffer(s.r - w)))
    return shapely.unary_union(parts)


def crossed(box, geometry, tol: float = 0.1) -> bool:
    """Whether ink reaches more than ``tol`` inside the box (figure-report's rule)."""
    x0, y0, x1, y1 = box
    return shapely.box(x0 + tol, y0 + tol, x1 - tol, y1 - tol).intersects(geometry)


# ----------------------------------------------------------------------------- basics
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
    assert all(p.sources == (p.label,) for p in first)


def test_box_is_the_browsers_cell_and_clears_the_anchor() -> None:
    (p,) = place_labels([Label("O1", (5.0, 5.0), size=3.5)])
    w, up, down = text_extent("O1", 3.5, italic=True)
    x0, y0, x1, y1 = p.box
    assert (x1 - x0, y1 - y0) == pytest.approx((w, up + down), abs=1e-12)
    assert p.center == pytest.approx(((x0 + x1) / 2, (y0 + y1) / 2), abs=1e-12)
    assert p.baseline == pytest.approx((p.center[0], y0 + down))  # y up: the descent under it
    # the anchor (and a hinge of radius 1.2 mm around it) stays outside the box
    cx = min(max(5.0, x0), x1)
    cy = min(max(5.0, y0), y1)
    assert math.hypot(cx - 5.0, cy - 5.0) >= 1.6
    # nothing in the way: upper right, and close enough to need no leader
    assert p.center[0] > 5.0 and p.center[1] > 5.0 and p.leader is None


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


def test_two_labels_of_close_points_keep_apart() -> None:
    a, b = place_labels([Label("A", (0.0, 0.0)), Label("B", (1.0, 0.0))])
    assert boxes_overlap(a.box, b.box) == 0.0
    assert a.center != b.center


def test_label_keeps_off_a_hinge_next_to_it() -> None:
    (free,) = place_labels([Label("B", (0.0, 0.0))])
    c = free.center
    (p,) = place_labels([Label("B", (0.0, 0.0))], discs=[(c, 1.3)])
    x0, y0, x1, y1 = p.box
    nx, ny = min(max(c[0], x0), x1), min(max(c[1], y0), y1)
    assert math.hypot(nx - c[0], ny - c[1]) >= 1.3


# ----------------------------------------------------------------------------- every stroke
STAR = tuple(Segment((0.0, 0.0), (30.0 * math.cos(math.radians(a)), 30.0 * math.sin(math.radians(a))))
             for a in range(0, 360, 30))

OBSTACLE_PANELS = {
    # C on a slider block: not inside the block, not on the guide's hatching
    "slider": (Slider((0.0, 0.0), 0.0), GuideLine((-30.0, -2.5), (30.0, -2.5)), Segment((0.0, 0.0), (25.0, 12.0)),
               Hinge((0.0, 0.0)), Label("C", (0.0, 0.0))),
    # a frame pivot: not on its triangle or hatching, not on the link
    "pivot": (FixedPivot((0.0, 0.0)), Segment((0.0, 0.0), (20.0, 20.0)), Label("A", (0.0, 0.0))),
    # a plate's vertex: not on the filled triangle
    "plate": (Plate(((0.0, 0.0), (30.0, 0.0), (10.0, 20.0))), Hinge((0.0, 0.0)), Segment((0.0, 0.0), (-20.0, 10.0)),
              Label("B", (0.0, 0.0))),
    # the centre of a small circle: the label may not sit on the circle (it goes outside, with a leader)
    "circle": (Circle((0.0, 0.0), 3.0), Circle((0.0, 0.0), 6.0, dashed=True), Label("O", (0.0, 0.0))),
    # an arrow's tip: neither on the shaft nor on the head
    "arrow": (Arrow((-20.0, -3.0), (0.0, 0.0)), Arrow((0.0, 0.0), (3.0, 18.0)), Label("b", (0.0, 0.0))),
    # a point inside a curve of 800 chords that winds round it three times, 8 mm apart
    "curve": (Polyline(tuple((r * math.cos(t), r * math.sin(t)) for t, r in
                             ((k * 0.025, 2.5 + 1.3 * k * 0.025) for k in range(800)))), Label("K", (0.0, 0.0))),
    # a point where twelve lines meet
    "star": STAR + (Label("E", (0.0, 0.0)),),
}


@pytest.mark.parametrize("name", sorted(OBSTACLE_PANELS))
def test_no_label_on_anything_drawn(name: str) -> None:
    panel = Panel(name, "", OBSTACLE_PANELS[name])
    (p,) = panel_labels(panel, panel_shapes(panel))
    assert not crossed(p.box, ink(panel)), p


def test_a_label_that_had_to_move_gets_a_leader_from_near_its_point_to_its_box() -> None:
    panel = Panel("star", "", STAR + (Hinge((0.0, 0.0)), Label("E", (0.0, 0.0))))
    (p,) = panel_labels(panel, panel_shapes(panel))
    x0, y0, x1, y1 = p.box
    gap = math.hypot(max(x0, 0.0, -x1), max(y0, 0.0, -y1))
    assert gap > LEADER_FROM and p.leader is not None
    (a, b) = p.leader
    assert 1.2 < math.hypot(*a) < 2.5  # just outside the hinge
    # the leader's end is LEADER_GAP short of the box's edge, on the line to its centre
    assert math.hypot(b[0] - a[0], b[1] - a[1]) > 1.0
    d = np.subtract(p.center, a) / np.hypot(*np.subtract(p.center, a))
    assert d[0] * (b[1] - a[1]) - d[1] * (b[0] - a[0]) == pytest.approx(0.0, abs=1e-9)
    ex, ey = b[0] + LEADER_GAP * d[0], b[1] + LEADER_GAP * d[1]
    assert min(abs(ex - x0), abs(ex - x1), abs(ey - y0), abs(ey - y1)) == pytest.approx(0.0, abs=1e-9)
    # the leader itself keeps off the lines of the star
    assert not shapely.LineString(p.leader).intersects(ink(Panel("s", "", STAR)))


def test_leaders_drawn_are_obstacles_for_later_labels() -> None:
    panel = Panel("star", "", STAR + (Label("E", (0.0, 0.0)),))
    (e,) = panel_labels(panel, panel_shapes(panel))
    assert e.leader is not None
    mid = ((e.leader[0][0] + e.leader[1][0]) / 2.0, (e.leader[0][1] + e.leader[1][1]) / 2.0)
    e2, f = place_labels([Label("E", (0.0, 0.0)), Label("F", mid)], obstacles=_obstacles(panel_shapes(panel)))
    assert e2 == e
    assert not shapely.box(*f.box).intersects(shapely.LineString(e.leader).buffer(0.1))


# ----------------------------------------------------------------------------- coincident points
def test_point_names() -> None:
    assert [is_point_name(t) for t in ("A", "B₁", "c_{3}", "n₂′", "p′", "π", "P_{13}", "a″")] == [True] * 8
    assert [is_point_name(t) for t in ("ω₁", "1", "12", "φ₂ = 4.30°", "F i", "γmin", "")] == [False] * 7


def test_merged_text_writes_the_pole_first_and_the_others_in_brackets() -> None:
    assert merged_text(["c₃", "p"]) == "p (c₃)"
    assert merged_text(["p′", "c₃′", "d′"]) == "p′ (c₃′, d′)"
    assert merged_text(["π", "b"]) == "π (b)"
    assert merged_text(["a′", "n₂′"]) == "a′, n₂′"
    assert merged_text(["B", "B"]) == "B"
    assert merged_text(["p"]) == "p"


def test_coincident_points_get_one_label() -> None:
    labels = [Label("c₃", (10.0, 5.0), ((1.0, 0.0),)), Label("p", (10.2, 5.1), ((0.0, 1.0),)),
              Label("a′", (0.0, 0.0)), Label("n₂′", (0.0, 0.25)),
              Label("b", (20.0, 0.0)), Label("k", (20.5, 0.0)),  # 0.5 mm apart: two labels
              Label("D", (30.0, 0.0)), Label("ω₁", (30.0, 0.0)),  # not a point name
              Label("E", (40.0, 0.0)), Label("F", (40.0, 0.0), size=2.5)]  # sizes differ
    got = merge_coincident(labels)
    assert [lab.text for lab, _ in got] == ["p (c₃)", "a′, n₂′", "b", "k", "D", "ω₁", "E", "F"]
    pole, src = got[0]
    assert pole.anchor == (10.0, 5.0) and src == tuple(labels[:2])
    assert pole.avoid == ((1.0, 0.0), (0.0, 1.0))
    placed = place_labels(labels)
    assert [p.label.text for p in placed] == [lab.text for lab, _ in got]
    assert placed[0].sources == tuple(labels[:2])
    assert [p.label.text for p in place_labels(labels, merge=False)] == [lab.text for lab in labels]


def test_a_chain_of_close_points_is_one_label() -> None:
    # each within 0.3 mm of the one before: one group, though the ends are 0.5 mm apart
    labels = [Label("a", (0.0, 0.0)), Label("b", (0.25, 0.0)), Label("c", (0.5, 0.0))]
    assert [lab.text for lab, _ in merge_coincident(labels)] == ["a, b, c"]


# ----------------------------------------------------------------------------- scale and limits
@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(-50, 50), st.floats(-50, 50)),
                min_size=1, max_size=40),
       st.tuples(st.floats(-60, 60), st.floats(-60, 60), st.floats(0.1, 30), st.floats(0.1, 30)))
def test_the_grid_finds_every_piece_in_a_region(segs, region) -> None:
    arr = np.array(segs, dtype=float)
    grid = _Grid(np.column_stack([arr, np.zeros(len(segs))]))
    x, y, w, h = region
    box = (x, y, x + w, y + h)
    found = set(grid.query(box).tolist())
    target = shapely.box(*box)
    for i, (x0, y0, x1, y1) in enumerate(segs):
        line = shapely.LineString([(x0, y0), (x1, y1)]) if (x0, y0) != (x1, y1) else shapely.Point(x0, y0)
        if line.intersects(target):
            assert i in found


def test_500_labels_among_20000_stroke_pieces() -> None:
    # a spiral of 20 000 chords, its turns 20 mm apart, and 500 points on it
    t = np.linspace(0.0, 40.0 * math.pi, 20_001)
    r = 10.0 + 20.0 * t / (2.0 * math.pi)
    pts = np.column_stack([r * np.cos(t), r * np.sin(t)])
    segs = np.column_stack([pts[:-1], pts[1:]])
    obstacles = Obstacles(segs, np.full(len(segs), 0.6))
    labels = [Label(f"P_{{{k}}}", (float(pts[i, 0]), float(pts[i, 1])))
              for k, i in enumerate(range(20, 20_001, 40))]
    assert len(labels) == 500
    placed = place_labels(labels, obstacles=obstacles)
    assert [p.label for p in placed] == labels
    spiral = shapely.LineString(pts).buffer(0.3)
    boxes = [p.box for p in placed]
    assert not any(crossed(b, spiral) for b in boxes)
    tree = shapely.STRtree([shapely.box(*b) for b in boxes])
    pairs = tree.query([shapely.box(*b) for b in boxes], predicate="overlaps")
    assert all(boxes_overlap(boxes[i], boxes[j]) < 0.01 for i, j in pairs.T if i != j)


def test_no_free_spot_at_all_gives_the_least_bad_and_goes_on() -> None:
    # hatching 0.5 mm apart all over a 100 mm square: every candidate crosses something
    ys = np.arange(-50.0, 50.0, 0.5)
    segs = [((-50.0, y), (50.0, y + 3.0)) for y in ys]
    labels = [Label(c, (float(x), 0.0)) for c, x in zip("ABCDE", range(-20, 21, 10))]
    placed = place_labels(labels, segs)
    assert [p.label.text for p in placed] == list("ABCDE")
    for p in placed:  # still by its point: on the nearest ring, as it crosses anyway
        x0, y0, x1, y1 = p.box
        ax, ay = p.label.anchor
        assert math.hypot(max(x0 - ax, 0.0, ax - x1), max(y0 - ay, 0.0, ay - y1)) <= DEFAULT.label_gaps[0] + 1e-9
    assert place_labels(labels, [((0.0, 0.0), (math.inf, 1.0))] + segs) == placed  # a non-finite piece is dropped


# ----------------------------------------------------------------------------- the old property
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


# ----------------------------------------------------------------------------- every reference figure
@pytest.mark.parametrize("path", sorted(SCENES.glob("*.toml")), ids=lambda p: p.stem)
def test_reference_figures_labels_clear_of_each_other_and_of_every_stroke(path) -> None:
    scene = load_scene(path)
    drawing, _ = scene_sheet(scene, ("graphmech",))
    for panel in drawing.panels:
        placed = panel_labels(panel, panel_shapes(panel))
        geometry = ink(panel)
        for p in placed:
            assert not crossed(p.box, geometry), (panel.name, p.label.text)
        for p, q in itertools.combinations(placed, 2):
            assert boxes_overlap(p.box, q.box) == 0.0, (panel.name, p.label.text, q.label.text)
        drawn = [t for p in placed for t in ([p.label.text] if len(p.sources) == 1 else [s.text for s in p.sources])]
        assert sorted(drawn) == sorted(it.text for it in panel.items if isinstance(it, Label))
