"""Which way a frame pivot's base stands: below it, as the book draws it, unless a link of the
panel runs down through it (a crank pointing down) — then to the side, or above, where no line
runs. The frontend and the layout both orient a panel's pivots here, so what is drawn and the
room reckoned for it agree.

>>> from graphmech.drawing.primitives import FixedPivot, Panel, Segment
>>> up = Panel("m", "", (FixedPivot((0.0, 0.0)), Segment((0.0, 0.0), (0.0, 30.0))))
>>> down = Panel("m", "", (FixedPivot((0.0, 0.0)), Segment((0.0, 0.0), (0.0, -30.0))))
>>> [p.base for p in oriented(up).items[:1]], [p.base for p in oriented(down).items[:1]]
([(0.0, -1.0)], [(1.0, 0.0)])
"""
from __future__ import annotations

import dataclasses

import numpy as np

from graphmech.drawing.primitives import (XY, ArcArrow, Arrow, FixedPivot, GuideLine, Panel, Plate, Polyline,
                                          Primitive, Segment)
from graphmech.render.labels import clip_lengths
from graphmech.render.style import DEFAULT, Style

#: The directions a base may stand in, in the order preferred: below, right, left, above.
BASES: tuple[XY, ...] = ((0.0, -1.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0))
#: How much less line (mm) another side must have under its base to be taken instead of below.
GAIN_MM = 0.5


def _pieces(item: Primitive) -> list[tuple[XY, XY]]:
    """The straight pieces of what an item draws that a base could stand on."""
    if isinstance(item, (Segment, Arrow, GuideLine)):
        return [(item.p0, item.p1)]
    if isinstance(item, (Polyline, Plate)):
        pts = list(item.points) + ([item.points[0]] if isinstance(item, Plate) or item.closed else [])
        return list(zip(pts[:-1], pts[1:]))
    if isinstance(item, ArcArrow):
        pts = list(item.points())
        return list(zip(pts[:-1], pts[1:]))
    return []


def base_of(pivot: FixedPivot, pieces: list[tuple[XY, XY]], style: Style = DEFAULT) -> XY:
    """The side the pivot's base stands on: the first of BASES with least line under it (below
    unless another side has GAIN_MM less). Under a base: from the hinge's rim (where every link
    of the pivot starts) to the hatching's end along the side, the ground line's half to either
    side, measured in the base's own frame."""
    if not pieces:
        return BASES[0]
    segs = np.array([(a[0], a[1], b[0], b[1]) for a, b in pieces], dtype=float) - np.tile(pivot.center, 2)
    box = np.array([style.hinge_r, -style.pivot_ground_half, style.pivot_height + style.hatch_length,
                    style.pivot_ground_half])
    lengths = []
    for dx, dy in BASES:  # each piece in the frame (along the base, across it)
        local = np.column_stack([segs[:, 0] * dx + segs[:, 1] * dy, -segs[:, 0] * dy + segs[:, 1] * dx,
                                 segs[:, 2] * dx + segs[:, 3] * dy, -segs[:, 2] * dy + segs[:, 3] * dx])
        lengths.append(float(clip_lengths(np.tile(box, (len(segs), 1)), local).sum()))
    best = min(range(len(BASES)), key=lambda k: (lengths[k], k))
    return BASES[best] if lengths[0] - lengths[best] > GAIN_MM else BASES[0]


def oriented(panel: Panel, style: Style = DEFAULT) -> Panel:
    """The panel with each frame pivot that says nothing of its base given one (``base``)."""
    if not any(isinstance(i, FixedPivot) and i.base is None for i in panel.items):
        return panel
    pieces = [p for i in panel.items for p in _pieces(i)]
    items = tuple(dataclasses.replace(i, base=base_of(i, pieces, style))
                  if isinstance(i, FixedPivot) and i.base is None else i for i in panel.items)
    return dataclasses.replace(panel, items=items)
