"""graphmech/render/chromium.py: finding the browser, the pipe client, and its failures — a
missing browser, one that dies, one that hangs — each a one-line BrowserError, never a hang.

The fake browsers are shell scripts in tmp_path; the real one follows tests/test_browser.py's rule
(skip without one unless CI is set)."""
from __future__ import annotations

import os
import signal
import stat

import pytest

from graphmech.errors import GraphmechError
from graphmech.render.chromium import (
    BROWSERS,
    ENVIRON,
    Browser,
    BrowserError,
    find_chromium,
    root_size_mm,
)
from tests.browser import open_browser

browser = pytest.fixture(scope="module")(open_browser)


def script(folder, name: str, body: str) -> str:
    path = folder / name
    path.write_text("#!/bin/sh\n" + body + "\n", encoding="utf-8")
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return str(path)


@pytest.fixture
def no_environment(monkeypatch):
    for name in ENVIRON:
        monkeypatch.delenv(name, raising=False)


def test_find_chromium_prefers_graphmech_chromium_then_chromium_then_path(tmp_path, monkeypatch, no_environment):
    on_path = tmp_path / "bin"
    on_path.mkdir()
    monkeypatch.setenv("PATH", str(on_path))
    assert find_chromium() is None
    last = script(on_path, BROWSERS[-1], "exit 0")
    assert find_chromium() == last
    first = script(on_path, BROWSERS[0], "exit 0")
    assert find_chromium() == first
    mine = script(tmp_path, "my-chrome", "exit 0")
    monkeypatch.setenv("CHROMIUM", mine)
    assert find_chromium() == mine
    ours = script(tmp_path, "our-chrome", "exit 0")
    monkeypatch.setenv("GRAPHMECH_CHROMIUM", ours)
    assert find_chromium() == ours
    # a variable naming nothing runnable is passed over
    monkeypatch.setenv("GRAPHMECH_CHROMIUM", str(tmp_path / "absent"))
    assert find_chromium() == mine


def test_without_a_browser_the_error_says_how_to_install_one(tmp_path, monkeypatch, no_environment):
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(BrowserError) as e:
        Browser()
    message = str(e.value)
    assert isinstance(e.value, GraphmechError) and "\n" not in message
    assert "headless Chromium" in message and "apt-get install chromium" in message and "GRAPHMECH_CHROMIUM" in message


def test_a_browser_that_exits_at_once_is_one_line(tmp_path):
    crash = script(tmp_path, "crash", "echo 'cannot open display' >&2; exit 1")
    with pytest.raises(BrowserError, match="exited: cannot open display"):
        Browser(crash, timeout=30)


def test_a_browser_that_never_answers_is_killed_at_the_deadline(tmp_path):
    pid_file = tmp_path / "pid"
    hang = script(tmp_path, "hang", f"echo $$ > {pid_file}; exec sleep 300")
    with pytest.raises(BrowserError, match=r"did not answer Browser.getVersion within 0.5 s"):
        Browser(hang, timeout=0.5)
    pid = int(pid_file.read_text())
    with pytest.raises(ProcessLookupError):  # killed and reaped, not left running
        os.kill(pid, 0)


def test_an_executable_that_cannot_run_is_one_line(tmp_path):
    path = tmp_path / "not-a-program"
    path.write_bytes(b"\x00\x01")
    path.chmod(0o755)
    with pytest.raises(BrowserError, match="could not start"):
        Browser(str(path))


@pytest.mark.parametrize("head, size", [
    ('<svg xmlns="http://www.w3.org/2000/svg" width="297mm" height="210mm">', (297.0, 210.0)),
    ('<?xml version="1.0"?><svg height="1in" width="96px">', (25.4, 25.4)),
    ('<svg width="10cm" height="72pt">', (100.0, 25.4)),
])
def test_root_size_mm(head, size):
    assert root_size_mm(head + "</svg>") == pytest.approx(size)


@pytest.mark.parametrize("text", ['<svg width="100%" height="50mm"></svg>', '<svg height="5mm"></svg>',
                                  '<svg width="0mm" height="5mm"></svg>', "<html></html>"])
def test_root_size_mm_refuses_a_page_without_an_absolute_size(text):
    with pytest.raises(BrowserError):
        root_size_mm(text)


# ---------------------------------------------------------------------------- the real browser


def test_one_browser_serves_many_tabs(browser):
    assert "Chrome" in browser.version or "Chromium" in browser.version
    for n in range(3):
        with browser.tab("data:text/html,<p>x</p>") as tab:
            assert tab.evaluate(f"Promise.resolve({n} + 1)") == n + 1
    with browser.tab("data:text/html,<p>x</p>") as tab, pytest.raises(BrowserError, match="the page's script failed: .*boom"):
        tab.evaluate("(function () { throw new Error('boom'); })()")


def test_a_browser_that_dies_is_an_error_not_a_hang(tmp_path):
    with Browser() as b:
        os.killpg(b._proc.pid, signal.SIGKILL)
        with pytest.raises(BrowserError, match="exited"), b.tab("data:text/html,x"):
            pass
        with pytest.raises(BrowserError, match="stopped answering"):
            b.call("Browser.getVersion")
    b.close()  # twice is harmless
    assert not b.workdir.exists()
