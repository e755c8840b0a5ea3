"""Exact characteristics of a linkage's basic loop, in closed form (the cosine rule).

The linkage characteristics a course asks for before synthesis — the Grashof class, the two
extreme (dead-centre) positions of the output, the swing angle ψ or stroke H, the crank angle
θ between the extreme positions, the time ratio K = (180° + θ)/(180° − θ) and the smallest
transmission angle γ_min — for the three loops the textbooks treat:

four-bar (crank AB = a, coupler BC = b, rocker CD = c, frame AD = d)
    At an extreme position crank and coupler are collinear, so |AC| = b − a (folded) or b + a
    (extended); the triangle A–C–D then has all three sides known and the cosine rule gives the
    angle at A. The transmission angle is the angle BCD (or its supplement), whose cosine
    (b² + c² − BD²)/(2bc) is monotone in BD² = a² + d² − 2ad·cos(φ − φ_AD): its extremes are at
    φ − φ_AD = 0 and 180°.
slider-crank with offset (crank a, coupler b, offset e of the pivot A from the guide)
    |AC| = b ∓ a again, and the slider lies √(AC² − e²) along the guide from the foot of A.
    The pressure angle α has sin α = (distance of B from the guide)/b, largest (a + |e|)/b.
guide bar (crank a about A, the bar pivoted on the frame at C, |AC| = d, a < d)
    At the extremes the bar is tangent to the crank circle: cos ∠CAB = a/d, ψ = θ =
    2·arcsin(a/d); the block drives the bar at right angles, so γ = 90° throughout.

Rotatability (the Grashof classes) is decided here by the closure of the triangle B–C–D over
the whole range of BD, not by Grashof's sum rule, so that the drawn classification (which uses
the sum rule) is checked by something else. Nothing here uses the construction code.

All lengths in any one unit, angles in radians unless a name ends in ``_deg``.
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import Callable

from graphmech.errors import NotApplicable

__all__ = [
    "ExactCharacteristics",
    "fourbar",
    "fourbar_class",
    "grashof_ranges",
    "guide_bar",
    "offset_guide_bar",
    "slider_crank",
    "time_ratio",
    "timing",
]

#: Relative slack within which two sums of link lengths count as equal (a change point).
EQUAL_REL = 1e-12
#: Strokes whose crank angles differ by less than this (rad) count as equal: position 1 is then
#: the extended position (the methods' drawing makes the same choice).
TIE = 1e-9


@dataclass(frozen=True)
class ExactCharacteristics:
    """The characteristics of one loop.

    Attributes
    ----------
    kind : str
        ``"fourbar"``, ``"slider_crank"`` or ``"guide_bar"``.
    grashof : str
        ``"crank_rocker_AB"`` (the crank turns fully), ``"crank_rocker_CD"``, ``"double_crank"``,
        ``"double_rocker"``, ``"change_point"`` (Grashof's equality), or for the other loops
        ``"crank"`` (the crank turns fully) / ``"rotating_guide_bar"``.
    phi_start, phi_end : float or None
        The crank's absolute angles at the extreme positions (rad in [0, 2π)): the working
        (slow) stroke runs from ``phi_start`` to ``phi_end`` in the crank's sense. None when the
        output turns fully too (a double crank, a parallelogram): it has no extreme positions.
    theta : float or None
        The crank angle between the extreme positions, rad.
    psi : float or None
        The rocker's (bar's) swing angle, rad (None for a slider or without extremes).
    stroke : float or None
        The slider's stroke H (None for a rocker).
    gamma_min : float
        The smallest transmission angle, rad.
    gamma_min_at : float
        An absolute crank angle where it occurs (rad in [0, 2π)).
    """

    kind: str
    grashof: str
    phi_start: float | None
    phi_end: float | None
    theta: float | None
    psi: float | None
    stroke: float | None
    gamma_min: float
    gamma_min_at: float

    @property
    def K(self) -> float | None:
        """The time ratio (180° + θ)/(180° − θ) (None without extreme positions)."""
        return None if self.theta is None else time_ratio(self.theta)


def time_ratio(theta: float) -> float:
    """K = (π + θ)/(π − θ), θ in rad.

    >>> round(time_ratio(math.radians(30.0)), 12)
    1.4
    """
    return (math.pi + theta) / (math.pi - theta)


def timing(theta: float, t_work: float) -> dict[str, float]:
    """Crank angles and times of the working and return strokes, from θ and the working time.

    The crank turns uniformly: the working stroke takes 180° + θ of its turn, the return
    180° − θ.

    >>> t = timing(math.radians(30.0), 7.0)
    >>> round(t["t_return"], 12), round(t["crank_period"], 12), round(t["n_crank"], 12)
    (5.0, 12.0, 5.0)
    """
    work, back = math.pi + theta, math.pi - theta
    period = t_work * 2.0 * math.pi / work
    return {"phi_work": work, "phi_return": back, "t_work": t_work, "t_return": period - t_work,
            "crank_period": period, "n_crank": 60.0 / period}


def _angle_at(adjacent1: float, adjacent2: float, opposite: float) -> float:
    """The angle between two sides of a triangle from its three sides (cosine rule), rad."""
    c = (adjacent1 ** 2 + adjacent2 ** 2 - opposite ** 2) / (2.0 * adjacent1 * adjacent2)
    return math.acos(max(-1.0, min(1.0, c)))


def _wrap(x: float) -> float:
    return x % (2.0 * math.pi)


def _equal(x: float, y: float, size: float) -> bool:
    return abs(x - y) <= EQUAL_REL * size


def _turns(a: float, b: float, c: float, d: float) -> bool:
    """Whether link a, hinged to the frame d, turns fully: triangle (b, c, BD) closes for every
    BD between |d − a| and d + a."""
    size = a + b + c + d
    return abs(b - c) <= abs(d - a) + EQUAL_REL * size and d + a <= b + c + EQUAL_REL * size


def fourbar_class(a: float, b: float, c: float, d: float) -> str:
    """The Grashof class of a four-bar (crank a, coupler b, rocker c, frame d).

    ``"change_point"`` when the four links can lie on one line (two of them sum to the other
    two), ``"none"`` when it cannot be assembled at all.

    >>> fourbar_class(28, 52, 50, 72), fourbar_class(50, 30, 50, 30), fourbar_class(50, 50, 35, 30)
    ('crank_rocker_AB', 'change_point', 'double_crank')
    """
    size = a + b + c + d
    if max(a, b, c, d) >= size - max(a, b, c, d) - EQUAL_REL * size:
        return "none" if max(a, b, c, d) > size - max(a, b, c, d) + EQUAL_REL * size else "change_point"
    if any(_equal(x, size - x, size) for x in (a + b, a + c, a + d)):
        return "change_point"
    crank, rocker = _turns(a, b, c, d), _turns(c, b, a, d)
    if crank and rocker:
        return "double_crank"
    if crank:
        return "crank_rocker_AB"
    if rocker:
        return "crank_rocker_CD"
    return "double_rocker"


def grashof_ranges(b: float, c: float, d: float) -> list[tuple[str, float, float]]:
    """The classes a four-bar takes as the crank's length a runs from 0 to the assembly limit.

    Returns ``(class, a_min, a_max)`` in order; ``a_max`` of the last is b + c + d. The
    boundaries are where two sums of lengths become equal (a flattened configuration appears);
    each open interval is classified at its middle by :func:`fourbar_class`.

    >>> [(k, round(lo, 9), round(hi, 9)) for k, lo, hi in grashof_ranges(50, 35, 30)]
    [('crank_rocker_AB', 0.0, 15.0), ('double_rocker', 15.0, 45.0), ('double_crank', 45.0, 55.0), ('double_rocker', 55.0, 115.0)]
    """
    b, c, d = float(b), float(c), float(d)
    limit = b + c + d
    cuts = sorted({x for x in (c + d - b, b + d - c, b + c - d, b - c - d, c - b - d, d - b - c)
                   if 0.0 < x < limit} | {0.0, limit})
    out: list[tuple[str, float, float]] = []
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        k = fourbar_class(0.5 * (lo + hi), b, c, d)
        if k == "none":
            continue
        if out and out[-1][0] == k and _equal(out[-1][2], lo, limit):
            out[-1] = (k, out[-1][1], hi)
        else:
            out.append((k, lo, hi))
    return out


def _pick(cands: list[complex], keep: Callable[[complex], bool]) -> complex:
    for z in cands:
        if keep(z):
            return z
    return cands[0]


def _extremes(A: complex, C1: complex, C2: complex, sense: float) -> tuple[float, float, float]:
    """(phi_start, phi_end, θ) from the folded (C1) and extended (C2) positions of C."""
    phi_f = _wrap(cmath.phase(C1 - A) + math.pi)
    phi_e = _wrap(cmath.phase(C2 - A))
    delta = _wrap(sense * (phi_f - phi_e))  # the crank's travel from extended to folded
    theta = abs(delta - math.pi)
    # equal strokes (θ = 0, K = 1) start at the extended position, whatever the rounding says
    return (phi_e, phi_f, theta) if delta >= math.pi - TIE else (phi_f, phi_e, theta)


def fourbar(A: complex, D: complex, a: float, b: float, c: float, branch: str,
            sense: float = 1.0) -> ExactCharacteristics:
    """The characteristics of a crank-rocker (or double-crank) four-bar.

    Parameters
    ----------
    A, D : complex
        The crank's and the rocker's frame pivots (x + iy).
    a, b, c : float
        Crank AB, coupler BC, rocker DC.
    branch : {"left", "right"}
        C lies to this side of the directed line B → D (as the dyad states it).
    sense : float
        +1 for a crank turning counter-clockwise, −1 clockwise.

    Raises
    ------
    ValueError
        When the crank does not turn fully (no extreme positions of a crank).

    Examples
    --------
    >>> ch = fourbar(0j, 72 + 0j, 28, 52, 50, "left")
    >>> ch.grashof, round(math.degrees(ch.theta), 4), round(math.degrees(ch.psi), 4)
    ('crank_rocker_AB', 18.5617, 70.5582)
    >>> round(math.degrees(ch.gamma_min), 4), round(ch.K, 6)
    (22.7342, 1.229954)
    """
    d = abs(D - A)
    kind = fourbar_class(a, b, c, d)
    if kind not in ("crank_rocker_AB", "double_crank", "change_point") or not _turns(a, b, c, d):
        raise NotApplicable(f"the crank does not turn fully ({kind.replace('_', ' ')}): no extreme positions")
    side = 1.0 if branch == "left" else -1.0
    # Coincident frame pivots (d = 0): B and C both turn about A, the triangle ABC is rigid and γ
    # the same everywhere; the x axis stands in for the undefined frame line.
    u = (D - A) / d if d > 0.0 else 1.0 + 0j
    gamma_min = _fourbar_gamma(a, b, c, d, u)
    if _turns(c, b, a, d):  # the output turns fully too: no extreme positions
        return ExactCharacteristics("fourbar", kind, None, None, None, None, None, *gamma_min)

    def c_at(ac: float, b_dir: float) -> complex:
        """C with |AC| = ac on the branch; B = A + b_dir·a·(C − A)/|AC|."""
        gamma = _angle_at(ac, d, c)
        cands = [A + ac * u * cmath.exp(1j * s * gamma) for s in (1.0, -1.0)]

        def on_branch(C: complex) -> bool:
            B = A + b_dir * a * (C - A) / abs(C - A)
            return side * ((D - B).real * (C - B).imag - (D - B).imag * (C - B).real) >= 0.0

        return _pick(cands, on_branch)

    if _equal(a, b, a + b + c + d):  # a deltoid: the folded position puts C on A, B anywhere
        raise NotApplicable("AB = BC (a deltoid): at the folded position C falls on A, so the crank's angle "
                         "there is undetermined: no extreme positions")
    C1, C2 = c_at(b - a, -1.0), c_at(b + a, 1.0)
    start, end, theta = _extremes(A, C1, C2, sense)
    psi = abs(cmath.phase((C2 - D) / (C1 - D)))
    return ExactCharacteristics("fourbar", kind, start, end, theta, psi, None, *gamma_min)


def _fourbar_gamma(a: float, b: float, c: float, d: float, u: complex) -> tuple[float, float]:
    """γ_min and the crank angle where it is: BD = d − a (φ = φ_AD) or d + a (φ = φ_AD + 180°)."""
    best = None
    for off, bd in ((0.0, abs(d - a)), (math.pi, d + a)):
        delta = _angle_at(b, c, bd)
        gamma = min(delta, math.pi - delta)
        if best is None or gamma < best[0] - 1e-15:
            best = (gamma, _wrap(cmath.phase(u) + off))
    assert best is not None
    return best


def slider_crank(A: complex, G: complex, guide_angle: float, a: float, b: float, branch: str,
                 sense: float = 1.0) -> ExactCharacteristics:
    """The characteristics of an (offset) slider-crank.

    Parameters
    ----------
    A : complex
        The crank's pivot.
    G, guide_angle : complex, float
        A point of the slider's guide and its direction (rad).
    a, b : float
        Crank AB, coupler BC.
    branch : {"forward", "backward"}
        C ahead of or behind the foot of the perpendicular from B, along the guide.
    sense : float
        +1 counter-clockwise, −1 clockwise.

    Examples
    --------
    >>> ch = slider_crank(0j, 30j, 0.0, 100, 300, "forward")
    >>> round(ch.stroke, 6), round(math.degrees(ch.theta), 6), round(math.degrees(ch.gamma_min), 6)
    (201.136214, 4.325704, 64.320711)
    """
    g = cmath.exp(1j * guide_angle)
    rel = (A - G) / g  # A in the guide's frame: along, offset
    t_a, e = rel.real, rel.imag
    if a + abs(e) > b * (1.0 + EQUAL_REL):
        raise NotApplicable(f"the crank does not turn fully: a + |e| = {a + abs(e):.6g} > b = {b:.6g}")
    sgn = 1.0 if branch == "forward" else -1.0

    def c_at(ac: float) -> complex:
        return G + g * (t_a + sgn * math.sqrt(max(ac * ac - e * e, 0.0)))

    C1, C2 = c_at(b - a), c_at(b + a)
    start, end, theta = _extremes(A, C1, C2, sense)
    stroke = abs((C2 - C1) / g)
    gamma_min = math.acos(min(1.0, (a + abs(e)) / b))
    # B farthest from the guide: the crank at right angles to the guide, away from it
    away = 1.0 if e > 0.0 else -1.0
    at = _wrap(guide_angle + away * math.pi / 2.0)
    return ExactCharacteristics("slider_crank", "crank", start, end, theta, None, stroke, gamma_min, at)


def guide_bar(A: complex, C: complex, a: float, sense: float = 1.0, e: float = 0.0) -> ExactCharacteristics:
    """The characteristics of a swinging guide-bar (quick-return) mechanism, crank a about A,
    bar pivoted at C; ``e``: an offset guide bar, its line at e to the left of C (:func:`offset_guide_bar`).

    Examples
    --------
    >>> ch = guide_bar(0j, -200j, 100)
    >>> round(math.degrees(ch.theta), 9), round(math.degrees(ch.psi), 9), round(ch.K, 9)
    (60.0, 60.0, 2.0)
    """
    if e != 0.0:
        return offset_guide_bar(A, C, a, e, sense)
    d = abs(C - A)
    if a >= d * (1.0 - EQUAL_REL):
        raise NotApplicable(f"the bar turns fully (crank {a:.6g} ≥ frame {d:.6g}): a rotating guide bar "
                         "has no extreme positions")
    beta = math.acos(a / d)  # at an extreme the bar is tangent to the crank circle: ∠CAB
    base = cmath.phase(C - A)
    p1, p2 = _wrap(base + beta), _wrap(base - beta)
    delta = _wrap(sense * (p2 - p1))
    theta = abs(delta - math.pi)
    start, end = (p1, p2) if delta >= math.pi else (p2, p1)
    psi = 2.0 * math.asin(a / d)
    return ExactCharacteristics("guide_bar", "crank", start, end, theta, psi, None, math.pi / 2.0, start)


def offset_guide_bar(A: complex, C: complex, a: float, e: float, sense: float = 1.0) -> ExactCharacteristics:
    """An offset guide bar: its line at e to the left of C (along its direction û towards the block).

    At an extreme the line is tangent to the crank circle, with the block at the point of contact:
    the line's normal n̂ = iû satisfies ``(A − C)·n̂ = e + σa`` (σ = ±1, B = A − σa·n̂), and the block
    ahead of the foot, ``(A − C)·û > 0``, takes ``arg n̂ = arg(A − C) + arccos((e + σa)/|AC|)``. So
    ψ = |arccos((e + a)/d) − arccos((e − a)/d)|, the crank at ``arg n̂ + π`` (σ = +1) and ``arg n̂``
    (σ = −1). The block pushes ⟂ the line while the bar's point at B moves ⟂ CB: γ = arccos(|e|/|CB|),
    smallest with the crank pointing at C, γ_min = arccos(|e|/(d − a)).

    Examples
    --------
    >>> ch = offset_guide_bar(0j, -200j, 100, 0.0)
    >>> round(math.degrees(ch.theta), 9), round(math.degrees(ch.psi), 9)
    (60.0, 60.0)
    >>> ch = offset_guide_bar(0j, -350j, 110, 40)
    >>> round(math.degrees(ch.theta), 6), round(math.degrees(ch.psi), 6), round(math.degrees(ch.gamma_min), 6)
    (36.913893, 36.913893, 80.405932)
    """
    d = abs(C - A)
    if a + abs(e) >= d * (1.0 - EQUAL_REL):
        raise NotApplicable(f"the crank pin reaches the circle of radius |e| about the bar's pivot (crank {a:.6g} + "
                            f"|e| {abs(e):.6g} ≥ frame {d:.6g}): no extreme positions")
    base = cmath.phase(A - C)
    n_plus = base + math.acos((e + a) / d)
    n_minus = base + math.acos((e - a) / d)
    p1, p2 = _wrap(n_plus + math.pi), _wrap(n_minus)
    delta = _wrap(sense * (p2 - p1))
    theta = abs(delta - math.pi)
    start, end = (p1, p2) if delta >= math.pi else (p2, p1)
    psi = abs(math.acos((e + a) / d) - math.acos((e - a) / d))
    gamma_min = math.acos(abs(e) / (d - a))
    return ExactCharacteristics("guide_bar", "crank", start, end, theta, psi, None, gamma_min, _wrap(cmath.phase(C - A)))
