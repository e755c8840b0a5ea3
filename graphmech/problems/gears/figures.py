"""The figures of involute gears: a few teeth, the meshing with its line of action, the contact
zones on B₁B₂, the measurement over span and pins, the root circle against the base circle.

The constructions are :mod:`graphmech.methods.involute`'s and :mod:`graphmech.methods.gear_meshing`'s
(metres, about their own origins); this module only lays them off at the panels' μ and letters
them. No circle is drawn whole when it is larger than the panel's window: every circle is cut to
the window the panel shows (z = 1000 draws a few teeth on arcs of a 4 m circle, nothing more).

tooth (at μ "tooth")
    the drawn teeth (bold), the reference and base circles thin dash-dot, tip and root circles
    thin, all as arcs over the teeth shown; one flank constructed by points (the strings N_iK_i
    thin, N_i and K_i small, numbered 0, 1, 2 …); p, s, e on the reference circle, s_a, h_a,
    h_f; ρ and ρ_a as the segments NK; α_k at a stated radius; the pointed tip; "undercut".
meshing (at μ "l")
    O₁, O₂, the working pitch circles through P (dash-dot), the base and tip circles (thin; arcs
    near the line of action when the gears are large), N₁N₂ thin, B₁B₂ bold, P, B₁, B₂, N₁, N₂,
    α′ at P against the common tangent, ω₁ clockwise and ω₂; a ring's rim; a rack's lines.
zones (at μ "zones")
    B₁B₂ laid off large (孙桓 Fig. 5-19), the points at p_b from each end, the double-contact
    zones hatched at both ends and the single-contact zone between, dimensioned; ε < 1: the gap.
measurement (at μ "l", the whole gear's scale)
    the caliper over k teeth (its jaws, W_k dimensioned); the pins with M dimensioned.
root_base
    r_f/m and r_b/m against z, two straight lines crossing where the root circle is the base circle.

Every size fixed here is paper millimetres.
"""
from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from itertools import pairwise

from graphmech.drawing.lettering import LETTER, number, scale_text, text_box_size
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (
    ArcArrow,
    Arrow,
    Circle,
    Hinge,
    Label,
    Panel,
    Polyline,
    Primitive,
    Role,
    Segment,
    Sheet,
    Text,
    angle_arc,
    clip_interval,
)
from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear import GearSet, SpurGear
from graphmech.methods.gear_meshing import MeshConstruction
from graphmech.methods.involute import (
    AtRadius,
    Flank,
    PinMeasurement,
    SpanMeasurement,
    ToothOutline,
    circles,
)
from graphmech.scales import round_scale

XY = tuple[float, float]
Box = tuple[float, float, float, float]  # xmin, ymin, xmax, ymax (mm)

#: The panels a gear sheet can show, in this order.
PANELS = ("tooth", "meshing", "zones", "measurement", "root_base", "generation", "helix")  # helix: helix_figure.py

#: The gear sheet's words (graphmech.drawing.notation's shape): key → (English, 中文 (孙桓), русский).
WORDS: dict[str, tuple[str, str, str]] = {
    "tooth": ("Involute teeth", "渐开线齿廓", "Эвольвентные зубья"),
    "gear": (", gear «n»", "，齿轮 «n»", ", колесо «n»"),
    "meshing": ("Meshing: the line of action N_{1}N_{2}", "啮合图：啮合线 N_{1}N_{2}",
                "Картина зацепления: линия зацепления N_{1}N_{2}"),
    "zones": ("Contact zones on B_{1}B_{2}", "实际啮合线 B_{1}B_{2} 上的单、双齿啮合区",
              "Зоны зацепления на B_{1}B_{2}"),
    "measurement": ("Span measurement W_{k}", "公法线长度 W_{k}", "Длина общей нормали W_{k}"),
    "pins": ("Dimension over pins M", "跨棒距 M", "Размер по роликам M"),
    "root_base": ("Root circle and base circle against z", "齿根圆与基圆随齿数 z 的变化",
                  "Окружность впадин и основная окружность в зависимости от z"),
    "two pairs": ("two pairs", "两对齿啮合区", "двухпарное зацепление"),
    "one pair": ("one pair", "单对齿啮合区", "однопарное зацепление"),
    "not continuous": ("ε_{α} < 1: not continuous", "ε_{α} < 1：不能连续传动", "ε_{α} < 1: зацепление прерывается"),
    "gap": ("gap", "间断", "разрыв"),
    "three pairs": ("ε_{α} ≥ 2: at least two pairs always in contact", "ε_{α} ≥ 2：始终至少有两对齿啮合",
                    "ε_{α} ≥ 2: в зацеплении всегда не менее двух пар"),
    "undercut": ("undercut", "根切", "подрез"),
    "pointed": ("pointed tip", "齿顶变尖", "заострение"),
    "alpha_w": ("α′", "α′", "α_{w}"),
    "rack": ("rack", "齿条", "рейка"),
    "interference": ("interference", "干涉", "интерференция"),
    "not to scale": ("M not to scale: the gear is larger than the panel", "M 未按比例：齿轮大于图幅",
                     "M не в масштабе: колесо больше поля"),
    "root=base": ("r_{f} = r_{b} at z = «z»", "z = «z» 时 r_{f} = r_{b}", "r_{f} = r_{b} при z = «z»"),
}

#: Chords of a drawn arc, mm; the most chords of one arc.
CHORD, ARC_MOST = 0.5, 4000
#: Margin of a panel's window around what it must show, mm.
MARGIN = 8.0
#: A meshing panel draws whole gears while they fit this square, mm; else a window on N₁N₂.
WHOLE_MOST = 400.0
#: Dimension lines: the arrow's length, the offsets of arc dimensions outside the tip circle, mm.
ARROW, DIM_IN, DIM_OUT = 2.5, 4.0, 11.0
#: A point K_i / N_i of the construction by points (a small dot), mm.
DOT = 0.35
#: Least distance between two numbers of the construction by points, mm.
NUMBER_GAP = 4.5
#: The zone band's height above B₁B₂ and its hatching's spacing; dimension rows below, mm.
BAND, HATCH = 4.0, 1.5
DIM_ROWS = (-11.0, -19.0, -27.0, -35.0)
#: The most teeth a whole gear is drawn with (a larger one: the teeth about its pins, and its
#: tip and root circles).
WHOLE_TEETH_MOST = 200
#: The most teeth a span panel draws whole; a longer span draws the two teeth at each end.
SPAN_TEETH_MOST = 12
#: The root–base diagram's width, mm.
DIAGRAM_W = 75.0


@dataclass(frozen=True)
class GearDrawing:
    """What a gear sheet draws: the model, the scales (m/mm: ``"l"`` the meshing panel or a single
    gear's whole view and the measurement panels, ``"tooth"`` the tooth panel, ``"zones"`` the enlarged
    B₁B₂), and the constructions, each tagged with its gear's name ("" for a single gear, "1"
    or "2" in a pair). ``root_base``: (z at which the root circle equals the base circle, the
    gear's own z or 0)."""

    gears: GearSet
    scales: dict[str, float]
    teeth: tuple[tuple[str, ToothOutline], ...] = ()
    at_radii: tuple[tuple[str, AtRadius], ...] = ()
    pointed: tuple[tuple[str, AtRadius], ...] = ()
    span: tuple[tuple[str, SpanMeasurement], ...] = ()
    pins: tuple[tuple[str, PinMeasurement], ...] = ()
    mesh: MeshConstruction | None = None
    root_base: tuple[float, float] | None = None
    #: the meshing panel shows the whole gears (False: a window about B₁B₂ — a large pair's, whose
    #: μl the check chose for the line of action)
    mesh_whole: bool = True
    #: the generation by the rack cutter, its panel built by problems/gears/generation.py
    generation: Panel | None = None


# ----------------------------------------------------------------------------- geometry on paper
def paper_label(text: str, at: XY, avoid: Sequence[XY] = (), size: float = LETTER, italic: bool = True) -> Label:
    """A label avoiding the given directions (made unit; a zero one, a degenerate line, dropped)."""
    dirs = tuple(_unit(d) for d in avoid if math.hypot(d[0], d[1]) > 1e-12)
    return Label(text, at, dirs, size, italic)


def mm_text(x: float) -> str:
    """A length in mm as gear drawings give it: to 0.01 mm (101.97 mm, not 102), at least four
    significant figures for a small one."""
    v = x * 1e3
    sig = max(4, math.floor(math.log10(abs(v))) + 3) if v != 0.0 and math.isfinite(v) else 4
    return f"{number(v, sig)} mm"


def to_paper(p: XY, mu: float) -> XY:
    return (p[0] / mu, p[1] / mu)


def _sub(p: XY, q: XY) -> XY:
    return (p[0] - q[0], p[1] - q[1])


def _add(p: XY, q: XY, k: float = 1.0) -> XY:
    return (p[0] + k * q[0], p[1] + k * q[1])


def _unit(v: XY) -> XY:
    n = math.hypot(v[0], v[1])
    return (v[0] / n, v[1] / n) if n > 0 else (0.0, 0.0)


def _neg(v: XY) -> XY:
    return (-v[0], -v[1])


def _polar(r: float, a: float, c: XY = (0.0, 0.0)) -> XY:
    return (c[0] + r * math.cos(a), c[1] + r * math.sin(a))


def _angle(p: XY, c: XY = (0.0, 0.0)) -> float:
    return math.atan2(p[1] - c[1], p[0] - c[0])


def _rotate(p: XY, a: float) -> XY:
    ca, sa = math.cos(a), math.sin(a)
    return (ca * p[0] - sa * p[1], sa * p[0] + ca * p[1])


def _box(points: Iterable[XY], grow: float = 0.0) -> Box:
    pts = list(points)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return (min(xs) - grow, min(ys) - grow, max(xs) + grow, max(ys) + grow)


def _inside(p: XY, box: Box, tol: float = 1e-9) -> bool:
    return box[0] - tol <= p[0] <= box[2] + tol and box[1] - tol <= p[1] <= box[3] + tol


def arc_points(c: XY, r: float, a0: float, a1: float) -> tuple[XY, ...]:
    """The arc about ``c`` from angle ``a0`` to ``a1`` (rad) in chords of about :data:`CHORD` mm.

    >>> len(arc_points((0.0, 0.0), 10.0, 0.0, math.pi / 2))
    33
    """
    n = min(ARC_MOST, max(2, math.ceil(abs(a1 - a0) * r / CHORD)))
    return tuple(_polar(r, a0 + (a1 - a0) * k / n, c) for k in range(n + 1))


def circle_in(c: XY, r: float, box: Box) -> list[tuple[float, float]]:
    """The angular intervals (a0 < a1, rad) of the circle (``c``, ``r``) inside ``box``;
    [(0, 2π)] when the whole circle is inside, [] when none of it is.

    >>> circle_in((0.0, 0.0), 1.0, (-2.0, -2.0, 2.0, 2.0)), circle_in((0.0, 0.0), 1e4, (-5.0, -5.0, 5.0, 5.0))
    ([(0.0, 6.283185307179586)], [])
    >>> [(round(a, 4), round(b, 4)) for a, b in circle_in((0.0, 0.0), 1.0, (0.0, -2.0, 2.0, 2.0))]
    [(-1.5708, 1.5708)]
    """
    cuts: list[float] = []
    for k, v in ((0, box[0]), (0, box[2]), (1, box[1]), (1, box[3])):
        d = v - c[k]
        if abs(d) < r:
            h = math.sqrt(r * r - d * d)
            for s in (h, -h):
                cuts.append(math.atan2(s, d) if k == 0 else math.atan2(d, s))
    if not cuts:
        return [(0.0, math.tau)] if _inside(_polar(r, 0.0, c), box) else []
    cuts = sorted(a % math.tau for a in cuts)
    out: list[tuple[float, float]] = []
    for a, b in zip(cuts, cuts[1:] + [cuts[0] + math.tau]):
        if b - a > 1e-12 and _inside(_polar(r, (a + b) / 2.0, c), box):
            if out and abs(out[-1][1] - a) < 1e-12:
                out[-1] = (out[-1][0], b)
            else:
                out.append((a, b))
    if len(out) > 1 and abs(out[-1][1] - math.tau - out[0][0]) < 1e-12:  # joined across 0
        out = [(out[-1][0] - math.tau, out[0][1])] + out[1:-1]
    return [(a - math.tau, b - math.tau) if a >= math.pi else (a, b) for a, b in out]


def clipped_circle(c: XY, r: float, box: Box, role: Role = "construction", dashdot: bool = False,
                   dashed: bool = False) -> list[Primitive]:
    """A circle as much of it as ``box`` shows: a :class:`Circle` when it is wholly inside, else
    its arcs in the box as polylines; nothing when none of it is."""
    runs = circle_in(c, r, box)
    if runs == [(0.0, math.tau)]:
        return [Circle(c, r, role, dashed=dashed, dashdot=dashdot)]
    return [Polyline(arc_points(c, r, a, b), role, dashed=dashed, dashdot=dashdot)
            for a, b in runs if (b - a) * r > CHORD]


def clipped_segment(p0: XY, p1: XY, box: Box) -> tuple[XY, XY] | None:
    """The part of p0p1 inside ``box`` (Liang–Barsky), None when none is."""
    part = clip_interval(p0, p1, box)
    if part is None:
        return None
    d = _sub(p1, p0)
    return _add(p0, d, part[0]), _add(p0, d, part[1])


def dimension(p0: XY, p1: XY, text: str, side: XY | None = None) -> list[Primitive]:
    """A linear dimension between p0 and p1 (arrowheads at both ends, inward; outward when too
    short) and its text beside the middle (on ``side`` if given); nothing for a length of zero
    (an addendum of h*a = 0 has no extent to dimension)."""
    n = math.dist(p0, p1)
    if not n > 0.0:
        return []
    d = _unit(_sub(p1, p0))
    mid = _add(p0, p1)
    mid = (mid[0] / 2.0, mid[1] / 2.0)
    if n >= 2.0 * ARROW + 1.0:
        items: list[Primitive] = [Arrow(mid, p0, "label"), Arrow(mid, p1, "label")]
    else:
        items = [Segment(p0, p1, "label"), Arrow(_add(p0, d, -ARROW - 1.5), p0, "label"),
                 Arrow(_add(p1, d, ARROW + 1.5), p1, "label")]
    avoid = (d, _neg(d)) + ((_neg(side),) if side else ())
    return items + [paper_label(text, mid, avoid, LETTER, italic=False)]


def arc_dimension(c: XY, r: float, a0: float, a1: float, text: str) -> list[Primitive]:
    """An arc dimension about ``c`` at radius ``r`` from a0 to a1 (rad), arrowheads at both
    ends, the text outside the arc's middle."""
    pts = arc_points(c, r, a0, a1)
    items: list[Primitive] = [Polyline(pts, "label")]
    length = abs(a1 - a0) * r
    for end, towards in ((a0, a1), (a1, a0)):
        tip = _polar(r, end, c)
        if length >= 2.0 * ARROW + 1.0:
            back = _polar(r, end + math.copysign(ARROW / r, towards - end), c)
        else:  # too short: the arrows stand outside, pointing in
            back = _polar(r, end - math.copysign((ARROW + 1.5) / r, towards - end), c)
            items.append(Polyline(arc_points(c, r, end, end - math.copysign((ARROW + 1.5) / r, towards - end)),
                                  "label"))
        items.append(Arrow(back, tip, "label"))
    mid = (a0 + a1) / 2.0
    out = (math.cos(mid), math.sin(mid))
    return items + [paper_label(text, _polar(r, mid, c), ((-out[0], -out[1]), (-out[1], out[0]), (out[1], -out[0])),
                          LETTER)]


def hatch_box(x0: float, x1: float, y0: float, y1: float, step: float = HATCH) -> list[Primitive]:
    """45° hatching of the rectangle [x0, x1] × [y0, y1] (thin strokes clipped to it)."""
    items: list[Primitive] = []
    h = y1 - y0
    k = 0
    while True:
        s = x0 - h + k * step  # stroke from (s, y0) to (s + h, y1)
        if s > x1:
            break
        got = clipped_segment((s, y0), (s + h, y1), (x0, y0, x1, y1))
        if got is not None and math.dist(*got) > 0.2:
            items.append(Segment(got[0], got[1], "construction"))
        k += 1
    return items


# ----------------------------------------------------------------------------- teeth
def _gear(gears: GearSet, name: str) -> SpurGear:
    return gears.gears[int(name) - 1] if name else gears.gears[0]


def _sub_name(name: str) -> str:
    return f"_{{{name}}}" if name else ""


def _annulus(t: ToothOutline) -> tuple[float, float]:
    lo, hi = min(t.rf, t.ra), max(t.rf, t.ra)
    return lo * (1.0 - 1e-6), hi * (1.0 + 1e-6)


def outline_runs(t: ToothOutline) -> list[tuple[XY, ...]]:
    """The outline's runs between the root and tip circles (whatever closes the sector — a line
    to O, an inner arc — is left out)."""
    lo, hi = _annulus(t)
    runs: list[list[XY]] = [[]]
    for p in t.outline:
        if lo <= math.hypot(*p) <= hi:
            runs[-1].append(p)
        elif runs[-1]:
            runs.append([])
    return [tuple(r) for r in runs if len(r) >= 2]


def _tooth0(t: ToothOutline) -> int:
    """The index of tooth 0 (centred on +y) among the drawn teeth."""
    def off(k: int) -> float:
        left, right = t.teeth[k]
        pts = left.points + right.points
        return abs(sum(p[0] for p in pts) / max(len(pts), 1))
    return min(range(len(t.teeth)), key=off)


def pitch_piece(t: ToothOutline, z: int) -> tuple[XY, ...]:
    """The outline of one pitch about tooth 0 (polar angles within π/2 ± π/z), in the order of
    the outline, ordered clockwise (decreasing polar angle)."""
    half = math.pi / z
    best: tuple[XY, ...] = ()
    for run in outline_runs(t):
        cur: list[XY] = []
        for p in run + ((math.inf, math.inf),):
            if math.isfinite(p[0]) and abs(_angle(p) - math.pi / 2.0) <= half:
                cur.append(p)
            else:
                if len(cur) > len(best):
                    best = tuple(cur)
                cur = []
    if len(best) >= 2 and _angle(best[0]) < _angle(best[-1]):
        best = best[::-1]
    return best


def replicated(t: ToothOutline, z: int, js: Sequence[int]) -> tuple[XY, ...]:
    """Tooth 0's pitch repeated at j·2π/z for the ``js`` (descending: clockwise), as one line."""
    piece = pitch_piece(t, z)
    out: list[XY] = []
    for j in sorted(js, reverse=True):
        out += [_rotate(p, j * math.tau / z) for p in piece]
    return tuple(out)


def _numbers(points: Sequence[XY]) -> list[int]:
    """Which of the construction's points are numbered: every k-th, k the least that keeps them
    NUMBER_GAP apart (the last always)."""
    n = len(points)
    if n == 0:
        return []
    for k in range(1, n + 1):
        idx = list(range(0, n, k))
        if all(math.dist(points[a], points[b]) >= NUMBER_GAP for a, b in pairwise(idx)):
            return idx
    return [0]


def _at(items: Sequence[tuple[str, AtRadius]] | Sequence[AtRadius], name: str, r: float) -> AtRadius | None:
    """The construction at radius ``r`` of gear ``name`` (items tagged with names or, "" asked, plain)."""
    for it in items:
        n, a = it if isinstance(it, tuple) else ("", it)
        if n == name and abs(a.r_k - r) <= 1e-9 * max(r, 1.0):
            return a
    return None


def _tooth_angle(flanks: tuple[Flank, Flank]) -> float:
    """The polar angle of a drawn tooth's middle (between its flanks' starts)."""
    a, b = _angle(flanks[0].start), _angle(flanks[1].start)
    return (a + b) / 2.0


def _turned(a: AtRadius, turn: float) -> AtRadius:
    """The construction at r_k turned about O by ``turn`` (onto another tooth: drawing only)."""
    return replace(a, K_left=_rotate(a.K_left, turn), K_right=_rotate(a.K_right, turn),
                   N_left=_rotate(a.N_left, turn), N_right=_rotate(a.N_right, turn))


def tooth_items(drawing: GearDrawing, name: str, t: ToothOutline, notation: str = "en") -> list[Primitive]:
    """A gear's teeth at μ "tooth", about O at the origin (off the panel unless the gear is small)."""
    mu = drawing.scales["tooth"]
    gear = _gear(drawing.gears, name)
    z = gear.z
    runs = [tuple(to_paper(p, mu) for p in r) for r in outline_runs(t)]
    i0 = _tooth0(t)
    right = t.teeth[i0][1]
    step = math.tau / z
    # the construction by points on the left flank of the rightmost tooth drawn (its strings run
    # off to the right), ρ and α_k on the right flank of the leftmost (theirs run off to the
    # left), the dimensions p, s, e, s_a, h_a, h_f on tooth 0 between them
    centres = [_tooth_angle(f) for f in t.teeth]
    i_right, i_left = min(range(len(t.teeth)), key=lambda i: centres[i]), max(range(len(t.teeth)),
                                                                                key=lambda i: centres[i])
    turn = round((centres[i_left] - math.pi / 2.0) / step) * step  # tooth 0 → the leftmost
    mine = [_turned(a, turn) for n, a in drawing.at_radii if n == name]
    pointed = [a for n, a in drawing.pointed if n == name]
    # (a ring's flanks are the other way round: its left flank's strings run off to the left)
    strings = [(to_paper(n_, mu), to_paper(k, mu)) for n_, k in t.teeth[i_right][int(gear.internal)].strings]
    flank = "left" if gear.internal else "right"  # the flank of the leftmost tooth carrying ρ and α_k
    teeth_box = _box([p for r in runs for p in r] + [to_paper(p, mu) for a in mine + pointed for p in (a.K_left, a.K_right)],
                     MARGIN)
    # the strings' ends N on the base circle too, unless they lie far off (a large gear's strings
    # are long: then they run out of the window towards N)
    ns_all = [n_ for n_, _ in strings] + [to_paper(_nk(a, flank)[0], mu) for a in mine]
    wide = _box([(teeth_box[0], teeth_box[1]), (teeth_box[2], teeth_box[3])] + ns_all, 0.0)
    w0, h0 = teeth_box[2] - teeth_box[0], teeth_box[3] - teeth_box[1]
    fits = wide[2] - wide[0] <= max(1.6 * w0, w0 + 60.0) and wide[3] - wide[1] <= max(1.6 * h0, h0 + 60.0)
    window = _box([(wide[0], wide[1]), (wide[2], wide[3])], MARGIN if fits else 0.0) if fits else teeth_box
    O = (0.0, 0.0)
    items: list[Primitive] = []
    labels: list[Primitive] = []
    # the circles: reference and base dash-dot, tip and root thin, as arcs over the window
    for r, dashdot in ((t.r, True), (t.rb, True), (t.ra, False), (t.rf, False)):
        items += clipped_circle(O, r / mu, window, "construction", dashdot=dashdot)
    if _inside(O, window):
        items.append(Hinge(O))
        labels.append(paper_label("O", O, ((0.0, 1.0),), LETTER))
    # the tooth axis of tooth 0, dash-dot, from the root circle past the tip
    r_lo, r_hi = min(t.rf, t.ra) / mu, max(t.rf, t.ra) / mu
    items.append(Segment((0.0, r_lo - 3.0), (0.0, r_hi + 3.0), "construction", dashdot=True))
    items += [Polyline(r, "result") for r in runs]
    # the right flank of tooth 0 by points: strings N_iK_i, the points, numbered
    for (n_, k) in strings:
        seg = clipped_segment(n_, k, window)
        if seg is not None:
            items.append(Segment(seg[0], seg[1], "construction"))
    ks = [k for _, k in strings]
    for n_, k in strings:
        items += [Circle(q, DOT, "result") for q in (n_, k) if _inside(q, window)]
    for i in _numbers(ks):  # K_i numbered i′, N_i (when in the window) i
        n_, k = strings[i]
        labels.append(paper_label(f"{i}′", k, (_sub(n_, k),), LETTER * 0.8, italic=False))
    on_base = [i for i, (n_, _) in enumerate(strings) if _inside(n_, window)]
    for j in _numbers([strings[i][0] for i in on_base]):
        n_, k = strings[on_base[j]]
        labels.append(paper_label(str(on_base[j]), n_, (_sub(k, n_), n_), LETTER * 0.8, italic=False))
    # p, s, e on the reference circle; s_a over the tip
    ref, tip = _at(drawing.at_radii, name, t.r), _at(drawing.at_radii, name, t.ra)
    ref_l, tip_l = _at(mine, "", t.r), _at(mine, "", t.ra)
    outer = max(t.ra, t.rf) / mu
    if ref is not None:
        aL, aR = _angle(ref.K_left), _angle(ref.K_right)
        items += arc_dimension(O, t.r / mu, aR, aL, "s")
        items += arc_dimension(O, t.r / mu, aL - step, aR, "e")  # to the left flank of the next tooth
        # p from tooth 0's right flank to its right neighbour's, outside the teeth
        rp = outer + DIM_OUT
        for a in (aR, aR - step):
            items.append(Segment(_polar(t.r / mu, a), _polar(rp + 1.5, a), "label"))
        items += arc_dimension(O, rp, aR - step, aR, "p")
        # ρ at the reference circle: N K on the left flank
        if ref_l is not None:
            items += _rho("ρ", ref_l, flank, mu, window)
    if tip is not None and tip.s_k > 0.0:  # a pointed tooth has no s_a
        aL, aR = _angle(tip.K_left), _angle(tip.K_right)
        ra = outer + DIM_IN
        for a in (aL, aR):
            items.append(Segment(_polar(t.ra / mu, a), _polar(ra + 1.5, a), "label"))
        items += arc_dimension(O, ra, aR, aL, "s_{a}")
        if tip_l is not None:
            items += _rho("ρ_{a}", tip_l, flank, mu, window)
    # h_a and h_f radially in the space left of tooth 0
    a_sp = math.pi / 2.0 + step / 2.0
    sgn = -1.0 if gear.internal else 1.0  # a ring's tip is inside its reference circle
    ha_end, hf_end = _polar(t.ra / mu, a_sp), _polar(t.rf / mu, a_sp)
    at_r = _polar(t.r / mu, a_sp)
    side = (-math.sin(a_sp) * sgn, math.cos(a_sp) * sgn)
    items += dimension(at_r, ha_end, "h_{a}", side) + dimension(hf_end, at_r, "h_{f}", side)
    # α_k at the other stated radii: at K between the normal NK and the velocity ⟂ OK
    for ak in mine:
        if ak is ref_l or ak is tip_l or abs(ak.r_k - t.rb) <= 1e-9 * t.rb:
            continue
        items += _alpha_k(ak, flank, mu)
    for pt in pointed:  # the flanks meet at K: the tip circle may not pass this radius
        k = to_paper(pt.K_left, mu)
        items += clipped_circle(O, pt.r_k / mu, window, "construction", dashed=True)
        items.append(Circle(k, 2.0 * DOT, "result"))
        labels.append(paper_label(f"{word('pointed', notation, WORDS)}: r = {mm_text(pt.r_k)}", k, ((0.0, -1.0),), LETTER,
                             italic=False))
    if t.undercut:
        at = to_paper(right.points[0], mu) if right.points else _polar(t.rb / mu, math.pi / 2.0)
        labels.append(paper_label(word("undercut", notation, WORDS), at, ((0.0, 1.0), (-1.0, 0.0)), LETTER, italic=False))
    return items + labels


def _nk(a: AtRadius, flank: str) -> tuple[XY, XY]:
    """N and K of the construction at r_k on its ``flank`` ("left" or "right"), m."""
    return (a.N_left, a.K_left) if flank == "left" else (a.N_right, a.K_right)


def _rho(text: str, a: AtRadius, flank: str, mu: float, window: Box) -> list[Primitive]:
    """ρ at r_k: the segment N K of ``flank`` (as much as the window shows), labelled."""
    n_, k = _nk(a, flank)
    seg = clipped_segment(to_paper(n_, mu), to_paper(k, mu), window)
    if seg is None:
        return []
    d = _sub(seg[1], seg[0])
    return [Segment(seg[0], seg[1], "label"),
            paper_label(text, ((seg[0][0] + seg[1][0]) / 2.0, (seg[0][1] + seg[1][1]) / 2.0), (d, _neg(d)))]


def _alpha_k(a: AtRadius, flank: str, mu: float) -> list[Primitive]:
    """α_k at K on ``flank``: the normal K–N continued past K, the velocity ⟂ OK, the arc."""
    n_, k = (to_paper(q, mu) for q in _nk(a, flank))
    u = _unit(_sub(k, n_))
    ok = _unit(k)
    v = (-ok[1], ok[0])
    if v[0] * u[0] + v[1] * u[1] < 0.0:
        v = _neg(v)
    items: list[Primitive] = [Segment(n_, _add(k, u, 10.0), "label"), Segment(k, _add(k, v, 10.0), "label"),
                              Circle(k, 2.0 * DOT, "result")]
    arc = angle_arc(k, u, v, 7.0)
    if arc is not None:
        items.append(arc)
    mid = _unit(_add(u, v))
    items += [paper_label(f"α_{{k}} = {number(math.degrees(a.alpha_k))}°", _add(k, mid, 8.0), (_neg(mid),), LETTER,
                    italic=False),
              paper_label("K", k, (_neg(u), _neg(v)), LETTER)]
    return items


def tooth_notes(drawing: GearDrawing, name: str, t: ToothOutline) -> tuple[str, ...]:
    g = _gear(drawing.gears, name)
    s = drawing.gears.system
    data = (f"m = {mm_text(s.m)}, z{_sub_name(name)} = {g.z}, α = {number(math.degrees(s.alpha))}°, "
            f"h_{{a}}* = {number(s.ha_star)}, c* = {number(s.c_star)}, x{_sub_name(name)} = {number(g.x)}"
            + (f", Δy = {number(g.delta_y)} (tip shortened)" if g.delta_y else ""))
    vals = [f"r = {mm_text(t.r)}", f"r_{{b}} = {mm_text(t.rb)}", f"r_{{a}} = {mm_text(t.ra)}", f"r_{{f}} = {mm_text(t.rf)}"]
    for n, a in drawing.at_radii:
        if n == name and abs(a.r_k - t.r) > 1e-9 * t.r and abs(a.r_k - t.ra) > 1e-9 * t.ra:
            vals.append(f"r_{{k}} = {mm_text(a.r_k)}: s_{{k}} = {mm_text(a.s_k)}, ρ_{{k}} = {mm_text(a.rho_k)}")
    return (scale_text("l", drawing.scales["tooth"]), data, ", ".join(vals))


# ----------------------------------------------------------------------------- meshing
def _rack_lines(m: MeshConstruction, gears: GearSet) -> tuple[float, float]:
    """The rack's reference line (y = a′) and its tip line (through B₂), m."""
    return m.a_w, m.B2[1]


def _ring_rim(gears: GearSet) -> float:
    """A ring's root radius, m."""
    return circles(gears.system, gears.gears[1])[3]


def meshing_items(drawing: GearDrawing, m: MeshConstruction, notation: str = "en") -> list[Primitive]:
    """The pair in mesh at μ "l" (the construction's frame: O₁ at the origin, P on the y axis)."""
    mu = drawing.scales["l"]
    gears = drawing.gears
    rack = gears.meshing == "rack"
    internal = gears.meshing == "internal"
    O1 = to_paper(m.O1, mu)
    O2 = to_paper(m.O2, mu) if m.O2 is not None else None
    P, N1, B1, B2 = to_paper(m.P, mu), to_paper(m.N1, mu), to_paper(m.B1, mu), to_paper(m.B2, mu)
    N2 = to_paper(m.N2, mu) if m.N2 is not None else None
    rb1, ra1 = math.dist(m.O1, m.N1) / mu, math.dist(m.O1, m.B1) / mu
    drawn: list[tuple[XY, float, bool]] = [(O1, m.r_w1 / mu, True), (O1, rb1, False), (O1, ra1, False)]
    if O2 is not None and m.O2 is not None and m.N2 is not None and m.r_w2 is not None:
        drawn += [(O2, m.r_w2 / mu, True), (O2, math.dist(m.O2, m.N2) / mu, False),
                    (O2, math.dist(m.O2, m.B2) / mu, False)]
        if internal:
            drawn.append((O2, _ring_rim(gears) / mu, False))
    # the window: the whole gears when they fit, else around the line of action
    whole = _box([p for c, r, _ in drawn for p in ((c[0] - r, c[1] - r), (c[0] + r, c[1] + r))], MARGIN)
    if rack:
        y_ref, _ = _rack_lines(m, gears)
        whole = _box([(whole[0], whole[1]), (whole[2], whole[3]), (whole[0], y_ref / mu + 3 * gears.system.m / mu)],
                     0.0)
    if drawing.mesh_whole and whole[2] - whole[0] <= WHOLE_MOST and whole[3] - whole[1] <= WHOLE_MOST:
        window = whole
    else:  # about B₁B₂ and P; N₁, N₂ shown if near, else the line runs out of the window towards them
        core = _box([P, B1, B2])
        grow = max(4.0 * MARGIN, 0.5 * max(core[2] - core[0], core[3] - core[1]))
        window = _box([P, B1, B2], grow)
        near = [q for q in (N1, N2) if q is not None and _inside(q, _box([P, B1, B2], 2.0 * grow))]
        window = _box([(window[0], window[1]), (window[2], window[3])] + near, 0.0 if not near else MARGIN)
    items: list[Primitive] = []
    labels: list[Primitive] = []
    for c, r, dd in drawn:
        items += clipped_circle(c, r, window, "construction", dashdot=dd)
    if internal and O2 is not None:  # the ring's body: its rim, bold, just outside the root circle
        items += clipped_circle(O2, _ring_rim(gears) / mu + 4.0, window, "given")
    if rack:
        y_ref, y_tip = _rack_lines(m, gears)
        for y, dd in ((y_ref / mu, True), (y_tip / mu, False)):
            seg = clipped_segment((window[0], y), (window[2], y), window)
            if seg is not None:
                items.append(Segment(seg[0], seg[1], "construction", dashdot=dd))
        labels.append(paper_label(word("rack", notation, WORDS), (window[0] + 6.0, y_ref / mu), ((0.0, -1.0),), LETTER,
                            italic=False))
    # the centre line O₁O₂ (to the rack's line), dash-dot
    far = O2 if O2 is not None else (0.0, _rack_lines(m, gears)[0] / mu + 5.0)
    seg = clipped_segment(O1, far, window)
    if seg is not None:
        items.append(Segment(seg[0], seg[1], "construction", dashdot=True))
    # the line of action N₁N₂ thin, B₁B₂ bold; a rack's runs on past B₂ to its reference line
    u = _unit(_sub(P, N1))
    far_end = N2 if N2 is not None else _add(P, u, max(math.dist(P, B1), 10.0) + 6.0)
    seg = clipped_segment(N1, far_end, window)
    if seg is not None:
        items.append(Segment(seg[0], seg[1], "label"))
    items.append(Segment(B2, B1, "result"))
    # the common tangent at P and α′ against it
    t = (1.0, 0.0) if u[0] >= 0.0 else (-1.0, 0.0)
    tl = 18.0
    items.append(Segment(_add(P, t, -tl), _add(P, t, tl), "label"))
    arc = angle_arc(P, t, u, 10.0)
    if arc is not None:
        items.append(arc)
        mid = _unit(_add(t, u))
        labels.append(paper_label(word("alpha_w", notation, WORDS), _add(P, mid, 12.0), (_neg(mid),), LETTER))
    # points
    for name, p in (("O_{1}", O1), ("O_{2}", O2)):
        if p is not None and _inside(p, window):
            items.append(Hinge(p))
            labels.append(paper_label(name, p, ((0.0, 1.0), (0.0, -1.0)), LETTER))
    for name, p in (("P", P), ("N_{1}", N1), ("N_{2}", N2), ("B_{1}", B1), ("B_{2}", B2)):
        if p is not None and _inside(p, window):
            items.append(Circle(p, 2.0 * DOT, "result"))
            labels.append(paper_label(name, p, (u, _neg(u)), LETTER))
    # senses: ω₁ clockwise about O₁; ω₂ counter-clockwise (external), clockwise (ring), v₂ (rack)
    if _inside(O1, window):
        r_arc = min(10.0, 0.5 * rb1)
        w1 = ArcArrow(O1, r_arc, math.radians(-40.0), math.radians(-80.0), "given")
        items.append(w1)
        labels.append(paper_label("ω_{1}", w1.points(2)[1], ((0.0, 1.0),), LETTER))
    if O2 is not None and _inside(O2, window) and m.N2 is not None and m.O2 is not None:
        r_arc = min(10.0, 0.5 * math.dist(m.O2, m.N2) / mu)
        sweep = math.radians(-80.0) if internal else math.radians(80.0)
        w2 = ArcArrow(O2, r_arc, math.radians(220.0 if not internal else 140.0), sweep, "given")
        items.append(w2)
        labels.append(paper_label("ω_{2}", w2.points(2)[1], ((0.0, -1.0),), LETTER))
    if rack:
        y_ref = _rack_lines(m, gears)[0] / mu
        a0 = (P[0] + 10.0, y_ref + 6.0)
        items.append(Arrow(a0, _add(a0, (12.0, 0.0)), "given"))
        labels.append(paper_label("v_{2}", _add(a0, (6.0, 0.0)), ((0.0, -1.0),), LETTER))
    return items + labels


def meshing_notes(drawing: GearDrawing, m: MeshConstruction, notation: str = "en") -> tuple[str, ...]:
    g = drawing.gears
    s = g.system
    zs = ", ".join(f"z_{{{k + 1}}} = {x.z}" for k, x in enumerate(g.gears))
    line = (f"m = {mm_text(s.m)}, {zs}, α = {number(math.degrees(s.alpha))}°; a′ = {mm_text(m.a_w)}, "
            f"α′ = {number(math.degrees(m.alpha_w))}°")
    line2 = f"B_{{1}}B_{{2}} = {mm_text(m.B1B2)}, p_{{b}} = {mm_text(m.pb)}, ε_{{α}} = {number(m.eps_alpha)}"
    notes = [scale_text("l", drawing.scales["l"]), line, line2]
    if any(x.x for x in g.gears):  # a shifted pair: its shifts and the tips' shortening
        xs = ", ".join(f"x_{{{k + 1}}} = {number(x.x)}" for k, x in enumerate(g.gears))
        dy = g.gears[0].delta_y
        notes.insert(2, xs + (f", Δy = {number(dy)}" if dy else ""))
    if m.interference:
        notes.append(f"{word('interference', notation, WORDS)}: {', '.join(m.interference)}")
    return tuple(notes)


# ----------------------------------------------------------------------------- zones
def zones_items(drawing: GearDrawing, m: MeshConstruction, notation: str = "en") -> list[Primitive]:
    """B₁B₂ laid off along x at μ "zones" (B₂, where contact begins, at the left)."""
    mu = drawing.scales["zones"]
    u = _unit(_sub(m.B1, m.B2))

    def x_of(p: XY) -> float:
        d = _sub(p, m.B2)
        return (d[0] * u[0] + d[1] * u[1]) / mu

    L, pb = m.B1B2 / mu, m.pb / mu
    xP = x_of(m.P)
    items: list[Primitive] = []
    labels: list[Primitive] = []
    ends = [0.0, L, xP]
    named = [("B_{2}", 0.0), ("B_{1}", L), ("P", xP)]
    for name, p in (("N_{1}", m.N1), ("N_{2}", m.N2)):
        if p is not None and -30.0 <= x_of(p) <= L + 30.0:
            named.append((name, x_of(p)))
            ends.append(x_of(p))
    lo, hi = min(ends + [0.0]) - 6.0, max(ends + [L, pb]) + 6.0
    items.append(Segment((lo, 0.0), (hi, 0.0), "label"))
    items.append(Segment((0.0, 0.0), (L, 0.0), "result"))
    for name, x in named:
        items.append(Segment((x, -1.5), (x, 1.5), "label"))
        labels.append(paper_label(name, (x, 0.0), ((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0)), LETTER))
    zx = sorted(x_of(p) for p in m.zone_points)
    eps = m.eps_alpha
    label_y = BAND + 2.5
    if len(zx) == 2 and 1.0 <= eps < 2.0:
        a, b = zx  # a at p_b from B₁, b at p_b from B₂ (1 ≤ ε < 2: a ≤ b)
        for x0, x1 in ((0.0, a), (b, L)):
            items += hatch_box(x0, x1, 0.0, BAND)
            items.append(Polyline(((x0, 0.0), (x0, BAND), (x1, BAND), (x1, 0.0)), "label"))
            items.append(Text(word("two pairs", notation, WORDS), ((x0 + x1) / 2.0, label_y), LETTER * 0.85))
        items.append(Polyline(((a, 0.0), (a, BAND), (b, BAND), (b, 0.0)), "label"))
        items.append(Segment(((a + b) / 2.0, BAND), ((a + b) / 2.0, BAND + 6.5), "label"))
        items.append(Text(word("one pair", notation, WORDS), ((a + b) / 2.0, BAND + 8.5), LETTER * 0.85))
        for x in (a, b):
            items.append(Segment((x, DIM_ROWS[0] + 1.5), (x, 0.0), "label"))
            items.append(Circle((x, 0.0), 2.0 * DOT, "result"))
        for x in (0.0, L):
            items.append(Segment((x, DIM_ROWS[-1] - 1.5), (x, 0.0), "construction"))
        items += _hdim(0.0, a, DIM_ROWS[0], "(ε_{α}−1)p_{b}")
        items += _hdim(a, b, DIM_ROWS[0], "(2−ε_{α})p_{b}")
        items += _hdim(b, L, DIM_ROWS[0], "(ε_{α}−1)p_{b}")
        items.append(Segment((b, DIM_ROWS[1] - 1.5), (b, DIM_ROWS[0]), "construction"))
        items.append(Segment((a, DIM_ROWS[2] - 1.5), (a, DIM_ROWS[0]), "construction"))
        items += _hdim(0.0, b, DIM_ROWS[1], "p_{b}")
        items += _hdim(a, L, DIM_ROWS[2], "p_{b}")
        items += _hdim(0.0, L, DIM_ROWS[3], "B_{1}B_{2}")
    elif eps < 1.0:  # the next pair comes into contact at B₂ only when this one is p_b past it
        items.append(Segment((L, 0.0), (pb, 0.0), "result", dashed=True))
        items += hatch_box(L, pb, -BAND, 0.0)
        items.append(Text(word("gap", notation, WORDS), ((L + pb) / 2.0, -BAND - 3.0), LETTER * 0.85))
        for x in (0.0, L, pb):
            items.append(Segment((x, DIM_ROWS[2] - 1.5), (x, 0.0), "construction"))
        items += _hdim(0.0, L, DIM_ROWS[1], "B_{1}B_{2}")
        items += _hdim(0.0, pb, DIM_ROWS[2], "p_{b}")
        items.append(Text(word("not continuous", notation, WORDS), (L / 2.0, BAND + 6.0), LETTER))
    else:
        for x in (0.0, L):
            items.append(Segment((x, DIM_ROWS[1] - 1.5), (x, 0.0), "construction"))
        items += _hdim(0.0, L, DIM_ROWS[1], "B_{1}B_{2}")
        if eps >= 2.0:
            items.append(Text(word("three pairs", notation, WORDS), (L / 2.0, BAND + 6.0), LETTER))
    return items + labels


def _hdim(x0: float, x1: float, y: float, text: str) -> list[Primitive]:
    """A horizontal dimension from x0 to x1 at height y, its text set just above its middle — or
    left out where it is wider than the dimension (the notes under the panel give the value)."""
    items = dimension((x0, y), (x1, y), text)
    lab = items.pop()
    assert isinstance(lab, Label)
    size = LETTER * 0.85
    if text_box_size(text, size)[0] > abs(x1 - x0) - 1.0:
        return items
    return items + [Text(text, ((x0 + x1) / 2.0, y + 2.8), size, italic=True)]


def zones_notes(drawing: GearDrawing, m: MeshConstruction) -> tuple[str, ...]:
    notes = [scale_text("l", drawing.scales["zones"]),
             (f"p_{{b}} = {mm_text(m.pb)}, B_{{1}}B_{{2}} = {mm_text(m.B1B2)}, ε_{{α}} = B_{{1}}B_{{2}}/p_{{b}} = "
              f"{number(m.eps_alpha)}")]
    if m.double_contact is not None and m.single_contact is not None:
        notes.append(f"(ε_{{α}}−1)p_{{b}} = {mm_text(m.double_contact)}, (2−ε_{{α}})p_{{b}} = {mm_text(m.single_contact)}")
    return tuple(notes)


# ----------------------------------------------------------------------------- measurement
def span_items(drawing: GearDrawing, name: str, sp: SpanMeasurement) -> list[Primitive]:
    """The caliper over k teeth at μ "l": the teeth between, the line K₁K₂ tangent to the
    base circle at N, the jaws ⟂ to it at K₁, K₂, W_k dimensioned outside."""
    mu = drawing.scales["l"]
    z = _gear(drawing.gears, name).z
    t = dict(drawing.teeth).get(name)
    K1, K2, N = to_paper(sp.K1, mu), to_paper(sp.K2, mu), to_paper(sp.N, mu)
    items: list[Primitive] = []
    pts = [K1, K2, N]
    if t is not None:
        a1, a2 = sorted((_angle(sp.K1), _angle(sp.K2)))
        step = math.tau / z
        js = list(range(round((a1 - math.pi / 2) / step), round((a2 - math.pi / 2) / step) + 1))  # the teeth K₁, K₂ touch and between
        # a long span (k of a large gear) draws the two teeth at each end; those between are the
        # same teeth, and drawing thousands of them would only take time
        groups = [js] if len(js) <= SPAN_TEETH_MOST else [js[:2], js[-2:]]
        for group in groups:
            line = tuple(to_paper(p, mu) for p in replicated(t, z, group))
            if len(line) >= 2:
                items.append(Polyline(line, "result"))
                pts += list(line)
    window = _box(pts, MARGIN + 6.0)
    if t is not None:
        items += clipped_circle((0.0, 0.0), t.rb / mu, window, "construction", dashdot=True)
        items += clipped_circle((0.0, 0.0), t.r / mu, window, "construction", dashdot=True)
    d = _unit(_sub(K2, K1))
    n = (-d[1], d[0])
    if n[0] * N[0] + n[1] * N[1] < 0.0:  # outward, away from O
        n = _neg(n)
    items.append(Segment(_add(K1, d, -4.0), _add(K2, d, 4.0), "label"))
    jaw = 8.0
    off = 14.0
    for k in (K1, K2):
        items.append(Segment(_add(k, n, -jaw), _add(k, n, off + 2.0), "given"))
        items.append(Circle(k, 2.0 * DOT, "result"))
    items.append(Circle(N, 2.0 * DOT, "result"))
    items += dimension(_add(K1, n, off), _add(K2, n, off), f"W_{{{sp.k}}} = {mm_text(sp.W)}", n)
    items += [paper_label("K_{1}", K1, (d, _neg(n)), LETTER), paper_label("K_{2}", K2, (_neg(d), _neg(n)), LETTER),
              paper_label("N", N, (d, _neg(d)), LETTER)]
    return items


def pins_items(drawing: GearDrawing, name: str, pm: PinMeasurement) -> tuple[list[Primitive], bool]:
    """The pins in their spaces and M over them at μ "l"; the whole gear when it fits
    :data:`WHOLE_MOST`, else the first pin's region only (False: M not to scale)."""
    mu = drawing.scales["l"]
    gear = _gear(drawing.gears, name)
    z = gear.z
    t = dict(drawing.teeth).get(name)
    rp = pm.d_pin / 2.0 / mu
    C = [to_paper(c, mu) for c in pm.centres]
    reach = max(math.hypot(*c) + rp for c in C)
    items: list[Primitive] = []
    whole = 2.0 * reach <= WHOLE_MOST
    shown = C if whole else C[:1]
    pts: list[XY] = [p for c in shown for p in ((c[0] - rp, c[1] - rp), (c[0] + rp, c[1] + rp))]
    if t is not None:
        groups: list[list[int]] = []
        if whole and z <= WHOLE_TEETH_MOST:
            groups = [list(range(z))]
        else:  # the teeth about each pin shown; a large gear's others are its tip and root circles
            for c in (pm.centres if whole else pm.centres[:1]):
                j0 = round((_angle(c) - math.pi / 2.0) / (math.tau / z))
                groups.append([j0 - 2, j0 - 1, j0, j0 + 1, j0 + 2])
        closed = whole and z <= WHOLE_TEETH_MOST
        for group in groups:
            line = tuple(to_paper(p, mu) for p in replicated(t, z, group))
            if len(line) >= 2:
                items.append(Polyline(line, "result", closed=closed))
                pts += list(line)
        if whole and not closed:
            for r in (t.ra, t.rf):
                items.append(Circle((0.0, 0.0), r / mu, "construction"))
    window = _box(pts, MARGIN)
    if t is not None:
        items += clipped_circle((0.0, 0.0), t.r / mu, window, "construction", dashdot=True)
    if _inside((0.0, 0.0), window):
        items.append(Hinge((0.0, 0.0)))
    for c in shown:
        items += [Circle(c, rp, "given"), Circle(c, 2.0 * DOT, "result")]
    for q in pm.contacts:
        qq = to_paper(q, mu)
        if _inside(qq, window):
            items.append(Circle(qq, DOT, "result"))
    d = _unit(_sub(C[1], C[0]))
    n = (-d[1], d[0])
    if whole:
        if gear.internal:  # M between the pins: their inner points
            e0, e1 = _add(C[0], d, rp), _add(C[1], d, -rp)
        else:
            e0, e1 = _add(C[0], d, -rp), _add(C[1], d, rp)
        off = (max(t.ra, t.rf) / mu if t is not None else reach) + 8.0  # beside the gear, parallel to the pins' line
        for e in (e0, e1):
            items.append(Segment(e, _add(e, n, off + 1.5), "label"))
        items += dimension(_add(e0, n, off), _add(e1, n, off), f"M = {mm_text(pm.M)}", n)
    else:
        e0 = _add(C[0], d, -rp) if not gear.internal else _add(C[0], d, rp)
        items += [Segment(e0, _add(e0, n, rp + 6.0), "label"),
                  Arrow(_add(_add(e0, n, rp + 4.5), d, 25.0), _add(e0, n, rp + 4.5), "label"),
                  paper_label(f"M = {mm_text(pm.M)}", _add(_add(e0, n, rp + 4.5), d, 25.0), (_neg(d),), LETTER, italic=False)]
    return items, whole


# ----------------------------------------------------------------------------- root circle and base circle
def root_base_items(drawing: GearDrawing, notation: str = "en") -> list[Primitive]:
    """r_b/m = z·cos α/2 and r_f/m = z/2 − (z₀/2)(1 − cos α) against z, crossing at z₀; the
    gear's own z marked. Axes at a common scale of DIAGRAM_W mm for the z range."""
    assert drawing.root_base is not None
    z0, zg = drawing.root_base
    ca = math.cos(drawing.gears.system.alpha)
    z_max = round_scale(1.4 * max(z0, zg, 10.0))
    k = DIAGRAM_W / z_max  # mm per tooth and per unit of r/m

    def rb(z: float) -> float:
        return z * ca / 2.0

    def rf(z: float) -> float:
        return z / 2.0 - z0 / 2.0 * (1.0 - ca)

    y_lo = min(0.0, rf(0.0))
    y_hi = max(rb(z_max), rf(z_max))
    items: list[Primitive] = [Arrow((0.0, y_lo * k - 2.0), (0.0, y_hi * k + 8.0), "label"),
                              Arrow((0.0, 0.0), (DIAGRAM_W + 8.0, 0.0), "label")]
    labels: list[Primitive] = [paper_label("r/m", (0.0, y_hi * k + 8.0), ((0.0, -1.0),), LETTER),
                               paper_label("z", (DIAGRAM_W + 8.0, 0.0), ((-1.0, 0.0),), LETTER)]
    tick = round_scale(z_max / 6.0)
    v = tick
    while v <= z_max + 1e-9:
        items.append(Segment((v * k, 0.0), (v * k, -1.5), "label"))
        labels.append(paper_label(number(v), (v * k, -1.5), ((0.0, 1.0),), LETTER * 0.8, italic=False))
        v += tick
    v = tick / 2.0 if tick >= 2.0 else tick
    while v <= y_hi + 1e-9:
        items.append(Segment((0.0, v * k), (-1.5, v * k), "label"))
        labels.append(paper_label(number(v), (-1.5, v * k), ((1.0, 0.0),), LETTER * 0.8, italic=False))
        v += tick / 2.0 if tick >= 2.0 else tick
    items.append(Polyline(((0.0, 0.0), (z_max * k, rb(z_max) * k)), "result"))
    z_f0 = z0 * (1.0 - ca)  # where r_f = 0
    items.append(Polyline(((0.0, rf(0.0) * k), (z_max * k, rf(z_max) * k)), "result", dashed=True))
    items.append(Segment((0.0, rf(0.0) * k), (z_f0 * k, 0.0), "construction"))
    labels += [paper_label("r_{b}/m", (z_max * k, rb(z_max) * k), ((-1.0, -0.4),), LETTER),
               paper_label("r_{f}/m", (z_max * k, rf(z_max) * k), ((-1.0, -0.5),), LETTER)]
    cross = (z0 * k, rb(z0) * k)
    items += [Circle(cross, 0.8, "result"), Segment(cross, (z0 * k, 0.0), "construction", dashed=True)]
    labels.append(paper_label(word("root=base", notation, WORDS).replace("«z»", number(z0)), cross, ((1.0, 0.5), (0.0, -1.0)),
                        LETTER, italic=False))
    if zg > 0.0:
        items.append(Segment((zg * k, 0.0), (zg * k, max(rb(zg), rf(zg)) * k + 6.0), "label", dashdot=True))
        labels.append(paper_label(f"z = {number(zg)}", (zg * k, max(rb(zg), rf(zg)) * k + 6.0), ((0.0, -1.0),), LETTER,
                            italic=False))
    return items + labels


# ----------------------------------------------------------------------------- the sheet
def _caption(key: str, name: str, notation: str) -> str:
    head = word(key, notation, WORDS)
    return head + (word("gear", notation, WORDS).replace("«n»", name) if name else "")


def gear_sheet(title: str, show: Sequence[str], drawing: GearDrawing, page: tuple[float, float],
               footer: tuple[str, ...] = (), notation: str = "en") -> Sheet:
    """The gear sheet: the panels of ``show`` in the order of :data:`PANELS` (a tooth panel and
    a measurement panel per gear drawn), each stating its scale.

    Raises
    ------
    OutOfDomain
        An unknown panel; a shown panel whose scale is missing or not positive, or whose
        construction is missing (zones and meshing need ``mesh``, root_base its tuple).
    """
    bad = [p for p in show if p not in PANELS]
    if bad:
        raise OutOfDomain(f"unknown panel(s) {', '.join(map(repr, bad))}; use {', '.join(PANELS)}")
    need = {"tooth": "tooth", "meshing": "l", "zones": "zones", "measurement": "l"}
    for p in PANELS:
        if p in show and p in need:
            mu = drawing.scales.get(need[p], 0.0)
            if not (mu > 0.0 and math.isfinite(mu)):
                raise OutOfDomain(f"the {p} panel needs the scale {need[p]!r}, finite and > 0")
    if ("meshing" in show or "zones" in show) and drawing.mesh is None:
        raise OutOfDomain("the meshing and zones panels need the meshing construction")
    if "root_base" in show and drawing.root_base is None:
        raise OutOfDomain("the root_base panel needs (z where r_f = r_b, the gear's z)")
    panels: list[Panel] = []
    row = 0
    if "tooth" in show:
        for name, t in drawing.teeth:
            panels.append(Panel(f"tooth{name}", _caption("tooth", name, notation),
                                tuple(tooth_items(drawing, name, t, notation)), tooth_notes(drawing, name, t), row,
                                (("l", drawing.scales["tooth"]),)))
        row += 1
    if drawing.mesh is not None and ("meshing" in show or "zones" in show):
        if "meshing" in show:
            panels.append(Panel("meshing", word("meshing", notation, WORDS),
                                tuple(meshing_items(drawing, drawing.mesh, notation)),
                                meshing_notes(drawing, drawing.mesh, notation), row, (("l", drawing.scales["l"]),)))
        if "zones" in show:
            panels.append(Panel("zones", word("zones", notation, WORDS),
                                tuple(zones_items(drawing, drawing.mesh, notation)),
                                zones_notes(drawing, drawing.mesh), row, (("l", drawing.scales["zones"]),)))
        row += 1
    if "measurement" in show:
        mu = drawing.scales["l"]
        for name, sp in drawing.span:
            panels.append(Panel(f"measurement{name}", _caption("measurement", name, notation),
                                tuple(span_items(drawing, name, sp)),
                                (scale_text("l", mu), f"k = {sp.k}, W_{{{sp.k}}} = {mm_text(sp.W)}"), row,
                                (("l", mu),)))
        for name, pm in drawing.pins:
            items, whole = pins_items(drawing, name, pm)
            notes: tuple[str, ...] = (scale_text("l", mu), f"d_{{p}} = {mm_text(pm.d_pin)}, M = {mm_text(pm.M)}")
            if not whole:
                notes += (word("not to scale", notation, WORDS),)
            panels.append(Panel(f"pins{name}", _caption("pins", name, notation), tuple(items), notes, row,
                                (("l", mu),)))
        row += 1
    if "root_base" in show:
        s = drawing.gears.system
        note = (f"r_{{b}}/m = (z/2)·cos α, r_{{f}}/m = z/2 − (h_{{a}}* + c* − x); α = {number(math.degrees(s.alpha))}°, "
                f"h_{{a}}* = {number(s.ha_star)}, c* = {number(s.c_star)}")
        panels.append(Panel("root_base", word("root_base", notation, WORDS), tuple(root_base_items(drawing, notation)),
                            (note,), row))
        row += 1
    if "generation" in show and drawing.generation is not None:
        panels.append(replace(drawing.generation, row=row))
    return Sheet(title, tuple(panels), page, footer)


__all__ = [
    "PANELS",
    "WORDS",
    "GearDrawing",
    "arc_dimension",
    "arc_points",
    "circle_in",
    "clipped_circle",
    "clipped_segment",
    "dimension",
    "gear_sheet",
    "meshing_items",
    "mm_text",
    "outline_runs",
    "paper_label",
    "pins_items",
    "replicated",
    "root_base_items",
    "span_items",
    "to_paper",
    "tooth_items",
    "zones_items",
]
