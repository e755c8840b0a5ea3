"""The one headless-Chromium driver: the DevTools protocol over a pipe.

The browser is found as ``$GRAPHMECH_CHROMIUM`` or ``$CHROMIUM`` (a name on PATH or a path), else
the first of :data:`BROWSERS` on PATH — Debian's ``chromium``, no browser downloaded by Playwright
or pyppeteer. It is driven with ``--remote-debugging-pipe`` (the browser reads commands on fd 3
and writes answers on fd 4, JSON messages ended by NUL), so no port is opened and nothing but
the standard library is needed. One :class:`Browser` (a context manager) serves many figures:
each opens a fresh tab (:meth:`Browser.tab`), so a batch starts one browser, not one per figure.

Every step has a deadline (``timeout``): a browser that hangs or dies raises
:class:`BrowserError` — a :class:`~graphmech.errors.GraphmechError`, so the command prints it
as its one line — and is then killed with everything it started.

Used by :mod:`graphmech.render.export` (PDF and PNG) and by the tests' measuring code
(tests/browser.py).
"""
from __future__ import annotations

import fcntl
import json
import os
import re
import select
import shutil
import signal
import subprocess
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Self

from graphmech.errors import GraphmechError

#: The browsers looked for on PATH, in order (after the environment variables of :data:`ENVIRON`).
BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
#: Environment variables naming the browser (a path or a name on PATH), first wins.
ENVIRON = ("GRAPHMECH_CHROMIUM", "CHROMIUM")
#: s: the browser must answer each protocol step within this (a hang guard, not a speed demand).
STEP_S = 60.0
#: How to get a browser, for the message when there is none.
NOT_FOUND = ("PDF and PNG are printed by headless Chromium, which was not found: install it "
             "(Debian/Ubuntu: apt-get install chromium) or set GRAPHMECH_CHROMIUM to its path")

_LENGTH = re.compile(r"^\s*([0-9.eE+-]+)\s*(mm|cm|in|pt|pc|px)?\s*$")
_MM_PER = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72, "pc": 25.4 / 6, "px": 25.4 / 96, None: 25.4 / 96}


class BrowserError(GraphmechError):
    """The browser could not be started, did not answer in time, died, or refused a step (the
    message says which and why)."""


def find_chromium() -> str | None:
    """The browser to use: the first of :data:`ENVIRON` that is set and names an executable, else
    the first of :data:`BROWSERS` on PATH; None when there is none."""
    for name in (*(os.environ.get(v) for v in ENVIRON), *BROWSERS):
        if name and (found := shutil.which(name)):
            return found
    return None


def root_size_mm(svg_text: str) -> tuple[float, float]:
    """The root ``<svg>``'s width and height in mm, from its attributes (what the page is)."""
    start = svg_text.find("<svg")
    end = svg_text.find(">", start)
    if start < 0 or end < 0:
        raise BrowserError("not an SVG document: no <svg> element")
    head = svg_text[start: end + 1]
    out = []
    for attr in ("width", "height"):
        m = re.search(rf'\s{attr}="([^"]*)"', head)
        v = _LENGTH.match(m.group(1)) if m else None
        if v is None or not float(v.group(1)) > 0:
            raise BrowserError(f"the root <svg> has no absolute {attr}")
        out.append(float(v.group(1)) * _MM_PER[v.group(2)])
    return out[0], out[1]


class Tab:
    """One page of the browser, attached with its own session (see :meth:`Browser.tab`)."""

    def __init__(self, browser: Browser, session: str) -> None:
        self.browser = browser
        self.session = session

    def call(self, method: str, params: dict[str, Any] | None = None) -> dict[str, Any]:
        """A protocol command in this tab; its result."""
        return self.browser.call(method, params, self.session)

    def evaluate(self, expression: str) -> Any:
        """``expression`` evaluated in the page (a promise awaited); its value, as JSON."""
        value = self.call("Runtime.evaluate", {"expression": expression, "awaitPromise": True,
                                               "returnByValue": True})
        if "exceptionDetails" in value:
            d = value["exceptionDetails"]
            raise BrowserError(f"the page's script failed: {d.get('exception', {}).get('description') or d.get('text')}")
        return value["result"].get("value")

    def events(self) -> list[dict[str, Any]]:
        """The events this tab has reported so far, in order (each with its ``method``, ``params``)."""
        return [e for e in self.browser.events if e.get("sessionId") == self.session]


class Browser:
    """One headless Chromium driven over the DevTools pipe. A context manager: leaving it closes
    the browser and removes its profile (a fresh temporary one, which :attr:`workdir` is).

    ``executable`` defaults to :func:`find_chromium`'s; with none, :class:`BrowserError` says how
    to install one. ``timeout`` (s) bounds each protocol step.
    """

    def __init__(self, executable: str | None = None, timeout: float = STEP_S) -> None:
        found = executable or find_chromium()
        if found is None:
            raise BrowserError(NOT_FOUND)
        self.executable = found
        self.timeout = timeout
        self.events: list[dict[str, Any]] = []
        self._profile = tempfile.TemporaryDirectory(prefix="graphmech-browser-")
        self.workdir = Path(self._profile.name)
        self._log = open(self.workdir / "stderr.log", "w+b")  # noqa: SIM115 (open while the browser runs)
        self._buffer = b""
        self._next = 0
        self._broken = False
        self._closed = False
        to_browser, self._in = os.pipe()     # we write commands; the browser reads them on fd 3
        self._out, from_browser = os.pipe()  # the browser writes answers on fd 4; we read them

        def child_fds() -> None:  # in the child: the pipes onto fds 3 and 4, inheritable
            a = fcntl.fcntl(to_browser, fcntl.F_DUPFD, 10)
            b = fcntl.fcntl(from_browser, fcntl.F_DUPFD, 10)
            os.dup2(a, 3)
            os.dup2(b, 4)

        try:
            # its own process group, so a browser that hangs is killed with its renderers
            self._proc = subprocess.Popen(
                [found, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                 "--disable-extensions", "--disable-background-networking", "--hide-scrollbars",
                 "--mute-audio", "--remote-debugging-pipe",
                 f"--user-data-dir={self.workdir}", "about:blank"],
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=self._log,
                preexec_fn=child_fds, close_fds=False, start_new_session=True)  # noqa: PLW1509 (dup2 only)
        except OSError as e:
            for fd in (to_browser, from_browser, self._in, self._out):
                os.close(fd)
            self._log.close()
            self._profile.cleanup()
            raise BrowserError(f"could not start {found}: {e.strerror or e}") from None
        os.close(to_browser)
        os.close(from_browser)
        try:
            self.version: str = self.call("Browser.getVersion")["product"]
        except BaseException:
            self.close()
            raise

    # --- the protocol
    def call(self, method: str, params: dict[str, Any] | None = None, session: str | None = None) -> dict[str, Any]:
        """Send one command (to a tab's ``session``, else to the browser) and wait for its answer;
        the events that arrive meanwhile are kept in :attr:`events`."""
        if self._broken or self._closed:
            raise BrowserError("the browser stopped answering earlier; start a new one" if self._broken
                               else "the browser was closed")
        self._next += 1
        message: dict[str, Any] = {"id": self._next, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        data = json.dumps(message).encode() + b"\0"
        try:
            while data:
                data = data[os.write(self._in, data):]
        except BrokenPipeError:
            self._broken = True
            raise BrowserError(f"the browser exited: {self._stderr_tail()}") from None
        while True:
            m = self._receive(method)
            if m.get("id") == self._next:
                if "error" in m:
                    raise BrowserError(f"{method}: {m['error'].get('message')}")
                result: dict[str, Any] = m.get("result", {})
                return result
            if "method" in m:
                self.events.append(m)

    def wait_for(self, method: str, session: str | None = None) -> dict[str, Any]:
        """The first event ``method`` (of ``session``), taken out of :attr:`events` or awaited."""
        while True:
            for i, e in enumerate(self.events):
                if e["method"] == method and e.get("sessionId") == session:
                    return self.events.pop(i)
            m = self._receive(method)
            if "method" in m:
                self.events.append(m)

    def _receive(self, waiting_for: str) -> dict[str, Any]:
        deadline = time.monotonic() + self.timeout
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._out], [], [], left)[0]:
                self._broken = True
                raise BrowserError(f"headless Chromium did not answer {waiting_for} within {self.timeout:g} s")
            chunk = os.read(self._out, 1 << 20)
            if not chunk:
                self._broken = True
                raise BrowserError(f"headless Chromium exited: {self._stderr_tail() or 'no message'}")
            self._buffer += chunk
        raw, self._buffer = self._buffer.split(b"\0", 1)
        result: dict[str, Any] = json.loads(raw)
        return result

    def _stderr_tail(self) -> str:
        """The last line the browser wrote on stderr (its reason, if it gave one)."""
        self._log.flush()
        self._log.seek(0)
        lines = [s.strip() for s in self._log.read().decode(errors="replace").splitlines() if s.strip()]
        return lines[-1][-300:] if lines else ""

    # --- pages
    @contextmanager
    def tab(self, url: str, domains: tuple[str, ...] = ("Page",)) -> Iterator[Tab]:
        """A fresh tab with ``domains`` enabled, ``url`` loaded (the load event awaited); closed on
        leaving. A page that cannot be loaded raises :class:`BrowserError`."""
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        try:
            for domain in dict.fromkeys(("Page", *domains)):
                self.call(f"{domain}.enable", session=session)
            self.events = [e for e in self.events if e.get("sessionId") != session]
            nav = self.call("Page.navigate", {"url": url}, session=session)
            if nav.get("errorText"):
                raise BrowserError(f"{url}: {nav['errorText']}")
            self.wait_for("Page.loadEventFired", session)
            yield Tab(self, session)
        finally:
            self.events = [e for e in self.events if e.get("sessionId") != session]
            if not self._broken:
                self.call("Target.closeTarget", {"targetId": target})

    @property
    def alive(self) -> bool:
        """Whether it still answers: not closed, not broken by an earlier failure, running."""
        return not (self._broken or self._closed) and self._proc.poll() is None

    def close(self) -> None:
        """Close the browser (killed with its process group if it does not answer) and remove its
        profile. Safe to call twice."""
        if self._closed:
            return
        self._closed = True
        if self._proc.poll() is None:
            try:
                if self._broken:
                    raise BrowserError("broken")
                self.call("Browser.close")
                self._proc.wait(10)
            except (BrowserError, OSError, subprocess.TimeoutExpired):
                try:
                    os.killpg(self._proc.pid, signal.SIGKILL)
                except OSError:
                    pass
                self._proc.wait()
        for fd in (self._in, self._out):
            try:
                os.close(fd)
            except OSError:
                pass
        self._log.close()
        self._profile.cleanup()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
