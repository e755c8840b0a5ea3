"""A graphic scale bar for each scale μ of a panel, drawn under its caption, so that a figure
shrunk into a report stays measurable (FIGURES.md, "Scales").

The bar is a round value of the quantity — 1, 2 or 5 × 10^k of its unit, 0.05 m, 0.2 m/s, 50°
— drawn at the panel's μ, 20 to 50 mm of paper (the one nearest 30 mm). It is cut into divisions (five
of 0.2 for a 1, four of 0.5 for a 2, five of 1 for a 5), alternately black and white as on a
map; the numbers stand under the ticks (every tick where they fit, else 0, the middle and the
end), the scale's symbol (μv) to the left of the bar and the unit to its right. An angle's
scale ("phi", "psi": kept in rad/mm) is measured in degrees, as its statement is written.

Coordinates: a bar's block is laid out from its top-left corner, page millimetres, y down.

>>> bar = scale_bar("v", 0.005)
>>> bar.value, bar.length, bar.divisions, bar.unit
(0.2, 40.0, 4, 'm/s')
>>> [t for _, t in bar.ticks]
['0', '0.05', '0.1', '0.15', '0.2']
>>> b = scale_bar("phi", math.radians(2.0))
>>> b.value, b.length, b.unit
(50.0, 25.0, '°')
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.drawing.lettering import BASELINE_DROP, number, scale_symbol, text_box_size
from graphmech.render.backend import Backend
from graphmech.render.style import DEFAULT, Style
from graphmech.scales import ANGLE_SCALES, SCALE_INFO

#: The shortest and longest bar, paper mm: shorter is hard to measure with, longer crowds the
#: caption. Mantissas 1, 2, 5 step by at most 2.5×, so the round value always falls in between.
BAR_RANGE_MM = (20.0, 50.0)
#: The length a bar comes nearest to, mm.
BAR_TARGET_MM = 30.0
#: Round values of a bar, × 10^k, and how many divisions each is cut into.
BAR_MANTISSAS = ((1.0, 5), (2.0, 4), (5.0, 5))
#: The bar's thickness, the gap from it to its numbers, the least gap to the symbol and unit, mm.
BAR_HEIGHT = 1.2
NUMBER_GAP = 1.0
SIDE_GAP = 2.0
#: The least free space between two neighbouring numbers, mm.
NUMBER_SPACING = 1.5


def unit_of(symbol: str) -> str:
    """The unit a scale's bar is measured in: its μ's unit without the "per mm".

    >>> unit_of("a"), unit_of("phi"), unit_of("M"), unit_of("l")
    ('m/s²', '°', 'N·m', 'm')
    """
    unit = SCALE_INFO[symbol][1].removesuffix("/mm")
    return unit[1:-1] if unit.startswith("(") and unit.endswith(")") else unit


@dataclass(frozen=True)
class ScaleBar:
    """One scale bar, laid out from its block's top-left corner (page mm, y down).

    Attributes
    ----------
    symbol : str
        The scale's key in :data:`graphmech.scales.SCALE_INFO` ("v", "phi" …).
    name : str
        The scale's symbol as the caption writes it ("μv").
    unit : str
        What the numbers count ("m/s", "°").
    value : float
        The whole bar in ``unit``: a round number.
    length : float
        The whole bar on paper, mm (``value`` at the panel's μ).
    divisions : int
        How many alternately black and white parts the bar is cut into.
    ticks : tuple of (float, str)
        Where a number stands (mm from the bar's left end) and its text.
    size : float
        The numbers', symbol's and unit's font size, mm.
    """

    symbol: str
    name: str
    unit: str
    value: float
    length: float
    divisions: int
    ticks: tuple[tuple[float, str], ...]
    size: float

    def _gaps(self) -> tuple[float, float]:
        """Room from the symbol to the bar and from the bar to the unit, mm: clear of the
        first and the last number's halves, which stand under the bar's ends."""
        w_first = text_box_size(self.ticks[0][1], self.size)[0]
        w_last = text_box_size(self.ticks[-1][1], self.size)[0]
        return (max(SIDE_GAP, w_first / 2.0 + NUMBER_SPACING), max(SIDE_GAP, w_last / 2.0 + NUMBER_SPACING))

    @property
    def bar_left(self) -> float:
        """The bar's left end from the block's left edge, mm (after the symbol)."""
        return text_box_size(self.name, self.size)[0] + self._gaps()[0]

    @property
    def bar_top(self) -> float:
        """The bar's top edge from the block's top, mm: the symbol and unit are centred on it."""
        return max(self.size / 2.0 - BAR_HEIGHT / 2.0, 0.0)

    @property
    def width(self) -> float:
        """The whole block's width, mm: symbol, bar, unit."""
        return self.bar_left + self.length + self._gaps()[1] + text_box_size(self.unit, self.size)[0]

    @property
    def height(self) -> float:
        """The whole block's height, mm: bar, gap, one line of numbers."""
        return self.bar_top + BAR_HEIGHT + NUMBER_GAP + self.size


def scale_bar(symbol: str, mu: float, size: float = DEFAULT.note_size) -> ScaleBar:
    """The bar of the scale ``symbol`` (a key of SCALE_INFO) at ``mu`` SI units per mm.

    Raises
    ------
    ValueError
        For an unknown symbol or a μ that is not positive and finite.
    """
    if symbol not in SCALE_INFO:
        raise ValueError(f"no scale {symbol!r}; the scales are {', '.join(SCALE_INFO)}")
    if not (mu > 0.0 and math.isfinite(mu)):
        raise ValueError(f"a scale bar needs a positive, finite μ, not {mu!r}")
    per_mm = math.degrees(mu) if symbol in ANGLE_SCALES else mu  # an angle is written in degrees
    lo, hi = BAR_RANGE_MM
    k = math.floor(math.log10(lo * per_mm))
    # the round values whose bar is 20 … 50 mm (one at least: 1, 2, 5 step by ≤ 2.5×), and of
    # them the one nearest BAR_TARGET_MM (in ratio; the longer one on a tie)
    found = [(float(f"{m}e{e}"), n) for e in (k, k + 1) for m, n in BAR_MANTISSAS
             if lo * (1.0 - 1e-12) <= float(f"{m}e{e}") / per_mm <= hi * (1.0 + 1e-12)]
    value, divisions = min(reversed(found), key=lambda c: abs(math.log(c[0] / per_mm / BAR_TARGET_MM)))
    length = value / per_mm
    step = value / divisions
    every = tuple((length * i / divisions, number(step * i)) for i in range(divisions + 1))
    ticks = every if _fit(every, size) else _ends(every, divisions, size)
    return ScaleBar(symbol, scale_symbol(symbol), unit_of(symbol), value, length, divisions, ticks, size)


def _fit(ticks: tuple[tuple[float, str], ...], size: float) -> bool:
    """Whether numbers centred at these places stand clear of one another."""
    for (x0, t0), (x1, t1) in zip(ticks[:-1], ticks[1:]):
        half = (text_box_size(t0, size)[0] + text_box_size(t1, size)[0]) / 2.0
        if x1 - x0 < half + NUMBER_SPACING:
            return False
    return True


def _ends(every: tuple[tuple[float, str], ...], divisions: int, size: float) -> tuple[tuple[float, str], ...]:
    """0 and the end, and the middle tick where there is one and its number fits."""
    ends = (every[0], every[-1])
    if divisions % 2 == 0:
        with_middle = (every[0], every[divisions // 2], every[-1])
        if _fit(with_middle, size):
            return with_middle
    return ends


def draw_scale_bar(bar: ScaleBar, at: tuple[float, float], backend: Backend[object],
                   style: Style = DEFAULT) -> None:
    """Draw ``bar`` with its block's top-left corner at ``at`` (page mm, y down)."""
    x0 = at[0] + bar.bar_left
    top = at[1] + bar.bar_top
    bottom = top + BAR_HEIGHT
    part = bar.length / bar.divisions
    for i in range(bar.divisions):
        a, b = x0 + i * part, x0 + (i + 1) * part
        box = [(a, top), (b, top), (b, bottom), (a, bottom)]
        backend.polyline(box, "hatch", closed=True, filled=i % 2 == 0)
    mid = (top + bottom) / 2.0 + BASELINE_DROP * bar.size
    before, after = bar._gaps()
    backend.text(bar.name, (x0 - before, mid), bar.size, "end", False, "text")
    backend.text(bar.unit, (x0 + bar.length + after, mid), bar.size, "start", False, "text")
    base = bottom + NUMBER_GAP + bar.size / 2.0 + BASELINE_DROP * bar.size
    for x, text in bar.ticks:
        backend.text(text, (x0 + x, base), bar.size, "middle", False, "text")
