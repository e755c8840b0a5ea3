"""What both constructions by chords share, so the differentiation need not import the integration (which imports it).

The divisions x₀ < x₁ < … < x_N with the curve's ordinates at them and the pole distance H,
checked (:func:`divisions`), and the read-only copies the results hold (:func:`frozen_array`):
used by :mod:`~graphmech.methods.graphical_integration`,
:mod:`~graphmech.methods.graphical_differentiation` and :mod:`~graphmech.methods.full_cycle`.
"""
from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import OutOfDomain


def frozen_array(a: ArrayLike) -> np.ndarray:
    """A read-only float copy of ``a``."""
    a = np.array(a, dtype=float)  # a copy the caller cannot change under us
    a.setflags(write=False)
    return a


def divisions(x_mm: ArrayLike, y_mm: ArrayLike, H_mm: float) -> tuple[np.ndarray, np.ndarray, float]:
    """The divisions, ordinates (mm) and pole distance of a construction by chords, checked.

    Raises
    ------
    ValueError
        Fewer than two divisions, arrays of different lengths, non-finite values, abscissae not
        strictly increasing, or H not positive and finite.
    """
    x = np.asarray(x_mm, dtype=float)
    y = np.asarray(y_mm, dtype=float)
    if x.ndim != 1 or y.shape != x.shape or x.size < 2:
        raise OutOfDomain(f"x_mm and y_mm must be 1-D of the same length ≥ 2, got shapes {x.shape} and {y.shape}")
    if not (np.isfinite(x).all() and np.isfinite(y).all()):
        raise OutOfDomain("the divisions and ordinates must be finite")
    if not np.all(np.diff(x) > 0.0):
        raise OutOfDomain("the division abscissae must be strictly increasing")
    if not (H_mm > 0.0 and math.isfinite(H_mm)):
        raise OutOfDomain(f"the pole distance H must be positive and finite, not {H_mm!r}")
    return x, y, float(H_mm)


__all__ = ["divisions", "frozen_array"]
