"""The extreme positions of a driver that cannot move without bound, in closed form.

A rocker (a driver pivoted on the frame that cannot turn fully) or a slider driving a dyad can go
only as far as the dyad on its point can be assembled: its limits are where that dyad toggles.

rocker AB = a about A, dyad RRR B–C–D (BC = l₂, CD = l₃, D on the frame, AD = d)
    the dyad toggles where BC and CD are collinear: BD = l₂ + l₃ (stretched) or |l₂ − l₃|
    (folded), and BD² = a² + d² − 2ad·cos(φ − φ_AD) (the cosine rule) gives
    φ = φ_AD ± arccos((a² + d² − BD²)/(2ad)).
rocker with an RRP dyad B–C (BC = l, the guide through T with unit normal n)
    B's distance from the guide e(φ) = (A − T)·n + a·cos(φ − φ_n) reaches ±l (BC at right angles
    to the guide): φ = φ_n ± arccos((±l − (A − T)·n)/a).
slider B = O + s·g driving RRR B–C–D
    |O + s·g − D|² = BD² is a quadratic in s: s = −(O − D)·g ± √(((O − D)·g)² − |O − D|² + BD²).
slider driving RRP B–C
    (O + s·g − T)·n = ±l is linear in s.

The output CD of an RRR swings between the angles it takes at the swing's ends and wherever inside
the swing it stops (ω₃ = 0): a rocker's A, B, C in one line, AC = AB ± BC, so the angle ADC has
cos = (AD² + CD² − AC²)/(2·AD·CD); a slider's BC at right angles to its guide, so C is BC off
the guide, (D − C)·n = … a quadratic along the guide.

The limits of the swing through the driver's stated position are the nearest of these on either
side of it. Nothing here uses the construction code (:mod:`graphmech.methods.swing` draws them).
Lengths in m, angles in rad.
"""
from __future__ import annotations

import cmath
import math

import numpy as np

from graphmech.errors import NotApplicable
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, SliderInput

__all__ = ["driver_limits", "output_swing"]

TWO_PI = 2.0 * math.pi


def _toggles(linkage: Linkage) -> list[float]:
    """Every driver position (φ or s) at which a dyad on the driver's point toggles: the first such
    dyad must, the later ones (a rocker driving two dyads) do where their own toggles stop it too."""
    d = linkage.driver
    tip = d.tip if isinstance(d, Crank) else d.point
    on_tip = [y for y in linkage.dyads if isinstance(y, (RRR, RRP)) and tip in (y.p, getattr(y, "q", None))]
    if not on_tip:
        raise NotApplicable("no RRR or RRP dyad on the driver's point: nothing toggles, so there are no limits")
    out = _dyad_toggles(linkage, on_tip[0])
    for y in on_tip[1:]:
        try:
            out += _dyad_toggles(linkage, y)
        except NotApplicable:  # a later dyad whose toggle is no limit (on a moving point): none of its own
            pass
    return out


def _dyad_toggles(linkage: Linkage, dyad: RRR | RRP) -> list[float]:
    """Every driver position (φ or s) at which ``dyad``, on the driver's point, toggles."""
    d = linkage.driver
    tip = d.tip if isinstance(d, Crank) else d.point
    frame = linkage.frame_points
    out: list[float] = []
    if isinstance(dyad, RRR):
        other = dyad.q if dyad.p == tip else dyad.p
        if other not in frame:
            raise NotApplicable(f"the dyad on {tip} is not pivoted on the frame at {other}: its toggle is not the driver's limit")
        Dx, Dy = frame[other]
        l2, l3 = dyad.lengths if dyad.p == tip else dyad.lengths[::-1]
        radii = [l2 + l3] + ([abs(l2 - l3)] if l2 != l3 else [])
        if isinstance(d, Crank):
            Ax, Ay = frame[d.pivot]
            dist, base = math.hypot(Dx - Ax, Dy - Ay), math.atan2(Dy - Ay, Dx - Ax)
            for r in radii:
                c = (d.length ** 2 + dist ** 2 - r ** 2) / (2.0 * d.length * dist)
                if -1.0 <= c <= 1.0:
                    out += [base + math.acos(c), base - math.acos(c)]
        else:
            (Ox, Oy), (gx, gy) = d.guide.through, d.guide.direction
            b = (Ox - Dx) * gx + (Oy - Dy) * gy
            for r in radii:
                disc = b * b - ((Ox - Dx) ** 2 + (Oy - Dy) ** 2 - r * r)
                if disc >= 0.0:
                    out += [-b + math.sqrt(disc), -b - math.sqrt(disc)]
        return out
    if not isinstance(dyad.guide, Guide):
        raise NotApplicable(f"the dyad on {tip} slides on a moving link's guide: its toggle is not the driver's limit")
    (Tx, Ty), (ux, uy) = dyad.guide.through, dyad.guide.direction
    nx, ny = -uy, ux
    for e in (dyad.length, -dyad.length):
        if isinstance(d, Crank):
            Ax, Ay = frame[d.pivot]
            c = (e - ((Ax - Tx) * nx + (Ay - Ty) * ny)) / d.length
            if -1.0 <= c <= 1.0:
                base = math.atan2(ny, nx)
                out += [base + math.acos(c), base - math.acos(c)]
        else:
            (Ox, Oy), (gx, gy) = d.guide.through, d.guide.direction
            gn = gx * nx + gy * ny
            if gn != 0.0:
                out.append((e - ((Ox - Tx) * nx + (Oy - Ty) * ny)) / gn)
    return out


def driver_limits(linkage: Linkage, q0: float) -> tuple[float, float]:
    """The driver's limits on either side of its position ``q0`` (φ in rad, unwrapped about q0,
    or s in m): ``(lower, upper)`` with lower < q0 < upper.

    Raises
    ------
    NotApplicable
        Nothing toggles, or the driver moves without bound on a side (a crank that turns fully).
    """
    cands = _toggles(linkage)
    if isinstance(linkage.driver, Crank):
        ahead = sorted((c - q0) % TWO_PI for c in cands)
        behind = sorted((q0 - c) % TWO_PI for c in cands)
        if not ahead:
            raise NotApplicable("the driver turns fully: it has no limits (give the swing's ends)")
        return q0 - behind[0], q0 + ahead[0]
    assert isinstance(linkage.driver, SliderInput)
    lo = [c for c in cands if c < q0]
    hi = [c for c in cands if c > q0]
    if not lo or not hi:
        raise NotApplicable("the slider's stroke has no limit " + ("behind" if not lo else "ahead of")
                            + " its position: give the stroke's ends")
    return max(lo), min(hi)


def output_swing(linkage: Linkage, q_from: float, q_to: float) -> float:
    """The swing (rad) of the output CD of the RRR on the driver's point over the driver's swing
    from ``q_from`` to ``q_to``: max − min of its angle at the ends and at every stop inside."""
    from graphmech.exact.linkage import solve

    d = linkage.driver
    tip = d.tip if isinstance(d, Crank) else d.point
    y = next(y for y in linkage.dyads if isinstance(y, RRR) and tip in (y.p, y.q))
    other = y.q if y.p == tip else y.p
    D = complex(*linkage.frame_points[other])
    bc, cd = y.lengths if y.p == tip else y.lengths[::-1]
    stops = []
    if isinstance(d, Crank):
        A = complex(*linkage.frame_points[d.pivot])
        ad = abs(A - D)
        for ac, way in ((d.length + bc, 1.0), (abs(d.length - bc), 1.0 if d.length > bc else -1.0)):
            c = (ad * ad + cd * cd - ac * ac) / (2.0 * ad * cd) if ac > 0 else 2.0
            if -1.0 <= c <= 1.0:
                for sign in (1.0, -1.0):
                    C = D + cd * cmath.exp(1j * (cmath.phase(A - D) + sign * math.acos(c)))
                    stops.append(cmath.phase(way * (C - A)))
        span = q_to - q_from
        stops = [q_from + math.copysign((math.copysign(1.0, span) * (q - q_from)) % TWO_PI, span) for q in stops]
    else:
        O, g = complex(*d.guide.through), complex(*d.guide.direction)
        n = 1j * g
        for e in (bc, -bc):  # C = O + e·n + t·g on the circle |C − D| = CD
            P = O + e * n - D
            b = (P * g.conjugate()).real
            disc = b * b - (abs(P) ** 2 - cd * cd)
            if disc >= 0.0:
                stops += [((P + D + t * g - e * n - O) * g.conjugate()).real for t in (-b + math.sqrt(disc), -b - math.sqrt(disc))]
    lo, hi = sorted((q_from, q_to))
    # in order along the swing, with 1000 more between, so the angle is followed round continuously
    qs = np.sort(np.concatenate([[q_from, q_to], [q for q in stops if lo < q < hi], np.linspace(lo, hi, 1000)]))
    sol = solve(linkage, qs)
    pts = sol.point[y.c][:, 0] + 1j * sol.point[y.c][:, 1]
    for i in np.flatnonzero(~sol.valid):  # an end at the limits: the dyad in one line, C on the line BD
        B = complex(*sol.point[tip][i])
        if abs(abs(pts[i] - D) - cd) <= 1e-9 * cd and abs(abs(pts[i] - B) - bc) <= 1e-9 * bc:
            continue  # assembled, held at a dead centre (of this dyad or another one on the driver)
        u = (D - B) / abs(D - B)
        pts[i] = min((B + bc * u, B - bc * u), key=lambda c: abs(abs(c - D) - cd))
        if abs(abs(pts[i] - D) - cd) > 1e-9 * cd:  # not a toggle: a grid position off the assembly
            pts[i] = np.nan
    pts = pts[~np.isnan(pts)]
    psi = np.unwrap(np.angle(pts - D))
    return float(psi.max() - psi.min())
