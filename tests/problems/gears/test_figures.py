"""The gear figures: the constructions' points at their panel's μ, circles cut to the panel's
window (z = 1000), words in three notations, byte-identical SVG, undercut and ε < 1 said."""
from __future__ import annotations

import math

import pytest

from graphmech.drawing.lettering import plain
from graphmech.drawing.primitives import Arrow, Circle, Label, Polyline, Segment, Sheet, Text
from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem
from graphmech.methods.gear_meshing import MeshConstruction
from graphmech.methods.involute import AtRadius, Flank, PinMeasurement, SpanMeasurement, ToothOutline
from graphmech.problems.gears.figures import (PANELS, GearDrawing, circle_in, clipped_circle, gear_sheet,
                                              outline_runs)
from graphmech.render.layout import item_box
from graphmech.render.svg import render_svg

A3 = (420.0, 297.0)
ALPHA = math.radians(20.0)
SYSTEM = ToothSystem(0.008, ALPHA)


# ----------------------------------------------------------------------------- hand-made constructions
# Built here from the involute's closed form (the figures only lay off what they are given):
# tooth 0 centred on +y, its half angle at r_k ψ + inv α − inv α_k, ψ = (π/2 + 2x tan α)/z.
def inv(a: float) -> float:
    return math.tan(a) - a


def radii(s: ToothSystem, g: SpurGear) -> tuple[float, float, float, float]:
    r = s.m * g.z / 2.0
    return r, r * math.cos(s.alpha), r + (s.ha_star + g.x) * s.m, r - (s.ha_star + s.c_star - g.x) * s.m


def half(s: ToothSystem, g: SpurGear, rk: float) -> float:
    r, rb, _, _ = radii(s, g)
    ak = math.acos(min(rb / rk, 1.0))
    return (math.pi / 2.0 + 2.0 * g.x * math.tan(s.alpha)) / g.z + inv(s.alpha) - inv(ak)


def polar(r: float, a: float) -> tuple[float, float]:
    return (r * math.cos(a), r * math.sin(a))


def at(s: ToothSystem, g: SpurGear, rk: float) -> AtRadius:
    _, rb, _, _ = radii(s, g)
    b = half(s, g, rk)
    ak = math.acos(rb / rk)
    aL, aR = math.pi / 2 + b, math.pi / 2 - b
    return AtRadius(rk, polar(rk, aL), polar(rk, aR), polar(rb, aL - ak), polar(rb, aR + ak), ak, 2 * rk * b,
                    math.sqrt(rk * rk - rb * rb), inv(ak))


def outline(s: ToothSystem, g: SpurGear, teeth: int = 3, n: int = 8, undercut: bool = False) -> ToothOutline:
    r, rb, ra, rf = radii(s, g)
    lo = max(rb, rf)
    step = math.tau / g.z
    drawn, pts = [], []
    for j in range(teeth // 2, -(teeth // 2) - 1, -1):  # left to right: clockwise
        rot = j * step
        ks = [lo + (ra - lo) * i / (n - 1) for i in range(n)]
        left = [polar(rk, math.pi / 2 + half(s, g, rk) + rot) for rk in ks]
        right = [polar(rk, math.pi / 2 - half(s, g, rk) + rot) for rk in ks]
        strings = tuple((polar(rb, math.pi / 2 - half(s, g, rk) + rot + math.acos(rb / rk)), p)
                        for rk, p in zip(ks, right))
        lstr = tuple((polar(rb, math.pi / 2 + half(s, g, rk) + rot - math.acos(rb / rk)), p)
                     for rk, p in zip(ks, left))
        drawn.append((Flank(polar(rb, math.pi / 2 + half(s, g, rb) + rot), tuple(left), lstr),
                       Flank(polar(rb, math.pi / 2 - half(s, g, rb) + rot), tuple(right), strings)))
        a_root = math.pi / 2 + half(s, g, lo) + rot
        gap = step - 2.0 * half(s, g, lo)  # the root arc from the tooth on the left to this one
        pts += [polar(rf, a_root + gap * (1.0 - i / 6.0)) for i in range(6)]
        pts += [polar(rf, a_root)] + left + right[::-1] + [polar(rf, math.pi / 2 - half(s, g, lo) + rot)]
    pts.append((0.0, 0.0))  # the sector closed through O: the figure must leave that out
    return ToothOutline(r, rb, ra, rf, tuple(drawn), (), tuple(pts), undercut)


def mesh(s: ToothSystem, z1: int, z2: int) -> MeshConstruction:
    g1, g2 = SpurGear(z1), SpurGear(z2)
    r1, rb1, ra1, _ = radii(s, g1)
    r2, rb2, ra2, _ = radii(s, g2)
    a = r1 + r2
    u = (math.cos(s.alpha), math.sin(s.alpha))
    P = (0.0, r1)
    N1 = (P[0] - r1 * math.sin(s.alpha) * u[0], P[1] - r1 * math.sin(s.alpha) * u[1])
    N2 = (P[0] + r2 * math.sin(s.alpha) * u[0], P[1] + r2 * math.sin(s.alpha) * u[1])
    t1 = math.sqrt(ra1 ** 2 - rb1 ** 2)
    t2 = math.sqrt(ra2 ** 2 - rb2 ** 2)
    B1 = (N1[0] + t1 * u[0], N1[1] + t1 * u[1])
    B2 = (N2[0] - t2 * u[0], N2[1] - t2 * u[1])
    pb = math.pi * s.m * math.cos(s.alpha)
    L = math.dist(B1, B2)
    eps = L / pb
    zp = ((B2[0] + pb * u[0], B2[1] + pb * u[1]), (B1[0] - pb * u[0], B1[1] - pb * u[1])) if 1 <= eps < 2 else ()
    return MeshConstruction((0.0, 0.0), (0.0, a), P, N1, N2, B1, B2, a, s.alpha, r1, r2, pb, L,
                            math.dist(N1, N2), eps, zp, (2 - eps) * pb if zp else None,
                            (eps - 1) * pb if zp else None, {}, None, ())


def pair(z1: int = 19, z2: int = 42, s: ToothSystem = SYSTEM, scales: dict | None = None) -> GearDrawing:
    g1, g2 = SpurGear(z1), SpurGear(z2)
    return GearDrawing(GearSet(s, (g1, g2), "external"), scales or {"l": 0.002, "tooth": 0.0005, "zones": 0.0005},
                       teeth=(("1", outline(s, g1)),),
                       at_radii=(("1", at(s, g1, radii(s, g1)[0])), ("1", at(s, g1, radii(s, g1)[2])),
                                 ("1", at(s, g1, 0.081))),
                       mesh=mesh(s, z1, z2))


def single(z: int = 20, undercut: bool = False, mu_tooth: float = 0.0005) -> GearDrawing:
    g = SpurGear(z)
    r, rb, ra, rf = radii(SYSTEM, g)
    sp = span_of(SYSTEM, g, 3)
    return GearDrawing(GearSet(SYSTEM, (g,)), {"l": 0.001, "tooth": mu_tooth},
                       teeth=(("", outline(SYSTEM, g, undercut=undercut)),),
                       at_radii=(("", at(SYSTEM, g, r)), ("", at(SYSTEM, g, ra))), span=(("", sp),),
                       root_base=(41.45, float(z)))


def span_of(s: ToothSystem, g: SpurGear, k: int) -> SpanMeasurement:
    """Over k teeth centred on tooth 0 (odd k): the base tangent at the top, K on the outer flanks."""
    _, rb, _, _ = radii(s, g)
    W = s.m * math.cos(s.alpha) * ((k - 0.5) * math.pi + g.z * inv(s.alpha))
    N = (0.0, rb)
    return SpanMeasurement(k, N, (-W / 2, rb), (W / 2, rb), W)


def texts(sheet: Sheet, panel: str | None = None) -> list[str]:
    return [i.text for p in sheet.panels if panel is None or p.name == panel for i in p.items
            if isinstance(i, (Label, Text))]


def items(sheet: Sheet, panel: str) -> tuple:
    return next(p for p in sheet.panels if p.name == panel).items


ALL = list(PANELS)
