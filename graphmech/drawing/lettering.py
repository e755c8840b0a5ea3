"""Lettering as the figures set it: subscript digits after a symbol (φ₁, ω₂), and the room a
line of text takes — which a figure needs before anything is drawn (the numbers along an axis
must not collide), and the renderer's label placer uses too.
"""
from __future__ import annotations


_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def subscript(digits: str) -> str:
    """Digits as the book sets them after a symbol: ``"φ" + subscript("1")`` → ``φ₁``.

    >>> subscript("c2")
    'c₂'
    """
    return digits.translate(_SUBSCRIPT)


def text_box_size(text: str, size: float) -> tuple[float, float]:
    """Estimated width and height (mm) of a line of text at font size ``size`` mm.

    >>> text_box_size("ab", 3.5)
    (4.2, 3.5)
    """
    return (round(0.6 * size * max(len(text), 1), 12), float(size))
