"""Diagrams against a crank angle (or any position number): the numbers 1 … N along the φ axis,
numbering and thinning every k-th position so the numbers stand clear, and moving drawn items
(a diagram is drawn at its origin, then set in its place on the panel).

Shared by the flywheel's diagrams (Mп, A, ΔT, Jп against φ) and the full cycle's (s, v, a
against φ).
"""
from __future__ import annotations

import dataclasses
from typing import overload

import numpy as np

from graphmech.drawing.lettering import text_box_size
from graphmech.drawing.primitives import (XY, ArcArrow, Arrow, Circle, GuideLine, Label, Polyline, Primitive,
                                          Segment, Slider)

#: Font size of the position numbers (the least body text a drawing sets, issue 15), and the
#: least free distance between two of them, mm.
NUMBER_SIZE, NUMBER_CLEARANCE = 3.5, 1.2


#: The steps numbering and thinning use: every k-th position, k one of these.
NICE_STEPS = tuple(int(m * 10 ** e) for e in range(6) for m in (1, 2, 3, 4, 5, 6, 8)
                   if float(m * 10 ** e).is_integer()) + (10 ** 6,)


#: How far the axes run past what they carry, mm.
AXIS_OVERRUN = 7.0


BELOW = ((0.0, 1.0), (1.0, 0.0), (-1.0, 0.0))  # avoid: a number under a horizontal axis


def nice_step(least: float) -> int:
    """The smallest of 1, 2, 3, 4, 5, 6, 8, 10, 20 … that is ≥ ``least``.

    >>> nice_step(1.0), nice_step(2.5), nice_step(7), nice_step(99.5)
    (1, 3, 8, 100)
    """
    for k in NICE_STEPS:
        if k >= least - 1e-12:
            return k
    return NICE_STEPS[-1]


def numbers_every(n: int, spacing_mm: float, size: float = NUMBER_SIZE) -> int:
    """Number every k-th of ``n`` positions ``spacing_mm`` apart so the numbers stand clear.

    >>> numbers_every(12, 12.0), numbers_every(36, 4.0), numbers_every(3600, 0.04)
    (1, 2, 300)
    """
    need = text_box_size(str(n), size)[0] + 2.0 * NUMBER_CLEARANCE
    return nice_step(need / spacing_mm) if spacing_mm > 0 else n


def count_every(n: int, most: int) -> int:
    """Every k-th of ``n`` so that at most ``most`` are taken (k a nice step).

    >>> count_every(12, 36), count_every(48, 36), count_every(3600, 36)
    (1, 2, 100)
    """
    return nice_step(n / most)


@overload
def transformed(item: Label, k: float = 1.0, dx: float = 0.0, dy: float = 0.0) -> Label: ...
@overload
def transformed(item: Primitive, k: float = 1.0, dx: float = 0.0, dy: float = 0.0) -> Primitive: ...
def transformed(item: Primitive, k: float = 1.0, dx: float = 0.0, dy: float = 0.0) -> Primitive:
    """The item enlarged ``k`` times about the origin, then moved by (dx, dy) mm: its points, and
    the sizes that belong to the drawing (a circle's radius, a slider block); the paper sizes of
    letters, hinges and arrowheads stay. A label stays a label.

    >>> transformed(Segment((1.0, 2.0), (3.0, 4.0)), 2.0, 10.0).p1, transformed(Circle((1.0, 0.0), 2.0), 3.0).r
    ((16.0, 8.0), 6.0)
    """
    def tf(p: XY) -> XY:
        return (k * p[0] + dx, k * p[1] + dy)
    if isinstance(item, (Segment, Arrow, GuideLine)):
        return dataclasses.replace(item, p0=tf(item.p0), p1=tf(item.p1))
    if isinstance(item, (ArcArrow, Circle)):
        return dataclasses.replace(item, center=tf(item.center), r=item.r * k)
    if isinstance(item, Polyline):
        return dataclasses.replace(item, points=tuple(tf(p) for p in item.points))
    if isinstance(item, Slider):
        return dataclasses.replace(item, center=tf(item.center), length=item.length * k, width=item.width * k)
    if isinstance(item, Label):
        return dataclasses.replace(item, anchor=tf(item.anchor))
    raise TypeError(f"cannot move {item!r}")


@overload
def moved(item: Label, dx: float, dy: float) -> Label: ...
@overload
def moved(item: Primitive, dx: float, dy: float) -> Primitive: ...
def moved(item: Primitive, dx: float, dy: float) -> Primitive:
    """The item translated by (dx, dy) mm (a label stays a label)."""
    return transformed(item, 1.0, dx, dy)


def phi_axis_numbers(x: np.ndarray, every: int, y: float = 0.0) -> list[Label]:
    """Numbers 1 … N at the positions (every k-th) and 1 again at the cycle's end."""
    n = x.size - 1
    out = [Label(str(k + 1), (float(x[k]), y), BELOW, NUMBER_SIZE, italic=False) for k in range(0, n, every)]
    if n % every == 0:
        out.append(Label("1", (float(x[n]), y), BELOW, NUMBER_SIZE, italic=False))
    return out
