"""Pure construction kernels on plain components.

Every kernel takes an *ops* object first (:class:`ScalarOps` for one position with Python
floats, :class:`ArrayOps` for many positions with numpy arrays) and the values of its inputs:

* a point is ``(x, y)``;
* a line is ``(px, py, dx, dy)``: a point on it and its unit direction;
* a circle is ``(cx, cy, r)``.

The same arithmetic serves both paths. A degenerate case (parallel lines, circles that do not
meet, a direction from two coincident points) goes through ``ops.guard``: the scalar path
raises :class:`~graphmech.errors.DegenerateConstruction` naming the step, the batch path marks
the positions and substitutes a harmless finite value so no NaN is ever produced. Each
intersection reports its *condition number* (≈ 1/sin of the angle at which the two loci meet)
through ``ops.cond`` so callers can warn where the result is ill-conditioned.

>>> ops = ScalarOps()
>>> intersect_lines(ops, (0.0, 0.0, 1.0, 0.0), (2.0, -1.0, 0.0, 1.0))
(2.0, 0.0)
>>> ops.conds["?"]
1.0
"""
from __future__ import annotations

import math
from typing import Any, Callable, Protocol

import numpy as np

from graphmech.errors import AssemblyError, DegenerateConstruction
from graphmech.tolerances import COINCIDENT_REL, PARALLEL_SIN, TANGENT_REL

Reason = str | Callable[[], str]
#: One component: a float on the scalar path, an array (one entry per position) on the batch path.
#: The kernels are written once for both, so a component stays open (Any) to the type checker.
Value = Any
#: A point (x, y), a line (px, py, dx, dy), a circle (cx, cy, r), a direction (ux, uy, length).
Components = tuple[Value, ...]

#: Condition numbers are capped here so that "infinite" stays a finite, printable number.
COND_CAP = 1e300


def _text(reason: Reason) -> str:
    return reason() if callable(reason) else reason


class ScalarOps:
    """Ops for one position: Python floats and ``math``; degeneracy raises."""

    sqrt = staticmethod(math.sqrt)
    cos = staticmethod(math.cos)
    sin = staticmethod(math.sin)
    hypot = staticmethod(math.hypot)
    batch = False

    def __init__(self) -> None:
        self.step = "?"
        self.position: str | None = None
        self.conds: dict[str, Any] = {}

    def guard(self, bad: Any, reason: Reason, assembly: bool = False) -> bool:
        if bad:
            cls = AssemblyError if assembly else DegenerateConstruction
            raise cls(self.step, _text(reason), self.position)
        return False

    @staticmethod
    def where(bad: Any, fallback: Any, value: Any) -> Any:
        return value

    def fix(self, bad: Any, value: Any, fallback: Any, reason: Reason, assembly: bool = False) -> Any:
        """``value``, or raise where ``bad`` (the batch twin substitutes ``fallback`` and marks)."""
        if bad:
            self.guard(True, reason, assembly)
        return value

    @staticmethod
    def maximum(a: Any, b: Any) -> Any:
        return a if a > b else b

    @staticmethod
    def absolute(a: Any) -> Any:
        return abs(a)

    def cond(self, c: Any) -> None:
        self.conds[self.step] = c if c < COND_CAP else COND_CAP


class ArrayOps:
    """Ops for many positions at once: numpy arrays; degeneracy marks positions."""

    sqrt = staticmethod(np.sqrt)
    cos = staticmethod(np.cos)
    sin = staticmethod(np.sin)
    hypot = staticmethod(np.hypot)
    where = staticmethod(np.where)
    maximum = staticmethod(np.maximum)
    absolute = staticmethod(np.abs)
    batch = True

    def __init__(self, n: int) -> None:
        self.n = n
        self.step = "?"
        self.conds: dict[str, Any] = {}
        self.bad = np.zeros(n, dtype=bool)
        self.failures: dict[str, tuple[np.ndarray, str]] = {}

    def guard(self, bad: Any, reason: Reason, assembly: bool = False) -> Any:
        if not np.count_nonzero(bad):  # the usual case, kept cheap (np.any costs ten times as much)
            return bad
        bad = np.broadcast_to(np.asarray(bad, dtype=bool), (self.n,))
        if bad.any():
            # Only the first step that fails at a position is that position's reason.
            new = bad & ~self.bad
            if new.any():
                text = _text(reason)
                self.failures[self.step] = (new.copy(), f"cannot be assembled: {text}" if assembly else text)
            self.bad = self.bad | bad
        return bad

    def fix(self, bad: Any, value: Any, fallback: Any, reason: Reason, assembly: bool = False) -> Any:
        if not np.count_nonzero(bad):
            return value
        return np.where(self.guard(bad, reason, assembly), fallback, value)

    def cond(self, c: Any) -> None:
        self.conds[self.step] = c  # capped (and broadcast) when read: BatchSolution.conds


class Ops(Protocol):
    """What a kernel asks of its ops: :class:`ScalarOps` or :class:`ArrayOps`."""

    batch: bool
    step: str
    conds: dict[str, Any]

    def sqrt(self, x: Value, /) -> Value: ...
    def cos(self, x: Value, /) -> Value: ...
    def sin(self, x: Value, /) -> Value: ...
    def hypot(self, x: Value, y: Value, /) -> Value: ...
    def where(self, bad: Value, fallback: Value, value: Value, /) -> Value: ...
    def maximum(self, a: Value, b: Value, /) -> Value: ...
    def absolute(self, a: Value, /) -> Value: ...
    def guard(self, bad: Value, reason: Reason, assembly: bool = False) -> Value: ...
    def fix(self, bad: Value, value: Value, fallback: Value, reason: Reason, assembly: bool = False) -> Value: ...
    def cond(self, c: Value) -> None: ...

# --------------------------------------------------------------------------- directions


def coincident(ops: Ops, n: Any, ax: Any, ay: Any, bx: Any, by: Any) -> Any:
    """Whether two points a distance n apart are the same point, to rounding.

    Relative to the points' own coordinates: 1e-14 mm apart at 100 mm from the origin is
    rounding, not a direction, and a line drawn through such a pair points anywhere.
    """
    size = ops.absolute(ax) + ops.absolute(ay) + ops.absolute(bx) + ops.absolute(by)
    return n <= COINCIDENT_REL * size


def unit(ops: Ops, a: Components, b: Components) -> Components:
    """The direction a→b as ``(ux, uy, length)`` — a set square laid along AB, used by every
    line drawn ⟂ or ∥ to it and by every reading of ω or α along it."""
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    n = ops.hypot(dx, dy)
    n = ops.fix(coincident(ops, n, a[0], a[1], b[0], b[1]), n, 1.0,
                "the two points coincide: the line has no direction")
    return (dx / n, dy / n, n)


def line_perpendicular_to(ops: Ops, through: Components, u: Components) -> Components:
    """The line through ``through`` perpendicular to the direction ``u`` (from :func:`unit`)."""
    return (through[0], through[1], -u[1], u[0])


def line_parallel_to(ops: Ops, through: Components, u: Components) -> Components:
    """The line through ``through`` parallel to the direction ``u`` (from :func:`unit`)."""
    return (through[0], through[1], u[0], u[1])


def line_fixed(ops: Ops, through: Components, dx: float, dy: float) -> Components:
    """The line through ``through`` along the fixed unit direction (dx, dy) ("∥ the guide")."""
    return (through[0], through[1], dx + 0.0 * through[0], dy + 0.0 * through[0])


# --------------------------------------------------------------------------- intersections


def intersect_lines(ops: Ops, l1: Components, l2: Components) -> Components:
    """Intersection of two lines; condition number 1/|sin θ| (θ the angle between them).

    Notes
    -----
    With unit directions d, e and ``det = d × e = sin θ``, the point is ``P + t·d`` where
    ``t = ((Q − P) × e) / det``. A perturbation δ of either line moves the point by about
    δ/|sin θ|, hence the condition number.
    """
    px, py, dx, dy = l1
    qx, qy, ex, ey = l2
    det = dx * ey - dy * ex
    det = ops.fix(ops.absolute(det) < PARALLEL_SIN, det, 1.0, "the two lines are parallel: no intersection")
    adet = ops.absolute(det)
    ops.cond(1.0 / adet)
    t = ((qx - px) * ey - (qy - py) * ex) / det
    return (px + t * dx, py + t * dy)


def intersect_circles(
    ops: Ops, c1: Components, r1: Any, c2: Components, r2: Any, side: float, explain: Callable[[Any], str]
) -> Components:
    """Intersection of circles (c1, r1) and (c2, r2) on the given side of c1→c2 (+1 left, −1 right).

    Two circles that just touch (within a relative ``TANGENT_REL``) meet at their tangent
    point, with an infinite condition number; circles further apart fail with the message
    ``explain(d)`` (the caller words it in the mechanism's terms).

    Notes
    -----
    With d = |c1c2|, the foot of the common chord lies a = (r1² − r2² + d²)/(2d) from c1 and
    the half chord is h = √(r1² − a²). The angle γ between the two radii at the point has
    sin γ = d·h/(r1·r2); its reciprocal is the condition number.
    """
    x1, y1 = c1
    x2, y2 = c2
    dx = x2 - x1
    dy = y2 - y1
    d = ops.hypot(dx, dy)
    bad_d = ops.guard(coincident(ops, d, x1, y1, x2, y2), "the two centres coincide", assembly=True)
    d = ops.where(bad_d, 1.0, d)
    a = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d)
    h2 = r1 * r1 - a * a
    slack = TANGENT_REL * r1 * r1
    bad = ops.guard(h2 < -slack, lambda: explain(d), assembly=True)
    h2 = ops.maximum(ops.where(bad, 0.0, h2), 0.0)
    h = ops.sqrt(h2)
    ops.cond(r1 * r2 / ops.maximum(d * h, 1e-300 * r1 * r2))
    ux = dx / d
    uy = dy / d
    return (x1 + a * ux - side * h * uy, y1 + a * uy + side * h * ux)


def intersect_circle_line(
    ops: Ops, c: Components, r: Any, line: Components, side: float, explain: Callable[[Any], str]
) -> Components:
    """Intersection of circle (c, r) and a line, ahead (+1) or behind (−1) the foot of c.

    Notes
    -----
    The foot F of the perpendicular from c has offset e = (c − P) × d from the line; the
    point is F ± √(r² − e²)·d. The circle's radius meets the line at angle γ with
    sin γ = √(r² − e²)/r, whose reciprocal is the condition number.
    """
    px, py, dx, dy = line
    cx, cy = c
    t = (cx - px) * dx + (cy - py) * dy
    e = (cx - px) * dy - (cy - py) * dx
    h2 = r * r - e * e
    bad = ops.guard(h2 < -TANGENT_REL * r * r, lambda: explain(ops.absolute(e)), assembly=True)
    h = ops.sqrt(ops.maximum(ops.where(bad, 0.0, h2), 0.0))
    ops.cond(r / ops.maximum(h, 1e-300 * r))
    s = t + side * h
    return (px + s * dx, py + s * dy)


# --------------------------------------------------------------------------- laying off


def similar_point(ops: Ops, U: Components, V: Components, E: Components, u: Components, v: Components) -> Components:
    """Image e of E such that triangle u v e is similar to U V E, same letter order.

    Notes
    -----
    In complex numbers e = u + (v − u)·(E − U)/(V − U): the image figure is the original
    turned and scaled by the ratio (v − u)/(V − U) — the velocity (acceleration) image.
    """
    Dx = V[0] - U[0]
    Dy = V[1] - U[1]
    n2 = Dx * Dx + Dy * Dy
    bad = ops.guard(coincident(ops, ops.sqrt(n2), U[0], U[1], V[0], V[1]), "the two base points coincide")
    n2 = ops.where(bad, 1.0, n2)
    Ex = E[0] - U[0]
    Ey = E[1] - U[1]
    # ratio (E − U)/(V − U) as a complex number
    rx = (Ex * Dx + Ey * Dy) / n2
    ry = (Ey * Dx - Ex * Dy) / n2
    wx = v[0] - u[0]
    wy = v[1] - u[1]
    return (u[0] + wx * rx - wy * ry, u[1] + wx * ry + wy * rx)


def cross(ax: Any, ay: Any, bx: Any, by: Any) -> Any:
    """z-component of a × b."""
    return ax * by - ay * bx
