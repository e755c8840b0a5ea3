"""A root of a function bracketed by a sign change: Brent's method (Brent 1973, "zero").

The exact solutions refine an extreme or a crossing between two samples with it. It is the same
algorithm, step for step, as ``scipy.optimize.brentq`` (its C source, zeros/brentq.c), so it
returns the same floats; it lives here because importing ``scipy.optimize`` costs a third of a
second, longer than a whole cam check takes without it (issue 23: cold starts under 0.5 s).
"""
from __future__ import annotations

import math
from collections.abc import Callable

from graphmech.errors import NoSolution, OutOfDomain

#: scipy's defaults: absolute and relative tolerance on x, iterations.
XTOL = 2e-12
RTOL = 4.0 * 2.220446049250313e-16
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


__all__ = ["brentq", "XTOL", "RTOL", "MAXITER"]
