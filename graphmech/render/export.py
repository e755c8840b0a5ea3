"""A figure as SVG, PDF or PNG, the format chosen by the file's extension.

SVG is the drawing itself. PDF and PNG are printed from it by headless Chromium
(:mod:`graphmech.render.chromium`), the SVG opened as a browser opens it — so the text is the
same text with the same font fallback (a Chinese, Cyrillic or Greek label takes the first font of
the family list that has its glyphs), not outlines of one font:

* **PDF** (``Page.printToPDF``) at 1:1: the page is exactly the SVG root's width × height in mm,
  so every scale factor μ printed on the sheet stays true; the text is real text with the fonts
  embedded as subsets; one page. Chromium sizes a printed page in whole points (and 1/300 in),
  up to 0.2 mm off, so the page is printed a little larger, the drawing anchored at its top-left
  corner, and its ``/MediaBox`` then set to the exact size by an incremental update (the page's
  object appended anew; nothing Chromium wrote is changed).
* **PNG** (``Page.captureScreenshot``) at ``dpi`` (device scale factor dpi/96 over a viewport of
  the page's CSS px), on white: round(mm / 25.4 · dpi) pixels each way, with a ``pHYs`` chunk
  saying the dpi, so LaTeX, Word and image viewers place it at its true size.

Nothing is written unless the conversion succeeded (:func:`save` writes atomically).
"""
from __future__ import annotations

import base64
import json
import math
import re
import struct
import zlib
from pathlib import Path

from graphmech.errors import GraphmechError
from graphmech.files import write_atomic
from graphmech.render.chromium import (
    NOT_FOUND,
    Browser,
    BrowserError,
    Tab,
    find_chromium,
    root_size_mm,
)

FORMATS = ("svg", "pdf", "png")
DPI = 150.0  # the PNG's default resolution: sharp on screen and on a printed A4, ≈ 0.3 MB
MIN_DPI, MAX_DPI = 10.0, 2400.0
#: px: the longest side of a PNG (Chromium draws no larger texture; viewers struggle beyond it)
MAX_SIDE = 16384
#: px: the most pixels a PNG may have (an A4 sheet at 1200 dpi is 1.4e8)
MAX_PIXELS = 150_000_000

MM_PER_IN = 25.4
PT_PER_IN = 72.0
CSS_PX_PER_IN = 96.0
#: pt: the page Chromium prints on is asked this much larger than the drawing each way, so its
#: rounding (up to whole points, then to 1/300 in) never cuts the drawing or adds a second page
PAGE_SLACK_PT = 0.5

_WHITE = {"r": 255, "g": 255, "b": 255, "a": 1}
_MEDIABOX = re.compile(rb"/MediaBox\s*\[([^\]]*)\]")
# The page the figure is printed from: an HTML page holding the SVG inline, since Chromium prints
# an SVG document (or an SVG <img>) with its size snapped to whole CSS px — up to 0.04 % off.
_PAGE = ("data:text/html,<!doctype html><style>html,body{margin:0;padding:0}svg{display:block}</style>")
# The SVG parsed as the XML it is (so a broken one is refused, not shown as an error page), put
# in the page, its fonts awaited; the value is false when it does not parse.
_PLACE = """(function (text) {
  var doc = new DOMParser().parseFromString(text, 'image/svg+xml'), root = doc.documentElement;
  if (doc.querySelector('parsererror') || root.namespaceURI !== 'http://www.w3.org/2000/svg') return false;
  document.body.appendChild(document.importNode(root, true));
  return document.fonts.ready.then(function () { return true; });
})(%s)"""


def format_of(path: str | Path, fmt: str | None = None) -> str:
    """The format to write ``path`` in: its extension (any case), or ``fmt`` when given.

    A path without an extension is written in ``fmt`` (SVG when none is given, as it always was);
    an extension that is not one of :data:`FORMATS`, or one that disagrees with ``fmt``, is
    refused with a one-line :class:`GraphmechError`.

    >>> format_of("fig.PDF"), format_of("fig.png", "png"), format_of("fig"), format_of("fig", "png"), format_of(".png")
    ('pdf', 'png', 'svg', 'png', 'png')
    """
    name = Path(path).name
    wanted = None if fmt is None else fmt.lower()
    if wanted is not None and wanted not in FORMATS:
        raise GraphmechError(f"unknown format {fmt!r}: choose from {', '.join(FORMATS)}")
    # the text after the name's last dot, as a user reads it: ".png" is a PNG (pathlib sees no suffix)
    suffix = name.rpartition(".")[2].lower() if "." in name else ""
    if not suffix:
        return wanted or "svg"
    if suffix not in FORMATS:
        raise GraphmechError(f"{name}: unknown format .{suffix}: write .svg, .pdf or .png (or --format)")
    if wanted is not None and wanted != suffix:
        raise GraphmechError(f"{name}: the extension .{suffix} is not the format {wanted}: "
                             f"name the file .{wanted} or drop --format")
    return suffix


def check_dpi(dpi: float) -> float:
    """``dpi`` if it is a resolution a PNG can be printed at; else a one-line GraphmechError."""
    if not (math.isfinite(dpi) and MIN_DPI <= dpi <= MAX_DPI):
        raise GraphmechError(f"--dpi must be a number from {MIN_DPI:g} to {MAX_DPI:g} (dots per inch), not {dpi:g}")
    return dpi


def png_size(width_mm: float, height_mm: float, dpi: float) -> tuple[int, int]:
    """The PNG's pixels for a page of ``width_mm`` × ``height_mm`` at ``dpi``; refused (one line)
    beyond :data:`MAX_SIDE` or :data:`MAX_PIXELS`."""
    w, h = (max(1, round(v / MM_PER_IN * check_dpi(dpi))) for v in (width_mm, height_mm))
    if max(w, h) > MAX_SIDE or w * h > MAX_PIXELS:
        raise GraphmechError(f"a PNG of {w} × {h} px ({width_mm:g} × {height_mm:g} mm at {dpi:g} dpi) is too large: "
                             f"at most {MAX_SIDE} px a side and {MAX_PIXELS / 1e6:g} Mpx; lower --dpi")
    return w, h


def convert(svg_text: str, fmt: str, dpi: float = DPI, browser: Browser | None = None) -> bytes:
    """``svg_text`` as ``fmt`` (one of :data:`FORMATS`): the file's bytes. PDF and PNG are
    printed by ``browser`` (one is started and closed for this figure when None: pass one to
    convert many)."""
    if fmt == "svg":
        return svg_text.encode("utf-8")
    if fmt not in FORMATS:
        raise GraphmechError(f"unknown format {fmt!r}: choose from {', '.join(FORMATS)}")
    width, height = root_size_mm(svg_text)
    pixels = png_size(width, height, dpi) if fmt == "png" else (0, 0)  # refused before a browser starts
    if browser is None:
        with Browser() as own:
            return convert(svg_text, fmt, dpi, own)
    with browser.tab(_PAGE) as tab:
        if tab.evaluate(_PLACE % json.dumps(svg_text)) is not True:
            raise BrowserError("headless Chromium could not read the SVG (not well-formed XML)")
        if fmt == "pdf":
            return _pdf(tab.call("Page.printToPDF", {
                "paperWidth": (width / MM_PER_IN * PT_PER_IN + PAGE_SLACK_PT) / PT_PER_IN,
                "paperHeight": (height / MM_PER_IN * PT_PER_IN + PAGE_SLACK_PT) / PT_PER_IN,
                "marginTop": 0, "marginBottom": 0, "marginLeft": 0, "marginRight": 0,
                "printBackground": True, "scale": 1})["data"], width, height)
        return _png(tab, pixels, dpi)


def save(svg_text: str, path: str | Path, fmt: str | None = None, dpi: float = DPI,
         browser: Browser | None = None) -> str:
    """Write ``svg_text`` to ``path`` in the format its extension (or ``fmt``) names, atomically:
    nothing is written if the conversion fails. Returns the format written."""
    kind = format_of(path, fmt)
    write_atomic(path, convert(svg_text, kind, dpi, browser))
    return kind


def require_browser(fmt: str) -> None:
    """Refuse at once (one line) when ``fmt`` is printed by a browser and there is none — before
    anything is drawn."""
    if fmt != "svg" and find_chromium() is None:
        raise BrowserError(NOT_FOUND)


# ---------------------------------------------------------------------------- the two prints


def _pdf(data: str, width_mm: float, height_mm: float) -> bytes:
    """Chromium's PDF with its one page's /MediaBox set to ``width_mm`` × ``height_mm``, cut from
    the printed page's top-left corner (where the drawing is anchored)."""
    pdf = base64.b64decode(data)
    pages = re.findall(rb"/Type\s*/Pages\b[^>]*?/Count\s+(\d+)", pdf)
    if pages != [b"1"]:
        raise BrowserError(f"headless Chromium printed {b'+'.join(pages).decode() or 'no'} pages, not one")
    boxes = list(_MEDIABOX.finditer(pdf))
    if len(boxes) != 1:
        raise BrowserError(f"the printed PDF has {len(boxes)} page boxes, not one")
    x0, y0, x1, y1 = (float(v) for v in boxes[0].group(1).split())
    w, h = (v / MM_PER_IN * PT_PER_IN for v in (width_mm, height_mm))
    if x1 - x0 < w - 0.2 or y1 - y0 < h - 0.2:
        raise BrowserError(f"headless Chromium printed a page of {x1 - x0:g} × {y1 - y0:g} pt, smaller than "
                           f"the drawing's {w:g} × {h:g} pt")
    box = " ".join(f"{v:.3f}".rstrip("0").rstrip(".") for v in (x0, y1 - h, x0 + w, y1))  # 0.001 pt = 0.35 µm
    return updated(pdf, boxes[0].start(), b"/MediaBox [" + box.encode() + b"]")


def updated(pdf: bytes, at: int, entry: bytes) -> bytes:
    """``pdf`` with the ``/Key [value]`` entry found at byte ``at`` replaced by ``entry``, as an
    incremental update (PDF 1.7 § 7.5.6): the object holding it is appended anew, with an xref
    section and a trailer pointing back to the old ones — nothing before is moved."""
    heads = list(re.finditer(rb"(\d+) (\d+) obj\b", pdf[:at]))
    end = pdf.find(b"endobj", at)
    trailer = list(re.finditer(rb"trailer\s*(<<.*?>>)\s*startxref\s+(\d+)", pdf, re.DOTALL))
    if not heads or end < 0 or not trailer:
        raise BrowserError("the printed PDF is not laid out as expected (no object or no trailer)")
    head = heads[-1]
    body = pdf[head.end(): end]
    old = re.match(rb"/\w+\s*\[[^\]]*\]", pdf[at:end])
    assert old is not None
    body = body.replace(old.group(0), entry, 1)
    number, generation = int(head.group(1)), int(head.group(2))
    base = pdf if pdf.endswith(b"\n") else pdf + b"\n"
    offset = len(base)
    obj = b"%d %d obj" % (number, generation) + body + b"endobj\n"
    # the free head of the list (object 0) first, as readers expect of every xref section
    xref = b"xref\n0 1\n0000000000 65535 f \n%d 1\n%010d %05d n \n" % (number, offset, generation)
    old_trailer = re.sub(rb"/Prev\s+\d+\s*", b"", trailer[-1].group(1))
    new_trailer = old_trailer.replace(b"<<", b"<</Prev " + trailer[-1].group(2) + b"\n", 1)
    return (base + obj + xref + b"trailer\n" + new_trailer + b"\nstartxref\n%d\n%%%%EOF\n"
            % (offset + len(obj)))


def _png(tab: Tab, pixels: tuple[int, int], dpi: float) -> bytes:
    """The opened page's screenshot at ``dpi``, exactly ``pixels`` large, with its ``pHYs``."""
    scale = dpi / CSS_PX_PER_IN
    # Chromium clips a screenshot to whole CSS px (then × scale, rounded), so it is taken a little
    # larger and cut to the pixels asked
    clip = [math.ceil(n / scale - 1e-9) for n in pixels]
    tab.call("Emulation.setDeviceMetricsOverride", {
        "width": clip[0] + 1, "height": clip[1] + 1, "deviceScaleFactor": scale, "mobile": False})
    tab.call("Emulation.setDefaultBackgroundColorOverride", {"color": _WHITE})
    shot = base64.b64decode(tab.call("Page.captureScreenshot", {
        "format": "png", "clip": {"x": 0, "y": 0, "width": clip[0], "height": clip[1], "scale": 1}})["data"])
    return with_dpi(cropped(shot, *pixels), dpi)


def cropped(png: bytes, width: int, height: int) -> bytes:
    """``png`` cut to its top-left ``width`` × ``height`` pixels. No pixel is decoded: PNG's row
    filters refer only to pixels left of and above the one filtered, so the first bytes of each
    of the first rows are still a valid filtered image (8-bit RGB or RGBA, not interlaced)."""
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        raise BrowserError("headless Chromium's screenshot is not a PNG")
    w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", png[16:29])
    channels = {2: 3, 6: 4}.get(colour)
    if channels is None or depth != 8 or interlace or w < width or h < height:
        raise BrowserError(f"headless Chromium's screenshot ({w} × {h} px, colour type {colour}, depth {depth}) "
                           f"cannot be cut to {width} × {height} px")
    before: list[bytes] = []  # the chunks before the image data, which stay there (sRGB, iCCP)
    data: list[bytes] = []
    at = 33
    while at < len(png):
        length, kind = struct.unpack(">I4s", png[at: at + 8])
        if kind == b"IDAT":
            data.append(png[at + 8: at + 8 + length])
        elif not data and kind != b"IEND":
            before.append(png[at: at + 12 + length])
        at += 12 + length
    raw = zlib.decompress(b"".join(data))
    stride = 1 + w * channels  # a row: its filter byte, then its pixels
    rows = b"".join(raw[r * stride: r * stride + 1 + width * channels] for r in range(height))
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, 0)
    return (png[:8] + _chunk(b"IHDR", ihdr) + b"".join(before) + _chunk(b"IDAT", zlib.compress(rows, 6))
            + _chunk(b"IEND", b""))


def _chunk(kind: bytes, body: bytes) -> bytes:
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


def with_dpi(png: bytes, dpi: float) -> bytes:
    """``png`` with a ``pHYs`` chunk saying ``dpi`` (pixels per metre), after its IHDR, any older
    one dropped — so the image is placed at its true size."""
    head, ihdr_end = png[:8], 8 + 8 + 13 + 4
    chunks, at = [], ihdr_end
    while at < len(png):
        length, kind = struct.unpack(">I4s", png[at: at + 8])
        end = at + 12 + length
        if kind != b"pHYs":
            chunks.append(png[at:end])
        at = end
    ppm = round(dpi / MM_PER_IN * 1000)
    return head + png[8:ihdr_end] + _chunk(b"pHYs", struct.pack(">IIB", ppm, ppm, 1)) + b"".join(chunks)
