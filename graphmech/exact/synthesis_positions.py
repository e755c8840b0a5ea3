"""The independent check of the designs by given positions: the circumcentre solved as a linear
system, and each designed linkage re-analysed through the prescribed positions.

circumcentre
    The centre X is equally far from p₁, p₂, p₃: |X − p_k|² = |X − p₁|² is linear in X,
    2(p_k − p₁)·X = |p_k|² − |p₁|² (k = 2, 3), solved by numpy.linalg.solve.
re-analysis
    The designed linkage is assembled (frame pivots, crank, dyad) and driven to the prescribed
    input positions by :func:`graphmech.exact.linkage.solve`, on the branch of position 1 (a
    position at a dead centre counts as reached: it is assembled, only its rates are unbounded); the
    error is the largest distance between a prescribed and a reached point, divided by the
    linkage's longest link. The characteristics (Grashof class, γ_min, θ, ψ, K) come from
    :mod:`graphmech.exact.characteristics`; a design whose input does not turn fully is said in
    ``note``, not refused: positions may admit no Grashof crank.

Nothing here uses the constructions (methods/, geometry/). Points are complex numbers x + iy
(m), angles in radians.
"""
from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.exact.characteristics import (
    ExactCharacteristics,
    fourbar,
    fourbar_class,
    slider_crank,
)
from graphmech.exact.linkage import solve
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, LinkPoint

__all__ = ["Reanalysis", "circumcentre", "reanalyse_coupler", "reanalyse_fourbar", "reanalyse_rocker_slider",
           "reanalyse_slider_crank"]

#: |sin| of the triangle's angle below which three points count as on one line.
COLLINEAR_SIN = 1e-9


@dataclass(frozen=True)
class Reanalysis:
    """A designed linkage driven through its prescribed positions.

    Attributes
    ----------
    error : float
        The largest distance between a prescribed point and the point the linkage reaches, divided
        by its longest link (inf where a position cannot be assembled).
    reached : tuple of complex
        The output point at each prescribed position (C, or F for the rocker-slider), m.
    branch : str
        The assembly branch of position 1 (``"left"``/``"right"`` of B→D, ``"forward"``/``"backward"``).
    one_branch : bool
        Whether every prescribed position lies on that branch (else the linkage must be taken apart
        to pass through them: the branch defect).
    grashof : str
        The class of the loop (:func:`~graphmech.exact.characteristics.fourbar_class`), or for a
        slider-crank ``"crank"`` / ``"no_crank"``, for a rocker driving a slider ``"rocker"``.
    characteristics : ExactCharacteristics or None
        θ, ψ or H, K, γ_min of the whole cycle where the input turns fully, else None.
    gamma : tuple of float
        The transmission angle at each prescribed position, rad.
    note : str
        ``""``, or in words what the design lacks (no Grashof crank, the branch defect).
    """

    error: float
    reached: tuple[complex, ...]
    branch: str
    one_branch: bool
    grashof: str
    characteristics: ExactCharacteristics | None
    gamma: tuple[float, ...]
    note: str


def circumcentre(p1: complex, p2: complex, p3: complex) -> complex:
    """The centre of the circle through three points, from the linear equations of equal distance.

    >>> circumcentre(0j, 4 + 0j, 4j)
    (2+2j)
    """
    # about p1: 2(p_k − p₁)·(X − p₁) = |p_k − p₁|², coordinates the size of the figure, not of its
    # distance from the origin
    m = np.array([[(p2 - p1).real, (p2 - p1).imag], [(p3 - p1).real, (p3 - p1).imag]]) * 2.0
    if abs(np.linalg.det(m)) <= 4.0 * COLLINEAR_SIN * abs(p2 - p1) * abs(p3 - p1):
        raise NoSolution("the three points lie on one straight line (or two coincide): no circle passes through them")
    x = np.linalg.solve(m, np.array([abs(p2 - p1) ** 2, abs(p3 - p1) ** 2]))
    return p1 + complex(float(x[0]), float(x[1]))


def _side(P: complex, Q: complex, C: complex) -> Literal["left", "right"]:
    """The side of C from the directed line P → Q."""
    cr = (Q - P).real * (C - P).imag - (Q - P).imag * (C - P).real
    return "left" if cr >= 0.0 else "right"


def _ahead(coupler: complex, g: complex) -> Literal["forward", "backward"]:
    """The slider ahead of or behind its coupler's other end, along the guide g."""
    return "forward" if (coupler / g).real >= 0.0 else "backward"


def _angles(points: Sequence[complex], pivot: complex) -> np.ndarray:
    return np.array([cmath.phase(p - pivot) for p in points])


def _gamma(B: complex, C: complex, D: complex) -> float:
    """The transmission angle at C: ∠BCD or its supplement, whichever is acute."""
    if C == D or B == C:
        raise OutOfDomain("a link of the design has no length (C on D or on B): no transmission angle")
    delta = abs(cmath.phase((B - C) / (D - C)))
    return min(delta, math.pi - delta)


def _positions(n: int, *seqs: Sequence[object]) -> None:
    if n not in (2, 3) or any(len(s) != n for s in seqs):
        raise OutOfDomain("two or three prescribed positions are re-analysed, the same number of each")


def _fourbar_check(A: complex, D: complex, a: float, b: float, c: float, phi: np.ndarray,
                   branch: Literal["left", "right"], sides: list[Literal["left", "right"]],
                   prescribed: list[complex], B_given: list[complex] | None,
                   extra: tuple[LinkPoint, list[complex]] | None = None) -> Reanalysis:
    """Assemble A B C D on ``branch``, drive AB to φ and compare C (and B, and a coupler point)
    with the prescribed."""
    lk = Linkage({"A": (A.real, A.imag), "D": (D.real, D.imag)}, Crank("1", "A", "B", a, 1.0),
                 (RRR("B", "C", "D", ("2", "3"), (b, c), branch),), (extra[0],) if extra else ())
    kin = solve(lk, phi)
    d = abs(D - A)
    size = max(a, b, c, d)
    Bs = [complex(*xy) for xy in kin.point["B"]]
    Cs = [complex(*xy) for xy in kin.point["C"]]
    err = max(abs(Cs[i] - prescribed[i]) for i in range(len(phi)))
    if B_given is not None:
        err = max(err, *(abs(Bs[i] - B_given[i]) for i in range(len(phi))))
    if extra is not None:
        Es = [complex(*xy) for xy in kin.point[extra[0].name]]
        err = max(err, *(abs(Es[i] - extra[1][i]) for i in range(len(phi))))
    if not bool(np.all(kin.assembled)):  # a prescribed position at a dead centre is reached
        err = math.inf
    one = all(s == branch for s in sides)
    grashof = fourbar_class(a, b, c, d)
    notes = []
    try:
        ch: ExactCharacteristics | None = fourbar(A, D, a, b, c, branch)
    except NotApplicable:
        ch = None
        if grashof == "double_rocker" or grashof == "none":
            notes.append(f"the positions admit no Grashof crank ({grashof.replace('_', ' ')}): AB does not turn fully")
        else:
            notes.append(f"AB does not turn fully ({grashof.replace('_', ' ')})")
    if not one:
        notes.append("the prescribed positions lie on both branches: the linkage cannot pass through them "
                     "without being taken apart")
    gamma = tuple(_gamma(Bs[i], Cs[i], D) for i in range(len(phi)))
    return Reanalysis(err / size, tuple(Cs), branch, one, grashof, ch, gamma, "; ".join(notes))


def reanalyse_coupler(A: complex, D: complex, B: Sequence[complex], C: Sequence[complex],
                      E: Sequence[complex] | None = None) -> Reanalysis:
    """The four-bar A B C D (pivots designed, coupler positions B_i C_i prescribed) driven by AB to
    the angles of A B_i: B_i and C_i reached? With ``E``, a coupler point fixed on BC at its place
    in position 1, its prescribed positions E_i too."""
    _positions(len(B), B, C, *([E] if E is not None else []))
    a, b, c = abs(B[0] - A), abs(C[0] - B[0]), abs(C[0] - D)
    sides = [_side(B[i], D, C[i]) for i in range(len(B))]
    extra = None
    if E is not None:
        rel = (E[0] - B[0]) / ((C[0] - B[0]) / b)  # E in the frame of B → C: along, left
        extra = (LinkPoint("E", "2", ("B", "C"), rel.real, rel.imag), list(E))
    return _fourbar_check(A, D, a, b, c, _angles(B, A), sides[0], sides, list(C), list(B), extra)


def reanalyse_fourbar(A: complex, D: complex, l_AB: float, l_BC: float, l_CD: float, phi: Sequence[float],
                      psi: Sequence[float], C1: complex) -> Reanalysis:
    """The four-bar designed for corresponding positions, driven to φ_i: does DC turn by ψ_i − ψ₁?

    ``C1`` the designed joint at position 1 (it gives the branch and where ψ is measured from).
    """
    _positions(len(phi), phi, psi)
    B = [A + l_AB * cmath.exp(1j * f) for f in phi]
    prescribed = [D + (C1 - D) * cmath.exp(1j * (p - psi[0])) for p in psi]
    sides = [_side(B[i], D, prescribed[i]) for i in range(len(phi))]
    return _fourbar_check(A, D, l_AB, l_BC, l_CD, np.asarray(phi, dtype=float), sides[0], sides, prescribed, None)


def reanalyse_slider_crank(A: complex, l_AB: float, l_BC: float, phi: Sequence[float], s: Sequence[float],
                           guide_angle: float, C1: complex) -> Reanalysis:
    """The slider-crank (pin C₁ at position 1, its path along ``guide_angle``) driven to φ_i: does
    the slider stand at s_i − s₁ from C₁?"""
    _positions(len(phi), phi, s)
    g = cmath.exp(1j * guide_angle)
    B = [A + l_AB * cmath.exp(1j * f) for f in phi]
    prescribed = [C1 + (x - s[0]) * g for x in s]
    ahead = [_ahead(prescribed[i] - B[i], g) for i in range(len(phi))]
    branch = ahead[0]
    lk = Linkage({"A": (A.real, A.imag)}, Crank("1", "A", "B", l_AB, 1.0),
                 (RRP("B", "C", ("2", "3"), l_BC, Guide((C1.real, C1.imag), guide_angle), branch),))
    kin = solve(lk, np.asarray(phi, dtype=float))
    Cs = [complex(*xy) for xy in kin.point["C"]]
    Bs = [complex(*xy) for xy in kin.point["B"]]
    err = max(abs(Cs[i] - prescribed[i]) for i in range(len(phi))) / max(l_AB, l_BC)
    if not bool(np.all(kin.assembled)):  # a prescribed position at a dead centre is reached
        err = math.inf
    notes = []
    try:
        ch: ExactCharacteristics | None = slider_crank(A, C1, guide_angle, l_AB, l_BC, branch)
        grashof = "crank"
    except NotApplicable:
        ch, grashof = None, "no_crank"
        notes.append("the crank does not turn fully: a + |e| > BC")
    one = all(x == branch for x in ahead)
    if not one:
        notes.append("the prescribed positions lie on both branches: the linkage cannot pass through them "
                     "without being taken apart")
    # the transmission angle: 90° less the pressure angle, sin α = (B's distance from the path)/BC
    gamma = tuple(math.acos(min(1.0, abs(((Bs[i] - Cs[i]) / g).imag) / l_BC)) for i in range(len(phi)))
    return Reanalysis(err, tuple(Cs), branch, one, grashof, ch, gamma, "; ".join(notes))


def reanalyse_rocker_slider(D: complex, rocker: Sequence[float], E1: complex, F: Sequence[complex]) -> Reanalysis:
    """A rocker about D (its angles ``rocker``, rad) carrying the joint E (E₁ at position 1) drives a
    slider on the line F₁F_n (where it comes back to F₁: its farthest two positions) through a
    coupler EF: does the slider reach F_i?"""
    _positions(len(rocker), rocker, F)
    l_DE, l_EF = abs(E1 - D), abs(F[0] - E1)
    # the guide along F₁ → F_n, or where the slider comes back to F₁ along the farthest pair
    ends = (F[0], F[-1]) if abs(F[-1] - F[0]) > 1e-12 * max(abs(f - D) for f in F) else \
        max(((f, g) for f in F for g in F), key=lambda fg: abs(fg[1] - fg[0]))
    guide_angle = cmath.phase(ends[1] - ends[0])
    g = cmath.exp(1j * guide_angle)
    turn = np.array([cmath.phase(E1 - D) + r - rocker[0] for r in rocker])
    E = [D + l_DE * cmath.exp(1j * t) for t in turn]
    ahead = [_ahead(F[i] - E[i], g) for i in range(len(F))]
    lk = Linkage({"D": (D.real, D.imag)}, Crank("3", "D", "E", l_DE, 1.0),
                 (RRP("E", "F", ("5", "6"), l_EF, Guide((F[0].real, F[0].imag), guide_angle), ahead[0]),),
                 frame_link="1")
    kin = solve(lk, turn)
    Fs = [complex(*xy) for xy in kin.point["F"]]
    err = max(abs(Fs[i] - F[i]) for i in range(len(F))) / max(l_DE, l_EF)
    if not bool(np.all(kin.assembled)):  # a prescribed position at a dead centre is reached
        err = math.inf
    one = all(x == ahead[0] for x in ahead)
    gamma = tuple(math.acos(min(1.0, abs(((E[i] - Fs[i]) / g).imag) / l_EF)) for i in range(len(F)))
    note = "" if one else ("the prescribed positions lie on both branches: the linkage cannot pass through them "
                           "without being taken apart")
    return Reanalysis(err, tuple(Fs), ahead[0], one, "rocker", None, gamma, note)
