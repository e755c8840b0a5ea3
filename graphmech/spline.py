"""The periodic cubic spline through a closed run of points: scipy's ``CubicSpline(bc_type="periodic")``.

A cam given point by point is the spline through its points. This is the same construction, step
for step, as scipy's (the condensed cyclic tridiagonal system solved twice by LAPACK's ``gtsv``,
Gaussian elimination with partial pivoting; the Hermite coefficients; ``PPoly``'s evaluation), so
it gives the same floats; it lives here because importing ``scipy.interpolate`` costs half a second,
longer than a whole check of a cam given by points takes without it (issue 23: cold starts under
0.5 s). :meth:`PeriodicSpline.point` evaluates one parameter in scalar arithmetic for the root
finders, :meth:`PeriodicSpline.at` many at once.
"""
from __future__ import annotations

import math
from bisect import bisect_right

import numpy as np

from graphmech.errors import OutOfDomain


def _gtsv(dl: list[float], d: list[float], du: list[float], b: list[list[float]]) -> list[list[float]]:
    """LAPACK's dgtsv (reference implementation): the tridiagonal system with sub-, main and
    super-diagonals ``dl``, ``d``, ``du`` and right-hand sides ``b`` (rows of columns), solved by
    Gaussian elimination with partial pivoting. The lists are overwritten."""
    n = len(d)
    nrhs = len(b[0])
    for i in range(n - 1):
        if abs(d[i]) >= abs(dl[i]):  # no row interchange
            if d[i] == 0.0:
                raise OutOfDomain("the spline's system is singular (repeated points?)")
            fact = dl[i] / d[i]
            d[i + 1] = d[i + 1] - fact * du[i]
            for j in range(nrhs):
                b[i + 1][j] = b[i + 1][j] - fact * b[i][j]
            if i < n - 2:
                dl[i] = 0.0
        else:  # interchange rows i and i + 1
            fact = d[i] / dl[i]
            d[i] = dl[i]
            temp = d[i + 1]
            d[i + 1] = du[i] - fact * temp
            if i < n - 2:
                dl[i] = du[i + 1]
                du[i + 1] = -fact * dl[i]
            du[i] = temp
            for j in range(nrhs):
                temp = b[i][j]
                b[i][j] = b[i + 1][j]
                b[i + 1][j] = temp - fact * b[i + 1][j]
    if d[n - 1] == 0.0:
        raise OutOfDomain("the spline's system is singular (repeated points?)")
    for j in range(nrhs):
        b[n - 1][j] = b[n - 1][j] / d[n - 1]
        if n > 1:
            b[n - 2][j] = (b[n - 2][j] - du[n - 2] * b[n - 1][j]) / d[n - 2]
        for i in range(n - 3, -1, -1):
            b[i][j] = (b[i][j] - du[i] * b[i + 1][j] - dl[i] * b[i + 2][j]) / d[i]
    return b


class PeriodicSpline:
    """The periodic cubic spline through ``y[k]`` at the increasing ``x[k]`` (``y[-1] == y[0]``;
    rows of coordinates, at least 4 of them), as ``CubicSpline(x, y, bc_type="periodic")``.

    >>> s = PeriodicSpline([0.0, 1.0, 2.0, 3.0, 4.0], [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0], [1.0, 0.0]])
    >>> s.point(1.0), s.point(5.0), s.point(-3.0)
    ((0.0, 1.0), (0.0, 1.0), (0.0, 1.0))
    """

    def __init__(self, x: list[float], y: list[list[float]]) -> None:
        n = len(x)
        x = [float(v) for v in x]
        y = [[float(v) for v in row] for row in y]
        if n < 4 or len(y) != n or y[0] != y[-1]:
            raise OutOfDomain("a periodic spline needs at least 4 points, the last equal to the first")
        if not all(math.isfinite(v) for v in x) or not all(math.isfinite(v) for row in y for v in row):
            raise OutOfDomain("a spline's parameters and points must be finite")
        dim = len(y[0])
        dx = [x[i + 1] - x[i] for i in range(n - 1)]
        if not all(h > 0.0 for h in dx):
            raise OutOfDomain("a spline's parameter must increase strictly")
        slope = [[(y[i + 1][j] - y[i][j]) / dx[i] for j in range(dim)] for i in range(n - 1)]
        # The banded system of CubicSpline (rows: upper, main, lower diagonal), periodic: n − 1
        # unknowns, condensed to n − 2 by taking out the last row and column.
        upper = [0.0, 0.0] + dx[:-1]
        main = [0.0] + [2 * (dx[i] + dx[i + 1]) for i in range(n - 2)] + [0.0]
        lower = dx[1:] + [0.0, 0.0]
        b = [[0.0] * dim] + [[3 * (dx[i + 1] * slope[i][j] + dx[i] * slope[i + 1][j]) for j in range(dim)]
                             for i in range(n - 2)]
        main[0] = 2 * (dx[-1] + dx[0])
        upper[1] = dx[-1]
        a_m1_0, a_m1_m2, a_m1_m1, a_m2_m1, a_0_m1 = dx[-2], dx[-1], 2 * (dx[-1] + dx[-2]), dx[-3], dx[0]
        b[0] = [3 * (dx[0] * slope[-1][j] + dx[-1] * slope[0][j]) for j in range(dim)]
        b[-1] = [3 * (dx[-1] * slope[-2][j] + dx[-2] * slope[-1][j]) for j in range(dim)]
        m = n - 2  # the condensed system: columns 0 … n − 3 of the banded rows
        du, dd, dl = upper[1:m], main[:m], lower[:m - 1]
        s1 = _gtsv(list(dl), list(dd), list(du), [list(row) for row in b[:m]])
        b2 = [[0.0] for _ in range(m)]
        b2[0][0] = -a_0_m1
        b2[-1][0] = -a_m2_m1
        s2 = [row[0] for row in _gtsv(list(dl), list(dd), list(du), b2)]
        s_m1 = [(b[-1][j] - a_m1_0 * s1[0][j] - a_m1_m2 * s1[-1][j]) / (a_m1_m1 + a_m1_0 * s2[0] + a_m1_m2 * s2[-1])
                for j in range(dim)]
        s = [[s1[i][j] + s_m1[j] * s2[i] for j in range(dim)] for i in range(m)]
        s += [s_m1, s[0]]
        if not all(math.isfinite(v) for row in s for v in row):
            raise OutOfDomain("the spline's slopes overflow: its points are too far apart for floats")
        # CubicHermiteSpline's coefficients, highest power first
        coef = []
        for i in range(n - 1):
            row = []
            for j in range(dim):
                t = (s[i][j] + s[i + 1][j] - 2 * slope[i][j]) / dx[i]
                row.append((t / dx[i], (slope[i][j] - s[i][j]) / dx[i] - t, s[i][j], y[i][j]))
            coef.append(row)
        self.x = x
        self._coef = coef
        self._dim = dim
        self.c = np.array([[[coef[i][j][k] for j in range(dim)] for i in range(n - 1)] for k in range(4)])

    @property
    def period(self) -> float:
        """x[-1] − x[0]."""
        return self.x[-1] - self.x[0]

    def _reduce(self, t: float) -> tuple[int, float]:
        x = self.x
        u = x[0] + (t - x[0]) % (x[-1] - x[0])  # PPoly's periodic extrapolation
        i = min(max(bisect_right(x, u) - 1, 0), len(x) - 2)  # the interval closed on the left
        return i, u - x[i]

    def point(self, t: float, order: int = 0) -> tuple[float, ...]:
        """The spline (order 0) or its derivative of that order (1, 2, 3) at one t, coordinate by
        coordinate: PPoly's sum of the powers of s = t − x[i], lowest first."""
        i, s = self._reduce(float(t))
        out = []
        for a3, a2, a1, a0 in self._coef[i]:
            if order == 0:
                ss = s * s
                out.append(0.0 + a0 + a1 * s + a2 * ss + a3 * (ss * s))
            elif order == 1:
                out.append(0.0 + a1 + a2 * s * 2.0 + a3 * (s * s) * 3.0)
            elif order == 2:
                out.append(0.0 + a2 * 2.0 + a3 * s * 6.0)
            elif order == 3:
                out.append(0.0 + a3 * 6.0)
            else:
                raise OutOfDomain(f"a cubic's derivative of order 0 … 3, not {order}")
        return tuple(out)

    def point_and_slope(self, t: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """(:meth:`point` of order 0, of order 1) at one t, its interval found once."""
        i, s = self._reduce(float(t))
        ss = s * s
        sss = ss * s
        rows = self._coef[i]
        return (tuple(0.0 + a0 + a1 * s + a2 * ss + a3 * sss for a3, a2, a1, a0 in rows),
                tuple(0.0 + a1 + a2 * s * 2.0 + a3 * ss * 3.0 for a3, a2, a1, a0 in rows))

    def at(self, t: np.ndarray, order: int = 0) -> np.ndarray:
        """:meth:`point` at each of ``t``, shape (len(t), dim): the same floats, array by array."""
        x = np.asarray(self.x)
        t = np.asarray(t, dtype=float)
        u = x[0] + (t.ravel() - x[0]) % (x[-1] - x[0])
        i = np.clip(np.searchsorted(x, u, side="right") - 1, 0, len(x) - 2)
        s = (u - x[i])[:, None]
        c = self.c[:, i, :]
        if order == 0:
            ss = s * s
            out = 0.0 + c[3] + c[2] * s + c[1] * ss + c[0] * (ss * s)
        elif order == 1:
            out = 0.0 + c[2] + c[1] * s * 2.0 + c[0] * (s * s) * 3.0
        elif order == 2:
            out = 0.0 + c[1] * 2.0 + c[0] * s * 6.0
        elif order == 3:
            out = 0.0 + c[0] * 6.0 + 0.0 * s
        else:
            raise OutOfDomain(f"a cubic's derivative of order 0 … 3, not {order}")
        return np.asarray(out.reshape(t.shape + (self._dim,)))


__all__ = ["PeriodicSpline"]
