"""A four-bar function generator by Freudenstein's equation, precision points Chebyshev-spaced.

The book's method: the function ``y = f(x)`` over ``[x₀, x₁]`` is mapped linearly to the input
crank's swing (``φ = φ₀ + Δφ·(x − x₀)/(x₁ − x₀)``) and to the output rocker's swing
(``ψ = ψ₀ + Δψ·(y − y₀)/(y₁ − y₀)``, ``y₀ = f(x₀)``, ``y₁ = f(x₁)``). At the precision points
``x_k = (x₀ + x₁)/2 − (x₁ − x₀)/2·cos((2k − 1)π/(2n))``, k = 1 … n (Chebyshev's spacing), the
four-bar must give exactly the output ψ_k for the input φ_k. Freudenstein's equation of the loop,

    R₁·cos φ − R₂·cos ψ + R₃ = cos(φ − ψ),   R₁ = d/c,  R₂ = d/a,  R₃ = (a² − b² + c² + d²)/(2ac),

is linear in R₁, R₂, R₃: three points give a 3×3 linear system; more points are met in the least-
squares sense (the equation's residuals are then not zero: said in :attr:`Design.method`); two
points leave one R free and the minimum-norm solution is taken (said). The frame d is stated and
``c = d/R₁``, ``a = d/R₂``, ``b² = a² + c² + d² − 2ac·R₃``.

Convention (the one in which the equation above holds): the input pivot A at the origin, the output
pivot D at ``(−d, 0)``; φ is the angle of AB and ψ that of DC, both counter-clockwise from the
direction D → A. A negative ``a`` (or ``c``) is a link of length ``|a|`` pointing the other way:
AB at ``φ + 180°`` (:attr:`Design.input_reversed`), likewise DC.

The functions a scene can name are a fixed table (:data:`FUNCTIONS`); no text is evaluated. The
angles of sin, cos and tan are in radians.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from graphmech.errors import OutOfDomain

__all__ = ["FUNCTIONS", "Design", "Function", "chebyshev_points", "design", "named_function",
           "uniform_points"]

_Fn = Callable[[np.ndarray], np.ndarray]

#: Condition number of the precision points' equations above which they count as dependent.
_MAX_CONDITION = 1e8

#: The numbers of precision points offered.
POINTS = (2, 3, 4, 5)


@dataclass(frozen=True)
class Function:
    """A function ``y = f(x)`` the generator is asked to produce, with its domain check.

    ``refuse(x0, x1)`` returns why the interval is outside the domain ("" when inside).
    """

    name: str
    f: _Fn
    refuse: Callable[[float, float], str] = field(default=lambda x0, x1: "")  # no domain limit

    def __call__(self, x: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):  # an overflow is refused by the callers (not finite)
            return np.asarray(self.f(np.asarray(x, dtype=float)), dtype=float)


def _positive(what: str) -> Callable[[float, float], str]:
    return lambda x0, x1: "" if min(x0, x1) > 0.0 else f"{what} needs x > 0 over the range"


def _not_negative(what: str) -> Callable[[float, float], str]:
    return lambda x0, x1: "" if min(x0, x1) >= 0.0 else f"{what} needs x ≥ 0 over the range"


def _no_zero(what: str) -> Callable[[float, float], str]:
    return lambda x0, x1: ("" if min(x0, x1) > 0.0 or max(x0, x1) < 0.0
                           else f"{what} is undefined at x = 0, inside the range")


def _tan_domain(x0: float, x1: float) -> str:
    # a pole π/2 + kπ in [x0, x1]: the first pole at or above min(x0, x1)
    lo, hi = min(x0, x1), max(x0, x1)
    k = math.ceil((lo - math.pi / 2) / math.pi)
    pole = math.pi / 2 + k * math.pi
    return "" if pole > hi else f"tan has a pole at x = {pole:.6g} rad, inside the range"


FUNCTIONS: dict[str, Function] = {
    "log10": Function("log10", np.log10, _positive("log10")),
    "ln": Function("ln", np.log, _positive("ln")),
    "exp": Function("exp", np.exp),
    "sqrt": Function("sqrt", np.sqrt, _not_negative("sqrt")),
    "square": Function("square", np.square),
    "cube": Function("cube", lambda x: x ** 3),
    "reciprocal": Function("reciprocal", np.reciprocal, _no_zero("reciprocal 1/x")),
    "sin": Function("sin", np.sin),
    "cos": Function("cos", np.cos),
    "tan": Function("tan", np.tan, _tan_domain),
}
"""The functions a scene can name (plus ``power`` with its exponent: :func:`named_function`)."""


def named_function(name: str, exponent: float | None = None) -> Function:
    """The table's function ``name``; ``"power"`` takes ``exponent`` (``y = x**exponent``).

    >>> named_function("power", 0.5).name
    'power 0.5'
    """
    if name == "power":
        if exponent is None or not math.isfinite(exponent):
            raise OutOfDomain("power needs a finite exponent")
        p = float(exponent)
        if p == int(p):
            refuse = _no_zero(f"x**{p:g}") if p < 0 else (lambda x0, x1: "")
        else:
            refuse = _positive(f"x**{p:g}") if p < 0 else _not_negative(f"x**{p:g}")
        return Function(f"power {p:g}", lambda x: np.power(x, p), refuse)
    if exponent is not None:
        raise OutOfDomain(f"{name} takes no exponent (only power does)")
    try:
        return FUNCTIONS[name]
    except KeyError:
        raise OutOfDomain(f"no function {name!r}: one of {', '.join([*FUNCTIONS, 'power'])}") from None


def chebyshev_points(x0: float, x1: float, n: int = 3) -> np.ndarray:
    """Chebyshev's precision points ``x_k = (x₀+x₁)/2 − (x₁−x₀)/2·cos((2k−1)π/(2n))``, k = 1 … n.

    >>> [round(float(x), 4) for x in chebyshev_points(1.0, 2.0)]
    [1.067, 1.5, 1.933]
    """
    k = np.arange(1, n + 1)
    return (x0 + x1) / 2 - (x1 - x0) / 2 * np.cos((2 * k - 1) * np.pi / (2 * n))


def uniform_points(x0: float, x1: float, n: int = 3) -> np.ndarray:
    """Equally spaced precision points, the ends included (the comparison for Chebyshev's)."""
    return np.linspace(x0, x1, n)


@dataclass(frozen=True)
class Design:
    """A function generator designed by Freudenstein's equation (lengths in the frame's unit).

    ``x``, ``phi``, ``psi``: the precision points (x, and the input and output angles there, rad).
    ``R``: (R₁, R₂, R₃). ``a, b, c, d``: the crank AB, coupler BC, rocker DC and frame AD, all > 0;
    ``input_reversed`` / ``output_reversed``: AB at φ + π (DC at ψ + π), from a negative R₂ (R₁).
    ``residuals``: Freudenstein's equation at each precision point (0 to rounding for n ≤ 3).
    """

    function: Function
    x0: float
    x1: float
    phi0: float
    dphi: float
    psi0: float
    dpsi: float
    spacing: str
    x: np.ndarray
    phi: np.ndarray
    psi: np.ndarray
    R: tuple[float, float, float]
    a: float
    b: float
    c: float
    d: float
    input_reversed: bool
    output_reversed: bool
    residuals: np.ndarray
    condition: float
    method: str

    @property
    def n(self) -> int:
        return int(self.x.size)

    def phi_of(self, x: np.ndarray) -> np.ndarray:
        """The input angle for ``x`` (the linear map)."""
        return self.phi0 + self.dphi * (np.asarray(x, dtype=float) - self.x0) / (self.x1 - self.x0)

    def psi_of(self, x: np.ndarray) -> np.ndarray:
        """The desired output angle for ``x``: ``ψ₀ + Δψ·(f(x) − y₀)/(y₁ − y₀)``."""
        y0, y1 = self.function(np.array([self.x0, self.x1]))
        y = self.function(np.asarray(x, dtype=float))
        return np.asarray(self.psi0 + self.dpsi * (y - y0) / (y1 - y0), dtype=float)

    def precision_positions(self) -> dict[str, np.ndarray]:
        """Joints at the precision points as complex numbers: A, D (scalars), B_k, C_k (arrays).

        Every ``|B_k C_k|`` is b for n ≤ 3 (the equation holds there).
        """
        sa = -1.0 if self.input_reversed else 1.0
        sc = -1.0 if self.output_reversed else 1.0
        a_pt, d_pt = np.array(0j), np.array(complex(-self.d, 0.0))
        return {"A": a_pt, "D": d_pt, "B": sa * self.a * np.exp(1j * self.phi),
                "C": d_pt + sc * self.c * np.exp(1j * self.psi)}


def _finite(**values: float) -> None:
    for name, v in values.items():
        if not math.isfinite(v):
            raise OutOfDomain(f"{name} = {v} is not finite")


def design(function: Function, x0: float, x1: float, phi0: float, dphi: float, psi0: float,
           dpsi: float, d: float = 1.0, n: int = 3,
           spacing: Literal["chebyshev", "uniform"] = "chebyshev",
           points: np.ndarray | None = None) -> Design:
    """The four-bar that generates ``function`` over ``[x0, x1]`` (angles in radians).

    ``points`` (optional) gives the precision points' x instead of ``spacing`` (its length is n).

    Raises
    ------
    OutOfDomain
        In words: x₀ = x₁, Δφ = 0, Δψ = 0, d ≤ 0, n outside 2 … 5, the interval outside the
        function's domain, f(x₀) = f(x₁) (no linear map to ψ), precision points outside the range
        or coincident / the equations nearly dependent (e.g. Δφ tiny), R₁ or R₂ = 0 (a link of
        infinite length), b² ≤ 0 (no real coupler).
    """
    _finite(x0=x0, x1=x1, phi0=phi0, dphi=dphi, psi0=psi0, dpsi=dpsi, d=d)
    if x0 == x1:
        raise OutOfDomain("x₀ = x₁: the range of x is empty")
    if dphi == 0.0:
        raise OutOfDomain("Δφ = 0: the input crank does not turn")
    if dpsi == 0.0:
        raise OutOfDomain("Δψ = 0: the output link does not turn, no function is generated")
    if d <= 0.0:
        raise OutOfDomain(f"the frame d = {d} must be > 0")
    why = function.refuse(x0, x1)
    if why:
        raise OutOfDomain(f"{function.name} over [{x0:g}, {x1:g}]: {why}")
    label: str = spacing
    if points is None:
        if n not in POINTS:
            raise OutOfDomain(f"n = {n} precision points: 2 … 5 are offered")
        if spacing == "chebyshev":
            xs = chebyshev_points(x0, x1, n)
        elif spacing == "uniform":
            xs = uniform_points(x0, x1, n)
        else:
            raise OutOfDomain(f"spacing {spacing!r}: 'chebyshev' or 'uniform'")
    else:
        xs = np.asarray(points, dtype=float).ravel()
        label = "given"
        if xs.size not in POINTS:
            raise OutOfDomain(f"{xs.size} precision points: 2 … 5 are offered")
        lo, hi = min(x0, x1), max(x0, x1)
        if not (np.all(np.isfinite(xs)) and np.all((xs >= lo) & (xs <= hi))):
            raise OutOfDomain(f"the precision points must lie in [{lo:g}, {hi:g}]")
        if np.unique(xs).size < xs.size:
            raise OutOfDomain("two precision points coincide: their equations are the same")
    y_ends = function(np.array([x0, x1]))
    if not np.all(np.isfinite(y_ends)):
        raise OutOfDomain(f"{function.name} is not finite at the ends of [{x0:g}, {x1:g}]")
    if y_ends[0] == y_ends[1]:
        raise OutOfDomain(f"f(x₀) = f(x₁) = {y_ends[0]:g}: the output swing cannot be mapped to y")
    phi = phi0 + dphi * (xs - x0) / (x1 - x0)
    ys = function(xs)
    if not np.all(np.isfinite(ys)):
        raise OutOfDomain(f"{function.name} is not finite at a precision point")
    psi = psi0 + dpsi * (ys - y_ends[0]) / (y_ends[1] - y_ends[0])

    # R₁·cos φ − R₂·cos ψ + R₃ = cos(φ − ψ): one row per precision point
    m = np.column_stack([np.cos(phi), -np.cos(psi), np.ones_like(phi)])
    rhs = np.cos(phi - psi)
    sv = np.linalg.svd(m, compute_uv=False)
    rank_need = min(xs.size, 3)
    cond = float(sv[0] / sv[rank_need - 1]) if sv[rank_need - 1] > 0.0 else math.inf
    if cond > _MAX_CONDITION:
        raise OutOfDomain(f"the precision points' equations are (nearly) dependent (condition number "
                          f"{cond:.3g}): the points too close together (Δφ or Δψ too small, or coincident)")
    if xs.size == 3:
        r = np.linalg.solve(m, rhs)
        method = "3 precision points: Freudenstein's equation solved exactly (3×3)"
    elif xs.size == 2:
        r = np.linalg.lstsq(m, rhs, rcond=None)[0]
        method = "2 precision points: one R free, the minimum-norm solution taken"
    else:
        r = np.linalg.lstsq(m, rhs, rcond=None)[0]
        method = f"{xs.size} precision points: Freudenstein's equation met in least squares (not exactly)"
    r1, r2, r3 = (float(v) for v in r)
    if abs(r1) < 1e-12 or abs(r2) < 1e-12:
        which = "R₁ = d/c" if abs(r1) < 1e-12 else "R₂ = d/a"
        raise OutOfDomain(f"{which} = 0: that link would be infinitely long")
    a_s, c_s = d / r2, d / r1
    b2 = a_s * a_s + c_s * c_s + d * d - 2.0 * a_s * c_s * r3
    if not b2 > 0.0:
        raise OutOfDomain(f"no real coupler: b² = a² + c² + d² − 2ac·R₃ = {b2:.6g} ≤ 0")
    return Design(function, float(x0), float(x1), float(phi0), float(dphi), float(psi0), float(dpsi),
                  label, xs, phi, psi, (r1, r2, r3), abs(a_s), math.sqrt(b2), abs(c_s), float(d),
                  a_s < 0.0, c_s < 0.0, m @ r - rhs, cond, method)
