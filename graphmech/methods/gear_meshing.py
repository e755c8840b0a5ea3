"""Two gears in mesh, constructed as the book does (Fig. 5-19 of the Chinese text).

Gear 1 (the driver) at O₁ = (0, 0); gear 2 above it at O₂ = (0, a′) for an external pair, below
at O₂ = (0, −a′) for a ring, or a rack whose reference line is y = a′. The pitch point P lies on
O₁O₂ (on the y axis); the line of action N₁N₂ is tangent to both base circles through P, rising
to the right at α′ to the common tangent (gear 1 turns clockwise); the tip circles cut it at B₂
(gear 2's tip: contact begins) and B₁ (gear 1's tip: contact ends). Everything measured here —
α′, B₁B₂, p_b, the zones, the radii of curvature at B₁, B₂ — is a length or angle on that
construction; the closed forms are :mod:`graphmech.exact.gear`'s.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.geometry.kernels import (
    ScalarOps,
    intersect_circle_line,
    intersect_circles,
    intersect_lines,
    unit,
)
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem
from graphmech.methods.involute import at_radius, bisect_root, circles

XY = tuple[float, float]


@dataclass(frozen=True)
class MeshConstruction:
    """The construction of a pair in mesh (m, rad).

    O2, N2, r_w2 are None for a rack (N₂ is at infinity along the line of action). ``a_w`` is the
    centre distance drawn (a′), ``alpha_w`` the angle measured between N₁N₂ and the common tangent
    at P, ``r_w1``/``r_w2`` the working pitch radii (O₁P, O₂P). ``pb`` the base pitch as laid off
    on the line of action, ``B1B2``, ``N1N2`` (None for a rack), ``eps_alpha`` = B₁B₂/p_b.
    ``zone_points``: the points at p_b from B₁ and from B₂ on B₁B₂ (bounding the double-contact
    zones at its ends and the single-contact zone between), empty when ε < 1 or ε ≥ 2;
    ``single_contact``/``double_contact`` their lengths (None likewise). ``rho``: the radii of
    curvature at the ends of contact, {"N1B1", "N1B2", "N2B1", "N2B2"} (N2… absent for a rack),
    signed: negative where the contact lies beyond N (interference).
    ``backlash``: circumferential, on the working pitch circle, from the flanks constructed there
    (None unless the set states both a′ and the shifts). ``interference``: B₁ or B₂ beyond N₂ or
    N₁ ("B1 beyond N2" …), empty when the contact lies within N₁N₂."""

    O1: XY
    O2: XY | None
    P: XY
    N1: XY
    N2: XY | None
    B1: XY
    B2: XY
    a_w: float
    alpha_w: float
    r_w1: float
    r_w2: float | None
    pb: float
    B1B2: float
    N1N2: float | None
    eps_alpha: float
    zone_points: tuple[XY, ...]
    single_contact: float | None
    double_contact: float | None
    rho: dict[str, float]
    backlash: float | None
    interference: tuple[str, ...]


def _dist(a: XY, b: XY) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def _along(a: XY, u: tuple[float, float], length: float) -> XY:
    return (a[0] + length * u[0], a[1] + length * u[1])


@dataclass(frozen=True)
class ActionLine:
    """The line of action drawn at a′: N₁, N₂ (None for a rack), P, and its direction."""

    O2: XY | None
    N1: XY
    N2: XY | None
    P: XY
    u: tuple[float, float]


def line_of_action(system: ToothSystem, g1: SpurGear, g2: SpurGear | None, meshing: str, a_w: float) -> ActionLine:
    """O₁O₂ drawn at a′ and the common tangent of the base circles rising to the right: the
    tangent from O₁ to the circle (O₂, r_b1 ± r_b2) — Thales' circle on O₁O₂ — touches it at T;
    N₂ is O₂ + r_b2·O₂T/|O₂T| and N₁ is O₁ ± r_b1 along the same direction (internal tangent of an
    external pair: opposite; external tangent for a ring: the same). P = N₁N₂ ∩ O₁O₂.
    A rack: its flank's normal at α tangent to the base circle (α′ = α)."""
    ops = ScalarOps()
    _, rb1, _, _ = circles(system, g1)
    O1 = (0.0, 0.0)
    if meshing == "rack":
        N1 = (-rb1 * math.sin(system.alpha), rb1 * math.cos(system.alpha))
        u = (math.cos(system.alpha), math.sin(system.alpha))
        ops.step = "P = line of action ∩ O1's normal to the rack"
        P = intersect_lines(ops, (N1[0], N1[1], u[0], u[1]), (0.0, 0.0, 0.0, 1.0))
        return ActionLine(None, N1, None, (float(P[0]), float(P[1])), u)
    assert g2 is not None
    _, rb2, _, _ = circles(system, g2)
    ring = meshing == "internal"
    O2 = (0.0, -a_w) if ring else (0.0, a_w)
    aux = rb2 - rb1 if ring else rb1 + rb2
    ops.step = "T = circle (O2, rb2 ∓ rb1) ∩ circle on O1O2"
    mid = (O2[0] / 2.0, O2[1] / 2.0)
    candidates = [intersect_circles(ops, O2, aux, mid, a_w / 2.0, side,
                                    lambda d: "the base circles have no common tangent at this centre distance")
                  for side in (1.0, -1.0)]
    # the tangent rising to the right has N₁ (hence T seen from O₂, for either kind) up and left
    T = min(candidates, key=lambda t: t[0])
    n = unit(ops, O2, (float(T[0]), float(T[1])))
    N2 = _along(O2, n, rb2)
    N1 = _along(O1, n, rb1) if ring else _along(O1, n, -rb1)
    if N1[0] > 0.0:  # the other tangent was taken: mirror it
        N1, N2 = (-N1[0], N1[1]), (-N2[0], N2[1])
    u3 = unit(ops, N1, N2) if not ring else unit(ops, N2, N1)
    u = (u3[0], u3[1])
    ops.step = "P = N1N2 ∩ O1O2"
    P = intersect_lines(ops, (N1[0], N1[1], u[0], u[1]), (0.0, 0.0, 0.0, 1.0))
    return ActionLine(O2, N1, N2, (float(P[0]), float(P[1])), u)


def _backlash(system: ToothSystem, gears: GearSet, line: ActionLine, a_w: float) -> float:
    """The circumferential backlash on the working pitch circle: the working pitch 2π r_w1/z₁ less
    the two teeth's arc thicknesses constructed there (a rack: its space on its working pitch line
    less the pinion's tooth)."""
    g1 = gears.gears[0]
    r_w1 = math.hypot(*line.P)
    s1 = at_radius(system, g1, r_w1).s_k
    if gears.meshing == "rack":
        # the rack's flanks are straight at α: its space on the line y = r_w1, a′ − r_w1 below its
        # reference line where the space is πm/2
        depth = a_w - r_w1
        return math.pi * system.m / 2.0 + 2.0 * depth * math.tan(system.alpha) - s1
    g2 = gears.gears[1]
    assert line.O2 is not None
    s2 = at_radius(system, g2, _dist(line.O2, line.P)).s_k
    return 2.0 * math.pi * r_w1 / g1.z - s1 - s2


def construct_meshing(gears: GearSet) -> MeshConstruction:
    """The pair drawn at a′ (stated, or the distance without backlash: a bisection on a′ of the
    backlash constructed from the flanks on the working pitch circles, to the last bit of a′),
    the line of action and B₁B₂ cut from it by the tip circles (a rack: its addendum line)."""
    if gears.meshing is None:
        raise NotApplicable("one gear alone does not mesh: state meshing = external, internal or rack")
    system, meshing = gears.system, gears.meshing
    need = 1 if meshing == "rack" else 2
    if len(gears.gears) != need:
        raise OutOfDomain(f"a {meshing} pair has {need} gear(s) here, not {len(gears.gears)}")
    g1 = gears.gears[0]
    g2 = gears.gears[1] if need == 2 else None
    if g1.internal or (meshing == "external" and g2 is not None and g2.internal):
        raise OutOfDomain("in an external pair neither gear is a ring; in an internal pair only gear 2 is")
    if meshing == "internal" and g2 is not None and not g2.internal:
        raise OutOfDomain("in an internal pair gear 2 is the ring (internal = true)")
    r1, rb1, _, _ = circles(system, g1)
    m = system.m
    if meshing == "internal" and g2 is not None:
        _, rb2, ra2, _ = circles(system, g2)
        if ra2 < rb2:
            raise NotApplicable(f"the ring's tip circle (r_a2 = {ra2 * 1e3:.6g} mm) lies inside its base circle "
                                f"(r_b2 = {rb2 * 1e3:.6g} mm): it never reaches the line of action")

    def drawn(a_w: float) -> ActionLine:
        return line_of_action(system, g1, g2, meshing, a_w)

    if gears.centre_distance is not None:
        a_w = gears.centre_distance
        if not (a_w > 0 and math.isfinite(a_w)):
            raise OutOfDomain(f"the centre distance must be positive and finite, not {a_w!r}")
        line = drawn(a_w)
        j = _backlash(system, gears, line, a_w)
        if j < -1e-12 * m:
            raise NoSolution(f"the teeth overlap by {-j * 1e3:.6g} mm on the working pitch circle at "
                             f"a′ = {a_w * 1e3:.6g} mm: the pair cannot be assembled this close")
        backlash: float | None = j
    else:
        backlash = None
        if meshing == "rack":
            a_w = r1 + g1.x * m
        else:
            assert g2 is not None
            r2, rb2, _, _ = circles(system, g2)
            if meshing == "internal":  # between the base circles crossing and touching inside
                lo, hi = abs(rb2 - rb1) * (1.0 + 1e-9), rb2 + rb1
            else:
                lo, hi = (rb1 + rb2) * (1.0 + 1e-9), 2.0 * (r1 + r2 + 4.0 * m)
            grid = [lo + (hi - lo) * i / 256 for i in range(257)]

            def gap(a: float) -> float:
                return _backlash(system, gears, drawn(a), a)

            values = []
            found = None
            for i, a in enumerate(grid):
                try:
                    values.append(gap(a))
                except (NoSolution, OutOfDomain, ArithmeticError):
                    values.append(math.nan)
                if i and not math.isnan(values[-1]) and not math.isnan(values[-2]) and \
                        (values[-1] > 0.0) != (values[-2] > 0.0):
                    found = i
                    break
            if found is None:
                raise NoSolution("no centre distance lets these teeth mesh without backlash")
            a_w = bisect_root(gap, grid[found - 1], grid[found])
        line = drawn(a_w)
    return _measure(gears, line, a_w, backlash)


def _measure(gears: GearSet, line: ActionLine, a_w: float, backlash: float | None) -> MeshConstruction:
    system, meshing = gears.system, gears.meshing
    g1 = gears.gears[0]
    _, rb1, ra1, _ = circles(system, g1)
    ops = ScalarOps()
    P, u, N1, N2 = line.P, line.u, line.N1, line.N2
    lo = (P[0], P[1], u[0], u[1])
    ops.step = "B1 = gear 1's tip circle ∩ N1N2"
    B1 = intersect_circle_line(ops, (0.0, 0.0), ra1, lo, 1.0,
                               lambda e: "gear 1's tip circle misses the line of action")
    if meshing == "rack":
        ops.step = "B2 = the rack's addendum line ∩ N1N2"
        B2 = intersect_lines(ops, (0.0, a_w - system.ha_star * system.m, 1.0, 0.0), lo)
    else:
        g2 = gears.gears[1]
        _, _, ra2, _ = circles(system, g2)
        assert line.O2 is not None
        ops.step = "B2 = gear 2's tip circle ∩ N1N2"
        B2 = intersect_circle_line(ops, line.O2, ra2, lo, -1.0 if meshing == "external" else 1.0,
                                   lambda e: "gear 2's tip circle misses the line of action")
    B1 = (float(B1[0]), float(B1[1]))
    B2 = (float(B2[0]), float(B2[1]))
    pb = 2.0 * math.pi * rb1 / g1.z
    B1B2 = _dist(B1, B2)
    if (B1[0] - B2[0]) * u[0] + (B1[1] - B2[1]) * u[1] < 0.0:
        raise NoSolution("the tip circles cut the line of action in the wrong order: the teeth do not come into contact")
    eps = B1B2 / pb
    zone: tuple[XY, ...] = ()
    single = double = None
    if 1.0 <= eps < 2.0:
        Za = _along(B1, u, -pb)
        Zb = _along(B2, u, pb)
        zone = (Za, Zb)
        single, double = _dist(Za, Zb), _dist(B2, Za)
    def along(frm: XY, to: XY) -> float:  # (to − frm)·u: a length on N₁N₂, signed along it
        return (to[0] - frm[0]) * u[0] + (to[1] - frm[1]) * u[1]

    # the radii of curvature at B₁, B₂, negative where the contact point lies beyond N (interference)
    rho = {"N1B1": along(N1, B1), "N1B2": along(N1, B2)}
    notes = []
    if (B2[0] - N1[0]) * u[0] + (B2[1] - N1[1]) * u[1] < 0.0:
        notes.append("B2 beyond N1")
    if N2 is not None:
        # gear 2's centre of curvature N₂ lies ahead of P along u for an external pair, behind N₁ for a ring
        sign = 1.0 if meshing == "internal" else -1.0
        rho["N2B1"], rho["N2B2"] = sign * along(N2, B1), sign * along(N2, B2)
        if meshing == "external" and (B1[0] - N2[0]) * u[0] + (B1[1] - N2[1]) * u[1] > 0.0:
            notes.append("B1 beyond N2")
    alpha_w = math.atan2(u[1], u[0])
    return MeshConstruction(
        O1=(0.0, 0.0), O2=line.O2, P=P, N1=N1, N2=N2, B1=B1, B2=B2, a_w=a_w, alpha_w=alpha_w,
        r_w1=math.hypot(*P), r_w2=None if line.O2 is None else _dist(line.O2, P), pb=pb, B1B2=B1B2,
        N1N2=None if N2 is None else _dist(N1, N2), eps_alpha=eps, zone_points=zone, single_contact=single,
        double_contact=double, rho=rho, backlash=backlash, interference=tuple(notes))

__all__ = ["MeshConstruction", "construct_meshing"]
