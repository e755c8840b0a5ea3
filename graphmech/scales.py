"""Scale factors μ: real quantity per millimetre of drawing; round-number choice; paper sizes.

>>> round_scale(0.0031)
0.005
>>> round_scale(0.0021)
0.0025
>>> round_scale(2.0)
2.0
"""
from __future__ import annotations

import math

from graphmech.errors import OutOfDomain
from graphmech.tolerances import SCALE_RANGE_SI

#: Paper sizes in mm (width, height), landscape unless named "-portrait" (ISO 216: a course
#: project's sheet is A1 or A2, a figure A4 or A3).
PAPER = {
    "A4": (297.0, 210.0),
    "A4-portrait": (210.0, 297.0),
    "A3": (420.0, 297.0),
    "A3-portrait": (297.0, 420.0),
    "A2": (594.0, 420.0),
    "A2-portrait": (420.0, 594.0),
    "A1": (841.0, 594.0),
    "A1-portrait": (594.0, 841.0),
}

#: ``[page] size = "fit"`` (and ``--page fit``): the page is cropped to the drawing with the
#: page margin. Its scales μ are chosen — and a kind's "does the sheet fit its page" is
#: judged — for this working area, so a fit figure is drawn as it would be on that paper.
FIT = "fit"
FIT_WORKING_AREA = PAPER["A3"]

#: The mantissas textbooks use for scales: 1, 2, 2.5, 5 × 10^k.
ROUND_MANTISSAS = (1.0, 2.0, 2.5, 5.0, 10.0)

#: Symbols and units of the scales used by the kinematics methods.
SCALE_INFO = {
    "l": ("μl", "m/mm"),
    "v": ("μv", "(m/s)/mm"),
    "a": ("μa", "(m/s²)/mm"),
    "s": ("μs", "m/mm"),
    "phi": ("μφ", "°/mm"),  # kept in rad/mm, written in degrees per mm as books do
    "psi": ("μψ", "°/mm"),  # an oscillating follower's swing, kept in rad/mm, written like φ
    "epsilon": ("με", "(rad/s²)/mm"),  # an angular acceleration (ω has "omega")
    "M": ("μM", "(N·m)/mm"),
    "J": ("μJ", "(kg·m²)/mm"),
    "T": ("μT", "J/mm"),
    "t": ("μt", "s/mm"),
    "omega": ("μω", "(rad/s)/mm"),
    "F": ("μF", "N/mm"),
    "W": ("μW", "(kg·m)/mm"),
    # a gear sheet's tooth and contact-zone panels: each drawing is lettered μl, as the book does
    "tooth": ("μl", "m/mm"),
    "zones": ("μl", "m/mm"),
    "generation": ("μl", "m/mm"),
}


#: Scales of an angle, kept in rad/mm and written in degrees per mm as books do.
ANGLE_SCALES = ("phi", "psi")


def round_scale(minimum: float) -> float:
    """The smallest round scale (1, 2, 2.5, 5 × 10^k) that is ≥ ``minimum`` (> 0)."""
    if not (minimum > 0.0 and math.isfinite(minimum)):
        raise OutOfDomain(f"a scale must be positive and finite, not {minimum!r}")
    k = math.floor(math.log10(minimum))
    for m in ROUND_MANTISSAS:
        value = float(f"{m}e{k}")  # exact decimal, no 0.30000000000000004
        if value >= minimum * (1 - 1e-12):
            return value
    return float(f"1e{k + 1}")


def round_scale_below(most: float) -> float:
    """The largest round scale (1, 2, 2.5, 5 × 10^k) that is ≤ ``most`` (> 0): the coarsest
    scale that still draws a length at least as long as ``most`` asks.

    >>> round_scale_below(3.214), round_scale_below(2.5), round_scale_below(0.0078)
    (2.5, 2.5, 0.005)
    """
    if not (most > 0.0 and math.isfinite(most)):
        raise OutOfDomain(f"a scale must be positive and finite, not {most!r}")
    k = math.floor(math.log10(most))
    for m in reversed(ROUND_MANTISSAS):
        value = float(f"{m}e{k}")
        if value <= most * (1 + 1e-12):
            return value
    return float(f"1e{k - 1}")  # (not reached: 1e{k} ≤ most)


def is_round_scale(value: float) -> bool:
    """True for 1, 2, 2.5, 5 × 10^k (to round-off).

    >>> is_round_scale(2.5), is_round_scale(1.25), is_round_scale(0.25)
    (True, False, True)
    """
    return value > 0.0 and math.isfinite(value) and abs(round_scale(value) - value) <= 1e-9 * value


def format_scale(symbol: str, value: float) -> str:
    """The note written on a drawing, e.g. ``μv = 0.005 (m/s)/mm``.

    >>> format_scale("phi", math.radians(2.0))
    'μφ = 2 °/mm'
    """
    sym, unit = SCALE_INFO[symbol]
    if symbol in ANGLE_SCALES:
        value = math.degrees(value)
    return f"{sym} = {value:.6g} {unit}"

def scale_out_of_range(si: float) -> str:
    """Why a stated scale μ (SI per drawing mm) cannot be drawn at, or "" (tolerances.SCALE_RANGE_SI).

    >>> scale_out_of_range(0.002), scale_out_of_range(5e-324)[:11]
    ('', 'under 1e-15')
    """
    lo, hi = SCALE_RANGE_SI
    if lo <= si <= hi:
        return ""
    return f"{'under' if si < lo else 'over'} {lo if si < lo else hi:g} SI units per mm once converted: no page shows a figure at that scale"


#: A figure drawn at a stated μ must come out between these sizes on the paper, mm: under 0.1 mm
#: it is a dot; over 10 m of paper (eight A0 sheets) no page shows it and its dashes and hatching
#: take minutes to draw (1e-300 m/mm drew kilometres of 1e298).
DRAWN_SIZE_RANGE_MM = (0.1, 1e4)


def drawn_size_problem(size: float, mu: float, symbol: str = "l", what: str = "the mechanism",
                       note: str | None = None) -> str | None:
    """Why a figure ``size`` across (SI units of ``symbol``'s scale) cannot be drawn at ``mu``
    (SI per mm); None if it can. ``note`` writes the scale where its unit is not ``symbol``'s
    (an oscillating follower's μs is an angle per mm).

    >>> drawn_size_problem(0.1, 0.001) is None, drawn_size_problem(0.1, 1e-300)[:38]
    (True, 'μl = 1e-300 m/mm draws the mechanism 1')
    >>> drawn_size_problem(4.0, 1e-9, "v", "the velocity polygon")[:52]
    'μv = 1e-09 (m/s)/mm draws the velocity polygon 4e+09'
    """
    lo, hi = DRAWN_SIZE_RANGE_MM
    drawn = size / mu
    if lo <= drawn <= hi:
        return None
    sym, unit = SCALE_INFO[symbol]
    note = note or f"{sym} = {mu:g} {unit}"
    if not math.isfinite(drawn):
        return f"{what} is too large for double precision (the scene's sizes are too extreme) at {note}"
    return (f"{note} draws {what} {drawn:.3g} mm across: choose {sym} so that it is "
            f"{lo:g} … {hi:g} mm")


#: The φ axis of a diagram (a whole turn) is between these lengths on the drawing, mm.
PHI_AXIS_RANGE_MM = (10.0, 2000.0)


def phi_axis_problem(mu_phi: float) -> str | None:
    """Why a whole turn's φ axis cannot be drawn at ``mu_phi`` (rad/mm); None if it can.

    >>> phi_axis_problem(math.radians(2.5)) is None, phi_axis_problem(math.radians(2.5e-6))[:39]
    (True, 'μφ makes the φ axis of a turn 1.44e+08 ')
    """
    axis = 2.0 * math.pi / mu_phi
    lo, hi = PHI_AXIS_RANGE_MM
    if lo <= axis <= hi:
        return None
    return (f"μφ makes the φ axis of a turn {axis:.3g} mm long: choose μφ so that it "
            f"is {lo:g} … {hi:g} mm (phi_deg_per_mm = {360 / hi:g} … {360 / lo:g})")
