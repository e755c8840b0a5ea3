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
import math

from graphmech.drawing.primitives import (XY, ArcArrow, Arrow, FixedPivot, GuideLine, Panel, Plate, Polyline,
                                          Primitive, Segment)
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


def _inside(a: XY, b: XY, c: XY, d: XY, near: float, depth: float, half: float) -> float:
    """Length of the piece a–b inside the base's box: from ``near`` to ``depth`` along ``d`` from
    the pivot ``c`` (the hinge itself, where every link of the pivot starts, left out), ``half``
    to either side (Liang–Barsky in the base's own frame)."""
    def local(p: XY) -> XY:
        x, y = p[0] - c[0], p[1] - c[1]
        return (x * d[0] + y * d[1], -x * d[1] + y * d[0])  # along d, across it

    (u0, v0), (u1, v1) = local(a), local(b)
    t0, t1 = 0.0, 1.0
    for p, q in ((-(u1 - u0), u0 - near), (u1 - u0, depth - u0), (-(v1 - v0), v0 + half), (v1 - v0, half - v0)):
        if p == 0.0:
            if q < 0.0:
                return 0.0
            continue
        r = q / p
        if p < 0.0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
    return max(t1 - t0, 0.0) * math.hypot(u1 - u0, v1 - v0)


def base_of(pivot: FixedPivot, pieces: list[tuple[XY, XY]], style: Style = DEFAULT) -> XY:
    """The side the pivot's base stands on: the first of BASES with least line under it (below
    unless another side has GAIN_MM less)."""
    depth = style.pivot_height + style.hatch_length
    half = style.pivot_ground_half
    near = style.hinge_r
    lengths = [sum(_inside(a, b, pivot.center, d, near, depth, half) for a, b in pieces) for d in BASES]
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
