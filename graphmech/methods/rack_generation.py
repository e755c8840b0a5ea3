"""Generation by the rack cutter (范成法), constructed as the book draws it: the cutter at
successive positions relative to the blank, the tooth as what they leave of it.

The cutter (the basic rack, its teeth (h*a + c*)m deep below the datum line with the tip rounding
ρ_f of :func:`graphmech.methods.involute.cutter_rounding`) rolls its pitch line — the datum line
shifted by xm — on the blank's reference circle: when the blank has turned by φ the cutter has
moved rφ. In the blank's frame the cutter therefore both turns (by φ about O) and translates; its
N positions per tooth pitch (φ steps of 2π/(zN), the cutter πm/N apart) are cut out of the blank
(shapely's set difference of the tip-circle sector and the union of the cutter's positions: the
tooth left is their envelope, scallops and undercut included, with the cusps where two positions
cross as exact vertices). The thickness of the generated tooth is measured on that outline where
it crosses a circle.

The rolling circle itself is constructed from the speeds (the velocity distribution ω·y along
the blank's radius cut by the cutter's v).

Frame: :mod:`graphmech.methods.involute`'s — O at the origin, the space cut by the cutter's
tooth 0 at φ = 0 centred on +y; the cutter's frame has its datum line on y = 0, x along the rack,
the teeth pointing down (−y). Lengths in m, angles in rad.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.geometry.kernels import ScalarOps, intersect_lines
from graphmech.mechanisms.gear import SpurGear, ToothSystem
from graphmech.methods.involute import circles, cutter_rounding

XY = tuple[float, float]
Points = NDArray[np.float64]

#: Points on each tip rounding of the cutter tooth that cuts the measured space; the teeth beside
#: it (they cut only the neighbouring spaces) get a quarter.
ROUNDING_POINTS = 24
#: Chords of the blank's tip arc per radian (its vertices lie on the arc, the chords outside it).
TIP_CHORDS_PER_RAD = 4000
#: The cutter's body above its root line, in modules (it only closes the polygon).
BODY = 1.0
#: The most outline vertices one generation unites (:func:`work`): about 6 s of shapely's union;
#: the check refuses a generation beyond it rather than run for minutes (z = 10⁵ at N = 12).
WORK_MOST = 4_000_000


@dataclass(frozen=True)
class Generation:
    """The generated gear (whole z, shift x) and the construction: the rolling radius r, the datum
    distance L = r + xm, N positions per pitch at the rolling angles ``phis``, the cutter's outline
    (3 teeth, its own frame), and ``profile``: the generated outline over one pitch from the axis of
    the tooth right of the space (π/2 − π/z) to the axis of the tooth left of it (π/2 + π/z)."""

    system: ToothSystem
    gear: SpurGear
    r: float
    L: float
    ra: float
    rf: float
    positions: int
    phis: tuple[float, ...]
    cutter: tuple[XY, ...]
    profile: tuple[XY, ...]

    @property
    def pitch_angle(self) -> float:
        return 2.0 * math.pi / self.gear.z

    def cutter_at(self, phi: float) -> Points:
        """The cutter's outline in the blank's frame after the rolling φ."""
        return place(np.asarray(self.cutter), phi, self.r, self.L)

    def teeth(self, spaces: range = range(-1, 2)) -> Points:
        """The generated outline over several pitches (space k turned by k·2π/z), counter-clockwise
        as the profile runs."""
        base = np.asarray(self.profile)
        parts = [_turn(base, k * self.pitch_angle)[int(i > 0):] for i, k in enumerate(sorted(spaces))]
        return np.concatenate(parts) if parts else base


def rolling_radius(v: float, omega: float) -> float:
    """The rolling circle from the speeds, as drawn: along the blank's radius the velocities ω·y
    rise on a line through O; the cutter's v is a line parallel to the radius; they cross at y = r
    (the pitch point, where blank and cutter move alike: r = v/ω)."""
    if not (v > 0.0 and omega > 0.0 and math.isfinite(v) and math.isfinite(omega)):
        raise OutOfDomain(f"the speeds must be positive and finite, not v = {v!r}, ω = {omega!r}")
    ops = ScalarOps()
    ops.step = "pitch point = (ω·y on the radius) ∩ (the cutter's v)"
    # the velocities drawn at a round scale k that lays the ω·y line at 0.3 … 3 when ω is extreme
    # (at ω = 1e-299 rad/s it would run parallel to the radius and miss the v line)
    k = 1.0 if 1e-6 <= omega <= 1e6 else 10.0 ** -round(math.log10(omega))
    n = math.hypot(1.0, omega * k)
    y, _ = intersect_lines(ops, (0.0, 0.0, 1.0 / n, omega * k / n), (0.0, v * k, 1.0, 0.0))
    return float(y)


def cutter_outline(system: ToothSystem, gear: SpurGear, rounding_points: int = ROUNDING_POINTS,
                   teeth: tuple[int, ...] = (-1, 0, 1)) -> tuple[XY, ...]:
    """The cutter's outline in its own frame (datum line y = 0), its teeth k·πm apart, closed over
    its body: each tooth's flanks at α to the vertical, h*a + c* deep, its tip rounded by ρ_f."""
    m, a = system.m, system.alpha
    xc, yc, rho = cutter_rounding(system, gear)
    H = (system.ha_star + system.c_star) * m  # the cutter's root line, the clearance above the blank's tip
    out: list[XY] = []
    for k in teeth:
        n = rounding_points if k == 0 else max(4, rounding_points // 4)
        x0 = k * math.pi * m
        right = [(xc + rho * math.cos(t), yc + rho * math.sin(t))
                 for t in np.linspace(-0.5 * math.pi, -a, n)]
        left = [(-x, y) for x, y in reversed(right)]
        top = math.pi * m / 4.0 + H * math.tan(a)
        tooth = [(-0.5 * math.pi * m, H), (-top, H)] + left + right[int(xc == 0.0):] + [(top, H),
                                                                                         (0.5 * math.pi * m, H)]
        out += [(x0 + x, y) for x, y in tooth][int(bool(out)):]
    lo, hi = out[0][0], out[-1][0]
    return tuple(out + [(hi, H + BODY * m), (lo, H + BODY * m)])


def place(outline: Points, phi: float | Points, r: float, L: float) -> Points:
    """The cutter's points in the blank's frame: moved rφ along the rack at L from O, turned by φ
    about O (the blank turned by −φ seen from the blank). ``phi`` an array gives one outline each."""
    p = np.asarray(outline, dtype=float)
    f = np.asarray(phi, dtype=float)[..., None]
    x, y = p[:, 0] + r * f, p[:, 1] + L
    c, s = np.cos(f), np.sin(f)
    return np.stack([c * x - s * y, s * x + c * y], axis=-1)


def _turn(p: Points, angle: float) -> Points:
    c, s = math.cos(angle), math.sin(angle)
    return np.stack([c * p[:, 0] - s * p[:, 1], s * p[:, 0] + c * p[:, 1]], axis=-1)


def generate(system: ToothSystem, gear: SpurGear, positions: int = 12,
             rounding_points: int | None = None, stagger: float = 0.0) -> Generation:
    """Cut the blank (the tip circle r_a) with the cutter at N = ``positions`` per pitch over the
    whole engagement, and return the outline left over one pitch. ``rounding_points`` (default
    max(24, 4N)) keeps the rounding's chords finer than the scallops of N positions. ``stagger``
    shifts every position by that fraction of a step (½: the positions halfway between, whose
    scallops fall between those of the others — how the check estimates the scallops' effect)."""
    import shapely

    if gear.internal:
        raise NotApplicable("a ring is cut by a pinion cutter: a rack cannot generate it")
    if not 2 <= positions <= 4096:
        raise OutOfDomain(f"2 … 4096 cutter positions per pitch, not {positions}")
    m = system.m
    r, _, ra, rf = circles(system, gear)
    L = r + gear.x * m
    if rf <= 0.0:
        raise NoSolution(f"the cutter's tip line passes O (r_f = {rf:g} m): nothing of the blank is left")
    npts = rounding_points if rounding_points is not None else max(ROUNDING_POINTS, 4 * positions)
    cutter = cutter_outline(system, gear, npts)
    half = math.pi / gear.z
    step = 2.0 * half / positions
    J = _half_engagement(system, gear, positions)
    phis = np.asarray((np.arange(-J, J + 1) + stagger) * step, dtype=np.float64)
    cut = shapely.union_all(shapely.polygons(place(np.asarray(cutter), phis, r, L)))
    n_arc = max(16, math.ceil(2.0 * half * TIP_CHORDS_PER_RAD))
    t = np.linspace(0.5 * math.pi - half, 0.5 * math.pi + half, n_arc + 1)
    r_out = ra / math.cos(half / n_arc)  # vertices outside, chords touching the circle: no tip under r_a
    arc = np.stack([r_out * np.cos(t), r_out * np.sin(t)], axis=-1)
    arc[0], arc[-1] = arc[0] * ra / r_out, arc[-1] * ra / r_out
    sector = shapely.Polygon(np.vstack([[[0.0, 0.0]], arc]))
    left = sector.difference(cut)
    inside = shapely.Point(0.0, 0.5 * rf)
    parts = list(getattr(left, "geoms", [left]))
    body = next((g for g in parts if g.contains(inside)), None)
    if body is None or body.is_empty:
        raise NoSolution("the cutter leaves nothing of the blank near its root circle")
    return Generation(system=system, gear=gear, r=r, L=L, ra=ra, rf=rf, positions=positions,
                      phis=tuple(float(p) for p in phis), cutter=cutter, profile=_profile(body, half))


def _half_engagement(system: ToothSystem, gear: SpurGear, positions: int) -> int:
    """J: the positions on each side of φ = 0 over the engagement (the cutter's teeth inside the
    tip circle, one pitch beyond on each side)."""
    m = system.m
    r, _, ra, _ = circles(system, gear)
    tip_line = r + gear.x * m - (system.ha_star + system.c_star) * m
    reach = math.sqrt(max(ra * ra - tip_line * tip_line, 0.0)) + 2.0 * math.pi * m
    return math.ceil(min(reach / r, 0.45 * math.pi) / (2.0 * (math.pi / gear.z) / positions))


def work(system: ToothSystem, gear: SpurGear, positions: int) -> int:
    """The outline vertices :func:`generate` unites at N = ``positions`` (default rounding): the
    cost of the cut, which grows as N² and with √z."""
    return (2 * _half_engagement(system, gear, positions) + 1) * max(ROUNDING_POINTS, 4 * positions)


def _profile(body: object, half: float) -> tuple[XY, ...]:
    """The outline of the cut sector without its two radii: from the right edge (π/2 − π/z) to the
    left one (π/2 + π/z)."""
    ring = np.asarray(body.exterior.coords)[:-1]  # type: ignore[attr-defined]
    theta = np.arctan2(ring[:, 1], ring[:, 0])
    rho = np.hypot(ring[:, 0], ring[:, 1])
    lo, hi = 0.5 * math.pi - half, 0.5 * math.pi + half
    tol = 1e-12
    on_edge = (rho < tol * max(rho.max(), 1e-300)) | (np.abs(theta - lo) < tol) | (np.abs(theta - hi) < tol)
    # start the ring at O (its vertex nearest the origin), so that the profile is one run between the radii
    start = int(np.argmin(rho))
    ring, theta, on_edge = (np.roll(v, -start, axis=0) for v in (ring, theta, on_edge))
    keep = ~on_edge
    idx = np.nonzero(keep)[0]
    run = ring[idx[0] - 1: idx[-1] + 2]  # the edge points at each end, where the profile meets the radii
    th = np.arctan2(run[:, 1], run[:, 0])
    if th[0] > th[-1]:
        run = run[::-1]
    return tuple((float(x), float(y)) for x, y in run)


def crossings(profile: Points, rho: float) -> list[float]:
    """The polar angles where the profile crosses the circle ρ, in order along it (each segment
    cut with the circle exactly)."""
    p = np.asarray(profile, dtype=float)
    a, b = p[:-1], p[1:]
    ra, rb = np.hypot(a[:, 0], a[:, 1]), np.hypot(b[:, 0], b[:, 1])
    out = []
    for i in np.nonzero((ra - rho) * (rb - rho) <= 0.0)[0]:
        if ra[i] == rho and rb[i] == rho:
            continue
        d = b[i] - a[i]
        A, B, C = d @ d, 2.0 * (a[i] @ d), a[i] @ a[i] - rho * rho
        disc = max(B * B - 4.0 * A * C, 0.0)
        ts = [t for t in ((-B + math.sqrt(disc)) / (2.0 * A), (-B - math.sqrt(disc)) / (2.0 * A)) if 0.0 <= t <= 1.0]
        if ts:
            q = a[i] + min(ts, key=lambda t: abs(t - 0.5)) * d
            out.append(math.atan2(q[1], q[0]))
    return out


def thickness(gen: Generation, rho: float) -> float | None:
    """The generated tooth's arc thickness on the circle ρ: the pitch arc less the space between
    the profile's first crossings from either end (the two flanks that face the space); None where
    the tooth does not reach ρ or the space is closed there."""
    cr = crossings(np.asarray(gen.profile), rho * (1.0 - 1e-12))
    if len(cr) < 2:
        return None
    right, left = cr[0], cr[-1]
    return rho * (gen.pitch_angle - (left - right))


__all__ = ["WORK_MOST", "Generation", "crossings", "cutter_outline", "generate", "place", "rolling_radius", "thickness",
           "work"]
