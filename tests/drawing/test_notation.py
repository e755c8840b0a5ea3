"""The drawing's words in English, Chinese and Russian."""
from __future__ import annotations

import pytest

from graphmech.drawing.lettering import runs
from graphmech.drawing.notation import WORDS, word


def test_every_word_is_given_in_all_three_notations() -> None:
    for key, (en, zh, ru) in WORDS.items():
        assert en and zh and ru, key
        assert "_" not in "".join(t for t, _ in runs(en + zh + ru)), key  # marks only, no ASCII _


def test_the_book_symbols_of_the_reduced_link() -> None:
    assert [word("J_red", n) for n in ("en", "zh", "ru")] == ["J_{red}", "J_{e}", "J_{п}"]
    assert word("force polygon", "zh") == "力多边形" and word("force polygon", "ru") == "план сил"


def test_an_unknown_key_or_notation_is_a_key_error() -> None:
    with pytest.raises(KeyError):
        word("no such caption")
    with pytest.raises(KeyError):
        word("force polygon", "de")
