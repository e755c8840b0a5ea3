"""Layout: panels side by side, centred, wrapped; never scaled; warnings when they cannot fit."""
from __future__ import annotations

import pytest

from graphmech.render.layout import item_box, layout_sheet, panel_bbox
from graphmech.drawing.primitives import Arrow, FixedPivot, Hinge, Label, Panel, Segment, Sheet
from graphmech.render.style import DEFAULT


def bar(name: str, w: float, h: float = 20.0, title: str = "") -> Panel:
    return Panel(name, title, (Segment((0.0, 0.0), (w, h)),))


def overlap(a, b) -> bool:
    return min(a[2], b[2]) > max(a[0], b[0]) and min(a[3], b[3]) > max(a[1], b[1])


def inside(box, page, margin: float) -> bool:
    x0, y0, x1, y1 = box
    return margin <= x0 and x1 <= page[0] - margin and margin <= y0 and y1 <= page[1] - margin


def test_two_panels_side_by_side_in_order_within_the_page() -> None:
    sheet = Sheet("Title", (bar("a", 80.0, title="Mechanism"), bar("b", 60.0, 40.0)), footer=("f",))
    lay = layout_sheet(sheet)
    assert lay.warnings == ()
    a, b = lay.panels
    assert not overlap(a.frame, b.frame)
    assert a.frame[2] < b.frame[0]  # left → right in the given order
    assert b.frame[0] - a.frame[2] == pytest.approx(DEFAULT.panel_gap)
    for p in (a, b):
        assert inside(p.frame, sheet.page, DEFAULT.page_margin)
        assert inside(p.drawing_on_page, sheet.page, DEFAULT.page_margin)
    # the row is centred on the page and the panels stand on one line
    assert a.frame[0] - 0.0 == pytest.approx(297.0 - b.frame[2])
    assert a.frame[3] == pytest.approx(b.frame[3])
    # below the sheet title, above the footer
    assert min(a.frame[1], b.frame[1]) > lay.title_at[1]
    assert max(a.frame[3], b.frame[3]) < lay.footer_at[0][1] - DEFAULT.note_size


def test_placement_is_translation_and_flip_only() -> None:
    sheet = Sheet("", (bar("a", 50.0), bar("b", 30.0)))
    for pl, panel in zip(layout_sheet(sheet).panels, sheet.panels):
        bb = panel_bbox(panel)
        x0, y0, x1, y1 = pl.drawing_on_page
        assert (x1 - x0, y1 - y0) == pytest.approx((bb[2] - bb[0], bb[3] - bb[1]), abs=1e-12)
        p, q = pl.to_page((0.0, 0.0)), pl.to_page((3.0, 4.0))
        assert (q[0] - p[0], q[1] - p[1]) == pytest.approx((3.0, -4.0), abs=1e-12)


def test_too_wide_panel_keeps_its_scale_and_warns() -> None:
    sheet = Sheet("", (bar("huge", 350.0),))
    lay = layout_sheet(sheet)
    assert len(lay.warnings) == 1
    assert "'huge'" in lay.warnings[0] and "μ is kept" in lay.warnings[0]
    x0, _, x1, _ = lay.panels[0].drawing_on_page
    bb = panel_bbox(sheet.panels[0])
    assert x1 - x0 == pytest.approx(bb[2] - bb[0])  # not shrunk to the page
    assert (x0 + x1) / 2 == pytest.approx(297.0 / 2)  # still centred


def test_a_row_too_wide_wraps_to_a_second_row() -> None:
    sheet = Sheet("", (bar("a", 120.0), bar("b", 120.0), bar("c", 120.0)))
    lay = layout_sheet(sheet)
    assert lay.warnings == ()
    a, b, c = lay.panels
    assert a.frame[1] == pytest.approx(b.frame[1])  # a and b share the first row
    assert c.frame[1] >= max(a.frame[3], b.frame[3]) + DEFAULT.panel_gap - 1e-9
    assert (c.frame[0] + c.frame[2]) / 2 == pytest.approx(297.0 / 2)
    for p in lay.panels:
        assert inside(p.frame, sheet.page, DEFAULT.page_margin)
    for p, q in [(a, b), (a, c), (b, c)]:
        assert not overlap(p.frame, q.frame)


def test_rows_too_tall_warn() -> None:
    sheet = Sheet("", (bar("a", 200.0, 120.0), bar("b", 200.0, 120.0)))
    lay = layout_sheet(sheet)
    assert len(lay.warnings) == 1 and "height" in lay.warnings[0]


def test_layout_is_deterministic() -> None:
    sheet = Sheet("t", (bar("a", 70.0), bar("b", 90.0), bar("c", 150.0)), footer=("x", "y"))
    assert layout_sheet(sheet) == layout_sheet(sheet)


def test_bounding_box_includes_symbols() -> None:
    assert item_box(Hinge((0.0, 0.0), 1.2)) == pytest.approx((-1.4, -1.4, 1.4, 1.4))
    # the arrowhead's half width sticks out sideways
    assert item_box(Arrow((0.0, 0.0), (10.0, 0.0)))[1] == pytest.approx(-0.8)
    x0, y0, x1, y1 = item_box(FixedPivot((0.0, 0.0)))
    assert y0 < -DEFAULT.pivot_height - 1.0 and x1 >= DEFAULT.pivot_ground_half
    lab = Label("AB", (0.0, 0.0))
    bb = panel_bbox(Panel("p", "", (Segment((0.0, 0.0), (1.0, 0.0)), lab)))
    assert bb[0] < -4.0 and bb[3] > 4.0  # a conservative margin for the label
    panel = Panel("p", "", (Segment((0.0, 0.0), (1.0, 0.0)), lab))
    tight = panel_bbox(panel, label_boxes=[(1.0, 1.0, 5.0, 4.5)])
    assert tight == pytest.approx((-1.0 - 0.35, -1.0 - 0.35, 6.0, 5.5))


def test_empty_panel_is_refused() -> None:
    with pytest.raises(ValueError, match="nothing to draw"):
        layout_sheet(Sheet("", (Panel("e", "", ()),)))



def test_fixed_text_box_is_its_line_by_its_anchor() -> None:
    from graphmech.drawing.lettering import text_box_size
    from graphmech.drawing.primitives import Text

    w, h = text_box_size("n = 12", 3.5)
    assert item_box(Text("n = 12", (0.0, 0.0), 3.5, "start")) == pytest.approx((0.0, -h / 2, w, h / 2))
    assert item_box(Text("n = 12", (0.0, 0.0), 3.5, "middle")) == pytest.approx((-w / 2, -h / 2, w / 2, h / 2))
    assert item_box(Text("n = 12", (5.0, 1.0), 3.5, "end")) == pytest.approx((5.0 - w, 1.0 - h / 2, 5.0, 1.0 + h / 2))
