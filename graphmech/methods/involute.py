"""The involute tooth constructed as the book draws it: by points.

The base circle is divided, a tangent drawn at each division N, and the arc unwound from the
flank's start to N laid off along it: K = N − r_b·φ·t (the string unwound from the base circle).
A point at a stated radius r_k is found the same way with φ = tan α_k (the tangent length NK is
√(r_k² − r_b²), the leg of the right triangle ONK). Thicknesses are arcs between the two flanks'
points, radii of curvature the lengths NK; nothing here uses inv α = tan α − α, which is the
exact solution's (:mod:`graphmech.exact.gear`).

Placement: the gear's centre O at the origin, tooth 0 centred on +y, the drawn teeth 0, ±1 …
around it; lengths in m, angles in rad.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.geometry.kernels import (
    ScalarOps,
    intersect_circles,
    intersect_lines,
    unit,
)
from graphmech.mechanisms.gear import SpurGear, ToothSystem

XY = tuple[float, float]


@dataclass(frozen=True)
class Flank:
    """One flank by points: the start on the base circle, the points K₀ … K_{N−1} from the base
    (or from where the fillet meets it) to the tip, and the strings (N_i, K_i) drawn for them."""

    start: XY
    points: tuple[XY, ...]
    strings: tuple[tuple[XY, XY], ...]


@dataclass(frozen=True)
class ToothOutline:
    """A gear's drawn teeth about O = (0, 0): its circles (m), each tooth's (left, right) flanks,
    the root fillets traced by the cutter's tip between them, and the closed outline of the drawn
    sector (flanks, tip arcs, fillets, root arcs) as one polyline. ``undercut``: the fillet cuts
    into the involute above the base circle (the cutter's tip line passes beyond N)."""

    r: float
    rb: float
    ra: float
    rf: float
    teeth: tuple[tuple[Flank, Flank], ...]
    fillets: tuple[tuple[XY, ...], ...]
    outline: tuple[XY, ...]
    undercut: bool
    r_start: float


@dataclass(frozen=True)
class AtRadius:
    """Tooth 0 cut by the circle r_k: the points K on its left and right flank, their strings'
    ends N on the base circle, and what is measured there: α_k (the angle at O between OK and ON),
    the arc thickness s_k between the two K, ρ_k = NK, θ_k the polar angle of K from its flank's
    start on the base circle."""

    r_k: float
    K_left: XY
    K_right: XY
    N_left: XY
    N_right: XY
    alpha_k: float
    s_k: float
    rho_k: float
    theta_k: float


@dataclass(frozen=True)
class SpanMeasurement:
    """The span W_k over k teeth: a line tangent to the base circle (the caliper's jaws are
    perpendicular to it) and its points K₁, K₂ on the two outer flanks of k teeth; W = |K₁K₂|."""

    k: int
    N: XY
    K1: XY
    K2: XY
    W: float


@dataclass(frozen=True)
class PinMeasurement:
    """Pins of diameter d_p in two spaces opposite (or nearest opposite, odd z): their centres,
    the points where they touch the flanks, and M over them (between them for an internal gear)."""

    d_pin: float
    centres: tuple[XY, XY]
    contacts: tuple[XY, ...]
    M: float


# ------------------------------------------------------------------------------ the circles

def _check(system: ToothSystem, gear: SpurGear) -> None:
    if not (system.m > 0 and math.isfinite(system.m)):
        raise OutOfDomain(f"the module must be positive and finite, not {system.m!r}")
    if not 0 < system.alpha < math.pi / 2:
        raise OutOfDomain(f"the pressure angle must lie between 0 and 90°, not {math.degrees(system.alpha):g}°")
    if gear.z < 1:
        raise OutOfDomain(f"a gear has at least one tooth, not z = {gear.z}")


def circles(system: ToothSystem, gear: SpurGear) -> tuple[float, float, float, float]:
    """The reference, base, tip and root radii (r, r_b, r_a, r_f) drawn for the gear (m).

    r = mz/2, r_b = r cos α; an external gear's tip and root lie (h*a + x)m outside and
    (h*a + c* − x)m inside the reference circle, a ring's (h*a − x)m inside and (h*a + c* + x)m
    outside (:mod:`graphmech.mechanisms.gear`)."""
    _check(system, gear)
    m = system.m
    r = m * gear.z / 2.0
    rb = r * math.cos(system.alpha)
    if gear.internal:
        return r, rb, r - (system.ha_star - gear.x) * m, r + (system.ha_star + system.c_star + gear.x) * m
    return r, rb, r + (system.ha_star + gear.x - gear.delta_y) * m, r - (system.ha_star + system.c_star - gear.x) * m


def _thickness(system: ToothSystem, gear: SpurGear) -> float:
    """The tooth's arc thickness on the reference circle: πm/2 ± 2xm tan α (+ external, − ring,
    whose *space* is the external tooth's)."""
    shift = 2.0 * gear.x * system.m * math.tan(system.alpha)
    return math.pi * system.m / 2.0 + (-shift if gear.internal else shift)


def _polar(p: XY) -> float:
    return math.atan2(p[1], p[0])


def _turn(p: XY, angle: float) -> XY:
    c, s = math.cos(angle), math.sin(angle)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


def _mirror(p: XY, axis: float) -> XY:
    """p reflected in the line through O at polar angle ``axis``."""
    c, s = math.cos(2.0 * axis), math.sin(2.0 * axis)
    return (c * p[0] + s * p[1], s * p[0] - c * p[1])


def _angle_between(a: XY, b: XY) -> float:
    """The signed angle at O from OA to OB (counter-clockwise positive), in (−π, π]."""
    return math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1])


def _arc(radius: float, start: float, stop: float, step: float = math.radians(2.0)) -> list[XY]:
    """Points on the circle ``radius`` from polar angle start to stop (both included)."""
    n = max(2, math.ceil(abs(stop - start) / step) + 1)
    return [(radius * math.cos(start + (stop - start) * i / (n - 1)), radius * math.sin(start + (stop - start) * i / (n - 1)))
            for i in range(n)]


# ------------------------------------------------------------------------------ one flank

@dataclass(frozen=True)
class _Involute:
    """One flank's involute: the base radius, the polar angle θ₀ of its start on the base circle
    and the sense σ in which its string unwinds (+1 counter-clockwise)."""

    rb: float
    theta0: float
    sigma: int

    def string(self, phi: float) -> tuple[XY, XY]:
        """(N, K): the tangent point at θ₀ + σφ and the string's end K = N − σ·r_b·φ·t_ccw(N)."""
        a = self.theta0 + self.sigma * phi
        c, s = math.cos(a), math.sin(a)
        length = self.sigma * self.rb * phi
        return (self.rb * c, self.rb * s), (self.rb * c + length * s, self.rb * s - length * c)

    def at(self, r_k: float) -> tuple[XY, XY]:
        """(N, K) at radius r_k: φ = NK/r_b with NK = √(r_k² − r_b²) from the right triangle ONK."""
        return self.string(_unwound(self.rb, r_k))

    def through(self, N: XY) -> XY:
        """K whose string touches the base circle at N: φ is the arc from the start to N."""
        phi = self.sigma * _wrapped(_polar(N) - self.theta0)
        return self.string(phi)[1]


def _unwound(rb: float, r_k: float) -> float:
    """φ = √(r_k² − r_b²)/r_b (the tangent length over the base radius)."""
    if r_k < rb * (1.0 - 1e-14):
        raise OutOfDomain(f"r_k = {r_k:g} m lies inside the base circle (r_b = {rb:g} m): the involute has no point there")
    return math.sqrt(max((r_k - rb) * (r_k + rb), 0.0)) / rb


def _wrapped(a: float) -> float:
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def _tangent_point(rb: float, X: XY, side: float) -> XY:
    """The point N where a tangent from X touches the base circle (Thales: the circle on OX as
    diameter ∩ the base circle), on the left (+1) or right (−1) of OX."""
    ops = ScalarOps()
    ops.step = "N = base circle ∩ circle on OX"
    half = (X[0] / 2.0, X[1] / 2.0)
    x, y = intersect_circles(ops, (0.0, 0.0), rb, half, math.hypot(*half), side,
                             lambda d: "the point lies inside the base circle: no tangent from it")
    return (float(x), float(y))


def _flank(system: ToothSystem, gear: SpurGear, centre: float, right: bool) -> _Involute:
    """The involute of the right (or left) flank of the tooth centred at polar angle ``centre``.

    Its reference point C is laid off s/2 along the reference circle from the tooth's axis; the
    tangent from C to the base circle touches it at N_C, and the string NC unwound back along the
    base circle gives the flank's start: θ₀ = ∠N_C − σ·|N_C C|/r_b. An external tooth narrows
    outward, so its right flank unwinds counter-clockwise (σ = +1); a ring's tooth widens
    outward and its right flank unwinds clockwise."""
    r, rb, _, _ = circles(system, gear)
    sigma = (1 if right else -1) * (-1 if gear.internal else 1)
    psi = _thickness(system, gear) / (2.0 * r)
    a = centre - psi if right else centre + psi
    C = (r * math.cos(a), r * math.sin(a))
    N = _tangent_point(rb, C, sigma)
    return _Involute(rb, _polar(N) - sigma * math.hypot(C[0] - N[0], C[1] - N[1]) / rb, sigma)


def _flanks(system: ToothSystem, gear: SpurGear, centre: float) -> tuple[_Involute, _Involute]:
    return _flank(system, gear, centre, right=False), _flank(system, gear, centre, right=True)


# ------------------------------------------------------------------------------ at a radius

def at_radius(system: ToothSystem, gear: SpurGear, r_k: float) -> AtRadius:
    """Tooth 0 cut by the circle r_k (≥ r_b): both flanks' points K by their strings, the arc
    between them s_k = r_k·∠K_right O K_left (signed: negative past the pointed tip), ρ_k = |NK|,
    α_k = ∠KON, θ_k = the polar angle of K measured from its flank's start. For a ring the
    thickness is its tooth's (the space is the external tooth's shape)."""
    left, right = _flanks(system, gear, math.pi / 2.0)
    N_l, K_l = left.at(r_k)
    N_r, K_r = right.at(r_k)
    return AtRadius(
        r_k=r_k, K_left=K_l, K_right=K_r, N_left=N_l, N_right=N_r,
        alpha_k=abs(_angle_between(K_r, N_r)),
        s_k=r_k * _angle_between(K_r, K_l),
        rho_k=math.hypot(K_r[0] - N_r[0], K_r[1] - N_r[1]),
        theta_k=abs(_wrapped(_polar(K_r) - right.theta0)),
    )


def bisect_root(f: Callable[[float], float], lo: float, hi: float) -> float:
    """The root of f between lo and hi (f changes sign there), halved until the interval stops
    shrinking in floating point (≈ 1e-16 relative)."""
    f_lo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        f_mid = f(mid)
        if f_mid == 0.0:
            return mid
        if (f_mid > 0.0) == (f_lo > 0.0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def pointed_tip(system: ToothSystem, gear: SpurGear) -> AtRadius:
    """Where the two flanks of an external tooth meet (s_k = 0): the string length φ at which the
    constructed thickness changes sign, found by stepping φ by 0.05 and then bisection on the
    constructed s_k (to the last bit of φ, ≈ 1e-15 relative in r_k); returned as
    :func:`at_radius` there. A ring's tooth widens outward and is never pointed."""
    if gear.internal:
        raise NotApplicable("a ring's tooth widens outward: its flanks never meet")
    _, rb, _, _ = circles(system, gear)

    def thickness(phi: float) -> float:
        return at_radius(system, gear, rb * math.hypot(1.0, phi)).s_k

    if thickness(0.0) <= 0.0:
        raise NoSolution("the flanks already cross on the base circle: the tooth has no involute part")
    lo = 0.0
    while thickness(lo + 0.05) > 0.0:
        lo += 0.05
    phi = bisect_root(thickness, lo, lo + 0.05)
    return at_radius(system, gear, rb * math.hypot(1.0, phi))


# ------------------------------------------------------------------------------ the tooth drawn

@dataclass(frozen=True)
class _Cutter:
    """The rack cutter's tip rounding as it generates the space centred on +y: its centre
    (x_c, y_c) in the frame where the blank's reference circle touches the rolling line y = r at
    (0, r) (the pitch point I), its radius ρ_f, and the rolling angles β₀ (the rounding's lowest
    point cuts the root circle) and β₁ (its tangent point Q with the straight flank is in contact)."""

    r: float
    xc: float
    yc: float
    rho: float
    beta0: float
    beta1: float

    def centre(self, beta: float) -> XY:
        """The rounding's centre in the blank's frame after the blank turned β clockwise and the
        cutter moved rβ to the right: a point of the trochoid."""
        return _turn((self.xc + self.r * beta, self.yc), beta)

    def envelope(self, beta: float) -> XY:
        """The fillet's point at β: the trochoid's normal passes through the pole I, so the
        rounding touches the envelope on the line I–centre, on the gear's side (away from the
        cutter's body: its outward normal points down)."""
        vx, vy = self.xc + self.r * beta, self.yc - self.r
        n = math.hypot(vx, vy)
        if n == 0.0:
            ux, uy = 0.0, -1.0
        else:
            sign = 1.0 if vy < 0.0 else -1.0
            ux, uy = sign * vx / n, sign * vy / n
        return _turn((self.xc + self.r * beta + self.rho * ux, self.yc + self.rho * uy), beta)


def _cutter(system: ToothSystem, gear: SpurGear) -> _Cutter:
    r, _, _, _ = circles(system, gear)
    m, alpha = system.m, system.alpha
    ops = ScalarOps()
    datum = r + gear.x * m  # the cutter's reference line, x·m beyond the rolling line
    tip = datum - (system.ha_star + system.c_star) * m

    def centre(rho: float) -> tuple[float, float]:
        # The cutter's right flank through (πm/4, datum) inclined at α to the vertical; the
        # rounding is tangent to it and to the tip line: its centre on both lines drawn ρ_f inside.
        ops.step = "rounding centre = (flank moved ρ_f in) ∩ (tip line moved ρ_f up)"
        x, y = intersect_lines(
            ops,
            (math.pi * m / 4.0 - rho * math.cos(alpha), datum + rho * math.sin(alpha), math.sin(alpha),
             math.cos(alpha)),
            (0.0, tip + rho, 1.0, 0.0),
        )
        return float(x), float(y)

    sharp = centre(0.0)[0]  # half the basic rack's tip width: πm/4 − (h*a + c*)m·tan α
    if sharp <= 0.0:
        raise NotApplicable(f"the basic rack's tooth is pointed before its tip line at α = {math.degrees(alpha):g}° "
                            "(its tip width πm/2 − 2(h*a + c*)m·tan α ≤ 0): no cutter has these teeth")
    rho = system.c_star * m / (1.0 - math.sin(alpha))  # the full rounding that fills the clearance
    xc, yc = centre(rho)
    if xc < 0.0:  # the two roundings would overlap across the tip: they meet at its middle instead
        rho *= sharp / (sharp - xc)  # the centre's x is linear in ρ_f
        xc, yc = 0.0, centre(rho)[1]
    # Q, the rounding's tangent point with the flank; it is in contact when its normal (the
    # flank's, (cos α, −sin α)) passes through the pole: the cutter has moved −x_cross.
    Q = (xc + rho * math.cos(alpha), yc - rho * math.sin(alpha))
    ops.step = "normal at Q ∩ rolling line"
    x_cross, _ = intersect_lines(ops, (Q[0], Q[1], math.cos(alpha), -math.sin(alpha)), (0.0, r, 1.0, 0.0))
    return _Cutter(r, xc, yc, rho, -xc / r, -x_cross / r)


def cutter_rounding(system: ToothSystem, gear: SpurGear) -> tuple[float, float, float]:
    """The rack cutter's right tip rounding as :func:`tooth_outline`'s fillet constructs it: its
    centre's distance x_c from the cutter tooth's axis, its height above the cutter's datum line
    (negative: below it) and ρ_f (what :mod:`graphmech.methods.rack_generation` draws the cutter with)."""
    c = _cutter(system, gear)
    return c.xc, c.yc - (c.r + gear.x * system.m), c.rho


def _fillet_and_start(system: ToothSystem, gear: SpurGear) -> tuple[list[XY], float, bool]:
    """The fillet under the left flank of the tooth right of the space centred on +y, from the
    root circle up to where the profile starts, that radius, and whether the gear is undercut.

    Not undercut, the fillet meets the involute at Q's point (the straight part of the cutter
    generates the involute from there). Undercut — Q's contact lies beyond N on the line of
    action — the fillet cuts the involute above the base circle: that crossing is found by
    bisection on β of the angle at O between the fillet's point and the involute's point at the
    same radius (to the last bit of β), after a bisection for the β at which the fillet comes
    down to the base circle."""
    r, rb, _, _ = circles(system, gear)
    cut = _cutter(system, gear)
    flank = _flank(system, gear, math.pi / 2.0 - math.pi / gear.z, right=False)
    alpha = system.alpha
    # the line of action of the cutter's right flank through I = (0, r), and its foot N
    d = (math.cos(alpha), -math.sin(alpha))
    Q_world = _turn(cut.envelope(cut.beta1), -cut.beta1)
    N_world = (r * math.sin(alpha) * d[0], r + r * math.sin(alpha) * d[1])
    beyond = (Q_world[0] - N_world[0]) * d[0] + (Q_world[1] - N_world[1]) * d[1]
    end = cut.beta1
    undercut = False
    if beyond > 0.0:
        def off(beta: float) -> float:
            E = cut.envelope(beta)
            return _wrapped(_polar(E) - _polar(flank.at(max(math.hypot(*E), rb))[1]))

        # at β₁ the fillet's end lies on the mirrored branch (in the space); where it comes down
        # to the base circle it lies inside the tooth: between the two it crosses the involute
        lo = cut.beta0
        if math.hypot(*cut.envelope(lo)) < rb:
            lo = bisect_root(lambda beta: math.hypot(*cut.envelope(beta)) - rb, cut.beta0, cut.beta1)
        if (off(lo) > 0.0) != (off(cut.beta1) > 0.0):
            end = bisect_root(off, lo, cut.beta1)
            undercut = True
    n = 24
    fillet = [cut.envelope(cut.beta0 + (end - cut.beta0) * i / (n - 1)) for i in range(n)]
    r_start = max(math.hypot(*fillet[-1]), rb)
    return fillet, r_start, undercut


def tooth_outline(system: ToothSystem, gear: SpurGear, teeth: int = 3, points: int = 12) -> ToothOutline:
    """``teeth`` teeth about +y (all z when teeth ≥ z), from left to right, each flank by
    ``points`` points evenly spaced in φ from where the profile starts to the tip.

    External gear: generated by the rack cutter, its root fillets are the envelope of the
    cutter's tip rounding (ρ_f = c*m/(1 − sin α)) — the rounding's centre traces a trochoid as the
    blank rolls its reference circle on the cutter's line x·m inside the cutter's reference line,
    and the fillet is that trochoid offset by ρ_f along its normal through the pole. Where the
    root circle lies below the base circle the profile between them is the fillet; where the
    fillet cuts the involute above the base circle the gear is ``undercut`` and the profile is
    the involute above that crossing only. ``r_start`` is where the involute profile starts.

    Ring: cut by a pinion cutter, it is drawn with a plain root corner (no fillets: ``fillets``
    is empty); its flanks run from the tip (inner) outward to the root, and where its tip circle
    lies inside its base circle the part inside is drawn as a radial line (the flank's first
    point on the tip circle, then its points from the base circle).

    ``outline`` runs from the middle of the space left of the first tooth to the middle of the
    space right of the last, then closes through O (external) or along a rim arc (h*a + c*)m
    outside the root circle (ring); with every tooth drawn it is the closed profile itself."""
    if points < 2:
        raise OutOfDomain(f"a flank needs at least 2 points, not {points}")
    if teeth < 1:
        raise OutOfDomain(f"draw at least one tooth, not {teeth}")
    r, rb, ra, rf = circles(system, gear)
    z = gear.z
    teeth = min(teeth, z)
    pitch = 2.0 * math.pi / z
    centres = [math.pi / 2.0 + pitch * j for j in range((teeth - 1) // 2, -(teeth // 2) - 1, -1)]
    if gear.internal:
        r_lo = max(ra, rb)
        p0, p1 = _unwound(rb, r_lo), _unwound(rb, rf)
        fillet0: list[XY] = []
        r_start, undercut = r_lo, False
    else:
        if ra <= rb:
            raise NoSolution(f"the tip circle (r_a = {ra:g} m) lies inside the base circle: the tooth has no involute")
        fillet0, r_start, undercut = _fillet_and_start(system, gear)
        p0, p1 = _unwound(rb, min(r_start, ra)), _unwound(rb, ra)
    phis = [p0 + (p1 - p0) * i / (points - 1) for i in range(points)]

    def drawn(ev: _Involute) -> Flank:
        strings = tuple(ev.string(phi) for phi in phis)
        pts = [K for _, K in strings]
        if gear.internal and ra < rb:
            start = ev.string(0.0)[0]
            pts.insert(0, (start[0] * ra / rb, start[1] * ra / rb))
        return Flank(start=ev.string(0.0)[0], points=tuple(pts), strings=strings)

    drawn_teeth: list[tuple[Flank, Flank]] = []
    fillets: list[tuple[XY, ...]] = []
    for c in centres:
        left, right = _flanks(system, gear, c)
        drawn_teeth.append((drawn(left), drawn(right)))
        if fillet0:
            # fillet0 is under the left flank of the tooth centred at π/2 − pitch/2 … rotate it
            # there; the right flank's is its mirror in the tooth's axis
            fl = tuple(_turn(p, c - (math.pi / 2.0 - pitch / 2.0)) for p in fillet0)
            fillets.append(fl)
            fillets.append(tuple(_mirror(p, c) for p in fl))
    outline = _outline(gear, centres, drawn_teeth, fillets, pitch, ra, rf, teeth == z)
    return ToothOutline(r=r, rb=rb, ra=ra, rf=rf, teeth=tuple(drawn_teeth), fillets=tuple(fillets),
                        outline=outline, undercut=undercut, r_start=r_start)


def _outline(gear: SpurGear, centres: list[float], teeth: list[tuple[Flank, Flank]], fillets: list[tuple[XY, ...]],
             pitch: float, ra: float, rf: float, whole: bool) -> tuple[XY, ...]:
    """Left to right (clockwise): root arc, fillet, left flank up, tip arc, right flank down,
    fillet, root arc … ."""
    path: list[XY] = []
    for i, (c, (left, right)) in enumerate(zip(centres, teeth)):
        if gear.internal:  # a ring's flank points run from its tip (inner) out to its root
            rising, falling = list(reversed(left.points)), list(right.points)
            below_l: list[XY] = []
            below_r: list[XY] = []
        else:
            rising, falling = list(left.points), list(reversed(right.points))
            below_l, below_r = list(fillets[2 * i]), list(reversed(fillets[2 * i + 1]))
        first = (below_l or rising)[0]
        last = (below_r or falling)[-1]
        path += _arc(rf, c + pitch / 2.0, _near(_polar(first), c))[:-1]
        path += below_l + rising
        path += _arc(ra, _near(_polar(rising[-1]), c), _near(_polar(falling[0]), c))[1:-1]
        path += falling + below_r
        path += _arc(rf, _near(_polar(last), c), c - pitch / 2.0)[1:]
    if whole:
        path.append(path[0])
        return tuple(path)
    if gear.internal:
        rim = rf + (rf - ra)
        a_end = _polar(path[-1])
        path += _arc(rim, a_end, a_end + pitch * len(centres))
    else:
        path.append((0.0, 0.0))
    path.append(path[0])
    return tuple(path)


def _near(angle: float, centre: float) -> float:
    """The polar angle ``angle`` taken within ±π of ``centre`` (so that arcs do not wrap)."""
    return centre + _wrapped(angle - centre)


# ------------------------------------------------------------------------------ measurement

def span(system: ToothSystem, gear: SpurGear, k: int) -> SpanMeasurement:
    """The span over teeth 0 … k−1 (tooth j centred at 90° − j·360°/z): the caliper's line
    tangent to the base circle at N on the group's axis; it is the normal of both outer flanks
    there, so it cuts each at the end of the string touching at N (the arc from the flank's
    start to N unwound). W = |K₁K₂|, K₁ on tooth 0's left flank, K₂ on tooth k−1's right one."""
    if gear.internal:
        raise NotApplicable("the span is measured over an external gear's teeth; a ring is measured over pins")
    if not 1 <= k < gear.z:
        raise OutOfDomain(f"the span is taken over 1 … z − 1 = {gear.z - 1} teeth, not k = {k}")
    _, rb, ra, _ = circles(system, gear)
    pitch = 2.0 * math.pi / gear.z
    axis = math.pi / 2.0 - (k - 1) * pitch / 2.0
    N = (rb * math.cos(axis), rb * math.sin(axis))
    K1 = _flank(system, gear, math.pi / 2.0, right=False).through(N)
    K2 = _flank(system, gear, math.pi / 2.0 - (k - 1) * pitch, right=True).through(N)
    reach = math.hypot(*K1)
    if reach > ra * (1.0 + 1e-12):
        raise OutOfDomain(f"over k = {k} teeth the jaws would touch the flanks at r = {reach:g} m, beyond the tip "
                          f"circle (r_a = {ra:g} m): take fewer teeth")
    return SpanMeasurement(k=k, N=N, K1=K1, K2=K2, W=math.hypot(K1[0] - K2[0], K1[1] - K2[1]))


def over_pins(system: ToothSystem, gear: SpurGear, d_pin: float | None = None) -> PinMeasurement:
    """Pins in space 0 (centred on the axis at 90° − 180°/z, between tooth 0 and tooth 1) and in
    the space opposite (even z) or the one nearest opposite (odd z).

    d_pin None: the pins touch the flanks on the reference circle; the flank's normal there is the
    tangent to the base circle through its reference point C, and it cuts the space's axis at the
    pin's centre X: d_p = 2|XC|. Given d_pin: the centre X on the space's axis at which the
    tangent from X to the base circle (the normal from X to the flank) measures d_p/2 from the
    flank, found by a scan of the axis and bisection on that constructed distance (to the last
    bit of |OX|). M = |X₁X₂| + d_p (a ring: |X₁X₂| − d_p, between the pins)."""
    r, rb, ra, rf = circles(system, gear)
    pitch = 2.0 * math.pi / gear.z
    axis = math.pi / 2.0 - pitch / 2.0
    flank = _flank(system, gear, math.pi / 2.0, right=True)
    ops = ScalarOps()
    if d_pin is None:
        N, C = flank.at(r)
        if math.atan2(C[1], C[0]) <= axis:  # the flank's reference point lies past the space's axis
            raise NoSolution("the tooth space on the reference circle is closed: no pin touches the flanks there "
                             "— state pin_diameter")
        ops.step = "X = normal at C ∩ the space's axis"
        u = unit(ops, N, C)
        x, y = intersect_lines(ops, (N[0], N[1], u[0], u[1]), (0.0, 0.0, math.cos(axis), math.sin(axis)))
        X = (float(x), float(y))
        K = C
        d = 2.0 * math.hypot(X[0] - C[0], X[1] - C[1])
    else:
        if not (d_pin > 0 and math.isfinite(d_pin)):
            raise OutOfDomain(f"the pin diameter must be positive and finite, not {d_pin!r}")
        d = d_pin
        outward = -1.0 if gear.internal else 1.0  # an external space widens outward, a ring's narrows

        def gap(R: float) -> float:
            X = (R * math.cos(axis), R * math.sin(axis))
            N = _tangent_point(rb, X, flank.sigma)
            Kp = flank.through(N)
            along = math.hypot(X[0] - N[0], X[1] - N[1]) - math.hypot(Kp[0] - N[0], Kp[1] - N[1])
            return outward * along - d / 2.0

        lo, hi = rb * (1.0 + 1e-9), (ra if not gear.internal else rf) + d
        steps = 256
        grid = [lo + (hi - lo) * i / steps for i in range(steps + 1)]
        values = [gap(R) for R in grid]
        found = next((i for i in range(steps) if (values[i] > 0.0) != (values[i + 1] > 0.0)), None)
        if found is None:
            raise NoSolution(f"no pin of diameter {d:g} m touches both flanks of a space")
        R = bisect_root(gap, grid[found], grid[found + 1])
        X = (R * math.cos(axis), R * math.sin(axis))
        K = flank.through(_tangent_point(rb, X, flank.sigma))
    reach = math.hypot(*K)
    if not gear.internal and reach > ra * (1.0 + 1e-12):
        raise OutOfDomain(f"a pin of diameter {d:g} m would touch above the tip circle: it rests on the tip corners")
    if gear.internal and reach > rf * (1.0 + 1e-12):
        raise OutOfDomain(f"a pin of diameter {d:g} m would not reach the flanks above the root circle")
    # even z: the space z/2 is at 180°; odd z: space (z − 1)/2 at 180° − 180°/z … turned there
    opposite = math.pi if gear.z % 2 == 0 else math.pi - pitch / 2.0
    X2 = _turn(X, opposite)
    K_mirror = _mirror(K, axis)
    contacts = (K, K_mirror, _turn(K, opposite), _turn(K_mirror, opposite))
    across = math.hypot(X[0] - X2[0], X[1] - X2[1])
    return PinMeasurement(d_pin=d, centres=(X, X2), contacts=contacts, M=across - d if gear.internal else across + d)

__all__ = ["AtRadius", "Flank", "PinMeasurement", "SpanMeasurement", "ToothOutline", "at_radius", "bisect_root",
           "circles", "cutter_rounding", "over_pins", "pointed_tip", "span", "tooth_outline"]
