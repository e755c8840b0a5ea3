"""The least value of a function on an interval: Brent's bounded search (golden sections and parabolas).

The exact solutions refine an extreme between two samples with it. It is the same algorithm, step
for step, as ``scipy.optimize.minimize_scalar(method="bounded")`` (scipy's ``fminbound``, Brent
1973, "localmin"), so it returns the same floats; it lives here because importing
``scipy.optimize`` costs a third of a second, longer than a whole cam check takes without it
(issue 23: cold starts under 0.5 s). :mod:`graphmech.roots` is its companion for a root.
"""
from __future__ import annotations

import math
from collections.abc import Callable

from graphmech.errors import OutOfDomain

#: scipy's defaults: absolute tolerance on x, function evaluations.
XATOL = 1e-5
MAXITER = 500

_SQRT_EPS = math.sqrt(2.2e-16)
_GOLDEN = 0.5 * (3.0 - math.sqrt(5.0))


def _sign(x: float) -> float:
    """numpy's sign: −1, 0 or 1 (NaN stays NaN); x may be a numpy scalar (f's values are)."""
    return x if x != x else float(x > 0.0) - float(x < 0.0)


def fminbound(f: Callable[[float], float], lo: float, hi: float, xatol: float = XATOL,
              maxiter: int = MAXITER) -> tuple[float, float]:
    """(x, f(x)) where f is least on [lo, hi], x to about ``xatol`` (at most ``maxiter`` calls of f;
    the best point found so far is returned when they run out).

    A golden-section search that takes a parabola's vertex through its last three points when that
    lands inside the bracket and shortens the step enough: never slower than golden sections,
    superlinear near a smooth minimum.

    >>> x, fx = fminbound(lambda x: (x - 1.0) ** 2, 0.0, 3.0, xatol=1e-12)
    >>> abs(x - 1.0) < 1e-8, fx < 1e-16
    (True, True)
    >>> fminbound(math.cos, 1.0, 0.0)
    Traceback (most recent call last):
    ...
    graphmech.errors.OutOfDomain: the bounds must be finite with lo ≤ hi, not 1.0, 0.0
    """
    a, b = float(lo), float(hi)
    if not (math.isfinite(a) and math.isfinite(b) and a <= b):
        raise OutOfDomain(f"the bounds must be finite with lo ≤ hi, not {lo!r}, {hi!r}")
    fulc = a + _GOLDEN * (b - a)
    nfc, xf = fulc, fulc
    rat = e = 0.0
    x = xf
    fx = f(x)
    num = 1
    ffulc = fnfc = fx
    xm = 0.5 * (a + b)
    tol1 = _SQRT_EPS * abs(xf) + xatol / 3.0
    tol2 = 2.0 * tol1
    while abs(xf - xm) > (tol2 - 0.5 * (b - a)):
        golden = True
        if abs(e) > tol1:  # try a parabola through the three points
            golden = False
            r = (xf - nfc) * (fx - ffulc)
            q = (xf - fulc) * (fx - fnfc)
            p = (xf - fulc) * q - (xf - nfc) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            r = e
            e = rat
            if abs(p) < abs(0.5 * q * r) and p > q * (a - xf) and p < q * (b - xf):  # acceptable
                rat = (p + 0.0) / q
                x = xf + rat
                if (x - a) < tol2 or (b - x) < tol2:
                    rat = tol1 * (_sign(xm - xf) + ((xm - xf) == 0))
            else:
                golden = True
        if golden:
            e = a - xf if xf >= xm else b - xf
            rat = _GOLDEN * e
        step = max(abs(rat), tol1) if abs(rat) == abs(rat) else abs(rat)  # numpy's maximum keeps a NaN
        x = xf + (_sign(rat) + (rat == 0)) * step
        fu = f(x)
        num += 1
        if fu <= fx:
            if x >= xf:
                a = xf
            else:
                b = xf
            fulc, ffulc = nfc, fnfc
            nfc, fnfc = xf, fx
            xf, fx = x, fu
        else:
            if x < xf:
                a = x
            else:
                b = x
            if fu <= fnfc or nfc == xf:
                fulc, ffulc = nfc, fnfc
                nfc, fnfc = x, fu
            elif fu <= ffulc or fulc == xf or fulc == nfc:
                fulc, ffulc = x, fu
        xm = 0.5 * (a + b)
        tol1 = _SQRT_EPS * abs(xf) + xatol / 3.0
        tol2 = 2.0 * tol1
        if num >= maxiter:
            break
    return xf, fx


__all__ = ["fminbound", "XATOL", "MAXITER"]
