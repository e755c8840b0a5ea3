"""The exact reduced machine of the flywheel problem: Jп(φ), Mп(φ), ΔT(φ) and the flywheel.

The textbook reduces a machine to its crank: a reduced moment of inertia ``Jп(φ)`` (the kinetic
energy of every moving link divided by ``ω1²/2``) and a reduced moment ``Mп(φ)`` (the power of
every load divided by ``ω1``). A constant balancing moment ``M_b`` makes the work over a cycle
zero; the kinetic energy then changes by ``ΔT(φ) = ∫_0^φ (Mп + M_b) dφ``, and the flywheel ``J_F``
keeps the speed within ``ω_m(1 ± δ/2)``: the energy-mass (Wittenbauer) diagram, or the energy
indicator ``ΔW_max/(ω_m²δ)``.

Everything here is *exact* — velocities in closed form from :func:`graphmech.exact.linkage.solve`,
integrals by composite Gauss–Legendre between the angles where ``Mп`` has a kink or a step (it is
analytic between them), extremes at roots of the exact derivative found by ``brentq`` — so that it
can check the graphical constructions. Nothing is taken from ``graphmech.construction``,
``graphmech.methods`` or ``graphmech.geometry``.

Conventions are those of :mod:`graphmech.mechanisms.machine`: φ is the crank angle from
position 1 in the crank's sense of rotation, moments are signed by power (positive drives).
Units are SI throughout (m, kg, kg·m², N·m, J, rad, rad/s).
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass
from itertools import pairwise
from typing import Literal, cast

import numpy as np

from graphmech.errors import NotApplicable, OutOfDomain, SceneError
from graphmech.roots import brentq  # scipy's algorithm without loading scipy.optimize (0.3 s)
from graphmech.exact.linkage import Kinematics, solve
from graphmech.mechanisms.linkage import Crank, Linkage
from graphmech.mechanisms.machine import (
    CrankMoment,
    LinkMoment,
    Machine,
    SliderLoad,
    Table,
)

__all__ = ["ExactMachine", "Extremes", "Indicator", "Motion", "Stroke", "Tangents", "table_line",
           "table_value"]

_TWO_PI = 2.0 * math.pi

#: Longest quadrature cell, rad: with 8 Gauss–Legendre nodes an analytic Mп whose nearest complex
#: singularity is ~1 rad away integrates to rounding (the error falls like (h/4d)^16).
_CELL = _TWO_PI / 360.0
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)
#: Samples per quadrature cell used to bracket the roots of a derivative (extremes).
_SAMPLES_PER_CELL = 4
#: Samples per crank revolution used to bracket a slider's dead centres.
_SCAN = 720
#: Two breaks closer than this (rad) are one break; a break this close to 0 or Φ is at 0.
_SAME_ANGLE = 1e-12
#: brentq's absolute tolerance on an angle, rad (its relative one is the minimum, 4ε).
_XTOL = 1e-14


# --------------------------------------------------------------------------------------------
# Results


@dataclass(frozen=True)
class Stroke:
    """A loaded slider's stroke along its guide.

    Parameters
    ----------
    H : float
        The stroke, m (the travel between the two dead centres along the guide).
    phi_back, phi_front : float
        φ (rad from position 1, in [0, 2π)) of the backward extreme (``s = 0``: the dead centre
        nearest the guide's tail) and of the forward one (``s = H``).
    back : float
        The slider's coordinate along the guide (``P·u``, m, u the guide's unit vector) at the
        backward extreme: ``s = P·u − back``.
    """

    H: float
    phi_back: float
    phi_front: float
    back: float


@dataclass(frozen=True)
class Extremes:
    """The global maximum and minimum of a function over one cycle.

    Parameters
    ----------
    maximum, minimum : float
        The extreme values (J for ΔT, kg·m² for Jп).
    phi_max, phi_min : float
        Where they are reached, rad from position 1, in [0, Φ).
    """

    maximum: float
    phi_max: float
    minimum: float
    phi_min: float


@dataclass(frozen=True)
class Tangents:
    """The Wittenbauer (energy-mass) diagram's two tangents and the flywheel they give.

    Parameters
    ----------
    form : "exact" or "book"
        ``exact``: ω_max = ω_m(1 + δ/2), ω_min = ω_m(1 − δ/2); ``book``: ω_max² = ω_m²(1 + δ),
        ω_min² = ω_m²(1 − δ).
    omega_max, omega_min : float
        The design extreme speeds of that form, rad/s.
    k, l : float
        Intercepts on the ΔT axis, J: ``k = max[ΔT − ω_max²·Jп/2]``, ``l = min[ΔT − ω_min²·Jп/2]``.
    phi_k, phi_l : float
        The crank angles of the tangent points, rad from position 1, in [0, Φ).
    J_F : float
        The flywheel's moment of inertia ``(k − l)/(ω_m²·δ)``, kg·m² (≤ 0: none needed).
    """

    form: Literal["exact", "book"]
    omega_max: float
    omega_min: float
    k: float
    l: float
    phi_k: float
    phi_l: float
    J_F: float


@dataclass(frozen=True)
class Indicator:
    """The energy-indicator estimate of the flywheel.

    Parameters
    ----------
    delta_W : float
        ΔW_max = ΔT_max − ΔT_min, J.
    J_mean : float
        The mean reduced inertia (1/Φ)∫Jп dφ, kg·m².
    J_F : float
        ``ΔW_max/(ω_m²δ) − J_mean``, kg·m².
    """

    delta_W: float
    J_mean: float
    J_F: float


@dataclass(frozen=True)
class Motion:
    """The steady motion from the energy equation ``(J_F + Jп)ω²/2 = T0 + ΔT(φ)``.

    Parameters
    ----------
    J_F : float
        The flywheel used, kg·m².
    T0 : float
        The kinetic energy at φ = 0, J, chosen so that (ω_max + ω_min)/2 = ω_m.
    omega0 : float
        ω at φ = 0, rad/s.
    omega_max, omega_min : float
        The extreme speeds over the cycle, rad/s.
    phi_omega_max, phi_omega_min : float
        Where they are reached, rad from position 1, in [0, Φ).
    delta : float
        The coefficient of speed fluctuation achieved, (ω_max − ω_min)/ω_m.
    """

    J_F: float
    T0: float
    omega0: float
    omega_max: float
    omega_min: float
    phi_omega_max: float
    phi_omega_min: float
    delta: float


# --------------------------------------------------------------------------------------------
# Piecewise-linear tables


def table_value(table: Table, x: np.ndarray | float) -> np.ndarray:
    """A table's value at x (right-continuous at a step; the end values hold outside).

    Parameters
    ----------
    table : Table
        Nodes ``x`` (non-decreasing; a repeated x is a step) and values ``y``.
    x : array_like
        Where to evaluate (the table's units).

    Returns
    -------
    ndarray
        y(x), same shape as ``x``.

    Examples
    --------
    >>> t = Table((0.0, 1.0, 1.0, 2.0), (0.0, 10.0, 4.0, 4.0))
    >>> table_value(t, np.array([0.5, 1.0, 3.0])).tolist()
    [5.0, 4.0, 4.0]
    """
    xs = np.asarray(table.x, dtype=float)
    ys = np.asarray(table.y, dtype=float)
    x = np.asarray(x, dtype=float)
    if xs.size == 1:
        return np.full(x.shape, ys[0])
    i = np.clip(np.searchsorted(xs, x, side="right") - 1, 0, xs.size - 2)
    x0, x1, y0, y1 = xs[i], xs[i + 1], ys[i], ys[i + 1]
    width = np.where(x1 > x0, x1 - x0, 1.0)  # x0 ≤ x < x1 inside, so width > 0 where it is used
    out = y0 + (y1 - y0) * (x - x0) / width
    out = np.where(x < xs[0], ys[0], out)
    return cast(np.ndarray, np.where(x >= xs[-1], ys[-1], out))


def table_line(table: Table, x: float) -> tuple[float, float]:
    """The straight line ``y = a + b·x`` of the table's segment that holds x (right-continuous).

    Used to continue one segment exactly up to its ends (a one-sided limit at a step).

    Examples
    --------
    >>> table_line(Table((0.0, 2.0, 4.0), (0.0, 4.0, 0.0)), 3.0)
    (8.0, -2.0)
    """
    xs, ys = table.x, table.y
    if len(xs) == 1 or x < xs[0]:
        return float(ys[0]), 0.0
    if x >= xs[-1]:
        return float(ys[-1]), 0.0
    i = int(np.searchsorted(np.asarray(xs, dtype=float), x, side="right")) - 1
    b = (ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i])
    return float(ys[i] - b * xs[i]), float(b)


def _table_slope(table: Table, x: np.ndarray) -> np.ndarray:
    """dy/dx of a table without steps, right-continuous at its points (0 outside it)."""
    xs, ys = np.asarray(table.x, dtype=float), np.asarray(table.y, dtype=float)
    i = np.clip(np.searchsorted(xs, x, side="right") - 1, 0, xs.size - 2)
    slope = (ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i])
    return np.where((x < xs[0]) | (x >= xs[-1]), 0.0, slope)


# --------------------------------------------------------------------------------------------
# Extremes at the roots of an exact derivative


def _global_extremes(s: np.ndarray, f_s: np.ndarray, d_s: np.ndarray,
                     f: Callable[[float], float], d: Callable[[float], float]
                     ) -> tuple[float, float, float, float]:
    """Global (max, φ_max, min, φ_min) of f, sampled at ``s`` with derivative ``d_s`` there.

    Every strict sign change of the derivative between two samples holds a local extreme; brentq
    finds it on the exact derivative (accurate to ~1e-14 rad, where refining the *values* of a
    flat extreme would only reach √ε). A step in f′ (a break) is a sign change too: brentq then
    converges onto the break, which is the extreme. The samples themselves are candidates, which
    covers an extreme at a kink without a sign change and a stretch where f′ ≡ 0.
    """
    cand_phi = [float(p) for p in s]
    cand_f = [float(v) for v in f_s]
    change = np.flatnonzero(d_s[:-1] * d_s[1:] < 0.0)
    for i in change:
        r = brentq(d, float(s[i]), float(s[i + 1]), xtol=_XTOL)
        cand_phi.append(r)
        cand_f.append(f(r))
    vals = np.array(cand_f)
    i_max, i_min = int(np.argmax(vals)), int(np.argmin(vals))
    return float(vals[i_max]), cand_phi[i_max], float(vals[i_min]), cand_phi[i_min]


def _dedupe_angles(angles: list[float], period: float) -> list[float]:
    """Angles mod ``period``, sorted, one per cluster closer than ``_SAME_ANGLE``; an angle that
    close to 0 or to ``period`` is 0."""
    out: list[float] = []
    for a in sorted(a % period for a in angles):
        if a < _SAME_ANGLE or period - a < _SAME_ANGLE:
            a = 0.0
        if not out or a - out[-1] > _SAME_ANGLE:
            out.append(a)
    return sorted(set(out))


# --------------------------------------------------------------------------------------------


class ExactMachine:
    """The exact reduced machine: Jп, dJп/dφ, Mп, M_b, ΔT and the flywheel by three methods.

    Build it once per :class:`~graphmech.mechanisms.machine.Machine`; every function of φ is
    vectorised over arrays of φ (rad from position 1, any value: the cycle repeats).

    Parameters
    ----------
    machine : Machine
        The machine (SI units). With a linkage its driver must be a :class:`Crank` and the cycle
        Φ a whole number of crank turns; without one, only :class:`CrankMoment` loads and the
        constant ``machine.inertia``.

    Attributes
    ----------
    machine : Machine
    strokes : tuple of (Stroke or None)
        Per load in ``machine.loads``: the :class:`Stroke` of a :class:`SliderLoad`, else None.

    Raises
    ------
    SceneError (a ValueError)
        If the machine is inconsistent (a mass or load naming a point or link the linkage lacks,
        a driver that is not a crank, Φ not a whole number of turns, a slider that does not
        move, …: every problem found, at once), or the linkage cannot be solved at some φ (the
        message gives that φ).

    Notes
    -----
    With ω1 the crank's angular velocity and the crank turning uniformly (ε = 0),

    * ``Jп = J_const + Σ (m·|v_S|² + J_S·ω_link²)/ω1²`` and, since ``dφ/dt = |ω1|``,
      ``dJп/dφ = 2·Σ (m·v_S·a_S + J_S·ω_link·α_link)/(ω1²·|ω1|)``;
    * a slider load ``F = sense·F(s/H)`` along the guide's unit vector u gives
      ``Mп = F·(v·u)/|ω1| = F·ds/dφ`` on its stroke; a link moment ``M·ω_link/|ω1|``; a crank
      moment its table.

    ``Mп`` is analytic between its breaks (table nodes crossed, dead centres, steps), so composite
    Gauss–Legendre on cells that end at the breaks integrates it to rounding. The dead centres
    are the roots of ``v·u`` (brentq on a 0.5° bracket, ~1e-15 rad); minimising the slider's
    coordinate itself would locate a flat extreme only to ~√ε ≈ 1e-8 rad.

    Examples
    --------
    The IC engine of ``fly.ic_engine_flywheel``: a torque over half a turn, constant resistance.

    >>> from graphmech.mechanisms.machine import CrankMoment, Machine, Table
    >>> md = Table(tuple(np.radians([0.0, 20.0, 50.0, 180.0])), (0.0, 200.0, 200.0, 0.0))
    >>> m = ExactMachine(Machine(None, 0.0, math.pi, 620 * math.pi / 30, 0.01,
    ...                          loads=(CrankMoment(md),), balance="resisting"))
    >>> round(m.balancing_moment(), 3), round(m.indicator().J_F, 4)
    (-116.667, 2.1133)
    """

    def __init__(self, machine: Machine) -> None:
        self.machine = machine
        self.cycle = float(machine.cycle)
        self._validate()
        lk = machine.linkage
        self._linkage: Linkage | None = None
        self._w1 = 1.0
        if lk is not None and isinstance(lk.driver, Crank):  # (checked above)
            # ε = 0: the reduced quantities are those of a uniformly turning crank.
            self._linkage = dataclasses.replace(lk, driver=dataclasses.replace(lk.driver, epsilon=0.0))
            self._w1 = abs(float(lk.driver.omega))
        self.strokes = self._find_strokes()
        self._breaks = self._find_breaks()

        # Quadrature cells: the breaks, then no cell longer than _CELL.
        edges = [0.0, *[b for b in self._breaks if b > 0.0], self.cycle]
        cells = []
        for a, b in pairwise(edges):
            n = max(1, math.ceil((b - a) / _CELL - 1e-9))
            cells.append(np.linspace(a, b, n + 1)[:-1])
        self._edges = np.append(np.concatenate(cells), self.cycle)
        a, b = self._edges[:-1], self._edges[1:]
        half = 0.5 * (b - a)
        nodes = (a + half)[:, None] + half[:, None] * _GL_X[None, :]
        jn, _, mn = self._evaluate(nodes.ravel())
        wts = half[:, None] * _GL_W[None, :]
        m_cell = (mn.reshape(nodes.shape) * wts).sum(axis=1)
        self._cum_m = np.concatenate(([0.0], np.cumsum(m_cell)))  # ∫_0^edge Mп dφ
        self._work = float(self._cum_m[-1])
        self._abs_work = float((np.abs(mn.reshape(nodes.shape)) * wts).sum())
        self._j_mean = float((jn.reshape(nodes.shape) * wts).sum()) / self.cycle

        # Dense samples for bracketing extremes: every edge and 3 points inside each cell.
        frac = np.arange(_SAMPLES_PER_CELL) / _SAMPLES_PER_CELL
        self._s = np.append((a[:, None] + (b - a)[:, None] * frac[None, :]).ravel(), self.cycle)
        self._s_j, self._s_dj, self._s_m = self._evaluate(self._s)
        self._s_dt: np.ndarray | None = None  # ΔT at the samples, once M_b is known to exist

    # ----------------------------------------------------------------------------------------
    # Checking the machine

    def _validate(self) -> None:
        mc = self.machine
        problems: list[tuple[str, str]] = []
        if not mc.omega_m > 0:
            problems.append(("omega_m", "the mean angular velocity must be > 0"))
        if not 0 < mc.delta < 2 and not math.isnan(mc.delta):  # NaN: a run-down, no δ asked
            problems.append(("delta", "δ must lie in (0, 2)"))
        if not (mc.cycle > 0 and math.isfinite(mc.cycle)):
            problems.append(("cycle", "the cycle Φ must be > 0"))
        if mc.balance not in ("driving", "resisting"):
            problems.append(("balance", "balance must be 'driving' or 'resisting'"))
        for k, ms in enumerate(mc.masses):
            if not (ms.mass >= 0 and ms.inertia >= 0):
                problems.append((f"masses[{k}]", "mass and inertia must be ≥ 0"))
        lk = mc.linkage
        if lk is None:
            if mc.masses:
                problems.append(("masses", ("masses need a linkage (without one, give the "
                                            "constant inertia)")))
            for k, ld in enumerate(mc.loads):
                if not isinstance(ld, CrankMoment):
                    problems.append((f"loads[{k}]", f"a {type(ld).__name__} needs a linkage"))
        else:
            if not isinstance(lk.driver, Crank):
                problems.append(("linkage.driver", "the reduced link must be a crank"))
            elif lk.driver.omega == 0:
                problems.append(("linkage.driver.omega", "the crank's ω must not be 0"))
            turns = mc.cycle / _TWO_PI
            if abs(turns - round(turns)) > 1e-9 or round(turns) < 1:
                problems.append(("cycle", (f"with a linkage Φ must be a whole number of crank "
                                           f"turns (Φ = {math.degrees(mc.cycle):.6g}°)")))
            if not problems:
                kin = solve(lk, np.array([mc.start]))
                points, moving = set(kin.point), set(kin.omega)
                for k, ms in enumerate(mc.masses):
                    if ms.link not in moving:
                        problems.append((f"masses[{k}].link", f"{ms.link!r} is not a moving link"))
                    if ms.point not in points:
                        problems.append((f"masses[{k}].point", f"no point {ms.point!r}"))
                for k, ld in enumerate(mc.loads):
                    if isinstance(ld, SliderLoad):
                        if ld.point not in points:
                            problems.append((f"loads[{k}].point", f"no point {ld.point!r}"))
                        if ld.sense not in (1, -1):
                            problems.append((f"loads[{k}].sense", "sense must be +1 or -1"))
                        if ld.during not in ("forward", "backward", "both"):
                            problems.append((f"loads[{k}].during",
                                             "during must be 'forward', 'backward' or 'both'"))
                    elif isinstance(ld, LinkMoment) and ld.link not in moving:
                        problems.append((f"loads[{k}].link", f"{ld.link!r} is not a moving link"))
        jt = mc.inertia_table
        if jt is not None:
            xs, ys = np.asarray(jt.x, dtype=float), np.asarray(jt.y, dtype=float)
            if not (xs.size == ys.size >= 2 and np.isfinite(xs).all() and np.isfinite(ys).all()):
                problems.append(("inertia_table", "x and y must be finite, of one length ≥ 2"))
            elif not (np.all(np.diff(xs) > 0.0) and xs[0] == 0.0 and abs(xs[-1] - mc.cycle) <= 1e-12 * mc.cycle):
                problems.append(("inertia_table.x", "φ must increase strictly from 0 to Φ"))
            elif not (np.all(ys > 0.0) and ys[-1] == ys[0]):
                problems.append(("inertia_table.y", "Jп must be > 0 and repeat every cycle (Jп(Φ) = Jп(0))"))
        et = mc.energy_table
        if et is not None:
            xs, ys = np.asarray(et.x, dtype=float), np.asarray(et.y, dtype=float)
            if not (xs.size == ys.size >= 2 and np.isfinite(xs).all() and np.isfinite(ys).all()):
                problems.append(("energy_table", "x and y must be finite, of one length ≥ 2"))
            elif not (np.all(np.diff(xs) > 0.0) and xs[0] == 0.0 and abs(xs[-1] - mc.cycle) <= 1e-12 * mc.cycle):
                problems.append(("energy_table.x", "φ must increase strictly from 0 to Φ"))
            elif not ys[0] == ys[-1] == 0.0:
                problems.append(("energy_table.y", ("ΔT must be 0 at φ = 0 and at Φ (counted from position 1, "
                                                    "repeating every cycle)")))
            if mc.loads:
                problems.append(("loads", "not with a table of ΔT: it already holds the loads' work"))
        for k, ld in enumerate(mc.loads):
            t = ld.table
            if len(t.x) != len(t.y) or not t.x:
                problems.append((f"loads[{k}].table", "x and y must have the same (≥ 1) length"))
            elif any(b < a for a, b in zip(t.x[:-1], t.x[1:])):
                problems.append((f"loads[{k}].table.x", "x must be non-decreasing"))
        if problems:
            raise SceneError(problems, source="machine")

    # ----------------------------------------------------------------------------------------
    # Kinematics and the reduced quantities at arrays of φ

    def _kinematics(self, phi: np.ndarray) -> Kinematics:
        assert self._linkage is not None
        mc = self.machine
        kin = solve(self._linkage, mc.start + mc.sense * phi.ravel())
        if not kin.valid.all():
            i = int(np.flatnonzero(~kin.valid)[0])
            why = (f"cannot be solved at φ = {math.degrees(phi.ravel()[i]):.9g}° from position 1: "
                   f"{kin.reason[i]}")
            raise SceneError([("linkage", why)], source="machine")
        return kin

    def _evaluate(self, phi: np.ndarray | float, kin: Kinematics | None = None, mean_at_steps: bool = False
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(Jп, dJп/dφ, Mп) at φ (one linkage solve); Mп right-continuous at a table's step, or
        with ``mean_at_steps`` the mean of both sides there (the rule for a position on a step)."""
        phi = np.asarray(phi, dtype=float)
        mc = self.machine
        shape = phi.shape
        phi = phi.ravel()
        j = np.full(phi.shape, float(mc.inertia))
        dj = np.zeros(phi.shape)
        m = np.zeros(phi.shape)
        w1 = self._w1
        if self._linkage is not None:
            if kin is None:
                kin = self._kinematics(phi)
            w1s = w1 * w1
            for ms in mc.masses:
                v, a = kin.vel[ms.point], kin.acc[ms.point]
                w, al = kin.omega[ms.link], kin.alpha[ms.link]
                j += (ms.mass * (v[:, 0] ** 2 + v[:, 1] ** 2) + ms.inertia * w * w) / w1s
                dj += 2.0 * (ms.mass * (v[:, 0] * a[:, 0] + v[:, 1] * a[:, 1])
                             + ms.inertia * w * al) / (w1s * w1)
        tau = np.mod(phi, self.cycle)
        if mc.inertia_table is not None:  # Jп as given: linear between the table's points
            j += table_value(mc.inertia_table, tau)
            dj += _table_slope(mc.inertia_table, tau)

        def value(table: Table, x: np.ndarray, period: float | None = None) -> np.ndarray:
            v = table_value(table, x)
            return table.mean_at_steps(x, v, period)[0] if mean_at_steps else v

        for k, ld in enumerate(mc.loads):
            if isinstance(ld, CrankMoment):
                m += value(ld.table, tau, self.cycle)
            elif isinstance(ld, LinkMoment):
                assert kin is not None
                m += value(ld.table, tau, self.cycle) * kin.omega[ld.link] / w1
            else:
                assert kin is not None
                st = self.strokes[k]
                assert st is not None
                ux, uy = math.cos(ld.axis), math.sin(ld.axis)
                p, v = kin.point[ld.point], kin.vel[ld.point]
                x = (p[:, 0] * ux + p[:, 1] * uy - st.back) / st.H
                vax = v[:, 0] * ux + v[:, 1] * uy
                active = self._active(ld, vax)
                m += np.where(active, ld.sense * value(ld.table, x) * vax / w1, 0.0)
        return j.reshape(shape), dj.reshape(shape), m.reshape(shape)

    @staticmethod
    def _active(ld: SliderLoad, vax: np.ndarray) -> np.ndarray:
        if ld.during == "forward":
            return vax > 0.0
        if ld.during == "backward":
            return vax < 0.0
        return np.ones(vax.shape, dtype=bool)

    def inertia(self, phi: np.ndarray | float) -> np.ndarray:
        """The reduced moment of inertia Jп(φ), kg·m².

        Parameters
        ----------
        phi : array_like
            Crank angle from position 1, rad.
        """
        return self._evaluate(phi)[0]

    def inertia_slope(self, phi: np.ndarray | float) -> np.ndarray:
        """dJп/dφ, kg·m²/rad (exact, from the accelerations of a uniformly turning crank)."""
        return self._evaluate(phi)[1]

    def load_moment(self, phi: np.ndarray | float, mean_at_steps: bool = False) -> np.ndarray:
        """The loads' reduced moment Mп(φ), N·m, signed by power (positive drives); at a step of
        a table right-continuous, or with ``mean_at_steps`` the mean of both sides."""
        return self._evaluate(phi, mean_at_steps=mean_at_steps)[2]

    def slider_travel(self, k: int, phi: np.ndarray | float
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Load k's slider: (s, ds/dφ, d²s/dφ²) — m, m/rad, m/rad² — s from the backward extreme.

        ``ds/dφ = (v·u)/|ω1|`` and ``d²s/dφ² = (a·u)/ω1²`` for a uniformly turning crank.
        """
        ld, st = self.machine.loads[k], self.strokes[k]
        if not isinstance(ld, SliderLoad) or st is None:
            raise NotApplicable(f"load {k} is not a slider load")
        phi = np.asarray(phi, dtype=float)
        kin = self._kinematics(phi)
        ux, uy = math.cos(ld.axis), math.sin(ld.axis)
        p, v, a = kin.point[ld.point], kin.vel[ld.point], kin.acc[ld.point]
        w1 = self._w1
        s = p[:, 0] * ux + p[:, 1] * uy - st.back
        ds = (v[:, 0] * ux + v[:, 1] * uy) / w1
        dds = (a[:, 0] * ux + a[:, 1] * uy) / (w1 * w1)
        return s.reshape(phi.shape), ds.reshape(phi.shape), dds.reshape(phi.shape)

    def link_ratio(self, link: str, phi: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        """(ω_link/|ω1|, its derivative α_link/ω1² per rad) at φ — 1 and 1/rad."""
        phi = np.asarray(phi, dtype=float)
        kin = self._kinematics(phi)
        w1 = self._w1
        return ((kin.omega[link] / w1).reshape(phi.shape),
                (kin.alpha[link] / (w1 * w1)).reshape(phi.shape))

    # ----------------------------------------------------------------------------------------
    # Strokes and breaks

    def _axis_motion(self, ld: SliderLoad, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        kin = self._kinematics(phi)
        ux, uy = math.cos(ld.axis), math.sin(ld.axis)
        p, v = kin.point[ld.point], kin.vel[ld.point]
        return p[:, 0] * ux + p[:, 1] * uy, v[:, 0] * ux + v[:, 1] * uy

    def _dead_centres(self, ld: SliderLoad) -> list[float]:
        """φ in [0, 2π) where the slider's velocity along the guide changes sign."""
        h = _TWO_PI / _SCAN
        grid = (np.arange(-1, _SCAN + 1) + 0.5) * h  # offset: a dead centre at φ = 0 is inside
        _, vax = self._axis_motion(ld, grid)

        def v(phi: float) -> float:
            return float(self._axis_motion(ld, np.array([phi]))[1][0])

        roots = [float(grid[i]) for i in np.flatnonzero(vax == 0.0)]
        for i in np.flatnonzero(vax[:-1] * vax[1:] < 0.0):
            roots.append(brentq(v, float(grid[i]), float(grid[i + 1]), xtol=_XTOL))
        return _dedupe_angles(roots, _TWO_PI)

    def _find_strokes(self) -> tuple[Stroke | None, ...]:
        out: list[Stroke | None] = []
        for k, ld in enumerate(self.machine.loads):
            if not isinstance(ld, SliderLoad):
                out.append(None)
                continue
            dcs = self._dead_centres(ld)
            if len(dcs) < 2:
                why = f"slider {ld.point} does not move along its guide: no stroke"
                raise SceneError([(f"loads[{k}]", why)], source="machine")
            proj, _ = self._axis_motion(ld, np.array(dcs))
            i_b, i_f = int(np.argmin(proj)), int(np.argmax(proj))
            out.append(Stroke(H=float(proj[i_f] - proj[i_b]), phi_back=dcs[i_b],
                              phi_front=dcs[i_f], back=float(proj[i_b])))
        return tuple(out)

    def _slider_breaks(self, k: int, ld: SliderLoad) -> list[float]:
        """Dead centres and the φ where s/H crosses a table node on an active stroke, in [0, 2π)."""
        st = self.strokes[k]
        assert st is not None
        dcs = self._dead_centres(ld)
        out = list(dcs)
        nodes = sorted({x for x in ld.table.x if 0.0 < x < 1.0})
        ends = [*dcs, dcs[0] + _TWO_PI]
        for a, b in pairwise(ends):
            _, vmid = self._axis_motion(ld, np.array([0.5 * (a + b)]))
            if not self._active(ld, vmid)[0]:
                continue
            pa, _ = self._axis_motion(ld, np.array([a, b]))
            xa, xb = (pa - st.back) / st.H
            for x in nodes:
                def g(phi: float, x: float = x) -> float:
                    return float((self._axis_motion(ld, np.array([phi]))[0][0] - st.back) / st.H - x)
                if (xa - x) * (xb - x) < 0.0:
                    out.append(brentq(g, a, b, xtol=_XTOL))
        return out

    def _find_breaks(self) -> np.ndarray:
        phis: list[float] = []
        turns = max(1, round(self.cycle / _TWO_PI)) if self._linkage is not None else 1
        for k, ld in enumerate(self.machine.loads):
            if isinstance(ld, SliderLoad):
                one = self._slider_breaks(k, ld)
                phis += [p + _TWO_PI * r for r in range(turns) for p in one]
            else:  # every node (ends too: the cycle wraps round, a kink or step may be there)
                phis += [x for x in ld.table.x if 0.0 <= x <= self.cycle]
        for table in (self.machine.inertia_table, self.machine.energy_table):  # kinks: the slope jumps there
            if table is not None:
                phis += [x for x in table.x if 0.0 <= x <= self.cycle]
        return np.array(_dedupe_angles(phis, self.cycle))

    def breaks(self) -> np.ndarray:
        """φ in [0, Φ) where Mп has a kink or a step, rad, sorted.

        Table nodes of crank and link moments; for a slider load its dead centres and the φ where
        s/H crosses a node of its table on an active stroke (brentq, ~1e-15 rad).
        """
        return self._breaks.copy()

    # ----------------------------------------------------------------------------------------
    # Energy

    def balancing_moment(self) -> float:
        """The constant moment M_b, N·m, signed by power, with ``Φ·M_b + ∫_0^Φ Mп dφ = 0``.

        Raises
        ------
        SceneError (a ValueError)
            If the loads do no work at all (Mп ≡ 0: then ΔT ≡ 0 and J_F is undefined), or the
            balance has the wrong sign for ``machine.balance`` (a "driving" moment that would
            have to resist).
        NotApplicable (a ValueError)
            If ΔT was given as a table: its moments are not known.
        """
        if self.machine.energy_table is not None:
            raise NotApplicable("ΔT was given as a table ([flywheel.energy_increment]): it cannot be split back "
                                "into its driving and resisting moments")
        if self._abs_work == 0.0:
            why = ("the loads do no work (Mп ≡ 0): the balancing moment is 0 and ΔT ≡ 0, so J_F "
                   "is undefined")
            raise SceneError([("loads", why)], source="machine")
        mb = -self._work / self.cycle
        slack = 1e-12 * self._abs_work / self.cycle
        want = self.machine.balance
        if (want == "driving" and mb < -slack) or (want == "resisting" and mb > slack):
            why = (f"the loads' net work over a cycle is {self._work:.6g} J, so the balancing "
                   f"moment {mb:.6g} N·m cannot be {want}")
            raise SceneError([("balance", why)], source="machine")
        return mb

    def _energy_and_state(self, phi: np.ndarray | float
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(ΔT, Jп, dJп/dφ, Mп) at φ with one linkage solve (φ and the partial cells' nodes); ΔT
        given as a table: read off it (Mп then 0)."""
        phi = np.asarray(phi, dtype=float)
        shape = phi.shape
        tau = np.mod(phi.ravel(), self.cycle)
        et = self.machine.energy_table
        if et is not None:
            jj, dj, m = self._evaluate(tau)
            return (table_value(et, tau).reshape(shape), jj.reshape(shape), dj.reshape(shape), m.reshape(shape))
        mb = self.balancing_moment()
        j = np.clip(np.searchsorted(self._edges, tau, side="right") - 1, 0, self._edges.size - 2)
        a = self._edges[j]
        half = 0.5 * (tau - a)
        nodes = (a + half)[:, None] + half[:, None] * _GL_X[None, :]
        jj, dj, m = self._evaluate(np.concatenate((tau, nodes.ravel())))
        n = tau.size
        partial = (m[n:].reshape(nodes.shape) * _GL_W[None, :]).sum(axis=1) * half
        dt = self._cum_m[j] + partial + mb * tau
        return (dt.reshape(shape), jj[:n].reshape(shape), dj[:n].reshape(shape),
                m[:n].reshape(shape))

    def energy(self, phi: np.ndarray | float) -> np.ndarray:
        """ΔT(φ) = ∫_0^φ (Mп + M_b) dφ, J (ΔT(0) = 0; periodic over Φ).

        Exact to ~1e-12 relative: cumulative Gauss–Legendre over the cells up to φ, and 8 nodes
        on the last partial cell. Given as a table: the table, linear between its points.
        """
        return self._energy_and_state(phi)[0]

    def _samples_dt(self) -> np.ndarray:
        if self._s_dt is None:
            self._s_dt = self.energy(self._s)
        return self._s_dt

    def _wrap(self, phi: float) -> float:
        return 0.0 if phi >= self.cycle else phi

    def extremes(self) -> Extremes:
        """ΔT_max, ΔT_min over the cycle (J) and their φ (rad): roots of Mп + M_b, global (found
        once per machine: every J row of a check asks for them)."""
        found = self.__dict__.get("_extremes")
        if found is None:
            found = self.__dict__["_extremes"] = self._find_extremes()
        return found

    def _slope_dt(self, phi: np.ndarray, m: np.ndarray) -> np.ndarray:
        """dΔT/dφ at φ (right-continuous), ``m`` being Mп there: Mп + M_b, or the ΔT table's slope."""
        et = self.machine.energy_table
        if et is not None:
            return _table_slope(et, np.mod(phi, self.cycle))
        return m + self.balancing_moment()

    def _vertices(self) -> np.ndarray | None:
        """With ΔT given as a table and Jп piecewise linear too (a table, a constant, a linkage without
        masses): the φ of the polygonal curve's vertices, where its extremes and the Wittenbauer
        tangents' points of contact lie (a linear function is extreme over a polygon at a vertex);
        else None."""
        mc = self.machine
        if mc.energy_table is None or (self._linkage is not None and mc.masses):
            return None
        return np.union1d([0.0], self._breaks)

    def _find_extremes(self) -> Extremes:
        v = self._vertices()
        if v is not None:  # closed form: at the table's points
            dt = self.energy(v)
            i_hi, i_lo = int(np.argmax(dt)), int(np.argmin(dt))
            return Extremes(float(dt[i_hi]), float(v[i_hi]), float(dt[i_lo]), float(v[i_lo]))
        et = self.machine.energy_table
        if et is not None:  # ΔT polygonal: its extremes are at its own points, whatever Jп
            xs, ys = np.asarray(et.x[:-1]), np.asarray(et.y[:-1])
            i_hi, i_lo = int(np.argmax(ys)), int(np.argmin(ys))
            return Extremes(float(ys[i_hi]), float(xs[i_hi]), float(ys[i_lo]), float(xs[i_lo]))
        mb = self.balancing_moment()
        dt = self._samples_dt()

        def f(phi: float) -> float:
            return float(self.energy(np.array([phi]))[0])

        def d(phi: float) -> float:
            return float(self.load_moment(np.array([phi]))[0]) + mb

        hi, p_hi, lo, p_lo = _global_extremes(self._s, dt, self._s_m + mb, f, d)
        return Extremes(hi, self._wrap(p_hi), lo, self._wrap(p_lo))

    def inertia_extremes(self) -> Extremes:
        """Jп_max, Jп_min (kg·m²) and their φ (rad): roots of dJп/dφ, global."""
        def f(phi: float) -> float:
            return float(self.inertia(np.array([phi]))[0])

        def d(phi: float) -> float:
            return float(self.inertia_slope(np.array([phi]))[0])

        if self._linkage is None and self.machine.inertia_table is None:
            j0 = float(self.machine.inertia)
            return Extremes(j0, 0.0, j0, 0.0)
        hi, p_hi, lo, p_lo = _global_extremes(self._s, self._s_j, self._s_dj, f, d)
        return Extremes(hi, self._wrap(p_hi), lo, self._wrap(p_lo))

    def mean_inertia(self) -> float:
        """(1/Φ)∫_0^Φ Jп dφ, kg·m² (Gauss–Legendre on the cells)."""
        return self._j_mean

    # ----------------------------------------------------------------------------------------
    # Flywheel

    def design_speeds(self, form: Literal["exact", "book"] = "exact") -> tuple[float, float]:
        """(ω_max, ω_min), rad/s, that δ allows: exact ω_m(1 ± δ/2), book ω_m·√(1 ± δ)."""
        wm, de = self.machine.omega_m, self.machine.delta
        if form == "exact":
            return wm * (1.0 + 0.5 * de), wm * (1.0 - 0.5 * de)
        if form == "book":
            return wm * math.sqrt(1.0 + de), wm * math.sqrt(1.0 - de)
        raise OutOfDomain(f"form must be 'exact' or 'book', got {form!r}")

    def wittenbauer(self, form: Literal["exact", "book"] = "exact") -> Tangents:
        """The energy-mass diagram's tangents k, l and the flywheel ``(k − l)/(ω_m²δ)``.

        ``k = max_φ[ΔT − c_max·Jп]`` and ``l = min_φ[ΔT − c_min·Jп]`` with ``c = ω²/2`` of the
        design speeds (:meth:`design_speeds`); the tangent points are the roots of
        ``Mп + M_b − c·dJп/dφ`` (brentq), not the positions.
        """
        w_hi, w_lo = self.design_speeds(form)
        v = self._vertices()
        if v is not None:  # closed form: the tangents to a polygonal curve touch it at vertices
            g_v, j_v = self.energy(v), self.inertia(v)

            def tangent(c: float) -> tuple[float, float, float, float]:
                g = g_v - c * j_v
                hi, lo = int(np.argmax(g)), int(np.argmin(g))
                return float(g[hi]), float(v[hi]), float(g[lo]), float(v[lo])
        else:
            dt = self._samples_dt()
            slope = self._slope_dt(self._s, self._s_m)

            def tangent(c: float) -> tuple[float, float, float, float]:
                def f(phi: float) -> float:
                    e, j, _, _ = self._energy_and_state(np.array([phi]))
                    return float(e[0] - c * j[0])

                def d(phi: float) -> float:
                    _, dj, m = self._evaluate(np.array([phi]))
                    return float(self._slope_dt(np.array([phi]), m)[0] - c * dj[0])

                return _global_extremes(self._s, dt - c * self._s_j, slope - c * self._s_dj, f, d)

        k, phi_k, _, _ = tangent(0.5 * w_hi * w_hi)
        _, _, l, phi_l = tangent(0.5 * w_lo * w_lo)
        wm, de = self.machine.omega_m, self.machine.delta
        return Tangents(form, w_hi, w_lo, k, l, self._wrap(phi_k), self._wrap(phi_l),
                        (k - l) / (wm * wm * de))

    def indicator(self) -> Indicator:
        """The energy-indicator flywheel ``ΔW_max/(ω_m²δ) − J_mean``."""
        ex = self.extremes()
        dw = ex.maximum - ex.minimum
        wm, de = self.machine.omega_m, self.machine.delta
        return Indicator(dw, self._j_mean, dw / (wm * wm * de) - self._j_mean)

    def energy_motion(self, J_F: float) -> Motion:
        """The steady motion with flywheel J_F from ``(J_F + Jп)ω²/2 = T0 + ΔT(φ)``.

        T0 is found by brentq so that (ω_max + ω_min)/2 = ω_m; the extremes of ω are the roots
        of ``d(ω²)/dφ ∝ (Mп + M_b)(J_F + Jп) − (T0 + ΔT)·dJп/dφ``.

        Parameters
        ----------
        J_F : float
            The flywheel, kg·m² (J_F + min Jп must be > 0).

        Raises
        ------
        ValueError
            If J_F + Jп is not positive everywhere, or no energy level keeps ω > 0 with the mean
            speed ω_m (the flywheel is far too small).
        """
        mb = self.balancing_moment()
        wm = self.machine.omega_m
        jmin = self.inertia_extremes().minimum
        if not J_F + jmin > 0:
            raise OutOfDomain(f"J_F + Jп must be > 0 everywhere (J_F = {J_F:.6g}, "
                             f"min Jп = {jmin:.6g} kg·m²)")
        dt_s = self._samples_dt()
        jt_s = J_F + self._s_j
        ex = self.extremes()

        def omega_extremes(t0: float) -> tuple[float, float, float, float]:
            def f(phi: float) -> float:
                e, j, _, _ = self._energy_and_state(np.array([phi]))
                return math.sqrt(max(2.0 * (t0 + float(e[0])) / (J_F + float(j[0])), 0.0))

            def d(phi: float) -> float:
                e, j, dj, m = self._energy_and_state(np.array([phi]))
                return float((m[0] + mb) * (J_F + j[0]) - (t0 + e[0]) * dj[0])

            w_s = np.sqrt(np.maximum(2.0 * (t0 + dt_s) / jt_s, 0.0))
            h_s = (self._s_m + mb) * jt_s - (t0 + dt_s) * self._s_dj
            return _global_extremes(self._s, w_s, h_s, f, d)

        def excess(t0: float) -> float:
            hi, _, lo, _ = omega_extremes(t0)
            return 0.5 * (hi + lo) - wm

        t_lo = -ex.minimum  # ω reaches 0 at the lowest energy
        if excess(t_lo) > 0:
            raise OutOfDomain(f"J_F = {J_F:.6g} kg·m² is too small: the speed would fall to 0 before "
                             f"the mean speed could be ω_m")
        t_hi = 0.5 * (J_F + self._j_mean) * wm * wm + abs(ex.minimum) + abs(ex.maximum)
        while excess(t_hi) < 0:
            t_hi *= 2.0
        t0 = brentq(excess, t_lo, t_hi, xtol=1e-15 * t_hi, rtol=4 * np.finfo(float).eps)
        hi, p_hi, lo, p_lo = omega_extremes(t0)
        j0 = float(self.inertia(np.array([0.0]))[0])
        return Motion(J_F, t0, math.sqrt(2.0 * t0 / (J_F + j0)), hi, lo, self._wrap(p_hi),
                      self._wrap(p_lo), (hi - lo) / wm)
