"""The figures of the graphical flywheel design, as the course project's sheet draws them.

Methods produce primitives with roles; a renderer turns them into SVG and knows nothing of
flywheels. Every quantity is laid off at its panel's μ; every other size is paper millimetres.

moment — Mп(φ) integrated by chords (at μM, μφ)
    the φ axis numbered at the positions 1 … N (and 1 again at the cycle's end), the ordinates
    Mп_k (thin) and the curve; the mean ordinate of each interval as a thin step, projected onto
    the moment axis (thin dashed); the pole P on the φ axis at the distance H left of O (dimensioned)
    and the rays from P to the projections (thin); the ray from P parallel to the balancing
    work's line (thin dashed) cuts the moment axis at the constant moment Mд (or Mс), drawn bold
    across the cycle.
work — A(φ) (at μA = μT)
    the chord polygon Aп (bold), each chord parallel to its ray, and the straight line A_b of
    the constant moment's work (bold dashed) from the origin to −Aп(Φ).
energy — ΔT(φ) = Aп + A_b (at μT)
    the curve with its ordinates, its largest and smallest values marked.
inertia — Jп(φ), drawn as the Russian book does: Jп horizontal, φ downwards
    at μJ and its own μφ′ (the φ axis about 40 mm long).
wittenbauer — the Wittenbauer diagram ΔT(Jп) (at μJ, μT)
    the numbered points (dots) and the closed curve through them (thin), the two tangents at ψmax
    and ψmin (bold) with their angles marked by arcs, k and l on the ΔT axis and the segment kl
    dimensioned. Shown together with ``energy`` and/or ``inertia``, these are drawn in the same
    panel on the continuations of its axes — ΔT(φ) to the left (its φ axis continued is the Jп
    axis), Jп(φ) below (its φ axis continued is the ΔT axis) — and the points are carried across
    by thin lines, as the book builds the diagram. That panel is named by its members joined with
    ``+`` (``"energy+inertia+wittenbauer"``). When k or l lie far below the points the tangents
    are clipped and the intercepts written out.
indicator — the energy-indicator diagram (at μT)
    the chain of vertical vectors f₁, f₂, … (excess up, deficit down) from a back to a′ on one
    level, its vertices lettered, and ΔW_max dimensioned between the highest and lowest.

Many positions (N up to thousands) are drawn with every position in the curves; numbers, rays,
ordinates and carried lines are thinned to a readable count.
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from graphmech.methods.flywheel import FlywheelDesign
from graphmech.drawing.lettering import text_box_size
from graphmech.drawing.primitives import (XY, ArcArrow, Arrow, Circle, Label, Panel, Polyline, Primitive, Role,
                                         Segment, Sheet)
from graphmech.render.style import DEFAULT
from graphmech.scales import PAPER, format_scale, round_scale
from graphmech.drawing.diagrams import (
    AXIS_OVERRUN,
    NUMBER_CLEARANCE,
    NUMBER_SIZE,
    count_every,
    moved,
    numbers_every,
    phi_axis_numbers,
)
from graphmech.errors import OutOfDomain

#: The panels a flywheel sheet can show, in their order on the sheet.
PANELS = ("moment", "work", "energy", "inertia", "wittenbauer", "indicator")
#: Drawn in one panel with the Wittenbauer diagram when it is shown.
BESIDE_WITTENBAUER = ("energy", "inertia")
#: At most this many numbered points on the Wittenbauer curve, rays from the pole, and lines
#: carried across to the Wittenbauer diagram.
MOST_NUMBERS, MOST_RAYS, MOST_CARRIED = 36, 24, 24
#: All ordinates are drawn up to this many positions; above, only the numbered ones.
MOST_ORDINATES = 48
#: Points of the Wittenbauer curve get a dot up to this many positions.
MOST_DOTS = 360
#: Radius of a dot marking a point (drawn with the result pen: a solid dot), mm.
DOT = 0.3
#: The Jп(φ) diagram's φ axis is about this long, mm (its μφ′ a round number of °/mm).
INERTIA_PHI_MM = 40.0
#: The ΔT axis of the Wittenbauer diagram runs down to k and l unless they lie more than this
#: below the lowest point; then the tangents are clipped this far below it, mm.
FAR_MM, CLIP_MM = 60.0, 20.0
#: The tangents run this far past the right-most point and left of the ΔT axis, mm.
TANGENT_RIGHT, TANGENT_LEFT = 10.0, 4.0
#: The ψ arcs' radius, and the least arc length that carries an arrowhead, mm.
PSI_R = 16.0
#: The kl dimension line's distance left of the ΔT axis, mm.
KL_AT = 7.0
#: Free space between ΔT(φ) and the Wittenbauer diagram's ΔT axis, and between the diagram
#: and Jп(φ) below it, mm.
GAP_LEFT, GAP_BELOW = 24.0, 12.0
#: The energy indicator's vectors stand this far apart (at most), its chain at most this wide, mm.
INDICATOR_STEP, INDICATOR_WIDTH = 6.0, 90.0

TITLES = {
    "moment": "Reduced moment Mп(φ), integrated by chords",
    "work": "Work diagrams A(φ)",
    "energy": "Increment of kinetic energy ΔT(φ)",
    "inertia": "Reduced moment of inertia Jп(φ)",
    "wittenbauer": "Wittenbauer diagram ΔT(Jп)",
    "indicator": "Energy indicator diagram",
}

_LEFT = ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0))  # … left of a vertical one


# ----------------------------------------------------------------------------- helpers


def wittenbauer_every(x: np.ndarray, y: np.ndarray, size: float = NUMBER_SIZE) -> int:
    """Number every k-th point of the Wittenbauer curve: at most :data:`MOST_NUMBERS` numbers, and
    no more than the curve has room for — 1.25 numbers per number's width (plus clearance) of its
    length, but at least six.

    >>> t = np.linspace(0.0, 2 * np.pi, 12, endpoint=False)
    >>> wittenbauer_every(30 + 10 * np.cos(t), 10 * np.sin(t)), wittenbauer_every(np.zeros(36), np.sin(t.repeat(3)))
    (1, 6)
    """
    n = len(x)
    length = float(np.hypot(np.diff(x, append=x[:1]), np.diff(y, append=y[:1])).sum())
    room = int(1.25 * length / (text_box_size(str(n), size)[0] + 2.0 * NUMBER_CLEARANCE))
    return count_every(n, min(MOST_NUMBERS, max(6, room)))


def _dirs(*ds: tuple[float, float]) -> tuple[tuple[float, float], ...]:
    out = []
    for dx, dy in ds:
        n = math.hypot(dx, dy)
        if n > 1e-12:
            out.append((dx / n, dy / n))
    return tuple(out)


def _pts(x: np.ndarray, y: np.ndarray) -> tuple[XY, ...]:
    return tuple(zip(np.asarray(x, dtype=float).tolist(), np.asarray(y, dtype=float).tolist()))


def _split(items: Sequence[Primitive]) -> tuple[list[Primitive], list[Label]]:
    return [i for i in items if not isinstance(i, Label)], [i for i in items if isinstance(i, Label)]


def _ordinate_positions(n: int, every: int) -> range:
    return range(0, n + 1) if n <= MOST_ORDINATES else range(0, n + 1, every)


def _diagram(x: np.ndarray, y: np.ndarray, every: int, name: str, *, curve_role: Role = "result",
             ordinates: bool = True) -> tuple[list[Primitive], list[Label]]:
    """Axes φ →, ``name`` ↑ through the origin, the ordinates and the curve through (x, y)."""
    lo, hi = min(0.0, float(y.min())), max(0.0, float(y.max()))
    items: list[Primitive] = [Arrow((0.0, 0.0), (float(x[-1]) + AXIS_OVERRUN, 0.0), "label"),
                              Arrow((0.0, lo - (3.0 if lo < 0.0 else 0.0)), (0.0, hi + AXIS_OVERRUN), "label")]
    for k in range(every, x.size, every):  # ticks at the numbered positions
        items.append(Segment((float(x[k]), 0.0), (float(x[k]), -1.0), "label"))
    if ordinates:
        items += [Segment((float(x[k]), 0.0), (float(x[k]), float(y[k])), "construction")
                  for k in _ordinate_positions(x.size - 1, every) if abs(y[k]) > 1e-9]
    items.append(Polyline(_pts(x, y), curve_role))
    labels = [Label(name, (0.0, hi + AXIS_OVERRUN), ((0.0, -1.0),), 3.2),
              Label("φ", (float(x[-1]) + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), 3.2),
              Label("O", (0.0, 0.0), ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0)), 3.0)]
    return items, labels + phi_axis_numbers(x, every)


def _every(design: FlywheelDesign) -> int:
    x = design.moment.x_mm
    return numbers_every(design.n, float(np.min(np.diff(x))))


def _constant_names(design: FlywheelDesign) -> tuple[str, str]:
    """The constant moment's and its work's names: Mд, Aд (driving) or Mс, Aс (resisting)."""
    return ("Mд", "Aд") if design.balance == "driving" else ("Mс", "Aс")


# ----------------------------------------------------------------------------- the panels
def moment_items(design: FlywheelDesign, every: int | None = None) -> list[Primitive]:
    """Mп(φ) at μM, μφ with the integration's construction and the constant moment (O at the origin)."""
    g = design.moment
    every = every or _every(design)
    x, y, mean = g.x_mm, g.y_mm, g.mean_mm
    n, H, mb = design.n, design.H_mm, design.balancing_mm
    P = g.pole
    xe = float(x[-1])
    items, labels = _diagram(x, y, every, "Mп", curve_role="given")
    items[0] = Arrow((-H - 4.0, 0.0), (xe + AXIS_OVERRUN, 0.0), "label")  # the φ axis carries the pole
    lo = min(0.0, float(y.min()), float(mean.min()), mb)
    # the mean ordinates as a step of equal area; projections on the moment axis; rays from P
    step = np.empty((2 * n, 2))
    step[0::2, 0], step[1::2, 0] = x[:-1], x[1:]
    step[0::2, 1] = step[1::2, 1] = mean
    construction: list[Primitive] = [Polyline(_pts(step[:, 0], step[:, 1]), "construction")]
    for i in range(0, n, count_every(n, MOST_RAYS)):
        m = float(mean[i])
        construction += [Segment((float(x[i]), m), (0.0, m), "construction", dashed=True),
                         Segment(P, (0.0, m), "construction")]
    # the ray from P parallel to the balancing work's line, and the constant moment it cuts off
    name, _ = _constant_names(design)
    result: list[Primitive] = [Segment(P, (0.0, mb), "label", dashed=True),
                               Segment((0.0, mb), (xe, mb), "result"), Circle(P, DOT, "result")]
    # the pole distance H, dimensioned under the fan of rays
    yd = lo - 5.0
    dim: list[Primitive] = [Segment(P, (P[0], yd - 1.5), "label"), Arrow((-H / 2.0, yd), (-H, yd), "label"),
                            Arrow((-H / 2.0, yd), (0.0, yd), "label")]
    if lo >= 0.0:
        dim.append(Segment((0.0, 0.0), (0.0, yd - 1.5), "label"))
    top = [Label("P", P, ((1.0, 0.0), (1.0, 0.5)), 3.2), Label("H", (-H / 2.0, yd), ((1.0, 0.0), (-1.0, 0.0)), 3.2),
           Label(name, (xe, mb), ((-1.0, 0.0),), 3.2)]
    return construction + items + result + dim + labels[:3] + top + labels[3:]


def work_items(design: FlywheelDesign, every: int | None = None) -> list[Primitive]:
    """A(φ) at μA = μT: the chord polygon Aп and the constant moment's work line (O at the origin)."""
    every = every or _every(design)
    x, a, b = design.moment.x_mm, design.work_mm, design.balance_work_mm
    xe = float(x[-1])
    both = np.concatenate([a, b])
    items, labels = _diagram(x, a, every, "A")
    items[1] = Arrow((0.0, min(0.0, float(both.min())) - (3.0 if both.min() < 0 else 0.0)),
                     (0.0, max(0.0, float(both.max())) + AXIS_OVERRUN), "label")
    labels[0] = Label("A", (0.0, max(0.0, float(both.max())) + AXIS_OVERRUN), ((0.0, -1.0),), 3.2)
    _, work_name = _constant_names(design)
    line = Segment((0.0, 0.0), (xe, float(b[-1])), "result", dashed=True)
    far = int(np.argmax(np.abs(a)))
    names = [Label("Aп", (float(x[far]), float(a[far])), _dirs((-1.0, 0.0), (1.0, 0.0)), 3.2),
             Label(work_name, (xe, float(b[-1])), ((-1.0, -float(b[-1]) / xe),), 3.2)]
    return items + [line] + labels[:3] + names + labels[3:]


def energy_items(design: FlywheelDesign, every: int | None = None) -> list[Primitive]:
    """ΔT(φ) at μT, μφ with its extremes marked (O at the origin)."""
    every = every or _every(design)
    x, t = design.moment.x_mm, design.energy_mm
    items, labels = _diagram(x, t, every, "ΔT")
    marks: list[Primitive] = []
    for i, text in ((design.energy_max_index, "ΔTₘₐₓ"), (design.energy_min_index, "ΔTₘᵢₙ")):
        p = (float(x[i]), float(t[i]))
        marks.append(Circle(p, 2 * DOT, "result"))
        labels.append(Label(text, p, ((0.0, -1.0) if text.endswith("ₓ") else (0.0, 1.0),), 3.0, italic=False))
    return items + marks + labels


def inertia_phi_scale(design: FlywheelDesign) -> float:
    """μφ′ of the Jп(φ) diagram, rad/mm: a round number of °/mm, the cycle about 40 mm long."""
    return math.radians(round_scale(math.degrees(design.cycle) / INERTIA_PHI_MM))


def inertia_items(design: FlywheelDesign, every: int | None = None) -> list[Primitive]:
    """Jп(φ) at μJ and μφ′: Jп to the right, φ downwards from the origin."""
    mu = inertia_phi_scale(design)
    n = design.n
    v = -np.append(design.phi, design.cycle) / mu
    xj = np.append(design.inertia_mm, design.inertia_mm[0])
    every = every or numbers_every(n, float(np.min(-np.diff(v))))
    right = float(xj.max())
    items: list[Primitive] = [Arrow((0.0, 0.0), (right + AXIS_OVERRUN, 0.0), "label"),
                              Arrow((0.0, 0.0), (0.0, float(v[-1]) - AXIS_OVERRUN), "label")]
    items += [Segment((0.0, float(v[k])), (-1.0, float(v[k])), "label") for k in range(every, n + 1, every)]
    items += [Segment((0.0, float(v[k])), (float(xj[k]), float(v[k])), "construction")
              for k in _ordinate_positions(n, every) if xj[k] > 1e-9]
    items.append(Polyline(_pts(xj, v), "given"))
    labels = [Label("Jп", (right + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), 3.2),
              Label("φ", (0.0, float(v[-1]) - AXIS_OVERRUN), ((0.0, 1.0),), 3.2)]
    labels += [Label(str(k + 1), (0.0, float(v[k])), _LEFT, NUMBER_SIZE, italic=False) for k in range(0, n, every)]
    if n % every == 0:
        labels.append(Label("1", (0.0, float(v[n])), _LEFT, NUMBER_SIZE, italic=False))
    return items + labels


def _window(design: FlywheelDesign) -> tuple[float, float, float, float, bool]:
    """The Wittenbauer diagram's drawn window (x0, x1, y0, y1) and whether k or l lie beyond it."""
    w = design.wittenbauer
    assert w is not None
    lowest = float(w.y_mm.min())
    reach = min(lowest, w.k_mm, w.l_mm)
    far = lowest - reach > FAR_MM
    y0 = lowest - CLIP_MM if far else reach - 4.0
    return -TANGENT_LEFT, float(w.x_mm.max()) + TANGENT_RIGHT, y0, float(w.y_mm.max()) + 6.0, far


def _tangent(c: float, t: float, box: tuple[float, float, float, float]) -> tuple[XY, XY]:
    """The part of y = c + t·x (t > 0) inside the box."""
    x0, x1, y0, y1 = box
    lo, hi = x0, x1
    if t > 0.0:
        lo, hi = max(lo, (y0 - c) / t), min(hi, (y1 - c) / t)
    return (lo, c + t * lo), (hi, c + t * hi)


def _angle_mark(at: XY, t: float, name: str) -> list[Primitive]:
    """ψ at ``at``: a horizontal reference, the arc from it to the tangent (an arrow when long enough), ψ named."""
    psi = math.atan(t)
    items: list[Primitive] = [Segment(at, (at[0] + PSI_R + 3.0, at[1]), "label")]
    if psi * PSI_R >= 2.5 * DEFAULT.arrow_length:
        items.append(ArcArrow(at, PSI_R, 0.0, psi, "label"))
    elif psi * PSI_R >= 0.3:
        m = max(3, int(psi * PSI_R / 0.5))
        items.append(Polyline(tuple((at[0] + PSI_R * math.cos(psi * i / m), at[1] + PSI_R * math.sin(psi * i / m))
                                    for i in range(m + 1)), "label"))
    tip = (at[0] + (PSI_R + 1.0) * math.cos(psi / 2), at[1] + (PSI_R + 1.0) * math.sin(psi / 2))
    items.append(Label(name, tip, ((-1.0, 0.0),), 3.0))
    return items


def wittenbauer_items(design: FlywheelDesign) -> list[Primitive]:
    """The Wittenbauer diagram at μJ, μT (O, Jп = 0 and ΔT = 0, at the origin)."""
    w = design.wittenbauer
    if w is None:
        raise OutOfDomain("the design has no Wittenbauer diagram: design it with need=('wittenbauer', …)")
    x, y, n = w.x_mm, w.y_mm, design.n
    box = _window(design)
    x0, x1, y0, y1, far = box
    items: list[Primitive] = [Arrow((0.0, y0 - 2.0), (0.0, y1 + AXIS_OVERRUN), "label"),
                              Arrow((0.0, 0.0), (x1 + AXIS_OVERRUN, 0.0), "label")]
    labels = [Label("ΔT", (0.0, y1 + AXIS_OVERRUN), ((0.0, -1.0),), 3.2),
              Label("Jп", (x1 + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), 3.2)]
    # the points and the closed curve through them in the order of the positions
    if n <= MOST_DOTS:
        items += [Circle(p, DOT, "result") for p in _pts(x, y)]
    items.append(Polyline(_pts(x, y), "label", closed=True))  # thinner than the tangents
    # the tangents at ψmax (from above) and ψmin (from below), k and l on the ΔT axis
    for c, t, tag, sub in ((w.k_mm, w.tan_psi_max, "k", "ₘₐₓ"), (w.l_mm, w.tan_psi_min, "l", "ₘᵢₙ")):
        p0, p1 = _tangent(c, t, box[:4])
        items.append(Segment(p0, p1, "result"))
        seen = c >= y0
        at = (0.0, c) if seen else p0
        items += [i for i in _angle_mark(at, t, "ψ" + sub) if not isinstance(i, Label)]
        labels += [i for i in _angle_mark(at, t, "ψ" + sub) if isinstance(i, Label)]
        if seen:
            items.append(Segment((-1.2, c), (1.2, c), "label"))
            labels.insert(2, Label(tag, (0.0, c), _dirs((1.0, t), (-1.0, -t), (0.0, 1.0), (0.0, -1.0)), 3.2))
        else:
            labels.append(Label(f"{tag} = {c:.1f} mm", (0.0, y0 - 2.0), ((0.0, 1.0),), 3.0, italic=False))
    k, l = w.k_mm, w.l_mm
    if not far and abs(k - l) > 1e-9:  # the segment kl, dimensioned left of the ΔT axis
        xd = -KL_AT
        hi, lo = max(k, l), min(k, l)
        items += [Segment((0.0, k), (xd - 1.5, k), "label"), Segment((0.0, l), (xd - 1.5, l), "label")]
        if hi - lo >= 2.0 * DEFAULT.arrow_length + 1.0:
            mid = (hi + lo) / 2.0
            items += [Arrow((xd, mid), (xd, hi), "label"), Arrow((xd, mid), (xd, lo), "label")]
        else:
            items += [Arrow((xd, hi + 4.0), (xd, hi), "label"), Arrow((xd, lo - 4.0), (xd, lo), "label"),
                      Segment((xd, lo), (xd, hi), "label")]
        labels.append(Label("kl", (xd, (k + l) / 2.0), ((1.0, 0.0),), 3.2))
    every = wittenbauer_every(x, y)
    for i in range(0, n, every):
        a, b = (x[i - 1], y[i - 1]), (x[(i + 1) % n], y[(i + 1) % n])
        p = (float(x[i]), float(y[i]))
        labels.append(Label(str(i + 1), p, _dirs((a[0] - p[0], a[1] - p[1]), (b[0] - p[0], b[1] - p[1])),
                            NUMBER_SIZE, italic=False))
    return items + labels


def indicator_items(design: FlywheelDesign) -> list[Primitive]:
    """The energy-indicator chain at μT: vertical vectors from a to a′, ΔW_max dimensioned."""
    e = design.indicator
    if e is None:
        raise OutOfDomain("the design has no energy indicator: design it with need=(…, 'indicator')")
    lv = [float(v) for v in e.levels_mm]
    m = len(lv) - 1
    step = min(INDICATOR_STEP, INDICATOR_WIDTH / max(m - 1, 1))
    xs = [step * i for i in range(m)]
    where = xs + [xs[-1]]  # vertex j at the tail of vector j; the last (a′) at the last head
    items: list[Primitive] = [Segment((-3.0, lv[0]), (xs[-1] + 3.0, lv[0]), "label")]
    labels: list[Label] = []
    for i in range(m):
        if abs(lv[i + 1] - lv[i]) > 1e-9:
            items.append(Arrow((xs[i], lv[i]), (xs[i], lv[i + 1]), "result"))
            if m <= 12:
                up = 1.0 if lv[i + 1] > lv[i] else -1.0
                labels.append(Label(f"f{chr(0x2080 + i + 1) if i < 9 else str(i + 1)}",
                                    (xs[i], (lv[i] + lv[i + 1]) / 2.0), ((0.0, up), (0.0, -up)), 2.8))
        if i + 1 < m:
            items.append(Segment((xs[i], lv[i + 1]), (xs[i + 1], lv[i + 1]), "construction"))
    if m <= 26:
        names = [chr(ord("a") + j) for j in range(m)] + ["a′"]
        for j, name in enumerate(names):
            labels.append(Label(name, (where[j], lv[j]), ((0.0, 1.0), (0.0, -1.0)), 3.0))
    if e.dW_max_mm > 1e-9:
        xd = xs[-1] + 8.0
        hi, lo = lv[e.highest], lv[e.lowest]
        items += [Segment((where[e.highest], hi), (xd + 1.5, hi), "construction"),
                  Segment((where[e.lowest], lo), (xd + 1.5, lo), "construction")]
        mid = (hi + lo) / 2.0
        if hi - lo >= 2.0 * DEFAULT.arrow_length + 1.0:
            items += [Arrow((xd, mid), (xd, hi), "label"), Arrow((xd, mid), (xd, lo), "label")]
        else:
            items += [Arrow((xd, hi + 4.0), (xd, hi), "label"), Arrow((xd, lo - 4.0), (xd, lo), "label"),
                      Segment((xd, lo), (xd, hi), "label")]
        labels.insert(0, Label("ΔWₘₐₓ", (xd, mid), ((-1.0, 0.0),), 3.2))
    return items + labels


# ----------------------------------------------------------------------------- notes
def _phi_note(mu: float) -> str:
    return f"{format_scale('phi', mu)} ({mu:.6g} rad/mm)"


def _notes(design: FlywheelDesign, members: Sequence[str]) -> tuple[str, ...]:
    s = design.scales
    out: list[str] = []
    name, work_name = _constant_names(design)
    if "moment" in members:
        out += [f"{format_scale('M', s['M'])}, {_phi_note(s['phi'])}",
                f"H = {design.H_mm:.6g} mm; {name} = μM·⟨{name}⟩ = {design.balancing_moment:.6g} N·m"]
    if "work" in members:
        out += [f"μA = μM·μφ·H: {format_scale('T', s['T']).replace('μT', 'μA')}, {_phi_note(s['phi'])}"]
    if "energy" in members or "indicator" in members:
        out += [f"{format_scale('T', s['T'])} (= μA)"]
        if "energy" in members:
            out[-1] += f", {format_scale('phi', s['phi'])}"
    if "inertia" in members:
        out += [f"{format_scale('J', s['J'])}; Jп(φ): {format_scale('phi', inertia_phi_scale(design))}"]
    if "wittenbauer" in members:
        w = design.wittenbauer
        assert w is not None
        if "inertia" not in members:
            out += [format_scale("J", s["J"])]
        reading = "ω = ωm(1 ± δ/2)" if design.form == "exact" else "ω² = ωm²(1 ± δ)"
        out += [f"tan ψ = μJ·ω²/(2μT), {reading}: tan ψmax = {w.tan_psi_max:.5g} (ψmax = {w.psi_max_deg:.4g}°), "
                f"tan ψmin = {w.tan_psi_min:.5g} (ψmin = {w.psi_min_deg:.4g}°)",
                f"k = {w.k_mm:.4g} mm, l = {w.l_mm:.4g} mm, kl = {w.kl_mm:.4g} mm: "
                f"J_F = μT·kl/(ωm²δ) = {design.J_F:.6g} kg·m²"]
        if w.ill_conditioned:
            out += [f"the tangents are {w.angle_between_deg:.2g}° apart: they meet {-w.intersection[0]:.4g} mm left "
                    "of the ΔT axis, too far to find by hand; k and l are read on the axis"]
    if "indicator" in members:
        assert design.DeltaW_max is not None and design.J_F_indicator is not None
        out += [f"ΔWmax = {design.DeltaW_max:.6g} J, Jmean = {design.J_mean:.6g} kg·m²",
                f"J_F′ = ΔWmax/(ωm²δ) − Jmean = {design.J_F_indicator:.6g} kg·m²"]
    return tuple(out)


# ----------------------------------------------------------------------------- the sheet
def _beside(design: FlywheelDesign, members: Sequence[str]) -> list[Primitive]:
    """The Wittenbauer diagram with ΔT(φ) on the left and Jп(φ) below, points carried across."""
    w = design.wittenbauer
    assert w is not None
    witt, wlabels = _split(wittenbauer_items(design))
    items: list[Primitive] = []
    labels: list[Label] = []
    x, y = w.x_mm, w.y_mm
    n = design.n
    carried = range(0, n, count_every(n, MOST_CARRIED))
    if "energy" in members:
        xe = design.moment.x_mm
        dx = -(GAP_LEFT + float(xe[-1]) + AXIS_OVERRUN)
        it, lb = _split(energy_items(design))
        items += [moved(i, dx, 0.0) for i in it]
        labels += [moved(i, dx, 0.0) for i in lb]
        items += [Segment((dx + float(xe[k]), float(y[k])), (float(x[k]), float(y[k])), "construction")
                  for k in carried if abs(float(x[k]) - dx - float(xe[k])) > 1e-9]
    if "inertia" in members:
        dy = _window(design)[2] - 2.0 - GAP_BELOW
        it, lb = _split(inertia_items(design))
        items += [moved(i, 0.0, dy) for i in it]
        labels += [moved(i, 0.0, dy) for i in lb]
        mu = inertia_phi_scale(design)
        items += [Segment((float(x[k]), dy - float(design.phi[k]) / mu), (float(x[k]), float(y[k])), "construction")
                  for k in carried]
    return items + witt + wlabels + labels


def panel_members(show: Sequence[str]) -> list[tuple[str, ...]]:
    """The panels of a sheet showing ``show``: one per entry, except that energy and inertia stand in
    the Wittenbauer diagram's panel when it is shown.

    >>> panel_members(["wittenbauer", "moment", "energy"])
    [('moment',), ('energy', 'wittenbauer')]
    """
    bad = [p for p in show if p not in PANELS]
    if bad:
        raise OutOfDomain(f"unknown panel(s) {', '.join(map(repr, bad))}; use {', '.join(PANELS)}")
    wanted = [p for p in PANELS if p in show]
    if "wittenbauer" not in wanted:
        return [(p,) for p in wanted]
    out: list[tuple[str, ...]] = []
    for p in wanted:
        if p in BESIDE_WITTENBAUER:
            continue
        if p == "wittenbauer":
            out.append(tuple(q for q in wanted if q in BESIDE_WITTENBAUER) + ("wittenbauer",))
        else:
            out.append((p,))
    return out


def flywheel_sheet(title: str, design: FlywheelDesign, show: Sequence[str],
                   page_size: tuple[float, float] = PAPER["A3"], footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet of the graphical flywheel design: the panels of ``show`` in the order of :data:`PANELS`.

    Mп(φ) and A(φ) stand in the first row; ΔT(φ), Jп(φ), the Wittenbauer diagram and the energy
    indicator in the second. A panel's name is its entry of ``show`` (the Wittenbauer diagram's
    panel: its members joined by ``+``); its notes state its scales and what it finds.

    Parameters
    ----------
    title : str
    design : FlywheelDesign
        From :func:`~graphmech.methods.flywheel.design_flywheel` (with the Wittenbauer diagram
        or the energy indicator when those are shown).
    show : sequence of str
        A non-empty subset of :data:`PANELS`.
    page_size : (float, float)
        mm.
    footer : tuple of str

    Raises
    ------
    ValueError
        An unknown or no panel, or a diagram the design did not compute.

    Examples
    --------
    >>> from graphmech.methods.flywheel import design_flywheel
    >>> phi = np.arange(12) * np.pi / 6
    >>> d = design_flywheel(phi, 0.5 + 0.1 * np.cos(phi) ** 2, -50.0 + 100.0 * np.sin(phi), cycle=2 * np.pi,
    ...                     omega_m=100.0, delta=0.02)
    >>> [p.name for p in flywheel_sheet("Flywheel", d, ["moment", "energy", "wittenbauer"]).panels]
    ['moment', 'energy+wittenbauer']
    """
    if not show:
        raise OutOfDomain(f"show at least one of {', '.join(PANELS)}")
    members = panel_members(show)
    if "wittenbauer" in show and design.wittenbauer is None:
        raise OutOfDomain("the Wittenbauer diagram is shown but the design has none (need=('wittenbauer',))")
    if "indicator" in show and design.indicator is None:
        raise OutOfDomain("the energy indicator is shown but the design has none (need=('indicator',))")
    every = _every(design)
    build = {"moment": lambda: moment_items(design, every), "work": lambda: work_items(design, every),
             "energy": lambda: energy_items(design, every), "inertia": lambda: inertia_items(design),
             "indicator": lambda: indicator_items(design)}
    panels = []
    for group in members:
        if "wittenbauer" in group:
            items = _beside(design, group)
            head = TITLES["wittenbauer"] + "".join(
                f" with {'ΔT(φ)' if g == 'energy' else 'Jп(φ)'}" for g in group if g != "wittenbauer")
        else:
            items = build[group[0]]()
            head = TITLES[group[0]]
            if group[0] == "work":
                head += f": Aп (chords), {_constant_names(design)[1]} (dashed)"
        row = 0 if group[0] in ("moment", "work") else 1
        panels.append(Panel("+".join(group), head, tuple(items), _notes(design, group), row=row))
    return Sheet(title, tuple(panels), (page_size[0], page_size[1]), tuple(footer))


__all__ = ["PANELS", "energy_items", "flywheel_sheet", "indicator_items", "inertia_items", "moment_items",
           "panel_members", "wittenbauer_items", "work_items"]
