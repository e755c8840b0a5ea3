"""Where each panel goes on the page — by translation only, never by scaling.

A panel is drawn at its own scale μ: its items are drawing millimetres and stay so on paper.
Layout therefore only *moves* panels: left to right in the given order, ``Style.panel_gap``
apart, each row centred on the page, panels of a row standing on a common line so their
captions (title, then notes such as "μv = 0.005 (m/s)/mm") line up under them. A row that
would be wider than the page between its margins wraps; what still does not fit keeps its μ
and is reported in :attr:`SheetLayout.warnings` (the caller reports them).

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
>>> [round(pl.frame[0], 3) for pl in lay.panels]  # 42.7 mm boxes (stroke, padding), 12 mm apart
[99.8, 154.5]
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
from graphmech.render.style import DEFAULT, Style


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
    if isinstance(item, FixedPivot):
        cx, cy = item.center
        top = cy + style.hinge_r + style.hinge.width / 2.0
        bottom = cy - style.pivot_height - style.hatch_length / math.sqrt(2.0)
        half = max(style.pivot_ground_half, style.pivot_half_base)
        grow = max(style.frame.width, style.hatch.width) / 2.0
        return (cx - half - grow, bottom - grow, cx + half + grow, top)
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
        The page box (y down) of drawing and caption together.
    caption : tuple of CaptionLine
        Title and notes, centred under the drawing.
    """

    name: str
    drawing: Box
    dx: float
    dy: float
    frame: Box
    caption: tuple[CaptionLine, ...]

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
    """Placement of all panels plus the sheet title's and footer lines' baselines."""

    panels: tuple[PanelPlacement, ...]
    title_at: XY
    footer_at: tuple[XY, ...]
    warnings: tuple[str, ...]


def _caption_lines(panel: Panel, style: Style) -> list[tuple[str, float]]:
    lines = [(panel.title, style.panel_title_size)] if panel.title else []
    return lines + [(n, style.note_size) for n in panel.notes]


#: Free distance between a drawing and the first line of its caption, mm.
CAPTION_GAP = 2.0


def layout_sheet(
    sheet: Sheet,
    style: Style = DEFAULT,
    label_boxes: Sequence[Sequence[Box]] | None = None,
) -> SheetLayout:
    """Lay the sheet's panels out on its page (see the module's docstring).

    Parameters
    ----------
    sheet : Sheet
        Title, panels in order, page size (mm) and footer.
    style : Style
        Gaps, margins, font sizes.
    label_boxes : sequence of sequences of Box, optional
        Per panel, the placed labels' boxes in the panel's frame (see :func:`panel_bbox`).

    Returns
    -------
    SheetLayout
        Deterministic; ``warnings`` says what does not fit the page (μ is never changed).
    """
    page_w, page_h = sheet.page
    m = style.page_margin
    if label_boxes is not None and len(label_boxes) != len(sheet.panels):
        raise ValueError("label_boxes must give one sequence of boxes per panel")

    title_at = (page_w / 2.0, m + style.title_size)
    top = m + (style.title_size * (1.0 + style.line_gap) if sheet.title else 0.0)
    step = style.note_size * style.line_gap
    n_foot = len(sheet.footer)
    footer_at = tuple((m, page_h - m - step * (n_foot - 1 - k)) for k in range(n_foot))
    bottom = page_h - m - (step * n_foot + style.note_size if n_foot else 0.0)
    avail_w = page_w - 2.0 * m
    avail_h = bottom - top
    warnings: list[str] = []

    # sizes of each panel: drawing box, caption height and width, frame size
    sizes = []
    for i, panel in enumerate(sheet.panels):
        draw = panel_bbox(panel, style, None if label_boxes is None else label_boxes[i])
        lines = _caption_lines(panel, style)
        cap_h = (CAPTION_GAP + sum(s * style.line_gap for _, s in lines)) if lines else 0.0
        cap_w = max((text_box_size(t, s)[0] for t, s in lines), default=0.0)
        dw, dh = draw[2] - draw[0], draw[3] - draw[1]
        fw, fh = max(dw, cap_w), dh + cap_h
        sizes.append((draw, lines, fw, fh))
        if fw > avail_w + 1e-9:
            warnings.append(
                f"panel {panel.name!r} is {fw:.1f} mm wide but the page leaves {avail_w:.1f} mm "
                "between its margins; its scale μ is kept, so it runs off the page"
            )

    # rows as the panels ask (e.g. one row per mechanism position), else greedy, left to right
    rows: list[list[int]] = []
    width = 0.0
    explicit: dict[int, list[int]] = {}
    for i, panel in enumerate(sheet.panels):
        if panel.row is not None:
            explicit.setdefault(panel.row, []).append(i)
    for i, (_, _, fw, _) in enumerate(sizes):
        row = sheet.panels[i].row
        if row is not None:
            if i == explicit[row][0]:
                rows.append(explicit[row])
            continue
        if rows and width + style.panel_gap + fw <= avail_w + 1e-9:
            rows[-1].append(i)
            width += style.panel_gap + fw
        else:
            rows.append([i])
            width = fw
    row_w = [sum(sizes[i][2] for i in r) + style.panel_gap * (len(r) - 1) for r in rows]
    for r, w in zip(rows, row_w):
        if len(r) > 1 and w > avail_w + 1e-9:
            warnings.append(f"a row of {len(r)} panels is {w:.1f} mm wide but the page leaves "
                            f"{avail_w:.1f} mm; their scales μ are kept, so it runs off the page")
    row_h = [max(sizes[i][3] for i in r) for r in rows]
    total_h = sum(row_h) + style.panel_gap * (len(rows) - 1) if rows else 0.0
    if total_h > avail_h + 1e-9:
        warnings.append(
            f"the panels need {total_h:.1f} mm of height in {len(rows)} row(s) but the page "
            f"leaves {avail_h:.1f} mm; their scales μ are kept, so they run off the page"
        )
        y = top
    else:
        y = top + (avail_h - total_h) / 2.0

    placements: list[PanelPlacement | None] = [None] * len(sizes)
    for r, rw, rh in zip(rows, row_w, row_h):
        x = (page_w - rw) / 2.0
        for i in r:
            draw, lines, fw, fh = sizes[i]
            dw, dh = draw[2] - draw[0], draw[3] - draw[1]
            ftop = y + rh - fh
            left = x + (fw - dw) / 2.0
            dx = left - draw[0]
            dy = ftop + draw[3]
            cx = x + fw / 2.0
            base = ftop + dh + CAPTION_GAP
            caption: list[CaptionLine] = []
            for text, size in lines:
                base += size * (style.line_gap - 1.0) if caption else 0.0
                base += size
                caption.append(CaptionLine(text, size, (cx, base)))
            placements[i] = PanelPlacement(
                sheet.panels[i].name, draw, dx, dy, (x, ftop, x + fw, ftop + fh), tuple(caption)
            )
            x += fw + style.panel_gap
        y += rh + style.panel_gap
    return SheetLayout(
        tuple(p for p in placements if p is not None), title_at, footer_at, tuple(warnings)
    )
