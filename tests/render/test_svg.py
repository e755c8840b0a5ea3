"""The SVG backend: byte-stable, escaped, prefixed ids, numbers where they belong."""
from __future__ import annotations

import math
import pathlib
import re
import xml.etree.ElementTree as ET
from dataclasses import replace

import pytest

from graphmech.render.layout import layout_sheet
from graphmech.drawing.primitives import (
    Arrow,
    FixedPivot,
    GuideLine,
    Hinge,
    Label,
    Panel,
    Segment,
    Sheet,
    Slider,
)
from graphmech.render.style import DEFAULT
from graphmech.render.svg import SvgBackend, clean_text, fmt, render_svg, sheet_id_prefix

NS = "{http://www.w3.org/2000/svg}"
EVIL = "</text><script>alert(1)</script>&\x00\x1b\ufffe\ud800"
EVIL_CLEAN = "</text><script>alert(1)</script>&"


def demo_sheet(title: str = "Four-bar: velocities", label: str = "b") -> Sheet:
    mech = Panel(
        "mech",
        "Mechanism",
        (
            Segment((0.0, 0.0), (10.0, 17.32)),
            Segment((10.0, 17.32), (55.0, 25.0)),
            Segment((55.0, 25.0), (60.0, 0.0)),
            FixedPivot((0.0, 0.0)),
            FixedPivot((60.0, 0.0)),
            Hinge((10.0, 17.32)),
            Hinge((55.0, 25.0)),
            GuideLine((70.0, -2.5), (100.0, -2.5)),
            Slider((85.0, 0.0), 0.0),
            Label("A", (10.0, 17.32)),
            Label("B", (55.0, 25.0)),
        ),
        ("μl = 0.002 m/mm",),
    )
    vel = Panel(
        "vel",
        "Velocity polygon",
        (
            Arrow((0.0, 0.0), (-30.0, 17.0), role="given"),
            Arrow((-30.0, 17.0), (-10.0, 30.0)),
            Arrow((0.0, 0.0), (-10.0, 30.0)),
            Label("p", (0.0, 0.0)),
            Label(label, (-10.0, 30.0)),
            Label("c", (-30.0, 17.0)),
        ),
        ("μv = 0.005 (m/s)/mm",),
    )
    return Sheet(title, (mech, vel), footer=("graphmech",))


def test_same_sheet_gives_byte_identical_svg() -> None:
    a = render_svg(demo_sheet(), "gm1a2b")
    b = render_svg(demo_sheet(), "gm1a2b")
    assert a == b
    assert a.encode("utf-8") == b.encode("utf-8")
    assert render_svg(demo_sheet(), "gm9") != a  # the prefix is really used


def test_page_size_and_viewbox() -> None:
    root = ET.fromstring(render_svg(demo_sheet(), "gm1"))
    assert root.tag == NS + "svg"
    assert (root.get("width"), root.get("height"), root.get("viewBox")) == (
        "297mm",
        "210mm",
        "0 0 297 210",
    )
    small = Sheet("", (Panel("a", "", (Segment((0.0, 0.0), (10.0, 0.0)),)),), page=(210.0, 148.5))
    root = ET.fromstring(render_svg(small, "gm1"))
    assert (root.get("width"), root.get("viewBox")) == ("210mm", "0 0 210 148.5")


def test_numbers_have_three_decimals_and_no_negative_zero() -> None:
    assert fmt(-0.0) == "0.000" and fmt(-0.0004999) == "0.000" and fmt(-0.0005001) == "-0.001"
    with pytest.raises(ValueError):
        fmt(math.nan)
    b = SvgBackend("gm1")
    b.begin(297.0, 210.0)
    b.line((-0.0, -1e-9), (-0.0004, 5.0), "given")
    b.polyline([(-0.0, -0.0), (1.0, -0.0002)], "construction", closed=True)
    b.circle((-1e-12, 3.0), 1.2, "hinge", filled=True)
    b.text("x", (-0.0001, -0.0), 3.5)
    svg = b.finish()
    assert "-0.000" not in svg
    assert 'x1="0.000" x2="0.000" y1="0.000" y2="5.000"' in svg
    full = render_svg(demo_sheet(), "gm1")
    assert "-0.000" not in full
    # every number in a coordinate attribute has exactly three decimals
    for attr, value in re.findall(r'\b(x1|x2|y1|y2|cx|cy|r|x|y|points)="([^"]*)"', full):
        for num in re.findall(r"-?\d+(?:\.\d+)?", value):
            assert re.fullmatch(r"-?\d+\.\d{3}", num), (attr, value)


def test_hostile_text_is_escaped_and_stripped() -> None:
    svg = render_svg(demo_sheet(title=EVIL, label=EVIL), "gm1")
    root = ET.fromstring(svg)  # parses: well-formed XML 1.0
    tags = {el.tag for el in root.iter()}
    assert NS + "script" not in tags and "script" not in tags
    assert "<script" not in svg  # only the escaped form appears
    assert "&lt;script&gt;" in svg
    for el in root.iter():
        assert not any(k.lower().startswith("on") for k in el.attrib)
    title = root.find(NS + "title")
    assert title is not None and title.text == EVIL_CLEAN
    assert list(root)[0] is title
    texts = [t.text for t in root.iter(NS + "text")]
    assert texts.count(EVIL_CLEAN) == 2  # sheet title and the label
    assert "\x00" not in svg and "\x1b" not in svg and "\ufffe" not in svg


def test_clean_text_keeps_what_xml_allows() -> None:
    s = "tab\tnl\ncr\r μ′ω² 𝜔 \x7f"
    assert clean_text(s) == s
    assert clean_text("\x01\x08\x0b\x0c\x1f\uffff\udfff") == ""


def test_clean_text_keeps_exactly_xml_s_chars_less_the_bidi_overrides() -> None:
    """Every code point: kept iff XML 1.0's Char production allows it
    (#x9 | #xA | #xD | [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF]) and it is not a
    bidirectional override (U+202A–202E, U+2066–2069)."""
    def allowed(c: int) -> bool:
        char = c in (0x9, 0xA, 0xD) or 0x20 <= c <= 0xD7FF or 0xE000 <= c <= 0xFFFD or c >= 0x10000
        return char and not (0x202A <= c <= 0x202E or 0x2066 <= c <= 0x2069)

    everything = "".join(map(chr, range(0x110000)))
    assert clean_text(everything) == "".join(chr(c) for c in range(0x110000) if allowed(c))


def test_ids_are_prefixed_and_unique() -> None:
    sheet = Sheet(
        "t",
        (
            Panel("same", "", (Segment((0.0, 0.0), (10.0, 0.0)),)),
            Panel("same", "", (Segment((0.0, 0.0), (10.0, 0.0)),)),
            Panel("x\"><script>", "", (Segment((0.0, 0.0), (10.0, 0.0)),)),
        ),
    )
    prefix = sheet_id_prefix(sheet)
    assert re.fullmatch(r"gm[0-9a-f]{8}", prefix)
    root = ET.fromstring(render_svg(sheet, prefix))
    ids = [el.get("id") for el in root.iter() if el.get("id") is not None]
    assert len(ids) >= 5
    assert all(i.startswith(prefix + "-") for i in ids)
    assert len(set(ids)) == len(ids)
    assert all(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.-]*", i) for i in ids)


def test_two_figures_on_one_page_do_not_share_ids() -> None:
    a, b = demo_sheet(), demo_sheet(label="d")
    ids = []
    for sheet in (a, b):
        root = ET.fromstring(render_svg(sheet, sheet_id_prefix(sheet)))
        ids.append({el.get("id") for el in root.iter() if el.get("id")})
    assert sheet_id_prefix(a) != sheet_id_prefix(b)
    assert not ids[0] & ids[1]


def test_bad_prefix_is_refused() -> None:
    for bad in ("", "3fa2", "a b", 'a"', "a<b"):
        with pytest.raises(ValueError, match="id_prefix"):
            SvgBackend(bad)


def test_arrow_line_and_head_numerically() -> None:
    arrow = Arrow((0.0, 0.0), (40.0, 0.0))
    sheet = Sheet("", (Panel("v", "", (arrow,)),))
    root = ET.fromstring(render_svg(sheet, "gm1"))
    pl = layout_sheet(sheet, DEFAULT, [[]]).panels[0]
    (line,) = list(root.iter(NS + "line"))
    got = [float(line.get(k)) for k in ("x1", "y1", "x2", "y2")]  # type: ignore[arg-type]
    tail, tip = pl.to_page(arrow.p0), pl.to_page(arrow.p1)
    want = [tail[0], tail[1], tip[0] - DEFAULT.arrow_length, tip[1]]
    assert got == pytest.approx(want, abs=1e-3)
    assert line.get("stroke-width") == "0.600" and line.get("stroke") == "black"
    (head,) = list(root.iter(NS + "polygon"))
    pts = [tuple(map(float, p.split(","))) for p in head.get("points", "").split()]
    assert pts[0] == pytest.approx(tip, abs=1e-3)
    assert pts[1] == pytest.approx((tip[0] - 2.8, tip[1] - 0.8), abs=1e-3)
    assert pts[2] == pytest.approx((tip[0] - 2.8, tip[1] + 0.8), abs=1e-3)
    assert head.get("fill") == "black" and head.get("stroke") == "none"


def test_pens_become_attributes() -> None:
    sheet = Sheet(
        "",
        (
            Panel(
                "m",
                "",
                (
                    Segment((0.0, 0.0), (20.0, 0.0), role="construction", dashed=True),
                    Segment((0.0, 5.0), (20.0, 5.0)),
                    Hinge((0.0, 5.0)),
                    Label("A", (0.0, 5.0)),
                ),
            ),
        ),
    )
    root = ET.fromstring(render_svg(sheet, "gm1"))
    thin, link = list(root.iter(NS + "line"))
    assert (thin.get("stroke"), thin.get("stroke-width")) == ("#555555", "0.180")
    assert thin.get("stroke-dasharray") == "2.500 1.200"
    assert (link.get("stroke-width"), link.get("stroke-dasharray")) == ("0.700", None)
    (hinge,) = list(root.iter(NS + "circle"))
    assert (hinge.get("fill"), hinge.get("r")) == ("white", "1.200")
    (letter,) = [t for t in root.iter(NS + "text") if t.text == "A"]
    assert letter.get("font-style") == "italic" and "serif" in letter.get("font-family", "")
    assert root.find(f".//{NS}style") is None and root.find(f".//{NS}script") is None


def test_backend_misuse_is_refused() -> None:
    b = SvgBackend("gm1")
    with pytest.raises(RuntimeError):
        b.line((0.0, 0.0), (1.0, 1.0), "given")
    b.begin(100.0, 100.0)
    b.begin_group("g")
    with pytest.raises(RuntimeError, match="left open"):
        b.finish()
    b.end_group()
    with pytest.raises(RuntimeError):
        b.end_group()
    with pytest.raises(KeyError):
        b.line((0.0, 0.0), (1.0, 1.0), "bold")


def test_only_the_svg_backend_writes_xml_and_nothing_imports_svgwrite() -> None:
    """svgwrite is no dependency (README, Dependencies); render/svg.py alone knows how SVG is written."""
    root = pathlib.Path(__file__).resolve().parents[2] / "graphmech"
    importing = re.compile(r"^\s*(?:import|from)\s+(svgwrite|xml)\b", re.MULTILINE)
    found = sorted(
        (m, p.relative_to(root).as_posix())
        for p in root.rglob("*.py")
        for m in importing.findall(p.read_text(encoding="utf-8"))
    )
    assert found == [("xml", "render/svg.py")]


def test_the_document_is_written_in_svgwrite_s_form() -> None:
    """The form the reference figures were written in (by svgwrite, through ElementTree): the
    root's attributes, then <title> and an empty <defs />, every element's attributes sorted by
    name, an empty one left out, polyline points "x,y x,y", no XML declaration."""
    b = SvgBackend("gm1", replace(DEFAULT, given=replace(DEFAULT.given, dash=())))
    b.begin(297.5, 210.0, "T")
    b.begin_group("a b")
    b.line((1.0, 2.0), (3.0, 4.0), "given", dashed=True)  # an empty dash pattern: no attribute
    b.polyline([(0.0, 0.0), (1.0, 2.5)], "given")
    b.end_group()
    svg = b.finish()
    assert svg == (
        '<svg baseProfile="full" height="210mm" id="gm1-svg" version="1.1" viewBox="0 0 297.5 210" '
        'width="297.5mm" xmlns="http://www.w3.org/2000/svg" xmlns:ev="http://www.w3.org/2001/xml-events" '
        'xmlns:xlink="http://www.w3.org/1999/xlink"><title>T</title><defs /><g id="gm1-a-b">'
        '<line stroke="black" stroke-linecap="round" stroke-width="0.700" '
        'x1="1.000" x2="3.000" y1="2.000" y2="4.000" />'
        '<polyline fill="none" points="0.000,0.000 1.000,2.500" stroke="black" stroke-linecap="round" '
        'stroke-linejoin="round" stroke-width="0.700" />'
        "</g></svg>"
    )


def test_every_element_s_attributes_are_sorted_in_a_whole_figure() -> None:
    svg = render_svg(demo_sheet(label="M_{b}′"), "gm1")
    tags = re.findall(r"<([a-z]+)((?: [a-zA-Z0-9:-]+=\"[^\"]*\")*) ?/?>", svg)
    assert {t for t, _ in tags} >= {"svg", "title", "defs", "g", "line", "polygon", "circle", "text", "tspan"}
    for tag, attrs in tags:
        names = re.findall(r' ([a-zA-Z0-9:-]+)="', attrs)
        assert names == sorted(names), (tag, names)


def test_markup_in_a_subscript_or_quotes_stays_text() -> None:
    svg = render_svg(demo_sheet(title='say "hi" & <b>', label="M_{</tspan><script>}"), "gm1")
    root = ET.fromstring(svg)
    assert root.find(NS + "title").text == 'say "hi" & <b>'
    assert "<script" not in svg and "&lt;/tspan&gt;&lt;script&gt;" in svg
    [text] = [t for t in root.iter(NS + "text") if t.text == "M"]
    assert [s.text for s in text] == ["</tspan><script>"]


def test_a_subscript_is_a_tspan_lowered_by_dy_and_the_next_run_comes_back() -> None:
    """M_{b}′: the b lowered and smaller by dy (not baseline-shift, which Firefox ignores), the
    prime back on the line; a Unicode subscript digit is set the same way."""
    root = ET.fromstring(render_svg(demo_sheet(label="M_{b}′ ω₂"), "gm1"))
    [text] = [t for t in root.iter(NS + "text") if t.text == "M"]
    sub, back, digit = list(text)
    assert sub.tag == NS + "tspan" and (sub.text, back.text, digit.text) == ("b", "′ ω", "2")
    size = float(text.get("font-size"))
    assert float(sub.get("dy")) == pytest.approx(0.25 * size, abs=1e-3)
    assert float(back.get("dy")) == pytest.approx(-0.25 * size, abs=1e-3)
    assert float(sub.get("font-size")) == pytest.approx(0.72 * size, abs=1e-3)
    assert float(sub.get("font-size")) >= 2.5
    assert back.get("font-size") is None and float(digit.get("dy")) == pytest.approx(0.25 * size, abs=1e-3)
    # scene text with a bare underscore is left as written
    root = ET.fromstring(render_svg(demo_sheet(title="M_b and x_y"), "gm1"))
    assert [t.text for t in root.iter(NS + "text")][0] == "M_b and x_y"
