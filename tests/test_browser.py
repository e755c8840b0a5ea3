"""The reference figures as users see them: each scene of figures/scenes rendered afresh and opened
in headless Chromium (tests/browser.py: the driver, the measuring script and the geometry that
``.ci/figure-report`` uses too; its docstring says what is measured, its head holds the
tolerances). Per figure, so a failure names it:

* it loads with no error (no XML parse error, no console error, the measuring script ran);
* no label box (Chromium's ``getBBox()``) is crossed by a stroke that is not its own, and no two
  label boxes overlap (by more than ``TOL``);
* no text graphmech composes holds an ASCII ``_`` (the sheet title is the scene's own text, kept
  verbatim; the reference scenes' titles hold none either);
* rendered with ``--page fit``, the union of the element boxes covers at least ``FIT_FILLED`` of
  the page.

Without a browser (graphmech.render.chromium.find_chromium finds none) these tests skip, saying
why — unless the environment variable ``CI`` is set: there they fail, so CI cannot skip them
silently (``.ci/run`` installs Debian's chromium and fonts-noto-cjk first). tests/browser.py's
``no_browser`` says so for every browser test.
"""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from graphmech.render.chromium import ENVIRON
from tests.browser import (
    FIT_FILLED,
    TOL,
    Browser,
    BrowserError,
    analyse,
    find_chromium,
    no_browser,
    open_browser,
)
from tests.conftest import SCENES, run_cli

SCENE_FILES = sorted(SCENES.glob("*.toml"))
NAMES = [p.stem for p in SCENE_FILES]
# Rendering all 50 scenes takes ≈ 6 s alone; the guard only stops a hang.
RENDER_GUARD_S = 600.0
SHOWN = 12  # a failure lists this many of its hits


browser = pytest.fixture(scope="module")(open_browser)  # one headless Chromium for the module


def render_and_measure(browser: Browser, folder: Path, *options: str) -> dict[str, dict | str]:
    """Every reference scene rendered by one ``graphmech render`` into ``folder`` and measured:
    name → the analysis, or the error (a string) that stopped it."""
    try:
        code, _, err = run_cli("render", *options, "-d", str(folder), *map(str, SCENE_FILES),
                               limit=RENDER_GUARD_S)
    except SystemExit as e:  # argparse: the command line refused its options (its message is lost)
        code, err = e.code, f"the command line refused {' '.join(options)}"
    if code != 0:
        why = f"graphmech render {' '.join(options)} failed (exit {code}): {err.strip()[-800:]}"
        return {name: why for name in NAMES}
    out: dict[str, dict | str] = {}
    for name in NAMES:
        try:
            out[name] = analyse(name, browser.measure(folder / f"{name}.svg"))
        except BrowserError as e:
            out[name] = str(e)
    return out


@pytest.fixture(scope="module")
def figures(browser, tmp_path_factory) -> dict[str, dict | str]:
    """The scenes on their own pages (what ``graphmech render`` gives by default)."""
    return render_and_measure(browser, tmp_path_factory.mktemp("figures"))


@pytest.fixture(scope="module")
def fit_figures(browser, tmp_path_factory) -> dict[str, dict | str]:
    """The scenes on pages cropped to their content (``--page fit``)."""
    return render_and_measure(browser, tmp_path_factory.mktemp("fit"), "--page", "fit")


def loaded(figures: dict[str, dict | str], name: str) -> dict:
    """The figure's analysis; the test fails (naming the error) if it did not load cleanly."""
    r = figures[name]
    if isinstance(r, str):
        pytest.fail(r, pytrace=False)
    assert not r["errors"], f"{name}: the page reports errors:\n" + "\n".join(r["errors"])
    return r


def listing(items: list[str]) -> str:
    more = f"\n  … and {len(items) - SHOWN} more" if len(items) > SHOWN else ""
    return "".join(f"\n  {i}" for i in items[:SHOWN]) + more


# ---------------------------------------------------------------------------- every reference figure


@pytest.mark.parametrize("name", NAMES)
def test_figure_loads_without_error(figures, name):
    r = loaded(figures, name)
    assert r["texts"] > 0, f"{name}: the measuring script found no text (every sheet has its title)"


@pytest.mark.parametrize("name", NAMES)
def test_no_label_is_crossed_by_a_stroke_not_its_own(figures, name):
    r = loaded(figures, name)
    hits = [f"{c['text']!r} by {', '.join(sorted(set(c['by'])))}" for c in r["crossings"] if c["by"]]
    assert r["label_stroke"] == 0, f"{name}: {r['label_stroke']} label boxes crossed (> {TOL} mm):" + listing(hits)


@pytest.mark.parametrize("name", NAMES)
def test_no_two_labels_overlap(figures, name):
    r = loaded(figures, name)
    pairs = [f"{p['a']!r} × {p['b']!r}: {p['overlap'][0]:.2f} × {p['overlap'][1]:.2f} mm" for p in r["label_pairs"]]
    assert r["label_label"] == 0, f"{name}: {r['label_label']} overlapping label pairs (> {TOL} mm):" + listing(pairs)


@pytest.mark.parametrize("name", NAMES)
def test_no_composed_text_holds_an_ascii_underscore(figures, name):
    r = loaded(figures, name)
    assert r["underscore"] == 0, f"{name}: {r['underscore']} texts with '_':" + listing(map(repr, r["underscore_texts"]))
    # the title is the scene's own text, kept verbatim: the reference titles are written without one
    assert r["underscore_title"] == 0, f"{name}: the sheet title holds '_'"


@pytest.mark.parametrize("name", NAMES)
def test_a_fit_page_is_at_least_half_filled(fit_figures, name):
    """The sheet's elements are its panels, title, footer and title block (the root's groups):
    their boxes cover at least half of a page cropped to them. (Single strokes and letters leave
    most of their surroundings empty: the union of every line's and letter's own box is 2–35 %
    even of a well-filled sheet, so it is reported, not asserted.)"""
    r = loaded(fit_figures, name)
    assert r["panel_filled"] >= FIT_FILLED, (
        f"{name}: on a fit page of {r['page_mm'][0]:.0f} × {r['page_mm'][1]:.0f} mm the sheet's elements "
        f"cover {r['panel_filled']:.1%} (< {FIT_FILLED:.0%}); single elements' boxes {r['filled']:.1%}")


def test_the_reference_titles_hold_no_ascii_underscore():
    """Scene text is drawn verbatim, so the reference scenes' titles write subscripts as Unicode
    characters (rᵣ, Fᵢ₃), which the lettering sets as subscripts, or in words."""
    titles = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")).get("title", "") for p in SCENE_FILES}
    assert len(titles) == len(NAMES) >= 50
    assert [n for n, t in titles.items() if "_" in t] == []


# ---------------------------------------------------------------------------- the checker itself

SVG = """<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50"
     font-family="'Liberation Serif', serif" font-size="5">
  <g id="panel">
    <line x1="5" y1="10" x2="40" y2="10" stroke="black" stroke-width="0.35"/>
    <text x="10" y="12">A</text>
    <text x="60" y="20">B_2</text>
    <text x="63" y="21">C</text>
    <line x1="5" y1="40" x2="25" y2="40" stroke="black" stroke-width="0.35"/>
    <text x="10" y="47">E</text>
    <line x1="70" y1="45" x2="95" y2="45" stroke="black" stroke-width="0.35" data-label-for="f"/>
    <text id="f" x="80" y="46">F</text>
  </g>
  <g id="label-D">
    <line x1="30" y1="30" x2="40" y2="25" stroke="black" stroke-width="0.25"/>
    <text x="35" y="29">D</text>
  </g>
  <g id="s-title"><text x="50" y="5" font-size="3">a_b</text></g>
</svg>
"""


@pytest.fixture(scope="module")
def hand_written(browser, tmp_path_factory) -> dict:
    svg = tmp_path_factory.mktemp("hand") / "hand.svg"
    svg.write_text(SVG, encoding="utf-8")
    return analyse("hand", browser.measure(svg))


def test_checker_counts_a_label_crossed_by_a_line_and_not_one_with_its_own_leader(hand_written):
    # A sits on the line y = 10; the line y = 40 passes above E's box (its top is ≈ 42.5, the
    # font's ascent 0.89 em below the baseline y = 47); D's leader is in D's own <g>; the line
    # through F names F (data-label-for).
    assert [c["text"] for c in hand_written["crossings"] if c["by"]] == ["A"]
    assert hand_written["label_stroke"] == 1


def test_checker_counts_two_overlapping_labels_once(hand_written):
    assert [(p["a"], p["b"]) for p in hand_written["label_pairs"]] == [("B_2", "C")]


def test_checker_finds_an_underscore_in_composed_text_apart_from_the_title(hand_written):
    assert hand_written["underscore_texts"] == ["B_2"]
    assert (hand_written["underscore"], hand_written["underscore_title"]) == (1, 1)


def test_checker_measures_the_filled_fraction_and_the_panels(browser, tmp_path):
    svg = tmp_path / "filled.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50">'
                   '<rect x="-10" y="0" width="70" height="50" fill="black"/>'  # 60 × 50 of it on the page
                   '<g id="panel"><rect x="50" y="0" width="20" height="25" fill="none" stroke="black"/>'
                   '<rect x="80" y="40" width="10" height="10"/></g>'
                   '</svg>', encoding="utf-8")
    r = analyse("filled", browser.measure(svg))
    assert r["errors"] == [] and tuple(r["page_mm"]) == (100.0, 50.0)
    # the element boxes (a stroke's width is not in getBBox): 60 × 50 + 10 × 25 + 10 × 10
    assert r["filled"] == pytest.approx(3350 / 5000, abs=1e-3)
    # the one <g>: x 50 … 90, y 0 … 50
    assert r["panel_filled"] == pytest.approx(2000 / 5000, abs=1e-3)


def test_checker_reports_a_console_error_and_refuses_a_parse_error(browser, tmp_path):
    bad = tmp_path / "bad.svg"
    bad.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm">'
                   '<rect width="-3" height="2"/><text x="1" y="5">a</text></svg>', encoding="utf-8")
    errors = browser.measure(bad)["errors"]
    assert len(errors) == 1 and "negative value" in errors[0], errors
    broken = tmp_path / "broken.svg"
    broken.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm">'
                      '<text x="1" y="5">a & b</text></svg>', encoding="utf-8")
    with pytest.raises(BrowserError, match="XML parse error"):
        browser.measure(broken)


def test_without_a_browser_ci_fails_and_elsewhere_the_tests_skip(monkeypatch, tmp_path):
    for name in ENVIRON:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))
    assert find_chromium() is None
    with pytest.raises(pytest.fail.Exception, match="CI is set"):
        no_browser(ci=True)
    with pytest.raises(pytest.skip.Exception, match="no browser: none of chromium, chromium-browser, google-chrome"):
        no_browser(ci=False)
