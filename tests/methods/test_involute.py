"""The tooth constructed by strings unwound, against the book's closed forms written here."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.exact.gear import span_teeth
from graphmech.mechanisms.gear import SpurGear, ToothSystem
from graphmech.methods.involute import (
    at_radius,
    circles,
    over_pins,
    pointed_tip,
    span,
    tooth_outline,
)

ALPHA = math.radians(20.0)
REL = 1e-9


def inv(a: float) -> float:
    return math.tan(a) - a


def arc_inv(value: float) -> float:
    """α with inv α = value (bisection: inv is increasing on (0, π/2))."""
    lo, hi = 0.0, math.pi / 2 - 1e-9
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inv(mid) < value else (lo, mid)
    return (lo + hi) / 2


def s_closed(m: float, z: int, x: float, r_k: float, alpha: float = ALPHA) -> float:
    """The book's s_k = s·r_k/r − 2r_k(inv α_k − inv α), s = πm/2 + 2xm tan α."""
    r = m * z / 2
    s = math.pi * m / 2 + 2 * x * m * math.tan(alpha)
    return s * r_k / r - 2 * r_k * (inv(math.acos(r * math.cos(alpha) / r_k)) - inv(alpha))


def test_bank_involute_z20_m8() -> None:
    """gear.involute_z20_m8 (tests/reference/problems.toml, [problem.exact])."""
    system, gear = ToothSystem(m=8e-3, alpha=ALPHA), SpurGear(20)
    r, rb, ra, _ = circles(system, gear)
    assert (2 * r, 2 * ra, 2 * rb) == pytest.approx((0.160, 0.176, 0.15035081932574536e0), rel=REL)
    pitch = at_radius(system, gear, r)
    assert pitch.rho_k == pytest.approx(27.3616114660535e-3, rel=REL)
    tip = at_radius(system, gear, ra)
    assert math.degrees(tip.alpha_k) == pytest.approx(31.321257929651313, rel=REL)
    assert tip.rho_k == pytest.approx(45.74557663883218e-3, rel=REL)
    assert tip.s_k == pytest.approx(5.559039876569942e-3, rel=REL)
    assert at_radius(system, gear, rb).s_k == pytest.approx(14.049412062373653e-3, rel=REL)
    pointed = pointed_tip(system, gear)
    assert pointed.r_k == pytest.approx(92.30669896387995e-3, rel=REL)
    assert pointed.theta_k == pytest.approx(0.09344420020708127, rel=REL)  # inv α at the point
    assert math.degrees(pointed.alpha_k) == pytest.approx(35.471029507740546, rel=REL)
    assert abs(pointed.s_k) < 1e-15


@pytest.mark.parametrize("z, x", [(20, 0.0), (13, 0.4), (57, -0.3), (1000, 0.0)])
def test_at_radius_against_the_closed_forms(z: int, x: float) -> None:
    system, gear = ToothSystem(m=3e-3, alpha=ALPHA), SpurGear(z, x)
    r, rb, ra, _ = circles(system, gear)
    for r_k in (rb, (rb + ra) / 2, r, ra):
        a = at_radius(system, gear, r_k)
        alpha_k = math.acos(rb / r_k)
        assert a.s_k == pytest.approx(s_closed(3e-3, z, x, r_k), rel=REL)
        assert a.alpha_k == pytest.approx(alpha_k, rel=REL, abs=1e-12)
        assert a.rho_k == pytest.approx(rb * math.tan(alpha_k), rel=REL, abs=1e-15)
        assert a.theta_k == pytest.approx(inv(alpha_k), rel=1e-7, abs=1e-12)
        assert math.hypot(*a.K_left) == pytest.approx(r_k, rel=REL)
        assert a.K_left == pytest.approx((-a.K_right[0], a.K_right[1]), rel=REL, abs=1e-15)


def test_ring_tooth_is_the_space_of_the_external_one() -> None:
    system = ToothSystem(m=2e-3, alpha=ALPHA)
    ring = SpurGear(60, 0.2, internal=True)
    r, rb, ra, rf = circles(system, ring)
    assert (ra, rf) == pytest.approx((r - 0.8 * 2e-3, r + 1.45 * 2e-3), rel=REL)
    for r_k in (r, rf):
        # ring tooth = pitch − the external tooth of the same z and x
        pitch = 2 * math.pi * r_k / 60
        assert at_radius(system, ring, r_k).s_k == pytest.approx(pitch - s_closed(2e-3, 60, 0.2, r_k), rel=REL)
    with pytest.raises(NotApplicable, match="widens outward"):
        pointed_tip(system, ring)
    with pytest.raises(OutOfDomain, match="inside the base circle"):
        at_radius(system, ring, 0.9 * rb)


@pytest.mark.parametrize("z, x, k", [(20, 0.0, 3), (21, 0.3, 3), (30, -0.2, 3), (60, 0.0, 7), (1000, 0.0, 112)])
def test_span(z: int, x: float, k: int) -> None:
    m = 4e-3
    system, gear = ToothSystem(m=m, alpha=ALPHA), SpurGear(z, x)
    assert span_teeth(system, gear) == k  # exact/gear's choice, the one the check uses
    # the book's rule: k = z/π (tan α_x − 2x tan α/z − inv α) + 0.5, α_x = arccos(d_b/(d + 2xm))
    alpha_x = math.acos(z * math.cos(ALPHA) / (z + 2 * x))
    assert k == round(z / math.pi * (math.tan(alpha_x) - 2 * x * math.tan(ALPHA) / z - inv(ALPHA)) + 0.5)
    if x == 0.0:
        assert k == round(z * 20 / 180 + 0.5)
    w = span(system, gear, k)
    closed = m * math.cos(ALPHA) * ((k - 0.5) * math.pi + z * inv(ALPHA)) + 2 * x * m * math.sin(ALPHA)
    assert w.W == pytest.approx(closed, rel=REL)
    _, rb, _, _ = circles(system, gear)
    assert math.hypot(*w.N) == pytest.approx(rb, rel=REL)
    with pytest.raises(OutOfDomain, match="beyond the tip"):
        span(system, gear, z - 1)


def pins_closed(m: float, z: int, x: float, d: float, internal: bool = False) -> float:
    db = m * z * math.cos(ALPHA)
    sign = -1 if internal else 1
    a_m = arc_inv(inv(ALPHA) + sign * (d / db - math.pi / (2 * z)) + 2 * x * math.tan(ALPHA) / z)
    across = db / math.cos(a_m) * (1.0 if z % 2 == 0 else math.cos(math.pi / (2 * z)))
    return across + sign * d


def test_over_pins_book_000_gear_3() -> None:
    """000 齿轮 3: z = 18, m = 5, pins touching at the reference circle: d_p/2 = 4.33, M = 101.98."""
    system, gear = ToothSystem(m=5e-3, alpha=ALPHA), SpurGear(18)
    p = over_pins(system, gear)
    rb = 45e-3 * math.cos(ALPHA)
    a_m = ALPHA + math.pi / 36  # α_M = α + 90°/z when the pins touch at the reference circle
    assert p.d_pin / 2 == pytest.approx(rb * (math.tan(a_m) - math.tan(ALPHA)), rel=REL)
    assert p.M == pytest.approx(pins_closed(5e-3, 18, 0.0, p.d_pin), rel=REL)
    assert p.d_pin / 2 == pytest.approx(4.33e-3, abs=0.005e-3)
    assert p.M == pytest.approx(101.98e-3, abs=0.015e-3)
    for c in p.contacts:
        assert math.hypot(*c) == pytest.approx(45e-3, rel=REL)
    # the same pin given by its diameter lands where it was
    assert over_pins(system, gear, p.d_pin).M == pytest.approx(p.M, rel=REL)


@pytest.mark.parametrize("z, x, internal, d", [(20, 0.0, False, 1.7), (21, 0.3, False, 1.7), (30, -0.2, False, 1.5),
                                               (60, 0.0, True, 1.44), (61, 0.25, True, 1.5), (1000, 0.0, False, 1.7)])
def test_over_pins_given_diameter(z: int, x: float, internal: bool, d: float) -> None:
    m = 5e-3
    p = over_pins(ToothSystem(m=m, alpha=ALPHA), SpurGear(z, x, internal), d * m)
    assert p.M == pytest.approx(pins_closed(m, z, x, d * m, internal), rel=REL)


def test_undercut_at_the_limit() -> None:
    """Undercut where the cutter's straight flank reaches beyond N: z < 2(h*a − x)/sin²α (17.097)."""
    system = ToothSystem(m=1e-3, alpha=ALPHA)
    limit = 2 / math.sin(ALPHA) ** 2
    assert limit == pytest.approx(17.097, abs=1e-3)
    for z in (8, 14, 16, 17):
        t = tooth_outline(system, SpurGear(z))
        assert t.undercut and t.r_start > t.rb
    # at z = 17 the fillet cuts the involute only 0.54 ppm of r_b above the base circle
    assert tooth_outline(system, SpurGear(17)).r_start / circles(system, SpurGear(17))[1] - 1 < 1e-6
    for z in (18, 20, 41, 42, 100):
        assert not tooth_outline(system, SpurGear(z)).undercut
    # a positive shift takes the cutter out: x_min = h*a − z sin²α/2
    assert not tooth_outline(system, SpurGear(14, 1 - 14 * math.sin(ALPHA) ** 2 / 2 + 1e-3)).undercut
    assert tooth_outline(system, SpurGear(14, 1 - 14 * math.sin(ALPHA) ** 2 / 2 - 1e-3)).undercut


def test_fillet_meets_the_involute_where_the_cutter_flank_ends() -> None:
    """Not undercut, the profile starts where the cutter's straight flank ends, h*a·m below its
    reference line: on the line of action at (h*a − x)m/sin α from P, i.e. r² = r_b² + (r sin α − (h*a − x)m/sin α)²."""
    m = 2e-3
    for z, x in ((20, 0.0), (42, 0.0), (30, 0.4), (18, 0.05)):
        t = tooth_outline(ToothSystem(m=m, alpha=ALPHA), SpurGear(z, x))
        r = m * z / 2
        along = r * math.sin(ALPHA) - (1 - x) * m / math.sin(ALPHA)
        assert t.r_start == pytest.approx(math.hypot(t.rb, along), rel=REL)
        left, _ = t.teeth[len(t.teeth) // 2]
        assert math.hypot(*left.points[0]) == pytest.approx(t.r_start, rel=REL)
        assert math.hypot(*left.points[-1]) == pytest.approx(t.ra, rel=REL)
        for fillet in t.fillets:
            assert math.hypot(*fillet[0]) == pytest.approx(t.rf, rel=REL)
            assert math.hypot(*fillet[-1]) == pytest.approx(t.r_start, rel=REL)


def test_outline_shapes() -> None:
    system = ToothSystem(m=1e-3, alpha=ALPHA)
    t = tooth_outline(system, SpurGear(20), teeth=3, points=12)
    assert len(t.teeth) == 3 and len(t.fillets) == 6
    assert all(len(f.points) == 12 and len(f.strings) == 12 for pair in t.teeth for f in pair)
    assert t.outline[-1] == t.outline[0] and (0.0, 0.0) in t.outline
    # tooth 0 is centred on +y: its flanks are mirror images
    left, right = t.teeth[1]
    assert left.points[5] == pytest.approx((-right.points[5][0], right.points[5][1]), rel=REL)
    whole = tooth_outline(system, SpurGear(9), teeth=20)
    assert len(whole.teeth) == 9 and (0.0, 0.0) not in whole.outline
    # a ring whose tip circle lies inside its base circle: the part inside is a radial line
    ring = tooth_outline(system, SpurGear(30, -0.5, internal=True), points=5)
    assert ring.ra < ring.rb and ring.fillets == () and not ring.undercut
    left, _ = ring.teeth[1]
    assert len(left.points) == 6
    assert math.hypot(*left.points[0]) == pytest.approx(ring.ra, rel=REL)
    assert math.hypot(*left.points[1]) == pytest.approx(ring.rb, rel=REL)
    assert math.atan2(*left.points[0][::-1]) == pytest.approx(math.atan2(*left.points[1][::-1]), rel=REL)
    assert math.hypot(*left.points[-1]) == pytest.approx(ring.rf, rel=REL)


@settings(max_examples=60, deadline=None)
@given(z=st.integers(8, 300), x=st.floats(-0.5, 0.8), m=st.sampled_from([1e-3, 2.5e-3, 8e-3]),
       alpha_deg=st.sampled_from([15.0, 20.0]), internal=st.booleans())
def test_random_gears(z: int, x: float, m: float, alpha_deg: float, internal: bool) -> None:
    alpha = math.radians(alpha_deg)
    if internal:
        z += 20
    system, gear = ToothSystem(m=m, alpha=alpha), SpurGear(z, x, internal)
    r, rb, ra, rf = circles(system, gear)
    s = math.pi * m / 2 + 2 * x * m * math.tan(alpha)
    expected = 2 * math.pi * r / z - s if internal else s
    assert at_radius(system, gear, r).s_k == pytest.approx(expected, rel=REL)
    if not internal and ra <= rb:
        return
    t = tooth_outline(system, gear, teeth=2, points=6)
    lo, hi = min(ra, rf), max(ra, rf)
    for p in t.outline:
        if p != (0.0, 0.0) and math.hypot(*p) < 1.5 * hi:  # the ring's rim is outside on purpose
            assert lo * (1 - 1e-12) <= math.hypot(*p) <= hi * (1 + 1e-12) or internal
    for pair in t.teeth:
        for f in pair:
            for p in f.points:
                assert lo * (1 - 1e-12) <= math.hypot(*p) <= hi * (1 + 1e-12)


def test_the_cutters_rounding_is_capped_where_the_two_meet_and_a_pointed_rack_is_refused():
    """c*m/(1 − sin α) fills the clearance at 20°; from about 22° the two roundings of the cutter's
    tip would overlap, so they meet at its middle (a full-round tip); past 32° (h*a + c* = 1.25)
    the basic rack's tooth is pointed before its tip line and no cutter exists."""
    from graphmech.errors import NotApplicable
    from graphmech.methods.involute import tooth_outline

    for deg in (22.0, 25.0, 30.0):
        out = tooth_outline(ToothSystem(0.004, math.radians(deg)), SpurGear(30), teeth=1)
        rs = [math.hypot(*p) for p in out.outline if p != (0.0, 0.0)]  # the sector closes through O
        assert min(rs) == pytest.approx(out.rf, rel=1e-9)  # the fillet still reaches the root circle
        assert max(rs) <= out.ra * (1 + 1e-12)
    with pytest.raises(NotApplicable, match="pointed before its tip line"):
        tooth_outline(ToothSystem(0.004, math.radians(35.0)), SpurGear(30))
