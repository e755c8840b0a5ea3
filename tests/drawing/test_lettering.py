"""Lettering: subscript digits, and the room a line of text takes."""
from __future__ import annotations

import pytest

from graphmech.drawing.lettering import minus, number, plain, runs, subscript, text_box_size, text_extent


def test_subscript_turns_every_digit_and_nothing_else() -> None:
    assert subscript("0123456789") == "₀₁₂₃₄₅₆₇₈₉"
    assert "φ" + subscript("1") == "φ₁"
    assert subscript("O12'") == "O₁₂'"
    assert subscript("") == ""


def test_text_box_size_counts_each_character_from_above() -> None:
    assert text_box_size("ω₂", 5.0) == (6.16, 5.0)  # ω 0.8 em, the subscript 0.6 em at 0.72 size
    assert text_box_size("速度", 5.0) == (10.0, 5.0)  # a CJK character is a full em
    assert text_box_size("0.1", 2.8) == (4.62, 2.8)  # digits 0.6, the point 0.45; rounded
    assert text_box_size("", 4.0) == (2.4, 4.0)  # an empty label still takes a character's room
    w, h = text_box_size("x", 3)
    assert type(h) is float and w == 1.8


#: Widths (em) of single characters as Chromium's getBBox() gave them for this project's font
#: list (Liberation Serif, fallbacks for the rest), the larger of upright and italic.
MEASURED_EM = {"M": 0.93, "W": 0.95, "H": 0.79, "D": 0.75, "B": 0.67, "S": 0.56, "I": 0.42,
               "m": 0.78, "w": 0.74, "p": 0.58, "i": 0.28, "j": 0.41, "7": 0.56, "ω": 0.71,
               "ψ": 0.64, "φ": 0.58, "Π": 0.82, "Φ": 0.76, "Ш": 1.14, "Ж": 0.98, "т": 0.72,
               "′": 0.24, "=": 0.67, "−": 0.67, "(": 0.40, "°": 0.40, " ": 0.25}


def test_text_extent_holds_what_the_browser_draws() -> None:
    for ch, em in MEASURED_EM.items():
        assert text_extent(ch, 10.0, italic=True)[0] >= 10.0 * em, ch
    assert text_extent("速", 10.0, italic=True)[0] >= 11.6  # a slanted CJK box is wider
    # the font's cell: ascent 0.891, descent 0.216 (brackets 0.238); scripts reach further
    assert text_extent("B", 10.0) == (7.0, 9.0, 2.4)
    w, up, down = text_extent("R^{n}_{34}", 10.0)
    assert up >= 10.15 and down >= 4.09  # Chromium: 1.015 and 0.409 em
    assert text_extent("x_{2}", 10.0)[1:] == (9.0, 4.228)


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


def test_a_point_name_gets_its_digits_as_a_subscript_and_its_apostrophes_as_primes() -> None:
    from graphmech.drawing.lettering import point_name

    assert [point_name(n) for n in ("S2", "K12", "C'", "c2''", "B", "E2F")] == [
        "S_{2}", "K_{12}", "C′", "c_{2}′′", "B", "E2F"]
    assert plain(point_name("S2")) == "S2" and runs(point_name("S2")) == (("S", 0), ("2", -1))


def test_scale_text_states_every_scale_with_its_subscripted_symbol_and_four_figures() -> None:
    import math

    from graphmech.drawing.lettering import scale_symbol, scale_text
    from graphmech.scales import SCALE_INFO

    for key in SCALE_INFO:
        text = scale_text(key, 0.0123456)
        assert text.startswith(scale_symbol(key) + " = ") and "_" not in plain(text)
    assert scale_text("phi", math.radians(4.0)) == "μ_{φ} = 4 °/mm"
    assert scale_text("l", 0.0123456) == "μ_{l} = 0.01235 m/mm"


def test_text_extent_remembered_is_what_it_measures() -> None:
    """Every label candidate asks for its box again: a float size is answered from a cache, the
    same numbers (and types) as measuring afresh; any other size is measured each time."""
    import numpy as np

    from graphmech.drawing.lettering import _measure, _text_extent

    for text, size, italic in (("B", 10.0, False), ("ω_{2}", 3.5, True), ("p (c₃, d₃)", 2.5, False)):
        got = text_extent(text, size, italic)
        assert got == text_extent(text, size, italic) == _measure(text, size, italic)
        assert all(type(v) is float for v in got)
    assert _text_extent.cache_info().currsize >= 3
    wide = text_extent("B", np.float64(10.0))
    assert wide == (7.0, 9.0, 2.4) and type(wide[0]) is np.float64  # not the cached floats
