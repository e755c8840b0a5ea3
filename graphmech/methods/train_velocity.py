"""The velocity diagram of a gear train with parallel axes (the book's graphical method).

Drawn beside the side view: the vertical is the height y of the schematic at μl (m/mm), the
horizontal the peripheral velocity v of the points at that height at μv ((m/s)/mm), positive
toward the viewer (a speed ω along +x moves the points above its axis toward the viewer:
v = ω·(y − y_axis)). Each member's velocities lie on one straight line, its *velocity line*:

* a member whose axis is fixed passes through (0, y_axis); a fixed member's line is the vertical;
* an input's line passes through its axis and the velocity ω·r laid off at its gear's radius;
* the two gears of a mesh have one velocity at the pitch point P: P is on both lines;
* a planet's line passes through its carrier's velocity at the planet's axis.

The lines are found as a construction: a member's line is drawn as soon as two of its points (at
two heights) are known, or one point and its slope (an input); a point shared with a member
whose line is drawn is read off that line at its height. A closed differential leaves a loop with
no order to draw it in: one member's line is then drawn by trial through a known point, twice,
with two slopes, the construction carried round the loop each time, and the slope that closes it
found by false position — exact, because every step is linear in the slope (several loops: one
trial member each, the closures solved together).

The speeds: from a pole O, rays parallel to the velocity lines cut a horizontal line at the pole
distance H above O; the cut of member k lies ℓ_k (mm, signed, to the right of the foot of O) from
the foot, and ω_k = μv·ℓ_k/(μl·H) = μω·ℓ_k along +x (a member whose axis is ``"-x"``: the
negative). A fixed member's ℓ is 0.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from graphmech.errors import DegenerateConstruction, NotApplicable, OutOfDomain
from graphmech.methods.train_layout import TrainLayout

XY = tuple[float, float]


@dataclass(frozen=True)
class Shared:
    """Two members with one velocity at the height ``y`` (m): a pitch point (``mesh`` its index)
    or a planet's axis (``mesh`` None)."""

    a: str
    b: str
    y: float
    mesh: int | None


@dataclass(frozen=True)
class VelocityLine:
    """A member's velocity line on the paper: X = slope·(Y − Y0) + X0 (mm); ``points`` the points
    it was drawn through and those read off it, lowest first."""

    member: str
    slope: float  # dX/dY on the paper
    x0: float
    y0: float
    points: tuple[XY, ...]

    def x_at(self, y: float) -> float:
        return self.x0 + self.slope * (y - self.y0)


@dataclass(frozen=True)
class TrainVelocityDiagram:
    """The diagram: scales, the lines, the pitch points, the pole and the ω line's lengths ℓ."""

    mu_l: float
    mu_v: float
    H: float  # mm
    lines: Mapping[str, VelocityLine]
    shared: tuple[Shared, ...]
    pole: XY
    lengths: Mapping[str, float]  # ℓ_k, mm, to the right of the pole's foot
    sense: Mapping[str, float]  # +1 a member whose axis is along +x, −1 along −x
    trials: tuple[str, ...]  # members drawn by false position

    @property
    def mu_omega(self) -> float:
        """μω = μv/(μl·H), (rad/s)/mm."""
        return self.mu_v / (self.mu_l * self.H)

    def omega(self, member: str) -> float:
        """ω read off the diagram, signed along the member's axis (rad/s)."""
        return self.sense[member] * self.mu_omega * self.lengths[member]

    def cut(self, member: str) -> XY:
        """Where the ray of ``member`` cuts the ω line."""
        return (self.pole[0] + self.lengths[member], self.pole[1] + self.H)


def _shared_points(lay: TrainLayout) -> list[Shared]:
    train = lay.train
    out = [Shared(train.gear(m.a).member, train.gear(m.b).member, lay.pitch[k][1], k)
           for k, m in enumerate(train.meshes)]
    out += [Shared(p.name, p.carrier, lay.height(p.name), None) for p in train.members if p.carrier is not None]
    return out


def input_radius(lay: TrainLayout, member: str) -> float:
    """The radius at which an input's velocity ω·r is laid off: its first gear's, else its first
    planet's arm (a bare carrier), else one module."""
    for g in lay.train.gears:
        if g.member == member:
            return lay.radius[g.name]
    for p in lay.train.planets(member):
        return abs(lay.arm(p))
    return lay.module


def velocity_diagram(lay: TrainLayout, mu_l: float, mu_v: float, H: float,
                     pole: XY | None = None) -> TrainVelocityDiagram:
    """The construction at μl, μv and the pole distance H (mm); the pole below the lines' lowest
    point unless given.

    Raises
    ------
    NotApplicable
        A spatial train (an axis not along x, a bevel or worm mesh).
    DegenerateConstruction
        A member whose line the construction cannot reach (no mesh ties it to the inputs).
    """
    if not lay.parallel:
        raise NotApplicable("the velocity diagram is drawn for trains whose axes are all parallel; this one is "
                            "spatial (bevel or worm meshes, or axes across x)")
    for name, v in (("μl", mu_l), ("μv", mu_v), ("H", H)):
        if not (v > 0.0 and math.isfinite(v)):
            raise OutOfDomain(f"{name} is positive and finite, not {v!r}")
    train = lay.train
    names = [m.name for m in train.members]
    shared = _shared_points(lay)
    sense = {n: lay.axis[n][0] for n in names}  # +1 along +x, −1 along −x
    # what is known before the construction: the frame's points and the inputs' slopes (paper)
    base_points: dict[str, list[XY]] = {n: [] for n in names}
    base_slope: dict[str, float] = {}
    for m in train.members:
        if m.carrier is None:
            base_points[m.name].append((0.0, lay.height(m.name) / mu_l))
    for n in train.fixed:
        base_slope[n] = 0.0
    for n, w in train.inputs.items():
        # the drawn point ω·r at the input's radius fixes the slope dX/dY = ω·μl/μv
        r = input_radius(lay, n)
        base_slope[n] = (sense[n] * w * r / mu_v) / (r / mu_l)

    def construct(trial: Mapping[str, float]) -> tuple[dict[str, VelocityLine], list[float], str | None]:
        """The lines from the known points and slopes (``trial``: assumed slopes); the misclosures
        at the shared points used twice; the first member still undrawn (None: all drawn)."""
        slope = dict(base_slope) | dict(trial)
        points = {n: list(p) for n, p in base_points.items()}
        lines: dict[str, VelocityLine] = {}
        used: set[int] = set()
        grew = True
        while grew:
            grew = False
            for k, s in enumerate(shared):  # read the shared points off the lines drawn
                if k in used:
                    continue
                for p, q in ((s.a, s.b), (s.b, s.a)):
                    if p in lines and q not in lines:
                        points[q].append((lines[p].x_at(s.y / mu_l), s.y / mu_l))
                        used.add(k)
                        grew = True
                        break
            for n in names:  # draw every line that has what it needs
                if n in lines:
                    continue
                pts = points[n]
                if n in slope and pts:
                    x0, y0 = pts[0]
                    lines[n] = VelocityLine(n, slope[n], x0, y0, ())
                    grew = True
                else:
                    two = [(p, q) for p in pts for q in pts if q[1] - p[1] > 0.0]
                    if two:
                        (xa, ya), (xb, yb) = max(two, key=lambda pq: pq[1][1] - pq[0][1])  # the widest base
                        lines[n] = VelocityLine(n, (xb - xa) / (yb - ya), xa, ya, ())
                        grew = True
        misclosure = [lines[s.a].x_at(s.y / mu_l) - lines[s.b].x_at(s.y / mu_l)
                      for k, s in enumerate(shared) if k not in used and s.a in lines and s.b in lines]
        misclosure += [lines[n].x_at(y) - x for n in lines for x, y in points[n]]
        undrawn = next((n for n in names if n not in lines and points[n]), None)
        if undrawn is None:
            undrawn = next((n for n in names if n not in lines), None)
        for s in shared:  # every point a line passes through, for drawing it across them all
            for p in (s.a, s.b):
                if p in lines:
                    points[p].append((lines[p].x_at(s.y / mu_l), s.y / mu_l))
        lines = {n: VelocityLine(n, ln.slope, ln.x0, ln.y0, tuple(sorted(set(points[n]), key=lambda p: (p[1], p[0]))))
                 for n, ln in lines.items()}
        return lines, misclosure, undrawn

    trial: dict[str, float] = {}
    lines, mis, undrawn = construct(trial)
    while undrawn is not None:  # a closed loop: one more member drawn by trial
        if not base_points[undrawn] and not any(undrawn in (s.a, s.b) for s in shared):
            raise DegenerateConstruction(f"the velocity line of {undrawn}", "no mesh ties it to the inputs")
        trial[undrawn] = 0.0
        lines, mis, undrawn = construct(trial)
        if len(trial) > len(names):
            raise DegenerateConstruction("the velocity diagram", "it does not close")
    if trial:
        # false position: the misclosures are linear in the trial slopes; two trials per slope
        keys = list(trial)
        base = np.array(mis)
        cols = []
        for key in keys:
            _, m1, _ = construct(trial | {key: 1.0})
            cols.append(np.array(m1) - base)
        A = np.array(cols).T
        if np.linalg.matrix_rank(A) < len(keys):
            raise DegenerateConstruction("the trial lines", "they do not close the loop: the train's speeds are not fixed")
        sol = np.linalg.lstsq(A, -base, rcond=None)[0]
        trial = {k: float(v) for k, v in zip(keys, sol)}
        lines, mis, _ = construct(trial)
    lo = min(p[1] for ln in lines.values() for p in ln.points)
    if pole is None:
        pole = (0.0, lo - H - 10.0)
    lengths = {n: H * lines[n].slope for n in names}
    return TrainVelocityDiagram(mu_l, mu_v, H, lines, tuple(shared), pole, lengths, sense, tuple(trial))


__all__ = ["Shared", "TrainVelocityDiagram", "VelocityLine", "input_radius", "velocity_diagram"]
