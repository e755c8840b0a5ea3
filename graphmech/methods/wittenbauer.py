"""The Wittenbauer (energy–mass) diagram and the energy-indicator diagram.

Wittenbauer diagram (диаграмма Виттенбауэра, ΔT(Jп))
    the points (Jп_k/μJ, ΔT_k/μT), k = 1 … N, joined in order into a closed curve. With the
    flywheel J_F on the crank the machine's kinetic energy is T = T₀ + ΔT = (J_F + Jп)·ω²/2, so
    seen from the true origin O′ = (−J_F/μJ, −T₀/μT) the ray to a point has the slope
    μJ·ω²/(2μT): the steepest ray belongs to ω_max, the flattest to ω_min. The draftsman draws
    the two tangents to the curve at the angles

        tan ψmax = μJ·ω_max²/(2μT),   tan ψmin = μJ·ω_min²/(2μT),

    the upper one touching the curve from above, the lower from below; they cut the ΔT axis
    (Jп = 0) at k and l, and

        J_F = μT·kl/(ω_m²·δ).

    Derivation: both tangents pass through O′, so k − l = (J_F/μJ)·(tan ψmax − tan ψmin) and
    tan ψmax − tan ψmin = μJ·(ω_max² − ω_min²)/(2μT) = μJ·ω_m²·δ/μT, exactly for both readings
    of ω_max, ω_min below (ω_m(1 ± δ/2) squared differ by 2δω_m², and so do ω_m²(1 ± δ)).
    The tangents meet at O′, far to the left when δ is small: that intersection is
    ill-conditioned (the tangents almost parallel), while k and l themselves are well defined.
    A negative kl says the machine's own inertia already keeps the speed within δ.

Energy indicator (能量指示图)
    from the ΔT sequence over the cycle, closed back to its start, the chain of vertical vectors
    between consecutive local extremes: each vector is one excess or deficit of work (盈亏功)
    f₁, f₂, …; the chain returns to its start; ΔW_max is the height between its highest and
    lowest points, and J_F′ = ΔW_max/(ω_m²·δ) − J_mean (the mean reduced inertia subtracted).
    With Jп constant both methods give the same J_F.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import OutOfDomain
from graphmech.tolerances import SHALLOW_DEG

TangentForm = Literal["exact", "book"]


def _frozen(a: ArrayLike, dtype: type = float) -> np.ndarray:
    out: np.ndarray = np.array(a, dtype=dtype)
    out.setflags(write=False)
    return out


@dataclass(frozen=True, eq=False)
class WittenbauerDiagram:
    """The Wittenbauer diagram's construction, in drawing millimetres.

    Attributes
    ----------
    x_mm, y_mm : ndarray, shape (N,)
        The points Jп_k/μJ and ΔT_k/μT; point ``i`` is position ``i + 1``.
    tan_psi_max, tan_psi_min : float
        The tangents' slopes in drawing units (mm/mm).
    k_mm : float
        Where the upper tangent cuts the ΔT axis: max(y − x·tan ψmax).
    l_mm : float
        Where the lower tangent cuts it: min(y − x·tan ψmin).
    k_index, l_index : int
        The points the tangents touch (0-based; position = index + 1): ω_max and ω_min.
    kl_mm : float
        k − l (negative: no flywheel is needed).
    intersection : (float, float)
        Where the tangents meet (the true origin O′ of the diagram).
    angle_between_deg : float
        ψmax − ψmin, degrees.
    ill_conditioned : bool
        ``angle_between_deg`` below :data:`graphmech.tolerances.SHALLOW_DEG`: drawn by hand
        the tangents' intersection cannot be found; k and l are still sharp.
    """

    x_mm: np.ndarray
    y_mm: np.ndarray
    tan_psi_max: float
    tan_psi_min: float
    k_mm: float
    l_mm: float
    k_index: int
    l_index: int
    kl_mm: float
    intersection: tuple[float, float]
    angle_between_deg: float
    ill_conditioned: bool

    @property
    def psi_max_deg(self) -> float:
        """ψmax, degrees."""
        return math.degrees(math.atan(self.tan_psi_max))

    @property
    def psi_min_deg(self) -> float:
        """ψmin, degrees."""
        return math.degrees(math.atan(self.tan_psi_min))


def tangent_slopes(omega_m: float, delta: float, mu_J: float, mu_T: float,
                   form: TangentForm = "exact") -> tuple[float, float]:
    """The slopes (tan ψmax, tan ψmin) of the Wittenbauer tangents in drawing units.

    ``tan ψ = μJ·ω²/(2·μT)`` with

    * ``form="exact"``: ω_max = ω_m(1 + δ/2), ω_min = ω_m(1 − δ/2) (ω_m the arithmetic mean),
      so tan ψ = μJ·ω_m²·(1 ± δ/2)²/(2μT);
    * ``form="book"``: ω² = ω_m²(1 ± δ), the books' rounding of the same, so
      tan ψ = μJ·ω_m²·(1 ± δ)/(2μT).

    Parameters
    ----------
    omega_m : float
        Mean angular velocity of the crank, rad/s (> 0).
    delta : float
        Coefficient of speed fluctuation (0 < δ < 2 exact, 0 < δ < 1 book).
    mu_J, mu_T : float
        Scales of the diagram, kg·m²/mm and J/mm.

    Examples
    --------
    The course project (ω₁ = 28 rad/s, δ = 0.2, μJ = 0.0246 kg·m²/mm, μT = 109 J/mm), as the book
    computes it:

    >>> [round(t, 5) for t in tangent_slopes(28.0, 0.2, 0.0246, 109.0, "book")]
    [0.10616, 0.07078]
    """
    if form not in ("exact", "book"):
        raise OutOfDomain(f"form must be 'exact' or 'book', not {form!r}")
    limit = 2.0 if form == "exact" else 1.0
    if not (omega_m > 0.0 and math.isfinite(omega_m)):
        raise OutOfDomain(f"ω_m must be positive and finite, not {omega_m!r}")
    if not (0.0 < delta < limit):
        raise OutOfDomain(f"δ must lie in (0, {limit:g}) for the {form} tangents, not {delta!r}")
    if not (mu_J > 0.0 and mu_T > 0.0 and math.isfinite(mu_J) and math.isfinite(mu_T)):
        raise OutOfDomain(f"the scales μJ and μT must be positive and finite, not {mu_J!r}, {mu_T!r}")
    c = mu_J * omega_m * omega_m / (2.0 * mu_T)
    if form == "exact":
        return c * (1.0 + delta / 2.0) ** 2, c * (1.0 - delta / 2.0) ** 2
    return c * (1.0 + delta), c * (1.0 - delta)


def flywheel_inertia(kl_mm: float, mu_T: float, omega_m: float, delta: float) -> float:
    """J_F = μT·kl/(ω_m²·δ), kg·m² (also J_F′ + J_mean from ΔW_max in mm).

    >>> round(flywheel_inertia(61.0, 109.0, 28.0, 0.2), 2)    # the course project's 42.4 kg·m²
    42.4
    """
    return float(mu_T) * float(kl_mm) / (float(omega_m) ** 2 * float(delta))


def wittenbauer(J_mm: ArrayLike, T_mm: ArrayLike, tan_psi_max: float, tan_psi_min: float) -> WittenbauerDiagram:
    """The Wittenbauer diagram of the points (J_mm[i], T_mm[i]) and its two tangents.

    Parameters
    ----------
    J_mm : array_like, shape (N,)
        Jп_k/μJ, mm (≥ 0: the ΔT axis is Jп = 0).
    T_mm : array_like, shape (N,)
        ΔT_k/μT, mm.
    tan_psi_max, tan_psi_min : float
        The tangents' slopes (:func:`tangent_slopes`), tan ψmax > tan ψmin.

    Raises
    ------
    ValueError
        Arrays of different shapes or empty, non-finite values, or tan ψmax ≤ tan ψmin.

    Examples
    --------
    >>> w = wittenbauer([10.0, 12.0, 10.0, 8.0], [0.0, 5.0, 2.0, -4.0], 0.5, 0.4)
    >>> w.k_mm, w.k_index, w.l_mm, w.l_index, w.kl_mm
    (-1.0, 1, -7.2, 3, 6.2)
    """
    x = np.asarray(J_mm, dtype=float)
    y = np.asarray(T_mm, dtype=float)
    if x.ndim != 1 or x.shape != y.shape or x.size == 0:
        raise OutOfDomain(f"J_mm and T_mm must be 1-D of one length ≥ 1, got shapes {x.shape} and {y.shape}")
    if not (np.isfinite(x).all() and np.isfinite(y).all()):
        raise OutOfDomain("the diagram's points must be finite")
    if not (math.isfinite(tan_psi_max) and math.isfinite(tan_psi_min) and tan_psi_max > tan_psi_min):
        raise OutOfDomain(f"tan ψmax must exceed tan ψmin, got {tan_psi_max!r} and {tan_psi_min!r}")
    tmax, tmin = float(tan_psi_max), float(tan_psi_min)
    upper = y - x * tmax  # each point's tangent of slope tan ψmax, cut on the ΔT axis
    lower = y - x * tmin
    ki, li = int(np.argmax(upper)), int(np.argmin(lower))
    k, l = float(upper[ki]), float(lower[li])
    xs = (l - k) / (tmax - tmin)  # k + tmax·x = l + tmin·x
    angle = math.degrees(math.atan(tmax) - math.atan(tmin))
    return WittenbauerDiagram(_frozen(x), _frozen(y), tmax, tmin, k, l, ki, li, k - l,
                              (xs, k + tmax * xs), angle, angle < SHALLOW_DEG)


@dataclass(frozen=True, eq=False)
class EnergyIndicator:
    """The energy-indicator diagram: a chain of vertical vectors, drawing mm.

    Attributes
    ----------
    vertices : ndarray of int, shape (m+1,)
        Where the chain turns, as indices into the closed ΔT sequence (0 … N; N is the end of
        the cycle, back at position 1): 0, the local extremes in order, N.
    levels_mm : ndarray, shape (m+1,)
        ΔT at the vertices (mm): the chain's points a, b, c, …, a′.
    vectors_mm : ndarray, shape (m,)
        The excess (+) and deficit (−) areas f₁ … f_m, each the rise from one vertex to the next.
    highest, lowest : int
        The chain's highest and lowest vertices (indices into ``vertices``).
    dW_max_mm : float
        ΔW_max: their height difference (mm).
    """

    vertices: np.ndarray
    levels_mm: np.ndarray
    vectors_mm: np.ndarray
    highest: int
    lowest: int
    dW_max_mm: float


def energy_indicator(T_mm: ArrayLike) -> EnergyIndicator:
    """The energy-indicator diagram of ΔT_1 … ΔT_N (mm), closed by returning to ΔT_1.

    Successive differences of one sign make one vector (a monotone run between two extremes);
    differences below 1e-12 of the largest |ΔT| are rounding and join either neighbour.

    Examples
    --------
    >>> e = energy_indicator([0.0, 3.0, 5.0, 1.0, -2.0, -1.0])
    >>> e.vertices.tolist(), e.vectors_mm.tolist(), e.dW_max_mm
    ([0, 2, 4, 6], [5.0, -7.0, 2.0], 7.0)
    """
    t = np.asarray(T_mm, dtype=float)
    if t.ndim != 1 or t.size == 0 or not np.isfinite(t).all():
        raise OutOfDomain("ΔT must be a non-empty 1-D array of finite values")
    n = t.size
    closed = np.append(t, t[0])
    d = np.diff(closed)
    tol = 1e-12 * float(np.abs(closed).max())
    nz = np.flatnonzero(np.abs(d) > tol)
    if nz.size == 0:
        vertices = np.array([0, n])
    else:
        s = np.sign(d[nz])
        turns = nz[np.flatnonzero(s[1:] != s[:-1])] + 1  # the last index of a run, +1: its end point
        vertices = np.concatenate([[0], turns, [n]])
    levels = closed[vertices]
    return EnergyIndicator(_frozen(vertices, int), _frozen(levels), _frozen(np.diff(levels)),
                           int(np.argmax(levels)), int(np.argmin(levels)),
                           float(levels.max() - levels.min()))


__all__ = ["EnergyIndicator", "WittenbauerDiagram", "energy_indicator", "flywheel_inertia", "tangent_slopes",
           "wittenbauer"]
