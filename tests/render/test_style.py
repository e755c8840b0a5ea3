"""The textbook's style: a pen per style key, and only for a style key."""
from __future__ import annotations

import pytest

from graphmech.render.style import DEFAULT, STYLE_KEYS, Pen, Style


def test_every_style_key_has_its_own_pen() -> None:
    pens = {key: DEFAULT.pen(key) for key in STYLE_KEYS}
    assert all(isinstance(p, Pen) for p in pens.values())
    assert pens == {key: getattr(DEFAULT, key) for key in STYLE_KEYS}
    assert set(STYLE_KEYS) == {"given", "construction", "result", "label", "frame", "hatch", "hinge", "slider", "text", "plate"}


def test_the_books_line_weights() -> None:
    w = {key: DEFAULT.pen(key).width for key in ("given", "result", "construction")}
    assert w == {"given": 0.7, "result": 0.6, "construction": 0.18}  # links, results, thin construction
    assert DEFAULT.pen("construction").colour == "#555555" and DEFAULT.pen("construction").dash == (2.5, 1.2)
    # joints, slider blocks and pivot triangles are white inside: they cover the lines beneath
    assert [DEFAULT.pen(k).fill for k in ("hinge", "slider", "frame")] == ["white"] * 3
    assert DEFAULT.pen("result").fill == "black"  # arrowheads take the stroke's colour


def test_a_pen_can_be_changed_in_a_style_of_ones_own() -> None:
    red = Pen(1.0, "red")
    style = Style(given=red, arrow_length=4.0)
    assert style.pen("given") is red and (red.fill, red.dash) == ("black", (3.0, 1.5))
    assert style.pen("result") == DEFAULT.pen("result") and style.arrow_length == 4.0
    assert Style() == DEFAULT


@pytest.mark.parametrize("key", ["bold", "arrow_length", "pen", "font_family", "Given", ""])
def test_a_name_that_is_not_a_style_key_is_refused(key: str) -> None:
    with pytest.raises(KeyError, match="unknown style key"):
        DEFAULT.pen(key)
