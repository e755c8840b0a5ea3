"""The follower's motion laws for disc cams (推程/回程 with 远/近休止): s(δ) and its derivatives.

A :class:`~graphmech.mechanisms.cam.MotionProgram` is a string of segments — rise (推程), dwell
(休止), return (回程), dwell … — whose angles add up to 2π. Over a rise or return of angle δ0 the
follower moves by the stroke h following a law f(x), x = (δ − start)/δ0 ∈ [0, 1):

==============  =======================  ===============================================
law             textbook name            f(x)
==============  =======================  ===============================================
``uniform``     等速                     x
``parabolic``   等加速等减速             2x² for x < ½, 1 − 2(1 − x)² for x ≥ ½
``cosine``      余弦加速度 (harmonic)    (1 − cos πx)/2
``sine``        正弦加速度 (cycloidal)   x − sin(2πx)/(2π)
``poly345``     3-4-5 polynomial         10x³ − 15x⁴ + 6x⁵
``table``       tabulated                monotone cubic (PCHIP) through the points
==============  =======================  ===============================================

A rise gives s = h·f(x), a return s = h·(1 − f(x)); a dwell holds s at h after a rise and at 0
after a return (the program starts at s = 0). Derivatives with respect to the cam angle are
d^k s/dδ^k = ±h·f^(k)(x)/δ0^k (+ for a rise, − for a return); with a constant ω the follower's
velocity, acceleration and jerk are ω·s′, ω²·s″, ω³·s‴.

Everything here is a pure function of the (frozen) program; evaluation is vectorised over the
cam angles (a loop runs over the handful of segments only). scipy is imported only when a
program has a ``table`` law.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, cast

import numpy as np

from graphmech.errors import OutOfDomain, SceneError
from graphmech.mechanisms.cam import Law, MotionProgram

__all__ = ["LAWS", "Extremum", "Impact", "breakpoints", "displacement", "impacts", "maxima", "validate"]

#: The motion laws a rise or return may follow.
LAWS: tuple[Law, ...] = ("uniform", "parabolic", "cosine", "sine", "poly345", "table")

TWO_PI = 2.0 * math.pi

#: The segments' angles must add up to 2π within this, rad.
ANGLE_SUM_TOL = 1e-9

#: A cam angle this close to a joint (or to a law's own knot, e.g. the parabolic law's x = ½) is
#: evaluated exactly there, i.e. takes the right-hand value: 8 ulp of 2π ≈ 7.1e-15 rad. It absorbs
#: the rounding of an angle that the caller computed another way (π/4 + π/4 against π/2).
SNAP = 8.0 * float(np.spacing(TWO_PI))

#: Two candidate extrema within this relative difference count as the same maximum (the first
#: cam angle wins).
_TIE_REL = 1e-12

# Fractions of a segment where every analytic law's |f'|, |f''|, |f'''| peaks (x = 1 as a left-hand
# limit is added separately): 0, ¼, ½, ¾ and the poly345 law's (3 ∓ √3)/6.
_ANALYTIC_CANDIDATES = np.array([0.0, 0.25, 0.5, 0.75, (3.0 - math.sqrt(3.0)) / 6.0, (3.0 + math.sqrt(3.0)) / 6.0])


# --------------------------------------------------------------------------------------------
# the laws f^(k)(x) on one segment
# --------------------------------------------------------------------------------------------


def _ppoly_eval(pp: Any, x: np.ndarray, k: int, left: bool) -> np.ndarray:
    """k-th derivative of a scipy PPoly at x, on the interval to the right of a knot (or, with
    ``left``, to its left: the left-hand limit). Evaluated from the coefficients, exactly."""
    knots = pp.x
    coef = pp.c  # (degree + 1, intervals), highest power first
    i = np.searchsorted(knots, x, side="left" if left else "right") - 1
    i = np.clip(i, 0, len(knots) - 2)
    t = x - knots[i]
    degree = coef.shape[0] - 1
    out = np.zeros_like(x, dtype=float)
    for row in range(coef.shape[0] - k):  # Horner over the k-th derivative's coefficients
        power = degree - row
        factor = math.perm(power, k)  # power·(power−1)···(power−k+1)
        out = out * t + factor * coef[row, i]
    return out


def _f(law: str | None, x: np.ndarray, k: int, table: Any = None, left: bool = False) -> np.ndarray:
    """d^k f/dx^k of a law at x ∈ [0, 1] (right-hand values; left-hand limits with ``left``)."""
    x = np.asarray(x, dtype=float)
    if law == "uniform":
        return x.copy() if k == 0 else np.full_like(x, 1.0 if k == 1 else 0.0)
    if law == "parabolic":
        second_half = (x > 0.5) if left else (x >= 0.5)
        y = 1.0 - x
        if k == 0:
            return np.where(second_half, 1.0 - 2.0 * y * y, 2.0 * x * x)
        if k == 1:
            return np.where(second_half, 4.0 * y, 4.0 * x)
        if k == 2:
            return np.where(second_half, -4.0, 4.0)
        return np.zeros_like(x)
    if law == "cosine":
        px = math.pi * x
        if k == 0:
            return (1.0 - np.cos(px)) / 2.0
        if k == 1:
            return math.pi / 2.0 * np.sin(px)
        if k == 2:
            return math.pi**2 / 2.0 * np.cos(px)
        return -(math.pi**3) / 2.0 * np.sin(px)
    if law == "sine":
        t = TWO_PI * x
        if k == 0:
            return x - np.sin(t) / TWO_PI
        if k == 1:
            return 1.0 - np.cos(t)
        if k == 2:
            return TWO_PI * np.sin(t)
        return TWO_PI**2 * np.cos(t)
    if law == "poly345":
        if k == 0:
            return x**3 * (10.0 + x * (-15.0 + 6.0 * x))
        if k == 1:
            return x**2 * (30.0 + x * (-60.0 + 30.0 * x))
        if k == 2:
            return x * (60.0 + x * (-180.0 + 120.0 * x))
        return 60.0 + x * (-360.0 + 360.0 * x)
    if law == "table":
        return _ppoly_eval(table, x, k, left)
    raise AssertionError(f"unknown law {law!r}")  # validate() rejects it first


# --------------------------------------------------------------------------------------------
# validation and the compiled program
# --------------------------------------------------------------------------------------------


def _finite_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool) and math.isfinite(value)


def _table_problems(table: Any, path: str) -> list[tuple[str, str]]:
    try:
        points = [tuple(p) for p in table]
    except TypeError:
        return [(path, "must be a sequence of (x, y) points")]
    if len(points) < 2:
        return [(path, f"a table law needs at least the points (0, 0) and (1, 1), got {len(points)} point(s)")]
    problems: list[tuple[str, str]] = []
    for j, p in enumerate(points):
        if len(p) != 2 or not all(_finite_number(v) for v in p):
            problems.append((f"{path}[{j}]", f"must be a pair of finite numbers (x, y), got {p!r}"))
    if problems:
        return problems
    xs = [float(p[0]) for p in points]
    ys = [float(p[1]) for p in points]
    if (xs[0], ys[0]) != (0.0, 0.0):
        problems.append((f"{path}[0]", f"the first point must be (0, 0), got ({xs[0]:g}, {ys[0]:g})"))
    if (xs[-1], ys[-1]) != (1.0, 1.0):
        problems.append((f"{path}[{len(points) - 1}]", f"the last point must be (1, 1), got ({xs[-1]:g}, {ys[-1]:g})"))
    for j in range(1, len(points)):
        if not xs[j] > xs[j - 1]:
            problems.append((f"{path}[{j}]", f"x must increase strictly: {xs[j]:g} after {xs[j - 1]:g}"))
        if ys[j] < ys[j - 1]:
            problems.append((f"{path}[{j}]", f"y must not decrease (the follower would turn back): {ys[j]:g} after {ys[j - 1]:g}"))
    return problems


def validate(program: MotionProgram) -> list[tuple[str, str]]:
    """Every problem of a motion program, as (key path, reason); empty when it is valid.

    The rules: the stroke is finite and > 0; every segment's angle (rad) is finite and > 0 (a dwell
    of angle 0 is simply left out) and the angles add up to 2π within 1e-9 rad; the kind is
    "rise", "return" or "dwell"; starting from s = 0, rises and returns alternate (a rise lifts
    the follower by the stroke, a return lowers it by the stroke) and s is back at 0 by the end;
    a rise or return has a known law (:data:`LAWS`); a ``table`` law's points start at (0, 0),
    end at (1, 1), have strictly increasing x and non-decreasing y, all finite. A dwell's ``law``
    and a non-table law's ``table`` are ignored.

    Parameters
    ----------
    program : MotionProgram

    Returns
    -------
    list of (str, str)
        Key paths such as ``"program.segments[2].angle"`` with the reason; the other functions of
        this module raise :class:`~graphmech.errors.SceneError` with this list.

    Examples
    --------
    >>> from graphmech.mechanisms.cam import MotionProgram, Segment
    >>> bad = MotionProgram(0.02, (Segment("rise", math.pi, "sine"), Segment("dwell", 0.0),
    ...                            Segment("return", math.pi, "cubic")))
    >>> for key, reason in validate(bad):
    ...     print(key, "-", reason)
    program.segments[1].angle - must be > 0 (a dwell of angle 0 is left out), got 0
    program.segments[2].law - unknown law 'cubic'; one of uniform, parabolic, cosine, sine, poly345, table
    """
    problems: list[tuple[str, str]] = []
    stroke: Any = getattr(program, "stroke", None)
    if not _finite_number(stroke) or not stroke > 0:
        problems.append(("program.stroke", f"must be a finite number > 0 (m, or rad), got {stroke!r}"))
    segments: Any = getattr(program, "segments", None)  # like stroke: whatever was passed, checked here
    try:
        segments = tuple(segments)
    except TypeError:
        return problems + [("program.segments", "must be a sequence of segments")]
    if not segments:
        return problems + [("program.segments", "no segments: a program needs at least a rise and a return")]

    total = 0.0
    angles_ok = True
    level = 0  # 0 at the bottom, 1 at the top
    for i, seg in enumerate(segments):
        path = f"program.segments[{i}]"
        angle: Any = getattr(seg, "angle", None)
        if not _finite_number(angle):
            problems.append((f"{path}.angle", f"must be a finite number of radians, got {angle!r}"))
            angles_ok = False
        elif not angle > 0:
            problems.append((f"{path}.angle", f"must be > 0 (a dwell of angle 0 is left out), got {angle:g}"))
            angles_ok = False
        else:
            total += float(angle)
        kind = getattr(seg, "kind", None)
        if kind not in ("rise", "return", "dwell"):
            problems.append((f"{path}.kind", f"must be 'rise', 'return' or 'dwell', got {kind!r}"))
            continue
        if kind == "dwell":
            continue
        if kind == "rise" and level == 1:
            problems.append((f"{path}.kind", "a rise after a rise: rises and returns must alternate (the follower is already up by the stroke)"))
        elif kind == "return" and level == 0:
            problems.append((f"{path}.kind", "a return with the follower down: rises and returns must alternate, starting with a rise"))
        level = 1 if kind == "rise" else 0
        law = getattr(seg, "law", None)
        if law not in LAWS:
            problems.append((f"{path}.law", f"unknown law {law!r}; one of {', '.join(LAWS)}"))
        elif law == "table":
            problems += _table_problems(getattr(seg, "table", ()), f"{path}.table")
    if level == 1:
        problems.append(("program.segments", "the displacement ends at the stroke, not 0: the program needs a return after its last rise"))
    if angles_ok and abs(total - TWO_PI) > ANGLE_SUM_TOL:
        problems.append(("program.segments", f"the angles add up to {total:.12g} rad, not 2π = {TWO_PI:.12g} rad"))
    return problems


@dataclass(frozen=True)
class _Compiled:
    """A validated program as arrays, ready for vectorised evaluation."""

    stroke: float
    kinds: tuple[str, ...]
    laws: tuple[str | None, ...]
    tables: tuple[Any, ...]  # PchipInterpolator or None
    starts: np.ndarray  # (n,) rad
    angles: np.ndarray  # (n,) rad
    levels: np.ndarray  # (n,) s during a dwell (m or rad)
    knot_angle: np.ndarray  # sorted: joints, laws' own knots, and 2π (the wrap)
    knot_seg: np.ndarray
    knot_x: np.ndarray


def _interior_knots(law: str | None, table: Any) -> np.ndarray:
    """The law's own joints inside a segment, as fractions x ∈ (0, 1)."""
    if law == "parabolic":
        return np.array([0.5])
    if law == "table":
        return np.asarray(table.x[1:-1], dtype=float)
    return np.empty(0)


def _build(program: MotionProgram) -> _Compiled:
    problems = validate(program)
    if problems:
        raise SceneError(problems, "motion program")
    h = float(program.stroke)
    segs = tuple(program.segments)
    angles = np.array([float(s.angle) for s in segs])
    starts = np.concatenate(([0.0], np.cumsum(angles)[:-1]))
    tables: list[Any] = []
    levels = np.zeros(len(segs))
    level = 0.0
    for i, s in enumerate(segs):
        if s.kind == "rise":
            level = h
        elif s.kind == "return":
            level = 0.0
        levels[i] = level
        if s.kind != "dwell" and s.law == "table":
            from scipy.interpolate import (
                PchipInterpolator,  # lazily: only table laws need scipy
            )

            pts = np.asarray(s.table, dtype=float)
            tables.append(PchipInterpolator(pts[:, 0], pts[:, 1]))
        else:
            tables.append(None)
    laws = tuple(s.law if s.kind != "dwell" else None for s in segs)
    k_angle, k_seg, k_x = [], [], []
    for i in range(len(segs)):
        xs = np.concatenate(([0.0], _interior_knots(laws[i], tables[i])))
        k_angle.append(starts[i] + xs * angles[i])
        k_seg.append(np.full(len(xs), i))
        k_x.append(xs)
    k_angle.append(np.array([TWO_PI]))  # the wrap: 2π is δ = 0, the first segment's start
    k_seg.append(np.array([0]))
    k_x.append(np.array([0.0]))
    ka, ks, kx = np.concatenate(k_angle), np.concatenate(k_seg), np.concatenate(k_x)
    order = np.argsort(ka, kind="stable")
    return _Compiled(h, tuple(s.kind for s in segs), laws, tuple(tables), starts, angles, levels,
                     ka[order], ks[order], kx[order])


@lru_cache(maxsize=64)
def _build_cached(program: MotionProgram) -> _Compiled:
    return _build(program)


def _compile(program: MotionProgram) -> _Compiled:
    try:
        return _build_cached(program)
    except TypeError:  # unhashable (e.g. a table given as lists): no caching
        return _build(program)


def _locate(c: _Compiled, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The segment owning each angle (1-D, finite) and the fraction x ∈ [0, 1] into it."""
    d = np.mod(delta, TWO_PI)
    seg = np.clip(np.searchsorted(c.starts, d, side="right") - 1, 0, len(c.starts) - 1)
    x = np.clip((d - c.starts[seg]) / c.angles[seg], 0.0, 1.0)
    # angles within SNAP of a joint or knot are taken exactly there (the right-hand value)
    ka = c.knot_angle
    pos = np.searchsorted(ka, d)
    lo = np.clip(pos - 1, 0, len(ka) - 1)
    hi = np.clip(pos, 0, len(ka) - 1)
    near = np.where(np.abs(ka[hi] - d) <= np.abs(d - ka[lo]), hi, lo)
    snap = np.abs(ka[near] - d) <= SNAP
    seg = np.where(snap, c.knot_seg[near], seg)
    x = np.where(snap, c.knot_x[near], x)
    return seg, x


def _segment_values(c: _Compiled, i: int, x: np.ndarray, order: int, left: bool = False) -> np.ndarray:
    """d^order s/dδ^order on segment i at fractions x (right-hand values, or left-hand limits)."""
    kind = c.kinds[i]
    if kind == "dwell":
        return np.full_like(x, c.levels[i] if order == 0 else 0.0, dtype=float)
    f = _f(c.laws[i], x, order, c.tables[i], left)
    h = c.stroke
    if order == 0:
        return h * f if kind == "rise" else h * (1.0 - f)
    scale = h / c.angles[i] ** order
    return cast(np.ndarray, scale * f if kind == "rise" else -scale * f)


# --------------------------------------------------------------------------------------------
# the public functions
# --------------------------------------------------------------------------------------------


def displacement(program: MotionProgram, delta: np.ndarray | float, order: int = 0) -> np.ndarray:
    """The follower's displacement s(δ) or its derivative d^order s/dδ^order.

    Parameters
    ----------
    program : MotionProgram
        A valid program (see :func:`validate`); stroke h in m (translating follower) or rad
        (oscillating follower).
    delta : array_like or float
        Cam angles δ, rad, any shape; taken modulo 2π. Must be finite.
    order : int
        0 for s, 1 for ds/dδ, 2 for d²s/dδ², 3 for d³s/dδ³.

    Returns
    -------
    numpy.ndarray
        Same shape as ``delta`` (0-d for a scalar): s in m (or rad), the derivatives in m/rad^order
        (or rad/rad^order). A segment owns [start, end): at a joint the value is the right-hand
        limit, i.e. the next segment's; likewise at a law's own joint (the parabolic law's
        x = ½, a table's points). Angles within :data:`SNAP` (≈ 7e-15 rad) of a joint count as
        the joint. The uniform law's d²s/dδ² is 0 inside the stroke: its infinite accelerations
        at the ends are reported by :func:`impacts`, never as inf. Never inf or NaN.

    Raises
    ------
    SceneError
        If the program is invalid (every problem, with its key path).
    ValueError
        If ``order`` is not 0…3 or an angle is not finite.

    Notes
    -----
    With x = (δ − start)/δ0 on a segment of angle δ0, d/dδ = (1/δ0)·d/dx, so a rise gives
    d^k s/dδ^k = h·f^(k)(x)/δ0^k and a return (s = h·(1 − f)) gives −h·f^(k)(x)/δ0^k for k ≥ 1.

    Examples
    --------
    Rise 50 mm over π/2 by the sine (cycloidal) law, far dwell, return likewise, near dwell:

    >>> from graphmech.mechanisms.cam import MotionProgram, Segment
    >>> p = MotionProgram(0.05, (Segment("rise", math.pi / 2, "sine"), Segment("dwell", math.pi / 2),
    ...                          Segment("return", math.pi / 2, "sine"), Segment("dwell", math.pi / 2)))
    >>> float(displacement(p, math.pi / 4))                        # half the stroke at mid-rise, m
    0.025
    >>> np.round(displacement(p, [0.0, math.pi / 4, 3.0, 5 * math.pi / 4], order=1), 6).tolist()
    [0.0, 0.063662, 0.0, -0.063662]
    >>> round(float(displacement(p, math.pi / 8, order=2)), 6)    # 2πh/δ0², m/rad²
    0.127324
    >>> displacement(p, np.linspace(0, 2 * math.pi, 3600)).shape
    (3600,)
    """
    if isinstance(order, bool) or order not in (0, 1, 2, 3):
        raise OutOfDomain(f"order must be 0, 1, 2 or 3, got {order!r}")
    c = _compile(program)
    d = np.asarray(delta, dtype=float)
    if not np.all(np.isfinite(d)):
        raise OutOfDomain("cam angles δ must be finite")
    flat = d.ravel()
    seg, x = _locate(c, flat)
    out = np.empty(flat.shape)
    for i in range(len(c.kinds)):  # a loop over the segments, not the angles
        mask = seg == i
        if mask.any():
            out[mask] = _segment_values(c, i, x[mask], order)
    return (out + 0.0).reshape(d.shape)  # + 0.0 turns −0.0 into 0.0


def breakpoints(program: MotionProgram) -> np.ndarray:
    """The joints between the program's segments: their cam angles in [0, 2π), sorted, 0 included.

    Only the joints between segments; a law's own joints (the parabolic law's x = ½, a table's
    points) are not included — :func:`impacts` reports those where something jumps.

    Parameters
    ----------
    program : MotionProgram

    Returns
    -------
    numpy.ndarray
        (n,) angles, rad, one per segment (its start).

    Examples
    --------
    >>> from graphmech.mechanisms.cam import MotionProgram, Segment
    >>> p = MotionProgram(0.05, (Segment("rise", math.pi / 2, "cosine"), Segment("dwell", math.pi / 2),
    ...                          Segment("return", math.pi, "cosine")))
    >>> (breakpoints(p) / math.pi).tolist()
    [0.0, 0.5, 1.0]
    """
    return _compile(program).starts.copy()


@dataclass(frozen=True)
class Impact:
    """A jump of the follower's velocity (rigid impact, 刚性冲击) or acceleration (soft impact,
    柔性冲击) at a joint.

    Parameters
    ----------
    angle : float
        The joint's cam angle, rad, in [0, 2π).
    kind : str
        ``"rigid"``: ds/dδ jumps, the acceleration is (theoretically) infinite there;
        ``"soft"``: ds/dδ is continuous but d²s/dδ² jumps by a finite amount.
    jump : float
        Right minus left: of ds/dδ (m/rad, or rad/rad) for a rigid impact, of d²s/dδ²
        (m/rad², or rad/rad²) for a soft one. Multiply by ω (ω²) for the velocity (acceleration).
    """

    angle: float
    kind: str
    jump: float


def impacts(program: MotionProgram, tol: float = 1e-9) -> tuple[Impact, ...]:
    """The rigid and soft impacts of a program, in order of cam angle.

    Every joint is examined — between segments, including the wrap 2π → 0, and a law's own joints
    (the parabolic law's x = ½; the interior points of a table, where the PCHIP interpolant's
    second derivative generally jumps). Where ds/dδ jumps the impact is rigid; otherwise, where
    d²s/dδ² jumps, it is soft; where neither jumps there is no entry.

    Parameters
    ----------
    program : MotionProgram
    tol : float
        A jump counts when |right − left| > tol·ref, ref being the larger of |left|, |right| and
        h/δ0^k for the moving segments meeting there (k = 1 for ds/dδ, 2 for d²s/dδ²), so that
        rounding (sin π ≈ 1e-16) never makes an impact.

    Returns
    -------
    tuple of Impact

    Examples
    --------
    Uniform (等速) rise and return: rigid impacts at both ends of each.

    >>> from graphmech.mechanisms.cam import MotionProgram, Segment
    >>> p = MotionProgram(0.05, (Segment("rise", math.pi / 2, "uniform"), Segment("dwell", math.pi / 2),
    ...                          Segment("return", math.pi / 2, "uniform"), Segment("dwell", math.pi / 2)))
    >>> [(round(i.angle / math.pi, 3), i.kind, round(i.jump, 4)) for i in impacts(p)]
    [(0.0, 'rigid', 0.0318), (0.5, 'rigid', -0.0318), (1.0, 'rigid', -0.0318), (1.5, 'rigid', 0.0318)]

    Parabolic (等加速等减速): soft impacts at the start, the middle and the end of the rise.

    >>> p = MotionProgram(0.05, (Segment("rise", math.pi / 2, "parabolic"), Segment("dwell", math.pi / 2),
    ...                          Segment("return", math.pi / 2, "sine"), Segment("dwell", math.pi / 2)))
    >>> [(round(i.angle / math.pi, 3), i.kind, round(i.jump, 4)) for i in impacts(p)]
    [(0.0, 'soft', 0.0811), (0.25, 'soft', -0.1621), (0.5, 'soft', 0.0811)]
    """
    c = _compile(program)
    n = len(c.kinds)
    h = c.stroke
    found: list[Impact] = []

    def ref_scale(k: int, segs: tuple[int, ...]) -> float:
        return max((h / c.angles[j] ** k for j in segs if c.kinds[j] != "dwell"), default=0.0)

    def check(angle: float, left_seg: int, left_x: float, right_seg: int, right_x: float) -> None:
        xl, xr = np.array([left_x]), np.array([right_x])
        for k, kind in ((1, "rigid"), (2, "soft")):
            left = float(_segment_values(c, left_seg, xl, k, left=True)[0])
            right = float(_segment_values(c, right_seg, xr, k)[0])
            ref = max(abs(left), abs(right), ref_scale(k, (left_seg, right_seg)))
            if abs(right - left) > tol * ref:
                found.append(Impact(float(angle), kind, right - left + 0.0))
                return

    for i in range(n):
        check(float(c.starts[i]), (i - 1) % n, 1.0, i, 0.0)
        for x in _interior_knots(c.laws[i], c.tables[i]):
            check(float(c.starts[i] + x * c.angles[i]), i, float(x), i, float(x))
    return tuple(sorted(found, key=lambda imp: imp.angle))


@dataclass(frozen=True)
class Extremum:
    """The largest magnitude of a follower quantity over a turn of the cam.

    Parameters
    ----------
    value : float
        max |q|, SI: m/s, m/s², m/s³ (rad/s, rad/s², rad/s³ for an oscillating follower).
    at : float
        The first cam angle where it is reached, rad.
    signed : float
        q there, with its sign.
    """

    value: float
    at: float
    signed: float


def _candidates(c: _Compiled, i: int) -> tuple[np.ndarray, np.ndarray]:
    """Fractions x on segment i where |f'|, |f''| or |f'''| can peak, and whether each is a
    left-hand limit (x = 1, or a table's knot approached from the left)."""
    if c.kinds[i] == "dwell":
        return np.array([0.0]), np.array([False])
    if c.laws[i] != "table":
        return np.append(_ANALYTIC_CANDIDATES, 1.0), np.append(np.zeros(len(_ANALYTIC_CANDIDATES), bool), True)
    pp = c.tables[i]
    knots = np.asarray(pp.x, dtype=float)
    # a cubic piece: f'' is linear and f''' constant, so they peak at the knots; f' is quadratic
    # and may also peak at its vertex t = −b/(3a) inside the piece.
    a, b = pp.c[0], pp.c[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(a != 0.0, -b / (3.0 * a), -1.0)
    inside = (t > 0.0) & (t < np.diff(knots))
    vertices = knots[:-1][inside] + t[inside]
    xs = np.concatenate((knots[:-1], vertices, knots[1:]))
    left = np.concatenate((np.zeros(len(knots) - 1 + len(vertices), bool), np.ones(len(knots) - 1, bool)))
    return xs, left


def maxima(program: MotionProgram, omega: float) -> dict[str, Extremum]:
    """The follower's largest velocity, acceleration and jerk at a constant cam speed ω.

    Parameters
    ----------
    program : MotionProgram
    omega : float
        The cam's angular velocity, rad/s (finite; its sign only flips the signs).

    Returns
    -------
    dict
        ``"v"``: v = ω·ds/dδ (m/s), ``"a"``: a = ω²·d²s/dδ² (m/s²), ``"j"``: j = ω³·d³s/dδ³
        (m/s³) — rad/s… for an oscillating follower — each an :class:`Extremum`. ``at`` is the
        first angle where the largest magnitude is reached (the first of equal maxima).

    Notes
    -----
    Exact, not sampled. For the analytic laws every peak of |f′|, |f″|, |f‴| on a segment lies at
    x ∈ {0, ¼, ½, ¾, (3 ∓ √3)/6} or at the end x → 1, so these are evaluated; e.g. the sine law's
    a_max = 2πhω²/δ0² at x = ¼, the cosine law's π²hω²/(2δ0²) at x = 0, the parabolic law's
    4hω²/δ0² on the whole first half (reported at its start), the poly345 law's
    10√3·hω²/(3δ0²) at x = (3 − √3)/6. For a table law the PCHIP interpolant is piecewise cubic,
    so its peaks are found exactly too: at the knots (either side) and at the vertices of f′.
    The value just before a joint (a left-hand limit, a supremum not taken by
    :func:`displacement` there) counts, with the joint's angle as ``at``.

    The uniform law's acceleration is 0 inside the stroke and its impulses at the ends are not
    counted (see :func:`impacts`); likewise the parabolic law's jerk is 0 and that of any
    soft impact is not counted.

    Examples
    --------
    The textbook's sine-acceleration rise, h = 50 mm over δ0 = π/2 at ω = 10 rad/s:

    >>> from graphmech.mechanisms.cam import MotionProgram, Segment
    >>> p = MotionProgram(0.05, (Segment("rise", math.pi / 2, "sine"), Segment("dwell", math.pi / 2),
    ...                          Segment("return", math.pi / 2, "sine"), Segment("dwell", math.pi / 2)))
    >>> m = maxima(p, 10.0)
    >>> round(m["v"].value, 4), round(m["v"].at / math.pi, 4)     # m/s at δ = π/4
    (0.6366, 0.25)
    >>> round(m["a"].value, 3), round(m["a"].at / math.pi, 4)     # m/s² at δ = π/8
    (12.732, 0.125)
    """
    if not _finite_number(omega):
        raise OutOfDomain(f"omega must be a finite number of rad/s, got {omega!r}")
    c = _compile(program)
    result: dict[str, Extremum] = {}
    for k, key in ((1, "v"), (2, "a"), (3, "j")):
        angles, values = [], []
        for i in range(len(c.kinds)):  # a loop over the segments
            xs, left = _candidates(c, i)
            vals = np.where(left, _segment_values(c, i, xs, k, left=True), _segment_values(c, i, xs, k))
            angles.append(c.starts[i] + xs * c.angles[i])
            values.append(vals * float(omega) ** k)
        ang, val = np.concatenate(angles), np.concatenate(values)
        peak = float(np.max(np.abs(val)))
        ties = np.flatnonzero(np.abs(val) >= peak * (1.0 - _TIE_REL))
        first = ties[np.argmin(ang[ties])]
        signed = float(val[first]) + 0.0
        result[key] = Extremum(abs(signed), float(ang[first]), signed)
    return result
