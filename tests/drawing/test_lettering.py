"""Lettering: subscript digits, and the room a line of text takes."""
from __future__ import annotations

from graphmech.drawing.lettering import subscript, text_box_size


def test_subscript_turns_every_digit_and_nothing_else() -> None:
    assert subscript("0123456789") == "₀₁₂₃₄₅₆₇₈₉"
    assert "φ" + subscript("1") == "φ₁"
    assert subscript("O12'") == "O₁₂'"
    assert subscript("") == ""


def test_text_box_size_is_three_fifths_of_the_size_per_character() -> None:
    assert text_box_size("ω₂", 5.0) == (6.0, 5.0)
    assert text_box_size("0.1", 2.8) == (5.04, 2.8)  # rounded: no 5.040000000000001
    assert text_box_size("", 4.0) == (2.4, 4.0)  # an empty label still takes a character's room
    w, h = text_box_size("x", 3)
    assert type(h) is float and w == 1.8
