"""A driver that swings: a rocker (or a crank told to) or a slider, over N positions out and back.

A driver pivoted on the frame that cannot turn fully — a rocker — or a slider drives the
mechanism between two positions and back: its *swing* (a slider's *stroke*). The limits of a
rocker or slider are where a dyad on its point toggles (the first to, where several hang on it),
constructed on the drawing:

* an RRR dyad B–C–D: BC and CD collinear, so B lies on a circle about D of radius
  l₂ + l₃ (stretched) or |l₂ − l₃| (folded), cut with the rocker's circle about A or the
  slider's guide;
* an RRP dyad B–C: BC at right angles to its guide, so B lies on a line parallel to the guide
  at the distance l = BC, cut with the rocker's circle or the slider's guide.

The nearest cut on either side of the driver's stated position bounds its swing. The N positions
(N even) go out in N/2 equal steps from ``from`` (position 1) to ``to`` (position N/2 + 1) and
back in N/2 more (position N + 1 would be 1 again), so the driver moving uniformly at |ω| (|v|)
takes equal times between them, its sense reversed on the return stroke: positions 1 … N/2 leave
in the first stroke's sense, N/2 + 1 … N in the other. Position k and position N + 2 − k are the
same place. Checked against :mod:`graphmech.exact.swing`.

The output's swing (an RRR's link CD about D) is the spread of its angle over the driver's swing:
at the swing's ends, or inside it where the output stops (ω₃ = 0) — a rocker's AB and BC in one
line (C on a circle of radius AB ± BC about A), a slider's BC at right angles to its guide (C on
the guide moved sideways by ±BC) — each cut with the output's circle about D.
"""
from __future__ import annotations

import math

import numpy as np

from graphmech.errors import NotApplicable
from graphmech.geometry.kernels import (
    ScalarOps,
    intersect_circle_line,
    intersect_circles,
    intersect_lines,
)
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, SliderInput

__all__ = ["driver_limits", "output_swing", "swing_positions", "toggle_dyad", "toggle_dyads"]

TWO_PI = 2.0 * math.pi


def swing_positions(q_from: float, q_to: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The driver's positions 1 … N of a swing from ``q_from`` to ``q_to`` and back (N even), and
    which of them leave on the return stroke.

    >>> q, back = swing_positions(10.0, 40.0, 6)
    >>> q.tolist(), back.tolist()
    ([10.0, 20.0, 30.0, 40.0, 30.0, 20.0], [False, False, False, True, True, True])
    """
    half = n // 2
    k = np.arange(n)
    u = np.where(k <= half, k, n - k) / half
    return q_from + (q_to - q_from) * u, k >= half


def toggle_dyads(linkage: Linkage) -> list[RRR | RRP]:
    """The dyads on the driver's point whose toggles limit the driver (RRR to a frame point, RRP on
    a frame guide), in assembly order: the first one stops the driver where it toggles."""
    d = linkage.driver
    tip = d.tip if isinstance(d, Crank) else d.point
    out: list[RRR | RRP] = []
    for y in linkage.dyads:
        if isinstance(y, RRR) and tip in (y.p, y.q):
            if (y.q if y.p == tip else y.p) not in linkage.frame_points:
                break
            out.append(y)
        if isinstance(y, RRP) and y.p == tip and isinstance(y.guide, Guide):
            out.append(y)
    if not out:
        raise NotApplicable("the limits are where the dyad on the driver's point toggles: it needs an RRR pivoted on "
                            "the frame or an RRP on a frame guide there (give the swing's ends instead)")
    return out


def toggle_dyad(linkage: Linkage) -> RRR | RRP:
    """The first dyad on the driver's point whose toggle limits the driver (its output is the swing's)."""
    return toggle_dyads(linkage)[0]


def _cuts(linkage: Linkage) -> list[tuple[float, float]]:
    """The driver's point at every toggle of the dyads on it, constructed (circle ∩ circle, circle ∩
    line, line ∩ line)."""
    return [p for y in toggle_dyads(linkage) for p in _dyad_cuts(linkage, y)]


def _dyad_cuts(linkage: Linkage, y: RRR | RRP) -> list[tuple[float, float]]:
    """The driver's point at every toggle of the dyad ``y`` on it."""
    ops = ScalarOps()
    d = linkage.driver
    frame = linkage.frame_points
    path: tuple[float, ...]  # the driver point's path: the rocker's circle (A, AB) or the slider's guide
    if isinstance(d, Crank):
        path = (*frame[d.pivot], d.length)
    else:
        path = (*d.guide.through, *d.guide.direction)
    out: list[tuple[float, float]] = []

    def never(_: object) -> str:  # the cuts are tried only where they exist
        return "no cut"

    if isinstance(y, RRR):
        tip = d.tip if isinstance(d, Crank) else d.point
        other = y.q if y.p == tip else y.p
        D = frame[other]
        l2, l3 = y.lengths
        for r in [l2 + l3] + ([abs(l2 - l3)] if l2 != l3 else []):
            for side in (1.0, -1.0):
                if len(path) == 3:  # the circle of radius r about D cuts the rocker's circle
                    dist = math.dist(path[:2], D)
                    if abs(path[2] - r) <= dist <= path[2] + r and dist > 0.0:
                        out.append(intersect_circles(ops, path[:2], path[2], D, r, side, never))
                else:  # … or the slider's guide
                    e = (D[0] - path[0]) * path[3] - (D[1] - path[1]) * path[2]
                    if abs(e) <= r:
                        out.append(intersect_circle_line(ops, D, r, path, side, never))
        return out
    assert isinstance(y.guide, Guide)  # toggle_dyad keeps frame guides only
    (tx, ty), (ux, uy) = y.guide.through, y.guide.direction
    for e in (y.length, -y.length):  # the guide moved sideways by ±BC: where B must be at the toggle
        line = (tx - e * uy, ty + e * ux, ux, uy)
        if len(path) == 3:
            off = (path[0] - line[0]) * uy - (path[1] - line[1]) * ux
            if abs(off) <= path[2]:
                out += [intersect_circle_line(ops, path[:2], path[2], line, side, never) for side in (1.0, -1.0)]
        elif abs(path[2] * uy - path[3] * ux) > 1e-12:
            out.append(intersect_lines(ops, path, line))
    return out


def driver_limits(linkage: Linkage, q0: float) -> tuple[float, float]:
    """The driver's limits on either side of its position ``q0`` (rocker: φ in rad, unwrapped
    about q0; slider: s in m along its guide), by construction: ``(lower, upper)``.

    Raises
    ------
    NotApplicable
        Nothing toggles, the driver goes on without bound on a side (a crank that turns fully, a
        slider whose dyad always assembles ahead), or the dyad cannot be assembled at ``q0``.
    """
    d = linkage.driver
    cuts = _cuts(linkage)
    if isinstance(d, Crank):
        A = linkage.frame_points[d.pivot]
        qs = [math.atan2(p[1] - A[1], p[0] - A[0]) for p in cuts]
        if not qs:
            raise NotApplicable("the driver turns fully: it has no limits (give the swing's ends)")
        lower = q0 - min((q0 - q) % TWO_PI for q in qs)
        upper = q0 + min((q - q0) % TWO_PI for q in qs)
    else:
        assert isinstance(d, SliderInput)
        (ox, oy), (gx, gy) = d.guide.through, d.guide.direction
        qs = [(p[0] - ox) * gx + (p[1] - oy) * gy for p in cuts]
        lo, hi = [q for q in qs if q < q0], [q for q in qs if q > q0]
        if not lo or not hi:
            raise NotApplicable("the slider's stroke has no limit " + ("behind" if not lo else "ahead of")
                                + " its position: give the stroke's ends")
        lower, upper = max(lo), min(hi)
    _assembles_at(linkage, q0)
    return lower, upper


def _assembles_at(linkage: Linkage, q0: float) -> None:
    """Refuse a stated position outside every swing: between two cuts where the dyad cannot close."""
    d = linkage.driver
    if isinstance(d, Crank):
        A = linkage.frame_points[d.pivot]
        B = (A[0] + d.length * math.cos(q0), A[1] + d.length * math.sin(q0))
    else:
        assert isinstance(d, SliderInput)
        B = (d.guide.through[0] + q0 * d.guide.direction[0], d.guide.through[1] + q0 * d.guide.direction[1])
    ok = True
    for y in toggle_dyads(linkage):
        if isinstance(y, RRR):
            D = linkage.frame_points[y.q if y.p == (d.tip if isinstance(d, Crank) else d.point) else y.p]
            ok = ok and abs(y.lengths[0] - y.lengths[1]) <= math.dist(B, D) <= sum(y.lengths)
        else:
            assert isinstance(y.guide, Guide)  # toggle_dyads keeps frame guides only
            (tx, ty), (ux, uy) = y.guide.through, y.guide.direction
            ok = ok and abs((B[0] - tx) * uy - (B[1] - ty) * ux) <= y.length
    if not ok:
        raise NotApplicable("the mechanism cannot be assembled at the driver's stated position: state one inside "
                            "the swing (it picks the swing whose limits are found)")


def _in_swing(linkage: Linkage, q: float, q_from: float, q_to: float) -> float | None:
    """``q`` as a position of the swing from ``q_from`` to ``q_to`` (a rocker's angle unwrapped
    into it), or None when outside it."""
    if isinstance(linkage.driver, Crank):
        span = q_to - q_from
        q = q_from + math.copysign((math.copysign(1.0, span) * (q - q_from)) % TWO_PI, span)
    lo, hi = sorted((q_from, q_to))
    return q if lo < q < hi else None


def output_swing(linkage: Linkage, q_from: float, q_to: float) -> tuple[float, str]:
    """The output's swing over the driver's swing from ``q_from`` to ``q_to``, constructed (rad),
    and the output link: the RRR on the driver's point, its link pivoted on the frame.

    Raises
    ------
    NotApplicable
        The dyad on the driver's point is no RRR pivoted on the frame (nothing rocks about a pivot).
    """
    from graphmech.methods.polygons import build_polygons

    y = toggle_dyad(linkage)
    if not isinstance(y, RRR):
        raise NotApplicable("the output's swing is that of an RRR's link pivoted on the frame; here the dyad on the "
                            "driver's point slides")
    d = linkage.driver
    ops = ScalarOps()
    tip = d.tip if isinstance(d, Crank) else d.point
    D = linkage.frame_points[y.q if y.p == tip else y.p]
    bc, cd = y.lengths if y.p == tip else y.lengths[::-1]
    out_link = y.links[1] if y.p == tip else y.links[0]
    b = build_polygons(linkage, {"l": 1.0, "v": 1.0, "a": 1.0})
    plan = b.g.prune([b.mech[y.c]])
    ox, oy = b.origin

    def never(_: object) -> str:
        return "no cut"

    stops: list[float] = []  # driver positions inside the swing where the output stops
    if isinstance(d, Crank):
        A = linkage.frame_points[d.pivot]
        for r, way in ((d.length + bc, 1.0), (abs(d.length - bc), 1.0 if d.length > bc else -1.0)):
            dist = math.dist(A, D)
            if r == 0.0 or not abs(r - cd) <= dist <= r + cd:
                continue
            for side in (1.0, -1.0):
                C = intersect_circles(ops, A, r, D, cd, side, never)  # C on the circle AB ± BC about A
                q = math.atan2(way * (C[1] - A[1]), way * (C[0] - A[0]))
                stops.append(q)
    else:
        assert isinstance(d, SliderInput)
        (gx, gy), (px, py) = d.guide.direction, d.guide.through
        for e in (bc, -bc):
            line = (px - e * gy, py + e * gx, gx, gy)  # the guide moved sideways by ±BC: BC ⟂ the guide
            off = (D[0] - line[0]) * gy - (D[1] - line[1]) * gx
            if abs(off) > cd:
                continue
            for side in (1.0, -1.0):
                C = intersect_circle_line(ops, D, cd, line, side, never)
                stops.append((C[0] + e * gy - px) * gx + (C[1] - e * gx - py) * gy)
    # the stops and the ends give the extremes; a grid between them only follows the output round
    # continuously (it may swing more than half a turn), the values are the stops' and the ends'
    inside = [x for x in (_in_swing(linkage, q, q_from, q_to) for q in stops) if x is not None]
    qs = np.sort(np.concatenate([[q_from, q_to], inside, np.linspace(q_from, q_to, UNWRAP_GRID)]))
    with np.errstate(all="ignore"):
        batch = plan.evaluate_batch({b.param: qs})
    cx, cy = batch.values[b.mech[y.c]]
    psi = np.unwrap(np.arctan2(np.asarray(cy) + oy - D[1], np.asarray(cx) + ox - D[0])[batch.valid])
    return float(psi.max() - psi.min()), out_link


#: Positions laid over a swing only to follow the output's angle continuously (never its extremes).
UNWRAP_GRID = 256
