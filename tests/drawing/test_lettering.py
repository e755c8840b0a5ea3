"""Lettering: subscript digits, and the room a line of text takes."""
from __future__ import annotations

import pytest

from graphmech.drawing.lettering import minus, number, plain, runs, subscript, text_box_size


def test_subscript_turns_every_digit_and_nothing_else() -> None:
    assert subscript("0123456789") == "₀₁₂₃₄₅₆₇₈₉"
    assert "φ" + subscript("1") == "φ₁"
    assert subscript("O12'") == "O₁₂'"
    assert subscript("") == ""


def test_text_box_size_is_three_fifths_of_the_size_per_character() -> None:
    assert text_box_size("ω₂", 5.0) == (5.16, 5.0)  # the subscript at its own 0.72 size
    assert text_box_size("速度", 5.0) == (10.0, 5.0)  # a CJK character is a full em
    assert text_box_size("0.1", 2.8) == (5.04, 2.8)  # rounded: no 5.040000000000001
    assert text_box_size("", 4.0) == (2.4, 4.0)  # an empty label still takes a character's room
    w, h = text_box_size("x", 3)
    assert type(h) is float and w == 1.8


def test_runs_read_the_marks_and_the_unicode_scripts_alike() -> None:
    assert runs("J_{F}") == runs("J_{F}") == (("J", 0), ("F", -1))
    assert runs("φ₁₂") == runs("φ_{12}") == (("φ", 0), ("12", -1))
    assert runs("m/s²") == (("m/s", 0), ("2", 1))
    assert runs("a_b x^y _{}") == (("a_b x^y _{}", 0),)  # no braces, or empty: as typed
    assert plain("M_{b}′") == "Mb′"


def test_number_has_four_significant_figures_and_a_true_minus() -> None:
    assert number(26.3843297494) == "26.38"
    assert number(-0.5) == "−0.5" and "-" not in number(-1e-9)
    assert number(0.00872665) == "0.008727"
    assert number(-0.0) == "0"
    assert number(123456.7) == "123500" and number(999999.0) == "1×10^{6}"
    assert number(100.0) == "100" and number(0.0001) == "0.0001"
    assert number(1e-7) == "1×10^{−7}"
    with pytest.raises(ValueError):
        number(float("nan"))


def test_minus_sets_signs_but_keeps_hyphens_in_words() -> None:
    assert minus("φ = -30°, four-bar, x-3") == "φ = −30°, four-bar, x-3"
