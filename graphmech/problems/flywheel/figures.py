"""The figures of the graphical flywheel design, as the course project's sheet draws them.

Methods produce primitives with roles; a renderer turns them into SVG and knows nothing of
flywheels. Every quantity is laid off at its panel's μ; every other size is paper millimetres.
Symbols and captions are in the scene's notation (``[page] notation``: the reduced moment is
M_{red}, M_{e} or M_{п}; see :data:`FLY_WORDS`); the names in ``find`` and ``check`` never change.

moment — M_{red}(φ) integrated by chords (at μM, μφ)
    the φ axis numbered at the positions 1 … N (and 1 again at the cycle's end), the ordinates
    (thin) and the curve; the mean ordinate of each interval as a thin step, projected onto
    the moment axis (thin dashed); the pole P on the φ axis at the distance H left of O (dimensioned)
    and the rays from P to the projections (thin); the ray from P parallel to the balancing
    work's line (thin dashed) cuts the moment axis at the constant moment M_{d} (or M_{r}), drawn
    bold across the cycle.
work — A(φ) (at μA = μT)
    the chord polygon A_{red} (bold), each chord parallel to its ray, and the straight line of
    the constant moment's work (bold dashed) from the origin to −A_{red}(Φ).
energy — ΔT(φ) = A_{red} + A_{b} (at μT, or at μT′ = μT/k when it would be lower than
    :data:`ENERGY_LEAST` and stands alone)
    the curve with its ordinates, its largest and smallest values marked.
inertia — J_{red}(φ), drawn as the Russian book does: J horizontal, φ downwards
    at μJ and its own μφ′ (the φ axis about 40 mm long).
wittenbauer — the Wittenbauer diagram ΔT(J_{red}) (at μJ, μT)
    the numbered points (dots; the numbers set outward from the curve's centroid, clear of the
    curve and the tangents) and the closed curve through them (thin), the two tangents at ψmax
    and ψmin (bold) with their angles marked by arcs, k and l on the ΔT axis and the segment kl
    dimensioned. Shown together with ``energy`` and/or ``inertia``, these are drawn in the same
    panel on the continuations of its axes — ΔT(φ) to the left (its φ axis continued is the J
    axis), J(φ) below (its φ axis continued is the ΔT axis) — and the points are carried across
    by thin lines, as the book builds the diagram. That panel is named by its members joined with
    ``+`` (``"energy+inertia+wittenbauer"``). When k or l lie far below the points the tangents
    are clipped and the intercepts written out.
indicator — the energy-indicator diagram (at μT, or μT′ as the energy diagram)
    the chain of vertical vectors f_{1}, f_{2}, … (excess up, deficit down) from a back to a′ on
    one level, its vertices lettered, and ΔW_{max} dimensioned between the highest and lowest.
motion — ω(φ) of the true motion (at μω, μφ; :func:`motion_panel`)
    the φ axis at ω_m, the ordinates ω − ω_m, the curve and the levels ω_max, ω_min (thin dashed).

Many positions (N up to thousands) are drawn with every position in the curves; numbers, rays,
ordinates and carried lines are thinned to a readable count.
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from graphmech.methods.flywheel import FlywheelDesign
from graphmech.drawing.lettering import LETTER, number, scale_text, text_box_size
from graphmech.drawing.notation import WORDS, word
from graphmech.drawing.primitives import (XY, ArcArrow, Arrow, Circle, Label, Panel, Polyline, Primitive, Role,
                                         Segment, Sheet)
from graphmech.render.style import DEFAULT
from graphmech.scales import PAPER, round_scale
from graphmech.drawing.diagrams import (
    AXIS_OVERRUN,
    NICE_STEPS,
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
#: The J(φ) diagram's φ axis is about this long, mm (its μφ′ a round number of °/mm).
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
#: and J(φ) below it, mm.
GAP_LEFT, GAP_BELOW = 24.0, 12.0
#: The energy indicator's vectors stand this far apart (at most), its chain at most this wide, mm.
INDICATOR_STEP, INDICATOR_WIDTH = 16.0, 120.0
#: A diagram of ΔT alone (the energy indicator, or ΔT(φ) not beside the Wittenbauer diagram,
#: whose ΔT axis it shares) lower than ENERGY_LEAST at μT is drawn at μT′ = μT/k, k the
#: largest nice step that keeps it within ENERGY_MM, mm.
ENERGY_LEAST, ENERGY_MM = 30.0, 50.0
#: The true motion's ω − ω_m spans about this many mm (μω a round number), and ω(φ) is
#: sampled at this many points of the cycle.
MOTION_MM, MOTION_SAMPLES = 40.0, 145

#: The flywheel sheet's own words (laid out as graphmech.drawing.notation.WORDS: English, 中文,
#: русский); «…» are filled with the symbols of the same notation (braces are the lettering's
#: marks). Drawn text only.
FLY_WORDS: dict[str, tuple[str, str, str]] = {
    "A": ("A", "W", "A"),
    "A_red": ("A_{red}", "W_{e}", "A_{п}"),
    "A_d": ("A_{d}", "W_{d}", "A_{д}"),
    "A_r": ("A_{r}", "W_{r}", "A_{с}"),
    "DeltaT": ("ΔT", "ΔE", "ΔT"),
    "moment": ("Reduced moment «M»(φ), integrated by chords", "等效力矩 «M»(φ) 及其图解积分",
               "Приведённый момент «M»(φ), графическое интегрирование"),
    "work": ("Work diagrams «A»(φ): «Ared» (chords), «Ab» (dashed)", "功曲线 «A»(φ)：«Ared»（弦线），«Ab»（虚线）",
             "Диаграммы работ «A»(φ): «Ared» (хорды), «Ab» (штриховая)"),
    "energy": ("Increment of kinetic energy «T»(φ)", "动能增量 «T»(φ)", "Приращение кинетической энергии «T»(φ)"),
    "inertia": ("Reduced moment of inertia «J»(φ)", "等效转动惯量 «J»(φ)", "Приведённый момент инерции «J»(φ)"),
    "wittenbauer": ("Wittenbauer diagram «T»(«J»)", "能量–质量曲线（维滕鲍尔图）«T»(«J»)",
                    "Диаграмма Виттенбауэра «T»(«J»)"),
    "with": (" with «x»", "，附 «x»", " с «x»"),
    "indicator": ("Energy indicator diagram", "能量指示图", "Диаграмма избыточных работ"),
    "motion": ("Angular velocity of the true motion ω(φ)", "真实运动的角速度 ω(φ)",
               "Угловая скорость истинного движения ω(φ)"),
    "rundown": ("Run-down under the brake ω(t)", "制动停车过程 ω(t)", "Выбег под тормозом ω(t)"),
    "t allowed": ("t allowed", "允许 t", "допустимое t"),
    "stops": ("stops in time", "能按时停车", "останавливается вовремя"),
    "stops not": ("does NOT stop in time", "不能按时停车", "НЕ останавливается вовремя"),
    "required": ("required", "要求", "требуется"),
    "ordinates": ("ordinates ω − ω_{m}, the φ axis at ω_{m} = «w» rad/s",
                  "纵坐标 ω − ω_{m}，φ 轴位于 ω_{m} = «w» rad/s",
                  "ординаты ω − ω_{m}, ось φ на уровне ω_{m} = «w» рад/с"),
    "far tangents": ("the tangents are «a»° apart: they meet «d» mm left of the «T» axis, too far to find by "
                     "hand; k and l are read on the axis",
                     "两切线夹角仅 «a»°，交点在 «T» 轴左方 «d» mm，无法作图求得；k、l 在轴上量取",
                     "касательные расходятся на «a»°: они пересекаются в «d» мм левее оси «T», слишком далеко; "
                     "k и l читаются на оси"),
}


def fly_word(key: str, notation: str = "en", **symbols: str) -> str:
    """``key`` of :data:`FLY_WORDS` (or of the general WORDS) in ``notation``, its «…» filled in.

    >>> fly_word("M_red", "ru"), fly_word("energy", "zh", T=fly_word("DeltaT", "zh"))
    ('M_{п}', '动能增量 ΔE(φ)')
    """
    text = word(key, notation, FLY_WORDS if key in FLY_WORDS else WORDS)
    for name, value in symbols.items():
        text = text.replace(f"«{name}»", value)
    return text


def _syms(notation: str) -> dict[str, str]:
    """The symbols a caption is filled with."""
    return {"M": fly_word("M_red", notation), "J": fly_word("J_red", notation), "A": fly_word("A", notation),
            "T": fly_word("DeltaT", notation), "Ared": fly_word("A_red", notation)}


_LEFT = ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0))  # … left of a vertical one


# ----------------------------------------------------------------------------- helpers


def wittenbauer_every(x: np.ndarray, y: np.ndarray, size: float = NUMBER_SIZE) -> int:
    """Number every k-th point of the Wittenbauer curve: at most :data:`MOST_NUMBERS` numbers, and
    no more than the curve has room for — 1.25 numbers per number's width (plus clearance) of its
    length, but at least six.

    >>> t = np.linspace(0.0, 2 * np.pi, 12, endpoint=False)
    >>> wittenbauer_every(30 + 20 * np.cos(t), 20 * np.sin(t)), wittenbauer_every(np.zeros(36), np.sin(t.repeat(3)))
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
    for k in range(every, x.size, every):  # ticks at the numbered positions, up: clear of the numbers below
        items.append(Segment((float(x[k]), 0.0), (float(x[k]), 1.0), "label"))
    if ordinates:
        items += [Segment((float(x[k]), 0.0), (float(x[k]), float(y[k])), "construction")
                  for k in _ordinate_positions(x.size - 1, every) if abs(y[k]) > 1e-9]
    items.append(Polyline(_pts(x, y), curve_role))
    labels = [Label(name, (0.0, hi + AXIS_OVERRUN), ((0.0, -1.0),), LETTER),
              Label("φ", (float(x[-1]) + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), LETTER),
              Label("O", (0.0, 0.0), ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0)), LETTER)]
    return items, labels + phi_axis_numbers(x, every)


def _every(design: FlywheelDesign) -> int:
    x = design.x_mm
    return numbers_every(design.n, float(np.min(np.diff(x))))


def _constant_keys(design: FlywheelDesign) -> tuple[str, str]:
    """The constant moment's and its work's keys: M_d, A_d (driving) or M_r, A_r (resisting)."""
    return ("M_d", "A_d") if design.balance == "driving" else ("M_r", "A_r")


def energy_factor(design: FlywheelDesign) -> int:
    """k of μT′ = μT/k for a ΔT diagram drawn alone: 1 when ΔT spans ENERGY_LEAST mm or more at μT,
    else the largest nice step keeping it within ENERGY_MM.

    >>> phi = np.arange(12) * np.pi / 6
    >>> from graphmech.methods.flywheel import design_flywheel
    >>> energy_factor(design_flywheel(phi, np.full(12, 0.5), -50.0 + 5.0 * np.sin(phi), cycle=2 * np.pi,
    ...                               omega_m=100.0, delta=0.02, H_mm=40.0))
    10
    """
    t = design.energy_mm
    span = float(max(t.max(), 0.0) - min(t.min(), 0.0))
    if span >= ENERGY_LEAST or span <= 0.0:
        return 1
    return max(k for k in NICE_STEPS if k == 1 or k * span <= ENERGY_MM)


# ----------------------------------------------------------------------------- the panels
def moment_items(design: FlywheelDesign, every: int | None = None, notation: str = "en") -> list[Primitive]:
    """M_{red}(φ) at μM, μφ with the integration's construction and the constant moment (O at the origin)."""
    g = design.moment
    every = every or _every(design)
    assert g is not None and design.H_mm is not None and design.balancing_mm is not None  # ΔT given: no panel
    x, y, mean = g.x_mm, g.y_mm, g.mean_mm
    n, H, mb = design.n, design.H_mm, design.balancing_mm
    P = g.pole
    xe = float(x[-1])
    items, labels = _diagram(x, y, every, fly_word("M_red", notation), curve_role="given")
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
    name = fly_word(_constant_keys(design)[0], notation)
    result: list[Primitive] = [Segment(P, (0.0, mb), "label", dashed=True),
                               Segment((0.0, mb), (xe, mb), "result"), Circle(P, DOT, "result")]
    # the pole distance H, dimensioned under the fan of rays
    yd = lo - 6.0
    dim: list[Primitive] = [Segment(P, (P[0], yd - 1.5), "label"), Arrow((-H / 2.0, yd), (-H, yd), "label"),
                            Arrow((-H / 2.0, yd), (0.0, yd), "label")]
    if lo >= 0.0:
        dim.append(Segment((0.0, 0.0), (0.0, yd - 1.5), "label"))
    top = [Label("P", P, ((1.0, 0.0), (1.0, 0.5)), LETTER), Label("H", (-H / 2.0, yd), ((1.0, 0.0), (-1.0, 0.0)), LETTER),
           Label(name, (xe, mb), ((-1.0, 0.0),), LETTER)]
    return construction + items + result + dim + labels[:3] + top + labels[3:]


def work_items(design: FlywheelDesign, every: int | None = None, notation: str = "en") -> list[Primitive]:
    """A(φ) at μA = μT: the chord polygon A_{red} and the constant moment's work line (O at the origin)."""
    every = every or _every(design)
    x, a, b = design.x_mm, design.work_mm, design.balance_work_mm
    assert a is not None and b is not None  # ΔT given: no work panel
    xe = float(x[-1])
    both = np.concatenate([a, b])
    A = fly_word("A", notation)
    items, labels = _diagram(x, a, every, A)
    items[1] = Arrow((0.0, min(0.0, float(both.min())) - (3.0 if both.min() < 0 else 0.0)),
                     (0.0, max(0.0, float(both.max())) + AXIS_OVERRUN), "label")
    labels[0] = Label(A, (0.0, max(0.0, float(both.max())) + AXIS_OVERRUN), ((0.0, -1.0),), LETTER)
    work_name = fly_word(_constant_keys(design)[1], notation)
    line = Segment((0.0, 0.0), (xe, float(b[-1])), "result", dashed=True)
    far = int(np.argmax(np.abs(a)))
    names = [Label(fly_word("A_red", notation), (float(x[far]), float(a[far])), _dirs((-1.0, 0.0), (1.0, 0.0)), LETTER),
             Label(work_name, (xe, float(b[-1])), ((-1.0, -float(b[-1]) / xe),), LETTER)]
    return items + [line] + labels[:3] + names + labels[3:]


def energy_items(design: FlywheelDesign, every: int | None = None, notation: str = "en",
                 factor: int = 1) -> list[Primitive]:
    """ΔT(φ) at μT/``factor``, μφ with its extremes marked (O at the origin)."""
    every = every or _every(design)
    x, t = design.x_mm, design.energy_mm * factor
    T = fly_word("DeltaT", notation)
    items, labels = _diagram(x, t, every, T)
    marks: list[Primitive] = []
    for i, sub, up in ((design.energy_max_index, "max", True), (design.energy_min_index, "min", False)):
        p = (float(x[i]), float(t[i]))
        marks.append(Circle(p, 2 * DOT, "result"))
        off = (p[0], p[1] + (1.0 if up else -1.0))  # clear of the mark's dot
        labels.append(Label(f"{T}_{{{sub}}}", off, ((0.0, -1.0) if up else (0.0, 1.0),), LETTER))
    return items + marks + labels


def inertia_phi_scale(design: FlywheelDesign) -> float:
    """μφ′ of the J(φ) diagram, rad/mm: a round number of °/mm, the cycle about 40 mm long."""
    return math.radians(round_scale(math.degrees(design.cycle) / INERTIA_PHI_MM))


def inertia_items(design: FlywheelDesign, every: int | None = None, notation: str = "en") -> list[Primitive]:
    """J_{red}(φ) at μJ and μφ′: J to the right, φ downwards from the origin."""
    mu = inertia_phi_scale(design)
    n = design.n
    v = -np.append(design.phi, design.cycle) / mu
    xj = np.append(design.inertia_mm, design.inertia_mm[0])
    every = every or numbers_every(n, float(np.min(-np.diff(v))), NUMBER_SIZE * 0.6)  # numbers stacked: height
    right = float(xj.max())
    items: list[Primitive] = [Arrow((0.0, 0.0), (right + AXIS_OVERRUN, 0.0), "label"),
                              Arrow((0.0, 0.0), (0.0, float(v[-1]) - AXIS_OVERRUN), "label")]
    items += [Segment((0.0, float(v[k])), (-1.0, float(v[k])), "label") for k in range(every, n + 1, every)]
    items += [Segment((0.0, float(v[k])), (float(xj[k]), float(v[k])), "construction")
              for k in _ordinate_positions(n, every) if xj[k] > 1e-9]
    items.append(Polyline(_pts(xj, v), "given"))
    labels = [Label(fly_word("J_red", notation), (right + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), LETTER),
              Label("φ", (0.0, float(v[-1]) - AXIS_OVERRUN), ((0.0, 1.0),), LETTER)]
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
    items.append(Label(name, tip, ((-1.0, 0.0),), LETTER))
    return items


def wittenbauer_items(design: FlywheelDesign, notation: str = "en") -> list[Primitive]:
    """The Wittenbauer diagram at μJ, μT (O, J = 0 and ΔT = 0, at the origin)."""
    w = design.wittenbauer
    if w is None:
        raise OutOfDomain("the design has no Wittenbauer diagram: design it with need=('wittenbauer', …)")
    x, y, n = w.x_mm, w.y_mm, design.n
    box = _window(design)
    x0, x1, y0, y1, far = box
    items: list[Primitive] = [Arrow((0.0, y0 - 2.0), (0.0, y1 + AXIS_OVERRUN), "label"),
                              Arrow((0.0, 0.0), (x1 + AXIS_OVERRUN, 0.0), "label")]
    labels = [Label(fly_word("DeltaT", notation), (0.0, y1 + AXIS_OVERRUN), ((0.0, -1.0),), LETTER),
              Label(fly_word("J_red", notation), (x1 + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), LETTER)]
    # the points and the closed curve through them in the order of the positions
    if n <= MOST_DOTS:
        items += [Circle(p, DOT, "result") for p in _pts(x, y)]
    items.append(Polyline(_pts(x, y), "label", closed=True))  # thinner than the tangents
    # the tangents at ψmax (from above) and ψmin (from below), k and l on the ΔT axis
    tangent_dirs: list[XY] = []
    for c, t, tag, sub in ((w.k_mm, w.tan_psi_max, "k", "max"), (w.l_mm, w.tan_psi_min, "l", "min")):
        p0, p1 = _tangent(c, t, box[:4])
        items.append(Segment(p0, p1, "result"))
        tangent_dirs.append((1.0, t))
        seen = c >= y0
        at = (0.0, c) if seen else p0
        mark = _angle_mark(at, t, f"ψ_{{{sub}}}")
        items += [i for i in mark if not isinstance(i, Label)]
        labels += [i for i in mark if isinstance(i, Label)]
        if seen:
            items.append(Segment((-1.2, c), (1.2, c), "label"))
            labels.insert(2, Label(tag, (0.0, c), _dirs((1.0, t), (-1.0, -t), (0.0, 1.0), (0.0, -1.0)), LETTER))
        else:
            labels.append(Label(f"{tag} = {number(c)} mm", (0.0, y0 - 2.0), ((0.0, 1.0),), LETTER, italic=False))
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
        labels.append(Label("kl", (xd, (k + l) / 2.0), ((1.0, 0.0),), LETTER))
    # the point numbers: set outward from the curve's centroid, clear of the curve and the tangents
    every = wittenbauer_every(x, y)
    cx, cy = float(np.mean(x)), float(np.mean(y))
    for i in range(0, n, every):
        a, b = (x[i - 1], y[i - 1]), (x[(i + 1) % n], y[(i + 1) % n])
        p = (float(x[i]), float(y[i]))
        inward = _dirs((cx - p[0], cy - p[1]))
        avoid = _dirs((a[0] - p[0], a[1] - p[1]), (b[0] - p[0], b[1] - p[1]), *tangent_dirs,
                      *[(-d[0], -d[1]) for d in tangent_dirs]) + inward * 3
        labels.append(Label(str(i + 1), p, avoid, NUMBER_SIZE, italic=False))
    return items + labels


def indicator_items(design: FlywheelDesign, notation: str = "en", factor: int = 1) -> list[Primitive]:
    """The energy-indicator chain at μT/``factor``: vertical vectors from a to a′, ΔW_{max} dimensioned."""
    del notation  # its letters are the same in every notation
    e = design.indicator
    if e is None:
        raise OutOfDomain("the design has no energy indicator: design it with need=(…, 'indicator')")
    lv = [float(v) * factor for v in e.levels_mm]
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
                labels.append(Label(f"f_{{{i + 1}}}", (xs[i], (lv[i] + lv[i + 1]) / 2.0), ((0.0, 1.0), (0.0, -1.0)),
                                    LETTER))
        if i + 1 < m:
            items.append(Segment((xs[i], lv[i + 1]), (xs[i + 1], lv[i + 1]), "construction"))
    if m <= 26:
        names = [chr(ord("a") + j) for j in range(m)] + ["a′"]
        for j, name in enumerate(names):
            labels.append(Label(name, (where[j], lv[j]), ((0.0, 1.0), (0.0, -1.0)), LETTER))
    if e.dW_max_mm > 1e-9:
        xd = xs[-1] + 10.0
        hi, lo = lv[e.highest], lv[e.lowest]
        items += [Segment((where[e.highest], hi), (xd + 1.5, hi), "construction"),
                  Segment((where[e.lowest], lo), (xd + 1.5, lo), "construction")]
        mid = (hi + lo) / 2.0
        if hi - lo >= 2.0 * DEFAULT.arrow_length + 1.0:
            items += [Arrow((xd, mid), (xd, hi), "label"), Arrow((xd, mid), (xd, lo), "label")]
        else:
            items += [Arrow((xd, hi + 4.0), (xd, hi), "label"), Arrow((xd, lo - 4.0), (xd, lo), "label"),
                      Segment((xd, lo), (xd, hi), "label")]
        labels.insert(0, Label("ΔW_{max}", (xd, mid), ((-1.0, 0.0),), LETTER))
    return items + labels


def motion_panel(phi: np.ndarray, omega: np.ndarray, omega_m: float, mu_phi: float, notation: str = "en",
                 extremes: tuple[float, float] | None = None) -> Panel:
    """ω(φ) of the true motion: the φ axis at ω_m (μφ as the other diagrams), the ordinates
    ω − ω_m at a round μω so that they span about MOTION_MM, the levels ω_max and ω_min dashed.

    ``phi`` (rad from position 1, the cycle's end included) and ``omega`` (rad/s) sample one
    periodic cycle; ``extremes`` are (ω_max, ω_min) as the check found them (default: the samples').

    >>> phi = np.linspace(0.0, 2 * np.pi, 73)
    >>> p = motion_panel(phi, 100.0 + 0.02 * np.sin(phi), 100.0, math.radians(2.5))
    >>> p.name, p.scales[0], p.notes[0]
    ('motion', ('omega', 0.001), 'μ_{ω} = 0.001 (rad/s)/mm, μ_{φ} = 2.5 °/mm')
    """
    hi, lo = extremes if extremes is not None else (float(omega.max()), float(omega.min()))
    span = max(hi - omega_m, 0.0) - min(lo - omega_m, 0.0)
    mu = round_scale(span / MOTION_MM) if span > 0.0 else round_scale(max(abs(omega_m), 1.0) * 1e-6)
    x = np.asarray(phi, dtype=float) / mu_phi
    y = (np.asarray(omega, dtype=float) - omega_m) / mu
    items: list[Primitive] = [Arrow((0.0, 0.0), (float(x[-1]) + AXIS_OVERRUN, 0.0), "label"),
                              Arrow((0.0, min(0.0, float(y.min())) - 4.0), (0.0, max(0.0, float(y.max())) + AXIS_OVERRUN),
                                    "label")]
    labels = [Label("ω", (0.0, max(0.0, float(y.max())) + AXIS_OVERRUN), ((0.0, -1.0),), LETTER),
              Label("φ", (float(x[-1]) + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), LETTER),
              Label("ω_{m}", (0.0, 0.0), ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0)), LETTER)]
    xe = float(x[-1])
    for value, sub in ((hi, "max"), (lo, "min")):
        yv = (value - omega_m) / mu
        items.append(Segment((0.0, yv), (xe, yv), "construction", dashed=True))
        labels.append(Label(f"ω_{{{sub}}}", (xe, yv), ((-1.0, 0.0),), LETTER))
    items.append(Polyline(_pts(x, y), "result"))
    ticks = [k * 30.0 for k in range(1, int(math.degrees(float(phi[-1])) // 30.0) + 1)]  # every 30° of φ
    for deg in ticks:
        xt = math.radians(deg) / mu_phi
        items.append(Segment((xt, 0.0), (xt, -1.0), "label"))
        if deg % 90.0 == 0.0:
            labels.append(Label(f"{deg:g}°", (xt, 0.0), ((0.0, 1.0), (1.0, 0.0), (-1.0, 0.0)), NUMBER_SIZE, italic=False))
    delta = (hi - lo) / omega_m
    notes = (f"{scale_text('omega', mu)}, {scale_text('phi', mu_phi)}",
             fly_word("ordinates", notation, w=number(omega_m)),
             f"ω_{{max}} − ω_{{min}} = {number(hi - lo)} rad/s, δ = {number(delta)}")
    title = fly_word("motion", notation)
    return Panel("motion", title, (*items, *labels), notes, row=2, scales=(("omega", mu), ("phi", mu_phi)))


# ----------------------------------------------------------------------------- notes
def _notes(design: FlywheelDesign, members: Sequence[str], notation: str, factor: int) -> tuple[str, ...]:
    s = design.scales
    out: list[str] = []
    const = fly_word(_constant_keys(design)[0], notation)
    T = fly_word("DeltaT", notation)
    mu_A = " (= μ_{A})" if design.moment is not None else ""  # ΔT given: nothing integrated
    if "moment" in members:
        assert design.H_mm is not None and design.balancing_moment is not None
        out += [f"{scale_text('M', s['M'])}, {scale_text('phi', s['phi'])}",
                f"H = {number(design.H_mm)} mm; {const} = μ_{{M}}·⟨{const}⟩ = {number(design.balancing_moment)} N·m"]
    if "work" in members:
        out += [f"μ_{{A}} = μ_{{M}}·μ_{{φ}}·H: {scale_text('T', s['T']).replace('μ_{T}', 'μ_{A}')}, "
                f"{scale_text('phi', s['phi'])}"]
    alone = "wittenbauer" not in members
    if "energy" in members or "indicator" in members:
        if alone and factor > 1:
            out += [f"μ_{{T}}′ = μ_{{T}}/{factor} = {scale_text('T', s['T'] / factor).split(' = ', 1)[1]}, "
                    f"{scale_text('T', s['T'])}{mu_A}"]
        else:
            out += [f"{scale_text('T', s['T'])}{mu_A}"]
        if "energy" in members:
            out[-1] += f", {scale_text('phi', s['phi'])}"
    if "inertia" in members:
        out += [f"{scale_text('J', s['J'])}; {fly_word('J_red', notation)}(φ): "
                f"{scale_text('phi', inertia_phi_scale(design), '′')}"]
    if "wittenbauer" in members:
        w = design.wittenbauer
        assert w is not None and design.J_F is not None
        if "inertia" not in members:
            out += [scale_text("J", s["J"])]
        reading = "ω = ω_{m}(1 ± δ/2)" if design.form == "exact" else "ω^{2} = ω_{m}^{2}(1 ± δ)"
        out += [f"tan ψ = μ_{{J}}·ω^{{2}}/(2μ_{{T}}), {reading}: tan ψ_{{max}} = {number(w.tan_psi_max)} "
                f"(ψ_{{max}} = {number(w.psi_max_deg)}°), tan ψ_{{min}} = {number(w.tan_psi_min)} "
                f"(ψ_{{min}} = {number(w.psi_min_deg)}°)",
                f"k = {number(w.k_mm)} mm, l = {number(w.l_mm)} mm, kl = {number(w.kl_mm)} mm: "
                f"{fly_word('J_F', notation)} = μ_{{T}}·kl/(ω_{{m}}^{{2}}δ) = {number(design.J_F)} kg·m^{{2}}"]
        if w.ill_conditioned:
            out += [fly_word("far tangents", notation, a=number(w.angle_between_deg, 2),
                             d=number(-w.intersection[0]), T=T)]
    if "indicator" in members:
        assert design.DeltaW_max is not None and design.J_F_indicator is not None
        out += [f"ΔW_{{max}} = {number(design.DeltaW_max)} J, J_{{mean}} = {number(design.J_mean)} kg·m^{{2}}",
                f"{fly_word('J_F', notation)} = ΔW_{{max}}/(ω_{{m}}^{{2}}δ) − J_{{mean}} = "
                f"{number(design.J_F_indicator)} kg·m^{{2}}"]
    return tuple(out)


def _scales(design: FlywheelDesign, members: Sequence[str], factor: int) -> tuple[tuple[str, float], ...]:
    """The paper scales of a panel showing ``members`` (Panel.scales)."""
    s = design.scales
    out: list[tuple[str, float]] = []
    if "moment" in members:
        out.append(("M", s["M"]))
    if "wittenbauer" in members or "work" in members:
        out.append(("T", s["T"]))
    elif "energy" in members or "indicator" in members:
        out.append(("T", s["T"] / factor))
    if "inertia" in members or "wittenbauer" in members:
        out.append(("J", s["J"]))
    if any(m in members for m in ("moment", "work", "energy")):
        out.append(("phi", s["phi"]))
    if "inertia" in members:
        out.append(("phi", inertia_phi_scale(design)))
    return tuple(out)


# ----------------------------------------------------------------------------- the sheet
def _beside(design: FlywheelDesign, members: Sequence[str], notation: str = "en") -> list[Primitive]:
    """The Wittenbauer diagram with ΔT(φ) on the left and J(φ) below, points carried across."""
    w = design.wittenbauer
    assert w is not None
    witt, wlabels = _split(wittenbauer_items(design, notation))
    items: list[Primitive] = []
    labels: list[Label] = []
    x, y = w.x_mm, w.y_mm
    n = design.n
    carried = range(0, n, count_every(n, MOST_CARRIED))
    if "energy" in members:
        xe = design.x_mm
        dx = -(GAP_LEFT + float(xe[-1]) + AXIS_OVERRUN)
        it, lb = _split(energy_items(design, notation=notation))
        items += [moved(i, dx, 0.0) for i in it]
        labels += [moved(i, dx, 0.0) for i in lb]
        items += [Segment((dx + float(xe[k]), float(y[k])), (float(x[k]), float(y[k])), "construction")
                  for k in carried if abs(float(x[k]) - dx - float(xe[k])) > 1e-9]
    if "inertia" in members:
        dy = _window(design)[2] - 2.0 - GAP_BELOW
        it, lb = _split(inertia_items(design, notation=notation))
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


def panel_title(group: Sequence[str], design: FlywheelDesign, notation: str = "en") -> str:
    """The caption of the panel showing ``group``, in ``notation``.

    >>> from graphmech.methods.flywheel import design_flywheel
    >>> phi = np.arange(12) * np.pi / 6
    >>> d = design_flywheel(phi, np.full(12, 0.5), -50.0 + 100.0 * np.sin(phi), cycle=2 * np.pi, omega_m=100.0,
    ...                     delta=0.02)
    >>> panel_title(("moment",), d, "ru"), panel_title(("energy", "wittenbauer"), d, "zh")
    ('Приведённый момент M_{п}(φ), графическое интегрирование', '能量–质量曲线（维滕鲍尔图）ΔE(J_{e})，附 ΔE(φ)')
    """
    sy = _syms(notation)
    if "wittenbauer" in group:
        return fly_word("wittenbauer", notation, **sy) + "".join(
            fly_word("with", notation, x=f"{sy['T']}(φ)" if g == "energy" else f"{sy['J']}(φ)")
            for g in group if g != "wittenbauer")
    if group[0] == "work":
        return fly_word("work", notation, Ab=fly_word(_constant_keys(design)[1], notation), **sy)
    return fly_word(group[0], notation, **sy)


def flywheel_sheet(title: str, design: FlywheelDesign, show: Sequence[str],
                   page_size: tuple[float, float] = PAPER["A3"], footer: tuple[str, ...] = (),
                   notation: str = "en") -> Sheet:
    """The sheet of the graphical flywheel design: the panels of ``show`` in the order of :data:`PANELS`.

    M(φ) and A(φ) stand in the first row; ΔT(φ), J(φ), the Wittenbauer diagram and the energy
    indicator in the second. A panel's name is its entry of ``show`` (the Wittenbauer diagram's
    panel: its members joined by ``+``); its notes state its scales and what it finds, its
    ``scales`` the scales of its paper. ΔT(φ) alone and the energy indicator are drawn at
    μT′ = μT/k (:func:`energy_factor`) when at μT they would be too low to read.

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
    notation : "en", "zh" or "ru"
        Whose symbols and captions (drawn text only).

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
    k = energy_factor(design)
    build = {"moment": lambda: moment_items(design, every, notation),
             "work": lambda: work_items(design, every, notation),
             "energy": lambda: energy_items(design, every, notation, k), "inertia": lambda: inertia_items(design, None, notation),
             "indicator": lambda: indicator_items(design, notation, k)}
    panels = []
    for group in members:
        items = _beside(design, group, notation) if "wittenbauer" in group else build[group[0]]()
        row = 0 if group[0] in ("moment", "work") else 1
        panels.append(Panel("+".join(group), panel_title(group, design, notation), tuple(items),
                            _notes(design, group, notation, k), row=row, scales=_scales(design, group, k)))
    return Sheet(title, tuple(panels), (page_size[0], page_size[1]), tuple(footer))


__all__ = ["FLY_WORDS", "PANELS", "energy_factor", "energy_items", "fly_word", "flywheel_sheet", "indicator_items",
           "inertia_items", "moment_items", "motion_panel", "panel_members", "panel_title", "wittenbauer_items",
           "work_items"]
