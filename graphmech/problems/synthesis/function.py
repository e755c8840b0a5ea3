"""The synthesis task ``function``: a four-bar function generator by Freudenstein's equation.

Read: ``function`` (the table's name, ``exponent`` with ``"power"``), ``x_range``, ``phi_start``,
``phi_range``, ``psi_start``, ``psi_range``, ``points`` (2 … 5), ``spacing`` and ``frame`` (l_AD).
Analysed: the design (:func:`graphmech.methods.freudenstein.design`) drawn at μl at its first
precision position, its lengths measured against Freudenstein's system solved again in exact
rational arithmetic (:func:`exact_lengths`); the drawn and the exact linkage re-analysed by
:mod:`graphmech.exact.freudenstein` (the dyad by the law of cosines): the precision positions
reached, the structural error read off the sampled curve the figure draws (its own estimate from
twice the samples) against the located extreme, γ_min over the working range, Grashof's class and
a reversed link said under the table. Near-dependent precision points are warned of.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import numpy as np

from graphmech.errors import GraphmechError, SceneError
from graphmech.problems.reader import MISSING
from graphmech.problems.synthesis.common import read_length, unit
from graphmech.tolerances import EPS

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Panel, Primitive
    from graphmech.exact.freudenstein import FourBar, StructuralError
    from graphmech.methods.freudenstein import Design, Function
    from graphmech.problems.judging import Row
    from graphmech.problems.reader import Reader

#: The spacings of the precision points.
SPACINGS = ("chebyshev", "uniform")
#: Condition number of Freudenstein's system above which the points count as nearly dependent
#: (warned of, rows flagged); the method refuses above 1e8.
ILL_CONDITION = 1e3
#: Samples of the structural-error curve the figure draws and the check reads (200 intervals);
#: its own error estimate reads the curve again at twice the intervals.
CURVE_SAMPLES = 201
#: The round-off of an angle found from the drawn lengths (ψ by the law of cosines, γ by acos), rad:
#: the floor of the sampled rows' estimates (≈ 100 ε).
ANGLE_ROUND_OFF = 100.0 * EPS
#: The largest |x| and the narrowest range (relative to |x|) a scene takes: beyond them the map of
#: x on φ and of y on ψ loses the digits the precision points need.
MAX_X, NARROW = 1e6, 1e-9
#: The error plot's x axis and its largest ordinate, mm.
PLOT_WIDTH, PLOT_HEIGHT = 100.0, 40.0
#: The task's rows, with their units.
NAMES = {"lAB": "m", "lBC": "m", "lCD": "m", "lAD": "m", "reanalysis_error": "", "structural_error_max": "deg",
         "x_error_max": "", "gamma_min_range": "deg"}


@dataclass(frozen=True)
class FunctionProblem:
    """y = f(x) over [x0, x1] on the crank's swing φ0 … φ0 + Δφ and the rocker's ψ0 … ψ0 + Δψ
    (rad), ``points`` precision points ``spacing``-spaced, the frame l_AD (m)."""

    function: str
    exponent: float | None
    x0: float
    x1: float
    phi0: float
    dphi: float
    psi0: float
    dpsi: float
    points: int
    spacing: str
    frame: float
    key: str

    def f(self) -> Function:
        from graphmech.methods.freudenstein import named_function

        return named_function(self.function, self.exponent)


def _angle(r: Reader, base: str, nonzero: bool) -> float | None:
    v = r.scalar(base, "angle")
    if v is None:
        return None
    key = r.at(r.present(base) or base)
    if nonzero and v == 0.0:
        what = "Δφ = 0: the input crank does not turn" if base == "phi_range" else \
            "Δψ = 0: the output link does not turn, no function is generated"
        r.problem(key, what)
        return None
    if nonzero and abs(v) > 2.0 * math.pi:
        r.problem(key, "more than a turn: the precision positions would repeat")
        return None
    return v


def read_function(r: Reader) -> FunctionProblem | None:
    """The rest of [synthesis] for ``task = "function"`` (None after reporting)."""
    from graphmech.methods.freudenstein import FUNCTIONS, POINTS, named_function

    name = r.string("function", choices=(*FUNCTIONS, "power"), required=True)
    exp_raw = r.raw("exponent")
    exponent = None if exp_raw is MISSING else r.number(exp_raw, r.at("exponent"))
    if name is not None and name != "power" and exp_raw is not MISSING:
        r.problem(r.at("exponent"), f"{name} takes no exponent (only function = \"power\" does)")
        name = None
    elif name == "power" and exp_raw is MISSING:
        r.problem(r.at("exponent"), "missing: function = \"power\" needs exponent (y = x**exponent)")
        name = None
    elif name == "power" and exponent is None:
        name = None
    xr = r.raw("x_range", required=True, hint="x_range = [x0, x1], the range of x")
    xs = None if xr is MISSING else r.numbers(xr, r.at("x_range"), 2, shape="[x0, x1]")
    if xs is not None and xs[0] == xs[1]:
        r.problem(r.at("x_range"), f"x₀ = x₁ = {xs[0]:g}: the range of x is empty")
        xs = None
    elif xs is not None and max(abs(xs[0]), abs(xs[1])) > MAX_X:
        r.problem(r.at("x_range"), f"|x| up to {max(abs(xs[0]), abs(xs[1])):g}: beyond {MAX_X:g} (scale x first)")
        xs = None
    elif xs is not None and abs(xs[1] - xs[0]) < NARROW * max(abs(xs[0]), abs(xs[1])):
        r.problem(r.at("x_range"), f"[{xs[0]:.17g}, {xs[1]:.17g}] is too narrow for double precision: "
                                   f"x₁ − x₀ under {NARROW:g} of |x|")
        xs = None
    if xs is not None and name is not None:
        fn = named_function(name, exponent)
        why = fn.refuse(xs[0], xs[1])
        ends = fn(np.array(xs))
        if why:
            r.problem(r.at("x_range"), f"{fn.name} over [{xs[0]:g}, {xs[1]:g}]: {why}")
            xs = None
        elif not np.all(np.isfinite(ends)):
            r.problem(r.at("x_range"), f"{fn.name} is not finite at the ends of [{xs[0]:g}, {xs[1]:g}]")
            xs = None
        elif ends[0] == ends[1]:
            r.problem(r.at("x_range"), f"f(x₀) = f(x₁) = {ends[0]:g}: the output's swing cannot be laid on y")
            xs = None
    phi0, dphi = _angle(r, "phi_start", False), _angle(r, "phi_range", True)
    psi0, dpsi = _angle(r, "psi_start", False), _angle(r, "psi_range", True)
    n_raw = r.raw("points")
    n: int | None = 3
    if n_raw is not MISSING:
        if isinstance(n_raw, bool) or not isinstance(n_raw, int):
            r.problem(r.at("points"), f"must be a whole number of precision points (2 … 5), not {n_raw!r}")
            n = None
        elif n_raw not in POINTS:
            r.problem(r.at("points"), f"{n_raw} precision points: 2 … 5 are offered")
            n = None
        else:
            n = n_raw
    spacing = r.string("spacing", choices=SPACINGS, default="chebyshev")
    frame = read_length(r, "frame")  # within the positions task's bounds: double precision
    if (name is None or xs is None or phi0 is None or dphi is None or psi0 is None or dpsi is None or n is None
            or spacing is None or frame is None):
        return None
    return FunctionProblem(name, exponent, xs[0], xs[1], phi0, dphi, psi0, dpsi, n, spacing, frame,
                           r.at(r.present("psi_range") or "psi_range"))


def _design(p: FunctionProblem) -> Design:
    from graphmech.methods.freudenstein import design

    return design(p.f(), p.x0, p.x1, p.phi0, p.dphi, p.psi0, p.dpsi, p.frame, p.points,
                  "uniform" if p.spacing == "uniform" else "chebyshev")


def size(p: FunctionProblem) -> float:
    """The drawing's spread, m: the pivots and the joints at the precision positions (the frame
    alone where no design exists: the analysis says why)."""
    try:
        q = _design(p).precision_positions()
    except GraphmechError:
        return p.frame
    pts = np.concatenate([np.atleast_1d(q["A"]), np.atleast_1d(q["D"]), q["B"], q["C"]])
    return float(max(np.ptp(pts.real), np.ptp(pts.imag)))


def choose_scale(p: FunctionProblem) -> float:
    """μl that draws the linkage about 100 mm across."""
    from graphmech.scales import round_scale

    return round_scale(size(p) / 100.0)


# ----------------------------------------------------------------------------- the exact side
def _solve(m: list[list[Fraction]], rhs: list[Fraction]) -> list[Fraction]:
    """Gaussian elimination in rational arithmetic (no round-off); a singular system raises."""
    n = len(rhs)
    a = [row[:] + [v] for row, v in zip(m, rhs)]
    for col in range(n):
        piv = next((i for i in range(col, n) if a[i][col] != 0), None)
        if piv is None:
            raise GraphmechError("Freudenstein's equations at the precision points are dependent")
        a[col], a[piv] = a[piv], a[col]
        for i in range(n):
            if i != col and a[i][col] != 0:
                k = a[i][col] / a[col][col]
                a[i] = [x - k * y for x, y in zip(a[i], a[col])]
    return [a[i][n] / a[i][i] for i in range(n)]


def exact_R(phi: np.ndarray, psi: np.ndarray) -> tuple[Fraction, Fraction, Fraction]:
    """R₁, R₂, R₃ from the precision angles, solved exactly from their cosines (as floats): three
    points the 3×3 itself, two the minimum-norm solution Mᵀ(MMᵀ)⁻¹r, more the normal equations."""
    m = [[Fraction(math.cos(f)), Fraction(-math.cos(s)), Fraction(1)] for f, s in zip(phi, psi)]
    rhs = [Fraction(math.cos(f - s)) for f, s in zip(phi, psi)]
    if len(m) == 3:
        r = _solve(m, rhs)
    elif len(m) == 2:
        mmt = [[sum((x * y for x, y in zip(ri, rj)), Fraction(0)) for rj in m] for ri in m]
        w = _solve(mmt, rhs)
        r = [sum((m[i][j] * w[i] for i in range(2)), Fraction(0)) for j in range(3)]
    else:
        mtm = [[sum((row[i] * row[j] for row in m), Fraction(0)) for j in range(3)] for i in range(3)]
        mtr = [sum((row[i] * v for row, v in zip(m, rhs)), Fraction(0)) for i in range(3)]
        r = _solve(mtm, mtr)
    return r[0], r[1], r[2]


def exact_lengths(phi: np.ndarray, psi: np.ndarray, d: float) -> dict[str, float]:
    """a, b, c, d (m) of the exact solution: c = d/R₁, a = d/R₂ (their signs kept as ``sa``,
    ``sc``), b² = a² + c² + d² − 2ac·R₃ — all rational until b's square root."""
    return lengths_from_R(*exact_R(phi, psi), d)


def lengths_from_R(r1: Fraction, r2: Fraction, r3: Fraction, d: float) -> dict[str, float]:
    """The lengths from R₁, R₂, R₃ and the frame d (rational until b's square root)."""
    if r1 == 0 or r2 == 0:
        raise GraphmechError("R₁ or R₂ = 0: a link would be infinitely long")
    dd = Fraction(d)
    a, c = dd / r2, dd / r1
    b2 = a * a + c * c + dd * dd - 2 * a * c * r3
    if b2 <= 0:
        raise GraphmechError(f"no real coupler: b² = a² + c² + d² − 2ac·R₃ = {float(b2):.6g} ≤ 0")
    return {"a": float(abs(a)), "b": math.sqrt(b2), "c": float(abs(c)), "d": d,
            "sa": -1.0 if a < 0 else 1.0, "sc": -1.0 if c < 0 else 1.0}


def gamma_min_range(bar: FourBar, phi0: float, dphi: float) -> float:
    """The smallest transmission angle over φ0 … φ0 + Δφ in closed form (rad): γ is least where
    BD is longest or shortest (|cos∠BCD| = |b² + c² − BD²|/(2bc) is linear in BD²), and BD² =
    a² + d² + 2ad·cos θ (θ the direction of AB) is extreme at the range's ends or at θ = kπ."""
    off = math.pi if bar.input_reversed else 0.0
    lo, hi = sorted((phi0 + off, phi0 + dphi + off))
    cands = [lo, hi] + [k * math.pi for k in range(math.ceil(lo / math.pi), math.floor(hi / math.pi) + 1)]
    worst = 0.0
    for t in cands:
        bd2 = bar.a ** 2 + bar.d ** 2 + 2.0 * bar.a * bar.d * math.cos(t)
        worst = max(worst, min(1.0, abs(bar.b ** 2 + bar.c ** 2 - bd2) / (2.0 * bar.b * bar.c)))
    return math.acos(worst)


def _sampled_gamma(bar: FourBar, phi: np.ndarray, branch: str) -> np.ndarray:
    """γ at the sampled positions (rad): ∠BCD of each, taken ≤ 90°."""
    from graphmech.exact.freudenstein import output_angle

    psi, _ = output_angle(bar, phi, branch)
    B = (-1.0 if bar.input_reversed else 1.0) * bar.a * np.exp(1j * phi)
    C = -bar.d + (-1.0 if bar.output_reversed else 1.0) * bar.c * np.exp(1j * psi)
    cosd = np.real((B - C) * np.conj(-bar.d - C)) / (bar.b * bar.c)
    return np.asarray(np.arccos(np.minimum(1.0, np.abs(cosd))), dtype=float)


def _missed(v: np.ndarray, k: int) -> float:
    """What samples can miss of a smooth extreme found at sample ``k``: the true one lies within half
    a step, where the parabola through the three samples rises by at most |v[k+1] − 2v[k] + v[k−1]|/8
    (h²|v″|/8); nothing at an end sample (the end is sampled)."""
    return abs(float(v[k + 1] - 2.0 * v[k] + v[k - 1])) / 8.0 if 0 < k < v.size - 1 else 0.0


# ----------------------------------------------------------------------------- the analysis
@dataclass
class FunctionFound:
    """The design, its drawing at μl (mm: A, D, B_k, C_k), the drawn and the exact re-analyses,
    the rows, the warnings and what ``check --json`` adds."""

    problem: FunctionProblem
    design: Design
    exact: dict[str, float]
    mm: dict[str, Any]
    drawn_mm: dict[str, float]
    drawn_bar: FourBar
    drawn_re: StructuralError
    exact_re: StructuralError
    curve_max: tuple[float, float]  # the sampled curve's largest |Δψ| (rad) and its x
    rows: list[Row]
    warnings: list[str]
    solutions: list[dict[str, Any]]
    names: list[str]

    def x_of(self, phi: np.ndarray) -> np.ndarray:
        p = self.problem
        return np.asarray(p.x0 + (np.asarray(phi) - p.phi0) * (p.x1 - p.x0) / p.dphi, dtype=float)


def _re(bar: FourBar, p: FunctionProblem, d: Design, samples: int) -> StructuralError:
    from graphmech.exact.freudenstein import structural_error

    f, lo, hi = p.f(), min(p.x0, p.x1), max(p.x0, p.x1)

    def inside(x: np.ndarray) -> np.ndarray:  # x from φ rounds a hair past an end: sqrt(−1e-17)
        return f(np.clip(x, lo, hi))

    return structural_error(bar, inside, p.x0, p.x1, p.phi0, p.dphi, p.psi0, p.dpsi, d.phi, samples)


def _curve_max(s: StructuralError, p: FunctionProblem) -> tuple[float, float]:
    k = int(np.argmax(np.abs(s.error)))
    return float(abs(s.error[k])), float(p.x0 + (s.phi[k] - p.phi0) * (p.x1 - p.x0) / p.dphi)


def _miss(s: StructuralError, bar: FourBar) -> float:
    """The largest miss of C at the precision points over the longest link: |ΔC| = 2c·|sin(e/2)|."""
    return float(np.max(2.0 * bar.c * np.abs(np.sin(s.at_points / 2.0)))) / max(bar.a, bar.b, bar.c, bar.d)


def analyse_function(p: FunctionProblem, mu: float, find: tuple[str, ...] = (), source: str = "") -> FunctionFound:
    """The design drawn at μl = ``mu`` against the exact solution, both re-analysed."""
    from graphmech.accuracy import DISCRETISATION, relative, richardson
    from graphmech.exact.freudenstein import FourBar, output_angle
    from graphmech.methods.characteristics import grashof_class
    from graphmech.problems.judging import Row

    try:
        d = _design(p)
        ex = exact_lengths(d.phi, d.psi, p.frame)
    except GraphmechError as e:
        raise SceneError([(p.key, str(e))], source) from None
    xbar = FourBar(ex["a"], ex["b"], ex["c"], ex["d"], ex["sa"] < 0, ex["sc"] < 0)
    xr = _re(xbar, p, d, 2001)
    if not xr.assembles:
        raise SceneError([(p.key, f"the designed linkage {xr.why}")], source)
    if p.points <= 3 and not xr.zero_at_points(1e-6):
        k = int(np.argmax(np.abs(xr.at_points)))
        raise SceneError([(p.key, (f"the precision points lie on both assembly branches: the linkage through "
                                  f"point 1 misses point {k + 1} by {math.degrees(abs(xr.at_points[k])):.4g}° — "
                                  "it cannot pass through them in one motion"))], source)
    # the drawing: the method's lengths at μl, each precision position on the branch found
    mbar = FourBar(d.a / mu, d.b / mu, d.c / mu, d.d / mu, d.input_reversed, d.output_reversed)
    psi_mm, _ = output_angle(mbar, d.phi, xr.branch)
    A, D = 0j, complex(-mbar.d, 0.0)
    B = (-1.0 if mbar.input_reversed else 1.0) * mbar.a * np.exp(1j * d.phi)
    C = D + (-1.0 if mbar.output_reversed else 1.0) * mbar.c * np.exp(1j * psi_mm)
    mm = {"A": A, "D": D, "B": B, "C": C}
    drawn = {"lAB": abs(B[0] - A), "lBC": abs(C[0] - B[0]), "lCD": abs(C[0] - D), "lAD": abs(D - A)}
    exact = {"lAB": ex["a"], "lBC": ex["b"], "lCD": ex["c"], "lAD": ex["d"]}
    gbar = FourBar(drawn["lAB"] * mu, drawn["lBC"] * mu, drawn["lCD"] * mu, drawn["lAD"] * mu,
                   d.input_reversed, d.output_reversed)
    gr = _re(gbar, p, d, CURVE_SAMPLES)
    gr2 = _re(gbar, p, d, 2 * CURVE_SAMPLES - 1)
    if not (gr.assembles and gr2.assembles):
        raise SceneError([(p.key, f"the drawn linkage {gr.why or gr2.why}")], source)
    if not (np.all(np.isfinite(gr.error)) and np.all(np.isfinite(gr2.error)) and math.isfinite(xr.max_error)):
        raise SceneError([(p.key, ("the structural error is not finite over the range: f or the linkage breaks "
                                  "down in double precision"))], source)
    size_m = max(exact.values())
    # plain floats: numpy's scalars reach the verdicts (a numpy bool is no JSON) and the table
    rows = [Row(n, "m", float(v), mu, float(v) * mu, exact[n], float(abs(v * mu - exact[n]) / size_m))
            for n, v in drawn.items()]
    gm, xm = float(_miss(gr, gbar)), float(_miss(xr, xbar))
    rows.append(Row("reanalysis_error", "", None, 1.0, gm, xm, abs(gm - xm)))
    # the structural error: read off the sampled curve, against the located extreme
    (e1, x1), (e2, x2) = _curve_max(gr, p), _curve_max(gr2, p)
    k = int(np.argmax(np.abs(xr.extremes)))
    ex_x = float(p.x0 + (xr.extremes_phi[k] - p.phi0) * (p.x1 - p.x0) / p.dphi)
    # each estimate: the curve read again at twice the samples (Richardson, order 2), at least what
    # the samples can miss of the extreme (_missed), at least the angles' round-off (ANGLE_ROUND_OFF)
    basis = f"{CURVE_SAMPLES} samples of the curve"
    ke = int(np.argmax(np.abs(gr.error)))
    err_e = max(richardson(e1, e2, 2), _missed(np.abs(gr.error), ke), ANGLE_ROUND_OFF)
    rows.append(Row("structural_error_max", "deg", None, 1.0, math.degrees(e1), math.degrees(xr.max_error),
                    abs(e1 - xr.max_error) / xr.max_error if xr.max_error > 0 else abs(e1))
                .estimated(DISCRETISATION, relative(err_e, e1), basis))
    span = abs(p.x1 - p.x0)
    half_step = 0.5 / (CURVE_SAMPLES - 1) if 0 < ke < gr.error.size - 1 else 0.0
    rows.append(Row("x_error_max", "", None, 1.0, x1, ex_x, abs(x1 - ex_x) / span)
                .estimated(DISCRETISATION, max(abs(x1 - x2) / span, half_step), basis))
    gv, gv2 = _sampled_gamma(gbar, gr.phi, gr.branch), _sampled_gamma(gbar, gr2.phi, gr2.branch)
    kg = int(np.argmin(gv))
    g1, g2 = float(gv[kg]), float(gv2.min())
    gx = gamma_min_range(xbar, p.phi0, p.dphi)
    err_g = max(richardson(g1, g2, 2), _missed(gv, kg), ANGLE_ROUND_OFF)
    rows.append(Row("gamma_min_range", "deg", None, 1.0, math.degrees(g1), math.degrees(gx), abs(g1 - gx) / math.pi)
                .estimated(DISCRETISATION, relative(err_g, math.pi), basis))
    warnings = []
    if d.condition > ILL_CONDITION:
        warnings.append(f"the precision points are nearly dependent: Freudenstein's system has the condition "
                        f"number {d.condition:.3g} (over {ILL_CONDITION:g}) — a small change of φ_k, ψ_k moves "
                        "the lengths much (Δφ or Δψ small, the points crowded)")
        rows = [replace(r, ill_conditioned=True) for r in rows]
    if p.points > 3:
        warnings.append(f"{p.points} precision points: Freudenstein's equation is met in least squares — the "
                        f"linkage passes near them, not through them (missed by up to "
                        f"{math.degrees(float(np.max(np.abs(xr.at_points)))):.4g}°)")
    elif p.points == 2:
        warnings.append("2 precision points: one of R₁, R₂, R₃ is free; the minimum-norm solution is taken")
    grashof = grashof_class(ex["a"], ex["b"], ex["c"], ex["d"])
    xs_ext = [float(v) for v in p.x0 + (xr.extremes_phi - p.phi0) * (p.x1 - p.x0) / p.dphi]
    sol = {"name": "design", "function": d.function.name, **exact, "R": list(d.R),
           "precision_points": {"x": [float(v) for v in d.x], "phi_deg": [math.degrees(v) for v in d.phi],
                                "psi_deg": [math.degrees(v) for v in d.psi]},
           "spacing": d.spacing, "input_reversed": d.input_reversed, "output_reversed": d.output_reversed,
           "condition": d.condition, "method": d.method, "grashof": grashof, "branch": xr.branch,
           "reanalysis": {"error": xm, "psi_error_deg": [math.degrees(v) for v in xr.at_points]},
           "structural_error": {"max_deg": math.degrees(xr.max_error), "x_at": ex_x, "extremes_x": xs_ext,
                                "extremes_deg": [math.degrees(v) for v in xr.extremes],
                                "max_y": xr.max_error_y},
           "gamma_min_range_deg": math.degrees(gx)}
    names = [r.name for r in rows]
    wanted = set(find) or None
    return FunctionFound(p, d, ex, mm, drawn, gbar, gr, xr, (e1, x1), [r for r in rows if wanted is None or r.name in wanted],
                         warnings, [sol], names)


#: The task's protocol names (:data:`graphmech.problems.synthesis.check.SELF_CONTAINED`).
analyse = analyse_function


def lines(ff: FunctionFound) -> list[str]:
    """Under the table: the lengths, Grashof's class, a reversed link, the re-analysis, where the
    largest structural error is."""
    s = ff.solutions[0]
    cls = str(s["grashof"]).replace("_", " ")
    rev = [w for w, on in (("AB points at φ + 180° (R₂ < 0)", s["input_reversed"]),
                           ("DC points at ψ + 180° (R₁ < 0)", s["output_reversed"])) if on]
    se = s["structural_error"]
    return [f"design: l_AB = {s['lAB'] * 1000:.6g} mm, l_BC = {s['lBC'] * 1000:.6g} mm, l_CD = {s['lCD'] * 1000:.6g} mm, "
            f"l_AD = {s['lAD'] * 1000:.6g} mm: {cls}" + "".join(f"; {r}" for r in rev)
            + f"; re-analysed at the {len(s['precision_points']['x'])} precision points: error "
            f"{s['reanalysis']['error']:.1e}",
            (f"structural error ({s['spacing']} spacing): largest {se['max_deg']:.4f}° at x = {se['x_at']:.6g} "
            f"(located on {ff.exact_re.phi.size} samples, refined); condition number {s['condition']:.3g}")]


# ----------------------------------------------------------------------------- the figure
def _xy(z: complex) -> tuple[float, float]:
    return (float(z.real), float(z.imag))


def linkage_items(ff: FunctionFound) -> list[Primitive]:
    """The designed four-bar bold at the first precision position, AB_k, B_kC_k, DC_k thin dashed
    at the others, the frame line dash-dot, the swings Δφ at A and Δψ at D marked."""
    from graphmech.drawing.primitives import (
        FixedPivot,
        Hinge,
        Label,
        Segment,
        angle_arc,
    )

    m = ff.mm
    A, D = _xy(m["A"]), _xy(m["D"])
    B, C = [_xy(z) for z in m["B"]], [_xy(z) for z in m["C"]]
    n = len(B)
    ext = 0.15 * abs(D[0])
    items: list[Primitive] = [Segment((A[0] + ext, 0.0), (D[0] - ext, 0.0), "construction", dashdot=True)]
    for k in range(1, n):
        items += [Segment(A, B[k], "given", dashed=True), Segment(B[k], C[k], "given", dashed=True),
                  Segment(D, C[k], "given", dashed=True), Hinge(B[k]), Hinge(C[k])]
    items += [Segment(A, B[0], "result"), Segment(B[0], C[0], "result"), Segment(C[0], D, "result"),
              FixedPivot(A), FixedPivot(D), Hinge(B[0]), Hinge(C[0])]
    labels: list[Primitive] = [Label("A", A, (unit(A, B[0]), unit(A, D), *(unit(A, b) for b in B[1:]))),
                               Label("D", D, (unit(D, C[0]), unit(D, A), *(unit(D, c) for c in C[1:])))]
    for centre, ends, r_link, text in ((A, B, ff.drawn_mm["lAB"], "Δφ"), (D, C, ff.drawn_mm["lCD"], "Δψ")):
        u0, u1 = unit(centre, ends[0]), unit(centre, ends[-1])
        arc = angle_arc(centre, u0, u1, 0.3 * r_link, "construction")
        if arc is not None:
            items.append(arc)
            mid = arc.points[len(arc.points) // 2]
            labels.append(Label(text, mid, (unit(mid, centre),), italic=False))
    labels += [Label(f"B_{{{k + 1}}}", B[k]) for k in range(n)] + [Label(f"C_{{{k + 1}}}", C[k]) for k in range(n)]
    return items + labels


def _round_step(span: float, most: int) -> float:
    """The smallest of 1, 2, 2.5, 5 × 10^k giving at most ``most`` intervals over ``span``."""
    from graphmech.scales import round_scale

    return round_scale(span / most)


def error_items(ff: FunctionFound, mu_e: float) -> list[Primitive]:
    """The structural error Δψ against x: the sampled curve (the one the check reads), the x axis
    below it with its numbers, the Δψ axis with its numbers, the zero line, the precision points
    marked on it and the largest error marked."""
    from graphmech.drawing.diagrams import AXIS_OVERRUN, NUMBER_SIZE
    from graphmech.drawing.lettering import number
    from graphmech.drawing.primitives import (
        Arrow,
        Circle,
        Label,
        Polyline,
        Segment,
        Text,
    )

    p, s = ff.problem, ff.drawn_re
    small = NUMBER_SIZE
    x0, x1 = min(p.x0, p.x1), max(p.x0, p.x1)
    width = PLOT_WIDTH

    def X(x: float | np.ndarray) -> Any:
        return (np.asarray(x, dtype=float) - x0) / (x1 - x0) * width

    xs = ff.x_of(s.phi)
    ys = np.degrees(s.error) / mu_e
    lo, hi = min(0.0, float(ys.min())), max(0.0, float(ys.max()))
    base = lo - 5.0  # the x axis, under the curve
    items: list[Primitive] = [Arrow((0.0, base), (width + AXIS_OVERRUN, base), "label"),
                              Arrow((0.0, base), (0.0, hi + AXIS_OVERRUN), "label"),
                              Segment((0.0, 0.0), (width, 0.0), "construction")]
    texts: list[Primitive] = [Label("Δψ", (0.0, hi + AXIS_OVERRUN), ((0.0, -1.0),)),
                              Label("x", (width + AXIS_OVERRUN, base), ((-1.0, 0.0),))]
    step = _round_step(x1 - x0, 5)
    k0 = math.ceil(x0 / step - 1e-9)
    for k in range(k0, math.floor(x1 / step + 1e-9) + 1):
        xt = float(X(k * step))
        items.append(Segment((xt, base), (xt, base - 1.0), "label"))
        texts.append(Text(number(k * step), (xt, base - 1.0 - 0.6 * small - 0.8), small))
    e_step = _round_step(max(hi, -lo), 2) if hi > lo else 1.0
    for k in range(math.ceil(lo / e_step - 1e-9), math.floor(hi / e_step + 1e-9) + 1):
        yt = k * e_step
        items.append(Segment((0.0, yt), (-1.0, yt), "label"))
        if k != 0:  # the zero line is the curve's own reference: its 0 would crowd x₁ there
            texts.append(Text(f"{number(yt * mu_e)}°", (-1.8, yt), small, anchor="end"))
    for k, xk in enumerate(ff.design.x):  # the precision points on the zero line, dashed down to the axis
        xt = float(X(xk))
        items += [Segment((xt, 0.0), (xt, base), "construction", dashed=True), Circle((xt, 0.0), 0.8, "result")]
        texts.append(Label(f"x_{{{k + 1}}}", (xt, 0.0), ((0.0, -1.0), (1.0, 0.0), (-1.0, 0.0),
                                                         (0.0, 1.0 if ys[int(np.argmin(np.abs(xs - xk)))] > 0 else -1.0))))
    items.append(Polyline(tuple(zip((float(v) for v in X(xs)), (float(v) for v in ys))), "result"))
    # the largest error's level, dashed across the plot, named at its right end
    k = int(np.argmax(np.abs(s.error)))
    level = float(ys[k])
    items += [Segment((0.0, level), (width, level), "construction", dashed=True), Circle((float(X(xs[k])), level), 0.8, "result")]
    texts.append(Label("Δψ_{max}", (width, level), ((-1.0, 0.0),)))
    return items + texts


def panels(ff: FunctionFound, mu: float) -> tuple[str, list[Panel]]:
    """The sheet's title and its panels: the designed four-bar at μl, the structural error."""
    from graphmech.drawing.lettering import number, scale_text
    from graphmech.drawing.primitives import Panel
    from graphmech.scales import round_scale

    p, g = ff.problem, ff.drawn_bar
    d = ff.design
    title = f"Function generator for y = {_fname(p)}, {p.points} {p.spacing} precision points"
    rev = tuple(w for w, on in (("AB reversed: at φ + 180°", d.input_reversed),
                                ("DC reversed: at ψ + 180°", d.output_reversed)) if on)
    notes1 = (scale_text("l", mu),
              (f"l_{{AB}} = {number(g.a * 1000)} mm, l_{{BC}} = {number(g.b * 1000)} mm, "
              f"l_{{CD}} = {number(g.c * 1000)} mm, l_{{AD}} = {number(g.d * 1000)} mm"), *rev)
    e_max, x_max = ff.curve_max
    mu_deg = round_scale(max(math.degrees(e_max), 1e-12) / PLOT_HEIGHT)
    span = abs(p.x1 - p.x0)
    notes2 = (f"{scale_text('psi', math.radians(mu_deg))}, μ_{{x}} = {number(span / PLOT_WIDTH)} /mm",
              f"Δψ_{{max}} = {number(math.degrees(e_max))}° at x = {number(x_max)} ({CURVE_SAMPLES} samples)",
              "x_{k} = " + ", ".join(number(float(v)) for v in d.x))
    return title, [Panel("design", "Four-bar by Freudenstein's equation", tuple(linkage_items(ff)), notes1, row=0,
                         scales=(("l", mu),)),
                   Panel("error", "Structural error Δψ against x", tuple(error_items(ff, mu_deg)), notes2, row=0,
                         scales=(("psi", math.radians(mu_deg)),))]


def _fname(p: FunctionProblem) -> str:
    if p.function == "power":
        return f"x^{{{p.exponent:g}}}"
    return {"square": "x^{2}", "cube": "x^{3}", "reciprocal": "1/x",
            "sqrt": "√x", "log10": "log x", "ln": "ln x"}.get(p.function, f"{p.function} x")


# ----------------------------------------------------------------------------- the protocol
#: The function task's phrases: key → (English, 中文, русский). 孙桓 §8: 按给定函数设计 (函数生成机构).
PHRASES: dict[str, tuple[str, str, str]] = {
    "fn points": (("the {n} precision points ({spacing}): x_k = {x}; on the crank φ_k = {phi}°, on the rocker "
                   "ψ_k = {psi}°"),
                  "{n}个精确点（{spacing}）：x_k = {x}；对应输入角φ_k = {phi}°，输出角ψ_k = {psi}°",
                  ("{n} точки точного воспроизведения ({spacing}): x_k = {x}; углы кривошипа φ_k = {phi}°, "
                   "коромысла ψ_k = {psi}°")),
    "fn solve": (("Freudenstein's equation R₁cos φ_k − R₂cos ψ_k + R₃ = cos(φ_k − ψ_k) at the points: "
                  "R₁ = {r1}, R₂ = {r2}, R₃ = {r3} (condition number {cond})"),
                 ("在各精确点列Freudenstein方程R₁cos φ_k − R₂cos ψ_k + R₃ = cos(φ_k − ψ_k)，解得R₁ = {r1}，"
                 "R₂ = {r2}，R₃ = {r3}（条件数{cond}）"),
                 ("уравнение Фрейденштейна R₁cos φ_k − R₂cos ψ_k + R₃ = cos(φ_k − ψ_k) в точках: "
                  "R₁ = {r1}, R₂ = {r2}, R₃ = {r3} (число обусловленности {cond})")),
    "fn lengths": ("with l_AD = {d} m: l_CD = d/R₁ = {c} m, l_AB = d/|R₂| = {a} m, l_BC = {b} m{rev}",
                   "取l_AD = {d} m：l_CD = d/R₁ = {c} m，l_AB = d/|R₂| = {a} m，l_BC = {b} m{rev}",
                   "при l_AD = {d} m: l_CD = d/R₁ = {c} m, l_AB = d/|R₂| = {a} m, l_BC = {b} m{rev}"),
    "fn chebyshev": ("Chebyshev spacing", "切比雪夫间隔", "по Чебышёву"),
    "fn uniform": ("equal spacing", "等间隔", "равномерно"),
    "fn reversed": ("; R₂ < 0: AB is drawn at φ + 180°", "；R₂ < 0：AB画在φ + 180°方向",
                    "; R₂ < 0: AB откладываем под углом φ + 180°"),
    "fn draw": (("draw AD = {d} mm, AB₁ = {a} mm at φ₁ and DC₁ = {c} mm at ψ₁; measure B₁C₁ = {b} mm: "
                 "l_BC = {lb} m"),
                "作AD = {d} mm，AB₁ = {a} mm（φ₁方向），DC₁ = {c} mm（ψ₁方向）；量得B₁C₁ = {b} mm：l_BC = {lb} m",
                ("строим AD = {d} mm, AB₁ = {a} mm под углом φ₁ и DC₁ = {c} mm под углом ψ₁; измеряем "
                 "B₁C₁ = {b} mm: l_BC = {lb} m")),
    "fn check": (("check: the four-bar driven to φ_k reaches ψ_k to {err}; the structural error over the range "
                  "is largest, {e}°, at x = {x} ({n} samples)"),
                 "校核：机构转到φ_k时达到ψ_k，误差{err}；全程结构误差最大{e}°，在x = {x}处（{n}个采样点）",
                 ("проверка: четырёхзвенник в положениях φ_k даёт ψ_k с погрешностью {err}; структурная ошибка "
                  "на всём диапазоне наибольшая, {e}°, при x = {x} (точек: {n})")),
}



def steps(ff: FunctionFound, mu: float, say: Callable[..., str], num: Callable[[float], str]) -> list[str]:
    """The construction protocol's lines after μl is chosen: the numbers the check's rows read."""
    d, g = ff.design, ff.drawn_mm
    e_max, x_max = ff.curve_max

    def many(vs: Any) -> str:
        return ", ".join(num(float(v)) for v in vs)

    return [say("fn points", n=str(d.n), spacing=say(f"fn {d.spacing}"), x=many(d.x), phi=many(np.degrees(d.phi)), psi=many(np.degrees(d.psi))),
            say("fn solve", r1=num(d.R[0]), r2=num(d.R[1]), r3=num(d.R[2]), cond=num(d.condition)),
            say("fn lengths", d=num(d.d), c=num(d.c), a=num(d.a), b=num(d.b),
                rev=say("fn reversed") if d.input_reversed else ""),
            say("fn draw", d=num(g["lAD"]), a=num(g["lAB"]), b=num(g["lBC"]), c=num(g["lCD"]), lb=num(g["lBC"] * mu)),
            say("fn check", err=f"{ff.solutions[0]['reanalysis']['error']:.1e}",
                e=num(math.degrees(e_max)), x=num(x_max), n=str(CURVE_SAMPLES))]


__all__ = [
    "NAMES",
    "PHRASES",
    "FunctionFound",
    "FunctionProblem",
    "analyse",
    "analyse_function",
    "choose_scale",
    "error_items",
    "exact_R",
    "exact_lengths",
    "gamma_min_range",
    "lengths_from_R",
    "lines",
    "linkage_items",
    "panels",
    "read_function",
    "size",
    "steps",
]
