"""The structural error of a four-bar function generator: the designed linkage solved exactly.

Independent of the design (``graphmech.methods.freudenstein``): the four-bar is assembled as a
:class:`~graphmech.mechanisms.linkage.Linkage` (crank AB about A, dyad B–C–D) and its output angle
ψ(φ) comes from :func:`graphmech.exact.linkage.solve` (law of cosines in the dyad's triangle), not
from Freudenstein's equation. The desired output ``ψ_d(φ)`` is the linear map of ``y = f(x)``;
the structural error is ``e(φ) = ψ(φ) − ψ_d(φ)``.

Convention (the design's): A at the origin, D at ``(−d, 0)``; φ (of AB) and ψ (of DC) counter-
clockwise from the direction D → A; a reversed link points at the angle + π.

How the extremes are found: e is sampled at ``samples`` equally spaced φ over the range (ends
included); every sampled local extremum of e (a sample whose |e| is not below either neighbour's,
on the same side of 0) is refined by zooming: 21 points across the bracket of its two neighbours,
the best one kept with its neighbours as the new bracket (10× narrower each pass), until the bracket
is below 1e-13 rad. The ends of the range are extremes too (the error there is not refined).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np

from graphmech.errors import OutOfDomain
from graphmech.exact.linkage import solve
from graphmech.mechanisms.linkage import RRR, Crank, Linkage
from graphmech.timing import best_time

__all__ = ["FourBar", "StructuralError", "convergence", "output_angle", "structural_error"]

#: Sampled points of the error over the range (the default).
SAMPLES = 2001

_ZOOM_POINTS = 21
_ZOOM_TOL = 1e-13  # rad: the refined extremum's bracket

_Fn = Callable[[np.ndarray], np.ndarray]


@dataclass(frozen=True)
class FourBar:
    """A four-bar in the design's convention: crank a, coupler b, rocker c, frame d (> 0)."""

    a: float
    b: float
    c: float
    d: float
    input_reversed: bool = False
    output_reversed: bool = False

    def linkage(self, branch: str) -> Linkage:
        lengths = (self.a, self.b, self.c, self.d)
        if not all(math.isfinite(v) and v > 0.0 for v in lengths):
            raise OutOfDomain(f"link lengths a, b, c, d = {lengths} must be finite and > 0")
        return Linkage({"A": (0.0, 0.0), "D": (-self.d, 0.0)}, Crank("1", "A", "B", self.a, 1.0),
                       (RRR("B", "C", "D", ("2", "3"), (self.b, self.c), branch),),)  # type: ignore[arg-type]


def output_angle(bar: FourBar, phi: np.ndarray, branch: str) -> tuple[np.ndarray, np.ndarray]:
    """ψ(φ) on the assembly ``branch`` ("left" / "right" of B → D), and where it assembles.

    ψ is unwrapped along the array (continuous) where valid; NaN where it does not assemble.
    """
    phi = np.asarray(phi, dtype=float)
    crank = phi + (math.pi if bar.input_reversed else 0.0)
    kin = solve(bar.linkage(branch), crank)
    psi = kin.angle["3"] - (math.pi if bar.output_reversed else 0.0)
    valid = np.asarray(kin.valid, dtype=bool)
    return np.where(valid, psi, np.nan), valid


def _near(psi: np.ndarray, want: np.ndarray) -> np.ndarray:
    """ψ − ψ_want folded into (−π, π]."""
    return np.asarray(np.angle(np.exp(1j * (psi - want))), dtype=float)


@dataclass(frozen=True)
class StructuralError:
    """The structural error of a function generator over its range (angles in rad).

    ``assembles``: False when the linkage cannot be assembled on the branch through the first
    precision point somewhere in the range, or at that point on either branch (``why`` says
    where); then the error arrays are NaN where it does not assemble and ``max_error`` is ``inf``.
    ``phi``, ``error``: the sampled curve e(φ) = ψ(φ) − ψ_d(φ); ``error_y`` the same in units of y.
    ``extremes_phi`` / ``extremes``: the located extremes of e (ends included), in φ order;
    ``extremes_sampled``: e at the samples they were refined from (the sampling's own estimate).
    ``max_error``: max |e| (rad), ``max_error_y`` in units of y.
    ``at_points``: e at the precision points (≈ 0 when the equation is met there).
    """

    branch: str
    assembles: bool
    why: str
    phi: np.ndarray
    error: np.ndarray
    error_y: np.ndarray
    extremes_phi: np.ndarray
    extremes: np.ndarray
    extremes_sampled: np.ndarray
    max_error: float
    max_error_y: float
    at_points: np.ndarray
    method: str

    def zero_at_points(self, tol: float = 1e-9) -> bool:
        """The precision points are reached: |e| ≤ ``tol`` at every one."""
        return bool(np.all(np.abs(self.at_points) <= tol))


def structural_error(bar: FourBar, f: _Fn, x0: float, x1: float, phi0: float, dphi: float,
                     psi0: float, dpsi: float, precision_phi: np.ndarray,
                     samples: int = SAMPLES) -> StructuralError:
    """The structural error of ``bar`` generating ``f`` over ``[x0, x1]`` (map as in the design).

    The assembly branch is the one that passes through the first precision point. A linkage that
    does not assemble over the whole range is a result (``assembles`` False, ``why``), not an error.

    Raises
    ------
    OutOfDomain
        ``samples`` < 3, Δφ or Δψ = 0, x₀ = x₁, f(x₀) = f(x₁), or no precision point.
    """
    if samples < 3:
        raise OutOfDomain(f"samples = {samples}: at least 3")
    if dphi == 0.0 or dpsi == 0.0 or x0 == x1:
        raise OutOfDomain("Δφ, Δψ and x₁ − x₀ must not be 0")
    y0, y1 = (float(v) for v in np.asarray(f(np.array([x0, x1], dtype=float)), dtype=float))
    if y0 == y1:
        raise OutOfDomain("f(x₀) = f(x₁): no linear map of y to ψ")
    pp = np.asarray(precision_phi, dtype=float).ravel()
    if pp.size == 0:
        raise OutOfDomain("no precision point")

    def desired(phi: np.ndarray) -> np.ndarray:
        x = x0 + (phi - phi0) * (x1 - x0) / dphi
        return psi0 + dpsi * (np.asarray(f(x), dtype=float) - y0) / (y1 - y0)

    # the branch through the first precision point
    best, branch = math.inf, ""
    for side in ("left", "right"):
        psi1, ok = output_angle(bar, pp[:1], side)
        if ok[0]:
            miss = abs(float(_near(psi1, desired(pp[:1]))[0]))
            if miss < best:
                best, branch = miss, side
    phi = phi0 + dphi * np.linspace(0.0, 1.0, samples)
    empty = np.full(0, np.nan)
    if not branch:
        at = f"{math.degrees(float(pp[0])):.4f}°"
        return StructuralError("", False, f"cannot be assembled at the first precision point φ = {at} "
                               "on either branch", phi, np.full(samples, np.nan), np.full(samples, np.nan),
                               empty, empty, empty, math.inf, math.inf, np.full(pp.size, np.nan), "")

    def err(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        psi, ok = output_angle(bar, phi, branch)
        return _near(psi, desired(phi)), ok

    e, ok = err(phi)
    at_points = err(pp)[0]
    scale_y = (y1 - y0) / dpsi
    method = (f"ψ(φ) by exact/linkage.solve on the {branch} branch at {samples} equally spaced φ; "
              f"sampled extremes refined by zooming ({_ZOOM_POINTS} points a pass, bracket 10× narrower) "
              f"to {_ZOOM_TOL:g} rad")
    if not np.all(ok):
        first = float(np.degrees(phi[~ok][0]))
        return StructuralError(branch, False, f"cannot be assembled on the {branch} branch from φ = "
                               f"{first:.4f}° on (no continuous motion over the range)", phi, e,
                               e * scale_y, empty, empty, empty, math.inf, math.inf, at_points, method)

    # sampled local extremes of e: |e| not below either neighbour (interior), plus the two ends
    mag = np.abs(e)
    inner = np.flatnonzero((mag[1:-1] >= mag[:-2]) & (mag[1:-1] >= mag[2:])) + 1
    inner = inner[mag[inner] > 0.0]
    sampled = np.concatenate([e[:1], e[inner], e[-1:]])
    lo, hi = phi[inner - 1], phi[inner + 1]
    while inner.size and float(np.max(np.abs(hi - lo))) > _ZOOM_TOL:
        t = np.linspace(0.0, 1.0, _ZOOM_POINTS)
        grid = lo[:, None] + (hi - lo)[:, None] * t[None, :]
        g = np.abs(err(grid.ravel())[0]).reshape(grid.shape)
        k = np.clip(np.argmax(g, axis=1), 1, _ZOOM_POINTS - 2)
        rows = np.arange(grid.shape[0])
        lo, hi = grid[rows, k - 1], grid[rows, k + 1]
    ext_phi = np.concatenate([phi[:1], (lo + hi) / 2.0, phi[-1:]])  # in φ order, as the samples
    ext = err(ext_phi)[0]
    peak = float(np.max(np.abs(np.concatenate([ext, e]))))
    return StructuralError(branch, True, "", phi, e, e * scale_y, ext_phi, ext, sampled, peak,
                           peak * abs(scale_y), at_points, method)


def convergence(bar: FourBar, f: _Fn, x0: float, x1: float, phi0: float, dphi: float, psi0: float,
                dpsi: float, precision_phi: np.ndarray, case: str = "",
                samples: tuple[int, ...] = (11, 21, 51, 101, 201, 501, 2001),
                repeat: int = 3) -> list[dict[str, Any]]:
    """Bench records (as :mod:`graphmech.bench`'s) of the structural error at each number of samples.

    ``max_rel_error``: the located max |e| against the one at the most samples (relative);
    ``sampled_rel_error``: the largest sampled extreme (not refined) against that same reference;
    ``max_error_deg``: the located max |e| in degrees; ``seconds``: per call, best of ``repeat``.
    Without the refinement the max is only as good as the sampling (``sampled_rel_error``); a
    coarse sampling may also miss an extreme altogether.
    """
    outs = []
    for n in samples:
        secs, out = best_time(partial(structural_error, bar, f, x0, x1, phi0, dphi, psi0, dpsi,
                                      precision_phi, n), repeat)
        outs.append((n, secs, out))
    ref = outs[-1][2].max_error
    return [{"method": "freudenstein structural error", "case": case, "n": n, "seconds": secs,
             "max_rel_error": abs(out.max_error - ref) / ref,
             "sampled_rel_error": abs(float(np.max(np.abs(out.extremes_sampled))) - ref) / ref,
             "max_error_deg": math.degrees(out.max_error)} for n, secs, out in outs]
