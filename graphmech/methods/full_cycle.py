"""The full cycle: a linkage at N positions of its crank, as a course sheet draws it.

The crank's turn is divided into N equal parts from a stated start (an extreme position of
the output, or the crank's given angle) and numbered 1 … N in the crank's sense. The whole
construction — kinematic diagram, velocity and acceleration polygons — is built once and
evaluated at all N positions in one vectorised pass (``Plan.evaluate_batch``); from it:

* the positions of every point on the kinematic diagram (the mechanism overlaid N times) and
  the paths of chosen points (coupler curves);
* the displacement diagram s–φ of a slider (along its guide, from position 1), the angle
  diagram ψ–φ of a rotating link, or the way of any other point along its path (its chords laid
  end to end, as with dividers), *read off the kinematic diagram* at μs (μψ) and μφ;
* the v–φ (ω–φ) diagram by graphical differentiation of s–φ by chords with the pole distance
  H₁, at μv = μs·ω₁/(μφ·H₁), its values at the middles of the intervals; and the a–φ (ε–φ)
  diagram by differentiating v–φ again with H₂, at μa = μv·ω₁/(μφ·H₂), its values back at the
  positions (the middles of the middles).

The φ axis is a time axis (t = φ/ω₁) only for a crank turning uniformly, so the diagrams need
ε₁ = 0. Nothing here draws; :mod:`graphmech.problems.cycle.figures` does.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Sequence

import numpy as np

from graphmech.construction.graph import BatchSolution
from graphmech.errors import DegenerateConstruction
from graphmech.geometry.kernels import Components
from graphmech.mechanisms.linkage import RPP, RRP, Crank, Guide, Linkage, SliderInput
from graphmech.methods.chords import frozen_array
from graphmech.methods.diagram import offset_bar_lines
from graphmech.methods.graphical_differentiation import Differentiation, differentiate_cycle
from graphmech.methods.polygons import LinkageConstruction, build_polygons

__all__ = ["CycleDiagram", "FullCycle", "cycle_positions", "diagram_subjects", "driver_text", "evaluate_cycle",
           "reversed_driver", "sliders"]

TWO_PI = 2.0 * math.pi


def cycle_positions(start: float, n: int, sense: float) -> np.ndarray:
    """The crank's absolute angles at positions 1 … N (rad), from ``start`` in its sense.

    >>> np.degrees(cycle_positions(math.radians(30.0), 4, -1.0)).round(9).tolist()
    [30.0, 300.0, 210.0, 120.0]
    """
    k = np.arange(n, dtype=float)
    return np.mod(start + sense * k * TWO_PI / n, TWO_PI)


def finer_positions(start: float, n: int, sense: float, m: int, middles: bool) -> np.ndarray:
    """The m·N positions of the same cycle drawn m times finer, placed so that each of the N
    positions is the (m·k)-th of them (``middles``: each middle of the N intervals, where a chord's
    slope is laid off, is the (m·k)-th middle of the finer intervals). How a chord diagram checks itself.

    >>> fine = np.degrees(finer_positions(0.0, 4, 1.0, 2, True))
    >>> ((fine[::2] + fine[1::2]) / 2).round(9).tolist()
    [45.0, 135.0, 225.0, 315.0]
    """
    step = TWO_PI / n
    offset = sense * (step / 2.0 - step / (2.0 * m)) if middles else 0.0
    return cycle_positions(start + offset, m * n, sense)


def sliders(linkage: Linkage) -> dict[str, tuple[float, float]]:
    """Points that slide on a frame guide → the guide's unit direction."""
    out: dict[str, tuple[float, float]] = {}
    d = linkage.driver
    if isinstance(d, SliderInput):
        out[d.point] = d.guide.direction
    for y in linkage.dyads:
        if isinstance(y, (RRP, RPP)) and isinstance(y.guide, Guide):  # a slider on a frame guide
            out[y.c] = y.guide.direction
    return out


def diagram_subjects(linkage: Linkage) -> dict[str, str]:
    """What may have s–φ, v–φ, a–φ diagrams: sliders (``"point"``: along the guide), rotating links
    (``"link"``: their angle), and every other moving point (``"path"``: the distance travelled along
    its path, v its speed, a its tangential acceleration)."""
    out = {name: "point" for name in sliders(linkage)}
    translating = {y.links[1] for y in linkage.dyads if isinstance(y, (RRP, RPP)) and isinstance(y.guide, Guide)}
    for link, pts in linkage.links().items():
        if link not in translating and len(pts) >= 2:
            out[link] = "link"
        for p in pts:
            if p not in out and p not in linkage.frame_points:
                out[p] = "path"
    return out


@dataclass(frozen=True, eq=False)
class CycleDiagram:
    """s–φ, v–φ and a–φ of one slider (or ψ–φ, ω–φ, ε–φ of one link) on the drawing.

    Attributes
    ----------
    subject : str
        The slider's point name (``"C"``) or the link's id (``"3"``).
    kind : str
        ``"point"`` (a slider: m, m/s, m/s² along its guide), ``"link"`` (rad, rad/s, rad/s²) or
        ``"path"`` (a point's distance along its path, its speed, its tangential acceleration).
    x_mm : ndarray, shape (N,)
        The positions on the φ axis, mm (position 1 at 0).
    s_mm : ndarray, shape (N,)
        The displacement (angle) from position 1, read off the kinematic diagram, at ``mu_s``.
    velocity : Differentiation
        s–φ differentiated by chords with H₁ (its ordinates at the middles, at ``mu_v``).
    acceleration : Differentiation
        v–φ differentiated with H₂ (at ``mu_a``); ``a_mm`` holds its ordinates at the positions.
    """

    subject: str
    kind: str
    x_mm: np.ndarray
    s_mm: np.ndarray
    velocity: Differentiation
    acceleration: Differentiation
    mu_s: float
    mu_v: float
    mu_a: float
    rise_mm: float = 0.0  # what s gains over the cycle: a turn of a link, the length of a path

    @property
    def a_mm(self) -> np.ndarray:
        """The a–φ ordinates at positions 1 … N (the second chords' middles are the positions)."""
        return np.roll(self.acceleration.derivative_mm, 1)


@dataclass(frozen=True, eq=False)
class FullCycle:
    """The linkage at N positions, evaluated once.

    Attributes
    ----------
    build : LinkageConstruction
        The construction (kinematic diagram, polygons) at the sheet's μl, μv, μa.
    angles : ndarray, shape (N,)
        The crank's absolute angles at positions 1 … N, rad.
    mech, vel, acc : dict
        Point name → (N, 2) array of its place on the kinematic diagram, its velocity image,
        its acceleration image (mm; velocity and acceleration only when asked for).
    values : dict
        Every evaluated step's values at all positions (for the overlaid polygons).
    diagrams : tuple of CycleDiagram
        The diagrams asked for.
    polygon_failures : dict
        Position index → why its polygon cannot be drawn (a change point), those left out.
    conds : dict
        Intersection step → its condition number at every position (the drawn panels' steps).
    mu_phi : float
        rad/mm of the φ axis (each diagram's pole distances are its ``velocity.H_mm`` and
        ``acceleration.H_mm``).
    """

    build: LinkageConstruction
    plan: object
    angles: np.ndarray
    mech: dict[str, np.ndarray] = field(hash=False)
    vel: dict[str, np.ndarray] = field(hash=False)
    acc: dict[str, np.ndarray] = field(hash=False)
    values: dict[str, object] = field(hash=False)
    diagrams: tuple[CycleDiagram, ...]
    mu_phi: float
    sense: float
    paths: dict[str, np.ndarray] = field(default_factory=dict, hash=False)
    polygon_failures: dict[int, str] = field(default_factory=dict, hash=False)
    conds: dict[str, np.ndarray] = field(default_factory=dict, hash=False)
    backward: np.ndarray | None = field(default=None, hash=False)  # a swing: the positions of the return stroke

    @property
    def swing(self) -> bool:
        """The driver goes out and back (:mod:`graphmech.methods.swing`) instead of turning."""
        return self.backward is not None

    @property
    def n(self) -> int:
        return int(self.angles.size)


def _xy(values: dict[str, Components], step: str, n: int) -> np.ndarray:
    x, y = values[step]
    return frozen_array(np.column_stack([np.broadcast_to(np.asarray(x, dtype=float), (n,)),
                                         np.broadcast_to(np.asarray(y, dtype=float), (n,))]))


def _unwrap_from_first(theta: np.ndarray, sense: float) -> np.ndarray:
    """A link's angle from position 1, continuous over the cycle (rad)."""
    return np.unwrap(theta - theta[0])


def reversed_driver(linkage: Linkage) -> Linkage:
    """The same linkage with its driver's ω (a slider's v) reversed: the return stroke of a swing
    (ε = 0 there, so every velocity changes sign and every acceleration stays)."""
    d = linkage.driver
    rev = replace(d, omega=-d.omega) if isinstance(d, Crank) else replace(d, velocity=-d.velocity)
    return replace(linkage, driver=rev)


def driver_text(d: Crank | SliderInput, q: float) -> str:
    """A driver's position as a message says it: ``φ1 = 30°``, ``s1 = 40 mm``."""
    if isinstance(d, Crank):
        return f"φ{d.link} = {math.degrees(q):.6g}°"
    return f"s{d.link} = {q * 1000:.6g} mm"


def _strokes(fwd: BatchSolution, back: BatchSolution, mask: np.ndarray) -> BatchSolution:
    """One batch of a swing's positions: the first stroke's values, the return stroke's where ``mask``."""

    def pick(f: object, r: object) -> object:
        if isinstance(f, tuple) and isinstance(r, tuple):
            return tuple(pick(x, y) for x, y in zip(f, r))
        if isinstance(f, (float, int, np.ndarray)) and isinstance(r, (float, int, np.ndarray)):
            return np.where(mask, np.broadcast_to(np.asarray(r, dtype=float), mask.shape),
                            np.broadcast_to(np.asarray(f, dtype=float), mask.shape))
        return f

    values = {k: pick(v, back.values.get(k, v)) for k, v in fwd.values.items()}
    conds = {k: np.where(mask, back.conds.get(k, c), c) for k, c in fwd.conds.items()}
    none = np.zeros(mask.shape, dtype=bool)
    failures = {}
    for step in {**fwd.failures, **back.failures}:
        mf, wf = fwd.failures.get(step, (none, ""))
        mb, wb = back.failures.get(step, (none, ""))
        m = (mf & ~mask) | (mb & mask)
        if m.any():
            failures[step] = (m, wf or wb)
    return BatchSolution(values, conds, np.where(mask, back.valid, fwd.valid), failures, fwd.n)


#: A point's path is drawn through at least this many positions (the N among them), so a coupler
#: curve is smooth however few positions the sheet has.
PATH_POSITIONS = 360


def evaluate_cycle(linkage: Linkage, scales: dict[str, float], angles: np.ndarray, *,
                   polygons: Sequence[str] = (), diagrams: Sequence[str] = (), paths: Sequence[str] = (),
                   mu_phi: float, mu_s: dict[str, float] | None = None,
                   H_mm: tuple[float, float] | dict[str, tuple[float, float]] = (30.0, 30.0),
                   backward: np.ndarray | None = None) -> FullCycle:
    """Evaluate the construction at all positions; read off and differentiate the diagrams.

    Parameters
    ----------
    linkage : Linkage
        Crank-driven; ε₁ = 0 when diagrams are asked for.
    scales : dict
        μl, μv, μa of the kinematic diagram and the polygons (SI per mm).
    angles : ndarray, shape (N,)
        The crank's angles at positions 1 … N (:func:`cycle_positions`), N ≥ 3.
    polygons : sequence of str
        ``"velocity"``, ``"acceleration"``: which overlaid polygons to evaluate.
    diagrams : sequence of str
        Slider point names and link ids (:func:`diagram_subjects`).
    mu_phi : float
        rad/mm of the φ axis.
    mu_s : dict
        Per diagram subject, its μs (m/mm) or μψ (rad/mm).
    H_mm : (float, float) or dict
        Pole distances H₁ (s → v) and H₂ (v → a), mm — for every diagram, or per subject.
    paths : sequence of str
        Points whose paths are evaluated at k·N ≥ :data:`PATH_POSITIONS` positions (the N
        among them), for a smooth curve through the N.
    backward : ndarray of bool, shape (N,)
        A swing (:mod:`graphmech.methods.swing`): the positions that leave on the return stroke,
        whose polygons are drawn with the driver's ω (v) reversed; ``angles`` are then the
        driver's positions (φ, or a slider's s), the paths run over the first stroke, and
        no diagrams are drawn (the driver reverses at the ends).

    Raises
    ------
    DegenerateConstruction
        A position cannot be constructed (the crank does not turn fully): one line naming it.
    """
    d = linkage.driver
    assert isinstance(d, Crank) or backward is not None, "a slider drives a swing"
    assert backward is None or not diagrams, "no chord diagrams over a swing"
    n = int(np.asarray(angles).size)
    b = build_polygons(linkage, scales)
    targets = list(b.mech.values())
    for panel in polygons:
        targets += b.steps_of_panel(panel)
    plan = b.g.prune(targets)
    with np.errstate(all="ignore"):
        batch = plan.evaluate_batch({b.param: np.asarray(angles, dtype=float)})
    if backward is not None and polygons and backward.any():  # the return stroke: the same places, ω (v) reversed
        rb = build_polygons(reversed_driver(linkage), scales)
        with np.errstate(all="ignore"):
            back = rb.g.prune(targets).evaluate_batch({rb.param: np.asarray(angles, dtype=float)})
        batch = _strokes(batch, back, np.asarray(backward, dtype=bool))
    # A position the mechanism cannot take ends the cycle; a polygon that cannot be drawn at a
    # position (a change point: two of its lines parallel) only leaves that polygon out.
    panel_of = {st.text: st.panel for st in plan.steps}
    polygon_failures: dict[int, str] = {}
    i: int | np.intp
    for step, (mask, why) in batch.failures.items():
        for i in np.flatnonzero(mask):
            i = int(i)
            if panel_of.get(step) == "mechanism" or why.startswith("cannot be assembled"):
                if backward is not None:
                    raise DegenerateConstruction(step, f"{why}: the swing goes beyond the driver's limits",
                                                 f"position {i + 1} ({driver_text(d, float(angles[i]))})")
                raise DegenerateConstruction(step, f"{why}: the crank cannot make a full turn, so there is no full "
                                                   "cycle", f"position {i + 1} (φ{d.link} = "
                                                            f"{math.degrees(float(angles[i])):.6g}°)")
            polygon_failures.setdefault(i, f"{step}: {why}")
    conds = {text: c for text, c in batch.conds.items() if panel_of.get(text) in ("mechanism", *polygons)}
    vals = batch.values
    mech = {p: _xy(vals, s, n) for p, s in b.mech.items() if s in vals}
    vel = {p: _xy(vals, s, n) for p, s in b.vel.items() if s in vals} if "velocity" in polygons else {}
    acc = {p: _xy(vals, s, n) for p, s in b.acc.items() if s in vals} if "acceleration" in polygons else {}
    rate = d.omega if isinstance(d, Crank) else d.velocity
    sense = -1.0 if rate < 0 else 1.0
    w = abs(rate)
    x = np.arange(n, dtype=float) * (TWO_PI / n) / mu_phi
    period = TWO_PI / mu_phi
    slide = sliders(linkage)
    links = linkage.links()
    out = []
    for subject in diagrams:
        mu = (mu_s or {})[subject]
        rise = 0.0  # what s gains over the cycle
        if subject in slide:
            gx, gy = slide[subject]
            p = mech[subject]
            s_m = ((p[:, 0] - p[0, 0]) * gx + (p[:, 1] - p[0, 1]) * gy) * b.mu_l  # along the guide
            kind = "point"
        elif subject in links:
            u, v = offset_bar_lines(linkage).get(subject, tuple(links[subject][:2]))  # an offset bar: its line
            pu, pv = mech[u], mech[v]
            theta = np.arctan2(pv[:, 1] - pu[:, 1], pv[:, 0] - pu[:, 0])
            s_m = _unwrap_from_first(theta, sense)
            rise = float(s_m[-1] + (theta[0] - theta[-1] + math.pi) % TWO_PI - math.pi)  # a full turn, or 0
            kind = "link"
        else:  # a point's way along its path: the chords between its positions, laid end to end (dividers)
            p = mech[subject]
            chords = np.hypot(*np.diff(np.vstack([p, p[:1]]), axis=0).T) * b.mu_l
            s_m = np.concatenate([[0.0], np.cumsum(chords[:-1])])
            rise = float(chords.sum())
            kind = "path"
        s_mm = s_m / mu
        h1, h2 = H_mm[subject] if isinstance(H_mm, dict) else H_mm
        vdiff = differentiate_cycle(x, s_mm, period, h1, rise / mu)
        mu_v = mu * w / (mu_phi * h1)
        adiff = differentiate_cycle(vdiff.mid_mm, vdiff.derivative_mm, period, h2)
        mu_a = mu_v * w / (mu_phi * h2)
        out.append(CycleDiagram(subject, kind, frozen_array(x), frozen_array(s_mm), vdiff, adiff, mu, mu_v, mu_a, rise / mu))
    dense: dict[str, np.ndarray] = {}
    if paths:
        k = max(1, -(-PATH_POSITIONS // n))
        fine = (np.asarray(angles, dtype=float)[:, None] + sense * np.arange(k) * TWO_PI / (n * k)).ravel()
        if backward is not None:  # a swing traces its path out and back: the first stroke, ends included
            fine = np.linspace(float(angles[0]), float(angles[n // 2]), max(PATH_POSITIONS, n // 2 + 1))
            k = 2
        if k == 1:
            dense = {p: mech[p] for p in paths}
        else:
            pplan = b.g.prune([b.mech[p] for p in paths])
            with np.errstate(all="ignore"):
                pb = pplan.evaluate_batch({b.param: fine})
            if pb.valid.all():
                dense = {p: _xy(pb.values, b.mech[p], fine.size) for p in paths}
            else:  # a position between the N cannot be built: the path through the N only
                dense = {p: mech[p] for p in paths}
    return FullCycle(b, plan, frozen_array(angles), mech, vel, acc, vals, tuple(out), mu_phi,
                     sense, dense, polygon_failures, conds,
                     None if backward is None else frozen_array(np.asarray(backward, dtype=bool)))
