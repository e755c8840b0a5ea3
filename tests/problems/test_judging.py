"""Judging (graphmech/problems/judging.py): a check table's rows, a hand measurement's verdict
within the drawing precision × μ, names with a position, drawn segments, and values that leave
double precision refused in words."""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from graphmech.accuracy import CONSTRUCTION
from graphmech.errors import DegenerateConstruction
from graphmech.problems.judging import (OUT_OF_RANGE, Row, Verdict, close_names, finite, in_double_precision,
                                        is_segment, judge_value, measured_entries, refuse_non_finite, split_name)

#: pc = 43.36 mm at μv = 0.02 (m/s)/mm: v_C = 0.8672 m/s against the exact 0.86713 m/s.
PC = Row("v_C@50", "m/s", 43.36, 0.02, 0.8672, 0.86713, 8.1e-5)


def test_a_row_is_a_construction_until_it_carries_its_own_estimate():
    assert PC.error_source == CONSTRUCTION and PC.error_estimate is None and not PC.ill_conditioned
    chord = PC.estimated("chords", 0.016, "12 positions")
    assert (chord.error_source, chord.error_estimate, chord.basis) == ("chords", 0.016, "12 positions")
    assert chord.graphical == PC.graphical and PC.error_source == CONSTRUCTION  # a new row; the old one unchanged
    assert list(PC.as_dict()) == ["name", "unit", "drawn_mm", "scale", "graphical", "exact", "rel_error",
                                  "ill_conditioned", "error_source", "error_estimate", "basis"]
    assert PC.as_dict()["drawn_mm"] == 43.36


def test_a_length_off_the_drawing_is_judged_within_the_precision_times_mu():
    """0.5 mm at μv = 0.02 (m/s)/mm: ± 0.01 m/s about 0.86713."""
    ok = judge_value("v_C", 0.876, 0.86713, 43.36, 0.02, 0.5, "m/s")
    assert ok == Verdict("v_C", 0.876, 0.86713, pytest.approx(0.01), True, "m/s")
    assert not judge_value("v_C", 0.878, 0.86713, 43.36, 0.02, 0.5, "m/s").ok
    assert judge_value("v_C", 0.86713 - 0.01, 0.86713, 43.36, -0.02, 0.5, "m/s").ok  # |μ|, the edge included


def test_a_computed_value_is_judged_within_a_thousandth():
    v = judge_value("omega_3", 2.502, 2.5, None, 1.0, 0.5, "rad/s")
    assert v.tolerance == pytest.approx(0.0025) and v.ok
    assert not judge_value("omega_3", 2.503, 2.5, None, 1.0, 0.5, "rad/s").ok
    zero = judge_value("v_C", 0.0, 0.0, None, 1.0, 0.5, "m/s")
    assert zero.ok and zero.tolerance > 0.0  # a zero expected value still has a tolerance
    assert zero.as_dict() == {"name": "v_C", "measured": 0.0, "expected": 0.0, "tolerance": zero.tolerance,
                              "ok": True, "unit": "m/s"}


def test_names_split_at_the_position():
    assert split_name("v_C@50") == ("v_C", "50")
    assert split_name("omega_2") == ("omega_2", None)
    assert split_name("v_C_diagram@1.5") == ("v_C_diagram", "1.5")


@pytest.mark.parametrize("name, segment", [
    ("pc", True), ("p'c'", True), ("n2'c'", True), ("b′c′", True), ("v_C", False), ("pcd", False), ("p", False),
    ("omega", False),
])
def test_a_drawn_segment_is_named_by_its_two_end_letters(name, segment):
    assert is_segment(name) is segment


def test_close_names_suggest_up_to_three():
    assert close_names("omega_4", ["omega_2", "omega_3", "v_C"]) == "; did you mean omega_3, omega_2?"  # best first
    assert close_names("zzz", ["v_C"]) == ""


def test_measured_entries_keep_where_each_value_came_from():
    scene = SimpleNamespace(measured=(("pc", 43.0), ("omega_3@30", -2.5)))
    assert measured_entries(scene, (("v_C", 0.86),)) == [
        ("measured.pc", "pc", 43.0), ("measured.omega_3@30", "omega_3@30", -2.5), ("--measured v_C", "v_C", 0.86)]


def test_numbers_out_of_double_precision_are_said_in_one_line():
    with in_double_precision("J_F"):
        assert np.isinf(np.float64(1e300) * 1e300)  # numpy quiet
    with pytest.raises(DegenerateConstruction) as info:
        with in_double_precision("J_F"):
            raise OverflowError("(34, 'Numerical result out of range')")
    assert OUT_OF_RANGE in str(info.value) and "J_F" in str(info.value)


def test_a_row_that_is_not_finite_is_refused_by_name():
    refuse_non_finite([PC])
    with pytest.raises(DegenerateConstruction, match="J_F"):
        refuse_non_finite([Row("J_F", "kg·m²", None, 1.0, math.inf, 1.0, 0.0)])
    with pytest.raises(DegenerateConstruction, match="its error estimate left double precision"):
        refuse_non_finite([PC.estimated("chords", math.nan, "12 positions")])
    an = SimpleNamespace(rows=[PC])
    assert finite(an) is an
    with pytest.raises(DegenerateConstruction):
        finite(SimpleNamespace(rows=[Row("x", "m", None, 1.0, 1.0, math.nan, 0.0)]))
