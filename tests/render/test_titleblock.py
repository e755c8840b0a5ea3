"""The title block: cells in the scene's notation, each as wide as its text, ruling the whole
block without gaps or overlaps; the scale from the panels' μl; drawn as a ruled table."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.drawing.lettering import text_box_size
from graphmech.drawing.primitives import Arrow, Panel, Segment, Sheet, TitleBlock
from graphmech.render.layout import layout_sheet
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet
from graphmech.render.titleblock import (MIN_WIDTH, PAD, ROW, draw_title_block, scale_text,
                                         title_block_layout)
from graphmech.scales import PAPER


def test_the_words_in_each_notation() -> None:
    labels = {n: [c.text for c in title_block_layout(TitleBlock(notation=n), "T", "1:1").cells[1::2]]
              for n in ("en", "zh", "ru")}
    # scale, sheet (top right), then drawn by, class, date (bottom row)
    assert labels["zh"] == ["比例", "图号", "设计", "班级", "日期"]
    assert labels["en"] == ["Scale", "Sheet", "Drawn", "Class", "Date"]
    assert labels["ru"] == ["Масштаб", "Лист", "Разраб.", "Группа", "Дата"]


def test_the_values_are_the_scenes_strings_and_the_title_defaults_to_the_sheets() -> None:
    block = TitleBlock(name="张三", group="机械 2101", date="2024-06-01", sheet="1/3")
    cells = title_block_layout(block, "Crank-rocker", "1:2").cells
    assert (cells[0].text, cells[2].text, cells[4].text, cells[6].text, cells[8].text, cells[10].text) == (
        "Crank-rocker", "1:2", "1/3", "张三", "机械 2101", "2024-06-01")
    assert title_block_layout(TitleBlock(title="Sheet 1"), "Crank-rocker", "").cells[0].text == "Sheet 1"


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200), st.text(max_size=60), st.text(max_size=60), st.sampled_from(["en", "zh", "ru"]))
def test_cells_hold_their_text_and_tile_the_block(title: str, name: str, date: str, notation: str) -> None:
    lay = title_block_layout(TitleBlock(title=title, name=name, date=date, notation=notation), "", "1:5")
    assert lay.width >= MIN_WIDTH and lay.height == 3 * ROW
    area = 0.0
    for i, c in enumerate(lay.cells):
        x0, y0, x1, y1 = c.box
        assert 0.0 <= x0 < x1 <= lay.width + 1e-9 and 0.0 <= y0 < y1 <= lay.height
        if c.text:
            w, h = text_box_size(c.text, c.size)
            assert w + 2 * PAD <= x1 - x0 + 1e-9 and h < y1 - y0
        area += (x1 - x0) * (y1 - y0)
        for d in lay.cells[i + 1:]:
            assert not (min(x1, d.box[2]) > max(x0, d.box[0]) + 1e-9 and min(y1, d.box[3]) > max(y0, d.box[1]) + 1e-9)
    assert area == pytest.approx(lay.width * lay.height)  # no gaps either


def test_the_scale_is_the_one_length_scale_as_a_ratio() -> None:
    def panels(*mus: float) -> list[Panel]:
        return [Panel(f"p{k}", "", (), scales=(("l", mu), ("v", 0.01))) for k, mu in enumerate(mus)]
    assert scale_text(panels(0.002, 0.002)) == "1:2"
    assert scale_text(panels(0.001)) == "1:1"
    assert scale_text(panels(0.0005)) == "2:1"
    assert scale_text(panels(0.0025)) == "1:2.5"
    assert scale_text(panels(0.002, 0.005)) == ""  # several: each panel states its own
    assert scale_text([Panel("v", "", (), scales=(("v", 0.01),))]) == ""


def test_drawn_as_a_ruled_table_with_a_heavy_outline() -> None:
    lay = title_block_layout(TitleBlock(name="Li Lei", notation="en"), "Four-bar", "1:2")
    rec = RecordingBackend()
    draw_title_block(lay, (100.0, 50.0), rec)
    calls = rec.finish()
    rules = [c for c in calls if c[0] == "polyline"]
    assert len(rules) == len(lay.cells) + 1 and all(c[3] for c in rules)  # closed boxes
    assert [c[2] for c in rules] == ["label"] * len(lay.cells) + ["given"]
    assert rules[-1][1] == ((100.0, 50.0), (100.0 + lay.width, 50.0), (100.0 + lay.width, 74.0), (100.0, 74.0))
    texts = [c[1] for c in calls if c[0] == "text"]
    assert texts == ["Four-bar", "Scale", "1:2", "Sheet", "Drawn", "Li Lei", "Class", "Date"]


# ------------------------------------------------------------------------- on a whole sheet
def demo_sheet(notation: str = "zh", fit: bool = False) -> Sheet:
    """A course-project sheet in small: a mechanism and a velocity polygon with their scales."""
    mech = Panel("mechanism", "机构运动简图", (Segment((0.0, 0.0), (30.0, 40.0)), Segment((30.0, 40.0), (110.0, 10.0))),
                 ("μl = 0.002 m/mm",), scales=(("l", 0.002),))
    vel = Panel("velocity", "速度多边形", (Arrow((0.0, 0.0), (50.0, 20.0)), Arrow((50.0, 20.0), (60.0, -15.0))),
                ("μv = 0.01 (m/s)/mm",), scales=(("v", 0.01),))
    block = TitleBlock(title="曲柄摇杆机构的运动分析", name="张三", group="机械 2101", date="2024-06-01",
                       sheet="1", notation=notation)
    return Sheet("Crank-rocker", (mech, vel), PAPER["A3"], ("graphmech 0.1.0",), fit=fit, title_block=block)


def test_a_sheet_draws_its_title_block_after_the_panels_and_its_scale_bars_in_the_panels() -> None:
    rec = RecordingBackend()
    calls = draw_sheet(demo_sheet(), rec)
    groups = [c[1] for c in calls if c[0] == "begin_group"]
    assert groups[-2:] == ["title-block", "footer"] and groups.count("title-block") == 1
    lay = layout_sheet(demo_sheet())
    box = lay.title_block_box
    assert box is not None and calls[0] == ("begin", 420.0, 297.0, "Crank-rocker")
    # the block's outline is where the layout put it, clear of both panels
    outline = [c for c in calls if c[0] == "polyline" and c[2] == "given" and c[3] and not c[4]][-1]
    assert outline[1][0] == pytest.approx((box[0], box[1])) and outline[1][2] == pytest.approx((box[2], box[3]))
    texts = [c[1] for c in calls if c[0] == "text"]
    assert "比例" in texts and "1:2" in texts and "张三" in texts
    assert texts.count("μ_{l}") == 1 and texts.count("μ_{v}") == 1 and "m/s" in texts  # one bar per scale


def test_a_fit_sheet_begins_on_its_cropped_page() -> None:
    lay = layout_sheet(demo_sheet(fit=True))
    calls = draw_sheet(demo_sheet(fit=True), RecordingBackend())
    assert calls[0][1:3] == lay.page and lay.page[0] < 300.0 and lay.page[1] < 200.0


def test_the_same_sheet_gives_the_same_bytes() -> None:
    from graphmech.render.svg import render_svg

    for fit in (False, True):
        first = render_svg(demo_sheet(fit=fit), "gm1")
        assert first == render_svg(demo_sheet(fit=fit), "gm1")
        assert 'id="gm1-title-block"' in first
