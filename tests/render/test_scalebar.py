"""Scale bars: a round value of the quantity, 20–50 mm of paper at the panel's μ, numbers under
the ticks clear of each other, the symbol left and the unit right; angles in degrees."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.drawing.lettering import text_box_size
from graphmech.render.recording import RecordingBackend
from graphmech.render.scalebar import (BAR_HEIGHT, BAR_RANGE_MM, ScaleBar, draw_scale_bar, scale_bar,
                                       unit_of)
from graphmech.scales import SCALE_INFO


def text_boxes(calls) -> list[tuple[str, tuple[float, float, float, float]]]:
    """The texts' boxes as drawn (anchor start / middle / end, box centred on the baseline's text)."""
    out = []
    for _, s, (x, y), size, anchor, _, _ in [c for c in calls if c[0] == "text"]:
        w, h = text_box_size(s, size)
        x0 = {"start": x, "middle": x - w / 2, "end": x - w}[anchor]
        mid = y - 0.35 * size
        out.append((s, (x0, mid - h / 2, x0 + w, mid + h / 2)))
    return out


def overlap(a, b) -> bool:
    return min(a[2], b[2]) > max(a[0], b[0]) and min(a[3], b[3]) > max(a[1], b[1])


def test_a_velocity_bar() -> None:
    bar = scale_bar("v", 0.005)
    assert (bar.name, bar.unit, bar.value, bar.length, bar.divisions) == ("μ_{v}", "m/s", 0.2, 40.0, 4)
    assert bar.ticks == ((0.0, "0"), (10.0, "0.05"), (20.0, "0.1"), (30.0, "0.15"), (40.0, "0.2"))


def test_an_angle_is_measured_in_degrees() -> None:
    bar = scale_bar("phi", math.radians(2.0))  # μφ kept in rad/mm, written 2 °/mm
    assert (bar.unit, bar.value, bar.length) == ("°", 50.0, 25.0)
    assert [t for _, t in bar.ticks] == ["0", "50"]


def test_units_are_the_scales_without_per_mm() -> None:
    assert [unit_of(s) for s in ("l", "v", "a", "F", "M", "J", "T", "t", "omega", "W", "s")] == [
        "m", "m/s", "m/s²", "N", "N·m", "kg·m²", "J", "s", "rad/s", "kg·m", "m"]


def test_numbers_that_do_not_fit_every_tick_stand_at_the_ends_and_middle() -> None:
    bar = scale_bar("l", 0.001)  # 0.02 m in 20 mm: four parts of 5 mm, no room for "0.005"
    assert bar.divisions == 4 and [t for _, t in bar.ticks] == ["0", "0.01", "0.02"]
    tiny = scale_bar("l", 1e-300)
    assert [t for _, t in tiny.ticks] == ["0", "2×10^{−299}"]  # the drawing's powers of ten


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(sorted(SCALE_INFO)), st.floats(1e-12, 1e12))
def test_every_bar_is_round_measurable_and_lettered_clear(symbol: str, mu: float) -> None:
    bar = scale_bar(symbol, mu)
    lo, hi = BAR_RANGE_MM
    assert lo - 1e-9 <= bar.length <= hi + 1e-9
    per_mm = math.degrees(mu) if symbol in ("phi", "psi") else mu
    assert bar.length == pytest.approx(bar.value / per_mm, rel=1e-12)  # drawn at the panel's μ
    mantissa = bar.value / 10.0 ** math.floor(math.log10(bar.value))
    assert min(abs(mantissa - m) for m in (1.0, 2.0, 5.0)) < 1e-9
    assert bar.ticks[0] == (0.0, "0") and bar.ticks[-1][0] == pytest.approx(bar.length)
    rec = RecordingBackend()
    draw_scale_bar(bar, (100.0, 50.0), rec)
    calls = rec.finish()
    parts = [c for c in calls if c[0] == "polyline"]
    assert len(parts) == bar.divisions and [c[4] for c in parts] == [k % 2 == 0 for k in range(bar.divisions)]
    xs = [p[0] for c in parts for p in c[1]]
    assert min(xs) == pytest.approx(100.0 + bar.bar_left) and max(xs) == pytest.approx(100.0 + bar.bar_left + bar.length)
    boxes = text_boxes(calls)
    assert [s for s, _ in boxes] == [bar.name, bar.unit] + [t for _, t in bar.ticks]
    for i, (_, a) in enumerate(boxes):
        assert 100.0 - 1e-9 <= a[0] and a[2] <= 100.0 + bar.width + 1e-9  # inside the block
        assert 50.0 - 1e-9 <= a[1] and a[3] <= 50.0 + bar.height + 1e-9
        for _, b in boxes[i + 1:]:
            assert not overlap(a, b)
    bar_box = (100.0 + bar.bar_left, 50.0 + bar.bar_top, 100.0 + bar.bar_left + bar.length,
               50.0 + bar.bar_top + BAR_HEIGHT)
    assert not any(overlap(b, bar_box) for _, b in boxes)


def test_refused_scales() -> None:
    for mu in (0.0, -1.0, math.inf, math.nan):
        with pytest.raises(ValueError, match="positive, finite"):
            scale_bar("l", mu)
    with pytest.raises(ValueError, match="no scale 'chi'"):
        scale_bar("chi", 0.01)
    # an oscillating follower's swing ψ is an angle: measured in degrees like φ
    psi, phi = scale_bar("psi", math.radians(0.5)), scale_bar("phi", math.radians(0.5))
    assert (psi.length, psi.value, psi.unit, psi.ticks) == (phi.length, phi.value, phi.unit, phi.ticks)


def test_bars_are_values() -> None:
    assert scale_bar("F", 25.0) == scale_bar("F", 25.0)
    assert isinstance(scale_bar("F", 25.0), ScaleBar)
