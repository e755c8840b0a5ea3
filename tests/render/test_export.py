"""graphmech/render/export.py and ``graphmech render -o x.svg|x.pdf|x.png``: the format by the
extension (refusals in one line, nothing written), the PDF at 1:1 with its fonts embedded and its
Chinese text kept, the PNG at its dpi and as the browser shows the SVG.

The PDF is read with pypdf and the PNG with Pillow (the [test] extra). The browser tests follow
tests/test_browser.py's rule (skip without a browser unless CI is set)."""
from __future__ import annotations

import io
import re
import struct
import zlib

import numpy as np
import pypdf
import pytest
from PIL import Image

from graphmech.errors import GraphmechError
from graphmech.render.chromium import ENVIRON, BrowserError, root_size_mm
from graphmech.render.export import (
    FORMATS,
    MAX_DPI,
    MIN_DPI,
    check_dpi,
    convert,
    cropped,
    format_of,
    png_size,
    save,
    with_dpi,
)
from graphmech.scene import render_scene
from tests.browser import open_browser
from tests.conftest import SCENES, assert_refused, run_cli

browser = pytest.fixture(scope="module")(open_browser)

ZH = SCENES / "kin.oscillating_block-zh.toml"  # notation = "zh": a Chinese sheet
MM_PER_PT = 25.4 / 72
PAGE_TOL_MM = 0.1
# The PNG against the browser's own screenshot of the SVG file: a pixel differs when its grey is
# more than GREY_TOL levels (of 255) from every pixel of the other image's 3 × 3 around it, either
# way — anti-aliasing allowed for: Chromium paints an SVG document's root in a box snapped to
# whole CSS px, on A4 0.04 % larger than the page's mm (0.7 px at the far edge at 150 dpi), where
# the PNG is at true scale. At most PIXELS_DIFFER of the page may differ.
GREY_TOL = 64
PIXELS_DIFFER = 0.01


@pytest.fixture(scope="module")
def zh_svg() -> str:
    svg, _ = render_scene(ZH)
    return svg


@pytest.fixture(scope="module")
def zh_pdf(zh_svg, browser) -> pypdf.PdfReader:
    return pypdf.PdfReader(io.BytesIO(convert(zh_svg, "pdf", browser=browser)))


def page_mm(reader: pypdf.PdfReader) -> tuple[float, float]:
    box = reader.pages[0].mediabox
    return float(box.width) * MM_PER_PT, float(box.height) * MM_PER_PT


def png_image(data: bytes) -> Image.Image:
    return Image.open(io.BytesIO(data))


# ---------------------------------------------------------------------------- the format


@pytest.mark.parametrize("path, fmt, kind", [
    ("a.svg", None, "svg"), ("a.PDF", None, "pdf"), ("dir.v2/a.Png", None, "png"), ("a.pdf", "pdf", "pdf"),
    ("a.png", "PNG", "png"), ("a", None, "svg"), ("a", "pdf", "pdf"), ("", "png", "png"),
    (".png", None, "png"), ("dir/.PDF", None, "pdf"),  # a name that is all extension: never SVG in it
])
def test_the_format_is_the_extension_or_the_one_asked(path, fmt, kind):
    assert format_of(path, fmt) == kind


@pytest.mark.parametrize("path, fmt, words", [
    ("out.jpg", None, "out.jpg: unknown format .jpg: write .svg, .pdf or .png (or --format)"),
    ("out.svgz", "svg", "out.svgz: unknown format .svgz"),
    ("out.pdf", "png", "out.pdf: the extension .pdf is not the format png"),
    ("out.png", "gif", "unknown format 'gif': choose from svg, pdf, png"),
    (".png", "svg", ".png: the extension .png is not the format svg"),
])
def test_an_unknown_or_mismatched_format_is_refused_in_one_line(path, fmt, words):
    with pytest.raises(GraphmechError) as e:
        format_of(path, fmt)
    assert str(e.value).startswith(words) and "\n" not in str(e.value)


@pytest.mark.parametrize("dpi", [0, -72, MIN_DPI - 1, MAX_DPI + 1, float("nan"), float("inf")])
def test_a_bad_dpi_is_refused(dpi):
    with pytest.raises(GraphmechError, match="--dpi must be a number from"):
        check_dpi(dpi)


def test_the_png_size_is_the_page_at_its_dpi_and_bounded():
    assert png_size(297, 210, 150) == (1754, 1240)  # 297 / 25.4 · 150 = 1753.9
    assert png_size(297, 210, 96) == (1123, 794)
    assert png_size(1, 1, 10) == (1, 1)  # 0.39 px: at least one
    with pytest.raises(GraphmechError, match=r"19866 × 14031 px .* too large"):
        png_size(841, 594, 600)  # A1 at 600 dpi


def test_svg_needs_no_browser(tmp_path, monkeypatch, zh_svg):
    for name in ENVIRON:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))
    assert convert(zh_svg, "svg") == zh_svg.encode()
    assert save(zh_svg, tmp_path / "a.svg") == "svg"
    assert (tmp_path / "a.svg").read_text(encoding="utf-8") == zh_svg
    with pytest.raises(BrowserError, match="apt-get install chromium"):
        save(zh_svg, tmp_path / "a.pdf")
    assert not (tmp_path / "a.pdf").exists()


def synthetic_png(width: int, height: int) -> tuple[bytes, np.ndarray]:
    """An RGB PNG of gradients, every row with a different filter (all five), and its pixels."""
    y, x = np.mgrid[0:height, 0:width]
    pixels = np.stack([(x * 7 + y) % 256, (y * 5) % 256, (x * y) % 256], axis=-1).astype(np.uint8)
    rows = []
    for r in range(height):
        raw = pixels[r].astype(int).ravel()
        left = np.concatenate([[0, 0, 0], raw[:-3]])
        up = pixels[r - 1].astype(int).ravel() if r else np.zeros_like(raw)
        kind = r % 5
        if kind == 4:  # Paeth, byte by byte
            ul = np.concatenate([[0, 0, 0], up[:-3]])
            p = left + up - ul
            pa, pb, pc = abs(p - left), abs(p - up), abs(p - ul)
            pred = np.where((pa <= pb) & (pa <= pc), left, np.where(pb <= pc, up, ul))
        else:
            pred = [np.zeros_like(raw), left, up, (left + up) // 2][kind]
        rows.append(bytes([kind]) + ((raw - pred) % 256).astype(np.uint8).tobytes())
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"sRGB", b"\x00")
           + chunk(b"IDAT", zlib.compress(b"".join(rows))) + chunk(b"IEND", b""))
    return png, pixels


def test_a_png_is_cut_without_decoding_and_keeps_its_pixels():
    png, pixels = synthetic_png(23, 17)
    assert np.array_equal(np.asarray(png_image(png)), pixels)  # the synthetic PNG is right
    cut = cropped(png, 20, 11)
    assert np.array_equal(np.asarray(png_image(cut).convert("RGB")), pixels[:11, :20])
    assert cut.index(b"sRGB") < cut.index(b"IDAT")  # a chunk before the data stays before it
    with pytest.raises(BrowserError, match="cannot be cut"):
        cropped(png, 24, 10)


def test_a_png_says_its_dpi():
    png, pixels = synthetic_png(5, 4)
    marked = with_dpi(with_dpi(png, 96), 300)  # the older pHYs is replaced, not repeated
    assert marked.count(b"pHYs") == 1
    image = png_image(marked)
    assert image.info["dpi"] == pytest.approx((300, 300), abs=0.01)
    assert np.array_equal(np.asarray(image), pixels)


# ---------------------------------------------------------------------------- the PDF


def test_the_pdf_page_is_the_svg_page_at_one_to_one(zh_svg, zh_pdf):
    assert len(zh_pdf.pages) == 1
    w, h = page_mm(zh_pdf)
    assert root_size_mm(zh_svg) == (297.0, 210.0)
    assert w == pytest.approx(297.0, abs=PAGE_TOL_MM) and h == pytest.approx(210.0, abs=PAGE_TOL_MM)


def test_the_pdf_draws_at_one_to_one_from_the_top_left_corner(zh_svg, zh_pdf):
    """The footer's text stands where the SVG puts it, in mm from the page's top-left corner."""
    m = re.search(r'<text[^>]* x="([\d.]+)" y="([\d.]+)">graphmech \d', zh_svg)
    assert m, "the sheet's footer"
    page = zh_pdf.pages[0]
    top = float(page.mediabox.top)
    found = []

    def visit(text, cm, tm, font, size):
        if text.startswith("graphmech"):
            x = tm[4] * cm[0] + tm[5] * cm[2] + cm[4]
            y = tm[4] * cm[1] + tm[5] * cm[3] + cm[5]
            found.append((x * MM_PER_PT, (top - y) * MM_PER_PT))

    page.extract_text(visitor_text=visit)
    assert len(found) == 1
    assert found[0] == pytest.approx((float(m.group(1)), float(m.group(2))), abs=PAGE_TOL_MM)


def test_a_fit_page_is_its_own_size(browser):
    svg, _ = render_scene(ZH, "fit")
    w, h = root_size_mm(svg)
    assert (w, h) != (297.0, 210.0)
    reader = pypdf.PdfReader(io.BytesIO(convert(svg, "pdf", browser=browser)))
    assert page_mm(reader) == pytest.approx((w, h), abs=PAGE_TOL_MM)


def test_the_pdf_embeds_subsets_of_its_fonts(zh_pdf):
    """Each font is in the file: a font program (TrueType FontFile2, CFF FontFile3) or, for the CFF
    outlines of Noto CJK that Skia cannot embed as a program, a Type 3 font whose glyphs are drawn
    in the PDF itself; each names a subset (``ABCDEF+``); none leans on an installed font."""
    fonts = {}
    for font in zh_pdf.pages[0]["/Resources"]["/Font"].values():
        font = font.get_object()
        described = font["/DescendantFonts"][0].get_object() if "/DescendantFonts" in font else font
        descriptor = described["/FontDescriptor"].get_object()
        programs = [k for k in ("/FontFile", "/FontFile2", "/FontFile3") if k in descriptor]
        embedded = programs or (font["/Subtype"] == "/Type3" and len(font["/CharProcs"]) > 0)
        assert embedded, f"{descriptor['/FontName']} is not embedded"
        assert "/ToUnicode" in font, f"{descriptor['/FontName']}: no ToUnicode (its text could not be copied)"
        fonts[str(descriptor["/FontName"]).lstrip("/")] = programs
    assert all(re.fullmatch(r"[A-Z]{6}\+\S+", name) for name in fonts), sorted(fonts)
    families = {name.split("+")[1]: programs for name, programs in fonts.items()}
    assert families["LiberationSerif"] == ["/FontFile2"]  # Latin letters: a TrueType subset
    assert any("CJK" in name for name in families), sorted(families)  # the Chinese letters' font


def test_the_chinese_text_survives_in_the_pdf(zh_svg, zh_pdf):
    text = zh_pdf.pages[0].extract_text()
    for words in ("速度多边形", "加速度多边形", "机构运动简图", "摇块机构的速度多边形与加速度多边形"):
        assert words in zh_svg
        assert words in text, words
    assert "ω1 = 10 rad/s" in text  # Greek and Latin beside it


def test_save_writes_nothing_when_the_browser_fails(tmp_path, zh_svg):
    from graphmech.render.chromium import Browser

    out = tmp_path / "a.pdf"
    out.write_bytes(b"before")
    with Browser() as dead:
        dead.close()
        with pytest.raises(GraphmechError):
            save(zh_svg, out, browser=dead)
    assert out.read_bytes() == b"before"
    assert [p.name for p in tmp_path.iterdir()] == ["a.pdf"]  # no temporary file left


def test_a_broken_svg_is_refused_not_printed(browser):
    with pytest.raises(BrowserError, match="not well-formed"):
        convert('<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm"><text>a & b</text></svg>',
                "pdf", browser=browser)


# ---------------------------------------------------------------------------- the PNG


@pytest.mark.parametrize("dpi", [72, 150, 300])
def test_the_png_is_the_page_at_its_dpi_on_white(browser, zh_svg, dpi):
    image = png_image(convert(zh_svg, "png", dpi=dpi, browser=browser))
    assert image.size == (round(297 / 25.4 * dpi), round(210 / 25.4 * dpi))
    assert image.info["dpi"] == pytest.approx((dpi, dpi), abs=0.02)
    grey = np.asarray(image.convert("L"))
    assert grey[0, 0] == grey[-1, -1] == 255  # white corners: the background, not transparency
    assert 0.005 < (grey < 128).mean() < 0.1  # and a drawing on it


def unmatched(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Where ``a``'s grey is more than GREY_TOL from every pixel of the 3 × 3 around it in ``b``."""
    h, w = a.shape
    padded = np.pad(b.astype(int), 1, mode="edge")
    return np.min([np.abs(a.astype(int) - padded[dy:dy + h, dx:dx + w]) for dy in range(3) for dx in range(3)],
                  axis=0) > GREY_TOL


def different_pixels(png: np.ndarray, shot: np.ndarray) -> float:
    """The fraction of the pixels that differ, either way, between ``png`` and ``shot`` (cut to
    the PNG's size)."""
    shot = shot[:png.shape[0], :png.shape[1]]
    return float((unmatched(png, shot) | unmatched(shot, png)).mean())


def test_the_png_is_what_the_browser_shows_of_the_svg_file(browser, zh_svg, tmp_path):
    svg = tmp_path / "zh.svg"
    svg.write_text(zh_svg, encoding="utf-8")
    dpi = 150
    png = np.asarray(png_image(convert(zh_svg, "png", dpi=dpi, browser=browser)).convert("L"))
    shot = np.asarray(png_image(browser.screenshot(svg, dpi)).convert("L"))
    assert shot.shape[0] >= png.shape[0] and shot.shape[1] >= png.shape[1]
    differ = different_pixels(png, shot)
    assert differ <= PIXELS_DIFFER, f"{differ:.2%} of the pixels differ"
    # the comparison can fail: the drawing moved by 4 px (0.7 mm), or left out, differs by more
    assert different_pixels(np.roll(png, 4, axis=1), shot) > PIXELS_DIFFER
    assert different_pixels(np.full_like(png, 255), shot) > PIXELS_DIFFER


# ---------------------------------------------------------------------------- the command line


@pytest.mark.parametrize("name, fmt", [("zh.pdf", None), ("zh.PNG", None), ("zh", "png"), ("zh.svg", "svg")])
def test_render_writes_the_format_of_the_extension(tmp_path, browser, name, fmt):
    out = tmp_path / name
    code, stdout, err = run_cli("render", str(ZH), "-o", str(out), *(["--format", fmt] if fmt else []),
                                "--dpi", "100")
    assert code == 0, err
    assert stdout == f"{out}\n"
    magic = {"pdf": b"%PDF-", "png": b"\x89PNG\r\n\x1a\n", "svg": b"<svg"}[format_of(name, fmt)]
    assert out.read_bytes().startswith(magic)
    if magic.startswith(b"\x89PNG"):
        assert png_image(out.read_bytes()).size == (round(297 / 25.4 * 100), round(210 / 25.4 * 100))


def test_render_into_a_folder_in_the_format_asked(tmp_path, browser):
    scenes = [ZH, SCENES / "kin.oscillating_block.toml"]
    code, _, err = run_cli("render", *map(str, scenes), "-d", str(tmp_path), "--format", "pdf")
    assert code == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(f"{s.stem}.pdf" for s in scenes)
    assert all(len(pypdf.PdfReader(p).pages) == 1 for p in tmp_path.iterdir())


@pytest.mark.parametrize("args, words", [
    (["-o", "{}/out.jpg"], "out.jpg: unknown format .jpg: write .svg, .pdf or .png (or --format)"),
    (["-o", "{}/out.png", "--format", "svg"], "out.png: the extension .png is not the format svg"),
    (["-o", "{}/.png", "--format", "svg"], ".png: the extension .png is not the format svg"),
    (["-o", "{}/out.pdf", "--format", "tiff"], "unknown format 'tiff'"),
    (["-d", "{}", "--format", "jpg"], "unknown format 'jpg'"),
    (["-o", "{}/out.png", "--dpi", "0"], "--dpi must be a number from"),
    (["-o", "{}/out.png", "--dpi", "-150"], "--dpi must be a number from"),
    (["-o", "{}/out.png", "--dpi", "1e9"], "--dpi must be a number from"),
    (["-o", "{}/out.png", "--dpi", "nan"], "--dpi must be a number from"),
])
def test_render_refuses_a_bad_format_or_dpi_in_one_line_and_writes_nothing(tmp_path, args, words):
    result = run_cli("render", str(ZH), *(a.format(tmp_path) for a in args))
    assert_refused(result, "graphmech", words)
    assert list(tmp_path.iterdir()) == []


def test_a_dpi_that_is_no_number_is_argparses_one_line(tmp_path, capsys):
    from graphmech.cli import main

    with pytest.raises(SystemExit) as stop:  # argparse's own exit, as for any bad option
        main(["render", str(ZH), "-o", str(tmp_path / "out.png"), "--dpi", "many"])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and err == "graphmech: argument --dpi: invalid float value: 'many'\n"
    assert list(tmp_path.iterdir()) == []


def test_render_without_a_browser_says_how_to_get_one_and_writes_nothing(tmp_path, monkeypatch):
    for name in ENVIRON:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))
    result = run_cli("render", str(ZH), "-o", str(tmp_path / "a.png"))
    assert_refused(result, "graphmech", "headless Chromium", "apt-get install chromium", "GRAPHMECH_CHROMIUM")
    assert list(tmp_path.iterdir()) == []
    assert run_cli("render", str(ZH), "-o", str(tmp_path / "a.svg"))[0] == 0  # SVG needs none


def test_formats_are_the_three():
    assert FORMATS == ("svg", "pdf", "png")
