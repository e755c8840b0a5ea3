"""The shared words of every construction protocol (graphmech/problems/protocol.py)."""
from __future__ import annotations

import math

import pytest

from graphmech.problems.protocol import (
    PHRASES,
    num,
    phrase,
    scale,
    scale_choice,
    sense,
    text,
)


def test_numbers_have_four_significant_figures_and_plain_powers():
    assert [num(x) for x in (52.134, -0.00872665, 2.5, 1234567.0, 0.0)] == ["52.13", "−0.008727", "2.5", "1.235×10⁶", "0"]
    assert text("μ_{F} = 2×10^{−6} N/mm") == "μF = 2×10⁻⁶ N/mm" and text("ω_{12}") == "ω₁₂"


def test_a_scale_is_stated_and_says_whether_it_was_given():
    assert scale("v", 0.005) == "μv = 0.005 (m/s)/mm" and scale("phi", math.radians(2.5)) == "μφ = 2.5 °/mm"
    assert scale_choice("a", 0.05, True, "en") == "μa = 0.05 (m/s²)/mm (as the scene gives it)"
    assert scale_choice("l", 0.002, False, "zh") == "μl = 0.002 m/mm（按图幅选取）"
    assert scale_choice("l", 0.002, False, "ru") == "μl = 0.002 m/mm (выбран по формату листа)"


def test_senses_and_phrases_in_three_notations():
    assert (sense(2.0, "en"), sense(-2.0, "zh"), sense(-1.0, "ru"), sense(0.0, "en")) == \
        ("counter-clockwise", "顺时针", "по часовой стрелке", "")
    assert phrase("measure", "en", PHRASES, seg="pc", mm="52.1", value="v_C = 0.521 m/s") == \
        "measure pc = 52.1 mm: v_C = 0.521 m/s"
    with pytest.raises(KeyError):
        phrase("measure", "de", PHRASES, seg="", mm="", value="")
