"""The generation's kinematics and the exact generated profile: the bank's four cases, and the
profile checked against the involute and fillet the tooth construction draws."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.exact import gear as ex
from graphmech.exact import rack_generation as erg
from graphmech.mechanisms.gear import RackGeneration, SpurGear, ToothSystem
from graphmech.methods import involute as inv

M4 = ToothSystem(0.004, math.radians(20.0))
RPM = math.pi / 30.0


def test_the_books_four_cases(problems):
    e = problems["gear.rack_cutter_generation_cases"]["exact"]
    c1 = erg.kinematics(M4, RackGeneration(0.002), 15)
    assert (c1.r * 1e3, c1.L * 1e3, c1.n) == pytest.approx((e["c1_r_mm"], e["c1_L_mm"], e["c1_n_r_min"]), rel=1e-12)
    c2 = erg.kinematics(M4, RackGeneration(0.002), 15, 2.0 / 17.0)
    assert (c2.x, c2.L * 1e3, c2.n) == pytest.approx((e["c2_x"], e["c2_L_mm"], e["c2_n_r_min"]), rel=1e-12)
    for case, n in (("c3", 0.7958), ("c4", 0.5305)):
        c = erg.kinematics(M4, RackGeneration(0.002, n * RPM, 0.030))
        assert (c.r * 1e3, c.z, c.x) == pytest.approx((e[f"{case}_r_mm"], e[f"{case}_z"], e[f"{case}_x"]), rel=1e-12)
        assert c.n == pytest.approx(n, rel=1e-14) and c.L == 0.030


def test_kinematics_refusals():
    with pytest.raises(OutOfDomain):
        erg.kinematics(M4, RackGeneration(0.002, 0.1))  # ω without L
    with pytest.raises(OutOfDomain):
        erg.kinematics(M4, RackGeneration(0.002))  # neither ω nor z


@pytest.mark.parametrize("gear", [SpurGear(15), SpurGear(10), SpurGear(18, -1.5), SpurGear(40, 0.5),
                                  SpurGear(15, 2.0 / 17.0)])
def test_the_profile_passes_through_the_drawn_tooth(gear):
    # methods/involute draws tooth 0 on +y; here the space is on +y: half a pitch apart
    o = inv.tooth_outline(M4, gear, teeth=3, points=40)
    pts = np.array([p for f in o.fillets for p in f] + [p for t in o.teeth for fl in t for p in fl.points])
    c, s = math.cos(math.pi / gear.z), math.sin(math.pi / gear.z)
    turned = pts @ np.array([[c, s], [-s, c]])
    prof = erg.generated_profile(M4, gear)
    assert prof.distance(turned).max() < 1e-12 * M4.m
    assert prof.distance(pts).max() > 0.1 * M4.m  # a real test: off by half a pitch it is far
    assert prof.undercut == o.undercut
    # near the limit shift the fillet crosses the involute at a grazing angle: the crossing is ill-conditioned
    assert prof.r_limit == pytest.approx(o.r_start, rel=1e-9 if abs(gear.x - 2.0 / 17.0) > 0.01 else 1e-5)


def test_thickness_on_the_involute_and_on_the_fillet():
    g = SpurGear(30, 0.3)
    prof, t = erg.generated_profile(M4, g), ex.tooth(M4, g)
    assert prof.thickness(prof.r) == pytest.approx(t.s, rel=1e-13)
    assert prof.thickness(prof.ra) == pytest.approx(t.sa, rel=1e-13)
    cut = erg.generated_profile(M4, SpurGear(18, -1.5))
    assert cut.r_limit > cut.ra  # the fillet has cut away all the involute
    sa = cut.thickness(cut.ra)
    assert sa is not None and sa < ex.tooth(M4, SpurGear(18, -1.5)).sa
    assert cut.thickness(cut.rf * 0.99) is None


def test_no_ring():
    with pytest.raises(NotApplicable):
        erg.generated_profile(M4, SpurGear(40, internal=True))
