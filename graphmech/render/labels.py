"""Deterministic placement of labels so they overlap neither each other nor the drawing.

Works in any right-handed frame with **y up** (the frontend uses each panel's own drawing
millimetres); "upper right" means +x, +y.

For each label, in the given order, candidate text boxes are laid around its anchor: 16
directions (starting at 45°, counter-clockwise in steps of 22.5°) on each ring of
``Style.label_gaps`` (the free distance between the anchor and the box edge along the
direction). Each candidate gets a score (lower is better):

* ``W_OVERLAP`` · overlap area (mm²) with the boxes already placed, each grown by the
  clearance, plus ``W_OVERLAP_HIT`` per box touched;
* ``W_CROSS`` · length (mm) of drawn segments inside the box, plus ``W_CROSS_HIT`` per segment;
* ``W_DISC`` per hinge disc and ``W_ANCHOR`` per other label's anchor the box covers;
* ``W_AVOID`` · Σ max(0, d·a)² over the label's ``avoid`` directions a (d the candidate's
  direction): lines leave the anchor there;
* ``W_RING`` · ring index and ``W_UPPER_RIGHT`` · (1 − d·(1, 1)/√2)/2, the small preferences
  for the nearest ring and the upper right.

The minimum wins; ties go to the earlier candidate. When every candidate overlaps an
already placed label, further rings (3 mm apart, up to four) are tried before giving in.

Examples
--------
>>> from graphmech.drawing.primitives import Label
>>> [p] = place_labels([Label("B", (0.0, 0.0))])
>>> p.center[0] > 0 and p.center[1] > 0        # upper right when nothing is in the way
True
>>> [q] = place_labels([Label("B", (0.0, 0.0))], segments=[((0.0, 0.0), (10.0, 10.0))])
>>> q.center != p.center                        # … but not across a line
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from graphmech.drawing.lettering import text_box_size
from graphmech.drawing.primitives import XY, Label
from graphmech.render.style import DEFAULT, Style

#: (xmin, ymin, xmax, ymax), mm.
Box = tuple[float, float, float, float]

W_OVERLAP = 100.0
W_OVERLAP_HIT = 50.0
W_CROSS = 20.0
W_CROSS_HIT = 5.0
W_DISC = 40.0
W_ANCHOR = 40.0
W_AVOID = 8.0
W_RING = 1.0
W_UPPER_RIGHT = 0.5

#: Number of candidate directions per ring.
N_DIRECTIONS = 16
#: Extra rings tried when every candidate overlaps a placed label: spacing (mm) and count.
FALLBACK_RING_STEP = 3.0
FALLBACK_RINGS = 4

_DIRECTIONS = np.array(
    [
        (math.cos(math.radians(45.0 + 22.5 * k)), math.sin(math.radians(45.0 + 22.5 * k)))
        for k in range(N_DIRECTIONS)
    ]
)
_UPPER_RIGHT = np.array([math.sqrt(0.5), math.sqrt(0.5)])


@dataclass(frozen=True)
class PlacedLabel:
    """A label with the centre of its (estimated) text box and the box, in the anchor's frame."""

    label: Label
    center: XY
    box: Box


def _support(d: np.ndarray, hw: float, hh: float) -> np.ndarray:
    """Distance from a box's centre to its boundary along unit directions ``d`` (n × 2)."""
    ax = np.abs(d[:, 0])
    ay = np.abs(d[:, 1])
    with np.errstate(divide="ignore"):
        tx = np.where(ax > 1e-12, hw / np.where(ax > 1e-12, ax, 1.0), np.inf)
        ty = np.where(ay > 1e-12, hh / np.where(ay > 1e-12, ay, 1.0), np.inf)
    result: np.ndarray = np.minimum(tx, ty)
    return result


def candidate_centres(label: Label, gaps: Sequence[float]) -> np.ndarray:
    """Candidate box centres (n × 2), ring-major, in candidate order."""
    w, h = text_box_size(label.text, label.size)
    support = _support(_DIRECTIONS, w / 2.0, h / 2.0)
    anchor = np.asarray(label.anchor, dtype=float)
    rings = [anchor + _DIRECTIONS * (gap + support)[:, None] for gap in gaps]
    return np.concatenate(rings, axis=0)


def _overlap_areas(boxes: np.ndarray, placed: np.ndarray) -> np.ndarray:
    """Intersection areas (C × P) of candidate boxes (C × 4) with placed boxes (P × 4)."""
    ix = np.minimum(boxes[:, None, 2], placed[None, :, 2]) - np.maximum(
        boxes[:, None, 0], placed[None, :, 0]
    )
    iy = np.minimum(boxes[:, None, 3], placed[None, :, 3]) - np.maximum(
        boxes[:, None, 1], placed[None, :, 1]
    )
    result: np.ndarray = np.clip(ix, 0.0, None) * np.clip(iy, 0.0, None)
    return result


def _clip_lengths(boxes: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """Length (C × S) of each segment (S × 4: x0, y0, x1, y1) inside each box (Liang–Barsky)."""
    x0 = segs[None, :, 0]
    y0 = segs[None, :, 1]
    dx = segs[None, :, 2] - segs[None, :, 0]
    dy = segs[None, :, 3] - segs[None, :, 1]
    xmin, ymin = boxes[:, None, 0], boxes[:, None, 1]
    xmax, ymax = boxes[:, None, 2], boxes[:, None, 3]
    shape = (boxes.shape[0], segs.shape[0])
    t0 = np.zeros(shape)
    t1 = np.ones(shape)
    ok = np.ones(shape, dtype=bool)
    for p, q in ((-dx, x0 - xmin), (dx, xmax - x0), (-dy, y0 - ymin), (dy, ymax - y0)):
        p = np.broadcast_to(p, shape)
        q = np.broadcast_to(q, shape)
        zero = p == 0.0
        ok &= ~(zero & (q < 0.0))
        r = q / np.where(zero, 1.0, p)
        t0 = np.where(~zero & (p < 0.0), np.maximum(t0, r), t0)
        t1 = np.where(~zero & (p > 0.0), np.minimum(t1, r), t1)
    seg_len = np.hypot(dx, dy)
    result: np.ndarray = np.where(ok, np.clip(t1 - t0, 0.0, None), 0.0) * seg_len
    return result


def _unit(v: XY) -> np.ndarray:
    n = math.hypot(v[0], v[1])
    if not n > 0.0 or not math.isfinite(n):
        raise ValueError(f"a label's avoid direction must be a non-zero vector, got {v!r}")
    return np.array([v[0] / n, v[1] / n])


def _scores(
    label: Label,
    centres: np.ndarray,
    n_per_ring: int,
    placed: np.ndarray,
    segs: np.ndarray,
    discs: np.ndarray,
    others: np.ndarray,
    clearance: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Scores of the candidates, their boxes (C × 4) and their overlap with placed labels."""
    w, h = text_box_size(label.text, label.size)
    boxes = np.column_stack(
        [centres[:, 0] - w / 2, centres[:, 1] - h / 2, centres[:, 0] + w / 2, centres[:, 1] + h / 2]
    )
    n = centres.shape[0]
    score = np.zeros(n)
    overlap = np.zeros(n)
    if placed.shape[0]:
        grown = boxes + np.array([-clearance, -clearance, clearance, clearance])
        areas = _overlap_areas(grown, placed)
        overlap = areas.sum(axis=1)
        score += W_OVERLAP * overlap + W_OVERLAP_HIT * (areas > 0.0).sum(axis=1)
    if segs.shape[0]:
        inside = _clip_lengths(boxes, segs)
        score += W_CROSS * inside.sum(axis=1) + W_CROSS_HIT * (inside > 1e-9).sum(axis=1)
    if discs.shape[0]:
        cx = np.clip(discs[None, :, 0], boxes[:, None, 0], boxes[:, None, 2])
        cy = np.clip(discs[None, :, 1], boxes[:, None, 1], boxes[:, None, 3])
        dist = np.hypot(cx - discs[None, :, 0], cy - discs[None, :, 1])
        score += W_DISC * (dist < discs[None, :, 2]).sum(axis=1)
    if others.shape[0]:
        covered = (
            (others[None, :, 0] >= boxes[:, None, 0])
            & (others[None, :, 0] <= boxes[:, None, 2])
            & (others[None, :, 1] >= boxes[:, None, 1])
            & (others[None, :, 1] <= boxes[:, None, 3])
        )
        score += W_ANCHOR * covered.sum(axis=1)
    dirs = np.tile(_DIRECTIONS, (n // N_DIRECTIONS, 1))
    for a in label.avoid:
        score += W_AVOID * np.clip(dirs @ _unit(a), 0.0, None) ** 2
    ring = np.repeat(np.arange(n // n_per_ring), n_per_ring)
    score += W_RING * ring + W_UPPER_RIGHT * (1.0 - dirs @ _UPPER_RIGHT) / 2.0
    return score, boxes, overlap


def place_labels(
    labels: Sequence[Label],
    segments: Sequence[tuple[XY, XY]] = (),
    discs: Sequence[tuple[XY, float]] = (),
    style: Style = DEFAULT,
) -> tuple[PlacedLabel, ...]:
    """Place ``labels`` in order, each at its best candidate given those placed before.

    Parameters
    ----------
    labels : sequence of Label
        In placement order: earlier labels get the better spots.
    segments : sequence of (p0, p1)
        Drawn strokes a label should not cross (links, vectors, construction lines).
    discs : sequence of (centre, radius)
        Round symbols a label should not cover (hinges).
    style : Style
        Supplies ``label_gaps`` and ``label_clearance``.

    Returns
    -------
    tuple of PlacedLabel
        One per label, in the given order; same input → same output.
    """
    segs = np.array([(a[0], a[1], b[0], b[1]) for a, b in segments], dtype=float).reshape(-1, 4)
    disc_arr = np.array([(c[0], c[1], r) for c, r in discs], dtype=float).reshape(-1, 3)
    anchors = np.array([lab.anchor for lab in labels], dtype=float).reshape(-1, 2)
    placed_boxes: list[Box] = []
    out: list[PlacedLabel] = []
    base_gaps = tuple(style.label_gaps)
    fallback = tuple(
        base_gaps[-1] + FALLBACK_RING_STEP * (k + 1) for k in range(FALLBACK_RINGS)
    )
    for i, label in enumerate(labels):
        others = np.delete(anchors, i, axis=0)
        placed = np.array(placed_boxes, dtype=float).reshape(-1, 4)
        gaps = base_gaps
        while True:
            centres = candidate_centres(label, gaps)
            score, boxes, overlap = _scores(
                label, centres, N_DIRECTIONS, placed, segs, disc_arr, others,
                style.label_clearance,
            )
            best = int(np.argmin(score))  # first minimum: ties go to candidate order
            if overlap[best] <= 0.0 or len(gaps) > len(base_gaps):
                break
            gaps = base_gaps + fallback
        row = boxes[best]
        box = (float(row[0]), float(row[1]), float(row[2]), float(row[3]))
        centre = (float(centres[best, 0]), float(centres[best, 1]))
        placed_boxes.append(box)
        out.append(PlacedLabel(label, centre, box))
    return tuple(out)


def boxes_overlap(a: Box, b: Box) -> float:
    """Intersection area of two boxes, mm² (0 when they only touch or are apart).

    >>> boxes_overlap((0, 0, 2, 2), (1, 1, 3, 3))
    1.0
    """
    ix = min(a[2], b[2]) - max(a[0], b[0])
    iy = min(a[3], b[3]) - max(a[1], b[1])
    return float(max(ix, 0.0) * max(iy, 0.0))
