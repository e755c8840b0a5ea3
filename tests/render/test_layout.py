"""Layout: panels in rows, the free room spread, wrapped; never scaled; warnings when they cannot
fit; fit pages cropped to the content; scale bars in the frames; the title block clear of panels."""
from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.render.layout import (BAR_GAP, FIT_MARGIN, FIT_MAX_SHAPE, SheetLayout, footer_room, item_box,
                                     layout_sheet, panel_bbox)
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet
from graphmech.drawing.primitives import Arrow, FixedPivot, Hinge, Label, Panel, Segment, Sheet, TitleBlock
from graphmech.render.style import DEFAULT
from graphmech.scales import PAPER


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
    for p in (a, b):
        assert inside(p.frame, sheet.page, DEFAULT.page_margin)
        assert inside(p.drawing_on_page, sheet.page, DEFAULT.page_margin)
    # the free width is spread evenly before, between (beyond the panel gap) and after them
    m = DEFAULT.page_margin
    slot = a.frame[0] - m
    assert slot > 30.0
    assert b.frame[0] - a.frame[2] - DEFAULT.panel_gap == pytest.approx(slot)
    assert 297.0 - m - b.frame[2] == pytest.approx(slot)
    assert a.frame[3] == pytest.approx(b.frame[3])  # they stand on one line
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


# ---------------------------------------------------------------- the free room spread out
def test_rows_are_spread_over_the_height() -> None:
    panels = tuple(Panel(f"p{k}", "", (Segment((0.0, 0.0), (40.0, 30.0)),), row=k) for k in range(3))
    lay = layout_sheet(Sheet("T", panels, footer=("f",)))
    tops = [p.frame[1] for p in lay.panels]
    bottoms = [p.frame[3] for p in lay.panels]
    top = DEFAULT.page_margin + DEFAULT.title_size * (1.0 + DEFAULT.line_gap)
    bottom = 210.0 - DEFAULT.page_margin - footer_room(1, DEFAULT.page_margin)
    gaps = [tops[0] - top, tops[1] - bottoms[0] - DEFAULT.panel_gap,
            tops[2] - bottoms[1] - DEFAULT.panel_gap, bottom - bottoms[2]]
    assert gaps == pytest.approx([gaps[0]] * 4) and gaps[0] > 10.0


def test_rows_of_as_many_panels_share_columns() -> None:
    rows = [(30.0, 80.0, 50.0), (60.0, 40.0, 20.0)]
    panels = tuple(Panel(f"r{r}c{c}", "", (Segment((0.0, 0.0), (w, 20.0)),), row=r)
                   for r, ws in enumerate(rows) for c, w in enumerate(ws))
    lay = layout_sheet(Sheet("", panels, (420.0, 297.0)))
    centres = [(p.frame[0] + p.frame[2]) / 2.0 for p in lay.panels]
    assert centres[:3] == pytest.approx(centres[3:])  # column by column, one above the other
    assert centres[0] < centres[1] < centres[2]


def test_one_small_panel_stays_in_the_middle_of_the_page() -> None:
    lay = layout_sheet(Sheet("", (bar("a", 50.0),)))
    x0, y0, x1, y1 = lay.panels[0].frame
    assert (x0 + x1) / 2 == pytest.approx(297.0 / 2) and (y0 + y1) / 2 == pytest.approx(210.0 / 2)


@st.composite
def sheets(draw: st.DrawFn, fit: bool = False, block: bool = False) -> Sheet:
    n = draw(st.integers(1, 7))
    explicit = draw(st.booleans())
    panels = []
    for k in range(n):
        w = draw(st.floats(5.0, 120.0))
        h = draw(st.floats(0.0, 80.0))
        notes = tuple(draw(st.lists(st.sampled_from(["μl = 0.002 m/mm", "note"]), max_size=2)))
        scales = tuple(draw(st.lists(st.tuples(st.sampled_from(["l", "v", "phi", "F"]),
                                               st.floats(1e-4, 50.0)), max_size=2)))
        row = draw(st.integers(0, 2)) if explicit else None
        panels.append(Panel(f"p{k}", draw(st.sampled_from(["", "Velocity polygon"])),
                            (Segment((0.0, 0.0), (w, h)),), notes, row, scales))
    if explicit:  # rows numbered in the order they first appear, as the kinds number them
        order = {r: i for i, r in enumerate(dict.fromkeys(p.row for p in panels))}
        panels = [dataclasses.replace(p, row=order[p.row]) for p in panels]
    page = draw(st.sampled_from(sorted(PAPER.values())))
    tb = TitleBlock(name=draw(st.sampled_from(["", "Li Lei", "Иванов И. И."])), sheet="1",
                    notation=draw(st.sampled_from(["en", "zh", "ru"]))) if block else None
    return Sheet(draw(st.sampled_from(["", "A sheet"])), tuple(panels), page,
                 ("graphmech 0.1.0",), fit=fit, title_block=tb)


def _assert_sound(sheet: Sheet) -> SheetLayout:
    lay = layout_sheet(sheet)
    assert lay == layout_sheet(sheet)  # deterministic
    for pl, panel in zip(lay.panels, sheet.panels):  # translation and flip only
        bb = panel_bbox(panel)
        x0, y0, x1, y1 = pl.drawing_on_page
        assert (x1 - x0, y1 - y0) == pytest.approx((bb[2] - bb[0], bb[3] - bb[1]), abs=1e-9)
        assert pl.frame[0] <= x0 + 1e-9 and x1 <= pl.frame[2] + 1e-9 and pl.frame[1] <= y0 + 1e-9
        for bar, (bx, by) in pl.scale_bars:  # the bars are inside the frame, under the drawing
            assert pl.frame[0] - 1e-9 <= bx and bx + bar.width <= pl.frame[2] + 1e-9
            assert y1 <= by and by + bar.height <= pl.frame[3] + 1e-9
    if not lay.warnings:
        frames = [p.frame for p in lay.panels]
        for i, a in enumerate(frames):
            assert inside(a, lay.page, (FIT_MARGIN if sheet.fit else DEFAULT.page_margin) - 1e-9)
            for b in frames[i + 1:]:
                assert not overlap(a, b)
    return lay


@settings(max_examples=150, deadline=None)
@given(sheets())
def test_any_sheet_is_laid_out_without_overlap(sheet: Sheet) -> None:
    _assert_sound(sheet)


# ---------------------------------------------------------------- fit: cropped to the content
@settings(max_examples=150, deadline=None)
@given(sheets(fit=True))
def test_a_fit_page_holds_its_content_and_no_more(sheet: Sheet) -> None:
    lay = _assert_sound(sheet)
    assert lay.warnings == ()  # the page is made to hold it
    m = FIT_MARGIN
    frames = [p.frame for p in lay.panels]
    assert lay.page == tuple(float(round(x)) for x in lay.page)  # whole millimetres
    # cropped: the content reaches the margins (less than a millimetre of rounding), at the
    # left and right unless the title or footer is wider, and at the bottom above the footer
    widest = max(f[2] - f[0] for f in frames)
    assert min(f[0] for f in frames) < m + 1.0 or widest < lay.page[0] - 2 * m - 1.0
    lowest = max(f[3] for f in frames)
    foot = footer_room(len(sheet.footer), m)
    assert lay.page[1] - m - foot - 1.0 < lowest <= lay.page[1] - m - foot + 1e-9


def test_a_fit_page_is_cropped_whatever_the_working_area() -> None:
    panels = (bar("a", 60.0, 30.0, "Mechanism"), bar("b", 40.0, 40.0))
    small = layout_sheet(Sheet("", panels, PAPER["A4"], fit=True))
    large = layout_sheet(Sheet("", panels, PAPER["A1"], fit=True))
    assert small.page == large.page and small.page[0] < 160.0 and small.page[1] < 160.0
    huge = layout_sheet(Sheet("", (bar("h", 900.0, 700.0),), PAPER["A4"], fit=True))
    assert huge.warnings == () and huge.page[0] > 900.0 and huge.page[1] > 700.0


def test_a_fit_sheet_of_many_panels_is_not_a_strip() -> None:
    lay = layout_sheet(Sheet("", tuple(bar(f"p{k}", 80.0, 60.0) for k in range(8)), fit=True))
    w, h = lay.page
    assert 1 / FIT_MAX_SHAPE < w / h < FIT_MAX_SHAPE  # not one row (or one column) of eight
    assert {len({p.frame[1] for p in lay.panels}), len({p.frame[0] for p in lay.panels})} == {2, 4}


def test_a_fit_pages_title_is_wrapped_to_the_drawing() -> None:
    title = "Crank-rocker AB = 28, BC = 52, CD = 50, AD = 72 mm through a whole turn"
    lay = layout_sheet(Sheet(title, (bar("a", 90.0, 40.0),), fit=True))
    assert len(lay.title_lines) == 3 and " ".join(lay.title_lines) == title
    assert lay.page[0] < 120.0  # not as wide as the title on one line (about 210 mm)
    assert min(p.frame[1] for p in lay.panels) > lay.title_at[1] + DEFAULT.title_size * DEFAULT.line_gap
    calls = draw_sheet(Sheet(title, (bar("a", 90.0, 40.0),), fit=True), RecordingBackend())
    drawn = [c for c in calls if c[0] == "text" and c[3] == DEFAULT.title_size]
    assert [c[1] for c in drawn] == list(lay.title_lines)
    assert drawn[1][2][1] - drawn[0][2][1] == pytest.approx(DEFAULT.title_size * DEFAULT.line_gap)
    assert layout_sheet(Sheet(title, (bar("a", 90.0, 40.0),))).title_lines == (title,)  # a paper page: one line


# ---------------------------------------------------------------- scale bars in the frame
def test_scale_bars_stand_under_the_caption_inside_the_frame() -> None:
    plain = Panel("v", "Velocity polygon", (Segment((0.0, 0.0), (60.0, 20.0)),), ("μv = 0.005 (m/s)/mm",))
    barred = dataclasses.replace(plain, scales=(("v", 0.005), ("l", 0.002)))
    a = layout_sheet(Sheet("", (plain,))).panels[0]
    b = layout_sheet(Sheet("", (barred,))).panels[0]
    bars = [bar for bar, _ in b.scale_bars]
    assert [x.symbol for x in bars] == ["v", "l"]
    grown = sum(x.height + BAR_GAP for x in bars)
    assert (b.frame[3] - b.frame[1]) - (a.frame[3] - a.frame[1]) == pytest.approx(grown)
    last_base = b.caption[-1].at[1]
    (_, (x1, y1)), (_, (x2, y2)) = b.scale_bars
    assert last_base < y1 and y1 + bars[0].height < y2  # under the notes, one under the other
    cx = (b.frame[0] + b.frame[2]) / 2.0
    assert x1 + bars[0].width / 2.0 == pytest.approx(cx)  # centred under the caption


# ---------------------------------------------------------------- the title block
@settings(max_examples=150, deadline=None)
@given(sheets(block=True))
def test_the_title_block_is_at_the_lower_right_clear_of_every_panel(sheet: Sheet) -> None:
    lay = _assert_sound(sheet)
    box = lay.title_block_box
    assert box is not None
    m = DEFAULT.page_margin
    if box[2] - box[0] <= lay.page[0] - 2.0 * m:
        assert box[2] == pytest.approx(lay.page[0] - m) and box[3] == pytest.approx(lay.page[1] - m)
    if not lay.warnings:
        for p in lay.panels:
            assert not overlap(p.frame, box)


@settings(max_examples=60, deadline=None)
@given(sheets(fit=True, block=True))
def test_a_fit_page_holds_its_title_block(sheet: Sheet) -> None:
    lay = _assert_sound(sheet)
    box = lay.title_block_box
    assert lay.warnings == () and box is not None
    assert inside(box, lay.page, FIT_MARGIN - 1e-9)
    for p in lay.panels:
        assert not overlap(p.frame, box)


def test_the_rows_make_room_for_the_title_block_only_where_they_must() -> None:
    block = TitleBlock(name="Li Lei")
    panels = (bar("a", 60.0, 60.0), bar("b", 60.0, 60.0))
    clear = layout_sheet(Sheet("", panels, PAPER["A3"], title_block=block))
    alone = layout_sheet(Sheet("", panels, PAPER["A3"]))
    assert clear.panels == alone.panels  # a row high above the block is laid out as without it
    tall = tuple(bar(k, 60.0, 240.0) for k in "abc")
    beside = layout_sheet(Sheet("", tall, PAPER["A3"], title_block=block))
    box = beside.title_block_box
    assert box is not None and beside.warnings == ()
    for p in beside.panels:  # down beside it, all on its left
        assert p.frame[3] > box[1] and p.frame[2] <= box[0] - DEFAULT.panel_gap + 1e-9
    wide = layout_sheet(Sheet("", (bar("w", 380.0, 60.0), bar("v", 380.0, 150.0)), PAPER["A3"], title_block=block))
    box = wide.title_block_box
    assert box is not None and wide.warnings == ()
    assert wide.panels[1].frame[3] <= box[1] - DEFAULT.panel_gap + 1e-9  # above it


def test_a_title_block_wider_than_the_page_warns() -> None:
    block = TitleBlock(title="x" * 200)
    lay = layout_sheet(Sheet("", (bar("a", 20.0),), PAPER["A4"], title_block=block))
    assert any("title block" in w for w in lay.warnings)


def test_a_tight_page_closes_the_gaps_before_it_lets_panels_run_off() -> None:
    """Two rows that need 170 mm with 12 mm gaps but 164 mm with TIGHT_GAP: laid out without a
    warning, the rows TIGHT_GAP apart at least; two that need more still warn."""
    from graphmech.render.layout import TIGHT_GAP

    def rows(h: float) -> Sheet:
        return Sheet("", tuple(Panel(f"p{k}", "", (Segment((0.0, 0.0), (40.0, h)),), row=k) for k in range(2)))

    room = 210.0 - 2 * DEFAULT.page_margin
    h = (room - TIGHT_GAP) / 2.0 - 2 * DEFAULT.panel_padding - 1.0  # fits with the tight gap only
    lay = layout_sheet(rows(h))
    assert lay.warnings == ()
    (a, b) = lay.panels
    assert TIGHT_GAP - 1e-9 <= b.frame[1] - a.frame[3] < DEFAULT.panel_gap
    assert any("run off" in w for w in layout_sheet(rows(h + TIGHT_GAP)).warnings)


def test_a_long_note_is_wrapped_to_its_drawing_or_note_width_in_even_lines() -> None:
    from graphmech.drawing.lettering import text_box_size
    from graphmech.render.layout import NOTE_WIDTH

    note = "the crank turns fully; position 1 (bold): the working stroke begins " * 4
    lay = layout_sheet(Sheet("", (Panel("p", "T", (Segment((0.0, 0.0), (30.0, 0.0)),), (note.strip(),)),),
                             (420.0, 297.0)))
    lines = [c.text for c in lay.panels[0].caption[1:]]
    widths = [text_box_size(t, DEFAULT.note_size)[0] for t in lines]
    assert len(lines) > 1 and " ".join(lines) == note.strip()
    assert max(widths) <= NOTE_WIDTH + 1e-9 and min(widths) > 0.5 * max(widths)  # no lone last word


def test_a_fit_page_stacks_short_panels_beside_a_tall_one() -> None:
    """One panel 100 mm tall and two of 40 mm: on a fit page the short ones stand one above the
    other beside the tall one (a cell), not in a row that leaves 60 mm empty under them."""
    tall = Panel("tall", "", (Segment((0.0, 0.0), (60.0, 100.0)),))
    short = [Panel(f"s{k}", "", (Segment((0.0, 0.0), (50.0, 40.0)),)) for k in range(2)]
    lay = layout_sheet(Sheet("", (tall, *short), fit=True))
    t, a, b = (p.frame for p in lay.panels)
    assert a[0] == pytest.approx(b[0]) and a[3] < b[1]  # stacked: same column, a above b
    assert a[0] > t[2] and b[3] <= t[3] + 1e-9  # beside the tall one, no lower
    area = sum((f[2] - f[0]) * (f[3] - f[1]) for f in (t, a, b))
    assert area / (lay.page[0] * lay.page[1]) > 0.6


def test_fill_rows_keeps_fixed_rows_apart_from_the_greedy_ones() -> None:
    from graphmech.render.layout import fill_rows

    assert fill_rows([10, 10, 10, 5], 25, 2) == [[0, 1], [2, 3]]
    # a fixed row takes no greedy panel after it, and its members stand together wherever they are
    assert fill_rows([10, 10, 10, 10], 100, 2, [0, None, 0, None]) == [[0, 2], [1, 3]]
    assert fill_rows([50, 10], 20, 2) == [[0], [1]]  # a thing wider than the limit stands alone
