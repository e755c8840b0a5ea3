"""Reduction to the crank from the velocity polygons: Jп and Mп at the course-project positions.

The book's table (e.g. Table 3 of the Russian course project): at each position the velocity
polygon is drawn, the segments ``ps`` to the images of the centres of mass and ``bc`` of the
links are measured, and

    Jп = J_const + Σ (m·v_S² + J_S·ω²)/ω1²,     v_S = |ps|·μv,   ω = |bc|·μv/l_BC,
    Mп = Σ F·v·cos(F, v)/ω1 + Σ M·ω/ω1           (signed by power: positive drives).

Here the polygons are the exact constructions of :mod:`graphmech.methods.polygons`, evaluated
at all positions at once; every velocity is a drawn segment times μv. The slider's stroke, which
an indicator diagram is drawn against, is found on the drawn mechanism: the slider's two
extreme positions (where its image in the velocity polygon reaches the pole).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import cast

import numpy as np

from graphmech.construction.graph import Plan
from graphmech.errors import DegenerateConstruction
from graphmech.mechanisms.linkage import Crank
from graphmech.mechanisms.machine import CrankMoment, LinkMoment, Machine, SliderLoad, Table
from graphmech.methods.polygons import LinkageConstruction, build_polygons
from graphmech.methods.velocity import POLE
from graphmech.minimum import fminbound

#: Coarse positions over a turn on which a slider's extreme positions are bracketed.
STROKE_SAMPLES = 720


@dataclass(frozen=True)
class Reduction:
    """Jп and Mп at the positions, each from drawn segments.

    Attributes
    ----------
    phi : ndarray (N,)
        Positions, rad from position 1.
    J : ndarray (N,)
        Reduced moment of inertia Jп, kg·m².
    M : ndarray (N,)
        Reduced moment of the loads Mп, N·m, signed by power.
    valid : ndarray of bool (N,)
        False where the mechanism cannot be drawn (reason in ``reasons``).
    reasons : tuple of str
    strokes : dict
        Slider point → (s_min, s_max) along its axis, m (from the drawn extreme positions).
    on_steps : tuple of (int, int)
        (load index, position index), 0-based, where a step of the load's table fell on the
        position: Mп there takes the mean of both sides.
    """

    phi: np.ndarray
    J: np.ndarray
    M: np.ndarray
    valid: np.ndarray
    reasons: tuple[str, ...]
    strokes: dict[str, tuple[float, float]]
    on_steps: tuple[tuple[int, int], ...] = ()


def table_at(table: Table, x: np.ndarray, period: float | None = None) -> np.ndarray:
    """A piecewise-linear table at x (a repeated node is a step: at the step, the mean of both
    sides — :meth:`Table.mean_at_steps`; ``period``: the table repeats every Φ)."""
    return _table_at(table, x, period)[0]


def _table_at(table: Table, x: np.ndarray, period: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The table at x and where x fell on a step (``period``: the table repeats every Φ)."""
    xs, ys = np.asarray(table.x, float), np.asarray(table.y, float)
    return table.mean_at_steps(x, np.interp(x, xs, ys), period)


def _axis_of(b: LinkageConstruction, point: str, load: SliderLoad) -> tuple[float, float]:
    return (math.cos(load.axis), math.sin(load.axis))


def _projection(b: LinkageConstruction, plan: Plan, point: str, u: tuple[float, float],
                theta: np.ndarray) -> np.ndarray:
    batch = plan.evaluate_batch({b.param: theta})
    x, y = batch[b.mech[point]]
    return (np.asarray(x) * u[0] + np.asarray(y) * u[1]) * b.mu_l


def slider_stroke(b: LinkageConstruction, machine: Machine, point: str,
                  u: tuple[float, float]) -> tuple[float, float]:
    """The slider's extreme positions along u, m (relative to the drawing's origin).

    The mechanism is drawn at :data:`STROKE_SAMPLES` crank angles; each extreme is then pinned
    down by Brent's method on the drawn position (flat at the extreme, so its value is found to
    rounding).
    """
    plan = b.g.prune([b.mech[point]])
    start = machine.crank_angle(0.0)
    theta = start + np.linspace(0.0, 2.0 * math.pi, STROKE_SAMPLES, endpoint=False)
    s = _projection(b, plan, point, u, theta)
    h = 2.0 * math.pi / STROKE_SAMPLES
    out = []
    for sign in (1.0, -1.0):  # minimum, then maximum
        i = int(np.argmin(sign * s))

        def f(t: float) -> float:
            return float(sign * _projection(b, plan, point, u, np.array([t]))[0])

        _, least = fminbound(f, theta[i] - h, theta[i] + h, xatol=1e-12)  # scipy's bounded search, written out
        out.append(min(sign * least, sign * float(s[i]), key=lambda v: sign * v))
    return out[0], out[1]


def reduce_to_crank(machine: Machine, phi: np.ndarray, scales: dict[str, float]) -> Reduction:
    """Jп(φ_k) and Mп(φ_k) from the velocity polygons at the positions ``phi``.

    Parameters
    ----------
    machine : Machine
        With or without a linkage (without one, Jп is the constant ``machine.inertia`` and only
        crank moments load it).
    phi : ndarray (N,)
        Positions, rad from position 1.
    scales : dict
        μl and μv of the polygons (``"l"``, ``"v"``).

    Examples
    --------
    A machine without a linkage: an engine's torque curve on a flywheel of 2 kg·m². The curve
    repeats every half turn, so at φ = 0 it jumps from 0 back to 100 N·m: position 1 takes the
    mean of both sides.

    >>> import math
    >>> from graphmech.mechanisms.machine import CrankMoment, Machine, Table
    >>> m = Machine(None, 0.0, math.pi, 65.0, 0.01, inertia=2.0,
    ...             loads=(CrankMoment(Table((0.0, math.pi), (100.0, 0.0))),))
    >>> r = reduce_to_crank(m, np.array([0.0, math.pi / 2]), {})
    >>> r.J.tolist(), r.M.tolist()
    ([2.0, 2.0], [50.0, 50.0])
    """
    phi = np.asarray(phi, dtype=float)
    n = phi.shape[0]
    J = np.full(n, float(machine.inertia))
    M = np.zeros(n)
    valid = np.ones(n, dtype=bool)
    reasons = [""] * n
    strokes: dict[str, tuple[float, float]] = {}
    on_steps: list[tuple[int, int]] = []  # (load, position) where a table's step fell on a position

    def sample(k: int, table: Table, x: np.ndarray, where: np.ndarray | None = None,
               period: float | None = None) -> np.ndarray:
        values, hit = _table_at(table, x, period)
        if where is not None:
            hit &= where
        on_steps.extend((k, int(i)) for i in np.flatnonzero(hit))
        return values

    if machine.inertia_table is not None:  # Jп read off its table at the positions
        J += table_at(machine.inertia_table, np.mod(phi, machine.cycle))
    for k, load in enumerate(machine.loads):
        if isinstance(load, CrankMoment):
            M += sample(k, load.table, np.mod(phi, machine.cycle), period=machine.cycle)
    link = machine.linkage
    if link is None:
        return Reduction(phi, J, M, valid, tuple(reasons), strokes, tuple(sorted(on_steps)))

    b = build_polygons(link, {"l": scales["l"], "v": scales["v"], "a": scales.get("a", 1.0)})
    w1 = abs(cast(Crank, link.driver).omega)  # a machine's linkage is driven by a crank
    mv = b.scales["v"]
    targets = [POLE]
    for mass in machine.masses:
        targets.append(b.vel[mass.point])
        if mass.inertia:
            targets.append(b.omega[mass.link])
    for load in machine.loads:
        if isinstance(load, SliderLoad):
            targets += [b.vel[load.point], b.mech[load.point]]
        elif isinstance(load, LinkMoment):
            targets.append(b.omega[load.link])
    plan = b.g.prune(targets)
    theta = np.array([machine.crank_angle(float(f)) for f in phi])
    batch = plan.evaluate_batch({b.param: theta})
    for step, (mask, why) in batch.failures.items():
        for i in np.flatnonzero(mask):
            reasons[i] = reasons[i] or f"{step}: {why}"
    valid = np.asarray(batch.valid, dtype=bool).copy()

    def image(point: str) -> tuple[np.ndarray, np.ndarray]:
        """The velocity of a point, m/s: its segment p→image in the polygon times μv."""
        x, y = batch[b.vel[point]]
        return (np.broadcast_to(x, (n,)) * mv, np.broadcast_to(y, (n,)) * mv)

    def rate(link_id: str) -> np.ndarray:
        drawn, scale = batch[b.omega[link_id]]
        return np.broadcast_to(np.asarray(drawn) * scale, (n,))

    for mass in machine.masses:
        vx, vy = image(mass.point)
        J = J + mass.mass * (vx * vx + vy * vy) / (w1 * w1)
        if mass.inertia:
            w = rate(mass.link)
            J = J + mass.inertia * w * w / (w1 * w1)
    for k, load in enumerate(machine.loads):
        if isinstance(load, SliderLoad):
            u = _axis_of(b, load.point, load)
            if load.point not in strokes:
                strokes[load.point] = slider_stroke(b, machine, load.point, u)
            s_min, s_max = strokes[load.point]
            stroke = s_max - s_min
            if not stroke > 0:
                raise DegenerateConstruction(f"the stroke of {load.point}", "the slider does not move")
            x, y = batch[b.mech[load.point]]
            s = (np.asarray(x) * u[0] + np.asarray(y) * u[1]) * b.mu_l - s_min
            vx, vy = image(load.point)
            v = vx * u[0] + vy * u[1]  # along the axis
            on = {"forward": v > 0, "backward": v < 0, "both": np.ones(n, dtype=bool)}[load.during]
            force = load.sense * sample(k, load.table, np.clip(s / stroke, 0.0, 1.0), on & (v != 0.0))
            M = M + np.where(on, force * v, 0.0) / w1
        elif isinstance(load, LinkMoment):
            M = M + sample(k, load.table, np.mod(phi, machine.cycle), period=machine.cycle) * rate(load.link) / w1
    J = np.where(valid, J, 0.0)
    M = np.where(valid, M, 0.0)
    return Reduction(phi, J, M, valid, tuple(reasons), strokes, tuple(sorted(on_steps)))


__all__ = ["Reduction", "reduce_to_crank", "slider_stroke", "table_at"]
