"""Line weights, colours, dashes, arrowheads and lettering of a textbook figure.

Every size is paper millimetres: a style never depends on a panel's scale μ. A backend looks a
pen up by its *style key*; the keys are the four roles of :mod:`graphmech.drawing.primitives`
(``given``, ``construction``, ``result``, ``label``) and the symbol pens the frontend uses
(``frame`` for pivot triangles and guides, ``hatch`` for ground hatching, ``hinge`` for the
white-filled joint circles, ``slider`` for the white-filled slider blocks, ``text`` for titles
and notes).

Examples
--------
>>> DEFAULT.pen("given").width
0.7
>>> DEFAULT.pen("construction").colour
'#555555'
>>> DEFAULT.pen("hinge").fill
'white'
"""
from __future__ import annotations

from dataclasses import dataclass, field

from graphmech.drawing.lettering import LETTER

#: The style keys a backend must understand.
STYLE_KEYS: tuple[str, ...] = (
    "given",
    "construction",
    "result",
    "label",
    "frame",
    "hatch",
    "hinge",
    "slider",
    "text",
    "plate",
)


#: The serif faces of the book, then fallbacks that carry what the first lack: Greek and
#: Cyrillic (DejaVu Serif, STIX Two), Chinese (Noto Serif CJK SC — Debian's fonts-noto-cjk —,
#: then SimSun on Windows).
FONT_FAMILY = ("'Times New Roman', Times, 'Liberation Serif', 'DejaVu Serif', 'STIX Two Text', "
               "'Noto Serif CJK SC', 'Noto Serif SC', SimSun, serif")


@dataclass(frozen=True)
class Pen:
    """How one kind of stroke (and its fill, when a shape is filled) is drawn.

    Parameters
    ----------
    width : float
        Stroke width, mm.
    colour : str
        Stroke colour (also the text colour for text keys).
    fill : str
        Fill used when a shape of this key is drawn ``filled`` (arrowheads take the stroke
        colour, hinges and slider blocks are white so they cover the lines beneath).
    dash : tuple of float
        Dash pattern, mm, used when a line of this key is drawn ``dashed``.
    """

    width: float
    colour: str = "black"
    fill: str = "black"
    dash: tuple[float, ...] = (3.0, 1.5)


@dataclass(frozen=True)
class Style:
    """The whole look of a sheet; :data:`DEFAULT` is the textbook's.

    Parameters
    ----------
    given, construction, result, label, frame, hatch, hinge, slider, text, plate : Pen
        The pens, by style key (``plate`` outlines and fills a ternary link's triangle).
    dashdot : tuple of float
        The pattern of centre lines, mm (on, off, on, off).
    arrow_length, arrow_half_width : float
        Arrowhead length along the vector and half its base width, mm.
    hinge_r : float
        Radius of a frame pivot's hinge circle, mm (a :class:`Hinge` carries its own).
    pivot_height, pivot_half_base, pivot_ground_half : float
        Frame pivot: triangle height and half base, half length of its ground line, mm.
    hatch_spacing, hatch_length : float
        Distance between ground hatch strokes along the ground line and a stroke's length, mm.
    font_family : str
        Font family list for every text (a serif, like the book).
    label_size, title_size, panel_title_size, note_size : float
        Font sizes, mm (labels carry their own size; ``label_size`` is the default margin).
    line_gap : float
        Baseline distance of stacked text lines as a multiple of the font size.
    label_gaps : tuple of float
        Free distance between a label's anchor and its text box for the candidate rings, mm.
    label_clearance : float
        Minimum free distance kept between two label boxes, mm.
    page_margin, panel_gap, panel_padding : float
        Page margin, gap between panels, free band around a panel's drawing, mm.
    """

    given: Pen = field(default_factory=lambda: Pen(0.7, "black", "black", (4.0, 1.5)))
    construction: Pen = field(default_factory=lambda: Pen(0.18, "#555555", "#555555", (2.5, 1.2)))
    result: Pen = field(default_factory=lambda: Pen(0.6, "black", "black", (4.0, 1.5)))
    label: Pen = field(default_factory=lambda: Pen(0.25, "black", "black"))
    frame: Pen = field(default_factory=lambda: Pen(0.45, "black", "white"))
    hatch: Pen = field(default_factory=lambda: Pen(0.25, "black", "black"))
    hinge: Pen = field(default_factory=lambda: Pen(0.4, "black", "white"))
    slider: Pen = field(default_factory=lambda: Pen(0.5, "black", "white"))
    text: Pen = field(default_factory=lambda: Pen(0.0, "black", "black"))
    plate: Pen = field(default_factory=lambda: Pen(0.7, "black", "#e4e4e4"))
    #: The dash-dot of a centre line: long dash, gap, dot, gap (mm).
    dashdot: tuple[float, ...] = (8.0, 1.5, 0.8, 1.5)

    arrow_length: float = 2.8
    arrow_half_width: float = 0.8
    hinge_r: float = 1.2
    pivot_height: float = 4.0
    pivot_half_base: float = 2.6
    pivot_ground_half: float = 4.8
    hatch_spacing: float = 1.4
    hatch_length: float = 1.8

    font_family: str = FONT_FAMILY
    label_size: float = LETTER
    title_size: float = 5.0
    panel_title_size: float = LETTER
    note_size: float = LETTER
    line_gap: float = 1.4  # 1.35 let a subscript touch the next line's superscript

    label_gaps: tuple[float, ...] = (2.0, 4.5)
    label_clearance: float = 0.6

    page_margin: float = 10.0
    panel_gap: float = 12.0
    panel_padding: float = 1.0

    def pen(self, key: str) -> Pen:
        """The pen of a style key.

        Raises
        ------
        KeyError
            For a key that is not one of :data:`STYLE_KEYS`.
        """
        if key not in STYLE_KEYS:
            raise KeyError(f"unknown style key {key!r}; expected one of {', '.join(STYLE_KEYS)}")
        pen: Pen = getattr(self, key)
        return pen


#: The textbook's style: links 0.7 mm, construction 0.18 mm grey, results 0.6 mm, serif italics.
DEFAULT = Style()
