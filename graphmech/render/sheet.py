"""The frontend: a :class:`~graphmech.drawing.primitives.Sheet` → calls on a backend.

What the frontend decides, so that every backend draws the same figure:

* **Placement** (:mod:`graphmech.render.layout`): each panel is translated and flipped onto the
  page, never scaled — the drawing's μ stays true on paper.
* **Symbols**, expanded into lines, polygons and circles, all of paper size:
  an arrow is its shaft plus a small filled triangle (never an SVG marker) whose tip is the
  vector's end; a frame pivot is a hinge on a triangle standing on a ground line with short 45°
  hatch strokes; a guide is a line with hatching on its right side; a slider is a white
  rotated rectangle; a hinge is a small white-filled circle; a polyline is one open or closed
  stroke, never filled — a dashed one is cut into its dashes here (the backend's polyline has no
  dash pattern), each dash a short polyline following the curve, with the pen's pattern.
* **Order** (back to front): ground and guides with their hatching, slider blocks,
  construction lines, given lines, result lines, hinges (so they cover the line ends), labels.
  Items of the same layer keep the panel's order.
* **Labels** (:mod:`graphmech.render.labels`), placed around their anchors clear of each other
  and of everything the panel draws (:func:`_obstacles`), coincident point names merged; drawn
  last, each in a group of its own with its leader (a thin line from near the anchor to a label
  that had to move away), so the leader is the label's own stroke.
* **Lettering**: sheet title at the top, each panel's title and notes centred under it, then a
  graphic scale bar per scale of the panel (:mod:`graphmech.render.scalebar`), all in a caption
  group of their own; footer lines at the bottom left, the title block at the bottom right
  (:mod:`graphmech.render.titleblock`).

Examples
--------
>>> from graphmech.drawing.primitives import Arrow, Panel, Sheet
>>> from graphmech.render.recording import RecordingBackend
>>> sheet = Sheet("", (Panel("v", "", (Arrow((0.0, 0.0), (20.0, 0.0)),)),))
>>> calls = draw_sheet(sheet, RecordingBackend())
>>> [c[0] for c in calls if c[0] in ("line", "polyline")]
['line', 'polyline']
"""
from __future__ import annotations

import functools
import math
import re
import warnings
from dataclasses import dataclass
from typing import Callable, Sequence, TypeVar, Union

import numpy as np

from graphmech.drawing.lettering import BASELINE_DROP
from graphmech.render.backend import Backend
from graphmech.render.pivots import oriented
from graphmech.render.labels import Obstacles, PlacedLabel, place_labels
from graphmech.render.layout import PanelPlacement, layout_sheet, slider_corners
from graphmech.render.scalebar import draw_scale_bar
from graphmech.render.titleblock import draw_title_block
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

R = TypeVar("R")

#: Draw layers, back to front.
LAYER_GROUND, LAYER_SLIDER, LAYER_CONSTRUCTION, LAYER_GIVEN, LAYER_RESULT, LAYER_HINGE = range(6)
_ROLE_LAYER = {
    "construction": LAYER_CONSTRUCTION,
    "given": LAYER_GIVEN,
    "label": LAYER_GIVEN,
    "result": LAYER_RESULT,
}




class LayoutWarning(UserWarning):
    """A sheet does not fit its page at the panels' scales (μ is kept, never changed)."""


# ----------------------------------------------------------------------------- shapes
@dataclass(frozen=True)
class LineShape:
    p0: XY
    p1: XY
    key: str
    dashed: bool = False


@dataclass(frozen=True)
class PolyShape:
    points: tuple[XY, ...]
    key: str
    closed: bool = False
    filled: bool = False
    #: Text written on the shape and drawn with it, in one group (a plate's number): text,
    #: where (panel frame, the text's centre), size mm.
    text: tuple[str, XY, float] | None = None


@dataclass(frozen=True)
class CircleShape:
    c: XY
    r: float
    key: str
    filled: bool = False


Shape = Union[LineShape, PolyShape, CircleShape]


def hatch(p0: XY, p1: XY, style: Style = DEFAULT) -> list[LineShape]:
    """Ground hatching on the right of the line p0→p1 (panel frame, y up): strokes of
    ``hatch_length`` at 45° to the line, leaning back towards p0, every ``hatch_spacing``.

    >>> [tuple(round(v, 3) for v in s.p1) for s in hatch((0.0, 0.0), (4.0, 0.0))][:2]
    [(0.0, -1.273), (1.4, -1.273)]
    """
    (x0, y0), (x1, y1) = p0, p1
    length = math.hypot(x1 - x0, y1 - y0)
    if length == 0.0:
        return []
    tx, ty = (x1 - x0) / length, (y1 - y0) / length
    nx, ny = ty, -tx  # right-hand side seen p0 → p1
    k = style.hatch_length / math.sqrt(2.0)
    sx, sy = k * (nx - tx), k * (ny - ty)
    out = []
    s = k
    while s <= length + 1e-9:
        a = (x0 + s * tx, y0 + s * ty)
        out.append(LineShape(a, (a[0] + sx, a[1] + sy), "hatch"))
        s += style.hatch_spacing
    return out


def arrow_shapes(a: Arrow, style: Style = DEFAULT) -> list[Shape]:
    """Shaft (from the tail to the middle of the head's base) and the filled head.

    The head is ``arrow_length`` long and ``2·arrow_half_width`` wide, its tip at ``a.p1``;
    an arrow shorter than its head gets a head shrunk to its length (and no shaft).

    Raises
    ------
    ValueError
        For a zero-length arrow (it has no direction).
    """
    (x0, y0), (x1, y1) = a.p0, a.p1
    length = math.hypot(x1 - x0, y1 - y0)
    if not length > 0.0:
        raise ValueError(f"an arrow needs two distinct points, got {a.p0!r} → {a.p1!r}")
    ux, uy = (x1 - x0) / length, (y1 - y0) / length
    head = min(style.arrow_length, length)
    hw = style.arrow_half_width * head / style.arrow_length
    bx, by = x1 - head * ux, y1 - head * uy
    shapes: list[Shape] = []
    if length > head:
        shapes.append(LineShape(a.p0, (bx, by), a.role))
    tri = ((x1, y1), (bx - hw * uy, by + hw * ux), (bx + hw * uy, by - hw * ux))
    shapes.append(PolyShape(tri, a.role, closed=True, filled=True))
    return shapes


#: A dashed line needing more dashes than this (a line metres long on paper, at a stated μl) is
#: drawn solid: cutting it would take minutes and megabytes.
MOST_DASHES = 20000


def dash_pieces(points: Sequence[XY], closed: bool, pattern: Sequence[float]) -> list[tuple[XY, ...]]:
    """The dashes of a dashed polyline: pieces of the path (corners kept) laid along its length
    by ``pattern`` (on, off, on, off … mm, repeated), starting with a dash at the first point.

    >>> [tuple(p[0] for p in d) for d in dash_pieces([(0.0, 0.0), (10.0, 0.0)], False, (3.0, 1.0))]
    [(0.0, 3.0), (4.0, 7.0), (8.0, 10.0)]
    """
    pts = list(points) + ([points[0]] if closed and len(points) > 1 else [])
    pattern = [float(v) for v in pattern if v > 0.0] or [1.0]
    if len(pattern) % 2:
        pattern = pattern * 2
    total = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts[:-1], pts[1:]))
    if not math.isfinite(total) or total > MOST_DASHES * sum(pattern) / len(pattern):
        return [tuple(pts)] if len(pts) > 1 else []  # kilometres of paper: one solid line, not 1e300 dashes
    out: list[tuple[XY, ...]] = []
    k, left, on = 0, pattern[0], True  # current pattern entry, length left of it, drawing?
    piece: list[XY] = [pts[0]] if pts else []
    for a, b in zip(pts[:-1], pts[1:]):
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        t = 0.0
        while length - t > left:
            t += left
            f = t / length
            p = (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))
            if on:
                piece.append(p)
                out.append(tuple(piece))
                piece = []
            else:
                piece = [p]
            on = not on
            k = (k + 1) % len(pattern)
            left = pattern[k]
        left -= length - t
        if on:
            piece.append(b)
    if on and len(piece) > 1:
        out.append(tuple(piece))
    return [d for d in out if any(q != d[0] for q in d[1:])]


def pivot_shapes(p: FixedPivot, style: Style = DEFAULT) -> list[tuple[int, Shape]]:
    """A frame pivot: legs and ground line, hatching beyond it, and the hinge on top — drawn
    standing on ``p.base`` (below when None), the whole symbol turned about the hinge."""
    cx, cy = p.center
    bx, by = p.base or (0.0, -1.0)
    cos, sin = -by, bx  # the turn taking "below" (0, −1) to the base's direction

    def turn(q: XY) -> XY:
        x, y = q[0] - cx, q[1] - cy
        return (cx + x * cos - y * sin, cy + x * sin + y * cos)

    gy = cy - style.pivot_height
    left, right = (cx - style.pivot_ground_half, gy), (cx + style.pivot_ground_half, gy)
    legs = [LineShape(p.center, turn((cx - style.pivot_half_base, gy)), "frame"),
            LineShape(p.center, turn((cx + style.pivot_half_base, gy)), "frame"),
            LineShape(turn(left), turn(right), "frame")]
    out: list[tuple[int, Shape]] = [(LAYER_GROUND, s) for s in legs]
    out += [(LAYER_GROUND, s) for s in hatch(turn(left), turn(right), style)]
    out.append((LAYER_HINGE, CircleShape(p.center, style.hinge_r, "hinge", filled=True)))
    return out


def item_shapes(item: Primitive, style: Style = DEFAULT) -> list[tuple[int, Shape]]:
    """One primitive as (layer, shape) pairs in its panel's frame; labels give none."""
    if isinstance(item, Segment):
        if item.dashdot:
            pieces = dash_pieces((item.p0, item.p1), False, style.dashdot)
            return [(_ROLE_LAYER[item.role], PolyShape(d, item.role)) for d in pieces]
        return [(_ROLE_LAYER[item.role], LineShape(item.p0, item.p1, item.role, item.dashed))]
    if isinstance(item, Arrow):
        return [(_ROLE_LAYER[item.role], s) for s in arrow_shapes(item, style)]
    if isinstance(item, ArcArrow):
        pts = item.points()
        # the head's tip at the arc's end, pointing along its tangent
        th = item.start + item.sweep
        sgn = 1.0 if item.sweep >= 0 else -1.0
        tx, ty = -math.sin(th) * sgn, math.cos(th) * sgn
        tip = pts[-1]
        base = (tip[0] - style.arrow_length * tx, tip[1] - style.arrow_length * ty)
        hw = style.arrow_half_width
        head = PolyShape((tip, (base[0] - hw * ty, base[1] + hw * tx), (base[0] + hw * ty, base[1] - hw * tx)),
                         item.role, closed=True, filled=True)
        return [(_ROLE_LAYER[item.role], PolyShape(pts, item.role, closed=False, filled=False)),
                (_ROLE_LAYER[item.role], head)]
    if isinstance(item, Polyline):
        layer = _ROLE_LAYER[item.role]
        if not (item.dashed or item.dashdot):
            return [(layer, PolyShape(item.points, item.role, closed=item.closed, filled=False))]
        pattern = style.dashdot if item.dashdot else style.pen(item.role).dash
        pieces = dash_pieces(item.points, item.closed, pattern)
        return [(layer, PolyShape(d, item.role, closed=False, filled=False)) for d in pieces]
    if isinstance(item, Circle):
        if item.dashed or item.dashdot:  # a 1° polygon cut into the pattern
            ring = tuple((item.center[0] + item.r * math.cos(math.radians(k)),
                          item.center[1] + item.r * math.sin(math.radians(k))) for k in range(360))
            pattern = style.dashdot if item.dashdot else style.pen(item.role).dash
            return [(_ROLE_LAYER[item.role], PolyShape(d, item.role))
                    for d in dash_pieces(ring, True, pattern)]
        return [(_ROLE_LAYER[item.role], CircleShape(item.center, item.r, item.role))]
    if isinstance(item, Plate):
        at = item.number_at or (sum(p[0] for p in item.points) / len(item.points),
                                sum(p[1] for p in item.points) / len(item.points))
        text = (item.number, at, item.number_size) if item.number else None
        return [(LAYER_SLIDER, PolyShape(item.points, "plate", closed=True, filled=True, text=text))]
    if isinstance(item, Hinge):
        return [(LAYER_HINGE, CircleShape(item.center, item.r, "hinge", filled=True))]
    if isinstance(item, FixedPivot):
        return pivot_shapes(item, style)
    if isinstance(item, Slider):
        block = PolyShape(slider_corners(item), "slider", closed=True, filled=True)
        return [(LAYER_SLIDER, block)]
    if isinstance(item, GuideLine):
        out: list[tuple[int, Shape]] = [(LAYER_GROUND, LineShape(item.p0, item.p1, "frame"))]
        return out + [(LAYER_GROUND, s) for s in hatch(item.p0, item.p1, style)]
    if isinstance(item, (Label, Text)):
        return []
    raise TypeError(f"not a draw primitive: {item!r}")


def panel_shapes(panel: Panel, style: Style = DEFAULT) -> list[Shape]:
    """All shapes of a panel in drawing order (layer, then the panel's order); its frame pivots
    stand where :func:`graphmech.render.pivots.oriented` puts their bases."""
    panel = oriented(panel, style)
    tagged = []
    for i, item in enumerate(panel.items):
        for j, (layer, shape) in enumerate(item_shapes(item, style)):
            tagged.append((layer, i, j, shape))
    tagged.sort(key=lambda t: t[:3])
    return [t[3] for t in tagged]


#: Chord length, mm, of the polygon a drawn circle is an obstacle as (its sagitta is at most
#: about r·(π/n)²/2; the chords are never fewer than 24 nor more than 720).
CIRCLE_CHORD = 1.0


def _ring(c: XY, r: float) -> np.ndarray:
    """A drawn circle as the chords (n × 4) of the polygon it is an obstacle as."""
    n = min(720, max(24, math.ceil(2.0 * math.pi * r / CIRCLE_CHORD)))
    t = np.linspace(0.0, 2.0 * math.pi, n + 1)
    x, y = c[0] + r * np.cos(t), c[1] + r * np.sin(t)
    return np.column_stack([x[:-1], y[:-1], x[1:], y[1:]])


def _obstacles(shapes: Sequence[Shape], style: Style = DEFAULT) -> Obstacles:
    """Everything drawn, as labels must keep clear of it (panel frame): every stroke as pieces
    with its pen's width (hatching, pivot triangles, outlines, circles as chords, curves piece by
    piece), hinges as discs, slider blocks, plates and arrowheads as fills."""
    pieces: list[np.ndarray] = []
    widths: list[np.ndarray] = []
    discs: list[tuple[XY, float]] = []
    fills: list[tuple[XY, ...]] = []
    for s in shapes:
        pen = style.pen(s.key)
        width = pen.width
        if isinstance(s, LineShape):
            segs = np.array([[s.p0[0], s.p0[1], s.p1[0], s.p1[1]]])
        elif isinstance(s, PolyShape):
            pts = np.array(s.points + ((s.points[0],) if s.closed else ()), dtype=float)
            segs = np.column_stack([pts[:-1], pts[1:]])
            # a filled shape of the stroke's own colour is drawn without a stroke (an arrowhead)
            if s.filled:
                fills.append(s.points)
                width = 0.0 if pen.fill == pen.colour else width
        elif s.filled:  # a hinge
            discs.append((s.c, s.r + pen.width / 2.0))
            continue
        else:
            segs = _ring(s.c, s.r)
        pieces.append(segs)
        widths.append(np.full(segs.shape[0], width))
    if not pieces:
        return Obstacles(discs=discs, fills=fills)
    return Obstacles(np.concatenate(pieces), np.concatenate(widths), discs, fills)


def panel_labels(
    panel: Panel, shapes: Sequence[Shape], style: Style = DEFAULT
) -> tuple[PlacedLabel, ...]:
    """The panel's labels placed clear of each other and of everything drawn (panel frame);
    coincident point names come back as one label. ``shapes`` are ``panel_shapes(panel, style)``."""
    try:
        return _placed(panel, style)
    except TypeError:  # a panel that holds something unhashable is placed afresh
        return _place(panel, shapes, style)


@functools.lru_cache(maxsize=48)
def _placed(panel: Panel, style: Style) -> tuple[PlacedLabel, ...]:
    """Labels placed lately, by (panel, style): a kind that lays its sheet out to choose its scales
    (the force sheets) places the same panels again when it draws them, and placing is most of a
    drawing's time (its shapes, made again here, cost a hundredth of it). The panels are frozen
    values: equal content, equal placement."""
    return _place(panel, panel_shapes(panel, style), style)


def _place(panel: Panel, shapes: Sequence[Shape], style: Style) -> tuple[PlacedLabel, ...]:
    labels = [it for it in panel.items if isinstance(it, Label)]
    return place_labels(labels, style=style, obstacles=_obstacles(shapes, style))


# ----------------------------------------------------------------------------- drawing
def _group_name(prefix: str, name: str) -> str:
    clean = re.sub(r"[^A-Za-z0-9_-]+", "-", name).strip("-")
    return f"{prefix}-{clean}" if clean else prefix


def _emit(shape: Shape, pl: PanelPlacement, backend: Backend[object]) -> None:
    if isinstance(shape, LineShape):
        backend.line(pl.to_page(shape.p0), pl.to_page(shape.p1), shape.key, shape.dashed)
    elif isinstance(shape, PolyShape):
        pts = [pl.to_page(p) for p in shape.points]
        if shape.text is None:
            backend.polyline(pts, shape.key, shape.closed, shape.filled)
            return
        text, at, size = shape.text  # the shape and its text in one group: the text's own ground
        backend.begin_group("plate")
        backend.polyline(pts, shape.key, shape.closed, shape.filled)
        x, y = pl.to_page(at)
        backend.text(text, (x, y + BASELINE_DROP * size), size, "middle", False, "label")
        backend.end_group()
    else:
        backend.circle(pl.to_page(shape.c), shape.r, shape.key, shape.filled)


def draw_sheet(
    sheet: Sheet,
    backend: Backend[R],
    style: Style = DEFAULT,
    on_warning: Callable[[str], None] | None = None,
) -> R:
    """Draw a whole sheet on ``backend`` and return what its ``finish`` returns.

    Parameters
    ----------
    sheet : Sheet
        Title, panels (each in its own drawing millimetres, y up), page size, footer.
    backend : Backend
        Receives page coordinates (mm, y down, origin top-left).
    style : Style
        Pens, arrowheads, symbol sizes, fonts, gaps.
    on_warning : callable, optional
        Gets each layout warning (a panel that does not fit the page at its μ); by default
        they are issued as :class:`LayoutWarning` with :func:`warnings.warn`.
    """
    shapes = [panel_shapes(p, style) for p in sheet.panels]
    placed = [panel_labels(p, s, style) for p, s in zip(sheet.panels, shapes)]
    layout = layout_sheet(sheet, style, [[pl.box for pl in labels] for labels in placed])
    for w in layout.warnings:
        if on_warning is None:
            warnings.warn(w, LayoutWarning, stacklevel=2)
        else:
            on_warning(w)

    backend.begin(layout.page[0], layout.page[1], sheet.title)
    if sheet.title:
        backend.begin_group("title")
        x, y = layout.title_at
        for k, text in enumerate(layout.title_lines):  # one line, unless a fit page wraps it
            backend.text(text, (x, y + k * style.title_size * style.line_gap), style.title_size, "middle", False, "text")
        backend.end_group()
    for i, (panel, pl, panel_shape, labels) in enumerate(
        zip(sheet.panels, layout.panels, shapes, placed)
    ):
        backend.begin_group(_group_name(f"panel{i + 1}", panel.name))
        for shape in panel_shape:
            _emit(shape, pl, backend)
        for k, lab in enumerate(labels):
            # one group per label, its leader with it: the leader is the label's own stroke
            backend.begin_group(f"label{k + 1}")
            if lab.leader is not None:
                backend.line(pl.to_page(lab.leader[0]), pl.to_page(lab.leader[1]), "label")
            backend.text(lab.label.text, pl.to_page(lab.baseline), lab.label.size, "middle",
                         lab.label.italic, "label")
            backend.end_group()
        for t in panel.items:  # text set where the figure put it (a table's cells)
            if isinstance(t, Text):
                x, y = pl.to_page(t.at)
                backend.text(t.text, (x, y + BASELINE_DROP * t.size), t.size, t.anchor, t.italic, "label")
        # the caption in a group of its own: its strokes (the bars) are its, the panel's are not
        if pl.caption or pl.scale_bars:
            backend.begin_group("caption")
            for line in pl.caption:
                backend.text(line.text, line.at, line.size, "middle", False, "text")
            for bar, corner in pl.scale_bars:
                draw_scale_bar(bar, corner, backend, style)
            backend.end_group()
        backend.end_group()
    if layout.title_block is not None:
        backend.begin_group("title-block")
        draw_title_block(*layout.title_block, backend, style)
        backend.end_group()
    if sheet.footer:
        backend.begin_group("footer")
        for text, at in zip(sheet.footer, layout.footer_at):
            backend.text(text, at, style.note_size, "start", False, "text")
        backend.end_group()
    return backend.finish()
