"""Graphical integration by chords and graphical differentiation of a straight line.

The constructions of the course project's work diagram (метод хорд), carried out on drawing
millimetres exactly as the draftsman does them:

integration by chords
    the abscissa is divided at the positions x₀ < x₁ < … < x_N; in each interval the curve is
    replaced by its *mean ordinate* (the step of equal area; from the ordinates at the ends,
    (y_i + y_{i+1})/2), which is projected onto the ordinate axis; from the pole P = (−H, 0) a
    ray is drawn to each projection; in each interval of the integral diagram a chord is drawn
    parallel to that interval's ray, each chord starting where the previous one ended. So the
    integral's ordinate grows in interval i by mean_i·Δx_i/H (similar triangles: the ray rises
    mean_i over the run H, the chord rises over the run Δx_i).
differentiation by a ray
    a straight line from the origin to (x_end, y_end) is differentiated by the ray from P
    parallel to it: the ray cuts the ordinate axis at H·y_end/x_end — the one-chord case of
    :func:`graphmech.methods.graphical_differentiation.differentiate_by_chords`, which does it.

Scales: if the abscissa is at μx (units per mm) and the integrand at μy, the integral curve is at
``μ_integral = μy·μx·H`` (:func:`integral_scale`); reading back, the derivative of a line drawn at
μ_integral is at μy again.

Everything here is vectorised: N may be thousands of intervals.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import OutOfDomain
from graphmech.methods.chords import divisions, frozen_array
from graphmech.methods.graphical_differentiation import differentiate_by_chords


@dataclass(frozen=True, eq=False)
class Integration:
    """The construction of a graphical integration by chords, in drawing millimetres.

    Attributes
    ----------
    x_mm : ndarray, shape (N+1,)
        The division abscissae, the interval's end included.
    y_mm : ndarray, shape (N+1,)
        The integrand's ordinates at them.
    mean_mm : ndarray, shape (N,)
        The mean ordinate of each interval, (y_i + y_{i+1})/2: its projection on the ordinate
        axis is the point (0, mean_i) the ray goes to.
    H_mm : float
        The pole distance.
    pole : (float, float)
        P = (−H, 0).
    integral_mm : ndarray, shape (N+1,)
        The ordinates of the chord polygon at the divisions, 0 at x₀.

    The arrays are read-only; the object is frozen.
    """

    x_mm: np.ndarray
    y_mm: np.ndarray
    mean_mm: np.ndarray
    H_mm: float
    pole: tuple[float, float]
    integral_mm: np.ndarray

    @property
    def ray_slopes(self) -> np.ndarray:
        """Slope of each ray P → (0, mean_i), which is also the slope of chord i (mm/mm)."""
        return self.mean_mm / self.H_mm

    @property
    def chords(self) -> np.ndarray:
        """The chords as an (N, 4) array of (x0, y0, x1, y1), mm."""
        return np.column_stack([self.x_mm[:-1], self.integral_mm[:-1], self.x_mm[1:], self.integral_mm[1:]])


def integral_scale(mu_x: float, mu_y: float, H_mm: float) -> float:
    """The scale of the integral curve, μy·μx·H (e.g. μA = μM·μφ·H, J/mm with μφ in rad/mm).

    >>> round(integral_scale(math.radians(2.5), 10.0, 40.0), 4)   # μφ = 2.5°/mm, μM = 10 N·m/mm, H = 40 mm
    17.4533
    """
    return float(mu_y) * float(mu_x) * float(H_mm)


def integrate_by_chords(x_mm: ArrayLike, y_mm: ArrayLike, H_mm: float) -> Integration:
    """Graphical integration by chords with the pole at distance ``H_mm`` left of the origin.

    Parameters
    ----------
    x_mm : array_like, shape (N+1,)
        Division abscissae, strictly increasing, including the end of the interval (mm).
    y_mm : array_like, shape (N+1,)
        Ordinates of the integrand at the divisions (mm).
    H_mm : float
        Pole distance (mm, > 0).

    Returns
    -------
    Integration
        ``integral_mm[0] = 0`` and ``integral_mm[i+1] = integral_mm[i] + mean_i·Δx_i/H``.

    Raises
    ------
    ValueError
        Fewer than two divisions, arrays of different lengths, non-finite values, abscissae not
        strictly increasing, or H not positive.

    Notes
    -----
    The ray from P = (−H, 0) to (0, m) has slope m/H; a chord of that slope over Δx rises
    m·Δx/H, so the chord polygon's ordinate is Σ m_i·Δx_i / H = (area under the step)/H, i.e. the
    trapezoidal integral of the ordinates divided by H. Its error against the true integral is
    O(Δx²) for a smooth integrand.

    Examples
    --------
    >>> g = integrate_by_chords([0.0, 10.0, 20.0], [0.0, 20.0, 20.0], 20.0)
    >>> g.mean_mm.tolist(), g.integral_mm.tolist(), g.pole
    ([10.0, 20.0], [0.0, 5.0, 15.0], (-20.0, 0.0))
    >>> g.ray_slopes.tolist()                     # each chord is parallel to its ray
    [0.5, 1.0]
    """
    x, y, H = divisions(x_mm, y_mm, H_mm)
    mean = 0.5 * (y[:-1] + y[1:])  # the step of equal area, projected on the ordinate axis
    rise = mean * np.diff(x) / H  # chord i ∥ ray P → (0, mean_i) over its interval
    integral = np.concatenate([[0.0], np.cumsum(rise)])
    return Integration(frozen_array(x), frozen_array(y), frozen_array(mean), H, (-H, 0.0), frozen_array(integral))


def differentiate_by_ray(x_mm: float, y_end_mm: float, H_mm: float) -> float:
    """Graphical differentiation of the straight line from the origin to (x_end, y_end).

    The ray from the pole P = (−H, 0) parallel to the line cuts the ordinate axis at
    ``H·y_end/x_end`` mm — the line's constant derivative drawn at the integrand's scale.

    Parameters
    ----------
    x_mm : float
        The line's end abscissa x_end (mm, > 0).
    y_end_mm : float
        Its end ordinate (mm).
    H_mm : float
        Pole distance (mm, > 0).

    Examples
    --------
    >>> differentiate_by_ray(160.0, -20.0, 40.0)   # a line falling 20 mm over 160 mm, H = 40 mm
    -5.0
    """
    if not (x_mm > 0.0 and math.isfinite(x_mm)):
        raise OutOfDomain(f"the line's end abscissa must be positive and finite, not {x_mm!r}")
    if not (H_mm > 0.0 and math.isfinite(H_mm)):
        raise OutOfDomain(f"the pole distance H must be positive and finite, not {H_mm!r}")
    if not math.isfinite(y_end_mm):
        raise OutOfDomain(f"the line's end ordinate must be finite, not {y_end_mm!r}")
    # a straight line is its own chord: the ray of its one interval, as differentiation by chords draws it
    return float(differentiate_by_chords([0.0, float(x_mm)], [0.0, float(y_end_mm)], float(H_mm)).derivative_mm[0])


__all__ = ["Integration", "differentiate_by_ray", "divisions", "integral_scale", "integrate_by_chords"]
