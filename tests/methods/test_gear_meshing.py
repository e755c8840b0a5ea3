"""The pair constructed in mesh, against the book's closed forms written here."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import NoSolution, NotApplicable
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem
from graphmech.methods.gear_meshing import construct_meshing
from tests.methods.test_involute import arc_inv, inv  # the closed forms the tests hold the constructions to

ALPHA = math.radians(20.0)
REL = 1e-9




def closed(m: float, z1: int, z2: int, x1: float = 0.0, x2: float = 0.0, a_w: float | None = None,
           internal: bool = False, ha: float = 1.0) -> dict[str, float]:
    """α′, B1B2 = r_b1(tan α_a1 − tan α′) ± r_b2(tan α_a2 − tan α′), ε, the radii N1B1 …, the backlash."""
    s = -1 if internal else 1
    a = m * (z2 + s * z1) / 2
    if a_w is None:
        xs = (x2 - x1) / (z2 - z1) if internal else (x1 + x2) / (z1 + z2)
        alpha_w = arc_inv(2 * math.tan(ALPHA) * xs + inv(ALPHA))
        a_w = a * math.cos(ALPHA) / math.cos(alpha_w)
    else:
        alpha_w = math.acos(a * math.cos(ALPHA) / a_w)
    rb1, rb2 = m * z1 * math.cos(ALPHA) / 2, m * z2 * math.cos(ALPHA) / 2
    ra1 = m * z1 / 2 + (ha + x1) * m
    ra2 = m * z2 / 2 - (ha - x2) * m if internal else m * z2 / 2 + (ha + x2) * m
    t1, t2 = math.sqrt(ra1**2 - rb1**2) / rb1, math.sqrt(ra2**2 - rb2**2) / rb2
    tw = math.tan(alpha_w)
    B1B2 = rb1 * (t1 - tw) + s * rb2 * (t2 - tw)
    pb = math.pi * m * math.cos(ALPHA)
    rw1, rw2 = rb1 / math.cos(alpha_w), rb2 / math.cos(alpha_w)

    def thick(z: int, x: float, rw: float) -> float:
        r = m * z / 2
        return (math.pi * m / 2 + 2 * x * m * math.tan(ALPHA)) * rw / r - 2 * rw * (inv(alpha_w) - inv(ALPHA))

    pw = 2 * math.pi * rw1 / z1
    s2 = (pw - thick(z2, x2, rw2)) if internal else thick(z2, x2, rw2)  # a ring's tooth = pitch − its space
    PB2 = rb2 * (t2 - tw) * s
    return {"a_w": a_w, "alpha_w": alpha_w, "B1B2": B1B2, "eps": B1B2 / pb, "pb": pb,
            "N1B1": rb1 * t1, "N2B2": rb2 * t2, "N1B2": rb1 * tw - PB2, "N2B1": rb2 * tw - s * rb1 * (t1 - tw),
            "backlash": pw - thick(z1, x1, rw1) - s2, "rw1": rw1, "rw2": rw2, "N1N2": abs(rb2 + s * rb1) * tw}


def test_bank_contact_ratio_19_42() -> None:
    """gear.contact_ratio_19_42 (tests/reference/problems.toml, [problem.exact])."""
    c = construct_meshing(GearSet(ToothSystem(m=5e-3, alpha=ALPHA), (SpurGear(19), SpurGear(42)), "external"))
    assert c.B1B2 == pytest.approx(24.10920747019434e-3, rel=REL)
    assert c.eps_alpha == pytest.approx(1.6333424177366997, rel=REL)
    assert c.a_w == pytest.approx(152.5e-3, rel=REL)
    assert c.alpha_w == pytest.approx(ALPHA, rel=REL)
    # α_a1 = 31.7668°, α_a2 = 26.2362° read at B1, B2 as the angle at O between OB and ON
    assert math.degrees(math.acos(math.hypot(*c.N1) / math.hypot(*c.B1))) == pytest.approx(31.76677921200012, rel=REL)
    assert c.O2 is not None and c.N2 is not None
    ra2 = math.hypot(c.B2[0] - c.O2[0], c.B2[1] - c.O2[1])
    assert math.degrees(math.acos(math.hypot(c.N2[0] - c.O2[0], c.N2[1] - c.O2[1]) / ra2)) \
        == pytest.approx(26.236190060663052, rel=REL)
    assert len(c.zone_points) == 2 and c.double_contact is not None and c.single_contact is not None
    assert c.double_contact == pytest.approx(c.B1B2 - c.pb, rel=REL)
    assert c.single_contact == pytest.approx(2 * c.pb - c.B1B2, rel=REL)
    assert c.backlash is None and c.interference == ()


@pytest.mark.parametrize("z1, z2, x1, x2, a_w, internal", [
    (19, 42, 0.0, 0.0, None, False),
    (19, 42, 0.0, 0.0, 153e-3, False),  # pulled apart: backlash
    (12, 12, 0.6252, 0.6252, None, False),  # the bank's 12/12 at a′ ≈ 130 mm (m = 10 → 5 here)
    (17, 33, 0.2, -0.1, None, False),
    (20, 1000, 0.0, 0.0, None, False),  # nearly a rack
    (20, 80, 0.0, 0.0, None, True),
    (18, 60, 0.1, 0.4, None, True),
    (18, 60, 0.0, 0.0, 104.5e-3, True),  # an internal pair gains backlash coming closer
])
def test_pairs_against_the_closed_forms(z1: int, z2: int, x1: float, x2: float, a_w: float | None,
                                        internal: bool) -> None:
    m = 5e-3
    c = construct_meshing(GearSet(ToothSystem(m=m, alpha=ALPHA), (SpurGear(z1, x1), SpurGear(z2, x2, internal)),
                                  "internal" if internal else "external", a_w))
    e = closed(m, z1, z2, x1, x2, a_w, internal)
    assert c.a_w == pytest.approx(e["a_w"], rel=REL)
    assert c.alpha_w == pytest.approx(e["alpha_w"], rel=REL)
    assert (c.r_w1, c.r_w2) == pytest.approx((e["rw1"], e["rw2"]), rel=REL)
    assert c.B1B2 == pytest.approx(e["B1B2"], rel=REL)
    assert c.eps_alpha == pytest.approx(e["eps"], rel=REL)
    assert c.pb == pytest.approx(e["pb"], rel=REL)
    assert c.N1N2 == pytest.approx(e["N1N2"], rel=REL)
    for key in ("N1B1", "N2B2", "N1B2", "N2B1"):
        assert c.rho[key] == pytest.approx(e[key], rel=REL), key  # signed: negative beyond N
    if a_w is None:
        assert c.backlash is None
    else:
        assert c.backlash == pytest.approx(e["backlash"], rel=REL) and c.backlash > 0
    # P on O1O2, N1 and N2 on the base circles and on the line through P at α′
    assert c.P[0] == pytest.approx(0.0, abs=1e-15)
    assert math.hypot(*c.N1) == pytest.approx(m * z1 * math.cos(ALPHA) / 2, rel=REL)


def test_rack_and_pinion() -> None:
    m, z, x = 4e-3, 20, 0.3
    system = ToothSystem(m=m, alpha=ALPHA)
    rb1, ra1 = m * z * math.cos(ALPHA) / 2, m * z / 2 + (1 + x) * m
    for a_w in (None, m * z / 2 + x * m + 0.5e-3):
        c = construct_meshing(GearSet(system, (SpurGear(z, x),), "rack", a_w))
        depth = (c.a_w - m * z / 2)  # the rack's reference line above the pinion's reference circle
        B1B2 = rb1 * (math.sqrt(ra1**2 - rb1**2) / rb1 - math.tan(ALPHA)) + (m - depth) / math.sin(ALPHA)
        assert c.alpha_w == pytest.approx(ALPHA, rel=REL)
        assert c.r_w1 == pytest.approx(m * z / 2, rel=REL) and c.r_w2 is None and c.N2 is None
        assert c.B1B2 == pytest.approx(B1B2, rel=REL)
        assert set(c.rho) == {"N1B1", "N1B2"}
        if a_w is None:
            assert c.a_w == pytest.approx(m * z / 2 + x * m, rel=REL) and c.backlash is None
        else:
            assert c.backlash == pytest.approx(2 * 0.5e-3 * math.tan(ALPHA), rel=REL)
    # the pair with a z = 1000 wheel approaches the rack's contact ratio
    wheel = construct_meshing(GearSet(system, (SpurGear(20), SpurGear(1000)), "external"))
    rack = construct_meshing(GearSet(system, (SpurGear(20),), "rack"))
    assert wheel.eps_alpha == pytest.approx(rack.eps_alpha, rel=5e-3) and wheel.eps_alpha < rack.eps_alpha


def test_contact_ratio_below_one_is_a_result() -> None:
    c = construct_meshing(GearSet(ToothSystem(m=2e-3, alpha=ALPHA, ha_star=0.5), (SpurGear(20), SpurGear(20)),
                                  "external"))
    e = closed(2e-3, 20, 20, ha=0.5)
    assert e["eps"] < 1 and c.eps_alpha == pytest.approx(e["eps"], rel=REL)
    assert c.zone_points == () and c.single_contact is None and c.double_contact is None


def test_interference_is_noted() -> None:
    system = ToothSystem(m=5e-3, alpha=ALPHA)
    c = construct_meshing(GearSet(system, (SpurGear(20), SpurGear(60, internal=True)), "internal"))
    e = closed(5e-3, 20, 60, internal=True)
    assert e["N1B2"] < 0 and c.interference == ("B2 beyond N1",)  # the ring's tip passes N1
    c = construct_meshing(GearSet(system, (SpurGear(10), SpurGear(60)), "external"))
    assert "B2 beyond N1" in c.interference and closed(5e-3, 10, 60)["N1B2"] < 0
    assert closed(5e-3, 18, 20)["N1B2"] > 0
    assert construct_meshing(GearSet(system, (SpurGear(18), SpurGear(20)), "external")).interference == ()


def test_refusals() -> None:
    system = ToothSystem(m=5e-3, alpha=ALPHA)
    with pytest.raises(NoSolution, match="overlap"):  # closer than the distance without backlash
        construct_meshing(GearSet(system, (SpurGear(19), SpurGear(42)), "external", 152e-3))
    with pytest.raises(NotApplicable, match="inside its base circle"):
        construct_meshing(GearSet(system, (SpurGear(12), SpurGear(30, -0.5, internal=True)), "internal"))
    with pytest.raises(NoSolution, match="overlap"):  # a ring pair pulled apart
        construct_meshing(GearSet(system, (SpurGear(18), SpurGear(60, internal=True)), "internal", 106e-3))
    with pytest.raises(NotApplicable, match="does not mesh"):
        construct_meshing(GearSet(system, (SpurGear(12),)))
