"""How big a linkage is (graphmech/problems/linkage/sizes.py): the position's name, the typical
length and speeds that scale relative errors, and a mechanism too far from the origin."""
from __future__ import annotations

import math
import tomllib
from types import SimpleNamespace

import pytest

from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import Guide, SliderInput
from graphmech.problems.linkage.check import analyse
from graphmech.problems.linkage.sizes import (characteristic, mechanism_size, offset_ratio, offset_warning,
                                              position_text, refuse_far_from_origin)
from graphmech.scene import parse_scene
from tests.scenes import scene_text

#: AD 120, AB 60 (link 2) at 30°, BC 120, CD 90 mm; 100 rpm, ε = 4 rad/s².
FOURBAR = scene_text("linkage/fourbar_phi30")
OMEGA = 100 * 2 * math.pi / 60


def fourbar(offset_mm: int = 0):
    """The four-bar, moved ``offset_mm`` along x from the origin."""
    text = FOURBAR.replace("A = [0, 0]", f"A = [{offset_mm}, 0]").replace("D = [120, 0]", f"D = [{offset_mm + 120}, 0]")
    return parse_scene(tomllib.loads(text))


def test_a_position_is_named_by_the_drivers_angle_or_travel():
    crank = SimpleNamespace(linkage=fourbar().linkage)
    assert position_text(crank, "30") == "φ₂ = 30°"
    slider = SimpleNamespace(linkage=SimpleNamespace(driver=SliderInput("1", "B", Guide((0.0, 0.0), 0.0), 0.5)))
    assert position_text(slider, "40") == "s₁ = 40"


def test_the_typical_length_without_a_solution_is_the_longest_link_or_frame_distance():
    assert mechanism_size(fourbar().linkage) == pytest.approx(0.12)  # BC = AD = 120 mm


def test_the_typical_length_with_a_solution_is_the_diagonal_of_what_the_points_sweep():
    scene = fourbar()
    an = analyse(scene)
    pts = [an.exact.point[p][0] for p in ("A", "B", "C", "D", "E")]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    assert mechanism_size(scene.linkage, an.exact) == pytest.approx(math.hypot(max(xs) - min(xs), max(ys) - min(ys)))


def test_characteristic_sizes_of_a_crank_driven_linkage():
    """ω₁·AB for speeds, (ω₁² + |ε|)·AB for accelerations, with √|ε| added to ω for a start from rest."""
    lk = fourbar().linkage
    w = OMEGA + 2.0  # √4
    assert characteristic(lk, "m/s") == pytest.approx(w * 0.06)
    assert characteristic(lk, "m/s²") == pytest.approx((OMEGA ** 2 + 4.0) * 0.06)
    assert characteristic(lk, "rad/s") == pytest.approx(w)
    assert characteristic(lk, "m", size=0.3) == 0.3
    assert characteristic(lk, "deg") == 360.0 and characteristic(lk, "N") == 1.0


def test_characteristic_sizes_of_a_slider_driven_linkage():
    lk = SimpleNamespace(driver=SliderInput("1", "B", Guide((0.0, 0.0), 0.0), 0.5, 2.0))
    assert characteristic(lk, "m/s", size=0.5) == pytest.approx(0.5 + 1.0)  # v + √(a·L)
    assert characteristic(lk, "m/s²", size=0.5) == pytest.approx(2.0 + 0.5)  # a + v²/L
    assert characteristic(lk, "rad/s", size=0.5) == pytest.approx(3.0)  # (v + √(a·L))/L


def test_a_mechanism_near_the_origin_gets_no_warning():
    lk = fourbar().linkage
    assert offset_ratio(lk, 0.12) == pytest.approx(1.0)  # D at 120 mm, the size 120 mm
    assert offset_warning(lk, 0.12) == ""


def test_far_from_the_origin_digits_are_lost_and_then_refused():
    mid = fourbar(10**12)  # 1e9 m away: about 9 digits left
    assert offset_ratio(mid.linkage, 0.12) == pytest.approx(1e9 / 0.12)
    assert offset_warning(mid.linkage, 0.12).startswith(
        "the mechanism lies 8.3e+09 times its own size from the origin: its coordinates keep only about 6 "
        "significant digits")
    far = fourbar(10**17)
    with pytest.raises(SceneError) as info:
        refuse_far_from_origin(far, far.linkage, 0.12)
    assert info.value.problems[0][0] == "frame" and "keep no digit of its geometry" in str(info.value)
    refuse_far_from_origin(mid, mid.linkage, 0.12)  # still drawn, with the warning
