"""``graphmech gallery DIR -d SITE``: the page of three reference scenes and a broken one — the files
written, every scene text escaped, the failure listed while the others are written, the same bytes
on a second run — and the page in headless Chromium: no console error, every image loaded."""
from __future__ import annotations

import html
import os
import re
import shutil
from html.parser import HTMLParser
from pathlib import Path

import pytest

from tests.browser import Browser, find_chromium
from tests.conftest import SCENES, assert_refused, check_json, run_cli
from tests.test_browser import no_browser

REFERENCE = ["kin.oscillating_block-zh", "cam.offset_roller_translating-pos", "fly.ic_engine_flywheel"]
HOSTILE = "<script>alert('title')</script> & \"quoted\" <img src=x onerror=alert(1)>"
BROKEN = 'title = "no driver"\n[frame]\nA_mm = [0, 0]\n'


class Page(HTMLParser):
    """What the page links to and shows: <img src>, <a href>, the element tags seen."""

    def __init__(self) -> None:
        super().__init__()
        self.images: list[str] = []
        self.links: list[str] = []
        self.tags: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        a = dict(attrs)
        if tag == "img":
            self.images.append(a["src"] or "")
        if tag == "a":
            self.links.append(a["href"] or "")


def scenes(folder: Path) -> Path:
    """Three reference scenes (the first retitled with markup) and a broken one, in ``folder``."""
    folder.mkdir()
    for name in REFERENCE:
        shutil.copy2(SCENES / f"{name}.toml", folder / f"{name}.toml")
    hostile = folder / f"{REFERENCE[0]}.toml"
    text = hostile.read_text(encoding="utf-8")
    toml_title = HOSTILE.replace("\\", "\\\\").replace('"', '\\"')
    hostile.write_text(re.sub(r'(?m)^title = ".*"$', f'title = "{toml_title}"', text, count=1), encoding="utf-8")
    (folder / "broken.toml").write_text(BROKEN, encoding="utf-8")
    return folder


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> tuple[Path, Path, tuple[int, str, str]]:
    root = tmp_path_factory.mktemp("gallery")
    folder = scenes(root / "scenes")
    out = root / "site"
    return folder, out, run_cli("gallery", str(folder), "-d", str(out))


def test_the_failed_scene_is_reported_in_one_line_and_the_others_are_written(site):
    folder, out, (code, stdout, stderr) = site
    assert code == 2
    assert stdout == f"{out / 'index.html'}\n"
    assert stderr.count("\n") == 1 and stderr.startswith("graphmech gallery: broken.toml: driver: missing")
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(["index.html", "broken.toml", *(f"{n}.svg" for n in REFERENCE),
                            *(f"{n}.toml" for n in REFERENCE)])
    for p in folder.iterdir():  # the copies are the scenes as given
        assert (out / p.name).read_bytes() == p.read_bytes()
    for name in REFERENCE:
        assert (out / f"{name}.svg").read_text(encoding="utf-8").rstrip().endswith("</svg>")


def test_the_page_escapes_every_text_of_a_scene(site):
    _, out, _ = site
    page = (out / "index.html").read_text(encoding="utf-8")
    assert "<script" not in page and "onerror=alert" not in page.replace("onerror=alert(1)&gt;", "")
    escaped = "&lt;script&gt;alert(&#x27;title&#x27;)&lt;/script&gt; &amp; &quot;quoted&quot; &lt;img src=x"
    assert page.count(escaped) == 2  # the heading and the image's alt text
    parsed = Page()
    parsed.feed(page)
    assert "script" not in parsed.tags and len(parsed.images) == 3  # the hostile <img> is text, not an image


def test_the_page_links_to_each_figure_and_scene_and_lists_the_failure(site):
    _, out, _ = site
    page = (out / "index.html").read_text(encoding="utf-8")
    parsed = Page()
    parsed.feed(page)
    assert parsed.images == [f"{n}.svg" for n in sorted(REFERENCE)]
    files = [h for h in parsed.links if not h.startswith("#")]
    assert sorted(set(files)) == sorted(["broken.toml", *(f"{n}.svg" for n in REFERENCE),
                                         *(f"{n}.toml" for n in REFERENCE)])
    assert all((out / f).is_file() for f in files)
    anchors = {h[1:] for h in parsed.links if h.startswith("#")}
    assert anchors == {f"scene-{n}" for n in ["broken", *REFERENCE]}
    assert all(f'id="{a}"' in page for a in anchors)
    assert '<p class="failed">failed: broken.toml: driver: missing: add a [driver] table' in page
    assert "4 scenes, 1 failed" in page


@pytest.mark.parametrize("name", REFERENCE[1:])
def test_each_check_row_is_in_the_table_with_its_values(site, name):
    _, out, _ = site
    page = (out / "index.html").read_text(encoding="utf-8")
    section = page[page.index(f'id="scene-{name}"'):]
    section = section[:section.index("</section>")]
    doc = check_json(SCENES / f"{name}.toml")
    rows = re.findall(r"<tr><td>([^<]*)</td>(.*?)</tr>", section)
    assert [n for n, _ in rows] == [q["name"] for q in doc["quantities"]]
    for (_, cells), q in zip(rows, doc["quantities"]):
        tds = re.findall(r"<td[^>]*>([^<]*)</td>", cells)
        assert float(tds[2]) == pytest.approx(q["graphical"], rel=1e-8, abs=1e-12)
        assert float(tds[3]) == pytest.approx(q["exact"], rel=1e-8, abs=1e-12)
        assert tds[6].startswith(q["error_source"])
        assert (tds[7] == "") == (q["error_estimate"] is None)
    for w in doc["warnings"]:
        assert f"<li>warning: {html.escape(w)}</li>" in section


def test_the_same_scenes_give_the_same_bytes(site, tmp_path):
    folder, out, _ = site
    again = tmp_path / "again"
    assert run_cli("gallery", str(folder), "-d", str(again))[0] == 2
    for p in out.iterdir():
        assert (again / p.name).read_bytes() == p.read_bytes(), p.name


def test_a_gallery_of_good_scenes_exits_0(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    shutil.copy2(SCENES / "bal.disc_static.toml", folder)
    code, _, err = run_cli("gallery", str(folder), "-d", str(tmp_path / "site"))
    assert (code, err) == (0, "") and (tmp_path / "site" / "bal.disc_static.svg").is_file()


def test_measured_values_are_judged_on_the_page(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    shutil.copy2(SCENES / "linkage.fourbar_28_52_50_72.toml", folder)
    assert run_cli("gallery", str(folder), "-d", str(tmp_path / "site"))[0] == 0
    page = (tmp_path / "site" / "index.html").read_text(encoding="utf-8")
    table = page[page.index('<table class="measured">'):]
    rows = re.findall(r"<tr><td>([^<]*)</td><td class=\"n\">([^<]*)</td><td class=\"n\">([^<]*)</td>"
                      r"<td class=\"n\">[^<]*</td><td[^>]*>([^<]*)</td>", table[:table.index("</table>")])
    measured = check_json(SCENES / "linkage.fourbar_28_52_50_72.toml")["measured"]
    assert measured and [r[0] for r in rows] == [html.escape(m["name"]) for m in measured]
    for (_, value, expected, verdict), m in zip(rows, measured):
        assert float(value) == pytest.approx(m["measured"], rel=1e-5)
        assert float(expected) == pytest.approx(m["expected"], rel=1e-5)
        assert verdict == ("ok" if m["ok"] else "OUT OF TOLERANCE")


def test_no_scenes_or_no_folder_is_refused_and_nothing_is_written(tmp_path):
    (tmp_path / "empty").mkdir()
    assert_refused(run_cli("gallery", str(tmp_path / "empty"), "-d", str(tmp_path / "site")), "graphmech",
                   "no scene files")
    assert_refused(run_cli("gallery", str(tmp_path / "none"), "-d", str(tmp_path / "site")), "graphmech",
                   "not a folder")
    (tmp_path / "file").write_text("x", encoding="utf-8")
    shutil.copy2(SCENES / "bal.disc_static.toml", tmp_path / "empty")
    assert_refused(run_cli("gallery", str(tmp_path / "empty"), "-d", str(tmp_path / "file")), "graphmech",
                   "is not a folder")
    assert not (tmp_path / "site").exists()


def test_a_file_name_that_is_not_utf8_is_shown_and_linked_by_its_bytes(tmp_path):
    """It was an internal error (exit 3) after the figures were written, with no page."""
    folder = tmp_path / "scenes"
    folder.mkdir()
    name = os.fsdecode(b"x\xff")
    shutil.copy2(SCENES / "bal.disc_static.toml", folder / f"{name}.toml")
    code, out, err = run_cli("gallery", str(folder), "-d", str(tmp_path / "site"))
    assert (code, err) == (0, "") and out.strip() == str(tmp_path / "site" / "index.html")
    parsed = Page()
    parsed.feed((tmp_path / "site" / "index.html").read_text(encoding="utf-8"))
    assert parsed.images == ["x%FF.svg"] and {"x%FF.toml", "x%FF.svg", "#scene-x%EF%BF%BD"} <= set(parsed.links)
    assert (tmp_path / "site" / f"{name}.svg").is_file()


def test_a_scene_over_a_mebibyte_is_refused_and_not_copied(tmp_path):
    folder = tmp_path / "scenes"
    folder.mkdir()
    (folder / "big.toml").write_bytes(b'title = "x"\n' + b"#" * (1 << 20))
    shutil.copy2(SCENES / "bal.disc_static.toml", folder)
    code, _, err = run_cli("gallery", str(folder), "-d", str(tmp_path / "site"))
    assert code == 2 and err.startswith("graphmech gallery: big.toml: file is larger than 1 MiB")
    assert sorted(p.name for p in (tmp_path / "site").iterdir()) == ["bal.disc_static.svg", "bal.disc_static.toml",
                                                                     "index.html"]


# ---------------------------------------------------------------------------- in the browser

IMAGES_JS = """(async function () {
  await document.fonts.ready;
  return Array.from(document.images).map(function (i) {
    return {src: i.getAttribute('src'), complete: i.complete, width: i.naturalWidth, height: i.naturalHeight};
  });
})()"""


@pytest.fixture(scope="module")
def browser():
    executable = find_chromium()
    if executable is None:
        no_browser("CI" in os.environ)
    with Browser(executable) as b:
        yield b


def test_the_page_loads_in_chromium_with_no_error_and_every_image(site, browser, tmp_path):
    _, out, _ = site
    images, errors = browser.evaluate(out / "index.html", IMAGES_JS)
    assert errors == []
    assert [i["src"] for i in images] == [f"{n}.svg" for n in sorted(REFERENCE)]
    assert all(i["complete"] and i["width"] > 0 and i["height"] > 0 for i in images), images
    # the check can fail: a figure gone from the site is an error and an image of no size
    copy = tmp_path / "site"
    shutil.copytree(out, copy)
    (copy / f"{REFERENCE[2]}.svg").unlink()
    images, errors = browser.evaluate(copy / "index.html", IMAGES_JS)
    assert len(errors) == 1 and "ERR_FILE_NOT_FOUND" in errors[0]
    assert [i["width"] for i in images if i["src"] == f"{REFERENCE[2]}.svg"] == [0]
