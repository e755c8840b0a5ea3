"""Backend-neutral draw primitives.

A method's construction is turned into these by a kind's figures
(``graphmech/problems/<kind>/figures.py``); the frontend (:mod:`graphmech.render.sheet`) lays
them out and a backend (SVG, recording) turns them into output. Coordinates are **drawing
millimetres, y up**, in the coordinate frame of the panel that holds them (a panel is one figure
on the sheet: the mechanism at μl, the velocity polygon at μv, …). Flipping y for SVG is the
backend's business.

Roles
-----
``given``         data of the problem (the mechanism's links, frame, known vectors)
``construction``  thin construction lines (perpendiculars, laid-off components)
``result``        what the construction finds (bold)
``label``         letters and notes
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal, Union

from graphmech.drawing.lettering import LETTER

Role = Literal["given", "construction", "result", "label"]
XY = tuple[float, float]


@dataclass(frozen=True)
class Segment:
    """A straight line; ``dashed`` for other positions and hidden or redundant members,
    ``dashdot`` for centre lines (FIGURES.md, GB/T 4457.4 line types)."""

    p0: XY
    p1: XY
    role: Role = "given"
    dashed: bool = False
    dashdot: bool = False


@dataclass(frozen=True)
class Arrow:
    """A vector p0 → p1 with a filled arrowhead (a small polygon, never an SVG marker) at p1."""

    p0: XY
    p1: XY
    role: Role = "result"


@dataclass(frozen=True)
class ArcArrow:
    """A curved arrow: the sense of an angular velocity or acceleration (ω₁ at a crank's pivot).

    The arc runs from angle ``start`` (rad, CCW from +x) through ``sweep`` (rad; negative
    for clockwise) about ``center`` at radius ``r``, with its head at the end.
    """

    center: XY
    r: float
    start: float
    sweep: float
    role: Role = "given"

    def points(self, n: int = 16) -> tuple[XY, ...]:
        import math

        return tuple((self.center[0] + self.r * math.cos(self.start + self.sweep * k / n),
                      self.center[1] + self.r * math.sin(self.start + self.sweep * k / n)) for k in range(n + 1))


@dataclass(frozen=True)
class Polyline:
    """A stroke through ``points`` (a cam's pitch curve and working profile, a diagram's curve
    drawn from dense evaluation); ``closed`` joins the last point to the first. Never filled.

    The points are kept as a tuple of float pairs (an ``(n, 2)`` array may be passed); at least
    two, all finite.

    >>> Polyline(((0, 0), (10, 0), (10, 5))).points[-1]
    (10.0, 5.0)
    """

    points: tuple[XY, ...]
    role: Role = "result"
    closed: bool = False
    dashed: bool = False
    dashdot: bool = False

    def __post_init__(self) -> None:
        import math

        pts = tuple((float(p[0]), float(p[1])) for p in self.points)
        if len(pts) < 2:
            raise ValueError(f"a polyline needs at least two points, got {len(pts)}")
        if not all(math.isfinite(v) for p in pts for v in p):
            raise ValueError("a polyline's points must be finite")
        object.__setattr__(self, "points", pts)


def clip_interval(a: XY, b: XY, box: tuple[float, float, float, float]) -> tuple[float, float] | None:
    """The part (t0, t1) of the segment a + t·(b − a), 0 ≤ t ≤ 1, inside ``box`` = (x0, y0, x1, y1)
    (Liang–Barsky); None when no stretch of it is (a point on an edge is none).

    >>> clip_interval((-1.0, 0.5), (3.0, 0.5), (0.0, 0.0, 1.0, 1.0))
    (0.25, 0.5)
    """
    x0, y0, x1, y1 = box
    dx, dy = b[0] - a[0], b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a[0] - x0), (dx, x1 - a[0]), (-dy, a[1] - y0), (dy, y1 - a[1])):
        if p == 0.0:
            if q < 0.0:
                return None
            continue
        t = q / p
        if p < 0.0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    return (t0, t1) if t0 < t1 else None


def angle_arc(at: XY, d1: XY, d2: XY, r: float, role: Role = "label") -> Polyline | None:
    """The arc of radius ``r`` (mm) about ``at`` marking the smaller angle between directions
    ``d1`` and ``d2``: chords of about 0.5 mm, at most ``ARC_MOST`` of them (a drawing at a stated
    μl may be kilometres wide); None when the arc would be shorter than 0.3 mm.

    >>> len(angle_arc((0, 0), (1, 0), (0, 1), 1e15).points) == ARC_MOST + 1
    True
    """
    import math

    a1, a2 = math.atan2(d1[1], d1[0]), math.atan2(d2[1], d2[0])
    sweep = (a2 - a1 + math.pi) % math.tau - math.pi
    if abs(sweep) * r < 0.3:
        return None
    n = min(ARC_MOST, max(4, int(abs(sweep) * r / 0.5)))
    return Polyline(tuple((at[0] + r * math.cos(a1 + sweep * k / n), at[1] + r * math.sin(a1 + sweep * k / n))
                          for k in range(n + 1)), role)


def angle_mark(at: XY, d1: XY, d2: XY, r: float, text: str) -> list["Primitive"]:
    """An angle's arc and its letter (θ, ψ, γ, α), set outside the arc on the bisector, off both arms."""
    import math

    arc = angle_arc(at, d1, d2, r)
    if arc is None:
        return [Label(text, at, (d1, d2), LETTER)]
    mid = arc.points[len(arc.points) // 2]
    n = math.dist(at, mid)
    out = ((mid[0] - at[0]) / n, (mid[1] - at[1]) / n)
    return [arc, Label(text, (mid[0] + 1.5 * out[0], mid[1] + 1.5 * out[1]), ((-out[0], -out[1]), d1, d2), LETTER)]


#: The most chords of an angle's arc (0.5 mm each up to an arc of 360 mm).
ARC_MOST = 720


def arc_through(centre: XY, points: tuple[XY, ...], margin: float = 0.12, margin_mm: float | None = None,
                role: Role = "construction") -> Polyline:
    """The arc about ``centre`` through ``points`` (on one circle; the first sets the radius),
    ``margin`` radians (or ``margin_mm`` along the arc) past the first and the last: a compass arc,
    or a huge circle's stretch that the drawing needs (the whole would run far off the sheet).

    >>> len(arc_through((0.0, 0.0), ((1.0, 0.0), (0.0, 1.0))).points)
    41
    """
    import math

    r = math.hypot(points[0][0] - centre[0], points[0][1] - centre[1])
    a = [math.atan2(q[1] - centre[1], q[0] - centre[0]) for q in points]
    a = [a[0] + math.remainder(x - a[0], math.tau) for x in a]
    if margin_mm is not None and r > 0.0:
        margin = margin_mm / r
    lo, hi = min(a) - margin, max(a) + margin
    return Polyline(tuple((centre[0] + r * math.cos(lo + (hi - lo) * k / 40),
                           centre[1] + r * math.sin(lo + (hi - lo) * k / 40)) for k in range(41)), role)


@dataclass(frozen=True)
class Circle:
    """A circle; ``dashdot`` for a centre circle (a cam's base or offset circle, a gear's
    pitch circle), ``dashed`` for one of another position."""

    center: XY
    r: float
    role: Role = "construction"
    dashed: bool = False
    dashdot: bool = False


@dataclass(frozen=True)
class Plate:
    """A link with three or more joints drawn as a filled polygon (a ternary link's
    triangle), outlined with the given pen; its joints' hinges are drawn on top. Its number is
    drawn with it, in one group: the plate is the number's own ground, not a stroke it crosses."""

    points: tuple[XY, ...]
    role: Role = "given"
    #: The link's number, written inside the plate at ``number_at`` (its vertices' centroid
    #: when None) in ``number_size`` mm, as the book numbers a ternary link.
    number: str = ""
    number_at: XY | None = None
    number_size: float = LETTER


@dataclass(frozen=True)
class Hinge:
    """A revolute joint: small open circle of fixed paper size (radius in mm)."""

    center: XY
    r: float = 1.2


@dataclass(frozen=True)
class FixedPivot:
    """A frame pivot: hinge on a small triangle standing on a hatched ground line. ``base`` is
    the unit direction from the hinge to its ground line: below (0, −1) as the book draws it;
    None lets the renderer choose a side no link of the panel runs through."""

    center: XY
    base: XY | None = None


@dataclass(frozen=True)
class Slider:
    """A slider block (rectangle) centred on ``center``, its long side along ``angle`` (rad)."""

    center: XY
    angle: float
    length: float = 8.0
    width: float = 5.0


@dataclass(frozen=True)
class GuideLine:
    """A fixed guide from p0 to p1 with ground hatching on its right side (seen p0→p1)."""

    p0: XY
    p1: XY


@dataclass(frozen=True)
class Label:
    """A letter or short note at ``anchor``; the backend places it so labels do not overlap.

    ``avoid`` lists directions (unit vectors) along which lines leave the anchor, so the
    label prefers the widest free sector.
    """

    text: str
    anchor: XY
    avoid: tuple[XY, ...] = ()
    size: float = LETTER  # font size, mm
    italic: bool = True


@dataclass(frozen=True)
class Text:
    """Text set exactly at ``at`` — a table's cell, a box's inscription — where no placement moves
    it: ``at`` is the middle of the line's height and, as ``anchor`` says, its start, middle or end.
    The figure that sets it keeps it clear of its own lines."""

    text: str
    at: XY
    size: float = LETTER  # font size, mm
    anchor: Literal["start", "middle", "end"] = "middle"
    italic: bool = False


Primitive = Union[Segment, Arrow, ArcArrow, Polyline, Circle, Plate, Hinge, FixedPivot, Slider, GuideLine,
                  Label, Text]


@dataclass(frozen=True)
class Panel:
    """One figure of the sheet, with its own scale; ``notes`` are printed under its title."""

    name: str
    title: str
    items: tuple[Primitive, ...]
    notes: tuple[str, ...] = ()  # e.g. ("μl = 0.002 m/mm",)
    row: int | None = None  # panels with the same row stand in one line; None: fill rows greedily
    #: The panel's scales that measure its paper, as (symbol, SI per mm) — keys of
    #: graphmech.scales.SCALE_INFO: each gets a graphic scale bar under the caption, so a
    #: figure shrunk into a report stays measurable.
    scales: tuple[tuple[str, float], ...] = ()


@dataclass(frozen=True)
class TitleBlock:
    """The title block of a course-project sheet (``[page.title_block]``): the scene's strings,
    drawn as they are, lettered in ``notation``; an empty title is the sheet's."""

    title: str = ""
    name: str = ""
    group: str = ""
    date: str = ""
    sheet: str = ""
    notation: str = "en"


@dataclass(frozen=True)
class Sheet:
    """A whole drawing: a title and panels laid out side by side on a page (size in mm).

    ``fit``: the page is cropped to the laid-out content with a margin (``page`` is then only
    the working area the scales were chosen for); ``title_block``: drawn at the lower right.
    """

    title: str
    panels: tuple[Panel, ...]
    page: tuple[float, float] = (297.0, 210.0)
    footer: tuple[str, ...] = field(default=())
    fit: bool = False
    title_block: TitleBlock | None = None
