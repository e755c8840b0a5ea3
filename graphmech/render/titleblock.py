"""The title block of a course-project sheet (机械原理课程设计): a ruled table at the page's lower
right, as FIGURES.md describes it ("Sheets").

::

    ┌───────────────────────────────┬──────┬──────────┐
    │                               │ 比例 │ 1:2      │
    │   title (the sheet's title)   ├──────┼──────────┤
    │                               │ 图号 │ sheet    │
    ├──────┬────────┬──────┬────────┼──────┴─┬────────┤
    │ 设计 │ name   │ 班级 │ group  │ 日期   │ date   │
    └──────┴────────┴──────┴────────┴────────┴────────┘

The words are the scene's notation's (en, zh, ru: :data:`WORDS`); the values are the scene's
strings, drawn as written — the date too: no clock is read, so the same scene gives the same
bytes. The scale is the sheet's length scale μl as a ratio (μl = 0.002 m/mm is 1:2) when the
panels state one and only one; otherwise that cell is empty. Every cell is at least as wide as
its text; the block is at least :data:`MIN_WIDTH` wide.

Coordinates: a block is laid out from its top-left corner, page millimetres, y down.

>>> from graphmech.drawing.primitives import TitleBlock
>>> lay = title_block_layout(TitleBlock(name="Li Lei", date="2024-06-01", notation="zh"), "Four-bar", "1:2")
>>> lay.width, lay.height
(140.0, 24.0)
>>> [c.text for c in lay.cells]
['Four-bar', '比例', '1:2', '图号', '', '设计', 'Li Lei', '班级', '', '日期', '2024-06-01']
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

from graphmech.drawing.lettering import BASELINE_DROP, number, text_box_size
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import Panel, TitleBlock
from graphmech.render.backend import Backend
from graphmech.render.labels import Box
from graphmech.render.style import DEFAULT, Style

#: Key → (English, 中文, русский): the labels of the block's cells.
WORDS: Mapping[str, tuple[str, str, str]] = {
    "scale": ("Scale", "比例", "Масштаб"),
    "sheet": ("Sheet", "图号", "Лист"),
    "name": ("Drawn", "设计", "Разраб."),
    "group": ("Class", "班级", "Группа"),
    "date": ("Date", "日期", "Дата"),
}

#: Height of one row of the block, mm (3.5 mm text with room above and below).
ROW = 8.0
#: The narrowest block, the narrowest label and value cells, mm.
MIN_WIDTH = 140.0
MIN_LABEL = 15.0
MIN_VALUE = 25.0
#: Free room left and right of a cell's text, mm.
PAD = 2.0


@dataclass(frozen=True)
class Cell:
    """One cell: its box from the block's top-left corner (mm, y down), its text and size."""

    box: Box
    text: str
    size: float


@dataclass(frozen=True)
class TitleBlockLayout:
    """The block's size (mm) and cells, title first, then row by row, left to right."""

    width: float
    height: float
    cells: tuple[Cell, ...]


def scale_text(panels: Sequence[Panel]) -> str:
    """The sheet's scale as a drawing states it, from the panels' length scales μl (m/mm):
    ``"1:2"`` for 0.002, ``"2:1"`` for 0.0005; ``""`` unless exactly one μl is stated.

    >>> p = Panel("m", "", (), scales=(("l", 0.002), ("v", 0.01)))
    >>> scale_text([p]), scale_text([p, Panel("n", "", (), scales=(("l", 0.0005),))]), scale_text([])
    ('1:2', '', '')
    """
    mus = {mu for p in panels for sym, mu in p.scales if sym == "l"}
    if len(mus) != 1:
        return ""
    ratio = next(iter(mus)) * 1000.0  # real mm per drawn mm
    return f"1:{number(ratio)}" if ratio >= 1.0 else f"{number(1.0 / ratio)}:1"


def title_block_layout(block: TitleBlock, sheet_title: str, scale: str,
                       style: Style = DEFAULT) -> TitleBlockLayout:
    """The cells of ``block``; its title is ``sheet_title`` where the block has none."""
    size, title_size = style.note_size, style.title_size
    say = {k: word(k, block.notation, WORDS) for k in WORDS}

    def need(text: str, at: float = size) -> float:
        return text_box_size(text, at)[0] + 2.0 * PAD if text else 0.0

    title = block.title or sheet_title
    bottom = (("name", block.name), ("group", block.group), ("date", block.date))
    top = (("scale", scale), ("sheet", block.sheet))
    label_w = max([MIN_LABEL] + [need(say[k]) for k in WORDS])
    top_value_w = max([MIN_VALUE] + [need(v) for _, v in top])
    values_w = [max(MIN_VALUE, need(v)) for _, v in bottom]
    width = max(MIN_WIDTH, 3 * label_w + sum(values_w), need(title, title_size) + label_w + top_value_w)
    extra = (width - 3 * label_w - sum(values_w)) / len(values_w)
    values_w = [w + extra for w in values_w]

    cells = [Cell((0.0, 0.0, width - label_w - top_value_w, 2.0 * ROW), title, title_size)]
    x = width - label_w - top_value_w
    for row, (key, value) in enumerate(top):
        y = row * ROW
        cells.append(Cell((x, y, x + label_w, y + ROW), say[key], size))
        cells.append(Cell((x + label_w, y, width, y + ROW), value, size))
    x = 0.0
    for (key, value), w in zip(bottom, values_w):
        cells.append(Cell((x, 2.0 * ROW, x + label_w, 3.0 * ROW), say[key], size))
        cells.append(Cell((x + label_w, 2.0 * ROW, x + label_w + w, 3.0 * ROW), value, size))
        x += label_w + w
    return TitleBlockLayout(width, 3.0 * ROW, tuple(cells))


def draw_title_block(lay: TitleBlockLayout, at: tuple[float, float], backend: Backend[object],
                     style: Style = DEFAULT) -> None:
    """Draw the block with its top-left corner at ``at`` (page mm, y down): each cell ruled
    thin, the whole framed with the outline's pen, the texts centred in their cells."""
    ax, ay = at
    for cell in lay.cells:
        x0, y0, x1, y1 = cell.box
        backend.polyline([(ax + x0, ay + y0), (ax + x1, ay + y0), (ax + x1, ay + y1), (ax + x0, ay + y1)],
                         "label", closed=True)
    outline = [(ax, ay), (ax + lay.width, ay), (ax + lay.width, ay + lay.height), (ax, ay + lay.height)]
    backend.polyline(outline, "given", closed=True)
    for cell in lay.cells:
        if cell.text:
            x0, y0, x1, y1 = cell.box
            middle = (ax + (x0 + x1) / 2.0, ay + (y0 + y1) / 2.0 + BASELINE_DROP * cell.size)
            backend.text(cell.text, middle, cell.size, "middle", False, "text")
