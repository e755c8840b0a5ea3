"""A driver's swing (graphmech/methods/swing.py): its N positions out and back, and its limits
constructed where the dyad on its point toggles — against the closed forms of exact/swing.py and
against the textbook's numbers worked by hand."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from graphmech.errors import NotApplicable
from graphmech.exact import swing as exact
from graphmech.mechanisms.linkage import RPR, RRP, RRR, Crank, Guide, Linkage, SliderInput
from graphmech.methods.swing import driver_limits, output_swing, swing_positions, toggle_dyad

#: AB = 80, BC = 40, CD = 60, AD = 50 mm: 80 + 40 > 60 + 50, so AB rocks (no link turns fully).
ROCKER = Linkage({"A": (0.0, 0.0), "D": (0.05, 0.0)}, Crank("1", "A", "B", 0.08, 5.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.04, 0.06), "left"),))
#: A slider B on the x axis through O drives BC = 80, CD = 50 mm, D = (100, 60) mm.
SLIDER = Linkage({"O": (0.0, 0.0), "D": (0.1, 0.06)}, SliderInput("1", "B", Guide((0.0, 0.0), 0.0), 0.5),
                 (RRR("B", "C", "D", ("2", "3"), (0.08, 0.05), "right"),))


def test_the_positions_go_out_in_equal_steps_and_back():
    q, back = swing_positions(-1.0, 2.0, 12)
    assert q[0] == -1.0 and q[6] == 2.0
    assert np.allclose(np.diff(q[:7]), 0.5, rtol=0, atol=1e-15)
    assert all(q[k] == q[12 - k] for k in range(1, 6))  # position k + 1 and 13 − k: one place
    assert back.tolist() == [False] * 6 + [True] * 6  # 7 … 12 leave on the return stroke


def test_a_rockers_limits_are_where_bc_and_cd_stretch_out():
    # BD = BC + CD = 100 mm: cos φ = (80² + 50² − 100²)/(2·80·50) = −0.1375
    lo, hi = driver_limits(ROCKER, 0.0)
    assert hi == pytest.approx(math.acos(-0.1375), abs=1e-12) and lo == pytest.approx(-math.acos(-0.1375), abs=1e-12)
    assert (lo, hi) == pytest.approx(exact.driver_limits(ROCKER, 0.0), abs=1e-12)


def test_a_sliders_limits_are_where_bd_reaches_bc_plus_cd():
    # (s − 100)² + 60² = 130²: s = 100 ± √13300 mm
    lo, hi = driver_limits(SLIDER, 0.06)
    r = math.sqrt(0.13 ** 2 - 0.06 ** 2)
    assert lo == pytest.approx(0.1 - r, abs=1e-14) and hi == pytest.approx(0.1 + r, abs=1e-14)
    assert (lo, hi) == pytest.approx(exact.driver_limits(SLIDER, 0.06), abs=1e-14)


def test_an_rrp_dyad_limits_its_driver_where_bc_stands_square_to_the_guide():
    # rocker AB = 50 about A = (0, 0), BC = 30 to a slider on y = 60: B's height reaches 60 − 30
    rocker = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.05, 1.0),
                     (RRP("B", "C", ("2", "3"), 0.03, Guide((0.0, 0.06), 0.0)),))
    lo, hi = driver_limits(rocker, math.radians(90.0))  # B no lower than 30 mm: sin φ ≥ 0.6
    assert (lo, hi) == pytest.approx((math.asin(0.6), math.pi - math.asin(0.6)), abs=1e-12)
    assert (lo, hi) == pytest.approx(exact.driver_limits(rocker, math.radians(90.0)), abs=1e-12)
    # a slider on the x axis drives BC = 30 to a slider on the line y = x + 10 mm (through (0, 10) at 45°)
    slider = Linkage({"O": (0.0, 0.0)}, SliderInput("1", "B", Guide((0.0, 0.0), 0.0), 1.0),
                     (RRP("B", "C", ("2", "3"), 0.03, Guide((0.0, 0.01), math.radians(45.0))),))
    lo, hi = driver_limits(slider, 0.0)
    # B = (s, 0) is |s + 10|/√2 from the line: ±30 gives s = −10 ∓ 30√2 mm
    assert (lo, hi) == pytest.approx((-0.01 - 0.03 * math.sqrt(2), -0.01 + 0.03 * math.sqrt(2)), abs=1e-14)
    assert (lo, hi) == pytest.approx(exact.driver_limits(slider, 0.0), abs=1e-14)


def test_what_has_no_limits_is_refused_with_the_reason():
    crank_rocker = Linkage({"A": (0.0, 0.0), "D": (0.072, 0.0)}, Crank("1", "A", "B", 0.028, 1.0),
                           (RRR("B", "C", "D", ("2", "3"), (0.052, 0.05), "left"),))
    with pytest.raises(NotApplicable, match="turns fully"):
        driver_limits(crank_rocker, 0.0)
    with pytest.raises(NotApplicable, match="cannot be assembled at the driver's stated position"):
        driver_limits(ROCKER, math.pi)  # 180° lies outside the swing ±97.9°
    guide_bar = Linkage({"A": (0.0, 0.0), "C": (0.0, -0.2)}, Crank("1", "A", "B", 0.1, 1.0),
                        (RPR("B", "C", ("2", "3"), "second"),))
    with pytest.raises(NotApplicable, match="toggles"):
        toggle_dyad(guide_bar)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.02, 0.2), st.floats(0.02, 0.2), st.floats(0.02, 0.2), st.floats(0.02, 0.2), st.floats(-3.0, 3.0))
def test_every_rockers_limits_agree_with_the_cosine_rule(a, b, c, d, phi0):
    lk = Linkage({"A": (0.0, 0.0), "D": (d * math.cos(0.4), d * math.sin(0.4))}, Crank("1", "A", "B", a, 1.0),
                 (RRR("B", "C", "D", ("2", "3"), (b, c), "left"),))
    # a limit where the crank's circle just touches the circle BD = b ± c is ill-conditioned (√ of ~0)
    assume(all(abs(abs((a * a + d * d - r * r) / (2 * a * d)) - 1.0) > 1e-4 for r in (b + c, abs(b - c))))
    try:
        ours = driver_limits(lk, phi0)
    except NotApplicable as e:
        if "turns fully" in str(e):  # no toggle anywhere: the closed form finds none either
            with pytest.raises(NotApplicable, match="turns fully"):
                exact.driver_limits(lk, phi0)
        else:
            assert not _assembles(lk, phi0)
        return
    assert ours == pytest.approx(exact.driver_limits(lk, phi0), abs=1e-9)
    for q in ours:  # at each limit BD is BC + CD or |BC − CD|: the dyad toggles
        bd = math.dist((a * math.cos(q), a * math.sin(q)), lk.frame_points["D"])
        assert min(abs(bd - (b + c)), abs(bd - abs(b - c))) <= 1e-12
    assert ours[0] < phi0 < ours[1]


def _assembles(lk, phi):
    y = lk.dyads[0]
    bd = math.dist((lk.driver.length * math.cos(phi), lk.driver.length * math.sin(phi)), lk.frame_points["D"])
    return abs(y.lengths[0] - y.lengths[1]) <= bd <= sum(y.lengths)


def test_the_outputs_swing_runs_from_a_limit_to_where_ab_and_bc_fold():
    # CD swings from its angle at the limit φ = 97.9° (B, C, D in one line: ψ = ∠(B − D)) to where
    # A, B, C fold into one line inside the swing (AC = AB − BC = 40: cos ∠ADC = (50² + 60² − 40²)/(2·50·60))
    phi = math.acos(-0.1375)
    B = complex(80.0 * math.cos(phi), 80.0 * math.sin(phi))
    C_fold = complex(50.0 - 60.0 * 0.75, -60.0 * math.sqrt(1.0 - 0.75 ** 2))
    by_hand = math.atan2((B - 50.0).imag, (B - 50.0).real) - math.atan2(C_fold.imag, (C_fold - 50.0).real)
    swing, link = output_swing(ROCKER, *driver_limits(ROCKER, 0.0))
    assert link == "3" and swing == pytest.approx(by_hand, abs=1e-12) and math.degrees(swing) > 180.0
    assert swing == pytest.approx(exact.output_swing(ROCKER, *exact.driver_limits(ROCKER, 0.0)), abs=1e-12)


def test_a_sliders_output_swings_between_its_angles_at_the_strokes_ends():
    # on this branch CD turns one way over 20 … 120 mm (its stop, BC ⟂ the guide at C = (60, 80),
    # is on the other branch): ψ = ∠(B − D) + ∠BDC, cos ∠BDC = (BD² + CD² − BC²)/(2·BD·CD)
    def psi(s_mm):
        bx, by = s_mm - 100.0, -60.0
        bd = math.hypot(bx, by)
        return math.atan2(by, bx) + math.acos((bd * bd + 50.0 ** 2 - 80.0 ** 2) / (2 * bd * 50.0))

    swing, _ = output_swing(SLIDER, 0.02, 0.12)
    assert swing == pytest.approx(psi(120.0) - psi(20.0), abs=1e-12)
    assert swing == pytest.approx(exact.output_swing(SLIDER, 0.02, 0.12), abs=1e-12)
    guide_bar_like = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.05, 1.0),
                             (RRP("B", "C", ("2", "3"), 0.03, Guide((0.0, 0.06), 0.0)),))
    with pytest.raises(NotApplicable, match="slides"):
        output_swing(guide_bar_like, 1.0, 2.0)


#: ROCKER with a second dyad on B: B–X–H, H = (0, 50) mm, BX = HX = 30 mm — it stretches (BH = 60 mm)
#: at φ = 90° − arccos((80² + 50² − 60²)/(2·80·50)) = 41.49°, inside the first dyad's swing.
TWO_ON_B = Linkage({"A": (0.0, 0.0), "D": (0.05, 0.0), "H": (0.0, 0.05)}, Crank("1", "A", "B", 0.08, 5.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.04, 0.06), "left"),
                    RRR("B", "X", "H", ("5", "6"), (0.03, 0.03), "left")))


def test_the_first_dyad_on_the_driver_to_toggle_limits_it():
    # only the first dyad's toggles were cut: the swing ran to −97.9°, past the second's limit, and
    # `between = "limits"` was refused as "the swing goes beyond the driver's limits at position 2"
    lo, hi = driver_limits(TWO_ON_B, math.radians(60))
    assert lo == pytest.approx(math.pi / 2 - math.acos(0.6625), abs=1e-14)
    assert hi == pytest.approx(math.acos(-0.1375), abs=1e-14)  # the first dyad's, BD = 100 mm
    assert (lo, hi) == pytest.approx(exact.driver_limits(TWO_ON_B, math.radians(60)), abs=1e-14)
    # the output CD's swing between them: its end at 41.49° is where the other dyad toggles, and the
    # exact one dropped that end (it took it for a position off the assembly)
    assert output_swing(TWO_ON_B, lo, hi)[0] == pytest.approx(exact.output_swing(TWO_ON_B, lo, hi), rel=1e-12)
