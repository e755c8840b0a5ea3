"""Deterministic placement of labels so they overlap neither each other nor anything drawn.

Works in any right-handed frame with **y up** (the frontend uses each panel's own drawing
millimetres); "upper right" means +x, +y.

Obstacles
---------
Everything drawn is an obstacle (:class:`Obstacles`): **strokes** as straight pieces with their
half width (links, arrow shafts, hatching, pivot triangles, the outlines of slider blocks and
plates, circles and curves as the chords they are drawn with), **discs** a box must not touch
(hinges) and **fills** whose interior a box must not sit in (slider blocks, plates,
arrowheads). Strokes are looked up through a grid of cells (:data:`CELL` mm, coarser for very
long drawings so that at most about :data:`MAX_SAMPLES` samples index them): each label sees
only the pieces near its candidates, so the time grows with the number of labels times what
lies near each, not with their product.

The box of a label is what a browser's ``getBBox()`` gives its text, from above
(:func:`graphmech.drawing.lettering.text_extent`: the font's whole cell, scripts included).

Coincident points: one label
----------------------------
Point names (:func:`is_point_name`: a Latin letter or π, then only letters, digits and primes,
sub- and superscripts allowed — "B", "c₃", "n₂′", not "ω₁", "2" or "φ = 30°") whose anchors lie
within :data:`MERGE_DISTANCE` (0.3 mm) of a name already gathered, of the same size and slant,
are written as one label at the first one's anchor (:func:`merge_coincident`), as the book
writes them: a pole (:data:`POLES`: p, p′, π, π′) first and the others in brackets,
"p (c₃, d₃)"; without a pole, in the given order, separated by commas, "a′, n₂′". A name given
twice is written once.

Candidates and scores
---------------------
For each label, in the given order, candidate text boxes are laid around its anchor: 16
directions (starting at 45°, counter-clockwise in steps of 22.5°) on each ring of
``Style.label_gaps``, then 32 on each ring of :data:`FAR_GAPS` (the gap is the free distance
between the anchor and the box edge along the direction). Each candidate gets a score (lower is better):

* ``W_OVERLAP`` · overlap area (mm²) with the boxes already placed, each grown by the
  clearance, plus ``W_OVERLAP_HIT`` per box touched;
* ``W_CROSS`` · length (mm) of strokes (and of the leaders already drawn) inside the box grown
  by each stroke's half width and :data:`STROKE_CLEARANCE`, plus ``W_CROSS_HIT`` per piece;
* ``W_FILL`` per fill holding the box's centre, ``W_DISC`` per disc it touches and ``W_ANCHOR``
  per other label's anchor the box covers;
* ``W_AVOID`` · Σ max(0, d·a)² over the label's ``avoid`` directions a (d the candidate's
  direction): lines leave the anchor there;
* ``W_RING`` · ring index and ``W_UPPER_RIGHT`` · (1 − d·(1, 1)/√2)/2, the small preferences
  for the nearest ring and the upper right;
* for a box further than :data:`LEADER_FROM` from its anchor, which gets a **leader** (a thin
  line from near the anchor to the box's edge): ``W_LEADER``, plus ``W_LEADER_CROSS`` per
  stroke and ``W_LEADER_LABEL`` per placed box the leader would cross, and ``W_LEADER_ALONG``
  per point of four along it that runs beside a stroke (it would read as part of the drawing).

The minimum wins; ties go to the earlier candidate. A free spot on a far ring beats any
crossing near the anchor; where no candidate is free, the least bad is taken — placement never
fails and never loops.

Examples
--------
>>> from graphmech.drawing.primitives import Label
>>> [p] = place_labels([Label("B", (0.0, 0.0))])
>>> p.center[0] > 0 and p.center[1] > 0        # upper right when nothing is in the way
True
>>> [q] = place_labels([Label("B", (0.0, 0.0))], segments=[((0.0, 0.0), (10.0, 10.0))])
>>> q.center != p.center                        # … but not across a line
True
>>> [m] = place_labels([Label("c₃", (5.0, 5.0)), Label("p", (5.1, 5.0))])
>>> m.label.text
'p (c₃)'
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np

from graphmech.drawing.lettering import plain, text_extent
from graphmech.drawing.primitives import XY, Label
from graphmech.render.style import DEFAULT, Style

#: (xmin, ymin, xmax, ymax), mm.
Box = tuple[float, float, float, float]

W_OVERLAP = 100.0
W_OVERLAP_HIT = 50.0
W_CROSS = 20.0
W_CROSS_HIT = 5.0
W_FILL = 60.0
W_DISC = 40.0
W_ANCHOR = 40.0
W_AVOID = 8.0
W_RING = 1.0
W_UPPER_RIGHT = 0.5
W_LEADER = 1.5
W_LEADER_CROSS = 2.0
W_LEADER_LABEL = 30.0
W_LEADER_ALONG = 1.5

#: Number of candidate directions per ring: on the near rings, and on the far ones (where the
#: free gaps between lines fanning out from a point are narrower in angle).
N_DIRECTIONS = 16
N_FAR_DIRECTIONS = 32
#: Rings beyond ``Style.label_gaps``, mm: a label pushed this far gets a leader.
FAR_GAPS = (7.5, 10.5, 14.0, 18.0)
#: A box whose gap to its anchor is larger than this (mm) gets a leader.
LEADER_FROM = 3.5
#: A leader starts this far from its anchor (or just outside the hinge or block there) and
#: stops this short of the box, mm; none is drawn shorter than LEADER_SHORTEST.
LEADER_START = 0.8
LEADER_GAP = 0.3
LEADER_SHORTEST = 1.0
#: A leader's point this close to a stroke (beyond its half width), mm, runs beside it.
LEADER_ALONG_DISTANCE = 0.6
#: Free distance kept between a box and a stroke's ink (the stroke's half width more), mm.
STROKE_CLEARANCE = 0.15
#: Anchors of point names closer than this (mm) share one label.
MERGE_DISTANCE = 0.3
#: The letters of a polygon's pole, written first when images coincide with it.
POLES = ("p", "p′", "π", "π′")
#: Cell of the stroke grid, mm, and the most samples it is indexed by.
CELL = 5.0
MAX_SAMPLES = 400_000



def _directions(n: int) -> np.ndarray:
    """``n`` unit directions from 45°, counter-clockwise, evenly spaced."""
    a = np.radians(45.0 + 360.0 / n * np.arange(n))
    return np.column_stack([np.cos(a), np.sin(a)])


_DIRECTIONS = _directions(N_DIRECTIONS)
_FAR_DIRECTIONS = _directions(N_FAR_DIRECTIONS)
_UPPER_RIGHT = np.array([math.sqrt(0.5), math.sqrt(0.5)])
_POINT_NAME = re.compile(r"^(?:[A-Za-z]|π)[A-Za-z0-9′″']*$")


@dataclass(frozen=True)
class PlacedLabel:
    """A label placed: the centre of its text box and the box, the middle of its baseline (where
    the text is set, centred), and its leader (from near the anchor to the box) or None — all
    in the anchor's frame. ``label`` is what is drawn; ``sources`` the labels it stands for
    (more than one where coincident points were merged)."""

    label: Label
    center: XY
    box: Box
    baseline: XY = (0.0, 0.0)
    leader: tuple[XY, XY] | None = None
    sources: tuple[Label, ...] = ()


# ----------------------------------------------------------------------------- coincident points
def is_point_name(text: str) -> bool:
    """Whether ``text`` names a point (it may be merged with a coincident one).

    >>> [is_point_name(t) for t in ("B", "c₃", "n_{2}′", "P₁₃", "ω₁", "2", "F = 3 N")]
    [True, True, True, True, False, False, False]
    """
    return bool(_POINT_NAME.match(plain(text)))


def merged_text(texts: Sequence[str]) -> str:
    """The one label of coincident points: a pole first and the others in brackets, else all
    in order separated by commas; a name given twice is written once.

    >>> merged_text(["c₃", "p"]), merged_text(["a′", "n₂′", "a′"]), merged_text(["b"])
    ('p (c₃)', 'a′, n₂′', 'b')
    """
    names = list(dict.fromkeys(texts))
    poles = [t for t in names if plain(t) in POLES]
    if poles and len(names) > 1:
        rest = [t for t in names if t != poles[0]]
        return f"{poles[0]} ({', '.join(rest)})"
    return ", ".join(names)


def merge_coincident(
    labels: Sequence[Label], distance: float = MERGE_DISTANCE
) -> list[tuple[Label, tuple[Label, ...]]]:
    """The labels to draw, each with the labels it stands for, in the order of their first.

    Point names of the same size and slant within ``distance`` of a name already in a group join
    it; other labels stand alone.
    """
    groups: list[list[Label]] = []
    cells: dict[tuple[int, int], list[int]] = {}  # cells of side ``distance``: the groups in them
    for lab in labels:
        if not is_point_name(lab.text):
            groups.append([lab])
            continue
        ix, iy = math.floor(lab.anchor[0] / distance), math.floor(lab.anchor[1] / distance)
        near = sorted({g for dx in (-1, 0, 1) for dy in (-1, 0, 1) for g in cells.get((ix + dx, iy + dy), ())})
        for g in near:
            head = groups[g][0]
            if (head.size == lab.size and head.italic == lab.italic
                    and any(math.dist(m.anchor, lab.anchor) <= distance for m in groups[g])):
                groups[g].append(lab)
                break
        else:
            g = len(groups)
            groups.append([lab])
        cells.setdefault((ix, iy), []).append(g)
    out: list[tuple[Label, tuple[Label, ...]]] = []
    for members in groups:
        if len(members) == 1:
            out.append((members[0], (members[0],)))
            continue
        avoid = tuple(dict.fromkeys(a for m in members for a in m.avoid))
        out.append((replace(members[0], text=merged_text([m.text for m in members]), avoid=avoid), tuple(members)))
    return out


# ----------------------------------------------------------------------------- obstacles
class _Grid:
    """Stroke pieces indexed by the cells they pass through (sampled every half cell, so a
    look-up one cell wider than its region finds every piece in the region)."""

    def __init__(self, segs: np.ndarray) -> None:
        n = segs.shape[0]
        self.cell = CELL
        self.keys = np.zeros(0, dtype=np.int64)
        self.ids = np.zeros(0, dtype=np.int64)
        self.origin = (0.0, 0.0)
        self.nx = self.ny = 0
        if n == 0:
            return
        x0, y0, x1, y1 = segs[:, 0], segs[:, 1], segs[:, 2], segs[:, 3]
        length = np.hypot(x1 - x0, y1 - y0)
        self.cell = max(CELL, 2.0 * float(length.sum()) / MAX_SAMPLES)
        k = np.ceil(length / (self.cell / 2.0)).astype(np.int64) + 1
        ids = np.repeat(np.arange(n, dtype=np.int64), k)
        first = np.repeat(np.cumsum(k) - k, k)
        t = (np.arange(ids.shape[0]) - first) / np.maximum(np.repeat(k - 1, k), 1)
        px = x0[ids] + t * (x1 - x0)[ids]
        py = y0[ids] + t * (y1 - y0)[ids]
        self.origin = (float(px.min()), float(py.min()))
        ix = np.floor((px - self.origin[0]) / self.cell).astype(np.int64)
        iy = np.floor((py - self.origin[1]) / self.cell).astype(np.int64)
        self.nx, self.ny = int(ix.max()) + 1, int(iy.max()) + 1
        both = np.unique((ix * self.ny + iy) * n + ids)
        self.keys, self.ids = both // n, both % n

    def query(self, region: Box) -> np.ndarray:
        """Indices of the pieces that may pass through ``region`` (sorted, no repeats)."""
        if self.ids.shape[0] == 0:
            return self.ids
        c, (ox, oy) = self.cell, self.origin
        ix0 = max(int(math.floor((region[0] - ox) / c)) - 1, 0)
        ix1 = min(int(math.floor((region[2] - ox) / c)) + 1, self.nx - 1)
        iy0 = max(int(math.floor((region[1] - oy) / c)) - 1, 0)
        iy1 = min(int(math.floor((region[3] - oy) / c)) + 1, self.ny - 1)
        if ix0 > ix1 or iy0 > iy1:
            return self.ids[:0]
        rows = np.arange(ix0, ix1 + 1, dtype=np.int64) * self.ny
        lo = np.searchsorted(self.keys, rows + iy0, "left")
        hi = np.searchsorted(self.keys, rows + iy1, "right")
        found = np.concatenate([self.ids[a:b] for a, b in zip(lo, hi)])
        return np.unique(found)


class Obstacles:
    """What labels keep clear of, in the labels' frame.

    Parameters
    ----------
    segments : sequence of (p0, p1), or an array n × 4 (x0, y0, x1, y1)
        Straight pieces of the strokes.
    widths : sequence of float
        The stroke width of each piece, mm (empty: hairlines).
    discs : sequence of (centre, radius)
        Round symbols a box must not touch (hinges).
    fills : sequence of point sequences
        Filled polygons a box must not sit in (their outlines belong in ``segments``).
    """

    def __init__(
        self,
        segments: Sequence[tuple[XY, XY]] | np.ndarray = (),
        widths: Sequence[float] | np.ndarray = (),
        discs: Sequence[tuple[XY, float]] = (),
        fills: Sequence[Sequence[XY]] = (),
    ) -> None:
        if isinstance(segments, np.ndarray):
            segs = np.asarray(segments, dtype=float).reshape(-1, 4)
        else:
            segs = np.array([(a[0], a[1], b[0], b[1]) for a, b in segments], dtype=float).reshape(-1, 4)
        half = np.asarray(widths, dtype=float).reshape(-1) / 2.0 if len(widths) else np.zeros(segs.shape[0])
        keep = np.isfinite(segs).all(axis=1)
        self.segs = np.column_stack([segs, half])[keep]
        self.discs = np.array([(c[0], c[1], r) for c, r in discs], dtype=float).reshape(-1, 3)
        self.fills = [np.asarray(f, dtype=float).reshape(-1, 2) for f in fills if len(f) >= 3]
        self.fill_boxes = np.array(
            [(f[:, 0].min(), f[:, 1].min(), f[:, 0].max(), f[:, 1].max()) for f in self.fills], dtype=float
        ).reshape(-1, 4)
        self._grid = _Grid(self.segs)
        self._reach = float(self.segs[:, 4].max()) if self.segs.shape[0] else 0.0

    def near(self, region: Box) -> tuple[np.ndarray, np.ndarray, list[np.ndarray]]:
        """The stroke pieces (n × 5: x0, y0, x1, y1, half width), discs and fills that may reach
        into ``region``."""
        r = self._reach + STROKE_CLEARANCE
        grown = (region[0] - r, region[1] - r, region[2] + r, region[3] + r)
        segs = self.segs[self._grid.query(grown)]
        # the grid's cells are coarse: keep only the pieces whose box comes within reach of the
        # region (a leader's points look LEADER_ALONG_DISTANCE round them), in their order — the
        # others could reach no candidate, so every score is the same, sooner
        far = self._reach + max(STROKE_CLEARANCE, LEADER_ALONG_DISTANCE)
        segs = segs[(np.maximum(segs[:, 0], segs[:, 2]) >= region[0] - far)
                    & (np.minimum(segs[:, 0], segs[:, 2]) <= region[2] + far)
                    & (np.maximum(segs[:, 1], segs[:, 3]) >= region[1] - far)
                    & (np.minimum(segs[:, 1], segs[:, 3]) <= region[3] + far)]
        d = self.discs
        discs = d[(d[:, 0] + d[:, 2] >= region[0]) & (d[:, 0] - d[:, 2] <= region[2])
                  & (d[:, 1] + d[:, 2] >= region[1]) & (d[:, 1] - d[:, 2] <= region[3])]
        fb = self.fill_boxes
        hit = np.nonzero((fb[:, 2] >= region[0]) & (fb[:, 0] <= region[2])
                         & (fb[:, 3] >= region[1]) & (fb[:, 1] <= region[3]))[0]
        return segs, discs, [self.fills[i] for i in hit]


# ----------------------------------------------------------------------------- geometry
def _support(d: np.ndarray, hw: float, hh: float) -> np.ndarray:
    """Distance from a box's centre to its boundary along unit directions ``d`` (n × 2)."""
    ax = np.abs(d[:, 0])
    ay = np.abs(d[:, 1])
    with np.errstate(divide="ignore"):
        tx = np.where(ax > 1e-12, hw / np.where(ax > 1e-12, ax, 1.0), np.inf)
        ty = np.where(ay > 1e-12, hh / np.where(ay > 1e-12, ay, 1.0), np.inf)
    result: np.ndarray = np.minimum(tx, ty)
    return result


def _extent(label: Label) -> tuple[float, float, float]:
    return text_extent(label.text, label.size, label.italic)


def candidate_centres(label: Label, gaps: Sequence[float], dirs: np.ndarray = _DIRECTIONS) -> np.ndarray:
    """Candidate box centres (n × 2), ring-major, in candidate order, along ``dirs`` (m × 2)."""
    w, up, down = _extent(label)
    support = _support(dirs, w / 2.0, (up + down) / 2.0)
    anchor = np.asarray(label.anchor, dtype=float)
    rings = [anchor + dirs * (gap + support)[:, None] for gap in gaps]
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


def clip_lengths(boxes: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """Length of each segment (n × 4: x0, y0, x1, y1) inside its box (n × 4) (Liang–Barsky)."""
    x0, y0 = segs[:, 0], segs[:, 1]
    dx, dy = segs[:, 2] - x0, segs[:, 3] - y0
    t0 = np.zeros(x0.shape)
    t1 = np.ones(x0.shape)
    ok = np.ones(x0.shape, dtype=bool)
    for p, q in ((-dx, x0 - boxes[:, 0]), (dx, boxes[:, 2] - x0), (-dy, y0 - boxes[:, 1]), (dy, boxes[:, 3] - y0)):
        zero = p == 0.0
        ok &= ~(zero & (q < 0.0))
        r = q / np.where(zero, 1.0, p)
        t0 = np.where(~zero & (p < 0.0), np.maximum(t0, r), t0)
        t1 = np.where(~zero & (p > 0.0), np.minimum(t1, r), t1)
    result: np.ndarray = np.where(ok, np.clip(t1 - t0, 0.0, None), 0.0) * np.hypot(dx, dy)
    return result


def _inside(boxes: np.ndarray, segs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per box (C × 4): total length of the pieces (S × 5, half width last) inside it, each
    box grown by the piece's half width and the clearance, and how many pieces reach in."""
    c = boxes.shape[0]
    if segs.shape[0] == 0:
        return np.zeros(c), np.zeros(c)
    g = segs[:, 4] + STROKE_CLEARANCE
    lo_x = np.minimum(segs[:, 0], segs[:, 2]) - g
    hi_x = np.maximum(segs[:, 0], segs[:, 2]) + g
    lo_y = np.minimum(segs[:, 1], segs[:, 3]) - g
    hi_y = np.maximum(segs[:, 1], segs[:, 3]) + g
    near = ((lo_x[None, :] < boxes[:, 2:3]) & (hi_x[None, :] > boxes[:, 0:1])
            & (lo_y[None, :] < boxes[:, 3:4]) & (hi_y[None, :] > boxes[:, 1:2]))
    ci, si = np.nonzero(near)
    if ci.shape[0] == 0:
        return np.zeros(c), np.zeros(c)
    grown = boxes[ci] + np.column_stack([-g[si], -g[si], g[si], g[si]])
    length = clip_lengths(grown, segs[si, :4])
    return (np.bincount(ci, weights=length, minlength=c),
            np.bincount(ci, weights=(length > 1e-9).astype(float), minlength=c))


def _next_vertices(poly: np.ndarray) -> np.ndarray:
    """The next vertex of each of a closed polygon's (k × 2): np.roll's values, without its overhead."""
    return np.concatenate((poly[1:], poly[:1]))


def _in_polygon(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Whether each point (n × 2) is inside the polygon (k × 2), by the even–odd rule."""
    x, y = pts[:, 0:1], pts[:, 1:2]
    ax, ay = poly[:, 0][None, :], poly[:, 1][None, :]
    nxt = _next_vertices(poly)
    bx, by = nxt[:, 0][None, :], nxt[:, 1][None, :]
    straddle = (ay > y) != (by > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xc = ax + (y - ay) * (bx - ax) / np.where(by != ay, by - ay, 1.0)
    result: np.ndarray = (np.sum(straddle & (x < xc), axis=1) % 2) == 1
    return result


def _crossings(p0: np.ndarray, p1: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """How many of the segments (S × ≥4) each segment p0→p1 (C × 2 each) properly crosses."""
    c = p0.shape[0]
    if segs.shape[0] == 0 or c == 0:
        return np.zeros(c)
    near = ((np.minimum(segs[:, 0], segs[:, 2])[None, :] <= np.maximum(p0[:, 0], p1[:, 0])[:, None])
            & (np.maximum(segs[:, 0], segs[:, 2])[None, :] >= np.minimum(p0[:, 0], p1[:, 0])[:, None])
            & (np.minimum(segs[:, 1], segs[:, 3])[None, :] <= np.maximum(p0[:, 1], p1[:, 1])[:, None])
            & (np.maximum(segs[:, 1], segs[:, 3])[None, :] >= np.minimum(p0[:, 1], p1[:, 1])[:, None]))
    ci, si = np.nonzero(near)
    if ci.shape[0] == 0:
        return np.zeros(c)
    a, b = p0[ci], p1[ci]
    s0, s1 = segs[si, 0:2], segs[si, 2:4]

    def orient(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
        r: np.ndarray = (v[:, 0] - u[:, 0]) * (w[:, 1] - u[:, 1]) - (v[:, 1] - u[:, 1]) * (w[:, 0] - u[:, 0])
        return r

    hit = (orient(a, b, s0) * orient(a, b, s1) < 0.0) & (orient(s0, s1, a) * orient(s0, s1, b) < 0.0)
    result: np.ndarray = np.bincount(ci, weights=hit.astype(float), minlength=c)
    return result


def _along(p0: np.ndarray, p1: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """How many of the points at ¼, ½, ¾ and the end of each leader p0→p1 (C × 2 each) lie
    within LEADER_ALONG_DISTANCE of a stroke (S × 5): a leader running beside a line reads as
    part of the drawing."""
    c = p0.shape[0]
    if segs.shape[0] == 0 or c == 0:
        return np.zeros(c)
    f = np.array([0.25, 0.5, 0.75, 1.0])
    q = (p0[:, None, :] + f[None, :, None] * (p1 - p0)[:, None, :]).reshape(-1, 2)  # (4C) × 2
    reach = segs[:, 4] + LEADER_ALONG_DISTANCE
    near = ((np.minimum(segs[:, 0], segs[:, 2]) - reach)[None, :] <= q[:, 0:1]) \
        & ((np.maximum(segs[:, 0], segs[:, 2]) + reach)[None, :] >= q[:, 0:1]) \
        & ((np.minimum(segs[:, 1], segs[:, 3]) - reach)[None, :] <= q[:, 1:2]) \
        & ((np.maximum(segs[:, 1], segs[:, 3]) + reach)[None, :] >= q[:, 1:2])
    qi, si = np.nonzero(near)
    if qi.shape[0] == 0:
        return np.zeros(c)
    a, d = segs[si, 0:2], segs[si, 2:4] - segs[si, 0:2]
    dd = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("ij,ij->i", q[qi] - a, d) / np.where(dd > 0.0, dd, 1.0), 0.0, 1.0)
    gap = np.hypot(*(q[qi] - a - t[:, None] * d).T)
    close = np.zeros(q.shape[0], dtype=bool)
    close[qi[gap <= reach[si]]] = True
    result: np.ndarray = close.reshape(c, 4).sum(axis=1).astype(float)
    return result


def _leader_start(anchor: np.ndarray, dirs: np.ndarray, discs: np.ndarray, fills: list[np.ndarray]) -> np.ndarray:
    """Where a leader leaves its anchor along each direction: past the hinge or the block the
    anchor is on, or LEADER_START from it."""
    start = np.full(dirs.shape[0], LEADER_START)
    for cx, cy, r in discs:
        off = math.hypot(anchor[0] - cx, anchor[1] - cy)
        if off < r:
            start = np.maximum(start, r + off + LEADER_GAP)
    for poly in fills:
        if not _in_polygon(anchor[None, :], poly)[0]:
            continue
        e0, e1 = poly, _next_vertices(poly)
        ex, ey = (e1 - e0)[:, 0], (e1 - e0)[:, 1]
        wx, wy = (e0 - anchor)[:, 0], (e0 - anchor)[:, 1]
        den = dirs[:, 0:1] * ey[None, :] - dirs[:, 1:2] * ex[None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (wx[None, :] * ey[None, :] - wy[None, :] * ex[None, :]) / den
            s = (wx[None, :] * dirs[:, 1:2] - wy[None, :] * dirs[:, 0:1]) / den
        ok = (den != 0.0) & (t > 0.0) & (s >= 0.0) & (s <= 1.0)
        start = np.maximum(start, np.where(ok, t, 0.0).max(axis=1) + LEADER_GAP)
    return start


def _unit(v: XY) -> np.ndarray:
    n = math.hypot(v[0], v[1])
    if not n > 0.0 or not math.isfinite(n):
        raise ValueError(f"a label's avoid direction must be a non-zero vector, got {v!r}")
    return np.array([v[0] / n, v[1] / n])


# ----------------------------------------------------------------------------- placement
class _Placed:
    """What the labels placed so far occupy: boxes (n × 4), leaders (m × 5, as stroke pieces)."""

    def __init__(self, most: int) -> None:
        self._boxes = np.zeros((most, 4))
        self._leaders = np.zeros((most, 5))
        self.n = self.m = 0

    @property
    def boxes(self) -> np.ndarray:
        return self._boxes[: self.n]

    @property
    def leaders(self) -> np.ndarray:
        return self._leaders[: self.m]

    def add(self, p: PlacedLabel, half_width: float) -> None:
        self._boxes[self.n] = p.box
        self.n += 1
        if p.leader is not None:
            (x0, y0), (x1, y1) = p.leader
            self._leaders[self.m] = (x0, y0, x1, y1, half_width)
            self.m += 1


@dataclass
class _Batch:
    """Candidates on some rings, scored: centres, boxes, scores, and their leaders."""

    centres: np.ndarray
    boxes: np.ndarray
    score: np.ndarray
    lead: np.ndarray
    p0: np.ndarray
    p1: np.ndarray


def _score(
    label: Label,
    gaps: Sequence[float],
    first_ring: int,
    obstacles: Obstacles,
    placed: _Placed,
    anchors: np.ndarray,
    me: int,
    style: Style,
) -> _Batch:
    """The candidates of ``label`` on the rings ``gaps`` (the first of them ``first_ring``)."""
    w, up, down = _extent(label)
    ring_dirs = _DIRECTIONS if first_ring == 0 else _FAR_DIRECTIONS
    m = ring_dirs.shape[0]
    centres = candidate_centres(label, gaps, ring_dirs)
    n = centres.shape[0]
    boxes = np.column_stack([centres[:, 0] - w / 2, centres[:, 1] - (up + down) / 2,
                             centres[:, 0] + w / 2, centres[:, 1] + (up + down) / 2])
    anchor = np.asarray(label.anchor, dtype=float)
    region: Box = (min(float(boxes[:, 0].min()), anchor[0]), min(float(boxes[:, 1].min()), anchor[1]),
                   max(float(boxes[:, 2].max()), anchor[0]), max(float(boxes[:, 3].max()), anchor[1]))

    def inside(rows: np.ndarray, x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
        keep: np.ndarray = ((np.maximum(rows[:, x0], rows[:, x1]) >= region[0])
                            & (np.minimum(rows[:, x0], rows[:, x1]) <= region[2])
                            & (np.maximum(rows[:, y0], rows[:, y1]) >= region[1])
                            & (np.minimum(rows[:, y0], rows[:, y1]) <= region[3]))
        return keep

    segs, discs, fills = obstacles.near(region)
    pb = placed.boxes[inside(placed.boxes, 0, 1, 2, 3)]
    leaders = placed.leaders[inside(placed.leaders, 0, 1, 2, 3)]
    strokes = np.concatenate([segs, leaders]) if leaders.shape[0] else segs
    others = anchors[inside(anchors, 0, 1, 0, 1) & (np.arange(anchors.shape[0]) != me)]
    score = np.zeros(n)

    # other labels: their boxes and anchors; strokes and leaders
    if pb.shape[0]:
        cl = style.label_clearance
        areas = _overlap_areas(boxes + np.array([-cl, -cl, cl, cl]), pb)
        score += W_OVERLAP * areas.sum(axis=1) + W_OVERLAP_HIT * (areas > 0.0).sum(axis=1)
    length, count = _inside(boxes, strokes)
    score += W_CROSS * length + W_CROSS_HIT * count
    if others.shape[0]:
        covered = ((others[None, :, 0] > boxes[:, None, 0]) & (others[None, :, 0] < boxes[:, None, 2])
                   & (others[None, :, 1] > boxes[:, None, 1]) & (others[None, :, 1] < boxes[:, None, 3]))
        score += W_ANCHOR * covered.sum(axis=1)

    # fills and discs
    for poly in fills:
        lo, hi = poly.min(axis=0), poly.max(axis=0)
        inb = np.nonzero((centres >= lo).all(axis=1) & (centres <= hi).all(axis=1))[0]
        if inb.shape[0]:
            score[inb] += W_FILL * _in_polygon(centres[inb], poly)
    if discs.shape[0]:
        cx = np.clip(discs[None, :, 0], boxes[:, None, 0], boxes[:, None, 2])
        cy = np.clip(discs[None, :, 1], boxes[:, None, 1], boxes[:, None, 3])
        dist = np.hypot(cx - discs[None, :, 0], cy - discs[None, :, 1])
        score += W_DISC * (dist < discs[None, :, 2] + STROKE_CLEARANCE).sum(axis=1)

    # preferences
    dirs = np.tile(ring_dirs, (len(gaps), 1))
    for a in label.avoid:
        score += W_AVOID * np.clip(dirs @ _unit(a), 0.0, None) ** 2
    ring = first_ring + np.repeat(np.arange(len(gaps)), m)
    score += W_RING * ring + W_UPPER_RIGHT * (1.0 - dirs @ _UPPER_RIGHT) / 2.0

    # leaders: from past the anchor's hinge or block to just short of the box
    gap = np.repeat(np.asarray(gaps, dtype=float), m)
    to_centre = centres - anchor
    dist_c = np.hypot(to_centre[:, 0], to_centre[:, 1])
    u = to_centre / dist_c[:, None]
    t1 = dist_c - _support(u, w / 2.0, (up + down) / 2.0) - LEADER_GAP
    t0 = _leader_start(anchor, u, discs, fills)
    lead = (gap > LEADER_FROM) & (t1 - t0 >= LEADER_SHORTEST)
    p0 = anchor + u * t0[:, None]
    p1 = anchor + u * t1[:, None]
    idx = np.nonzero(lead)[0]
    if idx.shape[0]:
        extra = (W_LEADER + W_LEADER_CROSS * _crossings(p0[idx], p1[idx], strokes)
                 + W_LEADER_ALONG * _along(p0[idx], p1[idx], strokes))
        if pb.shape[0]:
            k = pb.shape[0]
            crossed = clip_lengths(np.repeat(pb, idx.shape[0], axis=0),
                            np.tile(np.column_stack([p0[idx], p1[idx]]), (k, 1))).reshape(k, -1) > 1e-9
            extra += W_LEADER_LABEL * crossed.sum(axis=0)
        score[idx] += extra
    return _Batch(centres, boxes, score, lead, p0, p1)


def _place_one(
    label: Label,
    batches: Sequence[tuple[int, Sequence[float]]],
    obstacles: Obstacles,
    placed: _Placed,
    anchors: np.ndarray,
    me: int,
    style: Style,
) -> PlacedLabel:
    """The best candidate of ``label``, the rings tried nearest first: a ring whose least score
    (W_RING per ring, every other term ≥ 0) cannot beat the best found is not looked at."""
    best: tuple[float, _Batch, int] | None = None
    for first_ring, gaps in batches:
        if best is not None and best[0] <= W_RING * first_ring:
            break
        b = _score(label, gaps, first_ring, obstacles, placed, anchors, me, style)
        k = int(np.argmin(b.score))  # first minimum: ties go to candidate order
        if best is None or b.score[k] < best[0]:
            best = (float(b.score[k]), b, k)
    assert best is not None
    _, b, k = best
    row = b.boxes[k]
    box = (float(row[0]), float(row[1]), float(row[2]), float(row[3]))
    centre = (float(b.centres[k, 0]), float(b.centres[k, 1]))
    leader: tuple[XY, XY] | None = None
    if b.lead[k]:
        leader = ((float(b.p0[k, 0]), float(b.p0[k, 1])), (float(b.p1[k, 0]), float(b.p1[k, 1])))
    down = _extent(label)[2]
    return PlacedLabel(label, centre, box, (centre[0], box[1] + down), leader)


def place_labels(
    labels: Sequence[Label],
    segments: Sequence[tuple[XY, XY]] = (),
    discs: Sequence[tuple[XY, float]] = (),
    style: Style = DEFAULT,
    *,
    obstacles: Obstacles | None = None,
    merge: bool = True,
) -> tuple[PlacedLabel, ...]:
    """Place ``labels`` in order, each at its best candidate given those placed before.

    Parameters
    ----------
    labels : sequence of Label
        In placement order: earlier labels get the better spots.
    segments : sequence of (p0, p1)
        Drawn strokes a label should not cross, as hairlines (links, vectors, construction lines).
    discs : sequence of (centre, radius)
        Round symbols a label should not cover (hinges).
    style : Style
        Supplies ``label_gaps`` and ``label_clearance``.
    obstacles : Obstacles, optional
        Everything drawn, with stroke widths and fills (the frontend's); used instead of
        ``segments`` and ``discs``.
    merge : bool
        Merge coincident point names into one label (see the module's notes).

    Returns
    -------
    tuple of PlacedLabel
        One per label drawn — per label given, unless coincident ones were merged — in the
        order of the first label each stands for; same input → same output.
    """
    obs = obstacles if obstacles is not None else Obstacles(segments, (), discs)
    groups = merge_coincident(labels) if merge else [(lab, (lab,)) for lab in labels]
    anchors = np.array([g[0].anchor for g in groups], dtype=float).reshape(-1, 2)
    near = tuple(style.label_gaps)
    batches = [(0, near)] + [(len(near) + k, (g,)) for k, g in enumerate(g for g in FAR_GAPS if g > max(near))]
    placed = _Placed(len(groups))
    pen = style.pen("label").width / 2.0
    out: list[PlacedLabel] = []
    for i, (label, sources) in enumerate(groups):
        p = replace(_place_one(label, batches, obs, placed, anchors, i, style), sources=sources)
        placed.add(p, pen)
        out.append(p)
    return tuple(out)


def boxes_overlap(a: Box, b: Box) -> float:
    """Intersection area of two boxes, mm² (0 when they only touch or are apart).

    >>> boxes_overlap((0, 0, 2, 2), (1, 1, 3, 3))
    1.0
    """
    ix = min(a[2], b[2]) - max(a[0], b[0])
    iy = min(a[3], b[3]) - max(a[1], b[1])
    return float(max(ix, 0.0) * max(iy, 0.0))
