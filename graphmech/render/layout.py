"""Where each panel goes on the page — by translation only, never by scaling.

A panel is drawn at its own scale μ: its items are drawing millimetres and stay so on paper.
Layout therefore only *moves* panels. Each panel's *frame* is its drawing with its caption
under it (title, then notes such as "μv = 0.005 (m/s)/mm", then a graphic scale bar per scale
of ``Panel.scales``: :mod:`graphmech.render.scalebar`). Panels fill rows left to right in the
given order, ``Style.panel_gap`` apart at least (``Panel.row`` puts panels in one row, e.g. one
row per mechanism position); a row that would be wider than the page between its margins wraps.
The page's free room is then spread out, not left as a margin around a clump: the free height
evenly before, between and after the rows, each row's free width before, between and after its
panels; rows with as many panels each share columns. Panels of a row stand on a common line,
so their captions line up under them. What still does not fit keeps its μ and is reported in
:attr:`SheetLayout.warnings` (the caller reports them).

A sheet with a title block (:mod:`graphmech.render.titleblock`) has it at the page's lower
right, inside the margins: the rows stand as without it where they clear it, else the last row
stands beside it where every row then clears it, else the rows keep above it. A *fit* sheet (``[page] size = "fit"``) is laid out
first, its page then cropped to the content with a small margin (:data:`FIT_MARGIN`, panels
:data:`FIT_GAP` apart): of the ways to fill rows, the one whose page is smallest (not a strip),
its title wrapped to the drawing's width, in whole millimetres.

Coordinates: a panel's drawing box is in its own frame (y up); everything else is page
millimetres (origin top-left, y down). ``PanelPlacement.to_page`` is the only transform:
``(x, y) ↦ (x + dx, dy − y)``.

Examples
--------
>>> from graphmech.drawing.primitives import Panel, Segment, Sheet
>>> p = Panel("a", "Mechanism", (Segment((0.0, 0.0), (40.0, 0.0)),))
>>> lay = layout_sheet(Sheet("t", (p, p)))
>>> lay.warnings
()
>>> [round(pl.frame[0], 3) for pl in lay.panels]  # 42.7 mm boxes, the free width in thirds
[69.867, 184.433]
>>> fit = layout_sheet(Sheet("t", (p, p), fit=True))
>>> fit.page, [round(pl.frame[1], 3) for pl in fit.panels]  # cropped; one above the other
((53.0, 48.0), [17.267, 33.133])
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

from graphmech.drawing.lettering import text_box_size
from graphmech.render.labels import Box
from graphmech.drawing.primitives import (
    XY,
    ArcArrow,
    Arrow,
    Circle,
    FixedPivot,
    GuideLine,
    Hinge,
    Label,
    Panel,
    Plate,
    Polyline,
    Primitive,
    Segment,
    Sheet,
    Slider,
    Text,
)
from graphmech.render.pivots import oriented
from graphmech.render.scalebar import ScaleBar, scale_bar
from graphmech.render.style import DEFAULT, Style
from graphmech.render.titleblock import TitleBlockLayout, scale_text, title_block_layout


def _box_of(points: Sequence[XY], grow: float) -> Box:
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return (min(xs) - grow, min(ys) - grow, max(xs) + grow, max(ys) + grow)


def union(boxes: Sequence[Box]) -> Box:
    """The smallest box holding all ``boxes``.

    >>> union([(0, 0, 1, 1), (2, -1, 3, 0)])
    (0, -1, 3, 1)
    """
    if not boxes:
        raise ValueError("union of no boxes")
    return (
        min(b[0] for b in boxes),
        min(b[1] for b in boxes),
        max(b[2] for b in boxes),
        max(b[3] for b in boxes),
    )


def slider_corners(s: Slider) -> tuple[XY, XY, XY, XY]:
    """The slider block's corners, counter-clockwise, in the panel frame."""
    ux, uy = math.cos(s.angle), math.sin(s.angle)
    vx, vy = -uy, ux
    hl, hw = s.length / 2.0, s.width / 2.0
    cx, cy = s.center
    return (
        (cx - hl * ux - hw * vx, cy - hl * uy - hw * vy),
        (cx + hl * ux - hw * vx, cy + hl * uy - hw * vy),
        (cx + hl * ux + hw * vx, cy + hl * uy + hw * vy),
        (cx - hl * ux + hw * vx, cy - hl * uy + hw * vy),
    )


def label_margin_box(label: Label, style: Style = DEFAULT) -> Box:
    """A box sure to hold the label wherever it is placed around its anchor (first rings)."""
    w, h = text_box_size(label.text, label.size)
    r = max(style.label_gaps) + math.hypot(w, h)
    return _box_of([label.anchor], r)


def item_box(item: Primitive, style: Style = DEFAULT) -> Box:
    """Extent of one drawn item in its panel's frame, mm, stroke widths, hinge radii,
    arrowheads, pivot and guide hatching included (labels: :func:`label_margin_box`)."""
    if isinstance(item, Segment):
        return _box_of([item.p0, item.p1], style.pen(item.role).width / 2.0)
    if isinstance(item, Arrow):
        grow = max(style.arrow_half_width, style.pen(item.role).width / 2.0)
        return _box_of([item.p0, item.p1], grow)
    if isinstance(item, ArcArrow):
        return _box_of(list(item.points()), style.arrow_length)
    if isinstance(item, Polyline):
        return _box_of(list(item.points), style.pen(item.role).width / 2.0)
    if isinstance(item, Circle):
        return _box_of([item.center], item.r + style.pen(item.role).width / 2.0)
    if isinstance(item, Plate):
        return _box_of(list(item.points), style.plate.width / 2.0)
    if isinstance(item, Hinge):
        return _box_of([item.center], item.r + style.hinge.width / 2.0)
    if isinstance(item, FixedPivot):  # drawn below, then turned onto its base's side
        cx, cy = item.center
        top = style.hinge_r + style.hinge.width / 2.0
        depth = style.pivot_height + style.hatch_length / math.sqrt(2.0)
        half = max(style.pivot_ground_half, style.pivot_half_base)
        grow = max(style.frame.width, style.hatch.width) / 2.0
        bx, by = item.base or (0.0, -1.0)
        corners = [(cx + bx * a - by * b, cy + by * a + bx * b)
                   for a in (-top, depth + grow) for b in (-half - grow, half + grow)]
        return _box_of(corners, 0.0)
    if isinstance(item, Slider):
        return _box_of(list(slider_corners(item)), style.slider.width / 2.0)
    if isinstance(item, GuideLine):
        (x0, y0), (x1, y1) = item.p0, item.p1
        length = math.hypot(x1 - x0, y1 - y0)
        if length == 0.0:
            return _box_of([item.p0], style.frame.width / 2.0)
        nx, ny = (y1 - y0) / length, -(x1 - x0) / length
        d = style.hatch_length
        pts = [item.p0, item.p1, (x0 + d * nx, y0 + d * ny), (x1 + d * nx, y1 + d * ny)]
        return _box_of(pts, max(style.frame.width, style.hatch.width) / 2.0)
    if isinstance(item, Label):
        return label_margin_box(item, style)
    if isinstance(item, Text):  # set where it stands: its line's box, by its anchor
        w, h = text_box_size(item.text, item.size)
        x0 = item.at[0] - {"start": 0.0, "middle": w / 2.0, "end": w}[item.anchor]
        return (x0, item.at[1] - h / 2.0, x0 + w, item.at[1] + h / 2.0)
    raise TypeError(f"not a draw primitive: {item!r}")


def panel_bbox(
    panel: Panel, style: Style = DEFAULT, label_boxes: Sequence[Box] | None = None
) -> Box:
    """Bounding box of a panel's drawing in its own frame (y up), padded by
    ``Style.panel_padding``.

    ``label_boxes`` are the placed labels' text boxes; without them every label counts with
    the conservative :func:`label_margin_box`.

    Raises
    ------
    ValueError
        For a panel with nothing to draw.
    """
    panel = oriented(panel, style)
    boxes = [item_box(it, style) for it in panel.items if not isinstance(it, Label)]
    if label_boxes is None:
        boxes += [label_margin_box(it, style) for it in panel.items if isinstance(it, Label)]
    else:
        boxes += list(label_boxes)
    if not boxes:
        raise ValueError(f"panel {panel.name!r} has nothing to draw")
    pad = style.panel_padding
    x0, y0, x1, y1 = union(boxes)
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


@dataclass(frozen=True)
class CaptionLine:
    """One line of a panel's caption: text, font size (mm) and baseline position on the page."""

    text: str
    size: float
    at: XY


@dataclass(frozen=True)
class PanelPlacement:
    """Where one panel goes.

    Attributes
    ----------
    name : str
        The panel's name.
    drawing : Box
        Its drawing box in its own frame (y up), padding included.
    dx, dy : float
        The transform to page: ``(x, y) ↦ (x + dx, dy − y)`` — a translation and a flip.
    frame : Box
        The page box (y down) of drawing, caption and scale bars together.
    caption : tuple of CaptionLine
        Title and notes, centred under the drawing.
    scale_bars : tuple of (ScaleBar, (x, y))
        A graphic scale bar per scale of the panel, under the caption, each with its block's
        top-left corner on the page.
    """

    name: str
    drawing: Box
    dx: float
    dy: float
    frame: Box
    caption: tuple[CaptionLine, ...]
    scale_bars: tuple[tuple[ScaleBar, XY], ...] = ()

    def to_page(self, p: XY) -> XY:
        """A point of the panel (mm, y up) on the page (mm, y down)."""
        return (p[0] + self.dx, self.dy - p[1])

    @property
    def drawing_on_page(self) -> Box:
        """The drawing box on the page (xmin, ymin, xmax, ymax), y down."""
        x0, y0 = self.to_page((self.drawing[0], self.drawing[3]))
        x1, y1 = self.to_page((self.drawing[2], self.drawing[1]))
        return (x0, y0, x1, y1)


@dataclass(frozen=True)
class SheetLayout:
    """Placement of all panels, the sheet title's and footer lines' baselines, the page drawn on
    (the sheet's, or for a fit sheet its crop to the content) and the title block with its
    top-left corner on the page."""

    panels: tuple[PanelPlacement, ...]
    title_at: XY
    footer_at: tuple[XY, ...]
    warnings: tuple[str, ...]
    page: tuple[float, float]
    title_block: tuple[TitleBlockLayout, XY] | None = None
    #: The sheet title as drawn, a line each, the first at ``title_at`` (a fit page wraps a
    #: title wider than its drawing).
    title_lines: tuple[str, ...] = ()

    @property
    def title_block_box(self) -> Box | None:
        """The title block's box on the page, or None."""
        if self.title_block is None:
            return None
        block, (x, y) = self.title_block
        return (x, y, x + block.width, y + block.height)


def footer_room(n: int, margin: float, style: Style = DEFAULT) -> float:
    """The height ``n`` footer lines take from the panels above the bottom margin, mm: the
    footer stands in the margin, its last baseline FOOT_EDGE above the edge, so one line takes
    none.

    >>> footer_room(0, 10.0), footer_room(1, 10.0), round(footer_room(2, 10.0), 3)
    (0.0, 1.0, 5.9)
    """
    if n == 0:
        return 0.0
    return max(style.note_size * style.line_gap * (n - 1) + style.note_size + FOOT_EDGE + FOOT_GAP - margin, 0.0)


def _caption_lines(panel: Panel, style: Style, width: float = math.inf) -> list[tuple[str, float]]:
    """Title and notes; a note wider than ``width`` (the drawing's, at least NOTE_WIDTH) is
    broken at spaces, so one long remark does not widen its panel across the page."""
    lines = [(panel.title, style.panel_title_size)] if panel.title else []
    room = max(width, NOTE_WIDTH)
    return lines + [(part, style.note_size) for n in panel.notes for part in balanced_wrap(n, room, style.note_size)]


def balanced_wrap(text: str, width: float, size: float) -> tuple[str, ...]:
    """:func:`wrap` into as few lines, but as even as they go: no lone last word.

    >>> balanced_wrap("working stroke 210° in 7 s, return 150° in 5 s: a turn in 12 s, n = 5 r/min", 130.0, 3.5)
    ('working stroke 210° in 7 s, return 150°', 'in 5 s: a turn in 12 s, n = 5 r/min')
    """
    lines = wrap(text, width, size)
    if len(lines) < 2:
        return lines
    lo, hi = max(text_box_size(w, size)[0] for w in text.split(" ")), width
    for _ in range(30):  # the narrowest width that still gives as few lines (bisection)
        mid = (lo + hi) / 2.0
        if len(wrap(text, mid, size)) <= len(lines):
            hi = mid
        else:
            lo = mid
    return wrap(text, hi, size)


#: The footer's last baseline above the page's lower edge, and its least gap to the panels, mm.
FOOT_EDGE = 5.5
FOOT_GAP = 2.0
#: A caption note is wrapped to its drawing's width, but not narrower than this, mm.
NOTE_WIDTH = 130.0
#: The least gap between panels and rows when the page is tight, mm (instead of panel_gap):
#: a sheet that fits with narrower gaps is better than one that runs off the page.
TIGHT_GAP = 4.0


#: Free distance between a drawing and the first line of its caption, mm.
CAPTION_GAP = 2.0
#: Free distance above each scale bar (from the caption or the bar before it), mm.
BAR_GAP = 1.0
#: A fit page's margin and least gap between panels, mm: a figure for a report is cropped to
#: its content with a small margin.
FIT_MARGIN = 5.0
FIT_GAP = 6.0
#: A fit page's title is wrapped to the drawing's width, but not narrower than this, mm.
FIT_TITLE_WIDTH = 80.0
#: The longest side of a fit page over its shortest beyond which the rows are rearranged
#: (a strip of panels in one row, or a column, reads badly).
FIT_MAX_SHAPE = 2.0


#: Free distance between two scale bars standing side by side, mm.
BAR_SIDE_GAP = 6.0


def bar_rows(bars: Sequence[ScaleBar], width: float) -> list[list[ScaleBar]]:
    """The panel's scale bars in rows under its caption: side by side while a row stays within
    ``width`` (the panel's drawing or caption, whichever is wider), so a diagram with μs and μφ
    costs one bar's height, not two.

    >>> b = scale_bar("l", 0.001)
    >>> [len(r) for r in bar_rows([b, b, b], 2 * b.width + BAR_SIDE_GAP)]
    [2, 1]
    """
    return [[bars[i] for i in row] for row in fill_rows([b.width for b in bars], width, BAR_SIDE_GAP)]


def _row_width(row: Sequence[ScaleBar]) -> float:
    return sum(b.width for b in row) + BAR_SIDE_GAP * (len(row) - 1)


@dataclass(frozen=True)
class _Size:
    """A panel's drawing box (own frame), caption lines, scale bars and frame size (mm)."""

    draw: Box
    lines: tuple[tuple[str, float], ...]
    bars: tuple[ScaleBar, ...]
    w: float
    h: float


def _panel_size(panel: Panel, style: Style, label_boxes: Sequence[Box] | None) -> _Size:
    draw = panel_bbox(panel, style, label_boxes)
    lines = tuple(_caption_lines(panel, style, draw[2] - draw[0]))
    bars = tuple(scale_bar(sym, mu, style.note_size) for sym, mu in panel.scales)
    text_w = max([text_box_size(t, s)[0] for t, s in lines], default=0.0)
    rows = bar_rows(bars, max(draw[2] - draw[0], text_w))
    cap_h = sum(s * style.line_gap for _, s in lines)
    cap_h += sum(BAR_GAP + max(b.height for b in row) for row in rows)
    cap_h += CAPTION_GAP if lines or bars else 0.0
    cap_w = max([text_w] + [_row_width(row) for row in rows])
    return _Size(draw, lines, bars, max(draw[2] - draw[0], cap_w), draw[3] - draw[1] + cap_h)


def fill_rows(widths: Sequence[float], limit: float, gap: float,
              fixed: Sequence[int | None] | None = None) -> list[list[int]]:
    """Indices of things ``widths`` wide in rows ``gap`` apart, filled greedily left to right up
    to ``limit``; a thing with a ``fixed`` row key stands in the row of that key, in order (one
    row per mechanism position). Panels on a sheet and scale bars under a caption alike.

    >>> fill_rows([10, 10, 10, 5], 25, 2), fill_rows([10, 10, 10], 100, 2, [None, 0, 0])
    ([[0, 1], [2, 3]], [[0], [1, 2]])
    """
    keys = list(fixed) if fixed is not None else [None] * len(widths)
    explicit: dict[int, list[int]] = {}
    for i, key in enumerate(keys):
        if key is not None:
            explicit.setdefault(key, []).append(i)
    rows: list[list[int]] = []
    used = 0.0
    free_row = False  # the last row is one greedy filling may go on
    for i, w in enumerate(widths):
        key = keys[i]
        if key is not None:
            if i == explicit[key][0]:
                rows.append(explicit[key])
                free_row = False
            continue
        if rows and free_row and used + gap + w <= limit + 1e-9:
            rows[-1].append(i)
            used += gap + w
        else:
            rows.append([i])
            used, free_row = w, True
    return rows


def _rows(panels: Sequence[Panel], sizes: Sequence[_Size], limit: float, gap: float) -> list[list[int]]:
    """Rows as the panels ask (``Panel.row``), the others filled greedily up to ``limit`` mm."""
    return fill_rows([s.w for s in sizes], limit, gap, [p.row for p in panels])


def _stacks(panels: Sequence[Panel], sizes: Sequence[_Size], gap: float) -> list[list[int]]:
    """Consecutive panels stacked one above the other (a fit page's cells): a panel goes under the
    one before while the stack stays no taller than the sheet's tallest panel and its widths
    within a factor of two — so short panels fill the height a tall one gives their row."""
    tallest = max((s.h for s in sizes), default=0.0)
    cells: list[list[int]] = []
    for i, size in enumerate(sizes):
        if cells and panels[i].row is None and panels[cells[-1][0]].row is None:
            cell = cells[-1]
            height = sum(sizes[j].h + gap for j in cell) + size.h
            widths = [sizes[j].w for j in cell] + [size.w]
            if height <= tallest + 1e-9 and min(widths) >= 0.5 * max(widths):
                cell.append(i)
                continue
        cells.append([i])
    return cells


def _cell_sizes(cells: Sequence[Sequence[int]], sizes: Sequence[_Size], gap: float) -> list[_Size]:
    """A cell's size: its one panel's, or a stack's (the widest, the heights and gaps summed)."""
    return [sizes[c[0]] if len(c) == 1 else
            _Size(sizes[c[0]].draw, (), (), max(sizes[j].w for j in c), sum(sizes[j].h for j in c) + gap * (len(c) - 1))
            for c in cells]


def _row_sizes(rows: Sequence[Sequence[int]], sizes: Sequence[_Size], gap: float) -> tuple[list[float], list[float]]:
    widths = [sum(sizes[i].w for i in r) + gap * (len(r) - 1) for r in rows]
    return widths, [max(sizes[i].h for i in r) for r in rows]


def _arrange(rows: Sequence[Sequence[int]], sizes: Sequence[_Size], room: Box, gap: float,
             last_right: float | None = None) -> dict[int, XY]:
    """Each panel's frame's top-left corner: the free height spread evenly before, between and
    after the rows, each row's free width before, between and after its panels; panels of a
    row stand on one line. Rows with as many panels each share columns (the widest of each).
    ``last_right`` narrows the last row's room (beside a title block)."""
    left, top, right, bottom = room
    _, row_h = _row_sizes(rows, sizes, gap)
    total_h = sum(row_h) + gap * (len(rows) - 1) if rows else 0.0
    free_h = bottom - top - total_h
    slot_h = free_h / (len(rows) + 1) if free_h > 0.0 else 0.0
    rights = [right] * len(rows)
    if rows and last_right is not None:
        rights[-1] = last_right
    columns: list[float] | None = None
    k = len(rows[0]) if rows else 0
    if len(rows) > 1 and k > 1 and all(len(r) == k for r in rows):
        columns = [max(sizes[r[j]].w for r in rows) for j in range(k)]
        if any(sum(columns) + gap * (k - 1) > r - left + 1e-9 for r in rights):
            columns = None
    at: dict[int, XY] = {}
    y = top + slot_h
    for r, rh, r_right in zip(rows, row_h, rights):
        cells = columns or [sizes[i].w for i in r]
        free = r_right - left - sum(cells) - gap * (len(r) - 1)
        slot = free / (len(r) + 1) if free > 0.0 else 0.0
        x = left + (slot if free > 0.0 else free / 2.0)  # a row too wide runs off both sides alike
        for i, cell in zip(r, cells):
            at[i] = (x + (cell - sizes[i].w) / 2.0, y + rh - sizes[i].h)
            x += cell + gap + slot
        y += rh + gap + slot_h
    return at


def _overlaps(a: Box, b: Box) -> bool:
    return min(a[2], b[2]) > max(a[0], b[0]) and min(a[3], b[3]) > max(a[1], b[1])


def wrap(text: str, width: float, size: float) -> tuple[str, ...]:
    """``text`` broken at spaces into lines at most ``width`` mm wide at font ``size`` (a word
    wider than that stands alone on its line).

    >>> wrap("Crank-rocker through a whole turn", 40.0, 5.0)
    ('Crank-rocker', 'through a', 'whole turn')
    """
    lines: list[str] = []
    for word in text.split(" "):
        if lines and text_box_size(lines[-1] + " " + word, size)[0] <= width + 1e-9:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return tuple(lines)


def _head(lines: Sequence[str], style: Style) -> float:
    """The height the sheet title's lines take above the panels, mm."""
    return style.title_size * (1.0 + len(lines) * style.line_gap) if lines else 0.0


def _fit(sheet: Sheet, sizes: Sequence[_Size], block: TitleBlockLayout | None, style: Style,
         foot: float) -> tuple[list[list[int]], tuple[float, float], tuple[str, ...], list[list[int]]]:
    """The rows, the page and the title's lines of a fit sheet: of the ways to fill rows (every
    width limit a run of panels gives), the one whose cropped page is smallest — the most filled
    — unless it is longer than FIT_MAX_SHAPE times its width or height (the first of equals);
    the title wrapped to the drawing's width; the page holds title, rows, footer and title block
    with FIT_MARGIN, rounded up to whole millimetres. The rows are of cells: panels one by one,
    or stacked (:func:`_stacks`), whichever fills the page better. Returns the rows (of cell
    indices), the page, the title's lines and the cells."""
    m, gap = FIT_MARGIN, FIT_GAP
    fixed = max([text_box_size(f, style.note_size)[0] + (gap + block.width if block else 0.0)
                 for f in sheet.footer] + [block.width if block else 0.0, 1.0])
    band = max(foot, block.height + gap if block else 0.0)
    best: tuple[float, list[list[int]], tuple[float, float], tuple[str, ...], list[list[int]]] | None = None
    singles = [[i] for i in range(len(sizes))]
    for cells in (singles, _stacks(sheet.panels, sizes, gap)):
        csizes = _cell_sizes(cells, sizes, gap)
        heads = [sheet.panels[c[0]] for c in cells]
        n = len(csizes)
        limits = sorted({sum(s.w for s in csizes[i:j + 1]) + gap * (j - i) for i in range(n) for j in range(i, n)})
        for limit in limits or [0.0]:
            rows = _rows(heads, csizes, limit, gap)
            row_w, row_h = _row_sizes(rows, csizes, gap)
            inner = max([fixed] + row_w)
            title = balanced_wrap(sheet.title, max(inner, FIT_TITLE_WIDTH), style.title_size) if sheet.title else ()
            inner = max([inner] + [text_box_size(t, style.title_size)[0] for t in title])
            w = inner + 2.0 * m
            h = _head(title, style) + sum(row_h) + gap * max(len(rows) - 1, 0) + band + 2.0 * m
            stretch = max(w / h, h / w) / FIT_MAX_SHAPE
            score = w * h * max(stretch, 1.0) ** 2
            if best is None or score < best[0] - 1e-9:
                best = (score, rows, (w, h), title, cells)
    assert best is not None
    _, rows, (w, h), title, cells = best
    return rows, (float(math.ceil(w - 1e-9)), float(math.ceil(h - 1e-9))), title, cells  # whole millimetres


def layout_sheet(
    sheet: Sheet,
    style: Style = DEFAULT,
    label_boxes: Sequence[Sequence[Box]] | None = None,
) -> SheetLayout:
    """Lay the sheet's panels out on its page (see the module's docstring).

    Parameters
    ----------
    sheet : Sheet
        Title, panels in order, page size (mm), footer; whether the page is cropped to the
        content (``fit``) and its title block.
    style : Style
        Gaps, margins, font sizes.
    label_boxes : sequence of sequences of Box, optional
        Per panel, the placed labels' boxes in the panel's frame (see :func:`panel_bbox`).

    Returns
    -------
    SheetLayout
        Deterministic; ``warnings`` says what does not fit the page (μ is never changed).
    """
    if label_boxes is not None and len(label_boxes) != len(sheet.panels):
        raise ValueError("label_boxes must give one sequence of boxes per panel")
    sizes = [_panel_size(p, style, None if label_boxes is None else label_boxes[i])
             for i, p in enumerate(sheet.panels)]
    block = None if sheet.title_block is None else \
        title_block_layout(sheet.title_block, sheet.title, scale_text(sheet.panels), style)
    m, gap = (FIT_MARGIN, FIT_GAP) if sheet.fit else (style.page_margin, style.panel_gap)
    step = style.note_size * style.line_gap
    n_foot = len(sheet.footer)
    foot = footer_room(n_foot, m, style)
    cells = [[i] for i in range(len(sizes))]
    if sheet.fit:
        rows, page, title, cells = _fit(sheet, sizes, block, style, foot)
    else:
        page = sheet.page
        title = (sheet.title,) if sheet.title else ()
        height = page[1] - 2.0 * m - _head(title, style) - foot
        for gap in (style.panel_gap, min(style.panel_gap, TIGHT_GAP)):  # the wide gap if it fits
            rows = _rows(sheet.panels, sizes, page[0] - 2.0 * m, gap)
            row_w, row_h = _row_sizes(rows, sizes, gap)
            if max(row_w, default=0.0) <= page[0] - 2.0 * m + 1e-9 and \
                    sum(row_h) + gap * (len(rows) - 1) <= height + 1e-9:
                break
    panel_sizes, sizes = sizes, _cell_sizes(cells, sizes, gap)  # the rows hold cells from here
    head = _head(title, style)
    page_w, page_h = page
    title_at = (page_w / 2.0, m + style.title_size)
    footer_at = tuple((m, page_h - FOOT_EDGE - step * (n_foot - 1 - k)) for k in range(n_foot))
    room = (m, m + head, page_w - m, page_h - m - foot)
    warnings: list[str] = []

    block_at: XY | None = None
    at: dict[int, XY] | None = None
    if block is not None:
        block_at = (page_w - m - block.width, page_h - m - block.height)
        block_box = (block_at[0] - gap, block_at[1] - gap, page_w, page_h)
        if block.width > page_w - 2.0 * m + 1e-9:
            warnings.append(f"the title block is {block.width:.1f} mm wide but the page leaves "
                            f"{page_w - 2.0 * m:.1f} mm between its margins")
        if not sheet.fit:  # the rows as without it, or the last row beside it, if every row clears it
            last_right = block_at[0] - gap
            narrow = not rows or _row_sizes(rows[-1:], sizes, gap)[0][0] <= last_right - m + 1e-9
            for right in [None] + ([last_right] if narrow else []):
                tried = _arrange(rows, sizes, room, gap, right)
                if not any(_overlaps(_frame(tried[i], sizes[i]), block_box) for i in tried):
                    at = tried
                    break
        if at is None:  # else a band of the page's width above it
            room = (room[0], room[1], room[2], min(room[3], block_at[1] - gap))
    if at is None:
        at = _arrange(rows, sizes, room, gap)

    avail_w, avail_h = room[2] - room[0], room[3] - room[1]
    for i, (panel, size) in enumerate(zip(sheet.panels, panel_sizes)):
        if size.w > avail_w + 1e-9:
            warnings.append(
                f"panel {panel.name!r} is {_mm(size.w)} mm wide but the page leaves {avail_w:.1f} mm "
                "between its margins; its scale μ is kept, so it runs off the page"
            )
    row_w, row_h = _row_sizes(rows, sizes, gap)
    for r, w in zip(rows, row_w):
        if len(r) > 1 and w > avail_w + 1e-9:
            warnings.append(f"a row of {len(r)} panels is {_mm(w)} mm wide but the page leaves "
                            f"{avail_w:.1f} mm; their scales μ are kept, so it runs off the page")
    total_h = sum(row_h) + gap * (len(rows) - 1) if rows else 0.0
    if total_h > avail_h + 1e-9:
        warnings.append(
            f"the panels need {_mm(total_h)} mm of height in {len(rows)} row(s) but the page "
            f"leaves {avail_h:.1f} mm; their scales μ are kept, so they run off the page"
        )

    corners: dict[int, XY] = {}
    for k, cell in enumerate(cells):  # a stack's panels top-down in its cell, each centred
        x, y = at[k]
        for i in cell:
            corners[i] = (x + (sizes[k].w - panel_sizes[i].w) / 2.0, y)
            y += panel_sizes[i].h + gap
    placements = tuple(_placement(sheet.panels[i], panel_sizes[i], corners[i], style)
                       for i in range(len(panel_sizes)))
    return SheetLayout(placements, title_at, footer_at, tuple(warnings), (page_w, page_h),
                       None if block is None or block_at is None else (block, block_at), title)


def _mm(x: float) -> str:
    """A size on paper in a warning: 0.1 mm, or three figures for an absurd one (1e300 mm).

    >>> _mm(436.66), _mm(2.4e300)
    ('436.7', '2.4e+300')
    """
    return f"{x:.1f}" if x < 1e7 else f"{x:.3g}"


def _frame(corner: XY, size: _Size) -> Box:
    return (corner[0], corner[1], corner[0] + size.w, corner[1] + size.h)


def _placement(panel: Panel, size: _Size, corner: XY, style: Style) -> PanelPlacement:
    """The panel's transform, caption lines and scale bars, its frame's top-left at ``corner``."""
    x, ftop = corner
    draw = size.draw
    dw, dh = draw[2] - draw[0], draw[3] - draw[1]
    dx = x + (size.w - dw) / 2.0 - draw[0]
    dy = ftop + draw[3]
    cx = x + size.w / 2.0
    cursor = ftop + dh + CAPTION_GAP
    base = cursor
    caption: list[CaptionLine] = []
    for text, s in size.lines:
        base += s * (style.line_gap - 1.0) if caption else 0.0
        base += s
        caption.append(CaptionLine(text, s, (cx, base)))
        cursor += s * style.line_gap
    bars: list[tuple[ScaleBar, XY]] = []
    text_w = max([text_box_size(t, s)[0] for t, s in size.lines], default=0.0)
    for row in bar_rows(size.bars, max(dw, text_w)):
        cursor += BAR_GAP
        left = cx - _row_width(row) / 2.0
        for bar in row:
            bars.append((bar, (left, cursor)))
            left += bar.width + BAR_SIDE_GAP
        cursor += max(b.height for b in row)
    return PanelPlacement(panel.name, draw, dx, dy, _frame(corner, size), tuple(caption), tuple(bars))
