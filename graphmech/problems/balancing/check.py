"""Checking a balancing scene: the mass-radius polygons against the equations of balance.

The correction's m·r, magnitude and angle are read off the polygons of
:mod:`graphmech.methods.balancing` (drawn length × μW; the closing side's direction) and set
against :mod:`graphmech.exact.balancing`, which solves the balance of forces (and of moments)
directly; the rotor with the *drawn* corrections added is then shown to have zero resultant force
and moment to round-off (``residual_force``, ``residual_moment``). A plane that needs no
correction says so instead of an angle.
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, cast

from graphmech.problems.judging import Row, Verdict, close_names, judge_value, measured_entries
from graphmech.errors import SceneError
from graphmech.exact import balancing as ex
from graphmech.geometry.primitives import degrees_0_360
from graphmech.methods import balancing as gm
from graphmech.scales import format_scale, round_scale
from graphmech.geometry.kernels import ScalarOps, intersect_lines
from graphmech.problems.balancing.scene import (DEFAULT_FIND, QUANTITIES, SPEED_QUANTITIES, SPLIT_QUANTITIES,
                                                BalancingProblem)
from graphmech.tolerances import EPS

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.reader import Scene
    from graphmech.mechanisms.rotor import RotorMass

#: The longest polygon side when graphmech chooses μW, mm.
POLYGON_MM = 60.0
#: Above this z/Δ (the largest |z| over the planes' distance Δ) the two-plane split amplifies the
#: round-off of the z's past 1e-10 of the corrections: warned of and flagged ill-conditioned.
ILL_SPLIT = 1e6


@dataclass
class BalancingAnalysis:
    """What one balancing scene produced: the corrections (one per plane), rows, warnings."""

    scene: Scene[BalancingProblem]
    problem: BalancingProblem
    corrections: tuple[gm.Correction, ...] = ()
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: set[str] = field(default_factory=set)
    extra_measured: tuple[tuple[str, float], ...] = ()
    #: the split's corner K on the polygon (mm): start of W_b → K ∥ α₁, K → o ∥ α₂
    split_corner: tuple[float, float] | None = None

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) + ("" if k in self.stated else " (chosen)") for k, v in self.scales.items()]

    @property
    def size(self) -> float:
        """Σ|mᵢrᵢ|, kg·m: the characteristic size of the residuals."""
        return sum(u.m * u.r for u in self.problem.masses)

    @property
    def split_condition(self) -> float:
        """z/Δ: how much the lever rule (z_II − z)/Δ amplifies a rounding of the z's (1 for a
        static balance). The corrections grow as (rotor length)/Δ and cancel each other's force."""
        p = self.problem
        if p.planes is None:
            return 1.0
        span = abs(p.planes[1] - p.planes[0])
        return max([abs(u.z) for u in p.masses] + [abs(z) for z in p.planes]) / span


def units(p: BalancingProblem) -> dict[str, str]:
    """The quantities a balancing problem can give: its type's, the split's, F_unbalanced."""
    return {**QUANTITIES[p.type], **(SPLIT_QUANTITIES if p.split else {}), **(SPEED_QUANTITIES if p.omega else {})}


def requested(scene: Scene[BalancingProblem], extra: tuple[tuple[str, float], ...] = ()) -> list[str]:
    p: BalancingProblem = scene.problem
    q = units(p)
    names = list(scene.find) or list(DEFAULT_FIND[p.type])
    problems = []
    for key, name in [(f"find[{i}]", n) for i, n in enumerate(scene.find)] + \
            [(k, n) for k, n, _ in measured_entries(scene, extra)]:
        if name in SPLIT_QUANTITIES and not p.split:
            problems.append((key, f"{name} needs [balancing] split_angles (a static balance's two directions)"))
        elif name in SPEED_QUANTITIES and not p.omega:
            problems.append((key, f"{name} needs [balancing] speed (e.g. speed_rpm)"))
        elif name not in q:
            problems.append((key, f"unknown {p.type} balancing quantity {name!r}{close_names(name, q)}"))
    if problems:
        raise SceneError(problems, scene.source)
    return names


def analyse_balancing(scene: Scene[BalancingProblem], extra_measured: tuple[tuple[str, float], ...] = ()) -> BalancingAnalysis:
    """Draw the polygons the scene needs and build its check table."""
    p: BalancingProblem = scene.problem
    names = requested(scene, extra_measured)
    an = BalancingAnalysis(scene, p, extra_measured=tuple(extra_measured))
    masses = list(p.masses)
    # The polygons are linear in 1/μW: drawn once at 1 kg·m/mm they give every length, so a stated
    # μW is judged (and an absurd one refused) before anything is divided by it.
    trial = _balance(p, masses, 1.0)
    longest = max([math.hypot(s.end[0] - s.start[0], s.end[1] - s.start[1]) for c in trial
                   for s in c.sides + (c.closing,)] + [EPS])
    if "W" in scene.scales:
        an.scales["W"] = scene.scales["W"]
        an.stated.add("W")
        drawn = longest / an.scales["W"]
        if not 2.0 <= drawn <= 2000.0:
            raise SceneError([("scales", f"μW = {an.scales['W']:g} kg·m/mm draws the largest mass-radius product "
                                         f"{drawn:.3g} mm long: choose μW so that it is 2 … 2000 mm (about "
                                         f"{round_scale(longest / POLYGON_MM):g} kg·m/mm)")],
                             scene.source)
    else:  # a round μW that draws the longest side POLYGON_MM long
        an.scales["W"] = round_scale(longest / POLYGON_MM)
    an.corrections = _balance(p, masses, an.scales["W"])
    if p.split is not None and not an.corrections[0].balanced:
        an.split_corner = _split_corner(an.corrections[0].closing, p.split)
    for c in an.corrections:
        if c.balanced and c.plane and not any(share for _, share in c.shares):
            an.warnings.append(f"plane {c.plane}: every mass lies in the other correction plane, so none has a "
                               "share here: no correction mass needed (its polygon is a point)")
        elif c.balanced:
            where = "the rotor is" if p.type == "static" else f"plane {c.plane} is"
            an.warnings.append(f"{where} already balanced: no correction mass needed (the polygon closes by "
                               "itself, so there is no angle)")
    kappa = an.split_condition
    if kappa > ILL_SPLIT:
        z1, z2 = _planes(p)  # only a dynamic problem has a split to condition
        span = abs(z2 - z1)
        an.warnings.append(f"the correction planes are only {span * 1000:.3g} mm apart against z up to "
                           f"{kappa * span * 1000:.4g} mm: the two-plane split amplifies round-off by z/Δ = "
                           f"{kappa:.2g} (ill-conditioned; the corrections are good to about {kappa * 2e-16:.0e} "
                           "and cancel each other's force) — put the planes further apart")
    for name in names:
        row = _row(an, name)
        if row is not None:
            an.rows.append(row)
    return an


def _planes(p: BalancingProblem) -> tuple[float, float]:
    """z_I, z_II of a dynamic problem: read_balancing refuses one without them."""
    return cast("tuple[float, float]", p.planes)


def _balance(p: BalancingProblem, masses: list[RotorMass], mu_W: float) -> tuple[gm.Correction, ...]:
    if p.type == "static":
        return (gm.static_balance(masses, p.r_b[0], mu_W),)
    return gm.dynamic_balance(masses, *_planes(p), (p.r_b[0], p.r_b[1]), mu_W)


def _exact(an: BalancingAnalysis) -> tuple[complex, ...]:
    p = an.problem
    us = [ex.Unbalance(u.m, u.r, u.theta, u.z) for u in p.masses]
    if p.type == "static":
        return (ex.static_correction(us),)
    return ex.dynamic_correction(us, *_planes(p))


def _split_corner(closing: gm.DrawnSide, split: tuple[float, float]) -> tuple[float, float]:
    """The force-polygon construction of the split: through the closing side's start a line ∥ α₁,
    through its end (o) a line ∥ α₂; they meet at the corner K (mm)."""
    a1, a2 = split
    return intersect_lines(ScalarOps(), (closing.start[0], closing.start[1], math.cos(a1), math.sin(a1)),
                           (closing.end[0], closing.end[1], math.cos(a2), math.sin(a2)))


def split_exact(w: complex, split: tuple[float, float]) -> tuple[float, float]:
    """W = W₁e^{iα₁} + W₂e^{iα₂} solved for (W₁, W₂) by Cramer's rule (the 2×2 linear solve).

    >>> [round(x, 12) for x in split_exact(1 + 1j, (0.0, math.pi / 2))]
    [1.0, 1.0]
    """
    a1, a2 = split
    det = math.sin(a2 - a1)
    return ((w.real * math.sin(a2) - w.imag * math.cos(a2)) / det,
            (w.imag * math.cos(a1) - w.real * math.sin(a1)) / det)


def _deg360(theta: float) -> float:
    """An angle in degrees in [0, 360) (−0° and −1e-17° are 0°, not 360°)."""
    g = math.degrees(theta) % 360.0
    return 0.0 if g >= 360.0 else g + 0.0


def _angle_diff_deg(a: float, b: float) -> float:
    return (a - b + 180.0) % 360.0 - 180.0


def _values(an: BalancingAnalysis, name: str) -> tuple[float, float, float | None, float, float] | None:
    """(graphical, exact, drawn mm or None, μ, characteristic); None for the angle of no correction."""
    p = an.problem
    mu = an.scales["W"]
    if name.startswith("residual"):
        us = [ex.Unbalance(u.m, u.r, u.theta, u.z) for u in p.masses]
        planes = (0.0,) if p.type == "static" else _planes(p)
        drawn = [(c.vector, z) for c, z in zip(an.corrections, planes)]
        force, moment = ex.residuals(us, drawn, planes[0])  # about plane I: no far-off lever to cancel
        span = 1.0 if p.type == "static" else abs(_planes(p)[1] - _planes(p)[0])
        if name == "residual_force":
            return force, 0.0, None, 1.0, an.size
        return moment, 0.0, None, 1.0, an.size * span
    if name in SPLIT_QUANTITIES:
        return _split_values(an, name)
    if name in SPEED_QUANTITIES:
        w2 = (p.omega or 0.0) ** 2  # units() offers F_unbalanced only with a speed
        drawn_sum = abs(sum((c.vector for c in an.corrections), 0j))  # −Σ mᵢrᵢ as the polygons close it
        exact_sum = abs(sum((cmath.rect(u.m * u.r, u.theta) for u in p.masses), 0j))
        return w2 * drawn_sum, w2 * exact_sum, None, 1.0, w2 * an.size
    plane = name.split("_", 1)[1]
    k = 0 if plane in ("b", "I") else 1
    c, w = an.corrections[k], _exact(an)[k]
    if name.startswith("W"):
        return c.W, abs(w), c.drawn_mm, mu, an.size
    if name.startswith("m"):
        return c.m_b, abs(w) / c.r_b, c.drawn_mm, mu / c.r_b, an.size / c.r_b
    if c.theta is None:  # balanced
        return None
    g = degrees_0_360(float(c.theta))
    e = _deg360(cmath.phase(w))
    return g, g - _angle_diff_deg(g, e), None, 1.0, 360.0


def _split_values(an: BalancingAnalysis, name: str) -> tuple[float, float, float | None, float, float]:
    """W_b1, W_b2 (m_b1, m_b2): the sides of the split triangle measured × μW, signed along α."""
    p, c = an.problem, an.corrections[0]
    split = cast("tuple[float, float]", p.split)
    k = 0 if name.endswith("1") else 1
    exact = split_exact(_exact(an)[0], split)[k]
    if an.split_corner is None:  # already balanced: nothing to split
        g, drawn = 0.0, 0.0
    else:
        K, s = an.split_corner, c.closing
        a, b = (s.start, K) if k == 0 else (K, s.end)
        d = (b[0] - a[0], b[1] - a[1])
        drawn = math.hypot(*d)
        sign = 1.0 if d[0] * math.cos(split[k]) + d[1] * math.sin(split[k]) >= 0 else -1.0
        g = sign * drawn * an.scales["W"]
    if name.startswith("m"):
        return g / c.r_b, exact / c.r_b, drawn, an.scales["W"] / c.r_b, an.size / c.r_b
    return g, exact, drawn, an.scales["W"], an.size


def _row(an: BalancingAnalysis, name: str) -> Row | None:
    v = _values(an, name)
    if v is None:
        return None
    g, e, drawn, scale, char = v
    unit = units(an.problem)[name]
    return Row(name, unit, drawn, scale, g, e, abs(g - e) / max(abs(e), char, 1e-300),
               an.split_condition > ILL_SPLIT)


def judge_balancing(an: BalancingAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """Hand values against the drawing: m·r and m within the drawing precision × their μ, angles
    within the angle a precision-long slip at the closing side's end turns it by."""
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    out = []
    for _key, name, value in measured_entries(an.scene, an.extra_measured):
        v = _values(an, name)
        unit = units(an.problem)[name]
        if v is None:
            out.append(Verdict(name, value, 0.0, 0.0, False, unit))
            continue
        g, _e, drawn, scale, _c = v
        if unit == "deg":
            c = an.corrections[0 if name.endswith(("_b", "_I")) else 1]
            tol = math.degrees(math.atan2(prec, max(c.drawn_mm, prec)))
            out.append(Verdict(name, value, g, tol, abs(_angle_diff_deg(value, g)) <= tol, unit))
        else:
            out.append(judge_value(name, value, g, drawn, scale, prec, unit))
    return out


__all__ = ["BalancingAnalysis", "analyse_balancing", "judge_balancing", "requested", "split_exact", "units"]


def balancing_figure(an: BalancingAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet of the scene's ``show``: the rotor and the mass-radius polygons."""
    from graphmech.problems.balancing.figures import balancing_sheet

    p = an.problem
    return balancing_sheet(an.scene.title, p.type, p.masses, p.planes, an.corrections, an.scales["W"],
                           list(an.scene.show), page, footer, an.scene.page.notation, an.split_corner)
