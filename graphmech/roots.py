"""Roots of equations, without scipy.optimize: importing it costs a third of a second, longer
than a whole cam check takes without it (issue 23: cold starts under 0.5 s).

* :func:`brentq` — a root of a function bracketed by a sign change: Brent's method (Brent 1973,
  "zero"). The exact solutions refine an extreme or a crossing between two samples with it. It is
  the same algorithm, step for step, as ``scipy.optimize.brentq`` (its C source,
  zeros/brentq.c), so it returns the same floats.
* :func:`newton` — a root of a system near a start: Newton's method to the last bit (a convex
  corner of a cam's profile, the friction equations).
"""
from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.tolerances import EPS

#: scipy's defaults: absolute and relative tolerance on x, iterations.
XTOL = 2e-12
RTOL = 4.0 * EPS
MAXITER = 100


def brentq(f: Callable[[float], float], a: float, b: float, xtol: float = XTOL, rtol: float = RTOL,
           maxiter: int = MAXITER) -> float:
    """The root of ``f`` in [a, b], where f(a) and f(b) differ in sign, to ``xtol + rtol·|x|``.

    Inverse quadratic interpolation or the secant where it moves fast enough, bisection where it
    does not: never slower than bisection, superlinear near a simple root.

    >>> abs(brentq(lambda x: x * x - 2.0, 0.0, 2.0) - math.sqrt(2.0)) < 2e-12
    True
    >>> brentq(math.cos, 0.0, 1.0)
    Traceback (most recent call last):
    ...
    graphmech.errors.OutOfDomain: f(a) and f(b) must differ in sign: f(0) = 1, f(1) = 0.540302
    """
    if not (xtol > 0.0 and rtol >= RTOL):
        raise OutOfDomain(f"tolerances xtol > 0 and rtol ≥ 4ε, not {xtol!r}, {rtol!r}")
    xpre, xcur = float(a), float(b)
    fpre, fcur = float(f(xpre)), float(f(xcur))
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise OutOfDomain(f"f(a) and f(b) must differ in sign: f({xpre:g}) = {fpre:g}, f({xcur:g}) = {fcur:g}")
    xblk = fblk = spre = scur = 0.0
    for _ in range(maxiter):
        if fpre != 0.0 and fcur != 0.0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk, fblk = xpre, fpre  # the other end of the bracket
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):  # the better end is called xcur
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2.0
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # the secant
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:  # inverse quadratic interpolation through the three points
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):  # a good short step
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0.0 else -delta)
        fcur = float(f(xcur))
    raise NoSolution(f"Brent's method did not converge in {maxiter} iterations (last x = {xcur!r})")


def newton(f: Callable[[np.ndarray], np.ndarray], jac: Callable[[np.ndarray], np.ndarray], z: np.ndarray,
           maxiter: int = MAXITER) -> tuple[np.ndarray, int]:
    """The root of f near z by Newton's method, to the last bit, and the calls of f made.

    Iterated until a step is rounding (each component within 4ε of its size, or of 1) or
    ``maxiter``; the point of least residual (largest |f_k|) is returned, whether or not it is a
    root — the caller judges the residual. A residual that grows is not the end: where the
    equations change form (a friction couple switching on, a clamp at a cam's corner) a step may
    overshoot, and the next lands where Newton's method converges fast.

    >>> z, calls = newton(lambda z: z * z - 2.0, lambda z: np.diag(2.0 * z), np.array([1.0]))
    >>> float(z[0]) == math.sqrt(2.0), calls < 10
    (True, True)
    """
    fz = f(z)
    calls = 1
    best, best_z = float(np.max(np.abs(fz))), z
    for _ in range(maxiter):
        if best == 0.0:
            break
        try:
            step = np.linalg.solve(jac(z), -fz)
        except np.linalg.LinAlgError:
            break
        z = z + step
        fz = f(z)
        calls += 1
        r = float(np.max(np.abs(fz)))
        if not math.isfinite(r):
            break
        if r < best:
            best, best_z = r, z
        elif np.all(np.abs(step) <= 4.0 * EPS * np.maximum(1.0, np.abs(z))):
            break  # at the last bit: the residual is rounding
    return best_z, calls


__all__ = ["MAXITER", "RTOL", "XTOL", "brentq", "newton"]
