"""A backend that records the draw calls, so tests assert on the stream instead of pixels.

Examples
--------
>>> rec = RecordingBackend()
>>> rec.begin(297.0, 210.0, "demo")
>>> rec.line((0.0, 0.0), (10.0, 0.0), "given")
>>> calls = rec.finish()
>>> calls[1]
('line', (0.0, 0.0), (10.0, 0.0), 'given', False)
>>> [c for c in calls if c[0] == "line"] == rec.of("line")
True
"""
from __future__ import annotations

from typing import Any, Sequence

from graphmech.render.backend import Anchor, PagePoint

Call = tuple[Any, ...]


def _pt(p: PagePoint) -> PagePoint:
    return (float(p[0]), float(p[1]))


class RecordingBackend:
    """Records every call as a tuple ``(method_name, *args)``, points as float pairs.

    ``finish`` returns the recorded calls as a tuple; :attr:`calls` stays readable afterwards.
    The recorded argument order is the order of the :class:`~graphmech.render.backend.Backend`
    signature, defaults filled in:

    ``("begin", page_w, page_h, title)``, ``("begin_group", name)``, ``("end_group",)``,
    ``("line", p0, p1, style_key, dashed)``,
    ``("polyline", points, style_key, closed, filled)`` (points a tuple),
    ``("circle", c, r, style_key, filled)``,
    ``("text", s, at, size, anchor, italic, style_key)``, ``("finish",)``.
    """

    def __init__(self) -> None:
        self.calls: list[Call] = []

    def begin(self, page_w: float, page_h: float, title: str = "") -> None:
        self.calls.append(("begin", float(page_w), float(page_h), title))

    def begin_group(self, name: str) -> None:
        self.calls.append(("begin_group", name))

    def end_group(self) -> None:
        self.calls.append(("end_group",))

    def line(self, p0: PagePoint, p1: PagePoint, style_key: str, dashed: bool = False) -> None:
        self.calls.append(("line", _pt(p0), _pt(p1), style_key, bool(dashed)))

    def polyline(
        self,
        points: Sequence[PagePoint],
        style_key: str,
        closed: bool = False,
        filled: bool = False,
    ) -> None:
        pts = tuple(_pt(p) for p in points)
        self.calls.append(("polyline", pts, style_key, bool(closed), bool(filled)))

    def circle(self, c: PagePoint, r: float, style_key: str, filled: bool = False) -> None:
        self.calls.append(("circle", _pt(c), float(r), style_key, bool(filled)))

    def text(
        self,
        s: str,
        at: PagePoint,
        size: float,
        anchor: Anchor = "start",
        italic: bool = False,
        style_key: str = "text",
    ) -> None:
        self.calls.append(("text", s, _pt(at), float(size), anchor, bool(italic), style_key))

    def finish(self) -> tuple[Call, ...]:
        self.calls.append(("finish",))
        return tuple(self.calls)

    def of(self, method: str) -> list[Call]:
        """The recorded calls of one method, in order."""
        return [c for c in self.calls if c[0] == method]
