"""The drawing vocabulary a backend understands.

The frontend (:func:`graphmech.render.sheet.draw_sheet`) turns primitives into these calls; a
backend turns the calls into output (an SVG string, a recorded list for tests). Coordinates are
**page** millimetres: origin at the page's top-left corner, x to the right, **y down**. A backend
never scales, lays out or places anything; it draws what it is told, in the order it is told.

Style keys name a :class:`graphmech.render.style.Pen` (``"given"``, ``"construction"``,
``"result"``, ``"label"``, ``"frame"``, ``"hatch"``, ``"hinge"``, ``"slider"``, ``"text"``).
"""
from __future__ import annotations

from typing import Literal, Protocol, Sequence, TypeVar, runtime_checkable

PagePoint = tuple[float, float]
Anchor = Literal["start", "middle", "end"]

R_co = TypeVar("R_co", covariant=True)


@runtime_checkable
class Backend(Protocol[R_co]):
    """What a backend implements; ``finish`` returns its product (e.g. the SVG ``str``)."""

    def begin(self, page_w: float, page_h: float, title: str = "") -> None:
        """Start a page ``page_w`` × ``page_h`` mm; ``title`` is the document's title."""

    def begin_group(self, name: str) -> None:
        """Open a named group (a panel, the titles, …); groups nest."""

    def end_group(self) -> None:
        """Close the innermost open group."""

    def line(self, p0: PagePoint, p1: PagePoint, style_key: str, dashed: bool = False) -> None:
        """A straight stroke from ``p0`` to ``p1``."""

    def polyline(
        self,
        points: Sequence[PagePoint],
        style_key: str,
        closed: bool = False,
        filled: bool = False,
    ) -> None:
        """A stroke through ``points``; ``closed`` joins the last to the first, ``filled`` fills
        it with the pen's fill."""

    def circle(self, c: PagePoint, r: float, style_key: str, filled: bool = False) -> None:
        """A circle of radius ``r`` mm about ``c``."""

    def text(
        self,
        s: str,
        at: PagePoint,
        size: float,
        anchor: Anchor = "start",
        italic: bool = False,
        style_key: str = "text",
    ) -> None:
        """Text of font size ``size`` mm whose baseline passes through ``at``; ``anchor`` says
        whether ``at`` is the start, middle or end of the line."""

    def finish(self) -> R_co:
        """End the page and return the product."""
        ...
