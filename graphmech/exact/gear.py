"""Involute spur gears in closed form: the tooth, the measurements over it, a pair in mesh.

The independent reference for the constructions of :mod:`graphmech.methods.involute` and
:mod:`graphmech.methods.gear_meshing`: every value here comes from the involute's equation
(r_k = r_b / cos α_k, θ_k = inv α_k = tan α_k − α_k) and the book's formulas, never from a drawn
point. Imports only the gear model, ``math`` and the base modules.

Conventions (those of :mod:`graphmech.mechanisms.gear`): SI lengths, angles in rad.

- A gear's own circles carry no tip shortening: da = d + 2(h*a + x)m (a ring: d − 2(h*a − x)m);
  a pair meshes on the tip circles of :func:`tooth`.
- A ring's tooth *space* at the reference circle is e = πm/2 + 2xm·tan α, its tooth s = p − e;
  the space is bounded by involutes like an external tooth, so the ring's tooth *thickens* outward.
- A value that cannot exist is ``None`` in a record (a ring whose tip circle is inside its base
  circle has no α_a), and a refusal (:class:`~graphmech.errors.NotApplicable`) where the function
  asked for is that value. Something wrong with the gear but computable (an undercut, a pointed
  tooth, a contact ratio below 1, contact beyond N) is said in ``notes``, plain sentences.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem
from graphmech.tolerances import COINCIDENT_REL

HALF_PI = 0.5 * math.pi

# sin α − α cos α = Σ_{k≥1} (−1)^(k+1) · 2k/(2k+1)! · α^(2k+1): the coefficients of α³, α⁵, …
# Summed this way the involute keeps full relative precision at small α, where tan α − α cancels.
_SIN_MINUS_ALPHA_COS = tuple((-1) ** (k + 1) * 2 * k / math.factorial(2 * k + 1) for k in range(1, 13))


def inv(alpha: float) -> float:
    """The involute function inv α = tan α − α, for 0 ≤ α < π/2 (rad).

    Below α = 1 it is summed as (sin α − α cos α)/cos α with the numerator's series, so that it
    keeps its relative precision (tan α − α loses ~3/α² ulps to cancellation there).

    >>> round(inv(math.radians(20)), 12)
    0.014904383867
    """
    if not (math.isfinite(alpha) and 0.0 <= alpha < HALF_PI):
        raise OutOfDomain(f"the involute function takes a pressure angle from 0 to 90°, not {alpha!r} rad")
    if alpha >= 1.0:
        return math.tan(alpha) - alpha
    a2 = alpha * alpha
    acc = 0.0
    for c in reversed(_SIN_MINUS_ALPHA_COS):
        acc = acc * a2 + c
    return alpha * a2 * acc / math.cos(alpha)


def inv_inverse(v: float) -> float:
    """The pressure angle α ∈ [0, π/2) with inv α = tan α − α = v, for v ≥ 0.

    Newton's method on f(α) = inv α − v, which is increasing and convex on [0, π/2), started from
    an upper bound of the root, α₀ = min((3v)^(1/3), atan(v + π/2)) (inv α ≥ α³/3 and
    tan α = v + α < v + π/2), so that every step stays above the root and the iterates fall
    monotonically; it stops when a step no longer lowers α, and the float nearest the root of its
    neighbours is kept (α to ~1 ulp). inv(inv_inverse(v)) then equals v to about κ·ε, where
    κ = α tan²α / inv α is the involute's condition number (3 at small α, ≈ α·tan α ≈ 1.6e3 at v = 1e3).

    >>> round(math.degrees(inv_inverse(0.09344420020708127)), 9)
    35.471029508
    """
    if not (math.isfinite(v) and v >= 0.0):
        raise OutOfDomain(f"inv α = {v!r} has no pressure angle: the involute function takes values ≥ 0")
    if v == 0.0:
        return 0.0
    alpha = min(math.cbrt(3.0 * v), math.atan(v + HALF_PI))
    alpha = min(alpha, math.nextafter(HALF_PI, 0.0))
    for _ in range(200):
        t = math.tan(alpha)
        nxt = alpha - (inv(alpha) - v) / (t * t)
        if not nxt < alpha:
            break
        alpha = max(nxt, 0.0)
    best = alpha
    for near in (math.nextafter(alpha, 0.0), math.nextafter(alpha, HALF_PI)):
        if 0.0 <= near < HALF_PI and abs(inv(near) - v) < abs(inv(best) - v):
            best = near
    return best


# --------------------------------------------------------------------------------------------
# The tooth


def _check(system: ToothSystem, gear: SpurGear) -> None:
    if not (math.isfinite(system.m) and system.m > 0.0):
        raise OutOfDomain(f"the module m must be a positive length, not {system.m!r} m")
    if not (math.isfinite(system.alpha) and 0.0 < system.alpha < HALF_PI):
        raise OutOfDomain(f"the pressure angle α must lie between 0 and 90°, not {system.alpha!r} rad")
    if not (math.isfinite(system.ha_star) and system.ha_star >= 0.0
            and math.isfinite(system.c_star) and system.c_star >= 0.0):
        raise OutOfDomain("the addendum and clearance coefficients h*a, c* must be ≥ 0 "
                          f"(h*a = {system.ha_star!r}, c* = {system.c_star!r})")
    if isinstance(gear.z, bool) or not isinstance(gear.z, int) or gear.z < 1:
        raise OutOfDomain(f"the tooth number z must be a whole number ≥ 1, not {gear.z!r}")
    if not math.isfinite(gear.x):
        raise OutOfDomain(f"the shift coefficient x must be a finite number, not {gear.x!r}")


def _radii(system: ToothSystem, gear: SpurGear) -> tuple[float, float, float, float]:
    """(r, rb, ra, rf) of a gear (its tips shortened by Δy·m when the pair asks for it)."""
    m, x = system.m, gear.x
    r = 0.5 * m * gear.z
    if gear.internal:
        ra = r - (system.ha_star - x) * m
        rf = r + (system.ha_star + system.c_star + x) * m
    else:
        ra = r + (system.ha_star + x - gear.delta_y) * m  # Δy: the tips shortened in a shifted pair
        rf = r - (system.ha_star + system.c_star - x) * m
    return r, r * math.cos(system.alpha), ra, rf


def _s(system: ToothSystem, gear: SpurGear) -> float:
    """The tooth's arc thickness at the reference circle: πm/2 ± 2xm tan α (− for a ring)."""
    shift = 2.0 * gear.x * system.m * math.tan(system.alpha)
    return 0.5 * math.pi * system.m + (-shift if gear.internal else shift)


def _pressure_angle(rb: float, r_k: float) -> float:
    """α_k = arccos(rb/r_k), as atan2(√(r_k² − rb²), rb): accurate near the base circle."""
    return math.atan2(math.sqrt((r_k - rb) * (r_k + rb)), rb)


def _thickness(s: float, r: float, alpha: float, r_k: float, alpha_k: float, internal: bool) -> float:
    """s_k = s·r_k/r ∓ 2r_k(inv α_k − inv α): − for an external tooth, + for a ring's tooth."""
    change = 2.0 * r_k * (inv(alpha_k) - inv(alpha))
    return s * r_k / r + (change if internal else -change)


@dataclass(frozen=True)
class ToothValues:
    """A gear's circles and tooth (m, rad): reference, base, tip and root diameters d, db, da, df;
    addendum, dedendum and whole depth ha, hf, h (radial, from the reference circle); pitch and
    base pitch p = πm, pb = πm cos α; tooth and space at the reference circle s, e (s + e = p);
    tip and base thickness sa, sb (arcs, s_k at ra and rb); tip pressure angle alpha_a; radii of
    curvature of the profile at the reference and tip circles rho_pitch = rb tan α,
    rho_a = rb tan α_a. ``alpha_a``, ``sa``, ``rho_a`` are None for a ring whose tip circle lies
    inside its base circle (no involute there). ``notes``: what is wrong with the tooth, in words."""

    d: float
    db: float
    da: float
    df: float
    ha: float
    hf: float
    h: float
    p: float
    pb: float
    s: float
    e: float
    sa: float | None
    sb: float
    alpha_a: float | None
    rho_pitch: float
    rho_a: float | None
    notes: tuple[str, ...] = ()


def tooth(system: ToothSystem, gear: SpurGear) -> ToothValues:
    """The circles and the tooth of one gear.

    d = mz, db = d cos α; external da = d + 2(h*a + x)m, df = d − 2(h*a + c* − x)m,
    ha = (h*a + x)m, hf = (h*a + c* − x)m; a ring da = d − 2(h*a − x)m, df = d + 2(h*a + c* + x)m,
    ha = (h*a − x)m, hf = (h*a + c* + x)m. s = πm/2 + 2xm tan α (a ring: πm/2 − 2xm tan α), e = p − s.
    At any radius s_k = s·r_k/r − 2r_k(inv α_k − inv α) (a ring's tooth: + instead of −), so
    sa = s_k(ra) and sb = s_k(rb) = s cos α ± 2rb inv α.

    >>> t = tooth(ToothSystem(m=0.008, alpha=math.radians(20)), SpurGear(z=20))
    >>> round(t.sa * 1e3, 9), round(math.degrees(t.alpha_a), 9)
    (5.559039877, 31.32125793)
    """
    _check(system, gear)
    m, alpha = system.m, system.alpha
    r, rb, ra, rf = _radii(system, gear)
    p = math.pi * m
    s = _s(system, gear)
    notes: list[str] = []
    sb = _thickness(s, r, alpha, rb, 0.0, gear.internal)
    alpha_a: float | None
    sa: float | None
    rho_a: float | None
    if ra < rb:
        alpha_a = sa = rho_a = None
        notes.append(f"the tip circle (ra = {ra:.6g} m) lies inside the base circle (rb = {rb:.6g} m): "
                     "the teeth have no involute near their tips")
    else:
        alpha_a = _pressure_angle(rb, ra)
        sa = _thickness(s, r, alpha, ra, alpha_a, gear.internal)
        rho_a = rb * math.tan(alpha_a)
        if sa < 0.0:
            notes.append(f"the tooth is pointed below its tip circle (sa = {sa:.6g} m < 0): "
                         "its flanks meet before they reach ra")
    if not gear.internal and gear.x < system.ha_star - 0.5 * gear.z * math.sin(alpha) ** 2:
        notes.append(f"z = {gear.z} with x = {gear.x:g} is undercut when cut by a rack")
    ha = (system.ha_star - gear.x if gear.internal else system.ha_star + gear.x - gear.delta_y) * m
    hf = (system.ha_star + system.c_star + (gear.x if gear.internal else -gear.x)) * m
    return ToothValues(d=2.0 * r, db=2.0 * rb, da=2.0 * ra, df=2.0 * rf, ha=ha, hf=hf, h=ha + hf,
                       p=p, pb=p * math.cos(alpha), s=s, e=p - s, sa=sa, sb=sb, alpha_a=alpha_a,
                       rho_pitch=rb * math.tan(alpha), rho_a=rho_a, notes=tuple(notes))


@dataclass(frozen=True)
class RadiusValues:
    """The profile at radius r_k (m, rad): pressure angle α_k = arccos(rb/r_k), the tooth's arc
    thickness s_k there, the radius of curvature ρ_k = rb tan α_k = √(r_k² − rb²), and the polar
    angle θ_k = inv α_k of the point from its flank's start on the base circle."""

    alpha_k: float
    s_k: float
    rho_k: float
    theta_k: float


def at_radius(system: ToothSystem, gear: SpurGear, r_k: float) -> RadiusValues:
    """The tooth cut by the circle r_k ≥ rb (any radius on the involute, also beyond the tip).

    >>> v = at_radius(ToothSystem(m=0.008, alpha=math.radians(20)), SpurGear(z=20), 0.08)
    >>> round(v.s_k * 1e3, 9), round(v.rho_k * 1e3, 9)
    (12.566370614, 27.361611466)
    """
    _check(system, gear)
    r, rb, _, _ = _radii(system, gear)
    if not (math.isfinite(r_k) and r_k >= rb):
        raise OutOfDomain(f"the involute starts on the base circle rb = {rb:.6g} m: "
                          f"it has no point at the radius {r_k!r} m inside it")
    alpha_k = _pressure_angle(rb, r_k)
    return RadiusValues(alpha_k=alpha_k, s_k=_thickness(_s(system, gear), r, system.alpha, r_k, alpha_k, gear.internal),
                        rho_k=math.sqrt((r_k - rb) * (r_k + rb)), theta_k=inv(alpha_k))


@dataclass(frozen=True)
class PointedTip:
    """Where the two flanks of a tooth meet: the radius ra_pointed (m), its pressure angle
    alpha_a_pointed (rad) and inv_alpha_a_pointed."""

    ra_pointed: float
    alpha_a_pointed: float
    inv_alpha_a_pointed: float


def pointed_tip(system: ToothSystem, gear: SpurGear) -> PointedTip:
    """The radius at which s_k = 0: inv α = s/(2r) + inv α (external); a ring's tooth, thinning
    inward, is pointed where inv α_k = inv α − s/(2r) (refused when that is negative: the ring's
    tooth still has thickness on its base circle). r = rb / cos α_k.

    >>> round(pointed_tip(ToothSystem(m=0.008, alpha=math.radians(20)), SpurGear(z=20)).ra_pointed * 1e3, 9)
    92.306698964
    """
    _check(system, gear)
    r, rb, _, _ = _radii(system, gear)
    half = _s(system, gear) / (2.0 * r)
    v = inv(system.alpha) + (-half if gear.internal else half)
    if v < 0.0:
        raise NotApplicable(f"the ring's tooth is still {-2 * rb * v:.6g} m thick on its base circle: "
                            "it is not pointed anywhere on its involute")
    alpha_k = inv_inverse(v)
    return PointedTip(ra_pointed=rb / math.cos(alpha_k), alpha_a_pointed=alpha_k, inv_alpha_a_pointed=v)


@dataclass(frozen=True)
class Undercut:
    """The rack cutter's undercut limit: the least tooth number z_min_exact for the gear's shift,
    the least shift x_min_exact for its tooth number, and whether the gear is undercut."""

    z_min_exact: float
    x_min_exact: float
    undercut: bool


def undercut(system: ToothSystem, gear: SpurGear) -> Undercut:
    """An external gear generated by a rack cutter is undercut when the cutter's addendum line
    passes beyond N: z_min = 2(h*a − x)/sin²α, x_min = h*a − z sin²α/2; at the limit exactly
    (x = x_min) it is not undercut.

    >>> round(undercut(ToothSystem(m=0.004, alpha=math.radians(20)), SpurGear(z=17)).x_min_exact, 6)
    0.005689
    """
    _check(system, gear)
    if gear.internal:
        raise NotApplicable("a ring (internal gear) is cut by a pinion cutter, not a rack: "
                            "the rack's undercut limit does not apply to it")
    s2 = math.sin(system.alpha) ** 2
    x_min = system.ha_star - 0.5 * gear.z * s2
    return Undercut(z_min_exact=2.0 * (system.ha_star - gear.x) / s2, x_min_exact=x_min, undercut=gear.x < x_min)


def z_root_eq_base(system: ToothSystem, x: float = 0.0) -> float:
    """The (fractional) tooth number of an external gear whose root circle is its base circle:
    mz − 2(h*a + c* − x)m = mz cos α, so z = 2(h*a + c* − x)/(1 − cos α) (1 − cos α = 2 sin²(α/2)).

    >>> round(z_root_eq_base(ToothSystem(m=1.0, alpha=math.radians(20))), 9)
    41.454296847
    """
    _check(system, SpurGear(z=1, x=x))
    return 2.0 * (system.ha_star + system.c_star - x) / (2.0 * math.sin(0.5 * system.alpha) ** 2)


# --------------------------------------------------------------------------------------------
# Measurement: span and pins


def span_teeth(system: ToothSystem, gear: SpurGear) -> int:
    """The book's number of teeth spanned, k = round(z·α_x/π + 0.5) with
    α_x = arccos(d cos α / (d + 2xm)) (α_x = α when x = 0; α_x = 0 when the circle d + 2xm lies
    inside the base circle), kept within 1 … z − 1.

    >>> span_teeth(ToothSystem(m=0.005, alpha=math.radians(20)), SpurGear(z=20))
    3
    """
    _check(system, gear)
    if gear.internal:
        raise NotApplicable("a span is measured over the teeth of an external gear; "
                            "measure a ring (internal gear) between pins")
    if gear.z < 2:
        raise OutOfDomain("a span needs at least two teeth")
    d = system.m * gear.z
    ratio = d * math.cos(system.alpha) / (d + 2.0 * gear.x * system.m)
    alpha_x = math.acos(ratio) if 0.0 < ratio < 1.0 else 0.0
    k = math.floor(gear.z * alpha_x / math.pi + 0.5 + 0.5)
    return min(max(k, 1), gear.z - 1)


def span(system: ToothSystem, gear: SpurGear, k: int) -> float:
    """The span over k teeth, W_k = (k − 1)pb + sb = m cos α[(k − 0.5)π + z inv α] + 2xm sin α:
    the length of a base tangent between the outer flanks of k teeth.

    >>> round(span(ToothSystem(m=0.005, alpha=math.radians(20)), SpurGear(z=20), 3) * 1e3, 9)
    38.30219688
    """
    _check(system, gear)
    if gear.internal:
        raise NotApplicable("the span W_k is measured over an external gear's teeth; "
                            "measure a ring (internal gear) between pins")
    if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= gear.z - 1:
        raise OutOfDomain(f"the span is over k = 1 … z − 1 = {gear.z - 1} teeth, not {k!r}")
    m, alpha = system.m, system.alpha
    return (m * math.cos(alpha) * ((k - 0.5) * math.pi + gear.z * inv(alpha))
            + 2.0 * gear.x * m * math.sin(alpha))


def pin_diameter(system: ToothSystem, gear: SpurGear) -> float:
    """The diameter of pins touching the flanks on the reference circle, their centres on the
    spaces' axes: external α_M = α + (π/2 − 2x tan α)/z, d_p = db(tan α_M − tan α);
    a ring α_M = α − (π/2 + 2x tan α)/z, d_p = db(tan α − tan α_M).

    >>> round(pin_diameter(ToothSystem(m=0.005, alpha=math.radians(20)), SpurGear(z=18)) * 1e3, 9)
    8.654914985
    """
    _check(system, gear)
    _, rb, _, _ = _radii(system, gear)
    alpha, z, t = system.alpha, gear.z, math.tan(system.alpha)
    # the space on the reference circle, e/m = π/2 + 2x tan α (a ring's) or π/2 − 2x tan α: where it
    # is closed no pin touches the flanks there
    if (HALF_PI + 2.0 * gear.x * t if gear.internal else HALF_PI - 2.0 * gear.x * t) <= 0.0:
        raise NoSolution("the tooth space on the reference circle is closed (e = πm/2 ∓ 2xm·tan α ≤ 0): no pin "
                         "touches the flanks there — state pin_diameter")
    if gear.internal:
        alpha_m = alpha - (HALF_PI + 2.0 * gear.x * t) / z
        if not alpha_m > 0.0:
            raise NoSolution("a pin touching this ring's flanks on the reference circle would have "
                             "its centre inside the base circle: choose the pin diameter")
        return 2.0 * rb * (t - math.tan(alpha_m))
    alpha_m = alpha + (HALF_PI - 2.0 * gear.x * t) / z
    if not 0.0 < alpha_m < HALF_PI:
        raise NoSolution("no pin with its centre on the space's axis touches these flanks on the reference "
                         "circle (the shift is too large for the tooth number): choose the pin diameter")
    return 2.0 * rb * (math.tan(alpha_m) - t)


@dataclass(frozen=True)
class PinValues:
    """The measurement over (a ring: between) two pins of diameter d_pin in spaces opposite, or
    nearest opposite for an odd z: the pressure angle alpha_M of the involute through the pins'
    centres, the dimension M, and the radius r_contact at which each pin touches its flanks."""

    d_pin: float
    alpha_M: float
    M: float
    r_contact: float


def over_pins(system: ToothSystem, gear: SpurGear, d_pin: float | None = None) -> PinValues:
    """M over pins of diameter d_p (default :func:`pin_diameter`). A pin's centre lies on the
    involute offset from its flank by d_p/2, i.e. on the same base circle's involute turned by
    d_p/db; set on the space's axis, external:
    inv α_M = inv α + d_p/db − π/(2z) + 2x tan α/z, M = db/cos α_M + d_p (even z) or
    db·cos(π/(2z))/cos α_M + d_p (odd z); a ring, between the pins:
    inv α_M = inv α + π/(2z) + 2x tan α/z − d_p/db, M = db/cos α_M − d_p (odd z: × cos(π/(2z))).

    >>> round(over_pins(ToothSystem(m=0.005, alpha=math.radians(20)), SpurGear(z=18)).M * 1e3, 9)
    101.97016294
    """
    _check(system, gear)
    if d_pin is None:
        d_pin = pin_diameter(system, gear)
    if not (math.isfinite(d_pin) and d_pin > 0.0):
        raise OutOfDomain(f"a pin's diameter must be a positive length, not {d_pin!r} m")
    _, rb, _, _ = _radii(system, gear)
    z, t, db = gear.z, math.tan(system.alpha), 2.0 * rb
    pins = d_pin / db
    sign = -1.0 if gear.internal else 1.0
    v = inv(system.alpha) + sign * (pins - math.pi / (2.0 * z)) + 2.0 * gear.x * t / z
    if v < 0.0:
        raise NoSolution(f"a pin of {d_pin:.6g} m is too {'large' if gear.internal else 'small'} for these spaces: "
                         "its centre would lie inside the base circle")
    alpha_m = inv_inverse(v)
    # N K = N C ∓ d_p/2 along the base tangent through the pin's centre C.
    nk = rb * math.tan(alpha_m) - sign * 0.5 * d_pin
    if nk < 0.0:
        raise NoSolution(f"a pin of {d_pin:.6g} m cannot touch these flanks on their involutes "
                         "(it would touch them inside the base circle)")
    centres = db / math.cos(alpha_m) * (math.cos(math.pi / (2.0 * z)) if z % 2 else 1.0)
    return PinValues(d_pin=d_pin, alpha_M=alpha_m, M=centres + sign * d_pin, r_contact=math.hypot(rb, nk))


# --------------------------------------------------------------------------------------------
# A pair in mesh


@dataclass(frozen=True)
class MeshValues:
    """A pair in mesh (m, rad), gear 1 the pinion; the line of action's points are given by their
    distances from the pitch point P.

    a: the standard centre distance (m(z₁ ± z₂)/2; rack: r₁ + x₁m); a_w: the centre distance a′
    (stated, or the one without backlash); alpha_w: α′; r_w1, r_w2: the working pitch radii
    (r_w2 None for a rack; a rack's pinion rolls on its reference circle, r_w1 = r₁);
    alpha_a1, alpha_a2: the tip pressure angles (alpha_a2 None for a rack); pb = πm cos α.
    PB1 = rb₁(tan α_a1 − tan α′): how far gear 1's tip circle cuts the line past P towards N₂
    (a ring: away from N₁, N₂); PB2: how far gear 2's tip circle (the rack's addendum line) cuts it
    past P towards N₁ — negative when a tip circle falls short of P. B1B2 = PB1 + PB2,
    N1N2 = a′ sin α′ (None for a rack), eps_alpha = B₁B₂/p_b; single_contact = (2 − ε)p_b and
    double_contact = (ε − 1)p_b (the length of each double-contact zone at an end of B₁B₂)
    when 1 ≤ ε < 2, else None. N1B1, N1B2, N2B1, N2B2: the radii of curvature of the profiles at
    the ends of contact, signed (negative beyond N); N2… None for a rack. Specific sliding
    η₁ = 1 − ρ₂/(uρ₁), η₂ = 1 − uρ₁/ρ₂ (u = z₂/z₁; rack η₁ = 1 − N₁P/N₁K, η₂ = 1 − N₁K/N₁P):
    eta_tip1 and eta_root2 at B₁, eta_root1 and eta_tip2 at B₂ (None where a ρ is 0: infinite).
    backlash: circumferential on the working pitch circles (None unless a′ is stated).
    notes: what is wrong with the drive, in words (ε < 1, interference)."""

    meshing: str
    a: float
    a_w: float
    alpha_w: float
    r_w1: float
    r_w2: float | None
    alpha_a1: float
    alpha_a2: float | None
    pb: float
    PB1: float
    PB2: float
    B1B2: float
    N1N2: float | None
    eps_alpha: float
    single_contact: float | None
    double_contact: float | None
    N1B1: float
    N1B2: float
    N2B1: float | None
    N2B2: float | None
    eta_tip1: float | None
    eta_root1: float | None
    eta_tip2: float | None
    eta_root2: float | None
    backlash: float | None
    notes: tuple[str, ...] = ()


def _pair_check(gears: GearSet) -> None:
    kind, g = gears.meshing, gears.gears
    if kind is None:
        raise NotApplicable("this gear set is one gear: a meshing needs a pair (external, internal or rack)")
    if kind == "rack":
        if len(g) != 1 or g[0].internal:
            raise OutOfDomain("a rack and pinion is given by the pinion alone, an external gear")
    elif len(g) != 2:
        raise OutOfDomain(f"an {kind} pair needs two gears, not {len(g)}")
    elif g[0].internal:
        raise OutOfDomain("gear 1, the pinion, must be an external gear")
    elif g[1].internal != (kind == "internal"):
        raise OutOfDomain("in an internal pair gear 2 is the ring (internal), in an external pair it is not")
    elif kind == "internal" and g[1].z <= g[0].z:
        raise OutOfDomain(f"the ring must have more teeth than its pinion (z₂ = {g[1].z} ≤ z₁ = {g[0].z})")
    for gear in g:
        _check(gears.system, gear)
    a_w = gears.centre_distance
    if a_w is not None and not (math.isfinite(a_w) and a_w > 0.0):
        raise OutOfDomain(f"the centre distance a′ must be a positive length, not {a_w!r} m")


def _tip_angle(rb: float, ra: float, i: int) -> float:
    """α_a of gear i, refused where its tip circle lies inside its base circle (no involute there)."""
    if ra < rb:
        raise NotApplicable(f"gear {i}'s tip circle (ra = {ra:.6g} m) lies inside its base circle (rb = {rb:.6g} m): "
                            "it has no tip pressure angle and does not cut the line of action, "
                            f"so there is no B{'₁' if i == 1 else '₂'}")
    return _pressure_angle(rb, ra)


def _eta(rho_own: float, rho_other: float, ratio: float) -> float | None:
    """1 − ρ_other/(ratio·ρ_own), None where ρ_own = 0 (infinite)."""
    return None if rho_own == 0.0 else 1.0 - rho_other / (ratio * rho_own)


def meshing(gears: GearSet) -> MeshValues:
    """The closed forms of a pair in mesh.

    a′ stated: α′ = arccos(a cos α / a′) (rack: α′ = α). Not stated, from the shifts:
    inv α′ = 2 tan α (x₁ + x₂)/(z₁ + z₂) + inv α (internal: (x₂ − x₁)/(z₂ − z₁)), a′ = a cos α / cos α′
    (rack: a′ = r₁ + x₁m). B₁B₂ = rb₁(tan α_a1 − tan α′) ± rb₂(tan α_a2 − tan α′) (+ external,
    − internal); rack: rb₁(tan α_a1 − tan α) + (h*a m − (a′ − r₁))/sin α. Backlash on the working
    circles: external j = p′ − s₁′ − s₂′, internal j = e₂′ − s₁′ with s′ = s r′/r − 2r′(inv α′ − inv α)
    (e₂′ likewise from the ring's space); rack j = 2(a′ − r₁ − x₁m) tan α.

    >>> mv = meshing(GearSet(ToothSystem(m=0.005, alpha=math.radians(20)), (SpurGear(19), SpurGear(42)), "external"))
    >>> round(mv.B1B2 * 1e3, 9), round(mv.eps_alpha, 9)
    (24.10920747, 1.633342418)
    """
    _pair_check(gears)
    system, kind = gears.system, gears.meshing
    m, alpha = system.m, system.alpha
    tan_a, inv_a = math.tan(alpha), inv(alpha)
    g1 = gears.gears[0]
    r1, rb1, ra1, _ = _radii(system, g1)
    alpha_a1 = _tip_angle(rb1, ra1, 1)
    notes: list[str] = []
    stated = gears.centre_distance
    tol = COINCIDENT_REL * math.pi * m

    if kind == "rack":
        a = r1 + g1.x * m
        a_w = a if stated is None else stated
        backlash = None if stated is None else 2.0 * (a_w - a) * tan_a
        if backlash is not None and backlash < -tol:
            raise NoSolution(f"at a′ = {a_w:.6g} m the rack's teeth overlap the pinion's: the least "
                             f"distance from the pinion's centre to the rack's reference line is r₁ + x₁m = {a:.6g} m")
        alpha_w, r_w1, r_w2 = alpha, r1, None
        rho_p = rb1 * tan_a                      # N₁P
        pb1 = rb1 * (math.tan(alpha_a1) - tan_a)
        pb2 = (system.ha_star * m - (a_w - r1)) / math.sin(alpha)
        n1b1, n1b2 = rho_p + pb1, rho_p - pb2
        n2b1 = n2b2 = alpha_a2 = n1n2 = None
        eta_tip1, eta_root1 = _eta(n1b1, rho_p, 1.0), _eta(n1b2, rho_p, 1.0)
        eta_tip2, eta_root2 = _eta(rho_p, n1b2, 1.0), _eta(rho_p, n1b1, 1.0)
        if n1b2 < 0.0:
            notes.append("B2 lies beyond N1: the rack's tip interferes with the pinion's root (undercut)")
    else:
        internal = kind == "internal"
        g2 = gears.gears[1]
        r2, rb2, ra2, _ = _radii(system, g2)
        alpha_a2 = _tip_angle(rb2, ra2, 2)
        sign = -1.0 if internal else 1.0
        zsum = g2.z - g1.z if internal else g1.z + g2.z
        a = 0.5 * m * zsum
        xsum = g2.x - g1.x if internal else g1.x + g2.x
        # The backlash at α′ is j = (cos α/cos α′)·m(z₁ ± z₂)·±(inv α′ − v): it grows with a′ for an
        # external pair but shrinks for a ring (the pinion moves into the ring's teeth), so a′ from
        # the shifts is the least distance of an external pair and the greatest of an internal one.
        v = 2.0 * tan_a * xsum / zsum + inv_a
        bound = "greatest" if internal else "least"
        a_free = a * math.cos(alpha) / math.cos(inv_inverse(v)) if v >= 0.0 else None
        if a_free is None and (internal or stated is None):
            raise NoSolution(f"the shifts ({'x₂ − x₁' if internal else 'x₁ + x₂'} = {xsum:.6g}) are so negative "
                             "that the teeth cannot mesh without backlash at any centre distance"
                             + (" (in this ring they overlap at every one)" if internal else ""))
        if stated is None:
            assert a_free is not None
            a_w, alpha_w = a_free, inv_inverse(v)
        else:
            a_w = stated
            if a * math.cos(alpha) / a_w > 1.0:
                if internal:
                    raise NoSolution(f"at a′ = {a_w:.6g} m the pinion's base circle lies inside the ring's "
                                     f"without touching it (a′ < rb₂ − rb₁ = {a * math.cos(alpha):.6g} m): "
                                     "there is no line of action")
                raise NoSolution(f"at a′ = {a_w:.6g} m the teeth overlap (the base circles would cross): the least "
                                 f"centre distance for these shifts is {a_free if a_free is not None else a * math.cos(alpha):.6g} m")
            alpha_w = math.acos(a * math.cos(alpha) / a_w)
        tan_w, inv_w = math.tan(alpha_w), inv(alpha_w)
        r_w1, r_w2 = rb1 / math.cos(alpha_w), rb2 / math.cos(alpha_w)
        backlash = None
        if stated is not None:
            s1 = _s(system, g1) * r_w1 / r1 - 2.0 * r_w1 * (inv_w - inv_a)
            if internal:
                e2 = (math.pi * m - _s(system, g2)) * r_w2 / r2 - 2.0 * r_w2 * (inv_w - inv_a)
                backlash = e2 - s1
            else:
                s2 = _s(system, g2) * r_w2 / r2 - 2.0 * r_w2 * (inv_w - inv_a)
                backlash = 2.0 * math.pi * r_w1 / g1.z - s1 - s2
            if backlash < -tol:
                raise NoSolution(f"at a′ = {a_w:.6g} m the teeth overlap (backlash {backlash:.6g} m < 0): "
                                 f"the {bound} centre distance for these shifts is {a_free:.6g} m")
        pb1 = rb1 * (math.tan(alpha_a1) - tan_w)
        pb2 = sign * rb2 * (math.tan(alpha_a2) - tan_w)
        # Positions on the line of action from P, positive towards N₁: N₁, N₂, B₁, B₂.
        t_n1, t_n2 = rb1 * tan_w, -sign * rb2 * tan_w
        t_b1, t_b2 = -pb1, pb2
        n1b1, n1b2 = t_n1 - t_b1, t_n1 - t_b2
        n2b1, n2b2 = sign * (t_b1 - t_n2), sign * (t_b2 - t_n2)
        n1n2 = a_w * math.sin(alpha_w)
        u = g2.z / g1.z
        eta_tip1, eta_root1 = _eta(n1b1, n2b1, u), _eta(n1b2, n2b2, u)
        eta_tip2, eta_root2 = _eta(n2b2, n1b2, 1.0 / u), _eta(n2b1, n1b1, 1.0 / u)
        if n1b2 < 0.0:
            notes.append("B2 lies beyond N1: gear 2's tip interferes with gear 1's root")
        if n2b1 < 0.0:
            notes.append("B1 lies beyond N2: gear 1's tip interferes with gear 2's root")
    b1b2 = pb1 + pb2
    pb = math.pi * m * math.cos(alpha)
    eps = b1b2 / pb
    if pb1 < 0.0:
        notes.append("gear 1's tip circle does not reach the pitch point P")
    if pb2 < 0.0:
        notes.append("gear 2's tip does not reach the pitch point P")
    if eps < 1.0:
        notes.append(f"ε = {eps:.4g} < 1: the drive is not continuous")
    zones = 1.0 <= eps < 2.0
    if backlash is not None and backlash < 0.0:
        backlash = 0.0                          # within rounding of the distance without backlash
    return MeshValues(
        meshing=str(kind), a=a, a_w=a_w, alpha_w=alpha_w, r_w1=r_w1, r_w2=r_w2, alpha_a1=alpha_a1,
        alpha_a2=alpha_a2, pb=pb, PB1=pb1, PB2=pb2, B1B2=b1b2, N1N2=n1n2, eps_alpha=eps,
        single_contact=(2.0 - eps) * pb if zones else None, double_contact=(eps - 1.0) * pb if zones else None,
        N1B1=n1b1, N1B2=n1b2, N2B1=n2b1, N2B2=n2b2, eta_tip1=eta_tip1, eta_root1=eta_root1,
        eta_tip2=eta_tip2, eta_root2=eta_root2, backlash=backlash, notes=tuple(notes))


__all__ = ["MeshValues", "PinValues", "PointedTip", "RadiusValues", "ToothValues", "Undercut", "at_radius",
           "inv", "inv_inverse", "meshing", "over_pins", "pin_diameter", "pointed_tip", "span", "span_teeth",
           "tooth", "undercut", "z_root_eq_base"]
