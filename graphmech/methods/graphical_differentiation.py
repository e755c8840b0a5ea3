"""Graphical differentiation by chords, as taught for the s–φ, v–φ, a–φ diagrams.

The curve y(x) is drawn at the divisions x₀ < x₁ < … < x_N. In each interval the draftsman
draws the *chord* of the curve; through the pole P = (−H, 0), on the abscissa H to the left of
the origin, a ray parallel to that chord; the ray cuts the ordinate axis at H·(Δy/Δx) — the
derivative's ordinate, which is laid off at the *middle* of the interval (where the chord's
slope equals the curve's to second order). Differentiating the result once more gives the
second derivative at the middles of the middles.

This is the converse of graphical integration by chords (:mod:`graphical_integration`): the
same pole P = (−H, 0), the same rays, read the other way (there the ray to the mean ordinate
gives the chord's slope; here the chord's slope gives the ray and its ordinate). Scales: if
the abscissa is at μx per mm and the curve at μy, the derivative is at ``μy/(μx·H)``
(:func:`derivative_scale`); with the crank's angle as abscissa and time t = φ/ω, the velocity
diagram's scale is μv = μs·ω/(μφ·H).

For a cycle the curve is periodic: the chord from the last division to the first one of the
next cycle closes it, so N divisions give N derivatives (:func:`differentiate_cycle`).

Everything is vectorised: N may be thousands.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import OutOfDomain
from graphmech.methods.chords import divisions, frozen_array

__all__ = ["Differentiation", "derivative_scale", "differentiate_by_chords", "differentiate_cycle"]


@dataclass(frozen=True, eq=False)
class Differentiation:
    """The construction of a graphical differentiation by chords, in drawing millimetres.

    Attributes
    ----------
    x_mm, y_mm : ndarray, shape (N+1,)
        The divisions and the curve's ordinates at them.
    H_mm : float
        The pole distance.
    pole : (float, float)
        P = (−H, 0).
    mid_mm : ndarray, shape (N,)
        The middle of each interval, where the derivative's ordinate is laid off.
    derivative_mm : ndarray, shape (N,)
        Where the ray from P parallel to chord i cuts the ordinate axis: H·Δy_i/Δx_i.
    """

    x_mm: np.ndarray
    y_mm: np.ndarray
    H_mm: float
    pole: tuple[float, float]
    mid_mm: np.ndarray
    derivative_mm: np.ndarray

    @property
    def chord_slopes(self) -> np.ndarray:
        """Slope of each chord (mm/mm), which is the slope of its ray from P."""
        return self.derivative_mm / self.H_mm

    @property
    def chords(self) -> np.ndarray:
        """The chords as an (N, 4) array of (x0, y0, x1, y1), mm."""
        return np.column_stack([self.x_mm[:-1], self.y_mm[:-1], self.x_mm[1:], self.y_mm[1:]])


def derivative_scale(mu_x: float, mu_y: float, H_mm: float) -> float:
    """The scale of the derivative curve, μy/(μx·H) — the inverse of the integral's μy·μx·H.

    >>> import math
    >>> round(derivative_scale(math.radians(2.0), 0.002, 20.0), 9)   # μφ = 2°/mm, μs = 2 mm/mm, H = 20 mm
    0.002864789
    """
    return float(mu_y) / (float(mu_x) * float(H_mm))


def differentiate_by_chords(x_mm: ArrayLike, y_mm: ArrayLike, H_mm: float) -> Differentiation:
    """Graphical differentiation by chords with the pole at distance ``H_mm`` left of the origin.

    Parameters
    ----------
    x_mm : array_like, shape (N+1,)
        Division abscissae, strictly increasing (mm).
    y_mm : array_like, shape (N+1,)
        The curve's ordinates at them (mm).
    H_mm : float
        Pole distance (mm, > 0).

    Returns
    -------
    Differentiation
        ``derivative_mm[i] = H·(y[i+1] − y[i])/(x[i+1] − x[i])`` at ``mid_mm[i]``.

    Raises
    ------
    ValueError
        Fewer than two divisions, shapes that differ, non-finite values, abscissae not strictly
        increasing, or H not positive.

    Notes
    -----
    The ray from P = (−H, 0) with the chord's slope k rises k·H over the run H to the ordinate
    axis. For a smooth curve the chord's slope is y′ at the interval's middle plus
    y‴·Δx²/24, so the error is O(Δx²).

    Examples
    --------
    >>> d = differentiate_by_chords([0.0, 10.0, 20.0], [0.0, 5.0, 20.0], 20.0)
    >>> d.derivative_mm.tolist(), d.mid_mm.tolist(), d.pole
    ([10.0, 30.0], [5.0, 15.0], (-20.0, 0.0))
    """
    x, y, H = divisions(x_mm, y_mm, H_mm)
    ray = H * np.diff(y) / np.diff(x)  # the ray from P ∥ the chord cuts the ordinate axis here
    mid = 0.5 * (x[:-1] + x[1:])
    return Differentiation(frozen_array(x), frozen_array(y), H, (-H, 0.0), frozen_array(mid), frozen_array(ray))


def differentiate_cycle(x_mm: ArrayLike, y_mm: ArrayLike, period_mm: float, H_mm: float,
                        rise_mm: float = 0.0) -> Differentiation:
    """Differentiate a periodic curve given at N divisions of one period.

    The chord from the last division to the first one of the next period (x₀ + period, y₀ + rise)
    closes the cycle, so the result has N derivatives, at the middles of the N intervals. ``rise``
    is what the curve gains over a period: 0 for a slider or a rocker, a full turn for a link that
    turns fully, the path's length for a distance travelled along it.

    >>> d = differentiate_cycle([0.0, 10.0, 20.0, 30.0], [0.0, 5.0, 0.0, -5.0], 40.0, 10.0)
    >>> d.derivative_mm.tolist(), d.mid_mm.tolist()
    ([5.0, -5.0, -5.0, 5.0], [5.0, 15.0, 25.0, 35.0])
    """
    x = np.asarray(x_mm, dtype=float)
    y = np.asarray(y_mm, dtype=float)
    if x.ndim != 1 or x.size < 2 or y.shape != x.shape:
        raise OutOfDomain("a cycle needs at least two divisions, with one ordinate each")
    if not (period_mm > x[-1] - x[0]):
        raise OutOfDomain("the period must be longer than the span of the divisions")
    return differentiate_by_chords(np.append(x, x[0] + period_mm), np.append(y, y[0] + rise_mm), H_mm)
