"""The frontend's draw stream, asserted on a recording backend (no pixels)."""
from __future__ import annotations

import dataclasses
import math
import warnings

import pytest

from graphmech.render.layout import FOOT_EDGE, layout_sheet
from graphmech.drawing.primitives import (
    Arrow,
    Circle,
    FixedPivot,
    GuideLine,
    Hinge,
    Label,
    Panel,
    Segment,
    Sheet,
    Slider,
)
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import LayoutWarning, draw_sheet, panel_labels, panel_shapes
from graphmech.render.style import DEFAULT, Style


def record(sheet: Sheet, **kw: object) -> RecordingBackend:
    rec = RecordingBackend()
    draw_sheet(sheet, rec, **kw)  # type: ignore[arg-type]
    return rec


def one_panel(*items: object, title: str = "", notes: tuple[str, ...] = ()) -> Sheet:
    return Sheet("", (Panel("p", title, tuple(items), notes),))  # type: ignore[arg-type]


def placement(sheet: Sheet, i: int = 0):  # labels-free sheets: no label boxes
    return layout_sheet(sheet, DEFAULT, [[] for _ in sheet.panels]).panels[i]


def test_backends_satisfy_the_protocol() -> None:
    from graphmech.render.backend import Backend
    from graphmech.render.svg import SvgBackend

    assert isinstance(RecordingBackend(), Backend)
    assert isinstance(SvgBackend("gm1"), Backend)


def test_style_is_frozen() -> None:
    with pytest.raises(dataclasses.FrozenInstanceError):
        DEFAULT.arrow_length = 3.0  # type: ignore[misc]
    with pytest.raises(KeyError):
        DEFAULT.pen("bold")


# ------------------------------------------------------------------------- arrows
def test_arrow_is_one_shaft_and_one_filled_head_tip_at_end() -> None:
    arrow = Arrow((3.0, 4.0), (33.0, 24.0))
    sheet = one_panel(arrow)
    rec = record(sheet)
    lines, polys = rec.of("line"), rec.of("polyline")
    assert len(lines) == 1 and len(polys) == 1
    _, pts, key, closed, filled = polys[0]
    assert (key, closed, filled) == ("result", True, True)
    assert len(pts) == 3

    pl = placement(sheet)
    tip = pl.to_page(arrow.p1)
    assert pts[0] == pytest.approx(tip, abs=1e-9)
    # direction in page coordinates: y flipped
    L = math.hypot(30.0, 20.0)
    u = (30.0 / L, -20.0 / L)
    base = ((pts[1][0] + pts[2][0]) / 2, (pts[1][1] + pts[2][1]) / 2)
    assert base == pytest.approx((tip[0] - 2.8 * u[0], tip[1] - 2.8 * u[1]), abs=1e-9)
    # the head is 2 × 0.8 mm wide, symmetric and square to the arrow
    half = ((pts[1][0] - pts[2][0]) / 2, (pts[1][1] - pts[2][1]) / 2)
    assert math.hypot(*half) == pytest.approx(0.8, abs=1e-12)
    assert half[0] * u[0] + half[1] * u[1] == pytest.approx(0.0, abs=1e-12)
    # the shaft runs from the tail to the middle of the head's base
    _, p0, p1, skey, dashed = lines[0]
    assert p0 == pytest.approx(pl.to_page(arrow.p0), abs=1e-9)
    assert p1 == pytest.approx(base, abs=1e-9)
    assert (skey, dashed) == ("result", False)


def test_arrowhead_follows_the_style() -> None:
    style = Style(arrow_length=4.0, arrow_half_width=1.0)
    sheet = one_panel(Arrow((0.0, 0.0), (0.0, 20.0), role="construction"))
    rec = record(sheet, style=style)
    (_, pts, key, _, _), = rec.of("polyline")
    assert key == "construction"
    # pointing up on paper: page y decreases towards the tip
    assert pts[1][1] - pts[0][1] == pytest.approx(4.0, abs=1e-9)
    assert abs(pts[1][0] - pts[2][0]) == pytest.approx(2.0, abs=1e-9)


def test_arrow_shorter_than_its_head_gets_a_shrunk_head_and_no_shaft() -> None:
    rec = record(one_panel(Arrow((0.0, 0.0), (1.4, 0.0))))
    assert rec.of("line") == []
    (_, pts, _, _, _), = rec.of("polyline")
    assert pts[0][0] - pts[1][0] == pytest.approx(1.4, abs=1e-9)
    assert abs(pts[1][1] - pts[2][1]) == pytest.approx(0.8, abs=1e-9)


def test_zero_length_arrow_is_refused() -> None:
    with pytest.raises(ValueError, match="two distinct points"):
        record(one_panel(Arrow((1.0, 1.0), (1.0, 1.0))))


# ------------------------------------------------------------------------- symbols
def test_fixed_pivot_hinge_triangle_ground_and_45_degree_hatching() -> None:
    sheet = one_panel(FixedPivot((10.0, 10.0)))
    rec = record(sheet)
    pl = placement(sheet)
    c = pl.to_page((10.0, 10.0))
    hatch = [x for x in rec.of("line") if x[3] == "hatch"]
    frame = [x for x in rec.of("line") if x[3] == "frame"]
    k = DEFAULT.hatch_length / math.sqrt(2)
    expected = int((2 * DEFAULT.pivot_ground_half - k) / DEFAULT.hatch_spacing + 1e-9) + 1
    assert len(hatch) == expected >= 5
    ground_y = c[1] + DEFAULT.pivot_height  # below the hinge on the page
    for _, p0, p1, _, _ in hatch:
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        assert abs(dx) == pytest.approx(abs(dy), abs=1e-12)  # 45°
        assert math.hypot(dx, dy) == pytest.approx(DEFAULT.hatch_length, abs=1e-12)
        assert p0[1] == pytest.approx(ground_y, abs=1e-12)  # starts on the ground line
        assert dy > 0  # hatching is under the ground (page y down)
    # two legs from the hinge centre and the ground line
    assert len(frame) == 3
    assert sum(1 for x in frame if x[1] == pytest.approx(c)) == 2
    on_ground = pytest.approx(ground_y)
    ground = [x for x in frame if x[1][1] == on_ground and x[2][1] == on_ground]
    assert len(ground) == 1
    assert abs(ground[0][2][0] - ground[0][1][0]) == pytest.approx(2 * DEFAULT.pivot_ground_half)
    # the hinge: white-filled circle drawn after every line
    (_, cc, r, key, filled), = rec.of("circle")
    assert cc == pytest.approx(c) and r == DEFAULT.hinge_r and key == "hinge" and filled
    calls = rec.calls
    assert calls.index(rec.of("circle")[0]) > max(calls.index(x) for x in rec.of("line"))


def test_hinges_are_drawn_after_lines_whatever_the_item_order() -> None:
    rec = record(one_panel(Hinge((0.0, 0.0)), Segment((0.0, 0.0), (20.0, 0.0)), Hinge((20.0, 0.0))))
    names = [c[0] for c in rec.calls if c[0] in ("line", "circle")]
    assert names == ["line", "circle", "circle"]
    assert all(c[3] == "hinge" and c[4] for c in rec.of("circle"))


def test_layers_back_to_front() -> None:
    rec = record(
        one_panel(
            Segment((0.0, 0.0), (10.0, 0.0), role="result"),
            Segment((0.0, 1.0), (10.0, 1.0), role="given"),
            Segment((0.0, 2.0), (10.0, 2.0), role="construction", dashed=True),
            GuideLine((0.0, -5.0), (10.0, -5.0)),
        )
    )
    keys = [c[3] for c in rec.of("line") if c[3] != "hatch"]
    assert keys == ["frame", "construction", "given", "result"]
    assert [c[4] for c in rec.of("line") if c[3] == "construction"] == [True]


def test_guide_hatching_on_the_right_side_seen_p0_to_p1() -> None:
    sheet = one_panel(GuideLine((0.0, 0.0), (0.0, 20.0)))  # going up: right side is +x
    rec = record(sheet)
    pl = placement(sheet)
    x_line = pl.to_page((0.0, 0.0))[0]
    hatch = [c for c in rec.of("line") if c[3] == "hatch"]
    assert len(hatch) >= 10
    for _, p0, p1, _, _ in hatch:
        assert p0[0] == pytest.approx(x_line)
        assert p1[0] - p0[0] == pytest.approx(DEFAULT.hatch_length / math.sqrt(2))


def test_slider_is_a_rotated_white_rectangle() -> None:
    s = Slider((0.0, 0.0), math.radians(30.0), 8.0, 5.0)
    sheet = one_panel(s)
    rec = record(sheet)
    (_, pts, key, closed, filled), = rec.of("polyline")
    assert (key, closed, filled) == ("slider", True, True)
    sides = [math.dist(pts[i], pts[(i + 1) % 4]) for i in range(4)]
    assert sides == pytest.approx([8.0, 5.0, 8.0, 5.0], abs=1e-9)
    # long side along 30° on paper: page y flipped
    dx, dy = pts[1][0] - pts[0][0], pts[1][1] - pts[0][1]
    assert math.degrees(math.atan2(-dy, dx)) == pytest.approx(30.0, abs=1e-9)
    centre = (sum(p[0] for p in pts) / 4, sum(p[1] for p in pts) / 4)
    assert centre == pytest.approx(placement(sheet).to_page((0.0, 0.0)), abs=1e-9)


# ------------------------------------------------------------------------- placement
def test_panel_items_are_translated_and_flipped_never_scaled() -> None:
    pts = [(0.0, 0.0), (40.0, 10.0), (13.0, -25.0), (-7.5, 31.25)]
    items = [Segment(pts[i], pts[i + 1]) for i in range(3)]
    first = Panel("a", "", (Segment((0.0, 0.0), (5.0, 0.0)),))
    rec = record(Sheet("", (first, Panel("b", "", tuple(items)))))
    lines = [c for c in rec.of("line")][1:]
    page = [lines[0][1]] + [c[2] for c in lines]
    for i in range(4):
        for j in range(i + 1, 4):
            assert math.dist(page[i], page[j]) == pytest.approx(math.dist(pts[i], pts[j]), abs=1e-9)
    # a flip: page minus panel is a constant (dx, dy) with page y = dy - y
    dxs = {round(page[i][0] - pts[i][0], 9) for i in range(4)}
    dys = {round(page[i][1] + pts[i][1], 9) for i in range(4)}
    assert len(dxs) == 1 and len(dys) == 1


def test_everything_drawn_lies_in_its_panel_frame() -> None:
    items = (
        Segment((0.0, 0.0), (30.0, 12.0)),
        Arrow((30.0, 12.0), (50.0, -10.0)),
        Circle((10.0, 5.0), 8.0),
        FixedPivot((0.0, 0.0)),
        Hinge((30.0, 12.0)),
        Slider((50.0, -10.0), 0.3),
        GuideLine((35.0, -14.0), (65.0, -14.0)),
        Label("B", (30.0, 12.0)),
        Label("O1", (0.0, 0.0)),
    )
    sheet = Sheet("t", (Panel("m", "Mechanism", items, ("μl = 0.002 m/mm",)),))
    rec = record(sheet)
    drawn = []
    for c in rec.calls:
        if c[0] == "line":
            drawn += [c[1], c[2]]
        elif c[0] == "polyline":
            drawn += list(c[1])
        elif c[0] == "circle":
            drawn += [(c[1][0] - c[2], c[1][1] - c[2]), (c[1][0] + c[2], c[1][1] + c[2])]
    # the layout used for drawing: with the placed labels' boxes
    shapes = panel_shapes(sheet.panels[0])
    boxes = [p.box for p in panel_labels(sheet.panels[0], shapes)]
    pl = layout_sheet(sheet, DEFAULT, [boxes]).panels[0]
    x0, y0, x1, y1 = pl.drawing_on_page
    for x, y in drawn:
        assert x0 <= x <= x1 and y0 <= y <= y1
    labels = [c for c in rec.of("text") if c[6] == "label"]
    assert [c[1] for c in labels] == ["B", "O1"]
    for c in labels:
        assert x0 <= c[2][0] <= x1 and y0 <= c[2][1] <= y1


def test_labels_are_drawn_last_in_their_panel_then_the_caption() -> None:
    sheet = one_panel(
        Segment((0.0, 0.0), (20.0, 0.0)),
        Hinge((0.0, 0.0)),
        Label("A", (0.0, 0.0)),
        title="Mechanism",
        notes=("μl = 0.002 m/mm",),
    )
    rec = record(sheet)
    kinds = [c[0] for c in rec.calls]
    first_text = kinds.index("text")
    # after the first letter only letters and their groups (label, caption): no stroke is drawn
    # over them (the label has no leader here)
    assert set(kinds[first_text:]) == {"text", "begin_group", "end_group", "finish"}
    assert [c[1] for c in rec.of("begin_group")][-2:] == ["label1", "caption"]
    texts = rec.of("text")
    assert [t[1] for t in texts] == ["A", "Mechanism", "μl = 0.002 m/mm"]
    assert texts[0][5] is True and texts[0][6] == "label"  # italic letter
    assert texts[1][2][1] < texts[2][2][1]  # notes under the title
    assert all(t[4] == "middle" for t in texts)


def test_groups_and_sheet_lettering() -> None:
    sheet = Sheet(
        "Velocity analysis",
        (Panel("mech", "", (Segment((0.0, 0.0), (20.0, 0.0)),)),),
        footer=("line 1", "line 2"),
    )
    rec = record(sheet)
    assert rec.calls[0] == ("begin", 297.0, 210.0, "Velocity analysis")
    assert [c[1] for c in rec.of("begin_group")] == ["title", "panel1-mech", "footer"]
    assert len(rec.of("end_group")) == 3
    title, f1, f2 = rec.of("text")
    assert title[1] == "Velocity analysis" and title[2] == (148.5, pytest.approx(15.0))
    assert f1[4] == "start" and f1[2][0] == DEFAULT.page_margin
    assert f1[2][1] < f2[2][1] == pytest.approx(210.0 - FOOT_EDGE)  # in the bottom margin
    assert rec.calls[-1] == ("finish",)


def test_layout_warnings_are_reported() -> None:
    wide = Sheet("", (Panel("big", "", (Segment((0.0, 0.0), (400.0, 0.0)),)),))
    got: list[str] = []
    record(wide, on_warning=got.append)
    assert len(got) == 1 and "'big'" in got[0]
    with pytest.warns(LayoutWarning, match="runs off the page"):
        record(wide)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        record(one_panel(Segment((0.0, 0.0), (40.0, 0.0))))


def test_a_centre_line_is_dash_dot_and_a_plate_is_a_filled_outlined_polygon() -> None:
    from graphmech.drawing.primitives import Circle, Plate, Segment
    from graphmech.render.sheet import item_shapes

    pieces = [s for _, s in item_shapes(Segment((0.0, 0.0), (40.0, 0.0), "construction", dashdot=True))]
    lengths = sorted({round(s.points[-1][0] - s.points[0][0], 6) for s in pieces})
    assert lengths[0] == pytest.approx(0.8) and lengths[-1] == pytest.approx(8.0)  # dot and dash
    ring = [s for _, s in item_shapes(Circle((0.0, 0.0), 20.0, dashdot=True))]
    assert len(ring) > 10 and all(abs(math.hypot(*p) - 20.0) < 1e-2 for s in ring for p in s.points)
    [(layer, tri)] = item_shapes(Plate(((0.0, 0.0), (10.0, 0.0), (5.0, 8.0))))
    assert tri.key == "plate" and tri.closed and tri.filled and len(tri.points) == 3
    assert DEFAULT.pen("plate").fill not in ("white", "none", "black")


# ------------------------------------------------------------------------- fixed text
def test_text_is_set_exactly_where_the_figure_put_it_and_moves_for_nothing() -> None:
    from graphmech.drawing.primitives import Text
    from graphmech.drawing.lettering import BASELINE_DROP

    cell = Text("p_{l}", (10.0, -8.0), 3.5, "end")
    # a line through its point and a label anchored there: a label would move, the text does not
    sheet = one_panel(Segment((0.0, -8.0), (20.0, -8.0)), cell, Label("A", (10.0, -8.0)))
    rec = record(sheet)
    at = placement_with_labels(sheet).to_page(cell.at)
    texts = {c[1]: c for c in rec.of("text")}
    assert texts["p_{l}"][2:] == (pytest.approx((at[0], at[1] + BASELINE_DROP * 3.5)), 3.5, "end", False, "label")
    assert texts["A"][2] != pytest.approx((at[0], at[1] + BASELINE_DROP * 3.5))
    assert panel_shapes(one_panel(cell).panels[0]) == []  # no strokes of its own


def placement_with_labels(sheet: Sheet, i: int = 0):
    shapes = [panel_shapes(p) for p in sheet.panels]
    placed = [panel_labels(p, s) for p, s in zip(sheet.panels, shapes)]
    return layout_sheet(sheet, DEFAULT, [[q.box for q in lab] for lab in placed]).panels[i]


def test_each_label_is_a_group_of_its_own_with_its_leader() -> None:
    star = tuple(Segment((0.0, 0.0), (30.0 * math.cos(math.radians(a)), 30.0 * math.sin(math.radians(a))))
                 for a in range(0, 360, 30))
    sheet = one_panel(*star, Hinge((0.0, 0.0)), Label("E", (0.0, 0.0)), Label("F", (60.0, 0.0)),
                      title="Star")
    rec = record(sheet)
    calls = rec.calls
    (e,) = [i for i, c in enumerate(calls) if c[0] == "text" and c[1] == "E"]
    (f,) = [i for i, c in enumerate(calls) if c[0] == "text" and c[1] == "F"]
    # E had to move from the star's centre: its group holds its leader and its text, nothing else
    assert calls[e - 2][0] == "begin_group" and calls[e - 2][1] == "label1"
    assert calls[e - 1][0] == "line" and calls[e - 1][3] == "label" and calls[e + 1] == ("end_group",)
    # F is free: its text alone
    assert calls[f - 1] == ("begin_group", "label2") and calls[f + 1] == ("end_group",)
    # the leader on the page: from just outside the hinge to near E's text
    placed = panel_labels(sheet.panels[0], panel_shapes(sheet.panels[0]))
    pl = layout_sheet(sheet, DEFAULT, [[p.box for p in placed]]).panels[0]
    centre = pl.to_page((0.0, 0.0))
    a, b = calls[e - 1][1], calls[e - 1][2]
    assert 1.2 < math.dist(a, centre) < 2.5 and math.dist(b, centre) > math.dist(a, centre) + 1.0
    # the text is set on the placed baseline
    assert calls[e][2] == pytest.approx(pl.to_page(placed[0].baseline))


def test_coincident_points_are_drawn_as_one_label() -> None:
    sheet = one_panel(Arrow((0.0, 0.0), (20.0, 5.0)), Label("c₃", (0.0, 0.0)), Label("p", (0.1, 0.0)),
                      Label("b", (20.0, 5.0)))
    assert [c[1] for c in record(sheet).of("text")] == ["p (c₃)", "b"]


def test_a_label_keeps_off_the_block_and_the_hatching_it_names() -> None:
    sheet = one_panel(GuideLine((-30.0, -2.5), (30.0, -2.5)), Slider((0.0, 0.0), 0.0),
                      Segment((0.0, 0.0), (-25.0, 15.0)), Hinge((0.0, 0.0)), Label("C", (0.0, 0.0)))
    (p,) = panel_labels(sheet.panels[0], panel_shapes(sheet.panels[0]))
    x0, y0, x1, y1 = p.box
    # the block is 8 × 5 about C; the hatching hangs 1.3 mm under the guide at y = −2.5
    assert x1 <= -4.0 or x0 >= 4.0 or y0 >= 2.5 + 0.25 or y1 <= -2.5 - 1.3 - 0.1


def test_a_plate_and_its_number_are_drawn_in_one_group() -> None:
    """The number is the plate's own (the browser test's ownership rule: a group holding one text
    owns its shapes); drawn at the given point, else at the vertices' centroid."""
    from graphmech.drawing.primitives import Plate

    rec = record(one_panel(Plate(((0.0, 0.0), (30.0, 0.0), (15.0, 24.0)), number="3"),
                           Plate(((40.0, 0.0), (70.0, 0.0), (55.0, 24.0)))))
    kinds = [c[0] if c[0] != "begin_group" else c[1] for c in rec.calls]
    i = kinds.index("plate")
    assert kinds[i + 1:i + 4] == ["polyline", "text", "end_group"] and kinds.count("plate") == 1
    text = rec.calls[i + 2]
    poly = rec.calls[i + 1][1]
    cx = sum(p[0] for p in poly) / 3
    assert text[1] == "3" and text[2][0] == pytest.approx(cx) and text[6] == "label"


def test_a_dashed_line_kilometres_long_is_drawn_solid_not_cut_forever():
    # a dash-dot common normal of a higher pair with ρ = 1e300 mm once took minutes (fuzz seed 94)
    from graphmech.render.sheet import MOST_DASHES, dash_pieces

    assert dash_pieces([(0.0, 0.0), (1e300, 0.0)], False, (6.0, 1.5, 1.0, 1.5)) == [((0.0, 0.0), (1e300, 0.0))]
    short = dash_pieces([(0.0, 0.0), (100.0, 0.0)], False, (3.0, 1.0))
    assert len(short) == 25 and MOST_DASHES * 2.0 > 100.0


def test_a_force_sheet_laid_out_to_choose_its_scales_places_each_panels_labels_once(monkeypatch):
    """The force kind lays its sheet out (labels and all) to choose the scales, then draws it: the
    same panels are placed once, and the drawing is the one placed afresh."""
    from pathlib import Path

    from graphmech import api
    from graphmech.render import sheet as sheet_module

    scene = Path(__file__).parents[2] / "figures" / "scenes" / "force.sixbar_kinetostatic.toml"
    placed = []
    real = sheet_module._place

    def counting(panel, shapes, style):
        placed.append(panel.name)
        return real(panel, shapes, style)

    sheet_module._placed.cache_clear()
    monkeypatch.setattr(sheet_module, "_place", counting)
    svg = api.load(scene).render().svg
    assert placed and len(placed) == len(set(placed))  # every panel once
    sheet_module._placed.cache_clear()
    monkeypatch.setattr(sheet_module, "_placed", lambda panel, style: real(  # nothing kept: afresh
        panel, sheet_module.panel_shapes(panel, style), style))
    assert api.load(scene).render().svg == svg
