"""The SVG backend — the only module of graphmech that knows how SVG is written.

The document is built with the standard library's :mod:`xml.etree.ElementTree` and serialised in
the form svgwrite gave it (svgwrite serialised through ElementTree too): attributes sorted by
name, empty ones left out, the root's ``xmlns``, ``baseProfile`` and ``version``, the ``<title>``
and an empty ``<defs />`` first — so figures are byte-identical to the ones svgwrite wrote, and a
render no longer imports svgwrite (about 36 ms of import: urllib, http.client and its pyparsing
validator, even with validation off).

Output is byte-stable: numbers are formatted here with three decimals (never ``-0.000``), every
id is explicit and starts with the caller's ``id_prefix`` (a short hash of the scene, so two
figures inline on one HTML page do not clash), and nothing depends on time or chance.

Scene text (titles, labels, notes) goes only into text nodes — and the document's ``<title>``
— with the characters XML 1.0 forbids removed; ElementTree escapes ``&``, ``<`` and ``>`` (and
quotes in attributes). No ``<style>``, ``<script>`` or event attribute is ever written;
presentation is given by fixed attributes taken from the :class:`~graphmech.render.style.Style`.

Examples
--------
>>> b = SvgBackend("gm1")
>>> b.begin(297.0, 210.0, "A & B")
>>> b.line((0.0, 0.0), (10.0, -0.0001), "given")
>>> svg = b.finish()
>>> 'x1="0.000" x2="10.000" y1="0.000" y2="0.000"' in svg      # never -0.000
True
>>> '<title>A &amp; B</title>' in svg
True
"""
from __future__ import annotations

import hashlib
import math
import re
from collections.abc import Callable, Sequence
from xml.etree.ElementTree import Element, SubElement, tostring

from graphmech.drawing.lettering import SCRIPT_SCALE, SUB_SHIFT, SUP_SHIFT, runs
from graphmech.drawing.primitives import Sheet
from graphmech.render.backend import Anchor, PagePoint
from graphmech.render.sheet import draw_sheet
from graphmech.render.style import DEFAULT, Style

# What clean_text removes: the characters XML 1.0 forbids, spelt as ranges (the complement of
# its Char production, which as a negated class with an astral range took 5 ms to compile at
# every start), and the bidirectional overrides.
_UNWANTED = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff\u202a-\u202e\u2066-\u2069]")
_PREFIX = re.compile(r"^[A-Za-z_][A-Za-z0-9_.-]*$")


def fmt(x: float) -> str:
    """A number with three decimals, ``-0.000`` written ``0.000``.

    >>> fmt(-0.0004), fmt(2.5), fmt(-1.23456)
    ('0.000', '2.500', '-1.235')
    """
    if not math.isfinite(x):
        raise ValueError(f"cannot write a non-finite number to SVG: {x!r}")
    s = f"{x:.3f}"
    return "0.000" if s == "-0.000" else s


def _short(x: float) -> str:
    """A page dimension without trailing zeros: 297.0 → '297', 297.5 → '297.5'."""
    return fmt(x).rstrip("0").rstrip(".")


def clean_text(s: str) -> str:
    """``s`` without the characters XML 1.0 forbids (control characters other than tab, LF
    and CR; U+FFFE, U+FFFF; lone surrogates), nor the bidirectional overrides that would make
    a title read differently from what it says (U+202A–202E, U+2066–2069).

    >>> clean_text("a\\x00b\\x1bc\\td\\ufffe\\u202e")
    'abc\\td'
    """
    return _UNWANTED.sub("", s)


def _set_runs(el: Element, s: str, size: float) -> None:
    """Fill a text element with the runs of ``s`` (see :func:`graphmech.drawing.lettering.runs`):
    a sub- or superscript is a ``tspan`` of its own size whose baseline is moved by ``dy``, and
    the next run on the line moves it back. ``dy`` rather than ``baseline-shift``, which Firefox
    and CairoSVG do not honour."""
    level_at = 0.0
    for k, (text, level) in enumerate(runs(s)):
        shift = {0: 0.0, -1: SUB_SHIFT, 1: SUP_SHIFT}[level] * size
        if k == 0 and level == 0:
            el.text = text
            continue
        span = SubElement(el, "tspan")
        span.text = text
        if shift != level_at:
            span.set("dy", fmt(level_at - shift))  # SVG's dy is down; the shifts are up
        if level:
            span.set("font-size", fmt(SCRIPT_SCALE * size))
        level_at = shift


def sheet_id_prefix(sheet: Sheet) -> str:
    """A short id prefix derived from the sheet's content: ``"gm"`` + 8 hex digits."""
    return "gm" + hashlib.sha256(repr(sheet).encode("utf-8")).hexdigest()[:8]


class SvgBackend:
    """Draws into an SVG document; :meth:`finish` returns it as a ``str``.

    Parameters
    ----------
    id_prefix : str
        Start of every id in the document; an XML name (a letter or ``_`` first, then
        letters, digits, ``_ . -``). A hex hash should be given a letter first (``"gm3fa2…"``).
    style : Style
        Pens and fonts by style key.

    Notes
    -----
    A *filled* shape whose pen fills with its stroke colour (an arrowhead) is drawn without a
    stroke, so its tip stays exactly where it is put (a stroked acute tip would overshoot by
    a miter). A shape whose fill differs (a white hinge, a slider block) keeps its stroke.
    """

    def __init__(self, id_prefix: str, style: Style = DEFAULT) -> None:
        if not _PREFIX.match(id_prefix):
            raise ValueError(
                f"id_prefix must be an XML name (letter or '_' first, then letters, digits, "
                f"'_', '.', '-'), got {id_prefix!r}"
            )
        self.id_prefix = id_prefix
        self.style = style
        self._root: Element | None = None
        self._stack: list[Element] = []
        self._ids: set[str] = set()

    # --------------------------------------------------------------- helpers
    def _id(self, name: str) -> str:
        clean = re.sub(r"[^A-Za-z0-9_-]+", "-", name).strip("-")
        base = f"{self.id_prefix}-{clean}" if clean else f"{self.id_prefix}-g"
        ident, k = base, 1
        while ident in self._ids:
            k += 1
            ident = f"{base}-{k}"
        self._ids.add(ident)
        return ident

    def _add(self, tag: str, **attrs: str) -> Element:
        """A new element ``tag`` in the open group (attributes sorted when written)."""
        if not self._stack:
            raise RuntimeError("SvgBackend: begin() must come first")
        return SubElement(self._stack[-1], tag, attrs)

    def _stroke(self, element: Element, key: str, dashed: bool = False) -> Element:
        pen = self.style.pen(key)
        element.set("stroke", pen.colour)
        element.set("stroke-width", fmt(pen.width))
        element.set("stroke-linecap", "round")
        if dashed:
            element.set("stroke-dasharray", " ".join(fmt(d) for d in pen.dash))
        return element

    @staticmethod
    def _pt(p: PagePoint) -> tuple[str, str]:
        return (fmt(p[0]), fmt(p[1]))

    # --------------------------------------------------------------- Backend
    def begin(self, page_w: float, page_h: float, title: str = "") -> None:
        if self._root is not None:
            raise RuntimeError("SvgBackend: begin() called twice")
        w, h = _short(page_w), _short(page_h)
        root = Element("svg", {
            "xmlns": "http://www.w3.org/2000/svg",
            "xmlns:xlink": "http://www.w3.org/1999/xlink",
            "xmlns:ev": "http://www.w3.org/2001/xml-events",
            "baseProfile": "full", "version": "1.1",
            "width": f"{w}mm", "height": f"{h}mm", "viewBox": f"0 0 {w} {h}",
            "id": self._id("svg"),
        })
        SubElement(root, "title").text = clean_text(title)
        SubElement(root, "defs")  # empty, as svgwrite always wrote it: figures stay byte-identical
        self._root = root
        self._stack = [root]

    def begin_group(self, name: str) -> None:
        if self._root is None:
            raise RuntimeError("SvgBackend: begin() must come first")
        self._stack.append(self._add("g", id=self._id(name)))

    def end_group(self) -> None:
        if len(self._stack) < 2:
            raise RuntimeError("SvgBackend: end_group() without an open group")
        self._stack.pop()

    def line(self, p0: PagePoint, p1: PagePoint, style_key: str, dashed: bool = False) -> None:
        (x1, y1), (x2, y2) = self._pt(p0), self._pt(p1)
        self._stroke(self._add("line", x1=x1, y1=y1, x2=x2, y2=y2), style_key, dashed)

    def polyline(
        self,
        points: Sequence[PagePoint],
        style_key: str,
        closed: bool = False,
        filled: bool = False,
    ) -> None:
        pts = " ".join(",".join(self._pt(p)) for p in points)
        el = self._add("polygon" if closed else "polyline", points=pts)
        pen = self.style.pen(style_key)
        if filled and pen.fill == pen.colour:
            el.set("fill", pen.fill)
            el.set("stroke", "none")
        else:
            el.set("fill", pen.fill if filled else "none")
            self._stroke(el, style_key)
            el.set("stroke-linejoin", "round")

    def circle(self, c: PagePoint, r: float, style_key: str, filled: bool = False) -> None:
        cx, cy = self._pt(c)
        el = self._add("circle", cx=cx, cy=cy, r=fmt(r))
        el.set("fill", self.style.pen(style_key).fill if filled else "none")
        self._stroke(el, style_key)

    def text(
        self,
        s: str,
        at: PagePoint,
        size: float,
        anchor: Anchor = "start",
        italic: bool = False,
        style_key: str = "text",
    ) -> None:
        if self._root is None:
            raise RuntimeError("SvgBackend: begin() must come first")
        if anchor not in ("start", "middle", "end"):
            raise ValueError(f"text anchor must be start, middle or end, got {anchor!r}")
        x, y = self._pt(at)
        el = self._add("text", x=x, y=y)
        _set_runs(el, clean_text(s), size)
        el.set("font-family", self.style.font_family)
        el.set("font-size", fmt(size))
        el.set("fill", self.style.pen(style_key).colour)
        if anchor != "start":
            el.set("text-anchor", anchor)
        if italic:
            el.set("font-style", "italic")

    def finish(self) -> str:
        if self._root is None:
            raise RuntimeError("SvgBackend: begin() must come first")
        if len(self._stack) != 1:
            raise RuntimeError(f"SvgBackend: {len(self._stack) - 1} group(s) left open")
        for el in self._root.iter():
            # svgwrite's form: attributes by name, an empty value left out
            el.attrib = {k: v for k, v in sorted(el.attrib.items()) if v}
        out = tostring(self._root, encoding="unicode")
        self._stack = []
        return out


def render_svg(
    sheet: Sheet,
    id_prefix: str,
    style: Style = DEFAULT,
    on_warning: Callable[[str], None] | None = None,
) -> str:
    """The sheet as an SVG document (a ``str``, byte-identical for the same input).

    ``on_warning`` receives layout warnings (see :func:`graphmech.render.sheet.draw_sheet`).
    """
    return draw_sheet(sheet, SvgBackend(id_prefix, style), style, on_warning)
