"""Lettering as the figures set it: sub- and superscripts, numbers, and the room a line of text
takes — which a figure needs before anything is drawn (the numbers along an axis must not
collide), and the renderer's label placer uses too.

Markup of drawn text
--------------------
A figure composes its text with two marks the renderer turns into raised or lowered, smaller
letters (an SVG ``tspan``): ``_{…}`` a subscript, ``^{…}`` a superscript (``"M_{b}"``,
``"J_{F}"``, ``"r_{r}"``). The Unicode subscript and superscript characters (``φ₂``, ``m/s²``)
are read as the same marks, because the serif fonts lack most of them (Liberation Serif has no
₀–₉; a renderer without a fallback draws boxes). A ``_`` or ``^`` not followed by ``{`` is an
ordinary character, so scene text such as a title ``"a_b"`` is drawn as typed.

>>> runs("M_{b}′ = 12")
(('M', 0), ('b', -1), ('′ = 12', 0))
>>> runs("ω₂ m/s²")
(('ω', 0), ('2', -1), (' m/s', 0), ('2', 1))
>>> plain("φ_{2} = " + number(-26.3843297494) + "°")
'φ2 = −26.38°'
"""
from __future__ import annotations

import functools
import math
import re
import unicodedata

from graphmech.scales import ANGLE_SCALES, SCALE_INFO

_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")

#: Unicode sub- and superscript characters and the ordinary characters they stand for.
_SUB_CHARS = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₒₓₕₖₗₘₙₚₛₜᵢᵣᵤᵥ", "0123456789+−=()aeoxhklmnpstiruv"))
_SUP_CHARS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱ", "0123456789+−=()ni"))

#: The body text of every drawing at 1:1, mm (FIGURES.md: 3.5 mm letters; scripts at
#: SCRIPT_SCALE of it, 2.5 mm): labels, captions, numbers along axes.
LETTER = 3.5

#: A line's baseline below the middle of its box, as a fraction of its size: where to write a
#: text that is to stand centred on a point (a label, a table's cell, a scale bar's number).
BASELINE_DROP = 0.35

#: The true minus sign, which drawings use instead of the hyphen.
MINUS = "\u2212"

#: A sub- or superscript's size as a fraction of its line's, and how far its baseline moves
#: (fraction of the line's size, + up): a subscript of 3.5 mm text is 2.5 mm high.
SCRIPT_SCALE = 0.72
SUB_SHIFT = -0.25
SUP_SHIFT = 0.38

Run = tuple[str, int]


def subscript(digits: str) -> str:
    """Digits as the book sets them after a symbol: ``"φ" + subscript("1")`` → ``φ₁``.

    >>> subscript("c2")
    'c₂'
    """
    return digits.translate(_SUBSCRIPT)


def point_name(name: str) -> str:
    """A point's name as a drawing letters it: the digits after its letters a subscript, an
    apostrophe a prime (the scene writes ``S2``, ``K1``, ``C'``); any other name as written.

    >>> point_name("S2"), point_name("K1'"), point_name("B"), point_name("12"), point_name("hK")
    ('S_{2}', 'K_{1}′', 'B', '12', 'hK')
    """
    m = re.fullmatch(r"([^\W\d_]+?)(\d+)(['′]*)", name)
    if m is None:
        return name.replace("'", "′")
    return f"{m[1]}_{{{m[2]}}}{m[3].replace(chr(39), '′')}"


def runs(text: str) -> tuple[Run, ...]:
    """``text`` cut into runs of the same level: 0 on the line, −1 subscript, +1 superscript.

    >>> runs("a_b ^{2}"), runs("x_{")
    ((('a_b ', 0), ('2', 1)), (('x_{', 0),))
    """
    out: list[list[object]] = []

    def put(ch: str, level: int) -> None:
        if out and out[-1][1] == level:
            out[-1][0] = str(out[-1][0]) + ch
        else:
            out.append([ch, level])

    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch in "_^" and i + 1 < n and text[i + 1] == "{":
            end = text.find("}", i + 2)
            if end > i + 2:
                for c in text[i + 2:end]:
                    put(c, -1 if ch == "_" else 1)
                i = end + 1
                continue
        if ch in _SUB_CHARS:
            put(_SUB_CHARS[ch], -1)
        elif ch in _SUP_CHARS:
            put(_SUP_CHARS[ch], 1)
        else:
            put(ch, 0)
        i += 1
    return tuple((str(t), int(str(lv))) for t, lv in out)


def plain(text: str) -> str:
    """The characters of ``text`` without its marks (what a reader of the drawing reads).

    >>> plain("J_{F} = 1.2 kg·m²")
    'JF = 1.2 kg·m2'
    """
    return "".join(t for t, _ in runs(text))


def number(x: float, sig: int = 4) -> str:
    """``x`` as a drawing writes it: ``sig`` significant figures, no trailing zeros, a true
    minus, and a power of ten as ×10 with a superscript outside 10⁻⁴ … 10⁶.

    >>> number(26.3843297494), number(-0.00872665), number(2.5), number(12346.0), number(1234567.0)
    ('26.38', '−0.008727', '2.5', '12350', '1.235×10^{6}')
    """
    if not math.isfinite(x):
        raise ValueError(f"cannot letter a non-finite number: {x!r}")
    s = f"{x:.{sig}g}"
    if 1e-4 <= abs(float(s)) < 1e6:  # fixed point: 12346 N is written 12350, not 1.235×10⁴
        places = max(sig - 1 - math.floor(math.log10(abs(float(s)))), 0)
        s = f"{float(s):.{places}f}"
        s = s.rstrip("0").rstrip(".") if "." in s else s
    elif "e" in s:
        mant, _, exp = s.partition("e")
        s = f"{mant}×10^{{{int(exp)}}}"
    if s in ("-0", "0"):
        return "0"
    return s.replace("-", MINUS)


def minus(text: str) -> str:
    """A composed line with its hyphen-minus signs set as true minus signs (a hyphen between
    two letters, as in "four-bar", stays).

    >>> minus("x = -3, a-b, -0.5 mm, ω = -2")
    'x = −3, a-b, −0.5 mm, ω = −2'
    """
    out = []
    for i, ch in enumerate(text):
        if ch == "-" and i + 1 < len(text) and (text[i + 1].isdigit() or text[i + 1] == "."):
            prev = text[i - 1] if i else " "
            if not prev.isalnum():
                out.append(MINUS)
                continue
        out.append(ch)
    return "".join(out)


#: Advance widths (em) rounded up into classes, so a box holds what a browser draws: the
#: larger of the upright and italic widths of Liberation Serif (metric-compatible with Times
#: New Roman, the SVG's first face) and of the fallbacks Chromium takes for what it lacks,
#: as measured there (M 0.93, W 0.95, B 0.67, i 0.28, ω 0.71, Ш 1.14; a CJK character is
#: 1.0 upright but 1.16 slanted, the browser's synthetic italic widening its box).
#: Characters in none of the classes: 0.6 (lower case, digits, most Greek); upper case: 0.8.
_EM_CLASSES = (
    (0.45, "Iijlrtfsz′″·.,:;()/°- ιτγενξ"),
    (0.7, "BEFLPSTZΓΔΞΣБВГЕЗРЬЭ"),
    (0.8, "mwψω∞=−+×мтфшщюы"),
    (0.85, "ΠИЙП"),
    (1.0, "MW%ЖЫж"),
    (1.15, "ШЩЮ"),
)
_EM = {c: w for w, chars in _EM_CLASSES for c in chars}

#: A line's ascent and descent below its baseline (em) as a browser's text box has them —
#: the font's whole cell (Liberation Serif 0.891 and 0.216; brackets 0.9 and 0.238) — and how
#: far a superscript raises the top and a subscript lowers the bottom, each set at
#: SCRIPT_SCALE with its baseline moved by SUP_SHIFT or SUB_SHIFT (see :func:`runs`).
ASCENT = 0.9
DESCENT = 0.24
SUP_ASCENT = SUP_SHIFT + ASCENT * SCRIPT_SCALE
SUB_DESCENT = -SUB_SHIFT + DESCENT * SCRIPT_SCALE


def _em(ch: str, italic: bool = False) -> float:
    """Width of one character in ems, from above (:data:`_EM_CLASSES`)."""
    if unicodedata.east_asian_width(ch) in ("W", "F"):
        return 1.2 if italic else 1.0
    return _EM.get(ch, 0.8 if ch.isupper() else 0.6)


def text_extent(text: str, size: float, italic: bool = False) -> tuple[float, float, float]:
    """Width, ascent and descent (mm) of a line of text at font size ``size`` mm, from above:
    the box a browser's ``getBBox()`` gives the line lies inside ``width`` × (ascent above the
    baseline + descent below it), a superscript raising the top and a subscript lowering the
    bottom.

    >>> text_extent("B", 10.0), text_extent("ω_{2}", 10.0, italic=True)
    ((7.0, 9.0, 2.4), (12.32, 9.0, 4.228))
    """
    if type(size) is float and size > 0.0 and type(italic) is bool:  # the usual call, asked again and again
        return _text_extent(text, size, italic)
    return _measure(text, size, italic)


@functools.lru_cache(maxsize=4096)
def _text_extent(text: str, size: float, italic: bool) -> tuple[float, float, float]:
    return _measure(text, size, italic)


def _measure(text: str, size: float, italic: bool) -> tuple[float, float, float]:
    width = 0.0
    levels = set()
    for t, level in runs(text):
        scale = 1.0 if level == 0 else SCRIPT_SCALE
        width += sum(_em(c, italic) for c in t) * scale
        levels.add(level)
    ascent = max(ASCENT, SUP_ASCENT if 1 in levels else 0.0)
    descent = max(DESCENT, SUB_DESCENT if -1 in levels else 0.0)
    return (round(size * max(width, 0.6), 12), round(size * ascent, 12), round(size * descent, 12))


def text_box_size(text: str, size: float) -> tuple[float, float]:
    """Width (from above, see :func:`text_extent`) and height (the font size) of a line of
    upright text at font size ``size`` mm: the room layouts leave for it.

    >>> text_box_size("ab", 3.5), text_box_size("ω_{2}", 5.0)
    ((4.2, 3.5), (6.16, 5.0))
    """
    return (text_extent(text, size)[0], float(size))


def scale_text(symbol: str, value: float, prime: str = "") -> str:
    """A scale as a drawing states it — the one way every figure writes its μ: μ with its
    subscript, the value to four significant figures, the unit of
    :data:`graphmech.scales.SCALE_INFO` (an angle per mm in degrees, as scenes give it);
    ``prime`` marks a second scale of the same quantity (μ_{φ}′). ``check`` keeps full precision.

    >>> scale_text("phi", math.radians(2.5)), scale_text("T", 12.21730476), scale_text("omega", 2e-6, "′")
    ('μ_{φ} = 2.5 °/mm', 'μ_{T} = 12.22 J/mm', 'μ_{ω}′ = 2×10^{−6} (rad/s)/mm')
    >>> scale_text("psi", math.radians(0.5)), scale_text("F", 25.0)
    ('μ_{ψ} = 0.5 °/mm', 'μ_{F} = 25 N/mm')
    """
    shown = math.degrees(value) if symbol in ANGLE_SCALES else value
    return f"{scale_symbol(symbol)}{prime} = {number(shown)} {SCALE_INFO[symbol][1]}"


def scale_symbol(symbol: str) -> str:
    """μ with the scale's letter as its subscript, as drawings write it.

    >>> scale_symbol("l"), scale_symbol("phi")
    ('μ_{l}', 'μ_{φ}')
    """
    return f"μ_{{{SCALE_INFO[symbol][0][1:]}}}"
