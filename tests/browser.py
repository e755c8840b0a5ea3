"""Figures as headless Chromium shows them: the one browser driver, measuring script and geometry
that tests/test_browser.py and ``.ci/figure-report`` share.

The browser and its driver are graphmech's own (graphmech/render/chromium.py: Debian's
``chromium`` found on PATH or named by ``$GRAPHMECH_CHROMIUM`` / ``$CHROMIUM``, driven over the
DevTools pipe — no Playwright or pyppeteer, which download a browser of their own); this module
adds what only the tests need. One browser process serves every figure: each SVG is opened from
its file as an SVG document in a fresh tab, the fonts awaited, and :data:`MEASURE_JS` evaluated in
it; the page's errors (an XML parse error, a console error such as "<path> attribute d: Expected
number", an uncaught exception, a failed load) are collected beside the measurements.
:meth:`Browser.screenshot` photographs an SVG file the same way, for comparing graphmech's PNG
with what the browser shows.

What the browser measures (all mapped to the root's user space, i.e. page millimetres, with
``elem.getScreenCTM()`` composed with the inverse of the root's ``getScreenCTM()``):

* every ``<text>``: its ``getBBox()`` (the font's ascent–descent cell, as Chromium lays it out
  with the fonts installed; Times New Roman is absent on Debian, Liberation Serif — metric
  compatible — is what is used), its computed font size, and the same for each ``<tspan>``;
* every drawn shape (line, polyline, polygon, path, circle, ellipse, rect): its geometry —
  vertices for line/poly*, 360 points for circle/ellipse, corners for rect, and a path sampled
  with ``getTotalLength()``/``getPointAtLength()`` every 0.25 mm (so curves and arcs count) —
  its computed stroke, stroke width, fill and ``getBBox()``.

What :func:`analyse` computes per figure (mm at 1:1, tolerances below, in one place):

* ``label_stroke`` — the number of text boxes crossed by ink that is not the text's own.
  A shape's *ink* is its stroke (the centre line thickened by half the stroke width, round
  caps) plus, where it is filled (fill not ``none``: arrowheads, white hinges, slider blocks),
  its filled area — so a letter inside a slider block or on an arrowhead counts. A box is
  *crossed* when ink reaches more than ``TOL`` inside it (the box shrunk by ``TOL`` on each
  side meets the ink). **Ownership rule**: a shape belongs to a text only when the two are
  in the same parent ``<g>`` and that ``<g>`` holds no other ``<text>`` (a label group with its
  own leader, box or underline), or the shape names the text in ``data-label-for="<text id>"``.
  Each crossing (text, shapes) is listed in ``crossings``; ``label_stroke_ink`` repeats the
  count with the glyphs' tight box (canvas ``measureText``) where the text has one position.
* ``label_label`` — pairs of text boxes overlapping by more than ``TOL`` both across and down.
* ``filled`` — area of the union (shapely) of the ``getBBox()`` boxes of every drawn element
  (texts and shapes; a horizontal or vertical line's box has no area), clipped to the page,
  over the page's area (the root's width × height in mm). ``extent`` is the bounding box of
  all of them over the page: how much of the sheet the figure spans at all; ``panel_filled``
  the union of the boxes of the root's ``<g>`` children (the panels with their captions, the
  title, the footer) over the page: how much of the sheet the layout uses.
* ``min_text`` — the smallest font size of a ``<text>`` (its em, mm); ``min_sub`` the smallest
  of a ``<tspan>`` (a sub-/superscript), None where there is none; ``small_text`` how many
  texts are under ``SMALL_TEXT``; ``unicode_scripts`` how many texts write a sub- or
  superscript as a Unicode character beyond Latin-1 (₂, ᵗ, ⁿ).
* ``min_vector`` — the shortest drawn vector, tail to tip. graphmech marks no arrow with a class
  or marker: an arrow is a ``<line>`` shaft from the tail to the middle of the head's base,
  followed at once by its head, a filled ``<polygon>`` of three points with no stroke, tip first
  (``graphmech/render/sheet.py: arrow_shapes``); an arrow shorter than its head is the head
  alone. A head that follows a ``<polyline>`` ending at its tip is an arc arrow (the sense of
  an ω or ε), not a vector, and is left out. ``short_vectors`` counts vectors under
  ``SHORT_VECTOR``.
* ``underscore`` — texts holding an ASCII ``_``, not counting the sheet title (``<g id=…-title>``,
  the scene's own text, kept verbatim); ``underscore_title`` counts those in the title.

The numbers depend only on the SVG, Chromium's text layout and the installed fonts, so they are
the same on every run on one machine.
"""
from __future__ import annotations

import base64
import os
import re
from pathlib import Path
from typing import Any, NoReturn

import numpy as np
import pytest
from shapely import STRtree
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import unary_union

from graphmech.render import chromium
from graphmech.render.chromium import (
    BROWSERS,
    BrowserError,
    find_chromium,
    root_size_mm,
)

__all__ = ["BROWSERS", "Browser", "BrowserError", "analyse", "find_chromium", "no_browser", "open_browser", "root_size_mm"]

# ---------------------------------------------------------------------------- tolerances (one place)
TOL = 0.1            # mm: how far ink or another box must reach into a text box to count
FIT_FILLED = 0.5     # a fit page: the union of the element boxes covers at least this fraction
SMALL_TEXT = 3.5     # mm: body text smaller than this is counted (the rule)
SHORT_VECTOR = 10.0  # mm: vectors shorter than this are counted
JOIN_TOL = 0.01      # mm: a shaft's end and a head's base meet within this (coordinates have 3 decimals)

# Evaluated in each figure's page; its value (returned by value, as JSON) is the measurement.
MEASURE_JS = r"""
(async function () {
  var out = {ok: true};
  try {
    var pe = document.querySelector('parsererror');
    if (pe) throw new Error('XML parse error: ' + pe.textContent.trim().replace(/\s+/g, ' '));
    var root = document.documentElement;
    if (root.namespaceURI !== 'http://www.w3.org/2000/svg' || root.localName !== 'svg')
      throw new Error('the document is not an SVG document: <' + root.localName + '>');
    await document.fonts.ready;
    var R = root.getScreenCTM().inverse();
    var M = function (el) { return R.multiply(el.getScreenCTM()); };
    var P = function (m, x, y) { return [m.a * x + m.c * y + m.e, m.b * x + m.d * y + m.f]; };
    var S = function (m) { return Math.sqrt(Math.abs(m.a * m.d - m.b * m.c)); };
    var BOX = function (m, b) {
      var c = [P(m, b.x, b.y), P(m, b.x + b.width, b.y), P(m, b.x, b.y + b.height),
               P(m, b.x + b.width, b.y + b.height)];
      var xs = c.map(function (p) { return p[0]; }), ys = c.map(function (p) { return p[1]; });
      return [Math.min.apply(null, xs), Math.min.apply(null, ys),
              Math.max.apply(null, xs), Math.max.apply(null, ys)];
    };
    var vb = root.viewBox && root.viewBox.baseVal;
    out.page = {width_px: root.width.baseVal.value, height_px: root.height.baseVal.value,
                viewbox: vb && vb.width > 0 ? [vb.x, vb.y, vb.width, vb.height] : null};
    var groups = [], gindex = new Map();
    var gid = function (g) {
      if (g === root) return -1;
      if (!gindex.has(g)) { gindex.set(g, groups.length); groups.push(g.getAttribute('id') || ''); }
      return gindex.get(g);
    };
    var SHAPES = {line: 1, polyline: 1, polygon: 1, path: 1, circle: 1, ellipse: 1, rect: 1};
    var els = [];
    var all = root.querySelectorAll('*');
    for (var i = 0; i < all.length; i++) {
      var el = all[i], tag = el.localName;
      if (el.namespaceURI !== 'http://www.w3.org/2000/svg') continue;
      if (!(tag in SHAPES) && tag !== 'text') continue;
      if (el.closest('defs, clipPath, mask, marker, pattern, symbol, title, metadata')) continue;
      var cs = getComputedStyle(el);
      if (cs.display === 'none' || cs.visibility === 'hidden') continue;
      var m = M(el), s = S(m), r = {tag: tag, parent: gid(el.parentNode),
                                    id: el.getAttribute('id') || '',
                                    owner: el.getAttribute('data-label-for') || ''};
      r.bbox = BOX(m, el.getBBox());
      if (tag === 'text') {
        r.text = el.textContent;
        r.font_size = parseFloat(cs.fontSize) * s;
        r.italic = cs.fontStyle === 'italic';
        r.ink = null;  // the glyphs' tight box, from canvas measureText (single-position text only)
        if (el.querySelector('tspan') === null && el.x.baseVal.numberOfItems === 1 &&
            el.y.baseVal.numberOfItems === 1 && el.dx.baseVal.numberOfItems === 0 &&
            el.dy.baseVal.numberOfItems === 0 && !el.hasAttribute('rotate')) {
          var fs = parseFloat(cs.fontSize), ctx = new OffscreenCanvas(8, 8).getContext('2d');
          ctx.font = cs.fontStyle + ' ' + cs.fontWeight + ' 100px ' + cs.fontFamily;
          ctx.textAlign = {start: 'left', middle: 'center', end: 'right'}[cs.textAnchor] || 'left';
          ctx.textBaseline = 'alphabetic';
          var tm0 = ctx.measureText(el.textContent), f = fs / 100;
          var x0 = el.x.baseVal.getItem(0).value, y0 = el.y.baseVal.getItem(0).value;
          r.ink = BOX(m, {x: x0 - tm0.actualBoundingBoxLeft * f, y: y0 - tm0.actualBoundingBoxAscent * f,
                          width: (tm0.actualBoundingBoxLeft + tm0.actualBoundingBoxRight) * f,
                          height: (tm0.actualBoundingBoxAscent + tm0.actualBoundingBoxDescent) * f});
        }
        r.tspans = [];
        var ts = el.querySelectorAll('tspan');
        for (var k = 0; k < ts.length; k++) {
          var tm = M(ts[k]);
          r.tspans.push({text: ts[k].textContent,
                         font_size: parseFloat(getComputedStyle(ts[k]).fontSize) * S(tm),
                         bbox: BOX(tm, ts[k].getBBox())});
        }
      } else {
        r.stroke = cs.stroke;
        r.stroke_width = cs.stroke === 'none' ? 0 : parseFloat(cs.strokeWidth) * s;
        r.fill = cs.fill;
        r.closed = tag !== 'line' && tag !== 'polyline';
        var pts = [];
        if (tag === 'line') {
          pts = [P(m, el.x1.baseVal.value, el.y1.baseVal.value), P(m, el.x2.baseVal.value, el.y2.baseVal.value)];
        } else if (tag === 'polyline' || tag === 'polygon') {
          for (var k = 0; k < el.points.numberOfItems; k++) {
            var q = el.points.getItem(k); pts.push(P(m, q.x, q.y));
          }
        } else if (tag === 'circle' || tag === 'ellipse') {
          var cx = el.cx.baseVal.value, cy = el.cy.baseVal.value;
          var rx = tag === 'circle' ? el.r.baseVal.value : el.rx.baseVal.value;
          var ry = tag === 'circle' ? rx : el.ry.baseVal.value;
          for (var k = 0; k < 360; k++) {
            var a = 2 * Math.PI * k / 360; pts.push(P(m, cx + rx * Math.cos(a), cy + ry * Math.sin(a)));
          }
        } else if (tag === 'rect') {
          var x = el.x.baseVal.value, y = el.y.baseVal.value, w = el.width.baseVal.value, h = el.height.baseVal.value;
          pts = [P(m, x, y), P(m, x + w, y), P(m, x + w, y + h), P(m, x, y + h)];
        } else {  // path: sampled along its length, so curves and arcs count
          var L = el.getTotalLength(), n = Math.min(20000, Math.max(32, Math.ceil(L * s / 0.25)));
          for (var k = 0; k <= n; k++) { var q = el.getPointAtLength(L * k / n); pts.push(P(m, q.x, q.y)); }
          var d = el.getAttribute('d') || '';
          r.closed = /[zZ]\s*$/.test(d);
        }
        r.points = pts;
      }
      els.push(r);
    }
    out.groups = groups;
    out.blocks = [];  // the boxes of the root's <g> children: the panels, the title, the footer
    for (var c = root.firstElementChild; c; c = c.nextElementSibling) {
      if (c.localName !== 'g') continue;
      var gb = c.getBBox();
      if (gb.width > 0 || gb.height > 0) out.blocks.push(BOX(M(c), gb));
    }
    out.elements = els;
  } catch (e) {
    out = {ok: false, error: String(e && e.stack || e)};
  }
  return out;
})()
"""

_SCRIPTS = re.compile("[\u2070-\u209c\u1d2c-\u1d6a]")  # sub-/superscript characters beyond Latin-1


def no_browser(ci: bool) -> NoReturn:
    """Without a browser: fail where CI is set (CI must not skip silently), else skip saying why.
    Every browser test's fixture calls this when :func:`find_chromium` finds none."""
    why = f"no browser: none of {', '.join(BROWSERS)} is on PATH"
    if ci:
        pytest.fail(f"{why}, and CI is set: the browser tests must run in CI (.ci/run installs chromium)")
    pytest.skip(f"{why} (CI is unset; with CI set this fails)")


def open_browser():
    """The browser tests' module fixture (``browser = pytest.fixture(scope="module")(open_browser)``):
    one headless Chromium for the module, or :func:`no_browser`."""
    executable = find_chromium()
    if executable is None:
        no_browser("CI" in os.environ)
    with Browser(executable) as b:
        yield b


class Browser(chromium.Browser):
    """graphmech's headless Chromium with the tests' two uses: ``measure(svg)`` and
    ``screenshot(svg, dpi)`` per figure file. A context manager."""

    def measure(self, svg: Path) -> dict[str, Any]:
        """``svg`` opened as users open it, measured: the script's JSON plus ``errors`` (the page's
        error messages, in order) and ``page_mm``. Raises BrowserError where nothing could be
        measured (the message holds the page's errors too)."""
        with self.tab(Path(svg).resolve().as_uri(), ("Page", "Runtime", "Log")) as tab:
            value = tab.call("Runtime.evaluate", {"expression": MEASURE_JS, "awaitPromise": True,
                                                  "returnByValue": True})
            errors = [msg for e in tab.events() for msg in [_error_message(e)] if msg]
        if "exceptionDetails" in value:
            raise BrowserError(f"{svg.name}: the measuring script failed: {value['exceptionDetails']}")
        data: dict[str, Any] = value["result"]["value"]
        if not data.get("ok"):
            raise BrowserError(f"{svg.name}: {data.get('error')}" + "".join(f"\n  {e}" for e in errors))
        data["errors"] = errors
        data["page_mm"] = root_size_mm(Path(svg).read_text(encoding="utf-8"))
        return data

    def evaluate(self, page: Path, expression: str) -> tuple[Any, list[str]]:
        """Any local file (an HTML page) opened in a fresh tab, after its load event (its images
        loaded or failed): ``expression``'s value (awaited, by value) and the page's errors."""
        with self.tab(Path(page).resolve().as_uri(), ("Page", "Runtime", "Log")) as tab:
            value = tab.evaluate(expression)
            errors = [msg for e in tab.events() for msg in [_error_message(e)] if msg]
        return value, errors

    def screenshot(self, svg: Path, dpi: float) -> bytes:
        """``svg`` opened from its file as an SVG document and photographed whole at ``dpi``, on
        white, as the browser shows it — not graphmech.render.export's way (an HTML page holding
        the SVG, cut to the exact pixels): the PNG the tests compare it with."""
        w, h = root_size_mm(Path(svg).read_text(encoding="utf-8"))
        with self.tab(Path(svg).resolve().as_uri()) as tab:
            tab.call("Emulation.setDeviceMetricsOverride", {
                "width": round(w / 25.4 * 96), "height": round(h / 25.4 * 96), "deviceScaleFactor": dpi / 96,
                "mobile": False})
            tab.call("Emulation.setDefaultBackgroundColorOverride", {"color": {"r": 255, "g": 255, "b": 255, "a": 1}})
            tab.call("Runtime.evaluate", {"expression": "document.fonts.ready.then(function () { return 1; })",
                                          "awaitPromise": True})
            return base64.b64decode(tab.call("Page.captureScreenshot", {"format": "png"})["data"])


def _error_message(event: dict[str, Any]) -> str | None:
    """The page error an event reports, or None (events that are not errors)."""
    p = event.get("params", {})
    if event["method"] == "Log.entryAdded" and p["entry"]["level"] == "error":
        return f"{p['entry']['source']}: {p['entry']['text']}"
    if event["method"] == "Runtime.consoleAPICalled" and p["type"] in ("error", "assert"):
        return "console: " + " ".join(str(a.get("value", a.get("description", ""))) for a in p["args"])
    if event["method"] == "Runtime.exceptionThrown":
        d = p["exceptionDetails"]
        return "exception: " + str(d.get("exception", {}).get("description") or d.get("text"))
    return None


# ---------------------------------------------------------------------------- the geometry
def _ink(el: dict, k: float):
    """A shape's ink (stroke band ∪ filled area) in mm, or None when nothing is drawn."""
    pts = [(x * k, y * k) for x, y in el["points"]]
    if not pts:
        return None
    parts = []
    sw = el["stroke_width"] * k
    if el["stroke"] != "none" and sw > 0:
        if len(pts) == 1 or all(p == pts[0] for p in pts):
            parts.append(Point(pts[0]).buffer(sw / 2))
        else:
            ring = pts + [pts[0]] if el["closed"] else pts
            parts.append(LineString(ring).buffer(sw / 2))
    if el["fill"] != "none" and len(pts) >= 3:
        poly = Polygon(pts)
        if not poly.is_valid:
            poly = poly.buffer(0)
        if poly.area > 0:
            parts.append(poly)
    if not parts:
        return None
    return parts[0] if len(parts) == 1 else unary_union(parts)


def _describe(el: dict, k: float) -> str:
    sw = el["stroke_width"] * k
    what = el["tag"]
    if el["fill"] != "none" and len(el["points"]) >= 3 and el["tag"] != "polyline":
        what += " filled " + ("white" if el["fill"] == "rgb(255, 255, 255)" else "ink")
    if el["stroke"] != "none":
        what += f" stroke-width={sw:.2f}"
    return what


def _vectors(shapes: list[dict], k: float) -> tuple[list[dict], int]:
    """Drawn vectors (tail, tip, length, group) and the number of arc arrows left out."""
    out, arcs = [], 0
    for i, el in enumerate(shapes):
        if not (el["tag"] == "polygon" and len(el["points"]) == 3 and el["stroke"] == "none"
                and el["fill"] != "none"):
            continue
        tip = np.array(el["points"][0]) * k
        base = (np.array(el["points"][1]) + np.array(el["points"][2])) * k / 2
        tail = base
        prev = shapes[i - 1] if i > 0 and shapes[i - 1]["parent"] == el["parent"] else None
        if prev is not None and prev["tag"] == "line" and \
                np.hypot(*(np.array(prev["points"][1]) * k - base)) <= JOIN_TOL:
            tail = np.array(prev["points"][0]) * k
        elif prev is not None and prev["tag"] == "polyline" and \
                np.hypot(*(np.array(prev["points"][-1]) * k - tip)) <= JOIN_TOL:
            arcs += 1
            continue
        out.append({"tail": [round(float(v), 3) for v in tail], "tip": [round(float(v), 3) for v in tip],
                    "length": round(float(np.hypot(*(tip - tail))), 3), "parent": el["parent"],
                    "head_only": bool(tail is base)})
    return out, arcs


def analyse(name: str, data: dict) -> dict:
    """Everything the module's docstring lists, for one figure's measurement ``data``."""
    page_w, page_h = data["page_mm"]
    vb = data["page"]["viewbox"]
    k = page_w / vb[2] if vb else 25.4 / 96  # mm per root user unit
    groups = data["groups"]
    els = data["elements"]
    texts = [e for e in els if e["tag"] == "text"]
    shapes = [e for e in els if e["tag"] != "text"]
    tboxes = [tuple(v * k for v in t["bbox"]) for t in texts]

    # ownership: a <g> holding exactly one text owns its shapes for that text
    texts_in = {}
    for ti, t in enumerate(texts):
        texts_in.setdefault(t["parent"], []).append(ti)

    def owns(ti: int, sh: dict) -> bool:
        t = texts[ti]
        if sh["owner"] and sh["owner"] == t["id"]:
            return True
        return sh["parent"] == t["parent"] and t["parent"] != -1 and len(texts_in[t["parent"]]) == 1

    inks = [_ink(s, k) for s in shapes]
    idx = [i for i, g in enumerate(inks) if g is not None]
    tree = STRtree([inks[i] for i in idx])

    def hits_of(ti: int, b: tuple) -> list[int]:
        if not (b[2] - b[0] > 2 * TOL and b[3] - b[1] > 2 * TOL):
            return []
        inner = box(b[0] + TOL, b[1] + TOL, b[2] - TOL, b[3] - TOL)
        return [idx[int(j)] for j in sorted(tree.query(inner, predicate="intersects"))
                if not owns(ti, shapes[idx[int(j)]])]

    crossings = []
    per_text = []
    crossed_ink = 0
    for ti, (t, b) in enumerate(zip(texts, tboxes)):
        hits = hits_of(ti, b)
        ink_box = tuple(v * k for v in t["ink"]) if t.get("ink") else b
        ink_hits = hits_of(ti, ink_box)
        crossed_ink += bool(ink_hits)
        if hits or ink_hits:
            crossings.append({"text": t["text"], "group": groups[t["parent"]] if t["parent"] >= 0 else "",
                              "box": [round(v, 3) for v in b], "ink_box": [round(v, 3) for v in ink_box],
                              "by": [_describe(shapes[si], k) for si in hits],
                              "by_ink": [_describe(shapes[si], k) for si in ink_hits]})
        per_text.append(len(hits))
    crossed = sum(1 for c in crossings if c["by"])

    pairs = []
    for i in range(len(texts)):
        a = tboxes[i]
        for j in range(i + 1, len(texts)):
            c = tboxes[j]
            dx = min(a[2], c[2]) - max(a[0], c[0])
            dy = min(a[3], c[3]) - max(a[1], c[1])
            if dx > TOL and dy > TOL:
                pairs.append({"a": texts[i]["text"], "b": texts[j]["text"],
                              "overlap": [round(dx, 3), round(dy, 3)]})

    page = box(0, 0, page_w, page_h)
    boxes = [box(*(v * k for v in e["bbox"])) for e in els]
    covered = unary_union([b for b in boxes if b.area > 0]).intersection(page)
    blocks = unary_union([box(*(v * k for v in b)) for b in data["blocks"]]).intersection(page)
    allb = np.array([[v * k for v in e["bbox"]] for e in els]) if els else np.zeros((0, 4))
    ext = box(max(0.0, allb[:, 0].min()), max(0.0, allb[:, 1].min()),
              min(page_w, allb[:, 2].max()), min(page_h, allb[:, 3].max())) if len(allb) else box(0, 0, 0, 0)

    sizes = [t["font_size"] * k for t in texts]
    subs = [ts["font_size"] * k for t in texts for ts in t["tspans"]]
    vectors, arcs = _vectors(shapes, k)
    shortest = min(vectors, key=lambda v: (v["length"], v["tail"], v["tip"])) if vectors else None
    under = [t for t in texts if "_" in t["text"]]
    in_title = [t for t in under if t["parent"] >= 0 and groups[t["parent"]].endswith("-title")]
    composed = [t for t in under if t not in in_title]

    return {
        "figure": name,
        "page_mm": [page_w, page_h],
        "texts": len(texts),
        "shapes": len(shapes),
        "label_stroke": crossed,
        "label_stroke_pairs": sum(per_text),
        "label_stroke_ink": crossed_ink,
        "label_label": len(pairs),
        "filled": round(covered.area / page.area, 4),
        "extent": round(ext.area / page.area, 4),
        "panel_filled": round(blocks.area / page.area, 4),
        "min_text": round(min(sizes), 3) if sizes else None,
        "min_sub": round(min(subs), 3) if subs else None,
        "small_text": sum(1 for s in sizes if s < SMALL_TEXT - 1e-9),
        "min_vector": shortest["length"] if shortest else None,
        "min_vector_group": (groups[shortest["parent"]] if shortest and shortest["parent"] >= 0 else None),
        "vectors": len(vectors),
        "short_vectors": sum(1 for v in vectors if v["length"] < SHORT_VECTOR),
        "arc_arrows": arcs,
        "underscore": len(composed),
        "underscore_title": len(in_title),
        "underscore_texts": [t["text"] for t in composed],
        "unicode_scripts": sum(1 for t in texts if _SCRIPTS.search(t["text"])),
        "crossings": crossings,
        "label_pairs": pairs,
        "vector_list": sorted(vectors, key=lambda v: (v["length"], v["tail"], v["tip"])),
        "font_sizes": sorted({round(s, 3) for s in sizes}),
        "errors": list(data.get("errors", [])),
    }
