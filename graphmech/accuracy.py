"""How accurate a row of the check table is, as the method itself can tell without the exact value.

Every row has an ``error_source``:

- ``"construction"``: exact but for round-off (``ill_conditioned`` flags where round-off grows);
- ``"discretisation"``: the method works on N positions or divisions (chords, a flywheel from N
  positions, graphical differentiation and integration), so its error falls with N;
- ``"reading"``: read off the drawing at a finite resolution (the largest pressure angle at the
  cam's divisions, a radius of curvature from three drawn points).

The last two carry an ``error_estimate``: the relative error (with the row's own denominator, as
``rel_error``) that the method estimates by doing the work again more finely, never from the exact
solution — Richardson's estimate for a method of known order p from N and 2N,

    e(N) ≈ |v(N) − v(2N)| · 2ᵖ / (2ᵖ − 1),

or, where the order is not known in advance (a maximum that may sit at a kink), the order observed
on N, 2N and 4N.
"""
from __future__ import annotations

import math
from typing import Any, cast

import numpy as np

CONSTRUCTION, DISCRETISATION, READING = "construction", "discretisation", "reading"
SOURCES = (CONSTRUCTION, DISCRETISATION, READING)


def percent(fraction: float) -> str:
    """A relative error as the check tables print it (text and the gallery's HTML).

    >>> percent(0.08), percent(1.3e-4), percent(0.0)
    ('8 %', '0.013 %', '<1e-10 %')
    """
    p = 100.0 * fraction
    return "<1e-10 %" if p < 1e-10 else f"{p:.2g} %"


def richardson(coarse: float, fine: float, order: float) -> float:
    """The estimated absolute error of ``coarse`` (at N) from ``fine`` (at 2N), order p known."""
    return cast(float, abs(coarse - fine) * 2.0**order / (2.0**order - 1.0))  # float ** float is Any to mypy


def extrapolated(coarse: float, fine: float, order: float) -> float:
    """The value at infinitely many positions from N (``coarse``) and 2N (``fine``), order p known:
    fine + (fine − coarse)/(2ᵖ − 1). Works on arrays too.

    >>> extrapolated(1.0 + 1/4, 1.0 + 1/16, 2)
    1.0
    """
    return cast(float, fine + (fine - coarse) / (2.0**order - 1.0))


def observed_order(v1: float, v2: float, v4: float, lo: float = 0.5, hi: float = 4.0) -> float:
    """The order seen on N, 2N, 4N: log₂(|v1 − v2| / |v2 − v4|), kept within [lo, hi].

    >>> round(observed_order(1.0 + 1/16, 1.0 + 1/64, 1.0 + 1/256), 6)
    2.0
    """
    d12, d24 = abs(v1 - v2), abs(v2 - v4)
    if d24 == 0.0 or d12 == 0.0:
        return hi  # already converged to round-off: assume the fast end
    return min(hi, max(lo, math.log2(d12 / d24)))


def estimate_from_three(v1: float, v2: float, v4: float) -> float:
    """The estimated absolute error of v1 (at N) from the same method at 2N and 4N."""
    return richardson(v1, v2, observed_order(v1, v2, v4))


def relative(abs_error: float, denominator: float) -> float:
    """An absolute error estimate as a relative one, as ``rel_error`` is (never NaN; inf where the
    finer work itself broke down — graphmech.problems refuses such a row in words)."""
    if not math.isfinite(abs_error):
        return math.inf
    return abs_error / denominator if denominator > 0.0 else abs_error


def convergence_order(records: list[dict[str, Any]], key: str = "max_rel_error") -> dict[str, Any]:
    """Order of convergence of ``key`` over records of one case: −slope of log error against log n.

    ``overall`` is the least-squares slope over all the records; ``asymptotic`` the least-squares
    slope over the leading run where each doubling-or-more of n still divides the error by more
    than 2^1.5 (pairwise order ≥ 1.5), with that run's n range — where the error stops falling
    (a floor) is where the run ends.
    """
    rs = sorted(records, key=lambda r: r["n"])
    n = np.log([r["n"] for r in rs])
    e = np.log([max(r[key], 1e-300) for r in rs])
    overall = -float(np.polyfit(n, e, 1)[0])
    end = 1
    while end < len(rs) and -(e[end] - e[end - 1]) / (n[end] - n[end - 1]) >= 1.5:
        end += 1
    asym = -float(np.polyfit(n[:end], e[:end], 1)[0]) if end >= 2 else math.nan
    return {"overall": overall, "asymptotic": asym, "n_from": rs[0]["n"], "n_to": rs[end - 1]["n"]}
