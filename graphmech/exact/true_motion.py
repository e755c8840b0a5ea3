"""The machine's true motion, integrated by scipy's (stiff) solvers: the check of the flywheel.

The equation of motion of the reduced machine (crank angle φ, speed ω > 0) is

    J(φ)·dω/dt = M(φ, ω) − ½·J′(φ)·ω²,    dφ/dt = ω,

with ``J = J_F + Jп(φ)`` and ``M = Mп(φ) + M_drive``: the constant balancing moment, or a motor
whose straight characteristic ``M0·(ω_s − ω)/(ω_s − ω_m)`` makes the equation stiff when steep.
Since ω > 0 the crank angle can be the independent variable; with ``y = (ω, t, q)``

    dω/dφ = (M − ½·J′·ω²)/(J·ω),    dt/dφ = 1/ω,    dq/dφ = ω,

so a cycle is exactly φ = 0 … Φ, the breaks of Mп (kinks, steps) are the ends of separate runs
(the solver never steps across one), the cycle period is t(Φ) and the φ-mean speed q(Φ)/Φ.

Jп, its derivative and the smooth factors of Mп (a slider's s and ds/dφ, a link's ω_link/ω1) are
tabulated once from :class:`~graphmech.exact.flywheel.ExactMachine` with their exact derivatives
and evaluated by a cubic Hermite interpolant on a uniform grid (O(1) lookup, scalar Python math:
per call it is cheaper than any numpy object). ``J′`` is the interpolant's own derivative, so the
integrated equation conserves the interpolated energy ``½·J·ω²`` exactly (no drift from a
mismatched J′). The tables' piecewise-linear laws (indicator diagram, moments) are evaluated
exactly, one segment per run.

Nothing here comes from ``graphmech.construction``, ``graphmech.methods`` or
``graphmech.geometry``.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from itertools import pairwise
from typing import Any

import numpy as np

from graphmech.errors import GraphmechError, OutOfDomain
from graphmech.exact.flywheel import ExactMachine, table_line
from graphmech.mechanisms.machine import CrankMoment, LinkMoment, Machine, SliderLoad
from graphmech.minimum import fminbound

# scipy.integrate (a third of a second to import) is imported by the functions that integrate:
# a braking check asks for the closed form alone.

__all__ = ["Braking", "Run", "TrueMotion", "TrueMotionError", "braking_time", "integrate",
           "motor_synchronous_speed", "true_motion"]

IMPLICIT = ("Radau", "BDF", "LSODA")
EXPLICIT = ("RK45", "DOP853", "RK23")
#: Right-hand-side calls per step (accepted or rejected) of scipy's explicit Runge–Kutta pairs.
_CALLS_PER_STEP = {"RK45": 6, "DOP853": 12, "RK23": 3}
#: ω below this fraction of ω_m is a stall (the equation in φ needs ω > 0): a terminal event.
_STALL = 1e-4
#: Trial values below this fraction of ω_m (a step the solver will reject) are evaluated there.
_FLOOR = 1e-7
#: Hermite grid intervals per crank turn: the cubic's error ~h⁴/384·max|f⁗| stays ~1e-14 of Jп.
_GRID_PER_TURN = 4096
#: The shortest stopping time taken as a number, s (below it J·ω0/M has lost its digits).
T_STOP_MIN = 1e-290


class TrueMotionError(GraphmechError, ValueError):
    """The true motion cannot be found: the machine stalls, never becomes periodic, or an
    explicit solver would need absurdly many steps."""


class _Budget(Exception):
    pass


@dataclass(frozen=True)
class TrueMotion:
    """The periodic steady motion found by integrating the equation of motion.

    Parameters
    ----------
    omega_max, omega_min : float
        Extreme speeds over the periodic cycle, rad/s (from dense output, refined by a short
        re-integration to the extreme's φ).
    phi_omega_max, phi_omega_min : float
        Where they are reached, rad from position 1.
    delta : float
        (ω_max − ω_min)/ω_m.
    omega0 : float
        ω at φ = 0 of the periodic cycle, rad/s.
    omega_time_mean : float
        Φ/T_cycle, rad/s.
    omega_phi_mean : float
        (1/Φ)∫ω dφ, rad/s.
    period : float
        T_cycle, s.
    cycles : int
        Whole cycles integrated (root-finding on ω0 for the constant moment, iterations of the
        cycle map for the motor).
    steps : int
        Accepted steps in the last (periodic) cycle.
    nfev, njev : int
        Right-hand-side and Jacobian evaluations, all cycles.
    solver : str
        The scipy method.
    rtol, atol : float
        The tolerances (atol: that of ω, rad/s).
    omega_s : float or None
        The motor's synchronous speed, rad/s (None: constant driving moment).
    J_F : float
        The flywheel, kg·m².
    """

    omega_max: float
    omega_min: float
    phi_omega_max: float
    phi_omega_min: float
    delta: float
    omega0: float
    omega_time_mean: float
    omega_phi_mean: float
    period: float
    cycles: int
    steps: int
    nfev: int
    njev: int
    solver: str
    rtol: float
    atol: float
    omega_s: float | None
    J_F: float


@dataclass(frozen=True)
class Run:
    """One integration over an interval of φ.

    Parameters
    ----------
    omega : float
        ω at the end, rad/s.
    time : float
        Time taken, s.
    steps : int
        Accepted steps.
    nfev, njev : int
        Evaluations.
    """

    omega: float
    time: float
    steps: int
    nfev: int
    njev: int


@dataclass(frozen=True)
class Braking:
    """The time to stop a rotor of inertia J from ω0 by a constant braking moment.

    Parameters
    ----------
    t : float
        Closed form ``J·ω0/M``, s.
    t_numeric : float
        ``solve_ivp`` of ``J·dω/dt = −M`` with a terminal event at ω = 0, s: the closed form's
        cross-check, integrated when first asked for (the check needs ``t`` alone).
    """

    t: float

    @cached_property
    def t_numeric(self) -> float:
        from scipy.integrate import solve_ivp

        def stopped(tau: float, y: np.ndarray) -> float:
            return float(y[0])

        # solve_ivp reads an event's options off the function itself (untyped scipy)
        stopped.terminal = True  # type: ignore[attr-defined]
        stopped.direction = -1  # type: ignore[attr-defined]
        # In units of ω0 and of J·ω0/M the run-down is dω/dτ = −1 from 1: the solver (and its event
        # search, whose tolerances are absolute) then sees numbers of order one whatever J, ω0, M are.
        sol = solve_ivp(lambda tau, y: [-1.0], (0.0, 10.0), [1.0], events=stopped, rtol=1e-12, atol=1e-12)
        return self.t * float(sol.t_events[0][0])


# --------------------------------------------------------------------------------------------
# The tabulated model


@dataclass(frozen=True)
class _Piece:
    lo: float
    hi: float
    f: Callable[[float, np.ndarray], list[float]]
    jac: Callable[[float, np.ndarray], np.ndarray]


def motor_synchronous_speed(machine: Machine, exact: ExactMachine, J_F: float) -> float:
    """ω_s of ``machine.motor`` (rad/s): given, or from its stiffness ratio r as
    ``ω_m + M0/(r·ω_m·(J_F + max Jп))``.

    Raises
    ------
    TrueMotionError
        If the motor is not set, is set both ways or neither, ω_s ≤ ω_m, or the balancing moment
        is not driving.
    """
    mo = machine.motor
    if mo is None:
        raise TrueMotionError("the machine has no motor")
    if machine.balance != "driving":
        raise TrueMotionError("a motor drives: machine.balance must be 'driving'")
    if (mo.synchronous is None) == (mo.stiffness is None):
        raise TrueMotionError("give the motor either its synchronous speed or its stiffness")
    m0 = exact.balancing_moment()
    wm = machine.omega_m
    if mo.synchronous is not None:
        ws = float(mo.synchronous)
    else:
        r = float(mo.stiffness or 0.0)
        if not r > 0:
            raise TrueMotionError("the motor's stiffness must be > 0")
        ws = wm + m0 / (r * wm * (J_F + exact.inertia_extremes().maximum))
    if not ws > wm:
        raise TrueMotionError(f"the synchronous speed ω_s = {ws:.9g} rad/s must exceed "
                              f"ω_m = {wm:.9g} rad/s")
    return ws


class _Model:
    """Hermite tables of J, s, ds/dφ, ω_link/ω1 and one right-hand side per break-free piece."""

    def __init__(self, machine: Machine, exact: ExactMachine, J_F: float,
                 drive: tuple[float, float]) -> None:
        self.cycle = cyc = exact.cycle
        n = max(64, math.ceil(_GRID_PER_TURN * cyc / (2.0 * math.pi)))
        h = cyc / n
        grid = np.linspace(0.0, cyc, n + 1)
        jv = exact.inertia(grid) + J_F
        if not float(jv.min()) > 0.0:
            raise TrueMotionError(f"J_F + Jп must be > 0 (J_F = {J_F:.6g} kg·m²)")
        tables: dict[str, tuple[list[float], list[float]]] = {
            "J": (jv.tolist(), (exact.inertia_slope(grid) * h).tolist())}
        for k, ld in enumerate(machine.loads):
            if isinstance(ld, SliderLoad):
                s, ds, dds = exact.slider_travel(k, grid)
                tables[f"s{k}"] = (s.tolist(), (ds * h).tolist())
                tables[f"ds{k}"] = (ds.tolist(), (dds * h).tolist())
            elif isinstance(ld, LinkMoment) and f"r{ld.link}" not in tables:
                r, dr = exact.link_ratio(ld.link, grid)
                tables[f"r{ld.link}"] = (r.tolist(), (dr * h).tolist())
        self.n, self.h, self.tables = n, h, tables
        self.drive = drive  # M_drive = A − C·ω
        self.floor = _FLOOR * machine.omega_m
        stall = _STALL * machine.omega_m

        def stalled(phi: float, y: np.ndarray) -> float:
            return float(y[0]) - stall

        # scipy's solve_ivp reads an event's options off the function itself (untyped scipy)
        stalled.terminal = True  # type: ignore[attr-defined]
        stalled.direction = -1  # type: ignore[attr-defined]
        self.stalled = stalled
        edges = [0.0, *[b for b in exact.breaks() if b > 0.0], cyc]
        self.pieces = [self._piece(machine, exact, a, b) for a, b in pairwise(edges)]
        self.calls = 0
        self.call_limit = math.inf

    def _piece(self, machine: Machine, exact: ExactMachine, lo: float, hi: float) -> _Piece:
        mid = 0.5 * (lo + hi)
        c0 = c1 = 0.0
        sliders: list[tuple[float, float, list[float], list[float], list[float], list[float]]] = []
        links: list[tuple[float, float, list[float], list[float]]] = []
        for k, ld in enumerate(machine.loads):
            if isinstance(ld, CrankMoment):
                a, b = table_line(ld.table, mid)
                c0, c1 = c0 + a, c1 + b
            elif isinstance(ld, LinkMoment):
                a, b = table_line(ld.table, mid)
                links.append((a, b, *self.tables[f"r{ld.link}"]))
            else:
                st = exact.strokes[k]
                assert st is not None
                s, ds, _ = exact.slider_travel(k, np.array([mid]))
                v = float(ds[0])
                if not {"forward": v > 0, "backward": v < 0, "both": True}[ld.during]:
                    continue
                # this segment of the diagram over the whole piece: F = a + b·(s/H), exactly
                a, b = table_line(ld.table, float(s[0]) / st.H)
                sliders.append((ld.sense * a, ld.sense * b / st.H, *self.tables[f"s{k}"],
                                *self.tables[f"ds{k}"]))
        return _Piece(lo, hi, *self._functions(c0, c1, tuple(sliders), tuple(links)))

    def _functions(self, c0: float, c1: float,
                   sliders: tuple[tuple[float, float, list[float], list[float], list[float], list[float]], ...],
                   links: tuple[tuple[float, float, list[float], list[float]], ...]
                   ) -> tuple[Callable[[float, np.ndarray], list[float]],
                              Callable[[float, np.ndarray], np.ndarray]]:
        """f and its Jacobian for one piece, with every constant bound as a local (speed)."""
        n, inv_h = self.n, 1.0 / self.h
        jv, jd = self.tables["J"]
        a_drv, c_drv = self.drive
        last = n - 1

        def state(phi: float, w: float) -> tuple[float, float, float]:
            x = phi * inv_h
            i = int(x)
            if i > last:
                i = last
            elif i < 0:
                i = 0
            t = x - i
            t2 = t * t
            t3 = t2 * t
            h00 = 2.0 * t3 - 3.0 * t2 + 1.0
            h10 = t3 - 2.0 * t2 + t
            h01 = 1.0 - h00
            h11 = t3 - t2
            j0, j1, d0, d1 = jv[i], jv[i + 1], jd[i], jd[i + 1]
            J = h00 * j0 + h10 * d0 + h01 * j1 + h11 * d1
            dJ = ((6.0 * t2 - 6.0 * t) * (j0 - j1) + (3.0 * t2 - 4.0 * t + 1.0) * d0
                  + (3.0 * t2 - 2.0 * t) * d1) * inv_h
            M = a_drv - c_drv * w + c0 + c1 * phi
            for a, b, sv, sd, dv, dd in sliders:
                s = h00 * sv[i] + h10 * sd[i] + h01 * sv[i + 1] + h11 * sd[i + 1]
                ds = h00 * dv[i] + h10 * dd[i] + h01 * dv[i + 1] + h11 * dd[i + 1]
                M += (a + b * s) * ds
            for a, b, rv, rd in links:
                M += (a + b * phi) * (h00 * rv[i] + h10 * rd[i] + h01 * rv[i + 1] + h11 * rd[i + 1])
            return J, dJ, M

        floor = self.floor

        def f(phi: float, y: np.ndarray) -> list[float]:
            w = y.item(0)
            w = max(w, floor)  # a trial value of a step the solver will reject; a stall is an event
            J, dJ, M = state(phi, w)
            return [(M - 0.5 * dJ * w * w) / (J * w), 1.0 / w, w]

        def jac(phi: float, y: np.ndarray) -> np.ndarray:
            w = y.item(0)
            w = max(w, floor)
            J, dJ, M = state(phi, w)
            # ∂/∂ω of (M − ½J′ω²)/(Jω): the stiff entry, −C/(Jω) for a steep motor.
            dfw = -c_drv / (J * w) - M / (J * w * w) - 0.5 * dJ / J
            return np.array([[dfw, 0.0, 0.0], [-1.0 / (w * w), 0.0, 0.0], [1.0, 0.0, 0.0]])

        return f, jac

    def counted(self, f: Callable[[float, np.ndarray], list[float]]
                ) -> Callable[[float, np.ndarray], list[float]]:
        """f that raises _Budget once the explicit solver's call budget is spent."""
        def g(phi: float, y: np.ndarray) -> list[float]:
            self.calls += 1
            if self.calls > self.call_limit:
                raise _Budget
            return f(phi, y)
        return g


# --------------------------------------------------------------------------------------------
# Running pieces and cycles


@dataclass
class _Segment:
    sol: Any  # scipy OdeResult of one piece
    piece: _Piece


@dataclass
class _Cycle:
    w0: float
    w_end: float
    time: float
    q: float
    steps: int
    nfev: int
    njev: int
    segments: list[_Segment]


class _Integrator:
    def __init__(self, model: _Model, solver: str, rtol: float, atol: float, max_steps: int,
                 omega_m: float) -> None:
        if solver not in IMPLICIT + EXPLICIT:
            raise OutOfDomain(f"solver must be one of {IMPLICIT + EXPLICIT}, got {solver!r}")
        self.model, self.solver, self.rtol = model, solver, rtol
        # One atol for ω, t and q: t (~Φ/ω_m) then has an accuracy like ω's. A much tighter one
        # for t, however scaled, keeps LSODA in Adams mode on the stiff case (stability-limited
        # steps, 1e5 per cycle): its stiffness test weighs t's error too.
        self.atol = atol
        self.explicit = solver in EXPLICIT
        self.max_steps = max_steps
        if self.explicit:
            model.call_limit = max_steps * _CALLS_PER_STEP[solver] + 10
        self.nfev = self.njev = 0

    def _solve(self, piece: _Piece, lo: float, hi: float, y0: list[float], dense: bool,
               first_step: float | None = None) -> Any:
        kw: dict[str, Any] = {"method": self.solver, "rtol": self.rtol, "atol": self.atol,
                              "dense_output": dense, "events": self.model.stalled}
        if first_step is not None and self.solver != "LSODA":  # LSODA restarts as Adams: unstable
            kw["first_step"] = first_step
        if self.explicit:
            fun = self.model.counted(piece.f)
        else:
            fun = piece.f
            kw["jac"] = piece.jac
        from scipy.integrate import solve_ivp

        try:
            sol = solve_ivp(fun, (lo, hi), y0, **kw)
        except _Budget:
            raise TrueMotionError(f"explicit solver {self.solver} exceeded {self.max_steps} steps: "
                                  "the equation is stiff, use Radau/BDF/LSODA") from None
        self.nfev += sol.nfev
        self.njev += sol.njev
        if sol.status == 1:
            raise TrueMotionError(f"the machine stalls (ω → 0) near φ = {math.degrees(sol.t[-1]):.4g}°: "
                                  "the driving moment cannot carry the load")
        if sol.status != 0:
            w = float(sol.y[0, -1])
            raise TrueMotionError(f"{self.solver} failed at φ = {math.degrees(sol.t[-1]):.6g}° "
                                  f"(ω = {w:.6g} rad/s): {sol.message}")
        return sol

    def run(self, lo: float, hi: float, w0: float, dense: bool) -> _Cycle:
        """Integrate φ = lo … hi (within one cycle), one solve per break-free piece."""
        w, time_, q, steps = w0, 0.0, 0.0, 0
        nfev0, njev0 = self.nfev, self.njev
        segs = []
        for p in self.model.pieces:
            a, b = max(lo, p.lo), min(hi, p.hi)
            if b <= a:
                continue
            sol = self._solve(p, a, b, [w, 0.0, 0.0], dense)
            w = float(sol.y[0, -1])
            time_ += float(sol.y[1, -1])
            q += float(sol.y[2, -1])
            steps += sol.t.size - 1
            segs.append(_Segment(sol, p))
        return _Cycle(w0, w, time_, q, steps, self.nfev - nfev0, self.njev - njev0, segs)

    def cycle(self, w0: float) -> _Cycle:
        return self.run(0.0, self.model.cycle, w0, dense=True)

    def extremes(self, cy: _Cycle) -> tuple[float, float, float, float]:
        """(ω_max, φ, ω_min, φ) over a cycle: step points, then the dense output's extreme
        near the best ones, its value re-integrated from the step point before it."""
        phis, ws, owner = [], [], []
        for k, sg in enumerate(cy.segments):
            start = 0 if k == 0 else 1  # a piece starts where the last one ended
            phis += sg.sol.t[start:].tolist()
            ws += sg.sol.y[0, start:].tolist()
            owner += [k] * (sg.sol.t.size - start)
        w = np.array(ws)
        margin = float(np.abs(np.diff(w)).max()) if w.size > 1 else 0.0
        return (*self._best(cy, phis, w, owner, margin, +1.0),
                *self._best(cy, phis, w, owner, margin, -1.0))

    def _best(self, cy: _Cycle, phis: list[float], w: np.ndarray, owner: list[int],
              margin: float, sign: float) -> tuple[float, float]:
        v = sign * w
        top = float(v.max())
        left = np.concatenate(([-np.inf], v[:-1]))
        right = np.concatenate((v[1:], [-np.inf]))
        cand = np.flatnonzero((v >= left) & (v >= right) & (v >= top - margin))
        cand = cand[np.argsort(-v[cand])][:8]
        best_v, best_phi = top, phis[int(np.argmax(v))]
        for i in cand:
            for lo_i in (i - 1, i):  # the step interval on either side of the step point
                hi_i = lo_i + 1
                if lo_i < 0 or hi_i >= len(phis):
                    continue
                seg = cy.segments[owner[hi_i]]
                a, b = phis[lo_i], phis[hi_i]
                dense = seg.sol.sol  # the piece's dense output, searched here and now
                x, _ = fminbound(lambda x: -sign * float(dense(x)[0]), a, b, xatol=1e-12 * max(1.0, b))
                if x - a <= 1e-12 or b - x <= 1e-12:
                    continue  # the extreme of this interval is at a step point: known exactly
                # the value from a short run at the solver's full order (dense output is lower)
                k = int(np.searchsorted(seg.sol.t, a))  # a is a step point of this piece
                short = self._solve(seg.piece, a, x, [float(seg.sol.y[0, k]), 0.0, 0.0],
                                    dense=False, first_step=x - a)
                val = sign * float(short.y[0, -1])
                if val > best_v:
                    best_v, best_phi = val, x
        return sign * best_v, best_phi


def _tolerances(machine: Machine, rtol: float, atol: float | None) -> tuple[float, float]:
    if not (0 < rtol < 1):
        raise OutOfDomain(f"rtol must lie in (0, 1), got {rtol}")
    a = 1e-3 * rtol * machine.omega_m if atol is None else float(atol)
    if not a > 0:
        raise OutOfDomain(f"atol must be > 0, got {atol}")
    return rtol, a


def _drive(machine: Machine, exact: ExactMachine, J_F: float) -> tuple[tuple[float, float],
                                                                       float | None]:
    """(A, C) of ``M_drive = A − C·ω`` and ω_s (None for the constant moment)."""
    mb = exact.balancing_moment()
    if machine.motor is None:
        return (mb, 0.0), None
    ws = motor_synchronous_speed(machine, exact, J_F)
    c = mb / (ws - machine.omega_m)
    return (c * ws, c), ws


def _stepping_model(machine: Machine, exact: ExactMachine, J_F: float) -> _Model:
    """The equation of motion :func:`integrate` steps through: built once per exact machine and
    flywheel (a drawn true motion is stepped a stretch at a time, ~150 calls, each of which would
    otherwise tabulate Jп and find ω_s anew), its explicit solver's call count started afresh.
    :func:`true_motion` builds its own each time (the bench times it whole)."""
    if machine is not exact.machine:
        return _Model(machine, exact, J_F, _drive(machine, exact, J_F)[0])
    models: dict[float, _Model] = exact.__dict__.setdefault("_stepping_models", {})
    model = models.get(J_F)
    if model is None:
        model = models[J_F] = _Model(machine, exact, J_F, _drive(machine, exact, J_F)[0])
    model.calls, model.call_limit = 0, math.inf
    return model


def integrate(machine: Machine, exact: ExactMachine, J_F: float, phi_span: tuple[float, float],
              omega0: float, *, solver: str = "Radau", rtol: float = 1e-10,
              atol: float | None = None, max_steps: int = 2_000_000) -> Run:
    """Integrate the equation of motion over ``phi_span`` (within [0, Φ]) from ω = omega0.

    For counting an explicit solver's steps over a part of the cycle (extrapolated to a cycle),
    or stepping to a φ from the periodic ω0.

    Parameters
    ----------
    machine, exact, J_F
        As for :func:`true_motion`.
    phi_span : (float, float)
        φ from … to, rad, ``0 ≤ φ_a < φ_b ≤ Φ``.
    omega0 : float
        ω at φ_a, rad/s.

    Returns
    -------
    Run
    """
    rtol, a = _tolerances(machine, rtol, atol)
    model = _stepping_model(machine, exact, J_F)
    lo, hi = float(phi_span[0]), float(phi_span[1])
    if not 0.0 <= lo < hi <= exact.cycle:
        raise OutOfDomain(f"phi_span must lie within [0, Φ] with φ_a < φ_b, got {phi_span}")
    ig = _Integrator(model, solver, rtol, a, max_steps, machine.omega_m)
    cy = ig.run(lo, hi, float(omega0), dense=False)
    return Run(cy.w_end, cy.time, cy.steps, cy.nfev, cy.njev)


def true_motion(machine: Machine, exact: ExactMachine, J_F: float, *, solver: str = "Radau",
                rtol: float = 1e-10, atol: float | None = None, max_cycles: int = 50,
                max_steps: int = 2_000_000) -> TrueMotion:
    """The periodic steady motion of the machine with flywheel J_F, by ``solve_ivp``.

    Parameters
    ----------
    machine : Machine
        The machine; ``machine.motor`` None: constant driving moment M_b (then every ω0 gives a
        periodic motion and ω0 is chosen, by Newton's method on whole cycles, so that
        (ω_max + ω_min)/2 = ω_m); a Motor: its straight characteristic with M0 = M_b, and the
        cycle map ω(0) → ω(Φ) is iterated (secant) until ``|ω(Φ) − ω(0)| < rtol·ω_m``.
    exact : ExactMachine
        The same machine's exact reduction (built once, shared).
    J_F : float
        The flywheel, kg·m².
    solver : str
        ``"Radau"``, ``"BDF"``, ``"LSODA"`` (implicit, analytic Jacobian) or ``"RK45"``,
        ``"DOP853"``, ``"RK23"`` (explicit, for comparison).
    rtol, atol : float
        Tolerances; ``atol`` is that of ω, rad/s (default ``1e-3·rtol·ω_m``: rtol governs).
    max_cycles : int
        Whole cycles allowed to reach the periodic motion.
    max_steps : int
        Step budget of an explicit solver (all cycles).

    Returns
    -------
    TrueMotion

    Raises
    ------
    TrueMotionError (a ValueError)
        The machine stalls (ω ≤ 0), the motion is not periodic within ``max_cycles``, or an
        explicit solver exceeds ``max_steps``.

    Notes
    -----
    Newton's derivative for the constant moment comes from the energy equation:
    ``J(φ)·ω(φ)² = J(0)·ω0² + 2ΔT(φ)`` gives ``∂ω(φ)/∂ω0 = J(0)·ω0/(J(φ)·ω(φ))``.

    Examples
    --------
    A rotor of 2 kg·m² with the IC engine's torque of ``fly.ic_engine_flywheel``:

    >>> from graphmech.mechanisms.machine import CrankMoment, Machine, Table
    >>> md = Table(tuple(np.radians([0.0, 20.0, 50.0, 180.0])), (0.0, 200.0, 200.0, 0.0))
    >>> mc = Machine(None, 0.0, math.pi, 620 * math.pi / 30, 0.01, loads=(CrankMoment(md),),
    ...              inertia=2.0, balance="resisting")
    >>> ex = ExactMachine(mc)
    >>> tm = true_motion(mc, ex, 0.0)
    >>> abs(tm.delta / ex.energy_motion(0.0).delta - 1.0) < 1e-8
    True
    """
    rtol, a = _tolerances(machine, rtol, atol)
    if max_cycles < 1:
        raise OutOfDomain("max_cycles must be ≥ 1")
    drive, ws = _drive(machine, exact, J_F)
    model = _Model(machine, exact, J_F, drive)
    ig = _Integrator(model, solver, rtol, a, max_steps, machine.omega_m)
    wm = machine.omega_m
    tol = rtol * wm
    j_at = _hermite_j(model)
    cycles = 0
    w0 = wm
    if ws is None:
        best: tuple[float, _Cycle, tuple[float, float, float, float]] | None = None
        prev = math.inf
        while True:
            cy = ig.cycle(w0)
            cycles += 1
            ext = ig.extremes(cy)
            err = 0.5 * (ext[0] + ext[2]) - wm
            if best is None or abs(err) < abs(best[0]):
                best = (err, cy, ext)
            if abs(err) <= tol or (cycles > 2 and abs(err) > 0.5 * prev and abs(err) < 1e3 * tol):
                break  # converged, or Newton stalls at the integration's noise
            if cycles >= max_cycles:
                raise TrueMotionError(f"the mean speed is not ω_m within {max_cycles} cycles "
                                      f"(off by {err:.3g} rad/s)")
            slope = 0.5 * j_at(0.0) * w0 * (1.0 / (j_at(ext[1]) * ext[0]) + 1.0 / (j_at(ext[3]) * ext[2]))
            prev = abs(err)
            w0 -= err / slope
        _, cy, ext = best
    else:
        hist: list[tuple[float, float]] = []
        while True:
            cy = ig.cycle(w0)
            cycles += 1
            g = cy.w_end - w0
            if abs(g) <= tol and cycles >= 2:  # the first cycle starts from a guess
                break
            if cycles >= max_cycles:
                raise TrueMotionError(f"the motion is not periodic within {max_cycles} cycles "
                                      f"(|ω(Φ) − ω(0)| = {abs(g):.3g} rad/s)")
            if hist and g != hist[-1][1]:  # secant on g(ω0) = ω(Φ) − ω0
                w_prev, g_prev = hist[-1]
                w_new = w0 - g * (w0 - w_prev) / (g - g_prev)
            else:
                w_new = cy.w_end  # the cycle map itself: contracting
            hist.append((w0, g))
            w0 = w_new
        ext = ig.extremes(cy)
    w_hi, p_hi, w_lo, p_lo = ext
    return TrueMotion(omega_max=w_hi, omega_min=w_lo, phi_omega_max=p_hi, phi_omega_min=p_lo,
                      delta=(w_hi - w_lo) / wm, omega0=cy.w0, omega_time_mean=model.cycle / cy.time,
                      omega_phi_mean=cy.q / model.cycle, period=cy.time, cycles=cycles,
                      steps=cy.steps, nfev=ig.nfev, njev=ig.njev, solver=solver, rtol=rtol, atol=a,
                      omega_s=ws, J_F=J_F)


def _hermite_j(model: _Model) -> Callable[[float], float]:
    """J(φ) from the model's own Hermite table (for Newton's slope)."""
    jv, jd = model.tables["J"]
    n, inv_h = model.n, 1.0 / model.h

    def j(phi: float) -> float:
        x = phi * inv_h
        i = min(max(int(x), 0), n - 1)
        t = x - i
        t2, t3 = t * t, t * t * t
        return ((2 * t3 - 3 * t2 + 1) * jv[i] + (t3 - 2 * t2 + t) * jd[i]
                + (3 * t2 - 2 * t3) * jv[i + 1] + (t3 - t2) * jd[i + 1])

    return j


def braking_time(J: float, omega0: float, M_brake: float) -> Braking:
    """Stopping time of a rotor J (kg·m²) at ω0 (rad/s) under a constant brake M (N·m).

    Examples
    --------
    ``fly.brake_time``: J = 0.5 kg·m², ω = 100 rad/s, M = 20 N·m.

    >>> b = braking_time(0.5, 100.0, 20.0)
    >>> b.t, round(b.t_numeric, 12)
    (2.5, 2.5)
    """
    if not (J > 0 and omega0 > 0 and M_brake > 0):
        raise OutOfDomain("J, ω0 and the braking moment must all be > 0")
    t = J * omega0 / M_brake
    if not (math.isfinite(t) and t >= T_STOP_MIN):
        raise OutOfDomain(f"the stopping time J·ω0/M = {J:.6g}·{omega0:.6g}/{M_brake:.6g} s is out of range")
    return Braking(t)
