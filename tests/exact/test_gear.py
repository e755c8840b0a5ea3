"""The closed forms of involute gears: the bank's problems, the involute function, and each formula
against the geometry it stands for (the flank built by unwinding a string from the base circle,
tip circles cut with the line of action), with the extreme cases said in words."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain
from graphmech.exact.gear import (
    at_radius,
    inv,
    inv_inverse,
    meshing,
    over_pins,
    pin_diameter,
    pointed_tip,
    span,
    span_teeth,
    tooth,
    undercut,
    z_root_eq_base,
)
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem

MM = 1e-3
DEG = math.pi / 180.0
EPS = 2.220446049250313e-16
REL = 1e-12
ISO = ToothSystem(m=5 * MM, alpha=20 * DEG)


def close(a: float, b: float, rel: float = REL) -> bool:
    return abs(a - b) <= rel * max(abs(a), abs(b))


# --------------------------------------------------------------------------------------------
# The flank as the book builds it: a string unwound from the base circle (no inv α anywhere).
# Tooth (or, for a ring, space) centred on the polar angle 0; its right flank, at negative angles,
# starts on the base circle at −ψ_b and K(u) = N + rb·u·(sin φ, −cos φ) with N = rb(cos φ, sin φ),
# φ = −ψ_b + u (u the roll angle, u = tan α_k). ψ_b is fixed by the arc width w at the reference
# circle (the tooth, or a ring's space): the flank passes through r at the polar angle −w/(2r).


def psi_b(rb: float, r: float, w: float) -> float:
    u = u_at(rb, r)
    return w / (2 * r) + u - math.atan(u)


def flank(rb: float, psi: float, u: float) -> np.ndarray:
    phi = -psi + u
    return rb * np.array([math.cos(phi) + u * math.sin(phi), math.sin(phi) - u * math.cos(phi)])


def rot(p: np.ndarray, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])


def arc_width(rb: float, psi: float, r_k: float) -> float:
    """The arc between a tooth's two flanks at r_k, from the string construction."""
    u = u_at(rb, r_k)
    return 2 * r_k * (psi - (u - math.atan(u)))


def u_at(rb: float, r_k: float) -> float:
    return math.sqrt(max((r_k - rb) * (r_k + rb), 0.0)) / rb


# --------------------------------------------------------------------------------------------
# The bank (tests/reference/problems.toml, exact values)

Z20_M8 = {"d": 160.0, "da": 176.0, "db": 150.35081932574536, "rho_pitch": 27.3616114660535,
          "alpha_a_deg": 31.321257929651313, "rho_a": 45.74557663883218, "sa": 5.559039876569942,
          "sb": 14.049412062373653, "inv_alpha_a_pointed": 0.09344420020708127,
          "alpha_a_pointed_deg": 35.471029507740546, "ra_pointed": 92.30669896387995}


def test_bank_involute_z20_m8() -> None:
    system, gear = ToothSystem(m=8 * MM, alpha=20 * DEG, ha_star=1.0), SpurGear(z=20)
    t = tooth(system, gear)
    got = {"d": t.d / MM, "da": t.da / MM, "db": t.db / MM, "rho_pitch": t.rho_pitch / MM,
           "alpha_a_deg": t.alpha_a / DEG, "rho_a": t.rho_a / MM, "sa": t.sa / MM, "sb": t.sb / MM}
    tip = pointed_tip(system, gear)
    got |= {"inv_alpha_a_pointed": tip.inv_alpha_a_pointed, "alpha_a_pointed_deg": tip.alpha_a_pointed / DEG,
            "ra_pointed": tip.ra_pointed / MM}
    for key, value in Z20_M8.items():
        assert close(got[key], value), (key, got[key], value)
    assert t.notes == ()
    assert close(t.p, 8 * MM * math.pi) and close(t.pb, t.p * math.cos(20 * DEG))
    assert close(t.ha, 8 * MM) and close(t.hf, 10 * MM) and close(t.h, 18 * MM)
    assert close(t.s, t.e) and close(t.s, 4 * math.pi * MM)


def test_bank_root_circle_equals_base_circle() -> None:
    system = ToothSystem(m=1.0, alpha=20 * DEG, ha_star=1.0, c_star=0.25)
    assert close(z_root_eq_base(system), 41.45429684690798)
    t = tooth(system, SpurGear(z=42))
    assert close((t.df - t.db) / system.m, 0.03290992699184869, 1e-11)
    # Shifting out by x lowers the tooth number by 2x/(1 − cos α); at that z the circles coincide.
    z = z_root_eq_base(system, x=0.5)
    assert close(z, 41.45429684690798 - 1.0 / (1 - math.cos(20 * DEG)))
    assert abs(z * (1 - math.cos(20 * DEG)) - 2 * (1.25 - 0.5)) < 1e-13


def test_bank_contact_ratio_19_42() -> None:
    mv = meshing(GearSet(ISO, (SpurGear(19), SpurGear(42)), "external"))
    assert close(mv.B1B2 / MM, 24.10920747019434)
    assert close(mv.eps_alpha, 1.6333424177366997)
    assert close(mv.alpha_a1 / DEG, 31.76677921200012)
    assert close(mv.alpha_a2 / DEG, 26.236190060663052)
    # Standard gears without backlash: α′ = α, a′ = a, the working circles are the reference circles.
    assert close(mv.alpha_w, 20 * DEG) and close(mv.a_w, mv.a) and close(mv.a, 152.5 * MM)
    assert close(mv.r_w1, 47.5 * MM) and close(mv.r_w2, 105 * MM)
    assert mv.backlash is None and mv.notes == ()
    # ε by the book's second formula: [z₁(tan α_a1 − tan α′) + z₂(tan α_a2 − tan α′)]/2π.
    tw = math.tan(mv.alpha_w)
    assert close(mv.eps_alpha, (19 * (math.tan(mv.alpha_a1) - tw) + 42 * (math.tan(mv.alpha_a2) - tw)) / (2 * math.pi))
    # The zones: two double-contact zones of (ε − 1)p_b at the ends, single contact (2 − ε)p_b between.
    assert close(2 * mv.double_contact + mv.single_contact, mv.B1B2)
    assert close(mv.single_contact, (2 - 1.6333424177366997) * mv.pb)
    assert close(mv.N1N2, mv.a_w * math.sin(mv.alpha_w))


# --------------------------------------------------------------------------------------------
# The involute function

# tan α − α by a 50-digit computation (mpmath), for the float α given.
INV_50 = {1e-6: 3.3333333333346662141e-19, 1e-4: 3.3333333466666671999e-13, 1e-2: 3.3334666720637109754e-7,
          0.1: 0.00033467208545054511396, 0.35: 0.015028494830424555359, 0.3490658503988659: 0.014904383867336443347,
          0.9: 0.3601582175503391724, 0.999: 0.55498753132952770223, 1.0: 0.55740772465490223051,
          1.2: 1.3721516221263186416, 1.5: 12.601419947171719388}


@pytest.mark.parametrize("alpha", sorted(INV_50))
def test_inv_to_an_ulp(alpha: float) -> None:
    # Also where tan α − α cancels (α ≪ 1): summed as a series there.
    assert abs(inv(alpha) - INV_50[alpha]) <= 2 * EPS * INV_50[alpha]


def test_inv_inverse_round_trip() -> None:
    for v in np.logspace(-12, 3, 1501):
        v = float(v)
        alpha = inv_inverse(v)
        # The involute's condition number κ = α tan²α/inv α (3 at small α, ≈ 1.6e3 at v = 1e3):
        # the nearest float α to the root gives inv α within ~κ·ε/2 of v, never better.
        kappa = alpha * math.tan(alpha) ** 2 / inv(alpha)
        assert abs(inv(alpha) - v) <= max(1e-14, 2 * kappa * EPS) * v, v
        # α is the float nearest the root: its neighbours bracket v.
        assert inv(math.nextafter(alpha, 0)) <= v <= inv(math.nextafter(alpha, 2)), v
        if v <= 10:
            assert abs(inv(alpha) - v) <= 1e-14 * v
    for alpha in np.linspace(1e-5, 1.55, 500):
        assert abs(inv_inverse(inv(float(alpha))) - alpha) <= 2 * EPS * alpha
    assert inv_inverse(0.0) == 0.0 and inv(0.0) == 0.0


@pytest.mark.parametrize("call", [lambda: inv_inverse(-1e-3), lambda: inv_inverse(math.nan), lambda: inv_inverse(math.inf),
                                  lambda: inv(math.pi / 2), lambda: inv(-0.1), lambda: inv(math.nan)])
def test_involute_refuses_in_words(call) -> None:
    with pytest.raises(OutOfDomain, match="involute|pressure angle"):
        call()


# --------------------------------------------------------------------------------------------
# The tooth against the string construction

gears = st.builds(SpurGear, z=st.integers(8, 300), x=st.floats(-0.5, 1.0))
rings = st.builds(SpurGear, z=st.integers(40, 300), x=st.floats(-0.3, 0.5), internal=st.just(True))
systems = st.builds(ToothSystem, m=st.floats(0.5 * MM, 20 * MM), alpha=st.floats(14.5 * DEG, 25 * DEG),
                    ha_star=st.sampled_from([0.8, 1.0]), c_star=st.sampled_from([0.25, 0.3]))


@settings(max_examples=120, deadline=None)
@given(systems, st.one_of(gears, rings), st.floats(0.0, 1.0))
def test_thickness_at_any_radius_against_the_string(system: ToothSystem, gear: SpurGear, f: float) -> None:
    t = tooth(system, gear)
    r, rb = t.d / 2, t.db / 2
    # At the reference circle s_k = s; a ring's tooth is p − e, its space bounded like an external tooth.
    assert close(at_radius(system, gear, r).s_k, t.s, 1e-13)
    r_k = rb + f * (max(t.da, t.df) / 2 - rb) * 1.2
    v = at_radius(system, gear, r_k)
    if gear.internal:
        s_k = 2 * math.pi * r_k / gear.z - arc_width(rb, psi_b(rb, r, t.e), r_k)
    else:
        s_k = arc_width(rb, psi_b(rb, r, t.s), r_k)
    assert abs(v.s_k - s_k) <= 1e-11 * system.m
    assert close(math.cos(v.alpha_k), rb / r_k, 1e-13)
    assert close(v.rho_k**2 + rb**2, r_k**2, 1e-14)
    u = u_at(rb, r_k)
    assert abs(v.theta_k - (u - math.atan(u))) <= 1e-15 + 1e-13 * v.theta_k
    # The point's polar angle from its flank's start on the base circle, by the string.
    k = flank(rb, 0.0, u)
    assert abs(math.atan2(k[1], k[0]) - v.theta_k) <= 1e-12
    if not gear.internal:
        assert close(t.sb, at_radius(system, gear, rb).s_k, 1e-12)
        assert close(t.sb, t.s * math.cos(system.alpha) + t.db * inv(system.alpha), 1e-12)


@settings(max_examples=80, deadline=None)
@given(systems, st.one_of(gears, rings))
def test_pointed_tip_has_no_thickness(system: ToothSystem, gear: SpurGear) -> None:
    try:
        tip = pointed_tip(system, gear)
    except NotApplicable:
        assert gear.internal
        t = tooth(system, gear)
        assert at_radius(system, gear, t.db / 2).s_k > 0     # the ring's tooth is thick at the base circle
        return
    assert abs(at_radius(system, gear, tip.ra_pointed).s_k) <= 1e-11 * system.m
    assert close(math.cos(tip.alpha_a_pointed), tooth(system, gear).db / 2 / tip.ra_pointed, 1e-13)


def test_pointed_and_undercut_said() -> None:
    # A small, strongly shifted pinion: pointed before its tip circle.
    system = ToothSystem(m=MM, alpha=20 * DEG)
    t = tooth(system, SpurGear(z=8, x=1.0))
    assert t.sa < 0 and any("pointed" in n for n in t.notes)
    assert pointed_tip(system, SpurGear(z=8, x=1.0)).ra_pointed < t.da / 2
    t = tooth(system, SpurGear(z=12))
    assert t.sa > 0 and t.notes == ("z = 12 with x = 0 is undercut when cut by a rack",)


def test_undercut_limit() -> None:
    system = ToothSystem(m=4 * MM, alpha=20 * DEG)
    s2 = math.sin(20 * DEG) ** 2
    u = undercut(system, SpurGear(z=17))
    assert close(u.z_min_exact, 2 / s2) and abs(u.z_min_exact - 17.097) < 1e-3
    assert u.undercut                                 # 17 < 17.097 with x = 0
    assert not undercut(system, SpurGear(z=18)).undercut
    # rack_cutter_generation_cases: z = 15 is just not undercut at x = 1 − 15 sin²α/2 = 0.1227.
    x15 = undercut(system, SpurGear(z=15)).x_min_exact
    assert abs(x15 - 0.1227) < 1e-4
    # At the limit exactly: not undercut; a hair below: undercut.
    assert not undercut(system, SpurGear(z=15, x=x15)).undercut
    assert undercut(system, SpurGear(z=15, x=math.nextafter(x15, 0))).undercut
    assert close(undercut(system, SpurGear(z=15, x=x15)).z_min_exact, 15.0, 1e-13)
    # case 4 of the bank: z = 18, x = −1.5 far below x_min = −0.053.
    u = undercut(system, SpurGear(z=18, x=-1.5))
    assert u.undercut and close(u.x_min_exact, 1 - 9 * s2)
    with pytest.raises(NotApplicable, match="pinion cutter"):
        undercut(system, SpurGear(z=60, internal=True))


def test_at_radius_refuses_inside_the_base_circle() -> None:
    rb = tooth(ISO, SpurGear(20)).db / 2
    assert at_radius(ISO, SpurGear(20), rb).alpha_k == 0.0
    with pytest.raises(OutOfDomain, match="starts on the base circle"):
        at_radius(ISO, SpurGear(20), 0.999 * rb)


def test_ring_tip_inside_base_circle() -> None:
    # A ring with few teeth: ra = r − m < rb = r cos α when z < 2/(1 − cos α) = 33.2.
    system, ring = ToothSystem(m=MM, alpha=20 * DEG), SpurGear(z=30, internal=True)
    t = tooth(system, ring)
    assert t.da < t.db and t.alpha_a is None and t.sa is None and t.rho_a is None
    assert "inside the base circle" in t.notes[0]
    assert close(t.da, 28 * MM) and close(t.df, 32.5 * MM)
    with pytest.raises(NotApplicable, match="no B₂"):
        meshing(GearSet(system, (SpurGear(12), ring), "internal"))
    # A ring's tooth thickens outward: thinner at its tip (inside) than at the reference circle.
    t = tooth(ISO, SpurGear(z=80, internal=True))
    assert t.da < t.d < t.df and t.sa < t.s and close(t.s + t.e, t.p)


@pytest.mark.parametrize(("system", "gear", "match"), [
    (ToothSystem(m=0.0, alpha=20 * DEG), SpurGear(20), "module"),
    (ToothSystem(m=MM, alpha=95 * DEG), SpurGear(20), "pressure angle"),
    (ToothSystem(m=MM, alpha=20 * DEG, ha_star=-1), SpurGear(20), "coefficients"),
    (ToothSystem(m=MM, alpha=20 * DEG), SpurGear(0), "tooth number"),
    (ToothSystem(m=MM, alpha=20 * DEG), SpurGear(20, x=math.nan), "shift"),
])
def test_tooth_refuses_bad_data(system: ToothSystem, gear: SpurGear, match: str) -> None:
    with pytest.raises(OutOfDomain, match=match):
        tooth(system, gear)


# --------------------------------------------------------------------------------------------
# Span and pins against brute force on the string's flank


def test_span_book_values() -> None:
    # Standard gears, m = 1, α = 20°: the tables' W* for z = 20 (k = 3) and z = 40 (k = 5).
    one = ToothSystem(m=1.0, alpha=20 * DEG)
    assert span_teeth(one, SpurGear(20)) == 3 and abs(span(one, SpurGear(20), 3) - 7.6604) < 1e-4
    assert span_teeth(one, SpurGear(40)) == 5 and abs(span(one, SpurGear(40), 5) - 13.8448) < 1e-4
    assert span_teeth(one, SpurGear(2)) == 1 and span_teeth(one, SpurGear(1000)) == 112
    # A shift raises the measuring circle and with it k.
    assert span_teeth(one, SpurGear(20, x=1.0)) == 4
    with pytest.raises(NotApplicable, match="between pins"):
        span(one, SpurGear(60, internal=True), 7)
    with pytest.raises(NotApplicable, match="between pins"):
        span_teeth(one, SpurGear(60, internal=True))
    with pytest.raises(OutOfDomain, match="k = 1 … z − 1 = 19"):
        span(one, SpurGear(20), 20)
    with pytest.raises(OutOfDomain, match="k = 1"):
        span(one, SpurGear(20), 0)


@settings(max_examples=60, deadline=None)
@given(systems, st.builds(SpurGear, z=st.integers(10, 200), x=st.floats(-0.3, 0.8)))
def test_span_is_the_calipers_reading(system: ToothSystem, gear: SpurGear) -> None:
    # The jaws parallel to the axis of k teeth, closed on the outer flanks: by symmetry
    # W = −2·min over the right flank of tooth 0 of p·n, n ⟂ the axis at (k − 1)τ/2.
    assume(undercut(system, gear).x_min_exact <= gear.x)
    t = tooth(system, gear)
    rb, r, ra = t.db / 2, t.d / 2, t.da / 2
    assume(t.sa > 0.1 * system.m)
    k = span_teeth(system, gear)
    psi = psi_b(rb, r, t.s)
    c = (k - 1) * math.pi / gear.z
    n = np.array([-math.sin(c), math.cos(c)])
    u_lo, u_hi = u_at(rb, max(rb, t.df / 2)), u_at(rb, ra)
    res = minimize_scalar(lambda u: float(flank(rb, psi, u) @ n), bounds=(u_lo, u_hi), method="bounded",
                          options={"xatol": 1e-12})
    w = -2 * res.fun
    assert close(span(system, gear, k), w, 1e-10)
    # The book's k puts the jaws' contact on the involute, clear of root and tip.
    assert u_lo < res.x < u_hi
    # (the minimiser's u is fixed only to ~√ε by a flat minimum)
    assert close(math.hypot(rb, w / 2), float(np.linalg.norm(flank(rb, psi, res.x))), 1e-6)


def pin_check(system: ToothSystem, gear: SpurGear, d_pin: float | None) -> tuple[float, float]:
    """(distance from a pin's centre to its flank − d_p/2, M by the pins' centres) by brute force."""
    pins = over_pins(system, gear, d_pin)
    t = tooth(system, gear)
    rb, r, z = t.db / 2, t.d / 2, gear.z
    if gear.internal:
        # The ring's space centred on 0, the pin's centre on its axis.
        psi, axis = psi_b(rb, r, t.e), 0.0
    else:
        # The space between tooth 0 and tooth −1, its axis at −π/z.
        psi, axis = psi_b(rb, r, t.s), -math.pi / z
    rc = rb / math.cos(pins.alpha_M)
    centre = rc * np.array([math.cos(axis), math.sin(axis)])
    res = minimize_scalar(lambda u: float(np.linalg.norm(flank(rb, psi, u) - centre)),
                          bounds=(0.0, u_at(rb, 2 * r)), method="bounded", options={"xatol": 1e-13})
    assert abs(float(np.linalg.norm(flank(rb, psi, res.x))) - pins.r_contact) <= 1e-8 * r
    other = rot(centre, math.pi * (z - z % 2) / z)        # the space opposite (nearest opposite: odd z)
    gap = float(np.linalg.norm(other - centre))
    return res.fun - pins.d_pin / 2, gap + (-pins.d_pin if gear.internal else pins.d_pin)


def test_pins_book_000_gear_3() -> None:
    # z = 18, m = 5, α = 20°, x = 0: d_p/2 = 4.33 mm, M = 101.98 mm (book).
    gear = SpurGear(18)
    d_p = pin_diameter(ISO, gear)
    assert abs(d_p / 2 / MM - 4.33) < 0.005
    pins = over_pins(ISO, gear)
    assert abs(pins.M / MM - 101.98) < 0.015 and close(pins.alpha_M, 25 * DEG)
    assert close(pins.r_contact, 45 * MM)                  # touching on the reference circle
    gap, m = pin_check(ISO, gear, None)
    assert abs(gap) < 1e-12 and close(m, pins.M, 1e-12)


@settings(max_examples=80, deadline=None)
@given(systems, st.one_of(st.builds(SpurGear, z=st.integers(8, 200), x=st.floats(-0.3, 0.8)), rings),
       st.floats(0.85, 1.15))
def test_pins_touch_their_flanks(system: ToothSystem, gear: SpurGear, f: float) -> None:
    d_p = pin_diameter(system, gear)
    assert close(over_pins(system, gear).r_contact, system.m * gear.z / 2, 1e-12)
    try:
        gap, m = pin_check(system, gear, d_p * f)
    except NoSolution as e:
        # Only where the pin would touch below the base circle: a smaller pin in an external gear's
        # space, a larger one in a ring's.
        assert (f > 1) == gear.internal and "base circle" in str(e)
        return
    assert abs(gap) <= 1e-11 * system.m
    assert close(m, over_pins(system, gear, d_p * f).M, 1e-12)


def test_pins_refused() -> None:
    with pytest.raises(NoSolution, match="too small"):
        over_pins(ISO, SpurGear(18), 0.1 * MM)
    with pytest.raises(OutOfDomain, match="positive length"):
        over_pins(ISO, SpurGear(18), -1.0)


# --------------------------------------------------------------------------------------------
# Meshing against the line of action cut by the tip circles


def line_cuts(gears: GearSet) -> tuple[float, float, float, dict[str, float]]:
    """(B₁B₂, N₁B₁, N₁B₂, the specific slidings at B₁ and B₂) from coordinates: O₁ at 0, the line of
    action through P = (0, r_w1), gear 1 turning at ω₁ = 1 counter-clockwise. The slidings by their
    definition: the velocities of the two teeth's points at K have the same component along the
    line of action (the contact holds); η = 1 − (the other's tangential component)/(its own)."""
    mv = meshing(gears)
    system, kind = gears.system, gears.meshing
    g1 = gears.gears[0]
    t1 = tooth(system, g1)
    p = np.array([0.0, mv.r_w1])
    d = np.array([math.cos(mv.alpha_w), -math.sin(mv.alpha_w)])
    tangent = np.array([math.sin(mv.alpha_w), math.cos(mv.alpha_w)])

    def foot(o: np.ndarray) -> float:
        return float((o - p) @ d)

    def cut(o: np.ndarray, radius: float, towards: float) -> float:
        tn = foot(o)
        h = math.sqrt(radius**2 - float(np.linalg.norm(o - p - tn * d)) ** 2)
        return tn + math.copysign(h, towards - tn)

    def turning(omega: float, o: np.ndarray):
        return lambda k: omega * np.array([-(k - o)[1], (k - o)[0]])

    o1 = np.zeros(2)
    tn1 = foot(o1)
    v1 = turning(1.0, o1)
    if kind == "rack":
        tb1 = cut(o1, t1.da / 2, -tn1)
        tb2 = (mv.a_w - system.ha_star * system.m - p[1]) / d[1]   # the rack's addendum line
        def v2(k: np.ndarray) -> np.ndarray:
            return np.array([-mv.r_w1, 0.0])                      # the rack moves with P
    else:
        z1, z2 = g1.z, gears.gears[1].z
        t2 = tooth(system, gears.gears[1])
        o2 = np.array([0.0, mv.a_w if kind == "external" else -mv.a_w])
        v2 = turning(-z1 / z2 if kind == "external" else z1 / z2, o2)
        tn2 = foot(o2)
        if kind == "external":
            tb1, tb2 = cut(o1, t1.da / 2, tn2), cut(o2, t2.da / 2, tn1)
        else:
            tb1, tb2 = cut(o1, t1.da / 2, -tn1), cut(o2, t2.da / 2, 0.0)
        assert close(abs(tn1 - tn2), mv.N1N2, 1e-12)
    eta = {}
    for end, tb in (("B1", tb1), ("B2", tb2)):
        k = p + tb * d
        assert abs(float((v1(k) - v2(k)) @ d)) <= 1e-12 * mv.r_w1
        w1, w2 = float(v1(k) @ tangent), float(v2(k) @ tangent)
        eta[f"1{end}"], eta[f"2{end}"] = 1 - w2 / w1, 1 - w1 / w2
    return abs(tb1 - tb2), abs(tb1 - tn1), math.copysign(abs(tb2 - tn1), (tb2 - tn1) * (0.0 - tn1)), eta


PAIRS = [
    GearSet(ISO, (SpurGear(19), SpurGear(42)), "external"),
    GearSet(ISO, (SpurGear(12, 0.3), SpurGear(30, 0.2)), "external"),
    GearSet(ISO, (SpurGear(12, 0.3), SpurGear(30, 0.2)), "external", centre_distance=112 * MM),
    GearSet(ISO, (SpurGear(20), SpurGear(80, internal=True)), "internal"),
    GearSet(ISO, (SpurGear(20, 0.2), SpurGear(80, 0.5, internal=True)), "internal", centre_distance=151 * MM),
    GearSet(ISO, (SpurGear(20),), "rack"),
    GearSet(ISO, (SpurGear(14, 0.3),), "rack", centre_distance=37 * MM),
]


@pytest.mark.parametrize("gears", PAIRS)
def test_meshing_against_the_line_of_action(gears: GearSet) -> None:
    mv = meshing(gears)
    b1b2, n1b1, n1b2, eta = line_cuts(gears)
    assert close(mv.B1B2, b1b2, 1e-12) and close(mv.N1B1, n1b1, 1e-12) and close(mv.N1B2, n1b2, 1e-12)
    assert close(mv.eta_tip1, eta["1B1"], 1e-10) and close(mv.eta_root2, eta["2B1"], 1e-10)
    assert close(mv.eta_root1, eta["1B2"], 1e-10) and close(mv.eta_tip2, eta["2B2"], 1e-10)
    assert close(mv.eps_alpha, mv.B1B2 / (math.pi * gears.system.m * math.cos(gears.system.alpha)), 1e-14)
    # The specific slidings at each end: (1 − η₁)(1 − η₂) = 1 at the same point.
    assert close((1 - mv.eta_tip1) * (1 - mv.eta_root2), 1.0, 1e-12)
    assert close((1 - mv.eta_root1) * (1 - mv.eta_tip2), 1.0, 1e-12)
    z1 = gears.gears[0].z
    if gears.meshing == "rack":
        assert mv.alpha_w == gears.system.alpha and mv.r_w2 is None and mv.N2B1 is None
        assert close(mv.eta_tip1, 1 - mv.r_w1 * math.sin(mv.alpha_w) / mv.N1B1, 1e-12)
    else:
        z2 = gears.gears[1].z
        assert close(mv.eta_tip1, 1 - mv.N2B1 / (z2 / z1 * mv.N1B1), 1e-12)
        if gears.meshing == "external":
            assert close(mv.N1B1 + mv.N2B1, mv.N1N2, 1e-12)
        else:                                   # N₁ between P and N₂, B₁ on the other side of P
            assert close(mv.N2B1 - mv.N1B1, mv.N1N2, 1e-12)
        sign = 1 if gears.meshing == "external" else -1
        tw = math.tan(mv.alpha_w)
        assert close(mv.eps_alpha, (z1 * (math.tan(mv.alpha_a1) - tw) + sign * z2 * (math.tan(mv.alpha_a2) - tw))
                     / (2 * math.pi), 1e-12)
        assert close(mv.r_w2 + sign * mv.r_w1, mv.a_w, 1e-13)
        assert close(mv.r_w2 / mv.r_w1, z2 / z1, 1e-13)


def test_internal_and_rack_values() -> None:
    # Standard internal pair 20/80, m = 5: a = 150 mm, α′ = α, ra₂ = 195 mm.
    mv = meshing(PAIRS[3])
    rb1, rb2 = 50 * MM * math.cos(20 * DEG), 200 * MM * math.cos(20 * DEG)
    assert close(mv.a, 150 * MM) and close(mv.a_w, 150 * MM) and close(mv.alpha_w, 20 * DEG)
    assert close(mv.alpha_a2, math.acos(rb2 / (195 * MM)))
    t20 = math.tan(20 * DEG)
    assert close(mv.B1B2, rb1 * (math.tan(mv.alpha_a1) - t20) - rb2 * (math.tan(mv.alpha_a2) - t20))
    assert close(mv.N1N2, (rb2 - rb1) * t20)
    # Rack and pinion z = 20: B₂ on the rack's addendum line, m/sin α from P.
    mv = meshing(PAIRS[5])
    assert close(mv.a, 50 * MM) and close(mv.PB2, 5 * MM / math.sin(20 * DEG))
    assert close(mv.B1B2, rb1 * (math.tan(mv.alpha_a1) - t20) + 5 * MM / math.sin(20 * DEG))
    assert mv.N1N2 is None and mv.alpha_a2 is None and mv.backlash is None
    # The stated rack distance 37 mm, pinion 14, x = 0.3: j = 2(a′ − r − xm) tan α.
    mv = meshing(PAIRS[6])
    assert close(mv.backlash, 2 * (37 - 35 - 1.5) * MM * t20) and close(mv.a, 36.5 * MM)


def test_the_rack_is_the_limit_of_a_large_wheel() -> None:
    # The wheel's part of B₁B₂, √(ra₂² − rb₂²) − r₂ sin α, tends to the rack's m/sin α only as 1/z₂:
    # PB₂ ≈ m/sin α + m²(1 − 1/sin²α)/(2r₂ sin α), so at z₂ = 1000 ε is still 7.4e-3 short of the
    # rack's (α = 20°), and within 1e-3 only from z₂ ≈ 7500.
    rack = meshing(GearSet(ISO, (SpurGear(19),), "rack"))
    s, m = math.sin(ISO.alpha), ISO.m
    for z2, within in ((1000, 2e-4), (10000, 2e-6)):
        big = meshing(GearSet(ISO, (SpurGear(19), SpurGear(z2)), "external"))
        leading = m * m * (1 - 1 / s**2) / (2 * (m * z2 / 2) * s) / big.pb
        assert abs(big.eps_alpha - rack.eps_alpha - leading) < within
        assert close(big.alpha_a1, rack.alpha_a1) and close(big.PB1, rack.PB1)
    assert abs(big.eps_alpha - rack.eps_alpha) < 1e-3
    # The root's sliding, 1/N₁B₂, is the sensitive one near N₁.
    assert abs(big.eta_tip1 - rack.eta_tip1) < 1e-3 and close(big.eta_root1, rack.eta_root1, 1e-2)


@settings(max_examples=100, deadline=None)
@given(st.integers(10, 60), st.integers(10, 150), st.floats(-0.4, 0.8), st.floats(-0.4, 0.8),
       st.sampled_from(["external", "internal"]))
def test_no_backlash_at_the_distance_from_the_shifts(z1: int, z2: int, x1: float, x2: float, kind: str) -> None:
    if kind == "internal":
        z2 = z1 + 10 + z2
    pair = GearSet(ISO, (SpurGear(z1, x1), SpurGear(z2, x2, internal=kind == "internal")), kind)  # type: ignore[arg-type]
    xsum, zsum = (x2 - x1, z2 - z1) if kind == "internal" else (x1 + x2, z1 + z2)
    try:
        free = meshing(pair)
    except NotApplicable as e:                 # a tip circle inside its base circle
        assert "inside its base circle" in str(e)
        return
    except NoSolution as e:                    # inv α′ would be < 0
        assert 2 * math.tan(ISO.alpha) * xsum / zsum + inv(ISO.alpha) < 0 and "so negative" in str(e)
        return
    stated = meshing(GearSet(ISO, pair.gears, kind, centre_distance=free.a_w))  # type: ignore[arg-type]
    assert abs(stated.backlash) <= 1e-12 * ISO.m
    assert close(stated.alpha_w, free.alpha_w, 1e-9)
    # Moved by Δa: j ≈ ±2Δa tan α′ (the book's rule; + external, − a ring, whose teeth the pinion
    # moves into), and the other way the teeth overlap.
    sign = 1 if kind == "external" else -1
    looser = meshing(GearSet(ISO, pair.gears, kind, centre_distance=free.a_w + sign * 1e-8))  # type: ignore[arg-type]
    assert close(looser.backlash, 2e-8 * math.tan(free.alpha_w), 1e-3)
    bound = "least" if kind == "external" else "greatest"
    with pytest.raises(NoSolution, match=f"{bound} centre distance"):
        meshing(GearSet(ISO, pair.gears, kind, centre_distance=free.a_w - sign * 1e-8))  # type: ignore[arg-type]


def test_discontinuous_drive_and_interference_said() -> None:
    # Stubby teeth far apart: ε < 1.
    wide = GearSet(ISO, (SpurGear(19), SpurGear(42)), "external", centre_distance=156 * MM)
    mv = meshing(wide)
    assert mv.eps_alpha < 1 and mv.single_contact is None and mv.double_contact is None
    assert f"ε = {mv.eps_alpha:.4g} < 1: the drive is not continuous" in mv.notes
    # A 12-tooth pinion on a rack: the rack's tip passes beyond N₁ (the pinion is undercut).
    mv = meshing(GearSet(ISO, (SpurGear(12),), "rack"))
    assert mv.N1B2 < 0 and any("beyond N1" in n for n in mv.notes)
    # Two 12-tooth gears: each tip passes beyond the other's N.
    mv = meshing(GearSet(ISO, (SpurGear(12), SpurGear(12)), "external"))
    assert mv.N1B2 < 0 and mv.N2B1 < 0
    assert {"B2 lies beyond N1: gear 2's tip interferes with gear 1's root",
            "B1 lies beyond N2: gear 1's tip interferes with gear 2's root"} <= set(mv.notes)
    # Contact ratio ≥ 2: no zones.
    mv = meshing(GearSet(ToothSystem(m=MM, alpha=14.5 * DEG, ha_star=1.2), (SpurGear(60), SpurGear(200)), "external"))
    assert mv.eps_alpha >= 2 and mv.single_contact is None


@pytest.mark.parametrize(("gears", "error", "match"), [
    (GearSet(ISO, (SpurGear(19),)), NotApplicable, "one gear"),
    (GearSet(ISO, (SpurGear(19), SpurGear(42, internal=True)), "external"), OutOfDomain, "ring"),
    (GearSet(ISO, (SpurGear(50), SpurGear(42, internal=True)), "internal"), OutOfDomain, "more teeth"),
    (GearSet(ISO, (SpurGear(19), SpurGear(42)), "rack"), OutOfDomain, "pinion alone"),
    (GearSet(ISO, (SpurGear(19), SpurGear(42)), "external", centre_distance=140 * MM), NoSolution,
     "least centre distance for these shifts is 0.1525 m"),
    (GearSet(ISO, (SpurGear(19),), "rack", centre_distance=47 * MM), NoSolution, "r₁ \\+ x₁m = 0.0475 m"),
    (GearSet(ISO, (SpurGear(100, -2.1), SpurGear(100, -2.1)), "external"), NoSolution, "so negative"),
    (GearSet(ISO, (SpurGear(20, 0.3), SpurGear(60, -0.6, internal=True)), "internal"), NoSolution, "overlap at every"),
    (GearSet(ISO, (SpurGear(19), SpurGear(42, -3.0)), "external"), NotApplicable, "gear 2's tip circle .* no B₂"),
    (GearSet(ISO, (SpurGear(19, -3.0),), "rack"), NotApplicable, "gear 1's tip circle .* no B₁"),
    (GearSet(ISO, (SpurGear(20), SpurGear(80, internal=True)), "internal", centre_distance=140 * MM), NoSolution,
     "no line of action"),
    (GearSet(ISO, (SpurGear(20), SpurGear(80, internal=True)), "internal", centre_distance=151 * MM), NoSolution,
     "greatest centre distance for these shifts is 0.15 m"),
    (GearSet(ISO, (SpurGear(19), SpurGear(42)), "external", centre_distance=-1.0), OutOfDomain, "positive length"),
])
def test_meshing_refused_in_words(gears: GearSet, error: type, match: str) -> None:
    with pytest.raises(error, match=match):
        meshing(gears)
