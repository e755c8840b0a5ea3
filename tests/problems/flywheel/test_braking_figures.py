"""The run-down under a brake drawn as ω(t): its scales, intercepts, the required time, the draw calls."""
from __future__ import annotations

import re

import math

import pytest

from graphmech.drawing.primitives import Arrow, Sheet
from graphmech.problems.flywheel.braking_figures import (AXIS_OVERRUN, OMEGA_AXIS_MM, T_AXIS_MM, draw_rundown,
                                                         rundown_panel)
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet
from graphmech.scales import round_scale
from tests.conftest import SCENES, check_json, values


def test_a_braking_scene_draws_its_rundown_and_reads_t_stop_off_it():
    """ω(t) from ω0 = 100 rad/s at μω = 2 (rad/s)/mm falls to 0 at 125 mm of t at μt = 0.02 s/mm: 2.5 s."""
    from graphmech.scene import render_scene
    from graphmech.problems.flywheel.braking_figures import rundown_panel
    from graphmech.drawing.primitives import Segment

    doc = check_json(SCENES / "fly.brake_time.toml")
    q = values(doc)["t_stop"]
    assert (q["drawn_mm"], q["scale"], q["graphical"]) == (125.0, 0.02, 2.5)
    assert doc["scales"] == {"t": 0.02, "omega": 2.0}
    panel = rundown_panel(0.5, 100.0, 20.0, 3.0)
    bold = [i for i in panel.items if isinstance(i, Segment) and i.role == "result"]
    assert [(b.p0, b.p1) for b in bold] == [((0.0, 50.0), (125.0, 0.0))]
    required = [i for i in panel.items if isinstance(i, Segment) and i.dashed]
    assert required[0].p0 == (150.0, 0.0)  # t ≤ 3 s at 0.02 s/mm
    assert "stops in time" in panel.notes[-1]
    assert "does NOT stop in time" in rundown_panel(0.5, 100.0, 20.0, 2.0).notes[-1]
    svg, _ = render_scene(SCENES / "fly.brake_time.toml")
    seen = re.sub(r"<[^>]+>", "", svg)  # the text as read: sub- and superscripts are tspans
    assert "μt = 0.02 s/mm" in seen and "Run-down" in seen


# ----------------------------------------------------------------------------- draw_rundown
@pytest.mark.parametrize("J, omega0, M", [(0.5, 100.0, 20.0), (1.0, 7.0, 3.0), (12.5, 157.08, 400.0),
                                          (3e-4, 0.2, 1e-3)])
def test_the_intercept_on_the_t_axis_is_J_omega0_over_M(J, omega0, M):
    """Uniform deceleration ε = M/J: the line from ω0 meets the t axis at t = J·ω0/M."""
    r = draw_rundown(J, omega0, M)
    assert r.t_stop == pytest.approx(J * omega0 / M, rel=1e-12)
    assert r.omega0_mm * r.mu_omega == pytest.approx(omega0, rel=1e-15)
    # the scales are round and the smallest that keep both axes within their lengths
    assert round_scale(r.mu_t) == r.mu_t and round_scale(r.mu_omega) == r.mu_omega
    assert r.t_stop_mm <= T_AXIS_MM * (1 + 1e-12) and r.omega0_mm <= OMEGA_AXIS_MM * (1 + 1e-12)
    assert r.mu_t == round_scale(J * omega0 / M / T_AXIS_MM)
    assert r.mu_omega == round_scale(omega0 / OMEGA_AXIS_MM)


def test_a_required_time_longer_than_the_stop_sets_the_t_scale():
    """J = 1, ω0 = 7, M = 3 stops in 7/3 s; a limit of 10 s is drawn too, so μt is chosen for 10 s."""
    free, limited = draw_rundown(1.0, 7.0, 3.0), draw_rundown(1.0, 7.0, 3.0, 10.0)
    assert free.mu_t == 0.02 and limited.mu_t == 0.1  # round_scale(7/3/160), round_scale(10/160)
    assert limited.t_stop_mm == pytest.approx(70.0 / 3.0, rel=1e-15) and limited.t_stop == pytest.approx(7 / 3)
    assert limited.mu_omega == free.mu_omega == 0.1 and limited.omega0_mm == pytest.approx(70.0)
    # a limit shorter than the stop leaves the scale to the stop itself
    assert draw_rundown(1.0, 7.0, 3.0, 1.0) == free


@pytest.mark.parametrize("J, omega0, M", [(0.0, 100.0, 20.0), (0.5, -100.0, 20.0), (0.5, 100.0, 0.0),
                                          (math.nan, 100.0, 20.0), (0.5, 100.0, -20.0)])
def test_a_run_down_needs_positive_inertia_speed_and_moment(J, omega0, M):
    with pytest.raises(ValueError, match="must all be > 0"):
        draw_rundown(J, omega0, M)


# ----------------------------------------------------------------------------- rundown_panel
def record(panel) -> tuple:
    return draw_sheet(Sheet("run-down", (panel,)), RecordingBackend(), on_warning=lambda w: None)


def test_the_drawn_line_and_axes_in_the_draw_calls():
    """fly.brake_time: the bold line runs 125 mm along t and 50 mm down from ω0; the axes overrun both."""
    calls = record(rundown_panel(0.5, 100.0, 20.0))
    lines = [c for c in calls if c[0] == "line"]
    (result,) = [c for c in lines if c[3] == "result"]
    (x0, y0), (x1, y1) = result[1], result[2]
    assert (x1 - x0, y1 - y0) == pytest.approx((125.0, 50.0), abs=1e-9)  # the page's y grows downwards
    t_axis, omega_axis = [c for c in lines if c[3] == "label"]
    assert t_axis[1] == pytest.approx((x0, y1)) and omega_axis[1] == pytest.approx((x0, y1))  # both from O
    assert t_axis[2][0] - x0 > 125.0 and omega_axis[2][1] < y0  # past t_stop and above ω0 (less the arrowheads)
    assert not [c for c in lines if c[4]]  # no required time: nothing dashed
    texts = [c[1] for c in calls if c[0] == "text"]
    assert {"ω", "t", "O", "ω_{0}", "t_{stop}"} <= set(texts) and "t allowed" not in texts
    assert "ε = M_{T}/J = 20/0.5 = 40 rad/s^{2}; t_{stop} = μ_{t}·⟨Ot_{stop}⟩ = 0.02·125 = 2.5 s" in texts


def test_the_required_time_is_a_dashed_ordinate_up_to_omega0():
    panel = rundown_panel(0.5, 100.0, 20.0, 3.0)
    calls = record(panel)
    (result,) = [c for c in calls if c[0] == "line" and c[3] == "result"]
    (dashed,) = [c for c in calls if c[0] == "line" and c[4]]
    assert dashed[3] == "construction"
    (x0, y0), (_, y_t) = result[1], result[2]
    assert dashed[1][0] - x0 == pytest.approx(150.0, abs=1e-9)  # 3 s at 0.02 s/mm
    assert sorted([dashed[1][1], dashed[2][1]]) == pytest.approx(sorted([y0, y_t]), abs=1e-9)  # 0 … ω0
    assert "t allowed" in [c[1] for c in calls if c[0] == "text"]
    # the t axis reaches past the limit, not only past t_stop
    arrow = [i for i in panel.items if isinstance(i, Arrow)][0]
    assert arrow.p1 == (150.0 + AXIS_OVERRUN, 0.0)


@pytest.mark.parametrize("limit, verdict", [(2.5, "stops in time"), (2.4999, "does NOT stop in time"),
                                            (60.0, "stops in time")])
def test_the_verdict_on_the_required_time(limit, verdict):
    """t_stop = 2.5 s: a limit of exactly 2.5 s is met (t ≤ t_allowed)."""
    panel = rundown_panel(0.5, 100.0, 20.0, limit)
    assert panel.name == "rundown" and len(panel.notes) == 3
    assert panel.notes[-1] == f"required t ≤ {limit:.6g} s: {verdict}"
    assert len(rundown_panel(0.5, 100.0, 20.0).notes) == 2  # no limit, no verdict
