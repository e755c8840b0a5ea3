"""The synthesis check table: names asked by find, hand values judged, unknown names refused."""
from __future__ import annotations

import pytest

from graphmech.errors import SceneError
from graphmech.problems.synthesis.check import (
    analyse_synthesis,
    judge_synthesis,
    text_lines,
)
from tests.scenes import parse_text, replace_once, scene_text

SWING = scene_text("synthesis/swing")


def test_find_keeps_the_rows_asked_in_their_order_and_mu_is_chosen():
    an = analyse_synthesis(parse_text(replace_once(SWING, "[synthesis]", 'find = ["lAB", "K"]\n[synthesis]')))
    assert [r.name for r in an.rows] == ["lAB", "K"]
    assert an.scales == {"l": 0.002} and an.scale_notes() == ["μl = 0.002 m/mm (chosen)"]


def test_a_stated_scale_is_kept_and_the_drawn_length_is_the_length_over_it():
    an = analyse_synthesis(parse_text(replace_once(SWING, "[synthesis]", "[scales]\nl_mm_per_mm = 1\n[synthesis]")))
    r = {r.name: r for r in an.rows}["lAB"]
    assert an.stated == {"l"} and r.drawn_mm == pytest.approx(r.exact * 1000, rel=1e-12)


def test_a_hand_length_is_judged_within_the_drawing_precision():
    text = replace_once(SWING, "swing_deg = 40", "swing_deg = 40\n[measured]\nlAB = 0.0230\nlBC = 0.052")
    verdicts = {v.name: v for v in judge_synthesis(analyse_synthesis(parse_text(text)))}
    assert verdicts["lAB"].ok and not verdicts["lBC"].ok and verdicts["lAB"].tolerance == pytest.approx(0.001)


def test_an_unknown_name_is_refused_with_the_nearest():
    with pytest.raises(SceneError) as e:
        analyse_synthesis(parse_text(replace_once(SWING, "[synthesis]", 'find = ["sol1_lAB"]\n[synthesis]')))
    assert e.value.problems == [("find[0]", ("unknown synthesis quantity 'sol1_lAB': the construction gives one "
                                             "design, its names take no sol prefix (lAB)"))]
    with pytest.raises(SceneError) as e:
        analyse_synthesis(parse_text(replace_once(SWING, "[synthesis]", 'find = ["lABC"]\n[synthesis]')))
    assert e.value.problems == [("find[0]", "unknown synthesis quantity 'lABC'; did you mean lBC, lAB?")]


def test_under_the_table_each_design_says_its_class_and_reanalysis():
    (line,) = text_lines(analyse_synthesis(parse_text(SWING)))
    assert "crank-rocker" in line and "K = 1.4" in line and "psi" in line
